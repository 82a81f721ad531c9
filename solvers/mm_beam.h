/* mm_beam.h — statically determinate beams: reactions, shear force and
 * bending moment diagrams as exact piecewise polynomials, the deflection
 * line by integrating EI y'' = M twice, and the deflection at a point by
 * virtual work (the unit-load method) as a second route.
 *
 * Conventions (API.md, sta-beam-diagrams): x from 0 to L along the beam,
 * loads positive up (+y), couples counter-clockwise positive, a
 * distributed load linear from q1 at x1 to q2 at x2 [N/m].  The shear
 * V(x) is the sum of the vertical forces left of x (reactions included);
 * the bending moment M(x) = sum Fy (x - x_i) - sum C over the loads left of
 * x (sagging positive).  So dV/dx = q, dM/dx = V, and a point force F at x
 * makes V jump by +F there, a couple C makes M jump by -C.  The deflection
 * y is positive up; EI y'' = M.
 *
 * Supports: a pin at a and a roller at b (0 <= a < b <= L: simply
 * supported when a = 0 and b = L, overhanging otherwise), or a cantilever
 * clamped at x = 0.  Both are statically determinate, so the reactions come
 * from two equilibrium equations (eqs. 2-3 of sta/beam_diagrams.md).
 *
 * The solution is kept per segment between breakpoints (the ends, the
 * supports, every point load and couple, the ends of every distributed
 * load): on a segment q is linear, V quadratic, M cubic, the slope quartic
 * and y quintic, all in closed form from the segment's start.  V and M at
 * a segment's start come from the loads left of it (a sweep from x = 0)
 * or right of it (from x = L), whichever sums the smaller magnitudes: a
 * sweep carries the rounding of all it has passed, reactions included.
 *
 * No globals; mm_beam_solve allocates the solution, mm_beam_free releases it.
 */
#ifndef MM_BEAM_H
#define MM_BEAM_H

#include "mm_status.h"

#define MM_BEAM_MAX_LOADS 100   /* rows of each kind of load */

typedef enum mm_beam_kind {
    MM_BEAM_TWO_SUPPORTS,     /* pin at a, roller at b */
    MM_BEAM_CANTILEVER        /* clamped at x = 0 */
} mm_beam_kind;

typedef struct mm_beam_problem {
    double L;                 /* length [m] */
    mm_beam_kind kind;
    double a, b;              /* pin and roller positions [m] (two supports) */
    int n_point;
    const double *point;      /* n_point x 2: x [m], Fy [N] */
    int n_dist;
    const double *dist;       /* n_dist x 4: x1, x2 [m], q1, q2 [N/m] */
    int n_moment;
    const double *moment;     /* n_moment x 2: x [m], C [N m] */
    double EI;                /* bending stiffness [N m^2]; 0: no deflection */
} mm_beam_problem;

typedef struct mm_beam mm_beam;   /* a solved beam (opaque) */

typedef struct mm_beam_value {
    double q;                 /* distributed load [N/m] */
    double V;                 /* shear force [N] */
    double M;                 /* bending moment [N m] */
    double theta;             /* slope dy/dx (0 when EI = 0) */
    double y;                 /* deflection [m] (0 when EI = 0) */
} mm_beam_value;

/* Limits and positions: L > 0 ("L"); 0 <= a < b <= L ("a", "b"); every load
 * on the beam, 0 <= x <= L ("point_loads", "moments"), a distributed load
 * with 0 <= x1 < x2 <= L ("distributed"); at most MM_BEAM_MAX_LOADS rows of
 * each; finite values; EI >= 0 ("EI").  MM_ERANGE or MM_EVALUE naming the
 * parameter.  No side effects. */
int mm_beam_check(const mm_beam_problem *p, mm_error *err);

/* Solve: reactions, diagrams and (EI > 0) deflection.  *out is a new
 * solution to release with mm_beam_free.  Fails as mm_beam_check, or
 * MM_ENOMEM. */
int mm_beam_solve(const mm_beam_problem *p, mm_beam **out, mm_error *err);

void mm_beam_free(mm_beam *b);

/* The reactions: their number (2, or 1 for a cantilever), positions x[],
 * vertical forces Ry[] [N] and couples C[] [N m] (the clamp's; 0 for pin
 * and roller).  Arrays of 2.  Right to rounding (within half an ulp and
 * 1e-30 relative) however much the loads' terms cancel in them: the
 * loads' forces and moments are summed exactly, only one division rounds
 * (pin and roller each from the moments about the other support).  Cannot
 * fail. */
int mm_beam_reactions(const mm_beam *b, double *x, double *Ry, double *C);

