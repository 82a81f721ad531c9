/* sdof_free.c — vib-sdof-free: free vibration of a damped mass-spring system.
 *
 *     m x'' + c x' + k x = 0,   x(0) = x0,  x'(0) = v0              (1)
 *
 * Goal: the three regimes of damping (under, critical, over) and how the
 * damping ratio sets the decay.  The response is integrated (DOP853, dense
 * output) and checked against the closed form at every fifth point; a third
 * equation integrates the power lost in the damper so that the energy
 * balance E(0) = E(t_end) + dissipated work is a second, independent check.
 * Reference: S. S. Rao, Mechanical Vibrations, ch. 2.
 */
#include <math.h>

#include "mm_exhelp.h"
#include "mm_ode.h"

enum { P_M, P_K, P_C, P_X0, P_V0, P_TEND, P_POINTS };

static const mm_param params[] = {
    [P_M] = {"m", "mass", "kg", MM_REAL, 1, 1e-3, 1e3, .help = "the moving mass"},
    [P_K] = {"k", "stiffness", "N/m", MM_REAL, 100, 1e-2, 1e6, .help = "spring force per metre of stretch"},
    [P_C] = {"c", "damping coefficient", "N s/m", MM_REAL, 2, 0, 1e4,
             .help = "viscous damper force per m/s; c = 2 sqrt(k m) is critical damping"},
    [P_X0] = {"x0", "initial displacement", "m", MM_REAL, 0.01, -10, 10, .help = "x at t = 0"},
    [P_V0] = {"v0", "initial velocity", "m/s", MM_REAL, 0, -1e3, 1e3, .help = "dx/dt at t = 0"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 5, 1e-3, 1e4,
                .help = "simulated time; at most 1e4 radians of the fastest motion"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 501, 11, 4001,
                  .help = "samples of the time response returned for the plot"},
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

/* y = (x, v, D): D' = c v^2 is the work the damper has taken (eq. 5). */
static int rhs_energy(double t, const double *y, double *dy, void *ctx)
{
    (void)t;
    const mm_sdof *s = ctx;
    dy[0] = y[1];
    dy[1] = -(s->c * y[1] + s->k * y[0]) / s->m;
    dy[2] = s->c * y[1] * y[1];
    return 0;
}

static int energy_balance(const mm_sdof *s, double t_end, double *E0, double *Eend,
                          double *D, mm_error *err)
{
    double y0[3] = {s->x0, s->v0, 0}, yend[3];
    mm_ode_problem prob = {.n = 3, .f = rhs_energy, .params = (void *)s, .t0 = 0,
                           .t_end = t_end, .y0 = y0};
    mm_ode_options opt;
    mm_ode_options_init(&opt);
    opt.method = MM_ODE_DOP853;
    opt.rtol = 1e-9;
    opt.atol = 1e-14;
    opt.max_steps = 1000000;
    mm_ode_result r = {0};
    r.y_end = yend;
    mm_ode_work *w = mm_ode_work_alloc(3);
    int rc = mm_ode_solve(&prob, &opt, w, &r, err);
    mm_ode_work_free(w);
    if (rc != MM_OK)
        return rc;
    *E0 = 0.5 * s->m * s->v0 * s->v0 + 0.5 * s->k * s->x0 * s->x0;
    *Eend = 0.5 * s->m * yend[1] * yend[1] + 0.5 * s->k * yend[0] * yend[0];
    *D = yend[2];
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    mm_sdof s = model(in);
    mm_sdof_props p;
    mm_sdof_props_get(&s, &p);
    double t_end = in[P_TEND].x;
    int n = (int)in[P_POINTS].x;

    mm_res_scalar_v1(res, "omega_n", "natural frequency", "rad/s", p.omega_n);
    mm_res_scalar_v1(res, "zeta", "damping ratio", "", p.zeta);
    mm_res_scalar_v1(res, "omega_d", "damped frequency", "rad/s", p.omega_d);
    mm_res_scalar_text_v1(res, "regime", "damping regime", "", p.regime, mm_sdof_regime_name(p.regime));
    if (p.regime == MM_SDOF_UNDER) {
        mm_res_scalar_v1(res, "T_d", "damped period", "s", 2 * M_PI / p.omega_d);
        mm_res_scalar_v1(res, "log_decrement", "logarithmic decrement", "",
                      2 * M_PI * p.zeta / sqrt((1 - p.zeta) * (1 + p.zeta)));
    }
    mm_res_scalar_v1(res, "c_critical", "critical damping coefficient", "N s/m", 2 * sqrt(s.k * s.m));

    mm_series *sx = mm_res_series_v1(res, "x", "displacement", "m", "t", "s", n);
    if (!sx)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_linspace(0, t_end, n, sx->x);
    int rc = mm_ex_sdof_run(&s, t_end, n, sx->x, sx->y, NULL, 5, res, err);
    if (rc != MM_OK)
        return rc;

    double E0, Eend, D;
    rc = energy_balance(&s, t_end, &E0, &Eend, &D, err);
    if (rc != MM_OK)
        return rc;
    mm_res_scalar_v1(res, "energy_dissipated", "energy taken by the damper", "J", D);
    /* the balance holds to the integrator's tolerance (rtol 1e-9) of E0 */
    mm_res_check_abs(res, "energy balance: E(t_end) + damper work vs E(0)", Eend + D, E0,
                     1e-7 * E0 + 1e-300);

    if (p.regime == MM_SDOF_UNDER && (n - 1) / (t_end / (2 * M_PI / p.omega_d)) < 8)
        mm_res_warn(res, "the plot has under 8 points per period: it cannot show the oscillation "
                         "(it aliases); shorten t_end or raise points");
    return MM_OK;
}

static const char *const references[] = {
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, section 2.6",
    NULL,
};

const mm_exercise mm_ex_vib_sdof_free = {
    .id = "vib-sdof-free",
    .chapter = 5,
    .section = "5.9.1",
    .title = "Free vibration of a damped oscillator",
    .summary = "A released mass on a spring and damper: under-, critically and overdamped motion.",
    .tags = "vibration, 1 DOF, free, damping",
    .theory = "exercises/vib/sdof_free.md",
    .params = params,
    .n_params = MM_COUNT(params),
    .references = references,
    .check = check,
    .solve = solve,
};
