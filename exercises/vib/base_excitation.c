/* base_excitation.c — vib-base-excitation: a mass on a spring and damper
 * whose other ends are attached to a support that moves, y = Y cos(omega t).
 *
 *     m x'' + c x' + k x = k y + c y' = k Y cos(wt) - c Y w sin(wt)      (2)
 *
 * Goal: the transmissibility X/Y (how much of the support's motion reaches
 * the mass), why it is 1 at omega = sqrt(2) omega_n whatever the damping,
 * and why isolation (X < Y) needs omega > sqrt(2) omega_n, where damping
 * makes it worse.  Eq. (2) is a 1-DOF oscillator driven by a cosine and a
 * sine force, so the plotted response is its closed form (mm_sdof); DOP853
 * integrates eq. (2) beside it.  The steady amplitude and phase are
 * measured from an integration started on the steady orbit.
 * Reference: S. S. Rao, Mechanical Vibrations, 6th ed., section 3.6.
 */
#include <float.h>
#include <math.h>

#include "mm_exhelp.h"
#include "mm_roots.h"
#include "mm_vib.h"

enum { P_M, P_K, P_C, P_Y, P_OMEGA, P_X0, P_V0, P_TEND, P_POINTS };

static const mm_param params[] = {
    [P_M] = {"m", "mass", "kg", MM_REAL, 1, 1e-3, 1e3,
             .help = "the moving mass, 1 g to 1 t (a lab model to a machine)"},
    [P_K] = {"k", "stiffness", "N/m", MM_REAL, 100, 1e-2, 1e6,
             .help = "spring between support and mass; with m it sets omega_n between 3e-3 and 3e4 rad/s"},
    [P_C] = {"c", "damping coefficient", "N s/m", MM_REAL, 2, 0, 1e4,
             .help = "damper between support and mass; c = 2 sqrt(k m) is critical damping"},
    [P_Y] = {"Y", "support amplitude", "m", MM_REAL, 0.01, 0, 1,
             .help = "the support moves as Y cos(omega t); up to 1 m, a shaking table's stroke"},
    [P_OMEGA] = {"omega", "support frequency", "rad/s", MM_REAL, 8, 1e-3, 1e4,
                 .help = "angular frequency of the support's motion, the range of omega_n"},
    [P_X0] = {"x0", "initial displacement", "m", MM_REAL, 0, -10, 10,
              .help = "absolute position of the mass at t = 0 (the support is then at Y); within 10 m"},
    [P_V0] = {"v0", "initial velocity", "m/s", MM_REAL, 0, -1e3, 1e3, .help = "dx/dt at t = 0"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 10, 1e-3, 1e4,
                .help = "simulated time; at most 2e4 radians of the fastest motion (3,200 periods), "
                        "what one request integrates in 250 ms"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 401, 11, 4001,
                  .help = "samples of the time response returned for the plot (a plot shows no more)"},
};

enum { O_OMEGA_N, O_ZETA, O_R, O_T, O_X, O_PHASE, O_Z, O_FT, O_ISOLATES, O_RCROSS, O_XT, O_YT, O_ERR, O_TCURVE,
       O_TREF1, O_TREF5, O_ANIM };

static const mm_output outputs[] = {
    [O_OMEGA_N] = MM_SCALAR("omega_n", "natural frequency", "rad/s", .flags = MM_EXACT),
    [O_ZETA] = MM_SCALAR("zeta", "damping ratio", "", .flags = MM_EXACT),
    [O_R] = MM_SCALAR("r", "frequency ratio omega/omega_n", "", .flags = MM_EXACT),
    [O_T] = MM_SCALAR("transmissibility", "transmissibility X/Y, eq. (3)", "", .flags = MM_ANSWER | MM_EXACT),
    [O_X] = MM_SCALAR("X", "steady amplitude of the mass", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_PHASE] = MM_SCALAR("phase", "lag of the mass behind the support, eq. (4)", "rad", .flags = MM_ANSWER | MM_EXACT),
    [O_Z] = MM_SCALAR("Z", "steady amplitude of the spring's stretch x - y", "m", .flags = MM_EXACT),
    [O_FT] = MM_SCALAR("force_transmitted", "amplitude of the force on the support, eq. (5)", "N",
                       .flags = MM_ANSWER | MM_EXACT),
    [O_ISOLATES] = MM_SCALAR("isolates", "isolation (X < Y)", "", .flags = MM_EXACT),
    [O_RCROSS] = MM_SCALAR("r_crossing", "frequency ratio where T = 1, found by Brent's method", ""),
    [O_XT] = MM_SERIES("x", "mass displacement (closed form)", "m", "t", "s", .figure = "response"),
    [O_YT] = MM_SERIES("y", "support displacement", "m", "t", "s", .figure = "response", .role = "reference"),
    [O_ERR] = MM_SERIES("error_dop853", "x by DOP853 minus the closed form", "m", "t", "s", .figure = "error"),
    [O_TCURVE] = MM_SERIES("T", "transmissibility X/Y of this system", "", "omega/omega_n", "",
                           .figure = "transmissibility"),
    [O_TREF1] = MM_SERIES("T_zeta_0_1", "transmissibility, zeta = 0.1", "", "omega/omega_n", "",
                          .figure = "transmissibility", .role = "reference"),
    [O_TREF5] = MM_SERIES("T_zeta_0_5", "transmissibility, zeta = 0.5", "", "omega/omega_n", "",
                          .figure = "transmissibility", .role = "reference"),
    [O_ANIM] = MM_ANIMATION("the mass on its spring and damper over the moving support"),
};

