/* integrators.c — vib-integrators: one oscillator, six time integrators,
 * every error next to its cost.
 *
 *     x'' + 2 zeta omega_n x' + omega_n^2 x = F cos(omega t),
 *     x(0) = x0,  x'(0) = v0                                            (1)
 *
 * Goal: choose an integrator with open eyes.  The same problem, whose exact
 * solution is known (mm_sdof), is solved by central difference, Newmark's
 * average acceleration, Stormer-Verlet (mm_newmark), classical Runge-Kutta
 * and the adaptive Dormand-Prince pairs DOPRI5 and DOP853 (mm_ode).  A
 * table gives each method's step taken, steps, evaluations and achieved
 * error at the h and rtol chosen, or "unstable" with the reason; a
 * work-precision sweep gives error against step and cost, and the observed
 * orders are checked against theory.  A long free run shows what a method
 * does to energy: average acceleration keeps it, Verlet keeps it bounded,
 * RK4 drains it at exactly the rate its stability function predicts.
 * Reference: E. Hairer, S. P. Norsett, G. Wanner, Solving Ordinary
 * Differential Equations I, Springer 1993 (II.1, II.4-II.6); T. J. R.
 * Hughes, The Finite Element Method, Dover 2000, ch. 9 (Newmark).
 */
#include <complex.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mm_exhelp.h"
#include "mm_newmark.h"
#include "mm_ode.h"

enum { P_OMEGA_N, P_ZETA, P_F, P_OMEGA, P_X0, P_V0, P_TEND, P_H, P_RTOL, P_PERIODS };

static const mm_param params[] = {
    [P_OMEGA_N] = {"omega_n", "natural frequency", "rad/s", MM_REAL, 10, 0.1, 1e3,
                   .help = "sqrt(k/m) of the oscillator, 0.1 to 1000 rad/s"},
    [P_ZETA] = {"zeta", "damping ratio", "", MM_REAL, 0.05, 0, 2,
                .help = "c / (2 sqrt(k m)), from none to well overdamped (2)"},
    [P_F] = {"F", "force per unit mass", "m/s^2", MM_REAL, 1, 0, 1e3,
             .help = "amplitude of the force divided by the mass (up to 100 g); 0 gives free vibration"},
    [P_OMEGA] = {"omega", "forcing frequency", "rad/s", MM_REAL, 8, 0, 1e3,
                 .help = "angular frequency of the force, up to 1000 rad/s like omega_n"},
    [P_X0] = {"x0", "initial displacement", "m", MM_REAL, 0.01, -10, 10,
              .help = "x at t = 0; within 10 m, where a linear spring is still a fair model"},
    [P_V0] = {"v0", "initial velocity", "m/s", MM_REAL, 0, -1e3, 1e3, .help = "dx/dt at t = 0"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 10, 1e-2, 1e4,
                .help = "simulated time; at most 2e4 radians of the fastest motion and 5e4 steps of h "
                        "(the work of one request)"},
    [P_H] = {"h", "step of the fixed-step methods", "s", MM_REAL, 0.01, 1e-5, 10,
             .help = "central difference, Newmark, Verlet and RK4 take this step; try it near 2/omega_n"},
    [P_RTOL] = {"rtol", "tolerance of the adaptive methods", "", MM_REAL, 1e-6, 1e-12, 1e-2,
                .help = "relative tolerance of DOPRI5 and DOP853 (the absolute one is rtol times the motion's "
                        "size); 1e-12 is near what double precision can honour"},
    [P_PERIODS] = {"periods", "length of the energy run", "periods", MM_INT, 1000, 10, 20000,
                   .help = "free undamped periods integrated at 20 steps per period to watch the energy; up to "
                           "20000 (400,000 steps of three methods: what one request integrates in 250 ms)"},
};

enum { O_OMEGA_N, O_H_TAKEN, O_WN_H, O_H_STABLE, O_AMPLITUDE, O_T_SWEEP, O_DRIFT_RK4, O_E_VERLET, O_E_NEWMARK,
       O_METHODS, O_X_EXACT, O_X_M, O_WORK, O_STEP, O_ENERGY };

/* the keys of the series families: the method names as identifiers */
static const char *const mkeys[] = {"central_difference", "newmark_average_acceleration", "stormer_verlet",
                                    "rk4", "dopri5", "dop853", NULL};
