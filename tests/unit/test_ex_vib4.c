/* test_ex_vib4.c — the hard cases of chapters 5.10-5.12 and of num-newmark,
 * through the real pipeline (text parameters -> validation -> solve ->
 * JSON), read back with cJSON:
 *   vib-2dof:           closed form and conventions; repeated frequencies
 *                       (k2 = 0 between twins); a rigid-body mode;
 *   vib-absorber:       anti-resonance, the sweep 0 .. omega_max, Den Hartog;
 *   vib-2dof-transient, vib-ndof-transient: the truncation error vanishes
 *                       with every mode kept, and not before; a large force
 *                       leaves the transition matrix its digits;
 *   vib-chain-modes:    the largest chain, its error below n^2 eps;
 *   vib-bar-modes:      rigid-body mode left out; h^2 from both masses;
 *   vib-beam-modes:     beta L of the tables, two rigid modes, h^4,
 *                       1000 elements;
 *   vib-bar-wave:       exact nodes at the Courant limit, refused above it;
 *   vib-beam-transient: a sudden load's dynamic factor 2; 1000 elements;
 *                       stiffly damped modes under a fast load; the
 *                       factor where the motion has not reached the
 *                       probe; a step a moving load crosses within;
 *   num-newmark:        issue 10's defects #1 and #12, the raised limits. */
#include "mm_test.h"

#include <cJSON.h>
#include <stdlib.h>
#include <string.h>

#include "mm_api.h"
#include "mm_pipeline.h"

#define EPS 2.220446049250313e-16

static const cJSON *named(const cJSON *doc, const char *list, const char *name)
{
    const cJSON *s;
    cJSON_ArrayForEach(s, cJSON_GetObjectItem(doc, list)) {
        if (strcmp(cJSON_GetObjectItem(s, "name")->valuestring, name) == 0)
            return s;
    }
    return NULL;
}

static double scalar(const cJSON *doc, const char *name)
{
    const cJSON *s = named(doc, "scalars", name);
    if (!s)
        fail_msg("no scalar %s", name);
    return cJSON_GetObjectItem(s, "value")->valuedouble;
}

static double cell(const cJSON *doc, const char *table, int row, const char *col)
{
    const cJSON *t = named(doc, "tables", table), *cols = cJSON_GetObjectItem(t, "columns");
    assert_non_null(t);
    int k = -1;
    for (int j = 0; j < cJSON_GetArraySize(cols); j++)
        if (strcmp(cJSON_GetArrayItem(cols, j)->valuestring, col) == 0)
            k = j;
    assert_true(k >= 0);
    return cJSON_GetArrayItem(cJSON_GetArrayItem(cJSON_GetObjectItem(t, "rows"), row), k)->valuedouble;
}

static int rows(const cJSON *doc, const char *table)
{
    return cJSON_GetArraySize(cJSON_GetObjectItem(named(doc, "tables", table), "rows"));
}

static int warned(const cJSON *doc, const char *text)
{
    const cJSON *w;
    cJSON_ArrayForEach(w, cJSON_GetObjectItem(doc, "warnings")) {
        if (strstr(w->valuestring, text))
            return 1;
    }
    return 0;
}

static const cJSON *check_named(const cJSON *doc, const char *text)
{
    const cJSON *c;
    cJSON_ArrayForEach(c, cJSON_GetObjectItem(doc, "checks")) {
        if (strstr(cJSON_GetObjectItem(c, "name")->valuestring, text))
            return c;
    }
    return NULL;
}

/* ---- vib-2dof ------------------------------------------------------------------ */

