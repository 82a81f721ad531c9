/* test_fem.c — mm_fem against the theory of bars and beams.
 *
 * References: the exact frequencies of uniform continua (n pi c / L,
 * (beta_n L)^2 sqrt(EI / rho A L^4) with roots checked against Blevins'
 * tables and against their own equations), closed-form mode shapes,
 * properties of the element matrices (rigid motion costs no strain
 * energy, the mass matrix carries rho A L and rho A L^3/3), and the orders
 * of convergence h^2 (bar) and h^4 (beam) with the sign of the error
 * (consistent mass from above, lumped from below).
 */
#include <stdlib.h>
#include <string.h>

#include "mm_test.h"
#include "mm_fem.h"
#include "mm_mdof.h"

static const double PI = 3.14159265358979323846;

/* steel, 1 m, 1 cm^2, I = 1e-8 m^4 (the exercises' defaults) */
static mm_fem_problem member(mm_fem_kind kind, mm_fem_bc bc, mm_fem_mass mass,
                             size_t n_el)
{
    mm_fem_problem p = {kind, bc, mass, n_el, {1.0, 2.1e11, 1e-4, 1e-8, 7850}, NULL};
    return p;
}

/* Relative errors of the first nm FE frequencies against the closed form. */
static void fe_errors(const mm_fem_problem *p, size_t nm, double *rel,
                      size_t *n_rigid)
{
    double om[8], ex[8];
    mm_fem_modes res = {om, NULL, 0, 0, 0, MM_FEM_AUTO};
    mm_error err;
    assert_int_equal(mm_fem_modes_solve(p, nm, NULL, &res, &err), MM_OK);
    assert_int_equal(res.n_modes, nm);
    assert_int_equal(mm_fem_exact_omegas(p, nm, ex, &err), MM_OK);
    for (size_t j = 0; j < nm; j++)
        rel[j] = om[j] / ex[j] - 1;
    if (n_rigid)
        *n_rigid = res.n_rigid;
}

/* ---- element matrices ----------------------------------------------------- */

static double form(const double *a, int n, const double *u, const double *v)
{
    double s = 0;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            s += u[i] * a[n * i + j] * v[j];
    return s;
}

static void element_stiffness_times_rigid_motion_should_be_zero(void **state)
{
    (void)state;
    mm_fem_element el = {0.37, 7e10, 3e-4, 2e-9, 2700};
    double k[16], m[16];
    mm_error err;
    assert_int_equal(mm_fem_element_matrices(MM_FEM_BAR, MM_FEM_CONSISTENT, &el,
                                             k, m, &err), MM_OK);
    for (int i = 0; i < 2; i++)   /* entries ~ EA/L = 6e7: exact cancellation */
        check_abs(k[2 * i] + k[2 * i + 1], 0.0, 0.0, "bar k [1 1]^T = 0");
    assert_int_equal(mm_fem_element_matrices(MM_FEM_BEAM, MM_FEM_CONSISTENT, &el,
                                             k, m, &err), MM_OK);
    double L = el.L, trans[4] = {1, 0, 1, 0}, rot[4] = {0, 1, L, 1};
    double scale = el.E * el.I / (L * L * L) * 12;   /* largest entry */
    for (int i = 0; i < 4; i++) {
        double kt = 0, kr = 0;
        for (int j = 0; j < 4; j++) {
            kt += k[4 * i + j] * trans[j];
            kr += k[4 * i + j] * rot[j];
        }
        /* a few roundings of entries of size 'scale' */
        check_abs(kt, 0.0, 1e-15 * scale, "beam k * translation = 0");
        check_abs(kr, 0.0, 1e-15 * scale * L, "beam k * rotation (w = x, theta = 1) = 0");
    }
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            check_abs(k[4 * i + j], k[4 * j + i], 0.0, "k symmetric");
            check_abs(m[4 * i + j], m[4 * j + i], 0.0, "m symmetric");
        }
}

static void element_mass_should_carry_rho_A_L_and_its_second_moment(void **state)
{
    (void)state;
    mm_fem_element el = {0.37, 7e10, 3e-4, 2e-9, 2700};
    double mass = el.rho * el.A * el.L, k[16], m[16], one[2] = {1, 1};
    mm_error err;
    mm_fem_mass kinds[] = {MM_FEM_CONSISTENT, MM_FEM_LUMPED};
    for (int i = 0; i < 2; i++) {
        assert_int_equal(mm_fem_element_matrices(MM_FEM_BAR, kinds[i], &el, k, m,
                                                 &err), MM_OK);
        /* kinetic energy of a unit rigid velocity = total mass (rounding) */
        check_rel(form(m, 2, one, one), mass, 1e-15, "bar: 1^T m 1 = rho A L");
    }
    assert_int_equal(mm_fem_element_matrices(MM_FEM_BEAM, MM_FEM_CONSISTENT, &el,
                                             k, m, &err), MM_OK);
    double L = el.L, trans[4] = {1, 0, 1, 0}, rot[4] = {0, 1, L, 1};
    check_rel(form(m, 4, trans, trans), mass, 1e-15, "beam: translation carries rho A L");
    /* cubic shape functions reproduce w = x exactly: rho A int x^2 dx */
    check_rel(form(m, 4, rot, rot), mass * L * L / 3, 1e-15,
              "beam: rotation about x = 0 carries rho A L^3 / 3");
}

/* ---- closed-form references ----------------------------------------------- */

