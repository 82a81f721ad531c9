/* mm_num.h — the chapter kit of the chapter-1 (numerical methods)
 * exercises: what they share that is not numerics (that is in solvers/):
 * a function of x typed by the learner, printed values with their bounds,
 * their standard figures (the Argand plane, a polynomial on the real axis,
 * a fit with its data), and num-newmark's runs and drawing.
 */
#ifndef MM_NUM_H
#define MM_NUM_H

#include "mm_dd.h"
#include "mm_exercise.h"
#include "mm_expr.h"
#include "mm_newmark.h"
#include "mm_poly.h"

/* ---- a function of x typed by the learner ----------------------------------------- */

/* f(x) compiled from the parameter's text, and the number of times it was
 * evaluated (the method's "evaluations"). */
typedef struct mm_num_f {
    mm_expr *e;
    long evals;
} mm_num_f;

/* Compile text as f of the variable x; a syntax error names the parameter
 * "f".  Returns MM_OK or mm_expr_compile's code with err filled. */
int mm_num_f_compile(mm_num_f *f, const char *text, mm_error *err);

/* Free f's expression.  Cannot fail. */
void mm_num_f_free(mm_num_f *f);

/* f(x), counted: an mm_roots_fn / mm_quad callback (ctx the mm_num_f),
 * always 0; and the same as a value. */
int mm_num_f_eval(double x, double *fx, void *ctx);
double mm_num_f_at(mm_num_f *f, double x);

/* f(x) with the estimate of its rounding error (mm_expr_eval_err), an
 * mm_roots_fn_err callback; not counted (an estimate, not the method's
 * work).  Always 0. */
int mm_num_f_eval_err(double x, double *fx, double *err, void *ctx);

/* The largest rounding error of f (mm_expr_eval_err) at 33 of the n
 * points x at most (every (n + 31) / 32-th).  Cannot fail. */
double mm_num_f_rounding(mm_num_f *f, int n, const double *x);

/* The same for mm_opt_refine_extreme: with err the value and its rounding
 * error (not counted), without it the value alone (counted). */
double mm_num_f_value_err(double x, double *err, void *ctx);

/* The series `out`: f at np equally spaced points over [a, b] (not
 * counted), those where f is not finite left out: *bad of them, the first
 * at *first_bad.  *crossings receives the zero crossings the plot shows,
 * between neighbouring finite samples (a zero sample counts once).
 * Returns MM_OK or MM_ENOMEM. */
int mm_num_f_curve(mm_result *res, int out, mm_num_f *f, double a, double b, int np, int *bad,
                   double *first_bad, int *crossings);

/* The values v[0..n-1] for a warning, "%.6g" each, separated by ", ",
 * until the list passes 90 characters (it fits MM_NUM_LIST).  Cannot
 * fail. */
#define MM_NUM_LIST 120
void mm_num_list(char *list, const double *v, int n);

/* Member i of the scalar family `out` with its error (mm_res_scalar_i,
 * then mm_res_scalar_err's error and kind).  Never NULL. */
mm_scalar *mm_num_scalar_i_err(mm_result *res, int out, int i, double value, double error, mm_err_kind kind);

/* Scalar `out` from a double-double value v known within e: v rounded to
 * double, its bound e plus the rounding; marked exact when that is 0. */
void mm_num_scalar_dd(mm_result *res, int out, mm_dd v, double e);

/* ---- the Argand plane ---------------------------------------------------------- */

/* The series `out` as an arrow from the origin to (x, y), the way a
 * complex number is drawn on the Argand plane.  Returns MM_OK or MM_ENOMEM. */
int mm_num_arrow(mm_result *res, int out, double x, double y);

/* The series `out`: the powers a^0, a^1, ..., a^n (n < 0: of 1 / a, to
 * a^n), multiplied out one after the other in double-double: a spiral that
 * turns by arg a a step.  Returns MM_OK or MM_ENOMEM. */
int mm_num_powers(mm_result *res, int out, mm_cdd a, int n);

/* ---- polynomials ----------------------------------------------------------------- */

/* The series `out`: p (ncoef coefficients, highest power first) on the real
 * axis at 201 points over the real parts of its nr roots and a quarter of
 * their span on either side (the span at least 1e-3 of their size, and
 * 1e-3).  When p overflows somewhere on that range the curve is left out,
 * with a warning.  Returns MM_OK or MM_ENOMEM. */
int mm_num_poly_curve(mm_result *res, int out, int ncoef, const double *p, const mm_poly_root *roots, int nr);

/* The standard figure of a fit: the n data points (x, y) as series
 * `data`, and as series `curve` the fitted polynomial on 201 points over
 * their span and 5 % beyond either end (1 when the x are all equal),
 * evaluated from its ncoef coefficients bt in t = (x - mu) / scale (no
 * cancellation of powers of x).  Returns MM_OK or MM_ENOMEM. */
int mm_num_fit_plot(mm_result *res, int data, int curve, int n, const double *x, const double *y, int ncoef,
                    const double *bt, double mu, double scale);

/* ---- num-newmark ------------------------------------------------------------------- */

/* The rows a Newmark run stored, in res's arena. */
typedef struct mm_num_newmark_rows {
    double *t, *q;               /* the stored rows: times, and n displacements each */
    mm_newmark_energy *e;        /* the energy balance (eq. 7 of newmark.md) at them */
    mm_newmark_result r;
} mm_num_newmark_rows;

/* N steps of h of the problem pb (its t_end taken as N h) with the options
 * base, storing every stride-th step and the last, or `points` rows spread
 * evenly when points > 0, the work of the forces integrated in q
 * (work_in_q).  Returns MM_OK, MM_ENOMEM, or mm_newmark_check's or
 * mm_newmark_solve's code with err filled. */
int mm_num_newmark_run(const mm_newmark_problem *pb, const mm_newmark_options *base, double h, long N, long stride,
                       int points, mm_num_newmark_rows *o, mm_result *res, mm_error *err);

/* The modes of M q'' + C q' + K q = 0 (n coordinates): into *wmax the
 * highest undamped natural frequency, into *kappa cond(M) from the
 * eigenvalues of M (1 / eps when M is singular), and the damped modes
 * (mm_mdof_complex_modes) as the rows of the table `out`: mode, omega,
 * zeta, omega_d, omega h.  Returns MM_OK, MM_ENOMEM or mm_mdof's code with
 * err filled. */
int mm_num_newmark_modes(mm_result *res, int out, int n, const double *M, const double *C, const double *K, double h,
                         double *wmax, double *kappa, mm_error *err);

/* The masses of stiffness K (n of them) on their springs, one frame a
 * stored row of a (mm_vib_masses_draw, drawn to 4 times the largest
 * displacement).  Returns MM_OK or MM_ENOMEM. */
int mm_num_newmark_draw(mm_result *res, int n, const double *K, const mm_num_newmark_rows *a);

#endif
