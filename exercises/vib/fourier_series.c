/* fourier_series.c — vib-fourier-series: the Fourier series of a square, a
 * sawtooth and a triangle wave, and the Gibbs overshoot at a jump.
 *
 *     f(t) ~ S_K(t) = a_0/2 + sum_{k=1..K} (a_k cos k w t + b_k sin k w t)   (1)
 *
 * Goal: the coefficients in closed form (eqs. 6-8), and the same computed
 * numerically (one period sampled and transformed by the FFT, eq. 5) beside
 * them with their errors; the partial sum S_K from the exact coefficients
 * rings at a jump: its maximum overshoots by about 8.95 % of the jump
 * however many terms are taken (Gibbs).  The overshoot is S_K at its known
 * maximum (eqs. 10, 12, 14); the maximum refined numerically (scan + golden
 * section, mm_fourier_series_max) and the one of the FFT's series are shown
 * beside it, and the overshoot is checked against the Gibbs constant with a
 * bound that depends honestly on K (eqs. 11, 13).
 * Reference: S. S. Rao, Mechanical Vibrations, 6th ed., section 1.11;
 * H. S. Carslaw, Introduction to the Theory of Fourier's Series and
 * Integrals, 3rd ed., Dover 1930, ch. IX (Gibbs's phenomenon).
 */
#include <float.h>
#include <math.h>

#include "mm_exhelp.h"
#include "mm_fourier.h"
#include "mm_special.h"

enum { P_WAVE, P_TERMS, P_T, P_A };
enum { W_SQUARE, W_SAWTOOTH, W_TRIANGLE };

static const char *const waves[] = {"square", "sawtooth", "triangle", NULL};

#define MAX_TERMS 1000   /* max S_K costs 8 K^2 term evaluations: 25 ms at 1000 */

static const mm_param params[] = {
    [P_WAVE] = {"wave", "wave form", "", MM_CHOICE, W_SQUARE, 0, 0, .choices = waves,
                .help = "square: +A then -A; sawtooth: a ramp from -A to A, then a jump back; "
                        "triangle: straight lines between A and -A (no jump)"},
    [P_TERMS] = {"terms", "highest harmonic K", "", MM_INT, 25, 1, MAX_TERMS,
                 .help = "harmonics 1..K are summed; the ripple narrows as K grows, the overshoot does not; "
                         "at most 1000 (refining max S_K costs 8 K^2 terms)"},
    [P_T] = {"T", "period", "s", MM_REAL, 1, 1e-3, 1e3,
             .help = "the wave repeats every T seconds (1 ms to 1000 s: only the time axis scales)"},
    [P_A] = {"A", "amplitude", "", MM_REAL, 1, 1e-6, 1e6,
             .help = "peak value of the wave (any unit: m, N, V); the wave swings between -A and A; "
                     "1e-6 to 1e6 (it only scales)"},
};

enum { O_OVERSHOOT, O_FRACTION, O_TMAX, O_GIBBS, O_SAMPLES, O_OMEGA, O_COEFFS, O_WAVE, O_SUM, O_WAVE_ZOOM,
       O_SUM_ZOOM };

static const char *const coef_cols[] = {"k", "a_k", "b_k", "a_k_fft", "b_k_fft", "fft_error", "fft_error_bound",
                                        NULL};
static const char *const coef_units[] = {"", "", "", "", "", "", "", NULL};

