/* mm_linalg.c — dense and banded linear algebra on top of LAPACKE.
 *
 * The only file of the project that includes lapacke.h (STYLE.md §1).
 * Contracts are in mm_linalg.h; this file explains the how.
 *
 * Layout trick used throughout: a row-major m x n array, read as a
 * column-major array with leading dimension n, is the transpose A^T.  So
 * instead of letting LAPACKE's row-major wrappers copy and transpose every
 * matrix, we call the column-major routines on A^T and ask for the
 * transposed operation ("solve A^T^T x = b" = trans 'T'), or use the fact
 * that the answer is the same for A^T (singular values, symmetric matrices).
 */
#include "mm_linalg.h"

#include <assert.h>
#include <float.h>
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <lapacke.h>

/* One lock around every call into LAPACK and the BLAS.  Debian's default
 * BLAS and LAPACK (the alternatives point at libopenblas0-serial 0.3.21)
 * come from an OpenBLAS built single-threaded WITHOUT USE_LOCKING, and such
 * a build shares its pool of scratch buffers between threads without a
 * lock: two threads in a BLAS call at the same moment can be handed the
 * same buffer and write into each other's data.  Measured on this machine:
 * 1 to 22 of 160,000 64 x 64 dgemm products from 8 threads wrong, and
 * dsygvd eigenvectors off by up to 0.7 in 3 of 24,000 calls under load
 * (tests/unit/test_linalg.c "identical answers from many threads").  The
 * calls are short (microseconds at the sizes of the exercises), so a lock
 * costs little; it makes the answers right and bit-identical whatever the
 * BLAS the machine selects. */
static pthread_mutex_t lapack_lock = PTHREAD_MUTEX_INITIALIZER;

#define LAPACK_CALL(li, call)                 \
    do {                                      \
        pthread_mutex_lock(&lapack_lock);     \
        (li) = (call);                        \
        pthread_mutex_unlock(&lapack_lock);   \
    } while (0)

/* ==== small helpers ======================================================== */

/* LAPACKE's own errors: -1010 (work array) and -1011 (transpose copy) mean
 * malloc failed inside LAPACKE; any other info < 0 is an illegal argument,
 * which after our checks can only be our bug. */
static int lapack_fail(mm_error *err, lapack_int info, const char *routine)
{
    if (info == LAPACK_WORK_MEMORY_ERROR || info == LAPACK_TRANSPOSE_MEMORY_ERROR)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory in %s", routine);
    return mm_error_set(err, MM_EINTERNAL, "",
                        "%s rejected argument %d", routine, (int)-info);
}

static void *alloc_doubles(size_t count)
{
    return malloc((count ? count : 1) * sizeof(double));
}

int mm_linalg_check_finite(const char *param, size_t count, const double *a,
                           mm_error *err)
{
    for (size_t k = 0; k < count; k++)
        if (!isfinite(a[k]))
            return mm_error_set(err, MM_EVALUE, param,
                                "bad value in '%s' (entries must be finite "
                                "numbers, got %g at position %zu)",
                                param, a[k], k + 1);
    return MM_OK;
}

/* Same check for a row-major matrix, naming the entry as (row, column),
 * 1-based as a learner would count. */
static int check_matrix(const char *param, int m, int n, const double *a,
                        mm_error *err)
{
    for (int i = 0; i < m; i++)
        for (int j = 0; j < n; j++) {
            double v = a[(size_t)i * (size_t)n + (size_t)j];
            if (!isfinite(v))
                return mm_error_set(err, MM_EVALUE, param,
                                    "bad value in '%s' (entries must be finite "
                                    "numbers, got %g at (%d,%d))",
                                    param, v, i + 1, j + 1);
        }
    return MM_OK;
}

static int check_order(const char *param, int n, int max, mm_error *err)
{
    if (n < 1 || n > max)
        return mm_error_set(err, MM_ERANGE, param,
                            "bad parameter '%s' (must be between 1 and %d, got %d)",
                            param, max, n);
    return MM_OK;
}

int mm_linalg_is_symmetric(int n, const double *a, int *bad_i, int *bad_j)
{
    assert(n >= 0 && a);
    double amax = 0.0;
    size_t nn = (size_t)n * (size_t)n;
    for (size_t k = 0; k < nn; k++)
        amax = fmax(amax, fabs(a[k]));
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            if (!(fabs(a[(size_t)i * (size_t)n + (size_t)j] - a[(size_t)j * (size_t)n + (size_t)i]) <=
                  MM_LINALG_SYM_TOL * amax)) {
                if (bad_i)
                    *bad_i = i;
                if (bad_j)
                    *bad_j = j;
                return 0;
            }
    return 1;
}

