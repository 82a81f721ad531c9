/* test_pendulum.c — mm_pendulum against published values: T / T0 at a
 * quarter turn is 2 K(1/sqrt 2) / pi with K(1/sqrt 2) = Gamma(1/4)^2 /
 * (4 sqrt pi) = 1.854074677301372 (Abramowitz & Stegun 17.3.29); the
 * series' coefficients 1/16, 11/3072 (A&S 17.3.11 squared out); the
 * amplitude of a 1 % longer period by Newton on the series.  The exact
 * motion against the small-swing limit, its own energy, its derivative by
 * differences, a period's return, and an independent DOP853 integration
 * of theta'' = -(g/L) sin theta: a swing near the separatrix, a turn over
 * the top either way, and the separatrix itself. */
#include "mm_test.h"

#include <float.h>

#include "mm_ode.h"
#include "mm_pendulum.h"

static void period_ratio_should_match_the_lemniscate_value(void **state)
{
    (void)state;
    check_rel(mm_pendulum_period_ratio(M_PI / 2), 2 * 1.854074677301372 / M_PI, 4 * DBL_EPSILON,
              "T/T0 at pi/2");
    check_rel(mm_pendulum_period_ratio(0), 1, DBL_EPSILON, "small swings: T0");
    /* the series to theta^8 within twice its next term, where it converges fast */
    double next, s = mm_pendulum_ratio_series(0.5, &next);
    check_abs(s, mm_pendulum_period_ratio(0.5), 2 * next + 4 * DBL_EPSILON, "series at 0.5");
    assert_true(next > 0 && next < 1e-8);
    check_rel(mm_pendulum_ratio_series(0.01, &next), 1 + 1e-4 / 16 + 11e-8 / 3072, 2 * DBL_EPSILON,
              "the first two terms at 0.01");
}

static void amplitude_of_a_one_percent_longer_period(void **state)
{
    (void)state;
    double th, err;
    assert_int_equal(mm_pendulum_amplitude(1.01, 0.1, 1.0, &th, &err, NULL), MM_OK);
    check_abs(mm_pendulum_period_ratio(th), 1.01, 4 * DBL_EPSILON, "the ratio at the root");
    assert_true(err > 0 && err < 1e-12);             /* 4 eps 1.01 / (slope / 2), slope ~ 0.05 */
    /* Newton on the series (its truncation, 1.4e-10 in the ratio, moves the
     * root by 1.4e-10 / 0.05 = 3e-9) */
    double x = 0.4, next;
    for (int k = 0; k < 20; k++) {
        double h = 1e-6, f = mm_pendulum_ratio_series(x, &next) - 1.01;
        double d = (mm_pendulum_ratio_series(x + h, &next) - mm_pendulum_ratio_series(x - h, &next)) / (2 * h);
        x -= f / d;
    }
    check_abs(th, x, 4e-9, "the amplitude by the series");
}

static void closed_form_should_reduce_to_the_small_swing(void **state)
{
    (void)state;
    /* theta0 = 1e-3: theta = theta0 cos(wn t) to theta0^3, T = T0 (1 + theta0^2 / 16) */
    double th0 = 1e-3;
    mm_pendulum_motion p = mm_pendulum_motion_init(2, 9.81, th0, 0);
    assert_int_equal(p.motion, MM_PENDULUM_SWING);
    check_rel(p.T, p.T0 * (1 + th0 * th0 / 16), 1e-12, "T = T0 (1 + theta0^2/16 + O(theta0^4))");
    for (int i = 0; i <= 10; i++) {
        double w, t = 0.37 * i, th = mm_pendulum_exact(&p, t, &w);
        check_abs(th, th0 * cos(p.wn * t), th0 * th0 * th0, "theta(t) = theta0 cos(wn t) + O(theta0^3)");
    }
    check_abs(mm_pendulum_sin_top(M_PI), 0, 0, "sin at the top is exactly 0");
    /* the energy is kept by the exact motion (a large swing) */
    mm_pendulum_motion big = mm_pendulum_motion_init(1, 9.81, 2.5, 0.3);
    double w0, th = mm_pendulum_exact(&big, 0, &w0), E0 = mm_pendulum_energy(&big, th, w0);
    check_rel(th, 2.5, 1e-14, "theta(0) = theta0");
    for (int i = 1; i <= 10; i++) {
        double w, thi = mm_pendulum_exact(&big, 0.41 * i, &w);
        check_rel(mm_pendulum_energy(&big, thi, w), E0, 1e-13, "energy conserved by the closed form");
    }
}

