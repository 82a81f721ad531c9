/* test_rational.c — mm_rational_approx against known fractions and known
 * convergents: typed ratios found exactly, irrational numbers refused at
 * a few eps with q <= 1000, pi's convergent 355/113 at a looser tolerance. */
#include "mm_test.h"

#include <float.h>

#include "mm_rational.h"

#define TIGHT (4 * DBL_EPSILON)

static void typed_ratios_should_be_found(void **state)
{
    (void)state;
    long p = 0, q = 0;
    assert_int_equal(mm_rational_approx(10.0 / 11.0, 1000, TIGHT, &p, &q), 1);
    assert_true(p == 10 && q == 11);
    assert_int_equal(mm_rational_approx(0.1 / 0.3, 1000, TIGHT, &p, &q), 1);   /* not 1/3 exactly in binary */
    assert_true(p == 1 && q == 3);
    assert_int_equal(mm_rational_approx(617.0 / 991.0, 1000, TIGHT, &p, &q), 1);
    assert_true(p == 617 && q == 991);
    assert_int_equal(mm_rational_approx(7.0, 1000, TIGHT, &p, &q), 1);
    assert_true(p == 7 && q == 1);
}

static void irrationals_and_near_ones_should_be_refused(void **state)
{
    (void)state;
    long p = -1, q = -1;
    assert_int_equal(mm_rational_approx(sqrt(2.0), 1000, TIGHT, &p, &q), 0);    /* ... 1393/985, 3363/2378 */
    assert_int_equal(mm_rational_approx(M_PI, 1000, TIGHT, &p, &q), 0);
    assert_int_equal(mm_rational_approx(1 / 1.0000000001, 1000, TIGHT, &p, &q), 0);
    assert_int_equal(mm_rational_approx(617.0 / 991.0, 990, TIGHT, &p, &q), 0);  /* q over the limit */
    assert_true(p == -1 && q == -1);                                            /* left alone */
}

static void a_loose_tolerance_should_stop_at_a_convergent(void **state)
{
    (void)state;
    long p, q;
    /* pi: 3, 22/7 (1.3e-3 off), 333/106 (8.3e-5), 355/113 (2.7e-7) */
    assert_int_equal(mm_rational_approx(M_PI, 1000, 1e-6, &p, &q), 1);
    assert_true(p == 355 && q == 113);
    assert_int_equal(mm_rational_approx(M_PI, 1000, 1e-3, &p, &q), 1);
    assert_true(p == 22 && q == 7);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(typed_ratios_should_be_found),
        cmocka_unit_test(irrationals_and_near_ones_should_be_refused),
        cmocka_unit_test(a_loose_tolerance_should_stop_at_a_convergent),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
