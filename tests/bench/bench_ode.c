/* bench_ode.c — work against achieved error for mm_ode and GSL's odeiv2.
 *
 * Problem: the forced damped oscillator
 *     m x'' + c x' + k x = F0 cos(omega t),  m = 1, c = 2, k = 100, F0 = 1,
 *     omega = 8, x(0) = 0, x'(0) = 0, t in [0, 10],
 * whose exact solution (transient + steady state) is written out in exact().
 *
 * Tables:
 *   1. fixed-step RK4 by number of steps;
 *   2. adaptive methods at rtol = atol = 1e-3 .. 1e-12: ours DOPRI5, DOP853
 *      and GSL rkf45, rk8pd (gsl_odeiv2 evolve loop, control_y_new, the
 *      same loop gsl_odeiv2_driver_apply runs), with achieved error,
 *      calls of f and wall time;
 *   3. the ratios at matched achieved error (log-log interpolation between
 *      tolerance points): ours DOPRI5 / GSL rkf45, ours DOP853 / GSL rk8pd;
 *   4. a 1000-point output grid: GSL's driver stepping to each point
 *      against ours filling the grid by dense output.
 *
 * Achieved error = max |x - x_exact| over every accepted step point (the
 * natural output of each code, so both are measured the same way).  For our
 * codes the table also shows the max error over a 2001-point check grid
 * filled by dense output, to show the interpolant costs no accuracy.
 * Wall time: best of 11 batches of >= 5 ms, taken in round-robin passes over
 * all runs so that a burst of load from elsewhere spoils one pass only.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "mm_ode.h"

#define T_END 10.0
#define NTOL 10          /* tolerances 1e-3 .. 1e-12 */
#define NCHECK 2001      /* check grid for dense-output error */
#define NPLOT 1000       /* the plot grid of table 4 */
#define MAXREC 400000    /* room for recorded steps */

/* ---- the problem ---------------------------------------------------------- */

typedef struct counter {
    long calls;
} counter;

static void osc_rhs(double t, const double *y, double *dydt)
{
    dydt[0] = y[1];                                       /* x' = v */
    dydt[1] = cos(8.0 * t) - 2.0 * y[1] - 100.0 * y[0];   /* v' = (F - c v - k x)/m */
}

static int rhs_mm(double t, const double *y, double *dydt, void *params)
{
    ((counter *)params)->calls++;
    osc_rhs(t, y, dydt);
    return 0;
}

static int rhs_gsl(double t, const double y[], double dydt[], void *params)
{
    ((counter *)params)->calls++;
    osc_rhs(t, y, dydt);
    return GSL_SUCCESS;
}

/* x(t) for x(0) = x'(0) = 0.  Steady state A cos 8t + B sin 8t with
 * (k - 64) A + 16 B = 1, (k - 64) B - 16 A = 0  ->  A = 9/388, B = 1/97;
 * transient e^{-t} (C cos wd t + D sin wd t), wd = sqrt(99) (zeta = 0.1,
 * wn = 10), with C = x0 - A, D = (v0 + C - 8 B) / wd. */
