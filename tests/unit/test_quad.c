/* test_quad.c — mm_quad against closed-form integrals: degrees of
 * exactness, the order of the composite rule, error estimates that cover
 * the true error, oscillatory and singular integrands, failures named. */
#include "mm_test.h"

#include <float.h>
#include <string.h>

#include "mm_quad.h"

#define EPS DBL_EPSILON

static int f_pow(double x, double *fx, void *p)
{
    *fx = pow(x, *(const int *)p);
    return 0;
}

static int f_exp(double x, double *fx, void *p)
{
    (void)p;
    *fx = exp(x);
    return 0;
}

static int f_sin_k(double x, double *fx, void *p)
{
    *fx = sin(*(const double *)p * x);
    return 0;
}

static int f_sqrt(double x, double *fx, void *p)
{
    (void)p;
    *fx = sqrt(x);
    return 0;
}

static int f_runge(double x, double *fx, void *p)
{
    (void)p;
    *fx = 1 / (1 + 25 * x * x);
    return 0;
}

static int f_log(double x, double *fx, void *p)
{
    (void)p;
    *fx = log(x);                                    /* NaN for x < 0 */
    return 0;
}

static int f_stop(double x, double *fx, void *p)
{
    (void)p;
    *fx = x;
    return x > 0.5 ? MM_EVALUE : 0;
}

static mm_quad_result gk(mm_quad_fn f, void *p, double a, double b)
{
    mm_quad_options o;
    mm_quad_options_init(&o);
    mm_quad_result r;
    mm_error err;
    assert_int_equal(mm_quad_gk(f, p, a, b, &o, NULL, &r, &err), MM_OK);
    return r;
}

static void gauss_kronrod_should_integrate_polynomials_to_degree_22_exactly(void **state)
{
    (void)state;
    /* K15 is exact for degree <= 3*7 + 1 = 22: x^k over [0, 1] is 1/(k+1) to
     * rounding (a few eps: compensated sums of 8 + pieces) */
    for (int k = 0; k <= 22; k++) {
        mm_quad_result r = gk(f_pow, &k, 0, 1);
        check_rel(r.value, 1.0 / (k + 1), 4 * EPS, "integral of x^k over [0, 1]");
        assert_true(fabs(r.value - 1.0 / (k + 1)) <= r.err);
        assert_true(r.converged);
    }
}

static void gauss_kronrod_should_match_closed_forms_within_its_estimate(void **state)
{
    (void)state;
    /* e^x on [-1, 2]: e^2 - e^-1 */
    mm_quad_result r = gk(f_exp, NULL, -1, 2);
    check_rel(r.value, exp(2) - exp(-1), 4 * EPS, "integral of e^x");
    assert_true(fabs(r.value - (exp(2) - exp(-1))) <= r.err);
    /* Runge's function on [-1, 1]: 2 atan(5) / 5 */
    r = gk(f_runge, NULL, -1, 1);
    check_rel(r.value, 2 * atan(5.0) / 5, 4 * EPS, "Runge's function");
    assert_true(fabs(r.value - 2 * atan(5.0) / 5) <= r.err);
    /* sin(100 x) on [0, 1]: (1 - cos 100) / 100, fifteen oscillations */
    double k = 100;
    r = gk(f_sin_k, &k, 0, 1);
    check_abs(r.value, (1 - cos(100.0)) / 100, 1e-15, "oscillatory");
    assert_true(fabs(r.value - (1 - cos(100.0)) / 100) <= r.err);
    /* sqrt on [0, 1]: 2/3; the end singularity of f' costs pieces, and the
     * estimate still covers the error */
    r = gk(f_sqrt, NULL, 0, 1);
    check_rel(r.value, 2.0 / 3, 1e-12, "sqrt(x), singular derivative at 0");
    assert_true(fabs(r.value - 2.0 / 3) <= r.err);
    /* an odd function over a symmetric interval: 0, found at once thanks to
     * the 8 starting pieces */
    r = gk(f_sin_k, &k, -1, 1);
    check_abs(r.value, 0, 1e-17, "odd integrand");
}

static void the_estimate_should_not_overstate_a_smooth_error_by_orders(void **state)
{
    (void)state;
    /* QUADPACK's |K15 - G7| estimate overstates K15's error by many orders
     * for a smooth f; the estimate reported is the change of one more
     * halving: within a few eps of the integral of |f| here */
    mm_quad_result r = gk(f_exp, NULL, 0, 1);
    assert_true(r.err <= 16 * EPS * r.abs_value);
}