static int check_symmetric(const char *param, int n, const double *a,
                           mm_error *err)
{
    int i, j;
    if (mm_linalg_is_symmetric(n, a, &i, &j))
        return MM_OK;
    return mm_error_set(err, MM_EVALUE, param,
                        "bad value in '%s' (must be symmetric, but "
                        "%s(%d,%d) = %g and %s(%d,%d) = %g)",
                        param, param, i + 1, j + 1, a[(size_t)i * (size_t)n + (size_t)j],
                        param, j + 1, i + 1, a[(size_t)j * (size_t)n + (size_t)i]);
}

/* Sign convention of mm_linalg.h: the first component of the mode (stride
 * apart in v) whose magnitude exceeds 1e-8 of the largest is positive.  The
 * threshold skips components that are zero in exact arithmetic and come out
 * as rounding noise of either sign. */
static void fix_sign(int n, double *v, size_t stride)
{
    double vmax = 0.0;
    for (int i = 0; i < n; i++)
        vmax = fmax(vmax, fabs(v[(size_t)i * stride]));
    for (int i = 0; i < n; i++) {
        double vi = v[(size_t)i * stride];
        if (fabs(vi) > 1e-8 * vmax) {
            if (vi < 0)
                for (int k = 0; k < n; k++)
                    v[(size_t)k * stride] = -v[(size_t)k * stride];
            return;
        }
    }
}

/* Column-major n x m Z (mode j = Z[j*n ...]) -> row-major V (mode j in
 * column j of an n x m array), with the sign convention applied. */
static void modes_out(int n, int m, const double *Z, double *V)
{
    for (int j = 0; j < m; j++)
        for (int i = 0; i < n; i++)
            V[(size_t)i * (size_t)m + (size_t)j] = Z[(size_t)j * (size_t)n + (size_t)i];
    for (int j = 0; j < m; j++)
        fix_sign(n, V + j, (size_t)m);
}

void mm_linalg_band_pack(int n, int kd, const double *A, double *Ab)
{
    assert(n >= 1 && kd >= 0 && A && Ab);
    for (int i = 0; i < n; i++)
        for (int d = 0; d <= kd; d++)
            Ab[MM_LINALG_BAND_INDEX(kd, i, i + d)] =
                i + d < n ? A[(size_t)i * (size_t)n + (size_t)(i + d)] : 0.0;
}

/* ==== linear systems ======================================================== */

int mm_linalg_solve(int n, int nrhs, const double *A, const double *B,
                    double *X, mm_linalg_solve_info *info, mm_error *err)
{
    int rc;
    assert(A && B && X);
    if ((rc = check_order("n", n, MM_LINALG_MAX_N, err)) ||
        (rc = check_order("nrhs", nrhs, MM_LINALG_MAX_NRHS, err)) ||
        (rc = check_matrix("A", n, n, A, err)) ||
        (rc = mm_linalg_check_finite("b", (size_t)n * (size_t)nrhs, B, err)))
        return rc;

    size_t nn = (size_t)n * (size_t)n, nb = (size_t)n * (size_t)nrhs;
    double *a = alloc_doubles(nn), *af = alloc_doubles(nn);
    double *b = alloc_doubles(nb), *x = alloc_doubles(nb);
    double *r = alloc_doubles((size_t)n), *c = alloc_doubles((size_t)n);
    double *ferr = alloc_doubles((size_t)nrhs), *berr = alloc_doubles((size_t)nrhs);
    lapack_int *ipiv = malloc((size_t)n * sizeof *ipiv);
    mm_linalg_solve_info inf = {0};
    if (!a || !af || !b || !x || !r || !c || !ferr || !berr || !ipiv) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory solving a %d x %d system", n, n);
        goto out;
    }
    /* Row-major A is column-major A^T: solve (A^T)^T x = b with trans 'T'.
     * B goes column-major (one column per right-hand side). */
    memcpy(a, A, nn * sizeof *a);
    for (int i = 0; i < n; i++)
        for (int k = 0; k < nrhs; k++)
            b[(size_t)k * (size_t)n + (size_t)i] = B[(size_t)i * (size_t)nrhs + (size_t)k];

    char equed = 'N';
    double rpivot = 0.0;
    /* 'E': equilibrate rows and columns, factor, estimate rcond, solve, and
     * improve x by iterative refinement (error bounds ferr/berr). */
    lapack_int li;
    LAPACK_CALL(li, LAPACKE_dgesvx(LAPACK_COL_MAJOR, 'E', 'T', n, nrhs, a, n,
                                   af, n, ipiv, &equed, r, c, b, n, x, n,
                                   &inf.rcond, ferr, berr, &rpivot));
    if (li < 0) {
        rc = lapack_fail(err, li, "dgesvx");
        goto out;
    }
    if (li > 0 && li <= n) {   /* U(li,li) exactly zero: x not computed */
        inf.rcond = 0.0;
        inf.warn = 1;
        rc = mm_error_set(err, MM_ESINGULAR, "A",
                          "the matrix 'A' is singular (zero pivot in column %d "
                          "of the elimination): some equations are combinations "
                          "of others, so there is no unique solution", (int)li);
        goto out;
    }
    /* li == n+1 means rcond < eps: covered by the test below */
    /* Below n*eps the solution may have no correct digit, yet the residual
     * is still small (backward stability): like MATLAB, answer and warn
     * loudly; only an exact zero pivot above is refused. */
    inf.warn = inf.rcond < MM_LINALG_RCOND_WARN;
    inf.untrusted = !(inf.rcond >= n * DBL_EPSILON);

    for (size_t k = 0; k < nb; k++)
        if (!isfinite(x[k])) {
            rc = mm_error_set(err, MM_ENONFINITE, "b",
                              "the solution overflows (entries of 'A' or 'b' too "
                              "large or too small)");
            goto out;
        }
    /* Residual r = b - A x with the original A and b, and the normwise
     * backward error ||r|| / (||A|| ||x|| + ||b||) (Rigal-Gaches). */
    double anorm = 0.0;
    for (int i = 0; i < n; i++) {
        double s = 0.0;
        for (int j = 0; j < n; j++)
            s += fabs(A[(size_t)i * (size_t)n + (size_t)j]);
        anorm = fmax(anorm, s);
    }
    for (int k = 0; k < nrhs; k++) {
        const double *xk = x + (size_t)k * (size_t)n;
        double r2 = 0.0, rinf = 0.0, xinf = 0.0, binf = 0.0;
        for (int i = 0; i < n; i++) {
            double bi = B[(size_t)i * (size_t)nrhs + (size_t)k], s = bi;
            for (int j = 0; j < n; j++)
                s -= A[(size_t)i * (size_t)n + (size_t)j] * xk[j];
            r2 += s * s;
            rinf = fmax(rinf, fabs(s));
            xinf = fmax(xinf, fabs(xk[i]));
            binf = fmax(binf, fabs(bi));
        }
        double denom = anorm * xinf + binf;
        inf.residual = fmax(inf.residual, sqrt(r2));
        inf.backward_error = fmax(inf.backward_error, denom > 0 ? rinf / denom : 0.0);
        inf.ferr = fmax(inf.ferr, ferr[k]);
    }
    for (int i = 0; i < n; i++)          /* X may alias B: B was copied above */
        for (int k = 0; k < nrhs; k++)
            X[(size_t)i * (size_t)nrhs + (size_t)k] = x[(size_t)k * (size_t)n + (size_t)i];
    rc = MM_OK;
