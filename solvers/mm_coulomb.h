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

#endif
