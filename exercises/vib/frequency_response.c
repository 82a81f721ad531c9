/* frequency_response.c — vib-frequency-response: the amplitude and phase of
 * a damped oscillator's steady response against the forcing frequency, for
 * several damping ratios.
 *
 *     x'' + 2 zeta omega_n x' + omega_n^2 x = omega_n^2 (F0/k) cos(omega t)
 *     X / (F0/k) = |H(r)| = 1 / |1 - r^2 + 2 i zeta r|,  r = omega/omega_n   (1)
 *
 * Goal: read a frequency response: where the peak is (r = sqrt(1 - 2
 * zeta^2), not r = 1), how high (1 / (2 zeta sqrt(1 - zeta^2))), how wide
 * (the half-power bandwidth, about 2 zeta omega_n), and how the phase swings
 * through pi/2 at r = 1.  The peak is found numerically by golden-section
 * search on |H|, the half-power points by Brent's method, and both are
 * checked against the formulas; the formula (1) itself is checked by a time
 * integration (DOP853) started on the steady orbit, measured at the peak
 * and at r = 1.
 * Reference: S. S. Rao, Mechanical Vibrations, 6th ed., sections 3.4-3.5;
 * golden section: W. H. Press et al., Numerical Recipes, 3rd ed., 10.2.
 */
#include <math.h>
#include <stdio.h>

#include "mm_exhelp.h"
#include "mm_ode.h"
#include "mm_roots.h"

enum { P_ZETA, P_OMEGA_N, P_RMAX, P_POINTS };

#define MAX_ZETAS 8

