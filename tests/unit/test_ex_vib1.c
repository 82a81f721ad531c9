/* test_ex_vib1.c — the hard cases of the time-integration exercises, through
 * the real pipeline (mm_api_solve: text parameters -> validation -> solve ->
 * JSON), read back with cJSON:
 *   vib-resonance:          zero damping, tuned: the response is
 *                           F0 t sin(omega t) / (2 m omega) at every point and
 *                           the envelope grows at F0 / (2 m omega_n);
 *   critical damping:       vib-resonance and vib-base-excitation at exactly
 *                           c = 2 sqrt(k m) agree with c one part in 1e9
 *                           either side (no 0/0 in the closed form); num-newmark
 *                           falls back to DOP853 (defective modes);
 *   vib-coulomb:            the mass sticks where |k x| <= mu m g and stays
 *                           there: one stop, velocity exactly 0 afterwards,
 *                           the closed-form rests; a start inside the band
 *                           never moves; a knife-edge rest counts as a stop;
 *   num-newmark:            average acceleration stable (and energy
 *                           conserving) at omega_max h = 8, central
 *                           difference refused past 2 / omega_max, Newton
 *                           reported with the cubic spring;
 *   vib-integrators:        RK4's energy loss equals |R(i omega h)|^(2N);
 *   vib-frequency-response: the peak and half-power points;
 *   vib-base-excitation:    T = 1 at r = sqrt(2) for any damping. */
#include "mm_test.h"


#include "mm_api.h"
#include "mm_vibtest.h"

/* ---- vib-resonance ------------------------------------------------------------- */

static void undamped_resonance_should_grow_like_t_sin_t(void **state)
{
    (void)state;
    /* m = 2, k = 50: omega_n = 5; F0 = 3 */
    cJSON *d = solve_ok("vib-resonance", "m=2&k=50&c=0&F0=3&detuning=0&t_end=20&points=2001");
    double *t, *x;
    int n = series(d, "x", &t, &x);
    double w = 5, a = 3 / (2 * 2 * w), worst = 0;
    for (int i = 0; i < n; i++)
        worst = fmax(worst, fabs(x[i] - a * t[i] * sin(w * t[i])));
    /* DOP853 at rtol 1e-10 over 100 radians: far below 1e-7 of the 3 m reached */
    check_abs(worst, 0, 1e-7 * a * 20, "x(t) against F0 t sin(omega t) / (2 m omega) at every point");
    /* the envelope: exact linear growth, measured from peaks */
    check_rel(stat(d, "growth_rate_measured"), a, 1e-3, "envelope growth vs F0/(2 m omega_n)");
    check_rel(scalar(d, "growth_rate_theory"), a, 1e-15, "the formula");
    free(t);
    free(x);
    cJSON_Delete(d);
}

static void damped_resonance_should_build_up_to_F0_over_c_omega(void **state)
{
    (void)state;
    /* zeta = 0.025, tau = 4 s: after 80 s the amplitude is X = F0 / (c omega_n) = 0.2 m */
    cJSON *d = solve_ok("vib-resonance", "c=0.5&t_end=80");
    check_rel(scalar(d, "X"), 0.2, 1e-12, "X = F0/(c omega_n)");
    check_rel(scalar(d, "tau"), 4, 1e-12, "tau = 1/(zeta omega_n)");
    check_rel(scalar(d, "amplitude_final"), 0.2, 1e-6, "amplitude after 20 time constants");
    cJSON_Delete(d);
}

/* ---- critical damping ------------------------------------------------------------- */

