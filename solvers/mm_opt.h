/* mm_opt.h — the maximum of a function of one variable on an interval.
 *
 * Golden-section search (J. Kiefer 1953; W. H. Press et al., Numerical
 * Recipes, 3rd ed., section 10.2): for f unimodal on [a, b] (one maximum,
 * increasing before it and decreasing after), keep a bracket [a, b] and two
 * interior points at the golden ratio; each evaluation discards the part
 * that cannot hold the maximum and shrinks the bracket by 0.618.  It needs
 * no derivative and never leaves the bracket, so it also finds a maximum
 * at an end of [a, b].  Accuracy: the bracket shrinks to tol, but near a
 * smooth maximum f differs from f(x*) only by (x - x*)^2 f''/2, so
 * function values below about sqrt(eps) relative cannot place x closer than
 * about sqrt(eps) |x*| (the search then stops when the two interior values
 * are equal and the point halfway between them is no higher: it reports
 * the bracket it reached; a higher midpoint means the two straddle a sharp
 * maximum, and the search goes on between them).
 *
 * To find a minimum, maximise -f.  No globals; safe from many threads as
 * long as f is.
 */
#ifndef MM_OPT_H
#define MM_OPT_H

#include "mm_status.h"

/* f(x) into *fx; return 0, or nonzero to stop the search (returned). */
typedef int (*mm_opt_fn)(double x, double *fx, void *params);

typedef struct mm_opt_result {
    double x;          /* the argument of the largest value found */
    double fx;         /* f(x) */
    double bracket;    /* width of the final bracket, which holds x* */
    int evals;         /* evaluations of f */
} mm_opt_result;

/* Maximise f on [a, b] (a < b finite) until the bracket is below tol (> 0)
 * or max_evals (>= 3) evaluations are spent.  Returns MM_OK, MM_EVALUE for
 * bad arguments, MM_ENONFINITE when f is not finite at a point it needed,
 * or f's own nonzero return; err filled. */
int mm_opt_golden_max(mm_opt_fn f, void *params, double a, double b, double tol, int max_evals,
                      mm_opt_result *res, mm_error *err);

/* ---- refining a sampled extreme ---------------------------------------------- */

/* f(x), and when err is not NULL a bound on its rounding error into *err
 * (0 if unknown); NaN where f is not defined. */
typedef double (*mm_opt_fn_err)(double x, double *err, void *params);

typedef struct mm_opt_extreme {
    double x, fx;      /* where s f is largest near x0, and f there */
    double x_err;      /* estimated error of x */
    double fx_err;     /* estimated error of fx */
} mm_opt_extreme;

/* The extreme of s f (s = +1 the largest, -1 the smallest value) near a
 * sample x0 of a scan with spacing h, within [a, b]: a finer scan of
 * [x0 - h, x0 + h] (the window may hold more than one bump), then golden
 * section between the best point's neighbours.  x_err is the final bracket
 * or the flat band where the rounding of f hides the peak, whichever is
 * larger: golden section compares two values, each off by up to err_f
 * (never less than an ulp), so it cannot tell points apart where
 * |f''| dx^2 / 2 < 2 err_f, i.e. within dx = sqrt(4 err_f / |f''|), with
 * f'' from a second difference on a scale well above the noise; fx_err is
 * err_f + |f''| x_err^2 / 2.  Costs about 40 + 2 log(h / x_err) / log(1.618)
 * evaluations of f.  If golden section cannot beat the scan (an extreme at
 * an end of [a, b]) the best sample is returned. */
void mm_opt_refine_extreme(mm_opt_fn_err f, void *params, double s, double x0, double h, double a, double b,
                           mm_opt_extreme *out);

/* ---- a scan, then golden sections (chapter 5, vib-absorber) ---- */

/* The largest value of f over the grid x_i = i step, i = 0 .. n (step >
 * 0), the first largest one at x_ib, refined by mm_opt_golden_max on
 * [x_{max(ib-1, 0)}, x_{min(ib+1, n)}] (never outside the grid) to tol
 * within max_evals evaluations: the global maximum of a function whose
 * peaks are wider than 2 step.  res as mm_opt_golden_max's (its evals those
 * of the golden sections alone), except that a sample higher than what the
 * golden sections found, or as high (a maximum at an end of the grid, or
 * at a kink), is
 * returned itself.  Returns f's nonzero return, or what mm_opt_golden_max
 * returns. */
int mm_opt_scan_golden_max(mm_opt_fn f, void *params, double step, int n, double tol, int max_evals,
                           mm_opt_result *res, mm_error *err);

#endif
