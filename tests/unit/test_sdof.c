/* test_sdof.c — the closed-form 1-DOF response (mm_sdof) against the
 * equation itself and against limiting cases written out by hand. */
#include "mm_test.h"

#include <float.h>
#include <string.h>

#include "mm_sdof.h"

static double x_of(const mm_sdof *s, double t, double *v)
{
    mm_sdof_props p;
    mm_sdof_props_get(s, &p);
    return mm_sdof_x(s, &p, t, v);
}

/* m x'' + c x' + k x - F0 cos wt by central differences of the returned
 * velocity: O(h^2) = 1e-10 relative with h = 1e-5 s. */
static double residual(const mm_sdof *s, double t)
{
    const double h = 1e-5;
    double vp, vm, v, x = x_of(s, t, &v);
    x_of(s, t + h, &vp);
    x_of(s, t - h, &vm);
    double a = (vp - vm) / (2 * h);
    return s->m * a + s->c * v + s->k * x - s->F0 * cos(s->omega * t);
}

static void response_should_satisfy_the_equation_in_every_regime(void **state)
{
    (void)state;
    const double cs[] = {0.0, 2.0, 19.999, 20.0, 20.001, 60.0};  /* zeta 0 .. 3 for m=1, k=100 */
    for (unsigned i = 0; i < sizeof cs / sizeof cs[0]; i++) {
        mm_sdof s = {.m = 1, .c = cs[i], .k = 100, .F0 = 1, .omega = 8, .x0 = 0.01, .v0 = -0.3};
        for (double t = 0.05; t < 5; t += 0.37) {
            /* force scale: k * |x| ~ 1 N; differences leave ~1e-8 N */
            check_abs(residual(&s, t), 0.0, 1e-6, "residual of m x'' + c x' + k x = F");
        }
        double v0, x0 = x_of(&s, 0, &v0);
        check_abs(x0, s.x0, 1e-15, "x(0)");
        check_abs(v0, s.v0, 1e-14, "v(0)");
    }
}

static void critical_damping_should_match_its_textbook_form(void **state)
{
    (void)state;
    /* zeta = 1: x = (x0 + (v0 + wn x0) t) e^(-wn t), wn = 10 */
    mm_sdof s = {.m = 1, .c = 20, .k = 100, .x0 = 0.01, .v0 = 0.5};
    for (double t = 0; t < 2; t += 0.1) {
        double want = (0.01 + (0.5 + 10 * 0.01) * t) * exp(-10 * t);
        check_abs(x_of(&s, t, NULL), want, 1e-17, "critical damping closed form");
    }
    /* continuity through critical damping: zeta = 1 -+ 1e-13 moves x by about
     * 1e-13 x (the physics), so 1e-14 m; a textbook two-root formula would
     * lose everything here (its constants grow like 1/sqrt(zeta^2 - 1)) */
    mm_sdof lo = s, hi = s;
    lo.c = 20 * (1 - 1e-13);
    hi.c = 20 * (1 + 1e-13);
    for (double t = 0; t < 2; t += 0.1) {
        check_abs(x_of(&lo, t, NULL), x_of(&s, t, NULL), 1e-14, "just under critical");
        check_abs(x_of(&hi, t, NULL), x_of(&s, t, NULL), 1e-14, "just over critical");
    }
}

/* the flow over tau against the textbook motions in every regime, written
 * here from their formulas: undamped rotation, critical damping's
 * (1 + w t) e^(-w t), overdamped two exponentials; far past one radian
 * (many squarings) and at tau = 0 */
