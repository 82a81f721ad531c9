/* mm_linalg_dd.c — small dense problems in double-double arithmetic, with
 * error bounds: the references the LAPACK (double) results are checked
 * against, and the values an exercise prints when every digit must be true.
 * Contracts in mm_linalg.h ("double-double").
 *
 * Eigenvalues: the pencil (K, M) is reduced to C = L^-1 K L^-T (M = L L^T
 * by Cholesky) and C diagonalised by cyclic Jacobi rotations (Golub & Van
 * Loan, Matrix Computations, 4th ed., 8.5), all in double-double.  The
 * bounds do not trust that computation: they come from the residuals
 * s_j = K v_j - theta_j M v_j, computed in double-double from the given K
 * and M, through the residual theorem for symmetric matrices (Parlett, The
 * Symmetric Eigenvalue Problem, Thm 11.5.1, after Kahan): for the
 * orthonormal Y = L^T V of a cluster of k Ritz values there are k
 * eigenvalues within ||C Y - Y Theta||_2 <= ||L^-1 S||_F of them.  Singular
 * values are the eigenvalues of [0 A; A^T 0].  Linear systems: Gaussian
 * elimination with partial pivoting and one step of refinement, all in
 * double-double; the bound is ||x - x_true|| <= ||b - A x|| / sigma_min.
 */
#include "mm_linalg.h"

#include <assert.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mm_dd.h"

#define JACOBI_SWEEPS 40

static int check_dims(int n, mm_error *err)
{
    if (n < 1 || n > MM_LINALG_DD_MAX_N)
        return mm_error_set(err, MM_ERANGE, "n", "bad parameter 'n' (the double-double routines take "
                            "1 to %d unknowns, got %d)", MM_LINALG_DD_MAX_N, n);
    return MM_OK;
}

static int all_finite(const char *param, size_t count, const double *a, mm_error *err)
{
    return a ? mm_linalg_check_finite(param, count, a, err) : MM_OK;
}

/* 2^-e for the largest |a|: the scaled matrix has entries below 2 in size,
 * exactly (so nothing squared in the bounds can overflow or underflow);
 * 1 for a zero matrix.  even: an even power, whose square root is exact. */
static double pow2_scale(size_t count, const double *a, int even)
{
    double big = 0;
    for (size_t k = 0; k < count; k++)
        big = fmax(big, fabs(a[k]));
    if (!(big > 0))
        return 1;
    int e = ilogb(big);
    if (e < -1000)                                   /* subnormal: 2^-e would overflow */
        e = -1000;
    if (even && (e & 1))
        e++;
    return ldexp(1, -e);
}

static double *scaled_copy(size_t count, const double *a, double s)
{
    double *c = malloc((count ? count : 1) * sizeof *c);
    for (size_t k = 0; c && k < count; k++)
        c[k] = a[k] * s;
    return c;
}

/* ---- Jacobi ------------------------------------------------------------------ */

/* Diagonalise the symmetric n x n c (row-major, dd) by cyclic Jacobi: on
 * return the diagonal of c holds the eigenvalues and column j of q
 * (initialised here) the eigenvector of c[j][j].  A rotation is skipped
 * when |c_pq| is negligible beside sqrt(|c_pp c_qq|) (this is what gives
 * tiny eigenvalues their relative accuracy), or beside the matrix when the
 * diagonal is zero.  Whatever is left after JACOBI_SWEEPS sweeps shows in
 * the residual bounds; nothing here needs to be trusted. */