static void critical_damping_should_be_continuous(void **state)
{
    (void)state;
    /* k = 100, m = 1: c = 20 is critical; the responses at c (1 -+ 1e-9) must
     * lie within ~1e-9 of it (the closed form has no 0/0 there) */
    const char *qs[3] = {"c=19.99999998&t_end=3", "c=20&t_end=3", "c=20.00000002&t_end=3"};
    double *t[3], *x[3];
    int n[3];
    for (int k = 0; k < 3; k++) {
        cJSON *d = solve_ok("vib-base-excitation", qs[k]);
        if (k == 1)
            check_rel(scalar(d, "zeta"), 1, 1e-15, "exactly critical");
        n[k] = series(d, "x", &t[k], &x[k]);
        cJSON_Delete(d);
    }
    assert_int_equal(n[0], n[1]);
    double worst = 0, big = 0;
    for (int i = 0; i < n[1]; i++) {
        worst = fmax(worst, fmax(fabs(x[0][i] - x[1][i]), fabs(x[2][i] - x[1][i])));
        big = fmax(big, fabs(x[1][i]));
    }
    check_abs(worst, 0, 1e-7 * big, "responses either side of critical damping");
    for (int k = 0; k < 3; k++) {
        free(t[k]);
        free(x[k]);
    }
    /* resonance with critical damping builds up without overshoot */
    cJSON *d = solve_ok("vib-resonance", "c=20&t_end=5");
    check_rel(scalar(d, "zeta"), 1, 1e-15, "critical");
    cJSON_Delete(d);
}

static void newmark_should_fall_back_to_dop853_for_critical_damping(void **state)
{
    (void)state;
    /* one mass, c = 2 sqrt(k m): a double eigenvalue, modes defective; the
     * exact motion (a transition matrix) and the exact discrete solution
     * (powers of the amplification matrix) need no modes, so no fallback */
    cJSON *d = solve_ok("num-newmark", "M=1&C=20&K=100&F=1&q0=0.01&v0=0&omega=3&h=0.001&t_end=2");
    const cJSON *c;
    int found = 0;
    cJSON_ArrayForEach(c, cJSON_GetObjectItem(d, "checks"))
        if (strstr(cJSON_GetObjectItem(c, "name")->valuestring, "exact discrete solution"))
            found = 1;
    assert_true(found);
    check_abs(scalar(d, "observed_order"), 2, 0.1, "second order at critical damping");
    cJSON_Delete(d);
}

/* ---- vib-coulomb --------------------------------------------------------------------- */

static void coulomb_should_stop_once_where_static_friction_holds(void **state)
{
    (void)state;
    /* defaults: m = 1, k = 100, mu = 0.1, g = 9.81, x0 = 0.1: the band is
     * d = 0.00981 m; rests at 0.1 -> -0.08038 -> 0.06076 -> -0.04114 ->
     * 0.02152 -> -0.0019, every pi/10 s */
    cJSON *d = solve_ok("vib-coulomb", "points=2001");
    double dd = 0.1 * 9.81 / 100;
    assert_int_equal((int)scalar(d, "half_cycles"), 5);
    check_rel(scalar(d, "stop_time"), 5 * M_PI / 10, 1e-9, "stop after five half periods");
    check_abs(scalar(d, "x_final"), -(0.1 - 10 * dd), 1e-10, "x_final = -(x0 - 5 * 2 d), on the far side");
    check_rel(scalar(d, "decay_per_cycle"), 4 * dd, 1e-15, "4 mu m g / k");
    int rows = table_rows(d, "rests");
    assert_int_equal(rows, 5);
    for (int j = 0; j < rows; j++) {
        double r = cell(d, "rests", j, "spring_over_friction")->valuedouble;
        if (j < rows - 1)
            assert_true(r > 1);           /* the spring beats friction: turn back */
        else
            assert_true(r <= 1);          /* static friction holds: the one stop */
    }
    /* after the stop: velocity exactly 0, position frozen (no chattering) */
    double *t, *v, *tx, *x;
    int n = series(d, "v", &t, &v);
    series(d, "x", &tx, &x);
    double ts = scalar(d, "stop_time"), xf = scalar(d, "x_final");
    int after = 0, sign_changes = 0;
    for (int i = 0; i < n; i++) {
        if (t[i] > ts) {
            after++;
            assert_true(v[i] == 0);
            assert_true(x[i] == xf);
        }
        if (i > 0 && t[i] < ts && v[i] * v[i - 1] < 0)
            sign_changes++;
    }
    assert_true(after > 100);
    /* the velocity changes sign only at the four turning rests (each once;
     * a rest falling on a plot point shows as an exact zero, not a change) */
    assert_true(sign_changes <= 4);
    free(t);
    free(v);
    free(tx);
    free(x);
    cJSON_Delete(d);
}

