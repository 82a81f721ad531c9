/* test_sc_newton.c — mm_sc_momentum_residual and mm_sc_drift: hand-worked
 * values, and Newton's law for the rod and the piston against the joint
 * forces mm_sc_accel finds in the null space of the constraints (a
 * different route: the multipliers from the equations of motion, the
 * momentum from the centres of mass). */
#include "mm_test.h"

#include <float.h>

#include "mm_multibody.h"

static const mm_sc_model sc = {.r = 0.1, .l = 0.35, .J_crank = 0.5, .m_rod = 2, .J_rod = 0.02,
                                   .m_piston = 4, .torque = 3};

static void momentum_residual_should_match_a_hand_value(void **state)
{
    (void)state;
    /* forces: bearing (1, 2), guide N = 3; inertia: 2 * 0.5 + 4 * 0.25 = 2 along x */
    const double lam[4] = {-1, -2, 0, -3}, qdd[5] = {0, 0.5, 0, 0, 0.25};
    double scale, r = mm_sc_momentum_residual(&sc, qdd, lam, &scale);
    check_rel(r, sqrt(26.0), DBL_EPSILON, "|(1 - 2, 2 + 3 - 0)|");
    check_rel(scale, sqrt(5.0) + 3 + 1 + 1, DBL_EPSILON, "|F_A| + |F_B| + the inertia forces");
}

static void joint_forces_should_obey_newton_at_every_crank_angle(void **state)
{
    (void)state;
    for (int k = 0; k < 24; k++) {
        double q[MM_SC_NQ], qd[MM_SC_NQ], qdd[MM_SC_NQ], lam[MM_SC_NC], scale;
        mm_sc_assemble(&sc, 2 * M_PI * k / 24, 30 - k, q, qd);
        assert_int_equal(mm_sc_accel(&sc, q, qd, 0, 0, qdd, lam), MM_OK);
        double r = mm_sc_momentum_residual(&sc, qdd, lam, &scale);
        check_abs(r, 0, 16 * DBL_EPSILON * scale, "Newton for rod and piston vs the multipliers");
        /* the assembled configuration satisfies the constraints to rounding */
        check_abs(mm_sc_drift(&sc, q), 0, 4 * DBL_EPSILON * (sc.r + sc.l), "constraints at assembly");
    }
    /* a piston moved by 1e-3 m off its pin: the drift is that */
    double q[MM_SC_NQ], qd[MM_SC_NQ];
    mm_sc_assemble(&sc, 1, 0, q, qd);
    q[4] += 1e-3;
    check_rel(mm_sc_drift(&sc, q), 1e-3, 1e-12, "x2 + l/2 cos phi2 - x3 off by 1e-3");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(momentum_residual_should_match_a_hand_value),
        cmocka_unit_test(joint_forces_should_obey_newton_at_every_crank_angle),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