static void beam_roots_should_match_tables_and_their_equations(void **state)
{
    (void)state;
    /* Blevins, Formulas for Natural Frequency and Mode Shape, table 8-1 */
    struct { mm_fem_beam_eq eq; int n; double table; } rows[] = {
        {MM_FEM_COSCOSH_MINUS1, 1, 1.87510407}, {MM_FEM_COSCOSH_MINUS1, 2, 4.69409113},
        {MM_FEM_COSCOSH_MINUS1, 3, 7.85475744}, {MM_FEM_COSCOSH_PLUS1, 1, 4.73004074},
        {MM_FEM_COSCOSH_PLUS1, 2, 7.85320462},  {MM_FEM_COSCOSH_PLUS1, 3, 10.9956078},
        {MM_FEM_TAN_TANH, 1, 3.92660231},       {MM_FEM_TAN_TANH, 2, 7.06858275},
        {MM_FEM_TAN_TANH, 3, 10.2101761},
    };
    for (size_t i = 0; i < sizeof rows / sizeof *rows; i++) {
        double x = mm_fem_beam_root(rows[i].eq, rows[i].n);
        /* the table has 9 significant digits */
        check_abs(x, rows[i].table, 6e-8, "root vs table");
        /* full precision: the unscaled equation's residual, divided by its
         * derivative, is the distance to the root: a few ulps of x */
        double f, df;
        if (rows[i].eq == MM_FEM_TAN_TANH) {
            f = sin(x) * cosh(x) - cos(x) * sinh(x);
            df = 2 * sin(x) * sinh(x);
        } else {
            double s = rows[i].eq == MM_FEM_COSCOSH_MINUS1 ? 1 : -1;
            f = cos(x) * cosh(x) + s;
            df = -sin(x) * cosh(x) + cos(x) * sinh(x);
        }
        check_abs(f / df, 0.0, 4e-16 * x, "Newton step at the root ~ ulps");
    }
    /* higher roots approach the asymptotes (2n-1)pi/2 and (2n+1)pi/2:
     * the difference is ~2 e^-x, below rounding for n >= 12 */
    check_abs(mm_fem_beam_root(MM_FEM_COSCOSH_MINUS1, 20), 39 * PI / 2, 1e-13, "n = 20");
    check_abs(mm_fem_beam_root(MM_FEM_COSCOSH_PLUS1, 20), 41 * PI / 2, 1e-13, "n = 20");
    assert_true(isnan(mm_fem_beam_root(MM_FEM_TAN_TANH, 0)));
}

/* ---- convergence ---------------------------------------------------------- */

static void bar_frequencies_should_converge_as_h2_from_above_with_consistent_mass(void **state)
{
    (void)state;
    mm_fem_bc bcs[] = {MM_FEM_FIXED_FREE, MM_FEM_FIXED_FIXED, MM_FEM_FREE_FREE};
    for (int b = 0; b < 3; b++) {
        double prev[3], rel[3];
        for (size_t n = 16, step = 0; n <= 128; n *= 2, step++) {
            mm_fem_problem p = member(MM_FEM_BAR, bcs[b], MM_FEM_CONSISTENT, n);
            fe_errors(&p, 3, rel, NULL);
            for (int j = 0; j < 3; j++) {
                assert_true(rel[j] > 0);   /* Rayleigh-Ritz: an upper bound */
                /* error = C h^2 (1 + O(h^2)): the ratio is 4 within 2 % on
                 * these meshes (mode 3 at 16 elements is the coarsest case) */
                if (step > 0)
                    check_rel(prev[j] / rel[j], 4.0, 0.02, "bar consistent: h^2");
                prev[j] = rel[j];
            }
        }
    }
}

static void bar_frequencies_should_converge_as_h2_from_below_with_lumped_mass(void **state)
{
    (void)state;
    double prev[3], rel[3];
    for (size_t n = 16, step = 0; n <= 128; n *= 2, step++) {
        mm_fem_problem p = member(MM_FEM_BAR, MM_FEM_FIXED_FREE, MM_FEM_LUMPED, n);
        fe_errors(&p, 3, rel, NULL);
        for (int j = 0; j < 3; j++) {
            assert_true(rel[j] < 0);       /* lumping lowers the kinetic energy bound */
            if (step > 0)
                check_rel(prev[j] / rel[j], 4.0, 0.02, "bar lumped: h^2");
            prev[j] = rel[j];
        }
    }
}

static void beam_frequencies_should_converge_as_h4_to_the_beta_L_roots(void **state)
{
    (void)state;
    mm_fem_bc bcs[] = {MM_FEM_FIXED_FREE, MM_FEM_PINNED_PINNED, MM_FEM_FIXED_FIXED,
                       MM_FEM_FIXED_PINNED, MM_FEM_FREE_FREE};
    for (int b = 0; b < 5; b++) {
        double prev[3], rel[3];
        for (size_t n = 16, step = 0; n <= 128; n *= 2, step++) {
            mm_fem_problem p = member(MM_FEM_BEAM, bcs[b], MM_FEM_CONSISTENT, n);
            fe_errors(&p, 3, rel, NULL);
            for (int j = 0; j < 3; j++) {
                assert_true(rel[j] > 0);
                /* cubic elements: error C h^4 (1 + O(h^2)); the ratio is
                 * 16 within 5 % from 16 -> 32 elements on (15.6 for the
                 * free-free mode 3 there, 16.0 at 64 -> 128), and the
                 * errors, 1e-9 at least, stay far above the rounding
                 * floor (~1e-11) */
                if (step > 0)
                    check_rel(prev[j] / rel[j], 16.0, 0.05, "beam: h^4");
                prev[j] = rel[j];
            }
        }
    }
}

static void fine_meshes_should_stay_accurate_to_the_rounding_floor(void **state)
{
    (void)state;
    /* the Rayleigh-quotient refinement keeps 300 and 1000 elements useful:
     * the raw eigenvalues would be off by 1e-5 and 8e-3 (see mm_fem.h) */
    mm_fem_options opt;
    mm_fem_options_init(&opt);
    double om[2], ex[2];
    mm_error err;
    struct { size_t n; mm_fem_method m; double tol; } cases[] = {
        {300, MM_FEM_DENSE, 1e-10},   /* measured 1.2e-12 */
        {300, MM_FEM_BANDED, 1e-8},   /* measured 7e-10 */
        {1000, MM_FEM_BANDED, 1e-5},  /* measured 1.1e-6 */
    };
    for (int i = 0; i < 3; i++) {
        mm_fem_problem p = member(MM_FEM_BEAM, MM_FEM_FIXED_FREE, MM_FEM_CONSISTENT,
                                  cases[i].n);
        opt.method = cases[i].m;
        mm_fem_modes res = {om, NULL, 0, 0, 0, MM_FEM_AUTO};
        assert_int_equal(mm_fem_modes_solve(&p, 2, &opt, &res, &err), MM_OK);
        assert_int_equal(res.n_rigid, 0);
        assert_int_equal(mm_fem_exact_omegas(&p, 2, ex, &err), MM_OK);
        check_rel(om[0], ex[0], cases[i].tol, "cantilever mode 1 on a fine mesh");
        check_rel(om[1], ex[1], cases[i].tol, "cantilever mode 2 on a fine mesh");
    }
}

/* ---- rigid-body modes ----------------------------------------------------- */

