/* mm_rational.c — continued fractions (see mm_rational.h). */
#include "mm_rational.h"

#include <math.h>

int mm_rational_approx(double r, long max_q, double rtol, long *p, long *q)
{
    long h0 = 0, h1 = 1, k0 = 1, k1 = 0;
    double x = r;
    for (int i = 0; i < 40; i++) {
        double a = floor(x);
        long h2 = (long)a * h1 + h0, k2 = (long)a * k1 + k0;
        if (k2 > max_q)
            return 0;
        h0 = h1;
        h1 = h2;
        k0 = k1;
        k1 = k2;
        if (fabs((double)h1 / (double)k1 - r) <= rtol * r) {
            *p = h1;
            *q = k1;
            return 1;
        }
        if (x - a < 1e-15)
            return 0;
        x = 1 / (x - a);
    }
    return 0;
}
