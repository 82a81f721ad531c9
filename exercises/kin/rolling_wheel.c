/* rolling_wheel.c — kin-rolling-wheel: a wheel of radius R rolls without
 * slipping along the ground; it has turned through phi(t) = omega t +
 * alpha t^2/2, and P is a point at distance b from its centre, at the
 * bottom at t = 0.
 *
 *     O = (R phi, R),  P = O + b (-sin phi, -cos phi)                       (1)
 *     v_P = phi' (R - b cos phi, b sin phi)                                  (2)
 *     a_P = phi'' (R - b cos phi, b sin phi) + phi'^2 (b sin phi, b cos phi) (3)
 *
 * Goal: rolling without slipping means the contact point is at rest: it is
 * the instantaneous centre, every point moves square to the line joining
 * it to the contact point with speed |phi'| times that distance, and the
 * contact point itself accelerates upward at R phi'^2.  A rim point traces
 * a cycloid (b = R), an inner point a curtate, an outer one (a flange) a
 * prolate trochoid.
 * Checks: (2)-(3) against central differences of (1); |v_P| against
 * |phi'| |P C|; the contact point's velocity computed as a point of the
 * wheel (exactly zero); the path's radius of curvature against the circle
 * through three close points; the length of one arch by Gauss-Legendre
 * quadrature against its closed form 4 (R + b) E(k) (8R for the cycloid).
 * Reference: F. P. Beer, E. R. Johnston, Vector Mechanics for Engineers:
 * Dynamics, sections 15.6-15.7 (instantaneous centre, rolling).
 */
#include <float.h>
#include <math.h>

#include "mm_elliptic.h"
#include "mm_geom.h"
#include "mm_kin.h"
#include "mm_scene.h"

enum { P_R, P_B, P_W, P_AL, P_T, P_TEND, P_POINTS };

static const mm_param params[] = {
    [P_R] = {"R", "wheel radius", "m", MM_REAL, 0.5, 1e-3, 10, .help = "the radius that rolls on the ground"},
    [P_B] = {"b", "distance of P from the centre", "m", MM_REAL, 0.5, 0, 10,
             .help = "b = R: a point of the rim (cycloid); b < R inside; b > R on a flange"},
    [P_W] = {"omega", "angular velocity at t = 0", "rad/s", MM_REAL, 2, -100, 100,
             .help = "positive: rolling to the right (turning clockwise)"},
    [P_AL] = {"alpha", "angular acceleration", "rad/s^2", MM_REAL, 0, -100, 100, .help = "constant"},
    [P_T] = {"t", "instant", "s", MM_REAL, 1, 0, 10, .help = "the time at which the answers are given (at most t_end)"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 3.2, 0.01, 10, .help = "the motion plotted and animated"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 301, 11, 2001, .help = "samples of the plotted curves"},
};

enum {
    O_VO, O_X, O_Y, O_VX, O_VY, O_V, O_AX, O_AY, O_A, O_VC, O_AC, O_RHO, O_RHOTOP, O_ARC,
    O_PATH, O_SV, O_SA, O_FDV, O_FDA, O_ANIM
};

static const mm_output outputs[] = {
    [O_VO] = MM_SCALAR("v_O", "speed of the centre R phi'", "m/s", .flags = MM_ANSWER | MM_EXACT),
    [O_X] = MM_SCALAR("x", "position of P, x", "m", .flags = MM_EXACT),
    [O_Y] = MM_SCALAR("y", "position of P, y (height)", "m", .flags = MM_EXACT),
    [O_VX] = MM_SCALAR("vx", "velocity of P, x", "m/s", .flags = MM_EXACT),
    [O_VY] = MM_SCALAR("vy", "velocity of P, y", "m/s", .flags = MM_EXACT),
    [O_V] = MM_SCALAR("v", "speed of P", "m/s", .flags = MM_ANSWER | MM_EXACT),
    [O_AX] = MM_SCALAR("ax", "acceleration of P, x", "m/s^2", .flags = MM_EXACT),
    [O_AY] = MM_SCALAR("ay", "acceleration of P, y", "m/s^2", .flags = MM_EXACT),
    [O_A] = MM_SCALAR("a", "magnitude of P's acceleration", "m/s^2", .flags = MM_ANSWER | MM_EXACT),
    [O_VC] = MM_SCALAR("v_contact", "speed of the wheel's point in contact with the ground", "m/s",
                       .flags = MM_ANSWER | MM_EXACT),
    [O_AC] = MM_SCALAR("a_contact", "acceleration of that point (upward, R phi'^2)", "m/s^2", .flags = MM_ANSWER | MM_EXACT),
    [O_RHO] = MM_SCALAR("rho", "radius of curvature of P's path at t", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_RHOTOP] = MM_SCALAR("rho_top", "radius of curvature of P's path at the top, (R + b)^2 / b", "m",
                           .flags = MM_EXACT),
    [O_ARC] = MM_SCALAR("arch_length", "length of P's path over one turn, 4 (R + b) E(k)", "m",
                        .flags = MM_ANSWER | MM_EXACT),
    [O_PATH] = MM_SERIES("path", "path of P", "m", "x", "m", .aspect = "equal", .figure = "path"),
    [O_SV] = MM_SERIES("v", "speed of P", "m/s", "t", "s", .figure = "speed"),
    [O_SA] = MM_SERIES("a", "acceleration of P", "m/s^2", "t", "s", .figure = "acceleration"),
    [O_FDV] = MM_KIN_FD_SERIES("fd_error_v", "worst error of the central difference of P vs eq. (2)", "m/s", "s"),
    [O_FDA] = MM_KIN_FD_SERIES("fd_error_a", "worst error of the second difference vs eq. (3)", "m/s^2", "s"),
    [O_ANIM] = MM_ANIMATION("the wheel rolling, P's path, velocity and acceleration, the contact point"),
};

