/* plot.c — num-plot: plot any function of x over an interval, the book's
 * x = -5:0.1:5; plot(x, sin(x)./(x.*x+1)).
 *
 *     y_i = f(x_i),   x_i = a + (b - a) i / (N - 1),   i = 0..N-1       (1)
 *
 * Goal: a plot is a table of samples joined by straight lines; learn what
 * that hides (a peak between samples, a pole drawn as a steep line) and
 * read numbers off the curve properly: the largest and smallest values,
 * refined between the samples (golden-section search, eq. 6), and the area
 * under the curve.  The area is computed by two quadrature rules with
 * different error behaviour — adaptive Gauss-Kronrod (7-15 points, eq. 4)
 * and composite 5-point Gauss-Legendre on a mesh refined by halving (eq. 5,
 * its estimate the halving's change summed panel by panel, which errors
 * cancelling between panels cannot fool), both in mm_quad — which must
 * agree within their error estimates; the
 * trapezoid rule on the plot's own samples (eq. 3) is what the drawn
 * polyline encloses.
 * Every printed number carries an error estimate: the extremes are searched
 * among the plot's samples and on the adaptive rule's finer partition, then
 * located by golden section; where f is flat at its peak, the rounding of f
 * (mm_expr_eval_err) leaves x known only to about sqrt(2 err_f / |f''|).
 * Reference: R. Piessens et al., QUADPACK, Springer 1983 (qk15); W. Press
 * et al., Numerical Recipes, 3rd ed., sections 4.5-4.6 (Gauss quadrature)
 * and 10.2 (golden section).
 */
#include <math.h>
#include <string.h>

#include "mm_exhelp.h"
#include "mm_num.h"
#include "mm_quad.h"
#include "mm_samples.h"

#define MAXPTS 2001
#define GK_MAX 400             /* most subintervals of the adaptive rule */
#define GL_MAX 2048            /* most panels of the composite Gauss rule */
#define SCAN 8                 /* points per adaptive piece searched for extremes */
/* The work beyond the samples, in evaluations of f: an evaluation costs
 * about 0.06 us per character of f (30 us for a 511-character power
 * tower), so WORK / length evaluations take about 60 ms whatever f is.  The
 * quadratures and the search for extremes share it (the defaults, 14
 * characters, stay at 400 pieces and 2048 panels). */
#define WORK 1.0e6

enum { P_F, P_A, P_B, P_POINTS };

static const mm_param params[] = {
    [P_F] = {"f", "function f(x)", "", MM_EXPR, 0, 0, 0, "sin(x)/(x^2+1)", .vars = "x",
             .help = "any expression of x: + - * / ^, sin cos tan exp ln sqrt abs ..., pi and e; at most 512 characters, "
                     "so that one evaluation stays within microseconds"},
    [P_A] = {"a", "left end of the plot", "", MM_REAL, -5, -1e3, 1e3,
             .help = "the plot starts at x = a; |a| <= 1000, so that 400 adaptive pieces resolve a wave of "
                     "period 1 over the whole interval"},
    [P_B] = {"b", "right end of the plot", "", MM_REAL, 5, -1e3, 1e3, .help = "and ends at x = b > a; |b| <= 1000"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 101, 11, MAXPTS,
                  .help = "samples joined by straight lines; 101 on [-5, 5] is the book's step of 0.1; at most "
                          "2001, about the pixels across a screen"},
};

enum { O_MAX, O_XMAX, O_MIN, O_XMIN, O_POINTS, O_INT, O_INT_PLOT, O_F };

static const mm_output outputs[] = {
    [O_MAX] = MM_SCALAR("max", "largest value of f (refined between samples)", "", .flags = MM_ANSWER),
    [O_XMAX] = MM_SCALAR("x_max", "where f is largest", "", .flags = MM_ANSWER),
    [O_MIN] = MM_SCALAR("min", "smallest value of f (refined between samples)", "", .flags = MM_ANSWER),
    [O_XMIN] = MM_SCALAR("x_min", "where f is smallest", ""),
    [O_POINTS] = MM_SCALAR("points", "points plotted", "", .flags = MM_EXACT),
    [O_INT] = MM_SCALAR("integral", "integral of f from a to b (area, signed)", "", .flags = MM_ANSWER),
    [O_INT_PLOT] = MM_SCALAR("integral_plot", "trapezoid rule on the plotted samples (the polyline's area)", ""),
    [O_F] = MM_SERIES("f", "f(x)", "", "x", ""),
};

static int check(const mm_value *in, mm_error *err)
{
    if (!(in[P_B].x > in[P_A].x))
        return mm_error_set(err, MM_ERANGE, "b", "b must be greater than a = %g; got %g", in[P_A].x, in[P_B].x);
    return MM_OK;
}