/* The regression: 1902 arcs of 7.9 m each made the same ~9e-13 relative
 * error at rtol 1e-10 and 1e-12 alike, so a whole second run at rtol/100
 * called x_final good to 2.5e-10 m where it was 7.3e-9 m off (the energy
 * check 17 times over).  Each arc is now checked against itself at rtol
 * 1e-14 and the errors summed; all checks must pass here. */
static void coulomb_long_decay_should_bound_its_error_arc_by_arc(void **state)
{
    (void)state;
    cJSON *d = solve_ok("vib-coulomb", "m=0.0529352356745823&k=0.048100184818084014&mu=0.0042567983946563059"
                                       "&g=0.44454942295444166&x0=0.079144453195678643&v0=7.5506910382631567"
                                       "&points=376");
    assert_int_equal((int)scalar(d, "half_cycles"), 1902);
    cJSON_Delete(d);
}

static void coulomb_inside_the_band_should_never_move(void **state)
{
    (void)state;
    cJSON *d = solve_ok("vib-coulomb", "x0=0.009");
    check_abs(scalar(d, "stop_time"), 0, 0, "never moves");
    check_abs(scalar(d, "x_final"), 0.009, 0, "stays at x0");
    assert_int_equal((int)scalar(d, "half_cycles"), 0);
    cJSON_Delete(d);
    /* just outside the band: one slide of 2 d, stops on the same side */
    d = solve_ok("vib-coulomb", "x0=0.0099");
    assert_int_equal((int)scalar(d, "half_cycles"), 1);
    check_abs(scalar(d, "x_final"), 2 * 0.00981 - 0.0099, 1e-9, "x_final = 2 d - x0 after one slide");
    check_rel(scalar(d, "stop_time"), M_PI / 10, 1e-9, "half a period");
    cJSON_Delete(d);
}

static void coulomb_knife_edge_should_count_as_a_stop(void **state)
{
    (void)state;
    /* d = 0.01 exactly: 0.05 -> -0.03 -> 0.01 = d: |k x| = mu m g, a stop */
    cJSON *d = solve_ok("vib-coulomb", "m=1&k=100&mu=0.1&g=10&x0=0.05");
    assert_int_equal((int)scalar(d, "half_cycles"), 2);
    check_abs(scalar(d, "x_final"), 0.01, 1e-9, "stops at the band's edge");
    cJSON_Delete(d);
    /* a moving start: v0 > 0 from x0 = 0 */
    d = solve_ok("vib-coulomb", "x0=0&v0=1");
    assert_true(scalar(d, "half_cycles") >= 2);
    cJSON_Delete(d);
    /* a short first arc moving left (v0 < 0): stop_time = (atan2 + pi)/w_n
     * cancelled to 2.3e-14; mpmath at 40 digits: 0.021119119333822773917 s */
    d = solve_ok("vib-coulomb", "m=73.886549389761&k=0.12214804332253584&mu=1.733648035127852"
                                "&g=9.514769309138005&x0=0.6766213569662685&v0=-0.34834185018648967");
    check_rel(scalar(d, "stop_time"), 0.021119119333822773917, 4e-16, "a short arc's stop time");
    cJSON_Delete(d);
}

/* ---- num-newmark ----------------------------------------------------------------------- */

