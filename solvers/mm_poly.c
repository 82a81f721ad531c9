/* mm_poly.c — polynomial evaluation, roots and least-squares fit.
 *
 * Roots: companion matrix -> eigenvalues (mm_linalg_geev) -> Newton polish
 * with compensated (double-double) evaluation -> error estimate per root,
 * with clusters of roots treated as multiple roots.  Fit: Vandermonde in a
 * centred, scaled variable -> SVD least squares (mm_linalg_lstsq) -> expand
 * back to the original variable.  Contracts in mm_poly.h.
 */
#include "mm_poly.h"

#include "mm_complex.h"

#include <assert.h>
#include <complex.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mm_dd.h"
#include "mm_linalg.h"

#define U_ROUND (DBL_EPSILON / 2)   /* unit roundoff u */

/* ==== evaluation ============================================================= */

double mm_poly_eval(int ncoef, const double *p, double x, double *err_bound)
{
    assert(ncoef >= 1 && p);
    double y = p[0], mu = fabs(y) / 2;
    for (int k = 1; k < ncoef; k++) {
        y = x * y + p[k];
        mu = fabs(x) * mu + fabs(y);      /* Higham Alg. 5.1, running bound */
    }
    if (err_bound)
        *err_bound = U_ROUND * (2 * mu - fabs(y));
    return y;
}

double mm_poly_backward_error(int ncoef, const double *p, double zr, double zi)
{
    assert(ncoef >= 1 && p);
    const int d = ncoef - 1;
    double r = hypot(zr, zi), yr, yi = 0, s;
    if (r <= 1) {
        yr = p[0];
        s = fabs(p[0]);
        for (int k = 1; k <= d; k++) {
            double tr = yr * zr - yi * zi + p[k];
            yi = yr * zi + yi * zr;
            yr = tr;
            s = s * r + fabs(p[k]);
        }
    } else {
        double wr = zr / r / r, wi = -zi / r / r;  /* 1/z, without forming r^2 */
        yr = p[d];
        s = fabs(p[d]);
        for (int k = d - 1; k >= 0; k--) {
            double tr = yr * wr - yi * wi + p[k];
            yi = yr * wi + yi * wr;
            yr = tr;
            s = s / r + fabs(p[k]);
        }
    }
    double pz = hypot(yr, yi);
    return s > 0 ? pz / s : pz;
}

/* p(z) for complex z = zr + i zi, Horner in double-double: the result is
 * as accurate as if computed with ~32 digits, so near a root it tells the
 * true size of |p(z)| instead of rounding noise. */
static double complex eval_dd(int d, const double *q, double complex z)
{
    double zr = creal(z), zi = cimag(z);
    mm_dd yr = {q[0], 0.0}, yi = {0.0, 0.0};
    for (int k = 1; k <= d; k++) {
        mm_dd nr = mm_dd_add(mm_dd_mul_d(yr, zr), mm_dd_mul_d(yi, -zi));
        mm_dd ni = mm_dd_add(mm_dd_mul_d(yr, zi), mm_dd_mul_d(yi, zr));
        yr = mm_dd_add(nr, mm_dd_from(q[k]));
        yi = ni;
    }
    return mm_cmplx(yr.hi + yr.lo, yi.hi + yi.lo);
}

/* p'(z) in ordinary complex arithmetic (it only scales the Newton step). */
static double complex eval_deriv(int d, const double *q, double complex z)
{
    double complex y = d * q[0];
    for (int k = 1; k < d; k++)
        y = y * z + (double)(d - k) * q[k];
    return y;
}

/* sum |q_k| |z|^(d-k): the size of the terms of p(z).  A relative change
 * eps/2 in every coefficient changes p(z) by at most eps/2 times this. */
static double abs_poly(int d, const double *q, double r)
{
    double s = fabs(q[0]);
    for (int k = 1; k <= d; k++)
        s = s * r + fabs(q[k]);
    return s;
}

/* ==== roots ================================================================== */

typedef struct root_work {
    double complex z;
    double e1;       /* first-order error estimate */
    double err;
    int cluster;     /* union-find parent */
    int size;
} root_work;

