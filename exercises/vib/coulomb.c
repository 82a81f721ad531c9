/* coulomb.c — vib-coulomb: a mass on a spring sliding on a rough floor.
 *
 *     m x'' + k x = -mu m g sign(x'),   x(0) = x0,  x'(0) = v0          (1)
 *
 * The friction force has a constant size and always opposes the motion, so
 * between two velocity zeros the mass swings on a harmonic arc about a
 * shifted centre, loses 2 mu m g / k of amplitude per half cycle (a straight
 * envelope, not an exponential one) and stops for good at the first
 * velocity zero where the spring can no longer beat static friction,
 * |k x| <= mu m g.
 * Goal: see the linear decay and the final stop away from x = 0, and learn
 * to integrate a discontinuous right-hand side honestly: integrate each
 * smooth piece (friction sign frozen), locate the velocity zero as an event
 * (Brent's method on v(t)), decide there whether the mass sticks or turns,
 * and restart.  No step ever straddles the switch, so nothing chatters.
 * Reference: S. S. Rao, Mechanical Vibrations, 6th ed., section 2.9
 * (Coulomb damping); Hairer, Norsett, Wanner, Solving ODE I, section II.6
 * (dense output and event location).
 */
#include <math.h>

#include "mm_exhelp.h"
#include "mm_ode.h"
#include "mm_roots.h"

enum { P_M, P_K, P_MU, P_G, P_X0, P_V0, P_POINTS };

static const mm_param params[] = {
    [P_M] = {"m", "mass", "kg", MM_REAL, 1, 1e-3, 1e3, .help = "the sliding mass"},
    [P_K] = {"k", "stiffness", "N/m", MM_REAL, 100, 1e-2, 1e6, .help = "spring force per metre of stretch"},
    [P_MU] = {"mu", "friction coefficient", "", MM_REAL, 0.1, 1e-3, 2,
              .help = "one coefficient for sticking and sliding: the friction force is at most mu m g"},
    [P_G] = {"g", "gravity", "m/s^2", MM_REAL, 9.81, 0.1, 100,
             .help = "acceleration of gravity, which presses the mass on the floor"},
    [P_X0] = {"x0", "initial displacement", "m", MM_REAL, 0.1, -1, 1,
              .help = "stretch of the spring at t = 0"},
    [P_V0] = {"v0", "initial velocity", "m/s", MM_REAL, 0, -10, 10, .help = "dx/dt at t = 0"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 501, 11, 4001,
                  .help = "samples of the time response returned for the plot"},
};

/* Most sliding arcs (half cycles) one request may integrate. */
#define MAX_ARCS 2000

/* A rest with |k x| within this relative margin of mu m g counts as a stop
 * (eq. 6 with the knife edge given to sticking), in the closed form and in
 * the numerical solution alike: their positions differ by ~1e-10. */
#define STICK_MARGIN 1e-9

/* ---- the piecewise closed form ------------------------------------------------- */

typedef struct model {
    double m, k, mu, g, x0, v0;
    double w;        /* omega_n = sqrt(k/m) [rad/s] */
    double d;        /* friction band mu m g / k [m]: the centre shift */
} model;

static model model_of(const mm_value *in)
{
    model s = {.m = in[P_M].x, .k = in[P_K].x, .mu = in[P_MU].x, .g = in[P_G].x,
               .x0 = in[P_X0].x, .v0 = in[P_V0].x};
    s.w = sqrt(s.k / s.m);
    s.d = s.mu * s.m * s.g / s.k;
    return s;
}

/* Eq. (6): at rest at x, does static friction hold the mass? */
static int sticks(const model *s, double x)
{
    return fabs(s->k * x) <= s->mu * s->m * s->g * (1 + STICK_MARGIN);
}

/* The first arc of eq. (3): direction sg of the motion (+1 or -1), duration
 * tau and end position x1.  Returns 0 when the mass never moves. */