static void average_acceleration_should_be_stable_at_a_large_step(void **state)
{
    (void)state;
    /* omega_max = 16.18 rad/s, h = 0.5 s: omega_max h = 8.1, far past any
     * explicit limit; free undamped motion for 200 s (400 steps) */
    cJSON *d = solve_ok("num-newmark", "h=0.5&t_end=200&F=0,0&C=0,0;0,0&q0=0.01,0");
    check_rel(scalar(d, "omega_max_h"), 16.180339887498949 * 0.5, 1e-12, "omega_max h");
    /* stable: energy kept to round-off (a check), motion bounded by the
     * start's energy: |q_i| <= sqrt(2 E0 / lambda_min) with E0 = 1/2 q0^T K q0 */
    check_abs(scalar(d, "energy_residual"), 0, 1e-12, "energy conserved");
    double E0 = 0.5 * 200 * 1e-4, lmin = 150 - sqrt(12500.0);
    double bound = sqrt(2 * E0 / lmin);
    for (int i = 1; i <= 2; i++) {
        char nm[8];
        snprintf(nm, sizeof nm, "q%d", i);
        double *t, *q;
        int n = series(d, nm, &t, &q);
        for (int k = 0; k < n; k++)
            assert_true(fabs(q[k]) <= bound * (1 + 1e-9));
        free(t);
        free(q);
    }
    cJSON_Delete(d);
    /* central difference is refused above 2/omega_max = 0.1236 s */
    expect_refused("num-newmark", "method=central-difference&h=0.13", "h");
    cJSON_Delete(solve_ok("num-newmark", "method=central-difference&h=0.12"));
    /* linear acceleration above 2 sqrt(3)/omega_max = 0.214 s */
    expect_refused("num-newmark", "method=linear-acceleration&h=0.22", "h");
}

static void newmark_should_converge_at_second_order(void **state)
{
    (void)state;
    static const char *const m[4] = {"average-acceleration", "linear-acceleration", "hht-alpha",
                                     "central-difference"};
    for (int k = 0; k < 4; k++) {
        char q[80];
        snprintf(q, sizeof q, "method=%s&h=0.005", m[k]);
        cJSON *d = solve_ok("num-newmark", q);
        check_abs(scalar(d, "observed_order"), 2, 0.05, m[k]);
        cJSON_Delete(d);
    }
}

static void newmark_should_report_newton_with_the_cubic_spring(void **state)
{
    (void)state;
    cJSON *d = solve_ok("num-newmark", "knl=1e5");
    double it = scalar(d, "newton_iterations");
    assert_true(it >= 1000);             /* at least one correction per step */
    assert_true(scalar(d, "newton_per_step") < 5);
    assert_true(scalar(d, "omega_max_tangent") > scalar(d, "omega_max"));
    cJSON_Delete(d);
    d = solve_ok("num-newmark", "");
    check_abs(scalar(d, "newton_iterations"), 0, 0, "linear: no Newton");
    cJSON_Delete(d);
}

static void newmark_should_refuse_bad_systems(void **state)
{
    (void)state;
    expect_refused("num-newmark", "M=1,0;0,1&K=100,-200;-200,100", "K");          /* indefinite */
    expect_refused("num-newmark", "M=1,0;0,1;1,1", "M");                         /* not square */
    expect_refused("num-newmark", "F=1,2,3", "F");                               /* wrong size */
    answer a = solve("num-newmark", "K=100,-50;-60,100");
    assert_int_equal(a.status, 400);                                              /* not symmetric */
    cJSON_Delete(a.doc);
}

/* ---- vib-integrators ---------------------------------------------------------------------- */

static void rk4_energy_should_fall_by_its_stability_function(void **state)
{
    (void)state;
    cJSON *d = solve_ok("vib-integrators", "periods=2000");
    /* omega h = 2 pi / 20, N = 40000 steps */
    double y = 2 * M_PI / 20, re = 1 - y * y / 2 + y * y * y * y / 24, im = y - y * y * y / 6;
    double want = pow(re * re + im * im, 40000) - 1;
    check_rel(scalar(d, "energy_drift_rk4"), want, 1e-8, "RK4 energy after 40000 steps");
    assert_true(fabs(scalar(d, "energy_error_newmark")) < 1e-11);
    check_abs(scalar(d, "energy_error_verlet"), 0, y * y / (4 - y * y), "Verlet bounded");
    check_abs(cell(d, "methods", 3, "observed_order")->valuedouble, 4, 0.1, "RK4 order");
    cJSON_Delete(d);
}

