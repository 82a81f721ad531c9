/* mm_geom.c — planar and spatial geometry (see mm_geom.h). */
#include "mm_geom.h"

#include <assert.h>
#include <float.h>
#include <string.h>

#include "mm_dd.h"

/* ---- 3x3 matrices and rotations ------------------------------------------------ */

void mm_geom_m3_mul(const double A[9], const double B[9], double C[9])
{
    double T[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            T[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j];
    memcpy(C, T, sizeof T);
}

void mm_geom_m3_transpose(const double A[9], double T[9])
{
    double U[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            U[3 * j + i] = A[3 * i + j];
    memcpy(T, U, sizeof U);
}

mm_v3 mm_geom_m3_apply(const double A[9], mm_v3 v)
{
    return (mm_v3){A[0] * v.x + A[1] * v.y + A[2] * v.z, A[3] * v.x + A[4] * v.y + A[5] * v.z,
                   A[6] * v.x + A[7] * v.y + A[8] * v.z};
}

double mm_geom_m3_det(const double A[9])
{
    return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
           A[2] * (A[3] * A[7] - A[4] * A[6]);
}

void mm_geom_rot_axis(int axis, double angle, double R[9])
{
    assert(axis >= 0 && axis <= 2);
    double c = cos(angle), s = sin(angle);
    int j = (axis + 1) % 3, k = (axis + 2) % 3;   /* (axis, j, k) cyclic */
    memset(R, 0, 9 * sizeof *R);
    R[3 * axis + axis] = 1;
    R[3 * j + j] = c, R[3 * j + k] = -s;
    R[3 * k + j] = s, R[3 * k + k] = c;
}

void mm_geom_skew(mm_v3 w, double S[9])
{
    S[0] = 0, S[1] = -w.z, S[2] = w.y;
    S[3] = w.z, S[4] = 0, S[5] = -w.x;
    S[6] = -w.y, S[7] = w.x, S[8] = 0;
}

mm_v3 mm_geom_unskew(const double S[9])
{
    return (mm_v3){0.5 * (S[7] - S[5]), 0.5 * (S[2] - S[6]), 0.5 * (S[3] - S[1])};
}

int mm_geom_rot_axis_angle(mm_v3 u, double angle, double R[9], mm_error *err)
{
    double n = mm_v3_norm(u);
    if (!(n > 0) || !isfinite(n) || !isfinite(angle))
        return mm_error_set(err, MM_EVALUE, "axis", "the rotation axis must be a finite non-zero vector");
    u = mm_v3_scale(u, 1 / n);
    /* R = I + sin [u]x + (1 - cos) [u]x^2, with [u]x^2 = u u^T - I;
     * 1 - cos = 2 sin^2(angle/2) keeps its digits for small angles */
    double s = sin(angle), v = 2 * sin(0.5 * angle) * sin(0.5 * angle);
    double U[3] = {u.x, u.y, u.z};
    double K[9];
    mm_geom_skew(u, K);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[3 * i + j] = (i == j ? 1 - v : 0) + s * K[3 * i + j] + v * U[i] * U[j];
    return MM_OK;
}

void mm_geom_rot_log(const double R[9], mm_v3 *axis, double *angle)
{
    /* sin(angle) u = unskew(R), cos(angle) = (trace - 1)/2: atan2 of both
     * is accurate over the whole range */
    mm_v3 w = mm_geom_unskew(R);
    double s = mm_v3_norm(w), c = 0.5 * (R[0] + R[4] + R[8] - 1);
    *angle = atan2(s, c);
    if (c > 0 || s > 1e-3) {                 /* the skew part gives the axis */
        *axis = s > 0 ? mm_v3_scale(w, 1 / s) : (mm_v3){0, 0, 1};
        return;
    }
    /* near pi: R + R^T = 2 cos I + 2 (1 - cos) u u^T; the largest column of
     * u u^T gives u, the skew part its sign */
    double M[9];
    for (int i = 0; i < 9; i++)
        M[i] = 0.5 * (R[i] + R[3 * (i % 3) + i / 3]) - (i % 4 == 0 ? c : 0);
    int k = 0;
    for (int i = 1; i < 3; i++)
        if (M[4 * i] > M[4 * k])
            k = i;
    mm_v3 u = {M[k], M[3 + k], M[6 + k]};
    double n = mm_v3_norm(u);
    u = mm_v3_scale(u, 1 / n);
    if (mm_v3_dot(u, w) < 0)
        u = mm_v3_scale(u, -1);
    *axis = u;
}

double mm_geom_rot_orth_error(const double R[9], double *det_err)
{
    double worst = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double s = R[i] * R[j] + R[3 + i] * R[3 + j] + R[6 + i] * R[6 + j];
            worst = fmax(worst, fabs(s - (i == j)));
        }
    if (det_err)
        *det_err = mm_geom_m3_det(R) - 1;
    return worst;
}

/* ---- Euler angles ---------------------------------------------------------------- */

int mm_geom_euler_check(const int seq[3])
{
    for (int n = 0; n < 3; n++)
        if (seq[n] < 0 || seq[n] > 2)
            return 0;
    return seq[0] != seq[1] && seq[1] != seq[2];
}

void mm_geom_euler_matrix(const int seq[3], const double ang[3], double R[9])
{
    double A[9], B[9], C[9];
    mm_geom_rot_axis(seq[0], ang[0], A);
    mm_geom_rot_axis(seq[1], ang[1], B);
    mm_geom_rot_axis(seq[2], ang[2], C);
    mm_geom_m3_mul(A, B, R);
    mm_geom_m3_mul(R, C, R);
}

/* +1 when (i, j, k) is a cyclic permutation of (0, 1, 2), -1 otherwise */
static int parity(int i, int j)
{
    return (j - i + 3) % 3 == 1 ? 1 : -1;
}

/* the angle a of a rotation about axis i, from its matrix */
static double axis_angle_of(int i, const double Ri[9])
{
    int j = (i + 1) % 3, k = (i + 2) % 3;
    return atan2(Ri[3 * k + j], Ri[3 * j + j]);
}

int mm_geom_euler_angles(const int seq[3], const double R[9], double ang[3], double lock_tol,
                         double *cond)
{
    assert(mm_geom_euler_check(seq));
    int i = seq[0], j = seq[1], proper = seq[2] == i;
    int k = 3 - i - j;                        /* the axis neither i nor j */
    double sg = parity(i, j);
#define E(r, c) R[3 * (r) + (c)]
    double a, b, c, lock;
    if (proper) {                             /* R_i(a) R_j(b) R_i(c): E(i,i) = cos b */
        double sb = hypot(E(i, j), E(i, k));
        b = atan2(sb, E(i, i));
        lock = sb;
        a = atan2(E(j, i), -sg * E(k, i));
        c = atan2(E(i, j), sg * E(i, k));
    } else {                                  /* R_i(a) R_j(b) R_k(c): E(i,k) = sg sin b */
        double cb = hypot(E(i, i), E(i, j));
        b = atan2(sg * E(i, k), cb);
        lock = cb;
        a = atan2(-sg * E(j, k), E(k, k));
        c = atan2(-sg * E(i, j), E(i, i));
    }
#undef E
    if (cond)
        *cond = lock > 0 ? 1 / lock : INFINITY;
    if (lock >= lock_tol) {
        ang[0] = a, ang[1] = b, ang[2] = c;
        return 0;
    }
    /* gimbal lock: c = 0 and R_i(a) = R R_j(b)^T */
    double Bm[9], Ri[9];
    mm_geom_rot_axis(j, -b, Bm);
    mm_geom_m3_mul(R, Bm, Ri);
    ang[0] = axis_angle_of(i, Ri), ang[1] = b, ang[2] = 0;
    return 1;
}

void mm_geom_euler_rates(const int seq[3], const double ang[3], int body, double B[9])
{
    /* omega_space = a' e_i + b' R_i(a) e_j + c' R_i(a) R_j(b) e_k */
    double Ra[9], Rab[9], Rb[9];
    mm_geom_rot_axis(seq[0], ang[0], Ra);
    mm_geom_rot_axis(seq[1], ang[1], Rb);
    mm_geom_m3_mul(Ra, Rb, Rab);
    for (int r = 0; r < 3; r++) {
        B[3 * r] = r == seq[0];
        B[3 * r + 1] = Ra[3 * r + seq[1]];
        B[3 * r + 2] = Rab[3 * r + seq[2]];
    }
    if (body) {                               /* R^T B with R = R_i R_j R_k */
        double R[9], Rt[9];
        mm_geom_euler_matrix(seq, ang, R);
        mm_geom_m3_transpose(R, Rt);
        mm_geom_m3_mul(Rt, B, B);
    }
}

/* ---- intersections in the plane --------------------------------------------------- */

int mm_geom_circle_circle(mm_v2 c1, double r1, mm_v2 c2, double r2, mm_v2 p[2], double *disc)
{
    mm_v2 e = mm_v2_sub(c2, c1);
    double d = mm_v2_norm(e);
    /* 4 d^2 h^2 = ((r1+r2)^2 - d^2)(d^2 - (r1-r2)^2), each factor a product */
    double D = (r1 + r2 - d) * (r1 + r2 + d) * (d - r1 + r2) * (d + r1 - r2);
    if (disc)
        *disc = D;
    double big = r1 + r2 + d, tiny = 2 * DBL_EPSILON * big * big * big * big;
    if (!(d > 0) || D < -tiny || !isfinite(D))
        return 0;
    double a = (d * d + r1 * r1 - r2 * r2) / (2 * d);   /* along c1 -> c2 from c1 */
    double h = D > tiny ? sqrt(D) / (2 * d) : 0;         /* the half chord */
    mm_v2 u = mm_v2_scale(e, 1 / d), m = mm_v2_add(c1, mm_v2_scale(u, a)), n = mm_v2_perp(u);
    p[0] = mm_v2_add(m, mm_v2_scale(n, h));             /* left: +90 degrees from c1 -> c2 */
    p[1] = mm_v2_sub(m, mm_v2_scale(n, h));
    return h > 0 ? 2 : 1;
}

int mm_geom_line_circle(mm_v2 p0, mm_v2 u, mm_v2 c, double r, double t[2], double *disc)
{
    double uu = mm_v2_dot(u, u);
    assert(uu > 0);
    mm_v2 w = mm_v2_sub(p0, c);
    double tm = -mm_v2_dot(w, u) / uu;                  /* foot of the perpendicular from c */
    double dist = fabs(mm_v2_cross(u, w)) / sqrt(uu);   /* distance of c from the line */
    double D = (r - dist) * (r + dist);
    if (disc)
        *disc = D;
    double tiny = 8 * DBL_EPSILON * (r + dist) * (r + dist);
    if (D < -tiny || !isfinite(D))
        return 0;
    double h = D > tiny ? sqrt(D / uu) : 0;
    t[0] = tm - h, t[1] = tm + h;
    return h > 0 ? 2 : 1;
}

int mm_geom_line_line(mm_v2 p1, mm_v2 u1, mm_v2 p2, mm_v2 u2, mm_v2 *x)
{
    double den = mm_v2_cross(u1, u2);
    if (!(fabs(den) > 8 * DBL_EPSILON * mm_v2_norm(u1) * mm_v2_norm(u2)))
        return 0;
    double s = mm_v2_cross(mm_v2_sub(p2, p1), u2) / den;
    *x = mm_v2_add(p1, mm_v2_scale(u1, s));
    return 1;
}

int mm_geom_circumcircle(mm_v2 a, mm_v2 b, mm_v2 c, mm_v2 *centre, double *radius)
{
    /* about a, to keep the digits of close points far from the origin */
    mm_v2 B = mm_v2_sub(b, a), C = mm_v2_sub(c, a);
    double den = 2 * mm_v2_cross(B, C), bb = mm_v2_dot(B, B), cc = mm_v2_dot(C, C);
    double side = sqrt(fmax(fmax(bb, cc), mm_v2_dot(mm_v2_sub(C, B), mm_v2_sub(C, B))));
    mm_v2 o = {(C.y * bb - B.y * cc) / den, (B.x * cc - C.x * bb) / den};
    double R = mm_v2_norm(o);
    if (!(den != 0) || !(R <= 1e15 * side))
        return 0;
    *centre = mm_v2_add(a, o);
    *radius = R;
    return 1;
}

/* the error of x y for x, y known within ex, ey, rounded within unit of it */
static double prod_err(double x, double ex, double y, double ey, double unit)
{
    return fabs(x) * ey + fabs(y) * ex + ex * ey + unit * fabs(x * y);
}

/* A bound of the rounding of |o|, o = (C.y bb - B.y cc, B.x cc - C.x bb) /
 * (2 B x C), from exact B and C, each operation within unit of its result
 * and the root within 2 unit: a running error analysis. */
static double circumradius_rounding(mm_v2 B, mm_v2 C, double unit)
{
    double cr = mm_v2_cross(B, C), den = 2 * cr;
    double e_den = 2 * (prod_err(B.x, 0, C.y, 0, unit) + prod_err(B.y, 0, C.x, 0, unit) + unit * fabs(cr));
    double bb = mm_v2_dot(B, B), cc = mm_v2_dot(C, C), e_bb = 2 * unit * bb, e_cc = 2 * unit * cc;
    double nx = C.y * bb - B.y * cc, ny = B.x * cc - C.x * bb;
    double e_nx = prod_err(C.y, 0, bb, e_bb, unit) + prod_err(B.y, 0, cc, e_cc, unit) + unit * fabs(nx);
    double e_ny = prod_err(B.x, 0, cc, e_cc, unit) + prod_err(C.x, 0, bb, e_bb, unit) + unit * fabs(ny);
    if (!(e_den < fabs(den)))
        return INFINITY;
    double ox = nx / den, oy = ny / den;
    double e_ox = (e_nx + fabs(ox) * e_den) / (fabs(den) - e_den) + unit * fabs(ox);
    double e_oy = (e_ny + fabs(oy) * e_den) / (fabs(den) - e_den) + unit * fabs(oy);
    return hypot(e_ox, e_oy) + 2 * unit * hypot(ox, oy);            /* | |o + d| - |o| | <= |d| */
}

double mm_geom_circumradius_err(mm_v2 a, mm_v2 b, mm_v2 c, mm_v2 ea, mm_v2 eb, mm_v2 ec)
{
    mm_v2 centre;
    double R;
    if (!mm_geom_circumcircle(a, b, c, &centre, &R))
        return INFINITY;
    /* the points' errors: R = |B| |C| |C - B| / (2 |B x C|), so
     * d ln R / dB = B / |B|^2 - D / |D|^2 - (C.y, -C.x) / (B x C),
     * d ln R / dC = C / |C|^2 + D / |D|^2 - (-B.y, B.x) / (B x C), D = C - B,
     * and d/da = -(d/dB + d/dC) */
    mm_v2 B = mm_v2_sub(b, a), C = mm_v2_sub(c, a), D = mm_v2_sub(C, B);
    double cr = mm_v2_cross(B, C), nB = mm_v2_dot(B, B), nC = mm_v2_dot(C, C), nD = mm_v2_dot(D, D);
    mm_v2 gB = {R * (B.x / nB - D.x / nD - C.y / cr), R * (B.y / nB - D.y / nD + C.x / cr)};
    mm_v2 gC = {R * (C.x / nC + D.x / nD + B.y / cr), R * (C.y / nC + D.y / nD - B.x / cr)};
    mm_v2 gA = {-gB.x - gC.x, -gB.y - gC.y};
    double points = fabs(gA.x) * ea.x + fabs(gA.y) * ea.y + fabs(gB.x) * eb.x + fabs(gB.y) * eb.y +
                    fabs(gC.x) * ec.x + fabs(gC.y) * ec.y;
    /* its own rounding, measured: the same operations in double-double
     * (b - a and c - a exact by TwoSum), whose own error is bounded as above
     * with 8 MM_DD_EPS an operation */
    mm_dd Bx = mm_dd_two_sum(b.x, -a.x), By = mm_dd_two_sum(b.y, -a.y);
    mm_dd Cx = mm_dd_two_sum(c.x, -a.x), Cy = mm_dd_two_sum(c.y, -a.y);
    mm_dd den = mm_dd_mul_d(mm_dd_sub(mm_dd_mul(Bx, Cy), mm_dd_mul(By, Cx)), 2);
    mm_dd bb = mm_dd_add(mm_dd_mul(Bx, Bx), mm_dd_mul(By, By)), cc = mm_dd_add(mm_dd_mul(Cx, Cx), mm_dd_mul(Cy, Cy));
    mm_dd ox = mm_dd_div(mm_dd_sub(mm_dd_mul(Cy, bb), mm_dd_mul(By, cc)), den);
    mm_dd oy = mm_dd_div(mm_dd_sub(mm_dd_mul(Bx, cc), mm_dd_mul(Cx, bb)), den);
    mm_dd Rdd = mm_dd_sqrt(mm_dd_add(mm_dd_mul(ox, ox), mm_dd_mul(oy, oy)));
    double own = mm_dd_abs(mm_dd_sub(Rdd, mm_dd_from(R))) + 1.01 * circumradius_rounding(B, C, 8 * MM_DD_EPS);
    return 1.01 * points + own;
}

/* ---- a parametric curve: derivatives and curvature ---------------------------------- */

/* Neville's table of one component's differences at steps h0 / CON^i,
 * extrapolated in h^2; the best entry, its error estimate, and the level
 * (step index) it came from. */
static void ridders(const double *D, int levels, double *best, double *errest, int *level)
{
    const double CON2 = 1.4 * 1.4, SAFE = 2;
    double a[MM_GEOM_RIDDERS_LEVELS][MM_GEOM_RIDDERS_LEVELS];
    double err = INFINITY, ans = D[0];
    int lev = 0;
    a[0][0] = D[0];
    for (int i = 1; i < levels; i++) {
        a[0][i] = D[i];
        double fac = CON2;
        for (int j = 1; j <= i; j++) {            /* eliminate h^2, h^4, ... */
            a[j][i] = (a[j - 1][i] * fac - a[j - 1][i - 1]) / (fac - 1);
            fac *= CON2;
            double e = fmax(fabs(a[j][i] - a[j - 1][i]), fabs(a[j][i] - a[j - 1][i - 1]));
            if (e <= err) {
                err = e;
                ans = a[j][i];
                lev = i;
            }
        }
        /* rounding has taken over; not before four columns, where a lucky
         * agreement of the first extrapolations can fake a small error */
        if (i >= 4 && fabs(a[i][i] - a[i - 1][i - 1]) >= SAFE * err)
            break;
    }
    *best = ans;
    *errest = 4 * err;            /* the table's differences undershoot the error by up to 3 (measured) */
    *level = lev;
}

int mm_geom_curve_derivs(mm_geom_curve_fn f, void *params, int k, double t, double h0, double *d1,
                         double *e1, double *d2, double *e2, mm_error *err)
{
    assert(k >= 1 && k <= MM_GEOM_CURVE_MAX && h0 > 0);
    enum { L = MM_GEOM_RIDDERS_LEVELS };
    double f0[MM_GEOM_CURVE_MAX], fp[MM_GEOM_CURVE_MAX], fm[MM_GEOM_CURVE_MAX], big[MM_GEOM_CURVE_MAX];
    double D1[MM_GEOM_CURVE_MAX][L], D2[MM_GEOM_CURVE_MAX][L], hs[L];
    int rc = f(t, f0, params);
    double h = h0;
    for (int c = 0; c < k && rc == 0; c++)
        big[c] = fabs(f0[c]);
    for (int i = 0; i < L && rc == 0; i++, h /= 1.4) {
        volatile double tp = t + h, tm = t - h;     /* the steps actually taken */
        double hh = 0.5 * (tp - tm);
        hs[i] = hh;
        if ((rc = f(tp, fp, params)) != 0 || (rc = f(tm, fm, params)) != 0)
            break;
        for (int c = 0; c < k; c++) {
            if (!isfinite(fp[c]) || !isfinite(fm[c]) || !isfinite(f0[c]))
                return mm_error_set(err, MM_ENONFINITE, "t", "the curve is not finite near t = %g", t);
            D1[c][i] = (fp[c] - fm[c]) / (2 * hh);
            D2[c][i] = (fp[c] - 2 * f0[c] + fm[c]) / (hh * hh);
            big[c] = fmax(big[c], fmax(fabs(fp[c]), fabs(fm[c])));
        }
    }
    if (rc != 0)
        return mm_error_set(err, rc > MM_OK && rc < MM_STATUS_COUNT ? rc : MM_EVALUE, "t",
                            "the curve could not be evaluated near t = %g", t);
    for (int c = 0; c < k; c++) {
        /* the table's own estimate misses part of the rounding: add that of
         * the differences at the step used, |f| eps / h (and / h^2), times
         * the table's amplification (16, measured below 10) */
        int lev;
        ridders(D1[c], L, &d1[c], &e1[c], &lev);
        /* and the rounding of t +- h itself: f moves by |f'| eps |t| */
        double shift = fabs(d1[c]) * fabs(t);
        e1[c] += 16 * DBL_EPSILON * (big[c] + shift) / hs[lev];
        if (d2) {
            ridders(D2[c], L, &d2[c], &e2[c], &lev);
            e2[c] += 64 * DBL_EPSILON * (big[c] + shift) / (hs[lev] * hs[lev]);
        }
    }
    return MM_OK;
}

double mm_geom_curvature(mm_v2 v, mm_v2 a)
{
    double s = mm_v2_norm(v);
    return s > 0 ? mm_v2_cross(v, a) / (s * s * s) : 0;
}

/* ---- polygons --------------------------------------------------------------------- */

int mm_geom_polygon(const double *xy, int n, mm_geom_polygon_props *p, mm_error *err)
{
    if (n < 3)
        return mm_error_set(err, MM_EVALUE, "polygon", "a polygon needs at least 3 vertices; got %d", n);
    for (int i = 0; i < 2 * n; i++)
        if (!isfinite(xy[i]))
            return mm_error_set(err, MM_EVALUE, "polygon", "vertex %d is not finite", i / 2 + 1);
    /* Green's theorem edge by edge, coordinates relative to vertex 0 */
    double x0 = xy[0], y0 = xy[1];
    double A2 = 0, Sx = 0, Sy = 0, Sxx = 0, Syy = 0, Sxy = 0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        double xi = xy[2 * i] - x0, yi = xy[2 * i + 1] - y0, xj = xy[2 * j] - x0, yj = xy[2 * j + 1] - y0;
        double cr = xi * yj - xj * yi;
        A2 += cr;
        Sx += (xi + xj) * cr;
        Sy += (yi + yj) * cr;
        Sxx += (yi * yi + yi * yj + yj * yj) * cr;            /* int y^2 dA * 12 */
        Syy += (xi * xi + xi * xj + xj * xj) * cr;            /* int x^2 dA * 12 */
        Sxy += (xi * yj + 2 * xi * yi + 2 * xj * yj + xj * yi) * cr;   /* int x y dA * 24 */
    }
    double A = 0.5 * A2;
    if (!(fabs(A) > 0))
        return mm_error_set(err, MM_EVALUE, "polygon", "the polygon has zero area");
    double xc = Sx / (6 * A), yc = Sy / (6 * A);
    double s = A > 0 ? 1 : -1;
    p->area = fabs(A);
    p->orientation = (int)s;
    p->xc = xc + x0, p->yc = yc + y0;
    /* parallel axes back to the centroid */
    p->Ixx = s * Sxx / 12 - p->area * yc * yc;
    p->Iyy = s * Syy / 12 - p->area * xc * xc;
    p->Ixy = s * Sxy / 24 - p->area * xc * yc;
    return MM_OK;
}

