/* relative_motion.c — kin-relative-motion: a slider runs along a straight
 * slot cut in a turntable; the table turns about its fixed centre O.  Seen
 * from the table (the moving frame) the slider moves on a line; seen from
 * the ground (the absolute frame) it spirals.
 *
 *     r = R(theta) (s, h),  theta = theta0 + omega t + alpha t^2/2,
 *     s = s0 + u t + b t^2/2                                               (1)
 *     v = v_rel + w x r                                                    (2)
 *     a = a_rel + alpha x r - w^2 r + 2 w x v_rel                          (3)
 *
 * Goal: the absolute velocity is the relative one plus the transport
 * velocity of the point of the table under the slider; the absolute
 * acceleration needs, besides the relative and transport terms, the
 * Coriolis term 2 w x v_rel.
 * Checks: (2) and (3) against central differences of the absolute position
 * (1): the Coriolis theorem checked, the error shown against its step.
 * Reference: F. P. Beer, E. R. Johnston, Vector Mechanics for Engineers:
 * Dynamics, sections 15.10-15.11 (rotating frame, Coriolis acceleration).
 */
#include <float.h>
#include <math.h>

#include "mm_geom.h"
#include "mm_kin.h"
#include "mm_scene.h"

enum { P_W, P_AL, P_TH0, P_S0, P_U, P_B, P_H, P_T, P_TEND, P_POINTS };

static const mm_param params[] = {
    [P_W] = {"omega", "table's angular velocity at t = 0", "rad/s", MM_REAL, 2, -20, 20,
             .help = "counter-clockwise positive"},
    [P_AL] = {"alpha", "table's angular acceleration", "rad/s^2", MM_REAL, 0, -20, 20, .help = "constant"},
    [P_TH0] = {"theta0", "table's angle at t = 0", "rad", MM_REAL, 0, -10, 10, .help = "the slot's direction at t = 0"},
    [P_S0] = {"s0", "slider's place along the slot at t = 0", "m", MM_REAL, 0.1, -10, 10,
              .help = "measured from the foot of the slot's perpendicular from O"},
    [P_U] = {"u", "slider's speed along the slot at t = 0", "m/s", MM_REAL, 0.4, -10, 10, .help = "relative to the table"},
    [P_B] = {"b", "slider's acceleration along the slot", "m/s^2", MM_REAL, 0, -10, 10, .help = "relative, constant"},
    [P_H] = {"h", "offset of the slot from O", "m", MM_REAL, 0, -10, 10,
             .help = "0: the slot runs along a radius; otherwise parallel to one at distance h"},
    [P_T] = {"t", "instant", "s", MM_REAL, 0.5, 0, 10, .help = "the time at which the answers are given (at most t_end)"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 2, 0.01, 10, .help = "the motion plotted and animated"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 301, 11, 2001, .help = "samples of the plotted curves"},
};

enum {
    O_VREL, O_VTR, O_V, O_AREL, O_ATT, O_ATN, O_ACOR, O_A, O_VTAB, O_ATAB,
    O_PATH, O_RPATH, O_SV, O_SA, O_FDV, O_FDA, O_ANIM
};

static const char *const cols[] = {"term", "x", "y", "x_table", "y_table", NULL};
static const char *const vunits[] = {"", "m/s", "m/s", "m/s", "m/s", NULL};
static const char *const aunits[] = {"", "m/s^2", "m/s^2", "m/s^2", "m/s^2", NULL};

