/* mm_num.h — helpers of the chapter-1 (numerical methods) exercises that
 * are not numerics: their standard figures.
 */
#ifndef MM_NUM_H
#define MM_NUM_H

#include "mm_dd.h"
#include "mm_exercise.h"
#include "mm_poly.h"

/* Member i of the scalar family `out` with its error (mm_res_scalar_i,
 * then mm_res_scalar_err's error and kind).  Never NULL. */
mm_scalar *mm_num_scalar_i_err(mm_result *res, int out, int i, double value, double error, mm_err_kind kind);

/* Scalar `out` from a double-double value v known within e: v rounded to
 * double, its bound e plus the rounding; marked exact when that is 0. */
void mm_num_scalar_dd(mm_result *res, int out, mm_dd v, double e);

/* ---- the Argand plane ---------------------------------------------------------- */

/* The series `out` as an arrow from the origin to (x, y), the way a
 * complex number is drawn on the Argand plane.  Returns MM_OK or MM_ENOMEM. */
int mm_num_arrow(mm_result *res, int out, double x, double y);

/* The series `out`: the powers a^0, a^1, ..., a^n (n < 0: of 1 / a, to
 * a^n), multiplied out one after the other in double-double: a spiral that
 * turns by arg a a step.  Returns MM_OK or MM_ENOMEM. */
int mm_num_powers(mm_result *res, int out, mm_cdd a, int n);

/* ---- polynomials ----------------------------------------------------------------- */

/* The series `out`: p (ncoef coefficients, highest power first) on the real
 * axis at 201 points over the real parts of its nr roots and a quarter of
 * their span on either side (the span at least 1e-3 of their size, and
 * 1e-3).  When p overflows somewhere on that range the curve is left out,
 * with a warning.  Returns MM_OK or MM_ENOMEM. */
int mm_num_poly_curve(mm_result *res, int out, int ncoef, const double *p, const mm_poly_root *roots, int nr);

/* The standard figure of a fit: the n data points (x, y) as series
 * `data`, and as series `curve` the fitted polynomial on 201 points over
 * their span and 5 % beyond either end (1 when the x are all equal),
 * evaluated from its ncoef coefficients bt in t = (x - mu) / scale (no
 * cancellation of powers of x).  Returns MM_OK or MM_ENOMEM. */
int mm_num_fit_plot(mm_result *res, int data, int curve, int n, const double *x, const double *y, int ncoef,
                    const double *bt, double mu, double scale);

#endif