static const char *const skeys[] = {"central_difference", "newmark_average_acceleration", "stormer_verlet", "rk4",
                                    NULL};
static const char *const ekeys[] = {"newmark", "verlet", "rk4", NULL};
static const char *const cols[] = {"method", "order", "step", "steps", "evaluations", "rejected", "max_error",
                                   "relative_error", "observed_order", "order_spread", NULL};
static const char *const units[] = {"", "", "s", "", "", "", "m", "", "", "", NULL};

static const mm_output outputs[] = {
    [O_OMEGA_N] = MM_SCALAR("omega_n", "natural frequency", "rad/s", .flags = MM_EXACT),
    [O_H_TAKEN] = MM_SCALAR("h_taken", "step the fixed-step methods take, t_end / ceil(t_end / h)", "s",
                            .flags = MM_ANSWER | MM_EXACT),
    [O_WN_H] = MM_SCALAR("omega_n_h", "omega_n h: radians per step the fixed-step methods take", "",
                         .flags = MM_ANSWER | MM_EXACT),
    [O_H_STABLE] = MM_SCALAR("h_stable_explicit",
                             "stability limit of central difference (and of Verlet without damping), 2/omega_n", "s",
                             .flags = MM_ANSWER | MM_EXACT),
    [O_AMPLITUDE] = MM_SCALAR("amplitude", "largest |x| of the exact motion at the plotted times", "m",
                              .flags = MM_EXACT),
    [O_T_SWEEP] = MM_SCALAR("t_sweep", "time span of the work-precision sweeps", "s", .flags = MM_EXACT),
    [O_DRIFT_RK4] = MM_SCALAR("energy_drift_rk4", "RK4: relative energy change after the run", "", .flags = MM_ANSWER),
    [O_E_VERLET] = MM_SCALAR("energy_error_verlet", "Verlet: largest relative energy error", ""),
    [O_E_NEWMARK] = MM_SCALAR("energy_error_newmark", "average acceleration: largest relative energy error", ""),
    [O_METHODS] = MM_TABLE("methods", "each method at the chosen h or rtol", cols, units),
    [O_X_EXACT] = MM_SERIES("x_exact", "exact displacement", "m", "t", "s", .figure = "response", .role = "reference"),
    [O_X_M] = MM_SERIES("x_%s", "%s", "m", "t", "s", .keys = mkeys, .figure = "response", .mark = "dots"),
    [O_WORK] = MM_SERIES("work_%s", "error of the end state against evaluations, %s", "m", "evaluations", "",
                         .keys = mkeys, .figure = "work", .x_scale = "log", .y_scale = "log"),
    [O_STEP] = MM_SERIES("step_%s", "rms error at the times every run of the sweep steps on, against step, %s",
                         "m", "h", "s", .keys = skeys,
                         .figure = "step", .x_scale = "log", .y_scale = "log"),
    [O_ENERGY] = MM_SERIES("energy_%s", "relative energy error, %s", "", "t/T", "periods", .keys = ekeys,
                           .figure = "energy"),
};

#define MAX_STEPS 50000L        /* steps of one fixed-step run */
#define SWEEP_STEPS 16384L      /* finest run of a work-precision sweep */
#define SWEEP_EVALS 100000L     /* an adaptive sweep stops after a run this costly */
#define PLOT 250                /* samples of each method's curve */
#define STEPS_PER_PERIOD 20     /* of the long free run */

enum { M_CD = MM_EX_CENTRAL, M_AA = MM_EX_AVERAGE, M_VERLET = MM_EX_VERLET, M_RK4 = MM_EX_RK4,
       M_DOPRI5 = MM_EX_DOPRI5, M_DOP853 = MM_EX_DOP853, NM = MM_EX_METHODS };
static const char *const mname[NM] = {"central-difference", "newmark-average-acceleration", "stormer-verlet",
                                      "rk4", "dopri5", "dop853"};
static const int morder[NM] = {2, 2, 2, 4, 5, 8};

typedef struct problem {
    mm_sdof s;             /* m = 1: the closed form of eq. (1) */
    mm_sdof_props p;
    double t_end, scale;   /* scale: largest |x| of the exact motion */
    double *buf_t, *buf_x, *buf_v; /* scratch for MAX_STEPS + 2 step points */
} problem;

