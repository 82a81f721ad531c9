/* test_newmark.c — the second-order integrators of mm_newmark against
 * independent references: closed-form oscillator solutions, measured orders
 * of convergence, textbook stability limits and period errors, conserved
 * quantities, and the pendulum period from the complete elliptic integral.
 */
#include "mm_test.h"

#include <stdlib.h>
#include <string.h>

#include "mm_newmark.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* ======================================================================== */
/* Helpers                                                                  */
/* ======================================================================== */

/* m x'' + c x' + k x = F0 cos(w t), one degree of freedom. */
typedef struct osc {
    double m, c, k, F0, w;
} osc;

static int osc_force(double t, const double *q, const double *qd, double *F,
                     void *params)
{
    const osc *s = params;
    (void)q;
    (void)qd;
    F[0] = s->F0 * cos(s->w * t);
    return 0;
}

/* Closed-form x(t) of the oscillator from x(0) = x0, x'(0) = v0: a
 * particular solution (t sin t growth at undamped resonance) plus the free
 * motion for under-, critical or over-damping. */
static double osc_exact(const osc *s, double x0, double v0, double t)
{
    double wn = sqrt(s->k / s->m), zeta = s->c / (2.0 * sqrt(s->k * s->m));
    double xp = 0.0, xp0 = 0.0, vp0 = 0.0;

    if (s->F0 != 0.0 && s->c == 0.0 && s->w == wn) {    /* resonance */
        xp = s->F0 / (2.0 * s->m * wn) * t * sin(wn * t);
    } else if (s->F0 != 0.0) {
        double kd = s->k - s->m * s->w * s->w, cw = s->c * s->w;
        double D = kd * kd + cw * cw;
        double A = s->F0 * kd / D, B = s->F0 * cw / D;
        xp = A * cos(s->w * t) + B * sin(s->w * t);
        xp0 = A;
        vp0 = B * s->w;
    }
    double X = x0 - xp0, V = v0 - vp0, xh;
    if (zeta < 1.0 - 1e-12) {
        double wd = wn * sqrt(1.0 - zeta * zeta);
        xh = exp(-zeta * wn * t) * (X * cos(wd * t) + (V + zeta * wn * X) / wd * sin(wd * t));
    } else if (zeta > 1.0 + 1e-12) {
        double r = wn * sqrt(zeta * zeta - 1.0);
        double s1 = -zeta * wn + r, s2 = -zeta * wn - r;
        double c1 = (V - s2 * X) / (s1 - s2), c2 = X - c1;
        xh = c1 * exp(s1 * t) + c2 * exp(s2 * t);
    } else {
        xh = exp(-wn * t) * (X + (V + wn * X) * t);
    }
    return xp + xh;
}

/* A problem for the oscillator; q0, v0 must outlive it. */
static mm_newmark_problem osc_problem(const osc *s, const double *x0,
                                      const double *v0, double t_end)
{
    mm_newmark_problem p;
    memset(&p, 0, sizeof p);
    p.n = 1;
    p.M = &s->m;
    p.C = s->c != 0.0 ? &s->c : NULL;
    p.K = &s->k;
    p.force = s->F0 != 0.0 ? osc_force : NULL;
    p.force_kind = MM_NEWMARK_FORCE_TIME;
    p.params = (void *)s;
    p.q0 = x0;
    p.qd0 = v0;
    p.t0 = 0.0;
    p.t_end = t_end;
    return p;
}

/* Run with result arrays for every stored row (t, q, qd, qdd, energy).
 * Free with result_free. */
static int integrate(const mm_newmark_problem *p, const mm_newmark_options *o,
                     mm_newmark_result *res, mm_error *err)
{
    memset(res, 0, sizeof *res);
    mm_error_clear(err);
    int rc = mm_newmark_check(p, o, err);
    if (rc)
        return rc;
    int rows = mm_newmark_output_rows(p, o);
    size_t nr = (size_t)rows * (size_t)p->n;
    res->t = calloc((size_t)rows, sizeof *res->t);
    res->q = calloc(nr, sizeof *res->q);
    res->qd = calloc(nr, sizeof *res->qd);
    res->qdd = calloc(nr, sizeof *res->qdd);
    res->energy = calloc((size_t)rows, sizeof *res->energy);
    res->max_rows = rows;
    assert_non_null(res->t);
    assert_non_null(res->q);
    assert_non_null(res->qd);
    assert_non_null(res->qdd);
    assert_non_null(res->energy);
    mm_newmark_work *w = mm_newmark_work_alloc(p->n);
    assert_non_null(w);
    rc = mm_newmark_solve(p, o, w, res, err);
    mm_newmark_work_free(w);
    return rc;
}

static void result_free(mm_newmark_result *res)
{
    free(res->t);
    free(res->q);
    free(res->qd);
    free(res->qdd);
    free(res->energy);
    memset(res, 0, sizeof *res);
}

/* Run without storing rows (counters and energy figures only). */
static int integrate_bare(const mm_newmark_problem *p, const mm_newmark_options *o,
                          mm_newmark_result *res, mm_error *err)
{
    memset(res, 0, sizeof *res);
    mm_error_clear(err);
    mm_newmark_work *w = mm_newmark_work_alloc(p->n);
    assert_non_null(w);
    int rc = mm_newmark_solve(p, o, w, res, err);
    mm_newmark_work_free(w);
    return rc;
}

static mm_newmark_options options(mm_newmark_method method, double h)
{
    mm_newmark_options o;
    mm_newmark_options_init(&o);
    o.method = method;
    o.h = h;
    return o;
}

/* Largest |x - exact| over every step of a run of the oscillator. */
static double osc_max_error(const osc *s, double x0, double v0, double t_end,
                            const mm_newmark_options *o)
{
    mm_newmark_problem p = osc_problem(s, &x0, &v0, t_end);
    mm_newmark_result res;
    mm_error err;
    int rc = integrate(&p, o, &res, &err);
    if (rc)
        print_error("solve failed: %s\n", err.msg);
    assert_int_equal(rc, MM_OK);
    double e = 0.0;
    for (int i = 0; i < res.rows; i++) {
        double d = fabs(res.q[i] - osc_exact(s, x0, v0, res.t[i]));
        if (d > e)
            e = d;
    }
    result_free(&res);
    return e;
}

/* Error ratio when h is halved: about 2^p for a method of order p. */
static double order_ratio(const osc *s, double x0, double v0, double t_end,
                          mm_newmark_options o)
{
    double e1 = osc_max_error(s, x0, v0, t_end, &o);
    o.h /= 2.0;
    double e2 = osc_max_error(s, x0, v0, t_end, &o);
    return e1 / e2;
}

/* Time of the j-th (1-based) zero crossing of q, by linear interpolation
 * between stored rows; -1 if there are fewer. */
static double zero_crossing(const mm_newmark_result *res, int j)
{
    int found = 0;
    for (int i = 0; i + 1 < res->rows; i++) {
        double a = res->q[i], b = res->q[i + 1];
        if ((a > 0.0 && b <= 0.0) || (a < 0.0 && b >= 0.0))
            if (++found == j)
                return res->t[i] + (res->t[i + 1] - res->t[i]) * a / (a - b);
    }
    return -1.0;
}

/* Arithmetic-geometric mean: K(k) = pi / (2 agm(1, sqrt(1 - k^2))). */
static double agm(double a, double b)
{
    while (fabs(a - b) > 1e-15 * a) {
        double m = 0.5 * (a + b);
        b = sqrt(a * b);
        a = m;
    }
    return a;
}

/* ======================================================================== */
/* Closed forms                                                             */
/* ======================================================================== */

/* omega_n = 2 pi (T = 1 s), h = 1e-3 s: omega h = 6.3e-3.  Average
 * acceleration's phase error is omega t (omega h)^2 / 12 = 6e-5 rad after
 * 3 s, so 1e-4 on a unit amplitude covers it; damped cases do better. */
static void average_acceleration_should_match_free_underdamped_oscillator(void **state)
{
    (void)state;
    osc s = {1.0, 2.0 * 0.1 * 2.0 * M_PI, 4.0 * M_PI * M_PI, 0.0, 0.0};  /* zeta = 0.1 */
    mm_newmark_options o = options(MM_NEWMARK_AVERAGE, 1e-3);
    check_abs(osc_max_error(&s, 1.0, 0.5, 3.0, &o), 0.0, 1e-4,
              "underdamped, zeta = 0.1: phase error omega t (omega h)^2/12 = 6e-5");
}