static void jacobi(int n, mm_dd *c, mm_dd *q)
{
    double big = 0;
    for (int k = 0; k < n * n; k++)
        big = fmax(big, mm_dd_abs(c[k]));
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            q[i * n + j] = mm_dd_from(i == j);
    const double tiny = 1e-34 * big + DBL_MIN;
    for (int sweep = 0; sweep < JACOBI_SWEEPS; sweep++) {
        int rotated = 0;
        for (int p = 0; p < n; p++)
            for (int r = p + 1; r < n; r++) {
                mm_dd apq = c[p * n + r];
                double a = mm_dd_abs(apq);
                if (a <= 1e-33 * sqrt(mm_dd_abs(c[p * n + p]) * mm_dd_abs(c[r * n + r])) || a <= tiny)
                    continue;
                rotated = 1;
                /* theta = (c_rr - c_pp) / (2 c_pq); t = sign / (|theta| + sqrt(theta^2 + 1)) */
                mm_dd theta = mm_dd_div(mm_dd_sub(c[r * n + r], c[p * n + p]), mm_dd_mul_d(apq, 2));
                mm_dd t;
                if (fabs(theta.hi) > 1e100) {
                    t = mm_dd_div(mm_dd_from(0.5), theta);
                } else {
                    mm_dd root = mm_dd_sqrt(mm_dd_add(mm_dd_mul(theta, theta), mm_dd_from(1)));
                    mm_dd den = theta.hi >= 0 ? mm_dd_add(theta, root) : mm_dd_sub(theta, root);
                    t = mm_dd_div(mm_dd_from(1), den);
                }
                mm_dd cs = mm_dd_div(mm_dd_from(1), mm_dd_sqrt(mm_dd_add(mm_dd_mul(t, t), mm_dd_from(1))));
                mm_dd sn = mm_dd_mul(t, cs);
                mm_dd tap = mm_dd_mul(t, apq), app = c[p * n + p], arr = c[r * n + r];
                for (int k = 0; k < n; k++) {             /* columns p, r */
                    mm_dd ckp = c[k * n + p], ckr = c[k * n + r];
                    c[k * n + p] = mm_dd_sub(mm_dd_mul(cs, ckp), mm_dd_mul(sn, ckr));
                    c[k * n + r] = mm_dd_add(mm_dd_mul(sn, ckp), mm_dd_mul(cs, ckr));
                }
                for (int k = 0; k < n; k++) {             /* rows p, r */
                    mm_dd cpk = c[p * n + k], crk = c[r * n + k];
                    c[p * n + k] = mm_dd_sub(mm_dd_mul(cs, cpk), mm_dd_mul(sn, crk));
                    c[r * n + k] = mm_dd_add(mm_dd_mul(sn, cpk), mm_dd_mul(cs, crk));
                }
                /* the 2 x 2 block exactly as the rotation makes it */
                c[p * n + p] = mm_dd_sub(app, tap);
                c[r * n + r] = mm_dd_add(arr, tap);
                c[p * n + r] = c[r * n + p] = mm_dd_from(0);
                for (int k = 0; k < n; k++) {
                    mm_dd qkp = q[k * n + p], qkr = q[k * n + r];
                    q[k * n + p] = mm_dd_sub(mm_dd_mul(cs, qkp), mm_dd_mul(sn, qkr));
                    q[k * n + r] = mm_dd_add(mm_dd_mul(sn, qkp), mm_dd_mul(cs, qkr));
                }
            }
        if (!rotated)
            break;
    }
}

/* ---- the symmetric-definite pencil ---------------------------------------------- */

static double norm2(int n, const mm_dd *v)
{
    double big = 0, s = 0;
    for (int i = 0; i < n; i++)
        big = fmax(big, mm_dd_abs(v[i]));
    if (big == 0)
        return 0;
    for (int i = 0; i < n; i++)
        s += (mm_dd_abs(v[i]) / big) * (mm_dd_abs(v[i]) / big);
    return big * sqrt(s);
}

/* A(i,j) of a symmetric matrix given by its upper triangle (the triangle
 * the symmetric solvers use), or of I when a is NULL. */
static double sym(int n, const double *a, int i, int j)
{
    if (!a)
        return i == j;
    return i <= j ? a[(size_t)i * (size_t)n + (size_t)j] : a[(size_t)j * (size_t)n + (size_t)i];
}

