/* centroid.c — sta-centroid: area, centroid and second moments of any
 * polygon a learner types (either orientation), with discs added or cut
 * out: a composite area.
 *
 * Goal: centroids and second moments by Green's theorem over the edges
 * (eqs. 2-4 of centroid.md), the parallel-axis theorem (5), principal
 * axes (6); why a polygon that crosses itself has no area to speak of.
 * Checks: a second decomposition of the same area into triangles (ear
 * clipping), each by its own closed form and combined by the
 * parallel-axis theorem; the invariants of Mohr's circle (I1 + I2 =
 * Ixx + Iyy, I1 I2 = Ixx Iyy - Ixy^2); the moment about the axis at alpha
 * equal to I1 with no product there.
 * Reference: Hibbeler, Statics, 14th ed., ch. 9 and 10; Meriam & Kraige,
 * Statics, ch. 5 and appendix A.
 */
#include <math.h>

#include "mm_exhelp.h"
#include "mm_section.h"
#include "mm_sta.h"

#define MAXV 200
#define MAXC 20

enum { P_POLYGON, P_CIRCLES, P_POINTS };
static const mm_param params[] = {
    [P_POLYGON] = {"polygon", "polygon vertices (x, y per row)", "m", MM_MATRIX, 0, -1e4, 1e4,
                   "0,0;4,0;4,1;1,1;1,3;0,3", NULL, MAXV, 2,
                   .help = "3 to 200 vertices in order round the outline, either way round; the first is "
                           "not repeated; the outline must not cross or touch itself"},
    [P_CIRCLES] = {"circles", "discs (x, y, r per row; r < 0 a hole)", "m", MM_MATRIX, 0, -1e4, 1e4, "", NULL,
                   MAXC, 3,
                   .help = "composite parts: a disc of radius r at (x, y) added outside the polygon, or "
                           "with r < 0 a hole of radius |r| cut inside it; none by default"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 181, 11, 1801,
                  .help = "samples of I(t) over the axis angle t"},
};

enum { O_AREA, O_XC, O_YC, O_IXX, O_IYY, O_IXY, O_I1, O_I2, O_ALPHA, O_ORIENT, O_IT, O_ANIM };
static const mm_output outputs[] = {
    [O_AREA] = MM_SCALAR("area", "area", "m^2", .flags = MM_ANSWER | MM_EXACT),
    [O_XC] = MM_SCALAR("xc", "centroid x", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_YC] = MM_SCALAR("yc", "centroid y", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_IXX] = MM_SCALAR("Ixx", "second moment about the centroidal x axis", "m^4", .flags = MM_ANSWER | MM_EXACT),
    [O_IYY] = MM_SCALAR("Iyy", "second moment about the centroidal y axis", "m^4", .flags = MM_ANSWER | MM_EXACT),
    [O_IXY] = MM_SCALAR("Ixy", "product of inertia about the centroidal axes", "m^4",
                        .flags = MM_ANSWER | MM_EXACT),
    [O_I1] = MM_SCALAR("I1", "largest principal second moment", "m^4", .flags = MM_ANSWER | MM_EXACT),
    [O_I2] = MM_SCALAR("I2", "smallest principal second moment", "m^4", .flags = MM_ANSWER | MM_EXACT),
    [O_ALPHA] = MM_SCALAR("alpha", "angle of the I1 axis from x", "rad", .flags = MM_ANSWER | MM_EXACT),
    [O_ORIENT] = MM_SCALAR("orientation", "vertex order (+1 counter-clockwise, -1 clockwise)", "",
                           .flags = MM_EXACT),
    [O_IT] = MM_SERIES("I_t", "second moment about the centroidal axis at angle t", "m^4", "t", "rad"),
    [O_ANIM] = MM_ANIMATION("the area, its centroid and principal axes"),
};

/* ---- the composite ---------------------------------------------------------------- */

/* The discs must not overlap the polygon or each other: an added disc lies
 * outside it, a hole inside it (its areas would otherwise count twice). */
static int check_circles(const mm_value *P, const mm_value *C, mm_error *err)
{
    if (C->rows == 0)
        return MM_OK;
    if (C->cols != 3)
        return mm_error_set(err, MM_ERANGE, "circles", "each disc is one row x,y,r; got rows of %d numbers",
                            C->cols);
    for (int k = 0; k < C->rows; k++) {
        const double *c = C->data + 3 * k;
        double d;
        int in = mm_section_inside(P->rows, P->data, c[0], c[1], &d);
        if (c[2] == 0)
            return mm_error_set(err, MM_ERANGE, "circles", "disc %d has radius 0", k + 1);
        if (c[2] < 0 && !(in && d >= -c[2]))
            return mm_error_set(err, MM_ERANGE, "circles",
                                "hole %d (radius %g at %g, %g) must lie inside the polygon; it reaches %.3g m "
                                "past an edge", k + 1, -c[2], c[0], c[1], in ? -c[2] - d : -c[2] + d);
        if (c[2] > 0 && (in || d < c[2]))
            return mm_error_set(err, MM_ERANGE, "circles",
                                "disc %d (radius %g at %g, %g) must lie outside the polygon; composite parts "
                                "may not overlap (their areas would count twice)", k + 1, c[2], c[0], c[1]);
        for (int q = 0; q < k; q++) {
            const double *o = C->data + 3 * q;
            if (hypot(c[0] - o[0], c[1] - o[1]) < fabs(c[2]) + fabs(o[2]))
                return mm_error_set(err, MM_ERANGE, "circles", "discs %d and %d overlap", q + 1, k + 1);
        }
    }
    return MM_OK;
}

