/* harmonics.c — vib-harmonics: the sum of two harmonic motions; beats, the
 * envelope, periodicity, and the Lissajous figure of one against the other.
 *
 *     x(t) = A1 cos(w1 t + phi1) + A2 cos(w2 t + phi2)                    (1)
 *
 * Goal: see that two close frequencies beat — the sum swells and fades
 * with the beat period 2 pi / |w1 - w2| between |A1 - A2| and A1 + A2
 * (the envelope, eq. 4 of the theory) — and that the sum is periodic only
 * when w1 / w2 is a ratio of whole numbers (eq. 6), which is also when the
 * Lissajous figure closes.
 * The motion is a closed form, so the checks compare two closed forms that
 * are computed differently (the direct sum (1) against the envelope-phase
 * form (3), and the product form (5) when A1 = A2), and, when the motion
 * does beat, *measurements* on the signal against the formulas: the carrier
 * peaks (local maxima of x, found by Brent's method on x' = 0) reach up to
 * A1 + A2, and the minima of the peak heights recur with the beat period.
 * Reference: S. S. Rao, Mechanical Vibrations, 6th ed., section 1.10;
 * A. P. French, Vibrations and Waves, Norton 1971, ch. 2.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>

#include "mm_exhelp.h"
#include "mm_peaks.h"
#include "mm_rational.h"
#include "mm_roots.h"

enum { P_A1, P_W1, P_PHI1, P_A2, P_W2, P_PHI2, P_TEND, P_POINTS };

#define MAX_RADIANS 2e4        /* t_end times the faster frequency: ~3200 periods */
#define MAX_Q 1000             /* largest denominator of w1/w2 called periodic */
#define MAX_MINIMA 4000

static const mm_param params[] = {
    [P_A1] = {"A1", "amplitude 1", "m", MM_REAL, 1, 1e-6, 1e3,
              .help = "amplitude of the first harmonic, 1 um to 1 km (only the ratio A2/A1 shapes the sum)"},
    [P_W1] = {"omega1", "angular frequency 1", "rad/s", MM_REAL, 10, 0.01, 1e3,
              .help = "angular frequency of the first harmonic, 0.01 to 1000 rad/s"},
    [P_PHI1] = {"phi1", "phase 1", "rad", MM_REAL, 0, -M_PI, M_PI,
                .help = "phase angle of the first harmonic (one turn, -pi to pi, says it all)"},
    [P_A2] = {"A2", "amplitude 2", "m", MM_REAL, 1, 1e-6, 1e3,
              .help = "amplitude of the second harmonic; equal amplitudes cancel fully at the beat nodes"},
    [P_W2] = {"omega2", "angular frequency 2", "rad/s", MM_REAL, 11, 0.01, 1e3,
              .help = "close to omega1 the sum beats; a ratio of whole numbers (q <= 1000) makes it periodic"},
    [P_PHI2] = {"phi2", "phase 2", "rad", MM_REAL, 0, -M_PI, M_PI,
                .help = "phase angle of the second harmonic (one turn, -pi to pi, says it all)"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 20, 0.01, 1e3,
                .help = "length of the plotted motion; at most 2e4 radians of the faster harmonic "
                        "(3,200 periods: the peaks are found one by one)"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 401, 101, 4001,
                  .help = "samples of each plotted curve (a plot shows no more)"},
};

enum { O_BEAT, O_BEAT_F, O_CARRIER, O_EMAX, O_EMIN, O_PERIODIC, O_PERIOD, O_PEAK_MAX, O_PEAK_MIN, O_X, O_ENV,
       O_ENV_LO, O_X1, O_X2, O_LISSAJOUS };

