/* mm_multibody.h — equations of motion of the small multibody systems of
 * chapter 4: the double pendulum, the two-link robot arm and the
 * slider-crank mechanism.
 *
 * Each system is a plain struct of its physical constants; the functions
 * evaluate its equations (mass matrix, generalised forces, constraints,
 * energy) at a state.  They are pure: no allocation, no global state, safe
 * from any thread.  The right-hand sides have the mm_ode_rhs signature
 * (params = a pointer to the system struct) so they plug into mm_ode and
 * mm_symplectic.  Arguments are the caller's responsibility (validated
 * before: positive masses and lengths); none of the functions can fail
 * except where an int return says so.
 *
 * Conventions: SI units, angles in radians, counter-clockwise positive;
 * x to the right, y up.
 */
#ifndef MM_MULTIBODY_H
#define MM_MULTIBODY_H

#include "mm_status.h"

/* ==== the double pendulum ====================================================
 * Two point masses on massless rods, hanging from a fixed pivot at the
 * origin; theta1, theta2 measured from the downward vertical.  With
 * d = theta1 - theta2, the Lagrangian L = T - V has
 *   T = (m1+m2) l1^2 w1^2 / 2 + m2 l2^2 w2^2 / 2 + m2 l1 l2 w1 w2 cos d
 *   V = -(m1+m2) g l1 cos theta1 - m2 g l2 cos theta2
 * and the momenta p = M(d) w with
 *   M = [(m1+m2) l1^2, m2 l1 l2 cos d; m2 l1 l2 cos d, m2 l2^2]. */
typedef struct mm_dpend {
    double m1, m2;    /* bob masses [kg] */
    double l1, l2;    /* rod lengths [m] */
    double g;         /* gravity [m/s^2] */
} mm_dpend;

/* Lagrange's equations solved for the accelerations: y = (theta1, theta2,
 * w1, w2), dy = (w1, w2, theta1'', theta2'').  params: mm_dpend.  Returns 0. */
int mm_dpend_rhs_lagrange(double t, const double *y, double *dy, void *params);

/* Hamilton's equations in the canonical coordinates y = (theta1, theta2,
 * p1, p2): dy = (dH/dp1, dH/dp2, -dH/dtheta1, -dH/dtheta2).  params:
 * mm_dpend.  Returns 0. */
int mm_dpend_rhs_hamilton(double t, const double *y, double *dy, void *params);

/* (theta, w) -> (theta, p) and back.  Cannot fail. */
void mm_dpend_to_momenta(const mm_dpend *s, const double *yw, double *yp);
void mm_dpend_to_velocities(const mm_dpend *s, const double *yp, double *yw);

/* Total energy T + V [J] at (theta1, theta2, w1, w2); *scale (may be NULL)
 * receives the size of the largest term summed, for round-off bounds. */
double mm_dpend_energy(const mm_dpend *s, const double *yw, double *scale);

/* The small oscillation about the hanging position: the two natural
 * frequencies [rad/s] of the linearised equations, slow <= fast, from the
 * closed-form roots of det(K - w^2 M) = 0 (the slow one written without
 * cancellation).  Cannot fail. */
void mm_dpend_linear(const mm_dpend *s, double *w_slow, double *w_fast);

/* The bob positions [m]: (x1, y1), (x2, y2).  Cannot fail. */
void mm_dpend_points(const mm_dpend *s, double theta1, double theta2, double *x1, double *y1,
                     double *x2, double *y2);

/* ==== the two-link robot arm =================================================
 * Two uniform slender rods in a vertical plane, the shoulder at the origin;
 * q1 from the +x axis counter-clockwise, q2 of link 2 relative to link 1;
 * gravity g along -y.  The equations of motion tau = M(q) q'' + c(q, q') +
 * G(q) with
 *   M11 = m1 l1^2/3 + m2 (l1^2 + l2^2/3 + l1 l2 cos q2)
 *   M12 = m2 (l2^2/3 + l1 l2 cos q2 / 2),   M22 = m2 l2^2 / 3
 *   c1  = -m2 l1 l2 sin q2 (q1' q2' + q2'^2 / 2),  c2 = m2 l1 l2 sin q2 q1'^2 / 2
 *   G1  = (m1/2 + m2) g l1 cos q1 + m2 g l2/2 cos(q1 + q2),  G2 = m2 g l2/2 cos(q1 + q2) */
