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
 * bins (a second computation that does not use FFTW).
 * Reference: A. V. Oppenheim, R. W. Schafer, Discrete-Time Signal
 * Processing, 3rd ed., Pearson 2010, ch. 8 and 10; F. J. Harris, On the use
 * of windows for harmonic analysis with the DFT, Proc. IEEE 66 (1978) 51-83.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

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
#define ALIAS_GUARD 8          /* bins above fs/2 ignored by the aliasing test */
#define ALIAS_LEVEL 1e-3       /* amplitude above fs/2, relative to the largest, that is reported */

static const mm_param params[] = {
    [P_SIGNAL] = {"signal", "signal x(t)", "", MM_EXPR, 0, 0, 0, "sin(2*pi*5*t)+0.5*sin(2*pi*12*t)",
                  .vars = "t",
                  .help = "any expression of the time t in s: sin(2*pi*f*t) is a sine of f Hz and amplitude 1"},
    [P_FS] = {"fs", "sampling frequency", "Hz", MM_REAL, 100, 1e-2, 1e6,
              .help = "samples per second; frequencies above fs/2 cannot be told from lower ones"},
    [P_N] = {"N", "number of samples", "", MM_INT, 256, 8, MAX_N,
             .help = "samples taken at t = 0, 1/fs, ...; the bins are fs/N apart (N times the length of the signal may be at most 8e6)"},
    [P_WINDOW] = {"window", "window", "", MM_CHOICE, WIN_RECT, 0, 0, .choices = windows,
                  .help = "rect: the samples as they are; hann: tapered to zero at both ends, less leakage"},
};

/* Power of bin k in the single-sided spectrum (a sine of amplitude a has
 * mean square a^2/2; the bins 0 and N/2 have no mirror image). */
static double bin_power(const double *amp, size_t k, size_t n)
{
    return (k == 0 || 2 * k == n) ? amp[k] * amp[k] : 0.5 * amp[k] * amp[k];
}

/* Amplitude of bin k by the defining sum (1), without FFTW: O(N) per bin.
 * cs[m] = cos(2 pi m / N), sn[m] = sin(2 pi m / N), m < N, so the angle of
 * term j is reduced exactly, (j k mod N), before it is looked up. */
static double direct_amp(const double *wx, size_t n, size_t k, const double *cs, const double *sn, double gain)
{
    double re = 0, im = 0;
    for (size_t j = 0, m = 0; j < n; j++, m = (m + k) % n) {
        re += wx[j] * cs[m];
        im -= wx[j] * sn[m];
    }
    double single = (k == 0 || 2 * k == n) ? 1 : 2;
    return single * hypot(re, im) / ((double)n * gain);
}

/* A local maximum at bin k (strictly above the left neighbour, at least the
 * right one, so a flat top counts once) higher than floor. */
static int is_peak(const double *amp, size_t nb, size_t k, double floor)
{
    double left = k > 0 ? amp[k - 1] : -1, right = k + 1 < nb ? amp[k + 1] : -1;
    return amp[k] > left && amp[k] >= right && amp[k] > floor;
}

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