static void average_acceleration_should_match_free_critically_damped_oscillator(void **state)
{
    (void)state;
    osc s = {1.0, 4.0, 4.0, 0.0, 0.0};      /* zeta = c / (2 sqrt(k m)) = 1 exactly */
    mm_newmark_options o = options(MM_NEWMARK_AVERAGE, 1e-3);
    check_abs(osc_max_error(&s, 1.0, -3.0, 5.0, &o), 0.0, 1e-6,
              "critical damping: no oscillation, global error O(h^2) = 1e-6");
}

static void average_acceleration_should_match_free_overdamped_oscillator(void **state)
{
    (void)state;
    osc s = {1.0, 8.0, 4.0, 0.0, 0.0};      /* zeta = 2 */
    mm_newmark_options o = options(MM_NEWMARK_AVERAGE, 1e-3);
    check_abs(osc_max_error(&s, 1.0, 2.0, 5.0, &o), 0.0, 1e-6,
              "overdamped: roots -0.54 and -7.46, error O((7.5 h)^2) < 1e-6");
}

/* x'' + 2x' + 100x = cos 8t from rest: transient plus steady state
 * (amplitude 1/sqrt(36^2 + 16^2) = 0.025). */
static void average_acceleration_should_match_forced_damped_oscillator(void **state)
{
    (void)state;
    osc s = {1.0, 2.0, 100.0, 1.0, 8.0};
    mm_newmark_options o = options(MM_NEWMARK_AVERAGE, 1e-3);
    check_abs(osc_max_error(&s, 0.0, 0.0, 10.0, &o), 0.0, 3e-6,
              "the steady state is locked to the forcing, so the error does not "
              "accumulate: O((omega h)^2) = 1e-4 of the 0.025 amplitude");
}

/* x'' + x = cos t from rest: x = t sin t / 2, growing without bound. */
static void average_acceleration_should_follow_undamped_resonance(void **state)
{
    (void)state;
    osc s = {1.0, 0.0, 1.0, 1.0, 1.0};
    double x0 = 0.0, v0 = 0.0, t_end = 20.0 * M_PI;
    mm_newmark_problem p = osc_problem(&s, &x0, &v0, t_end);
    mm_newmark_options o = options(MM_NEWMARK_AVERAGE, 1e-3);
    mm_newmark_result res;
    mm_error err;
    assert_int_equal(integrate(&p, &o, &res, &err), MM_OK);
    double worst = 0.0;
    for (int i = 0; i < res.rows; i++) {
        double t = res.t[i], d = fabs(res.q[i] - 0.5 * t * sin(t));
        if (d > worst)
            worst = d;
    }
    check_rel(res.q[res.rows - 1], 0.5 * res.t[res.rows - 1] * sin(res.t[res.rows - 1]),
              1.0, "sanity: the end value is near the closed form");
    check_abs(worst, 0.0, 3e-4,
              "amplitude t/2 = 31 times phase error t h^2/12 = 5e-6 rad at t = 20 pi");
    result_free(&res);
}

/* ======================================================================== */
/* Measured order of convergence: halve h, the error falls by 2^p            */
/* ======================================================================== */

/* x'' + 2x' + 100x = cos 8t over [0, 2] s at h = T/40, T/80 (omega h = 0.16,
 * 0.08): close enough to the asymptotic regime that the ratio is 4 within
 * 10 % (the next term is (omega h)^2 smaller). */
#define ORDER_H (2.0 * M_PI / 10.0 / 40.0)

static void average_acceleration_should_be_second_order(void **state)
{
    (void)state;
    osc s = {1.0, 2.0, 100.0, 1.0, 8.0};
    check_rel(order_ratio(&s, 0.0, 0.0, 2.0, options(MM_NEWMARK_AVERAGE, ORDER_H)), 4.0, 0.1,
              "error ratio when h halves, second order: 4 within 10 %");
}

static void linear_acceleration_should_be_second_order(void **state)
{
    (void)state;
    osc s = {1.0, 2.0, 100.0, 1.0, 8.0};
    check_rel(order_ratio(&s, 0.0, 0.0, 2.0, options(MM_NEWMARK_LINEAR, ORDER_H)), 4.0, 0.1,
              "error ratio when h halves, second order: 4 within 10 %");
}

static void central_difference_should_be_second_order(void **state)
{
    (void)state;
    osc s = {1.0, 2.0, 100.0, 1.0, 8.0};
    check_rel(order_ratio(&s, 0.0, 0.0, 2.0, options(MM_NEWMARK_CENTRAL, ORDER_H)), 4.0, 0.1,
              "error ratio when h halves, second order: 4 within 10 %");
}

/* Verlet is second order for C = 0: x'' + 100x = cos 8t. */
static void verlet_should_be_second_order_without_damping(void **state)
{
    (void)state;
    osc s = {1.0, 0.0, 100.0, 1.0, 8.0};
    check_rel(order_ratio(&s, 0.0, 0.0, 2.0, options(MM_NEWMARK_VERLET, ORDER_H)), 4.0, 0.1,
              "error ratio when h halves, second order: 4 within 10 %");
}

/* With C != 0 Verlet takes the damping force at the half-step velocity:
 * an O(h) error in the force, so the method drops to first order. */
static void verlet_should_drop_to_first_order_with_damping(void **state)
{
    (void)state;
    osc s = {1.0, 2.0, 100.0, 1.0, 8.0};
    mm_newmark_options o = options(MM_NEWMARK_VERLET, ORDER_H / 4.0);
    check_rel(order_ratio(&s, 0.0, 0.0, 2.0, o), 2.0, 0.1,
              "error ratio when h halves, first order: 2 within 10 %");
}

static void hht_alpha_should_be_second_order(void **state)
{
    (void)state;
    osc s = {1.0, 2.0, 100.0, 1.0, 8.0};
    mm_newmark_options o = options(MM_NEWMARK_HHT, ORDER_H);
    o.alpha = -0.1;
    check_rel(order_ratio(&s, 0.0, 0.0, 2.0, o), 4.0, 0.1,
              "error ratio when h halves, second order: 4 within 10 %");
}

static void generalized_alpha_should_be_second_order(void **state)
{
    (void)state;
    osc s = {1.0, 2.0, 100.0, 1.0, 8.0};
    mm_newmark_options o = options(MM_NEWMARK_GENERALIZED_ALPHA, ORDER_H);
    o.rho_inf = 0.8;
    check_rel(order_ratio(&s, 0.0, 0.0, 2.0, o), 4.0, 0.1,
              "error ratio when h halves, second order: 4 within 10 %");
}

/* alpha = 0 makes (G) plain Newmark with beta = 1/4, gamma = 1/2. */
static void hht_with_alpha_zero_should_equal_average_acceleration(void **state)
{
    (void)state;
    osc s = {1.0, 2.0, 100.0, 1.0, 8.0};
    mm_newmark_options a = options(MM_NEWMARK_AVERAGE, 0.01), b = options(MM_NEWMARK_HHT, 0.01);
    b.alpha = 0.0;
    check_abs(osc_max_error(&s, 0.0, 0.0, 2.0, &b), osc_max_error(&s, 0.0, 0.0, 2.0, &a),
              1e-15, "same scheme, same arithmetic");
}

/* ======================================================================== */
/* Stability                                                                */
/* ======================================================================== */

/* x'' + x = 0 with h = 10 T: average acceleration keeps
 * 1/2 v^2 + 1/2 x^2 exactly, so |x| never exceeds its starting value. */
static void average_acceleration_should_stay_bounded_at_ten_periods_per_step(void **state)
{
    (void)state;
    osc s = {1.0, 0.0, 1.0, 0.0, 0.0};
    double x0 = 1.0, v0 = 0.0;
    mm_newmark_problem p = osc_problem(&s, &x0, &v0, 1000 * 20.0 * M_PI);
    mm_newmark_options o = options(MM_NEWMARK_AVERAGE, 20.0 * M_PI);
    mm_newmark_result res;
    mm_error err;
    assert_int_equal(integrate(&p, &o, &res, &err), MM_OK);
    assert_int_equal(res.steps, 1000);
    double xmax = 0.0;
    for (int i = 0; i < res.rows; i++)
        xmax = fmax(xmax, fabs(res.q[i]));
    check_abs(xmax, 1.0, 1e-12, "the energy invariant bounds |x| by 1 (round-off only)");
    check_abs(res.energy_error, 0.0, 1e-12, "energy not growing: round-off only");
    result_free(&res);
}

/* Central difference with omega h = 2.1 > 2: the amplification factor
 * has modulus 1.9, so 2000 steps overflow; the limit is reported. */
