/* mm_mech.h — constraint kinematics of mechanisms: positions from the
 * constraint equations Phi(q, t) = 0 by Newton-Raphson, velocities and
 * accelerations by linear solves with the constraint Jacobian, and a sweep
 * that follows one assembly of the mechanism from frame to frame without
 * jumping branch, locating where it stops closing (toggle), where its
 * Jacobian changes sign (a change point, where branches cross) and where a
 * chosen coordinate turns back (dead centre).
 *
 * The model (E. J. Haug, Computer Aided Kinematics and Dynamics of
 * Mechanical Systems, 1989, ch. 3; P. E. Nikravesh, Computer-Aided Analysis
 * of Mechanical Systems, 1988, ch. 3):
 *
 *     Phi(q, t) = 0                     m equations in n coordinates q  (1)
 *     Phi_q q'  = nu,      nu = -Phi_t                                  (2)
 *     Phi_q q'' = gamma,   gamma = -(Phi_q q')_q q' - 2 Phi_qt q' - Phi_tt (3)
 *
 * The constraints include the drivers (a crank angle prescribed as a
 * function of t), so that a mechanism with one degree of freedom and its
 * driver has m = n.  t is whatever drives: a time, or a crank angle.
 * m > n is allowed for an overconstrained mechanism whose equations are
 * consistent (Newton then takes least-squares steps); m < n cannot be
 * solved for positions.
 *
 * Linear algebra: systems of order <= MM_MECH_TINY are solved by our own
 * LU with partial pivoting (and an exact 1-norm condition number from the
 * inverse); larger or non-square ones through mm_linalg (LAPACK).
 *
 * Weighted norms: coordinates mix angles and lengths.  A length is divided
 * by opt.length (a size of the mechanism) and an angle taken as it is, so
 * |dq|_w is in radians, or in lengths of the mechanism.
 *
 * No globals; a workspace belongs to one thread.  The callbacks are called
 * only from the calling thread.
 */
#ifndef MM_MECH_H
#define MM_MECH_H

#include "mm_status.h"

#define MM_MECH_MAX_N     64      /* most coordinates */
#define MM_MECH_MAX_M     128     /* most constraint equations */
#define MM_MECH_TINY      6       /* own LU up to this order, LAPACK above */
#define MM_MECH_MAX_EVENTS 16     /* events of each kind a sweep records */

/* A vector callback: Phi(q, t) or nu(q, t) into out (m values), or Phi_q
 * into out (m x n, row-major).  Return 0, or an MM_E* code to stop. */
typedef int (*mm_mech_fn)(const double *q, double t, double *out, void *params);
/* gamma(q, q', t) into out (m values). */
typedef int (*mm_mech_acc_fn)(const double *q, const double *qd, double t, double *out, void *params);

typedef struct mm_mech_problem {
    int n;                  /* coordinates, 1..MM_MECH_MAX_N */
    int m;                  /* equations, n..MM_MECH_MAX_M (1..MM_MECH_MAX_M for mm_mech_rank) */
    mm_mech_fn phi;         /* eq. (1) */
    mm_mech_fn jac;         /* Phi_q */
    mm_mech_fn nu;          /* eq. (2)'s right side; NULL: 0 (no driver in time) */
    mm_mech_acc_fn gamma;   /* eq. (3)'s right side; NULL: accelerations not asked */
    const unsigned char *is_length; /* n flags: 1 for a length coordinate, 0 for an angle; NULL: all angles */
    void *params;           /* passed to the callbacks untouched */
} mm_mech_problem;

typedef struct mm_mech_options {
    double length;          /* a size of the mechanism [m], > 0: scales lengths in norms */
    double xtol;            /* Newton stops when |dq|_w <= xtol (default 1e-12), or below
                               the rounding floor 8 eps (|q|_w + 1) / rcond near a toggle */
    int max_iter;           /* Newton iterations at most (default 60: linear convergence at a toggle) */
    double max_step;        /* a Newton step is cut to |dq|_w <= max_step (default 0.5) */
    double sing_rcond;      /* a square Jacobian with rcond below this is singular (default 1e-13) */
    double phi_scale;       /* the size of the largest term summed in Phi (the sum of the
                               link lengths, say): Phi is known to a few eps of it, which
                               bounds how well q can be known; 0: length */
} mm_mech_options;

typedef struct mm_mech_info {
    int iterations;         /* Newton iterations taken */
    double residual;        /* |Phi|_inf at the solution, in the units of Phi */
    double step;            /* |dq|_w of the last Newton step */
    double err_est;         /* estimate of |q - q_exact|_w: the geometric tail of the
                               last steps, s_k r / (1 - r) with r = s_k / s_{k-1}, plus
                               the rounding: (|Phi| + 4 eps phi_scale) |Phi_q^-1| */
    double rcond;           /* 1/cond_1(Phi_q) (square), sigma_min/sigma_max (other) */
    double det;             /* det Phi_q when square and n <= MM_MECH_TINY, else 0 */
    double inv_norm;        /* |Phi_q^-1| from |Phi|_inf to |.|_w: exact for n <= MM_MECH_TINY,
                               n / (rcond |Phi_q|_1) or sqrt(m) / sigma_min otherwise */
    int rank;               /* numerical rank of Phi_q (square: n unless singular) */
} mm_mech_info;

typedef struct mm_mech_work mm_mech_work;   /* opaque scratch for one problem size */

/* The defaults above, length = 1.  Cannot fail. */
void mm_mech_options_init(mm_mech_options *opt);