static const mm_output outputs[] = {
    [O_VREL] = MM_SCALAR("v_rel", "relative speed (along the slot)", "m/s", .flags = MM_ANSWER | MM_EXACT),
    [O_VTR] = MM_SCALAR("v_transport", "transport speed |w x r|", "m/s", .flags = MM_ANSWER | MM_EXACT),
    [O_V] = MM_SCALAR("v", "absolute speed", "m/s", .flags = MM_ANSWER | MM_EXACT),
    [O_AREL] = MM_SCALAR("a_rel", "relative acceleration (along the slot)", "m/s^2", .flags = MM_EXACT),
    [O_ATT] = MM_SCALAR("a_transport_t", "transport acceleration, tangential |alpha x r|", "m/s^2", .flags = MM_EXACT),
    [O_ATN] = MM_SCALAR("a_transport_n", "transport acceleration, centripetal omega^2 |r|", "m/s^2", .flags = MM_EXACT),
    [O_ACOR] = MM_SCALAR("a_coriolis", "Coriolis acceleration |2 w x v_rel|", "m/s^2", .flags = MM_ANSWER | MM_EXACT),
    [O_A] = MM_SCALAR("a", "absolute acceleration", "m/s^2", .flags = MM_ANSWER | MM_EXACT),
    [O_VTAB] = MM_TABLE("velocities", "velocity terms, in ground (x, y) and table axes", cols, vunits),
    [O_ATAB] = MM_TABLE("accelerations", "acceleration terms, in ground (x, y) and table axes", cols, aunits),
    [O_PATH] = MM_SERIES("path", "absolute path of the slider", "m", "x", "m", .aspect = "equal", .figure = "paths"),
    [O_RPATH] = MM_SERIES("slot", "the slot at the instant t", "m", "x", "m", .aspect = "equal", .figure = "paths",
                          .role = "reference"),
    [O_SV] = MM_SERIES("v", "absolute speed", "m/s", "t", "s", .figure = "speed"),
    [O_SA] = MM_SERIES("a_coriolis", "Coriolis acceleration", "m/s^2", "t", "s", .figure = "Coriolis"),
    [O_FDV] = MM_KIN_FD_SERIES("fd_error_v", "worst error of the central difference of r vs eq. (2)", "m/s", "s"),
    [O_FDA] = MM_KIN_FD_SERIES("fd_error_a", "worst error of the second difference vs eq. (3)", "m/s^2", "s"),
    [O_ANIM] = MM_ANIMATION("the turning table with its slot and slider, the absolute path, v and the Coriolis term"),
};

typedef struct table {
    double w, al, th0, s0, u, b, h;
} table;

/* every term of (2)-(3) at t, ground components */
typedef struct terms {
    double th, w, s;
    mm_v2 r, vrel, vtr, v, arel, att, atn, acor, a;
} terms;

static terms at(const table *p, double t)
{
    terms k;
    k.th = p->th0 + p->w * t + 0.5 * p->al * t * t;
    k.w = p->w + p->al * t;
    k.s = p->s0 + p->u * t + 0.5 * p->b * t * t;
    mm_v2 ex = mm_v2_polar(1, k.th);                        /* the slot's direction */
    k.r = mm_v2_rotate((mm_v2){k.s, p->h}, k.th);
    k.vrel = mm_v2_scale(ex, p->u + p->b * t);
    k.vtr = mm_v2_scale(mm_v2_perp(k.r), k.w);              /* w x r */
    k.v = mm_v2_add(k.vrel, k.vtr);
    k.arel = mm_v2_scale(ex, p->b);
    k.att = mm_v2_scale(mm_v2_perp(k.r), p->al);            /* alpha x r */
    k.atn = mm_v2_scale(k.r, -k.w * k.w);                   /* w x (w x r) */
    k.acor = mm_v2_scale(mm_v2_perp(k.vrel), 2 * k.w);      /* 2 w x v_rel */
    k.a = mm_v2_add(mm_v2_add(k.arel, k.att), mm_v2_add(k.atn, k.acor));
    return k;
}

/* the animation's frame at t */
static void frame(double t, mm_kin_slot_state *k, void *ctx)
{
    terms a = at(ctx, t);
    *k = (mm_kin_slot_state){a.th, a.r, a.v, a.vrel, a.acor, a.a};
}

static int check(const mm_value *in, mm_error *err)
{
    return mm_kin_check_t(in[P_T].x, in[P_TEND].x, err);
}

static int fd_pos(double ts, double h, double *q, double *qerr, void *ctx, mm_error *err)
{
    (void)err;
    const table *p = ctx;
    double t = ts + h;
    terms k = at(p, t);
    q[0] = k.r.x, q[1] = k.r.y;
    /* theta and s are sums of three rounded terms */
    double dth = 4 * DBL_EPSILON * (fabs(p->th0) + fabs(p->w * t) + fabs(p->al * t * t)),
           ds = 4 * DBL_EPSILON * (fabs(p->s0) + fabs(p->u * t) + fabs(p->b * t * t));
    *qerr = ds + mm_v2_norm(k.r) * (dth + 4 * DBL_EPSILON);
    return MM_OK;
}

