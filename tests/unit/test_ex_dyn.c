/* test_ex_dyn.c — the hard cases of chapter 4 (dynamics), through the real
 * pipeline (text parameters -> validation -> solve -> JSON), read back
 * with cJSON:
 *   dyn-pendulum:        the separatrix (no period, the bob stays up), just
 *                        below it (the logarithmic period), over the top,
 *                        and the defaults against 20-digit values;
 *   dyn-double-pendulum: the energy over 1,000 periods of the small
 *                        oscillation (symplectic bounded, Dormand-Prince
 *                        drifting), and chaos at the defaults;
 *   dyn-robot-2link:     a target out of reach is a 422 naming the joint;
 *                        the torques start from the static ones;
 *   dyn-slider-crank:    coasting through its dead centres with zero
 *                        torque, by both methods. */
#include "mm_test.h"

#include <cJSON.h>
#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "mm_api.h"
#include "mm_draw.h"
#include "mm_dyn.h"
#include "mm_answer.h"

static double scalar_error(const cJSON *doc, const char *name)
{
    return cJSON_GetObjectItem(named(doc, "scalars", name), "error")->valuedouble;
}

static int has_animation(const cJSON *doc)
{
    const cJSON *a = cJSON_GetObjectItem(doc, "animation");
    return a && cJSON_GetArraySize(cJSON_GetObjectItem(a, "t")) >= 2 &&
           cJSON_GetArraySize(cJSON_GetObjectItem(a, "t")) <= 240;
}

/* ---- dyn-pendulum ---------------------------------------------------------------- */

static void pendulum_defaults_should_give_the_elliptic_period(void **state)
{
    (void)state;
    cJSON *d = solve_ok("dyn-pendulum", "");
    /* mpmath: 4 / sqrt(9.81) K(m = sin^2(1/2)) = 2.1391376005586888448 */
    check_rel(scalar(d, "period"), 2.1391376005586888448, 4 * DBL_EPSILON, "period by the AGM");
    check_rel(scalar(d, "period_small"), 2 * M_PI / sqrt(9.81), 2 * DBL_EPSILON, "2 pi sqrt(L/g)");
    /* mpmath findroot: 0.3981767846748320688, inside the error bound given */
    check_abs(scalar(d, "theta_1pct"), 0.3981767846748320688, scalar_error(d, "theta_1pct"),
              "1 % amplitude within its stated bound");
    assert_true(scalar_error(d, "theta_1pct") < 1e-12);
    assert_true(has_animation(d));
    assert_non_null(find(d, "series", "theta"));
    cJSON_Delete(d);
}

static void pendulum_at_the_separatrix_should_give_no_period_and_stay_up(void **state)
{
    (void)state;
    cJSON *d = solve_ok("dyn-pendulum", "theta0=pi&t_end=30");
    assert_null(find(d, "scalars", "period"));
    assert_true(warned(d, "separatrix"));
    assert_int_equal((int)scalar(d, "motion"), 1);
    double *th;
    int n = series_y(d, "theta", &th);
    for (int i = 0; i < n; i++)
        assert_true(th[i] == M_PI);                /* balanced exactly: sin(pi) taken as 0 */
    free(th);
    check_rel(scalar(d, "period_small"), 2 * M_PI / sqrt(9.81), 2 * DBL_EPSILON, "still given");
    cJSON_Delete(d);
}

static void pendulum_just_below_the_separatrix_should_have_the_logarithmic_period(void **state)
{
    (void)state;
    /* theta0 = pi - 1e-6 (as the double nearest): kc = cos(theta0/2) ~ 5e-7 and
     * K = ln(4/kc) + O(kc^2 ln kc): the period 4 K / omega_n to 1e-12 */
    double th0 = M_PI - 1e-6, kc = cos(th0 / 2);
    char q[64];
    snprintf(q, sizeof q, "theta0=%.17g&t_end=40", th0);
    cJSON *d = solve_ok("dyn-pendulum", q);
    check_rel(scalar(d, "period"), 4 * log(4 / kc) / sqrt(9.81), 1e-12, "period ~ 4 ln(4/kc) / omega_n");
    assert_true(scalar(d, "period_ratio") > 10);
    assert_int_equal((int)scalar(d, "motion"), 0);
    assert_true(warned(d, "separatrix"));
    /* the swing reaches theta_max = theta0 and comes back through the bottom */
    double *th;
    int n = series_y(d, "theta", &th), crossed = 0;
    for (int i = 1; i < n; i++)
        crossed |= th[i - 1] > 0 && th[i] <= 0;
    free(th);
    assert_true(crossed);
    cJSON_Delete(d);
}

static void pendulum_pushed_over_the_top_should_turn(void **state)
{
    (void)state;
    /* k^2 = sin^2(1/2) + (7 / (2 sqrt 9.81))^2 > 1: it goes round */
    cJSON *d = solve_ok("dyn-pendulum", "omega0=7&t_end=5");
    assert_int_equal((int)scalar(d, "motion"), 2);
    assert_null(find(d, "scalars", "theta_max"));
    double *th;
    int n = series_y(d, "theta", &th);
    for (int i = 1; i < n; i++)
        assert_true(th[i] > th[i - 1]);          /* always forward */
    /* one turn per period */
    check_rel(th[n - 1] - th[0], 2 * M_PI * 5 / scalar(d, "period"), 0.2, "turns = t_end / period, roughly");
    free(th);
    cJSON_Delete(d);
}

/* ---- dyn-double-pendulum --------------------------------------------------------- */

