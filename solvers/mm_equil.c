/* mm_equil.c — equilibrium equations: sparse-aware LU for the determinate
 * case, QR with column pivoting for the rank test and the null vectors.
 * The contract is in mm_equil.h; this file explains the how.
 */
#include "mm_equil.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

const char *mm_equil_kind_name(mm_equil_kind kind)
{
    switch (kind) {
    case MM_EQUIL_DETERMINATE: return "determinate";
    case MM_EQUIL_MECHANISM: return "mechanism";
    case MM_EQUIL_INDETERMINATE: return "statically indeterminate";
    case MM_EQUIL_CRITICAL: return "mechanism and statically indeterminate";
    }
    return "?";
}

void mm_equil_residual(int n_eq, int n_unk, const double *A, const double *b, const double *x,
                       double *residual, double *scale)
{
    double worst = 0, big = 0;
    for (int i = 0; i < n_eq; i++) {
        double r = b[i], s = fabs(b[i]);
        const double *row = A + (size_t)i * (size_t)n_unk;
        for (int j = 0; j < n_unk; j++) {
            r -= row[j] * x[j];
            s += fabs(row[j] * x[j]);
        }
        worst = fmax(worst, fabs(r));
        big = fmax(big, s);
    }
    *residual = worst;
    *scale = big;
}

/* ==== the matrix, compressed by columns ======================================= */

typedef struct csc {
    int m, n;
    int *cp;              /* n + 1 column starts */
    int *ri;              /* row of each entry */
    double *v;            /* value of each entry (duplicates kept: they add) */
} csc;

static void csc_free(csc *a)
{
    free(a->cp);
    free(a->ri);
    free(a->v);
}

static int csc_from_triplets(int m, int n, int nnz, const int *row, const int *col, const double *val,
                             csc *a)
{
    a->m = m, a->n = n;
    a->cp = calloc((size_t)n + 1, sizeof *a->cp);
    a->ri = malloc((size_t)(nnz ? nnz : 1) * sizeof *a->ri);
    a->v = malloc((size_t)(nnz ? nnz : 1) * sizeof *a->v);
    if (!a->cp || !a->ri || !a->v)
        return MM_ENOMEM;
    for (int k = 0; k < nnz; k++)
        a->cp[col[k] + 1]++;
    for (int j = 0; j < n; j++)
        a->cp[j + 1] += a->cp[j];
    int *next = malloc((size_t)(n ? n : 1) * sizeof *next);
    if (!next)
        return MM_ENOMEM;
    memcpy(next, a->cp, (size_t)n * sizeof *next);
    for (int k = 0; k < nnz; k++) {
        int q = next[col[k]]++;
        a->ri[q] = row[k];
        a->v[q] = val[k];
    }
    free(next);
    return MM_OK;
}

/* ==== equilibration ========================================================== */

/* A power of two near 1/v, so that scaling is exact (no rounding). */
static double pow2_inverse(double v)
{
    if (!(v > 0))
        return 1;
    int e;
    frexp(v, &e);                        /* v = f 2^e, f in [0.5, 1) */
    if (e > 1000)
        e = 1000;
    if (e < -1000)
        e = -1000;
    return ldexp(1.0, -e);
}

/* Row scales rs[m] and column scales cs[n]: the largest entry of each row of
 * R A, then of each column of R A C, lies in [0.5, 1).  rs holds the row
 * maxima on the way. */
static void equilibrate(const csc *a, double *rs, double *cs)
{
    for (int i = 0; i < a->m; i++)
        rs[i] = 0;
    for (int j = 0; j < a->n; j++)
        for (int q = a->cp[j]; q < a->cp[j + 1]; q++) {
            double v = fabs(a->v[q]);
            if (v > rs[a->ri[q]])
                rs[a->ri[q]] = v;
        }
    for (int i = 0; i < a->m; i++)
        rs[i] = pow2_inverse(rs[i]);
    for (int j = 0; j < a->n; j++) {
        double big = 0;
        for (int q = a->cp[j]; q < a->cp[j + 1]; q++) {
            double v = fabs(rs[a->ri[q]] * a->v[q]);
            if (v > big)
                big = v;
        }
        cs[j] = pow2_inverse(big);
    }
}

