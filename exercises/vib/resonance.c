/* resonance.c — vib-resonance: a mass on a spring (and damper) driven at,
 * or near, its natural frequency, from rest.
 *
 *     m x'' + c x' + k x = F0 cos(omega t),  omega = omega_n (1 + detuning),
 *     x(0) = 0,  x'(0) = 0                                              (1)
 *
 * Goal: what resonance does in time.  Without damping and exactly tuned the
 * amplitude grows without bound, linearly: x = F0 t sin(omega t) / (2 m
 * omega) (eq. 3).  Damping stops the growth at X = F0 / (c omega) after a
 * few time constants 1 / (zeta omega_n) (eq. 5); detuning turns the growth
 * into beats (eq. 4).  The response is integrated (DOP853, dense output)
 * and checked against the closed form over the whole run; the growth rate
 * of the envelope is measured from the integrated peaks and checked against
 * F0 / (2 m omega_n).
 * Reference: S. S. Rao, Mechanical Vibrations, 6th ed., sections 3.3-3.4.
 */
#include <math.h>
#include <stdio.h>

#include "mm_exhelp.h"
#include "mm_ode.h"

enum { P_M, P_K, P_C, P_F0, P_DETUNING, P_TEND, P_POINTS };

static const mm_param params[] = {
    [P_M] = {"m", "mass", "kg", MM_REAL, 1, 1e-3, 1e3, .help = "the moving mass"},
    [P_K] = {"k", "stiffness", "N/m", MM_REAL, 100, 1e-2, 1e6, .help = "spring force per metre of stretch"},
    [P_C] = {"c", "damping coefficient", "N s/m", MM_REAL, 0, 0, 1e4,
             .help = "viscous damper force per m/s; 0 lets the amplitude grow without bound"},
    [P_F0] = {"F0", "force amplitude", "N", MM_REAL, 1, 0, 1e4, .help = "amplitude of F0 cos(omega t)"},
    [P_DETUNING] = {"detuning", "detuning", "", MM_REAL, 0, -0.5, 0.5,
                    .help = "relative distance of the forcing frequency from omega_n: omega = omega_n (1 + detuning)"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 10, 1e-3, 1e4,
                .help = "simulated time; at most 1e4 radians of the fastest motion"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 1001, 11, 4001,
                  .help = "samples of the time response returned for the plot"},
};

static mm_sdof model(const mm_value *in)
{
    double wn = sqrt(in[P_K].x / in[P_M].x);
    return (mm_sdof){.m = in[P_M].x, .c = in[P_C].x, .k = in[P_K].x, .F0 = in[P_F0].x,
                     .omega = wn * (1 + in[P_DETUNING].x)};
}

static int check(const mm_value *in, mm_error *err)
{
    mm_sdof s = model(in);
    return mm_ex_sdof_work_check(&s, in[P_TEND].x, err);
}

/* Eq. (1) as y = (x, v). */
static int rhs(double t, const double *y, double *dy, void *ctx)
{
    const mm_sdof *s = ctx;
    dy[0] = y[1];
    dy[1] = (s->F0 * cos(s->omega * t) - s->c * y[1] - s->k * y[0]) / s->m;
    return 0;
}

/* DOP853 at rtol 1e-10 from rest over [0, t_end], dense output on the n
 * times t (x and v may be NULL).  The absolute tolerance is scaled by a
 * bound of the motion that stays finite at resonance: from rest,
 * |x| <= F0 t / (m omega_n) while it grows (the impulse response is at most
 * 1/(m omega_d)), and about X once it has settled; near exact resonance X
 * itself is useless (k - m omega^2 may round to 1e-17 instead of 0). */
static int run(const mm_sdof *s, const mm_sdof_props *p, double t_end, int n, const double *t, double *x,
               double *v, mm_ode_result *r, mm_result *res, mm_error *err)
{
    double y0[2] = {0, 0};
    double scale = s->F0 * t_end / (s->m * p->omega_n);
    if (!p->resonant)
        scale = fmin(scale, p->X);
    return mm_ex_ode_grid(2, rhs, (void *)s, y0, t_end, n, t, 1e-10, 1e-10 * (scale > 0 ? scale : 1), 0,
                          x, v, r, res, err);
}

/* The slowly varying envelope, eq. (6): X |1 - exp(-(zeta omega_n + i delta) t)|
 * (omega_d - omega in place of delta when damped), and its limit F0 t / (2 m omega) at exact,
 * undamped resonance (eq. 3). */
