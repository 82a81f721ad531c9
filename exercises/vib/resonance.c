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
 * into beats (eq. 4).  The plotted response is the closed form (mm_sdof,
 * exact also at and near resonance); DOP853 integrates eq. (1) beside it
 * and its error is shown and checked.  Everything that depends on
 * omega_n - omega is computed from the detuning itself (k - m omega^2 =
 * -k detuning (2 + detuning)), so a detuning of 1e-12 keeps its digits.  The
 * growth rate of the envelope is measured from the peaks of the motion and
 * checked against eq. (7).
 * Reference: S. S. Rao, Mechanical Vibrations, 6th ed., sections 3.3-3.4.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>

#include "mm_exhelp.h"
#include "mm_fourier.h"
#include "mm_peaks.h"
#include "mm_vib.h"

enum { P_M, P_K, P_C, P_F0, P_DETUNING, P_TEND, P_POINTS };

static const mm_param params[] = {
    [P_M] = {"m", "mass", "kg", MM_REAL, 1, 1e-3, 1e3,
             .help = "the moving mass, 1 g to 1 t (a lab model to a machine)"},
    [P_K] = {"k", "stiffness", "N/m", MM_REAL, 100, 1e-2, 1e6,
             .help = "spring force per metre of stretch; with m it sets omega_n between 3e-3 and 3e4 rad/s"},
    [P_C] = {"c", "damping coefficient", "N s/m", MM_REAL, 0, 0, 1e4,
             .help = "viscous damper force per m/s; 0 lets the amplitude grow without bound"},
    [P_F0] = {"F0", "force amplitude", "N", MM_REAL, 1, 0, 1e4, .help = "amplitude of F0 cos(omega t), up to 10 kN"},
    [P_DETUNING] = {"detuning", "detuning", "", MM_REAL, 0, -0.5, 0.5,
                    .help = "relative distance of the forcing frequency from omega_n: omega = omega_n (1 + detuning); "
                            "within +-0.5, beyond which it is no longer near resonance"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 10, 1e-3, 1e4,
                .help = "simulated time; at most 2e4 radians of the fastest motion (3,200 periods), "
                        "what one request integrates in 250 ms"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 501, 11, 4001,
                  .help = "samples of the time response returned for the plot (a plot shows no more)"},
};

enum { O_OMEGA_N, O_OMEGA, O_ZETA, O_RATE_TH, O_X, O_MAGN, O_TAU, O_BEAT, O_AMP_FINAL, O_XT, O_ENV, O_ERR,
       O_ANIM };

