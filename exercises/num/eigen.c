/* eigen.c — num-eigen: the generalized symmetric eigenproblem K v = lambda M v,
 * MATLAB's [V, D] = eig(K, M).
 *
 *     K v = lambda M v,   lambda = omega^2                            (1)-(2)
 *
 * Goal: the free vibration of a chain of masses and springs, x = v cos(omega t),
 * turns into eq. (1): each eigenvalue lambda is the square of a natural
 * frequency, each eigenvector v the shape in which the whole system can
 * swing at that frequency.  The default is three 1 kg masses on three
 * 100 N/m springs hanging from a wall.
 * Method: MATLAB's eig(K, M) is a Cholesky reduction M = L L^T to the
 * symmetric L^-1 K L^-T, in double precision (LAPACK dsygvd); its error
 * grows with cond(M) and with ||K|| / |lambda| (eq. 6).  The numbers
 * printed are the exact eigenvalues rounded to double, each with a bound
 * from its residual (eq. 7): the same reduction and Jacobi rotations in
 * double-double arithmetic (mm_linalg_sygv_dd).
 * Checks: eig in double within its bound, eq. (6); the printed modes in
 * eq. (1) and M-orthonormal (eq. 4) to the rounding of their digits;
 * trace(M^-1 K) = sum of the lambdas (eq. 5), M^-1 K by an LU solve.
 * A negative lambda (K indefinite: a buckled or inverted structure) has no
 * real omega; the table says so in words.
 * Reference: S. S. Rao, Mechanical Vibrations, 6th ed., ch. 6; G. H. Golub,
 * C. F. Van Loan, Matrix Computations, 4th ed., sections 8.1 and 8.7.
 */
#include <float.h>
#include <math.h>

#include "mm_errbound.h"
#include "mm_exhelp.h"
#include "mm_linalg.h"

#define MAXN 12
#define U (DBL_EPSILON / 2)

enum { P_K, P_M };

static const mm_param params[] = {
    [P_K] = {"K", "stiffness matrix", "N/m", MM_MATRIX, 0, -1e100, 1e100, "200,-100,0;-100,200,-100;0,-100,100",
             NULL, MAXN, MAXN, .help = "symmetric; the default is a chain wall-k-m-k-m-k-m, k = 100 N/m; at most "
             "12 x 12 (each row costs n^2 work in 32-digit arithmetic), entries of any size to 1e100"},
    [P_M] = {"M", "mass matrix", "kg", MM_MATRIX, 0, -1e100, 1e100, "1,0,0;0,1,0;0,0,1", NULL, MAXN, MAXN,
             .help = "symmetric positive definite, as large as K; diagonal for point masses; entries of any size "
                     "to 1e100 (the squares the bounds need stay inside the doubles)"},
};

enum { O_EIGEN, O_MODES, O_SHAPE, O_LMIN, O_LMAX, O_UNSTABLE, O_CONDM };

static const char *const eig_cols[] = {"lambda", "omega", "f", "lambda_err", "omega_err", "f_err", "lambda_matlab",
                                       NULL};
static const char *const eig_units[] = {"1/s^2", "rad/s", "Hz", "1/s^2", "rad/s", "Hz", "1/s^2", NULL};
static const char *const mode_cols[] = {"mode", "dof", "phi", NULL}, *const mode_units[] = {"", "", "", NULL};

static const mm_output outputs[] = {
    [O_EIGEN] = MM_TABLE("eigen", "eigenvalues lambda = omega^2, natural frequencies, and eig in double", eig_cols,
                         eig_units),
    [O_MODES] = MM_TABLE("modes", "mode shapes: MATLAB's V, column by column", mode_cols, mode_units),
    [O_SHAPE] = MM_SERIES("mode%d", "mode shape %d", "", "degree of freedom", "", .first = 1, .last = MAXN,
                          .figure = "modes", .mark = "line"),
    [O_LMIN] = MM_SCALAR("lambda_min", "smallest eigenvalue", "1/s^2", .flags = MM_ANSWER),
    [O_LMAX] = MM_SCALAR("lambda_max", "largest eigenvalue", "1/s^2", .flags = MM_ANSWER),
    [O_UNSTABLE] = MM_SCALAR("unstable_modes", "modes with lambda < 0 (beyond its bound)", "", .flags = MM_EXACT),
    [O_CONDM] = MM_SCALAR("cond_M", "condition number of M (2-norm)", ""),
};