static void running_out_of_pieces_should_say_so(void **state)
{
    (void)state;
    mm_quad_options o;
    mm_quad_options_init(&o);
    o.max_pieces = 8;
    double k = 2000;                                 /* 320 periods on 8 pieces */
    mm_quad_result r;
    assert_int_equal(mm_quad_gk(f_sin_k, &k, 0, 1, &o, NULL, &r, NULL), MM_OK);
    assert_false(r.converged);
    assert_true(fabs(r.value - (1 - cos(2000.0)) / 2000) <= r.err);
}

static void composite_gauss_legendre_should_converge_with_order_ten(void **state)
{
    (void)state;
    /* error of G5 on m panels ~ C h^10: the observed order for sin(10 x) on
     * [0, 1] from m = 4, 8, 16 (errors 1e-5 to 1e-11, far above rounding) */
    double k = 10, exact = (1 - cos(10.0)) / 10, e[3];
    for (int i = 0; i < 3; i++) {
        mm_quad_result r;
        int m = 4 << i;
        assert_int_equal(mm_quad_gl(f_sin_k, &k, 0, 1, m, m, 0, &r, NULL), MM_OK);
        e[i] = fabs(r.value - exact);
    }
    double p1 = log2(e[0] / e[1]), p2 = log2(e[1] / e[2]);
    check_abs(p1, 10, 0.3, "order of composite 5-point Gauss (m = 4 -> 8)");
    check_abs(p2, 10, 0.3, "order (m = 8 -> 16)");
    exact = exp(1) - 1;
    mm_quad_result r;
    assert_int_equal(mm_quad_gl(f_exp, NULL, 0, 1, 1, 1024, 1e-14, &r, NULL), MM_OK);
    assert_true(r.converged);
    check_rel(r.value, exact, 4 * EPS, "converged composite Gauss");
    assert_true(fabs(r.value - exact) <= r.err);
}

static int f_sin_over_1px2(double x, double *fx, void *p)
{
    (void)p;
    *fx = sin(x) / (x * x + 1);
    return 0;
}

static void the_gauss_estimate_should_not_rest_on_panels_cancelling(void **state)
{
    (void)state;
    /* odd f, a mesh point 0.074 from 0 on 1024 panels: the two panels there
     * err by +-1.23e-7 and cancel to 3e-12, while on 2048 panels the one
     * across 0 errs by 2.5e-10; |G_2048 - G_1024| (2.22e-10) fell short of
     * that error (2.25e-10).  Summed panel by panel it is 2.5e-7.  mpmath
     * quad, split at the multiples of pi: 0.00152629195254315552216996946727 */
    mm_quad_result r;
    assert_int_equal(mm_quad_gl(f_sin_over_1px2, NULL, -24.91236337002283, 917.1070996834376, 512, 2048, 1e-11, &r,
                                NULL), MM_OK);
    assert_int_equal(r.pieces, 2048);
    assert_false(r.converged);
    double e = fabs(r.value - 0.00152629195254315552);
    assert_true(e > 1e-10);                          /* the case: G_2048 is off */
    assert_true(e <= r.err);
}

/* num-plot's defaults: sin(x)/(x^2+1) on [-5, 5], 0 by oddness.  The
 * mesh converges at 128 panels; r.err, the change from 64 panels (8.2e-15),
 * is the 64-panel mesh's error and 2,800 times that of the 128-panel value
 * (2.9e-18), which num-plot's check took as the latter's.  The change from
 * 32 to 64 panels was 1.1e-11: rate 7.3e-4 (2^-10 is 9.8e-4), so the
 * halvings to come change the value by about 6e-18, below the rounding
 * floor (4 eps of the integral of |f|, 1.4e-15, and the nodes'). */
