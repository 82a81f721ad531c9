/* two_dof_transient.c — vib-2dof-transient: the transient of two masses in
 * a chain, by modal superposition (analytical) and by direct integration
 * (numerical), side by side.
 *
 *     M x'' + C x' + K x = F cos(omega t),   C = M Phi diag(2 zeta omega_j) Phi^T M   (1)
 *     x(t) = sum_j phi_j eta_j(t),  eta_j'' + 2 zeta omega_j eta_j' + omega_j^2 eta_j = phi_j^T F cos(omega t)   (2)
 *
 * Goal: the modes uncouple the equations (2); each modal coordinate is a
 * one-mass oscillator with a closed form, and their sum is the exact
 * motion; Newmark's average acceleration integrates the coupled equations
 * step by step with a small phase error (period longer by (omega h)^2/12);
 * keeping only the first mode leaves out part of the motion (the
 * truncation error, shown).  Checks: the direct run against the sum of
 * every mode's exact discrete Newmark solution, and the modal sum against
 * the coupled system's transition matrix, both to rounding.
 * Reference: S. S. Rao, Mechanical Vibrations, 6th ed., secs. 6.13-6.14.
 */
#include <math.h>

#include "mm_exhelp.h"
#include "mm_mdof.h"
#include "mm_vib.h"

enum { P_M1, P_M2, P_K1, P_K2, P_K3, P_ZETA, P_F1, P_F2, P_OMEGA, P_X10, P_X20, P_V10, P_V20, P_MODES, P_H,
       P_TEND, P_POINTS };

static const mm_param params[] = {
    [P_M1] = {"m1", "mass 1", "kg", MM_REAL, 1, 1e-3, 1e3, .help = "the left mass"},
    [P_M2] = {"m2", "mass 2", "kg", MM_REAL, 1, 1e-3, 1e3, .help = "the right mass"},
    [P_K1] = {"k1", "left spring", "N/m", MM_REAL, 100, 0, 1e6, .help = "wall to mass 1"},
    [P_K2] = {"k2", "coupling spring", "N/m", MM_REAL, 100, 0, 1e6, .help = "between the masses"},
    [P_K3] = {"k3", "right spring", "N/m", MM_REAL, 0, 0, 1e6, .help = "mass 2 to the right wall"},
    [P_ZETA] = {"zeta", "modal damping ratio", "", MM_REAL, 0.02, 0, 0.99,
                .help = "the same damping ratio in both modes (C built from the modes, eq. 1)"},
    [P_F1] = {"F1", "force on mass 1", "N", MM_REAL, 0, -1e4, 1e4, .help = "amplitude of F1 cos(omega t)"},
    [P_F2] = {"F2", "force on mass 2", "N", MM_REAL, 1, -1e4, 1e4, .help = "amplitude of F2 cos(omega t)"},
    [P_OMEGA] = {"omega", "forcing frequency", "rad/s", MM_REAL, 0, 0, 1e3,
                 .help = "0: the forces are constant, applied at t = 0 (a step)"},
    [P_X10] = {"x1_0", "initial x1", "m", MM_REAL, 0, -1, 1, .help = "displacement of mass 1 at t = 0"},
    [P_X20] = {"x2_0", "initial x2", "m", MM_REAL, 0, -1, 1, .help = "displacement of mass 2 at t = 0"},
    [P_V10] = {"v1_0", "initial v1", "m/s", MM_REAL, 0, -100, 100, .help = "velocity of mass 1 at t = 0"},
    [P_V20] = {"v2_0", "initial v2", "m/s", MM_REAL, 0, -100, 100, .help = "velocity of mass 2 at t = 0"},
    [P_MODES] = {"modes", "modes retained", "", MM_INT, 2, 1, 2,
                 .help = "1: the modal sum keeps the first mode only, and shows what the second adds"},
    [P_H] = {"h", "Newmark step", "s", MM_REAL, 0.01, 1e-5, 1, .help = "the fixed step of the direct integration"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 5, 1e-3, 1e3,
                .help = "simulated time; at most 2e5 steps of h (the direct run's work)"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 201, 11, 2001, .help = "steps returned for the plot"},
};

enum { O_W1, O_W2, O_ERR, O_TRUNC, O_PER1, O_PER2, O_X1, O_X2, O_X1E, O_X2E, O_X1M, O_X2M, O_ANIM };

static const mm_output outputs[] = {
    [O_W1] = MM_SCALAR("omega1", "first natural frequency", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_W2] = MM_SCALAR("omega2", "second natural frequency", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_ERR] = MM_SCALAR("max_error", "largest |x_Newmark - x_exact| at the plotted steps", "m", .flags = MM_ANSWER),
    [O_TRUNC] = MM_SCALAR("truncation_error", "largest |x_retained modes - x_exact|", "m", .flags = MM_ANSWER),
    [O_PER1] = MM_SCALAR("period_error_1", "Newmark's period elongation in mode 1, 2 atan(w h/2)/(w h) - 1", "",
                         .flags = MM_EXACT),
    [O_PER2] = MM_SCALAR("period_error_2", "the same in mode 2", "", .flags = MM_EXACT),
    [O_X1] = MM_SERIES("x1", "x1, Newmark", "m", "t", "s", .figure = "x1"),
    [O_X2] = MM_SERIES("x2", "x2, Newmark", "m", "t", "s", .figure = "x2"),
    [O_X1E] = MM_SERIES("x1_exact", "x1, modal superposition (exact)", "m", "t", "s", .figure = "x1",
                        .role = "reference"),
    [O_X2E] = MM_SERIES("x2_exact", "x2, modal superposition (exact)", "m", "t", "s", .figure = "x2",
                        .role = "reference"),
    [O_X1M] = MM_SERIES("x1_modes", "x1 from the retained modes", "m", "t", "s", .figure = "x1"),
    [O_X2M] = MM_SERIES("x2_modes", "x2 from the retained modes", "m", "t", "s", .figure = "x2"),
    [O_ANIM] = MM_ANIMATION("the two masses on their springs in the exact motion"),
};

