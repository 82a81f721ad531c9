/* mm_roots.c — scan for sign changes, refine each with Brent's method.
 * Contracts in mm_roots.h.
 */
#include "mm_roots.h"

#include <assert.h>
#include <float.h>
#include <math.h>

void mm_roots_options_init(mm_roots_options *opt)
{
    assert(opt);
    opt->n = 100;
    opt->tol = 1e-6;
    opt->max_iter = 400;
    opt->suspect = 1e-3;
}

int mm_roots_check(const mm_roots_problem *prob, const mm_roots_options *opt,
                   mm_error *err)
{
    assert(prob && opt && prob->f);
    if (!isfinite(prob->a))
        return mm_error_set(err, MM_EVALUE, "a", "bad value for 'a' (must be a finite number, got %g)", prob->a);
    if (!isfinite(prob->b))
        return mm_error_set(err, MM_EVALUE, "b", "bad value for 'b' (must be a finite number, got %g)", prob->b);
    if (!(prob->a < prob->b))
        return mm_error_set(err, MM_ERANGE, "b",
                            "bad parameter 'b' (must be greater than a = %g, got %g)",
                            prob->a, prob->b);
    if (!isfinite(prob->b - prob->a))
        return mm_error_set(err, MM_ERANGE, "b",
                            "bad parameter 'b' (the interval [%g, %g] is too wide "
                            "to subdivide)", prob->a, prob->b);
    if (opt->n < 1 || opt->n > MM_ROOTS_MAX_N)
        return mm_error_set(err, MM_ERANGE, "n",
                            "bad parameter 'n' (must be between 1 and %d, got %d)",
                            MM_ROOTS_MAX_N, opt->n);
    if (!(opt->tol > 0) || !isfinite(opt->tol))
        return mm_error_set(err, MM_ERANGE, "tol",
                            "bad parameter 'tol' (must be a finite number > 0, got %g)",
                            opt->tol);
    if (opt->max_iter < 1 || opt->max_iter > MM_ROOTS_MAX_ITER)
        return mm_error_set(err, MM_ERANGE, "max_iter",
                            "bad parameter 'max_iter' (must be between 1 and %d, got %d)",
                            MM_ROOTS_MAX_ITER, opt->max_iter);
    if (!(opt->suspect >= 0))
        return mm_error_set(err, MM_ERANGE, "suspect",
                            "bad parameter 'suspect' (must be >= 0, got %g)",
                            opt->suspect);
    return MM_OK;
}

/* One call of f, counted; a nonzero return from f becomes our status. */
static int call(mm_roots_fn f, void *params, double x, double *fx,
                long *nevals, mm_error *err)
{
    if (nevals)
        ++*nevals;
    int rc = f(x, fx, params);
    if (rc != 0) {
        if (rc <= MM_OK || rc >= MM_STATUS_COUNT)
            rc = MM_EVALUE;
        return mm_error_set(err, rc, "f",
                            "the function could not be evaluated at x = %.17g", x);
    }
    return MM_OK;
}

/* ==== Brent's method ========================================================== */