static void central_difference_should_report_blow_up_past_two_over_omega(void **state)
{
    (void)state;
    osc s = {1.0, 0.0, 100.0, 0.0, 0.0};    /* omega = 10 rad/s, limit 0.2 s */
    double x0 = 1.0, v0 = 0.0, h = 0.21;
    mm_newmark_problem p = osc_problem(&s, &x0, &v0, 2000 * h);
    mm_newmark_options o = options(MM_NEWMARK_CENTRAL, h);
    mm_newmark_result res;
    mm_error err;
    assert_int_equal(integrate(&p, &o, &res, &err), MM_ENONFINITE);
    assert_int_equal(err.code, MM_ENONFINITE);
    assert_string_equal(err.param, "h");
    assert_non_null(strstr(err.msg, "stability limit"));
    assert_non_null(strstr(err.msg, "0.2 s"));
    check_rel(res.h_stable, 0.2, 1e-9, "h_stable = 2/omega = 0.2 s (1 x 1: exact)");
    assert_true(res.steps < 2000);
    assert_true(res.rows == res.steps + 1);     /* the rows before the overflow */
    result_free(&res);
}

/* Just below the limit, omega h = 1.99: the central-difference invariant
 * q_k^2 + q_{k+1}^2 - (2 - (omega h)^2) q_k q_{k+1} bounds |q| by 1 when
 * it starts at q = 1, v = 0. */
static void central_difference_should_stay_bounded_just_below_the_limit(void **state)
{
    (void)state;
    osc s = {1.0, 0.0, 100.0, 0.0, 0.0};
    double x0 = 1.0, v0 = 0.0, h = 0.199;
    mm_newmark_problem p = osc_problem(&s, &x0, &v0, 10000 * h);
    mm_newmark_options o = options(MM_NEWMARK_CENTRAL, h);
    mm_newmark_result res;
    mm_error err;
    assert_int_equal(integrate(&p, &o, &res, &err), MM_OK);
    double xmax = 0.0;
    for (int i = 0; i < res.rows; i++)
        xmax = fmax(xmax, fabs(res.q[i]));
    check_abs(xmax, 1.0, 1e-9, "invariant bounds |q| by 1; 1e4 steps of round-off");
    result_free(&res);
}

/* Linear acceleration: stable for omega h < 2 sqrt(3) = 3.46. */
static void linear_acceleration_should_report_blow_up_past_its_limit(void **state)
{
    (void)state;
    osc s = {1.0, 0.0, 1.0, 0.0, 0.0};
    double x0 = 1.0, v0 = 0.0, h = 3.6;
    mm_newmark_problem p = osc_problem(&s, &x0, &v0, 5000 * h);
    mm_newmark_options o = options(MM_NEWMARK_LINEAR, h);
    mm_newmark_result res;
    mm_error err;
    assert_int_equal(integrate(&p, &o, &res, &err), MM_ENONFINITE);
    assert_string_equal(err.param, "h");
    assert_non_null(strstr(err.msg, "3.46/omega_max"));
    check_rel(res.h_stable, 2.0 * sqrt(3.0), 1e-9, "h_stable = 2 sqrt(3) / omega");
    result_free(&res);
}

/* M = diag(1, 2), K = [3 -1; -1 1]: det(K - lambda M) = 2 lambda^2 -
 * 7 lambda + 2, so omega_max^2 = (7 + sqrt 33)/4. */
static void central_difference_should_estimate_the_limit_of_a_two_dof_system(void **state)
{
    (void)state;
    double M[4] = {1, 0, 0, 2}, K[4] = {3, -1, -1, 1}, q0[2] = {1, 0};
    mm_newmark_problem p;
    memset(&p, 0, sizeof p);
    p.n = 2; p.M = M; p.K = K; p.q0 = q0; p.t_end = 1.0;
    mm_newmark_options o = options(MM_NEWMARK_CENTRAL, 0.01);
    mm_newmark_result res;
    mm_error err;
    assert_int_equal(integrate(&p, &o, &res, &err), MM_OK);
    double wmax = sqrt((7.0 + sqrt(33.0)) / 4.0);
    check_rel(res.omega_max, wmax, 1e-14, "omega_max from every eigenvalue: exact to rounding");
    check_rel(res.h_stable, 2.0 / wmax, 1e-14, "h_stable = 2 / omega_max");
    result_free(&res);
}


/* ======================================================================== */
/* Stability limit and amplification matrix                                 */
/* ======================================================================== */

/* The n = 160 fixed-fixed chain, k = 1e4 N/m, m = 1 kg: omega_max =
 * 2 sqrt(k/m) sin(n pi / (2 (n + 1))), so h_stable = 0.0100005 s; the
 * power iteration this replaced said 0.0100196 s (issue 9): too large, an
 * unstable step called stable. */
static void central_difference_should_find_the_exact_limit_of_a_160_mass_chain(void **state)
{
    (void)state;
    enum { N = 160 };
    double *M = calloc(N * N, sizeof *M), *K = calloc(N * N, sizeof *K), q0[N];
    for (int i = 0; i < N; i++) {
        M[i * N + i] = 1;
        K[i * N + i] = 2e4;
        if (i + 1 < N)
            K[i * N + i + 1] = K[(i + 1) * N + i] = -1e4;
        q0[i] = sin(3.0 * i);
    }
    mm_newmark_problem p;
    memset(&p, 0, sizeof p);
    p.n = N; p.M = M; p.K = K; p.q0 = q0; p.t_end = 0.01;
    mm_newmark_options o = options(MM_NEWMARK_CENTRAL, 0.001);
    mm_newmark_result res;
    mm_error err;
    assert_int_equal(integrate(&p, &o, &res, &err), MM_OK);
    double wmax = 200 * sin(N * M_PI / (2.0 * (N + 1)));
    /* the largest eigenvalue of a symmetric pencil: backward error of a few
     * eps, here exactly conditioned (M = I) */
    check_rel(res.omega_max, wmax, 1e-13, "omega_max of the chain, closed form");
    check_rel(res.h_stable, 2 / wmax, 1e-13, "h_stable = 2/omega_max = 0.0100005 s");
    assert_true(res.h_stable < 0.0100006);
    result_free(&res);
    free(M);
    free(K);
}

static void omega_h_limit_should_be_the_textbook_values(void **state)
{
    (void)state;
    mm_newmark_options o;
    mm_newmark_options_init(&o);
    static const struct { mm_newmark_method m; double lim; } t[] = {
        {MM_NEWMARK_CENTRAL, 2}, {MM_NEWMARK_VERLET, 2}, {MM_NEWMARK_LINEAR, 3.4641016151377544},
        {MM_NEWMARK_AVERAGE, 0}, {MM_NEWMARK_HHT, 0}, {MM_NEWMARK_GENERALIZED_ALPHA, 0},
    };
    for (size_t i = 0; i < sizeof t / sizeof t[0]; i++) {
        o.method = t[i].m;
        check_rel(mm_newmark_omega_h_limit(&o), t[i].lim, 1e-15, mm_newmark_method_name(t[i].m));
    }
    o.method = MM_NEWMARK_BETA_GAMMA;
    o.beta = 0.1, o.gamma = 0.5;      /* 1/sqrt(0.25 - 0.1) */
    check_rel(mm_newmark_omega_h_limit(&o), 1 / sqrt(0.15), 1e-15, "beta 0.1, gamma 0.5");
    o.beta = 0.3;                     /* 2 beta >= gamma: unconditional */
    check_abs(mm_newmark_omega_h_limit(&o), 0, 0, "beta 0.3");
}

/* The spectral radius on x'' + omega^2 x = 0: 1 for average acceleration at
 * any step; 1 for central difference below omega h = 2 and, above it, the
 * root of l^2 - (2 - W^2) l + 1 = 0 of largest size; HHT-alpha tends to
 * (1 + alpha)/(1 - alpha) at infinite omega h, generalized-alpha to rho_inf. */
