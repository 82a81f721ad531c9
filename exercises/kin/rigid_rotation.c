/* rigid_rotation.c — kin-rigid-rotation: a rigid body turning about a
 * fixed axis through O with direction u, while the axis may translate at
 * constant velocity v_axis; P is a point of the body.
 *
 *     theta(t) = omega t + alpha t^2 / 2,  r = R(u, theta) r0               (1)
 *     v_P = v_axis + w x r,                 w = (omega + alpha t) u          (2)
 *     a_P = alpha u x r + w x (w x r)                                        (3)
 *
 * Goal: every point of a rotating body moves on a circle about the axis;
 * its speed is |w| rho (rho its distance from the axis), its acceleration
 * has the tangential part alpha rho and the normal part |w|^2 rho towards
 * the axis; a translation adds the same velocity to every point.
 * Checks: (2)-(3) against central differences of the positions (1), which
 * are built by Rodrigues' rotation (mm_geom); |v - v_axis| and the
 * tangential and normal parts of a against rho |w|, rho alpha, rho w^2.
 * Reference: F. P. Beer, E. R. Johnston, Vector Mechanics for Engineers:
 * Dynamics, sections 15.2-15.4.
 */
#include <float.h>
#include <math.h>

#include "mm_geom.h"
#include "mm_kin.h"
#include "mm_scene.h"

enum { P_AXIS, P_OMEGA, P_ALPHA, P_POINT, P_VAX, P_T, P_TEND, P_POINTS };

static const mm_param params[] = {
    [P_AXIS] = {"axis", "direction of the axis", "", MM_VECTOR, 0, -10, 10, "0,0,1", .max_cols = 3,
                .help = "any non-zero vector along the axis through O; its length does not matter"},
    [P_OMEGA] = {"omega", "angular velocity at t = 0", "rad/s", MM_REAL, 3, -100, 100,
                 .help = "about the axis, right-hand rule"},
    [P_ALPHA] = {"alpha", "angular acceleration", "rad/s^2", MM_REAL, 1, -100, 100, .help = "constant"},
    [P_POINT] = {"point", "position of P at t = 0", "m", MM_VECTOR, 0, -10, 10, "0.3,0.2,0.1", .max_cols = 3,
                 .help = "x, y, z of the body point P from O"},
    [P_VAX] = {"v_axis", "velocity of the axis", "m/s", MM_VECTOR, 0, -100, 100, "0,0,0", .max_cols = 3,
               .help = "a translation of the whole body (0: rotation about a fixed axis)"},
    [P_T] = {"t", "instant", "s", MM_REAL, 0.5, 0, 10, .help = "the time at which the answers are given (at most t_end)"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 2, 0.01, 10, .help = "the motion plotted and animated"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 201, 11, 2001, .help = "samples of the plotted curves"},
};

enum {
    O_TH, O_W, O_RHO, O_VX, O_VY, O_VZ, O_V, O_AX, O_AY, O_AZ, O_A, O_AT, O_AN,
    O_SV, O_SAT, O_SAN, O_FDV, O_FDA, O_ANIM
};

static const mm_output outputs[] = {
    [O_TH] = MM_SCALAR("theta", "angle turned", "rad", .flags = MM_EXACT),
    [O_W] = MM_SCALAR("omega_t", "angular velocity at t", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_RHO] = MM_SCALAR("rho", "distance of P from the axis", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_VX] = MM_SCALAR("vx", "velocity of P, x", "m/s", .flags = MM_EXACT),
    [O_VY] = MM_SCALAR("vy", "velocity of P, y", "m/s", .flags = MM_EXACT),
    [O_VZ] = MM_SCALAR("vz", "velocity of P, z", "m/s", .flags = MM_EXACT),
    [O_V] = MM_SCALAR("v", "speed of P", "m/s", .flags = MM_ANSWER | MM_EXACT),
    [O_AX] = MM_SCALAR("ax", "acceleration of P, x", "m/s^2", .flags = MM_EXACT),
    [O_AY] = MM_SCALAR("ay", "acceleration of P, y", "m/s^2", .flags = MM_EXACT),
    [O_AZ] = MM_SCALAR("az", "acceleration of P, z", "m/s^2", .flags = MM_EXACT),
    [O_A] = MM_SCALAR("a", "magnitude of the acceleration", "m/s^2", .flags = MM_ANSWER | MM_EXACT),
    [O_AT] = MM_SCALAR("a_t", "tangential acceleration alpha rho", "m/s^2", .flags = MM_ANSWER | MM_EXACT),
    [O_AN] = MM_SCALAR("a_n", "normal acceleration omega^2 rho", "m/s^2", .flags = MM_ANSWER | MM_EXACT),
    [O_SV] = MM_SERIES("v", "speed of P", "m/s", "t", "s", .figure = "speed"),
    [O_SAT] = MM_SERIES("a_t", "tangential acceleration", "m/s^2", "t", "s", .figure = "acceleration"),
    [O_SAN] = MM_SERIES("a_n", "normal acceleration", "m/s^2", "t", "s", .figure = "acceleration"),
    [O_FDV] = MM_KIN_FD_SERIES("fd_error_v", "worst error of the central difference of P vs v_P", "m/s", "s"),
    [O_FDA] = MM_KIN_FD_SERIES("fd_error_a", "worst error of the second difference vs a_P", "m/s^2", "s"),
    [O_ANIM] = MM_ANIMATION("the body seen along its axis, P's path, velocity and acceleration"),
};

