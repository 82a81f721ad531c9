/* mm_ode.h — time integrators for first-order systems y' = f(t, y).
 *
 * Three explicit Runge–Kutta methods, from the textbook to the workhorse:
 *   MM_ODE_RK4     classical 4th-order Runge–Kutta, fixed step h;
 *   MM_ODE_DOPRI5  Dormand–Prince 5(4), adaptive, 4th-order dense output;
 *   MM_ODE_DOP853  Dormand–Prince 8(5,3), adaptive, 7th-order dense output.
 * The adaptive methods follow Hairer, Nørsett & Wanner, "Solving Ordinary
 * Differential Equations I", 2nd ed., Springer 1993 (chapter II), and
 * Hairer's codes DOPRI5 and DOP853; PI step-size control and stiffness
 * detection follow Hairer & Wanner, "... II", 2nd ed. 1996, section IV.2.
 *
 * Higher-order ODEs are written as first-order systems: x'' = a(t, x, x')
 * becomes y = (x, v), y' = (v, a).
 *
 * How to call it (problem / options / workspace / result, see STYLE.md §3):
 *
 *     mm_ode_problem prob = { .n = 2, .f = rhs, .params = &p,
 *                             .t0 = 0, .t_end = 10, .y0 = y0 };
 *     mm_ode_options opt;
 *     mm_ode_options_init(&opt);            // DOPRI5, rtol 1e-6, atol 1e-9
 *     mm_ode_result res = {0};
 *     res.t_out = t; res.nout = 500; res.y_out = y;   // a plot: 500 x 2 values
 *     rc = mm_ode_check(&prob, &opt, &res, &err);      // before allocating
 *     mm_ode_work *w = mm_ode_work_alloc(prob.n);
 *     if (rc == MM_OK) rc = mm_ode_solve(&prob, &opt, w, &res, &err);
 *     mm_ode_work_free(w);
 *
 * Output on a grid: the caller lists the times; the solver steps as the
 * tolerance allows and fills the grid by the method's continuous extension
 * (dense output) between steps.  It never shortens a step to hit a grid
 * point, so a 1000-point plot costs little more than the end value alone
 * (DOP853 calls f 3 more times in each step that holds grid points).  The
 * extensions are of order 3 (RK4, cubic Hermite), 4 (DOPRI5) and 7
 * (DOP853): grid values are about as accurate as the tolerance asks, while
 * DOP853's step values, 8th order, are usually more accurate still.
 *
 * Thread safety: no global or static mutable state.  Each call reads only
 * its arguments; a workspace belongs to one call at a time.  Any number of
 * threads may integrate at once, each with its own workspace.
 *
 * Conventions: time runs forward only (t_end > t0).  Arrays of states are
 * row-major: row i holds the n components at time i.  Units are the
 * caller's; the comments say seconds for t because mechmat's are.
 */
#ifndef MM_ODE_H
#define MM_ODE_H

#include <stddef.h>

#include "mm_status.h"

/* Limits, checked by mm_ode_check before anything is allocated. */
#define MM_ODE_MAX_DIM    1024L      /* most equations in one system */
#define MM_ODE_MAX_STEPS  10000000L  /* highest allowed options.max_steps */
#define MM_ODE_RTOL_MIN   1e-14      /* smallest rtol that double can honour */

/* Right-hand side: write f(t, y) into dydt (n values).  y is read-only.
 * Return 0 to go on; any other value stops the integration (see
 * mm_ode_solve).  It is called at trial states too, including those of
 * steps that are later rejected. */
typedef int (*mm_ode_rhs)(double t, const double *y, double *dydt,
                          void *params);

/* Event function: write g(t, y) into *g.  Return 0 to go on, nonzero to
 * stop the integration (as the right-hand side).  See "Events" below. */
typedef int (*mm_ode_event_fn)(double t, const double *y, double *g,
                               void *params);

typedef enum mm_ode_method {
    MM_ODE_RK4 = 0,    /* classical Runge–Kutta, 4 stages, fixed step h */
    MM_ODE_DOPRI5,     /* Dormand–Prince 5(4), 7 stages (6 with FSAL) */
    MM_ODE_DOP853      /* Dormand–Prince 8(5,3), 12 stages (+3 for dense output) */
} mm_ode_method;

/* The problem: owned by the caller, never modified. */
typedef struct mm_ode_problem {
    size_t n;            /* number of equations, 1..MM_ODE_MAX_DIM */
    mm_ode_rhs f;        /* right-hand side f(t, y) */
    void *params;        /* handed to f untouched */
    double t0;           /* start time [s] */
    double t_end;        /* end time [s], > t0 */
    const double *y0;    /* initial state, n values (read only) */
    mm_ode_event_fn event; /* NULL, or g(t, y): the run stops at its first
                            zero crossed in event_dir (see "Events") */
    int event_dir;       /* -1: g falls through 0 (from > 0 to <= 0);
                            +1: g rises (from < 0 to >= 0); 0: either */
} mm_ode_problem;

