/* mm_quad.c — adaptive Gauss-Kronrod and composite Gauss-Legendre
 * quadrature.  Contracts in mm_quad.h.
 */
#include "mm_quad.h"

#include <assert.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>

/* ---- Gauss-Kronrod 7-15 (QUADPACK qk15): nodes and weights on [-1, 1] ---- */

static const double xgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                              0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                              0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                              0.207784955007898467600689403773245, 0.0};
static const double wgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                              0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                              0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                              0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
static const double wg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                             0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

/* 5-point Gauss-Legendre on [-1, 1], the code base's one copy (mm_quad.h):
 * the nodes in increasing order and their weights */
const double mm_quad_gl5_node[5] = {-0.906179845938663992797626878299, -0.538469310105683091036314420700, 0,
                                    0.538469310105683091036314420700, 0.906179845938663992797626878299};
const double mm_quad_gl5_weight[5] = {0.236926885056189087514264040720, 0.478628670499366468041291514836,
                                      0.568888888888888888888888888889, 0.478628670499366468041291514836,
                                      0.236926885056189087514264040720};

/* a rounding floor: the error estimates never claim better than this many
 * eps of the integral of |f| (QUADPACK takes 50; with compensated sums a
 * few are what rounding reaches), plus what the rounding of the nodes
 * themselves does: a node x is placed to within u |x|, which moves f by
 * |f'| u |x|, so the integral by up to u max |x| times the total variation
 * of f (measured between the nodes) */
#define FLOOR_EPS 4

static double floor_of(double resabs, double tv, double a, double b)
{
    return FLOOR_EPS * DBL_EPSILON * resabs + DBL_EPSILON / 2 * fmax(fabs(a), fabs(b)) * tv;
}

void mm_quad_options_init(mm_quad_options *opt)
{
    assert(opt);
    opt->rtol = 1e-12;
    opt->atol = 0;
    opt->max_pieces = 400;
    opt->start_pieces = 8;
}

int mm_quad_check(double a, double b, const mm_quad_options *opt, mm_error *err)
{
    assert(opt);
    if (!isfinite(a))
        return mm_error_set(err, MM_EVALUE, "a", "bad value for 'a' (must be finite, got %g)", a);
    if (!isfinite(b) || !(b > a) || !isfinite(b - a))
        return mm_error_set(err, MM_EVALUE, "b", "bad value for 'b' (must be finite and greater than a = %g, "
                            "got %g)", a, b);
    if (!(opt->rtol >= 0) || !isfinite(opt->rtol))
        return mm_error_set(err, MM_EVALUE, "rtol", "bad value for 'rtol' (must be >= 0, got %g)", opt->rtol);
    if (!(opt->atol >= 0) || !isfinite(opt->atol) || (opt->rtol == 0 && opt->atol == 0))
        return mm_error_set(err, MM_EVALUE, "atol", "bad value for 'atol' (must be >= 0, and rtol and atol "
                            "not both 0, got %g)", opt->atol);
    if (opt->max_pieces < 1 || opt->max_pieces > MM_QUAD_MAX_PIECES)
        return mm_error_set(err, MM_EVALUE, "max_pieces", "bad value for 'max_pieces' (must be between 1 and "
                            "%d, got %d)", MM_QUAD_MAX_PIECES, opt->max_pieces);
    if (opt->start_pieces < 1 || opt->start_pieces > opt->max_pieces)
        return mm_error_set(err, MM_EVALUE, "start_pieces", "bad value for 'start_pieces' (must be between 1 "
                            "and max_pieces = %d, got %d)", opt->max_pieces, opt->start_pieces);
    return MM_OK;
}

/* Neumaier's compensated sum: s + c is the sum to ~eps |s| */
typedef struct csum {
    double s, c;
} csum;

static void cadd(csum *k, double x)
{
    double t = k->s + x;
    k->c += fabs(k->s) >= fabs(x) ? (k->s - t) + x : (x - t) + k->s;
    k->s = t;
}

static double cval(const csum *k) { return k->s + k->c; }

static int call(mm_quad_fn f, void *params, double x, double *fx, long *evals, mm_error *err)
{
    ++*evals;
    int rc = f(x, fx, params);
    if (rc != 0)
        return rc;
    if (!isfinite(*fx))
        return mm_error_set(err, MM_ENONFINITE, "f", "f is not finite at x = %.17g", x);
    return MM_OK;
}