/* MM_OK, or MM_ERANGE/MM_EVALUE naming what is wrong (n, m, a missing
 * callback, options out of range).  No side effects. */
int mm_mech_check(const mm_mech_problem *p, const mm_mech_options *opt, mm_error *err);

/* Scratch for n coordinates and m equations; NULL when out of memory or
 * sizes outside the limits (m < n is allowed here, for mm_mech_rank of a
 * mechanism without its drivers).  mm_mech_work_free(NULL) does nothing. */
mm_mech_work *mm_mech_work_alloc(int n, int m);
void mm_mech_work_free(mm_mech_work *w);

/* Solve eq. (1) at t by Newton-Raphson from the guess in q (overwritten
 * with the solution).  Converges to the assembly nearest the guess in the
 * Newton sense; near a toggle (double root) convergence is linear.
 * Square: q <- q - Phi_q^{-1} Phi; singular or non-square: the
 * least-squares minimum-norm step.  Fails with MM_ENOCONV ("q": no
 * convergence in max_iter; q holds the last iterate), MM_ENONFINITE, or a
 * callback's code.  info may be NULL. */
int mm_mech_position(const mm_mech_problem *p, const mm_mech_options *opt, mm_mech_work *w,
                     double t, double *q, mm_mech_info *info, mm_error *err);

/* Velocities q' from eq. (2) at the solved q.  MM_ESINGULAR ("q") when
 * Phi_q is singular (rcond < sing_rcond: a toggle, where the driver cannot
 * move the mechanism), the rank-deficient overconstrained case included.
 * info (may be NULL) receives rcond, det and rank. */
int mm_mech_velocity(const mm_mech_problem *p, const mm_mech_options *opt, mm_mech_work *w,
                     double t, const double *q, double *qd, mm_mech_info *info, mm_error *err);

/* Accelerations q'' from eq. (3) at the solved q, q'.  As mm_mech_velocity
 * (p->gamma must be set). */
int mm_mech_acceleration(const mm_mech_problem *p, const mm_mech_options *opt, mm_mech_work *w,
                         double t, const double *q, const double *qd, double *qdd, mm_mech_info *info,
                         mm_error *err);

/* Singular values of Phi_q at q (min(m, n) of them, largest first) and the
 * numerical rank (those above tol * sigma_max; tol <= 0: max(m, n) eps).
 * n - rank is the mobility of the mechanism at q (drivers left out of Phi).
 * sv may be NULL.  Fails as mm_linalg_svdvals or a callback. */
int mm_mech_rank(const mm_mech_problem *p, mm_mech_work *w, double t, const double *q, double tol,
                 double *sv, int *rank, mm_error *err);

/* ---- following one assembly over a range of t ------------------------------------ */

typedef struct mm_mech_sweep {
    /* in */
    int nt;                 /* frames, >= 2 */
    const double *t;        /* nt values, strictly monotonic (increasing or decreasing) */
    double *q;              /* nt x n: q[0..n-1] holds the assembly guess for t[0] on entry */
    double *qd, *qdd;       /* nt x n each, or NULL: velocities, accelerations per frame */
    int watch;              /* a coordinate whose turning points (q'_watch = 0, a dead
                               centre) are located, or -1 */
    double tol_t;           /* events are located to within this in t (default 1e-11
                               of the range when 0) */
    /* out */
    int solved;             /* frames solved from t[0] on: nt, unless it stopped closing */
    double t_limit;         /* when solved < nt: where it stops closing (a toggle),
                               located to tol_t between t[solved-1] and t[solved] */
    int n_sing;             /* sign changes of det Phi_q met (branch crossings), with */
    double t_sing[MM_MECH_MAX_EVENTS];  /* their places (det = 0 by the secant rule) */
    int n_turn;             /* turning points of q_watch, with */
    double t_turn[MM_MECH_MAX_EVENTS];  /* their places and */
    double q_turn[MM_MECH_MAX_EVENTS];  /* the values of q_watch there */
    int steps, newton;      /* continuation steps taken (frames included), Newton iterations */
    int singular_frames;    /* frames whose velocities could not be solved (singular) */
    double err_est;         /* largest mm_mech_info.err_est over the frames */
} mm_mech_sweep;

/* Follow the assembly that Newton reaches from the guess at t[0] through
 * t[1], t[2], ...: each frame is reached in steps whose predictor
 * extrapolates the last two or three solutions, and a step is halved when
 * Newton fails or its correction is large beside the step (a branch jump
 * would be), or when det Phi_q changes sign over it and the bisection for
 * the crossing leaves the chord between its ends (it landed on another
 * assembly that passes close, not through a change point).  A solution
 * whose Jacobian's condition has collapsed beside the last one's (a frame
 * on a change point) is kept for its frame but not for the predictor,
 * which would not know which way to go on from it.  When steps shrink below tol_t without a solution, the
 * mechanism has stopped closing: s->solved and s->t_limit say where, and
 * the function still returns MM_OK.  Velocities and accelerations of each
 * frame are solved when qd (qdd) are given; a singular frame (exactly at a
 * change point) gets zeros and is counted.  Returns MM_ENOCONV when even
 * t[0] cannot be assembled, a callback's code, or MM_ERANGE for bad sweep
 * arguments.  A gap where the mechanism cannot close that is narrower than
 * a step (max_step, or the frames' spacing) can be stepped across when it
 * closes again just beyond: keep the frames inside the range that closes,
 * or closer together than its gaps. */
int mm_mech_sweep_solve(const mm_mech_problem *p, const mm_mech_options *opt, mm_mech_work *w,
                        mm_mech_sweep *s, mm_error *err);

#endif