static void double_pendulum_energy_over_1000_periods_should_stay_bounded_only_when_symplectic(void **state)
{
    (void)state;
    /* small swings: the slow period 2 pi / 2.3972 = 2.621 s; 1,000 of them */
    cJSON *d = solve_ok("dyn-double-pendulum", "theta1_0=0.05&theta2_0=0.05&t_end=2621&h=0.042");
    double sy = stat(d, "symplectic_largest_energy_error"), dp = stat(d, "dopri5_largest_energy_error");
    /* Gauss-4 at omega_fast h = 0.24: an O(h^4) error on an energy of
     * 1e-3 of the scale, bounded: seen at 1e-12; Dormand-Prince at rtol 1e-6
     * drifts to ~4e-6 */
    assert_true(sy < 1e-10);
    assert_true(dp > 1e4 * sy);
    assert_null(find(d, "scalars", "lyapunov"));       /* regular: the twins stay together */
    const cJSON *c;
    int found = 0;
    cJSON_ArrayForEach(c, cJSON_GetObjectItem(d, "checks"))
        found |= strstr(cJSON_GetObjectItem(c, "name")->valuestring, "second half") != NULL;
    assert_true(found);                                 /* the no-drift check ran, and passed */
    /* the Dormand-Prince error grows: its last plotted value is near its largest */
    double *e;
    int n = series_y(d, "energy_error_dopri", &e);
    assert_true(e[n - 1] > 0.5 * dp);
    assert_true(e[n / 10] < 0.5 * dp);
    free(e);
    cJSON_Delete(d);
}

static void double_pendulum_defaults_should_be_chaotic(void **state)
{
    (void)state;
    cJSON *d = solve_ok("dyn-double-pendulum", "");
    double lam = scalar(d, "lyapunov"), e = scalar_error(d, "lyapunov");
    /* positive beyond its error: chaos.  The error is honest and large
     * (0.91 on 0.99): at separation 1e-9 the fit sees only 3 decades of
     * growth, about 5 s, and the twin parting along theta1 takes its 5 s
     * elsewhere (1.90).  A twin 1e-13 apart grows over 7 decades, 14 s:
     * both directions agree to 3 %, chaos beyond doubt, and the default's
     * exponent lies within its stated error of that one. */
    assert_true(lam - e > 0);
    cJSON *f = solve_ok("dyn-double-pendulum", "separation=1e-13");
    double lam_f = scalar(f, "lyapunov"), e_f = scalar_error(f, "lyapunov");
    assert_true(e_f < 0.1 * lam_f && lam_f - e_f > 0.5);
    check_abs(lam, lam_f, e + e_f, "the default's exponent within its stated error of the long window's");
    cJSON_Delete(f);
    assert_true(scalar(d, "t_horizon") > 10 && scalar(d, "t_horizon") < 30);
    /* the linearised frequencies of two equal pendulums */
    check_rel(scalar(d, "omega_slow"), sqrt((2 - sqrt(2)) * 9.81), 4 * DBL_EPSILON, "slow mode");
    check_rel(scalar(d, "E0"), 3 * 9.81, 4 * DBL_EPSILON, "both rods horizontal: E - V_min = 3 m g l");
    assert_true(has_animation(d));
    cJSON_Delete(d);
}

static void double_pendulum_twins_apart_from_the_start_should_have_horizon_zero(void **state)
{
    (void)state;
    /* separation at its limit 1e-3: with the state-space weights the twins
     * can start more than 1e-3 apart, so the horizon is the start itself.
     * The search read the grid point before the first (index -1) here and
     * printed no horizon (found by the num/dyn helper, 2026-12-07) */
    for (int k = 0; k < 2; k++) {
        cJSON *d = solve_ok("dyn-double-pendulum", k ? "separation=1e-3&theta2_0=0.7" : "separation=1e-3&theta2_0=0.1");
        assert_true(has_scalar(d, "t_horizon"));
        assert_true(scalar(d, "t_horizon") == 0);
        cJSON_Delete(d);
    }
}

/* ---- dyn-robot-2link -------------------------------------------------------------- */

static void expect_unreachable(const char *query, const char *param)
{
    answer a = solve("dyn-robot-2link", query);
    const cJSON *e = cJSON_GetObjectItem(a.doc, "error");
    if (a.status != 422 || strcmp(cJSON_GetObjectItem(e, "code")->valuestring, "no_solution") != 0 ||
        strcmp(cJSON_GetObjectItem(e, "param")->valuestring, param) != 0 ||
        !strstr(cJSON_GetObjectItem(e, "message")->valuestring, "out of reach")) {
        char *s = cJSON_PrintUnformatted(a.doc);
        fail_msg("%s: expected 422 naming %s, got %d %.300s", query, param, a.status, s);
    }
    cJSON_Delete(a.doc);
}

static void robot_commanded_out_of_reach_should_say_which_joint(void **state)
{
    (void)state;
    expect_unreachable("q2_1=pi", "q2_1");
    expect_unreachable("q2_1=-pi", "q2_1");
    expect_unreachable("q2_0=pi&q2_1=1", "q2_0");
    /* one step inside the range is reachable, and the folded arm is reported */
    cJSON *d = solve_ok("dyn-robot-2link", "q2_1=3.14");
    assert_true(warned(d, "folding"));
    cJSON_Delete(d);
}

