/* mm_kin.c — the kinematics chapter's kit (see mm_kin.h). */
#include "mm_kin.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mm_exhelp.h"
#include "mm_expr.h"
#include "mm_geom.h"
#include "mm_quad.h"

/* ---- drawing ------------------------------------------------------------------------ */

mm_anim *mm_kin_draw_start(mm_kin_draw *d, mm_result *res, int nf, const char *t_label,
                           const char *t_unit, double size)
{
    memset(d, 0, sizeof *d);
    d->res = res;
    d->nf = nf;
    d->size = size > 0 && isfinite(size) ? size : 1;
    d->inv_grid = pow(10, -floor(log10(1e-4 * d->size)));   /* an exact power of ten */
    d->anim = mm_res_animation(res, nf, t_label, t_unit);
    return d->anim;
}

mm_shape *mm_kin_shape(mm_kin_draw *d, const char *name, mm_shape_kind kind, int moving, int npts)
{
    if (d->nshapes >= MM_KIN_MAX_SHAPES)
        return NULL;
    mm_shape *s = mm_anim_shape(d->res, name, kind, moving ? d->nf : 1, npts);
    if (s)
        d->shapes[d->nshapes++] = s;
    return s;
}

void mm_kin_pt(mm_shape *s, int f, int k, double x, double y)
{
    size_t i = (size_t)(s->frames > 1 ? f : 0) * (size_t)s->npts + (size_t)k;
    s->x[i] = x;
    s->y[i] = y;
}

mm_shape *mm_kin_arrow_shape(mm_kin_draw *d, const char *name, const char *unit, double vmax)
{
    mm_shape *s = mm_kin_shape(d, name, MM_SHAPE_ARROW, 1, 2);
    if (!s)
        return NULL;
    s->unit = unit;
    s->scale = vmax > 0 && isfinite(vmax) ? 0.3 * d->size / vmax : 0;
    /* a scale of short decimals: 3 significant digits */
    if (s->scale > 0) {
        double p = pow(10, floor(log10(s->scale)) - 2);
        s->scale = round(s->scale / p) * p;
    }
    return s;
}

void mm_kin_arrow(mm_shape *s, int f, double x, double y, double vx, double vy)
{
    mm_kin_pt(s, f, 0, x, y);
    mm_kin_pt(s, f, 1, x + s->scale * vx, y + s->scale * vy);
}

mm_shape *mm_kin_pivot(mm_kin_draw *d, const char *name, double x, double y)
{
    mm_shape *s = mm_kin_shape(d, name, MM_SHAPE_POLYGON, 0, 3);
    if (!s)
        return NULL;
    double h = 0.04 * d->size;
    s->style = "ground";
    mm_kin_pt(s, 0, 0, x, y);
    mm_kin_pt(s, 0, 1, x - 0.6 * h, y - h);
    mm_kin_pt(s, 0, 2, x + 0.6 * h, y - h);
    return s;
}

void mm_kin_block(mm_shape *s, int f, double x, double y, double w, double h, double angle)
{
    static const double corner[4][2] = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
    double c = cos(angle), sn = sin(angle);
    for (int k = 0; k < 4; k++) {
        double u = corner[k][0] * w, v = corner[k][1] * h;
        mm_kin_pt(s, f, k, x + c * u - sn * v, y + sn * u + c * v);
    }
}

int mm_kin_draw_finish(mm_kin_draw *d)
{
    double g = d->inv_grid;
    for (int i = 0; i < d->nshapes; i++) {
        mm_shape *s = d->shapes[i];
        size_t m = (size_t)s->frames * (size_t)s->npts;
        for (size_t k = 0; k < m; k++) {
            s->x[k] = round(s->x[k] * g) / g;
            s->y[k] = round(s->y[k] * g) / g;
        }
    }
    return MM_OK;
}

/* ---- a finite-difference study --------------------------------------------------------- */