out:
    if (info)
        *info = inf;
    free(ipiv); free(berr); free(ferr); free(c); free(r);
    free(x); free(b); free(af); free(a);
    return rc;
}

static int check_rect(int m, int n, mm_error *err)
{
    int rc;
    if ((rc = check_order("m", m, MM_LINALG_MAX_ROWS, err)) ||
        (rc = check_order("n", n, MM_LINALG_MAX_N, err)))
        return rc;
    if ((long long)m * n > MM_LINALG_MAX_ELEMS)
        return mm_error_set(err, MM_ERANGE, "m",
                            "matrix too large (%d x %d = %lld entries, at most %d)",
                            m, n, (long long)m * n, MM_LINALG_MAX_ELEMS);
    return MM_OK;
}

int mm_linalg_svdvals(int m, int n, const double *A, double *s, mm_error *err)
{
    int rc;
    assert(A && s);
    if ((rc = check_rect(m, n, err)) || (rc = check_matrix("A", m, n, A, err)))
        return rc;
    double *a = alloc_doubles((size_t)m * (size_t)n);
    if (!a)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory for an SVD");
    memcpy(a, A, (size_t)m * (size_t)n * sizeof *a);
    /* column-major view: the n x m matrix A^T, same singular values */
    lapack_int li;
    LAPACK_CALL(li, LAPACKE_dgesdd(LAPACK_COL_MAJOR, 'N', n, m, a, n, s,
                                   NULL, 1, NULL, 1));
    if (li < 0)
        rc = lapack_fail(err, li, "dgesdd");
    else if (li > 0)
        rc = mm_error_set(err, MM_ENOCONV, "A",
                          "the singular value decomposition of 'A' did not converge");
    else
        rc = MM_OK;
    free(a);
    return rc;
}

int mm_linalg_cond2(int m, int n, const double *A, double *cond, mm_error *err)
{
    int rc, k = m < n ? m : n;
    assert(cond);
    *cond = NAN;
    if ((rc = check_rect(m, n, err)))
        return rc;
    double *s = alloc_doubles((size_t)k);
    if (!s)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory for an SVD");
    if ((rc = mm_linalg_svdvals(m, n, A, s, err)) == MM_OK) {
        if (s[k - 1] > 0.0) {
            *cond = s[0] / s[k - 1];
        } else {
            *cond = INFINITY;
            rc = mm_error_set(err, MM_ESINGULAR, "A",
                              "the matrix 'A' is singular (its smallest singular "
                              "value is zero), so its condition number is infinite");
        }
    }
    free(s);
    return rc;
}