static void robot_defaults_should_start_from_the_static_torques(void **state)
{
    (void)state;
    cJSON *d = solve_ok("dyn-robot-2link", "");
    double *t1, *t2;
    series_y(d, "tau1", &t1);
    series_y(d, "tau2", &t2);
    /* at t = 0 the quintic has q'' = 0: the arm stretched along +x holds
     * g (m1 l1/2 + m2 (l1 + l2/2)) = 19.62 N m and g m2 l2 / 2 = 4.905 N m */
    check_rel(t1[0], 9.81 * (0.5 + 1.5), 4 * DBL_EPSILON, "shoulder at t = 0");
    check_rel(t2[0], 9.81 * 0.5, 4 * DBL_EPSILON, "elbow at t = 0");
    free(t1);
    free(t2);
    check_rel(scalar(d, "reach_max"), 2, 0, "stretched at the start: l1 + l2");
    check_abs(scalar(d, "t_singular"), 0, 0, "singular at t = 0");
    assert_true(warned(d, "stretched"));
    /* from along +x (V = 0) to link 1 up, link 2 back along -x at height l1:
     * m1 g l1/2 + m2 g l1 */
    check_rel(scalar(d, "delta_V"), 9.81 * (0.5 + 1), 4 * DBL_EPSILON, "rise of the potential energy");
    assert_true(has_animation(d));
    cJSON_Delete(d);
}

/* issue 10: a short run of a short pendulum plotted on a fine grid erred
 * 1.14 times the step term of eq. (8) (the dense output between the few
 * steps adds its own error): the check failed on a valid request.  The
 * tolerance now allows 1.5 times it, and stays within 100x of the error
 * at the defaults. */
/* make study, 8,000 draws: a light inner bob (m1/m2 = 0.15) whipped 2.25
 * times faster in the second half of a regular run than in the first (136
 * against 61 rad/s), and gauss4's energy error there was 142 times the
 * first half's: not a drift (the grid's samples between the peaks stayed
 * at the first half's level), a faster region; the check allowed 4 times */
static void double_pendulum_symplectic_check_should_allow_a_faster_second_half(void **state)
{
    (void)state;
    const char *name = "symplectic energy error: largest over the second half vs over the first half";
    cJSON *d = solve_ok("dyn-double-pendulum",
                        "m1=0.01385660491081253&m2=0.09131832261601305&l1=0.13638735228169813&l2=0.0823286280952834&"
                        "g=82.01375709579006&theta1_0=-1.1898991906283405&theta2_0=-1.4187109976219374&"
                        "omega1_0=-11.91891405471766&omega2_0=1.7285908505275671&t_end=11.732226302046538&"
                        "rtol=6.284441267022008e-08&symplectic=gauss4&h=0.00023239727199717542&"
                        "separation=0.0006393655222225213&points=285");
    const cJSON *c = find(d, "checks", name);
    assert_non_null(c);
    assert_true(cJSON_IsTrue(cJSON_GetObjectItem(c, "passed")));
    cJSON_Delete(d);
}

/* make study, 8,000 draws: a swing of 0.0063 rad pushed at -0.578 rad/s
 * (k^2 = 1.5e-5) aborted the process: the period's sensitivity stepped its
 * energy below the bottom and asked K for kc > 1 (mm_pendulum.c) */
static void pendulum_tiny_swing_should_be_answered(void **state)
{
    (void)state;
    cJSON *d = solve_ok("dyn-pendulum", "L=0.0014096398095928481&g=25.080367619783328&theta0=0.006308859985167666&"
                                        "t_end=14.371454538120666&omega0=-0.5778520772030333&points=30");
    const cJSON *c;
    cJSON_ArrayForEach(c, cJSON_GetObjectItem(d, "checks")) assert_true(cJSON_IsTrue(cJSON_GetObjectItem(c, "passed")));
    cJSON_Delete(d);
}

static void pendulum_short_run_on_a_fine_grid_should_pass_its_trajectory_check(void **state)
{
    (void)state;
    const char *name = "theta(t): DOP853 vs the exact solution in Jacobi functions, worst point [rad]";
    cJSON *d = solve_ok("dyn-pendulum", "L=0.00167503&g=10.4317&theta0=0.412348&t_end=0.0285716&"
                                        "omega0=-29.7686&points=2016");
    cJSON_Delete(d);
    d = solve_ok("dyn-pendulum", "");
    const cJSON *c = find(d, "checks", name);
    assert_non_null(c);
    double e = cJSON_GetObjectItem(c, "abs_error")->valuedouble;
    assert_true(e > 0 && cJSON_GetObjectItem(c, "tolerance")->valuedouble <= 100 * e);
    cJSON_Delete(d);
}

/* MM_DRAWS=200: two fast turns over the top (omega0 >> sqrt(g/L)) failed
 * the energy check, 1.15 and 25 times over.  The motion is nearly uniform,
 * so DOP853's error control took steps of up to 0.8 rad, and its dense
 * output (order 7, not error-controlled) erred 36 times more between the
 * steps than at them.  The step is now held to 0.2 rad of the motion: the
 * drift on the plot grid is a small fraction of the bound, and the bound
 * stays within 100x of the error at the defaults. */
static void pendulum_fast_turn_over_the_top_should_keep_its_energy_between_steps(void **state)
{
    (void)state;
    const char *name = "energy: largest drift of theta'^2/2 + (g/L)(1 - cos theta) over the run [1/s^2]";
    const char *draws[] = {
        "L=0.004231716260598704&g=76.98365653355184&theta0=1.6679502212127833e-06&"
        "t_end=0.017461004333938174&omega0=-599.5628933992496&points=374",
        "L=0.0012510361692849316&g=0.8997306352492933&theta0=0.28372936681322153&"
        "t_end=0.10473365150618474&omega0=-115.37995612305065&points=638",
    };
    for (int k = 0; k < 2; k++) {
        cJSON *d = solve_ok("dyn-pendulum", draws[k]);   /* every check passes */
        assert_int_equal((int)scalar(d, "motion"), 2);
        const cJSON *c = find(d, "checks", name);
        assert_non_null(c);
        double e = cJSON_GetObjectItem(c, "abs_error")->valuedouble;
        assert_true(e <= 0.1 * cJSON_GetObjectItem(c, "tolerance")->valuedouble);
        cJSON_Delete(d);
    }
    cJSON *d = solve_ok("dyn-pendulum", "");
    const cJSON *c = find(d, "checks", name);
    assert_non_null(c);
    double e = cJSON_GetObjectItem(c, "abs_error")->valuedouble;
    assert_true(e > 0 && cJSON_GetObjectItem(c, "tolerance")->valuedouble <= 100 * e);
    cJSON_Delete(d);
}

