/* mm_elliptic.c — K, F and the Jacobi functions (see mm_elliptic.h). */
#include "mm_elliptic.h"

#include <assert.h>
#include <float.h>
#include <math.h>

#define PI 3.14159265358979323846
#define AGM_MAX 32        /* steps; 7 reach round-off even at kc = 1e-300 + a few */

/* The AGM sequence from (1, kc): a[0..n], c[0..n] with c[0] = k, stopped
 * when c[n] <= eps a[n].  Returns n. */
static int agm(double k, double kc, double *a, double *c)
{
    double b = kc;
    a[0] = 1;
    c[0] = k;
    int n = 0;
    while (n < AGM_MAX - 1 && fabs(c[n]) > DBL_EPSILON * a[n]) {
        a[n + 1] = 0.5 * (a[n] + b);
        c[n + 1] = 0.5 * (a[n] - b);
        b = sqrt(a[n] * b);
        n++;
    }
    return n;
}

double mm_elliptic_Kc(double kc)
{
    assert(kc >= 0 && kc <= 1);
    if (kc == 0)
        return INFINITY;
    double a = 1, b = kc;
    for (int i = 0; i < AGM_MAX && a - b > DBL_EPSILON * a; i++) {
        double an = 0.5 * (a + b);
        b = sqrt(a * b);
        a = an;
    }
    return PI / (a + b);                    /* pi / (2 AGM), AGM ~ (a + b)/2 at the end */
}

double mm_elliptic_K(double k)
{
    assert(k >= 0 && k <= 1);
    return mm_elliptic_Kc(sqrt((1 - k) * (1 + k)));
}

double mm_elliptic_RF(double x, double y, double z)
{
    assert(x >= 0 && y >= 0 && z >= 0 && (x > 0) + (y > 0) + (z > 0) >= 2);
    /* duplication until the three arguments agree to 0.0008 relative: the
     * neglected terms of the series below are then of order 0.0008^6 / 4,
     * about 6e-20 (Carlson 1995, eq. 2.2 with the 5th-order terms) */
    const double tol = 0.0008;
    double mu, dx, dy, dz;
    for (int i = 0; i < 100; i++) {
        mu = (x + y + z) / 3;
        dx = (mu - x) / mu;
        dy = (mu - y) / mu;
        dz = (mu - z) / mu;
        if (fmax(fabs(dx), fmax(fabs(dy), fabs(dz))) < tol)
            break;
        double sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
        double lam = sx * (sy + sz) + sy * sz;
        x = 0.25 * (x + lam);
        y = 0.25 * (y + lam);
        z = 0.25 * (z + lam);
    }
    double e2 = dx * dy - dz * dz, e3 = dx * dy * dz;
    return (1 - e2 / 10 + e3 / 14 + e2 * e2 / 24 - 3 * e2 * e3 / 44) / sqrt(mu);
}

double mm_elliptic_F(double phi, double k, double kc)
{
    assert(k >= 0 && k <= 1 && kc >= 0 && kc <= 1);
    double m = nearbyint(phi / PI), r = phi - m * PI;    /* r in [-pi/2, pi/2] */
    double s = sin(r), c = cos(r);
    /* 1 - k^2 sin^2 r written as kc^2 + k^2 cos^2 r: no cancellation near k = 1 */
    double f = s * mm_elliptic_RF(c * c, kc * kc + k * k * c * c, 1);
    if (m == 0)
        return f;
    assert(kc > 0);
    return f + 2 * m * mm_elliptic_Kc(kc);
}

/* sn, cn, dn, am at r in [0, K] by the descending AGM (A&S 16.4.3): a[],
 * c[] of agm() up to n. */
static void jacobi_agm(double r, double k, const double *a, const double *c, int n, double *sn,
                       double *cn, double *dn, double *am)
{
    double phi = ldexp(a[n] * r, n), prev = phi;
    for (int j = n; j >= 1; j--) {
        prev = phi;
        phi = 0.5 * (phi + asin(c[j] / a[j] * sin(phi)));
    }
    *sn = sin(phi);
    *cn = cos(phi);
    *dn = n > 0 ? cos(phi) / cos(prev - phi) : sqrt(1 - k * k * sin(phi) * sin(phi));
    *am = phi;
}

void mm_elliptic_jacobi(double u, double k, double kc, double *sn, double *cn, double *dn,
                        double *am)
{
    assert(k >= 0 && k <= 1 && kc >= 0 && kc <= 1);
    double s, c, d, ph;
    if (kc == 0) {                              /* k = 1: the separatrix */
        s = tanh(u);
        c = d = 1 / cosh(u);
        ph = atan(sinh(u));                     /* the Gudermannian */
    } else {
        double a[AGM_MAX], cc[AGM_MAX];
        int n = agm(k, kc, a, cc);
        double K = PI / (2 * a[n]);
        double m = nearbyint(u / (2 * K)), r = u - 2 * K * m;   /* am(u + 2K) = am(u) + pi */
        double ar = fabs(r);
        if (ar <= 0.5 * K) {
            jacobi_agm(ar, k, a, cc, n, &s, &c, &d, &ph);
        } else {
            /* near the quarter period cn and dn are small and cos(am) would
             * keep only their absolute accuracy: go through v = K - r,
             * sn(K - v) = cn/dn, cn(K - v) = kc sn/dn, dn(K - v) = kc/dn (A&S 16.8) */
            double sv, cv, dv, av;
            jacobi_agm(K - ar, k, a, cc, n, &sv, &cv, &dv, &av);
            s = cv / dv;
            c = kc * sv / dv;
            d = kc / dv;
            ph = atan2(cv, kc * sv);
        }
        if (r < 0) {                            /* sn and am are odd, cn and dn even */
            s = -s;
            ph = -ph;
        }
        if (fmod(m, 2) != 0) {                  /* half a period on: sn, cn change sign */
            s = -s;
            c = -c;
        }
        ph += m * PI;
    }
    if (sn)
        *sn = s;
    if (cn)
        *cn = c;
    if (dn)
        *dn = d;
    if (am)
        *am = ph;
}

/* ---- added for the kinematics chapter ------------------------------------------------ */

double mm_elliptic_E(double k)
{
    double a = 1, g = sqrt((1 - k) * (1 + k)), c = k, sum = 0.5 * c * c, p2 = 0.5;
    if (!(g > 0))
        return 1;                  /* k = 1 (or rounds to it): the AGM of 1 and 0 never converges */
    for (int i = 0; i < 40 && fabs(c) > DBL_EPSILON * a; i++) {
        double an = 0.5 * (a + g);
        c = 0.5 * (a - g);
        g = sqrt(a * g);
        a = an;
        p2 *= 2;
        sum += p2 * c * c;
    }
    return M_PI / (2 * a) * (1 - sum);
}
