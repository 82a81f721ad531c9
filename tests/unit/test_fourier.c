/* test_fourier.c — mm_fourier against closed forms.
 *
 * References are independent of the FFT: coefficients of square, sawtooth
 * and triangle waves from their integrals, the discrete sums of sampled
 * waves summed by hand (cot formulas, geometric series), a naive O(N^2)
 * DFT, Parseval's identity, the Gibbs constant Si(pi)/pi - 1/2 and the
 * Fourier transform of a Gaussian.
 */
#include <complex.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "mm_test.h"
#include "mm_fourier.h"

static const double PI = 3.14159265358979323846;

/* ---- helpers ------------------------------------------------------------- */

/* Deterministic pseudo-random numbers in [-1, 1) (a 64-bit LCG). */
static double lcg(unsigned long long *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) / 4503599627370496.0 - 1.0;
}

/* Naive DFT: X_k = sum_j x_j exp(-2 pi i j k / N), angles reduced exactly
 * through (j k) mod N so the reference has no phase rounding build-up. */
static double complex naive_dft(const double *x, size_t n, size_t k)
{
    double complex X = 0;
    for (size_t j = 0; j < n; j++) {
        double ang = -2 * PI * (double)((j * k) % n) / (double)n;
        X += x[j] * cexp(I * ang);
    }
    return X;
}

/* Square wave of amplitude A, odd: +A on (0, T/2), -A on (T/2, T), and
 * the mean 0 at the jumps t = 0 and T/2 (what the series converges to). */
static void sample_square(double *x, size_t n, double A)
{
    for (size_t j = 0; j < n; j++)
        x[j] = (j == 0 || 2 * j == n) ? 0.0 : (2 * j < n ? A : -A);
}

/* ---- transforms ---------------------------------------------------------- */

static void dft_should_equal_naive_sum_scaled_by_one_over_n(void **state)
{
    (void)state;
    size_t sizes[] = {2, 7, 12, 97, 128};
    unsigned long long seed = 1;
    for (size_t s = 0; s < sizeof sizes / sizeof *sizes; s++) {
        size_t n = sizes[s], nb = mm_fourier_bins(n);
        double x[128], re[65], im[65];
        for (size_t j = 0; j < n; j++)
            x[j] = lcg(&seed);
        mm_error err;
        assert_int_equal(mm_fourier_dft(x, n, re, im, &err), MM_OK);
        for (size_t k = 0; k < nb; k++) {
            double complex X = naive_dft(x, n, k) / (double)n;
            /* both sums round at ~N eps with |x_j| <= 1 */
            check_abs(re[k], creal(X), 1e-14, "Re c_k vs naive DFT / N");
            check_abs(im[k], cimag(X), 1e-14, "Im c_k vs naive DFT / N");
        }
    }
}

static void spectrum_should_satisfy_parseval_for_even_and_odd_n(void **state)
{
    (void)state;
    size_t sizes[] = {1000, 999};
    unsigned long long seed = 7;
    for (size_t s = 0; s < 2; s++) {
        size_t n = sizes[s], nb = mm_fourier_bins(n);
        double *x = malloc(n * sizeof *x), *amp = malloc(nb * sizeof *amp);
        double ms = 0, sum = 0;
        for (size_t j = 0; j < n; j++) {
            x[j] = lcg(&seed);
            ms += x[j] * x[j] / (double)n;
        }
        mm_error err;
        assert_int_equal(mm_fourier_spectrum(x, n, 1.0, NULL, NULL, amp,
                                             NULL, &err), MM_OK);
        /* mean square = A_0^2 + sum A_k^2 / 2 (+ A_{N/2}^2: no mirror bin) */
        for (size_t k = 0; k < nb; k++)
            sum += (k == 0 || 2 * k == n) ? amp[k] * amp[k]
                                          : 0.5 * amp[k] * amp[k];
        /* FFT rounding grows like eps log2 N; 1e-12 leaves a wide margin */
        check_rel(sum, ms, 1e-12, "Parseval: sum of bin powers = mean square");
        free(x);
        free(amp);
    }
}

