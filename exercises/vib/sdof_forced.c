/* sdof_forced.c — vib-sdof-forced: a damped mass-spring system driven by a
 * harmonic force, from its initial state to the steady state.
 *
 *     m x'' + c x' + k x = F0 cos(omega t)                       (1)
 *
 * Goal: see the transient die out and the steady state X cos(omega t - phase)
 * remain, with X and phase from the dynamic stiffness (eqs. 3-4 of the
 * theory).  The plotted response is the closed form (mm_sdof), checked
 * without an integrator: its steady state by the residual in eq. (1), its
 * free part by the flow of the free equation (mm_ex_sdof_flow_check).  On
 * request (integrator=dop853, ten times the work) DOP853 integrates eq. (1)
 * beside it, its error shown and checked, and X and phase are measured
 * from an integration started on the steady orbit.
 * Reference: any vibrations text, e.g. S. S. Rao, Mechanical Vibrations, ch. 3.
 */
#include <math.h>

#include "mm_exhelp.h"
#include "mm_vib.h"

enum { P_M, P_K, P_C, P_F0, P_OMEGA, P_X0, P_V0, P_TEND, P_POINTS, P_INTEGRATOR };

static const char *const integrators[] = {"none", "dop853", NULL};

static const mm_param params[] = {
    [P_M] = {"m", "mass", "kg", MM_REAL, 1, 1e-3, 1e3,
             .help = "the moving mass, 1 g to 1 t (a lab model to a machine)"},
    [P_K] = {"k", "stiffness", "N/m", MM_REAL, 100, 1e-2, 1e6,
             .help = "spring force per metre of stretch; with m it sets omega_n between 3e-3 and 3e4 rad/s"},
    [P_C] = {"c", "damping coefficient", "N s/m", MM_REAL, 2, 0, 1e4,
             .help = "viscous damper force per m/s; c = 2 sqrt(k m) is critical damping"},
    [P_F0] = {"F0", "force amplitude", "N", MM_REAL, 1, 0, 1e4, .help = "amplitude of F0 cos(omega t), up to 10 kN"},
    [P_OMEGA] = {"omega", "forcing frequency", "rad/s", MM_REAL, 8, 1e-3, 1e4,
                 .help = "angular frequency of the force, the range of omega_n; near omega_n the response peaks"},
    [P_X0] = {"x0", "initial displacement", "m", MM_REAL, 0, -10, 10,
              .help = "x at t = 0; within 10 m, where a linear spring is still a fair model"},
    [P_V0] = {"v0", "initial velocity", "m/s", MM_REAL, 0, -1e3, 1e3, .help = "dx/dt at t = 0"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 10, 1e-3, 1e4,
                .help = "simulated time; at most 2e4 radians of the fastest motion (3,200 periods), "
                        "what one request integrates in 250 ms"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 501, 11, 4001,
                  .help = "samples of the time response returned for the plot (a plot shows no more)"},
    [P_INTEGRATOR] = {"integrator", "numerical integration beside the closed form", "", MM_CHOICE, 0, 0, 0,
                      NULL, integrators,
                      .help = "none: the closed form alone, checked against the flow of eq. (1); dop853: "
                              "eq. (1) integrated as well, its error shown and checked, and X and phase "
                              "measured on the steady orbit (ten times the work)"},
};

enum { O_OMEGA_N, O_ZETA, O_X, O_PHASE, O_MAGNIFICATION, O_R, O_REGIME, O_XT, O_ANIM };

static const mm_output outputs[] = {
    [O_OMEGA_N] = MM_SCALAR("omega_n", "natural frequency", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_ZETA] = MM_SCALAR("zeta", "damping ratio", "", .flags = MM_ANSWER | MM_EXACT),
    [O_X] = MM_SCALAR("X", "steady amplitude", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_PHASE] = MM_SCALAR("phase", "phase lag", "rad", .flags = MM_ANSWER | MM_EXACT),
    [O_MAGNIFICATION] = MM_SCALAR("magnification", "dynamic magnification X/(F0/k)", "", .flags = MM_ANSWER | MM_EXACT),
    [O_R] = MM_SCALAR("r", "frequency ratio omega/omega_n", "", .flags = MM_EXACT),
    [O_REGIME] = MM_SCALAR("regime", "damping regime", "", .flags = MM_EXACT),
    [O_XT] = MM_SERIES("x", "displacement (closed form)", "m", "t", "s", .figure = "response"),
    [O_ANIM] = MM_ANIMATION("the mass on its spring and damper, driven by the force"),
};

