/* pendulum.c — dyn-pendulum: a point mass on a massless rod, swung to any
 * amplitude, up to the top and over it.
 *
 *     theta'' + (g/L) sin theta = 0,   theta(0) = theta0,  theta'(0) = omega0     (1)
 *
 * Goal: see the period grow with the amplitude, from the small-angle
 * 2 pi sqrt(L/g) to infinity at the top (the separatrix), and learn the
 * closed form that says by how much: T = 4 sqrt(L/g) K(sin(theta0/2)), K the
 * complete elliptic integral of the first kind, computed here by Gauss's
 * arithmetic-geometric mean to round-off.  The motion itself is integrated
 * (DOP853) and checked against the exact solution in Jacobi elliptic
 * functions; the period is measured from the integration (the orbit must
 * close after one period) and checked against the closed form; and the
 * amplitude at which the period is 1 % longer than the small-angle one is
 * found as a root.  An initial angular velocity sends the bob over the top
 * (rotation); exactly at the top at rest it stays there (the separatrix:
 * infinite period).
 * Reference: Abramowitz & Stegun, Handbook of Mathematical Functions,
 * ch. 16-17; J. L. Meriam, L. G. Kraige, Engineering Mechanics: Dynamics,
 * the simple pendulum; Hairer, Norsett & Wanner, Solving ODE I (DOP853).
 */
#include <float.h>
#include <math.h>

#include "mm_dyn.h"
#include "mm_elliptic.h"
#include "mm_exhelp.h"
#include "mm_pendulum.h"

enum { P_L, P_G, P_THETA0, P_TEND, P_OMEGA0, P_POINTS };

static const mm_param params[] = {
    [P_L] = {"L", "rod length", "m", MM_REAL, 1, 1e-3, 100, .help = "from the pivot to the bob (a point mass)"},
    [P_G] = {"g", "gravity", "m/s^2", MM_REAL, 9.81, 0.01, 100, .help = "acceleration of gravity"},
    [P_THETA0] = {"theta0", "release angle", "rad", MM_REAL, 1, 1e-6, M_PI,
                  .help = "angle from the hanging position at t = 0; pi is straight up, the separatrix "
                          "(at rest there the period is infinite)"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 10, 0.01, 1e4,
                .help = "simulated time; at most 1e4 radians of the motion"},
    [P_OMEGA0] = {"omega0", "initial angular velocity", "rad/s", MM_REAL, 0, -1e3, 1e3,
                  .help = "theta' at t = 0; 0 releases the bob from rest; above 2 sqrt(g/L) cos(theta0/2) "
                          "the bob goes over the top"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 501, 11, 4001,
                  .help = "samples of the time response returned for the plot"},
};

enum {
    O_PERIOD, O_PERIOD_SMALL, O_RATIO, O_AMPL, O_K, O_MOTION, O_T1PCT, O_OMEGA_N,
    O_THETA, O_THETA_LIN, O_RATIO_CURVE, O_RATIO_SERIES, O_ANIM
};

static const mm_output outputs[] = {
    [O_PERIOD] = MM_SCALAR("period", "period (of a swing, or of a turn over the top)", "s",
                           .flags = MM_ANSWER | MM_EXACT),
    [O_PERIOD_SMALL] = MM_SCALAR("period_small", "small-angle period 2 pi sqrt(L/g)", "s",
                                 .flags = MM_ANSWER | MM_EXACT),
    [O_RATIO] = MM_SCALAR("period_ratio", "period / small-angle period", "", .flags = MM_EXACT),
    [O_AMPL] = MM_SCALAR("theta_max", "amplitude (largest angle of the swing)", "rad",
                         .flags = MM_ANSWER | MM_EXACT),
    [O_K] = MM_SCALAR("k", "modulus sqrt(E / (2 m g L)) (< 1 swings, > 1 turns over)", "", .flags = MM_EXACT),
    [O_MOTION] = MM_SCALAR("motion", "kind of motion (0 swing, 1 separatrix, 2 over the top)", "",
                           .flags = MM_EXACT),
    [O_T1PCT] = MM_SCALAR("theta_1pct", "amplitude at which the period is 1 % above the small-angle one",
                          "rad", .flags = MM_ANSWER),
    [O_OMEGA_N] = MM_SCALAR("omega_n", "small-angle frequency sqrt(g/L)", "rad/s", .flags = MM_EXACT),
    [O_THETA] = MM_SERIES("theta", "angle (DOP853)", "rad", "t", "s", .figure = "motion"),
    [O_THETA_LIN] = MM_SERIES("theta_linear", "small-angle solution", "rad", "t", "s", .figure = "motion",
                              .role = "reference"),
    [O_RATIO_CURVE] = MM_SERIES("period_curve", "period / small-angle period (elliptic integral)", "",
                                "amplitude", "rad", .figure = "period"),
    [O_RATIO_SERIES] = MM_SERIES("period_series", "first correction 1 + theta0^2/16", "", "amplitude", "rad",
                                 .figure = "period", .role = "reference"),
    [O_ANIM] = MM_ANIMATION("the pendulum swinging, with the path of its bob"),
};

