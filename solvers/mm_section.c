/* mm_section.c — plane areas by Green's theorem, by triangles and by
 * composites.  The contract is in mm_section.h. */
#include "mm_section.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* twice the signed area of the triangle a, b, c: > 0 when counter-clockwise */
static double orient(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

static int sgn(double v)
{
    return (v > 0) - (v < 0);
}

/* c on the segment ab, given that the three are collinear */
static int on_segment(const double *a, const double *b, const double *c)
{
    return fmin(a[0], b[0]) <= c[0] && c[0] <= fmax(a[0], b[0]) && fmin(a[1], b[1]) <= c[1] &&
           c[1] <= fmax(a[1], b[1]);
}

/* Do segments pq and rs meet (cross or touch)?  Where, into w. */
static int segments_meet(const double *p, const double *q, const double *r, const double *s, double *w)
{
    int o1 = sgn(orient(p, q, r)), o2 = sgn(orient(p, q, s));
    int o3 = sgn(orient(r, s, p)), o4 = sgn(orient(r, s, q));
    if (o1 * o2 < 0 && o3 * o4 < 0) {
        double d1 = orient(r, s, p), d2 = orient(r, s, q), t = d1 / (d1 - d2);
        w[0] = p[0] + t * (q[0] - p[0]);
        w[1] = p[1] + t * (q[1] - p[1]);
        return 1;
    }
    const double *touch = o1 == 0 && on_segment(p, q, r)   ? r
                          : o2 == 0 && on_segment(p, q, s) ? s
                          : o3 == 0 && on_segment(r, s, p) ? p
                          : o4 == 0 && on_segment(r, s, q) ? q
                                                           : NULL;
    if (!touch)
        return 0;
    w[0] = touch[0], w[1] = touch[1];
    return 1;
}

static double signed_area2(int n, const double *xy)
{
    double s = 0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        s += xy[2 * i] * xy[2 * j + 1] - xy[2 * j] * xy[2 * i + 1];
    }
    return s;
}

int mm_section_simple(int n, const double *xy, mm_section_fault *fault)
{
    mm_section_fault local;
    if (!fault)
        fault = &local;
    fault->e1 = fault->e2 = -1;
    fault->x = fault->y = 0;
    if (n < 3)
        return 0;
    for (int k = 0; k < n; k++) {
        const double *a = xy + 2 * k, *b = xy + 2 * ((k + 1) % n);
        if (a[0] == b[0] && a[1] == b[1]) {
            fault->e1 = fault->e2 = k;
            fault->x = a[0], fault->y = a[1];
            return 0;
        }
    }
    for (int i = 0; i < n; i++) {
        const double *p = xy + 2 * i, *q = xy + 2 * ((i + 1) % n), *r = xy + 2 * ((i + 2) % n);
        /* neighbours share q: they must not run back along each other */
        double d1x = q[0] - p[0], d1y = q[1] - p[1], d2x = r[0] - q[0], d2y = r[1] - q[1];
        if (d1x * d2y - d1y * d2x == 0 && d1x * d2x + d1y * d2y < 0) {
            fault->e1 = i, fault->e2 = (i + 1) % n;
            fault->x = q[0], fault->y = q[1];
            return 0;
        }
        for (int j = i + 2; j < n; j++) {
            if (i == 0 && j == n - 1)
                continue;                                  /* neighbours through vertex 0 */
            double w[2];
            if (segments_meet(p, q, xy + 2 * j, xy + 2 * ((j + 1) % n), w)) {
                fault->e1 = i, fault->e2 = j;
                fault->x = w[0], fault->y = w[1];
                return 0;
            }
        }
    }
    return signed_area2(n, xy) != 0;
}

void mm_section_principal(mm_section_props *p)
{
    double mean = 0.5 * (p->Ixx + p->Iyy), d = 0.5 * (p->Ixx - p->Iyy);
    double ixy = fabs(p->Ixy) <= 64 * DBL_EPSILON * (fabs(p->Ixx) + fabs(p->Iyy)) ? 0 : p->Ixy;
    double R = hypot(d, ixy);
    p->I1 = mean + R;
    p->I2 = mean - R;
    double a = R > 0 ? 0.5 * atan2(-2 * ixy, p->Ixx - p->Iyy) : 0;
    if (a <= -M_PI / 2)
        a += M_PI;
    p->alpha = a;
}

