/* test_roots_first.c — mm_roots_first: the first root met on a grid, against
 * functions whose roots are known: cos x from 0 (pi/2, not 3 pi/2), a root
 * on a grid point returned as it is, none in range (NAN), the start moved
 * past a root, and the evaluations counted. */
#include "mm_test.h"

#include <float.h>

#include "mm_roots.h"

static int cosine(double x, double *fx, void *params)
{
    (void)params;
    *fx = cos(x);
    return 0;
}

static int line(double x, double *fx, void *params)
{
    *fx = x - *(const double *)params;
    return 0;
}

static void first_root_should_be_the_first_sign_change(void **state)
{
    (void)state;
    double x;
    int it;
    long ev = 0;
    mm_error err;
    assert_int_equal(mm_roots_first(cosine, NULL, 0.25, 0, 64, 1e-13, 200, &x, &it, &ev, &err), MM_OK);
    check_abs(x, M_PI / 2, 2e-13, "cos: pi/2, Brent to 1e-13");
    assert_true(it > 0);
    assert_true(ev == 8 + it);                      /* 0 .. 1.75 scanned, then one a Brent iteration */
    /* from i0 = 7 (x = 1.75) on, the next one: 3 pi / 2 */
    assert_int_equal(mm_roots_first(cosine, NULL, 0.25, 7, 64, 1e-13, 200, &x, NULL, NULL, &err), MM_OK);
    check_abs(x, 1.5 * M_PI, 2e-13, "cos from 1.75: 3 pi/2");
}

static void a_root_on_the_grid_should_be_returned_as_it_is(void **state)
{
    (void)state;
    double at = 0.75, x;
    int it = -1;
    long ev = 10;
    mm_error err;
    assert_int_equal(mm_roots_first(line, &at, 0.25, 0, 64, 1e-13, 200, &x, &it, &ev, &err), MM_OK);
    assert_true(x == 0.75 && it == 0 && ev == 10 + 4);   /* 0, 0.25, 0.5, 0.75 */
    at = 100;                                            /* beyond 64 steps of 0.25 */
    assert_int_equal(mm_roots_first(line, &at, 0.25, 0, 64, 1e-13, 200, &x, &it, NULL, &err), MM_OK);
    assert_true(isnan(x));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(first_root_should_be_the_first_sign_change),
        cmocka_unit_test(a_root_on_the_grid_should_be_returned_as_it_is),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