int mm_roots_brent(mm_roots_fn f, void *params, double a, double b,
                   double fa, double fb, double tol, int max_iter,
                   double *x, double *fx, double *width, int *iter,
                   long *nevals, mm_error *err)
{
    assert(f && x && fx && width);
    assert((fa < 0 && fb > 0) || (fa > 0 && fb < 0));
    /* Brent's zeroin (Forsythe, Malcolm & Moler 1977, after Brent 1973):
     * b is the best estimate, [b, c] brackets the root, a is the previous b.
     * Each step tries inverse quadratic interpolation through a, b, c (or
     * the secant through a, b when a == c), and falls back to bisection
     * whenever the interpolated step is not safely inside the bracket or
     * does not shrink fast enough; so it is never slower than bisection by
     * more than a bounded factor, and superlinear near a simple root.
     * Brent's own safeguard still lets the bracket shrink slowly for a long
     * time near a multiple root ((x-1)^3 needed 109-146 steps to 1e-12):
     * here, when three steps in a row have not halved the bracket, the next
     * one bisects, so every four steps at least halve it and 4 log2(width /
     * tol) + 4 steps always suffice. */
    double c = a, fc = fa, d = b - a, e = d, checkpoint = fabs(b - a);
    int slow = 0;
    for (int it = 0;; it++) {
        if ((fb > 0) == (fc > 0)) {          /* root now in [a, b]: rename */
            c = a; fc = fa;
            d = e = b - a;
        }
        if (fabs(c - b) <= 0.5 * checkpoint) {
            checkpoint = fabs(c - b);
            slow = 0;
        } else {
            slow++;
        }
        if (fabs(fc) < fabs(fb)) {           /* keep b the better end */
            a = b; b = c; c = a;
            fa = fb; fb = fc; fc = fa;
        }
        double tol1 = 2 * DBL_EPSILON * fabs(b) + 0.5 * tol;
        double xm = 0.5 * (c - b);
        if (fabs(xm) <= tol1 || fb == 0) {
            *x = b;
            *fx = fb;
            *width = fabs(c - b);
            return MM_OK;
        }
        if (it >= max_iter)
            return mm_error_set(err, MM_ENOCONV, "max_iter",
                                "no convergence in %d iterations of Brent's method "
                                "(bracket still [%.17g, %.17g]); raise max_iter or tol",
                                max_iter, b < c ? b : c, b < c ? c : b);
        if (iter)
            ++*iter;
        if (slow >= 3) {
            d = e = xm;                      /* forced bisection */
            slow = 0;
        } else if (fabs(e) >= tol1 && fabs(fa) > fabs(fb)) {
            double s = fb / fa, p, q;
            if (a == c) {                    /* secant */
                p = 2 * xm * s;
                q = 1 - s;
            } else {                         /* inverse quadratic interpolation */
                double qq = fa / fc, r = fb / fc;
                p = s * (2 * xm * qq * (qq - r) - (b - a) * (r - 1));
                q = (qq - 1) * (r - 1) * (s - 1);
            }
            if (p > 0) q = -q;
            else p = -p;
            /* accept only a step that lands well inside the bracket and is
             * less than half the step before last (else bisect) */
            if (2 * p < 3 * xm * q - fabs(tol1 * q) && p < fabs(0.5 * e * q)) {
                e = d;
                d = p / q;
            } else {
                d = e = xm;
            }
        } else {
            d = e = xm;                      /* bisection */
        }
        a = b;
        fa = fb;
        b += fabs(d) > tol1 ? d : (xm > 0 ? tol1 : -tol1);  /* at least tol1 */
        int rc = call(f, params, b, &fb, nevals, err);
        if (rc)
            return rc;
        if (!isfinite(fb))
            return mm_error_set(err, MM_ENONFINITE, "f",
                                "the function is not finite at x = %.17g", b);
    }
}

/* ==== the scan ================================================================ */

/* f, recording the largest finite |f| it returns: a jump keeps |f| large
 * everywhere in the bracket, a root only near its ends */
typedef struct watch {
    mm_roots_fn f;
    void *params;
    double fmax;
} watch;

static int watched(double x, double *fx, void *p)
{
    watch *w = p;
    int rc = w->f(x, fx, w->params);
    if (rc == 0 && isfinite(*fx))
        w->fmax = fmax(w->fmax, fabs(*fx));
    return rc;
}

int mm_roots_solve(const mm_roots_problem *prob, const mm_roots_options *opt,
                   mm_roots_result *res, mm_error *err)
{
    int rc;
    assert(res && res->roots);
    res->nroots = res->npoles = res->nskipped = res->max_iterations = 0;
    res->nevals = 0;
    if ((rc = mm_roots_check(prob, opt, err)))
        return rc;
    if (res->cap < 1)
        return mm_error_set(err, MM_ERANGE, "n", "no room for roots (cap = %d)", res->cap);

    const int n = opt->n;
    const double a = prob->a, b = prob->b;
    double x0 = a, f0;
    if ((rc = call(prob->f, prob->params, x0, &f0, &res->nevals, err)))
        return rc;
    for (int i = 0; i <= n; i++) {
        double x1 = i == n ? b : a + (b - a) * i / n, f1;  /* ends exact */
        if (i == 0) {
            f1 = f0;
        } else if ((rc = call(prob->f, prob->params, x1, &f1, &res->nevals, err))) {
            return rc;
        }
        if (f1 == 0.0) {                     /* a root on the grid: once */
            if (res->nroots >= res->cap)
                goto full;
            res->roots[res->nroots++] = (mm_roots_root){x1, 0.0, 0.0, 0, MM_ROOTS_EXACT, i};
        } else if (i > 0 && isfinite(f0) && isfinite(f1) && ((f0 < 0) != (f1 < 0))
                   && f0 != 0.0) {
            double x, fx, w;
            int iter = 0;
            mm_error local;
            watch wt = {prob->f, prob->params, fmax(fabs(f0), fabs(f1))};
            rc = mm_roots_brent(watched, &wt, x0, x1, f0, f1, opt->tol,
                                opt->max_iter, &x, &fx, &w, &iter, &res->nevals,
                                &local);
            if (iter > res->max_iterations)
                res->max_iterations = iter;
            if (rc == MM_ENONFINITE) {
                res->nskipped++;
            } else if (rc) {
                if (err)
                    *err = local;
                return rc;
            } else {
                double fend = fmax(fabs(f0), fabs(f1));
                if (fabs(fx) > fend) {       /* |f| grew as the bracket shrank */
                    if (res->poles && res->npoles < res->pole_cap)
                        res->poles[res->npoles] = x;
                    res->npoles++;
                } else {
                    if (res->nroots >= res->cap)
                        goto full;
                    /* a residual large beside every |f| met in the part:
                     * f jumps through zero rather than crossing it */
                    int flags = fabs(fx) > opt->suspect * wt.fmax ? MM_ROOTS_SUSPECT : 0;
                    res->roots[res->nroots++] = (mm_roots_root){x, fx, w, iter, flags, i - 1};
                }
            }
        } else if (i > 0 && (!isfinite(f0) || !isfinite(f1))) {
            res->nskipped++;
        }
        x0 = x1;
        f0 = f1;
    }
    return MM_OK;
full:
    return mm_error_set(err, MM_ERANGE, "n",
                        "more than %d roots found; give more room or a shorter "
                        "interval", res->cap);
}