/* Residual bounds of the Ritz pairs (theta_j, v_j) of (K, M), with Kahan's
 * theorem applied to clusters of overlapping intervals: bound[j] such that
 * the j-th eigenvalue (ascending) lies within bound[j] of theta_j.
 * L is M's Cholesky factor (NULL for M = I); y = L^T v are the Jacobi
 * vectors (orthonormal to ~1e-31). */
static void bounds(int n, const double *K, const double *M, const mm_dd *L, const mm_dd *theta,
                   const mm_dd *v, const mm_dd *y, double *bound, mm_dd *s, mm_dd *r)
{
    /* ||L^-1||_F, for the rounding of the residuals themselves */
    double linv = 1;
    if (L) {
        double acc = 0;
        for (int j = 0; j < n; j++) {             /* column j of L^-1: solve L z = e_j */
            for (int i = 0; i < n; i++) {
                mm_dd t = mm_dd_from(i == j);
                for (int k = 0; k < i; k++)
                    t = mm_dd_sub(t, mm_dd_mul(L[i * n + k], r[k]));
                r[i] = mm_dd_div(t, L[i * n + i]);
            }
            double nz = norm2(n, r);
            acc += nz * nz;
        }
        linv = sqrt(acc);
    }
    /* Y^T Y - I: Kahan's theorem wants orthonormal Y */
    double eta = 0;
    for (int j = 0; j < n; j++)
        for (int k = 0; k <= j; k++) {
            mm_dd g = mm_dd_from(0);
            for (int i = 0; i < n; i++)
                g = mm_dd_add(g, mm_dd_mul(y[i * n + j], y[i * n + k]));
            eta = fmax(eta, mm_dd_abs(mm_dd_sub(g, mm_dd_from(j == k))));
        }
    double orth = eta < 0.01 ? 1 / (1 - n * eta) : INFINITY;
    double *rho = malloc((size_t)n * sizeof *rho);
    int *grp = malloc((size_t)n * sizeof *grp);
    if (!rho || !grp) {                           /* no memory: no bound, said so */
        for (int j = 0; j < n; j++)
            bound[j] = INFINITY;
        free(rho); free(grp);
        return;
    }
    for (int j = 0; j < n; j++) {
        double size = 0;                          /* |K||v| + |theta||M||v|, 2-norm */
        for (int i = 0; i < n; i++) {
            mm_dd t = mm_dd_from(0);
            double a = 0;
            for (int k = 0; k < n; k++) {
                double kik = sym(n, K, i, k), mik = sym(n, M, i, k);
                mm_dd vk = v[k * n + j];
                t = mm_dd_add(t, mm_dd_mul_d(vk, kik));
                t = mm_dd_sub(t, mm_dd_mul(theta[j], mm_dd_mul_d(vk, mik)));
                a += fabs(kik * vk.hi) + fabs(theta[j].hi) * fabs(mik * vk.hi);
            }
            s[i] = t;
            size += a * a;
        }
        if (L)
            for (int i = 0; i < n; i++) {         /* r = L^-1 s */
                mm_dd t = s[i];
                for (int k = 0; k < i; k++)
                    t = mm_dd_sub(t, mm_dd_mul(L[i * n + k], r[k]));
                r[i] = mm_dd_div(t, L[i * n + i]);
            }
        else
            memcpy(r, s, (size_t)n * sizeof *r);
        double ny = 0;
        for (int i = 0; i < n; i++)
            ny += mm_dd_abs(y[i * n + j]) * mm_dd_abs(y[i * n + j]);
        ny = sqrt(ny);
        /* the residual, plus what rounding in computing it can hide (each
         * dd operation 4 u^2 relative, 3n + 2 of them a component), with a
         * margin of 1 % for the double-precision norms */
        double rounding = (3.0 * n + 2) * MM_DD_EPS * sqrt(size) * linv;
        rho[j] = 1.01 * (norm2(n, r) + rounding) / (ny > 0 ? ny : 1) * orth;
    }
    /* clusters: Ritz values whose intervals overlap share one Kahan bound,
     * sqrt(sum rho^2) >= ||R_cluster||_2; merge until the intervals are apart */
    for (int j = 0; j < n; j++)
        grp[j] = j;
    for (int pass = 0; pass < n; pass++) {
        for (int j = 0; j < n; j++) {             /* bound of each group */
            double sq = 0;
            for (int k = 0; k < n; k++)
                if (grp[k] == grp[j])
                    sq += rho[k] * rho[k];
            bound[j] = sqrt(sq);
        }
        int merged = 0;
        for (int j = 0; j + 1 < n; j++)           /* theta ascending: neighbours */
            if (grp[j] != grp[j + 1] &&
                !(theta[j].hi + bound[j] < theta[j + 1].hi - bound[j + 1])) {
                int old = grp[j + 1];
                for (int k = 0; k < n; k++)
                    if (grp[k] == old)
                        grp[k] = grp[j];
                merged = 1;
            }
        if (!merged)
            break;
    }
    free(grp);
    free(rho);
}

