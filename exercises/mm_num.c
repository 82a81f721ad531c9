/* mm_num.c — helpers of the chapter-1 (numerical methods) exercises (see
 * mm_num.h). */
#include "mm_num.h"

#include <math.h>
#include <stdlib.h>

#include "mm_exhelp.h"

mm_scalar *mm_num_scalar_i_err(mm_result *res, int out, int i, double value, double error, mm_err_kind kind)
{
    mm_scalar *s = mm_res_scalar_i(res, out, i, value);
    s->error = error;
    s->error_kind = kind;
    return s;
}

void mm_num_scalar_dd(mm_result *res, int out, mm_dd v, double e)
{
    double x = mm_dd_val(v);
    double total = e + mm_dd_abs(mm_dd_sub(v, mm_dd_from(x)));
    mm_scalar *s = mm_res_scalar_err(res, out, x, total, MM_ERR_BOUND);
    if (total == 0)
        s->exact = 1;
}

int mm_num_arrow(mm_result *res, int out, double x, double y)
{
    mm_series *s = mm_res_series(res, out, 2);
    if (!s)
        return MM_ENOMEM;
    s->x[1] = x;
    s->y[1] = y;
    return MM_OK;
}

int mm_num_powers(mm_result *res, int out, mm_cdd a, int n)
{
    int m = abs(n) + 1;
    mm_series *s = mm_res_series(res, out, m);
    if (!s)
        return MM_ENOMEM;
    mm_cdd step = n >= 0 ? a : mm_cdd_div(mm_cdd_exact(1, 0), a), p = mm_cdd_exact(1, 0);
    for (int j = 0; j < m; j++) {
        s->x[j] = mm_dd_val(p.re);
        s->y[j] = mm_dd_val(p.im);
        p = mm_cdd_mul(p, step);
    }
    return MM_OK;
}

int mm_num_poly_curve(mm_result *res, int out, int ncoef, const double *p, const mm_poly_root *roots, int nr)
{
    double lo = roots[0].re, hi = lo;
    for (int i = 0; i < nr; i++) {
        lo = fmin(lo, roots[i].re);
        hi = fmax(hi, roots[i].re);
    }
    double span = fmax(hi - lo, fmax(1e-3 * fmax(fabs(lo), fabs(hi)), 1e-3)), m = 0.25 * span;
    enum { NP = 201 };
    double xs[NP], ys[NP];
    int ok = 1;
    mm_linspace(lo - m, hi + m, NP, xs);
    for (int i = 0; i < NP && ok; i++) {
        ys[i] = mm_poly_eval(ncoef, p, xs[i], NULL);
        ok = isfinite(ys[i]);
    }
    if (!ok) {
        mm_res_warn(res, "p(x) overflows on the plot range; the curve is left out");
        return MM_OK;
    }
    mm_series *s = mm_res_series(res, out, NP);
    if (!s)
        return MM_ENOMEM;
    for (int i = 0; i < NP; i++) {
        s->x[i] = xs[i];
        s->y[i] = ys[i];
    }
    return MM_OK;
}

int mm_num_fit_plot(mm_result *res, int data, int curve, int n, const double *x, const double *y, int ncoef,
                    const double *bt, double mu, double scale)
{
    enum { NP = 201 };
    mm_series *sd = mm_res_series(res, data, n), *sf = mm_res_series(res, curve, NP);
    if (!sd || !sf)
        return MM_ENOMEM;
    double xlo = x[0], xhi = x[0];
    for (int i = 0; i < n; i++) {
        sd->x[i] = x[i];
        sd->y[i] = y[i];
        xlo = fmin(xlo, x[i]);
        xhi = fmax(xhi, x[i]);
    }
    double margin = xhi > xlo ? 0.05 * (xhi - xlo) : 1;
    mm_linspace(xlo - margin, xhi + margin, NP, sf->x);
    for (int i = 0; i < NP; i++)
        sf->y[i] = mm_poly_eval(ncoef, bt, (sf->x[i] - mu) / scale, NULL);
    return MM_OK;
}
