/* cam_follower.c — kin-cam-follower: a disc cam turning at omega lifts a
 * translating roller follower (offset e from the cam's centre) by h over
 * beta_rise, holds it over beta_dwell, lets it down over beta_return, and
 * holds it at the bottom for the rest of the turn.
 *
 *     s(theta) by the chosen law, v = omega s', a = omega^2 s'', j = omega^3 s'''  (1)
 *     pressure angle: tan phi = (s' - e) / (s0 + s),  s0 = sqrt((Rb + Rr)^2 - e^2)  (2)
 *     pitch curve P(theta) = R(-theta) (e, s0 + s),  rho from P', P''       (3)
 *     cam profile: P moved by Rr towards the cam;  rho_cam = rho_pitch - Rr   (4)
 *
 * Goal: the follower's motion laws (harmonic, cycloidal, 3-4-5 polynomial,
 * constant acceleration) and what they cost in velocity, acceleration and
 * jerk; the pressure angle; the cam profile that makes them, and where it
 * cannot: a roller larger than the pitch curve's radius of curvature
 * undercuts the cam (negative rho_cam, warned).
 * Checks: central differences of s against s' and s'' (error against the
 * step, order 2); the peak velocity and acceleration of the closed forms
 * against golden-section searches of the laws; the pitch curve's radius of
 * curvature (3) against the circle through three close points of it.
 * Reference: R. L. Norton, Cam Design and Manufacturing Handbook, 2nd ed.,
 * Industrial Press 2009, ch. 3, 7; Design of Machinery, ch. 8.
 */
#include <float.h>
#include <math.h>

#include "mm_cam.h"
#include "mm_geom.h"
#include "mm_kin.h"
#include "mm_opt.h"

enum { P_LAW, P_H, P_BR, P_BD, P_BT, P_RB, P_RR, P_E, P_W, P_TH, P_POINTS };

static const char *const laws[] = {"cycloidal", "harmonic", "polynomial345", "constant_acceleration", NULL};

static const mm_param params[] = {
    [P_LAW] = {"law", "motion law", "", MM_CHOICE, 0, 0, 3, .choices = laws,
               .help = "how the follower rises and falls: cycloidal and 3-4-5 keep the acceleration finite and "
                       "continuous; harmonic and constant acceleration jump in acceleration"},
    [P_H] = {"h", "lift", "m", MM_REAL, 0.02, 1e-4, 1, .help = "how far the follower rises"},
    [P_BR] = {"beta_rise", "rise angle", "rad", MM_REAL, M_PI / 2, 0.05, 5, .help = "cam angle of the rise"},
    [P_BD] = {"beta_dwell", "dwell angle at the top", "rad", MM_REAL, M_PI / 6, 0, 5,
              .help = "cam angle held at the top; the rest of the turn after the return is the bottom dwell"},
    [P_BT] = {"beta_return", "return angle", "rad", MM_REAL, M_PI / 2, 0.05, 5, .help = "cam angle of the return"},
    [P_RB] = {"Rb", "base circle radius", "m", MM_REAL, 0.05, 1e-3, 2, .help = "the cam's smallest radius"},
    [P_RR] = {"Rr", "roller radius", "m", MM_REAL, 0.01, 0, 1, .help = "0 for a knife-edge follower"},
    [P_E] = {"e", "offset", "m", MM_REAL, 0, -1, 1,
             .help = "distance of the follower's line from the cam's centre; lowers the pressure angle on the rise"},
    [P_W] = {"omega", "cam speed", "rad/s", MM_REAL, 10, -1000, 1000, .help = "constant, counter-clockwise positive"},
    [P_TH] = {"theta", "cam angle", "rad", MM_REAL, 0.7, -100, 100, .help = "the instant asked, from the start of the rise"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 121, 25, 1441, .help = "cam angles of the plots over the turn"},
};

enum {
    O_S, O_V, O_A, O_J, O_VMAX, O_AMAX, O_PHI, O_PHIMAX, O_RHOP, O_RHOC, O_UNDER,
    O_SS, O_SV, O_SA, O_SJ, O_SPHI, O_PROF, O_PITCH, O_FDV, O_FDA, O_ANIM
};

