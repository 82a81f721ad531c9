/* sdof_forced.c — vib-sdof-forced: a damped mass-spring system driven by a
 * harmonic force, from its initial state to the steady state.
 *
 *     m x'' + c x' + k x = F0 cos(omega t)                       (1)
 *
 * Goal: see the transient die out and the steady state X cos(omega t - phase)
 * remain, with X and phase from the dynamic stiffness (eqs. 3-4 of the
 * theory).  The time response is integrated (DOP853, dense output) and
 * checked against the closed form; X and phase are also measured from a
 * second integration started on the steady orbit, a check of eqs. (3)-(4)
 * that does not use them.
 * Reference: any vibrations text, e.g. S. S. Rao, Mechanical Vibrations, ch. 3.
 */
#include <math.h>

#include "mm_exhelp.h"
#include "mm_scene.h"

enum { P_M, P_K, P_C, P_F0, P_OMEGA, P_X0, P_V0, P_TEND, P_POINTS };

static const mm_param params[] = {
    [P_M] = {"m", "mass", "kg", MM_REAL, 1, 1e-3, 1e3, .help = "the moving mass"},
    [P_K] = {"k", "stiffness", "N/m", MM_REAL, 100, 1e-2, 1e6, .help = "spring force per metre of stretch"},
    [P_C] = {"c", "damping coefficient", "N s/m", MM_REAL, 2, 0, 1e4,
             .help = "viscous damper force per m/s; c = 2 sqrt(k m) is critical damping"},
    [P_F0] = {"F0", "force amplitude", "N", MM_REAL, 1, 0, 1e4, .help = "amplitude of F0 cos(omega t)"},
    [P_OMEGA] = {"omega", "forcing frequency", "rad/s", MM_REAL, 8, 1e-3, 1e4,
                 .help = "angular frequency of the force; near omega_n the response peaks"},
    [P_X0] = {"x0", "initial displacement", "m", MM_REAL, 0, -10, 10, .help = "x at t = 0"},
    [P_V0] = {"v0", "initial velocity", "m/s", MM_REAL, 0, -1e3, 1e3, .help = "dx/dt at t = 0"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 10, 1e-3, 1e4,
                .help = "simulated time; at most 1e4 radians of the fastest motion"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 501, 11, 4001,
                  .help = "samples of the time response returned for the plot"},
};

enum { O_OMEGA_N, O_ZETA, O_X, O_PHASE, O_MAGNIFICATION, O_R, O_REGIME, O_XT, O_ANIM };

static const mm_output outputs[] = {
    [O_OMEGA_N] = MM_SCALAR("omega_n", "natural frequency", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_ZETA] = MM_SCALAR("zeta", "damping ratio", "", .flags = MM_ANSWER | MM_EXACT),
    [O_X] = MM_SCALAR("X", "steady amplitude", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_PHASE] = MM_SCALAR("phase", "phase lag", "rad", .flags = MM_ANSWER | MM_EXACT),
    [O_MAGNIFICATION] = MM_SCALAR("magnification", "dynamic magnification X/(F0/k)", "",
                                  .flags = MM_ANSWER | MM_EXACT),
    [O_R] = MM_SCALAR("r", "frequency ratio omega/omega_n", "", .flags = MM_EXACT),
    [O_REGIME] = MM_SCALAR("regime", "damping regime", "", .flags = MM_EXACT),
    [O_XT] = MM_SERIES("x", "displacement", "m", "t", "s"),
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
    mm_sdof_props p;
    mm_sdof_props_get(&s, &p);
    if (p.resonant && s.F0 != 0)
        return mm_error_set(err, MM_ERANGE, "omega",
                            "omega = omega_n = %g rad/s with c = 0 has no steady state (the amplitude "
                            "grows without bound); add damping or move omega (see vib-resonance)",
                            p.omega_n);
    return mm_ex_sdof_work_check(&s, in[P_TEND].x, err);
}

/* X and phase measured from an integration started on the steady orbit
 * x_p(0), x_p'(0): project 2 periods of samples on cos and sin, which is
 * exact for a pure harmonic sampled evenly over whole periods. */
