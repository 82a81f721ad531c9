/* rotation_plane.c — kin-rotation-plane: a point moving about a fixed
 * point O in a plane, in polar coordinates: an arm turns through
 * theta(t) = theta0 + omega0 t + alpha t^2/2 while the point slides along
 * it, r(t) = r0 + u t + b t^2/2.
 *
 *     v = r' e_r + r theta' e_theta                                         (2)
 *     a = (r'' - r theta'^2) e_r + (r theta'' + 2 r' theta') e_theta           (3)
 *
 * Goal: the radial and transverse components of velocity and acceleration,
 * the centripetal term -r theta'^2 and the Coriolis term 2 r' theta', and
 * their special case, circular motion (u = b = 0): v = r omega,
 * a_t = r alpha, a_n = r omega^2.
 * Checks: (2)-(3) against the Cartesian derivatives of x = r cos theta,
 * y = r sin theta (the chain rule done the other way round), against
 * central differences of the position (error against the step, order 2),
 * and the path's radius of curvature |v|^3 / |v x a| against the circle
 * through three close points of the path.
 * Reference: F. P. Beer, E. R. Johnston, Vector Mechanics for Engineers:
 * Dynamics, section 11.14 (radial and transverse components).
 */
#include <float.h>
#include <math.h>

#include "mm_dd.h"
#include "mm_errbound.h"
#include "mm_exhelp.h"
#include "mm_geom.h"
#include "mm_kin.h"
#include "mm_scene.h"

enum { P_R0, P_U, P_B, P_TH0, P_W0, P_AL, P_T, P_TEND, P_POINTS };

static const mm_param params[] = {
    [P_R0] = {"r0", "distance from O at t = 0", "m", MM_REAL, 0.5, -10, 10, .help = "r(0); r may pass through O"},
    [P_U] = {"u", "radial speed at t = 0", "m/s", MM_REAL, 0, -10, 10,
             .help = "r'(0): the point sliding out along the arm (0: circular motion)"},
    [P_B] = {"b", "radial acceleration", "m/s^2", MM_REAL, 0, -10, 10, .help = "r'', constant"},
    [P_TH0] = {"theta0", "angle at t = 0", "rad", MM_REAL, 0, -10, 10, .help = "theta(0) from the x axis"},
    [P_W0] = {"omega0", "angular velocity at t = 0", "rad/s", MM_REAL, 2, -20, 20, .help = "theta'(0)"},
    [P_AL] = {"alpha", "angular acceleration", "rad/s^2", MM_REAL, 0.5, -20, 20, .help = "theta'', constant"},
    [P_T] = {"t", "instant", "s", MM_REAL, 1, 0, 10, .help = "the time at which the answers are given (at most t_end)"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 3, 0.01, 10, .help = "the motion plotted and animated from t = 0"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 301, 11, 2001, .help = "samples of the plotted curves"},
};

enum {
    O_R, O_TH, O_VR, O_VT, O_V, O_AR, O_AT, O_A, O_CENT, O_COR, O_ATAN, O_ANOR, O_RHO,
    O_PATH, O_SV, O_SAR, O_SAT, O_FDV, O_FDA, O_ANIM
};

