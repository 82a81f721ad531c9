/* double_pendulum.c — dyn-double-pendulum: Lagrange's equations of two
 * pendulums hung one from the other, how well integrators keep their
 * energy, and how fast two nearly equal starts part (chaos).
 *
 * Goal: derive equations of motion by Lagrange's method (eqs. 1-3), see
 * that an accurate but non-symplectic integrator (adaptive Dormand–Prince,
 * "ode45") lets the energy drift while a symplectic one (Gauss–Legendre
 * collocation on Hamilton's equations) keeps its error bounded, and watch
 * two trajectories started 1e-9 apart separate exponentially: the slope of
 * their log distance estimates the largest Lyapunov exponent.
 * Reference: H. Goldstein, Classical Mechanics, ch. 1-2 and 8; E. Hairer,
 * C. Lubich, G. Wanner, Geometric Numerical Integration, Springer 2006;
 * T. Stachowiak, T. Okada, Chaos Solitons Fractals 29 (2006) 417-422.
 */
#include <float.h>
#include <math.h>

#include "mm_dyn.h"
#include "mm_exhelp.h"
#include "mm_multibody.h"
#include "mm_scene.h"
#include "mm_symplectic.h"

enum {
    P_M1, P_M2, P_L1, P_L2, P_G, P_TH1, P_TH2, P_W1, P_W2, P_TEND, P_RTOL, P_SYMP, P_H, P_SEP, P_POINTS
};

static const char *const symp_methods[] = {"gauss4", "midpoint", NULL};

static const mm_param params[] = {
    [P_M1] = {"m1", "upper bob mass", "kg", MM_REAL, 1, 0.01, 100, .help = "a point mass at the end of rod 1"},
    [P_M2] = {"m2", "lower bob mass", "kg", MM_REAL, 1, 0.01, 100, .help = "a point mass at the end of rod 2"},
    [P_L1] = {"l1", "upper rod length", "m", MM_REAL, 1, 0.05, 10, .help = "massless rod from the pivot"},
    [P_L2] = {"l2", "lower rod length", "m", MM_REAL, 1, 0.05, 10, .help = "massless rod from the upper bob"},
    [P_G] = {"g", "gravity", "m/s^2", MM_REAL, 9.81, 0.1, 100, .help = "acceleration of gravity"},
    [P_TH1] = {"theta1_0", "start angle of rod 1", "rad", MM_REAL, M_PI / 2, -M_PI, M_PI,
               .help = "from the downward vertical, counter-clockwise"},
    [P_TH2] = {"theta2_0", "start angle of rod 2", "rad", MM_REAL, M_PI / 2, -M_PI, M_PI,
               .help = "from the downward vertical (not relative to rod 1)"},
    [P_W1] = {"omega1_0", "start angular velocity of rod 1", "rad/s", MM_REAL, 0, -30, 30, .help = "theta1' at t = 0"},
    [P_W2] = {"omega2_0", "start angular velocity of rod 2", "rad/s", MM_REAL, 0, -30, 30, .help = "theta2' at t = 0"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 30, 0.1, 5000,
                .help = "simulated time; at most 1.6e4 radians of the fastest motion"},
    [P_RTOL] = {"rtol", "Dormand-Prince tolerance", "", MM_REAL, 1e-6, 1e-9, 1e-3,
                .help = "relative tolerance of the adaptive Dormand-Prince 5(4) run whose energy is plotted"},
    [P_SYMP] = {"symplectic", "symplectic method", "", MM_CHOICE, 0, 0, 0, .choices = symp_methods,
                .help = "gauss4: 2-stage Gauss-Legendre, order 4; midpoint: the implicit midpoint rule, order 2"},
    [P_H] = {"h", "symplectic step", "s", MM_REAL, 0.01, 1e-4, 0.5,
             .help = "fixed step of the symplectic method; at most 65536 steps over t_end"},
    [P_SEP] = {"separation", "initial separation of the twin", "rad", MM_REAL, 1e-9, 1e-13, 1e-3,
               .help = "the second trajectory starts with theta2 larger by this much"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 201, 11, 2001, .help = "samples returned for the plots"},
};

enum {
    O_WSLOW, O_WFAST, O_E0, O_LYAP, O_THORIZON,
    O_TH1, O_TH2, O_DE_DP, O_DE_SY, O_SEP, O_SEP_FIT, O_ANIM
};