static int first_arc(const model *s, double *sg, double *tau, double *x1)
{
    if (s->v0 == 0) {
        if (sticks(s, s->x0))
            return 0;                              /* static friction holds, eq. (6) */
        *sg = s->x0 > 0 ? -1 : 1;                  /* the spring pulls it back */
        *tau = M_PI / s->w;
        *x1 = 2 * (-*sg * s->d) - s->x0;           /* eq. (4) */
        return 1;
    }
    *sg = s->v0 > 0 ? 1 : -1;
    double c = -*sg * s->d, R = hypot(s->x0 - c, s->v0 / s->w);
    double th = atan2(s->v0 / s->w, s->x0 - c);    /* x - c = R cos(w t - th) */
    *tau = (*sg > 0 ? th : th + M_PI) / s->w;
    *x1 = c + *sg * R;
    return 1;
}

/* Number of sliding arcs, from eqs. (3)-(5), without stepping through them
 * (for the work bound; may be huge). */
static double arc_count(const model *s)
{
    double sg, tau, x1;
    if (!first_arc(s, &sg, &tau, &x1))
        return 0;
    if (sticks(s, x1))
        return 1;
    return 1 + ceil((fabs(x1) - s->d) / (2 * s->d));
}

/* The whole motion in closed form: rest times t[j] and places x[j] at the
 * end of arc j (j = 0..n-1), arc directions sg[j]. */
static int exact_arcs(const model *s, double *t, double *x, double *sg, int cap)
{
    double dir, tau, x1;
    if (!first_arc(s, &dir, &tau, &x1))
        return 0;
    int n = 0;
    t[n] = tau;
    x[n] = x1;
    sg[n++] = dir;
    while (!sticks(s, x[n - 1]) && n < cap) {     /* eq. (4): turn and slide back */
        dir = x[n - 1] > 0 ? -1 : 1;
        t[n] = t[n - 1] + M_PI / s->w;
        x[n] = 2 * (-dir * s->d) - x[n - 1];
        sg[n++] = dir;
    }
    return n;
}

/* x(t) and x'(t) of the closed form at time tt, given the arcs. */
static double exact_x(const model *s, const double *t, const double *x, const double *sg,
                      int n, double tt, double *v)
{
    double ts = 0, xs = s->x0, vs = s->v0;
    for (int j = 0; j < n; j++) {
        if (tt <= t[j]) {
            double c = -sg[j] * s->d, wt = s->w * (tt - ts);
            *v = -(xs - c) * s->w * sin(wt) + vs * cos(wt);
            return c + (xs - c) * cos(wt) + vs / s->w * sin(wt);
        }
        ts = t[j];
        xs = x[j];
        vs = 0;
    }
    *v = 0;
    return xs;                                     /* at rest for good */
}

static int check(const mm_value *in, mm_error *err)
{
    model s = model_of(in);
    double n = arc_count(&s);
    if (n > MAX_ARCS)
        return mm_error_set(err, MM_ERANGE, "mu",
                            "the mass would slide %.3g half cycles before it stops (each loses "
                            "2 mu m g/k = %.3g m); at most %d fit one request: raise mu or start "
                            "nearer rest", n, 2 * s.d, MAX_ARCS);
    return MM_OK;
}

/* ---- the numerical solution ---------------------------------------------------- */

/* Eq. (2) on one arc, friction direction frozen: y = (x, v). */
typedef struct arc_ctx {
    double w2, f;    /* omega_n^2 and the friction acceleration sg mu g */
} arc_ctx;

static int arc_rhs(double t, const double *y, double *dy, void *ctx)
{
    (void)t;
    const arc_ctx *a = ctx;
    dy[0] = y[1];
    dy[1] = -a->w2 * y[0] - a->f;
    return 0;
}

/* The event function: sg v(t) at tau after the state ya, by one DOPRI5 step
 * of length tau from ya (the arc is autonomous, so each step starts at 0). */
typedef struct event_ctx {
    arc_ctx arc;
    double ya[2], sg, atol;
    mm_ode_work *w;
    double y[2];     /* the state at the last evaluation */
    long evals;
} event_ctx;