/* K15, its error estimate and K15 of |f| on [a, b] (QUADPACK qk15) */
static int gk15(mm_quad_fn f, void *params, double a, double b, mm_quad_piece *p, long *evals, mm_error *err)
{
    double h = 0.5 * (b - a), m = 0.5 * (a + b), fv[15];
    int rc = call(f, params, m, &fv[0], evals, err);
    for (int j = 0; j < 7 && rc == MM_OK; j++) {
        rc = call(f, params, m - h * xgk[j], &fv[1 + 2 * j], evals, err);
        if (rc == MM_OK)
            rc = call(f, params, m + h * xgk[j], &fv[2 + 2 * j], evals, err);
    }
    if (rc != MM_OK)
        return rc;
    double k = wgk[7] * fv[0], g = wg[3] * fv[0], ak = wgk[7] * fabs(fv[0]);
    for (int j = 0; j < 7; j++) {
        double s = fv[1 + 2 * j] + fv[2 + 2 * j];
        k += wgk[j] * s;
        ak += wgk[j] * (fabs(fv[1 + 2 * j]) + fabs(fv[2 + 2 * j]));
        if (j % 2 == 1)
            g += wg[j / 2] * s;
    }
    double mean = 0.5 * k, asc = wgk[7] * fabs(fv[0] - mean);
    for (int j = 0; j < 7; j++)
        asc += wgk[j] * (fabs(fv[1 + 2 * j] - mean) + fabs(fv[2 + 2 * j] - mean));
    double e = fabs((k - g) * h), resasc = asc * fabs(h), resabs = ak * fabs(h);
    if (resasc != 0 && e != 0)                       /* QUADPACK's sharpening */
        e = resasc * fmin(1, pow(200 * e / resasc, 1.5));
    /* total variation between the nodes in order: m - h x_0 < ... < m < ... < m + h x_0 */
    double tv = 0, prev = fv[1];
    for (int j = 1; j < 7; j++) {
        tv += fabs(fv[1 + 2 * j] - prev);
        prev = fv[1 + 2 * j];
    }
    tv += fabs(fv[0] - prev);
    prev = fv[0];
    for (int j = 6; j >= 0; j--) {
        tv += fabs(fv[2 + 2 * j] - prev);
        prev = fv[2 + 2 * j];
    }
    double fl = floor_of(resabs, tv, a, b);
    *p = (mm_quad_piece){a, b, k * h, fmax(e, fl), resabs, fl};
    return MM_OK;
}

