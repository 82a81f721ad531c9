/* mm_complex.h — x + iy as a double complex, exactly.
 *
 * C11's CMPLX is not there under every compiler (clang 14 with glibc lacks
 * it), and writing x + I*y turns an infinite x or y into NaN through 0*inf.
 * C11 6.2.5 lays a double complex out as double[2]: set the two parts.
 */
#ifndef MM_COMPLEX_H
#define MM_COMPLEX_H

#include <complex.h>

static inline double complex mm_cmplx(double x, double y)
{
    double complex z;
    double *p = (double *)&z;
    p[0] = x;
    p[1] = y;
    return z;
}

#endif
