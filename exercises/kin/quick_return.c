/* quick_return.c — kin-quick-return: the crank and slotted lever of a
 * shaping machine.  The crank O2A (r) turns at constant omega about O2 =
 * (0, d); its pin A slides in the slot of a lever pivoted at O4 = (0, 0);
 * the lever's slot also drives a block on the ram, which runs along the
 * line y = H.
 *
 *     s cos th4 = r cos th2,        s sin th4 = d + r sin th2
 *     s2 cos th4 = X,               s2 sin th4 = H                          (1)
 *     th4 = atan2(d + r sin th2, r cos th2),  X = H r cos th2 / (d + r sin th2)   (2)
 *     time ratio = (pi + 2 alpha) / (pi - 2 alpha),  sin alpha = r / d        (3)
 *
 * Goal: one turn of the crank drives the ram out slowly (the cutting stroke)
 * and back quickly: the lever's two dead centres, where it is tangent to
 * the crank circle, split the turn unequally.
 * Method: eq. (1) in q = (th4, s, X, s2) by Newton-Raphson (mm_mech), the
 * velocities and accelerations by Jacobian solves.  Checks: the closed
 * forms (2) and their derivatives; central differences of the positions;
 * the dead centres the sweep located (the ram turning back) against
 * sin th2 = -r/d, and the time ratio they give against (3).
 * Reference: R. L. Norton, Design of Machinery, 5th ed., section 3.8;
 * J. E. Shigley, J. J. Uicker, Theory of Machines and Mechanisms, ch. 1.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "mm_kin.h"
#include "mm_kin_linkage.h"
#include "mm_linkage.h"
#include "mm_mech.h"

enum { P_R, P_D, P_H, P_W, P_TH, P_POINTS };

static const mm_param params[] = {
    [P_R] = {"r", "crank length", "m", MM_REAL, 0.1, 1e-3, 10, .help = "O2 to the crank pin A; less than d"},
    [P_D] = {"d", "distance O4 O2", "m", MM_REAL, 0.25, 1e-3, 10,
             .help = "the lever's pivot O4 is d below the crank's O2; r / d sets the time ratio"},
    [P_H] = {"H", "height of the ram's line above O4", "m", MM_REAL, 0.45, 1e-3, 20,
             .help = "the stroke is 2 H r / sqrt(d^2 - r^2)"},
    [P_W] = {"omega", "crank speed", "rad/s", MM_REAL, 10, -1000, 1000, .help = "constant, counter-clockwise positive"},
    [P_TH] = {"theta2", "crank angle", "rad", MM_REAL, 0.5, -100, 100, .help = "from the horizontal through O2"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 121, 13, 721, .help = "crank angles of the plots over the turn"},
};

enum {
    O_TH4, O_W4, O_A4, O_X, O_V, O_A, O_STROKE, O_RATIO, O_VCUT, O_VRET, O_DC1, O_DC2,
    O_SX, O_SV, O_SA, O_STH4, O_FDV, O_FDA, O_ANIM
};

static const mm_output outputs[] = {
    [O_TH4] = MM_SCALAR("theta4", "lever angle", "rad", .flags = MM_ANSWER | MM_EXACT),
    [O_W4] = MM_SCALAR("omega4", "lever angular velocity", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_A4] = MM_SCALAR("alpha4", "lever angular acceleration", "rad/s^2", .flags = MM_EXACT),
    [O_X] = MM_SCALAR("x_ram", "ram position (from the line through O4 and O2)", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_V] = MM_SCALAR("v_ram", "ram velocity", "m/s", .flags = MM_ANSWER | MM_EXACT),
    [O_A] = MM_SCALAR("a_ram", "ram acceleration", "m/s^2", .flags = MM_ANSWER | MM_EXACT),
    [O_STROKE] = MM_SCALAR("stroke", "ram stroke 2 H r / sqrt(d^2 - r^2)", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_RATIO] = MM_SCALAR("time_ratio", "time ratio, cutting stroke / return stroke", "", .flags = MM_ANSWER | MM_EXACT),
    [O_VCUT] = MM_SCALAR("v_cut_avg", "mean ram speed on the cutting stroke", "m/s", .flags = MM_EXACT),
    [O_VRET] = MM_SCALAR("v_return_avg", "mean ram speed on the return", "m/s", .flags = MM_EXACT),
    [O_DC1] = MM_SCALAR("theta2_dead1", "crank angle at the ram's outer end (lever tangent to the crank circle)", "rad",
                        .flags = MM_EXACT),
    [O_DC2] = MM_SCALAR("theta2_dead2", "crank angle at the ram's inner end", "rad", .flags = MM_EXACT),
    [O_SX] = MM_SERIES("x_ram", "ram position", "m", "crank angle", "rad", .figure = "ram position"),
    [O_SV] = MM_SERIES("v_ram", "ram velocity", "m/s", "crank angle", "rad", .figure = "ram velocity"),
    [O_SA] = MM_SERIES("a_ram", "ram acceleration", "m/s^2", "crank angle", "rad", .figure = "ram acceleration"),
    [O_STH4] = MM_SERIES("theta4", "lever angle", "rad", "crank angle", "rad", .figure = "lever angle"),
    [O_FDV] = MM_KIN_FD_SERIES("fd_error_v",
                               "worst error of the central difference of (theta4, X) vs eq. (2)'s derivative", "", "rad"),
    [O_FDA] = MM_KIN_FD_SERIES("fd_error_a", "worst error of the second difference", "", "rad"),
    [O_ANIM] = MM_ANIMATION("crank, slotted lever and ram over a turn, with the ram's velocity"),
};

typedef mm_quick_return qr;
typedef mm_qr_pos qr_pos;

static int check(const mm_value *in, mm_error *err)
{
    double r = in[P_R].x, d = in[P_D].x, H = in[P_H].x;
    if (!(r <= 0.95 * d))
        return mm_error_set(err, MM_ERANGE, "r", "the crank must be at most 0.95 d = %g m: at r = d the crank "
                            "passes the lever's pivot and the stroke grows without bound (at 0.95 d it is already "
                            "6 H, with a time ratio of 8.9); got %g m", 0.95 * d, r);
    if (!(H > d + r))
        return mm_error_set(err, MM_ERANGE, "H", "the ram's line must pass above the crank circle, H > d + r = %g m; "
                            "got %g m", d + r, H);
    return MM_OK;
}

typedef struct fd_ctx {
    const mm_mech_problem *p;
    const mm_mech_options *o;
    mm_mech_work *w;
    const double *th, *q;
} fd_ctx;

static int fd_pos(int i, double h, double *q, double *qerr, void *ctx, mm_error *err)
{
    fd_ctx *c = ctx;
    mm_mech_info info;
    double full[4];
    memcpy(full, c->q + 4 * i, sizeof full);
    int rc = mm_mech_position(c->p, c->o, c->w, c->th[i] + h, full, &info, err);
    q[0] = full[0], q[1] = full[2];                       /* theta4 and X */
    *qerr = info.err_est;
    return rc;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    qr m = {in[P_R].x, in[P_D].x, in[P_H].x};
    const double w = in[P_W].x, th = in[P_TH].x;
    /* the lever is drawn long enough to reach the ram at its dead centres */
    const double L = 1.15 * m.H * m.d / sqrt((m.d - m.r) * (m.d + m.r));
    const int n = (int)in[P_POINTS].x;
    mm_mech_problem prob;
    mm_linkage_qr_problem(&m, &prob);
    mm_mech_options opt;
    mm_mech_options_init(&opt);
    opt.length = m.H, opt.phi_scale = m.H + m.d + m.r + L;
    mm_mech_work *wk = mm_mech_work_alloc(4, 4);
    if (!wk)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    int rc = MM_OK;
    const double al = asin(m.r / m.d), root = sqrt((m.d - m.r) * (m.d + m.r));

    /* ---- at theta2: the closed form printed, Newton and the solves checked ---- */
    qr_pos c = mm_linkage_qr_closed(&m, th);
    mm_res_scalar(res, O_TH4, c.t4);
    mm_res_scalar(res, O_W4, w * c.t4p);
    mm_res_scalar(res, O_A4, w * w * c.t4pp);
    mm_res_scalar(res, O_X, c.X);
    mm_res_scalar(res, O_V, w * c.Xp);
    mm_res_scalar(res, O_A, w * w * c.Xpp);
    double q[4], qd[4], qdd[4];
    mm_linkage_qr_guess(&m, th, q);
    mm_mech_info info;
    if ((rc = mm_mech_position(&prob, &opt, wk, th, q, &info, err)) != MM_OK ||
        (rc = mm_mech_velocity(&prob, &opt, wk, th, q, qd, NULL, err)) != MM_OK ||
        (rc = mm_mech_acceleration(&prob, &opt, wk, th, q, qd, qdd, NULL, err)) != MM_OK)
        goto out;
    /* positions: Newton's own estimate; rates: a few eps of the largest terms
     * of X' and X'' (their denominators (d + r sin th2)^k are smallest at
     * d - r), plus the positions' error carried through */
    double dq = info.err_est, g = m.d - m.r;
    double big1 = m.H * m.r * (m.d + m.r) / (g * g), big2 = m.H * m.r * (3 * m.d + 2 * m.r) * (m.d + m.r) / (g * g * g);
    mm_res_check_abs(res, "theta4: Newton on eq. (1) vs eq. (2)", mm_kin_near(q[0], c.t4), c.t4, 4 * dq + 16 * DBL_EPSILON);
    mm_res_check_abs(res, "x_ram: Newton on eq. (1) vs eq. (2)", q[2], c.X, (4 * dq + 16 * DBL_EPSILON) * m.H);
    mm_res_check_abs(res, "v_ram per unit omega: Jacobian solve vs d/dtheta2 of eq. (2)", qd[2], c.Xp,
                     (32 * DBL_EPSILON + 4 * dq) * big1);
    mm_res_check_abs(res, "a_ram per unit omega^2: Jacobian solve vs d2/dtheta2^2 of eq. (2)", qdd[2], c.Xpp,
                     (32 * DBL_EPSILON + 4 * dq) * big2);

    /* ---- the stroke and the time ratio, eq. (3) ---- */
    double stroke = 2 * m.H * m.r / root, ratio = (M_PI + 2 * al) / (M_PI - 2 * al);
    mm_res_scalar(res, O_STROKE, stroke);
    mm_res_scalar(res, O_RATIO, ratio);
    mm_res_scalar(res, O_VCUT, stroke * fabs(w) / (M_PI + 2 * al));
    mm_res_scalar(res, O_VRET, stroke * fabs(w) / (M_PI - 2 * al));
    mm_res_scalar(res, O_DC1, -al);
    mm_res_scalar(res, O_DC2, M_PI + al);

    /* ---- the turn ---- */
    mm_series *sx = mm_res_series(res, O_SX, n), *sv = mm_res_series(res, O_SV, n), *sa = mm_res_series(res, O_SA, n);
    mm_series *st = mm_res_series(res, O_STH4, n);
    double *Q = mm_res_alloc(res, 4 * (size_t)n * sizeof *Q), *QD = mm_res_alloc(res, 4 * (size_t)n * sizeof *QD);
    double *QDD = mm_res_alloc(res, 4 * (size_t)n * sizeof *QDD);
    if (!sx || !sv || !sa || !st || !Q || !QD || !QDD) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
        goto out;
    }
    mm_kin_grid(0, 2 * M_PI, n, sx->x);
    mm_linkage_qr_guess(&m, 0, Q);
    mm_mech_sweep s = {.nt = n, .t = sx->x, .q = Q, .qd = QD, .qdd = QDD, .watch = 2};
    if ((rc = mm_mech_sweep_solve(&prob, &opt, wk, &s, err)) != MM_OK)
        goto out;
    double worst = -1, wv = 0, wr = 0, wt = 1;
    for (int i = 0; i < n; i++) {
        qr_pos ci = mm_linkage_qr_closed(&m, sx->x[i]);
        sv->x[i] = sa->x[i] = st->x[i] = sx->x[i];
        sx->y[i] = Q[4 * i + 2], sv->y[i] = w * QD[4 * i + 2], sa->y[i] = w * w * QDD[4 * i + 2];
        st->y[i] = Q[4 * i];
        double tol = (4 * s.err_est + 16 * DBL_EPSILON) * m.H, e = fabs(Q[4 * i + 2] - ci.X);
        if (e / tol > worst)
            worst = e / tol, wv = Q[4 * i + 2], wr = ci.X, wt = tol;
    }
    mm_res_check_abs(res, "sweep: x_ram on every frame vs eq. (2), the frame nearest its bound", wv, wr, wt);
    /* the ram's dead centres: where the sweep found X' = 0 */
    mm_res_check_abs(res, "dead centres: turning points of the ram found by the sweep over a turn", s.n_turn, 2, 0);
    if (s.n_turn == 2) {
        double t1 = s.t_turn[0], t2 = s.t_turn[1];
        double a = mm_kin_near(-al, t1), b = mm_kin_near(M_PI + al, t2);
        if (fabs(mm_kin_wrap(t1 - (M_PI + al))) < fabs(mm_kin_wrap(t1 + al)))   /* found in the other order */
            a = mm_kin_near(M_PI + al, t1), b = mm_kin_near(-al, t2);
        /* bisection to 1e-11 of the turn, then the secant of X': rounding of theta2 */
        mm_res_check_abs(res, "first dead centre: located by the sweep vs sin(theta2) = -r/d", t1, a,
                         64 * DBL_EPSILON * (1 + fabs(a)));
        mm_res_check_abs(res, "second dead centre: located by the sweep vs sin(theta2) = -r/d", t2, b,
                         64 * DBL_EPSILON * (1 + fabs(b)));
        /* the turn split by them: the longer part over the shorter */
        double arc = t2 - t1 - 2 * M_PI * floor((t2 - t1) / (2 * M_PI));
        double meas = fmax(arc, 2 * M_PI - arc) / fmin(arc, 2 * M_PI - arc);
        mm_res_check_rel(res, "time ratio from the located dead centres vs eq. (3)", meas, ratio,
                         256 * DBL_EPSILON * ratio / (M_PI - 2 * al));
    }
    /* central differences of theta4 and X, X weighted by 1/H */
    {
        int ns = (n + 3) / 4;
        double *ph = mm_res_alloc(res, (size_t)ns * sizeof *ph), *qs = mm_res_alloc(res, 4 * (size_t)ns * sizeof *qs);
        double *d1 = mm_res_alloc(res, 2 * (size_t)ns * sizeof *d1), *d2 = mm_res_alloc(res, 2 * (size_t)ns * sizeof *d2);
        if (!ph || !qs || !d1 || !d2) {
            rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
            goto out;
        }
        for (int j = 0; j < ns; j++) {
            int i = 4 * j < n ? 4 * j : n - 1;
            ph[j] = sx->x[i];
            memcpy(qs + 4 * j, Q + 4 * i, 4 * sizeof *qs);
            d1[2 * j] = QD[4 * i], d1[2 * j + 1] = QD[4 * i + 2];
            d2[2 * j] = QDD[4 * i], d2[2 * j + 1] = QDD[4 * i + 2];
        }
        fd_ctx fc = {&prob, &opt, wk, ph, qs};
        const double wt2[2] = {1, 1 / m.H};
        /* theta4's Taylor series about theta2 = pi converges within (d - r)/r
         * (the block passes closest to O there): steps well inside it */
        double h0 = fmin(0.05, 0.1 * (m.d - m.r) / m.r);
        if ((rc = mm_kin_fd_va(res, O_FDV, O_FDA, "d(theta4, X)/dtheta2", "d2(theta4, X)/dtheta2^2", fd_pos, &fc, 2,
                               wt2, ns, d1, d2, h0, 0, 0, err)) != MM_OK)
            goto out;
    }

    mm_res_method(res, "Newton-Raphson on the loop closure, Jacobian solves for velocity and acceleration", 0);
    mm_res_method_stat(res, "error_estimate", s.err_est);
    rc = mm_kin_qr_animate(&m, w, L, stroke, &prob, &opt, wk, Q, res, err);
out:
    mm_mech_work_free(wk);
    return rc;
}

static const char *const references[] = {
    "R. L. Norton, Design of Machinery, 5th ed., McGraw-Hill 2012, section 3.8 (quick-return mechanisms)",
    "J. E. Shigley, J. J. Uicker, Theory of Machines and Mechanisms, ch. 1 (the Whitworth and crank-shaper)", NULL,
};

const mm_exercise mm_ex_kin_quick_return = {
    .id = "kin-quick-return", .chapter = 2, .section = "2.4.4",
    .title = "Quick-return mechanism: crank and slotted lever",
    .summary = "A shaper's crank and slotted lever: ram position, velocity and acceleration, the stroke, the "
               "dead centres and the time ratio of cutting to return.",
    .tags = "kinematics, mechanism, quick return, shaper, slotted lever, time ratio",
    .theory = "exercises/kin/quick_return.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