static const mm_output outputs[] = {
    [O_BEAT] = MM_SCALAR("beat_period", "beat period 2 pi / |omega1 - omega2|", "s", .flags = MM_ANSWER | MM_EXACT),
    [O_BEAT_F] = MM_SCALAR("beat_frequency", "beat frequency |omega1 - omega2| / (2 pi)", "Hz", .flags = MM_EXACT),
    [O_CARRIER] = MM_SCALAR("carrier_omega", "mean angular frequency (omega1 + omega2)/2", "rad/s", .flags = MM_EXACT),
    [O_EMAX] = MM_SCALAR("envelope_max", "largest envelope A1 + A2", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_EMIN] = MM_SCALAR("envelope_min", "smallest envelope |A1 - A2|", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_PERIODIC] = MM_SCALAR("periodic", "is the sum periodic?", "", .flags = MM_ANSWER | MM_EXACT),
    [O_PERIOD] = MM_SCALAR("period", "period of the sum, eq. (6)", "s", .flags = MM_ANSWER | MM_EXACT),
    [O_PEAK_MAX] = MM_SCALAR("peak_max", "highest carrier peak (measured)", "m"),
    [O_PEAK_MIN] = MM_SCALAR("peak_min", "lowest carrier peak (measured)", "m"),
    [O_X] = MM_SERIES("x", "x1 + x2", "m", "t", "s", .figure = "sum"),
    [O_ENV] = MM_SERIES("envelope", "envelope +E(t)", "m", "t", "s", .figure = "sum", .role = "reference"),
    [O_ENV_LO] = MM_SERIES("envelope_lower", "envelope -E(t)", "m", "t", "s", .figure = "sum", .role = "reference"),
    [O_X1] = MM_SERIES("x1", "first harmonic x1", "m", "t", "s", .figure = "parts"),
    [O_X2] = MM_SERIES("x2", "second harmonic x2", "m", "t", "s", .figure = "parts"),
    [O_LISSAJOUS] = MM_SERIES("lissajous", "Lissajous figure: x2 against x1", "m", "x1", "m", .figure = "lissajous",
                              .aspect = "equal"),
};

typedef struct harm {
    double A1, w1, p1, A2, w2, p2;
} harm;

static harm model(const mm_value *in)
{
    return (harm){in[P_A1].x, in[P_W1].x, in[P_PHI1].x, in[P_A2].x, in[P_W2].x, in[P_PHI2].x};
}

static int check(const mm_value *in, mm_error *err)
{
    double wmax = fmax(in[P_W1].x, in[P_W2].x), t_end = in[P_TEND].x;
    if (t_end * wmax > MAX_RADIANS)
        return mm_error_set(err, MM_ERANGE, "t_end",
                            "t_end must be at most %g s with the faster harmonic at %g rad/s (%g radians, "
                            "about 3200 periods); got %g s", MAX_RADIANS / wmax, wmax, MAX_RADIANS, t_end);
    return MM_OK;
}

static double x_sum(const harm *h, double t)                      /* eq. (1) */
{
    return h->A1 * cos(h->w1 * t + h->p1) + h->A2 * cos(h->w2 * t + h->p2);
}

/* The envelope and the phase of eq. (3): x = E cos(w1 t + phi1 + psi),
 * E = |A1 + A2 e^{i Delta}|, Delta = (w2 - w1) t + phi2 - phi1. */
static double envelope(const harm *h, double t, double *psi)
{
    double d = (h->w2 - h->w1) * t + (h->p2 - h->p1);
    double re = h->A1 + h->A2 * cos(d), im = h->A2 * sin(d);
    if (psi)
        *psi = atan2(im, re);
    return hypot(re, im);                                          /* eq. (4), no cancellation */
}

static int dx_dt(double t, double *fx, void *ctx)
{
    const harm *h = ctx;
    *fx = -h->A1 * h->w1 * sin(h->w1 * t + h->p1) - h->A2 * h->w2 * sin(h->w2 * t + h->p2);
    return 0;
}

/* The carrier peaks: local maxima of x found by Brent's method on x' = 0
 * over 8 parts per period of the faster harmonic.  tp, pp receive their
 * times and heights; returns the count, or -1 with *rc set. */
