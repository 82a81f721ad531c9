/* mm_exhelp.h — small helpers shared by exercises (not a solver: these know
 * about mm_result and parameters).
 */
#ifndef MM_EXHELP_H
#define MM_EXHELP_H

#include "mm_exercise.h"
#include "mm_ode.h"
#include "mm_sdof.h"

/* n equally spaced values from a to b into x (n >= 2), written as
 * a + (b - a) * i / (n - 1) so that round grids print short. */
void mm_linspace(double a, double b, int n, double *x);

/* n equally spaced times from 0 to t_end (n >= 2) as mm_linspace, each the
 * double nearest its short decimal when the step is a short decimal
 * (t_end = 1.9, n = 501: 0.0038 i), so that a plot's times print short. */
void mm_ex_time_grid(double t_end, int n, double *t);

/* x > 0 rounded up to two significant digits (1.806 -> 1.9): a plot's end
 * that makes a short grid.  Cannot fail. */
double mm_ex_nice_up(double x);

/* Largest |y[i]| over n values. */
double mm_maxabs(const double *y, int n);

/* Integrate y' = f(t, y), n equations, from t = 0 with y0 to t_end by
 * DOP853 at rtol and atol (h_max > 0 caps the step), and write the dense
 * output at the nt times t: x[i] = y_0(t_i), v[i] = y_1(t_i) (x or v may be
 * NULL).  r receives the solver's counters.  Scratch comes from res's arena.
 * Returns MM_OK, or the solver's code with err filled. */
int mm_ex_ode_grid(size_t n, mm_ode_rhs f, void *ctx, const double *y0, double t_end,
                   int nt, const double *t, double rtol, double atol, double h_max,
                   double *x, double *v, mm_ode_result *r, mm_result *res, mm_error *err);

/* Integrate the 1-DOF oscillator s from 0 to t_end with DOP853 (rtol 1e-8),
 * dense output onto t[0..n-1]; x and v receive displacement and velocity
 * (v may be NULL).  With stride > 0 it also reports the method and its
 * counters on res and checks the whole response against the closed form
 * mm_sdof_x at every stride-th point; with stride = 0 it only integrates
 * (res then serves as the arena).  Returns MM_OK or an mm_status code with
 * err filled. */
int mm_ex_sdof_run(const mm_sdof *s, double t_end, int n, const double *t,
                   double *x, double *v, int stride, mm_result *res, mm_error *err);

/* The work bound of 1-DOF time responses: t_end * (largest rate of the
 * system: omega_n, omega when forced, and the fast decay rate when
 * overdamped) must not pass MM_SDOF_MAX_RADIANS, or the request would take
 * too long: the DOP853 run shown and its error estimate at rtol / 100 cost
 * about 10 us a radian together, so 2e4 radians (3,200 periods) stay under
 * 250 ms (bench_limits). */
#define MM_SDOF_MAX_RADIANS 2e4
int mm_ex_sdof_work_check(const mm_sdof *s, double t_end, mm_error *err);

/* ---- 1-DOF responses: the closed form plotted, the integrator beside it ------- */

/* The relative tolerance of the DOP853 runs of the 1-DOF exercises. */
#define MM_EX_SDOF_RTOL 1e-10

/* Their errors are estimated by a second run at MM_EX_SDOF_RTOL /
 * MM_EX_SDOF_REF: its error is about a tenth of the first run's, so the
 * difference of the two is 0.8-1.0 times the first run's error (over 1000
 * random draws of the 1-DOF exercises the checks built on it used at most
 * a quarter of their tolerance of 10 estimates).  At rtol / 100 the
 * estimate was a little closer and the second run cost 1.78 times the
 * first instead of 1.33 (DOP853's steps grow as tol^(-1/8)): it was half
 * of a vib-sdof-forced request's integration. */
#define MM_EX_SDOF_REF 10

/* Integrate the 1-DOF oscillator s (mm_sdof_rhs) from 0 to t_end by DOP853
 * at rtol (atol rtol times the size of the motion, found by a first run
 * when the guess was far off), steps at most h_max (0: one radian of the
 * fastest motion), dense output onto t[0..n-1]: x and v (v may be NULL).
 * r receives the counters (evaluations of both runs).  Returns MM_OK or
 * the solver's code with err filled. */
int mm_ex_sdof_integrate(const mm_sdof *s, double t_end, int n, const double *t, double *x,
                         double *v, double rtol, double h_max, mm_ode_result *r, mm_result *res,
                         mm_error *err);