/* Eq. (2): the oscillator driven by F0 = k Y (cosine) and G0 = -c omega Y (sine). */
static mm_sdof model(const mm_value *in)
{
    double k = in[P_K].x, c = in[P_C].x, Y = in[P_Y].x, w = in[P_OMEGA].x;
    return (mm_sdof){.m = in[P_M].x, .c = c, .k = k, .F0 = k * Y, .G0 = -c * w * Y, .omega = w,
                     .x0 = in[P_X0].x, .v0 = in[P_V0].x};
}

/* Transmissibility of eq. (3) at frequency ratio r and damping ratio z. */
static double transmissibility(double r, double z)
{
    double a = 1 - r * r, b = 2 * z * r;
    return sqrt((1 + b * b) / (a * a + b * b));
}

static int check(const mm_value *in, mm_error *err)
{
    mm_sdof s = model(in);
    return mm_vib_sdof_check(&s, in[P_TEND].x, in[P_Y].x != 0, "motion", err);   /* no steady state at resonance */
}

static int t_minus_one(double r, double *f, void *ctx)
{
    *f = transmissibility(r, *(const double *)ctx) - 1;
    return 0;
}

/* T = 1 at r = sqrt(2) for every damping, eq. (6): the crossing found by
 * Brent's method on T(r) - 1 over [1.01, 3], beside sqrt 2. */
static int crossing(double z, mm_result *res, mm_error *err)
{
    double lo = 1.01, hi = 3, flo, fhi, rx, fx, width;
    t_minus_one(lo, &flo, &z);
    t_minus_one(hi, &fhi, &z);
    if (!(flo > 0 && fhi < 0))
        return MM_OK;
    int rc = mm_roots_brent(t_minus_one, &z, lo, hi, flo, fhi, 1e-14, 200, &rx, &fx, &width, NULL, NULL, err);
    if (rc != MM_OK)
        return rc;
    /* Brent's bracket (1e-14) plus T - 1's rounding (4 eps (1 + 8 z^2))
     * over its slope dT/dr = 2 sqrt 2 / (1 + 8 z^2) at sqrt 2: where the
     * rounding noise hides the crossing, any root finder lands somewhere in
     * that band, so the bound is the printed error */
    double tol = 2 * (2 * DBL_EPSILON * M_SQRT2 + 0.5e-14) + 4 * DBL_EPSILON * (1 + 8 * z * z) * (1 + 8 * z * z) / (2 * M_SQRT2);
    mm_res_scalar_err(res, O_RCROSS, rx, fmax(tol, fabs(rx - M_SQRT2)), MM_ERR_BOUND);
    return mm_res_check_abs(res, "T = 1 crossing found by Brent vs sqrt(2), eq. (6)", rx, M_SQRT2, tol);
}

