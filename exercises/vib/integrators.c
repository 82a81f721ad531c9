/* integrators.c — vib-integrators: one oscillator, six time integrators,
 * every error next to its cost.
 *
 *     x'' + 2 zeta omega_n x' + omega_n^2 x = F cos(omega t),
 *     x(0) = x0,  x'(0) = v0                                            (1)
 *
 * Goal: choose an integrator with open eyes.  The same problem, whose exact
 * solution is known, is solved by central difference, Newmark's average
 * acceleration, Stormer-Verlet (second order, one force evaluation per
 * step), classical Runge-Kutta (fourth order, four evaluations) and the
 * adaptive Dormand-Prince pairs DOPRI5 and DOP853.  A table gives, for the
 * step h and tolerance rtol chosen, each method's step taken (t_end /
 * ceil(t_end / h)), steps, evaluations and achieved error, or "unstable"
 * with the reason when the method is past its stability limit at that step
 * (or its error exceeds 10 times the motion); a work-precision sweep gives
 * error against step and against cost, and the observed orders are checked
 * against theory.  A long
 * free run shows what a method does to energy: average acceleration keeps
 * it, Verlet keeps it bounded, RK4 drains it at exactly the rate its
 * stability function predicts.
 * Reference: E. Hairer, S. P. Norsett, G. Wanner, Solving Ordinary
 * Differential Equations I, Springer 1993 (II.1, II.4-II.6); T. J. R.
 * Hughes, The Finite Element Method, Dover 2000, ch. 9 (Newmark).
 */
#include <complex.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mm_exhelp.h"
#include "mm_newmark.h"
#include "mm_ode.h"

enum { P_OMEGA_N, P_ZETA, P_F, P_OMEGA, P_X0, P_V0, P_TEND, P_H, P_RTOL, P_PERIODS };

static const mm_param params[] = {
    [P_OMEGA_N] = {"omega_n", "natural frequency", "rad/s", MM_REAL, 10, 0.1, 1e3,
                   .help = "sqrt(k/m) of the oscillator"},
    [P_ZETA] = {"zeta", "damping ratio", "", MM_REAL, 0.05, 0, 2, .help = "c / (2 sqrt(k m))"},
    [P_F] = {"F", "force per unit mass", "m/s^2", MM_REAL, 1, 0, 1e3,
             .help = "amplitude of the force divided by the mass; 0 gives free vibration"},
    [P_OMEGA] = {"omega", "forcing frequency", "rad/s", MM_REAL, 8, 0, 1e3,
                 .help = "angular frequency of the force"},
    [P_X0] = {"x0", "initial displacement", "m", MM_REAL, 0.01, -10, 10, .help = "x at t = 0"},
    [P_V0] = {"v0", "initial velocity", "m/s", MM_REAL, 0, -1e3, 1e3, .help = "dx/dt at t = 0"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 10, 1e-2, 1e4,
                .help = "simulated time; at most 1e4 radians of the fastest motion"},
    [P_H] = {"h", "step of the fixed-step methods", "s", MM_REAL, 0.01, 1e-5, 10,
             .help = "central difference, Newmark, Verlet and RK4 take this step; try it near 2/omega_n"},
    [P_RTOL] = {"rtol", "tolerance of the adaptive methods", "", MM_REAL, 1e-6, 1e-12, 1e-2,
                .help = "relative tolerance of DOPRI5 and DOP853 (the absolute one is rtol times the motion's size)"},
    [P_PERIODS] = {"periods", "length of the energy run", "periods", MM_INT, 1000, 10, 5000,
                   .help = "free undamped periods integrated at 20 steps per period to watch the energy"},
};

enum { O_OMEGA_N, O_H_TAKEN, O_WN_H, O_H_STABLE, O_AMPLITUDE, O_T_SWEEP, O_ORDER, O_DRIFT_RK4, O_E_VERLET,
       O_E_NEWMARK, O_METHODS, O_X_EXACT, O_X_M, O_WORK, O_STEP, O_ENERGY };

/* the keys of the series families: the method names as identifiers */
static const char *const mkeys[] = {"central_difference", "newmark_average_acceleration", "stormer_verlet",
                                    "rk4", "dopri5", "dop853", NULL};
static const char *const okeys[] = {"central_difference", "newmark", "verlet", "rk4", NULL};
static const char *const skeys[] = {"central_difference", "newmark_average_acceleration", "stormer_verlet", "rk4",
                                    NULL};
static const char *const ekeys[] = {"newmark", "verlet", "rk4", NULL};
static const char *const cols[] = {"method", "order", "step", "steps", "evaluations", "rejected",
                                   "max_error", "relative_error", NULL};
static const char *const units[] = {"", "", "s", "", "", "", "m", "", NULL};