/* The tolerance study (answers --checks -n 2000): a 9 mm pendulum swung
 * hard (omega0 = 27.9 against 2 sqrt(g/L) = 43.1), 0.28 rad of motion in 3
 * steps, failed the energy check 1.03 times over.  Its steps erred 5.5e-12
 * in the energy; the plot grid, read from DOP853's dense output, 1.1e-9:
 * mid-step the interpolant erred 1.4 RTOL (1 + |theta'|) in theta'.  The
 * old bound, RTOL (E0 + g/L)(1 + rate t_end), had no room for it.  It is
 * now RTOL times the energy's gradient against DOP853's allowance (eq. 8)
 * times (6 for the dense output + rate t_end), plus rounding: the drift
 * passes with a fifth of it, and the bound stays within 100x of the
 * error at the defaults. */
static void pendulum_short_hard_swing_should_keep_its_energy_on_the_plot_grid(void **state)
{
    (void)state;
    const char *name = "energy: largest drift of theta'^2/2 + (g/L)(1 - cos theta) over the run [1/s^2]";
    cJSON *d = solve_ok("dyn-pendulum", "L=0.00925525536028067&g=4.302346129853195&theta0=0.006858548812466235&"
                                        "t_end=0.010169708125491004&omega0=27.862322771159597&points=531");
    assert_int_equal((int)scalar(d, "motion"), 0);
    const cJSON *c = find(d, "checks", name);
    assert_non_null(c);
    double e = cJSON_GetObjectItem(c, "abs_error")->valuedouble;
    assert_true(e <= 0.5 * cJSON_GetObjectItem(c, "tolerance")->valuedouble);
    cJSON_Delete(d);
    d = solve_ok("dyn-pendulum", "");
    c = find(d, "checks", name);
    assert_non_null(c);
    e = cJSON_GetObjectItem(c, "abs_error")->valuedouble;
    assert_true(e > 0 && cJSON_GetObjectItem(c, "tolerance")->valuedouble <= 100 * e);
    cJSON_Delete(d);
}

/* The tolerance study (answers --checks -n 2000): a fast start (18 rad/s)
 * at low g failed the reference's energy check 4.2 times over.  The
 * solver's guess of the first step, 0.0157 s (0.5 rad of the motion), lay
 * where DOP853's error estimate passes through zero (its 5th-order part
 * changes sign): estimate 0.43, true error 40 times the tolerance, and the
 * energy kept that step's error, 1.1e-8 of Es, for the whole run.  mm_ode
 * checks each trial of a first step against the estimate of its first
 * half (3.96 here, larger than the whole step's) and began at 0.0059 s:
 * the energy error is 6.1e-12, 1/450 of the tolerance. */
static void double_pendulum_first_step_should_not_land_on_a_zero_of_the_error_estimate(void **state)
{
    (void)state;
    cJSON *d = solve_ok("dyn-double-pendulum",
                        "m1=24.676302929733605&m2=6.2482601887673965&l1=3.1792366200779565&l2=6.033744326306736&"
                        "g=2.2263574553979835&theta1_0=-0.18658741539725598&theta2_0=0.34518013887703525&"
                        "omega1_0=11.827816869136647&omega2_0=-17.98976473564513&t_end=0.17951103829393178&"
                        "rtol=1.306724060560581e-09&symplectic=gauss4&h=0.00024082522669694272&"
                        "separation=4.890186868869341e-08&points=11");
    const cJSON *c = find(d, "checks", "energy of the reference run (DOP853, rtol 1e-10): largest relative error");
    assert_non_null(c);
    double e = cJSON_GetObjectItem(c, "abs_error")->valuedouble;
    assert_true(e <= 0.01 * cJSON_GetObjectItem(c, "tolerance")->valuedouble);
    cJSON_Delete(d);
}

/* MM_DRAWS=200: Dormand-Prince at the learner's loose rtol (3.7e-4) over a
 * long chaotic run let its energy run away until its step collapsed: the
 * whole answer was a 422, though the reference and the symplectic run were
 * fine.  Its failure is now part of the answer: a warning, and its energy
 * error plotted up to where it stopped. */
static void double_pendulum_loose_dopri5_that_runs_away_should_still_answer(void **state)
{
    (void)state;
    cJSON *d = solve_ok("dyn-double-pendulum",
                        "m1=8.344578595588057&m2=18.7671282277406&l1=1.868528201722031&l2=0.36976118529680246&"
                        "g=0.33199706945673807&theta1_0=1.5744518895613595&theta2_0=-2.65121505142366&"
                        "omega1_0=8.537284251956336&omega2_0=22.661634800675643&t_end=62.5786292076357&"
                        "rtol=0.0003679099631398327&symplectic=midpoint&h=0.0013856538127842444&"
                        "separation=6.404217655693968e-13&points=319");
    assert_true(warned(d, "lost the motion"));
    double *de, *th;
    int nd = series_y(d, "energy_error_dopri", &de), n = series_y(d, "theta1", &th);
    assert_true(nd > 1 && nd < n && n == 319);
    free(de);
    free(th);
    cJSON_Delete(d);
}

