/* mm_sdof.h — the closed-form response of one mass on a spring and damper.
 *
 *     m x'' + c x' + k x = F0 cos(omega t) + G0 sin(omega t),
 *     x(0) = x0,  x'(0) = v0
 *
 * (G0 is 0 for a force F0 cos(omega t); a moving support y = Y cos(omega t)
 * pulling through the spring and damper gives F0 = k Y, G0 = -c omega Y.)
 * The reference that the 1-DOF exercises check their time integrators
 * against, so it is written to stay accurate where textbook formulas lose
 * digits:
 *   - one formula for every damping regime: with lambda = omega_n^2 (1 - zeta^2),
 *       x_h(t) = e^(-zeta omega_n t) [ A C(t) + B S(t) ],
 *       C = cos(sqrt(lambda) t),  S = sin(sqrt(lambda) t) / sqrt(lambda)
 *     (cosh and sinh for lambda < 0, C = 1 and S = t at lambda = 0), with S
 *     computed through sinc so that it is continuous through critical
 *     damping: zeta = 1 - 1e-12, 1 and 1 + 1e-12 give the same numbers;
 *   - without damping, the forced part is written as the product
 *       (cos omega t - cos omega_n t) / (omega_n^2 - omega^2)
 *         = t sin(s t) sinc(d t) / s,   s = (omega_n + omega)/2, d = (omega_n - omega)/2,
 *     which stays exact at and near resonance, where it becomes
 *     t sin(omega t) / (2 omega): the growth of undamped resonance; the sine
 *     force's part likewise as
 *       (sin omega t - (omega/omega_n) sin omega_n t) / (omega_n^2 - omega^2)
 *         = (sin(omega_n t)/omega_n - t cos(s t) sinc(d t)) / (2 s);
 *   - the dynamic stiffness k - m omega^2 without cancellation (an exact
 *     product by fma), so that omega = omega_n (1 + 1e-9) keeps its digits.
 * All quantities SI: m [kg], c [N s/m], k [N/m], F0 [N], omega [rad/s].
 */
#ifndef MM_SDOF_H
#define MM_SDOF_H

#include "mm_status.h"

enum mm_sdof_regime {
    MM_SDOF_UNDER = 0,     /* zeta < 1: decaying oscillation */
    MM_SDOF_CRITICAL = 1,  /* zeta = 1 (to 1e-12): fastest return without overshoot */
    MM_SDOF_OVER = 2       /* zeta > 1: creeping return */
};

typedef struct mm_sdof {
    double m, c, k;        /* mass [kg], damping [N s/m], stiffness [N/m] */
    double F0, omega;      /* forcing amplitude [N] and frequency [rad/s]; F0 = 0: free */
    double x0, v0;         /* initial displacement [m] and velocity [m/s] */
    double G0;             /* amplitude of the sine force G0 sin(omega t) [N]; usually 0 */
} mm_sdof;

typedef struct mm_sdof_props {
    double omega_n;        /* natural frequency sqrt(k/m) [rad/s] */
    double zeta;           /* damping ratio c / (2 sqrt(k m)) */
    double omega_d;        /* damped frequency omega_n sqrt(1 - zeta^2) [rad/s]; 0 unless under */
    int regime;            /* enum mm_sdof_regime */
    int resonant;          /* 1: c = 0 and |k - m omega^2| <= 1e-9 k: no steady
                              state is ever reached (X is then reported as 0) */
    double X;              /* steady amplitude |F0 - i G0| / |k - m omega^2 + i c omega| [m];
                              0 if resonant */
    double phase;          /* lag of the steady state behind the force, in [0, pi] [rad]:
                              x = X cos(omega t + psi - phase), psi = atan2(-G0, F0) */
    double magnification;  /* X / (|F0 - i G0|/k), dimensionless (1/|1 - r^2 + 2 i zeta r|) */
    double stiffness_re;   /* k - m omega^2 [N/m], without cancellation */
} mm_sdof_props;

/* "underdamped", "critically damped" or "overdamped"; "" for another value.
 * Cannot fail. */
const char *mm_sdof_regime_name(int regime);

