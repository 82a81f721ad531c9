/* mm_fourier.h — discrete Fourier analysis for the vibration chapter.
 *
 * What it offers (all over FFTW's real-to-complex transform):
 *   - mm_fourier_dft:        the scaled DFT c_k of N real samples;
 *   - mm_fourier_spectrum:   single-sided amplitude and phase spectrum, with
 *                            a window and coherent-gain correction;
 *   - mm_fourier_series_*:   Fourier-series coefficients a_k, b_k of one
 *                            sampled period, the partial sum S_K(t), and its
 *                            maximum found by refinement (Gibbs overshoot);
 *   - mm_fourier_pulse_transform: the continuous Fourier transform X(f) of a
 *                            sampled pulse (FFT times dt, shifted to t0).
 *
 * Conventions (fixed here, used by every function):
 *   - samples x_j = x(t_j), t_j = t0 + j dt, j = 0..N-1, N = n;
 *   - the DFT is X_k = sum_j x_j exp(-2 pi i j k / N).  FFTW returns X_k
 *     unnormalised; this module never hands out X_k itself: mm_fourier_dft
 *     returns c_k = X_k / N (the complex Fourier coefficient of the periodic
 *     extension), the other functions scale as each one says;
 *   - a real signal has N/2 + 1 independent bins k = 0..N/2 (integer
 *     division), at frequencies f_k = k fs / N; mm_fourier_bins(n) says how
 *     many.  For even N the last one is the Nyquist bin fs/2;
 *   - phase: x(t) = sum_k A_k cos(2 pi f_k t + phi_k), phi_k = atan2(Im X_k,
 *     Re X_k) in (-pi, pi], time measured from the first sample.  A sine
 *     sin(w t) has phase -pi/2.
 *
 * Memory: every function writes into arrays the caller owns and never keeps
 * a pointer to them.  Inputs are const and never overwritten (the transforms
 * work on an aligned private copy).  Scratch space is allocated and freed
 * inside each call; a failed allocation returns MM_ENOMEM.
 *
 * Threads: every function may be called from many threads at once.  FFTW's
 * planner is not thread-safe, so plan creation and destruction happen under
 * this module's mutex (the project's only one); plans are made with
 * FFTW_ESTIMATE (cheap, never touches the arrays) and kept in a cache keyed
 * by N, at most MM_FOURIER_PLAN_CACHE sizes; a size beyond that gets a
 * plan for the one call, destroyed under the lock afterwards.  Execution
 * uses fftw_execute_dft_r2c on arrays from fftw_malloc, so the new arrays
 * always have the alignment the plan was made for.
 * Call mm_fourier_cleanup() once at exit, when no other thread is inside
 * this module, to free the cached plans (valgrind then reports no leak).
 *
 * Errors: MM_ERANGE for sizes over the limits below, MM_EVALUE for
 * non-finite samples or nonsensical steps, MM_ENOMEM, MM_EINTERNAL when
 * FFTW cannot make a plan.  Every fallible function validates all of its
 * arguments before it allocates anything.
 */
#ifndef MM_FOURIER_H
#define MM_FOURIER_H

#include <stddef.h>

#include "mm_status.h"

/* ---- limits -------------------------------------------------------------- */

#define MM_FOURIER_MIN_N        2           /* samples in one transform */
#define MM_FOURIER_MAX_N        (1 << 20)
#define MM_FOURIER_MAX_TERMS    4096        /* harmonics K in a partial sum */
#define MM_FOURIER_MAX_POINTS   (1 << 20)   /* points S_K(t) is evaluated at */
#define MM_FOURIER_PLAN_CACHE   32          /* distinct sizes N kept planned */

/* ---- windows ------------------------------------------------------------- */

typedef enum mm_window {
    MM_WINDOW_RECT,     /* w_j = 1 (no window); coherent gain 1 */
    MM_WINDOW_HANN,     /* w_j = 0.5 - 0.5 cos(2 pi j / N); coherent gain 0.5 */
    MM_WINDOW_HAMMING   /* w_j = 0.54 - 0.46 cos(2 pi j / N); gain 0.54 */
} mm_window;

