/* test_symplectic.c — the Gauss–Legendre methods (mm_symplectic): their
 * order of convergence, the quadratic invariants they keep exactly, the
 * area they preserve (symplecticity), the bounded energy error over long
 * runs, and the errors they report. */
#include "mm_test.h"

#include <float.h>
#include <string.h>

#include "mm_symplectic.h"

#define EPS DBL_EPSILON

/* x'' = -w^2 x as (x, v) */
static int oscillator(double t, const double *y, double *dy, void *params)
{
    (void)t;
    double w = *(const double *)params;
    dy[0] = y[1];
    dy[1] = -w * w * y[0];
    return 0;
}

/* the pendulum q'' = -sin q as (q, p): H = p^2/2 - cos q */
static int pendulum(double t, const double *y, double *dy, void *params)
{
    (void)t;
    (void)params;
    dy[0] = y[1];
    dy[1] = -sin(y[0]);
    return 0;
}

static int run(mm_symp_method m, mm_ode_rhs f, void *par, const double *y0, double t_end, double h,
               double *y_end)
{
    mm_symp_problem p = {.n = 2, .f = f, .params = par, .t0 = 0, .t_end = t_end, .y0 = y0};
    mm_symp_options o;
    mm_symp_options_init(&o);
    o.method = m;
    o.h = h;
    mm_symp_work *w = mm_symp_work_alloc(2);
    mm_error err;
    int rc = mm_symp_solve(&p, &o, w, NULL, NULL, y_end, NULL, &err);
    mm_symp_work_free(w);
    return rc;
}

static void methods_should_converge_with_orders_2_and_4(void **state)
{
    (void)state;
    double w = 2, y0[2] = {1, 0};
    for (int m = MM_SYMP_MIDPOINT; m <= MM_SYMP_GAUSS4; m++) {
        double e[4], hs[4] = {0.1, 0.05, 0.025, 0.0125};
        for (int i = 0; i < 4; i++) {
            double y[2];
            assert_int_equal(run(m, oscillator, &w, y0, 3, hs[i], y), MM_OK);
            e[i] = hypot(y[0] - cos(2 * 3), (y[1] + 2 * sin(2 * 3)) / 2);
        }
        int p = mm_symp_order(m);
        for (int i = 0; i < 3; i++) {
            /* halving h divides the error by 2^p; within 0.1 of p in the asymptotic range */
            double slope = log(e[i] / e[i + 1]) / log(2);
            check_abs(slope, p, 0.1, "observed order of convergence");
        }
    }
}

static void quadratic_invariants_should_be_kept_to_round_off(void **state)
{
    (void)state;
    /* Gauss methods conserve every quadratic invariant exactly: the
     * oscillator's energy w^2 x^2 + v^2 over N = 1e5 steps of w h = 0.5
     * moves by round-off only: a random walk of about sqrt(N) eps, far from
     * the N eps of a systematic drift */
    double w = 5, y0[2] = {1, 0};
    for (int m = MM_SYMP_MIDPOINT; m <= MM_SYMP_GAUSS4; m++) {
        double y[2];
        assert_int_equal(run(m, oscillator, &w, y0, 1e4, 0.1, y), MM_OK);
        check_abs(w * w * y[0] * y[0] + y[1] * y[1], w * w, 4 * sqrt(1e5) * EPS * w * w,
                  "energy of the oscillator");
    }
}

static void one_step_map_should_preserve_area(void **state)
{
    (void)state;
    /* a map of the plane is symplectic iff its Jacobian determinant is 1:
     * finite differences of the pendulum's step map, h = 0.3; differences
     * of 1e-6 leave ~1e-10 */
    for (int m = MM_SYMP_MIDPOINT; m <= MM_SYMP_GAUSS4; m++) {
        double y0[2] = {1.2, 0.4}, d = 1e-6, a[2], b[2], c[2], e[2];
        double pq[2] = {y0[0] + d, y0[1]}, mq[2] = {y0[0] - d, y0[1]};
        double pp[2] = {y0[0], y0[1] + d}, mp[2] = {y0[0], y0[1] - d};
        assert_int_equal(run(m, pendulum, NULL, pq, 0.3, 0.3, a), MM_OK);
        assert_int_equal(run(m, pendulum, NULL, mq, 0.3, 0.3, b), MM_OK);
        assert_int_equal(run(m, pendulum, NULL, pp, 0.3, 0.3, c), MM_OK);
        assert_int_equal(run(m, pendulum, NULL, mp, 0.3, 0.3, e), MM_OK);
        double J11 = (a[0] - b[0]) / (2 * d), J21 = (a[1] - b[1]) / (2 * d);
        double J12 = (c[0] - e[0]) / (2 * d), J22 = (c[1] - e[1]) / (2 * d);
        check_abs(J11 * J22 - J12 * J21, 1, 1e-8, "det of the step map's Jacobian = 1");
    }
}

