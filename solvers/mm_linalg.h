/* mm_linalg.h — dense and banded linear algebra on top of LAPACK.
 *
 * This is the only module that talks to LAPACKE; everything else in the
 * project calls these functions.  The conventions, once for all:
 *
 *   - Matrices are ROW-MAJOR: A(i,j) is A[i*ncols + j], 0-based.  A "column"
 *     of an eigenvector or solution matrix is what MATLAB would print as a
 *     column: mode j of V is V[i*ncols + j], i = 0..n-1.
 *   - Inputs are const and never overwritten: every function copies what
 *     LAPACK would destroy into scratch memory it allocates and frees
 *     itself.  Outputs go to arrays the caller owns, with the sizes given in
 *     each comment.  No function keeps a pointer after it returns.
 *   - No globals but one lock: safe to call from many threads at once.
 *     Debian's serial OpenBLAS (the default BLAS/LAPACK) shares scratch
 *     buffers between threads without a lock, so mm_linalg.c makes every
 *     LAPACK/BLAS call under one mutex (see there); the double-double
 *     routines (mm_linalg_*_dd) need no lock.
 *   - Every fallible function returns MM_OK or an MM_E* code and fills err
 *     (may be NULL) with the parameter concerned and a message for a
 *     learner.  Sizes are checked against the MM_LINALG_MAX_* limits, and
 *     every input element is checked to be finite (MM_EVALUE), BEFORE any
 *     allocation; so LAPACK never sees NaN and an "illegal argument" from
 *     LAPACK is our bug (MM_EINTERNAL).
 *   - Passing a NULL pointer for a required argument, or n < 1 where the
 *     comment says n >= 1, is a programmer error and is assert()ed.
 *   - The parameter names used in messages are "A", "b", "K", "M", "n",
 *     "nrhs", "nev", "kd": the names the canonical exercises use.
 */
#ifndef MM_LINALG_H
#define MM_LINALG_H

#include <stddef.h>

#include "mm_status.h"

/* ---- limits (part of the API) ------------------------------------------- */

#define MM_LINALG_MAX_N      2000    /* largest dense order (32 MB per matrix) */
#define MM_LINALG_MAX_NRHS   2000    /* most right-hand sides in one solve */
#define MM_LINALG_MAX_ROWS   100000  /* most rows of a least-squares matrix */
#define MM_LINALG_MAX_ELEMS  4000000 /* most elements (rows*cols) of any matrix */
#define MM_LINALG_MAX_BAND_N 20000   /* largest order of a banded problem */
#define MM_LINALG_MAX_KD     200     /* largest half-bandwidth of a banded problem */
#define MM_LINALG_MAX_NEV    500     /* most modes from the banded solver */

/* Trust levels of a linear solve, on the reciprocal condition number rcond
 * (1-norm estimate, 1/rcond ~ cond_1(A)):
 *   rcond <  n * DBL_EPSILON     -> MM_ESINGULAR (no digit of x can be trusted)
 *   rcond <  MM_LINALG_RCOND_WARN -> MM_OK with warn = 1 (about log10(1/rcond)
 *                                    of the ~16 digits of x may be wrong) */
#define MM_LINALG_RCOND_WARN 1e-10

/* The symmetry rule of the whole project (mm_linalg_is_symmetric): a
 * matrix is symmetric when |a_ij - a_ji| <= MM_LINALG_SYM_TOL * max |a_kl|.
 * A matrix typed in decimal is exactly symmetric, and one assembled from
 * element matrices is symmetric to a few units of rounding (~1e-15); a
 * difference in the 12th digit is a typing error.  The symmetric solvers
 * use the upper triangle. */
#define MM_LINALG_SYM_TOL    1e-12

/* ---- helpers ------------------------------------------------------------- */

/* 1 when the row-major n x n a is symmetric by the rule of
 * MM_LINALG_SYM_TOL, else 0 with the first offending pair (0-based, i < j)
 * in *bad_i, *bad_j (each may be NULL).  Cannot fail. */
int mm_linalg_is_symmetric(int n, const double *a, int *bad_i, int *bad_j);