static const mm_output outputs[] = {
    [O_R] = MM_SCALAR("r", "distance from O", "m", .flags = MM_EXACT),
    [O_TH] = MM_SCALAR("theta", "angle", "rad", .flags = MM_EXACT),
    [O_VR] = MM_SCALAR("v_r", "radial velocity r'", "m/s", .flags = MM_ANSWER | MM_EXACT),
    [O_VT] = MM_SCALAR("v_theta", "transverse velocity r theta'", "m/s", .flags = MM_ANSWER | MM_EXACT),
    [O_V] = MM_SCALAR("v", "speed", "m/s", .flags = MM_ANSWER | MM_EXACT),
    [O_AR] = MM_SCALAR("a_r", "radial acceleration r'' - r theta'^2", "m/s^2", .flags = MM_ANSWER | MM_EXACT),
    [O_AT] = MM_SCALAR("a_theta", "transverse acceleration r theta'' + 2 r' theta'", "m/s^2", .flags = MM_ANSWER | MM_EXACT),
    [O_A] = MM_SCALAR("a", "magnitude of the acceleration", "m/s^2", .flags = MM_ANSWER | MM_EXACT),
    [O_CENT] = MM_SCALAR("a_centripetal", "centripetal term -r theta'^2", "m/s^2", .flags = MM_EXACT),
    [O_COR] = MM_SCALAR("a_coriolis", "Coriolis term 2 r' theta'", "m/s^2", .flags = MM_EXACT),
    [O_ATAN] = MM_SCALAR("a_t", "tangential acceleration dv/dt", "m/s^2", .flags = MM_EXACT),
    [O_ANOR] = MM_SCALAR("a_n", "normal acceleration v^2/rho", "m/s^2", .flags = MM_EXACT),
    [O_RHO] = MM_SCALAR("rho", "radius of curvature of the path", "m", .flags = MM_EXACT),
    [O_PATH] = MM_SERIES("path", "path of the point", "m", "x", "m", .aspect = "equal", .figure = "path"),
    [O_SV] = MM_SERIES("v", "speed", "m/s", "t", "s", .figure = "speed"),
    [O_SAR] = MM_SERIES("a_r", "radial acceleration", "m/s^2", "t", "s", .figure = "acceleration components"),
    [O_SAT] = MM_SERIES("a_theta", "transverse acceleration", "m/s^2", "t", "s", .figure = "acceleration components"),
    [O_FDV] = MM_KIN_FD_SERIES("fd_error_v", "worst error of the central difference of (x, y) vs v", "m/s", "s"),
    [O_FDA] = MM_KIN_FD_SERIES("fd_error_a", "worst error of the second difference vs a", "m/s^2", "s"),
    [O_ANIM] = MM_ANIMATION("the arm turning about O with the point on it, its velocity and acceleration"),
};

typedef struct polar {
    double r0, u, b, th0, w0, al;
} polar;

typedef struct state {
    double r, r1, r2, th, th1, th2;
} state;

static state at(const polar *p, double t)
{
    return (state){p->r0 + p->u * t + 0.5 * p->b * t * t, p->u + p->b * t, p->b,
                   p->th0 + p->w0 * t + 0.5 * p->al * t * t, p->w0 + p->al * t, p->al};
}

/* eqs. (2)-(3) in polar components, and the Cartesian x, v, a they give */
static void kin(const state *s, mm_v2 *x, mm_v2 *v, mm_v2 *a, double *vr, double *vt, double *ar, double *at_)
{
    mm_v2 er = mm_v2_polar(1, s->th), et = mm_v2_perp(er);
    *vr = s->r1, *vt = s->r * s->th1;
    *ar = s->r2 - s->r * s->th1 * s->th1, *at_ = s->r * s->th2 + 2 * s->r1 * s->th1;
    *x = mm_v2_scale(er, s->r);
    *v = mm_v2_add(mm_v2_scale(er, *vr), mm_v2_scale(et, *vt));
    *a = mm_v2_add(mm_v2_scale(er, *ar), mm_v2_scale(et, *at_));
}

/* the other way round: differentiate x = r cos th, y = r sin th directly */
static void cartesian(const state *s, mm_v2 *v, mm_v2 *a)
{
    double c = cos(s->th), sn = sin(s->th), w = s->th1;
    v->x = s->r1 * c - s->r * w * sn;
    v->y = s->r1 * sn + s->r * w * c;
    a->x = s->r2 * c - 2 * s->r1 * w * sn - s->r * s->th2 * sn - s->r * w * w * c;
    a->y = s->r2 * sn + 2 * s->r1 * w * c + s->r * s->th2 * c - s->r * w * w * sn;
}

