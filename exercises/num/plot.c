/* plot.c — num-plot: plot any function of x over an interval, the book's
 * x = -5:0.1:5; plot(x, sin(x)./(x.*x+1)).
 *
 *     y_i = f(x_i),   x_i = a + (b - a) i / (N - 1),   i = 0..N-1       (1)
 *
 * Goal: a plot is a table of samples joined by straight lines; learn what
 * that hides (a peak between samples, a pole drawn as a steep line) and
 * read numbers off the curve properly: the largest and smallest values,
 * refined between the samples (golden-section search), and the area under
 * the curve.  The area is computed by two quadrature rules with different
 * error behaviour — adaptive Gauss-Kronrod (7-15 points, eq. 4) and
 * composite 5-point Gauss-Legendre on a mesh refined by halving (eq. 5) —
 * which must agree within their error estimates; the trapezoid rule on the
 * plot's own samples (eq. 3) is what the drawn polyline encloses.
 * Reference: R. Piessens et al., QUADPACK, Springer 1983 (qk15); W. Press
 * et al., Numerical Recipes, 3rd ed., sections 4.5-4.6 (Gauss quadrature)
 * and 10.2 (golden section).
 */
#include <float.h>
#include <math.h>
#include <stdio.h>

#include "mm_exhelp.h"
#include "mm_expr.h"

#define MAXPTS 2001
#define GK_MAX 400             /* most subintervals of the adaptive rule */
#define GK_START 8             /* pieces to begin with */
#define GL_MAX 2048            /* most panels of the composite Gauss rule */

enum { P_F, P_A, P_B, P_POINTS };

static const mm_param params[] = {
    [P_F] = {"f", "function f(x)", "", MM_EXPR, 0, 0, 0, "sin(x)/(x^2+1)", .vars = "x",
             .help = "any expression of x: + - * / ^, sin cos tan exp ln sqrt abs ..., pi and e"},
    [P_A] = {"a", "left end of the plot", "", MM_REAL, -5, -1e3, 1e3, .help = "the plot starts at x = a"},
    [P_B] = {"b", "right end of the plot", "", MM_REAL, 5, -1e3, 1e3, .help = "and ends at x = b > a"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 101, 11, MAXPTS,
                  .help = "samples joined by straight lines; 101 on [-5, 5] is the book's step of 0.1"},
};

static int check(const mm_value *in, mm_error *err)
{
    if (!(in[P_B].x > in[P_A].x))
        return mm_error_set(err, MM_ERANGE, "b", "b must be greater than a = %g; got %g", in[P_A].x, in[P_B].x);
    return MM_OK;
}

typedef struct fctx {
    mm_expr *e;
    long evals;
    int nonfinite;              /* a quadrature met inf or NaN */
} fctx;

static double f1(fctx *c, double x)
{
    c->evals++;
    double y = mm_expr_eval(c->e, &x);
    if (!isfinite(y))
        c->nonfinite = 1;
    return y;
}

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

typedef struct piece {
    double a, b, k, err, absk;
} piece;

/* K15 and |K15 - G7| on [a, b] (the difference is the error estimate: the
 * 7-point Gauss rule shares 7 of the 15 nodes), and K15 of |f|. */
static piece gk15(fctx *c, double a, double b)
{
    double h = 0.5 * (b - a), m = 0.5 * (a + b);
    double fc = f1(c, m), k = wgk[7] * fc, g = wg[3] * fc, ak = wgk[7] * fabs(fc);
    for (int j = 0; j < 7; j++) {
        double f1v = f1(c, m - h * xgk[j]), f2v = f1(c, m + h * xgk[j]);
        k += wgk[j] * (f1v + f2v);
        ak += wgk[j] * (fabs(f1v) + fabs(f2v));
        if (j % 2 == 1)
            g += wg[j / 2] * (f1v + f2v);
    }
    return (piece){a, b, k * h, fabs((k - g) * h), ak * fabs(h)};
}

/* Global adaptive Gauss-Kronrod: split the piece with the largest error
 * estimate until the sum of estimates is below tol (relative to the
 * integral of |f|) or GK_MAX pieces are used. */