/* The eigen-decomposition shared by the public functions: K symmetric, M
 * symmetric positive definite or NULL (= I).  theta ascending (dd), v the
 * vectors (column j, dd, M-orthonormal), bound[j] as above. */
static int pencil(int n, const double *K, const double *M, mm_dd *theta, mm_dd *v, double *bound,
                  mm_error *err)
{
    size_t nn = (size_t)n * (size_t)n;
    mm_dd *L = M ? malloc(nn * sizeof *L) : NULL, *c = malloc(nn * sizeof *c), *q = malloc(nn * sizeof *q);
    mm_dd *s = malloc((size_t)n * sizeof *s), *r = malloc((size_t)n * sizeof *r);
    int *order = malloc((size_t)n * sizeof *order);
    int rc = MM_OK;
    if ((M && !L) || !c || !q || !s || !r || !order) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory for a double-double eigenproblem");
        goto out;
    }
    if (M) {                                      /* Cholesky M = L L^T */
        for (int j = 0; j < n; j++) {
            mm_dd d = mm_dd_from(sym(n, M, j, j));
            for (int k = 0; k < j; k++)
                d = mm_dd_sub(d, mm_dd_mul(L[j * n + k], L[j * n + k]));
            if (!(d.hi > 0)) {
                rc = mm_error_set(err, MM_ESINGULAR, "M", "mass matrix is not positive definite (its "
                                  "leading %d x %d block is not): every mode must carry kinetic energy, "
                                  "check for zero or negative masses", j + 1, j + 1);
                goto out;
            }
            L[j * n + j] = mm_dd_sqrt(d);
            for (int i = j + 1; i < n; i++) {
                mm_dd t = mm_dd_from(sym(n, M, i, j));
                for (int k = 0; k < j; k++)
                    t = mm_dd_sub(t, mm_dd_mul(L[i * n + k], L[j * n + k]));
                L[i * n + j] = mm_dd_div(t, L[j * n + j]);
            }
            for (int i = 0; i < j; i++)
                L[i * n + j] = mm_dd_from(0);
        }
        /* q = L^-1 K (column by column), then c = L^-1 q^T = L^-1 K L^-T */
        for (int col = 0; col < n; col++)
            for (int i = 0; i < n; i++) {
                mm_dd t = mm_dd_from(sym(n, K, i, col));
                for (int k = 0; k < i; k++)
                    t = mm_dd_sub(t, mm_dd_mul(L[i * n + k], q[k * n + col]));
                q[i * n + col] = mm_dd_div(t, L[i * n + i]);
            }
        for (int col = 0; col < n; col++)
            for (int i = 0; i < n; i++) {
                mm_dd t = q[col * n + i];
                for (int k = 0; k < i; k++)
                    t = mm_dd_sub(t, mm_dd_mul(L[i * n + k], c[k * n + col]));
                c[i * n + col] = mm_dd_div(t, L[i * n + i]);
            }
        for (int i = 0; i < n; i++)               /* symmetric to the last bit */
            for (int j = 0; j < i; j++) {
                mm_dd m = mm_dd_mul_d(mm_dd_add(c[i * n + j], c[j * n + i]), 0.5);
                c[i * n + j] = c[j * n + i] = m;
            }
    } else {
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++)
                c[i * n + j] = mm_dd_from(sym(n, K, i, j));
    }
    jacobi(n, c, q);
    /* ascending order (a stable insertion sort: n is small) */
    for (int j = 0; j < n; j++)
        order[j] = j;
    for (int j = 1; j < n; j++)
        for (int k = j; k > 0 && mm_dd_sub(c[order[k - 1] * n + order[k - 1]], c[order[k] * n + order[k]]).hi > 0;
             k--) {
            int t = order[k];
            order[k] = order[k - 1];
            order[k - 1] = t;
        }
    mm_dd *y = c;                                 /* c's off-diagonal is no longer needed */
    for (int j = 0; j < n; j++)
        theta[j] = c[order[j] * n + order[j]];
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++)
            y[i * n + j] = q[i * n + order[j]];
    /* v = L^-T y */
    for (int j = 0; j < n; j++)
        for (int i = n - 1; i >= 0; i--) {
            mm_dd t = y[i * n + j];
            if (M) {
                for (int k = i + 1; k < n; k++)
                    t = mm_dd_sub(t, mm_dd_mul(L[k * n + i], v[k * n + j]));
                t = mm_dd_div(t, L[i * n + i]);
            }
            v[i * n + j] = t;
        }
    bounds(n, K, M, L, theta, v, y, bound, s, r);