static int check(const mm_value *in, mm_error *err)
{
    const mm_value *P = &in[P_POLYGON];
    if (P->cols != 2)
        return mm_error_set(err, MM_ERANGE, "polygon", "each vertex is one row x,y; got rows of %d numbers",
                            P->cols);
    mm_section_props p;
    int rc = mm_section_polygon(P->rows, P->data, &p, NULL, err);
    if (rc != MM_OK)
        return rc;
    rc = check_circles(P, &in[P_CIRCLES], err);
    if (rc != MM_OK)
        return rc;
    mm_section_props parts[1 + MAXC], c;
    int sign[1 + MAXC];
    parts[0] = p, sign[0] = 1;
    for (int k = 0; k < in[P_CIRCLES].rows; k++) {
        const double *d = in[P_CIRCLES].data + 3 * k;
        mm_section_disc(d[0], d[1], fabs(d[2]), &parts[k + 1]);
        sign[k + 1] = d[2] > 0 ? 1 : -1;
    }
    return mm_section_combine(1 + in[P_CIRCLES].rows, parts, sign, &c, err);
}

/* The polygon (as given or as its triangles) with the discs. */
static void composite(const mm_section_props *poly, const mm_value *C, mm_section_props *out)
{
    mm_section_props parts[1 + MAXC];
    int sign[1 + MAXC];
    parts[0] = *poly, sign[0] = 1;
    for (int k = 0; k < C->rows; k++) {
        const double *d = C->data + 3 * k;
        mm_section_disc(d[0], d[1], fabs(d[2]), &parts[k + 1]);
        sign[k + 1] = d[2] > 0 ? 1 : -1;
    }
    mm_section_combine(1 + C->rows, parts, sign, out, NULL);   /* checked in check() */
}

static double moment_at(const mm_section_props *p, double t)
{
    double c = cos(t), s = sin(t);
    return p->Ixx * c * c - 2 * p->Ixy * s * c + p->Iyy * s * s;   /* eq. (6) */
}