/* The response of s on the n times t: the closed form mm_sdof_x into x
 * (the answer that is plotted), DOP853 (mm_ex_sdof_integrate at
 * MM_EX_SDOF_RTOL) into xi (shown beside it), the method and its counters
 * on res, and the check of xi against x (mm_check_curve) within ten times
 * DOP853's error estimated by a second run at MM_EX_SDOF_RTOL / MM_EX_SDOF_REF (plus
 * round-off, mm_ex_roundoff).  *worst receives the largest |xi - x|.
 * Returns MM_OK or the solver's code. */
int mm_ex_sdof_response(const mm_sdof *s, const mm_sdof_props *p, double t_end, int n,
                        const double *t, double *x, double *xi, double *worst, mm_result *res,
                        mm_error *err);

/* The plotted response of s from 0 to t_end on sx->n equally spaced times
 * (mm_linspace): the closed form into sx and DOP853 beside it, checked
 * (mm_ex_sdof_response), and DOP853's difference from the closed form into
 * se, rounded to 3 significant digits (an error needs no more).  sx and se
 * come from mm_res_series (NULL: MM_ENOMEM, already recorded in res).
 * Returns MM_OK or the solver's code with err filled. */
int mm_ex_sdof_plot(const mm_sdof *s, const mm_sdof_props *p, double t_end, mm_series *sx, mm_series *se,
                    mm_result *res, mm_error *err);

/* The closed form of s checked against eq. (1) without an integrator, at
 * J + 1 = 65 equally spaced times over [0, t_end] (J intervals of tau):
 * (x, v) from mm_sdof_x less the steady state (x_p, v_p) of mm_sdof_props
 * must be carried from each time to the next by the flow of the free
 * equation over tau (mm_sdof_flow, a matrix exponential that uses none of
 * the closed form's formulas), and x(0), v(0) must be x0, v0: two checks
 * at round-off (mm_ex_roundoff over the span, of the terms' sizes).  Not
 * at undamped resonance (no steady state; nothing is checked).  Returns
 * MM_OK or MM_ENOMEM (recorded in res). */
int mm_ex_sdof_flow_check(const mm_sdof *s, const mm_sdof_props *p, double t_end, mm_result *res);

/* Round-off in a time response over `radians` of the fastest motion of
 * largest size peak: 16 eps (1 + radians) peak (the closed form's cosines
 * carry eps of their argument; an integrator adds eps a step). */
double mm_ex_roundoff(double radians, double peak);

/* The steady state of s measured in the time domain: DOP853 (MM_EX_SDOF_RTOL)
 * started on the steady orbit X cos(omega t + psi - phase) (mm_sdof_props)
 * for `periods` forcing periods, 64 samples a period, projected on cos and
 * sin (mm_fourier_harmonic).  *X and *lag receive the amplitude and the lag
 * behind cos(omega t), the lag put within pi of lag_near; *X_est and
 * *lag_est their errors estimated by a second run at rtol / MM_EX_SDOF_REF:
 * the size |d| of the difference of the two X e^{-i lag}, and |d| / X (each
 * part of an error is within its size; a part's own difference may not
 * shrink with rtol).  A check of the steady-state formulas that does not
 * use them beyond the start. */
int mm_ex_sdof_steady_measure(const mm_sdof *s, const mm_sdof_props *p, int periods,
                              double lag_near, double *X, double *lag, double *X_est,
                              double *lag_est, mm_result *res, mm_error *err);

/* ---- warnings, printed values ----------------------------------------------------- */

/* A plot of n points over span s of a motion with angular frequency omega
 * [rad/s] has (n - 1) / (span omega / 2 pi) points a period: under 8 it
 * cannot draw the oscillation (it aliases).  Warns with the remedy and
 * returns 1 then, else 0. */
int mm_ex_warn_aliasing(mm_result *res, int n, double span, double omega, const char *remedy);

/* A numerical value shown beside its exact value: scalar `out` gets value
 * with the error bound |value - exact| + exact_err (exact_err bounds the
 * exact value's own rounding).  Returns the scalar. */
mm_scalar *mm_ex_scalar_beside(mm_result *res, int out, double value, double exact,
                               double exact_err);

/* Round y[0..n-1] to `digits` significant decimal digits (the double
 * nearest each short decimal, so that the answer prints it short): for
 * numbers whose further digits mean nothing, an error curve or a drawing. */
void mm_ex_round_sig(double *y, int n, int digits);

/* ---- animation of an oscillator ----------------------------------------------------- */

/* Frames for a motion of shortest period `period` over t_end (24 a period,
 * as mm_scene_frames) within a budget of MM_EX_ANIM_POINTS drawn points
 * in all, each frame drawing npts points: fewer periods are shown, never
 * fewer frames a period.  *t_show receives the span shown. */
#define MM_EX_ANIM_POINTS 1800
int mm_ex_anim_frames(double t_end, double period, int npts, double *t_show);