/* The breakpoints: their count, and *x pointing at them (sorted, 0 first,
 * L last).  Segment k runs from x[k] to x[k+1]. */
int mm_beam_breaks(const mm_beam *b, const double **x);

/* Values on segment k at s from its start (0 <= s <= its length): at s = 0
 * the values just right of the breakpoint, at the end just left of the
 * next.  Cannot fail (k is clamped). */
void mm_beam_eval_segment(const mm_beam *b, int k, double s, mm_beam_value *v);

/* Values at x; side < 0 the limit from the left, side >= 0 from the right
 * (they differ where a point force or couple sits).  Left of 0 everything
 * is 0; right of L, V and M are what the closing jumps leave (0 up to
 * rounding: see mm_beam_closure).  Cannot fail. */
void mm_beam_eval(const mm_beam *b, double x, int side, mm_beam_value *v);

/* V and M just right of x = L after every jump there: zero for a beam in
 * equilibrium, rounding otherwise (a second route: reactions from two
 * equations, diagrams summed load by load from x = 0, whichever sweep the
 * diagrams kept).  *scale receives the sum of
 * the magnitudes summed into them, each term counted by the magnitudes it
 * was itself computed from (a load or a reaction by its own: the
 * reactions are right to rounding; q on a segment by its terms), and for
 * M every segment's V h counted as (that sum for V so far) h: V's
 * rounding carried along the segment.
 * Rounding is a small multiple of DBL_EPSILON times it.  Cannot fail. */
void mm_beam_closure(const mm_beam *b, double *V_end, double *M_end, double *V_scale, double *M_scale);

/* The extremes: the value of largest magnitude, with its sign, and where
 * (the first x if several, magnitudes within 1e-12 counting as equal);
 * where V or M jumps, the larger one-sided value.  Extremes inside a
 * segment come from the closed-form roots of q (for V) and V (for M);
 * those of y from the roots of the slope, bracketed and refined to
 * rounding.  mm_beam_extreme_y gives 0, 0 when EI = 0.  Cannot fail. */
void mm_beam_extreme_V(const mm_beam *b, double *value, double *x);
void mm_beam_extreme_M(const mm_beam *b, double *value, double *x);
void mm_beam_extreme_y(const mm_beam *b, double *value, double *x);

/* The deflection at x0 by virtual work: y(x0) = integral of M m / EI dx,
 * with m the bending moment of a unit upward force at x0 on the same
 * supports, by 3-point Gauss-Legendre quadrature on every piece (exact:
 * M m is a quartic there).  Independent of the double integration.
 * *scale (may be NULL) receives the integral of |M m| / EI, the size of
 * the terms that cancel in it.  Returns MM_OK, MM_EVALUE when EI = 0, or
 * MM_ENOMEM. */
int mm_beam_unit_load(const mm_beam *b, double x0, double *y, double *scale, mm_error *err);

/* ---- statics (chapter 3): the diagrams sampled, and the checks' numerics ------ */

/* The diagrams sampled for a plot of about n points: each segment gets
 * points in proportion to its length, at least its two ends, so that
 * every jump shows as two points at one x (the values from either side).
 * mm_beam_sample_size gives the number of points (max(n, 2 segments) at
 * most); mm_beam_sample writes them: x ascending, V, M and, when y is not
 * NULL, the deflection.  Cannot fail. */
int mm_beam_sample_size(const mm_beam *b, int n);
void mm_beam_sample(const mm_beam *b, int n, double *x, double *V, double *M, double *y);

/* The whole beam's two equilibrium equations put back, with the reactions
 * found: *Fy the sum of the vertical forces (loads, each distributed load
 * as the two triangles of its trapezoid, and reactions), *Mo the sum of
 * their moments about x = 0 and of the couples, *sF and *sM the sums of
 * the magnitudes of those terms (what their rounding is measured against).
 * Cannot fail. */
void mm_beam_residual(const mm_beam_problem *p, const mm_beam *b, double *Fy, double *Mo, double *sF, double *sM);

/* dV/dx = q and dM/dx = V on every segment, two ways, each as the worst
 * ratio of a difference to its rounding tolerance (16 eps of the
 * segment's terms): *wi in integral form, V(end) - V(start) against the
 * integral of q and M likewise against that of V by 3-point Gauss-Legendre
 * (exact: V is quadratic); *wd by central differences of step 1e-3 of the
 * segment at its middle, less the truncation d^2 q'/6 of M's (none for V's,
 * a quadratic).  Both are at most 1 for diagrams that are consistent.
 * Cannot fail. */
void mm_beam_derivative_check(const mm_beam *b, double *wi, double *wd);

#endif
