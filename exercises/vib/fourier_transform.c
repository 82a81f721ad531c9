/* fourier_transform.c — vib-fourier-transform: the spectrum of a single
 * pulse (rectangular, triangular, Gaussian, half-sine) by the FFT, against
 * the closed-form Fourier integral.
 *
 *     X(f) = int x(t) exp(-2 pi i f t) dt                                (1)
 *
 * Goal: see that a short pulse has a wide spectrum (first zero at a few
 * times 1/duration, eqs. 3-6 of the theory), that the FFT of samples times
 * dt approximates the integral (eq. 7) with an error set by the sampling
 * (eq. 8: the spectrum folded back from multiples of fs; first order at a
 * jump), and that a pulse centred at t_c has the phase exp(-2 pi i f t_c)
 * (eq. 2), handled by measuring time from t = 0, not from the first sample.
 * The printed answers are the closed forms (area, first zero or
 * half-amplitude frequency); the FFT's area and the zero located by Brent's
 * method on the transform of the samples summed directly (no FFT) are shown
 * beside them with their errors.  Checks: the complex FFT spectrum against
 * the closed form in a band, within the error bound of eq. (8) or (9); the
 * located zero and the FFT's area against the closed forms.
 * Reference: R. N. Bracewell, The Fourier Transform and Its Applications,
 * 3rd ed., McGraw-Hill 2000, ch. 2-6 and 10; S. S. Rao, Mechanical
 * Vibrations, 6th ed., section 4.8 (response spectrum of pulses).
 */
#include <float.h>
#include <math.h>

#include "mm_exhelp.h"
#include "mm_fourier.h"
#include "mm_roots.h"

enum { P_PULSE, P_TAU, P_A, P_TC, P_FS, P_N };
enum { PU_RECT, PU_TRI, PU_GAUSS, PU_HSINE };

static const char *const pulses[] = {"rectangular", "triangular", "gaussian", "half-sine", NULL};

#define MAX_N 65536
#define MIN_PER_PULSE 8        /* samples across the pulse, at least */
#define GAUSS_SIGMAS 8         /* the Gaussian is kept out to +-8 sigma: exp(-32) */
#define PLOT_MAX 1001

static const mm_param params[] = {
    [P_PULSE] = {"pulse", "pulse shape", "", MM_CHOICE, PU_RECT, 0, 0, .choices = pulses,
                 .help = "rectangular: a constant A; triangular: up to A and down; gaussian: bell with "
                         "sigma = duration/6; half-sine: A sin over the duration"},
    [P_TAU] = {"duration", "pulse duration", "s", MM_REAL, 0.1, 1e-4, 10,
               .help = "length of the pulse, 0.1 ms (an impact) to 10 s; the spectrum's width scales as 1/duration"},
    [P_A] = {"A", "peak value", "", MM_REAL, 1, 1e-6, 1e6,
             .help = "the pulse's largest value (a force in N, an acceleration in m/s^2, ...); it only scales"},
    [P_TC] = {"t_c", "pulse centre", "s", MM_REAL, 0.2, -10, 10,
              .help = "time of the middle of the pulse, within 10 s of t = 0; it changes only the phase of the spectrum"},
    [P_FS] = {"fs", "sampling frequency", "Hz", MM_REAL, 1000, 1, 1e6,
              .help = "samples per second, up to 1 MHz; at least 8 across the pulse"},
    [P_N] = {"N", "number of samples", "", MM_INT, 1024, 16, MAX_N,
             .help = "samples in the window of N/fs seconds centred on the pulse; frequency step fs/N; "
                     "at most 65536 (the direct sums that locate the zero cost N each)"},
};

enum { O_AREA, O_AREA_FFT, O_HALF_F, O_HALF_FT, O_ZERO, O_ZERO_T, O_DF, O_WINDOW, O_MAXERR, O_BAND, O_MAG,
       O_MAG_EXACT, O_PULSE };

