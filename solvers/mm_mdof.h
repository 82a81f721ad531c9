/* mm_mdof.h — linear systems of several degrees of freedom
 *
 *     M q'' + C q' + K q = F(t),   q(0) = q0,  q'(0) = v0                 (1)
 *
 * their modes, and their motion computed in ways that share no code with
 * a time stepper, so that a step-by-step run can be checked against them:
 *
 *   - real modes K phi = omega^2 M phi (mass-normalised, rigid-body modes
 *     counted), and the complex modes of the state-space form y' = G y,
 *     y = (q, q'), with any damping: natural frequency |lambda| and
 *     damping ratio -Re(lambda)/|lambda| of each;
 *   - the exact motion under F(t) = F cos(omega t) by the transition
 *     matrix e^{G dt} of the state augmented with (cos omega t, sin omega t)
 *     (Moler and Van Loan's "method 3": scaling and squaring of a Pade
 *     approximant).  One formula for every linear system: resonance,
 *     repeated or defective eigenvalues (critical damping), rigid-body
 *     motion, where a superposition of modes fails;
 *   - the exact discrete solution of a Newmark scheme on (1), the powers of
 *     its amplification matrix (mm_newmark_amplification) augmented the
 *     same way: what a run of mm_newmark_solve must reproduce to rounding;
 *   - one mode at a time: the exact response of a modal coordinate
 *         eta'' + c eta' + omega^2 eta = p(t)                               (2)
 *     (c = 2 zeta omega) to a harmonic load switched off at t_off (a step,
 *     a rectangular pulse, a harmonic force) or to a polynomial load, and
 *     its modal superposition q = sum over the retained modes phi_j eta_j
 *     for a system whose damping the real modes uncouple (C = a M + b K,
 *     or modal damping ratios).
 *
 * Conventions: matrices dense, row-major, n x n; a mode matrix Phi holds
 * mode j in column j: Phi[i*ld + j].  SI units (kg, N s/m, N/m, N, m, s).
 * Every function reads only its arguments and allocates its own scratch
 * (freed before it returns): thread-safe.  Errors as mm_status.h, with the
 * parameter named "M", "C", "K", "F", "h", "n", "modes".
 */
#ifndef MM_MDOF_H
#define MM_MDOF_H

#include "mm_newmark.h"
#include "mm_status.h"

#define MM_MDOF_MAX_DOF 2000        /* modes: the dense eigen solver's limit */
#define MM_MDOF_MAX_STATE_DOF 30    /* transition matrices (orders 2n+2, 3n+2) */

/* A mode is rigid (omega = 0) when omega^2 <= MM_MDOF_RIGID_TOL x the
 * largest K_ii / M_ii: far below any elastic mode of a sensible model, far
 * above the rounding (a few eps of that scale) of a true zero. */
#define MM_MDOF_RIGID_TOL 1e-11

typedef struct mm_mdof_system {
    int n;              /* degrees of freedom, 1..MM_MDOF_MAX_DOF */
    const double *M;    /* mass, symmetric positive definite [kg] */
    const double *C;    /* damping, or NULL for none [N s/m] */
    const double *K;    /* stiffness, symmetric positive semidefinite [N/m] */
} mm_mdof_system;

/* ---- modes ---------------------------------------------------------------- */

/* The nmodes lowest modes (1 <= nmodes <= n) of K phi = omega^2 M phi:
 * omega[nmodes] ascending [rad/s], Phi (n x nmodes, or NULL) mass-normalised
 * (Phi^T M Phi = I), in each mode the first component larger than 1e-8 of
 * the largest positive.  Rigid-body modes (see MM_MDOF_RIGID_TOL) come
 * first with omega exactly 0; *n_rigid (may be NULL) counts them.  All
 * eigenpairs by LAPACK dsygvd when nmodes = n, the lowest by dsygvx
 * otherwise.  For a repeated omega the modes span its space; which basis is
 * not specified.  Errors: MM_ERANGE (n, nmodes "modes"; K with a clearly
 * negative eigenvalue: "K"), MM_EVALUE (non-finite, not symmetric),
 * MM_ESINGULAR (M not positive definite: "M"), MM_ENOCONV, MM_ENOMEM. */
