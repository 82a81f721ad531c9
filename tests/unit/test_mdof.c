/* test_mdof.c — mm_mdof against closed forms: the modes of a 2-DOF system
 * and of a chain, rigid-body modes, complex modes (proportional damping, a
 * defective pair), the exact motion by transition matrices against the
 * 1-DOF closed form (every regime, resonance) and against modal
 * superposition, the exact discrete solution against mm_newmark runs, and
 * the modal coordinate under pulses and polynomial loads. */
#include "mm_test.h"

#include <stdlib.h>
#include <string.h>

#include "mm_mdof.h"
#include "mm_ode.h"
#include "mm_sdof.h"

#define EPS 2.220446049250313e-16

/* ---- modes ----------------------------------------------------------------- */

/* wall-k1-m1-k2-m2-k3-wall: omega^2 = roots of m1 m2 l^2 - (m1 (k2 + k3) +
 * m2 (k1 + k2)) l + (k1 k2 + k1 k3 + k2 k3) = 0. */
static void modes_should_match_the_two_dof_closed_form(void **state)
{
    (void)state;
    double m1 = 2, m2 = 0.5, k1 = 300, k2 = 80, k3 = 40;
    double M[4] = {m1, 0, 0, m2}, K[4] = {k1 + k2, -k2, -k2, k2 + k3}, w[2], Phi[4];
    mm_mdof_system s = {2, M, NULL, K};
    mm_error err;
    int nr;
    assert_int_equal(mm_mdof_modes(&s, 2, w, Phi, &nr, &err), MM_OK);
    double b = m1 * (k2 + k3) + m2 * (k1 + k2), c = k1 * k2 + k1 * k3 + k2 * k3, a = m1 * m2;
    double l2 = (b + sqrt(b * b - 4 * a * c)) / (2 * a), l1 = c / (a * l2);
    check_rel(w[0], sqrt(l1), 4 * EPS, "omega1 (symmetric pencil: a few eps)");
    check_rel(w[1], sqrt(l2), 4 * EPS, "omega2");
    assert_int_equal(nr, 0);
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) {
            double mij = m1 * Phi[i] * Phi[j] + m2 * Phi[2 + i] * Phi[2 + j];
            check_abs(mij, i == j, 8 * EPS, "mass-normalised and M-orthogonal");
        }
    assert_true(Phi[0] > 0 && Phi[1] > 0);   /* first component positive */
}

/* The closed form, every component to a few eps of itself, against mpmath
 * (50 digits, the double inputs exactly).  (a) A mass ratio of 5.6e5 (the
 * 8,000-draw study's failing vib-2dof request): theta = atan2(2b, a - d)/2
 * lay 3.6e-5 from pi/2, and cos/sin of it gave the small components with
 * 24,700 eps of error (5.5e-12).  (b) Nearly equal uncoupled frequencies
 * (a - d = 4.3e-5 of a): a and d rounded, their difference carried eps a
 * into the modes' small components, 540 eps. */
static void two_dof_closed_form_should_give_every_component_to_a_few_eps(void **state)
{
    (void)state;
    static const struct {
        double m1, m2, k1, k2, k3, w[2], phi[4];
    } c[] = {
        {693.9386378752288, 0.0012416879053236717, 320158.95550674456, 1993.5845898484406, 478396.99235529656,
         {21.54590143186047743466, 19669.39557229692553048},
         {0.03796115916235098189002, 2.107297564700386713307e-7, 0.0001575361307202314002928,
          -28.37878348206557277559}},
        {3, 0.7, 300.7, 0.0001, 70.1, {10.00714744306811244875, 10.01166153639654361573},
         {0.0004408806949016630772726, 0.5773501008552316831924, 1.195228260849090253042,
          -0.0009127097499916858696285}},
    };
    for (size_t k = 0; k < sizeof c / sizeof *c; k++) {
        double w[2], phi[4];
        mm_mdof_two_dof(c[k].m1, c[k].m2, c[k].k1, c[k].k2, c[k].k3, w, phi);
        for (int j = 0; j < 2; j++)
            check_rel(w[j], c[k].w[j], 4 * EPS, "omega_j, mpmath");
        for (int i = 0; i < 4; i++)
            check_rel(phi[i], c[k].phi[i], 4 * EPS, "phi, each component to a few eps of itself (mpmath)");
    }
}

