/* sdof_free.c — vib-sdof-free: free vibration of a damped mass-spring system.
 *
 *     m x'' + c x' + k x = 0,   x(0) = x0,  x'(0) = v0              (1)
 *
 * Goal: the three regimes of damping (under, critical, over) and how the
 * damping ratio sets the decay.  The plotted x(t) is the closed form of the
 * regime (eq. 4 and its critical and overdamped forms, mm_sdof); DOP853
 * integrates eq. (1) beside it and its error is shown.  The energy balance
 * (5) is the second check: a third equation adds up the damper's work
 * during the integration (mm_sdof_damper_work), and it must equal what the
 * closed form says the block has lost.
 * Reference: S. S. Rao, Mechanical Vibrations, ch. 2.
 */
#include <float.h>
#include <math.h>

#include "mm_exhelp.h"
#include "mm_vib.h"

enum { P_M, P_K, P_C, P_X0, P_V0, P_TEND, P_POINTS };

static const mm_param params[] = {
    [P_M] = {"m", "mass", "kg", MM_REAL, 1, 1e-3, 1e3,
             .help = "the moving mass, 1 g to 1 t (a lab model to a machine)"},
    [P_K] = {"k", "stiffness", "N/m", MM_REAL, 100, 1e-2, 1e6,
             .help = "spring force per metre of stretch; with m it sets omega_n between 3e-3 and 3e4 rad/s"},
    [P_C] = {"c", "damping coefficient", "N s/m", MM_REAL, 2, 0, 1e4,
             .help = "viscous damper force per m/s; c = 2 sqrt(k m) is critical damping"},
    [P_X0] = {"x0", "initial displacement", "m", MM_REAL, 0.01, -10, 10,
              .help = "x at t = 0; within 10 m, where a linear spring is still a fair model"},
    [P_V0] = {"v0", "initial velocity", "m/s", MM_REAL, 0, -1e3, 1e3, .help = "dx/dt at t = 0"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 5, 1e-3, 1e4,
                .help = "simulated time; at most 2e4 radians of the fastest motion (3,200 periods), "
                        "what one request integrates in 250 ms"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 501, 11, 4001,
                  .help = "samples of the time response returned for the plot (a plot shows no more)"},
};

enum { O_OMEGA_N, O_ZETA, O_OMEGA_D, O_REGIME, O_TD, O_LOGDEC, O_CCRIT, O_EDISS, O_X, O_ERR, O_ANIM };

static const mm_output outputs[] = {
    [O_OMEGA_N] = MM_SCALAR("omega_n", "natural frequency", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_ZETA] = MM_SCALAR("zeta", "damping ratio", "", .flags = MM_ANSWER | MM_EXACT),
    [O_OMEGA_D] = MM_SCALAR("omega_d", "damped frequency (0: no oscillation)", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_REGIME] = MM_SCALAR("regime", "damping regime", "", .flags = MM_ANSWER | MM_EXACT),
    [O_TD] = MM_SCALAR("T_d", "damped period", "s", .flags = MM_EXACT),
    [O_LOGDEC] = MM_SCALAR("log_decrement", "logarithmic decrement", "", .flags = MM_EXACT),
    [O_CCRIT] = MM_SCALAR("c_critical", "critical damping coefficient", "N s/m", .flags = MM_EXACT),
    [O_EDISS] = MM_SCALAR("energy_dissipated", "energy taken by the damper, E(0) - E(t_end), eq. (5)", "J",
                          .flags = MM_ANSWER),
    [O_X] = MM_SERIES("x", "displacement (closed form)", "m", "t", "s", .figure = "response"),
    [O_ERR] = MM_SERIES("error_dop853", "x by DOP853 minus the closed form", "m", "t", "s", .figure = "error"),
    [O_ANIM] = MM_ANIMATION("the block on its spring and damper"),
};

static mm_sdof model(const mm_value *in)
{
    return (mm_sdof){.m = in[P_M].x, .c = in[P_C].x, .k = in[P_K].x,
                     .x0 = in[P_X0].x, .v0 = in[P_V0].x};
}

