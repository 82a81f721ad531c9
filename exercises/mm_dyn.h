/* mm_dyn.h — helpers of the chapter-4 (dynamics) exercises that are not
 * numerics: drawing coordinates rounded for the animation, and a floor
 * for values plotted on a log axis.
 */
#ifndef MM_DYN_H
#define MM_DYN_H

#include "mm_exercise.h"
#include "mm_multibody.h"
#include "mm_ode.h"
#include "mm_pendulum.h"
#include "mm_symplectic.h"

/* The decimal quantum of an animation drawn to the size `size` [m]: the
 * power of ten at or below size * 1e-5 (a thousandth of a pixel on a
 * 1000-pixel canvas).  Cannot fail. */
double mm_dyn_quantum(double size);

/* x rounded to a multiple of the decimal quantum q (a power of ten), so
 * that it prints short ("0.12345" rather than 17 digits): a drawing needs
 * no more.  Cannot fail. */
double mm_dyn_round(double x, double q);

/* Round every coordinate of shape s to q.  Cannot fail. */
void mm_dyn_round_shape(mm_shape *s, double q);

/* The frame times of an animation: nf frames evenly over [0, t_show],
 * never past it (the last is t_show exactly, so an integration to t_show
 * reaches every frame).  Cannot fail. */
void mm_dyn_frame_times(mm_anim *a, double t_show);

/* ---- dyn-robot-2link: a point-to-point move of the two-link arm -------------- */

/* The move: joint angles from q0 to q0 + dq in time T by the quintic
 * (quintic = 1) or cubic time law (robot_2link.md, eq. 2 and 3). */
typedef struct mm_dyn_plan {
    mm_robot2 arm;
    int quintic;
    double q0[2], dq[2], T;
    double t_left;          /* forward simulation: when it left the path by 2 pi (or -1) */
} mm_dyn_plan;

/* The planned q, q', q'' at time t (clamped to [0, T]).  Cannot fail. */
void mm_dyn_plan_at(const mm_dyn_plan *p, double t, double *q, double *qd, double *qdd);

/* The joint torques that drive the planned move at time t (inverse
 * dynamics, eq. 1).  Cannot fail. */
void mm_dyn_plan_torque(const mm_dyn_plan *p, double t, double *tau);

/* The open-loop forward dynamics under the planned torques (eq. 5), an
 * mm_ode right-hand side: y = (q1, q2, q1', q2'), ctx a mm_dyn_plan.  While
 * p->t_left < 0, leaving the path by 2 pi records the time there and
 * returns MM_ENOCONV (the integration stops). */
int mm_dyn_plan_forward_rhs(double t, const double *y, double *dy, void *ctx);

/* A cheap upper estimate of the exponent by which the open-loop arm
 * amplifies small errors over the move.  Cannot fail. */
double mm_dyn_plan_growth(const mm_dyn_plan *p);

/* The variational equations Phi' = J(t) Phi along the planned path, an
 * mm_ode right-hand side of 16 values (Phi row-major); set p->t_left >= 0. */
int mm_dyn_plan_variational_rhs(double t, const double *y, double *dy, void *ctx);

/* The work of the motors over the move, int tau . q' dt, by 5-point
 * Gauss-Legendre on 64 panels (the integrand is a polynomial in t times
 * sines and cosines: far below round-off), and into *wabs the same of
 * |tau_1 q1'| + |tau_2 q2'| (the scale of its rounding).  Cannot fail. */
double mm_dyn_plan_work(const mm_dyn_plan *p, double *wabs);

/* How much the open-loop arm amplifies small errors over the move: into *A
 * the largest norm ||Phi(t)||_inf (max row sum, at least 1) of the
 * fundamental matrix of the variational equations (DOP853 at 1e-6) on a
 * grid of 33 times (an estimate: an error made at t0 > 0 grows by Phi(t)
 * Phi(t0)^-1, which is smaller while errors only grow).  Returns MM_OK,
 * MM_ENOMEM or the integrator's code with err filled. */
int mm_dyn_plan_amplification(const mm_dyn_plan *p, mm_result *res, double *A, mm_error *err);

/* When the arm is stretched (q2 = 0) on a move whose q2 passes 0 (it moves
 * monotonically from q2_0 to q2_1): *t_s by Brent on q2(t) to 1e-14 T, and
 * its bound *err_ts (the final bracket, or when an exact zero of the
 * computed q2 ended Brent early, the rounding of q2 over its speed there);
 * at an end where q2 is exactly 0, that end with *err_ts = 0 (exact).
 * Returns MM_OK or mm_roots_brent's code with err filled. */
int mm_dyn_plan_stretched(const mm_dyn_plan *p, double *t_s, double *err_ts, mm_error *err);

/* dyn-robot-2link's animation: the arm over the planned move (24 frames a
 * fifth of T), its base, and the tip's planned path.  Returns MM_OK or
 * MM_ENOMEM. */
int mm_dyn_plan_animate(const mm_dyn_plan *p, mm_result *res);