int mm_quad_gk(mm_quad_fn f, void *params, double a, double b, const mm_quad_options *opt,
               mm_quad_piece *piece, mm_quad_result *r, mm_error *err)
{
    assert(f && r);
    *r = (mm_quad_result){0};
    int rc = mm_quad_check(a, b, opt, err);
    if (rc != MM_OK)
        return rc;
    mm_quad_piece *p = piece ? piece : malloc((size_t)opt->max_pieces * sizeof *p);
    if (!p)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory for quadrature");
    int np = opt->start_pieces;
    for (int i = 0; i < np && rc == MM_OK; i++)
        rc = gk15(f, params, i == 0 ? a : a + (b - a) * i / np, i == np - 1 ? b : a + (b - a) * (i + 1) / np,
                  &p[i], &r->evals, err);
    while (rc == MM_OK) {
        csum sum = {0, 0}, abs_sum = {0, 0};
        double e = 0;
        int worst = 0;
        for (int i = 0; i < np; i++) {
            cadd(&sum, p[i].value);
            cadd(&abs_sum, p[i].abs_value);
            e += p[i].err;
            if (p[i].err > p[worst].err)
                worst = i;
        }
        r->value = cval(&sum);
        r->abs_value = cval(&abs_sum);
        r->err = e;
        r->pieces = np;
        r->converged = e <= fmax(opt->atol, opt->rtol * r->abs_value);
        double mid = 0.5 * (p[worst].a + p[worst].b);
        if (r->converged || np == opt->max_pieces || !(mid > p[worst].a && mid < p[worst].b))
            break;                                   /* done, out of pieces, or no room to split */
        mm_quad_piece left, right;
        rc = gk15(f, params, p[worst].a, mid, &left, &r->evals, err);
        if (rc == MM_OK)
            rc = gk15(f, params, mid, p[worst].b, &right, &r->evals, err);
        if (rc == MM_OK) {
            p[worst] = left;
            p[np++] = right;
        }
    }
    /* the estimate reported: every piece halved once more, and the sum of
     * what that changed; the halves' sum is returned.  QUADPACK's estimate,
     * which steered the subdivision, overstates the error of a smooth f by
     * orders of magnitude (|K15 - G7| measures G7, not K15); this one is the
     * error of the partition before the last halving, so it still errs on
     * the safe side */
    if (rc == MM_OK) {
        csum sum = {0, 0}, abs_sum = {0, 0};
        double e = 0, floor_total = 0;
        for (int i = 0; i < np && rc == MM_OK; i++) {
            double mid = 0.5 * (p[i].a + p[i].b);
            mm_quad_piece left, right;
            if (!(mid > p[i].a && mid < p[i].b)) {
                cadd(&sum, p[i].value);
                cadd(&abs_sum, p[i].abs_value);
                e += p[i].err;
                floor_total += p[i].floor;
                continue;
            }
            rc = gk15(f, params, p[i].a, mid, &left, &r->evals, err);
            if (rc == MM_OK)
                rc = gk15(f, params, mid, p[i].b, &right, &r->evals, err);
            if (rc == MM_OK) {
                cadd(&sum, left.value);
                cadd(&sum, right.value);
                cadd(&abs_sum, left.abs_value);
                cadd(&abs_sum, right.abs_value);
                e += fabs(left.value + right.value - p[i].value);
                floor_total += left.floor + right.floor;  /* rounding: the halves' own floors */
            }
        }
        if (rc == MM_OK) {
            r->value = cval(&sum);
            r->abs_value = cval(&abs_sum);
            r->err = r->err_value = fmax(e, floor_total);
        }
    }
    if (!piece)
        free(p);
    return rc;
}

/* G5 on m equal panels, compensated, with the integral of |f| and the
 * rounding floor (floor_of: the variation of f along the nodes); part[i],
 * if not NULL, receives panel i's share */
static int gauss_panels(mm_quad_fn f, void *params, double a, double b, int m, double *value, double *abs_value,
                        double *floor, double *part, long *evals, mm_error *err)
{
    csum s = {0, 0}, as = {0, 0};
    double prev = NAN, fl = 0;
    for (int i = 0; i < m; i++) {
        double lo = i == 0 ? a : a + (b - a) * i / m, hi = i == m - 1 ? b : a + (b - a) * (i + 1) / m;
        double mid = 0.5 * (lo + hi), hh = 0.5 * (hi - lo), p = 0, ap = 0, tv = 0;
        for (int j = 0; j < 5; j++) {
            double fv;
            int rc = call(f, params, mid + hh * mm_quad_gl5_node[j], &fv, evals, err);
            if (rc != MM_OK)
                return rc;
            p += mm_quad_gl5_weight[j] * fv;
            ap += mm_quad_gl5_weight[j] * fabs(fv);
            if (!isnan(prev))
                tv += fabs(fv - prev);
            prev = fv;
        }
        if (part)
            part[i] = p * hh;
        cadd(&s, p * hh);
        cadd(&as, ap * hh);
        fl += floor_of(ap * hh, tv, lo, hi);   /* each panel's nodes rounded to u/2 of its own |x| */
    }
    *value = cval(&s);
    *abs_value = cval(&as);
    *floor = fl;
    return MM_OK;
}