static double exact(double t)
{
    const double A = 9.0 / 388.0, B = 1.0 / 97.0, wd = sqrt(99.0);
    const double C = -A, D = (C - 8.0 * B) / wd;
    return A * cos(8.0 * t) + B * sin(8.0 * t)
           + exp(-t) * (C * cos(wd * t) + D * sin(wd * t));
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---- one run of each code --------------------------------------------------- */

typedef struct point {
    double tol;
    long acc, rej, evals;
    double err;        /* max error at step points */
    double err_grid;   /* max error on the check grid (ours), or NAN */
    double us;         /* wall time per run [us] */
} point;

static double *rec_t, *rec_y;      /* recorded steps (ours) */
static double check_t[NCHECK], check_y[2 * NCHECK];

/* Ours.  With record: steps and check grid are written (for the errors);
 * without: only the end state, as a bare solve would be timed. */
static int run_mm(mm_ode_method method, double tol, double h, int record,
                  mm_ode_work *w, mm_ode_result *res, counter *cnt)
{
    static const double y0[2] = {0.0, 0.0};
    mm_ode_problem prob = {.n = 2, .f = rhs_mm, .params = cnt,
                           .t0 = 0.0, .t_end = T_END, .y0 = y0};
    mm_ode_options opt;
    mm_ode_options_init(&opt);
    opt.method = method;
    opt.rtol = opt.atol = tol;
    opt.h = h;
    opt.max_steps = MM_ODE_MAX_STEPS;
    double y_end[2];
    memset(res, 0, sizeof *res);
    res->y_end = y_end;
    if (record) {
        res->t_steps = rec_t;
        res->y_steps = rec_y;
        res->steps_cap = MAXREC;
        res->t_out = check_t;
        res->nout = NCHECK;
        res->y_out = check_y;
    }
    mm_error err;
    int rc = mm_ode_solve(&prob, &opt, w, res, &err);
    if (rc)
        fprintf(stderr, "mm_ode_solve: %s\n", err.msg);
    return rc;
}

/* GSL: the evolve loop of gsl_odeiv2_driver_apply, optionally recording
 * the max error at each accepted step. */
static int run_gsl(const gsl_odeiv2_step_type *T, double tol, double *err_max,
                   long *acc, long *rej, counter *cnt)
{
    gsl_odeiv2_system sys = {rhs_gsl, NULL, 2, cnt};
    gsl_odeiv2_step *s = gsl_odeiv2_step_alloc(T, 2);
    gsl_odeiv2_control *c = gsl_odeiv2_control_y_new(tol, tol);
    gsl_odeiv2_evolve *e = gsl_odeiv2_evolve_alloc(2);
    double t = 0.0, h = 1e-3, y[2] = {0.0, 0.0}, emax = 0.0;
    int rc = GSL_SUCCESS;
    while (t < T_END) {
        rc = gsl_odeiv2_evolve_apply(e, c, s, &sys, &t, T_END, &h, y);
        if (rc != GSL_SUCCESS)
            break;
        if (err_max)
            emax = fmax(emax, fabs(y[0] - exact(t)));
    }
    if (err_max)
        *err_max = emax;
    if (acc)
        *acc = (long)(e->count - e->failed_steps);
    if (rej)
        *rej = (long)e->failed_steps;
    gsl_odeiv2_evolve_free(e);
    gsl_odeiv2_control_free(c);
    gsl_odeiv2_step_free(s);
    return rc;
}

/* ---- timing ------------------------------------------------------------------ */

typedef struct job {
    int gsl;
    mm_ode_method method;
    const gsl_odeiv2_step_type *T;
    double tol, h;
    mm_ode_work *w;
    long reps;        /* runs per batch */
    double *us;       /* where the best time per run goes [us] */
} job;

#define MAX_JOBS 64
static job jobs[MAX_JOBS];
static int n_jobs;

/* Queue a timing; time_all() fills *us later. */
static void queue_job(job j, double *us)
{
    if (n_jobs == MAX_JOBS) {
        fprintf(stderr, "too many timing jobs\n");
        exit(1);
    }
    j.us = us;
    jobs[n_jobs++] = j;
}

static void run_job(const job *j)
{
    counter cnt = {0};
    if (j->gsl) {
        run_gsl(j->T, j->tol, NULL, NULL, NULL, &cnt);
    } else {
        mm_ode_result res;
        run_mm(j->method, j->tol, j->h, 0, j->w, &res, &cnt);
    }
}

/* Every queued job in round-robin passes, each pass one batch of >= 5 ms
 * per job; the best batch of 11 passes gives microseconds per run.  Spread
 * over the whole run this way, a burst of load from another process spoils
 * one pass of each job, not every pass of a few. */
static void time_all(void)
{
    for (int k = 0; k < n_jobs; k++) {          /* size the batches */
        job *j = &jobs[k];
        for (j->reps = 1;; j->reps *= 2) {
            double t0 = now();
            for (long i = 0; i < j->reps; i++)
                run_job(j);
            if (now() - t0 >= 0.005)
                break;
        }
        *j->us = INFINITY;
    }
    for (int pass = 0; pass < 11; pass++)
        for (int k = 0; k < n_jobs; k++) {
            job *j = &jobs[k];
            double t0 = now();
            for (long i = 0; i < j->reps; i++)
                run_job(j);
            double us = (now() - t0) / (double)j->reps * 1e6;
            if (us < *j->us)
                *j->us = us;
        }
}

/* ---- matched-error interpolation ---------------------------------------- */

/* log-log interpolation of evals (what = 0) or time (what = 1) at achieved
 * error E: scan the points in order of tightening tolerance for the first
 * pair whose errors bracket E.  NAN when E is outside the measured range. */
static double at_error(const point *p, int np, double E, int what)
{
    for (int i = 0; i + 1 < np; i++) {
        double e0 = p[i].err, e1 = p[i + 1].err;
        if (e0 >= E && E >= e1 && e0 > e1) {
            double s = (log(E) - log(e0)) / (log(e1) - log(e0));
            double v0 = what ? p[i].us : (double)p[i].evals;
            double v1 = what ? p[i + 1].us : (double)p[i + 1].evals;
            return exp(log(v0) + s * (log(v1) - log(v0)));
        }
    }
    return NAN;
}

/* Fewest calls among the runs whose error is <= E (NAN if none). */
static double cheapest(const point *p, int np, double E)
{
    double best = NAN;
    for (int i = 0; i < np; i++)
        if (p[i].err <= E && (isnan(best) || (double)p[i].evals < best))
            best = (double)p[i].evals;
    return best;
}

/* ---- tables ------------------------------------------------------------------ */

static void print_points(const char *name, const point *p, int np)
{
    printf("\n%s\n", name);
    printf("  %-8s %8s %6s %9s %11s %11s %10s\n", "rtol=atol", "accepted",
           "reject", "f calls", "max err", "grid err", "time [us]");
    for (int i = 0; i < np; i++) {
        printf("  %-8.0e %8ld %6ld %9ld %11.3e ", p[i].tol, p[i].acc, p[i].rej,
               p[i].evals, p[i].err);
        if (isnan(p[i].err_grid))
            printf("%11s", "-");
        else
            printf("%11.3e", p[i].err_grid);
        printf(" %10.1f\n", p[i].us);
    }
}

static void sweep_mm(mm_ode_method method, mm_ode_work *w, point *p)
{
    for (int i = 0; i < NTOL; i++) {
        double tol = pow(10.0, -3 - i);
        counter cnt = {0};
        mm_ode_result res;
        run_mm(method, tol, 0.0, 1, w, &res, &cnt);
        double e = 0.0, eg = 0.0;
        for (size_t k = 0; k < res.n_stored; k++)
            e = fmax(e, fabs(rec_y[2 * k] - exact(rec_t[k])));
        for (int k = 0; k < NCHECK; k++)
            eg = fmax(eg, fabs(check_y[2 * k] - exact(check_t[k])));
        cnt.calls = 0;                          /* calls without the grid */
        run_mm(method, tol, 0.0, 0, w, &res, &cnt);
        p[i] = (point){tol, res.n_accepted, res.n_rejected, res.n_eval, e, eg, NAN};
        queue_job((job){.gsl = 0, .method = method, .tol = tol, .w = w}, &p[i].us);
    }
}

static void sweep_gsl(const gsl_odeiv2_step_type *T, point *p)
{
    for (int i = 0; i < NTOL; i++) {
        double tol = pow(10.0, -3 - i), e;
        long acc, rej;
        counter cnt = {0};
        run_gsl(T, tol, &e, &acc, &rej, &cnt);
        p[i] = (point){tol, acc, rej, cnt.calls, e, NAN, NAN};
        queue_job((job){.gsl = 1, .T = T, .tol = tol}, &p[i].us);
    }
}

static void print_ratios(const char *ours_name, const point *ours,
                         const char *gsl_name, const point *gsl)
{
    printf("\n%s against %s at matched achieved error (ratio < 1: ours cheaper)\n",
           ours_name, gsl_name);
    printf("  %-9s %10s %10s %7s %11s %11s %7s\n", "max err", "ours f", "GSL f",
           "ratio", "ours [us]", "GSL [us]", "ratio");
    for (int e = 4; e <= 11; e++) {
        double E = pow(10.0, -e);
        double fo = at_error(ours, NTOL, E, 0), fg = at_error(gsl, NTOL, E, 0);
        double to = at_error(ours, NTOL, E, 1), tg = at_error(gsl, NTOL, E, 1);
        if (isnan(fo) || isnan(fg)) {
            printf("  %-9.0e %10s (outside the measured range of one code)\n",
                   E, "-");
            continue;
        }
        printf("  %-9.0e %10.0f %10.0f %7.2f %11.1f %11.1f %7.2f\n", E, fo, fg,
               fo / fg, to, tg, to / tg);
    }
}

/* Table 4: the plot grid. */
static void plot_grid(mm_ode_method method, const gsl_odeiv2_step_type *T,
                      mm_ode_work *w)
{
    static double tp[NPLOT], yp[2 * NPLOT];
    for (int i = 0; i < NPLOT; i++)
        tp[i] = T_END * (double)(i + 1) / NPLOT;
    point ours[NTOL], gsl[NTOL];
    static const double y0[2] = {0.0, 0.0};

    for (int i = 0; i < NTOL; i++) {
        double tol = pow(10.0, -3 - i);
        /* ours: one run, grid by dense output */
        counter cnt = {0};
        mm_ode_problem prob = {.n = 2, .f = rhs_mm, .params = &cnt,
                               .t0 = 0.0, .t_end = T_END, .y0 = y0};
        mm_ode_options opt;
        mm_ode_options_init(&opt);
        opt.method = method;
        opt.rtol = opt.atol = tol;
        mm_ode_result res = {0};
        res.t_out = tp;
        res.nout = NPLOT;
        res.y_out = yp;
        mm_error err;
        if (mm_ode_solve(&prob, &opt, w, &res, &err))
            fprintf(stderr, "mm_ode_solve: %s\n", err.msg);
        double e = 0.0;
        for (int k = 0; k < NPLOT; k++)
            e = fmax(e, fabs(yp[2 * k] - exact(tp[k])));
        ours[i] = (point){tol, res.n_accepted, res.n_rejected, res.n_eval, e,
                          NAN, 0.0};

        /* GSL: the driver, applied to each grid point in turn */
        counter gc = {0};
        gsl_odeiv2_system sys = {rhs_gsl, NULL, 2, &gc};
        gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, T, 1e-3,
                                                             tol, tol);
        double t = 0.0, y[2] = {0.0, 0.0};
        e = 0.0;
        for (int k = 0; k < NPLOT; k++) {
            if (gsl_odeiv2_driver_apply(d, &t, tp[k], y) != GSL_SUCCESS)
                break;
            e = fmax(e, fabs(y[0] - exact(tp[k])));
        }
        gsl[i] = (point){tol, 0, 0, gc.calls, e, NAN, 0.0};
        gsl_odeiv2_driver_free(d);
    }

    printf("\n%d-point output grid: ours %s (dense output) against GSL %s "
           "(driver to each point)\n", NPLOT, mm_ode_method_name(method),
           T->name);
    printf("  %-8s %9s %11s %9s %11s\n", "rtol=atol", "ours f", "ours err",
           "GSL f", "GSL err");
    for (int i = 0; i < NTOL; i++)
        printf("  %-8.0e %9ld %11.3e %9ld %11.3e\n", ours[i].tol, ours[i].evals,
               ours[i].err, gsl[i].evals, gsl[i].err);
    printf("  cheapest run reaching max err <= E (ours interpolated in log-log; GSL's\n"
           "  driver errors all sit near round-off, so its cost is the same for any E):\n");
    printf("  %-9s %9s %9s %11s\n", "E", "ours f", "GSL f", "GSL / ours");
    for (int e = 4; e <= 10; e += 2) {
        double E = pow(10.0, -e);
        double fo = at_error(ours, NTOL, E, 0), fg = cheapest(gsl, NTOL, E);
        if (isnan(fo) || isnan(fg))
            printf("  %-9.0e  (outside the measured range)\n", E);
        else
            printf("  %-9.0e %9.0f %9.0f %10.1fx\n", E, fo, fg, fg / fo);
    }
}