static void spectral_radius_should_match_the_closed_forms(void **state)
{
    (void)state;
    mm_newmark_options o = options(MM_NEWMARK_AVERAGE, 1);
    for (double W = 0.01; W < 1e4; W *= 3.7)
        check_rel(mm_newmark_spectral_radius(&o, W, 0), 1, 1e-12, "average acceleration undamped");
    o.method = MM_NEWMARK_CENTRAL;
    check_rel(mm_newmark_spectral_radius(&o, 1.999, 0), 1, 1e-6, "central difference below 2");
    for (double W = 2.001; W < 10; W *= 1.3) {
        double b = 2 - W * W, l = fabs((b - sqrt(b * b - 4)) / 2);
        check_rel(mm_newmark_spectral_radius(&o, W, 0), l, 1e-12, "central difference above 2");
        assert_true(mm_newmark_spectral_radius(&o, W, 0) > 1);
    }
    o.method = MM_NEWMARK_HHT;
    o.alpha = -0.3;
    check_rel(mm_newmark_spectral_radius(&o, 1e7, 0), 0.7 / 1.3, 1e-5, "HHT at infinity");
    o.method = MM_NEWMARK_GENERALIZED_ALPHA;
    o.rho_inf = 0.6;
    /* a double eigenvalue -rho_inf at infinity: its pair splits like
     * sqrt(1/(omega h)), so 3e-5 at omega h = 1e7 */
    check_rel(mm_newmark_spectral_radius(&o, 1e7, 0), 0.6, 1e-4, "generalized-alpha at infinity");
    /* damping lowers Verlet's limit below 2 */
    o.method = MM_NEWMARK_VERLET;
    assert_true(mm_newmark_spectral_radius(&o, 1.99, 0.2) > 1);
    o.method = MM_NEWMARK_CENTRAL;
    assert_true(mm_newmark_spectral_radius(&o, 1.99, 0.2) < 1);
}

static int f3(double t, const double *q, const double *qd, double *F, void *params)
{
    (void)q;
    (void)qd;
    (void)params;
    F[0] = cos(3 * t);
    F[1] = 0.5 * cos(3 * t);
    F[2] = -cos(3 * t);
    return 0;
}

/* The powers of the amplification matrix (A) reproduce every scheme's run
 * of a damped, forced 3-DOF system step for step: two statements of the
 * same recursion, one written from the scheme's equations, one stepping. */
static void amplification_matrix_should_reproduce_every_scheme(void **state)
{
    (void)state;
    double M[9] = {2, 0.5, 0, 0.5, 1, 0, 0, 0, 1.5};
    double K[9] = {300, -100, 0, -100, 250, -150, 0, -150, 150};
    double C[9] = {0.8, -0.2, 0, -0.2, 0.5, -0.1, 0, -0.1, 0.3};
    double q0[3] = {0.01, -0.02, 0.005}, v0[3] = {0.1, 0, -0.2};
    static const mm_newmark_method ms[] = {MM_NEWMARK_AVERAGE, MM_NEWMARK_LINEAR, MM_NEWMARK_HHT,
                                           MM_NEWMARK_GENERALIZED_ALPHA, MM_NEWMARK_CENTRAL,
                                           MM_NEWMARK_VERLET, MM_NEWMARK_BETA_GAMMA};
    for (size_t mi = 0; mi < sizeof ms / sizeof ms[0]; mi++) {
        mm_newmark_problem p;
        memset(&p, 0, sizeof p);
        p.n = 3; p.M = M; p.C = C; p.K = K; p.q0 = q0; p.qd0 = v0; p.t_end = 2.0;
        p.force = f3; p.force_kind = MM_NEWMARK_FORCE_TIME;
        mm_newmark_options o = options(ms[mi], 0.02);
        o.beta = 0.3, o.gamma = 0.6;
        mm_newmark_result res;
        mm_error err;
        assert_int_equal(integrate(&p, &o, &res, &err), MM_OK);
        double A[81], B0[27], B1[27], y[9], y1[9], F0[3], F1[3];
        assert_int_equal(mm_newmark_amplification(3, M, C, K, &o, A, B0, B1, &err), MM_OK);
        for (int i = 0; i < 3; i++) {
            y[i] = res.q[i];
            y[3 + i] = res.qd[i];
            y[6 + i] = res.qdd[i];
        }
        double worst = 0, big = 0;
        for (int k = 0; k < res.rows - 1; k++) {
            f3(res.t[k], NULL, NULL, F0, NULL);
            f3(res.t[k + 1], NULL, NULL, F1, NULL);
            for (int i = 0; i < 9; i++) {
                y1[i] = 0;
                for (int j = 0; j < 9; j++)
                    y1[i] += A[i * 9 + j] * y[j];
                for (int j = 0; j < 3; j++)
                    y1[i] += B0[i * 3 + j] * F0[j] + B1[i * 3 + j] * F1[j];
            }
            memcpy(y, y1, sizeof y);
            for (int i = 0; i < 3; i++) {
                worst = fmax(worst, fabs(y[i] - res.q[(k + 1) * 3 + i]));
                big = fmax(big, fabs(y[i]));
            }
        }
        /* 100 steps, each adding a few eps of the state's size */
        check_abs(worst, 0, 1e-12 * big, mm_newmark_method_name(ms[mi]));
        result_free(&res);
    }
}

/* ======================================================================== */
/* Period elongation and long-time energy                                   */
/* ======================================================================== */

/* Average acceleration turns e^{i omega h} into (1 + i Oh/2)/(1 - i Oh/2):
 * omega_num h = 2 atan(omega h / 2), so T_num/T - 1 = (Oh/2)/atan(Oh/2) - 1
 * = (omega h)^2/12 - (omega h)^4/180 + ... */
static void average_acceleration_should_lengthen_the_period_by_omega_h_squared_over_12(void **state)
{
    (void)state;
    osc s = {1.0, 0.0, 1.0, 0.0, 0.0};
    double x0 = 1.0, v0 = 0.0, Oh = 0.1;
    mm_newmark_problem p = osc_problem(&s, &x0, &v0, 1001 * 2.0 * M_PI);
    mm_newmark_options o = options(MM_NEWMARK_AVERAGE, Oh);
    mm_newmark_result res;
    mm_error err;
    assert_int_equal(integrate(&p, &o, &res, &err), MM_OK);
    /* x = cos(omega_num t): crossing j is at (j - 1/2) pi / omega_num;
       after 1000 periods the lag is 5.2 s */
    int j = 2000;
    double tj = zero_crossing(&res, j);
    assert_true(tj > 0.0);
    double elong = tj / ((j - 0.5) * M_PI) - 1.0;
    check_rel(elong, Oh * Oh / 12.0, 0.01,
              "(omega h)^2/12; the neglected (omega h)^4/180 term is 0.07 % of it");
    check_rel(elong, (Oh / 2.0) / atan(Oh / 2.0) - 1.0, 1e-4,
              "exact elongation; linear interpolation misplaces the crossing by "
              "< (omega h)^3/6 = 1.7e-4 s of the 5.2 s lag: 3e-5");
    result_free(&res);
}

/* 1e5 periods at 20 steps per period (Oh = 2 pi/20), x'' + x = 0 from the
 * turning point x = 1.  Velocity Verlet conserves exactly
 *     E~ = 1/2 v^2 + 1/2 omega^2 (1 - (omega h)^2/4) x^2,
 * so E = E~ + (omega h)^2/8 omega^2 x^2 oscillates with half-amplitude
 * about (omega h)^2/8 of E around its mean; from x = 1 it runs between
 * E0 (1 - (omega h)^2/4) and E0, without drift.  max |E - E0|/E0 is
 * therefore (omega h)^2/4 = 0.0247 to round-off, once some step lands
 * near x = 0 (1e5 periods sample the phase densely). */
static void verlet_energy_error_should_stay_bounded_over_1e5_periods(void **state)
{
    (void)state;
    osc s = {1.0, 0.0, 1.0, 0.0, 0.0};
    double x0 = 1.0, v0 = 0.0, Oh = 2.0 * M_PI / 20.0;
    mm_newmark_problem p = osc_problem(&s, &x0, &v0, 1e5 * 2.0 * M_PI);
    mm_newmark_options o = options(MM_NEWMARK_VERLET, Oh);
    o.max_steps = 3000000;
    mm_newmark_result res;
    mm_error err;
    assert_int_equal(integrate_bare(&p, &o, &res, &err), MM_OK);
    assert_int_equal(res.steps, 2000000);
    check_rel(res.energy_error, Oh * Oh / 4.0, 1e-6,
              "bound (omega h)^2/4 from the modified energy, reached and not exceeded");

    /* the same bound after 100 periods: no secular growth */
    mm_newmark_result early;
    p.t_end = 100 * 2.0 * M_PI;
    assert_int_equal(integrate_bare(&p, &o, &early, &err), MM_OK);
    check_rel(res.energy_error, early.energy_error, 1e-3,
              "max error over 1e5 periods equals that over 100 periods: bounded");
}

/* Average acceleration satisfies the discrete energy identity exactly for a
 * linear undamped system: what remains is round-off, which drifts a little
 * (about 2e-11 over the 2e6 steps here) and is bounded by N eps. */