/* n masses m, springs k, both ends fixed: omega_j = 2 sqrt(k/m) sin(j pi / (2 (n + 1))). */
static void modes_should_match_the_fixed_chain_and_its_lowest_modes(void **state)
{
    (void)state;
    enum { N = 40 };
    double *M = calloc(N * N, sizeof *M), *K = calloc(N * N, sizeof *K), w[N], wf[5];
    for (int i = 0; i < N; i++) {
        M[i * N + i] = 3;
        K[i * N + i] = 2 * 75;
        if (i + 1 < N)
            K[i * N + i + 1] = K[(i + 1) * N + i] = -75;
    }
    mm_mdof_system s = {N, M, NULL, K};
    mm_error err;
    assert_int_equal(mm_mdof_modes(&s, N, w, NULL, NULL, &err), MM_OK);
    assert_int_equal(mm_mdof_modes(&s, 5, wf, NULL, NULL, &err), MM_OK);
    for (int j = 1; j <= N; j++) {
        double ex = 2 * sqrt(75.0 / 3) * sin(j * M_PI / (2.0 * (N + 1)));
        /* absolute error of an eigenvalue ~ eps lambda_max: relative on
         * omega_j about eps lambda_max / (2 lambda_j) */
        double tol = 10 * EPS * (w[N - 1] * w[N - 1]) / (ex * ex);
        check_rel(w[j - 1], ex, tol, "chain, closed form");
        if (j <= 5)
            check_rel(wf[j - 1], ex, tol, "lowest modes only (dsygvx)");
    }
    free(M);
    free(K);
}

/* Free-free: two masses on one spring have omega = 0 and sqrt(k (m1 + m2) / (m1 m2)). */
static void modes_should_count_a_rigid_body_mode(void **state)
{
    (void)state;
    double M[4] = {1, 0, 0, 3}, K[4] = {50, -50, -50, 50}, w[2], Phi[4];
    mm_mdof_system s = {2, M, NULL, K};
    mm_error err;
    int nr;
    assert_int_equal(mm_mdof_modes(&s, 2, w, Phi, &nr, &err), MM_OK);
    assert_int_equal(nr, 1);
    check_abs(w[0], 0, 0, "rigid: exactly 0");
    check_rel(w[1], sqrt(50.0 * 4 / 3), 4 * EPS, "elastic mode");
    check_rel(Phi[0], Phi[2], 4 * EPS, "rigid mode: both masses move alike");
    double Kn[4] = {50, -60, -60, 50};
    s.K = Kn;
    assert_int_equal(mm_mdof_modes(&s, 2, w, Phi, &nr, &err), MM_ERANGE);
    assert_string_equal(err.param, "K");
}

/* ---- complex modes ------------------------------------------------------------- */

static void complex_modes_should_give_rayleigh_damping_ratios(void **state)
{
    (void)state;
    double M[9] = {1, 0, 0, 0, 2, 0, 0, 0, 1}, K[9] = {200, -100, 0, -100, 300, -200, 0, -200, 200};
    double a = 0.4, b = 0.002, C[9], w[3];
    for (int i = 0; i < 9; i++)
        C[i] = a * M[i] + b * K[i];
    mm_mdof_system s = {3, M, C, K};
    mm_mdof_cmode cm[3];
    mm_error err;
    assert_int_equal(mm_mdof_modes(&s, 3, w, NULL, NULL, &err), MM_OK);
    assert_int_equal(mm_mdof_complex_modes(&s, cm, &err), MM_OK);
    for (int j = 0; j < 3; j++) {
        double z = a / (2 * w[j]) + b * w[j] / 2;
        check_rel(cm[j].omega, w[j], 1e-13, "|lambda| = omega_j with proportional damping");
        check_rel(cm[j].zeta, z, 1e-12, "zeta_j = a/(2 omega_j) + b omega_j/2");
        check_rel(cm[j].omega_d, w[j] * sqrt(1 - z * z), 1e-13, "omega_d");
    }
}

/* M = I, K = [200 -100; -100 100], C = diag(20, 0): det(l^2 M + l C + K) =
 * l^4 + 20 l^3 + 300 l^2 + 2000 l + 10000 = (l^2 + 10 l + 100)^2, a double
 * (defective) pair with omega = 10, zeta = 0.5 (issue 10: the table said
 * 0.447 from phi^T C phi of the undamped modes). */