static const mm_output outputs[] = {
    [O_AREA] = MM_SCALAR("area", "pulse area X(0) = int x dt, eqs. (3)-(6)", "s", .flags = MM_ANSWER | MM_EXACT),
    [O_AREA_FFT] = MM_SCALAR("area_fft", "X(0) by the FFT of the samples, eq. (7)", "s"),
    [O_HALF_F] = MM_SCALAR("half_amplitude_frequency", "frequency where |X| falls to half of X(0), eq. (5)", "Hz",
                           .flags = MM_ANSWER | MM_EXACT),
    [O_HALF_FT] = MM_SCALAR("half_amplitude_times_duration", "that frequency times the duration", "",
                            .flags = MM_EXACT),
    [O_ZERO] = MM_SCALAR("first_zero", "first zero of the spectrum, eqs. (3), (4), (6)", "Hz",
                         .flags = MM_ANSWER | MM_EXACT),
    [O_ZERO_T] = MM_SCALAR("first_zero_times_duration", "first zero times the duration", "", .flags = MM_EXACT),
    [O_DF] = MM_SCALAR("df", "frequency step fs/N", "Hz", .flags = MM_EXACT),
    [O_WINDOW] = MM_SCALAR("window", "window length N/fs", "s", .flags = MM_EXACT),
    [O_MAXERR] = MM_SCALAR("max_error_band", "largest |FFT - exact| below the band edge, relative to X(0)", ""),
    [O_BAND] = MM_SCALAR("band", "band edge of the check: min(fs/4, 10/duration)", "Hz", .flags = MM_EXACT),
    [O_MAG] = MM_SERIES("magnitude", "|X(f)| by FFT", "s", "f", "Hz", .figure = "spectrum", .mark = "dots"),
    [O_MAG_EXACT] = MM_SERIES("magnitude_exact", "|X(f)| exact", "s", "f", "Hz", .figure = "spectrum",
                              .role = "reference"),
    [O_PULSE] = MM_SERIES("pulse", "the pulse x(t)", "", "t", "s", .figure = "pulse"),
};

static double sigma_of(double tau) { return tau / 6; }

/* Time the pulse lasts (its support; for the Gaussian, +-8 sigma). */
static double support(int pulse, double tau)
{
    return pulse == PU_GAUSS ? 2 * GAUSS_SIGMAS * sigma_of(tau) : tau;
}

static int check(const mm_value *in, mm_error *err)
{
    int pulse = (int)in[P_PULSE].x;
    double tau = in[P_TAU].x, fs = in[P_FS].x, n = in[P_N].x;
    if (fs * tau < MIN_PER_PULSE)
        return mm_error_set(err, MM_ERANGE, "fs",
                            "fs must give at least %d samples across the pulse: fs >= %g Hz for a "
                            "duration of %g s; got %g Hz", MIN_PER_PULSE, MIN_PER_PULSE / tau, tau, fs);
    double need = ceil(support(pulse, tau) * fs) + 3;
    if (n < need)
        return mm_error_set(err, MM_ERANGE, "N",
                            "N must be at least %.0f so that the window N/fs covers the whole %s pulse "
                            "(%g s); got %.0f", need, pulses[pulse], support(pulse, tau), n);
    return MM_OK;
}

/* The pulse at s = t - t_c.  A sample exactly on a jump of the rectangle
 * takes the mean of the two sides (what the Fourier integral converges to). */
static double pulse_at(int pulse, double tau, double A, double s, double dt)
{
    double a = fabs(s), h = tau / 2;
    switch (pulse) {
    case PU_RECT:
        if (fabs(a - h) <= 1e-9 * dt)
            return A / 2;
        return a < h ? A : 0;
    case PU_TRI:
        return a < h ? A * (1 - a / h) : 0;
    case PU_GAUSS: {
        double sg = sigma_of(tau);
        return A * exp(-0.5 * (s / sg) * (s / sg));
    }
    default:
        return a < h ? A * cos(M_PI * s / tau) : 0;
    }
}

static double sinc(double x) { return x == 0 ? 1 : sin(M_PI * x) / (M_PI * x); }