int mm_linalg_lstsq(int m, int n, int nrhs, const double *A, const double *B,
                    double rcond, double *X, int *rank, double *resid,
                    double *sv, mm_error *err)
{
    int rc;
    assert(A && B && X && X != B);
    if ((rc = check_rect(m, n, err)) ||
        (rc = check_order("nrhs", nrhs, MM_LINALG_MAX_NRHS, err)) ||
        (rc = check_matrix("A", m, n, A, err)) ||
        (rc = mm_linalg_check_finite("b", (size_t)m * (size_t)nrhs, B, err)))
        return rc;
    if ((long long)(m > n ? m : n) * nrhs > MM_LINALG_MAX_ELEMS)
        return mm_error_set(err, MM_ERANGE, "nrhs",
                            "too many right-hand sides (%d for %d rows)", nrhs, m);

    int mx = m > n ? m : n, k = m < n ? m : n;
    double *a = alloc_doubles((size_t)m * (size_t)n);
    double *b = alloc_doubles((size_t)mx * (size_t)nrhs);
    double *s = alloc_doubles((size_t)k);
    if (!a || !b || !s) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory for least squares");
        goto out;
    }
    /* dgelsd needs A itself (not A^T): transpose into column-major.  B is
     * column-major with max(m,n) rows, the first n of which return X. */
    for (int i = 0; i < m; i++)
        for (int j = 0; j < n; j++)
            a[(size_t)j * (size_t)m + (size_t)i] = A[(size_t)i * (size_t)n + (size_t)j];
    memset(b, 0, (size_t)mx * (size_t)nrhs * sizeof *b);
    for (int i = 0; i < m; i++)
        for (int c = 0; c < nrhs; c++)
            b[(size_t)c * (size_t)mx + (size_t)i] = B[(size_t)i * (size_t)nrhs + (size_t)c];
    if (!(rcond > 0.0))
        rcond = mx * DBL_EPSILON;            /* MATLAB's pinv tolerance */
    lapack_int lrank = 0;
    lapack_int li;
    LAPACK_CALL(li, LAPACKE_dgelsd(LAPACK_COL_MAJOR, m, n, nrhs, a, m, b, mx,
                                   s, rcond, &lrank));
    if (li < 0) {
        rc = lapack_fail(err, li, "dgelsd");
        goto out;
    }
    if (li > 0) {
        rc = mm_error_set(err, MM_ENOCONV, "A",
                          "the least-squares SVD of 'A' did not converge");
        goto out;
    }
    for (int j = 0; j < n; j++)
        for (int c = 0; c < nrhs; c++) {
            double v = b[(size_t)c * (size_t)mx + (size_t)j];
            if (!isfinite(v)) {
                rc = mm_error_set(err, MM_ENONFINITE, "b",
                                  "the least-squares solution overflows");
                goto out;
            }
            X[(size_t)j * (size_t)nrhs + (size_t)c] = v;
        }
    if (rank)
        *rank = (int)lrank;
    if (sv)
        memcpy(sv, s, (size_t)k * sizeof *s);
    if (resid)                 /* ||b - A x||_2 from the original data */
        for (int c = 0; c < nrhs; c++) {
            double r2 = 0.0;
            for (int i = 0; i < m; i++) {
                double ri = B[(size_t)i * (size_t)nrhs + (size_t)c];
                for (int j = 0; j < n; j++)
                    ri -= A[(size_t)i * (size_t)n + (size_t)j] *
                          X[(size_t)j * (size_t)nrhs + (size_t)c];
                r2 += ri * ri;
            }
            resid[c] = sqrt(r2);
        }
    rc = MM_OK;
out:
    free(s); free(b); free(a);
    return rc;
}

/* ==== symmetric generalized eigenproblem ===================================== */

static int mass_not_pd(mm_error *err, int minor)
{
    return mm_error_set(err, MM_ESINGULAR, "M",
                        "mass matrix is not positive definite (its leading "
                        "%d x %d block is not): every mode must carry kinetic "
                        "energy, check for zero or negative masses", minor, minor);
}

static int eig_noconv(mm_error *err, const char *routine, int count)
{
    return mm_error_set(err, MM_ENOCONV, "K",
                        "the eigenvalue iteration (%s) did not converge "
                        "(%d values or vectors failed)", routine, count);
}

static int check_pair(int n, const double *K, const double *M, mm_error *err)
{
    int rc;
    if ((rc = check_matrix("K", n, n, K, err)) ||
        (rc = check_matrix("M", n, n, M, err)) ||
        (rc = check_symmetric("K", n, K, err)) ||
        (rc = check_symmetric("M", n, M, err)))
        return rc;
    return MM_OK;
}