static void complex_modes_should_find_the_defective_pair_of_issue_10(void **state)
{
    (void)state;
    double M[4] = {1, 0, 0, 1}, K[4] = {200, -100, -100, 100}, C[4] = {20, 0, 0, 0};
    mm_mdof_system s = {2, M, C, K};
    mm_mdof_cmode cm[2];
    mm_error err;
    assert_int_equal(mm_mdof_complex_modes(&s, cm, &err), MM_OK);
    for (int j = 0; j < 2; j++) {
        /* a double eigenvalue is found to about sqrt(eps) */
        check_rel(cm[j].omega, 10, 1e-14, "omega of the defective pair (the mean of its split)");
        check_rel(cm[j].zeta, 0.5, 1e-14, "zeta of the defective pair");
    }
}

static void complex_modes_should_pair_an_overdamped_mode(void **state)
{
    (void)state;
    double M = 2, C = 100, K = 50, w = 5, z = 100 / (2 * sqrt(2.0 * 50));
    mm_mdof_system s = {1, &M, &C, &K};
    mm_mdof_cmode cm;
    mm_error err;
    assert_int_equal(mm_mdof_complex_modes(&s, &cm, &err), MM_OK);
    check_rel(cm.omega, w, 1e-13, "sqrt(l1 l2) = omega_n");
    check_rel(cm.zeta, z, 1e-13, "-(l1 + l2)/(2 omega) = zeta");
    check_abs(cm.omega_d, 0, 0, "no oscillation");
}

/* ---- exact motion ------------------------------------------------------------------ */

static double sdof_worst(double m, double c, double k, double F0, double w, double x0, double v0,
                         double h, int nt, long gap)
{
    long *ks = malloc((size_t)nt * sizeof *ks);
    double *q = malloc((size_t)nt * sizeof *q), *v = malloc((size_t)nt * sizeof *v), worst = 0, big = 0;
    for (int i = 0; i < nt; i++)
        ks[i] = i * gap;
    mm_mdof_system s = {1, &m, &c, &k};
    mm_mdof_motion mo = {&x0, &v0, &F0, w};
    mm_error err;
    assert_int_equal(mm_mdof_exact(&s, &mo, h, nt, ks, q, v, &err), MM_OK);
    mm_sdof sd = {m, c, k, F0, w, x0, v0, 0};
    mm_sdof_props p;
    mm_sdof_props_get(&sd, &p);
    for (int i = 0; i < nt; i++) {
        double vx, x = mm_sdof_x(&sd, &p, ks[i] * h, &vx);
        worst = fmax(worst, fabs(q[i] - x));
        big = fmax(big, fabs(x));
    }
    free(ks);
    free(q);
    free(v);
    return worst / big;
}

/* One mass in every regime, against mm_sdof's closed form: under, critical
 * (a defective pair: modal superposition has no basis there), over,
 * undamped resonance (growth t sin t). */
static void exact_should_match_the_one_dof_closed_form_in_every_regime(void **state)
{
    (void)state;
    /* 400 samples, each a product by a transition matrix good to a few eps:
     * rounding grows like the number of samples */
    check_abs(sdof_worst(1, 2, 100, 1, 8, 0.01, 0, 1e-3, 400, 25), 0, 400 * 8 * EPS, "underdamped, forced");
    check_abs(sdof_worst(1, 20, 100, 1, 3, 0.01, 0, 1e-3, 400, 5), 0, 400 * 8 * EPS, "critical damping");
    check_abs(sdof_worst(2, 90, 100, 0, 0, 0.01, 1, 1e-3, 400, 5), 0, 400 * 8 * EPS, "overdamped");
    check_abs(sdof_worst(1, 0, 100, 1, 10, 0, 0, 1e-2, 400, 7), 0, 400 * 8 * EPS, "undamped resonance");
    check_abs(sdof_worst(1, 0, 100, 5, 0, 0.01, 0, 1e-2, 400, 3), 0, 400 * 8 * EPS, "a step load");
}

/* Free-free pair pushed by a constant force: the centre of mass moves as
 * F t^2 / (2 (m1 + m2)) while the spring vibrates: rigid-body motion. */
