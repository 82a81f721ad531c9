/* dft.c — vib-dft: the discrete Fourier transform of a sampled signal, and
 * what sampling does to a spectrum: resolution, leakage, windows, aliasing.
 *
 *     X_k = sum_{j=0}^{N-1} w_j x(j / fs) exp(-2 pi i j k / N),   f_k = k fs / N    (1)-(2)
 *
 * Goal: read a single-sided amplitude spectrum (eq. 3 of the theory) and
 * know why a sine of amplitude 1 may not read 1 in it: a frequency between
 * two bins leaks into its neighbours (eq. 5; the Hann window, eq. 6, keeps
 * the leak close), and a frequency above fs/2 folds back below it (eq. 7).
 * Aliasing cannot be seen in the samples themselves, so the expression is
 * also evaluated on a grid R times finer and its spectrum searched for
 * content above fs/2.
 * Checks: Parseval's theorem (eq. 4), and the FFT against the defining sum
 * (1) evaluated directly, bin by bin, at the largest peaks and a few other
 * bins (a second computation that does not use FFTW).  Samples that are
 * all zero to rounding (a sine sampled only at its zeros: exactly at fs/2)
 * have no spectrum to speak of: that is said instead of a peak of 1e-14.
 * Reference: A. V. Oppenheim, R. W. Schafer, Discrete-Time Signal
 * Processing, 3rd ed., Pearson 2010, ch. 8 and 10; F. J. Harris, On the use
 * of windows for harmonic analysis with the DFT, Proc. IEEE 66 (1978) 51-83.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mm_dd.h"
#include "mm_exhelp.h"
#include "mm_expr.h"
#include "mm_fourier.h"

enum { P_SIGNAL, P_FS, P_N, P_WINDOW };
enum { WIN_RECT, WIN_HANN };

static const char *const windows[] = {"rect", "hann", NULL};

#define MAX_N 65536
#define MAX_PEAKS 10           /* rows of the peaks table */
#define PEAK_FLOOR 1e-6        /* peaks below this share of the largest are rounding noise */
#define LEAK_PEAK 1e-3        /* peaks counted by the leakage figure: above -60 dB of the largest */
#define LOBE 2                 /* bins either side of a peak counted as the peak (Hann main lobe) */
#define PLOT_BINS 4097         /* most points of the amplitude series */
#define SHOW_SAMPLES 256       /* samples drawn in the time plot */
#define BETWEEN 4              /* points of the signal drawn between two samples */
#define NOISE 1e-12            /* samples below this share of the signal's size are rounding noise */
#define ALIAS_GUARD 8          /* bins above fs/2 ignored by the aliasing test */
#define ALIAS_LEVEL 1e-3       /* amplitude above fs/2, relative to the largest, that is reported */

static const mm_param params[] = {
    [P_SIGNAL] = {"signal", "signal x(t)", "", MM_EXPR, 0, 0, 0, "sin(2*pi*5*t)+0.5*sin(2*pi*12*t)",
                  .vars = "t",
                  .help = "any expression of the time t in s: sin(2*pi*f*t) is a sine of f Hz and amplitude 1; "
                          "its values must stay below 1e300/N (the transform adds N of them)"},
    [P_FS] = {"fs", "sampling frequency", "Hz", MM_REAL, 100, 1e-2, 1e6,
              .help = "samples per second, 0.01 Hz to 1 MHz; frequencies above fs/2 cannot be told from lower ones"},
    [P_N] = {"N", "number of samples", "", MM_INT, 256, 8, MAX_N,
             .help = "samples taken at t = 0, 1/fs, ...; the bins are fs/N apart; at most 65536, and N times "
                     "the length of the signal at most 8e6 (the work of one request)"},
    [P_WINDOW] = {"window", "window", "", MM_CHOICE, WIN_RECT, 0, 0, .choices = windows,
                  .help = "rect: the samples as they are; hann: tapered to zero at both ends, less leakage"},
};

enum { O_DF, O_NYQ, O_DUR, O_PEAK_F, O_PEAK_A, O_LEAK, O_GAIN, O_PEAKS, O_AMP, O_SAMPLES, O_SIGNAL };

static const char *const peak_cols[] = {"f", "amplitude", NULL};
static const char *const peak_units[] = {"Hz", "", NULL};

