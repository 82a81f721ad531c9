/* mm_sta.c — the statics kit for chapter 3: drawings, standard figures, answer and check idioms (see mm_sta.h). */
#include "mm_sta.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* ---- drawing: the free-body diagram and its parts ----------------------------------- */

int mm_sta_fbd(mm_result *res)
{
    mm_anim *a = mm_res_animation(res, 1, "t", "s");
    if (!a)
        return MM_ENOMEM;
    a->t[0] = 0;
    return MM_OK;
}

double mm_sta_scale(double fmax, double size, double frac)
{
    return fmax > 0 && size > 0 ? frac * size / fmax : 0;
}

static mm_shape *shape(mm_result *res, const char *name, mm_shape_kind kind, int npts)
{
    return mm_anim_shape(res, name, kind, 1, npts);
}

int mm_sta_force(mm_result *res, const char *name, double px, double py, double Fx, double Fy,
                 double scale, int head)
{
    mm_shape *s = shape(res, name, MM_SHAPE_ARROW, 2);
    double *v = s ? mm_shape_values(res, s) : NULL;
    if (!v)
        return MM_ENOMEM;
    s->unit = "N";
    s->scale = scale;
    v[0] = hypot(Fx, Fy);
    double dx = scale * Fx, dy = scale * Fy;
    s->x[0] = head ? px - dx : px, s->y[0] = head ? py - dy : py;
    s->x[1] = head ? px : px + dx, s->y[1] = head ? py : py + dy;
    return MM_OK;
}

int mm_sta_line(mm_result *res, const char *name, double x0, double y0, double x1, double y1,
                const char *style, int has_value, double value)
{
    mm_shape *s = shape(res, name, MM_SHAPE_LINE, 2);
    if (!s)
        return MM_ENOMEM;
    s->x[0] = x0, s->y[0] = y0, s->x[1] = x1, s->y[1] = y1;
    s->style = style;
    if (has_value) {
        double *v = mm_shape_values(res, s);
        if (!v)
            return MM_ENOMEM;
        v[0] = value;
    }
    return MM_OK;
}

int mm_sta_member(mm_result *res, const char *name, double x0, double y0, double x1, double y1, double F,
                  double tol)
{
    const char *style = F > tol ? "tension" : F < -tol ? "compression" : NULL;
    return mm_sta_line(res, name, x0, y0, x1, y1, style, 1, F);
}

int mm_sta_polygon(mm_result *res, const char *name, int n, const double *xy, const char *style)
{
    mm_shape *s = shape(res, name, MM_SHAPE_POLYGON, n);
    if (!s)
        return MM_ENOMEM;
    for (int k = 0; k < n; k++)
        s->x[k] = xy[2 * k], s->y[k] = xy[2 * k + 1];
    s->style = style;
    return MM_OK;
}

int mm_sta_path(mm_result *res, const char *name, int n, const double *xy, const char *style)
{
    mm_shape *s = shape(res, name, MM_SHAPE_LINE, n);
    if (!s)
        return MM_ENOMEM;
    for (int k = 0; k < n; k++)
        s->x[k] = xy[2 * k], s->y[k] = xy[2 * k + 1];
    s->style = style;
    return MM_OK;
}

int mm_sta_circle(mm_result *res, const char *name, double x, double y, double r, const char *style)
{
    mm_shape *s = shape(res, name, MM_SHAPE_CIRCLE, 1);
    if (!s)
        return MM_ENOMEM;
    s->x[0] = x, s->y[0] = y;
    s->radius = r;
    s->style = style;
    return MM_OK;
}

static int vlabel(mm_result *res, double x, double y, const char *fmt, va_list ap)
{
    char buf[160];
    vsnprintf(buf, sizeof buf, fmt, ap);
    mm_shape *s = shape(res, "label", MM_SHAPE_LABEL, 1);
    char *text = mm_res_strdup(res, buf);
    if (!s || !text)
        return MM_ENOMEM;
    s->x[0] = x, s->y[0] = y;
    s->text = text;
    return MM_OK;
}

int mm_sta_label(mm_result *res, double x, double y, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int rc = vlabel(res, x, y, fmt, ap);
    va_end(ap);
    return rc;
}

int mm_sta_arrow(mm_result *res, const char *name, double x0, double y0, double x1, double y1, const char *unit,
                 double scale, double value)
{
    mm_shape *s = shape(res, name, MM_SHAPE_ARROW, 2);
    double *v = s ? mm_shape_values(res, s) : NULL;
    if (!v)
        return MM_ENOMEM;
    s->x[0] = x0, s->y[0] = y0, s->x[1] = x1, s->y[1] = y1;
    s->unit = unit, s->scale = scale, v[0] = value;
    return MM_OK;
}

/* (u, v) in the support's frame (v up from the ground) to the drawing */
static void turn(double x, double y, double angle, double u, double v, double *px, double *py)
{
    double c = cos(angle), s = sin(angle);
    *px = x + c * u - s * v;
    *py = y + s * u + c * v;
}

static int ground(mm_result *res, const char *name, double x, double y, double size, double angle, double depth)
{
    double xy[4];
    turn(x, y, angle, -0.8 * size, -depth, &xy[0], &xy[1]);
    turn(x, y, angle, 0.8 * size, -depth, &xy[2], &xy[3]);
    return mm_sta_path(res, name, 2, xy, "ground");
}