/* A block on a spring (and damper) tied to a support, drawn over nf
 * frames at the times t: x[f] the block's displacement, y[f] the
 * support's (NULL: a fixed wall), F[f] a force on the block drawn as an
 * arrow named force_name (NULL: none), a damper beside the spring when
 * `damper`, a floor under the block when `on_floor` (dry friction).  Drawn to
 * the scale of the motion (a rest length of 5 times its largest
 * displacement), coordinates rounded to 1e-3 of that length so that the
 * frames stay short in the answer.  Returns MM_OK or MM_ENOMEM. */
int mm_ex_animate_oscillator(mm_result *res, int nf, const double *t, const double *x,
                             const double *y, const double *F, const char *force_name, int damper,
                             int on_floor);

/* A plot grid over [a, b] that also resolves a narrow feature (a resonance
 * peak): n equally spaced points merged with nwin equally spaced points over
 * [c - half, c + half] (clipped to [a, b]), sorted, exact repeats dropped.
 * x needs room for n + nwin values; returns the number written (>= n).
 * n >= 2, nwin >= 0, half >= 0. */
int mm_ex_grid_refined(double a, double b, int n, double c, double half, int nwin, double *x);

/* ---- checks that every chapter needs ------------------------------------------ */

/* A curve against its reference: the worst |got[i] - ref[i]| over n points,
 * checked against tol_peak times the reference's own largest |ref| (never a
 * scale of the method's own: a wrong curve must not widen its tolerance).
 * Returns the worst error; the check is named name. */
double mm_check_curve(mm_result *res, const char *name, int n, const double *got,
                      const double *ref, double tol_peak);

/* A residual that must be round-off: |residual| <= ulps * eps * scale, where
 * scale is the size of the largest term that was summed into it.  Say what
 * scale is in the name ("sum of |F_i|"). */
int mm_check_residual(mm_result *res, const char *name, double residual, double scale,
                      double ulps);

/* The observed order of convergence: the least-squares slope of log e
 * against log h over n >= 3 points, checked against the expected order
 * within tol (the points must lie in the asymptotic range: above round-off
 * and below the step where the error stops following h^p).  Returns the
 * slope. */
double mm_check_order(mm_result *res, const char *name, int n, const double *h,
                      const double *e, double expected, double tol);

/* ---- one oscillator by the textbook's time integrators ------------------------------ */

enum mm_ex_method {
    MM_EX_CENTRAL,      /* central difference (mm_newmark), damping implicit */
    MM_EX_AVERAGE,      /* Newmark average acceleration (mm_newmark) */
    MM_EX_VERLET,       /* Stormer-Verlet (mm_newmark) */
    MM_EX_RK4,          /* classical Runge-Kutta (mm_ode) */
    MM_EX_DOPRI5,       /* Dormand-Prince 5(4), adaptive (mm_ode) */
    MM_EX_DOP853,       /* Dormand-Prince 8(5,3), adaptive (mm_ode) */
    MM_EX_METHODS
};

typedef struct mm_ex_run {
    int rows;           /* rows written into t, x, v */
    long steps, evals, rejected;
    double h;           /* the step taken (fixed: t_end / ceil(t_end / h)); mean step if adaptive */
    int failed;         /* 1: the numbers overflowed (past a stability limit), or an
                           adaptive run needed more than its steps */
} mm_ex_run;

/* The 1-DOF oscillator s (m x'' + c x' + k x = F0 cos wt) over [0, t_end]
 * by method m: the fixed-step ones with N = ceil(t_end / h) equal steps of
 * t_end / N (o->h), the adaptive ones at rtol and atol.  The state at every
 * stride-th step (and the last) goes into t, x and v (v may be NULL), at
 * most cap rows; stride > 1 only for the fixed-step methods.  At most (cap - 1) stride steps are taken.  Returns
 * MM_OK (also when the run failed: o->failed says so), or an error of the
 * solvers with err filled. */
int mm_ex_sdof_method(const mm_sdof *s, int m, double h, double rtol, double atol, double t_end, long stride,
                      int cap, double *t, double *x, double *v, mm_ex_run *o, mm_result *res, mm_error *err);

/* The observed order of convergence of errors e against steps h (n
 * points, h decreasing): the least-squares slope of log e against log h
 * over the (up to) four finest points whose error lies in [lo, hi] (above
 * hi the leading error term does not rule yet, below lo round-off does).
 * *spread receives the largest difference of a local slope (between
 * neighbours) from the fit: how far the points are from one straight line,
 * the error of the slope.  Returns the number of points used (the slope is
 * written only when it is 3 or more). */
int mm_ex_observed_order(const double *h, const double *e, int n, double lo, double hi, double *order,
                         double *spread);

#endif