static void free_free_should_find_one_rigid_mode_for_a_bar_and_two_for_a_beam(void **state)
{
    (void)state;
    size_t sizes[] = {1, 2, 20, 300, 1000};
    for (size_t i = 0; i < 5; i++) {
        double om[3], ex[3];
        mm_error err;
        mm_fem_problem bar = member(MM_FEM_BAR, MM_FEM_FREE_FREE, MM_FEM_CONSISTENT,
                                    sizes[i]);
        mm_fem_modes res = {om, NULL, 0, 0, 0, MM_FEM_AUTO};
        assert_int_equal(mm_fem_modes_solve(&bar, 1, NULL, &res, &err), MM_OK);
        assert_int_equal(res.n_rigid, 1);
        assert_int_equal(res.n_modes, 1);
        assert_int_equal(mm_fem_exact_omegas(&bar, 1, ex, &err), MM_OK);
        /* one element: sqrt(12) c/L against pi c/L, +10 %; then ~h^2 */
        check_rel(om[0], ex[0], 0.11, "first elastic bar mode is pi c / L");

        mm_fem_problem beam = member(MM_FEM_BEAM, MM_FEM_FREE_FREE,
                                     MM_FEM_CONSISTENT, sizes[i]);
        size_t want = sizes[i] == 1 ? 2 : 3;   /* one element: 4 DOFs, 2 elastic */
        assert_int_equal(mm_fem_modes_solve(&beam, want, NULL, &res, &err), MM_OK);
        assert_int_equal(res.n_rigid, 2);
        assert_int_equal(res.n_modes, want);
        assert_int_equal(mm_fem_exact_omegas(&beam, 1, ex, &err), MM_OK);
        if (sizes[i] >= 20)           /* h^4: 1e-6 at 20 elements */
            check_rel(om[0], ex[0], 1e-5, "first elastic beam mode (4.73004)^2");
    }
}

static void supported_members_should_have_no_rigid_modes(void **state)
{
    (void)state;
    size_t nr;
    double rel[3];
    mm_fem_problem p = member(MM_FEM_BEAM, MM_FEM_PINNED_PINNED, MM_FEM_CONSISTENT, 10);
    fe_errors(&p, 3, rel, &nr);
    assert_int_equal(nr, 0);
    p = member(MM_FEM_BAR, MM_FEM_FIXED_FREE, MM_FEM_LUMPED, 10);
    fe_errors(&p, 3, rel, &nr);
    assert_int_equal(nr, 0);
}

/* ---- modes ------------------------------------------------------------------ */

static void bar_mode_shapes_should_be_mass_normalised_sines(void **state)
{
    (void)state;
    enum { N = 100 };
    mm_fem_problem p = member(MM_FEM_BAR, MM_FEM_FIXED_FREE, MM_FEM_CONSISTENT, N);
    double om[3], shape[3 * (N + 1)], x[N + 1];
    mm_fem_modes res = {om, shape, 0, 0, 0, MM_FEM_AUTO};
    mm_error err;
    assert_int_equal(mm_fem_modes_solve(&p, 3, NULL, &res, &err), MM_OK);
    mm_fem_node_x(&p, x);
    double mass = p.uniform.rho * p.uniform.A * p.uniform.L;
    for (int j = 0; j < 3; j++)
        for (size_t i = 0; i <= N; i++) {
            /* u_n = sqrt(2 / (rho A L)) sin((2n-1) pi x / 2L): int rho A u^2 = 1;
             * nodal values are O(h^2) off: 1e-3 of the amplitude for mode 3 */
            double want = sqrt(2 / mass) * sin((2 * j + 1) * PI * x[i] / 2);
            check_abs(shape[j * (N + 1) + i], want, 1e-3 * sqrt(2 / mass),
                      "bar mode = sqrt(2/m) sin((2n-1) pi x / 2L)");
        }
}

static void cantilever_mode_shape_should_match_the_closed_form(void **state)
{
    (void)state;
    enum { N = 50 };
    mm_fem_problem p = member(MM_FEM_BEAM, MM_FEM_FIXED_FREE, MM_FEM_CONSISTENT, N);
    size_t ndof = mm_fem_ndof(&p);
    double om[2], *shape = malloc(2 * ndof * sizeof *shape), x[N + 1];
    mm_fem_modes res = {om, shape, 0, 0, 0, MM_FEM_AUTO};
    mm_error err;
    assert_int_equal(mm_fem_modes_solve(&p, 2, NULL, &res, &err), MM_OK);
    mm_fem_node_x(&p, x);
    double mass = p.uniform.rho * p.uniform.A * p.uniform.L;
    for (int j = 0; j < 2; j++) {
        double bl = mm_fem_beam_root(MM_FEM_COSCOSH_MINUS1, j + 1);
        double sg = (cosh(bl) + cos(bl)) / (sinh(bl) + sin(bl));
        for (size_t i = 0; i <= N; i++) {
            double b = bl * x[i];     /* L = 1 */
            /* phi = cosh - cos - sg (sinh - sin) has int phi^2 dx = L, so
             * phi / sqrt(rho A L) is mass-normalised; positive at the tip */
            double w = (cosh(b) - cos(b) - sg * (sinh(b) - sin(b))) / sqrt(mass);
            double th = bl * (sinh(b) + sin(b) - sg * (cosh(b) - cos(b))) / sqrt(mass);
            /* Hermite cubics: nodal values converge fast (h^4); 1e-6 of
             * the tip amplitude 2/sqrt(m) is a loose bound at 50 elements */
            check_abs(shape[j * ndof + 2 * i], w, 1e-6 * 2 / sqrt(mass), "w(x) of the cantilever");
            check_abs(shape[j * ndof + 2 * i + 1], th, 1e-5 * 2 * bl / sqrt(mass),
                      "theta(x) of the cantilever");
        }
    }
    free(shape);
}

static void dense_and_banded_solvers_should_agree(void **state)
{
    (void)state;
    mm_fem_problem p = member(MM_FEM_BEAM, MM_FEM_FIXED_FIXED, MM_FEM_CONSISTENT, 60);
    size_t ndof = mm_fem_ndof(&p);
    double od[5], ob[5], *sd = malloc(5 * ndof * sizeof *sd), *sb = malloc(5 * ndof * sizeof *sb);
    mm_fem_options opt;
    mm_fem_options_init(&opt);
    mm_error err;
    opt.method = MM_FEM_DENSE;
    mm_fem_modes rd = {od, sd, 0, 0, 0, MM_FEM_AUTO}, rb = {ob, sb, 0, 0, 0, MM_FEM_AUTO};
    assert_int_equal(mm_fem_modes_solve(&p, 5, &opt, &rd, &err), MM_OK);
    opt.method = MM_FEM_BANDED;
    assert_int_equal(mm_fem_modes_solve(&p, 5, &opt, &rb, &err), MM_OK);
    assert_int_equal(rd.method, MM_FEM_DENSE);
    assert_int_equal(rb.method, MM_FEM_BANDED);
    double amp = 0;
    for (size_t i = 0; i < 5 * ndof; i++)
        amp = fmax(amp, fabs(sd[i]));
    for (int j = 0; j < 5; j++)       /* two algorithms, one problem: rounding */
        check_rel(ob[j], od[j], 1e-11, "same frequencies");
    for (size_t i = 0; i < 5 * ndof; i++)
        check_abs(sb[i], sd[i], 1e-7 * amp, "same mode shapes, same signs");
    free(sd);
    free(sb);
}