static void spectrum_should_read_a_cosine_amplitude_and_phase(void **state)
{
    (void)state;
    enum { N = 200 };
    double fs = 100, x[N], f[N / 2 + 1], amp[N / 2 + 1], ph[N / 2 + 1];
    for (size_t j = 0; j < N; j++) {
        double t = (double)j / fs;
        x[j] = 0.25 + 1.5 * cos(2 * PI * 5 * t + 0.3) + 0.5 * sin(2 * PI * 12 * t);
    }
    mm_error err;
    assert_int_equal(mm_fourier_spectrum(x, N, fs, NULL, f, amp, ph, &err), MM_OK);
    /* bins 0.5 Hz apart: 5 Hz is bin 10, 12 Hz bin 24.  Bin-centred tones
     * have no leakage, so only rounding (~1e-15) separates the values. */
    check_abs(f[10], 5.0, 1e-12, "bin 10 is 5 Hz");
    check_abs(amp[0], 0.25, 1e-13, "the mean reads |X_0|/N");
    check_abs(amp[10], 1.5, 1e-13, "cosine amplitude reads 2|X_k|/N");
    check_abs(ph[10], 0.3, 1e-12, "cosine phase");
    check_abs(amp[24], 0.5, 1e-13, "sine amplitude");
    check_abs(ph[24], -PI / 2, 1e-12, "a sine is a cosine lagging pi/2");
    check_abs(amp[30], 0.0, 1e-13, "an empty bin reads zero");
    check_abs(ph[30], 0.0, 0.0, "phase of an empty bin is set to 0, not noise");
}

static void nyquist_bin_should_not_be_doubled(void **state)
{
    (void)state;
    enum { N = 64 };
    double x[N], amp[N / 2 + 1];
    for (size_t j = 0; j < N; j++)
        x[j] = (j % 2 ? -0.7 : 0.7);   /* cos(pi j): a tone at fs/2 */
    mm_error err;
    assert_int_equal(mm_fourier_spectrum(x, N, 1.0, NULL, NULL, amp, NULL, &err),
                     MM_OK);
    check_abs(amp[N / 2], 0.7, 1e-14, "Nyquist tone reads |X_{N/2}|/N = A");
    check_abs(amp[0], 0.0, 1e-14, "no mean");
}

static void a_70_hz_sine_sampled_at_100_hz_should_appear_at_30_hz(void **state)
{
    (void)state;
    enum { N = 100 };
    double fs = 100, x[N], f[N / 2 + 1], amp[N / 2 + 1], ph[N / 2 + 1];
    for (size_t j = 0; j < N; j++)
        x[j] = sin(2 * PI * 70 * (double)j / fs);
    mm_error err;
    assert_int_equal(mm_fourier_spectrum(x, N, fs, NULL, f, amp, ph, &err), MM_OK);
    size_t kmax = 0;
    for (size_t k = 1; k <= N / 2; k++)
        if (amp[k] > amp[kmax])
            kmax = k;
    check_abs(f[kmax], 30.0, 1e-12, "alias of 70 Hz at fs = 100 Hz is |70 - 100| Hz");
    /* sin(2 pi 70 t_j) = sin(2 pi (70 - 100) t_j) = -sin(2 pi 30 t_j) */
    check_abs(amp[kmax], 1.0, 1e-12, "the alias keeps the amplitude");
    check_abs(ph[kmax], PI / 2, 1e-12, "and flips the sine: phase +pi/2");
}

/* Sine of unit amplitude at fractional bin a = 100.5 of N = 1024: the
 * exact DFT by the geometric series sum_j z^j = (1 - z^N) / (1 - z). */
static double complex sine_dft_exact(size_t n, double a, size_t k)
{
    double complex zp = cexp(2 * PI * I * (a - (double)k) / (double)n);
    double complex zm = cexp(2 * PI * I * (-a - (double)k) / (double)n);
    double complex Dp = (1 - cpow(zp, (double)n)) / (1 - zp);
    double complex Dm = (1 - cpow(zm, (double)n)) / (1 - zm);
    return (Dp - Dm) / (2 * I);       /* sin = (e^{i.} - e^{-i.}) / 2i */
}