typedef struct body {
    mm_v3 u, r0, vax;     /* unit axis, P at t = 0, axis velocity */
    double w0, al;
} body;

static int check(const mm_value *in, mm_error *err)
{
    const int vec[3] = {P_AXIS, P_POINT, P_VAX};
    for (int k = 0; k < 3; k++)
        if (in[vec[k]].cols != 3)
            return mm_error_set(err, MM_ERANGE, params[vec[k]].name, "%s needs 3 components x,y,z; got %d",
                                params[vec[k]].name, in[vec[k]].cols);
    const double *u = in[P_AXIS].data;
    if (!(u[0] * u[0] + u[1] * u[1] + u[2] * u[2] > 0))
        return mm_error_set(err, MM_ERANGE, "axis", "the axis needs a direction: a non-zero vector");
    return mm_kin_check_t(in[P_T].x, in[P_TEND].x, err);
}

/* P at t, eq. (1), and v, a of eqs. (2)-(3) */
static mm_v3 pos(const body *b, double t, mm_v3 *v, mm_v3 *a)
{
    double th = b->w0 * t + 0.5 * b->al * t * t, w = b->w0 + b->al * t, R[9];
    mm_geom_rot_axis_angle(b->u, th, R, NULL);
    mm_v3 r = mm_geom_m3_apply(R, b->r0), wv = mm_v3_scale(b->u, w);
    mm_v3 wxr = mm_v3_cross(wv, r);
    if (v)
        *v = mm_v3_add(b->vax, wxr);
    if (a)
        *a = mm_v3_add(mm_v3_scale(mm_v3_cross(b->u, r), b->al), mm_v3_cross(wv, wxr));
    return mm_v3_add(mm_v3_scale(b->vax, t), r);
}

/* the animation's frame at t */
static void frame(double t, mm_kin_axis_state *k, void *ctx)
{
    const body *b = ctx;
    k->th = b->w0 * t + 0.5 * b->al * t * t;
    k->P = pos(b, t, &k->v, &k->a);
    k->O = mm_v3_scale(b->vax, t);
}

