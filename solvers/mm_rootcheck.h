/* mm_rootcheck.h — what a scan for roots (mm_roots_solve) can miss, and its
 * roots confirmed by a second method, for num-nonlinear-roots.
 *
 * Pure numerics: no globals, safe from many threads; the caller owns every
 * array.  Nothing here can fail.
 */
#ifndef MM_ROOTCHECK_H
#define MM_ROOTCHECK_H

#include "mm_roots.h"

/* A root at an end of [a, b] has no sign change inside to show it (sin(pi x)
 * at x = -1 gives -1.2e-16, not 0, because pi is rounded): an end where f
 * is finite and zero within its own rounding error (f_err), not already
 * listed, is added to rr as a root (fx its value, width 0, part -1: found
 * at an end), keeping the roots in ascending order.  rr->roots needs room
 * for rr->nroots + 2. */
void mm_rootcheck_ends(mm_roots_fn_err f_err, void *ctx, double a, double b, mm_roots_result *rr);

/* The roots of a scan of [a, b] in n parts to tol, confirmed:
 *   by bisection restarted from the part each was found in, to tol / 4 (a
 *   slower method whose error bound is certain; Brent's claim is
 *   |x - root| <= tol + 4 eps |x|): worst = the largest |x_Brent - x_bisection|,
 *   within allowed = 1.25 tol + 12 eps max |x|; lost = roots whose part
 *   shows no sign change for bisection;
 *   by a sign change of f across x +- h, h = tol + 8 eps |x| covering
 *   Brent's final bracket (for a continuous f, a root within h of x):
 *   nosign = roots without one;
 *   crowded = roots with their own sign change where bisection lands on
 *   another root than Brent's: the part holds three or more roots (n is too
 *   small to separate them; not an error of the root).
 * Roots that are exact zeros (MM_ROOTS_EXACT) or found at an end are
 * proven and skipped. */
typedef struct mm_rootcheck {
    double worst, allowed;
    int lost, nosign, crowded;
} mm_rootcheck;

void mm_rootcheck_confirm(mm_roots_fn f, void *ctx, double a, double b, int n, double tol,
                          const mm_roots_result *rr, mm_rootcheck *o);

#endif