/* ---- meshes ----------------------------------------------------------------- */

static void one_element_bar_should_give_its_hand_calculation(void **state)
{
    (void)state;
    /* k = EA/L, m = rho A L/3 (consistent) or /2 (lumped) on the free node */
    double om[5];
    mm_error err;
    mm_fem_problem p = member(MM_FEM_BAR, MM_FEM_FIXED_FREE, MM_FEM_CONSISTENT, 1);
    mm_fem_modes res = {om, NULL, 0, 0, 0, MM_FEM_AUTO};
    assert_int_equal(mm_fem_modes_solve(&p, 5, NULL, &res, &err), MM_OK);
    assert_int_equal(res.n_modes, 1);   /* fewer than asked: one DOF */
    double c2 = p.uniform.E / p.uniform.rho;
    check_rel(om[0], sqrt(3 * c2), 1e-15, "w = sqrt(3) c / L");
    p.mass = MM_FEM_LUMPED;
    assert_int_equal(mm_fem_modes_solve(&p, 5, NULL, &res, &err), MM_OK);
    check_rel(om[0], sqrt(2 * c2), 1e-15, "w = sqrt(2) c / L");
}

static void graded_per_element_mesh_should_converge_to_the_same_member(void **state)
{
    (void)state;
    enum { N = 64 };
    mm_fem_element els[N];
    double total = 0;
    for (int e = 0; e < N; e++) {     /* lengths varying by +-30 % */
        els[e] = (mm_fem_element){1.0 + 0.3 * sin(1.7 * e), 2.1e11, 1e-4, 1e-8, 7850};
        total += els[e].L;
    }
    for (int e = 0; e < N; e++)
        els[e].L /= total;            /* a 1 m member again */
    mm_fem_problem p = member(MM_FEM_BEAM, MM_FEM_FIXED_FREE, MM_FEM_CONSISTENT, N);
    p.elements = els;
    double om[3], ex[3];
    mm_fem_modes res = {om, NULL, 0, 0, 0, MM_FEM_AUTO};
    mm_error err;
    assert_int_equal(mm_fem_modes_solve(&p, 3, NULL, &res, &err), MM_OK);
    mm_fem_problem u = member(MM_FEM_BEAM, MM_FEM_FIXED_FREE, MM_FEM_CONSISTENT, N);
    assert_int_equal(mm_fem_exact_omegas(&u, 3, ex, &err), MM_OK);
    for (int j = 0; j < 3; j++) {
        assert_true(om[j] > ex[j]);   /* still an upper bound */
        /* h^4 with h up to 1.3/64: 2e-7 for mode 3 on the uniform mesh */
        check_rel(om[j], ex[j], 1e-6, "graded mesh, same beam");
    }
    double x[N + 1];
    mm_fem_node_x(&p, x);
    check_abs(x[N], 1.0, 1e-15, "node positions add the element lengths");
}

/* ---- errors ----------------------------------------------------------------- */


/* ---- omega_max, loads, statics ------------------------------------------------ */

#define EPS 2.220446049250313e-16

/* The top of the spectrum: against every eigenvalue of the dense solver,
 * and for the lumped fixed-free bar (a chain with half a mass at its free
 * end) against its closed form (2c/h) sin((2n-1) pi / (4n)). */
static void omega_max_should_be_the_top_of_the_spectrum(void **state)
{
    (void)state;
    static const mm_fem_kind kinds[3] = {MM_FEM_BAR, MM_FEM_BAR, MM_FEM_BEAM};
    static const mm_fem_mass masses[3] = {MM_FEM_LUMPED, MM_FEM_CONSISTENT, MM_FEM_CONSISTENT};
    static const mm_fem_bc bcs[3] = {MM_FEM_FIXED_FREE, MM_FEM_FREE_FREE, MM_FEM_FIXED_FREE};
    for (int c = 0; c < 3; c++) {
        mm_fem_problem p = member(kinds[c], bcs[c], masses[c], 30);
        size_t nf = mm_fem_ndof(&p) - (bcs[c] == MM_FEM_FIXED_FREE ? (size_t)(kinds[c] == MM_FEM_BEAM ? 2 : 1) : 0);
        double *om = malloc(nf * sizeof *om), wmax;
        mm_fem_options opt;
        mm_fem_options_init(&opt);
        opt.method = MM_FEM_DENSE;
        mm_fem_modes res = {om, NULL, 0, 0, 0, MM_FEM_AUTO};
        mm_error err;
        size_t want = nf - (bcs[c] == MM_FEM_FREE_FREE);
        assert_int_equal(mm_fem_modes_solve(&p, want > 100 ? 100 : want, &opt, &res, &err), MM_OK);
        assert_int_equal(mm_fem_omega_max(&p, &wmax, &err), MM_OK);
        if (want <= 100)   /* the dense solver's top, Rayleigh-refined */
            check_rel(wmax, om[res.n_modes - 1], 1e-12, "omega_max vs the dense solver's top");
        if (c == 0) {
            double cw = sqrt(2.1e11 / 7850), h = 1.0 / 30;
            check_rel(wmax, 2 * cw / h * sin(59 * PI / 120), 1e-13, "lumped fixed-free bar, closed form");
        }
        free(om);
    }
}

/* Consistent loads carry the force and its moment; cubic beam elements are
 * exact for point loads (a cantilever's tip: P L^3 / 3EI; a simply
 * supported beam at midspan: P L^3 / 48 EI; a point between nodes too). */