static void two_dof_should_give_mass_normalised_modes_with_phi1_positive(void **state)
{
    (void)state;
    cJSON *d = solve_ok("vib-2dof", "m1=2&m2=0.5&k1=300&k2=80&k3=40");
    double l2 = 0, b = 2 * 120 + 0.5 * 380, c = 300 * 80 + 300 * 40 + 80 * 40;
    l2 = (b + sqrt(b * b - 4 * c)) / 2;              /* m1 m2 = 1 */
    check_rel(scalar(d, "omega2"), sqrt(l2), 4 * EPS, "omega2, quadratic formula");
    check_rel(scalar(d, "omega1"), sqrt(c / l2), 4 * EPS, "omega1, product of the roots");
    for (int j = 0; j < 2; j++) {
        double p1 = cell(d, "modes", j, "phi1"), p2 = cell(d, "modes", j, "phi2");
        check_rel(2 * p1 * p1 + 0.5 * p2 * p2, 1, 8 * EPS, "phi^T M phi = 1");
        assert_true(p1 >= 0);
    }
    check_abs(2 * cell(d, "modes", 0, "phi1") * cell(d, "modes", 1, "phi1") +
              0.5 * cell(d, "modes", 0, "phi2") * cell(d, "modes", 1, "phi2"), 0, 8 * EPS, "M-orthogonal");
    cJSON_Delete(d);
}

/* The 8,000-draw study's failing request, mass ratio 5.6e5: the mode-shape
 * check failed (56.76 against 2.0e-13) because LAPACK's mode 2 came with
 * the other sign (mm_mdof_modes makes the first component above 1e-8 of
 * the largest positive: phi1 = 2.1e-7 against phi2 = -28.4 is below it),
 * and the printed small components (phi2 of mode 1, phi1 of mode 2, the
 * amplitude ratio) were 5.5e-12 off: cos of an angle 3.6e-5 from pi/2.
 * mpmath, 50 digits. */
static void two_dof_should_give_a_large_mass_ratio_its_small_components(void **state)
{
    (void)state;
    cJSON *d = solve_ok("vib-2dof", "m1=693.9386378752288&m2=0.0012416879053236717&k1=320158.95550674456"
                                    "&k2=1993.5845898484406&k3=478396.99235529656&mode=2");
    check_rel(cell(d, "modes", 0, "phi1"), 0.03796115916235098189002, 4 * EPS, "mode 1 phi1");
    check_rel(cell(d, "modes", 0, "phi2"), 0.0001575361307202314002928, 4 * EPS, "mode 1 phi2");
    check_rel(cell(d, "modes", 1, "phi1"), 2.107297564700386713307e-7, 4 * EPS, "mode 2 phi1");
    check_rel(cell(d, "modes", 1, "phi2"), -28.37878348206557277559, 4 * EPS, "mode 2 phi2");
    check_rel(scalar(d, "amplitude_ratio_1"), 0.004149929406699260323979, 4 * EPS, "x2/x1, mode 1");
    check_rel(scalar(d, "omega1"), 21.54590143186047743466, 4 * EPS, "omega1");
    check_rel(scalar(d, "omega2"), 19669.39557229692553048, 4 * EPS, "omega2");
    cJSON_Delete(d);
}

/* Twins with k2 = 0: one frequency twice, any combination a mode. */
static void two_dof_should_report_a_repeated_frequency(void **state)
{
    (void)state;
    cJSON *d = solve_ok("vib-2dof", "k2=0&k3=100");
    check_rel(scalar(d, "omega1"), 10, 4 * EPS, "sqrt(k1/m1)");
    check_rel(scalar(d, "omega2"), 10, 4 * EPS, "the same");
    assert_true(warned(d, "repeated"));
    assert_null(check_named(d, "mode-shape difference"));     /* not comparable: not unique */
    cJSON_Delete(d);
}

static void two_dof_should_count_a_rigid_body_mode(void **state)
{
    (void)state;
    cJSON *d = solve_ok("vib-2dof", "k1=0&k3=0");
    check_abs(scalar(d, "omega1"), 0, 0, "rigid: exactly 0");
    check_rel(scalar(d, "omega2"), sqrt(200.0), 4 * EPS, "sqrt(k2 (m1 + m2)/(m1 m2))");
    check_abs(scalar(d, "rigid_modes"), 1, 0, "one rigid-body mode");
    check_rel(cell(d, "modes", 0, "phi1"), cell(d, "modes", 0, "phi2"), 4 * EPS, "both masses alike");
    cJSON_Delete(d);
}