static const mm_output outputs[] = {
    [O_OMEGA_N] = MM_SCALAR("omega_n", "natural frequency", "rad/s", .flags = MM_EXACT),
    [O_H_TAKEN] = MM_SCALAR("h_taken", "step the fixed-step methods take, t_end / ceil(t_end / h)", "s",
                            .flags = MM_ANSWER | MM_EXACT),
    [O_WN_H] = MM_SCALAR("omega_n_h", "omega_n h: radians per step the fixed-step methods take", "",
                         .flags = MM_ANSWER | MM_EXACT),
    [O_H_STABLE] = MM_SCALAR("h_stable_explicit",
                             "stability limit of central difference (and of Verlet without damping), 2/omega_n", "s",
                             .flags = MM_ANSWER | MM_EXACT),
    [O_AMPLITUDE] = MM_SCALAR("amplitude", "largest |x| of the exact motion at the plotted times", "m",
                              .flags = MM_EXACT),
    [O_T_SWEEP] = MM_SCALAR("t_sweep", "time span of the work-precision sweeps", "s", .flags = MM_EXACT),
    [O_ORDER] = MM_SCALAR("order_%s", "observed order of %s (slope of log error against log h)", "",
                          .keys = okeys),
    [O_DRIFT_RK4] = MM_SCALAR("energy_drift_rk4", "RK4: relative energy change after the run", "",
                              .flags = MM_ANSWER),
    [O_E_VERLET] = MM_SCALAR("energy_error_verlet", "Verlet: largest relative energy error", ""),
    [O_E_NEWMARK] = MM_SCALAR("energy_error_newmark", "average acceleration: largest relative energy error", ""),
    [O_METHODS] = MM_TABLE("methods", "each method at the chosen h or rtol", cols, units),
    [O_X_EXACT] = MM_SERIES("x_exact", "exact displacement", "m", "t", "s", .figure = "response",
                            .role = "reference"),
    [O_X_M] = MM_SERIES("x_%s", "%s", "m", "t", "s", .keys = mkeys, .figure = "response", .mark = "dots"),
    [O_WORK] = MM_SERIES("work_%s", "max error against evaluations, %s", "m", "evaluations", "", .keys = mkeys,
                         .figure = "work", .x_scale = "log", .y_scale = "log"),
    [O_STEP] = MM_SERIES("step_%s", "max error against step, %s", "m", "h", "s", .keys = skeys, .figure = "step",
                         .x_scale = "log", .y_scale = "log"),
    [O_ENERGY] = MM_SERIES("energy_%s", "relative energy error, %s", "", "t/T", "periods", .keys = ekeys,
                           .figure = "energy"),
};

#define MAX_STEPS 50000L        /* steps of one fixed-step run */
#define SWEEP_STEPS 16384L      /* finest run of a work-precision sweep */
#define SWEEP_EVALS 100000L     /* an adaptive sweep stops after a run this costly */
#define PLOT 250                /* samples of each method's curve */
#define STEPS_PER_PERIOD 20     /* of the long free run */

enum { M_CD, M_AA, M_VERLET, M_RK4, M_DOPRI5, M_DOP853, NM };
static const char *const mname[NM] = {"central-difference", "newmark-average-acceleration", "stormer-verlet",
                                      "rk4", "dopri5", "dop853"};
static const int morder[NM] = {2, 2, 2, 4, 5, 8};

typedef struct problem {
    mm_sdof s;             /* m = 1: the closed form of eq. (1) */
    mm_sdof_props p;
    double t_end, scale;   /* scale: largest |x| of the exact motion */
    double *buf_t, *buf_x; /* scratch for MAX_STEPS + 2 step points */
    double *buf_y;         /* 2 (MAX_STEPS + 2) states of the Runge-Kutta runs */
} problem;

typedef struct outcome {
    int ok;                /* 0: the run blew up (unstable) */
    long steps, evals, rejected;
    double h, err;         /* step taken (t_end / ceil(t_end / h); mean step if adaptive),
                              max |x - x_exact| over the step points */
    int n;                 /* step points in buf_t, buf_x */
} outcome;

static mm_sdof model(const mm_value *in)
{
    double wn = in[P_OMEGA_N].x;
    return (mm_sdof){.m = 1, .k = wn * wn, .c = 2 * in[P_ZETA].x * wn, .F0 = in[P_F].x,
                     .omega = in[P_OMEGA].x, .x0 = in[P_X0].x, .v0 = in[P_V0].x};
}

static int check(const mm_value *in, mm_error *err)
{
    mm_sdof s = model(in);
    double t_end = in[P_TEND].x, h = in[P_H].x;
    if (t_end / h > MAX_STEPS)
        return mm_error_set(err, MM_ERANGE, "h", "h = %g s takes %.3g steps to cover t_end = %g s; at most %ld "
                            "fit one request: make h at least %.3g s", h, t_end / h, t_end, MAX_STEPS,
                            t_end / MAX_STEPS);
    return mm_ex_sdof_work_check(&s, t_end, err);
}

/* ---- the runs ------------------------------------------------------------------ */