/* MM_OK if all count values of a are finite, else MM_EVALUE naming param and
 * the first bad entry (by 0-based flat index).  Cannot fail otherwise. */
int mm_linalg_check_finite(const char *param, size_t count, const double *a,
                           mm_error *err);

/* Band storage used by the banded functions (our own, simple layout):
 *
 *     Ab[i*(kd+1) + d] = A(i, i+d),   i = 0..n-1,  d = 0..kd
 *
 * Row i of Ab holds the diagonal entry of row i of A and the kd entries to
 * its right (the upper triangle; the lower one follows by symmetry).
 * Entries with i+d >= n are padding: never read, may hold anything.  Ab has
 * n*(kd+1) doubles.  (This is exactly LAPACK's column-major lower band
 * storage with leading dimension kd+1, so no conversion is needed.)
 * Example, n = 3, kd = 1, A = [2 -1 0; -1 2 -1; 0 -1 1]:
 *     Ab = { 2,-1,   2,-1,   1,(pad) } */
#define MM_LINALG_BAND_INDEX(kd, i, j) ((size_t)(i) * (size_t)((kd) + 1) + (size_t)((j) - (i)))

/* Pack the upper band of the symmetric n x n row-major A into Ab (layout
 * above; padding set to 0).  Entries of A outside the band are ignored.
 * Cannot fail. */
void mm_linalg_band_pack(int n, int kd, const double *A, double *Ab);

/* ---- linear systems -------------------------------------------------------- */

typedef struct mm_linalg_solve_info {
    double rcond;     /* reciprocal condition number, 1-norm estimate of the
                         row/column-equilibrated A (LAPACK dgesvx); 1 = perfect,
                         0 = singular */
    int warn;         /* 1 when rcond < MM_LINALG_RCOND_WARN: the answer is
                         returned but digits may be lost; 0 otherwise */
    int untrusted;    /* 1 when rcond < n*eps: singular to working precision;
                         the answer is returned (its residual is still small)
                         but no digit of it can be trusted: say so */
    double residual;  /* max over right-hand sides of ||b - A x||_2 */
    double backward_error; /* max over rhs of ||b - A x||_inf /
                              (||A||_inf ||x||_inf + ||b||_inf): ~1e-16 for a
                              stable solve, whatever the conditioning */
    double ferr;      /* LAPACK's estimated bound on the relative forward
                         error ||x - x_true||_inf / ||x||_inf (max over rhs) */
} mm_linalg_solve_info;

/* Solve A X = B for X.  A is n x n, B and X are n x nrhs (row-major; for one
 * right-hand side, a plain vector of n).  A and B are not modified; X may be
 * the same array as B.  Uses LU with partial pivoting after row/column
 * equilibration, then iterative refinement (LAPACK dgesvx/dgerfs, at most
 * 5 steps).  Cost: ~1.3 us at n = 3, ~160 us at n = 100 (bench_linalg).
 * info may be NULL.
 * Fails with:
 *   MM_ERANGE    n outside 1..MM_LINALG_MAX_N ("n"), nrhs outside
 *                1..MM_LINALG_MAX_NRHS ("nrhs");
 *   MM_EVALUE    a NaN or infinite entry in A ("A") or B ("b");
 *   MM_ESINGULAR A exactly singular: a zero pivot in the elimination ("A");
 *                X is then left unspecified but info is filled.  A matrix
 *                singular only to working precision (rcond < n*eps) is
 *                solved and flagged info->untrusted instead;
 *   MM_ENONFINITE the solution overflows ("b");
 *   MM_ENOMEM, MM_EINTERNAL. */
int mm_linalg_solve(int n, int nrhs, const double *A, const double *B,
                    double *X, mm_linalg_solve_info *info, mm_error *err);

/* Singular values of the m x n row-major A, largest first, into
 * s[min(m,n)].  A is not modified.  Fails with MM_ERANGE (sizes: m, n >= 1,
 * m <= MM_LINALG_MAX_ROWS, n <= MM_LINALG_MAX_N, m*n <= MM_LINALG_MAX_ELEMS),
 * MM_EVALUE (non-finite entry, "A"), MM_ENOCONV (SVD did not converge),
 * MM_ENOMEM, MM_EINTERNAL. */