/* ---- the chapter's shared code (exercises/mm_dyn.c) ------------------------------- */

static void dyn_plan_should_start_and_end_at_rest_and_drive_the_planned_acceleration(void **state)
{
    (void)state;
    for (int quintic = 0; quintic <= 1; quintic++) {
        mm_dyn_plan p = {.arm = {.l1 = 1, .l2 = 0.7, .m1 = 3, .m2 = 2, .g = 9.81}, .quintic = quintic,
                         .q0 = {0.3, -0.4}, .dq = {1.1, 0.9}, .T = 2, .t_left = -1};
        double q[2], qd[2], qdd[2];
        mm_dyn_plan_at(&p, 0, q, qd, qdd);
        check_abs(q[0], 0.3, 0, "q1(0) = q10 exactly");
        check_abs(qd[0] + qd[1], 0, 0, "at rest at t = 0");
        mm_dyn_plan_at(&p, 2, q, qd, qdd);
        check_rel(q[1], -0.4 + 0.9, 4 * DBL_EPSILON, "q2(T) = q21");
        check_abs(qd[0] + qd[1], 0, 1e-15, "at rest at t = T");
        /* forward dynamics under the inverse-dynamics torques gives back the
         * planned acceleration: two different routines of mm_multibody */
        double y[4], dy[4], t = 0.7;
        mm_dyn_plan_at(&p, t, q, qd, qdd);
        y[0] = q[0], y[1] = q[1], y[2] = qd[0], y[3] = qd[1];
        assert_int_equal(mm_dyn_plan_forward_rhs(t, y, dy, &p), 0);
        check_abs(dy[2], qdd[0], 1e-12, "forward(inverse(qdd)) = qdd, shoulder (round-off of a 2x2 solve)");
        check_abs(dy[3], qdd[1], 1e-12, "forward(inverse(qdd)) = qdd, elbow");
        /* the planned speed is the derivative of the planned angle */
        double qa[2], qb[2], h = 1e-5;
        mm_dyn_plan_at(&p, t - h, qa, qd, qdd);
        mm_dyn_plan_at(&p, t + h, qb, qd, qdd);
        mm_dyn_plan_at(&p, t, q, qd, qdd);
        check_abs((qb[0] - qa[0]) / (2 * h), qd[0], 1e-8, "q1' = dq1/dt (central difference, h^2 error)");
    }
}

static void dyn_slider_crank_energy_bound_should_bound_the_energy_difference(void **state)
{
    (void)state;
    mm_sc_model s = {.r = 0.1, .l = 0.4, .J_crank = 0.05, .m_rod = 1, .J_rod = 0.015, .m_piston = 1,
                         .torque = 20};
    srand(7);
    for (int k = 0; k < 200; k++) {
        double phi = 6.3 * (rand() / (double)RAND_MAX), w = 100 * (rand() / (double)RAND_MAX) - 50;
        double dphi = 1e-2 * (rand() / (double)RAND_MAX - 0.5), dw = 1 * (rand() / (double)RAND_MAX - 0.5);
        double q[MM_SC_NQ], qd[MM_SC_NQ], qr[MM_SC_NQ], qdr[MM_SC_NQ], bJ;
        mm_sc_assemble(&s, phi + dphi, w + dw, q, qd);
        mm_sc_assemble(&s, phi, w, qr, qdr);
        double b = mm_dyn_sc_energy_bound(&s, q, qd, qr, qdr, 0, &bJ);
        double dE = fabs(mm_sc_kinetic(&s, q, qd) - s.torque * q[0] - mm_sc_kinetic(&s, qr, qdr) + s.torque * qr[0]);
        double JA = mm_sc_inertia(&s, q[0], NULL), JB = mm_sc_inertia(&s, qr[0], NULL);
        double dEJ = fabs(0.5 * JA * qd[0] * qd[0] - s.torque * q[0] - 0.5 * JB * qdr[0] * qdr[0] + s.torque * qr[0]);
        /* exact bounds; 1e-12: the round-off of the energies (tens of J) */
        assert_true(dE <= b + 1e-12);
        assert_true(dEJ <= bJ + 1e-12);
    }
}

static void dyn_extreme_error_should_find_the_vertex_of_a_sampled_parabola(void **state)
{
    (void)state;
    /* v = 5 - (x - 0.3)^2 sampled at x = 0, 0.25, ..., 1: the parabola
     * through three samples is v itself, so the estimate is exact */
    double v[5];
    for (int i = 0; i < 5; i++) {
        double x = 0.25 * i;
        v[i] = 5 - (x - 0.3) * (x - 0.3);
    }
    /* best sample x = 0.25 (i = 1); the vertex 5 is above it by 0.05^2 */
    check_abs(mm_dyn_extreme_error(v, 5, 1), 0.05 * 0.05, 1e-15, "the parabola's vertex above the best sample");
    check_abs(mm_dyn_extreme_error(v, 5, 0), 0, 0, "an end point: the run's own value");
}

/* ---- dyn-slider-crank -------------------------------------------------------------- */

