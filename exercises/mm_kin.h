/* mm_kin.h — what the kinematics chapter's exercises share that is not
 * numerics: drawing links, pivots, sliders and vector arrows into an
 * answer's animation; the finite-difference study that checks an analytic
 * velocity or acceleration against differences of the positions (the
 * error against the step, its observed order, the value within the
 * difference's own error bound) and its samples; a plane curve typed as
 * two expressions; the radius of curvature measured from three points;
 * and the drawing of each particle and rigid-body exercise's animation,
 * fed the state of a frame by the exercise (mm_kin_linkage.h draws the
 * linkages).
 *
 *   mm_kin_draw d;
 *   if (!mm_kin_draw_start(&d, res, nf, "crank angle", "rad", size)) return MM_ENOMEM;
 *   mm_shape *crank = mm_kin_shape(&d, "crank", MM_SHAPE_LINE, 1, 2);
 *   for (f...) { mm_kin_pt(crank, f, 0, 0, 0); mm_kin_pt(crank, f, 1, xB, yB); }
 *   return mm_kin_draw_finish(&d);      rounds every coordinate to d.grid
 */
#ifndef MM_KIN_H
#define MM_KIN_H

#include "mm_cam.h"
#include "mm_exercise.h"
#include "mm_geom.h"

/* ---- drawing ------------------------------------------------------------------------ */

#define MM_KIN_MAX_SHAPES 48

typedef struct mm_kin_draw {
    mm_result *res;
    mm_anim *anim;
    int nf;               /* frames */
    double size;          /* the size of the scene [m]: sets grid and arrow lengths */
    double inv_grid;      /* coordinates are rounded to 1/inv_grid [m], a power of ten
                             about 1e-4 of the size: far below a pixel, and short in JSON */
    mm_shape *shapes[MM_KIN_MAX_SHAPES];
    int nshapes;
} mm_kin_draw;

/* Start the animation of nf frames (t[] to be filled by the caller).
 * Returns the animation, or NULL when out of memory. */
mm_anim *mm_kin_draw_start(mm_kin_draw *d, mm_result *res, int nf, const char *t_label,
                           const char *t_unit, double size);

/* A shape that moves (moving = 1: nf frames) or not (one frame), of npts
 * points.  NULL when out of memory or too many shapes. */
mm_shape *mm_kin_shape(mm_kin_draw *d, const char *name, mm_shape_kind kind, int moving, int npts);

/* Point k of frame f of s (frame 0 for a shape that does not move). */
void mm_kin_pt(mm_shape *s, int f, int k, double x, double y);

/* An arrow shape for a vector quantity in unit, scaled so that the
 * largest of magnitude vmax is 0.3 of the scene (scale 0 when vmax is 0).
 * NULL when out of memory. */
mm_shape *mm_kin_arrow_shape(mm_kin_draw *d, const char *name, const char *unit, double vmax);

/* Frame f of arrow s: from (x, y) along (vx, vy) times s->scale. */
void mm_kin_arrow(mm_shape *s, int f, double x, double y, double vx, double vy);

/* A fixed pivot at (x, y): a small triangle under it, style "ground".
 * NULL when out of memory. */
mm_shape *mm_kin_pivot(mm_kin_draw *d, const char *name, double x, double y);

/* A slider block (rectangle) centred at (x, y), w by h, turned by angle:
 * frame f of a polygon of 4 points.  Cannot fail. */
void mm_kin_block(mm_shape *s, int f, double x, double y, double w, double h, double angle);

/* Round every coordinate of every shape to the grid.  Returns MM_OK. */
int mm_kin_draw_finish(mm_kin_draw *d);

/* ---- a finite-difference study --------------------------------------------------------- */

#define MM_KIN_FD_MAX 32

/* q(t_i + h): the k coordinates of sample i displaced by h in t, into q,
 * and a bound of their error in the weighted norm (Newton's err_est, 0 for
 * a closed form) into *qerr.  Return MM_OK or an MM_E* code (err filled). */
typedef int (*mm_kin_pos_fn)(int i, double h, double *q, double *qerr, void *ctx, mm_error *err);