static void exact_should_follow_rigid_body_motion(void **state)
{
    (void)state;
    double M[4] = {1, 0, 0, 1}, K[4] = {100, -100, -100, 100}, F[2] = {2, 0}, q[2 * 50];
    long ks[50];
    for (int i = 0; i < 50; i++)
        ks[i] = 3 * i;
    mm_mdof_system s = {2, M, NULL, K};
    mm_mdof_motion mo = {NULL, NULL, F, 0};
    mm_error err;
    assert_int_equal(mm_mdof_exact(&s, &mo, 0.01, 50, ks, q, NULL, &err), MM_OK);
    double w = sqrt(200.0);
    for (int i = 0; i < 50; i++) {
        double t = ks[i] * 0.01, xc = t * t / 2, rel = (1 - cos(w * t)) / 200;   /* (q1 - q2)/2 */
        check_abs(q[2 * i], xc + rel, 1e-14, "q1 = centre + relative");
        check_abs(q[2 * i + 1], xc - rel, 1e-14, "q2");
    }
}

/* Proportionally damped 3-DOF under a harmonic force: the superposition of
 * its three modes (each by mm_sdof's closed form) and the transition matrix
 * agree to rounding. */
static void exact_and_modal_superposition_should_agree(void **state)
{
    (void)state;
    double M[9] = {1, 0, 0, 0, 2, 0, 0, 0, 1}, K[9] = {200, -100, 0, -100, 300, -200, 0, -200, 200};
    double C[9], F[3] = {0, 1, -0.5}, q0[3] = {0.01, 0, -0.01}, v0[3] = {0, 0.2, 0};
    for (int i = 0; i < 9; i++)
        C[i] = 0.3 * M[i] + 0.001 * K[i];
    mm_mdof_system s = {3, M, C, K};
    double w[3], Phi[9], c[3], t[100], qm[300], qe[300];
    long ks[100];
    mm_error err;
    assert_int_equal(mm_mdof_modes(&s, 3, w, Phi, NULL, &err), MM_OK);
    for (int j = 0; j < 3; j++)
        c[j] = 0.3 + 0.001 * w[j] * w[j];
    for (int i = 0; i < 100; i++) {
        ks[i] = 11 * i;
        t[i] = ks[i] * 0.01;
    }
    mm_mdof_pulse g = {1, 7, INFINITY};
    assert_int_equal(mm_mdof_modal_response(3, 3, w, c, Phi, 3, M, q0, v0, F, &g, 100, t, qm, &err), MM_OK);
    mm_mdof_motion mo = {q0, v0, F, 7};
    assert_int_equal(mm_mdof_exact(&s, &mo, 0.01, 100, ks, qe, NULL, &err), MM_OK);
    double worst = 0, big = 0;
    for (int i = 0; i < 300; i++) {
        worst = fmax(worst, fabs(qm[i] - qe[i]));
        big = fmax(big, fabs(qe[i]));
    }
    check_abs(worst, 0, 1e-12 * big, "modal superposition vs transition matrix");
}

/* ---- exact discrete solution ---------------------------------------------------------- */

typedef struct harm {
    const double *F;
    double w;
    int n;
} harm;

static int harm_force(double t, const double *q, const double *qd, double *F, void *params)
{
    (void)q;
    (void)qd;
    const harm *h = params;
    for (int i = 0; i < h->n; i++)
        F[i] = h->F[i] * cos(h->w * t);
    return 0;
}

/* Every scheme's run equals its exact discrete solution to rounding, with
 * a forced, non-proportionally damped 3-DOF system over 20 000 steps. */