int mm_linalg_svdvals(int m, int n, const double *A, double *s, mm_error *err);

/* 2-norm condition number sigma_max / sigma_min of the m x n A (what MATLAB's
 * cond(A) returns), computed from the SVD.  A is not modified.  When the
 * smallest singular value is exactly 0, *cond = INFINITY and the result is
 * MM_ESINGULAR ("A").  Other failures as mm_linalg_svdvals. */
int mm_linalg_cond2(int m, int n, const double *A, double *cond, mm_error *err);

/* Least squares: X minimises ||A X - B||_2 column by column; among several
 * minimisers (rank-deficient A) the one of least norm.  A is m x n, B is
 * m x nrhs, X is n x nrhs (all row-major; X may not alias B).  Singular
 * values s_i <= rcond * s_1 count as zero; rcond <= 0 selects the default
 * max(m,n) * DBL_EPSILON (MATLAB's pinv rule).  Outputs, each optional
 * (NULL): rank (numerical rank), resid[nrhs] (||b_k - A x_k||_2 for each
 * right-hand side), sv[min(m,n)] (singular values, largest first).
 * Uses LAPACK dgelsd (SVD, divide and conquer).  Fails with MM_ERANGE
 * ("m", "n", "nrhs" against the limits above), MM_EVALUE ("A", "b"),
 * MM_ENONFINITE (the solution overflows, "b"), MM_ENOCONV, MM_ENOMEM,
 * MM_EINTERNAL. */
int mm_linalg_lstsq(int m, int n, int nrhs, const double *A, const double *B,
                    double rcond, double *X, int *rank, double *resid,
                    double *sv, mm_error *err);

/* ---- symmetric generalized eigenproblem K v = lambda M v ------------------ */
/*
 * Common to the three functions below:
 *   - K symmetric, M symmetric positive definite (checked: MM_EVALUE "K"/"M"
 *     when |a_ij - a_ji| > MM_LINALG_SYM_TOL * max|a|; only the upper
 *     triangle is then used).  M not positive definite -> MM_ESINGULAR
 *     ("M", "mass matrix is not positive definite").  K may be singular or
 *     indefinite (a free structure has lambda ~ 0 rigid-body modes, which
 *     may come out as tiny negative numbers ~ -eps*||K||).
 *   - lambda ascending.  Modes are M-normalised: v^T M v = 1, and
 *     M-orthogonal to each other (K-orthogonal too, v_i^T K v_j = lambda_i
 *     delta_ij).
 *   - Sign convention: in each mode, the first component whose magnitude
 *     exceeds 1e-8 of the mode's largest magnitude is positive.  For a
 *     repeated eigenvalue the modes span the right space but which basis of
 *     it is returned is not specified.
 *   - V is n x ncols row-major with mode j in column j: V[i*ncols + j], where
 *     ncols = n for the full solver and nev for the selective ones.  V may be
 *     NULL when only the eigenvalues are wanted.
 *   - Other failures: MM_ERANGE for sizes over the limits ("n", "nev",
 *     "kd"), MM_EVALUE for non-finite entries, MM_ENOCONV, MM_ENOMEM,
 *     MM_EINTERNAL.
 */

/* All n eigenpairs, dense (LAPACK dsygvd).  K, M are n x n, lambda[n],
 * V[n*n] or NULL. */
int mm_linalg_sygv(int n, const double *K, const double *M, double *lambda,
                   double *V, mm_error *err);

/* Only the nev lowest eigenpairs, dense (LAPACK dsygvx, range il=1..iu=nev);
 * 1 <= nev <= n.  lambda[nev], V[n*nev] or NULL.  Same results as
 * mm_linalg_sygv's first nev, for less work when nev << n. */
int mm_linalg_sygv_first(int n, int nev, const double *K, const double *M,
                         double *lambda, double *V, mm_error *err);