static void the_flow_should_carry_the_free_motion_in_every_regime(void **state)
{
    (void)state;
    for (int pass = 0; pass < 3; pass++) {
        double tau = pass == 0 ? 0.0137 : pass == 1 ? 1.7 : 300;   /* 0.137, 17 and 3000 rad */
        double Phi[4], w = 10;
        int q;
        /* undamped, wn = 10 = w: a rotation by wn tau */
        mm_sdof s = {.m = 1, .c = 0, .k = 100};
        mm_sdof_flow(&s, w, tau, Phi, &q);
        double c = cos(10 * tau), sn = sin(10 * tau), e = 64 * DBL_EPSILON * (q + 1) * (1 + 10 * tau / 64);
        check_abs(Phi[0], c, e, "undamped Phi_xx");
        check_abs(Phi[1], sn, e, "undamped Phi_xv");
        check_abs(Phi[2], -sn, e, "undamped Phi_vx");
        check_abs(Phi[3], c, e, "undamped Phi_vv");
        /* critical, wn = 10, w = 20: x = (x0 + (v0 + wn x0) t) e^(-wn t) */
        s.c = 20;
        mm_sdof_flow(&s, 20, tau, Phi, &q);
        double E = exp(-10 * tau), ee = 64 * DBL_EPSILON * (q + 1);
        check_abs(Phi[0], (1 + 10 * tau) * E, ee, "critical Phi_xx");
        check_abs(Phi[1], 20 * tau * E, ee, "critical Phi_xv (v0 = 20 u0)");
        check_abs(Phi[2], -100 * tau * E / 20, ee, "critical Phi_vx: v = -wn^2 t e^(-wn t) x0");
        check_abs(Phi[3], (1 - 10 * tau) * E, ee, "critical Phi_vv");
        /* overdamped: roots -2 and -50 (c/m = 52, k/m = 100), w = 50 */
        s.c = 52;
        mm_sdof_flow(&s, 50, tau, Phi, &q);
        double a = exp(-2 * tau), b = exp(-50 * tau);
        /* x = (50 x0 + v0) e^(-2t)/48 - (2 x0 + v0) e^(-50t)/48 */
        check_abs(Phi[0], (50 * a - 2 * b) / 48, ee, "overdamped Phi_xx");
        check_abs(Phi[1], 50 * (a - b) / 48, ee, "overdamped Phi_xv");
        check_abs(Phi[2], (-100 * a + 100 * b) / 48 / 50, ee, "overdamped Phi_vx");
        check_abs(Phi[3], (-2 * a + 50 * b) / 48, ee, "overdamped Phi_vv");
    }
    double Phi[4];
    mm_sdof s = {.m = 2, .c = 3, .k = 5};
    mm_sdof_flow(&s, 1, 0, Phi, NULL);
    check_abs(Phi[0] - 1 + Phi[1] + Phi[2] + Phi[3] - 1, 0, 0, "tau = 0: the identity");
}

static void undamped_resonance_should_grow_like_t_sin_t(void **state)
{
    (void)state;
    /* x'' + x = cos t from rest: x = t sin t / 2 */
    mm_sdof s = {.m = 1, .c = 0, .k = 1, .F0 = 1, .omega = 1};
    mm_sdof_props p;
    mm_sdof_props_get(&s, &p);
    assert_true(p.resonant);
    for (double t = 0; t < 200; t += 3.3)
        check_abs(x_of(&s, t, NULL), 0.5 * t * sin(t), 1e-12 * (1 + t), "t sin t / 2");
    /* a hair off resonance: the beat formula, not a cancellation of huge terms */
    s.omega = 1 + 1e-9;
    for (double t = 0; t < 200; t += 3.3) {
        /* (cos wt - cos t)/(1 - w^2) with w = 1 + d, expanded in d by hand:
         * t sin t / 2 + d (t^2 cos t - t sin t) / 4 + O(d^2 t^3), and
         * d^2 t^3 < 1e-11 here.  d is the double nearest w - 1.
         * (Evaluating the quotient directly would lose ~7 digits.) */
        double d = s.omega - 1;
        double want = 0.5 * t * sin(t) + d * (t * t * cos(t) - t * sin(t)) / 4;
        check_abs(x_of(&s, t, NULL), want, 1e-10 * (1 + t), "near resonance");
    }
}

static void steady_state_should_follow_the_dynamic_stiffness(void **state)
{
    (void)state;
    /* the numbers: m=2, k=50, c=1, F0=3, w=4 */
    mm_sdof s = {.m = 2, .c = 1, .k = 50, .F0 = 3, .omega = 4};
    mm_sdof_props p;
    mm_sdof_props_get(&s, &p);
    double want = 3 / sqrt((50 - 2 * 16.0) * (50 - 2 * 16.0) + 16.0);
    check_rel(p.X, want, 1e-15, "X = F0 / |k - m w^2 + i c w|");
    check_rel(p.phase, atan(4.0 / 18.0), 1e-15, "phase below resonance");
    /* after 60 time constants the transient is e^-60: x is the steady state */
    double t = 60 / (p.zeta * p.omega_n);
    check_abs(x_of(&s, t, NULL), p.X * cos(s.omega * t - p.phase), 1e-15, "steady state");
    /* above resonance the lag passes pi/2 */
    s.omega = 10;
    mm_sdof_props_get(&s, &p);
    assert_true(p.phase > M_PI / 2 && p.phase < M_PI);
}

static void bad_models_should_be_refused_with_the_field_named(void **state)
{
    (void)state;
    mm_error err;
    mm_sdof s = {.m = -1, .c = 0, .k = 1};
    assert_int_equal(mm_sdof_check(&s, &err), MM_ERANGE);
    assert_string_equal(err.param, "m");
    s.m = 1;
    s.c = NAN;
    assert_int_equal(mm_sdof_check(&s, &err), MM_EVALUE);
    assert_string_equal(err.param, "c");
}