/* ---- vib-absorber --------------------------------------------------------------- */

static void absorber_should_stop_the_main_mass_at_the_tuned_frequency(void **state)
{
    (void)state;
    cJSON *d = solve_ok("vib-absorber", "omega=10");
    check_abs(scalar(d, "X1"), 0, 0, "anti-resonance: m1 still");
    check_rel(scalar(d, "X2"), 1.0 / 10, 4 * EPS, "X2 = F0/k2");
    check_rel(scalar(d, "tuned_omega"), 10, 0, "sqrt(k2/m2)");
    /* the sweep runs from 0 to 3 sqrt(k1/m1) = 30 */
    const cJSON *s = named(d, "series", "X1"), *x = cJSON_GetObjectItem(s, "x");
    check_abs(cJSON_GetArrayItem(x, 0)->valuedouble, 0, 0, "from 0");
    check_rel(cJSON_GetArrayItem(x, cJSON_GetArraySize(x) - 1)->valuedouble, 30, 0, "to omega_max");
    check_rel(scalar(d, "omega_max"), 30, 0, "3 sqrt(k1/m1)");
    /* Den Hartog for mu = 0.1: f = 1/1.1, zeta = sqrt(0.3 / (8 1.1^3)), fixed points (F0/k1) sqrt(21) */
    check_rel(scalar(d, "tuning_opt"), 1 / 1.1, 4 * EPS, "1/(1 + mu)");
    check_rel(scalar(d, "zeta_opt"), sqrt(0.3 / (8 * 1.331)), 4 * EPS, "sqrt(3 mu / (8 (1 + mu)^3))");
    check_rel(scalar(d, "X1_fixed_points"), 0.01 * sqrt(21.0), 4 * EPS, "(F0/k1) sqrt(1 + 2/mu)");
    /* the optimum's real peak lies slightly above the fixed points */
    double r = scalar(d, "X1_opt_peak") / scalar(d, "X1_fixed_points");
    assert_true(r >= 1 && r < 1.01);
    cJSON_Delete(d);
}

/* ---- transients: truncation ------------------------------------------------------- */

static void transients_should_lose_nothing_with_every_mode_kept(void **state)
{
    (void)state;
    cJSON *d = solve_ok("vib-2dof-transient", "modes=2&x1_0=0.01");
    check_abs(scalar(d, "truncation_error"), 0, 0, "every mode: nothing truncated");
    cJSON_Delete(d);
    d = solve_ok("vib-2dof-transient", "modes=1&x1_0=0.01");
    assert_true(scalar(d, "truncation_error") > 1e-3);         /* the second mode carries about 1 cm */
    cJSON_Delete(d);
    double prev = INFINITY;
    static const char *const q[] = {"modes=1", "modes=3", "modes=6", "modes=10"};
    for (int k = 0; k < 4; k++) {
        d = solve_ok("vib-ndof-transient", q[k]);
        double e = scalar(d, "truncation_error");
        assert_true(e < prev);
        prev = e;
        cJSON_Delete(d);
    }
    check_abs(prev, 0, 0, "ten modes of ten masses: nothing truncated");
}

/* Twenty-five 1 g masses, strongly damped, pushed by 3e3 N for one step of
 * 0.039 s (x_9 = -114 m): the transition matrix's load column f / w was 1.1e4
 * a step against the mechanics' 10, so expm squared 12 times and was off by
 * 8.5e-11 m (3400 eps of the motion; the modal sum is right to 6e-14, by
 * 50 digits), 2.5 times the check's rounding bound.  With the load's state
 * scaled (mm_mdof_exact) it agrees with the modal sum to a few eps. */
