/* ndof_transient.c — vib-ndof-transient: a chain of n masses with Rayleigh
 * damping pushed by a force on one mass: modal superposition with the
 * modes one keeps, against direct integration of all of them.
 *
 *     M x'' + (a M + b K) x' + K x = F e_p cos(omega t)                      (1)
 *     zeta_j = a / (2 omega_j) + b omega_j / 2                                (2)
 *     x(t) ~ sum_{j <= m} phi_j eta_j(t),   r = K^-1 F - sum_{j <= m} phi_j phi_j^T F / omega_j^2   (3)
 *
 * Goal: Rayleigh damping keeps the modes uncoupled, damping the low modes
 * through a and the high ones through b; a load excites every mode, and
 * keeping only m of them leaves an error whose static part r (3) the
 * retained modes cannot represent.  Checks: the direct run against every
 * mode's exact discrete Newmark solution, the modal sum against the
 * transition matrix, the modes against the chain's closed form.
 * Reference: R. W. Clough, J. Penzien, Dynamics of Structures, 2nd ed.,
 * McGraw-Hill 1993, ch. 12-13.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "mm_exhelp.h"
#include "mm_mdof.h"
#include "mm_vib.h"

#define MAXN 30

enum { P_N, P_M, P_K, P_ENDS, P_A, P_B, P_F, P_AT, P_OMEGA, P_MODES, P_H, P_TEND, P_POINTS };
static const char *const ends[] = {"fixed-fixed", "fixed-free", NULL};

static const mm_param params[] = {
    [P_N] = {"n", "masses", "", MM_INT, 10, 2, MAXN, .help = "how many masses (at most 30: the exact "
             "reference's transition matrices grow like n^3)"},
    [P_M] = {"m", "each mass", "kg", MM_REAL, 1, 1e-3, 1e3, .help = "all masses are equal"},
    [P_K] = {"k", "each spring", "N/m", MM_REAL, 100, 1e-2, 1e6, .help = "all springs are equal"},
    [P_ENDS] = {"ends", "ends", "", MM_CHOICE, 0, 0, 0, .choices = ends, .help = "fixed-free: the last mass is free"},
    [P_A] = {"alpha", "mass-proportional damping a", "1/s", MM_REAL, 0.1, 0, 100,
             .help = "C = a M + b K; a damps the slow modes: zeta_j = a/(2 omega_j) + b omega_j/2"},
    [P_B] = {"beta", "stiffness-proportional damping b", "s", MM_REAL, 1e-3, 0, 1, .help = "b damps the fast modes"},
    [P_F] = {"F", "force", "N", MM_REAL, 10, -1e4, 1e4, .help = "amplitude of F cos(omega t) on mass p"},
    [P_AT] = {"p", "loaded mass", "", MM_INT, 10, 1, MAXN, .help = "which mass the force pushes (1 .. n)"},
    [P_OMEGA] = {"omega", "forcing frequency", "rad/s", MM_REAL, 0, 0, 1e3, .help = "0: a constant force (a step)"},
    [P_MODES] = {"modes", "modes retained", "", MM_INT, 3, 1, MAXN,
                 .help = "the modal sum keeps the lowest m modes (1 .. n)"},
    [P_H] = {"h", "Newmark step", "s", MM_REAL, 0.01, 1e-5, 1, .help = "the step of the direct integration"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 5, 1e-3, 1e3,
                .help = "simulated time; at most 2.7e6 / (10 + (n + 1)^2) steps of h (the direct run's work)"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 201, 11, 2001, .help = "steps returned for the plot"},
};

enum { O_W1, O_ERR, O_TRUNC, O_STATIC, O_MODES, O_X, O_XE, O_XM, O_ANIM };
static const char *const mcols[] = {"mode", "omega", "zeta", "force", NULL};
static const char *const munits[] = {"", "rad/s", "", "N/sqrt(kg)", NULL};

static const mm_output outputs[] = {
    [O_W1] = MM_SCALAR("omega1", "lowest natural frequency (closed form)", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_ERR] = MM_SCALAR("max_error", "largest |x_Newmark - x_exact|, every mass and plotted step", "m",
                        .flags = MM_ANSWER),
    [O_TRUNC] = MM_SCALAR("truncation_error", "largest |x_retained modes - x_exact|", "m", .flags = MM_ANSWER),
    [O_STATIC] = MM_SCALAR("static_residual", "largest |r| of eq. (3): the static deflection the retained modes "
                           "miss", "m"),
    [O_MODES] = MM_TABLE("modes", "modes: frequency, Rayleigh damping, modal force phi_j^T F", mcols, munits),
    [O_X] = MM_SERIES("x_p", "displacement of the loaded mass, Newmark", "m", "t", "s", .figure = "x_p"),
    [O_XE] = MM_SERIES("x_p_exact", "the same, every mode (exact)", "m", "t", "s", .figure = "x_p",
                       .role = "reference"),
    [O_XM] = MM_SERIES("x_p_modes", "the same, the retained modes", "m", "t", "s", .figure = "x_p"),
    [O_ANIM] = MM_ANIMATION("the chain in its exact motion"),
};

static int check(const mm_value *in, mm_error *err)
{
    int n = (int)in[P_N].x;
    double max_steps = floor(2.7e6 / (10 + (n + 1) * (n + 1)));
    if (in[P_AT].x > n)
        return mm_error_set(err, MM_ERANGE, "p", "the loaded mass p must be one of the %d masses", n);
    if (in[P_MODES].x > n)
        return mm_error_set(err, MM_ERANGE, "modes", "a chain of %d masses has %d modes: make modes at most %d", n,
                            n, n);
    if (in[P_TEND].x / in[P_H].x > max_steps)
        return mm_error_set(err, MM_ERANGE, "h", "h = %g s takes %.3g steps to cover t_end = %g s; at most %.0f fit "
                            "one request for %d masses: make h at least %.3g s", in[P_H].x, in[P_TEND].x / in[P_H].x,
                            in[P_TEND].x, max_steps, n, in[P_TEND].x / max_steps);
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    const int n = (int)in[P_N].x, free_end = (int)in[P_ENDS].x, p = (int)in[P_AT].x - 1, m = (int)in[P_MODES].x;
    const double mass = in[P_M].x, k = in[P_K].x, a = in[P_A].x, b = in[P_B].x, W = in[P_OMEGA].x;
    const double h = in[P_H].x, eps = DBL_EPSILON;
    size_t nn = (size_t)n * n;
    double *M = mm_res_alloc(res, nn * sizeof *M), *K = mm_res_alloc(res, nn * sizeof *K);
    double *Phi = mm_res_alloc(res, nn * sizeof *Phi), w[MAXN], c[MAXN], F[MAXN] = {0};
    if (!M || !K || !Phi)
        return MM_ENOMEM;
    mm_mdof_chain_matrices(n, mass, k, free_end, M, K);
    F[p] = in[P_F].x;
    mm_mdof_system sys = {n, M, NULL, K};
    int rc = mm_mdof_modes(&sys, n, w, Phi, NULL, err);
    if (rc)
        return rc;
    /* the closed form of the chain (vib-chain-modes, eqs. 2-3) */
    double worst = 0, w0 = 2 * sqrt(k / mass);
    mm_table *t = mm_res_table(res, O_MODES, n);
    if (!t)
        return MM_ENOMEM;
    for (int j = 0; j < n; j++) {
        double ex = w0 * sin(mm_mdof_chain_theta(n, j, free_end));
        worst = fmax(worst, fabs(w[j] * w[j] - ex * ex));
        c[j] = a + b * w[j] * w[j];                                    /* 2 zeta_j omega_j, eq. (2) */
        double row[4] = {j + 1, w[j], c[j] / (2 * w[j]), Phi[p * n + j] * F[p]};
        memcpy(t->cell + 4 * j, row, sizeof row);
        if (j == 0)
            mm_res_scalar(res, O_W1, ex);
    }
    mm_res_check_abs(res, "LAPACK dsygvd vs the chain's closed form: worst |omega_j^2 difference| [1/s^2] "
                          "(rounding, eps lambda_max)", worst, 0, 16 * eps * w0 * w0);

    mm_vib_transient tr;
    if ((rc = mm_vib_transient_run(res, n, M, K, w, Phi, c, m, NULL, NULL, F, W, h, in[P_TEND].x,
                                   (int)in[P_POINTS].x, &tr, err)))
        return rc;
    static const int sid[3] = {O_X, O_XE, O_XM};
    if ((rc = mm_vib_transient_show(res, &tr, n, h, O_ERR, O_TRUNC, 1, &p, sid, m < n ? 3 : 2)))
        return rc;
    /* eq. (3): K^-1 F less what the retained modes carry statically */
    double r[MAXN];
    if ((rc = mm_mdof_static_residual(n, m, K, w, Phi, p, F[p], r, err)))
        return rc;
    mm_res_scalar_err(res, O_STATIC, mm_maxabs(r, n), 16 * eps * n * mm_vib_big(tr.q_ex, (size_t)tr.ns * n),
                      MM_ERR_ESTIMATE);

    if (w[n - 1] * h > 2)
        mm_res_warn(res, "omega_max h = %.3g: the fastest modes take fewer than 3 steps a period; average "
                         "acceleration keeps them bounded but at the wrong frequency", w[n - 1] * h);

    /* the exact motion, 16 frames a period of the lowest mode, the largest moving 0.3 of a gap */
    int nf;
    double *q;
    if ((rc = mm_vib_modal_frames(res, n, M, w, c, Phi, NULL, NULL, F, W, in[P_TEND].x, 2 * M_PI / w[0] / 2,
                                  1500 / (4 * n + 4), &nf, &q, err)))
        return rc;
    mm_vib_scale(q, (size_t)nf * n, 0.3);
    return mm_vib_chain_draw(res, n, !free_end, nf, q, 1.0);
}

static const char *const references[] = {
    "R. W. Clough, J. Penzien, Dynamics of Structures, 2nd ed., McGraw-Hill 1993, chapters 12-13",
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, section 6.14",
    NULL,
};

const mm_exercise mm_ex_vib_ndof_transient = {
    .id = "vib-ndof-transient", .chapter = 5, .section = "5.11.1",
    .title = "The transient of n degrees of freedom: modes retained and Rayleigh damping",
    .summary = "A chain pushed at one mass: modal superposition with m modes against direct integration of all.",
    .tags = "vibration, n DOF, transient, modal superposition, Rayleigh damping, truncation, Newmark",
    .theory = "exercises/vib/ndof_transient.md", .params = params, .n_params = MM_COUNT(params), .outputs = outputs,
    .n_outputs = MM_COUNT(outputs), .references = references, .check = check, .solve = solve,
};