static void a_sine_between_bins_should_leak_with_rect_and_much_less_with_hann(void **state)
{
    (void)state;
    enum { N = 1024 };
    const double a = 100.5;           /* half-way between bins 100 and 101 */
    double x[N], rect[N / 2 + 1], hann[N / 2 + 1];
    for (size_t j = 0; j < N; j++)
        x[j] = sin(2 * PI * a * (double)j / N);
    mm_fourier_options opt;
    mm_fourier_options_init(&opt);
    mm_error err;
    assert_int_equal(mm_fourier_spectrum(x, N, N, &opt, NULL, rect, NULL, &err), MM_OK);
    opt.window = MM_WINDOW_HANN;
    assert_int_equal(mm_fourier_spectrum(x, N, N, &opt, NULL, hann, NULL, &err), MM_OK);

    /* exact references: rect from the geometric series; the periodic Hann
     * window is 1/2 - e^{i.}/4 - e^{-i.}/4, so its DFT is
     * X_k/2 - X_{k-1}/4 - X_{k+1}/4, divided by the coherent gain 1/2 */
    for (size_t k = 2; k < N / 2 - 1; k++) {
        double r = 2 * cabs(sine_dft_exact(N, a, k)) / N;
        double complex h = 0.5 * sine_dft_exact(N, a, k)
                           - 0.25 * sine_dft_exact(N, a, k - 1)
                           - 0.25 * sine_dft_exact(N, a, k + 1);
        /* the geometric-series reference itself rounds at ~1e-13 near the
         * peak (1 - z with z close to 1) */
        check_abs(rect[k], r, 1e-12, "rect bin vs geometric-series DFT");
        check_abs(hann[k], 2 * cabs(h) / N / 0.5, 1e-12, "hann bin vs exact");
    }

    /* scalloping at the peak: rect reads |sinc(1/2)| = 2/pi of the
     * amplitude, Hann sinc(1/2) / (1 - 1/4) = 0.849 (continuous-window
     * values).  The mirror tone at -100.5 bins, 201 bins away, adds up to
     * 1/(pi 201) = 1.6e-3 to rect and 1/(pi 201^3) to Hann; finite N
     * changes both by (pi/2N)^2 ~ 2e-6 */
    check_abs(rect[100], 2 / PI, 2e-3, "rect peak loss 2/pi");
    check_abs(hann[100], (2 / PI) / 0.75, 1e-5, "hann peak loss sinc(1/2)/0.75");

    /* sidelobes 10.5 bins from the tone: rect decays as 1/(pi d), Hann as
     * 1/(pi d (d^2 - 1)); within 10 % (the image at -100.5 bins and the
     * finite N make up the rest) */
    double d = 10.5;
    check_rel(rect[111], 1 / (PI * d), 0.10, "rect sidelobe ~ 1/(pi d)");
    check_rel(hann[111], 1 / (PI * d * (d * d - 1)), 0.10,
              "hann sidelobe ~ 1/(pi d (d^2-1))");

    /* energy spread: fraction of the power outside the 6 bins 98..103 */
    double pr = 0, pr_out = 0, ph = 0, ph_out = 0;
    for (size_t k = 1; k < N / 2; k++) {
        int out = k < 98 || k > 103;
        pr += rect[k] * rect[k];
        ph += hann[k] * hann[k];
        if (out) {
            pr_out += rect[k] * rect[k];
            ph_out += hann[k] * hann[k];
        }
    }
    print_message("  power outside 6 bins: rect %.3g %%, hann %.3g %%\n",
                  100 * pr_out / pr, 100 * ph_out / ph);
    /* continuous-window prediction: power at offset d is sinc(d)^2 (rect),
     * (sinc(d) / (1 - d^2))^2 (hann), d = +-(m + 1/2); the tail |d| >= 3.5
     * is 6.7 % for rect (1/d^2 decay) and 1.1e-4 for hann (1/d^6) */
    double tr = 0, tr_all = 0, th = 0, th_all = 0;
    for (int m = 0; m < 100000; m++) {
        double dd = m + 0.5, sc = 1 / (PI * dd);   /* |sinc(d)| */
        double r2 = 2 * sc * sc, h2 = 2 * pow(sc / (dd * dd - 1), 2);
        tr_all += r2;
        th_all += h2;
        if (m >= 3) {
            tr += r2;
            th += h2;
        }
    }
    /* the mirror tone and finite N shift the measured fractions by ~1 % */
    check_rel(pr_out / pr, tr / tr_all, 0.03, "rect leaks 6.7 % past 3 bins");
    check_rel(ph_out / ph, th / th_all, 0.03, "hann leaks 1.1e-4 past 3 bins");
    assert_true(pr_out / pr > 300 * (ph_out / ph));  /* the point of a window */
}