static void a_large_force_should_not_cost_the_transition_matrix_its_digits(void **state)
{
    (void)state;
    cJSON *d = solve_ok("vib-ndof-transient", "n=25&m=0.0011815219954385311&k=0.04294435627722371&"
                        "ends=fixed-fixed&alpha=86.19536485758786&beta=0.4515146737564145&F=-2987.19945686341&"
                        "p=9&omega=83.03113654419269&modes=16&h=0.038626576468506396&t_end=0.00672991146546028&"
                        "points=130");
    const cJSON *c = check_named(d, "vs the coupled system's transition matrix");
    assert_non_null(c);
    assert_true(cJSON_IsTrue(cJSON_GetObjectItem(c, "passed")));
    const cJSON *y = cJSON_GetObjectItem(named(d, "series", "x_p_exact"), "y");
    assert_int_equal(cJSON_GetArraySize(y), 2);
    double x = cJSON_GetArrayItem(y, 1)->valuedouble, err = cJSON_GetObjectItem(c, "abs_error")->valuedouble;
    check_rel(x, -113.98741539646567, 1e-14, "x_9 at h, 50 digits by mpmath");
    if (!(err < 64 * EPS * fabs(x)))
        fail_msg("modal sum vs transition matrix: %.3g m, over 64 eps of the motion", err);
    cJSON_Delete(d);
}

/* The two rounding checks guard differences of a few hundred eps; their
 * tolerances were 2,890 and 181 times the differences at the defaults
 * (64 eps a sample where the samples' products round by about one).  Now
 * within 100 times, and still bounds at a soft chain (omega_1 t_end = 0.055)
 * whose velocity errors drift into q: the run there differs by 6e5 eps of
 * q + h v + h^2 a, 0.975 of the old bound. */
static void transient_checks_should_be_bounds_within_100_times_the_rounding(void **state)
{
    (void)state;
    static const char *const name[2] = {"every mode's exact discrete Newmark", "the coupled system's transition"};
    cJSON *d = solve_ok("vib-ndof-transient", "");
    for (int k = 0; k < 2; k++) {
        const cJSON *c = check_named(d, name[k]);
        assert_non_null(c);
        double e = cJSON_GetObjectItem(c, "abs_error")->valuedouble;
        double tol = cJSON_GetObjectItem(c, "tolerance")->valuedouble;
        if (!(e > 0 && e < tol && tol < 100 * e))
            fail_msg("%s: error %.3g, tolerance %.3g (%.0f times)", name[k], e, tol, tol / e);
    }
    cJSON_Delete(d);
    d = solve_ok("vib-ndof-transient", "n=24&m=23.128973938938618&k=0.1591051056433618&ends=fixed-free&"
                 "alpha=10.788519866436829&beta=0.2266853773419234&F=1109.7634882391158&p=19&"
                 "omega=723.7271199891709&modes=24&h=0.004935016746018873&t_end=10.423782031926134&points=35");
    const cJSON *c = check_named(d, name[0]);
    assert_non_null(c);
    assert_true(cJSON_IsTrue(cJSON_GetObjectItem(c, "passed")));
    cJSON_Delete(d);
}

/* ---- vib-chain-modes -------------------------------------------------------------- */

/* The largest chain: relative errors below the n^2 eps bound, and the
 * bound is what (5) says, 8 eps lambda_max / lambda_1. */
static void chain_of_1000_masses_should_stay_within_n_squared_eps(void **state)
{
    (void)state;
    cJSON *d = solve_ok("vib-chain-modes", "n=1000&modes=10");
    double b = scalar(d, "rounding_bound_mode1"), s = sin(M_PI / 2002);
    check_rel(b, 8 * EPS / (s * s), 1e-12, "8 eps lambda_max / lambda_1 ~ n^2 eps");
    assert_true(b > 1e-10);                                    /* 7e-10: the n^2 growth */
    assert_true(scalar(d, "max_rel_error") <= b);
    assert_non_null(strstr(cJSON_GetObjectItem(cJSON_GetObjectItem(d, "method"), "name")->valuestring, "banded"));
    check_rel(cell(d, "modes", 0, "omega_exact"), 20 * s, 1e-15, "eq. (2)");
    cJSON_Delete(d);
    d = solve_ok("vib-chain-modes", "n=10");
    assert_non_null(strstr(cJSON_GetObjectItem(cJSON_GetObjectItem(d, "method"), "name")->valuestring, "dense"));
    cJSON_Delete(d);
}