typedef struct drift {
    double E0, first, second;
    long N;
} drift;

static int watch(long step, double t, const double *y, void *params)
{
    (void)t;
    drift *d = params;
    double e = fabs(0.5 * y[1] * y[1] - cos(y[0]) - d->E0);
    if (2 * step <= d->N)
        d->first = fmax(d->first, e);
    else
        d->second = fmax(d->second, e);
    return 0;
}

static void pendulum_energy_error_should_stay_bounded_over_long_runs(void **state)
{
    (void)state;
    /* 2e5 steps of h = 0.1 over ~3000 periods of a wide swing: the error
     * oscillates at O(h^2s) and does not grow: the second half's largest
     * error stays within 10 % of the first half's */
    for (int m = MM_SYMP_MIDPOINT; m <= MM_SYMP_GAUSS4; m++) {
        double y0[2] = {2, 0};
        drift d = {.E0 = -cos(2.0), .N = 200000};
        mm_symp_problem p = {.n = 2, .f = pendulum, .t0 = 0, .t_end = 2e4, .y0 = y0};
        mm_symp_options o;
        mm_symp_options_init(&o);
        o.method = m;
        o.h = 0.1;
        mm_symp_work *w = mm_symp_work_alloc(2);
        mm_symp_result r;
        mm_error err;
        assert_int_equal(mm_symp_solve(&p, &o, w, watch, &d, NULL, &r, &err), MM_OK);
        mm_symp_work_free(w);
        assert_int_equal(r.n_steps, 200000);
        check_abs(d.second, d.first, 0.1 * d.first, "no energy drift: second half vs first half");
        assert_true(d.first < (m == MM_SYMP_MIDPOINT ? 1e-2 : 1e-4));
    }
}

static void bad_requests_should_be_refused_naming_the_field(void **state)
{
    (void)state;
    double w = 1, y0[2] = {1, 0};
    mm_symp_problem p = {.n = 2, .f = oscillator, .params = &w, .t0 = 0, .t_end = 1, .y0 = y0};
    mm_symp_options o;
    mm_symp_options_init(&o);
    mm_error err;
    o.h = 0;
    assert_int_equal(mm_symp_check(&p, &o, &err), MM_ERANGE);
    assert_string_equal(err.param, "h");
    o.h = 1e-9;
    assert_int_equal(mm_symp_check(&p, &o, &err), MM_ERANGE);   /* 1e9 steps */
    assert_string_equal(err.param, "h");
    o.h = 0.1;
    p.t_end = 0;
    assert_int_equal(mm_symp_check(&p, &o, &err), MM_ERANGE);
    assert_string_equal(err.param, "t_end");
    p.t_end = 1;
    p.n = 0;
    assert_int_equal(mm_symp_check(&p, &o, &err), MM_ERANGE);
    assert_string_equal(err.param, "n");
    p.n = 2;
    o.method = 7;
    assert_int_equal(mm_symp_check(&p, &o, &err), MM_ERANGE);
    assert_string_equal(err.param, "method");
    assert_null(mm_symp_work_alloc(0));
    mm_symp_work_free(NULL);
    assert_string_equal(mm_symp_method_name(MM_SYMP_GAUSS4), "gauss-legendre-4");
}

static void a_step_too_large_should_be_reported_not_hidden(void **state)
{
    (void)state;
    /* w h = 1e4: Newton's iteration still solves a linear problem, so take a
     * nonlinear one where the stages cannot be found: the pendulum at h = 50 */
    double y0[2] = {3, 2}, y[2];
    int rc = run(MM_SYMP_GAUSS4, pendulum, NULL, y0, 100, 50, y);
    if (rc != MM_OK)
        assert_int_equal(rc, MM_ENOCONV);
    else
        assert_true(isfinite(y[0]) && isfinite(y[1]));       /* or an honest finite answer */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(methods_should_converge_with_orders_2_and_4),
        cmocka_unit_test(quadratic_invariants_should_be_kept_to_round_off),
        cmocka_unit_test(one_step_map_should_preserve_area),
        cmocka_unit_test(pendulum_energy_error_should_stay_bounded_over_long_runs),
        cmocka_unit_test(bad_requests_should_be_refused_naming_the_field),
        cmocka_unit_test(a_step_too_large_should_be_reported_not_hidden),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