static void window_gain_correction_should_restore_a_bin_centred_amplitude(void **state)
{
    (void)state;
    enum { N = 256 };
    double x[N], amp[N / 2 + 1], w[N], g;
    for (size_t j = 0; j < N; j++)
        x[j] = 2.0 * cos(2 * PI * 16 * (double)j / N);
    mm_fourier_options opt;
    mm_fourier_options_init(&opt);
    mm_error err;
    mm_window wins[] = {MM_WINDOW_RECT, MM_WINDOW_HANN, MM_WINDOW_HAMMING};
    double gains[] = {1.0, 0.5, 0.54};
    for (int i = 0; i < 3; i++) {
        opt.window = wins[i];
        opt.gain_correction = 1;
        assert_int_equal(mm_fourier_spectrum(x, N, 1.0, &opt, NULL, amp, NULL, &err), MM_OK);
        check_abs(amp[16], 2.0, 1e-13, "corrected amplitude of a bin-centred tone");
        opt.gain_correction = 0;
        assert_int_equal(mm_fourier_spectrum(x, N, 1.0, &opt, NULL, amp, NULL, &err), MM_OK);
        check_abs(amp[16], 2.0 * gains[i], 1e-13, "raw amplitude = A times the gain");
        /* the gain is the mean of the window samples */
        assert_int_equal(mm_fourier_window(wins[i], N, w, &g, &err), MM_OK);
        double mean = 0;
        for (size_t j = 0; j < N; j++)
            mean += w[j] / N;
        check_abs(g, mean, 1e-14, "coherent gain = mean of w");
        check_abs(g, gains[i], 1e-15, "tabulated gain");
    }
    assert_int_equal(mm_fourier_window(MM_WINDOW_HANN, N, w, NULL, &err), MM_OK);
    check_abs(w[0], 0.0, 0.0, "periodic hann starts at 0");
    check_abs(w[N / 2], 1.0, 1e-15, "and peaks at N/2");
}

/* ---- Fourier series ------------------------------------------------------ */

static void square_wave_coefficients_should_be_4A_over_pi_k_for_odd_k(void **state)
{
    (void)state;
    enum { N = 4096, K = 25 };
    const double A = 1.5;
    double x[N], a[K + 1], b[K + 1];
    sample_square(x, N, A);
    mm_error err;
    assert_int_equal(mm_fourier_series_coeffs(x, N, K, a, b, &err), MM_OK);
    for (size_t k = 0; k <= K; k++) {
        check_abs(a[k], 0.0, 1e-14, "odd wave: no cosine terms");
        double want = (k % 2) ? 4 * A / (PI * k) : 0.0;
        double discrete = (k % 2) ? 4 * A / N / tan(PI * k / N) : 0.0;
        /* sum of the samples by hand: (4A/N) cot(pi k/N), summed exactly */
        check_abs(b[k], discrete, 1e-13, "b_k vs the discrete sum (4A/N)cot(pi k/N)");
        /* against the integral the trapezoid rule's aliasing error is
         * (pi k/N)^2 / 3 relative: 1.2e-4 at k = 25 */
        double u = PI * k / N;
        if (k % 2)
            check_rel(b[k], want, u * u / 3 * 1.01 + 1e-13, "b_k = 4A/(pi k)");
        else
            check_abs(b[k], 0.0, 1e-14, "even harmonics vanish");
    }
}

