/* mm_sdof.c — closed-form 1-DOF response (see mm_sdof.h for the formulas). */
#include "mm_sdof.h"

#include <complex.h>
#include <math.h>

const char *mm_sdof_regime_name(int regime)
{
    static const char *const names[] = {"underdamped", "critically damped", "overdamped"};
    return regime >= 0 && regime <= 2 ? names[regime] : "";
}

int mm_sdof_check(const mm_sdof *s, mm_error *err)
{
    const struct { const char *name; double v; } f[] = {
        {"m", s->m}, {"c", s->c}, {"k", s->k}, {"F0", s->F0},
        {"omega", s->omega}, {"x0", s->x0}, {"v0", s->v0}, {"G0", s->G0},
    };
    for (unsigned i = 0; i < sizeof f / sizeof f[0]; i++)
        if (!isfinite(f[i].v))
            return mm_error_set(err, MM_EVALUE, f[i].name, "%s must be a finite number", f[i].name);
    if (!(s->m > 0))
        return mm_error_set(err, MM_ERANGE, "m", "m must be > 0 kg; got %g", s->m);
    if (!(s->k > 0))
        return mm_error_set(err, MM_ERANGE, "k", "k must be > 0 N/m; got %g", s->k);
    if (!(s->c >= 0))
        return mm_error_set(err, MM_ERANGE, "c", "c must be >= 0 N s/m; got %g", s->c);
    if (!(s->omega >= 0))
        return mm_error_set(err, MM_ERANGE, "omega", "omega must be >= 0 rad/s; got %g", s->omega);
    return MM_OK;
}

void mm_sdof_props_get(const mm_sdof *s, mm_sdof_props *p)
{
    p->omega_n = sqrt(s->k / s->m);
    p->zeta = s->c / (2.0 * sqrt(s->k * s->m));
    p->regime = fabs(p->zeta - 1.0) <= 1e-12 ? MM_SDOF_CRITICAL
              : p->zeta < 1.0                 ? MM_SDOF_UNDER
                                              : MM_SDOF_OVER;
    p->omega_d = p->regime == MM_SDOF_UNDER ? p->omega_n * sqrt((1 - p->zeta) * (1 + p->zeta)) : 0.0;

    /* dynamic stiffness k - m w^2 + i c w; m w^2 as the exact sum
     * q + e2 + e1 w (two fma products), so that k - m w^2 near resonance
     * keeps the digits the data have */
    double w = s->omega, mw = s->m * w, e1 = fma(s->m, w, -mw);
    double q = mw * w, e2 = fma(mw, w, -q);
    double re = ((s->k - q) - e2) - e1 * w;
    double im = s->c * w;
    double F = hypot(s->F0, s->G0);
    p->stiffness_re = re;
    /* no damping and |k - m w^2| within 1e-9 k: the beat period is then over
     * 1e9 natural periods, so no steady state is ever reached (and X would
     * be a meaningless 1e9 F0/k or more) */
    p->resonant = (im == 0.0 && fabs(re) <= 1e-9 * s->k);
    if (p->resonant) {
        p->X = 0.0;
        p->phase = M_PI / 2;
        p->magnification = 0.0;
    } else {
        double mod = hypot(re, im);
        p->X = F / mod;
        p->phase = atan2(im, re);                     /* in [0, pi] since im >= 0 */
        p->magnification = s->k / mod;
    }
}

/* sin(x)/x and sinh(x)/x, accurate near 0. */
static double sinc(double x)
{
    if (fabs(x) < 1e-4)
        return 1.0 - x * x / 6.0 * (1.0 - x * x / 20.0);
    return sin(x) / x;
}

static double sinhc(double x)
{
    if (fabs(x) < 1e-4)
        return 1.0 + x * x / 6.0 * (1.0 + x * x / 20.0);
    return sinh(x) / x;
}