static void newmark_runs_should_equal_their_exact_discrete_solution(void **state)
{
    (void)state;
    double M[9] = {2, 0.5, 0, 0.5, 1, 0, 0, 0, 1.5}, K[9] = {300, -100, 0, -100, 250, -150, 0, -150, 150};
    double C[9] = {0.8, -0.2, 0, -0.2, 0.5, -0.1, 0, -0.1, 0.3};
    double q0[3] = {0.01, -0.02, 0.005}, v0[3] = {0.1, 0, -0.2}, F[3] = {1, 0.5, -1};
    static const mm_newmark_method ms[] = {MM_NEWMARK_AVERAGE, MM_NEWMARK_LINEAR, MM_NEWMARK_HHT,
                                           MM_NEWMARK_GENERALIZED_ALPHA, MM_NEWMARK_CENTRAL};
    enum { STEPS = 20000, STRIDE = 100, NT = STEPS / STRIDE + 1 };
    harm hm = {F, 3, 3};
    for (size_t mi = 0; mi < sizeof ms / sizeof ms[0]; mi++) {
        mm_newmark_problem p = {.n = 3, .M = M, .C = C, .K = K, .force = harm_force,
                                .force_kind = MM_NEWMARK_FORCE_TIME, .params = &hm, .q0 = q0,
                                .qd0 = v0, .t0 = 0, .t_end = STEPS * 0.005};
        mm_newmark_options o;
        mm_newmark_options_init(&o);
        o.method = ms[mi];
        o.h = 0.005;
        o.stride = STRIDE;
        static double t[NT], q[3 * NT], qd[3 * NT];
        mm_newmark_result r = {.t = t, .q = q, .qd = qd, .max_rows = NT};
        mm_error err;
        mm_newmark_work *wk = mm_newmark_work_alloc(3);
        assert_int_equal(mm_newmark_solve(&p, &o, wk, &r, &err), MM_OK);
        mm_newmark_work_free(wk);
        assert_int_equal(r.rows, NT);
        long ks[NT];
        for (int i = 0; i < NT; i++)
            ks[i] = (long)i * STRIDE;
        static double qx[3 * NT], vx[3 * NT];
        mm_mdof_system s = {3, M, C, K};
        mm_mdof_motion mo = {q0, v0, F, 3};
        assert_int_equal(mm_mdof_newmark_exact(&s, &mo, &o, NT, ks, qx, vx, &err), MM_OK);
        double worst = 0, big = 0;
        for (int i = 0; i < 3 * NT; i++) {
            worst = fmax(worst, fabs(q[i] - qx[i]));
            big = fmax(big, fabs(qx[i]));
        }
        /* the run adds a few eps of the state per step (random-walk-like),
         * the powers about log2(100) eps per sample */
        check_abs(worst, 0, 1e-11 * big, mm_newmark_method_name(ms[mi]));
    }
}

/* ---- one modal coordinate ------------------------------------------------------------- */

/* A rigid-body mode (omega = 0) with and without damping, under a step, a
 * pulse and a harmonic load, against the transition matrix of the same
 * 1-DOF system with K = 0. */
static void sdof_pulse_should_handle_rigid_modes(void **state)
{
    (void)state;
    static const double cs[2] = {0, 3}, Ws[2] = {0, 4};
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2; b++) {
            double m = 1, c = cs[a], k = 0, F = 2, x0 = 0.1, v0 = -0.3, q[41], v[41];
            long ks[41];
            for (int i = 0; i < 41; i++)
                ks[i] = i;
            mm_mdof_system s = {1, &m, &c, &k};
            mm_mdof_motion mo = {&x0, &v0, &F, Ws[b]};
            mm_error err;
            assert_int_equal(mm_mdof_exact(&s, &mo, 0.05, 41, ks, q, v, &err), MM_OK);
            mm_mdof_pulse g = {F, Ws[b], INFINITY};
            for (int i = 0; i < 41; i++) {
                double vd, x = mm_mdof_sdof_pulse(0, c, x0, v0, &g, ks[i] * 0.05, &vd);
                check_abs(x, q[i], 1e-14, "rigid mode: displacement");
                check_abs(vd, v[i], 1e-14, "rigid mode: velocity");
            }
        }
}

/* A rectangular pulse of duration td on an undamped oscillator from rest:
 * after it, x = (p/w^2) [cos w (t - td) - cos w t]. */
static void sdof_pulse_should_leave_the_free_vibration_of_a_rectangular_pulse(void **state)
{
    (void)state;
    double w = 7, p = 3, td = 0.4;
    mm_mdof_pulse g = {p, 0, td};
    for (double t = 0; t < 3; t += 0.037) {
        double want = t < td ? p / (w * w) * (1 - cos(w * t)) : p / (w * w) * (cos(w * (t - td)) - cos(w * t));
        /* two closed-form stages, phases w t up to 21 rad: tens of eps of 2 p/w^2 */
        check_abs(mm_mdof_sdof_pulse(w, 0, 0, 0, &g, t, NULL), want, 64 * EPS * 2 * p / (w * w), "pulse");
    }
}

/* A strongly overdamped mode (zeta = 50) under a harmonic load: the
 * exponential form against the transition matrix, and no overflow at
 * zeta omega t = 1e5 (where cosh and e^{-zeta omega t} would). */