static void static_deflection_should_match_beam_formulas(void **state)
{
    (void)state;
    double EI = 2.1e11 * 1e-8, P = -100;
    mm_fem_problem p = member(MM_FEM_BEAM, MM_FEM_FIXED_FREE, MM_FEM_CONSISTENT, 7);
    size_t nd = mm_fem_ndof(&p);
    double *f = malloc(18 * sizeof *f), *u = malloc(18 * sizeof *u);   /* room for 8 elements */
    mm_fem_load ld = {MM_FEM_LOAD_POINT, P, 0.3, 0, INFINITY, 0};
    mm_fem_load_vector(&p, &ld, 0, f);
    double sf = 0, sm = 0;
    for (size_t i = 0; i < 8; i++) {
        sf += f[2 * i];
        sm += f[2 * i] * (double)i / 7 + f[2 * i + 1];
    }
    check_rel(sf, P, 1e-15, "the nodal forces add up to P");
    check_rel(sm, P * 0.3, 1e-14, "and their moment to P a");
    mm_error err;
    /* tip load */
    ld.x = 1;
    mm_fem_load_vector(&p, &ld, 0, f);
    assert_int_equal(mm_fem_static_solve(&p, f, u, &err), MM_OK);
    /* cond(K) of a beam ~ 1e4 here (w and theta in different units): 1e-12 */
    check_rel(u[nd - 2], P / (3 * EI), 1e-12, "cantilever tip deflection P L^3 / 3EI");
    /* a point between nodes: deflection at the load P a^2 (3L - a) / 6EI at the tip */
    ld.x = 0.3;
    mm_fem_load_vector(&p, &ld, 0, f);
    assert_int_equal(mm_fem_static_solve(&p, f, u, &err), MM_OK);
    check_rel(u[nd - 2], P * 0.09 * (3 - 0.3) / (6 * EI), 1e-12, "tip under a load at a = 0.3 L");
    p = member(MM_FEM_BEAM, MM_FEM_PINNED_PINNED, MM_FEM_CONSISTENT, 8);
    ld.x = 0.5;
    mm_fem_load_vector(&p, &ld, 0, f);
    assert_int_equal(mm_fem_static_solve(&p, f, u, &err), MM_OK);
    check_rel(u[8], P / (48 * EI), 1e-12, "midspan P L^3 / 48 EI");
    p = member(MM_FEM_BEAM, MM_FEM_FREE_FREE, MM_FEM_CONSISTENT, 8);
    assert_int_equal(mm_fem_static_solve(&p, f, u, &err), MM_ESINGULAR);
    free(u);
    free(f);
}

/* ---- transient response ------------------------------------------------------- */

/* A 12-element cantilever under a tip step load and a harmonic load, with
 * Rayleigh damping: the banded average-acceleration run equals the
 * superposition of every mode's exact discrete Newmark solution (the
 * scheme commutes with the modal decomposition of a proportionally damped
 * system), to rounding. */
static void banded_newmark_should_equal_the_modal_newmark_solution(void **state)
{
    (void)state;
    enum { NEL = 12, NM = 24, STEPS = 400 };
    mm_fem_problem p = member(MM_FEM_BEAM, MM_FEM_FIXED_FREE, MM_FEM_CONSISTENT, NEL);
    size_t nd = mm_fem_ndof(&p), tip = nd - 2;
    double om[NM], *sh = malloc(NM * nd * sizeof *sh), *f = malloc(nd * sizeof *f);
    mm_fem_options opt;
    mm_fem_options_init(&opt);
    opt.method = MM_FEM_DENSE;
    mm_fem_modes md = {om, sh, 0, 0, 0, MM_FEM_AUTO};
    mm_error err;
    assert_int_equal(mm_fem_modes_solve(&p, NM, &opt, &md, &err), MM_OK);
    assert_int_equal(md.n_modes, NM);
    mm_fem_damping dmp = {2.0, 1e-5};
    static const double Omegas[2] = {0, 300};
    for (int c = 0; c < 2; c++) {
        mm_fem_load ld = {MM_FEM_LOAD_POINT, 50, 1.0, Omegas[c], INFINITY, 0};
        double out[STEPS + 1];
        mm_fem_transient tr = {MM_FEM_AVERAGE, 2e-4, STEPS, dmp, 1, 1, &tip, out, 0, NULL, NULL, 0};
        assert_int_equal(mm_fem_transient_solve(&p, &ld, &tr, &err), MM_OK);
        ld.P = 1;
        mm_fem_load_vector(&p, &ld, 0, f);
        double qm[STEPS + 1] = {0}, big = 0, worst = 0;
        long ks[STEPS + 1];
        for (int i = 0; i <= STEPS; i++)
            ks[i] = i;
        for (int j = 0; j < NM; j++) {
            double pj = 0, one = 1, k2 = om[j] * om[j], cj = dmp.a + dmp.b * k2, eta[STEPS + 1];
            for (size_t g = 0; g < nd; g++)
                pj += sh[j * nd + g] * f[g] * 50;
            mm_mdof_system s = {1, &one, &cj, &k2};
            mm_mdof_motion mo = {NULL, NULL, &pj, Omegas[c]};
            mm_newmark_options o;
            mm_newmark_options_init(&o);
            o.h = 2e-4;
            assert_int_equal(mm_mdof_newmark_exact(&s, &mo, &o, STEPS + 1, ks, eta, NULL, &err), MM_OK);
            for (int i = 0; i <= STEPS; i++)
                qm[i] += sh[j * nd + tip] * eta[i];
        }
        for (int i = 0; i <= STEPS; i++) {
            worst = fmax(worst, fabs(out[i] - qm[i]));
            big = fmax(big, fabs(qm[i]));
        }
        /* 24 modes, 400 steps: rounding of the banded solves and of the
         * modes (their top frequencies are stiff: omega h up to 50) */
        check_abs(worst, 0, 1e-10 * big, c ? "harmonic load" : "step load");
    }
    free(f);
    free(sh);
}

/* Modal superposition with every mode, exact in time, against the direct
 * run as h halves: the difference falls like h^2 (Newmark's error), for a
 * harmonic point load and for a load crossing a simply supported beam.  (A
 * jump in the load, a rectangular pulse, falls inside a step and costs the
 * direct run its second order: not tested here.) */