static const char *const motion_names[] = {"swinging", "separatrix", "over the top"};

/* ---- the model and its closed form ------------------------------------------- */

static mm_pendulum_motion model(const mm_value *in)
{
    return mm_pendulum_motion_init(in[P_L].x, in[P_G].x, in[P_THETA0].x, in[P_OMEGA0].x);
}

static int rhs(double t, const double *y, double *dy, void *ctx)
{
    (void)t;
    const mm_pendulum_motion *p = ctx;
    dy[0] = y[1];
    dy[1] = -p->wn * p->wn * mm_pendulum_sin_top(y[0]);                /* eq. (1) */
    return 0;
}

/* The fastest rate of the motion [1/s]: wn, and the largest |theta'|. */
static double rate(const mm_pendulum_motion *p)
{
    double a = fabs(p->omega0) / (2 * p->wn), s = sin(0.5 * p->theta0);
    return p->wn * fmax(1, 2 * sqrt(s * s + a * a));
}

#define MAX_RADIANS 1e4
#define RTOL 1e-12           /* DOP853's tolerance: the checks below are sized to it */
/* The longest step, in radians of the motion.  DOP853 controls the error
 * of its steps, not that of its dense output between them (order 7, one
 * below the steps: mid-step it errs by about 2e-12 (rate h / 0.2)^8 of the
 * motion's size, measured on a unit oscillator, and up to 4.3e-12 on a
 * swing of k about 0.5 whose harmonics the interpolant follows less well).
 * The plot and the energy and trajectory checks read the dense output, so
 * the step is held where that stays within a few RTOL.  A radian a step
 * let a fast turn over the top (omega0 >> sqrt(g/L): nearly uniform, the
 * error control content with 0.8 rad steps) err 3.6e-10 of its energy
 * between the steps, 36 times its error at them and 25 times the energy
 * check's bound (found by MM_DRAWS=200: L=0.00125 g=0.90 theta0=0.284
 * omega0=-115.4). */
#define STEP_RADIANS 0.2
/* The dense output's energy error at that step, in steps' allowances
 * (RTOL times the energy's gradient, eq. 8): measured at most 4.3 over 8e5
 * random motions (swings, near the top, over it; runs of 0.05 to 200 rad),
 * most where the run is a few steps long and its own steps err far less */
#define DENSE_STEPS 6

static int check(const mm_value *in, mm_error *err)
{
    mm_pendulum_motion p = model(in);
    double t_end = in[P_TEND].x, r = rate(&p);
    if (t_end * r > MAX_RADIANS)
        return mm_error_set(err, MM_ERANGE, "t_end",
                            "t_end = %g s spans %.3g radians of the motion (rate %.4g 1/s); at most %g fit "
                            "one request: make t_end at most %.4g s", t_end, t_end * r, r, MAX_RADIANS,
                            MAX_RADIANS / r);
    return MM_OK;
}

