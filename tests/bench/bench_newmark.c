/* bench_newmark.c — work against achieved error for the mm_newmark schemes.
 *
 * Problem 1: the forced damped oscillator
 *     x'' + 2 x' + 100 x = cos 8t,  x(0) = 0, x'(0) = 0,  t in [0, 10],
 * exact solution (transient + steady state) in exact().  Natural period
 * T = 2 pi / 10 = 0.628 s.
 *
 * Tables:
 *   1. for each scheme and h = T/10 ... T/1000: steps, calls of F, max
 *      |x - x_exact| over every step, the observed order from consecutive
 *      rows, the energy-balance residual (an error indicator that needs no
 *      exact solution), wall time;
 *   2. calls of F for a max error of 1e-6 (log-log interpolation in table 1),
 *      to set beside PERFORMANCE.md's yardsticks;
 *   3. over 1e5 periods of x'' + x = 0 at 20 steps per period: energy error
 *      and phase error of Verlet, average acceleration and HHT-alpha, with
 *      the textbook values.
 * Wall time: best of 5 batches, each repeated for at least 20 ms.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "mm_newmark.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define T_END 10.0
#define NRES 7          /* steps per period: 10 20 50 100 200 500 1000 */

/* ---- problem 1 ------------------------------------------------------------ */

static int force(double t, const double *q, const double *qd, double *F, void *params)
{
    (void)q;
    (void)qd;
    (void)params;
    F[0] = cos(8.0 * t);
    return 0;
}

/* x(t) for x(0) = x'(0) = 0: steady state A cos 8t + B sin 8t with
 * A = 9/388, B = 1/97, plus e^{-t} (C cos wd t + D sin wd t), wd = sqrt 99. */
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

typedef struct scheme {
    const char *label;
    mm_newmark_method method;
    double param;                   /* alpha or rho_inf */
    mm_newmark_force_kind kind;     /* TIME: factored once; STATE: Newton */
} scheme;

static const scheme schemes[] = {
    {"average acceleration",       MM_NEWMARK_AVERAGE, 0.0, MM_NEWMARK_FORCE_TIME},
    {"  same, F flagged F(t,q,q')", MM_NEWMARK_AVERAGE, 0.0, MM_NEWMARK_FORCE_STATE},
    {"linear acceleration",        MM_NEWMARK_LINEAR, 0.0, MM_NEWMARK_FORCE_TIME},
    {"hht-alpha, alpha = -0.1",    MM_NEWMARK_HHT, -0.1, MM_NEWMARK_FORCE_TIME},
    {"generalized-alpha, rho 0.8", MM_NEWMARK_GENERALIZED_ALPHA, 0.8, MM_NEWMARK_FORCE_TIME},
    {"central difference",         MM_NEWMARK_CENTRAL, 0.0, MM_NEWMARK_FORCE_TIME},
    {"stormer-verlet (C != 0)",    MM_NEWMARK_VERLET, 0.0, MM_NEWMARK_FORCE_TIME},
};
#define NSCHEME ((int)(sizeof schemes / sizeof schemes[0]))

typedef struct row {
    long steps, evals;
    double h, err, balance, us;
} row;

static int run_once(const scheme *s, double h, double *t, double *q,
                    int max_rows, mm_newmark_work *w, mm_newmark_result *res)
{
    static const double m = 1.0, c = 2.0, k = 100.0;
    mm_newmark_problem p;
    memset(&p, 0, sizeof p);
    p.n = 1; p.M = &m; p.C = &c; p.K = &k;
    p.force = force; p.force_kind = s->kind;
    p.t0 = 0.0; p.t_end = T_END;
    mm_newmark_options o;
    mm_newmark_options_init(&o);
    o.method = s->method;
    o.h = h;
    o.alpha = s->method == MM_NEWMARK_HHT ? s->param : o.alpha;
    o.rho_inf = s->method == MM_NEWMARK_GENERALIZED_ALPHA ? s->param : o.rho_inf;
    memset(res, 0, sizeof *res);
    res->t = t; res->q = q; res->max_rows = max_rows;
    mm_error err;
    int rc = mm_newmark_solve(&p, &o, w, res, &err);
    if (rc)
        fprintf(stderr, "%s, h = %g: %s\n", s->label, h, err.msg);
    return rc;
}