static int find(root_work *w, int i)
{
    while (w[i].cluster != i)
        i = w[i].cluster = w[w[i].cluster].cluster;   /* path halving */
    return i;
}

/* Newton polish of root i: steps accepted only while |p| falls and the step
 * stays within half the distance to the nearest other root. */
static void polish(int d, const double *q, root_work *w, int n, int i)
{
    double complex z = w[i].z;
    double complex pz = eval_dd(d, q, z);
    double dmin = HUGE_VAL;
    for (int k = 0; k < n; k++)
        if (k != i)
            dmin = fmin(dmin, cabs(w[k].z - z));
    for (int it = 0; it < 8 && cabs(pz) > 0; it++) {
        double complex dz = eval_deriv(d, q, z);
        if (cabs(dz) == 0)
            break;
        double complex step = pz / dz;
        if (!(cabs(step) <= 0.5 * dmin))
            break;
        double complex znew = z - step, pnew = eval_dd(d, q, znew);
        if (!(cabs(pnew) < cabs(pz)))
            break;
        z = znew;
        pz = pnew;
        if (cabs(step) <= DBL_EPSILON * cabs(z))
            break;                                     /* converged */
    }
    w[i].z = z;
}

/* Taylor coefficients t_k = p^(k)(c)/k!, k = 0..m, by repeated synthetic
 * division (Horner's scheme for the shifted polynomial). */
static void taylor(int d, const double *q, double complex c, int m,
                   double complex *t, double complex *b)
{
    for (int k = 0; k <= d; k++)
        b[k] = q[k];
    for (int k = 0; k <= m; k++) {
        for (int j = 1; j <= d - k; j++)
            b[j] += c * b[j - 1];
        t[k] = b[d - k];
    }
}

/* Error estimates of mm_poly.h.  Clusters: roots i, k are linked when
 * |z_i - z_k| <= 4 (err_i + err_k).  (For an m-fold root the computed roots
 * lie on a circle of radius rho with neighbours ~2 pi rho / m apart, and the
 * first-order estimate at each is ~rho/m, so the factor 4 links them for
 * every m.)  A cluster of m gets the radius R from Fujiwara's bound on the
 * roots of its Taylor polynomial sum_{k<=m} t_k h^k about the centroid c,
 * with |t_0| enlarged by the coefficient uncertainty eps/2 * sum |q_k||c|^k:
 *     R = 2 max_{k<m} (|t_k| / |t_m|)^(1/(m-k)),
 * and each member's error is |z_i - c| + R.  Repeat until nothing links. */
static int estimate(int d, const double *q, root_work *w, int n)
{
    double complex *t = malloc((size_t)(d + 1) * sizeof *t);
    double complex *b = malloc((size_t)(d + 1) * sizeof *b);
    if (!t || !b) {
        free(t); free(b);
        return MM_ENOMEM;
    }
    for (int i = 0; i < n; i++) {
        double complex z = w[i].z;
        double delta = cabs(eval_dd(d, q, z)) + U_ROUND * abs_poly(d, q, cabs(z));
        double dp = cabs(eval_deriv(d, q, z));
        w[i].e1 = w[i].err = dp > 0 ? delta / dp : HUGE_VAL;
        w[i].cluster = i;
        w[i].size = 1;
    }
    for (int pass = 0; pass < n; pass++) {
        int linked = 0;
        for (int i = 0; i < n; i++)
            for (int k = i + 1; k < n; k++) {
                int ri = find(w, i), rk = find(w, k);
                if (ri == rk || !(cabs(w[i].z - w[k].z) <= 4 * (w[i].err + w[k].err)))
                    continue;
                w[rk].cluster = ri;
                w[ri].size += w[rk].size;
                linked = 1;
            }
        if (!linked)
            break;
        for (int r = 0; r < n; r++) {
            if (find(w, r) != r || w[r].size < 2)
                continue;
            int m = w[r].size;
            double complex c = 0;
            for (int i = 0; i < n; i++)
                if (find(w, i) == r)
                    c += w[i].z;
            c /= m;
            taylor(d, q, c, m, t, b);
            t[0] = eval_dd(d, q, c);                    /* accurate value */
            double tm = cabs(t[m]), R = 0;
            for (int k = 0; k < m; k++) {
                double tk = cabs(t[k]);
                if (k == 0)
                    tk += U_ROUND * abs_poly(d, q, cabs(c));
                R = fmax(R, pow(tk / tm, 1.0 / (m - k)));
            }
            R = tm > 0 ? 2 * R : HUGE_VAL;
            for (int i = 0; i < n; i++)
                if (find(w, i) == r)
                    w[i].err = cabs(w[i].z - c) + R;
        }
    }
    free(b); free(t);
    return MM_OK;
}