typedef struct mm_kin_fd {
    int nh;
    double h[MM_KIN_FD_MAX];      /* steps, largest first, halving */
    double err[MM_KIN_FD_MAX];    /* worst weighted |difference - analytic| over the samples */
    double round[MM_KIN_FD_MAX];  /* a bound of the rounding in that difference */
    double slope;                 /* observed order over the steps where truncation rules */
    int nfit;                     /* how many steps the slope was fitted on (0: none: the
                                     difference is exact to rounding, e.g. a quadratic motion) */
    double worst;                 /* the value check: worst |difference - analytic| ... */
    double bound;                 /* ... and its bound at that sample, at step h_check */
    double h_check;
} mm_kin_fd;

/* Central differences of order `deriv` (1: (q(t+h) - q(t-h))/2h, 2: (q(t+h)
 * - 2 q(t) + q(t-h))/h^2) of the k coordinates at the n samples, against
 * the analytic derivatives d (n x k), for nh steps h0, h0/2, ...; each
 * coordinate weighted by w[j] (1/length for lengths, 1 for angles; NULL:
 * all 1).  The positions' own error bounds (from pos) enter the rounding
 * bound; d_err bounds the error of the analytic derivatives themselves
 * (weighted; 0 for a closed form) and is added to the value check's.  Fills fd; then checks
 * on res:
 *   - the observed order (2) over the steps where the error is above 100x
 *     its rounding bound, when there are at least 3 of them, within 0.15;
 *   - the analytic derivative against the difference at the step where the
 *     bound 2 |D(h) - D(h/2)| + 3 (R(h) + R(h/2)) is smallest (the
 *     truncation error of D(h) is 4/3 |D(h) - D(h/2)| to leading order; R
 *     bounds the rounding), sample by sample, the worst ratio reported;
 * and, when out >= 0, writes the error against the step as the series out
 * (x = h, y = worst error; the floor of the log plot is 1e-17 of the
 * derivative's size).  what names the derivative in the checks ("dx/dphi").
 * Returns MM_OK or pos's code. */
int mm_kin_fd_study(mm_result *res, int out, const char *what, mm_kin_pos_fn pos, void *ctx, int k,
                    const double *w, int n, const double *d, int deriv, double h0, int nh, double d_err,
                    mm_kin_fd *fd, mm_error *err);

/* The study every kinematic answer makes of its velocity and acceleration:
 * mm_kin_fd_study of order 1 over 24 steps from h0 (series out_v, checks
 * named what_v) and then, when that went well, of order 2 over 18 steps
 * (out_a, what_a); d1 and d2 are the analytic derivatives (n x k), d1_err
 * and d2_err bound their own error (0 for a closed form).  n = 0: nothing
 * to study, MM_OK.  Returns MM_OK or pos's code. */
int mm_kin_fd_va(mm_result *res, int out_v, int out_a, const char *what_v, const char *what_a, mm_kin_pos_fn pos,
                 void *ctx, int k, const double *w, int n, const double *d1, const double *d2, double h0,
                 double d1_err, double d2_err, mm_error *err);

/* The joint limit of a motion shown from 0 to t_end and asked at t:
 * t <= t_end, else MM_ERANGE naming "t". */
int mm_kin_check_t(double t, double t_end, mm_error *err);

/* ---- a plane curve typed as two expressions of t ------------------------------------ */

typedef struct mm_expr mm_expr;

typedef struct mm_kin_curve {
    mm_expr *x, *y;           /* x(t), y(t), compiled for this request */
    const char *px, *py;      /* their parameter names, for messages */
} mm_kin_curve;

/* Compile the texts of the parameters px and py as functions of t.
 * Returns MM_OK or mm_expr's code with err naming the parameter. */
int mm_kin_curve_compile(mm_kin_curve *c, const char *x, const char *y, const char *px, const char *py,
                         mm_error *err);
void mm_kin_curve_free(mm_kin_curve *c);

/* The solve of an exercise on a typed curve: compile the expressions of
 * the parameters px and py (named x and y), run, free.  Returns
 * mm_kin_curve_compile's code or run's. */
int mm_kin_curve_solve(const mm_value *in, int px, int py,
                       int (*run)(mm_kin_curve *c, const mm_value *in, mm_result *res, mm_error *err),
                       mm_result *res, mm_error *err);

/* The work of an exercise on a typed curve: every point it computes costs
 * a Ridders derivative (21 evaluations of x and y), an evaluation about 9
 * ns a character (4.4 us for 500), so (points + extra) * (len(x) +
 * len(y)) <= 8e5 (the length counted as at least 32) keeps the worst
 * request near 150 ms; with short expressions every points is allowed.
 * extra: the points computed besides the plotted ones.  MM_OK or
 * MM_ERANGE naming "points" with the largest allowed. */
