/* dispersion.c — vib-dispersion: a wave packet in a bar (no dispersion)
 * and in a beam (flexural waves, dispersive): phase velocity, group
 * velocity, and the packet spreading.
 *
 *     bar:  omega = c k,  c = sqrt(E / rho);
 *     beam: omega = a k^2,  a = sqrt(E I / (rho A)) = h sqrt(E / (12 rho))      (1)-(2)
 *
 * Goal: see the crests of a packet move at the phase velocity omega/k while
 * the packet itself — its envelope, where the energy is — moves at the
 * group velocity d omega/dk (eqs. 3-4 of the theory): equal in the bar,
 * twice the phase velocity in the beam, where the packet also spreads
 * (eq. 7) because its short waves outrun its long ones.
 * Method: the initial packet (eq. 5) is sampled on a periodic domain, its
 * Fourier coefficients taken by the FFT, and every mode advanced exactly in
 * time by its own phase exp(-i omega(k) t) and summed again (eq. 6).  No
 * time stepping: the only errors are sampling and rounding.
 * The answers are the closed forms (eqs. 1-4, 7, 8: speeds, travel,
 * widths); what is measured on the superposed modes (the centroid's speed
 * and travel, the r.m.s. widths) is shown beside them with its error.
 * Checks: the packet at time t against the closed forms (the translated
 * packet for the bar; the Gaussian chirp of eq. 7 for the beam); the
 * measured centroid speed and width against eqs. (4) and (8).
 * Reference: K. F. Graff, Wave Motion in Elastic Solids, Dover 1991,
 * sections 1.3 and 3.1; G. B. Whitham, Linear and Nonlinear Waves, Wiley
 * 1974, ch. 11.
 */
#include <complex.h>
#include <float.h>
#include <math.h>

#include "mm_exhelp.h"
#include "mm_fourier.h"
#include "mm_quad.h"

enum { P_MEDIUM, P_E, P_RHO, P_H, P_LAMBDA, P_CYCLES, P_AMP, P_T };
enum { M_BEAM, M_BAR };

static const char *const media[] = {"beam", "bar", NULL};

#define MARGIN 9.0             /* envelope widths kept either side: exp(-81/2) */
#define MAX_WAVES 250          /* domain length in carrier wavelengths */
#define SUM_RESTART 64         /* the mode sum's rotation restarts exactly this often */

static const mm_param params[] = {
    [P_MEDIUM] = {"medium", "medium", "", MM_CHOICE, M_BEAM, 0, 0, .choices = media,
                  .help = "beam: bending waves, omega = a k^2 (dispersive); bar: longitudinal waves, omega = c k"},
    [P_E] = {"E", "Young's modulus", "Pa", MM_REAL, 2.1e11, 1e6, 1e12,
             .help = "steel 2.1e11, aluminium 7e10; 1 MPa (foam) to 1 TPa (diamond)"},
    [P_RHO] = {"rho", "density", "kg/m^3", MM_REAL, 7850, 10, 3e4,
               .help = "steel 7850, aluminium 2700; 10 (foam) to 3e4 (beyond osmium)"},
    [P_H] = {"h", "beam thickness", "m", MM_REAL, 0.01, 1e-4, 1,
             .help = "depth of the rectangular section, I/A = h^2/12 (beam only); 0.1 mm to 1 m"},
    [P_LAMBDA] = {"wavelength", "carrier wavelength", "m", MM_REAL, 0.2, 1e-3, 100,
                  .help = "wavelength 2 pi/k0 of the waves inside the packet, 1 mm to 100 m"},
    [P_CYCLES] = {"cycles", "packet width in wavelengths", "", MM_REAL, 1.5, 1.3, 6,
                  .help = "sigma, the Gaussian envelope's half-width, in carrier wavelengths: from 1.3 (below, "
                          "the packet's spectrum reaches k = 0 and it is no longer one carrier) to 6"},
    [P_AMP] = {"A", "amplitude", "m", MM_REAL, 1e-3, 1e-9, 1,
               .help = "largest displacement at t = 0 (the theory is linear: it only scales)"},
    [P_T] = {"t", "time", "s", MM_REAL, 3e-3, 1e-7, 10,
             .help = "when the packet is shown the second time; the domain must stay under 250 wavelengths "
                     "(what a plot can show)"},
};

