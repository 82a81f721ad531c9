/* test_fourier_bins.c — the spectrum helpers of mm_fourier (vibration
 * chapter, vib-dft): a bin's amplitude by the defining sum against FFTW's
 * spectrum (rect and Hann, even and odd n); the largest local maxima of a
 * written-out spectrum in order, a flat top once, the floor and the limit
 * kept; the leakage of written-out spectra against the power sums done by
 * hand. */
#include "mm_test.h"

#include <complex.h>
#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "mm_complex.h"
#include "mm_fourier.h"

#define EPS DBL_EPSILON

static void direct_amp_should_be_the_fft(void **state)
{
    (void)state;
    enum { NMAX = 49 };
    static const size_t ns[2] = {48, 49};
    for (int a = 0; a < 2; a++)
        for (int h = 0; h < 2; h++) {
            size_t n = ns[a], nb = mm_fourier_bins(n);
            double x[NMAX], w[NMAX], wx[NMAX], cs[NMAX], sn[NMAX], amp[NMAX], gain, sum = 0;
            mm_window win = h ? MM_WINDOW_HANN : MM_WINDOW_RECT;
            for (size_t j = 0; j < n; j++)
                x[j] = 0.3 + sin(0.7 * j) + 0.2 * cos(2.9 * j + 1) * j / n;
            mm_fourier_options o;
            mm_fourier_options_init(&o);
            o.window = win;
            mm_error err;
            assert_int_equal(mm_fourier_spectrum(x, n, 100, &o, NULL, amp, NULL, &err), MM_OK);
            assert_int_equal(mm_fourier_window(win, n, w, &gain, &err), MM_OK);
            for (size_t j = 0; j < n; j++)
                wx[j] = w[j] * x[j], sum += fabs(wx[j]);
            mm_fourier_twiddles(n, cs, sn);
            /* both round by a few eps of sum |w x| over n g (vib-dft allows
             * 2 eps (n + 16) times that; measured here: 2.3 eps) */
            double tol = 8 * EPS * sum / ((double)n * gain);
            for (size_t k = 0; k < nb; k++)
                check_abs(mm_fourier_direct_amp(wx, n, k, cs, sn, gain), amp[k], tol, "bin k: direct sum vs FFTW");
        }
}

static void peaks_should_be_the_largest_local_maxima(void **state)
{
    (void)state;
    /* maxima at 1 (0.5), 4-5 (flat 0.9: counted once, at 4), 8 (2), 11 (1e-7, below the floor) */
    double amp[13] = {0.1, 0.5, 0.2, 0.3, 0.9, 0.9, 0.4, 0.3, 2, 0.1, 0, 1e-7, 0};
    size_t pk[4];
    assert_int_equal(mm_fourier_peaks(amp, 13, 1e-6, 4, pk), 3);
    assert_true(pk[0] == 8 && pk[1] == 4 && pk[2] == 1);
    assert_int_equal(mm_fourier_peaks(amp, 13, 1e-6, 2, pk), 2);   /* the limit keeps the largest */
    assert_true(pk[0] == 8 && pk[1] == 4);
    assert_int_equal(mm_fourier_peaks(amp, 13, 0, 4, pk), 4);      /* no floor: 11 too */
    assert_true(pk[3] == 11);
}

static void leakage_should_be_the_power_away_from_the_peaks(void **state)
{
    (void)state;
    /* n = 24: 13 bins; a peak at 6 (1, its lobe 4..8 with 0.2, 0.5, 0.5, 0.2)
     * and power elsewhere: 0.1 at 0 (the mean: counted whole), 0.05 at 11,
     * 0.15 at 12 (Nyquist: whole); with level 0.2 only 6 is a peak */
    double amp[13] = {0.1, 0, 0, 0, 0.2, 0.5, 1, 0.5, 0.2, 0, 0, 0.05, 0.15};
    unsigned char mark[13];
    memset(mark, 0, sizeof mark);
    double lobe = 0.5 * (0.04 + 0.25 + 1 + 0.25 + 0.04), away = 0.01 + 0.5 * 0.0025 + 0.0225;
    /* 1 - near / total: its rounding grows as 1 / leakage (25 here) */
    check_rel(mm_fourier_leakage(amp, 13, 24, 1, 0.2, 2, mark), away / (lobe + away), 64 * EPS,
              "leakage: power away from the peak over all of it");
    /* level 1e-3: 0 and 12 are peaks too, 11 in 12's lobe: nothing is away */
    memset(mark, 0, sizeof mark);
    assert_true(mm_fourier_leakage(amp, 13, 24, 1, 1e-3, 2, mark) == 0);
    /* relative to top: a spectrum scaled by 1e200 leaks the same */
    double big[13];
    for (int k = 0; k < 13; k++)
        big[k] = 1e200 * amp[k];
    memset(mark, 0, sizeof mark);
    check_rel(mm_fourier_leakage(big, 13, 24, 1e200, 0.2, 2, mark), away / (lobe + away), 64 * EPS, "scaled");
}

