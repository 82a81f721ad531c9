/* robot_2link.c — dyn-robot-2link: the joint torques that move a two-link
 * arm along a planned trajectory, and the forward simulation that must
 * reproduce it.
 *
 *     tau = M(q) q'' + c(q, q') + G(q)                                   (1)
 *
 * Two uniform slender rods in a vertical plane, driven at the shoulder and
 * the elbow.  The joint angles follow a quintic in time from rest to rest
 * (zero velocity and acceleration at both ends); eq. (1) gives the torques
 * in closed form (inverse dynamics).  Feeding those torques to the
 * equations of motion and integrating them (forward dynamics, DOP853) must
 * bring the arm along the same path: the check, with its error.  The power
 * the motors put in must equal the rise of the energy (a second check, by
 * quadrature).  Singular configurations on the way (the arm stretched, det J
 * = l1 l2 sin q2 = 0, the reach limit l1 + l2) are detected; a target that
 * folds link 2 onto link 1 is unreachable (422).
 * Reference: J. J. Craig, Introduction to Robotics, 3rd ed., ch. 6-7;
 * M. W. Spong, S. Hutchinson, M. Vidyasagar, Robot Modeling and Control,
 * sections 5.3 (quintic), 7.3 (two-link planar arm).
 */
#include <float.h>
#include <math.h>

#include "mm_dyn.h"
#include "mm_exhelp.h"
#include "mm_multibody.h"
#include "mm_roots.h"
#include "mm_scene.h"

enum { P_L1, P_L2, P_M1, P_M2, P_G, P_TRAJ, P_Q10, P_Q20, P_Q11, P_Q21, P_T, P_POINTS };

static const char *const trajectories[] = {"quintic", "cubic", NULL};

static const mm_param params[] = {
    [P_L1] = {"l1", "length of link 1", "m", MM_REAL, 1, 0.05, 10, .help = "shoulder to elbow"},
    [P_L2] = {"l2", "length of link 2", "m", MM_REAL, 1, 0.05, 10, .help = "elbow to tip"},
    [P_M1] = {"m1", "mass of link 1", "kg", MM_REAL, 1, 0.01, 100, .help = "a uniform slender rod"},
    [P_M2] = {"m2", "mass of link 2", "kg", MM_REAL, 1, 0.01, 100, .help = "a uniform slender rod"},
    [P_G] = {"g", "gravity", "m/s^2", MM_REAL, 9.81, 0, 100,
             .help = "acceleration of gravity along -y; 0 for an arm moving in a horizontal plane"},
    [P_TRAJ] = {"trajectory", "time law", "", MM_CHOICE, 0, 0, 0, .choices = trajectories,
                .help = "quintic: zero velocity and acceleration at both ends; cubic: zero velocity only "
                        "(the acceleration, and the torque, jump at the ends)"},
    [P_Q10] = {"q1_0", "start angle of the shoulder", "rad", MM_REAL, 0, -2 * M_PI, 2 * M_PI,
               .help = "link 1 from the +x axis, counter-clockwise"},
    [P_Q20] = {"q2_0", "start angle of the elbow", "rad", MM_REAL, 0, -M_PI, M_PI,
               .help = "link 2 relative to link 1; 0 is the stretched arm, +-pi folds link 2 onto link 1 "
                       "(out of reach)"},
    [P_Q11] = {"q1_1", "target angle of the shoulder", "rad", MM_REAL, M_PI / 2, -2 * M_PI, 2 * M_PI,
               .help = "where q1 ends after T seconds"},
    [P_Q21] = {"q2_1", "target angle of the elbow", "rad", MM_REAL, M_PI / 2, -M_PI, M_PI,
               .help = "where q2 ends; the elbow's range is -pi < q2 < pi"},
    [P_T] = {"T", "duration of the move", "s", MM_REAL, 2, 0.1, 20,
             .help = "time from start to target; halving it quadruples the inertial torques"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 201, 11, 2001,
                  .help = "samples of the trajectory and the torques returned for the plots"},
};

enum {
    O_TAU1_MAX, O_TAU2_MAX, O_T_TAU1, O_T_TAU2, O_WORK, O_DV, O_REACH, O_DETJ_MIN, O_T_SING,
    O_Q1, O_Q2, O_TAU1, O_TAU2, O_TAU1_STATIC, O_TAU2_STATIC, O_DETJ, O_ANIM
};

