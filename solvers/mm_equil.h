/* mm_equil.h — the equilibrium equations of joints, particles and rigid
 * bodies, A x = b, with the rank test that says what the structure is.
 *
 * The rows of A are equilibrium equations (sum Fx, sum Fy, sum M of each
 * free body or joint); its columns are the unknown forces (member forces,
 * reaction components, pin forces, a holding force); b is minus the applied
 * loads, so that A x + loads = 0 reads A x = b.  With r the rank of the
 * n_eq x n_unk matrix A:
 *
 *   r = n_eq = n_unk   statically DETERMINATE: one set of forces balances
 *                      any load; it is solved;
 *   r < n_eq           a MECHANISM: n_eq - r independent motions that no
 *                      unknown force resists.  A left null vector u
 *                      (u^T A = 0) is such a motion: by virtual work, the
 *                      entry of u of an equation is the virtual
 *                      displacement along that equation's direction (the
 *                      x or y motion of a joint, a body's rotation), and
 *                      no unknown force does work on it;
 *   r < n_unk          statically INDETERMINATE: n_unk - r independent
 *                      self-stress states s (A s = 0): forces in
 *                      equilibrium with no load at all, so equilibrium
 *                      alone cannot share the load among the unknowns.
 *
 * A square A can be both (rank below n): a "critical form" such as a truss
 * with three collinear hinges.  Counting alone (n_eq = n_unk) cannot see
 * that; the rank test does.
 *
 * The method:
 *   - rows and columns are scaled so that their largest entry is 1
 *     (equilibration): equations in N and N m, lengths in mm or km, give
 *     the same decisions;
 *   - a square A is factored by LU with partial pivoting that skips zero
 *     entries (equilibrium matrices have a few entries per column: a truss
 *     member enters 4 equations), with the columns ordered by their first
 *     equation to keep the fill small; then the solution is refined once
 *     and the condition number estimated (Hager-Higham 1-norm estimator).
 *     rcond < MM_EQUIL_RCOND_SINGULAR counts as singular: no digit of x
 *     could be trusted;
 *   - when A is singular or not square, the rank and the null vectors come
 *     from Householder QR with column pivoting of A (self-stress) and of
 *     A^T (mechanism), rank decided at MM_EQUIL_RANK_TOL times the largest
 *     diagonal entry of R.
 *
 * Cost: the determinate path is about O(n^2) for the sparse matrices of
 * structures (30 us for a 50-node truss, tests/bench/bench_statics.c); the
 * diagnosis is dense O(n^3) and runs only when the structure fails.
 * Memory: scratch is allocated and freed inside; the caller owns A, b and
 * the outputs.  No globals: safe from many threads.
 */
#ifndef MM_EQUIL_H
#define MM_EQUIL_H

#include "mm_status.h"

#define MM_EQUIL_MAX_N     800    /* most equations, and most unknowns */
#define MM_EQUIL_RANK_TOL  1e-11  /* a diagonal of R below this times the
                                     largest counts as zero (rank test) */
#define MM_EQUIL_RCOND_SINGULAR 1e-13 /* a determinate-looking A whose
                                     estimated rcond is below this is
                                     treated as singular */

typedef enum mm_equil_kind {
    MM_EQUIL_DETERMINATE = 0,
    MM_EQUIL_MECHANISM,          /* r < n_eq only */
    MM_EQUIL_INDETERMINATE,      /* r < n_unk only */
    MM_EQUIL_CRITICAL            /* both: a mechanism with a self-stress */
} mm_equil_kind;

typedef struct mm_equil_result {
    mm_equil_kind kind;
    int rank;
    int n_mech;          /* n_eq - rank: independent mechanism motions */
    int n_self;          /* n_unk - rank: independent self-stress states */
    double rcond;        /* determinate: estimated reciprocal 1-norm
                            condition number of the equilibrated A (1 is
                            perfect); else 0 */
    double residual;     /* determinate: max over rows of |b_i - (A x)_i| */
    double scale;        /* determinate: the largest over rows of
                            |b_i| + sum_j |A_ij x_j|, the size of the terms
                            that cancel in the residual */
    double growth;       /* determinate: the largest |x_j| times the largest
                            |A_ij| over the largest |b_i|: how much larger the
                            unknowns are than the loads (a nearly collinear
                            joint gives a large one) */
} mm_equil_result;

/* Solve (or diagnose) A x = b.  A is n_eq x n_unk, row-major, b has n_eq
 * entries; neither is modified.
 *   - Determinate: x[n_unk] receives the solution and MM_OK is returned.
 *   - Otherwise MM_ESINGULAR is returned with res->kind, rank, n_mech and
 *     n_self filled, err saying "mechanism" / "statically indeterminate" in
 *     general words (callers that know the structure write better ones), and
 *       mech[n_eq]  (may be NULL) one mechanism motion u, u^T A = 0, when
 *                   n_mech > 0 (zeros otherwise);
 *       self[n_unk] (may be NULL) one self-stress s, A s = 0, when
 *                   n_self > 0 (zeros otherwise);
 *     each scaled so that its largest entry is 1 in magnitude and positive.
 *     x is then left unspecified.
 * res may be NULL.  Fails also with MM_ERANGE (n_eq or n_unk outside
 * 1..MM_EQUIL_MAX_N, param "n"), MM_EVALUE (a non-finite entry of A "A" or
 * b "b"), MM_ENONFINITE (the solution overflows), MM_ENOMEM. */
int mm_equil_solve(int n_eq, int n_unk, const double *A, const double *b, double *x,
                   double *mech, double *self, mm_equil_result *res, mm_error *err);

/* The same for A given by its nonzero entries (triplets): entry k is
 * val[k] at row row[k], column col[k] (0-based); repeated positions add.
 * The form to use for large structures: no n_eq x n_unk array is made on
 * the determinate path.  Also fails with MM_ERANGE (param "A") for an
 * entry outside the matrix or nnz < 0. */
int mm_equil_solve_sparse(int n_eq, int n_unk, int nnz, const int *row, const int *col,
                          const double *val, const double *b, double *x, double *mech, double *self,
                          mm_equil_result *res, mm_error *err);

/* The residual check of a solution, independent of how it was found: the
 * largest |b_i - sum_j A_ij x_j| over the rows into *residual and the
 * largest |b_i| + sum_j |A_ij x_j| into *scale (so residual / scale is the
 * relative round-off, a few eps for a backward-stable solve).  Cannot
 * fail. */
void mm_equil_residual(int n_eq, int n_unk, const double *A, const double *b, const double *x,
                       double *residual, double *scale);

/* Name of a kind ("determinate", "mechanism", "statically indeterminate",
 * "mechanism and statically indeterminate").  Cannot fail. */
const char *mm_equil_kind_name(mm_equil_kind kind);

#endif