int mm_kin_fd_study(mm_result *res, int out, const char *what, mm_kin_pos_fn pos, void *ctx, int k,
                    const double *w, int n, const double *d, int deriv, double h0, int nh, double d_err,
                    mm_kin_fd *fd, mm_error *err)
{
    enum { KMAX = 16 };
    memset(fd, 0, sizeof *fd);
    nh = nh > MM_KIN_FD_MAX ? MM_KIN_FD_MAX : nh;
    fd->nh = nh;
    double *D = mm_res_alloc(res, (size_t)nh * (size_t)n * (size_t)k * sizeof *D);   /* D[m][i][j] */
    double *R = mm_res_alloc(res, (size_t)nh * (size_t)n * (size_t)k * sizeof *R);   /* rounding bounds */
    if (!D || !R || k > KMAX)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    double q0[KMAX], qp[KMAX], qm[KMAX], big = 0, e0 = 0, ep, em;
    for (int i = 0; i < n; i++) {
        int rc = deriv == 2 ? pos(i, 0, q0, &e0, ctx, err) : MM_OK;
        if (rc != MM_OK)
            return rc;
        for (int m = 0; m < nh; m++) {
            double h = ldexp(h0, -m);
            if ((rc = pos(i, h, qp, &ep, ctx, err)) != MM_OK || (rc = pos(i, -h, qm, &em, ctx, err)) != MM_OK)
                return rc;
            for (int j = 0; j < k; j++) {
                double wj = w ? w[j] : 1, *Dm = D + ((size_t)m * (size_t)n + (size_t)i) * (size_t)k + (size_t)j;
                double *Rm = R + (Dm - D);
                double sum = fabs(qp[j]) + fabs(qm[j]) + (deriv == 2 ? 2 * fabs(q0[j]) : 0);
                /* half an ulp in each position, a few for the subtraction and
                 * division, and each position's own error (weighted) */
                double perr = 4 * DBL_EPSILON * sum * wj + ep + em + (deriv == 2 ? 2 * e0 : 0);
                if (deriv == 1) {
                    *Dm = wj * (qp[j] - qm[j]) / (2 * h);
                    *Rm = perr / (2 * h);
                } else {
                    *Dm = wj * (qp[j] - 2 * q0[j] + qm[j]) / (h * h);
                    *Rm = perr / (h * h);
                }
            }
        }
        for (int j = 0; j < k; j++)
            big = fmax(big, fabs(d[(size_t)i * (size_t)k + (size_t)j]) * (w ? w[j] : 1));
    }
    /* the worst error over the samples at each step */
    for (int m = 0; m < nh; m++) {
        fd->h[m] = ldexp(h0, -m);
        for (size_t c = 0; c < (size_t)n * (size_t)k; c++) {
            double wj = w ? w[c % (size_t)k] : 1;
            double e = fabs(D[(size_t)m * (size_t)n * (size_t)k + c] - wj * d[c]);
            if (!(e <= fd->err[m]))
                fd->err[m] = e;
            fd->round[m] = fmax(fd->round[m], R[(size_t)m * (size_t)n * (size_t)k + c]);
        }
    }
    /* the range where truncation rules: error above 100x its rounding bound */
    int first = -1, last = -1;
    for (int m = 0; m < nh; m++) {
        if (fd->err[m] > 100 * fd->round[m]) {
            if (first < 0)
                first = m;
            last = m;
        } else if (first >= 0) {
            break;
        }
    }
    char name[200];
    if (first >= 0 && last - first + 1 >= 3) {
        int nfit = last - first + 1 > 4 ? 4 : last - first + 1;
        int m0 = last - nfit + 1;                      /* the smallest steps of the range */
        fd->nfit = nfit;
        snprintf(name, sizeof name, "%s: observed order of the central difference (steps %.3g to %.3g)", what,
                 fd->h[m0], fd->h[last]);
        fd->slope = mm_check_order(res, name, nfit, fd->h + m0, fd->err + m0, 2, 0.15);
    }
    /* the value: at the step whose bound 2 |D(h) - D(h/2)| + 3 (R(h) + R(h/2))
     * is smallest (the truncation error of D(h) is 4/3 |D(h) - D(h/2)| to
     * leading order; R bounds the rounding), sample by sample */
    size_t nk = (size_t)n * (size_t)k;
    double best = INFINITY;
    int mb = 0;
    for (int m = 0; m + 1 < nh; m++) {
        double bm = 0;
        for (size_t c = 0; c < nk; c++) {
            size_t i0 = (size_t)m * nk + c, i1 = i0 + nk;
            bm = fmax(bm, 2 * fabs(D[i0] - D[i1]) + 3 * (R[i0] + R[i1]) + d_err);
        }
        if (bm < best)
            best = bm, mb = m;
    }
    fd->h_check = fd->h[mb];
    double ratio = -1, got = 0, ref = 0, tol = 0;
    for (size_t c = 0; c < nk; c++) {
        size_t i0 = (size_t)mb * nk + c, i1 = i0 + nk;
        double wj = w ? w[c % (size_t)k] : 1;
        double b = 2 * fabs(D[i0] - D[i1]) + 3 * (R[i0] + R[i1]) + d_err;
        double e = fabs(D[i0] - wj * d[c]);
        double r = e / (b + 1e-300);
        if (r > ratio) {
            ratio = r, got = D[i0], ref = wj * d[c], tol = b;
            fd->worst = e, fd->bound = b;
        }
    }
    snprintf(name, sizeof name, "%s: analytic vs central difference at h = %.3g (bound: 2|D(h)-D(h/2)| + rounding)",
             what, fd->h_check);
    mm_res_check_abs(res, name, got, ref, tol);
    if (out >= 0) {
        mm_series *s = mm_res_series(res, out, nh);
        if (!s)
            return mm_error_set(err, MM_ENOMEM, "", "out of memory");
        double floor_ = 1e-17 * (big > 0 ? big : 1);
        for (int m = 0; m < nh; m++) {
            s->x[m] = fd->h[m];
            s->y[m] = fmax(fd->err[m], floor_);
        }
    }
    return MM_OK;
}

int mm_kin_fd_va(mm_result *res, int out_v, int out_a, const char *what_v, const char *what_a, mm_kin_pos_fn pos,
                 void *ctx, int k, const double *w, int n, const double *d1, const double *d2, double h0,
                 double d1_err, double d2_err, mm_error *err)
{
    if (n <= 0)
        return MM_OK;
    mm_kin_fd fd;
    int rc = mm_kin_fd_study(res, out_v, what_v, pos, ctx, k, w, n, d1, 1, h0, 24, d1_err, &fd, err);
    if (rc == MM_OK)
        rc = mm_kin_fd_study(res, out_a, what_a, pos, ctx, k, w, n, d2, 2, h0, 18, d2_err, &fd, err);
    return rc;
}

int mm_kin_check_t(double t, double t_end, mm_error *err)
{
    if (t > t_end)
        return mm_error_set(err, MM_ERANGE, "t", "t must lie within the motion, 0 to t_end = %g s; got %g s", t_end, t);
    return MM_OK;
}

/* ---- a plane curve typed as two expressions of t ------------------------------------ */

int mm_kin_curve_compile(mm_kin_curve *c, const char *x, const char *y, const char *px, const char *py,
                         mm_error *err)
{
    static const char *const vars[] = {"t"};
    c->x = c->y = NULL;
    c->px = px, c->py = py;
    int rc = mm_expr_compile(x, vars, 1, &c->x, err);
    if (rc != MM_OK) {
        if (err)
            snprintf(err->param, sizeof err->param, "%s", px);
        return rc;
    }
    rc = mm_expr_compile(y, vars, 1, &c->y, err);
    if (rc != MM_OK) {
        mm_kin_curve_free(c);
        if (err)
            snprintf(err->param, sizeof err->param, "%s", py);
    }
    return rc;
}

void mm_kin_curve_free(mm_kin_curve *c)
{
    mm_expr_free(c->x);
    mm_expr_free(c->y);
    c->x = c->y = NULL;
}

