/* mm_opt.c — golden-section search (see mm_opt.h). */
#include "mm_opt.h"

#include <float.h>
#include <math.h>

int mm_opt_golden_max(mm_opt_fn f, void *params, double a, double b, double tol, int max_evals,
                      mm_opt_result *res, mm_error *err)
{
    if (!(a < b) || !isfinite(a) || !isfinite(b) || !(tol > 0) || max_evals < 3)
        return mm_error_set(err, MM_EVALUE, "", "golden section needs a < b finite, tol > 0, "
                            "at least 3 evaluations");
    const double g = 0.5 * (sqrt(5.0) - 1);      /* 0.618: the bracket's shrink per step */
    double c = b - g * (b - a), d = a + g * (b - a), fc, fd;
    int rc = f(c, &fc, params);
    if (rc == 0)
        rc = f(d, &fd, params);
    int evals = 2;
    if (rc != 0)
        return rc;
    while (b - a > tol && evals < max_evals) {
        if (!isfinite(fc) || !isfinite(fd))
            return mm_error_set(err, MM_ENONFINITE, "", "the function is not finite at x = %g",
                                isfinite(fc) ? d : c);
        if (fc == fd && fabs(d - c) <= 1e-8 * fmax(fabs(c), fabs(d))) {
            /* Equal values say the top is flat to rounding only if the point
             * halfway between is no higher: c and d may instead lie either
             * side of a sharp maximum, equal by symmetry and well below it
             * (|H| of a resonance at zeta = 0.0305 on [0, 1.5]: 6.6e-9
             * apart, 5.8e-15 = 26 eps relative below the top, as
             * f'' dx^2 / 2 says).  Then the maximum is in [c, d]: search
             * on there (three more evaluations, within max_evals). */
            if (evals + 3 > max_evals)
                break;
            double m = 0.5 * (c + d), fm;
            rc = f(m, &fm, params);
            evals++;
            if (rc != 0)
                return rc;
            if (!(fm > fc))
                break;                           /* values no longer tell the points apart */
            a = c, b = d;
            c = b - g * (b - a), d = a + g * (b - a);
            rc = f(c, &fc, params);
            if (rc == 0)
                rc = f(d, &fd, params);
            evals += 2;
            if (rc != 0)
                return rc;
            continue;
        }
        if (fc >= fd) {                          /* the maximum is in [a, d] */
            b = d, d = c, fd = fc;
            c = b - g * (b - a);
            rc = f(c, &fc, params);
        } else {                                 /* in [c, b] */
            a = c, c = d, fc = fd;
            d = a + g * (b - a);
            rc = f(d, &fd, params);
        }
        evals++;
        if (rc != 0)
            return rc;
    }
    if (!isfinite(fc) || !isfinite(fd))
        return mm_error_set(err, MM_ENONFINITE, "", "the function is not finite near x = %g", c);
    res->x = fc >= fd ? c : d;
    res->fx = fc >= fd ? fc : fd;
    res->bracket = b - a;
    res->evals = evals;
    return MM_OK;
}

typedef struct signed_fn {
    mm_opt_fn_err f;
    void *params;
    double s;
} signed_fn;

static int signed_eval(double x, double *fx, void *p)
{
    const signed_fn *g = p;
    *fx = g->s * g->f(x, NULL, g->params);
    return 0;
}

void mm_opt_refine_extreme(mm_opt_fn_err f, void *params, double s, double x0, double h, double a, double b,
                           mm_opt_extreme *out)
{
    enum { FINE = 32 };
    double lo = fmax(a, x0 - h), hi = fmin(b, x0 + h), best = x0, fbest = s * f(x0, NULL, params);
    for (int k = 0; k <= FINE && hi > lo; k++) {
        double y = k == FINE ? hi : lo + (hi - lo) * k / FINE, v = s * f(y, NULL, params);
        if (isfinite(v) && v > fbest)
            best = y, fbest = v;
    }
    h = (hi - lo) / FINE;
    lo = fmax(a, best - h), hi = fmin(b, best + h);
    mm_opt_result r = {best, fbest, 0, 0};
    signed_fn g = {f, params, s};
    if (hi > lo)
        mm_opt_golden_max(signed_eval, &g, lo, hi, 4 * DBL_EPSILON * fmax(fabs(lo), fabs(hi)) + DBL_MIN, 200, &r,
                          NULL);
    if (!(r.fx >= fbest))                           /* golden section lost to the scan (an end maximum) */
        r.x = best, r.bracket = 0;
    double ef = 0, v = f(r.x, &ef, params);
    ef = fmax(ef, v != 0 ? ldexp(1, ilogb(v) - 52) : 0);
    /* f'' by a second difference on a scale H well above the noise */
    double H = fmax(h / 4, 1e-6 * fmax(fabs(r.x), h)), fl = f(r.x - H, NULL, params), fr = f(r.x + H, NULL, params);
    double f2 = fabs(fl - 2 * v + fr) / (H * H);
    double band = f2 > 0 ? sqrt(4 * ef / f2) : (hi - lo);
    out->x = r.x;
    out->fx = v;
    out->x_err = fmax(r.bracket, fmin(band, hi - lo)) + 2 * DBL_EPSILON * fabs(r.x);
    out->fx_err = ef + 0.5 * f2 * out->x_err * out->x_err;
}

/* ==== a scan, then golden sections (chapter 5, vib-absorber) ================== */

int mm_opt_scan_golden_max(mm_opt_fn f, void *params, double step, int n, double tol, int max_evals,
                           mm_opt_result *res, mm_error *err)
{
    double best = -INFINITY, fx;
    int ib = 0;
    for (int i = 0; i <= n; i++) {
        int rc = f(i * step, &fx, params);
        if (rc != 0)
            return rc;
        if (fx > best)
            best = fx, ib = i;
    }
    int rc = mm_opt_golden_max(f, params, fmax(ib - 1, 0) * step, fmin(ib + 1, n) * step, tol, max_evals, res, err);
    if (rc == MM_OK && best >= res->fx)          /* the sample is as high (an end, or a kink) */
        res->x = ib * step, res->fx = best;
    return rc;
}
