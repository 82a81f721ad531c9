/* test_polycheck.c — mm_poly_roots_summarize on roots written by hand:
 * the counts follow from the definitions, the sums and products from
 * Vieta's formulas worked out exactly, the backward errors from p(z)
 * computed by hand. */
#include "mm_test.h"

#include <float.h>

#include "mm_polycheck.h"

#define EPS DBL_EPSILON
#define U (DBL_EPSILON / 2)

/* (x - 1)(x - 2)(x - 3) = x^3 - 6 x^2 + 11 x - 6: exact roots, so the
 * backward error is 0, the sum 6 = -p_1/p_0 and the product 6 = -p_3/p_0 */
static void exact_real_roots_should_meet_vieta_exactly(void **state)
{
    (void)state;
    const double p[] = {1, -6, 11, -6};
    const mm_poly_root r[] = {{3, 0, 1e-15, 1, 1, 0}, {2, 0, 1e-15, 1, 1, 0}, {1, 0, 1e-15, 1, 1, 0}};
    mm_poly_roots_summary s;
    mm_poly_roots_summarize(4, p, r, &s);
    assert_int_equal(s.real, 3);
    assert_int_equal(s.sure_real, 3);
    assert_int_equal(s.multiple + s.illcond + s.zeros, 0);
    assert_true(s.backward == 0.0);                     /* p(1) = p(2) = p(3) = 0 exactly */
    check_abs(s.sum, 6, 0, "1 + 2 + 3, exact in double");
    check_abs(s.sum_ref, 6, 0, "-p_1 / p_0");
    check_rel(s.logprod, log(6.0), 2 * EPS, "log 1 + log 2 + log 3 = log 6");
    check_rel(s.logprod_ref, log(6.0), 2 * EPS, "log |p_3 / p_0|");
    /* the tolerances: the roots' errors plus 4 d eps of the sizes summed */
    check_rel(s.sum_tol, 3e-15 + 12 * EPS * 12, 1e-15, "sum: 3 err + 4 d eps (|z| sum + |sum_ref|)");
    check_rel(s.logprod_tol, 1e-15 * (1 + 0.5 + 1.0 / 3) + 12 * EPS * (1 + log(6.0)), 1e-15,
              "log product: sum err/|z| + 4 d eps (1 + |log product|)");
    check_abs(s.max_err, 1e-15, 0, "the largest err");
}

/* x^2 + 1 = 0 at +-i: complex, far from the axis; x^2 at a double root 0
 * with errors: counted real, not certainly; a zero root skips the product */
static void complex_double_and_zero_roots_should_be_counted(void **state)
{
    (void)state;
    const double p1[] = {1, 0, 1};
    const mm_poly_root r1[] = {{0, 1, 1e-16, 1, 1, 0}, {0, -1, 1e-16, 1, 1, 0}};
    mm_poly_roots_summary s;
    mm_poly_roots_summarize(3, p1, r1, &s);
    assert_int_equal(s.real, 0);
    assert_int_equal(s.sure_real, 0);
    assert_true(s.backward == 0.0);                     /* i^2 + 1 = 0 exactly */
    check_abs(s.sum, 0, 0, "i + (-i) = 0");
    check_abs(s.logprod, 0, 0, "|i| |-i| = 1 = |p_2 / p_0|");

    /* (x - 1)^2 = x^2 - 2x + 1 computed as 1 +- 1e-4 i, a cluster of two:
     * p(1 + 1e-4 i) = -1e-8 (to 1e-16), so the backward error is 1e-8 / (|z|^2 + 2|z| + 1) */
    const double p2[] = {1, -2, 1};
    const mm_poly_root r2[] = {{1, 1e-4, 2e-4, 1, 2, MM_POLY_ROOT_MULTIPLE},
                               {1, -1e-4, 2e-4, 1, 2, MM_POLY_ROOT_MULTIPLE | MM_POLY_ROOT_ILLCOND}};
    mm_poly_roots_summarize(3, p2, r2, &s);
    assert_int_equal(s.real, 2);                        /* |im| <= err: the discs meet the axis */
    assert_int_equal(s.sure_real, 0);                   /* neither computed real and simple */
    assert_int_equal(s.multiple, 2);
    assert_int_equal(s.illcond, 0);                     /* ill-conditioned but multiple: counted as multiple */
    check_abs(s.mult_err, 2e-4, 0, "the cluster's error");
    check_rel(s.backward, 1e-8 / 4, 1e-7, "|p(z)| / sum |p_k| |z|^k at 1 + 1e-4 i (|z| = 1 + 5e-9)");
    check_abs(s.sum, 2, 0, "sum 2 = -p_1/p_0");

    /* x^3 - x: roots 1, 0, -1; the exact zero root leaves the product out */
    const double p3[] = {1, 0, -1, 0};
    const mm_poly_root r3[] = {{1, 0, 0, 0, 1, 0}, {-1, 0, 0, 0, 1, MM_POLY_ROOT_ILLCOND}, {0, 0, 0, 0, 1, 0}};
    mm_poly_roots_summarize(4, p3, r3, &s);
    assert_int_equal(s.zeros, 1);
    assert_int_equal(s.illcond, 1);
    assert_int_equal(s.real, 3);
    assert_true(s.logprod_ref == 0 && s.logprod_tol == 0);
    check_abs(s.sum, 0, 0, "1 - 1 + 0");
}

static void distinct_values_should_be_counted_once(void **state)
{
    (void)state;
    const double x[] = {1, 2, 2, 3, 1, -0.0, 0.0};
    assert_int_equal(mm_poly_distinct(5, x), 3);
    assert_int_equal(mm_poly_distinct(7, x), 4);                /* -0 == 0 */
    assert_int_equal(mm_poly_distinct(0, x), 0);
}