static const mm_output outputs[] = {
    [O_S] = MM_SCALAR("s", "follower lift", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_V] = MM_SCALAR("v", "follower velocity", "m/s", .flags = MM_ANSWER | MM_EXACT),
    [O_A] = MM_SCALAR("a", "follower acceleration", "m/s^2", .flags = MM_ANSWER | MM_EXACT),
    [O_J] = MM_SCALAR("jerk", "follower jerk", "m/s^3", .flags = MM_EXACT),
    [O_VMAX] = MM_SCALAR("v_max", "largest velocity over the turn", "m/s", .flags = MM_ANSWER | MM_EXACT),
    [O_AMAX] = MM_SCALAR("a_max", "largest acceleration over the turn", "m/s^2", .flags = MM_ANSWER | MM_EXACT),
    [O_PHI] = MM_SCALAR("pressure_angle", "pressure angle at theta", "rad", .flags = MM_ANSWER | MM_EXACT),
    [O_PHIMAX] = MM_SCALAR("pressure_angle_max", "largest pressure angle over the turn", "rad", .flags = MM_ANSWER),
    [O_RHOP] = MM_SCALAR("rho_pitch_min", "smallest radius of curvature of the pitch curve (convex parts)", "m"),
    [O_RHOC] = MM_SCALAR("rho_cam_min", "smallest radius of curvature of the cam profile (negative: undercut)", "m",
                         .flags = MM_ANSWER),
    [O_UNDER] = MM_SCALAR("undercut", "the roller undercuts the cam (1) or not (0)", "", .flags = MM_EXACT),
    [O_SS] = MM_SERIES("s", "lift", "m", "cam angle", "rad", .figure = "lift"),
    [O_SV] = MM_SERIES("v", "velocity", "m/s", "cam angle", "rad", .figure = "velocity"),
    [O_SA] = MM_SERIES("a", "acceleration", "m/s^2", "cam angle", "rad", .figure = "acceleration"),
    [O_SJ] = MM_SERIES("jerk", "jerk", "m/s^3", "cam angle", "rad", .figure = "jerk"),
    [O_SPHI] = MM_SERIES("pressure_angle", "pressure angle", "rad", "cam angle", "rad", .figure = "pressure angle"),
    [O_PROF] = MM_SERIES("profile", "cam profile", "m", "x", "m", .aspect = "equal", .figure = "cam"),
    [O_PITCH] = MM_SERIES("pitch_curve", "pitch curve (path of the roller's centre)", "m", "x", "m", .aspect = "equal",
                          .figure = "cam", .role = "reference"),
    [O_FDV] = MM_KIN_FD_SERIES("fd_error_v", "worst error of the central difference of s vs s'", "m", "rad"),
    [O_FDA] = MM_KIN_FD_SERIES("fd_error_a", "worst error of the second difference vs s''", "m", "rad"),
    [O_ANIM] = MM_ANIMATION("the cam turning, the roller follower rising and falling, its velocity"),
};

typedef mm_cam cam;

static int check(const mm_value *in, mm_error *err)
{
    double used = in[P_BR].x + in[P_BD].x + in[P_BT].x;
    if (used > 2 * M_PI)
        return mm_error_set(err, MM_ERANGE, "beta_dwell",
                            "rise, top dwell and return must fit in one turn: their sum is %g rad, more than 2 pi; "
                            "make beta_dwell at most %g rad", used, 2 * M_PI - in[P_BR].x - in[P_BT].x);
    if (fabs(in[P_E].x) >= in[P_RB].x + in[P_RR].x)
        return mm_error_set(err, MM_ERANGE, "e", "the offset must be less than Rb + Rr = %g m (the follower's line "
                            "must cross the pitch circle); got %g m", in[P_RB].x + in[P_RR].x, in[P_E].x);
    return MM_OK;
}

static int fd_pos(double ths, double h, double *q, double *qerr, void *ctx, mm_error *err)
{
    (void)err;
    const cam *m = ctx;
    double d[4];
    int seg;
    double th = ths + h;
    mm_cam_motion(m, th, d, &seg);
    q[0] = d[0];
    /* the law's polynomial or trigonometric terms (up to 31 h), and theta's
     * own rounding, reduced to a turn: s' eps (|theta| + 2 pi) */
    *qerr = 64 * DBL_EPSILON * m->h + 4 * DBL_EPSILON * fabs(d[1]) * (fabs(th) + 2 * M_PI);
    return MM_OK;
}

