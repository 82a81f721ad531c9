/* linear_system.c — num-linear-system: A x = b, MATLAB's x = A \ b.
 *
 *     A x = b,   A square n x n,  b of n numbers                     (1)
 *
 * Goal: solve the book's system (x = 993.33, -2006.7, 1010) and learn what
 * decides how many digits of x a double-precision solver keeps: not the
 * residual b - A x, which a good solver always makes tiny (backward
 * stability, eq. 4), but the condition number cond(A) = sigma_max /
 * sigma_min (eq. 5), which multiplies that tiny residual into the error of
 * x (eq. 6).
 * Method: MATLAB's A \ b is LU with partial pivoting (LAPACK dgesvx, with
 * equilibration and iterative refinement), in double precision.  The
 * numbers printed are the exact solution and singular values rounded to
 * double, each with its bound: computed in double-double (~32 digits,
 * mm_linalg_solve_dd / mm_linalg_svdvals_dd), with bounds from residuals
 * (eq. 7).  A \ b is shown beside them with its true error.
 * Checks: the printed x against the data (its residual within the rounding
 * of x to double); A \ b against the accurate x within the forward error
 * bound of eq. (7) of its own residual; A \ b's componentwise backward
 * error a few eps (eq. 4); LAPACK's singular values (MATLAB's svd) within
 * their normwise bound n eps sigma_max.
 * Reference: G. Strang, Introduction to Linear Algebra, 5th ed., ch. 2 and
 * 7.3; N. J. Higham, Accuracy and Stability of Numerical Algorithms, 2nd
 * ed., SIAM 2002, ch. 7 and 9.
 */
#include <float.h>
#include <math.h>

#include "mm_dd.h"
#include "mm_errbound.h"
#include "mm_exhelp.h"
#include "mm_linalg.h"
#include "mm_num.h"

#define MAXN 12
#define U (DBL_EPSILON / 2)                   /* unit roundoff */

enum { P_A, P_B };

static const mm_param params[] = {
    [P_A] = {"A", "coefficient matrix", "", MM_MATRIX, 0, -1e300, 1e300, "1,2,3;4,5,6;7,8,10", NULL, MAXN, MAXN,
             .help = "a square matrix, rows separated by ';' (MATLAB's [1,2,3;4,5,6;7,8,10]); at most 12 x 12, "
                     "the size a learner types (each extra row costs n^2 work in 32-digit arithmetic); entries "
                     "of any size a double holds (to 1e300): accuracy depends on cond(A), not on size"},
    [P_B] = {"b", "right-hand side", "", MM_VECTOR, 0, -1e300, 1e300, "10,0,1000", NULL, 0, MAXN,
             .help = "one number per row of A, of any size a double holds (to 1e300)"},
};

enum { O_X, O_COND, O_RESIDUAL, O_BERR, O_DIGITS, O_SOLUTION, O_SIGMAS, O_XS, O_SIGMA };

static const char *const sol_cols[] = {"i", "x", "x_err", "x_matlab", "matlab_error", NULL},
                         *const sol_units[] = {"", "", "", "", "", NULL};
static const char *const sv_cols[] = {"i", "sigma", "sigma_err", "sigma_matlab", NULL},
                         *const sv_units[] = {"", "", "", "", NULL};

static const mm_output outputs[] = {
    [O_X] = MM_SCALAR("x%d", "unknown x_%d", "", .flags = MM_ANSWER, .first = 1, .last = MAXN),
    [O_COND] = MM_SCALAR("cond", "condition number cond(A) = sigma_max / sigma_min (2-norm)", "", .flags = MM_ANSWER),
    [O_RESIDUAL] = MM_SCALAR("residual", "residual ||b - A x|| (2-norm): rounding-level for any backward-stable x",
                             ""),
    [O_BERR] = MM_SCALAR("backward_error", "relative residual ||b - A x|| / (||A|| ||x|| + ||b||)", ""),
    [O_DIGITS] = MM_SCALAR("digits", "digits a double-precision solve keeps, floor(-log10(cond(A) eps))", "",
                           .flags = MM_EXACT),
    [O_SOLUTION] = MM_TABLE("solution", "x to the last digit, and A\\b in double precision", sol_cols, sol_units),
    [O_SIGMAS] = MM_TABLE("singular_values", "singular values of A", sv_cols, sv_units),
    [O_XS] = MM_SERIES("x", "solution x_i", "", "i", "", .mark = "bars"),
    [O_SIGMA] = MM_SERIES("sigma", "singular values of A", "", "i", "", .mark = "dots", .y_scale = "log"),
};