/* ---- vib-bar-modes, vib-beam-modes ------------------------------------------------- */

static void bar_modes_should_leave_the_rigid_mode_out_and_converge_like_h2(void **state)
{
    (void)state;
    cJSON *d = solve_ok("vib-bar-modes", "bc=free-free");
    check_abs(scalar(d, "rigid_modes"), 1, 0, "one rigid-body mode");
    double c = sqrt(2.1e11 / 7850);
    check_rel(cell(d, "modes", 0, "omega_exact"), M_PI * c, 1e-15, "first elastic mode pi c / L");
    assert_true(cell(d, "modes", 0, "omega") > cell(d, "modes", 0, "omega_exact"));   /* consistent: above */
    check_abs(scalar(d, "slope_consistent"), 2, 0.05, "h^2");
    check_abs(scalar(d, "slope_lumped"), 2, 0.05, "h^2");
    assert_true(cell(d, "mass_models", 0, "omega_lumped") < cell(d, "mass_models", 0, "omega_exact"));
    assert_int_equal(rows(d, "modes"), 5);
    cJSON_Delete(d);
}

/* beta_1 L of Blevins's table 8-1 and two rigid modes of a free beam;
 * the fitted order 4. */
static void beam_modes_should_find_the_tabulated_roots_and_h4(void **state)
{
    (void)state;
    cJSON *d = solve_ok("vib-beam-modes", "");
    /* the table's nine digits: half a unit of the last, 1e-9 relative */
    check_rel(cell(d, "modes", 0, "beta_L"), 1.87510407, 2e-9, "cantilever beta_1 L");
    check_rel(cell(d, "modes", 1, "beta_L"), 4.69409113, 2e-9, "cantilever beta_2 L");
    check_abs(scalar(d, "slope"), 4, 0.1, "h^4");
    cJSON_Delete(d);
    d = solve_ok("vib-beam-modes", "bc=free-free");
    check_abs(scalar(d, "rigid_modes"), 2, 0, "translation and rotation");
    check_rel(cell(d, "modes", 0, "beta_L"), 4.73004074, 2e-9, "free-free beta_1 L");
    cJSON_Delete(d);
}

/* A 1000-element beam answers, and right.  How long it takes (the budget
 * is 250 ms) is measured by make bench (bench_limits), not here: a timed
 * assertion failed under valgrind and would on any slow machine. */
static void beam_of_1000_elements_should_answer(void **state)
{
    (void)state;
    cJSON *d = solve_ok("vib-beam-modes", "elements=1000");
    assert_non_null(strstr(cJSON_GetObjectItem(cJSON_GetObjectItem(d, "method"), "name")->valuestring, "Lanczos"));
    /* the discretisation error is 1e-15 here; Lanczos with Rayleigh
     * quotients keeps the rounding near 3e-13 (bench_fem) */
    check_rel(scalar(d, "omega1"), scalar(d, "omega1_exact"), 1e-11, "1000 elements");
    cJSON_Delete(d);
    /* 30 modes: Lanczos still, as accurate, and so no warning of rounding
     * (the banded solver's n^4 eps, which it had before) */
    d = solve_ok("vib-beam-modes", "elements=1000&modes=30");
    assert_non_null(strstr(cJSON_GetObjectItem(cJSON_GetObjectItem(d, "method"), "name")->valuestring, "Lanczos"));
    check_rel(scalar(d, "omega1"), scalar(d, "omega1_exact"), 1e-11, "1000 elements, 30 modes");
    assert_false(warned(d, "rounding"));
    cJSON_Delete(d);
    d = solve_ok("vib-beam-transient", "elements=1000&h=1e-4&t_end=0.02&modes=20");
    cJSON_Delete(d);
}

