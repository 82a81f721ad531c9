/* plane_motion.c — kin-plane-motion: a ladder AB of length L slides with A
 * on the floor and B against the wall; A is pulled away from the wall at
 * constant speed vA.  theta is the ladder's angle with the floor.
 *
 *     A = (L cos theta, 0),  B = (0, L sin theta),  P = A + s (B - A)        (1)
 *     omega = vA / (L sin theta),  alpha = omega^2 cot theta                 (2)
 *     v_P = omega k x (P - I),  I = (L cos theta, L sin theta)              (3)
 *     a_P = a_A + alpha k x (P - A) - omega^2 (P - A)                        (4)
 *
 * Goal: in plane motion every velocity is a rotation about the
 * instantaneous centre I, where the normals to the velocities of A and B
 * meet; I moves along the space centrode (a circle of radius L about the
 * corner) while the body centrode (the circle on AB as diameter) rolls on
 * it.  The accelerations turn about another point, the acceleration pole.
 * Checks: I from the normals (line intersection) against I from one
 * velocity, r_A + k x v_A / omega; (3) and (4) against central differences
 * of the positions (1) as A moves; v_P = omega k x (P - I) and (4) against
 * the derivatives of (1) by the chain rule; the acceleration at the pole.
 * Reference: F. P. Beer, E. R. Johnston, Vector Mechanics for Engineers:
 * Dynamics, sections 15.6-15.8.
 */
#include <float.h>
#include <math.h>

#include "mm_geom.h"
#include "mm_kin.h"

enum { P_L, P_TH, P_VA, P_S, P_POINTS };

static const mm_param params[] = {
    [P_L] = {"L", "ladder length", "m", MM_REAL, 2, 0.01, 100, .help = "from A on the floor to B at the wall"},
    [P_TH] = {"theta", "angle with the floor", "rad", MM_REAL, M_PI / 3, 0.01, 1.56,
              .help = "the instant asked: 0 lying flat, pi/2 upright"},
    [P_VA] = {"vA", "speed of A away from the wall", "m/s", MM_REAL, 1, -10, 10,
              .help = "constant; negative pushes the ladder up the wall"},
    [P_S] = {"s", "place of P along AB", "", MM_REAL, 0.5, 0, 1, .help = "0 at A, 1 at B: 0.5 is the midpoint"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 141, 11, 2001,
                  .help = "samples of the plotted curves, theta from 80 to 10 degrees"},
};

enum {
    O_W, O_AL, O_VB, O_AB, O_ICX, O_ICY, O_VPX, O_VPY, O_VP, O_APX, O_APY, O_AP, O_QX, O_QY,
    O_SW, O_SVB, O_SPATH, O_FDV, O_FDA, O_ANIM
};

static const mm_output outputs[] = {
    [O_W] = MM_SCALAR("omega", "angular velocity of the ladder (counter-clockwise)", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_AL] = MM_SCALAR("alpha", "angular acceleration of the ladder", "rad/s^2", .flags = MM_ANSWER | MM_EXACT),
    [O_VB] = MM_SCALAR("v_B", "velocity of B (up the wall)", "m/s", .flags = MM_ANSWER | MM_EXACT),
    [O_AB] = MM_SCALAR("a_B", "acceleration of B (up the wall)", "m/s^2", .flags = MM_ANSWER | MM_EXACT),
    [O_ICX] = MM_SCALAR("ic_x", "instantaneous centre, x", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_ICY] = MM_SCALAR("ic_y", "instantaneous centre, y", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_VPX] = MM_SCALAR("vPx", "velocity of P, x", "m/s", .flags = MM_EXACT),
    [O_VPY] = MM_SCALAR("vPy", "velocity of P, y", "m/s", .flags = MM_EXACT),
    [O_VP] = MM_SCALAR("v_P", "speed of P", "m/s", .flags = MM_ANSWER | MM_EXACT),
    [O_APX] = MM_SCALAR("aPx", "acceleration of P, x", "m/s^2", .flags = MM_EXACT),
    [O_APY] = MM_SCALAR("aPy", "acceleration of P, y", "m/s^2", .flags = MM_EXACT),
    [O_AP] = MM_SCALAR("a_P", "magnitude of P's acceleration", "m/s^2", .flags = MM_ANSWER | MM_EXACT),
    [O_QX] = MM_SCALAR("pole_x", "acceleration pole (the point at rest in acceleration), x", "m", .flags = MM_EXACT),
    [O_QY] = MM_SCALAR("pole_y", "acceleration pole, y", "m", .flags = MM_EXACT),
    [O_SW] = MM_SERIES("omega", "angular velocity", "rad/s", "theta", "rad", .figure = "omega"),
    [O_SVB] = MM_SERIES("v_B", "velocity of B", "m/s", "theta", "rad", .figure = "v_B"),
    [O_SPATH] = MM_SERIES("path", "path of P", "m", "x", "m", .aspect = "equal", .figure = "path of P"),
    [O_FDV] = MM_KIN_FD_SERIES("fd_error_v", "worst error of the central difference of P vs eq. (3)", "m/s", "s"),
    [O_FDA] = MM_KIN_FD_SERIES("fd_error_a", "worst error of the second difference vs eq. (4)", "m/s^2", "s"),
    [O_ANIM] = MM_ANIMATION("the ladder sliding, its instantaneous centre on the space centrode, the body centrode "
                            "rolling on it, and the velocity field"),
};

