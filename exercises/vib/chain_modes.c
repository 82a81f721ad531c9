/* chain_modes.c — vib-chain-modes: n equal masses joined by equal springs,
 * fixed at both ends or at one: the natural frequencies and modes of a
 * system with many degrees of freedom, against their closed form.
 *
 *     m x_i'' + k (2 x_i - x_{i-1} - x_{i+1}) = 0,   x_0 = 0, x_{n+1} = 0    (1)
 *     omega_j = 2 sqrt(k/m) sin(j pi / (2 (n + 1)))          fixed-fixed     (2)
 *     omega_j = 2 sqrt(k/m) sin((2j - 1) pi / (2 (2n + 1)))  fixed-free      (3)
 *
 * Goal: the frequencies crowd towards 2 sqrt(k/m) as n grows, the modes
 * are sampled sines, and a computer's eigenvalues are good to
 * eps x lambda_max in absolute terms: the lowest mode loses digits like
 * n^2 eps (shown, and checked against that bound).  Only the modes shown
 * are computed (LAPACK's dsbgvx on the tridiagonal matrices) once the
 * chain is long; the page says which solver ran.
 * Reference: L. Brillouin, Wave Propagation in Periodic Structures, 1946;
 * S. S. Rao, Mechanical Vibrations, 6th ed., sec. 6.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "mm_exhelp.h"
#include "mm_mdof.h"
#include "mm_vib.h"

#define MAXN 1000

enum { P_N, P_M, P_K, P_ENDS, P_MODES, P_MODE };
static const char *const ends[] = {"fixed-fixed", "fixed-free", NULL};

static const mm_param params[] = {
    [P_N] = {"n", "masses", "", MM_INT, 10, 1, MAXN,
             .help = "how many masses; at most 1000 (the lowest frequency then carries 1e-10 of rounding)"},
    [P_M] = {"m", "each mass", "kg", MM_REAL, 1, 1e-3, 1e3, .help = "all masses are equal"},
    [P_K] = {"k", "each spring", "N/m", MM_REAL, 100, 1e-2, 1e6, .help = "all springs are equal"},
    [P_ENDS] = {"ends", "ends", "", MM_CHOICE, 0, 0, 0, .choices = ends,
                .help = "fixed-fixed: a spring to a wall at each end; fixed-free: the last mass is free"},
    [P_MODES] = {"modes", "modes shown", "", MM_INT, 10, 1, 100,
                 .help = "the lowest modes computed and tabulated (at most n, at most 100)"},
    [P_MODE] = {"mode", "mode animated", "", MM_INT, 1, 1, 100, .help = "which of the modes shown is animated"},
};

enum { O_MAXERR, O_BOUND1, O_W1, O_MODES, O_ERR, O_BOUND, O_ANIM };
static const char *const mcols[] = {"mode", "omega", "omega_exact", "rel_error", NULL};
static const char *const munits[] = {"", "rad/s", "rad/s", "", NULL};

static const mm_output outputs[] = {
    [O_MAXERR] = MM_SCALAR("max_rel_error", "largest |omega / omega_exact - 1| of the modes shown", "",
                           .flags = MM_ANSWER),
    [O_BOUND1] = MM_SCALAR("rounding_bound_mode1", "8 eps lambda_max / lambda_1: the rounding a solver leaves "
                           "in mode 1, ~ n^2 eps", "", .flags = MM_EXACT),
    [O_W1] = MM_SCALAR("omega1", "lowest natural frequency, eq. (2) or (3)", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_MODES] = MM_TABLE("modes", "natural frequencies: computed and closed form", mcols, munits),
    [O_ERR] = MM_SERIES("rel_error", "|omega / omega_exact - 1|", "", "mode", "", .figure = "errors",
                        .mark = "dots", .y_scale = "log"),
    [O_BOUND] = MM_SERIES("rounding_bound", "8 eps lambda_max / lambda_j", "", "mode", "", .figure = "errors",
                          .role = "reference", .y_scale = "log"),
    [O_ANIM] = MM_ANIMATION("the chain moving in the chosen mode"),
};

static int check(const mm_value *in, mm_error *err)
{
    int n = (int)in[P_N].x, m = (int)in[P_MODES].x;
    if (m > n)
        return mm_error_set(err, MM_ERANGE, "modes", "a chain of %d masses has %d modes; make modes at most %d",
                            n, n, n);
    if (in[P_MODE].x > m)
        return mm_error_set(err, MM_ERANGE, "mode", "mode must be one of the %d modes shown; make it at most %d",
                            m, m);
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    const int n = (int)in[P_N].x, nm = (int)in[P_MODES].x, free_end = (int)in[P_ENDS].x, dense = n <= 40;
    const double m = in[P_M].x, k = in[P_K].x, eps = DBL_EPSILON, w0 = 2 * sqrt(k / m);
    int ld = dense ? n : nm;
    double *lam = mm_res_alloc(res, (size_t)n * sizeof *lam), *V = mm_res_alloc(res, (size_t)n * ld * sizeof *V);
    double *ex = mm_res_alloc(res, (size_t)nm * sizeof *ex);
    if (!lam || !V || !ex)
        return MM_ENOMEM;
    int rc = mm_mdof_chain_modes(n, m, k, free_end, dense ? 0 : nm, lam, V, err);   /* dense: all n modes */
    if (rc != MM_OK)
        return rc;
    mm_res_method(res, dense ? "LAPACK dsygvd, dense: all n modes" : "LAPACK dsbgvx, banded: only the modes shown",
                  0);
    mm_res_method_stat(res, "modes_computed", dense ? n : nm);

    /* the closed form, eqs. (2)-(3), and the rounding bound: an eigen
     * solver's eigenvalues carry about eps lambda_max absolute */
    double lmax = w0 * w0, worst = 0, wb = 0, shape = 0;
    mm_table *t = mm_res_table(res, O_MODES, nm);
    mm_series *se = mm_res_series(res, O_ERR, nm), *sb = mm_res_series(res, O_BOUND, nm);
    if (!t || !se || !sb)
        return MM_ENOMEM;
    for (int j = 0; j < nm; j++) {
        double th = mm_mdof_chain_theta(n, j, free_end);
        ex[j] = w0 * sin(th);
        double w = sqrt(fmax(lam[j], 0)), e = fabs(w / ex[j] - 1), b = 8 * eps * lmax / (ex[j] * ex[j]);
        double row[4] = {j + 1, w, ex[j], e};
        memcpy(t->cell + 4 * j, row, sizeof row);
        se->x[j] = sb->x[j] = j + 1;
        se->y[j] = e, sb->y[j] = b;
        worst = fmax(worst, e);
        wb = fmax(wb, e / b);
        /* the mode: a sampled sine, eq. (4), normalised to phi^T M phi = 1;
         * an eigenvector is good to eps lambda_max / (gap to its neighbours) */
        double s2 = 0, dot = 0, big = 0, gap = INFINITY;
        for (int i = 0; i < n; i++) {
            double sn = sin(2 * (i + 1) * th);
            s2 += sn * sn, dot += sn * V[i * ld + j];
        }
        for (int d = -1; d <= 1; d += 2) {
            int jj = j + d;
            if (jj < 0 || jj >= n)
                continue;
            double tj = mm_mdof_chain_theta(n, jj, free_end);
            gap = fmin(gap, fabs(lmax * sin(tj) * sin(tj) - ex[j] * ex[j]));
        }
        double dmax = 0;
        for (int i = 0; i < n; i++) {
            double sn = sin(2 * (i + 1) * th) / sqrt(m * s2) * (dot < 0 ? -1 : 1);
            big = fmax(big, fabs(sn));
            dmax = fmax(dmax, fabs(V[i * ld + j] - sn));
        }
        if (n > 1)
            shape = fmax(shape, dmax / (big * eps * lmax / gap));
    }
    /* itself rounding: anywhere from 0 to the bound of mode 1, the largest */
    mm_res_scalar_err(res, O_MAXERR, worst, 8 * eps * lmax / (ex[0] * ex[0]), MM_ERR_BOUND);
    mm_res_scalar(res, O_BOUND1, 8 * eps * lmax / (ex[0] * ex[0]));
    mm_res_scalar(res, O_W1, ex[0]);
    mm_res_check_abs(res, "computed vs closed form (2)-(3): worst |omega/omega_exact - 1| over its rounding "
                          "bound 8 eps lambda_max / lambda_j", wb, 0, 1);
    /* the backward error of a symmetric eigen solver: up to about n eps lambda_max */
    mm_res_check_abs(res, "modes vs sampled sines (4): worst difference over eps lambda_max / gap x |phi|", shape, 0,
                     16.0 * n + 64);

    /* the chosen mode, one period in 24 frames */
    enum { NF = 24 };
    int j = (int)in[P_MODE].x - 1;
    mm_anim *a = mm_res_animation(res, NF, "t", "s");
    double *q = mm_res_alloc(res, (size_t)NF * n * sizeof *q);
    if (!a || !q)
        return MM_ENOMEM;
    mm_vib_mode_frames(n, V, ld, j, sqrt(lam[j]), 1, NF, a->t, q);
    mm_vib_scale(q, (size_t)NF * n, 0.3);             /* the largest moves 0.3 of a gap */
    return mm_vib_chain_draw(res, n, !free_end, NF, q, 1.0);
}

static const char *const references[] = {
    "L. Brillouin, Wave Propagation in Periodic Structures, McGraw-Hill 1946, ch. 1",
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, ch. 6",
    "J. W. Demmel, Applied Numerical Linear Algebra, SIAM 1997, section 5.2 (eigenvalue perturbation)",
    NULL,
};

const mm_exercise mm_ex_vib_chain_modes = {
    .id = "vib-chain-modes", .chapter = 5, .section = "5.11.1",
    .title = "A chain of n masses: natural frequencies and modes",
    .summary = "n equal masses on equal springs: frequencies and sampled-sine modes against their closed form.",
    .tags = "vibration, n DOF, chain, natural frequencies, mode shapes, eigenvalues, rounding",
    .theory = "exercises/vib/chain_modes.md", .params = params, .n_params = MM_COUNT(params), .outputs = outputs,
    .n_outputs = MM_COUNT(outputs), .references = references, .check = check, .solve = solve,
};
