/* fourier_series.c — vib-fourier-series: the Fourier series of a square, a
 * sawtooth and a triangle wave, and the Gibbs overshoot at a jump.
 *
 *     f(t) ~ S_K(t) = a_0/2 + sum_{k=1..K} (a_k cos k w t + b_k sin k w t)   (1)
 *
 * Goal: compute the coefficients numerically (one period sampled and
 * transformed by the FFT, eq. 5 of the theory), see that they match the
 * closed forms (eqs. 6-8), and watch the partial sum ring at a jump: its
 * maximum overshoots by about 8.95 % of the jump however many terms are
 * taken (Gibbs).  The overshoot is found by refining the maximum of S_K
 * (scan + golden section), and checked against the value of S_K at its
 * known maximum (eqs. 10, 12) and against the Gibbs constant with a bound
 * that depends honestly on K (eqs. 11, 13).
 * Reference: S. S. Rao, Mechanical Vibrations, 6th ed., section 1.11;
 * H. S. Carslaw, Introduction to the Theory of Fourier's Series and
 * Integrals, 3rd ed., Dover 1930, ch. IX (Gibbs's phenomenon).
 */
#include <float.h>
#include <math.h>

#include "mm_exhelp.h"
#include "mm_fourier.h"

enum { P_WAVE, P_TERMS, P_T, P_A };
enum { W_SQUARE, W_SAWTOOTH, W_TRIANGLE };

static const char *const waves[] = {"square", "sawtooth", "triangle", NULL};

#define MAX_TERMS 1000   /* max S_K costs 8 K^2 term evaluations: 25 ms at 1000 */

static const mm_param params[] = {
    [P_WAVE] = {"wave", "wave form", "", MM_CHOICE, W_SQUARE, 0, 0, .choices = waves,
                .help = "square: +A then -A; sawtooth: a ramp from -A to A, then a jump back; "
                        "triangle: straight lines between A and -A (no jump)"},
    [P_TERMS] = {"terms", "highest harmonic K", "", MM_INT, 25, 1, MAX_TERMS,
                 .help = "harmonics 1..K are summed; the ripple narrows as K grows, the overshoot does not"},
    [P_T] = {"T", "period", "s", MM_REAL, 1, 1e-3, 1e3, .help = "the wave repeats every T seconds"},
    [P_A] = {"A", "amplitude", "", MM_REAL, 1, 1e-6, 1e6,
             .help = "peak value of the wave (any unit: m, N, V); the wave swings between -A and A"},
};

/* The wave at t = u T, u in [0, 1), sampled on j/N: exact jumps (u = 0, and
 * u = 1/2 for the square) get the mean of the two one-sided values, which is
 * what the series converges to there. */
static double wave_at(int wave, double A, long j, long N)
{
    double u = (double)j / (double)N;
    switch (wave) {
    case W_SQUARE:
        if (j == 0 || 2 * j == N)
            return 0;
        return 2 * j < N ? A : -A;
    case W_SAWTOOTH:                               /* A (2u - 1) on (0, 1), eq. (3) */
        return j == 0 ? 0 : A * (2 * u - 1);
    default: {                                     /* A (1 - 4|u|), u in [-1/2, 1/2), eq. (4) */
        double v = u < 0.5 ? u : u - 1;
        return A * (1 - 4 * fabs(v));
    }
    }
}

/* The wave at any time t (for the plots), jumps drawn at their mean. */
static double wave_t(int wave, double A, double T, double t)
{
    double u = t / T - floor(t / T);
    switch (wave) {
    case W_SQUARE:
        if (u == 0 || u == 0.5)
            return 0;
        return u < 0.5 ? A : -A;
    case W_SAWTOOTH:
        return u == 0 ? 0 : A * (2 * u - 1);
    default: {
        double v = u < 0.5 ? u : u - 1;
        return A * (1 - 4 * fabs(v));
    }
    }
}

/* Closed-form coefficients, eqs. (6)-(8). */
static void exact_coeff(int wave, double A, int k, double *a, double *b)
{
    *a = *b = 0;
    if (k == 0)
        return;
    switch (wave) {
    case W_SQUARE:
        if (k % 2)
            *b = 4 * A / (k * M_PI);
        break;
    case W_SAWTOOTH:
        *b = -2 * A / (k * M_PI);
        break;
    default:
        if (k % 2)
            *a = 8 * A / (M_PI * M_PI * (double)k * k);
        break;
    }
}