typedef struct ladder {
    double L, vA, s;
} ladder;

typedef struct lstate {
    double th, w, al;
    mm_v2 A, B, P, I, vP, aP, aA;
} lstate;

/* everything at the angle th, eqs. (1)-(4); A moves at the constant vA */
static lstate at(const ladder *m, double th)
{
    lstate k;
    double c = cos(th), sn = sin(th);
    k.th = th;
    k.w = m->vA / (m->L * sn);                                 /* eq. (2) */
    k.al = k.w * k.w * c / sn;
    k.A = (mm_v2){m->L * c, 0}, k.B = (mm_v2){0, m->L * sn};
    k.P = mm_v2_add(k.A, mm_v2_scale(mm_v2_sub(k.B, k.A), m->s));
    k.I = (mm_v2){m->L * c, m->L * sn};
    k.vP = mm_v2_scale(mm_v2_perp(mm_v2_sub(k.P, k.I)), k.w);               /* eq. (3) */
    k.aA = (mm_v2){0, 0};
    mm_v2 d = mm_v2_sub(k.P, k.A);
    k.aP = mm_v2_add(k.aA, mm_v2_sub(mm_v2_scale(mm_v2_perp(d), k.al), mm_v2_scale(d, k.w * k.w)));   /* (4) */
    return k;
}

/* the angle when A has moved on by time tau from th0 */
static double th_after(const ladder *m, double th0, double tau)
{
    double x = m->L * cos(th0) + m->vA * tau;
    return acos(fmax(-1, fmin(1, x / m->L)));
}