/* Events.  With prob.event set, the solver evaluates g at the start and at
 * the end of every accepted step (fixed or adaptive).  When g has crossed
 * zero in the direction asked since the last accepted step, the zero is
 * located on the method's continuous extension (the dense output, of
 * order 3, 4 and 7 for RK4, DOPRI5 and DOP853) by Brent's method to a few
 * eps of t, and the run stops there:
 *   - res.event = 1, res.t_event = t_reached = the zero (<= t_end);
 *   - y_end and the last recorded step (t_steps / y_steps) hold the state
 *     at the zero, from the continuous extension;
 *   - grid rows are written only up to t_event: nout_done says how many;
 *   - mm_ode_solve returns MM_OK.
 * The error of t_event is the extension's error in g over |dg/dt| (plus a
 * few eps |t|): a tolerance rtol gives an event time good to about rtol of
 * the time scale of g.  A zero of g at t0 itself does not count (a run
 * may start on the surface: a mass at rest whose velocity is g).  Two
 * zeros inside one step cancel and go unseen: cap the step (h_max) below
 * the shortest time between zeros when that can happen.  Without a zero
 * the run ends at t_end with res.event = 0. */

/* How to integrate: fill with mm_ode_options_init, then change fields. */
typedef struct mm_ode_options {
    mm_ode_method method;  /* default MM_ODE_DOPRI5 */
    double rtol;      /* relative tolerance, MM_ODE_RTOL_MIN..1 (default 1e-6) */
    double atol;      /* absolute tolerance, units of y, > 0 (default 1e-9) */
    double h;         /* fixed step [s].  Required (> 0) for RK4.  For DOPRI5
                         and DOP853, h > 0 switches the error control off and
                         takes equal steps (for order studies); 0 = adaptive.
                         Fixed steps are made equal: N = ceil((t_end - t0)/h)
                         steps of (t_end - t0)/N <= h each. */
    double h_init;    /* first trial step [s] of an adaptive run; 0 = choose
                         it automatically (Hairer's HINIT, costs one f call).
                         Either way, until a step is accepted each trial is
                         checked against the error estimate of its first
                         half (n_first_halves): a step too long for its
                         estimate to be asymptotic is rejected, however
                         small the estimate at its whole length. */
    double h_max;     /* largest step [s] of an adaptive run; 0 = no limit */
    long max_steps;   /* most step attempts (accepted + rejected), 1..
                         MM_ODE_MAX_STEPS (default 100000) */
    int pi_control;   /* 1 = PI step-size control, smoother step sequences
                         (default); 0 = the elementary controller */
} mm_ode_options;

/* The defaults of mm_ode_options_init with an adaptive method m, its
 * tolerances and its budget of step attempts: the options of most runs in
 * one expression. */
mm_ode_options mm_ode_options_adaptive(mm_ode_method m, double rtol, double atol, long max_steps);

/* Opaque scratch space for systems up to a size n (28 n doubles). */
typedef struct mm_ode_work mm_ode_work;

/* What to write and what happened.  The caller sets the array fields it
 * wants (unused pointers NULL, counts 0: start from `mm_ode_result r = {0}`);
 * the solver fills the rest.  The solver never allocates or frees them. */
typedef struct mm_ode_result {
    /* --- set by the caller ------------------------------------------------ */
    const double *t_out; /* nout output times [s], nondecreasing, each in
                            [t0, t_end]; read only */
    size_t nout;         /* 0 = no grid output */
    double *y_out;       /* nout x n, OVERWRITTEN: y_out[i*n + j] = y_j(t_out[i]) */
    double *y_end;       /* n values or NULL, OVERWRITTEN: state at t_reached */
    double *t_steps;     /* steps_cap values or NULL, OVERWRITTEN: t0, then
                            the end time of every accepted step */
    double *y_steps;     /* steps_cap x n or NULL, OVERWRITTEN: the states
                            at those times */
    size_t steps_cap;    /* room in t_steps / y_steps; 0 = do not record */
    /* --- filled by mm_ode_solve (also when it fails) ----------------------- */
    double t_reached;    /* time of the last accepted state [s] (t_end on success) */
    size_t nout_done;    /* grid rows written: t_out[0..nout_done-1] (nout on success) */
    size_t n_stored;     /* entries written to t_steps / y_steps */
    long n_accepted;     /* accepted steps */
    long n_rejected;     /* steps rejected by the error test (or non-finite) */
    long n_eval;         /* calls of f, all included */
    double h_smallest;   /* smallest and largest accepted step [s] */
    double h_largest;
    double err_local_max;/* largest local error estimate of an accepted step,
                            max norm, units of y */
    double err_sum;      /* sum of the local error estimates of the accepted
                            steps: a rough guide to the global error, which
                            can be smaller (a damped system forgets) or larger
                            (a growing one amplifies).  The estimates belong
                            to the lower-order partner of each method (3rd
                            order for RK4, 4th for DOPRI5, the 5th/3rd blend
                            for DOP853), so they are cautious for the
                            higher-order solution actually propagated. */
    int stiff;           /* 1 if Hairer's stiffness test fired: the step size
                            was held at the stability limit for 15 steps */
    int event;           /* 1: the run stopped at a zero of prob.event */
    double t_event;      /* its time [s] (valid when event = 1) */
    long n_event_evals;  /* calls of the event function */
    long n_first_halves; /* adaptive runs: half steps taken to check the
                            first step's error estimate, one per trial of
                            the first step (each costs a step's calls of f,
                            counted in n_eval; see h_init) */
} mm_ode_result;