static int pendulum_rhs(double t, const double *y, double *dy, void *ctx)
{
    (void)t;
    const mm_pendulum_motion *p = ctx;
    dy[0] = y[1];
    dy[1] = -p->wn * p->wn * sin(y[0]);
    return 0;
}

/* The closed form at 41 times over two periods (3 s on the separatrix)
 * against DOP853 at rtol = atol = 1e-12, whose global error sets each
 * case's tolerances (measured 6e-10, 2e-11, 4e-12 and 4e-11 in theta).
 * And theta' against the central difference of theta with step h = 1e-5:
 * its error is h^2 / 6 times theta''' = -wn^2 cos(theta) theta', so at
 * most h^2 wn^2 wmax / 6 with wmax^2 = omega0^2 + 4 wn^2 sin^2(theta0 / 2)
 * from the energy, plus rounding (a few eps theta / h, under 1e-9). */
static void exact_motion_should_match_an_integration(void **state)
{
    (void)state;
    const struct { double L, theta0, omega0; int motion; double tol_th, tol_w; } cases[] = {
        {1.0, 3.0, 0.0, MM_PENDULUM_SWING, 1e-9, 2e-9},       /* k = sin 1.5 = 0.997: a long, flat-topped swing */
        {0.5, 0.3, 9.0, MM_PENDULUM_OVER, 5e-11, 1e-10},      /* over the top, forwards */
        {2.0, -1.0, -5.0, MM_PENDULUM_OVER, 2e-11, 2e-11},    /* over the top, backwards */
        {1.0, 0.0, -1, MM_PENDULUM_SEPARATRIX, 1e-10, 3e-10}, /* omega0 = 2 sqrt(g/L), set below */
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        double omega0 = cases[c].omega0 < -0.5 ? 2 * sqrt(9.81 / cases[c].L) : cases[c].omega0;
        mm_pendulum_motion p = mm_pendulum_motion_init(cases[c].L, 9.81, cases[c].theta0, omega0);
        if (cases[c].motion == MM_PENDULUM_SEPARATRIX)
            assert_true(p.motion != MM_PENDULUM_SWING);   /* k^2 = 1 to rounding: either side of it */
        else
            assert_int_equal(p.motion, cases[c].motion);
        double t_end = isfinite(p.T) && cases[c].motion != MM_PENDULUM_SEPARATRIX ? 2 * p.T : 3.0;
        double t[41], y[82], yend[2];
        for (int i = 0; i < 41; i++)
            t[i] = t_end * i / 40;
        double y0[2] = {cases[c].theta0, omega0};
        mm_ode_problem prob = {.n = 2, .f = pendulum_rhs, .params = &p, .t0 = 0, .t_end = t_end, .y0 = y0};
        mm_ode_options o = mm_ode_options_adaptive(MM_ODE_DOP853, 1e-12, 1e-12, 100000);
        mm_ode_result r = {.t_out = t, .nout = 41, .y_out = y, .y_end = yend};
        assert_int_equal(mm_ode_run(&prob, &o, &r, NULL), MM_OK);
        double h = 1e-5, s0 = sin(0.5 * cases[c].theta0);
        double wmax = sqrt(omega0 * omega0 + 4 * p.wn * p.wn * s0 * s0);
        double tol_fd = h * h / 6 * p.wn * p.wn * wmax + 1e-9;
        for (int i = 0; i < 41; i++) {
            double w, th = mm_pendulum_exact(&p, t[i], &w);
            check_abs(th, y[2 * i], cases[c].tol_th, "theta: closed form against DOP853");
            check_abs(w, y[2 * i + 1], cases[c].tol_w, "theta': closed form against DOP853");
            double wa, wb;
            double d = (mm_pendulum_exact(&p, t[i] + h, &wa) - mm_pendulum_exact(&p, t[i] - h, &wb)) / (2 * h);
            check_abs(d, w, tol_fd, "theta' = d theta / dt (central difference)");
        }
    }
}

