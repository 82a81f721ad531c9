/* absorber.c — vib-absorber: a small mass on a spring (and damper) tuned to
 * the forcing frequency stops the main mass it hangs on.
 *
 *     m1 x1'' + k1 x1 + c2 (x1' - x2') + k2 (x1 - x2) = F0 cos(omega t)
 *     m2 x2'' + c2 (x2' - x1') + k2 (x2 - x1) = 0                           (1)
 *
 * Goal: the steady amplitudes over frequency: the anti-resonance of m1 at
 * omega_a = sqrt(k2/m2), the two new peaks either side of it at the
 * natural frequencies of the coupled pair, and Den Hartog's optimal tuning
 * and damping, which flatten the two peaks to the height of the fixed
 * points that every damping's curve passes through (eqs. 5-7 of the theory).
 * Checks: the closed form of the amplitudes (eq. 3) against a numerical
 * solve of the complex 2 x 2 system; the anti-resonance and the
 * frequency equation to rounding; the fixed points' height the same for
 * any damping; the optimum curve's peak found numerically against the
 * fixed points it must pass through.
 * Reference: J. P. Den Hartog, Mechanical Vibrations, 4th ed., Dover, sec. 3.3;
 * S. S. Rao, Mechanical Vibrations, 6th ed., sec. 9.11.
 */
#include "mm_vib.h"   /* before complex.h: mm_fem.h has a field named I */

#include <complex.h>
#include <float.h>
#include <math.h>

#include "mm_complex.h"
#include "mm_exhelp.h"
#include "mm_linalg.h"
#include "mm_mdof.h"
#include "mm_opt.h"

enum { P_M1, P_K1, P_M2, P_K2, P_F0, P_C2, P_OMEGA, P_WMAX, P_POINTS };

static const mm_param params[] = {
    [P_M1] = {"m1", "main mass", "kg", MM_REAL, 1, 1e-3, 1e3, .help = "the machine to be kept still"},
    [P_K1] = {"k1", "main spring", "N/m", MM_REAL, 100, 1e-2, 1e6, .help = "holds the main mass to the ground"},
    [P_M2] = {"m2", "absorber mass", "kg", MM_REAL, 0.1, 1e-4, 1e3,
              .help = "the small mass added; the mass ratio m2/m1 sets how far apart the new peaks are"},
    [P_K2] = {"k2", "absorber spring", "N/m", MM_REAL, 10, 1e-3, 1e6,
              .help = "tunes the absorber: m1 stands still at omega = sqrt(k2/m2)"},
    [P_F0] = {"F0", "force amplitude", "N", MM_REAL, 1, 1e-3, 1e4, .help = "F0 cos(omega t) on the main mass"},
    [P_C2] = {"c2", "absorber damping", "N s/m", MM_REAL, 0, 0, 1e4,
              .help = "damper beside k2; 0 is the classical undamped absorber (infinite peaks)"},
    [P_OMEGA] = {"omega", "forcing frequency", "rad/s", MM_REAL, 10, 0, 1e4,
                 .help = "the frequency of the steady motion animated and of the scalars X1, X2"},
    [P_WMAX] = {"omega_max", "end of the sweep", "rad/s", MM_REAL, 0, 0, 1e5,
                .help = "the sweep runs from 0 to omega_max; 0 takes 3 sqrt(k1/m1)"},
    [P_POINTS] = {"points", "sweep points", "", MM_INT, 301, 21, 2001, .help = "frequencies of the sweep"},
};

enum { O_W1, O_W2, O_WA, O_MU, O_X1, O_X2, O_WEND, O_FOPT, O_K2OPT, O_ZOPT, O_C2OPT, O_XFP, O_XPEAK,
       O_SX1, O_SX2, O_SOPT, O_ANIM };