static int run(const mm_value *in, mm_expr *e, mm_result *res, mm_error *err)
{
    const double fs = in[P_FS].x;
    const size_t n = (size_t)in[P_N].x, nb = mm_fourier_bins(n);
    const mm_window win = (int)in[P_WINDOW].x == WIN_HANN ? MM_WINDOW_HANN : MM_WINDOW_RECT;

    double *t = mm_res_alloc(res, n * sizeof *t), *x = mm_res_alloc(res, n * sizeof *x);
    double *w = mm_res_alloc(res, n * sizeof *w), *wx = mm_res_alloc(res, n * sizeof *wx);
    double *freq = mm_res_alloc(res, nb * sizeof *freq), *amp = mm_res_alloc(res, nb * sizeof *amp);
    if (!t || !x || !w || !wx || !freq || !amp)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");

    size_t bad;
    if (sample(e, n, 1 / fs, t, x, &bad) != MM_OK)
        return mm_error_set(err, MM_EVALUE, "signal",
                            "signal is not a finite number at t = %g s (sample %zu: %g); "
                            "every sample must be finite", t[bad], bad, x[bad]);

    /* the spectrum, eq. (3), by FFTW */
    mm_fourier_options opt;
    mm_fourier_options_init(&opt);
    opt.window = win;
    int rc = mm_fourier_spectrum(x, n, fs, &opt, freq, amp, NULL, err);
    if (rc != MM_OK)
        return rc;
    double gain;
    if ((rc = mm_fourier_window(win, n, w, &gain, err)) != MM_OK)
        return rc;
    for (size_t j = 0; j < n; j++)
        wx[j] = w[j] * x[j];

    /* ---- peaks: local maxima at bins, largest first ---- */
    double top = 0;
    for (size_t k = 0; k < nb; k++)
        top = fmax(top, amp[k]);
    size_t pk[MAX_PEAKS];
    int np = 0;
    for (size_t k = 0; k < nb; k++) {
        if (!is_peak(amp, nb, k, PEAK_FLOOR * top))
            continue;
        int pos = np < MAX_PEAKS ? np : MAX_PEAKS;  /* insertion into the sorted short list */
        while (pos > 0 && amp[pk[pos - 1]] < amp[k])
            pos--;
        if (pos >= MAX_PEAKS)
            continue;
        int last = np < MAX_PEAKS ? np : MAX_PEAKS - 1;
        for (int i = last; i > pos; i--)
            pk[i] = pk[i - 1];
        pk[pos] = k;
        if (np < MAX_PEAKS)
            np++;
    }
    static const char *const cols[] = {"f", "amplitude"};
    static const char *const units[] = {"Hz", ""};
    mm_table *tab = mm_res_table_v1(res, "peaks", np, 2, cols, units);
    if (!tab)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (int i = 0; i < np; i++) {
        tab->cell[2 * i] = freq[pk[i]];
        tab->cell[2 * i + 1] = amp[pk[i]];
    }

    /* ---- leakage, eq. (5): the share of power farther than LOBE bins from
     * every significant peak (a local maximum above LEAK_PEAK of the largest;
     * the table lists only the largest MAX_PEAKS of them) ---- */
    unsigned char *lobe = mm_res_alloc(res, nb);
    if (!lobe)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (size_t k = 0; k < nb; k++)
        if (is_peak(amp, nb, k, LEAK_PEAK * top))
            for (size_t i = k > LOBE ? k - LOBE : 0; i <= k + LOBE && i < nb; i++)
                lobe[i] = 1;
    double total = 0, near = 0;
    for (size_t k = 0; k < nb; k++) {
        double p = bin_power(amp, k, n);
        total += p;
        if (lobe[k])
            near += p;
    }
    double leakage = total > 0 ? fmax(0, 1 - near / total) : 0;

    /* ---- scalars ---- */
    mm_res_scalar_v1(res, "df", "frequency resolution fs/N (bin spacing)", "Hz", fs / (double)n);
    mm_res_scalar_v1(res, "nyquist", "Nyquist frequency fs/2", "Hz", fs / 2);
    mm_res_scalar_v1(res, "duration", "record length N/fs", "s", (double)n / fs);
    if (np > 0) {
        mm_res_scalar_v1(res, "peak_frequency", "frequency of the largest peak", "Hz", freq[pk[0]]);
        mm_res_scalar_v1(res, "peak_amplitude", "amplitude of the largest peak", "", amp[pk[0]]);
    }
    mm_res_scalar_v1(res, "leakage",
                  "share of the power more than 2 bins from every peak (local maximum above 1e-3 of the largest)",
                  "", leakage);
    mm_res_scalar_v1(res, "coherent_gain", "window coherent gain (divided out)", "", gain);

    /* ---- checks ---- */
    /* Parseval, eq. (4): sum (w x)^2 = N g^2 [a_0^2 + sum a_k^2 / 2 + a_{N/2}^2] */
    double e_time = 0, e_freq = 0, sum_abs = 0;
    for (size_t j = 0; j < n; j++) {
        e_time += wx[j] * wx[j];
        sum_abs += fabs(wx[j]);
    }
    for (size_t k = 0; k < nb; k++)
        e_freq += bin_power(amp, k, n);
    e_freq *= (double)n * gain * gain;
    mm_res_check_rel(res, "Parseval: sum of squared (windowed) samples vs spectrum energy, eq. (4)", e_freq,
                     e_time, 1e-12);
    /* the FFT against the direct sum (1) at the peaks and a few more bins;
     * rounding: the direct sum of N terms, <= 2 eps N sum|w x| before scaling */
    size_t bins[MAX_PEAKS + 4];
    int nbins = 0;
    for (int i = 0; i < np && i < 5; i++)
        bins[nbins++] = pk[i];
    bins[nbins++] = 0;
    bins[nbins++] = nb - 1;
    bins[nbins++] = nb / 3;
    bins[nbins++] = (2 * nb) / 3;
    double *cs = mm_res_alloc(res, n * sizeof *cs), *sn = mm_res_alloc(res, n * sizeof *sn);
    if (!cs || !sn)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (size_t m = 0; m < n; m++) {
        cs[m] = cos(2 * M_PI * (double)m / (double)n);
        sn[m] = sin(2 * M_PI * (double)m / (double)n);
    }
    double worst = 0;
    for (int i = 0; i < nbins; i++)
        worst = fmax(worst, fabs(amp[bins[i]] - direct_amp(wx, n, bins[i], cs, sn, gain)));
    double tol = 2 * DBL_EPSILON * (double)(n + 16) * 2 * sum_abs / ((double)n * gain);
    mm_res_check_abs(res, "FFT vs the direct sum (1) at the 5 largest peaks and 4 more bins: worst |amplitude error|",
                     worst, 0, fmax(tol, 1e-300));

    /* ---- aliasing: the same record sampled m >= 2N times (a power of 2, so
     * its FFT plan is cached), over the same duration N/fs: its bins are
     * the same fs/N apart and reach R fs/2, R = m/N ---- */
    size_t len = strlen(in[P_SIGNAL].text);
    size_t budget = ((size_t)1 << 24) / (32 + len);  /* ~10 ms of evaluations whatever the length */
    if (budget > ((size_t)1 << 18))
        budget = (size_t)1 << 18;
    if (budget > 64 * n)
        budget = 64 * n;
    size_t m = 1;
    while (2 * m <= budget)
        m *= 2;
    double R = (double)m / (double)n, above = 0;
    if (m >= 2 * n) {
        size_t mb = mm_fourier_bins(m);
        double *tf = mm_res_alloc(res, m * sizeof *tf), *xf = mm_res_alloc(res, m * sizeof *xf);
        double *af = mm_res_alloc(res, mb * sizeof *af);
        if (!tf || !xf || !af)
            return mm_error_set(err, MM_ENOMEM, "", "out of memory");
        if (sample(e, m, 1 / (fs * R), tf, xf, &bad) != MM_OK) {
            mm_res_warn(res, "aliasing not tested: the signal is not finite at t = %g s, between the samples",
                        tf[bad]);
        } else {
            mm_fourier_options fo;
            mm_fourier_options_init(&fo);
            fo.window = MM_WINDOW_HANN;               /* keeps the leak of components below fs/2 close */
            if ((rc = mm_fourier_spectrum(xf, m, fs * R, &fo, NULL, af, NULL, err)) != MM_OK)
                return rc;
            double ftop = 0, hi = 0, p_all = 0, p_above = 0;
            size_t khi = 0;
            for (size_t k = 0; k < mb; k++) {
                double p = bin_power(af, k, m);
                p_all += p;
                ftop = fmax(ftop, af[k]);
                if (2 * k > n + 2 * ALIAS_GUARD) {    /* above fs/2 + guard: f_k = k fs / N */
                    p_above += p;
                    if (af[k] > hi) {
                        hi = af[k];
                        khi = k;
                    }
                }
            }
            above = p_all > 0 ? p_above / p_all : 0;
            if (hi > ALIAS_LEVEL * ftop) {
                double f = (double)khi * fs / (double)n, fa = fabs(f - fs * nearbyint(f / fs));
                mm_res_warn(res, "aliasing: the signal has content above fs/2 = %g Hz (largest near %g Hz, "
                                 "amplitude %.3g, %.2g %% of the power); sampled at %g Hz it shows up at "
                                 "|f - m fs| = %g Hz. Raise fs above %g Hz or remove that component",
                            fs / 2, f, hi, 100 * above, fs, fa, 2 * f);
            }
        }
        mm_res_scalar_v1(res, "alias_check_up_to", "highest frequency the aliasing test can see (R fs / 2)", "Hz",
                      R * fs / 2);
        mm_res_scalar_v1(res, "above_nyquist", "share of the power above fs/2 (from the finer sampling)", "", above);
    } else {
        mm_res_warn(res, "aliasing not tested: the expression is long and N large (the finer sampling would "
                         "take too long); lower N to test it");
    }

    /* ---- leakage and resolution remarks ---- */
    if (np > 0 && leakage > 0.01)
        mm_res_warn(res, "%.1f %% of the power lies more than 2 bins from every peak: leakage (a frequency "
                         "between bins, or a record that is not a whole number of periods)%s",
                    100 * leakage, win == MM_WINDOW_RECT ? "; try window=hann" : "");

    /* ---- series ---- */
    size_t group = (nb + PLOT_BINS - 1) / PLOT_BINS, ns = (nb + group - 1) / group;
    mm_series *sa = mm_res_series_v1(res, "amplitude", "single-sided amplitude", "", "f", "Hz", (int)ns);
    if (!sa)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
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

    size_t nshow = n < SHOW_SAMPLES ? n : SHOW_SAMPLES, nfine = 8 * (nshow - 1) + 1;
    mm_series *sx = mm_res_series_v1(res, "samples", "samples x_j", "", "t", "s", (int)nshow);
    mm_series *sf = mm_res_series_v1(res, "signal", "x(t) between the samples", "", "t", "s", (int)nfine);
    if (!sx || !sf)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    memcpy(sx->x, t, nshow * sizeof *t);
    memcpy(sx->y, x, nshow * sizeof *x);
    for (size_t i = 0; i < nfine; i++)
        sf->x[i] = (double)i / (8 * fs);
    mm_expr_eval_bulk(e, sf->x, nfine, sf->y);
    size_t holes = 0;
    for (size_t i = 0; i < nfine; i++)
        if (!isfinite(sf->y[i])) {                   /* a pole between samples: no number to draw */
            sf->y[i] = 0;
            holes++;
        }
    if (holes)
        mm_res_warn(res, "the signal is not finite at %zu points between the samples; the curve "
                         "\"signal\" is drawn at 0 there", holes);

    mm_res_method(res, win == MM_WINDOW_HANN ? "FFT (FFTW, real input), Hann window" : "FFT (FFTW, real input)",
                  1 / fs);
    mm_res_method_stat(res, "samples", (double)n);
    mm_res_method_stat(res, "bins", (double)nb);
    mm_res_method_stat(res, "alias_oversampling", m >= 2 * n ? R : 0);
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
    .id = "vib-dft",
    .chapter = 5,
    .section = "5.6",
    .title = "Discrete Fourier transform: sampling, leakage, aliasing",
    .summary = "The amplitude spectrum of a sampled signal by the FFT: bins, leakage between bins, "
               "the Hann window, and aliasing above fs/2.",
    .tags = "DFT, FFT, spectrum, sampling, aliasing, leakage, window",
    .theory = "exercises/vib/dft.md",
    .params = params,
    .n_params = MM_COUNT(params),
    .references = references,
    .check = check,
    .solve = solve,
};
