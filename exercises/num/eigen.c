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
 * Method: Cholesky M = L L^T, then the symmetric standard problem
 * L^-1 K L^-T y = lambda y (LAPACK dsygvd).  Checks: the residual
 * ||K v - lambda M v|| of every mode, M-orthonormality V^T M V = I, and
 * trace(M^-1 K) = sum of the lambdas (M^-1 K from a separate linear solve).
 * A negative lambda (K indefinite: a buckled or inverted structure) has no
 * real omega; the table says so in words.
 * Reference: S. S. Rao, Mechanical Vibrations, 6th ed., ch. 6; G. H. Golub,
 * C. F. Van Loan, Matrix Computations, 4th ed., section 8.7.
 */
#include <float.h>
#include <math.h>

#include "mm_exhelp.h"
#include "mm_linalg.h"

#define MAXN 12

enum { P_K, P_M };

static const mm_param params[] = {
    [P_K] = {"K", "stiffness matrix", "N/m", MM_MATRIX, 0, -1e9, 1e9, "200,-100,0;-100,200,-100;0,-100,100",
             NULL, MAXN, MAXN, .help = "symmetric; the default is a chain wall-k-m-k-m-k-m, k = 100 N/m"},
    [P_M] = {"M", "mass matrix", "kg", MM_MATRIX, 0, -1e6, 1e6, "1,0,0;0,1,0;0,0,1", NULL, MAXN, MAXN,
             .help = "symmetric positive definite, as large as K; diagonal for point masses"},
};

static const char *const phi_name[MAXN + 1] = {"dof", "phi1", "phi2", "phi3", "phi4", "phi5", "phi6",
                                               "phi7", "phi8", "phi9", "phi10", "phi11", "phi12"};
static const char *const phi_unit[MAXN + 1] = {"", "", "", "", "", "", "", "", "", "", "", "", ""};
static const char *const mode_name[MAXN] = {"mode1", "mode2", "mode3", "mode4", "mode5", "mode6",
                                            "mode7", "mode8", "mode9", "mode10", "mode11", "mode12"};
static const char *const mode_label[MAXN] = {
    "mode shape 1", "mode shape 2", "mode shape 3", "mode shape 4", "mode shape 5", "mode shape 6",
    "mode shape 7", "mode shape 8", "mode shape 9", "mode shape 10", "mode shape 11", "mode shape 12"};

/* Symmetric to the solver's tolerance?  Else names the first offending pair. */
static int symmetric(const char *name, const mm_value *v, mm_error *err)
{
    int n = v->rows;
    double big = mm_maxabs(v->data, n * n);
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            if (fabs(v->data[i * n + j] - v->data[j * n + i]) > MM_LINALG_SYM_TOL * big)
                return mm_error_set(err, MM_EVALUE, name, "%s must be symmetric, but %s(%d,%d) = %g and "
                                    "%s(%d,%d) = %g", name, name, i + 1, j + 1, v->data[i * n + j], name,
                                    j + 1, i + 1, v->data[j * n + i]);
    return MM_OK;
}

static int check(const mm_value *in, mm_error *err)
{
    const mm_value *K = &in[P_K], *M = &in[P_M];
    if (K->rows != K->cols)
        return mm_error_set(err, MM_ERANGE, "K", "K must be square; got %d rows and %d columns", K->rows,
                            K->cols);
    if (M->rows != K->rows || M->cols != K->cols)
        return mm_error_set(err, MM_ERANGE, "M", "M must be %d x %d like K; got %d x %d", K->rows, K->cols,
                            M->rows, M->cols);
    int rc = symmetric("K", K, err);
    return rc != MM_OK ? rc : symmetric("M", M, err);
}

