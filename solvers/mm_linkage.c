/* mm_linkage.c — closed forms of two classic linkages, and their loop
 * closures for mm_mech: the four-bar (Freudenstein's equation, the rates,
 * Grashof's classes and the arcs a crank can reach) and the offset
 * slider-crank (positions and their derivatives by the crank angle, the
 * toggles); the Bennett linkage's frames.  Equation numbers are those of exercises/kin/four_bar.md and
 * slider_crank.md.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "mm_geom.h"
#include "mm_linkage.h"

/* x wrapped to (-pi, pi] */
static double wrap(double x)
{
    double r = remainder(x, 2 * M_PI);
    return r <= -M_PI ? r + 2 * M_PI : r;
}

/* ==== the four-bar ==== */
/* ---- closed forms ------------------------------------------------------------------------- */

/* |O4 B|^2 - (b -+ c)^2 through products; the crank can be at th2 when
 * (b - c)^2 <= |O4 B|^2 <= (b + c)^2 */
double mm_linkage_fb_disc(const mm_fourbar *m, double th2)
{
    double e = hypot(m->d - m->a * cos(th2), m->a * sin(th2));
    return (m->b + m->c - e) * (e - fabs(m->b - m->c));
}

/* Freudenstein: K1 cos th4 - K2 cos th2 + K3 = cos(th2 - th4), solved by the
 * half-angle substitution t = tan(th4/2): A t^2 + B t + C = 0, eq. (2),
 * in the stable form t = Q/A or C/Q with Q = -(B + sign(B) sqrt(B^2 - 4AC))/2
 * (A = 0 when a + c = b + d... e.g. a rhombus: then one root is th4 = pi);
 * the root that puts C left (side = +1) or right (-1) of B -> O4; then th3
 * from the loop, eq. (3).  *err (may be NULL) receives a first-order bound
 * of the rounding of th3 and th4: the coefficients' and the square root's,
 * carried through th4 = 2 atan2(y, x). */
void mm_linkage_fb_angles(const mm_fourbar *m, double th2, int side, double *th3, double *th4, double *err)
{
    double a = m->a, b = m->b, c = m->c, d = m->d, c2 = cos(th2), s2 = sin(th2);
    double K1 = d / a, K2 = d / c, K3 = (a * a - b * b + c * c + d * d) / (2 * a * c);
    double A = c2 - K1 - K2 * c2 + K3, B = -2 * s2, C = K1 - (K2 + 1) * c2 + K3;
    double disc = B * B - 4 * A * C, big = B * B + 4 * fabs(A * C);
    double r = disc > 8 * DBL_EPSILON * big ? sqrt(disc) : 0;      /* a double root within rounding */
    double Q = -0.5 * (B + copysign(r, B));
    /* the two roots as (y, x) with t = y / x; a double root at B = r = 0 */
    double ys[2] = {Q, C}, xs[2] = {A, Q};
    if (Q == 0)
        ys[1] = -B, xs[1] = 2 * A;
    if (A == 0 && B == 0 && C != 0)
        ys[1] = 1, xs[1] = 0;             /* the double root at t = infinity: th4 = pi (a toggle) */
    double Bx = a * c2, By = a * s2, best = -INFINITY, y = 0, x = 1;
    int kb = 0;
    /* no root at all: A = B = C = 0, B on O4 with b = c (a rhombus at
     * th2 = 0), where every th4 closes the loop; 0 is taken (y = 0, x = 1) */
    *th4 = 0;
    for (int k = 0; k < 2; k++) {
        if (ys[k] == 0 && xs[k] == 0)
            continue;
        double t4 = 2 * atan2(ys[k], xs[k]);
        double Cx = d + c * cos(t4), Cy = c * sin(t4);
        double side_k = side * ((d - Bx) * (Cy - By) + By * (Cx - Bx));   /* cross(O4 - B, C - B) */
        if (side_k > best)
            best = side_k, *th4 = t4, y = ys[k], x = xs[k], kb = k;
    }
    double Cx = d + c * cos(*th4), Cy = c * sin(*th4);
    *th3 = wrap(atan2(Cy - By, Cx - Bx));
    *th4 = wrap(*th4);
    if (err) {
        double MA = fabs(c2) + fabs(K1) + fabs(K2 * c2) + fabs(K3), MC = fabs(K1) + fabs((K2 + 1) * c2) + fabs(K3);
        double dB = 2 * DBL_EPSILON * fabs(B), dA = 4 * DBL_EPSILON * MA, dC = 4 * DBL_EPSILON * MC;
        double ddisc = 4 * DBL_EPSILON * big + 2 * fabs(B) * dB + 4 * (fabs(A) * dC + fabs(C) * dA);
        double dr = r > 0 ? ddisc / (2 * r) : sqrt(ddisc);
        double dQ = 0.5 * (dB + dr) + DBL_EPSILON * fabs(Q);
        double dy = kb == 0 ? dQ : dC, dx = kb == 0 ? dA : dQ;
        if (Q == 0 && kb == 1)
            dy = dB + dr, dx = 2 * dA;
        double e4 = 2 * (fabs(x) * dy + fabs(y) * dx) / (x * x + y * y) + 4 * DBL_EPSILON;
        *err = e4 * fmax(1, c / b) + 4 * DBL_EPSILON;                 /* th3 moves with C */
    }
}

