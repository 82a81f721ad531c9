/* path_coordinates.c — kin-path-coordinates: a particle on a path typed as
 * x(t), y(t), described by its own tangent and normal directions.
 *
 *     v = v T,   a = (dv/dt) T + (v^2 / rho) N                               (1)
 *     a_t = v . a / |v|,  a_n = |v x a| / |v|,  kappa = (v x a) / |v|^3      (2)
 *
 * Goal: the tangential acceleration changes the speed, the normal one the
 * direction; their sizes, the radius of curvature rho = 1/|kappa| and the
 * centre of curvature, along any path.
 * Method: v and a by Ridders' extrapolation (mm_geom_curve_derivs), each
 * with its error estimate, carried into (2).
 * Checks: a_t against central differences of the speed |v(t)| (error
 * against the step, order 2); rho against the circle through three close
 * points of the path.
 * Reference: F. P. Beer, E. R. Johnston, Vector Mechanics for Engineers:
 * Dynamics, section 11.13 (tangential and normal components).
 */
#include <float.h>
#include <math.h>

#include "mm_geom.h"
#include "mm_kin.h"

enum { P_X, P_Y, P_T0, P_T1, P_T, P_POINTS };

static const mm_param params[] = {
    [P_X] = {"x", "x(t)", "m", MM_EXPR, 0, 0, 0, "2*cos(t)", .vars = "t",
             .help = "the x coordinate as an expression of t: + - * / ^, sin cos exp sqrt ..., pi"},
    [P_Y] = {"y", "y(t)", "m", MM_EXPR, 0, 0, 0, "sin(t)", .vars = "t", .help = "the y coordinate"},
    [P_T0] = {"t0", "start of the motion shown", "s", MM_REAL, 0, -100, 100, .help = "the path is drawn from t0"},
    [P_T1] = {"t1", "end of the motion shown", "s", MM_REAL, 2 * M_PI, -100, 100, .help = "to t1 > t0"},
    [P_T] = {"t", "instant", "s", MM_REAL, 0.6, -100, 100, .help = "the time at which the answers are given"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 201, 11, 2001, .help = "samples of the plotted curves"},
};

enum {
    O_V, O_AT, O_AN, O_A, O_K, O_RHO, O_CX, O_CY, O_DIR,
    O_PATH, O_EVOL, O_SAT, O_SAN, O_FD, O_ANIM
};

static const mm_output outputs[] = {
    [O_V] = MM_SCALAR("v", "speed", "m/s", .flags = MM_ANSWER),
    [O_AT] = MM_SCALAR("a_t", "tangential acceleration dv/dt", "m/s^2", .flags = MM_ANSWER),
    [O_AN] = MM_SCALAR("a_n", "normal acceleration v^2/rho", "m/s^2", .flags = MM_ANSWER),
    [O_A] = MM_SCALAR("a", "magnitude of the acceleration", "m/s^2"),
    [O_K] = MM_SCALAR("kappa", "curvature (positive turning left)", "1/m"),
    [O_RHO] = MM_SCALAR("rho", "radius of curvature", "m", .flags = MM_ANSWER),
    [O_CX] = MM_SCALAR("centre_x", "centre of curvature, x", "m"),
    [O_CY] = MM_SCALAR("centre_y", "centre of curvature, y", "m"),
    [O_DIR] = MM_SCALAR("direction", "direction of motion (angle of T from x)", "rad"),
    [O_PATH] = MM_SERIES("path", "path of the particle", "m", "x", "m", .aspect = "equal", .figure = "path"),
    [O_EVOL] = MM_SERIES("evolute", "centres of curvature (the evolute)", "m", "x", "m", .aspect = "equal",
                         .figure = "path", .mark = "dots"),
    [O_SAT] = MM_SERIES("a_t", "tangential acceleration", "m/s^2", "t", "s", .figure = "acceleration components"),
    [O_SAN] = MM_SERIES("a_n", "normal acceleration", "m/s^2", "t", "s", .figure = "acceleration components"),
    [O_FD] = MM_KIN_FD_SERIES("fd_error", "worst error of the central difference of the speed vs a_t", "m/s^2", "s"),
    [O_ANIM] = MM_ANIMATION("the particle with its tangential and normal accelerations and the osculating circle"),
};

/* The work (mm_kin_curve_work): every plotted point and animation frame
 * costs a Ridders derivative, the difference study of the speed 8 x 48
 * more: as many as 460 points besides the plotted. */
static int check(const mm_value *in, mm_error *err)
{
    int rc = mm_kin_curve_work(in[P_X].text, in[P_Y].text, in[P_POINTS].x, 460, err);
    return rc != MM_OK ? rc : mm_kin_check_window(in[P_T0].x, in[P_T1].x, in[P_T].x, err);
}

/* eq. (2) and its first-order error from Ridders' estimates e1, e2 */
typedef struct frenet {
    double v, at, an, a, k, rho;
    double ev, eat, ean, ek;
    mm_v2 T, N, C;
} frenet;

