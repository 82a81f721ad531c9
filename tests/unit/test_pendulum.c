/* test_pendulum.c — mm_pendulum against published values: T / T0 at a
 * quarter turn is 2 K(1/sqrt 2) / pi with K(1/sqrt 2) = Gamma(1/4)^2 /
 * (4 sqrt pi) = 1.854074677301372 (Abramowitz & Stegun 17.3.29); the
 * series' coefficients 1/16, 11/3072 (A&S 17.3.11 squared out); the
 * amplitude of a 1 % longer period by Newton on the series. */
#include "mm_test.h"

#include <float.h>

#include "mm_pendulum.h"

static void period_ratio_should_match_the_lemniscate_value(void **state)
{
    (void)state;
    check_rel(mm_pendulum_period_ratio(M_PI / 2), 2 * 1.854074677301372 / M_PI, 4 * DBL_EPSILON,
              "T/T0 at pi/2");
    check_rel(mm_pendulum_period_ratio(0), 1, DBL_EPSILON, "small swings: T0");
    /* the series to theta^8 within twice its next term, where it converges fast */
    double next, s = mm_pendulum_ratio_series(0.5, &next);
    check_abs(s, mm_pendulum_period_ratio(0.5), 2 * next + 4 * DBL_EPSILON, "series at 0.5");
    assert_true(next > 0 && next < 1e-8);
    check_rel(mm_pendulum_ratio_series(0.01, &next), 1 + 1e-4 / 16 + 11e-8 / 3072, 2 * DBL_EPSILON,
              "the first two terms at 0.01");
}

static void amplitude_of_a_one_percent_longer_period(void **state)
{
    (void)state;
    double th, err;
    assert_int_equal(mm_pendulum_amplitude(1.01, 0.1, 1.0, &th, &err, NULL), MM_OK);
    check_abs(mm_pendulum_period_ratio(th), 1.01, 4 * DBL_EPSILON, "the ratio at the root");
    assert_true(err > 0 && err < 1e-12);             /* 4 eps 1.01 / (slope / 2), slope ~ 0.05 */
    /* Newton on the series (its truncation, 1.4e-10 in the ratio, moves the
     * root by 1.4e-10 / 0.05 = 3e-9) */
    double x = 0.4, next;
    for (int k = 0; k < 20; k++) {
        double h = 1e-6, f = mm_pendulum_ratio_series(x, &next) - 1.01;
        double d = (mm_pendulum_ratio_series(x + h, &next) - mm_pendulum_ratio_series(x - h, &next)) / (2 * h);
        x -= f / d;
    }
    check_abs(th, x, 4e-9, "the amplitude by the series");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(period_ratio_should_match_the_lemniscate_value),
        cmocka_unit_test(amplitude_of_a_one_percent_longer_period),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