/* Frobenius norm of the n x n a. */
static double fro(int n, const double *a)
{
    double big = mm_maxabs(a, n * n), s = 0;
    if (big == 0)
        return 0;
    for (int i = 0; i < n * n; i++)
        s += (a[i] / big) * (a[i] / big);
    return big * sqrt(s);
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    const int n = in[P_K].rows;
    const double *K = in[P_K].data, *M = in[P_M].data;
    double *lam = mm_res_alloc(res, n * sizeof *lam), *V = mm_res_alloc(res, (size_t)n * n * sizeof *V);
    double *MK = mm_res_alloc(res, (size_t)n * n * sizeof *MK), *sv = mm_res_alloc(res, n * sizeof *sv);
    if (!lam || !V || !MK || !sv)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");

    int rc = mm_linalg_sygv(n, K, M, lam, V, err);
    if (rc == MM_ESINGULAR)
        return mm_error_set(err, MM_ESINGULAR, "M", "M is not positive definite: some motion would have zero "
                            "or negative kinetic energy 1/2 v^T M v; every mass must be positive");
    if (rc != MM_OK)
        return rc;

    /* cond(M) sets how well the reduction to standard form can do */
    rc = mm_linalg_svdvals(n, n, M, sv, err);
    if (rc != MM_OK)
        return rc;
    double condM = sv[0] / sv[n - 1];
    double nK = fro(n, K), nM = fro(n, M), lmax = fmax(fabs(lam[0]), fabs(lam[n - 1]));
    double tiny = 64 * n * DBL_EPSILON * condM * lmax;      /* lambda indistinguishable from 0 */

    static const char *const cols[] = {"lambda", "omega", "f"};
    static const char *const units[] = {"1/s^2", "rad/s", "Hz"};
    mm_table *t = mm_res_table_v1(res, "eigen", n, 3, cols, units);
    if (!t)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    int unstable = 0, rigid = 0;
    for (int j = 0; j < n; j++) {
        double *row = t->cell + 3 * j;
        row[0] = lam[j];
        if (lam[j] < -tiny) {                    /* eq. (2) has no real omega */
            unstable++;
            t->text[3 * j + 1] = "imaginary (lambda < 0: unstable)";
            t->text[3 * j + 2] = "imaginary";
        } else {
            if (lam[j] <= tiny)
                rigid++;
            row[1] = lam[j] > tiny ? sqrt(lam[j]) : 0;
            row[2] = row[1] / (2 * M_PI);
        }
    }

    /* mode shapes: as MATLAB's V (one column per mode), and as plot series */
    mm_table *ts = mm_res_table_v1(res, "modes", n, n + 1, phi_name, phi_unit);
    if (!ts)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (int i = 0; i < n; i++) {
        ts->cell[i * (n + 1)] = i + 1;
        for (int j = 0; j < n; j++)
            ts->cell[i * (n + 1) + j + 1] = V[i * n + j];
    }
    for (int j = 0; j < n; j++) {
        mm_series *s = mm_res_series_v1(res, mode_name[j], mode_label[j], "", "degree of freedom", "", n);
        if (!s)
            return mm_error_set(err, MM_ENOMEM, "", "out of memory");
        for (int i = 0; i < n; i++) {
            s->x[i] = i + 1;
            s->y[i] = V[i * n + j];
        }
    }

    mm_res_scalar_v1(res, "lambda_min", "smallest eigenvalue", "1/s^2", lam[0]);
    mm_res_scalar_v1(res, "lambda_max", "largest eigenvalue", "1/s^2", lam[n - 1]);
    mm_res_scalar_v1(res, "unstable_modes", "modes with lambda < 0", "", unstable);

    /* check 1: every mode satisfies eq. (1), relative to the sizes involved;
     * Cholesky reduction is backward stable up to a factor cond(M) */
    double worst = 0, wo = 0;
    for (int j = 0; j < n; j++) {
        double num = 0, vn = 0;
        for (int i = 0; i < n; i++) {
            double kv = 0, mv = 0;
            for (int k = 0; k < n; k++) {
                kv += K[i * n + k] * V[k * n + j];
                mv += M[i * n + k] * V[k * n + j];
            }
            num += (kv - lam[j] * mv) * (kv - lam[j] * mv);
            vn += V[i * n + j] * V[i * n + j];
        }
        double den = (nK + fabs(lam[j]) * nM) * sqrt(vn);
        worst = fmax(worst, den > 0 ? sqrt(num) / den : sqrt(num));
        /* check 2 on the way: v_j^T M v_l = delta_jl */
        for (int l = 0; l <= j; l++) {
            double s = 0;
            for (int i = 0; i < n; i++)
                for (int k = 0; k < n; k++)
                    s += V[i * n + j] * M[i * n + k] * V[k * n + l];
            wo = fmax(wo, fabs(s - (j == l)));
        }
    }
    double tol = 64 * n * DBL_EPSILON * condM;
    mm_res_check_abs(res, "worst ||K v - lambda M v|| / ((||K|| + |lambda| ||M||) ||v||), eq. (1)", worst, 0, tol);
    mm_res_check_abs(res, "M-orthonormality: worst |v_j^T M v_l - delta_jl|, eq. (4)", wo, 0, tol);

    /* check 3: trace(M^-1 K) = sum lambda (eq. 5), M^-1 K by an LU solve */
    mm_linalg_solve_info info;
    rc = mm_linalg_solve(n, n, M, K, MK, &info, err);
    if (rc != MM_OK)
        return rc;
    double tr = 0, sl = 0, sabs = 0;
    for (int j = 0; j < n; j++) {
        tr += MK[j * n + j];
        sl += lam[j];
        sabs += fabs(lam[j]);
    }
    mm_res_check_abs(res, "sum of lambda vs trace(M^-1 K), eq. (5)", sl, tr,
                     tol * (sabs + fro(n, MK)));

    mm_res_method(res, "Cholesky reduction to a symmetric eigenproblem (LAPACK dsygvd)", 0);
    mm_res_method_stat(res, "cond_M", condM);
    if (unstable)
        mm_res_warn(res, "%d eigenvalue%s negative: K is not positive semi-definite, and the motion in %s "
                    "grows exponentially, like e^(sqrt(-lambda) t), instead of oscillating (a buckled or "
                    "inverted system)", unstable, unstable > 1 ? "s are" : " is", unstable > 1 ? "those modes" : "that mode");
    if (rigid)
        mm_res_warn(res, "%d eigenvalue%s zero to rounding: rigid-body motion (the structure can move "
                    "without deforming a spring); omega = 0 is reported", rigid, rigid > 1 ? "s are" : " is");
    return MM_OK;
}

static const char *const references[] = {
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, ch. 6",
    "G. H. Golub, C. F. Van Loan, Matrix Computations, 4th ed., Johns Hopkins 2013, section 8.7",
    NULL,
};

const mm_exercise mm_ex_num_eigen = {
    .id = "num-eigen",
    .chapter = 1,
    .section = "1.4.2",
    .title = "Eigenvalues: natural frequencies and mode shapes",
    .summary = "Solve K v = lambda M v like MATLAB's eig(K, M): natural frequencies and mode shapes of a spring-mass chain.",
    .tags = "linear algebra, eigenvalues, eigenvectors, natural frequencies, mode shapes",
    .theory = "exercises/num/eigen.md",
    .params = params,
    .n_params = MM_COUNT(params),
    .references = references,
    .check = check,
    .solve = solve,
};
