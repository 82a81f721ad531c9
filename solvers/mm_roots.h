/* mm_roots.h — all roots of a scalar function f(x) = 0 on [a, b].
 *
 * The book's `rroots` idea: split [a, b] into n equal parts, keep each part
 * whose ends have strictly opposite signs of f, and refine each such
 * bracket with Brent's method (bisection + secant + inverse quadratic
 * interpolation, R. P. Brent, "Algorithms for Minimization without
 * Derivatives", 1973, ch. 4) to an absolute tolerance tol on x.
 *
 * What it finds and what it cannot:
 *   - A subdivision point where f is exactly 0 is a root; it is reported
 *     once (the parts on either side do not then count as brackets).
 *   - A sign change can also be a pole (tan x at pi/2) or a jump.  When |f|
 *     at the converged point is larger than at both ends of the original
 *     part, f grew as the bracket shrank: that is a pole, reported in
 *     poles[], not as a root (MATLAB's fzero uses the same test).  A jump
 *     that does not grow (sign(x)) cannot be told from a steep root; it is
 *     reported as a root with MM_ROOTS_SUSPECT set, because its residual
 *     |f(x)| is not small beside the values of |f| met in the part.
 *   - Roots of EVEN multiplicity ((x-1)^2, a curve touching the axis) do
 *     not change sign and are NOT found; neither are two roots inside one
 *     part (no sign change, or they cancel).  Raise n to separate close
 *     roots; look for a minimum of |f| for touching roots.
 *   - A part where f is not finite at an end (NaN, +-Inf) is skipped and
 *     counted in nskipped; so is a bracket where f becomes non-finite
 *     during the refinement.
 *
 * No globals; safe from many threads as long as f is.  Arrays belong to the
 * caller.
 */
#ifndef MM_ROOTS_H
#define MM_ROOTS_H

#include "mm_status.h"

#define MM_ROOTS_MAX_N    100000  /* most subintervals */
#define MM_ROOTS_MAX_ITER 1000    /* largest allowed max_iter */

/* The function.  Store f(x) in *fx and return 0; return nonzero to stop the
 * search (that value, if an MM_E* code, or else MM_EVALUE, is returned by
 * mm_roots_solve, with err naming x). */
typedef int (*mm_roots_fn)(double x, double *fx, void *params);

typedef struct mm_roots_problem {
    mm_roots_fn f;
    void *params;     /* passed to f untouched */
    double a, b;      /* the interval, a < b, both finite */
} mm_roots_problem;

typedef struct mm_roots_options {
    int n;            /* number of equal subintervals, 1..MM_ROOTS_MAX_N */
    double tol;       /* absolute tolerance on x (> 0): each root is within
                         tol of a sign change of f (up to rounding of x) */
    int max_iter;     /* Brent iterations per bracket, 1..MM_ROOTS_MAX_ITER */
    double suspect;   /* MM_ROOTS_SUSPECT when |f(root)| > suspect times the
                         largest |f| met in the part (its ends and every
                         point Brent's method evaluated) */
} mm_roots_options;

/* n = 100, tol = 1e-6 (API.md's defaults), max_iter = 400 (with the forced
 * bisection of mm_roots_brent, 4 log2(width / tol) + 4 iterations always
 * suffice: under 300 for any bracket of doubles down to tol = 1e-15),
 * suspect = 1e-3.  Cannot fail. */
void mm_roots_options_init(mm_roots_options *opt);

enum {
    MM_ROOTS_EXACT   = 1, /* f(x) == 0 exactly at a subdivision point */
    MM_ROOTS_SUSPECT = 2  /* residual not small: a jump, or a very steep root */
};

typedef struct mm_roots_root {
    double x;         /* the root (the bracket end where |f| is smaller) */
    double fx;        /* f(x), the residual */
    double width;     /* width of the final bracket (0 for an exact hit) */
    int iterations;   /* Brent iterations spent on it (0 for an exact hit) */
    int flags;        /* MM_ROOTS_* bits */
    int part;         /* found in [x_part, x_part+1] of the scan (for an
                         exact hit, part is the grid index of x) */
} mm_roots_root;

typedef struct mm_roots_result {
    /* set by the caller: */
    mm_roots_root *roots; /* room for cap roots; cap >= n + 1 always suffices */
    int cap;
    double *poles;    /* room for pole_cap pole locations; may be NULL */
    int pole_cap;
    /* filled by mm_roots_solve: */
    int nroots;       /* roots stored, ascending in x */
    int npoles;       /* poles found (only min(npoles, pole_cap) stored) */
    int nskipped;     /* parts skipped because f was not finite */
    int max_iterations; /* the largest Brent iteration count of any bracket */
    long nevals;      /* calls of f in all */
} mm_roots_result;