/* residual r = b - A x and, per row, |b| + sum |A x|; returns the largest of each */
static void csc_residual(const csc *a, const double *b, const double *x, double *r, double *s,
                         double *worst, double *scale)
{
    for (int i = 0; i < a->m; i++)
        r[i] = b[i], s[i] = fabs(b[i]);
    for (int j = 0; j < a->n; j++)
        for (int q = a->cp[j]; q < a->cp[j + 1]; q++) {
            double t = a->v[q] * x[j];
            r[a->ri[q]] -= t;
            s[a->ri[q]] += fabs(t);
        }
    double w = 0, big = 0;
    for (int i = 0; i < a->m; i++) {
        if (fabs(r[i]) > w)
            w = fabs(r[i]);
        if (s[i] > big)
            big = s[i];
    }
    *worst = w;
    *scale = big;
}

/* ==== LU with partial pivoting on a sparse matrix kept dense ================== */

typedef struct lu {
    int n;
    double *a;            /* n x n: unit L strictly below, U on and above */
    int *piv;             /* step k swapped rows k and piv[k] */
    int *chi;             /* the last row that may hold an entry of column k */
    int *rlo, *rhi;       /* the first and last column that may hold an entry of row i */
    int *col;             /* factored column k is column col[k] of the scaled A */
    int *lp, *li, *up, *ui;   /* rows of L and U, compressed (CSR) */
    double *lv, *uv;
    double *work;         /* n scratch values */
} lu;

static void lu_free(lu *f)
{
    free(f->a);
    free(f->piv);
    free(f->chi);
    free(f->rlo);
    free(f->rhi);
    free(f->col);
    free(f->lp);
    free(f->li);
    free(f->up);
    free(f->ui);
    free(f->lv);
    free(f->uv);
    free(f->work);
}

/* Columns in the order of their first nonzero row (a counting sort, stable),
 * all-zero columns last: for the banded structure of a truss numbered along
 * its span this keeps the elimination inside the band.  first holds 2n + 2
 * ints of scratch. */
static void order_columns(const csc *a, int *col, int *first)
{
    int n = a->n;
    int *count = first + n;
    memset(count, 0, (size_t)(n + 2) * sizeof *count);
    for (int j = 0; j < n; j++) {
        int f = n;
        for (int q = a->cp[j]; q < a->cp[j + 1]; q++)
            if (a->v[q] != 0 && a->ri[q] < f)
                f = a->ri[q];
        first[j] = f;
        count[f + 1]++;
    }
    for (int k = 1; k <= n + 1; k++)
        count[k] += count[k - 1];
    for (int j = 0; j < n; j++)
        col[count[first[j]]++] = j;
}

/* Factor P (As Q) = L U.  Returns -1, or the step at which no pivot larger
 * than tol was left (singular).  The envelopes keep every scan to where
 * entries can be: rows k..chi[k] of column k, columns rlo[i]..rhi[i] of
 * row i (filled in by the caller from the scattered entries). */
