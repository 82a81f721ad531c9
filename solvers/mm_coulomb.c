/* mm_coulomb.c — the exact motion of a block on a spring with Coulomb friction
 * (see mm_coulomb.h). */
#include "mm_coulomb.h"

#include <math.h>
#include <stdlib.h>

#include "mm_ode.h"

mm_coulomb mm_coulomb_make(double m, double k, double mu, double g, double x0, double v0)
{
    mm_coulomb s = {.m = m, .k = k, .mu = mu, .g = g, .x0 = x0, .v0 = v0};
    s.w = sqrt(s.k / s.m);
    /* d = mu m g / k in double-double: exact products by fma, one corrected division */
    double p = s.mu * s.m, p_lo = fma(s.mu, s.m, -p);
    double q = p * s.g, q_lo = fma(p, s.g, -q) + p_lo * s.g;
    s.d = q / s.k;
    s.d_lo = (fma(-s.d, s.k, q) + q_lo) / s.k;
    return s;
}

/* Eq. (6): at rest at x, does static friction hold the mass? */
int mm_coulomb_sticks(const mm_coulomb *s, double x)
{
    return fabs(s->k * x) <= s->mu * s->m * s->g * (1 + MM_COULOMB_STICK_MARGIN);
}

/* The first arc of eq. (3): direction sg of the motion (+1 or -1), duration
 * tau and end position x1.  Returns 0 when the mass never moves. */
int mm_coulomb_first_arc(const mm_coulomb *s, double *sg, double *tau, double *x1)
{
    if (s->v0 == 0) {
        if (mm_coulomb_sticks(s, s->x0))
            return 0;                              /* static friction holds, eq. (6) */
        *sg = s->x0 > 0 ? -1 : 1;                  /* the spring pulls it back */
        *tau = M_PI / s->w;
        *x1 = 2 * (-*sg * s->d) - s->x0;           /* eq. (4) */
        return 1;
    }
    *sg = s->v0 > 0 ? 1 : -1;
    double c = -*sg * s->d, R = hypot(s->x0 - c, s->v0 / s->w);
    /* x - c = (x0 - c) cos wt + v0/w sin wt stops where tan wt = v0 / (w (x0 - c)),
     * first in (0, pi): the angle straight from atan2 (th + pi for v0 < 0
     * would cancel when the arc is short) */
    *tau = atan2(*sg * s->v0 / s->w, *sg * (s->x0 - c)) / s->w;
    *x1 = c + *sg * R;
    return 1;
}

/* Number of sliding arcs, from eqs. (3)-(5), without stepping through them
 * (for the work bound; may be huge). */
double mm_coulomb_arc_count(const mm_coulomb *s)
{
    double sg, tau, x1;
    if (!mm_coulomb_first_arc(s, &sg, &tau, &x1))
        return 0;
    if (mm_coulomb_sticks(s, x1))
        return 1;
    return 1 + ceil((fabs(x1) - s->d) / (2 * s->d));
}

/* The whole motion in closed form: rest times t[j] and places x[j] at the
 * end of arc j (j = 0..n-1), arc directions sg[j].  Eq. (4) repeated:
 * after the first rest x_1 every arc loses 2 d, x_j = sign (|x_1| - 2 (j - 1) d)
 * with alternating sign, computed in one rounding from the double-double d
 * (and from x0 itself, |x0| - 2 j d, when the motion starts from rest). */
int mm_coulomb_arcs(const mm_coulomb *s, double *t, double *x, double *sg, int cap)
{
    double dir, tau, x1;
    if (!mm_coulomb_first_arc(s, &dir, &tau, &x1))
        return 0;
    int n = 0, from_rest = s->v0 == 0;
    double base = from_rest ? fabs(s->x0) : fabs(x1), side = from_rest ? (s->x0 > 0 ? -1 : 1) : (x1 > 0 ? 1 : -1);
    t[n] = tau;
    x[n] = x1;
    sg[n++] = dir;
    while (!mm_coulomb_sticks(s, x[n - 1]) && n < cap) {     /* eq. (4): turn and slide back */
        double j = from_rest ? n + 1 : n;          /* arcs lost since `base` */
        side = -side;
        sg[n] = x[n - 1] > 0 ? -1 : 1;
        t[n] = tau + n * (M_PI / s->w);
        x[n] = side * (fma(-2 * j, s->d, base) - 2 * j * s->d_lo);
        n++;
    }
    return n;
}