/* ---- Denavit-Hartenberg frames ---- */

void mm_geom_dh(double th, double a, double al, double T[12])
{
    double c = cos(th), s = sin(th), ca = cos(al), sa = sin(al);
    double M[12] = {c, -s * ca, s * sa, a * c, s, c * ca, -c * sa, a * s, 0, sa, ca, 0};
    memcpy(T, M, sizeof M);
}

void mm_geom_frame_mul(const double A[12], const double B[12], double C[12])
{
    double T[12];
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 4; j++)
            T[4 * i + j] = A[4 * i] * B[j] + A[4 * i + 1] * B[4 + j] + A[4 * i + 2] * B[8 + j];
        T[4 * i + 3] += A[4 * i + 3];
    }
    memcpy(C, T, sizeof T);
}

/* ---- added for the kinematics chapter ------------------------------------------------ */

#include "mm_quad.h"          /* mm_geom_trochoid_arch's Gauss-Legendre panels */

double mm_geom_m3_maxdiff(const double A[9], const double B[9])
{
    double d = 0;
    for (int i = 0; i < 9; i++)
        d = fmax(d, fabs(A[i] - B[i]));
    return d;
}

void mm_geom_euler_quat_matrix(const int seq[3], const double ang[3], double R[9])
{
    double q[4] = {1, 0, 0, 0};
    for (int s = 0; s < 3; s++) {
        double e[4] = {cos(0.5 * ang[s]), 0, 0, 0}, r[4];
        e[1 + seq[s]] = sin(0.5 * ang[s]);
        r[0] = q[0] * e[0] - q[1] * e[1] - q[2] * e[2] - q[3] * e[3];
        r[1] = q[0] * e[1] + q[1] * e[0] + q[2] * e[3] - q[3] * e[2];
        r[2] = q[0] * e[2] - q[1] * e[3] + q[2] * e[0] + q[3] * e[1];
        r[3] = q[0] * e[3] + q[1] * e[2] - q[2] * e[1] + q[3] * e[0];
        memcpy(q, r, sizeof q);
    }
    double w = q[0], x = q[1], y = q[2], z = q[3];
    R[0] = 1 - 2 * (y * y + z * z), R[1] = 2 * (x * y - w * z), R[2] = 2 * (x * z + w * y);
    R[3] = 2 * (x * y + w * z), R[4] = 1 - 2 * (x * x + z * z), R[5] = 2 * (y * z - w * x);
    R[6] = 2 * (x * z - w * y), R[7] = 2 * (y * z + w * x), R[8] = 1 - 2 * (x * x + y * y);
}