enum { O_K0, O_OMEGA0, O_F0, O_CP, O_CG, O_RATIO, O_SPEED, O_TRAVEL, O_SLIP, O_WIDTH0, O_WIDTH, O_SPREAD,
       O_SPEED_M, O_TRAVEL_M, O_WIDTH0_M, O_WIDTH_M, O_SPREAD_M, O_U0, O_U, O_ENV0, O_ENV, O_VP, O_VG };

static const mm_output outputs[] = {
    [O_K0] = MM_SCALAR("k0", "carrier wavenumber 2 pi / wavelength", "rad/m", .flags = MM_EXACT),
    [O_OMEGA0] = MM_SCALAR("omega0", "carrier angular frequency omega(k0)", "rad/s", .flags = MM_EXACT),
    [O_F0] = MM_SCALAR("f0", "carrier frequency", "Hz", .flags = MM_ANSWER | MM_EXACT),
    [O_CP] = MM_SCALAR("phase_velocity", "phase velocity omega/k at k0, eq. (3)", "m/s", .flags = MM_ANSWER | MM_EXACT),
    [O_CG] = MM_SCALAR("group_velocity", "group velocity d omega/dk at k0, eq. (4)", "m/s",
                       .flags = MM_ANSWER | MM_EXACT),
    [O_RATIO] = MM_SCALAR("ratio", "group / phase velocity", "", .flags = MM_ANSWER | MM_EXACT),
    [O_SPEED] = MM_SCALAR("centre_speed", "speed of the envelope's centroid: the group velocity, eq. (7)", "m/s",
                          .flags = MM_EXACT),
    [O_TRAVEL] = MM_SCALAR("travel", "distance the packet travelled, c_g t", "m", .flags = MM_EXACT),
    [O_SLIP] = MM_SCALAR("crest_slip", "wavelengths the crests slip through the envelope, (c_g - c_p) t / wavelength",
                         "", .flags = MM_EXACT),
    [O_WIDTH0] = MM_SCALAR("width0", "r.m.s. width of the envelope at t = 0, sigma/sqrt 2", "m", .flags = MM_EXACT),
    [O_WIDTH] = MM_SCALAR("width", "r.m.s. width of the envelope at t, sigma_t/sqrt 2, eq. (8)", "m",
                          .flags = MM_ANSWER | MM_EXACT),
    [O_SPREAD] = MM_SCALAR("spread", "width at t / width at 0, sigma_t/sigma", "", .flags = MM_ANSWER | MM_EXACT),
    [O_SPEED_M] = MM_SCALAR("centre_speed_measured", "speed of the centroid of |psi|^2, measured on the modes", "m/s"),
    [O_TRAVEL_M] = MM_SCALAR("travel_measured", "distance the centroid travelled, measured", "m"),
    [O_WIDTH0_M] = MM_SCALAR("width0_measured", "r.m.s. width at t = 0, measured", "m"),
    [O_WIDTH_M] = MM_SCALAR("width_measured", "r.m.s. width at t, measured", "m"),
    [O_SPREAD_M] = MM_SCALAR("spread_measured", "width at t / width at 0, measured", ""),
    [O_U0] = MM_SERIES("u0", "packet at t = 0", "m", "x", "m", .figure = "packet"),
    [O_U] = MM_SERIES("u", "packet at time t", "m", "x", "m", .figure = "packet"),
    [O_ENV0] = MM_SERIES("envelope0", "envelope at t = 0", "m", "x", "m", .figure = "packet", .role = "reference"),
    [O_ENV] = MM_SERIES("envelope", "envelope at time t", "m", "x", "m", .figure = "packet", .role = "reference"),
    [O_VP] = MM_SERIES("phase_velocity", "phase velocity omega/k", "m/s", "k", "rad/m", .figure = "dispersion"),
    [O_VG] = MM_SERIES("group_velocity", "group velocity d omega/dk", "m/s", "k", "rad/m", .figure = "dispersion"),
};