int main(void)
{
    gsl_set_error_handler_off();
    rec_t = malloc(MAXREC * sizeof(double));
    rec_y = malloc(2 * MAXREC * sizeof(double));
    mm_ode_work *w = mm_ode_work_alloc(2);
    if (!rec_t || !rec_y || !w) {
        fprintf(stderr, "out of memory\n");
        return 1;
    }
    for (int i = 0; i < NCHECK; i++)
        check_t[i] = T_END * (double)i / (NCHECK - 1);

    printf("Forced damped oscillator x'' + 2x' + 100x = cos 8t, x(0) = x'(0) = 0, "
           "t in [0, 10]\n");
    printf("max err: max |x - x_exact| over accepted step points; grid err: "
           "over %d points by dense output\n", NCHECK);

    /* Measure everything first (errors and calls), queueing the timings;
     * time them all together; then print. */
    enum { NRK4 = 10 };
    struct { long N; long evals; double err, err_grid, us; } rk4[NRK4];
    for (int i = 0; i < NRK4; i++) {
        long N = 100L << i;
        counter cnt = {0};
        mm_ode_result res;
        double h = T_END / (double)N;
        run_mm(MM_ODE_RK4, 1e-6, h, 1, w, &res, &cnt);
        double e = 0.0, eg = 0.0;
        for (size_t k = 0; k < res.n_stored; k++)
            e = fmax(e, fabs(rec_y[2 * k] - exact(rec_t[k])));
        for (int k = 0; k < NCHECK; k++)
            eg = fmax(eg, fabs(check_y[2 * k] - exact(check_t[k])));
        rk4[i].N = N;
        rk4[i].evals = res.n_eval;
        rk4[i].err = e;
        rk4[i].err_grid = eg;
        queue_job((job){.gsl = 0, .method = MM_ODE_RK4, .tol = 1e-6, .h = h,
                        .w = w}, &rk4[i].us);
    }
    point dp5[NTOL], dop[NTOL], rkf[NTOL], rk8[NTOL];
    sweep_mm(MM_ODE_DOPRI5, w, dp5);
    sweep_mm(MM_ODE_DOP853, w, dop);
    sweep_gsl(gsl_odeiv2_step_rkf45, rkf);
    sweep_gsl(gsl_odeiv2_step_rk8pd, rk8);
    time_all();

    /* 1. RK4 by steps */
    printf("\nfixed-step RK4 (ours)\n");
    printf("  %8s %9s %11s %11s %10s\n", "steps", "f calls", "max err",
           "grid err", "time [us]");
    for (int i = 0; i < NRK4; i++)
        printf("  %8ld %9ld %11.3e %11.3e %10.1f\n", rk4[i].N, rk4[i].evals,
               rk4[i].err, rk4[i].err_grid, rk4[i].us);

    /* 2. adaptive methods */
    print_points("ours DOPRI5 (5th order, error 4th, PI control)", dp5, NTOL);
    print_points("GSL rkf45 (evolve loop, control_y_new, h0 = 1e-3)", rkf, NTOL);
    print_points("ours DOP853 (8th order, error 5th+3rd, PI control)", dop, NTOL);
    print_points("GSL rk8pd (evolve loop, control_y_new, h0 = 1e-3)", rk8, NTOL);

    /* 3. matched error */
    print_ratios("ours DOPRI5", dp5, "GSL rkf45", rkf);
    print_ratios("ours DOP853", dop, "GSL rk8pd", rk8);

    /* 4. plot grid */
    plot_grid(MM_ODE_DOPRI5, gsl_odeiv2_step_rkf45, w);
    plot_grid(MM_ODE_DOP853, gsl_odeiv2_step_rk8pd, w);

    mm_ode_work_free(w);
    free(rec_y);
    free(rec_t);
    return 0;
}