int mm_kin_curve_eval(double t, double *out, void *ctx)
{
    mm_kin_curve *c = ctx;
    out[0] = mm_expr_eval(c->x, &t);
    out[1] = mm_expr_eval(c->y, &t);
    return isfinite(out[0]) && isfinite(out[1]) ? MM_OK : MM_ENONFINITE;
}

int mm_kin_curve_at(mm_kin_curve *c, double t, double h0, double r[2], double d1[2], double e1[2], double d2[2],
                    double e2[2], mm_error *err)
{
    int rc = mm_kin_curve_eval(t, r, c);
    if (rc == MM_OK)
        rc = mm_geom_curve_derivs(mm_kin_curve_eval, c, 2, t, h0, d1, e1, d2, e2, NULL);
    if (rc != MM_OK) {
        double q[2];
        mm_kin_curve_eval(t, q, c);
        return mm_error_set(err, MM_ENONFINITE, isfinite(q[0]) ? c->py : c->px,
                            "the path is not finite at or near t = %g (%s(t) gives %g): choose an expression "
                            "defined there, or another time range", t, isfinite(q[0]) ? c->py : c->px,
                            isfinite(q[0]) ? q[1] : q[0]);
    }
    return MM_OK;
}

int mm_kin_curve_integrals(mm_kin_curve *c, double a, double b, int np, double h0, double iv[2], double ev[2],
                           double ia[2], double ea[2], mm_error *err)
{
    const double *x5 = mm_quad_gl5_node, *w5 = mm_quad_gl5_weight;
    for (int i = 0; i < 2; i++)
        iv[i] = ev[i] = ia[i] = ea[i] = 0;
    double hw = 0.5 * (b - a) / np;
    for (int p = 0; p < np; p++)
        for (int j = 0; j < 5; j++) {
            double r[2], d1[2], e1[2], d2[2], e2[2], t = a + hw * (2 * p + 1 + x5[j]);
            int rc = mm_kin_curve_at(c, t, h0, r, d1, e1, d2, e2, err);
            if (rc != MM_OK)
                return rc;
            for (int i = 0; i < 2; i++) {
                iv[i] += w5[j] * hw * d1[i], ev[i] += w5[j] * hw * e1[i];
                ia[i] += w5[j] * hw * d2[i], ea[i] += w5[j] * hw * e2[i];
            }
        }
    return MM_OK;
}

/* ---- small things ------------------------------------------------------------------------- */

double mm_kin_grid(double a, double b, int n, double *x)
{
    double step = (b - a) / (n - 1);
    double p = pow(10, floor(log10(fabs(step))) - 2);        /* 3 significant digits */
    double ia = a / p, is = round(step / p);
    if (n > 2 && fabs(ia - round(ia)) < 1e-9 && fabs(is * p - step) * (n - 2) <= 0.1 * fabs(step) && is != 0) {
        /* x_i = (a/p + i * s/p) * p: integers, then one division by 1/p, exact
         * powers of ten, so each value is the double nearest a short decimal */
        double ip = round(1 / p) > 0 && fabs(round(1 / p) - 1 / p) < 1e-9 ? round(1 / p) : 0;
        for (int i = 0; i < n - 1; i++) {
            double num = round(ia) + i * is;
            x[i] = ip > 0 ? num / ip : num * p;
        }
        x[n - 1] = b;
        return is * p;
    }
    mm_linspace(a, b, n, x);
    return step;
}

double mm_kin_wrap(double x)
{
    double r = remainder(x, 2 * M_PI);
    return r <= -M_PI ? r + 2 * M_PI : r;
}

double mm_kin_near(double x, double ref)
{
    return ref + remainder(x - ref, 2 * M_PI);
}

/* ---- mobility ---- */

/* the joints table from "name:kind:freedom,..." */
int mm_kin_joints_table(mm_result *res, int out, const char *spec, mm_error *err)
{
    int rows = 1;
    for (const char *c = spec; *c; c++)
        rows += *c == ',';
    mm_table *t = mm_res_table(res, out, rows);
    char *copy = mm_res_strdup(res, spec);
    if (!t || !copy)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    char *save = NULL;
    int r = 0;
    for (char *tok = strtok_r(copy, ",", &save); tok && r < rows; tok = strtok_r(NULL, ",", &save), r++) {
        char *k = strchr(tok, ':'), *f = k ? strchr(k + 1, ':') : NULL;
        if (!k || !f)
            return mm_error_set(err, MM_EINTERNAL, "", "bad joint list");
        *k = *f = '\0';
        t->text[3 * r] = tok, t->text[3 * r + 1] = k + 1;
        t->cell[3 * r + 2] = f[1] - '0';
    }
    return MM_OK;
}

/* the rank decision: zero singular values at rounding, the others clear */
void mm_kin_rank_checks(mm_result *res, const double *sv, int k, int rank, int m, int n)
{
    double zero = (m > n ? m : n) * DBL_EPSILON * sv[0];
    if (rank < k)
        mm_res_check_abs(res, "largest singular value counted as zero: at rounding (max(m,n) eps sigma_1 x 64)",
                         sv[rank], 0, 64 * zero);
    if (rank > 0)
        mm_res_check_abs(res, "smallest singular value counted as non-zero: well clear of rounding (>= 1e-6 sigma_1)",
                         fmin(sv[rank - 1], 1e-6 * sv[0]), 1e-6 * sv[0], 0);
}

int mm_kin_curve_solve(const mm_value *in, int px, int py,
                       int (*run)(mm_kin_curve *c, const mm_value *in, mm_result *res, mm_error *err),
                       mm_result *res, mm_error *err)
{
    mm_kin_curve c;
    int rc = mm_kin_curve_compile(&c, in[px].text, in[py].text, "x", "y", err);
    if (rc != MM_OK)
        return rc;
    rc = run(&c, in, res, err);
    mm_kin_curve_free(&c);
    return rc;
}

