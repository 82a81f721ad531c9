/* mm_pendulum.h — the plane pendulum theta'' = -(g/L) sin theta solved in
 * closed form (dyn-pendulum, eqs. 3-7 of pendulum.md): the exact motion by
 * Jacobi's elliptic functions, swinging, on the separatrix or over the
 * top; the period against the amplitude, T / T0 = 2 K(sin(theta0 / 2)) / pi,
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

/* ---- the exact motion ---- */

/* The kinds of motion; the fields of the closed form (eqs. 3-7). */
enum { MM_PENDULUM_SWING = 0, MM_PENDULUM_SEPARATRIX = 1, MM_PENDULUM_OVER = 2 };
typedef struct mm_pendulum_motion {
    double L, g, wn;        /* wn = sqrt(g/L) */
    double theta0, omega0;
    int motion;
    double k, kc;           /* SWING: modulus and its complement; OVER: of 1/k */
    double kk;              /* OVER: the energy modulus k > 1 (kc, k then of 1/kk) */
    double u0;              /* argument of the Jacobi functions at t = 0 */
    double sg;              /* OVER: direction of the rotation */
    double T, T0;           /* period (INFINITY on the separatrix), small-angle period */
} mm_pendulum_motion;

/* The closed form of the pendulum of length L under g started at theta0
 * with speed omega0: the motion, its moduli and period.  Cannot fail. */
mm_pendulum_motion mm_pendulum_motion_init(double L, double g, double theta0, double omega0);

/* The exact theta(t), and theta'(t) in *w (eqs. 4 and 6).  Cannot fail. */
double mm_pendulum_exact(const mm_pendulum_motion *p, double t, double *w);

/* sin theta, exactly 0 at theta = pi (the double nearest pi as the
 * parameter reads it: the inverted equilibrium).  Cannot fail. */
double mm_pendulum_sin_top(double th);

/* Energy per unit m L^2: theta'^2 / 2 + wn^2 (1 - cos theta), keeping its
 * digits near the bottom.  Cannot fail. */
double mm_pendulum_energy(const mm_pendulum_motion *p, double th, double w);

/* |dT/dE|, the period's sensitivity to the energy per unit m L^2, by a
 * central difference (~1e-8 relative: it sizes a tolerance).  Cannot fail. */
double mm_pendulum_period_sensitivity(const mm_pendulum_motion *p);

#endif