typedef struct wave {
    int medium;
    double c, a;           /* bar speed [m/s]; beam constant [m^2/s] */
    double k0, sigma, A, t;
} wave;

static wave model(const mm_value *in)
{
    wave w = {.medium = (int)in[P_MEDIUM].x, .A = in[P_AMP].x, .t = in[P_T].x};
    w.c = sqrt(in[P_E].x / in[P_RHO].x);
    w.a = in[P_H].x * sqrt(in[P_E].x / (12 * in[P_RHO].x));
    w.k0 = 2 * M_PI / in[P_LAMBDA].x;
    w.sigma = in[P_CYCLES].x * in[P_LAMBDA].x;
    return w;
}

static double omega_of(const wave *w, double k) { return w->medium == M_BAR ? w->c * k : w->a * k * k; }
static double group_of(const wave *w, double k) { return w->medium == M_BAR ? w->c : 2 * w->a * k; }
static double sigma_t(const wave *w)                                  /* eq. (8) */
{
    if (w->medium == M_BAR)
        return w->sigma;
    double beta = 2 * w->a * w->t / (w->sigma * w->sigma);
    return w->sigma * sqrt(1 + beta * beta);
}

/* The domain [xl, xr]: MARGIN envelope widths either side of the packet at
 * t = 0 (centre 0) and at t (centre c_g t). */
static void domain(const wave *w, double *xl, double *xr)
{
    *xl = -MARGIN * w->sigma;
    *xr = group_of(w, w->k0) * w->t + MARGIN * sigma_t(w);
}

static int check(const mm_value *in, mm_error *err)
{
    wave w = model(in);
    double xl, xr, lambda = in[P_LAMBDA].x;
    domain(&w, &xl, &xr);
    if ((xr - xl) / lambda > MAX_WAVES) {
        double cg = group_of(&w, w.k0);
        return mm_error_set(err, MM_ERANGE, "t",
                            "t must be shorter: by t = %g s the packet (group velocity %.4g m/s) has moved and "
                            "spread over %.0f wavelengths, more than the %d a plot can show; try t below %.3g s",
                            w.t, cg, (xr - xl) / lambda, MAX_WAVES,
                            fmax(0, (MAX_WAVES * lambda - 2 * MARGIN * w.sigma) / (cg + 2 * MARGIN * w.a / w.sigma)));
    }
    return MM_OK;
}

/* Closed form of the complex packet, eqs. (5) and (7):
 *   psi = A / sqrt(1 + i beta) exp(i (k0 x - w0 t)) exp(-(x - cg t)^2 / (2 sigma^2 (1 + i beta)))
 * with beta = 2 a t / sigma^2 for the beam, beta = 0 for the bar. */