int mm_linalg_sygv(int n, const double *K, const double *M, double *lambda,
                   double *V, mm_error *err)
{
    int rc;
    assert(K && M && lambda);
    if ((rc = check_order("n", n, MM_LINALG_MAX_N, err)) ||
        (rc = check_pair(n, K, M, err)))
        return rc;
    size_t nn = (size_t)n * (size_t)n;
    double *k = alloc_doubles(nn), *m = alloc_doubles(nn);
    if (!k || !m) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory for eigenvalues");
        goto out;
    }
    memcpy(k, K, nn * sizeof *k);
    memcpy(m, M, nn * sizeof *m);
    /* symmetric, so the column-major view is the same matrix; the row-major
     * upper triangle is the column-major lower one: uplo 'L'.  itype 1:
     * K v = lambda M v, vectors returned with Z^T M Z = I. */
    lapack_int li;
    LAPACK_CALL(li, LAPACKE_dsygvd(LAPACK_COL_MAJOR, 1, V ? 'V' : 'N', 'L', n,
                                   k, n, m, n, lambda));
    if (li < 0)
        rc = lapack_fail(err, li, "dsygvd");
    else if (li > n)
        rc = mass_not_pd(err, (int)li - n);
    else if (li > 0)
        rc = eig_noconv(err, "dsygvd", (int)li);
    else {
        if (V)
            modes_out(n, n, k, V);
        rc = MM_OK;
    }
out:
    free(m); free(k);
    return rc;
}

int mm_linalg_stev(int n, const double *d, const double *e, int il, int iu, double *lambda,
                   double *Z, mm_error *err)
{
    int rc;
    assert(d && lambda && (n == 1 || e));
    if ((rc = check_order("n", n, MM_LINALG_MAX_N, err)) ||
        (rc = mm_linalg_check_finite("d", (size_t)n, d, err)) ||
        (rc = mm_linalg_check_finite("e", (size_t)n - 1, e, err)))
        return rc;
    if (il < 1 || il > iu || iu > n)
        return mm_error_set(err, MM_ERANGE, "il", "eigenvalue indices %d..%d outside 1..%d", il, iu, n);
    double *dd = alloc_doubles((size_t)n), *ee = alloc_doubles((size_t)n);
    lapack_int *ifail = malloc((size_t)n * sizeof *ifail), m = 0;
    if (!dd || !ee || !ifail) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory for eigenvalues");
        goto out;
    }
    memcpy(dd, d, (size_t)n * sizeof *dd);
    if (n > 1)
        memcpy(ee, e, (size_t)(n - 1) * sizeof *ee);
    lapack_int li;
    /* abstol = 2 x the underflow threshold: eigenvalues to full relative
     * accuracy where the matrix determines them so (LAPACK's advice) */
    LAPACK_CALL(li, LAPACKE_dstevx(LAPACK_COL_MAJOR, Z ? 'V' : 'N', 'I', n, dd, ee, 0.0, 0.0, il, iu,
                                   2 * DBL_MIN, &m, lambda, Z, n, ifail));
    if (li < 0)
        rc = lapack_fail(err, li, "dstevx");
    else if (li > 0 || m != iu - il + 1)
        rc = eig_noconv(err, "dstevx", li > 0 ? (int)li : 1);
    else
        rc = MM_OK;
out:
    free(ifail);
    free(ee);
    free(dd);
    return rc;
}

int mm_linalg_sygv_first(int n, int nev, const double *K, const double *M,
                         double *lambda, double *V, mm_error *err)
{
    int rc;
    assert(K && M && lambda);
    if ((rc = check_order("n", n, MM_LINALG_MAX_N, err)) ||
        (rc = check_order("nev", nev, n, err)) ||
        (rc = check_pair(n, K, M, err)))
        return rc;
    size_t nn = (size_t)n * (size_t)n;
    double *k = alloc_doubles(nn), *m = alloc_doubles(nn), *w = alloc_doubles((size_t)n);
    double *z = V ? alloc_doubles((size_t)n * (size_t)nev) : NULL;
    lapack_int *ifail = malloc((size_t)n * sizeof *ifail);
    if (!k || !m || !w || (V && !z) || !ifail) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory for eigenvalues");
        goto out;
    }
    memcpy(k, K, nn * sizeof *k);
    memcpy(m, M, nn * sizeof *m);
    lapack_int found = 0;
    double dummy = 0.0;
    /* range 'I' il..iu = 1..nev; abstol 2*safmin: eigenvalues to full
     * relative accuracy (LAPACK's advice for dsygvx) */
    lapack_int li;
    LAPACK_CALL(li, LAPACKE_dsygvx(LAPACK_COL_MAJOR, 1, V ? 'V' : 'N', 'I', 'L',
                                   n, k, n, m, n, 0.0, 0.0, 1, nev,
                                   2.0 * LAPACKE_dlamch('S'), &found, w,
                                   V ? z : &dummy, n, ifail));
    if (li < 0)
        rc = lapack_fail(err, li, "dsygvx");
    else if (li > n)
        rc = mass_not_pd(err, (int)li - n);
    else if (li > 0)
        rc = eig_noconv(err, "dsygvx", (int)li);
    else if (found != nev)
        rc = mm_error_set(err, MM_EINTERNAL, "", "dsygvx found %d of %d modes",
                          (int)found, nev);
    else {
        memcpy(lambda, w, (size_t)nev * sizeof *w);
        if (V)
            modes_out(n, nev, z, V);
        rc = MM_OK;
    }