/* Fill w[0..n-1] with the window.  The windows are periodic ("DFT-even",
 * the form used for spectral analysis: the first sample is the minimum and
 * the symmetric point is j = N/2), not MATLAB's symmetric hann(N).
 * *coherent_gain (may be NULL) receives the mean of w, the factor by which
 * the window lowers the amplitude of a sine centred on a bin.
 * Returns MM_ERANGE (param "N") if n is outside [MM_FOURIER_MIN_N,
 * MM_FOURIER_MAX_N], MM_EVALUE (param "window") for an unknown window. */
int mm_fourier_window(mm_window window, size_t n, double *w,
                      double *coherent_gain, mm_error *err);

/* Number of independent bins of n real samples: n/2 + 1.  Cannot fail. */
size_t mm_fourier_bins(size_t n);

/* Validate samples: n within [MM_FOURIER_MIN_N, MM_FOURIER_MAX_N]
 * (MM_ERANGE) and every x_j finite (MM_EVALUE).  param names the signal in
 * the message ("signal" when NULL).  No side effects. */
int mm_fourier_check(const double *x, size_t n, const char *param,
                     mm_error *err);

/* ---- transforms ---------------------------------------------------------- */

/* Scaled DFT of n real samples: c_k = (1/N) sum_j x_j exp(-2 pi i jk/N)
 * for k = 0..n/2, written to re[k], im[k] (mm_fourier_bins(n) entries
 * each).  The scale 1/N makes c_0 the mean and |c_k| half the amplitude of
 * a bin-centred cosine.  Errors: those of mm_fourier_check, MM_ENOMEM,
 * MM_EINTERNAL. */
int mm_fourier_dft(const double *x, size_t n, double *re, double *im,
                   mm_error *err);

typedef struct mm_fourier_options {
    mm_window window;       /* default MM_WINDOW_RECT */
    int gain_correction;    /* 1 (default): divide by the window's coherent
                               gain, so a bin-centred sine of amplitude A
                               reads A whatever the window; 0: raw */
    double phase_floor;     /* phase is set to 0 in bins whose amplitude is
                               below phase_floor times the largest one, where
                               it would be rounding noise; default 1e-9 */
} mm_fourier_options;

/* Defaults listed above.  Cannot fail. */
void mm_fourier_options_init(mm_fourier_options *opt);

/* Single-sided spectrum of n samples taken at fs [Hz] (n/2 + 1 bins).
 * With Y_k = sum_j w_j x_j exp(-2 pi i jk/N) and g the coherent gain (1 if
 * gain_correction is 0 or the window is rect):
 *     amp[0]   = |Y_0| / (N g)                 (the mean; 0 Hz)
 *     amp[k]   = 2 |Y_k| / (N g),  0 < k < N/2
 *     amp[N/2] = |Y_{N/2}| / (N g)             (Nyquist bin, even N only:
 *                                              it has no mirror image)
 * so a sine of amplitude A at a bin frequency reads A.  freq[k] = k fs / N
 * [Hz]; phase[k] [rad] as in the file comment.  freq and phase may be NULL;
 * amp may not.  opt may be NULL (defaults).  Errors: those of
 * mm_fourier_check, MM_ERANGE for fs not finite and > 0 (param "fs"),
 * MM_EVALUE for an unknown window, MM_ENOMEM, MM_EINTERNAL. */
int mm_fourier_spectrum(const double *x, size_t n, double fs,
                        const mm_fourier_options *opt, double *freq,
                        double *amp, double *phase, mm_error *err);

/* ---- Fourier series ------------------------------------------------------ */
/* Convention (Rao, Mechanical Vibrations, ch. 1, "Harmonic analysis"):
 * for a function of period T, w = 2 pi / T,
 *     f(t) ~ S_K(t) = a_0/2 + sum_{k=1..K} (a_k cos k w t + b_k sin k w t),
 *     a_k = (2/T) int_0^T f cos(k w t) dt,  b_k = (2/T) int_0^T f sin(k w t) dt,
 * so a_0 is twice the mean.  Arrays a and b hold K + 1 entries, index k
 * (b[0] is 0 and ignored). */