int mm_kin_curve_work(const char *x, const char *y, double points, double extra, mm_error *err);

/* The joint limits of a motion shown from t0 to t1 and asked at t:
 * t1 > t0 (else MM_ERANGE naming "t1"), t within [t0, t1] (naming "t"). */
int mm_kin_check_window(double t0, double t1, double t, mm_error *err);

/* (x(t), y(t)) into out; MM_ENONFINITE when either is not finite (an
 * mm_geom_curve_fn, ctx is the curve).  Does not fill an mm_error. */
int mm_kin_curve_eval(double t, double *out, void *ctx);

/* r, r' and r'' at t by Ridders' extrapolation (mm_geom_curve_derivs), h0
 * the first step; e1, e2 their error estimates (per component).  MM_OK or
 * MM_ENONFINITE with err naming the expression that is not finite near t. */
int mm_kin_curve_at(mm_kin_curve *c, double t, double h0, double r[2], double d1[2], double e1[2], double d2[2],
                    double e2[2], mm_error *err);

/* The integrals over [a, b] of r' and r'' of the curve by composite
 * 5-point Gauss-Legendre on np panels (Ridders' derivatives at the nodes,
 * h0 their first step), and the sums of the Ridders error estimates they
 * met (weighted like the values): iv, ev for r'; ia, ea for r''.  MM_OK or
 * mm_kin_curve_at's code. */
int mm_kin_curve_integrals(mm_kin_curve *c, double a, double b, int np, double h0, double iv[2], double ev[2],
                           double ia[2], double ea[2], mm_error *err);

/* ---- small things ------------------------------------------------------------------------- */

/* n points from a to b as short decimals: a + i * step with step = (b - a) / (n - 1)
 * rounded to 3 significant digits when rounding moves no point by more
 * than a tenth of a step; b exactly last.  So plots of a crank angle
 * print 0.0524 and not 0.052359877559829883.  Returns the step used. */
double mm_kin_grid(double a, double b, int n, double *x);

/* x wrapped to (-pi, pi]. */
double mm_kin_wrap(double x);

/* x unwrapped to lie within pi of ref. */
double mm_kin_near(double x, double ref);

/* a table (output out; columns joint, kind, freedom) from a spec
 * "name:kind:f,name:kind:f,..." (f one digit) */
int mm_kin_joints_table(mm_result *res, int out, const char *spec, mm_error *err);

/* checks of a rank decision from the singular values sv[0..k-1] of an
 * m x n matrix: the largest one counted as zero is at rounding, the
 * smallest one counted as non-zero is clear of it */
void mm_kin_rank_checks(mm_result *res, const double *sv, int k, int rank, int m, int n);

/* ---- the idioms the chapter's files share ----------------------------------------------- */

/* The output of a difference study: its worst error against the step h
 * (mm_kin_fd_study's series), log-log, as dots, in the figure "difference
 * error"; un the unit of the error, hu the step's. */
#define MM_KIN_FD_SERIES(nm, lb, un, hu)                                                     \
    MM_SERIES(nm, lb, un, "step h", hu, .x_scale = "log", .y_scale = "log", .mark = "dots", \
              .figure = "difference error")

/* The samples of a motion's difference study: one plotted point in 8 (i =
 * 0, 8, 16, ...) and the last, which takes the last place; with the
 * analytic first and second derivatives of its k coordinates. */
typedef struct mm_kin_samples {
    int n, ns, k;                 /* plotted points, samples ((n + 7) / 8), coordinates */
    double *t, *d1, *d2;          /* ns times; ns x k first, second derivatives */
} mm_kin_samples;

/* Room in res's arena for the samples of n points.  MM_OK or MM_ENOMEM
 * (err filled). */
int mm_kin_samples_init(mm_kin_samples *s, mm_result *res, int n, int k, mm_error *err);

/* Whether point i (of the n) is a sample. */
int mm_kin_sampled(const mm_kin_samples *s, int i);

/* Point i (of the n) at t, its derivatives d1 and d2 (k each; d2 may be
 * NULL): kept when it is a sample.  Returns 1 when kept, else 0. */
int mm_kin_sample(mm_kin_samples *s, int i, double t, const double *d1, const double *d2);