/* The fixed-step methods take t_end / ceil(t_end / h): that is the step
 * reported.  Past a method's stability limit (at that step) the table says
 * unstable instead of showing the error as an ordinary number. */
static void integrators_should_report_the_step_taken_and_label_instability(void **state)
{
    (void)state;
    static const char *const fixed[4] = {"central-difference", "newmark-average-acceleration",
                                         "stormer-verlet", "rk4"};
    /* h = 0.03: 10 / 0.03 = 333.3, so 334 steps of 0.0299401... */
    answer a = solve("vib-integrators", "h=0.03&periods=10");
    assert_int_equal(a.status, 200);
    for (int m = 0; m < 4; m++) {
        assert_string_equal(cell(a.doc, "methods", m, "method")->valuestring, fixed[m]);
        check_rel(cell(a.doc, "methods", m, "step")->valuedouble, 10.0 / ceil(10 / 0.03), 1e-15, "step taken");
        assert_int_equal((int)cell(a.doc, "methods", m, "steps")->valuedouble, 334);
        assert_true(cJSON_IsNumber(cell(a.doc, "methods", m, "max_error")));
    }
    check_rel(scalar(a.doc, "omega_n_h"), 10 * 10.0 / 334, 1e-15, "omega_n h at the step taken");
    check_rel(scalar(a.doc, "h_taken"), 10.0 / 334, 1e-15, "h taken");
    /* and it is the step they take: each curve ends at t_end (Newmark's three
     * were given h = 0.03 and stepped past it, to 10.02 s) */
    static const char *const curve[4] = {"x_central_difference", "x_newmark_average_acceleration",
                                         "x_stormer_verlet", "x_rk4"};
    for (int m = 0; m < 4; m++) {
        double *t, *x;
        int n = series(a.doc, curve[m], &t, &x);
        check_rel(t[n - 1], 10, 1e-15, curve[m]);
        check_rel(t[1] - t[0], 2 * 10.0 / 334, 1e-12, "every second step plotted");
        free(t);
        free(x);
    }
    cJSON_Delete(a.doc);

    /* one step: t_end = 0.02 s at h = 0.23 s (omega_n h = 2.3 asked, 0.2 taken).  The Newmark
     * three stepped 0.23 s and reported errors of 0.53, 0.16 and 0.53 of the motion for the
     * step of 0.02 s; that step errs 4.24e-7 and 8.28e-7 m (CD, AA; 40 digits, mpmath) */
    a = solve("vib-integrators", "t_end=0.02&h=0.23&periods=10");
    assert_int_equal(a.status, 200);
    for (int m = 0; m < 4; m++) {
        assert_int_equal((int)cell(a.doc, "methods", m, "steps")->valuedouble, 1);
        assert_true(cJSON_IsNumber(cell(a.doc, "methods", m, "max_error")));
        assert_true(cell(a.doc, "methods", m, "relative_error")->valuedouble < 1e-3);
    }
    cJSON_Delete(a.doc);

    /* h = 0.21: 48 steps of 0.2083 s, omega_n h = 2.08 > 2: central
     * difference and Verlet unstable (their errors reach 1e8 m), average
     * acceleration and RK4 (limit about 2.91 at zeta = 0.05) not */
    a = solve("vib-integrators", "h=0.21&periods=10");
    assert_int_equal(a.status, 200);
    for (int m = 0; m < 4; m++)
        check_rel(cell(a.doc, "methods", m, "step")->valuedouble, 10.0 / ceil(10 / 0.21), 1e-15, "step taken");
    check_rel(scalar(a.doc, "omega_n_h"), 10 * 10.0 / 48, 1e-15, "omega_n h = 2.08");
    for (int m = 0; m < 4; m++) {
        const cJSON *e = cell(a.doc, "methods", m, "max_error"), *r = cell(a.doc, "methods", m, "relative_error");
        if (m == 0 || m == 2) {
            assert_true(cJSON_IsString(e) && cJSON_IsString(r));
            assert_non_null(strstr(e->valuestring, "unstable"));
            assert_non_null(strstr(e->valuestring, "omega_n h = 2.08"));
            assert_non_null(strstr(r->valuestring, "unstable"));
        } else {
            assert_true(cJSON_IsNumber(e) && cJSON_IsNumber(r));
            assert_true(r->valuedouble < 10);
        }
    }
    cJSON_Delete(a.doc);

    /* h = 0.30: RK4 at omega_n h = 2.94 is past its damped limit (|R| = 1.09)
     * although its error has only doubled in 34 steps; h = 0.29 (2.86) not */
    a = solve("vib-integrators", "h=0.30&periods=10");
    assert_non_null(strstr(cell(a.doc, "methods", 3, "max_error")->valuestring, "|R(lambda h)|"));
    cJSON_Delete(a.doc);
    a = solve("vib-integrators", "h=0.29&periods=10");
    assert_true(cJSON_IsNumber(cell(a.doc, "methods", 3, "max_error")));
    cJSON_Delete(a.doc);

    /* damping lowers Verlet's limit: zeta = 0.5, omega_n h = 1.3 (limit
     * about 1.24) is unstable for Verlet only */
    a = solve("vib-integrators", "zeta=0.5&h=0.13&periods=10");
    assert_true(cJSON_IsNumber(cell(a.doc, "methods", 0, "max_error")));
    assert_non_null(strstr(cell(a.doc, "methods", 2, "max_error")->valuestring, "unstable"));
    cJSON_Delete(a.doc);
}

