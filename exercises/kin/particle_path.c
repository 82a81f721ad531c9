/* particle_path.c — kin-particle-path: a particle whose position is typed
 * as two expressions x(t), y(t).
 *
 *     v = dr/dt,  a = d2r/dt2                                              (1)
 *     v_avg = (r(t + dt) - r(t)) / dt,  a_avg = (v(t + dt) - v(t)) / dt    (2)
 *
 * Goal: position, velocity and acceleration as vectors; the average
 * velocity and acceleration over an interval against the instantaneous
 * ones (they agree as dt shrinks); and numerical differentiation itself:
 * the central difference's error against its step, falling like h^2 until
 * rounding takes over.
 * Method: the expressions are evaluated by muParser, which has no symbolic
 * derivative; v and a come from Ridders' extrapolation of central
 * differences (mm_geom_curve_derivs), each with its error estimate.
 * Checks: the plain central difference against them over the whole path
 * (order 2 and value); the mean-value theorem: the average velocity (2)
 * against (1/dt) times the integral of v over [t, t + dt] by Gauss-Legendre
 * quadrature (and the same for a), within the sum of their error bounds.
 * Reference: F. P. Beer, E. R. Johnston, Vector Mechanics for Engineers:
 * Dynamics, sections 11.9-11.11; W. H. Press et al., Numerical Recipes, 3rd
 * ed., section 5.7.
 */
#include <float.h>
#include <math.h>

#include "mm_geom.h"
#include "mm_kin.h"

enum { P_X, P_Y, P_T0, P_T1, P_T, P_DT, P_POINTS };

static const mm_param params[] = {
    [P_X] = {"x", "x(t)", "m", MM_EXPR, 0, 0, 0, "2*cos(t)-cos(2*t)", .vars = "t",
             .help = "the x coordinate as an expression of t: + - * / ^, sin cos exp sqrt ..., pi"},
    [P_Y] = {"y", "y(t)", "m", MM_EXPR, 0, 0, 0, "2*sin(t)-sin(2*t)", .vars = "t", .help = "the y coordinate"},
    [P_T0] = {"t0", "start of the motion shown", "s", MM_REAL, 0, -100, 100, .help = "the path is drawn from t0"},
    [P_T1] = {"t1", "end of the motion shown", "s", MM_REAL, 2 * M_PI, -100, 100, .help = "to t1 > t0"},
    [P_T] = {"t", "instant", "s", MM_REAL, 1, -100, 100, .help = "the time at which the answers are given"},
    [P_DT] = {"dt", "averaging interval", "s", MM_REAL, 0.5, 1e-6, 100,
              .help = "the average velocity and acceleration are taken over [t, t + dt]"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 401, 11, 2001, .help = "samples of the plotted path"},
};

enum {
    O_X, O_Y, O_VX, O_VY, O_V, O_AX, O_AY, O_A, O_VAX, O_VAY, O_AAX, O_AAY,
    O_PATH, O_SV, O_FD, O_ANIM
};

static const mm_output outputs[] = {
    [O_X] = MM_SCALAR("x", "position x", "m", .flags = MM_EXACT),
    [O_Y] = MM_SCALAR("y", "position y", "m", .flags = MM_EXACT),
    [O_VX] = MM_SCALAR("vx", "velocity x", "m/s", .flags = MM_ANSWER),
    [O_VY] = MM_SCALAR("vy", "velocity y", "m/s", .flags = MM_ANSWER),
    [O_V] = MM_SCALAR("v", "speed", "m/s", .flags = MM_ANSWER),
    [O_AX] = MM_SCALAR("ax", "acceleration x", "m/s^2", .flags = MM_ANSWER),
    [O_AY] = MM_SCALAR("ay", "acceleration y", "m/s^2", .flags = MM_ANSWER),
    [O_A] = MM_SCALAR("a", "magnitude of the acceleration", "m/s^2", .flags = MM_ANSWER),
    [O_VAX] = MM_SCALAR("v_avg_x", "average velocity over [t, t+dt], x", "m/s", .flags = MM_ANSWER),
    [O_VAY] = MM_SCALAR("v_avg_y", "average velocity over [t, t+dt], y", "m/s", .flags = MM_ANSWER),
    [O_AAX] = MM_SCALAR("a_avg_x", "average acceleration over [t, t+dt], x", "m/s^2"),
    [O_AAY] = MM_SCALAR("a_avg_y", "average acceleration over [t, t+dt], y", "m/s^2"),
    [O_PATH] = MM_SERIES("path", "path of the particle", "m", "x", "m", .aspect = "equal", .figure = "path"),
    [O_SV] = MM_SERIES("v", "speed", "m/s", "t", "s", .figure = "speed"),
    [O_FD] = MM_KIN_FD_SERIES("fd_error", "worst error of the central difference of r vs Ridders' v", "m/s", "s"),
    [O_ANIM] = MM_ANIMATION("the particle moving along its path with its velocity and acceleration"),
};

