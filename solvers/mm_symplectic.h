/* mm_symplectic.h — Gauss–Legendre collocation: implicit Runge–Kutta
 * methods that are symplectic for ANY Hamiltonian, separable or not.
 *
 *   MM_SYMP_MIDPOINT  the implicit midpoint rule (1 stage, order 2):
 *                     y1 = y0 + h f(t0 + h/2, (y0 + y1)/2)
 *   MM_SYMP_GAUSS4    the 2-stage Gauss method (order 4)
 *
 * Why these: a splitting or Störmer–Verlet scheme is explicit only when
 * H(q, p) = T(p) + V(q).  A double pendulum's kinetic energy
 * p^T M(q)^-1 p / 2 mixes q and p, so the explicit splittings do not
 * apply; the Gauss methods are symplectic for every Hamiltonian system
 * written in canonical coordinates (q, p), conserve every quadratic
 * invariant exactly, and are symmetric, so over long times their energy
 * error stays bounded (oscillates, O(h^2s)) instead of drifting (Hairer,
 * Lubich & Wanner, "Geometric Numerical Integration", 2nd ed., Springer
 * 2006, sections II.1.3, VI.4, IX.3 and VIII.6 for the implementation).
 * Symplectic only in canonical coordinates: give f as Hamilton's
 * equations q' = dH/dp, p' = -dH/dq, not as (q, q').
 *
 * The stage equations are solved by fixed-point iteration, continued until
 * the increments stop decreasing (round-off: GNI VIII.6.1), so that the
 * map computed is the symplectic one to the last bit; the solution is
 * summed with compensated (Kahan) summation so that round-off does not
 * random-walk the energy over 10^5 steps.  Fixed-point iteration contracts
 * when h L < 1 (L the Lipschitz constant of f, for an oscillator about its
 * highest frequency); a step too large for it is reported, not hidden.
 *
 * Fixed step h: N = ceil((t_end - t0) / h) equal steps of (t_end - t0)/N.
 * After every step (and at t0) an observer may look at the state: the
 * caller stores what it wants (a plot every k steps, the energy at every
 * step) without the solver keeping arrays.
 *
 * Thread safety: no global state; a workspace belongs to one call at a time.
 */
#ifndef MM_SYMPLECTIC_H
#define MM_SYMPLECTIC_H

#include <stddef.h>

#include "mm_ode.h"      /* mm_ode_rhs: the same right-hand side type */
#include "mm_status.h"

#define MM_SYMP_MAX_DIM    64         /* most equations */
#define MM_SYMP_MAX_STEPS  10000000L  /* highest allowed max_steps */

typedef enum mm_symp_method {
    MM_SYMP_MIDPOINT = 1,   /* Gauss–Legendre, 1 stage, order 2 */
    MM_SYMP_GAUSS4 = 2      /* Gauss–Legendre, 2 stages, order 4 */
} mm_symp_method;

/* The problem: owned by the caller, never modified. */
typedef struct mm_symp_problem {
    size_t n;               /* equations, 1..MM_SYMP_MAX_DIM */
    mm_ode_rhs f;           /* right-hand side; returns 0 to go on */
    void *params;           /* handed to f untouched */
    double t0, t_end;       /* [s], t_end > t0 */
    const double *y0;       /* n initial values */
    const double *scale;    /* n typical sizes of the components (> 0), for
                               the convergence test of the iteration; NULL:
                               max(|y0_j|, 1) */
} mm_symp_problem;

typedef struct mm_symp_options {
    mm_symp_method method;  /* default MM_SYMP_GAUSS4 */
    double h;               /* step [s], > 0 (default 0.01) */
    long max_steps;         /* most steps, 1..MM_SYMP_MAX_STEPS (default 1e6) */
    int max_iter;           /* most fixed-point iterations a step, 2..200 (default 60) */
} mm_symp_options;

/* Called at t0 (step 0) and after every step with the state y (n values,
 * read only).  Return 0 to go on; anything else stops the integration and
 * is returned by mm_symp_solve (an mm_status code, or MM_EINTERNAL). */
typedef int (*mm_symp_observer)(long step, double t, const double *y, void *params);

/* Counters, filled by mm_symp_solve (also when it fails). */
typedef struct mm_symp_result {
    double h;               /* the step taken [s] */
    long n_steps;           /* steps done */
    long n_eval;            /* calls of f */
    int iter_max;           /* most fixed-point iterations in one step */
    double iter_mean;       /* mean iterations a step */
    double t_reached;       /* time of the last state [s] */
} mm_symp_result;

/* Defaults above.  Cannot fail. */
void mm_symp_options_init(mm_symp_options *opt);

/* "implicit-midpoint" or "gauss-legendre-4"; "unknown" otherwise.  Cannot fail. */
const char *mm_symp_method_name(mm_symp_method method);

/* Order of the method (2 or 4; 0 for an unknown one).  Cannot fail. */
int mm_symp_order(mm_symp_method method);

/* Workspace for up to n equations (NULL if n is 0, above MM_SYMP_MAX_DIM,
 * or memory runs out).  _free(NULL) does nothing. */
typedef struct mm_symp_work mm_symp_work;
mm_symp_work *mm_symp_work_alloc(size_t n);
void mm_symp_work_free(mm_symp_work *w);

/* Validate without doing any work.  MM_OK or:
 *   MM_EVALUE  a non-finite t0, t_end, y0[i], scale[i] or h (param names it);
 *   MM_ERANGE  n outside 1..MM_SYMP_MAX_DIM ("n"), t_end <= t0 ("t_end"),
 *              unknown method ("method"), h <= 0 or more than max_steps
 *              steps or a step too small to advance t ("h"), max_steps or
 *              max_iter outside their ranges, scale[i] <= 0 ("scale"). */
int mm_symp_check(const mm_symp_problem *prob, const mm_symp_options *opt, mm_error *err);

/* Integrate from t0 to t_end.  w from mm_symp_work_alloc(m), m >= n; y_end
 * (n values, may be NULL) receives the final state, OVERWRITTEN; res (may
 * be NULL) the counters; observe may be NULL.  Returns MM_OK or:
 *   any code of mm_symp_check;
 *   MM_ENOMEM      w is NULL;
 *   MM_ENOCONV     the fixed-point iteration did not contract (h too large
 *                  for the fastest motion: "h", the message says at what t);
 *   MM_ENONFINITE  the state became NaN or infinite ("h");
 *   f's or observe's own nonzero return (an mm_status code, else
 *                  MM_EINTERNAL), param "f" or "observer". */
int mm_symp_solve(const mm_symp_problem *prob, const mm_symp_options *opt, mm_symp_work *w,
                  mm_symp_observer observe, void *obs_params, double *y_end,
                  mm_symp_result *res, mm_error *err);

#endif
