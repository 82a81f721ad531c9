/* mm_pendulum.h — the period of the plane pendulum against its amplitude
 * (dyn-pendulum, eq. 5 of pendulum.md): T / T0 = 2 K(sin(theta0 / 2)) / pi,
 * its Maclaurin series, and the amplitude of a given ratio.
 *
 * Pure numerics: no globals, safe from many threads.
 */
#ifndef MM_PENDULUM_H
#define MM_PENDULUM_H

#include "mm_status.h"

/* T / T0 at the amplitude theta0 in [0, pi): 2 K / pi with K by the
 * arithmetic-geometric mean on the complementary modulus cos(theta0 / 2)
 * (mm_elliptic_Kc), to a few eps.  Cannot fail. */
double mm_pendulum_period_ratio(double theta0);

/* The amplitude in [a, b] at which T / T0 = ratio (Brent, to the spacing
 * of doubles), and into *err its bound: the final bracket, and the 4 eps
 * (times ratio) by which the computed ratio can be off, divided by the
 * slope of the ratio there (a central difference).  ratio - T / T0 must
 * change sign over [a, b].  Fails as mm_roots_brent. */
int mm_pendulum_amplitude(double ratio, double a, double b, double *theta0, double *err, mm_error *e);

/* T / T0 by its Maclaurin series in theta0 to theta0^8 (1 + theta0^2 / 16
 * + 11 theta0^4 / 3072 + ...), and into *next the first term left out (of
 * theta0^10): the terms are positive, and for theta0 under about 1 each
 * is under half the one before, so the series is within 2 next of the
 * ratio.  Cannot fail. */
double mm_pendulum_ratio_series(double theta0, double *next);

#endif
