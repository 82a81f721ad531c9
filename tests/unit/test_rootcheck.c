/* test_rootcheck.c — mm_rootcheck on functions whose roots are known in
 * closed form: sqrt 2, the ends of x (x - 1/2) (x - 1), three roots in one
 * part that bisection and the given root resolve differently. */
#include "mm_test.h"

#include <float.h>

#include "mm_rootcheck.h"

static int cubic(double x, double *fx, void *ctx)               /* roots 0.1, 0.2, 0.3 */
{
    (void)ctx;
    *fx = (x - 0.1) * (x - 0.2) * (x - 0.3);
    return 0;
}

static int ends_cubic(double x, double *fx, double *err, void *ctx)   /* roots 0, 1/2, 1 */
{
    *fx = x * (x - 0.5) * (x - 1) + *(const double *)ctx;
    *err = 1e-15;
    return 0;
}

static int square_minus_two(double x, double *fx, void *ctx)
{
    (void)ctx;
    *fx = x * x - 2;
    return 0;
}

static int touching(double x, double *fx, void *ctx)             /* a double root at 0.1: no sign change */
{
    (void)ctx;
    *fx = (x - 0.1) * (x - 0.1);
    return 0;
}

static void roots_at_the_ends_should_be_added_in_order(void **state)
{
    (void)state;
    mm_roots_root roots[3] = {{0.5, 0, 1e-12, 5, 0, 1}};
    mm_roots_result rr = {.roots = roots, .cap = 1, .nroots = 1};
    double shift = 0;
    mm_rootcheck_ends(ends_cubic, &shift, 0, 1, &rr);
    assert_int_equal(rr.nroots, 3);
    assert_true(roots[0].x == 0 && roots[1].x == 0.5 && roots[2].x == 1);
    assert_int_equal(roots[0].part, -1);
    assert_int_equal(roots[2].part, -1);
    assert_int_equal(roots[1].part, 1);
    mm_rootcheck_ends(ends_cubic, &shift, 0, 1, &rr);              /* listed already: not again */
    assert_int_equal(rr.nroots, 3);
    /* f shifted by 1e-14, ten times its rounding error: no root at the ends */
    rr.nroots = 1;
    roots[0] = roots[1];
    shift = 1e-14;
    mm_rootcheck_ends(ends_cubic, &shift, 0, 1, &rr);
    assert_int_equal(rr.nroots, 1);
}

static void a_true_root_should_be_confirmed_by_bisection(void **state)
{
    (void)state;
    mm_roots_problem prob = {.f = square_minus_two, .a = 0, .b = 2};
    mm_roots_options opt;
    mm_roots_options_init(&opt);
    opt.n = 4;
    opt.tol = 1e-10;
    mm_roots_root roots[5];
    mm_roots_result rr = {.roots = roots, .cap = 5};
    assert_int_equal(mm_roots_solve(&prob, &opt, &rr, NULL), MM_OK);
    assert_int_equal(rr.nroots, 1);
    check_abs(roots[0].x, sqrt(2.0), 1e-10, "the root against sqrt 2");
    mm_rootcheck k;
    mm_rootcheck_confirm(square_minus_two, NULL, 0, 2, 4, 1e-10, &rr, &k);
    assert_int_equal(k.lost + k.nosign + k.crowded, 0);
    check_abs(k.allowed, 1.25e-10 + 12 * DBL_EPSILON * roots[0].x, 1e-25, "1.25 tol + 12 eps |x|");
    /* both within their brackets of sqrt 2: Brent's tol and bisection's tol / 4 */
    assert_true(k.worst <= 1.25e-10);
}

static void three_roots_in_one_part_should_count_as_crowded(void **state)
{
    (void)state;
    /* [0, 1] in one part; the root given is 0.1, bisection from [0, 1]
     * halves to [0.25, 0.5] (f(0.5) > 0 > f(0.25)) and finds 0.3 */
    mm_roots_root roots[1] = {{0.1, 0, 1e-12, 5, 0, 0}};
    mm_roots_result rr = {.roots = roots, .cap = 1, .nroots = 1};
    mm_rootcheck k;
    mm_rootcheck_confirm(cubic, NULL, 0, 1, 1, 1e-10, &rr, &k);
    assert_int_equal(k.crowded, 1);
    assert_int_equal(k.lost + k.nosign, 0);
    assert_true(k.worst == 0.0);
    /* a double root: no sign change around it, none across its part */
    mm_rootcheck_confirm(touching, NULL, 0, 1, 1, 1e-10, &rr, &k);
    assert_int_equal(k.nosign, 1);
    assert_int_equal(k.lost, 1);
    /* an exact zero or a root found at an end is proven: skipped */
    roots[0].flags = MM_ROOTS_EXACT;
    mm_rootcheck_confirm(touching, NULL, 0, 1, 1, 1e-10, &rr, &k);
    assert_int_equal(k.nosign + k.lost, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(roots_at_the_ends_should_be_added_in_order),
        cmocka_unit_test(a_true_root_should_be_confirmed_by_bisection),
        cmocka_unit_test(three_roots_in_one_part_should_count_as_crowded),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
