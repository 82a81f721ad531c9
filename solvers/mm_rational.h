/* mm_rational.h — the simplest fraction p/q near a number, by continued
 * fractions (chapter 5, vib-harmonics: is a sum of two harmonics
 * periodic?).  Pure function, thread-safe.
 */
#ifndef MM_RATIONAL_H
#define MM_RATIONAL_H

/* r > 0 as p/q with q <= max_q, to within rtol r: the convergents h/k of
 * r's continued fraction (at most 40 terms) until one is within rtol r of
 * r (then *p = h, *q = k and 1 is returned) or its k passes max_q, or the
 * remainder is below 1e-15 (0 returned: r is no such fraction).  With rtol
 * a few eps, 10/11 and 0.1/0.3 as typed are fractions, 1/1.0000000001 is
 * not (it needs q = 1e10). */
int mm_rational_approx(double r, long max_q, double rtol, long *p, long *q);

#endif