/* Coefficients from one period sampled at t_j = j T / N, j = 0..N-1 (t = T
 * left out: it repeats t = 0): a_k = (2/N) Re X_k, b_k = -(2/N) Im X_k, the
 * trapezoidal rule, exact for trigonometric polynomials of degree < N/2.
 * At a jump, sample the mean of the two one-sided values (the value the
 * series converges to).  Terms K must satisfy K < N/2, so that harmonic K
 * is below the Nyquist frequency (MM_ERANGE, param "terms", otherwise, and
 * for K > MM_FOURIER_MAX_TERMS).  Other errors: those of mm_fourier_check,
 * MM_ENOMEM, MM_EINTERNAL. */
int mm_fourier_series_coeffs(const double *x, size_t n, size_t K,
                             double *a, double *b, mm_error *err);

/* Partial sum s[i] = S_K(t[i]), i < nt, for period T [s].  Cost O(K nt):
 * cos k w t and sin k w t by rotation, recomputed exactly every 32 terms so
 * rounding cannot build up.  Errors: MM_ERANGE for K over
 * MM_FOURIER_MAX_TERMS (param "terms") or nt over MM_FOURIER_MAX_POINTS
 * (param "points"), MM_EVALUE for T not finite and > 0 (param "T") or a
 * non-finite coefficient or time.  Never allocates. */
int mm_fourier_series_eval(const double *a, const double *b, size_t K,
                           double T, const double *t, size_t nt, double *s,
                           mm_error *err);

/* Maximum of S_K over [t_lo, t_hi]: a scan at 8 (K + 1) points per period
 * (at least 8 per period of the highest harmonic, so the scan cannot miss a
 * lobe) picks the best sample, then golden-section search (mm_opt) on the
 * two neighbouring intervals refines it to |dt| <= 1e-13 T.  Writes the place
 * to *t_max and the value to *s_max.  Requires t_lo < t_hi <= t_lo + T
 * (MM_EVALUE / MM_ERANGE, param "t"); other errors as mm_fourier_series_eval.
 * Never allocates. */
int mm_fourier_series_max(const double *a, const double *b, size_t K,
                          double T, double t_lo, double t_hi,
                          double *t_max, double *s_max, mm_error *err);

/* ---- one harmonic of a sampled signal --------------------------------------- */

/* Amplitude and phase of the harmonic of period T in n samples
 * x_j = x(t0 + j T / per), j = 0..n-1, that cover whole periods (n a
 * multiple of per, per >= 3):
 *     a = (2/n) sum x_j cos(2 pi j / per),  b = (2/n) sum x_j sin(2 pi j / per),
 *     *amp = hypot(a, b),  *phase = atan2(b, a)   in (-pi, pi],
 * so that x(t) = amp cos(2 pi (t - t0) / T - phase) + (the rest).  Exact
 * (to rounding) for a harmonic of that period plus a constant and any other
 * harmonic k / T with k < per / 2, k != 1, sampled this way (discrete
 * orthogonality; the trapezoidal rule over whole periods).  Errors:
 * MM_ERANGE (param "n") when per < 3, n < per or n is not a multiple of
 * per; MM_EVALUE for a non-finite sample.  Never allocates. */
int mm_fourier_harmonic(const double *x, size_t n, size_t per, double *amp,
                        double *phase, mm_error *err);

/* ---- continuous transform of a pulse -------------------------------------- */

/* X(f) = int x(t) exp(-2 pi i f t) dt of a pulse sampled at t_j = t0 + j dt,
 * j = 0..N-1, approximated by the rectangle rule at the DFT frequencies:
 *     f_k = k / (N dt),  X(f_k) ~ dt exp(-2 pi i f_k t0) X_k,  k = 0..N/2,
 * where the factor exp(-2 pi i f_k t0) moves the time origin from the
 * first sample to t = 0.  Accurate when the pulse has died out at both ends
 * of the window and is sampled well above its bandwidth.  freq [Hz] may be
 * NULL; re and im receive X [signal unit x s].  Errors: those of
 * mm_fourier_check, MM_EVALUE for dt not finite and > 0 (param "dt") or t0
 * not finite (param "t0"), MM_ENOMEM, MM_EINTERNAL. */
int mm_fourier_pulse_transform(const double *x, size_t n, double dt,
                               double t0, double *freq, double *re,
                               double *im, mm_error *err);

/* ---- process end ---------------------------------------------------------- */

