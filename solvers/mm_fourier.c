/* mm_fourier.c — FFT-based spectra, Fourier series and pulse transforms.
 *
 * The only file that includes fftw3.h, and the only one with a mutex: FFTW's
 * planner keeps global state, so planning and destroying plans happen under
 * plan_lock; executing a plan on new arrays (fftw_execute_dft_r2c) is
 * thread-safe and happens outside it.  See mm_fourier.h for the contract.
 */
#include "mm_fourier.h"

#include "mm_opt.h"

#include <assert.h>
#include <math.h>
#include <pthread.h>
#include <stdlib.h>

#include <fftw3.h>

static const double two_pi = 6.283185307179586476925286766559;

/* ==== plan cache ========================================================= */

/* Plans for r2c transforms of size n, out of place, made with FFTW_ESTIMATE
 * on arrays from fftw_malloc.  Every array handed to fftw_execute_dft_r2c
 * also comes from fftw_malloc, so it has the SIMD alignment the plan
 * assumed (FFTW manual, "New-array Execute Functions"); no FFTW_UNALIGNED
 * needed.  The cache only grows, up to MM_FOURIER_PLAN_CACHE entries, so a
 * cached plan is never destroyed while another thread executes it; only
 * mm_fourier_cleanup empties it. */
static pthread_mutex_t plan_lock = PTHREAD_MUTEX_INITIALIZER;
static struct {
    size_t n;
    fftw_plan plan;
} cache[MM_FOURIER_PLAN_CACHE];
static size_t cache_len;

/* A plan for size n (cached, or made for this call when the cache is full:
 * then *transient = 1 and the caller must hand it to plan_drop).  NULL if
 * FFTW cannot plan.  in/out are only looked at, never written (ESTIMATE). */
static fftw_plan plan_get(size_t n, double *in, fftw_complex *out,
                          int *transient)
{
    fftw_plan p = NULL;
    *transient = 0;
    pthread_mutex_lock(&plan_lock);
    for (size_t i = 0; i < cache_len; i++)
        if (cache[i].n == n) {
            p = cache[i].plan;
            break;
        }
    if (!p) {
        p = fftw_plan_dft_r2c_1d((int)n, in, out, FFTW_ESTIMATE);
        if (p && cache_len < MM_FOURIER_PLAN_CACHE) {
            cache[cache_len].n = n;
            cache[cache_len].plan = p;
            cache_len++;
        } else if (p) {
            *transient = 1;
        }
    }
    pthread_mutex_unlock(&plan_lock);
    return p;
}

static void plan_drop(fftw_plan p)
{
    pthread_mutex_lock(&plan_lock);   /* fftw_destroy_plan is not thread-safe */
    fftw_destroy_plan(p);
    pthread_mutex_unlock(&plan_lock);
}

void mm_fourier_cleanup(void)
{
    pthread_mutex_lock(&plan_lock);
    for (size_t i = 0; i < cache_len; i++)
        fftw_destroy_plan(cache[i].plan);
    cache_len = 0;
    fftw_cleanup();                   /* FFTW's own tables and wisdom */
    pthread_mutex_unlock(&plan_lock);
}

/* ==== windows ============================================================ */

static int window_known(mm_window w)
{
    return w == MM_WINDOW_RECT || w == MM_WINDOW_HANN || w == MM_WINDOW_HAMMING;
}

/* w_j of the periodic window; the mean of cos(2 pi j/N) over j is 0, which
 * gives the coherent gains of window_gain exactly. */
static double window_value(mm_window w, size_t j, size_t n)
{
    double c = cos(two_pi * (double)j / (double)n);
    switch (w) {
    case MM_WINDOW_HANN:    return 0.5 - 0.5 * c;
    case MM_WINDOW_HAMMING: return 0.54 - 0.46 * c;
    default:                return 1.0;
    }
}

static double window_gain(mm_window w)
{
    switch (w) {
    case MM_WINDOW_HANN:    return 0.5;
    case MM_WINDOW_HAMMING: return 0.54;
    default:                return 1.0;
    }
}

static int check_n(size_t n, mm_error *err)
{
    if (n < MM_FOURIER_MIN_N || n > MM_FOURIER_MAX_N)
        return mm_error_set(err, MM_ERANGE, "N",
                            "N must be between %d and %d samples; got %zu",
                            MM_FOURIER_MIN_N, MM_FOURIER_MAX_N, n);
    return MM_OK;
}

static int check_window(mm_window w, mm_error *err)
{
    if (!window_known(w))
        return mm_error_set(err, MM_EVALUE, "window",
                            "window must be rect, hann or hamming; got code %d",
                            (int)w);
    return MM_OK;
}

