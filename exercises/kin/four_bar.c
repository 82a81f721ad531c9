/* four_bar.c — kin-four-bar: the crank O2B (a) turns at constant omega2,
 * the coupler BC (b) joins it to the rocker O4C (c); the ground O2O4 is d.
 *
 *     a cos th2 + b cos th3 - c cos th4 - d = 0
 *     a sin th2 + b sin th3 - c sin th4     = 0                              (1)
 *
 * Goal: the angles, angular velocities and accelerations of coupler and
 * rocker; Grashof's condition and the class it gives; the transmission
 * angle over the cycle (its extremes and where); the coupler curve of a
 * point P; the rocker's dead centres; toggles of a crank that cannot turn
 * round, and the change point of s + l = p + q where the two assemblies
 * cross.  Method: eq. (1) by Newton-Raphson (mm_mech) from frame to frame
 * (the assembly kept), velocities and accelerations by linear solves with
 * its Jacobian.  Checks: Freudenstein's equation (closed form of the
 * angles), the velocity and acceleration closed forms, central differences
 * of the positions, the toggles and dead centres of the closed form
 * against those the sweep located, the transmission angle by the law of
 * cosines.
 * Reference: R. L. Norton, Design of Machinery, 5th ed., sections 2.12
 * (Grashof), 4.5-4.10 (positions, Freudenstein), 6.7, 7.3; F. Freudenstein,
 * Trans. ASME 77 (1955) 853-861.
 * API.md: O2 = (0, 0), O4 = (d, 0); "open" puts C left of the directed line
 * from B to O4, "crossed" right of it.
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

enum { P_A, P_B, P_C, P_D, P_OMEGA2, P_THETA2, P_BRANCH, P_PX, P_PY, P_POINTS };

static const char *const branches[] = {"open", "crossed", NULL};

static const mm_param params[] = {
    [P_A] = {"a", "crank O2B", "m", MM_REAL, 0.2, 0.01, 10, .help = "the driven link, pivoted at O2 = (0, 0)"},
    [P_B] = {"b", "coupler BC", "m", MM_REAL, 0.5, 0.01, 10, .help = "the floating link"},
    [P_C] = {"c", "rocker O4C", "m", MM_REAL, 0.4, 0.01, 10, .help = "the output link, pivoted at O4 = (d, 0)"},
    [P_D] = {"d", "ground O2O4", "m", MM_REAL, 0.6, 0.01, 10, .help = "distance between the fixed pivots"},
    [P_OMEGA2] = {"omega2", "crank speed", "rad/s", MM_REAL, 10, -1e4, 1e4,
                  .help = "constant angular velocity of the crank, counter-clockwise positive"},
    [P_THETA2] = {"theta2", "crank angle", "rad", MM_REAL, 1, -100, 100,
                  .help = "the crank's angle from O2O4 at the instant asked"},
    [P_BRANCH] = {"branch", "assembly", "", MM_CHOICE, 0, 0, 1, .choices = branches,
                  .help = "open: C left of the line from B to O4; crossed: right of it"},
    [P_PX] = {"px", "coupler point along BC", "m", MM_REAL, 0.25, -10, 10,
              .help = "P's coordinate from B along BC: its path is the coupler curve"},
    [P_PY] = {"py", "coupler point across BC", "m", MM_REAL, 0.15, -10, 10,
              .help = "P's coordinate across BC, to its left"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 121, 13, 721,
                  .help = "crank angles of the plots over the turn (or over the range the crank can reach)"},
};

enum {
    O_TH3, O_TH4, O_OM3, O_OM4, O_AL3, O_AL4, O_GRASHOF, O_MU, O_MU_MIN, O_MU_MAX, O_TH_MUMIN, O_TH_MUMAX,
    O_SWING, O_TOG1, O_TOG2, O_VP, O_AP,
    O_S3, O_S4, O_SW3, O_SW4, O_SA3, O_SA4, O_SMU, O_SCOUP, O_FDV, O_FDA, O_ANIM
};

static const mm_output outputs[] = {
    [O_TH3] = MM_SCALAR("theta3", "coupler angle", "rad", .flags = MM_ANSWER | MM_EXACT),
    [O_TH4] = MM_SCALAR("theta4", "rocker angle", "rad", .flags = MM_ANSWER | MM_EXACT),
    [O_OM3] = MM_SCALAR("omega3", "coupler angular velocity", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_OM4] = MM_SCALAR("omega4", "rocker angular velocity", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_AL3] = MM_SCALAR("alpha3", "coupler angular acceleration", "rad/s^2", .flags = MM_ANSWER | MM_EXACT),
    [O_AL4] = MM_SCALAR("alpha4", "rocker angular acceleration", "rad/s^2", .flags = MM_ANSWER | MM_EXACT),
    [O_GRASHOF] = MM_SCALAR("grashof", "Grashof: s + l <= p + q (1) or not (0)", "", .flags = MM_ANSWER | MM_EXACT),
    [O_MU] = MM_SCALAR("mu", "transmission angle at theta2 (between coupler and rocker)", "rad",
                       .flags = MM_ANSWER | MM_EXACT),
    [O_MU_MIN] = MM_SCALAR("mu_min", "smallest transmission angle over the cycle", "rad", .flags = MM_ANSWER | MM_EXACT),
    [O_MU_MAX] = MM_SCALAR("mu_max", "largest transmission angle over the cycle", "rad", .flags = MM_ANSWER | MM_EXACT),
    [O_TH_MUMIN] = MM_SCALAR("theta2_mu_min", "crank angle of the smallest transmission angle", "rad", .flags = MM_EXACT),
    [O_TH_MUMAX] = MM_SCALAR("theta2_mu_max", "crank angle of the largest transmission angle", "rad", .flags = MM_EXACT),
    [O_SWING] = MM_SCALAR("rocker_swing", "the rocker's swing between its dead centres", "rad", .flags = MM_EXACT),
    [O_TOG1] = MM_SCALAR("theta2_toggle1", "crank angle of the first toggle (coupler and rocker in line)", "rad",
                         .flags = MM_EXACT),
    [O_TOG2] = MM_SCALAR("theta2_toggle2", "crank angle of the second toggle", "rad", .flags = MM_EXACT),
    [O_VP] = MM_SCALAR("v_P", "speed of the coupler point", "m/s", .flags = MM_EXACT),
    [O_AP] = MM_SCALAR("a_P", "acceleration of the coupler point", "m/s^2", .flags = MM_EXACT),
    [O_S3] = MM_SERIES("theta3", "coupler angle", "rad", "crank angle", "rad", .figure = "angles"),
    [O_S4] = MM_SERIES("theta4", "rocker angle", "rad", "crank angle", "rad", .figure = "angles"),
    [O_SW3] = MM_SERIES("omega3", "coupler angular velocity", "rad/s", "crank angle", "rad", .figure = "angular velocities"),
    [O_SW4] = MM_SERIES("omega4", "rocker angular velocity", "rad/s", "crank angle", "rad", .figure = "angular velocities"),
    [O_SA3] = MM_SERIES("alpha3", "coupler angular acceleration", "rad/s^2", "crank angle", "rad",
                        .figure = "angular accelerations"),
    [O_SA4] = MM_SERIES("alpha4", "rocker angular acceleration", "rad/s^2", "crank angle", "rad",
                        .figure = "angular accelerations"),
    [O_SMU] = MM_SERIES("mu", "transmission angle", "rad", "crank angle", "rad", .figure = "transmission angle"),
    [O_SCOUP] = MM_SERIES("coupler_curve", "path of the coupler point P", "m", "x", "m", .aspect = "equal",
                          .figure = "coupler curve"),
    [O_FDV] = MM_KIN_FD_SERIES("fd_error_v", "worst error of the central difference of theta3, theta4 vs d/dtheta2",
                               "rad", "rad"),
    [O_FDA] = MM_KIN_FD_SERIES("fd_error_a", "worst error of the second difference vs d2/dtheta2^2", "rad", "rad"),
    [O_ANIM] = MM_ANIMATION("crank, coupler and rocker over the cycle, the coupler curve, the velocity and "
                            "acceleration of P"),
};

typedef mm_fourbar fb;
typedef mm_fourbar_class fb_class;

static int check(const mm_value *in, mm_error *err)
{
    fb m = {in[P_A].x, in[P_B].x, in[P_C].x, in[P_D].x};
    const char *names[4] = {"a", "b", "c", "d"};
    double L[4] = {m.a, m.b, m.c, m.d}, sum = m.a + m.b + m.c + m.d;
    for (int i = 0; i < 4; i++)
        if (L[i] > sum - L[i])
            return mm_error_set(err, MM_ERANGE, names[i],
                                "the four links cannot close: %s = %g m is longer than the other three together "
                                "(%g m)", names[i], L[i], sum - L[i]);
    double th2 = in[P_THETA2].x, tiny = 8 * DBL_EPSILON * sum * sum;
    if (mm_linkage_fb_disc(&m, th2) < -tiny) {
        fb_class k = mm_linkage_fb_classify(&m, th2);
        return mm_error_set(err, MM_ERANGE, "theta2",
                            "the linkage cannot close at theta2 = %g rad: B is out of the coupler and rocker's "
                            "reach there; the crank can reach %.6g to %.6g rad (toggles at the ends)", th2,
                            k.lo, k.hi);
    }
    return MM_OK;
}

/* the assembly at th2 on the side asked, for mm_kin_toggle_checks */
typedef struct fb_side {
    const fb *m;
    int side;
} fb_side;

