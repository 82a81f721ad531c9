/* mm_order.h — how far an observed order of convergence may honestly stray
 * from the expected one: the two parts of its tolerance.
 *
 * An observed order is the least-squares slope of log e against log h over
 * K levels.  It moves away from the asymptotic order p for two reasons:
 * the next term of the error (e = c h^p (1 + B h^2 + ...)) bends the line,
 * and rounding in the e_k shakes it.  Each function bounds one of them, so
 * that a check of the order can carry a tolerance with a reason instead of
 * a guess (sta-belt-friction's peg belt).
 *
 * No globals, no allocation; cannot fail.
 */
#ifndef MM_ORDER_H
#define MM_ORDER_H

/* How far the least-squares slope over K >= 2 halvings of h strays from p
 * when e = c h^p (1 + B h^2) and |B| h_0^2 = b < 1 on the coarsest level:
 * the slope of log(1 - b 4^-k) against -k ln 2, the larger of the two
 * signs of B (B < 0 bends more).  In radians of slope, >= 0. */
double mm_order_drift_h2(double b, int K);

/* The most the least-squares slope of log e_k against log h_k (K >= 2
 * points, h not all equal) can move when each e_k carries an error of at
 * most rnd (to first order in rnd / e_k): sum_k |log h_k - mean| / S_xx
 * rnd / e_k, S_xx = sum_k (log h_k - mean)^2.  >= 0. */
double mm_order_rounding_drift(int K, const double *h, const double *e, double rnd);

#endif