int mm_fourier_window(mm_window window, size_t n, double *w,
                      double *coherent_gain, mm_error *err)
{
    int rc = check_n(n, err);
    if (rc)
        return rc;
    if ((rc = check_window(window, err)))
        return rc;
    for (size_t j = 0; j < n; j++)
        w[j] = window_value(window, j, n);
    if (coherent_gain)
        *coherent_gain = window_gain(window);
    return MM_OK;
}

size_t mm_fourier_bins(size_t n) { return n / 2 + 1; }

int mm_fourier_check(const double *x, size_t n, const char *param,
                     mm_error *err)
{
    int rc = check_n(n, err);
    if (rc)
        return rc;
    if (!param)
        param = "signal";
    for (size_t j = 0; j < n; j++)
        if (!isfinite(x[j]))
            return mm_error_set(err, MM_EVALUE, param,
                                "%s sample %zu is not finite (%g); every "
                                "sample must be a finite number",
                                param, j, x[j]);
    return MM_OK;
}

/* ==== the transform ====================================================== */

/* X_k = sum_j w_j x_j exp(-2 pi i jk/N), k = 0..n/2, unnormalised, in a new
 * fftw_malloc'ed array *out (caller fftw_frees it).  Window rect = none.
 * Arguments already checked. */
static int rfft(const double *x, size_t n, mm_window window,
                fftw_complex **out, mm_error *err)
{
    int rc = MM_OK, transient = 0;
    double *in = fftw_malloc(sizeof *in * n);
    fftw_complex *X = fftw_malloc(sizeof *X * (n / 2 + 1));
    *out = NULL;
    if (!in || !X) {
        rc = mm_error_set(err, MM_ENOMEM, NULL,
                          "out of memory for a transform of %zu samples", n);
        goto out;
    }
    /* new-array execute needs the plan's alignment: both come from
     * fftw_malloc, which aligns for SIMD, so alignment_of is 0 for all */
    assert(fftw_alignment_of(in) == 0 && fftw_alignment_of((double *)X) == 0);
    if (window == MM_WINDOW_RECT)
        for (size_t j = 0; j < n; j++)
            in[j] = x[j];
    else
        for (size_t j = 0; j < n; j++)
            in[j] = window_value(window, j, n) * x[j];

    fftw_plan p = plan_get(n, in, X, &transient);
    if (!p) {
        rc = mm_error_set(err, MM_EINTERNAL, NULL,
                          "FFTW could not plan a transform of %zu samples", n);
        goto out;
    }
    fftw_execute_dft_r2c(p, in, X);
    if (transient)
        plan_drop(p);
    *out = X;
    X = NULL;
out:
    fftw_free(X);
    fftw_free(in);
    return rc;
}

int mm_fourier_dft(const double *x, size_t n, double *re, double *im,
                   mm_error *err)
{
    fftw_complex *X;
    int rc = mm_fourier_check(x, n, NULL, err);
    if (rc || (rc = rfft(x, n, MM_WINDOW_RECT, &X, err)))
        return rc;
    double scale = 1.0 / (double)n;   /* FFTW is unnormalised: c_k = X_k / N */
    for (size_t k = 0; k <= n / 2; k++) {
        re[k] = X[k][0] * scale;
        im[k] = X[k][1] * scale;
    }
    fftw_free(X);
    return MM_OK;
}

void mm_fourier_options_init(mm_fourier_options *opt)
{
    opt->window = MM_WINDOW_RECT;
    opt->gain_correction = 1;
    opt->phase_floor = 1e-9;
}

int mm_fourier_spectrum(const double *x, size_t n, double fs,
                        const mm_fourier_options *opt, double *freq,
                        double *amp, double *phase, mm_error *err)
{
    mm_fourier_options def;
    fftw_complex *X;
    if (!opt) {
        mm_fourier_options_init(&def);
        opt = &def;
    }
    int rc = mm_fourier_check(x, n, NULL, err);
    if (rc)
        return rc;
    if (!(isfinite(fs) && fs > 0))
        return mm_error_set(err, MM_ERANGE, "fs",
                            "sampling frequency fs must be > 0 Hz; got %g", fs);
    if ((rc = check_window(opt->window, err)))
        return rc;
    if ((rc = rfft(x, n, opt->window, &X, err)))
        return rc;

    double g = opt->gain_correction ? window_gain(opt->window) : 1.0;
    double scale = 1.0 / ((double)n * g), top = 0;
    size_t nb = n / 2 + 1;
    for (size_t k = 0; k < nb; k++) {
        /* bins 0 and N/2 (even N) have no mirror at -f: single weight */
        int single = k == 0 || 2 * k == n;
        amp[k] = (single ? 1.0 : 2.0) * scale * hypot(X[k][0], X[k][1]);
        if (amp[k] > top)
            top = amp[k];
        if (freq)
            freq[k] = (double)k * fs / (double)n;
    }
    if (phase)
        for (size_t k = 0; k < nb; k++)
            phase[k] = amp[k] > opt->phase_floor * top
                           ? atan2(X[k][1], X[k][0]) : 0.0;
    fftw_free(X);
    return MM_OK;
}

