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
 * are equal: it reports the bracket it reached).
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

#endif