static void sdof_pulse_should_stay_finite_when_strongly_overdamped(void **state)
{
    (void)state;
    double m = 1, c = 100, k = 1, F = 3, x0 = 0.2, v0 = 1, q[30], v[30];
    long ks[30];
    for (int i = 0; i < 30; i++)
        ks[i] = i;
    mm_mdof_system s = {1, &m, &c, &k};
    mm_mdof_motion mo = {&x0, &v0, &F, 2};
    mm_error err;
    assert_int_equal(mm_mdof_exact(&s, &mo, 0.1, 30, ks, q, v, &err), MM_OK);
    mm_mdof_pulse g = {F, 2, INFINITY};
    for (int i = 0; i < 30; i++) {
        double vd, x = mm_mdof_sdof_pulse(1, c, x0, v0, &g, ks[i] * 0.1, &vd);
        check_abs(x, q[i], 1e-13, "overdamped: displacement");
        check_abs(vd, v[i], 1e-12, "overdamped: velocity");
    }
    double x = mm_mdof_sdof_pulse(1e3, 1e6, x0, v0, &g, 1e3, NULL);
    assert_true(isfinite(x));
}

/* A ramp load a1 tau from rest, undamped: eta = a1 (tau/w^2 - sin(w tau)/w^3);
 * and a cubic load with damping against DOP853. */
static int poly_rhs(double t, const double *y, double *dy, void *params)
{
    const double *a = params;    /* w, c, a0..a3 */
    dy[0] = y[1];
    dy[1] = a[2] + t * (a[3] + t * (a[4] + t * a[5])) - a[1] * y[1] - a[0] * a[0] * y[0];
    return 0;
}

static void sdof_poly_should_be_exact_for_polynomial_loads(void **state)
{
    (void)state;
    double w = 5, a[4] = {0, 2, 0, 0};
    for (double tau = 0.1; tau < 3; tau += 0.3) {
        double eta = 0, etad = 0;
        mm_mdof_sdof_poly(w, 0, a, tau, &eta, &etad);
        check_abs(eta, 2 * (tau / (w * w) - sin(w * tau) / (w * w * w)), 1e-16, "ramp load");
    }
    /* cubic with damping, in two halves (the state carries over) */
    double par[6] = {4, 0.6, 1, -2, 0.5, 0.3}, y0[2] = {0.1, -0.2}, tout[1] = {2}, yout[2];
    mm_ode_problem prob = {.n = 2, .f = poly_rhs, .params = par, .t0 = 0, .t_end = 2, .y0 = y0};
    mm_ode_options opt;
    mm_ode_options_init(&opt);
    opt.method = MM_ODE_DOP853;
    opt.rtol = opt.atol = 1e-13;
    mm_ode_result r = {.t_out = tout, .nout = 1, .y_out = yout};
    mm_error err;
    mm_ode_work *wk = mm_ode_work_alloc(2);
    assert_int_equal(mm_ode_solve(&prob, &opt, wk, &r, &err), MM_OK);
    mm_ode_work_free(wk);
    double eta = 0.1, etad = -0.2, a1[4] = {1, -2, 0.5, 0.3};
    mm_mdof_sdof_poly(4, 0.6, a1, 1, &eta, &etad);
    /* the same cubic from tau = 1: a(tau') with tau = 1 + tau' */
    double a2[4] = {1 - 2 + 0.5 + 0.3, -2 + 1 + 0.9, 0.5 + 0.9, 0.3};
    mm_mdof_sdof_poly(4, 0.6, a2, 1, &eta, &etad);
    check_abs(eta, yout[0], 1e-11, "cubic load, damped, vs DOP853 at 1e-13");
    check_abs(etad, yout[1], 1e-11, "its velocity");
    /* rigid modes, undamped and damped: against the same ODE with w = 0 */
    for (int damped = 0; damped < 2; damped++) {
        double pr[6] = {0, damped ? 0.8 : 0, 1, -2, 0.5, 0.3};
        prob.params = pr;
        mm_ode_result r2 = {.t_out = tout, .nout = 1, .y_out = yout};
        wk = mm_ode_work_alloc(2);
        assert_int_equal(mm_ode_solve(&prob, &opt, wk, &r2, &err), MM_OK);
        mm_ode_work_free(wk);
        eta = 0.1, etad = -0.2;
        mm_mdof_sdof_poly(0, pr[1], a1, 2, &eta, &etad);
        check_abs(eta, yout[0], 1e-11, damped ? "rigid, damped" : "rigid, undamped");
        check_abs(etad, yout[1], 1e-11, "its velocity");
    }
}

