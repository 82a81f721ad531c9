/* two_dof.c — vib-2dof: the natural frequencies and modes of two masses in
 * a chain wall-k1-m1-k2-m2-k3-wall.
 *
 *     [m1 0; 0 m2] x'' + [k1+k2  -k2; -k2  k2+k3] x = 0                 (1)
 *
 * Goal: two degrees of freedom, two natural frequencies and two mode
 * shapes, where the masses move in phase (the lower) or against each
 * other (the higher); a repeated frequency when the coupling k2 vanishes
 * between twins, and a rigid-body mode when nothing holds the chain.
 * The frequencies and shapes are the closed form (eqs. 3-5 of the theory);
 * LAPACK's dsygvd is checked against it, and the closed form against the
 * equation it solves.
 * Reference: S. S. Rao, Mechanical Vibrations, 6th ed., ch. 5.
 */
#include <float.h>
#include <math.h>

#include "mm_exhelp.h"
#include "mm_mdof.h"
#include "mm_vib.h"

enum { P_M1, P_M2, P_K1, P_K2, P_K3, P_MODE };

static const mm_param params[] = {
    [P_M1] = {"m1", "mass 1", "kg", MM_REAL, 1, 1e-3, 1e3, .help = "the left mass"},
    [P_M2] = {"m2", "mass 2", "kg", MM_REAL, 1, 1e-3, 1e3, .help = "the right mass"},
    [P_K1] = {"k1", "left spring", "N/m", MM_REAL, 100, 0, 1e6, .help = "from the left wall to mass 1; 0: no spring"},
    [P_K2] = {"k2", "coupling spring", "N/m", MM_REAL, 100, 0, 1e6,
              .help = "between the masses; 0 uncouples them (twins then share one frequency)"},
    [P_K3] = {"k3", "right spring", "N/m", MM_REAL, 0, 0, 1e6, .help = "from mass 2 to the right wall; 0: no spring"},
    [P_MODE] = {"mode", "mode animated", "", MM_INT, 1, 1, 2, .help = "which mode the animation shows"},
};

enum { O_W1, O_W2, O_RIGID, O_RATIO, O_MODES, O_DET, O_ROOTS, O_ANIM };
static const char *const mcols[] = {"mode", "omega", "phi1", "phi2", NULL};
static const char *const munits[] = {"", "rad/s", "1/sqrt(kg)", "1/sqrt(kg)", NULL};

