/* bar_wave.c — vib-bar-wave: a stress wave in a bar after a sudden end
 * load, by finite elements in space and time, against d'Alembert's exact
 * travelling front.
 *
 *     rho A u_tt = E A u_xx,  u(0, t) = 0,  E A u_x(L, t) = F for t > 0     (1)
 *     sigma(x, t) = (F/A) sum_k (-1)^k [H(ct - (2k+1)L + x) + H(ct - (2k+1)L - x)]   (2)
 *
 * Goal: a step front runs from the loaded end at c = sqrt(E/rho), doubles
 * at the fixed end and comes back; the free end moves at F/(rho A c) and
 * reaches 2FL/(EA), twice the static stretch.  A mesh cannot carry a jump:
 * its short waves travel at the wrong speed (mesh dispersion), consistent
 * mass too fast, lumped mass too slow, and the front comes out smeared
 * with ringing behind it.  Central difference with lumped mass at Courant
 * number C = c h / h_e = 1 is exact at the nodes; just above the limit it
 * is unstable (said, not shown).
 * Checks: the scheme's energy identity over every step (rounding); at
 * C = 1 with lumped mass, the nodal displacements against (2) (rounding).
 * Reference: K.-J. Bathe, Finite Element Procedures, 1996, sec. 9.2;
 * T. Belytschko, T. J. R. Hughes (eds.), Computational Methods for
 * Transient Analysis, North-Holland 1983, ch. 1.
 */
#include <float.h>
#include <math.h>

#include "mm_exhelp.h"
#include "mm_fem.h"
#include "mm_newmark.h"
#include "mm_vib.h"

enum { P_E, P_RHO, P_A, P_L, P_EL, P_F, P_C, P_METHOD, P_AT, P_TRANSITS };
static const char *const methods[] = {"central-difference", "average-acceleration", NULL};

static const mm_param params[] = {
    [P_E] = {"E", "Young's modulus", "Pa", MM_REAL, 2.1e11, 1e6, 1e13, .help = "steel 2.1e11"},
    [P_RHO] = {"rho", "density", "kg/m^3", MM_REAL, 7850, 1, 1e5, .help = "steel 7850"},
    [P_A] = {"A", "cross-section area", "m^2", MM_REAL, 1e-4, 1e-8, 1, .help = "stress is F/A"},
    [P_L] = {"L", "length", "m", MM_REAL, 1, 1e-3, 1e3, .help = "fixed at x = 0, loaded at x = L"},
    [P_EL] = {"elements", "elements", "", MM_INT, 100, 2, 1000, .help = "linear elements of equal length h_e"},
    [P_F] = {"F", "end force", "N", MM_REAL, 1000, -1e7, 1e7, .help = "applied suddenly at t = 0 and held"},
    [P_C] = {"courant", "Courant number", "", MM_REAL, 0.5, 0.01, 3,
             .help = "c h / h_e: the time step in element transit times; central difference is stable up to 1 "
                     "(lumped) and 1/sqrt(3) (consistent)"},
    [P_METHOD] = {"method", "time integrator", "", MM_CHOICE, 0, 0, 0, .choices = methods,
                  .help = "central difference (explicit) or average acceleration (implicit, always stable)"},
    [P_AT] = {"snapshot", "snapshot time", "L/c", MM_REAL, 0.5, 0, 20,
              .help = "when the stress along the bar is shown, in transit times L/c (0.5: the front at mid-bar)"},
    [P_TRANSITS] = {"transits", "duration", "L/c", MM_REAL, 4, 0.1, 20,
                    .help = "simulated time in transit times L/c (4: one period of the free end); steps x "
                            "elements at most 4e6 (the work of a request)"},
};

enum { O_C, O_TRANSIT, O_H, O_HSL, O_HSC, O_UMAX, O_UMAXX, O_EBL, O_EBC, O_SL, O_SC, O_SX, O_UL, O_UC, O_UX,
       O_ANIM };

static const mm_output outputs[] = {
    [O_C] = MM_SCALAR("c", "wave speed sqrt(E/rho)", "m/s", .flags = MM_ANSWER | MM_EXACT),
    [O_TRANSIT] = MM_SCALAR("transit_time", "L/c", "s", .flags = MM_EXACT),
    [O_H] = MM_SCALAR("h", "time step, courant x h_e / c", "s", .flags = MM_EXACT),
    [O_HSL] = MM_SCALAR("courant_limit_lumped", "largest stable Courant number of central difference, lumped "
                        "mass (2 / (omega_max h_e / c))", "", .flags = MM_EXACT),
    [O_HSC] = MM_SCALAR("courant_limit_consistent", "the same, consistent mass", "", .flags = MM_EXACT),
    [O_UMAX] = MM_SCALAR("u_end_max", "largest free-end displacement at the stored steps, the model shown first", "m"),
    [O_UMAXX] = MM_SCALAR("u_end_max_exact", "2 F L / (E A): twice the static stretch", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_EBL] = MM_SCALAR("energy_identity_lumped", "the scheme's energy identity over the run, relative", ""),
    [O_EBC] = MM_SCALAR("energy_identity_consistent", "the same, consistent mass", ""),
    [O_SL] = MM_SERIES("stress_lumped", "stress at the snapshot, lumped mass", "Pa", "x", "m", .figure = "stress",
                       .mark = "step"),
    [O_SC] = MM_SERIES("stress_consistent", "stress at the snapshot, consistent mass", "Pa", "x", "m",
                       .figure = "stress", .mark = "step"),
    [O_SX] = MM_SERIES("stress_exact", "exact stress (2), the travelling front", "Pa", "x", "m", .figure = "stress",
                       .role = "reference"),
    [O_UL] = MM_SERIES("u_end_lumped", "free-end displacement, lumped mass", "m", "t", "s", .figure = "u_end"),
    [O_UC] = MM_SERIES("u_end_consistent", "free-end displacement, consistent mass", "m", "t", "s", .figure = "u_end"),
    [O_UX] = MM_SERIES("u_end_exact", "exact free-end displacement (a triangle wave)", "m", "t", "s",
                       .figure = "u_end", .role = "reference"),
    [O_ANIM] = MM_ANIMATION("the bar and its axial displacement as the wave runs (exact motion)"),
};