/* ---- vib-bar-wave ----------------------------------------------------------------- */

/* At the Courant limit C = 1 (lumped mass, central difference) the mesh is
 * exact at the nodes; just above it the run is unstable, said and not shown. */
static void bar_wave_should_be_exact_at_the_courant_limit_and_refuse_above(void **state)
{
    (void)state;
    cJSON *d = solve_ok("vib-bar-wave", "courant=1");
    const cJSON *c = check_named(d, "nodal displacements");
    assert_non_null(c);
    assert_true(cJSON_IsTrue(cJSON_GetObjectItem(c, "passed")));
    assert_non_null(named(d, "series", "stress_lumped"));
    assert_null(named(d, "series", "stress_consistent"));      /* consistent is unstable at C = 1 */
    check_rel(scalar(d, "u_end_max"), scalar(d, "u_end_max_exact"), 1e-12, "2FL/EA at the nodes");
    cJSON_Delete(d);
    d = solve_ok("vib-bar-wave", "courant=1.01&method=average-acceleration");
    assert_non_null(named(d, "series", "stress_lumped"));      /* implicit: stable */
    cJSON_Delete(d);
    answer a = solve("vib-bar-wave", "courant=1.01");
    assert_int_equal(a.status, 200);
    assert_true(warned(a.doc, "unstable"));
    assert_null(named(a.doc, "series", "stress_lumped"));
    assert_null(named(a.doc, "series", "u_end_lumped"));
    assert_null(named(a.doc, "scalars", "u_end_max"));
    cJSON_Delete(a.doc);
}

/* ---- vib-beam-transient ----------------------------------------------------------- */

static void sudden_load_should_nearly_double_the_static_deflection(void **state)
{
    (void)state;
    cJSON *d = solve_ok("vib-beam-transient", "load=step");
    double f = scalar(d, "dynamic_factor");
    assert_true(f > 1.9 && f < 2.0);                            /* 2 undamped; a little damping */
    /* exact at the nodes, but for the solve's rounding (cond(K) ~ 1e6) */
    check_rel(scalar(d, "w_static"), -100.0 / (48 * 2.1e11 * 1e-8), 1e-10, "P L^3 / 48 EI, exact at nodes");
    assert_non_null(check_named(d, "every mode's Newmark recursion"));
    cJSON_Delete(d);
}

/* A force crossing 48 stiffly damped elements (c / omega^2 = 0.72 s) in 4 us,
 * followed for 23 ms: the polynomial modal solution once cancelled to 1e-6 m
 * of noise, and w_max read 1 m for a beam that never moved at the probe.
 * (Found at h = 0.0233 s, a step the force crosses within, now refused: at
 * h = 3.5 us the direct run has it on the span once.) */
static void stiffly_damped_modes_should_stay_exact_under_a_fast_load(void **state)
{
    (void)state;
    cJSON *d = solve_ok("vib-beam-transient", "E=5.49e12&I=2.29e-10&rho=47&A=1.4e-7&L=0.00571&"
                        "bc=simply-supported&elements=48&load=moving&P=-6.7e5&v=1462&alpha=8680&beta=0.72&"
                        "modes=67&h=3.5e-6&t_end=0.0226&probe=0.476&points=144");
    double ws = fabs(scalar(d, "w_static"));
    assert_true(scalar(d, "truncation_error") < 1e-12 * ws);    /* ~1e-22 m: no noise */
    assert_true(scalar(d, "time_error") < 1e-3 * ws);
    assert_true(scalar(d, "w_max") < 1e-3 * ws);
    cJSON_Delete(d);
}

/* A step load at 0.92 L of a clamped beam whose first period is 4 days,
 * followed for 8 s: the motion has not reached the probe at 0.22 L (w_max =
 * 2.5e-322 m).  The dynamic factor's error was factor x (werr / max(w_max,
 * 1e-300) + ...) = 0 x inf, a NaN, and the answer a 422; it is 0 with the
 * error of w_max over |w_static|. */