/* X_c(f) = X(f) exp(2 pi i f t_c), real for these even pulses: eqs. (3)-(6). */
static double exact_c(int pulse, double tau, double A, double f)
{
    switch (pulse) {
    case PU_RECT:
        return A * tau * sinc(f * tau);
    case PU_TRI:
        return 0.5 * A * tau * sinc(0.5 * f * tau) * sinc(0.5 * f * tau);
    case PU_GAUSS: {
        double sg = sigma_of(tau);
        return A * sg * sqrt(2 * M_PI) * exp(-2 * M_PI * M_PI * sg * sg * f * f);
    }
    default:            /* (2 A tau / pi) cos(pi f tau) / (1 - 4 f^2 tau^2), written without 0/0 at f tau = 1/2 */
        f = fabs(f);
        return A * tau * sinc(f * tau - 0.5) / (1 + 2 * f * tau);
    }
}

/* A bound of |X_c(g)| that falls monotonically with |g| (|g| large enough):
 * used for the folded spectrum of eq. (8). */
static double envelope(int pulse, double tau, double A, double g)
{
    g = fabs(g);
    switch (pulse) {
    case PU_TRI:   return 2 * A / (M_PI * M_PI * tau * g * g);
    case PU_HSINE: return 2 * A * tau / M_PI / (4 * g * g * tau * tau - 1);
    default:       return fabs(exact_c(PU_GAUSS, tau, A, g));
    }
}

/* Bound of |FFT dt - X| at frequency f <= fs/4.  Eq. (8) (Poisson):
 * the samples see sum_m X(f - m fs), so the error is at most the sum of the
 * envelope over m != 0 (64 terms each side and a tail bound for 1/g^2).
 * Eq. (9) for the rectangle: its jumps make the rule first order, error
 * A |w_eff - tau| plus the trapezoid term A tau (2 pi f dt)^2 / 6 (the sum
 * does not converge absolutely there, so eq. (8) cannot bound it). */
