/* linear_system.c — num-linear-system: A x = b, MATLAB's x = A \ b.
 *
 *     A x = b,   A square n x n,  b of n numbers                     (1)
 *
 * Goal: solve the book's system (x = 993.33, -2006.7, 1010) and learn what
 * decides how many digits of x can be trusted: not the residual b - A x,
 * which a good solver always makes tiny (backward stability, eq. 4), but
 * the condition number cond(A) = sigma_max / sigma_min (eq. 5), which
 * multiplies that tiny residual into the error of x (eq. 6).
 * Method: LU with partial pivoting after equilibration, then iterative
 * refinement, repeated while it still helps, at most five steps (LAPACK
 * dgesvx).  Checks: the residual computed in compensated
 * (twice-the-precision) arithmetic against the backward stability bound,
 * and a second solution by the singular value decomposition (LAPACK
 * dgelsd), which must agree within cond(A) * eps.
 * Reference: G. Strang, Introduction to Linear Algebra, 5th ed., ch. 2 and
 * 7.3; N. J. Higham, Accuracy and Stability of Numerical Algorithms, 2nd
 * ed., SIAM 2002, ch. 7 and 9.
 */
#include <float.h>
#include <math.h>

#include "mm_exhelp.h"
#include "mm_linalg.h"

#define MAXN 12

enum { P_A, P_B };

static const mm_param params[] = {
    [P_A] = {"A", "coefficient matrix", "", MM_MATRIX, 0, -1e6, 1e6, "1,2,3;4,5,6;7,8,10", NULL, MAXN, MAXN,
             .help = "a square matrix, rows separated by ';' (MATLAB's MAT = [1,2,3;4,5,6;7,8,10])"},
    [P_B] = {"b", "right-hand side", "", MM_VECTOR, 0, -1e6, 1e6, "10,0,1000", NULL, 0, MAXN,
             .help = "one number per row of A"},
};

static const char *const xname[MAXN] = {"x1", "x2", "x3", "x4", "x5", "x6",
                                        "x7", "x8", "x9", "x10", "x11", "x12"};
static const char *const xlabel[MAXN] = {
    "unknown 1", "unknown 2", "unknown 3", "unknown 4", "unknown 5", "unknown 6",
    "unknown 7", "unknown 8", "unknown 9", "unknown 10", "unknown 11", "unknown 12"};

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

/* (a, b) -> s + e exactly (Knuth's TwoSum). */
static void two_sum(double a, double b, double *s, double *e)
{
    *s = a + b;
    double bb = *s - a;
    *e = (a - (*s - bb)) + (b - bb);
}

/* r = A x - b, each component by a compensated dot product (Ogita, Rump &
 * Oishi's Dot2): as accurate as if computed in twice the precision, so the
 * residual shown is the true residual of the stored x, not rounding noise. */
static void residual(int n, const double *A, const double *x, const double *b, double *r)
{
    for (int i = 0; i < n; i++) {
        double s = -b[i], c = 0;
        for (int j = 0; j < n; j++) {
            double p = A[i * n + j] * x[j], pe = fma(A[i * n + j], x[j], -p), q;
            two_sum(s, p, &s, &q);
            c += q + pe;
        }
        r[i] = s + c;
    }
}

