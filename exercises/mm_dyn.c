/* mm_dyn.c — see mm_dyn.h. */
#include "mm_dyn.h"

#include <math.h>

double mm_dyn_quantum(double size)
{
    if (!(size > 0) || !isfinite(size))
        return 1e-6;
    return pow(10, floor(log10(size * 1e-5)));
}

double mm_dyn_round(double x, double q)
{
    if (q < 1) {                       /* divide by an exact power of ten: the result is the
                                          double nearest the short decimal */
        double p = nearbyint(1 / q);
        return nearbyint(x * p) / p;
    }
    return nearbyint(x / q) * q;
}

void mm_dyn_round_shape(mm_shape *s, double q)
{
    size_t m = (size_t)s->frames * (size_t)s->npts;
    for (size_t k = 0; k < m; k++) {
        s->x[k] = mm_dyn_round(s->x[k], q);
        s->y[k] = mm_dyn_round(s->y[k], q);
    }
}

void mm_dyn_frame_times(mm_anim *a, double t_show)
{
    for (int f = 0; f < a->nframes; f++)
        a->t[f] = a->nframes > 1 ? t_show * f / (a->nframes - 1) : 0;
}
