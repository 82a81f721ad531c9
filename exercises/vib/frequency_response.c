/* frequency_response.c — vib-frequency-response: the amplitude and phase of
 * a damped oscillator's steady response against the forcing frequency, for
 * several damping ratios.
 *
 *     x'' + 2 zeta omega_n x' + omega_n^2 x = omega_n^2 (F0/k) cos(omega t)
 *     X / (F0/k) = |H(r)| = 1 / |1 - r^2 + 2 i zeta r|,  r = omega/omega_n   (1)
 *
 * Goal: read a frequency response: where the peak is (r = sqrt(1 - 2
 * zeta^2), not r = 1; at r = 0 when zeta >= 1/sqrt(2)), how high
 * (1 / (2 zeta sqrt(1 - zeta^2))), how wide (the half-power bandwidth,
 * about 2 zeta omega_n), and how the phase swings through pi/2 at r = 1.
 * The answers are the closed forms (3)-(5); the peak is also found by
 * golden-section search on |H| (mm_opt) and the half-power points by
 * Brent's method, each shown with the bound of its error; formula (1)
 * itself is checked by a time integration started on the steady orbit.
 * Reference: S. S. Rao, Mechanical Vibrations, 6th ed., sections 3.4-3.5;
 * golden section: W. H. Press et al., Numerical Recipes, 3rd ed., 10.2.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>

#include "mm_exhelp.h"
#include "mm_opt.h"
#include "mm_roots.h"

enum { P_ZETA, P_OMEGA_N, P_RMAX, P_POINTS };

#define MAX_ZETAS 8
#define WINDOW 60                 /* extra points around each peak */
#define DELTA (4 * DBL_EPSILON)   /* relative rounding of |H| as computed */

static const mm_param params[] = {
    [P_ZETA] = {"zeta", "damping ratios", "", MM_VECTOR, 0, 1e-3, 5, .def_text = "0.05,0.1,0.2,0.5,1",
                .max_cols = MAX_ZETAS,
                .help = "one curve per damping ratio c/(2 sqrt(k m)), at most 8 (a plot shows no more); from "
                        "0.001 (a bell) to 5 (a creeping door closer); the first one's numbers are the scalars"},
    [P_OMEGA_N] = {"omega_n", "natural frequency", "rad/s", MM_REAL, 10, 1e-3, 1e4,
                   .help = "sqrt(k/m): converts the frequency ratio r to omega = r omega_n; 1e-3 to 1e4 rad/s"},
    [P_RMAX] = {"r_max", "largest frequency ratio", "", MM_REAL, 3, 1.5, 20,
                .help = "the plots run over omega/omega_n from 0 to r_max: past the peak (1.5) to far above it (20)"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 201, 51, 4001,
                  .help = "equally spaced samples of each curve (60 more are added around each peak); "
                          "a plot shows no more than 4001"},
};

enum { O_ZETA, O_Q, O_PEAK_R, O_PEAK_OMEGA, O_PEAK_H, O_PEAK_FOUND, O_BW, O_BW_APPROX, O_PHASE_RES, O_PEAKS,
       O_AMP, O_PHASE };

static const char *const peak_cols[] = {"zeta", "r_peak", "r_peak_found", "r_peak_found_error", "H_peak",
                                        "H_peak_found", "bandwidth", "bandwidth_approx", NULL};
static const char *const peak_units[] = {"", "", "", "", "", "", "rad/s", "rad/s", NULL};

static const mm_output outputs[] = {
    [O_ZETA] = MM_SCALAR("zeta", "damping ratio of the first curve", "", .flags = MM_EXACT),
    [O_Q] = MM_SCALAR("Q", "quality factor 1/(2 zeta)", "", .flags = MM_ANSWER | MM_EXACT),
    [O_PEAK_R] = MM_SCALAR("peak_r", "peak frequency ratio sqrt(1 - 2 zeta^2), eq. (3)", "",
                           .flags = MM_ANSWER | MM_EXACT),
    [O_PEAK_OMEGA] = MM_SCALAR("peak_omega", "peak frequency omega_n sqrt(1 - 2 zeta^2)", "rad/s",
                               .flags = MM_ANSWER | MM_EXACT),
    [O_PEAK_H] = MM_SCALAR("peak_height", "peak magnification 1/(2 zeta sqrt(1 - zeta^2))", "",
                           .flags = MM_ANSWER | MM_EXACT),
    [O_PEAK_FOUND] = MM_SCALAR("peak_omega_found", "peak frequency found by golden-section search", "rad/s"),
    [O_BW] = MM_SCALAR("bandwidth", "half-power bandwidth (exact, eq. 5)", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_BW_APPROX] = MM_SCALAR("bandwidth_approx", "half-power bandwidth, approximation 2 zeta omega_n", "rad/s",
                              .flags = MM_EXACT),
    [O_PHASE_RES] = MM_SCALAR("phase_at_resonance", "phase lag at omega = omega_n, eq. (4)", "rad", .flags = MM_EXACT),
    [O_PEAKS] = MM_TABLE("peaks", "peak and bandwidth of each damping ratio", peak_cols, peak_units),
    [O_AMP] = MM_SERIES("amplitude_%d", "|H| = X/(F0/k), curve %d", "", "omega/omega_n", "", .first = 1,
                        .last = MAX_ZETAS, .figure = "amplitude"),
    [O_PHASE] = MM_SERIES("phase_%d", "phase lag, curve %d", "rad", "omega/omega_n", "", .first = 1,
                          .last = MAX_ZETAS, .figure = "phase"),
};