/* ---- vib-frequency-response ------------------------------------------------------------------ */

static void frequency_response_peaks_should_match_the_formulas(void **state)
{
    (void)state;
    cJSON *d = solve_ok("vib-frequency-response", "zeta=0.01,0.3,0.8&omega_n=2");
    check_rel(scalar(d, "peak_height"), 1 / (2 * 0.01 * sqrt(1 - 1e-4)), 1e-14, "peak height");
    check_rel(scalar(d, "peak_omega"), 2 * sqrt(1 - 2e-4), 1e-14, "peak frequency");
    check_abs(scalar(d, "peak_omega_found"), 2 * sqrt(1 - 2e-4), error_of(d, "peak_omega_found"),
              "peak found, within its printed bound");
    double r1 = sqrt(1 - 2e-4 - 0.02 * sqrt(1 - 1e-4)), r2 = sqrt(1 - 2e-4 + 0.02 * sqrt(1 - 1e-4));
    check_rel(scalar(d, "bandwidth"), 2 * (r2 - r1), 1e-12, "exact half-power bandwidth");
    check_rel(scalar(d, "bandwidth"), scalar(d, "bandwidth_approx"), 2e-4, "2 zeta omega_n, close at small zeta");
    /* zeta = 0.3 has a peak, zeta = 0.8 none: its peak is at r = 0 */
    assert_true(cell(d, "peaks", 1, "r_peak")->valuedouble > 0);
    check_abs(cell(d, "peaks", 2, "r_peak")->valuedouble, 0, 0, "zeta >= 1/sqrt(2): peak at r = 0");
    assert_true(cJSON_IsString(cell(d, "peaks", 2, "bandwidth")));
    assert_true(!has_scalar(d, "no_such_scalar"));
    cJSON_Delete(d);
}

/* Three draws of the tolerance study where the check "peak height found by
 * golden section vs eq. (3)" failed for the first zeta (about 0.03, 1.2 to
 * 1.65 times its bound 16 eps): golden section stopped on two points either
 * side of the sharp peak whose values were equal by symmetry, 19-26 eps
 * below the top (mm_opt).  Guards that every check passes there. */