/* The largest |tau_j| over the move, its time *t_at and an error estimate
 * *err of the value.  Cannot fail. */
double mm_dyn_plan_peak(const mm_dyn_plan *p, int j, double *t_at, double *err);

/* ---- dyn-slider-crank and reading extremes off samples ---------------------- */

/* The extremes *Jmin, *Jmax of the slider-crank's effective inertia J(phi)
 * (slider_crank.md, eq. 5) over a turn.  Cannot fail. */
void mm_dyn_sc_inertia_range(const mm_sc_model *s, double *Jmin, double *Jmax);

/* An estimate of the error of v[i] as the extreme of the samples v[0..n-1]:
 * how far the parabola through v[i] and its neighbours moves it (0 at an
 * end).  Cannot fail. */
double mm_dyn_extreme_error(const double *v, int n, int i);

/* How far the slider-crank's energy at the state (q, qd) can lie from its
 * value at the reference state (qr, qdr): the kinetic energy minus the
 * torque's work, bounded body by body; *bJ the same for J(phi) w^2 / 2
 * minus the work in the crank's (phi, w).  Both exact bounds at any
 * distance, plus what an error tol_ref (absolute and relative) of the
 * reference's crank angle and speed can make (to first order).  Cannot
 * fail. */
double mm_dyn_sc_energy_bound(const mm_sc_model *s, const double *q, const double *qd, const double *qr,
                              const double *qdr, double tol_ref, double *bJ);

/* ---- dyn-pendulum: its exact motion is mm_pendulum's (solvers/) -------------- */

/* The period of p measured from an integration of f (its equation of
 * motion, ctx p) by DOP853 at rtol with steps up to h_max, where it is well
 * conditioned: the times of two successive passages through the bottom
 * (theta = 0 mod 2 pi, where |theta'| is largest), each located by one
 * Newton step from the integrated state at the closed form's prediction;
 * half a period apart for a swing, a whole one for a turn over the top.
 * *dE receives the larger energy error of the two states.  Not on the
 * separatrix.  Returns MM_OK or the integrator's code with err filled. */
int mm_dyn_pend_measure_period(const mm_pendulum_motion *p, mm_ode_rhs f, double rtol, double h_max, mm_result *res,
                               double *Tm, double *dE, mm_error *err);

/* The period against the amplitude, eq. (5): T / T0 (mm_pendulum) as the
 * series `curve` and its first correction 1 + theta0^2 / 16 as `series`,
 * 200 amplitudes up to 3.1 rad (the ratio is 4.5 there).  Returns MM_OK or
 * MM_ENOMEM. */
int mm_dyn_pend_period_curve(mm_result *res, int curve, int series);

/* dyn-pendulum's animation: the pendulum over the frames of t_end (24 a
 * period, the shorter of T and T0), each frame by the closed form, with the
 * bob's path from the n integrated angles th at the times t (at most 360
 * points).  Returns MM_OK or MM_ENOMEM. */
int mm_dyn_pend_animate(const mm_pendulum_motion *p, double t_end, int n, const double *t, const double *th,
                        mm_result *res);

/* ---- dyn-double-pendulum ------------------------------------------------------ */

/* The fastest rate of the double pendulum's motion from y0 [1/s]: the fast
 * small-oscillation frequency, or the largest angular speed its energy
 * allows.  Cannot fail. */
double mm_dyn_dpend_rate(const mm_dpend *s, const double *y0);

/* Lagrange's equations (double_pendulum.md, eq. 3) integrated by method m
 * at tolerance rtol from y0 over [0, t_end]; y receives the n x 4 states at
 * t[0..n-1], *r the run's statistics.  Errors of mm_ode_solve. */
int mm_dyn_dpend_run(const mm_dpend *s, const double *y0, double t_end, int n, const double *t,
                     mm_ode_method m, double rtol, double *y, mm_ode_result *r, mm_error *err);

/* The distance of two states, angles in radians and angular velocities in
 * units of wf.  Cannot fail. */
double mm_dyn_dpend_distance(const double *a, const double *b, double wf);

/* The separation of two runs ya, yb of the double pendulum (n states on
 * the times x): d[i] by mm_dyn_dpend_distance, and plot[i] the same
 * floored at eps d0 (a log axis).  Returns the time the two are 1e-3 apart
 * (log-linear between the grid points; x[0] when they start apart by more),
 * or -1 when they never are.
 * Cannot fail. */
double mm_dyn_dpend_separation(const double *ya, const double *yb, int n, const double *x, double wf, double d0,
                               double *d, double *plot);

/* dyn-double-pendulum's reference: Lagrange's equations from y0 by DOP853
 * at rtol (atol rtol, at most 2e6 steps) over [0, t_end], the n states at
 * the times t into y (n x 4), the run's statistics into *r; watched at the
 * end of every accepted step: *drift the largest energy error |E - E0| /
 * Es there, *allow the largest allowance of eq. (7)
 * (mm_dpend_energy_allowance) over Es.  The grid points between the steps
 * are DOP853's dense output, a 7th-order interpolant whose error the step
 * control does not see (on a short fast run, 23 steps and 746 points, its
 * energy error was 10 times that of the steps themselves): the energy is
 * judged at the steps.  Returns MM_OK or mm_ode_run's code with err
 * filled. */