static int root_order(const void *pa, const void *pb)
{
    const mm_poly_root *a = pa, *b = pb;
    double ma = hypot(a->re, a->im), mb = hypot(b->re, b->im);
    if (ma != mb) return ma < mb ? 1 : -1;
    if (a->re != b->re) return a->re < b->re ? 1 : -1;
    if (a->im != b->im) return a->im < b->im ? 1 : -1;
    return 0;
}

int mm_poly_roots(int ncoef, const double *p, mm_poly_root *roots, int *nroots,
                  mm_error *err)
{
    int rc;
    assert(p && roots && nroots);
    *nroots = 0;
    if (ncoef < 1 || ncoef > MM_POLY_MAX_DEGREE + 1)
        return mm_error_set(err, MM_ERANGE, "p",
                            "bad parameter 'p' (must have 1 to %d coefficients, "
                            "got %d)", MM_POLY_MAX_DEGREE + 1, ncoef);
    if ((rc = mm_linalg_check_finite("p", (size_t)ncoef, p, err)))
        return rc;
    int lead = 0, last = ncoef - 1;
    while (lead < ncoef && p[lead] == 0.0)
        lead++;
    if (lead == ncoef)
        return mm_error_set(err, MM_EVALUE, "p",
                            "bad value in 'p' (all coefficients are zero: every "
                            "number would be a root)");
    while (p[last] == 0.0)
        last--;
    int nzero = ncoef - 1 - last;          /* x^nzero divides p */
    int d = last - lead;                   /* degree of what remains */
    const double *q = p + lead;

    double *C = NULL, *wr = NULL, *wi = NULL;
    root_work *w = NULL;
    if (d >= 1) {
        C = calloc((size_t)d * (size_t)d, sizeof *C);
        wr = malloc((size_t)d * sizeof *wr);
        wi = malloc((size_t)d * sizeof *wi);
        w = malloc((size_t)d * sizeof *w);
        if (!C || !wr || !wi || !w) {
            rc = mm_error_set(err, MM_ENOMEM, "", "out of memory for polynomial roots");
            goto out;
        }
        /* companion matrix (MATLAB's form): first row -q[1..d]/q[0], ones
         * on the subdiagonal; its characteristic polynomial is q/q[0] */
        for (int j = 0; j < d; j++) {
            C[j] = -q[j + 1] / q[0];
            if (!isfinite(C[j])) {
                rc = mm_error_set(err, MM_ENONFINITE, "p",
                                  "the leading coefficient of 'p' is too small "
                                  "beside the others: the roots overflow");
                goto out;
            }
        }
        for (int i = 1; i < d; i++)
            C[(size_t)i * (size_t)d + (size_t)(i - 1)] = 1.0;
        if ((rc = mm_linalg_geev(d, C, wr, wi, NULL, err)))
            goto out;
        for (int i = 0; i < d; i++)
            w[i].z = mm_cmplx(wr[i], wi[i]);
        /* polish: real roots stay real (real Newton), a conjugate pair is
         * polished through its upper member and the other set to its
         * conjugate, so pairs stay exact pairs */
        for (int i = 0; i < d; i++) {
            if (wi[i] < 0)
                continue;
            polish(d, q, w, d, i);
            if (wi[i] > 0 && i + 1 < d && wi[i + 1] < 0)
                w[i + 1].z = conj(w[i].z);
        }
        if ((rc = estimate(d, q, w, d))) {
            rc = mm_error_set(err, rc, "", "out of memory for polynomial roots");
            goto out;
        }
    }
    for (int i = 0; i < d; i++) {
        mm_poly_root *r = &roots[i];
        double az = cabs(w[i].z);
        r->re = creal(w[i].z);
        r->im = cimag(w[i].z);
        r->err = w[i].err;
        r->cond = w[i].err / (U_ROUND * (az > 0 ? az : 1.0));
        r->multiplicity = w[find(w, i)].size;
        r->flags = (r->multiplicity > 1 ? MM_POLY_ROOT_MULTIPLE : 0) |
                   (!(r->err <= 1e-8 * fmax(az, 1.0)) ? MM_POLY_ROOT_ILLCOND : 0);
    }
    for (int i = d; i < d + nzero; i++)    /* exact zero roots */
        roots[i] = (mm_poly_root){0.0, 0.0, 0.0, 0.0, nzero,
                                  nzero > 1 ? MM_POLY_ROOT_MULTIPLE : 0};
    *nroots = d + nzero;
    qsort(roots, (size_t)*nroots, sizeof *roots, root_order);
    rc = MM_OK;
out:
    free(w); free(wi); free(wr); free(C);
    return rc;
}