/* velocities and accelerations per unit crank rate (omega2 = 1), eqs. (4)-(5) */
void mm_linkage_fb_rates(const mm_fourbar *m, double th2, double th3, double th4, double *w3, double *w4,
                         double *a3, double *a4)
{
    *w3 = m->a * sin(th4 - th2) / (m->b * sin(th3 - th4));
    *w4 = m->a * sin(th2 - th3) / (m->c * sin(th4 - th3));
    double A = m->c * sin(th4), B = m->b * sin(th3), D = m->c * cos(th4), E = m->b * cos(th3);
    double C = m->a * cos(th2) + m->b * *w3 * *w3 * cos(th3) - m->c * *w4 * *w4 * cos(th4);
    double F = -m->a * sin(th2) - m->b * *w3 * *w3 * sin(th3) + m->c * *w4 * *w4 * sin(th4);
    *a3 = (C * D - A * F) / (A * E - B * D);
    *a4 = (C * E - B * F) / (A * E - B * D);
}

/* ---- eq. (1) for mm_mech: q = (th3, th4), t = th2 ---------------------------------------------- */

static int fb_phi(const double *q, double t, double *F, void *ctx)
{
    const mm_fourbar *m = ctx;
    F[0] = m->a * cos(t) + m->b * cos(q[0]) - m->c * cos(q[1]) - m->d;
    F[1] = m->a * sin(t) + m->b * sin(q[0]) - m->c * sin(q[1]);
    return 0;
}

static int fb_jac(const double *q, double t, double *J, void *ctx)
{
    (void)t;
    const mm_fourbar *m = ctx;
    J[0] = -m->b * sin(q[0]), J[1] = m->c * sin(q[1]);
    J[2] = m->b * cos(q[0]), J[3] = -m->c * cos(q[1]);
    return 0;
}

static int fb_nu(const double *q, double t, double *nu, void *ctx)
{
    (void)q;
    const mm_fourbar *m = ctx;
    nu[0] = m->a * sin(t), nu[1] = -m->a * cos(t);
    return 0;
}

static int fb_gamma(const double *q, const double *qd, double t, double *g, void *ctx)
{
    const mm_fourbar *m = ctx;
    double w3 = qd[0] * qd[0], w4 = qd[1] * qd[1];
    g[0] = m->a * cos(t) + m->b * cos(q[0]) * w3 - m->c * cos(q[1]) * w4;
    g[1] = m->a * sin(t) + m->b * sin(q[0]) * w3 - m->c * sin(q[1]) * w4;
    return 0;
}

/* ---- Grashof and the reachable crank angles -------------------------------------------------- */