/* Largest |x - exact| over the step points in buf: all of them up to 2000,
 * else 2000 evenly spread ones and the last (the closed form costs more than
 * a step; the sample keeps every request fast). */
static double max_error(const problem *pb, int n)
{
    double e = 0;
    int stride = n > 2000 ? (n + 1999) / 2000 : 1;
    for (int i = 0; i < n; i += stride)
        e = fmax(e, fabs(pb->buf_x[i] - mm_sdof_x(&pb->s, &pb->p, pb->buf_t[i], NULL)));
    if (n > 0)
        e = fmax(e, fabs(pb->buf_x[n - 1] - mm_sdof_x(&pb->s, &pb->p, pb->buf_t[n - 1], NULL)));
    return e;
}

static int force_fn(double t, const double *q, const double *qd, double *F, void *ctx)
{
    (void)q;
    (void)qd;
    const mm_sdof *s = ctx;
    F[0] = s->F0 * cos(s->omega * t);
    return 0;
}

/* The step a fixed-step run of mm_newmark or mm_ode takes when asked for h
 * over [0, T]: both make the steps equal (mm_ode_fixed_steps). */
static double step_taken(double T, double h)
{
    return T / mm_ode_fixed_steps(T, h);
}

/* Central difference, average acceleration or Verlet with step h over
 * [0, t_end] (mm_newmark), every step point into buf. */
static int run_newmark(problem *pb, int m, double h, double t_end, outcome *o, mm_error *err)
{
    double M = 1, C = pb->s.c, K = pb->s.k, q0 = pb->s.x0, v0 = pb->s.v0;
    mm_newmark_problem prob = {.n = 1, .M = &M, .C = &C, .K = &K, .force = pb->s.F0 ? force_fn : NULL,
                               .force_kind = MM_NEWMARK_FORCE_TIME, .params = &pb->s, .q0 = &q0,
                               .qd0 = &v0, .t0 = 0, .t_end = t_end};
    mm_newmark_options opt;
    mm_newmark_options_init(&opt);
    opt.method = m == M_CD ? MM_NEWMARK_CENTRAL : m == M_AA ? MM_NEWMARK_AVERAGE : MM_NEWMARK_VERLET;
    opt.h = h;
    opt.max_steps = MAX_STEPS + 1;
    mm_newmark_result r = {.t = pb->buf_t, .q = pb->buf_x, .max_rows = MAX_STEPS + 2};
    *o = (outcome){.h = step_taken(t_end, h)};
    int rc = mm_newmark_check(&prob, &opt, err);
    if (rc == MM_OK)
        o->h = t_end / (double)mm_newmark_step_count(&prob, &opt);   /* the steps it takes */
    mm_newmark_work *w = rc == MM_OK ? mm_newmark_work_alloc(1) : NULL;
    if (rc == MM_OK && !w)
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
    if (rc == MM_OK)
        rc = mm_newmark_solve(&prob, &opt, w, &r, err);
    mm_newmark_work_free(w);
    o->steps = r.steps;
    o->evals = r.force_evals ? r.force_evals : r.steps + 1;   /* F = 0: the force is still "evaluated" */
    if (rc == MM_ENONFINITE)
        return MM_OK;                     /* unstable: reported, not an error */
    if (rc != MM_OK)
        return rc;
    o->ok = 1;
    o->n = r.rows;
    o->err = max_error(pb, r.rows);
    return MM_OK;
}

/* RK4 with step h, or DOPRI5 / DOP853 at tolerance rtol (mm_ode), every
 * accepted step point into buf. */
static int run_rk(problem *pb, int m, double h, double rtol, double t_end, outcome *o, mm_error *err)
{
    double y0[2] = {pb->s.x0, pb->s.v0};
    size_t cap = MAX_STEPS + 2;
    double *ys = pb->buf_y;
    mm_ode_problem prob = {.n = 2, .f = mm_sdof_rhs, .params = &pb->s, .t0 = 0, .t_end = t_end, .y0 = y0};
    mm_ode_options opt;
    mm_ode_options_init(&opt);
    opt.method = m == M_RK4 ? MM_ODE_RK4 : m == M_DOPRI5 ? MM_ODE_DOPRI5 : MM_ODE_DOP853;
    if (m == M_RK4) {
        opt.h = h;
    } else {
        opt.rtol = rtol;
        opt.atol = rtol * pb->scale;
    }
    opt.max_steps = MAX_STEPS;
    mm_ode_result r = {0};
    r.t_steps = pb->buf_t;
    r.y_steps = ys;
    r.steps_cap = cap;
    *o = (outcome){.h = m == M_RK4 ? step_taken(t_end, h) : 0};
    int rc = mm_ode_check(&prob, &opt, &r, err);
    mm_ode_work *w = rc == MM_OK ? mm_ode_work_alloc(2) : NULL;
    if (rc == MM_OK && !w)
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
    if (rc == MM_OK)
        rc = mm_ode_solve(&prob, &opt, w, &r, err);
    mm_ode_work_free(w);
    o->steps = r.n_accepted;
    o->evals = r.n_eval;
    o->rejected = r.n_rejected;
    if (m != M_RK4)
        o->h = r.n_accepted ? r.t_reached / r.n_accepted : 0;
    if (rc == MM_ENONFINITE || (m != M_RK4 && rc == MM_ENOCONV))
        return MM_OK;                     /* unstable, or too costly: reported */
    if (rc != MM_OK)
        return rc;
    o->ok = 1;
    o->n = (int)r.n_stored;
    for (int i = 0; i < o->n; i++)
        pb->buf_x[i] = ys[2 * i];
    o->err = max_error(pb, o->n);
    return MM_OK;
}

