/* mm_errbound.h — error bounds of numbers computed in double and in
 * double-double: what the chapter-1 exercises (num-linear-system, num-eigen)
 * print beside a value, and the tolerances of their checks.
 *
 * Pure numerics: no globals, safe from many threads; the caller owns every
 * array.  u = DBL_EPSILON / 2, the unit roundoff.
 */
#ifndef MM_ERRBOUND_H
#define MM_ERRBOUND_H

#include "mm_dd.h"
#include "mm_status.h"

/* A bound of |s1 / sn - kappa| for kappa = S1 / Sn, the singular values
 * known as s1 +- e1 and sn +- en (sn - en > 0), the division's rounding
 * included: written relative, (s1 / sn) (e1 / s1 + en / (sn - en)), not as
 * the ends of an interval in double, where s1 + e1 rounds back to s1 when
 * e1 is under half an ulp.  Cannot fail. */
double mm_errbound_cond(double s1, double e1, double sn, double en);

/* How good a computed solution xc of the n x n system A x = b is: its
 * residual r = b - A xc in double-double, and from it
 *   the return value: a bound of ||xc - A^-1 b||_2, ||r|| / sigma_min
 *     (sigma_min_lo > 0 a lower bound of A's smallest singular value), the
 *     residual's own rounding included;
 *   *omega: the componentwise backward error max |r_i| / (|A| |xc| + |b|)_i
 *     (a few eps for a backward-stable solve).
 * work: 2n doubles.  Cannot fail. */
double mm_errbound_solve(int n, const double *A, const double *b, const double *xc, double sigma_min_lo,
                         double *omega, double *work);

/* The largest residual ||b - A x||_2 that the rounding of a solution to
 * double leaves: || |A| (u |x| + x_err) ||_2, x_err[i] the bound of x[i]
 * before its rounding.  work: n doubles.  Cannot fail. */
double mm_errbound_rounded_residual(int n, const double *A, const double *x, const double *x_err, double *work);

/* The spacing of the doubles at x: 2^(e - 52) for 2^e <= |x| < 2^(e + 1)
 * (0 at 0).  Cannot fail. */
double mm_errbound_ulp(double x);

/* ---- complex numbers in double-double (mm_cdd) ------------------------------ */

/* The argument of z in (-pi, pi], with its bound in *err: atan2 of z
 * rounded to double (within 0.52 ulp, measured against 50 digits), moved
 * by the low parts (x dy - y dx) / |z|^2, z.err turned into an angle at
 * |z| (twice z.err / |z| while z.err stays under half of |z|).  For z = 0
 * the argument 0 by convention, within pi if z.err > 0.  Cannot fail. */
double mm_errbound_arg(mm_cdd z, double *err);

/* How far r e^(i theta) computed in polar form in double can be from the
 * exact number, for r from hypot and theta from atan2 (each within an
 * ulp), then a power n (|n| = an; 1 for a product or a quotient) and n
 * theta (|theta| <= th) and cos and sin: the modulus within (|n| + 3) u
 * relative, the angle within (3 |n| th + 2) u, both doubled and taken
 * together (sqrt 2).  Cannot fail. */
double mm_errbound_polar(double r, int an, double th);

/* The n roots w_k of a (mm_cdd_root with r = |a|, theta = arg a in
 * double), rounded to double into re[k], im[k], k = 0..n-1, and two checks
 * of them as printed, in double-double: *back = max |w_k^n - a| with its
 * bound *back_tol, n |w|^(n-1) times the rounding of w (1.01 of it) plus
 * the power's own; *sum = |sum of the roots| (0 for n >= 2: the
 * coefficient of z^(n-1) in z^n - a), *sum_tol the roots' rounding and
 * that of the running sum (1.01 of it).  Cannot fail. */
void mm_errbound_roots(mm_cdd a, double r, double theta, int n, double *re, double *im, double *back,
                       double *back_tol, double *sum, double *sum_tol);

/* ---- symmetric eigenproblems ------------------------------------------------ */

/* The extreme eigenvalues of a symmetric matrix, to the last digit
 * (mm_linalg_sygv_dd), as bounds of its norms. */
typedef struct mm_errbound_sym {
    double norm_hi;     /* >= ||a||_2 */
    double min_lo;      /* <= the smallest eigenvalue: > 0 proves a positive definite */
    double min, max;    /* the smallest and the largest eigenvalue, rounded */
} mm_errbound_sym;

/* The bounds b of the symmetric n x n a; work: 2n doubles.  Fails as
 * mm_linalg_sygv_dd. */
int mm_errbound_sym_extremes(int n, const double *a, double *work, mm_errbound_sym *b, mm_error *err);

/* omega = sqrt(lambda) for lambda known within lambda_err (lambda +
 * lambda_err >= 0), and into *omega_err its bound, the rounding of the root
 * included: lambda_err / (sqrt(lambda - lambda_err) + omega), a quotient,
 * when the interval stays above 0 (as the difference of roots in double,
 * lambda + lambda_err rounds back to lambda when lambda_err is under half
 * an ulp, and the bound was u omega alone); else the wider side of the
 * interval of roots.  Cannot fail. */
double mm_errbound_sqrt(double lambda, double lambda_err, double *omega_err);

/* trace(M^-1 K) against the sum of the eigenvalues of K v = lambda M v:
 * *trace from MK = M^-1 K (n x n, computed by an LU solve whose forward
 * error bound is ferr per column, relative to the column's largest entry),
 * *sum of lambda[0..n-1]; returns the tolerance of |trace - sum|: the
 * eigenvalues' bounds, the columns' bounds and 2 n u of every term summed.
 * Cannot fail. */
double mm_errbound_trace(int n, const double *MK, double ferr, const double *lambda, const double *lambda_err,
                         double *trace, double *sum);

#endif