/* The rectangle of height A and width tau = 2 M dt sampled with half
 * weight at its ends sums to A dt sin(pi f tau) cot(pi f dt) (the
 * Dirichlet kernel); its derivative in f by the product rule. */
static void even_transform_should_be_the_dirichlet_kernel(void **state)
{
    (void)state;
    enum { M = 40, HALF = 60, N = 2 * HALF + 1 };
    double x[N], A = 3, dt = 1e-3, tau = 2 * M * dt;
    for (int j = 0; j < N; j++) {
        int i = abs(j - HALF);
        x[j] = i < M ? A : i == M ? A / 2 : 0;
    }
    mm_fourier_even d = {.x = x, .m = HALF, .half = HALF, .dt = dt, .level = 0.5};
    for (int k = 1; k < 40; k++) {
        double f = 3.7 * k, u = M_PI * f * tau, v = M_PI * f * dt, X, dX;
        double ex = A * dt * sin(u) / tan(v);
        double dex = A * dt * (M_PI * tau * cos(u) / tan(v) - M_PI * dt * sin(u) / (sin(v) * sin(v)));
        d.deriv = 0;
        mm_fourier_even_transform(f, &X, &d);
        d.deriv = 1;
        mm_fourier_even_transform(f, &dX, &d);
        /* rounding, a few eps of the terms summed: dt sum |x| ~ A tau, and
         * 4 pi dt^2 sum i |x_i| ~ 2 pi dt^2 M^2 A for the derivative
         * (measured: 1.4 and 3.4 eps of them) */
        check_abs(X + 0.5, ex, 8 * DBL_EPSILON * A * tau, "X_c(f) - level vs the closed form");
        check_abs(dX, dex, 16 * DBL_EPSILON * 2 * M_PI * dt * dt * M * M * A, "d X_c / df vs the closed form's");
    }
}

/* The series by rotation against each term's own cexp (angles reduced the
 * same way), 150 modes from j = 7, at points off any grid. */
static void mode_sum_should_be_the_terms_summed_one_by_one(void **state)
{
    (void)state;
    enum { JLO = 7, JHI = 156, NM = JHI - JLO + 1, NX = 9 };
    double complex C[NM], psi[NX], c0 = mm_cmplx(0.25, 0);
    double x[NX], dk = 0.37, xl = -3.1, S = cabs(c0);
    for (int j = 0; j < NM; j++) {
        C[j] = mm_cmplx(cos(0.3 * j) / (1 + 0.05 * j), sin(1.7 * j) / (1 + 0.05 * j));
        S += 2 * cabs(C[j]);
    }
    for (int i = 0; i < NX; i++)
        x[i] = -2.9 + 1.37 * i;
    mm_fourier_mode_sum(C, JLO, JHI, dk, c0, x, NX, xl, 64, psi);
    for (int i = 0; i < NX; i++) {
        double complex ref = 0;
        for (int j = JLO; j <= JHI; j++)
            ref += C[j - JLO] * cexp(I * fmod((double)j * dk * (x[i] - xl), 2 * M_PI));
        ref = c0 + 2 * ref;
        /* the rotation drifts by about an eps a step, 63 steps between
         * restarts (measured: 7.6 eps of the sum of the terms' sizes) */
        check_abs(cabs(psi[i] - ref), 0, 32 * DBL_EPSILON * S, "psi(x): rotation vs each term's cexp");
    }
}

/* The power above a bin, by hand: n = 24 (13 bins), amplitudes 0.1 (mean,
 * whole), 1 at 6, 0.2 at 9, 0.4 at 10, 0.3 at 12 (Nyquist, whole). */
static void power_above_should_be_the_share_by_hand(void **state)
{
    (void)state;
    double amp[13] = {0.1, 0, 0, 0, 0, 0, 1, 0, 0, 0.2, 0.4, 0, 0.3};
    double all = 0.01 + 0.5 * (1 + 0.04 + 0.16) + 0.09;
    size_t k;
    check_rel(mm_fourier_power_above(amp, 13, 24, 1, 8, &k), (0.5 * (0.04 + 0.16) + 0.09) / all, 4 * DBL_EPSILON,
              "share above bin 8");
    assert_true(k == 10);
    check_rel(mm_fourier_power_above(amp, 13, 24, 1, 10, &k), 0.09 / all, 4 * DBL_EPSILON, "share above bin 10");
    assert_true(k == 12);
    double zero[13] = {0.1, 0, 0, 0, 0, 0, 1};
    assert_true(mm_fourier_power_above(zero, 13, 24, 1, 8, &k) == 0 && k == 0);   /* nothing above */
    assert_true(mm_fourier_power_above(zero, 13, 24, 0, 0, &k) == 0 && k == 0);   /* top 0: nothing at all */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(direct_amp_should_be_the_fft),
        cmocka_unit_test(peaks_should_be_the_largest_local_maxima),
        cmocka_unit_test(leakage_should_be_the_power_away_from_the_peaks),
        cmocka_unit_test(even_transform_should_be_the_dirichlet_kernel),
        cmocka_unit_test(mode_sum_should_be_the_terms_summed_one_by_one),
        cmocka_unit_test(power_above_should_be_the_share_by_hand),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