static double envelope(const mm_sdof *s, const mm_sdof_props *p, double t)
{
    if (p->resonant)
        return s->F0 * t / (2 * s->m * s->omega);
    double a = p->zeta * p->omega_n * t, b = (p->omega_d - s->omega) * t;
    double e = exp(-a);
    /* |1 - e^{-a} e^{-ib}|^2 = (1 - e^{-a})^2 + 2 e^{-a} (1 - cos b), the
     * second term as 4 e^{-a} sin^2(b/2) to keep small b accurate */
    double sb = sin(b / 2);
    return p->X * sqrt(-expm1(-a) * -expm1(-a) + 4 * e * sb * sb);
}

/* The shape of the slowly varying envelope, eq. (6) divided by its initial
 * slope: g(t) = |1 - exp(-(a + i b) t)| / |a + i b|, a = zeta omega_n,
 * b = omega_d - omega; g(t) = t when a = b = 0. */
static double shape(double a, double b, double t)
{
    double z = hypot(a, b);
    if (z * t < 1e-8)
        return t;
    double sb = sin(b * t / 2);
    return sqrt(expm1(-a * t) * expm1(-a * t) + 4 * exp(-a * t) * sb * sb) / z;
}

/* The initial growth rate beta of the envelope, measured from the
 * integrated peaks of |x| over [ta, tb] by least squares on
 * peak = beta g(t) (eq. 7).  The peaks are the
 * velocity zeros of a dense-output run sampled 32 times per period; each
 * peak is placed by linear interpolation of v and valued by the cubic
 * Hermite interpolant of (x, v).  Returns the number of peaks used. */
static int measure_growth(const mm_sdof *s, const mm_sdof_props *p, double ta, double tb, double *rate,
                          mm_result *res, mm_error *err, int *rc)
{
    double a = p->zeta * p->omega_n, b = p->omega_d - s->omega;
    double T = 2 * M_PI / s->omega;
    int n = (int)ceil(32 * tb / T) + 1;
    double *t = mm_res_alloc(res, 3 * (size_t)n * sizeof *t), *x = t + n, *v = x + n;
    if (!t) {
        *rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
        return 0;
    }
    mm_linspace(0, tb, n, t);
    mm_ode_result r;
    *rc = run(s, p, tb, n, t, x, v, &r, res, err);
    if (*rc != MM_OK)
        return 0;
    double sgg = 0, sgp = 0;
    int np = 0;
    for (int i = 0; i + 1 < n; i++) {
        if (t[i] < ta || !(v[i] * v[i + 1] < 0 || (v[i + 1] == 0 && v[i] != 0)))
            continue;
        double h = t[i + 1] - t[i], u = v[i] / (v[i] - v[i + 1]);    /* v = 0 at t[i] + u h */
        double h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u);
        double h01 = u * u * (3 - 2 * u), h11 = u * u * (u - 1);
        double xp = h00 * x[i] + h10 * h * v[i] + h01 * x[i + 1] + h11 * h * v[i + 1];
        double g = shape(a, b, t[i] + u * h);
        sgg += g * g;
        sgp += g * fabs(xp);
        np++;
    }
    if (np >= 4)
        *rate = sgp / sgg;
    return np;
}

/* Amplitude over the last two forcing periods of [0, t_end], by projection
 * on cos and sin (exact for a pure harmonic sampled over whole periods). */