typedef struct wheel {
    double R, b, w, al;
} wheel;

typedef struct wstate {
    double phi, w, al;
    mm_v2 O, P, v, a;
} wstate;

static wstate at(const wheel *m, double t)
{
    wstate s;
    s.phi = m->w * t + 0.5 * m->al * t * t, s.w = m->w + m->al * t, s.al = m->al;
    double c = cos(s.phi), sn = sin(s.phi);
    mm_v2 g = {m->R - m->b * c, m->b * sn};                         /* dP/dphi */
    s.O = (mm_v2){m->R * s.phi, m->R};
    s.P = (mm_v2){s.O.x - m->b * sn, s.O.y - m->b * c};             /* eq. (1) */
    s.v = mm_v2_scale(g, s.w);                                       /* eq. (2) */
    s.a = mm_v2_add(mm_v2_scale(g, s.al), mm_v2_scale((mm_v2){m->b * sn, m->b * c}, s.w * s.w));   /* (3) */
    return s;
}

static int check(const mm_value *in, mm_error *err)
{
    return mm_kin_check_t(in[P_T].x, in[P_TEND].x, err);
}

/* P(phi + e) - P(phi), for mm_kin_circle3: by differences that keep their digits */
static int point(double phi, double e, mm_v2 *P, void *ctx)
{
    const wheel *m = ctx;
    double s2 = 2 * sin(0.5 * e);
    *P = e == 0 ? (mm_v2){0, 0} : (mm_v2){m->R * e - m->b * cos(phi + 0.5 * e) * s2, m->b * sin(phi + 0.5 * e) * s2};
    return 1;
}

/* the animation's frame at t */
static void frame(double t, mm_kin_wheel_state *k, void *ctx)
{
    wstate s = at(ctx, t);
    *k = (mm_kin_wheel_state){s.phi, s.w, s.O, s.P, s.v, s.a};
}