/* MM_OK, or MM_ERANGE / MM_EVALUE naming the field: "a", "b" (finite,
 * a < b, b - a finite), "n", "tol" (finite, > 0), "max_iter", "suspect"
 * (>= 0).  No side effects. */
int mm_roots_check(const mm_roots_problem *prob, const mm_roots_options *opt,
                   mm_error *err);

/* Find the roots (see the top of this file).  Checks first (as
 * mm_roots_check), then:
 *   MM_ERANGE   cap < 1, or more roots than cap ("n": lower n or give room);
 *   MM_ENOCONV  a bracket not refined to tol in max_iter iterations
 *               ("max_iter");
 *   f's own nonzero return code (MM_EVALUE if it is not an MM_E* code).
 * res->nroots etc. are valid (partial) after a failure as well. */
int mm_roots_solve(const mm_roots_problem *prob, const mm_roots_options *opt,
                   mm_roots_result *res, mm_error *err);

/* Brent's method on one bracket: fa = f(a), fb = f(b) with fa * fb < 0
 * (assert).  Refines until the bracket is shorter than 2 (2 eps |x| + tol/2)
 * or f(x) == 0; a step bisects whenever the three before it did not halve
 * the bracket, so 4 log2(|b - a| / tol) + 4 iterations always suffice.
 * On MM_OK, *x is the end of the final bracket with the
 * smaller |f|, *fx its value, *width the bracket width.  *iter and *nevals
 * (may be NULL) are incremented by the iterations and calls made.
 * Fails with MM_ENOCONV after max_iter iterations, MM_ENONFINITE when f
 * returns NaN or Inf, or f's own code. */
int mm_roots_brent(mm_roots_fn f, void *params, double a, double b,
                   double fa, double fb, double tol, int max_iter,
                   double *x, double *fx, double *width, int *iter,
                   long *nevals, mm_error *err);

/* Plain bisection of [xl, xr], where f changes sign (fl = f(xl)), down to
 * width w or to the spacing of doubles: a sign change of f is then within
 * w of *x (the final midpoint), whatever f does (eq. 3 of the theory of
 * num-nonlinear-roots: after k halvings the bracket is (xr - xl) / 2^k).
 * At most 200 halvings.  Fails with MM_ENONFINITE when f is not finite at
 * a midpoint, or f's own code. */
int mm_roots_bisect(mm_roots_fn f, void *params, double xl, double xr, double fl, double w, double *x,
                    mm_error *err);

/* f with an estimate of its rounding error at x: *fx, and *err >= 0 (inf
 * when unknown).  Return 0, or nonzero to stop. */
typedef int (*mm_roots_fn_err)(double x, double *fx, double *err, void *params);

/* Where the sign of f is blurred by its rounding error around a root x:
 * step out from x by h = max(w, 4 eps |x|), doubling, until f is
 * certainly nonzero (|f| above its error) on each side, staying inside
 * [lo, hi].  Returns the larger of the two distances reached: an estimate
 * of how far the root of the exact f can be from x (at a root of
 * multiplicity m, about (error of f)^(1/m)).  At most 80 doublings a side.
 * Cannot fail (a stop or a non-finite value ends that side). */
double mm_roots_band(mm_roots_fn_err f, void *params, double x, double w, double lo, double hi);

/* ---- statics (chapter 3): every root on an interval, in one call ----------------- */

/* mm_roots_solve on [a, b] in n equal parts at tolerance tol, at most
 * max_iter Brent iterations a bracket (0: the default of
 * mm_roots_options_init), the roots into roots[n + 1] (enough for any f):
 * res is set up here (no poles kept) and filled as by mm_roots_solve.
 * Returns as mm_roots_solve. */
int mm_roots_scan(mm_roots_fn f, void *params, double a, double b, int n, double tol, int max_iter,
                  mm_roots_root *roots, mm_roots_result *res, mm_error *err);

/* ---- the first root on a grid (chapter 5, vib-fourier-transform) ---- */

/* The first root of f met on the grid x_i = i step (step > 0), i = i0 ..
 * i1: f is evaluated at x_i in turn until it is 0 there (that x_i is the
 * root) or its sign ((f > 0) or not) changes from x_{i-1} to x_i (i > i0),
 * which bracket mm_roots_brent then closes to tol in at most max_iter
 * iterations.  *x receives the root, NAN when none is met; *iter (may be
 * NULL) Brent's iterations (0 without); *nevals (may be NULL) is
 * incremented by every evaluation.  Returns MM_OK or Brent's error. */
int mm_roots_first(mm_roots_fn f, void *params, double step, int i0, int i1, double tol, int max_iter, double *x,
                   int *iter, long *nevals, mm_error *err);

#endif
