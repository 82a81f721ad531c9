/* space_motion.c — kin-space-motion: a rigid body turning about a fixed
 * point, its attitude given by three Euler angles that change at constant
 * rates.
 *
 *     R = R_i(a) R_j(b) R_k(c)                                          (1)
 *     w = a' e_i + b' R_i(a) e_j + c' R_i(a) R_j(b) e_k = B(a, b) rates  (2)
 *     dR/dt = [w]x R,   d2R/dt2 = ([w']x + [w]x^2) R                      (3)
 *
 * Goal: build a rotation matrix from Euler angles (intrinsic sequences),
 * find the angular velocity from the angle rates, read the angles back from
 * the matrix, and meet gimbal lock: where the second angle lines the first
 * and third axes up (b = 0, pi for z-y-z; b = +-pi/2 for z-y-x), det B = 0,
 * only a + c (or a - c) is determined, and no rates give a turn about the
 * missing axis.
 * Checks: R orthogonal with det 1; R against the product of three
 * quaternions (an independent construction); the angles read back (or, at
 * the lock, R rebuilt from them); (3) against central differences of R(t)
 * (the error against the step, order 2).
 * Reference: J. J. Craig, Introduction to Robotics, 3rd ed., ch. 2 and
 * appendix B; E. J. Haug, Computer Aided Kinematics and Dynamics of
 * Mechanical Systems, ch. 6.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "mm_geom.h"
#include "mm_kin.h"
#include "mm_scene.h"

enum { P_SEQ, P_A, P_B, P_C, P_AD, P_BD, P_CD, P_POINT, P_TEND, P_POINTS };

static const char *const seqs[] = {"zyx", "zyz", "zxz", "xyz", NULL};
static const int seq_axes[4][3] = {{2, 1, 0}, {2, 1, 2}, {2, 0, 2}, {0, 1, 2}};

static const mm_param params[] = {
    [P_SEQ] = {"sequence", "Euler sequence", "", MM_CHOICE, 0, 0, 3, .choices = seqs,
               .help = "axes of the three turns, each about the axis as already turned: zyx is yaw, pitch, roll"},
    [P_A] = {"phi", "first angle", "rad", MM_REAL, 0.5, -10, 10, .help = "about the first axis of the sequence"},
    [P_B] = {"theta", "second angle", "rad", MM_REAL, 0.8, -10, 10,
             .help = "gimbal lock at +-pi/2 (zyx, xyz) or 0, pi (zyz, zxz)"},
    [P_C] = {"psi", "third angle", "rad", MM_REAL, 0.3, -10, 10, .help = "about the third axis"},
    [P_AD] = {"phi_dot", "rate of the first angle", "rad/s", MM_REAL, 1, -20, 20, .help = "constant"},
    [P_BD] = {"theta_dot", "rate of the second angle", "rad/s", MM_REAL, 0.5, -20, 20, .help = "constant"},
    [P_CD] = {"psi_dot", "rate of the third angle", "rad/s", MM_REAL, 2, -20, 20, .help = "constant"},
    [P_POINT] = {"point", "a point of the body", "m", MM_VECTOR, 0, -10, 10, "0.3,0.2,0.1", .max_cols = 3,
                 .help = "its body coordinates x, y, z from the fixed point"},
    [P_TEND] = {"t_end", "duration of the motion shown", "s", MM_REAL, 4, 0.01, 10,
                .help = "the angles change at their rates from t = 0 (the instant asked) to t_end"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 201, 11, 2001, .help = "samples of the plotted curves"},
};

enum {
    O_WX, O_WY, O_WZ, O_W, O_WBX, O_WBY, O_WBZ, O_AX, O_AY, O_AZ, O_ANG, O_DETB, O_LOCK, O_TLOCK, O_VP,
    O_R, O_BACK, O_SANG, O_SDET, O_SW, O_FDV, O_FDA, O_ANIM
};

static const char *const rcols[] = {"row", "x", "y", "z", NULL}, *const runits[] = {"", "", "", "", NULL};
static const char *const bcols[] = {"angle", "given", "read_back", NULL}, *const bunits[] = {"", "rad", "rad", NULL};

static const mm_output outputs[] = {
    [O_WX] = MM_SCALAR("omega_x", "angular velocity, space x", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_WY] = MM_SCALAR("omega_y", "angular velocity, space y", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_WZ] = MM_SCALAR("omega_z", "angular velocity, space z", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_W] = MM_SCALAR("omega", "magnitude of the angular velocity", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_WBX] = MM_SCALAR("omega_body_x", "angular velocity, body x", "rad/s", .flags = MM_EXACT),
    [O_WBY] = MM_SCALAR("omega_body_y", "angular velocity, body y", "rad/s", .flags = MM_EXACT),
    [O_WBZ] = MM_SCALAR("omega_body_z", "angular velocity, body z", "rad/s", .flags = MM_EXACT),
    [O_AX] = MM_SCALAR("alpha_x", "angular acceleration, space x", "rad/s^2", .flags = MM_EXACT),
    [O_AY] = MM_SCALAR("alpha_y", "angular acceleration, space y", "rad/s^2", .flags = MM_EXACT),
    [O_AZ] = MM_SCALAR("alpha_z", "angular acceleration, space z", "rad/s^2", .flags = MM_EXACT),
    [O_ANG] = MM_SCALAR("rotation_angle", "angle of the single turn equal to R", "rad", .flags = MM_ANSWER | MM_EXACT),
    [O_DETB] = MM_SCALAR("det_B", "determinant of the Euler-rate matrix B (0: gimbal lock)", "", .flags = MM_EXACT),
    [O_LOCK] = MM_SCALAR("gimbal_lock", "in gimbal lock at t = 0 (1) or not (0)", "", .flags = MM_ANSWER | MM_EXACT),
    [O_TLOCK] = MM_SCALAR("t_lock", "first time the motion passes a gimbal lock", "s", .flags = MM_EXACT),
    [O_VP] = MM_SCALAR("v_P", "speed of the body point", "m/s", .flags = MM_EXACT),
    [O_R] = MM_TABLE("R", "rotation matrix (body to space)", rcols, runits),
    [O_BACK] = MM_TABLE("angles_back", "the angles read back from R", bcols, bunits),
    [O_SANG] = MM_SERIES("theta", "second angle", "rad", "t", "s", .figure = "second angle"),
    [O_SDET] = MM_SERIES("det_B", "det B: zero at a gimbal lock", "", "t", "s", .figure = "det B"),
    [O_SW] = MM_SERIES("omega", "magnitude of the angular velocity", "rad/s", "t", "s", .figure = "omega"),
    [O_FDV] = MM_KIN_FD_SERIES("fd_error_v", "worst error of the central difference of R vs [w]x R", "1/s", "s"),
    [O_FDA] = MM_KIN_FD_SERIES("fd_error_a", "worst error of the second difference vs ([w']x + [w]x^2) R",
                               "1/s^2", "s"),
    [O_ANIM] = MM_ANIMATION("the body (a box) turning about the fixed point, its axes and angular velocity"),
};

typedef struct att {
    int seq[3];
    double a0[3], rate[3];
} att;

static void angles_at(const att *m, double t, double ang[3])
{
    for (int i = 0; i < 3; i++)
        ang[i] = m->a0[i] + m->rate[i] * t;
}

/* omega (space) and its rate w' = dB/dt rates, by differentiating (2):
 * d/dt R_i(a) e_j = a' e_i x (R_i(a) e_j), and so on */