static row measure(const scheme *s, int per_period, mm_newmark_work *w)
{
    const double T = 2.0 * M_PI / 10.0;
    long N = lround(T_END / (T / per_period));  /* h divides [0, 10] */
    double h = T_END / (double)N;
    double *t = malloc((size_t)(N + 1) * sizeof *t), *q = malloc((size_t)(N + 1) * sizeof *q);
    mm_newmark_result res;
    row r = {0, 0, h, NAN, NAN, NAN};
    if (!t || !q || run_once(s, h, t, q, (int)N + 1, w, &res)) {
        free(t);
        free(q);
        return r;
    }
    r.steps = res.steps;
    r.evals = res.force_evals;
    r.balance = res.energy_error;
    r.err = 0.0;
    for (int i = 0; i < res.rows; i++)
        r.err = fmax(r.err, fabs(q[i] - exact(t[i])));

    double best = INFINITY;                 /* time: best of 5 batches >= 20 ms */
    for (int b = 0; b < 5; b++) {
        int reps = 0;
        double t0 = now(), el;
        do {
            run_once(s, h, t, q, (int)N + 1, w, &res);
            reps++;
            el = now() - t0;
        } while (el < 0.02);
        best = fmin(best, el / reps);
    }
    r.us = 1e6 * best;
    free(t);
    free(q);
    return r;
}

/* ---- problem 2: 1e5 periods of x'' + x = 0 ---------------------------------- */

static void long_run(const char *label, mm_newmark_method method, double alpha,
                     double theory_phase, const char *theory_note)
{
    const double Oh = 2.0 * M_PI / 20.0, m = 1.0, k = 1.0, x0 = 1.0;
    const long N = 2000000, stride = 5;     /* 4 samples per period for unwrapping */
    mm_newmark_problem p;
    memset(&p, 0, sizeof p);
    p.n = 1; p.M = &m; p.K = &k; p.q0 = &x0;
    p.t0 = 0.0; p.t_end = 1e5 * 2.0 * M_PI;
    mm_newmark_options o;
    mm_newmark_options_init(&o);
    o.method = method; o.h = Oh; o.alpha = alpha;
    o.stride = stride; o.max_steps = 3 * N;
    int rows = mm_newmark_output_rows(&p, &o);
    mm_newmark_result res;
    memset(&res, 0, sizeof res);
    res.t = malloc((size_t)rows * sizeof *res.t);
    res.q = malloc((size_t)rows * sizeof *res.q);
    res.qd = malloc((size_t)rows * sizeof *res.qd);
    res.max_rows = rows;
    mm_newmark_work *w = mm_newmark_work_alloc(1);
    mm_error err;
    double t0 = now();
    int rc = (!res.t || !res.q || !res.qd || !w) ? MM_ENOMEM
                                                 : mm_newmark_solve(&p, &o, w, &res, &err);
    double el = now() - t0;
    if (rc) {
        printf("%-24s failed: %s\n", label, rc == MM_ENOMEM ? "out of memory" : err.msg);
    } else {
        /* phase of (x, -v): unwrap, then compare with omega t */
        double phase = 0.0, prev = 0.0;
        for (int i = 0; i < res.rows; i++) {
            double ph = atan2(-res.qd[i], res.q[i]);
            if (i > 0) {
                double d = ph - prev;
                d -= 2.0 * M_PI * floor((d + M_PI) / (2.0 * M_PI));   /* into [-pi, pi) */
                phase += d;
            }
            prev = ph;
        }
        double t_end = res.t[res.rows - 1];
        double lag = (t_end - phase) / (2.0 * M_PI);    /* periods behind the exact motion */
        double E = res.energy_end.kinetic + res.energy_end.potential;
        char lag_s[32] = "n/a", th_s[32] = "";
        if (E > 1e-30 * res.energy_start)   /* a phase needs an amplitude left */
            snprintf(lag_s, sizeof lag_s, "%+.1f", lag);
        if (!isnan(theory_phase))
            snprintf(th_s, sizeof th_s, "%+.1f", theory_phase);
        printf("%-24s %9ld %12.3e %12.3e %10s %10s  %-28s %7.0f\n", label, res.steps,
               res.energy_error, E / res.energy_start - 1.0, lag_s, th_s, theory_note,
               1e3 * el);
    }
    mm_newmark_work_free(w);
    free(res.t);
    free(res.q);
    free(res.qd);
}