int mm_section_polygon(int n, const double *xy, mm_section_props *p, int *orientation, mm_error *err)
{
    if (n < 3 || n > MM_SECTION_MAX_VERTICES)
        return mm_error_set(err, MM_ERANGE, "polygon", "a polygon needs 3 to %d vertices; got %d",
                            MM_SECTION_MAX_VERTICES, n);
    for (int k = 0; k < 2 * n; k++)
        if (!isfinite(xy[k]))
            return mm_error_set(err, MM_EVALUE, "polygon", "vertex %d has a coordinate that is not a number",
                                k / 2 + 1);
    mm_section_fault f;
    if (!mm_section_simple(n, xy, &f)) {
        if (f.e1 < 0)
            return mm_error_set(err, MM_ERANGE, "polygon",
                                "the polygon has no area: its vertices lie on one line");
        if (f.e1 == f.e2)
            return mm_error_set(err, MM_ERANGE, "polygon",
                                "vertices %d and %d are the same point (%g, %g); leave one out", f.e1 + 1,
                                (f.e1 + 1) % n + 1, f.x, f.y);
        return mm_error_set(err, MM_ERANGE, "polygon",
                            "the polygon crosses itself: edge %d-%d meets edge %d-%d at (%.4g, %.4g); "
                            "a self-intersecting outline has no inside",
                            f.e1 + 1, (f.e1 + 1) % n + 1, f.e2 + 1, (f.e2 + 1) % n + 1, f.x, f.y);
    }
    /* coordinates relative to the mean vertex: no cancellation far from 0 */
    double mx = 0, my = 0;
    for (int i = 0; i < n; i++)
        mx += xy[2 * i], my += xy[2 * i + 1];
    mx /= n, my /= n;
    double A2 = 0, Sx = 0, Sy = 0, Sxx = 0, Syy = 0, Sxy = 0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        double x0 = xy[2 * i] - mx, y0 = xy[2 * i + 1] - my, x1 = xy[2 * j] - mx, y1 = xy[2 * j + 1] - my;
        double c = x0 * y1 - x1 * y0;                /* eq. (2) of sta/centroid.md */
        A2 += c;
        Sx += (x0 + x1) * c;
        Sy += (y0 + y1) * c;
        Sxx += (x0 * x0 + x0 * x1 + x1 * x1) * c;
        Syy += (y0 * y0 + y0 * y1 + y1 * y1) * c;
        Sxy += (x0 * y1 + 2 * x0 * y0 + 2 * x1 * y1 + x1 * y0) * c;
    }
    double s = A2 > 0 ? 1 : -1;
    if (orientation)
        *orientation = (int)s;
    double A = s * A2 / 2, xr = s * Sx / 6 / A, yr = s * Sy / 6 / A;
    p->A = A;
    p->xc = mx + xr;
    p->yc = my + yr;
    p->Ixx = s * Syy / 12 - A * yr * yr;
    p->Iyy = s * Sxx / 12 - A * xr * xr;
    p->Ixy = s * Sxy / 24 - A * xr * yr;
    mm_section_principal(p);
    return MM_OK;
}

void mm_section_triangle(const double *p0, const double *p1, const double *p2, mm_section_props *p)
{
    double A = 0.5 * fabs(orient(p0, p1, p2));
    double xc = (p0[0] + p1[0] + p2[0]) / 3, yc = (p0[1] + p1[1] + p2[1]) / 3;
    const double *v[3] = {p0, p1, p2};
    double sxx = 0, syy = 0, sxy = 0;
    for (int k = 0; k < 3; k++) {
        double xi = v[k][0] - xc, eta = v[k][1] - yc;
        sxx += xi * xi, syy += eta * eta, sxy += xi * eta;
    }
    p->A = A;
    p->xc = xc, p->yc = yc;
    p->Ixx = A / 12 * syy;
    p->Iyy = A / 12 * sxx;
    p->Ixy = A / 12 * sxy;
    mm_section_principal(p);
}

void mm_section_disc(double x, double y, double r, mm_section_props *p)
{
    p->A = M_PI * r * r;
    p->xc = x, p->yc = y;
    p->Ixx = p->Iyy = M_PI * r * r * r * r / 4;
    p->Ixy = 0;
    mm_section_principal(p);
}

int mm_section_combine(int n, const mm_section_props *part, const int *sign, mm_section_props *out,
                       mm_error *err)
{
    double A = 0, Qx = 0, Qy = 0;
    for (int k = 0; k < n; k++) {
        A += sign[k] * part[k].A;
        Qy += sign[k] * part[k].A * part[k].xc;
        Qx += sign[k] * part[k].A * part[k].yc;
    }
    if (!(A > 0))
        return mm_error_set(err, MM_ERANGE, "circles", "the holes take away all the area (net %g m^2)", A);
    double xc = Qy / A, yc = Qx / A, Ixx = 0, Iyy = 0, Ixy = 0;
    for (int k = 0; k < n; k++) {
        double dx = part[k].xc - xc, dy = part[k].yc - yc;   /* parallel axes, eq. (5) */
        Ixx += sign[k] * (part[k].Ixx + part[k].A * dy * dy);
        Iyy += sign[k] * (part[k].Iyy + part[k].A * dx * dx);
        Ixy += sign[k] * (part[k].Ixy + part[k].A * dx * dy);
    }
    *out = (mm_section_props){.A = A, .xc = xc, .yc = yc, .Ixx = Ixx, .Iyy = Iyy, .Ixy = Ixy};
    mm_section_principal(out);
    return MM_OK;
}