/* The same for a plane point (k = 2) and a space point (k = 3). */
int mm_kin_sample2(mm_kin_samples *s, int i, double t, mm_v2 v, mm_v2 a);
int mm_kin_sample3(mm_kin_samples *s, int i, double t, mm_v3 v, mm_v3 a);

/* The positions of a sample at t displaced by h: the k coordinates into
 * q, a bound of their error (as mm_kin_pos_fn's) into *qerr. */
typedef int (*mm_kin_at_fn)(double t, double h, double *q, double *qerr, void *ctx, mm_error *err);

/* mm_kin_fd_va over the samples s (unweighted, the analytic derivatives
 * closed forms): the velocity and acceleration checked against central
 * differences of the positions at, steps from h0.  MM_OK or at's code. */
int mm_kin_fd_samples(mm_result *res, int out_v, int out_a, const char *what_v, const char *what_a, mm_kin_at_fn at,
                      void *ctx, const mm_kin_samples *s, double h0, mm_error *err);

/* A still path through the points of series s.  NULL when out of memory. */
mm_shape *mm_kin_path(mm_kin_draw *d, const char *name, const mm_series *s);

/* A circle of radius r, moving (nf frames) or not.  NULL when out of memory. */
mm_shape *mm_kin_circle(mm_kin_draw *d, const char *name, int moving, double r);

/* The time of frame f of a motion shown from t0 to t1, t0 + (t1 - t0) f /
 * (nf - 1), written into the animation and returned. */
double mm_kin_frame_t(mm_kin_draw *d, int f, double t0, double t1);

/* The isometric view of a space point (x, y, z up): its screen x, y. */
void mm_kin_iso(mm_v3 p, double *x, double *y);

/* A radius of curvature measured from three points of a path: R[k] the
 * radius of the circle through p(t - h_k), p(t), p(t + h_k), h_k = h / 2^k
 * for k = 0, 1, 2 (R(h) - rho = O(h): in the asymptotic regime R[2] lies
 * within 2 |R[1] - R[2]| of rho).  p writes the point at t + e (the
 * offset e = (j - 1) h / 2^k given apart, for a path taken relative to
 * p(t)) and returns 0 when it cannot.  Returns 1 when all three circles
 * were found, else 0. */
int mm_kin_circle3(int (*p)(double t, double e, mm_v2 *P, void *ctx), void *ctx, double t, double h, double R[3]);

/* ---- the chapter's drawings ------------------------------------------------------------- */

/* kin-relative-motion: a turntable of radius size turning about O (a notch
 * shows the turn), its slot at distance h from O, the slider on it, its
 * absolute path (the series path), and at the slider v and v_rel on one
 * scale (vmax), a_coriolis and a on another (amax); nf frames over
 * [0, t_show], frame(t) giving the table's angle and the slider's terms.
 * MM_OK or MM_ENOMEM (err filled). */
typedef struct mm_kin_slot_state {
    double th;
    mm_v2 r, v, vrel, acor, a;
} mm_kin_slot_state;

int mm_kin_anim_turntable(mm_result *res, int nf, double t_show, double size, double h, const mm_series *path,
                          double vmax, double amax, void (*frame)(double t, mm_kin_slot_state *k, void *ctx),
                          void *ctx, mm_error *err);

/* kin-rigid-rotation: a body turning about the unit axis u, seen along it:
 * a hexagonal plate of radius 1.3 R turning with the body (a corner at
 * r0's direction at th = 0), the axis through O(t) as a small circle, the
 * radius from it to the point P, P's path (121 points over [0, t_show]),
 * v_P and a_P at P; drift the distance the axis moves.  nf frames over
 * [0, t_show], frame(t) giving the angle turned, O, P, v, a.  MM_OK or
 * MM_ENOMEM (err filled). */
typedef struct mm_kin_axis_state {
    double th;
    mm_v3 O, P, v, a;
} mm_kin_axis_state;

int mm_kin_anim_axis(mm_result *res, int nf, double t_show, mm_v3 u, mm_v3 r0, double R, double drift, double vmax,
                     double amax, void (*frame)(double t, mm_kin_axis_state *k, void *ctx), void *ctx, mm_error *err);

/* kin-plane-motion: a ladder of length L with A on the floor and B at the
 * wall, its instantaneous centre I on the space centrode (the quarter
 * circle of radius L about the corner), the body centrode (the circle on
 * AB as diameter) rolling on it, P's path (the series path), and the
 * velocity field w k x (X - I) at five points X along AB (v_A, v, v_B, on
 * the scale of vmax); frame f at k[f].  MM_OK or MM_ENOMEM (err filled). */