typedef struct outcome {
    mm_ex_run r;           /* the run: steps, evaluations, step taken, failed */
    double err;            /* max |x - x_exact| over its step points */
    double err_end;        /* |(x - x_exact, (v - v_exact)/w)| at the run's end, w the fastest rate */
} outcome;

static mm_sdof model(const mm_value *in)
{
    double wn = in[P_OMEGA_N].x;
    return (mm_sdof){.m = 1, .k = wn * wn, .c = 2 * in[P_ZETA].x * wn, .F0 = in[P_F].x,
                     .omega = in[P_OMEGA].x, .x0 = in[P_X0].x, .v0 = in[P_V0].x};
}

static int check(const mm_value *in, mm_error *err)
{
    mm_sdof s = model(in);
    double t_end = in[P_TEND].x, h = in[P_H].x;
    if (t_end / h > MAX_STEPS)
        return mm_error_set(err, MM_ERANGE, "h", "h = %g s takes %.3g steps to cover t_end = %g s; at most %ld "
                            "fit one request: make h at least %.3g s", h, t_end / h, t_end, MAX_STEPS,
                            t_end / MAX_STEPS);
    return mm_ex_sdof_work_check(&s, t_end, err);
}

/* Method m over [0, t_end] (mm_ex_sdof_method), every step point into buf;
 * the largest |x - exact| over them (all up to 2000, else 2000 spread ones
 * and the last: the closed form costs more than a step), the end state's error. */
static int run(problem *pb, int m, double h, double rtol, double t_end, outcome *o, mm_error *err, mm_result *res)
{
    o->err = o->err_end = 0;
    int rc = mm_ex_sdof_method(&pb->s, m, h, rtol, rtol * pb->scale, t_end, 1, MAX_STEPS + 2, pb->buf_t,
                               pb->buf_x, pb->buf_v, &o->r, res, err);
    if (rc != MM_OK || o->r.failed)
        return rc;
    int n = o->r.rows, stride = n > 2000 ? (n + 1999) / 2000 : 1;
    for (int i = 0; i < n; i += stride)
        o->err = fmax(o->err, fabs(pb->buf_x[i] - mm_sdof_x(&pb->s, &pb->p, pb->buf_t[i], NULL)));
    if (n > 0) {
        double ve, xe = mm_sdof_x(&pb->s, &pb->p, pb->buf_t[n - 1], &ve);
        double w = fmax(pb->p.omega_n, pb->s.F0 != 0 ? pb->s.omega : 0);
        o->err = fmax(o->err, fabs(pb->buf_x[n - 1] - xe));
        o->err_end = hypot(pb->buf_x[n - 1] - xe, (pb->buf_v[n - 1] - ve) / w);
    }
    return MM_OK;
}

/* Free undamped x'' + w^2 x = 0 from x = 1, N steps of h, by method m; the
 * relative energy error every stride steps (and at the end) into se;
 * e[0] the last one, e[1] the largest, e[2] the largest of Verlet's
 * modified energy v^2/2 + w^2 x^2 (1 - (w h)^2/4)/2. */
static int energy_view(int m, double w, double h, long N, long stride, mm_series *se, double e[3], double *tb,
                       mm_result *res, mm_error *err)
{
    mm_sdof s = {.m = 1, .k = w * w, .x0 = 1};
    double *xb = tb + se->n, *vb = xb + se->n, a = (w * h) * (w * h) / 4, E0 = 0.5 * w * w;
    mm_ex_run r;
    int rc = mm_ex_sdof_method(&s, m, h, 1e-6, 1e-6, N * h, stride, se->n, tb, xb, vb, &r, res, err);
    if (rc != MM_OK || r.failed)
        return rc != MM_OK ? rc : mm_error_set(err, MM_EINTERNAL, "", "the free run at 20 steps a period blew up");
    e[1] = e[2] = 0;
    se->n = r.rows;
    for (int i = 0; i < r.rows; i++) {
        double E = 0.5 * vb[i] * vb[i] + 0.5 * w * w * xb[i] * xb[i], Em = E - 0.5 * w * w * xb[i] * xb[i] * a;
        se->x[i] = nearbyint(tb[i] / h) / STEPS_PER_PERIOD;     /* t / T, short */
        se->y[i] = e[0] = E / E0 - 1;
        e[1] = fmax(e[1], fabs(e[0]));
        e[2] = fmax(e[2], fabs(Em / (E0 * (1 - a)) - 1));
    }
    mm_ex_round_sig(se->y, r.rows, 3);                 /* an error needs no more digits */
    return MM_OK;
}