/* Validate: m > 0, k > 0, c >= 0, omega >= 0, all finite.  Returns MM_OK,
 * MM_EVALUE (non-finite; param names the field) or MM_ERANGE. */
int mm_sdof_check(const mm_sdof *s, mm_error *err);

/* The derived properties of s (s must pass mm_sdof_check).  Cannot fail. */
void mm_sdof_props_get(const mm_sdof *s, mm_sdof_props *p);

/* The exact displacement at time t >= 0 [m]; the velocity [m/s] into *v if
 * v is not NULL.  Valid in every regime, also at undamped resonance.
 * s must pass mm_sdof_check.  Cannot fail. */
double mm_sdof_x(const mm_sdof *s, const mm_sdof_props *p, double t, double *v);

/* x[i] = mm_sdof_x(s, p, t[i], NULL) for i < n, the same numbers, with what
 * does not depend on t computed once (a 501-point plot: 40 % less time). */
void mm_sdof_x_many(const mm_sdof *s, const mm_sdof_props *p, int n, const double *t, double *x);

/* The equation as a first-order system for mm_ode (an mm_ode_rhs):
 * y = (x, v), dydt = (v, (F0 cos wt + G0 sin wt - c v - k x) / m),
 * params a const mm_sdof *.  Returns 0. */
int mm_sdof_rhs(double t, const double *y, double *dydt, void *params);

/* The flow of the free equation m x'' + c x' + k x = 0 over a time tau >= 0,
 * in the scaled state u = (x, v/w) (w > 0 a rate, e.g. mm_sdof_fastest_rate,
 * so that both entries are lengths): u(t + tau) = Phi u(t), Phi row-major
 * 2 x 2.  Computed as exp(tau A) of A = [[0, w], [-k/(m w), -c/m]] by
 * scaling and squaring of its Taylor series, using none of the regime
 * formulas of mm_sdof_x: a second route to the same motion.  *squarings
 * (may be NULL) receives the number of squarings (each may add an eps of
 * ||Phi|| to its rounding).  Cannot fail. */
void mm_sdof_flow(const mm_sdof *s, double w, double tau, double Phi[4], int *squarings);

/* The mechanical energy 1/2 m v^2 + 1/2 k x^2 [J].  Cannot fail. */
double mm_sdof_energy(const mm_sdof *s, double x, double v);

/* The largest rate of the motion [1/s]: omega_n, omega (when forced), and
 * the fast decay rate omega_n (zeta + sqrt(zeta^2 - 1)) when overdamped.
 * The time scale of the work of a time integration.  Cannot fail. */
double mm_sdof_fastest_rate(const mm_sdof *s, const mm_sdof_props *p);

/* Spectral radius of one fixed step h of x'' + 2 zeta omega_n x' + omega_n^2 x = 0,
 * wh = omega_n h: RK4's |R(lambda h)| for both roots lambda, and Stormer-Verlet's
 * (damping at the half-step velocity) map of (x, v half), [[1, h], [-h k,
 * 1 - h c - h^2 k]] (per unit mass): trace 2 - 2 zeta wh - wh^2, determinant
 * 1 - 2 zeta wh.  Above 1: the step amplifies, the method is past its limit. */
double mm_sdof_rk4_gain(double wh, double zeta);
double mm_sdof_verlet_gain(double wh, double zeta);

/* ---- the damper's work (chapter 5, vib-sdof-free) ---- */

/* The work the damper takes over [0, t_end], D = integral of c v^2 dt (the
 * energy lost, E(0) - E(t_end), for a free motion), integrated with the
 * motion as a third equation D' = c v^2 by DOP853 at rtol, the absolute
 * tolerance rtol times the smallest scale of x, v and D (the amplitude
 * sqrt(2 E0 / k), omega_n times it, and E0 = E(0)), steps at most one
 * radian of the fastest motion (mm_sdof_fastest_rate).  Needs E0 > 0.
 * Returns MM_OK or mm_ode_run's error with err filled; *D is written. */
int mm_sdof_damper_work(const mm_sdof *s, const mm_sdof_props *p, double t_end, double rtol, double *D,
                        mm_error *err);

#endif