/* The motion with x(0) = A, x'(0) = dv of x'' + 2 a x' + wn2 x = 0, and its
 * velocity, lambda = wn2 - a^2 = omega_n^2 (1 - zeta^2):
 *   x = e^(-a t) [A (C + a S) + dv S],  v = e^(-a t) [dv (C - a S) - wn2 A S],
 * C = cos(sqrt(lambda) t), S = sin(sqrt(lambda) t)/sqrt(lambda) (cosh, sinh
 * when lambda < 0; 1, t when 0).  In this form a^2 + lambda = wn2 never
 * appears as a difference (it loses 2 log10(2 zeta) digits when overdamped). */
static double homogeneous(double a, double lambda, double wn2, double A, double dv, double t, double *v)
{
    double C, S;
    if (lambda > 0) {
        double w = sqrt(lambda);
        C = cos(w * t);
        S = t * sinc(w * t);
    } else if (lambda < 0) {
        double mu = sqrt(-lambda);
        if (mu * t > 1.0) {
            /* overdamped, far from critical: the two decaying modes
             *   x = c1 e^(-r1 t) + c2 e^(-r2 t),  r2 = a + mu,  r1 = a - mu = wn2 / r2,
             *   c1 = (r2 A + dv) / (2 mu),  c2 = -(r1 A + dv) / (2 mu),
             * so that neither a - mu cancels nor e^(-at) cosh, sinh overflow */
            double r2 = a + mu, r1 = wn2 / r2;
            double c1 = (r2 * A + dv) / (2 * mu), c2 = -(r1 * A + dv) / (2 * mu);
            double slow = c1 * exp(-r1 * t), fast = c2 * exp(-r2 * t);
            if (v)
                *v = -r1 * slow - r2 * fast;
            return slow + fast;
        }
        C = cosh(mu * t);
        S = t * sinhc(mu * t);
    } else {
        C = 1.0;
        S = t;
    }
    double e = exp(-a * t);
    if (v)
        *v = e * (dv * (C - a * S) - wn2 * A * S);
    return e * (A * (C + a * S) + dv * S);
}

/* The damped (or free) response: the steady state X cos(w t - lag) plus
 * the homogeneous part that meets the initial conditions.  What does not
 * depend on t is computed once (damped_form), so that a plot of n points
 * and one point give the same numbers. */
typedef struct damped_form {
    double a, lambda, wn2, w, X, lag, x0h, v0h;
    int forced;
} damped_form;

static damped_form damped_prep(const mm_sdof *s, const mm_sdof_props *p)
{
    double wn = p->omega_n;
    damped_form d = {.a = p->zeta * wn,                          /* decay rate c / 2m */
                     .lambda = p->regime == MM_SDOF_CRITICAL ? 0.0 : wn * wn * (1 - p->zeta) * (1 + p->zeta),
                     .wn2 = wn * wn, .w = s->omega, .X = p->X, .x0h = s->x0, .v0h = s->v0,
                     .forced = s->F0 != 0.0 || s->G0 != 0.0};
    if (d.forced) {
        d.lag = p->phase - atan2(-s->G0, s->F0);               /* x_p = X cos(w t - lag) */
        d.x0h -= d.X * cos(-d.lag);
        d.v0h -= -d.X * d.w * sin(-d.lag);
    }
    return d;
}

static double damped_x(const damped_form *d, double t, double *v)
{
    double xp = 0, vp = 0;
    if (d->forced) {
        xp = d->X * cos(d->w * t - d->lag);
        if (v)                                     /* a plot asks for x alone */
            vp = -d->X * d->w * sin(d->w * t - d->lag);
    }
    double vh, xh = homogeneous(d->a, d->lambda, d->wn2, d->x0h, d->v0h, t, &vh);
    if (v)
        *v = vh + vp;
    return xh + xp;
}

