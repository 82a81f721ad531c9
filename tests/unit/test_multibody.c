/* test_multibody.c — the equations of mm_multibody against each other and
 * against closed forms: the double pendulum's two formulations and its
 * small oscillation, the arm's inverse and forward dynamics and its power
 * balance, the slider-crank's constraints, multipliers and effective
 * inertia. */
#include "mm_test.h"

#include <float.h>

#include "mm_multibody.h"

#define EPS DBL_EPSILON

static unsigned long long rs = 0x243F6A8885A308D3ULL;

static double urand(double a, double b)
{
    rs ^= rs >> 12;
    rs ^= rs << 25;
    rs ^= rs >> 27;
    return a + (b - a) * (double)((rs * 2685821657736338717ULL) >> 11) / 9007199254740992.0;
}

/* ---- the double pendulum ------------------------------------------------------- */

static void double_pendulum_hamilton_should_equal_lagrange(void **state)
{
    (void)state;
    for (int it = 0; it < 200; it++) {
        mm_dpend s = {urand(0.1, 3), urand(0.1, 3), urand(0.2, 2), urand(0.2, 2), 9.81};
        double y[4] = {urand(-3, 3), urand(-3, 3), urand(-5, 5), urand(-5, 5)}, yp[4], yw[4], dl[4], dh[4];
        mm_dpend_to_momenta(&s, y, yp);
        mm_dpend_to_velocities(&s, yp, yw);
        for (int k = 0; k < 4; k++)
            check_abs(yw[k], y[k], 1e-12 * (1 + fabs(y[k])), "w -> p -> w");
        mm_dpend_rhs_lagrange(0, y, dl, &s);
        mm_dpend_rhs_hamilton(0, yp, dh, &s);
        /* dp/dt = M w' + M' w, M' = -m2 l1 l2 sin d (d') [0 1; 1 0] */
        double d = y[0] - y[1], k = s.m2 * s.l1 * s.l2, c = cos(d), sn = sin(d), dd = y[2] - y[3];
        double p1 = (s.m1 + s.m2) * s.l1 * s.l1 * dl[2] + k * (c * dl[3] - sn * dd * y[3]);
        double p2 = s.m2 * s.l2 * s.l2 * dl[3] + k * (c * dl[2] - sn * dd * y[2]);
        double scale = fabs(p1) + fabs(p2) + k * (fabs(dl[2]) + fabs(dl[3]) + fabs(dd) * (fabs(y[2]) + fabs(y[3])));
        /* both sides pass through M^-1: with m1 >= 0.1 its condition is below ~1e3 */
        check_abs(dh[2], p1, 1e3 * EPS * scale, "dp1/dt: Hamilton vs Lagrange");
        check_abs(dh[3], p2, 1e3 * EPS * scale, "dp2/dt: Hamilton vs Lagrange");
    }
}

static void double_pendulum_small_oscillation_should_have_the_textbook_frequencies(void **state)
{
    (void)state;
    /* equal masses and lengths: w^2 = (2 -+ sqrt 2) g / l */
    mm_dpend s = {1, 1, 1, 1, 9.81};
    double ws, wf;
    mm_dpend_linear(&s, &ws, &wf);
    check_rel(ws, sqrt((2 - sqrt(2)) * 9.81), 4 * EPS, "slow mode");
    check_rel(wf, sqrt((2 + sqrt(2)) * 9.81), 4 * EPS, "fast mode");
    /* a light lower bob: the slow mode tends to the upper pendulum's sqrt(g/l1) */
    mm_dpend t = {1, 1e-8, 2, 0.5, 9.81};
    mm_dpend_linear(&t, &ws, &wf);
    check_rel(ws, sqrt(9.81 / 2), 1e-7, "m2 -> 0: sqrt(g/l1)");
    /* energy is zero at the bottom at rest plus V_min */
    double y[4] = {0, 0, 0, 0}, sc;
    check_rel(mm_dpend_energy(&s, y, &sc), -3 * 9.81, 4 * EPS, "V_min = -(m1+m2) g l1 - m2 g l2");
}

/* ---- the robot ------------------------------------------------------------------ */

static void robot_forward_should_invert_inverse_dynamics(void **state)
{
    (void)state;
    for (int it = 0; it < 200; it++) {
        mm_robot2 s = {urand(0.1, 3), urand(0.1, 3), urand(0.1, 10), urand(0.1, 10), urand(0, 20)};
        double q[2] = {urand(-6, 6), urand(-3, 3)}, qd[2] = {urand(-5, 5), urand(-5, 5)};
        double qdd[2] = {urand(-20, 20), urand(-20, 20)}, tau[2], back[2];
        mm_robot2_inverse(&s, q, qd, qdd, tau);
        mm_robot2_forward(&s, q, qd, tau, back);
        check_abs(back[0], qdd[0], 1e-9 * (1 + fabs(qdd[0])), "forward(inverse(qdd)) = qdd, joint 1");
        check_abs(back[1], qdd[1], 1e-9 * (1 + fabs(qdd[1])), "forward(inverse(qdd)) = qdd, joint 2");
    }
}