out:
    free(order); free(r); free(s); free(q); free(c); free(L);
    return rc;
}

static int check_pencil(int n, const double *K, const double *M, mm_error *err)
{
    int rc, i, j;
    size_t nn = (size_t)n * (size_t)n;
    if ((rc = check_dims(n, err)) || (rc = all_finite("K", nn, K, err)) || (rc = all_finite("M", nn, M, err)))
        return rc;
    if (!mm_linalg_is_symmetric(n, K, &i, &j))
        return mm_error_set(err, MM_EVALUE, "K", "bad value in 'K' (must be symmetric, but K(%d,%d) = %g and "
                            "K(%d,%d) = %g)", i + 1, j + 1, K[i * n + j], j + 1, i + 1, K[j * n + i]);
    if (M && !mm_linalg_is_symmetric(n, M, &i, &j))
        return mm_error_set(err, MM_EVALUE, "M", "bad value in 'M' (must be symmetric, but M(%d,%d) = %g and "
                            "M(%d,%d) = %g)", i + 1, j + 1, M[i * n + j], j + 1, i + 1, M[j * n + i]);
    return MM_OK;
}

int mm_linalg_sygv_dd(int n, const double *K, const double *M, double *lambda, double *lambda_err,
                      double *V, mm_error *err)
{
    assert(K && lambda && lambda_err);
    int rc = check_pencil(n, K, M, err);
    if (rc)
        return rc;
    size_t nn = (size_t)n * (size_t)n;
    /* K and M scaled by powers of 2 (exact): lambda scales by sk / sm, the
     * M-normalised modes by sqrt(sm) (sm an even power: exact too) */
    double sk = pow2_scale(nn, K, 0), sm = M ? pow2_scale(nn, M, 1) : 1, back = sm / sk, vback = sqrt(sm);
    double *Ks = scaled_copy(nn, K, sk), *Ms = M ? scaled_copy(nn, M, sm) : NULL;
    mm_dd *theta = malloc((size_t)n * sizeof *theta), *v = malloc(nn * sizeof *v);
    double *bound = malloc((size_t)n * sizeof *bound);
    if (!Ks || (M && !Ms) || !theta || !v || !bound) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory for a double-double eigenproblem");
        goto out;
    }
    if ((rc = pencil(n, Ks, Ms, theta, v, bound, err)))
        goto out;
    for (int j = 0; j < n; j++) {
        mm_dd t = mm_dd_mul_d(theta[j], back);
        lambda[j] = mm_dd_val(t);
        lambda_err[j] = bound[j] * back + mm_dd_abs(mm_dd_sub(t, mm_dd_from(lambda[j])));
        if (!isfinite(lambda[j]) || !isfinite(lambda_err[j])) {
            rc = mm_error_set(err, MM_ENONFINITE, "K", "the eigenvalues overflow the doubles (K / M beyond "
                              "1e308): choose other units for K and M");
            goto out;
        }
    }
    if (V) {
        for (size_t k = 0; k < nn; k++)
            V[k] = mm_dd_val(v[k]) * vback;
        for (int j = 0; j < n; j++) {             /* mm_linalg.h's sign convention */
            double vmax = 0;
            for (int i = 0; i < n; i++)
                vmax = fmax(vmax, fabs(V[i * n + j]));
            for (int i = 0; i < n; i++)
                if (fabs(V[i * n + j]) > 1e-8 * vmax) {
                    if (V[i * n + j] < 0)
                        for (int k = 0; k < n; k++)
                            V[k * n + j] = -V[k * n + j];
                    break;
                }
        }
    }
