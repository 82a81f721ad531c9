/* bar_modes.c — vib-bar-modes: the axial natural frequencies of a bar by
 * finite elements, against the exact ones of the continuum.
 *
 *     rho A u_tt = E A u_xx,   omega_n = n pi c / L (fixed-fixed, free-free),
 *     (2n - 1) pi c / (2L) (fixed-free),  c = sqrt(E / rho)                   (1)
 *
 * Goal: linear elements with consistent mass give frequencies above the
 * exact ones, with lumped mass below, both converging like h^2 (fitted on
 * log axes); a free-free bar has one rigid-body mode (omega = 0), counted
 * and left out of the table.  The FE frequencies of a uniform bar are also
 * known in closed form (the dispersion relation of the mesh, eq. 4), so the
 * eigen solver is checked to rounding and the discretisation error is
 * exact.  Only the modes shown are computed once the mesh is large (the
 * banded selective solver); the page says which ran.
 * Reference: T. J. R. Hughes, The Finite Element Method, Dover 2000, sec. 9.2.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "mm_exhelp.h"
#include "mm_fem.h"
#include "mm_vib.h"

enum { P_E, P_RHO, P_A, P_L, P_EL, P_BC, P_MASS, P_MODES, P_MODE };
static const char *const bcs[] = {"fixed-free", "fixed-fixed", "free-free", NULL};
static const char *const masses[] = {"consistent", "lumped", NULL};

static const mm_param params[] = {
    [P_E] = {"E", "Young's modulus", "Pa", MM_REAL, 2.1e11, 1e6, 1e13, .help = "steel 2.1e11, aluminium 7e10"},
    [P_RHO] = {"rho", "density", "kg/m^3", MM_REAL, 7850, 1, 1e5, .help = "steel 7850, aluminium 2700"},
    [P_A] = {"A", "cross-section area", "m^2", MM_REAL, 1e-4, 1e-8, 1, .help = "does not change the frequencies"},
    [P_L] = {"L", "length", "m", MM_REAL, 1, 1e-3, 1e3, .help = "the bar's length"},
    [P_EL] = {"elements", "elements", "", MM_INT, 20, 1, 1000, .help = "linear elements of equal length"},
    [P_BC] = {"bc", "ends", "", MM_CHOICE, 0, 0, 0, .choices = bcs,
              .help = "fixed-free: held at x = 0; free-free has a rigid-body mode"},
    [P_MASS] = {"mass", "mass matrix", "", MM_CHOICE, 0, 0, 0, .choices = masses,
                .help = "consistent (from the shape functions) or lumped (half of each element at each node)"},
    [P_MODES] = {"modes", "modes shown", "", MM_INT, 5, 1, 100,
                 .help = "the lowest elastic modes computed and tabulated"},
    [P_MODE] = {"mode", "mode animated", "", MM_INT, 1, 1, 100, .help = "which of the modes shown is animated"},
};

enum { O_W1, O_W1X, O_RIGID, O_SLOPE_C, O_SLOPE_L, O_MODES, O_MASSES, O_CONV_C, O_CONV_L, O_ANIM };
static const char *const mcols[] = {"mode", "omega", "omega_exact", "rel_error", NULL};
static const char *const munits[] = {"", "rad/s", "rad/s", "", NULL};
static const char *const ccols[] = {"mode", "omega_consistent", "omega_lumped", "omega_exact", NULL};
static const char *const cunits[] = {"", "rad/s", "rad/s", "rad/s", NULL};

static const mm_output outputs[] = {
    [O_W1] = MM_SCALAR("omega1", "lowest elastic frequency, finite elements", "rad/s", .flags = MM_ANSWER),
    [O_W1X] = MM_SCALAR("omega1_exact", "lowest elastic frequency of the continuum, eq. (1)", "rad/s",
                        .flags = MM_ANSWER | MM_EXACT),
    [O_RIGID] = MM_SCALAR("rigid_modes", "rigid-body modes, left out of the table", "", .flags = MM_EXACT),
    [O_SLOPE_C] = MM_SCALAR("slope_consistent", "fitted order of convergence, consistent mass (h^2)", ""),
    [O_SLOPE_L] = MM_SCALAR("slope_lumped", "fitted order of convergence, lumped mass (h^2)", ""),
    [O_MODES] = MM_TABLE("modes", "natural frequencies: finite elements and exact", mcols, munits),
    [O_MASSES] = MM_TABLE("mass_models", "consistent against lumped mass, same mesh (up to 10 modes)", ccols, cunits),
    [O_CONV_C] = MM_SERIES("convergence_consistent", "|rel. error| of omega1, consistent mass", "", "elements", "",
                           .figure = "convergence", .mark = "dots", .x_scale = "log", .y_scale = "log"),
    [O_CONV_L] = MM_SERIES("convergence_lumped", "|rel. error| of omega1, lumped mass", "", "elements", "",
                           .figure = "convergence", .mark = "dots", .x_scale = "log", .y_scale = "log"),
    [O_ANIM] = MM_ANIMATION("the bar vibrating in the chosen mode (axial displacement, exaggerated)"),
};

static mm_fem_problem problem(const mm_value *in, mm_fem_mass mass, size_t n_el)
{
    static const mm_fem_bc bc[] = {MM_FEM_FIXED_FREE, MM_FEM_FIXED_FIXED, MM_FEM_FREE_FREE};
    return (mm_fem_problem){MM_FEM_BAR, bc[(int)in[P_BC].x], mass, n_el,
                            {in[P_L].x, in[P_E].x, in[P_A].x, 0, in[P_RHO].x}, NULL};
}

static int check(const mm_value *in, mm_error *err)
{
    int n = (int)in[P_EL].x, bc = (int)in[P_BC].x, m = (int)in[P_MODES].x;
    int have = bc == 1 ? n - 1 : n;                 /* elastic modes of the mesh */
    if (bc == 1 && n < 2)
        return mm_error_set(err, MM_ERANGE, "elements", "a fixed-fixed bar of one element has no free node; "
                            "take at least 2 elements");
    if (m > have)
        return mm_error_set(err, MM_ERANGE, "modes", "%d elements give %d elastic modes; make modes at most %d "
                            "or add elements", n, have, have);
    if (in[P_MODE].x > m)
        return mm_error_set(err, MM_ERANGE, "mode", "mode must be one of the %d modes shown", m);
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    const int nm = (int)in[P_MODES].x, mass = (int)in[P_MASS].x, no = nm < 10 ? nm : 10;
    const size_t n_el = (size_t)in[P_EL].x;
    const double c = sqrt(in[P_E].x / in[P_RHO].x), eps = DBL_EPSILON;
    mm_fem_problem p = problem(in, mass ? MM_FEM_LUMPED : MM_FEM_CONSISTENT, n_el);
    size_t nd = mm_fem_ndof(&p);
    double *w[2], *ex = mm_res_alloc(res, nm * sizeof *ex), *shape = mm_res_alloc(res, nm * nd * sizeof *shape);
    w[0] = mm_res_alloc(res, nm * sizeof *w[0]);
    w[1] = mm_res_alloc(res, nm * sizeof *w[1]);
    if (!ex || !shape || !w[0] || !w[1])
        return MM_ENOMEM;
    mm_fem_modes md = {0}, other = {w[!mass], NULL, 0, 0, 0, MM_FEM_AUTO};
    md.omega = w[mass], md.shape = shape;
    mm_fem_problem po = problem(in, mass ? MM_FEM_CONSISTENT : MM_FEM_LUMPED, n_el);
    int rc;
    if ((rc = mm_fem_modes_solve(&p, (size_t)nm, NULL, &md, err)) ||
        (rc = mm_fem_modes_solve(&po, (size_t)no, NULL, &other, err)) ||
        (rc = mm_fem_exact_omegas(&p, (size_t)nm, ex, err)))
        return rc;
    mm_res_method(res, mm_vib_fem_method(md.method), 0);
    mm_res_method_stat(res, "free_dofs", (double)md.n_free);

    /* eq. (4), the mesh's dispersion relation (mm_fem_bar_omega), against the
     * eigen solver: rounding, eps lambda_max / lambda_j */
    mm_table *t = mm_res_table(res, O_MODES, nm), *tm = mm_res_table(res, O_MASSES, no);
    if (!t || !tm)
        return MM_ENOMEM;
    double top = 2 * c * n_el / p.uniform.L, worst = 0, order = 0;
    for (int j = 0; j < nm; j++) {
        const double *wj = w[mass];
        double row[4] = {j + 1, wj[j], ex[j], wj[j] / ex[j] - 1}, row2[4] = {j + 1, w[0][j], w[1][j], ex[j]};
        memcpy(t->cell + 4 * j, row, sizeof row);
        if (j < no)
            memcpy(tm->cell + 4 * j, row2, sizeof row2);
        for (int k = 0; k < 2; k++) {
            if (k != mass && j >= no)
                continue;
            mm_fem_problem pk = problem(in, k ? MM_FEM_LUMPED : MM_FEM_CONSISTENT, n_el);
            double f = mm_fem_bar_omega(&pk, j + 1);
            /* each model's own omega_max: consistent mass sqrt(3) x lumped's; 64 eps
             * for dsygvd's rounding (measured to 1.5 x 16 eps over 200 draws) */
            mm_fem_method mk = (k == mass ? md : other).method;
            double tk = k ? top : sqrt(3.0) * top, sub = mk == MM_FEM_SUBSPACE || mk == MM_FEM_LANCZOS;
            /* subspace iteration's and Lanczos' Ritz values jitter at ~1e-12 (mm_fem.c): 1e-11 more */
            worst = fmax(worst, fabs(w[k][j] / f - 1) / (64 * eps * (tk * tk) / (f * f) + (sub ? 1e-11 : 0)));
            /* Rayleigh-Ritz: consistent above the exact, lumped below (eq. 5) */
            order = fmax(order, k ? w[1][j] - ex[j] : ex[j] - w[0][j]);   /* the other model: first 10 */
        }
    }
    mm_res_check_abs(res, "FE frequencies vs their closed form (4), both mass models: worst rel. error over the "
                          "rounding bound 64 eps omega_max^2 / omega_j^2 (+ 1e-11 by subspace iteration or Lanczos)", worst, 0, 1);
    mm_res_check_abs(res, "consistent mass above the exact frequencies, lumped below (5) [rad/s]", fmax(order, 0), 0,
                     16 * eps * top);
    mm_res_scalar_err(res, O_W1, w[mass][0], fabs(w[mass][0] - ex[0]), MM_ERR_BOUND);
    mm_res_scalar(res, O_W1X, ex[0]);
    mm_res_scalar(res, O_RIGID, (double)md.n_rigid);

    /* convergence of omega1 with the mesh, 4 .. 128 elements, both masses:
     * the fitted slope of log |error| against log h, eq. (6) */
    enum { NC = 6 };
    static const int mesh[NC] = {4, 8, 16, 32, 64, 128};
    mm_series *sc[2] = {mm_res_series(res, O_CONV_C, NC), mm_res_series(res, O_CONV_L, NC)};
    if (!sc[0] || !sc[1])
        return MM_ENOMEM;
    for (int k = 0; k < 2; k++) {
        double h[NC], e[NC];
        mm_fem_problem pc = problem(in, k ? MM_FEM_LUMPED : MM_FEM_CONSISTENT, n_el);
        if ((rc = mm_fem_omega1_errors(&pc, NC, mesh, ex[0], h, e, err)))
            return rc;
        for (int i = 0; i < NC; i++)
            sc[k]->x[i] = mesh[i], sc[k]->y[i] = e[i];
        double sl = mm_check_order(res, k ? "lumped mass: fitted order of omega1's error vs 2 (h^2)"
                                          : "consistent mass: fitted order of omega1's error vs 2 (h^2)",
                                   NC, h, e, 2, 0.05);
        /* its error: the fit against the slope of the two finest meshes */
        mm_res_scalar_err(res, k ? O_SLOPE_L : O_SLOPE_C, sl, fabs(sl - log(e[NC - 2] / e[NC - 1]) / log(2)),
                          MM_ERR_ESTIMATE);
    }

    /* the chosen mode, one period in 16 frames; the largest axial
     * displacement drawn as a fifth of the length */
    int j = (int)in[P_MODE].x - 1;
    double big = mm_vib_big(shape + j * nd, nd);
    return mm_vib_member_mode(res, &p, shape + j * nd, w[mass][j], 16, 0.2 * p.uniform.L / big);
}

static const char *const references[] = {
    "T. J. R. Hughes, The Finite Element Method, Dover 2000, sections 7.3 and 9.2",
    "R. D. Cook, D. S. Malkus, M. E. Plesha, R. J. Witt, Concepts and Applications of Finite Element Analysis, "
    "4th ed., Wiley 2002, ch. 11",
    NULL,
};

const mm_exercise mm_ex_vib_bar_modes = {
    .id = "vib-bar-modes", .chapter = 5, .section = "5.12.1", .title = "Axial vibration of a bar by finite elements",
    .summary = "Natural frequencies of a bar from linear elements, consistent and lumped mass, against n pi c / L.",
    .tags = "vibration, continuous systems, bar, finite elements, consistent mass, lumped mass, convergence",
    .theory = "exercises/vib/bar_modes.md", .params = params, .n_params = MM_COUNT(params), .outputs = outputs,
    .n_outputs = MM_COUNT(outputs), .references = references, .check = check, .solve = solve,
};