static int check(const mm_value *in, mm_error *err)
{
    if (in[P_TEND].x / in[P_H].x > 2e5)
        return mm_error_set(err, MM_ERANGE, "h", "h = %g s takes %.3g steps to cover t_end = %g s; at most 2e5 "
                            "fit one request: make h at least %.3g s", in[P_H].x, in[P_TEND].x / in[P_H].x,
                            in[P_TEND].x, in[P_TEND].x / 2e5);
    return MM_OK;
}

/* The period elongation of average acceleration at omega h: the discrete
 * frequency is 2 atan(omega h / 2) / h. */
static double period_error(double wh)
{
    return wh > 0 ? wh / (2 * atan(wh / 2)) - 1 : 0;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    double m1 = in[P_M1].x, m2 = in[P_M2].x, k1 = in[P_K1].x, k2 = in[P_K2].x, k3 = in[P_K3].x;
    double M[4] = {m1, 0, 0, m2}, K[4] = {k1 + k2, -k2, -k2, k2 + k3}, w[2], phi[4], c[2];
    double F[2] = {in[P_F1].x, in[P_F2].x}, x0[2] = {in[P_X10].x, in[P_X20].x}, v0[2] = {in[P_V10].x, in[P_V20].x};
    const double h = in[P_H].x, t_end = in[P_TEND].x, W = in[P_OMEGA].x;
    int m = (int)in[P_MODES].x, rc;
    mm_mdof_two_dof(m1, m2, k1, k2, k3, w, phi);                       /* the modes, closed form */
    for (int j = 0; j < 2; j++)
        c[j] = 2 * in[P_ZETA].x * w[j];
    mm_res_scalar(res, O_W1, w[0]);
    mm_res_scalar(res, O_W2, w[1]);
    mm_res_scalar(res, O_PER1, period_error(w[0] * h));
    mm_res_scalar(res, O_PER2, period_error(w[1] * h));
    for (int j = 0; j < 2; j++)
        if (w[j] == 0 && F[0] + F[1] != 0 && W == 0)
            mm_res_warn(res, "a rigid-body mode under a constant force: the chain accelerates away without "
                             "bound (x grows like t^2)");

    mm_vib_transient tr;
    if ((rc = mm_vib_transient_run(res, 2, M, K, w, phi, c, m, x0, v0, F, W, h, t_end, (int)in[P_POINTS].x, &tr,
                                   err)))
        return rc;
    static const int coord[2] = {0, 1}, sid[6] = {O_X1, O_X2, O_X1E, O_X2E, O_X1M, O_X2M};
    if ((rc = mm_vib_transient_show(res, &tr, 2, h, O_ERR, O_TRUNC, 2, coord, sid, m < 2 ? 3 : 2)))
        return rc;
    if (w[1] * h > 0.5)
        mm_res_warn(res, "omega2 h = %.3g: fewer than 13 steps per period of mode 2, whose period Newmark "
                         "lengthens by %.2g %%: reduce h", w[1] * h, 100 * period_error(w[1] * h));

    /* the exact motion, 16 frames a period of mode 2, within the budget */
    int nf;
    double *q;
    if ((rc = mm_vib_modal_frames(res, 2, M, w, c, phi, x0, v0, F, W, t_end, w[1] > 0 ? 2 * M_PI / w[1] : 0,
                                  1500 / mm_vib_masses_numbers(2, K), &nf, &q, err)))
        return rc;
    double big = mm_vib_big(q, 2 * (size_t)nf);
    return mm_vib_masses_draw(res, 2, K, nf, q, 4 * big);
}

static const char *const references[] = {
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, sections 6.13-6.14",
    "T. J. R. Hughes, The Finite Element Method, Dover 2000, section 9.3",
    NULL,
};

const mm_exercise mm_ex_vib_2dof_transient = {
    .id = "vib-2dof-transient", .chapter = 5, .section = "5.10.2",
    .title = "The transient of two degrees of freedom: modes against steps",
    .summary = "Two masses set moving: modal superposition (exact) beside Newmark's direct integration.",
    .tags = "vibration, 2 DOF, transient, modal superposition, Newmark, truncation",
    .theory = "exercises/vib/two_dof_transient.md", .params = params, .n_params = MM_COUNT(params), .outputs = outputs,
    .n_outputs = MM_COUNT(outputs), .references = references, .check = check, .solve = solve,
};