out:
    free(bound); free(v); free(theta); free(Ms); free(Ks);
    return rc;
}

int mm_linalg_svdvals_dd(int m, int n, const double *A, double *s, double *s_err, mm_error *err)
{
    assert(A && s && s_err);
    int rc, N = m + n, k = m < n ? m : n;
    if (m < 1 || n < 1 || N > MM_LINALG_DD_MAX_N)
        return mm_error_set(err, MM_ERANGE, "A", "bad parameter 'A' (the double-double SVD takes m + n <= %d, "
                            "got %d x %d)", MM_LINALG_DD_MAX_N, m, n);
    if ((rc = all_finite("A", (size_t)m * (size_t)n, A, err)))
        return rc;
    double sa = pow2_scale((size_t)m * (size_t)n, A, 0);   /* exact: singular values scale by sa */
    double *H = calloc((size_t)N * (size_t)N, sizeof *H), *bound = malloc((size_t)N * sizeof *bound);
    mm_dd *theta = malloc((size_t)N * sizeof *theta), *v = malloc((size_t)N * (size_t)N * sizeof *v);
    if (!H || !bound || !theta || !v) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory for a double-double SVD");
        goto out;
    }
    for (int i = 0; i < m; i++)                   /* H = [0 A; A^T 0] */
        for (int j = 0; j < n; j++)
            H[(size_t)i * N + (size_t)(m + j)] = H[(size_t)(m + j) * N + (size_t)i] = A[(size_t)i * n + j] * sa;
    if ((rc = pencil(N, H, NULL, theta, v, bound, err)))
        goto out;
    for (int i = 0; i < k; i++) {                 /* the k largest, descending */
        mm_dd t = mm_dd_mul_d(theta[N - 1 - i], 1 / sa);
        double val = mm_dd_val(t);
        s[i] = val > 0 ? val : 0;
        s_err[i] = bound[N - 1 - i] / sa + mm_dd_abs(mm_dd_sub(t, mm_dd_from(s[i])));
    }
out:
    free(v); free(theta); free(bound); free(H);
    return rc;
}

/* ---- linear systems ---------------------------------------------------------------- */

