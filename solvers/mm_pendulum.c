/* mm_pendulum.c — the pendulum's period against its amplitude (see
 * mm_pendulum.h). */
#include "mm_pendulum.h"

#include <float.h>
#include <math.h>

#include "mm_elliptic.h"
#include "mm_roots.h"

double mm_pendulum_period_ratio(double theta0) { return 2 * mm_elliptic_Kc(cos(0.5 * theta0)) / M_PI; }

static int ratio_minus(double th, double *f, void *ctx)
{
    *f = 2 * mm_elliptic_Kc(cos(0.5 * th)) / M_PI - *(const double *)ctx;
    return 0;
}

int mm_pendulum_amplitude(double ratio, double a, double b, double *theta0, double *err, mm_error *e)
{
    double fa, fb, fx, width;
    ratio_minus(a, &fa, &ratio);
    ratio_minus(b, &fb, &ratio);
    int iter = 0;
    int rc = mm_roots_brent(ratio_minus, &ratio, a, b, fa, fb, 1e-16, 200, theta0, &fx, &width, &iter, NULL, e);
    if (rc != MM_OK)
        return rc;
    /* the root of the computed function lies in the final bracket; the
     * computed function is within 4 eps of the true one, which moves the
     * root by 4 eps / slope (slope ~ theta/8 = 0.05 at a ratio of 1.01) */
    double h = 1e-4, fp, fm;
    ratio_minus(*theta0 + h, &fp, &ratio);
    ratio_minus(*theta0 - h, &fm, &ratio);
    double slope = (fp - fm) / (2 * h);
    *err = width + 4 * DBL_EPSILON * ratio / (0.5 * slope);
    return MM_OK;
}

double mm_pendulum_ratio_series(double theta0, double *next)
{
    double x2 = theta0 * theta0;
    *next = 1319183.0 / 951268147200 * x2 * x2 * x2 * x2 * x2;
    return 1 + x2 * (1.0 / 16 + x2 * (11.0 / 3072 + x2 * (173.0 / 737280 + x2 * 22931.0 / 1321205760)));
}