/* x(t) and x'(t) of the closed form at time tt, given the arcs. */
double mm_coulomb_x(const mm_coulomb *s, const double *t, const double *x, const double *sg,
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


/* ==== the same motion integrated (chapter 5, vib-coulomb) ===================== */

/* Eq. (2) on one arc, friction direction frozen: y = (x, v); sg is the
 * direction of the motion, f = sg mu g the friction acceleration. */
typedef struct arc_ctx {
    double w2, f, sg;
} arc_ctx;

static int arc_rhs(double t, const double *y, double *dy, void *ctx)
{
    (void)t;
    dy[0] = y[1];
    dy[1] = -((const arc_ctx *)ctx)->w2 * y[0] - ((const arc_ctx *)ctx)->f;
    return 0;
}

static int arc_event(double t, const double *y, double *g, void *ctx)   /* sg v falls through 0: at rest */
{
    (void)t;
    *g = ((const arc_ctx *)ctx)->sg * y[1];
    return 0;
}

double mm_coulomb_arc_energy(const mm_coulomb *s, double xs, double vs, double xe)
{
    return 0.5 * s->k * (xs * xs - xe * xe) + 0.5 * s->m * vs * vs - s->mu * s->m * s->g * fabs(xe - xs);
}

int mm_coulomb_integrate(const mm_coulomb *s, double rtol, int cap, int np, const double *tg, mm_coulomb_run *o,
                         mm_error *err)
{
    double *yg = malloc(2 * (size_t)np * sizeof *yg);
    mm_ode_work *w = yg ? mm_ode_work_alloc(2) : NULL;
    if (!w) {
        free(yg);
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    }
    double t = 0, y[2] = {s->x0, s->v0};
    double sg = s->v0 != 0 ? (s->v0 > 0 ? 1 : -1) : (s->x0 > 0 ? -1 : 1);
    int g = 0, rc = MM_OK, moving = s->v0 != 0 || !mm_coulomb_sticks(s, s->x0);   /* eq. (6) */
    o->n = 0;
    o->steps = o->evals = o->event_evals = 0;
    o->sum_dt = o->sum_dx = o->sum_de = 0;
    while (moving && rc == MM_OK && o->n <= cap) {
        arc_ctx arc = {.w2 = s->w * s->w, .f = sg * s->mu * s->g, .sg = sg};
        double R = hypot(fabs(y[0]) + s->d, y[1] / s->w);            /* the arc's size */
        mm_ode_problem prob = {.n = 2, .f = arc_rhs, .params = &arc, .t0 = t,
                               .t_end = t + 1.25 * M_PI / s->w, .y0 = y, .event = arc_event,
                               .event_dir = -1};
        mm_ode_options opt;
        mm_ode_options_init(&opt);
        opt.method = MM_ODE_DOP853;
        opt.rtol = rtol;
        opt.atol = rtol * R;
        /* the arc starts on the event surface (v = 0) and ends on it half a
         * period later: a step longer than that would carry g from 0 to 0
         * and the zero would go unseen (mm_ode.h, "Events").  An arc far
         * below the tolerance (a rest a hair outside the sticking band:
         * x0 = 25 d came back at d (1 + 1.9e-9)) is one step otherwise. */
        opt.h_max = 0.5 * M_PI / s->w;
        int gn = g;
        while (gn < np && tg[gn] <= prob.t_end)
            gn++;
        double yend[2];
        mm_ode_result r = {.t_out = tg + g, .nout = (size_t)(gn - g), .y_out = yg + 2 * g, .y_end = yend};
        rc = mm_ode_solve(&prob, &opt, w, &r, err);
        o->steps += r.n_accepted;
        o->evals += r.n_eval;
        o->event_evals += r.n_event_evals;
        if (rc == MM_OK && !r.event)
            rc = mm_error_set(err, MM_EINTERNAL, "", "no velocity zero within 1.25 half periods of a swing");
        if (rc == MM_OK && o->rtol_ref > 0) {                        /* the same arc, finer */
            double yref[2];
            mm_ode_result rr = {.y_end = yref};
            opt.rtol = o->rtol_ref;
            opt.atol = o->rtol_ref * R;
            rc = mm_ode_solve(&prob, &opt, w, &rr, err);
            if (rc == MM_OK && !rr.event)
                rc = mm_error_set(err, MM_EINTERNAL, "", "no velocity zero within 1.25 half periods of a swing");
            if (rc == MM_OK) {
                o->sum_dt += fabs(r.t_event - rr.t_event);
                o->sum_dx += fabs(yend[0] - yref[0]);
                o->sum_de += fabs(mm_coulomb_arc_energy(s, y[0], y[1], yend[0]) -
                                  mm_coulomb_arc_energy(s, y[0], y[1], yref[0]));
            }
        }
        if (rc != MM_OK)
            break;
        g += (int)r.nout_done;
        t = r.t_event;
        y[0] = yend[0];
        y[1] = 0;                                                    /* the event: at rest */
        o->t[o->n] = t, o->x[o->n++] = y[0];
        moving = !mm_coulomb_sticks(s, y[0]);                        /* eq. (6): stick, or turn back */
        sg = y[0] > 0 ? -1 : 1;
    }
    mm_ode_work_free(w);
    if (rc == MM_OK && moving)
        rc = mm_error_set(err, MM_EINTERNAL, "", "more sliding arcs than the work bound allows");
    for (int i = 0; i < np; i++)
        o->xg[i] = i < g ? yg[2 * i] : y[0];                         /* at rest for good */
    free(yg);
    return rc;
}

double mm_coulomb_energy_residual(const mm_coulomb *s, int n, const double *x)
{
    double path = 0, prev = s->x0, xf = n ? x[n - 1] : s->x0;
    for (int j = 0; j < n; j++) {
        path += fabs(x[j] - prev);
        prev = x[j];
    }
    double E0 = 0.5 * s->k * s->x0 * s->x0 + 0.5 * s->m * s->v0 * s->v0, Ef = 0.5 * s->k * xf * xf;
    return E0 - Ef - s->mu * s->m * s->g * path;
}