static void robot_power_should_equal_the_rate_of_energy(void **state)
{
    (void)state;
    /* tau . q' = d(T + V)/dt along q(t) = a + b t + c t^2: by a central
     * difference in t (h = 1e-5: error ~1e-9 of the power) */
    mm_robot2 s = {1.2, 0.7, 2, 1.5, 9.81};
    for (int it = 0; it < 50; it++) {
        double a[2] = {urand(-3, 3), urand(-3, 3)}, b[2] = {urand(-2, 2), urand(-2, 2)}, c[2] = {urand(-2, 2), urand(-2, 2)};
        double t = 0.3, h = 1e-5, E[2];
        for (int k = 0; k < 2; k++) {
            double tt = t + (k ? h : -h), q[2], qd[2], T, V;
            for (int j = 0; j < 2; j++)
                q[j] = a[j] + b[j] * tt + c[j] * tt * tt, qd[j] = b[j] + 2 * c[j] * tt;
            mm_robot2_energy(&s, q, qd, &T, &V);
            E[k] = T + V;
        }
        double q[2], qd[2], qdd[2], tau[2];
        for (int j = 0; j < 2; j++)
            q[j] = a[j] + b[j] * t + c[j] * t * t, qd[j] = b[j] + 2 * c[j] * t, qdd[j] = 2 * c[j];
        mm_robot2_inverse(&s, q, qd, qdd, tau);
        double P = tau[0] * qd[0] + tau[1] * qd[1];
        check_abs(P, (E[1] - E[0]) / (2 * h), 1e-7 * (1 + fabs(P)), "power of the motors = dE/dt");
    }
}

static void robot_static_torque_should_match_the_moment_of_gravity(void **state)
{
    (void)state;
    /* stretched horizontally: tau1 = g (m1 l1/2 + m2 (l1 + l2/2)), tau2 = g m2 l2 / 2 */
    mm_robot2 s = {1, 0.5, 2, 3, 9.81};
    double q[2] = {0, 0}, z[2] = {0, 0}, tau[2];
    mm_robot2_inverse(&s, q, z, z, tau);
    check_rel(tau[0], 9.81 * (2 * 0.5 + 3 * 1.25), 4 * EPS, "shoulder holds both links");
    check_rel(tau[1], 9.81 * 3 * 0.25, 4 * EPS, "elbow holds link 2");
    double x[3], y[3];
    double qq[2] = {M_PI / 2, -M_PI / 2};
    mm_robot2_points(&s, qq, x, y);
    check_abs(x[2], 0.5, 1e-15, "tip x");
    check_abs(y[2], 1, 1e-15, "tip y");
}

/* ---- the slider-crank ------------------------------------------------------------ */

static void slider_crank_assembly_should_satisfy_the_constraints(void **state)
{
    (void)state;
    mm_sc_model s = {.r = 0.1, .l = 0.35, .J_crank = 0.05, .m_rod = 1, .J_rod = 0.012, .m_piston = 0.8,
                         .torque = 3};
    for (double phi = -7; phi < 7; phi += 0.37) {
        double q[5], qd[5], Phi[4], Phid[4];
        mm_sc_assemble(&s, phi, 37, q, qd);
        mm_sc_constraints(&s, q, qd, Phi, Phid);
        for (int i = 0; i < 4; i++) {
            check_abs(Phi[i], 0, 4 * EPS * (s.r + s.l), "Phi = 0 at the closed-form position");
            check_abs(Phid[i], 0, 8 * EPS * 37 * (s.r + s.l), "Phi' = 0 at the closed-form velocity");
        }
        /* the kinetic energy of the bodies = J(phi) w^2 / 2 */
        check_rel(mm_sc_kinetic(&s, q, qd), 0.5 * mm_sc_inertia(&s, phi, NULL) * 37 * 37, 16 * EPS,
                  "T = J(phi) w^2 / 2");
        /* dJ/dphi by a central difference (h = 1e-5: ~1e-10 of J) */
        double dJ, Jp = mm_sc_inertia(&s, phi + 1e-5, NULL), Jm = mm_sc_inertia(&s, phi - 1e-5, NULL);
        mm_sc_inertia(&s, phi, &dJ);
        check_abs(dJ, (Jp - Jm) / 2e-5, 1e-8, "dJ/dphi");
        /* the accelerations satisfy Phi_q q'' = gamma (no stabilisation):
         * Phi'' by differences of Phi' along the motion over dt = 1e-6 */
        double qdd[5], lam[4];
        assert_int_equal(mm_sc_accel(&s, q, qd, 0, 0, qdd, lam), MM_OK);
        /* the crank: J_crank phi'' = torque + r x (lambda1, lambda2), the
         * rod pushing back on the crank pin */
        double moment = s.r * cos(phi) * lam[1] - s.r * sin(phi) * lam[0];
        check_abs(s.J_crank * qdd[0], s.torque + moment, 1e-12 * (fabs(s.torque) + fabs(moment)),
                  "crank: J phi'' = torque + r x F(rod on crank)");
        /* the piston: m x3'' = lambda3 (the rod pushes it) */
        check_abs(s.m_piston * qdd[4], lam[2], 1e-12 * fabs(lam[2]) + 1e-12, "piston: m a = F_B");
    }
    /* the effective inertia at the dead centre: J_crank + m_rod r^2/4 + J_rod (r/l)^2 */
    check_rel(mm_sc_inertia(&s, 0, NULL), 0.05 + 1 * 0.0025 + 0.012 * (0.1 / 0.35) * (0.1 / 0.35), 4 * EPS,
              "J(0) in closed form");
}