out:
    free(ifail); free(z); free(w); free(m); free(k);
    return rc;
}

/* ---- banded: eigenvalues by dsbgvx, modes by inverse iteration ------------- */

/* A(i,j) of a symmetric matrix in our band storage, 0 outside the band. */
static double band_at(const double *Ab, int kd, int i, int j)
{
    if (i > j) { int t = i; i = j; j = t; }
    return j - i <= kd ? Ab[MM_LINALG_BAND_INDEX(kd, i, j)] : 0.0;
}

/* y = A x for symmetric banded A. */
static void band_mv(int n, int kd, const double *Ab, const double *x, double *y)
{
    for (int i = 0; i < n; i++) {
        int lo = i - kd < 0 ? 0 : i - kd, hi = i + kd >= n ? n - 1 : i + kd;
        double s = 0.0;
        for (int j = lo; j <= hi; j++)
            s += band_at(Ab, kd, i, j) * x[j];
        y[i] = s;
    }
}

/* Infinity norm of symmetric banded A. */
static double band_norm(int n, int kd, const double *Ab)
{
    double nrm = 0.0;
    for (int i = 0; i < n; i++) {
        int lo = i - kd < 0 ? 0 : i - kd, hi = i + kd >= n ? n - 1 : i + kd;
        double s = 0.0;
        for (int j = lo; j <= hi; j++)
            s += fabs(band_at(Ab, kd, i, j));
        nrm = fmax(nrm, s);
    }
    return nrm;
}

static int check_band(const char *param, int n, int kd, const double *Ab,
                      mm_error *err)
{
    for (int i = 0; i < n; i++)
        for (int d = 0; d <= kd && i + d < n; d++) {
            double v = Ab[MM_LINALG_BAND_INDEX(kd, i, i + d)];
            if (!isfinite(v))
                return mm_error_set(err, MM_EVALUE, param,
                                    "bad value in '%s' (entries must be finite "
                                    "numbers, got %g at (%d,%d))",
                                    param, v, i + 1, i + d + 1);
        }
    return MM_OK;
}

/* Deterministic, stateless start vector for mode j (inverse iteration
 * needs a start with a component along the wanted mode; a fixed
 * pseudo-random one has it with probability 1 and keeps runs repeatable). */
static void start_vector(int n, int j, double *x)
{
    uint64_t s = UINT64_C(0x9E3779B97F4A7C15) * (uint64_t)(j + 1);
    for (int i = 0; i < n; i++) {
        s ^= s << 13; s ^= s >> 7; s ^= s << 17;             /* xorshift64 */
        x[i] = (double)(s >> 11) / 9007199254740992.0 - 0.5;  /* in [-0.5,0.5) */
    }
}