/* ==== Fourier series ===================================================== */

static int check_terms(size_t K, mm_error *err)
{
    if (K > MM_FOURIER_MAX_TERMS)
        return mm_error_set(err, MM_ERANGE, "terms",
                            "terms must be at most %d harmonics; got %zu",
                            MM_FOURIER_MAX_TERMS, K);
    return MM_OK;
}

int mm_fourier_series_coeffs(const double *x, size_t n, size_t K,
                             double *a, double *b, mm_error *err)
{
    fftw_complex *X;
    int rc = mm_fourier_check(x, n, NULL, err);
    if (rc || (rc = check_terms(K, err)))
        return rc;
    if (2 * K >= n)
        return mm_error_set(err, MM_ERANGE, "terms",
                            "terms must be below N/2 = %zu so that harmonic "
                            "K lies under the Nyquist frequency; got %zu "
                            "(sample the period with more than %zu points)",
                            n / 2, K, 2 * K);
    if ((rc = rfft(x, n, MM_WINDOW_RECT, &X, err)))
        return rc;
    double scale = 2.0 / (double)n;   /* (2/T) int f cos dt by the trapezoid rule */
    for (size_t k = 0; k <= K; k++) {
        a[k] = scale * X[k][0];
        b[k] = -scale * X[k][1];      /* exp(-i k w t) = cos - i sin */
    }
    b[0] = 0.0;
    fftw_free(X);
    return MM_OK;
}

static int check_series(const double *a, const double *b, size_t K, double T,
                        mm_error *err)
{
    int rc = check_terms(K, err);
    if (rc)
        return rc;
    if (!(isfinite(T) && T > 0))
        return mm_error_set(err, MM_EVALUE, "T",
                            "period T must be a finite number > 0 s; got %g", T);
    for (size_t k = 0; k <= K; k++)
        if (!isfinite(a[k]) || (k > 0 && !isfinite(b[k])))
            return mm_error_set(err, MM_EVALUE, "coefficients",
                                "coefficient of harmonic %zu is not finite", k);
    return MM_OK;
}

/* S_K(t).  cos k th, sin k th by rotation through th, restarted from the
 * library cos/sin every 32 terms so the rounding of the recurrence (about
 * one ulp per step) stays below 1e-14. */
static double partial_sum(const double *a, const double *b, size_t K,
                          double T, double t)
{
    double u = t / T;
    u -= floor(u);                     /* only t mod T matters */
    double th = two_pi * u, c1 = cos(th), s1 = sin(th);
    double c = 1.0, s = 0.0, sum = 0.5 * a[0];
    for (size_t k = 1; k <= K; k++) {
        if (k % 32 == 0) {
            c = cos((double)k * th);
            s = sin((double)k * th);
        } else {
            double cn = c * c1 - s * s1;
            s = s * c1 + c * s1;
            c = cn;
        }
        sum += a[k] * c + b[k] * s;
    }
    return sum;
}

int mm_fourier_series_eval(const double *a, const double *b, size_t K,
                           double T, const double *t, size_t nt, double *s,
                           mm_error *err)
{
    int rc = check_series(a, b, K, T, err);
    if (rc)
        return rc;
    if (nt > MM_FOURIER_MAX_POINTS)
        return mm_error_set(err, MM_ERANGE, "points",
                            "points must be at most %d; got %zu",
                            MM_FOURIER_MAX_POINTS, nt);
    for (size_t i = 0; i < nt; i++)
        if (!isfinite(t[i]))
            return mm_error_set(err, MM_EVALUE, "t",
                                "time %zu is not finite", i);
    for (size_t i = 0; i < nt; i++)
        s[i] = partial_sum(a, b, K, T, t[i]);
    return MM_OK;
}

typedef struct series_arg {
    const double *a, *b;
    size_t K;
    double T;
} series_arg;

static int series_at(double t, double *s, void *params)
{
    const series_arg *p = params;
    *s = partial_sum(p->a, p->b, p->K, p->T, t);
    return 0;
}