static const mm_param params[] = {
    [P_ZETA] = {"zeta", "damping ratios", "", MM_VECTOR, 0, 1e-3, 5, .def_text = "0.05,0.1,0.2,0.5,1",
                .max_cols = MAX_ZETAS,
                .help = "one curve per damping ratio c/(2 sqrt(k m)); the first one's peak is reported as scalars"},
    [P_OMEGA_N] = {"omega_n", "natural frequency", "rad/s", MM_REAL, 10, 1e-3, 1e4,
                   .help = "sqrt(k/m): converts the frequency ratio r to omega = r omega_n"},
    [P_RMAX] = {"r_max", "largest frequency ratio", "", MM_REAL, 3, 1.5, 20,
                .help = "the plots run over omega/omega_n from 0 to r_max"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 501, 51, 4001,
                  .help = "equally spaced samples of each curve (100 more are added around each peak)"},
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

/* |d|H|/dr| = |dD/dr| / (2 D^(3/2)), D = (1 - r^2)^2 + (2 zeta r)^2. */
static double slope(double r, double z)
{
    double D = (1 - r * r) * (1 - r * r) + 4 * z * z * r * r;
    return fabs(-4 * r * (1 - r * r) + 8 * z * z * r) / (2 * D * sqrt(D)) + 1e-300;
}

/* Golden-section search for the maximum of |H| on [a, b] (unimodal there):
 * the bracket shrinks by 0.618 per evaluation until it is below tol. */
static double golden_max(double z, double a, double b, double tol, int *evals)
{
    const double g = 0.5 * (sqrt(5.0) - 1);
    double c = b - g * (b - a), d = a + g * (b - a);
    double fc = amp(c, z), fd = amp(d, z);
    *evals += 2;
    while (b - a > tol) {
        if (fc >= fd) {             /* the maximum is in [a, d] */
            b = d;
            d = c;
            fd = fc;
            c = b - g * (b - a);
            fc = amp(c, z);
        } else {                    /* in [c, b] */
            a = c;
            c = d;
            fc = fd;
            d = a + g * (b - a);
            fd = amp(d, z);
        }
        ++*evals;
    }
    return fc >= fd ? c : d;
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
    int has_peak;          /* zeta < 1/sqrt(2) */
    double r_p, H_p;       /* eq. (3) */
    double r_found, H_found;
    int has_lower;         /* the lower half-power point exists */
    double r1, r2;         /* half-power points, eq. (5) */
    double r1_found, r2_found;
} peak;

static int analyse(double z, peak *pk, long *evals, mm_error *err)
{
    *pk = (peak){0};
    if (!(2 * z * z < 1))
        return MM_OK;
    pk->has_peak = 1;
    pk->r_p = sqrt(1 - 2 * z * z);
    pk->H_p = 1 / (2 * z * sqrt(1 - z * z));
    int ge = 0;
    pk->r_found = golden_max(z, 0, 1.5, 1e-12, &ge);
    pk->H_found = amp(pk->r_found, z);
    *evals += ge;

    /* eq. (5): r^2 = 1 - 2 zeta^2 -+ 2 zeta sqrt(1 - zeta^2) */
    double s = 2 * z * sqrt(1 - z * z), u1 = 1 - 2 * z * z - s;
    pk->r2 = sqrt(1 - 2 * z * z + s);
    pk->has_lower = u1 > 0;
    pk->r1 = pk->has_lower ? sqrt(u1) : 0;

    half_ctx h = {.z = z, .level = pk->H_found / M_SQRT2};   /* half power of the peak found */
    double f_lo, f_p, f_hi, fx, width;
    half_fn(pk->r_found, &f_p, &h);
    half_fn(2, &f_hi, &h);             /* |H(2)| <= 1/3 < 1/sqrt(2) <= H_p/sqrt(2) */
    int rc = mm_roots_brent(half_fn, &h, pk->r_found, 2, f_p, f_hi, 1e-15, 200, &pk->r2_found, &fx, &width,
                            NULL, evals, err);
    if (rc != MM_OK)
        return rc;
    half_fn(0, &f_lo, &h);
    if (f_lo < 0) {
        rc = mm_roots_brent(half_fn, &h, 0, pk->r_found, f_lo, f_p, 1e-15, 200, &pk->r1_found, &fx, &width,
                            NULL, evals, err);
        if (rc != MM_OK)
            return rc;
    }
    return MM_OK;
}

/* x'' + 2 z x' + x = cos(r t) as y = (x, v) (omega_n = 1, F0/k = 1). */
typedef struct osc {
    double z, r;
} osc;

static int osc_rhs(double t, const double *y, double *dy, void *ctx)
{
    const osc *o = ctx;
    dy[0] = y[1];
    dy[1] = cos(o->r * t) - 2 * o->z * y[1] - y[0];
    return 0;
}

/* Amplitude ratio and phase measured by integrating eq. (1) (DOP853 at
 * rtol 1e-10) from the steady orbit for four periods and projecting on cos
 * and sin; exact for a pure harmonic sampled evenly over whole periods. */
static int measure(double r, double z, double *H, double *ph, long *evals, mm_result *res, mm_error *err)
{
    enum { PER = 64, N = 4 * PER };
    (void)res;
    osc o = {.z = z, .r = r};
    double X = amp(r, z), lag = phase(r, z);
    double y0[2] = {X * cos(lag), X * r * sin(lag)};
    double T = 2 * M_PI / r, t[N + 1], y[2 * (N + 1)];
    mm_linspace(0, 4 * T, N + 1, t);
    mm_ode_problem prob = {.n = 2, .f = osc_rhs, .params = &o, .t0 = 0, .t_end = 4 * T, .y0 = y0};
    mm_ode_options opt;
    mm_ode_options_init(&opt);
    opt.method = MM_ODE_DOP853;
    opt.rtol = 1e-10;
    opt.atol = 1e-10 * X;
    mm_ode_result rr = {0};
    rr.t_out = t;
    rr.nout = N + 1;
    rr.y_out = y;
    mm_ode_work *w = mm_ode_work_alloc(2);
    int rc = w ? mm_ode_solve(&prob, &opt, w, &rr, err) : mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_ode_work_free(w);
    *evals += rr.n_eval;
    if (rc != MM_OK)
        return rc;
    double a = 0, b = 0;
    for (int i = 0; i < N; i++) {
        a += y[2 * i] * cos(2 * M_PI * i / PER);
        b += y[2 * i] * sin(2 * M_PI * i / PER);
    }
    *H = hypot(a, b) * 2.0 / N;
    *ph = atan2(b, a);
    if (*ph < -M_PI / 2)       /* a lag near pi may come out as -pi + eps */
        *ph += 2 * M_PI;
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    const mm_value *zv = &in[P_ZETA];
    int nz = zv->cols;
    double wn = in[P_OMEGA_N].x, r_max = in[P_RMAX].x;
    int np = (int)in[P_POINTS].x;
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
    mm_res_scalar_v1(res, "zeta", "damping ratio of the first curve", "", z0);
    mm_res_scalar_v1(res, "Q", "quality factor 1/(2 zeta)", "", 1 / (2 * z0));
    if (p0->has_peak) {
        mm_res_scalar_v1(res, "peak_r", "peak frequency ratio sqrt(1 - 2 zeta^2)", "", p0->r_p);
        mm_res_scalar_v1(res, "peak_omega", "peak frequency omega_n sqrt(1 - 2 zeta^2)", "rad/s", wn * p0->r_p);
        mm_res_scalar_v1(res, "peak_height", "peak magnification 1/(2 zeta sqrt(1 - zeta^2))", "", p0->H_p);
        mm_res_scalar_v1(res, "peak_omega_found", "peak frequency found by golden-section search", "rad/s",
                      wn * p0->r_found);
        if (p0->has_lower) {
            mm_res_scalar_v1(res, "bandwidth", "half-power bandwidth (exact, eq. 5)", "rad/s",
                          wn * (p0->r2 - p0->r1));
            mm_res_scalar_v1(res, "bandwidth_approx", "half-power bandwidth, approximation 2 zeta omega_n", "rad/s",
                          2 * z0 * wn);
        }
    } else {
        mm_res_scalar_text_v1(res, "peak_r", "peak frequency ratio", "", 0,
                           "no resonance peak: zeta >= 1/sqrt(2), |H| falls from r = 0");
    }
    mm_res_scalar_v1(res, "phase_at_resonance", "phase lag at omega = omega_n", "rad", phase(1, z0));

    /* ---- the table of peaks ---- */
    static const char *const cols[] = {"zeta", "r_peak", "r_peak_found", "H_peak", "H_peak_found",
                                       "bandwidth", "bandwidth_approx"};
    static const char *const units[] = {"", "", "", "", "", "rad/s", "rad/s"};
    mm_table *tab = mm_res_table_v1(res, "peaks", nz, 7, cols, units);
    if (!tab)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (int k = 0; k < nz; k++) {
        double *row = tab->cell + 7 * k;
        const char **txt = tab->text + 7 * k;
        row[0] = zv->data[k];
        row[6] = 2 * zv->data[k] * wn;
        if (pk[k].has_peak) {
            row[1] = pk[k].r_p;
            row[2] = pk[k].r_found;
            row[3] = pk[k].H_p;
            row[4] = pk[k].H_found;
            if (pk[k].has_lower)
                row[5] = wn * (pk[k].r2 - pk[k].r1);
            else
                txt[5] = "none: below half power only above the peak";
        } else {
            for (int j = 1; j <= 5; j++)
                txt[j] = "none";
        }
    }

    /* ---- the curves ---- */
    for (int k = 0; k < nz; k++) {
        double z = zv->data[k], c = pk[k].has_peak ? pk[k].r_p : 1;
        double *grid = mm_res_alloc(res, (size_t)(np + 100) * sizeof *grid);
        if (!grid)
            return mm_error_set(err, MM_ENOMEM, "", "out of memory");
        int ng = mm_ex_grid_refined(0, r_max, np, c, pk[k].has_peak ? fmin(0.5, 6 * z) : 0, 100, grid);
        char name[32], label[64];
        snprintf(name, sizeof name, "amplitude_%d", k + 1);
        snprintf(label, sizeof label, "|H| = X/(F0/k), zeta = %g", z);
        mm_series *sa = mm_res_series_v1(res, mm_res_strdup(res, name), mm_res_strdup(res, label), "",
                                      "omega/omega_n", "", ng);
        snprintf(name, sizeof name, "phase_%d", k + 1);
        snprintf(label, sizeof label, "phase lag, zeta = %g", z);
        mm_series *sp = mm_res_series_v1(res, mm_res_strdup(res, name), mm_res_strdup(res, label), "rad",
                                      "omega/omega_n", "", ng);
        if (!sa || !sp)
            return mm_error_set(err, MM_ENOMEM, "", "out of memory");
        for (int i = 0; i < ng; i++) {
            sa->x[i] = sp->x[i] = grid[i];
            sa->y[i] = amp(grid[i], z);
            sp->y[i] = phase(grid[i], z);
        }
    }

    /* ---- checks ---- */
    for (int k = 0; k < nz; k++) {
        if (!pk[k].has_peak)
            continue;
        double z = zv->data[k];
        /* A maximum is located only to about sqrt(eps) of its width: |H|
         * changes by a relative (2 r_p d)^2 / (2 D_p) at a distance d, with
         * D_p = 4 zeta^2 (1 - zeta^2); below eps that is invisible. */
        double Dp = 4 * z * z * (1 - z * z);
        double tol_r = 1e-7 * sqrt(Dp) / pk[k].r_p + 1e-11;
        char name[160];
        snprintf(name, sizeof name, "zeta = %g: peak found by golden section vs sqrt(1 - 2 zeta^2), eq. (3)", z);
        mm_res_check_abs(res, mm_res_strdup(res, name), pk[k].r_found, pk[k].r_p, tol_r);
        snprintf(name, sizeof name, "zeta = %g: peak height found vs 1/(2 zeta sqrt(1 - zeta^2)), eq. (3)", z);
        mm_res_check_rel(res, mm_res_strdup(res, name), pk[k].H_found, pk[k].H_p, 1e-12);
        /* the half-power points: Brent to 1e-15 on |H| - H_p/sqrt(2), which is
         * computed to a few eps of H_p: a root is located to about
         * eps H_p / |d|H|/dr| (large where |H| is flat, near r = 0) */
        snprintf(name, sizeof name, "zeta = %g: upper half-power point by Brent vs eq. (5)", z);
        mm_res_check_abs(res, mm_res_strdup(res, name), pk[k].r2_found, pk[k].r2,
                         1e-11 + 1e-14 * pk[k].H_p / slope(pk[k].r2, z));
        if (pk[k].has_lower) {
            snprintf(name, sizeof name, "zeta = %g: lower half-power point by Brent vs eq. (5)", z);
            mm_res_check_abs(res, mm_res_strdup(res, name), pk[k].r1_found, pk[k].r1,
                             1e-11 + 1e-14 * pk[k].H_p / slope(pk[k].r1, z));
        }
    }

    /* eq. (1) measured in the time domain for the first damping ratio: at
     * the peak (or r = 0.5 without one) and at r = 1 */
    double r_m = p0->has_peak ? p0->r_p : 0.5, Hm, phm;
    long dop_evals = 0;
    int rc = measure(r_m, z0, &Hm, &phm, &dop_evals, res, err);
    if (rc != MM_OK)
        return rc;
    /* DOP853 at rtol 1e-10 over 4 periods: about 1e-10 relative */
    mm_res_check_rel(res, "|H| measured by time integration vs eq. (1), first zeta", Hm, amp(r_m, z0), 1e-6);
    mm_res_check_abs(res, "phase measured by time integration vs eq. (2), first zeta", phm, phase(r_m, z0), 1e-6);
    rc = measure(1, z0, &Hm, &phm, &dop_evals, res, err);
    if (rc != MM_OK)
        return rc;
    mm_res_check_abs(res, "phase at r = 1 measured by time integration vs pi/2", phm, M_PI / 2, 1e-6);

    mm_res_method(res, "golden-section search (peaks), Brent's method (half-power points), "
                       "dop853 (time-domain measurement)", 0);
    mm_res_method_stat(res, "evaluations", (double)evals);   /* of |H|: golden section and Brent */
    mm_res_method_stat(res, "dop853_evaluations", (double)dop_evals);
    return MM_OK;
}

static const char *const references[] = {
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, sections 3.4-3.5",
    "W. H. Press et al., Numerical Recipes, 3rd ed., Cambridge 2007, section 10.2 (golden section)",
    "R. P. Brent, Algorithms for Minimization without Derivatives, Prentice-Hall 1973, ch. 4",
    NULL,
};

const mm_exercise mm_ex_vib_frequency_response = {
    .id = "vib-frequency-response",
    .chapter = 5,
    .section = "5.9.2",
    .title = "Frequency response: amplitude and phase",
    .summary = "Magnification and phase lag against the forcing frequency for several damping ratios; peak and bandwidth.",
    .tags = "vibration, 1 DOF, frequency response, resonance peak, bandwidth, phase",
    .theory = "exercises/vib/frequency_response.md",
    .params = params,
    .n_params = MM_COUNT(params),
    .references = references,
    .check = NULL,
    .solve = solve,
};