/* Eq. (2) and its integral: sigma(x, t) [Pa] and u(x, t) [m]. */
static double exact(double x, double t, double L, double c, double F, double E, double A, double *u)
{
    double s = 0, v = 0, ct = c * t;
    for (int k = 0; (2 * k + 1) * L - x <= ct; k++) {
        double a = (2 * k + 1) * L, sg = k % 2 ? -1 : 1;
        s += sg * ((ct > a - x) + (ct > a + x));
        v += sg * (fmax(0, x - fmax(0, a - ct)) + fmax(0, fmin(x, ct - a)));
    }
    if (u)
        *u = F / (E * A) * v;
    return F / A * s;
}

static int check(const mm_value *in, mm_error *err)
{
    double steps = ceil(in[P_TRANSITS].x * in[P_EL].x / in[P_C].x);
    if (steps * in[P_EL].x > 4e6)
        return mm_error_set(err, MM_ERANGE, "courant", "%.0f steps of %g elements are too much work for one "
                            "request (steps x elements at most 4e6): raise courant, or lower elements or "
                            "transits", steps, in[P_EL].x);
    if (in[P_AT].x > in[P_TRANSITS].x)
        return mm_error_set(err, MM_ERANGE, "snapshot", "the snapshot must fall within the run (at most %g)",
                            in[P_TRANSITS].x);
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    const double E = in[P_E].x, rho = in[P_RHO].x, A = in[P_A].x, L = in[P_L].x, F = in[P_F].x;
    const double c = sqrt(E / rho), T = L / c, C = in[P_C].x, eps = DBL_EPSILON;
    const int n_el = (int)in[P_EL].x, method = (int)in[P_METHOD].x;
    const double he = L / n_el, h = C * he / c;
    const long steps = (long)ceil(in[P_TRANSITS].x * T / h * (1 - 1e-12)), snap = lround(in[P_AT].x * T / h);
    mm_res_scalar(res, O_C, c);
    mm_res_scalar(res, O_TRANSIT, T);
    mm_res_scalar(res, O_H, h);
    mm_res_scalar(res, O_UMAXX, 2 * F * L / (E * A));
    mm_fem_load ld = {MM_FEM_LOAD_POINT, F, L, 0, INFINITY, 0};
    mm_newmark_options o;
    mm_newmark_options_init(&o);
    o.method = method ? MM_NEWMARK_AVERAGE : MM_NEWMARK_CENTRAL;
    o.h = h;

    /* the history: every stride-th step, about 150 points; where a round
     * trip 2L/c is a whole number of steps, a divisor of it, so that the
     * largest displacement falls on a stored step */
    long stride = steps / 150 + 1, trip = lround(2 * n_el / C);
    if (fabs(2 * n_el / C - trip) < 1e-9 * trip)
        while (trip % stride)
            stride--;
    int rows = (int)(steps / stride) + 1, shown = 0, rc;
    size_t tip = (size_t)n_el;
    mm_series *ux = mm_res_series(res, O_UX, rows), *sx = mm_res_series(res, O_SX, n_el);
    if (!ux || !sx)
        return MM_ENOMEM;
    for (int i = 0; i < rows; i++) {
        ux->x[i] = i * stride * h;
        exact(L, ux->x[i], L, c, F, E, A, &ux->y[i]);
    }
    for (int e = 0; e < n_el; e++) {                 /* at element midpoints */
        sx->x[e] = (e + 0.5) * he;
        sx->y[e] = exact(sx->x[e], snap * h, L, c, F, E, A, NULL);
    }
    for (int k = 0; k < 2; k++) {                    /* 0 lumped, 1 consistent */
        mm_fem_problem p = {MM_FEM_BAR, MM_FEM_FIXED_FREE, k ? MM_FEM_CONSISTENT : MM_FEM_LUMPED, (size_t)n_el,
                            {L, E, A, 0, rho}, NULL};
        double wmax;
        if ((rc = mm_fem_omega_max(&p, &wmax, err)))
            return rc;
        mm_res_scalar(res, k ? O_HSC : O_HSL, 2 / (wmax * he / c));
        if (!method && wmax * h >= 2) {                /* unstable: said, not shown */
            mm_res_warn(res, "central difference with %s mass is unstable at courant = %g (its limit is %.6g): the "
                             "highest mode grows by a factor %.4g every step, so its response is not shown",
                        k ? "consistent" : "lumped", C, 2 / (wmax * he / c),
                        mm_newmark_spectral_radius(&o, wmax, 0));
            continue;
        }
        double *hist = mm_res_alloc(res, (size_t)rows * sizeof *hist);
        double *field = mm_res_alloc(res, (size_t)(n_el + 1) * sizeof *field);
        mm_series *us = mm_res_series(res, k ? O_UC : O_UL, rows), *ss = mm_res_series(res, k ? O_SC : O_SL, n_el);
        if (!hist || !field || !us || !ss)
            return MM_ENOMEM;
        mm_fem_transient tr = {method ? MM_FEM_AVERAGE : MM_FEM_CENTRAL, h, steps, {0, 0}, stride, 1, &tip, hist,
                               1, &snap, field, 0};
        if ((rc = mm_fem_transient_solve(&p, &ld, &tr, err)))
            return rc;
        double umax = 0;
        for (int i = 0; i < rows; i++) {
            us->x[i] = ux->x[i], us->y[i] = hist[i];
            umax = fmax(umax, fabs(hist[i]));
        }
        for (int e = 0; e < n_el; e++)
            ss->x[e] = sx->x[e], ss->y[e] = E * (field[e + 1] - field[e]) / he;
        if (!shown++)
            mm_res_scalar_err(res, O_UMAX, copysign(umax, F), fabs(umax - 2 * fabs(F) * L / (E * A)), MM_ERR_BOUND);
        /* the energy identity of the scheme, step by step: rounding */
        mm_res_scalar_err(res, k ? O_EBC : O_EBL, tr.energy_balance, 64 * eps * steps, MM_ERR_ESTIMATE);
        mm_res_check_abs(res, k ? "consistent mass: the scheme's energy identity over every step, relative (rounding)"
                                : "lumped mass: the scheme's energy identity over every step, relative (rounding)",
                         tr.energy_balance, 0, 64 * eps * (steps + 10));
        if (!k && !method && C == 1) {
            /* at C = 1 the lumped mesh is exact at the nodes, eq. (5) */
            double worst = 0, big = 0, ue;
            for (int i = 0; i <= n_el; i++) {
                exact(i * he, snap * h, L, c, F, E, A, &ue);
                worst = fmax(worst, fabs(field[i] - ue));
                big = fmax(big, fabs(ue));
            }
            mm_res_check_abs(res, "courant = 1, lumped mass: nodal displacements at the snapshot vs (2) [m] "
                                  "(rounding: the mesh is exact at the nodes)", worst, 0, 64 * eps * snap * big +
                             1e-300);
        }
    }
    if (!shown)
        mm_res_warn(res, "no model is stable at this courant number with central difference: lower courant "
                         "below 1 (lumped) or 0.577 (consistent), or take average-acceleration");

    /* the exact motion: 24 frames over one period of the free end (4 L/c),
     * on 20 intervals */
    enum { NF = 24 };
    mm_anim *a = mm_res_animation(res, NF, "t", "s");
    mm_fem_problem pd = {MM_FEM_BAR, MM_FEM_FIXED_FREE, MM_FEM_LUMPED, 20,
                         {L, E, A, 0, rho}, NULL};
    int nd = (int)pd.n_el + 1;
    double *u = mm_res_alloc(res, (size_t)NF * nd * sizeof *u);
    if (!a || !u)
        return MM_ENOMEM;
    for (int f = 0; f < NF; f++) {
        a->t[f] = 4 * T * f / (NF - 1);
        for (int i = 0; i < nd; i++)
            exact(L * i / (nd - 1), a->t[f], L, c, F, E, A, &u[f * nd + i]);
    }
    return mm_vib_member_draw(res, &pd, NF, u, 0.1 * L / (2 * fabs(F) * L / (E * A)));
}

static const char *const references[] = {
    "K.-J. Bathe, Finite Element Procedures, Prentice Hall 1996, section 9.2",
    "T. Belytschko, T. J. R. Hughes (eds.), Computational Methods for Transient Analysis, North-Holland 1983, ch. 1",
    NULL,
};

const mm_exercise mm_ex_vib_bar_wave = {
    .id = "vib-bar-wave", .chapter = 5, .section = "5.12.1",
    .title = "A stress wave in a bar: mesh dispersion and the Courant number",
    .summary = "A sudden end load on a bar: the exact travelling front against finite elements, lumped and consistent.",
    .tags = "vibration, waves, bar, finite elements, central difference, Courant number, dispersion",
    .theory = "exercises/vib/bar_wave.md", .params = params, .n_params = MM_COUNT(params), .outputs = outputs,
    .n_outputs = MM_COUNT(outputs), .references = references, .check = check, .solve = solve,
};
