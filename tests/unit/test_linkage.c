/* test_linkage.c — mm_linkage's closed forms against what they must satisfy:
 * Freudenstein's angles close the loop (1) on the side asked, the rates are
 * the derivatives of the angles (central differences), Grashof's five
 * classes and the change point, the arc a rocking crank reaches ends where
 * the loop stops closing, the transmission angle's extremes, the rocker's
 * dead centres (crank and coupler in line); the slider-crank's closed form
 * closes its loop, its derivatives are differences of it, and its reach;
 * the quick return's closed form closes its loop and differentiates, and
 * Newton and the Jacobian solves on its loop closure land on it. */
#include "mm_test.h"

#include <float.h>
#include <string.h>

#include "mm_linkage.h"
#include "mm_mech.h"

#define EPS DBL_EPSILON

static const mm_fourbar crank_rocker = {0.2, 0.5, 0.4, 0.6};   /* kin-four-bar's defaults */

/* the residual of eq. (1) and the side of C relative to B -> O4 */
static double fb_residual(const mm_fourbar *m, double th2, double th3, double th4, double *side)
{
    double Bx = m->a * cos(th2), By = m->a * sin(th2), Cx = Bx + m->b * cos(th3), Cy = By + m->b * sin(th3);
    *side = (m->d - Bx) * (Cy - By) + By * (Cx - Bx);
    return fmax(fabs(Cx - m->d - m->c * cos(th4)), fabs(Cy - m->c * sin(th4)));
}

static void freudenstein_should_close_the_loop_on_the_side_asked(void **state)
{
    (void)state;
    const mm_fourbar ms[3] = {crank_rocker, {1, 1, 1, 1}, {0.3, 1, 0.9, 1.1}};   /* a rhombus: A = 0 */
    for (int k = 0; k < 3; k++)
        for (double th2 = -3.1; th2 < 3.14; th2 += 0.1)
            for (int side = -1; side <= 1; side += 2) {
                double t3, t4, e, sd;
                if (mm_linkage_fb_disc(&ms[k], th2) <= 0)
                    continue;
                mm_linkage_fb_angles(&ms[k], th2, side, &t3, &t4, &e);
                double S = ms[k].a + ms[k].b + ms[k].c + ms[k].d;
                /* rounding of the angles (their bound e) times a length, and a few eps of S */
                check_abs(fb_residual(&ms[k], th2, t3, t4, &sd), 0, 8 * EPS * S + 2 * S * e, "loop closure (1)");
                assert_true(side * sd >= -1e-12);
            }
}

static void a_rhombus_folded_flat_should_take_any_assembly_deterministically(void **state)
{
    (void)state;
    /* a = b = c = d at th2 = 0: B lies on O4 and every theta4 closes the
     * loop (A = B = C = 0).  Both roots were skipped and theta4 was read
     * uninitialised (valgrind, kin-four-bar's rhombus test); now theta4 = 0,
     * theta3 = 0 (the coupler along the frame), and the nearest root is the
     * sweep's own angles */
    const mm_fourbar m = {1, 1, 1, 1};
    double t3 = 9, t4 = 9, e;
    for (int side = -1; side <= 1; side += 2) {
        mm_linkage_fb_angles(&m, 0, side, &t3, &t4, &e);
        assert_true(t4 == 0 && t3 == 0);
    }
    double q[2] = {0.3, 1.2}, f[2];
    mm_linkage_fb_nearest(&m, 0, q, f, &e);
    assert_true(f[0] == q[0] && f[1] == q[1]);
    /* a hair away it is a linkage again: B = (cos h, sin h) and C on the circle about O4 */
    mm_linkage_fb_angles(&m, 1e-3, 1, &t3, &t4, &e);
    double Bx = cos(1e-3), By = sin(1e-3), Cx = 1 + cos(t4), Cy = sin(t4);
    check_abs(hypot(Cx - Bx, Cy - By), 1, 1e-12, "|BC| = b");
}

