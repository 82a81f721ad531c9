/* beam_modes.c — vib-beam-modes: the bending natural frequencies of a beam
 * by Hermite finite elements, against the roots of the beam's frequency
 * equation.
 *
 *     rho A w_tt + E I w_xxxx = 0,   omega_n = (beta_n L)^2 sqrt(E I / (rho A L^4))     (1)
 *     cantilever: cos bL cosh bL = -1;  clamped-clamped, free-free: cos bL cosh bL = 1;
 *     simply supported: sin bL = 0, bL = n pi                                         (2)
 *
 * Goal: cubic elements with consistent mass give frequencies above the
 * exact ones converging like h^4 (fitted on log axes); the roots beta_n L
 * are computed to rounding by Newton's method, not typed in (and checked in
 * their equation); a free-free beam has two rigid-body modes, counted and
 * left out.  Only the modes shown are computed (shift-invert Lanczos on
 * the banded K and M, mm_fem), a 1000-element beam in milliseconds.
 * Reference: R. D. Blevins, Formulas for Natural Frequency and Mode Shape,
 * Krieger 1979, table 8-1; T. J. R. Hughes, The Finite Element Method, ch. 9.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "mm_exhelp.h"
#include "mm_fem.h"
#include "mm_vib.h"

enum { P_E, P_I, P_RHO, P_A, P_L, P_EL, P_BC, P_MODES, P_MODE };
static const char *const bcs[] = {"cantilever", "simply-supported", "clamped-clamped", "free-free", NULL};
static const mm_fem_bc fem_bc[] = {MM_FEM_FIXED_FREE, MM_FEM_PINNED_PINNED, MM_FEM_FIXED_FIXED, MM_FEM_FREE_FREE};

static const mm_param params[] = {
    [P_E] = {"E", "Young's modulus", "Pa", MM_REAL, 2.1e11, 1e6, 1e13, .help = "steel 2.1e11, aluminium 7e10"},
    [P_I] = {"I", "second moment of area", "m^4", MM_REAL, 1e-8, 1e-16, 1, .help = "of the cross-section, about "
             "the bending axis"},
    [P_RHO] = {"rho", "density", "kg/m^3", MM_REAL, 7850, 1, 1e5, .help = "steel 7850, aluminium 2700"},
    [P_A] = {"A", "cross-section area", "m^2", MM_REAL, 1e-4, 1e-8, 1, .help = "carries the mass per length rho A"},
    [P_L] = {"L", "length", "m", MM_REAL, 1, 1e-3, 1e3, .help = "the beam's span"},
    [P_EL] = {"elements", "elements", "", MM_INT, 20, 1, 1000, .help = "Hermite cubic elements of equal length"},
    [P_BC] = {"bc", "supports", "", MM_CHOICE, 0, 0, 0, .choices = bcs,
              .help = "cantilever: clamped at x = 0; free-free has two rigid-body modes"},
    [P_MODES] = {"modes", "modes shown", "", MM_INT, 5, 1, 100,
                 .help = "the lowest elastic modes computed; modes x elements at most 30000 (the solver's work)"},
    [P_MODE] = {"mode", "mode animated", "", MM_INT, 1, 1, 100, .help = "which of the modes shown is animated"},
};

enum { O_W1, O_W1X, O_RIGID, O_SLOPE, O_MODES, O_CONV, O_ANIM };
static const char *const mcols[] = {"mode", "omega", "omega_exact", "rel_error", "beta_L", NULL};
static const char *const munits[] = {"", "rad/s", "rad/s", "", "", NULL};

static const mm_output outputs[] = {
    [O_W1] = MM_SCALAR("omega1", "lowest elastic frequency, finite elements", "rad/s", .flags = MM_ANSWER),
    [O_W1X] = MM_SCALAR("omega1_exact", "lowest elastic frequency of the continuum, eq. (1)", "rad/s",
                        .flags = MM_ANSWER | MM_EXACT),
    [O_RIGID] = MM_SCALAR("rigid_modes", "rigid-body modes, left out of the table", "", .flags = MM_EXACT),
    [O_SLOPE] = MM_SCALAR("slope", "fitted order of convergence of omega1 (h^4)", ""),
    [O_MODES] = MM_TABLE("modes", "natural frequencies: finite elements and exact", mcols, munits),
    [O_CONV] = MM_SERIES("convergence", "|rel. error| of omega1", "", "elements", "", .mark = "dots",
                         .x_scale = "log", .y_scale = "log"),
    [O_ANIM] = MM_ANIMATION("the beam vibrating in the chosen mode (deflection exaggerated)"),
};

static mm_fem_problem problem(const mm_value *in, size_t n_el)
{
    return (mm_fem_problem){MM_FEM_BEAM, fem_bc[(int)in[P_BC].x], MM_FEM_CONSISTENT, n_el,
                            {in[P_L].x, in[P_E].x, in[P_A].x, in[P_I].x, in[P_RHO].x}, NULL};
}

static int check(const mm_value *in, mm_error *err)
{
    int n = (int)in[P_EL].x, bc = (int)in[P_BC].x, m = (int)in[P_MODES].x;
    int have = bc == 0 ? 2 * n : bc == 1 ? 2 * n : bc == 2 ? 2 * n - 2 : 2 * n;   /* elastic modes */
    if (bc == 2 && n < 2)
        return mm_error_set(err, MM_ERANGE, "elements", "a clamped-clamped beam of one element has no free node; "
                            "take at least 2 elements");
    if (m > have)
        return mm_error_set(err, MM_ERANGE, "modes", "%d elements give %d elastic modes; make modes at most %d "
                            "or add elements", n, have, have);
    if (in[P_MODE].x > m)
        return mm_error_set(err, MM_ERANGE, "mode", "mode must be one of the %d modes shown", m);
    if ((double)m * n > 3e4)     /* inverse iteration: work ~ modes^2 x elements */
        return mm_error_set(err, MM_ERANGE, "modes", "%d modes of %d elements take too long for one request "
                            "(modes x elements at most 30000): make modes at most %d", m, n, 30000 / n);
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    const int nm = (int)in[P_MODES].x, bc = (int)in[P_BC].x;
    const size_t n_el = (size_t)in[P_EL].x;
    const double eps = DBL_EPSILON;
    mm_fem_problem p = problem(in, n_el);
    size_t nd = mm_fem_ndof(&p);
    double *w = mm_res_alloc(res, nm * sizeof *w), *ex = mm_res_alloc(res, nm * sizeof *ex);
    double *shape = mm_res_alloc(res, nm * nd * sizeof *shape);
    if (!w || !ex || !shape)
        return MM_ENOMEM;
    mm_fem_modes md = {w, shape, 0, 0, 0, MM_FEM_AUTO};
    int rc;
    if ((rc = mm_fem_modes_solve(&p, (size_t)nm, NULL, &md, err)) || (rc = mm_fem_exact_omegas(&p, (size_t)nm, ex, err)))
        return rc;
    mm_res_method(res, mm_vib_fem_method(md.method), 0);
    mm_res_method_stat(res, "free_dofs", (double)md.n_free);

    /* the roots of eq. (2), Newton's method to rounding; each checked in
     * its equation divided by cosh bL (its terms stay of size 1) */
    mm_table *t = mm_res_table(res, O_MODES, nm);
    if (!t)
        return MM_ENOMEM;
    double scale = sqrt(p.uniform.E * p.uniform.I / (p.uniform.rho * p.uniform.A)) / (p.uniform.L * p.uniform.L);
    /* the rounding an eigen solver leaves in mode j: eps lambda_max / lambda_j
     * relative on lambda, half that on omega; lambda_max / lambda_1 grows
     * like n^4 for a beam */
    double wtop = mm_fem_omega_bound(&p), resid = 0, above = 0;
    for (int j = 0; j < nm; j++) {
        double bl = sqrt(ex[j] / scale), f = 0;
        if (bc == 0)
            f = cos(bl) + 1 / cosh(bl);
        else if (bc == 1)
            f = sin(bl) / bl;
        else
            f = cos(bl) - 1 / cosh(bl);
        resid = fmax(resid, fabs(f) / bl);
        double row[5] = {j + 1, w[j], ex[j], w[j] / ex[j] - 1, bl};
        memcpy(t->cell + 5 * j, row, sizeof row);
        above = fmax(above, (ex[j] - w[j]) / ex[j] / (eps * (wtop / ex[j]) * (wtop / ex[j])));
    }
    /* a root good to rounding leaves f(bL) ~ eps bL (the slope of f is ~1) */
    mm_check_residual(res, "roots beta_n L in their frequency equation (2): worst |f(bL)| / bL", resid, 1, 8);
    /* Rayleigh-Ritz: consistent mass gives every frequency from above, but
     * for the solver's rounding */
    mm_res_check_abs(res, "finite elements above the exact frequencies (Rayleigh-Ritz), but for rounding: worst "
                          "(exact - FE)/exact over eps omega_max^2 / omega_j^2", fmax(above, 0), 0, 1);
    /* off the continuum by the discretisation, and off the exact FE value by
     * up to the rounding of a dense eigen solver, eps omega_max^2 / omega_1^2 / 2 */
    double rb1 = 0.5 * eps * (wtop / ex[0]) * (wtop / ex[0]);
    mm_res_scalar_err(res, O_W1, w[0], fabs(w[0] - ex[0]) + rb1 * w[0], MM_ERR_BOUND);
    mm_res_scalar(res, O_W1X, ex[0]);
    mm_res_scalar(res, O_RIGID, (double)md.n_rigid);

    /* convergence of omega1: 4 .. 64 elements, fitted slope of log |error|
     * against log h, eq. (3): h^4 */
    enum { NC = 5 };
    static const int mesh[NC] = {4, 8, 16, 32, 64};
    mm_series *sc = mm_res_series(res, O_CONV, NC);
    if (!sc)
        return MM_ENOMEM;
    double h[NC], e[NC];
    if ((rc = mm_fem_omega1_errors(&p, NC, mesh, ex[0], h, e, err)))
        return rc;
    for (int i = 0; i < NC; i++)
        sc->x[i] = mesh[i], sc->y[i] = e[i];
    double sl = mm_check_order(res, "fitted order of omega1's error vs 4 (h^4)", NC, h, e, 4, 0.2);
    mm_res_scalar_err(res, O_SLOPE, sl, fabs(sl - log(e[NC - 2] / e[NC - 1]) / log(2)), MM_ERR_ESTIMATE);
    double disc = e[NC - 1] * pow(64.0 / n_el, 4);
    if (rb1 > disc && md.method == MM_FEM_BANDED)   /* subspace iteration keeps ~1e-12 */
        mm_res_warn(res, "with %zu elements the eigen solver's rounding may reach %.2g of omega1 (eps "
                         "omega_max^2 / omega_1^2: it grows like elements^4), more than the discretisation error "
                         "left (about %.2g, h^4): a finer mesh makes omega1 worse, not better", n_el, rb1, disc);

    /* the chosen mode, one period in 16 frames; the largest deflection
     * drawn as a tenth of the span */
    int j = (int)in[P_MODE].x - 1;
    double big = 0;
    for (size_t g = 0; g < nd; g += 2)
        big = fmax(big, fabs(shape[j * nd + g]));
    return mm_vib_member_mode(res, &p, shape + j * nd, w[j], 16, 0.1 * p.uniform.L / big);
}

static const char *const references[] = {
    "R. D. Blevins, Formulas for Natural Frequency and Mode Shape, Krieger 1979, table 8-1",
    "T. J. R. Hughes, The Finite Element Method, Dover 2000, ch. 9",
    NULL,
};

const mm_exercise mm_ex_vib_beam_modes = {
    .id = "vib-beam-modes", .chapter = 5, .section = "5.12.2",
    .title = "Bending vibration of a beam by finite elements",
    .summary = "Natural frequencies of a beam from Hermite elements against the roots beta L of its frequency equation.",
    .tags = "vibration, continuous systems, beam, finite elements, Euler-Bernoulli, convergence",
    .theory = "exercises/vib/beam_modes.md", .params = params, .n_params = MM_COUNT(params), .outputs = outputs,
    .n_outputs = MM_COUNT(outputs), .references = references, .check = check, .solve = solve,
};