static void modal_response_should_be_the_limit_of_the_direct_run(void **state)
{
    (void)state;
    /* 4 elements keep omega_max h small enough (0.05 at the coarsest
     * step) for every mode to be in the asymptotic range */
    enum { NEL = 4, NM = 8 };
    mm_fem_problem p = member(MM_FEM_BEAM, MM_FEM_PINNED_PINNED, MM_FEM_CONSISTENT, NEL);
    size_t nd = mm_fem_ndof(&p), mid = 4;
    double om[NM], *sh = malloc(NM * nd * sizeof *sh);
    mm_fem_options opt;
    mm_fem_options_init(&opt);
    opt.method = MM_FEM_DENSE;
    mm_fem_modes md = {om, sh, 0, 0, 0, MM_FEM_AUTO};
    mm_error err;
    assert_int_equal(mm_fem_modes_solve(&p, NM, &opt, &md, &err), MM_OK);
    mm_fem_damping dmp = {5, 0};
    mm_fem_load lds[2] = {{MM_FEM_LOAD_POINT, -100, 0.37, 900, INFINITY, 0},
                          {MM_FEM_LOAD_MOVING, -100, 0, 0, INFINITY, 40}};
    for (int c = 0; c < 2; c++) {
        double T = 0.02, e[3];
        for (int r = 0; r < 3; r++) {
            long steps = 8000L << r;
            double h = T / (double)steps, *out = malloc((size_t)(steps + 1) * sizeof *out);
            mm_fem_transient tr = {MM_FEM_AVERAGE, h, steps, dmp, steps / 40, 1, &mid, out, 0, NULL, NULL, 0};
            assert_int_equal(mm_fem_transient_solve(&p, &lds[c], &tr, &err), MM_OK);
            double t[41], q[41];
            for (int i = 0; i <= 40; i++)
                t[i] = T * i / 40;
            assert_int_equal(mm_fem_modal_response(&p, &md, NM, &dmp, &lds[c], 41, t, 1, &mid, q, &err), MM_OK);
            e[r] = 0;
            for (int i = 0; i <= 40; i++)
                e[r] = fmax(e[r], fabs(out[i] - q[i]));
            free(out);
        }
        /* in the asymptotic range: log2 of the error ratio within 0.2 of 2 */
        check_abs(log2(e[0] / e[1]), 2, 0.2, c ? "moving load: order" : "harmonic load: order");
        check_abs(log2(e[1] / e[2]), 2, 0.2, c ? "moving load: order" : "harmonic load: order");
    }
    free(sh);
}

/* Subspace iteration agrees with the dense solver, and keeps mode 1 of a
 * 1000-element cantilever to rounding where the banded solver loses six
 * digits (bench_fem): the discretisation error there is 1e-15. */
static void subspace_iteration_should_match_dense_and_stay_accurate_when_fine(void **state)
{
    (void)state;
    mm_fem_problem p = member(MM_FEM_BEAM, MM_FEM_FIXED_FREE, MM_FEM_CONSISTENT, 60);
    double od[6], os[6], ex;
    mm_fem_options opt;
    mm_fem_options_init(&opt);
    opt.method = MM_FEM_DENSE;
    mm_fem_modes rd = {od, NULL, 0, 0, 0, MM_FEM_AUTO}, rs = {os, NULL, 0, 0, 0, MM_FEM_AUTO};
    mm_error err;
    assert_int_equal(mm_fem_modes_solve(&p, 6, &opt, &rd, &err), MM_OK);
    opt.method = MM_FEM_SUBSPACE;
    assert_int_equal(mm_fem_modes_solve(&p, 6, &opt, &rs, &err), MM_OK);
    assert_int_equal(rs.method, MM_FEM_SUBSPACE);
    for (int j = 0; j < 6; j++)
        check_rel(os[j], od[j], 1e-11, "subspace vs dense (both Rayleigh-refined)");
    p.n_el = 1000;
    assert_int_equal(mm_fem_modes_solve(&p, 1, &opt, &rs, &err), MM_OK);
    assert_int_equal(rs.method, MM_FEM_SUBSPACE);
    assert_int_equal(mm_fem_exact_omegas(&p, 1, &ex, &err), MM_OK);
    check_rel(os[0], ex, 1e-11, "mode 1 of 1000 elements");
}

/* ---- shift-invert Lanczos --------------------------------------------------------- */

/* One solve by the given method; omega[nm], shape (nm x ndof) or NULL. */
static mm_fem_modes solve_by(const mm_fem_problem *p, size_t nm, mm_fem_method m, double *omega, double *shape)
{
    mm_fem_options opt;
    mm_fem_options_init(&opt);
    opt.method = m;
    mm_fem_modes r = {omega, shape, 0, 0, 0, MM_FEM_AUTO};
    mm_error err;
    assert_int_equal(mm_fem_modes_solve(p, nm, &opt, &r, &err), MM_OK);
    assert_int_equal(r.method, m);
    assert_int_equal(r.n_modes, nm);
    return r;
}

/* The uniform bar's FE frequencies have a closed form of their own (the
 * mesh's dispersion relation): omega_j = 2 c / h sin(th / 2) (lumped), times
 * sqrt(3 / (3 - 2 sin^2(th / 2))) (consistent), th = j pi / n for fixed-fixed
 * and free-free (the same elastic spectrum), (2j - 1) pi / 2n for
 * fixed-free.  Lanczos must give them to rounding: the Rayleigh quotients
 * of its modes, a few n eps from the element strains (1e-13 allows 20x
 * the 5e-15 measured at 400 elements). */
static void lanczos_should_give_the_bar_meshes_closed_form_frequencies(void **state)
{
    (void)state;
    const mm_fem_bc bcs[] = {MM_FEM_FIXED_FREE, MM_FEM_FIXED_FIXED, MM_FEM_FREE_FREE};
    const size_t nel[] = {100, 400};
    for (int b = 0; b < 3; b++)
        for (int mass = 0; mass < 2; mass++)
            for (int s = 0; s < 2; s++) {
                mm_fem_problem p = member(MM_FEM_BAR, bcs[b], mass ? MM_FEM_LUMPED : MM_FEM_CONSISTENT, nel[s]);
                double om[20], n = (double)nel[s], h = 1.0 / n, c = sqrt(2.1e11 / 7850);
                mm_fem_modes r = solve_by(&p, 20, MM_FEM_LANCZOS, om, NULL);
                assert_int_equal(r.n_rigid, bcs[b] == MM_FEM_FREE_FREE ? 1 : 0);
                for (int j = 1; j <= 20; j++) {
                    double th = bcs[b] == MM_FEM_FIXED_FREE ? (2 * j - 1) * PI / (2 * n) : j * PI / n;
                    double sn = sin(th / 2), w = 2 * c / h * sn * (mass ? 1 : sqrt(3 / (3 - 2 * sn * sn)));
                    check_rel(om[j - 1], w, 1e-13, "bar: Lanczos vs the mesh's closed form");
                }
            }
}

/* Beams: against the roots beta_n L of the continuum (computed by
 * mm_fem_beam_root) where the discretisation error is below rounding
 * (1000 elements: mode 1 off by 1e-15 (h^4), mode 5 by 6e-11), on every
 * support including free-free, whose two rigid modes (a double eigenvalue
 * 0) are deflated, not iterated.  Tolerances: 3e-12 on mode 1 (measured
 * 1.2e-13 .. 9.2e-13, free-free the largest: the rounding of the solves,
 * which grows with the compliance of the supported structure), 2e-10 on
 * modes 2-5 (their discretisation error, h^4, 6e-11 on mode 5). */