int mm_sta_pin(mm_result *res, const char *name, double x, double y, double size, double angle)
{
    double tri[6];
    turn(x, y, angle, 0, 0, &tri[0], &tri[1]);
    turn(x, y, angle, -0.5 * size, -0.8 * size, &tri[2], &tri[3]);
    turn(x, y, angle, 0.5 * size, -0.8 * size, &tri[4], &tri[5]);
    int rc = mm_sta_polygon(res, name, 3, tri, "ground");
    return rc ? rc : ground(res, "ground", x, y, size, angle, 0.8 * size);
}

int mm_sta_roller(mm_result *res, const char *name, double x, double y, double size, double angle)
{
    double tri[6], c[2];
    turn(x, y, angle, 0, 0, &tri[0], &tri[1]);
    turn(x, y, angle, -0.5 * size, -0.6 * size, &tri[2], &tri[3]);
    turn(x, y, angle, 0.5 * size, -0.6 * size, &tri[4], &tri[5]);
    int rc = mm_sta_polygon(res, name, 3, tri, "ground");
    for (int k = -1; k <= 1 && !rc; k += 2) {
        turn(x, y, angle, 0.25 * k * size, -0.7 * size, &c[0], &c[1]);
        rc = mm_sta_circle(res, "wheel", c[0], c[1], 0.1 * size, "ground");
    }
    return rc ? rc : ground(res, "ground", x, y, size, angle, 0.8 * size);
}

int mm_sta_clamp(mm_result *res, const char *name, double x, double y, double size)
{
    int rc = mm_sta_line(res, name, x, y - size, x, y + size, "ground", 0, 0);
    for (int k = 0; k < 5 && !rc; k++) {
        double yk = y - size + 0.5 * size * k;
        rc = mm_sta_line(res, "hatch", x, yk, x - 0.35 * size, yk + 0.35 * size, "ground", 0, 0);
    }
    return rc;
}

int mm_sta_couple(mm_result *res, const char *name, double x, double y, double r, double C)
{
    enum { N = 19 };
    double xy[2 * N], dir = C >= 0 ? 1 : -1;
    for (int k = 0; k < N; k++) {
        double t = -0.75 * M_PI + dir * 1.5 * M_PI * k / (N - 1);
        xy[2 * k] = x + r * cos(t), xy[2 * k + 1] = y + r * sin(t);
    }
    mm_shape *s = shape(res, name, MM_SHAPE_LINE, N);
    double *v = s ? mm_shape_values(res, s) : NULL;
    if (!v)
        return MM_ENOMEM;
    for (int k = 0; k < N; k++)
        s->x[k] = xy[2 * k], s->y[k] = xy[2 * k + 1];
    v[0] = C;
    /* the head: a short arrow along the arc's last step */
    mm_shape *h = shape(res, "couple head", MM_SHAPE_ARROW, 2);
    double *hv = h ? mm_shape_values(res, h) : NULL;
    if (!hv)
        return MM_ENOMEM;
    h->unit = "N m";
    h->scale = 0;
    hv[0] = fabs(C);
    h->x[0] = xy[2 * (N - 2)], h->y[0] = xy[2 * (N - 2) + 1];
    h->x[1] = xy[2 * (N - 1)], h->y[1] = xy[2 * (N - 1) + 1];
    return MM_OK;
}

/* ---- drawing in space (an oblique projection) --------------------------------------- */

void mm_sta_project(double x, double y, double z, double *u, double *v)
{
    /* cabinet projection: x drawn at 210 degrees, half length */
    *u = y - 0.5 * x * cos(M_PI / 6);
    *v = z - 0.5 * x * sin(M_PI / 6);
}

int mm_sta_line3(mm_result *res, const char *name, const double *a, const double *b, const char *style)
{
    double xy[4];
    mm_sta_project(a[0], a[1], a[2], &xy[0], &xy[1]);
    mm_sta_project(b[0], b[1], b[2], &xy[2], &xy[3]);
    return mm_sta_path(res, name, 2, xy, style);
}

int mm_sta_arrow3(mm_result *res, const char *name, const double *p, const double *v, double scale, int head,
                  const char *unit, const char *style)
{
    double u0, v0, u1, v1;
    if (head) {
        mm_sta_project(p[0] - scale * v[0], p[1] - scale * v[1], p[2] - scale * v[2], &u0, &v0);
        mm_sta_project(p[0], p[1], p[2], &u1, &v1);
    } else {
        mm_sta_project(p[0], p[1], p[2], &u0, &v0);
        mm_sta_project(p[0] + scale * v[0], p[1] + scale * v[1], p[2] + scale * v[2], &u1, &v1);
    }
    mm_shape *s = mm_anim_shape(res, name, MM_SHAPE_ARROW, 1, 2);
    double *val = s ? mm_shape_values(res, s) : NULL;
    if (!val)
        return MM_ENOMEM;
    s->x[0] = u0, s->y[0] = v0, s->x[1] = u1, s->y[1] = v1;
    s->unit = unit, s->scale = scale, s->style = style;
    val[0] = mm_sta_norm(v);
    return MM_OK;
}

int mm_sta_label3(mm_result *res, const double *p, const char *fmt, ...)
{
    double u, v;
    mm_sta_project(p[0], p[1], p[2], &u, &v);
    va_list ap;
    va_start(ap, fmt);
    int rc = vlabel(res, u, v, fmt, ap);
    va_end(ap);
    return rc;
}

