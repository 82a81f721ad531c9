/* mm_dd.c — complex double-double arithmetic with running error bounds
 * (see mm_dd.h). */
#include "mm_dd.h"

#include <float.h>
#include <math.h>

#define U (DBL_EPSILON / 2)

double mm_cdd_abs(mm_cdd z) { return hypot(mm_dd_val(z.re), mm_dd_val(z.im)); }

mm_cdd mm_cdd_mul(mm_cdd a, mm_cdd b)
{
    /* each part: two dd products and a sum, under 8 eps_dd |a||b| */
    double ma = mm_cdd_abs(a), mb = mm_cdd_abs(b);
    return (mm_cdd){mm_dd_sub(mm_dd_mul(a.re, b.re), mm_dd_mul(a.im, b.im)),
                    mm_dd_add(mm_dd_mul(a.re, b.im), mm_dd_mul(a.im, b.re)),
                    (ma * b.err + mb * a.err + a.err * b.err + 8 * MM_DD_EPS * ma * mb) * (1 + 4 * U)};
}

mm_cdd mm_cdd_div(mm_cdd a, mm_cdd b)
{
    double mb = mm_cdd_abs(b);
    if (!(mb > 0) || !isfinite(mb))                  /* b = 0 (or underflowed to 0): no quotient */
        return (mm_cdd){mm_dd_from(INFINITY), mm_dd_from(INFINITY), INFINITY};
    int e = ilogb(mb);
    double s = ldexp(1, e < -1000 ? 1000 : -e);      /* 2^-e, kept finite for a subnormal |b| */
    mm_cdd bs = {mm_dd_mul_d(b.re, s), mm_dd_mul_d(b.im, s), b.err * s};
    mm_dd den = mm_dd_add(mm_dd_mul(bs.re, bs.re), mm_dd_mul(bs.im, bs.im));
    mm_cdd num = mm_cdd_mul(a, (mm_cdd){bs.re, mm_dd_neg(bs.im), bs.err});
    double ma = mm_cdd_abs(a), q = ma / mb, rel_b = b.err / (mb - b.err);
    return (mm_cdd){mm_dd_mul_d(mm_dd_div(num.re, den), s), mm_dd_mul_d(mm_dd_div(num.im, den), s),
                    (q * (a.err / ma + 2 * rel_b) + 16 * MM_DD_EPS * q) * (1 + 4 * U) + (ma == 0 ? a.err / mb : 0)};
}

mm_cdd mm_cdd_pow(mm_cdd a, int n)
{
    mm_cdd z = mm_cdd_exact(1, 0);
    while (n > 0) {
        if (n & 1)
            z = mm_cdd_mul(z, a);
        a = mm_cdd_mul(a, a);
        n >>= 1;
    }
    return z;
}

/* w^n - a */
static mm_cdd residual(mm_cdd w, mm_cdd a, int n)
{
    mm_cdd f = mm_cdd_pow(w, n);
    f.re = mm_dd_sub(f.re, a.re);
    f.im = mm_dd_sub(f.im, a.im);
    return f;
}

mm_cdd mm_cdd_root(mm_cdd a, double r, double theta, int n, int k)
{
    double r1 = pow(r, 1.0 / n), phi = (theta + 2 * M_PI * k) / n;
    mm_cdd w = mm_cdd_exact(r1 * cos(phi), r1 * sin(phi));
    if (r == 0)
        return w;
    for (int it = 0; it < 2; it++) {                 /* Newton: w <- w - (w^n - a) / (n w^(n-1)) */
        mm_cdd d = mm_cdd_pow(w, n - 1);
        d.re = mm_dd_mul_d(d.re, n);
        d.im = mm_dd_mul_d(d.im, n);
        mm_cdd step = mm_cdd_div(residual(w, a, n), d);
        w.re = mm_dd_sub(w.re, step.re);
        w.im = mm_dd_sub(w.im, step.im);
    }
    mm_cdd f = residual(w, a, n);
    double mw = mm_cdd_abs(w);
    w.err = 2 * (mm_cdd_abs(f) + f.err) / (n * pow(mw, n - 1)) + 4 * MM_DD_EPS * mw;
    double re = mm_dd_val(a.re), im = mm_dd_val(a.im);
    if (re == 0 || im == 0) {                        /* a on an axis: arg a / pi = q0 / 2 */
        long q0 = im == 0 ? (re > 0 ? 0 : 2) : (im > 0 ? 1 : -1);
        long q = q0 + 4L * k, m = 2L * n;            /* the root's angle / pi = q / (2n) */
        if (q % m == 0)
            w.im = mm_dd_from(0);                    /* a whole multiple of pi: on the real axis */
        else if (((q - n) % m + m) % m == 0)
            w.re = mm_dd_from(0);                    /* pi/2 plus a multiple of pi: on the imaginary axis */
    }
    return w;
}

/* ---- mm_ddb --------------------------------------------------------------------- */

static int is_double(mm_ddb a) { return a.e == 0 && a.x.lo == 0; }

mm_ddb mm_ddb_add(mm_ddb a, mm_ddb b)
{
    mm_dd s = mm_dd_add(a.x, b.x);
    return (mm_ddb){s, is_double(a) && is_double(b) ? 0 : a.e + b.e + MM_DDB_R * mm_dd_abs(s)};
}

mm_ddb mm_ddb_sub(mm_ddb a, mm_ddb b) { return mm_ddb_add(a, (mm_ddb){mm_dd_neg(b.x), b.e}); }

mm_ddb mm_ddb_mul(mm_ddb a, mm_ddb b)
{
    mm_dd p = mm_dd_mul(a.x, b.x);
    if (is_double(a) && is_double(b))
        return (mm_ddb){p, 0};
    return (mm_ddb){p, mm_ddb_mag(a) * b.e + mm_ddb_mag(b) * a.e + a.e * b.e + MM_DDB_R * mm_dd_abs(p)};
}

mm_ddb mm_ddb_quot(mm_ddb a, mm_ddb b)
{
    mm_dd q = mm_dd_div(a.x, b.x);
    double room = mm_ddb_mag(b) - b.e;
    return (mm_ddb){q, room > 0 ? (a.e + mm_dd_abs(q) * b.e) / room + MM_DDB_R * mm_dd_abs(q) : INFINITY};
}

mm_ddb mm_ddb_norm(mm_ddb a, mm_ddb b)
{
    mm_ddb q = mm_ddb_add(mm_ddb_mul(a, a), mm_ddb_mul(b, b));
    mm_dd r = mm_dd_sqrt(q.x);
    double rv = mm_dd_abs(r);
    return (mm_ddb){r, (rv > 0 ? q.e / rv : sqrt(q.e)) + MM_DDB_R * rv};
}