/* x = A^-1 b by partial pivoting in dd on the n x (n + 1) augmented lu. */
static int gepp(int n, mm_dd *lu, mm_dd *x)
{
    int w = n + 1;
    for (int c = 0; c < n; c++) {
        int p = c;
        for (int r = c + 1; r < n; r++)
            if (mm_dd_abs(lu[r * w + c]) > mm_dd_abs(lu[p * w + c]))
                p = r;
        if (mm_dd_abs(lu[p * w + c]) == 0)
            return -1;
        if (p != c)
            for (int k = 0; k < w; k++) {
                mm_dd t = lu[p * w + k];
                lu[p * w + k] = lu[c * w + k];
                lu[c * w + k] = t;
            }
        for (int r = c + 1; r < n; r++) {
            mm_dd f = mm_dd_div(lu[r * w + c], lu[c * w + c]);
            for (int k = c; k < w; k++)
                lu[r * w + k] = mm_dd_sub(lu[r * w + k], mm_dd_mul(f, lu[c * w + k]));
        }
    }
    for (int i = n - 1; i >= 0; i--) {
        mm_dd t = lu[i * w + n];
        for (int k = i + 1; k < n; k++)
            t = mm_dd_sub(t, mm_dd_mul(lu[i * w + k], x[k]));
        x[i] = mm_dd_div(t, lu[i * w + i]);
    }
    return 0;
}

int mm_linalg_solve_dd(int n, const double *A, const double *b, double sigma_min, double *x,
                       double *x_err, double *residual, mm_error *err)
{
    assert(A && b && x && x_err);
    int rc;
    if ((rc = check_dims(n, err)) || (rc = all_finite("A", (size_t)n * (size_t)n, A, err)) ||
        (rc = all_finite("b", (size_t)n, b, err)))
        return rc;
    if (!(sigma_min > 0))
        return mm_error_set(err, MM_ESINGULAR, "A", "the matrix 'A' is singular to the precision of the "
                            "computation: no bound of its smallest singular value above 0");
    /* A and b scaled by powers of 2 (exact): x = x' sa / sb */
    double sa = pow2_scale((size_t)n * (size_t)n, A, 0), sb = pow2_scale((size_t)n, b, 0), xs = sa / sb;
    double *As = scaled_copy((size_t)n * (size_t)n, A, sa), *bs = scaled_copy((size_t)n, b, sb);
    sigma_min *= sa;
    mm_dd *lu = malloc((size_t)n * (size_t)(n + 1) * sizeof *lu);
    mm_dd *xd = malloc((size_t)n * sizeof *xd), *d = malloc((size_t)n * sizeof *d);
    mm_dd *r = malloc((size_t)n * sizeof *r);
    if (!As || !bs || !lu || !xd || !d || !r) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory for a double-double solve");
        goto out;
    }
    double rn = 0, size = 0;
    for (int step = 0; step < 2; step++) {        /* solve, then refine once */
        for (int i = 0; i < n; i++) {
            mm_dd t = mm_dd_from(bs[i]);
            double a = fabs(bs[i]);
            for (int k = 0; k < n && step > 0; k++) {
                t = mm_dd_sub(t, mm_dd_mul_d(xd[k], As[(size_t)i * n + k]));
                a += fabs(As[(size_t)i * n + k] * xd[k].hi);
            }
            r[i] = t;
            size += step > 0 ? a * a : 0;
            for (int k = 0; k < n; k++)
                lu[i * (n + 1) + k] = mm_dd_from(As[(size_t)i * n + k]);
            lu[i * (n + 1) + n] = t;
        }
        if (gepp(n, lu, d) != 0) {
            rc = mm_error_set(err, MM_ESINGULAR, "A", "the matrix 'A' is singular: a zero pivot in "
                              "double-double elimination");
            goto out;
        }
        for (int i = 0; i < n; i++)
            xd[i] = step == 0 ? d[i] : mm_dd_add(xd[i], d[i]);
    }
    size = 0;                                     /* the final residual b - A x */
    for (int i = 0; i < n; i++) {
        mm_dd t = mm_dd_from(bs[i]);
        double a = fabs(bs[i]);
        for (int k = 0; k < n; k++) {
            t = mm_dd_sub(t, mm_dd_mul_d(xd[k], As[(size_t)i * n + k]));
            a += fabs(As[(size_t)i * n + k] * xd[k].hi);
        }
        r[i] = t;
        size += a * a;
    }
    rn = norm2(n, r) + (2.0 * n + 2) * MM_DD_EPS * sqrt(size);
    double fe = 1.01 * rn / sigma_min;            /* ||x - x_true||_2 <= ||r|| ||A^-1|| */
    for (int i = 0; i < n; i++) {
        xd[i] = mm_dd_mul_d(xd[i], xs);
        x[i] = mm_dd_val(xd[i]);
        if (!isfinite(x[i])) {
            rc = mm_error_set(err, MM_ENONFINITE, "b", "the solution overflows (entries of 'A' or 'b' too "
                              "large or too small)");
            goto out;
        }
        x_err[i] = fe * xs + mm_dd_abs(mm_dd_sub(xd[i], mm_dd_from(x[i])));
    }
    if (residual)
        *residual = rn / sb;