static frenet path_coords(const double *r, const double *d1, const double *e1, const double *d2, const double *e2)
{
    frenet f = {0};
    mm_v2 v = {d1[0], d1[1]}, a = {d2[0], d2[1]};
    double E1 = hypot(e1[0], e1[1]), E2 = hypot(e2[0], e2[1]);
    f.v = mm_v2_norm(v), f.a = mm_v2_norm(a);
    f.ev = E1;
    if (!(f.v > 0))
        return f;
    f.T = mm_v2_scale(v, 1 / f.v), f.N = mm_v2_perp(f.T);
    double cr = mm_v2_cross(v, a);
    f.at = mm_v2_dot(v, a) / f.v;
    f.an = fabs(cr) / f.v;
    f.k = cr / (f.v * f.v * f.v);
    f.eat = E2 + 2 * f.a * E1 / f.v;
    f.ean = E2 + 2 * f.a * E1 / f.v;
    f.ek = (E1 * f.a + f.v * E2) / (f.v * f.v * f.v) + 3 * fabs(f.k) * E1 / f.v;
    if (f.k != 0) {
        f.rho = 1 / fabs(f.k);
        f.C = mm_v2_add((mm_v2){r[0], r[1]}, mm_v2_scale(f.N, 1 / f.k));
    }
    return f;
}

/* the path at t + e, for mm_kin_circle3 */
static int point(double t, double e, mm_v2 *P, void *ctx)
{
    double q[2];
    int ok = mm_kin_curve_eval(t + e, q, ctx) == MM_OK;
    *P = (mm_v2){q[0], q[1]};
    return ok;
}

typedef struct fd_ctx {
    mm_kin_curve *c;
    const double *t;
    double h0;
} fd_ctx;

/* the speed |v(t)| by Ridders, as the "position" to difference */
static int fd_speed(int i, double h, double *q, double *qerr, void *ctx, mm_error *err)
{
    fd_ctx *f = ctx;
    double r[2], d1[2], e1[2];
    int rc = mm_kin_curve_at(f->c, f->t[i] + h, f->h0, r, d1, e1, NULL, NULL, err);
    q[0] = hypot(d1[0], d1[1]);
    *qerr = hypot(e1[0], e1[1]);
    return rc;
}