static void sawtooth_coefficients_should_be_minus_2A_over_pi_k(void **state)
{
    (void)state;
    enum { N = 2048, K = 40 };
    const double A = 2.0;
    double x[N], a[K + 1], b[K + 1];
    for (size_t j = 0; j < N; j++)     /* ramp -A..A; mean 0 at the jump */
        x[j] = j == 0 ? 0.0 : A * (2.0 * j / N - 1.0);
    mm_error err;
    assert_int_equal(mm_fourier_series_coeffs(x, N, K, a, b, &err), MM_OK);
    check_abs(a[0], 0.0, 1e-14, "zero mean");
    for (size_t k = 1; k <= K; k++) {
        double u = PI * k / N;
        check_abs(a[k], 0.0, 1e-13, "no cosine terms");
        /* discrete sum (2A/N) cot(pi k/N) vs integral 2A/(pi k): (pi k/N)^2/3 */
        check_rel(b[k], -2 * A / (PI * k), u * u / 3 * 1.01 + 1e-13,
                  "b_k = -2A/(pi k)");
    }
}

static void triangle_coefficients_should_be_8A_over_pi2_k2_for_odd_k(void **state)
{
    (void)state;
    enum { N = 1024, K = 30 };
    const double A = 1.0;
    double x[N], a[K + 1], b[K + 1];
    for (size_t j = 0; j < N; j++) {  /* A (1 - 4|t|/T), t in [-T/2, T/2) */
        double t = (double)j / N;
        if (t >= 0.5)
            t -= 1.0;
        x[j] = A * (1 - 4 * fabs(t));
    }
    mm_error err;
    assert_int_equal(mm_fourier_series_coeffs(x, N, K, a, b, &err), MM_OK);
    for (size_t k = 0; k <= K; k++) {
        check_abs(b[k], 0.0, 1e-14, "even wave: no sine terms");
        if (k % 2 == 0) {
            check_abs(a[k], 0.0, 1e-14, "even harmonics vanish");
            continue;
        }
        /* aliases k + mN and mN - k add sum_m (k/(mN -+ k))^2 relative,
         * at most 2 zeta(2) (k/N)^2 = 3.3 (k/N)^2 */
        double r = (double)k / N;
        check_rel(a[k], 8 * A / (PI * PI * k * k), 3.3 * r * r + 1e-13,
                  "a_k = 8A/(pi^2 k^2)");
    }
}

static void partial_sum_should_rebuild_a_trigonometric_polynomial(void **state)
{
    (void)state;
    enum { K = 300, M = 50 };
    double a[K + 1], b[K + 1], t[M], s[M];
    unsigned long long seed = 3;
    for (size_t k = 0; k <= K; k++) {
        a[k] = lcg(&seed) / (k + 1);
        b[k] = lcg(&seed) / (k + 1);
    }
    const double T = 0.37;
    for (size_t i = 0; i < M; i++)
        t[i] = -1.0 + 0.0731 * i;
    mm_error err;
    assert_int_equal(mm_fourier_series_eval(a, b, K, T, t, M, s, &err), MM_OK);
    for (size_t i = 0; i < M; i++) {
        double want = a[0] / 2;       /* direct: one cos and sin per term */
        for (size_t k = 1; k <= K; k++) {
            double th = 2 * PI * k * t[i] / T;
            want += a[k] * cos(th) + b[k] * sin(th);
        }
        /* the direct sum loses ~K*|t/T|*eps in the angles; 1e-12 covers it */
        check_abs(s[i], want, 1e-12, "S_K(t) vs term-by-term sum");
    }
}

