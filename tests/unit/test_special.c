/* test_special.c — mm_special_si, the sine integral, against published
 * values (Abramowitz & Stegun table 5.1; Si(pi), the Wilbraham-Gibbs
 * constant), against composite Simpson quadrature of sin(u)/u, and its
 * oddness. */
#include "mm_test.h"

#include <float.h>

#include "mm_special.h"

#define EPS DBL_EPSILON

/* Composite Simpson on [0, x], 4000 intervals: error ~ x^5 / (180 n^4) max|f''''| ~ 1e-17 */
static double simpson(double x)
{
    enum { N = 4000 };
    double h = x / N, s = 1 + sin(x) / x;
    for (int i = 1; i < N; i++)
        s += (i % 2 ? 4 : 2) * sin(i * h) / (i * h);
    return s * h / 3;
}

static void si_should_match_published_values(void **state)
{
    (void)state;
    check_rel(mm_special_si(M_PI), 1.8519370519824661703610533701579913633, 4 * EPS, "Si(pi)");
    check_rel(mm_special_si(1), 0.9460830703671830149413533138231796578, 4 * EPS, "Si(1)");
    check_rel(mm_special_si(0.5), 0.4931074180430666891616094361890298711, 4 * EPS, "Si(1/2)");
    assert_true(mm_special_si(0) == 0);
}

static void si_should_be_the_integral_and_odd(void **state)
{
    (void)state;
    for (double x = 0.25; x <= 4; x += 0.25) {
        /* both round: the series by its cancellation (e^x / x), Simpson over 4000 terms (measured: 25 eps) */
        check_abs(mm_special_si(x), simpson(x), 64 * EPS, "Si(x) vs Simpson");
        assert_true(mm_special_si(-x) == -mm_special_si(x));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(si_should_match_published_values),
        cmocka_unit_test(si_should_be_the_integral_and_odd),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
