/* nonlinear_roots.c — num-nonlinear-roots: every root of f(x) = 0 on [a, b],
 * the book's rroots(myfunc, -1, 10, 100, 1e-6) -> 1.0434.
 *
 *     f(x) = 0,   a <= x <= b                                            (1)
 *
 * Goal: find all the roots a scan can see, not just one: split [a, b] into n
 * equal parts, keep each part whose ends have opposite signs of f (by the
 * intermediate value theorem, eq. 2, it holds a root), and refine each to
 * the tolerance tol on x with Brent's method (bisection safeguarding
 * secant and inverse quadratic steps).  Learn what such a scan misses: roots
 * of even multiplicity (no sign change) and pairs of roots closer than
 * (b - a) / n, and what fools it: poles and jumps.
 * Each root x carries an error estimate: the width of its final bracket, or
 * where the rounding of f blurs the sign (near a multiple root f stays
 * within its own rounding error over a wide interval), whichever is wider;
 * f(x) carries the estimate of its rounding error (mm_expr_eval_err).
 * Checks: each root against plain bisection restarted from its part (a
 * slower method whose error bound is certain, eq. 3), and a sign change of
 * f across x +- tol around each root.
 * Reference: R. P. Brent, Algorithms for Minimization without Derivatives,
 * Prentice-Hall 1973, ch. 4; G. E. Forsythe, M. A. Malcolm, C. B. Moler,
 * Computer Methods for Mathematical Computations, Prentice-Hall 1977, zeroin.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mm_exhelp.h"
#include "mm_num.h"
#include "mm_rootcheck.h"

#define MAXN 1000
#define MAXPOLES 16
#define PLOT 801

enum { P_F, P_A, P_B, P_N, P_TOL };

static const mm_param params[] = {
    [P_F] = {"f", "function f(x)", "", MM_EXPR, 0, 0, 0, "x^3+sin(x)-2", .vars = "x",
             .help = "any expression of x: + - * / ^, sin cos tan exp ln sqrt abs ..., pi and e; at most 512 characters, "
                     "so that one evaluation stays within microseconds"},
    [P_A] = {"a", "left end of the interval", "", MM_REAL, -1, -1e6, 1e6,
             .help = "search from x = a; |a| <= 1e6 keeps (b - a) / n and tol on one scale"},
    [P_B] = {"b", "right end of the interval", "", MM_REAL, 10, -1e6, 1e6, .help = "to x = b > a; |b| <= 1e6"},
    [P_N] = {"n", "number of subintervals", "", MM_INT, 100, 1, MAXN,
             .help = "[a, b] is cut into n equal parts; two roots in one part are missed, so raise n to separate "
                     "them; at most 1000, and n times the length of f at most 120000 (the work of the scan)"},
    [P_TOL] = {"tol", "tolerance on x", "", MM_REAL, 1e-6, 1e-15, 1,
               .help = "each root is within tol of a sign change of f (absolute, in units of x); from 1e-15, "
                       "about the spacing of doubles near 1, to 1"},
};

enum { O_COUNT, O_X1, O_ROOTS, O_RPTS, O_F };

static const char *const root_cols[] = {"x", "err", "fx", "fx_err", "iterations", NULL},
                         *const root_units[] = {"", "", "", "", "", NULL};

static const mm_output outputs[] = {
    [O_COUNT] = MM_SCALAR("count", "number of roots found (sign changes of f)", "", .flags = MM_ANSWER | MM_EXACT),
    [O_X1] = MM_SCALAR("x1", "the first (smallest) root", "", .flags = MM_ANSWER),
    [O_ROOTS] = MM_TABLE("roots", "the roots, each within err (an estimate) of a root of f", root_cols, root_units),
    [O_RPTS] = MM_SERIES("roots", "roots", "", "x", "", .figure = "f", .mark = "dots"),
    [O_F] = MM_SERIES("f", "f(x)", "", "x", "", .figure = "f"),
};

/* The work grows with n (every part may be refined and checked) times the
 * cost of one evaluation of f, which grows with its length: 1000 parts of
 * a 512-character power tower took 292 ms.  n * max(len, 16) <= 120000
 * keeps the worst case near 70 ms; the default (12 characters, n = 100)
 * is at 1600. */