static void dynamic_factor_should_be_finite_where_the_motion_has_not_reached_the_probe(void **state)
{
    (void)state;
    cJSON *d = solve_ok("vib-beam-transient", "E=36337503227.40963&I=3.9294262940808374e-13&rho=177.32509105984178&"
                        "A=0.006531808451366835&L=388.73880662506605&bc=clamped-clamped&elements=841&load=step&"
                        "P=192395.6516379593&a=0.9163779294019139&modes=10&alpha=6160.373786917685&"
                        "beta=0.3763582557295705&h=0.7753092679603784&t_end=7.8834121666808&"
                        "probe=0.22343975501365254&points=502");
    const cJSON *f = named(d, "scalars", "dynamic_factor"), *w = named(d, "scalars", "w_max");
    assert_non_null(f);
    assert_true(cJSON_GetObjectItem(f, "value")->valuedouble < 1e-300);
    check_rel(cJSON_GetObjectItem(f, "error")->valuedouble,
              cJSON_GetObjectItem(w, "error")->valuedouble / fabs(scalar(d, "w_static")), 1e-12, "werr / |w_static|");
    cJSON_Delete(d);
    /* no static deflection at a support: no factor, and a warning why */
    d = solve_ok("vib-beam-transient", "probe=0");
    assert_null(named(d, "scalars", "dynamic_factor"));
    assert_true(warned(d, "w_static = 0"));
    cJSON_Delete(d);
}

/* A force that crosses the span within one step (L/v = 0.21 s, h = 0.26 s;
 * 0.048 s and 0.079 s) is over a support at t = 0 and past the far end at
 * t = h: the direct run never has it on the beam, w_max = 0 whatever P.
 * These were 422s (the factor's NaN above); now refused, naming h. */
static void beam_transient_should_refuse_a_step_a_moving_load_crosses_within(void **state)
{
    (void)state;
    static const char *const q[2] = {
        "E=38688117401.82408&I=0.0038432639186813077&rho=946.3032875436272&A=1.3681057606418699e-08&"
        "L=0.017408084146971484&bc=cantilever&elements=321&load=moving&P=453699.4044936169&v=0.08226317271312443&"
        "alpha=8949.213497689183&beta=0.32577197432175875&modes=32&h=0.2617478238790962&t_end=0.07415384598733969&"
        "probe=0.7230176463208792&points=23",
        "E=875586342982.117&I=2.0667531518666659e-10&rho=5.785475124326855&A=2.508916392412771e-08&"
        "L=0.0037628619462915687&bc=clamped-clamped&elements=443&load=moving&P=-98728.28390616248&"
        "v=0.0786076409464237&alpha=1464.3592986819897&beta=0.3437239690738433&modes=56&h=0.07941990967356227&"
        "t_end=1.9248175955440827&probe=0.38641765715143284&points=1338"};
    for (int k = 0; k < 2; k++) {
        answer a = solve("vib-beam-transient", q[k]);
        assert_int_equal(a.status, 400);
        const cJSON *e = cJSON_GetObjectItem(a.doc, "error");
        assert_string_equal(cJSON_GetObjectItem(e, "param")->valuestring, "h");
        assert_non_null(strstr(cJSON_GetObjectItem(e, "message")->valuestring, "L/v"));
        cJSON_Delete(a.doc);
    }
    /* just inside: the force is on the span at t = h */
    cJSON_Delete(solve_ok("vib-beam-transient", "v=1e4&h=9.9e-5"));
}

/* ---- num-newmark ------------------------------------------------------------------ */

/* Issue 10, defect 1: these passed with tolerances of 9041 m and 12469 m.
 * Now the check is the exact discrete solution (rounding), and the large
 * error against the exact motion is printed and warned about. */