int mm_mdof_modes(const mm_mdof_system *s, int nmodes, double *omega, double *Phi,
                  int *n_rigid, mm_error *err);

/* A damped mode: one complex-conjugate pair lambda of the state matrix
 * G = [0 I; -M^-1 K  -M^-1 C], or a pair of real ones (an overdamped mode:
 * the 2m real eigenvalues are paired smallest |lambda| with largest, as the
 * two roots of one overdamped oscillator lie either side of its omega). */
typedef struct mm_mdof_cmode {
    double omega;       /* |lambda| (a real pair: sqrt(l1 l2)) [rad/s] */
    double zeta;        /* -Re(lambda) / |lambda| (a real pair: -(l1 + l2) / (2 omega));
                           0 when omega = 0 */
    double omega_d;     /* |Im(lambda)|, the damped frequency; 0 for a real pair [rad/s] */
} mm_mdof_cmode;

/* The n damped modes of s (n <= MM_MDOF_MAX_STATE_DOF), ascending in omega,
 * from the 2n eigenvalues of G (LAPACK dgeev).  Without damping they are
 * the real modes' omega with zeta = 0; with C = a M + b K, zeta_j =
 * a / (2 omega_j) + b omega_j / 2.  Errors: MM_ERANGE (n), MM_EVALUE,
 * MM_ESINGULAR (M singular), MM_ENOCONV, MM_ENOMEM. */
int mm_mdof_complex_modes(const mm_mdof_system *s, mm_mdof_cmode *modes, mm_error *err);

/* The chain wall-k1-m1-k2-m2-k3-wall in closed form: omega[0] <= omega[1]
 * [rad/s] and the mass-normalised modes phi (2 x 2, mode j in column j:
 * phi[i*2 + j], first component >= 0, the second > 0 where the first is
 * 0), from the symmetric matrix M^-1/2 K M^-1/2 = [a b; b d]:
 *     lambda_2 = (a + d)/2 + hypot((a - d)/2, b),
 *     lambda_1 = (k1 k2 + k1 k3 + k2 k3) / (m1 m2 lambda_2)
 * (no cancellation: every term of the determinant is >= 0), and the
 * modes from the row of [a - lambda_2, b; b, d - lambda_2] that does not
 * cancel, every component to a few eps of itself.  A repeated pair
 * (k2 = 0, k1/m1 = k3/m2) gives the uncoupled modes.  m1, m2 > 0,
 * k1, k2, k3 >= 0.  Cannot fail. */
void mm_mdof_two_dof(double m1, double m2, double k1, double k2, double k3, double *omega,
                     double *phi);

/* ---- exact motion by transition matrices ------------------------------------ */

typedef struct mm_mdof_motion {
    const double *q0;   /* initial displacements, n, or NULL for 0 [m] */
    const double *v0;   /* initial velocities, n, or NULL for 0 [m/s] */
    const double *F;    /* amplitudes of F cos(omega t), n, or NULL for none [N] */
    double omega;       /* forcing frequency >= 0 (0: a constant F) [rad/s] */
} mm_mdof_motion;

/* The exact q(t) (and v(t) = q'(t) when v is not NULL) of (1) under mo at
 * the nt times t_i = k[i] h (k nondecreasing, k[0] >= 0), into q[i*n + j]:
 * the state (q, q'/w, s cos omega t, s sin omega t) (w = sqrt(max K_ii/M_ii),
 * s = 1, or the power of 2 above max|M^-1 F| / w^2 where that is > 1, for
 * balance: no column of G larger than the mechanics' w) is carried from
 * sample to sample by e^{G k h}, computed once for each different gap
 * k[i] - k[i-1].  Rounding grows with the number of samples, not of
 * steps: about nt eps relative to the motion's size (times the
 * conditioning of the modes' energy, for a stiff system).
 * n <= MM_MDOF_MAX_STATE_DOF.  Errors: MM_ERANGE (n, h <= 0, nt < 1, k
 * decreasing), MM_EVALUE, MM_ESINGULAR (M singular), MM_ENONFINITE (the
 * motion overflows), MM_ENOMEM. */
