/* polyfit.c — num-polyfit: least-squares polynomial through data points,
 * MATLAB's polyfit(x, y, degree).
 *
 *     minimise  S(c) = sum_i (y_i - p(x_i))^2,   p(x) = c_0 x^d + ... + c_d     (1)
 *
 * Goal: the book's best straight line through (1,10), (3,18), (10,37),
 * y = 2.92537 x + 8.01493, and what "best" means: the residuals are
 * orthogonal to every power of x (the normal equations, eq. 3), so no
 * change of the coefficients can lower S.
 * Method: the data are centred and scaled, t = (x - mean) / spread, the
 * Vandermonde least-squares problem is solved by the SVD (LAPACK dgelsd)
 * and the coefficients are expanded back to powers of x (mm_poly_fit).
 * The fitted values, residuals, rms residual and plotted curve are
 * evaluated from the coefficients in t (the same least-squares problem,
 * solved again in t here), so they stay right when the terms c_k x^k
 * cancel; the coefficients shown are those in powers of x, as MATLAB's.
 * Checks, each on the scale of the data (max |y|): the coefficients of x^k
 * as shown reproduce the fitted values (fails when their terms cancel);
 * the normal equations A^T r = 0 with the residuals as shown; the fitted
 * values against a second solution by the normal equations themselves
 * (whose error grows with cond^2 instead of cond); for degree 0 and 1 the
 * closed-form mean and regression line.
 * Reference: G. Strang, Introduction to Linear Algebra, 5th ed., section
 * 4.3; A. Bjorck, Numerical Methods for Least Squares Problems, SIAM 1996.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>

#include "mm_exhelp.h"
#include "mm_linalg.h"
#include "mm_poly.h"

#define MAXPTS 200
#define MAXDEG 8

enum { P_X, P_Y, P_DEGREE };

static const mm_param params[] = {
    [P_X] = {"x", "abscissae x_i", "", MM_VECTOR, 0, -1e4, 1e4, "1,3,10", NULL, 0, MAXPTS,
             .help = "where the data were measured (at most 200 points)"},
    [P_Y] = {"y", "measured values y_i", "", MM_VECTOR, 0, -1e9, 1e9, "10,18,37", NULL, 0, MAXPTS,
             .help = "one value per x"},
    [P_DEGREE] = {"degree", "degree of the polynomial", "", MM_INT, 1, 0, MAXDEG,
                  .help = "1 is a straight line; must be below the number of distinct x values"},
};

static const char *const cname[MAXDEG + 1] = {"c0", "c1", "c2", "c3", "c4", "c5", "c6", "c7", "c8"};

static int distinct(int n, const double *x)
{
    int count = 0;
    for (int i = 0; i < n; i++) {
        int seen = 0;
        for (int j = 0; j < i && !seen; j++)
            seen = x[j] == x[i];
        count += !seen;
    }
    return count;
}

static int check(const mm_value *in, mm_error *err)
{
    int n = in[P_X].cols, d = (int)in[P_DEGREE].x;
    if (in[P_Y].cols != n)
        return mm_error_set(err, MM_ERANGE, "y", "y must have one value per x, %d; got %d", n, in[P_Y].cols);
    int nd = distinct(n, in[P_X].data);
    if (d >= nd)
        return mm_error_set(err, MM_ERANGE, "degree", "degree must be below the number of distinct x values "
                            "(%d): %d points fix at most a polynomial of degree %d; got %d", nd, nd, nd - 1, d);
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    const int n = in[P_X].cols, d = (int)in[P_DEGREE].x, m = d + 1;
    const double *x = in[P_X].data, *y = in[P_Y].data;
    double c[MAXDEG + 1], b[MAXDEG + 1];
    double *fit = mm_res_alloc(res, n * sizeof *fit), *r = mm_res_alloc(res, n * sizeof *r);
    double *t = mm_res_alloc(res, n * sizeof *t), *mag = mm_res_alloc(res, n * sizeof *mag);
    double *V = mm_res_alloc(res, (size_t)n * m * sizeof *V);
    if (!fit || !r || !t || !mag || !V)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");

    mm_poly_fit_info info;
    int rc = mm_poly_fit(n, x, y, d, c, &info, err);
    if (rc != MM_OK)
        return rc;

    for (int k = 0; k <= d; k++) {
        char label[40];
        if (k == d)
            snprintf(label, sizeof label, "constant term");
        else if (k == d - 1)
            snprintf(label, sizeof label, "coefficient of x");
        else
            snprintf(label, sizeof label, "coefficient of x^%d", d - k);
        const char *l = mm_res_strdup(res, label);
        if (!l)
            return mm_error_set(err, MM_ENOMEM, "", "out of memory");
        mm_res_scalar_v1(res, cname[k], l, "", c[k]);
    }

    /* the same fit in the centred, scaled t = (x - mean) / spread (mean and
     * spread as mm_poly_fit chose them): coefficients b_k of t^k by SVD least
     * squares on the Vandermonde matrix of t.  The fitted values, residuals
     * and the plotted curve are evaluated from b in t, where the terms are
     * of the size of the data and do not cancel: they are right even when
     * the coefficients of powers of x are useless for evaluating p(x). */
    const double mu = info.mu, sp = info.scale;
    for (int i = 0; i < n; i++) {
        t[i] = (x[i] - mu) / sp;
        double v = 1;
        for (int k = d; k >= 0; k--) {
            V[(size_t)i * m + k] = v;
            v *= t[i];
        }
    }
    rc = mm_linalg_lstsq(n, m, 1, V, y, 0.0, b, NULL, NULL, NULL, err);
    if (rc != MM_OK)
        return rc;

    /* residuals (eq. 2) from the fit in t; and, for the coefficients c as
     * shown, p(x_i) by Horner in x and the size of its terms sum |c_k||x|^k,
     * which rounding scales with */
    double ss = 0, ymax = 0, xlo = x[0], xhi = x[0], cdev = 0;
    for (int i = 0; i < n; i++) {
        fit[i] = mm_poly_eval(m, b, t[i], NULL);
        r[i] = y[i] - fit[i];
        ss += r[i] * r[i];
        cdev = fmax(cdev, fabs(mm_poly_eval(m, c, x[i], NULL) - fit[i]));
        double s = fabs(c[0]);
        for (int k = 1; k <= d; k++)
            s = s * fabs(x[i]) + fabs(c[k]);
        mag[i] = s;
        ymax = fmax(ymax, fabs(y[i]));
        xlo = fmin(xlo, x[i]);
        xhi = fmax(xhi, x[i]);
    }
    double rms = sqrt(ss / n), magmax = mm_maxabs(mag, n), fitmax = mm_maxabs(fit, n);
    mm_res_scalar_v1(res, "rms_residual", "rms residual sqrt(sum r_i^2 / n)", "", rms);
    mm_res_scalar_v1(res, "cond", "condition number of the scaled least-squares matrix", "", info.cond);

    /* check 0: the coefficients c_k of powers of x, as shown, reproduce the
     * fitted values: p(x_i) evaluated from them against the fit in t, on the
     * scale of the data.  Rounding makes them differ by about eps times the
     * terms c_k x^k; when those terms cancel (data far from x = 0 and a high
     * degree) the difference reaches the size of the data and this check
     * fails: the coefficients are then of no use for computing p(x).  Half
     * the digits (1e-8 of max |y|) is the bar, as for the warning below. */
    const double ctol = 1e-8;
    mm_res_check_abs(res, "p(x_i) from the coefficients c_k of x^k vs the fit in t = (x - mean) / spread: "
                     "max |difference| / max |y| (at least 8 of 16 digits)",
                     ymax > 0 ? cdev / ymax : cdev, 0, ctol);

    /* check 1: the normal equations (eq. 3), A^T r = 0, with the residuals
     * as shown, in the basis of powers of t (the same polynomials as powers
     * of x, but well scaled); each sum relative to the size of the data.  A
     * backward-stable least-squares solution gives fitted values within about
     * cond * eps of the exact projection (Bjorck 1996, ch. 1), hence cond */
    double worst = 0;
    for (int k = 0; k <= d; k++) {
        double s = 0, sa = 0;
        for (int i = 0; i < n; i++) {
            double tk = pow(t[i], k);
            s += tk * r[i];
            sa += fabs(tk) * ymax;
        }
        worst = fmax(worst, sa > 0 ? fabs(s) / sa : fabs(s));
    }
    mm_res_check_abs(res, "normal equations: worst |sum t_i^k r_i| / (max |y| sum |t_i|^k), eq. (3) (cond eps)",
                     worst, 0, 16.0 * (d + 2) * (d + 2) * fmax(1, info.cond) * DBL_EPSILON);

    /* check 2: a second solution, by the normal equations (A^T A) a = A^T y
     * in t (LU); their error grows like cond^2 eps (eq. 4), so compare the
     * fitted values as shown within that, on the scale of the data */
    double N[(MAXDEG + 1) * (MAXDEG + 1)] = {0}, rhs[MAXDEG + 1] = {0}, a[MAXDEG + 1];
    for (int i = 0; i < n; i++) {
        double pw[2 * MAXDEG + 1];
        pw[0] = 1;
        for (int k = 1; k <= 2 * d; k++)
            pw[k] = pw[k - 1] * t[i];
        for (int j = 0; j <= d; j++) {
            rhs[j] += pw[j] * y[i];
            for (int k = 0; k <= d; k++)
                N[j * m + k] += pw[j + k];
        }
    }
    mm_linalg_solve_info si;
    mm_error local;
    double tol2 = 64.0 * m * n * info.cond * info.cond * DBL_EPSILON;
    rc = mm_linalg_solve(m, 1, N, rhs, a, &si, &local);
    if (rc == MM_OK && tol2 < 1e-2) {
        double dmax = 0;
        for (int i = 0; i < n; i++) {
            double v = 0;                            /* sum a_k t^k, Horner */
            for (int k = d; k >= 0; k--)
                v = v * t[i] + a[k];
            dmax = fmax(dmax, fabs(v - fit[i]));
        }
        mm_res_check_abs(res, "fitted values: SVD vs normal equations, max |difference| / max |y| (cond^2 eps)",
                         ymax > 0 ? dmax / ymax : dmax, 0, tol2);
    } else {
        mm_res_warn(res, "the normal equations A^T A a = A^T y are too ill-conditioned here (cond^2 = %.2g) "
                    "to serve as a second solution: this is why polyfit works on A itself", info.cond * info.cond);
    }

    /* check 3: closed forms for the mean (degree 0) and the regression line */
    double ybar = 0, mean = 0;
    for (int i = 0; i < n; i++) {
        ybar += y[i];
        mean += x[i];
    }
    ybar /= n;
    mean /= n;
    if (d == 0) {
        mm_res_check_abs(res, "c0 = mean of y", c[0], ybar, 8.0 * n * DBL_EPSILON * ymax);
    } else if (d == 1) {
        double sxx = 0, sxy = 0, syy = 0;
        for (int i = 0; i < n; i++) {
            sxx += (x[i] - mean) * (x[i] - mean);
            sxy += (x[i] - mean) * (y[i] - ybar);
            syy += (y[i] - ybar) * (y[i] - ybar);
        }
        double slope = sxy / sxx, icpt = ybar - slope * mean;
        double sscale = sqrt(syy / sxx) + fabs(slope);       /* what the slope is made of */
        mm_res_check_abs(res, "c0 = S_xy / S_xx (regression line, eq. 5)", c[0], slope,
                         16.0 * n * DBL_EPSILON * sscale);
        mm_res_check_abs(res, "c1 = mean(y) - c0 mean(x) (eq. 5)", c[1], icpt,
                         16.0 * n * DBL_EPSILON * (ymax + sscale * fmax(fabs(xlo), fabs(xhi))));
    }

    /* plots: the data, the fitted curve a little beyond them (in t), the
     * residuals */
    mm_series *sd = mm_res_series_v1(res, "data", "data points", "", "x", "", n);
    enum { NP = 201 };
    mm_series *sf = mm_res_series_v1(res, "fit", "fitted polynomial", "", "x", "", NP);
    static const char *const cols[] = {"x", "y", "fit", "residual"};
    static const char *const units[] = {"", "", "", ""};
    mm_table *tb = mm_res_table_v1(res, "residuals", n, 4, cols, units);
    if (!sd || !sf || !tb)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (int i = 0; i < n; i++) {
        sd->x[i] = x[i];
        sd->y[i] = y[i];
        double *row = tb->cell + 4 * i;
        row[0] = x[i];
        row[1] = y[i];
        row[2] = fit[i];
        row[3] = r[i];
    }
    double margin = xhi > xlo ? 0.05 * (xhi - xlo) : 1;
    mm_linspace(xlo - margin, xhi + margin, NP, sf->x);
    for (int i = 0; i < NP; i++)
        sf->y[i] = mm_poly_eval(m, b, (sf->x[i] - mu) / sp, NULL);

    mm_res_method(res, "least squares by SVD on centred, scaled x (LAPACK dgelsd)", 0);
    mm_res_method_stat(res, "rank", info.rank);
    if (n == d + 1 || rms <= 64 * DBL_EPSILON * ymax)
        mm_res_warn(res, "the polynomial passes through every point (as many coefficients as distinct points, "
                    "or exact data): this is interpolation, and the residual says nothing about measurement "
                    "error");
    double cancel = magmax / fmax(fitmax, ymax);
    if (cancel * DBL_EPSILON > 1e-8)
        mm_res_warn(res, "the terms c_k x^k reach %.2g but p(x) is only about %.2g: they cancel, and %.0f of the "
                    "16 digits are lost whenever p(x) is computed from these coefficients (here they miss the "
                    "fitted values by up to %.2g); the fitted values, residuals and curve shown are computed in "
                    "t = (x - mean) / spread and are not affected. Shift x to sit around 0",
                    magmax, fmax(fitmax, ymax), fmin(16, log10(cancel)), cdev);
    if (info.rank < m)
        mm_res_warn(res, "the data fix only %d of the %d coefficients to working precision (numerical rank %d): "
                    "the fit of least norm is shown; lower the degree or spread x", info.rank, m, info.rank);
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
    .id = "num-polyfit",
    .chapter = 1,
    .section = "1.4.2",
    .title = "Least-squares polynomial fit",
    .summary = "The polynomial of a given degree closest to data points in the least-squares sense, like MATLAB's polyfit.",
    .tags = "least squares, regression, polynomial fit, normal equations",
    .theory = "exercises/num/polyfit.md",
    .params = params,
    .n_params = MM_COUNT(params),
    .references = references,
    .check = check,
    .solve = solve,
};
