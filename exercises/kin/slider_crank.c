/* slider_crank.c — kin-slider-crank: the crank OA turns at constant omega,
 * the rod AB carries the slider B along the line y = e.
 *
 *     r cos phi + l cos theta3 - x = 0,   r sin phi + l sin theta3 - e = 0      (1)
 *
 * Goal: position, velocity and acceleration of the slider over a turn of
 * the crank; the dead centres (crank and rod in line, the slider at rest)
 * and the stroke; with an offset, the quick return; and with a rod too
 * short for the offset, the toggles where the rod stands square to the
 * slide and the crank cannot turn further.
 * Method: eq. (1) by Newton-Raphson (mm_mech) from frame to frame, the
 * velocities and accelerations by linear solves with its Jacobian (eqs.
 * 4-5 of the theory).  Checks: the closed form (eqs. 2-3), central
 * differences of the positions (error against the step, order 2), the dead
 * centres and toggles of the closed form against those the sweep located.
 * Reference: R. L. Norton, Design of Machinery, 5th ed., McGraw-Hill 2012,
 * sections 4.13 and 7.6; J. E. Shigley, J. J. Uicker, Theory of Machines
 * and Mechanisms, ch. 3.
 * API.md: crank pivot at the origin, slider on y = +e, x measured from the
 * pivot along that line; the slider right of the crank pin (x > r cos phi).
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mm_geom.h"
#include "mm_kin.h"
#include "mm_kin_linkage.h"
#include "mm_linkage.h"
#include "mm_mech.h"

enum { P_R, P_L, P_E, P_OMEGA, P_PHI, P_POINTS };

static const mm_param params[] = {
    [P_R] = {"r", "crank length", "m", MM_REAL, 0.1, 1e-3, 10, .help = "O to the crank pin A"},
    [P_L] = {"l", "rod length", "m", MM_REAL, 0.4, 1e-3, 10,
             .help = "A to the slider pin B; with l < r + |e| the crank cannot turn a full revolution"},
    [P_E] = {"e", "offset", "m", MM_REAL, 0, -10, 10,
             .help = "height of the slider's line above the crank pivot; non-zero gives a quick return"},
    [P_OMEGA] = {"omega", "crank speed", "rad/s", MM_REAL, 100, -1e4, 1e4,
                 .help = "constant angular velocity of the crank, counter-clockwise positive"},
    [P_PHI] = {"phi", "crank angle", "rad", MM_REAL, 0.5, -100, 100,
               .help = "the crank's angle from the x axis at the instant asked"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 121, 13, 721,
                  .help = "crank angles of the plots over the turn (or over the range the crank can reach)"},
};

enum {
    O_X, O_V, O_A, O_TH3, O_OM3, O_AL3, O_STROKE, O_XMAX, O_XMIN, O_PHI_OUT, O_PHI_IN, O_RATIO,
    O_TOG1, O_TOG2, O_NEWTON,
    O_SX, O_SV, O_SA, O_STH3, O_SMID, O_FDV, O_FDA, O_ANIM
};

static const char *const newton_cols[] = {"iteration", "residual", "step", NULL};
static const char *const newton_units[] = {"", "m", "", NULL};

static const mm_output outputs[] = {
    [O_X] = MM_SCALAR("x", "slider position", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_V] = MM_SCALAR("v", "slider velocity", "m/s", .flags = MM_ANSWER | MM_EXACT),
    [O_A] = MM_SCALAR("a", "slider acceleration", "m/s^2", .flags = MM_ANSWER | MM_EXACT),
    [O_TH3] = MM_SCALAR("theta3", "rod angle", "rad", .flags = MM_ANSWER | MM_EXACT),
    [O_OM3] = MM_SCALAR("omega3", "rod angular velocity", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_AL3] = MM_SCALAR("alpha3", "rod angular acceleration", "rad/s^2", .flags = MM_ANSWER | MM_EXACT),
    [O_STROKE] = MM_SCALAR("stroke", "stroke x_max - x_min", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_XMAX] = MM_SCALAR("x_max", "outer dead centre position", "m", .flags = MM_EXACT),
    [O_XMIN] = MM_SCALAR("x_min", "inner dead centre position", "m", .flags = MM_EXACT),
    [O_PHI_OUT] = MM_SCALAR("phi_outer", "crank angle at the outer dead centre", "rad", .flags = MM_EXACT),
    [O_PHI_IN] = MM_SCALAR("phi_inner", "crank angle at the inner dead centre", "rad", .flags = MM_EXACT),
    [O_RATIO] = MM_SCALAR("time_ratio", "time ratio, slow stroke / quick stroke", "",
                          .flags = MM_ANSWER | MM_EXACT),
    [O_TOG1] = MM_SCALAR("phi_toggle1", "crank angle of the first toggle (rod square to the slide)", "rad",
                         .flags = MM_EXACT),
    [O_TOG2] = MM_SCALAR("phi_toggle2", "crank angle of the second toggle", "rad", .flags = MM_EXACT),
    [O_NEWTON] = MM_TABLE("newton", "Newton's iterates at phi from the level rod: |Phi| and the weighted step",
                          newton_cols, newton_units),
    [O_SX] = MM_SERIES("x", "slider position", "m", "crank angle", "rad", .figure = "slider position"),
    [O_SV] = MM_SERIES("v", "slider velocity", "m/s", "crank angle", "rad", .figure = "slider velocity"),
    [O_SA] = MM_SERIES("a", "slider acceleration", "m/s^2", "crank angle", "rad", .figure = "slider acceleration"),
    [O_STH3] = MM_SERIES("theta3", "rod angle", "rad", "crank angle", "rad", .figure = "rod angle"),
    [O_SMID] = MM_SERIES("rod_midpoint", "path of the rod's midpoint", "m", "x", "m", .aspect = "equal",
                         .figure = "rod midpoint"),
    [O_FDV] = MM_KIN_FD_SERIES("fd_error_v", "worst error of the central difference of x vs dx/dphi", "m", "rad"),
    [O_FDA] = MM_KIN_FD_SERIES("fd_error_a", "worst error of the second difference of x vs d2x/dphi2", "m", "rad"),
    [O_ANIM] = MM_ANIMATION("the crank, the rod and the slider over the cycle, with the slider's velocity and acceleration"),
};

typedef mm_slider_crank sc;
typedef mm_sc_pos sc_pos;

static int check(const mm_value *in, mm_error *err)
{
    sc m = {in[P_R].x, in[P_L].x, in[P_E].x};
    double lo, hi;
    if (fabs(m.e) > m.l + m.r)
        return mm_error_set(err, MM_ERANGE, "e",
                            "the slide is out of the rod's reach at every crank angle: |e| must be at most "
                            "l + r = %g m; got %g m", m.l + m.r, m.e);
    if (mm_linkage_sc_reach(&m, in[P_PHI].x, &lo, &hi, NULL) < 0) {
        double up = (m.e + m.l) / m.r, dn = (m.e - m.l) / m.r;
        return mm_error_set(err, MM_ERANGE, "phi",
                            "the linkage cannot close at phi = %g rad: the rod (l = %g m) cannot reach the "
                            "slide there; it closes only where %g <= sin(phi) <= %g", in[P_PHI].x, m.l,
                            fmax(dn, -1), fmin(up, 1));
    }
    return MM_OK;
}

/* ---- Newton at phi, iterate by iterate ---------------------------------------------- */