static const mm_output outputs[] = {
    [O_TAU1_MAX] = MM_SCALAR("tau1_max", "largest shoulder torque |tau1|", "N m", .flags = MM_ANSWER),
    [O_TAU2_MAX] = MM_SCALAR("tau2_max", "largest elbow torque |tau2|", "N m", .flags = MM_ANSWER),
    [O_T_TAU1] = MM_SCALAR("t_tau1_max", "time of the largest |tau1|", "s"),
    [O_T_TAU2] = MM_SCALAR("t_tau2_max", "time of the largest |tau2|", "s"),
    [O_WORK] = MM_SCALAR("work", "work done by the two motors", "J", .flags = MM_ANSWER),
    [O_DV] = MM_SCALAR("delta_V", "rise of the potential energy", "J", .flags = MM_EXACT),
    [O_REACH] = MM_SCALAR("reach_max", "farthest the tip gets from the shoulder", "m",
                          .flags = MM_ANSWER | MM_EXACT),
    [O_DETJ_MIN] = MM_SCALAR("det_J_min", "smallest |det J| = l1 l2 |sin q2| on the way (0: singular)", "m^2",
                             .flags = MM_EXACT),
    [O_T_SING] = MM_SCALAR("t_singular", "time the arm passes the stretched (singular) configuration", "s"),
    [O_Q1] = MM_SERIES("q1", "shoulder angle (planned)", "rad", "t", "s", .figure = "angles"),
    [O_Q2] = MM_SERIES("q2", "elbow angle (planned)", "rad", "t", "s", .figure = "angles"),
    [O_TAU1] = MM_SERIES("tau1", "shoulder torque", "N m", "t", "s", .figure = "torques"),
    [O_TAU2] = MM_SERIES("tau2", "elbow torque", "N m", "t", "s", .figure = "torques"),
    [O_TAU1_STATIC] = MM_SERIES("tau1_static", "shoulder torque holding the arm still (gravity only)", "N m",
                                "t", "s", .figure = "torques", .role = "reference"),
    [O_TAU2_STATIC] = MM_SERIES("tau2_static", "elbow torque holding the arm still (gravity only)", "N m", "t",
                                "s", .figure = "torques", .role = "reference"),
    [O_DETJ] = MM_SERIES("det_J", "det J = l1 l2 sin q2 (0 at the singular configurations)", "m^2", "t", "s",
                         .figure = "singularity"),
    [O_ANIM] = MM_ANIMATION("the arm moving, with the planned path of its tip"),
};

static mm_dyn_plan plan_of(const mm_value *in)
{
    mm_dyn_plan p = {.arm = {.l1 = in[P_L1].x, .l2 = in[P_L2].x, .m1 = in[P_M1].x, .m2 = in[P_M2].x, .g = in[P_G].x},
              .quintic = (int)in[P_TRAJ].x == 0, .T = in[P_T].x, .t_left = -1};
    p.q0[0] = in[P_Q10].x;
    p.q0[1] = in[P_Q20].x;
    p.dq[0] = in[P_Q11].x - p.q0[0];
    p.dq[1] = in[P_Q21].x - p.q0[1];
    return p;
}

#define MAX_EXPONENT 36      /* e^36 = 4e15: past it an open-loop simulation is noise */

static int check(const mm_value *in, mm_error *err)
{
    mm_dyn_plan p = plan_of(in);
    double E = mm_dyn_plan_growth(&p);
    if (E > MAX_EXPONENT)
        return mm_error_set(err, MM_ERANGE, "T",
                            "along this move the arm balances so far above its joints, for so long, that an "
                            "open-loop simulation would amplify its errors by about e^%.0f: no digit of it could "
                            "be trusted; shorten T (or lower g, or choose a path that hangs lower)", E);
    return MM_OK;
}

/* ---- solve ------------------------------------------------------------------------ */