static void slider_crank_should_coast_through_its_dead_centres(void **state)
{
    (void)state;
    static const char *const qs[] = {"", "method=partitioning", "alpha=0"};
    for (int k = 0; k < 3; k++) {
        cJSON *d = solve_ok("dyn-slider-crank", qs[k]);
        double *w;
        int n = series_y(d, "omega", &w);
        for (int i = 0; i < n; i++)
            assert_true(w[i] > 80 && w[i] <= 100 * (1 + 1e-9));   /* never stops, never exceeds omega0 */
        free(w);
        /* 7.4 turns: through 14 dead centres; at each the speed is back to
         * omega0 (J is smallest there and the energy the same) */
        assert_true(scalar(d, "revolutions") > 7);
        check_rel(scalar(d, "omega_max"), 100, 1e-8, "omega at the dead centres = omega0");
        /* the lowest speed from the energy: omega0 sqrt(J(0) / J_max) */
        double wmin = 100 * sqrt(scalar(d, "J_dead_centre") / scalar(d, "J_max"));
        check_abs(scalar(d, "omega_min"), wmin, 2 * scalar_error(d, "omega_min") + 1e-6,
                  "omega_min = omega0 sqrt(J0 / J_max), within its estimated error");
        double *dr;
        int nd = series_y(d, "drift", &dr);
        double dmax = 0;
        for (int i = 0; i < nd; i++)
            dmax = fmax(dmax, dr[i]);
        free(dr);
        if (k == 1)
            assert_true(dmax < 1e-15);                        /* partitioning: round-off */
        else
            assert_true(dmax < 1e-9);
        assert_true(has_animation(d));
        cJSON_Delete(d);
    }
}

static void slider_crank_with_a_torque_should_gain_its_work(void **state)
{
    (void)state;
    /* torque 50 N m over the run: the energy check holds, the crank speeds up */
    cJSON *d = solve_ok("dyn-slider-crank", "torque=50");
    assert_true(scalar(d, "omega_end") > 100);
    cJSON_Delete(d);
    /* a rod shorter than the crank cannot turn: refused naming l */
    answer a = solve("dyn-slider-crank", "r=0.5&l=0.4");
    assert_int_equal(a.status, 400);
    assert_string_equal(cJSON_GetObjectItem(cJSON_GetObjectItem(a.doc, "error"), "param")->valuestring, "l");
    cJSON_Delete(a.doc);
}

/* issue 10: the energy checks' tolerance was 1260 times the error made at
 * the defaults.  Now it is built from the run's distance to the reference
 * run and the reference's own tolerance: within 100x of the error at the
 * defaults (48x measured), and it still holds where both runs take one
 * identical step (the reference's tolerance is then the whole bound). */
static void slider_crank_energy_tolerance_should_be_within_100x_of_its_error(void **state)
{
    (void)state;
    static const char *const names[] = {
        "energy balance: kinetic energy - T0 - torque (phi - phi0), worst point [J]",
        "J(phi) w^2 / 2 with the closed-form inertia (eq. 5) vs T0 + torque (phi - phi0) [J]"};
    cJSON *d = solve_ok("dyn-slider-crank", "");
    for (int k = 0; k < 2; k++) {
        const cJSON *c = find(d, "checks", names[k]);
        assert_non_null(c);
        double e = cJSON_GetObjectItem(c, "abs_error")->valuedouble;
        double tol = cJSON_GetObjectItem(c, "tolerance")->valuedouble;
        assert_true(e > 0 && tol <= 100 * e);
    }
    cJSON_Delete(d);
    /* one step covers the whole run in both runs: passed, not failed */
    d = solve_ok("dyn-slider-crank", "r=0.149639&l=0.743729&J_crank=0.00894655&m_rod=0.0328282&J_rod=85.151&"
                                     "m_piston=0.157691&torque=236.745&omega0=-4.69888&t_end=0.00639697&"
                                     "method=partitioning&rtol=1.35641e-07&points=18");
    cJSON_Delete(d);
}

/* Two of 200 random draws (helper mdof's sweep) answered 400 naming
 * "t_out", not a parameter: the last animation frame, t_show (nf - 1) /
 * (nf - 1), rounded one ulp past the end of the integration that draws it.
 * A valid request is answered, and every check passes. */
static void the_last_animation_frame_should_not_overshoot_the_run(void **state)
{
    (void)state;
    static const char *const draws[] = {
        "r=0.3022586002098682&l=1.842807601980939&J_crank=1.4279998396460616&m_rod=0.08580408665223217&"
        "J_rod=10.835605868453648&m_piston=6.133830323427796&torque=810.2179474512022&omega0=-811.6039908405575&"
        "t_end=0.5164497874748863&method=baumgarte&alpha=503.97102827779594&rtol=6.506410445680082e-08&points=147",
        "r=0.22968754679978073&l=2.8637099620464417&J_crank=0.003873522130241027&m_rod=0.0376589131474293&"
        "J_rod=0.6447472782719095&m_piston=76.13679194917492&torque=367.26133092909754&omega0=892.2908189117275&"
        "t_end=0.013094741171690051&method=partitioning&alpha=521.712578965639&rtol=3.891020766129639e-08&points=502",
    };
    for (size_t k = 0; k < sizeof draws / sizeof draws[0]; k++)
        cJSON_Delete(solve_ok("dyn-slider-crank", draws[k]));
}

/* dyn-slider-crank (mdof's sweep): J_rod 1e-6 next to m_rod 55 made
 * Phi_q M^-1 Phi_q^T ill-conditioned (accelerations 1e-9 off, the 1e-13
 * reference run hit max_steps: 422; the drift check 1.46x over).  Each is
 * answered 200 with every check passed. */
/* make study, 8,000 draws: a run of 0.009 s (0.185 rad of the crank) was
 * one DOP853 step for the run, its reference and the third run alike, each
 * accepted on an estimate below 1e-12; the step erred 2.4e-12 rad, the three
 * agreed, revolutions was printed with 2.9e-14 of error, 1/13 of its true
 * error (mpmath, 30 digits: 0.0294297500285027522), and the energy checks
 * failed 11.8 times over.  The reference now takes at most half the run's
 * largest step. */
