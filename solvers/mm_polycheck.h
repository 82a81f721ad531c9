/* mm_polycheck.h — independent checks of polynomial roots and fits: what
 * the roots of mm_poly_roots say about themselves (how many are real within
 * their errors, their backward errors, Vieta's formulas), for num-poly-roots.
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

#endif