/* ---- stability of the fixed-step methods on eq. (1) ------------------------------- */

/* Is fixed-step method m past its stability limit at the step h it takes?
 * (why: the reason.)  Average acceleration: never.  Central difference
 * (damping implicit): omega_n h >= 2.  Verlet (damping at the half-step
 * velocity): the map of (x, v half) [[1, h], [-h k, 1 - h c - h^2 k]], trace
 * 2 - h c - h^2 k, determinant 1 - h c, eigenvalues outside the unit circle.
 * RK4: |R(lambda h)| > 1, lambda = omega_n (-zeta +- sqrt(zeta^2 - 1)). */
static int past_limit(int m, double wn, double zeta, double h, char *why, size_t len)
{
    double wh = wn * h, gain = 0;
    if (m == M_AA)
        return 0;
    if (m == M_CD) {
        snprintf(why, len, "omega_n h = %.3g >= 2", wh);
        return wh >= 2;
    }
    gain = m == M_RK4 ? mm_sdof_rk4_gain(wh, zeta) : mm_sdof_verlet_gain(wh, zeta);
    if (m == M_RK4)
        snprintf(why, len, "|R(lambda h)| = %.4g > 1 at omega_n h = %.3g", gain, wh);
    else
        snprintf(why, len, "spectral radius of the step %.4g > 1 at omega_n h = %.3g%s", gain, wh,
                 zeta > 0 && wh < 2 ? " (damping lowers Verlet's limit below 2)" : "");
    return gain > 1 + 1e-12;
}

/* ---- solve ----------------------------------------------------------------------- */

/* The table row of method m after its run o at the chosen h or rtol. */
static int table_row(const problem *pb, int m, const outcome *o, double zeta, mm_table *tab, char *unstable,
                     size_t cap, mm_result *res)
{
    double *row = tab->cell + 10 * m, wn = pb->p.omega_n;
    const char **txt = tab->text + 10 * m;
    txt[0] = mname[m];
    row[1] = m == M_VERLET && zeta > 0 ? 1 : morder[m];        /* damped Verlet: first order, its damping
                                                                  force sees the half-step velocity */
    row[2] = o->r.h, row[3] = (double)o->r.steps, row[4] = (double)o->r.evals, row[5] = (double)o->r.rejected;
    row[6] = o->err, row[7] = o->err / pb->scale;              /* a text replaces them when unstable */
    /* unstable: past the method's stability limit at the step taken, or
     * blown up, or an error above 10 times the motion's size */
    char why[160], l6[240], l7[240];
    int past = m <= M_RK4 && past_limit(m, wn, zeta, o->r.h, why, sizeof why);
    if (past)
        snprintf(unstable + strlen(unstable), cap - strlen(unstable), "%s%s", unstable[0] ? ", " : "", mname[m]);
    if (o->r.failed || past || o->err > 10 * pb->scale) {
        if (!past && !o->r.failed)
            snprintf(why, sizeof why, "error %.3g times the motion's size (> 10)", o->err / pb->scale);
        snprintf(l6, sizeof l6, m > M_RK4 && o->r.failed ? "not finished: more than 5e4 steps"
                                : o->r.failed ? "unstable: %s; the solution overflowed" : "unstable: %s; error %.3g m",
                 past || !o->r.failed ? why : "blew up", o->err);
        snprintf(l7, sizeof l7, o->r.failed ? "%s" : "unstable: %s; error %.3g", o->r.failed ? l6 : why,
                 o->err / pb->scale);
        if (!(txt[6] = mm_res_strdup(res, l6)) || !(txt[7] = mm_res_strdup(res, l7)))
            return MM_ENOMEM;
    }
    /* the computed curve, at up to PLOT of its step points, to the digits
     * its error leaves (never fewer than 3) */
    if (!o->r.failed && o->r.rows >= 2) {
        int stride = (o->r.rows + PLOT - 1) / PLOT, ns = (o->r.rows - 1) / stride + 1;
        mm_series *sm = mm_res_series_i(res, O_X_M, m, ns);
        if (!sm)
            return MM_ENOMEM;
        for (int i = 0; i < ns; i++) {
            sm->x[i] = pb->buf_t[i * stride];
            sm->y[i] = pb->buf_x[i * stride];
        }
        double rel = o->err / pb->scale;
        mm_ex_round_sig(sm->y, ns, rel > 0 ? (int)fmin(17, fmax(3, ceil(-log10(rel)) + 1)) : 17);
    }
    return MM_OK;
}