int mm_section_triangulate(int n, const double *xy, int *tri)
{
    if (n < 3 || n > MM_SECTION_MAX_VERTICES)
        return -1;
    int idx[MM_SECTION_MAX_VERTICES], m = n, nt = 0;
    int ccw = signed_area2(n, xy) > 0;
    for (int i = 0; i < n; i++)
        idx[i] = ccw ? i : n - 1 - i;
    while (m > 3) {
        int clipped = 0;
        for (int k = 0; k < m && !clipped; k++) {
            int a = idx[(k + m - 1) % m], b = idx[k], c = idx[(k + 1) % m];
            const double *pa = xy + 2 * a, *pb = xy + 2 * b, *pc = xy + 2 * c;
            if (!(orient(pa, pb, pc) > 0))
                continue;                              /* a reflex or flat corner is no ear */
            int blocked = 0;
            for (int t = 0; t < m && !blocked; t++) {
                int v = idx[t];
                if (v == a || v == b || v == c)
                    continue;
                const double *pv = xy + 2 * v;
                blocked = orient(pa, pb, pv) >= 0 && orient(pb, pc, pv) >= 0 && orient(pc, pa, pv) >= 0;
            }
            if (blocked)
                continue;
            tri[3 * nt] = a, tri[3 * nt + 1] = b, tri[3 * nt + 2] = c;
            nt++;
            memmove(idx + k, idx + k + 1, (size_t)(m - k - 1) * sizeof *idx);
            m--;
            clipped = 1;
        }
        if (!clipped) {
            /* only flat corners left to take: a zero-area triangle each */
            for (int k = 0; k < m && !clipped; k++) {
                int a = idx[(k + m - 1) % m], b = idx[k], c = idx[(k + 1) % m];
                if (orient(xy + 2 * a, xy + 2 * b, xy + 2 * c) == 0) {
                    tri[3 * nt] = a, tri[3 * nt + 1] = b, tri[3 * nt + 2] = c;
                    nt++;
                    memmove(idx + k, idx + k + 1, (size_t)(m - k - 1) * sizeof *idx);
                    m--;
                    clipped = 1;
                }
            }
            if (!clipped)
                return -1;
        }
    }
    tri[3 * nt] = idx[0], tri[3 * nt + 1] = idx[1], tri[3 * nt + 2] = idx[2];
    return nt + 1;
}

int mm_section_inside(int n, const double *xy, double x, double y, double *dist)
{
    int in = 0;
    double best = INFINITY;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        double xi = xy[2 * i], yi = xy[2 * i + 1], xj = xy[2 * j], yj = xy[2 * j + 1];
        if ((yi > y) != (yj > y) && x < xi + (y - yi) * (xj - xi) / (yj - yi))
            in = !in;
        double ex = xj - xi, ey = yj - yi, L2 = ex * ex + ey * ey;
        double t = L2 > 0 ? ((x - xi) * ex + (y - yi) * ey) / L2 : 0;
        t = fmin(1, fmax(0, t));
        best = fmin(best, hypot(x - (xi + t * ex), y - (yi + t * ey)));
    }
    if (dist)
        *dist = best;
    return in && best > 0;
}

/* ---- statics (chapter 3): a polygon with discs added or cut out ------------- */

int mm_section_discs_check(int n, const double *xy, int n_disc, const double *disc, mm_error *err)
{
    for (int k = 0; k < n_disc; k++) {
        const double *c = disc + 3 * k;
        double d;
        int in = mm_section_inside(n, xy, c[0], c[1], &d);
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
            const double *o = disc + 3 * q;
            if (hypot(c[0] - o[0], c[1] - o[1]) < fabs(c[2]) + fabs(o[2]))
                return mm_error_set(err, MM_ERANGE, "circles", "discs %d and %d overlap", q + 1, k + 1);
        }
    }
    return MM_OK;
}

int mm_section_with_discs(const mm_section_props *poly, int n_disc, const double *disc, mm_section_props *out,
                          mm_error *err)
{
    if (n_disc > MM_SECTION_MAX_DISCS)
        return mm_error_set(err, MM_ERANGE, "circles", "at most %d discs; got %d", MM_SECTION_MAX_DISCS, n_disc);
    mm_section_props parts[1 + MM_SECTION_MAX_DISCS];
    int sign[1 + MM_SECTION_MAX_DISCS];
    parts[0] = *poly, sign[0] = 1;
    for (int k = 0; k < n_disc; k++) {
        const double *d = disc + 3 * k;
        mm_section_disc(d[0], d[1], fabs(d[2]), &parts[k + 1]);
        sign[k + 1] = d[2] > 0 ? 1 : -1;
    }
    return mm_section_combine(1 + n_disc, parts, sign, out, err);
}