static int run(problem *pb, int m, double h, double rtol, double t_end, outcome *o, mm_error *err)
{
    if (m <= M_VERLET)
        return run_newmark(pb, m, h, t_end, o, err);
    return run_rk(pb, m, h, rtol, t_end, o, err);
}

/* Slope of log(err) against log(h) by least squares over the (up to) four
 * finest steps whose error lies in the asymptotic range [1e-11, 1e-2] of
 * the motion's size (above: the step is too coarse for the leading error
 * term to rule; below: round-off).  h is decreasing.  *spread receives the
 * largest difference of a local slope (neighbours) from the fit: how far
 * the points are from one straight line.  Returns the number of points. */
static int observed_order(const double *h, const double *e, int n, double scale, double *p, double *spread)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0, lx[4], ly[4];
    int k = 0;
    for (int i = n - 1; i >= 0 && k < 4; i--) {
        if (!(e[i] <= 1e-2 * scale && e[i] >= 1e-11 * scale))
            continue;
        lx[k] = log(h[i]), ly[k] = log(e[i]);
        sx += lx[k], sy += ly[k], sxx += lx[k] * lx[k], sxy += lx[k] * ly[k];
        k++;
    }
    if (k < 3)
        return k;
    *p = (k * sxy - sx * sy) / (k * sxx - sx * sx);
    *spread = 0;
    for (int j = 1; j < k; j++)
        *spread = fmax(*spread, fabs((ly[j] - ly[j - 1]) / (lx[j] - lx[j - 1]) - *p));
    return k;
}

/* ---- the long free run: energy ------------------------------------------------- */

typedef struct energy_run {
    double drift_end;      /* E/E0 - 1 at the end */
    double worst;          /* max |E/E0 - 1| over the samples */
    double modified;       /* Verlet: max |Em/Em0 - 1| of the modified energy */
} energy_run;

/* Free undamped x'' + w^2 x = 0 from x = 1, N steps of h, by method m; the
 * relative energy error sampled every stride steps (and at the end) into
 * series se.  RK4 writes its samples as grid output (its continuous
 * extension at step ends), so no step is stored. */
static int energy_view(int m, double w, double h, long N, long stride, mm_series *se, energy_run *er,
                       double *tb, double *xb, double *vb, mm_result *res, mm_error *err)
{
    int rows = (int)(N / stride + 1 + (N % stride != 0)), rc;
    if (m == M_RK4) {
        double y0[2] = {1, 0}, *ys = mm_res_alloc(res, 2 * (size_t)rows * sizeof *ys);
        if (!ys)
            return MM_ENOMEM;
        for (int i = 0; i < rows; i++)
            tb[i] = (double)(i * stride < N ? i * stride : N) * h;
        mm_sdof s = {.m = 1, .k = w * w};
        mm_ode_problem prob = {.n = 2, .f = mm_sdof_rhs, .params = &s, .t0 = 0, .t_end = N * h, .y0 = y0};
        mm_ode_options opt;
        mm_ode_options_init(&opt);
        opt.method = MM_ODE_RK4;
        opt.h = h;
        opt.max_steps = N + 1;
        mm_ode_result r = {.t_out = tb, .nout = (size_t)rows, .y_out = ys};
        mm_ode_work *wk = mm_ode_work_alloc(2);
        rc = wk ? mm_ode_solve(&prob, &opt, wk, &r, err) : MM_ENOMEM;
        mm_ode_work_free(wk);
        for (int i = 0; i < rows; i++)
            xb[i] = ys[2 * i], vb[i] = ys[2 * i + 1];
    } else {
        double M = 1, K = w * w, q0 = 1, v0 = 0;
        mm_newmark_problem prob = {.n = 1, .M = &M, .K = &K, .q0 = &q0, .qd0 = &v0, .t0 = 0, .t_end = N * h};
        mm_newmark_options opt;
        mm_newmark_options_init(&opt);
        opt.method = m == M_AA ? MM_NEWMARK_AVERAGE : MM_NEWMARK_VERLET;
        opt.h = h;
        opt.stride = stride;
        opt.max_steps = N + 1;
        mm_newmark_result r = {.t = tb, .q = xb, .qd = vb, .max_rows = rows};
        rc = mm_newmark_check(&prob, &opt, err);
        mm_newmark_work *wk = rc == MM_OK ? mm_newmark_work_alloc(1) : NULL;
        if (rc == MM_OK)
            rc = wk ? mm_newmark_solve(&prob, &opt, wk, &r, err) : MM_ENOMEM;
        mm_newmark_work_free(wk);
        rows = r.rows;
    }
    if (rc != MM_OK)
        return rc;
    double a = (w * h) * (w * h) / 4;
    double E0 = 0.5 * w * w, Em0 = E0 * (1 - a);     /* x0 = 1, v0 = 0 */
    *er = (energy_run){0};
    se->n = rows;
    for (int i = 0; i < rows; i++) {
        double E = 0.5 * vb[i] * vb[i] + 0.5 * w * w * xb[i] * xb[i];
        double Em = 0.5 * vb[i] * vb[i] + 0.5 * w * w * xb[i] * xb[i] * (1 - a);
        se->x[i] = nearbyint(tb[i] / h) / STEPS_PER_PERIOD;     /* t / T, short */
        se->y[i] = E / E0 - 1;
        er->worst = fmax(er->worst, fabs(E / E0 - 1));
        er->modified = fmax(er->modified, fabs(Em / Em0 - 1));
        er->drift_end = E / E0 - 1;
    }
    mm_ex_round_sig(se->y, rows, 3);                   /* an error needs no more digits */
    return MM_OK;
}

