/* test_ode.c — the integrators of mm_ode against independent references:
 * closed-form solutions (forced damped oscillator with its transient,
 * exponential decay, rotation, undamped resonance, a stiff relaxation),
 * measured orders of convergence at steps and between them (dense output),
 * RK4's energy loss against its amplification factor, the counters, every
 * error path a request can reach, and concurrent use from several threads.
 * No method is ever checked against itself.
 */
#include "mm_test.h"

#include <pthread.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "mm_ode.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* ======================================================================== */
/* Problems with closed-form solutions                                      */
/* ======================================================================== */

/* Every right-hand side counts its calls, to check n_eval independently. */
typedef struct ctx {
    long calls;
    double lambda;     /* decay rate or stiffness, when used */
    double omega;      /* angular frequency, when used */
    double t_stop;     /* callback tests: misbehave after this time */
    int stop_code;     /* callback tests: value returned after t_stop */
} ctx;

/* Forced damped oscillator x'' + 2x' + 100x = cos 8t  (m = 1, c = 2,
 * k = 100, F0 = 1, omega = 8) as y = (x, v). */
static int osc_rhs(double t, const double *y, double *dydt, void *params)
{
    ((ctx *)params)->calls++;
    dydt[0] = y[1];
    dydt[1] = cos(8.0 * t) - 2.0 * y[1] - 100.0 * y[0];
    return 0;
}

/* Its exact solution from x(0) = x0, x'(0) = v0.
 * Steady state A cos 8t + B sin 8t:  (100 - 64) A + 16 B = 1 and
 * (100 - 64) B - 16 A = 0  give  A = 9/388, B = 1/97.
 * Transient e^{-t} (C cos wd t + D sin wd t) with zeta wn = 1,
 * wd = sqrt(100 - 1) = sqrt(99):  C = x0 - A,  D = (v0 - 8B + C) / wd. */
static void osc_exact(double x0, double v0, double t, double *x, double *v)
{
    const double A = 9.0 / 388.0, B = 1.0 / 97.0, wd = sqrt(99.0);
    const double C = x0 - A, D = (v0 - 8.0 * B + C) / wd;
    double e = exp(-t), cw = cos(wd * t), sw = sin(wd * t);
    *x = A * cos(8.0 * t) + B * sin(8.0 * t) + e * (C * cw + D * sw);
    *v = -8.0 * A * sin(8.0 * t) + 8.0 * B * cos(8.0 * t)
         + e * ((-C + D * wd) * cw + (-D - C * wd) * sw);
}

static double osc_x(double t)   /* x0 = 0.5, v0 = 0: the start used below */
{
    double x, v;
    osc_exact(0.5, 0.0, t, &x, &v);
    return x;
}

/* y' = -lambda y:  y = y0 e^{-lambda t}. */
static int decay_rhs(double t, const double *y, double *dydt, void *params)
{
    ctx *c = params;
    (void)t;
    c->calls++;
    dydt[0] = -c->lambda * y[0];
    return 0;
}

/* Rotation y1' = -omega y2, y2' = omega y1:  (cos omega t, sin omega t). */
static int rot_rhs(double t, const double *y, double *dydt, void *params)
{
    ctx *c = params;
    (void)t;
    c->calls++;
    dydt[0] = -c->omega * y[1];
    dydt[1] = c->omega * y[0];
    return 0;
}

/* Undamped oscillator x'' + omega^2 x = F(t); here F = cos t at omega = 1
 * (resonance) or F = 0 (free). */
static int res_rhs(double t, const double *y, double *dydt, void *params)
{
    ((ctx *)params)->calls++;
    dydt[0] = y[1];
    dydt[1] = cos(t) - y[0];
    return 0;
}

static int free_rhs(double t, const double *y, double *dydt, void *params)
{
    ctx *c = params;
    (void)t;
    c->calls++;
    dydt[0] = y[1];
    dydt[1] = -c->omega * c->omega * y[0];
    return 0;
}

/* Stiff relaxation onto cos t:  y' = -lambda (y - cos t).
 * Exact: y = (lambda^2 cos t + lambda sin t) / (lambda^2 + 1) + K e^{-lambda t},
 * K = y0 - lambda^2 / (lambda^2 + 1). */
static int stiff_rhs(double t, const double *y, double *dydt, void *params)
{
    ctx *c = params;
    c->calls++;
    dydt[0] = -c->lambda * (y[0] - cos(t));
    return 0;
}

static double stiff_exact(double lambda, double y0, double t)
{
    double l2 = lambda * lambda;
    return (l2 * cos(t) + lambda * sin(t)) / (l2 + 1.0)
           + (y0 - l2 / (l2 + 1.0)) * exp(-lambda * t);
}

/* y' = y^2 from y(0) = 1: y = 1 / (1 - t), blows up at t = 1. */
static int blowup_rhs(double t, const double *y, double *dydt, void *params)
{
    (void)t;
    ((ctx *)params)->calls++;
    dydt[0] = y[0] * y[0];
    return 0;
}

/* The oscillator, but the callback stops (returns c->stop_code) or returns
 * NaN (stop_code 0) once t > t_stop. */
static int misbehaving_rhs(double t, const double *y, double *dydt, void *params)
{
    ctx *c = params;
    osc_rhs(t, y, dydt, params);
    if (t > c->t_stop) {
        if (c->stop_code)
            return c->stop_code;
        dydt[1] = NAN;
    }
    return 0;
}

/* ======================================================================== */
/* Helpers                                                                  */
/* ======================================================================== */

/* Measured values, printed when MM_VERBOSE is set: what the tolerances
 * below were chosen against. */