int main(void)
{
    static const int per_period[NRES] = {10, 20, 50, 100, 200, 500, 1000};
    row tab[NSCHEME][NRES];
    mm_newmark_work *w = mm_newmark_work_alloc(1);
    if (!w)
        return 1;

    printf("mm_newmark: x'' + 2x' + 100x = cos 8t, x(0) = x'(0) = 0, t in [0, 10], "
           "T = 2 pi/10 s\n");
    printf("error = max |x - x_exact| over every step; order = log(error ratio) / "
           "log(h ratio) against\nthe row above; balance = energy-balance residual / "
           "largest energy term (needs no exact solution)\n\n");
    printf("Table 1. work against error\n");
    printf("%-28s %6s %10s %7s %8s %11s %6s %11s %10s\n", "scheme", "T/h", "h [s]",
           "steps", "F calls", "max error", "order", "balance", "time [us]");
    for (int s = 0; s < NSCHEME; s++) {
        for (int j = 0; j < NRES; j++) {
            row *r = &tab[s][j];
            *r = measure(&schemes[s], per_period[j], w);
            double order = NAN;
            if (j > 0)
                order = log(tab[s][j - 1].err / r->err) / log(tab[s][j - 1].h / r->h);
            printf("%-28s %6d %10.3e %7ld %8ld %11.3e %6.2f %11.3e %10.1f\n",
                   j == 0 ? schemes[s].label : "", per_period[j], r->h, r->steps,
                   r->evals, r->err, order, r->balance, r->us);
        }
        printf("\n");
    }

    printf("Table 2. calls of F for a max error of 1e-6 (log-log interpolation in table 1)\n");
    printf("%-28s %10s %12s\n", "scheme", "F calls", "time [us]");
    for (int s = 0; s < NSCHEME; s++) {
        double calls = NAN, us = NAN;
        for (int j = 1; j < NRES; j++) {
            const row *a = &tab[s][j - 1], *b = &tab[s][j];
            if (a->err >= 1e-6 && b->err <= 1e-6) {
                double f = log(a->err / 1e-6) / log(a->err / b->err);
                calls = exp(log((double)a->evals) + f * log((double)b->evals / (double)a->evals));
                us = exp(log(a->us) + f * log(b->us / a->us));
                break;
            }
        }
        if (isnan(calls))
            printf("%-28s %10s %12s\n", schemes[s].label, "> table", "");
        else
            printf("%-28s %10.0f %12.1f\n", schemes[s].label, calls, us);
    }
    printf("(PERFORMANCE.md: average acceleration 10 632, fixed-step RK4 2 388, "
           "GSL rkf45 1 925, rk8pd 794)\n\n");

    const double Oh = 2.0 * M_PI / 20.0;
    printf("Table 3. x'' + x = 0, x(0) = 1, 1e5 periods at 20 steps per period "
           "(omega h = %.4f)\n", Oh);
    printf("max |dE|/E0 is the run's energy_error; phase lag in periods "
           "(negative = leads), measured by\nunwrapping atan2(-v, x) every 5 steps\n");
    printf("%-24s %9s %12s %12s %10s %10s  %-28s %7s\n", "scheme", "steps",
           "max|dE|/E0", "E_end/E0-1", "lag", "theory", "theory from", "ms");
    long_run("stormer-verlet", MM_NEWMARK_VERLET, 0.0,
             -1e5 * (acos(1.0 - Oh * Oh / 2.0) / Oh - 1.0), "cos(w~h) = 1 - (wh)^2/2");
    long_run("average acceleration", MM_NEWMARK_AVERAGE, 0.0,
             1e5 * (1.0 - 2.0 * atan(Oh / 2.0) / Oh), "w~h = 2 atan(wh/2)");
    long_run("hht-alpha, alpha -0.05", MM_NEWMARK_HHT, -0.05, NAN, "decays by design");
    printf("verlet's bound: E swings between E0 (1 - (wh)^2/4) and E0 from a turning "
           "point: (wh)^2/4 = %.4f\n", Oh * Oh / 4.0);

    mm_newmark_work_free(w);
    return 0;
}