int mm_linalg_sbgv_first(int n, int kd, int nev, const double *Kb,
                         const double *Mb, double *lambda, double *V,
                         mm_error *err)
{
    int rc;
    assert(Kb && Mb && lambda);
    if ((rc = check_order("n", n, MM_LINALG_MAX_BAND_N, err)))
        return rc;
    if (kd < 0 || kd > MM_LINALG_MAX_KD || kd >= n)
        return mm_error_set(err, MM_ERANGE, "kd",
                            "bad parameter 'kd' (half-bandwidth must be between 0 "
                            "and min(n-1, %d), got %d)", MM_LINALG_MAX_KD, kd);
    if ((rc = check_order("nev", nev, n < MM_LINALG_MAX_NEV ? n : MM_LINALG_MAX_NEV, err)) ||
        (rc = check_band("K", n, kd, Kb, err)) ||
        (rc = check_band("M", n, kd, Mb, err)))
        return rc;

    size_t nb = (size_t)n * (size_t)(kd + 1);
    int ldlu = 3 * kd + 1;                     /* dgbtrf: 2*kl + ku + 1 */
    double *kb = alloc_doubles(nb), *mb = alloc_doubles(nb), *w = alloc_doubles((size_t)n);
    double *lu = NULL, *x = NULL, *y = NULL, *t = NULL, *z = NULL;
    lapack_int *ifail = malloc((size_t)n * sizeof *ifail), *ipiv = NULL;
    if (V) {
        lu = alloc_doubles((size_t)ldlu * (size_t)n);
        x = alloc_doubles((size_t)n); y = alloc_doubles((size_t)n);
        t = alloc_doubles((size_t)n);
        z = alloc_doubles((size_t)n * (size_t)nev);
        ipiv = malloc((size_t)n * sizeof *ipiv);
    }
    if (!kb || !mb || !w || !ifail ||
        (V && (!lu || !x || !y || !t || !z || !ipiv))) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory for banded eigenvalues");
        goto out;
    }
    memcpy(kb, Kb, nb * sizeof *kb);
    memcpy(mb, Mb, nb * sizeof *mb);

    /* Our layout is LAPACK's column-major lower band storage, ldab = kd+1.
     * jobz 'N': no n x n transformation matrix is formed. */
    lapack_int found = 0;
    double dq = 0.0, dz = 0.0;
    lapack_int li;
    LAPACK_CALL(li, LAPACKE_dsbgvx(LAPACK_COL_MAJOR, 'N', 'I', 'L', n, kd, kd,
                                   kb, kd + 1, mb, kd + 1, &dq, 1, 0.0, 0.0,
                                   1, nev, 2.0 * LAPACKE_dlamch('S'), &found, w,
                                   &dz, 1, ifail));
    if (li < 0) {
        rc = lapack_fail(err, li, "dsbgvx");
        goto out;
    }
    if (li > n) {
        rc = mass_not_pd(err, (int)li - n);
        goto out;
    }
    if (li > 0) {
        rc = eig_noconv(err, "dsbgvx", (int)li);
        goto out;
    }
    if (found != nev) {
        rc = mm_error_set(err, MM_EINTERNAL, "", "dsbgvx found %d of %d modes",
                          (int)found, nev);
        goto out;
    }
    memcpy(lambda, w, (size_t)nev * sizeof *w);
    if (!V) {
        rc = MM_OK;
        goto out;
    }

    /* Modes by inverse iteration: (K - lambda_j M) y = M x, then
     * M-orthogonalise against the modes already found whose eigenvalues lie
     * within the cluster gap (as LAPACK dstein does), M-normalise, repeat
     * until the residual ||K y - lambda M y|| is at rounding level. */
    double knorm = band_norm(n, kd, Kb), mnorm = band_norm(n, kd, Mb);
    double scale = knorm / mnorm;              /* ~ largest eigenvalue */
    double gap = 1e-3 * scale;                 /* dstein's cluster rule */
    const int max_it = 8;
    for (int j = 0; j < nev; j++) {
        double sigma = lambda[j];
        /* LU of K - sigma M in LAPACK general band storage (kl = ku = kd) */
        memset(lu, 0, (size_t)ldlu * (size_t)n * sizeof *lu);
        for (int c = 0; c < n; c++) {
            int lo = c - kd < 0 ? 0 : c - kd, hi = c + kd >= n ? n - 1 : c + kd;
            for (int r = lo; r <= hi; r++)
                lu[(size_t)c * (size_t)ldlu + (size_t)(2 * kd + r - c)] =
                    band_at(Kb, kd, r, c) - sigma * band_at(Mb, kd, r, c);
        }
        LAPACK_CALL(li, LAPACKE_dgbtrf(LAPACK_COL_MAJOR, n, n, kd, kd, lu, ldlu, ipiv));
        if (li < 0) {
            rc = lapack_fail(err, li, "dgbtrf");
            goto out;
        }
        /* An exactly zero pivot (sigma hit the eigenvalue exactly) is
         * replaced by a tiny one: the solve then blows up along the mode,
         * which is what inverse iteration wants. */
        for (int c = 0; c < n; c++) {
            double *u = &lu[(size_t)c * (size_t)ldlu + (size_t)(2 * kd)];
            if (*u == 0.0)
                *u = DBL_EPSILON * (knorm + fabs(sigma) * mnorm);
        }
        start_vector(n, j, x);
        int converged = 0;
        for (int it = 0; it < max_it && !converged; it++) {
            band_mv(n, kd, Mb, x, y);
            LAPACK_CALL(li, LAPACKE_dgbtrs(LAPACK_COL_MAJOR, 'N', n, kd, kd, 1, lu, ldlu,
                                ipiv, y, n));
            if (li < 0) {
                rc = lapack_fail(err, li, "dgbtrs");
                goto out;
            }
            /* scale down before orthogonalising: y may be ~1/eps large */
            double ymax = 0.0;
            for (int i = 0; i < n; i++)
                ymax = fmax(ymax, fabs(y[i]));
            if (!(ymax > 0.0 && isfinite(ymax)))
                break;
            for (int i = 0; i < n; i++)
                y[i] /= ymax;
            for (int pass = 0; pass < 2; pass++)      /* twice is enough */
                for (int p = 0; p < j; p++) {
                    if (fabs(lambda[p] - sigma) > gap)
                        continue;
                    const double *vp = z + (size_t)p * (size_t)n;
                    band_mv(n, kd, Mb, vp, t);
                    double d = 0.0;
                    for (int i = 0; i < n; i++)
                        d += t[i] * y[i];
                    for (int i = 0; i < n; i++)
                        y[i] -= d * vp[i];
                }
            band_mv(n, kd, Mb, y, t);
            double ymy = 0.0;
            for (int i = 0; i < n; i++)
                ymy += y[i] * t[i];
            if (!(ymy > 0.0))
                break;
            double f = 1.0 / sqrt(ymy), rmax = 0.0, vmax = 0.0;
            for (int i = 0; i < n; i++) {
                y[i] *= f;
                t[i] *= f;                     /* t = M y */
            }
            band_mv(n, kd, Kb, y, x);          /* x = K y, reused as scratch */
            for (int i = 0; i < n; i++) {
                rmax = fmax(rmax, fabs(x[i] - sigma * t[i]));
                vmax = fmax(vmax, fabs(y[i]));
            }
            /* backward-error test: residual at a modest multiple of the
             * rounding level of K y and lambda M y */
            converged = rmax <= 1e3 * DBL_EPSILON * (knorm + fabs(sigma) * mnorm) * vmax;
            memcpy(x, y, (size_t)n * sizeof *x);
        }
        if (!converged) {
            rc = mm_error_set(err, MM_ENOCONV, "K",
                              "mode %d could not be separated from its neighbours "
                              "by inverse iteration (eigenvalues too close); use "
                              "the dense solver", j + 1);
            goto out;
        }
        memcpy(z + (size_t)j * (size_t)n, x, (size_t)n * sizeof *x);
    }
    modes_out(n, nev, z, V);
    rc = MM_OK;