static void the_gauss_error_of_the_value_itself_should_follow_the_observed_rate(void **state)
{
    (void)state;
    mm_quad_result r;
    assert_int_equal(mm_quad_gl(f_sin_over_1px2, NULL, -5, 5, 32, 2048, 1.568e-11, &r, NULL), MM_OK);
    assert_true(r.converged);
    assert_int_equal(r.pieces, 128);
    assert_true(r.err > 5e-15);                      /* the 64-panel mesh's error */
    assert_true(fabs(r.value) <= r.err_value);
    assert_true(r.err_value < 2e-15);                /* the rounding floor, no more */
    assert_true(r.err_value > 4 * EPS * r.abs_value);
    /* converged on e^x: the rate's estimate still covers the error */
    assert_int_equal(mm_quad_gl(f_exp, NULL, 0, 1, 1, 1024, 1e-14, &r, NULL), MM_OK);
    assert_true(fabs(r.value - (exp(1) - 1)) <= r.err_value);
    /* not converged (the panels-cancelling case above): the last change */
    assert_int_equal(mm_quad_gl(f_sin_over_1px2, NULL, -24.91236337002283, 917.1070996834376, 512, 2048, 1e-11, &r,
                                NULL), MM_OK);
    assert_false(r.converged);
    assert_true(r.err_value == r.err);
}

static void non_finite_values_and_bad_arguments_should_be_named(void **state)
{
    (void)state;
    mm_quad_options o;
    mm_quad_options_init(&o);
    mm_quad_result r;
    mm_error err;
    assert_int_equal(mm_quad_gk(f_log, NULL, -1, 1, &o, NULL, &r, &err), MM_ENONFINITE);
    assert_string_equal(err.param, "f");
    assert_int_equal(mm_quad_gl(f_log, NULL, -1, 1, 2, 8, 0, &r, &err), MM_ENONFINITE);
    assert_int_equal(mm_quad_gk(f_stop, NULL, 0, 1, &o, NULL, &r, &err), MM_EVALUE);   /* f's own code */
    assert_int_equal(mm_quad_gk(f_exp, NULL, 1, 1, &o, NULL, &r, &err), MM_EVALUE);
    assert_string_equal(err.param, "b");
    assert_int_equal(mm_quad_gk(f_exp, NULL, NAN, 1, &o, NULL, &r, &err), MM_EVALUE);
    assert_string_equal(err.param, "a");
    o.max_pieces = MM_QUAD_MAX_PIECES + 1;
    assert_int_equal(mm_quad_gk(f_exp, NULL, 0, 1, &o, NULL, &r, &err), MM_EVALUE);
    assert_string_equal(err.param, "max_pieces");
    mm_quad_options_init(&o);
    o.rtol = 0;
    assert_int_equal(mm_quad_check(0, 1, &o, &err), MM_EVALUE);
    assert_string_equal(err.param, "atol");
    assert_int_equal(mm_quad_gl(f_exp, NULL, 0, 1, 4, 2, 0, &r, &err), MM_EVALUE);
}

static void the_partition_should_cover_the_interval(void **state)
{
    (void)state;
    mm_quad_options o;
    mm_quad_options_init(&o);
    mm_quad_piece p[400];
    mm_quad_result r;
    double k = 50;
    assert_int_equal(mm_quad_gk(f_sin_k, &k, -2, 3, &o, p, &r, NULL), MM_OK);
    double len = 0, sum = 0;
    for (int i = 0; i < r.pieces; i++) {
        assert_true(p[i].a >= -2 && p[i].b <= 3 && p[i].a < p[i].b);
        len += p[i].b - p[i].a;
        sum += p[i].value;
    }
    check_rel(len, 5, 4 * EPS, "the pieces cover [a, b] once");
    check_abs(sum, r.value, r.err, "the pieces' values add up to the integral");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(gauss_kronrod_should_integrate_polynomials_to_degree_22_exactly),
        cmocka_unit_test(gauss_kronrod_should_match_closed_forms_within_its_estimate),
        cmocka_unit_test(the_estimate_should_not_overstate_a_smooth_error_by_orders),
        cmocka_unit_test(running_out_of_pieces_should_say_so),
        cmocka_unit_test(composite_gauss_legendre_should_converge_with_order_ten),
        cmocka_unit_test(the_gauss_estimate_should_not_rest_on_panels_cancelling),
        cmocka_unit_test(the_gauss_error_of_the_value_itself_should_follow_the_observed_rate),
        cmocka_unit_test(non_finite_values_and_bad_arguments_should_be_named),
        cmocka_unit_test(the_partition_should_cover_the_interval),
    };
    return cmocka_run_group_tests_name("mm_quad", tests, NULL, NULL);
}
