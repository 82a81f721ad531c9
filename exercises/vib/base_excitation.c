/* base_excitation.c — vib-base-excitation: a mass on a spring and damper
 * whose other ends are attached to a support that moves, y = Y cos(omega t).
 *
 *     m x'' + c x' + k x = k y + c y' = k Y cos(wt) - c Y w sin(wt)      (1)
 *
 * Goal: the transmissibility X/Y (how much of the support's motion reaches
 * the mass), why it is 1 at omega = sqrt(2) omega_n whatever the damping,
 * and why isolation (X < Y) needs omega > sqrt(2) omega_n, where damping
 * makes it worse.  The response from rest is integrated (DOP853, dense
 * output) and checked against the closed form, built from three 1-DOF closed
 * forms (eq. 7); the steady amplitude and phase are measured from a second
 * integration started on the steady orbit.
 * Reference: S. S. Rao, Mechanical Vibrations, 6th ed., section 3.6.
 */
#include <math.h>

#include "mm_exhelp.h"
#include "mm_ode.h"
#include "mm_roots.h"

enum { P_M, P_K, P_C, P_Y, P_OMEGA, P_X0, P_V0, P_TEND, P_POINTS };

static const mm_param params[] = {
    [P_M] = {"m", "mass", "kg", MM_REAL, 1, 1e-3, 1e3, .help = "the moving mass"},
    [P_K] = {"k", "stiffness", "N/m", MM_REAL, 100, 1e-2, 1e6, .help = "spring between support and mass"},
    [P_C] = {"c", "damping coefficient", "N s/m", MM_REAL, 2, 0, 1e4,
             .help = "damper between support and mass; c = 2 sqrt(k m) is critical damping"},
    [P_Y] = {"Y", "support amplitude", "m", MM_REAL, 0.01, 0, 1, .help = "the support moves as Y cos(omega t)"},
    [P_OMEGA] = {"omega", "support frequency", "rad/s", MM_REAL, 8, 1e-3, 1e4,
                 .help = "angular frequency of the support's motion"},
    [P_X0] = {"x0", "initial displacement", "m", MM_REAL, 0, -10, 10,
              .help = "absolute position of the mass at t = 0 (the support is then at Y)"},
    [P_V0] = {"v0", "initial velocity", "m/s", MM_REAL, 0, -1e3, 1e3, .help = "dx/dt at t = 0"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 10, 1e-3, 1e4,
                .help = "simulated time; at most 1e4 radians of the fastest motion"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 501, 11, 4001,
                  .help = "samples of the time response returned for the plot"},
};

typedef struct model {
    double m, k, c, Y, w, x0, v0;
} model;

static model model_of(const mm_value *in)
{
    return (model){.m = in[P_M].x, .k = in[P_K].x, .c = in[P_C].x, .Y = in[P_Y].x,
                   .w = in[P_OMEGA].x, .x0 = in[P_X0].x, .v0 = in[P_V0].x};
}

/* The 1-DOF oscillator of the model with force F0 cos(omega t). */
static mm_sdof sdof(const model *s, double F0, double x0, double v0)
{
    return (mm_sdof){.m = s->m, .c = s->c, .k = s->k, .F0 = F0, .omega = s->w, .x0 = x0, .v0 = v0};
}

/* Transmissibility of eq. (3) at frequency ratio r and damping ratio z. */
static double transmissibility(double r, double z)
{
    double a = 1 - r * r, b = 2 * z * r;
    return sqrt((1 + b * b) / (a * a + b * b));
}

/* Steady state, eqs. (3)-(4): X = T Y and the lag of x behind y. */
static void steady(const model *s, double *T, double *X, double *phase)
{
    double D = s->k - s->m * s->w * s->w, cw = s->c * s->w;
    *T = sqrt((s->k * s->k + cw * cw) / (D * D + cw * cw));
    *X = *T * s->Y;
    *phase = atan2(cw, D) - atan2(cw, s->k);    /* arg(k - m w^2 + i c w) - arg(k + i c w) */
}

/* The exact response, eq. (7): the force k Y cos wt from (x0, v0), plus the
 * response to -c Y w sin wt from rest, which is the velocity of the response
 * u to c Y cos wt from rest minus a free motion started with v = c Y / m. */
