/* test_order.c — mm_order: the bend of an observed order by the next error
 * term against the two-point slope in closed form and against fitting
 * synthetic errors; the rounding drift against perturbing the errors the
 * worst way. */
#include "mm_test.h"

#include <float.h>

#include "mm_order.h"

#define EPS DBL_EPSILON

/* the least-squares slope of log e against log h, centred (not the
 * functions' own sums) */
static double slope(int K, const double *h, const double *e)
{
    double xm = 0, ym = 0, sxy = 0, sxx = 0;
    for (int k = 0; k < K; k++)
        xm += log(h[k]) / K, ym += log(e[k]) / K;
    for (int k = 0; k < K; k++) {
        sxy += (log(h[k]) - xm) * (log(e[k]) - ym);
        sxx += (log(h[k]) - xm) * (log(h[k]) - xm);
    }
    return sxy / sxx;
}

static void two_levels_should_give_the_two_point_slope(void **state)
{
    (void)state;
    for (double b = 0.01; b < 0.9; b *= 3) {
        /* x = 0, -ln 2; y = log(1 - b), log(1 - b/4) */
        double want = (log1p(-b / 4) - log1p(-b)) / M_LN2;
        check_rel(mm_order_drift_h2(b, 2), want, 16 * EPS, "K = 2: the chord's slope");
    }
}

static void synthetic_errors_should_bend_by_the_drift(void **state)
{
    (void)state;
    /* e = h^2 (1 - b (h/h0)^2) over 6 halvings: observed order 2 - drift;
     * with B > 0 the bend is smaller (the documented worse sign is B < 0) */
    enum { K = 6 };
    double h[K], e[K], ep[K], b = 0.3;
    for (int k = 0; k < K; k++) {
        h[k] = 0.5 * ldexp(1.0, -k);
        e[k] = h[k] * h[k] * (1 - b * ldexp(1.0, -2 * k));
        ep[k] = h[k] * h[k] * (1 + b * ldexp(1.0, -2 * k));
    }
    double d = mm_order_drift_h2(b, K);
    check_abs(slope(K, h, e), 2 - d, 1e-13, "observed order 2 - drift (rounding of 6 logs)");
    assert_true(fabs(slope(K, h, ep) - 2) <= d);
    assert_true(d > 0.01);                                   /* b = 0.3 bends visibly */
}

static void the_worst_rounding_should_move_the_slope_by_the_drift(void **state)
{
    (void)state;
    /* each e_k moved by rnd toward a steeper line: +rnd right of the mean
     * of log h, -rnd left of it; first order in rnd / e_k = 1e-7 */
    enum { K = 5 };
    double h[K], e[K], ew[K], xm = 0, rnd;
    for (int k = 0; k < K; k++)
        h[k] = 0.1 * ldexp(1.0, -k), e[k] = 3 * h[k] * h[k], xm += log(h[k]) / K;
    rnd = 1e-7 * e[K - 1];
    for (int k = 0; k < K; k++)
        ew[k] = e[k] + (log(h[k]) > xm ? rnd : -rnd);
    double d = mm_order_rounding_drift(K, h, e, rnd), moved = slope(K, h, ew) - slope(K, h, e);
    /* second order: (rnd / e)^2 ~ 1e-14 relative to the first-order terms' size */
    check_rel(moved, d, 1e-6, "the worst perturbation moves the slope by the drift, to first order");
    assert_true(d > 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(two_levels_should_give_the_two_point_slope),
        cmocka_unit_test(synthetic_errors_should_bend_by_the_drift),
        cmocka_unit_test(the_worst_rounding_should_move_the_slope_by_the_drift),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