mm_fourbar_class mm_linkage_fb_classify(const mm_fourbar *m, double th2)
{
    mm_fourbar_class k = {0};
    double L[4] = {m->a, m->b, m->c, m->d}, s = L[0], l = L[0], sum = 0;
    int is = 0;
    for (int i = 0; i < 4; i++) {
        sum += L[i];
        if (L[i] < s)
            s = L[i], is = i;
        l = fmax(l, L[i]);
    }
    double excess = s + l - (sum - s - l), tol = 4 * DBL_EPSILON * sum;
    k.change_point = fabs(excess) <= tol;
    k.shortest = is;
    k.grashof = excess <= tol;
    static const char *const grashof_names[4] = {"crank-rocker", "double rocker (Grashof)", "rocker-crank",
                                                 "double crank (drag link)"};
    k.name = k.change_point ? "change point" : k.grashof ? grashof_names[is] : "triple rocker (non-Grashof)";
    /* the crank turns round when |O4 B| stays within [|b - c|, b + c] */
    double g1 = fabs(m->d - m->a) - fabs(m->b - m->c), g2 = m->b + m->c - m->d - m->a;
    g1 = fabs(g1) <= tol ? 0 : g1, g2 = fabs(g2) <= tol ? 0 : g2;
    k.full = g1 >= 0 && g2 >= 0;
    if (k.full)
        return k;
    double uhi = (m->a * m->a + m->d * m->d - (m->b - m->c) * (m->b - m->c)) / (2 * m->a * m->d);
    double ulo = (m->a * m->a + m->d * m->d - (m->b + m->c) * (m->b + m->c)) / (2 * m->a * m->d);
    double Ahi = uhi < 1 ? acos(uhi) : 0, Alo = ulo > -1 ? acos(ulo) : M_PI;   /* reach: Ahi <= |th2| <= Alo */
    double w = wrap(th2);
    if (uhi < 1 && ulo > -1) {             /* two arcs: [Ahi, Alo] and [-Alo, -Ahi] */
        k.lo = w >= 0 ? Ahi : -Alo, k.hi = w >= 0 ? Alo : -Ahi;
        k.gap[0] = w >= 0 ? 2 * Ahi : 2 * M_PI - 2 * Alo, k.gap[1] = w >= 0 ? 2 * M_PI - 2 * Alo : 2 * Ahi;
    } else if (ulo > -1) {                 /* one arc about 0 */
        k.lo = -Alo, k.hi = Alo;
        k.gap[0] = k.gap[1] = 2 * M_PI - 2 * Alo;
    } else {                               /* one arc about pi */
        k.lo = Ahi, k.hi = 2 * M_PI - Ahi;
        k.gap[0] = k.gap[1] = 2 * Ahi;
        if (w < 0)
            w += 2 * M_PI;
    }
    k.lo += th2 - w, k.hi += th2 - w;      /* the arc next to the angle asked */
    return k;
}

/* the assembly of a side at th2: C from the circles about B and O4 */
void mm_linkage_fb_assemble(const mm_fourbar *m, double th2, int side, double *q)
{
    mm_v2 B = mm_v2_polar(m->a, th2), O4 = {m->d, 0}, P[2];
    int n = mm_geom_circle_circle(B, m->b, O4, m->c, P, NULL);
    mm_v2 C = n ? P[side > 0 ? 0 : 1] : mm_v2_add(B, mm_v2_scale(mm_v2_sub(O4, B), m->b / (m->b + m->c)));
    q[0] = atan2(C.y - B.y, C.x - B.x);
    q[1] = atan2(C.y, C.x - m->d);
}

/* the coupler point P and its velocity, acceleration per unit crank rate */
void mm_linkage_fb_coupler(const mm_fourbar *m, double px, double py, double th2, const double *q, const double *qd,
                           const double *qdd, mm_v2 *P, mm_v2 *V, mm_v2 *A)
{
    mm_v2 rp = mm_v2_rotate((mm_v2){px, py}, q[0]);          /* B to P */
    *P = mm_v2_add(mm_v2_polar(m->a, th2), rp);
    *V = mm_v2_add(mm_v2_perp(mm_v2_polar(m->a, th2)), mm_v2_scale(mm_v2_perp(rp), qd[0]));
    *A = mm_v2_add(mm_v2_scale(mm_v2_polar(m->a, th2), -1),
                   mm_v2_sub(mm_v2_scale(mm_v2_perp(rp), qdd[0]), mm_v2_scale(rp, qd[0] * qd[0])));
}

/* rounding bounds of one frame, given the error dth of its angles: the
 * rates inherit it through the solves (whose condition is kappa =
 * 1/|sin mu|, the Jacobian's smallest singular value being about
 * min(b, c) |sin mu|) */
