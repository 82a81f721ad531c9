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

/* mm_ddb: a cancellation kept to the last bit, and bounds that hold: every
 * corner of the operands' error boxes, divided in double-double, lies in
 * the quotient's box */
static void bounded_operations_should_keep_digits_and_their_bounds_should_hold(void **state)
{
    (void)state;
    /* (1 + 2^-30)^2 - (1 + 2^-29) = 2^-60: in double 0, in mm_ddb exact */
    double a = 1 + ldexp(1, -30);
    mm_ddb c = mm_ddb_sub(mm_ddb_mul(mm_ddb_exact(a), mm_ddb_exact(a)), mm_ddb_exact(1 + ldexp(1, -29)));
    check_abs(a * a - (1 + ldexp(1, -29)), 0, 0, "double loses it all");
    check_abs(mm_dd_val(c.x), ldexp(1, -60), 0, "mm_ddb keeps it");
    assert_true(c.e <= MM_DDB_R * ldexp(1, -60));       /* the product exact (TwoProd), one dd rounding */
    /* 3-4-5 */
    mm_ddb h = mm_ddb_norm(mm_ddb_exact(3), mm_ddb_exact(4));
    assert_true(fabs(mm_dd_val(h.x) - 5) <= h.e && h.e < 1e-29);
    /* a quotient of uncertain operands: 1 +- 1e-20 over 3 +- 2e-20 */
    mm_ddb n = {mm_dd_from(1), 1e-20}, d = {mm_dd_from(3), 2e-20}, q = mm_ddb_quot(n, d);
    for (int i = 0; i < 4; i++) {
        mm_dd ni = mm_dd_add(n.x, mm_dd_from(i & 1 ? n.e : -n.e)), di = mm_dd_add(d.x, mm_dd_from(i & 2 ? d.e : -d.e));
        mm_dd off = mm_dd_sub(mm_dd_div(ni, di), q.x);
        assert_true(mm_dd_abs(off) <= q.e);
        assert_true(mm_dd_abs(off) >= 0.9 * q.e || i == 0 || i == 3);   /* tight at the far corners */
    }
    /* a divisor that may be 0 has no bound */
    assert_true(isinf(mm_ddb_quot(n, (mm_ddb){mm_dd_from(1e-30), 1e-30}).e));
    /* rounding to double: the bound grows by the rounding, the value is the nearest double */
    mm_ddb third = mm_ddb_quot(mm_ddb_exact(1), mm_ddb_exact(3));
    double e, x = mm_ddb_round(third, &e);
    check_abs(x, 1.0 / 3, 0, "1/3 rounded");
    assert_true(e >= 0.999 * fabsl(x - 1.0L / 3) && e <= 0.5 * EPS * x);   /* 1.0L / 3 itself to 1e-20 */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(products_and_sums_should_be_exact),
        cmocka_unit_test(complex_operations_should_be_exact_where_the_answer_is),
        cmocka_unit_test(bounded_operations_should_keep_digits_and_their_bounds_should_hold),
    };
    return cmocka_run_group_tests_name("mm_dd", tests, NULL, NULL);
}
