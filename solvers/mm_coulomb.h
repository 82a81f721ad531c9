/* mm_coulomb.h — the exact motion of a block on a linear spring with dry
 * (Coulomb) friction, m x'' + k x = -mu m g sign(x'), arc by arc.
 *
 * Each sliding arc is half a cycle of the undamped oscillator about a centre
 * shifted by the friction band d = mu m g / k against the motion; every arc
 * after the first loses 2 d of amplitude, and the block stops for good at
 * the first rest inside the band |k x| <= mu m g.  The equations (1)-(7)
 * are those of exercises/vib/coulomb.md.  Pure functions, thread-safe.
 */
#ifndef MM_COULOMB_H
#define MM_COULOMB_H

#include "mm_status.h"

/* A rest with |k x| within this relative margin of mu m g counts as a stop
 * (eq. 6 with the knife edge given to sticking), in the closed form and in
 * a numerical solution alike: their positions differ by ~1e-10. */
#define MM_COULOMB_STICK_MARGIN 1e-9

typedef struct mm_coulomb {
    double m, k, mu, g, x0, v0;
    double w;        /* omega_n = sqrt(k/m) [rad/s] */
    double d;        /* friction band mu m g / k [m]: the centre shift */
    double d_lo;     /* d + d_lo is d to twice the precision (a long decay
                        subtracts many d: x0 - 10 d keeps its digits) */
} mm_coulomb;

mm_coulomb mm_coulomb_make(double m, double k, double mu, double g, double x0, double v0);
/* Eq. (6): at rest at x, does static friction hold the mass? */
int mm_coulomb_sticks(const mm_coulomb *s, double x);
/* The first arc: direction sg (+1 or -1), duration tau, end position x1;
 * 0 when the mass never moves. */
int mm_coulomb_first_arc(const mm_coulomb *s, double *sg, double *tau, double *x1);
/* The number of sliding arcs, without stepping through them (may be huge). */
double mm_coulomb_arc_count(const mm_coulomb *s);
/* Rest times t[j], places x[j] and directions sg[j] of arcs j = 0..n-1
 * (at most cap); returns n. */
int mm_coulomb_arcs(const mm_coulomb *s, double *t, double *x, double *sg, int cap);
/* x(tt) and *v = x'(tt) from the arcs. */
double mm_coulomb_x(const mm_coulomb *s, const double *t, const double *x, const double *sg, int n, double tt,
                    double *v);

/* ---- the same motion integrated (chapter 5, vib-coulomb) ---- */

/* A numerical run of eq. (1), arc by arc. */
typedef struct mm_coulomb_run {
    int n;              /* out: rests found (events) */
    double *t, *x;      /* in: room for cap + 1 values each; out: the rests' times and places */
    double *xg;         /* in: room for np values; out: x on the plot grid */
    long steps, evals, event_evals;    /* out: the integrator's counters, all arcs */
    /* in: > 0 to integrate each arc again from the same start at this
     * tolerance; out: the sums over the arcs of what that moves its end
     * time, end place and energy balance (7) — the error made on each arc,
     * estimated arc by arc (0 when rtol_ref = 0) */
    double rtol_ref, sum_dt, sum_dx, sum_de;
} mm_coulomb_run;

/* Eq. (1) from (x0, v0) arc by arc: DOP853 at rtol (atol rtol times the
 * arc's size) with friction frozen until the event sg v = 0 (mm_ode event
 * location), the stick test (6), the next arc, at most cap arcs.  The np
 * plot times tg (ascending from 0) receive the dense output of the arc
 * they fall on, and the place of the last rest after it.  Returns MM_OK,
 * or MM_EINTERNAL (no rest within 1.25 half periods of a swing, more than
 * cap arcs), MM_ENOMEM or mm_ode's error, with err filled. */
int mm_coulomb_integrate(const mm_coulomb *s, double rtol, int cap, int np, const double *tg, mm_coulomb_run *o,
                         mm_error *err);

/* Eq. (7) over one arc from (xs, vs) to the rest xe: E lost less mu m g
 * times the path, 0 for the exact arc. */
double mm_coulomb_arc_energy(const mm_coulomb *s, double xs, double vs, double xe);

/* E(0) - E(stop) - mu m g (path slid) over the n rests x of a run (eq. 7):
 * 0 for the exact motion. */
double mm_coulomb_energy_residual(const mm_coulomb *s, int n, const double *x);

#endif
