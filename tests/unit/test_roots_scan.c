/* test_roots_scan.c — mm_roots_scan, mm_roots_solve in one call: the
 * roots of sin on [0.5, 10] are pi, 2 pi, 3 pi within the tolerance asked,
 * the result is set up by the call, and the iteration cap given is the one
 * used (a cap of 1 cannot refine a bracket to 1e-12). */
#include "mm_test.h"

#include "mm_roots.h"

static int f_sin(double x, double *fx, void *p)
{
    (void)p;
    *fx = sin(x);
    return 0;
}

static void the_roots_of_sin_should_be_multiples_of_pi(void **state)
{
    (void)state;
    mm_roots_root roots[51];
    mm_roots_result rr = {.nroots = -1, .cap = -5};            /* overwritten by the call */
    mm_error err;
    assert_int_equal(mm_roots_scan(f_sin, NULL, 0.5, 10, 50, 1e-12, 0, roots, &rr, &err), MM_OK);
    assert_int_equal(rr.nroots, 3);
    for (int k = 0; k < 3; k++)
        check_abs(roots[k].x, (k + 1) * M_PI, 1e-12 + 4e-15, "k pi within tol (and rounding of x)");
    assert_true(rr.nevals > 51);
    assert_true(rr.roots == roots && rr.cap == 51 && rr.poles == NULL);
}

static void the_iteration_cap_given_should_be_used(void **state)
{
    (void)state;
    mm_roots_root roots[3];
    mm_roots_result rr;
    mm_error err;
    assert_int_equal(mm_roots_scan(f_sin, NULL, 2, 4, 2, 1e-12, 1, roots, &rr, &err), MM_ENOCONV);
    assert_string_equal(err.param, "max_iter");
    assert_int_equal(mm_roots_scan(f_sin, NULL, 2, 4, 2, 1e-12, 0, roots, &rr, &err), MM_OK);
    check_abs(roots[0].x, M_PI, 1e-12 + 4e-15, "pi with the default cap");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_roots_of_sin_should_be_multiples_of_pi),
        cmocka_unit_test(the_iteration_cap_given_should_be_used),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