/* m x'' + c x' + k x - F0 cos wt - G0 sin wt by central differences. */
static double residual_g(const mm_sdof *s, double t)
{
    const double h = 1e-5;
    double vp, vm, v, x = x_of(s, t, &v);
    x_of(s, t + h, &vp);
    x_of(s, t - h, &vm);
    double a = (vp - vm) / (2 * h);
    return s->m * a + s->c * v + s->k * x - s->F0 * cos(s->omega * t) - s->G0 * sin(s->omega * t);
}

static void a_sine_force_should_be_followed_in_every_regime(void **state)
{
    (void)state;
    /* the moving support of vib-base-excitation: F0 = k Y, G0 = -c w Y */
    const double cs[] = {0.0, 2.0, 20.0, 60.0};
    for (unsigned i = 0; i < sizeof cs / sizeof cs[0]; i++) {
        mm_sdof s = {.m = 1, .c = cs[i], .k = 100, .F0 = 100 * 0.01, .G0 = -cs[i] * 8 * 0.01, .omega = 8,
                     .x0 = 0.02, .v0 = 0.1};
        if (cs[i] == 0)
            s.G0 = 0.3;                       /* undamped: a sine force of its own */
        for (double t = 0.05; t < 5; t += 0.37)
            check_abs(residual_g(&s, t), 0.0, 1e-6, "residual with a sine force");
        double v0, x0 = x_of(&s, 0, &v0);
        check_abs(x0, s.x0, 1e-15, "x(0)");
        check_abs(v0, s.v0, 1e-14, "v(0)");
    }
    /* undamped, at resonance: the sine force's part is
     * (sin t - t cos t) / 2 for x'' + x = sin t from rest */
    mm_sdof s = {.m = 1, .k = 1, .G0 = 1, .omega = 1};
    for (double t = 0; t < 100; t += 2.9)
        check_abs(x_of(&s, t, NULL), 0.5 * (sin(t) - t * cos(t)), 1e-12 * (1 + t), "(sin t - t cos t)/2");
    /* the steady amplitude of F0 cos + G0 sin is |F0 - i G0| / |D| */
    s = (mm_sdof){.m = 1, .c = 2, .k = 100, .F0 = 3, .G0 = 4, .omega = 8};
    mm_sdof_props p;
    mm_sdof_props_get(&s, &p);
    check_rel(p.X, 5 / hypot(36, 16), 1e-15, "X = 5 / |36 + 16 i|");
}

static void the_dynamic_stiffness_should_keep_its_digits_near_resonance(void **state)
{
    (void)state;
    /* k - m w^2 with w = 10.00000005 (the double nearest): computed in
     * exact rational arithmetic (Python's fractions) it is
     * -1.0000000141860974e-06, and X = 1/|.| = 999999.98581390281; w^2
     * rounded to double would leave 9 digits, to long double 12 */
    mm_sdof s = {.m = 1, .k = 100, .F0 = 1, .omega = 10.00000005};
    mm_sdof_props p;
    mm_sdof_props_get(&s, &p);
    check_rel(p.stiffness_re, -1.0000000141860974e-06, 1e-15, "k - m w^2 by exact products");
    check_rel(p.X, 999999.98581390281, 1e-15, "X = F0 / |k - m w^2|");
    /* the right-hand side is the equation */
    double y[2] = {0.1, -0.2}, dy[2];
    s = (mm_sdof){.m = 2, .c = 3, .k = 50, .F0 = 1, .G0 = 0.5, .omega = 4};
    assert_int_equal(mm_sdof_rhs(0.3, y, dy, &s), 0);
    check_abs(dy[0], -0.2, 0, "x' = v");
    check_rel(dy[1], (cos(1.2) + 0.5 * sin(1.2) - 3 * -0.2 - 50 * 0.1) / 2, 1e-15, "v' from eq. (1)");
    check_rel(mm_sdof_energy(&s, 0.1, -0.2), 0.5 * 2 * 0.04 + 0.5 * 50 * 0.01, 1e-15, "energy");
    mm_sdof_props_get(&s, &p);
    check_rel(mm_sdof_fastest_rate(&s, &p), 5, 1e-15, "omega_n = 5 beats omega = 4");
    s.c = 100;                                 /* zeta = 5: the fast decay wn (zeta + sqrt(zeta^2 - 1)) */
    mm_sdof_props_get(&s, &p);
    check_rel(mm_sdof_fastest_rate(&s, &p), 5 * (5 + sqrt(24.0)), 1e-14, "overdamped fast rate");
}