static void frequency_response_should_reach_a_sharp_peak_height(void **state)
{
    (void)state;
    static const char *const qs[3] = {
        "zeta=0.03543807962139439,0.05551770298715441,0.19181132370626777,0.47620094771753757,0.9913153902327625"
        "&omega_n=0.011863183233762014&r_max=2.2445381724450804&points=3882",
        "zeta=0.030513960499703025,0.07737092747667002,0.2657024393079159,0.6062556264067744,0.5084985148662196"
        "&omega_n=1.51468240151862&r_max=14.36283553855037&points=2224",
        "zeta=0.030260945414241236,0.058786844888637016,0.12984863623317622,0.4103450352952307,1.1068028923559796"
        "&omega_n=0.0011178697223568808&r_max=12.192481260181054&points=3234",
    };
    for (int k = 0; k < 3; k++) {
        cJSON *d = solve_ok("vib-frequency-response", qs[k]);
        double z = cell(d, "peaks", 0, "zeta")->valuedouble;
        check_rel(cell(d, "peaks", 0, "H_peak_found")->valuedouble, 1 / (2 * z * sqrt(1 - z * z)),
                  16 * 2.2204460492503131e-16, "peak height found");
        cJSON_Delete(d);
    }
}

/* ---- vib-base-excitation ------------------------------------------------------------------------ */

static void transmissibility_should_be_one_at_root_two(void **state)
{
    (void)state;
    static const char *const cs[3] = {"0.2", "2", "40"};
    for (int k = 0; k < 3; k++) {
        char q[80];
        snprintf(q, sizeof q, "c=%s&omega=%.17g", cs[k], 10 * sqrt(2.0));
        cJSON *d = solve_ok("vib-base-excitation", q);
        check_rel(scalar(d, "transmissibility"), 1, 1e-14, "T(sqrt 2) = 1");
        check_abs(scalar(d, "r_crossing"), sqrt(2.0), 1e-10, "crossing found by Brent");
        cJSON_Delete(d);
    }
    /* defaults: r = 0.8, zeta = 0.1 */
    cJSON *d = solve_ok("vib-base-excitation", "");
    double r = 0.8, z = 0.1, T = sqrt((1 + 4 * z * z * r * r) / ((1 - r * r) * (1 - r * r) + 4 * z * z * r * r));
    check_rel(scalar(d, "transmissibility"), T, 1e-14, "eq. (3)");
    check_rel(scalar(d, "X"), 0.01 * T, 1e-14, "X = T Y");
    cJSON_Delete(d);
    /* undamped resonance has no steady state */
    expect_refused("vib-base-excitation", "c=0&omega=10", "omega");
}


int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(undamped_resonance_should_grow_like_t_sin_t),
        cmocka_unit_test(damped_resonance_should_build_up_to_F0_over_c_omega),
        cmocka_unit_test(critical_damping_should_be_continuous),
        cmocka_unit_test(newmark_should_fall_back_to_dop853_for_critical_damping),
        cmocka_unit_test(coulomb_should_stop_once_where_static_friction_holds),
        cmocka_unit_test(coulomb_long_decay_should_bound_its_error_arc_by_arc),
        cmocka_unit_test(coulomb_inside_the_band_should_never_move),
        cmocka_unit_test(coulomb_knife_edge_should_count_as_a_stop),
        cmocka_unit_test(average_acceleration_should_be_stable_at_a_large_step),
        cmocka_unit_test(newmark_should_converge_at_second_order),
        cmocka_unit_test(newmark_should_report_newton_with_the_cubic_spring),
        cmocka_unit_test(newmark_should_refuse_bad_systems),
        cmocka_unit_test(rk4_energy_should_fall_by_its_stability_function),
        cmocka_unit_test(integrators_should_report_the_step_taken_and_label_instability),
        cmocka_unit_test(frequency_response_peaks_should_match_the_formulas),
        cmocka_unit_test(frequency_response_should_reach_a_sharp_peak_height),
        cmocka_unit_test(transmissibility_should_be_one_at_root_two),
    };
    return cmocka_run_group_tests_name("ex_vib1", tests, NULL, NULL);
}