/* |R(i z)|^2 of classical Runge-Kutta, R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24:
 * with z = i y, |R|^2 = (1 - y^2/2 + y^4/24)^2 + (y - y^3/6)^2 = 1 - y^6/72 + y^8/576. */
static double rk4_gain2(double y)
{
    double re = 1 - y * y / 2 + y * y * y * y / 24, im = y - y * y * y / 6;
    return re * re + im * im;
}

/* ---- stability of the fixed-step methods on eq. (1) ------------------------------- */

/* One step of the free (F = 0) recursion of central difference, Verlet or
 * average acceleration on x'' + c x' + k x = 0, as mm_newmark takes it:
 * state (x, v, a) -> (x1, v1, a1). */
static void newmark_step(int m, double k, double c, double h, const double s[3], double o[3])
{
    double x = s[0], v = s[1], a = s[2];
    if (m == M_CD) {
        double vt = v + h / 2 * a;
        o[0] = x + h * v + h * h / 2 * a;
        o[2] = (-k * o[0] - c * vt) / (1 + h / 2 * c);
        o[1] = vt + h / 2 * o[2];
    } else if (m == M_VERLET) {
        double vt = v + h / 2 * a;                   /* damping sees the half-step velocity */
        o[0] = x + h * vt;
        o[2] = -k * o[0] - c * vt;
        o[1] = vt + h / 2 * o[2];
    } else {                                         /* beta = 1/4, gamma = 1/2 */
        double xp = x + h * v + h * h / 4 * a, vp = v + h / 2 * a;
        o[2] = (-k * xp - c * vp) / (1 + c * h / 2 + k * h * h / 4);
        o[0] = xp + h * h / 4 * o[2];
        o[1] = vp + h / 2 * o[2];
    }
}

/* Spectral radius of the amplification matrix A of that step (Hughes,
 * ch. 9): the new a follows from two combinations of the old state, so A
 * (3 x 3) has rank 2, det A = 0, and its other eigenvalues solve
 * l^2 - tr(A) l + (sum of the principal 2 x 2 minors) = 0. */
static double newmark_radius(int m, double k, double c, double h)
{
    double A[3][3];
    for (int j = 0; j < 3; j++) {
        double e[3] = {j == 0, j == 1, j == 2}, o[3];
        newmark_step(m, k, c, h, e, o);
        for (int i = 0; i < 3; i++)
            A[i][j] = o[i];
    }
    double tr = A[0][0] + A[1][1] + A[2][2];
    double c1 = A[0][0] * A[1][1] - A[0][1] * A[1][0] + A[0][0] * A[2][2] - A[0][2] * A[2][0] +
                A[1][1] * A[2][2] - A[1][2] * A[2][1];
    double complex d = csqrt(tr * tr - 4 * c1);
    return fmax(cabs((tr + d) / 2), cabs((tr - d) / 2));
}

/* Is fixed-step method m past its stability limit on eq. (1) at the step h
 * it takes?  Central difference and Verlet: omega_n h >= 2 (with damping
 * Verlet's damping force sees the half-step velocity and its limit drops
 * below 2: then the spectral radius of its step says); average
 * acceleration: spectral radius > 1 (never, for zeta >= 0); RK4: |R(lambda
 * h)| > 1 for an eigenvalue lambda = omega_n (-zeta +- sqrt(zeta^2 - 1)) of
 * the oscillator.  why receives the reason. */