#define RTOL 1e-12

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    mm_dyn_plan p = plan_of(in);
    const mm_robot2 *s = &p.arm;
    int n = (int)in[P_POINTS].x;
    /* the elbow's range: at q2 = +-pi link 2 would lie on link 1 */
    for (int k = 0; k < 2; k++) {
        int pi = k == 0 ? P_Q20 : P_Q21;
        if (fabs(in[pi].x) >= M_PI)
            return mm_error_set(err, MM_ESINGULAR, params[pi].name,
                                "%s = %.6g rad is out of reach: it folds link 2 onto link 1 (the links "
                                "collide); the elbow's range is -pi < q2 < pi",
                                params[pi].name, in[pi].x);
    }

    /* the path, the torques (eq. 1) and the gravity-only torques */
    mm_series *sq1 = mm_res_series(res, O_Q1, n), *sq2 = mm_res_series(res, O_Q2, n);
    mm_series *st1 = mm_res_series(res, O_TAU1, n), *st2 = mm_res_series(res, O_TAU2, n);
    mm_series *ss1 = mm_res_series(res, O_TAU1_STATIC, n), *ss2 = mm_res_series(res, O_TAU2_STATIC, n);
    mm_series *sdj = mm_res_series(res, O_DETJ, n);
    if (!sq1 || !sq2 || !st1 || !st2 || !ss1 || !ss2 || !sdj)
        return MM_ENOMEM;
    mm_linspace(0, p.T, n, sq1->x);
    for (int i = 0; i < n; i++) {
        double t = sq1->x[i], q[2], qd[2], qdd[2], tau[2], zero[2] = {0, 0}, tst[2];
        mm_dyn_plan_at(&p, t, q, qd, qdd);
        mm_robot2_inverse(s, q, qd, qdd, tau);
        mm_robot2_inverse(s, q, zero, zero, tst);
        sq2->x[i] = st1->x[i] = st2->x[i] = ss1->x[i] = ss2->x[i] = sdj->x[i] = t;
        sq1->y[i] = q[0], sq2->y[i] = q[1];
        st1->y[i] = tau[0], st2->y[i] = tau[1];
        ss1->y[i] = tst[0], ss2->y[i] = tst[1];
        sdj->y[i] = s->l1 * s->l2 * sin(q[1]);
    }

    double t1, t2, e1, e2, T1 = mm_dyn_plan_peak(&p, 0, &t1, &e1), T2 = mm_dyn_plan_peak(&p, 1, &t2, &e2);
    mm_res_scalar_err(res, O_TAU1_MAX, T1, e1, MM_ERR_ESTIMATE);
    mm_res_scalar_err(res, O_TAU2_MAX, T2, e2, MM_ERR_ESTIMATE);
    mm_res_scalar_err(res, O_T_TAU1, t1, 1e-6 * p.T, MM_ERR_ESTIMATE);
    mm_res_scalar_err(res, O_T_TAU2, t2, 1e-6 * p.T, MM_ERR_ESTIMATE);

    /* singular configurations and the reach (eq. 4): q2 moves monotonically
     * from q2_0 to q2_1, so |sin q2| is smallest at an end or where q2 = 0 */
    double qa = p.q0[1], qb = p.q0[1] + p.dq[1];
    int through0 = (qa <= 0 && qb >= 0) || (qa >= 0 && qb <= 0);
    double smin = through0 ? 0 : fmin(fabs(sin(qa)), fabs(sin(qb)));
    double cmax = through0 ? 1 : fmax(cos(qa), cos(qb));
    mm_res_scalar(res, O_DETJ_MIN, s->l1 * s->l2 * smin);
    mm_res_scalar(res, O_REACH, sqrt(s->l1 * s->l1 + s->l2 * s->l2 + 2 * s->l1 * s->l2 * cmax));
    if (through0) {
        double ts, ets;                                  /* q2(t) = 0 by Brent, or at an end exactly */
        int rc = mm_dyn_plan_stretched(&p, &ts, &ets, err);
        if (rc != MM_OK)
            return rc;
        if (ets > 0)
            mm_res_scalar_err(res, O_T_SING, ts, ets, MM_ERR_BOUND);
        else
            mm_res_scalar(res, O_T_SING, ts)->exact = 1;
        mm_res_warn(res, "the arm is stretched (q2 = 0) at t = %.4g s: a singular configuration, det J = 0, "
                         "with the tip at the reach limit l1 + l2 = %.4g m; there the tip cannot move along the "
                         "arm, and joint speeds for a tip speed would be unbounded", ts, s->l1 + s->l2);
    }
    double fold = M_PI - fmax(fabs(qa), fabs(qb));       /* distance from the folded arm */
    if (fold < 0.05)
        mm_res_warn(res, "the arm comes within %.3g rad of folding (q2 = +-pi, det J = 0): the other singular "
                         "configuration, with the tip at the inner edge of the reach |l1 - l2| = %.4g m",
                    fold, fabs(s->l1 - s->l2));
    else if (!through0 && smin < 0.05)
        mm_res_warn(res, "the arm comes within %.3g rad of the stretched configuration (det J = %.3g m^2): joint "
                         "speeds for a given tip speed grow like 1/sin q2 there",
                    asin(smin), s->l1 * s->l2 * smin);
    if (!p.quintic)
        mm_res_warn(res, "the cubic time law starts and stops with a jump in acceleration: the torques jump at "
                         "t = 0 and t = T (the quintic's do not)");

    /* the work of the motors, int tau . q' dt, by 5-point Gauss-Legendre on
     * 64 panels (the integrand is a polynomial in t times sines and cosines:
     * far below round-off), against the rise of the energy (eq. 6) */
    double wabs, work = mm_dyn_plan_work(&p, &wabs);
    double qe[2] = {p.q0[0] + p.dq[0], p.q0[1] + p.dq[1]}, z[2] = {0, 0}, Ta, Va, Tb, Vb;
    mm_robot2_energy(s, p.q0, z, &Ta, &Va);
    mm_robot2_energy(s, qe, z, &Tb, &Vb);
    double gscale = s->g * (0.5 * s->m1 + s->m2) * s->l1 + s->g * s->m2 * s->l2;
    mm_res_scalar(res, O_DV, Vb - Va);
    mm_res_scalar_err(res, O_WORK, work, 64 * DBL_EPSILON * (wabs + gscale), MM_ERR_BOUND);
    mm_res_check_abs(res, "work of the motors (Gauss-Legendre quadrature) vs the rise of the energy [J]", work,
                     Vb - Va, 64 * DBL_EPSILON * (wabs + gscale));

    /* the forward simulation, driven by the planned torques (eq. 5) */
    double *y = mm_res_alloc(res, (size_t)n * 4 * sizeof *y);
    if (!y)
        return MM_ENOMEM;
    double y0[4] = {p.q0[0], p.q0[1], 0, 0};
    mm_ode_problem prob = {.n = 4, .f = mm_dyn_plan_forward_rhs, .params = &p, .t0 = 0, .t_end = p.T, .y0 = y0};
    mm_ode_options opt = mm_ode_options_adaptive(MM_ODE_DOP853, RTOL, RTOL, 200000);
    mm_ode_result r = {.t_out = sq1->x, .nout = (size_t)n, .y_out = y};
    int rc = mm_ode_run(&prob, &opt, &r, err);
    if (rc != MM_OK && p.t_left < 0)
        return rc;
    int done = (int)r.nout_done;
    double worst = p.t_left >= 0 ? 2 * M_PI : 0, big = 0;
    for (int i = 0; i < done; i++) {
        worst = fmax(worst, fmax(fabs(y[4 * i] - sq1->y[i]), fabs(y[4 * i + 1] - sq2->y[i])));
        big = fmax(big, fmax(fabs(sq1->y[i]), fabs(sq2->y[i])));
    }
    mm_res_method(res, "inverse dynamics in closed form; forward simulation by dop853", 0);
    mm_res_method_stat(res, "rtol", RTOL);
    mm_res_method_stat(res, "steps", (double)r.n_accepted);
    mm_res_method_stat(res, "evaluations", (double)r.n_eval);
    double A;
    rc = mm_dyn_plan_amplification(&p, res, &A, err);
    if (rc != MM_OK)
        return rc;
    /* each step errs by about RTOL times the state's size; the arm
     * amplifies what it is given by up to A (eq. 7) */
    double tol = 4 * RTOL * (1 + big) * A;
    mm_res_check_abs(res, "forward simulation with the planned torques vs the planned path: worst |dq| [rad]",
                     worst, 0, tol);
    if (p.t_left >= 0)
        mm_res_warn(res, "the simulated arm fell off the planned path (by a whole turn) at t = %.4g s: driven open loop, "
                         "it amplifies small errors by about %.2g along this move; a real arm needs feedback",
                    p.t_left, A);
    else if (tol > 1e-6)
        mm_res_warn(res, "driven open loop the arm amplifies small errors by about %.2g along this move: the "
                         "simulation can follow the plan only to about %.2g rad", A, tol);
    return mm_dyn_plan_animate(&p, res);
}

static const char *const references[] = {
    "J. J. Craig, Introduction to Robotics: Mechanics and Control, 3rd ed., Pearson 2005, ch. 6-7",
    "M. W. Spong, S. Hutchinson, M. Vidyasagar, Robot Modeling and Control, Wiley 2006, sections 5.3 and 7.3",
    "E. Hairer, S. P. Norsett, G. Wanner, Solving Ordinary Differential Equations I, Springer 1993 (DOP853)",
    NULL,
};

const mm_exercise mm_ex_dyn_robot_2link = {
    .id = "dyn-robot-2link", .chapter = 4, .section = "4.4.2", .title = "Dynamics of a two-link robot arm",
    .summary = "Joint torques of a planned quintic move (inverse dynamics), checked by a forward simulation "
               "driven by them; singular configurations and the reach.",
    .tags = "dynamics, robot, inverse dynamics, trajectory, multibody", .theory = "exercises/dyn/robot_2link.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