/* From the level rod, q = (0, r cos phi + l), as a learner would guess: each
 * iterate's |Phi| and step into the table "newton".  When that guess leads
 * to the other assembly (slider left of A) or nowhere, start again from the
 * assembly built by intersecting the rod's circle with the slide. */
static int newton_at(const sc *m, const mm_mech_problem *prob, mm_mech_options *opt, mm_mech_work *w,
                     double phi, double *q, mm_mech_info *info, mm_result *res, mm_error *err)
{
    enum { KMAX = 12 };
    double rows[KMAX][2], guess[2] = {0, m->r * cos(phi) + m->l};
    int rc = MM_OK, k = 0;
    for (int attempt = 0; attempt < 2; attempt++) {
        if (attempt == 1) {                        /* the geometric assembly */
            double tt[2];
            if (mm_geom_line_circle((mm_v2){0, m->e}, (mm_v2){1, 0}, mm_v2_polar(m->r, phi), m->l, tt, NULL))
                guess[1] = tt[1];
            guess[0] = atan2(m->e - m->r * sin(phi), guess[1] - m->r * cos(phi));
        }
        double prev[2] = {guess[0], guess[1]};
        const int max_iter = opt->max_iter;
        for (k = 1; k <= KMAX; k++) {
            memcpy(q, guess, sizeof guess);
            opt->max_iter = k;
            rc = mm_mech_position(prob, opt, w, phi, q, info, NULL);
            double F[2];
            prob->phi(q, phi, F, prob->params);
            rows[k - 1][0] = fmax(fabs(F[0]), fabs(F[1]));
            rows[k - 1][1] = fmax(fabs(q[0] - prev[0]), fabs(q[1] - prev[1]) / m->l);
            memcpy(prev, q, sizeof prev);
            if (rc == MM_OK)
                break;
        }
        opt->max_iter = max_iter;
        if (rc == MM_OK && q[1] >= m->r * cos(phi) - 1e-9 * m->l)
            break;
        rc = MM_ENOCONV;
    }
    if (rc != MM_OK)
        return mm_error_set(err, MM_ENOCONV, "phi", "Newton could not assemble the linkage at phi = %g rad", phi);
    mm_table *t = mm_res_table(res, O_NEWTON, k);
    if (!t)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (int i = 0; i < k; i++) {
        t->cell[3 * i] = i + 1;
        t->cell[3 * i + 1] = rows[i][0];
        t->cell[3 * i + 2] = rows[i][1];
    }
    return MM_OK;
}