/* ---- eq. (1) and its features ------------------------------------------------ */

static double amp(double r, double z)
{
    return 1 / hypot(1 - r * r, 2 * z * r);
}

static double phase(double r, double z)
{
    return atan2(2 * z * r, 1 - r * r);   /* lag in [0, pi] */
}

static int amp_fn(double r, double *f, void *ctx)
{
    *f = amp(r, *(const double *)ctx);
    return 0;
}

/* |d|H|/dr| = |dD/dr| / (2 D^(3/2)), D = (1 - r^2)^2 + (2 zeta r)^2. */
static double slope(double r, double z)
{
    double D = (1 - r * r) * (1 - r * r) + 4 * z * z * r * r;
    return fabs(-4 * r * (1 - r * r) + 8 * z * z * r) / (2 * D * sqrt(D)) + 1e-300;
}

/* How far from the peak r_p |H| stays within a relative 2 DELTA of its
 * height, so that rounding (DELTA each way) cannot tell the points apart
 * (eq. 3 rewritten):
 * below 1/sqrt(2), D - D_min = (r^2 - r_p^2)^2; above, r_p = 0 and
 * D - 1 = r^4 + 2 (2 zeta^2 - 1) r^2.  |H| changes by (D - D_min)/(2 D_min). */
static double flat_width(double z, double rp)
{
    if (2 * z * z < 1) {
        double s = sqrt(4 * DELTA * 4 * z * z * (1 - z * z));        /* |r^2 - r_p^2| */
        double up = s / (sqrt(rp * rp + s) + rp), down = rp - sqrt(fmax(0, rp * rp - s));
        return fmax(up, down);
    }
    double q = 2 * z * z - 1;
    return sqrt(4 * DELTA / (q + sqrt(q * q + 4 * DELTA)));
}

typedef struct half_ctx {
    double z, level;
} half_ctx;

static int half_fn(double r, double *f, void *ctx)
{
    const half_ctx *h = ctx;
    *f = amp(r, h->z) - h->level;
    return 0;
}

/* One damping ratio: the formulas and the numerical findings. */
typedef struct peak {
    int has_peak;          /* zeta < 1/sqrt(2): the peak is above r = 0 */
    double r_p, H_p;       /* eq. (3); r = 0 and 1 without a peak */
    double r_found, H_found, r_bound;   /* golden section and the bound of its error */
    int has_lower;         /* the lower half-power point exists */
    double r1, r2;         /* half-power points, eq. (5) */
    double bw;             /* r2 - r1 = (r2^2 - r1^2)/(r2 + r1), no cancellation at small zeta */
    double r1_found, r2_found;
} peak;

static int analyse(double z, peak *pk, long *evals, mm_error *err)
{
    /* 1 - 2 zeta^2 and 1 - zeta^2 without cancellation: zeta^2 = zz + e exactly */
    double zz = z * z, e = fma(z, z, -zz), u = (1 - 2 * zz) - 2 * e;
    *pk = (peak){.has_peak = u > 0, .H_p = 1};
    if (pk->has_peak) {
        pk->r_p = sqrt(u);
        pk->H_p = 1 / (2 * z * sqrt((1 - zz) - e));
    }
    mm_opt_result o;
    int rc = mm_opt_golden_max(amp_fn, &z, 0, 1.5, 1e-12, 200, &o, err);
    if (rc != MM_OK)
        return rc;
    pk->r_found = o.x;
    pk->H_found = o.fx;
    pk->r_bound = o.bracket + flat_width(z, pk->r_p) + 2 * DBL_EPSILON * pk->r_p;
    *evals += o.evals;
    if (!pk->has_peak)
        return MM_OK;

    /* eq. (5): r^2 = 1 - 2 zeta^2 -+ 2 zeta sqrt(1 - zeta^2) */
    double s = 2 * z * sqrt((1 - zz) - e), u1 = u - s;
    pk->r2 = sqrt(u + s);
    pk->has_lower = u1 > 0;
    pk->r1 = pk->has_lower ? sqrt(u1) : 0;
    pk->bw = 2 * s / (pk->r2 + pk->r1);

    half_ctx h = {.z = z, .level = pk->H_found / M_SQRT2};   /* half power of the peak found */
    double f_lo, f_p, f_hi, fx, width;
    half_fn(pk->r_found, &f_p, &h);
    half_fn(2, &f_hi, &h);             /* |H(2)| <= 1/3 < 1/sqrt(2) <= H_p/sqrt(2) */
    rc = mm_roots_brent(half_fn, &h, pk->r_found, 2, f_p, f_hi, 1e-15, 200, &pk->r2_found, &fx, &width,
                        NULL, evals, err);
    if (rc != MM_OK)
        return rc;
    half_fn(0, &f_lo, &h);
    if (f_lo < 0)
        rc = mm_roots_brent(half_fn, &h, 0, pk->r_found, f_lo, f_p, 1e-15, 200, &pk->r1_found, &fx, &width,
                            NULL, evals, err);
    return rc;
}