static void slider_crank_one_step_run_should_state_its_error(void **state)
{
    (void)state;
    cJSON *d = solve_ok("dyn-slider-crank",
                        "r=0.19562068965732962&l=0.38881933341688707&J_crank=0.47111311279538054&"
                        "m_rod=3.200174922909418&J_rod=47.095137686969466&m_piston=84.42702083120437&"
                        "torque=96.0651114659529&omega0=20.38382372703927&t_end=0.009049680645104793&"
                        "method=partitioning&alpha=76.25695732656268&rtol=9.056217983676398e-08&points=28");
    assert_true(fabs(scalar(d, "revolutions") - 0.0294297500285027522) <= error_of(d, "revolutions"));
    assert_true(fabs(scalar(d, "omega_end") - 20.4980519223556566798) <= error_of(d, "omega_end"));
    const cJSON *c;
    cJSON_ArrayForEach(c, cJSON_GetObjectItem(d, "checks")) assert_true(cJSON_IsTrue(cJSON_GetObjectItem(c, "passed")));
    cJSON_Delete(d);
}

static void slider_crank_draws_that_failed_should_answer_with_every_check_passed(void **state)
{
    (void)state;
    static const char *const draws[] = {
        "r=0.28067456610545755&l=3.222178156176322&J_crank=0.00015459072620248407&m_rod=55.110509904418166&"
        "J_rod=1.274269237867056e-06&m_piston=0.12498536910087202&torque=-822.3991554464627&"
        "omega0=973.9072262242914&t_end=0.5227145816858115&method=baumgarte&alpha=577.473320609295&"
        "rtol=1.6831618284105864e-10&points=615",
        "r=0.9070011874696716&l=1.5470362855024586&J_crank=74.70898976220317&m_rod=76.65569499220122&"
        "J_rod=3.567244355804796e-05&m_piston=0.7333445940750143&torque=-698.1068458821103&"
        "omega0=-958.8064552665112&t_end=0.008951135839017951&method=baumgarte&alpha=393.5323039925092&"
        "rtol=3.630124177099853e-12&points=76",
    };
    for (size_t k = 0; k < sizeof draws / sizeof draws[0]; k++)
        cJSON_Delete(solve_ok("dyn-slider-crank", draws[k]));
}

/* dyn-slider-crank by partitioning at a loose rtol (2.6e-4 and the 1.3e-4
 * of its half-tolerance run, 1.5e-4): DOP853's steps grew until the run
 * left its energy level and w' = -J'/(2J) w^2 carried it to infinity (422,
 * step size below round-off at t = 0.414; the half-tolerance run spent 1.9 s
 * failing).  The step cap of 1/16 turn keeps it on the energy level: 200,
 * every check passed, and omega_end within its stated error of a run at
 * rtol 1e-10 (the speed swings by a factor 3 in a turn, so a loose run's
 * phase error makes omega_end off by as much as itself: the stated error
 * must say so). */
static void slider_crank_at_a_loose_tolerance_should_stay_on_its_energy_level(void **state)
{
    (void)state;
    static const char *const base = "r=0.8319333497455591&l=3.2651965575505466&J_crank=0.21132653469440935&"
                                    "m_rod=0.5917374664729194&J_rod=99.07011214440062&m_piston=0.2142580335676787&"
                                    "torque=181.1684863109574&omega0=910.6393853052145&t_end=0.6145351501261106&"
                                    "method=partitioning&alpha=935.4609145911653&points=152&rtol=";
    static const char *const tols[] = {"0.00025957782051835463", "0.00012978891025917731", "0.00015"};
    char q[512];
    snprintf(q, sizeof q, "%s1e-10", base);
    cJSON *ref = solve_ok("dyn-slider-crank", q);
    double w_ref = scalar(ref, "omega_end"), rev_ref = scalar(ref, "revolutions");
    cJSON_Delete(ref);
    for (size_t k = 0; k < sizeof tols / sizeof tols[0]; k++) {
        snprintf(q, sizeof q, "%s%s", base, tols[k]);
        cJSON *d = solve_ok("dyn-slider-crank", q);
        check_abs(scalar(d, "omega_end"), w_ref, scalar_error(d, "omega_end"), "omega_end within its stated error");
        check_abs(scalar(d, "revolutions"), rev_ref, scalar_error(d, "revolutions"), "turns within their stated error");
        cJSON_Delete(d);
    }
}

/* dyn-double-pendulum: the reference's energy tolerance (0.8 rtol per
 * radian) was 2.7x and 1.1x exceeded by short runs with slow gravity; the
 * symplectic no-growth check ran over part of one slow swing (1.22x); a
 * short fast run (23 steps, 746 points) was 2.14x over when its energy was
 * read off DOP853's dense output between the steps (now: at the steps). */