/* Only the nev lowest eigenpairs of banded K and M (half-bandwidth kd, band
 * storage as MM_LINALG_BAND_INDEX above; both share the same kd, pack the
 * narrower one with zeros).  1 <= nev <= min(n, MM_LINALG_MAX_NEV),
 * n <= MM_LINALG_MAX_BAND_N,
 * 0 <= kd <= MM_LINALG_MAX_KD, kd < n.  Kb, Mb have n*(kd+1) doubles and are
 * not modified; lambda[nev], V[n*nev] or NULL.  Eigenvalues by LAPACK dsbgvx
 * (no n x n matrix is formed), modes by inverse iteration with a banded LU
 * of K - lambda M, so memory is O(n*kd) and the cost O(n^2 kd + nev n kd^2).
 * MM_ENOCONV if a mode does not converge (eigenvalues so close that a mode
 * cannot be separated: use the dense solver). */
int mm_linalg_sbgv_first(int n, int kd, int nev, const double *Kb,
                         const double *Mb, double *lambda, double *V,
                         mm_error *err);

/* Eigenpairs il..iu (1-based, in ascending order of the eigenvalues;
 * 1 <= il <= iu <= n) of the symmetric tridiagonal matrix with diagonal
 * d[n] and off-diagonal e[n-1] (LAPACK dstevx: bisection to full accuracy,
 * then inverse iteration, so O(n (iu - il + 1)) work beyond an O(n^2)
 * worst case, not the O(n^3) of all vectors): lambda[iu - il + 1]
 * ascending, Z[n * (iu - il + 1)] (or NULL) column-major, eigenvector j in
 * Z[j*n .. j*n + n-1], each of Euclidean norm 1, sign as LAPACK leaves it.
 * d and e are not modified.  The small projected problem of a Lanczos
 * iteration (mm_fem).  MM_ERANGE ("n", "il"), MM_EVALUE (non-finite
 * entries), MM_ENOCONV (an eigenvector failed to converge), MM_ENOMEM. */
int mm_linalg_stev(int n, const double *d, const double *e, int il, int iu, double *lambda,
                   double *Z, mm_error *err);

/* ---- general (nonsymmetric) eigenproblem A v = lambda v -------------------- */

/* Eigenvalues of the general n x n A (LAPACK dgeev, with balancing):
 * lambda_j = wr[j] + i wi[j], in LAPACK's order (not sorted); a complex
 * conjugate pair occupies two consecutive entries, positive imaginary part
 * first.  A is not modified.  VR (n x n, or NULL) receives the right
 * eigenvectors, each of Euclidean norm 1, in LAPACK's packing: for a real
 * lambda_j, column j is the vector; for a pair (j, j+1), columns j and j+1
 * are the real and imaginary parts of the vector of lambda_j, and the vector
 * of lambda_{j+1} is their conjugate.
 * Fails with MM_ERANGE ("n"), MM_EVALUE ("A"), MM_ENOCONV (QR iteration did
 * not converge), MM_ENOMEM, MM_EINTERNAL. */
int mm_linalg_geev(int n, const double *A, double *wr, double *wi, double *VR,
                   mm_error *err);

/* ---- double-double: small problems with every digit, and its bound -------- */
/*
 * The same problems, solved in double-double arithmetic (~32 digits,
 * solvers/mm_dd.h) by simple methods (Jacobi rotations, Gaussian
 * elimination) and returned rounded to double with an error bound that
 * comes from residuals computed from the given data, not from trust in the
 * method.  For the learner's exercises (n <= 12), where a printed number
 * must be right to its last digit, and as an independent reference for the
 * LAPACK results above.  Work: n^3 operations in software arithmetic, about
 * 1 ms at n = 12 (24 for an SVD).  Thread-safe, no LAPACK.
 *
 * A bound err for a value x means |x - x_exact| <= err, where x_exact is
 * the exact answer for the given doubles, up to the double-double rounding
 * of the bound's own computation (a relative 1e-30 of it).  A double
 * rounding of x_exact is in every bound, so err is never below half an ulp
 * of x unless x is exact.
 */

#define MM_LINALG_DD_MAX_N 32     /* largest order (m + n for the SVD) */