static const mm_output outputs[] = {
    [O_OMEGA_N] = MM_SCALAR("omega_n", "natural frequency", "rad/s", .flags = MM_EXACT),
    [O_OMEGA] = MM_SCALAR("omega", "forcing frequency omega_n (1 + detuning)", "rad/s", .flags = MM_EXACT),
    [O_ZETA] = MM_SCALAR("zeta", "damping ratio", "", .flags = MM_EXACT),
    [O_RATE_TH] = MM_SCALAR("growth_rate_theory", "initial growth of the envelope F0/(2 m omega_n)", "m/s",
                            .flags = MM_ANSWER | MM_EXACT),
    [O_X] = MM_SCALAR("X", "steady amplitude", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_MAGN] = MM_SCALAR("magnification", "dynamic magnification X/(F0/k)", "", .flags = MM_EXACT),
    [O_TAU] = MM_SCALAR("tau", "time constant of the build-up 1/(zeta omega_n)", "s", .flags = MM_ANSWER | MM_EXACT),
    [O_BEAT] = MM_SCALAR("beat_period", "beat period 2 pi/|omega_n - omega| = 2 pi/(omega_n |detuning|)", "s",
                         .flags = MM_ANSWER | MM_EXACT),
    [O_AMP_FINAL] = MM_SCALAR("amplitude_final", "amplitude over the last two periods", "m"),
    [O_XT] = MM_SERIES("x", "displacement (closed form)", "m", "t", "s", .figure = "response"),
    [O_ENV] = MM_SERIES("envelope", "envelope of the build-up, eq. (6)", "m", "t", "s", .figure = "response",
                        .role = "reference"),
    [O_ERR] = MM_SERIES("error_dop853", "x by DOP853 minus the closed form", "m", "t", "s", .figure = "error"),
    [O_ANIM] = MM_ANIMATION("the mass on its spring, driven at resonance"),
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

/* The properties of the model with everything that depends on
 * omega_n - omega taken from the detuning d itself: k - m omega^2 =
 * -k d (2 + d) exactly, so X, phase and the beat keep their digits at
 * d = 1e-12 (from omega, rounded to 1e-16, they would keep 4).  Without
 * damping only d = 0 is resonant. */
static void props(const mm_sdof *s, double d, mm_sdof_props *p)
{
    mm_sdof_props_get(s, p);
    double re = -s->k * d * (2 + d), im = s->c * s->omega, mod = hypot(re, im);
    p->stiffness_re = re;
    p->resonant = mod == 0;
    p->X = p->resonant ? 0 : s->F0 / mod;
    p->phase = p->resonant ? M_PI / 2 : atan2(im, re);
    p->magnification = p->resonant ? 0 : s->k / mod;
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

/* The initial growth rate beta of the envelope, measured from the peaks
 * of |x| over [ta, tb] by least squares on peak = beta g(t) (eq. 7).  The
 * peaks are the velocity zeros of the motion sampled 32 times a period;
 * each is placed by linear interpolation of v and valued by the cubic
 * Hermite interpolant of (x, v) (mm_peaks_hermite).  Returns the number of
 * peaks used (MM_ENOMEM as -1). */
static int measure_growth(const mm_sdof *s, const mm_sdof_props *p, double ta, double tb, double *rate,
                          mm_result *res)
{
    double a = p->zeta * p->omega_n, b = p->omega_d - s->omega;
    double T = 2 * M_PI / s->omega;
    int n = (int)ceil(32 * tb / T) + 1;
    double *t = mm_res_alloc(res, 5 * (size_t)n * sizeof *t), *x = t + n, *v = x + n, *tp = v + n, *xp = tp + n;
    if (!t)
        return -1;
    mm_linspace(0, tb, n, t);
    for (int i = 0; i < n; i++)
        x[i] = mm_sdof_x(s, p, t[i], &v[i]);
    int np = mm_peaks_hermite(n, t, x, v, ta, n, tp, xp);
    double sgg = 0, sgp = 0;
    for (int i = 0; i < np; i++) {
        double g = shape(a, b, tp[i]);
        sgg += g * g;
        sgp += g * fabs(xp[i]);
    }
    if (np >= 4)
        *rate = sgp / sgg;
    return np;
}

/* Amplitude over the last two forcing periods of [0, t_end], by projection
 * of the closed form on cos and sin (mm_fourier_harmonic). */
static int final_amplitude(const mm_sdof *s, const mm_sdof_props *p, double t_end, double *amp,
                           double *transient, mm_error *err)
{
    enum { PER = 64, N = 2 * PER };
    double T = 2 * M_PI / s->omega, x[N], phase;
    *transient = 0;
    for (int i = 0; i < N; i++) {
        double t = t_end - 2 * T + T * i / PER;
        x[i] = mm_sdof_x(s, p, t, NULL);
        *transient = fmax(*transient, fabs(x[i] - p->X * cos(s->omega * t - p->phase)));
    }
    return mm_fourier_harmonic(x, N, PER, amp, &phase, err);
}

/* The growth measured where the envelope model (6) holds: light damping, a
 * beat much slower than the carrier.  Window: from 20/omega (the first
 * peaks of t sin t sit off the envelope by 1/(2 omega^2 t)) to 3 time
 * constants or the top of the first beat, at most 200 periods. */
static int growth(const mm_sdof *s, const mm_sdof_props *p, double detuning, double t_end, mm_result *res)
{
    double T = 2 * M_PI / s->omega, ta = 20 / s->omega, tb = fmin(t_end, 200 * T);
    const char *ended = "t_end = %.3g s comes";
    if (p->zeta > 0 && 3 / (p->zeta * p->omega_n) < tb) {
        tb = 3 / (p->zeta * p->omega_n);
        ended = "damping ends the growth after 3 time constants, 3/(zeta omega_n) = %.3g s,";
    }
    if (p->omega_d != s->omega && M_PI / fabs(p->omega_d - s->omega) < tb) {
        tb = M_PI / fabs(p->omega_d - s->omega);
        ended = "the detuning turns the growth into a beat, whose first top at pi/|omega_d - omega| = %.3g s comes";
    }
    if (s->F0 == 0)
        return MM_OK;
    if (!(p->zeta <= 0.1 && fabs(detuning) <= 0.2)) {
        mm_res_warn(res, "with zeta > 0.1 or |detuning| > 0.2 the motion hardly grows before damping or "
                         "detuning stop it: the growth rate of the envelope is not measured");
        return MM_OK;
    }
    if (tb - ta < 3 * T) {
        char head[160];
        snprintf(head, sizeof head, ended, tb);
        mm_res_warn(res, "%s less than 3 periods (3 T = %.3g s) after t = 20/omega = %.3g s, where the peaks "
                         "first follow the envelope: too few peaks of growth to fit, so the growth rate of the "
                         "envelope is not measured", head, 3 * T, ta);
        return MM_OK;
    }
    double rate = 0, ref = s->F0 / (s->m * (p->omega_n + s->omega));
    int np = measure_growth(s, p, ta, tb, &rate, res);
    if (np < 0)
        return MM_ENOMEM;
    if (np < 4)
        return MM_OK;
    mm_res_method_stat(res, "growth_rate_measured", rate);
    /* the peaks sit off the envelope by about 1/(2 (omega t)^2) of it (the
     * first at t = 20/omega: 1/800) and the Hermite value of a peak is good
     * to (omega h)^4/384 with h a 32nd of a period: the fit is within
     * 1/(2 (omega ta)^2) of beta */
    return mm_res_check_rel(res, "envelope growth: measured from the peaks vs F0/(m (omega_n + omega)), eq. (7)",
                            rate, ref, 0.5 / ((s->omega * ta) * (s->omega * ta)) + 4e-6);
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    mm_sdof s = model(in);
    double d = in[P_DETUNING].x, t_end = in[P_TEND].x;
    mm_sdof_props p;
    props(&s, d, &p);
    int n = (int)in[P_POINTS].x;

    mm_res_scalar(res, O_OMEGA_N, p.omega_n);
    mm_res_scalar(res, O_OMEGA, s.omega);
    mm_res_scalar(res, O_ZETA, p.zeta);
    mm_res_scalar(res, O_RATE_TH, s.F0 / (2 * s.m * p.omega_n));
    if (!p.resonant) {
        mm_res_scalar(res, O_X, p.X);
        mm_res_scalar(res, O_MAGN, p.magnification);
    } else {
        mm_res_scalar_text(res, O_X, 0, "none: the amplitude grows without bound");
    }
    if (p.zeta > 0)
        mm_res_scalar(res, O_TAU, 1 / (p.zeta * p.omega_n));
    if (d != 0)
        mm_res_scalar(res, O_BEAT, 2 * M_PI / (p.omega_n * fabs(d)));

    /* ---- the response from rest: the closed form, DOP853 beside it ---- */
    mm_series *sx = mm_res_series(res, O_XT, n), *se = mm_res_series(res, O_ENV, n);
    int rc = se ? mm_ex_sdof_plot(&s, &p, t_end, sx, mm_res_series(res, O_ERR, n), res, err) : MM_ENOMEM;
    if (rc != MM_OK)
        return rc;
    for (int i = 0; i < n; i++) {
        se->x[i] = sx->x[i];
        se->y[i] = envelope(&s, &p, sx->x[i]);
    }
    mm_ex_round_sig(se->y, n, 6);                             /* the envelope: a guide to the eye */
    if (p.resonant && s.F0 != 0) {
        /* the closed form's stable product formula against eq. (3) written out */
        double t = t_end, ref = s.F0 * t * sin(s.omega * t) / (2 * s.m * s.omega);
        mm_check_residual(res, "x(t_end): closed form (sinc product) vs F0 t sin(omega t)/(2 m omega), eq. (3) "
                               "(scale: F0 t/(2 m omega) times omega t)",
                          mm_sdof_x(&s, &p, t, NULL) - ref, s.F0 * t / (2 * s.m * s.omega) * (1 + s.omega * t), 8);
    }
    if ((rc = growth(&s, &p, d, t_end, res)) != MM_OK)
        return rc;

    /* ---- the build-up reaches the steady amplitude ---- */
    double T = 2 * M_PI / s.omega;
    if (t_end >= 2 * T) {
        double amp, transient;
        if ((rc = final_amplitude(&s, &p, t_end, &amp, &transient, err)) != MM_OK)
            return rc;
        /* of the closed form, but sampled at phases omega t near omega t_end,
         * each rounded to eps of it */
        mm_res_scalar_err(res, O_AMP_FINAL, amp, 8 * DBL_EPSILON * (1 + s.omega * t_end) * amp, MM_ERR_BOUND);
        /* what is left of the free motion, at most `transient` at the
         * samples, moves the projected amplitude by at most twice that */
        if (!p.resonant && p.zeta > 0 && transient < 0.1 * p.X)
            mm_res_check_abs(res, "final amplitude vs steady X = F0/|k - m w^2 + i c w|, within twice the "
                                  "free motion left", amp, p.X, 2.2 * transient + mm_ex_roundoff(t_end * s.omega, p.X));
    }
    mm_ex_warn_aliasing(res, n, t_end, fmax(p.omega_n, s.omega), "shorten t_end or raise points");

    /* the mass swinging wider and wider, frames from the closed form */
    return mm_vib_sdof_animate(res, &s, &p, t_end, T, p.zeta > 0 ? 35 : 24, 1, NULL, p.zeta > 0);
}

static const char *const references[] = {
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, sections 3.3-3.4",
    "E. Hairer, S. P. Norsett, G. Wanner, Solving Ordinary Differential Equations I, Springer 1993 (DOP853)",
    NULL,
};

const mm_exercise mm_ex_vib_resonance = {
    .id = "vib-resonance", .chapter = 5, .section = "5.9.6", .title = "Resonance: growth, build-up and beats",
    .summary = "Drive a mass-spring system at its natural frequency from rest: linear growth, damped build-up, beats.",
    .tags = "vibration, 1 DOF, forced, resonance, beats, envelope", .theory = "exercises/vib/resonance.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