out:
    free(r); free(d); free(xd); free(lu); free(bs); free(As);
    return rc;
}

/* ---- rounding of results printed in double -------------------------------------- */

void mm_linalg_residual_dd(int n, const double *A, const double *x, const double *b, double *r, double *mag)
{
    assert(A && x && b && r && mag);
    for (int i = 0; i < n; i++) {
        mm_dd s = mm_dd_from(b[i]);
        mag[i] = fabs(b[i]);
        for (int j = 0; j < n; j++) {
            s = mm_dd_sub(s, mm_dd_two_prod(A[(size_t)i * n + j], x[j]));
            mag[i] += fabs(A[(size_t)i * n + j] * x[j]);
        }
        r[i] = mm_dd_val(s);
    }
}

double mm_linalg_norm2(int n, const double *v)
{
    double big = 0, s = 0;
    for (int i = 0; i < n; i++)
        big = fmax(big, fabs(v[i]));
    if (big == 0 || !isfinite(big))
        return big;
    for (int i = 0; i < n; i++)
        s += (v[i] / big) * (v[i] / big);
    return big * sqrt(s);
}

void mm_linalg_sygv_rounding(int n, const double *K, const double *M, const double *lambda,
                             const double *lambda_err, const double *V, double *res, double *orth)
{
    const double u = DBL_EPSILON / 2;
    double wres = 0, wort = 0;
    for (int j = 0; j < n; j++) {
        for (int i = 0; i < n; i++) {
            mm_dd r = mm_dd_from(0);
            double a = 0, m = 0;
            for (int k = 0; k < n; k++) {
                double v = V[k * n + j];
                r = mm_dd_add(r, mm_dd_two_prod(K[i * n + k], v));
                r = mm_dd_sub(r, mm_dd_mul_d(mm_dd_two_prod(M[i * n + k], v), lambda[j]));
                a += fabs(K[i * n + k] * v) + fabs(lambda[j]) * fabs(M[i * n + k] * v);
                m += fabs(M[i * n + k] * v);
            }
            double bi = u * a + lambda_err[j] * m + 8 * n * MM_DD_EPS * a;
            wres = fmax(wres, mm_dd_abs(r) / (1.01 * bi + DBL_MIN));
        }
        for (int l = 0; l <= j; l++) {                  /* v_j^T M v_l - delta_jl */
            mm_dd g = mm_dd_from(0);
            double a = 0;
            for (int i = 0; i < n; i++)
                for (int k = 0; k < n; k++) {
                    g = mm_dd_add(g, mm_dd_mul_d(mm_dd_two_prod(V[i * n + j], M[i * n + k]), V[k * n + l]));
                    a += fabs(V[i * n + j] * M[i * n + k] * V[k * n + l]);
                }
            double dev = mm_dd_abs(mm_dd_sub(g, mm_dd_from(j == l)));
            wort = fmax(wort, dev / (1.01 * (2 * u + 4 * n * n * MM_DD_EPS) * a + DBL_MIN));
        }
    }
    *res = wres;
    *orth = wort;
}