int mm_sta_axes3(mm_result *res, const double *O, double len)
{
    static const char *const names[3] = {"x", "y", "z"};
    int rc = MM_OK;
    for (int k = 0; k < 3 && !rc; k++) {
        double tip[3] = {O[0], O[1], O[2]};
        tip[k] += len;
        rc = mm_sta_line3(res, names[k], O, tip, "ground");
        if (!rc)
            rc = mm_sta_label3(res, tip, "%s", names[k]);
    }
    return rc;
}

int mm_sta_polygon3(mm_result *res, const char *name, int n, const double *xyz, const char *style)
{
    double *xy = mm_res_alloc(res, 2 * (size_t)n * sizeof *xy);
    if (!xy)
        return MM_ENOMEM;
    for (int i = 0; i < n; i++)
        mm_sta_project(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2], &xy[2 * i], &xy[2 * i + 1]);
    return mm_sta_polygon(res, name, n, xy, style);
}

/* ---- answers and checks: the idioms of the chapter ---------------------------------- */

int mm_sta_rows(const mm_value *v, const char *param, const char *what, const char *row, int cols, mm_error *err)
{
    if (v->rows && v->cols != cols)
        return mm_error_set(err, MM_ERANGE, param, "each %s is one row %s; got %d numbers", what, row, v->cols);
    return MM_OK;
}

double mm_sta_shown(double v, double err)
{
    return fabs(v) <= err ? 0 : v;
}

double mm_sta_reactions(mm_result *res, int out, int out_plot, int n, const double *R, double rerr)
{
    double Rmax = 0;
    mm_series *rp = mm_res_series(res, out_plot, n);
    for (int k = 0; k < n; k++) {
        double shown = mm_sta_shown(R[k], rerr);
        mm_scalar *s = mm_res_scalar_i(res, out, k + 1, shown);
        if (s)
            s->error = rerr, s->error_kind = MM_ERR_ESTIMATE;
        if (rp)
            rp->x[k] = k + 1, rp->y[k] = shown;
        Rmax = fmax(Rmax, fabs(R[k]));
    }
    return Rmax;
}