static int lu_factor(lu *f, double tol, int *list)
{
    int n = f->n;
    double *a = f->a;
    int *chi = f->chi, *rlo = f->rlo, *rhi = f->rhi;
    for (int k = 0; k < n; k++) {
        int p = k, last = chi[k];
        double amax = fabs(a[(size_t)k * n + k]);
        for (int i = k + 1; i <= last; i++) {
            double v = fabs(a[(size_t)i * n + k]);
            if (v > amax) {
                amax = v;
                p = i;
            }
        }
        if (!(amax > tol))
            return k;
        f->piv[k] = p;
        if (p != k) {
            double *rk = a + (size_t)k * n, *rp = a + (size_t)p * n;
            int lo = rlo[k] < rlo[p] ? rlo[k] : rlo[p], hi = rhi[k] > rhi[p] ? rhi[k] : rhi[p];
            for (int j = lo; j <= hi; j++) {
                double t = rk[j];
                rk[j] = rp[j];
                rp[j] = t;
                if (rp[j] != 0 && chi[j] < p)
                    chi[j] = p;
            }
            int t = rlo[k];
            rlo[k] = rlo[p], rlo[p] = t;
            t = rhi[k];
            rhi[k] = rhi[p], rhi[p] = t;
        }
        const double *rk = a + (size_t)k * n;
        int cnt = 0;
        for (int j = k + 1; j <= rhi[k]; j++)
            if (rk[j] != 0)
                list[cnt++] = j;
        double pivot = rk[k];
        for (int i = k + 1; i <= last; i++) {
            double *ri = a + (size_t)i * n;
            if (ri[k] == 0)
                continue;
            double l = ri[k] / pivot;
            ri[k] = l;
            for (int t = 0; t < cnt; t++) {
                int j = list[t];
                ri[j] -= l * rk[j];
                if (chi[j] < i)
                    chi[j] = i;
            }
            if (rhi[i] < rhi[k])
                rhi[i] = rhi[k];
        }
    }
    return -1;
}

/* The rows of L and U, compressed, so that each solve costs their nonzeros. */
static int lu_compress(lu *f)
{
    int n = f->n;
    size_t nl = 0, nu = 0;
    for (int i = 0; i < n; i++)
        for (int j = f->rlo[i]; j <= f->rhi[i]; j++)
            if (f->a[(size_t)i * n + j] != 0 || i == j) {
                if (j < i)
                    nl++;
                else
                    nu++;
            }
    f->lp = malloc((size_t)(n + 1) * sizeof *f->lp);
    f->up = malloc((size_t)(n + 1) * sizeof *f->up);
    f->li = malloc((nl ? nl : 1) * sizeof *f->li);
    f->ui = malloc((nu ? nu : 1) * sizeof *f->ui);
    f->lv = malloc((nl ? nl : 1) * sizeof *f->lv);
    f->uv = malloc((nu ? nu : 1) * sizeof *f->uv);
    if (!f->lp || !f->up || !f->li || !f->ui || !f->lv || !f->uv)
        return MM_ENOMEM;
    size_t kl = 0, ku = 0;
    for (int i = 0; i < n; i++) {
        f->lp[i] = (int)kl;
        f->up[i] = (int)ku;
        const double *ri = f->a + (size_t)i * n;
        for (int j = f->rlo[i]; j < i; j++)
            if (ri[j] != 0) {
                f->li[kl] = j;
                f->lv[kl++] = ri[j];
            }
        for (int j = i; j <= f->rhi[i]; j++)  /* the diagonal first: uv[up[i]] = U_ii */
            if (ri[j] != 0 || j == i) {
                f->ui[ku] = j;
                f->uv[ku++] = ri[j];
            }
    }
    f->lp[n] = (int)kl;
    f->up[n] = (int)ku;
    return MM_OK;
}

/* z = As^{-1} y (z may be y). */
static void lu_solve(const lu *f, const double *y, double *z)
{
    int n = f->n;
    double *w = f->work;
    memcpy(w, y, (size_t)n * sizeof *w);
    for (int k = 0; k < n; k++)          /* P y */
        if (f->piv[k] != k) {
            double t = w[k];
            w[k] = w[f->piv[k]];
            w[f->piv[k]] = t;
        }
    for (int i = 0; i < n; i++)          /* L w = P y */
        for (int t = f->lp[i]; t < f->lp[i + 1]; t++)
            w[i] -= f->lv[t] * w[f->li[t]];
    for (int i = n - 1; i >= 0; i--) {   /* U w = ... */
        double s = w[i];
        for (int t = f->up[i] + 1; t < f->up[i + 1]; t++)
            s -= f->uv[t] * w[f->ui[t]];
        w[i] = s / f->uv[f->up[i]];
    }
    for (int k = 0; k < n; k++)          /* z = Q w */
        z[f->col[k]] = w[k];
}

