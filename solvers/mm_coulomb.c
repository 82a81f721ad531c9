/* mm_coulomb.c — the exact motion of a block on a spring with Coulomb friction
 * (see mm_coulomb.h). */
#include "mm_coulomb.h"

#include <math.h>

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