/* Work-precision sweeps over at most 20 periods of the fastest motion (long
 * runs would leave no room for fine steps), and the observed orders. */
static int sweeps(problem *pb, double zeta, long *total_evals, mm_table *tab, mm_result *res, mm_error *err)
{
    double wmax = fmax(pb->p.omega_n, pb->s.F0 != 0 ? pb->s.omega : 0);
    double t_sw = fmin(pb->t_end, 20 * 2 * M_PI / wmax), h0 = fmin(0.5 / wmax, t_sw / 8);
    mm_res_scalar(res, O_T_SWEEP, t_sw);
    /* the fixed-step runs halve the first one's N0 steps exactly, so each steps on its N0 + 1 times */
    double N0 = mm_ode_fixed_steps(t_sw, h0);
    for (int m = 0; m < NM; m++) {
        double hs[24], es[24], cs[24], rs[24];
        int n = 0;
        for (int k = 0; k < 24; k++) {
            outcome o;
            double hk = t_sw / (N0 * ldexp(1, k)), tol = pow(10, -3 - k);
            if ((m <= M_RK4 && N0 * ldexp(1, k) > SWEEP_STEPS) || (m > M_RK4 && tol < 1e-13))
                break;
            int rc = run(pb, m, hk, tol, t_sw, &o, err, res);
            if (rc != MM_OK)
                return rc;
            *total_evals += o.r.evals;
            if (o.r.failed)
                break;
            hs[n] = o.r.h;                     /* the step taken (mean if adaptive) */
            es[n] = fmax(o.err_end, 1e-300);   /* smooth in h, unlike a max over the grid */
            cs[n] = (double)o.r.evals;
            double sq = 0;   /* fixed-step: the rms error at the N0 + 1 shared times (integrators.md, 2) */
            for (long i = 0, st = 1L << k; m <= M_RK4 && i <= (long)N0 && i * st < o.r.rows; i++) {
                double ve, xe = mm_sdof_x(&pb->s, &pb->p, pb->buf_t[i * st], &ve);
                double ex = pb->buf_x[i * st] - xe, ev = (pb->buf_v[i * st] - ve) / wmax;
                sq += ex * ex + ev * ev;
            }
            rs[n] = fmax(sqrt(sq / (N0 + 1)), 1e-300);
            n++;
            if (m > M_RK4 && o.r.evals > SWEEP_EVALS)
                break;
        }
        mm_series *sw = mm_res_series_i(res, O_WORK, m, n);
        mm_series *sh = m <= M_RK4 ? mm_res_series_i(res, O_STEP, m, n) : NULL;
        if (!sw || (m <= M_RK4 && !sh))
            return MM_ENOMEM;
        for (int i = 0; i < n; i++) {   /* the plots get 3 digits of each error; the slopes use all of them */
            sw->x[i] = cs[i], sw->y[i] = es[i];
            if (sh)
                sh->x[i] = hs[i], sh->y[i] = rs[i];
        }
        mm_ex_round_sig(sw->y, n, 3);
        if (sh)
            mm_ex_round_sig(sh->y, n, 3);
        double order, spread;
        if (m > M_RK4 || mm_ex_observed_order(hs, rs, n, 1e-11 * pb->scale, 1e-2 * pb->scale, &order, &spread) < 3) {
            tab->text[10 * m + 8] = tab->text[10 * m + 9] = m > M_RK4 ? "adaptive: see work" : "too few steps";
            continue;
        }
        /* theory: 2, 2, 4, and Verlet 2 without damping (with damping its first-order damping error
         * competes with the second-order rest: reported, not checked); the rms error's slope is known to
         * the spread of the local slopes plus the error's next term, ~ |lambda| h of the finest step fitted,
         * lambda the fastest rate of the motion: omega (if forced) or the fastest root of (1),
         * omega_n (zeta + sqrt(zeta^2 - 1)) when overdamped, up to 2 zeta omega_n (not omega_n) */
        tab->cell[10 * m + 8] = order, tab->cell[10 * m + 9] = spread;
        if (m == M_VERLET && zeta > 0)
            continue;
        double hf = 0;
        for (int i = n - 1; i >= 0 && hf == 0; i--)
            hf = rs[i] >= 1e-11 * pb->scale && rs[i] <= 1e-2 * pb->scale ? hs[i] : 0;
        double lam = fmax(pb->p.omega_n * (zeta > 1 ? zeta + sqrt(zeta * zeta - 1) : 1),
                          pb->s.F0 != 0 ? pb->s.omega : 0);
        char name[200];
        snprintf(name, sizeof name, "%s: observed order vs %d, within 10 times the spread of its local slopes plus "
                 "|lambda| h of the finest step fitted, lambda the fastest rate", mname[m], morder[m]);
        mm_res_check_abs(res, name, order, morder[m], 10 * spread + lam * hf + 1e-4);
    }
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    problem pb = {.s = model(in), .t_end = in[P_TEND].x};
    mm_sdof_props_get(&pb.s, &pb.p);
    double h = in[P_H].x, rtol = in[P_RTOL].x, wn = pb.p.omega_n, zeta = in[P_ZETA].x, t_end = pb.t_end;
    int periods = (int)in[P_PERIODS].x, rc;

    pb.buf_t = mm_res_alloc(res, 3 * (MAX_STEPS + 2) * sizeof(double));
    if (!pb.buf_t)
        return MM_ENOMEM;
    pb.buf_x = pb.buf_t + MAX_STEPS + 2;
    pb.buf_v = pb.buf_x + MAX_STEPS + 2;

    /* the exact motion, and its size */
    mm_series *sx = mm_res_series(res, O_X_EXACT, 2 * PLOT + 1);
    if (!sx)
        return MM_ENOMEM;
    mm_ex_time_grid(t_end, 2 * PLOT + 1, sx->x);
    for (int i = 0; i <= 2 * PLOT; i++)
        sx->y[i] = mm_sdof_x(&pb.s, &pb.p, sx->x[i], NULL);
    pb.scale = fmax(mm_maxabs(sx->y, 2 * PLOT + 1), 1e-300);

    /* the fixed-step methods take N = ceil(t_end / h) equal steps */
    double h_taken = t_end / mm_ode_fixed_steps(t_end, h);
    mm_res_scalar(res, O_OMEGA_N, wn);
    mm_res_scalar(res, O_H_TAKEN, h_taken);
    mm_res_scalar(res, O_WN_H, wn * h_taken);
    mm_res_scalar(res, O_H_STABLE, 2 / wn);
    mm_res_scalar(res, O_AMPLITUDE, pb.scale);

    /* ---- the table: each method at the chosen h or rtol ---- */
    mm_table *tab = mm_res_table(res, O_METHODS, NM);
    if (!tab)
        return MM_ENOMEM;
    long total_evals = 0;
    char unstable[160] = "";
    for (int m = 0; m < NM; m++) {
        outcome o;
        if ((rc = run(&pb, m, h, rtol, t_end, &o, err, res)) != MM_OK ||
            (rc = table_row(&pb, m, &o, zeta, tab, unstable, sizeof unstable, res)) != MM_OK)
            return rc;
        total_evals += o.r.evals;
    }
    if (unstable[0])
        mm_res_warn(res, "at the step taken, h = %.4g s (omega_n h = %.3g), %s %s past the stability limit: "
                    "the solution grows without bound whatever the physics does (see the table); average "
                    "acceleration stays stable but is inaccurate at large steps", h_taken, wn * h_taken,
                    unstable, strchr(unstable, ',') ? "are" : "is");

    if ((rc = sweeps(&pb, zeta, &total_evals, tab, res, err)) != MM_OK)
        return rc;

    /* ---- the long free run: what happens to energy ---- */
    double hE = 2 * M_PI / wn / STEPS_PER_PERIOD;
    long N = (long)STEPS_PER_PERIOD * periods, stride = (N + 2 * PLOT - 1) / (2 * PLOT);
    int rows = (int)(N / stride + 2);
    double *tb = mm_res_alloc(res, 3 * (size_t)rows * sizeof *tb), er[3][3];   /* AA, Verlet, RK4 */
    if (!tb)
        return MM_ENOMEM;
    static const int em[3] = {M_AA, M_VERLET, M_RK4};
    for (int j = 0; j < 3; j++) {
        mm_series *se = mm_res_series_i(res, O_ENERGY, j, rows);
        if (!se)
            return MM_ENOMEM;
        if ((rc = energy_view(em[j], wn, hE, N, stride, se, er[j], tb, res, err)) != MM_OK)
            return rc;
        total_evals += em[j] == M_RK4 ? 4 * N : N;
    }
    double y = wn * hE, a = y * y / 4;
    double rnd = 4 * DBL_EPSILON * (double)N;   /* the round-off of N steps: a few eps of the energy each */
    /* RK4 maps (omega x, v) by a rotation-and-scaling: the energy is
     * multiplied by exactly |R(i omega h)|^2 each step, eq. (7) */
    double complex z = I * y, R = 1 + z + z * z / 2 + z * z * z / 6 + z * z * z * z / 24;
    double predicted = expm1((double)N * log(creal(R * conj(R))));   /* |R(i w h)|^2 per step */
    mm_ex_scalar_beside(res, O_DRIFT_RK4, er[2][0], predicted, 4 * DBL_EPSILON * N * fabs(predicted));
    mm_res_scalar_err(res, O_E_VERLET, er[1][1], rnd, MM_ERR_BOUND);
    mm_res_scalar_err(res, O_E_NEWMARK, er[0][1], rnd, MM_ERR_BOUND);
    mm_res_check_abs(res, "RK4: energy change over the run vs |R(i omega h)|^(2N) - 1, eq. (7), to round-off of "
                          "N steps", er[2][0], predicted, rnd * (1 + fabs(predicted)));
    /* Verlet conserves the modified energy v^2/2 + w^2 x^2 (1 - (w h)^2/4)/2
     * exactly, so the true energy stays within (w h)^2 / (4 - (w h)^2), eq. (8) */
    mm_res_check_abs(res, "Verlet: modified energy conserved, eq. (8), to round-off of N steps", er[1][2], 0,
                     rnd);
    mm_res_check_abs(res, "Verlet: energy error within the bound (w h)^2/(4 - (w h)^2) of eq. (8)", er[1][1], 0,
                     a / (1 - a) + rnd);
    /* average acceleration conserves the energy of a linear undamped system */
    mm_res_check_abs(res, "average acceleration: energy conserved, eq. (6), to round-off of N steps", er[0][1],
                     0, rnd);

    mm_res_method(res, "central difference, Newmark average acceleration, Stormer-Verlet, RK4 (step h, "
                       "made t_end / ceil(t_end / h)); DOPRI5, DOP853 (tolerance rtol)", h_taken);
    mm_res_method_stat(res, "rtol", rtol);
    mm_res_method_stat(res, "evaluations", (double)total_evals);
    return MM_OK;
}

static const char *const references[] = {
    "E. Hairer, S. P. Norsett, G. Wanner, Solving Ordinary Differential Equations I, 2nd ed., Springer 1993, "
    "sections II.1, II.4-II.6",
    "E. Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed., Springer 2006, ch. I and IX",
    "T. J. R. Hughes, The Finite Element Method, Dover 2000, ch. 9 (Newmark methods)",
    NULL,
};

const mm_exercise mm_ex_vib_integrators = {
    .id = "vib-integrators", .chapter = 5, .section = "5.8", .title = "Time integrators compared: error against cost",
    .summary = "One oscillator by central difference, Newmark, Verlet, RK4, DOPRI5 and DOP853: errors, costs, "
               "orders, energy.",
    .tags = "vibration, numerical methods, time integration, Newmark, Runge-Kutta, work-precision, energy",
    .theory = "exercises/vib/integrators.md", .params = params, .n_params = MM_COUNT(params), .outputs = outputs,
    .n_outputs = MM_COUNT(outputs), .references = references, .check = check, .solve = solve,
};