static int check(const mm_value *in, mm_error *err)
{
    const mm_value *A = &in[P_A], *b = &in[P_B];
    if (A->rows != A->cols)
        return mm_error_set(err, MM_ERANGE, "A", "A must be square (as many equations as unknowns); "
                            "got %d rows and %d columns", A->rows, A->cols);
    if (b->cols != A->rows)
        return mm_error_set(err, MM_ERANGE, "b", "b must have one number per row of A, %d; got %d",
                            A->rows, b->cols);
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    const int n = in[P_A].rows;
    const double *A = in[P_A].data, *b = in[P_B].data;
    double *x = mm_res_alloc(res, 10 * n * sizeof *x);
    if (!x)
        return MM_ENOMEM;
    double *xe = x + n, *xl = xe + n, *s = xl + n, *se = s + n, *sl = se + n, *r = sl + n, *mag = r + n,
           *w = mag + n;                                    /* w: 2n of scratch */

    /* singular values (eq. 5) to the last digit, with bounds */
    int rc = mm_linalg_svdvals_dd(n, n, A, s, se, err);
    if (rc != MM_OK)
        return rc;
    double smin_lo = s[n - 1] - se[n - 1];
    if (!(smin_lo > 0) || !(s[0] > 0))
        return mm_error_set(err, MM_ESINGULAR, "A", s[0] == 0 ? "A is all zeros: A x = b has no unique solution"
                            : "A is singular (its smallest singular value is 0 to 32 digits, cond(A) > %.0e: a "
                              "row is a combination of the others), so A x = b has no solution or infinitely "
                              "many; change A", se[n - 1] > 0 ? s[0] / se[n - 1] : INFINITY);
    /* x to the last digit (eq. 7 bounds it) */
    double rdd;
    if ((rc = mm_linalg_solve_dd(n, A, b, smin_lo, x, xe, &rdd, err)) != MM_OK)
        return rc;
    for (int i = 0; i < n; i++)
        mm_num_scalar_i_err(res, O_X, i + 1, x[i], xe[i], MM_ERR_BOUND);

    /* cond = s_1 / s_n, its bound from those of s_1 and s_n (relative: as the
     * ends of an interval in double it came out as U cond alone, 1.4 U off at
     * the defaults, reference harness tests/ref/num_ref.py) */
    double cond = s[0] / s[n - 1];
    mm_res_scalar_err(res, O_COND, cond, mm_errbound_cond(s[0], se[0], s[n - 1], se[n - 1]), MM_ERR_BOUND);

    /* the residual of the printed x, in double-double (eq. 3-4).  Its value
     * is rounding-level: the exact solution has residual 0, and rounding it
     * to double, or any backward-stable solve in double (MATLAB's), leaves
     * up to about (2n + 2) u || |A| |x| + |b| ||, so that is its error */
    mm_linalg_residual_dd(n, A, x, b, r, mag);
    double rnorm = mm_linalg_norm2(n, r), xnorm = mm_linalg_norm2(n, x), bnorm = mm_linalg_norm2(n, b);
    double rerr = 4 * MM_DD_EPS * n * mm_linalg_norm2(n, mag) + U * rnorm;
    double rlevel = (2.0 * n + 2) * U * mm_linalg_norm2(n, mag);
    mm_res_scalar_err(res, O_RESIDUAL, rnorm, rerr + rlevel, MM_ERR_ESTIMATE);
    double scale = s[0] * xnorm + bnorm;                    /* ||A|| ||x|| + ||b|| */
    mm_res_scalar_err(res, O_BERR, rnorm / scale, (rerr + rlevel + rnorm * (se[0] / s[0] + 4 * U)) / scale,
                      MM_ERR_ESTIMATE);
    mm_res_scalar(res, O_DIGITS, fmin(16, fmax(0, floor(-log10(cond * DBL_EPSILON)))));

    /* MATLAB's A \ b: LU with partial pivoting in double (LAPACK dgesvx) */
    mm_linalg_solve_info info;
    rc = mm_linalg_solve(n, 1, A, b, xl, &info, err);
    int have_lu = rc == MM_OK;
    if (rc != MM_OK && rc != MM_ESINGULAR)
        return rc;
    double dmax = 0, xmax = mm_maxabs(x, n);
    mm_table *t = mm_res_table(res, O_SOLUTION, n);
    mm_table *ts = mm_res_table(res, O_SIGMAS, n);
    mm_series *sx = mm_res_series(res, O_XS, n), *ss = mm_res_series(res, O_SIGMA, n);
    if (!t || !ts || !sx || !ss)
        return MM_ENOMEM;
    rc = mm_linalg_svdvals(n, n, A, sl, err);              /* MATLAB's svd(A) */
    if (rc != MM_OK)
        return rc;
    for (int i = 0; i < n; i++) {
        double *row = t->cell + 5 * i, d = fabs(xl[i] - x[i]);
        row[0] = i + 1, row[1] = x[i], row[2] = xe[i], row[3] = xl[i], row[4] = d;
        if (!have_lu)
            t->text[5 * i + 3] = t->text[5 * i + 4] = "zero pivot";
        dmax = fmax(dmax, d);
        ts->cell[4 * i] = i + 1, ts->cell[4 * i + 1] = s[i], ts->cell[4 * i + 2] = se[i], ts->cell[4 * i + 3] = sl[i];
        sx->x[i] = ss->x[i] = i + 1;
        sx->y[i] = x[i];
        ss->y[i] = s[i];
    }

    if (have_lu) {
        /* check: the forward error of A \ b is at most ||A^-1|| ||b - A x_lu||
         * (eq. 7) with its residual computed in double-double; the accurate x
         * carries its own bound.  And its componentwise backward error, max
         * |r_i| / (|A| |x| + |b|)_i (eq. 4): LU with refinement leaves a few eps */
        double omega, bound = mm_errbound_solve(n, A, b, xl, smin_lo, &omega, w);
        for (int i = 0; i < n; i++)
            w[i] = xl[i] - x[i];
        mm_res_check_abs(res, "A\\b: ||x_matlab - x|| <= ||b - A x_matlab|| / sigma_min, eq. (7)", mm_linalg_norm2(n, w), 0,
                         1.01 * bound + mm_linalg_norm2(n, xe));
        mm_res_check_abs(res, "A\\b: componentwise backward error max |r_i| / (|A| |x| + |b|)_i <= 2 eps, eq. (4)",
                         omega, 0, 2 * DBL_EPSILON);
    }
    /* check: the printed x against the data: its residual is what rounding x
     * to double leaves, |r| <= |A| (u |x| + x_err) */
    mm_res_check_abs(res, "printed x: ||b - A x|| <= || |A| (u |x| + x_err) ||, the rounding of x to double", rnorm, 0,
                     1.01 * mm_errbound_rounded_residual(n, A, x, xe, w) + rerr);
    /* check: MATLAB's svd (LAPACK dgesdd, double) within its normwise bound
     * p(n) eps sigma_max (LAPACK Users' Guide 4.9; p(n) = 4n here: the
     * largest seen over 200 random 3 x 3 draws was 0.96 n) */
    double sdev = 0;
    for (int i = 0; i < n; i++)
        sdev = fmax(sdev, fabs(sl[i] - s[i]) - se[i]);
    mm_res_check_abs(res, "svd(A) in double (LAPACK dgesdd) vs the accurate sigma_i: worst |difference| <= "
                     "4 n eps sigma_max", fmax(sdev, 0), 0, 4 * n * DBL_EPSILON * s[0]);

    mm_res_method(res, "A\\b: LU with partial pivoting, equilibrated, iterative refinement (LAPACK dgesvx); "
                       "x and sigma to the last digit in double-double arithmetic", 0);
    if (!have_lu) {
        mm_res_warn(res, "A\\b in double precision meets an exact zero pivot and gives no answer; the x printed "
                         "comes from 32-digit arithmetic, where A is not singular (cond(A) = %.3g)", cond);
        return MM_OK;
    }
    mm_res_method_stat(res, "rcond", info.rcond);
    mm_res_method_stat(res, "error_estimate", info.ferr);
    if (cond * DBL_EPSILON > 1e-8)
        mm_res_warn(res, "A is nearly singular: cond(A) = %.3g, so A\\b in double precision can lose about %.0f of "
                    "its 16 digits although its residual is tiny (here it is off by %.2g relative); the x printed is "
                    "computed in 32-digit arithmetic and right to the digits shown", cond,
                    fmin(16, ceil(log10(cond))), dmax / xmax);
    return MM_OK;
}

static const char *const references[] = {
    "G. Strang, Introduction to Linear Algebra, 5th ed., Wellesley-Cambridge 2016, ch. 2 and 7.3",
    "N. J. Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed., SIAM 2002, ch. 7 and 9",
    "E. Anderson et al., LAPACK Users' Guide, 3rd ed., SIAM 1999 (dgesvx, dgesdd)",
    NULL,
};

const mm_exercise mm_ex_num_linear_system = {
    .id = "num-linear-system", .chapter = 1, .section = "1.4.2", .title = "A linear system A x = b",
    .summary = "Solve A x = b like MATLAB's A\\b; the condition number tells how many digits of x a double-precision "
               "solve keeps.",
    .tags = "linear algebra, linear system, LU, condition number, residual", .theory = "exercises/num/linear_system.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
