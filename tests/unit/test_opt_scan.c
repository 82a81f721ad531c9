/* test_opt_scan.c — mm_opt_scan_golden_max against a function whose global
 * maximum is known: two parabolic bumps on disjoint supports, the taller
 * one narrow (top 2 at x = 3) beside a wide one (top 1 at x = 1); the scan
 * must pick the taller, golden sections place it to the tolerance; at the
 * grid's left end the bracket starts at 0. */
#include "mm_test.h"

#include <float.h>

#include "mm_opt.h"

static int bumps(double x, double *fx, void *params)
{
    (void)params;
    double a = 1 - (x - 1) * (x - 1), b = 1 - ((x - 3) / 0.3) * ((x - 3) / 0.3);
    *fx = fmax(a, 0) + 2 * fmax(b, 0);
    return 0;
}

static int falling(double x, double *fx, void *params)
{
    (void)params;
    *fx = -x * x;                    /* largest at the left end, x = 0 */
    return 0;
}

/* rising to the grid's right end x = 5, and not defined past it (as a
 * planned motion is not past its end, or an angle past its period) */
static int rising(double x, double *fx, void *params)
{
    double *past = params;
    if (x > 5)
        *past = fmax(*past, x);
    *fx = x > 5 ? 1e300 : x * x;
    return 0;
}

static void scan_then_golden_should_stay_on_the_grid_and_keep_an_end_sample(void **state)
{
    (void)state;
    mm_opt_result r;
    mm_error err;
    double past = 0;
    assert_int_equal(mm_opt_scan_golden_max(rising, &past, 0.5, 10, 1e-12, 200, &r, &err), MM_OK);
    check_abs(past, 0, 0, "no point past the grid's end was asked for");
    check_abs(r.x, 5, 0, "the end itself (its sample is the largest value)");
    check_abs(r.fx, 25, 0, "f there");
}

static void scan_then_golden_should_find_the_taller_bump(void **state)
{
    (void)state;
    mm_opt_result r;
    mm_error err;
    assert_int_equal(mm_opt_scan_golden_max(bumps, NULL, 0.1, 40, 1e-10, 200, &r, &err), MM_OK);
    /* near the top f = 2 - 2 (dx / 0.3)^2: where that drop is below f's
     * rounding (a few eps of 2) no method can tell the points apart, dx up
     * to 0.3 sqrt(4 eps) = 9e-9 (measured 1.3e-8: 8 eps); the height to
     * that rounding */
    check_abs(r.x, 3, 0.3 * sqrt(16 * DBL_EPSILON), "the narrow bump's top");
    check_abs(r.fx, 2, 16 * DBL_EPSILON, "its height");
    assert_true(fabs(r.x - 3) <= r.bracket);          /* the bracket it reports holds the top */
    assert_int_equal(mm_opt_scan_golden_max(falling, NULL, 0.5, 10, 1e-12, 200, &r, &err), MM_OK);
    check_abs(r.x, 0, sqrt(4 * DBL_EPSILON), "the left end (flat to rounding within sqrt(eps))");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(scan_then_golden_should_find_the_taller_bump),
        cmocka_unit_test(scan_then_golden_should_stay_on_the_grid_and_keep_an_end_sample),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