/* ---- the answers at t: in double-double, each with a bound of its error ----
 * Near an inflection v x a = v_r a_theta - v_theta a_r is a small
 * difference of large products, and a_r, a_theta, r, r' themselves may be
 * differences: in double, a_n and rho lost about |v| |a| / |v x a| ulps
 * (280 ulps of rho where that is 286, 7.6e6 ulps of a_n at 3.8e6, a_n 3.5
 * times too large at 3.2e16, each printed as exact).  In double-double from the parameters (exact
 * doubles) they keep ~32 digits, and a running error analysis says how
 * many (mm_ddb, solvers/mm_dd.h: each operation adds its own rounding to
 * its operands' errors). */
typedef struct state_dd {
    mm_ddb r, r1, r2, th, th1, th2;
} state_dd;

/* c0 + c1 t, and c0 + c1 t + c2 t^2 / 2 */
static mm_ddb linear(double c0, double c1, mm_ddb T)
{
    return mm_ddb_add(mm_ddb_exact(c0), mm_ddb_mul(mm_ddb_exact(c1), T));
}

static mm_ddb quadratic(double c0, double c1, double c2, mm_ddb T)
{
    return mm_ddb_add(linear(c0, c1, T), mm_ddb_scale2(mm_ddb_mul(mm_ddb_exact(c2), mm_ddb_mul(T, T)), 0.5));
}

static state_dd at_dd(const polar *p, double t)
{
    mm_ddb T = mm_ddb_exact(t);
    return (state_dd){quadratic(p->r0, p->u, p->b, T), linear(p->u, p->b, T), mm_ddb_exact(p->b),
                      quadratic(p->th0, p->w0, p->al, T), linear(p->w0, p->al, T), mm_ddb_exact(p->al)};
}

/* eqs. (2)-(3) and the path's v x a and v . a, from a state in double-double */
typedef struct polar_dd {
    mm_ddb vr, vt, ar, at, cent, cor, v, a, cr, dot;
} polar_dd;

static mm_ddb cross(mm_ddb ax, mm_ddb ay, mm_ddb bx, mm_ddb by)
{
    return mm_ddb_sub(mm_ddb_mul(ax, by), mm_ddb_mul(ay, bx));
}

static mm_ddb dot(mm_ddb ax, mm_ddb ay, mm_ddb bx, mm_ddb by)
{
    return mm_ddb_add(mm_ddb_mul(ax, bx), mm_ddb_mul(ay, by));
}

static polar_dd kin_dd(const state_dd *s)
{
    polar_dd k;
    k.vr = s->r1, k.vt = mm_ddb_mul(s->r, s->th1);
    k.cent = mm_ddb_scale2(mm_ddb_mul(s->r, mm_ddb_mul(s->th1, s->th1)), -1);     /* -r theta'^2 */
    k.cor = mm_ddb_scale2(mm_ddb_mul(s->r1, s->th1), 2);                           /* 2 r' theta' */
    k.ar = mm_ddb_add(s->r2, k.cent), k.at = mm_ddb_add(mm_ddb_mul(s->r, s->th2), k.cor);
    k.v = mm_ddb_norm(k.vr, k.vt), k.a = mm_ddb_norm(k.ar, k.at);
    k.cr = cross(k.vr, k.vt, k.ar, k.at), k.dot = dot(k.vr, k.vt, k.ar, k.at);
    return k;
}

/* a scalar rounded to double: exact while it is within an ulp of the exact
 * value (its bound within half an ulp), else with its bound */
static double put(mm_result *res, int o, mm_ddb v, double *bound)
{
    double e, x = mm_ddb_round(v, &e);
    if (v.e <= 0.5 * mm_errbound_ulp(x))
        mm_res_scalar(res, o, x);
    else
        mm_res_scalar_err(res, o, x, e, MM_ERR_BOUND);
    if (bound)
        *bound = e;
    return x;
}