static int event_fn(double tau, double *fx, void *ctx)
{
    event_ctx *e = ctx;
    if (tau <= 0) {
        e->y[0] = e->ya[0];
        e->y[1] = e->ya[1];
        *fx = e->sg * e->ya[1];
        return 0;
    }
    mm_ode_problem prob = {.n = 2, .f = arc_rhs, .params = &e->arc, .t0 = 0, .t_end = tau, .y0 = e->ya};
    mm_ode_options opt;
    mm_ode_options_init(&opt);
    opt.method = MM_ODE_DOPRI5;
    opt.h = tau;                    /* one step, no error control: the step is the interpolant */
    opt.rtol = 1e-10;
    opt.atol = e->atol;
    mm_ode_result r = {0};
    r.y_end = e->y;
    mm_error err;
    int rc = mm_ode_solve(&prob, &opt, e->w, &r, &err);
    e->evals += r.n_eval;
    if (rc != MM_OK)
        return rc;
    *fx = e->sg * e->y[1];
    return 0;
}

typedef struct stats {
    long steps, rejected, evals, brent_iters;
    double err_sum;
} stats;

/* Integrate one arc from (x, 0 or v0) with direction sg: find the velocity
 * zero, fill the plot samples tg[g..] that fall inside the arc.  On return
 * *t_rest and *x_rest hold the event. */