/* The work (mm_kin_curve_work): every plotted point, animation frame and
 * quadrature node costs a Ridders derivative, each sample of the
 * difference study 48 more: as many as 480 points besides the plotted. */
static int check(const mm_value *in, mm_error *err)
{
    int rc = mm_kin_curve_work(in[P_X].text, in[P_Y].text, in[P_POINTS].x, 480, err);
    return rc != MM_OK ? rc : mm_kin_check_window(in[P_T0].x, in[P_T1].x, in[P_T].x, err);
}

typedef struct fd_ctx {
    mm_kin_curve *c;
    const double *t;
    double vmax;              /* the largest speed on the path */
} fd_ctx;

static int fd_pos(int i, double h, double *q, double *qerr, void *ctx, mm_error *err)
{
    fd_ctx *f = ctx;
    double t = f->t[i] + h;
    if (mm_kin_curve_eval(t, q, f->c) != MM_OK)
        return mm_error_set(err, MM_ENONFINITE, "x", "the path is not finite at t = %g", t);
    /* the expression's own rounding, and t's: r moves by |v| eps |t| */
    *qerr = 8 * DBL_EPSILON * (fabs(q[0]) + fabs(q[1]) + f->vmax * fabs(t));
    return MM_OK;
}

static int run(mm_kin_curve *c, const mm_value *in, mm_result *res, mm_error *err)
{
    const double t0 = in[P_T0].x, t1 = in[P_T1].x, t = in[P_T].x, dt = in[P_DT].x;
    const int n = (int)in[P_POINTS].x;
    const double h0 = 0.05 * fmin(t1 - t0, 1);             /* Ridders' first step */

    /* ---- at t: position exact, derivatives by Ridders with their estimates ---- */
    double r[2], d1[2], e1[2], d2[2], e2[2];
    int rc = mm_kin_curve_at(c, t, h0, r, d1, e1, d2, e2, err);
    if (rc != MM_OK)
        return rc;
    mm_res_scalar(res, O_X, r[0]), mm_res_scalar(res, O_Y, r[1]);
    mm_res_scalar_err(res, O_VX, d1[0], e1[0], MM_ERR_ESTIMATE);
    mm_res_scalar_err(res, O_VY, d1[1], e1[1], MM_ERR_ESTIMATE);
    mm_res_scalar_err(res, O_V, hypot(d1[0], d1[1]), hypot(e1[0], e1[1]), MM_ERR_ESTIMATE);
    mm_res_scalar_err(res, O_AX, d2[0], e2[0], MM_ERR_ESTIMATE);
    mm_res_scalar_err(res, O_AY, d2[1], e2[1], MM_ERR_ESTIMATE);
    mm_res_scalar_err(res, O_A, hypot(d2[0], d2[1]), hypot(e2[0], e2[1]), MM_ERR_ESTIMATE);

    /* ---- averages over [t, t + dt], eq. (2), and the mean-value theorem ---- */
    double r2[2], v2[2], f1[2], a2[2], f2[2], t2 = t + dt, span = t2 - t;   /* the interval as rounded */
    if ((rc = mm_kin_curve_at(c, t2, h0, r2, v2, f1, a2, f2, err)) != MM_OK)
        return rc;
    double vs = fmax(hypot(d1[0], d1[1]), hypot(v2[0], v2[1]));
    static const char *const vnm[2] = {"v_avg_x: (r(t+dt) - r(t))/dt vs the mean of v by Gauss-Legendre",
                                       "v_avg_y: (r(t+dt) - r(t))/dt vs the mean of v by Gauss-Legendre"};
    static const char *const anm[2] = {"a_avg_x: (v(t+dt) - v(t))/dt vs the mean of a by Gauss-Legendre",
                                       "a_avg_y: (v(t+dt) - v(t))/dt vs the mean of a by Gauss-Legendre"};
    /* 8 and 16 panels of Gauss-Legendre (10th order): |Q16 - Q8| bounds Q8's
     * error and far more than Q16's */
    double q8[2][2], q16[2][2], b8[2][2], b16[2][2];
    if ((rc = mm_kin_curve_integrals(c, t, t2, 8, h0, q8[0], b8[0], q8[1], b8[1], err)) != MM_OK ||
        (rc = mm_kin_curve_integrals(c, t, t2, 16, h0, q16[0], b16[0], q16[1], b16[1], err)) != MM_OK)
        return rc;
    for (int k = 1; k <= 2; k++) {
        for (int i = 0; i < 2; i++) {
            double avg = k == 1 ? (r2[i] - r[i]) / span : (v2[i] - d1[i]) / span;
            /* the difference: rounding of r (the expression's, and |v| eps |t|
             * from t's), or Ridders' errors of v, over the interval */
            double eavg = k == 1 ? 8 * DBL_EPSILON * (fabs(r2[i]) + fabs(r[i]) + vs * (fabs(t) + fabs(t2))) / span
                                 : (f1[i] + e1[i]) / span;
            mm_res_scalar_err(res, k == 1 ? O_VAX + i : O_AAX + i, avg, eavg, k == 1 ? MM_ERR_BOUND : MM_ERR_ESTIMATE);
            /* quadrature error |Q16 - Q8|, the Ridders errors it summed, the
             * difference's own, and rounding of the sum */
            double tol = (fabs(q16[k - 1][i] - q8[k - 1][i]) + b16[k - 1][i]) / span + eavg + 8 * DBL_EPSILON * fabs(avg);
            mm_res_check_abs(res, k == 1 ? vnm[i] : anm[i], avg, q16[k - 1][i] / span, tol);
        }
    }

    /* ---- the path over [t0, t1] ---- */
    mm_series *path = mm_res_series(res, O_PATH, n), *sv = mm_res_series(res, O_SV, n);
    mm_kin_samples smp;
    if (!path || !sv || mm_kin_samples_init(&smp, res, n, 2, err) != MM_OK)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_kin_grid(t0, t1, n, sv->x);
    double derr = 0, size = 0, vmax_path = 0;
    for (int i = 0; i < n; i++) {
        double ri[2], vi[2], ei[2], ai[2], fi[2];
        if ((rc = mm_kin_curve_at(c, sv->x[i], h0, ri, vi, ei, ai, fi, err)) != MM_OK)
            return rc;
        path->x[i] = ri[0], path->y[i] = ri[1];
        sv->y[i] = hypot(vi[0], vi[1]);
        vmax_path = fmax(vmax_path, sv->y[i]);
        size = fmax(size, fmax(fabs(ri[0]), fabs(ri[1])));
        if (mm_kin_sample(&smp, i, sv->x[i], vi, NULL))
            derr = fmax(derr, fmax(ei[0], ei[1]));
    }
    /* the plain central difference against Ridders: error vs step, order 2 */
    fd_ctx fc = {c, smp.t, vmax_path};
    mm_kin_fd fd;
    if ((rc = mm_kin_fd_study(res, O_FD, "dr/dt", fd_pos, &fc, 2, NULL, smp.ns, smp.d1, 1, 0.5 * h0, 26, derr, &fd,
                              err)) != MM_OK)
        return rc;

    /* ---- the animation ---- */
    enum { NF = 72 };
    double V[NF][2], A[NF][2], P[NF][2], T[NF];
    for (int f = 0; f < NF; f++) {
        double e[2], g[2];
        T[f] = t0 + (t1 - t0) * f / (NF - 1);
        if ((rc = mm_kin_curve_at(c, T[f], h0, P[f], V[f], e, A[f], g, err)) != MM_OK)
            return rc;
    }
    mm_res_method(res, "Ridders' extrapolation of central differences (derivatives of muParser expressions)", 0);
    mm_res_method_stat(res, "first_step", h0);
    return mm_kin_anim_particle(res, NF, T, P, V, A, path, 2 * size + 1e-6, err);
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    return mm_kin_curve_solve(in, P_X, P_Y, run, res, err);
}

static const char *const references[] = {
    "F. P. Beer, E. R. Johnston, Vector Mechanics for Engineers: Dynamics, 9th ed., sections 11.9-11.11",
    "W. H. Press et al., Numerical Recipes, 3rd ed., Cambridge 2007, section 5.7 (Ridders' method)", NULL,
};

const mm_exercise mm_ex_kin_particle_path = {
    .id = "kin-particle-path", .chapter = 2, .section = "2.2.1",
    .title = "Position, velocity and acceleration of a particle",
    .summary = "A path typed as x(t), y(t): velocity and acceleration vectors, average against instantaneous, "
               "and the error of a finite difference against its step.",
    .tags = "kinematics, particle, velocity, acceleration, numerical differentiation, Ridders",
    .theory = "exercises/kin/particle_path.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