int mm_kin_curve_work(const char *x, const char *y, double points, double extra, mm_error *err)
{
    const double max_work = 8e5;
    double len = fmax((double)(strlen(x) + strlen(y)), 32);
    if ((points + extra) * len > max_work)
        return mm_error_set(err, MM_ERANGE, "points",
                            "points must be at most %.0f with these expressions of %.0f characters (each point "
                            "costs 21 evaluations of x and y, and a long expression costs more to evaluate); got %.0f",
                            floor(max_work / len - extra), len, points);
    return MM_OK;
}

int mm_kin_check_window(double t0, double t1, double t, mm_error *err)
{
    if (!(t1 > t0))
        return mm_error_set(err, MM_ERANGE, "t1", "t1 must be later than t0 = %g s; got %g s", t0, t1);
    if (t < t0 || t > t1)
        return mm_error_set(err, MM_ERANGE, "t", "t must lie within the motion shown, %g to %g s; got %g s", t0, t1, t);
    return MM_OK;
}

/* ---- the idioms the chapter's files share ----------------------------------------------- */

int mm_kin_samples_init(mm_kin_samples *s, mm_result *res, int n, int k, mm_error *err)
{
    s->n = n, s->ns = (n + 7) / 8, s->k = k;
    s->t = mm_res_alloc(res, (size_t)s->ns * sizeof *s->t);
    s->d1 = mm_res_alloc(res, (size_t)k * (size_t)s->ns * sizeof *s->d1);
    s->d2 = mm_res_alloc(res, (size_t)k * (size_t)s->ns * sizeof *s->d2);
    if (!s->t || !s->d1 || !s->d2)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    return MM_OK;
}

int mm_kin_sampled(const mm_kin_samples *s, int i)
{
    return i % 8 == 0 || i == s->n - 1;
}

int mm_kin_sample(mm_kin_samples *s, int i, double t, const double *d1, const double *d2)
{
    if (!mm_kin_sampled(s, i))
        return 0;
    int j = i % 8 == 0 ? i / 8 : s->ns - 1;
    s->t[j] = t;
    for (int c = 0; c < s->k; c++) {
        s->d1[s->k * j + c] = d1[c];
        if (d2)
            s->d2[s->k * j + c] = d2[c];
    }
    return 1;
}

int mm_kin_sample2(mm_kin_samples *s, int i, double t, mm_v2 v, mm_v2 a)
{
    const double d1[2] = {v.x, v.y}, d2[2] = {a.x, a.y};
    return mm_kin_sample(s, i, t, d1, d2);
}

int mm_kin_sample3(mm_kin_samples *s, int i, double t, mm_v3 v, mm_v3 a)
{
    const double d1[3] = {v.x, v.y, v.z}, d2[3] = {a.x, a.y, a.z};
    return mm_kin_sample(s, i, t, d1, d2);
}

typedef struct at_ctx {
    mm_kin_at_fn at;
    void *ctx;
    const double *t;
} at_ctx;

static int at_pos(int i, double h, double *q, double *qerr, void *ctx, mm_error *err)
{
    at_ctx *c = ctx;
    return c->at(c->t[i], h, q, qerr, c->ctx, err);
}

int mm_kin_fd_samples(mm_result *res, int out_v, int out_a, const char *what_v, const char *what_a, mm_kin_at_fn at,
                      void *ctx, const mm_kin_samples *s, double h0, mm_error *err)
{
    at_ctx c = {at, ctx, s->t};
    return mm_kin_fd_va(res, out_v, out_a, what_v, what_a, at_pos, &c, s->k, NULL, s->ns, s->d1, s->d2, h0, 0, 0, err);
}

mm_shape *mm_kin_path(mm_kin_draw *d, const char *name, const mm_series *s)
{
    mm_shape *p = mm_kin_shape(d, name, MM_SHAPE_PATH, 0, s->n);
    for (int i = 0; p && i < s->n; i++)
        mm_kin_pt(p, 0, i, s->x[i], s->y[i]);
    return p;
}

mm_shape *mm_kin_circle(mm_kin_draw *d, const char *name, int moving, double r)
{
    mm_shape *c = mm_kin_shape(d, name, MM_SHAPE_CIRCLE, moving, 1);
    if (c)
        c->radius = r;
    return c;
}

double mm_kin_frame_t(mm_kin_draw *d, int f, double t0, double t1)
{
    double t = t0 + (t1 - t0) * f / (d->nf - 1);
    d->anim->t[f] = t;
    return t;
}

void mm_kin_iso(mm_v3 p, double *x, double *y)
{
    *x = (p.y - p.x) * M_SQRT1_2;
    *y = (2 * p.z - p.x - p.y) / sqrt(6.0);
}

int mm_kin_circle3(int (*p)(double t, double e, mm_v2 *P, void *ctx), void *ctx, double t, double h, double R[3])
{
    for (int k = 0; k < 3; k++) {
        mm_v2 P[3], c;
        for (int j = 0; j < 3; j++)
            if (!p(t, (j - 1) * h / (1 << k), &P[j], ctx))
                return 0;
        if (!mm_geom_circumcircle(P[0], P[1], P[2], &c, &R[k]))
            return 0;
    }
    return 1;
}

/* ---- the chapter's drawings ------------------------------------------------------------- */