static void gibbs_overshoot_should_approach_8_95_percent_of_the_jump(void **state)
{
    (void)state;
    /* G = Si(pi)/pi - 1/2, Si(pi) = 1.851937051982466170... */
    const double G = 1.851937051982466170 / PI - 0.5;
    const double A = 1.0, T = 2.0;
    size_t Ks[] = {25, 101, 401, 1601};
    double prev_err = INFINITY;
    for (size_t i = 0; i < 4; i++) {
        size_t K = Ks[i];
        double *a = calloc(K + 1, sizeof *a), *b = calloc(K + 1, sizeof *b);
        for (size_t k = 1; k <= K; k += 2)
            b[k] = 4 * A / (PI * k);  /* closed form, no FFT involved */
        double tm, sm;
        mm_error err;
        /* the overshoot after the jump at t = 0; [0, T/4] leaves out its mirror
         * image before the jump at T/2, which is exactly as high */
        assert_int_equal(mm_fourier_series_max(a, b, K, T, 0.0, T / 4, &tm, &sm,
                                               &err), MM_OK);
        /* first maximum where sum_{odd k} cos(k w t) = sin((K+1) w t) /
         * (2 sin w t) = 0: t = T/(2(K+1)).  Golden section pins a flat
         * maximum to ~sqrt(eps) of the lobe width, hence 1e-6 */
        check_rel(tm, T / (2.0 * (K + 1)), 1e-6, "first peak at T/(2(K+1))");
        double peak = 0;               /* the value there, summed directly */
        for (size_t k = 1; k <= K; k += 2)
            peak += 4 * A / (PI * k) * sin(PI * k / (K + 1));
        check_rel(sm, peak, 1e-13, "refined max = S_K at the analytic peak");
        double ratio = (sm - A) / (2 * A), e = fabs(ratio - G);
        print_message("  K = %4zu: overshoot %.8f of the jump (limit %.8f, error %.2e)\n",
                      K, ratio, G, e);
        assert_true(e < prev_err);     /* converges as K grows */
        prev_err = e;
        free(a);
        free(b);
    }
    /* the error falls like 1/K^2 (about 0.16/K^2): at K = 1601 it is
     * 6.5e-8; 1e-6 states 8.949 % to four digits with margin */
    check_abs(prev_err, 0.0, 1e-6, "overshoot/jump -> 0.08949");
}

/* ---- pulse transform ----------------------------------------------------- */

static void gaussian_pulse_transform_should_match_the_closed_form(void **state)
{
    (void)state;
    enum { N = 512 };
    const double sigma = 0.05, dt = 2.0 / N, t0 = -1.0;
    double centres[] = {0.0, 0.3};
    for (int c = 0; c < 2; c++) {
        double tc = centres[c], x[N], f[N / 2 + 1], re[N / 2 + 1], im[N / 2 + 1];
        for (size_t j = 0; j < N; j++) {
            double t = t0 + j * dt - tc;
            x[j] = exp(-t * t / (2 * sigma * sigma));
        }
        mm_error err;
        assert_int_equal(mm_fourier_pulse_transform(x, N, dt, t0, f, re, im, &err),
                         MM_OK);
        for (size_t k = 0; k <= N / 2; k++) {
            /* X(f) = sigma sqrt(2 pi) exp(-2 pi^2 sigma^2 f^2) exp(-2 pi i f tc) */
            double mag = sigma * sqrt(2 * PI) * exp(-2 * PI * PI * sigma * sigma * f[k] * f[k]);
            double complex want = mag * cexp(-2 * PI * I * f[k] * tc);
            /* the pulse is e^-200 at the window ends and its spectrum e^-800
             * at fs/2: the rectangle rule is exact to rounding (X(0) = 0.125) */
            check_abs(re[k], creal(want), 1e-14, "Re X(f) of a Gaussian");
            check_abs(im[k], cimag(want), 1e-14, "Im X(f) of a Gaussian");
        }
        check_abs(f[1], 1.0 / (N * dt), 1e-15, "frequency step 1/(N dt)");
    }
}