static void the_rates_should_be_the_derivatives_of_the_angles(void **state)
{
    (void)state;
    const double h = 1e-4;
    for (double th2 = 0.05; th2 < 6.2; th2 += 0.3) {
        double t3, t4, p3, p4, m3, m4, w3, w4, a3, a4;
        mm_linkage_fb_angles(&crank_rocker, th2, 1, &t3, &t4, NULL);
        mm_linkage_fb_angles(&crank_rocker, th2 + h, 1, &p3, &p4, NULL);
        mm_linkage_fb_angles(&crank_rocker, th2 - h, 1, &m3, &m4, NULL);
        mm_linkage_fb_rates(&crank_rocker, th2, t3, t4, &w3, &w4, &a3, &a4);
        /* central differences: h^2 / 6 q''' (|q'''| < 30 here) and eps / h of rounding */
        check_abs(remainder(p3 - m3, 2 * M_PI) / (2 * h), w3, 1e-6, "omega3 / omega2 vs central difference");
        check_abs(remainder(p4 - m4, 2 * M_PI) / (2 * h), w4, 1e-6, "omega4 / omega2 vs central difference");
        check_abs(remainder(p3 - 2 * t3 + m3, 2 * M_PI) / (h * h), a3, 1e-4, "alpha3 vs second difference");
        check_abs(remainder(p4 - 2 * t4 + m4, 2 * M_PI) / (h * h), a4, 1e-4, "alpha4 vs second difference");
    }
}

static void grashof_should_name_the_five_classes_and_the_change_point(void **state)
{
    (void)state;
    struct {
        mm_fourbar m;
        const char *name;
        int full;
    } cases[] = {
        {{0.2, 0.5, 0.4, 0.6}, "crank-rocker", 1},
        {{0.5, 0.2, 0.6, 0.4}, "double rocker (Grashof)", 0},
        {{0.4, 0.6, 0.2, 0.5}, "rocker-crank", 0},
        {{0.5, 0.4, 0.6, 0.2}, "double crank (drag link)", 1},
        {{0.5, 0.7, 0.55, 0.45}, "triple rocker (non-Grashof)", 0},
        {{0.2, 0.6, 0.2, 0.6}, "change point", 1},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        mm_fourbar_class k = mm_linkage_fb_classify(&cases[i].m, 2.0);
        assert_string_equal(k.name, cases[i].name);
        assert_int_equal(k.full, cases[i].full);
    }
}

static void a_rocking_crank_should_reach_exactly_to_its_toggles(void **state)
{
    (void)state;
    const mm_fourbar m = {0.5, 0.7, 0.55, 0.45};                   /* triple rocker */
    mm_fourbar_class k = mm_linkage_fb_classify(&m, 2.0);
    assert_true(k.lo < 2.0 && 2.0 < k.hi);
    /* disc is a product of lengths that vanishes at the toggle: a few eps of S^2 */
    check_abs(mm_linkage_fb_disc(&m, k.lo), 0, 16 * EPS, "disc at the lower toggle");
    check_abs(mm_linkage_fb_disc(&m, k.hi), 0, 16 * EPS, "disc at the upper toggle");
    assert_true(mm_linkage_fb_disc(&m, k.lo - 1e-6) < 0 && mm_linkage_fb_disc(&m, k.hi + 1e-6) < 0);
    double mn, tmn, mx, tmx;
    mm_linkage_fb_mu_extremes(&m, 0, k.lo, k.hi, &mn, &tmn, &mx, &tmx);
    assert_true(mn == 0 || mx == M_PI);                             /* in line at a toggle */
}

static void the_transmission_angle_of_a_crank_rocker_should_peak_at_0_and_pi(void **state)
{
    (void)state;
    const mm_fourbar *m = &crank_rocker;
    double mn, tmn, mx, tmx;
    mm_linkage_fb_mu_extremes(m, 1, 0, 2 * M_PI, &mn, &tmn, &mx, &tmx);
    /* law of cosines with |O4 B| = d - a at th2 = 0 and d + a at pi */
    double at0 = acos((m->b * m->b + m->c * m->c - (m->d - m->a) * (m->d - m->a)) / (2 * m->b * m->c));
    double atpi = acos((m->b * m->b + m->c * m->c - (m->d + m->a) * (m->d + m->a)) / (2 * m->b * m->c));
    check_abs(mn, fmin(at0, atpi), 4 * EPS, "least transmission angle");
    check_abs(mx, fmax(at0, atpi), 4 * EPS, "greatest transmission angle");
    assert_true((tmn == 0 && tmx == M_PI) || (tmn == M_PI && tmx == 0));
}

