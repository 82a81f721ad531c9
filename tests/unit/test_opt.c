/* test_opt.c — golden-section search against maxima known in closed form. */
#include "mm_test.h"

#include "mm_opt.h"

static int parabola(double x, double *fx, void *p)
{
    (void)p;
    *fx = -(x - 0.3) * (x - 0.3) * 4 + 2;
    return 0;
}

static int resonance(double r, double *fx, void *p)
{
    double z = *(double *)p;
    *fx = 1 / hypot(1 - r * r, 2 * z * r);
    return 0;
}

static int ramp(double x, double *fx, void *p)
{
    (void)p;
    *fx = x;
    return 0;
}

static int stop(double x, double *fx, void *p)
{
    (void)p;
    *fx = x;
    return x > 0.5 ? MM_ENOCONV : 0;
}

static void golden_should_find_a_parabola_vertex(void **state)
{
    (void)state;
    mm_opt_result r;
    assert_int_equal(mm_opt_golden_max(parabola, NULL, -1, 2, 1e-10, 200, &r, NULL), MM_OK);
    /* the bracket holds x* = 0.3; it stops on a bracket of 1e-10 or where
     * f values tie (|x - x*| ~ sqrt(eps) * 0.3 / 2 = 1e-9) */
    check_abs(r.x, 0.3, 1e-8, "vertex");
    check_rel(r.fx, 2, 1e-15, "value at the vertex");
    assert_true(r.evals < 80);                   /* log(3/1e-10)/log(1/0.618) = 50 */
}

static void golden_should_find_the_resonance_peak(void **state)
{
    (void)state;
    double z = 0.1;
    mm_opt_result r;
    assert_int_equal(mm_opt_golden_max(resonance, &z, 0.5, 1.5, 1e-12, 200, &r, NULL), MM_OK);
    /* r_peak = sqrt(1 - 2 zeta^2), |H|max = 1/(2 zeta sqrt(1 - zeta^2)) */
    check_abs(r.x, sqrt(1 - 2 * z * z), 1e-7, "peak position (sqrt(eps) limited)");
    check_rel(r.fx, 1 / (2 * z * sqrt(1 - z * z)), 1e-14, "peak height");
}

static void golden_should_find_a_maximum_at_the_end(void **state)
{
    (void)state;
    mm_opt_result r;
    assert_int_equal(mm_opt_golden_max(ramp, NULL, 0, 1, 1e-9, 200, &r, NULL), MM_OK);
    check_abs(r.x, 1, 2e-9, "the right end");
}

static void golden_should_refuse_bad_arguments_and_pass_on_stops(void **state)
{
    (void)state;
    mm_opt_result r;
    mm_error err;
    assert_int_equal(mm_opt_golden_max(ramp, NULL, 1, 0, 1e-9, 200, &r, &err), MM_EVALUE);
    assert_int_equal(mm_opt_golden_max(ramp, NULL, 0, 1, 0, 200, &r, &err), MM_EVALUE);
    assert_int_equal(mm_opt_golden_max(stop, NULL, 0, 1, 1e-9, 200, &r, &err), MM_ENOCONV);
}


static void golden_should_reach_the_height_of_a_flat_maximum_at_an_end(void **state)
{
    (void)state;
    /* zeta = 1/sqrt 2: |H| = 1/sqrt(1 + r^4) is largest at r = 0 and flat
     * there to fourth order: values within 8 eps of 1 span r < (16 eps)^(1/4)
     * = 8e-4, so the place is known only that well; the height to rounding */
    double z = M_SQRT1_2;
    mm_opt_result r;
    assert_int_equal(mm_opt_golden_max(resonance, &z, 0, 1.5, 1e-12, 200, &r, NULL), MM_OK);
    check_abs(r.x, 0, r.bracket + pow(16 * 2.2204460492503131e-16, 0.25), "peak at r = 0, flat to r^4");
    check_rel(r.fx, 1, 8 * 2.2204460492503131e-16, "height |H(0)| = 1");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(golden_should_find_a_parabola_vertex),
        cmocka_unit_test(golden_should_find_the_resonance_peak),
        cmocka_unit_test(golden_should_find_a_maximum_at_the_end),
        cmocka_unit_test(golden_should_reach_the_height_of_a_flat_maximum_at_an_end),
        cmocka_unit_test(golden_should_refuse_bad_arguments_and_pass_on_stops),
    };
    return cmocka_run_group_tests_name("opt", tests, NULL, NULL);
}