static void omega_at(const att *m, double t, mm_v3 *w, mm_v3 *wd)
{
    double ang[3], B[9];
    angles_at(m, t, ang);
    mm_geom_euler_rates(m->seq, ang, 0, B);
    mm_v3 c0 = {B[0], B[3], B[6]}, c1 = {B[1], B[4], B[7]}, c2 = {B[2], B[5], B[8]};
    *w = mm_v3_add(mm_v3_add(mm_v3_scale(c0, m->rate[0]), mm_v3_scale(c1, m->rate[1])), mm_v3_scale(c2, m->rate[2]));
    mm_v3 w1 = mm_v3_scale(c0, m->rate[0]), w12 = mm_v3_add(w1, mm_v3_scale(c1, m->rate[1]));
    mm_v3 d1 = mm_v3_cross(w1, c1), d2 = mm_v3_cross(w12, c2);      /* how the 2nd and 3rd axes turn */
    *wd = mm_v3_add(mm_v3_scale(d1, m->rate[1]), mm_v3_scale(d2, m->rate[2]));
}

static int check(const mm_value *in, mm_error *err)
{
    if (in[P_POINT].cols != 3)
        return mm_error_set(err, MM_ERANGE, "point", "point needs 3 body coordinates x,y,z; got %d", in[P_POINT].cols);
    return MM_OK;
}

static int fd_pos(double ts, double h, double *q, double *qerr, void *ctx, mm_error *err)
{
    (void)err;
    const att *m = ctx;
    double ang[3], t = ts + h, big = 0;
    angles_at(m, t, ang);
    mm_geom_euler_matrix(m->seq, ang, q);
    for (int k = 0; k < 3; k++)
        big += fabs(m->a0[k]) + fabs(m->rate[k] * t);
    *qerr = (8 + 4 * big) * DBL_EPSILON;            /* three rounded angles, two products */
    return MM_OK;
}

