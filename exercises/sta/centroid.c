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

enum { P_POLYGON, P_CIRCLES, P_POINTS };
static const mm_param params[] = {
    [P_POLYGON] = {"polygon", "polygon vertices (x, y per row)", "m", MM_MATRIX, 0, -1e4, 1e4,
                   "0,0;4,0;4,1;1,1;1,3;0,3", NULL, MAXV, 2,
                   .help = "3 to 200 vertices in order round the outline, either way round; the first is "
                           "not repeated; the outline must not cross or touch itself"},
    [P_CIRCLES] = {"circles", "discs (x, y, r per row; r < 0 a hole)", "m", MM_MATRIX, 0, -1e4, 1e4, "", NULL, 20, 3,
                   .help = "composite parts: a disc of radius r at (x, y) added outside the polygon, or "
                           "with r < 0 a hole of radius |r| cut inside it; none by default"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 181, 11, 1801, .help = "samples of I(t) over the axis angle t"},
};

enum { O_AREA, O_XC, O_YC, O_IXX, O_IYY, O_IXY, O_I1, O_I2, O_ALPHA, O_ORIENT, O_IT, O_ANIM };
static const mm_output outputs[] = {
    [O_AREA] = MM_SCALAR("area", "area", "m^2", .flags = MM_ANSWER | MM_EXACT),
    [O_XC] = MM_SCALAR("xc", "centroid x", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_YC] = MM_SCALAR("yc", "centroid y", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_IXX] = MM_SCALAR("Ixx", "second moment about the centroidal x axis", "m^4", .flags = MM_ANSWER | MM_EXACT),
    [O_IYY] = MM_SCALAR("Iyy", "second moment about the centroidal y axis", "m^4", .flags = MM_ANSWER | MM_EXACT),
    [O_IXY] = MM_SCALAR("Ixy", "product of inertia about the centroidal axes", "m^4", .flags = MM_ANSWER | MM_EXACT),
    [O_I1] = MM_SCALAR("I1", "largest principal second moment", "m^4", .flags = MM_ANSWER | MM_EXACT),
    [O_I2] = MM_SCALAR("I2", "smallest principal second moment", "m^4", .flags = MM_ANSWER | MM_EXACT),
    [O_ALPHA] = MM_SCALAR("alpha", "angle of the I1 axis from x", "rad", .flags = MM_ANSWER | MM_EXACT),
    [O_ORIENT] = MM_SCALAR("orientation", "vertex order (+1 counter-clockwise, -1 clockwise)", "", .flags = MM_EXACT),
    [O_IT] = MM_SERIES("I_t", "second moment about the centroidal axis at angle t", "m^4", "t", "rad"),
    [O_ANIM] = MM_ANIMATION("the area, its centroid and principal axes"),
};

static int check(const mm_value *in, mm_error *err)
{
    const mm_value *P = &in[P_POLYGON];
    if (P->cols != 2)
        return mm_error_set(err, MM_ERANGE, "polygon", "each vertex is one row x,y; got rows of %d numbers", P->cols);
    mm_section_props p, c;
    int rc = mm_section_polygon(P->rows, P->data, &p, NULL, err);
    if (rc != MM_OK)
        return rc;
    const mm_value *C = &in[P_CIRCLES];
    if (C->rows && C->cols != 3)
        return mm_error_set(err, MM_ERANGE, "circles", "each disc is one row x,y,r; got rows of %d numbers", C->cols);
    /* the discs must not overlap the polygon or each other (an added disc
     * outside it, a hole inside it), and leave a positive area */
    rc = mm_section_discs_check(P->rows, P->data, C->rows, C->data, err);
    return rc != MM_OK ? rc : mm_section_with_discs(&p, C->rows, C->data, &c, err);
}

static double moment_at(const mm_section_props *p, double t)
{
    double c = cos(t), s = sin(t);
    return p->Ixx * c * c - 2 * p->Ixy * s * c + p->Iyy * s * s;   /* eq. (6) */
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    const mm_value *P = &in[P_POLYGON], *C = &in[P_CIRCLES];
    int n = P->rows, orient;
    mm_section_props g, p;
    int rc = mm_section_polygon(n, P->data, &g, &orient, err);
    if (rc != MM_OK)
        return rc;
    mm_section_with_discs(&g, C->rows, C->data, &p, NULL);   /* the discs: checked in check() */
    const double v[] = {p.A, p.xc, p.yc, p.Ixx, p.Iyy, p.Ixy, p.I1, p.I2, p.alpha};   /* O_AREA ... O_ALPHA */
    for (int k = 0; k < 9; k++)
        mm_res_scalar(res, O_AREA + k, v[k]);
    mm_res_scalar_text(res, O_ORIENT, orient, orient > 0 ? "counter-clockwise" : "clockwise");
    /* check 1: a second decomposition, into triangles (ear clipping) */
    int tri[3 * (MAXV - 2)], nt = mm_section_triangulate(n, P->data, tri);
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
        mm_section_with_discs(&t, C->rows, C->data, &q, NULL);
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
    mm_sta_fbd(res);
    return mm_sta_area(res, n, P->data, C->rows, C->data, &p);
}

static const char *const references[] = {
    MM_STA_HIBBELER "ch. 9 and 10", MM_STA_MERIAM "ch. 5 and appendix A",
    "B. Braden, The surveyor's area formula, The College Mathematics Journal 17 (1986) 326-337", NULL};

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