static int fd_pos(double ts, double h, double *q, double *qerr, void *ctx, mm_error *err)
{
    (void)err;
    const body *b = ctx;
    double t = ts + h;
    mm_v3 P = pos(b, t, NULL, NULL);
    q[0] = P.x, q[1] = P.y, q[2] = P.z;
    /* Rodrigues' matrix from a rounded angle theta(t): |r| (eps |theta| + 8 eps) */
    double th = fabs(b->w0 * t) + fabs(0.5 * b->al * t * t);
    *qerr = mm_v3_norm(b->r0) * (4 * th + 16) * DBL_EPSILON + 4 * DBL_EPSILON * mm_v3_norm(b->vax) * t;
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    const double *u = in[P_AXIS].data, *p = in[P_POINT].data, *va = in[P_VAX].data;
    mm_v3 U = {u[0], u[1], u[2]};
    body b = {mm_v3_scale(U, 1 / mm_v3_norm(U)), {p[0], p[1], p[2]}, {va[0], va[1], va[2]}, in[P_OMEGA].x,
              in[P_ALPHA].x};
    const double t = in[P_T].x, t_end = in[P_TEND].x;
    const int n = (int)in[P_POINTS].x;

    /* ---- at t ---- */
    mm_v3 v, a, P = pos(&b, t, &v, &a);
    mm_v3 r = mm_v3_sub(P, mm_v3_scale(b.vax, t));
    mm_v3 radial = mm_v3_sub(r, mm_v3_scale(b.u, mm_v3_dot(r, b.u)));        /* from the axis to P */
    double rho = mm_v3_norm(radial), w = b.w0 + b.al * t;
    mm_res_scalar(res, O_TH, b.w0 * t + 0.5 * b.al * t * t);
    mm_res_scalar(res, O_W, w);
    mm_res_scalar(res, O_RHO, rho);
    mm_res_scalar(res, O_VX, v.x), mm_res_scalar(res, O_VY, v.y), mm_res_scalar(res, O_VZ, v.z);
    mm_res_scalar(res, O_V, mm_v3_norm(v));
    mm_res_scalar(res, O_AX, a.x), mm_res_scalar(res, O_AY, a.y), mm_res_scalar(res, O_AZ, a.z);
    mm_res_scalar(res, O_A, mm_v3_norm(a));
    mm_res_scalar(res, O_AT, b.al * rho);
    mm_res_scalar(res, O_AN, w * w * rho);
    /* the cross products against the circle's own numbers */
    double big = (fabs(w) + fabs(b.al) + w * w) * mm_v3_norm(b.r0);
    mm_res_check_abs(res, "|v - v_axis| (w x r) vs |omega| rho: difference [m/s]",
                     mm_v3_norm(mm_v3_sub(v, b.vax)) - fabs(w) * rho, 0, 16 * DBL_EPSILON * big);
    if (rho > 0) {
        mm_v3 et = mm_v3_scale(mm_v3_cross(b.u, radial), 1 / rho), en = mm_v3_scale(radial, -1 / rho);
        mm_res_check_abs(res, "a along the circle's tangent (eq. 3) vs alpha rho [m/s^2]", mm_v3_dot(a, et), b.al * rho,
                         16 * DBL_EPSILON * big);
        mm_res_check_abs(res, "a towards the axis (eq. 3) vs omega^2 rho [m/s^2]", mm_v3_dot(a, en), w * w * rho,
                         16 * DBL_EPSILON * big);
    }

    /* ---- over [0, t_end] ---- */
    mm_series *sv = mm_res_series(res, O_SV, n), *sat = mm_res_series(res, O_SAT, n), *san = mm_res_series(res, O_SAN, n);
    if (!sv || !sat || !san)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_kin_grid(0, t_end, n, sv->x);
    mm_kin_samples smp;
    if (mm_kin_samples_init(&smp, res, n, 3, err) != MM_OK)
        return MM_ENOMEM;
    double vmax = 0, amax = 0;
    for (int i = 0; i < n; i++) {
        double ti = sv->x[i], wi = b.w0 + b.al * ti;
        mm_v3 vi, ai;
        pos(&b, ti, &vi, &ai);
        sat->x[i] = san->x[i] = ti;
        sv->y[i] = mm_v3_norm(vi), sat->y[i] = b.al * rho, san->y[i] = wi * wi * rho;
        vmax = fmax(vmax, sv->y[i]), amax = fmax(amax, mm_v3_norm(ai));
        mm_kin_sample3(&smp, i, ti, vi, ai);
    }
    double wm = fmax(fabs(b.w0), fabs(b.w0 + b.al * t_end)), h0 = 0.05 / fmax(1, wm);
    int rc = mm_kin_fd_samples(res, O_FDV, O_FDA, "dP/dt", "d2P/dt2", fd_pos, &b, &smp, h0, err);
    if (rc != MM_OK)
        return rc;

    /* ---- the animation: seen along the axis ---- */
    double t_show;
    int nf = mm_scene_frames(t_end, wm > 0 ? 2 * M_PI / wm : 0, &t_show);
    double R = fmax(rho, 0.05 * mm_v3_norm(b.r0) + 1e-3), drift = mm_v3_norm(b.vax) * t_show;
    mm_res_method(res, "closed form (cross products), positions by Rodrigues' rotation", 0);
    return mm_kin_anim_axis(res, nf, t_show, b.u, b.r0, R, drift, vmax, amax, frame, &b, err);
}

static const char *const references[] = {
    "F. P. Beer, E. R. Johnston, Vector Mechanics for Engineers: Dynamics, 9th ed., sections 15.2-15.4", NULL,
};

const mm_exercise mm_ex_kin_rigid_rotation = {
    .id = "kin-rigid-rotation", .chapter = 2, .section = "2.3.2",
    .title = "Translation and rotation about a fixed axis",
    .summary = "Velocity and acceleration of any point of a body turning about a fixed axis: omega x r, "
               "the tangential and normal parts, and a translation added.",
    .tags = "kinematics, rigid body, rotation, fixed axis, translation, cross product",
    .theory = "exercises/kin/rigid_rotation.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