static const mm_output outputs[] = {
    [O_W1] = MM_SCALAR("omega1", "first natural frequency of the pair (first peak)", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_W2] = MM_SCALAR("omega2", "second natural frequency (second peak)", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_WA] = MM_SCALAR("tuned_omega", "anti-resonance sqrt(k2/m2): m1 stands still", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_MU] = MM_SCALAR("mass_ratio", "mu = m2/m1", "", .flags = MM_EXACT),
    [O_X1] = MM_SCALAR("X1", "steady amplitude of m1 at omega", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_X2] = MM_SCALAR("X2", "steady amplitude of m2 at omega", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_WEND] = MM_SCALAR("omega_max", "end of the sweep", "rad/s", .flags = MM_EXACT),
    [O_FOPT] = MM_SCALAR("tuning_opt", "Den Hartog's tuning omega_a/omega_n = 1/(1 + mu)", "", .flags = MM_EXACT),
    [O_K2OPT] = MM_SCALAR("k2_opt", "the absorber spring of that tuning", "N/m", .flags = MM_ANSWER | MM_EXACT),
    [O_ZOPT] = MM_SCALAR("zeta_opt", "Den Hartog's damping c2/(2 m2 omega_n) = sqrt(3 mu / (8 (1 + mu)^3))", "",
                         .flags = MM_EXACT),
    [O_C2OPT] = MM_SCALAR("c2_opt", "the absorber damper of that damping", "N s/m", .flags = MM_ANSWER | MM_EXACT),
    [O_XFP] = MM_SCALAR("X1_fixed_points", "height of the fixed points, (F0/k1) sqrt(1 + 2/mu)", "m",
                        .flags = MM_ANSWER | MM_EXACT),
    [O_XPEAK] = MM_SCALAR("X1_opt_peak", "highest |X1| of the optimum design, found numerically", "m"),
    [O_SX1] = MM_SERIES("X1", "|X1|, main mass", "m", "omega", "rad/s", .figure = "amplitudes", .y_scale = "log"),
    [O_SX2] = MM_SERIES("X2", "|X2|, absorber mass", "m", "omega", "rad/s", .figure = "amplitudes", .y_scale = "log"),
    [O_SOPT] = MM_SERIES("X1_den_hartog", "|X1| with Den Hartog's optimal k2 and c2", "m", "omega", "rad/s",
                         .figure = "amplitudes", .y_scale = "log"),
    [O_ANIM] = MM_ANIMATION("the main mass and its absorber in the steady motion at omega"),
};

typedef struct absorber {
    double m1, k1, m2, k2, c2, F0;
} absorber;

/* Eq. (3): X1 = F0 (k2 - m2 w^2 + i w c2) / D, X2 = F0 (k2 + i w c2) / D,
 * D = (k1 - m1 w^2)(k2 - m2 w^2) - m2 w^2 k2 + i w c2 (k1 - (m1 + m2) w^2). */
static void amplitudes(const absorber *a, double w, double complex *X1, double complex *X2)
{
    double w2 = w * w;
    double complex z2 = mm_cmplx(a->k2 - a->m2 * w2, w * a->c2);
    double complex D = mm_cmplx((a->k1 - a->m1 * w2) * (a->k2 - a->m2 * w2) - a->m2 * w2 * a->k2,
                                w * a->c2 * (a->k1 - (a->m1 + a->m2) * w2));
    *X1 = a->F0 * z2 / D;
    *X2 = a->F0 * mm_cmplx(a->k2, w * a->c2) / D;
}