/* the animation's frame at t: R and omega */
static void frame(double t, double R[9], mm_v3 *w, void *ctx)
{
    double ang[3];
    mm_v3 wd;
    angles_at(ctx, t, ang);
    mm_geom_euler_matrix(((const att *)ctx)->seq, ang, R);
    omega_at(ctx, t, w, &wd);
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    att m;
    memcpy(m.seq, seq_axes[(int)in[P_SEQ].x], sizeof m.seq);
    m.a0[0] = in[P_A].x, m.a0[1] = in[P_B].x, m.a0[2] = in[P_C].x;
    m.rate[0] = in[P_AD].x, m.rate[1] = in[P_BD].x, m.rate[2] = in[P_CD].x;
    const double *pp = in[P_POINT].data, t_end = in[P_TEND].x;
    const int n = (int)in[P_POINTS].x, proper = m.seq[0] == m.seq[2];
    mm_v3 p = {pp[0], pp[1], pp[2]};

    /* ---- at t = 0: R, omega, the angles back ---- */
    double R[9], Rq[9], Rt[9], B[9], det_err;
    mm_geom_euler_matrix(m.seq, m.a0, R);
    mm_geom_euler_rates(m.seq, m.a0, 0, B);
    mm_table *tr = mm_res_table(res, O_R, 3);
    if (!tr)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (int i = 0; i < 3; i++) {
        tr->cell[4 * i] = i + 1;
        for (int j = 0; j < 3; j++)
            tr->cell[4 * i + 1 + j] = R[3 * i + j];
    }
    double big = 0;
    for (int k = 0; k < 3; k++)
        big += fabs(m.a0[k]);
    mm_res_check_abs(res, "R^T R = I: worst entry error", mm_geom_rot_orth_error(R, &det_err), 0, 16 * DBL_EPSILON);
    mm_res_check_abs(res, "det R = 1", det_err, 0, 16 * DBL_EPSILON);
    mm_geom_euler_quat_matrix(m.seq, m.a0, Rq);
    double dq = mm_geom_m3_maxdiff(R, Rq);
    mm_res_check_abs(res, "R from three rotation matrices vs from three quaternions: worst entry", dq, 0,
                     (16 + 4 * big) * DBL_EPSILON);
    mm_v3 w, wd, axis;
    omega_at(&m, 0, &w, &wd);
    mm_geom_m3_transpose(R, Rt);
    mm_v3 wb = mm_geom_m3_apply(Rt, w);
    mm_res_scalar(res, O_WX, w.x), mm_res_scalar(res, O_WY, w.y), mm_res_scalar(res, O_WZ, w.z);
    mm_res_scalar(res, O_W, mm_v3_norm(w));
    mm_res_scalar(res, O_WBX, wb.x), mm_res_scalar(res, O_WBY, wb.y), mm_res_scalar(res, O_WBZ, wb.z);
    mm_res_scalar(res, O_AX, wd.x), mm_res_scalar(res, O_AY, wd.y), mm_res_scalar(res, O_AZ, wd.z);
    double angle;
    mm_geom_rot_log(R, &axis, &angle);
    mm_res_scalar(res, O_ANG, angle);
    double detB = mm_geom_m3_det(B);
    mm_res_scalar(res, O_DETB, detB);
    mm_res_scalar(res, O_VP, mm_v3_norm(mm_v3_cross(w, mm_geom_m3_apply(R, p))));

    /* the angles back from R; gimbal lock within 1e-8 of the lock */
    double back[3], cond, Rb[9];
    int lock = mm_geom_euler_angles(m.seq, R, back, 1e-8, &cond);
    mm_res_scalar_text(res, O_LOCK, lock, lock ? "gimbal lock: first and third axes in line" : "no gimbal lock");
    mm_table *tb = mm_res_table(res, O_BACK, 3);
    if (!tb)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    static const char *const names[3] = {"phi", "theta", "psi"};
    for (int i = 0; i < 3; i++) {
        tb->text[3 * i] = names[i];
        tb->cell[3 * i + 1] = m.a0[i];
        tb->cell[3 * i + 2] = back[i];
    }
    /* R rebuilt from the angles read back: rounding grows like cond near the lock */
    mm_geom_euler_matrix(m.seq, back, Rb);
    double db = mm_geom_m3_maxdiff(R, Rb);
    mm_res_check_abs(res, lock ? "R rebuilt from the angles read back (at the lock, with psi = 0)"
                               : "R rebuilt from the angles read back",
                     db, 0, lock ? 1e-7 : 32 * DBL_EPSILON * fmin(cond, 1e8));
    if (lock) {
        /* which sum survives: R is unchanged by phi + d, psi + d when it depends on phi - psi */
        double sh[3] = {m.a0[0] + 0.1, m.a0[1], m.a0[2] + 0.1}, Rs[9];
        mm_geom_euler_matrix(m.seq, sh, Rs);
        double ds = mm_geom_m3_maxdiff(Rs, R);
        mm_res_warn(res, "gimbal lock: theta puts the first and third axes in line, so only %s is determined (psi "
                         "is read back as 0), det B = 0, and no angle rates give a turn about the axis square to both",
                    ds < 1e-6 ? "phi - psi" : "phi + psi");
    }
    /* the first lock the motion meets: theta(t) = pi k (proper) or pi/2 + pi k */
    if (m.rate[1] != 0) {
        double off = proper ? 0 : M_PI / 2, k = (m.a0[1] - off) / M_PI;
        double kn = m.rate[1] > 0 ? floor(k) + 1 : ceil(k) - 1;
        double tl = (off + M_PI * kn - m.a0[1]) / m.rate[1];
        if (tl <= t_end) {
            mm_res_scalar(res, O_TLOCK, tl);
            mm_res_warn(res, "the motion passes a gimbal lock at t = %.4g s (theta = %.4g rad): there the Euler "
                             "angles stop describing the turn smoothly", tl, off + M_PI * kn);
        }
    }

    /* ---- over [0, t_end] ---- */
    mm_series *sa = mm_res_series(res, O_SANG, n), *sd = mm_res_series(res, O_SDET, n), *sw = mm_res_series(res, O_SW, n);
    mm_kin_samples smp;
    if (!sa || !sd || !sw || mm_kin_samples_init(&smp, res, n, 9, err) != MM_OK)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_kin_grid(0, t_end, n, sa->x);
    double wmax = 0;
    for (int i = 0; i < n; i++) {
        double ti = sa->x[i], ang[3], Bi[9], Ri[9], W[9], WD[9], D1[9], D2[9];
        angles_at(&m, ti, ang);
        mm_geom_euler_rates(m.seq, ang, 0, Bi);
        mm_v3 wi, wdi;
        omega_at(&m, ti, &wi, &wdi);
        sd->x[i] = sw->x[i] = ti;
        sa->y[i] = ang[1], sd->y[i] = mm_geom_m3_det(Bi), sw->y[i] = mm_v3_norm(wi);
        wmax = fmax(wmax, sw->y[i]);
        if (mm_kin_sampled(&smp, i)) {
            /* eq. (3): R' = [w]x R, R'' = ([w']x + [w]x^2) R */
            mm_geom_euler_matrix(m.seq, ang, Ri);
            mm_geom_skew(wi, W), mm_geom_skew(wdi, WD);
            mm_geom_m3_mul(W, Ri, D1);
            mm_geom_m3_mul(W, D1, D2);
            mm_geom_m3_mul(WD, Ri, WD);
            for (int k = 0; k < 9; k++)
                D2[k] += WD[k];
            mm_kin_sample(&smp, i, ti, D1, D2);
        }
    }
    double h0 = 0.05 / fmax(1, wmax);
    int rc = mm_kin_fd_samples(res, O_FDV, O_FDA, "dR/dt = [w]x R", "d2R/dt2 = ([w']x + [w]x^2) R", fd_pos, &m, &smp,
                               h0, err);
    if (rc != MM_OK)
        return rc;

    /* ---- the animation: a box and its axes, seen isometrically ---- */
    double t_show;
    int nf = mm_scene_frames(t_end, wmax > 0 ? 2 * M_PI / wmax : 0, &t_show);
    mm_res_method(res, "closed form (Euler angles), checked by quaternions and central differences", 0);
    return mm_kin_anim_box(res, nf, t_show, wmax, p, frame, &m, err);
}

static const char *const references[] = {
    "J. J. Craig, Introduction to Robotics, 3rd ed., Pearson 2005, ch. 2 and appendix B",
    "E. J. Haug, Computer Aided Kinematics and Dynamics of Mechanical Systems, Allyn and Bacon 1989, ch. 6", NULL,
};

const mm_exercise mm_ex_kin_space_motion = {
    .id = "kin-space-motion", .chapter = 2, .section = "2.3.4",
    .title = "Motion in space: rotation matrices and Euler angles",
    .summary = "A body turning about a fixed point: its rotation matrix from Euler angles, the angular velocity "
               "from their rates, the angles read back, and gimbal lock.",
    .tags = "kinematics, rigid body, rotation matrix, Euler angles, angular velocity, gimbal lock, quaternion",
    .theory = "exercises/kin/space_motion.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