static const mm_output outputs[] = {
    [O_DF] = MM_SCALAR("df", "frequency resolution fs/N (bin spacing)", "Hz", .flags = MM_ANSWER | MM_EXACT),
    [O_NYQ] = MM_SCALAR("nyquist", "Nyquist frequency fs/2", "Hz", .flags = MM_ANSWER | MM_EXACT),
    [O_DUR] = MM_SCALAR("duration", "record length N/fs", "s", .flags = MM_EXACT),
    [O_PEAK_F] = MM_SCALAR("peak_frequency", "frequency of the largest peak (a bin frequency)", "Hz",
                           .flags = MM_ANSWER | MM_EXACT),
    [O_PEAK_A] = MM_SCALAR("peak_amplitude", "amplitude of the largest peak", "", .flags = MM_ANSWER),
    [O_LEAK] = MM_SCALAR("leakage",
                         "share of the power more than 2 bins from every peak (local maximum above 1e-3 of the largest)",
                         ""),
    [O_GAIN] = MM_SCALAR("coherent_gain", "window coherent gain (divided out)", "", .flags = MM_EXACT),
    [O_PEAKS] = MM_TABLE("peaks", "the largest peaks: local maxima at bin frequencies", peak_cols, peak_units),
    [O_AMP] = MM_SERIES("amplitude", "single-sided amplitude", "", "f", "Hz", .figure = "spectrum", .mark = "bars"),
    [O_SAMPLES] = MM_SERIES("samples", "samples x_j", "", "t", "s", .figure = "signal", .mark = "dots"),
    [O_SIGNAL] = MM_SERIES("signal", "x(t) between the samples", "", "t", "s", .figure = "signal", .role = "reference"),
};

/* Evaluate the expression at t_i = i h, i < m; MM_OK or the first
 * non-finite sample in *bad. */
static int sample(mm_expr *e, size_t m, double h, double *t, double *x, size_t *bad)
{
    for (size_t i = 0; i < m; i++)
        t[i] = (double)i * h;
    mm_expr_eval_bulk(e, t, m, x);
    for (size_t i = 0; i < m; i++)
        if (!isfinite(x[i])) {
            *bad = i;
            return MM_ENONFINITE;
        }
    return MM_OK;
}

/* Aliasing: the same record sampled m >= 2N times (a power of 2, so its FFT
 * plan is cached) over the same duration N/fs: its bins are the same fs/N
 * apart and reach R fs/2, R = m/N.  *fine_size receives its largest |x|. */
static int aliasing(const mm_value *in, mm_expr *e, size_t n, double fs, double *fine_size, mm_result *res,
                    mm_error *err)
{
    size_t len = strlen(in[P_SIGNAL].text), bad;
    size_t budget = ((size_t)1 << 24) / (32 + len);  /* ~10 ms of evaluations whatever the length */
    if (budget > ((size_t)1 << 18))
        budget = (size_t)1 << 18;
    if (budget > 64 * n)
        budget = 64 * n;
    size_t m = 1;
    while (2 * m <= budget)
        m *= 2;
    double R = (double)m / (double)n;
    *fine_size = 0;
    if (m < 2 * n) {
        mm_res_warn(res, "aliasing not tested: the expression is long and N large (the finer sampling would "
                         "take too long); lower N to test it");
        return MM_OK;
    }
    size_t mb = mm_fourier_bins(m);
    double *tf = mm_res_alloc(res, m * sizeof *tf), *xf = mm_res_alloc(res, m * sizeof *xf);
    double *af = mm_res_alloc(res, mb * sizeof *af);
    if (!tf || !xf || !af)
        return MM_ENOMEM;
    mm_res_method_stat(res, "alias_check_up_to", R * fs / 2);
    mm_res_method_stat(res, "alias_oversampling", R);
    if (sample(e, m, 1 / (fs * R), tf, xf, &bad) != MM_OK) {
        mm_res_warn(res, "aliasing not tested: the signal is not finite at t = %g s, between the samples", tf[bad]);
        return MM_OK;
    }
    *fine_size = mm_maxabs(xf, (int)m);
    mm_fourier_options fo;
    mm_fourier_options_init(&fo);
    fo.window = MM_WINDOW_HANN;                       /* keeps the leak of components below fs/2 close */
    int rc = mm_fourier_spectrum(xf, m, fs * R, &fo, NULL, af, NULL, err);
    if (rc != MM_OK)
        return rc;
    /* the power above fs/2 + guard (f_k = k fs / N: 2 k > N + 2 guard), and its largest component */
    double ftop = mm_maxabs(af, (int)mb);
    size_t khi;
    double above = mm_fourier_power_above(af, mb, m, ftop, (n + 2 * ALIAS_GUARD) / 2, &khi);
    double hi = khi ? af[khi] : 0;
    mm_res_method_stat(res, "above_nyquist", above);
    if (hi > ALIAS_LEVEL * ftop) {
        double f = (double)khi * fs / (double)n, fa = fabs(f - fs * nearbyint(f / fs));
        mm_res_warn(res, "aliasing: the signal has content above fs/2 = %g Hz (largest near %g Hz, "
                         "amplitude %.3g, %.2g %% of the power); sampled at %g Hz it shows up at "
                         "|f - m fs| = %g Hz. Raise fs above %g Hz or remove that component",
                    fs / 2, f, hi, 100 * above, fs, fa, 2 * f);
    }
    return MM_OK;
}