static void lanczos_should_give_the_beta_L_frequencies_of_a_fine_beam(void **state)
{
    (void)state;
    const mm_fem_bc bcs[] = {MM_FEM_FIXED_FREE, MM_FEM_FIXED_FIXED, MM_FEM_FREE_FREE, MM_FEM_PINNED_PINNED,
                             MM_FEM_FIXED_PINNED};
    for (int b = 0; b < 5; b++) {
        mm_fem_problem p = member(MM_FEM_BEAM, bcs[b], MM_FEM_CONSISTENT, 1000);
        double om[5], ex[5];
        mm_error err;
        mm_fem_modes r = solve_by(&p, 5, MM_FEM_LANCZOS, om, NULL);
        assert_int_equal(r.n_rigid, bcs[b] == MM_FEM_FREE_FREE ? 2 : 0);
        assert_int_equal(mm_fem_exact_omegas(&p, 5, ex, &err), MM_OK);
        check_rel(om[0], ex[0], 3e-12, "beam, 1000 elements: mode 1 vs beta_1 L");
        for (int j = 1; j < 5; j++)
            check_rel(om[j], ex[j], 2e-10, "beam, 1000 elements: modes 2-5 vs beta_n L");
        /* and AUTO takes Lanczos for it, first time */
        mm_fem_modes ra = {om, NULL, 0, 0, 0, MM_FEM_AUTO};
        assert_int_equal(mm_fem_modes_solve(&p, 5, NULL, &ra, &err), MM_OK);
        assert_int_equal(ra.method, MM_FEM_LANCZOS);
    }
}

/* Against the dense solver (dsygvd, every mode, Rayleigh-refined the same
 * way) on every support and both members, 100 elements, 30 modes: the
 * frequencies agree to 1e-13 (both are Rayleigh quotients of good modes;
 * measured 3e-15), the same rigid modes are found, and the
 * mass-normalised shapes agree to 1e-6 of their largest entry (measured
 * 2e-11 bar, 1.4e-8 beam: the dense solver's modes carry about
 * eps lambda_max / gap, 1e-8 for a beam's 30th mode). */
static void lanczos_should_match_the_dense_solver_on_every_support(void **state)
{
    (void)state;
    const mm_fem_bc bcs[] = {MM_FEM_FIXED_FREE, MM_FEM_FIXED_FIXED, MM_FEM_FREE_FREE, MM_FEM_PINNED_PINNED,
                             MM_FEM_FIXED_PINNED};
    enum { NM = 30 };
    for (int kind = 0; kind < 2; kind++)
        for (int b = 0; b < (kind ? 5 : 3); b++) {
            mm_fem_problem p = member(kind ? MM_FEM_BEAM : MM_FEM_BAR, bcs[b], MM_FEM_CONSISTENT, 100);
            size_t nd = mm_fem_ndof(&p);
            double ol[NM], od[NM], *sl = malloc(NM * nd * sizeof *sl), *sd = malloc(NM * nd * sizeof *sd);
            mm_fem_modes rl = solve_by(&p, NM, MM_FEM_LANCZOS, ol, sl);
            mm_fem_modes rd = solve_by(&p, NM, MM_FEM_DENSE, od, sd);
            assert_int_equal(rl.n_rigid, rd.n_rigid);
            double wf = 0, ws = 0;
            for (int j = 0; j < NM; j++) {
                check_rel(ol[j], od[j], 1e-13, "Lanczos vs dense: frequency");
                wf = fmax(wf, fabs(ol[j] / od[j] - 1));
                double big = 0, diff = 0;
                for (size_t g = 0; g < nd; g++) {
                    big = fmax(big, fabs(sd[j * nd + g]));
                    diff = fmax(diff, fabs(sl[j * nd + g] - sd[j * nd + g]));
                }
                check_abs(diff / big, 0, 1e-6, "Lanczos vs dense: mode shape");
                ws = fmax(ws, diff / big);
            }
            print_message("# %s, bc %d: frequencies %.2g, shapes %.2g\n", kind ? "beam" : "bar", (int)bcs[b], wf, ws);
            free(sd);
            free(sl);
        }
}

/* The modes solve their eigenproblem and are M-orthonormal: on the free
 * DOFs of a 1000-element free-free beam (rigid modes included in the
 * orthogonality) and a cantilever, max |K v - lambda M v| over
 * max |K| max |v| at most 1e-13 (measured 1.1e-15: the round-off of K v,
 * a few eps of its largest term) and |V^T M V - I| at most 1e-13 (full
 * reorthogonalisation keeps it at ~k eps; measured 4.7e-15). */
static void lanczos_modes_should_have_small_residuals_and_be_M_orthonormal(void **state)
{
    (void)state;
    const mm_fem_bc bcs[] = {MM_FEM_FREE_FREE, MM_FEM_FIXED_FREE};
    enum { NM = 12 };
    for (int b = 0; b < 2; b++) {
        mm_fem_problem p = member(MM_FEM_BEAM, bcs[b], MM_FEM_CONSISTENT, 1000);
        size_t nd = mm_fem_ndof(&p);
        long *map = malloc(nd * sizeof *map);
        size_t nf = mm_fem_free_dofs(&p, map);
        int kd = mm_fem_half_band(&p, nf);
        size_t w = (size_t)kd + 1;
        double *Kb = malloc(nf * w * sizeof *Kb), *Mb = malloc(nf * w * sizeof *Mb);
        mm_fem_assemble_band(&p, map, nf, Kb, Mb);
        double om[NM], *sh = malloc(NM * nd * sizeof *sh);
        mm_fem_modes r = solve_by(&p, NM, MM_FEM_LANCZOS, om, sh);
        double kmax = 0;
        for (size_t i = 0; i < nf * w; i++)
            kmax = fmax(kmax, fabs(Kb[i]));
        /* the rigid modes are not in shape: orthogonality among the elastic
         * ones, and their residuals */
        double *v = malloc(NM * nf * sizeof *v), *mv = malloc(NM * nf * sizeof *mv), worst_r = 0, worst_o = 0;
        for (int j = 0; j < NM; j++) {
            for (size_t g = 0; g < nd; g++)
                if (map[g] >= 0)
                    v[j * nf + (size_t)map[g]] = sh[j * nd + g];
            double *kv = malloc(nf * sizeof *kv), vmax = 0;
            for (size_t i = 0; i < nf; i++) {
                kv[i] = mv[j * nf + i] = 0;
                vmax = fmax(vmax, fabs(v[j * nf + i]));
            }
            for (size_t i = 0; i < nf; i++)   /* symmetric band products */
                for (size_t d = 0; d < w && i + d < nf; d++) {
                    kv[i] += Kb[i * w + d] * v[j * nf + i + d];
                    mv[j * nf + i] += Mb[i * w + d] * v[j * nf + i + d];
                    if (d) {
                        kv[i + d] += Kb[i * w + d] * v[j * nf + i];
                        mv[j * nf + i + d] += Mb[i * w + d] * v[j * nf + i];
                    }
                }
            for (size_t i = 0; i < nf; i++)
                worst_r = fmax(worst_r, fabs(kv[i] - om[j] * om[j] * mv[j * nf + i]) / (kmax * vmax));
            free(kv);
        }
        for (int a = 0; a < NM; a++)
            for (int c = 0; c < NM; c++) {
                double s = 0;
                for (size_t i = 0; i < nf; i++)
                    s += v[a * nf + i] * mv[c * nf + i];
                worst_o = fmax(worst_o, fabs(s - (a == c)));
            }
        print_message("# %s: residual %.2g, M-orthonormality %.2g, rigid %zu\n",
                      b ? "cantilever" : "free-free", worst_r, worst_o, r.n_rigid);
        check_abs(worst_r, 0, 1e-13, "Lanczos: |K v - lambda M v| / (|K| |v|)");
        check_abs(worst_o, 0, 1e-13, "Lanczos: |V^T M V - I|");
        free(mv);
        free(v);
        free(sh);
        free(Mb);
        free(Kb);
        free(map);
    }
}

