/* mm_polycheck.c — independent checks of polynomial roots and fits (see
 * mm_polycheck.h). */
#include "mm_polycheck.h"

#include <float.h>
#include <math.h>

#include "mm_dd.h"

#define U (DBL_EPSILON / 2)

void mm_poly_roots_summarize(int ncoef, const double *p, const mm_poly_root *roots, mm_poly_roots_summary *s)
{
    int d = ncoef - 1;
    double sabs = 0, serr = 0, lerr = 0;
    *s = (mm_poly_roots_summary){0};
    for (int i = 0; i < d; i++) {
        const mm_poly_root *z = &roots[i];
        double mod = hypot(z->re, z->im);
        s->real += fabs(z->im) <= z->err;
        s->sure_real += z->im == 0 && z->multiplicity == 1;
        s->max_err = fmax(s->max_err, z->err);
        if ((z->flags & MM_POLY_ROOT_MULTIPLE) && z->err > 0) {
            s->multiple++;
            s->mult_err = fmax(s->mult_err, z->err);
        }
        if ((z->flags & MM_POLY_ROOT_ILLCOND) && !(z->flags & MM_POLY_ROOT_MULTIPLE)) {
            s->illcond++;
            s->ill_err = fmax(s->ill_err, z->err);
        }
        s->backward = fmax(s->backward, mm_poly_backward_error(ncoef, p, z->re, z->im));
        s->sum += z->re;
        serr += z->err;
        sabs += mod;
        if (mod == 0) {
            s->zeros++;
        } else {
            s->logprod += log(mod);
            lerr += z->err / mod;
        }
    }
    s->sum_ref = d >= 1 ? -p[1] / p[0] : 0;
    s->sum_tol = serr + 4 * d * DBL_EPSILON * (sabs + fabs(s->sum_ref));
    if (s->zeros == 0) {
        s->logprod_ref = log(fabs(p[d])) - log(fabs(p[0]));
        s->logprod_tol = lerr + 4 * d * DBL_EPSILON * (1 + fabs(s->logprod));
    }
}

int mm_poly_distinct(int n, const double *x)
{
    int count = 0;
    for (int i = 0; i < n; i++) {
        int seen = 0;
        for (int j = 0; j < i && !seen; j++)
            seen = x[j] == x[i];
        count += !seen;
    }
    return count;
}

static double maxabs(int n, const double *y)
{
    double m = 0;
    for (int i = 0; i < n; i++)
        m = fmax(m, fabs(y[i]));
    return m;
}

double mm_poly_fit_level(int n, const double *x, const double *y, int ncoef, const double *c)
{
    int d = ncoef - 1;
    double terms = 0;
    for (int i = 0; i < n; i++) {
        double tk = 0;
        for (int k = 0; k <= d; k++)
            tk = tk * fabs(x[i]) + fabs(c[k]);
        terms = fmax(terms, tk);
    }
    return (2.0 * d + 2) * U * terms + (n + ncoef) * U * maxabs(n, y);
}

double mm_poly_horner_deviation(int n, const double *x, int ncoef, const double *c, const double *c_err,
                                const double *fit, const double *fit_err, double *rounding, double *terms)
{
    int d = ncoef - 1;
    double magmax = 0, cdev = 0, ctol = 0;
    for (int i = 0; i < n; i++) {
        double mag = 0, cerr = 0;
        for (int k = 0; k <= d; k++) {
            mag = mag * fabs(x[i]) + fabs(c[k]);
            cerr = cerr * fabs(x[i]) + c_err[k];
        }
        magmax = fmax(magmax, mag);
        cdev = fmax(cdev, fabs(mm_poly_eval(ncoef, c, x[i], NULL) - fit[i]) /
                              (1.01 * ((2 * d + 1) * U * mag + cerr + fit_err[i]) + DBL_MIN));
        ctol = fmax(ctol, (2 * d + 1) * U * mag);
    }
    *rounding = ctol;
    *terms = magmax;
    return cdev;
}