static int curves(mm_expr *e, size_t n, size_t nb, double fs, const double *t, const double *x,
                  const double *freq, const double *amp, mm_result *res)
{
    size_t group = (nb + PLOT_BINS - 1) / PLOT_BINS, ns = (nb + group - 1) / group;
    mm_series *sa = mm_res_series(res, O_AMP, (int)ns);
    size_t nshow = n < SHOW_SAMPLES ? n : SHOW_SAMPLES, nfine = BETWEEN * (nshow - 1) + 1;
    mm_series *sx = mm_res_series(res, O_SAMPLES, (int)nshow), *sf = mm_res_series(res, O_SIGNAL, (int)nfine);
    if (!sa || !sx || !sf)
        return MM_ENOMEM;
    for (size_t g = 0; g < ns; g++) {                 /* the largest bin of each group */
        size_t best = g * group;
        for (size_t k = g * group; k < nb && k < (g + 1) * group; k++)
            if (amp[k] > amp[best])
                best = k;
        sa->x[g] = freq[best];
        sa->y[g] = amp[best];
    }
    if (group > 1)
        mm_res_warn(res, "the amplitude plot shows the largest of every %zu bins (%zu bins in all)", group, nb);
    memcpy(sx->x, t, nshow * sizeof *t);
    memcpy(sx->y, x, nshow * sizeof *x);
    for (size_t i = 0; i < nfine; i++)
        sf->x[i] = (double)i / (BETWEEN * fs);
    mm_expr_eval_bulk(e, sf->x, nfine, sf->y);
    size_t holes = 0;
    for (size_t i = 0; i < nfine; i++)
        if (!isfinite(sf->y[i])) {                    /* a pole between samples: no number to draw */
            sf->y[i] = 0;
            holes++;
        }
    mm_ex_round_sig(sf->y, (int)nfine, 6);            /* the curve between the samples, for the eye */
    if (holes)
        mm_res_warn(res, "the signal is not finite at %zu points between the samples; the curve "
                         "\"signal\" is drawn at 0 there", holes);
    return MM_OK;
}

