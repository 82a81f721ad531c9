/* mm_polycheck.h — independent checks of polynomial roots and fits: what
 * the roots of mm_poly_roots say about themselves (how many are real within
 * their errors, their backward errors, Vieta's formulas), for num-poly-roots;
 * how far a least-squares fit (mm_poly_fit_dd, mm_poly_fit) can be trusted
 * and the checks of it that do not use it, for num-polyfit.
 *
 * Pure numerics: no globals, safe from many threads; the caller owns every
 * array.  Nothing here can fail.
 */
#ifndef MM_POLYCHECK_H
#define MM_POLYCHECK_H

#include "mm_poly.h"

typedef struct mm_poly_roots_summary {
    int real;           /* roots whose error disc |x - z| <= err meets the real axis */
    int sure_real;      /* of all roots, those computed real and simple: certainly real (the
                           disc holds this root alone, and a real polynomial's complex roots
                           come in conjugate pairs, the disc symmetric about the axis) */
    int multiple;       /* roots in clusters (MM_POLY_ROOT_MULTIPLE) with err > 0 (exact zero
                           roots are exact) */
    int illcond;        /* simple roots flagged MM_POLY_ROOT_ILLCOND */
    int zeros;          /* roots exactly 0 */
    double max_err;     /* largest err of a root */
    double mult_err;    /* largest err in a cluster */
    double ill_err;     /* largest err of an ill-conditioned simple root */
    double backward;    /* worst mm_poly_backward_error over the roots */
    /* Vieta's formulas: the sum of the roots against -p_1 / p_0, and
     * log |product of the roots| against log |p_d / p_0| (on log |.| so that
     * it cannot overflow; the reference and tolerance left 0 when a root is
     * exactly 0: the product is 0 = p_d then), each with a
     * tolerance: the roots' errors plus 4 d eps of the sizes summed */
    double sum, sum_ref, sum_tol;
    double logprod, logprod_ref, logprod_tol;
} mm_poly_roots_summary;

/* The summary of the d = ncoef - 1 roots of p (highest power first, p[0]
 * nonzero) as mm_poly_roots gives them.  Cannot fail. */
void mm_poly_roots_summarize(int ncoef, const double *p, const mm_poly_root *roots, mm_poly_roots_summary *s);

/* ---- least-squares fits ------------------------------------------------------ */

/* The number of distinct values among x[0..n-1] (compared exactly).
 * Cannot fail. */
int mm_poly_distinct(int n, const double *x);

/* The residual a fit in double leaves when the data are fitted exactly
 * (MATLAB's polyfit evaluated by polyval in powers of x): (2d + 2) u
 * max_i sum |c_k| |x_i|^k + (n + d + 1) u max |y|, for the ncoef = d + 1
 * coefficients c (highest power first) at the n points.  Cannot fail. */
double mm_poly_fit_level(int n, const double *x, const double *y, int ncoef, const double *c);

/* p(x_i) by Horner from the printed c (c_err their bounds) against the
 * fitted values fit (fit_err their bounds): the worst |p(x_i) - fit_i|
 * relative to what the rounding of Horner's rule leaves, (2d + 1) u sum
 * |c_k| |x_i|^k plus the coefficients' and the fit's own bounds (Higham,
 * Accuracy and Stability, 5.1; 1.01 of it): at most 1 for a consistent
 * fit.  *rounding receives the largest (2d + 1) u sum |c_k| |x_i|^k,
 * *terms the largest sum |c_k| |x_i|^k.  Cannot fail. */
double mm_poly_horner_deviation(int n, const double *x, int ncoef, const double *c, const double *c_err,
                                const double *fit, const double *fit_err, double *rounding, double *terms);

/* The normal equations (A^T A) a = A^T y with the residuals r as printed,
 * in the basis t = (x - mu) / scale (scale a power of 2, so that t is
 * exact in double-double): the worst |sum_i t_i^k r_i| over k = 0..d,
 * relative to what the rounding of the r_i leaves (r_err[i] + u |r_i|,
 * and the sum's own rounding; 1.01 of it): at most 1 for the residuals of
 * an exact least-squares fit.  Cannot fail. */
double mm_poly_normal_residual(int n, const double *x, const double *r, const double *r_err, int ncoef, double mu,
                               double scale);

/* The closed forms of the mean (degree 0) and of the regression line
 * (degree 1) of the n points, in double, each with the bound of its own
 * rounding ((n + 3) u of the sums of |terms|, the means' rounding included). */
typedef struct mm_poly_line {
    double mean_y, mean_y_err;
    double slope, slope_err;            /* S_xy / S_xx */
    double intercept, intercept_err;    /* mean(y) - slope mean(x) */
} mm_poly_line;

/* The mean and the line of the n >= 1 points (x, y) (with all x equal the
 * line's numbers are not finite).  Cannot fail. */
void mm_poly_line_fit(int n, const double *x, const double *y, mm_poly_line *l);

/* The fitted values of the fit in double two ways (mm_poly_fit_values, in
 * t = (x - mu) / scale: by the SVD, MATLAB's route, and by the normal
 * equations) against the exact fit (fit, within fit_err): how far each is
 * beyond fit_err, and each one's forward error bound (eq. 4 of
 * polyfit.md, Wedin; Bjorck 1996, 1.4): g (kappa ||A|| ||b|| + kappa ||r||
 * + ||y||) for the SVD, kappa^2 in place of the first kappa for the normal
 * equations (their backward error is in A^T A), g = 2 (d + 1) n u the
 * backward error of Householder QR or the SVD, kappa = cond (of the scaled
 * Vandermonde matrix, mm_poly_fit_info), ||r|| = rms sqrt(n). */
typedef struct mm_poly_fit_routes {
    double dev_svd, dev_ne;             /* worst |fit_route - fit| - fit_err, at least 0 */
    double bound_svd, bound_ne;         /* their forward error bounds */
} mm_poly_fit_routes;

/* Fails as mm_poly_fit_values (MM_ESINGULAR: A^T A singular in double);
 * work: 2n doubles. */
int mm_poly_fit_two_routes(int n, const double *x, const double *y, int degree, double mu, double scale,
                           double cond, double rms, const double *fit, const double *fit_err, double *work,
                           mm_poly_fit_routes *o, mm_error *err);

#endif