/* ==== bisection and the rounding band ============================================ */

int mm_roots_bisect(mm_roots_fn f, void *params, double xl, double xr, double fl, double w, double *x,
                    mm_error *err)
{
    assert(f && x);
    for (int it = 0; it < 200 && xr - xl > w && xr - xl > 4 * DBL_EPSILON * fmax(fabs(xl), fabs(xr)); it++) {
        double xm = xl + 0.5 * (xr - xl), fm;
        int rc = call(f, params, xm, &fm, NULL, err);
        if (rc)
            return rc;
        if (!isfinite(fm))
            return mm_error_set(err, MM_ENONFINITE, "f", "the function is not finite at x = %.17g", xm);
        if (fm == 0) {
            *x = xm;
            return MM_OK;
        }
        if ((fm < 0) == (fl < 0)) {
            xl = xm;
            fl = fm;
        } else {
            xr = xm;
        }
    }
    *x = xl + 0.5 * (xr - xl);
    return MM_OK;
}

double mm_roots_band(mm_roots_fn_err f, void *params, double x, double w, double lo, double hi)
{
    assert(f);
    double worst = 0;
    for (int side = -1; side <= 1; side += 2) {
        double h = fmax(w, 4 * DBL_EPSILON * fabs(x) + DBL_MIN);
        for (int it = 0; it < 80; it++, h *= 2) {
            double y = x + side * h, fy, e;
            if (y < lo || y > hi || f(y, &fy, &e, params) != 0 || !isfinite(fy) || fabs(fy) > e)
                break;
        }
        worst = fmax(worst, h);
    }
    return worst;
}

/* ---- statics (chapter 3): every root on an interval, in one call ----------------- */

int mm_roots_scan(mm_roots_fn f, void *params, double a, double b, int n, double tol, int max_iter,
                  mm_roots_root *roots, mm_roots_result *res, mm_error *err)
{
    mm_roots_options opt;
    mm_roots_options_init(&opt);
    opt.n = n;
    opt.tol = tol;
    if (max_iter > 0)
        opt.max_iter = max_iter;
    *res = (mm_roots_result){.roots = roots, .cap = n + 1};
    mm_roots_problem pb = {.f = f, .params = params, .a = a, .b = b};
    return mm_roots_solve(&pb, &opt, res, err);
}

/* ==== the first root on a grid (chapter 5, vib-fourier-transform) ============= */

int mm_roots_first(mm_roots_fn f, void *params, double step, int i0, int i1, double tol, int max_iter, double *x,
                   int *iter, long *nevals, mm_error *err)
{
    double fa = i0 * step, ga, gb;
    long evals = 1;
    int iters = 0, rc = MM_OK;
    *x = NAN;
    f(fa, &ga, params);
    for (int i = i0 + 1; i <= i1; i++) {
        double fb = i * step;
        f(fb, &gb, params);
        evals++;
        if (gb == 0) {
            *x = fb;
            break;
        }
        if ((ga > 0) != (gb > 0)) {
            double fx, width;
            rc = mm_roots_brent(f, params, fa, fb, ga, gb, tol, max_iter, x, &fx, &width, &iters, &evals, err);
            break;
        }
        fa = fb;
        ga = gb;
    }
    if (iter)
        *iter = iters;
    if (nevals)
        *nevals += evals;
    return rc;
}