int mm_fourier_series_max(const double *a, const double *b, size_t K,
                          double T, double t_lo, double t_hi,
                          double *t_max, double *s_max, mm_error *err)
{
    int rc = check_series(a, b, K, T, err);
    if (rc)
        return rc;
    if (!(isfinite(t_lo) && isfinite(t_hi) && t_lo < t_hi))
        return mm_error_set(err, MM_EVALUE, "t",
                            "the search interval needs t_lo < t_hi; got "
                            "[%g, %g]", t_lo, t_hi);
    if (t_hi - t_lo > T * (1 + 1e-12))
        return mm_error_set(err, MM_ERANGE, "t",
                            "the search interval [%g, %g] is longer than one "
                            "period T = %g", t_lo, t_hi, T);

    /* scan: 8 points per period of harmonic K + 1, so two scan points never
     * straddle more than a quarter period of the fastest term */
    size_t m = (size_t)ceil(8.0 * (double)(K + 1) * (t_hi - t_lo) / T);
    if (m < 8)
        m = 8;
    double h = (t_hi - t_lo) / (double)m, best_t = t_lo, best = -INFINITY;
    for (size_t i = 0; i <= m; i++) {
        double t = i == m ? t_hi : t_lo + (double)i * h;
        double v = partial_sum(a, b, K, T, t);
        if (v > best) {
            best = v;
            best_t = t;
        }
    }

    /* golden-section search (mm_opt) on [best_t - h, best_t + h], inside [t_lo, t_hi] */
    series_arg sa = {a, b, K, T};
    mm_opt_result o;
    double lo = fmax(t_lo, best_t - h), hi = fmin(t_hi, best_t + h);
    rc = mm_opt_golden_max(series_at, &sa, lo, hi, 1e-13 * T, 200, &o, err);
    if (rc)
        return rc;
    double tm = o.x, sm = o.fx;
    if (best > sm) {                  /* a scan point (t_lo or t_hi) wins */
        tm = best_t;
        sm = best;
    }
    *t_max = tm;
    *s_max = sm;
    return MM_OK;
}

/* ==== one harmonic ========================================================= */

int mm_fourier_harmonic(const double *x, size_t n, size_t per, double *amp,
                        double *phase, mm_error *err)
{
    if (per < 3 || n < per || n % per != 0)
        return mm_error_set(err, MM_ERANGE, "n",
                            "harmonic analysis needs whole periods of at least 3 "
                            "samples: n = %zu samples, %zu a period", n, per);
    double a = 0, b = 0;
    for (size_t j = 0; j < n; j++) {
        if (!isfinite(x[j]))
            return mm_error_set(err, MM_EVALUE, "x", "sample %zu is not finite", j);
        size_t m = j % per;                 /* the angle reduced exactly */
        double th = 2 * M_PI * (double)m / (double)per;
        a += x[j] * cos(th);
        b += x[j] * sin(th);
    }
    a *= 2.0 / (double)n;
    b *= 2.0 / (double)n;
    *amp = hypot(a, b);
    *phase = atan2(b, a);
    return MM_OK;
}

/* ==== continuous transform of a pulse ===================================== */

int mm_fourier_pulse_transform(const double *x, size_t n, double dt,
                               double t0, double *freq, double *re,
                               double *im, mm_error *err)
{
    fftw_complex *X;
    int rc = mm_fourier_check(x, n, NULL, err);
    if (rc)
        return rc;
    if (!(isfinite(dt) && dt > 0))
        return mm_error_set(err, MM_EVALUE, "dt",
                            "time step dt must be a finite number > 0 s; got %g",
                            dt);
    if (!isfinite(t0))
        return mm_error_set(err, MM_EVALUE, "t0",
                            "start time t0 must be a finite number; got %g", t0);
    if ((rc = rfft(x, n, MM_WINDOW_RECT, &X, err)))
        return rc;
    double span = (double)n * dt;
    for (size_t k = 0; k <= n / 2; k++) {
        double f = (double)k / span;
        /* shift of the time origin: exp(-2 pi i f t0), angle reduced first */
        double u = f * t0;
        u -= nearbyint(u);
        double c = cos(two_pi * u), s = -sin(two_pi * u);
        re[k] = dt * (X[k][0] * c - X[k][1] * s);
        im[k] = dt * (X[k][0] * s + X[k][1] * c);
        if (freq)
            freq[k] = f;
    }
    fftw_free(X);
    return MM_OK;
}

/* ==== a spectrum's peaks, leakage and bins by the defining sum (chapter 5) ==== */

void mm_fourier_twiddles(size_t n, double *cs, double *sn)
{
    for (size_t m = 0; m < n; m++) {
        cs[m] = cos(2 * M_PI * (double)m / (double)n);
        sn[m] = sin(2 * M_PI * (double)m / (double)n);
    }
}