static int carrier_peaks(const harm *h, double t_end, double wmax, double *tp, double *pp, int cap,
                         long *evals, int *nsub, mm_result *res, mm_error *err, int *rc)
{
    *nsub = (int)ceil(8 * t_end * wmax / (2 * M_PI)) + 8;
    mm_roots_problem prob = {.f = dx_dt, .params = (void *)h, .a = 0, .b = t_end};
    mm_roots_options opt;
    mm_roots_options_init(&opt);
    opt.n = *nsub;
    opt.tol = 1e-11 / wmax;
    mm_roots_result rr = {.cap = cap};
    rr.roots = mm_res_alloc(res, sizeof *rr.roots * (size_t)cap);
    if (!rr.roots) {
        *rc = MM_ENOMEM;
        return -1;
    }
    if ((*rc = mm_roots_solve(&prob, &opt, &rr, err)) != MM_OK)
        return -1;
    *evals = rr.nevals;
    int np = 0;
    for (int i = 0; i < rr.nroots; i++) {
        double t = rr.roots[i].x;
        double x2 = -h->A1 * h->w1 * h->w1 * cos(h->w1 * t + h->p1) - h->A2 * h->w2 * h->w2 * cos(h->w2 * t + h->p2);
        if (x2 < 0) {                                                /* a maximum of x */
            tp[np] = t;
            pp[np++] = x_sum(h, t);
        }
    }
    return np;
}

static int curves(const harm *h, double t_end, int n, double Tl, double tol_form, mm_result *res)
{
    mm_series *sx = mm_res_series(res, O_X, n), *se = mm_res_series(res, O_ENV, n);
    mm_series *sl = mm_res_series(res, O_ENV_LO, n), *s1 = mm_res_series(res, O_X1, n);
    mm_series *s2 = mm_res_series(res, O_X2, n), *lj = mm_res_series(res, O_LISSAJOUS, n);
    if (!sx || !se || !sl || !s1 || !s2 || !lj)
        return MM_ENOMEM;
    mm_ex_time_grid(t_end, n, sx->x);
    double worst_form = 0, worst_prod = 0, Emax = h->A1 + h->A2;
    int equal = fabs(h->A1 - h->A2) <= 1e-12 * Emax;
    for (int i = 0; i < n; i++) {
        double t = sx->x[i], psi;
        se->x[i] = sl->x[i] = s1->x[i] = s2->x[i] = t;
        s1->y[i] = h->A1 * cos(h->w1 * t + h->p1);
        s2->y[i] = h->A2 * cos(h->w2 * t + h->p2);
        sx->y[i] = s1->y[i] + s2->y[i];
        double E = envelope(h, t, &psi);
        se->y[i] = E;
        sl->y[i] = -E;
        worst_form = fmax(worst_form, fabs(sx->y[i] - E * cos(h->w1 * t + h->p1 + psi)));      /* eq. (3) */
        if (equal) {                                                                           /* eq. (5) */
            double xp = 2 * h->A1 * cos(0.5 * ((h->w2 - h->w1) * t + h->p2 - h->p1)) *
                        cos(0.5 * ((h->w1 + h->w2) * t + h->p1 + h->p2));
            worst_prod = fmax(worst_prod, fabs(sx->y[i] - xp));
        }
    }
    /* the Lissajous figure over one common period if it fits, else over t_end */
    for (int i = 0; i < n; i++) {
        double t = Tl * i / (n - 1);
        lj->x[i] = h->A1 * cos(h->w1 * t + h->p1);
        lj->y[i] = h->A2 * cos(h->w2 * t + h->p2);
    }
    /* the curves beside the answer x: six digits are all a plot can show */
    mm_ex_round_sig(se->y, n, 6);
    mm_ex_round_sig(sl->y, n, 6);
    mm_ex_round_sig(s1->y, n, 6);
    mm_ex_round_sig(s2->y, n, 6);
    mm_ex_round_sig(lj->x, n, 6);
    mm_ex_round_sig(lj->y, n, 6);
    mm_res_check_abs(res, "direct sum (1) vs envelope-phase form (3): worst difference [m]", worst_form, 0, tol_form);
    if (equal)
        mm_res_check_abs(res, "direct sum (1) vs product form (5) (A1 = A2): worst difference [m]", worst_prod, 0,
                         tol_form);
    return MM_OK;
}

/* Beats: the carrier peaks reach A1 + A2 and their lowest ones recur with
 * the beat period. */