/* ==== least-squares fit ======================================================= */

static int cmp_double(const void *pa, const void *pb)
{
    double a = *(const double *)pa, b = *(const double *)pb;
    return (a > b) - (a < b);
}

int mm_poly_fit(int npts, const double *x, const double *y, int degree,
                double *p, mm_poly_fit_info *info, mm_error *err)
{
    int rc;
    assert(x && y && p);
    if (npts < 1 || npts > MM_POLY_MAX_POINTS)
        return mm_error_set(err, MM_ERANGE, "x",
                            "bad parameter 'x' (must have 1 to %d points, got %d)",
                            MM_POLY_MAX_POINTS, npts);
    if (degree < 0 || degree > MM_POLY_MAX_FIT_DEGREE)
        return mm_error_set(err, MM_ERANGE, "degree",
                            "bad parameter 'degree' (must be between 0 and %d, got %d)",
                            MM_POLY_MAX_FIT_DEGREE, degree);
    if ((rc = mm_linalg_check_finite("x", (size_t)npts, x, err)) ||
        (rc = mm_linalg_check_finite("y", (size_t)npts, y, err)))
        return rc;

    int ncol = degree + 1;
    double *xs = malloc((size_t)npts * sizeof *xs);
    double *V = malloc((size_t)npts * (size_t)ncol * sizeof *V);
    double *c = malloc((size_t)ncol * sizeof *c);
    double *sv = malloc((size_t)ncol * sizeof *sv);
    mm_poly_fit_info inf = {0};
    if (!xs || !V || !c || !sv) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory for polyfit");
        goto out;
    }
    memcpy(xs, x, (size_t)npts * sizeof *xs);
    qsort(xs, (size_t)npts, sizeof *xs, cmp_double);
    int distinct = 1;
    for (int i = 1; i < npts; i++)
        distinct += xs[i] != xs[i - 1];
    if (degree >= distinct) {
        rc = mm_error_set(err, MM_ERANGE, "degree",
                          "bad parameter 'degree' (must be less than the number "
                          "of distinct x values, %d, got %d)", distinct, degree);
        goto out;
    }

    /* centre and scale: t = (x - mu)/scale lies in [-1, 1] */
    double mu = 0.0, scale = 0.0;
    for (int i = 0; i < npts; i++)
        mu += x[i];
    mu /= npts;
    for (int i = 0; i < npts; i++)
        scale = fmax(scale, fabs(x[i] - mu));
    if (!(scale > 0.0))
        scale = 1.0;
    for (int i = 0; i < npts; i++) {           /* Vandermonde, highest first */
        double t = (x[i] - mu) / scale, v = 1.0;
        for (int k = degree; k >= 0; k--) {
            V[(size_t)i * (size_t)ncol + (size_t)k] = v;
            v *= t;
        }
    }
    int rank = 0;
    if ((rc = mm_linalg_lstsq(npts, ncol, 1, V, y, 0.0, c, &rank, NULL, sv, err)))
        goto out;

    /* rms residual of the fit (in t, the better-conditioned form) */
    double r2 = 0.0;
    for (int i = 0; i < npts; i++) {
        double r = y[i] - mm_poly_eval(ncol, c, (x[i] - mu) / scale, NULL);
        r2 += r * r;
    }
    inf.rms = sqrt(r2 / npts);
    inf.mu = mu;
    inf.scale = scale;
    inf.rank = rank;
    int kmin = npts < ncol ? npts : ncol;
    inf.cond = sv[kmin - 1] > 0 ? sv[0] / sv[kmin - 1] : HUGE_VAL;

    /* back to x: p(x) = c((x - mu)/scale), expanded by Horner's scheme on
     * polynomials: P <- P * (x/scale - mu/scale) + c_k */
    for (int k = 0; k < ncol; k++)
        p[k] = 0.0;
    double a1 = 1.0 / scale, a0 = -mu / scale;
    for (int k = 0; k < ncol; k++) {
        /* P has k terms right-aligned in p[ncol-k .. ncol-1]; times
         * (a1 x + a0): new[j] = a1 old[j+1] + a0 old[j], j ascending */
        for (int j = ncol - k - 1; j < ncol; j++) {
            double next = j + 1 < ncol ? p[j + 1] : 0.0;
            p[j] = a1 * next + a0 * p[j];
        }
        p[ncol - 1] += c[k];
    }
    rc = MM_OK;
