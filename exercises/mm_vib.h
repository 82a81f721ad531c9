/* mm_vib.h — what the vibration exercises (chapter 5, and num-newmark)
 * share that is not numerics: drawing masses on springs, blocks, bars and
 * beams in an answer's animation, a mode's motion in frames, what a
 * transient exercise shows of its run, and the families of checks the
 * 1-DOF exercises share.  The numerics are in solvers/ (mm_sdof, mm_mdof,
 * mm_fem, mm_coulomb, mm_fourier, ...).
 */
#ifndef MM_VIB_H
#define MM_VIB_H

#include "mm_coulomb.h"
#include "mm_exercise.h"
#include "mm_fem.h"
#include "mm_sdof.h"
#include "mm_status.h"

/* How many frames show a motion of the given shortest period over t_end
 * within max_frames (<= MM_ANIM_MAX_FRAMES): 16 frames a period; when
 * that cannot cover t_end, the animation covers *t_show < t_end, else
 * t_show = t_end.  At least 2 frames.  A period <= 0 or infinite:
 * max_frames / 2 frames over t_end.  Keeping answers small (64 KB at the
 * defaults) is what max_frames is for: pass budget / numbers per frame. */
int mm_vib_frames(double t_end, double period, int max_frames, double *t_show);

/* Points of a spring drawn by mm_vib_masses_draw: 2 leads, 3 coils. */
#define MM_VIB_SPRING_POINTS 8

/* Masses on their springs, nf frames: n blocks in a row, block i at rest
 * at x = (i + 1) gap, moved by q[f*n + i] [m] in frame f.  The springs come
 * from the stiffness matrix K (n x n): -K_ij joins blocks i and j (next
 * neighbours in the row; others drawn as a line arching above), the row
 * sum sum_j K_ij ties block i to the nearer wall (a wall is drawn where a
 * spring meets it).  gap: rest spacing [m], a few times the largest |q|.
 * Creates the shapes "wall", "spring i-j", "mass i".  Returns MM_OK or
 * MM_ENOMEM. */
int mm_vib_masses_draw(mm_result *res, int n, const double *K, int nf, const double *q,
                       double gap);

/* Numbers per frame of mm_vib_masses_draw for n masses (at most). */
int mm_vib_masses_numbers(int n, const double *K);

/* A chain of n masses between walls (right_wall: 0 for a free right end),
 * nf frames: the masses as dots on a line of springs (straight), moved
 * along the line by q[f*n + i] [m], and the same displacements drawn
 * across the line as a curve above it (a chain's mode looks like a
 * string's).  At most 60 masses are drawn (every k-th of a longer chain)
 * and 120 points of the curve.  gap: the rest spacing [m].  Creates
 * "springs", "mass i", "wall left", "wall right", "u across".  Returns
 * MM_OK or MM_ENOMEM. */
int mm_vib_chain_draw(mm_result *res, int n, int right_wall, int nf, const double *q, double gap);

/* q[f*n + i] = A phi[i*ld + j] sin(2 pi f / (nf - 1)): one period of mode j
 * in nf frames, and t[f] = f T / (nf - 1), T = 2 pi / omega (t in periods
 * when omega = 0).  Cannot fail. */
void mm_vib_mode_frames(int n, const double *phi, int ld, int j, double omega, double A, int nf,
                        double *t, double *q);

/* A bar's or beam's motion, nf frames of the displacement u (nf x ndof,
 * every global DOF): a beam's centre line deflected by w(x) (Hermite
 * interpolation, 2 points per element, at most 61 in all), a bar's axis
 * with its nodes moved along it (drawn as dots, 11 at most) and the curve
 * of u(x) drawn above it (at most 51 points), both scaled by scale (metres
 * of drawing per metre of displacement).  Supports drawn as ground.  Creates "member", "nodes"
 * (bar), "u(x)" (bar), "support".  Returns MM_OK or MM_ENOMEM. */
int mm_vib_member_draw(mm_result *res, const mm_fem_problem *p, int nf, const double *u,
                       double scale);

/* The matrices of M q'' + C q' + K q = F as parameters named "M", "C",
 * "K" (C may be NULL): square, n x n like M, symmetric to 1e-12 of their
 * largest entry, M positive definite, C and K positive semidefinite; and
 * the nvec vectors vec[k] (named vnames[k]) of n values each.  Returns
 * MM_OK or MM_ERANGE / MM_EVALUE naming the parameter and saying why. */