static double gk_adaptive(fctx *c, double a, double b, double rtol, piece *p, double *err, double *l1)
{
    /* start from GK_START equal pieces: one piece over an interval symmetric
     * about a zero of an odd f would give K = G = 0 and stop at once */
    int np = GK_START;
    for (int i = 0; i < np; i++)
        p[i] = gk15(c, i == 0 ? a : a + (b - a) * i / np, i == np - 1 ? b : a + (b - a) * (i + 1) / np);
    for (;;) {
        double sum = 0, e = 0, abs_sum = 0;
        int worst = 0;
        for (int i = 0; i < np; i++) {
            sum += p[i].k;
            e += p[i].err;
            abs_sum += p[i].absk;
            if (p[i].err > p[worst].err)
                worst = i;
        }
        if (c->nonfinite || e <= rtol * abs_sum || np == GK_MAX) {
            *err = e;
            *l1 = abs_sum;
            return sum;
        }
        double m = 0.5 * (p[worst].a + p[worst].b);
        piece left = gk15(c, p[worst].a, m), right = gk15(c, m, p[worst].b);
        p[worst] = left;
        p[np++] = right;
    }
}

/* Composite 5-point Gauss-Legendre on m equal panels, m doubling from
 * m0: G_m.  Stops after two successive |G_m - G_m/2| <= tol, or at
 * GL_MAX panels; *err = the last |G_m - G_m/2|, which for a smooth f
 * overstates the error of G_m (it is about the error of G_m/2).  A rule
 * of another family than Gauss-Kronrod, on a fixed rather than adaptive
 * mesh: the two fail in different ways. */
static const double xgl[3] = {0.0, 0.538469310105683091036314420700208, 0.906179845938663992797626878299393};
static const double wgl[3] = {0.568888888888888888888888888888889, 0.478628670499366468041291514835639,
                              0.236926885056189087514264040719918};

static double gauss_panels(fctx *c, double a, double b, int m)
{
    double s = 0;
    for (int i = 0; i < m; i++) {
        double lo = i == 0 ? a : a + (b - a) * i / m, hi = i == m - 1 ? b : a + (b - a) * (i + 1) / m;
        double mid = 0.5 * (lo + hi), hh = 0.5 * (hi - lo), p = wgl[0] * f1(c, mid);
        for (int j = 1; j < 3; j++)
            p += wgl[j] * (f1(c, mid - hh * xgl[j]) + f1(c, mid + hh * xgl[j]));
        s += p * hh;
    }
    return s;
}

static double gauss_doubling(fctx *c, double a, double b, int m0, double tol, double *err, int *mused)
{
    double prev = gauss_panels(c, a, b, m0), cur = prev;
    int agree = 0;
    *err = INFINITY;
    for (int m = 2 * m0; m <= GL_MAX && !c->nonfinite; m *= 2) {
        cur = gauss_panels(c, a, b, m);
        *err = fabs(cur - prev);
        *mused = m;
        prev = cur;
        if (*err <= tol) {
            if (++agree == 2)
                break;
        } else {
            agree = 0;
        }
    }
    return cur;
}

/* Golden-section search for a maximum of s * f on [lo, hi] (s = +1 for a
 * maximum, -1 for a minimum), started knowing that the middle sample x0 is
 * at least as high as the ends.  Returns the best point seen. */
static double golden(fctx *c, double lo, double hi, double s, double x0, double *best)
{
    const double g = 0.5 * (sqrt(5.0) - 1);
    double bx = x0, bf = s * f1(c, x0);
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    double f1v = s * f1(c, x1), f2v = s * f1(c, x2);
    for (int it = 0; it < 80 && hi - lo > 4 * DBL_EPSILON * fmax(fabs(lo), fabs(hi)) + 1e-300; it++) {
        if (isfinite(f1v) && f1v > bf) { bf = f1v; bx = x1; }
        if (isfinite(f2v) && f2v > bf) { bf = f2v; bx = x2; }
        if (!(f1v < f2v)) {                      /* the peak is left of x2 */
            hi = x2;
            x2 = x1;
            f2v = f1v;
            x1 = hi - g * (hi - lo);
            f1v = s * f1(c, x1);
        } else {
            lo = x1;
            x1 = x2;
            f1v = f2v;
            x2 = lo + g * (hi - lo);
            f2v = s * f1(c, x2);
        }
    }
    *best = s * bf;
    return bx;
}