static void average_acceleration_should_conserve_energy_over_1e5_periods(void **state)
{
    (void)state;
    osc s = {1.0, 0.0, 1.0, 0.0, 0.0};
    double x0 = 1.0, v0 = 0.0;
    mm_newmark_problem p = osc_problem(&s, &x0, &v0, 1e5 * 2.0 * M_PI);
    mm_newmark_options o = options(MM_NEWMARK_AVERAGE, 2.0 * M_PI / 20.0);
    o.max_steps = 3000000;
    mm_newmark_result res;
    mm_error err;
    assert_int_equal(integrate_bare(&p, &o, &res, &err), MM_OK);
    check_abs(res.energy_error, 0.0, 2.2e-10,
              "round-off: at worst 2e6 steps times eps = 1.1e-16 in one direction");
    check_rel(res.energy_end.kinetic + res.energy_end.potential, 0.5, 2.2e-10,
              "final energy equals 1/2 to round-off");
}

/* Energy balance residual of one run of x'' + 2x' + 100x = cos 8t. */
static double forced_balance(mm_newmark_method method, double h, mm_newmark_result *keep)
{
    osc s = {1.0, 2.0, 100.0, 1.0, 8.0};
    double x0 = 0.01, v0 = 0.0;
    mm_newmark_problem p = osc_problem(&s, &x0, &v0, 10.0);
    mm_newmark_options o = options(method, h);
    mm_newmark_result res;
    mm_error err;
    assert_int_equal(integrate(&p, &o, &res, &err), MM_OK);
    double e = res.energy_error;
    if (keep)
        *keep = res;
    else
        result_free(&res);
    return e;
}

/* kinetic + potential = E0 + work - dissipated holds for the exact motion;
 * with work and dissipation integrated by the trapezoidal rule the residual
 * of a second-order scheme falls by 4 when h halves, with no reference
 * solution needed. */
static void energy_balance_should_be_a_second_order_error_indicator(void **state)
{
    (void)state;
    mm_newmark_result res;
    double e1 = forced_balance(MM_NEWMARK_AVERAGE, 0.01, &res);
    double e2 = forced_balance(MM_NEWMARK_AVERAGE, 0.005, NULL);
    check_rel(e1 / e2, 4.0, 0.1, "second order: ratio 4 within 10 %");
    check_abs(e1, 0.0, 1e-3, "(omega h)^2 = 1e-2 times a small constant");
    mm_newmark_energy e = res.energy[res.rows - 1];
    double last = fabs(e.kinetic + e.potential - res.energy_start - e.work + e.dissipated);
    assert_true(last <= res.energy_balance);    /* the stored rows agree with the maximum */
    assert_true(e.dissipated > 0.0);
    assert_true(e.dissipated > e.work * 0.5);   /* most of the work input is dissipated */
    result_free(&res);
    check_rel(forced_balance(MM_NEWMARK_CENTRAL, 0.01, NULL) /
              forced_balance(MM_NEWMARK_CENTRAL, 0.005, NULL), 4.0, 0.1,
              "central difference: second order too");
}

/* With the work taken by the trapezoidal rule in q, average acceleration
 * keeps the balance to rounding on a forced, damped system (its step
 * identity E_{k+1} - E_k = (q_{k+1} - q_k).(F_k + F_{k+1} - C v_k -
 * C v_{k+1})/2), while central difference still shows its error. */
static void work_in_q_should_make_the_average_acceleration_balance_exact(void **state)
{
    (void)state;
    osc s = {1.0, 2.0, 100.0, 1.0, 8.0};
    double x0 = 0.01, v0 = 0.0;
    mm_newmark_problem p = osc_problem(&s, &x0, &v0, 10.0);
    mm_newmark_options o = options(MM_NEWMARK_AVERAGE, 0.01);
    o.work_in_q = 1;
    mm_newmark_result res;
    mm_error err;
    assert_int_equal(integrate_bare(&p, &o, &res, &err), MM_OK);
    check_abs(res.energy_error, 0, 1e-13, "1000 steps of rounding");
    o.method = MM_NEWMARK_CENTRAL;
    assert_int_equal(integrate_bare(&p, &o, &res, &err), MM_OK);
    assert_true(res.energy_error > 1e-6);
}

/* HHT-alpha removes energy that no physical damper took: on a free
 * undamped oscillator the balance shows it, while average acceleration
 * keeps the energy to round-off. */
static void energy_balance_should_show_the_numerical_dissipation_of_hht_alpha(void **state)
{
    (void)state;
    osc s = {1.0, 0.0, 1.0, 0.0, 0.0};
    double x0 = 1.0, v0 = 0.0;
    mm_newmark_problem p = osc_problem(&s, &x0, &v0, 50.0);
    mm_newmark_options o = options(MM_NEWMARK_HHT, 0.5);
    o.alpha = -0.3;
    mm_newmark_result res;
    mm_error err;
    assert_int_equal(integrate_bare(&p, &o, &res, &err), MM_OK);
    double E = res.energy_end.kinetic + res.energy_end.potential;
    assert_true(E < 0.9 * res.energy_start);      /* omega h = 0.5: visibly damped */
    check_rel(res.energy_balance, res.energy_start - E, 1e-12,
              "no work, no damper: the imbalance is the energy lost");
    o.method = MM_NEWMARK_AVERAGE;
    assert_int_equal(integrate_bare(&p, &o, &res, &err), MM_OK);
    check_abs(res.energy_error, 0.0, 1e-14, "100 steps of round-off");
}

/* A circulatory (non-symmetric) K: its antisymmetric part does work, which
 * the bookkeeping puts in 'work'; the balance residual must still fall at
 * second order (left out, it would stay O(1)). */
static void energy_balance_should_count_the_work_of_a_nonsymmetric_stiffness(void **state)
{
    (void)state;
    double M[4] = {1, 0, 0, 1}, K[4] = {2, 0.3, -0.3, 1}, q0[2] = {1, 0.5};
    mm_newmark_problem p;
    memset(&p, 0, sizeof p);
    p.n = 2; p.M = M; p.K = K; p.q0 = q0; p.t_end = 20.0;
    mm_newmark_options o = options(MM_NEWMARK_AVERAGE, 0.02);
    mm_newmark_result res;
    mm_error err;
    assert_int_equal(integrate_bare(&p, &o, &res, &err), MM_OK);
    double e1 = res.energy_error;
    assert_true(fabs(res.energy_end.work) > 1e-2);  /* the circulatory force did work */
    o.h = 0.01;
    assert_int_equal(integrate_bare(&p, &o, &res, &err), MM_OK);
    check_rel(e1 / res.energy_error, 4.0, 0.1, "second order: ratio 4 within 10 %");
    check_abs(res.energy_error, 0.0, 1e-4, "small: (omega h)^2 = 2e-4");
}

/* ======================================================================== */
/* Numerical damping of a stiff mode                                         */
/* ======================================================================== */

/* M = I, K = R diag(1, 9e8) R^T (R a 30 degree rotation): a soft mode
 * omega = 1 rad/s and a stiff mode omega = 3e4 rad/s.  With h = 0.01 s the
 * soft mode has omega h = 0.01 and the stiff one omega h = 300, where the
 * principal roots of HHT-alpha have modulus (1 + alpha)/(1 - alpha) within
 * 1.5e-4 and the spurious root is below 0.25 (gone after 20 steps).
 * (A stiffer mode would do no better: every step solves for accelerations
 * of size omega^2, and their round-off, eps cond(S) omega^2, lands on the
 * soft mode too.) */
typedef struct two_dof {
    double M[4], K[4], phi1[2], phi2[2], q0[2];
} two_dof;

static void two_dof_init(two_dof *d)
{
    double c = cos(M_PI / 6.0), s = sin(M_PI / 6.0), w1 = 1.0, w2 = 9e8;
    double phi1[2] = {c, s}, phi2[2] = {-s, c};
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) {
            d->M[i * 2 + j] = i == j;
            d->K[i * 2 + j] = w1 * phi1[i] * phi1[j] + w2 * phi2[i] * phi2[j];
        }
    memcpy(d->phi1, phi1, sizeof phi1);
    memcpy(d->phi2, phi2, sizeof phi2);
    for (int i = 0; i < 2; i++)
        d->q0[i] = phi1[i] + phi2[i];   /* both modes at unit amplitude */
}

/* Run `steps` steps, every one stored; soft and stiff modal coordinates
 * y1, y2 of row k go to res->qd[2k], res->qd[2k + 1]. */