int mm_vib_check_system(const mm_value *M, const mm_value *C, const mm_value *K, int nvec,
                        const mm_value *const *vec, const char *const *vnames, mm_error *err);

/* A modally damped system M q'' + C q' + K q = F cos(W t), C = M Phi
 * diag(c) Phi^T M (c_j = 2 zeta_j omega_j), from q0, v0, computed three
 * ways at the ns sampled steps k_i h (every stride-th of N = ceil(t_end/h)
 * steps, and the last), for the transient exercises:
 *   q_nm   direct integration, mm_newmark average acceleration, coupled;
 *   q_ex   modal superposition of all n modes, each exact (mm_mdof);
 *   q_m    the same with the first m modes only (truncated);
 * and two checks made on res: q_nm against the superposition of every
 * mode's exact discrete Newmark solution (rounding: the scheme commutes
 * with the modal decomposition), and q_ex against the transition matrix of
 * the coupled system (rounding).  Phi: n x n mass-normalised modes, omega
 * their frequencies.  Arrays come from res's arena.  Returns MM_OK or an
 * mm_status code with err filled. */
typedef struct mm_vib_transient {
    int ns;               /* samples */
    long steps, stride;   /* Newmark steps, and steps between samples */
    double *t, *q_nm, *q_ex, *q_m;   /* ns, and ns x n each */
    double err_max;       /* max |q_nm - q_ex|: Newmark's error, exact to rounding */
    double trunc_max;     /* max |q_m - q_ex|: the truncation error, exact */
    double round;         /* the rounding of these (an estimate) */
    double round_nm;      /* that of err_max, with the Newmark run's own rounding */
} mm_vib_transient;

int mm_vib_transient_run(mm_result *res, int n, const double *M, const double *K, const double *omega,
                         const double *Phi, const double *c, int m, const double *q0, const double *v0,
                         const double *F, double W, double h, double t_end, int points,
                         mm_vib_transient *out, mm_error *err);

/* The largest |u| over n values, or 1 when all are 0 (a scale's divisor). */
double mm_vib_big(const double *u, size_t n);

/* ---- the transient exercises (5.10.2, 5.11.1): what they show ---------------- */

/* What a transient exercise shows of tr (mm_vib_transient_run) for a system
 * of n coordinates integrated with step h: the largest Newmark error and
 * truncation error as scalars out_err and out_trunc (each with the
 * rounding of its values, an estimate), the method (average acceleration,
 * step h) and its steps, and the histories of the nc coordinates
 * coord[0..nc-1] over tr->t: for each set of Newmark, exact, retained
 * modes (sets = 3; sets = 2 leaves the last out, when every mode is
 * retained), series out[set * nc + i] of coordinate coord[i], in that
 * order.  Returns MM_OK or MM_ENOMEM. */
int mm_vib_transient_show(mm_result *res, const mm_vib_transient *tr, int n, double h, int out_err,
                          int out_trunc, int nc, const int *coord, const int *out, int sets);

/* The exact motion of M q'' + C q' + K q = F cos(W t) from q0, v0 (C =
 * M Phi diag(c) Phi^T M, every mode: mm_mdof_modal_response) for an
 * animation: mm_vib_frames(t_end, period, max_frames) frames equally spaced
 * over the span shown; starts the animation (times in s) and sets *nf and
 * *q (nf x n, from res's arena).  Returns MM_OK or an mm_status code with
 * err filled. */
int mm_vib_modal_frames(mm_result *res, int n, const double *M, const double *omega, const double *c,
                        const double *Phi, const double *q0, const double *v0, const double *F, double W,
                        double t_end, double period, int max_frames, int *nf, double **q, mm_error *err);

/* Scale the n values of q so that the largest |q| becomes `largest` (a
 * drawing's displacements: 0.3 moves the largest 0.3 of a gap).  All 0:
 * left as they are.  Cannot fail. */
void mm_vib_scale(double *q, size_t n, double largest);

/* ---- the 1-DOF exercises (5.9): the block moving, the steady state measured ---- */