static void assemble(double th2, double *q, void *ctx)
{
    const fb_side *c = ctx;
    mm_linkage_fb_assemble(c->m, th2, c->side, q);
}

/* ---- the answer ------------------------------------------------------------------------------ */

/* a closed-form value: exact while its rounding bound stays below 1e-12 of
 * its size (or 1e-15 absolute), else printed with that bound as estimate */
static void put(mm_result *res, int o, double v, double bound)
{
    mm_scalar *s = mm_res_scalar(res, o, v + 0.0);                    /* no -0 */
    if (bound > 1e-12 * fabs(v) && bound > 1e-15) {
        s->exact = 0;
        s->error = bound;
        s->error_kind = MM_ERR_ESTIMATE;
    }
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    fb m = {in[P_A].x, in[P_B].x, in[P_C].x, in[P_D].x};
    const double w2 = in[P_OMEGA2].x, th2 = in[P_THETA2].x, px = in[P_PX].x, py = in[P_PY].x;
    const int side = in[P_BRANCH].x == 0 ? 1 : -1, n = (int)in[P_POINTS].x;
    const double S = m.a + m.b + m.c + m.d, tiny = 8 * DBL_EPSILON * S * S;
    mm_mech_problem prob;
    mm_linkage_fb_problem(&m, &prob);
    mm_mech_options opt;
    mm_mech_options_init(&opt);
    opt.phi_scale = S;
    mm_mech_work *w = mm_mech_work_alloc(2, 2);
    if (!w)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_kin_fb_run run = {&m, &prob, &opt, w};
    fb_class k = mm_linkage_fb_classify(&m, th2);
    int rc = MM_OK;
    mm_res_scalar_text(res, O_GRASHOF, k.grashof, k.name);

    /* ---- at theta2: Freudenstein printed, Newton and the Jacobian solves checked ---- */
    double t3, t4, q[2], qd[2], qdd[2], tol[3], ferr;
    mm_linkage_fb_angles(&m, th2, side, &t3, &t4, &ferr);
    int singular = mm_linkage_fb_disc(&m, th2) <= tiny;
    mm_linkage_fb_assemble(&m, th2, side, q);
    mm_mech_info info;
    if ((rc = mm_mech_position(&prob, &opt, w, th2, q, &info, err)) != MM_OK)
        goto out;
    double w3 = 0, w4 = 0, a3 = 0, a4 = 0;
    if (!singular)
        mm_linkage_fb_rates(&m, th2, t3, t4, &w3, &w4, &a3, &a4);
    double r1[2] = {w3, w4}, r2[2] = {a3, a4}, qq[2] = {t3, t4};
    mm_linkage_fb_frame_tol(&m, qq, r1, r2, mm_linkage_fb_newton_err(&m, qq, info.err_est) + ferr, tol);
    if (singular) {
        /* a toggle or a change point: the discriminant is zero within its
         * rounding, the angles known to sqrt of it */
        double b = sqrt(2 * tiny) / fmin(m.b, m.c);
        mm_res_scalar_err(res, O_TH3, t3, b, MM_ERR_BOUND);
        mm_res_scalar_err(res, O_TH4, t4, b, MM_ERR_BOUND);
        tol[0] = b;
        mm_res_warn(res, "theta2 = %g rad is a %s: coupler and rocker lie in line, the Jacobian of eq. (1) is "
                         "singular, the crank cannot drive the linkage through at constant speed, and omega3, "
                         "omega4, alpha3, alpha4 are not defined there (left out)", th2,
                    k.change_point ? "change point (all four links in line)" : "toggle");
    } else {
        put(res, O_TH3, t3, tol[0]);
        put(res, O_TH4, t4, tol[0]);
    }
    mm_res_check_abs(res, "theta3 at theta2: Newton on eq. (1) vs Freudenstein (2)", mm_kin_near(q[0], t3), t3, tol[0]);
    mm_res_check_abs(res, "theta4 at theta2: Newton on eq. (1) vs Freudenstein (3)", mm_kin_near(q[1], t4), t4, tol[0]);
    /* mu by the law of cosines: its cosine carries a few eps of the terms,
     * which near 0 or pi (a toggle) move mu by up to sqrt of that */
    double mu = mm_linkage_fb_mu(&m, th2);
    double dx = 4 * DBL_EPSILON * (m.a * m.a + m.d * m.d + 2 * m.a * m.d + m.b * m.b + m.c * m.c) / (2 * m.b * m.c);
    put(res, O_MU, mu, fmin(dx / fmax(sin(mu), 1e-300), sqrt(2 * dx)));
    if (!singular) {
        put(res, O_OM3, w2 * w3, fabs(w2) * tol[1]);
        put(res, O_OM4, w2 * w4, fabs(w2) * tol[1]);
        put(res, O_AL3, w2 * w2 * a3, w2 * w2 * tol[2]);
        put(res, O_AL4, w2 * w2 * a4, w2 * w2 * tol[2]);
        if ((rc = mm_mech_velocity(&prob, &opt, w, th2, q, qd, &info, err)) != MM_OK ||
            (rc = mm_mech_acceleration(&prob, &opt, w, th2, q, qd, qdd, &info, err)) != MM_OK)
            goto out;
        mm_res_check_abs(res, "omega3: Jacobian solve (4) vs closed form (4)", w2 * qd[0], w2 * w3, fabs(w2) * tol[1]);
        mm_res_check_abs(res, "omega4: Jacobian solve (4) vs closed form (4)", w2 * qd[1], w2 * w4, fabs(w2) * tol[1]);
        mm_res_check_abs(res, "alpha3: Jacobian solve (5) vs closed form (5)", w2 * w2 * qdd[0], w2 * w2 * a3,
                         w2 * w2 * tol[2]);
        mm_res_check_abs(res, "alpha4: Jacobian solve (5) vs closed form (5)", w2 * w2 * qdd[1], w2 * w2 * a4,
                         w2 * w2 * tol[2]);
        mm_v2 P, V, A;
        mm_linkage_fb_coupler(&m, px, py, th2, qq, r1, r2, &P, &V, &A);
        double L = hypot(px, py) + m.a;
        put(res, O_VP, fabs(w2) * mm_v2_norm(V), fabs(w2) * (tol[1] * L + 4 * DBL_EPSILON * mm_v2_norm(V)));
        put(res, O_AP, w2 * w2 * mm_v2_norm(A), w2 * w2 * (tol[2] * L + 4 * DBL_EPSILON * mm_v2_norm(A)));
    }

    /* ---- the cycle: a full turn, or the arc the crank can reach ---- */
    double lo = k.full ? 0 : k.lo, hi = k.full ? 2 * M_PI : k.hi, inset = k.full ? 0 : 1e-3 * (hi - lo);
    double th0 = k.full ? th2 - 2 * M_PI * floor(th2 / (2 * M_PI)) : th2;   /* th2 in [0, 2 pi) */
    mm_series *ser[7];
    for (int i = 0; i < 7; i++)
        if (!(ser[i] = mm_res_series(res, O_S3 + i, n))) {
            rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
            goto out;
        }
    mm_series *cc = mm_res_series(res, O_SCOUP, n);
    double *Q = mm_res_alloc(res, 2 * (size_t)n * sizeof *Q), *QD = mm_res_alloc(res, 2 * (size_t)n * sizeof *QD);
    double *QDD = mm_res_alloc(res, 2 * (size_t)n * sizeof *QDD), *x = ser[0]->x;
    if (!cc || !Q || !QD || !QDD) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
        goto out;
    }
    mm_kin_grid(lo + inset, hi - inset, n, x);
    if ((rc = mm_kin_fb_sweep(&run, th0, q, side, singular, n, x, Q, QD, QDD, res, err)) != MM_OK)
        goto out;
    mm_kin_worst e3 = {-1, 0, 0, 0}, e4 = e3, ew = e3, ea = e3, emu = e3;
    for (int i = 0; i < n; i++) {
        double *qi = Q + 2 * i, f3, f4, v3, v4, c3, c4;
        for (int j = 1; j < 7; j++)
            ser[j]->x[i] = x[i];
        ser[0]->y[i] = qi[0], ser[1]->y[i] = qi[1];
        ser[2]->y[i] = w2 * QD[2 * i], ser[3]->y[i] = w2 * QD[2 * i + 1];
        ser[4]->y[i] = w2 * w2 * QDD[2 * i], ser[5]->y[i] = w2 * w2 * QDD[2 * i + 1];
        double mu_q = fabs(mm_kin_wrap(qi[1] - qi[0]));                  /* the angle at C */
        ser[6]->y[i] = mu_q;
        mm_v2 P, V, A;
        mm_linkage_fb_coupler(&m, px, py, x[i], qi, QD + 2 * i, QDD + 2 * i, &P, &V, &A);
        cc->x[i] = P.x, cc->y[i] = P.y;
        /* the closed form of the same assembly: the Freudenstein root nearest */
        double fq[2], fe;
        mm_linkage_fb_nearest(&m, x[i], qi, fq, &fe);
        f3 = fq[0], f4 = fq[1];
        mm_linkage_fb_rates(&m, x[i], f3, f4, &v3, &v4, &c3, &c4);
        double fv[2] = {v3, v4}, fa[2] = {c3, c4};
        mm_linkage_fb_frame_tol(&m, fq, fv, fa, mm_linkage_fb_newton_err(&m, fq, 0) + fe, tol);
        mm_kin_track(&e3, mm_kin_near(qi[0], f3), f3, tol[0]);
        mm_kin_track(&e4, mm_kin_near(qi[1], f4), f4, tol[0]);
        /* a frame exactly at a change point has no rates (the sweep leaves
         * zeros there: B moves, so omega3 = omega4 = 0 cannot happen else) */
        int sing = (QD[2 * i] == 0 && QD[2 * i + 1] == 0) || !isfinite(v3 + v4 + c3 + c4);
        if (!sing) {
            mm_kin_track(&ew, QD[2 * i + (fabs(QD[2 * i] - v3) < fabs(QD[2 * i + 1] - v4))],
                  fabs(QD[2 * i] - v3) < fabs(QD[2 * i + 1] - v4) ? v4 : v3, tol[1]);
            mm_kin_track(&ea, QDD[2 * i + (fabs(QDD[2 * i] - c3) < fabs(QDD[2 * i + 1] - c4))],
                  fabs(QDD[2 * i] - c3) < fabs(QDD[2 * i + 1] - c4) ? c4 : c3, tol[2]);
        }
        mm_kin_track(&emu, mu_q, mm_linkage_fb_mu(&m, x[i]), 2 * tol[0] + 8 * DBL_EPSILON / fmax(sin(mu_q), 1e-300));
    }
    mm_res_check_abs(res, "sweep: theta3 vs Freudenstein, the frame nearest its bound (the assembly kept)", e3.got, e3.ref, e3.tol);
    mm_res_check_abs(res, "sweep: theta4 vs Freudenstein, the frame nearest its bound", e4.got, e4.ref, e4.tol);
    mm_res_check_abs(res, "sweep: omega3, omega4 per unit omega2 vs closed form (4), the frame nearest its bound",
                     ew.got, ew.ref, ew.tol);
    mm_res_check_abs(res, "sweep: alpha3, alpha4 per unit omega2^2 vs closed form (5), the frame nearest its bound",
                     ea.got, ea.ref, ea.tol);
    mm_res_check_abs(res, "sweep: transmission angle from theta4 - theta3 vs the law of cosines (6)", emu.got,
                     emu.ref, emu.tol);

    /* ---- differences of the positions, one frame in four, clear of toggles ---- */
    {
        double h0 = k.full ? 0.05 : fmin(0.05, 0.02 * (hi - lo));
        double *th = mm_res_alloc(res, (size_t)n * sizeof *th), *qs = mm_res_alloc(res, 2 * (size_t)n * sizeof *qs);
        double *d1 = mm_res_alloc(res, 2 * (size_t)n * sizeof *d1), *d2 = mm_res_alloc(res, 2 * (size_t)n * sizeof *d2);
        if (!th || !qs || !d1 || !d2) {
            rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
            goto out;
        }
        int ns = 0;
        double derr1 = 0, derr2 = 0;
        for (int i = 0; i < n; i += 4) {
            /* keep 4 h0 inside the arc between the toggles (a gap narrower
             * than 8 h0 would hide between two tests of its ends) and away
             * from where the Jacobian is near singular */
            if ((!k.full && (x[i] - 4 * h0 < lo || x[i] + 4 * h0 > hi)) || fabs(sin(Q[2 * i + 1] - Q[2 * i])) < 0.05)
                continue;
            th[ns] = x[i];
            memcpy(qs + 2 * ns, Q + 2 * i, 2 * sizeof *qs);
            memcpy(d1 + 2 * ns, QD + 2 * i, 2 * sizeof *d1);
            memcpy(d2 + 2 * ns, QDD + 2 * i, 2 * sizeof *d2);
            double ft[3];
            mm_linkage_fb_frame_tol(&m, Q + 2 * i, QD + 2 * i, QDD + 2 * i, mm_linkage_fb_newton_err(&m, Q + 2 * i, 0), ft);
            derr1 = fmax(derr1, ft[1]), derr2 = fmax(derr2, ft[2]);
            ns++;
        }
        mm_kin_link_fd fc = {&prob, &opt, w, th, qs, d1, d2};
        if ((rc = mm_kin_fd_va(res, O_FDV, O_FDA, "dtheta/dtheta2", "d2theta/dtheta2^2", mm_kin_link_fd_pos, &fc, 2, NULL,
                               ns, d1, d2, h0, derr1, derr2, err)) != MM_OK)
            goto out;
    }

    /* ---- transmission angle extremes, eq. (6) ---- */
    {
        double mn, mx, tmn, tmx;
        mm_linkage_fb_mu_extremes(&m, k.full, lo, hi, &mn, &tmn, &mx, &tmx);
        mm_res_scalar(res, O_MU_MIN, mn);
        mm_res_scalar(res, O_MU_MAX, mx);
        mm_res_scalar(res, O_TH_MUMIN, tmn);
        mm_res_scalar(res, O_TH_MUMAX, tmx);
        double dev = fmax(fabs(M_PI / 2 - mn), fabs(mx - M_PI / 2));
        if (k.full && dev > M_PI / 2 - 40 * M_PI / 180)
            mm_res_warn(res, "the transmission angle strays more than 50 degrees from 90 (%.1f to %.1f degrees): "
                             "the coupler pushes the rocker along itself more than it turns it",
                        mn * 180 / M_PI, mx * 180 / M_PI);
    }

    /* ---- events: dead centres of the rocker, toggles, change points ---- */
    if (k.full) {
        enum { NT = 49 };
        double t[NT], qq2[2 * NT], vv[2 * NT];
        for (int i = 0; i < NT; i++)
            t[i] = 0.123 + 2 * M_PI * i / (NT - 1);
        int j = 0;
        while (j + 1 < n && x[j + 1] <= t[0])
            j++;
        memcpy(qq2, Q + 2 * j, 2 * sizeof *qq2);
        mm_mech_sweep s = {.nt = NT, .t = t, .q = qq2, .qd = vv, .watch = 1};
        if ((rc = mm_mech_sweep_solve(&prob, &opt, w, &s, err)) != MM_OK)
            goto out;
        double dc[4], dce[4];
        int nd = mm_linkage_fb_dead_centres(&m, dc, dce);
        for (int i = 0; i < s.n_turn && i < 2; i++) {
            int best = 0;
            for (int c = 1; c < nd; c++)
                if (fabs(mm_kin_wrap(s.t_turn[i] - dc[c])) < fabs(mm_kin_wrap(s.t_turn[i] - dc[best])))
                    best = c;
            double want = nd ? mm_kin_near(dc[best], s.t_turn[i]) : 0;
            /* the sweep ends on the secant of q4' (rounding of theta2) */
            mm_res_check_abs(res, i ? "second dead centre of the rocker: located by the sweep vs crank and coupler in line"
                                    : "first dead centre of the rocker: located by the sweep vs crank and coupler in line",
                             s.t_turn[i], want, 64 * DBL_EPSILON * (1 + fabs(want)) + (nd ? dce[best] : 0));
        }
        if (!k.change_point && k.shortest == 0)          /* a crank-rocker's swing */
            mm_res_scalar(res, O_SWING, mm_linkage_fb_swing(&m, side));
        if (k.change_point) {
            /* all four links in line where |O4 B| = |b - c| (th2 = 0) or b + c
             * (th2 = pi); each one must be met as a sign change of det(Phi_q)
             * by the sweep, whose frames miss them (0.123 + k pi/24): bisected
             * to 1e-5 of the turn and a parabola through det (measured within
             * 5e-11; det's sign is lost within ~sqrt(eps) of the crossing).
             * The angles there carry eps S / (min(b, c) |sin mu|) of rounding,
             * |sin mu| ~ 1e-5 of the turn away: links of very unequal lengths
             * move the zero by that much */
            double tol_g = 4 * DBL_EPSILON * S;
            double tol_cp = 1e-9 + 4 * DBL_EPSILON * S / (fmin(m.b, m.c) * 1e-5 * 2 * M_PI);
            double want[2] = {fabs(fabs(m.d - m.a) - fabs(m.b - m.c)) <= tol_g ? 0 : -1,
                              fabs(m.b + m.c - m.d - m.a) <= tol_g ? M_PI : -1};
            for (int e = 0; e < 2; e++) {
                if (want[e] < 0)
                    continue;
                double cp = want[e] < t[0] ? want[e] + 2 * M_PI : want[e], got = INFINITY;   /* in the sweep's turn */
                for (int i = 0; i < s.n_sing; i++)
                    if (fabs(s.t_sing[i] - cp) < fabs(got - cp))
                        got = s.t_sing[i];
                mm_res_check_abs(res, "change point: located by the sweep (det = 0) vs all links in line",
                                 isfinite(got) ? got : t[NT - 1], cp, tol_cp);
            }
            mm_res_warn(res, "s + l = p + q: a change point. Where all four links lie in line the open and crossed "
                             "assemblies meet; the motion shown carries straight on through them, and past such a "
                             "point it is the assembly the other label describes");
        }
    } else {
        mm_res_scalar(res, O_TOG1, lo);
        mm_res_scalar(res, O_TOG2, hi);
        char what[200];
        snprintf(what, sizeof what, "%s: the crank cannot turn round; it rocks between the toggles at %.4g and %.4g "
                 "rad, where coupler and rocker lie in line,", k.name, lo, hi);
        mm_kin_warn_reach(res, what, lo, hi, k.gap);
        fb_side fs = {&m, side};
        if ((rc = mm_kin_toggle_checks(res, &prob, &opt, w, lo, hi, k.gap, assemble, &fs, "|O4 B| = b + c or |b - c|",
                                       err)) != MM_OK)
            goto out;
    }
    mm_res_method(res, "Newton-Raphson on the loop closure, Jacobian solves for velocity and acceleration", 0);
    mm_res_method_stat(res, "error_estimate", info.err_est);
    rc = mm_kin_fb_animate(&run, &k, side, w2, px, py, th0, q, singular, res, err);
out:
    mm_mech_work_free(w);
    return rc;
}

static const char *const references[] = {
    "R. L. Norton, Design of Machinery, 5th ed., McGraw-Hill 2012, sections 2.12, 4.5-4.10, 6.7, 7.3",
    "F. Freudenstein, Approximate synthesis of four-bar linkages, Trans. ASME 77 (1955) 853-861",
    NULL,
};

const mm_exercise mm_ex_kin_four_bar = {
    .id = "kin-four-bar", .chapter = 2, .section = "2.4.4",
    .title = "Four-bar linkage",
    .summary = "Angles, angular velocities and accelerations of coupler and rocker; Grashof's condition, "
               "transmission angle, coupler curve, toggles and change points.",
    .tags = "kinematics, mechanism, four-bar, Grashof, Freudenstein, transmission angle, coupler curve",
    .theory = "exercises/kin/four_bar.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