/* z = As^{-T} y (z may be y): U^T L^T P z = Q^T y. */
static void lu_solve_t(const lu *f, const double *y, double *z)
{
    int n = f->n;
    double *w = f->work;
    for (int k = 0; k < n; k++)
        w[k] = y[f->col[k]];
    for (int k = 0; k < n; k++) {        /* U^T v = Q^T y, by columns of U^T */
        w[k] /= f->uv[f->up[k]];
        for (int t = f->up[k] + 1; t < f->up[k + 1]; t++)
            w[f->ui[t]] -= f->uv[t] * w[k];
    }
    for (int k = n - 1; k >= 0; k--)     /* L^T t = v */
        for (int t = f->lp[k]; t < f->lp[k + 1]; t++)
            w[f->li[t]] -= f->lv[t] * w[k];
    for (int k = n - 1; k >= 0; k--)     /* z = P^T t */
        if (f->piv[k] != k) {
            double t = w[k];
            w[k] = w[f->piv[k]];
            w[f->piv[k]] = t;
        }
    memcpy(z, w, (size_t)n * sizeof *z);
}

/* Hager-Higham estimate of ||As^{-1}||_1 (N. J. Higham, Accuracy and
 * Stability of Numerical Algorithms, 2nd ed., algorithm 15.4): at most 5
 * pairs of solves.  v and s are n scratch values each. */
static double inverse_norm1(const lu *f, double *v, double *s)
{
    int n = f->n;
    for (int i = 0; i < n; i++)
        v[i] = 1.0 / n;
    double est = 0;
    int jlast = -1;
    for (int it = 0; it < 5; it++) {
        lu_solve(f, v, v);
        double nrm = 0;
        for (int i = 0; i < n; i++)
            nrm += fabs(v[i]);
        if (it > 0 && nrm <= est)
            break;
        est = nrm;
        for (int i = 0; i < n; i++)
            s[i] = v[i] >= 0 ? 1 : -1;
        lu_solve_t(f, s, s);
        int j = 0;
        for (int i = 1; i < n; i++)
            if (fabs(s[i]) > fabs(s[j]))
                j = i;
        if (it > 0 && j == jlast)
            break;
        jlast = j;
        memset(v, 0, (size_t)n * sizeof *v);
        v[j] = 1;
    }
    /* Higham's extra vector guards against the estimator's blind spots */
    for (int i = 0; i < n; i++)
        v[i] = (i % 2 ? -1.0 : 1.0) * (1.0 + (double)i / (n > 1 ? n - 1 : 1));
    lu_solve(f, v, v);
    double alt = 0;
    for (int i = 0; i < n; i++)
        alt += fabs(v[i]);
    alt = 2 * alt / (3.0 * n);
    return fmax(est, alt);
}

/* ==== QR with column pivoting: the rank and a null vector ====================== */

/* Householder QR with column pivoting of the m x n row-major M (overwritten:
 * R on and above the diagonal).  perm[k] is the original column at
 * position k.  nrm and nrm0 are n scratch values.  Returns the numerical
 * rank: the diagonal entries of R above MM_EQUIL_RANK_TOL |R_00|. */
