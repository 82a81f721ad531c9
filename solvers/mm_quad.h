/* mm_quad.h — definite integrals of a function of one variable.
 *
 * Two rules with different ways of failing, so that each can check the
 * other:
 *   - mm_quad_gk: global adaptive Gauss-Kronrod 7-15 (QUADPACK's qag with
 *     qk15: R. Piessens et al., QUADPACK, Springer 1983).  The interval is
 *     cut where the error estimate is largest until the estimates add up
 *     to the tolerance;
 *   - mm_quad_gl: composite 5-point Gauss-Legendre on m equal panels, m
 *     doubling until two successive meshes agree panel by panel (a fixed
 *     mesh, refined everywhere at once).
 * Error estimates are estimates.  mm_quad_gk steers its subdivision by
 * QUADPACK's (|K15 - G7| sharpened by (200 |K15 - G7| / I|f - mean|)^1.5),
 * which for a smooth f overstates the error of K15 by orders of magnitude;
 * when it is done it halves every piece once more and reports the sum of
 * what that changed (the error of the coarser partition, so still on the
 * safe side) together with the finer sum.  No estimate is below a few eps
 * of the integral of |f|, which rounding alone can reach; sums are
 * compensated (Neumaier), so adding thousands of terms keeps eps of the
 * result.
 *
 * No globals; safe from many threads as long as f is.  f returns 0, or a
 * nonzero code that stops the integration and is returned.  A value of f
 * that is not finite stops it too: MM_ENONFINITE, err naming "f" with x.
 */
#ifndef MM_QUAD_H
#define MM_QUAD_H

#include "mm_status.h"

#define MM_QUAD_MAX_PIECES 10000    /* most subintervals of mm_quad_gk */
#define MM_QUAD_MAX_PANELS 65536    /* most panels of mm_quad_gl */

typedef int (*mm_quad_fn)(double x, double *fx, void *params);

typedef struct mm_quad_options {
    double rtol;       /* stop when the error estimate <= rtol * integral of |f| ... */
    double atol;       /* ... or <= atol */
    int max_pieces;    /* most subintervals, 1..MM_QUAD_MAX_PIECES */
    int start_pieces;  /* equal pieces to begin with, 1..max_pieces: one piece over an
                          interval symmetric about a zero of an odd f has K15 = G7 = 0
                          and would stop at once */
} mm_quad_options;

/* rtol 1e-12, atol 0, max_pieces 400, start_pieces 8.  Cannot fail. */
void mm_quad_options_init(mm_quad_options *opt);

typedef struct mm_quad_piece {
    double a, b;       /* the subinterval */
    double value;      /* K15 on it */
    double err;        /* its error estimate */
    double abs_value;  /* K15 of |f| on it */
    double floor;      /* the rounding floor of err: a few eps of abs_value, and
                          u max |x| times the variation of f across the nodes */
} mm_quad_piece;

typedef struct mm_quad_result {
    double value;      /* the integral */
    double err;        /* error estimate of value (the sum over the pieces) */
    double err_value;  /* mm_quad_gk: err; mm_quad_gl: err is the last change, the error
                          of the coarser mesh; this is the finer's, value's own (below) */
    double abs_value;  /* the integral of |f| (the scale of the rounding) */
    int pieces;        /* subintervals in the final partition */
    long evals;        /* calls of f */
    int converged;     /* 1 when err met the tolerance, 0 when max_pieces ran out */
} mm_quad_result;

/* MM_OK, or MM_EVALUE naming "a"/"b" (not finite, or b <= a), "rtol"/"atol"
 * (negative or not finite, or both 0), "max_pieces", "start_pieces"
 * (outside their range).  No side effects. */
int mm_quad_check(double a, double b, const mm_quad_options *opt, mm_error *err);