/* ---- threads ------------------------------------------------------------- */

typedef struct job {
    size_t first_n;   /* sizes first_n, first_n + 7, ... */
    int failures;
} job;

/* Each thread takes spectra of cosines of 12 sizes, 60 times over: 4 threads
 * x 12 sizes > MM_FOURIER_PLAN_CACHE, so transient plans are exercised too. */
static void *spectra_worker(void *arg)
{
    job *jb = arg;
    for (int rep = 0; rep < 5; rep++)
        for (size_t s = 0; s < 12; s++) {
            size_t n = jb->first_n + 7 * s, bin = n / 5;
            double *x = malloc(n * sizeof *x), *amp = malloc((n / 2 + 1) * sizeof *amp);
            for (size_t j = 0; j < n; j++)
                x[j] = 0.5 + 3.0 * cos(2 * PI * (double)((bin * j) % n) / n);
            mm_error err;
            if (mm_fourier_spectrum(x, n, 1.0, NULL, NULL, amp, NULL, &err) != MM_OK
                || fabs(amp[bin] - 3.0) > 1e-11 || fabs(amp[0] - 0.5) > 1e-11
                || fabs(amp[bin + 1]) > 1e-11)
                jb->failures++;
            free(x);
            free(amp);
        }
    return NULL;
}

static void concurrent_spectra_of_different_sizes_should_all_be_right(void **state)
{
    (void)state;
    enum { NT = 4 };
    pthread_t th[NT];
    job jobs[NT];
    for (int r = 0; r < 12; r++) {
        for (int i = 0; i < NT; i++) {
            jobs[i].first_n = 64 + 100 * i + r;
            jobs[i].failures = 0;
            assert_int_equal(pthread_create(&th[i], NULL, spectra_worker, &jobs[i]), 0);
        }
        for (int i = 0; i < NT; i++) {
            pthread_join(th[i], NULL);
            assert_int_equal(jobs[i].failures, 0);
        }
    }
}

/* ---- errors -------------------------------------------------------------- */

static void errors_should_name_the_parameter(void **state)
{
    (void)state;
    double x[8] = {0, 1, 2, 3, 4, 5, 6, 7}, re[5], im[5], a[5], b[5], amp[5];
    mm_error err;
    assert_int_equal(mm_fourier_dft(x, 1, re, im, &err), MM_ERANGE);
    assert_string_equal(err.param, "N");
    assert_int_equal(mm_fourier_dft(x, (size_t)MM_FOURIER_MAX_N + 1, re, im, &err),
                     MM_ERANGE);
    x[3] = NAN;
    assert_int_equal(mm_fourier_dft(x, 8, re, im, &err), MM_EVALUE);
    assert_string_equal(err.param, "signal");
    x[3] = 3;
    assert_int_equal(mm_fourier_series_coeffs(x, 8, 4, a, b, &err), MM_ERANGE);
    assert_string_equal(err.param, "terms");
    assert_int_equal(mm_fourier_series_coeffs(x, 8, 3, a, b, &err), MM_OK);
    assert_int_equal(mm_fourier_spectrum(x, 8, 0.0, NULL, NULL, amp, NULL, &err),
                     MM_ERANGE);
    assert_string_equal(err.param, "fs");
    mm_fourier_options opt;
    mm_fourier_options_init(&opt);
    opt.window = (mm_window)9;
    assert_int_equal(mm_fourier_spectrum(x, 8, 1.0, &opt, NULL, amp, NULL, &err),
                     MM_EVALUE);
    assert_string_equal(err.param, "window");
    assert_int_equal(mm_fourier_pulse_transform(x, 8, -1.0, 0.0, NULL, re, im, &err),
                     MM_EVALUE);
    assert_string_equal(err.param, "dt");
    double t = 0, s;
    assert_int_equal(mm_fourier_series_eval(a, b, 3, 0.0, &t, 1, &s, &err), MM_EVALUE);
    assert_string_equal(err.param, "T");
    assert_int_equal(mm_fourier_series_max(a, b, 3, 1.0, 0.0, 2.0, &t, &s, &err),
                     MM_ERANGE);
    assert_string_equal(err.param, "t");
}