int mm_quad_gl(mm_quad_fn f, void *params, double a, double b, int m0, int max_panels, double tol,
               mm_quad_result *r, mm_error *err)
{
    assert(f && r);
    *r = (mm_quad_result){0};
    if (!isfinite(a) || !isfinite(b) || !(b > a) || !isfinite(b - a))
        return mm_error_set(err, MM_EVALUE, "b", "bad interval [%g, %g] (finite, a < b)", a, b);
    if (m0 < 1 || max_panels < m0 || max_panels > MM_QUAD_MAX_PANELS || !(tol >= 0))
        return mm_error_set(err, MM_EVALUE, "max_panels", "bad panel counts (1 <= m0 = %d <= max_panels = %d "
                            "<= %d) or tol (%g)", m0, max_panels, MM_QUAD_MAX_PANELS, tol);
    /* the panels' shares on the last two meshes: panel i of m is panels 2i
     * and 2i + 1 of 2m, to the last bit (a + (b - a) 2i / 2m is
     * a + (b - a) i / m: the factors of 2 are exact) */
    double small[2 * 8];                     /* up to 8 panels: no allocation, no MM_ENOMEM */
    double *base = max_panels <= 8 ? small : malloc(2 * (size_t)max_panels * sizeof *base);
    if (!base)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory for quadrature");
    double *prev_part = base, *cur_part = base + max_panels;
    double cur, abs_value, fl;
    int rc = gauss_panels(f, params, a, b, m0, &cur, &abs_value, &fl, prev_part, &r->evals, err);
    int agree = 0;
    double last = INFINITY;                 /* the change the previous doubling made */
    r->value = cur;
    r->err = r->err_value = INFINITY;
    r->pieces = m0;
    r->abs_value = abs_value;
    for (int m = 2 * m0; rc == MM_OK && m <= max_panels; m *= 2) {
        if ((rc = gauss_panels(f, params, a, b, m, &cur, &abs_value, &fl, cur_part, &r->evals, err)) != MM_OK)
            break;
        /* the estimate: what halving changed, panel by panel, added up in
         * absolute value.  The change of the whole sum would do if every
         * panel's error kept its sign; but the errors of panels on either
         * side of a symmetry point cancel on one mesh and not on the next
         * (sin(x)/(x^2+1), odd, with a mesh point 0.07 from 0: its two
         * panels there err by +-1.23e-7 at m = 1024, which leaves 3e-12 in
         * the sum, while at m = 2048 one panel across 0 errs by 2.5e-10, so
         * |G_2048 - G_1024| is that error itself).  A single panel cannot
         * cancel against another: as long as halving a panel at least
         * halves its error (it divides it by ~1024 once the mesh resolves
         * f), its change exceeds the error of its halves */
        csum d = {0, 0};
        for (int i = 0; i < m / 2; i++)
            cadd(&d, fabs(cur_part[2 * i] + cur_part[2 * i + 1] - prev_part[i]));
        r->err = fmax(cval(&d), fl);
        /* the error of cur itself: the halvings to come change it by
         * err rho + err rho^2 + ... at the rate rho the last two showed
         * (a panel's rate only improves as it resolves f: 2^-10 at the
         * end), once that rate has at least halved the change */
        double rho = isinf(last) ? 1 : cval(&d) / last;
        r->err_value = rho < 0.5 ? fmax(cval(&d) * rho / (1 - rho), fl) : r->err;
        last = cval(&d);
        r->value = cur;
        r->pieces = m;
        r->abs_value = abs_value;
        double *t = prev_part;
        prev_part = cur_part;
        cur_part = t;
        agree = r->err <= tol ? agree + 1 : 0;
        if (agree == 2)
            break;
    }
    if (base != small)
        free(base);
    r->converged = agree == 2;
    if (!r->converged)
        r->err_value = r->err;             /* no rate to trust: the mesh may not resolve f yet */
    return rc;
}

/* ---- statics (chapter 3) ------------------------------------------------------ */

void mm_quad_gl5_nodes(double a, double b, int m, double *x, double *w)
{
    static const int order[5] = {2, 3, 1, 4, 0};      /* mid, then +-0.538, +-0.906 */
    for (int k = 0; k < m; k++) {
        double lo = a + (b - a) * k / m, hi = a + (b - a) * (k + 1) / m;
        for (int g = 0; g < 5; g++) {
            x[5 * k + g] = 0.5 * (lo + hi) + 0.5 * (hi - lo) * mm_quad_gl5_node[order[g]];
            w[5 * k + g] = 0.5 * (hi - lo) * mm_quad_gl5_weight[order[g]];
        }
    }
}

/* ==== the moments of a sampled density (chapter 5, vib-dispersion) ============ */

void mm_quad_moments(const double *x, const double *p, int n, double *centre, double *width)
{
    double s0 = 0, s1 = 0, s2 = 0;
    for (int i = 0; i < n; i++) {
        s0 += p[i];
        s1 += p[i] * x[i];
    }
    *centre = s1 / s0;
    for (int i = 0; i < n; i++) {
        double d = x[i] - *centre;
        s2 += p[i] * d * d;
    }
    *width = sqrt(s2 / s0);
}