static int fill(mm_table *tb, int row, const char *name, mm_v2 g, double th)
{
    mm_v2 m = mm_v2_rotate(g, -th);                         /* in the table's axes */
    tb->text[5 * row] = name;
    tb->cell[5 * row + 1] = g.x, tb->cell[5 * row + 2] = g.y;
    tb->cell[5 * row + 3] = m.x, tb->cell[5 * row + 4] = m.y;
    return row + 1;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    table p = {in[P_W].x, in[P_AL].x, in[P_TH0].x, in[P_S0].x, in[P_U].x, in[P_B].x, in[P_H].x};
    const double t = in[P_T].x, t_end = in[P_TEND].x;
    const int n = (int)in[P_POINTS].x;

    /* ---- at t: every term ---- */
    terms k = at(&p, t);
    mm_res_scalar(res, O_VREL, mm_v2_norm(k.vrel));
    mm_res_scalar(res, O_VTR, mm_v2_norm(k.vtr));
    mm_res_scalar(res, O_V, mm_v2_norm(k.v));
    mm_res_scalar(res, O_AREL, mm_v2_norm(k.arel));
    mm_res_scalar(res, O_ATT, mm_v2_norm(k.att));
    mm_res_scalar(res, O_ATN, mm_v2_norm(k.atn));
    mm_res_scalar(res, O_ACOR, mm_v2_norm(k.acor));
    mm_res_scalar(res, O_A, mm_v2_norm(k.a));
    mm_table *tv = mm_res_table(res, O_VTAB, 3), *ta = mm_res_table(res, O_ATAB, 5);
    if (!tv || !ta)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    int row = fill(tv, 0, "relative v_rel", k.vrel, k.th);
    row = fill(tv, row, "transport w x r", k.vtr, k.th);
    fill(tv, row, "absolute v", k.v, k.th);
    row = fill(ta, 0, "relative a_rel", k.arel, k.th);
    row = fill(ta, row, "transport, tangential alpha x r", k.att, k.th);
    row = fill(ta, row, "transport, centripetal w x (w x r)", k.atn, k.th);
    row = fill(ta, row, "Coriolis 2 w x v_rel", k.acor, k.th);
    fill(ta, row, "absolute a", k.a, k.th);

    /* ---- over [0, t_end] ---- */
    mm_series *path = mm_res_series(res, O_PATH, n), *slot = mm_res_series(res, O_RPATH, 2);
    mm_series *sv = mm_res_series(res, O_SV, n), *sa = mm_res_series(res, O_SA, n);
    mm_kin_samples smp;
    if (!path || !slot || !sv || !sa || mm_kin_samples_init(&smp, res, n, 2, err) != MM_OK)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_kin_grid(0, t_end, n, sv->x);
    double vmax = 0, amax = 0, size = 0;
    for (int i = 0; i < n; i++) {
        terms ki = at(&p, sv->x[i]);
        path->x[i] = ki.r.x, path->y[i] = ki.r.y;
        sa->x[i] = sv->x[i];
        sv->y[i] = mm_v2_norm(ki.v), sa->y[i] = mm_v2_norm(ki.acor);
        vmax = fmax(vmax, sv->y[i]), amax = fmax(amax, mm_v2_norm(ki.a));
        size = fmax(size, mm_v2_norm(ki.r));
        mm_kin_sample2(&smp, i, sv->x[i], ki.v, ki.a);
    }
    size = fmax(size, fabs(p.h)) * 1.2 + 1e-3;
    mm_v2 s0 = mm_v2_rotate((mm_v2){-size, p.h}, k.th), s1 = mm_v2_rotate((mm_v2){size, p.h}, k.th);
    slot->x[0] = s0.x, slot->y[0] = s0.y, slot->x[1] = s1.x, slot->y[1] = s1.y;

    /* the Coriolis theorem against differences of the absolute position */
    double wm = fmax(fabs(p.w), fabs(p.w + p.al * t_end)), h0 = 0.05 / fmax(1, wm);
    int rc = mm_kin_fd_samples(res, O_FDV, O_FDA, "dr/dt = v_rel + w x r", "d2r/dt2 = a_rel + transport + Coriolis",
                               fd_pos, &p, &smp, h0, err);
    if (rc != MM_OK)
        return rc;

    /* ---- the animation ---- */
    double t_show;
    int nf = mm_scene_frames(t_end, wm > 0 ? 2 * M_PI / wm : 0, &t_show);
    mm_res_method(res, "closed form (moving frame), checked by central differences", 0);
    return mm_kin_anim_turntable(res, nf, t_show, size, p.h, path, vmax, amax, frame, &p, err);
}

static const char *const references[] = {
    "F. P. Beer, E. R. Johnston, Vector Mechanics for Engineers: Dynamics, 9th ed., sections 15.10-15.11", NULL,
};

const mm_exercise mm_ex_kin_relative_motion = {
    .id = "kin-relative-motion", .chapter = 2, .section = "2.2.4",
    .title = "Relative motion: a slider on a turntable",
    .summary = "Absolute velocity and acceleration from the relative motion in a turning frame: transport "
               "terms and the Coriolis acceleration.",
    .tags = "kinematics, moving frame, relative motion, Coriolis, transport acceleration",
    .theory = "exercises/kin/relative_motion.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