out:
    if (info)
        *info = inf;
    free(sv); free(c); free(V); free(xs);
    return rc;
}

int mm_poly_fit_values(int npts, const double *x, const double *y, int degree, double mu, double scale,
                       double *fit_svd, double *fit_ne, double *bnorm_svd, double *bnorm_ne, mm_error *err)
{
    int rc;
    assert(x && y && fit_svd && fit_ne && bnorm_svd && bnorm_ne);
    if (npts < 1 || npts > MM_POLY_MAX_POINTS || degree < 0 || degree > MM_POLY_MAX_FIT_DEGREE || !(scale > 0))
        return mm_error_set(err, MM_ERANGE, "degree", "bad sizes for a fit (%d points, degree %d)", npts, degree);
    const int n = npts, m = degree + 1;
    double *t = malloc((size_t)n * sizeof *t), *V = malloc((size_t)n * (size_t)m * sizeof *V);
    double *N = calloc((size_t)m * (size_t)m, sizeof *N), *rhs = calloc((size_t)m, sizeof *rhs);
    double *a = malloc((size_t)m * sizeof *a), *b = malloc((size_t)m * sizeof *b), *pw = malloc(2 * (size_t)m * sizeof *pw);
    if (!t || !V || !N || !rhs || !a || !b || !pw) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory for polyfit");
        goto out;
    }
    for (int i = 0; i < n; i++) {                    /* V (highest power first), A^T A and A^T y */
        t[i] = (x[i] - mu) / scale;
        pw[0] = 1;
        for (int k = 1; k <= 2 * degree; k++)
            pw[k] = pw[k - 1] * t[i];
        for (int k = 0; k <= degree; k++)
            V[(size_t)i * m + (size_t)(degree - k)] = pw[k];
        for (int j = 0; j <= degree; j++) {
            rhs[j] += pw[j] * y[i];
            for (int k = 0; k <= degree; k++)
                N[j * m + k] += pw[j + k];
        }
    }
    mm_linalg_solve_info si;
    if ((rc = mm_linalg_lstsq(n, m, 1, V, y, 0.0, b, NULL, NULL, NULL, err)) ||
        (rc = mm_linalg_solve(m, 1, N, rhs, a, &si, err)))
        goto out;
    *bnorm_svd = *bnorm_ne = 0;
    for (int k = 0; k < m; k++) {
        *bnorm_svd += b[k] * b[k];
        *bnorm_ne += a[k] * a[k];
    }
    *bnorm_svd = sqrt(*bnorm_svd);
    *bnorm_ne = sqrt(*bnorm_ne);
    for (int i = 0; i < n; i++) {                    /* Horner in t; a is lowest power first */
        double vs = 0, vn = 0;
        for (int k = 0; k <= degree; k++) {
            vs = vs * t[i] + b[k];
            vn = vn * t[i] + a[degree - k];
        }
        fit_svd[i] = vs;
        fit_ne[i] = vn;
    }
    rc = MM_OK;