int mm_sta_check_absf(mm_result *res, double value, double ref, double tol, const char *fmt, ...)
{
    char buf[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    return mm_res_check_abs(res, buf, value, ref, tol);
}

int mm_sta_worst(int n, const double *a, const double *b, int last)
{
    int w = 0;
    double d = -1;
    for (int k = 0; k < n; k++) {
        double e = fabs(a[k] - b[k]);
        if (last ? e >= d : e > d)
            d = e, w = k;
    }
    return w;
}

int mm_sta_improper2(const mm_equil_result *r, int n, const double *mech, const double *self, mm_error *err)
{
    const double *u = mech;
    int red = -1;
    if (r->n_self > 0) {
        red = 0;
        for (int k = 1; k < n; k++)
            if (fabs(self[k]) > fabs(self[red]))
                red = k;
    }
    if (r->n_mech == 0)
        return mm_error_set(err, MM_ESINGULAR, "links",
                            "statically indeterminate: %d links for 3 equations; link %d is redundant", n, red + 1);
    char what[120];
    if (fabs(u[2]) > 1e-9 * hypot(u[0], u[1]))
        snprintf(what, sizeof what, "the links let the body turn about (%.4g, %.4g) m", 0.0 - u[1] / u[2],
                 0.0 + u[0] / u[2]);
    else
        snprintf(what, sizeof what, "the links let the body slide along a line at %.1f deg to x",
                 atan2(u[1], u[0]) * 180 / M_PI);
    return mm_error_set(err, MM_ESINGULAR, "links", "improperly supported (%d link%s): %s%s; add or move a link", n,
                        n > 1 ? "s" : "", what, red >= 0 ? ", while another link is redundant" : "");
}

int mm_sta_improper3(const mm_equil_result *r, int n, const double *mech, const double *self, mm_error *err)
{
    if (r->n_mech > 0) {
        /* the free motion: origin velocity v, angular velocity w */
        const double *v = mech, *w = mech + 3;
        double wn = mm_sta_norm(w);
        if (wn > 1e-9 * mm_sta_norm(v)) {
            double p[3];
            mm_sta_cross(w, v, p);
            return mm_error_set(err, MM_ESINGULAR, "links",
                                "improperly supported (%d links, rank %d): the body can turn about the axis "
                                "through (%.3g, %.3g, %.3g) along (%.3g, %.3g, %.3g); add or move a link",
                                n, r->rank, p[0] / (wn * wn) + 0.0, p[1] / (wn * wn) + 0.0,
                                p[2] / (wn * wn) + 0.0, w[0] / wn + 0.0, w[1] / wn + 0.0, w[2] / wn + 0.0);
        }
        double vn = mm_sta_norm(v);
        return mm_error_set(err, MM_ESINGULAR, "links",
                            "improperly supported (%d links, rank %d): the body can slide along (%.3g, %.3g, "
                            "%.3g); add or move a link", n, r->rank, v[0] / vn + 0.0, v[1] / vn + 0.0,
                            v[2] / vn + 0.0);
    }
    int red = 0;
    for (int k = 1; k < n; k++)
        if (fabs(self[k]) > fabs(self[red]))
            red = k;
    return mm_error_set(err, MM_ESINGULAR, "links",
                        "statically indeterminate: %d links for 6 equations; link %d is redundant", n, red + 1);
}

int mm_sta_equilibria(mm_result *res, int n, const double *x, const double *y, const int *kind, int nk,
                      const int *outs)
{
    for (int k = 0; k < nk; k++) {
        int m = 0;
        for (int i = 0; i < n; i++)
            m += kind[i] == k;
        if (!m)
            continue;
        mm_series *d = mm_res_series(res, outs[k], m);
        if (!d)
            return MM_ENOMEM;
        for (int i = 0, j = 0; i < n; i++)
            if (kind[i] == k)
                d->x[j] = x[i], d->y[j] = y[i], j++;
    }
    return MM_OK;
}

int mm_sta_truss_tables(mm_result *res, const mm_truss *t, const double *F, const double *R, double ferr,
                        double ftol, int out_members, int out_plot, int out_react)
{
    int m = t->n_members;
    mm_table *mt = mm_res_table(res, out_members, m);
    if (!mt)
        return MM_ENOMEM;
    for (int e = 0; e < m; e++) {
        double *row = mt->cell + (size_t)e * 6;
        int a = t->ends[2 * e], b = t->ends[2 * e + 1];
        row[0] = e + 1, row[1] = mm_sta_shown(F[e], ferr), row[2] = a + 1, row[3] = b + 1;
        row[4] = hypot(t->xy[2 * b] - t->xy[2 * a], t->xy[2 * b + 1] - t->xy[2 * a + 1]);
        mt->text[e * 6 + 5] = F[e] > ftol ? "tension" : F[e] < -ftol ? "compression" : "zero-force";
    }
    mm_series *fp = mm_res_series(res, out_plot, m);
    if (!fp)
        return MM_ENOMEM;
    for (int e = 0; e < m; e++)
        fp->x[e] = e + 1, fp->y[e] = mm_sta_shown(F[e], ferr);
    mm_table *rt = mm_res_table(res, out_react, t->n_supports);
    if (!rt)
        return MM_ENOMEM;
    for (int s = 0; s < t->n_supports; s++) {
        int j = t->supports[3 * s];
        rt->cell[3 * s] = j + 1, rt->cell[3 * s + 1] = mm_sta_shown(R[2 * j], ferr);
        rt->cell[3 * s + 2] = mm_sta_shown(R[2 * j + 1], ferr);
    }
    return MM_OK;
}

/* ---- the standard figures of the exercises ------------------------------------------ */

int mm_sta_links2(mm_result *res, int n, const double *links, const double *R, double size, double sc)
{
    int rc = MM_OK;
    for (int k = 0; k < n; k++) {
        const double *l = links + 4 * k;
        double len = hypot(l[2], l[3]), e[2] = {l[2] / len, l[3] / len};
        mm_sta_line(res, "link", l[0], l[1], l[0] - 0.12 * size * e[0], l[1] - 0.12 * size * e[1], "ground", 0, 0);
        if (R[k] != 0)
            mm_sta_force(res, "reaction", l[0], l[1], R[k] * e[0], R[k] * e[1], sc, 1);
        rc = mm_sta_label(res, l[0] - 0.15 * size * e[0], l[1] - 0.15 * size * e[1], "R%d", k + 1);
    }
    return rc;
}

int mm_sta_links3(mm_result *res, int n, const double *links, const double *R, double size, double sc)
{
    int rc = MM_OK;
    for (int k = 0; k < n; k++) {
        const double *l = links + 6 * k;
        double len = mm_sta_norm(l + 3), e[3] = {l[3] / len, l[4] / len, l[5] / len}, t[4], f[3];
        mm_sta_project(l[0], l[1], l[2], &t[0], &t[1]);
        mm_sta_project(l[0] - 0.15 * size * e[0], l[1] - 0.15 * size * e[1], l[2] - 0.15 * size * e[2], &t[2], &t[3]);
        mm_sta_path(res, "link", 2, t, "ground");
        for (int c = 0; c < 3; c++)
            f[c] = R[k] * e[c];
        if (R[k] != 0)
            mm_sta_arrow3(res, "reaction", l, f, sc, 1, "N", NULL);
        rc = mm_sta_label(res, t[2], t[3], "R%d", k + 1);
    }
    return rc;
}

int mm_sta_loads2(mm_result *res, int n, const double *loads, double sc)
{
    int rc = MM_OK;
    for (int i = 0; i < n; i++) {
        const double *p = loads + 4 * i;
        rc = mm_sta_force(res, "load", p[0], p[1], p[2], p[3], sc, 1);
    }
    return rc;
}

int mm_sta_frame_apart(mm_result *res, const double *A, const double *B, const double *C, const double *R, int n,
                       const double *loads, double size, double sc)
{
    double gap = 0.08 * size, s = 0.04 * size;
    mm_sta_line(res, "left body", A[0], A[1], C[0], C[1], NULL, 0, 0);
    mm_sta_line(res, "right body", C[0] + gap, C[1], B[0] + gap, B[1], NULL, 0, 0);
    mm_sta_pin(res, "pin A", A[0], A[1], s, 0);
    mm_sta_pin(res, "pin B", B[0] + gap, B[1], s, 0);
    mm_sta_force(res, "reaction A", A[0], A[1], R[0], R[1], sc, 1);
    mm_sta_force(res, "reaction B", B[0] + gap, B[1], R[2], R[3], sc, 1);
    mm_sta_force(res, "pin force on the left body", C[0], C[1], R[4], R[5], sc, 1);
    mm_sta_force(res, "pin force on the right body", C[0] + gap, C[1], -R[4], -R[5], sc, 1);
    for (int i = 0; i < n; i++) {
        const double *p = loads + 4 * i;
        mm_sta_force(res, "load", p[0] + (p[0] > C[0] ? gap : 0), p[1], p[2], p[3], sc, 1);
    }
    mm_sta_label(res, A[0], A[1] - 2 * s, "A");
    mm_sta_label(res, B[0] + gap, B[1] - 2 * s, "B");
    return mm_sta_label(res, C[0] + 0.5 * gap, C[1] + s, "C");
}

int mm_sta_cables3(mm_result *res, int n, const double *ring, const double *anchors, const double *T,
                   const double (*u)[3], const double *P, double Fmax, double tol)
{
    double size = 0;
    for (int i = 0; i < n; i++) {
        double d[3] = {anchors[3 * i] - ring[0], anchors[3 * i + 1] - ring[1], anchors[3 * i + 2] - ring[2]};
        size = fmax(size, mm_sta_norm(d));
    }
    double fs = mm_sta_scale(Fmax, size, 0.4), ru, rv;
    mm_sta_project(ring[0], ring[1], ring[2], &ru, &rv);
    for (int i = 0; i < n; i++) {
        const double *a = anchors + 3 * i;
        double au, av;
        mm_sta_project(a[0], a[1], a[2], &au, &av);
        char nm[24];
        snprintf(nm, sizeof nm, "cable %d", i + 1);
        mm_sta_member(res, nm, ru, rv, au, av, T[i], tol);
        double box[8] = {au - 0.04 * size, av, au + 0.04 * size, av, au + 0.04 * size, av + 0.04 * size,
                         au - 0.04 * size, av + 0.04 * size};
        mm_sta_polygon(res, "anchor", 4, box, "ground");
        double t[3] = {T[i] * u[i][0], T[i] * u[i][1], T[i] * u[i][2]};
        if (T[i] > 0)
            mm_sta_arrow3(res, "tension", ring, t, fs, 0, "N", "tension");
        mm_sta_label(res, 0.5 * (ru + au), 0.5 * (rv + av), "T%d = %.4g N", i + 1, T[i]);
    }
    mm_sta_circle(res, "ring", ru, rv, 0.03 * size, NULL);
    return mm_sta_arrow3(res, "load", ring, P, fs, 0, "N", NULL);
}

int mm_sta_belt(mm_result *res, double T1, double T2, double theta, double r, double torque)
{
    double shown = fmin(theta, 2 * M_PI - 0.2), a0 = M_PI / 2 + shown / 2, a1 = a0 - shown;
    enum { N = 73 };
    double arc[2 * N];
    for (int k = 0; k < N; k++) {
        double t = a0 - shown * k / (N - 1);
        arc[2 * k] = 1.04 * r * cos(t), arc[2 * k + 1] = 1.04 * r * sin(t);
    }
    double sc = mm_sta_scale(T2, r, 1.6);
    /* the belt leaves at a0 (slack) and a1 (tight), along the tangents */
    double t1x = -sin(a0), t1y = cos(a0), t2x = sin(a1), t2y = -cos(a1);
    mm_sta_circle(res, "drum", 0, 0, r, NULL);
    mm_sta_path(res, "belt", N, arc, "tension");
    mm_sta_force(res, "T1", r * cos(a0), r * sin(a0), T1 * t1x, T1 * t1y, sc, 0);
    mm_sta_force(res, "T2", r * cos(a1), r * sin(a1), T2 * t2x, T2 * t2y, sc, 0);
    mm_sta_couple(res, "torque on the drum", 0, 0, 0.4 * r, torque);
    mm_sta_label(res, 1.1 * r * cos(a0), 1.1 * r * sin(a0), "T1 = %.4g N", T1);
    return mm_sta_label(res, 1.1 * r * cos(a1), 1.1 * r * sin(a1), "T2 = %.4g N", T2);
}

int mm_sta_slider_crank(mm_result *res, double r, double l, double e, double th, double xb, double Frod,
                        double ftol, double P, double M, double dx)
{
    double xa = r * cos(th), ya = r * sin(th), yb = e, L = r + l;
    double sc = mm_sta_scale(fabs(P), L, 0.25), bw = 0.1 * L;
    double box[8] = {xb - bw, yb - bw / 2, xb + bw, yb - bw / 2, xb + bw, yb + bw / 2, xb - bw, yb + bw / 2};
    double guide[4] = {-0.2 * L, yb - bw / 2, 1.3 * L, yb - bw / 2};
    mm_sta_path(res, "guide", 2, guide, "ground");
    mm_sta_pin(res, "pivot O", 0, 0, 0.06 * L, 0);
    mm_sta_line(res, "crank", 0, 0, xa, ya, NULL, 0, 0);
    mm_sta_member(res, "rod", xa, ya, xb, yb, Frod, ftol);
    mm_sta_polygon(res, "slider", 4, box, NULL);
    if (P != 0)
        mm_sta_force(res, "P", xb + bw, yb, -P, 0, sc, 1);
    if (M != 0)
        mm_sta_couple(res, "M", 0, 0, 0.25 * r, M);
    mm_sta_line(res, "virtual displacement dx_B", xb, yb + bw, xb + 0.3 * L * (dx >= 0 ? 1 : -1), yb + bw,
                "highlight", 1, dx);
    return mm_sta_label(res, -0.2 * L, 0.5 * L, "M = P dx_B/dtheta = %.4g N m", M);
}

int mm_sta_reduced3(mm_result *res, int n, const double *forces, const double *O, const double *R, const double *M,
                    const double *P, double pitch, int kind, double reach, const char *what)
{
    double fmx = 0, Rn = mm_sta_norm(R);
    for (int i = 0; i < n; i++)
        fmx = fmax(fmx, mm_sta_norm(forces + 6 * i + 3));
    double L = fmax(reach, 1e-3), fs = mm_sta_scale(fmax(fmx, Rn), L, 0.5);
    for (int i = 0; i < n; i++)
        mm_sta_arrow3(res, "force", forces + 6 * i, forces + 6 * i + 3, fs, 0, "N", NULL);
    if (kind >= 2) {
        mm_sta_arrow3(res, "R on the central axis", P, R, fs, 0, "N", "highlight");
        double a[3], b[3];
        for (int k = 0; k < 3; k++)
            a[k] = P[k] - L * R[k] / Rn, b[k] = P[k] + L * R[k] / Rn;
        mm_sta_line3(res, "central axis", a, b, "ground");
        if (kind == 3) {
            double mw[3] = {pitch * R[0], pitch * R[1], pitch * R[2]};
            mm_sta_arrow3(res, "couple of the wrench", P, mw, 0.5 * L / fabs(pitch * Rn), 0, "N m", "highlight");
        }
    } else if (kind == 1) {
        mm_sta_arrow3(res, "couple", O, M, 0.5 * L / mm_sta_norm(M), 0, "N m", "highlight");
    }
    return mm_sta_label3(res, O, "O: %s", what);
}

int mm_sta_area(mm_result *res, int n, const double *xy, int nd, const double *discs, const mm_section_props *p)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int k = 0; k < n; k++)
        for (int d = 0; d < 2; d++)
            lo[d] = fmin(lo[d], xy[2 * k + d]), hi[d] = fmax(hi[d], xy[2 * k + d]);
    double size = fmax(hi[0] - lo[0], hi[1] - lo[1]), half = 0.6 * size;
    mm_sta_polygon(res, "area", n, xy, NULL);
    for (int k = 0; k < nd; k++) {
        const double *d = discs + 3 * k;
        mm_sta_circle(res, d[2] > 0 ? "disc" : "hole", d[0], d[1], fabs(d[2]), d[2] > 0 ? NULL : "ground");
    }
    double c = cos(p->alpha), s = sin(p->alpha);
    mm_sta_line(res, "axis 1 (I1)", p->xc - half * c, p->yc - half * s, p->xc + half * c, p->yc + half * s,
                "highlight", 0, 0);
    mm_sta_line(res, "axis 2 (I2)", p->xc + half * s, p->yc - half * c, p->xc - half * s, p->yc + half * c,
                "highlight", 0, 0);
    mm_sta_circle(res, "centroid", p->xc, p->yc, 0.015 * size, "highlight");
    mm_sta_arrow(res, "weight of a uniform plate (per N/m^2)", p->xc, p->yc, p->xc, p->yc - 0.3 * size, "m^2",
                 0.3 * size / p->A, p->A);
    mm_sta_label(res, p->xc + 0.03 * size, p->yc + 0.03 * size, "C (%.4g, %.4g)", p->xc, p->yc);
    mm_sta_label(res, p->xc + half * c, p->yc + half * s, "1");
    return mm_sta_label(res, p->xc - half * s, p->yc + half * c, "2");
}