static int x1_abs(double w, double *fx, void *ctx)
{
    double complex X1, X2;
    amplitudes(ctx, w, &X1, &X2);
    *fx = cabs(X1);
    return 0;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    absorber a = {in[P_M1].x, in[P_K1].x, in[P_M2].x, in[P_K2].x, in[P_C2].x, in[P_F0].x};
    const double eps = DBL_EPSILON, wn = sqrt(a.k1 / a.m1), mu = a.m2 / a.m1, w = in[P_OMEGA].x;
    double wend = in[P_WMAX].x > 0 ? in[P_WMAX].x : 3 * wn, om[2], phi[4];
    int n = (int)in[P_POINTS].x, rc;
    mm_mdof_two_dof(a.m1, a.m2, a.k1, a.k2, 0, om, phi);             /* eq. (4): the peaks */
    double wa = sqrt(a.k2 / a.m2), Xst = a.F0 / a.k1;
    mm_res_scalar(res, O_W1, om[0]);
    mm_res_scalar(res, O_W2, om[1]);
    mm_res_scalar(res, O_WA, wa);
    mm_res_scalar(res, O_MU, mu);
    mm_res_scalar(res, O_WEND, wend);
    double complex X1, X2;
    amplitudes(&a, w, &X1, &X2);
    if (isfinite(cabs(X1)) && isfinite(cabs(X2))) {
        mm_res_scalar(res, O_X1, cabs(X1));
        mm_res_scalar(res, O_X2, cabs(X2));
    } else {
        mm_res_warn(res, "omega = %g rad/s is a natural frequency of the undamped pair: no steady state", w);
    }
    /* Den Hartog, eqs. (5)-(7) */
    double f = 1 / (1 + mu), z = sqrt(3 * mu / (8 * pow(1 + mu, 3))), wopt = f * wn;
    absorber o = {a.m1, a.k1, a.m2, a.m2 * wopt * wopt, 2 * z * a.m2 * wn, a.F0};
    double Xfp = Xst * sqrt(1 + 2 / mu);
    mm_res_scalar(res, O_FOPT, f);
    mm_res_scalar(res, O_K2OPT, o.k2);
    mm_res_scalar(res, O_ZOPT, z);
    mm_res_scalar(res, O_C2OPT, o.c2);
    mm_res_scalar(res, O_XFP, Xfp);

    /* the sweep, closed form (3), against a numerical solve of
     * [k1+k2 - m1 w^2 + i w c2, -k2 - i w c2; -k2 - i w c2, k2 - m2 w^2 + i w c2] X = [F0; 0]
     * written as a real 4 x 4 system: rounding, times its condition number */
    mm_series *s1 = mm_res_series(res, O_SX1, n), *s2 = mm_res_series(res, O_SX2, n);
    mm_series *so = mm_res_series(res, O_SOPT, n);
    if (!s1 || !s2 || !so)
        return MM_ENOMEM;
    mm_linspace(0, wend, n, s1->x);
    double worst = 0, poles = 0;
    for (int i = 0; i < n; i++) {
        double wi = s1->x[i], w2 = wi * wi, c = wi * a.c2, b[4] = {a.F0, 0, 0, 0}, xr[2], xi[2];
        s2->x[i] = so->x[i] = wi;
        amplitudes(&a, wi, &X1, &X2);
        s1->y[i] = cabs(X1);
        s2->y[i] = cabs(X2);
        double complex O1, O2;
        amplitudes(&o, wi, &O1, &O2);
        so->y[i] = cabs(O1);
        if (!isfinite(s1->y[i]) || !isfinite(s2->y[i])) {
            s1->y[i] = s2->y[i] = 0;      /* a grid point on a pole: cannot be drawn */
            poles++;
            continue;
        }
        double re[4] = {a.k1 + a.k2 - a.m1 * w2, -a.k2, -a.k2, a.k2 - a.m2 * w2}, im[4] = {c, -c, -c, c};
        mm_linalg_solve_info info;
        if ((rc = mm_linalg_solve_complex(2, re, im, b, b + 2, xr, xi, &info, err)) != MM_OK)
            return rc;
        double d = fmax(cabs(mm_cmplx(xr[0], xi[0]) - X1), cabs(mm_cmplx(xr[1], xi[1]) - X2));
        double big = fmax(s1->y[i], s2->y[i]) + Xst;
        worst = fmax(worst, d / (big * fmax(1 / fmax(info.rcond, 1e-300), 1)));
    }
    mm_res_check_abs(res, "closed form (3) vs a numerical solve of the complex system, over the sweep: worst "
                          "difference / (size x condition number)", worst, 0, 64 * eps);
    if (poles)
        mm_res_warn(res, "%g sweep point%s fell on a natural frequency of the undamped pair, where the amplitude "
                         "is infinite; drawn as 0", poles, poles > 1 ? "s" : "");

    /* the anti-resonance: the numerator of X1 vanishes at omega_a, eq. (3) */
    double na = a.k2 - a.m2 * wa * wa;
    mm_check_residual(res, "anti-resonance: k2 - m2 omega_a^2 [N/m] (rounding)", na, a.k2, 4);
    /* the peaks: omega1, omega2 solve the frequency equation (4) */
    double rmax = 0;
    for (int j = 0; j < 2; j++) {
        double w2 = om[j] * om[j];
        rmax = fmax(rmax, fabs((a.k1 + a.k2 - a.m1 * w2) * (a.k2 - a.m2 * w2) - a.k2 * a.k2));
    }
    double sc = (a.k1 + a.k2 + a.m1 * om[1] * om[1]) * (a.k2 + a.m2 * om[1] * om[1]) + a.k2 * a.k2;
    mm_check_residual(res, "omega1, omega2 in the frequency equation (4) [N^2/m^2] (rounding)", rmax, sc, 32);

    /* the fixed points of the optimally tuned absorber, eq. (6):
     * (omega/omega_n)^2 = (1 -+ sqrt(mu/(2 + mu))) / (1 + mu); there |X1| is
     * the same for every c2: 0, the optimum, and a locked absorber
     * (c2 -> infinity: one mass m1 + m2 on k1) */
    double spread = 0;
    for (int s = -1; s <= 1; s += 2) {
        double r = sqrt(mu / (2 + mu));     /* 1 - r = (2/(2 + mu)) / (1 + r), without cancellation */
        double g2 = (s > 0 ? 1 + r : 2 / (2 + mu) / (1 + r)) / (1 + mu), wp = wn * sqrt(g2);
        for (int k = 0; k < 2; k++) {
            absorber t = o;
            t.c2 = k ? o.c2 : 0;
            amplitudes(&t, wp, &X1, &X2);
            spread = fmax(spread, fabs(cabs(X1) - Xfp));
        }
        spread = fmax(spread, fabs(a.F0 / fabs(a.k1 - (a.m1 + a.m2) * wp * wp) - Xfp));
    }
    /* rounding, amplified where k1 - m1 omega^2 cancels (small mu, by
     * 1/sqrt(mu)) or the terms of D do (large mu, by mu) */
    mm_res_check_abs(res, "fixed points (6): |X1| the same for c2 = 0, optimal, locked [m] (rounding)", spread, 0,
                     64 * eps * Xfp * (1 + mu + 1 / sqrt(mu)));
    /* the optimum's highest peak: the best of 2000 points over 0 .. 3
     * omega_n, refined by golden sections; it passes through the fixed
     * points, so it is at least Xfp; Den Hartog's damping puts it only a
     * little above them */
    mm_opt_result pk;
    if ((rc = mm_opt_scan_golden_max(x1_abs, &o, 3 * wn / 2000, 2000, 1e-12 * wn, 200, &pk, err)))
        return rc;
    mm_res_scalar_err(res, O_XPEAK, pk.fx, 1e-12 * pk.fx, MM_ERR_ESTIMATE);
    mm_res_check_abs(res, "optimum curve's peak >= the fixed points' height it passes through [m]",
                     fmin(pk.fx - Xfp, 0), 0, 1e-12 * Xfp);

    /* the steady motion at omega, one period in 24 frames */
    amplitudes(&a, w, &X1, &X2);
    double K[4] = {a.k1 + a.k2, -a.k2, -a.k2, a.k2};
    double complex X[2] = {X1, X2};
    return mm_vib_masses_steady(res, 2, K, X, w, 24);
}

static const char *const references[] = {
    "J. P. Den Hartog, Mechanical Vibrations, 4th ed., Dover 1985, section 3.3",
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, section 9.11",
    NULL,
};

const mm_exercise mm_ex_vib_absorber = {
    .id = "vib-absorber", .chapter = 5, .section = "5.10.1", .title = "The dynamic vibration absorber",
    .summary = "A small tuned mass stops the machine it hangs on: anti-resonance, two new peaks, Den Hartog's optimum.",
    .tags = "vibration, 2 DOF, forced, absorber, tuned mass damper, anti-resonance, Den Hartog",
    .theory = "exercises/vib/absorber.md", .params = params, .n_params = MM_COUNT(params), .outputs = outputs,
    .n_outputs = MM_COUNT(outputs), .references = references, .solve = solve,
};