static void newmark_should_check_tightly_and_warn_of_a_large_error(void **state)
{
    (void)state;
    static const char *const q[2] = {"C=0,0;0,0&omega=16.18033988749895&t_end=100",
                                     "M=1&C=0&K=100&F=1&q0=0&v0=0&omega=10&t_end=100"};
    static const double rel[2] = {1.21, 0.40};
    for (int k = 0; k < 2; k++) {
        cJSON *d = solve_ok("num-newmark", q[k]);
        const cJSON *c = check_named(d, "exact discrete solution");
        assert_non_null(c);
        double tol = cJSON_GetObjectItem(c, "tolerance")->valuedouble;
        assert_true(tol < 1e-9);                                /* was 9041 m and 12469 m */
        check_abs(scalar(d, "relative_error"), rel[k], 0.01, "the scheme's error against the exact motion");
        assert_true(warned(d, "off the exact motion"));
        cJSON_Delete(d);
    }
}

/* Issue 10, defect 12: C = diag(20, 0) on the default chain gives the
 * state matrix a double pair l^2 + 10 l + 100: zeta = 0.5 (not 0.447). */
static void newmark_modes_should_take_zeta_from_the_complex_modes(void **state)
{
    (void)state;
    cJSON *d = solve_ok("num-newmark", "C=20,0;0,0");
    for (int j = 0; j < 2; j++) {
        check_rel(cell(d, "modes", j, "zeta"), 0.5, 1e-14, "zeta of the defective pair");
        check_rel(cell(d, "modes", j, "omega"), 10, 1e-14, "omega of the defective pair");
    }
    cJSON_Delete(d);
}

/* Issue 10, limits: 5e4 steps cost at most 80 ms; now what fits: 1.9e5
 * steps of one mass, 4.6e4 of six. */
static void newmark_should_allow_what_fits_the_budget(void **state)
{
    (void)state;
    cJSON_Delete(solve_ok("num-newmark", "M=1&C=0.2&K=100&F=1&q0=0&v0=0&omega=3&h=1e-3&t_end=190"));
    answer a = solve("num-newmark", "M=1&C=0.2&K=100&F=1&q0=0&v0=0&omega=3&h=1e-3&t_end=200");
    assert_int_equal(a.status, 400);
    cJSON_Delete(a.doc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(two_dof_should_give_mass_normalised_modes_with_phi1_positive),
        cmocka_unit_test(two_dof_should_give_a_large_mass_ratio_its_small_components),
        cmocka_unit_test(two_dof_should_report_a_repeated_frequency),
        cmocka_unit_test(two_dof_should_count_a_rigid_body_mode),
        cmocka_unit_test(absorber_should_stop_the_main_mass_at_the_tuned_frequency),
        cmocka_unit_test(transients_should_lose_nothing_with_every_mode_kept),
        cmocka_unit_test(a_large_force_should_not_cost_the_transition_matrix_its_digits),
        cmocka_unit_test(transient_checks_should_be_bounds_within_100_times_the_rounding),
        cmocka_unit_test(chain_of_1000_masses_should_stay_within_n_squared_eps),
        cmocka_unit_test(bar_modes_should_leave_the_rigid_mode_out_and_converge_like_h2),
        cmocka_unit_test(beam_modes_should_find_the_tabulated_roots_and_h4),
        cmocka_unit_test(beam_of_1000_elements_should_answer),
        cmocka_unit_test(bar_wave_should_be_exact_at_the_courant_limit_and_refuse_above),
        cmocka_unit_test(sudden_load_should_nearly_double_the_static_deflection),
        cmocka_unit_test(stiffly_damped_modes_should_stay_exact_under_a_fast_load),
        cmocka_unit_test(dynamic_factor_should_be_finite_where_the_motion_has_not_reached_the_probe),
        cmocka_unit_test(beam_transient_should_refuse_a_step_a_moving_load_crosses_within),
        cmocka_unit_test(newmark_should_check_tightly_and_warn_of_a_large_error),
        cmocka_unit_test(newmark_modes_should_take_zeta_from_the_complex_modes),
        cmocka_unit_test(newmark_should_allow_what_fits_the_budget),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