double mm_sdof_x(const mm_sdof *s, const mm_sdof_props *p, double t, double *v)
{
    double wn = p->omega_n, w = s->omega;
    if (s->c == 0.0 && (s->F0 != 0.0 || s->G0 != 0.0)) {
        /* undamped: x = x0 C + v0 S + F0/m g(t) + G0/m h(t), with
         *   g = (cos w t - cos wn t)/(wn^2 - w^2) = t sin(sm t) sinc(d t) / (2 sm),
         *   h = (sin w t - (w/wn) sin wn t)/(wn^2 - w^2)
         *     = (sin(wn t)/wn - t cos(sm t) sinc(d t)) / (2 sm),
         * sm = (wn + w)/2, d = (wn - w)/2; h' = w g. */
        double sm = 0.5 * (wn + w), d = 0.5 * (wn - w);
        double vh, xh = homogeneous(0.0, wn * wn, wn * wn, s->x0, s->v0, t, &vh);
        double sd = sinc(d * t);
        double g = t * sin(sm * t) * sd / (2.0 * sm);
        double h = (sin(wn * t) / wn - t * cos(sm * t) * sd) / (2.0 * sm);
        if (v) {
            /* g' by the product rule on (t/(2 sm)) sin(sm t) sinc(d t) */
            double dsinc = fabs(d * t) < 1e-4 ? -d * d * t / 3.0
                                              : d * (cos(d * t) - sd) / (d * t);  /* d/dt sinc(d t) */
            double gd = (sin(sm * t) * sd + t * sm * cos(sm * t) * sd + t * sin(sm * t) * dsinc) / (2.0 * sm);
            *v = vh + (s->F0 * gd + s->G0 * w * g) / s->m;
        }
        return xh + (s->F0 * g + s->G0 * h) / s->m;
    }

    damped_form d = damped_prep(s, p);
    return damped_x(&d, t, v);
}

void mm_sdof_x_many(const mm_sdof *s, const mm_sdof_props *p, int n, const double *t, double *x)
{
    if (s->c == 0.0 && (s->F0 != 0.0 || s->G0 != 0.0)) {
        for (int i = 0; i < n; i++)
            x[i] = mm_sdof_x(s, p, t[i], NULL);
        return;
    }
    damped_form d = damped_prep(s, p);
    for (int i = 0; i < n; i++)
        x[i] = damped_x(&d, t[i], NULL);
}

/* Written as x'' = F/m - (c/m) x' - (k/m) x: the quotients do not depend on
 * y, so they are computed while the integrator forms the stage, and the
 * path from y to dydt is two products and two sums (a division on it made
 * every DOP853 stage wait about 15 cycles more). */
int mm_sdof_rhs(double t, const double *y, double *dydt, void *params)
{
    const mm_sdof *s = params;
    double wt = s->omega * t, im = 1.0 / s->m;
    double F = s->G0 != 0.0 ? s->F0 * cos(wt) + s->G0 * sin(wt) : s->F0 * cos(wt);
    dydt[0] = y[1];
    dydt[1] = (F * im - (s->c * im) * y[1]) - (s->k * im) * y[0];
    return 0;
}