static void note(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
static void note(const char *fmt, ...)
{
    if (!getenv("MM_VERBOSE"))
        return;
    va_list ap;
    va_start(ap, fmt);
    fputs("   note: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
}

static mm_ode_options opts(mm_ode_method method, double tol, double h)
{
    mm_ode_options o;
    mm_ode_options_init(&o);
    o.method = method;
    o.rtol = o.atol = tol;
    o.h = h;
    return o;
}

/* Solve prob with o; fills res (caller sets its arrays).  Asserts that a
 * workspace exists. */
static int solve(const mm_ode_problem *prob, const mm_ode_options *o,
                 mm_ode_result *res, mm_error *err)
{
    mm_ode_work *w = mm_ode_work_alloc(prob->n);
    assert_non_null(w);
    int rc = mm_ode_solve(prob, o, w, res, err);
    mm_ode_work_free(w);
    return rc;
}

static mm_ode_problem osc_problem(ctx *c, const double *y0, double t_end)
{
    return (mm_ode_problem){.n = 2, .f = osc_rhs, .params = c, .t0 = 0.0,
                            .t_end = t_end, .y0 = y0};
}

static const double OSC_Y0[2] = {0.5, 0.0};

/* Uniform grid of n points on [a, b] (both ends included). */
static double *grid(double a, double b, size_t n)
{
    double *t = malloc(n * sizeof *t);
    assert_non_null(t);
    for (size_t i = 0; i < n; i++)
        t[i] = a + (b - a) * (double)i / (double)(n - 1);
    t[n - 1] = b;
    return t;
}

/* Max |x - osc_x(t)| over the n rows of (t, y) with stride 2. */
static double osc_max_err(const double *t, const double *y, size_t n)
{
    double e = 0.0;
    for (size_t i = 0; i < n; i++)
        e = fmax(e, fabs(y[2 * i] - osc_x(t[i])));
    return e;
}

/* Run the oscillator on [0, t_end] with fixed step h; return the max error
 * at the step points and at the midpoints between them (dense output). */
static void osc_fixed_errors(mm_ode_method method, double h, double t_end,
                             double *err_steps, double *err_mid)
{
    ctx c = {0};
    mm_ode_problem prob = osc_problem(&c, OSC_Y0, t_end);
    mm_ode_options o = opts(method, 1e-6, h);
    size_t N = (size_t)llround(t_end / h);
    double *ts = malloc((N + 1) * sizeof *ts), *ys = malloc(2 * (N + 1) * sizeof *ys);
    double *tm = malloc(N * sizeof *tm), *ym = malloc(2 * N * sizeof *ym);
    assert_true(ts && ys && tm && ym);
    for (size_t i = 0; i < N; i++)
        tm[i] = ((double)i + 0.5) * (t_end / (double)N);
    mm_ode_result res = {0};
    res.t_steps = ts;
    res.y_steps = ys;
    res.steps_cap = N + 1;
    res.t_out = tm;
    res.nout = N;
    res.y_out = ym;
    mm_error err;
    assert_int_equal(solve(&prob, &o, &res, &err), MM_OK);
    assert_int_equal(res.n_accepted, (long)N);
    assert_int_equal(res.n_first_halves, 0);     /* fixed steps: no estimate to check */
    *err_steps = osc_max_err(ts, ys, res.n_stored);
    *err_mid = osc_max_err(tm, ym, N);
    free(ts);
    free(ys);
    free(tm);
    free(ym);
}

/* ======================================================================== */
/* Closed forms                                                             */
/* ======================================================================== */

/* x and v on a 201-point grid against the closed form, for one method. */
static void check_oscillator(mm_ode_method method, double tol, double h,
                             double atol_x, double atol_v)
{
    ctx c = {0};
    mm_ode_problem prob = osc_problem(&c, OSC_Y0, 10.0);
    mm_ode_options o = opts(method, tol, h);
    double *t = grid(0.0, 10.0, 201), y[2 * 201], y_end[2];
    mm_ode_result res = {0};
    res.t_out = t;
    res.nout = 201;
    res.y_out = y;
    res.y_end = y_end;
    mm_error err;
    assert_int_equal(solve(&prob, &o, &res, &err), MM_OK);
    assert_int_equal(res.nout_done, 201);
    check_abs(res.t_reached, 10.0, 0.0, "run ends exactly at t_end");
    double ex = 0.0, ev = 0.0;
    for (int i = 0; i < 201; i++) {
        double x, v;
        osc_exact(0.5, 0.0, t[i], &x, &v);
        ex = fmax(ex, fabs(y[2 * i] - x));
        ev = fmax(ev, fabs(y[2 * i + 1] - v));
    }
    note("%s oscillator: max error in x %.3g, in v %.3g (%ld steps)",
         mm_ode_method_name(method), ex, ev, res.n_accepted);
    for (int i = 0; i < 201; i++) {
        double x, v;
        osc_exact(0.5, 0.0, t[i], &x, &v);
        check_abs(y[2 * i], x, atol_x, "x against the closed form");
        check_abs(y[2 * i + 1], v, atol_v, "v against the closed form");
    }
    double x, v;
    osc_exact(0.5, 0.0, 10.0, &x, &v);
    check_abs(y_end[0], x, atol_x, "x(t_end) against the closed form");
    free(t);
}

static void dopri5_should_match_the_forced_damped_oscillator(void **state)
{
    (void)state;
    /* rtol = atol = 1e-10: the damped system forgets old errors, so the
     * global error stays near the local tolerance (measured 7e-11 in x);
     * bound 10 tol.  v = x' is ~10x larger (omega ~ 10): 1e-8 (measured
     * 8e-10). */
    check_oscillator(MM_ODE_DOPRI5, 1e-10, 0.0, 1e-9, 1e-8);
}

static void dop853_should_match_the_forced_damped_oscillator(void **state)
{
    (void)state;
    /* Same reasoning; the grid comes from the 7th-order dense output, whose
     * error sits near tol (measured 5e-11 in x, 1.1e-9 in v). */
    check_oscillator(MM_ODE_DOP853, 1e-10, 0.0, 1e-9, 1e-8);
}

static void rk4_should_match_the_forced_damped_oscillator(void **state)
{
    (void)state;
    /* h = 1e-3: RK4's global error C h^4, measured 1.4e-10 in x and 1.5e-9
     * in v (halving h divides it by 16, see the order test); bounds 7x. */
    check_oscillator(MM_ODE_RK4, 1e-6, 1e-3, 1e-9, 1e-8);
}

static void every_method_should_match_exponential_decay(void **state)
{
    (void)state;
    const mm_ode_method methods[] = {MM_ODE_RK4, MM_ODE_DOPRI5, MM_ODE_DOP853};
    for (int m = 0; m < 3; m++) {
        ctx c = {.lambda = 2.0};
        double y0 = 3.0, t_out[4] = {0.0, 0.5, 1.7, 4.0}, y[4], y_end;
        mm_ode_problem prob = {.n = 1, .f = decay_rhs, .params = &c,
                               .t0 = 0.0, .t_end = 4.0, .y0 = &y0};
        /* RK4 at h = 0.01 multiplies by R(-lambda h) per step, whose
         * relative error against e^{-lambda h} is (lambda h)^5 / 120 =
         * 2.7e-11: after 400 steps 1.1e-8.  Adaptive at tol 1e-11: ~1e-10.
         * Bound 2e-8. */
        mm_ode_options o = opts(methods[m], 1e-11, methods[m] == MM_ODE_RK4 ? 0.01 : 0.0);
        mm_ode_result res = {0};
        res.t_out = t_out;
        res.nout = 4;
        res.y_out = y;
        res.y_end = &y_end;
        mm_error err;
        assert_int_equal(solve(&prob, &o, &res, &err), MM_OK);
        note("%s decay: rel error at t = 4: %.3g", mm_ode_method_name(methods[m]),
             fabs(y_end / (3.0 * exp(-8.0)) - 1.0));
        for (int i = 0; i < 4; i++)
            check_rel(y[i], 3.0 * exp(-2.0 * t_out[i]), 2e-8,
                      "decay: relative error under 2e-8 (see above)");
        check_rel(y_end, 3.0 * exp(-8.0), 2e-8, "decay at t_end");
    }
}

static void dop853_should_turn_a_rotation_by_exact_sin_and_cos(void **state)
{
    (void)state;
    ctx c = {.omega = 3.0};
    double y0[2] = {1.0, 0.0}, y[2 * 101];
    double *t = grid(0.0, 20.0, 101);   /* 9.5 turns */
    mm_ode_problem prob = {.n = 2, .f = rot_rhs, .params = &c, .t0 = 0.0,
                           .t_end = 20.0, .y0 = y0};
    mm_ode_options o = opts(MM_ODE_DOP853, 1e-12, 0.0);
    mm_ode_result res = {0};
    res.t_out = t;
    res.nout = 101;
    res.y_out = y;
    mm_error err;
    assert_int_equal(solve(&prob, &o, &res, &err), MM_OK);
    double e = 0.0;
    for (int i = 0; i < 101; i++)
        e = fmax(e, hypot(y[2 * i] - cos(3.0 * t[i]), y[2 * i + 1] - sin(3.0 * t[i])));
    note("dop853 rotation: max error %.3g over %ld steps", e, res.n_accepted);
    for (int i = 0; i < 101; i++) {
        /* Nothing damps a phase error: it grows with t.  Measured 3.4e-12
         * over 345 steps at tol 1e-12; bound 1e-10. */
        check_abs(y[2 * i], cos(3.0 * t[i]), 1e-10, "y1 = cos(omega t)");
        check_abs(y[2 * i + 1], sin(3.0 * t[i]), 1e-10, "y2 = sin(omega t)");
    }
    free(t);
}

/* ======================================================================== */
/* Orders of convergence                                                    */
/* ======================================================================== */

/* Halve h: the error should fall by 2^p, i.e. log2(e(h) / e(h/2)) ~ p.
 * +-0.3 in p allows the O(h) relative weight of the next error term in the
 * asymptotic range chosen for each method. */
static void check_order(mm_ode_method method, double h, double p)
{
    double s1, m1, s2, m2;
    osc_fixed_errors(method, h, 2.0, &s1, &m1);
    osc_fixed_errors(method, h / 2.0, 2.0, &s2, &m2);
    double p_steps = log2(s1 / s2), p_mid = log2(m1 / m2);
    note("%s h = %g: errors %.3g -> %.3g (order %.3f) at steps, %.3g -> %.3g "
         "(order %.3f) between", mm_ode_method_name(method), h, s1, s2, p_steps,
         m1, m2, p_mid);
    check_abs(p_steps, p, 0.3, "order at the step points");
    check_abs(p_mid, p, 0.3, "order of the dense output between steps");
}

static void rk4_should_converge_at_fourth_order(void **state)
{
    (void)state;
    check_order(MM_ODE_RK4, 0.0125, 4.0);     /* errors ~1e-7 .. 1e-8 */
}

static void dopri5_with_fixed_steps_should_converge_at_fifth_order(void **state)
{
    (void)state;
    check_order(MM_ODE_DOPRI5, 0.025, 5.0);   /* errors ~1e-8 .. 1e-9 */
}

static void dop853_with_fixed_steps_should_converge_at_eighth_order(void **state)
{
    (void)state;
    /* h = 0.05 -> 0.025: errors ~1e-10 -> ~4e-13, still 1000x above the
     * round-off floor (~1e-16 per step over 80 steps). */
    check_order(MM_ODE_DOP853, 0.05, 8.0);
}

/* Dense output between steps must not be much worse than the steps. */
static void dense_output_should_be_as_accurate_between_steps_as_at_them(void **state)
{
    (void)state;
    /* Fixed steps: the interpolant's local error O(h^(p+1)) is of the same
     * order as the global error O(h^p).  Measured ratios between/at steps:
     * RK4's cubic Hermite 1.00, DOPRI5's 4th-order extension 0.98, DOP853's
     * 7th-order one 2.6.  Bounds 2, 2 and 5. */
    const struct { mm_ode_method m; double h, bound; } cases[] = {
        {MM_ODE_RK4, 0.0125, 2.0},
        {MM_ODE_DOPRI5, 0.025, 2.0},
        {MM_ODE_DOP853, 0.05, 5.0},
    };
    for (int i = 0; i < 3; i++) {
        double es, em;
        osc_fixed_errors(cases[i].m, cases[i].h, 2.0, &es, &em);
        note("%s fixed h = %g: max error at steps %.3g, between %.3g (ratio %.2f)",
             mm_ode_method_name(cases[i].m), cases[i].h, es, em, em / es);
        assert_true(em <= cases[i].bound * es);
    }

    /* Adaptive runs with a 2001-point plot grid.  DOPRI5: the grid error
     * within 2x of the step-point error (measured equal to 3 digits).
     * DOP853 steps with the error of its 5th-order estimate near tol, while
     * the 8th-order solution it propagates is far more accurate (local
     * extrapolation); its 7th-order interpolant errs about as much as the
     * estimate, so the grid error sits near tol (measured 0.6 tol at 1e-7,
     * 1.1 tol at 1e-10) and above the step-point error.  Bound: 3 tol
     * (|x| < 1 here, so rtol and atol weigh alike). */
    const struct { mm_ode_method m; double tol; } runs[] = {
        {MM_ODE_DOPRI5, 1e-7}, {MM_ODE_DOP853, 1e-7}, {MM_ODE_DOP853, 1e-10},
    };
    for (int r = 0; r < 3; r++) {
        ctx c = {0};
        mm_ode_problem prob = osc_problem(&c, OSC_Y0, 10.0);
        mm_ode_options o = opts(runs[r].m, runs[r].tol, 0.0);
        double *t = grid(0.0, 10.0, 2001), *y = malloc(2 * 2001 * sizeof *y);
        double *ts = malloc(5000 * sizeof *ts), *ys = malloc(2 * 5000 * sizeof *ys);
        assert_true(y && ts && ys);
        mm_ode_result res = {0};
        res.t_out = t;
        res.nout = 2001;
        res.y_out = y;
        res.t_steps = ts;
        res.y_steps = ys;
        res.steps_cap = 5000;
        mm_error err;
        assert_int_equal(solve(&prob, &o, &res, &err), MM_OK);
        double es = osc_max_err(ts, ys, res.n_stored), eg = osc_max_err(t, y, 2001);
        note("%s adaptive tol %g: max error at steps %.3g, on the grid %.3g",
             mm_ode_method_name(runs[r].m), runs[r].tol, es, eg);
        if (runs[r].m == MM_ODE_DOPRI5)
            assert_true(eg <= 2.0 * es);
        else
            assert_true(eg <= 3.0 * runs[r].tol);
        free(t);
        free(y);
        free(ts);
        free(ys);
    }
}

/* ======================================================================== */
/* Long runs and stiffness                                                  */
/* ======================================================================== */

/* Undamped resonance x'' + x = cos t from rest: x = t sin(t) / 2, an
 * amplitude growing without bound, over 160 periods. */
static void adaptive_methods_should_follow_undamped_resonance_over_160_periods(void **state)
{
    (void)state;
    const mm_ode_method methods[] = {MM_ODE_DOPRI5, MM_ODE_DOP853};
    const double T = 320.0 * M_PI;
    for (int m = 0; m < 2; m++) {
        ctx c = {0};
        double y0[2] = {0.0, 0.0}, *t = grid(0.0, T, 1601);
        double *y = malloc(2 * 1601 * sizeof *y);
        assert_non_null(y);
        mm_ode_problem prob = {.n = 2, .f = res_rhs, .params = &c, .t0 = 0.0,
                               .t_end = T, .y0 = y0};
        mm_ode_options o = opts(methods[m], 1e-10, 0.0);
        mm_ode_result res = {0};
        res.t_out = t;
        res.nout = 1601;
        res.y_out = y;
        mm_error err;
        assert_int_equal(solve(&prob, &o, &res, &err), MM_OK);
        double emax = 0.0;
        for (int i = 0; i < 1601; i++)
            emax = fmax(emax, fabs(y[2 * i] - 0.5 * t[i] * sin(t[i])));
        note("%s resonance: max error %.3g (amplitude %.0f), %ld steps",
             mm_ode_method_name(methods[m]), emax, 0.5 * T, res.n_accepted);
        /* Nothing damps the errors: local errors of relative size 1e-10 on
         * an amplitude growing to 500 pile up over 4e3 (DOP853) to 3e4
         * (DOPRI5) steps; the pessimistic sum 500 * 1e-10 * 3e4 = 1.5e-3
         * is far above what happens (measured 2.2e-6 and 6e-7: the errors
         * partly cancel).  Bound 2e-5, 10x the worst measured and 4e-8 of
         * the amplitude. */
        check_abs(emax, 0.0, 2e-5, "resonance: max error over 160 periods");
        free(t);
        free(y);
    }
}

/* RK4 on x'' = -omega^2 x multiplies (x, v/omega) each step by the
 * stability function R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24 at z = i omega h.
 * With s = omega h:
 *   |R(is)|^2 = (1 - s^2/2 + s^4/24)^2 + (s - s^3/6)^2 = 1 - s^6/72 + s^8/576,
 * so the energy E = (v^2 + omega^2 x^2)/2 shrinks by exactly that factor per
 * step: a relative loss s^6/72 (the amplitude |R| loses s^6/144, half as
 * much; s^6/144 per step is the amplitude rule, not the energy rule).  At
 * 20 steps per period s = pi/10: loss 1.3188e-5 per step, and over 1e5
 * periods (2e6 steps) E falls to exp(-26.4) ~ 3.5e-12 of its start. */
static void rk4_should_lose_energy_by_its_amplification_factor_over_1e5_periods(void **state)
{
    (void)state;
    const double omega = 1.0, period = 2.0 * M_PI / omega;
    const long steps_per_period = 20, periods = 100000;
    const long N = steps_per_period * periods;
    const double h = period / (double)steps_per_period, s = omega * h;
    const double g = 1.0 - pow(s, 6) / 72.0 + pow(s, 8) / 576.0;

    ctx c = {.omega = omega};
    double y0[2] = {1.0, 0.0};
    enum { NCHECK = 11 };
    double t_out[NCHECK], y[2 * NCHECK];
    for (int i = 0; i < NCHECK; i++)    /* every 1e4 periods, on step points */
        t_out[i] = (double)i * (double)(periods / 10) * period;
    mm_ode_problem prob = {.n = 2, .f = free_rhs, .params = &c, .t0 = 0.0,
                           .t_end = (double)periods * period, .y0 = y0};
    t_out[NCHECK - 1] = prob.t_end;
    mm_ode_options o = opts(MM_ODE_RK4, 1e-6, h);
    o.max_steps = N;
    mm_ode_result res = {0};
    res.t_out = t_out;
    res.nout = NCHECK;
    res.y_out = y;
    mm_error err;
    assert_int_equal(solve(&prob, &o, &res, &err), MM_OK);
    assert_int_equal(res.n_accepted, N);

    double E0 = 0.5;
    for (int i = 1; i < NCHECK; i++) {
        double E = 0.5 * (y[2 * i + 1] * y[2 * i + 1] + omega * omega * y[2 * i] * y[2 * i]);
        double Eprev = 0.5 * (y[2 * i - 1] * y[2 * i - 1] + omega * omega * y[2 * i - 2] * y[2 * i - 2]);
        assert_true(E < Eprev);                      /* it only ever drains */
        double n_steps = (double)i * (double)(N / 10);
        /* log E/E0 = n log g exactly, but for round-off (~1e-16 per step,
         * relative 1e-9 of a log of order 1..26 is far above it) and the
         * grid points sitting on steps up to ~1e-9 in t (period * 1e5). */
        check_rel(log(E / E0), n_steps * log(g), 1e-6,
                  "energy follows |R(i omega h)|^2 per step");
    }
    /* The per-step loss is s^6/72 (to the s^8 term, 1.2 % here), twice the
     * amplitude rule s^6/144. */
    double E_end = 0.5 * (y[2 * NCHECK - 1] * y[2 * NCHECK - 1] + y[2 * NCHECK - 2] * y[2 * NCHECK - 2]);
    double loss = -log(E_end / E0) / (double)N;
    note("rk4 energy: E_end/E0 = %.4g, predicted g^N = %.4g; loss per step "
         "%.6g, s^6/72 = %.6g, s^6/144 = %.6g", E_end / E0, pow(g, (double)N),
         loss, pow(s, 6) / 72.0, pow(s, 6) / 144.0);
    check_rel(loss, pow(s, 6) / 72.0, 0.02, "loss per step is (omega h)^6 / 72");
    check_rel(E_end / E0, 3.5e-12, 0.05, "RK4 loses all of it over 1e5 periods");
}

/* y' = -1e6 (y - cos t): the solution is smooth (it hugs cos t) but an
 * explicit method must keep h |lambda| inside its stability region
 * (~3.3 for DOPRI5, ~6 for DOP853), so h ~ 3e-6: 3e5 steps per unit time. */
static void explicit_methods_should_stop_cleanly_on_a_stiff_problem(void **state)
{
    (void)state;
    const mm_ode_method methods[] = {MM_ODE_DOPRI5, MM_ODE_DOP853};
    for (int m = 0; m < 2; m++) {
        ctx c = {.lambda = 1e6};
        double y0 = 1.0, y_end;
        mm_ode_problem prob = {.n = 1, .f = stiff_rhs, .params = &c,
                               .t0 = 0.0, .t_end = 1.0, .y0 = &y0};
        mm_ode_options o = opts(methods[m], 1e-6, 0.0);
        o.max_steps = 100000;
        mm_ode_result res = {0};
        res.y_end = &y_end;
        mm_error err;
        int rc = solve(&prob, &o, &res, &err);
        note("%s stiff: rc %d, t_reached %.4g, %ld accepted, %ld rejected: %s",
             mm_ode_method_name(methods[m]), rc, res.t_reached, res.n_accepted,
             res.n_rejected, err.msg);
        assert_int_equal(rc, MM_ENOCONV);
        assert_int_equal(err.code, MM_ENOCONV);
        assert_string_equal(err.param, "max_steps");
        assert_non_null(strstr(err.msg, "stopped after 100000 steps at t = "));
        assert_non_null(strstr(err.msg, "stiff"));
        assert_int_equal(res.n_accepted + res.n_rejected, 100000);
        assert_true(res.stiff);                       /* Hairer's test fired */
        assert_true(res.t_reached > 0.0 && res.t_reached < 1.0);
        /* What was computed is right: tol 1e-6 on a contracting problem. */
        check_abs(y_end, stiff_exact(1e6, 1.0, res.t_reached), 1e-5,
                  "state at t_reached is still accurate");
    }
}

static void explicit_methods_should_solve_a_short_stiff_interval(void **state)
{
    (void)state;
    const mm_ode_method methods[] = {MM_ODE_DOPRI5, MM_ODE_DOP853};
    for (int m = 0; m < 2; m++) {
        ctx c = {.lambda = 1e6};
        double y0 = 1.0, y_end;
        /* t in [0, 0.01]: ~3000 stability-limited steps, within max_steps */
        mm_ode_problem prob = {.n = 1, .f = stiff_rhs, .params = &c,
                               .t0 = 0.0, .t_end = 0.01, .y0 = &y0};
        mm_ode_options o = opts(methods[m], 1e-8, 0.0);
        mm_ode_result res = {0};
        res.y_end = &y_end;
        mm_error err;
        assert_int_equal(solve(&prob, &o, &res, &err), MM_OK);
        /* The step is held by stability, not accuracy: the error sits far
         * below the tolerance; 1e-7 relative is safe. */
        check_rel(y_end, stiff_exact(1e6, 1.0, 0.01), 1e-7, "stiff y(0.01)");
    }
}

/* ======================================================================== */
/* Outputs and counters                                                     */
/* ======================================================================== */

static void every_accepted_step_should_be_recorded(void **state)
{
    (void)state;
    ctx c = {0};
    mm_ode_problem prob = osc_problem(&c, OSC_Y0, 10.0);
    mm_ode_options o = opts(MM_ODE_DOP853, 1e-9, 0.0);
    double ts[1000], ys[2000], y_end[2];
    mm_ode_result res = {0};
    res.t_steps = ts;
    res.y_steps = ys;
    res.steps_cap = 1000;
    res.y_end = y_end;
    mm_error err;
    assert_int_equal(solve(&prob, &o, &res, &err), MM_OK);
    assert_int_equal(res.n_stored, (size_t)res.n_accepted + 1);   /* + t0 */
    check_abs(ts[0], 0.0, 0.0, "first record is t0");
    check_abs(ys[0], 0.5, 0.0, "first record is y0");
    check_abs(ts[res.n_stored - 1], 10.0, 0.0, "last record is t_end");
    check_abs(ys[2 * (res.n_stored - 1)], y_end[0], 0.0, "last record is y_end");
    for (size_t i = 1; i < res.n_stored; i++) {
        double hs = ts[i] - ts[i - 1];
        assert_true(hs > 0.0);
        assert_true(hs >= res.h_smallest * (1 - 1e-12) && hs <= res.h_largest * (1 + 1e-12));
    }
    /* tol 1e-9 on the damped oscillator: measured 2e-10; bound 1e-8 */
    note("dop853 recorded steps: max error %.3g", osc_max_err(ts, ys, res.n_stored));
    assert_true(osc_max_err(ts, ys, res.n_stored) < 1e-8);
}

static void grid_points_at_both_ends_should_be_the_states_there(void **state)
{
    (void)state;
    ctx c = {0};
    mm_ode_problem prob = osc_problem(&c, OSC_Y0, 3.0);
    mm_ode_options o = opts(MM_ODE_DOPRI5, 1e-8, 0.0);
    double t_out[4] = {0.0, 0.0, 1.5, 3.0}, y[8], y_end[2];
    mm_ode_result res = {0};
    res.t_out = t_out;
    res.nout = 4;
    res.y_out = y;
    res.y_end = y_end;
    mm_error err;
    assert_int_equal(solve(&prob, &o, &res, &err), MM_OK);
    for (int i = 0; i < 2; i++) {                     /* repeated t0: y0 itself */
        check_abs(y[2 * i], 0.5, 0.0, "y_out at t0 is y0 exactly");
        check_abs(y[2 * i + 1], 0.0, 0.0, "y_out at t0 is y0 exactly");
    }
    /* theta = 1 reproduces y_new up to rounding in the nested form */
    check_rel(y[6], y_end[0], 1e-14, "y_out at t_end is y_end");
    check_rel(y[7], y_end[1], 1e-14, "y_out at t_end is y_end");
}

/* t + h of the last step can round to a neighbour of t_end; a grid point
 * at t_end must be filled all the same, for any t_end and method. */
static void a_grid_point_at_t_end_should_always_be_filled(void **state)
{
    (void)state;
    for (int m = 0; m < 3; m++) {
        for (int k = 1; k <= 60; k++) {
            ctx c = {0};
            double t_end = 0.1 * k + 1e-3 * k * k;   /* awkward binary values */
            double t_out[2] = {t_end / 3.0, t_end}, y[4], y_end[2];
            mm_ode_problem prob = osc_problem(&c, OSC_Y0, t_end);
            mm_ode_options o = opts((mm_ode_method)m, 1e-6, m == MM_ODE_RK4 ? 0.03 : 0.0);
            mm_ode_result res = {0};
            res.t_out = t_out;
            res.nout = 2;
            res.y_out = y;
            res.y_end = y_end;
            mm_error err;
            assert_int_equal(solve(&prob, &o, &res, &err), MM_OK);
            assert_int_equal(res.nout_done, 2);
            check_rel(y[2], y_end[0], 1e-14, "grid row at t_end is y_end");
        }
        /* one step from t0 = 0.5933... to 7.1459...: in doubles
         * t0 + (t_end - t0) falls one ulp short of t_end */
        ctx c = {0};
        double t0 = 0.5933612204694776, t_end = 7.145930561667314;
        assert_true(t0 + (t_end - t0) < t_end);
        double t_out[1] = {t_end}, y[2], y_end[2];
        mm_ode_problem prob = osc_problem(&c, OSC_Y0, t_end);
        prob.t0 = t0;
        mm_ode_options o = opts((mm_ode_method)m, 1.0, 10.0);   /* h > interval */
        mm_ode_result res = {0};
        res.t_out = t_out;
        res.nout = 1;
        res.y_out = y;
        res.y_end = y_end;
        mm_error err;
        assert_int_equal(solve(&prob, &o, &res, &err), MM_OK);
        assert_int_equal(res.n_accepted, 1);
        assert_int_equal(res.nout_done, 1);
        check_rel(y[0], y_end[0], 1e-14, "grid row at t_end after one step");
    }
}

/* n_eval counts every call (checked against the callback's own count), and
 * follows from the tableaux: RK4 4 per step + 1 (f at t0; its 5th, FSAL,
 * call gives the next step's first); DOPRI5 6 per attempt + 2 (f at t0,
 * HINIT); DOP853 11 per attempt + 1 per accepted step (FSAL) + 3 per step
 * that fills grid points + 2; the adaptive methods one attempt more for
 * each half step that checked a trial of the first step (at least one,
 * and only before the first accepted step). */
static void evaluation_counts_should_follow_from_the_tableaux(void **state)
{
    (void)state;
    double *t = grid(0.0, 10.0, 50), y[100];
    for (int m = 0; m < 3; m++) {
        for (int with_grid = 0; with_grid < 2; with_grid++) {
            ctx c = {0};
            mm_ode_problem prob = osc_problem(&c, OSC_Y0, 10.0);
            mm_ode_options o = opts((mm_ode_method)m, 1e-7, m == MM_ODE_RK4 ? 0.01 : 0.0);
            mm_ode_result res = {0};
            if (with_grid) {
                res.t_out = t;
                res.nout = 50;
                res.y_out = y;
            }
            mm_error err;
            assert_int_equal(solve(&prob, &o, &res, &err), MM_OK);
            assert_int_equal(res.n_eval, c.calls);
            long halves = res.n_first_halves;
            assert_true(m == MM_ODE_RK4 ? halves == 0 : halves >= 1 && halves <= res.n_rejected + 1);
            long attempts = res.n_accepted + res.n_rejected + halves;
            if (m == MM_ODE_RK4) {
                assert_int_equal(res.n_accepted, 1000);
                assert_int_equal(res.n_eval, 4 * 1000 + 1);
            } else if (m == MM_ODE_DOPRI5) {
                assert_int_equal(res.n_eval, 6 * attempts + 2);
            } else {
                long dense = c.calls - (11 * attempts + res.n_accepted + 2);
                assert_int_equal(dense % 3, 0);
                /* 49 grid points after t0 lie in at most 49 distinct steps */
                assert_true(with_grid ? (dense > 0 && dense <= 3 * 49) : dense == 0);
            }
        }
    }
    free(t);
}

/* The summed local estimates err_sum bound the achieved error on this
 * damped problem (the estimates are of the lower-order partner). */
static void error_estimate_should_bound_the_achieved_error(void **state)
{
    (void)state;
    for (int m = 0; m < 3; m++) {
        ctx c = {0};
        mm_ode_problem prob = osc_problem(&c, OSC_Y0, 10.0);
        mm_ode_options o = opts((mm_ode_method)m, 1e-6, m == MM_ODE_RK4 ? 0.01 : 0.0);
        double ts[5000], ys[10000];
        mm_ode_result res = {0};
        res.t_steps = ts;
        res.y_steps = ys;
        res.steps_cap = 5000;
        mm_error err;
        assert_int_equal(solve(&prob, &o, &res, &err), MM_OK);
        double e = osc_max_err(ts, ys, res.n_stored);
        assert_true(res.err_local_max > 0.0);
        assert_true(res.err_local_max <= res.err_sum);
        assert_true(e <= res.err_sum);
    }
}

/* A mass driven by a harmonic force, v' = cos(omega t) (unit force per
 * mass), from v(t0) = 1: v = 1 + (sin omega t - sin omega t0) / omega.  f
 * does not depend on v, so a step's local error is exactly the error of
 * its increment, v_i - v_(i-1) against the closed form's. */
static int driven_rhs(double t, const double *y, double *dydt, void *params)
{
    ctx *c = params;
    (void)y;
    c->calls++;
    dydt[0] = cos(c->omega * t);
    return 0;
}

/* The first step of an adaptive run has no earlier estimate behind it:
 * the solver's guess (HINIT) sizes it from f and f' alone, and here it
 * guesses 1.9 rad of the forcing (DOP853 at omega = 80 rad/s, tol 1e-10;
 * DOPRI5 at 400 rad/s, 1e-8), outside the range where the error estimate
 * grows like h^8 or h^5.  There the estimate, a polynomial in h, can pass
 * through zero: at the phases omega t0 below it does (DOP853 3e-4 of the
 * tolerance, DOPRI5 1e-3), while the step errs 13.7 and 7.8 times the
 * tolerance.  The estimate at half the step gives it away (0.62 both,
 * larger than at the whole step).  Every accepted step, the first too,
 * must keep its local error within the tolerance it was accepted at
 * (atol + rtol |v|; the estimates, of the lower-order partner, are
 * cautious for the solution propagated). */
static void first_step_should_not_pass_where_its_error_estimate_is_zero(void **state)
{
    (void)state;
    const struct {
        mm_ode_method method;
        double omega, tol, phase;   /* phase = omega t0: at the estimate's zero */
    } cases[] = {{MM_ODE_DOP853, 80.0, 1e-10, 2.157}, {MM_ODE_DOPRI5, 400.0, 1e-8, 0.416}};
    for (int k = 0; k < 2; k++) {
        ctx c = {.omega = cases[k].omega};
        double t0 = cases[k].phase / c.omega, y0 = 1.0, ts[2000], ys[2000];
        mm_ode_problem prob = {.n = 1, .f = driven_rhs, .params = &c, .t0 = t0,
                               .t_end = t0 + 20.0 / c.omega, .y0 = &y0};
        mm_ode_options o = opts(cases[k].method, cases[k].tol, 0.0);
        mm_ode_result res = {0};
        res.t_steps = ts;
        res.y_steps = ys;
        res.steps_cap = 2000;
        mm_error err;
        assert_int_equal(solve(&prob, &o, &res, &err), MM_OK);
        double worst = 0.0, first = 0.0;
        for (size_t i = 1; i < res.n_stored; i++) {
            double exact = (sin(c.omega * ts[i]) - sin(c.omega * ts[i - 1])) / c.omega;
            double e = fabs((ys[i] - ys[i - 1]) - exact);
            double tol = o.atol + o.rtol * fmax(fabs(ys[i]), fabs(ys[i - 1]));
            worst = fmax(worst, e / tol);
            if (i == 1)
                first = e / tol;
        }
        note("%s at omega t0 = %g: first step %.3g s, error/tolerance %.3g there, "
             "%.3g at worst over %ld steps (%ld trials of the first)",
             mm_ode_method_name(cases[k].method), cases[k].phase, ts[1] - ts[0], first, worst,
             res.n_accepted, res.n_first_halves);
        assert_true(worst <= 1.0);
    }
}

/* ======================================================================== */
/* Error paths                                                              */
/* ======================================================================== */

static void adaptive_run_should_stop_at_max_steps_with_a_clear_message(void **state)
{
    (void)state;
    ctx c = {0};
    mm_ode_problem prob = osc_problem(&c, OSC_Y0, 10.0);
    mm_ode_options o = opts(MM_ODE_DOPRI5, 1e-8, 0.0);
    o.max_steps = 10;
    double *t = grid(0.0, 10.0, 101), y[202], y_end[2];
    mm_ode_result res = {0};
    res.t_out = t;
    res.nout = 101;
    res.y_out = y;
    res.y_end = y_end;
    mm_error err;
    assert_int_equal(solve(&prob, &o, &res, &err), MM_ENOCONV);
    assert_string_equal(err.param, "max_steps");
    assert_non_null(strstr(err.msg, "stopped after 10 steps at t = "));
    assert_non_null(strstr(err.msg, "raise the tolerance"));
    assert_int_equal(res.n_accepted + res.n_rejected, 10);
    assert_true(res.t_reached > 0.0 && res.t_reached < 10.0);
    /* The partial results are valid: grid rows up to t_reached and the
     * state there (tol 1e-8 -> errors ~1e-9). */
    assert_true(res.nout_done >= 1 && res.nout_done < 101);
    assert_true(t[res.nout_done - 1] <= res.t_reached);
    for (size_t i = 0; i < res.nout_done; i++)
        check_abs(y[2 * i], osc_x(t[i]), 1e-7, "grid rows before the stop");
    check_abs(y_end[0], osc_x(res.t_reached), 1e-7, "state at t_reached");
    free(t);
}

/* One bad field at a time: mm_ode_check names it, with the right code. */
static void check_should_reject_each_bad_argument_naming_the_field(void **state)
{
    (void)state;
    ctx c = {0};
    double y0[2] = {0.5, 0.0}, y0_nan[2] = {0.5, NAN};
    double t_out[3] = {0.0, 1.0, 2.0}, t_back[3] = {0.0, 2.0, 1.0};
    double t_far[2] = {0.0, 11.0}, t_inf[2] = {0.0, INFINITY}, yo[6];
    enum { N_CASES = 23 };
    struct {
        const char *field;
        int code;
        const char *needle;   /* part of the message */
    } want[N_CASES] = {
        {"n", MM_ERANGE, "1 to 1024 equations, got 0"},
        {"n", MM_ERANGE, "got 1025"},
        {"t0", MM_EVALUE, "finite"},
        {"t_end", MM_EVALUE, "finite"},
        {"t_end", MM_ERANGE, "greater than the start time"},
        {"t_end", MM_ERANGE, "greater than the start time"},
        {"y0", MM_EVALUE, "y0[1]"},
        {"method", MM_ERANGE, "unknown method"},
        {"rtol", MM_ERANGE, "between 1e-14 and 1, got 0"},
        {"rtol", MM_ERANGE, "got 2"},
        {"rtol", MM_EVALUE, "finite"},
        {"atol", MM_ERANGE, "> 0 (use a tiny value"},
        {"h", MM_ERANGE, "rk4 takes fixed steps"},
        {"h", MM_ERANGE, ">= 0"},
        {"h_init", MM_ERANGE, ">= 0"},
        {"h_max", MM_EVALUE, "finite"},
        {"max_steps", MM_ERANGE, "between 1 and 10000000, got 0"},
        {"max_steps", MM_ERANGE, "got 20000000"},
        {"h", MM_ERANGE, "more than max_steps = 100000"},
        {"t_out", MM_ERANGE, "increasing order"},
        {"t_out", MM_ERANGE, "outside the interval"},
        {"t_out", MM_EVALUE, "finite"},
        {"h", MM_ERANGE, "too small to advance t"},
    };
    for (int k = 0; k < N_CASES; k++) {
        mm_ode_problem prob = osc_problem(&c, y0, 10.0);
        mm_ode_options o = opts(MM_ODE_DOPRI5, 1e-6, 0.0);
        mm_ode_result res = {0};
        switch (k) {
        case 0: prob.n = 0; break;
        case 1: prob.n = MM_ODE_MAX_DIM + 1; break;
        case 2: prob.t0 = NAN; break;
        case 3: prob.t_end = INFINITY; break;
        case 4: prob.t_end = 0.0; break;
        case 5: prob.t_end = -1.0; break;
        case 6: prob.y0 = y0_nan; break;
        case 7: o.method = (mm_ode_method)7; break;
        case 8: o.rtol = 0.0; break;
        case 9: o.rtol = 2.0; break;
        case 10: o.rtol = NAN; break;
        case 11: o.atol = 0.0; break;
        case 12: o.method = MM_ODE_RK4; o.h = 0.0; break;
        case 13: o.h = -0.1; break;
        case 14: o.h_init = -1e-3; break;
        case 15: o.h_max = NAN; break;
        case 16: o.max_steps = 0; break;
        case 17: o.max_steps = 20000000; break;
        case 18: o.method = MM_ODE_RK4; o.h = 1e-5; break;   /* 1e6 steps */
        case 19: res.t_out = t_back; res.nout = 3; res.y_out = yo; break;
        case 20: res.t_out = t_far; res.nout = 2; res.y_out = yo; break;
        case 21: res.t_out = t_inf; res.nout = 2; res.y_out = yo; break;
        case 22:                 /* 1e-7 s steps at t = 1e9 s: below 1 ulp */
            prob.t0 = 1e9; prob.t_end = 1e9 + 1e-6;
            o.method = MM_ODE_RK4; o.h = 1e-7;
            break;
        }
        mm_error err;
        mm_error_clear(&err);
        int rc = mm_ode_check(&prob, &o, &res, &err);
        if (rc != want[k].code || strcmp(err.param, want[k].field) != 0 ||
            !strstr(err.msg, want[k].needle)) {
            print_error("case %d: got code %d param '%s' msg '%s'\n", k, rc,
                        err.param, err.msg);
            fail();
        }
        assert_int_equal(err.code, rc);
        /* mm_ode_solve refuses the same way, before calling f */
        long calls = c.calls;
        mm_error err2;
        assert_int_equal(mm_ode_solve(&prob, &o, NULL, &res, &err2), rc);
        assert_string_equal(err2.param, want[k].field);
        assert_int_equal(c.calls, calls);
    }
    /* and a good request passes, leaving the result untouched */
    mm_ode_problem prob = osc_problem(&c, y0, 10.0);
    mm_ode_options o = opts(MM_ODE_DOPRI5, 1e-6, 0.0);
    mm_ode_result res = {0}, before;
    res.t_out = t_out;
    res.nout = 3;
    res.y_out = yo;
    memcpy(&before, &res, sizeof res);
    mm_error err;
    assert_int_equal(mm_ode_check(&prob, &o, &res, &err), MM_OK);
    assert_memory_equal(&before, &res, sizeof res);
    assert_int_equal(c.calls, 0);
}

static void solve_should_report_enomem_for_a_missing_workspace(void **state)
{
    (void)state;
    ctx c = {0};
    mm_ode_problem prob = osc_problem(&c, OSC_Y0, 1.0);
    mm_ode_options o = opts(MM_ODE_DOPRI5, 1e-6, 0.0);
    mm_ode_result res = {0};
    mm_error err;
    assert_int_equal(mm_ode_solve(&prob, &o, NULL, &res, &err), MM_ENOMEM);
    assert_int_equal(err.code, MM_ENOMEM);
    assert_int_equal(c.calls, 0);
}

static void work_alloc_should_refuse_bad_sizes_and_free_null(void **state)
{
    (void)state;
    assert_null(mm_ode_work_alloc(0));
    assert_null(mm_ode_work_alloc(MM_ODE_MAX_DIM + 1));
    mm_ode_work *w = mm_ode_work_alloc(MM_ODE_MAX_DIM);
    assert_non_null(w);
    mm_ode_work_free(w);
    mm_ode_work_free(NULL);
    /* a workspace for 5 equations serves a system of 2 */
    ctx c = {0};
    mm_ode_problem prob = osc_problem(&c, OSC_Y0, 1.0);
    mm_ode_options o = opts(MM_ODE_DOPRI5, 1e-8, 0.0);
    mm_ode_result res = {0};
    double y_end[2];
    res.y_end = y_end;
    w = mm_ode_work_alloc(5);
    assert_int_equal(mm_ode_solve(&prob, &o, w, &res, NULL), MM_OK);
    mm_ode_work_free(w);
    check_abs(y_end[0], osc_x(1.0), 1e-7, "solve with a larger workspace");
}

static void options_init_should_fill_the_documented_defaults(void **state)
{
    (void)state;
    mm_ode_options o;
    memset(&o, 0xff, sizeof o);
    mm_ode_options_init(&o);
    assert_int_equal(o.method, MM_ODE_DOPRI5);
    check_abs(o.rtol, 1e-6, 0.0, "default rtol");
    check_abs(o.atol, 1e-9, 0.0, "default atol");
    check_abs(o.h, 0.0, 0.0, "default h: adaptive");
    check_abs(o.h_init, 0.0, 0.0, "default h_init: automatic");
    check_abs(o.h_max, 0.0, 0.0, "default h_max: none");
    assert_int_equal(o.max_steps, 100000);
    assert_int_equal(o.pi_control, 1);
    assert_string_equal(mm_ode_method_name(MM_ODE_RK4), "rk4");
    assert_string_equal(mm_ode_method_name(MM_ODE_DOPRI5), "dopri5");
    assert_string_equal(mm_ode_method_name(MM_ODE_DOP853), "dop853");
    assert_string_equal(mm_ode_method_name((mm_ode_method)9), "unknown");
}

static void solve_should_stop_when_the_callback_returns_nonzero(void **state)
{
    (void)state;
    for (int m = 0; m < 3; m++) {
        /* an mm_status code passes through; any other value is internal */
        const int codes[2] = {MM_ERANGE, 42};
        for (int k = 0; k < 2; k++) {
            ctx c = {.t_stop = 0.5, .stop_code = codes[k]};
            mm_ode_problem prob = osc_problem(&c, OSC_Y0, 2.0);
            prob.f = misbehaving_rhs;
            /* RK4 at h = 0.002: error ~1e-8 on this transient */
            mm_ode_options o = opts((mm_ode_method)m, 1e-8, m == MM_ODE_RK4 ? 0.002 : 0.0);
            double y_end[2];
            mm_ode_result res = {0};
            res.y_end = y_end;
            mm_error err;
            int rc = solve(&prob, &o, &res, &err);
            assert_int_equal(rc, k == 0 ? MM_ERANGE : MM_EINTERNAL);
            assert_string_equal(err.param, "f");
            assert_non_null(strstr(err.msg, "right-hand side stopped"));
            assert_true(res.t_reached <= 0.5 + 1e-12);
            assert_int_equal(res.n_eval, c.calls);
            check_abs(y_end[0], osc_x(res.t_reached), 1e-6, "state at t_reached");
        }
    }
}

static void adaptive_run_should_report_nonfinite_when_f_gives_nan(void **state)
{
    (void)state;
    for (int m = 1; m < 3; m++) {
        ctx c = {.t_stop = 0.5, .stop_code = 0};      /* NaN after t = 0.5 */
        mm_ode_problem prob = osc_problem(&c, OSC_Y0, 2.0);
        prob.f = misbehaving_rhs;
        mm_ode_options o = opts((mm_ode_method)m, 1e-8, 0.0);
        mm_ode_result res = {0};
        mm_error err;
        assert_int_equal(solve(&prob, &o, &res, &err), MM_ENONFINITE);
        assert_string_equal(err.param, "y");
        assert_true(res.t_reached <= 0.5 + 1e-12 && res.t_reached > 0.4);
        assert_true(res.n_rejected > 0);
    }
    /* NaN from the very first call: refused before any step */
    ctx c = {.t_stop = -1.0, .stop_code = 0};
    mm_ode_problem prob = osc_problem(&c, OSC_Y0, 2.0);
    prob.f = misbehaving_rhs;
    mm_ode_options o = opts(MM_ODE_DOPRI5, 1e-8, 0.0);
    mm_ode_result res = {0};
    mm_error err;
    assert_int_equal(solve(&prob, &o, &res, &err), MM_ENONFINITE);
    assert_string_equal(err.param, "f");
    assert_int_equal(res.n_accepted + res.n_rejected, 0);
}

static void fixed_step_beyond_the_stability_limit_should_report_nonfinite(void **state)
{
    (void)state;
    /* RK4 on y' = -1000 y with h = 0.01: |R(-10)| = |1 - 10 + 50 - 166.7
     * + 416.7| = 291 per step, overflowing after ~125 steps. */
    ctx c = {.lambda = 1000.0};
    double y0 = 1.0;
    mm_ode_problem prob = {.n = 1, .f = decay_rhs, .params = &c, .t0 = 0.0,
                           .t_end = 10.0, .y0 = &y0};
    mm_ode_options o = opts(MM_ODE_RK4, 1e-6, 0.01);
    mm_ode_result res = {0};
    mm_error err;
    assert_int_equal(solve(&prob, &o, &res, &err), MM_ENONFINITE);
    assert_string_equal(err.param, "h");
    assert_non_null(strstr(err.msg, "too large for"));
    assert_true(res.n_accepted > 100 && res.n_accepted < 140);
}

static void blow_up_should_end_with_an_error_not_a_hang(void **state)
{
    (void)state;
    for (int m = 1; m < 3; m++) {
        ctx c = {0};
        double y0 = 1.0, y_end;
        mm_ode_problem prob = {.n = 1, .f = blowup_rhs, .params = &c,
                               .t0 = 0.0, .t_end = 2.0, .y0 = &y0};
        mm_ode_options o = opts((mm_ode_method)m, 1e-8, 0.0);
        mm_ode_result res = {0};
        res.y_end = &y_end;
        mm_error err;
        int rc = solve(&prob, &o, &res, &err);
        note("%s blow-up: rc %d at t = %.17g, y = %.3g: %s",
             mm_ode_method_name((mm_ode_method)m), rc, res.t_reached, y_end, err.msg);
        /* the steps shrink toward t = 1 until double precision (ENOCONV)
         * or an overflow (ENONFINITE) ends the run */
        assert_true(rc == MM_ENOCONV || rc == MM_ENONFINITE);
        assert_string_equal(err.param, rc == MM_ENOCONV ? "rtol" : "y");
        /* the numerical pole sits within the tolerance of the true one:
         * a relative error 1e-8 in y moves it by ~1e-8 in t */
        check_abs(res.t_reached, 1.0, 1e-6, "stopped at the pole t = 1");
        assert_true(isfinite(y_end) && y_end > 1e10);
    }
}

static void step_record_should_report_when_it_is_full(void **state)
{
    (void)state;
    ctx c = {0};
    mm_ode_problem prob = osc_problem(&c, OSC_Y0, 10.0);
    mm_ode_options o = opts(MM_ODE_DOPRI5, 1e-8, 0.0);
    double ts[20], ys[40];
    mm_ode_result res = {0};
    res.t_steps = ts;
    res.y_steps = ys;
    res.steps_cap = 20;
    mm_error err;
    assert_int_equal(solve(&prob, &o, &res, &err), MM_ETOOBIG);
    assert_string_equal(err.param, "steps");
    assert_int_equal(res.n_stored, 20);
    check_abs(ts[19], res.t_reached, 0.0, "the last record is the last state");
}

/* ======================================================================== */
/* Threads                                                                  */
/* ======================================================================== */

typedef struct job {
    mm_ode_method method;
    double y[2 * 64];
    int rc;
} job;

static void *run_job(void *arg)
{
    job *j = arg;
    ctx c = {0};
    mm_ode_problem prob = osc_problem(&c, OSC_Y0, 10.0);
    mm_ode_options o = opts(j->method, 1e-9, j->method == MM_ODE_RK4 ? 0.001 : 0.0);
    double t[64];
    for (int i = 0; i < 64; i++)
        t[i] = 10.0 * i / 63.0;
    mm_ode_result res = {0};
    res.t_out = t;
    res.nout = 64;
    res.y_out = j->y;
    mm_ode_work *w = mm_ode_work_alloc(2);
    j->rc = w ? mm_ode_solve(&prob, &o, w, &res, NULL) : MM_ENOMEM;
    mm_ode_work_free(w);
    return NULL;
}

static void concurrent_solves_should_match_a_serial_solve_bit_for_bit(void **state)
{
    (void)state;
    enum { NT = 6 };
    job serial[3], jobs[NT];
    for (int m = 0; m < 3; m++) {
        serial[m].method = (mm_ode_method)m;
        run_job(&serial[m]);
        assert_int_equal(serial[m].rc, MM_OK);
    }
    pthread_t th[NT];
    for (int i = 0; i < NT; i++) {
        jobs[i].method = (mm_ode_method)(i % 3);
        assert_int_equal(pthread_create(&th[i], NULL, run_job, &jobs[i]), 0);
    }
    for (int i = 0; i < NT; i++) {
        pthread_join(th[i], NULL);
        assert_int_equal(jobs[i].rc, MM_OK);
        assert_memory_equal(jobs[i].y, serial[i % 3].y, sizeof jobs[i].y);
    }
}


/* ======================================================================== */
/* Events and the fixed-step rule                                           */
/* ======================================================================== */

/* x'' = -x as y = (x, v): x = cos t, v = -sin t from (1, 0). */
static int cos_rhs(double t, const double *y, double *dydt, void *params)
{
    (void)t;
    (void)params;
    dydt[0] = y[1];
    dydt[1] = -y[0];
    return 0;
}

static int event_x(double t, const double *y, double *g, void *params)
{
    (void)t;
    (void)params;
    *g = y[0];
    return 0;
}

static int event_minus_v(double t, const double *y, double *g, void *params)
{
    (void)t;
    (void)params;
    *g = -y[1];
    return 0;
}

/* Run x'' = -x from (1, 0) over [0, t_end] with an event; grid of nout
 * points over [0, t_end] into y_out (2 nout); returns the result. */
static mm_ode_result run_event(mm_ode_method method, mm_ode_event_fn g, int dir, double t_end,
                               double rtol, double *y_end, size_t nout, const double *t_out, double *y_out)
{
    double y0[2] = {1, 0};
    mm_ode_problem prob = {.n = 2, .f = cos_rhs, .t0 = 0, .t_end = t_end, .y0 = y0, .event = g,
                           .event_dir = dir};
    mm_ode_options opt;
    mm_ode_options_init(&opt);
    opt.method = method;
    opt.rtol = rtol;
    opt.atol = rtol;
    if (method == MM_ODE_RK4)
        opt.h = 1e-3;
    mm_ode_result r = {.y_end = y_end, .t_out = t_out, .nout = nout, .y_out = y_out};
    mm_ode_work *w = mm_ode_work_alloc(2);
    mm_error err;
    assert_int_equal(mm_ode_solve(&prob, &opt, w, &r, &err), MM_OK);
    mm_ode_work_free(w);
    return r;
}

static void an_event_should_stop_the_run_at_the_zero_of_its_function(void **state)
{
    (void)state;
    /* x = cos t falls through 0 at pi/2: DOP853 at rtol 1e-12, its 7th-order
     * continuous extension, Brent to a few eps: t and the state to ~1e-12 */
    double y[2], tg[5] = {0, 0.5, 1.0, 1.5, 1.6}, yg[10];
    mm_ode_result r = run_event(MM_ODE_DOP853, event_x, -1, 10, 1e-12, y, 5, tg, yg);
    assert_int_equal(r.event, 1);
    check_abs(r.t_event, M_PI / 2, 1e-11, "cos t = 0 at pi/2");
    check_abs(r.t_reached, r.t_event, 0, "the run ends at the event");
    check_abs(y[0], 0, 1e-11, "x at the event");
    check_abs(y[1], -1, 1e-11, "v = -sin(pi/2) at the event");
    /* the grid is written up to the event only: 1.6 > pi/2 is left out */
    assert_int_equal((int)r.nout_done, 4);
    check_abs(yg[6], cos(1.5), 1e-11, "grid value before the event");
    assert_true(r.n_event_evals >= 3);
    /* DOPRI5 (4th-order extension) and RK4 (cubic Hermite, h = 1e-3:
     * error ~ h^4 = 1e-12) locate it too */
    r = run_event(MM_ODE_DOPRI5, event_x, -1, 10, 1e-10, y, 0, NULL, NULL);
    check_abs(r.t_event, M_PI / 2, 1e-8, "DOPRI5 at rtol 1e-10");
    r = run_event(MM_ODE_RK4, event_x, -1, 10, 1e-10, y, 0, NULL, NULL);
    check_abs(r.t_event, M_PI / 2, 1e-10, "RK4 with h = 1e-3");
}

static void an_event_should_respect_its_direction_and_ignore_the_start(void **state)
{
    (void)state;
    double y[2];
    /* x = cos t rises through 0 at 3 pi/2 only */
    mm_ode_result r = run_event(MM_ODE_DOP853, event_x, +1, 10, 1e-12, y, 0, NULL, NULL);
    assert_int_equal(r.event, 1);
    check_abs(r.t_event, 1.5 * M_PI, 1e-11, "first rising zero of cos t");
    /* either direction: the first zero, pi/2 */
    r = run_event(MM_ODE_DOP853, event_x, 0, 10, 1e-12, y, 0, NULL, NULL);
    check_abs(r.t_event, M_PI / 2, 1e-11, "first zero of cos t");
    /* -v = sin t is 0 at the start (a mass at rest): that zero does not
     * count; it falls through 0 at pi */
    r = run_event(MM_ODE_DOP853, event_minus_v, -1, 10, 1e-12, y, 0, NULL, NULL);
    check_abs(r.t_event, M_PI, 1e-11, "sin t falls through 0 at pi, not at 0");
    check_abs(y[0], -1, 1e-11, "x = cos(pi)");
    /* no zero before t_end: the run ends there, no event */
    r = run_event(MM_ODE_DOP853, event_x, -1, 1.5, 1e-12, y, 0, NULL, NULL);
    assert_int_equal(r.event, 0);
    check_abs(r.t_reached, 1.5, 0, "to t_end");
}

/* Free fall y'' = -g from rest at height H: y = H - g t^2 / 2 is a
 * polynomial the methods integrate exactly, so the ground is reached at
 * sqrt(2 H / g) to rounding. */
static int fall_rhs(double t, const double *y, double *dydt, void *params)
{
    (void)t;
    (void)params;
    dydt[0] = y[1];
    dydt[1] = -9.81;
    return 0;
}

static void a_falling_body_should_hit_the_ground_at_the_closed_form_time(void **state)
{
    (void)state;
    double y0[2] = {20, 0}, y[2];
    mm_ode_problem prob = {.n = 2, .f = fall_rhs, .t0 = 0, .t_end = 5, .y0 = y0, .event = event_x,
                           .event_dir = -1};
    mm_ode_options opt;
    mm_ode_options_init(&opt);
    opt.method = MM_ODE_DOPRI5;
    mm_ode_result r = {.y_end = y};
    mm_ode_work *w = mm_ode_work_alloc(2);
    mm_error err;
    assert_int_equal(mm_ode_solve(&prob, &opt, w, &r, &err), MM_OK);
    mm_ode_work_free(w);
    /* Brent to 2 eps |t| on a quadratic that the extension reproduces */
    check_rel(r.t_event, sqrt(2 * 20 / 9.81), 1e-14, "ground at sqrt(2 H / g)");
    check_rel(y[1], -sqrt(2 * 9.81 * 20), 1e-13, "speed sqrt(2 g H)");
    /* a bad direction is refused before anything runs */
    prob.event_dir = 2;
    assert_int_equal(mm_ode_check(&prob, &opt, NULL, &err), MM_ERANGE);
    assert_string_equal(err.param, "event_dir");
}

static void fixed_steps_should_be_equal_and_never_one_too_many(void **state)
{
    (void)state;
    check_abs(mm_ode_fixed_steps(10, 0.001), 10000, 0, "10 / 0.001 rounds to 10000.000000000002");
    check_abs(mm_ode_fixed_steps(10, 0.03), 334, 0, "333.3 -> 334 steps of 0.0299");
    check_abs(mm_ode_fixed_steps(1, 5), 1, 0, "a step longer than the span: one step");
    check_abs(mm_ode_fixed_steps(1, 0.1), 10, 0, "1 / 0.1 = 10 exactly");
}

/* mm_ode_run is the ritual check, workspace, solve, free in one call: the
 * same answer to the last bit as mm_ode_solve with a workspace of one's
 * own, and a refused problem refused before anything is allocated or
 * evaluated (the right-hand side is never called). */
static void run_should_give_what_check_and_solve_give_and_refuse_what_check_refuses(void **state)
{
    (void)state;
    ctx c1 = {0}, c2 = {0};
    mm_ode_problem p1 = osc_problem(&c1, OSC_Y0, 2.0), p2 = osc_problem(&c2, OSC_Y0, 2.0);
    mm_ode_options o = opts(MM_ODE_DOP853, 1e-9, 0);
    double t[5] = {0, 0.5, 1, 1.5, 2}, y1[10], y2[10];
    mm_ode_result r1 = {.t_out = t, .nout = 5, .y_out = y1}, r2 = {.t_out = t, .nout = 5, .y_out = y2};
    mm_error err;
    assert_int_equal(solve(&p1, &o, &r1, &err), MM_OK);
    assert_int_equal(mm_ode_run(&p2, &o, &r2, &err), MM_OK);
    assert_memory_equal(y1, y2, sizeof y1);
    assert_int_equal(r1.n_eval, r2.n_eval);
    assert_int_equal(c1.calls, c2.calls);

    ctx c3 = {0};
    mm_ode_problem bad = osc_problem(&c3, OSC_Y0, -1.0);        /* t_end before t0 */
    mm_ode_result r3 = {.t_out = NULL, .nout = 0};
    assert_int_equal(mm_ode_run(&bad, &o, &r3, &err), MM_ERANGE);
    assert_string_equal(err.param, "t_end");
    assert_int_equal(c3.calls, 0);
}

/* mm_ode_options_adaptive is mm_ode_options_init with the method, the two
 * tolerances and the step budget set, and nothing else changed. */
static void options_adaptive_should_be_the_defaults_with_four_fields_set(void **state)
{
    (void)state;
    mm_ode_options want, got = mm_ode_options_adaptive(MM_ODE_DOP853, 1e-8, 1e-11, 12345);
    mm_ode_options_init(&want);
    want.method = MM_ODE_DOP853;
    want.rtol = 1e-8;
    want.atol = 1e-11;
    want.max_steps = 12345;
    assert_int_equal(got.method, want.method);
    assert_true(got.rtol == want.rtol && got.atol == want.atol && got.max_steps == want.max_steps);
    assert_true(got.h == want.h && got.h_init == want.h_init && got.h_max == want.h_max);
    assert_int_equal(got.pi_control, want.pi_control);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(dopri5_should_match_the_forced_damped_oscillator),
        cmocka_unit_test(dop853_should_match_the_forced_damped_oscillator),
        cmocka_unit_test(rk4_should_match_the_forced_damped_oscillator),
        cmocka_unit_test(every_method_should_match_exponential_decay),
        cmocka_unit_test(dop853_should_turn_a_rotation_by_exact_sin_and_cos),
        cmocka_unit_test(rk4_should_converge_at_fourth_order),
        cmocka_unit_test(dopri5_with_fixed_steps_should_converge_at_fifth_order),
        cmocka_unit_test(dop853_with_fixed_steps_should_converge_at_eighth_order),
        cmocka_unit_test(dense_output_should_be_as_accurate_between_steps_as_at_them),
        cmocka_unit_test(adaptive_methods_should_follow_undamped_resonance_over_160_periods),
        cmocka_unit_test(rk4_should_lose_energy_by_its_amplification_factor_over_1e5_periods),
        cmocka_unit_test(explicit_methods_should_stop_cleanly_on_a_stiff_problem),
        cmocka_unit_test(explicit_methods_should_solve_a_short_stiff_interval),
        cmocka_unit_test(every_accepted_step_should_be_recorded),
        cmocka_unit_test(grid_points_at_both_ends_should_be_the_states_there),
        cmocka_unit_test(a_grid_point_at_t_end_should_always_be_filled),
        cmocka_unit_test(evaluation_counts_should_follow_from_the_tableaux),
        cmocka_unit_test(error_estimate_should_bound_the_achieved_error),
        cmocka_unit_test(first_step_should_not_pass_where_its_error_estimate_is_zero),
        cmocka_unit_test(adaptive_run_should_stop_at_max_steps_with_a_clear_message),
        cmocka_unit_test(check_should_reject_each_bad_argument_naming_the_field),
        cmocka_unit_test(solve_should_report_enomem_for_a_missing_workspace),
        cmocka_unit_test(run_should_give_what_check_and_solve_give_and_refuse_what_check_refuses),
        cmocka_unit_test(work_alloc_should_refuse_bad_sizes_and_free_null),
        cmocka_unit_test(options_init_should_fill_the_documented_defaults),
        cmocka_unit_test(options_adaptive_should_be_the_defaults_with_four_fields_set),
        cmocka_unit_test(solve_should_stop_when_the_callback_returns_nonzero),
        cmocka_unit_test(adaptive_run_should_report_nonfinite_when_f_gives_nan),
        cmocka_unit_test(fixed_step_beyond_the_stability_limit_should_report_nonfinite),
        cmocka_unit_test(blow_up_should_end_with_an_error_not_a_hang),
        cmocka_unit_test(step_record_should_report_when_it_is_full),
        cmocka_unit_test(concurrent_solves_should_match_a_serial_solve_bit_for_bit),
        cmocka_unit_test(an_event_should_stop_the_run_at_the_zero_of_its_function),
        cmocka_unit_test(an_event_should_respect_its_direction_and_ignore_the_start),
        cmocka_unit_test(a_falling_body_should_hit_the_ground_at_the_closed_form_time),
        cmocka_unit_test(fixed_steps_should_be_equal_and_never_one_too_many),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