static int check(const mm_value *in, mm_error *err)
{
    return mm_kin_check_t(in[P_T].x, in[P_TEND].x, err);
}

/* the point at t + e less the point at t, for mm_kin_circle3, in the frame
 * of theta(t) (rho does not depend on it) and from the same rounded r, r',
 * r'', theta', theta'' as eqs. (2)-(3): r(t + e) = r + dr, theta(t + e) =
 * theta + dth with dr = e (r' + r'' e/2), dth = e (theta' + theta'' e/2), so
 *     P(t + e) - P(t) = (dr cos dth - 2 r sin^2(dth/2), (r + dr) sin dth)
 * keeps its digits: no theta of up to 10^3 rad nor |x| rounded into it;
 * *err gets a bound of its rounding, componentwise */
static mm_v2 point_err(const state *s, double e, mm_v2 *err)
{
    const double u = DBL_EPSILON / 2;
    double q = 0.5 * s->r2 * e, w = s->r1 + q, dr = e * w;
    double qt = 0.5 * s->th2 * e, wt = s->th1 + qt, dth = e * wt;
    double sh = sin(0.5 * dth), cd = cos(dth), sd = sin(dth);
    mm_v2 P = {dr * cd - 2 * s->r * sh * sh, (s->r + dr) * sd};
    /* its rounding, each operation's u of its result carried through (s
     * taken as exact; sin and cos within an ulp, 2u, and moved by dth's
     * error at a slope of at most 1) */
    double e_dr = fabs(e) * u * (fabs(q) + fabs(w)) + u * fabs(dr);
    double e_dth = fabs(e) * u * (fabs(qt) + fabs(wt)) + u * fabs(dth);
    double e_sh = 0.5 * e_dth + 2 * u * fabs(sh), e_cd = e_dth + 2 * u * fabs(cd), e_sd = e_dth + 2 * u * fabs(sd);
    double t1 = dr * cd, x2 = 2 * s->r * sh, t2 = x2 * sh, rr = s->r + dr;
    double e_t1 = fabs(dr) * e_cd + fabs(cd) * e_dr + e_dr * e_cd + u * fabs(t1);
    double e_x2 = 2 * fabs(s->r) * e_sh + u * fabs(x2);
    double e_t2 = fabs(x2) * e_sh + fabs(sh) * e_x2 + e_x2 * e_sh + u * fabs(t2);
    double e_rr = e_dr + u * fabs(rr);
    *err = (mm_v2){e_t1 + e_t2 + u * fabs(P.x), fabs(rr) * e_sd + fabs(sd) * e_rr + e_rr * e_sd + u * fabs(P.y)};
    return P;
}

static int point(double t, double e, mm_v2 *P, void *ctx)
{
    (void)t;
    mm_v2 err;
    *P = point_err(ctx, e, &err);
    return 1;
}

/* a bound of the rounding of mm_kin_circle3's R at step h (the circle
 * through the points at -h, 0, h), the state taken as exact */
static double circle_err(const state *s, double h)
{
    mm_v2 Em, E0, Ep, Pm = point_err(s, -h, &Em), P0 = point_err(s, 0, &E0), Pp = point_err(s, h, &Ep);
    return mm_geom_circumradius_err(Pm, P0, Pp, Em, E0, Ep);
}

/* The step of the three-point circle.  Its curvature is even in h,
 *     k(h) = k + C2 h^2 + O(h^4),
 * and with the Taylor coefficients Z1 = v, Z2 = a/2, Z3, Z4 of the path
 * about t (P(t + e) - P(t) = Z1 e + Z2 e^2 + ...), T = Z1/|v| and x, y
 * the components along T and across it,
 *     C2 = 2/|v|^2 (y4 - (x2 y3 + 2 x3 y2)/|v| + y2 (x2^2 - y2^2)/|v|^2)
 * (0 on a circle run at constant speed).  R(h) = 1/|k(h)| is a series in
 * h^2 only while h is small beside the scales of the motion: rho/|v| (a
 * radian of turn), |Z1/Zk|^(1/(k-1)) (the speed or the direction changing,
 * a cusp) and sqrt|k/C2| (an inflection within reach: k(h) reaches 0 there,
 * however large rho/|v| is).  In the frame of theta(t), z = r e^(i theta):
 * E = e^(i dth) has E0 = 1, Ek = i (theta' E(k-1) + theta'' E(k-2)) / k,
 * and Zk = r Ek + r' E(k-1) + r''/2 E(k-2). */