int mm_kin_anim_turntable(mm_result *res, int nf, double t_show, double size, double h, const mm_series *path,
                          double vmax, double amax, void (*frame)(double t, mm_kin_slot_state *k, void *ctx),
                          void *ctx, mm_error *err)
{
    mm_kin_draw d;
    mm_anim *an = mm_kin_draw_start(&d, res, nf, "t", "s", 2 * size);
    mm_shape *disc = an ? mm_kin_shape(&d, "table", MM_SHAPE_POLYGON, 1, 24) : NULL;
    mm_shape *sl = mm_kin_shape(&d, "slot", MM_SHAPE_LINE, 1, 2);
    mm_shape *blk = mm_kin_shape(&d, "slider", MM_SHAPE_POLYGON, 1, 4);
    mm_shape *piv = mm_kin_pivot(&d, "O", 0, 0);
    mm_shape *tr = mm_kin_path(&d, "absolute path", path);
    mm_shape *vv = mm_kin_arrow_shape(&d, "v", "m/s", vmax), *vr = mm_kin_arrow_shape(&d, "v_rel", "m/s", vmax);
    mm_shape *ac = mm_kin_arrow_shape(&d, "a_coriolis", "m/s^2", amax);
    mm_shape *aa = mm_kin_arrow_shape(&d, "a", "m/s^2", amax);
    if (!disc || !sl || !blk || !piv || !tr || !vv || !vr || !ac || !aa)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    vr->scale = vv->scale;                                 /* velocities on one scale, accelerations on another */
    ac->scale = aa->scale;
    for (int f = 0; f < nf; f++) {
        mm_kin_slot_state k;
        frame(mm_kin_frame_t(&d, f, 0, t_show), &k, ctx);
        for (int j = 0; j < 24; j++) {
            mm_v2 q = mm_v2_polar(size * (j == 0 ? 0.92 : 1), k.th + 2 * M_PI * j / 24);   /* a notch shows the turn */
            mm_kin_pt(disc, f, j, q.x, q.y);
        }
        mm_v2 a0 = mm_v2_rotate((mm_v2){-size, h}, k.th), a1 = mm_v2_rotate((mm_v2){size, h}, k.th);
        mm_kin_pt(sl, f, 0, a0.x, a0.y);
        mm_kin_pt(sl, f, 1, a1.x, a1.y);
        mm_kin_block(blk, f, k.r.x, k.r.y, 0.08 * size, 0.05 * size, k.th);
        mm_kin_arrow(vv, f, k.r.x, k.r.y, k.v.x, k.v.y);
        mm_kin_arrow(vr, f, k.r.x, k.r.y, k.vrel.x, k.vrel.y);
        mm_kin_arrow(ac, f, k.r.x, k.r.y, k.acor.x, k.acor.y);
        mm_kin_arrow(aa, f, k.r.x, k.r.y, k.a.x, k.a.y);
    }
    return mm_kin_draw_finish(&d);
}

int mm_kin_anim_axis(mm_result *res, int nf, double t_show, mm_v3 u, mm_v3 r0, double R, double drift, double vmax,
                     double amax, void (*frame)(double t, mm_kin_axis_state *k, void *ctx), void *ctx, mm_error *err)
{
    /* e1, e2 across the axis */
    mm_v3 e1 = fabs(u.x) < 0.9 ? (mm_v3){1, 0, 0} : (mm_v3){0, 1, 0};
    e1 = mm_v3_sub(e1, mm_v3_scale(u, mm_v3_dot(e1, u)));
    e1 = mm_v3_scale(e1, 1 / mm_v3_norm(e1));
    mm_v3 e2 = mm_v3_cross(u, e1);
    mm_kin_draw d;
    mm_anim *an = mm_kin_draw_start(&d, res, nf, "t", "s", 2.6 * R + drift);
    mm_shape *plate = an ? mm_kin_shape(&d, "body", MM_SHAPE_POLYGON, 1, 6) : NULL;
    mm_shape *ax = mm_kin_circle(&d, "axis", 1, 0.04 * R);
    mm_shape *arm = mm_kin_shape(&d, "radius to P", MM_SHAPE_LINE, 1, 2);
    mm_shape *tr = mm_kin_shape(&d, "path of P", MM_SHAPE_PATH, 0, 121);
    mm_shape *vv = mm_kin_arrow_shape(&d, "v_P", "m/s", vmax), *aa = mm_kin_arrow_shape(&d, "a_P", "m/s^2", amax);
    if (!plate || !ax || !arm || !tr || !vv || !aa)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_kin_axis_state k;
    for (int j = 0; j <= 120; j++) {
        frame(t_show * j / 120, &k, ctx);
        mm_kin_pt(tr, 0, j, mm_v3_dot(k.P, e1), mm_v3_dot(k.P, e2));
    }
    double ang0 = atan2(mm_v3_dot(r0, e2), mm_v3_dot(r0, e1));
    for (int f = 0; f < nf; f++) {
        frame(mm_kin_frame_t(&d, f, 0, t_show), &k, ctx);
        double ox = mm_v3_dot(k.O, e1), oy = mm_v3_dot(k.O, e2), a = ang0 + k.th;
        for (int j = 0; j < 6; j++)                      /* a hexagonal plate turning with the body */
            mm_kin_pt(plate, f, j, ox + 1.3 * R * cos(a + M_PI * j / 3), oy + 1.3 * R * sin(a + M_PI * j / 3));
        mm_kin_pt(ax, f, 0, ox, oy);
        double px = mm_v3_dot(k.P, e1), py = mm_v3_dot(k.P, e2);
        mm_kin_pt(arm, f, 0, ox, oy);
        mm_kin_pt(arm, f, 1, px, py);
        mm_kin_arrow(vv, f, px, py, mm_v3_dot(k.v, e1), mm_v3_dot(k.v, e2));
        mm_kin_arrow(aa, f, px, py, mm_v3_dot(k.a, e1), mm_v3_dot(k.a, e2));
    }
    return mm_kin_draw_finish(&d);
}

