/* test_quad_moments.c — mm_quad_moments against a Gaussian density, whose
 * centroid mu and r.m.s. width sigma are known: sampled over +-12 sigma on
 * an even grid, the trapezoidal rule is exact to rounding for it (its
 * error falls like exp(-2 pi^2 sigma^2 / h^2)); the spacing and the
 * density's scale cancel. */
#include "mm_test.h"

#include <float.h>

#include "mm_quad.h"

static void moments_should_be_the_gaussians(void **state)
{
    (void)state;
    enum { N = 801 };
    double x[N], p[N], c, w;
    static const double mu[3] = {0.3, -41, 1e3}, sg[3] = {0.05, 2, 7.5}, scale[3] = {1, 1e-150, 1e150};
    for (int k = 0; k < 3; k++) {
        for (int i = 0; i < N; i++) {
            x[i] = mu[k] + sg[k] * (-12 + 24.0 * i / (N - 1));
            double u = (x[i] - mu[k]) / sg[k];
            p[i] = scale[k] * exp(-0.5 * u * u);
        }
        mm_quad_moments(x, p, N, &c, &w);
        /* sums of positive terms: a few eps of the largest |x| for the centroid
         * (measured: half of this bound), a few eps relative for the width
         * (measured: 3 eps) */
        check_abs(c, mu[k], 8 * DBL_EPSILON * (fabs(mu[k]) + 12 * sg[k]), "centroid");
        check_rel(w, sg[k], 16 * DBL_EPSILON, "r.m.s. width");
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(moments_should_be_the_gaussians),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