static int peak_table(const mm_value *zv, const peak *pk, double wn, mm_result *res)
{
    mm_table *tab = mm_res_table(res, O_PEAKS, zv->cols);
    if (!tab)
        return MM_ENOMEM;
    for (int k = 0; k < zv->cols; k++) {
        double *row = tab->cell + 8 * k;
        const char **txt = tab->text + 8 * k;
        row[0] = zv->data[k];
        row[1] = pk[k].r_p;
        row[2] = pk[k].r_found;
        row[3] = pk[k].r_bound;
        row[4] = pk[k].H_p;
        row[5] = pk[k].H_found;
        row[7] = 2 * zv->data[k] * wn;
        if (!pk[k].has_peak)
            txt[6] = "none: |H| never rises above 1";
        else if (pk[k].has_lower)
            row[6] = wn * pk[k].bw;
        else
            txt[6] = "none: below half power only above the peak";
    }
    return MM_OK;
}

static int curves(const mm_value *zv, const peak *pk, double r_max, int np, mm_result *res)
{
    double *grid = mm_res_alloc(res, (size_t)(np + WINDOW) * sizeof *grid);
    if (!grid)
        return MM_ENOMEM;
    for (int k = 0; k < zv->cols; k++) {
        double z = zv->data[k], c = pk[k].has_peak ? pk[k].r_p : 1;
        int ng = mm_ex_grid_refined(0, r_max, np, c, pk[k].has_peak ? fmin(0.5, 6 * z) : 0, WINDOW, grid);
        mm_ex_round_sig(grid, ng, 6);                 /* short abscissae: the curves are for the eye */
        mm_series *sa = mm_res_series_i(res, O_AMP, k + 1, ng), *sp = mm_res_series_i(res, O_PHASE, k + 1, ng);
        if (!sa || !sp)
            return MM_ENOMEM;
        for (int i = 0; i < ng; i++) {
            sa->x[i] = sp->x[i] = grid[i];
            sa->y[i] = amp(grid[i], z);
            sp->y[i] = phase(grid[i], z);
        }
        mm_ex_round_sig(sa->y, ng, 6);
        mm_ex_round_sig(sp->y, ng, 6);
    }
    return MM_OK;
}