out:
    free(ipiv); free(z); free(t); free(y); free(x); free(lu);
    free(ifail); free(w); free(mb); free(kb);
    return rc;
}

/* ==== general eigenproblem ================================================== */

int mm_linalg_geev(int n, const double *A, double *wr, double *wi, double *VR,
                   mm_error *err)
{
    int rc;
    assert(A && wr && wi);
    if ((rc = check_order("n", n, MM_LINALG_MAX_N, err)) ||
        (rc = check_matrix("A", n, n, A, err)))
        return rc;
    size_t nn = (size_t)n * (size_t)n;
    double *a = alloc_doubles(nn);
    if (!a)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory for eigenvalues");
    memcpy(a, A, nn * sizeof *a);
    /* Row-major here: eigenvectors of A^T would be the wrong (left) ones,
     * and the O(n^2) transposition in LAPACKE is small beside O(n^3). */
    lapack_int li;
    LAPACK_CALL(li, LAPACKE_dgeev(LAPACK_ROW_MAJOR, 'N', VR ? 'V' : 'N', n, a, n,
                                  wr, wi, NULL, n, VR, n));
    if (li < 0)
        rc = lapack_fail(err, li, "dgeev");
    else if (li > 0)
        rc = mm_error_set(err, MM_ENOCONV, "A",
                          "the eigenvalue iteration (QR algorithm) on 'A' did "
                          "not converge (%d eigenvalues missing)", (int)li);
    else
        rc = MM_OK;
    free(a);
    return rc;
}

/* ==== a complex linear system (chapter 5, vibrations) ========================= */

int mm_linalg_solve_complex(int n, const double *Are, const double *Aim, const double *bre, const double *bim,
                            double *xre, double *xim, mm_linalg_solve_info *info, mm_error *err)
{
    size_t N = 2 * (size_t)n;
    double *Z = malloc((N * N + 2 * N) * sizeof *Z), *b = Z ? Z + N * N : NULL, *x = b ? b + N : NULL;
    if (!Z)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory solving a complex system");
    for (size_t r = 0; r < (size_t)n; r++) {
        for (size_t k = 0; k < (size_t)n; k++) {
            Z[N * r + k] = Z[N * (r + n) + k + n] = Are[n * r + k];
            Z[N * r + k + n] = -Aim[n * r + k];
            Z[N * (r + n) + k] = Aim[n * r + k];
        }
        b[r] = bre[r], b[r + n] = bim[r];
    }
    mm_linalg_solve_info own;
    int rc = mm_linalg_solve((int)N, 1, Z, b, x, info ? info : &own, err);
    if (rc == MM_OK)
        for (size_t r = 0; r < (size_t)n; r++)
            xre[r] = x[r], xim[r] = x[r + n];
    free(Z);
    return rc;
}