void mm_linkage_fb_frame_tol(const mm_fourbar *m, const double *q, const double *qd, const double *qdd, double dth,
                             double tol[3])
{
    double mn = fmin(m->b, m->c);
    double kappa = 1 / fmax(fabs(sin(q[1] - q[0])), 1e-300);
    double W = fabs(qd[0]) + fabs(qd[1]) + m->a / mn;
    double L = fabs(qdd[0]) + fabs(qdd[1]) + (m->a + m->b * qd[0] * qd[0] + m->c * qd[1] * qd[1]) / mn;
    double dw = (16 * DBL_EPSILON + 2 * dth) * kappa * W;
    tol[0] = dth;
    tol[1] = dw;
    tol[2] = (16 * DBL_EPSILON + 2 * dth) * kappa * L + 2 * dw * kappa * (m->b * fabs(qd[0]) + m->c * fabs(qd[1])) / mn;
}

/* Newton's angles: a residual of eps S over the smallest singular value */
double mm_linkage_fb_newton_err(const mm_fourbar *m, const double *q, double err_est)
{
    double S = m->a + m->b + m->c + m->d;
    return 16 * DBL_EPSILON * S / (fmin(m->b, m->c) * fmax(fabs(sin(q[1] - q[0])), 1e-300)) + 2 * err_est;
}

/* the transmission angle from |O4 B| by the law of cosines, eq. (6) */
double mm_linkage_fb_mu(const mm_fourbar *m, double th2)
{
    double e2 = m->a * m->a + m->d * m->d - 2 * m->a * m->d * cos(th2);
    return acos(fmax(-1, fmin(1, (m->b * m->b + m->c * m->c - e2) / (2 * m->b * m->c))));
}

/* the Freudenstein root of either side nearest q (the assembly a sweep
 * keeps, which past a change point is the other label's): f = (th3, th4),
 * *err their rounding bound */
/* A = B = C = 0 in Freudenstein's equation: B on O4 and b = c, so that
 * every th4 (and its th3) closes the loop */
static int fb_every_th4(const mm_fourbar *m, double th2)
{
    double a = m->a, b = m->b, c = m->c, d = m->d, c2 = cos(th2), s2 = sin(th2);
    double K1 = d / a, K2 = d / c, K3 = (a * a - b * b + c * c + d * d) / (2 * a * c);
    return c2 - K1 - K2 * c2 + K3 == 0 && s2 == 0 && K1 - (K2 + 1) * c2 + K3 == 0;
}

void mm_linkage_fb_nearest(const mm_fourbar *m, double th2, const double *q, double *f, double *err)
{
    double g3, g4, h3, h4, ge, he;
    mm_linkage_fb_angles(m, th2, 1, &g3, &g4, &ge);
    mm_linkage_fb_angles(m, th2, -1, &h3, &h4, &he);
    if (fb_every_th4(m, th2)) {          /* every assembly closes: q is one of them */
        f[0] = q[0], f[1] = q[1], *err = ge;
        return;
    }
    int near1 = fabs(wrap(q[1] - g4)) + fabs(wrap(q[0] - g3)) <= fabs(wrap(q[1] - h4)) + fabs(wrap(q[0] - h3));
    f[0] = near1 ? g3 : h3, f[1] = near1 ? g4 : h4, *err = near1 ? ge : he;
}

/* the extremes of the transmission angle, eq. (6), over [lo, hi] (a full
 * turn when full): at the ends of |O4 B|'s range, th2 = 0 and pi, or at
 * the toggles lo, hi where coupler and rocker lie in line (mu is 0 or pi
 * exactly there: the law of cosines would give sqrt(eps)) */
void mm_linkage_fb_mu_extremes(const mm_fourbar *m, int full, double lo, double hi, double *mn, double *tmn,
                               double *mx, double *tmx)
{
    double cand[4] = {lo, hi, 0, M_PI};
    *mn = INFINITY, *mx = -INFINITY, *tmn = *tmx = 0;
    for (int i = 0; i < 4; i++) {
        double t = i < 2 ? cand[i] : cand[i] + 2 * M_PI * ceil((lo - cand[i]) / (2 * M_PI));   /* first one >= lo */
        if (t > hi + 1e-12 || (full && i < 2))
            continue;
        double v = mm_linkage_fb_mu(m, t);
        if (i < 2)
            v = v < M_PI / 2 ? 0 : M_PI;
        double where = i < 2 ? wrap(t) : cand[i];       /* 0 and pi as themselves */
        if (v < *mn)
            *mn = v, *tmn = where;
        if (v > *mx)
            *mx = v, *tmx = where;
    }
}