static double error_bound(int pulse, double tau, double A, double fs, double f, double w_eff)
{
    double dt = 1 / fs;
    if (pulse == PU_RECT)   /* a quarter more for the higher-order terms left out */
        return 1.25 * (A * fabs(w_eff - tau) + A * tau * pow(2 * M_PI * f * dt, 2) / 6);
    double sum = 0;
    for (int m = 1; m <= 64; m++)
        sum += envelope(pulse, tau, A, m * fs - f) + envelope(pulse, tau, A, m * fs + f);
    if (pulse != PU_GAUSS)   /* sum_{m>64} of C/((m - 1/4) fs)^2, both signs */
        sum += 2 * envelope(pulse, tau, A, fs) * 1.2 / 63;
    return sum;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    const int pulse = (int)in[P_PULSE].x;
    const double tau = in[P_TAU].x, A = in[P_A].x, tc = in[P_TC].x, fs = in[P_FS].x;
    const long n = (long)in[P_N].x, m = n / 2, nb = (long)mm_fourier_bins((size_t)n);
    const double dt = 1 / fs, t0 = tc - (double)m * dt;   /* sample m is the pulse centre */

    double *x = mm_res_alloc(res, sizeof *x * (size_t)n);
    double *freq = mm_res_alloc(res, sizeof *freq * (size_t)nb);
    double *re = mm_res_alloc(res, sizeof *re * (size_t)nb), *im = mm_res_alloc(res, sizeof *im * (size_t)nb);
    if (!x || !freq || !re || !im)
        return MM_ENOMEM;
    for (long j = 0; j < n; j++)
        x[j] = pulse_at(pulse, tau, A, (double)(j - m) * dt, dt);   /* s from whole steps: exactly symmetric */

    /* eq. (7): X(f_k) ~ dt exp(-2 pi i f_k t0) FFT_k, with the origin moved to t = 0 */
    int rc = mm_fourier_pulse_transform(x, (size_t)n, dt, t0, freq, re, im, err);
    if (rc != MM_OK)
        return rc;

    /* effective width of the sampled rectangle: the samples inside, or tau
     * when the jumps fall on samples (they then carry A/2) */
    double h = tau / 2;
    long inside = (long)floor(h / dt + 1e-9);
    int on_edge = fabs((double)inside * dt - h) <= 1e-9 * dt;
    double w_eff = on_edge ? tau : (2 * inside + 1) * dt;

    /* ---- the band check: complex error, phase included ---- */
    double X0 = exact_c(pulse, tau, A, 0);
    double f_band = fmin(fs / 4, 10 / tau);
    double worst = 0, worst_ratio = 0, tol_at_worst = 0, max_err = 0;
    long nband = 0;
    for (long k = 0; k < nb && freq[k] <= f_band; k++, nband++) {
        double xc = exact_c(pulse, tau, A, freq[k]);
        double u = freq[k] * tc;
        u -= nearbyint(u);                                   /* exp(-2 pi i f t_c), eq. (2) */
        double er = xc * cos(2 * M_PI * u), ei = -xc * sin(2 * M_PI * u);
        double e = hypot(re[k] - er, im[k] - ei);
        /* plus rounding: of the FFT, and of the phases 2 pi f t (both sides
         * round f t_c and f t0, each to eps |f t| cycles) */
        double tol = error_bound(pulse, tau, A, fs, freq[k], w_eff) + 64 * DBL_EPSILON * log2((double)n) * X0 +
                     8 * M_PI * DBL_EPSILON * freq[k] * (fabs(tc) + fabs(t0) + dt) * X0;
        max_err = fmax(max_err, e);
        if (e / tol > worst_ratio) {
            worst_ratio = e / tol;
            tol_at_worst = tol;
            worst = e;
        }
    }
    if (nband == 0)
        return mm_error_set(err, MM_EINTERNAL, "", "no bin in the band");

    /* ---- first zero (half amplitude for the Gaussian), by Brent on the
     * directly summed transform of the samples ---- */
    static const double zero_times_tau[] = {[PU_RECT] = 1, [PU_TRI] = 2, [PU_HSINE] = 1.5};
    long half = (long)ceil(0.5 * support(pulse, tau) / dt) + 1;
    if (half > m)
        half = m;
    if (half > n - 1 - m)
        half = n - 1 - m;
    /* X_c(f) of the samples summed directly (mm_fourier_even_transform): at
     * any f, not only at the bins */
    mm_fourier_even d = {.x = x, .m = m, .half = half, .dt = dt, .level = 0};
    double f_ref, fz;
    if (pulse == PU_GAUSS) {
        d.level = X0 / 2;
        f_ref = sqrt(log(2) / 2) / (M_PI * sigma_of(tau));
    } else {
        f_ref = zero_times_tau[pulse] / tau;
    }
    /* scan in steps of 1/(16 tau) up to 4/tau for the first sign change; the
     * triangle's spectrum touches zero without changing sign (sinc^2), so
     * there the derivative's sign change (the first minimum) is sought */
    d.deriv = pulse == PU_TRI;
    long evals = 0;
    int iters;
    if ((rc = mm_roots_first(mm_fourier_even_transform, &d, 1 / (16 * tau), d.deriv, 64, 1e-12 / tau, 200, &fz,
                             &iters, &evals, err)) != MM_OK)
        return rc;
    if (isnan(fz))
        return mm_error_set(err, MM_EINTERNAL, "", "no zero found below 4/duration");
    /* how far the zero may move.  A simple zero: the error bound at f_ref
     * over the slope of the exact spectrum there (central difference of the
     * closed form).  The triangle's double zero X ~ c (f - f_ref)^2,
     * c = A tau^3 / 8: an error B can move the minimum by sqrt(2 B / c);
     * taken with c/2 for the curvature's change nearby. */
    /* The samples of a rectangle whose ends fall on samples (half weight
     * there) and of a triangle whose half-width is a whole number of steps
     * have a transform with exactly the continuous pulse's zeros and area:
     * A dt sin(pi f tau) cot(pi f dt), and (A/M) dt sin^2(M th/2)/sin^2(th/2),
     * th = 2 pi f dt, M = tau/(2 dt).  Then only rounding separates them. */
    long M2 = (long)nearbyint(tau / (2 * dt));
    int exact_samples = (pulse == PU_RECT && on_edge) ||
                        (pulse == PU_TRI && M2 > 0 && fabs((double)M2 * dt - tau / 2) <= 1e-9 * dt);
    double rnd = 64 * DBL_EPSILON * (double)half * A * dt;       /* rounding of a direct sum */
    double B = (exact_samples ? 0 : error_bound(pulse, tau, A, fs, f_ref, w_eff)) + rnd;
    double tol_f, brent = 4 * (2 * DBL_EPSILON * f_ref + 1e-12 / tau);
    if (pulse == PU_TRI && exact_samples) {
        /* the minimum of X ~ c (f - f_ref)^2 by the zero of X': its rounding
         * (times 2 pi half dt) over X'' = 2 c, c = A tau^3 / 8 */
        tol_f = brent + rnd * 2 * M_PI * (double)half * dt / (A * tau * tau * tau / 4);
    } else if (pulse == PU_TRI) {
        /* an error B can move the double zero X ~ c (f - f_ref)^2 by sqrt(2 B / c);
         * taken with c/2 for the curvature's change nearby */
        tol_f = sqrt(4 * B / (A * tau * tau * tau / 8)) + brent;
    } else {
        double dfd = 1e-6 / tau;
        double slope = (exact_c(pulse, tau, A, f_ref + dfd) - exact_c(pulse, tau, A, f_ref - dfd)) / (2 * dfd);
        tol_f = 2 * B / fabs(slope) + brent;
    }
    double tol_area = (exact_samples ? 0 : error_bound(pulse, tau, A, fs, 0, w_eff)) +
                      4 * DBL_EPSILON * (double)n * A * dt;

    /* ---- scalars: the closed forms, the numerical values beside them ---- */
    mm_res_scalar(res, O_AREA, X0);
    mm_ex_scalar_beside(res, O_AREA_FFT, re[0], X0, 4 * DBL_EPSILON * X0);
    if (pulse == PU_GAUSS) {
        mm_res_scalar(res, O_HALF_F, f_ref);
        mm_res_scalar(res, O_HALF_FT, f_ref * tau);
    } else {
        mm_res_scalar(res, O_ZERO, f_ref);
        mm_res_scalar(res, O_ZERO_T, zero_times_tau[pulse]);
    }
    mm_res_scalar(res, O_DF, fs / (double)n);
    mm_res_scalar(res, O_WINDOW, (double)n / fs);
    /* its rounding, relative to X(0): the FFT's, and the phases' 2 pi f t_c
     * and 2 pi f t0 up to the band edge (the same terms the band check
     * allows each bin; a script that forms exp(-2 pi i f t_c) without
     * reducing f t_c lands that far away: 1.6e-12 seen where the FFT's
     * term alone said 1.1e-13) */
    double maxerr_err = 64 * DBL_EPSILON * log2((double)n) +
                        8 * M_PI * DBL_EPSILON * f_band * (fabs(tc) + fabs(t0) + dt);
    mm_res_scalar_err(res, O_MAXERR, max_err / X0, maxerr_err, MM_ERR_BOUND);
    mm_res_scalar(res, O_BAND, f_band);

    /* ---- checks ---- */
    mm_res_check_abs(res, pulse == PU_RECT
                              ? "spectrum: FFT vs closed form (complex, phase included) in the band, bound eq. (9) "
                                "at the worst bin [s]"
                              : "spectrum: FFT vs closed form (complex, phase included) in the band, folding bound "
                                "eq. (8) at the worst bin [s]",
                     worst, 0, tol_at_worst);
    mm_res_check_abs(res, pulse == PU_GAUSS
                              ? "half-amplitude frequency: Brent on the direct sum vs sqrt(ln 2 / 2)/(pi sigma) [Hz]"
                              : "first zero: Brent on the direct sum of the samples vs eqs. (3)-(6) [Hz]",
                     fz, f_ref, tol_f);
    mm_res_check_abs(res, "area X(0): FFT vs the closed form A tau, A tau/2, ... [s]", re[0], X0, tol_area);

    /* ---- series ---- */
    double f_plot = fmin(fs / 2, 8 / tau);
    long nplot = 0;
    while (nplot < nb && freq[nplot] <= f_plot)
        nplot++;
    long stride = (nplot + PLOT_MAX - 1) / PLOT_MAX, np = (nplot + stride - 1) / stride;
    mm_series *sn = mm_res_series(res, O_MAG, (int)np), *se = mm_res_series(res, O_MAG_EXACT, 401);
    mm_series *sp = mm_res_series(res, O_PULSE, 301);
    if (!sn || !se || !sp)
        return MM_ENOMEM;
    for (long i = 0; i < np; i++) {
        long k = i * stride;
        sn->x[i] = freq[k];
        sn->y[i] = hypot(re[k], im[k]);
    }
    mm_linspace(0, f_plot, 401, se->x);
    for (int i = 0; i < 401; i++)
        se->y[i] = fabs(exact_c(pulse, tau, A, se->x[i]));
    double wshow = 0.75 * support(pulse, tau);
    mm_linspace(tc - wshow, tc + wshow, 301, sp->x);
    for (int i = 0; i < 301; i++)
        sp->y[i] = pulse_at(pulse, tau, A, sp->x[i] - tc, 0);
    /* the curves for the eye: six digits */
    mm_ex_round_sig(sn->y, (int)np, 6);
    mm_ex_round_sig(se->x, 401, 8);
    mm_ex_round_sig(se->y, 401, 6);
    mm_ex_round_sig(sp->x, 301, 8);
    mm_ex_round_sig(sp->y, 301, 6);

    mm_res_method(res, "FFT of the sampled pulse times dt, origin shifted to t = 0 (FFTW); zero by Brent", dt);
    mm_res_method_stat(res, "samples", (double)n);
    mm_res_method_stat(res, "samples_in_pulse", floor(support(pulse, tau) * fs) + 1);
    mm_res_method_stat(res, "brent_iterations", iters);
    mm_res_method_stat(res, "direct_sum_evaluations", (double)evals);
    if (stride > 1)
        mm_res_warn(res, "the FFT spectrum is drawn at every %ld-th bin (%ld bins below %g Hz)", stride, nplot,
                    f_plot);
    if (pulse == PU_RECT && !on_edge)
        mm_res_warn(res, "the rectangle's ends fall between samples: the sampled pulse is %g s long instead of "
                         "%g s, a first-order error (make duration * fs an even whole number to avoid it)",
                    w_eff, tau);
    return MM_OK;
}

static const char *const references[] = {
    "R. N. Bracewell, The Fourier Transform and Its Applications, 3rd ed., McGraw-Hill 2000, ch. 2-6 and 10",
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, sections 4.7-4.8",
    "R. P. Brent, Algorithms for Minimization without Derivatives, Prentice-Hall 1973, ch. 4",
    NULL,
};

const mm_exercise mm_ex_vib_fourier_transform = {
    .id = "vib-fourier-transform", .chapter = 5, .section = "5.5", .title = "Fourier integral: the spectrum of a pulse",
    .summary = "Rectangular, triangular, Gaussian and half-sine pulses: their spectra by FFT against the closed "
               "forms; shorter pulse, wider spectrum.",
    .tags = "Fourier transform, Fourier integral, pulse, spectrum, FFT, sampling",
    .theory = "exercises/vib/fourier_transform.md", .params = params, .n_params = MM_COUNT(params), .outputs = outputs,
    .n_outputs = MM_COUNT(outputs), .references = references, .check = check, .solve = solve,
};