static int run(const mm_value *in, fctx *c, mm_result *res, mm_error *err)
{
    const double a = in[P_A].x, b = in[P_B].x;
    const int n = (int)in[P_POINTS].x;
    double *xs = mm_res_alloc(res, n * sizeof *xs), *ys = mm_res_alloc(res, n * sizeof *ys);
    piece *pieces = mm_res_alloc(res, GK_MAX * sizeof *pieces);
    if (!xs || !ys || !pieces)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_linspace(a, b, n, xs);
    mm_expr_eval_bulk(c->e, xs, (size_t)n, ys);
    c->evals += n;

    /* keep the finite samples; note the largest and smallest */
    int np = 0, bad = 0, imax = -1, imin = -1;
    double first_bad = 0;
    int *orig = mm_res_alloc(res, n * sizeof *orig);
    if (!orig)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (int i = 0; i < n; i++) {
        if (!isfinite(ys[i])) {
            if (!bad++)
                first_bad = xs[i];
            continue;
        }
        if (imax < 0 || ys[i] > ys[orig[imax]])
            imax = np;
        if (imin < 0 || ys[i] < ys[orig[imin]])
            imin = np;
        orig[np++] = i;
    }
    if (np == 0)
        return mm_error_set(err, MM_ENONFINITE, "f", "f is not a finite number anywhere on [%g, %g] (first "
                            "sample: f(%g)); choose another interval or function", a, b, a);

    mm_series *s = mm_res_series_v1(res, "f", "f(x)", "", "x", "", np);
    if (!s)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (int k = 0; k < np; k++) {
        s->x[k] = xs[orig[k]];
        s->y[k] = ys[orig[k]];
    }

    /* does the polyline follow f?  f between the samples against the chords,
     * at the golden-section fraction g of each step (an irrational fraction
     * rather than the midpoint, so that a wave whose period fits the step
     * twice cannot hide there too) */
    const double g = 0.381966011250105;          /* (3 - sqrt 5) / 2 */
    double dev = 0, xdev = 0, height = ys[orig[imax]] - ys[orig[imin]];
    for (int i = 0; i + 1 < n; i++) {
        if (!isfinite(ys[i]) || !isfinite(ys[i + 1]))
            continue;
        double xm = xs[i] + g * (xs[i + 1] - xs[i]), fm = f1(c, xm), chord = ys[i] + g * (ys[i + 1] - ys[i]);
        if (isfinite(fm) && fabs(fm - chord) > dev) {
            dev = fabs(fm - chord);
            xdev = xm;
        }
    }
    c->nonfinite = 0;                    /* a midpoint may hit a pole; the quadratures will tell */
    if (dev > 0.02 * height || (height == 0 && dev > 0))
        mm_res_warn(res, "between the samples f strays from the drawn lines by up to %.3g (at x = %.6g), %.0f%% of "
                    "the plot's height: the plot misses detail; raise points", dev, xdev,
                    height > 0 ? 100 * dev / height : 100.0);

    /* extremes: the best sample, refined between its neighbours */
    double ext_x[2], ext_f[2];
    for (int w = 0; w < 2; w++) {
        int k = orig[w == 0 ? imax : imin];
        double sg = w == 0 ? 1 : -1;
        ext_x[w] = xs[k];
        ext_f[w] = ys[k];
        if (k > 0 && k < n - 1 && isfinite(ys[k - 1]) && isfinite(ys[k + 1])) {
            double fb, xb = golden(c, xs[k - 1], xs[k + 1], sg, xs[k], &fb);
            if (isfinite(fb) && sg * fb >= sg * ext_f[w]) {
                ext_x[w] = xb;
                ext_f[w] = fb;
            }
        }
    }
    mm_res_scalar_v1(res, "max", "largest value of f (refined between samples)", "", ext_f[0]);
    mm_res_scalar_v1(res, "x_max", "where f is largest", "", ext_x[0]);
    mm_res_scalar_v1(res, "min", "smallest value of f (refined between samples)", "", ext_f[1]);
    mm_res_scalar_v1(res, "x_min", "where f is smallest", "", ext_x[1]);
    mm_res_scalar_v1(res, "points", "points plotted", "", np);

    if (bad) {
        mm_res_warn(res, "f is not finite at %d of the %d samples (first at x = %.6g: a pole, or a value outside "
                    "the domain such as ln of a negative number); they are left out, and the line drawn across "
                    "the gap is not part of the curve", bad, n, first_bad);
        mm_res_warn(res, "the integral of f over [%g, %g] is not computed: f is not finite inside", a, b);
        mm_res_method(res, "sampling on an even grid", 0);
        mm_res_method_stat(res, "evaluations", (double)c->evals);
        return MM_OK;
    }

    /* the area, two ways */
    double egk, l1, egl = INFINITY;
    int mgl = 0, m0 = 8;
    double igk = gk_adaptive(c, a, b, 1e-12, pieces, &egk, &l1);
    while (5 * m0 < n)                           /* start at least as fine as the plot */
        m0 *= 2;
    double igl = c->nonfinite ? 0 : gauss_doubling(c, a, b, m0, 1e-11 * l1, &egl, &mgl);
    if (c->nonfinite) {
        mm_res_warn(res, "the integral of f over [%g, %g] is not computed: f is not finite between the plot "
                    "samples (a pole or a domain error the plot does not show)", a, b);
    } else {
        mm_res_scalar_v1(res, "integral", "integral of f from a to b (area, signed)", "", igk);
        mm_res_check_abs(res, "integral: adaptive Gauss-Kronrod vs composite Gauss-Legendre, within both error "
                         "estimates", igk, igl, egk + egl + 1e-12 * l1);
        /* eq. (3): the trapezoid rule on the plot's samples */
        double tr = 0, hstep = (b - a) / (n - 1);
        for (int i = 0; i + 1 < n; i++)
            tr += 0.5 * hstep * (ys[i] + ys[i + 1]);
        mm_res_scalar_v1(res, "integral_plot", "trapezoid rule on the plotted samples", "", tr);
        if (egk > 1e-8 * l1)
            mm_res_warn(res, "the integral is uncertain: %.6g with an error estimate of %.2g (f changes too fast "
                        "for %d pieces of Gauss-Kronrod); shorten [a, b]", igk, egk, GK_MAX);
        mm_res_method_stat(res, "error_estimate", egk);
        mm_res_method_stat(res, "gauss_panels", mgl);
    }
    mm_res_method(res, "sampling on an even grid; adaptive Gauss-Kronrod 7-15 and composite Gauss-Legendre", 0);
    mm_res_method_stat(res, "evaluations", (double)c->evals);
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    static const char *const vars[] = {"x"};
    fctx c = {NULL, 0, 0};
    int rc = mm_expr_compile(in[P_F].text, vars, 1, &c.e, err);
    if (rc != MM_OK) {
        if (err)
            snprintf(err->param, sizeof err->param, "f");
        return rc;
    }
    rc = run(in, &c, res, err);
    mm_expr_free(c.e);
    return rc;
}

static const char *const references[] = {
    "R. Piessens, E. de Doncker-Kapenga, C. W. Uberhuber, D. K. Kahaner, QUADPACK, Springer 1983 (qk15)",
    "W. H. Press et al., Numerical Recipes, 3rd ed., Cambridge 2007, sections 4.5-4.6 and 10.2",
    NULL,
};

const mm_exercise mm_ex_num_plot = {
    .id = "num-plot",
    .chapter = 1,
    .section = "1.4.3",
    .title = "Plotting a function",
    .summary = "Plot any f(x) on an interval; read off its extremes and the area under it, and see what sampling hides.",
    .tags = "plotting, sampling, extrema, quadrature, Gauss-Kronrod, Gauss-Legendre",
    .theory = "exercises/num/plot.md",
    .params = params,
    .n_params = MM_COUNT(params),
    .references = references,
    .check = check,
    .solve = solve,
};