typedef struct mm_kin_ladder_state {
    double t;
    mm_v2 A, B, I;
    double w;
} mm_kin_ladder_state;

int mm_kin_anim_ladder(mm_result *res, int nf, const mm_kin_ladder_state *k, double L, const mm_series *path,
                       double vmax, mm_error *err);

/* kin-particle-path: a particle on its path (the series path) with its
 * velocity and acceleration (each arrow on the scale of its largest),
 * frame f at t[f], the particle at P[f], v = V[f], a = A[f]; size the
 * scene's.  MM_OK or MM_ENOMEM (err filled). */
int mm_kin_anim_particle(mm_result *res, int nf, const double *t, double (*P)[2], double (*V)[2], double (*A)[2],
                         const mm_series *path, double size, mm_error *err);

/* kin-rotation-plane: an arm turning about the pivot O at the angle th,
 * the point x on it, its path (the series path, which sets the scene's
 * size), v and a at the point (arrows on the scales of vmax, amax); nf
 * frames over [0, t_show], frame(t) giving th, x, v, a.  MM_OK or
 * MM_ENOMEM (err filled). */
typedef struct mm_kin_arm_state {
    double th;
    mm_v2 x, v, a;
} mm_kin_arm_state;

int mm_kin_anim_arm(mm_result *res, int nf, double t_show, const mm_series *path, double vmax, double amax,
                    void (*frame)(double t, mm_kin_arm_state *k, void *ctx), void *ctx, mm_error *err);

/* kin-path-coordinates: a particle on its path (the series path) with its
 * tangential and normal accelerations (arrows on the scale of amax) and
 * its osculating circle (of radius rho and curvature k, capped at 3 sizes
 * of the scene), frame f at k[f]: the particle at P, a_t = at, a_n = an
 * (towards the centre), N the left normal.  MM_OK or MM_ENOMEM (err
 * filled). */
typedef struct mm_kin_osc_state {
    double t;
    mm_v2 P, at, an, N;
    double k, rho;
} mm_kin_osc_state;

int mm_kin_anim_osculating(mm_result *res, int nf, const mm_kin_osc_state *k, const mm_series *path, double size,
                           double amax, mm_error *err);

/* kin-rolling-wheel: a wheel of radius R rolling on the ground (two
 * spokes show its turn, clockwise for phi > 0), the line from its centre
 * O to the point P at distance b, the contact point (the instantaneous
 * centre), P's path (121 points over [0, t_show]), and the arrows v_P,
 * v_top, v_O (one scale, vmax) and a_P (amax); nf frames over [0,
 * t_show], frame(t) giving phi, phi', O, P, v, a.  MM_OK or MM_ENOMEM (err
 * filled). */
typedef struct mm_kin_wheel_state {
    double phi, w;
    mm_v2 O, P, v, a;
} mm_kin_wheel_state;

int mm_kin_anim_wheel(mm_result *res, int nf, double t_show, double R, double b, double vmax, double amax,
                      void (*frame)(double t, mm_kin_wheel_state *k, void *ctx), void *ctx, mm_error *err);

/* kin-space-motion: a box 0.6 x 0.4 x 0.2 m turning about its centre,
 * seen isometrically: its bottom, top and edges, its body axes, the space
 * axes, omega (on the scale of wmax) and the path of its point p (body
 * coordinates; 121 points over [0, t_show]); nf frames over [0, t_show],
 * frame(t) giving the rotation matrix R (body to space) and omega.  MM_OK
 * or MM_ENOMEM (err filled). */
int mm_kin_anim_box(mm_result *res, int nf, double t_show, double wmax, mm_v3 p,
                    void (*frame)(double t, double R[9], mm_v3 *w, void *ctx), void *ctx, mm_error *err);

/* kin-cam-follower: the cam turning (36 frames a turn; its profile from
 * 48 points of mm_cam_points), its centre, the roller (of radius Rr, or a
 * small dot for a knife edge) on the follower's stem in its guide, and the
 * follower's velocity at cam speed omega (on the scale of vmax); size the
 * pitch curve's.  MM_OK or MM_ENOMEM (err filled). */
int mm_kin_anim_cam(mm_result *res, const mm_cam *m, double omega, double vmax, double size, mm_error *err);

#endif