static int fd_pos(double ts, double h, double *q, double *qerr, void *ctx, mm_error *err)
{
    (void)err;
    const wheel *m = ctx;
    double t = ts + h;
    wstate s = at(m, t);
    q[0] = s.P.x, q[1] = s.P.y;
    double dphi = 4 * DBL_EPSILON * (fabs(m->w * t) + fabs(m->al * t * t));
    *qerr = (m->R + m->b) * (dphi + 4 * DBL_EPSILON * (1 + fabs(s.phi)));
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    wheel m = {in[P_R].x, in[P_B].x, in[P_W].x, in[P_AL].x};
    const double t = in[P_T].x, t_end = in[P_TEND].x;
    const int n = (int)in[P_POINTS].x;

    /* ---- at t ---- */
    wstate s = at(&m, t);
    mm_res_scalar(res, O_VO, s.w * m.R);
    mm_res_scalar(res, O_X, s.P.x), mm_res_scalar(res, O_Y, s.P.y);
    mm_res_scalar(res, O_VX, s.v.x), mm_res_scalar(res, O_VY, s.v.y), mm_res_scalar(res, O_V, mm_v2_norm(s.v));
    mm_res_scalar(res, O_AX, s.a.x), mm_res_scalar(res, O_AY, s.a.y), mm_res_scalar(res, O_A, mm_v2_norm(s.a));
    /* the contact point C = (R phi, 0) as a point of the wheel: v_O + w x (C - O)
     * with w = -phi' k (clockwise), C - O = (0, -R); the two products are the
     * same numbers, so the difference is exactly 0 */
    mm_v2 vO = {s.w * m.R, 0}, CO = {0, -m.R};
    mm_v2 vC = mm_v2_add(vO, mm_v2_scale(mm_v2_perp(CO), -s.w));
    mm_v2 aC = mm_v2_add(mm_v2_add((mm_v2){s.al * m.R, 0}, mm_v2_scale(mm_v2_perp(CO), -s.al)),
                         mm_v2_scale(CO, -s.w * s.w));
    mm_res_scalar(res, O_VC, mm_v2_norm(vC));
    mm_res_scalar(res, O_AC, aC.y);
    mm_res_check_abs(res, "contact point's velocity as a point of the wheel: exactly 0 (rolling without slip)",
                     mm_v2_norm(vC), 0, 0);
    mm_res_check_abs(res, "contact point's acceleration: horizontal part exactly 0", aC.x, 0, 0);
    /* |v_P| = |phi'| |P C|: the instantaneous centre is the contact point */
    mm_v2 C = {m.R * s.phi, 0};
    double big = fabs(s.w) * (m.R + m.b) * (1 + fabs(s.phi));
    mm_res_check_abs(res, "|v_P| by eq. (2) vs |phi'| |PC| (instantaneous centre C) [m/s]", mm_v2_norm(s.v),
                     fabs(s.w) * mm_v2_norm(mm_v2_sub(s.P, C)), 16 * DBL_EPSILON * big);
    if (m.b > 0)
        mm_res_scalar(res, O_RHOTOP, (m.R + m.b) * (m.R + m.b) / m.b);
    /* the radius of curvature is the path's, a property of P(phi) alone:
     *     rho = |g|^3 / |g x g'| = |g|^3 / (b |R cos phi - b|),  g = dP/dphi   (R)
     * and |v|^3 / |v x a| = |phi'|^3 |g|^3 / |phi'^3 g x g'| is the same
     * number, but computed from (2)-(3) it subtracts phi' phi'' g x g (zero)
     * from itself: when phi'^2 is small beside |phi''| the rounding of that
     * zero swamps phi'^3 g x g' (at phi' = 0 it is 0 / 0), so (R) is the
     * answer and the kinematic formula is checked against it */
    double c = cos(s.phi), sn = sin(s.phi), cb = m.R * c - m.b;
    mm_v2 g = {m.R - m.b * c, m.b * sn};
    double gn = mm_v2_norm(g);
    if (m.b > 0 && cb != 0 && gn > 0) {
        double rho = gn * gn * gn / (m.b * fabs(cb));
        mm_res_scalar(res, O_RHO, rho);
        double cr = fabs(mm_v2_cross(s.v, s.a)), sp = mm_v2_norm(s.v), an = mm_v2_norm(s.a);
        /* the rounding of v x a: v and a carry eps (R + b) |phi'| and eps (R + b) |a| / |g|
         * of error (g to eps (R + b)), and g x g' = b (R cos phi - b) to eps (R + b)^2 */
        if (cr > 0 && sp > 0)
            mm_res_check_abs(res, "rho = |v|^3 / |v x a| from eqs. (2)-(3) vs |g|^3 / (b |R cos phi - b|), bound: the rounding of the "
                                  "cross product and of g x g'", sp * sp * sp / cr, rho,
                             4 * DBL_EPSILON * rho *
                                 (1 + (m.R + m.b) * fabs(s.w) * an / cr + (m.R + m.b) * (m.R + m.b) / (m.b * fabs(cb))));
        /* the circle through P(phi - d), P(phi), P(phi + d): O(d), the value at
         * d/4 within 2 |R(d/2) - R(d/4)| plus rounding.  The asymptotic regime
         * needs d small beside the scale on which the curvature k changes:
         * beside rho / |g| (a cusp), the distance |k / k'| to an inflection
         * (b < R: k = 0 where cos phi = b/R, and there rho -> infinity),
         * and the period 2 pi.  With k = b (R cos phi - b) / q^(3/2),
         * q = |g|^2 = R^2 + b^2 - 2 R b cos phi,
         *     k' = dk/dphi = -R b sin phi (q + 3 b (R cos phi - b)) / q^(5/2)
         * so k / k' = -(R cos phi - b) q / (R sin phi (q + 3 b (R cos phi - b))).
         * The points are taken relative to P(phi), by differences that keep
         * their digits: P(phi + e) - P(phi) = (R e - 2 b cos(phi + e/2) sin(e/2),
         * 2 b sin(phi + e/2) sin(e/2)) */
        double q = gn * gn, kd = m.R * sn * (q + 3 * m.b * cb), lk = kd != 0 ? fabs(cb * q / kd) : INFINITY;
        double d = 0.02 * fmin(fmin(rho / gn, lk), 2), R3[3];
        int ok = mm_kin_circle3(point, &m, s.phi, d, R3);
        /* rounding: the points at e = d/4 to a few eps |e| (R + b (1 + |phi|)) (the
         * last from the argument phi + e/2), the sagitta ds^2 / (2 rho) of the
         * chord ds = |g| d/4, so rho to 2 rho^2 / ds^2 times that (and the
         * circle's own rounding, eps rho^2 / ds, is smaller) */
        double ds = gn * d / 4, rnd = 8 * DBL_EPSILON * (m.R + m.b * (1 + fabs(s.phi))) * d * rho * rho / (ds * ds);
        if (ok)
            mm_res_check_abs(res, "rho = |g|^3 / (b |R cos phi - b|) vs the circle through three points of the path", R3[2], rho,
                             2 * fabs(R3[1] - R3[2]) + rnd);
    }
    /* one arch: 4 (R + b) E(k), k^2 = 4 R b / (R + b)^2 (8 R for b = R) */
    if (m.b > 0) {
        double k = 2 * sqrt(m.R * m.b) / (m.R + m.b), L = 4 * (m.R + m.b) * mm_elliptic_E(k);
        if (m.b == m.R)
            L = 8 * m.R;
        mm_res_scalar(res, O_ARC, L);
        /* the bound sums |Q(2n) - Q(n)| + 2 |Q(4n) - Q(2n)| panel by panel:
         * the panels' errors have either sign, and the difference of the
         * totals can vanish by their cancelling; and on one panel two rules
         * can err alike by chance (mm_geom_trochoid_arch) */
        double qe, q2 = mm_geom_trochoid_arch(m.R, m.b, &qe);
        mm_res_check_abs(res, "arch length: Gauss-Legendre on halving panels vs 4 (R + b) E(k), bound the sum over the panels "
                              "of |Q(2n) - Q(n)| + 2 |Q(4n) - Q(2n)|, + rounding",
                         q2, L, qe + 64 * DBL_EPSILON * L);
    } else {
        mm_res_scalar(res, O_ARC, 2 * M_PI * m.R);
    }

    /* ---- over [0, t_end] ---- */
    mm_series *path = mm_res_series(res, O_PATH, n), *sv = mm_res_series(res, O_SV, n), *sa = mm_res_series(res, O_SA, n);
    mm_kin_samples smp;
    if (!path || !sv || !sa || mm_kin_samples_init(&smp, res, n, 2, err) != MM_OK)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_kin_grid(0, t_end, n, sv->x);
    double vmax = 0, amax = 0;
    for (int i = 0; i < n; i++) {
        wstate si = at(&m, sv->x[i]);
        path->x[i] = si.P.x, path->y[i] = si.P.y;
        sa->x[i] = sv->x[i];
        sv->y[i] = mm_v2_norm(si.v), sa->y[i] = mm_v2_norm(si.a);
        vmax = fmax(vmax, fmax(sv->y[i], 2 * fabs(si.w) * m.R)), amax = fmax(amax, sa->y[i]);
        mm_kin_sample2(&smp, i, sv->x[i], si.v, si.a);
    }
    double wm = fmax(fabs(m.w), fabs(m.w + m.al * t_end)), h0 = 0.05 / fmax(1, wm);
    int rc = mm_kin_fd_samples(res, O_FDV, O_FDA, "dP/dt", "d2P/dt2", fd_pos, &m, &smp, h0, err);
    if (rc != MM_OK)
        return rc;

    /* ---- the animation ---- */
    double t_show;
    int nf = mm_scene_frames(t_end, wm > 0 ? 2 * M_PI / wm : 0, &t_show);
    mm_res_method(res, "closed form, checked by central differences; arch length by Gauss-Legendre and the AGM", 0);
    return mm_kin_anim_wheel(res, nf, t_show, m.R, m.b, vmax, amax, frame, &m, err);
}

static const char *const references[] = {
    "F. P. Beer, E. R. Johnston, Vector Mechanics for Engineers: Dynamics, 9th ed., sections 15.6-15.7",
    "M. Abramowitz, I. A. Stegun, Handbook of Mathematical Functions, 17.6 (E(k) by the AGM)", NULL,
};

const mm_exercise mm_ex_kin_rolling_wheel = {
    .id = "kin-rolling-wheel", .chapter = 2, .section = "2.3.5",
    .title = "Rolling without slipping: the cycloid",
    .summary = "A rolling wheel: the contact point at rest as instantaneous centre, the velocity and "
               "acceleration of any point, the cycloid's curvature and length.",
    .tags = "kinematics, rigid body, rolling, cycloid, trochoid, instantaneous centre",
    .theory = "exercises/kin/rolling_wheel.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