static const mm_output outputs[] = {
    [O_WSLOW] = MM_SCALAR("omega_slow", "slow small-oscillation frequency", "rad/s", .flags = MM_EXACT),
    [O_WFAST] = MM_SCALAR("omega_fast", "fast small-oscillation frequency", "rad/s", .flags = MM_EXACT),
    [O_E0] = MM_SCALAR("E0", "energy (zero with both bobs hanging still)", "J", .flags = MM_ANSWER | MM_EXACT),
    [O_LYAP] = MM_SCALAR("lyapunov", "growth rate of the separation (largest Lyapunov exponent, estimated)",
                         "1/s", .flags = MM_ANSWER),
    [O_THORIZON] = MM_SCALAR("t_horizon", "time the twins are 0.001 apart (the prediction horizon)", "s"),
    [O_TH1] = MM_SERIES("theta1", "angle of rod 1", "rad", "t", "s", .figure = "angles"),
    [O_TH2] = MM_SERIES("theta2", "angle of rod 2", "rad", "t", "s", .figure = "angles"),
    [O_DE_DP] = MM_SERIES("energy_error_dopri", "|E - E0| / E_scale, Dormand-Prince 5(4)", "", "t", "s",
                          .figure = "energy", .y_scale = "log"),
    [O_DE_SY] = MM_SERIES("energy_error_symplectic", "|E - E0| / E_scale, symplectic", "", "t", "s",
                          .figure = "energy", .y_scale = "log"),
    [O_SEP] = MM_SERIES("separation", "distance between the twins in the state space", "", "t", "s",
                        .figure = "chaos", .y_scale = "log"),
    [O_SEP_FIT] = MM_SERIES("separation_fit", "exponential fit d0 e^(lambda t)", "", "t", "s", .figure = "chaos",
                            .y_scale = "log", .role = "reference"),
    [O_ANIM] = MM_ANIMATION("the double pendulum and its twin started 1e-9 rad apart, with the lower bob's path"),
};

#define RTOL_REF 1e-10          /* the reference run (DOP853) */
#define RTOL_TWIN 1e-12         /* the twins (DOP853): far below their separation */
#define MAX_RADIANS 1.6e4
#define MAX_SYMP_STEPS 65536

static mm_dpend model_of(const mm_value *in)
{
    return (mm_dpend){.m1 = in[P_M1].x, .m2 = in[P_M2].x, .l1 = in[P_L1].x, .l2 = in[P_L2].x, .g = in[P_G].x};
}

static int check(const mm_value *in, mm_error *err)
{
    mm_dpend s = model_of(in);
    double y0[4] = {in[P_TH1].x, in[P_TH2].x, in[P_W1].x, in[P_W2].x}, t_end = in[P_TEND].x;
    double r = mm_dyn_dpend_rate(&s, y0);
    if (t_end * r > MAX_RADIANS)
        return mm_error_set(err, MM_ERANGE, "t_end",
                            "t_end = %g s spans %.3g radians of the fastest motion (rate %.4g 1/s); at most %g "
                            "fit one request: make t_end at most %.4g s", t_end, t_end * r, r, MAX_RADIANS,
                            MAX_RADIANS / r);
    double steps = ceil(t_end / in[P_H].x);
    if (steps > MAX_SYMP_STEPS)
        return mm_error_set(err, MM_ERANGE, "h",
                            "h = %g s needs %.0f steps over t_end; at most %d fit one request: make h at least "
                            "%.4g s", in[P_H].x, steps, MAX_SYMP_STEPS, t_end / MAX_SYMP_STEPS);
    /* the stage equations stiffen where the rods line up, the more so the
     * lighter the upper bob: the Jacobian of Hamilton's equations grows like
     * the speed times (m1 + m2)/m1 */
    double rj = r * (s.m1 + s.m2) / s.m1;
    if (in[P_H].x * rj > 0.5)
        return mm_error_set(err, MM_ERANGE, "h",
                            "h = %g s is too long for the fastest motion (rate %.4g 1/s, times (m1+m2)/m1 where "
                            "the rods line up): the implicit stage equations would not converge; make h at most "
                            "%.4g s", in[P_H].x, r, 0.5 / rj);
    return MM_OK;
}