/* the rocker's dead centres: crank and coupler in line, |O2 C| = b + a or
 * |b - a| with C on the rocker's circle; dc[] the crank angles, dce[] their
 * rounding (acos magnifies that of its argument by 1 / sin).  Returns how
 * many (at most 4) */
int mm_linkage_fb_dead_centres(const mm_fourbar *m, double dc[4], double dce[4])
{
    int nd = 0;
    for (int e = 0; e < 2; e++) {
        double L = e ? fabs(m->b - m->a) : m->b + m->a, cs = (L * L + m->d * m->d - m->c * m->c) / (2 * L * m->d);
        if (fabs(cs) > 1 || L == 0)
            continue;
        for (int sg = -1; sg <= 1; sg += 2) {
            double ang = sg * acos(cs);                                  /* the direction of O2 C */
            dc[nd] = e && m->b < m->a ? ang : (e ? ang + M_PI : ang);    /* the crank along or against */
            dce[nd++] = 8 * DBL_EPSILON * (1 + fabs(cs)) / fmax(sqrt(1 - cs * cs), DBL_EPSILON);
        }
    }
    return nd;
}

/* a crank-rocker's swing: theta4 where crank and coupler lie in line,
 * stretched (|O2 C| = b + a) and folded (b - a), each on the side of
 * B -> O4 the assembly keeps */
double mm_linkage_fb_swing(const mm_fourbar *m, int side)
{
    double th4[2] = {0, 0};
    for (int e = 0; e < 2; e++) {
        double L = e ? m->b - m->a : m->b + m->a, ang = acos((L * L + m->d * m->d - m->c * m->c) / (2 * L * m->d));
        double best = -INFINITY;
        for (int sg = -1; sg <= 1; sg += 2) {
            mm_v2 C = mm_v2_polar(L, sg * ang), B = mm_v2_scale(C, (e ? -m->a : m->a) / L);
            double sd = side * mm_v2_cross(mm_v2_sub((mm_v2){m->d, 0}, B), mm_v2_sub(C, B));
            if (sd > best)
                best = sd, th4[e] = atan2(C.y, C.x - m->d);
        }
    }
    return fabs(wrap(th4[0] - th4[1]));
}

void mm_linkage_fb_problem(const mm_fourbar *m, mm_mech_problem *prob)
{
    *prob = (mm_mech_problem){.n = 2, .m = 2, .phi = fb_phi, .jac = fb_jac, .nu = fb_nu, .gamma = fb_gamma,
                              .params = (void *)m};
}

/* ==== the slider-crank ==== */
/* ---- the closed form, eqs. (2)-(3): side = +1 (slider right of A) or -1 ---- */


double mm_linkage_sc_disc(const mm_slider_crank *m, double phi)
{
    double s = m->e - m->r * sin(phi);
    return (m->l - s) * (m->l + s);        /* l^2 - s^2 as a product: keeps its digits at a toggle */
}

mm_sc_pos mm_linkage_sc_closed(const mm_slider_crank *m, double phi, int side)
{
    double s = m->e - m->r * sin(phi), s1 = -m->r * cos(phi), s2 = m->r * sin(phi);
    double D = mm_linkage_sc_disc(m, phi), tiny = 2 * DBL_EPSILON * m->l * m->l;
    double R = D > tiny ? side * sqrt(D) : 0;         /* within rounding of a toggle: at it */
    mm_sc_pos p = {.R = R};
    p.x = m->r * cos(phi) + R;
    p.t = atan2(s, R);
    if (R != 0) {
        double R1 = -s * s1 / R, R2 = -(s1 * s1 + s * s2) / R - s * s * s1 * s1 / (R * R * R);
        p.x1 = -m->r * sin(phi) + R1;
        p.x2 = -m->r * cos(phi) + R2;
        p.t1 = s1 / R;
        p.t2 = (s2 + s * p.t1 * p.t1) / R;
    }
    return p;
}

/* ---- the constraint equations (1) for mm_mech: q = (theta3, x), t = phi ---- */

static int sc_phi(const double *q, double t, double *F, void *ctx)
{
    const mm_slider_crank *m = ctx;
    F[0] = m->r * cos(t) + m->l * cos(q[0]) - q[1];
    F[1] = m->r * sin(t) + m->l * sin(q[0]) - m->e;
    return 0;
}