int mm_sta_block_incline(mm_result *res, double a, double w, double h, double hP, double W, double P, double N,
                         double F, double xn, const char *what)
{
    double sa = sin(a), ca = cos(a);
    double L = 3 * fmax(w, h), ramp[6] = {-0.5 * L * ca, -0.5 * L * sa, 1.5 * L * ca, 1.5 * L * sa, 1.5 * L * ca,
                                         -0.5 * L * sa};
    mm_sta_polygon(res, "incline", 3, ramp, "ground");
    double c[8], loc[8] = {0, 0, w, 0, w, h, 0, h};
    for (int k = 0; k < 4; k++)
        c[2 * k] = loc[2 * k] * ca - loc[2 * k + 1] * sa, c[2 * k + 1] = loc[2 * k] * sa + loc[2 * k + 1] * ca;
    mm_sta_polygon(res, "block", 4, c, NULL);
    double sc = mm_sta_scale(fmax(fmax(W, P), N), fmax(w, h), 0.6);
    /* (u, v) in the slope frame, turned by a */
#define AT(u, v) (u) * ca - (v) * sa, (u) * sa + (v) * ca
    mm_sta_force(res, "W", AT(w / 2, h / 2), 0, -W, sc, 0);
    mm_sta_force(res, "P", AT(0, hP), P * ca, P * sa, sc, 1);
    mm_sta_force(res, "N", AT(xn, 0), -N * sa, N * ca, sc, 1);
    if (F != 0)
        mm_sta_force(res, "friction", AT(xn, 0), -F * ca, -F * sa, sc, 1);
    int rc = mm_sta_label(res, AT(0, h * 1.3), "%s at P = %.4g N", what, P);
#undef AT
    return rc;
}