static double complex exact_psi(const wave *w, double x, double t)
{
    double w0 = omega_of(w, w->k0), cg = group_of(w, w->k0);
    double beta = w->medium == M_BAR ? 0 : 2 * w->a * t / (w->sigma * w->sigma);
    double complex q = 1 + I * beta, y = x - cg * t;
    double ph = fmod(w->k0 * x - w0 * t, 2 * M_PI);
    return w->A / csqrt(q) * cexp(I * ph) * cexp(-y * y / (2 * w->sigma * w->sigma * q));
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    wave w = model(in);
    const double t = w.t, lambda = in[P_LAMBDA].x, h = in[P_H].x;
    /* c_p = omega/k0 is c (bar) or a k0 (beam) itself; omega(k0)/k0 would round */
    const double w0 = omega_of(&w, w.k0), cp = w.medium == M_BAR ? w.c : w.a * w.k0, cg = group_of(&w, w.k0);
    double xl, xr;
    domain(&w, &xl, &xr);
    const double L = xr - xl;

    /* samples: the spectrum exp(-sigma^2 (k - k0)^2 / 2) must be negligible
     * (exp(-50)) at the Nyquist wavenumber pi/dx: pi/dx >= k0 + 10/sigma */
    long N = 64;
    while (M_PI * (double)N / L < w.k0 + 10 / w.sigma)
        N *= 2;
    const double dx = L / (double)N, dk = 2 * M_PI / L;
    double *u0 = mm_res_alloc(res, sizeof *u0 * (size_t)N);
    size_t nb = mm_fourier_bins((size_t)N);
    double *cr = mm_res_alloc(res, sizeof *cr * nb), *ci = mm_res_alloc(res, sizeof *ci * nb);
    if (!u0 || !cr || !ci)
        return MM_ENOMEM;
    for (long n = 0; n < N; n++)
        u0[n] = creal(exact_psi(&w, xl + (double)n * dx, 0));           /* eq. (5) */
    int rc = mm_fourier_dft(u0, (size_t)N, cr, ci, err);
    if (rc != MM_OK)
        return rc;

    /* the modes that matter: |c_j| above 1e-17 of the largest */
    double cmax = 0;
    for (size_t j = 1; j < nb; j++)
        cmax = fmax(cmax, hypot(cr[j], ci[j]));
    int jlo = (int)nb - 1, jhi = 1;
    for (size_t j = 1; j + 1 < nb; j++)                               /* the Nyquist bin is left out */
        if (hypot(cr[j], ci[j]) > 1e-17 * cmax) {
            jlo = (int)j < jlo ? (int)j : jlo;
            jhi = (int)j;
        }
    int nm = jhi - jlo + 1;
    double complex *C0 = mm_res_alloc(res, sizeof *C0 * (size_t)nm), *Ct = mm_res_alloc(res, sizeof *Ct * (size_t)nm);
    if (!C0 || !Ct)
        return MM_ENOMEM;
    for (int j = jlo; j <= jhi; j++) {
        double k = j * dk;
        double ph = fmod(omega_of(&w, k) * t, 2 * M_PI);
        C0[j - jlo] = cr[j] + I * ci[j];
        Ct[j - jlo] = C0[j - jlo] * cexp(-I * ph);                     /* each mode's own phase, eq. (6) */
    }

    /* ---- the packet at 0 and at t on the plot grid ---- */
    int np = (int)ceil(8 * L / lambda) + 1;
    np = np < 501 ? 501 : np > 2001 ? 2001 : np;
    mm_series *s0 = mm_res_series(res, O_U0, np), *st = mm_res_series(res, O_U, np);
    mm_series *e0 = mm_res_series(res, O_ENV0, np), *et = mm_res_series(res, O_ENV, np);
    double complex *p0 = mm_res_alloc(res, sizeof *p0 * (size_t)np), *pt = mm_res_alloc(res, sizeof *pt * (size_t)np);
    if (!s0 || !st || !e0 || !et || !p0 || !pt)
        return MM_ENOMEM;
    mm_linspace(xl, xr, np, s0->x);
    double complex c0 = cr[0];
    /* psi(x, t) = c_0 + 2 sum_j C_j exp(i k_j (x - xl)), eq. (6), C_j = c_j exp(-i omega_j t) */
    mm_fourier_mode_sum(C0, jlo, jhi, dk, c0, s0->x, np, xl, SUM_RESTART, p0);
    mm_fourier_mode_sum(Ct, jlo, jhi, dk, c0, s0->x, np, xl, SUM_RESTART, pt);
    double worst = 0, worst0 = 0;
    for (int i = 0; i < np; i++) {
        double x = s0->x[i];
        st->x[i] = e0->x[i] = et->x[i] = x;
        s0->y[i] = creal(p0[i]);
        st->y[i] = creal(pt[i]);
        e0->y[i] = cabs(p0[i]);
        et->y[i] = cabs(pt[i]);
        worst = fmax(worst, fabs(st->y[i] - creal(exact_psi(&w, x, t))));
        worst0 = fmax(worst0, fabs(s0->y[i] - creal(exact_psi(&w, x, 0))));
    }
    /* the curves are for the eye: six digits, once the checks and the
     * moments have used them all */
    /* the centroid and r.m.s. width of |psi|^2 (mm_quad_moments) */
    double xc0, xct, wd0, wdt, *d0 = mm_res_alloc(res, 2 * sizeof *d0 * (size_t)np), *dt = d0 + np;
    if (!d0)
        return MM_ENOMEM;
    for (int i = 0; i < np; i++) {
        d0[i] = creal(p0[i]) * creal(p0[i]) + cimag(p0[i]) * cimag(p0[i]);
        dt[i] = creal(pt[i]) * creal(pt[i]) + cimag(pt[i]) * cimag(pt[i]);
    }
    mm_quad_moments(s0->x, d0, np, &xc0, &wd0);
    mm_quad_moments(s0->x, dt, np, &xct, &wdt);
    mm_series *sr[4] = {s0, st, e0, et};
    for (int k = 0; k < 4; k++) {
        mm_ex_round_sig(sr[k]->x, np, 8);
        mm_ex_round_sig(sr[k]->y, np, 6);
    }
    double speed = (xct - xc0) / t;

    /* ---- dispersion curves: phase and group velocity against k ---- */
    mm_series *vp = mm_res_series(res, O_VP, 201), *vg = mm_res_series(res, O_VG, 201);
    if (!vp || !vg)
        return MM_ENOMEM;
    mm_linspace(0, 2.5 * w.k0, 201, vp->x);
    for (int i = 0; i < 201; i++) {
        double k = vp->x[i];
        vg->x[i] = k;
        vp->y[i] = w.medium == M_BAR ? w.c : w.a * k;
        vg->y[i] = group_of(&w, k);
    }
    mm_ex_round_sig(vp->x, 201, 8);
    mm_ex_round_sig(vg->x, 201, 8);
    mm_ex_round_sig(vp->y, 201, 6);
    mm_ex_round_sig(vg->y, 201, 6);

    /* ---- scalars: the closed forms, the measurements beside them ---- */
    double w_0 = w.sigma / M_SQRT2, w_t = sigma_t(&w) / M_SQRT2, rnd = 4 * DBL_EPSILON;
    mm_res_scalar(res, O_K0, w.k0);
    mm_res_scalar(res, O_OMEGA0, w0);
    mm_res_scalar(res, O_F0, w0 / (2 * M_PI));
    mm_res_scalar(res, O_CP, cp);
    mm_res_scalar(res, O_CG, cg);
    mm_res_scalar(res, O_RATIO, cg / cp);
    mm_res_scalar(res, O_SPEED, cg);
    mm_res_scalar(res, O_TRAVEL, cg * t);
    mm_res_scalar(res, O_SLIP, (cg - cp) * t / lambda);
    mm_res_scalar(res, O_WIDTH0, w_0);
    mm_res_scalar(res, O_WIDTH, w_t);
    mm_res_scalar(res, O_SPREAD, sigma_t(&w) / w.sigma);
    /* each measured value carries its distance from the closed form plus the
     * rounding bound of the checks below (another summation order, a
     * learner's script, lands anywhere within it: a short t leaves the
     * centroids' difference mostly rounding) */
    double r_xc = 12 * DBL_EPSILON * (fabs(xl) + fabs(xr)), r_w = 8 * DBL_EPSILON * sqrt((double)np);
    mm_ex_scalar_beside(res, O_SPEED_M, speed, cg, rnd * cg + r_xc / t);
    mm_ex_scalar_beside(res, O_TRAVEL_M, xct - xc0, cg * t, rnd * cg * t + r_xc);
    mm_ex_scalar_beside(res, O_WIDTH0_M, wd0, w_0, (rnd + r_w) * w_0);
    mm_ex_scalar_beside(res, O_WIDTH_M, wdt, w_t, (rnd + r_w) * w_t);
    mm_ex_scalar_beside(res, O_SPREAD_M, wdt / wd0, sigma_t(&w) / w.sigma, (rnd + 2 * r_w) * sigma_t(&w) / w.sigma);

    /* ---- checks ---- */
    /* the mode sums round by a few eps of the sum of the sizes of their
     * terms, for each of the log2 N levels of the FFT and the rotations;
     * both sides carry phases k x - omega t rounded to eps of their size;
     * the spectrum was cut at exp(-50) and the domain at exp(-81/2) */
    double S = fabs(cr[0]);
    for (int j = jlo; j <= jhi; j++)
        S += 2 * cabs(C0[j - jlo]);
    double phase = w.k0 * fmax(fabs(xl), fabs(xr)) + w0 * t;
    double tol_u = 16 * DBL_EPSILON * S * log2((double)N) + 2 * DBL_EPSILON * phase * w.A + 4e-18 * w.A;
    mm_res_check_abs(res, "packet at t = 0: mode sum vs eq. (5) (sampling and FFT) [m]", worst0, 0, tol_u);
    mm_res_check_abs(res, w.medium == M_BAR
                              ? "packet at t: mode sum vs the initial packet moved by c t, eq. (7) with beta = 0 [m]"
                              : "packet at t: mode sum vs the Gaussian chirp, eq. (7) [m]",
                     worst, 0, tol_u);
    /* the centroids are sums of positive terms times x: they round by a
     * few eps of the domain's extent; the speed then to that over t; the
     * r.m.s. width by a few eps times sqrt(points) relative */
    mm_res_check_abs(res, "centroid speed of |psi|^2 (measured) vs group velocity d omega/dk, to rounding [m/s]",
                     speed, cg, r_xc / t);
    mm_res_check_rel(res, "r.m.s. width at t (measured) vs sigma_t / sqrt 2, eq. (8), to rounding [m]", wdt, w_t,
                     r_w);

    mm_res_method(res, "FFT of the sampled packet, each mode advanced by exp(-i omega(k) t), modes summed", 0);
    mm_res_method_stat(res, "samples", (double)N);
    mm_res_method_stat(res, "modes", nm);
    mm_res_method_stat(res, "domain_wavelengths", L / lambda);

    if (w.medium == M_BEAM && lambda < 10 * h)
        mm_res_warn(res, "the wavelength is only %.2g times the thickness: Euler-Bernoulli theory (eq. 2) needs "
                         "wavelengths well above 10 h; a real beam (Timoshenko) is slower here", lambda / h);
    return MM_OK;
}

static const char *const references[] = {
    "K. F. Graff, Wave Motion in Elastic Solids, Dover 1991, sections 1.3 (dispersion, group velocity) and 3.1",
    "G. B. Whitham, Linear and Nonlinear Waves, Wiley 1974, ch. 11",
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, ch. 8 (continuous systems)",
    NULL,
};

const mm_exercise mm_ex_vib_dispersion = {
    .id = "vib-dispersion", .chapter = 5, .section = "5.3",
    .title = "Phase and group velocity: a wave packet in a beam and in a bar",
    .summary = "A wave packet travels at the group velocity while its crests move at the phase velocity; in a "
               "beam the packet spreads, in a bar it keeps its shape.",
    .tags = "waves, dispersion, phase velocity, group velocity, wave packet, beam, bar",
    .theory = "exercises/vib/dispersion.md", .params = params, .n_params = MM_COUNT(params), .outputs = outputs,
    .n_outputs = MM_COUNT(outputs), .references = references, .check = check, .solve = solve,
};
