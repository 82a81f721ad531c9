/* mm_opt.c — golden-section search (see mm_opt.h). */
#include "mm_opt.h"

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
        if (fc == fd && fabs(d - c) <= 1e-8 * fmax(fabs(c), fabs(d)))
            break;                               /* values no longer tell the points apart */
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
