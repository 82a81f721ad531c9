/* mm_newmark.h — fixed-step time integrators for second-order systems
 *
 *     M q'' + C q' + K q = F(t, q, q')                                  (1)
 *
 * the book's `newmark`/`defphy` pair: a mechanical system given by its mass,
 * damping and stiffness matrices and a vector of generalised forces F that
 * may depend on time, position and velocity.
 *
 * Schemes (all with one fixed step h):
 *   - the Newmark family (beta, gamma): average acceleration (1/4, 1/2),
 *     linear acceleration (1/6, 1/2), or any pair you give;
 *   - HHT-alpha and generalized-alpha: Newmark plus controlled numerical
 *     damping of the high frequencies;
 *   - central difference (explicit, Newmark beta = 0, gamma = 1/2);
 *   - Stormer-Verlet (velocity Verlet; explicit, symplectic).
 * Implicit schemes with a force that depends on q or q' solve each step by
 * Newton's method, with the Jacobian from a callback or finite differences.
 *
 * Use it in four parts (STYLE.md section 3):
 *
 *     mm_newmark_options opt;
 *     mm_newmark_options_init(&opt);
 *     opt.method = MM_NEWMARK_AVERAGE; opt.h = 1e-3;
 *     if (mm_newmark_check(&prob, &opt, &err)) return err.code;   // no allocation yet
 *     int rows = mm_newmark_output_rows(&prob, &opt);             // size the result arrays
 *     mm_newmark_work *w = mm_newmark_work_alloc(prob.n);
 *     rc = mm_newmark_solve(&prob, &opt, w, &res, &err);
 *     mm_newmark_work_free(w);
 *
 * Conventions: matrices are dense, row-major, n x n: A[i*n + j] is row i,
 * column j.  Units are the SI units of the coordinates (kg, N s/m, N/m, N for
 * translations; kg m^2, N m s, N m, N m for rotations).  Time steps are
 * t_k = t0 + k h exactly; the run takes the fewest steps that reach t_end,
 * so it ends on t_end when h divides t_end - t0 and up to one step past it
 * otherwise.
 *
 * Thread safety: no globals; a workspace serves one run at a time.
 */
#ifndef MM_NEWMARK_H
#define MM_NEWMARK_H

#include "mm_status.h"

/* Limits checked by mm_newmark_check before anything is allocated. */
#define MM_NEWMARK_MAX_DOF 200                /* most degrees of freedom */
#define MM_NEWMARK_DEFAULT_MAX_STEPS 1000000L /* options.max_steps default */
#define MM_NEWMARK_STEPS_CEILING 100000000L   /* largest allowed max_steps */
#define MM_NEWMARK_MAX_NEWTON 100             /* largest newton_max_iter */

/* ---- problem ------------------------------------------------------------ */

/* Generalised forces F(t, q, q'): write n values into F.  Return 0, or a
 * nonzero code to stop the run (solve then returns that code when it is an
 * MM_E* value, MM_EINTERNAL otherwise).  Must not keep the pointers. */
typedef int (*mm_newmark_force_fn)(double t, const double *q, const double *qd,
                                   double *F, void *params);

/* Jacobian of F: dFdq[i*n + j] = dF_i/dq_j and dFdqd[i*n + j] = dF_i/dq'_j.
 * Both arrays are zeroed before the call, so fill only the nonzero entries.
 * Return 0, or a nonzero code to stop the run (as for the force). */
typedef int (*mm_newmark_jacobian_fn)(double t, const double *q,
                                      const double *qd, double *dFdq,
                                      double *dFdqd, void *params);

/* What F depends on.  The zero value is the safe default. */
typedef enum mm_newmark_force_kind {
    MM_NEWMARK_FORCE_STATE = 0, /* F(t, q, q'): Newton in implicit schemes */
    MM_NEWMARK_FORCE_POSITION,  /* F(t, q): Verlet stays symplectic */
    MM_NEWMARK_FORCE_TIME       /* F(t) only: the problem is linear, and the
                                   effective matrix is factored once */
} mm_newmark_force_kind;

