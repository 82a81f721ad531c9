/* mm_elliptic.h — complete and incomplete elliptic integrals of the first
 * kind and the Jacobi elliptic functions: the closed form of the pendulum.
 *
 *   K(k)      = integral_0^(pi/2) dt / sqrt(1 - k^2 sin^2 t)
 *   F(phi, k) = integral_0^phi    dt / sqrt(1 - k^2 sin^2 t)
 *   am(u, k)  = the phi with F(phi, k) = u;  sn = sin am,  cn = cos am,
 *               dn = sqrt(1 - k^2 sn^2)
 *
 * k is the MODULUS (not the parameter m = k^2).  Near k = 1 the integrals
 * depend on the complementary modulus kc = sqrt(1 - k^2), which cannot be
 * recovered from a rounded k (k = 1 - 1e-13 keeps 3 digits of 1 - k), so
 * every function takes kc from the caller, who can usually compute it
 * directly: the pendulum has k = sin(theta0/2), kc = cos(theta0/2).
 *
 * Two independent algorithms, so that each can check the other:
 *   - the arithmetic-geometric mean (Gauss; Abramowitz & Stegun 17.6 and
 *     16.4): K = pi / (2 AGM(1, kc)), and the Jacobi functions by the
 *     descending AGM sequence; quadratic convergence, about 5 steps at
 *     kc = 0.1, 7 at kc = 1e-16;
 *   - Carlson's symmetric integral R_F by duplication (B. C. Carlson,
 *     "Numerical computation of real or complex elliptic integrals",
 *     Numerical Algorithms 10, 1995): K = R_F(0, kc^2, 1) and
 *     F(phi, k) = sin(phi) R_F(cos^2 phi, 1 - k^2 sin^2 phi, 1).
 * Both are accurate to a few units of round-off (tests/unit/test_elliptic.c
 * measures them against closed forms at singular values and against
 * 30-digit values).
 *
 * Pure functions of their arguments: no state, safe from any thread.
 * Arguments outside the stated domains are programmer errors (assert);
 * callers validate user input first.
 */
#ifndef MM_ELLIPTIC_H
#define MM_ELLIPTIC_H

/* K from the complementary modulus kc in [0, 1] by the AGM:
 * pi / (2 AGM(1, kc)).  kc = 0 (k = 1, the separatrix) gives +INFINITY.
 * Relative error a few eps.  Cannot fail. */
double mm_elliptic_Kc(double kc);

/* K(k) for k in [0, 1]: mm_elliptic_Kc(sqrt((1 - k)(1 + k))).  Loses the
 * digits that k itself lost near 1; prefer mm_elliptic_Kc there.  Cannot
 * fail. */
double mm_elliptic_K(double k);

/* Carlson's R_F(x, y, z) = 1/2 integral_0^inf dt / sqrt((t+x)(t+y)(t+z)),
 * x, y, z >= 0, at most one of them 0.  Relative error a few eps.  Cannot
 * fail. */
double mm_elliptic_RF(double x, double y, double z);

/* F(phi, k) for any real phi, with kc = sqrt(1 - k^2) given (k, kc in
 * [0, 1], k^2 + kc^2 = 1 to rounding), by R_F and the quasi-periodicity
 * F(phi + m pi) = F(phi) + 2 m K.  phi beyond +-pi/2 needs kc > 0 (K
 * finite).  Cannot fail. */
double mm_elliptic_F(double phi, double k, double kc);

/* The Jacobi elliptic functions at u for the modulus pair (k, kc) by the
 * descending AGM (A&S 16.4), after reducing u by the period 2K of am:
 * am(u + 2K) = am(u) + pi.  am is continuous in u (a rotating pendulum
 * needs it unreduced).  kc = 0 gives the limits tanh, sech, sech and the
 * Gudermannian; k = 0 gives sin, cos, 1 and u.  Any of the outputs may be
 * NULL.  Near the quarter periods, where cn and dn are small, they are
 * computed through the complement K - u (A&S 16.8), so they keep their
 * relative accuracy.  Absolute error a few eps times (1 + |u| / K), except
 * near k = 1, where the descending AGM loses up to eps / sqrt(kc) in cn
 * and dn at u ~ K/2 (2e-11 at kc = 1e-12).  Cannot fail. */
void mm_elliptic_jacobi(double u, double k, double kc, double *sn, double *cn, double *dn,
                        double *am);

/* ---- added for the kinematics chapter ------------------------------------------------ */

/* The complete elliptic integral of the second kind,
 *     E(k) = integral_0^(pi/2) sqrt(1 - k^2 sin^2 t) dt,
 * k in [0, 1], by the arithmetic-geometric mean (Abramowitz & Stegun
 * 17.6.3-17.6.4): converges quadratically, to rounding in a handful of
 * steps.  E(0) = pi/2, E(1) = 1 (also for a k that rounds to 1 from a kc
 * far below eps, where E - 1 ~ kc^2 ln(4/kc) / 2 is below rounding).  The length of a trochoid's arch is
 * 4 (R + b) E(2 sqrt(R b) / (R + b)).  Cannot fail. */
double mm_elliptic_E(double k);

#endif