static int measure_steady(const mm_sdof *s, const mm_sdof_props *p, mm_result *res,
                          double *X, double *phase, mm_error *err)
{
    enum { PER = 32, N = 2 * PER };
    mm_sdof st = *s;
    st.x0 = p->X * cos(p->phase);
    st.v0 = p->X * s->omega * sin(p->phase);
    double T = 2 * M_PI / s->omega, t[N + 1], x[N + 1];
    mm_linspace(0, 2 * T, N + 1, t);
    int rc = mm_ex_sdof_run(&st, 2 * T, N + 1, t, x, NULL, 0, res, err);
    if (rc != MM_OK)
        return rc;
    double a = 0, b = 0;                       /* x = a cos wt + b sin wt */
    for (int i = 0; i < N; i++) {              /* the last point repeats the first */
        a += x[i] * cos(2 * M_PI * i / PER);
        b += x[i] * sin(2 * M_PI * i / PER);
    }
    a *= 2.0 / N;
    b *= 2.0 / N;
    *X = hypot(a, b);
    *phase = atan2(b, a);                      /* X cos(wt - phase) = X cos(phase) cos wt + X sin(phase) sin wt */
    return MM_OK;
}

/* The mass on its spring and damper, with the force as an arrow: x(t) by
 * the closed form at each frame.  The drawing is to the scale of the
 * motion: a rest length of 5 times its largest |x|. */