static void errors_should_name_the_parameter(void **state)
{
    (void)state;
    double om[5];
    mm_fem_modes res = {om, NULL, 0, 0, 0, MM_FEM_AUTO};
    mm_error err;
    mm_fem_problem p = member(MM_FEM_BEAM, MM_FEM_FIXED_FREE, MM_FEM_CONSISTENT,
                              MM_FEM_MAX_ELEMENTS + 1);
    assert_int_equal(mm_fem_modes_solve(&p, 5, NULL, &res, &err), MM_ERANGE);
    assert_string_equal(err.param, "elements");
    p.n_el = 0;
    assert_int_equal(mm_fem_check(&p, &err), MM_ERANGE);
    assert_string_equal(err.param, "elements");
    p.n_el = 10;
    p.uniform.E = 0;
    assert_int_equal(mm_fem_modes_solve(&p, 5, NULL, &res, &err), MM_EVALUE);
    assert_string_equal(err.param, "E");
    p.uniform.E = -2.1e11;
    assert_int_equal(mm_fem_check(&p, &err), MM_EVALUE);
    p.uniform.E = 2.1e11;
    p.uniform.I = NAN;
    assert_int_equal(mm_fem_check(&p, &err), MM_EVALUE);
    assert_string_equal(err.param, "I");
    p.uniform.I = 1e-8;
    p.mass = MM_FEM_LUMPED;
    assert_int_equal(mm_fem_check(&p, &err), MM_EVALUE);
    assert_string_equal(err.param, "mass");
    p = member(MM_FEM_BAR, MM_FEM_PINNED_PINNED, MM_FEM_CONSISTENT, 10);
    assert_int_equal(mm_fem_check(&p, &err), MM_EVALUE);
    assert_string_equal(err.param, "bc");
    p = member(MM_FEM_BAR, MM_FEM_FIXED_FIXED, MM_FEM_CONSISTENT, 1);
    assert_int_equal(mm_fem_check(&p, &err), MM_ERANGE);
    assert_string_equal(err.param, "elements");
    p.n_el = 4;
    assert_int_equal(mm_fem_modes_solve(&p, 0, NULL, &res, &err), MM_ERANGE);
    assert_string_equal(err.param, "modes");
    assert_int_equal(mm_fem_modes_solve(&p, MM_FEM_MAX_MODES + 1, NULL, &res, &err),
                     MM_ERANGE);
    mm_fem_element els[4] = {{.25, 1, 1, 1, 1}, {.25, 1, 1, 1, 1},
                             {.25, 1, 1, 1, -1}, {.25, 1, 1, 1, 1}};
    p.elements = els;
    assert_int_equal(mm_fem_check(&p, &err), MM_EVALUE);
    assert_string_equal(err.param, "elements");
    assert_non_null(strstr(err.msg, "element 3: rho"));
    els[2].rho = 1;
    assert_int_equal(mm_fem_exact_omegas(&p, 1, om, &err), MM_EVALUE);
    assert_string_equal(err.param, "elements");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(element_stiffness_times_rigid_motion_should_be_zero),
        cmocka_unit_test(element_mass_should_carry_rho_A_L_and_its_second_moment),
        cmocka_unit_test(beam_roots_should_match_tables_and_their_equations),
        cmocka_unit_test(bar_frequencies_should_converge_as_h2_from_above_with_consistent_mass),
        cmocka_unit_test(bar_frequencies_should_converge_as_h2_from_below_with_lumped_mass),
        cmocka_unit_test(beam_frequencies_should_converge_as_h4_to_the_beta_L_roots),
        cmocka_unit_test(fine_meshes_should_stay_accurate_to_the_rounding_floor),
        cmocka_unit_test(free_free_should_find_one_rigid_mode_for_a_bar_and_two_for_a_beam),
        cmocka_unit_test(supported_members_should_have_no_rigid_modes),
        cmocka_unit_test(bar_mode_shapes_should_be_mass_normalised_sines),
        cmocka_unit_test(cantilever_mode_shape_should_match_the_closed_form),
        cmocka_unit_test(dense_and_banded_solvers_should_agree),
        cmocka_unit_test(one_element_bar_should_give_its_hand_calculation),
        cmocka_unit_test(graded_per_element_mesh_should_converge_to_the_same_member),
        cmocka_unit_test(omega_max_should_be_the_top_of_the_spectrum),
        cmocka_unit_test(static_deflection_should_match_beam_formulas),
        cmocka_unit_test(banded_newmark_should_equal_the_modal_newmark_solution),
        cmocka_unit_test(modal_response_should_be_the_limit_of_the_direct_run),
        cmocka_unit_test(subspace_iteration_should_match_dense_and_stay_accurate_when_fine),
        cmocka_unit_test(lanczos_should_give_the_bar_meshes_closed_form_frequencies),
        cmocka_unit_test(lanczos_should_give_the_beta_L_frequencies_of_a_fine_beam),
        cmocka_unit_test(lanczos_should_match_the_dense_solver_on_every_support),
        cmocka_unit_test(lanczos_modes_should_have_small_residuals_and_be_M_orthonormal),
        cmocka_unit_test(errors_should_name_the_parameter),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