out:
    free(pw); free(b); free(a); free(rhs); free(N); free(V); free(t);
    return rc;
}

/* ==== the same fit in double-double ============================================ */

/* |x| of a dd as a double */
static double dabs(mm_dd a) { return fabs(mm_dd_val(a)); }

int mm_poly_fit_dd(int npts, const double *x, const double *y, int degree, double *c, double *c_err,
                   double *fit, double *fit_err, double *se, double *bt, mm_poly_fit_dd_info *info,
                   mm_error *err)
{
    int rc;
    assert(x && y && c && c_err && fit && fit_err && info);
    if (npts < 1 || npts > MM_POLY_MAX_POINTS)
        return mm_error_set(err, MM_ERANGE, "x", "bad parameter 'x' (must have 1 to %d points, got %d)",
                            MM_POLY_MAX_POINTS, npts);
    if (degree < 0 || degree > MM_POLY_MAX_FIT_DD_DEGREE || degree >= npts)
        return mm_error_set(err, MM_ERANGE, "degree", "bad parameter 'degree' (must be between 0 and %d and "
                            "below the number of points, got %d)", MM_POLY_MAX_FIT_DD_DEGREE, degree);
    if ((rc = mm_linalg_check_finite("x", (size_t)npts, x, err)) ||
        (rc = mm_linalg_check_finite("y", (size_t)npts, y, err)))
        return rc;
    const int n = npts, m = degree + 1;
    mm_dd *a = malloc((size_t)n * (size_t)(m + 1) * sizeof *a), *t = malloc((size_t)n * sizeof *t);
    mm_dd *b = malloc((size_t)m * sizeof *b), *T = malloc((size_t)m * (size_t)m * sizeof *T);
    mm_dd *G = malloc((size_t)m * (size_t)m * sizeof *G), *P = malloc((size_t)(m + 1) * sizeof *P);
    mm_dd *fv = malloc((size_t)n * sizeof *fv);
    double *A = malloc((size_t)m * (size_t)m * sizeof *A), *sv = malloc(2 * (size_t)m * sizeof *sv);
    mm_poly_fit_dd_info inf = {0};
    if (!a || !t || !b || !T || !G || !P || !A || !sv || !fv) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory for polyfit");
        goto out;
    }
    /* t = (x - mu) / scale exactly: x - mu as a dd (TwoSum), scale a power of 2 */
    double mu = 0, dev = 0;
    for (int i = 0; i < n; i++)
        mu += x[i];
    mu /= n;
    for (int i = 0; i < n; i++)
        dev = fmax(dev, fabs(x[i] - mu));
    double scale = dev > 0 ? ldexp(1, ilogb(dev) + 1) : 1, inv = 1 / scale;
    inf.mu = mu;
    inf.scale = scale;
    for (int i = 0; i < n; i++)
        t[i] = mm_dd_mul_d(mm_dd_two_sum(x[i], -mu), inv);
    /* [A | y], A(i, j) = t_i^(degree - j) */
    const int w = m + 1;
    for (int i = 0; i < n; i++) {
        mm_dd v = mm_dd_from(1);
        for (int j = degree; j >= 0; j--) {
            a[i * w + j] = v;
            v = mm_dd_mul(v, t[i]);
        }
        a[i * w + m] = mm_dd_from(y[i]);
    }
    /* Householder QR of A, applied to y as well */
    for (int k = 0; k < m; k++) {
        mm_dd s2 = mm_dd_from(0);
        for (int i = k; i < n; i++)
            s2 = mm_dd_add(s2, mm_dd_mul(a[i * w + k], a[i * w + k]));
        mm_dd nrm = mm_dd_sqrt(s2);
        if (nrm.hi == 0) {
            rc = mm_error_set(err, MM_ESINGULAR, "x", "the points do not fix a polynomial of degree %d", degree);
            goto out;
        }
        mm_dd alpha = a[k * w + k].hi >= 0 ? mm_dd_neg(nrm) : nrm;
        mm_dd vk = mm_dd_sub(a[k * w + k], alpha);           /* v = x - alpha e1 */
        mm_dd vtv = mm_dd_sub(mm_dd_mul(nrm, nrm), mm_dd_mul(alpha, a[k * w + k]));
        vtv = mm_dd_mul_d(vtv, 2);                           /* v^T v = 2 (|x|^2 - alpha x_1) */
        a[k * w + k] = vk;
        for (int j = k + 1; j < w; j++) {
            mm_dd d = mm_dd_from(0);
            for (int i = k; i < n; i++)
                d = mm_dd_add(d, mm_dd_mul(a[i * w + k], a[i * w + j]));
            mm_dd f = mm_dd_div(mm_dd_mul_d(d, 2), vtv);
            for (int i = k; i < n; i++)
                a[i * w + j] = mm_dd_sub(a[i * w + j], mm_dd_mul(f, a[i * w + k]));
        }
        a[k * w + k] = alpha;                                 /* R(k, k) */
    }
    /* R b = (Q^T y)_1..m */
    for (int j = m - 1; j >= 0; j--) {
        mm_dd s = a[j * w + m];
        for (int k = j + 1; k < m; k++)
            s = mm_dd_sub(s, mm_dd_mul(a[j * w + k], b[k]));
        b[j] = mm_dd_div(s, a[j * w + j]);
    }
    /* cond of the Vandermonde matrix in (x - mu) / dev: R with its columns
     * scaled by (scale / dev)^(power) */
    double f = dev > 0 ? scale / dev : 1;                  /* t / ((x - mu) / dev) */
    for (int i = 0; i < m; i++)
        for (int j = 0; j < m; j++)
            A[i * m + j] = j >= i ? mm_dd_val(a[i * w + j]) * pow(f, degree - j) : 0;
    if ((rc = mm_linalg_svdvals_dd(m, m, A, sv, sv + m, err)))
        goto out;
    double smin = sv[m - 1] - sv[2 * m - 1];
    if (!(smin > 0)) {
        rc = mm_error_set(err, MM_ESINGULAR, "x", "the points do not fix a polynomial of degree %d (the "
                          "least-squares matrix is singular to 32 digits)", degree);
        goto out;
    }
    inf.cond = sv[0] / sv[m - 1];
    inf.cond_err = (sv[0] + sv[m]) / smin - inf.cond + 2 * DBL_EPSILON * inf.cond;
    /* the same in the t actually used, for the bounds (R itself, rounded:
     * its singular values are those of A to ~1e-16, a 1 % margin covers it) */
    for (int i = 0; i < m; i++)
        for (int j = 0; j < m; j++)
            A[i * m + j] = j >= i ? mm_dd_val(a[i * w + j]) : 0;
    if ((rc = mm_linalg_svdvals_dd(m, m, A, sv, sv + m, err)))
        goto out;
    double kappa = 1.01 * sv[0] / (sv[m - 1] - sv[2 * m - 1]), smax = 0.99 * sv[0];
    /* fitted values and residuals in dd */
    double rss = 0, ynorm = 0, bnorm = 0;
    for (int j = 0; j < m; j++)
        bnorm += dabs(b[j]) * dabs(b[j]);
    bnorm = sqrt(bnorm);
    for (int i = 0; i < n; i++) {
        mm_dd v = b[0];
        for (int j = 1; j < m; j++)
            v = mm_dd_add(mm_dd_mul(v, t[i]), b[j]);
        fv[i] = v;
        mm_dd r = mm_dd_sub(mm_dd_from(y[i]), v);
        rss += dabs(r) * dabs(r);
        ynorm += y[i] * y[i];
    }
    ynorm = sqrt(ynorm);
    /* Wedin: ||db|| <= kappa / ||A|| (||dA|| (||b|| + kappa ||r|| / ||A||) + ||dy||) with the
     * backward error of Householder QR, ||dA|| <= 10 n m eps_dd ||A|| and ||dy|| likewise */
    double gam = 10.0 * n * m * MM_DD_EPS;
    double db = 2 * kappa * gam * (bnorm + kappa * sqrt(rss) / smax + ynorm / smax);
    for (int i = 0; i < n; i++) {
        double tp = 0, ti = dabs(t[i]), pw = 1, mag = 0;
        for (int j = degree; j >= 0; j--) {
            tp += pw * pw;
            mag += dabs(b[j]) * pw;
            pw *= ti;
        }
        fit[i] = mm_dd_val(fv[i]);
        fit_err[i] = db * sqrt(tp) + 2 * m * MM_DD_EPS * mag + dabs(mm_dd_sub(fv[i], mm_dd_from(fit[i])));
    }
    inf.rms = sqrt(rss / n);
    double e2 = 0;
    for (int i = 0; i < n; i++)
        e2 += fit_err[i] * fit_err[i];
    inf.rms_err = sqrt(e2 / n) + 2 * DBL_EPSILON * inf.rms;
    /* expand to powers of x: T(j, k) = coefficient of x^(degree-k) in t^(degree-j),
     * t = x / scale - mu / scale; P holds t^p, highest power first, right-aligned */
    mm_dd a1 = mm_dd_from(inv), a0 = mm_dd_mul_d(mm_dd_from(-mu), inv);
    for (int k = 0; k <= m; k++)
        P[k] = mm_dd_from(0);
    P[m - 1] = mm_dd_from(1);                                 /* t^0 */
    for (int p = 0; p <= degree; p++) {
        int j = degree - p;                                   /* row of T: t^p is b[j]'s basis */
        for (int k = 0; k < m; k++)
            T[j * m + k] = P[k];
        for (int k = 0; k < m; k++) {                         /* P <- P (a1 x + a0) */
            mm_dd next = k + 1 < m ? P[k + 1] : mm_dd_from(0);
            P[k] = mm_dd_add(mm_dd_mul(a1, next), mm_dd_mul(a0, P[k]));
        }
    }
    for (int k = 0; k < m; k++) {
        mm_dd s = mm_dd_from(0);
        double e = 0;
        for (int j = 0; j < m; j++) {
            s = mm_dd_add(s, mm_dd_mul(b[j], T[j * m + k]));
            /* |T| from binomials of |mu| / scale: the rounding of T itself is
             * a relative (degree + 2) eps_dd of |T| */
            e += dabs(T[j * m + k]) * (db + 4 * (degree + 3) * MM_DD_EPS * dabs(b[j]));
        }
        c[k] = mm_dd_val(s);
        c_err[k] = 1.01 * e + dabs(mm_dd_sub(s, mm_dd_from(c[k])));
        if (!isfinite(c[k]) || !isfinite(c_err[k])) {
            rc = mm_error_set(err, MM_ENONFINITE, "x", "the coefficients of powers of x overflow");
            goto out;
        }
    }
    if (bt)
        for (int j = 0; j < m; j++)
            bt[j] = mm_dd_val(b[j]);
    /* standard errors: Cov(c) = sigma^2 T^T R^-1 R^-T T, row k of T^T R^-1 */
    inf.dof = n - m;
    if (se) {
        double sigma = inf.dof > 0 ? sqrt(rss / inf.dof) : 0;
        for (int k = 0; k < m; k++) {                         /* G = (R^-T T)(:, k): solve R^T g = T(:, k) */
            for (int j = 0; j < m; j++) {
                mm_dd s = T[j * m + k];
                for (int i = 0; i < j; i++)
                    s = mm_dd_sub(s, mm_dd_mul(a[i * w + j], G[i * m + k]));
                G[j * m + k] = mm_dd_div(s, a[j * w + j]);
            }
            double q = 0;
            for (int j = 0; j < m; j++)
                q += dabs(G[j * m + k]) * dabs(G[j * m + k]);
            se[k] = sigma * sqrt(q);
        }
    }
    rc = MM_OK;
out:
    *info = inf;
    free(fv); free(sv); free(A); free(P); free(G); free(T); free(b); free(t); free(a);
    return rc;
}