static int teardown(void **state)
{
    (void)state;
    mm_fourier_cleanup();             /* frees the plan cache for valgrind */
    return 0;
}


static void one_harmonic_should_be_read_exactly_from_whole_periods(void **state)
{
    (void)state;
    /* x = 0.7 + 2.5 cos(th - 0.4) + 0.3 cos(3 th + 1) + 0.2 sin(5 th), th = 2 pi j / 16,
     * over 3 periods: discrete orthogonality gives 2.5 and 0.4 to rounding */
    enum { PER = 16, N = 3 * PER };
    double x[N], amp, phase;
    for (int j = 0; j < N; j++) {
        double th = 2 * M_PI * j / PER;
        x[j] = 0.7 + 2.5 * cos(th - 0.4) + 0.3 * cos(3 * th + 1) + 0.2 * sin(5 * th);
    }
    assert_int_equal(mm_fourier_harmonic(x, N, PER, &amp, &phase, NULL), MM_OK);
    check_rel(amp, 2.5, 1e-14, "amplitude of the fundamental, other harmonics and the mean rejected");
    check_abs(phase, 0.4, 1e-14, "its phase lag");
    /* a sine has phase pi/2: sin th = cos(th - pi/2) */
    for (int j = 0; j < N; j++)
        x[j] = -3 * sin(2 * M_PI * j / PER);
    assert_int_equal(mm_fourier_harmonic(x, N, PER, &amp, &phase, NULL), MM_OK);
    check_rel(amp, 3, 1e-14, "amplitude of -3 sin");
    check_abs(phase, -M_PI / 2, 1e-14, "-sin th = cos(th + pi/2)");
    /* not whole periods, too few samples a period: refused */
    mm_error err;
    assert_int_equal(mm_fourier_harmonic(x, N - 1, PER, &amp, &phase, &err), MM_ERANGE);
    assert_string_equal(err.param, "n");
    assert_int_equal(mm_fourier_harmonic(x, 4, 2, &amp, &phase, &err), MM_ERANGE);
    x[5] = NAN;
    assert_int_equal(mm_fourier_harmonic(x, N, PER, &amp, &phase, &err), MM_EVALUE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(dft_should_equal_naive_sum_scaled_by_one_over_n),
        cmocka_unit_test(spectrum_should_satisfy_parseval_for_even_and_odd_n),
        cmocka_unit_test(spectrum_should_read_a_cosine_amplitude_and_phase),
        cmocka_unit_test(nyquist_bin_should_not_be_doubled),
        cmocka_unit_test(a_70_hz_sine_sampled_at_100_hz_should_appear_at_30_hz),
        cmocka_unit_test(a_sine_between_bins_should_leak_with_rect_and_much_less_with_hann),
        cmocka_unit_test(window_gain_correction_should_restore_a_bin_centred_amplitude),
        cmocka_unit_test(square_wave_coefficients_should_be_4A_over_pi_k_for_odd_k),
        cmocka_unit_test(sawtooth_coefficients_should_be_minus_2A_over_pi_k),
        cmocka_unit_test(triangle_coefficients_should_be_8A_over_pi2_k2_for_odd_k),
        cmocka_unit_test(partial_sum_should_rebuild_a_trigonometric_polynomial),
        cmocka_unit_test(gibbs_overshoot_should_approach_8_95_percent_of_the_jump),
        cmocka_unit_test(gaussian_pulse_transform_should_match_the_closed_form),
        cmocka_unit_test(concurrent_spectra_of_different_sizes_should_all_be_right),
        cmocka_unit_test(errors_should_name_the_parameter),
        cmocka_unit_test(one_harmonic_should_be_read_exactly_from_whole_periods),
    };
    return cmocka_run_group_tests(tests, NULL, teardown);
}
