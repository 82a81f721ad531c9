/* mm_special.c — special functions (see mm_special.h). */
#include "mm_special.h"

double mm_special_si(double x)
{
    double term = x, sum = 0;                      /* term = (-1)^n x^(2n+1)/(2n+1)! */
    for (int n = 0; n < 30; n++) {
        sum += term / (2 * n + 1);
        term *= -x * x / ((2 * n + 2) * (2 * n + 3));
    }
    return sum;
}