static int run(const mm_value *in, mm_expr *e, mm_result *res, mm_error *err)
{
    const double fs = in[P_FS].x;
    const size_t n = (size_t)in[P_N].x, nb = mm_fourier_bins(n);
    const mm_window win = (int)in[P_WINDOW].x == WIN_HANN ? MM_WINDOW_HANN : MM_WINDOW_RECT;

    double *t = mm_res_alloc(res, n * sizeof *t), *x = mm_res_alloc(res, n * sizeof *x);
    double *w = mm_res_alloc(res, n * sizeof *w), *wx = mm_res_alloc(res, n * sizeof *wx);
    double *freq = mm_res_alloc(res, nb * sizeof *freq), *amp = mm_res_alloc(res, nb * sizeof *amp);
    double *cs = mm_res_alloc(res, n * sizeof *cs), *sn = mm_res_alloc(res, n * sizeof *sn);
    unsigned char *lobe = mm_res_alloc(res, nb);
    if (!t || !x || !w || !wx || !freq || !amp || !cs || !sn || !lobe)
        return MM_ENOMEM;

    size_t bad;
    if (sample(e, n, 1 / fs, t, x, &bad) != MM_OK)
        return mm_error_set(err, MM_EVALUE, "signal",
                            "signal is not a finite number at t = %g s (sample %zu: %g); "
                            "every sample must be finite", t[bad], bad, x[bad]);
    double size = mm_maxabs(x, (int)n);
    if (size > 1e300 / (double)n)
        return mm_error_set(err, MM_ERANGE, "signal",
                            "signal reaches %g: the transform adds %zu samples, which would overflow; "
                            "scale the signal below %g", size, n, 1e300 / (double)n);

    /* the spectrum, eq. (3), by FFTW */
    mm_fourier_options opt;
    mm_fourier_options_init(&opt);
    opt.window = win;
    double gain;
    int rc = mm_fourier_spectrum(x, n, fs, &opt, freq, amp, NULL, err);
    if (rc == MM_OK)
        rc = mm_fourier_window(win, n, w, &gain, err);
    if (rc != MM_OK)
        return rc;
    for (size_t j = 0; j < n; j++)
        wx[j] = w[j] * x[j];
    mm_res_scalar(res, O_DF, fs / (double)n);
    mm_res_scalar(res, O_NYQ, fs / 2);
    mm_res_scalar(res, O_DUR, (double)n / fs);
    mm_res_scalar(res, O_GAIN, gain);

    /* the finer sampling: aliasing, and the signal's size between the samples */
    double fine_size;
    if ((rc = aliasing(in, e, n, fs, &fine_size, res, err)) != MM_OK)
        return rc;
    /* samples that are all zero to rounding: nothing to analyse */
    double scale = fmax(fine_size, size);
    int noise = size <= NOISE * scale;

    /* ---- peaks, leakage ---- */
    double top = mm_maxabs(amp, (int)nb), sum_abs = 0;
    for (size_t j = 0; j < n; j++)
        sum_abs += fabs(wx[j]);
    /* rounding of an amplitude by the FFT or the direct sum (1): 2 eps N sum|w x| over N g */
    double tol = 2 * DBL_EPSILON * (double)(n + 16) * 2 * sum_abs / ((double)n * gain);
    size_t pk[MAX_PEAKS];
    int np = noise ? 0 : mm_fourier_peaks(amp, nb, PEAK_FLOOR * top, MAX_PEAKS, pk);   /* largest first */
    mm_table *tab = mm_res_table(res, O_PEAKS, np);
    if (!tab)
        return MM_ENOMEM;
    for (int i = 0; i < np; i++) {
        tab->cell[2 * i] = freq[pk[i]];
        tab->cell[2 * i + 1] = amp[pk[i]];
    }
    /* leakage, eq. (5): the share of power farther than LOBE bins from every
     * significant peak (a local maximum above LEAK_PEAK of the largest) */
    double leak = noise || top == 0 ? 0 : mm_fourier_leakage(amp, nb, n, top, LEAK_PEAK, LOBE, lobe);
    if (noise) {
        mm_res_scalar_text(res, O_LEAK, 0, "none: the samples are rounding noise")->exact = 1;
        mm_res_warn(res, "the samples are all zero to rounding (largest %.3g, the signal reaches %.3g between "
                         "them): sampling at %g Hz meets the signal only at its zeros (a sine at exactly fs/2 "
                         "= %g Hz, or a multiple of it); the spectrum of the samples is rounding noise, with no "
                         "peak and no leakage to speak of. Sample at another rate or shift the signal's phase",
                    size, scale, fs, fs / 2);
    } else {
        mm_res_scalar_err(res, O_LEAK, leak, 8 * DBL_EPSILON * (double)nb, MM_ERR_BOUND);
    }
    if (np > 0) {
        mm_res_scalar(res, O_PEAK_F, freq[pk[0]]);
        mm_res_scalar_err(res, O_PEAK_A, amp[pk[0]], tol, MM_ERR_BOUND);
    }

    /* ---- checks ---- */
    /* Parseval, eq. (4), relative to the largest sample (no overflow):
     * sum (w x)^2 = N g^2 [a_0^2 + sum a_k^2 / 2 + a_{N/2}^2].  Both sums
     * in double-double: summed in double, N terms add up to ~sqrt(N) eps of
     * rounding (5e-14 at N = 53,847, past the FFT's 8 eps log2 N that the
     * check is about; 4 of 8,000 draws failed on it) */
    double s = fmax(size, 1e-300);
    mm_dd dt = mm_dd_from(0), df = mm_dd_from(0);
    for (size_t j = 0; j < n; j++)
        dt = mm_dd_add(dt, mm_dd_two_prod(wx[j] / s, wx[j] / s));
    for (size_t k = 0; k < nb; k++)
        df = mm_dd_add(df, mm_dd_mul_d(mm_dd_two_prod(amp[k] / s, amp[k] / s), k == 0 || 2 * k == n ? 1 : 0.5));
    double e_time = mm_dd_val(dt), e_freq = mm_dd_val(df) * (double)n * gain * gain;
    mm_res_check_rel(res, "Parseval: sum of squared (windowed) samples vs spectrum energy, eq. (4)", e_freq,
                     e_time, 8 * DBL_EPSILON * log2((double)n) + 1e-300);
    /* the FFT against the direct sum (1) at the peaks and a few more bins */
    size_t bins[MAX_PEAKS + 4];
    int nbins = 0;
    for (int i = 0; i < np && i < 5; i++)
        bins[nbins++] = pk[i];
    bins[nbins++] = 0;
    bins[nbins++] = nb - 1;
    bins[nbins++] = nb / 3;
    bins[nbins++] = (2 * nb) / 3;
    mm_fourier_twiddles(n, cs, sn);
    double worst = 0;
    for (int i = 0; i < nbins; i++)
        worst = fmax(worst, fabs(amp[bins[i]] - mm_fourier_direct_amp(wx, n, bins[i], cs, sn, gain)));
    mm_res_check_abs(res, "FFT vs the direct sum (1) at the 5 largest peaks and 4 more bins: worst |amplitude error|",
                     worst, 0, fmax(tol, 1e-300));

    if (np > 0 && leak > 0.01)
        mm_res_warn(res, "%.1f %% of the power lies more than 2 bins from every peak: leakage (a frequency "
                         "between bins, or a record that is not a whole number of periods)%s",
                    100 * leak, win == MM_WINDOW_RECT ? "; try window=hann" : "");
    if ((rc = curves(e, n, nb, fs, t, x, freq, amp, res)) != MM_OK)
        return rc;
    mm_res_method(res, win == MM_WINDOW_HANN ? "FFT (FFTW, real input), Hann window" : "FFT (FFTW, real input)", 1 / fs);
    mm_res_method_stat(res, "bins", (double)nb);
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    static const char *const vars[] = {"t"};
    mm_expr *e = NULL;
    int rc = mm_expr_compile(in[P_SIGNAL].text, vars, 1, &e, err);
    if (rc != MM_OK) {
        snprintf(err->param, sizeof err->param, "signal");
        return rc;
    }
    rc = run(in, e, res, err);
    mm_expr_free(e);
    return rc;
}