/* the pitch curve at th + e, for mm_kin_circle3 */
static int pitch_point(double th, double e, mm_v2 *P, void *ctx)
{
    mm_v2 K;
    mm_cam_points(ctx, th + e, P, &K);
    return 1;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    cam m = {(int)in[P_LAW].x, in[P_H].x, in[P_BR].x, in[P_BD].x, in[P_BT].x, in[P_RB].x, in[P_RR].x, in[P_E].x, 0};
    m.s0 = sqrt((m.Rb + m.Rr - m.e) * (m.Rb + m.Rr + m.e));
    const double w = in[P_W].x, theta = in[P_TH].x;
    const int n = (int)in[P_POINTS].x;

    /* ---- at theta ---- */
    double d[4];
    int seg;
    mm_cam_motion(&m, theta, d, &seg);
    mm_res_scalar(res, O_S, d[0]);
    mm_res_scalar(res, O_V, w * d[1]);
    mm_res_scalar(res, O_A, w * w * d[2]);
    mm_res_scalar(res, O_J, w * w * w * d[3]);
    mm_res_scalar(res, O_PHI, mm_cam_pressure(&m, d));
    /* the peaks: closed forms of the rise and the return, against a
     * golden-section search of each law over its segment */
    double p1, p2;
    mm_cam_peaks(m.law, &p1, &p2);
    double vr = p1 * m.h / m.br, vt = p1 * m.h / m.bt, ar = p2 * m.h / (m.br * m.br), at = p2 * m.h / (m.bt * m.bt);
    mm_res_scalar(res, O_VMAX, fabs(w) * fmax(vr, vt));
    mm_res_scalar(res, O_AMAX, w * w * fmax(ar, at));
    for (int k = 1; k <= 2; k++) {
        int s2 = (k == 1 ? vr >= vt : ar >= at) ? 0 : 2;
        double a0 = s2 == 0 ? 0 : m.br + m.bd, b0 = a0 + (s2 == 0 ? m.br : m.bt);
        mm_opt_result r;
        /* |s''| of the constant-acceleration law is flat: any point is the peak */
        int rc = mm_cam_peak_search(&m, k, s2, a0, b0 - 1e-12 * b0, 1e-9 * (b0 - a0), &r, err);
        if (rc != MM_OK)
            return rc;
        double want = k == 1 ? fmax(vr, vt) : fmax(ar, at);
        /* at the top of a smooth peak the value is known to eps, whatever the
         * place; at a corner (the constant-acceleration law's s', harmonic s''
         * at the ends) to the slope times the place's uncertainty: the
         * bracket, or the 1e-9 of the segment asked for */
        mm_res_check_abs(res, k == 1 ? "peak s' of the law by golden section vs its closed form"
                                     : "peak s'' of the law by golden section vs its closed form",
                         r.fx, want,
                         64 * DBL_EPSILON * want + (k == 1 ? fmax(ar, at) : fmax(ar, at) / fmin(m.br, m.bt)) *
                                                       fmax(r.bracket, 1e-9 * (b0 - a0)));
    }

    /* ---- over the turn ---- */
    mm_series *ser[5];
    for (int i = 0; i < 5; i++)
        if (!(ser[i] = mm_res_series(res, O_SS + i, n)))
            return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_series *prof = mm_res_series(res, O_PROF, n), *pitch = mm_res_series(res, O_PITCH, n);
    int ns = 0;
    double *th = mm_res_alloc(res, (size_t)n * sizeof *th), *d1 = mm_res_alloc(res, (size_t)n * sizeof *d1),
           *d2 = mm_res_alloc(res, (size_t)n * sizeof *d2);
    if (!prof || !pitch || !th || !d1 || !d2)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_kin_grid(0, 2 * M_PI, n, ser[0]->x);
    const double h0 = 0.01 * fmin(m.br, m.bt);
    double phimax = 0, trmin = 0, size = m.s0 + m.h + m.Rr;
    for (int i = 0; i < n; i++) {
        double x = ser[0]->x[i], di[4];
        int si;
        mm_cam_motion(&m, x, di, &si);
        for (int k = 1; k < 5; k++)
            ser[k]->x[i] = x;
        ser[0]->y[i] = di[0], ser[1]->y[i] = w * di[1], ser[2]->y[i] = w * w * di[2], ser[3]->y[i] = w * w * w * di[3];
        double phi = mm_cam_pressure(&m, di);
        ser[4]->y[i] = phi;
        phimax = fmax(phimax, fabs(phi));
        mm_v2 P, K;
        mm_cam_points(&m, x, &P, &K);
        pitch->x[i] = P.x, pitch->y[i] = P.y, prof->x[i] = K.x, prof->y[i] = K.y;
        /* samples for the differences: 4 h0 inside a moving segment */
        int inside = (si == 0 || si == 2) && fabs(x - mm_cam_near_jump(&m, x)) > 4 * h0;
        if (inside && i % 4 == 0)
            th[ns] = x, d1[ns] = di[1], d2[ns] = di[2], ns++;
    }
    /* the largest pressure angle and the smallest convex rho, refined */
    double tphi2, ephi, phibest = mm_cam_pressure_max(&m, &tphi2, &ephi);
    mm_res_scalar_err(res, O_PHIMAX, phibest, ephi, MM_ERR_ESTIMATE);
    double e, best = mm_cam_rho_pitch_min(&m, &trmin, &e);
    if (isfinite(best)) {
        mm_res_scalar_err(res, O_RHOP, best, e, MM_ERR_ESTIMATE);
        mm_res_scalar_err(res, O_RHOC, best - m.Rr, e, MM_ERR_ESTIMATE);
        int under = best < m.Rr;
        mm_res_scalar_text(res, O_UNDER, under, under ? "undercut" : "no undercut");
        if (under)
            mm_res_warn(res, "undercut: the pitch curve's radius of curvature falls to %.4g m near cam angle %.4g rad, "
                             "less than the roller's %.4g m; the cam profile there would need a negative radius "
                             "(it loops over itself) and cannot be cut: enlarge Rb, shrink Rr, or spread the rise "
                             "over a larger angle", best, trmin, m.Rr);
        /* rho of eq. (3) against the circle through three pitch points */
        double d3[4];
        int s3;
        mm_cam_motion(&m, trmin, d3, &s3);
        double rp = mm_cam_rho_pitch(&m, d3), R3[3], dth = 0.02 * rp / hypot(m.s0 + d3[0], d3[1] - m.e);
        int ok = mm_kin_circle3(pitch_point, &m, trmin, dth, R3);
        double ds = 0.005 * rp, rnd = 64 * DBL_EPSILON * (size + rp) * rp * rp / (ds * ds);
        /* not across a jump of s'' (harmonic and constant acceleration):
         * there rho itself jumps and the circle straddles the jump */
        if (ok && s3 != 1 && s3 != 3 && fabs(trmin - mm_cam_near_jump(&m, trmin)) > 4 * dth)
            mm_res_check_abs(res, "rho of the pitch curve by eq. (3) vs the circle through three of its points", R3[2],
                             rp, 2 * fabs(R3[1] - R3[2]) + rnd);
    }
    if (phimax > 30 * M_PI / 180)
        mm_res_warn(res, "the pressure angle reaches %.1f degrees (above 30): the follower is pushed sideways in its "
                         "guide more than it is lifted", phimax * 180 / M_PI);
    mm_kin_samples smp = {n, ns, 1, th, d1, d2};
    int rc = mm_kin_fd_samples(res, O_FDV, O_FDA, "ds/dtheta", "d2s/dtheta2", fd_pos, &m, &smp, h0, err);
    if (rc != MM_OK)
        return rc;

    mm_res_method(res, "closed-form motion laws; pitch curve and profile by rotation; checked by central differences", 0);
    return mm_kin_anim_cam(res, &m, w, fabs(w) * fmax(vr, vt), size, err);   /* 36 frames a turn */
}

static const char *const references[] = {
    "R. L. Norton, Cam Design and Manufacturing Handbook, 2nd ed., Industrial Press 2009, ch. 3 and 7",
    "R. L. Norton, Design of Machinery, 5th ed., McGraw-Hill 2012, ch. 8", NULL,
};

const mm_exercise mm_ex_kin_cam_follower = {
    .id = "kin-cam-follower", .chapter = 2, .section = "2.4.4",
    .title = "Cam and roller follower",
    .summary = "A disc cam lifting a roller follower: motion laws, velocity, acceleration and jerk, pressure "
               "angle, the cam profile and its undercutting.",
    .tags = "kinematics, mechanism, cam, follower, motion law, pressure angle, undercutting",
    .theory = "exercises/kin/cam_follower.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
