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

/* A sharp resonance, zeta = 0.0305 (Q = 16): golden section on [0, 1.5]
 * reaches interior points 6.6e-9 apart either side of the peak whose values
 * are equal by symmetry, though 5.8e-15 (26 eps) relative below the top
 * (f''/f = -r_p^2 / (zeta^2 (1 - zeta^2)) = -1100: a drop f'' dx^2 / 2 at
 * dx = 3.3e-9).  Guards the search's stop on equal values: it stopped
 * there, 1.65 times outside rounding; the midpoint is higher, so it must
 * go on and reach the height to rounding; the top is flat to 8 eps within
 * zeta sqrt(16 eps) / r_p <= 2.2e-9 of it, where the place is not known
 * better. */
static void golden_should_reach_the_height_of_a_sharp_peak(void **state)
{
    (void)state;
    static const double zs[3] = {0.030513960499703025, 0.030260945414241236, 0.03543807962139439};
    for (int k = 0; k < 3; k++) {
        double z = zs[k];
        mm_opt_result r;
        assert_int_equal(mm_opt_golden_max(resonance, &z, 0, 1.5, 1e-12, 200, &r, NULL), MM_OK);
        check_rel(r.fx, 1 / (2 * z * sqrt(1 - z * z)), 8 * 2.2204460492503131e-16, "height of a sharp peak");
        check_abs(r.x, sqrt(1 - 2 * z * z), r.bracket + 2.2e-9, "within the bracket or the flat top");
        assert_true(r.evals < 60);
    }
}

/* ---- refining a sampled extreme ---- */

static double sine(double x, double *err, void *p)
{
    (void)p;
    if (err)
        *err = 0;                           /* the routine takes an ulp at least */
    return sin(x);
}

static double line(double x, double *err, void *p)
{
    (void)p;
    if (err)
        *err = 0;
    return 2 * x + 1;
}

/* sin peaks at pi/2 with f'' = -1: rounding (an ulp, 1.1e-16) hides the peak
 * within sqrt(4 * 1.1e-16) = 2.1e-8, so the stated x error must cover the
 * actual one and be no looser than that band (x 100, the checks' rule). */
static void refined_extreme_should_hold_pi_over_2_within_its_stated_error(void **state)
{
    (void)state;
    mm_opt_extreme q;
    mm_opt_refine_extreme(sine, NULL, 1, 1.4, 0.3, 0, 3, &q);
    assert_true(fabs(q.x - M_PI / 2) <= q.x_err);
    assert_true(q.x_err <= 100 * sqrt(4 * 1.1102230246251565e-16) + 1e-12);
    assert_true(fabs(q.fx - 1) <= q.fx_err + 1.2e-16);
    /* the smallest value: -1 at 3 pi / 2 */
    mm_opt_refine_extreme(sine, NULL, -1, 4.9, 0.5, 0, 7, &q);
    assert_true(fabs(q.x - 3 * M_PI / 2) <= q.x_err);
    assert_true(fabs(q.fx + 1) <= q.fx_err + 1.2e-16);
}

/* 2x + 1 on [0, 1]: the largest value at the end, x = 1.  With f'' = 0 no
 * band can be estimated, and the stated x error is the final window, one
 * step of the finer scan (2 h / 32): not tight, but a bound. */
static void refined_extreme_at_an_end_should_be_the_end(void **state)
{
    (void)state;
    mm_opt_extreme q;
    mm_opt_refine_extreme(line, NULL, 1, 0.95, 0.1, 0, 1, &q);
    assert_true(fabs(q.x - 1) <= q.x_err);
    assert_true(q.x_err <= 2 * 0.1 / 32 * (1 + 1e-12));
    assert_true(fabs(q.fx - 3) <= q.fx_err + 4.5e-16);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(golden_should_find_a_parabola_vertex),
        cmocka_unit_test(golden_should_find_the_resonance_peak),
        cmocka_unit_test(golden_should_find_a_maximum_at_the_end),
        cmocka_unit_test(golden_should_reach_the_height_of_a_flat_maximum_at_an_end),
        cmocka_unit_test(golden_should_reach_the_height_of_a_sharp_peak),
        cmocka_unit_test(golden_should_refuse_bad_arguments_and_pass_on_stops),
        cmocka_unit_test(refined_extreme_should_hold_pi_over_2_within_its_stated_error),
        cmocka_unit_test(refined_extreme_at_an_end_should_be_the_end),
    };
    return cmocka_run_group_tests_name("opt", tests, NULL, NULL);
}