static int run(const mm_value *in, mm_num_f *c, mm_result *res, mm_error *err)
{
    const double a = in[P_A].x, b = in[P_B].x;
    const int n = (int)in[P_POINTS].x;
    double *xs = mm_res_alloc(res, 2 * (size_t)n * sizeof *xs);
    mm_quad_piece *pieces = mm_res_alloc(res, GK_MAX * sizeof *pieces);
    if (!xs || !pieces)
        return MM_ENOMEM;
    double *ys = xs + n;
    mm_linspace(a, b, n, xs);
    mm_expr_eval_bulk(c->e, xs, (size_t)n, ys);
    c->evals += n;

    /* keep the finite samples; note the largest and smallest */
    int np = 0, bad = 0, imax = -1, imin = -1;
    double first_bad = 0;
    for (int i = 0; i < n; i++)
        np += isfinite(ys[i]) != 0;
    mm_series *s = mm_res_series(res, O_F, np);
    if (!s)
        return MM_ENOMEM;
    np = 0;
    for (int i = 0; i < n; i++) {
        if (!isfinite(ys[i])) {
            if (!bad++)
                first_bad = xs[i];
            continue;
        }
        if (imax < 0 || ys[i] > ys[imax])
            imax = i;
        if (imin < 0 || ys[i] < ys[imin])
            imin = i;
        s->x[np] = xs[i];
        s->y[np++] = ys[i];
    }
    if (np == 0)
        return mm_error_set(err, MM_ENONFINITE, "f", "f is not a finite number anywhere on [%g, %g] (first "
                            "sample: f(%g)); choose another interval or function", a, b, a);

    /* does the polyline follow f?  f between the samples against the chords,
     * at the golden-section fraction of each step (mm_samples_chord_deviation) */
    double xdev, dev = mm_samples_chord_deviation(mm_num_f_eval, c, n, xs, ys, &xdev), height = ys[imax] - ys[imin];
    if (dev > 0.02 * height || (height == 0 && dev > 0))
        mm_res_warn(res, "between the samples f strays from the drawn lines by up to %.3g (at x = %.6g), %.0f%% of "
                    "the plot's height: the plot misses detail; raise points", dev, xdev,
                    height > 0 ? 100 * dev / height : 100.0);

    /* the area, two ways (eqs. 4-5), within the work budget */
    double budget = WORK / fmax(16, (double)strlen(in[P_F].text));
    mm_quad_options qo;
    mm_quad_options_init(&qo);
    qo.max_pieces = (int)fmax(16, fmin(GK_MAX, 0.4 * budget / 30));   /* 15 evaluations, twice, a piece */
    int gl_max = 16;
    while (2 * gl_max <= GL_MAX && 2 * gl_max * 10 <= 0.4 * budget)  /* the doubling costs ~ 2 m 5 */
        gl_max *= 2;
    mm_quad_result gk = {0}, gl = {0};
    mm_error qerr;
    int have_int = 0;
    if (!bad) {
        int rc = mm_quad_gk(mm_num_f_eval, c, a, b, &qo, pieces, &gk, &qerr);
        int m0 = 8;
        while (5 * m0 < n && 2 * m0 <= gl_max / 4)   /* start at least as fine as the plot */
            m0 *= 2;
        if (rc == MM_OK)
            rc = mm_quad_gl(mm_num_f_eval, c, a, b, m0, gl_max, 1e-11 * gk.abs_value, &gl, &qerr);
        if (rc == MM_ENONFINITE)
            mm_res_warn(res, "the integral of f over [%g, %g] is not computed: f is not finite between the plot "
                        "samples (a pole or a domain error the plot does not show)", a, b);
        else if (rc != MM_OK)
            return mm_error_set(err, rc, "f", "%s", qerr.msg);
        have_int = rc == MM_OK;
    }

    /* extremes: the best few local extremes among the samples and on the
     * adaptive partition (neighbouring bumps of a decaying wave differ by
     * less than the sampling misses them by), each refined between its
     * neighbours (eq. 6); the best refined one wins */
    mm_samples_cand cd[2][MM_SAMPLES_NCAND] = {{{0}}};
    mm_samples_offer_scan(cd, n, xs, ys, (b - a) / (n - 1), 1);     /* the plot's samples */
    for (int p = 0; have_int && p < gk.pieces; p++) {
        double x[SCAN + 1], v[SCAN + 1], h = (pieces[p].b - pieces[p].a) / SCAN;
        for (int k = 0; k <= SCAN; k++) {
            x[k] = pieces[p].a + h * k;
            v[k] = mm_num_f_at(c, x[k]);
        }
        mm_samples_offer_scan(cd, SCAN + 1, x, v, h, 0);
    }
    for (int w = 0; w < 2; w++) {
        double sg = w == 0 ? 1 : -1;
        int k = w == 0 ? imax : imin;
        if ((k > 0 && !isfinite(ys[k - 1])) || (k < n - 1 && !isfinite(ys[k + 1]))) {
            mm_res_warn(res, "no %s value: f is not finite next to its %s sample (x = %.6g), so it is not bounded "
                        "there (a pole)", w == 0 ? "largest" : "smallest", w == 0 ? "largest" : "smallest", xs[k]);
            continue;
        }
        double x = xs[k], v = ys[k], xe, ve;         /* finer scan, then golden section (eq. 6) */
        int from_plot;
        mm_samples_best(mm_num_f_value_err, c, sg, cd[w], a, b, &x, &v, &xe, &ve, &from_plot);
        mm_res_scalar_err(res, w == 0 ? O_MAX : O_MIN, v, ve, MM_ERR_ESTIMATE);
        mm_res_scalar_err(res, w == 0 ? O_XMAX : O_XMIN, x, xe, MM_ERR_ESTIMATE);
        if (!from_plot && sg * (v - ys[k]) > 0.02 * height)
            mm_res_warn(res, "the plotted samples miss the %s value: between them f reaches %.6g at x = %.6g; raise "
                        "points to see it", w == 0 ? "largest" : "smallest", v, x);
    }
    mm_res_scalar(res, O_POINTS, np);

    if (bad) {
        mm_res_warn(res, "f is not finite at %d of the %d samples (first at x = %.6g: a pole, or a value outside "
                    "the domain such as ln of a negative number); they are left out, and the line drawn across "
                    "the gap is not part of the curve", bad, n, first_bad);
        mm_res_warn(res, "the integral of f over [%g, %g] is not computed: f is not finite inside", a, b);
    }
    if (have_int) {
        mm_res_scalar_err(res, O_INT, gk.value, gk.err, MM_ERR_ESTIMATE);
        /* two rules, each within its estimate of its own value's error, and
         * the rounding of the sums (compensated: a few eps of the integral
         * of |f|); Gauss-Legendre's last change is the coarser mesh's error */
        mm_res_check_abs(res, "integral: adaptive Gauss-Kronrod vs composite Gauss-Legendre, within both error "
                         "estimates, eqs. (4)-(5)", gk.value, gl.value, gk.err + gl.err_value);
        /* eq. (3): the trapezoid rule on the plot's samples, with the rounding
         * of f at each sample (mm_expr_eval_err) and of the compensated sum */
        double tre, ef = mm_num_f_rounding(c, n, xs);                 /* at 33 of the samples at most */
        double tr = mm_samples_trapezoid(n, a, b, ys, ef, &tre);   /* twice the largest rounding of f seen */
        mm_res_scalar_err(res, O_INT_PLOT, tr, tre, MM_ERR_ESTIMATE);
        if (!gk.converged)
            mm_res_warn(res, "the integral is uncertain: %.6g with an error estimate of %.2g (f changes too fast "
                        "for %d pieces of Gauss-Kronrod); shorten [a, b]", gk.value, gk.err, GK_MAX);
        mm_res_method_stat(res, "error_estimate", gk.err);
        mm_res_method_stat(res, "gauss_kronrod_pieces", gk.pieces);
        mm_res_method_stat(res, "gauss_panels", gl.pieces);
    }
    mm_res_method(res, "sampling on an even grid; adaptive Gauss-Kronrod 7-15 and composite Gauss-Legendre; "
                       "golden-section search", 0);
    mm_res_method_stat(res, "evaluations", (double)c->evals);
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    mm_num_f c;
    int rc = mm_num_f_compile(&c, in[P_F].text, err);
    if (rc == MM_OK)
        rc = run(in, &c, res, err);
    mm_num_f_free(&c);
    return rc;
}

static const char *const references[] = {
    "R. Piessens, E. de Doncker-Kapenga, C. W. Uberhuber, D. K. Kahaner, QUADPACK, Springer 1983 (qk15)",
    "W. H. Press et al., Numerical Recipes, 3rd ed., Cambridge 2007, sections 4.5-4.6 and 10.2",
    "W. Kahan, How futile are mindless assessments of roundoff in floating-point computation?, 2006",
    NULL,
};

const mm_exercise mm_ex_num_plot = {
    .id = "num-plot", .chapter = 1, .section = "1.4.3", .title = "Plotting a function",
    .summary = "Plot any f(x) on an interval; read off its extremes and the area under it, and see what sampling hides.",
    .tags = "plotting, sampling, extrema, quadrature, Gauss-Kronrod, Gauss-Legendre", .theory = "exercises/num/plot.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
