/* polyfit.c — num-polyfit: least-squares polynomial through data points,
 * MATLAB's polyfit(x, y, degree).
 *
 *     minimise  S(c) = sum_i (y_i - p(x_i))^2,   p(x) = c_0 x^d + ... + c_d     (1)
 *
 * Goal: the book's best straight line through (1,10), (3,18), (10,37),
 * y = 2.92537 x + 8.01493, and what "best" means: the residuals are
 * orthogonal to every power of x (the normal equations, eq. 3), so no
 * change of the coefficients can lower S.
 * Method: MATLAB's route in double (mm_poly_fit: centre and scale x, SVD
 * least squares, expand back to powers of x) is shown beside the numbers
 * printed, which are the exact least-squares solution rounded to double,
 * each with its bound: the same problem by Householder QR in double-double
 * (mm_poly_fit_dd).  A coefficient smaller than its own bound has no digit
 * determined (the powers of x cancel); one smaller than its standard error
 * (from the scatter of the data) is not distinguishable from 0.
 * Checks: the normal equations with the residuals as printed (eq. 3); the
 * coefficients as printed reproduce the fit to within the rounding of
 * p(x) in double; the fitted values by the SVD and by the normal equations
 * in double, each within its forward error bound (eq. 4); for degree 0 and
 * 1 the closed forms (eq. 5).
 * Reference: G. Strang, Introduction to Linear Algebra, 5th ed., section
 * 4.3; A. Bjorck, Numerical Methods for Least Squares Problems, SIAM 1996.
 */
#include <float.h>
#include <math.h>

#include "mm_exhelp.h"
#include "mm_num.h"
#include "mm_polycheck.h"

#define MAXPTS 200
#define MAXDEG 8
#define U (DBL_EPSILON / 2)

enum { P_X, P_Y, P_DEGREE };

static const mm_param params[] = {
    [P_X] = {"x", "abscissae x_i", "", MM_VECTOR, 0, -1e6, 1e6, "1,3,10", NULL, 0, MAXPTS,
             .help = "where the data were measured: at most 200 points (a table to type or paste), |x| <= 1e6 "
                     "so that x^8 stays far inside the doubles"},
    [P_Y] = {"y", "measured values y_i", "", MM_VECTOR, 0, -1e100, 1e100, "10,18,37", NULL, 0, MAXPTS,
             .help = "one value per x, of any size to 1e100"},
    [P_DEGREE] = {"degree", "degree of the polynomial", "", MM_INT, 1, 0, MAXDEG,
                  .help = "1 is a straight line; must be below the number of distinct x values; at most 8 (a "
                          "fit of higher degree swings wildly between the points)"},
};

enum { O_C, O_RMS, O_COND, O_COEFS, O_RESID, O_DATA, O_FIT };

static const char *const coef_cols[] = {"power", "c", "c_err", "std_error", "c_matlab", NULL},
                         *const coef_units[] = {"", "", "", "", "", NULL};
static const char *const res_cols[] = {"x", "y", "fit", "residual", "err", NULL},
                         *const res_units[] = {"", "", "", "", "", NULL};

static const mm_output outputs[] = {
    [O_C] = MM_SCALAR("c%d", "coefficient c%d (c0 of the highest power, as MATLAB's polyfit)", "",
                      .flags = MM_ANSWER, .first = 0, .last = MAXDEG),
    [O_RMS] = MM_SCALAR("rms_residual", "rms residual sqrt(sum r_i^2 / n)", "", .flags = MM_ANSWER),
    [O_COND] = MM_SCALAR("cond", "condition number of the least-squares matrix in t = (x - mean) / spread", ""),
    [O_COEFS] = MM_TABLE("coefficients", "coefficients: exact to the digits shown, their standard error from the "
                         "data's scatter, and MATLAB's polyfit in double", coef_cols, coef_units),
    [O_RESID] = MM_TABLE("residuals", "fitted values and residuals, each within err", res_cols, res_units),
    [O_DATA] = MM_SERIES("data", "data points", "", "x", "", .figure = "fit", .mark = "dots"),
    [O_FIT] = MM_SERIES("fit", "fitted polynomial", "", "x", "", .figure = "fit"),
};

