/* test_dpend_lh.c — mm_dpend_lh_residual: Lagrange's and Hamilton's
 * equations of the double pendulum agree to rounding, and the scale of
 * that rounding is the one worked out by hand at a state at rest. */
#include "mm_test.h"

#include <float.h>

#include "mm_multibody.h"

/* m = l = g = 1, both rods horizontal (theta = pi/2), at rest: M = [2 1; 1 1],
 * the gravity torques (-2, -1), so w' = M^-1 (-2, -1) = (-1, 0); the terms
 * summed are |2 w1'| + |w1'| + |p1'| + |p2'| = 2 + 1 + 2 + 1 = 6 and cond M
 * ~ trace^2 / det = 9: the scale is 54 */
static void a_state_at_rest_should_have_the_hand_worked_scale(void **state)
{
    (void)state;
    mm_dpend s = {.m1 = 1, .m2 = 1, .l1 = 1, .l2 = 1, .g = 1};
    const double y[4] = {M_PI / 2, M_PI / 2, 0, 0};
    double scale, r = mm_dpend_lh_residual(&s, y, &scale);
    check_rel(scale, 54, 8 * DBL_EPSILON, "(sum of |terms|) cond M");
    check_abs(r, 0, 8 * DBL_EPSILON * scale, "the two formulations at rest");
    const double hanging[4] = {0, 0, 0, 0};
    assert_true(mm_dpend_lh_residual(&s, hanging, &scale) == 0.0 && scale == 0.0);
}

/* moving states of an unequal pendulum: the two formulations within 8 eps
 * of the scale (the check of dyn-double-pendulum) */
static void moving_states_should_agree_to_rounding(void **state)
{
    (void)state;
    mm_dpend s = {.m1 = 0.3, .m2 = 2, .l1 = 1.5, .l2 = 0.4, .g = 9.81};
    for (int i = 0; i < 20; i++) {
        double y[4] = {-3 + 0.3 * i, 2 - 0.2 * i, 5 * sin(i), -7 * cos(2 * i)}, scale;
        double r = mm_dpend_lh_residual(&s, y, &scale);
        assert_true(scale > 0);
        check_abs(r, 0, 8 * DBL_EPSILON * scale, "Lagrange vs Hamilton at a moving state");
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_state_at_rest_should_have_the_hand_worked_scale),
        cmocka_unit_test(moving_states_should_agree_to_rounding),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