static void run_two_dof(const mm_newmark_options *o, int steps, mm_newmark_result *res)
{
    two_dof d;
    two_dof_init(&d);
    mm_newmark_problem p;
    memset(&p, 0, sizeof p);
    p.n = 2; p.M = d.M; p.K = d.K; p.q0 = d.q0; p.t_end = steps * o->h;
    mm_error err;
    int rc = integrate(&p, o, res, &err);
    if (rc)
        print_error("%s\n", err.msg);
    assert_int_equal(rc, MM_OK);
    assert_int_equal(res->rows, steps + 1);
    for (int i = 0; i < res->rows; i++) {  /* overwrite qd with modal coordinates */
        const double *q = res->q + 2 * i;
        res->qd[2 * i] = d.phi1[0] * q[0] + d.phi1[1] * q[1];
        res->qd[2 * i + 1] = d.phi2[0] * q[0] + d.phi2[1] * q[1];
    }
}

/* Decay per step of a sequence made of a complex pair r e^{+-i theta}:
 * D_k = y_k y_{k+2} - y_{k+1}^2 is proportional to r^{2k} whatever the
 * mix of the two roots, so r = (D_k2 / D_k1)^(1 / 2(k2 - k1)).  (The pair
 * is nearly double at large omega h, so plain amplitude ratios carry a
 * k r^k factor and mislead.)  y_k is res->qd[2k + 1]. */
static double pair_modulus(const mm_newmark_result *res, int k1, int k2)
{
    const double *y = res->qd;
#define D(k) (y[2 * (k) + 1] * y[2 * ((k) + 2) + 1] - y[2 * ((k) + 1) + 1] * y[2 * ((k) + 1) + 1])
    return pow(D(k2) / D(k1), 1.0 / (2.0 * (k2 - k1)));
#undef D
}

static void hht_alpha_should_damp_the_stiff_mode_at_its_spectral_radius(void **state)
{
    (void)state;
    /* (alpha = -0.3 is left out: its spurious root, 0.43 beside 0.54, would
       need 100 steps to fade, and by then the stiff mode is below round-off) */
    const double alphas[] = {-0.05, -0.1, -0.2};
    for (int a = 0; a < 3; a++) {
        mm_newmark_options o = options(MM_NEWMARK_HHT, 0.01);
        o.alpha = alphas[a];
        mm_newmark_result res;
        run_two_dof(&o, 60, &res);
        double rho_inf = (1.0 + o.alpha) / (1.0 - o.alpha);
        check_rel(pair_modulus(&res, 20, 55), rho_inf, 5e-4,
                  "measured decay per step of the stiff mode vs (1+alpha)/(1-alpha); "
                  "at omega h = 300 the roots sit <= 1.5e-4 above it");
        check_rel(res.qd[2 * 60], cos(0.6), 1e-4,
                  "the soft mode (omega h = 0.01) follows cos t: HHT damping "
                  "~ alpha (omega h)^3 is invisible there");
        result_free(&res);
    }
}

/* Average acceleration does not damp: from q = 1 at rest the stiff mode is
 * exactly cos(k theta) with theta = 2 atan(omega h / 2). */
static void average_acceleration_should_not_damp_the_stiff_mode(void **state)
{
    (void)state;
    mm_newmark_options o = options(MM_NEWMARK_AVERAGE, 0.01);
    mm_newmark_result res;
    run_two_dof(&o, 60, &res);
    check_rel(pair_modulus(&res, 20, 55), 1.0, 1e-6,
              "|roots| = 1, no numerical damping; round-off 5e-12 per step in y "
              "(q~ and beta h^2 a are 2e4 times y) is magnified 1400 times in D");
    check_abs(res.qd[2 * 60 + 1], cos(60 * 2.0 * atan(150.0)), 1e-9,
              "undamped, rotated by 2 atan(omega h / 2) per step");
    result_free(&res);
}

/* Generalized-alpha with rho_inf = 0 annihilates the highest modes: its
 * three roots at omega h = 300 are below 0.03. */
static void generalized_alpha_with_rho_inf_zero_should_annihilate_the_stiff_mode(void **state)
{
    (void)state;
    mm_newmark_options o = options(MM_NEWMARK_GENERALIZED_ALPHA, 0.01);
    o.rho_inf = 0.0;
    mm_newmark_result res;
    run_two_dof(&o, 10, &res);
    check_abs(res.qd[2 * 10 + 1], 0.0, 1e-8, "roots < 0.03: 10 steps leave < 1e-8 of it");
    check_rel(res.qd[2 * 10], cos(0.1), 1e-4, "the soft mode follows cos t");
    result_free(&res);
}

/* ======================================================================== */
/* Nonlinear: the pendulum                                                   */
/* ======================================================================== */

/* theta'' = -omega0^2 sin(theta): M = 1, K = 0, F = -omega0^2 sin(theta). */
static int pendulum_force(double t, const double *q, const double *qd, double *F,
                          void *params)
{
    (void)t;
    (void)qd;
    double w0 = *(const double *)params;
    F[0] = -w0 * w0 * sin(q[0]);
    return 0;
}

static int pendulum_jacobian(double t, const double *q, const double *qd,
                             double *dFdq, double *dFdqd, void *params)
{
    (void)t;
    (void)qd;
    (void)dFdqd;
    double w0 = *(const double *)params;
    dFdq[0] = -w0 * w0 * cos(q[0]);
    return 0;
}

/* Period T = 4 K(k) / omega0 with k = sin(theta0 / 2), K by the AGM. */
static double pendulum_period(double theta0, double w0)
{
    double k = sin(0.5 * theta0);
    return 4.0 * (M_PI / (2.0 * agm(1.0, sqrt(1.0 - k * k)))) / w0;
}

/* Release from theta0 = 2.5 rad (143 degrees; T is 1.6 times the small-
 * swing period).  The 8th zero crossing is at 15 T / 4.  With h = T/4000,
 * omega h <= 1.6e-3: period error (omega h)^2/12 <= 2e-7; at a crossing
 * theta'' = 0, so linear interpolation adds O(h^3). */
static double pendulum_measured_period(mm_newmark_method method, int with_jacobian,
                                       mm_newmark_result *res)
{
    double w0 = 1.0, theta0 = 2.5, T = pendulum_period(theta0, w0);
    double q0 = theta0;
    mm_newmark_problem p;
    memset(&p, 0, sizeof p);
    p.n = 1;
    double M = 1.0;
    p.M = &M;
    p.force = pendulum_force;
    p.jacobian = with_jacobian ? pendulum_jacobian : NULL;
    p.force_kind = MM_NEWMARK_FORCE_POSITION;
    p.params = &w0;
    p.q0 = &q0;
    p.t_end = 4.0 * T;
    mm_newmark_options o = options(method, T / 4000.0);
    mm_error err;
    int rc = integrate(&p, &o, res, &err);
    if (rc)
        print_error("%s\n", err.msg);
    assert_int_equal(rc, MM_OK);
    return zero_crossing(res, 8) * 4.0 / 15.0;
}

static void average_acceleration_should_find_the_large_amplitude_pendulum_period(void **state)
{
    (void)state;
    mm_newmark_result res;
    double T = pendulum_period(2.5, 1.0);
    check_rel(pendulum_measured_period(MM_NEWMARK_AVERAGE, 1, &res), T, 1e-6,
              "period error (omega h)^2/12 < 2e-7 against 4 K(k)/omega0");
    /* Newton with the exact Jacobian: one or two corrections per step */
    assert_true(res.newton_iters >= res.steps);
    assert_true(res.newton_iters <= 3 * res.steps);
    assert_int_equal(res.jacobian_evals, res.newton_iters + 1); /* +1: omega_max at t0 */
    check_abs(res.energy_error, 0.0, 1e-6,
              "the pendulum's potential enters as trapezoidal work of F: "
              "O((omega h)^2) = 3e-6 times a constant below 1");
    result_free(&res);
}

static void average_acceleration_should_converge_with_a_finite_difference_jacobian(void **state)
{
    (void)state;
    mm_newmark_result res;
    double T = pendulum_period(2.5, 1.0);
    check_rel(pendulum_measured_period(MM_NEWMARK_AVERAGE, 0, &res), T, 1e-6,
              "same period: the Jacobian only steers Newton, the residual decides");
    assert_int_equal(res.jacobian_evals, 0);
    assert_true(res.newton_iters <= 3 * res.steps);
    result_free(&res);
}