/* The integral of f over [a, b] by adaptive Gauss-Kronrod 7-15, then one
 * more halving of every piece for the estimate (see above): about
 * 45 (start_pieces + 2 (pieces - start_pieces)) evaluations.  piece, if
 * not NULL, has room for opt->max_pieces and receives the partition before
 * the last halving (r->pieces entries, in no particular order).  Returns MM_OK (also when
 * max_pieces ran out: r->converged = 0), the errors of mm_quad_check,
 * MM_ENONFINITE, MM_ENOMEM, or f's own nonzero return. */
int mm_quad_gk(mm_quad_fn f, void *params, double a, double b, const mm_quad_options *opt,
               mm_quad_piece *piece, mm_quad_result *r, mm_error *err);

/* The integral of f over [a, b] by composite 5-point Gauss-Legendre on m
 * equal panels, m = m0, 2 m0, 4 m0, ... <= max_panels, until two doublings
 * in a row change the result by at most tol; r->err receives the last
 * change, summed panel by panel in absolute value: sum over the panels of
 * the coarser mesh of |(its two halves on the finer) - (it)| (an estimate
 * that overstates the error of the finer result for a smooth f, and that
 * errors of opposite sign in different panels cannot cancel; never below
 * the rounding floor: a few eps of the integral of |f|, and each panel's
 * |x| u/2 times the variation of f across its nodes).  r->err_value is the
 * error of r->value itself: where the last change was at most half the
 * one before (rate rho), the changes still to come, err rho / (1 - rho),
 * else err.  1 <= m0 <= max_panels <= MM_QUAD_MAX_PANELS;
 * 16 max_panels bytes of scratch (on the stack up to 8 panels, so that
 * it cannot run out of memory).  Returns MM_OK (r->converged = 0 when
 * max_panels ran out), MM_EVALUE for bad arguments, MM_ENOMEM,
 * MM_ENONFINITE, or f's own return.  r->pieces is the number of panels,
 * r->abs_value the integral of |f|. */
int mm_quad_gl(mm_quad_fn f, void *params, double a, double b, int m0, int max_panels, double tol,
               mm_quad_result *r, mm_error *err);

/* ---- added for the kinematics chapter ------------------------------------------------ */

/* The nodes on [-1, 1] (increasing) and the weights of 5-point
 * Gauss-Legendre (exact for polynomials of degree 9), correctly rounded:
 * the one table of the code base, used by mm_quad_gl, mm_quad_gl5_nodes
 * and callers that sum the rule themselves (the integrand carries its
 * own error estimate, a corner is met by panels of their own). */
extern const double mm_quad_gl5_node[5], mm_quad_gl5_weight[5];

/* ---- statics (chapter 3): a fixed rule, its nodes and weights ---------------- */

/* Composite 5-point Gauss-Legendre on m >= 1 equal pieces of [a, b] (piece
 * k from a + (b - a) k / m to a + (b - a) (k + 1) / m) as 5 m nodes x and
 * weights w, piece by piece, each piece's nodes in the order mid, then
 * +-0.538, +-0.906 of its half-width out: sum w[i] f(x[i]) is the integral
 * of f, exact for a polynomial of degree 9 or less.  For a sum written out
 * by the caller (several integrands on the same nodes, each weighted its
 * own way), where mm_quad_gl would call one f again and again.  The
 * constants are mm_quad_gl5_node and mm_quad_gl5_weight. */
void mm_quad_gl5_nodes(double a, double b, int m, double *x, double *w);

/* ---- the moments of a sampled density (chapter 5, vib-dispersion) ---- */

/* The centroid sum p x / sum p and the r.m.s. width sqrt(sum p (x - c)^2 /
 * sum p) of the n samples p >= 0 (not all 0) at the equally spaced x: the
 * trapezoidal rule's moments of a density whose ends are negligible (the
 * end weights of 1/2 left out, and the spacing, which cancels).  Cannot
 * fail. */
void mm_quad_moments(const double *x, const double *p, int n, double *centre, double *width);

#endif