#define MAX_WORK 120000.0

static int check(const mm_value *in, mm_error *err)
{
    if (!(in[P_B].x > in[P_A].x))
        return mm_error_set(err, MM_ERANGE, "b", "b must be greater than a = %g; got %g", in[P_A].x, in[P_B].x);
    double len = fmax((double)strlen(in[P_F].text), 16);
    if (in[P_N].x * len > MAX_WORK)
        return mm_error_set(err, MM_ERANGE, "n",
                            "n must be at most %.0f with this %.0f-character f (n times the length of f "
                            "may be at most %.0f: a longer expression costs more to evaluate); got %.0f",
                            floor(MAX_WORK / len), len, MAX_WORK, in[P_N].x);
    return MM_OK;
}

static int run(const mm_value *in, mm_num_f *c, mm_result *res, mm_error *err)
{
    const double a = in[P_A].x, b = in[P_B].x, tol = in[P_TOL].x;
    const int n = (int)in[P_N].x;

    mm_roots_problem prob = {.f = mm_num_f_eval, .params = c, .a = a, .b = b};
    mm_roots_options opt;
    mm_roots_options_init(&opt);
    opt.n = n;
    opt.tol = tol;
    double poles[MAXPOLES];
    mm_roots_result rr = {.roots = mm_res_alloc(res, (size_t)(n + 3) * sizeof(mm_roots_root)),
                          .cap = n + 1, .poles = poles, .pole_cap = MAXPOLES};
    if (!rr.roots)
        return MM_ENOMEM;
    int rc = mm_roots_solve(&prob, &opt, &rr, err);
    if (rc == MM_ENOCONV)
        return mm_error_set(err, MM_ENOCONV, "tol", "a root could not be refined to tol = %g in %d steps "
                            "(f is too rough there); raise tol", tol, opt.max_iter);
    if (rc != MM_OK)
        return rc;
    /* a root at an end of [a, b], where f is zero within its own rounding
     * error, has no sign change inside to show it: it is added */
    mm_rootcheck_ends(mm_num_f_eval_err, c, a, b, &rr);
    const int nr = rr.nroots;

    mm_table *t = mm_res_table(res, O_ROOTS, nr);
    mm_series *sr = mm_res_series(res, O_RPTS, nr);
    if (!t || !sr)
        return MM_ENOMEM;
    long scan_evals = c->evals;
    int nsuspect = 0, nblur = 0;
    double wmax = 0, part = (b - a) / n;
    for (int i = 0; i < nr; i++) {
        const mm_roots_root *z = &rr.roots[i];
        double fe, fx = mm_expr_eval_err(c->e, &z->x, &fe);
        /* the root's error: its final bracket (plus the rounding of x), or
         * the band where rounding blurs the sign of f, if wider */
        double w = z->width + 2 * DBL_EPSILON * fabs(z->x);
        double band = mm_roots_band(mm_num_f_eval_err, c, z->x, w, z->x - part, z->x + part);
        nblur += band > fmax(w, tol);
        double e = fmax(w, band);
        double *row = t->cell + 5 * i;
        row[0] = z->x, row[1] = e, row[2] = fx, row[3] = fe, row[4] = z->iterations;
        if (!isfinite(fe))                    /* f overflows in another rounding mode or beside x */
            t->text[5 * i + 3] = "not estimated: f is not finite beside x";
        sr->x[i] = z->x;
        sr->y[i] = 0;
        nsuspect += (z->flags & MM_ROOTS_SUSPECT) != 0;
        wmax = fmax(wmax, e);
        if (i == 0)
            mm_res_scalar_err(res, O_X1, z->x, e, MM_ERR_ESTIMATE);
    }
    mm_res_scalar(res, O_COUNT, nr);

    /* check 1: every root against bisection restarted from its part, to a
     * width of tol/4.  check 2: a sign change of f across x +- h, h covering
     * Brent's final bracket: for a continuous f, a root within h of x. */
    mm_rootcheck k;
    mm_rootcheck_confirm(mm_num_f_eval, c, a, b, n, tol, &rr, &k);
    mm_res_check_abs(res, "worst |x_Brent - x_bisection| (bisection from the same part, to tol/4)", k.worst, 0,
                     k.allowed);
    if (k.lost)
        mm_res_check_abs(res, "roots bisection could not confirm (no sign change of f across their part)", k.lost,
                         0, 0);
    mm_res_check_abs(res, "roots without a sign change of f between x - tol and x + tol", k.nosign, 0, 0);
    if (k.crowded)
        mm_res_warn(res, "%d part%s of width %.3g hold%s three or more roots (bisection found another one than "
                    "Brent's method): roots are missed there; raise n", k.crowded, k.crowded > 1 ? "s" : "",
                    (b - a) / n, k.crowded > 1 ? "" : "s");

    /* the plot: f over [a, b]; points where f is not finite are left out */
    int bad, plot_changes;
    double first_bad;
    if (mm_num_f_curve(res, O_F, c, a, b, PLOT, &bad, &first_bad, &plot_changes))
        return MM_ENOMEM;
    if (plot_changes > nr + rr.npoles)
        mm_res_warn(res, "the plot crosses or touches zero %d times, but the scan found %d root%s%s: roots closer "
                    "than a part (%.3g), roots that only touch zero, and roots beside points where f is not finite "
                    "are missed; raise n", plot_changes, nr, nr == 1 ? "" : "s", rr.npoles ? " and poles" : "",
                    (b - a) / n);

    mm_res_method(res, "subdivision into n parts, Brent's method in each bracket", 0);
    mm_res_method_stat(res, "evaluations", (double)scan_evals);
    mm_res_method_stat(res, "max_iterations", rr.max_iterations);
    mm_res_method_stat(res, "error_estimate", wmax);

    if (bad)
        mm_res_warn(res, "f is not finite at %d of the %d plot points (first at x = %.6g: a pole or a value "
                    "outside the domain, such as sqrt of a negative number); they are left out of the plot",
                    bad, PLOT, first_bad);
    if (rr.npoles) {
        char list[MM_NUM_LIST];
        mm_num_list(list, poles, rr.npoles < MAXPOLES ? rr.npoles : MAXPOLES);
        mm_res_warn(res, "%d sign change%s at a pole, not a root (|f| grows as the bracket shrinks): x = %s%s",
                    rr.npoles, rr.npoles > 1 ? "s are" : " is", list, rr.npoles > MAXPOLES ? ", ..." : "");
    }
    if (rr.nskipped)
        mm_res_warn(res, "%d part%s skipped because f is not finite there", rr.nskipped,
                    rr.nskipped > 1 ? "s were" : " was");
    if (nsuspect)
        mm_res_warn(res, "%d root%s a large residual |f(x)|: a jump of f through zero (or a very steep root) "
                    "rather than a smooth crossing; look at the plot", nsuspect, nsuspect > 1 ? "s have" : " has");
    if (nblur)
        mm_res_warn(res, "%d root%s known only to within %s err: f stays within its own rounding error over a band "
                    "wider than tol around %s (a multiple root, or a flat crossing); no method can place %s closer "
                    "in double precision", nblur, nblur > 1 ? "s are" : " is", nblur > 1 ? "their" : "its",
                    nblur > 1 ? "them" : "it", nblur > 1 ? "them" : "it");
    if (nr == 0)
        mm_res_warn(res, "no sign change of f on [%g, %g] with n = %d: f may have no root there, only roots "
                    "where it touches zero without crossing (such as x^2), or two roots within one part; "
                    "raise n or look at the plot", a, b, n);
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
    "R. P. Brent, Algorithms for Minimization without Derivatives, Prentice-Hall 1973, ch. 4",
    "G. E. Forsythe, M. A. Malcolm, C. B. Moler, Computer Methods for Mathematical Computations, "
    "Prentice-Hall 1977, section 7.2 (zeroin)",
    NULL,
};

const mm_exercise mm_ex_num_nonlinear_roots = {
    .id = "num-nonlinear-roots", .chapter = 1, .section = "1.4.2", .title = "Roots of a nonlinear function",
    .summary = "Every root of f(x) = 0 on an interval: subdivide, keep the sign changes, refine each by Brent's method.",
    .tags = "nonlinear equation, roots, bisection, Brent, sign change", .theory = "exercises/num/nonlinear_roots.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