static void slider_crank_reduced_speed_should_follow_the_energy(void **state)
{
    (void)state;
    /* the reduced equation's acceleration at phi: J phi'' + J'(phi) w^2 / 2 = torque */
    mm_sc_model sc = {.r = 0.1, .l = 0.4, .J_crank = 0.05, .m_rod = 1, .J_rod = 0.015, .m_piston = 1,
                          .torque = 5};
    mm_sc_system sys = {.sc = sc};
    for (double phi = 0; phi < 6.3; phi += 0.5) {
        double y[2] = {phi, 80}, dy[2], dJ, J = mm_sc_inertia(&sc, phi, &dJ);
        assert_int_equal(mm_sc_rhs_reduced(0, y, dy, &sys), MM_OK);
        check_abs(J * dy[1] + 0.5 * dJ * 80 * 80, 5, 1e-9 * (5 + fabs(dJ) * 6400),
                  "J phi'' + J' w^2 / 2 = torque (Lagrange's equation in the crank angle)");
    }
}

/* The energy allowance of one DOP853 step is sum_j |dE/dy_j| rtol (1 + |y_j|):
 * its gradient against central differences of mm_dpend_energy (error
 * h^2 E'''/6, about 1e-9 of the gradient at h = 1e-5). */
static void energy_allowance_should_weigh_the_gradient_of_the_energy(void **state)
{
    (void)state;
    const mm_dpend s = {.m1 = 2, .m2 = 0.7, .l1 = 1.3, .l2 = 0.8, .g = 9.81};
    const double y[4] = {0.9, -2.1, 1.7, -0.4}, rtol = 1e-8, h = 1e-5;
    double want = 0;
    for (int j = 0; j < 4; j++) {
        double yp[4], ym[4];
        for (int k = 0; k < 4; k++)
            yp[k] = ym[k] = y[k];
        yp[j] += h, ym[j] -= h;
        double g = (mm_dpend_energy(&s, yp, NULL) - mm_dpend_energy(&s, ym, NULL)) / (2 * h);
        want += fabs(g) * rtol * (1 + fabs(y[j]));
    }
    check_rel(mm_dpend_energy_allowance(&s, y, rtol), want, 1e-8, "allowance against a differenced gradient");
}

/* The growth fit on an exact exponential d = d0 e^(lam t): the slope to
 * rounding, a standard error of nothing, the window where d passes 1e3 d0
 * and 1e-3; no fit when the separation never grows. */
static void growth_fit_should_recover_an_exact_exponential(void **state)
{
    (void)state;
    enum { N = 400 };
    double x[N], d[N], d0 = 1e-12, lam_true = 1.7, lam, a0, se;
    for (int i = 0; i < N; i++)
        x[i] = 0.05 * i, d[i] = d0 * exp(lam_true * x[i]);
    int lo, hi;
    assert_int_equal(mm_growth_fit(x, d, N, d0, &lo, &hi, &lam, &a0, &se), 1);
    check_rel(lam, lam_true, 1e-12, "slope of ln d");
    check_rel(a0, log(d0), 1e-12, "intercept");
    assert_true(se < 1e-10);
    assert_true(d[lo] > 1e3 * d0 && d[lo - 1] <= 1e3 * d0 && d[hi] > 1e-3 && d[hi - 1] <= 1e-3);
    for (int i = 0; i < N; i++)
        d[i] = d0;                                         /* no growth: nothing to fit */
    assert_int_equal(mm_growth_fit(x, d, N, d0, &lo, &hi, &lam, &a0, &se), 0);
    assert_int_equal(lo, -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(double_pendulum_hamilton_should_equal_lagrange),
        cmocka_unit_test(double_pendulum_small_oscillation_should_have_the_textbook_frequencies),
        cmocka_unit_test(robot_forward_should_invert_inverse_dynamics),
        cmocka_unit_test(robot_power_should_equal_the_rate_of_energy),
        cmocka_unit_test(robot_static_torque_should_match_the_moment_of_gravity),
        cmocka_unit_test(slider_crank_assembly_should_satisfy_the_constraints),
        cmocka_unit_test(slider_crank_reduced_speed_should_follow_the_energy),
        cmocka_unit_test(energy_allowance_should_weigh_the_gradient_of_the_energy),
        cmocka_unit_test(growth_fit_should_recover_an_exact_exponential),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