/* ---- solve -------------------------------------------------------------------- */

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    mm_pendulum_motion p = model(in);
    double t_end = in[P_TEND].x;
    int n = (int)in[P_POINTS].x;

    mm_res_scalar(res, O_OMEGA_N, p.wn);
    mm_res_scalar(res, O_PERIOD_SMALL, p.T0);
    mm_res_scalar_text(res, O_MOTION, p.motion, motion_names[p.motion]);
    if (isfinite(p.T)) {
        mm_res_scalar(res, O_PERIOD, p.T);
        mm_res_scalar(res, O_RATIO, p.T / p.T0);
    } else {
        mm_res_warn(res, "theta0 = pi with omega0 = 0 is the separatrix: the bob balances straight up, and "
                         "in exact arithmetic it stays there forever (the period is infinite, so none is "
                         "given); any disturbance makes it fall: try theta0 = 3.1415");
        if (p.omega0 != 0)
            mm_res_warn(res, "this push lands exactly on the separatrix: the bob creeps up to the top and "
                             "takes forever to arrive");
    }
    if (p.motion == MM_PENDULUM_SWING)
        mm_res_scalar(res, O_AMPL, 2 * asin(fmin(p.k, 1)));
    mm_res_scalar(res, O_K, p.motion == MM_PENDULUM_OVER ? p.kk : p.k);
    if (p.motion == MM_PENDULUM_SWING && p.kc < 1e-3)
        mm_res_warn(res, "the swing reaches within %.2g rad of the top: near the separatrix the period "
                         "grows like 4 ln(8/kc) / omega_n (kc = %.3g), and the integrator's tiny energy "
                         "errors decide the timing more and more", 2 * asin(p.kc), p.kc);

    /* the amplitude of a 1 % longer period, a root of eq. (5); independent:
     * the Maclaurin series of T/T0 in theta0 must give 1.01 within twice its
     * first neglected term */
    double th1, th1_err, next;
    int rc = mm_pendulum_amplitude(1.01, 0.1, 1.0, &th1, &th1_err, err);
    if (rc != MM_OK)
        return rc;
    mm_res_scalar_err(res, O_T1PCT, th1, th1_err, MM_ERR_BOUND);
    double series = mm_pendulum_ratio_series(th1, &next);
    mm_res_check_abs(res, "theta_1pct: T/T0 by its series in theta0 (to theta0^8) vs 1.01", series, 1.01,
                     2 * next + 4 * DBL_EPSILON);

    /* the motion, eq. (1), by DOP853 with dense output */
    mm_series *sth = mm_res_series(res, O_THETA, n), *slin = mm_res_series(res, O_THETA_LIN, n);
    if (!sth || !slin)
        return MM_ENOMEM;
    mm_linspace(0, t_end, n, sth->x);
    double *w = mm_res_alloc(res, (size_t)n * sizeof *w);
    if (!w)
        return MM_ENOMEM;
    double y0[2] = {p.theta0, p.omega0};
    mm_ode_result r;
    double hmax = STEP_RADIANS / rate(&p);    /* the dense output as good as the steps */
    rc = mm_ex_ode_grid(2, rhs, &p, y0, t_end, n, sth->x, RTOL, RTOL, hmax, sth->y, w, &r, res, err);
    if (rc != MM_OK)
        return rc;
    mm_res_method(res, "dop853 (Dormand-Prince 8(5,3), dense output)", 0);
    mm_res_method_stat(res, "rtol", RTOL);
    mm_res_method_stat(res, "steps", (double)r.n_accepted);
    mm_res_method_stat(res, "rejected", (double)r.n_rejected);
    mm_res_method_stat(res, "evaluations", (double)r.n_eval);

    /* checks: the energy, then the trajectory against the exact solution */
    double worst = 0, drift = 0, E0 = mm_pendulum_energy(&p, p.theta0, p.omega0), big = 0, wmax = 0, grad = 0;
    for (int i = 0; i < n; i++) {
        double we, the = mm_pendulum_exact(&p, sth->x[i], &we), th = sth->y[i];
        slin->x[i] = sth->x[i];
        slin->y[i] = p.theta0 * cos(p.wn * sth->x[i]) + p.omega0 / p.wn * sin(p.wn * sth->x[i]);
        worst = fmax(worst, fabs(th - the));
        drift = fmax(drift, fabs(mm_pendulum_energy(&p, th, w[i]) - E0));
        big = fmax(big, fabs(the));
        wmax = fmax(wmax, fabs(we));
        /* the energy's gradient times DOP853's allowance per state (check 2) */
        grad = fmax(grad, fabs(w[i]) * (1 + fabs(w[i])) +
                              p.wn * p.wn * fabs(mm_pendulum_sin_top(th)) * (1 + fabs(th)));
    }
    /* DOP853 holds each step's error in theta and theta' to about RTOL
     * (1 + their size), which moves the energy by at most RTOL grad; over
     * rate * t_end radians of motion these add up (as in eq. 8).  The
     * plotted points come from the dense output, whose own error mid-step
     * (order 7 in rate h <= STEP_RADIANS) the step control does not watch:
     * up to 4.3 RTOL grad over 8e5 random motions of every kind, so
     * DENSE_STEPS = 6 of it.  The old RTOL (E0 + g/L) (1 + rate t_end) had no room for it:
     * a short run (3 steps, 0.28 rad) whose interpolant erred 1.4 RTOL in
     * theta' mid-step failed it (L=0.00926 g=4.30 omega0=27.9).  Plus the
     * rounding of the two energies, each within 6 eps of E0. */
    double steps = 1 + rate(&p) * t_end;
    mm_res_check_abs(res, "energy: largest drift of theta'^2/2 + (g/L)(1 - cos theta) over the run [1/s^2]",
                     drift, 0, RTOL * grad * (DENSE_STEPS + rate(&p) * t_end) + 12 * DBL_EPSILON * E0);
    /* an energy error dE moves the period by |dT/dE| dE, the phase by
     * |theta'| t / T of that: near the separatrix |dT/dE| ~ 1/kc^2 and the
     * integration's own energy error decides the timing (eq. 9) */
    double dTdE = isfinite(p.T) ? mm_pendulum_period_sensitivity(&p) : 0;
    double phase = isfinite(p.T) ? 2 * wmax * t_end / p.T * dTdE * drift : 0;
    /* the steps' errors and the dense output's between them: 1.5 times the
     * step term (eq. 8; measured: a short run on a fine grid reached 1.14) */
    double tol_th = 1.5 * RTOL * (1 + big) * steps + phase;
    mm_res_check_abs(res, "theta(t): DOP853 vs the exact solution in Jacobi functions, worst point [rad]",
                     worst, 0, tol_th);
    if (tol_th > 0.1)
        mm_res_warn(res, "near the separatrix the integration's energy error (%.2g of %.3g) moves the period "
                         "by up to %.2g s: the computed angle can lose its phase by %.2g rad over t_end; the "
                         "closed form (the period, the exact solution) does not suffer from this",
                    drift, E0, dTdE * drift, tol_th);

    if (isfinite(p.T)) {
        double Ka = mm_elliptic_Kc(p.kc), Kc = mm_elliptic_RF(0, p.kc * p.kc, 1);
        mm_res_check_rel(res, "K: arithmetic-geometric mean vs Carlson's R_F", Ka, Kc, 8 * DBL_EPSILON);
        double Tm, dE;
        /* two successive passages through the bottom, where it is well
         * conditioned (mm_dyn_pend_measure_period) */
        rc = mm_dyn_pend_measure_period(&p, rhs, RTOL, STEP_RADIANS / rate(&p), res, &Tm, &dE, err);
        if (rc != MM_OK)
            return rc;
        /* each crossing time: RTOL of the angle's size divided by the speed
         * there, plus the period shift of the energy error at the crossings */
        double bigT = p.motion == MM_PENDULUM_SWING ? 2 * asin(fmin(p.k, 1)) : fabs(p.theta0) + 4 * M_PI;
        double tol_T = RTOL * (1 + bigT) / wmax + 2 * dTdE * dE;
        if (tol_T >= 0.01 * p.T)
            mm_res_warn(res, "the period measured from the integration (%.6g s) is not shown: this close to "
                             "the separatrix the integration's energy error alone can move it by %.2g s",
                        Tm, tol_T);
        mm_res_check_abs(res, "period: measured from two passages through the bottom vs 4 K(k) / omega_n [s]",
                         Tm, p.T, tol_T);
    }

    /* the period against the amplitude (eq. 5), with its first correction */
    if (mm_dyn_pend_period_curve(res, O_RATIO_CURVE, O_RATIO_SERIES))
        return MM_ENOMEM;
    return mm_dyn_pend_animate(&p, t_end, n, sth->x, sth->y, res);
}

static const char *const references[] = {
    "M. Abramowitz, I. A. Stegun, Handbook of Mathematical Functions, 1964, sections 16.4 and 17.6 (AGM)",
    "B. C. Carlson, Numerical computation of real or complex elliptic integrals, Numer. Algorithms 10 (1995)",
    "E. Hairer, S. P. Norsett, G. Wanner, Solving Ordinary Differential Equations I, Springer 1993 (DOP853)",
    NULL,
};

const mm_exercise mm_ex_dyn_pendulum = {
    .id = "dyn-pendulum", .chapter = 4, .section = "4.2", .title = "The pendulum at large amplitude",
    .summary = "Period against amplitude by the elliptic integral (AGM), the exact motion in Jacobi "
               "functions, the separatrix and rotation over the top.",
    .tags = "dynamics, pendulum, nonlinear, elliptic integral, separatrix", .theory = "exercises/dyn/pendulum.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