/* P when A has moved on by h from the sample at the angle th */
static int fd_pos(double th, double h, double *q, double *qerr, void *ctx, mm_error *err)
{
    (void)err;
    const ladder *m = ctx;
    lstate k = at(m, th_after(m, th, h));
    q[0] = k.P.x, q[1] = k.P.y;
    /* acos near its ends: x / L known to eps, theta to eps / sin theta */
    *qerr = 8 * DBL_EPSILON * m->L / sin(k.th);
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    ladder m = {in[P_L].x, in[P_VA].x, in[P_S].x};
    const double th = in[P_TH].x;
    const int n = (int)in[P_POINTS].x;
    lstate k = at(&m, th);
    double big = m.L * (fabs(k.w) + fabs(k.al) + k.w * k.w);
    mm_res_scalar(res, O_W, k.w);
    mm_res_scalar(res, O_AL, k.al);
    /* B = (0, L sin th): its velocity L cos th th' and acceleration, th' = -omega */
    mm_res_scalar(res, O_VB, -m.L * cos(th) * k.w);
    mm_res_scalar(res, O_AB, -m.L * (cos(th) * k.al + sin(th) * k.w * k.w));
    mm_res_scalar(res, O_VPX, k.vP.x), mm_res_scalar(res, O_VPY, k.vP.y), mm_res_scalar(res, O_VP, mm_v2_norm(k.vP));
    mm_res_scalar(res, O_APX, k.aP.x), mm_res_scalar(res, O_APY, k.aP.y), mm_res_scalar(res, O_AP, mm_v2_norm(k.aP));
    if (k.w != 0) {
        mm_res_scalar(res, O_ICX, k.I.x), mm_res_scalar(res, O_ICY, k.I.y);
        /* I where the normals to v_A (vertical through A) and v_B
         * (horizontal through B) meet, against I = r_A + k x v_A / omega */
        mm_v2 I2, vA = {m.vA, 0};
        mm_geom_line_line(k.A, mm_v2_perp(vA), k.B, (mm_v2){1, 0}, &I2);
        mm_v2 I1 = mm_v2_add(k.A, mm_v2_scale(mm_v2_perp(vA), 1 / k.w));
        mm_res_check_abs(res, "instantaneous centre: normals to v_A and v_B vs r_A + k x v_A / omega [m]",
                         mm_v2_norm(mm_v2_sub(I1, I2)), 0, 16 * DBL_EPSILON * m.L);
        /* the acceleration pole Q: a_A + alpha k x d - omega^2 d = 0, d = Q - A
         * (with A at constant speed, a_A = 0 and the pole is A itself) */
        double w2 = k.w * k.w, det = w2 * w2 + k.al * k.al;
        mm_v2 dq = {(w2 * k.aA.x - k.al * k.aA.y) / det, (k.al * k.aA.x + w2 * k.aA.y) / det};
        mm_v2 Q = mm_v2_add(k.A, dq);
        mm_res_scalar(res, O_QX, Q.x), mm_res_scalar(res, O_QY, Q.y);
        /* B's acceleration by eq. (4) (d = B - A) against d2/dt2 of L sin theta */
        mm_v2 dB = mm_v2_sub(k.B, k.A);
        mm_v2 aB = mm_v2_sub(mm_v2_scale(mm_v2_perp(dB), k.al), mm_v2_scale(dB, w2));
        mm_res_check_abs(res, "a_B by eq. (4) from A vs d2/dt2 of L sin(theta) [m/s^2]", aB.y,
                         -m.L * (cos(th) * k.al + sin(th) * w2), 16 * DBL_EPSILON * big / sin(th));
        mm_res_check_abs(res, "a_B by eq. (4): no horizontal part (B runs on the wall) [m/s^2]", aB.x, 0,
                         16 * DBL_EPSILON * big / sin(th));
    } else {
        mm_res_warn(res, "vA = 0: the ladder is at rest and has no instantaneous centre");
    }
    /* eqs. (3)-(4) against the chain rule on (1): P = ((1-s) L cos th, s L sin th), th' = -omega */
    double tdot = -k.w, tdd = -k.al;
    mm_v2 vc = {-(1 - m.s) * m.L * sin(th) * tdot, m.s * m.L * cos(th) * tdot};
    mm_v2 ac = {-(1 - m.s) * m.L * (cos(th) * tdot * tdot + sin(th) * tdd),
                m.s * m.L * (cos(th) * tdd - sin(th) * tdot * tdot)};
    mm_res_check_abs(res, "v_P = omega k x (P - I) vs d/dt of (1) [m/s]", mm_v2_norm(mm_v2_sub(vc, k.vP)), 0,
                     16 * DBL_EPSILON * big);
    mm_res_check_abs(res, "a_P by eq. (4) vs d2/dt2 of (1) [m/s^2]", mm_v2_norm(mm_v2_sub(ac, k.aP)), 0,
                     16 * DBL_EPSILON * big / sin(th));

    /* ---- the slide from 80 to 10 degrees ---- */
    const double th1 = 80 * M_PI / 180, th2 = 10 * M_PI / 180;
    mm_series *sw = mm_res_series(res, O_SW, n), *svb = mm_res_series(res, O_SVB, n), *sp = mm_res_series(res, O_SPATH, n);
    mm_kin_samples smp;
    if (!sw || !svb || !sp || mm_kin_samples_init(&smp, res, n, 2, err) != MM_OK)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_kin_grid(th2, th1, n, sw->x);
    for (int i = 0; i < n; i++) {
        lstate ki = at(&m, sw->x[i]);
        svb->x[i] = sw->x[i];
        sw->y[i] = ki.w, svb->y[i] = -m.L * cos(ki.th) * ki.w;
        sp->x[i] = ki.P.x, sp->y[i] = ki.P.y;
        mm_kin_sample2(&smp, i, ki.th, ki.vP, ki.aP);
    }
    if (m.vA != 0) {
        /* a step that moves A by at most 2 % of L: stays within 10..80 degrees +- 2 */
        double h0 = 0.02 * m.L / fabs(m.vA);
        int rc = mm_kin_fd_samples(res, O_FDV, O_FDA, "dP/dt", "d2P/dt2", fd_pos, &m, &smp, h0, err);
        if (rc != MM_OK)
            return rc;
    }

    /* ---- the animation: A moving at vA from 80 to 10 degrees (or back) ---- */
    enum { NF = 72 };
    double ta = m.vA >= 0 ? th1 : th2, tb = m.vA >= 0 ? th2 : th1;       /* A moves away (or in) */
    double T = m.vA != 0 ? m.L * (cos(tb) - cos(ta)) / m.vA : 1;
    mm_kin_ladder_state fr[NF];
    for (int f = 0; f < NF; f++) {
        double tf = T * f / (NF - 1);
        lstate kf = at(&m, m.vA != 0 ? th_after(&m, ta, tf) : th);
        fr[f] = (mm_kin_ladder_state){tf, kf.A, kf.B, kf.I, kf.w};
    }
    mm_res_method(res, "closed form (instantaneous centre), checked by central differences", 0);
    return mm_kin_anim_ladder(res, NF, fr, m.L, sp, fabs(m.vA) / sin(th2), err);   /* vmax: B's speed at 10 deg */
}

static const char *const references[] = {
    "F. P. Beer, E. R. Johnston, Vector Mechanics for Engineers: Dynamics, 9th ed., sections 15.6-15.8", NULL,
};

const mm_exercise mm_ex_kin_plane_motion = {
    .id = "kin-plane-motion", .chapter = 2, .section = "2.3.3",
    .title = "Plane motion: the sliding ladder",
    .summary = "A ladder sliding down a wall: instantaneous centre, centrodes, the velocity field, angular "
               "acceleration and the acceleration pole.",
    .tags = "kinematics, rigid body, plane motion, instantaneous centre, centrode, acceleration pole",
    .theory = "exercises/kin/plane_motion.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .solve = solve,
};