static int slide(const model *s, double t_start, double xs, double vs, double sg, mm_ode_work *w,
                 double *ts_buf, double *ys_buf, size_t cap, const double *tg, int ng, int *g,
                 double *xg, double *vg, double *t_rest, double *x_rest, stats *st, mm_result *res,
                 mm_error *err)
{
    double R = hypot(fabs(xs) + s->d, vs / s->w);   /* size of the arc's motion */
    arc_ctx arc = {.w2 = s->w * s->w, .f = sg * s->mu * s->g};
    double y0[2] = {xs, vs}, window = 1.25 * M_PI / s->w; /* a half period and a margin */
    double atol = 1e-12 * R * fmin(1, s->w);

    /* the plot samples the window covers (those after the event are dropped) */
    int g0 = *g, gn = g0;
    while (gn < ng && tg[gn] <= t_start + window)
        gn++;
    double *tout = NULL, *yout = NULL;
    if (gn > g0) {
        tout = mm_res_alloc(res, (size_t)(gn - g0) * sizeof *tout);
        yout = mm_res_alloc(res, 2 * (size_t)(gn - g0) * sizeof *yout);
        if (!tout || !yout)
            return mm_error_set(err, MM_ENOMEM, "", "out of memory");
        for (int i = g0; i < gn; i++)
            tout[i - g0] = fmax(0, tg[i] - t_start);
    }

    mm_ode_problem prob = {.n = 2, .f = arc_rhs, .params = &arc, .t0 = 0, .t_end = window, .y0 = y0};
    mm_ode_options opt;
    mm_ode_options_init(&opt);
    opt.method = MM_ODE_DOPRI5;
    opt.rtol = 1e-10;
    opt.atol = atol;
    opt.max_steps = (long)cap - 1;
    mm_ode_result r = {0};
    r.t_out = tout;
    r.nout = (size_t)(gn - g0);
    r.y_out = yout;
    r.t_steps = ts_buf;
    r.y_steps = ys_buf;
    r.steps_cap = cap;
    int rc = mm_ode_solve(&prob, &opt, w, &r, err);
    st->steps += r.n_accepted;
    st->rejected += r.n_rejected;
    st->evals += r.n_eval;
    st->err_sum += r.err_sum;
    if (rc != MM_OK)
        return rc;

    /* the first recorded step where sg v turns from positive to <= 0 */
    size_t k = 1;
    while (k < r.n_stored && sg * ys_buf[2 * k + 1] > 0)
        k++;
    if (k == r.n_stored)
        return mm_error_set(err, MM_EINTERNAL, "", "no velocity zero within %.3g s of the start of a "
                            "sliding arc", window);
    event_ctx e = {.arc = arc, .ya = {ys_buf[2 * (k - 1)], ys_buf[2 * (k - 1) + 1]}, .sg = sg,
                   .atol = atol, .w = w};
    double ta = ts_buf[k - 1], tb = ts_buf[k], lo = 0, span = tb - ta, fa = sg * e.ya[1], fb;
    if ((rc = event_fn(span, &fb, &e)) != MM_OK)
        return mm_error_set(err, rc, "", "event location failed");
    if (!(fa > 0)) {            /* the arc starts at rest: step off the zero at ta */
        lo = 1e-3 * span;
        if ((rc = event_fn(lo, &fa, &e)) != MM_OK)
            return mm_error_set(err, rc, "", "event location failed");
    }
    double tau;
    if (fb == 0) {
        tau = span;
    } else if (!(fa > 0 && fb < 0)) {
        return mm_error_set(err, MM_EINTERNAL, "", "the velocity zero of an arc could not be bracketed");
    } else {
        double fx, width;
        int iters = 0;
        rc = mm_roots_brent(event_fn, &e, lo, span, fa, fb, 1e-15 * (ta + span), 200, &tau, &fx, &width,
                            &iters, NULL, err);
        st->brent_iters += iters;
        if (rc != MM_OK)
            return rc;
    }
    double fend;
    if ((rc = event_fn(tau, &fend, &e)) != MM_OK)     /* the state at the event */
        return mm_error_set(err, rc, "", "event location failed");
    st->evals += e.evals;
    *t_rest = t_start + ta + tau;
    *x_rest = e.y[0];

    for (int i = g0; i < gn && tg[i] <= *t_rest; i++) {
        xg[i] = yout[2 * (i - g0)];
        vg[i] = yout[2 * (i - g0) + 1];
        *g = i + 1;
    }
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    model s = model_of(in);
    int np = (int)in[P_POINTS].x;
    double fric = s.mu * s.m * s.g;

    /* the closed form, eqs. (3)-(5) */
    double *te = mm_res_alloc(res, 3 * (MAX_ARCS + 1) * sizeof *te), *xe = te + MAX_ARCS + 1,
           *sge = xe + MAX_ARCS + 1;
    if (!te)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    int ne = exact_arcs(&s, te, xe, sge, MAX_ARCS + 1);
    double stop_exact = ne ? te[ne - 1] : 0, xf_exact = ne ? xe[ne - 1] : s.x0;

    mm_res_scalar_v1(res, "omega_n", "natural frequency sqrt(k/m)", "rad/s", s.w);
    mm_res_scalar_v1(res, "friction_band", "friction band mu m g / k", "m", s.d);
    mm_res_scalar_v1(res, "decay_per_cycle", "amplitude lost per cycle 4 mu m g / k", "m", 4 * s.d);

    /* the plot: to a little past the stop, or one period when it never moves */
    double t_plot = ne ? 1.15 * stop_exact : 2 * M_PI / s.w;
    mm_series *sx = mm_res_series_v1(res, "x", "displacement", "m", "t", "s", np);
    mm_series *sv = mm_res_series_v1(res, "v", "velocity", "m/s", "t", "s", np);
    if (!sx || !sv)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_linspace(0, t_plot, np, sx->x);
    mm_linspace(0, t_plot, np, sv->x);

    /* the numerical solution: arc by arc, each ended by an event */
    size_t cap = 20000;
    double *ts_buf = mm_res_alloc(res, cap * sizeof *ts_buf), *ys_buf = mm_res_alloc(res, 2 * cap * sizeof *ys_buf);
    double *tn = mm_res_alloc(res, (MAX_ARCS + 1) * sizeof *tn), *xn = mm_res_alloc(res, (MAX_ARCS + 1) * sizeof *xn);
    if (!ts_buf || !ys_buf || !tn || !xn)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_ode_work *w = mm_ode_work_alloc(2);
    if (!w)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    stats st = {0};
    int g = 0, nn = 0, rc = MM_OK;
    double t = 0, x = s.x0, v = s.v0;
    double sg;
    if (v != 0)
        sg = v > 0 ? 1 : -1;
    else
        sg = x > 0 ? -1 : 1;
    /* the mass moves when it has speed, or when the spring beats static friction, eq. (6) */
    int moving = v != 0 || !sticks(&s, x);
    while (moving && rc == MM_OK) {
        if (nn == MAX_ARCS + 1) {
            rc = mm_error_set(err, MM_EINTERNAL, "", "more sliding arcs than the work bound allows");
            break;
        }
        rc = slide(&s, t, x, v, sg, w, ts_buf, ys_buf, cap, sx->x, np, &g, sx->y, sv->y, &t, &x, &st, res, err);
        if (rc != MM_OK)
            break;
        v = 0;                                    /* the event: the mass is at rest */
        tn[nn] = t;
        xn[nn++] = x;
        moving = !sticks(&s, x);                  /* eq. (6): stick, or turn back */
        sg = x > 0 ? -1 : 1;
    }
    mm_ode_work_free(w);
    if (rc != MM_OK)
        return rc;
    for (; g < np; g++) {                         /* at rest for good */
        sx->y[g] = x;
        sv->y[g] = 0;
    }
    double stop_time = nn ? tn[nn - 1] : 0;

    mm_res_scalar_v1(res, "stop_time", "time the mass stops for good", "s", stop_time);
    mm_res_scalar_v1(res, "x_final", "final position", "m", x);
    mm_res_scalar_v1(res, "half_cycles", "sliding arcs (half cycles) before the stop", "", nn);
    mm_res_scalar_v1(res, "spring_force_final", "spring force at the stop, |k x_final|", "N", fabs(s.k * x));
    mm_res_scalar_v1(res, "friction_limit", "largest friction force mu m g", "N", fric);

    mm_res_method(res, "dopri5 per sliding arc, velocity zero located by Brent's method", 0);
    mm_res_method_stat(res, "rtol", 1e-10);
    mm_res_method_stat(res, "steps", (double)st.steps);
    mm_res_method_stat(res, "rejected", (double)st.rejected);
    mm_res_method_stat(res, "evaluations", (double)st.evals);
    mm_res_method_stat(res, "events", nn);
    mm_res_method_stat(res, "brent_iterations", (double)st.brent_iters);
    mm_res_method_stat(res, "error_estimate", st.err_sum);

    /* the rests: time, place, and the spring force against the friction limit */
    static const char *const cols[] = {"t", "x", "spring_over_friction"};
    static const char *const units[] = {"s", "m", ""};
    mm_table *tab = mm_res_table_v1(res, "rests", nn, 3, cols, units);
    mm_series *amp = mm_res_series_v1(res, "amplitude", "distance from x = 0 at each rest", "m", "t", "s",
                                   nn + 1);
    if (!tab || !amp)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    amp->x[0] = 0;
    amp->y[0] = fabs(s.x0);
    for (int j = 0; j < nn; j++) {
        tab->cell[3 * j] = tn[j];
        tab->cell[3 * j + 1] = xn[j];
        tab->cell[3 * j + 2] = fabs(s.k * xn[j]) / fric;
        amp->x[j + 1] = tn[j];
        amp->y[j + 1] = fabs(xn[j]);
    }

    /* ---- checks ---- */
    double size = fabs(s.x0) + fabs(s.v0) / s.w + s.d;    /* the scale of the motion */
    if (nn == 0) {
        /* never moves: the spring force is within the friction limit, eq. (6) */
        mm_res_check_abs(res, "at rest from the start: excess of |k x0| over mu m g [N]",
                         fmax(0, fabs(s.k * s.x0) - fric), 0, STICK_MARGIN * fric);
        mm_res_check_abs(res, "x_final vs x0 (it never moves)", x, s.x0, 0);
        return MM_OK;
    }
    /* Error budget: DOPRI5 at rtol 1e-10 and Brent to round-off put each rest
     * within about 1e-11 of the motion's size of the exact one; its time is
     * less sharp (the phase error of the arc, up to a few 1e-9 / omega_n),
     * while the place is insensitive to it (v = 0 there).  Each arc starts
     * where the last one ended, so the errors add up over the arcs: allow
     * 1e-10 of the size and 2e-9 / omega_n per arc. */
    double budget = 1e-10 * (nn + 5);
    mm_res_check_abs(res, "stop_time: located by events vs piecewise closed form", stop_time, stop_exact,
                     2e-9 * (nn + 5) / s.w);
    mm_res_check_abs(res, "x_final: located by events vs piecewise closed form", x, xf_exact, budget * size);
    mm_res_check_abs(res, "half cycles: counted by events vs closed form", nn, ne, 0);

    /* amplitude lost per half cycle started from rest, eq. (5): the arc from
     * x_{j-1} ends at x_j = -(x_{j-1} - 2 d sign x_{j-1}), so
     * |x_{j-1}| + sign(x_{j-1}) x_j = 2 d (also when the last arc stops short
     * on the same side) */
    if (nn >= 2) {
        double worst = -1, lost = 0;
        for (int j = 1; j < nn; j++) {
            double l = fabs(xn[j - 1]) + (xn[j - 1] > 0 ? xn[j] : -xn[j]);
            if (fabs(l - 2 * s.d) > worst) {
                worst = fabs(l - 2 * s.d);
                lost = l;
            }
        }
        mm_res_check_abs(res, "amplitude lost per half cycle (worst) vs 2 mu m g / k", lost, 2 * s.d,
                         budget * size);
    }

    /* energy: what is gone is friction force times path length (the path of
     * one arc is |x_end - x_start|: the velocity keeps its sign on an arc) */
    double path = fabs(xn[0] - s.x0);
    for (int j = 1; j < nn; j++)
        path += fabs(xn[j] - xn[j - 1]);
    double E0 = 0.5 * s.k * s.x0 * s.x0 + 0.5 * s.m * s.v0 * s.v0, Ef = 0.5 * s.k * x * x;
    mm_res_check_abs(res, "energy: E(0) - E(stop) vs mu m g times the path slid [J]", E0 - Ef, fric * path,
                     budget * (E0 + fric * size));

    /* the whole response against the closed form at every plotted point */
    double worst = -1, xw = 0, xr = 0;
    for (int i = 0; i < np; i++) {
        double vr, ref = exact_x(&s, te, xe, sge, ne, sx->x[i], &vr);
        if (fabs(sx->y[i] - ref) > worst) {
            worst = fabs(sx->y[i] - ref);
            xw = sx->y[i];
            xr = ref;
        }
    }
    mm_res_method_stat(res, "max_error", worst);
    /* between the rests x carries the arcs' phase error: the time budget */
    mm_res_check_abs(res, "x(t) vs piecewise closed form (worst plotted point)", xw, xr, 2e-9 * (nn + 5) * size);

    if ((np - 1) / (t_plot * s.w / (2 * M_PI)) < 8)
        mm_res_warn(res, "the plot has under 8 points per period: it cannot show each swing "
                         "(it aliases); raise points");
    return MM_OK;
}

static const char *const references[] = {
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, section 2.9 (Coulomb damping)",
    "E. Hairer, S. P. Norsett, G. Wanner, Solving Ordinary Differential Equations I, Springer 1993, "
    "sections II.5-II.6 (DOPRI5, dense output, event location)",
    "R. P. Brent, Algorithms for Minimization without Derivatives, Prentice-Hall 1973, ch. 4",
    NULL,
};

const mm_exercise mm_ex_vib_coulomb = {
    .id = "vib-coulomb",
    .chapter = 5,
    .section = "5.9.7",
    .title = "Vibration with Coulomb friction",
    .summary = "A mass on a spring sliding on a rough floor: straight-line decay and a stop away from zero.",
    .tags = "vibration, 1 DOF, dry friction, Coulomb, events, nonsmooth",
    .theory = "exercises/vib/coulomb.md",
    .params = params,
    .n_params = MM_COUNT(params),
    .references = references,
    .check = check,
    .solve = solve,
};
