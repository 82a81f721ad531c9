/* mm_exhelp.h — small helpers shared by exercises (not a solver: these know
 * about mm_result and parameters).
 */
#ifndef MM_EXHELP_H
#define MM_EXHELP_H

#include "mm_exercise.h"
#include "mm_ode.h"
#include "mm_sdof.h"
#include "mm_result_v1.h"   /* the builders by name, until every exercise declares its outputs */

/* n equally spaced values from a to b into x (n >= 2), written as
 * a + (b - a) * i / (n - 1) so that round grids print short. */
void mm_linspace(double a, double b, int n, double *x);

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
 * system: omega_n, omega, and the fast decay rate when overdamped) must not
 * pass MM_SDOF_MAX_RADIANS, or the request would take too long. */
#define MM_SDOF_MAX_RADIANS 1e4
int mm_ex_sdof_work_check(const mm_sdof *s, double t_end, mm_error *err);

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

#endif