typedef struct mm_newmark_problem {
    int n;                          /* degrees of freedom, 1..MM_NEWMARK_MAX_DOF */
    const double *M;                /* mass, n x n, symmetric positive definite [kg] */
    const double *C;                /* damping, n x n, or NULL for none [N s/m] */
    const double *K;                /* stiffness, n x n, or NULL for none [N/m] */
    mm_newmark_force_fn force;      /* F(t, q, q') [N], or NULL for F = 0 */
    mm_newmark_jacobian_fn jacobian;/* dF/dq, dF/dq', or NULL: finite differences */
    mm_newmark_force_kind force_kind;
    void *params;                   /* handed to force and jacobian untouched */
    const double *q0;               /* initial displacement, n, or NULL for 0 [m] */
    const double *qd0;              /* initial velocity, n, or NULL for 0 [m/s] */
    double t0, t_end;               /* time span, t_end > t0 [s] */
} mm_newmark_problem;

/* ---- options ------------------------------------------------------------ */

typedef enum mm_newmark_method {
    MM_NEWMARK_AVERAGE = 0,  /* Newmark beta = 1/4, gamma = 1/2 (trapezoidal):
                                unconditionally stable, conserves energy */
    MM_NEWMARK_LINEAR,       /* Newmark beta = 1/6, gamma = 1/2: stable for
                                h < 2 sqrt(3) / omega_max */
    MM_NEWMARK_BETA_GAMMA,   /* Newmark with options.beta, options.gamma */
    MM_NEWMARK_HHT,          /* Hilber-Hughes-Taylor, options.alpha */
    MM_NEWMARK_GENERALIZED_ALPHA, /* Chung-Hulbert, options.rho_inf */
    MM_NEWMARK_CENTRAL,      /* central difference: explicit, h < 2 / omega_max;
                                C is taken implicitly (M + h/2 C is factored
                                once), an F that depends on q' gets the
                                predicted velocity q'_k + h q''_k */
    MM_NEWMARK_VERLET,       /* velocity Verlet: explicit, symplectic when
                                C = 0 and F = F(t, q); h < 2 / omega_max.
                                With damping (C != 0 or F depending on q')
                                it still runs, but the damping force uses the
                                half-step velocity: first order, no longer
                                symplectic, and a lower stability limit */
    MM_NEWMARK_METHOD_COUNT
} mm_newmark_method;

typedef struct mm_newmark_options {
    mm_newmark_method method;
    double h;             /* time step, > 0 [s]; no default */
    double beta, gamma;   /* MM_NEWMARK_BETA_GAMMA: beta in [0, 1/2], gamma in
                             [1/2, 1]; unconditionally stable if 2 beta >= gamma */
    double alpha;         /* MM_NEWMARK_HHT: in [-1/3, 0]; 0 is average
                             acceleration, -1/3 damps the most */
    double rho_inf;       /* MM_NEWMARK_GENERALIZED_ALPHA: spectral radius at
                             infinite frequency, in [0, 1]; 1 is average
                             acceleration, 0 wipes out the highest modes
                             within a few steps */
    long stride;          /* store every stride-th step (and always the last) */
    int points;           /* > 0: store this many rows instead, spread evenly
                             over the run (first and last included); >= 2 */
    double newton_tol;    /* Newton stops when |residual| <= newton_tol times
                             the size of the forces in (1); in [1e-14, 1e-2] */
    int newton_max_iter;  /* most Newton corrections per step */
    long max_steps;       /* refuse runs needing more steps than this */
    int work_in_q;        /* energy bookkeeping: 0 (default) integrates the
                             powers q'.F and q'.C q' by the trapezoidal rule
                             in t; 1 integrates F dq and C q' dq by the
                             trapezoidal rule in q, (q_{k+1} - q_k).(F_k +
                             F_{k+1})/2, which average acceleration keeps
                             exactly on every linear system, forced and
                             damped (Hughes, ch. 9) */
} mm_newmark_options;

/* ---- result ------------------------------------------------------------- */

/* Energy bookkeeping of (1).  Multiplying (1) by q' gives
 *     d/dt (1/2 q'^T M q' + 1/2 q^T K q) = q'^T F - q'^T C q'
 * so  kinetic + potential = E0 + work - dissipated  for the exact motion.
 * potential uses the symmetric part of K; the work of the antisymmetric
 * (circulatory) part of K is counted in work.  work and dissipated
 * integrate the powers q'.F and q'.C q' by the trapezoidal rule over each
 * step (or in q, options.work_in_q), so the balance residual is a
 * second-order error indicator that needs no reference solution.  It is
 * round-off only where the scheme conserves energy exactly: average
 * acceleration on a free undamped linear system (and, with work_in_q, on
 * any linear system). */
typedef struct mm_newmark_energy {
    double kinetic;       /* 1/2 q'^T M q' [J] */
    double potential;     /* 1/2 q^T K q [J] */
    double work;          /* work done by F since t0 [J] */
    double dissipated;    /* energy taken out by C since t0 [J] */
} mm_newmark_energy;