static int past_limit(int m, double wn, double zeta, double h, char *why, size_t len)
{
    double wh = wn * h;
    if (m == M_RK4) {
        double complex root = csqrt(zeta * zeta - 1);
        double gain = 0;
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            double complex z = wh * (-zeta + sgn * root);
            gain = fmax(gain, cabs(1 + z + z * z / 2 + z * z * z / 6 + z * z * z * z / 24));
        }
        snprintf(why, len, "|R(lambda h)| = %.4g > 1 at omega_n h = %.3g", gain, wh);
        return gain > 1 + 1e-12;
    }
    if ((m == M_CD || m == M_VERLET) && wh >= 2) {
        snprintf(why, len, "omega_n h = %.3g >= 2", wh);
        return 1;
    }
    double rho = newmark_radius(m, wn * wn, 2 * zeta * wn, h);
    snprintf(why, len, "spectral radius of the step %.4g > 1 at omega_n h = %.3g%s", rho, wh,
             m == M_VERLET ? " (damping lowers Verlet's limit below 2)" : "");
    return rho > 1 + 1e-12;
}

/* Append s to the string in buf (cap bytes) if it fits. */
static void append(char *buf, size_t cap, const char *s)
{
    size_t l = strlen(buf), k = strlen(s);
    if (l + k < cap)
        memcpy(buf + l, s, k + 1);
}

/* ---- solve ----------------------------------------------------------------------- */

/* The table row of method m after its run o at the chosen h or rtol. */
static int table_row(const problem *pb, int m, const outcome *o, double zeta, mm_table *tab, char *unstable,
                     size_t cap, mm_result *res)
{
    double *row = tab->cell + 8 * m, wn = pb->p.omega_n;
    const char **txt = tab->text + 8 * m;
    txt[0] = mname[m];
    row[1] = m == M_VERLET && zeta > 0 ? 1 : morder[m];        /* damped Verlet: first order, its damping
                                                                  force sees the half-step velocity */
    row[2] = o->h;
    row[3] = (double)o->steps;
    row[4] = (double)o->evals;
    row[5] = (double)o->rejected;
    row[6] = o->ok ? o->err : 0;                               /* replaced by a text when not ok */
    row[7] = o->ok ? o->err / pb->scale : 0;
    /* unstable: past the method's stability limit at the step taken, or
     * blown up, or an error above 10 times the motion's size */
    char why[160], l6[240], l7[240];
    int past = m <= M_RK4 && past_limit(m, wn, zeta, o->h, why, sizeof why);
    if (past) {
        append(unstable, cap, unstable[0] ? ", " : "");
        append(unstable, cap, mname[m]);
    }
    if (!o->ok && m > M_RK4) {
        txt[6] = txt[7] = "not finished: more than 5e4 steps";
    } else if (!o->ok) {
        snprintf(l6, sizeof l6, "unstable: %s; the solution overflowed", past ? why : "blew up");
        if (!(txt[6] = txt[7] = mm_res_strdup(res, l6)))
            return MM_ENOMEM;
    } else if (past || o->err > 10 * pb->scale) {
        if (!past)
            snprintf(why, sizeof why, "error %.3g times the motion's size (> 10)", o->err / pb->scale);
        snprintf(l6, sizeof l6, "unstable: %s; error %.3g m", why, o->err);
        snprintf(l7, sizeof l7, "unstable: %s; error %.3g", why, o->err / pb->scale);
        if (!(txt[6] = mm_res_strdup(res, l6)) || !(txt[7] = mm_res_strdup(res, l7)))
            return MM_ENOMEM;
    }
    /* the computed curve, at up to PLOT of its step points, to the digits
     * its error leaves (never fewer than 3) */
    if (o->ok && o->n >= 2) {
        int stride = (o->n + PLOT - 1) / PLOT, ns = (o->n - 1) / stride + 1;
        mm_series *sm = mm_res_series_i(res, O_X_M, m, ns);
        if (!sm)
            return MM_ENOMEM;
        for (int i = 0; i < ns; i++) {
            sm->x[i] = pb->buf_t[i * stride];
            sm->y[i] = pb->buf_x[i * stride];
        }
        double rel = o->err / pb->scale;
        mm_ex_round_sig(sm->y, ns, rel > 0 ? (int)fmin(17, fmax(3, ceil(-log10(rel)) + 1)) : 17);
    }
    return MM_OK;
}

/* Work-precision sweeps over at most 20 periods of the fastest motion (long
 * runs would leave no room for fine steps), and the observed orders. */