/* Eigenvalues of the symmetric pencil K v = lambda M v (M symmetric
 * positive definite; M NULL means the identity), ascending, each with its
 * bound lambda_err[j].  V (n x n, or NULL) receives the modes, rounded to
 * double, M-normalised, signs as in mm_linalg_sygv.  Fails with MM_ERANGE
 * (n outside 1..MM_LINALG_DD_MAX_N, "n"), MM_EVALUE (non-finite or not
 * symmetric, "K"/"M"), MM_ESINGULAR (M not positive definite to ~32
 * digits, "M"), MM_ENOMEM. */
int mm_linalg_sygv_dd(int n, const double *K, const double *M, double *lambda, double *lambda_err,
                      double *V, mm_error *err);

/* Singular values of the m x n A, descending, into s[min(m,n)], each with
 * its bound s_err (s >= 0; a singular value whose bound reaches 0 may be
 * 0).  Needs m + n <= MM_LINALG_DD_MAX_N.  Fails with MM_ERANGE ("A"),
 * MM_EVALUE ("A"), MM_ENOMEM. */
int mm_linalg_svdvals_dd(int m, int n, const double *A, double *s, double *s_err, mm_error *err);

/* x = A^-1 b for the n x n A, rounded to double, each x[i] with its bound
 * x_err[i] = ||b - A x_dd||_2 / sigma_min + |x[i] - x_dd[i]|, where
 * sigma_min > 0 is a LOWER BOUND of A's smallest singular value (from
 * mm_linalg_svdvals_dd: s[n-1] - s_err[n-1]).  *residual (may be NULL)
 * receives ||b - A x_dd||_2 with its rounding.  Fails with MM_ERANGE,
 * MM_EVALUE, MM_ESINGULAR (sigma_min <= 0, or a zero pivot, "A"),
 * MM_ENONFINITE ("b"), MM_ENOMEM. */
int mm_linalg_solve_dd(int n, const double *A, const double *b, double sigma_min, double *x,
                       double *x_err, double *residual, mm_error *err);

/* r = b - A x for the n x n A, computed in double-double and rounded: the
 * true residual of the stored x to ~1e-32 of mag, where mag[i] =
 * sum_j |A_ij x_j| + |b_i| (also returned: the size of the terms, the
 * scale of every rounding bound).  Cannot fail. */
void mm_linalg_residual_dd(int n, const double *A, const double *x, const double *b, double *r, double *mag);

/* ||v||_2 without overflow or underflow in the squares.  Cannot fail. */
double mm_linalg_norm2(int n, const double *v);

/* For eigenpairs printed in double (lambda with its bound lambda_err, V the
 * M-normalised modes of the pencil K, M, n x n): how far they are from
 * eq. K v = lambda M v and from V^T M V = I, each relative to what rounding
 * the modes and eigenvalues to 16 digits explains (computed in
 * double-double, component by component):
 *   *res  = max |K v - lambda M v|_i / (u (|K||v| + |lambda||M||v|)_i + lambda_err (|M||v|)_i),
 *   *orth = max |v_j^T M v_l - delta_jl| / (2 u |v_j|^T |M| |v_l|);
 * both at most 1 for modes right to their last digit.  Cannot fail. */
void mm_linalg_sygv_rounding(int n, const double *K, const double *M, const double *lambda,
                             const double *lambda_err, const double *V, double *res, double *orth);

/* ---- a complex linear system (chapter 5, vibrations: steady amplitudes) ---- */

/* Solve the complex n x n system (Are + i Aim) x = bre + i bim as the real
 * 2n x 2n system [Are -Aim; Aim Are] [xre; xim] = [bre; bim] by
 * mm_linalg_solve (2n <= MM_LINALG_MAX_N).  Are, Aim row-major n x n; bre,
 * bim, xre, xim n values; info (may be NULL) receives the real system's
 * (its rcond bounds the complex one's condition).  Errors those of
 * mm_linalg_solve, MM_ENOMEM. */
int mm_linalg_solve_complex(int n, const double *Are, const double *Aim, const double *bre, const double *bim,
                            double *xre, double *xim, mm_linalg_solve_info *info, mm_error *err);

#endif