int mm_kin_anim_ladder(mm_result *res, int nf, const mm_kin_ladder_state *k, double L, const mm_series *path,
                       double vmax, mm_error *err)
{
    enum { NV = 5, NC = 17 };
    mm_kin_draw d;
    mm_anim *an = mm_kin_draw_start(&d, res, nf, "t", "s", 1.3 * L);
    mm_shape *fl = an ? mm_kin_shape(&d, "floor", MM_SHAPE_LINE, 0, 2) : NULL;
    mm_shape *wl = mm_kin_shape(&d, "wall", MM_SHAPE_LINE, 0, 2);
    mm_shape *lad = mm_kin_shape(&d, "ladder", MM_SHAPE_LINE, 1, 2);
    mm_shape *sc = mm_kin_shape(&d, "space centrode", MM_SHAPE_PATH, 0, 25);
    mm_shape *bc = mm_kin_shape(&d, "body centrode", MM_SHAPE_LINE, 1, NC);
    mm_shape *ic = mm_kin_circle(&d, "instantaneous centre", 1, 0.02 * L);
    mm_shape *pp = mm_kin_path(&d, "path of P", path);
    mm_shape *va[NV];
    for (int j = 0; j < NV; j++)
        va[j] = mm_kin_arrow_shape(&d, j == 0 ? "v_A" : j == NV - 1 ? "v_B" : "v", "m/s", vmax);
    if (!fl || !wl || !lad || !sc || !bc || !ic || !pp || !va[NV - 1])
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    fl->style = wl->style = "ground";
    mm_kin_pt(fl, 0, 0, 0, 0), mm_kin_pt(fl, 0, 1, 1.1 * L, 0);
    mm_kin_pt(wl, 0, 0, 0, 0), mm_kin_pt(wl, 0, 1, 0, 1.1 * L);
    ic->style = "highlight";
    for (int j = 0; j < 25; j++)
        mm_kin_pt(sc, 0, j, L * cos(M_PI / 2 * j / 24), L * sin(M_PI / 2 * j / 24));
    for (int f = 0; f < nf; f++) {
        const mm_kin_ladder_state *kf = k + f;
        an->t[f] = kf->t;
        mm_kin_pt(lad, f, 0, kf->A.x, kf->A.y), mm_kin_pt(lad, f, 1, kf->B.x, kf->B.y);
        mm_kin_pt(ic, f, 0, kf->I.x, kf->I.y);
        mm_v2 mid = mm_v2_scale(mm_v2_add(kf->A, kf->B), 0.5);
        for (int j = 0; j < NC; j++) {                           /* the circle on AB as diameter */
            mm_v2 q = mm_v2_add(mid, mm_v2_polar(0.5 * L, 2 * M_PI * j / (NC - 1)));
            mm_kin_pt(bc, f, j, q.x, q.y);
        }
        for (int j = 0; j < NV; j++) {                           /* the velocity field along AB */
            mm_v2 Pj = mm_v2_add(kf->A, mm_v2_scale(mm_v2_sub(kf->B, kf->A), (double)j / (NV - 1)));
            mm_v2 vj = mm_v2_scale(mm_v2_perp(mm_v2_sub(Pj, kf->I)), kf->w);
            mm_kin_arrow(va[j], f, Pj.x, Pj.y, vj.x, vj.y);
        }
    }
    return mm_kin_draw_finish(&d);
}

int mm_kin_anim_particle(mm_result *res, int nf, const double *t, double (*P)[2], double (*V)[2], double (*A)[2],
                         const mm_series *path, double size, mm_error *err)
{
    double vmax = 0, amax = 0;
    for (int f = 0; f < nf; f++)
        vmax = fmax(vmax, hypot(V[f][0], V[f][1])), amax = fmax(amax, hypot(A[f][0], A[f][1]));
    mm_kin_draw d;
    mm_anim *an = mm_kin_draw_start(&d, res, nf, "t", "s", size);
    mm_shape *tr = an ? mm_kin_path(&d, "path", path) : NULL;
    mm_shape *pt = mm_kin_circle(&d, "particle", 1, 0.015 * d.size);
    mm_shape *va = mm_kin_arrow_shape(&d, "v", "m/s", vmax), *aa = mm_kin_arrow_shape(&d, "a", "m/s^2", amax);
    if (!tr || !pt || !va || !aa)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (int f = 0; f < nf; f++) {
        an->t[f] = t[f];
        mm_kin_pt(pt, f, 0, P[f][0], P[f][1]);
        mm_kin_arrow(va, f, P[f][0], P[f][1], V[f][0], V[f][1]);
        mm_kin_arrow(aa, f, P[f][0], P[f][1], A[f][0], A[f][1]);
    }
    return mm_kin_draw_finish(&d);
}

int mm_kin_anim_arm(mm_result *res, int nf, double t_show, const mm_series *path, double vmax, double amax,
                    void (*frame)(double t, mm_kin_arm_state *k, void *ctx), void *ctx, mm_error *err)
{
    double size = 0;
    for (int i = 0; i < path->n; i++)
        size = fmax(size, hypot(path->x[i], path->y[i]));
    mm_kin_draw d;
    mm_anim *an = mm_kin_draw_start(&d, res, nf, "t", "s", 2 * size + 1e-3);
    mm_shape *piv = an ? mm_kin_pivot(&d, "O", 0, 0) : NULL;
    mm_shape *arm = mm_kin_shape(&d, "arm", MM_SHAPE_LINE, 1, 2);
    mm_shape *pt = mm_kin_circle(&d, "point", 1, 0.02 * d.size);
    mm_shape *tr = mm_kin_path(&d, "path", path);
    mm_shape *va = mm_kin_arrow_shape(&d, "v", "m/s", vmax), *aa = mm_kin_arrow_shape(&d, "a", "m/s^2", amax);
    if (!piv || !arm || !pt || !tr || !va || !aa)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (int f = 0; f < nf; f++) {
        mm_kin_arm_state k;
        frame(mm_kin_frame_t(&d, f, 0, t_show), &k, ctx);
        mm_v2 tip = mm_v2_polar(fmax(size, 1e-3) * 1.1, k.th);          /* the arm runs past the point */
        mm_kin_pt(arm, f, 0, 0, 0);
        mm_kin_pt(arm, f, 1, tip.x, tip.y);
        mm_kin_pt(pt, f, 0, k.x.x, k.x.y);
        mm_kin_arrow(va, f, k.x.x, k.x.y, k.v.x, k.v.y);
        mm_kin_arrow(aa, f, k.x.x, k.x.y, k.a.x, k.a.y);
    }
    return mm_kin_draw_finish(&d);
}