int mm_sta_wedge(mm_result *res, double be, double W, double Pin, double Pout, const double *N)
{
    double Lw = 2, H = Lw * tan(be), xl = 1.2, bw = 0.6;         /* the load sits at x in [xl - bw, xl] */
    double yl = (Lw - xl) * tan(be);                              /* incline height under the load's right edge */
    double wedge_xy[6] = {0, 0, Lw, 0, 0, H}, load[8] = {xl - bw, yl + bw * tan(be), xl, yl, xl, yl + 0.8,
                                                         xl - bw, yl + 0.8};
    double floor[4] = {-0.5, 0, Lw + 0.3, 0}, wall[4] = {xl, yl, xl, yl + 1.2};
    double sc = mm_sta_scale(fmax(fmax(Pin, W), N[1]), 1.5, 0.4);
    mm_sta_path(res, "floor", 2, floor, "ground");
    mm_sta_path(res, "wall", 2, wall, "ground");
    mm_sta_polygon(res, "wedge", 3, wedge_xy, NULL);
    mm_sta_polygon(res, "load", 4, load, NULL);
    mm_sta_force(res, "P", 0, 0.3 * H, Pin, 0, sc, 1);
    mm_sta_force(res, "W", xl - bw / 2, yl + 0.4, 0, -W, sc, 0);
    mm_sta_force(res, "N2 on the load", xl - bw / 2, yl + 0.5 * bw * tan(be), N[1] * sin(be), N[1] * cos(be), sc, 1);
    mm_sta_force(res, "N3 from the wall", xl, yl + 0.4, -N[2], 0, sc, 1);
    mm_sta_force(res, "N1 from the floor", 0.5 * Lw, 0, 0, N[0], sc, 1);
    return mm_sta_label(res, 0, H + 0.1, "P_in = %.4g N, P_out = %.4g N", Pin, Pout);
}