typedef struct mm_robot2 {
    double l1, l2;    /* link lengths [m] */
    double m1, m2;    /* link masses [kg] */
    double g;         /* gravity [m/s^2], may be 0 */
} mm_robot2;

/* M(q2) row-major 2 x 2 [kg m^2].  Cannot fail. */
void mm_robot2_mass(const mm_robot2 *s, double q2, double *M);

/* Joint torques [N m] that give the motion (q, q', q'') (inverse dynamics).
 * Cannot fail. */
void mm_robot2_inverse(const mm_robot2 *s, const double *q, const double *qd, const double *qdd,
                       double *tau);

/* Joint accelerations from the torques (forward dynamics): M q'' = tau - c - G,
 * solved in closed form (det M = m2 l1^2 l2^2 (m1/9 + m2 (1/3 - cos^2 q2 / 4))
 * > 0 in every configuration).  Cannot fail. */
void mm_robot2_forward(const mm_robot2 *s, const double *q, const double *qd, const double *tau,
                       double *qdd);

/* Kinetic and potential energy [J] (potential 0 at y = 0).  Cannot fail. */
void mm_robot2_energy(const mm_robot2 *s, const double *q, const double *qd, double *T, double *V);

/* Joint positions: x[0..2], y[0..2] = shoulder, elbow, tip [m].  Cannot fail. */
void mm_robot2_points(const mm_robot2 *s, const double *q, double *x, double *y);

/* ==== the slider-crank mechanism =============================================
 * Crank O-A of radius r turning about O = (0, 0), its centre of mass on the
 * axis (a flywheel: J_crank about O); connecting rod A-B of length l,
 * centre of mass at mid-length, J_rod about it; piston at B = (x3, 0)
 * sliding on the x axis.  Absolute coordinates
 *   q = (phi1, x2, y2, phi2, x3)
 * (crank angle, rod centre, rod angle, piston position) tied by four
 * constraints Phi(q) = 0 (the pins at A and B):
 *   x2 - l/2 cos phi2 - r cos phi1 = 0,   y2 - l/2 sin phi2 - r sin phi1 = 0
 *   x2 + l/2 cos phi2 - x3 = 0,           y2 + l/2 sin phi2 = 0
 * and the equations of motion with Lagrange multipliers
 *   M q'' + Phi_q^T lambda = Q,   M = diag(J_crank, m_rod, m_rod, J_rod, m_piston),
 *   Q = (torque, 0, 0, 0, 0).
 * lambda are the joint forces: the crank pin pushes the rod with
 * (-lambda1, -lambda2), the piston pushes the rod with (-lambda3, -lambda4),
 * the main bearing holds the crank with (-lambda1, -lambda2) (the crank's
 * centre of mass does not move), and the guide holds the piston with
 * N = -lambda4 along y. */
/* (mm_sc_model: the slider-crank with its masses and torque; mm_linkage.h
 * has mm_slider_crank, its geometry alone) */
typedef struct mm_sc_model {
    double r, l;            /* crank radius, rod length [m], r < l */
    double J_crank;         /* crank and flywheel about O [kg m^2] */
    double m_rod, J_rod;    /* rod mass [kg], about its centre [kg m^2] */
    double m_piston;        /* [kg] */
    double torque;          /* constant driving torque on the crank [N m] */
} mm_sc_model;

#define MM_SC_NQ 5          /* coordinates */
#define MM_SC_NC 4          /* constraints */

/* The constraint residuals Phi(q) [m] and the velocity residuals Phi_q q'
 * [m/s].  Cannot fail. */
void mm_sc_constraints(const mm_sc_model *s, const double *q, const double *qd, double *Phi,
                       double *Phid);

/* The consistent configuration at crank angle phi1 and crank speed w
 * (closed form: phi2 = -asin(r sin phi1 / l), x3 = r cos phi1 + l cos phi2):
 * q and qd (5 values each).  Cannot fail. */
void mm_sc_assemble(const mm_sc_model *s, double phi1, double w, double *q, double *qd);