static int sweeps(problem *pb, double zeta, long *total_evals, mm_result *res, mm_error *err)
{
    double wmax = fmax(pb->p.omega_n, pb->s.F0 != 0 ? pb->s.omega : 0);
    double t_sw = fmin(pb->t_end, 20 * 2 * M_PI / wmax), h0 = fmin(0.5 / wmax, t_sw / 8);
    mm_res_scalar(res, O_T_SWEEP, t_sw);
    for (int m = 0; m < NM; m++) {
        double hs[24], es[24], cs[24];
        int n = 0;
        for (int k = 0; k < 24; k++) {
            outcome o;
            double hk = h0 / ldexp(1, k), tol = pow(10, -3 - k);
            if ((m <= M_RK4 && t_sw / hk > SWEEP_STEPS) || (m > M_RK4 && tol < 1e-13))
                break;
            int rc = run(pb, m, hk, tol, t_sw, &o, err);
            if (rc != MM_OK)
                return rc;
            *total_evals += o.evals;
            if (!o.ok)
                break;
            hs[n] = o.h;                     /* the step taken (mean if adaptive) */
            es[n] = fmax(o.err, 1e-300);
            cs[n++] = (double)o.evals;
            if (m > M_RK4 && o.evals > SWEEP_EVALS)
                break;
        }
        mm_series *sw = mm_res_series_i(res, O_WORK, m, n), *sh = m <= M_RK4 ? mm_res_series_i(res, O_STEP, m, n) : NULL;
        if (!sw || (m <= M_RK4 && !sh))
            return MM_ENOMEM;
        for (int i = 0; i < n; i++) {
            sw->x[i] = cs[i], sw->y[i] = es[i];
            if (sh)
                sh->x[i] = hs[i], sh->y[i] = es[i];
        }
        mm_ex_round_sig(sw->y, n, 3);
        if (sh)
            mm_ex_round_sig(sh->y, n, 3);
        double order, spread;
        if (m > M_RK4 || observed_order(hs, es, n, pb->scale, &order, &spread) < 3)
            continue;
        /* the slope of a line through points that bend is known only to
         * their spread: that is its error */
        mm_scalar *sc = mm_res_scalar_i(res, O_ORDER, m, order);
        sc->error = spread;
        sc->error_kind = MM_ERR_ESTIMATE;
        /* theory: 2, 2, 4, and Verlet 2 without damping.  With damping
         * Verlet's damping force sees the half-step velocity, an error of
         * first order in zeta omega_n h beside the second-order error of the
         * rest: which one shows depends on zeta, omega and h, so that slope
         * is reported but not checked */
        if (m == M_VERLET && zeta > 0)
            continue;
        char name[160];
        snprintf(name, sizeof name, "%s: observed order vs %d, within 10 times the spread of its local slopes",
                 mname[m], morder[m]);
        mm_res_check_abs(res, name, order, morder[m], 10 * spread + 1e-4);
    }
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    problem pb = {.s = model(in), .t_end = in[P_TEND].x};
    mm_sdof_props_get(&pb.s, &pb.p);
    double h = in[P_H].x, rtol = in[P_RTOL].x, wn = pb.p.omega_n, zeta = in[P_ZETA].x;
    double t_end = pb.t_end;
    int periods = (int)in[P_PERIODS].x, rc;

    pb.buf_t = mm_res_alloc(res, 4 * (MAX_STEPS + 2) * sizeof(double));
    if (!pb.buf_t)
        return MM_ENOMEM;
    pb.buf_x = pb.buf_t + MAX_STEPS + 2;
    pb.buf_y = pb.buf_x + MAX_STEPS + 2;

    /* the exact motion, and its size */
    mm_series *sx = mm_res_series(res, O_X_EXACT, 2 * PLOT + 1);
    if (!sx)
        return MM_ENOMEM;
    mm_ex_time_grid(t_end, 2 * PLOT + 1, sx->x);
    for (int i = 0; i <= 2 * PLOT; i++)
        sx->y[i] = mm_sdof_x(&pb.s, &pb.p, sx->x[i], NULL);
    pb.scale = fmax(mm_maxabs(sx->y, 2 * PLOT + 1), 1e-300);

    /* the fixed-step methods take N = ceil(t_end / h) equal steps */
    double h_taken = step_taken(t_end, h);
    mm_res_scalar(res, O_OMEGA_N, wn);
    mm_res_scalar(res, O_H_TAKEN, h_taken);
    mm_res_scalar(res, O_WN_H, wn * h_taken);
    mm_res_scalar(res, O_H_STABLE, 2 / wn);
    mm_res_scalar(res, O_AMPLITUDE, pb.scale);

    /* ---- the table: each method at the chosen h or rtol ---- */
    mm_table *tab = mm_res_table(res, O_METHODS, NM);
    if (!tab)
        return MM_ENOMEM;
    long total_evals = 0;
    char unstable[160] = "";
    for (int m = 0; m < NM; m++) {
        outcome o;
        if ((rc = run(&pb, m, h, rtol, t_end, &o, err)) != MM_OK ||
            (rc = table_row(&pb, m, &o, zeta, tab, unstable, sizeof unstable, res)) != MM_OK)
            return rc;
        total_evals += o.evals;
    }
    if (unstable[0])
        mm_res_warn(res, "at the step taken, h = %.4g s (omega_n h = %.3g), %s %s past the stability limit: "
                    "the solution grows without bound whatever the physics does (see the table); average "
                    "acceleration stays stable but is inaccurate at large steps", h_taken, wn * h_taken,
                    unstable, strchr(unstable, ',') ? "are" : "is");

    if ((rc = sweeps(&pb, zeta, &total_evals, res, err)) != MM_OK)
        return rc;

    /* ---- the long free run: what happens to energy ---- */
    double hE = 2 * M_PI / wn / STEPS_PER_PERIOD;
    long N = (long)STEPS_PER_PERIOD * periods, stride = (N + 2 * PLOT - 1) / (2 * PLOT);
    int rows = (int)(N / stride + 2);
    double *tb = mm_res_alloc(res, 3 * (size_t)rows * sizeof *tb), *xb = tb + rows, *vb = xb + rows;
    if (!tb)
        return MM_ENOMEM;
    static const int em[3] = {M_AA, M_VERLET, M_RK4};
    energy_run er[3];
    for (int j = 0; j < 3; j++) {
        mm_series *se = mm_res_series_i(res, O_ENERGY, j, rows);
        if (!se)
            return MM_ENOMEM;
        if ((rc = energy_view(em[j], wn, hE, N, stride, se, &er[j], tb, xb, vb, res, err)) != MM_OK)
            return rc;
        total_evals += em[j] == M_RK4 ? 4 * N : N;
    }
    double y = wn * hE, a = y * y / 4;
    /* the round-off of N steps: a few eps of the energy each */
    double rnd = 4 * DBL_EPSILON * (double)N;
    /* RK4 maps (omega x, v) by a rotation-and-scaling: the energy is
     * multiplied by exactly |R(i omega h)|^2 each step, eq. (7) */
    double predicted = expm1((double)N * log(rk4_gain2(y)));
    mm_ex_scalar_beside(res, O_DRIFT_RK4, er[2].drift_end, predicted, 4 * DBL_EPSILON * N * fabs(predicted));
    mm_res_scalar_err(res, O_E_VERLET, er[1].worst, rnd, MM_ERR_BOUND);
    mm_res_scalar_err(res, O_E_NEWMARK, er[0].worst, rnd, MM_ERR_BOUND);
    mm_res_check_abs(res, "RK4: energy change over the run vs |R(i omega h)|^(2N) - 1, eq. (7), to round-off of "
                          "N steps", er[2].drift_end, predicted, rnd * (1 + fabs(predicted)));
    /* Verlet conserves the modified energy v^2/2 + w^2 x^2 (1 - (w h)^2/4)/2
     * exactly, so the true energy stays within (w h)^2 / (4 - (w h)^2), eq. (8) */
    mm_res_check_abs(res, "Verlet: modified energy conserved, eq. (8), to round-off of N steps", er[1].modified, 0,
                     rnd);
    mm_res_check_abs(res, "Verlet: energy error within the bound (w h)^2/(4 - (w h)^2) of eq. (8)", er[1].worst, 0,
                     a / (1 - a) + rnd);
    /* average acceleration conserves the energy of a linear undamped system */
    mm_res_check_abs(res, "average acceleration: energy conserved, eq. (6), to round-off of N steps", er[0].worst,
                     0, rnd);

    mm_res_method(res, "central difference, Newmark average acceleration, Stormer-Verlet, RK4 (step h, "
                       "made t_end / ceil(t_end / h)); DOPRI5, DOP853 (tolerance rtol)", h_taken);
    mm_res_method_stat(res, "rtol", rtol);
    mm_res_method_stat(res, "evaluations", (double)total_evals);
    return MM_OK;
}

static const char *const references[] = {
    "E. Hairer, S. P. Norsett, G. Wanner, Solving Ordinary Differential Equations I, 2nd ed., Springer 1993, "
    "sections II.1, II.4-II.6",
    "E. Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed., Springer 2006, ch. I and IX",
    "T. J. R. Hughes, The Finite Element Method, Dover 2000, ch. 9 (Newmark methods)",
    NULL,
};

const mm_exercise mm_ex_vib_integrators = {
    .id = "vib-integrators",
    .chapter = 5,
    .section = "5.8",
    .title = "Time integrators compared: error against cost",
    .summary = "One oscillator by central difference, Newmark, Verlet, RK4, DOPRI5 and DOP853: errors, costs, orders, energy.",
    .tags = "vibration, numerical methods, time integration, Newmark, Runge-Kutta, work-precision, energy",
    .theory = "exercises/vib/integrators.md",
    .script = "exercises/vib/integrators.m",
    .outputs = outputs,
    .n_outputs = MM_COUNT(outputs),
    .params = params,
    .n_params = MM_COUNT(params),
    .references = references,
    .check = check,
    .solve = solve,
};