static void peak_checks(double z, const peak *pk, mm_result *res)
{
    char name[200];
    /* the place of a flat maximum is defined only to the width where |H|
     * is flat to rounding (printed as the bound of r_peak_found); what
     * golden section must reach is the height, to rounding: both values
     * round by DELTA, the formula by a few eps */
    snprintf(name, sizeof name, "zeta = %g: peak height found by golden section vs %s", z,
             pk->has_peak ? "1/(2 zeta sqrt(1 - zeta^2)), eq. (3)" : "|H(0)| = 1");
    mm_res_check_rel(res, name, pk->H_found, pk->H_p, 2 * DELTA + 8 * DBL_EPSILON);
    if (!pk->has_peak)
        return;
    /* Brent to a bracket of 4 eps r + 1e-15 on |H| - H_found/sqrt 2: the
     * level is off by at most (DELTA + 4 eps) H_p/sqrt 2, |H| rounds by
     * DELTA H: over the slope of |H| there */
    for (int j = 0; j < 2; j++) {
        double found = j ? pk->r1_found : pk->r2_found, exact = j ? pk->r1 : pk->r2;
        if (j && !pk->has_lower)
            continue;
        snprintf(name, sizeof name, "zeta = %g: %s half-power point by Brent vs eq. (5)", z, j ? "lower" : "upper");
        mm_res_check_abs(res, name, found, exact,
                         4 * DBL_EPSILON * exact + 1e-15 + (2 * DELTA + 4 * DBL_EPSILON) * pk->H_p / slope(exact, z));
    }
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    const mm_value *zv = &in[P_ZETA];
    int nz = zv->cols;
    double wn = in[P_OMEGA_N].x, r_max = in[P_RMAX].x;
    long evals = 0;
    peak pk[MAX_ZETAS];
    for (int k = 0; k < nz; k++) {
        int rc = analyse(zv->data[k], &pk[k], &evals, err);
        if (rc != MM_OK)
            return rc;
    }

    /* ---- the first damping ratio: the numbers of a worked solution ---- */
    double z0 = zv->data[0];
    const peak *p0 = &pk[0];
    mm_res_scalar(res, O_ZETA, z0);
    mm_res_scalar(res, O_Q, 1 / (2 * z0));
    if (p0->has_peak) {
        mm_res_scalar(res, O_PEAK_R, p0->r_p);
        mm_res_scalar(res, O_PEAK_OMEGA, wn * p0->r_p);
        mm_res_scalar(res, O_PEAK_H, p0->H_p);
        if (p0->has_lower)
            mm_res_scalar(res, O_BW, wn * p0->bw);
    } else {
        const char *why = "no resonance peak: zeta >= 1/sqrt(2), |H| is largest at r = 0 and only falls";
        mm_res_scalar_text(res, O_PEAK_R, 0, why);
        mm_res_scalar_text(res, O_PEAK_OMEGA, 0, why);
        mm_res_scalar_text(res, O_PEAK_H, 1, "|H(0)| = 1: the static deflection F0/k");
    }
    mm_res_scalar_err(res, O_PEAK_FOUND, wn * p0->r_found, wn * p0->r_bound, MM_ERR_BOUND);
    mm_res_scalar(res, O_BW_APPROX, 2 * z0 * wn);
    mm_res_scalar(res, O_PHASE_RES, phase(1, z0));

    int rc = peak_table(zv, pk, wn, res);
    if (rc == MM_OK)
        rc = curves(zv, pk, r_max, (int)in[P_POINTS].x, res);
    if (rc != MM_OK)
        return rc;
    for (int k = 0; k < nz; k++)
        peak_checks(zv->data[k], &pk[k], res);

    /* eq. (1) measured in the time domain for the first damping ratio: at
     * the peak (or r = 0.5 when it is below 0.1: 2 periods there are long),
     * and the phase at r = 1; the oscillator m = k = 1, c = 2 zeta, F0 = 1 */
    double r_m = p0->has_peak && p0->r_p >= 0.1 ? p0->r_p : 0.5, rnd = mm_ex_roundoff(4 * M_PI, 1);
    for (int j = 0; j < 2; j++) {
        double r = j ? 1 : r_m, Hm, phm, He, phe;
        mm_sdof s = {.m = 1, .k = 1, .c = 2 * z0, .F0 = 1, .omega = r};
        mm_sdof_props p;
        mm_sdof_props_get(&s, &p);
        rc = mm_ex_sdof_steady_measure(&s, &p, 2, phase(r, z0), &Hm, &phm, &He, &phe, res, err);
        if (rc != MM_OK)
            return rc;
        if (j == 0)
            mm_res_check_abs(res, "|H| measured by time integration vs eq. (1), first zeta, within 10 times "
                                  "DOP853's error estimated at rtol/10", Hm, amp(r, z0), 10 * He + rnd * Hm);
        mm_res_check_abs(res, j ? "phase at r = 1 measured by time integration vs pi/2, eq. (4), within 10 times "
                                  "DOP853's error estimated at rtol/10"
                                : "phase measured by time integration vs eq. (2), first zeta, within 10 times "
                                  "DOP853's error estimated at rtol/10",
                         phm, phase(r, z0), 10 * phe + rnd);
    }

    mm_res_method(res, "closed forms; golden-section search (peaks, mm_opt), Brent's method (half-power "
                       "points), dop853 (time-domain measurement) beside them", 0);
    mm_res_method_stat(res, "evaluations", (double)evals);   /* of |H|: golden section and Brent */
    return MM_OK;
}

static const char *const references[] = {
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, sections 3.4-3.5",
    "W. H. Press et al., Numerical Recipes, 3rd ed., Cambridge 2007, section 10.2 (golden section)",
    "R. P. Brent, Algorithms for Minimization without Derivatives, Prentice-Hall 1973, ch. 4",
    NULL,
};

const mm_exercise mm_ex_vib_frequency_response = {
    .id = "vib-frequency-response", .chapter = 5, .section = "5.9.2",
    .title = "Frequency response: amplitude and phase",
    .summary = "Magnification and phase lag against the forcing frequency for several damping ratios; peak and bandwidth.",
    .tags = "vibration, 1 DOF, frequency response, resonance peak, bandwidth, phase",
    .theory = "exercises/vib/frequency_response.md", .params = params, .n_params = MM_COUNT(params), .outputs = outputs,
    .n_outputs = MM_COUNT(outputs), .references = references, .solve = solve,
};