int mm_kin_anim_osculating(mm_result *res, int nf, const mm_kin_osc_state *k, const mm_series *path, double size,
                           double amax, mm_error *err)
{
    enum { NC = 13 };
    mm_kin_draw d;
    mm_anim *an = mm_kin_draw_start(&d, res, nf, "t", "s", size);
    mm_shape *tr = an ? mm_kin_path(&d, "path", path) : NULL;
    mm_shape *pt = mm_kin_circle(&d, "particle", 1, 0.015 * d.size);
    mm_shape *oc = mm_kin_shape(&d, "osculating circle", MM_SHAPE_LINE, 1, NC);
    mm_shape *at = mm_kin_arrow_shape(&d, "a_t", "m/s^2", amax), *ann = mm_kin_arrow_shape(&d, "a_n", "m/s^2", amax);
    if (!tr || !pt || !oc || !at || !ann)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (int f = 0; f < nf; f++) {
        const mm_kin_osc_state *g = k + f;
        an->t[f] = g->t;
        mm_kin_pt(pt, f, 0, g->P.x, g->P.y);
        mm_kin_arrow(at, f, g->P.x, g->P.y, g->at.x, g->at.y);
        mm_kin_arrow(ann, f, g->P.x, g->P.y, g->an.x, g->an.y);
        /* the osculating circle, its radius capped at 3 sizes of the path */
        double R = g->k != 0 ? fmin(g->rho, 3 * d.size) : 3 * d.size, s = g->k >= 0 ? 1 : -1;
        mm_v2 C = mm_v2_add(g->P, mm_v2_scale(g->N, s * R));
        for (int j = 0; j < NC; j++) {
            mm_v2 q = mm_v2_add(C, mm_v2_scale(mm_v2_rotate(g->N, 2 * M_PI * j / (NC - 1)), -s * R));
            mm_kin_pt(oc, f, j, q.x, q.y);
        }
    }
    return mm_kin_draw_finish(&d);
}

int mm_kin_anim_wheel(mm_result *res, int nf, double t_show, double R, double b, double vmax, double amax,
                      void (*frame)(double t, mm_kin_wheel_state *k, void *ctx), void *ctx, mm_error *err)
{
    mm_kin_wheel_state k;
    double x0 = INFINITY, x1 = -INFINITY;
    for (int f = 0; f < nf; f++) {
        frame(t_show * f / (nf - 1), &k, ctx);
        x0 = fmin(x0, k.O.x - fmax(R, b)), x1 = fmax(x1, k.O.x + fmax(R, b));
    }
    mm_kin_draw d;
    mm_anim *an = mm_kin_draw_start(&d, res, nf, "t", "s", fmax(x1 - x0, 2 * (R + b)));
    mm_shape *gr = an ? mm_kin_shape(&d, "ground", MM_SHAPE_LINE, 0, 2) : NULL;
    mm_shape *wh = mm_kin_circle(&d, "wheel", 1, R);
    mm_shape *sp1 = mm_kin_shape(&d, "spoke", MM_SHAPE_LINE, 1, 2);
    mm_shape *sp2 = mm_kin_shape(&d, "spoke 2", MM_SHAPE_LINE, 1, 2);
    mm_shape *arm = mm_kin_shape(&d, "centre to P", MM_SHAPE_LINE, 1, 2);
    mm_shape *ic = mm_kin_circle(&d, "contact point (instantaneous centre)", 1, 0.04 * R);
    mm_shape *tr = mm_kin_shape(&d, "path of P", MM_SHAPE_PATH, 0, 121);
    mm_shape *vv = mm_kin_arrow_shape(&d, "v_P", "m/s", vmax), *vt = mm_kin_arrow_shape(&d, "v_top", "m/s", vmax);
    mm_shape *vo = mm_kin_arrow_shape(&d, "v_O", "m/s", vmax), *aa = mm_kin_arrow_shape(&d, "a_P", "m/s^2", amax);
    if (!gr || !wh || !sp1 || !sp2 || !arm || !ic || !tr || !vv || !vt || !vo || !aa)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    vt->scale = vo->scale = vv->scale;
    gr->style = "ground";
    mm_kin_pt(gr, 0, 0, x0, 0), mm_kin_pt(gr, 0, 1, x1, 0);
    ic->style = "highlight";
    for (int j = 0; j <= 120; j++) {
        frame(t_show * j / 120, &k, ctx);
        mm_kin_pt(tr, 0, j, k.P.x, k.P.y);
    }
    for (int f = 0; f < nf; f++) {
        frame(mm_kin_frame_t(&d, f, 0, t_show), &k, ctx);
        mm_kin_pt(wh, f, 0, k.O.x, k.O.y);
        mm_v2 e = mm_v2_polar(R, -k.phi);                          /* the wheel turns clockwise */
        mm_kin_pt(sp1, f, 0, k.O.x - e.x, k.O.y - e.y), mm_kin_pt(sp1, f, 1, k.O.x + e.x, k.O.y + e.y);
        mm_kin_pt(sp2, f, 0, k.O.x + e.y, k.O.y - e.x), mm_kin_pt(sp2, f, 1, k.O.x - e.y, k.O.y + e.x);
        mm_kin_pt(arm, f, 0, k.O.x, k.O.y), mm_kin_pt(arm, f, 1, k.P.x, k.P.y);
        mm_kin_pt(ic, f, 0, k.O.x, 0);
        mm_kin_arrow(vv, f, k.P.x, k.P.y, k.v.x, k.v.y);
        mm_kin_arrow(aa, f, k.P.x, k.P.y, k.a.x, k.a.y);
        mm_kin_arrow(vo, f, k.O.x, k.O.y, k.w * R, 0);
        mm_kin_arrow(vt, f, k.O.x, 2 * R, 2 * k.w * R, 0);
    }
    return mm_kin_draw_finish(&d);
}

