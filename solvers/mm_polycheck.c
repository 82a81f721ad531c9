/* mm_polycheck.c — independent checks of polynomial roots and fits (see
 * mm_polycheck.h). */
#include "mm_polycheck.h"

#include <float.h>
#include <math.h>

void mm_poly_roots_summarize(int ncoef, const double *p, const mm_poly_root *roots, mm_poly_roots_summary *s)
{
    int d = ncoef - 1;
    double sabs = 0, serr = 0, lerr = 0;
    *s = (mm_poly_roots_summary){0};
    for (int i = 0; i < d; i++) {
        const mm_poly_root *z = &roots[i];
        double mod = hypot(z->re, z->im);
        s->real += fabs(z->im) <= z->err;
        s->sure_real += z->im == 0 && z->multiplicity == 1;
        s->max_err = fmax(s->max_err, z->err);
        if ((z->flags & MM_POLY_ROOT_MULTIPLE) && z->err > 0) {
            s->multiple++;
            s->mult_err = fmax(s->mult_err, z->err);
        }
        if ((z->flags & MM_POLY_ROOT_ILLCOND) && !(z->flags & MM_POLY_ROOT_MULTIPLE)) {
            s->illcond++;
            s->ill_err = fmax(s->ill_err, z->err);
        }
        s->backward = fmax(s->backward, mm_poly_backward_error(ncoef, p, z->re, z->im));
        s->sum += z->re;
        serr += z->err;
        sabs += mod;
        if (mod == 0) {
            s->zeros++;
        } else {
            s->logprod += log(mod);
            lerr += z->err / mod;
        }
    }
    s->sum_ref = d >= 1 ? -p[1] / p[0] : 0;
    s->sum_tol = serr + 4 * d * DBL_EPSILON * (sabs + fabs(s->sum_ref));
    if (s->zeros == 0) {
        s->logprod_ref = log(fabs(p[d])) - log(fabs(p[0]));
        s->logprod_tol = lerr + 4 * d * DBL_EPSILON * (1 + fabs(s->logprod));
    }
}