static int check(const mm_value *in, mm_error *err)
{
    const mm_value *K = &in[P_K], *M = &in[P_M];
    if (K->rows != K->cols)
        return mm_error_set(err, MM_ERANGE, "K", "K must be square; got %d rows and %d columns", K->rows,
                            K->cols);
    if (M->rows != K->rows || M->cols != K->cols)
        return mm_error_set(err, MM_ERANGE, "M", "M must be %d x %d like K; got %d x %d", K->rows, K->cols,
                            M->rows, M->cols);
    int i, j;
    for (int k = 0; k < 2; k++) {
        const mm_value *v = k ? M : K;
        const char *name = k ? "M" : "K";
        if (!mm_linalg_is_symmetric(v->rows, v->data, &i, &j))
            return mm_error_set(err, MM_EVALUE, name, "%s must be symmetric, but %s(%d,%d) = %g and %s(%d,%d) = %g",
                                name, name, i + 1, j + 1, v->data[i * v->rows + j], name, j + 1, i + 1,
                                v->data[j * v->rows + i]);
    }
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    const int n = in[P_K].rows;
    const double *K = in[P_K].data, *M = in[P_M].data;
    double *lam = mm_res_alloc(res, (size_t)(2 * n * n + 5 * n) * sizeof *lam);
    if (!lam)
        return MM_ENOMEM;
    double *le = lam + n, *V = le + n, *ll = V + n * n, *MK = ll + n, *w = MK + n * n;      /* w: 2n of scratch */

    /* the eigenvalues to the last digit, with bounds (eq. 7) */
    int rc = mm_linalg_sygv_dd(n, K, M, lam, le, V, err);
    if (rc == MM_ESINGULAR)
        return mm_error_set(err, MM_ESINGULAR, "M", "M is not positive definite: some motion would have zero "
                            "or negative kinetic energy 1/2 v^T M v; every mass must be positive");
    if (rc != MM_OK)
        return rc;
    /* ||M||, ||M^-1|| = 1 / mu_min, ||K|| from their own eigenvalues */
    mm_errbound_sym bm, bk;
    if ((rc = mm_errbound_sym_extremes(n, M, w, &bm, err)) || (rc = mm_errbound_sym_extremes(n, K, w, &bk, err)))
        return rc;
    double mnorm = bm.norm_hi, mmin = bm.min_lo, knorm = bk.norm_hi;
    double condM = bm.max / bm.min;                /* M is positive definite: mu_max / mu_min */
    mm_res_scalar_err(res, O_CONDM, condM, mmin > 0 ? mnorm / mmin - condM + 2 * U * condM : condM, MM_ERR_BOUND);

    /* MATLAB's eig(K, M): LAPACK dsygvd in double */
    rc = mm_linalg_sygv(n, K, M, ll, NULL, err);
    if (rc != MM_OK)
        return rc;

    mm_table *t = mm_res_table(res, O_EIGEN, n), *tm = mm_res_table(res, O_MODES, n * n);
    if (!t || !tm)
        return MM_ENOMEM;
    int unstable = 0, rigid = 0;
    double worst = 0, worst_ratio = 0, lscale = fmax(fabs(lam[0]), fabs(lam[n - 1]));
    for (int j = 0; j < n; j++) {
        double *row = t->cell + 7 * j;
        row[0] = lam[j];
        row[3] = le[j];
        row[6] = ll[j];
        if (lam[j] + le[j] < 0) {                       /* eq. (2) has no real omega */
            unstable++;
            t->text[7 * j + 1] = t->text[7 * j + 2] = t->text[7 * j + 4] = t->text[7 * j + 5] =
                "imaginary (lambda < 0: unstable)";
        } else {
            double oe, om = mm_errbound_sqrt(lam[j], le[j], &oe);
            if (lam[j] - le[j] <= 0)
                rigid++;
            row[1] = om, row[4] = oe;
            row[2] = om / (2 * M_PI), row[5] = oe / (2 * M_PI) + 2 * U * row[2];
        }
        /* eq. (6): eig in double is exact for K + dK, M + dM with |dK| ~ eps ||K||,
         * |dM| ~ eps ||M||, so off by up to ~ eps ||M^-1|| (||K|| + |lambda| ||M||) */
        double d = fmax(fabs(ll[j] - lam[j]) - le[j], 0), scale = DBL_EPSILON / mmin * (knorm + fabs(lam[j]) * mnorm);
        worst = fmax(worst, fabs(ll[j] - lam[j]));
        worst_ratio = fmax(worst_ratio, mmin > 0 ? d / scale : INFINITY);
    }
    mm_res_scalar_err(res, O_LMIN, lam[0], le[0], MM_ERR_BOUND);
    mm_res_scalar_err(res, O_LMAX, lam[n - 1], le[n - 1], MM_ERR_BOUND);
    mm_res_scalar(res, O_UNSTABLE, unstable);

    /* mode shapes: MATLAB's V column by column, and as plot series */
    for (int j = 0; j < n; j++) {
        mm_series *s = mm_res_series_i(res, O_SHAPE, j + 1, n);
        if (!s)
            return MM_ENOMEM;
        for (int i = 0; i < n; i++) {
            double *row = tm->cell + 3 * (j * n + i);
            row[0] = j + 1, row[1] = i + 1, row[2] = V[i * n + j];
            s->x[i] = i + 1;
            s->y[i] = V[i * n + j];
        }
    }

    mm_res_check_abs(res, "eig(K, M) in double (LAPACK dsygvd) vs lambda: worst |difference| / (eps ||M^-1|| "
                     "(||K|| + |lambda| ||M||)) <= n, eq. (6)", worst_ratio, 0, n);

    /* the printed modes in eq. (1) and eq. (4), in double-double: what the
     * rounding of v and lambda to double leaves (u |K||v| + u |lambda||M||v|
     * + lambda_err |M v|, and 2 u |v_j|^T |M| |v_l|) */
    double wres, wort;
    mm_linalg_sygv_rounding(n, K, M, lam, le, V, &wres, &wort);
    mm_res_check_abs(res, "printed modes in eq. (1): worst |K v - lambda M v|_i / (its rounding bound) <= 1", wres, 0,
                     1);
    mm_res_check_abs(res, "printed modes M-orthonormal, eq. (4): worst |v_j^T M v_l - delta_jl| / (its rounding "
                     "bound) <= 1", wort, 0, 1);

    /* eq. (5): trace(M^-1 K) = sum of the lambdas, M^-1 K by LU (LAPACK
     * dgesvx), whose error is at most its forward error bound per column */
    mm_linalg_solve_info info;
    rc = mm_linalg_solve(n, n, M, K, MK, &info, err);
    if (rc == MM_OK) {
        double tr, sl, tol = mm_errbound_trace(n, MK, info.ferr, lam, le, &tr, &sl);
        mm_res_check_abs(res, "sum of lambda vs trace(M^-1 K) by LU, eq. (5), within their error bounds", sl, tr,
                         1.01 * tol);
    } else if (rc != MM_ESINGULAR) {
        return rc;
    }

    mm_res_method(res, "eig(K, M): Cholesky reduction (LAPACK dsygvd) in double; lambda to the last digit by the "
                       "same reduction and Jacobi rotations in double-double", 0);
    mm_res_method_stat(res, "cond_M", condM);
    if (condM * DBL_EPSILON > 1e-8)
        mm_res_warn(res, "M is ill-conditioned: cond(M) = %.3g, so eig(K, M) in double precision can lose about %.0f "
                    "digits of the eigenvalues that are small beside ||K|| ||M^-1|| (here its worst error is %.2g of "
                    "the largest lambda); the values printed are computed in 32-digit arithmetic, with their bounds",
                    condM, fmin(16, log10(condM)), worst / lscale);
    if (unstable)
        mm_res_warn(res, "%d eigenvalue%s negative: K is not positive semi-definite, and the motion in %s "
                    "grows exponentially, like e^(sqrt(-lambda) t), instead of oscillating (a buckled or "
                    "inverted system)", unstable, unstable > 1 ? "s are" : " is", unstable > 1 ? "those modes" : "that mode");
    if (rigid)
        mm_res_warn(res, "%d eigenvalue%s zero within %s bound: rigid-body motion (the structure can move "
                    "without deforming a spring), omega = 0 within the error shown", rigid, rigid > 1 ? "s are" : " is",
                    rigid > 1 ? "their" : "its");
    return MM_OK;
}

static const char *const references[] = {
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, ch. 6",
    "G. H. Golub, C. F. Van Loan, Matrix Computations, 4th ed., Johns Hopkins 2013, sections 8.1, 8.5 and 8.7",
    "B. N. Parlett, The Symmetric Eigenvalue Problem, SIAM 1998, ch. 11 (residual bounds)",
    NULL,
};

const mm_exercise mm_ex_num_eigen = {
    .id = "num-eigen", .chapter = 1, .section = "1.4.2", .title = "Eigenvalues: natural frequencies and mode shapes",
    .summary = "Solve K v = lambda M v like MATLAB's eig(K, M): natural frequencies and mode shapes of a spring-mass chain.",
    .tags = "linear algebra, eigenvalues, eigenvectors, natural frequencies, mode shapes",
    .theory = "exercises/num/eigen.md", .params = params, .n_params = MM_COUNT(params), .outputs = outputs,
    .n_outputs = MM_COUNT(outputs), .references = references, .check = check, .solve = solve,
};