typedef struct exact {
    mm_sdof s1, s2, s3;
    mm_sdof_props p1, p2, p3;
} exact;

static void exact_init(const model *s, exact *e)
{
    e->s1 = sdof(s, s->k * s->Y, s->x0, s->v0);
    e->s2 = sdof(s, s->c * s->Y, 0, 0);
    e->s3 = sdof(s, 0, 0, s->c * s->Y / s->m);
    mm_sdof_props_get(&e->s1, &e->p1);
    mm_sdof_props_get(&e->s2, &e->p2);
    mm_sdof_props_get(&e->s3, &e->p3);
}

static double exact_x(const exact *e, double t)
{
    double x = mm_sdof_x(&e->s1, &e->p1, t, NULL);
    if (e->s2.F0 != 0) {
        double u_dot;
        mm_sdof_x(&e->s2, &e->p2, t, &u_dot);
        x += u_dot - mm_sdof_x(&e->s3, &e->p3, t, NULL);
    }
    return x;
}

static int check(const mm_value *in, mm_error *err)
{
    model s = model_of(in);
    mm_sdof o = sdof(&s, s.k * s.Y, s.x0, s.v0);
    mm_sdof_props p;
    mm_sdof_props_get(&o, &p);
    if (p.resonant && s.Y != 0)
        return mm_error_set(err, MM_ERANGE, "omega",
                            "omega = omega_n = %g rad/s with c = 0 has no steady state (the motion grows "
                            "without bound); add damping or move omega (see vib-resonance)", p.omega_n);
    return mm_ex_sdof_work_check(&o, in[P_TEND].x, err);
}

/* Eq. (2) as y = (x, v). */
static int rhs(double t, const double *y, double *dy, void *ctx)
{
    const model *s = ctx;
    double wt = s->w * t;
    dy[0] = y[1];
    dy[1] = (s->k * (s->Y * cos(wt) - y[0]) + s->c * (-s->Y * s->w * sin(wt) - y[1])) / s->m;
    return 0;
}

/* DOP853 at rtol 1e-10 from (x0, v0) over [0, t_end], dense output on the
 * n times t; x receives the displacement.  scale is the expected size of
 * the motion (for the absolute tolerance).  r receives the counters. */
static int integrate(const model *s, double x0, double v0, double t_end, int n, const double *t,
                     double *x, double scale, mm_ode_result *r, mm_result *res, mm_error *err)
{
    double y0[2] = {x0, v0};
    return mm_ex_ode_grid(2, rhs, (void *)s, y0, t_end, n, t, 1e-10, 1e-10 * (scale > 0 ? scale : 1), 0,
                          x, NULL, r, res, err);
}

/* X and phase measured on the steady orbit: start at x_p(0), x_p'(0), run
 * four periods, project the samples on cos and sin (exact for a pure
 * harmonic sampled evenly over whole periods). */
static int measure_steady(const model *s, double X, double phase, double *Xm, double *phm,
                          mm_result *res, mm_error *err)
{
    enum { PER = 64, N = 4 * PER };
    double T = 2 * M_PI / s->w, t[N + 1], x[N + 1];
    mm_linspace(0, 4 * T, N + 1, t);
    mm_ode_result r;
    int rc = integrate(s, X * cos(phase), X * s->w * sin(phase), 4 * T, N + 1, t, x, X, &r, res, err);
    if (rc != MM_OK)
        return rc;
    double a = 0, b = 0;
    for (int i = 0; i < N; i++) {
        a += x[i] * cos(2 * M_PI * i / PER);
        b += x[i] * sin(2 * M_PI * i / PER);
    }
    a *= 2.0 / N;
    b *= 2.0 / N;
    *Xm = hypot(a, b);
    *phm = atan2(b, a);        /* X cos(wt - phase) = X cos(phase) cos wt + X sin(phase) sin wt */
    return MM_OK;
}