/* After one period a swing is back where it started, and a turn over the
 * top has gone once round (theta + 2 pi), to rounding (measured 4e-16
 * and 2e-15; T itself is good to a few eps). */
static void period_should_be_the_time_to_return(void **state)
{
    (void)state;
    mm_pendulum_motion sw = mm_pendulum_motion_init(1.5, 9.81, 2.0, 1.0);
    mm_pendulum_motion ov = mm_pendulum_motion_init(1.5, 9.81, 1.0, 8.0);
    assert_int_equal(sw.motion, MM_PENDULUM_SWING);
    assert_int_equal(ov.motion, MM_PENDULUM_OVER);
    double w, w0;
    double th0 = mm_pendulum_exact(&sw, 0, &w0);
    check_abs(mm_pendulum_exact(&sw, sw.T, &w), th0, 1e-14, "swing: theta(T) = theta(0)");
    check_abs(w, w0, 2e-14, "swing: theta'(T) = theta'(0)");
    th0 = mm_pendulum_exact(&ov, 0, &w0);
    check_abs(mm_pendulum_exact(&ov, ov.T, &w), th0 + 2 * M_PI, 1e-14, "over: theta(T) = theta(0) + 2 pi");
    check_abs(w, w0, 2e-14, "over: theta'(T) = theta'(0)");
}

/* A small swing: dT/dE at the bottom is pi / (4 wn^3) (T = T0 (1 + E /
 * (8 wn^2) + ...) from T = T0 (1 + theta0^2 / 16 + ...)); the central
 * difference stepped past E = 0 and aborted on K(kc > 1) (dyn-pendulum,
 * L = 0.00141 m, g = 25.08, theta0 = 0.0063, omega0 = -0.578: k^2 = 1.5e-5),
 * and at rest there is no energy below at all. */
static void period_sensitivity_of_a_small_swing_should_be_the_bottom_limit(void **state)
{
    (void)state;
    const double cases[][4] = {{0.0014096398095928481, 25.080367619783328, 0.006308859985167666, -0.5778520772030333},
                               {1, 9.81, 0, 0}, {1, 9.81, 1e-3, 0}};
    for (int i = 0; i < 3; i++) {
        mm_pendulum_motion p = mm_pendulum_motion_init(cases[i][0], cases[i][1], cases[i][2], cases[i][3]);
        assert_int_equal(p.motion, MM_PENDULUM_SWING);
        double lim = M_PI / (4 * p.wn * p.wn * p.wn);
        /* the one-sided difference's 1e-4 and the k^2 term's (about 3 k^2 / 8) */
        check_rel(mm_pendulum_period_sensitivity(&p), lim, 2e-4 + p.k * p.k, "dT/dE near the bottom");
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(period_ratio_should_match_the_lemniscate_value),
        cmocka_unit_test(amplitude_of_a_one_percent_longer_period),
        cmocka_unit_test(closed_form_should_reduce_to_the_small_swing),
        cmocka_unit_test(exact_motion_should_match_an_integration),
        cmocka_unit_test(period_should_be_the_time_to_return),
        cmocka_unit_test(period_sensitivity_of_a_small_swing_should_be_the_bottom_limit),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