/* Destroy the cached plans and free FFTW's internal state (fftw_cleanup).
 * Call at process exit, or between tests, when no other thread is inside
 * this module.  Calling it twice, or with nothing cached, is harmless; the
 * module works again afterwards (plans are remade on demand). */
void mm_fourier_cleanup(void);

/* ---- a spectrum's peaks, leakage and bins by the defining sum (chapter 5, vib-dft) ---- */

/* The twiddle tables cs[m] = cos(2 pi m / n), sn[m] = sin(2 pi m / n),
 * m < n.  Cannot fail. */
void mm_fourier_twiddles(size_t n, double *cs, double *sn);

/* The single-sided amplitude of bin k of the n (windowed) samples wx by
 * the defining sum, without FFTW: O(n) per bin, each term's angle reduced
 * exactly, (j k mod n), before it is looked up in the twiddle tables;
 * divided by n gain (the window's coherent gain), doubled but at k = 0 and
 * n/2: what mm_fourier_spectrum gives, by another route.  Cannot fail. */
double mm_fourier_direct_amp(const double *wx, size_t n, size_t k, const double *cs, const double *sn, double gain);

/* The largest peaks of the nb amplitudes amp: local maxima (strictly above
 * the left neighbour, at least the right one, so that a flat top counts
 * once) above floor, largest first, at most max of them into pk.  Returns
 * how many. */
int mm_fourier_peaks(const double *amp, size_t nb, double floor, int max, size_t *pk);

/* The leakage of a spectrum of n samples (nb = mm_fourier_bins(n)
 * amplitudes, the largest top > 0): the share of power farther than lobe
 * bins from every peak above level top (mm_fourier_peaks' sense of a peak),
 * powers relative to top so that nothing overflows.  mark: nb bytes of
 * scratch, zero on entry.  Cannot fail. */
double mm_fourier_leakage(const double *amp, size_t nb, size_t n, double top, double level, size_t lobe,
                          unsigned char *mark);

/* The share of a spectrum's power (n samples, nb = mm_fourier_bins(n)
 * amplitudes, the largest top) in the bins k > k0 (the mean and Nyquist
 * bins counted whole, the others half, powers relative to top), and the
 * bin of the largest nonzero amplitude among them into *kmax (0 when all
 * are 0; top 0: share 0 and *kmax 0).  Cannot fail. */
double mm_fourier_power_above(const double *amp, size_t nb, size_t n, double top, size_t k0, size_t *kmax);

/* ---- the transform of an even pulse's samples, summed directly (chapter 5, vib-fourier-transform) ---- */

/* Samples symmetric about x[m] (x[m - i] = x[m + i]), the ones from m -
 * half to m + half used, step dt [s]; level is subtracted from the
 * transform (0, or a height to find where it is crossed); deriv = 1 asks
 * for the derivative in f instead. */
typedef struct mm_fourier_even {
    const double *x;
    long m, half;
    double dt, level;
    int deriv;
} mm_fourier_even;

/* X_c(f) = dt (x_m + 2 sum_{i=1}^{half} x_{m+i} cos(2 pi f i dt)) - level,
 * the transform of the samples with the centre's phase taken out (real for
 * an even pulse), or its derivative in f, without an FFT: at any f, so
 * that a root finder can place a zero between the bins.  cos and sin of
 * i th by rotation, restarted exactly every 64 terms.  An mm_roots_fn:
 * ctx is an mm_fourier_even; writes *out, returns 0. */
int mm_fourier_even_transform(double f, double *out, void *ctx);

/* ---- a complex Fourier series at any points (chapter 5, vib-dispersion) ---- */

/* psi(x_i) = c0 + 2 sum_{j = jlo}^{jhi} C[j - jlo] exp(i j dk (x_i - xl)),
 * i < n: the modes' sum at any points (not only the FFT's grid).  exp(i j
 * dk X) by rotation in j, restarted exactly every `restart` modes; the
 * angles reduced mod 2 pi.  C and psi are C99 _Complex double arrays (this
 * header leaves complex.h out).  Cannot fail. */
void mm_fourier_mode_sum(const _Complex double *C, int jlo, int jhi, double dk, _Complex double c0, const double *x,
                         int n, double xl, int restart, _Complex double *psi);

#endif