/* The block of s moving from its initial state: frames over t_end as
 * mm_ex_anim_frames(t_end, period, npts) gives them, x(t) by the closed
 * form mm_sdof_x at each; with `force` (and F0 != 0) the force F0
 * cos(omega t) drawn as an arrow "F"; with Y (not NULL) the support moving
 * as *Y cos(omega t); a damper beside the spring when `damper`
 * (mm_ex_animate_oscillator).  Returns MM_OK or MM_ENOMEM. */
int mm_vib_sdof_animate(mm_result *res, const mm_sdof *s, const mm_sdof_props *p, double t_end, double period,
                        int npts, int force, const double *Y, int damper);

/* The limits of a forced 1-DOF exercise: at undamped resonance under a
 * force (forced != 0) there is no steady state, refused naming omega ("the
 * <what> grows without bound"); then the work bound of the time response
 * (mm_ex_sdof_work_check).  Returns MM_OK or MM_ERANGE with err filled. */
int mm_vib_sdof_check(const mm_sdof *s, double t_end, int forced, const char *what, mm_error *err);

/* The steady state of s measured in the time domain on its orbit
 * (mm_ex_sdof_steady_measure, two forcing periods) and checked against the
 * formulas: the amplitude against X = G A (a gain times an amplitude: the
 * transmissibility times the support's amplitude; a force's X times 1),
 * named "X: measured on the steady orbit vs <x_ref>, ...", and the lag
 * against `phase` (eq. (4)), each within 10 times DOP853's error estimated
 * at rtol/10 plus the round-off of two periods.  Nothing is done when four
 * forcing periods would pass the work bound (MM_SDOF_MAX_RADIANS).
 * Returns MM_OK or the solver's code with err filled. */
int mm_vib_steady_check(mm_result *res, const mm_sdof *s, const mm_sdof_props *p, double G, double A,
                        double phase, const char *x_ref, mm_error *err);

/* The block of vib-coulomb on its rough floor, frames from the exact
 * solution (mm_coulomb_x over the ne rests te, xe, sge of mm_coulomb_arcs)
 * over t_plot (mm_ex_anim_frames, 26 points a frame), the friction force
 * drawn as an arrow: sliding, mu m g against the motion; at rest, what
 * holds the spring, k x.  Returns MM_OK or MM_ENOMEM. */
int mm_vib_coulomb_animate(mm_result *res, const mm_coulomb *s, const double *te, const double *xe,
                           const double *sge, int ne, double t_plot);

/* ---- the finite-element exercises (5.12) ---------------------------------------- */

/* The words for the eigen solver mm_fem_modes_solve used ("LAPACK dsygvd,
 * dense: every mode of the mesh", ...), for mm_res_method. */
const char *mm_vib_fem_method(mm_fem_method m);

/* One mode of a bar or beam animated: one period 2 pi / omega in nf frames
 * (mm_vib_mode_frames), u = shape sin(2 pi f / (nf - 1)) over every global
 * DOF (shape: the mode, mm_fem_ndof(p) values), drawn by mm_vib_member_draw
 * at `scale`.  Starts the animation.  Returns MM_OK or MM_ENOMEM. */
int mm_vib_member_mode(mm_result *res, const mm_fem_problem *p, const double *shape, double omega, int nf,
                       double scale);

/* A transient run's snapshots of a bar or beam animated: frame f at t =
 * h snap[f] shows the field u + f * ndof (every global DOF), drawn by
 * mm_vib_member_draw so that the largest deflection of all frames (every
 * other DOF of a beam, every DOF of a bar) is frac of the length (scale 1
 * when all are 0).  Starts the animation.  Returns MM_OK or MM_ENOMEM. */
int mm_vib_member_snaps(mm_result *res, const mm_fem_problem *p, int nf, const long *snap, double h, const double *u,
                        double frac);

/* ---- the absorber (5.10.1): a steady motion of complex amplitudes ------------- */

/* The steady harmonic motion q_i(t) = Re(X_i e^{i omega t}) of n masses on
 * the springs of K (mm_vib_masses_draw, gap 1), one period in nf frames
 * (t in s; in periods when omega = 0), the largest |X_i| moving a quarter
 * gap (nothing moves when an amplitude is infinite or all are 0).  X: n
 * complex amplitudes (a C99 _Complex double array; this header leaves
 * complex.h out, see mm_fem.h's field I).  Starts the animation.  Returns
 * MM_OK or MM_ENOMEM. */
int mm_vib_masses_steady(mm_result *res, int n, const double *K, const _Complex double *X, double omega, int nf);

#endif