static mm_sdof model(const mm_value *in)
{
    return (mm_sdof){.m = in[P_M].x, .c = in[P_C].x, .k = in[P_K].x, .F0 = in[P_F0].x,
                     .omega = in[P_OMEGA].x, .x0 = in[P_X0].x, .v0 = in[P_V0].x};
}

static int check(const mm_value *in, mm_error *err)
{
    mm_sdof s = model(in);
    return mm_vib_sdof_check(&s, in[P_TEND].x, s.F0 != 0, "amplitude", err);   /* no steady state at resonance */
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
    mm_res_scalar(res, O_X, p.X);
    mm_res_scalar(res, O_PHASE, p.phase);
    mm_res_scalar(res, O_MAGNIFICATION, p.magnification);
    mm_res_scalar(res, O_R, s.omega / p.omega_n);
    mm_res_scalar_text(res, O_REGIME, p.regime, mm_sdof_regime_name(p.regime));

    /* the answer is the closed form; DOP853's curve, when asked for, is not
     * drawn (it lies on it), its largest error is printed and checked */
    int dop853 = (int)in[P_INTEGRATOR].x == 1;
    mm_series *sx = mm_res_series(res, O_XT, n);
    double *xi = dop853 ? mm_res_alloc(res, (size_t)n * sizeof *xi) : sx;
    if (!sx || !xi)
        return MM_ENOMEM;
    mm_linspace(0, t_end, n, sx->x);
    double worst;
    int rc = MM_OK;
    if (dop853) {
        rc = mm_ex_sdof_response(&s, &p, t_end, n, sx->x, sx->y, xi, &worst, res, err);
    } else {
        mm_sdof_x_many(&s, &p, n, sx->x, sx->y);
        mm_res_method(res, "closed form (eq. 2)", 0);
        rc = mm_ex_sdof_flow_check(&s, &p, t_end, res);
    }
    if (rc != MM_OK)
        return rc;

    if (s.F0 != 0) {
        /* eq. (3) with (4) put into eq. (1): the worst residual over a period
         * against F0 (round-off: a few eps of the largest term) */
        double worst_r = 0, big = fmax(fabs(s.F0), fmax(s.k, s.m * s.omega * s.omega) * p.X);
        for (int i = 0; i < 16; i++) {
            double wt = 2 * M_PI * i / 16;
            double xp = p.X * cos(wt - p.phase), vp = -p.X * s.omega * sin(wt - p.phase);
            double ap = -s.omega * s.omega * xp;
            worst_r = fmax(worst_r, fabs(s.m * ap + s.c * vp + s.k * xp - s.F0 * cos(wt)));
        }
        mm_check_residual(res, "steady state X cos(wt - phase) in eq. (1): worst residual [N] (sum of the "
                               "terms' sizes)", worst_r, big, 16);
        /* the same measured: an integration started on the steady orbit, when
         * four forcing periods fit the work bound */
        if (dop853 && (rc = mm_vib_steady_check(res, &s, &p, p.X, 1, p.phase, "eq. (4)", err)) != MM_OK)
            return rc;
    }

    mm_ex_warn_aliasing(res, n, t_end, fmax(p.omega_n, s.F0 != 0 ? s.omega : 0), "shorten t_end or raise points");
    double r = s.omega / p.omega_n;
    if (s.F0 != 0 && p.zeta == 0)
        mm_res_warn(res, "no damping: the free vibration started with the force never dies out; it beats "
                         "against the forced one with period 2 pi/|omega_n - omega| = %.4g s",
                    2 * M_PI / fabs(p.omega_n - s.omega));
    else if (s.F0 != 0 && p.zeta < 0.2 && fabs(r - 1) < 0.05)
        mm_res_warn(res, "near resonance (omega/omega_n = %.3f) with little damping: "
                         "the transient lasts about 4/(zeta omega_n) = %.3g s", r, 4 / (p.zeta * p.omega_n));
    /* the mass on its spring and damper, with the force as an arrow */
    return mm_vib_sdof_animate(res, &s, &p, t_end, 2 * M_PI / fmax(p.omega_n, s.omega), 35, 1, NULL, 1);
}

static const char *const references[] = {
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, sections 3.3-3.4",
    "E. Hairer, S. P. Norsett, G. Wanner, Solving Ordinary Differential Equations I, Springer 1993 (DOP853)",
    NULL,
};

const mm_exercise mm_ex_vib_sdof_forced = {
    .id = "vib-sdof-forced", .chapter = 5, .section = "5.9.2", .title = "Forced vibration of a damped oscillator",
    .summary = "A mass on a spring and damper driven by F0 cos(omega t): transient, steady amplitude and phase lag.",
    .tags = "vibration, 1 DOF, forced, damping, steady state", .theory = "exercises/vib/sdof_forced.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