static void the_dead_centres_should_put_crank_and_coupler_in_line(void **state)
{
    (void)state;
    double dc[4], dce[4];
    int nd = mm_linkage_fb_dead_centres(&crank_rocker, dc, dce);
    assert_int_equal(nd, 4);
    int in_line = 0;
    for (int i = 0; i < nd; i++)
        for (int side = -1; side <= 1; side += 2) {
            double t3, t4;
            mm_linkage_fb_angles(&crank_rocker, dc[i], side, &t3, &t4, NULL);
            /* sin of the angle between crank and coupler: the rounding of dc times a / b */
            in_line += fabs(sin(t3 - dc[i])) < 1e-7;
        }
    assert_true(in_line >= 4);          /* each dead centre on at least one assembly */
    /* the swing: the rocker's angles at the stretched and folded positions */
    double s = mm_linkage_fb_swing(&crank_rocker, 1), lo = INFINITY, hi = -INFINITY;
    for (double th2 = 0; th2 < 2 * M_PI; th2 += 1e-4) {
        double t3, t4;
        mm_linkage_fb_angles(&crank_rocker, th2, 1, &t3, &t4, NULL);
        t4 = t4 < 0 ? t4 + 2 * M_PI : t4;
        lo = fmin(lo, t4), hi = fmax(hi, t4);
    }
    /* sampled every 1e-4 rad near a turning point: (1e-4)^2 |theta4''| / 2 */
    check_abs(hi - lo, s, 1e-7, "swing vs the sampled extremes of theta4");
}

static void the_slider_crank_closed_form_should_close_its_loop_and_differentiate(void **state)
{
    (void)state;
    const mm_slider_crank m = {0.1, 0.35, 0.05};
    const double h = 1e-4;
    for (double phi = 0.05; phi < 6.2; phi += 0.3) {
        mm_sc_pos p = mm_linkage_sc_closed(&m, phi, 1), pp = mm_linkage_sc_closed(&m, phi + h, 1),
                  pm = mm_linkage_sc_closed(&m, phi - h, 1);
        check_abs(m.r * cos(phi) + m.l * cos(p.t) - p.x, 0, 4 * EPS, "loop closure along the slide");
        check_abs(m.r * sin(phi) + m.l * sin(p.t) - m.e, 0, 4 * EPS, "loop closure across the slide");
        /* h^2 / 6 of the third derivative (< 1 m here) and eps / h^2 of rounding */
        check_abs((pp.x - pm.x) / (2 * h), p.x1, 1e-8, "x' vs central difference");
        check_abs((pp.x - 2 * p.x + pm.x) / (h * h), p.x2, 1e-6, "x'' vs second difference");
        check_abs((pp.t - pm.t) / (2 * h), p.t1, 1e-8, "theta3' vs central difference");
    }
}

static void the_slider_crank_should_reach_between_its_toggles(void **state)
{
    (void)state;
    double lo, hi, gaps[2];
    const mm_slider_crank turns = {0.1, 0.35, 0.05}, rocks = {0.3, 0.2, 0.15};
    assert_int_equal(mm_linkage_sc_reach(&turns, 1, &lo, &hi, NULL), 0);
    assert_int_equal(mm_linkage_sc_reach(&rocks, 0.1, &lo, &hi, gaps), 1);
    assert_true(lo < 0.1 && 0.1 < hi);
    /* at a toggle the rod stands square to the slide: l^2 - s^2 = 0 to a few eps of l^2 */
    check_abs(mm_linkage_sc_disc(&rocks, lo), 0, 8 * EPS * 0.04, "disc at the lower toggle");
    check_abs(mm_linkage_sc_disc(&rocks, hi), 0, 8 * EPS * 0.04, "disc at the upper toggle");
    /* phi = -pi/2: e - r sin phi = 0.45 > l, out of the rod's reach */
    assert_int_equal(mm_linkage_sc_reach(&rocks, -M_PI / 2, &lo, &hi, NULL), -1);
}

/* ---- the quick return ---- */

static const mm_quick_return shaper = {0.1, 0.25, 0.45};       /* kin-quick-return's defaults */

static void the_quick_return_closed_form_should_close_its_loop_and_differentiate(void **state)
{
    (void)state;
    const mm_quick_return *m = &shaper;
    const double h = 1e-4;
    for (double th = 0.05; th < 6.2; th += 0.3) {
        mm_qr_pos p = mm_linkage_qr_closed(m, th), pp = mm_linkage_qr_closed(m, th + h),
                  pm = mm_linkage_qr_closed(m, th - h);
        /* A on the lever's line, and the block (X, H) on it */
        check_abs(sin(p.t4) * m->r * cos(th) - cos(p.t4) * (m->d + m->r * sin(th)), 0, 4 * EPS, "A on the lever");
        check_abs(sin(p.t4) * p.X - cos(p.t4) * m->H, 0, 8 * EPS, "the block on the lever");
        /* h^2 / 6 of the third derivative and eps / h^2 of rounding: at most
         * 3.8e-9, 3.3e-8, 1.4e-9, 8.5e-9 measured over these angles */
        check_abs((pp.t4 - pm.t4) / (2 * h), p.t4p, 1e-8, "theta4' vs central difference");
        check_abs((pp.t4 - 2 * p.t4 + pm.t4) / (h * h), p.t4pp, 1e-7, "theta4'' vs second difference");
        check_abs((pp.X - pm.X) / (2 * h), p.Xp, 1e-8, "X' vs central difference");
        check_abs((pp.X - 2 * p.X + pm.X) / (h * h), p.Xpp, 1e-7, "X'' vs second difference");
    }
}