int mm_mdof_exact(const mm_mdof_system *s, const mm_mdof_motion *mo, double h, int nt,
                  const long *k, double *q, double *v, mm_error *err);

/* The exact discrete solution of o's scheme (step o->h) on (1) under mo,
 * at the steps k[i] (nondecreasing): the state (q, q', q'', cos omega t_k,
 * sin omega t_k) carried by the powers of the amplification matrix
 * (mm_newmark_amplification) augmented with the rotation of the load,
 * each gap's power by repeated squaring.  Starts like mm_newmark_solve:
 * q''(0) from (1).  A run of mm_newmark_solve with a force F cos(omega t)
 * gives these numbers to rounding (about nt log2(gap) eps, relative).
 * n <= MM_MDOF_MAX_STATE_DOF.  Errors: as mm_mdof_exact, and those of
 * mm_newmark_amplification. */
int mm_mdof_newmark_exact(const mm_mdof_system *s, const mm_mdof_motion *mo,
                          const mm_newmark_options *o, int nt, const long *k, double *q,
                          double *v, mm_error *err);

/* The motion of (1) under a general force F(t, q, q') (mm_newmark's
 * force callback: a nonlinear spring, say) by DOP853 at relative tolerance
 * rtol (absolute rtol x scale [m]), dense output at the nt times t
 * (nondecreasing, from 0) into q[i*n + j]: a reference with an error of a
 * very different kind from a Newmark scheme's, where no exact motion is
 * known.  *evals (may be NULL) receives the calls of F.  n <=
 * MM_MDOF_MAX_STATE_DOF.  Errors: MM_ERANGE (n), MM_ESINGULAR (M singular),
 * MM_ENOCONV (more than 1e6 steps), those of F, MM_ENOMEM. */
int mm_mdof_ode(const mm_mdof_system *s, mm_newmark_force_fn force, void *params, const double *q0,
                const double *v0, int nt, const double *t, double rtol, double scale, double *q,
                long *evals, mm_error *err);

/* ---- one modal coordinate, eq. (2) -------------------------------------------- */

/* A load p(t) = p cos(Omega t) for 0 <= t < t_off, 0 after: Omega = 0 is a
 * step of height p (t_off = INFINITY) or a rectangular pulse (t_off its
 * duration). */
typedef struct mm_mdof_pulse {
    double p;           /* amplitude [N/sqrt(kg) for a mass-normalised mode] */
    double Omega;       /* >= 0 [rad/s] */
    double t_off;       /* > 0, or INFINITY */
} mm_mdof_pulse;

/* eta(t) of (2) from eta(0) = e0, eta'(0) = ed0 under the pulse, exact in
 * every regime (closed form of mm_sdof for omega > 0; the polynomial and
 * exponential solutions of a rigid-body mode, omega = 0, with c >= 0);
 * *etad (may be NULL) receives eta'(t).  t >= 0, omega >= 0, c >= 0, all
 * finite.  Cannot fail. */
double mm_mdof_sdof_pulse(double omega, double c, double e0, double ed0,
                          const mm_mdof_pulse *load, double t, double *etad);

/* Advance (eta, eta') of (2) exactly over a time dt >= 0 under the
 * polynomial load p(tau) = a[0] + a[1] tau + a[2] tau^2 + a[3] tau^3
 * (tau from 0 at the start of the interval): the free motion plus the
 * load's response from rest, sum_k a_k k! dt^{k+1} (phi_{k+1}(r1 dt) -
 * phi_{k+1}(r2 dt)) / (r1 - r2) with r1, r2 the roots of r^2 + c r +
 * omega^2 and phi_j the functions of exponential integrators: to a few eps
 * however stiff (c >> omega) or fast (omega dt << 1) the mode; within 10 %
 * of critical damping, where the roots meet, by the exponential of the
 * augmented 6 x 6 system.  omega >= 0, c >= 0.  Cannot fail. */