int mm_kin_anim_box(mm_result *res, int nf, double t_show, double wmax, mm_v3 p,
                    void (*frame)(double t, double R[9], mm_v3 *w, void *ctx), void *ctx, mm_error *err)
{
    static const double hx = 0.3, hy = 0.2, hz = 0.1;
    mm_kin_draw d;
    mm_anim *an = mm_kin_draw_start(&d, res, nf, "t", "s", 1.6);
    mm_shape *bot = an ? mm_kin_shape(&d, "box bottom", MM_SHAPE_POLYGON, 1, 4) : NULL;
    mm_shape *top = mm_kin_shape(&d, "box top", MM_SHAPE_POLYGON, 1, 4);
    mm_shape *edge[4], *ba[3], *sx[3];
    static const char *const en[4] = {"edge 1", "edge 2", "edge 3", "edge 4"};
    static const char *const bn[3] = {"body x", "body y", "body z"}, *const sn[3] = {"space x", "space y", "space z"};
    for (int k = 0; k < 4; k++)
        edge[k] = mm_kin_shape(&d, en[k], MM_SHAPE_LINE, 1, 2);
    for (int k = 0; k < 3; k++) {
        ba[k] = mm_kin_shape(&d, bn[k], MM_SHAPE_ARROW, 1, 2);
        sx[k] = mm_kin_shape(&d, sn[k], MM_SHAPE_LINE, 0, 2);
    }
    mm_shape *wa = mm_kin_arrow_shape(&d, "omega", "rad/s", wmax);
    mm_shape *pth = mm_kin_shape(&d, "path of the point", MM_SHAPE_PATH, 0, 121);
    if (!bot || !top || !edge[3] || !ba[2] || !sx[2] || !wa || !pth)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (int k = 0; k < 3; k++) {
        mm_v3 e = {k == 0, k == 1, k == 2};
        double x, y;
        mm_kin_iso(mm_v3_scale(e, 0.7), &x, &y);
        sx[k]->style = "ground";
        mm_kin_pt(sx[k], 0, 0, 0, 0), mm_kin_pt(sx[k], 0, 1, x, y);
        ba[k]->unit = "m", ba[k]->scale = 1;
    }
    double R[9], x, y;
    mm_v3 w;
    for (int k = 0; k <= 120; k++) {
        frame(t_show * k / 120, R, &w, ctx);
        mm_kin_iso(mm_geom_m3_apply(R, p), &x, &y);
        mm_kin_pt(pth, 0, k, x, y);
    }
    for (int f = 0; f < nf; f++) {
        frame(mm_kin_frame_t(&d, f, 0, t_show), R, &w, ctx);
        double X[8], Y[8];
        for (int c = 0; c < 8; c++) {                        /* corners: bottom 0-3, top 4-7 */
            int q = c & 3;
            mm_v3 corner = {(q == 1 || q == 2) ? hx : -hx, q >= 2 ? hy : -hy, c >= 4 ? hz : -hz};
            mm_kin_iso(mm_geom_m3_apply(R, corner), &X[c], &Y[c]);
        }
        for (int c = 0; c < 4; c++) {
            mm_kin_pt(bot, f, c, X[c], Y[c]);
            mm_kin_pt(top, f, c, X[c + 4], Y[c + 4]);
            mm_kin_pt(edge[c], f, 0, X[c], Y[c]), mm_kin_pt(edge[c], f, 1, X[c + 4], Y[c + 4]);
        }
        for (int k = 0; k < 3; k++) {
            mm_kin_iso(mm_v3_make(0.5 * R[k], 0.5 * R[3 + k], 0.5 * R[6 + k]), &x, &y);   /* column k of R */
            mm_kin_arrow(ba[k], f, 0, 0, x, y);
        }
        mm_kin_iso(w, &x, &y);
        mm_kin_arrow(wa, f, 0, 0, x, y);
    }
    return mm_kin_draw_finish(&d);
}

int mm_kin_anim_cam(mm_result *res, const mm_cam *m, double omega, double vmax, double size, mm_error *err)
{
    enum { NF = 36, NP = 48 };
    mm_kin_draw dr;
    mm_anim *an = mm_kin_draw_start(&dr, res, NF, "cam angle", "rad", 2 * size + 2 * m->Rr);
    mm_shape *cm = an ? mm_kin_shape(&dr, "cam", MM_SHAPE_POLYGON, 1, NP) : NULL;
    mm_shape *pv = mm_kin_pivot(&dr, "cam centre", 0, 0);
    mm_shape *rl = mm_kin_circle(&dr, "roller", 1, m->Rr > 0 ? m->Rr : 0.01 * size);
    mm_shape *st = mm_kin_shape(&dr, "follower", MM_SHAPE_LINE, 1, 2);
    mm_shape *gd = mm_kin_shape(&dr, "guide", MM_SHAPE_LINE, 0, 2);
    mm_shape *va = mm_kin_arrow_shape(&dr, "v", "m/s", vmax);
    if (!cm || !pv || !rl || !st || !gd || !va)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_v2 K[NP];
    for (int j = 0; j < NP; j++) {
        mm_v2 P;
        mm_cam_points(m, 2 * M_PI * j / NP, &P, &K[j]);
    }
    gd->style = "ground";
    mm_kin_pt(gd, 0, 0, m->e, m->s0 + m->h + 0.4 * size), mm_kin_pt(gd, 0, 1, m->e, m->s0 + m->h + 0.9 * size);
    for (int f = 0; f < NF; f++) {
        double thf = 2 * M_PI * f / NF, df[4];
        int sf;
        an->t[f] = thf;
        mm_cam_motion(m, thf, df, &sf);
        for (int j = 0; j < NP; j++) {
            mm_v2 q = mm_v2_rotate(K[j], thf);            /* the cam frame turned by thf */
            mm_kin_pt(cm, f, j, q.x, q.y);
        }
        double yc = m->s0 + df[0];
        mm_kin_pt(rl, f, 0, m->e, yc);
        mm_kin_pt(st, f, 0, m->e, yc), mm_kin_pt(st, f, 1, m->e, m->s0 + m->h + 0.9 * size);
        mm_kin_arrow(va, f, m->e + 1.5 * rl->radius, yc, 0, omega * df[1]);
    }
    return mm_kin_draw_finish(&dr);
}