int mm_dyn_dpend_reference(const mm_dpend *s, const double *y0, double t_end, double rtol, int n, const double *t,
                           double E0, double Es, double *y, mm_ode_result *r, double *drift, double *allow,
                           mm_error *err);

/* dyn-double-pendulum's symplectic run: Hamilton's equations in (theta, p)
 * from y0 = (theta1, theta2, w1, w2) by method m with step h over [0, t_end]
 * (at most max_steps steps; the Newton scale of p from the fastest rate),
 * the energy error |E - E0| / Es at every step: its largest over the first
 * and the second half of the run into *max_first, *max_second, how much
 * faster the second half went at its fastest than the first, the ratio of
 * the largest |theta1'| + |theta2'|, into *faster, and every
 * stride-th into the series out (at most n points, floored at eps for a
 * log axis).  Reports the run's statistics on res.  Returns MM_OK,
 * MM_ENOMEM or mm_symp_solve's code with err filled. */
int mm_dyn_dpend_symplectic(const mm_dpend *s, const double *y0, double t_end, double h, mm_symp_method m,
                            long max_steps, double E0, double Es, int out, int n, double *max_first,
                            double *max_second, double *faster, mm_result *res, mm_error *err);

/* dyn-double-pendulum's animation: the pendulum from y0 and its twin from
 * y0b (DOP853 at rtol), the lower bob's path, over about one slow period
 * or 120 frames at most. */
int mm_dyn_dpend_animate(const mm_dpend *s, double t_end, const double *y0, const double *y0b, double rtol,
                         mm_result *res, mm_error *err);

/* dyn-slider-crank's state at one grid point y as (q, qd), whatever the
 * method: the five coordinates themselves (Baumgarte), or assembled from
 * the crank's angle and speed (partitioning).  Cannot fail. */
void mm_dyn_sc_state(const mm_sc_model *s, int partition, const double *y, double *q, double *qd);

/* dyn-slider-crank's second and third runs of the reduced equation from
 * (0, w0) on the n times x, for the errors of what the run (options opt,
 * result r) shows: *yref the reference, at a tolerance 1000 times tighter
 * than the run's (between 1e-13 and 1e-12: its own error negligible), and
 * *yalt a run at half the run's tolerance (another step sequence: a
 * rounding-level change moves DOP853's step decisions, so the run's
 * distance from the reference is one sample of its error, and this run,
 * with an error about 0.55 times the run's, doubled, a second), each n x 2
 * from res's arena; when the third run fails (a budget of 4 times the
 * run's steps and 1000 ends one that went astray), the reference stands in
 * for it.  *tol_ref receives the reference's error: its tolerance at every
 * step it took, added up.  Returns MM_OK, MM_ENOMEM or the reference run's
 * code with err filled. */
int mm_dyn_sc_reference_runs(mm_sc_system *sys, double w0, double t_end, int n, const double *x,
                             const mm_ode_options *opt, const mm_ode_result *r, double **yref, double **yalt,
                             double *tol_ref, mm_result *res, mm_error *err);

/* What dyn-slider-crank's run (ny values a state, n states y) shows,
 * against the reference and third runs (yref, yalt: crank angle and speed,
 * mm_dyn_sc_reference_runs), state by state: */
typedef struct mm_dyn_sc_cmp {
    double ra, rb, rn;      /* the reference's largest bearing, rod-piston and guide forces */
    double aa, ab, an;      /* the worst pointwise differences of the run's forces fa, fb, |N| from the
                               reference's, or twice the third run's, whichever is larger (|max a - max b|
                               <= max |a_i - b_i|: the largest force is reached at several dead centres,
                               and a perturbed run may take its maximum at another one) */
    double eb, ebJ;         /* the energy error the run's distance from the reference can make
                               (mm_dyn_sc_energy_bound), with J(phi) w^2 / 2 for the second */
    int ia, ib, in;         /* where the run's fa, fb and |N| are largest */
} mm_dyn_sc_cmp;

/* Fills c, and absn[i] = |N[i]|.  Returns MM_OK, or MM_ESINGULAR with err
 * filled when the constraints became dependent (the rod stood vertical). */
int mm_dyn_sc_compare(const mm_sc_model *s, int partition, int ny, int n, const double *y, const double *yref,
                      const double *yalt, double tol_ref, const double *fa, const double *fb, const double *N,
                      double *absn, mm_dyn_sc_cmp *c, mm_error *err);

/* dyn-slider-crank's animation: the system sys integrated again from y0
 * (ny states, DOP853 at rtol, steps up to h_max) on 24 frames a turn at
 * the speed wmax, over the first 4 turns at most. */
int mm_dyn_sc_animate(const mm_sc_model *s, int partition, int ny, double t_end, double wmax, double rtol,
                      double h_max, const double *y0, mm_sc_system *sys, mm_result *res, mm_error *err);

#endif