static int qrcp(int m, int n, double *M, int *perm, double *nrm, double *nrm0)
{
    int kmax = m < n ? m : n;
    /* the matrix is equilibrated (entries at most 1): plain sums of squares
     * neither overflow nor lose anything that matters to the rank */
    for (int j = 0; j < n; j++) {
        double s = 0;
        for (int i = 0; i < m; i++)
            s += M[(size_t)i * n + j] * M[(size_t)i * n + j];
        nrm[j] = nrm0[j] = sqrt(s);
        perm[j] = j;
    }
    double r00 = 0;
    int rank = 0;
    for (int k = 0; k < kmax; k++) {
        int p = k;
        for (int j = k + 1; j < n; j++)
            if (nrm[j] > nrm[p])
                p = j;
        if (p != k) {
            for (int i = 0; i < m; i++) {
                double t = M[(size_t)i * n + k];
                M[(size_t)i * n + k] = M[(size_t)i * n + p];
                M[(size_t)i * n + p] = t;
            }
            double t = nrm[k];
            nrm[k] = nrm[p], nrm[p] = t;
            t = nrm0[k];
            nrm0[k] = nrm0[p], nrm0[p] = t;
            int q = perm[k];
            perm[k] = perm[p], perm[p] = q;
        }
        /* the reflector that zeroes column k below the diagonal */
        double alpha = M[(size_t)k * n + k], xn = 0;
        for (int i = k + 1; i < m; i++)
            xn += M[(size_t)i * n + k] * M[(size_t)i * n + k];
        xn = sqrt(xn);
        double beta = alpha, tau = 0;
        if (xn > 0) {
            beta = -copysign(hypot(alpha, xn), alpha);
            tau = (beta - alpha) / beta;
            double sc = 1.0 / (alpha - beta);
            for (int i = k + 1; i < m; i++)
                M[(size_t)i * n + k] *= sc;
        }
        M[(size_t)k * n + k] = beta;
        if (k == 0)
            r00 = fabs(beta);
        if (fabs(beta) > MM_EQUIL_RANK_TOL * r00 && r00 > 0)
            rank = k + 1;
        for (int j = k + 1; j < n; j++) {
            if (tau != 0) {
                double w = M[(size_t)k * n + j];
                for (int i = k + 1; i < m; i++)
                    w += M[(size_t)i * n + k] * M[(size_t)i * n + j];
                w *= tau;
                M[(size_t)k * n + j] -= w;
                for (int i = k + 1; i < m; i++)
                    M[(size_t)i * n + j] -= w * M[(size_t)i * n + k];
            }
            /* downdate the column norm; recompute when cancellation ate it
             * (LAPACK dlaqp2's rule) */
            if (nrm[j] > 0) {
                double t = fabs(M[(size_t)k * n + j]) / nrm[j];
                t = fmax(0, (1 + t) * (1 - t));
                double t2 = t * (nrm[j] / nrm0[j]) * (nrm[j] / nrm0[j]);
                if (t2 <= sqrt(DBL_EPSILON)) {
                    double s = 0;
                    for (int i = k + 1; i < m; i++)
                        s += M[(size_t)i * n + j] * M[(size_t)i * n + j];
                    nrm[j] = nrm0[j] = sqrt(s);
                } else {
                    nrm[j] *= sqrt(t);
                }
            }
        }
    }
    return rank;
}

/* The null vector of the factored M for rank r < n: in pivoted order
 * [-R11^{-1} R12 e_1; e_1], then back to the original order, into v[n]. */
static void null_vector(int n, const double *M, const int *perm, int r, double *v, double *tmp)
{
    for (int i = r - 1; i >= 0; i--) {  /* R11 y = R12 e_1 */
        double s = M[(size_t)i * n + r];
        for (int j = i + 1; j < r; j++)
            s -= M[(size_t)i * n + j] * tmp[j];
        tmp[i] = s / M[(size_t)i * n + i];
    }
    for (int j = 0; j < n; j++)
        v[j] = 0;
    for (int k = 0; k < r; k++)
        v[perm[k]] = -tmp[k];
    v[perm[r]] = 1;
}

/* Scale v so that its largest entry is +1. */
static void normalise(int n, double *v)
{
    int k = 0;
    for (int i = 1; i < n; i++)
        if (fabs(v[i]) > fabs(v[k]))
            k = i;
    double s = v[k];
    if (s != 0 && isfinite(s))
        for (int i = 0; i < n; i++)
            v[i] /= s;
}

/* The rank test of the scaled As (m x n) and its transpose: kind, rank and
 * the null vectors (unscaled).  force: LU already found As singular, so the
 * rank is below n even if QR's tolerance hesitates. */