static const mm_output outputs[] = {
    [O_W1] = MM_SCALAR("omega1", "first natural frequency", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_W2] = MM_SCALAR("omega2", "second natural frequency", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_RIGID] = MM_SCALAR("rigid_modes", "rigid-body modes (omega = 0)", "", .flags = MM_EXACT),
    [O_RATIO] = MM_SCALAR("amplitude_ratio_1", "x2/x1 in the first mode", "", .flags = MM_EXACT),
    [O_MODES] = MM_TABLE("modes", "natural modes, mass-normalised (phi^T M phi = 1)", mcols, munits),
    [O_DET] = MM_SERIES("frequency_equation", "det(K - omega^2 M) / (m1 m2)", "1/s^4", "omega", "rad/s",
                        .figure = "frequency equation"),
    [O_ROOTS] = MM_SERIES("roots", "its roots: omega1, omega2", "1/s^4", "omega", "rad/s",
                          .figure = "frequency equation", .mark = "dots"),
    [O_ANIM] = MM_ANIMATION("the masses on their springs, moving in the chosen mode"),
};

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    double m1 = in[P_M1].x, m2 = in[P_M2].x, k1 = in[P_K1].x, k2 = in[P_K2].x, k3 = in[P_K3].x;
    double M[4] = {m1, 0, 0, m2}, K[4] = {k1 + k2, -k2, -k2, k2 + k3}, w[2], phi[4], wl[2], Pl[4];
    const double eps = DBL_EPSILON;
    mm_mdof_two_dof(m1, m2, k1, k2, k3, w, phi);                    /* eqs. (3)-(5) */
    int rigid = (w[0] == 0) + (w[1] == 0);
    mm_res_scalar(res, O_W1, w[0]);
    mm_res_scalar(res, O_W2, w[1]);
    mm_res_scalar(res, O_RIGID, rigid);
    if (phi[0] != 0)
        mm_res_scalar(res, O_RATIO, phi[2] / phi[0]);
    mm_table *t = mm_res_table(res, O_MODES, 2);
    if (!t)
        return MM_ENOMEM;
    for (int j = 0; j < 2; j++) {
        double row[4] = {j + 1, w[j], phi[j], phi[2 + j]};
        for (int c = 0; c < 4; c++)
            t->cell[4 * j + c] = row[c];
    }

    /* the closed form in eq. (1): K phi = omega^2 M phi, each row to a few
     * eps of the sum of its terms' sizes (componentwise: the small
     * component of a mode at a large mass ratio is held to its own digits,
     * not to eps of the large one), and phi^T M phi = I */
    double l2 = w[1] * w[1], worst = 0, orth = 0;
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 2; i++) {
            double t0 = K[2 * i] * phi[j], t1 = K[2 * i + 1] * phi[2 + j], t2 = w[j] * w[j] * M[3 * i] * phi[2 * i + j];
            double size = fabs(t0) + fabs(t1) + fabs(t2);
            if (size > 0)
                worst = fmax(worst, fabs(t0 + t1 - t2) / size);
            orth = fmax(orth, fabs(m1 * phi[i] * phi[j] + m2 * phi[2 + i] * phi[2 + j] - (i == j)));
        }
    mm_check_residual(res, "closed form in eq. (1): worst |K phi - omega^2 M phi| of a row over its terms' sizes",
                      worst, 1, 16);
    mm_check_residual(res, "closed-form modes mass-orthonormal: |phi_i^T M phi_j - delta_ij|", orth, 1, 16);

    /* LAPACK's dsygvd on the same K, M: eigenvalues to eps * lambda_max;
     * modes to eps * lambda_max / gap (undetermined for a repeated pair) */
    mm_mdof_system sys = {2, M, NULL, K};
    int rc = mm_mdof_modes(&sys, 2, wl, Pl, NULL, err);
    if (rc != MM_OK)
        return rc;
    double dl = fmax(fabs(wl[0] * wl[0] - w[0] * w[0]), fabs(wl[1] * wl[1] - l2));
    mm_res_check_abs(res, "LAPACK dsygvd vs closed form: worst |omega_j^2 difference| [1/s^2]", dl, 0,
                     16 * eps * l2 + 1e-300);
    double gap = l2 - w[0] * w[0];
    if (gap > 1e-6 * l2) {
        /* a mode's sign is free, and the two follow different rules: the
         * closed form makes phi1 >= 0, mm_mdof_modes the first component
         * above 1e-8 of the largest positive (phi1 = 2.1e-7 against
         * phi2 = -28.4 at m2/m1 = 1.8e-6 is below it), so LAPACK's mode
         * is compared with the sign of phi^T M phi_lapack */
        double dphi = 0, big = fmax(fmax(fabs(phi[0]), fabs(phi[2])), fmax(fabs(phi[1]), fabs(phi[3])));
        for (int j = 0; j < 2; j++) {
            double sg = m1 * phi[j] * Pl[j] + m2 * phi[2 + j] * Pl[2 + j] < 0 ? -1 : 1;
            for (int i = 0; i < 2; i++)
                dphi = fmax(dphi, fabs(sg * Pl[2 * i + j] - phi[2 * i + j]));
        }
        mm_res_check_abs(res, "LAPACK dsygvd vs closed form: worst mode-shape difference [1/sqrt(kg)]", dphi, 0,
                         32 * eps * big * l2 / gap);
    } else {
        mm_res_warn(res, "omega1 = omega2 = %.6g rad/s (repeated): any combination of the two modes is a mode, "
                         "so the shapes are not unique; the table shows the uncoupled pair", w[0]);
    }
    if (rigid)
        mm_res_warn(res, "%d rigid-body mode%s: nothing holds the chain %s, so it can move as a whole "
                         "without deforming a spring (omega = 0)", rigid, rigid > 1 ? "s" : "",
                    rigid > 1 ? "at all" : "at both ends");

    /* the frequency equation, eq. (2), over 0 .. 1.3 omega2 */
    enum { NP = 201 };
    double wend = 1.3 * (w[1] > 0 ? w[1] : 1);
    mm_series *sd = mm_res_series(res, O_DET, NP), *sr = mm_res_series(res, O_ROOTS, 2);
    if (!sd || !sr)
        return MM_ENOMEM;
    mm_linspace(0, wend, NP, sd->x);
    for (int i = 0; i < NP; i++) {
        double x2 = sd->x[i] * sd->x[i];
        sd->y[i] = ((k1 + k2 - m1 * x2) * (k2 + k3 - m2 * x2) - k2 * k2) / (m1 * m2);
    }
    sr->x[0] = w[0], sr->x[1] = w[1], sr->y[0] = sr->y[1] = 0;

    /* the chosen mode, one period in 24 frames, drawn to a visible scale */
    int j = (int)in[P_MODE].x - 1, nf = 24;
    mm_anim *a = mm_res_animation(res, nf, "t", w[j] > 0 ? "s" : "periods");
    double *q = mm_res_alloc(res, 2 * nf * sizeof *q);
    if (!a || !q)
        return MM_ENOMEM;
    double amp = 0.25 / fmax(fabs(phi[j]), fabs(phi[2 + j]));      /* the larger moves a quarter gap */
    mm_vib_mode_frames(2, phi, 2, j, w[j], amp, nf, a->t, q);
    return mm_vib_masses_draw(res, 2, K, nf, q, 1.0);
}

static const char *const references[] = {
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, sections 5.2-5.3",
    "E. Anderson et al., LAPACK Users' Guide, 3rd ed., SIAM 1999 (dsygvd)",
    NULL,
};

const mm_exercise mm_ex_vib_2dof = {
    .id = "vib-2dof", .chapter = 5, .section = "5.10.1",
    .title = "Two degrees of freedom: natural frequencies and modes",
    .summary = "Two masses in a chain of three springs: two frequencies, two mode shapes, in phase and against.",
    .tags = "vibration, 2 DOF, natural frequencies, mode shapes, eigenvalues", .theory = "exercises/vib/two_dof.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .solve = solve,
};