static int run(mm_kin_curve *c, const mm_value *in, mm_result *res, mm_error *err)
{
    const double t0 = in[P_T0].x, t1 = in[P_T1].x, t = in[P_T].x, h0 = 0.05 * fmin(t1 - t0, 1);
    const int n = (int)in[P_POINTS].x;

    /* ---- at t ---- */
    double r[2], d1[2], e1[2], d2[2], e2[2];
    int rc = mm_kin_curve_at(c, t, h0, r, d1, e1, d2, e2, err);
    if (rc != MM_OK)
        return rc;
    frenet f = path_coords(r, d1, e1, d2, e2);
    mm_res_scalar_err(res, O_V, f.v, f.ev, MM_ERR_ESTIMATE);
    mm_res_scalar_err(res, O_A, f.a, hypot(e2[0], e2[1]), MM_ERR_ESTIMATE);
    if (f.v > 8 * f.ev) {
        mm_res_scalar_err(res, O_AT, f.at, f.eat, MM_ERR_ESTIMATE);
        mm_res_scalar_err(res, O_AN, f.an, f.ean, MM_ERR_ESTIMATE);
        mm_res_scalar_err(res, O_K, f.k, f.ek, MM_ERR_ESTIMATE);
        mm_res_scalar_err(res, O_DIR, atan2(f.T.y, f.T.x), f.ev / f.v, MM_ERR_ESTIMATE);
        if (fabs(f.k) > 8 * f.ek) {
            double erho = f.ek / (f.k * f.k);
            mm_res_scalar_err(res, O_RHO, f.rho, erho, MM_ERR_ESTIMATE);
            mm_res_scalar_err(res, O_CX, f.C.x, erho + 1e-16 * fabs(f.C.x), MM_ERR_ESTIMATE);
            mm_res_scalar_err(res, O_CY, f.C.y, erho + 1e-16 * fabs(f.C.y), MM_ERR_ESTIMATE);
            /* the circle through three points |v| h apart: the value at h/4
             * within 2 |R(h/2) - R(h/4)|, plus rounding and rho's own error */
            double R3[3], h = 0.02 * f.rho / f.v;
            int ok = mm_kin_circle3(point, c, t, h, R3);
            double ds = f.v * h / 4, rnd = 64 * DBL_EPSILON * (hypot(r[0], r[1]) + f.v * fabs(t) + f.rho) * f.rho *
                                           f.rho / (ds * ds);
            if (ok)
                mm_res_check_abs(res, "rho = |v|^3 / |v x a| vs the circle through three points of the path", R3[2],
                                 f.rho, 2 * fabs(R3[1] - R3[2]) + rnd + erho);
        } else {
            mm_res_warn(res, "the path is straight (an inflection) at t = %g: no radius of curvature", t);
        }
    } else {
        mm_res_warn(res, "the particle is at rest at t = %g: no direction of motion, so no tangential and normal "
                         "components", t);
    }

    /* ---- along the path ---- */
    mm_series *path = mm_res_series(res, O_PATH, n), *sat = mm_res_series(res, O_SAT, n);
    mm_series *san = mm_res_series(res, O_SAN, n);
    double *ev = mm_res_alloc(res, 2 * (size_t)n * sizeof *ev);
    const int stride = n / 8 > 1 ? n / 8 : 1, ns = n / stride + 1;      /* about 8 samples for the differences */
    double *ts = mm_res_alloc(res, (size_t)ns * sizeof *ts), *dd = mm_res_alloc(res, (size_t)ns * sizeof *dd);
    if (!path || !sat || !san || !ev || !ts || !dd)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_kin_grid(t0, t1, n, sat->x);
    double size = 0, amax = 0, derr = 0;
    int ne = 0, nfd = 0;
    for (int i = 0; i < n; i++) {
        double ri[2], vi[2], ei[2], ai[2], fi[2];
        if ((rc = mm_kin_curve_at(c, sat->x[i], h0, ri, vi, ei, ai, fi, err)) != MM_OK)
            return rc;
        frenet g = path_coords(ri, vi, ei, ai, fi);
        path->x[i] = ri[0], path->y[i] = ri[1];
        san->x[i] = sat->x[i];
        sat->y[i] = g.at, san->y[i] = g.an;
        size = fmax(size, hypot(ri[0], ri[1]));
        amax = fmax(amax, g.a);
        if (g.k != 0)
            ev[2 * ne] = g.C.x, ev[2 * ne + 1] = g.C.y, ne++;
        /* a_t against differences of the speed, where the speed is clear of 0 */
        if (i % stride == 0 && nfd < ns && g.v > 1e3 * g.ev) {
            ts[nfd] = sat->x[i], dd[nfd] = g.at;
            derr = fmax(derr, g.eat);
            nfd++;
        }
    }
    /* the evolute, without the far points of nearly straight stretches */
    int ke = 0;
    for (int i = 0; i < ne; i++)
        if (hypot(ev[2 * i], ev[2 * i + 1]) <= 3 * size + 1e-12)
            ev[2 * ke] = ev[2 * i], ev[2 * ke + 1] = ev[2 * i + 1], ke++;
    mm_series *se = mm_res_series(res, O_EVOL, ke > 0 ? ke : 1);
    if (!se)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (int i = 0; i < ke; i++)
        se->x[i] = ev[2 * i], se->y[i] = ev[2 * i + 1];
    if (ke == 0)
        se->x[0] = path->x[0], se->y[0] = path->y[0];
    if (nfd > 0) {
        fd_ctx fc = {c, ts, h0};
        mm_kin_fd fd;
        /* steps stay below a tenth of the time it takes the speed to change */
        if ((rc = mm_kin_fd_study(res, O_FD, "dv/dt = a_t", fd_speed, &fc, 1, NULL, nfd, dd, 1, 0.5 * h0, 24, derr,
                                  &fd, err)) != MM_OK)
            return rc;
    }

    /* ---- the animation ---- */
    enum { NF = 72 };
    mm_kin_osc_state fr[NF];
    for (int f2 = 0; f2 < NF; f2++) {
        double tf = t0 + (t1 - t0) * f2 / (NF - 1), ri[2], vi[2], ei[2], ai[2], fi[2];
        if ((rc = mm_kin_curve_at(c, tf, h0, ri, vi, ei, ai, fi, err)) != MM_OK)
            return rc;
        frenet g = path_coords(ri, vi, ei, ai, fi);
        mm_v2 an = {g.an * (g.k >= 0 ? g.N.x : -g.N.x), g.an * (g.k >= 0 ? g.N.y : -g.N.y)};   /* to the centre */
        fr[f2] = (mm_kin_osc_state){tf, {ri[0], ri[1]}, mm_v2_scale(g.T, g.at), an, g.N, g.k, g.rho};
    }
    mm_res_method(res, "Ridders' extrapolation of central differences (derivatives of muParser expressions)", 0);
    return mm_kin_anim_osculating(res, NF, fr, path, 2 * size + 1e-6, amax, err);
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    return mm_kin_curve_solve(in, P_X, P_Y, run, res, err);
}

static const char *const references[] = {
    "F. P. Beer, E. R. Johnston, Vector Mechanics for Engineers: Dynamics, 9th ed., section 11.13", NULL,
};

const mm_exercise mm_ex_kin_path_coordinates = {
    .id = "kin-path-coordinates", .chapter = 2, .section = "2.2.5",
    .title = "Tangential and normal coordinates",
    .summary = "Along any path typed as x(t), y(t): tangential and normal accelerations, curvature, radius "
               "and centre of curvature, the osculating circle.",
    .tags = "kinematics, particle, tangential, normal, curvature, osculating circle",
    .theory = "exercises/kin/path_coordinates.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
