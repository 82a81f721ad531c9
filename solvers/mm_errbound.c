/* mm_errbound.c — error bounds of computed numbers (see mm_errbound.h). */
#include "mm_errbound.h"

#include <float.h>
#include <math.h>

#include "mm_dd.h"
#include "mm_linalg.h"

#define U (DBL_EPSILON / 2)

double mm_errbound_cond(double s1, double e1, double sn, double en)
{
    /* the exact one is within (s1 / sn) (e1 / s1 + en / sn_lo) of s1 / sn,
     * and the division rounds by u more (the interval's ends in double were
     * 1.4 u off at num-linear-system's defaults) */
    double cond = s1 / sn, sn_lo = sn - en;
    return (1 + 8 * U) * cond * ((1 + U) * (e1 / s1 + en / sn_lo) + U);
}

double mm_errbound_solve(int n, const double *A, const double *b, const double *xc, double sigma_min_lo,
                         double *omega, double *work)
{
    double *r = work, *mag = work + n;
    mm_linalg_residual_dd(n, A, xc, b, r, mag);
    double bound = (mm_linalg_norm2(n, r) + 4 * MM_DD_EPS * n * mm_linalg_norm2(n, mag)) / sigma_min_lo;
    *omega = 0;
    for (int i = 0; i < n; i++)
        *omega = fmax(*omega, mag[i] > 0 ? fabs(r[i]) / mag[i] : 0);
    return bound;
}

double mm_errbound_rounded_residual(int n, const double *A, const double *x, const double *x_err, double *work)
{
    for (int i = 0; i < n; i++) {
        double acc = 0;
        for (int j = 0; j < n; j++)
            acc += fabs(A[i * n + j]) * (U * fabs(x[j]) + x_err[j]);
        work[i] = acc;
    }
    return mm_linalg_norm2(n, work);
}

int mm_errbound_sym_extremes(int n, const double *a, double *work, mm_errbound_sym *b, mm_error *err)
{
    double *w = work, *we = work + n;
    int rc = mm_linalg_sygv_dd(n, a, NULL, w, we, NULL, err);
    b->norm_hi = fmax(fabs(w[0]) + we[0], fabs(w[n - 1]) + we[n - 1]);
    b->min_lo = w[0] - we[0];
    b->min = w[0], b->max = w[n - 1];
    return rc;
}

double mm_errbound_sqrt(double lambda, double lambda_err, double *omega_err)
{
    double om = sqrt(fmax(lambda, 0)), lo = sqrt(fmax(lambda - lambda_err, 0)), hi = sqrt(lambda + lambda_err);
    /* |sqrt(lambda*) - sqrt(lambda)| = |lambda* - lambda| / (sqrt(lambda*) + sqrt(lambda))
     * <= lambda_err / (lo + om): as hi - om in double the bound was u omega alone,
     * 8 of 200 draws of num-eigen 1.01-1.24x over it (tests/ref/num_ref.py) */
    *omega_err = (lambda - lambda_err > 0 ? lambda_err / (lo + om) : fmax(hi - om, om - lo)) * (1 + 4 * U) + U * om;
    return om;
}

double mm_errbound_trace(int n, const double *MK, double ferr, const double *lambda, const double *lambda_err,
                         double *trace, double *sum)
{
    double tr = 0, sl = 0, tol = 0;
    for (int j = 0; j < n; j++) {
        double cmax = 0;
        for (int i = 0; i < n; i++)
            cmax = fmax(cmax, fabs(MK[i * n + j]));
        tr += MK[j * n + j];
        sl += lambda[j];
        tol += lambda_err[j] + ferr * cmax + 2 * n * U * (fabs(lambda[j]) + fabs(MK[j * n + j]));
    }
    *trace = tr;
    *sum = sl;
    return tol;
}

double mm_errbound_ulp(double x) { return x == 0 ? 0 : ldexp(1, ilogb(x) - 52); }

double mm_errbound_arg(mm_cdd z, double *err)
{
    double zre = mm_dd_val(z.re) + 0.0, zim = mm_dd_val(z.im) + 0.0;
    double mz = sqrt(mm_dd_add(mm_dd_mul(z.re, z.re), mm_dd_mul(z.im, z.im)).hi);
    if (!(mz > 0)) {
        *err = z.err > 0 ? M_PI : 0;
        return 0;
    }
    double ang = atan2(zim, zre);
    double lo = (zre * (z.im.lo + (z.im.hi - zim)) - zim * (z.re.lo + (z.re.hi - zre))) / (mz * mz);
    double aerr = z.err / (mz - fmin(z.err, 0.5 * mz)) * 2 + mm_errbound_ulp(ang);
    *err = aerr + fabs(lo) * U;
    return ang + lo;
}

double mm_errbound_polar(double r, int an, double th)
{
    return r * ((2.0 * an + 6) * U + (3.0 * an * th + 2) * 2 * U) * M_SQRT2;
}

void mm_errbound_roots(mm_cdd a, double r, double theta, int n, double *re, double *im, double *back,
                       double *back_tol, double *sum, double *sum_tol)
{
    double bk = 0, bk_tol = 0, sre = 0, sim = 0, stol = 0;
    for (int k = 0; k < n; k++) {
        mm_cdd w = mm_cdd_root(a, r, theta, n, k);
        re[k] = mm_dd_val(w.re), im[k] = mm_dd_val(w.im);
        mm_cdd wn = mm_cdd_pow(mm_cdd_exact(re[k], im[k]), n);
        double mw = hypot(re[k], im[k]), dw = w.err + M_SQRT2 * U * mw;
        bk = fmax(bk, hypot(mm_dd_val(mm_dd_sub(wn.re, a.re)), mm_dd_val(mm_dd_sub(wn.im, a.im))));
        bk_tol = fmax(bk_tol, 1.01 * n * pow(mw + dw, n - 1) * dw + wn.err);
        sre += re[k], sim += im[k];
        stol += dw + 2 * U * (fabs(sre) + fabs(sim));
    }
    *back = bk;
    *back_tol = bk_tol;
    *sum = hypot(sre, sim);
    *sum_tol = 1.01 * stol;
}