static void verlet_should_find_the_large_amplitude_pendulum_period(void **state)
{
    (void)state;
    mm_newmark_result res;
    double T = pendulum_period(2.5, 1.0);
    check_rel(pendulum_measured_period(MM_NEWMARK_VERLET, 1, &res), T, 1e-6,
              "Verlet period error (omega h)^2/24 < 1e-7");
    assert_int_equal(res.newton_iters, 0);
    assert_int_equal(res.force_evals, res.steps + 1);  /* one per step, plus t0 */
    result_free(&res);
}

/* ======================================================================== */
/* Counters and output rows                                                 */
/* ======================================================================== */

static void linear_problem_should_factor_once_and_call_the_force_once_per_step(void **state)
{
    (void)state;
    osc s = {1.0, 2.0, 100.0, 1.0, 8.0};
    double x0 = 0.0, v0 = 0.0;
    mm_newmark_problem p = osc_problem(&s, &x0, &v0, 1.0);
    mm_newmark_options o = options(MM_NEWMARK_HHT, 0.01);
    mm_newmark_result res;
    mm_error err;
    assert_int_equal(integrate(&p, &o, &res, &err), MM_OK);
    assert_int_equal(res.steps, 100);
    assert_int_equal(res.force_evals, 101);     /* t0 and one per step */
    assert_int_equal(res.factorizations, 2);    /* M for a0, then the effective matrix */
    assert_int_equal(res.newton_iters, 0);
    result_free(&res);
}

static void solve_should_store_every_stride_steps_and_the_last(void **state)
{
    (void)state;
    osc s = {1.0, 0.0, 1.0, 0.0, 0.0};
    double x0 = 1.0, v0 = 0.0;
    mm_newmark_problem p = osc_problem(&s, &x0, &v0, 1.0);
    mm_newmark_options o = options(MM_NEWMARK_AVERAGE, 0.1);
    o.stride = 3;
    assert_int_equal(mm_newmark_step_count(&p, &o), 10);
    assert_int_equal(mm_newmark_output_rows(&p, &o), 5);
    mm_newmark_result res;
    mm_error err;
    assert_int_equal(integrate(&p, &o, &res, &err), MM_OK);
    const double want[5] = {0.0, 0.3, 0.6, 0.9, 1.0};
    assert_int_equal(res.rows, 5);
    for (int i = 0; i < 5; i++)
        check_abs(res.t[i], want[i], 1e-14, "t_k = t0 + k h");
    check_abs(res.qdd[0], -1.0, 1e-15, "initial acceleration from M a = F - C v - K q");
    result_free(&res);
}

static void solve_should_spread_requested_points_evenly(void **state)
{
    (void)state;
    osc s = {1.0, 0.0, 1.0, 0.0, 0.0};
    double x0 = 1.0, v0 = 0.0;
    mm_newmark_problem p = osc_problem(&s, &x0, &v0, 10.0);
    mm_newmark_options o = options(MM_NEWMARK_AVERAGE, 0.001);
    o.points = 7;
    assert_int_equal(mm_newmark_step_count(&p, &o), 10000);
    mm_newmark_result res;
    mm_error err;
    assert_int_equal(integrate(&p, &o, &res, &err), MM_OK);
    assert_int_equal(res.rows, 7);
    for (int i = 0; i < 7; i++)   /* 10000/6 steps apart, rounded */
        check_abs(res.t[i], 0.001 * floor(i * 10000.0 / 6.0 + 0.5), 1e-12, "even spread");
    check_abs(res.t[6], 10.0, 1e-12, "h divides the span: the run ends on t_end");
    result_free(&res);
}

/* ======================================================================== */
/* Error paths                                                              */
/* ======================================================================== */

static void check_should_refuse_too_many_steps_before_allocating(void **state)
{
    (void)state;
    osc s = {1.0, 0.0, 1.0, 0.0, 0.0};
    double x0 = 1.0, v0 = 0.0;
    mm_newmark_problem p = osc_problem(&s, &x0, &v0, 1000.0);
    mm_newmark_options o = options(MM_NEWMARK_AVERAGE, 1e-6);   /* 1e9 steps */
    mm_error err;
    mm_error_clear(&err);
    assert_int_equal(mm_newmark_check(&p, &o, &err), MM_ERANGE);
    assert_string_equal(err.param, "h");
    assert_non_null(strstr(err.msg, "limit of 1000000"));
    mm_newmark_result res;      /* solve refuses it too, before any call */
    assert_int_equal(integrate_bare(&p, &o, &res, &err), MM_ERANGE);
    assert_int_equal(res.steps, 0);
    o.h = 1e-300;               /* (t_end - t0)/h overflows to inf */
    assert_int_equal(mm_newmark_check(&p, &o, &err), MM_ERANGE);
}

static void check_should_refuse_bad_sizes_and_values(void **state)
{
    (void)state;
    osc s = {1.0, 0.0, 1.0, 0.0, 0.0};
    double x0 = 1.0, v0 = 0.0;
    mm_newmark_problem p = osc_problem(&s, &x0, &v0, 1.0);
    mm_newmark_options o = options(MM_NEWMARK_AVERAGE, 0.1);
    mm_error err;

    p.n = 0;
    assert_int_equal(mm_newmark_check(&p, &o, &err), MM_ERANGE);
    assert_string_equal(err.param, "n");
    p.n = MM_NEWMARK_MAX_DOF + 1;
    assert_int_equal(mm_newmark_check(&p, &o, &err), MM_ERANGE);
    assert_string_equal(err.param, "n");
    assert_null(mm_newmark_work_alloc(0));
    assert_null(mm_newmark_work_alloc(MM_NEWMARK_MAX_DOF + 1));
    mm_newmark_work_free(NULL);     /* free(NULL)-safe */
    p.n = 1;

    o.h = 0.0;
    assert_int_equal(mm_newmark_check(&p, &o, &err), MM_ERANGE);
    assert_string_equal(err.param, "h");
    o.h = 0.1;
    p.t_end = 0.0;
    assert_int_equal(mm_newmark_check(&p, &o, &err), MM_ERANGE);
    assert_string_equal(err.param, "t_end");
    p.t_end = 1.0;

    double bad = NAN;
    p.K = &bad;
    assert_int_equal(mm_newmark_check(&p, &o, &err), MM_EVALUE);
    assert_string_equal(err.param, "K");
    p.K = &s.k;

    o.method = MM_NEWMARK_HHT;
    o.alpha = -0.5;
    assert_int_equal(mm_newmark_check(&p, &o, &err), MM_ERANGE);
    assert_string_equal(err.param, "alpha");
    o.method = MM_NEWMARK_GENERALIZED_ALPHA;
    o.rho_inf = 1.5;
    assert_int_equal(mm_newmark_check(&p, &o, &err), MM_ERANGE);
    assert_string_equal(err.param, "rho_inf");
    o.method = MM_NEWMARK_BETA_GAMMA;
    o.gamma = 0.4;
    assert_int_equal(mm_newmark_check(&p, &o, &err), MM_ERANGE);
    assert_string_equal(err.param, "gamma");
    o = options(MM_NEWMARK_AVERAGE, 0.1);
    o.points = 1;
    assert_int_equal(mm_newmark_check(&p, &o, &err), MM_ERANGE);
    assert_string_equal(err.param, "points");
}

static void check_should_refuse_a_massless_or_nonsymmetric_mass_matrix(void **state)
{
    (void)state;
    double M1[4] = {1, 0, 0, 0}, M2[4] = {1, 0.5, 0.2, 1};
    mm_newmark_problem p;
    memset(&p, 0, sizeof p);
    p.n = 2; p.M = M1; p.t_end = 1.0;
    mm_newmark_options o = options(MM_NEWMARK_AVERAGE, 0.1);
    mm_error err;
    assert_int_equal(mm_newmark_check(&p, &o, &err), MM_ESINGULAR);
    assert_string_equal(err.param, "M");
    p.M = M2;
    assert_int_equal(mm_newmark_check(&p, &o, &err), MM_EVALUE);
    assert_string_equal(err.param, "M");
}

static void solve_should_report_a_mass_matrix_that_is_not_positive_definite(void **state)
{
    (void)state;
    double M[4] = {1, 2, 2, 1};     /* eigenvalues 3 and -1 */
    mm_newmark_problem p;
    memset(&p, 0, sizeof p);
    p.n = 2; p.M = M; p.t_end = 1.0;
    mm_newmark_options o = options(MM_NEWMARK_AVERAGE, 0.1);
    mm_newmark_result res;
    mm_error err;
    assert_int_equal(mm_newmark_check(&p, &o, &err), MM_OK);  /* needs a factorisation */
    assert_int_equal(integrate(&p, &o, &res, &err), MM_ESINGULAR);
    assert_string_equal(err.param, "M");
    assert_non_null(strstr(err.msg, "positive definite"));
    result_free(&res);
}

