/* test_cam.c — mm_cam's rise laws against what defines them: a rise of 0
 * to 1 with the end conditions of each law, derivatives that are the
 * differences of the law, peaks that are the maxima over the rise; the
 * motion over a turn is continuous where the law says so; the pitch
 * curve's radius of curvature of a dwell is the pitch circle's; the
 * largest pressure angle and smallest convex radius found by the search
 * against a scan of 2e6 cam angles. */
#include "mm_test.h"

#include <float.h>

#include "mm_cam.h"

#define EPS DBL_EPSILON

static void every_law_should_rise_from_0_to_1_with_its_derivatives(void **state)
{
    (void)state;
    const double h = 1e-4;
    for (int law = 0; law < 4; law++) {
        double d0[4], d1[4];
        mm_cam_rise(law, 0, d0);
        mm_cam_rise(law, 1, d1);
        check_abs(d0[0], 0, 0, "s(0) = 0 exactly");
        check_abs(d1[0], 1, 2 * EPS, "s(1) = 1");
        check_abs(d0[1], 0, 0, "no speed at the start");
        check_abs(d1[1], 0, 4 * EPS, "no speed at the end");
        for (double u = 0.013; u < 1; u += 0.0417) {
            if (law == MM_CAM_CONST_ACC && fabs(u - 0.5) < 2 * h)
                continue;                                         /* s'' jumps at the middle */
            double p[4], m[4], c[4];
            mm_cam_rise(law, u + h, p), mm_cam_rise(law, u - h, m), mm_cam_rise(law, u, c);
            /* central differences: h^2 / 6 of the next derivative (< 250 for these laws) and eps / h */
            check_abs((p[0] - m[0]) / (2 * h), c[1], 1e-6, "s' vs central difference of s");
            check_abs((p[1] - m[1]) / (2 * h), c[2], 1e-5, "s'' vs central difference of s'");
            if (law != MM_CAM_CONST_ACC)
                check_abs((p[2] - m[2]) / (2 * h), c[3], 1e-4, "s''' vs central difference of s''");
        }
    }
}

static void the_peaks_should_be_the_maxima_over_the_rise(void **state)
{
    (void)state;
    for (int law = 0; law < 4; law++) {
        double p1, p2, m1 = 0, m2 = 0, d[4];
        mm_cam_peaks(law, &p1, &p2);
        for (int i = 0; i <= 100000; i++) {
            mm_cam_rise(law, i / 100000.0, d);
            m1 = fmax(m1, fabs(d[1])), m2 = fmax(m2, fabs(d[2]));
        }
        /* sampled every 1e-5: a smooth peak is missed by (1e-5)^2 |s'''| / 8 at most; the 3-4-5
         * acceleration peaks at u = (3 - sqrt 3)/6, between samples */
        check_rel(m1, p1, 1e-8, "peak |s'| vs sampled");
        check_rel(m2, p2, 1e-8, "peak |s''| vs sampled");
    }
}

static void the_motion_should_be_continuous_around_the_turn(void **state)
{
    (void)state;
    mm_cam m = {MM_CAM_CYCLOIDAL, 0.02, M_PI / 2, M_PI / 6, M_PI / 2, 0.05, 0.01, 0, 0};
    m.s0 = sqrt((m.Rb + m.Rr - m.e) * (m.Rb + m.Rr + m.e));
    const double ends[4] = {0, m.br, m.br + m.bd, m.br + m.bd + m.bt};
    for (int k = 0; k < 4; k++) {
        double a[4], b[4];
        int sa, sb;
        mm_cam_motion(&m, ends[k] - 1e-9, a, &sa);
        mm_cam_motion(&m, ends[k] + 1e-9, b, &sb);
        assert_int_equal(sb, k);
        /* cycloidal: s, s', s'' continuous; over 2e-9 rad they move by that times their rates */
        check_abs(a[0], b[0], 1e-9, "s continuous at a segment's end");
        check_abs(a[1], b[1], 1e-8, "s' continuous at a segment's end");
        check_abs(a[2], b[2], 1e-6, "s'' continuous at a segment's end");
        check_rel(mm_cam_near_jump(&m, ends[k] + 1e-3), ends[k], 0, "the nearest jump is that end");
    }
    double d[4];
    int seg;
    mm_cam_motion(&m, 0.5 * (m.br + m.bd + m.bt) + M_PI, d, &seg);       /* the bottom dwell */
    assert_int_equal(seg, 3);
    /* on a dwell the pitch curve is the circle of radius s0 (e = 0) */
    check_rel(mm_cam_rho_pitch(&m, d), m.s0, 4 * EPS, "pitch radius of the bottom dwell");
    check_abs(mm_cam_pressure(&m, d), 0, 0, "no pressure angle on a dwell without offset");
    mm_v2 P, K;
    mm_cam_points(&m, 1.0, &P, &K);
    check_rel(mm_v2_norm(mm_v2_sub(P, K)), m.Rr, 4 * EPS, "contact point a roller radius from the centre");
}

