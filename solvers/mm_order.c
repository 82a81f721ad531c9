/* mm_order.c — the tolerance of an observed order of convergence (see mm_order.h). */
#include "mm_order.h"

#include <math.h>

double mm_order_drift_h2(double b, int K)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int k = 0; k < K; k++) {
        double x = -k * M_LN2, y = log1p(-b * ldexp(1.0, -2 * k));
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    return fabs((K * sxy - sx * sy) / (K * sxx - sx * sx));
}

double mm_order_rounding_drift(int K, const double *h, const double *e, double rnd)
{
    double xm = 0, sxx = 0, drift = 0;
    for (int k = 0; k < K; k++)
        xm += log(h[k]) / K;
    for (int k = 0; k < K; k++)
        sxx += (log(h[k]) - xm) * (log(h[k]) - xm);
    for (int k = 0; k < K; k++)
        drift += fabs(log(h[k]) - xm) / sxx * rnd / e[k];
    return drift;
}