/* ---- solve ------------------------------------------------------------------------ */

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    mm_dpend s = model_of(in);
    double y0[4] = {in[P_TH1].x, in[P_TH2].x, in[P_W1].x, in[P_W2].x}, t_end = in[P_TEND].x;
    double rtol = in[P_RTOL].x, h = in[P_H].x, sep = in[P_SEP].x;
    int n = (int)in[P_POINTS].x;
    mm_symp_method sm = (int)in[P_SYMP].x == 0 ? MM_SYMP_GAUSS4 : MM_SYMP_MIDPOINT;

    double ws, wf, Escale, E0 = mm_dpend_energy(&s, y0, &Escale);
    mm_dpend_linear(&s, &ws, &wf);
    double Vmin = -(s.m1 + s.m2) * s.g * s.l1 - s.m2 * s.g * s.l2;
    mm_res_scalar(res, O_WSLOW, ws);
    mm_res_scalar(res, O_WFAST, wf);
    mm_res_scalar(res, O_E0, E0 - Vmin);
    /* the energy scale of the relative errors: the potential energy's range */
    double Es = fmax(-2 * Vmin, E0 - Vmin);

    /* the reference: DOP853 at 1e-10 on Lagrange's equations */
    mm_series *s1 = mm_res_series(res, O_TH1, n), *s2 = mm_res_series(res, O_TH2, n);
    mm_series *sdp = mm_res_series(res, O_DE_DP, n);
    double *yr = mm_res_alloc(res, (size_t)n * 4 * sizeof *yr), *yd = mm_res_alloc(res, (size_t)n * 4 * sizeof *yd);
    if (!s1 || !s2 || !sdp || !yr || !yd)
        return MM_ENOMEM;
    mm_linspace(0, t_end, n, s1->x);
    /* the reference's energy error and its allowance of eq. (7), watched at
     * the ends of its steps (mm_dyn_dpend_reference) */
    mm_ode_result rr, rd;
    double ref_drift, allow;
    int rc = mm_dyn_dpend_reference(&s, y0, t_end, RTOL_REF, n, s1->x, E0, Es, yr, &rr, &ref_drift, &allow, err);
    if (rc != MM_OK)
        return rc;
    /* Dormand-Prince at the learner's tolerance is the demonstration, not
     * the reference: at a loose one over a long chaotic run its energy can
     * run away (its error weights grow with the unwrapped angles, rtol |theta|:
     * after 500 turns rtol 3.7e-4 let a step err a radian), the speeds
     * with it, until its step collapses.  That is an answer, not an error:
     * its energy error is shown up to where it stopped. */
    mm_error derr = {0};
    int rcd = mm_dyn_dpend_run(&s, y0, t_end, n, s1->x, MM_ODE_DOPRI5, rtol, yd, &rd, &derr);
    int nd = rcd == MM_OK ? n : (int)rd.nout_done;
    if (rcd == MM_ENOMEM || rcd == MM_EINTERNAL || (rcd != MM_OK && nd < 1)) {
        *err = derr;
        return rcd;
    }
    if (rcd != MM_OK)
        mm_res_warn(res, "Dormand-Prince at rtol = %g lost the motion: its energy error grew without bound and "
                         "its step size collapsed at t = %.4g s (%s); its energy error is plotted up to there. "
                         "The reference (DOP853 at 1e-10) and the symplectic method carry on: try a smaller "
                         "rtol", rtol, rd.t_reached, derr.msg);
    double dp_drift = 0, lh_worst = 0, lh_scale = 0;
    for (int i = 0; i < n; i++) {
        const double *y = yr + 4 * i;
        s2->x[i] = sdp->x[i] = s1->x[i];
        s1->y[i] = y[0], s2->y[i] = y[1];
        if (i < nd) {
            double e = fabs(mm_dpend_energy(&s, yd + 4 * i, NULL) - E0) / Es;
            dp_drift = fmax(dp_drift, e);
            sdp->y[i] = fmax(e, DBL_EPSILON);
        }
        /* Lagrange's equations against Hamilton's at this state: dp/dt from
         * Hamilton must equal d(M w)/dt = M w' + M' w from Lagrange */
        double sc, r = mm_dpend_lh_residual(&s, y, &sc);
        lh_worst = fmax(lh_worst, r);
        lh_scale = fmax(lh_scale, sc);
    }
    sdp->n = nd;
    mm_res_method(res, "Lagrange's equations by dop853 (reference, rtol 1e-10; twins 1e-12) and dopri5; Hamilton's by "
                       "Gauss-Legendre collocation", 0);
    mm_res_method_stat(res, "reference_steps", (double)rr.n_accepted);
    mm_res_method_stat(res, "dopri5_rtol", rtol);
    mm_res_method_stat(res, "dopri5_steps", (double)rd.n_accepted);
    mm_res_method_stat(res, "dopri5_evaluations", (double)rd.n_eval);

    /* the symplectic run on Hamilton's equations, in (theta, p): its energy
     * error at every step, largest over each half of the run */
    long N = (long)ceil(t_end / h);
    double max_first, max_second, faster;
    rc = mm_dyn_dpend_symplectic(&s, y0, t_end, h, sm, MAX_SYMP_STEPS, E0, Es, O_DE_SY, n, &max_first, &max_second,
                                 &faster, res, err);
    if (rc != MM_OK)
        return rc;
    double sy_drift = fmax(max_first, max_second);
    /* the two drifts are the runs' own (no script or second method can
     * reproduce another integrator's rounding): said in words, plotted */
    mm_res_method_stat(res, "dopri5_largest_energy_error", dp_drift);
    mm_res_method_stat(res, "symplectic_largest_energy_error", sy_drift);

    /* checks */
    /* the energy is a first integral: its error at t is the sum of the
     * energy errors of the steps before, without amplification, each at
     * most the allowance of eq. (7).  The first steps (the trial step, the
     * controller settling) err up to it each; the many that follow have
     * errors of both signs that add like a random walk (its excursion
     * about 0.75 sqrt(steps) of them).  So the tolerance is the allowance
     * times (4 + 0.75 sqrt(steps)), judged at the ends of the steps (the
     * dense output between them is not what the step control bounds).  The
     * old one, 0.8 rtol (8 + rate t_end), ignored the size of the gradient
     * and of the angles in DOP853's weights: a short run with large angles
     * and slow gravity (8 steps) erred 2.7 times over it.  The bound
     * assumes each step's error within the allowance, which DOP853 keeps
     * only where its error estimate is asymptotic: mm_ode checks its first
     * step, the one no earlier estimate sized, against the estimate of its
     * first half.  At the defaults the error is 1/78 of this tolerance. */
    double n_ref = (double)rr.n_accepted;
    mm_res_check_abs(res, "energy of the reference run (DOP853, rtol 1e-10): largest relative error",
                     ref_drift, 0, allow * (4 + 0.75 * sqrt(n_ref)));
    mm_check_residual(res, "Lagrange's equations vs Hamilton's: dp/dt = d(M w)/dt at every plotted state "
                           "(scale: largest term times cond M)", lh_worst, lh_scale, 8);
    /* the twins: the reference and a start moved by sep in theta2, DOP853
     * at 1e-12, over at most 40 periods of the fast small oscillation (a
     * chaotic pair parts within a few); their distance on a grid */
    double y0b[4] = {y0[0], y0[1] + sep, y0[2], y0[3]}, t_ly = fmin(t_end, 40 * 2 * M_PI / wf);
    double *yb = mm_res_alloc(res, (size_t)n * 4 * sizeof *yb), *ya;
    mm_series *ssep = mm_res_series(res, O_SEP, n);
    if (!yb || !ssep)
        return MM_ENOMEM;
    mm_linspace(0, t_ly, n, ssep->x);
    mm_ode_result rb;
    ya = mm_res_alloc(res, (size_t)n * 4 * sizeof *ya);
    if (!ya)
        return MM_ENOMEM;
    rc = mm_dyn_dpend_run(&s, y0, t_ly, n, ssep->x, MM_ODE_DOP853, RTOL_TWIN, ya, &rb, err);
    if (rc != MM_OK)
        return rc;
    rc = mm_dyn_dpend_run(&s, y0b, t_ly, n, ssep->x, MM_ODE_DOP853, RTOL_TWIN, yb, &rb, err);
    if (rc != MM_OK)
        return rc;
    double d0 = mm_dyn_dpend_distance(y0, y0b, wf);
    double *dsep = mm_res_alloc(res, (size_t)n * sizeof *dsep);
    if (!dsep)
        return MM_ENOMEM;
    double t_h = mm_dyn_dpend_separation(ya, yb, n, ssep->x, wf, d0, dsep, ssep->y);
    if (t_h >= 0)
        mm_res_scalar_err(res, O_THORIZON, t_h, ssep->x[1] - ssep->x[0], MM_ERR_ESTIMATE);
    /* the exponent depends on where the motion goes while the twins part,
     * and a chaotic motion goes elsewhere after any change at all: with
     * twice the slope's standard error alone, a rounding-level change of
     * DOP853 moved it by 1.46 times that.  A third start, moved by sep in
     * theta1 instead of theta2, parts along another path; the difference of
     * the two exponents is the sensitivity the estimate has, and the stated
     * error is the larger of it and 2 se. */
    double lam, a0, se, lam_c, a0_c, se_c;
    int i_lo, i_hi, jl, jh;
    if (mm_growth_fit(ssep->x, dsep, n, d0, &i_lo, &i_hi, &lam, &a0, &se)) {
        double y0c[4] = {y0[0] + sep, y0[1], y0[2], y0[3]};
        rc = mm_dyn_dpend_run(&s, y0c, t_ly, n, ssep->x, MM_ODE_DOP853, RTOL_TWIN, yb, &rb, err);
        if (rc != MM_OK)
            return rc;
        double d0c = mm_dyn_dpend_distance(y0, y0c, wf);
        for (int i = 0; i < n; i++)
            dsep[i] = mm_dyn_dpend_distance(ya + 4 * i, yb + 4 * i, wf);
        double e_lam = 2 * se;
        if (mm_growth_fit(ssep->x, dsep, n, d0c, &jl, &jh, &lam_c, &a0_c, &se_c))
            e_lam = fmax(e_lam, fabs(lam - lam_c));
        mm_res_scalar_err(res, O_LYAP, lam, e_lam, MM_ERR_ESTIMATE);
        mm_series *sf = mm_res_series(res, O_SEP_FIT, 2);
        if (!sf)
            return MM_ENOMEM;
        sf->x[0] = ssep->x[i_lo], sf->x[1] = ssep->x[i_hi - 1];
        sf->y[0] = exp(a0 + lam * sf->x[0]), sf->y[1] = exp(a0 + lam * sf->x[1]);
    } else {
        mm_res_warn(res, "the twins stay close (%.2g apart at t = %.4g s): no exponential growth to fit, so "
                         "no Lyapunov exponent is given; the motion looks regular at this energy",
                    ssep->y[n - 1], t_ly);
    }
    /* a symplectic method's energy error oscillates but does not grow: on a
     * regular motion (the twins stay together) over many periods, the second
     * half of the run may not exceed the first by more than the variation
     * between the regions the motion visits (x4) and round-off */
    /* (the motion visits its regions over its slow period: a run of 20 fast
     * turns but a fraction of one slow swing sees other regions in its
     * second half, with gauss4's error 1.2 times that of the first).  A
     * region of faster motion has a larger error at the same step: the
     * bound grows with the sixth power of how much faster the second half
     * went at its fastest (a light inner bob that whipped 2.25 times faster
     * in the second half than in the first, 136 against 61 rad/s: the
     * error 142 times the first half's, 2.25^6 = 130; the grid's samples
     * between those peaks stayed at the first half's level, no drift) */
    if (i_lo < 0 && t_end * mm_dyn_dpend_rate(&s, y0) > 20 * 2 * M_PI && t_end * ws > 20 * 2 * M_PI)
        mm_res_check_abs(res, "symplectic energy error: largest over the second half vs over the first half",
                         max_second, 0, 4 * max_first * pow(fmax(faster, 1), 6) + 64 * DBL_EPSILON * sqrt((double)N));
    if (dp_drift > 10 * sy_drift && t_end * wf > 200)
        mm_res_warn(res, "over this run Dormand-Prince's energy error (%.2g) grew past the symplectic "
                         "method's (%.2g), which stays bounded", dp_drift, sy_drift);
    return mm_dyn_dpend_animate(&s, t_end, y0, y0b, RTOL_TWIN, res, err);
}

static const char *const references[] = {
    "H. Goldstein, C. Poole, J. Safko, Classical Mechanics, 3rd ed., Addison-Wesley 2002, ch. 1-2 and 8",
    "E. Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed., Springer 2006, II.1 and IX",
    "E. Hairer, S. P. Norsett, G. Wanner, Solving Ordinary Differential Equations I, Springer 1993 "
    "(Dormand-Prince)",
    NULL,
};

const mm_exercise mm_ex_dyn_double_pendulum = {
    .id = "dyn-double-pendulum", .chapter = 4, .section = "4.3",
    .title = "The double pendulum: Lagrange's equations, energy and chaos",
    .summary = "Equations of motion by Lagrange's method; the energy error of Dormand-Prince against a "
               "symplectic Gauss method; two starts 1e-9 apart and the Lyapunov exponent.",
    .tags = "dynamics, Lagrange, Hamilton, symplectic, energy drift, chaos, Lyapunov",
    .theory = "exercises/dyn/double_pendulum.md", .params = params, .n_params = MM_COUNT(params), .outputs = outputs,
    .n_outputs = MM_COUNT(outputs), .references = references, .check = check, .solve = solve,
};