static void the_extremes_should_match_a_fine_scan(void **state)
{
    (void)state;
    enum { N = 2000000 };
    for (int law = 0; law < 4; law++)
        for (int v = 0; v < 2; v++) {
            mm_cam m = {law, 0.02, 1.5707963267948966, 0.5235987755982988, 1.5707963267948966, 0.05,
                        v ? 0.03 : 0.01, v ? -0.02 : 0.005, 0};
            m.s0 = sqrt((m.Rb + m.Rr - m.e) * (m.Rb + m.Rr + m.e));
            double at, e, at2, e2, d[4];
            int seg;
            double pmax = mm_cam_pressure_max(&m, &at, &e), rmin = mm_cam_rho_pitch_min(&m, &at2, &e2);
            double sp = 0, sr = INFINITY;
            for (int k = 0; k < N; k++) {
                mm_cam_motion(&m, 6.283185307179586 * k / N, d, &seg);
                sp = fmax(sp, fabs(mm_cam_pressure(&m, d)));
                double r = mm_cam_rho_pitch(&m, d);
                if (r > 0 && r < sr)
                    sr = r;
            }
            /* the search never does worse than the scan, and the scan (steps
             * of 3e-6 rad) misses a peak by at most its slope times a step:
             * 2.7e-7 at the worst (a kink of the constant-acceleration law) */
            assert_true(pmax >= sp - 1e-15 && pmax - sp < 1e-6);
            assert_true(rmin <= sr + 1e-15 && sr - rmin < 1e-6);
            mm_cam_motion(&m, at, d, &seg);
            check_abs(fabs(mm_cam_pressure(&m, d)), pmax, 0, "the largest pressure angle is the one at *at");
            assert_true(e >= 1e-12 * pmax && e2 >= 1e-12 * rmin);
        }
}

static void the_peak_search_should_find_the_closed_form_peaks(void **state)
{
    (void)state;
    for (int law = 0; law < 4; law++) {
        mm_cam m = {law, 0.02, 1.2, 0.4, 1.7, 0.05, 0.01, 0, 0};
        m.s0 = sqrt((m.Rb + m.Rr) * (m.Rb + m.Rr));
        double p1, p2;
        mm_cam_peaks(law, &p1, &p2);
        for (int k = 1; k <= 2; k++)
            for (int seg = 0; seg <= 2; seg += 2) {
                double a = seg ? m.br + m.bd : 0, b = a + (seg ? m.bt : m.br), beta = seg ? m.bt : m.br;
                double want = (k == 1 ? p1 : p2) * m.h / (k == 1 ? beta : beta * beta);
                mm_opt_result r;
                assert_int_equal(mm_cam_peak_search(&m, k, seg, a, b - 1e-12 * b, 1e-9 * (b - a), &r, NULL), MM_OK);
                /* a smooth peak to eps; a corner (constant acceleration's s',
                 * harmonic's s'' at the ends) to its slope times the bracket */
                check_abs(r.fx, want, 64 * EPS * want + 10 * want / beta * fmax(r.bracket, 1e-9 * (b - a)),
                          "the searched peak vs the closed form");
            }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_law_should_rise_from_0_to_1_with_its_derivatives),
        cmocka_unit_test(the_peaks_should_be_the_maxima_over_the_rise),
        cmocka_unit_test(the_motion_should_be_continuous_around_the_turn),
        cmocka_unit_test(the_extremes_should_match_a_fine_scan),
        cmocka_unit_test(the_peak_search_should_find_the_closed_form_peaks),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