/* Fill opt with the defaults above.  Cannot fail. */
void mm_ode_options_init(mm_ode_options *opt);

/* The steps of a fixed-step run (RK4, or opt.h > 0) over a span T [s]
 * with the step asked h [s]: N = ceil(T / h), taken as N equal steps of
 * T / N <= h; the ceiling has a relative slack of 1e-12, so that rounding
 * (10 / 0.001 = 10000.000000000002) does not add a step.  At least 1.
 * A double: it may be huge before mm_ode_check refuses it.  T > 0 and
 * h > 0 finite; cannot fail. */
double mm_ode_fixed_steps(double T, double h);

/* Name of a method ("rk4", "dopri5", "dop853"), "unknown" otherwise.
 * Cannot fail. */
const char *mm_ode_method_name(mm_ode_method method);

/* Workspace for systems of up to n equations.  Returns NULL if n is 0 or
 * above MM_ODE_MAX_DIM or memory runs out.  mm_ode_work_free(NULL) does
 * nothing. */
mm_ode_work *mm_ode_work_alloc(size_t n);
void mm_ode_work_free(mm_ode_work *w);

/* Validate a request without doing any work: no allocation, no call of f,
 * nothing written except *err.  res may be NULL (then only problem and
 * options are checked).  Returns MM_OK or:
 *   MM_EVALUE  a non-finite number: t0, t_end, y0[i], rtol, atol, h,
 *              h_init, h_max or t_out[i] (param names the field);
 *   MM_ERANGE  a finite value outside its limits: n ("n"), t_end <= t0
 *              ("t_end"), unknown method ("method"), rtol outside
 *              [MM_ODE_RTOL_MIN, 1], atol <= 0, h <= 0 for RK4 or h < 0,
 *              h_init < 0, h_max < 0, max_steps outside [1, MM_ODE_MAX_STEPS],
 *              a fixed-step run needing more than max_steps steps, or with
 *              steps too small to advance t in double precision ("h"),
 *              a t_out value outside [t0, t_end] or out of order ("t_out").
 * Pointer misuse (f or y0 NULL, nout > 0 with t_out or y_out NULL,
 * steps_cap > 0 with t_steps or y_steps NULL) is a programmer error and
 * trips an assert. */
int mm_ode_check(const mm_ode_problem *prob, const mm_ode_options *opt,
                 const mm_ode_result *res, mm_error *err);

/* Integrate prob from t0 to t_end with opt, writing into res (see the
 * OVERWRITTEN fields above; all counters are reset first).  w must come from
 * mm_ode_work_alloc(m) with m >= prob->n; its contents are overwritten.
 * prob, opt and y0 are only read.  err may be NULL.
 *
 * Returns MM_OK with t_reached == t_end, nout_done == nout (or, stopped by
 * an event, t_reached == t_event and the rows up to it), or fails with:
 *   any code of mm_ode_check (then nothing else has happened);
 *   MM_ENOMEM      w is NULL (a failed mm_ode_work_alloc);
 *   MM_ENOCONV     max_steps step attempts were not enough ("max_steps";
 *                  the message says whether the stiffness test fired), or
 *                  the step size shrank below what double precision can
 *                  resolve at t ("rtol"); the message says where and why;
 *   MM_ENONFINITE  the state became NaN or infinite: a fixed step too large
 *                  for stability ("h"), a solution that blows up so that
 *                  shrinking adaptive steps cannot avoid it ("y"), or f not
 *                  finite at the start ("f");
 *   MM_ETOOBIG     t_steps / y_steps filled up before t_end ("steps");
 *   the value returned by f, when f returns nonzero and that value is an
 *                  mm_status code (otherwise MM_EINTERNAL); param is "f".
 * On failure res still describes everything done up to t_reached: y_end
 * holds the state there, and the first nout_done grid rows and n_stored
 * steps are valid. */
int mm_ode_solve(const mm_ode_problem *prob, const mm_ode_options *opt,
                 mm_ode_work *w, mm_ode_result *res, mm_error *err);

/* mm_ode_check, then mm_ode_solve with a workspace of prob->n allocated and
 * freed here (none when the check refuses): the whole ritual of a single
 * run.  Returns as mm_ode_solve. */
int mm_ode_run(const mm_ode_problem *prob, const mm_ode_options *opt, mm_ode_result *res, mm_error *err);

#endif