static void double_pendulum_draws_that_failed_should_answer_with_every_check_passed(void **state)
{
    (void)state;
    static const char *const draws[] = {
        "m1=6.3030506428212325&m2=13.393047863645773&l1=0.14448694844721918&l2=4.5554290594740525&"
        "g=20.254794063652213&theta1_0=1.3744702167283371&theta2_0=2.1930396602996396&omega1_0=14.33824880194932&"
        "omega2_0=2.6017818380118456&t_end=0.7945710294285288&rtol=0.0002752794920328391&symplectic=gauss4&"
        "h=0.0005440419735208131&separation=2.680226535266243e-12&points=12",
        "m1=7.247561286895587&m2=1.918650919800799&l1=5.054775244865773&l2=9.899425453545126&g=0.16858165498582467&"
        "theta1_0=-2.7017730795817285&theta2_0=-1.96397028812816&omega1_0=-6.763180735129584&"
        "omega2_0=7.952522586325209&t_end=0.13628591869355045&rtol=3.1500368869504655e-06&symplectic=gauss4&"
        "h=0.0025085202824797906&separation=1.8702245098577657e-11&points=561",
        "m1=2.8805512272343003&m2=0.29265017893768386&l1=1.0481935266528635&l2=5.442726514785798&"
        "g=0.11654933864557311&theta1_0=0.7225799000935567&theta2_0=-0.26222377502795835&"
        "omega1_0=20.233631648139486&omega2_0=-8.04597054625074&t_end=0.2090506709999215&"
        "rtol=3.2460201145413153e-06&symplectic=midpoint&h=0.016489572179164868&separation=1.5539255278321222e-08&"
        "points=526",
        "m1=34.041892169851764&m2=20.92278269355982&l1=2.063940029178092&l2=2.6961478429390433&g=13.203029733795228&"
        "theta1_0=-1.3016793328033835&theta2_0=-2.832599601908372&omega1_0=23.07923752198962&"
        "omega2_0=-10.332046578721162&t_end=0.1607741839828292&rtol=1.0815793396627521e-05&symplectic=gauss4&"
        "h=0.0018245311258397157&separation=1.2109912264783041e-08&points=746",
    };
    for (size_t k = 0; k < sizeof draws / sizeof draws[0]; k++)
        cJSON_Delete(solve_ok("dyn-double-pendulum", draws[k]));
}

/* Every dyn exercise over random draws of the product's generator: 200,
 * every check passed, never a 400 or 422 on a draw its check accepts.
 * MM_DYN_DRAWS overrides the number (the four take ~12 s at 200). */
static void dyn_exercises_should_pass_every_check_on_random_draws(void **state)
{
    (void)state;
    static const char *const ids[] = {"dyn-pendulum", "dyn-double-pendulum", "dyn-robot-2link", "dyn-slider-crank"};
    const char *env = getenv("MM_DYN_DRAWS");
    int n = env ? atoi(env) : 200;
    static mm_draw_set set;
    for (size_t e = 0; e < sizeof ids / sizeof ids[0]; e++) {
        const mm_exercise *ex = mm_exercise_find(ids[e]);
        assert_non_null(ex);
        mm_rng g;
        mm_rng_seed(&g, mm_draw_seed("test_ex_dyn", ids[e]));
        for (int i = 0; i < n; i++) {
            mm_error err = {0};
            if (mm_draw_request(ex, &g, 50, &set, &err) != MM_OK)
                continue;                      /* the joint check refused 50 in a row: nothing to solve */
            char q[4096];
            int p = 0;
            for (int k = 0; k < set.n; k++)
                p += snprintf(q + p, sizeof q - (size_t)p, "%s%.*s=%.*s", k ? "&" : "", (int)set.in[k].name_len,
                              set.in[k].name, (int)set.in[k].text_len, set.in[k].text);
            cJSON_Delete(solve_ok(ids[e], q));
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(pendulum_defaults_should_give_the_elliptic_period),
        cmocka_unit_test(double_pendulum_twins_apart_from_the_start_should_have_horizon_zero),
        cmocka_unit_test(pendulum_at_the_separatrix_should_give_no_period_and_stay_up),
        cmocka_unit_test(pendulum_just_below_the_separatrix_should_have_the_logarithmic_period),
        cmocka_unit_test(pendulum_pushed_over_the_top_should_turn),
        cmocka_unit_test(pendulum_tiny_swing_should_be_answered),
        cmocka_unit_test(double_pendulum_symplectic_check_should_allow_a_faster_second_half),
        cmocka_unit_test(pendulum_short_run_on_a_fine_grid_should_pass_its_trajectory_check),
        cmocka_unit_test(pendulum_fast_turn_over_the_top_should_keep_its_energy_between_steps),
        cmocka_unit_test(pendulum_short_hard_swing_should_keep_its_energy_on_the_plot_grid),
        cmocka_unit_test(double_pendulum_first_step_should_not_land_on_a_zero_of_the_error_estimate),
        cmocka_unit_test(double_pendulum_loose_dopri5_that_runs_away_should_still_answer),
        cmocka_unit_test(double_pendulum_energy_over_1000_periods_should_stay_bounded_only_when_symplectic),
        cmocka_unit_test(double_pendulum_defaults_should_be_chaotic),
        cmocka_unit_test(robot_commanded_out_of_reach_should_say_which_joint),
        cmocka_unit_test(robot_defaults_should_start_from_the_static_torques),
        cmocka_unit_test(dyn_plan_should_start_and_end_at_rest_and_drive_the_planned_acceleration),
        cmocka_unit_test(dyn_slider_crank_energy_bound_should_bound_the_energy_difference),
        cmocka_unit_test(dyn_extreme_error_should_find_the_vertex_of_a_sampled_parabola),
        cmocka_unit_test(slider_crank_should_coast_through_its_dead_centres),
        cmocka_unit_test(the_last_animation_frame_should_not_overshoot_the_run),
        cmocka_unit_test(slider_crank_with_a_torque_should_gain_its_work),
        cmocka_unit_test(slider_crank_energy_tolerance_should_be_within_100x_of_its_error),
        cmocka_unit_test(slider_crank_draws_that_failed_should_answer_with_every_check_passed),
        cmocka_unit_test(slider_crank_one_step_run_should_state_its_error),
        cmocka_unit_test(slider_crank_at_a_loose_tolerance_should_stay_on_its_energy_level),
        cmocka_unit_test(double_pendulum_draws_that_failed_should_answer_with_every_check_passed),
        cmocka_unit_test(dyn_exercises_should_pass_every_check_on_random_draws),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