static int sc_jac(const double *q, double t, double *J, void *ctx)
{
    (void)t;
    const mm_slider_crank *m = ctx;
    J[0] = -m->l * sin(q[0]), J[1] = -1;
    J[2] = m->l * cos(q[0]), J[3] = 0;
    return 0;
}

static int sc_nu(const double *q, double t, double *nu, void *ctx)   /* eq. (4): -Phi_phi */
{
    (void)q;
    const mm_slider_crank *m = ctx;
    nu[0] = m->r * sin(t), nu[1] = -m->r * cos(t);
    return 0;
}

static int sc_gamma(const double *q, const double *qd, double t, double *g, void *ctx)   /* eq. (5) */
{
    const mm_slider_crank *m = ctx;
    g[0] = m->r * cos(t) + m->l * cos(q[0]) * qd[0] * qd[0];
    g[1] = m->r * sin(t) + m->l * sin(q[0]) * qd[0] * qd[0];
    return 0;
}

static const unsigned char sc_is_length[2] = {0, 1};

/* ---- the range the crank can reach -------------------------------------------------- */

/* The crank can be at phi when |e - r sin phi| <= l, i.e. when
 * (e - l)/r <= sin phi <= (e + l)/r.  Over a turn: all of it (|e| + r <= l),
 * or arcs between toggles where sin phi = (e -+ l)/r.  The arc holding
 * phi0 into [lo, hi] (hi - lo < 2 pi), returns 1; 0 when the whole turn is
 * reachable; -1 when phi0 is not reachable.  gaps (may be NULL) gets the
 * widths of the unreachable arcs below lo and above hi. */
int mm_linkage_sc_reach(const mm_slider_crank *m, double phi0, double *lo, double *hi, double *gaps)
{
    double tiny = 2 * DBL_EPSILON * m->l * m->l;
    if (fabs(m->e) + m->r <= m->l)
        return 0;
    if (mm_linkage_sc_disc(m, phi0) < -tiny)
        return -1;
    double up = (m->e + m->l) / m->r, dn = (m->e - m->l) / m->r;
    double base[4], c[32] = {0};
    int nb = 0, nc = 0;
    if (up < 1)
        base[nb++] = asin(up), base[nb++] = M_PI - asin(up);
    if (dn > -1)
        base[nb++] = asin(dn), base[nb++] = -M_PI - asin(dn);
    for (int i = 0; i < nb; i++)           /* every toggle within two turns of phi0, sorted */
        for (int k = -3; k <= 3; k++) {
            double v = phi0 + remainder(base[i] - phi0, 2 * M_PI) + 2 * M_PI * k;
            int j = nc++;
            while (j > 0 && c[j - 1] > v)
                c[j] = c[j - 1], j--;
            c[j] = v;
        }
    int k = 0;
    while (k + 2 < nc && c[k + 1] <= phi0)
        k++;
    /* phi0 on the rounding edge of a gap: take the arc on its reachable side */
    if (mm_linkage_sc_disc(m, 0.5 * (c[k] + c[k + 1])) < 0)
        k += phi0 - c[k] < c[k + 1] - phi0 ? -1 : 1;
    *lo = c[k], *hi = c[k + 1];
    if (gaps)                              /* the unreachable gaps below and above */
        gaps[0] = k > 0 ? c[k] - c[k - 1] : 2 * M_PI, gaps[1] = k + 2 < nc ? c[k + 2] - c[k + 1] : 2 * M_PI;
    return 1;
}

void mm_linkage_sc_problem(const mm_slider_crank *m, mm_mech_problem *prob)
{
    *prob = (mm_mech_problem){.n = 2, .m = 2, .phi = sc_phi, .jac = sc_jac, .nu = sc_nu, .gamma = sc_gamma,
                              .is_length = sc_is_length, .params = (void *)m};
}

/* ==== the Bennett linkage: four revolutes, standard Denavit-Hartenberg ==== */

/* the frames of the four joints at th1: origins o[k], axes z[k]; the loop's
 * closing error |T1 T2 T3 T4 - I| into *gap */