static int beats(const harm *h, double t_end, const double *tp, const double *pp, int np, mm_result *res)
{
    const double dw = fabs(h->w1 - h->w2), wm = 0.5 * (h->w1 + h->w2), Emax = h->A1 + h->A2;
    const double Emin = fabs(h->A1 - h->A2), Tb = dw > 0 ? 2 * M_PI / dw : INFINITY, Tc = 2 * M_PI / wm;
    if (dw == 0)
        return mm_res_warn(res, "equal frequencies: no beats; the sum is one harmonic of amplitude %g m", Emax);
    if (wm < 5 * dw)
        return mm_res_warn(res, "the frequencies are far apart (beat period %.3g s, only %.2g carrier periods): "
                                "no clear beats to measure; bring omega2 closer to omega1", Tb, Tb / Tc);
    if (fmin(h->A1, h->A2) < 0.05 * fmax(h->A1, h->A2))
        return mm_res_warn(res, "the smaller amplitude is under 5 %% of the larger: the envelope hardly moves "
                                "(between %g and %g m); the beat period is not measured", Emin, Emax);
    double *tmin = mm_res_alloc(res, sizeof *tmin * MAX_MINIMA), *ymin = mm_res_alloc(res, sizeof *ymin * MAX_MINIMA);
    if (!tmin || !ymin)
        return MM_ENOMEM;
    /* the envelope's bottoms measured on the signal: the heights p_i of
     * successive carrier peaks sample E(t_i); where p_i^2 dips below the
     * mean level A1^2 + A2^2, a parabola through three neighbours gives the
     * bottom; dips closer than half a beat period are one */
    double *p2 = mm_res_alloc(res, sizeof *p2 * (size_t)(np + 1));
    if (!p2)
        return MM_ENOMEM;
    for (int i = 0; i < np; i++)
        p2[i] = pp[i] * pp[i];
    int nm = mm_peaks_minima(np, tp, p2, h->A1 * h->A1 + h->A2 * h->A2, 0.5 * Tb, MAX_MINIMA, tmin, ymin);
    int regular = nm >= 2;
    for (int i = 1; i < nm; i++)
        if (fabs(tmin[i] - tmin[i - 1] - Tb) > 0.5 * Tb)
            regular = 0;
    if (regular) {
        /* each bottom is placed to within half a carrier period, often far
         * better (a ratio of whole numbers repeats the peaks exactly): the
         * measurement is shown beside the formula with its actual error */
        double Tm = (tmin[nm - 1] - tmin[0]) / (nm - 1);
        mm_res_method_stat(res, "beat_period_measured", Tm);
        mm_res_method_stat(res, "beat_period_measured_error", fabs(Tm - Tb));
    } else if (t_end >= 2.5 * Tb) {
        mm_res_warn(res, "the envelope minima could not be told apart (%d found): the beat period is not measured",
                    nm);
    } else {
        mm_res_warn(res, "t_end = %g s holds fewer than two envelope minima: raise it above %.3g s to measure the "
                         "beat period", t_end, 2.5 * Tb);
    }
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    harm h = model(in);
    const double t_end = in[P_TEND].x;
    const int n = (int)in[P_POINTS].x;
    const double dw = fabs(h.w1 - h.w2), wm = 0.5 * (h.w1 + h.w2), wmax = fmax(h.w1, h.w2);
    const double Emax = h.A1 + h.A2;

    /* ---- periodicity, eq. (6) ---- */
    long p = 0, q = 0;
    /* w1/w2 = p/q with q <= MAX_Q, to the rounding of the given values (4 eps
     * relative: 10 and 11, or 0.1 and 0.3, as typed), by continued fractions */
    int periodic = mm_rational_approx(h.w1 / h.w2, MAX_Q, 4 * DBL_EPSILON, &p, &q);
    double Tp = periodic ? 2 * M_PI * (double)p / h.w1 : 0;   /* p periods of x1 = q periods of x2 */
    char ptext[120];
    if (periodic)
        snprintf(ptext, sizeof ptext, "periodic: omega1/omega2 = %ld/%ld", p, q);
    else
        snprintf(ptext, sizeof ptext, "not periodic: omega1/omega2 = %.17g is no ratio p/q with q <= %d",
                 h.w1 / h.w2, MAX_Q);

    if (dw > 0) {
        mm_res_scalar(res, O_BEAT, 2 * M_PI / dw);
        mm_res_scalar(res, O_BEAT_F, dw / (2 * M_PI));
    }
    mm_res_scalar(res, O_CARRIER, wm);
    mm_res_scalar(res, O_EMAX, Emax);
    mm_res_scalar(res, O_EMIN, fabs(h.A1 - h.A2));
    mm_res_scalar_text(res, O_PERIODIC, periodic, ptext);
    if (periodic)
        mm_res_scalar(res, O_PERIOD, Tp);

    /* rounding of cos at arguments up to w t_end: a few eps times the argument */
    double tol_form = 16 * DBL_EPSILON * (1 + wmax * t_end + M_PI) * Emax;
    int rc = curves(&h, t_end, n, periodic && Tp <= t_end ? Tp : t_end, tol_form, res);
    if (rc != MM_OK)
        return rc;

    /* ---- measurements on the signal: carrier peaks by Brent on x' = 0 ---- */
    int cap = (int)ceil(8 * t_end * wmax / (2 * M_PI)) + 9, nsub;
    double *tp = mm_res_alloc(res, sizeof *tp * (size_t)cap), *pp = mm_res_alloc(res, sizeof *pp * (size_t)cap);
    long evals = 0;
    if (!tp || !pp)
        return MM_ENOMEM;
    int np = carrier_peaks(&h, t_end, wmax, tp, pp, cap, &evals, &nsub, res, err, &rc);
    if (np < 0)
        return rc;
    double pmax = -INFINITY, pmin = INFINITY, excess = 0;
    for (int i = 0; i < np; i++) {
        pmax = fmax(pmax, pp[i]);
        pmin = fmin(pmin, pp[i]);
        excess = fmax(excess, pp[i] - envelope(&h, tp[i], NULL));
    }
    mm_res_method(res, "closed form; carrier peaks by Brent's method on x'(t) = 0", 0);
    mm_res_method_stat(res, "subintervals", nsub);
    mm_res_method_stat(res, "peaks", np);
    mm_res_method_stat(res, "evaluations", (double)evals);
    if (np > 0) {
        /* a peak's height: x at a time found to 2e-11/wmax, where x is flat
         * (x'' dt^2 / 2), plus the rounding of the cosines */
        double dt = 2e-11 / wmax, peak_err = tol_form + 0.5 * (h.A1 * h.w1 * h.w1 + h.A2 * h.w2 * h.w2) * dt * dt;
        mm_res_scalar_err(res, O_PEAK_MAX, pmax, peak_err, MM_ERR_BOUND);
        mm_res_scalar_err(res, O_PEAK_MIN, pmin, peak_err, MM_ERR_BOUND);
        mm_res_check_abs(res, "carrier peaks never rise above the envelope (4): worst excess [m]", fmax(0, excess), 0,
                         tol_form);
    }
    if ((rc = beats(&h, t_end, tp, pp, np, res)) != MM_OK)
        return rc;
    mm_ex_warn_aliasing(res, n, t_end, wmax, "shorten t_end or raise points");
    return MM_OK;
}

static const char *const references[] = {
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, section 1.10 (harmonic motion, beats)",
    "A. P. French, Vibrations and Waves, Norton 1971, ch. 2 (superposed vibrations, Lissajous figures)",
    "R. P. Brent, Algorithms for Minimization without Derivatives, Prentice-Hall 1973, ch. 4",
    NULL,
};

const mm_exercise mm_ex_vib_harmonics = {
    .id = "vib-harmonics", .chapter = 5, .section = "5.2", .title = "Two harmonics: beats and Lissajous figures",
    .summary = "The sum of two harmonic motions: beats and their envelope, when the sum is periodic, and the "
               "Lissajous figure of one against the other.",
    .tags = "harmonic motion, beats, envelope, periodic motion, Lissajous", .theory = "exercises/vib/harmonics.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