static double circle_step(const state *s, double speed, double k)
{
    mm_v2 E[5] = {{1, 0}}, Z[5];
    for (int j = 1; j < 5; j++) {
        mm_v2 w = mm_v2_scale(E[j - 1], s->th1);
        if (j >= 2)
            w = mm_v2_add(w, mm_v2_scale(E[j - 2], s->th2));
        E[j] = mm_v2_scale(mm_v2_perp(w), 1.0 / j);
        Z[j] = mm_v2_add(mm_v2_scale(E[j], s->r), mm_v2_scale(E[j - 1], s->r1));
        if (j >= 2)
            Z[j] = mm_v2_add(Z[j], mm_v2_scale(E[j - 2], 0.5 * s->r2));
    }
    mm_v2 T = mm_v2_scale(Z[1], 1 / speed);
    double x2 = mm_v2_dot(T, Z[2]), y2 = mm_v2_cross(T, Z[2]), x3 = mm_v2_dot(T, Z[3]), y3 = mm_v2_cross(T, Z[3]);
    double y4 = mm_v2_cross(T, Z[4]);
    double C2 = 2 / (speed * speed) * (y4 - (x2 * y3 + 2 * x3 * y2) / speed + y2 * (x2 * x2 - y2 * y2) / (speed * speed));
    double scale = 1 / (speed * fabs(k));
    for (int j = 2; j < 5; j++) {
        double zj = mm_v2_norm(Z[j]);
        if (zj > 0)
            scale = fmin(scale, pow(speed / zj, 1.0 / (j - 1)));
    }
    if (C2 != 0)
        scale = fmin(scale, sqrt(fabs(k / C2)));
    return 0.02 * scale;
}

/* the animation's frame at t */
static void frame(double t, mm_kin_arm_state *k, void *ctx)
{
    state s = at(ctx, t);
    double a1, a2, a3, a4;
    k->th = s.th;
    kin(&s, &k->x, &k->v, &k->a, &a1, &a2, &a3, &a4);
}

