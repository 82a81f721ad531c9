/* test_polycheck.c — mm_poly_roots_summarize on roots written by hand:
 * the counts follow from the definitions, the sums and products from
 * Vieta's formulas worked out exactly, the backward errors from p(z)
 * computed by hand. */
#include "mm_test.h"

#include <float.h>

#include "mm_polycheck.h"

#define EPS DBL_EPSILON

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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(exact_real_roots_should_meet_vieta_exactly),
        cmocka_unit_test(complex_double_and_zero_roots_should_be_counted),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