void mm_linkage_bennett(double a, double alpha, double beta, double th1, mm_v3 o[4], mm_v3 z[4], double *gap)
{
    double b = a * sin(beta) / sin(alpha), K = sin(0.5 * (beta + alpha)) / sin(0.5 * (beta - alpha));
    double th2 = 2 * atan(K / tan(0.5 * th1));                      /* Bennett: tan(th1/2) tan(th2/2) = K */
    double ths[4] = {th1, th2, -th1, -th2}, as[4] = {a, b, a, b}, als[4] = {alpha, beta, alpha, beta};
    double T[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}, Ti[12];
    for (int k = 0; k < 4; k++) {
        o[k] = (mm_v3){T[3], T[7], T[11]};
        z[k] = (mm_v3){T[2], T[6], T[10]};
        mm_geom_dh(ths[k], as[k], als[k], Ti);
        mm_geom_frame_mul(T, Ti, T);
    }
    double e = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            e = fmax(e, fabs(T[4 * i + j] - (i == j)));
    *gap = e;
}

/* ==== the quick-return mechanism (crank and slotted lever), added for kin-quick-return ==== */

mm_qr_pos mm_linkage_qr_closed(const mm_quick_return *m, double th)
{
    mm_qr_pos p;
    double c = cos(th), s = sin(th), N = m->r * c, D = m->d + m->r * s, q = N * N + D * D;
    p.t4 = atan2(D, N);
    p.t4p = m->r * (m->r + m->d * s) / q;                               /* d/dth2 of atan2(D, N) */
    double qp = 2 * m->d * m->r * c;                                      /* dq/dth2 */
    p.t4pp = (m->r * m->d * c * q - m->r * (m->r + m->d * s) * qp) / (q * q);
    p.X = m->H * N / D;
    p.Xp = -m->H * m->r * (m->d * s + m->r) / (D * D);
    p.Xpp = -m->H * m->r * c * (m->d * D - 2 * m->r * (m->d * s + m->r)) / (D * D * D);
    return p;
}

static int qr_phi(const double *q, double t, double *F, void *ctx)
{
    const mm_quick_return *m = ctx;
    double c4 = cos(q[0]), s4 = sin(q[0]);
    F[0] = q[1] * c4 - m->r * cos(t);
    F[1] = q[1] * s4 - m->d - m->r * sin(t);
    F[2] = q[3] * c4 - q[2];
    F[3] = q[3] * s4 - m->H;
    return 0;
}

static int qr_jac(const double *q, double t, double *J, void *ctx)
{
    (void)t, (void)ctx;
    double c4 = cos(q[0]), s4 = sin(q[0]);
    double Jv[16] = {-q[1] * s4, c4, 0, 0, q[1] * c4, s4, 0, 0, -q[3] * s4, 0, -1, c4, q[3] * c4, 0, 0, s4};
    memcpy(J, Jv, sizeof Jv);
    return 0;
}

static int qr_nu(const double *q, double t, double *nu, void *ctx)
{
    (void)q;
    const mm_quick_return *m = ctx;
    nu[0] = -m->r * sin(t), nu[1] = m->r * cos(t), nu[2] = nu[3] = 0;
    return 0;
}

static int qr_gamma(const double *q, const double *qd, double t, double *g, void *ctx)
{
    const mm_quick_return *m = ctx;
    double c4 = cos(q[0]), s4 = sin(q[0]), w = qd[0];
    g[0] = 2 * qd[1] * s4 * w + q[1] * c4 * w * w - m->r * cos(t);
    g[1] = -2 * qd[1] * c4 * w + q[1] * s4 * w * w - m->r * sin(t);
    g[2] = 2 * qd[3] * s4 * w + q[3] * c4 * w * w;
    g[3] = -2 * qd[3] * c4 * w + q[3] * s4 * w * w;
    return 0;
}

static const unsigned char qr_is_length[4] = {0, 1, 1, 1};

void mm_linkage_qr_problem(const mm_quick_return *m, mm_mech_problem *prob)
{
    *prob = (mm_mech_problem){.n = 4, .m = 4, .phi = qr_phi, .jac = qr_jac, .nu = qr_nu, .gamma = qr_gamma,
                              .is_length = qr_is_length, .params = (void *)m};
}

void mm_linkage_qr_guess(const mm_quick_return *m, double th, double *q)
{
    mm_qr_pos p = mm_linkage_qr_closed(m, th);
    q[0] = p.t4 + 0.01, q[1] = hypot(m->r * cos(th), m->d + m->r * sin(th)) * 1.01;   /* a rough guess */
    q[2] = p.X * 0.99, q[3] = m->H / sin(p.t4) * 1.01;
}
