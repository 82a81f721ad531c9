/* mm_special.h — special functions not in libm (chapter 5, vib-fourier-series:
 * the Gibbs overshoot is Si(pi) / pi - 1/2).  Pure functions, thread-safe.
 */
#ifndef MM_SPECIAL_H
#define MM_SPECIAL_H

/* The sine integral Si(x) = int_0^x sin(u)/u du for |x| <= 4, by its power
 * series sum_n (-1)^n x^(2n+1) / ((2n+1) (2n+1)!), 30 terms (they fall
 * like x^(2n)/(2n+1)!: at |x| = 4 far past double precision).  Cannot
 * fail; outside |x| <= 4 the series loses digits to cancellation. */
double mm_special_si(double x);

#endif
