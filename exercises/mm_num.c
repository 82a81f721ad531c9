/* mm_num.c — helpers of the chapter-1 (numerical methods) exercises (see
 * mm_num.h). */
#include "mm_num.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mm_exhelp.h"
#include "mm_mdof.h"
#include "mm_vib.h"

int mm_num_f_compile(mm_num_f *f, const char *text, mm_error *err)
{
    static const char *const vars[] = {"x"};
    *f = (mm_num_f){NULL, 0};
    int rc = mm_expr_compile(text, vars, 1, &f->e, err);
    if (rc != MM_OK && err)
        snprintf(err->param, sizeof err->param, "f");
    return rc;
}

void mm_num_f_free(mm_num_f *f)
{
    mm_expr_free(f->e);
    f->e = NULL;
}

int mm_num_f_eval(double x, double *fx, void *ctx)
{
    mm_num_f *f = ctx;
    f->evals++;
    *fx = mm_expr_eval(f->e, &x);
    return 0;
}

double mm_num_f_at(mm_num_f *f, double x)
{
    f->evals++;
    return mm_expr_eval(f->e, &x);
}

int mm_num_f_eval_err(double x, double *fx, double *err, void *ctx)
{
    mm_num_f *f = ctx;
    *fx = mm_expr_eval_err(f->e, &x, err);
    return 0;
}

double mm_num_f_rounding(mm_num_f *f, int n, const double *x)
{
    double ef = 0;
    for (int i = 0; i < n; i += (n + 31) / 32) {
        double e;
        mm_expr_eval_err(f->e, &x[i], &e);
        ef = fmax(ef, e);
    }
    return ef;
}

double mm_num_f_value_err(double x, double *err, void *ctx)
{
    mm_num_f *f = ctx;
    if (err)
        return mm_expr_eval_err(f->e, &x, err);
    return mm_num_f_at(f, x);
}

int mm_num_f_curve(mm_result *res, int out, mm_num_f *f, double a, double b, int np, int *bad,
                   double *first_bad, int *crossings)
{
    double *xs = mm_res_alloc(res, (size_t)np * sizeof *xs), *ys = mm_res_alloc(res, (size_t)np * sizeof *ys);
    if (!xs || !ys)
        return MM_ENOMEM;
    mm_linspace(a, b, np, xs);
    int m = 0;
    double prev = NAN;
    *bad = 0, *first_bad = 0, *crossings = 0;
    for (int i = 0; i < np; i++) {
        double y = mm_expr_eval(f->e, &xs[i]);
        if (isfinite(y) && (y == 0 || (isfinite(prev) && prev != 0 && (prev < 0) != (y < 0))))
            ++*crossings;
        prev = y;
        if (isfinite(y)) {
            xs[m] = xs[i];
            ys[m++] = y;
        } else if (!(*bad)++) {
            *first_bad = xs[i];
        }
    }
    mm_series *s = mm_res_series(res, out, m);
    if (!s)
        return MM_ENOMEM;
    memcpy(s->x, xs, m * sizeof *xs);
    memcpy(s->y, ys, m * sizeof *ys);
    return MM_OK;
}

void mm_num_list(char *list, const double *v, int n)
{
    list[0] = '\0';
    for (int i = 0; i < n && strlen(list) < 90; i++) {
        size_t l = strlen(list);
        snprintf(list + l, MM_NUM_LIST - l, "%s%.6g", i ? ", " : "", v[i]);
    }
}

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

int mm_num_newmark_run(const mm_newmark_problem *pb, const mm_newmark_options *base, double h, long N, long stride,
                       int points, mm_num_newmark_rows *o, mm_result *res, mm_error *err)
{
    int n = pb->n;
    mm_newmark_problem prob = *pb;
    prob.t_end = N * h;
    mm_newmark_options opt = *base;
    opt.h = h, opt.stride = stride, opt.points = points, opt.work_in_q = 1;
    int rc = mm_newmark_check(&prob, &opt, err), rows = mm_newmark_output_rows(&prob, &opt);
    if (rc != MM_OK)
        return rc;
    o->t = mm_res_alloc(res, (size_t)rows * sizeof *o->t);
    o->q = mm_res_alloc(res, (size_t)rows * n * sizeof *o->q);
    o->e = mm_res_alloc(res, (size_t)rows * sizeof *o->e);
    mm_newmark_work *w = mm_newmark_work_alloc(n);
    if (!o->t || !o->q || !o->e || !w) {
        mm_newmark_work_free(w);
        return MM_ENOMEM;
    }
    o->r = (mm_newmark_result){.t = o->t, .q = o->q, .energy = o->e, .max_rows = rows};
    rc = mm_newmark_solve(&prob, &opt, w, &o->r, err);
    mm_newmark_work_free(w);
    return rc;
}

int mm_num_newmark_draw(mm_result *res, int n, const double *K, const mm_num_newmark_rows *a)
{
    mm_anim *an = mm_res_animation(res, a->r.rows, "t", "s");
    if (!an)
        return MM_ENOMEM;
    memcpy(an->t, a->t, (size_t)a->r.rows * sizeof *a->t);
    return mm_vib_masses_draw(res, n, K, a->r.rows, a->q, 4 * mm_vib_big(a->q, (size_t)a->r.rows * n));
}

int mm_num_newmark_modes(mm_result *res, int out, int n, const double *M, const double *C, const double *K, double h,
                         double *wmax, double *kappa, mm_error *err)
{
    double *w = mm_res_alloc(res, (size_t)(n * n + 2 * n) * sizeof *w), *wm = w + n, *Id = wm + n;
    mm_mdof_cmode *cm = mm_res_alloc(res, (size_t)n * sizeof *cm);
    mm_table *mt = mm_res_table(res, out, n);
    if (!w || !cm || !mt)
        return MM_ENOMEM;
    for (int i = 0; i < n * n; i++)
        Id[i] = i % (n + 1) == 0;
    mm_mdof_system ms = {n, M, C, K}, mi = {n, Id, NULL, M};       /* the eigenvalues of M: its conditioning */
    int rc;
    if ((rc = mm_mdof_modes(&(mm_mdof_system){n, M, NULL, K}, n, w, NULL, NULL, err)) ||
        (rc = mm_mdof_modes(&mi, n, wm, NULL, NULL, err)) || (rc = mm_mdof_complex_modes(&ms, cm, err)))
        return rc;
    *wmax = w[n - 1];
    *kappa = wm[0] > 0 ? wm[n - 1] * wm[n - 1] / (wm[0] * wm[0]) : 1 / DBL_EPSILON;
    for (int j = 0; j < n; j++) {
        double row[5] = {j + 1, cm[j].omega, cm[j].zeta, cm[j].omega_d, cm[j].omega * h};
        memcpy(mt->cell + 5 * j, row, sizeof row);
    }
    return MM_OK;
}