static int diagnose(int m, int n, const double *As, const double *rs, const double *cs, int force,
                    double *mech, double *self, mm_equil_result *res)
{
    int big = m > n ? m : n;
    double *M = malloc((size_t)m * (size_t)n * sizeof *M);
    double *scratch = malloc((size_t)(3 * big) * sizeof *scratch);
    double *v = malloc((size_t)big * sizeof *v);
    int *perm = malloc((size_t)big * sizeof *perm);
    if (!M || !scratch || !v || !perm) {
        free(M), free(scratch), free(v), free(perm);
        return MM_ENOMEM;
    }
    double *nrm = scratch, *nrm0 = scratch + big, *tmp = scratch + 2 * big;

    /* self-stress: the null space of As */
    memcpy(M, As, (size_t)m * (size_t)n * sizeof *M);
    int r = qrcp(m, n, M, perm, nrm, nrm0);
    if (force && m == n && r == n)
        r = n - 1;
    res->rank = r;
    res->n_self = n - r;
    if (self) {
        memset(self, 0, (size_t)n * sizeof *self);
        if (r < n) {
            null_vector(n, M, perm, r, v, tmp);
            for (int j = 0; j < n; j++)
                self[j] = cs[j] * v[j];
            normalise(n, self);
        }
    }

    /* mechanism: the null space of As^T */
    for (int i = 0; i < m; i++)
        for (int j = 0; j < n; j++)
            M[(size_t)j * m + i] = As[(size_t)i * n + j];
    int rt = qrcp(n, m, M, perm, nrm, nrm0);
    if (force && m == n && rt == m)
        rt = m - 1;
    res->n_mech = m - rt;
    if (mech) {
        memset(mech, 0, (size_t)m * sizeof *mech);
        if (rt < m) {
            null_vector(m, M, perm, rt, v, tmp);
            for (int i = 0; i < m; i++)
                mech[i] = rs[i] * v[i];
            normalise(m, mech);
        }
    }
    free(M), free(scratch), free(v), free(perm);
    res->kind = res->n_mech > 0 && res->n_self > 0 ? MM_EQUIL_CRITICAL
                : res->n_mech > 0                 ? MM_EQUIL_MECHANISM
                : res->n_self > 0                 ? MM_EQUIL_INDETERMINATE
                                                  : MM_EQUIL_CRITICAL;
    return MM_OK;
}

/* ==== the driver ================================================================ */

/* The determinate path: LU of the scaled square matrix, the condition
 * estimate, the solve and one refinement step.  Returns MM_OK (x filled),
 * MM_ESINGULAR (no pivot, or rcond below the limit), MM_ENONFINITE or
 * MM_ENOMEM. */
