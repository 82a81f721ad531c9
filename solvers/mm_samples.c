/* mm_samples.c — reading numbers off samples (see mm_samples.h). */
#include "mm_samples.h"

#include <float.h>
#include <math.h>

#define U (DBL_EPSILON / 2)

double mm_samples_chord_deviation(mm_opt_fn f, void *ctx, int n, const double *x, const double *y,
                                  double *x_at)
{
    const double g = 0.381966011250105;          /* (3 - sqrt 5) / 2 */
    double dev = 0, xdev = 0;
    for (int i = 0; i + 1 < n; i++) {
        if (!isfinite(y[i]) || !isfinite(y[i + 1]))
            continue;
        double xm = x[i] + g * (x[i + 1] - x[i]), fm, chord = y[i] + g * (y[i + 1] - y[i]);
        f(xm, &fm, ctx);
        if (isfinite(fm) && fabs(fm - chord) > dev) {
            dev = fabs(fm - chord);
            xdev = xm;
        }
    }
    *x_at = xdev;
    return dev;
}

void mm_samples_offer(mm_samples_cand *cd, double s, double x, double v, double vl, double vr, double h,
                      int from_plot)
{
    if ((!isnan(vl) && s * vl > s * v) || (!isnan(vr) && s * vr > s * v))
        return;
    int j = MM_SAMPLES_NCAND - 1;
    if (cd[j].h > 0 && s * cd[j].v >= s * v)
        return;
    while (j > 0 && (cd[j - 1].h == 0 || s * cd[j - 1].v < s * v)) {
        cd[j] = cd[j - 1];
        j--;
    }
    cd[j] = (mm_samples_cand){x, v, h, from_plot};
}

void mm_samples_offer_scan(mm_samples_cand cd[2][MM_SAMPLES_NCAND], int n, const double *x, const double *y,
                           double h, int from_plot)
{
    for (int i = 0; i < n; i++)
        for (int w = 0; w < 2 && isfinite(y[i]); w++)
            mm_samples_offer(cd[w], w ? -1 : 1, x[i], y[i], i > 0 ? y[i - 1] : NAN, i < n - 1 ? y[i + 1] : NAN, h,
                             from_plot);
}

void mm_samples_best(mm_opt_fn_err f, void *ctx, double s, const mm_samples_cand *cd, double a, double b,
                     double *x, double *v, double *xe, double *ve, int *from_plot)
{
    *xe = 0, *ve = 0, *from_plot = 1;
    for (int j = 0; j < MM_SAMPLES_NCAND && cd[j].h > 0; j++) {
        mm_opt_extreme q;                 /* finer scan, then golden section */
        mm_opt_refine_extreme(f, ctx, s, cd[j].x, cd[j].h, a, b, &q);
        if (j == 0 || s * q.fx > s * *v)
            *x = q.x, *v = q.fx, *xe = q.x_err, *ve = q.fx_err, *from_plot = cd[j].from_plot;
    }
}

double mm_samples_trapezoid(int n, double a, double b, const double *y, double ef, double *err)
{
    double hstep = (b - a) / (n - 1), tr = 0, trc = 0, tre = 0;
    for (int i = 0; i < n; i++) {
        double wgt = (i == 0 || i == n - 1 ? 0.5 : 1) * hstep, term = wgt * y[i], t = tr + term;
        trc += fabs(tr) >= fabs(term) ? (tr - t) + term : (term - t) + tr;
        tr = t;
        tre += 2 * U * fabs(term);
    }
    *err = tre + 2 * ef * (b - a);
    return tr + trc;
}