/* the assembly at phi (the slider right of the pin), for mm_kin_toggle_checks */
static void assemble(double phi, double *q, void *ctx)
{
    sc_pos c = mm_linkage_sc_closed(ctx, phi, 1);
    q[0] = c.t, q[1] = c.x;
}

/* ---- the answer ------------------------------------------------------------------------------ */

/* the error of a closed-form value that divides by R^k: rounding grows
 * like (l/|R|)^k; exact (MM_EXACT) while that stays below 1e3 */
static void put(mm_result *res, int o, double v, double scale, double kappa, int k)
{
    double amp = pow(kappa, k);
    mm_scalar *s = mm_res_scalar(res, o, v);
    if (amp > 1e3) {
        s->exact = 0;
        s->error = 8 * DBL_EPSILON * scale * amp;
        s->error_kind = MM_ERR_ESTIMATE;
    }
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    sc m = {in[P_R].x, in[P_L].x, in[P_E].x};
    const double omega = in[P_OMEGA].x, phi = in[P_PHI].x;
    const int n = (int)in[P_POINTS].x;
    mm_mech_problem prob;
    mm_linkage_sc_problem(&m, &prob);
    mm_mech_options opt;
    mm_mech_options_init(&opt);
    opt.length = m.l;
    opt.phi_scale = m.r + m.l + fabs(m.e);
    mm_mech_work *w = mm_mech_work_alloc(2, 2);
    if (!w)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    int rc = MM_OK;
    const double scale = m.r + m.l + fabs(m.e), tiny = 2 * DBL_EPSILON * m.l * m.l;

    /* ---- at phi: the closed form printed, Newton and the Jacobian solves checked ---- */
    sc_pos c = mm_linkage_sc_closed(&m, phi, 1);
    double D = mm_linkage_sc_disc(&m, phi), kappa = m.l / fmax(fabs(c.R), DBL_MIN);
    int at_toggle = D <= tiny;
    if (at_toggle) {
        /* the discriminant is zero within its rounding tiny: the true one lies
         * in [-tiny, tiny], so x and theta3 are known to sqrt(2 tiny) */
        mm_res_scalar_err(res, O_X, c.x, sqrt(2 * tiny), MM_ERR_BOUND);
        mm_res_scalar_err(res, O_TH3, c.t, sqrt(2 * tiny) / m.l, MM_ERR_BOUND);
    } else {
        put(res, O_X, c.x, scale, kappa, 1);
        put(res, O_TH3, c.t, 1, kappa, 1);
    }
    double q[2], qd[2], qdd[2];
    mm_mech_info info;
    if ((rc = newton_at(&m, &prob, &opt, w, phi, q, &info, res, err)) != MM_OK)
        goto out;
    double tol_x = 16 * DBL_EPSILON * scale * kappa + info.err_est * m.l;
    mm_res_check_abs(res, "x at phi: Newton on eq. (1) vs closed form (2)", q[1], c.x, tol_x);
    mm_res_check_abs(res, "theta3 at phi: Newton vs closed form (2)", mm_kin_near(q[0], c.t), c.t,
                     tol_x / m.l);
    if (at_toggle) {
        mm_res_warn(res, "phi = %g rad is a toggle: the rod stands square to the slide, the crank cannot be "
                         "driven through it at constant speed, and v, a, omega3, alpha3 are unbounded there "
                         "(left out)", phi);
    } else {
        put(res, O_V, omega * c.x1, fabs(omega) * scale, kappa, 3);
        put(res, O_A, omega * omega * c.x2, omega * omega * scale, kappa, 5);
        put(res, O_OM3, omega * c.t1, fabs(omega), kappa, 3);
        put(res, O_AL3, omega * omega * c.t2, omega * omega, kappa, 5);
        if ((rc = mm_mech_velocity(&prob, &opt, w, phi, q, qd, &info, err)) != MM_OK ||
            (rc = mm_mech_acceleration(&prob, &opt, w, phi, q, qd, qdd, &info, err)) != MM_OK)
            goto out;
        /* rounding of the solves: the sizes of the terms of (3) (a short rod
         * makes s'^2/R large beside r), amplified by the condition kappa */
        double k3 = kappa * kappa * kappa, s0 = m.e - m.r * sin(phi), s1 = m.r * cos(phi), aR = fabs(c.R);
        double M1 = scale + fabs(s0 * s1) / aR;
        double M2 = scale + (s1 * s1 + fabs(s0) * m.r) / aR + s0 * s0 * s1 * s1 / (aR * aR * aR);
        mm_res_check_abs(res, "v at phi: Jacobian solve (4) vs closed form (3)", omega * qd[1], omega * c.x1,
                         64 * DBL_EPSILON * fabs(omega) * M1 * k3);
        mm_res_check_abs(res, "a at phi: Jacobian solve (5) vs closed form (3)", omega * omega * qdd[1],
                         omega * omega * c.x2, 256 * DBL_EPSILON * omega * omega * M2 * k3 * kappa * kappa);
    }

    /* ---- the cycle: a full turn, or the arc the crank can reach ---- */
    double lo = 0, hi = 2 * M_PI, gaps[2] = {2 * M_PI, 2 * M_PI};
    int partial = mm_linkage_sc_reach(&m, phi, &lo, &hi, gaps) == 1;
    mm_series *sx = mm_res_series(res, O_SX, n), *sv = mm_res_series(res, O_SV, n);
    mm_series *sa = mm_res_series(res, O_SA, n), *st = mm_res_series(res, O_STH3, n);
    mm_series *sm = mm_res_series(res, O_SMID, n);
    double *Q = mm_res_alloc(res, 2 * (size_t)n * sizeof *Q), *QD = mm_res_alloc(res, 2 * (size_t)n * sizeof *QD);
    double *QDD = mm_res_alloc(res, 2 * (size_t)n * sizeof *QDD);
    if (!sx || !sv || !sa || !st || !sm || !Q || !QD || !QDD) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
        goto out;
    }
    /* a partial range is plotted inset from its toggles by 1e-3 of the arc:
     * at the toggle itself v and a are unbounded */
    double inset = partial ? 1e-3 * (hi - lo) : 0;
    mm_kin_grid(lo + inset, hi - inset, n, sx->x);
    c = mm_linkage_sc_closed(&m, sx->x[0], 1);
    Q[0] = c.t, Q[1] = c.x;
    mm_mech_sweep s = {.nt = n, .t = sx->x, .q = Q, .qd = QD, .qdd = QDD, .watch = 1};
    if ((rc = mm_mech_sweep_solve(&prob, &opt, w, &s, err)) != MM_OK)
        goto out;
    if (s.solved < n) {
        rc = mm_error_set(err, MM_ENOCONV, "phi", "the sweep lost the linkage at phi = %g rad", s.t_limit);
        goto out;
    }
    /* the sweep kept its branch: every frame on the closed form, within the
     * rounding of the largest term plus the rounding of the position
     * (residual eps (r + |e| + l) over the Jacobian's l cos theta3 = R)
     * carried through d/dR of eqs. (3); the frame nearest its bound */
    mm_kin_worst wx = {-1, 0, 0, 0}, wv = wx, wa = wx;
    for (int i = 0; i < n; i++) {
        double ph = sx->x[i];
        c = mm_linkage_sc_closed(&m, ph, 1);
        sv->x[i] = sa->x[i] = st->x[i] = ph;
        sx->y[i] = Q[2 * i + 1];
        sv->y[i] = omega * QD[2 * i + 1];
        sa->y[i] = omega * omega * QDD[2 * i + 1];
        st->y[i] = Q[2 * i];
        sm->x[i] = 0.5 * (m.r * cos(ph) + Q[2 * i + 1]);
        sm->y[i] = 0.5 * (m.r * sin(ph) + m.e);
        double sg = m.e - m.r * sin(ph), s1 = -m.r * cos(ph), s2 = m.r * sin(ph), R = fabs(c.R);
        double dR = 4 * DBL_EPSILON * scale * m.l / R + s.err_est * m.l;         /* position error */
        double tx = 16 * DBL_EPSILON * scale + dR;
        double tv = 16 * DBL_EPSILON * (m.r + fabs(sg * s1) / R) + dR * fabs(sg * s1) / (R * R);
        double Ta = m.r + (s1 * s1 + fabs(sg * s2)) / R + sg * sg * s1 * s1 / (R * R * R);
        double ta = 16 * DBL_EPSILON * Ta + dR * ((s1 * s1 + fabs(sg * s2)) / (R * R) + 3 * sg * sg * s1 * s1 / (R * R * R * R));
        mm_kin_track(&wx, Q[2 * i + 1], c.x, tx);
        mm_kin_track(&wv, QD[2 * i + 1], c.x1, tv);
        mm_kin_track(&wa, QDD[2 * i + 1], c.x2, ta);
    }
    mm_res_check_abs(res, "sweep: x vs closed form (2), the frame nearest its bound (the branch kept)", wx.got, wx.ref,
                     wx.tol);
    mm_res_check_abs(res, "sweep: dx/dphi vs closed form (3), the frame nearest its bound", wv.got, wv.ref, wv.tol);
    mm_res_check_abs(res, "sweep: d2x/dphi2 vs closed form (3), the frame nearest its bound", wa.got, wa.ref, wa.tol);

    /* the positions differenced: one sample in four, kept 4 h0 clear of
     * the toggles of a partial range (the steps must not leave it) */
    {
        double h0 = partial ? fmin(0.05, 0.02 * (hi - lo)) : 0.05;
        double *ph = mm_res_alloc(res, (size_t)n * sizeof *ph), *qs = mm_res_alloc(res, 2 * (size_t)n * sizeof *qs);
        double *d1 = mm_res_alloc(res, 2 * (size_t)n * sizeof *d1), *d2 = mm_res_alloc(res, 2 * (size_t)n * sizeof *d2);
        if (!ph || !qs || !d1 || !d2) {
            rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
            goto out;
        }
        int ns = 0;
        for (int i = 0; i < n; i += 4) {
            if (partial && (sx->x[i] < lo + 4 * h0 || sx->x[i] > hi - 4 * h0))
                continue;
            ph[ns] = sx->x[i];
            memcpy(qs + 2 * ns, Q + 2 * i, 2 * sizeof *qs);
            memcpy(d1 + 2 * ns, QD + 2 * i, 2 * sizeof *d1);
            memcpy(d2 + 2 * ns, QDD + 2 * i, 2 * sizeof *d2);
            ns++;
        }
        mm_kin_link_fd fc = {&prob, &opt, w, ph, qs, d1, d2};
        const double wt[2] = {1, 1 / m.l};
        if ((rc = mm_kin_fd_va(res, O_FDV, O_FDA, "dq/dphi", "d2q/dphi2", mm_kin_link_fd_pos, &fc, 2, wt, ns, d1, d2, h0, 0,
                               0, err)) != MM_OK)
            goto out;
    }

    if (!partial) {
        /* dead centres: crank and rod in line, eq. (6) */
        double po = asin(m.e / (m.l + m.r)), pi_ = M_PI + asin(m.e / (m.l - m.r));
        double xo = sqrt((m.l + m.r - m.e) * (m.l + m.r + m.e)), xi = sqrt((m.l - m.r - m.e) * (m.l - m.r + m.e));
        mm_res_scalar(res, O_STROKE, xo - xi);
        mm_res_scalar(res, O_XMAX, xo);
        mm_res_scalar(res, O_XMIN, xi);
        mm_res_scalar(res, O_PHI_OUT, po);
        mm_res_scalar(res, O_PHI_IN, pi_);
        double beta = asin(m.e / (m.l - m.r)) - asin(m.e / (m.l + m.r));   /* eq. (7) */
        mm_res_scalar(res, O_RATIO, (M_PI + fabs(beta)) / (M_PI - fabs(beta)));
        /* where x turns back, located by a sweep that starts between them */
        enum { NT = 25 };
        double t[NT], qq[2 * NT], vv[2 * NT];
        for (int i = 0; i < NT; i++)
            t[i] = po + 0.25 + 2 * M_PI * i / (NT - 1);
        c = mm_linkage_sc_closed(&m, t[0], 1);
        qq[0] = c.t, qq[1] = c.x;
        mm_mech_sweep dc = {.nt = NT, .t = t, .q = qq, .qd = vv, .watch = 1};
        if ((rc = mm_mech_sweep_solve(&prob, &opt, w, &dc, err)) != MM_OK)
            goto out;
        mm_res_check_abs(res, "dead centres: turning points of x found by the sweep over a turn", dc.n_turn, 2, 0);
        for (int k = 0; k < dc.n_turn && k < 2; k++) {
            int outer = dc.q_turn[k] > 0.5 * (xo + xi);
            double want = outer ? po : pi_;
            double got = want + remainder(dc.t_turn[k] - want, 2 * M_PI);
            /* bisection to 1e-11 of the turn, then the secant of v: rounding of phi */
            mm_res_check_abs(res, outer ? "outer dead centre: located by the sweep (v = 0) vs eq. (6)"
                                        : "inner dead centre: located by the sweep (v = 0) vs eq. (6)",
                             got, want, 64 * DBL_EPSILON * (1 + fabs(want)));
        }
    } else {
        mm_res_scalar(res, O_TOG1, lo);
        mm_res_scalar(res, O_TOG2, hi);
        char what[200];
        snprintf(what, sizeof what, "the rod is too short for the offset: the crank cannot turn a full revolution; "
                 "it reaches only %.4g to %.4g rad (toggles, where the rod stands square to the slide)", lo, hi);
        mm_kin_warn_reach(res, what, lo, hi, gaps);
        /* the sweep run past each end stops where the closed form says */
        if ((rc = mm_kin_toggle_checks(res, &prob, &opt, w, lo, hi, gaps, assemble, &m,
                                       "sin(phi) = (e - l)/r or (e + l)/r", err)) != MM_OK)
            goto out;
    }
    mm_res_method(res, "Newton-Raphson on the loop closure, Jacobian solves for velocity and acceleration", 0);
    mm_res_method_stat(res, "sweep_steps", s.steps);
    mm_res_method_stat(res, "newton_iterations", s.newton);
    mm_res_method_stat(res, "error_estimate", s.err_est);
    rc = mm_kin_sc_animate(&m, omega, partial, lo, hi, &prob, &opt, w, res, err);
out:
    mm_mech_work_free(w);
    return rc;
}

static const char *const references[] = {
    "R. L. Norton, Design of Machinery, 5th ed., McGraw-Hill 2012, sections 4.13, 6.7 and 7.6",
    "E. J. Haug, Computer Aided Kinematics and Dynamics of Mechanical Systems, Allyn and Bacon 1989, ch. 3",
    NULL,
};

const mm_exercise mm_ex_kin_slider_crank = {
    .id = "kin-slider-crank", .chapter = 2, .section = "2.4.4",
    .title = "Slider-crank mechanism",
    .summary = "Position, velocity and acceleration of the slider over a turn: dead centres, stroke, "
               "offset and quick return, toggles of a short rod.",
    .tags = "kinematics, mechanism, slider-crank, loop closure, Newton-Raphson, dead centre",
    .theory = "exercises/kin/slider_crank.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