static int measure_final(const mm_sdof *s, const mm_sdof_props *p, double t_end, double *amp,
                         mm_result *res, mm_error *err)
{
    enum { PER = 64, N = 2 * PER };
    double T = 2 * M_PI / s->omega, t[N], x[N];
    for (int i = 0; i < N; i++)
        t[i] = t_end - 2 * T + T * i / PER;
    mm_ode_result r;
    int rc = run(s, p, t_end, N, t, x, NULL, &r, res, err);
    if (rc != MM_OK)
        return rc;
    double a = 0, b = 0;
    for (int i = 0; i < N; i++) {
        a += x[i] * cos(s->omega * t[i]);
        b += x[i] * sin(s->omega * t[i]);
    }
    *amp = hypot(a, b) * 2.0 / N;
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    mm_sdof s = model(in);
    mm_sdof_props p;
    mm_sdof_props_get(&s, &p);
    double t_end = in[P_TEND].x, delta = p.omega_n - s.omega;
    int n = (int)in[P_POINTS].x;
    double rate_theory = s.F0 / (2 * s.m * p.omega_n);

    mm_res_scalar_v1(res, "omega_n", "natural frequency", "rad/s", p.omega_n);
    mm_res_scalar_v1(res, "omega", "forcing frequency", "rad/s", s.omega);
    mm_res_scalar_v1(res, "zeta", "damping ratio", "", p.zeta);
    mm_res_scalar_v1(res, "growth_rate_theory", "initial growth of the envelope F0/(2 m omega_n)", "m/s",
                  rate_theory);
    if (!p.resonant) {
        mm_res_scalar_v1(res, "X", "steady amplitude", "m", p.X);
        mm_res_scalar_v1(res, "magnification", "dynamic magnification X/(F0/k)", "", p.magnification);
    } else {
        mm_res_scalar_text_v1(res, "X", "steady amplitude", "m", 0, "none: the amplitude grows without bound");
    }
    if (p.zeta > 0)
        mm_res_scalar_v1(res, "tau", "time constant of the build-up 1/(zeta omega_n)", "s",
                      1 / (p.zeta * p.omega_n));
    if (delta != 0)
        mm_res_scalar_v1(res, "beat_period", "beat period 2 pi/|omega_n - omega|", "s", 2 * M_PI / fabs(delta));

    /* ---- the response from rest, checked against the closed form ---- */
    mm_series *sx = mm_res_series_v1(res, "x", "displacement", "m", "t", "s", n);
    mm_series *se = mm_res_series_v1(res, "envelope", "envelope of the build-up, eq. (6)", "m", "t", "s", n);
    if (!sx || !se)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_linspace(0, t_end, n, sx->x);
    mm_ode_result rr;
    int rc = run(&s, &p, t_end, n, sx->x, sx->y, NULL, &rr, res, err);
    if (rc != MM_OK)
        return rc;
    mm_res_method(res, "dop853 (Dormand-Prince 8(5,3), dense output)", 0);
    mm_res_method_stat(res, "rtol", 1e-10);
    mm_res_method_stat(res, "steps", (double)rr.n_accepted);
    mm_res_method_stat(res, "rejected", (double)rr.n_rejected);
    mm_res_method_stat(res, "evaluations", (double)rr.n_eval);
    mm_res_method_stat(res, "error_estimate", rr.err_sum);
    /* the whole response against the closed form (mm_sdof: exact also at
     * and near resonance, eq. 3-4) at every fifth point */
    double worst = -1, xn = 0, xr = 0, peak = 0;
    for (int i = 0; i < n; i += 5) {
        double ref = mm_sdof_x(&s, &p, sx->x[i], NULL);
        peak = fmax(peak, fabs(ref));
        if (fabs(sx->y[i] - ref) > worst) {
            worst = fabs(sx->y[i] - ref);
            xn = sx->y[i];
            xr = ref;
        }
    }
    mm_res_method_stat(res, "max_error", worst);
    /* DOP853 at rtol 1e-10 over at most 1e4 radians: about 1e-9 of the
     * largest displacement; 1e-6 leaves room */
    mm_res_check_abs(res, "x(t) vs closed form (worst sampled point)", xn, xr, 1e-6 * fmax(peak, 1e-300));
    for (int i = 0; i < n; i++) {
        se->x[i] = sx->x[i];
        se->y[i] = envelope(&s, &p, sx->x[i]);
    }
    if (p.resonant) {
        /* eq. (3) directly, at the last plotted point */
        double t = sx->x[n - 1], ref = s.F0 * t * sin(s.omega * t) / (2 * s.m * s.omega);
        mm_res_check_abs(res, "x(t_end) vs F0 t sin(omega t)/(2 m omega), eq. (3)", sx->y[n - 1], ref,
                         1e-6 * fmax(mm_maxabs(sx->y, n), 1e-300));
    }

    /* ---- the growth rate measured from the peaks ----
     * Window: from 20/omega (the first peaks of t sin t sit off the
     * envelope by 1/(2 omega^2 t)) to 3 time constants or the top of the
     * first beat, at most 200 periods.  Measured only where the envelope
     * model (6) holds: light damping, a beat much slower than the carrier. */
    double T = 2 * M_PI / s.omega, ta = 20 / s.omega, tb = fmin(t_end, 200 * T);
    enum { BY_T_END, BY_DAMPING, BY_BEAT } limit = BY_T_END;   /* what ends the window */
    if (p.zeta > 0 && 3 / (p.zeta * p.omega_n) < tb) {
        tb = 3 / (p.zeta * p.omega_n);
        limit = BY_DAMPING;
    }
    if (p.omega_d != s.omega && M_PI / fabs(p.omega_d - s.omega) < tb) {
        tb = M_PI / fabs(p.omega_d - s.omega);
        limit = BY_BEAT;
    }
    int narrow = p.zeta <= 0.1 && fabs(in[P_DETUNING].x) <= 0.2;
    if (s.F0 > 0 && narrow && tb - ta >= 3 * T) {
        double rate = 0, ref = s.F0 / (s.m * (p.omega_n + s.omega));
        int np = measure_growth(&s, &p, ta, tb, &rate, res, err, &rc);
        if (rc != MM_OK)
            return rc;
        if (np >= 4) {
            mm_res_scalar_v1(res, "growth_rate", "initial growth of the envelope, measured from the peaks", "m/s",
                          rate);
            mm_res_check_rel(res, "envelope growth: measured from the peaks vs F0/(m (omega_n + omega)), eq. (7)",
                             rate, ref, 0.01);
        }
    } else if (s.F0 > 0 && !narrow) {
        mm_res_warn(res, "with zeta > 0.1 or |detuning| > 0.2 the motion hardly grows before damping or "
                    "detuning stop it: the growth rate of the envelope is not measured");
    } else if (s.F0 > 0) {
        /* the window [ta, tb] holds fewer than 3 periods: say what ended it */
        char head[160];
        if (limit == BY_DAMPING)
            snprintf(head, sizeof head, "damping ends the growth after 3 time constants, 3/(zeta omega_n) = "
                     "%.3g s,", tb);
        else if (limit == BY_BEAT)
            snprintf(head, sizeof head, "the detuning turns the growth into a beat, whose first top at "
                     "pi/|omega_d - omega| = %.3g s comes", tb);
        else
            snprintf(head, sizeof head, "t_end = %.3g s comes", tb);
        mm_res_warn(res, "%s less than 3 periods (3 T = %.3g s) after t = 20/omega = %.3g s, where the peaks "
                    "first follow the envelope: too few peaks of growth to fit, so the growth rate of the "
                    "envelope is not measured", head, 3 * T, ta);
    }

    /* ---- the build-up reaches the steady amplitude ---- */
    if (t_end >= 2 * T) {
        double amp;
        rc = measure_final(&s, &p, t_end, &amp, res, err);
        if (rc != MM_OK)
            return rc;
        mm_res_scalar_v1(res, "amplitude_final", "amplitude over the last two periods, measured", "m", amp);
        /* after 20 time constants of the slowest free motion the transient is
         * below (1 + 20) e^-20 = 4e-8 of its start, also near critical damping
         * (overdamped: the slow rate omega_n / (zeta + sqrt(zeta^2 - 1))) */
        double slow = p.zeta < 1 ? p.zeta * p.omega_n : p.omega_n / (p.zeta + sqrt((p.zeta - 1) * (p.zeta + 1)));
        if (!p.resonant && p.zeta > 0 && t_end * slow >= 20)
            mm_res_check_rel(res, "final amplitude: measured vs steady X = F0/|k - m w^2 + i c w|", amp, p.X,
                             1e-4);
    }

    double per_period = (n - 1) / (t_end / T);
    if (per_period < 8)
        mm_res_warn(res, "the plot has %.1f points per period: it cannot show the oscillation "
                         "(it aliases); shorten t_end or raise points", per_period);
    return MM_OK;
}

static const char *const references[] = {
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, sections 3.3-3.4",
    "E. Hairer, S. P. Norsett, G. Wanner, Solving Ordinary Differential Equations I, Springer 1993 (DOP853)",
    NULL,
};

const mm_exercise mm_ex_vib_resonance = {
    .id = "vib-resonance",
    .chapter = 5,
    .section = "5.9.6",
    .title = "Resonance: growth, build-up and beats",
    .summary = "Drive a mass-spring system at its natural frequency from rest: linear growth, damped build-up, beats.",
    .tags = "vibration, 1 DOF, forced, resonance, beats, envelope",
    .theory = "exercises/vib/resonance.md",
    .params = params,
    .n_params = MM_COUNT(params),
    .references = references,
    .check = check,
    .solve = solve,
};