/* Bound on |numerical - exact| of coefficient k from aliasing (eq. 9):
 * sampling N points per period folds harmonic mN +- k onto k. */
static double alias_bound(int wave, double A, int k, long N)
{
    double n2 = (double)N * N;
    switch (wave) {
    case W_SQUARE:   return 4 * M_PI / 3 * A * k / (n2 - (double)k * k);
    case W_SAWTOOTH: return 2 * M_PI / 3 * A * k / (n2 - (double)k * k);
    default:         return 8 * A / (3 * ((double)N - k) * ((double)N - k));
    }
}

/* Si(pi) = int_0^pi sin(u)/u du by its power series (terms fall like
 * pi^(2n)/(2n+1)!, 30 terms are far past double precision). */
static double si_pi(void)
{
    double term = M_PI, sum = 0;                   /* term = (-1)^n pi^(2n+1)/(2n+1)! */
    for (int n = 0; n < 30; n++) {
        sum += term / (2 * n + 1);
        term *= -M_PI * M_PI / ((2 * n + 2) * (2 * n + 3));
    }
    return sum;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    int wave = (int)in[P_WAVE].x, K = (int)in[P_TERMS].x;
    double T = in[P_T].x, A = in[P_A].x;
    double jump = wave == W_TRIANGLE ? 0 : 2 * A;

    /* one period at N = 2^m >= 256 K samples (at least 4096): the aliasing
     * error of eq. (9) is then below 1e-4 of the coefficient at k = K */
    long N = 4096;
    while (N < 256L * K)
        N *= 2;
    double *x = mm_res_alloc(res, sizeof *x * (size_t)N);
    double *a = mm_res_alloc(res, sizeof *a * (size_t)(K + 1));
    double *b = mm_res_alloc(res, sizeof *b * (size_t)(K + 1));
    if (!x || !a || !b)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (long j = 0; j < N; j++)
        x[j] = wave_at(wave, A, j, N);
    int rc = mm_fourier_series_coeffs(x, (size_t)N, (size_t)K, a, b, err);
    if (rc != MM_OK)
        return rc;

    /* table of coefficients, eq. (5) */
    static const char *const cols[] = {"k", "a_k", "b_k"};
    static const char *const units[] = {"", "", ""};
    mm_table *tab = mm_res_table_v1(res, "coefficients", K + 1, 3, cols, units);
    if (!tab)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    double worst = 0, tol_coef = 0;
    for (int k = 0; k <= K; k++) {
        double ae, be;
        exact_coeff(wave, A, k, &ae, &be);
        tab->cell[3 * k] = k;
        tab->cell[3 * k + 1] = a[k];
        tab->cell[3 * k + 2] = k ? b[k] : 0;
        worst = fmax(worst, fmax(fabs(a[k] - ae), k ? fabs(b[k] - be) : 0));
        tol_coef = fmax(tol_coef, alias_bound(wave, A, k, N));
    }

    /* The maximum of S_K over one period [-T/2, T/2], refined (the solver
     * scans 8 points per period of harmonic K + 1, then golden section).
     * S_K is defined by the true coefficients, so the reported overshoot
     * uses the closed forms (6)-(8): from the sampled ones it would carry
     * their aliasing error (about 7e-6 A at K = 25).  The maximum of the
     * sampled series is found too, and compared below. */
    double *ax = mm_res_alloc(res, sizeof *ax * (size_t)(K + 1));
    double *bx = mm_res_alloc(res, sizeof *bx * (size_t)(K + 1));
    if (!ax || !bx)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (int k = 0; k <= K; k++)
        exact_coeff(wave, A, k, &ax[k], &bx[k]);
    double t_max, s_max, t_fft, s_fft;
    rc = mm_fourier_series_max(ax, bx, (size_t)K, T, -T / 2, T / 2, &t_max, &s_max, err);
    if (rc == MM_OK)
        rc = mm_fourier_series_max(a, b, (size_t)K, T, -T / 2, T / 2, &t_fft, &s_fft, err);
    if (rc != MM_OK)
        return rc;
    double overshoot = s_max - A;

    /* The same maximum from the closed-form coefficients at its known place:
     * square eq. (10), sawtooth eq. (12), triangle the corner t = 0. */
    double s_ref = 0, t_ref = 0;
    int n_odd = (K + 1) / 2;                       /* odd harmonics 1, 3, .., <= K */
    if (wave == W_SQUARE) {
        for (int j = 1; j <= n_odd; j++)
            s_ref += sin((2 * j - 1) * M_PI / (2 * n_odd)) / (2 * j - 1);
        s_ref *= 4 * A / M_PI;
        t_ref = T / (4 * n_odd);
    } else if (wave == W_SAWTOOTH) {
        for (int k = 1; k <= K; k++)
            s_ref += sin(k * M_PI / (K + 1)) / k;
        s_ref *= 2 * A / M_PI;
        t_ref = -T / (2.0 * (K + 1));
    } else {
        for (int k = 1; k <= K; k += 2)
            s_ref += 1.0 / ((double)k * k);
        s_ref *= 8 * A / (M_PI * M_PI);
    }
    /* |S_K(numerical coefficients) - S_K(exact)| <= sum of the coefficient
     * errors; plus rounding of a K-term sum */
    double tol_round = 16 * DBL_EPSILON * A * (K + 10);
    double tol_max = 0;
    for (int k = 1; k <= K; k++)
        tol_max += alias_bound(wave, A, k, N);
    tol_max = 1.5 * tol_max + tol_round;

    /* ---- scalars ---- */
    const char *ov_label = wave == W_TRIANGLE
                               ? "overshoot max S_K - A (negative: the corner is rounded off, no overshoot)"
                               : "Gibbs overshoot max S_K - A";
    mm_res_scalar_v1(res, "overshoot", ov_label, "", overshoot);
    if (jump > 0)
        mm_res_scalar_v1(res, "overshoot_fraction", "overshoot / jump", "", overshoot / jump);
    mm_res_scalar_v1(res, "t_max", "time of the maximum of S_K", "s", t_max);
    double G = si_pi() / M_PI - 0.5;
    mm_res_scalar_v1(res, "gibbs_constant", "Gibbs constant Si(pi)/pi - 1/2 (limit of overshoot/jump)", "", G);
    mm_res_scalar_v1(res, "samples", "samples per period N", "", (double)N);
    mm_res_scalar_v1(res, "omega", "fundamental angular frequency 2 pi / T", "rad/s", 2 * M_PI / T);

    /* ---- checks ---- */
    mm_res_check_abs(res, "coefficients: FFT of a sampled period vs the closed forms (6)-(8), worst |error|",
                     worst, 0, 1.5 * tol_coef + 64 * DBL_EPSILON * A);
    /* the refined maximum against the analytic one: only rounding of the
     * K-term sums separates them (the value at a maximum is flat in t) */
    if (wave == W_SQUARE)
        mm_res_check_abs(res, "max S_K: refined vs S_K at t = T/(4n) from eq. (10)", s_max, s_ref, tol_round);
    else if (wave == W_SAWTOOTH)
        mm_res_check_abs(res, "max S_K: refined vs S_K at t = -T/(2(K+1)) from eq. (12)", s_max, s_ref, tol_round);
    else
        mm_res_check_abs(res, "max S_K: refined vs the value at the corner t = 0, eq. (14)", s_max, s_ref, tol_round);
    mm_res_check_abs(res, "max S_K from the FFT coefficients vs from the closed forms (aliasing bound)",
                     s_fft, s_max, tol_max);
    if (wave == W_SQUARE) {
        /* midpoint rule for Si(pi): |error| <= pi^2 / (72 n^2), eq. (11) */
        double bound = M_PI * M_PI / (72.0 * n_odd * n_odd);
        mm_res_check_abs(res, "overshoot / jump vs the Gibbs constant, bound pi^2/(72 n^2) of eq. (11)",
                         overshoot / jump, G, bound + tol_max / jump);
    } else if (wave == W_SAWTOOTH) {
        /* trapezoidal rule: G - 1/(2(K+1)) within pi^2 / (36 (K+1)^2), eq. (13) */
        double h = 1.0 / (K + 1);
        mm_res_check_abs(res, "overshoot / jump vs G - 1/(2(K+1)), bound pi^2/(36 (K+1)^2) of eq. (13)",
                         overshoot / jump, G - 0.5 * h, M_PI * M_PI / 36 * h * h + tol_max / jump);
    }
    /* the place of the maximum: the aliasing errors of the coefficients move
     * it by about 5e-6 T / K (their slope error over the curvature of S_K) */
    if (wave == W_SQUARE) {
        /* S_K of the square is symmetric about T/4: the same maximum sits at
         * T/(4n) and at T/2 - T/(4n); either is right */
        double dt = fmin(fabs(t_max - t_ref), fabs(t_max - (T / 2 - t_ref)));
        mm_res_check_abs(res, "time of the maximum: refined vs T/(4n) or T/2 - T/(4n), eq. (10) [s]", dt, 0,
                         1e-4 * T / (K + 1));
    } else if (wave == W_SAWTOOTH) {
        mm_res_check_abs(res, "time of the maximum: refined vs -T/(2(K+1)), eq. (12) [s]", t_max, t_ref,
                         1e-4 * T / (K + 1));
    }

    /* ---- series: one period, and a zoom on the jump (or the corner) ---- */
    int np = 16 * (K + 1) + 1;
    np = np < 1001 ? 1001 : np > 2001 ? 2001 : np;
    mm_series *sf = mm_res_series_v1(res, "wave", "the wave f(t)", "", "t", "s", np);
    mm_series *ss = mm_res_series_v1(res, "partial_sum", "partial sum S_K(t)", "", "t", "s", np);
    double half = fmin(T / 2, 6.0 * T / (K + 1));  /* six ripples either side */
    int nz = 601;
    mm_series *zf = mm_res_series_v1(res, "wave_zoom", "the wave near t = 0", "", "t", "s", nz);
    mm_series *zs = mm_res_series_v1(res, "partial_sum_zoom", "S_K(t) near t = 0", "", "t", "s", nz);
    if (!sf || !ss || !zf || !zs)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_linspace(-T / 2, T / 2, np, sf->x);
    mm_linspace(-half, half, nz, zf->x);
    for (int i = 0; i < np; i++) {
        ss->x[i] = sf->x[i];
        sf->y[i] = wave_t(wave, A, T, sf->x[i]);
    }
    for (int i = 0; i < nz; i++) {
        zs->x[i] = zf->x[i];
        zf->y[i] = wave_t(wave, A, T, zf->x[i]);
    }
    if ((rc = mm_fourier_series_eval(a, b, (size_t)K, T, ss->x, (size_t)np, ss->y, err)) != MM_OK ||
        (rc = mm_fourier_series_eval(a, b, (size_t)K, T, zs->x, (size_t)nz, zs->y, err)) != MM_OK)
        return rc;

    mm_res_method(res, "FFT of one sampled period (FFTW), golden-section refinement of max S_K", 0);
    mm_res_method_stat(res, "samples", (double)N);
    mm_res_method_stat(res, "terms", K);
    mm_res_method_stat(res, "scan_points", ceil(8.0 * (K + 1)));
    if (K > 120)
        mm_res_warn(res, "with K = %d the ripple (period about T/%d) is finer than the one-period plot "
                         "can draw; the zoom series shows it", K, K);
    return MM_OK;
}

static const char *const references[] = {
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, section 1.11 (harmonic analysis)",
    "H. S. Carslaw, Introduction to the Theory of Fourier's Series and Integrals, 3rd ed., Dover 1930, ch. IX",
    "E. Hewitt, R. E. Hewitt, The Gibbs-Wilbraham phenomenon, Arch. Hist. Exact Sci. 21 (1979) 129-160",
    NULL,
};

const mm_exercise mm_ex_vib_fourier_series = {
    .id = "vib-fourier-series",
    .chapter = 5,
    .section = "5.4",
    .title = "Fourier series and the Gibbs overshoot",
    .summary = "Square, sawtooth and triangle waves as sums of harmonics: coefficients by FFT, partial sums, "
               "the 9 % overshoot at a jump.",
    .tags = "Fourier series, harmonics, FFT, Gibbs phenomenon, periodic motion",
    .theory = "exercises/vib/fourier_series.md",
    .params = params,
    .n_params = MM_COUNT(params),
    .references = references,
    .check = NULL,
    .solve = solve,
};
