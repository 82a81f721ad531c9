/* test_dd.c — mm_dd: double-double arithmetic and complex numbers with a
 * running error bound, against exact answers (integers, exact rationals)
 * and long double. */
#include "mm_test.h"

#include <float.h>

#include "mm_dd.h"

#define EPS DBL_EPSILON

static void products_and_sums_should_be_exact(void **state)
{
    (void)state;
    /* (1 + 2^-30)^2 = 1 + 2^-29 + 2^-60: hi + lo holds it exactly */
    double a = 1 + ldexp(1, -30);
    mm_dd p = mm_dd_two_prod(a, a);
    check_abs(p.hi, 1 + ldexp(1, -29), 0, "hi");
    check_abs(p.lo, ldexp(1, -60), 0, "lo: the part a double drops");
    mm_dd s = mm_dd_two_sum(1, 1e-20);
    check_abs(s.hi, 1, 0, "1 + 1e-20: hi");
    check_abs(s.lo, 1e-20, 0, "the small term kept in lo");
    /* 1/3 * 3 = 1 to 32 digits; sqrt(2)^2 = 2 */
    mm_dd third = mm_dd_div(mm_dd_from(1), mm_dd_from(3)), back = mm_dd_mul_d(third, 3);
    assert_true(fabs(back.hi - 1 + back.lo) <= 4 * MM_DD_EPS);
    mm_dd r = mm_dd_sqrt(mm_dd_from(2)), sq = mm_dd_mul(r, r);
    assert_true(fabs(sq.hi - 2 + sq.lo) <= 8 * MM_DD_EPS);
    /* against long double (64-bit mantissa) for 1/7: the dd value is closer */
    long double q = 1.0L / 7;
    mm_dd d = mm_dd_div(mm_dd_from(1), mm_dd_from(7));
    assert_true(fabsl((long double)d.hi + d.lo - q) <= 2 * LDBL_EPSILON * q);
}

static void complex_operations_should_be_exact_where_the_answer_is(void **state)
{
    (void)state;
    mm_cdd z = mm_cdd_pow(mm_cdd_exact(1, 1), 8);        /* (1+i)^8 = 16 */
    check_abs(mm_dd_val(z.re), 16, 0, "(1+i)^8");
    check_abs(mm_dd_val(z.im), 0, 0, "real");
    /* (3+4i)/(1+2i) = 11/5 - 2/5 i, within the running bound */
    z = mm_cdd_div(mm_cdd_exact(3, 4), mm_cdd_exact(1, 2));
    assert_true(fabs(mm_dd_val(z.re) - 2.2) <= z.err + EPS * 2.2);
    assert_true(fabs(mm_dd_val(z.im) + 0.4) <= z.err + EPS * 0.4);
    assert_true(z.err < 1e-29);                          /* ~30 digits, far below a double's rounding */
    /* roots on the axes are exact: sqrt(-1) = i, (-4)^(1/4) = 1 + i, 8^(1/3) = 2 */
    z = mm_cdd_root(mm_cdd_exact(-1, 0), 1, M_PI, 2, 0);
    check_abs(mm_dd_val(z.re), 0, 0, "Re sqrt(-1)");
    check_abs(mm_dd_val(z.im), 1, 0, "Im sqrt(-1)");
    z = mm_cdd_root(mm_cdd_exact(-4, 0), 4, M_PI, 4, 0);
    check_abs(mm_dd_val(z.re), 1, 0, "Re (-4)^(1/4)");
    check_abs(mm_dd_val(z.im), 1, 0, "Im (-4)^(1/4)");
    z = mm_cdd_root(mm_cdd_exact(8, 0), 8, 0, 3, 1);      /* the second cube root: 2 e^(2 pi i / 3) */
    check_rel(mm_dd_val(z.re), -1, EPS, "Re");
    check_rel(mm_dd_val(z.im), sqrt(3), EPS, "Im");
    assert_true(fabs(mm_dd_val(z.im) - sqrt(3)) <= z.err + EPS * sqrt(3));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(products_and_sums_should_be_exact),
        cmocka_unit_test(complex_operations_should_be_exact_where_the_answer_is),
    };
    return cmocka_run_group_tests_name("mm_dd", tests, NULL, NULL);
}