/* Accelerations and joint forces at (q, qd): solves M q'' + Phi_q^T lambda = Q
 * with Phi_q q'' = gamma - 2 alpha Phi' - beta^2 Phi (Baumgarte's
 * stabilisation; alpha = beta = 0: the plain index-1 equations) in the
 * null space of Phi_q: the crank angle independent, the other four from
 * Phi_v (lengths only, so any mass ratio is accurate to round-off).  qdd (5),
 * lambda (4, may be NULL).  Returns MM_OK, or MM_ESINGULAR when the
 * constraints are dependent (the rod vertical: r >= l). */
int mm_sc_accel(const mm_sc_model *s, const double *q, const double *qd, double alpha,
                double beta, double *qdd, double *lambda);

/* Kinetic energy [J] at (q, qd).  Cannot fail. */
double mm_sc_kinetic(const mm_sc_model *s, const double *q, const double *qd);

/* The effective inertia of the whole mechanism referred to the crank,
 * J(phi) = 2 T / w^2 [kg m^2], and dJ/dphi (may be NULL), in closed form.
 * Cannot fail. */
double mm_sc_inertia(const mm_sc_model *s, double phi, double *dJ);

/* Right-hand sides for mm_ode, params = mm_sc_system:
 *   mm_sc_rhs_baumgarte: y = (q, qd), 10 values, the Baumgarte-stabilised
 *     index-1 equations in all five coordinates;
 *   mm_sc_rhs_reduced: y = (phi1, w), 2 values: coordinate partitioning,
 *     phi1 independent, the dependent coordinates and velocities recovered
 *     from the constraints at every evaluation (mm_sc_assemble), then
 *     phi1'' from mm_sc_accel.
 * Return 0, or MM_ESINGULAR (see mm_sc_accel). */
typedef struct mm_sc_system {
    mm_sc_model sc;
    double alpha, beta;     /* Baumgarte's constants [1/s] */
} mm_sc_system;

int mm_sc_rhs_baumgarte(double t, const double *y, double *dy, void *params);
int mm_sc_rhs_reduced(double t, const double *y, double *dy, void *params);

/* The energy error one DOP853 step at relative tolerance rtol (atol = rtol)
 * may make at state y = (theta1, theta2, w1, w2): the gradient of E times
 * the per-component error allowance, sum_j |dE/dy_j| rtol (1 + |y_j|) [J].
 * Cannot fail. */
double mm_dpend_energy_allowance(const mm_dpend *s, const double *y, double rtol);

/* The exponential regime of a separation d(t) sampled on x[0..n) (from
 * 1e3 d0, past the start's transient, to 1e-3, before saturation) and the
 * least-squares line ln d = a0 + lam t over it, se the slope's standard
 * error.  Returns 1 with all set, or 0 when there is no regime of more than
 * 8 points to fit (only *i_lo, *i_hi set; -1 when not reached). */
int mm_growth_fit(const double *x, const double *d, int n, double d0, int *i_lo, int *i_hi, double *lam,
                  double *a0, double *se);

/* ---- chapter 4 (dyn-double-pendulum): Lagrange's equations against Hamilton's ---- */

/* At the state y = (theta1, theta2, w1, w2): dp/dt from Hamilton's
 * equations (mm_dpend_rhs_hamilton at the momenta of y) against d(M w)/dt
 * = M w' + M' w from Lagrange's (mm_dpend_rhs_lagrange), and Hamilton's
 * dtheta/dt against w (times trace M, to be a momentum rate too).  Returns
 * the larger difference; *scale receives the largest term summed times
 * cond M ~ trace^2 / det (the Hamiltonian side goes through M^-1): the two
 * agree to a few eps of it.  Cannot fail. */
double mm_dpend_lh_residual(const mm_dpend *s, const double *y, double *scale);

/* ---- chapter 4 (dyn-slider-crank): the joint forces against Newton's law ---------- */

/* At a state of the slider-crank with accelerations qdd and multipliers lam
 * (mm_sc_accel): the bearing force on the crank (-lam1, -lam2) and the
 * guide force on the piston N = -lam4 accelerate the rod's and the piston's
 * centres of mass (m_rod (x2'', y2'') + m_piston (x3'', 0)).  Returns the
 * size of the difference [N]; *scale receives the sum of the forces and
 * the inertia forces.  Cannot fail. */
double mm_sc_momentum_residual(const mm_sc_model *s, const double *qdd, const double *lam, double *scale);

/* The largest constraint residual |Phi_k(q)| [m] (mm_sc_constraints).
 * Cannot fail. */
double mm_sc_drift(const mm_sc_model *s, const double *q);

#endif