static void a_strongly_overdamped_block_should_keep_its_digits(void **state)
{
    (void)state;
    /* zeta = 500 (m = k = 1, c = 1000), x0 = 1, v0 = 0; x, v by mpmath at 40
     * digits.  As differences a - mu and a^2 + lambda = omega_n^2 lose 2
     * log10(2 zeta) = 6 digits: v(0.001) came out 1.3e-11 off, and
     * energy_dissipated of vib-sdof-free 13 times over its printed bound. */
    mm_sdof s = {.m = 1, .k = 1, .c = 1000, .x0 = 1};
    const double t[] = {0.001, 1, 100};
    const double x[] = {0.99999963212058731079, 0.99900149783786834019, 0.90483823239208339891};
    const double v[] = {-0.00063212045519023930939, -0.00099900249684136418605, -0.00090483913723212547198};
    for (int i = 0; i < 3; i++) {
        double vt, xt = x_of(&s, t[i], &vt);
        check_rel(xt, x[i], 4 * DBL_EPSILON, "x of a strongly overdamped block");
        check_rel(vt, v[i], 4 * DBL_EPSILON, "v of a strongly overdamped block");
    }
}

/* The classic limits: undamped RK4 is stable to omega h = 2 sqrt(2), Verlet
 * to 2; on the limit both have gain 1, beyond it more, and damping keeps
 * RK4 inside (|R| < 1 for small steps). */
static void the_step_gains_should_meet_the_classic_stability_limits(void **state)
{
    (void)state;
    double y = 2 * sqrt(2.0);
    check_rel(mm_sdof_rk4_gain(y, 0), 1, 1e-14, "RK4 on its limit 2 sqrt 2");
    double re = 1 - 0.25 * 0.25 / 2 + pow(0.25, 4) / 24, im = 0.25 - pow(0.25, 3) / 6;
    check_rel(mm_sdof_rk4_gain(0.25, 0), hypot(re, im), 1e-15, "|R(i y)| written out");
    assert_true(mm_sdof_rk4_gain(y * 1.01, 0) > 1 && mm_sdof_rk4_gain(1, 0.1) < 1);
    check_rel(mm_sdof_verlet_gain(1.9, 0), 1, 1e-14, "Verlet inside its limit: a rotation");
    assert_true(mm_sdof_verlet_gain(2.01, 0) > 1);
    check_rel(mm_sdof_verlet_gain(0.5, 0.1), sqrt(1 - 2 * 0.1 * 0.5), 1e-14, "damped: sqrt of the determinant");
}

/* mm_sdof_x_many is mm_sdof_x with its constants hoisted: the same numbers,
 * bit for bit, in every regime, forced or free, with a sine force, undamped. */
static void many_points_should_be_mm_sdof_x_exactly(void **state)
{
    (void)state;
    const mm_sdof cases[] = {
        {.m = 1, .c = 2, .k = 100, .F0 = 1, .omega = 8},                   /* the default: under */
        {.m = 1, .c = 20, .k = 100, .F0 = 1, .omega = 8, .x0 = 0.1},       /* critical */
        {.m = 1, .c = 1000, .k = 1, .F0 = 2, .omega = 3, .v0 = -1},        /* over */
        {.m = 2, .c = 3, .k = 50, .F0 = 1, .G0 = 0.5, .omega = 4},         /* a sine force too */
        {.m = 1, .c = 0, .k = 100, .F0 = 1, .omega = 9.5},                 /* undamped: its own branch */
        {.m = 1, .c = 0.5, .k = 4, .x0 = 1, .v0 = 2},                      /* free */
    };
    double t[300], x[300];
    for (int i = 0; i < 300; i++)
        t[i] = 0.037 * i;
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        mm_sdof_props p;
        mm_sdof_props_get(&cases[c], &p);
        mm_sdof_x_many(&cases[c], &p, 300, t, x);
        for (int i = 0; i < 300; i++) {
            double one = mm_sdof_x(&cases[c], &p, t[i], NULL);
            if (memcmp(&one, &x[i], sizeof one) != 0)
                fail_msg("case %zu, t = %g: %.17g against mm_sdof_x's %.17g", c, t[i], x[i], one);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(response_should_satisfy_the_equation_in_every_regime),
        cmocka_unit_test(critical_damping_should_match_its_textbook_form),
        cmocka_unit_test(the_flow_should_carry_the_free_motion_in_every_regime),
        cmocka_unit_test(undamped_resonance_should_grow_like_t_sin_t),
        cmocka_unit_test(steady_state_should_follow_the_dynamic_stiffness),
        cmocka_unit_test(bad_models_should_be_refused_with_the_field_named),
        cmocka_unit_test(a_sine_force_should_be_followed_in_every_regime),
        cmocka_unit_test(the_dynamic_stiffness_should_keep_its_digits_near_resonance),
        cmocka_unit_test(a_strongly_overdamped_block_should_keep_its_digits),
        cmocka_unit_test(the_step_gains_should_meet_the_classic_stability_limits),
        cmocka_unit_test(many_points_should_be_mm_sdof_x_exactly),
    };
    return cmocka_run_group_tests_name("sdof", tests, NULL, NULL);
}