typedef struct mm_newmark_result {
    /* Arrays the caller supplies, each with room for max_rows rows, or NULL
     * when not wanted.  Row r of q is q + r*n (same for qd, qdd). */
    double *t;                  /* times [s] */
    double *q;                  /* displacements [m] */
    double *qd;                 /* velocities [m/s] */
    double *qdd;                /* accelerations [m/s^2] */
    mm_newmark_energy *energy;  /* energy bookkeeping at each row */
    int max_rows;

    /* Optional (NULL: none): called with the state at t_0 (k = 0) and after
     * every step k = 1..steps, whether the step is stored or not, so that a
     * caller can follow every step without storing it.  The arrays hold n
     * values and are valid during the call only.  Return 0 to go on, or a
     * nonzero code to stop the run (returned as for the force callback). */
    int (*observe)(long k, double t, const double *q, const double *qd, const double *qdd,
                   void *params);
    void *observe_params;

    /* Filled by mm_newmark_solve (also when it fails part-way: then they
     * describe the run up to the failure). */
    int rows;                   /* rows stored */
    long steps;                 /* steps taken */
    long force_evals;           /* calls of F, finite differences included */
    long jacobian_evals;        /* calls of the Jacobian callback */
    long newton_iters;          /* Newton corrections (0 for linear problems,
                                   which take one direct solve per step) */
    long factorizations;        /* LU factorizations of an n x n matrix */
    double omega_max;           /* the highest natural frequency of M and the
                                   symmetric part of K - dF/dq at t0 [rad/s],
                                   computed exactly (all eigenvalues of the
                                   pencil, LAPACK dsygvd: to rounding), or 0
                                   when there is no positive stiffness */
    double h_stable;            /* stability limit of a conditionally stable
                                   scheme, mm_newmark_omega_h_limit / omega_max
                                   (2/omega_max for central difference and
                                   Verlet) [s]; 0 when the scheme has none
                                   or omega_max is 0 */
    double energy_start;        /* kinetic + potential at t0 [J] */
    mm_newmark_energy energy_end;
    double energy_balance;      /* max over the steps of
                                   |kinetic + potential - E0 - work + dissipated| [J] */
    double energy_error;        /* energy_balance over the largest of |E0|,
                                   |kinetic + potential|, |work|, |dissipated|
                                   seen: an error indicator independent of the
                                   reference solution; 0 when all are 0 */
} mm_newmark_result;

/* ---- workspace ---------------------------------------------------------- */

typedef struct mm_newmark_work mm_newmark_work;

/* Scratch space for problems of up to n degrees of freedom (n x n matrices
 * and vectors; about 4 n^2 doubles).  NULL when out of memory or when n is
 * outside 1..MM_NEWMARK_MAX_DOF. */
mm_newmark_work *mm_newmark_work_alloc(int n);

/* Release w.  w may be NULL (then nothing happens). */
void mm_newmark_work_free(mm_newmark_work *w);

/* ---- calls -------------------------------------------------------------- */

/* Fill o with the defaults: average acceleration, h = 0 (the caller must
 * set it), beta = 1/4, gamma = 1/2, alpha = -0.1, rho_inf = 0.8, stride 1,
 * points 0, newton_tol 1e-10, newton_max_iter 20,
 * max_steps MM_NEWMARK_DEFAULT_MAX_STEPS.  Cannot fail. */
void mm_newmark_options_init(mm_newmark_options *o);

/* Validate p and o without allocating or calling F: sizes, finite entries,
 * a symmetric mass matrix with positive diagonal, the time span, h, the
 * scheme's parameters, the output choice, and the number of steps
 * (t_end - t0)/h against o->max_steps.  Returns MM_OK or
 *   MM_ERANGE      a size or value outside its limits, too many steps;
 *   MM_EVALUE      a non-finite entry, a mass matrix that is not symmetric;
 *   MM_ESINGULAR   a mass matrix with a zero or negative diagonal entry;
 * with err naming the field.  Reads its arguments only. */
int mm_newmark_check(const mm_newmark_problem *p, const mm_newmark_options *o,
                     mm_error *err);

/* Steps the run will take and rows it will store.  Only meaningful after
 * mm_newmark_check returned MM_OK; then they cannot fail. */
long mm_newmark_step_count(const mm_newmark_problem *p,
                           const mm_newmark_options *o);