void mm_mdof_sdof_poly(double omega, double c, const double a[4], double dt, double *eta,
                       double *etad);

/* Modal superposition, dense: q(t_i) = sum over the m retained modes of
 * Phi_j eta_j(t_i), with eta_j from mm_mdof_sdof_pulse under the load
 * F g(t) (g: pulse with p = 1): modal load phi_j^T F, initial values
 * phi_j^T M q0 and phi_j^T M v0 (mass-normalised modes).  omega[m] the
 * modes' frequencies, c[m] (or NULL: undamped) their 2 zeta_j omega_j;
 * Phi n x ld, mode j in column j (j < m <= ld).  q0, v0, F may be NULL.
 * q[i*n + r] for the nt times t.  Errors: MM_ERANGE (m outside 1..ld),
 * MM_ENOMEM. */
int mm_mdof_modal_response(int n, int m, const double *omega, const double *c,
                           const double *Phi, int ld, const double *M, const double *q0,
                           const double *v0, const double *F, const mm_mdof_pulse *g,
                           int nt, const double *t, double *q, mm_error *err);

/* ---- a chain of n equal masses m joined by equal springs k (chapter 5, vibrations) ----
 * wall-k-m-k-m-...-m-k-wall (fixed-fixed), or without the last spring
 * (fixed-free: the last mass free). */

/* The angle theta_j of mode j (0-based) of the chain:
 *   fixed-fixed: theta_j = (j + 1) pi / (2 (n + 1)),
 *   fixed-free:  theta_j = (2 j + 1) pi / (2 (2 n + 1)),
 * so that omega_j = 2 sqrt(k/m) sin(theta_j) and the mode is the sampled
 * sine phi_i = sin(2 (i + 1) theta_j), i = 0 .. n-1 (L. Brillouin, Wave
 * Propagation in Periodic Structures, 1946, ch. 1).  Cannot fail. */
double mm_mdof_chain_theta(int n, int j, int free_end);

/* The chain's mass and stiffness matrices, dense (n x n, row-major, every
 * entry written): M = m I, K tridiagonal with 2k on the diagonal (k in the
 * last place when free_end), -k beside it.  Cannot fail. */
void mm_mdof_chain_matrices(int n, double m, double k, int free_end, double *M, double *K);

/* The same in band storage with one off-diagonal (kd = 1,
 * MM_LINALG_BAND_INDEX of mm_linalg.h, as mm_linalg_sbgv_first takes it):
 * Kb[2 i] the diagonal entry of row i, Kb[2 i + 1] the one to its right
 * (0 in the last row).  Cannot fail. */
void mm_mdof_chain_band(int n, double m, double k, int free_end, double *Mb, double *Kb);

/* The static deflection that the first m modes miss under a point load Fp
 * on coordinate p (modal truncation, chapter 5):
 *   r = K^-1 F - sum_{j < m} phi_j phi_j^T F / omega_j^2,   F = Fp e_p,
 * with Phi (n x n, row-major, column j mode j) mass-normalised and omega
 * its frequencies (all > 0: K regular).  r has n values.  Returns MM_OK or
 * mm_linalg_solve's error with err filled. */
int mm_mdof_static_residual(int n, int m, const double *K, const double *omega, const double *Phi, int p,
                            double Fp, double *r, mm_error *err);

/* The chain's modes: every one (nev = 0) by LAPACK's dsygvd on the dense
 * matrices, lambda n values and V n x n; the lowest nev (1 <= nev <= n,
 * n >= 2) by mm_linalg_sbgv_first on the band storage (dsbgvx and inverse
 * iteration, no n x n matrix), lambda nev values and V n x nev.  lambda =
 * omega^2 ascending, V row-major with the mass-normalised mode j in column
 * j.  Returns MM_OK or the linalg error (MM_ENOMEM) with err filled. */
int mm_mdof_chain_modes(int n, double m, double k, int free_end, int nev, double *lambda, double *V,
                        mm_error *err);

#endif