static void solve_should_report_a_singular_effective_matrix(void **state)
{
    (void)state;
    double h = 0.1;
    osc s = {1.0, 0.0, -4.0 / (h * h), 0.0, 0.0};   /* M + h^2/4 K = 0 */
    double x0 = 1.0, v0 = 0.0;
    mm_newmark_problem p = osc_problem(&s, &x0, &v0, 1.0);
    mm_newmark_options o = options(MM_NEWMARK_AVERAGE, h);
    mm_newmark_result res;
    mm_error err;
    assert_int_equal(integrate(&p, &o, &res, &err), MM_ESINGULAR);
    assert_string_equal(err.param, "h");
    result_free(&res);
}

/* A stiff cubic spring, q'' = -1e4 q^3 from q = 10, with h = 1: the
 * predictor is far off and three Newton corrections cannot reach it. */
static int cubic_force(double t, const double *q, const double *qd, double *F, void *params)
{
    (void)t;
    (void)qd;
    (void)params;
    F[0] = -1e4 * q[0] * q[0] * q[0];
    return 0;
}

static void solve_should_report_newton_failure_and_ask_for_a_smaller_step(void **state)
{
    (void)state;
    double M = 1.0, q0 = 10.0;
    mm_newmark_problem p;
    memset(&p, 0, sizeof p);
    p.n = 1; p.M = &M; p.force = cubic_force; p.force_kind = MM_NEWMARK_FORCE_POSITION;
    p.q0 = &q0; p.t_end = 10.0;
    mm_newmark_options o = options(MM_NEWMARK_AVERAGE, 1.0);
    o.newton_max_iter = 3;
    mm_newmark_result res;
    mm_error err;
    assert_int_equal(integrate(&p, &o, &res, &err), MM_ENOCONV);
    assert_int_equal(err.code, MM_ENOCONV);
    assert_string_equal(err.param, "h");
    assert_non_null(strstr(err.msg, "reduce the step"));
    assert_int_equal(res.steps, 0);
    assert_int_equal(res.newton_iters, 3);
    result_free(&res);
}

/* The force callback stops the run with its own code at t > 0.5. */
static int stopping_force(double t, const double *q, const double *qd, double *F, void *params)
{
    (void)q;
    (void)qd;
    (void)params;
    F[0] = 0.0;
    return t > 0.5 ? MM_EVALUE : 0;
}

static int nan_force(double t, const double *q, const double *qd, double *F, void *params)
{
    (void)q;
    (void)qd;
    (void)params;
    F[0] = t > 0.5 ? NAN : 0.0;
    return 0;
}

static void solve_should_pass_on_the_force_callback_code_and_refuse_nan(void **state)
{
    (void)state;
    double M = 1.0, K = 1.0, q0 = 1.0;
    mm_newmark_problem p;
    memset(&p, 0, sizeof p);
    p.n = 1; p.M = &M; p.K = &K; p.force = stopping_force;
    p.force_kind = MM_NEWMARK_FORCE_TIME; p.q0 = &q0; p.t_end = 1.0;
    mm_newmark_options o = options(MM_NEWMARK_AVERAGE, 0.1);
    mm_newmark_result res;
    mm_error err;
    assert_int_equal(integrate(&p, &o, &res, &err), MM_EVALUE);
    assert_string_equal(err.param, "force");
    assert_int_equal(res.steps, 5);       /* t = 0.1 ... 0.5 done, t = 0.6 refused */
    assert_int_equal(res.rows, 6);
    result_free(&res);

    p.force = nan_force;
    assert_int_equal(integrate(&p, &o, &res, &err), MM_ENONFINITE);
    assert_string_equal(err.param, "force");
    result_free(&res);
}

static void solve_should_refuse_result_arrays_that_are_too_small(void **state)
{
    (void)state;
    osc s = {1.0, 0.0, 1.0, 0.0, 0.0};
    double x0 = 1.0, v0 = 0.0, t[3], q[3];
    mm_newmark_problem p = osc_problem(&s, &x0, &v0, 1.0);
    mm_newmark_options o = options(MM_NEWMARK_AVERAGE, 0.1);    /* 11 rows */
    mm_newmark_result res;
    memset(&res, 0, sizeof res);
    res.t = t; res.q = q; res.max_rows = 3;
    mm_error err;
    mm_newmark_work *w = mm_newmark_work_alloc(1);
    assert_int_equal(mm_newmark_solve(&p, &o, w, &res, &err), MM_EINTERNAL);
    mm_newmark_work_free(w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(average_acceleration_should_match_free_underdamped_oscillator),
        cmocka_unit_test(average_acceleration_should_match_free_critically_damped_oscillator),
        cmocka_unit_test(average_acceleration_should_match_free_overdamped_oscillator),
        cmocka_unit_test(average_acceleration_should_match_forced_damped_oscillator),
        cmocka_unit_test(average_acceleration_should_follow_undamped_resonance),
        cmocka_unit_test(average_acceleration_should_be_second_order),
        cmocka_unit_test(linear_acceleration_should_be_second_order),
        cmocka_unit_test(central_difference_should_be_second_order),
        cmocka_unit_test(verlet_should_be_second_order_without_damping),
        cmocka_unit_test(verlet_should_drop_to_first_order_with_damping),
        cmocka_unit_test(hht_alpha_should_be_second_order),
        cmocka_unit_test(generalized_alpha_should_be_second_order),
        cmocka_unit_test(hht_with_alpha_zero_should_equal_average_acceleration),
        cmocka_unit_test(average_acceleration_should_stay_bounded_at_ten_periods_per_step),
        cmocka_unit_test(central_difference_should_report_blow_up_past_two_over_omega),
        cmocka_unit_test(central_difference_should_stay_bounded_just_below_the_limit),
        cmocka_unit_test(linear_acceleration_should_report_blow_up_past_its_limit),
        cmocka_unit_test(central_difference_should_estimate_the_limit_of_a_two_dof_system),
        cmocka_unit_test(central_difference_should_find_the_exact_limit_of_a_160_mass_chain),
        cmocka_unit_test(omega_h_limit_should_be_the_textbook_values),
        cmocka_unit_test(spectral_radius_should_match_the_closed_forms),
        cmocka_unit_test(amplification_matrix_should_reproduce_every_scheme),
        cmocka_unit_test(average_acceleration_should_lengthen_the_period_by_omega_h_squared_over_12),
        cmocka_unit_test(verlet_energy_error_should_stay_bounded_over_1e5_periods),
        cmocka_unit_test(average_acceleration_should_conserve_energy_over_1e5_periods),
        cmocka_unit_test(energy_balance_should_be_a_second_order_error_indicator),
        cmocka_unit_test(work_in_q_should_make_the_average_acceleration_balance_exact),
        cmocka_unit_test(energy_balance_should_show_the_numerical_dissipation_of_hht_alpha),
        cmocka_unit_test(energy_balance_should_count_the_work_of_a_nonsymmetric_stiffness),
        cmocka_unit_test(hht_alpha_should_damp_the_stiff_mode_at_its_spectral_radius),
        cmocka_unit_test(average_acceleration_should_not_damp_the_stiff_mode),
        cmocka_unit_test(generalized_alpha_with_rho_inf_zero_should_annihilate_the_stiff_mode),
        cmocka_unit_test(average_acceleration_should_find_the_large_amplitude_pendulum_period),
        cmocka_unit_test(average_acceleration_should_converge_with_a_finite_difference_jacobian),
        cmocka_unit_test(verlet_should_find_the_large_amplitude_pendulum_period),
        cmocka_unit_test(linear_problem_should_factor_once_and_call_the_force_once_per_step),
        cmocka_unit_test(solve_should_store_every_stride_steps_and_the_last),
        cmocka_unit_test(solve_should_spread_requested_points_evenly),
        cmocka_unit_test(check_should_refuse_too_many_steps_before_allocating),
        cmocka_unit_test(check_should_refuse_bad_sizes_and_values),
        cmocka_unit_test(check_should_refuse_a_massless_or_nonsymmetric_mass_matrix),
        cmocka_unit_test(solve_should_report_a_mass_matrix_that_is_not_positive_definite),
        cmocka_unit_test(solve_should_report_a_singular_effective_matrix),
        cmocka_unit_test(solve_should_report_newton_failure_and_ask_for_a_smaller_step),
        cmocka_unit_test(solve_should_pass_on_the_force_callback_code_and_refuse_nan),
        cmocka_unit_test(solve_should_refuse_result_arrays_that_are_too_small),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