static int draw(const mm_value *P, const mm_value *C, const mm_section_props *p, mm_result *res)
{
    mm_sta_fbd(res);
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int k = 0; k < P->rows; k++)
        for (int d = 0; d < 2; d++)
            lo[d] = fmin(lo[d], P->data[2 * k + d]), hi[d] = fmax(hi[d], P->data[2 * k + d]);
    double size = fmax(hi[0] - lo[0], hi[1] - lo[1]), half = 0.6 * size;
    mm_sta_polygon(res, "area", P->rows, P->data, NULL);
    for (int k = 0; k < C->rows; k++) {
        const double *d = C->data + 3 * k;
        mm_sta_circle(res, d[2] > 0 ? "disc" : "hole", d[0], d[1], fabs(d[2]), d[2] > 0 ? NULL : "ground");
    }
    double c = cos(p->alpha), s = sin(p->alpha);
    mm_sta_line(res, "axis 1 (I1)", p->xc - half * c, p->yc - half * s, p->xc + half * c,
                         p->yc + half * s, "highlight", 0, 0);
    mm_sta_line(res, "axis 2 (I2)", p->xc + half * s, p->yc - half * c, p->xc - half * s,
                         p->yc + half * c, "highlight", 0, 0);
    mm_sta_circle(res, "centroid", p->xc, p->yc, 0.015 * size, "highlight");
    /* a uniform plate of this shape balances on a pin at C: its weight acts
     * there (drawn per unit areal weight: the arrow's value is the area) */
    mm_shape *w = mm_anim_shape(res, "weight of a uniform plate (per N/m^2)", MM_SHAPE_ARROW, 1, 2);
    double *wv = w ? mm_shape_values(res, w) : NULL;
    if (!wv)
        return MM_ENOMEM;
    w->unit = "m^2", w->scale = 0.3 * size / p->A, wv[0] = p->A;
    w->x[0] = w->x[1] = p->xc, w->y[0] = p->yc, w->y[1] = p->yc - 0.3 * size;
    mm_sta_label(res, p->xc + 0.03 * size, p->yc + 0.03 * size, "C (%.4g, %.4g)", p->xc, p->yc);
    mm_sta_label(res, p->xc + half * c, p->yc + half * s, "1");
    mm_sta_label(res, p->xc - half * s, p->yc + half * c, "2");
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    const mm_value *P = &in[P_POLYGON], *C = &in[P_CIRCLES];
    int n = P->rows, orient;
    mm_section_props g, p;
    int rc = mm_section_polygon(n, P->data, &g, &orient, err);
    if (rc != MM_OK)
        return rc;
    composite(&g, C, &p);
    mm_res_scalar(res, O_AREA, p.A);
    mm_res_scalar(res, O_XC, p.xc);
    mm_res_scalar(res, O_YC, p.yc);
    mm_res_scalar(res, O_IXX, p.Ixx);
    mm_res_scalar(res, O_IYY, p.Iyy);
    mm_res_scalar(res, O_IXY, p.Ixy);
    mm_res_scalar(res, O_I1, p.I1);
    mm_res_scalar(res, O_I2, p.I2);
    mm_res_scalar(res, O_ALPHA, p.alpha);
    mm_res_scalar_text(res, O_ORIENT, orient, orient > 0 ? "counter-clockwise" : "clockwise");

    /* check 1: a second decomposition, into triangles (ear clipping) */
    int tri[3 * (MAXV - 2)];
    int nt = mm_section_triangulate(n, P->data, tri);
    double size = 0;
    for (int k = 0; k < n; k++)
        size = fmax(size, hypot(P->data[2 * k] - g.xc, P->data[2 * k + 1] - g.yc));
    if (nt == n - 2) {
        mm_section_props parts[MAXV], t, q;
        int sign[MAXV];
        for (int k = 0; k < nt; k++) {
            mm_section_triangle(P->data + 2 * tri[3 * k], P->data + 2 * tri[3 * k + 1], P->data + 2 * tri[3 * k + 2],
                                &parts[k]);
            sign[k] = 1;
        }
        mm_section_combine(nt, parts, sign, &t, NULL);
        composite(&t, C, &q);
        /* both are sums of n terms of the size of the whole: n eps rounding */
        double ulps = 16.0 * n, Imax = fmax(fabs(p.Ixx), fabs(p.Iyy));
        mm_check_residual(res, "area: triangles vs Green's theorem [m^2]", fabs(q.A - p.A), p.A, ulps);
        mm_check_residual(res, "centroid: triangles vs Green's theorem, distance [m]", hypot(q.xc - p.xc, q.yc - p.yc),
                          size + hypot(p.xc, p.yc), ulps);
        mm_check_residual(res, "Ixx, Iyy, Ixy: triangles vs Green's theorem, largest difference [m^4]",
                          fmax(fmax(fabs(q.Ixx - p.Ixx), fabs(q.Iyy - p.Iyy)), fabs(q.Ixy - p.Ixy)),
                          Imax + p.A * size * (size + hypot(p.xc, p.yc)), ulps);
    } else {
        mm_res_warn(res, "the outline is too thin for the triangle check (no ear found): only Green's theorem");
    }
    /* check 2: Mohr's circle, eq. (7) */
    double Is = fabs(p.Ixx) + fabs(p.Iyy);
    mm_check_residual(res, "Mohr: I1 + I2 - (Ixx + Iyy) [m^4]", p.I1 + p.I2 - p.Ixx - p.Iyy, Is, 16);
    mm_check_residual(res, "Mohr: I1 I2 - (Ixx Iyy - Ixy^2) [m^8]", p.I1 * p.I2 - (p.Ixx * p.Iyy - p.Ixy * p.Ixy),
                      Is * Is, 64);
    /* check 3: the axis at alpha carries I1 (eq. 6 turned by alpha) */
    mm_check_residual(res, "I(alpha) - I1 [m^4]", moment_at(&p, p.alpha) - p.I1, Is, 16);

    int np = (int)in[P_POINTS].x;
    mm_series *s = mm_res_series(res, O_IT, np);
    if (!s)
        return MM_ENOMEM;
    mm_linspace(-M_PI / 2, M_PI / 2, np, s->x);
    for (int i = 0; i < np; i++)
        s->y[i] = moment_at(&p, s->x[i]);
    if (p.I1 - p.I2 <= 1e-12 * Is)
        mm_res_warn(res, "I1 = I2: every centroidal axis is principal; alpha = 0 is one choice");
    mm_res_method(res, "Green's theorem over the edges; ear-clipping triangles as a check", 0);
    return draw(P, C, &p, res);
}

static const char *const references[] = {
    MM_STA_HIBBELER "ch. 9 and 10", MM_STA_MERIAM "ch. 5 and appendix A",
    "B. Braden, The surveyor's area formula, The College Mathematics Journal 17 (1986) 326-337",
    NULL,
};

const mm_exercise mm_ex_sta_centroid = {
    .id = "sta-centroid", .chapter = 3, .section = "3.9",
    .title = "Centroid and second moments of an area",
    .summary = "Any polygon, with discs added or cut out: area, centroid, second moments and principal axes, "
               "by Green's theorem and by triangles.",
    .tags = "statics, centroid, centre of gravity, second moment of area, principal axes, composite area",
    .theory = "exercises/sta/centroid.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