double mm_poly_normal_residual(int n, const double *x, const double *r, const double *r_err, int ncoef, double mu,
                               double scale)
{
    double worst = 0;
    for (int k = 0; k < ncoef; k++) {
        mm_dd s = mm_dd_from(0);
        double bound = 0;
        for (int i = 0; i < n; i++) {
            mm_dd tk = mm_dd_from(1);
            for (int j = 0; j < k; j++)
                tk = mm_dd_mul(tk, mm_dd_two_sum(x[i], -mu));
            tk = mm_dd_mul_d(tk, pow(scale, -k));
            s = mm_dd_add(s, mm_dd_mul_d(tk, r[i]));
            bound += fabs(mm_dd_val(tk)) * (r_err[i] + U * fabs(r[i]) + 4 * (k + 2) * MM_DD_EPS * fabs(r[i]));
        }
        worst = fmax(worst, mm_dd_abs(s) / (1.01 * bound + DBL_MIN));
    }
    return worst;
}

void mm_poly_line_fit(int n, const double *x, const double *y, mm_poly_line *l)
{
    double ybar = 0, mean = 0, ymax = maxabs(n, y);
    for (int i = 0; i < n; i++) {
        ybar += y[i];
        mean += x[i];
    }
    ybar /= n;
    mean /= n;
    double sxx = 0, sxy = 0, ax = 0, axy = 0;
    for (int i = 0; i < n; i++) {
        sxx += (x[i] - mean) * (x[i] - mean);
        sxy += (x[i] - mean) * (y[i] - ybar);
        ax += fabs(x[i] - mean) * (fabs(x[i]) + fabs(mean));
        axy += fabs(x[i] - mean) * (fabs(y[i]) + fabs(ybar)) + fabs(y[i] - ybar) * (fabs(x[i]) + fabs(mean));
    }
    double slope = sxy / sxx, icpt = ybar - slope * mean;
    double es = (n + 4) * U * (axy / sxx + fabs(slope) * ax / sxx) + U * fabs(slope);
    l->mean_y = ybar;
    l->mean_y_err = (n + 1) * U * ymax;
    l->slope = slope;
    l->slope_err = es;
    l->intercept = icpt;
    l->intercept_err = (n + 2) * U * (ymax + fabs(slope * mean)) + es * fabs(mean);
}

/* the forward error bound of the fitted values from a backward-stable solve
 * in double: (A + dA) b = y with ||dA|| <= g ||A|| (the normal equations:
 * squared, kappa^2 in place of the first kappa) */
static double fit_bound(double g, double kappa, double anorm, double bnorm, double rnorm, double ynorm, int squared)
{
    double k = squared ? kappa * kappa : kappa;
    return g * (k * anorm * bnorm + kappa * rnorm + ynorm);
}

int mm_poly_fit_two_routes(int n, const double *x, const double *y, int degree, double mu, double scale,
                           double cond, double rms, const double *fit, const double *fit_err, double *work,
                           mm_poly_fit_routes *o, mm_error *err)
{
    double *fs = work, *fn = work + n, bsv, bne;
    int m = degree + 1, rc = mm_poly_fit_values(n, x, y, degree, mu, scale, fs, fn, &bsv, &bne, err);
    if (rc != MM_OK)
        return rc;
    double kappa = cond, anorm = sqrt((double)n * m), rn = rms * sqrt((double)n), yn = 0;
    double dsvd = 0, dne = 0, g = 2.0 * m * n * U;
    for (int i = 0; i < n; i++) {
        yn += y[i] * y[i];
        dsvd = fmax(dsvd, fabs(fs[i] - fit[i]) - fit_err[i]);
        dne = fmax(dne, fabs(fn[i] - fit[i]) - fit_err[i]);
    }
    yn = sqrt(yn);
    o->dev_svd = fmax(dsvd, 0);
    o->dev_ne = fmax(dne, 0);
    o->bound_svd = fit_bound(g, kappa, anorm, bsv, rn, yn, 0);
    o->bound_ne = fit_bound(g, kappa, anorm, bne, rn, yn, 1);
    return MM_OK;
}