/* Stiff, fast and near-critical modes, where a polynomial particular
 * solution cancels catastrophically (a moving load crossing an element in
 * 80 ns on a mode with c / omega^2 = 0.75 s gave 1e-6 m for 1e-23 m):
 * against the augmented exponential at 60 digits (mpmath). */
static void sdof_poly_should_stay_exact_when_stiff_fast_or_near_critical(void **state)
{
    (void)state;
    static const struct {
        double w, c, a[4], dt, e0, v0, eta, etad;
        const char *what;
    } cs[] = {
        {1.3e8, 1.26e16, {-2.5, 3.0e7, -1.1e14, 4e20}, 8e-8, 0, 0, -9.4188353629817073208e-24,
         -4.7555543048835967429e-17, "overdamped 5e7 times, the load crossing in 80 ns"},
        {10, 0.1, {1, 2e6, -3e12, 1e18}, 1e-6, 0.01, -0.5, 0.0099995000001583418699, -0.49999969997501583917,
         "underdamped, omega dt = 1e-5"},
        {100, 210, {1, 1e5, 1e10, 1e15}, 1e-5, 0, 0, 7.995101839797925094e-11, 0.000020816541287269410912,
         "5 % past critical, omega dt = 1e-3"},
        {0, 1e6, {1, -1e3, 1e6, 1e9}, 1e-3, 0.2, 3, 0.20000300108133733644, 1.9960079940000000831e-6,
         "rigid, c dt = 1000"},
        {1, 10, {1, -1, 0.5, 0.1}, 2, 0.3, -2, 0.22685892891605180307, 0.1386737541506355893, "overdamped, slow"},
        {3, 0, {0, 0, 0, 2}, 1e-4, 0, 0, 9.9999999785714309943e-22, 4.9999999850000009825e-17,
         "undamped cubic, omega dt = 3e-4"},
        {100, 195, {1, 0.1, 0.01, 0.001}, 50, 0.02, -1, 0.01558323896589107534, 0.00085937616815000001824,
         "2.5 % under critical, omega dt = 5000"},
        {2e5, 4.1e5, {3, -1e6, 2e11, 5e16}, 1e-6, 1e-6, 0.3, 1.2270092185682171337e-6, 0.16192915342009874436,
         "2.5 % past critical, omega dt = 0.2"},
    };
    for (size_t i = 0; i < sizeof cs / sizeof cs[0]; i++) {
        double eta = cs[i].e0, etad = cs[i].v0;
        mm_mdof_sdof_poly(cs[i].w, cs[i].c, cs[i].a, cs[i].dt, &eta, &etad);
        check_abs(eta, cs[i].eta, 1e-12 * fabs(cs[i].eta), cs[i].what);
        check_abs(etad, cs[i].etad, 1e-12 * fabs(cs[i].etad), cs[i].what);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(modes_should_match_the_two_dof_closed_form),
        cmocka_unit_test(two_dof_closed_form_should_give_every_component_to_a_few_eps),
        cmocka_unit_test(modes_should_match_the_fixed_chain_and_its_lowest_modes),
        cmocka_unit_test(modes_should_count_a_rigid_body_mode),
        cmocka_unit_test(complex_modes_should_give_rayleigh_damping_ratios),
        cmocka_unit_test(complex_modes_should_find_the_defective_pair_of_issue_10),
        cmocka_unit_test(complex_modes_should_pair_an_overdamped_mode),
        cmocka_unit_test(exact_should_match_the_one_dof_closed_form_in_every_regime),
        cmocka_unit_test(exact_should_follow_rigid_body_motion),
        cmocka_unit_test(exact_and_modal_superposition_should_agree),
        cmocka_unit_test(newmark_runs_should_equal_their_exact_discrete_solution),
        cmocka_unit_test(sdof_pulse_should_handle_rigid_modes),
        cmocka_unit_test(sdof_pulse_should_leave_the_free_vibration_of_a_rectangular_pulse),
        cmocka_unit_test(sdof_pulse_should_stay_finite_when_strongly_overdamped),
        cmocka_unit_test(sdof_poly_should_be_exact_for_polynomial_loads),
        cmocka_unit_test(sdof_poly_should_stay_exact_when_stiff_fast_or_near_critical),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