static const mm_output outputs[] = {
    [O_OVERSHOOT] = MM_SCALAR("overshoot", "overshoot max S_K - A (negative: no overshoot), eqs. (10), (12), (14)",
                              "", .flags = MM_ANSWER | MM_EXACT),
    [O_FRACTION] = MM_SCALAR("overshoot_fraction", "overshoot / jump", "", .flags = MM_ANSWER | MM_EXACT),
    [O_TMAX] = MM_SCALAR("t_max", "time of the maximum of S_K, eqs. (10), (12), (14)", "s", .flags = MM_EXACT),
    [O_GIBBS] = MM_SCALAR("gibbs_constant", "Gibbs constant Si(pi)/pi - 1/2 (limit of overshoot/jump)", "",
                          .flags = MM_EXACT),
    [O_SAMPLES] = MM_SCALAR("samples", "samples per period N of the FFT", "", .flags = MM_EXACT),
    [O_OMEGA] = MM_SCALAR("omega", "fundamental angular frequency 2 pi / T", "rad/s", .flags = MM_EXACT),
    [O_COEFFS] = MM_TABLE("coefficients", "coefficients: exact (6)-(8), and by FFT (5) with their error",
                          coef_cols, coef_units),
    [O_WAVE] = MM_SERIES("wave", "the wave f(t)", "", "t", "s", .figure = "period", .role = "reference"),
    [O_SUM] = MM_SERIES("partial_sum", "partial sum S_K(t)", "", "t", "s", .figure = "period"),
    [O_WAVE_ZOOM] = MM_SERIES("wave_zoom", "the wave near t = 0", "", "t", "s", .figure = "zoom", .role = "reference"),
    [O_SUM_ZOOM] = MM_SERIES("partial_sum_zoom", "S_K(t) near t = 0", "", "t", "s", .figure = "zoom"),
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

/* The maximum of S_K at its known place, eqs. (10), (12), (14): the value
 * (a K-term sum) and the time. */
static double known_max(int wave, double A, double T, int K, double *t)
{
    double s = 0;
    int n_odd = (K + 1) / 2;                       /* odd harmonics 1, 3, .., <= K */
    if (wave == W_SQUARE) {
        for (int j = 1; j <= n_odd; j++)
            s += sin((2 * j - 1) * M_PI / (2 * n_odd)) / (2 * j - 1);
        *t = T / (4 * n_odd);
        return s * 4 * A / M_PI;
    }
    if (wave == W_SAWTOOTH) {
        for (int k = 1; k <= K; k++)
            s += sin(k * M_PI / (K + 1)) / k;
        *t = -T / (2.0 * (K + 1));
        return s * 2 * A / M_PI;
    }
    for (int k = 1; k <= K; k += 2)
        s += 1.0 / ((double)k * k);
    *t = 0;
    return s * 8 * A / (M_PI * M_PI);
}

/* |S_K''(t)| = |sum k^2 w^2 (a_k cos k w t + b_k sin k w t)|: the curvature
 * at the maximum, which sets how far rounding can move it. */
static double curvature(const double *a, const double *b, int K, double T, double t)
{
    double w = 2 * M_PI / T, s = 0;
    for (int k = 1; k <= K; k++)
        s += (double)k * k * (a[k] * cos(k * w * t) + b[k] * sin(k * w * t));
    return fabs(s) * w * w;
}

/* The table: exact coefficients, the FFT's, their error and its bound (9). */
static int table(int wave, double A, int K, long N, const double *ax, const double *bx, const double *a,
                 const double *b, double *worst, double *tol_coef, mm_result *res)
{
    mm_table *tab = mm_res_table(res, O_COEFFS, K + 1);
    if (!tab)
        return MM_ENOMEM;
    *worst = *tol_coef = 0;
    for (int k = 0; k <= K; k++) {
        double *row = tab->cell + 7 * k, e = fmax(fabs(a[k] - ax[k]), k ? fabs(b[k] - bx[k]) : 0);
        row[0] = k;
        row[1] = ax[k];
        row[2] = bx[k];
        row[3] = a[k];
        row[4] = k ? b[k] : 0;
        row[5] = e;
        row[6] = alias_bound(wave, A, k, N) + 64 * DBL_EPSILON * A;
        *worst = fmax(*worst, e);
        *tol_coef = fmax(*tol_coef, alias_bound(wave, A, k, N));
    }
    return MM_OK;
}

static int curves(int wave, double A, double T, int K, const double *ax, const double *bx, mm_result *res,
                  mm_error *err)
{
    int np = 16 * (K + 1) + 1;
    np = np < 601 ? 601 : np > 2001 ? 2001 : np;
    double half = fmin(T / 2, 6.0 * T / (K + 1));  /* six ripples either side */
    int nz = 401;
    mm_series *sf = mm_res_series(res, O_WAVE, np), *ss = mm_res_series(res, O_SUM, np);
    mm_series *zf = mm_res_series(res, O_WAVE_ZOOM, nz), *zs = mm_res_series(res, O_SUM_ZOOM, nz);
    if (!sf || !ss || !zf || !zs)
        return MM_ENOMEM;
    mm_linspace(-T / 2, T / 2, np, sf->x);
    mm_linspace(-half, half, nz, zf->x);
    mm_ex_round_sig(sf->x, np, 12);
    mm_ex_round_sig(zf->x, nz, 12);
    for (int i = 0; i < np; i++) {
        ss->x[i] = sf->x[i];
        sf->y[i] = wave_t(wave, A, T, sf->x[i]);
    }
    for (int i = 0; i < nz; i++) {
        zs->x[i] = zf->x[i];
        zf->y[i] = wave_t(wave, A, T, zf->x[i]);
    }
    int rc = mm_fourier_series_eval(ax, bx, (size_t)K, T, ss->x, (size_t)np, ss->y, err);
    if (rc == MM_OK)
        rc = mm_fourier_series_eval(ax, bx, (size_t)K, T, zs->x, (size_t)nz, zs->y, err);
    return rc;
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
    double *x = mm_res_alloc(res, sizeof *x * (size_t)N), *a = mm_res_alloc(res, 4 * sizeof *a * (size_t)(K + 1));
    if (!x || !a)
        return MM_ENOMEM;
    double *b = a + K + 1, *ax = b + K + 1, *bx = ax + K + 1;
    for (long j = 0; j < N; j++)
        x[j] = wave_at(wave, A, j, N);
    int rc = mm_fourier_series_coeffs(x, (size_t)N, (size_t)K, a, b, err);
    if (rc != MM_OK)
        return rc;
    for (int k = 0; k <= K; k++)
        exact_coeff(wave, A, k, &ax[k], &bx[k]);
    double worst, tol_coef;
    if ((rc = table(wave, A, K, N, ax, bx, a, b, &worst, &tol_coef, res)) != MM_OK)
        return rc;

    /* the maximum of S_K: at its known place (the answer), refined
     * numerically from the exact coefficients, and from the FFT's */
    double t_ref, s_ref = known_max(wave, A, T, K, &t_ref), t_max, s_max, t_fft, s_fft;
    rc = mm_fourier_series_max(ax, bx, (size_t)K, T, -T / 2, T / 2, &t_max, &s_max, err);
    if (rc == MM_OK)
        rc = mm_fourier_series_max(a, b, (size_t)K, T, -T / 2, T / 2, &t_fft, &s_fft, err);
    if (rc != MM_OK)
        return rc;
    /* rounding of a K-term sum; the FFT's series is off by at most the sum
     * of its coefficients' errors (9) */
    double tol_round = 4 * DBL_EPSILON * A * (K + 10), tol_max = 0;
    for (int k = 1; k <= K; k++)
        tol_max += alias_bound(wave, A, k, N);
    tol_max = 1.5 * tol_max + tol_round;
    double G = mm_special_si(M_PI) / M_PI - 0.5;             /* Si(pi) = int_0^pi sin(u)/u du */
    /* S_K at its known place is a K-term sum: exact but for its rounding,
     * which matters when the overshoot is a small part of A (the triangle) */
    mm_res_scalar_err(res, O_OVERSHOOT, s_ref - A, tol_round, MM_ERR_BOUND);
    if (jump > 0)
        mm_res_scalar_err(res, O_FRACTION, (s_ref - A) / jump, tol_round / jump, MM_ERR_BOUND);
    mm_res_scalar(res, O_TMAX, t_ref);
    mm_res_scalar(res, O_GIBBS, G);
    mm_res_scalar(res, O_SAMPLES, (double)N);
    mm_res_scalar(res, O_OMEGA, 2 * M_PI / T);
    /* the square's S_K is symmetric about T/4: its maximum sits at T/(4n)
     * and at T/2 - T/(4n); the refined one is compared with the nearer */
    double t_near = wave == W_SQUARE && fabs(t_max - (T / 2 - t_ref)) < fabs(t_max - t_ref) ? T / 2 - t_ref : t_ref;

    /* ---- checks ---- */
    mm_res_check_abs(res, "coefficients: FFT of a sampled period vs the closed forms (6)-(8), worst |error|, "
                          "within the aliasing bound (9)", worst, 0, 1.5 * tol_coef + 64 * DBL_EPSILON * A);
    mm_res_check_abs(res, "max S_K: refined numerically vs S_K at its known place, eqs. (10), (12), (14) "
                          "(rounding of the K-term sums)", s_max, s_ref, tol_round);
    mm_res_check_abs(res, "max S_K from the FFT coefficients vs from the closed forms, within the sum of the "
                          "aliasing bounds (9)", s_fft, s_ref, tol_max);
    /* the place: golden section's bracket (1e-13 T), and the width where S_K
     * is flat to its rounding, sqrt(4 tol_round / |S_K''|) */
    if (wave != W_TRIANGLE)
        mm_res_check_abs(res, "time of the maximum: refined vs eqs. (10), (12) [s], within the bracket and the "
                              "width where S_K is flat to rounding", t_max, t_near,
                         1e-13 * T + sqrt(4 * tol_round / curvature(ax, bx, K, T, t_ref)));
    if (wave == W_SQUARE) {
        /* midpoint rule for Si(pi): |error| <= pi^2 / (72 n^2), eq. (11) */
        int n = (K + 1) / 2;
        mm_res_check_abs(res, "overshoot / jump vs the Gibbs constant, bound pi^2/(72 n^2) of eq. (11)",
                         (s_ref - A) / jump, G, M_PI * M_PI / (72.0 * n * n) + tol_round / jump);
    } else if (wave == W_SAWTOOTH) {
        /* trapezoidal rule: G - 1/(2(K+1)) within pi^2 / (36 (K+1)^2), eq. (13) */
        double h = 1.0 / (K + 1);
        mm_res_check_abs(res, "overshoot / jump vs G - 1/(2(K+1)), bound pi^2/(36 (K+1)^2) of eq. (13)",
                         (s_ref - A) / jump, G - 0.5 * h, M_PI * M_PI / 36 * h * h + tol_round / jump);
    }

    /* ---- series: one period, and a zoom on the jump (or the corner) ---- */
    if ((rc = curves(wave, A, T, K, ax, bx, res, err)) != MM_OK)
        return rc;
    mm_res_method(res, "closed forms; FFT of one sampled period (FFTW), golden-section refinement of max S_K "
                       "(mm_opt) beside them", 0);
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
    .id = "vib-fourier-series", .chapter = 5, .section = "5.4", .title = "Fourier series and the Gibbs overshoot",
    .summary = "Square, sawtooth and triangle waves as sums of harmonics: coefficients by FFT, partial sums, "
               "the 9 % overshoot at a jump.",
    .tags = "Fourier series, harmonics, FFT, Gibbs phenomenon, periodic motion",
    .theory = "exercises/vib/fourier_series.md", .params = params, .n_params = MM_COUNT(params), .outputs = outputs,
    .n_outputs = MM_COUNT(outputs), .references = references, .solve = solve,
};
