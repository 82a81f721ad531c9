/* beam_transient.c — vib-beam-transient: a beam under a moving force or a
 * sudden (impact) load, by modal superposition with the modes one keeps and
 * by direct integration of the finite-element model.
 *
 *     M w'' + (a M + b K) w' + K w = f(t)                                   (1)
 *     w ~ sum_{j <= m} phi_j eta_j,  eta_j'' + c_j eta_j' + omega_j^2 eta_j = phi_j^T f(t)   (2)
 *     r(t) = K^-1 f(t) - sum_{j <= m} phi_j phi_j^T f(t) / omega_j^2                     (3)
 *
 * Goal: a force crossing a bridge, or suddenly applied, excites the beam's
 * modes; a few modes carry most of the motion, the rest mostly a static
 * correction r (3); direct integration (Newmark average acceleration, all
 * DOFs, banded) carries every mode but with a phase error.  Each modal
 * coordinate is integrated exactly: a point load by its closed form, a
 * moving load through the cubic modal force of each element it crosses.
 * Checks: the direct run against the superposition of every mode's
 * Newmark recursion (where all modes are computed, up to 100 free DOFs),
 * and the scheme's energy identity, both to rounding.
 * Reference: L. Fryba, Vibration of Solids and Structures under Moving
 * Loads, Thomas Telford 1999, ch. 1; R. W. Clough, J. Penzien, Dynamics of
 * Structures, ch. 12-13.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "mm_exhelp.h"
#include "mm_fem.h"
#include "mm_newmark.h"
#include "mm_vib.h"

enum { P_E, P_I, P_RHO, P_A, P_L, P_BC, P_EL, P_LOAD, P_P, P_X, P_V, P_TD, P_ALPHA, P_BETA, P_MODES, P_H,
       P_TEND, P_PROBE, P_POINTS };
static const char *const bcs[] = {"simply-supported", "cantilever", "clamped-clamped", NULL};
static const mm_fem_bc fem_bc[] = {MM_FEM_PINNED_PINNED, MM_FEM_FIXED_FREE, MM_FEM_FIXED_FIXED};
static const char *const loads[] = {"moving", "step", "pulse", NULL};

static const mm_param params[] = {
    [P_E] = {"E", "Young's modulus", "Pa", MM_REAL, 2.1e11, 1e6, 1e13, .help = "steel 2.1e11"},
    [P_I] = {"I", "second moment of area", "m^4", MM_REAL, 1e-8, 1e-16, 1, .help = "of the cross-section"},
    [P_RHO] = {"rho", "density", "kg/m^3", MM_REAL, 7850, 1, 1e5, .help = "steel 7850"},
    [P_A] = {"A", "cross-section area", "m^2", MM_REAL, 1e-4, 1e-8, 1, .help = "the mass per length is rho A"},
    [P_L] = {"L", "length", "m", MM_REAL, 1, 1e-3, 1e3, .help = "the span"},
    [P_BC] = {"bc", "supports", "", MM_CHOICE, 0, 0, 0, .choices = bcs, .help = "cantilever: clamped at x = 0"},
    [P_EL] = {"elements", "elements", "", MM_INT, 20, 2, 1000, .help = "Hermite cubic elements"},
    [P_LOAD] = {"load", "load", "", MM_CHOICE, 0, 0, 0, .choices = loads,
                .help = "moving: P crosses at speed v; step: P applied at t = 0 and held; pulse: held for t_d"},
    [P_P] = {"P", "force", "N", MM_REAL, -100, -1e6, 1e6, .help = "transverse, positive up"},
    [P_X] = {"a", "load position", "L", MM_REAL, 0.5, 0, 1, .help = "where the step or pulse acts, as a fraction "
             "of L"},
    [P_V] = {"v", "speed of the moving force", "m/s", MM_REAL, 40, 1e-3, 1e5, .help = "it enters at x = 0 at t = 0"},
    [P_TD] = {"t_d", "pulse duration", "s", MM_REAL, 1e-3, 1e-7, 1e3, .help = "how long the pulse lasts"},
    [P_ALPHA] = {"alpha", "mass-proportional damping a", "1/s", MM_REAL, 2, 0, 1e4, .help = "C = a M + b K"},
    [P_BETA] = {"beta", "stiffness-proportional damping b", "s", MM_REAL, 0, 0, 1, .help = "damps the high modes"},
    [P_MODES] = {"modes", "modes retained", "", MM_INT, 10, 1, 100, .help = "the modal sum keeps the lowest m"},
    [P_H] = {"h", "Newmark step", "s", MM_REAL, 5e-5, 1e-8, 1, .help = "the step of the direct integration; "
             "a moving load must be on the span at t = h: h < L/v"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 0.05, 1e-6, 1e3,
                .help = "simulated time; steps x elements at most 2e6 (the direct run's work)"},
    [P_PROBE] = {"probe", "point shown", "L", MM_REAL, 0.5, 0, 1, .help = "where the deflection is plotted"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 201, 11, 2001, .help = "times returned for the plot"},
};

enum { O_W1, O_WST, O_WMAX, O_DAF, O_TRUNC, O_TEST, O_TERR, O_EB, O_SD, O_SM, O_SE, O_SR, O_ANIM };

static const mm_output outputs[] = {
    [O_W1] = MM_SCALAR("omega1", "lowest natural frequency of the mesh", "rad/s"),
    [O_WST] = MM_SCALAR("w_static", "static deflection at the probe under P at the load position", "m"),
    [O_WMAX] = MM_SCALAR("w_max", "largest |deflection| at the probe, direct run", "m", .flags = MM_ANSWER),
    [O_DAF] = MM_SCALAR("dynamic_factor", "w_max / |w_static|", ""),
    [O_TRUNC] = MM_SCALAR("truncation_error", "largest |w_retained - w_all modes| at the probe", "m"),
    [O_TEST] = MM_SCALAR("static_residual", "largest |r| of eq. (3) at the probe: the static part the retained "
                         "modes miss", "m"),
    [O_TERR] = MM_SCALAR("time_error", "largest |w_direct - w_all modes, exact| at the probe: Newmark's error", "m"),
    [O_EB] = MM_SCALAR("energy_identity", "the scheme's energy identity over the run, relative", ""),
    [O_SD] = MM_SERIES("w_direct", "deflection at the probe, direct (Newmark)", "m", "t", "s", .figure = "w"),
    [O_SM] = MM_SERIES("w_modal", "the same, the retained modes (exact in time)", "m", "t", "s", .figure = "w"),
    [O_SE] = MM_SERIES("w_all_modes", "the same, every mode (exact in time)", "m", "t", "s", .figure = "w",
                       .role = "reference"),
    [O_SR] = MM_SERIES("static_residual", "r(t) at the probe, eq. (3)", "m", "t", "s", .figure = "r"),
    [O_ANIM] = MM_ANIMATION("the beam and its load as the scheme moves them (deflection exaggerated)"),
};

static int check(const mm_value *in, mm_error *err)
{
    double steps = ceil(in[P_TEND].x / in[P_H].x), n = in[P_EL].x;
    int bc = (int)in[P_BC].x, have = bc == 2 ? 2 * (int)n - 2 : 2 * (int)n;
    /* a force that crosses the span within one step is over a support at
     * t = 0 and past the far end at t = h: every load vector of the direct
     * run is zero, and its w_max is 0 whatever P, E or v */
    double cross = in[P_L].x / in[P_V].x;
    if ((int)in[P_LOAD].x == 0 && in[P_H].x >= cross) {
        if (ceil(in[P_TEND].x / cross) * n > 2e6)
            return mm_error_set(err, MM_ERANGE, "h", "load=moving: it crosses the span in L/v = %.3g s, within "
                                "one step h = %.3g s, never seen by the direct run: make h less than %.3g s and "
                                "t_end less than %.3g s", cross, in[P_H].x, cross, 2e6 * cross / n);
        return mm_error_set(err, MM_ERANGE, "h", "load=moving: P crosses the span in L/v = %.3g s, within "
                            "one step h = %.3g s, so the direct run never has it on the beam: make h less than "
                            "%.3g s", cross, in[P_H].x, cross);
    }
    if (steps * n > 2e6)
        return mm_error_set(err, MM_ERANGE, "h", "%.3g steps of %g elements are too much work for one request "
                            "(steps x elements at most 2e6): make h at least %.3g s", steps, n, in[P_TEND].x * n / 2e6);
    if (in[P_MODES].x > have)
        return mm_error_set(err, MM_ERANGE, "modes", "%g elements give %d modes: make modes at most %d", n, have, have);
    if (in[P_MODES].x * n > 3e4)
        return mm_error_set(err, MM_ERANGE, "modes", "modes x elements at most 30000 (the eigen solver's work): make "
                            "modes at most %d", (int)(3e4 / n));
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    const int nel = (int)in[P_EL].x, m = (int)in[P_MODES].x, kind = (int)in[P_LOAD].x, np = (int)in[P_POINTS].x;
    const double L = in[P_L].x, h = in[P_H].x, t_end = in[P_TEND].x, eps = DBL_EPSILON;
    mm_fem_problem p = {MM_FEM_BEAM, fem_bc[(int)in[P_BC].x], MM_FEM_CONSISTENT, (size_t)nel,
                        {L, in[P_E].x, in[P_A].x, in[P_I].x, in[P_RHO].x}, NULL};
    mm_fem_load ld = {kind ? MM_FEM_LOAD_POINT : MM_FEM_LOAD_MOVING, in[P_P].x, in[P_X].x * L, 0,
                      kind == 2 ? in[P_TD].x : INFINITY, in[P_V].x};
    mm_fem_damping dmp = {in[P_ALPHA].x, in[P_BETA].x};
    size_t nd = mm_fem_ndof(&p), node = (size_t)lround(in[P_PROBE].x * nel), dof = 2 * node;
    long steps = (long)ceil(t_end / h * (1 - 1e-12)), stride = steps / (np - 1) + 1;
    int rows = (int)(steps / stride) + 1, rc;

    /* the modes: the m retained, or every one where there are at most 100 */
    size_t nf = nd - (p.bc == MM_FEM_FIXED_FIXED ? 4 : 2), nall = nf <= MM_FEM_MAX_MODES ? nf : (size_t)m;
    double *w = mm_res_alloc(res, nall * sizeof *w), *sh = mm_res_alloc(res, nall * nd * sizeof *sh);
    if (!w || !sh)
        return MM_ENOMEM;
    mm_fem_options fo;
    mm_fem_options_init(&fo);
    if (nall == nf)
        fo.method = MM_FEM_DENSE;
    mm_fem_modes md = {w, sh, 0, 0, 0, MM_FEM_AUTO};
    if ((rc = mm_fem_modes_solve(&p, nall, &fo, &md, err)))
        return rc;
    /* rounding: an eigen solver leaves about eps omega_max^2 / omega_1^2 / 2
     * of omega1 (subspace iteration far less, but a dense solver that much) */
    double wtop;
    if ((rc = mm_fem_omega_max(&p, &wtop, err)))
        return rc;
    double kappa = (wtop / w[0]) * (wtop / w[0]);     /* omega_max^2 / omega_1^2 ~ cond(K) */
    mm_res_scalar_err(res, O_W1, w[0], 0.5 * eps * kappa * w[0], MM_ERR_ESTIMATE);
    mm_res_method(res, mm_newmark_method_name(MM_NEWMARK_AVERAGE), h);
    mm_res_method_stat(res, "steps", (double)steps);
    mm_res_method_stat(res, "modes_computed", (double)nall);

    /* the direct run: Newmark on every DOF, banded, with snapshots */
    double *wd = mm_res_alloc(res, (size_t)rows * sizeof *wd), t_show;
    int nf_anim = mm_vib_frames(t_end, 0, 32, &t_show);
    long snap[MM_ANIM_MAX_FRAMES];
    double *snaps = mm_res_alloc(res, (size_t)nf_anim * nd * sizeof *snaps);
    if (!wd || !snaps)
        return MM_ENOMEM;
    for (int f = 0; f < nf_anim; f++)
        snap[f] = lround((double)steps * f / (nf_anim - 1));
    mm_fem_transient tr = {MM_FEM_AVERAGE, h, steps, dmp, stride, 1, &dof, wd, nf_anim, snap, snaps, 0};
    if ((rc = mm_fem_transient_solve(&p, &ld, &tr, err)))
        return rc;
    /* rounding: a few eps a step of the terms it adds up, which grow with
     * the damping and stiffness a step solves with (kS below), and the
     * curvatures of a fine mesh (measured: 0.08 eps elements^3, 20 to 400
     * elements) */
    /* kS: how much larger than M the matrix S = M + h/2 C + h^2/4 K a step
     * solves with is, 1 + h c_max/2 + (omega_max h)^2/4 */
    double kS = 1 + 0.5 * h * (dmp.a + dmp.b * wtop * wtop) + 0.25 * (wtop * h) * (wtop * h);
    double etol = 64 * eps * (steps + 10 + kS) + eps * pow(nel, 3);
    mm_res_scalar_err(res, O_EB, tr.energy_balance, etol, MM_ERR_BOUND);
    mm_res_check_abs(res, "direct run: the scheme's energy identity over every step, relative (rounding)",
                     tr.energy_balance, 0, etol);
    if (wtop * h > 1e4)
        mm_res_warn(res, "omega_max h = %.3g: a step of the stiffest mode adds up terms (omega_max h)^2 = %.2g times "
                         "the motion, so rounding limits what any check can confirm; a smaller h or fewer elements "
                         "keep it in bounds", wtop * h, (wtop * h) * (wtop * h));

    /* the modal sums, exact in time, at the sampled steps */
    double *t = mm_res_alloc(res, (size_t)rows * sizeof *t), *wm = mm_res_alloc(res, (size_t)rows * sizeof *wm);
    double *wa = mm_res_alloc(res, (size_t)rows * sizeof *wa);
    if (!t || !wm || !wa)
        return MM_ENOMEM;
    for (int i = 0; i < rows; i++)
        t[i] = h * (double)(i * stride);
    if ((rc = mm_fem_modal_response(&p, &md, (size_t)m, &dmp, &ld, rows, t, 1, &dof, wm, err)))
        return rc;
    /* the probe's scale, and the beam's (rounding of the modes and solves
     * is relative to the whole deflection, not to the probe's) */
    double wmax = mm_maxabs(wd, rows), big = fmax(wmax, mm_maxabs(wm, rows)), newmark_err = 0, gbig = big;
    for (size_t g = 0; g < (size_t)nf_anim * nd; g += 2)
        gbig = fmax(gbig, fabs(snaps[g]));
    if (nall == nf) {
        if ((rc = mm_fem_modal_response(&p, &md, nall, &dmp, &ld, rows, t, 1, &dof, wa, err)))
            return rc;
        double tmax = 0, emax = 0, dd = 0, sc, *wn = mm_res_alloc(res, (size_t)rows * sizeof *wn);
        if (!wn)
            return MM_ENOMEM;
        if ((rc = mm_fem_modal_newmark(&p, &md, &dmp, &ld, h, steps, stride, dof, wn, &sc, err)))
            return rc;
        for (int i = 0; i < rows; i++) {
            tmax = fmax(tmax, fabs(wm[i] - wa[i]));
            emax = fmax(emax, fabs(wd[i] - wa[i]));
            dd = fmax(dd, fabs(wd[i] - wn[i]));
        }
        /* rounding of the sums and of the modes (see the check below) */
        /* and an eigen solver's rounding of omega_j, eps kappa / 2 relative
         * at most, as a phase error over the run */
        double mre = (64 * eps * rows + 256 * eps * (w[nall - 1] / w[0]) + 0.5 * eps * kappa * (1 + w[0] * t_end)) *
                     gbig;
        mm_res_scalar_err(res, O_TRUNC, tmax, mre, MM_ERR_ESTIMATE);
        mm_res_scalar_err(res, O_TERR, emax, mre + 16 * eps * ((double)steps + kS) * gbig, MM_ERR_ESTIMATE);
        newmark_err = emax + dd;
        /* rounding of the steps, relative to the terms a step adds up (q +
         * h v + h^2 a, which cancel where omega h >> 1), and of the modes:
         * about 30 eps omega_max/omega_1 of the motion (measured on
         * cantilevers and simply supported beams) */
        mm_res_check_abs(res, "direct banded run vs every mode's Newmark recursion, superposed, at the probe [m] "
                              "(rounding)", dd, 0,
                         16 * eps * (steps + 64.0 * rows + kS) * sc + 256 * eps * (w[nall - 1] / w[0]) * big + 1e-300);
        mm_series *se = mm_res_series(res, O_SE, rows);
        if (!se)
            return MM_ENOMEM;
        for (int i = 0; i < rows; i++)
            se->x[i] = t[i], se->y[i] = wa[i];
    } else {
        mm_res_warn(res, "%zu free DOFs: only the %d modes retained are computed, so the truncation and "
                         "Newmark's error are estimated by the static residual r (3), not measured", nf, m);
    }

    /* eq. (3) at the probe, at the sampled times; the static deflection */
    double *f = mm_res_alloc(res, nd * sizeof *f), *u = mm_res_alloc(res, nd * sizeof *u), umax, wst;
    mm_series *sr = mm_res_series(res, O_SR, rows);
    if (!f || !u || !sr)
        return MM_ENOMEM;
    if ((rc = mm_fem_static_residual(&p, &md, (size_t)m, &ld, rows, t, dof, sr->y, &umax, err)))
        return rc;
    memcpy(sr->x, t, (size_t)rows * sizeof *t);
    double rmax = mm_maxabs(sr->y, rows);
    /* rounding: the static solve leaves up to about eps cond(K) ~ eps kappa of u */
    mm_res_scalar_err(res, O_TEST, rmax, 64 * eps * big + 2 * eps * kappa * umax, MM_ERR_ESTIMATE);
    mm_fem_load_vector(&p, &ld, kind ? 0 : 0.5 * L / ld.v, f);     /* moving: the load at midspan */
    if ((rc = mm_fem_static_solve(&p, f, u, err)))
        return rc;
    wst = u[dof];
    /* cubic elements: exact at the nodes, but for the solve's rounding */
    double west = 2 * eps * kappa * fabs(wst);
    for (size_t g = 0; g < nd; g += 2)
        west = fmax(west, 2 * eps * kappa * fabs(u[g]));
    mm_res_scalar_err(res, O_WST, wst, west, MM_ERR_ESTIMATE);
    /* w_max: off the exact motion by Newmark's error (measured where every
     * mode is computed, else estimated by r), and by the run's rounding,
     * a few eps a step of terms up to kS times the motion */
    double werr = (nall == nf ? newmark_err : rmax) + 16 * eps * ((double)steps + kS) * gbig;
    mm_res_scalar_err(res, O_WMAX, wmax, werr, MM_ERR_ESTIMATE);
    /* the error of w_max / |w_static|, as werr / |wst| + factor west / |wst|:
     * the relative form, factor (werr / w_max + west / |wst|), was 0 x inf
     * (NaN) where the motion has not reached the probe (w_max = 0 or
     * subnormal), and 0 where werr / 1e-300 stayed finite: a factor 0 with
     * an error 0, the motion it missed not counted */
    if (wst != 0) {
        double daf = wmax / fabs(wst);
        mm_res_scalar_err(res, O_DAF, daf, (werr + daf * west) / fabs(wst), MM_ERR_ESTIMATE);
    } else {
        mm_res_warn(res, "w_static = 0 at the probe (P = 0, or the probe on a support): dynamic_factor = "
                         "w_max / |w_static| does not exist and is left out");
    }
    mm_series *sd = mm_res_series(res, O_SD, rows), *sm = mm_res_series(res, O_SM, rows);
    if (!sd || !sm)
        return MM_ENOMEM;
    for (int i = 0; i < rows; i++) {
        sd->x[i] = sm->x[i] = t[i];
        sd->y[i] = wd[i], sm->y[i] = wm[i];
    }
    if (kind == 2)
        mm_res_warn(res, "a pulse switches off inside a step: the direct run then sees a jump it can place only to "
                         "a step, and its error falls like h, not h^2");
    if (w[md.n_modes - 1] * h > 10 && nall == nf)
        mm_res_warn(res, "the highest modes have omega h up to %.3g: average acceleration keeps them bounded but "
                         "at the wrong frequency", w[md.n_modes - 1] * h);

    /* the animation: the direct run's snapshots, the largest deflection a tenth of the span */
    return mm_vib_member_snaps(res, &p, nf_anim, snap, h, snaps, 0.1);
}

static const char *const references[] = {
    "L. Fryba, Vibration of Solids and Structures under Moving Loads, 3rd ed., Thomas Telford 1999, ch. 1",
    "R. W. Clough, J. Penzien, Dynamics of Structures, 2nd ed., McGraw-Hill 1993, chapters 12-13",
    NULL,
};

const mm_exercise mm_ex_vib_beam_transient = {
    .id = "vib-beam-transient", .chapter = 5, .section = "5.12.2",
    .title = "A beam under a moving or sudden load: modes kept against direct integration",
    .summary = "A force crossing a beam, or applied suddenly: modal superposition and Newmark on the FE model.",
    .tags = "vibration, beam, finite elements, moving load, impact, modal superposition, truncation, Newmark",
    .theory = "exercises/vib/beam_transient.md", .params = params, .n_params = MM_COUNT(params), .outputs = outputs,
    .n_outputs = MM_COUNT(outputs), .references = references, .check = check, .solve = solve,
};