static void newton_on_the_quick_return_should_land_on_the_closed_form(void **state)
{
    (void)state;
    const mm_quick_return *m = &shaper;
    mm_mech_problem prob;
    mm_linkage_qr_problem(m, &prob);
    mm_mech_options opt;
    mm_mech_options_init(&opt);
    mm_mech_work *w = mm_mech_work_alloc(4, 4);
    assert_non_null(w);
    for (double th = -3; th < 3.2; th += 0.5) {
        double q[4], qd[4], qdd[4];
        mm_mech_info info;
        mm_linkage_qr_guess(m, th, q);
        assert_int_equal(mm_mech_position(&prob, &opt, w, th, q, &info, NULL), MM_OK);
        assert_int_equal(mm_mech_velocity(&prob, &opt, w, th, q, qd, NULL, NULL), MM_OK);
        assert_int_equal(mm_mech_acceleration(&prob, &opt, w, th, q, qd, qdd, NULL, NULL), MM_OK);
        mm_qr_pos p = mm_linkage_qr_closed(m, th);       /* all within 2.3e-16 measured */
        check_abs(q[0], p.t4, 8 * EPS, "theta4: Newton vs closed form");
        check_abs(q[2], p.X, 8 * EPS, "X: Newton vs closed form");
        check_abs(q[1], hypot(m->r * cos(th), m->d + m->r * sin(th)), 8 * EPS, "s = |O4 A|");
        check_abs(qd[0], p.t4p, 8 * EPS, "theta4': Jacobian solve (nu) vs closed form");
        check_abs(qd[2], p.Xp, 8 * EPS, "X': Jacobian solve vs closed form");
        check_abs(qdd[0], p.t4pp, 8 * EPS, "theta4'': Jacobian solve (gamma) vs closed form");
        check_abs(qdd[2], p.Xpp, 8 * EPS, "X'': Jacobian solve vs closed form");
    }
    mm_mech_work_free(w);
}

/* A toggle where both roots of Freudenstein's quadratic are at t = infinity
 * (A = B = 0, C = 2): a = b = 1, c = d = 2 at th2 = 0 puts B at (1, 0), and
 * the only C at 1 from B and 2 from O4 = (2, 0) is the origin: th4 = pi.
 * Before, both roots were skipped and th4 = 0 came back (|BC| = 3). */
static void fourbar_double_root_at_infinity_should_give_pi(void **state)
{
    (void)state;
    mm_fourbar m = {.a = 1, .b = 1, .c = 2, .d = 2};
    for (int side = -1; side <= 1; side += 2) {
        double t3, t4, e;
        mm_linkage_fb_angles(&m, 0, side, &t3, &t4, &e);
        check_abs(fabs(t4), M_PI, 0, "th4 = pi at the toggle");
        double Cx = 2 + 2 * cos(t4), Cy = 2 * sin(t4);
        check_abs(hypot(Cx - 1, Cy), 1, 4 * DBL_EPSILON, "|BC| = b: the loop closes");
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(fourbar_double_root_at_infinity_should_give_pi),
        cmocka_unit_test(freudenstein_should_close_the_loop_on_the_side_asked),
        cmocka_unit_test(a_rhombus_folded_flat_should_take_any_assembly_deterministically),
        cmocka_unit_test(the_rates_should_be_the_derivatives_of_the_angles),
        cmocka_unit_test(grashof_should_name_the_five_classes_and_the_change_point),
        cmocka_unit_test(a_rocking_crank_should_reach_exactly_to_its_toggles),
        cmocka_unit_test(the_transmission_angle_of_a_crank_rocker_should_peak_at_0_and_pi),
        cmocka_unit_test(the_dead_centres_should_put_crank_and_coupler_in_line),
        cmocka_unit_test(the_slider_crank_closed_form_should_close_its_loop_and_differentiate),
        cmocka_unit_test(the_slider_crank_should_reach_between_its_toggles),
        cmocka_unit_test(the_quick_return_closed_form_should_close_its_loop_and_differentiate),
        cmocka_unit_test(newton_on_the_quick_return_should_land_on_the_closed_form),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