static int animate(const mm_sdof *s, const mm_sdof_props *p, double t_end, mm_result *res)
{
    double t_show;
    int nf = mm_scene_frames(t_end, 2 * M_PI / fmax(p->omega_n, s->omega), &t_show);
    mm_anim *a = mm_res_animation(res, nf, "t", "s");
    double *x = mm_res_alloc(res, (size_t)nf * sizeof *x);
    if (!a || !x)
        return MM_ENOMEM;
    double big = 0;
    for (int f = 0; f < nf; f++) {
        a->t[f] = t_show * f / (nf - 1);
        x[f] = mm_sdof_x(s, p, a->t[f], NULL);
        big = fmax(big, fabs(x[f]));
    }
    double L = 5 * (big > 0 ? big : 1), H = 0.6 * L;   /* rest length, block height */
    mm_shape *wall = mm_anim_shape(res, "wall", MM_SHAPE_LINE, 1, 2);
    mm_shape *spring = mm_anim_shape(res, "spring", MM_SHAPE_LINE, nf, MM_SCENE_SPRING_POINTS);
    mm_shape *cup = mm_anim_shape(res, "damper", MM_SHAPE_LINE, nf, MM_SCENE_CUP_POINTS);
    mm_shape *piston = mm_anim_shape(res, "piston", MM_SHAPE_LINE, nf, MM_SCENE_PISTON_POINTS);
    mm_shape *mass = mm_anim_shape(res, "mass", MM_SHAPE_POLYGON, nf, MM_SCENE_BOX_POINTS);
    mm_shape *force = mm_anim_shape(res, "F", MM_SHAPE_ARROW, nf, 2);
    double *Fv = mm_shape_values(res, force);
    if (!wall || !spring || !cup || !piston || !mass || !Fv)
        return MM_ENOMEM;
    wall->style = "ground";
    wall->x[0] = wall->x[1] = 0;
    wall->y[0] = -0.7 * H, wall->y[1] = 0.7 * H;
    force->unit = "N";
    force->scale = s->F0 != 0 ? 0.8 * L / fabs(s->F0) : 0;
    for (int f = 0; f < nf; f++) {
        double xm = L + x[f];                                 /* the block's left face */
        mm_scene_spring(spring, f, 0, 0.25 * H, xm, 0.25 * H, 0.2 * H);
        mm_scene_damper(cup, piston, f, 0, -0.25 * H, xm, -0.25 * H, 0.2 * H, L);
        mm_scene_box(mass, f, xm + 0.5 * H, 0, H, H, 0);
        Fv[f] = s->F0 * cos(s->omega * a->t[f]);
        force->x[2 * f] = xm + H, force->y[2 * f] = 0;
        force->x[2 * f + 1] = xm + H + force->scale * Fv[f], force->y[2 * f + 1] = 0;
    }
    return MM_OK;
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

    mm_series *sx = mm_res_series(res, O_XT, n);
    if (!sx)
        return MM_ENOMEM;
    mm_linspace(0, t_end, n, sx->x);
    int rc = mm_ex_sdof_run(&s, t_end, n, sx->x, sx->y, NULL, 5, res, err);
    if (rc != MM_OK)
        return rc;

    if (s.F0 != 0) {
        /* eq. (3) with (4) put into eq. (1): the worst residual over a period
         * against F0 (round-off: a few eps of the largest term) */
        double worst = 0, big = fmax(fabs(s.F0), fmax(s.k, s.m * s.omega * s.omega) * p.X);
        for (int i = 0; i < 16; i++) {
            double wt = 2 * M_PI * i / 16;
            double xp = p.X * cos(wt - p.phase), vp = -p.X * s.omega * sin(wt - p.phase);
            double ap = -s.omega * s.omega * xp;
            worst = fmax(worst, fabs(s.m * ap + s.c * vp + s.k * xp - s.F0 * cos(wt)));
        }
        mm_res_check_abs(res, "steady state X cos(wt - phase) in eq. (1): worst residual [N]", worst, 0,
                         1e-12 * big);
        /* the same measured: an integration started on the steady orbit, when
         * four forcing periods fit the work bound */
        if (2 * 2 * M_PI / s.omega * fmax(fmax(p.omega_n, s.omega), p.zeta > 1 ? 2 * p.zeta * p.omega_n : 0)
            <= MM_SDOF_MAX_RADIANS) {
            double Xm, phm;
            rc = measure_steady(&s, &p, res, &Xm, &phm, err);
            if (rc != MM_OK)
                return rc;
            /* DOP853 at rtol 1e-8 over 2 periods: about 1e-8 relative (seen up
             * to 1e-7 in sweeps); 1e-6 leaves room */
            mm_res_check_rel(res, "X: measured on the steady orbit vs eq. (4)", Xm, p.X, 1e-6);
            /* compare angles, not numbers: -0.001 and 2 pi - 0.001 agree */
            phm = p.phase + remainder(phm - p.phase, 2 * M_PI);
            mm_res_check_abs(res, "phase: measured on the steady orbit vs eq. (4)", phm, p.phase, 1e-6);
        }
    }

    double per_period = p.omega_n > 0 ? (n - 1) / (t_end * fmax(p.omega_n, s.omega) / (2 * M_PI)) : 1e9;
    if (per_period < 8)
        mm_res_warn(res, "the plot has %.1f points per period: it cannot show the oscillation "
                         "(it aliases); shorten t_end or raise points", per_period);
    if (p.zeta < 0.2 && fabs(s.omega / p.omega_n - 1) < 0.05)
        mm_res_warn(res, "near resonance (omega/omega_n = %.3f) with little damping: "
                         "the transient lasts about %.3g s", s.omega / p.omega_n,
                    p.zeta > 0 ? 4 / (p.zeta * p.omega_n) : INFINITY);
    return animate(&s, &p, t_end, res);
}

static const char *const references[] = {
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, sections 3.3-3.4",
    "E. Hairer, S. P. Norsett, G. Wanner, Solving Ordinary Differential Equations I, Springer 1993 (DOP853)",
    NULL,
};

const mm_exercise mm_ex_vib_sdof_forced = {
    .id = "vib-sdof-forced",
    .chapter = 5,
    .section = "5.9.2",
    .title = "Forced vibration of a damped oscillator",
    .summary = "A mass on a spring and damper driven by F0 cos(omega t): transient, steady amplitude and phase lag.",
    .tags = "vibration, 1 DOF, forced, damping, steady state",
    .theory = "exercises/vib/sdof_forced.md",
    .params = params,
    .n_params = MM_COUNT(params),
    .outputs = outputs,
    .n_outputs = MM_COUNT(outputs),
    .references = references,
    .check = check,
    .solve = solve,
};