double mm_fourier_direct_amp(const double *wx, size_t n, size_t k, const double *cs, const double *sn, double gain)
{
    double re = 0, im = 0;
    for (size_t j = 0, m = 0; j < n; j++, m = (m + k) % n) {
        re += wx[j] * cs[m];
        im -= wx[j] * sn[m];
    }
    double single = (k == 0 || 2 * k == n) ? 1 : 2;
    return single * hypot(re, im) / ((double)n * gain);
}

/* A local maximum at bin k higher than floor. */
static int is_peak(const double *amp, size_t nb, size_t k, double floor)
{
    double left = k > 0 ? amp[k - 1] : -1, right = k + 1 < nb ? amp[k + 1] : -1;
    return amp[k] > left && amp[k] >= right && amp[k] > floor;
}

int mm_fourier_peaks(const double *amp, size_t nb, double floor, int max, size_t *pk)
{
    int np = 0;
    for (size_t k = 0; k < nb; k++) {
        if (!is_peak(amp, nb, k, floor))
            continue;
        int pos = np < max ? np : max;                /* insertion into the sorted short list */
        while (pos > 0 && amp[pk[pos - 1]] < amp[k])
            pos--;
        if (pos >= max)
            continue;
        int last = np < max ? np : max - 1;
        for (int i = last; i > pos; i--)
            pk[i] = pk[i - 1];
        pk[pos] = k;
        if (np < max)
            np++;
    }
    return np;
}

double mm_fourier_leakage(const double *amp, size_t nb, size_t n, double top, double level, size_t lobe,
                          unsigned char *mark)
{
    for (size_t k = 0; k < nb; k++)
        if (is_peak(amp, nb, k, level * top))
            for (size_t i = k > lobe ? k - lobe : 0; i <= k + lobe && i < nb; i++)
                mark[i] = 1;
    double total = 0, near = 0;
    for (size_t k = 0; k < nb; k++) {
        double a = amp[k] / top, p = (k == 0 || 2 * k == n) ? a * a : 0.5 * a * a;
        total += p;
        if (mark[k])
            near += p;
    }
    return total > 0 ? fmax(0, 1 - near / total) : 0;
}

double mm_fourier_power_above(const double *amp, size_t nb, size_t n, double top, size_t k0, size_t *kmax)
{
    double hi = 0, p_all = 0, p_above = 0;
    *kmax = 0;
    for (size_t k = 0; k < nb && top > 0; k++) {
        double a = amp[k] / top, p = (k == 0 || 2 * k == n) ? a * a : 0.5 * a * a;
        p_all += p;
        if (k > k0) {
            p_above += p;
            if (amp[k] > hi)
                hi = amp[k], *kmax = k;
        }
    }
    return p_all > 0 ? p_above / p_all : 0;
}

/* ==== the transform of an even pulse's samples, summed directly (chapter 5) ==== */

int mm_fourier_even_transform(double f, double *out, void *ctx)
{
    const mm_fourier_even *d = ctx;
    double th = 2 * M_PI * f * d->dt, c1 = cos(th), s1 = sin(th), c = 1, s = 0, sum = 0;
    for (long i = 1; i <= d->half; i++) {
        if (i % 64 == 0) {
            c = cos((double)i * th);
            s = sin((double)i * th);
        } else {
            double cn = c * c1 - s * s1;
            s = s * c1 + c * s1;
            c = cn;
        }
        sum += d->deriv ? -d->x[d->m + i] * (double)i * s : d->x[d->m + i] * c;
    }
    if (d->deriv)
        *out = 2 * d->dt * 2 * M_PI * d->dt * sum;
    else
        *out = d->dt * (d->x[d->m] + 2 * sum) - d->level;
    return 0;
}

/* ==== a complex Fourier series at any points (chapter 5) ====================== */

#include <complex.h>   /* here, after fftw3.h: its fftw_complex stays double[2] */

void mm_fourier_mode_sum(const _Complex double *C, int jlo, int jhi, double dk, _Complex double c0, const double *x,
                         int n, double xl, int restart, _Complex double *psi)
{
    for (int i = 0; i < n; i++) {
        double X = x[i] - xl;
        double complex step = cexp(I * fmod(dk * X, 2 * M_PI)), e = 0, sum = 0;
        for (int j = jlo; j <= jhi; j++) {
            if ((j - jlo) % restart == 0)
                e = cexp(I * fmod((double)j * dk * X, 2 * M_PI));
            else
                e *= step;
            sum += C[j - jlo] * e;
        }
        psi[i] = c0 + 2 * sum;
    }
}
