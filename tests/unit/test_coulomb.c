/* test_coulomb.c — mm_coulomb against the textbook's decay: released from
 * rest at x0 = (2N + 1/2) d, the block stops every half period pi/omega at
 * |x0| - 2 j d with alternating sign, N + ... arcs, and stays in the band. */
#include "mm_test.h"

#include <math.h>

#include "mm_coulomb.h"

static void a_release_from_rest_should_lose_two_bands_each_half_cycle(void **state)
{
    (void)state;
    /* m = 2 kg, k = 800 N/m: omega = 20 rad/s; mu g = 0.2 * 10: d = 2 * 2 / 800 = 5 mm */
    mm_coulomb s = mm_coulomb_make(2, 800, 0.2, 10, 0.0525, 0);
    check_rel(s.w, 20, 1e-15, "omega_n");
    check_rel(s.d, 0.005, 1e-15, "friction band");
    double t[32], x[32], sg[32];
    int n = mm_coulomb_arcs(&s, t, x, sg, 32);
    /* 52.5 mm: rests at -42.5, 32.5, -22.5, 12.5, -2.5 mm (inside the band): 5 arcs */
    assert_int_equal(n, 5);
    assert_true(mm_coulomb_arc_count(&s) == 5);
    for (int j = 0; j < n; j++) {
        double want = (j % 2 ? 1 : -1) * (0.0525 - 0.01 * (j + 1));
        check_abs(x[j], want, 1e-16, "rest place");
        check_rel(t[j], (j + 1) * M_PI / 20, 1e-15, "rest time");
        assert_true(sg[j] == (j % 2 ? 1 : -1));
    }
    assert_true(mm_coulomb_sticks(&s, x[n - 1]));
    assert_false(mm_coulomb_sticks(&s, x[n - 2]));
    /* mid-arc: x - c = (x0 - c) cos(w t) on the first arc, c = +d */
    double v, xm = mm_coulomb_x(&s, t, x, sg, n, 0.5 * M_PI / 20, &v);
    check_abs(xm, 0.005, 1e-16, "at a quarter period the block passes the shifted centre");
    check_rel(v, -(0.0525 - 0.005) * 20, 1e-15, "with the velocity of the shifted oscillator");
    xm = mm_coulomb_x(&s, t, x, sg, n, 10, &v);
    assert_true(xm == x[n - 1] && v == 0);
}

static void a_block_inside_the_band_or_pushed_should_follow_the_first_arc(void **state)
{
    (void)state;
    double sg, tau, x1;
    mm_coulomb held = mm_coulomb_make(1, 100, 0.5, 9.81, 0.04, 0);   /* band 49 mm */
    assert_int_equal(mm_coulomb_first_arc(&held, &sg, &tau, &x1), 0);
    assert_true(mm_coulomb_arc_count(&held) == 0);
    /* pushed from x0 = 0 with v0: a half-cycle about c = -d of amplitude v0/w, ends at -d + R */
    mm_coulomb pushed = mm_coulomb_make(1, 100, 0.1, 10, 0, 1);      /* w = 10, d = 10 mm */
    assert_int_equal(mm_coulomb_first_arc(&pushed, &sg, &tau, &x1), 1);
    double R = hypot(0.01, 0.1);
    check_rel(x1, -0.01 + R, 1e-15, "end of the first arc");
    check_rel(tau, atan2(0.1, 0.01) / 10, 1e-15, "time of the first rest");
    assert_true(sg == 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_release_from_rest_should_lose_two_bands_each_half_cycle),
        cmocka_unit_test(a_block_inside_the_band_or_pushed_should_follow_the_first_arc),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