int mm_sta_rod_spring(mm_result *res, double L, double a, double k, double W, double q, const char *what)
{
    double xw = -0.6 * L, tip[2] = {L * sin(q), L * cos(q)}, sp[2] = {a * sin(q), a * cos(q)};
    mm_sta_pin(res, "hinge", 0, 0, 0.1 * L, 0);
    mm_sta_line(res, "rod", 0, 0, tip[0], tip[1], NULL, 0, 0);
    double guide[4] = {xw, 0, xw, 1.2 * L};
    mm_sta_path(res, "guide", 2, guide, "ground");
    mm_shape *spring = mm_anim_shape(res, "spring", MM_SHAPE_LINE, 1, 16);
    if (!spring)
        return MM_ENOMEM;
    for (int j = 0; j < 16; j++) {
        double f = j / 15.0, zig = j > 1 && j < 14 ? (j % 2 ? 0.04 : -0.04) * L : 0;
        spring->x[j] = xw + f * (sp[0] - xw), spring->y[j] = sp[1] + zig;
    }
    double sc = mm_sta_scale(fmax(W, k * a * fabs(sin(q))), L, 0.4);
    mm_sta_force(res, "W", tip[0], tip[1], 0, -W, sc, 0);
    if (q != 0)
        mm_sta_force(res, "spring force", sp[0], sp[1], -k * sp[0], 0, sc, 0);
    mm_sta_force(res, "hinge reaction", 0, 0, k * sp[0], W, sc, 1);
    return mm_sta_label(res, tip[0], tip[1] + 0.05 * L, "theta = %.4g rad (%s)", q, what);
}

int mm_sta_beam(mm_result *res, const mm_beam_problem *p, const mm_beam *b, double Mext, double xM)
{
    double L = p->L, h = 0.03 * L, beam[8] = {0, -h / 2, L, -h / 2, L, h / 2, 0, h / 2};
    double rx[2], ry[2], rcpl[2], Fbig = 0, qmax = 0;
    int nr = mm_beam_reactions(b, rx, ry, rcpl);
    for (int k = 0; k < nr; k++)
        Fbig = fmax(Fbig, fabs(ry[k]));
    for (int i = 0; i < p->n_point; i++)
        Fbig = fmax(Fbig, fabs(p->point[2 * i + 1]));
    for (int i = 0; i < p->n_dist; i++)
        qmax = fmax(qmax, fmax(fabs(p->dist[4 * i + 2]), fabs(p->dist[4 * i + 3])));
    double sc = mm_sta_scale(Fbig, L, 0.25), qs = qmax > 0 ? 0.12 * L / qmax : 0;
    mm_sta_polygon(res, "beam", 4, beam, NULL);
    if (p->kind == MM_BEAM_CANTILEVER) {
        mm_sta_clamp(res, "clamp", 0, 0, 3 * h);
        if (rcpl[0] != 0)
            mm_sta_couple(res, "clamp couple", 0, 0, 2.5 * h, rcpl[0]);
    } else {
        mm_sta_pin(res, "pin", p->a, -h / 2, 2 * h, 0);
        mm_sta_roller(res, "roller", p->b, -h / 2, 2 * h, 0);
    }
    for (int k = 0; k < nr; k++)
        if (ry[k] != 0)
            mm_sta_force(res, "reaction", rx[k], ry[k] > 0 ? -h / 2 : h / 2, 0, ry[k], sc, 1);
    for (int i = 0; i < p->n_point; i++) {
        double x = p->point[2 * i], F = p->point[2 * i + 1];
        if (F != 0)
            mm_sta_force(res, "load", x, F < 0 ? h / 2 : -h / 2, 0, F, sc, 1);
    }
    for (int i = 0; i < p->n_dist; i++) {
        const double *d = p->dist + 4 * i;
        /* the load's shape above (down loads) or below (up loads) the beam */
        double y1 = h / 2 - qs * d[2], y2 = h / 2 - qs * d[3];
        double outline[8] = {d[0], h / 2, d[1], h / 2, d[1], y2, d[0], y1};
        mm_sta_polygon(res, "distributed load", 4, outline, "highlight");
        for (int k = 0; k <= 4; k++) {
            double x = d[0] + (d[1] - d[0]) * k / 4, q = d[2] + (d[3] - d[2]) * k / 4;
            if (q != 0)
                mm_sta_force(res, "q", x, q < 0 ? h / 2 : -h / 2, 0, q * qs / sc, sc, 1);
        }
    }
    for (int i = 0; i < p->n_moment; i++)
        mm_sta_couple(res, "couple", p->moment[2 * i], 0, 2 * h, p->moment[2 * i + 1]);
    mm_sta_label(res, xM, -0.2 * L, "M = %.4g N m at x = %.4g m", Mext, xM);
    return mm_sta_label(res, 0, 0.3 * L, "V: sum of forces left of x, up +;  M: sagging +");
}