/* |dP/dphi| of the trochoid; p = {R, b} */
static int trochoid_speed(double phi, double *v, void *p)
{
    const double *rb = p, sn = sin(0.5 * phi);
    *v = sqrt((rb[0] - rb[1]) * (rb[0] - rb[1]) + 4 * rb[0] * rb[1] * sn * sn);
    return 0;
}

double mm_geom_trochoid_arch(double R, double b, double *err)
{
    enum { LEVELS = 48 };
    double rb[2] = {R, b}, sum = 0, est = 0;
    for (int j = 0; j <= LEVELS; j++) {
        double hi = ldexp(M_PI, -j), lo = j < LEVELS ? 0.5 * hi : 0;
        /* the panel in two halves (the value), its estimate |Q2 - Q1| (one
         * panel: mm_quad_gl's panel-by-panel sum), and in four */
        mm_quad_result q2, q4;
        int rc = mm_quad_gl(trochoid_speed, rb, lo, hi, 1, 2, 0, &q2, NULL);
        if (rc == MM_OK)
            rc = mm_quad_gl(trochoid_speed, rb, lo, hi, 4, 4, 0, &q4, NULL);
        assert(rc == MM_OK);                    /* f is finite; no scratch is allocated for 4 panels */
        if (rc != MM_OK)
            return NAN;
        sum += q2.value;
        /* panel by panel: the panels' errors have either sign, and summed
         * differences can cancel where the errors themselves do not.  Two
         * routes, each a bound on |e(Q2)| unless its pair of rules err
         * alike: |Q2 - Q1| when |e(Q2)| <= |e(Q1)| / 2, 2 |Q4 - Q2|
         * when |e(Q4)| <= |e(Q2)| / 2 */
        est += q2.err + 2 * fabs(q4.value - q2.value);
    }
    if (err)
        *err = 2 * est;
    return 2 * sum;
}

/* ---- statics (chapter 3) ------------------------------------------------------ */

double mm_geom_angle3(const double a[3], const double b[3])
{
    mm_v3 u = {a[0], a[1], a[2]}, v = {b[0], b[1], b[2]};
    return atan2(mm_v3_norm(mm_v3_cross(u, v)), mm_v3_dot(u, v));
}
