/* mm_rootcheck.c — a scan's roots confirmed (see mm_rootcheck.h). */
#include "mm_rootcheck.h"

#include <float.h>
#include <math.h>
#include <string.h>

void mm_rootcheck_ends(mm_roots_fn_err f_err, void *ctx, double a, double b, mm_roots_result *rr)
{
    for (int end = 0; end < 2; end++) {
        double x = end ? b : a, e, fx;
        f_err(x, &fx, &e, ctx);
        int have = rr->nroots > 0 && (end ? rr->roots[rr->nroots - 1].x == b : rr->roots[0].x == a);
        if (have || !isfinite(fx) || !(fabs(fx) <= e))
            continue;
        mm_roots_root z = {x, fx, 0, 0, 0, -1};
        if (end) {
            rr->roots[rr->nroots] = z;
        } else {
            memmove(rr->roots + 1, rr->roots, (size_t)rr->nroots * sizeof *rr->roots);
            rr->roots[0] = z;
        }
        rr->nroots++;
    }
}

static double at(mm_roots_fn f, void *ctx, double x)
{
    double y;
    f(x, &y, ctx);
    return y;
}

/* x by the scan's own formula (mm_roots.c), so that the parts are the same */
static double grid(double a, double b, int n, int i) { return i >= n ? b : i <= 0 ? a : a + (b - a) * i / n; }

void mm_rootcheck_confirm(mm_roots_fn f, void *ctx, double a, double b, int n, double tol,
                          const mm_roots_result *rr, mm_rootcheck *o)
{
    double xmax = 0;
    for (int i = 0; i < rr->nroots; i++)
        xmax = fmax(xmax, fabs(rr->roots[i].x));
    *o = (mm_rootcheck){.allowed = 1.25 * tol + 12 * DBL_EPSILON * xmax};
    for (int i = 0; i < rr->nroots; i++) {
        const mm_roots_root *z = &rr->roots[i];
        if ((z->flags & MM_ROOTS_EXACT) || z->part < 0)
            continue;                                /* f(x) = 0 exactly: proven */
        double h = tol + 8 * DBL_EPSILON * fabs(z->x), fm = at(f, ctx, z->x - h), fp = at(f, ctx, z->x + h);
        int own = fm == 0 || fp == 0 || (fm < 0) != (fp < 0);
        o->nosign += !own;
        int j = z->part;                             /* the part Brent refined */
        double xl = grid(a, b, n, j), xr = grid(a, b, n, j + 1), fl = at(f, ctx, xl), fr = at(f, ctx, xr), xb;
        if (j >= n || !(z->x >= xl && z->x <= xr) || !isfinite(fl) || !isfinite(fr) || fl == 0 || fr == 0 ||
            (fl < 0) == (fr < 0)) {
            o->lost++;                               /* no sign change across the part for bisection */
            continue;
        }
        if (mm_roots_bisect(f, ctx, xl, xr, fl, 0.25 * tol, &xb, NULL) != MM_OK)
            o->lost++;
        else if (fabs(z->x - xb) > o->allowed && own)
            o->crowded++;
        else
            o->worst = fmax(o->worst, fabs(z->x - xb));
    }
}