int mm_newmark_output_rows(const mm_newmark_problem *p,
                           const mm_newmark_options *o);

/* Integrate (1) from (t0, q0, qd0) to t_end with fixed step o->h.
 * w must come from mm_newmark_work_alloc(m) with m >= p->n.  Writes the
 * stored rows into res's non-NULL arrays (which need room for
 * mm_newmark_output_rows rows) and the counters and energy figures into res;
 * reads p and o only.  Row 0 is the initial state, with q'' from (1).
 * Returns MM_OK or
 *   any code of mm_newmark_check (nothing is allocated or called then);
 *   MM_ESINGULAR   M not positive definite, or a singular effective matrix
 *                  (e.g. M + gamma h C + beta h^2 K with negative stiffness);
 *   MM_ENOCONV     Newton did not converge within newton_max_iter: reduce h;
 *   MM_ENONFINITE  the solution overflowed (an explicit scheme past its
 *                  stability limit: the message names the limit), or F gave
 *                  NaN or Inf;
 *   a code returned by the force or Jacobian callback;
 *   MM_EINTERNAL   result arrays with too few rows.
 * On failure res holds the rows and counters up to the failing step. */
int mm_newmark_solve(const mm_newmark_problem *p, const mm_newmark_options *o,
                     mm_newmark_work *w, mm_newmark_result *res, mm_error *err);

/* ---- stability and the amplification matrix ---------------------------- */

/* The largest Omega = omega h at which o's scheme stays stable on an
 * undamped linear system, or 0 when it is stable at every step:
 *   central difference, Verlet                    2
 *   linear acceleration                           2 sqrt(3)
 *   Newmark (beta, gamma) with 2 beta < gamma     1 / sqrt(gamma/2 - beta)
 *   average acceleration, HHT-alpha, generalized-alpha, Newmark with
 *   2 beta >= gamma >= 1/2                        0 (unconditionally stable)
 * The step limit is h < limit / omega_max.  Damping lowers Verlet's limit
 * (its damping force sees the half-step velocity): mm_newmark_spectral_radius
 * tells.  Reads o->method, o->beta, o->gamma.  Cannot fail. */
double mm_newmark_omega_h_limit(const mm_newmark_options *o);

/* One step of o's scheme (step o->h) on the LINEAR system
 *     M q'' + C q' + K q = F(t)
 * as the linear map it is (T. J. R. Hughes, The Finite Element Method,
 * ch. 9), on the state y = (q, q', q'') of 3n values:
 *     y_{k+1} = A y_k + B0 F(t_k) + B1 F(t_{k+1})                        (A)
 * A is 3n x 3n, B0 and B1 are 3n x n (row-major; B0 and B1 may be NULL).
 * Written from the schemes' defining equations (N1), (N2), (G) of
 * mm_newmark.c, not by running a step, so that the recursion it gives is an
 * independent statement of what mm_newmark_solve computes: its powers are
 * the exact discrete solution of the scheme.  M is n x n positive definite,
 * C and K n x n or NULL (zero).  For plain Newmark, central difference and
 * Verlet the rows of q'' make A of rank 2n (q'' follows from q, q').
 * Returns MM_OK, or MM_ERANGE (n outside 1..MM_NEWMARK_MAX_DOF, an invalid
 * option: as mm_newmark_check), MM_ESINGULAR (the matrix the step solves
 * with, e.g. M + gamma h C + beta h^2 K, is singular), MM_ENOMEM. */
int mm_newmark_amplification(int n, const double *M, const double *C, const double *K,
                             const mm_newmark_options *o, double *A, double *B0,
                             double *B1, mm_error *err);

/* Spectral radius (largest |eigenvalue|) of A for the 1-DOF oscillator
 * x'' + 2 zeta omega x' + omega^2 x = 0 at the step o->h: the solution of
 * the scheme decays (< 1), keeps its size (1) or grows (> 1) per step.
 * omega >= 0, zeta >= 0.  Returns NaN when the options are invalid.
 * Cannot fail otherwise. */
double mm_newmark_spectral_radius(const mm_newmark_options *o, double omega, double zeta);

/* A name for each method, as used in the HTTP answer's "method" field:
 * "newmark-average-acceleration", "newmark-linear-acceleration",
 * "newmark-beta-gamma", "hht-alpha", "generalized-alpha",
 * "central-difference", "stormer-verlet"; "unknown" otherwise.
 * Cannot fail. */
const char *mm_newmark_method_name(mm_newmark_method method);

#endif