/* 2x + 1 at x = 1, 2 (values 3, 5; the terms |c_k| |x|^k sum to 5 at most) */
static void fit_level_and_horner_deviation_should_match_hand_values(void **state)
{
    (void)state;
    const double x[] = {1, 2}, y[] = {3, -5}, c[] = {2, 1}, ce[] = {0, 0}, fe[] = {0, 0};
    /* (2d + 2) u 5 + (n + d + 1) u max |y| = 20 u + 20 u */
    check_rel(mm_poly_fit_level(2, x, y, 2, c), 40 * U, 1e-15, "the level of a fit in double");
    double fit[] = {3, 5}, rounding, terms;
    assert_true(mm_poly_horner_deviation(2, x, 2, c, ce, fit, fe, &rounding, &terms) == 0.0);
    check_rel(rounding, 15 * U, 1e-15, "(2d + 1) u sum |c_k| |x|^k at x = 2");
    check_abs(terms, 5, 0, "2 * 2 + 1");
    /* a fitted value 1e-10 off: that over 1.01 of the rounding */
    fit[1] = 5 + 0x1p-33;
    check_rel(mm_poly_horner_deviation(2, x, 2, c, ce, fit, fe, &rounding, &terms), 0x1p-33 / (1.01 * 15 * U),
              1e-14, "the deviation in units of Horner's rounding");
}

/* residuals orthogonal to 1 and t at t = -1, 0, 1: (1, -2, 1) */
static void normal_residual_should_vanish_for_orthogonal_residuals(void **state)
{
    (void)state;
    const double x[] = {-1, 0, 1}, r[] = {1, -2, 1}, re[] = {0, 0, 0};
    assert_true(mm_poly_normal_residual(3, x, r, re, 2, 0, 1) == 0.0);
    /* x = 3, 5, 7 about mu = 5, scale 2: t = -1, 0, 1 again, exact */
    const double x2[] = {3, 5, 7};
    assert_true(mm_poly_normal_residual(3, x2, r, re, 3, 5, 2) > 0);    /* t^2: 1 + 1 = 2, not 0 */
    assert_true(mm_poly_normal_residual(3, x2, r, re, 2, 5, 2) == 0.0);
    /* r3 = 1.5: sum r = 0.5 against 1.01 (u + 8 eps_dd) sum |r| = 1.01 (u + 8 eps_dd) 4.5 */
    const double r2[] = {1, -2, 1.5};
    check_rel(mm_poly_normal_residual(3, x, r2, re, 1, 0, 1), 0.5 / (1.01 * 4.5 * (U + 8 * 4.93038065763132e-32)),
              1e-14, "sum r_i over its rounding");
}

/* the book's points (1, 10), (3, 18), (10, 37): slope 196/67, intercept 537/67 */
static void regression_line_should_be_the_exact_fraction(void **state)
{
    (void)state;
    const double x[] = {1, 3, 10}, y[] = {10, 18, 37};
    mm_poly_line l;
    mm_poly_line_fit(3, x, y, &l);
    check_abs(l.mean_y, 65.0 / 3, l.mean_y_err, "mean of y within its bound");
    check_abs(l.slope, 196.0 / 67, l.slope_err, "slope within its bound");
    check_abs(l.intercept, 537.0 / 67, l.intercept_err, "intercept within its bound");
    /* the bounds are rounding: (n + 4) u (sum |terms| / S_xx) = 182 u, and
     * for the intercept (n + 2) u (max |y| + |slope mean(x)|) + that mean(x) = 1102 u */
    assert_true(l.slope_err < 190 * U && l.intercept_err < 1150 * U);
}

/* the same line by the SVD and by the normal equations, in double, against
 * the exact fitted values 196/67 x + 537/67 */
static void two_routes_should_stay_within_their_bounds(void **state)
{
    (void)state;
    const double x[] = {1, 3, 10}, y[] = {10, 18, 37};
    double fit[3], fe[3], work[6], p[2];
    for (int i = 0; i < 3; i++) {
        fit[i] = 196.0 / 67 * x[i] + 537.0 / 67;
        fe[i] = 4 * U * 40;                                    /* the rounding of the fraction */
    }
    mm_poly_fit_info info;
    assert_int_equal(mm_poly_fit(3, x, y, 1, p, &info, NULL), MM_OK);
    mm_poly_fit_routes o;
    assert_int_equal(mm_poly_fit_two_routes(3, x, y, 1, info.mu, info.scale, info.cond, info.rms, fit, fe, work,
                                            &o, NULL), MM_OK);
    assert_true(o.dev_svd <= o.bound_svd && o.dev_ne <= o.bound_ne);
    /* kappa = 1.38 here: g (kappa ||A|| ||b|| + kappa ||r|| + ||y||) = 1.8e-13 by the SVD,
     * 2.3e-13 with kappa^2 */
    assert_true(o.bound_svd < 1.9e-13 && o.bound_ne < 2.4e-13 && o.bound_svd < o.bound_ne);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(exact_real_roots_should_meet_vieta_exactly),
        cmocka_unit_test(complex_double_and_zero_roots_should_be_counted),
        cmocka_unit_test(distinct_values_should_be_counted_once),
        cmocka_unit_test(fit_level_and_horner_deviation_should_match_hand_values),
        cmocka_unit_test(normal_residual_should_vanish_for_orthogonal_residuals),
        cmocka_unit_test(regression_line_should_be_the_exact_fraction),
        cmocka_unit_test(two_routes_should_stay_within_their_bounds),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
