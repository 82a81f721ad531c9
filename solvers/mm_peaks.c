/* mm_peaks.c — extrema of sampled signals (see mm_peaks.h). */
#include "mm_peaks.h"

int mm_peaks_hermite(int n, const double *t, const double *x, const double *v, double t_from, int cap,
                     double *tp, double *xp)
{
    int np = 0;
    for (int i = 0; i + 1 < n && np < cap; i++) {
        if (t[i] < t_from || !(v[i] * v[i + 1] < 0 || (v[i + 1] == 0 && v[i] != 0)))
            continue;
        double h = t[i + 1] - t[i], u = v[i] / (v[i] - v[i + 1]);    /* v = 0 at t[i] + u h */
        double h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u);
        double h01 = u * u * (3 - 2 * u), h11 = u * u * (u - 1);
        tp[np] = t[i] + u * h;
        xp[np++] = h00 * x[i] + h10 * h * v[i] + h01 * x[i + 1] + h11 * h * v[i + 1];
    }
    return np;
}

int mm_peaks_minima(int n, const double *t, const double *y, double level, double gap, int cap, double *tmin,
                    double *ymin)
{
    int nm = 0;
    for (int i = 1; i + 1 < n && nm < cap; i++) {
        double y0 = y[i - 1], y1 = y[i], y2 = y[i + 1];
        if (!(y1 < y0 && y1 <= y2 && y1 < level))
            continue;
        /* vertex of the parabola through (t0,y0), (t1,y1), (t2,y2) */
        double a = t[i - 1] - t[i], b = t[i + 1] - t[i];
        double da = y0 - y1, db = y2 - y1;
        double den = 2 * (da * b - db * a);
        double tv = t[i] + (den != 0 ? (da * b * b - db * a * a) / den : 0);
        if (tv < t[i - 1] || tv > t[i + 1])
            tv = t[i];
        if (nm > 0 && tv - tmin[nm - 1] < gap) {
            if (y1 < ymin[nm - 1]) {
                tmin[nm - 1] = tv;
                ymin[nm - 1] = y1;
            }
            continue;
        }
        tmin[nm] = tv;
        ymin[nm] = y1;
        nm++;
    }
    return nm;
}