static int t_minus_one(double r, double *f, void *ctx)
{
    *f = transmissibility(r, *(const double *)ctx) - 1;
    return 0;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    model s = model_of(in);
    double t_end = in[P_TEND].x;
    int n = (int)in[P_POINTS].x;
    mm_sdof o = sdof(&s, s.k * s.Y, s.x0, s.v0);
    mm_sdof_props p;
    mm_sdof_props_get(&o, &p);
    double r = s.w / p.omega_n, T, X, phase;
    steady(&s, &T, &X, &phase);
    double Z = s.Y * r * r * p.magnification;     /* stretch of the spring, before eq. (5) */

    mm_res_scalar_v1(res, "omega_n", "natural frequency", "rad/s", p.omega_n);
    mm_res_scalar_v1(res, "zeta", "damping ratio", "", p.zeta);
    mm_res_scalar_v1(res, "r", "frequency ratio omega/omega_n", "", r);
    mm_res_scalar_v1(res, "transmissibility", "transmissibility X/Y", "", T);
    mm_res_scalar_v1(res, "X", "steady amplitude of the mass", "m", X);
    mm_res_scalar_v1(res, "phase", "lag of the mass behind the support", "rad", phase);
    mm_res_scalar_v1(res, "Z", "steady amplitude of the spring's stretch x - y", "m", Z);
    mm_res_scalar_v1(res, "force_transmitted", "amplitude of the force on the support, eq. (5)", "N",
                  s.m * s.w * s.w * X);
    mm_res_scalar_text_v1(res, "isolates", "isolation (X < Y)", "", T < 1, T < 1 ? "yes" : "no");

    /* ---- the response from the initial state ---- */
    mm_series *sx = mm_res_series_v1(res, "x", "mass displacement", "m", "t", "s", n);
    mm_series *sy = mm_res_series_v1(res, "y", "support displacement", "m", "t", "s", n);
    if (!sx || !sy)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_linspace(0, t_end, n, sx->x);
    for (int i = 0; i < n; i++) {
        sy->x[i] = sx->x[i];
        sy->y[i] = s.Y * cos(s.w * sx->x[i]);
    }
    double scale = fmax(fmax(fabs(s.x0), fabs(s.v0) / fmax(p.omega_n, 1 / t_end)), fmax(X, s.Y));
    mm_ode_result rr;
    int rc = integrate(&s, s.x0, s.v0, t_end, n, sx->x, sx->y, scale, &rr, res, err);
    if (rc != MM_OK)
        return rc;
    mm_res_method(res, "dop853 (Dormand-Prince 8(5,3), dense output)", 0);
    mm_res_method_stat(res, "rtol", 1e-10);
    mm_res_method_stat(res, "steps", (double)rr.n_accepted);
    mm_res_method_stat(res, "rejected", (double)rr.n_rejected);
    mm_res_method_stat(res, "evaluations", (double)rr.n_eval);
    mm_res_method_stat(res, "error_estimate", rr.err_sum);

    /* the whole response against eq. (7) at every fifth point */
    exact e;
    exact_init(&s, &e);
    double worst = -1, xn = 0, xr = 0, peak = 0;
    for (int i = 0; i < n; i += 5) {
        double ref = exact_x(&e, sx->x[i]);
        peak = fmax(peak, fabs(ref));
        if (fabs(sx->y[i] - ref) > worst) {
            worst = fabs(sx->y[i] - ref);
            xn = sx->y[i];
            xr = ref;
        }
    }
    mm_res_method_stat(res, "max_error", worst);
    /* DOP853 at rtol 1e-10 over at most 1e4 radians: about 1e-9 of the motion */
    mm_res_check_abs(res, "x(t) vs closed form (worst sampled point)", xn, xr, 1e-6 * fmax(peak, scale));

    /* ---- the steady state measured on its orbit ---- */
    if (X > 0 && 4 * 2 * M_PI / s.w * fmax(fmax(p.omega_n, s.w), p.zeta > 1 ? 2 * p.zeta * p.omega_n : 0)
                     <= MM_SDOF_MAX_RADIANS) {
        double Xm, phm;
        rc = measure_steady(&s, X, phase, &Xm, &phm, res, err);
        if (rc != MM_OK)
            return rc;
        phm = phase + remainder(phm - phase, 2 * M_PI);   /* atan2 may give -pi for pi */
        /* DOP853 at rtol 1e-10 over 4 periods: about 1e-10 relative */
        mm_res_check_rel(res, "X: measured on the steady orbit vs T Y, eq. (3)", Xm, X, 1e-7);
        mm_res_check_abs(res, "phase: measured on the steady orbit vs eq. (4)", phm, phase, 1e-7);
    }

    /* ---- transmissibility against the frequency ratio ---- */
    double r_max = fmax(3, 1.5 * r), half = fmin(0.5, 6 * p.zeta);
    static const double zref[2] = {0.1, 0.5};
    static const char *const zname[2] = {"T_zeta_0.1", "T_zeta_0.5"};
    static const char *const zlabel[2] = {"transmissibility, zeta = 0.1", "transmissibility, zeta = 0.5"};
    double *grid = mm_res_alloc(res, (400 + 100) * sizeof *grid);
    if (!grid)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    int ng = mm_ex_grid_refined(0, r_max, 400, 1, half, 100, grid), nf = 0;
    for (int i = 0; i < ng; i++)                 /* undamped: r = 1 itself has no value */
        if (isfinite(transmissibility(grid[i], p.zeta)))
            grid[nf++] = grid[i];
    mm_series *st = mm_res_series_v1(res, "T", "transmissibility X/Y of this system", "", "omega/omega_n", "", nf);
    if (!st)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (int i = 0; i < nf; i++) {
        st->x[i] = grid[i];
        st->y[i] = transmissibility(grid[i], p.zeta);
    }
    for (int k = 0; k < 2; k++) {
        mm_series *sr = mm_res_series_v1(res, zname[k], zlabel[k], "", "omega/omega_n", "", 400);
        if (!sr)
            return mm_error_set(err, MM_ENOMEM, "", "out of memory");
        mm_linspace(0, r_max, 400, sr->x);
        for (int i = 0; i < 400; i++)
            sr->y[i] = transmissibility(sr->x[i], zref[k]);
    }

    /* T = 1 at r = sqrt(2) for every damping, eq. (6): the crossing found by
     * Brent's method on T(r) - 1 over [1.01, 3] */
    double z = p.zeta, lo = 1.01, hi = 3, flo, fhi, rc2, fx, width;
    t_minus_one(lo, &flo, &z);
    t_minus_one(hi, &fhi, &z);
    if (flo > 0 && fhi < 0) {
        rc = mm_roots_brent(t_minus_one, &z, lo, hi, flo, fhi, 1e-14, 200, &rc2, &fx, &width, NULL, NULL,
                            err);
        if (rc != MM_OK)
            return rc;
        mm_res_scalar_v1(res, "r_crossing", "frequency ratio where T = 1 (found by Brent's method)", "", rc2);
        /* T - 1 is computed to about eps; its slope at sqrt(2) is about
         * 2.8/(1 + 8 zeta^2), so heavy damping blunts the crossing */
        mm_res_check_abs(res, "T = 1 crossing found by Brent vs sqrt(2), eq. (6)", rc2, M_SQRT2,
                         1e-12 + 1e-14 * (1 + 8 * z * z));
    }

    if (p.regime == MM_SDOF_UNDER && (n - 1) / (t_end * fmax(p.omega_n, s.w) / (2 * M_PI)) < 8)
        mm_res_warn(res, "the plot has under 8 points per period: it cannot show the oscillation "
                         "(it aliases); shorten t_end or raise points");
    return MM_OK;
}

static const char *const references[] = {
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, section 3.6 (base excitation)",
    "E. Hairer, S. P. Norsett, G. Wanner, Solving Ordinary Differential Equations I, Springer 1993 (DOP853)",
    NULL,
};

const mm_exercise mm_ex_vib_base_excitation = {
    .id = "vib-base-excitation",
    .chapter = 5,
    .section = "5.9.5",
    .title = "Vibration of a moving support (base excitation)",
    .summary = "A mass on a spring and damper whose support moves as Y cos(omega t): transmissibility and isolation.",
    .tags = "vibration, 1 DOF, base excitation, transmissibility, isolation",
    .theory = "exercises/vib/base_excitation.md",
    .params = params,
    .n_params = MM_COUNT(params),
    .references = references,
    .check = check,
    .solve = solve,
};