/* The work grows with N times the cost of one evaluation of the signal,
 * which grows with its length (plus the faster resampling that looks for
 * aliasing): N = 65536 with a 512-character power tower took 242 ms.
 * N * max(len, 32) <= 8e6 keeps the worst case near 60 ms; every N is
 * allowed for signals up to 122 characters (the default has 33). */
#define MAX_WORK 8e6

static int check(const mm_value *in, mm_error *err)
{
    double len = fmax((double)strlen(in[P_SIGNAL].text), 32);
    if (in[P_N].x * len > MAX_WORK)
        return mm_error_set(err, MM_ERANGE, "N",
                            "N must be at most %.0f with this %.0f-character signal (N times the length "
                            "of the signal may be at most %.0f: a longer expression costs more to "
                            "evaluate); got %.0f",
                            floor(MAX_WORK / len), len, MAX_WORK, in[P_N].x);
    return MM_OK;
}

static const char *const references[] = {
    "A. V. Oppenheim, R. W. Schafer, Discrete-Time Signal Processing, 3rd ed., Pearson 2010, ch. 8 and 10",
    "F. J. Harris, On the use of windows for harmonic analysis with the discrete Fourier transform, "
    "Proc. IEEE 66 (1978) 51-83",
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, section 10.9 (signal analysis)",
    NULL,
};

const mm_exercise mm_ex_vib_dft = {
    .id = "vib-dft", .chapter = 5, .section = "5.6", .title = "Discrete Fourier transform: sampling, leakage, aliasing",
    .summary = "The amplitude spectrum of a sampled signal by the FFT: bins, leakage between bins, "
               "the Hann window, and aliasing above fs/2.",
    .tags = "DFT, FFT, spectrum, sampling, aliasing, leakage, window", .theory = "exercises/vib/dft.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