static int solve_square(const csc *a, const double *rs, const double *cs, const double *b, double *x,
                        mm_equil_result *res)
{
    int n = a->n, rc = MM_OK;
    lu f = {.n = n};
    size_t nn = (size_t)n * (size_t)n;
    f.a = calloc(nn, sizeof *f.a);
    f.piv = malloc((size_t)n * sizeof *f.piv);
    f.col = malloc((size_t)n * sizeof *f.col);
    f.work = malloc((size_t)n * sizeof *f.work);
    f.chi = malloc((size_t)n * sizeof *f.chi);
    f.rlo = malloc((size_t)n * sizeof *f.rlo);
    f.rhi = malloc((size_t)n * sizeof *f.rhi);
    int *iscratch = malloc((size_t)(2 * n + 2) * sizeof *iscratch);
    int *pos = malloc((size_t)n * sizeof *pos);
    double *v = malloc((size_t)(4 * n) * sizeof *v);
    if (!f.a || !f.piv || !f.col || !f.work || !f.chi || !f.rlo || !f.rhi || !iscratch || !pos || !v) {
        rc = MM_ENOMEM;
        goto out;
    }
    order_columns(a, f.col, iscratch);
    for (int k = 0; k < n; k++) {
        pos[f.col[k]] = k;
        f.chi[k] = k;                        /* the diagonal is always looked at */
        f.rlo[k] = k, f.rhi[k] = k;
    }
    double norm1 = 0;                        /* ||R A C||_1 */
    for (int j = 0; j < n; j++) {
        double s = 0;
        for (int q = a->cp[j]; q < a->cp[j + 1]; q++) {
            double e = rs[a->ri[q]] * a->v[q] * cs[j];
            int i = a->ri[q], k = pos[j];
            f.a[(size_t)i * n + k] += e;
            if (f.chi[k] < i)
                f.chi[k] = i;
            if (f.rlo[i] > k)
                f.rlo[i] = k;
            if (f.rhi[i] < k)
                f.rhi[i] = k;
            s += fabs(e);
        }
        if (s > norm1)
            norm1 = s;
    }
    /* scaled entries are at most 1: a pivot below n eps is round-off */
    if (lu_factor(&f, 16 * n * DBL_EPSILON, iscratch) >= 0) {
        rc = MM_ESINGULAR;
        goto out;
    }
    if ((rc = lu_compress(&f)) != MM_OK)
        goto out;
    res->rcond = 1.0 / (norm1 * inverse_norm1(&f, v, v + n));
    if (!(res->rcond >= MM_EQUIL_RCOND_SINGULAR)) {
        rc = MM_ESINGULAR;
        goto out;
    }
    /* (R A C) z = R b, x = C z; then one refinement step on the residual of
     * the unscaled equations */
    double *z = v, *r = v + n, *s = v + 2 * n;
    for (int i = 0; i < n; i++)
        z[i] = rs[i] * b[i];
    lu_solve(&f, z, z);
    for (int j = 0; j < n; j++)
        x[j] = cs[j] * z[j];
    double worst, scale;
    csc_residual(a, b, x, r, s, &worst, &scale);
    for (int i = 0; i < n; i++)
        r[i] *= rs[i];
    lu_solve(&f, r, r);
    double xmax = 0, amax = 0, bmax = 0;
    for (int j = 0; j < n; j++) {
        x[j] += cs[j] * r[j];
        if (!isfinite(x[j])) {
            rc = MM_ENONFINITE;
            goto out;
        }
        if (fabs(x[j]) > xmax)
            xmax = fabs(x[j]);
    }
    for (int q = 0; q < a->cp[n]; q++)
        if (fabs(a->v[q]) > amax)
            amax = fabs(a->v[q]);
    for (int i = 0; i < n; i++)
        if (fabs(b[i]) > bmax)
            bmax = fabs(b[i]);
    csc_residual(a, b, x, r, s, &res->residual, &res->scale);
    res->kind = MM_EQUIL_DETERMINATE;
    res->rank = n;
    res->growth = bmax > 0 ? xmax * amax / bmax : 0;
out:
    lu_free(&f);
    free(iscratch);
    free(pos);
    free(v);
    return rc;
}

static int solve_csc(const csc *a, const double *b, double *x, double *mech, double *self,
                     mm_equil_result *res, mm_error *err)
{
    int m = a->m, n = a->n, rc;
    for (int i = 0; i < m; i++)
        if (!isfinite(b[i]))
            return mm_error_set(err, MM_EVALUE, "b", "load %d is %g", i + 1, b[i]);
    for (int q = 0; q < a->cp[n]; q++)
        if (!isfinite(a->v[q]))
            return mm_error_set(err, MM_EVALUE, "A", "an entry of the equilibrium matrix is %g", a->v[q]);
    double *rs = malloc((size_t)m * sizeof *rs), *cs = malloc((size_t)n * sizeof *cs);
    double *As = NULL;
    if (!rs || !cs) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
        goto out;
    }
    equilibrate(a, rs, cs);
    if (m == n) {
        rc = solve_square(a, rs, cs, b, x, res);
        if (rc == MM_OK)
            goto out;
        if (rc == MM_ENONFINITE) {
            mm_error_set(err, rc, "b", "the forces overflow: the structure is too close to a mechanism");
            goto out;
        }
        if (rc != MM_ESINGULAR) {
            mm_error_set(err, rc, "", "out of memory");
            goto out;
        }
    }
    As = calloc((size_t)m * (size_t)n, sizeof *As);
    if (!As) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
        goto out;
    }
    for (int j = 0; j < n; j++)
        for (int q = a->cp[j]; q < a->cp[j + 1]; q++)
            As[(size_t)a->ri[q] * n + j] += rs[a->ri[q]] * a->v[q] * cs[j];
    rc = diagnose(m, n, As, rs, cs, m == n, mech, self, res);
    if (rc != MM_OK) {
        mm_error_set(err, rc, "", "out of memory");
        goto out;
    }
    res->rcond = 0;
    rc = mm_error_set(err, MM_ESINGULAR, "",
                      "the equilibrium equations are singular (%d equations, %d unknowns, rank %d): %s", m,
                      n, res->rank, mm_equil_kind_name(res->kind));