static int check(const mm_value *in, mm_error *err)
{
    mm_sdof s = model(in);
    return mm_ex_sdof_work_check(&s, in[P_TEND].x, err);
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    mm_sdof s = model(in);
    mm_sdof_props p;
    mm_sdof_props_get(&s, &p);
    double t_end = in[P_TEND].x;
    int n = (int)in[P_POINTS].x;

    mm_res_scalar(res, O_OMEGA_N, p.omega_n);
    mm_res_scalar(res, O_ZETA, p.zeta);
    mm_res_scalar_text(res, O_OMEGA_D, p.omega_d, p.regime == MM_SDOF_UNDER ? NULL : "no oscillation");
    mm_res_scalar_text(res, O_REGIME, p.regime, mm_sdof_regime_name(p.regime));
    if (p.regime == MM_SDOF_UNDER) {
        mm_res_scalar(res, O_TD, 2 * M_PI / p.omega_d);
        mm_res_scalar(res, O_LOGDEC, 2 * M_PI * p.zeta / sqrt((1 - p.zeta) * (1 + p.zeta)));
    }
    mm_res_scalar(res, O_CCRIT, 2 * sqrt(s.k * s.m));

    mm_series *sx = mm_res_series(res, O_X, n);
    int rc = mm_ex_sdof_plot(&s, &p, t_end, sx, mm_res_series(res, O_ERR, n), res, err);
    if (rc != MM_OK)
        return rc;

    /* eq. (5): what the block has lost, by the closed form; its rounding
     * grows with the phase w t_end carried by the cosines */
    double v_end, x_end = mm_sdof_x(&s, &p, t_end, &v_end);
    double E0 = mm_sdof_energy(&s, s.x0, s.v0), E1 = mm_sdof_energy(&s, x_end, v_end);
    double D_exact = E0 - E1, D_round = (16 + 4 * p.omega_n * t_end) * DBL_EPSILON * (E0 + E1);
    if (s.c == 0)
        D_exact = D_round = 0;                                /* no damper: nothing is lost */
    mm_res_scalar_err(res, O_EDISS, D_exact, D_round, MM_ERR_BOUND);
    double D = 0, Df = 0;                                      /* at rest: nothing to integrate */
    if (E0 > 0 && ((rc = mm_sdof_damper_work(&s, &p, t_end, MM_EX_SDOF_RTOL, &D, err)) != MM_OK ||
                   (rc = mm_sdof_damper_work(&s, &p, t_end, MM_EX_SDOF_RTOL / MM_EX_SDOF_REF, &Df, err)) != MM_OK))
        return rc;
    double radians = t_end * mm_sdof_fastest_rate(&s, &p);
    mm_res_check_abs(res, "energy balance (5): damper work by DOP853 vs E(0) - E(t_end) of the closed form, "
                          "within 10 times its error estimated at rtol/10",
                     D, D_exact, 10 * fabs(D - Df) + D_round + mm_ex_roundoff(radians, E0) + 1e-300);

    mm_ex_warn_aliasing(res, n, t_end, p.regime == MM_SDOF_UNDER ? p.omega_d : 0,
                        "shorten t_end or raise points");

    /* the block moving, frames from the closed form */
    return mm_vib_sdof_animate(res, &s, &p, t_end, 2 * M_PI / p.omega_n, 33, 0, NULL, 1);
}

static const char *const references[] = {
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, section 2.6",
    "E. Hairer, S. P. Norsett, G. Wanner, Solving Ordinary Differential Equations I, Springer 1993 (DOP853)",
    NULL,
};

const mm_exercise mm_ex_vib_sdof_free = {
    .id = "vib-sdof-free", .chapter = 5, .section = "5.9.1", .title = "Free vibration of a damped oscillator",
    .summary = "A released mass on a spring and damper: under-, critically and overdamped motion.",
    .tags = "vibration, 1 DOF, free, damping", .theory = "exercises/vib/sdof_free.md", .params = params,
    .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs), .references = references,
    .check = check, .solve = solve,
};