static double norm2(int n, const double *v)
{
    double s = 0, big = 0;
    for (int i = 0; i < n; i++)
        big = fmax(big, fabs(v[i]));
    if (big == 0)
        return 0;
    for (int i = 0; i < n; i++)
        s += (v[i] / big) * (v[i] / big);
    return big * sqrt(s);
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    const int n = in[P_A].rows;
    const double *A = in[P_A].data, *b = in[P_B].data;
    double *x = mm_res_alloc(res, n * sizeof *x), *x2 = mm_res_alloc(res, n * sizeof *x2);
    double *r = mm_res_alloc(res, n * sizeof *r), *sv = mm_res_alloc(res, n * sizeof *sv);
    if (!x || !x2 || !r || !sv)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");

    /* singular values first: cond(A) = s_1 / s_n (eq. 5) */
    int rc = mm_linalg_svdvals(n, n, A, sv, err);
    if (rc != MM_OK)
        return rc;
    double cond = sv[n - 1] > 0 ? sv[0] / sv[n - 1] : INFINITY;

    mm_linalg_solve_info info;
    rc = mm_linalg_solve(n, 1, A, b, x, &info, err);
    if (rc == MM_ESINGULAR || (rc == MM_OK && !isfinite(cond))) {
        if (sv[0] == 0)
            return mm_error_set(err, MM_ESINGULAR, "A", "A is all zeros: A x = b has no unique solution");
        return mm_error_set(err, MM_ESINGULAR, "A",
                            "A is singular (cond(A) = %.3g: a row is, to the last digit, a combination of "
                            "the others), so A x = b has no solution or infinitely many; change A",
                            cond);
    }
    if (rc != MM_OK)
        return rc;

    for (int i = 0; i < n; i++)
        mm_res_scalar_v1(res, xname[i], xlabel[i], "", x[i]);
    mm_res_scalar_v1(res, "cond", "condition number cond(A) (2-norm)", "", cond);

    residual(n, A, x, b, r);
    double rnorm = norm2(n, r), xnorm = norm2(n, x), bnorm = norm2(n, b);
    double scale = sv[0] * xnorm + bnorm;                  /* ||A|| ||x|| + ||b|| */
    double berr = scale > 0 ? rnorm / scale : 0;
    mm_res_scalar_v1(res, "residual", "residual ||b - A x|| (2-norm)", "", rnorm);
    mm_res_scalar_v1(res, "backward_error", "relative residual ||b - A x|| / (||A|| ||x|| + ||b||)", "", berr);
    mm_res_scalar_v1(res, "digits", "digits of x to trust, about 16 - log10(cond)", "",
                  fmax(0, floor(-log10(cond * DBL_EPSILON))));

    /* check 1: backward stability (eq. 4).  LU with partial pivoting and
     * refinement leaves a residual of a few eps relative to the data, for
     * any cond.  The residual itself is computed to ~eps^2, so the bound
     * is the solver's, not our rounding. */
    mm_res_check_abs(res, "relative residual ||b - A x|| / (||A|| ||x|| + ||b||) <= 8 n eps", berr, 0,
                     8.0 * n * DBL_EPSILON);

    /* check 2: a second method with other error behaviour, the SVD (least
     * squares with no singular value cut off).  Both are backward stable, so
     * each is within about cond * n * eps of the exact x (eq. 6): they must
     * agree to twice that. */
    rc = mm_linalg_lstsq(n, n, 1, A, b, 1e-300, x2, NULL, NULL, NULL, err);
    if (rc != MM_OK)
        return rc;
    double d = 0, x2max = 0;
    for (int i = 0; i < n; i++) {
        d = fmax(d, fabs(x[i] - x2[i]));
        x2max = fmax(x2max, fabs(x2[i]));
    }
    double tol = 16.0 * n * cond * DBL_EPSILON;
    mm_res_check_abs(res, "x by LU vs x by SVD: max |difference| / max |x| <= 16 n cond eps",
                     x2max > 0 ? d / x2max : d, 0, tol);

    mm_series *sx = mm_res_series_v1(res, "x", "solution x_i", "", "i", "", n);
    mm_series *ss = mm_res_series_v1(res, "sigma", "singular values of A", "", "i", "", n);
    if (!sx || !ss)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (int i = 0; i < n; i++) {
        sx->x[i] = ss->x[i] = i + 1;
        sx->y[i] = x[i];
        ss->y[i] = sv[i];
    }

    mm_res_method(res, "LU with partial pivoting, equilibrated, iterative refinement (LAPACK dgesvx)", 0);
    mm_res_method_stat(res, "rcond", info.rcond);
    mm_res_method_stat(res, "error_estimate", info.ferr);

    if (cond * DBL_EPSILON > 1e-8)
        mm_res_warn(res, "A is nearly singular: cond(A) = %.3g, so about %.0f of the 16 digits of x may be "
                    "wrong although the residual is tiny (a change of b in the 16th digit moves x that much)",
                    cond, fmin(16, ceil(log10(cond))));
    return MM_OK;
}

static const char *const references[] = {
    "G. Strang, Introduction to Linear Algebra, 5th ed., Wellesley-Cambridge 2016, ch. 2 and 7.3",
    "N. J. Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed., SIAM 2002, ch. 7 and 9",
    "E. Anderson et al., LAPACK Users' Guide, 3rd ed., SIAM 1999 (dgesvx, dgelsd)",
    NULL,
};

const mm_exercise mm_ex_num_linear_system = {
    .id = "num-linear-system",
    .chapter = 1,
    .section = "1.4.2",
    .title = "A linear system A x = b",
    .summary = "Solve A x = b like MATLAB's A\\b; the condition number tells how many digits of x to trust.",
    .tags = "linear algebra, linear system, LU, condition number, residual",
    .theory = "exercises/num/linear_system.md",
    .params = params,
    .n_params = MM_COUNT(params),
    .references = references,
    .check = check,
    .solve = solve,
};
