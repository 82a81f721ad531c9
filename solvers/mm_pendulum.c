/* mm_pendulum.c — the plane pendulum in closed form: its exact motion and
 * its period against the amplitude (see mm_pendulum.h). */
#include "mm_pendulum.h"

#include <float.h>
#include <math.h>

#include "mm_elliptic.h"
#include "mm_roots.h"

double mm_pendulum_period_ratio(double theta0) { return 2 * mm_elliptic_Kc(cos(0.5 * theta0)) / M_PI; }

static int ratio_minus(double th, double *f, void *ctx)
{
    *f = 2 * mm_elliptic_Kc(cos(0.5 * th)) / M_PI - *(const double *)ctx;
    return 0;
}

int mm_pendulum_amplitude(double ratio, double a, double b, double *theta0, double *err, mm_error *e)
{
    double fa, fb, fx, width;
    ratio_minus(a, &fa, &ratio);
    ratio_minus(b, &fb, &ratio);
    int iter = 0;
    int rc = mm_roots_brent(ratio_minus, &ratio, a, b, fa, fb, 1e-16, 200, theta0, &fx, &width, &iter, NULL, e);
    if (rc != MM_OK)
        return rc;
    /* the root of the computed function lies in the final bracket; the
     * computed function is within 4 eps of the true one, which moves the
     * root by 4 eps / slope (slope ~ theta/8 = 0.05 at a ratio of 1.01) */
    double h = 1e-4, fp, fm;
    ratio_minus(*theta0 + h, &fp, &ratio);
    ratio_minus(*theta0 - h, &fm, &ratio);
    double slope = (fp - fm) / (2 * h);
    *err = width + 4 * DBL_EPSILON * ratio / (0.5 * slope);
    return MM_OK;
}

double mm_pendulum_ratio_series(double theta0, double *next)
{
    double x2 = theta0 * theta0;
    *next = 1319183.0 / 951268147200 * x2 * x2 * x2 * x2 * x2;
    return 1 + x2 * (1.0 / 16 + x2 * (11.0 / 3072 + x2 * (173.0 / 737280 + x2 * 22931.0 / 1321205760)));
}


/* ---- the exact motion ---- */


/* sin theta with the top exact: theta = pi (the double nearest pi, as the
 * parameter reads it) is the inverted equilibrium, sin = 0. */
double mm_pendulum_sin_top(double th)
{
    double r = th - 2 * M_PI * nearbyint(th / (2 * M_PI));   /* r in [-pi, pi] */
    if (r > M_PI_2)
        return sin(M_PI - r);
    if (r < -M_PI_2)
        return -sin(M_PI + r);
    return sin(r);
}

/* The exact theta(t) and theta'(t) (eqs. 4 and 6). */
double mm_pendulum_exact(const mm_pendulum_motion *p, double t, double *w)
{
    double sn, cn, dn, am;
    switch (p->motion) {
    case MM_PENDULUM_SWING:
        mm_elliptic_jacobi(p->wn * t + p->u0, p->k, p->kc, &sn, &cn, &dn, NULL);
        *w = 2 * p->k * p->wn * cn;
        return 2 * atan2(p->k * sn, dn);       /* sin(theta/2) = k sn, cos(theta/2) = dn */
    case MM_PENDULUM_SEPARATRIX:
        if (p->omega0 == 0) {
            *w = 0;
            return M_PI;
        }
        /* with a push: the limit k = 1 of the rotation formula */
        /* fall through */
    default:
        mm_elliptic_jacobi(p->sg * p->kk * p->wn * t + p->u0, p->k, p->kc, &sn, &cn, &dn, &am);
        *w = 2 * p->sg * p->kk * p->wn * dn;
        return 2 * am;
    }
}