static int check(const mm_value *in, mm_error *err)
{
    int n = in[P_X].cols, d = (int)in[P_DEGREE].x;
    if (in[P_Y].cols != n)
        return mm_error_set(err, MM_ERANGE, "y", "y must have one value per x, %d; got %d", n, in[P_Y].cols);
    int nd = mm_poly_distinct(n, in[P_X].data);
    if (d >= nd)
        return mm_error_set(err, MM_ERANGE, "degree", "degree must be below the number of distinct x values "
                            "(%d): %d points fix at most a polynomial of degree %d; got %d", nd, nd, nd - 1, d);
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    const int n = in[P_X].cols, d = (int)in[P_DEGREE].x, m = d + 1;
    const double *x = in[P_X].data, *y = in[P_Y].data;
    double c[MAXDEG + 1], ce[MAXDEG + 1], se[MAXDEG + 1], bt[MAXDEG + 1], cm[MAXDEG + 1];
    double *fit = mm_res_alloc(res, 5 * (size_t)n * sizeof *fit);
    if (!fit)
        return MM_ENOMEM;
    double *fe = fit + n, *r = fe + n, *w = r + n;                      /* w: 2n of scratch */

    mm_poly_fit_dd_info info;
    int rc = mm_poly_fit_dd(n, x, y, d, c, ce, fit, fe, se, bt, &info, err);
    if (rc != MM_OK)
        return rc;
    mm_poly_fit_info mi;                                   /* MATLAB's polyfit in double */
    if ((rc = mm_poly_fit(n, x, y, d, cm, &mi, err)) != MM_OK)
        return rc;

    mm_table *tc = mm_res_table(res, O_COEFS, m);
    mm_table *tr = mm_res_table(res, O_RESID, n);
    if (!tc || !tr)
        return MM_ENOMEM;
    int noise = 0, insignificant = 0;
    for (int k = 0; k <= d; k++) {
        mm_scalar *s = mm_num_scalar_i_err(res, O_C, k, c[k], ce[k], MM_ERR_BOUND);
        if (!(fabs(c[k]) > ce[k])) {
            s->text = "below its own error: no digit determined";
            noise++;
        } else if (info.dof > 0 && fabs(c[k]) < se[k]) {
            s->text = "below its standard error: not distinguishable from 0 by these data";
            insignificant++;
        }
        double *row = tc->cell + 5 * k;
        row[0] = d - k, row[1] = c[k], row[2] = ce[k], row[3] = se[k], row[4] = cm[k];
        if (info.dof == 0)
            tc->text[5 * k + 3] = "no data left over";
    }
    /* the rms of the exact fit, to its bound; when the data are fitted
     * exactly (interpolation) it is 0 to rounding, and a fit in double
     * (MATLAB's, evaluated by polyval in powers of x) leaves residuals of
     * about (2d + 2) u sum |c_k| |x|^k + (n + d) u max |y|: that is its
     * error then */
    double ylevel = mm_poly_fit_level(n, x, y, m, c);
    if (info.rms <= ylevel)
        mm_res_scalar_err(res, O_RMS, info.rms, info.rms_err + ylevel, MM_ERR_ESTIMATE);
    else
        mm_res_scalar_err(res, O_RMS, info.rms, info.rms_err, MM_ERR_BOUND);
    mm_res_scalar_err(res, O_COND, info.cond, info.cond_err, MM_ERR_BOUND);

    double ymax = mm_maxabs(y, n);
    for (int i = 0; i < n; i++) {
        r[i] = y[i] - fit[i];
        double *row = tr->cell + 5 * i;
        row[0] = x[i], row[1] = y[i], row[2] = fit[i], row[3] = r[i], row[4] = fe[i] + U * fabs(r[i]);
    }

    /* check: the printed c reproduce the fitted values within the rounding
     * of p(x) computed from them by Horner's rule (when the terms c_k x^k
     * cancel, that rounding is large: the warning below says so) */
    double ctol, magmax, cdev = mm_poly_horner_deviation(n, x, m, c, ce, fit, fe, &ctol, &magmax);
    mm_res_check_abs(res, "p(x_i) from the coefficients c_k of x^k vs the fitted values: worst |difference| / (the "
                     "rounding of Horner's rule with these c_k) <= 1", cdev, 0, 1);

    /* check: the normal equations (eq. 3) with the residuals as printed, in
     * the exact basis t = (x - mu) / scale: sum t_i^k r_i = 0 within what the
     * rounding of the residuals leaves */
    mm_res_check_abs(res, "normal equations, eq. (3): worst |sum t_i^k r_i| / (the rounding of the printed r_i) <= 1",
                     mm_poly_normal_residual(n, x, r, fe, m, info.mu, info.scale), 0, 1);

    /* check: two solutions in double, by the SVD (MATLAB's route, in t) and
     * by the normal equations (A^T A) a = A^T y (LU), each within its forward
     * error bound from the exact fit (eq. 4): kappa eps and kappa^2 eps */
    mm_poly_fit_routes two;
    if (mm_poly_fit_two_routes(n, x, y, d, mi.mu, mi.scale, mi.cond, info.rms, fit, fe, w, &two, NULL) == MM_OK) {
        if (two.bound_ne < 1e-2 * ymax) {
            mm_res_check_abs(res, "fitted values: SVD vs normal equations, both in double: worst |error| / (its "
                             "bound, kappa eps and kappa^2 eps), eq. (4), <= 1",
                             fmax(two.dev_svd / two.bound_svd, two.dev_ne / two.bound_ne), 0, 1);
            mm_res_method_stat(res, "svd_fit_error", two.dev_svd);
            mm_res_method_stat(res, "normal_equations_fit_error", two.dev_ne);
        } else {
            mm_res_warn(res, "the normal equations A^T A a = A^T y are too ill-conditioned here (cond^2 = %.2g) "
                        "to serve as a second solution: this is why polyfit works on A itself", mi.cond * mi.cond);
        }
    }

    /* check: closed forms for the mean (degree 0) and the regression line
     * (eq. 5), in double, each within the rounding of its own sums */
    mm_poly_line line;
    mm_poly_line_fit(n, x, y, &line);
    if (d == 0) {
        mm_res_check_abs(res, "c0 = mean of y", c[0], line.mean_y, line.mean_y_err + ce[0]);
    } else if (d == 1) {
        mm_res_check_abs(res, "c0 = S_xy / S_xx (regression line, eq. 5), within its rounding", c[0], line.slope,
                         1.01 * line.slope_err + ce[0]);
        mm_res_check_abs(res, "c1 = mean(y) - c0 mean(x) (eq. 5), within its rounding", c[1], line.intercept,
                         1.01 * line.intercept_err + ce[1]);
    }

    /* plots: the data, and the fitted curve a little beyond them, from the
     * coefficients in t (no cancellation) */
    if (mm_num_fit_plot(res, O_DATA, O_FIT, n, x, y, m, bt, info.mu, info.scale))
        return MM_ENOMEM;

    mm_res_method(res, "polyfit: least squares by SVD on centred, scaled x (LAPACK dgelsd) in double; the numbers "
                       "printed by Householder QR in double-double", 0);
    mm_res_method_stat(res, "rank", mi.rank);
    if (n == m || info.rms <= 64 * DBL_EPSILON * ymax)
        mm_res_warn(res, "the polynomial passes through every point (as many coefficients as distinct points, "
                    "or exact data): this is interpolation, and the residual says nothing about measurement "
                    "error");
    double fitmax = mm_maxabs(fit, n), cancel = magmax / fmax(fitmax, ymax);
    if (cancel * DBL_EPSILON > 1e-8)
        mm_res_warn(res, "the terms c_k x^k reach %.2g but p(x) is only about %.2g: they cancel, and %.0f of the "
                    "16 digits are lost whenever p(x) is computed from these coefficients (up to %.2g here); the "
                    "fitted values, residuals and curve shown are computed in t = (x - mean) / spread and are not "
                    "affected. Shift x to sit around 0", magmax, fmax(fitmax, ymax), fmin(16, log10(cancel)), ctol);
    if (noise)
        mm_res_warn(res, "%d coefficient%s smaller than %s own error bound (see c_err): no digit of %s is "
                    "determined, because the powers of x cancel; shift x to sit around 0", noise,
                    noise > 1 ? "s are" : " is", noise > 1 ? "their" : "its", noise > 1 ? "them" : "it");
    if (insignificant)
        mm_res_warn(res, "%d coefficient%s smaller than %s standard error (std_error, from the scatter of the data "
                    "about the fit): these data cannot tell %s from 0; a lower degree may fit as well",
                    insignificant, insignificant > 1 ? "s are" : " is", insignificant > 1 ? "their" : "its",
                    insignificant > 1 ? "them" : "it");
    if (mi.rank < m)
        mm_res_warn(res, "in double precision the data fix only %d of the %d coefficients (numerical rank %d): "
                    "MATLAB's polyfit returns the fit of least norm (c_matlab); lower the degree or spread x", mi.rank,
                    m, mi.rank);
    if (info.cond * DBL_EPSILON > 1e-8)
        mm_res_warn(res, "the fit is ill-conditioned (cond = %.2g): the coefficients are sensitive to the "
                    "last digits of the data; lower the degree", info.cond);
    return MM_OK;
}

static const char *const references[] = {
    "G. Strang, Introduction to Linear Algebra, 5th ed., Wellesley-Cambridge 2016, section 4.3",
    "A. Bjorck, Numerical Methods for Least Squares Problems, SIAM 1996, ch. 1-2",
    NULL,
};

const mm_exercise mm_ex_num_polyfit = {
    .id = "num-polyfit", .chapter = 1, .section = "1.4.2", .title = "Least-squares polynomial fit",
    .summary = "The polynomial of a given degree closest to data points in the least-squares sense, like MATLAB's polyfit.",
    .tags = "least squares, regression, polynomial fit, normal equations", .theory = "exercises/num/polyfit.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