static int curves(double r, double zeta, mm_result *res)
{
    enum { NT = 120, NWIN = 40 };
    double r_max = fmax(3, 1.5 * r), *grid = mm_res_alloc(res, (NT + NWIN) * sizeof *grid);
    if (!grid)
        return MM_ENOMEM;
    int ng = mm_ex_grid_refined(0, r_max, NT, 1, fmin(0.5, 6 * zeta), NWIN, grid), nf = 0;
    for (int i = 0; i < ng; i++)                 /* undamped: r = 1 itself has no value */
        if (isfinite(transmissibility(grid[i], zeta)))
            grid[nf++] = grid[i];
    mm_series *st = mm_res_series(res, O_TCURVE, nf);
    if (!st)
        return MM_ENOMEM;
    for (int i = 0; i < nf; i++) {
        st->x[i] = grid[i];
        st->y[i] = transmissibility(grid[i], zeta);
    }
    mm_ex_round_sig(st->y, nf, 6);                            /* a plot needs no more digits */
    static const double zref[2] = {0.1, 0.5};
    for (int k = 0; k < 2; k++) {
        mm_series *sr = mm_res_series(res, k ? O_TREF5 : O_TREF1, NT);
        if (!sr)
            return MM_ENOMEM;
        mm_linspace(0, r_max, NT, sr->x);
        for (int i = 0; i < NT; i++)
            sr->y[i] = transmissibility(sr->x[i], zref[k]);
        mm_ex_round_sig(sr->y, NT, 6);
    }
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    mm_sdof s = model(in);
    mm_sdof_props p;
    mm_sdof_props_get(&s, &p);
    double t_end = in[P_TEND].x, Y = in[P_Y].x, w = s.omega, cw = s.c * w;
    int n = (int)in[P_POINTS].x;

    /* eqs. (3)-(5) from the dynamic stiffness D = k - m w^2 + i c w (its real
     * part without cancellation, mm_sdof): T = |k + i c w| / |D|, the lag
     * arg(D) - arg(k + i c w) = arg(D (k - i c w)) = atan2(c m w^3, k Re D + (c w)^2),
     * no difference of two small angles at small omega */
    double modD = hypot(p.stiffness_re, cw), T = hypot(s.k, cw) / modD;
    double phase = atan2(s.c * s.m * w * w * w, s.k * p.stiffness_re + cw * cw);
    mm_res_scalar(res, O_OMEGA_N, p.omega_n);
    mm_res_scalar(res, O_ZETA, p.zeta);
    mm_res_scalar(res, O_R, w / p.omega_n);
    mm_res_scalar(res, O_T, T);
    mm_res_scalar(res, O_X, T * Y);
    mm_res_scalar(res, O_PHASE, phase);
    mm_res_scalar(res, O_Z, Y * s.m * w * w / modD);          /* |x - y| = Y m w^2 / |D| */
    mm_res_scalar(res, O_FT, s.m * w * w * T * Y);
    mm_res_scalar_text(res, O_ISOLATES, T < 1, T < 1 ? "yes" : "no");

    /* ---- the response from the initial state ---- */
    mm_series *sx = mm_res_series(res, O_XT, n), *sy = mm_res_series(res, O_YT, n);
    int rc = sy ? mm_ex_sdof_plot(&s, &p, t_end, sx, mm_res_series(res, O_ERR, n), res, err) : MM_ENOMEM;
    if (rc != MM_OK)
        return rc;
    for (int i = 0; i < n; i++) {
        sy->x[i] = sx->x[i];
        sy->y[i] = Y * cos(w * sx->x[i]);
    }
    mm_ex_round_sig(sy->y, n, 4);                             /* the support: a reference to look at */

    /* ---- the steady state measured on its orbit ---- */
    if (Y > 0 && (rc = mm_vib_steady_check(res, &s, &p, T, Y, phase, "T Y, eq. (3)", err)) != MM_OK)
        return rc;

    if ((rc = curves(w / p.omega_n, p.zeta, res)) != MM_OK || (rc = crossing(p.zeta, res, err)) != MM_OK)
        return rc;
    mm_ex_warn_aliasing(res, n, t_end, fmax(p.omega_n, w), "shorten t_end or raise points");

    /* the support moving and the mass following, frames from the closed form (35 points, four curves beside) */
    return mm_vib_sdof_animate(res, &s, &p, t_end, 2 * M_PI / fmax(p.omega_n, w), 42, 0, &Y, 1);
}

static const char *const references[] = {
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, section 3.6 (base excitation)",
    "E. Hairer, S. P. Norsett, G. Wanner, Solving Ordinary Differential Equations I, Springer 1993 (DOP853)",
    NULL,
};

const mm_exercise mm_ex_vib_base_excitation = {
    .id = "vib-base-excitation", .chapter = 5, .section = "5.9.5",
    .title = "Vibration of a moving support (base excitation)",
    .summary = "A mass on a spring and damper whose support moves as Y cos(omega t): transmissibility and isolation.",
    .tags = "vibration, 1 DOF, base excitation, transmissibility, isolation",
    .theory = "exercises/vib/base_excitation.md", .params = params, .n_params = MM_COUNT(params), .outputs = outputs,
    .n_outputs = MM_COUNT(outputs), .references = references, .check = check, .solve = solve,
};