mm_pendulum_motion mm_pendulum_motion_init(double L, double g, double theta0, double omega0)
{
    mm_pendulum_motion p = {.L = L, .g = g, .theta0 = theta0, .omega0 = omega0};
    p.wn = sqrt(p.g / p.L);
    p.T0 = 2 * M_PI / p.wn;
    double s = sin(0.5 * p.theta0);
    double c = p.theta0 == M_PI ? 0 : cos(0.5 * p.theta0);   /* the top exactly */
    double a = fabs(p.omega0) / (2 * p.wn);
    /* eq. (3): k^2 = sin^2(theta0/2) + (omega0 / (2 wn))^2, kc^2 = 1 - k^2 */
    double kc2 = (c - a) * (c + a);
    if (kc2 > 0) {
        p.motion = MM_PENDULUM_SWING;
        p.kc = sqrt(kc2);
        p.k = sqrt(s * s + a * a);
        p.T = 4 * mm_elliptic_Kc(p.kc) / p.wn;                       /* eq. (5) */
        /* sn(u0) = sin(theta0/2)/k, cn(u0) = omega0/(2 k wn): u0 = F(phi0) */
        p.u0 = mm_elliptic_F(atan2(s, p.omega0 / (2 * p.wn)), p.k, p.kc);
    } else if (kc2 == 0 && p.omega0 == 0) {
        p.motion = MM_PENDULUM_SEPARATRIX;                                        /* at rest on the top */
        p.T = INFINITY;
        p.k = 1;
    } else {
        /* over the top (or on the separatrix with a push): theta/2 = am(sg kk wn t + u0, 1/kk) */
        p.motion = kc2 == 0 ? MM_PENDULUM_SEPARATRIX : MM_PENDULUM_OVER;
        p.kk = sqrt(s * s + a * a);
        p.k = 1 / p.kk;
        p.kc = sqrt(-kc2) / p.kk;
        p.sg = p.omega0 >= 0 ? 1 : -1;
        p.T = p.kc > 0 ? 2 * mm_elliptic_Kc(p.kc) / (p.kk * p.wn) : INFINITY;   /* eq. (7) */
        p.u0 = mm_elliptic_F(0.5 * p.theta0, p.k, p.kc);
    }
    return p;
}

/* Energy per unit m L^2: theta'^2 / 2 + wn^2 (1 - cos theta), written with
 * 2 sin^2(theta/2) so that it keeps its digits near the bottom. */
double mm_pendulum_energy(const mm_pendulum_motion *p, double th, double w)
{
    double s = sin(0.5 * th);
    return 0.5 * w * w + 2 * p->wn * p->wn * s * s;
}

/* The period (eqs. 5 and 7) as a function of the distance d = |E - Es| of
 * the energy per unit m L^2 from the separatrix's Es = 2 g/L, on the side
 * the motion is on. */
static double period_of_distance(const mm_pendulum_motion *p, double d)
{
    double Es = 2 * p->wn * p->wn;
    if (p->motion == MM_PENDULUM_SWING)
        return 4 * mm_elliptic_Kc(fmin(sqrt(d / Es), 1)) / p->wn;   /* d <= Es: E >= 0 */
    double E = Es + d;
    return 2 * mm_elliptic_Kc(sqrt(d / E)) / (sqrt(E / Es) * p->wn);
}

/* |dT/dE| by a central difference in d, relative step 1e-4 (accurate to
 * ~1e-8 relative: it only sizes a tolerance).  d comes from kc, which
 * keeps its digits right up to the separatrix.  A swing within h d of the
 * bottom (E = Es - d < h d: an amplitude under 0.02 rad) has no energy
 * below it to step to: there the difference is one-sided, from d down
 * (accurate to ~1e-4 relative; at the bottom dT/dE = pi / (4 wn^3)).
 * Stepping past E = 0 asked K for kc > 1. */
double mm_pendulum_period_sensitivity(const mm_pendulum_motion *p)
{
    double Es = 2 * p->wn * p->wn;
    double d = p->motion == MM_PENDULUM_SWING ? Es * p->kc * p->kc : Es * p->kk * p->kk * p->kc * p->kc, h = 1e-4;
    if (p->motion == MM_PENDULUM_SWING && d * (1 + h) > Es)
        return fabs(period_of_distance(p, d) - period_of_distance(p, d * (1 - 2 * h))) / (2 * h * d);
    return fabs(period_of_distance(p, d * (1 + h)) - period_of_distance(p, d * (1 - h))) / (2 * h * d);
}