int mm_sta_beam_diagrams(mm_result *res, const mm_beam *b, int n, int with_y, int out_V, int out_M, int out_y)
{
    int total = mm_beam_sample_size(b, n);
    mm_series *V = mm_res_series(res, out_V, total), *M = mm_res_series(res, out_M, total);
    mm_series *Y = with_y ? mm_res_series(res, out_y, total) : NULL;
    if (!V || !M || (with_y && !Y))
        return MM_ENOMEM;
    mm_beam_sample(b, n, V->x, V->y, M->y, Y ? Y->y : NULL);
    memcpy(M->x, V->x, (size_t)total * sizeof *V->x);
    if (Y)
        memcpy(Y->x, V->x, (size_t)total * sizeof *V->x);
    return MM_OK;
}

int mm_sta_truss(mm_result *res, const mm_truss *t, const double *F, const double *R, double pmax, double ftol)
{
    int nj = t->n_nodes;
    double lo = INFINITY, hi = -INFINITY, rmax = 0;
    for (int k = 0; k < 2 * nj; k++)
        lo = fmin(lo, t->xy[k]), hi = fmax(hi, t->xy[k]);
    for (int k = 0; k < 2 * nj; k++)
        rmax = fmax(rmax, fabs(R[k]));
    double fscale = mm_sta_scale(fmax(pmax, rmax), fmax(hi - lo, 1e-6), 0.2);
    double lo2[2] = {INFINITY, INFINITY}, hi2[2] = {-INFINITY, -INFINITY};
    for (int j = 0; j < nj; j++)
        for (int d = 0; d < 2; d++)
            lo2[d] = fmin(lo2[d], t->xy[2 * j + d]), hi2[d] = fmax(hi2[d], t->xy[2 * j + d]);
    double size = fmax(fmax(hi2[0] - lo2[0], hi2[1] - lo2[1]), 1e-6), sup = 0.06 * size;
    for (int e = 0; e < t->n_members; e++) {
        const double *a = t->xy + 2 * t->ends[2 * e], *b = t->xy + 2 * t->ends[2 * e + 1];
        char name[24];
        snprintf(name, sizeof name, "member %d", e + 1);
        mm_sta_member(res, name, a[0], a[1], b[0], b[1], F[e], ftol);
    }
    for (int s = 0; s < t->n_supports; s++) {
        const int *r = t->supports + 3 * s;
        const double *p = t->xy + 2 * r[0];
        if (r[1] && r[2])
            mm_sta_pin(res, "pin", p[0], p[1], sup, 0);
        else
            mm_sta_roller(res, "roller", p[0], p[1], sup, r[2] ? 0 : -M_PI / 2);
        for (int d = 0; d < 2; d++)
            if (r[1 + d] && fabs(R[2 * r[0] + d]) > ftol)
                mm_sta_force(res, "reaction", p[0], p[1], d == 0 ? R[2 * r[0]] : 0, d == 1 ? R[2 * r[0] + 1] : 0,
                             fscale, 1);
    }
    for (int l = 0; l < t->n_loads; l++) {
        const double *p = t->xy + 2 * t->load_node[l];
        mm_sta_force(res, "load", p[0], p[1], t->load_f[2 * l], t->load_f[2 * l + 1], fscale, 1);
    }
    int rc = MM_OK;
    for (int j = 0; j < nj; j++)
        rc = mm_sta_label(res, t->xy[2 * j] + 0.02 * size, t->xy[2 * j + 1] + 0.02 * size, "%d", j + 1);
    return rc;
}

/* ---- vectors ------------------------------------------------------------------------ */

void mm_sta_cross(const double *a, const double *b, double *c)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

double mm_sta_dot(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double mm_sta_norm(const double *a)
{
    return sqrt(mm_sta_dot(a, a));
}