void mm_sdof_flow(const mm_sdof *s, double w, double tau, double Phi[4], int *squarings)
{
    /* B = tau A / 2^q with ||B||_inf <= 1/2; its Taylor series to the term
     * below eps of the sum (at most 25 terms: 2^-25 / 25! is far below),
     * then squared q times */
    double A[4] = {0, tau * w, -tau * (s->k / s->m) / w, -tau * s->c / s->m};
    double norm = fmax(fabs(A[1]), fabs(A[2]) + fabs(A[3]));
    int q = 0;
    if (norm > 0.5)
        q = (int)ceil(log2(norm / 0.5));
    double sc = ldexp(1.0, -q);
    for (int i = 0; i < 4; i++)
        A[i] *= sc;
    double E[4] = {1, 0, 0, 1}, T[4] = {1, 0, 0, 1};
    for (int j = 1; j <= 25; j++) {
        double U[4] = {(T[0] * A[0] + T[1] * A[2]) / j, (T[0] * A[1] + T[1] * A[3]) / j,
                       (T[2] * A[0] + T[3] * A[2]) / j, (T[2] * A[1] + T[3] * A[3]) / j};
        for (int i = 0; i < 4; i++) {
            T[i] = U[i];
            E[i] += U[i];
        }
        if (fabs(T[0]) + fabs(T[1]) + fabs(T[2]) + fabs(T[3]) <= 1e-17 * (fabs(E[0]) + fabs(E[3])))
            break;
    }
    for (int r = 0; r < q; r++) {
        double U[4] = {E[0] * E[0] + E[1] * E[2], E[0] * E[1] + E[1] * E[3], E[2] * E[0] + E[3] * E[2],
                       E[2] * E[1] + E[3] * E[3]};
        for (int i = 0; i < 4; i++)
            E[i] = U[i];
    }
    for (int i = 0; i < 4; i++)
        Phi[i] = E[i];
    if (squarings)
        *squarings = q;
}

double mm_sdof_energy(const mm_sdof *s, double x, double v)
{
    return 0.5 * s->m * v * v + 0.5 * s->k * x * x;
}

double mm_sdof_fastest_rate(const mm_sdof *s, const mm_sdof_props *p)
{
    double rate = p->omega_n;
    if (s->F0 != 0.0 || s->G0 != 0.0)
        rate = fmax(rate, s->omega);
    if (p->zeta > 1)                                  /* fast overdamped mode */
        rate = fmax(rate, p->omega_n * (p->zeta + sqrt((p->zeta - 1) * (p->zeta + 1))));
    return rate;
}

double mm_sdof_rk4_gain(double wh, double zeta)
{
    double gain = 0;
    for (int sgn = -1; sgn <= 1; sgn += 2) {
        double complex z = wh * (-zeta + sgn * csqrt(zeta * zeta - 1));
        gain = fmax(gain, cabs(1 + z + z * z / 2 + z * z * z / 6 + z * z * z * z / 24));
    }
    return gain;
}

double mm_sdof_verlet_gain(double wh, double zeta)
{
    double T = 2 - 2 * zeta * wh - wh * wh, D = 1 - 2 * zeta * wh, gain = 0;
    for (int sgn = -1; sgn <= 1; sgn += 2)
        gain = fmax(gain, cabs((T + sgn * csqrt(T * T - 4 * D)) / 2));
    return gain;
}

/* ==== the damper's work (chapter 5, vib-sdof-free) ============================ */

#include "mm_ode.h"   /* here, with the block it serves: the rest of the file needs no integrator */

/* y = (x, v, D): D' = c v^2 is the work the damper has taken. */
static int rhs_energy(double t, const double *y, double *dy, void *ctx)
{
    const mm_sdof *s = ctx;
    mm_sdof_rhs(t, y, dy, ctx);
    dy[2] = s->c * y[1] * y[1];
    return 0;
}

int mm_sdof_damper_work(const mm_sdof *s, const mm_sdof_props *p, double t_end, double rtol, double *D,
                        mm_error *err)
{
    double E0 = mm_sdof_energy(s, s->x0, s->v0), size = sqrt(2 * E0 / s->k);
    double y0[3] = {s->x0, s->v0, 0}, y[3];
    mm_ode_problem prob = {.n = 3, .f = rhs_energy, .params = (void *)s, .t_end = t_end, .y0 = y0};
    mm_ode_options opt = mm_ode_options_adaptive(MM_ODE_DOP853, rtol, rtol * fmin(fmin(size, size * p->omega_n), E0),
                                                 1000000);
    opt.h_max = 1 / mm_sdof_fastest_rate(s, p);
    mm_ode_result r = {.y_end = y};
    int rc = mm_ode_run(&prob, &opt, &r, err);
    *D = y[2];
    return rc;
}