out:
    free(rs);
    free(cs);
    free(As);
    return rc;
}

static int check_sizes(int n_eq, int n_unk, mm_equil_result **res, mm_equil_result *local,
                       mm_error *err)
{
    if (!*res)
        *res = local;
    memset(*res, 0, sizeof **res);
    if (n_eq < 1 || n_eq > MM_EQUIL_MAX_N || n_unk < 1 || n_unk > MM_EQUIL_MAX_N)
        return mm_error_set(err, MM_ERANGE, "n",
                            "%d equations in %d unknowns: each must be between 1 and %d", n_eq, n_unk,
                            MM_EQUIL_MAX_N);
    return MM_OK;
}

int mm_equil_solve(int n_eq, int n_unk, const double *A, const double *b, double *x,
                   double *mech, double *self, mm_equil_result *res, mm_error *err)
{
    mm_equil_result local;
    int rc = check_sizes(n_eq, n_unk, &res, &local, err);
    if (rc != MM_OK)
        return rc;
    size_t mn = (size_t)n_eq * (size_t)n_unk;
    for (size_t k = 0; k < mn; k++)
        if (!isfinite(A[k]))
            return mm_error_set(err, MM_EVALUE, "A", "entry %zu of the equilibrium matrix is %g", k + 1,
                                A[k]);
    csc a = {.m = n_eq, .n = n_unk};
    int nnz = 0;
    for (size_t k = 0; k < mn; k++)
        nnz += A[k] != 0;
    a.cp = calloc((size_t)n_unk + 1, sizeof *a.cp);
    a.ri = malloc((size_t)(nnz ? nnz : 1) * sizeof *a.ri);
    a.v = malloc((size_t)(nnz ? nnz : 1) * sizeof *a.v);
    if (!a.cp || !a.ri || !a.v) {
        csc_free(&a);
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    }
    int q = 0;
    for (int j = 0; j < n_unk; j++) {
        for (int i = 0; i < n_eq; i++)
            if (A[(size_t)i * n_unk + j] != 0) {
                a.ri[q] = i;
                a.v[q++] = A[(size_t)i * n_unk + j];
            }
        a.cp[j + 1] = q;
    }
    rc = solve_csc(&a, b, x, mech, self, res, err);
    csc_free(&a);
    return rc;
}

int mm_equil_solve_sparse(int n_eq, int n_unk, int nnz, const int *row, const int *col,
                          const double *val, const double *b, double *x, double *mech, double *self,
                          mm_equil_result *res, mm_error *err)
{
    mm_equil_result local;
    int rc = check_sizes(n_eq, n_unk, &res, &local, err);
    if (rc != MM_OK)
        return rc;
    if (nnz < 0)
        return mm_error_set(err, MM_ERANGE, "A", "a negative number of entries: %d", nnz);
    for (int k = 0; k < nnz; k++)
        if (row[k] < 0 || row[k] >= n_eq || col[k] < 0 || col[k] >= n_unk)
            return mm_error_set(err, MM_ERANGE, "A", "entry %d at (%d, %d) is outside the %d x %d matrix",
                                k + 1, row[k] + 1, col[k] + 1, n_eq, n_unk);
    csc a = {0};
    if (csc_from_triplets(n_eq, n_unk, nnz, row, col, val, &a) != MM_OK) {
        csc_free(&a);
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    }
    rc = solve_csc(&a, b, x, mech, self, res, err);
    csc_free(&a);
    return rc;
}