static int fd_pos(double ts, double h, double *q, double *qerr, void *ctx, mm_error *err)
{
    (void)err;
    const polar *p = ctx;
    double t = ts + h;
    state s = at(p, t);
    q[0] = s.r * cos(s.th), q[1] = s.r * sin(s.th);
    /* the rounding of r(t) and theta(t), each a sum of three terms */
    double dr = 4 * DBL_EPSILON * (fabs(p->r0) + fabs(p->u * t) + fabs(p->b * t * t)),
           dth = 4 * DBL_EPSILON * (fabs(p->th0) + fabs(p->w0 * t) + fabs(p->al * t * t));
    *qerr = dr + fabs(s.r) * (dth + 2 * DBL_EPSILON);
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    polar p = {in[P_R0].x, in[P_U].x, in[P_B].x, in[P_TH0].x, in[P_W0].x, in[P_AL].x};
    const double t = in[P_T].x, t_end = in[P_TEND].x;
    const int n = (int)in[P_POINTS].x;

    /* ---- at t ---- */
    /* the answers in double-double from the parameters, rounded once: |v|,
     * |a|, v x a and v . a from the polar components, rotation-free, so v x a
     * is exactly 0 on a radial line (theta' = theta'' = 0) */
    state_dd S = at_dd(&p, t);
    polar_dd K = kin_dd(&S);
    double rho_err = 0;
    put(res, O_R, S.r, NULL);
    put(res, O_TH, S.th, NULL);
    put(res, O_VR, K.vr, NULL);
    put(res, O_VT, K.vt, NULL);
    double speed = put(res, O_V, K.v, NULL);
    put(res, O_AR, K.ar, NULL);
    put(res, O_AT, K.at, NULL);
    double amag = put(res, O_A, K.a, NULL);
    put(res, O_CENT, K.cent, NULL);
    put(res, O_COR, K.cor, NULL);
    mm_ddb an = mm_ddb_quot(mm_ddb_abs(K.cr), K.v), rho = mm_ddb_quot(mm_ddb_mul(K.v, K.v), an);
    if (speed > 0) {
        /* path components: a_t along v, a_n across it, rho = v^2 / a_n */
        put(res, O_ATAN, mm_ddb_quot(K.dot, K.v), NULL);
        put(res, O_ANOR, an, NULL);
        if (mm_ddb_mag(K.cr) > K.cr.e)
            put(res, O_RHO, rho, &rho_err);
        else if (K.cr.e == 0)
            mm_res_warn(res, "the path is straight at t = %g (v and a along one line): no radius of curvature", t);
        else
            mm_res_warn(res, "the path is straight at t = %g to within rounding (v x a = %.3g, within its bound "
                        "%.3g): no radius of curvature", t, mm_dd_val(K.cr.x), K.cr.e);
    }
    /* the same state rounded to double: the routes and the circle below */
    state s = {mm_dd_val(S.r.x), mm_dd_val(S.r1.x), p.b, mm_dd_val(S.th.x), mm_dd_val(S.th1.x), p.al};
    mm_v2 x, v, a, vc, ac;
    double vr, vt, ar, at_;
    kin(&s, &x, &v, &a, &vr, &vt, &ar, &at_);
    /* the polar route against the Cartesian one: rounding of the largest term */
    cartesian(&s, &vc, &ac);
    double big_v = fabs(s.r1) + fabs(s.r * s.th1), big_a = fabs(s.r2) + 2 * fabs(s.r1 * s.th1) +
                                                           fabs(s.r * s.th2) + fabs(s.r * s.th1 * s.th1);
    mm_res_check_abs(res, "v by eq. (2) vs d/dt of (r cos theta, r sin theta): |difference| [m/s]",
                     mm_v2_norm(mm_v2_sub(v, vc)), 0, 8 * DBL_EPSILON * big_v);
    mm_res_check_abs(res, "a by eq. (3) vs d2/dt2 of (r cos theta, r sin theta): |difference| [m/s^2]",
                     mm_v2_norm(mm_v2_sub(a, ac)), 0, 8 * DBL_EPSILON * big_a);
    /* radius of curvature against the circle through three points h apart
     * (h from circle_step): R(h) - rho = O(h^2), so the value at h/4 lies
     * within 2 |R(h/2) - R(h/4)| of the rho of the motion the points come
     * from, the rounded state s, once the rounding e1, e2 of R(h/2), R(h/4)
     * is added: 2 (|R1 - R2| + e1 + e2) + e2.  That rho differs from the
     * one printed by the state's rounding (rho from s in double-double,
     * with s's rounding as the error it starts from: within E of the exact
     * rho, and so of rho(s) within 2 E) and the printed one's own bound. */
    double an_ = mm_dd_val(an.x), rho_ = mm_dd_val(rho.x);
    if (speed > 0 && mm_ddb_mag(K.cr) > K.cr.e && an_ > 1e-9 * amag && speed > 1e-9 * (fabs(s.r) + 1)) {
        double k = mm_dd_val(K.cr.x) / (speed * speed * speed), R[3];
        double h = circle_step(&s, speed, k);
        int ok = mm_kin_circle3(point, &s, t, h, R);
        state_dd Sr = {{mm_dd_from(s.r), mm_dd_abs(mm_dd_sub(S.r.x, mm_dd_from(s.r))) + S.r.e},
                       {mm_dd_from(s.r1), mm_dd_abs(mm_dd_sub(S.r1.x, mm_dd_from(s.r1))) + S.r1.e},
                       S.r2, S.th,
                       {mm_dd_from(s.th1), mm_dd_abs(mm_dd_sub(S.th1.x, mm_dd_from(s.th1))) + S.th1.e}, S.th2};
        polar_dd Kr = kin_dd(&Sr);
        double E = mm_ddb_quot(mm_ddb_mul(Kr.v, Kr.v), mm_ddb_quot(mm_ddb_abs(Kr.cr), Kr.v)).e;
        double e1 = circle_err(&s, h / 2), e2 = circle_err(&s, h / 4);
        if (ok)
            mm_res_check_abs(res, "rho = v^2/a_n vs the circle through three points of the path, bound 2 |R(h/2) - R(h/4)| + rounding",
                             R[2], rho_, 2 * fabs(R[1] - R[2]) + 2 * e1 + 3 * e2 + 2 * E + rho_err);
    }

    /* ---- over [0, t_end] ---- */
    mm_series *path = mm_res_series(res, O_PATH, n), *sv = mm_res_series(res, O_SV, n);
    mm_series *sr = mm_res_series(res, O_SAR, n), *st = mm_res_series(res, O_SAT, n);
    mm_kin_samples smp;
    if (!path || !sv || !sr || !st || mm_kin_samples_init(&smp, res, n, 2, err) != MM_OK)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_kin_grid(0, t_end, n, sv->x);
    double vmax = 0, amax = 0;
    for (int i = 0; i < n; i++) {
        state si = at(&p, sv->x[i]);
        mm_v2 xi, vi, ai;
        double a1, a2, a3, a4;
        kin(&si, &xi, &vi, &ai, &a1, &a2, &a3, &a4);
        path->x[i] = xi.x, path->y[i] = xi.y;
        sr->x[i] = st->x[i] = sv->x[i];
        sv->y[i] = mm_v2_norm(vi), sr->y[i] = a3, st->y[i] = a4;
        vmax = fmax(vmax, sv->y[i]), amax = fmax(amax, mm_v2_norm(ai));
        if (i % 8 == 0)                       /* the samples: one point in 8 (the last only if it is one) */
            mm_kin_sample2(&smp, i, sv->x[i], vi, ai);
    }
    /* central differences of the position over the motion */
    double h0 = 0.05 / fmax(1, fmax(fabs(p.w0), fabs(p.w0) + fabs(p.al) * t_end));
    int rc = mm_kin_fd_samples(res, O_FDV, O_FDA, "d(x,y)/dt", "d2(x,y)/dt2", fd_pos, &p, &smp, h0, err);
    if (rc != MM_OK)
        return rc;

    /* ---- the animation: the arm, the point, its path and arrows ---- */
    double wmax = fmax(fabs(p.w0), fabs(p.w0 + p.al * t_end)), t_show;
    int nf = mm_scene_frames(t_end, wmax > 0 ? 2 * M_PI / wmax : 0, &t_show);
    mm_res_method(res, "closed form (polar components), checked by central differences", 0);
    return mm_kin_anim_arm(res, nf, t_show, path, vmax, amax, frame, &p, err);
}

static const char *const references[] = {
    "F. P. Beer, E. R. Johnston, Vector Mechanics for Engineers: Dynamics, 9th ed., section 11.14", NULL,
};

const mm_exercise mm_ex_kin_rotation_plane = {
    .id = "kin-rotation-plane", .chapter = 2, .section = "2.2.6",
    .title = "Motion about a fixed point: polar coordinates",
    .summary = "Radial and transverse velocity and acceleration of a point on a turning arm: the centripetal "
               "and Coriolis terms, and circular motion as the special case.",
    .tags = "kinematics, particle, polar coordinates, rotation, Coriolis, centripetal",
    .theory = "exercises/kin/rotation_plane.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
