/* test_linalg.c — mm_linalg against answers known independently:
 * exact rationals worked by hand, the closed-form inverse of the Hilbert
 * matrix, published condition numbers, closed-form frequencies and mode
 * shapes of spring-mass chains and of a finite-element bar.  Comparisons of
 * one solver with another (dense vs selective vs banded) are marked as
 * consistency checks; they come on top of the independent ones. */
#include "mm_test.h"

#include <float.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "mm_linalg.h"

#define EPS DBL_EPSILON
#define PI 3.14159265358979323846

/* ==== helpers =================================================================== */

__extension__ typedef __int128 i128;   /* GCC: exact products of binomials */

/* C(n, k), exact in 64 bits for the sizes used here (n <= 30). */
static long long binom(int n, int k)
{
    if (k < 0 || k > n) return 0;
    long long c = 1;
    for (int i = 1; i <= k; i++)
        c = c * (n - k + i) / i;              /* exact at every step */
    return c;
}

/* Entry (i, j) (1-based) of the inverse of the n x n Hilbert matrix, the
 * closed form (Choi, "Tricks or treats with the Hilbert matrix", 1983):
 * (-1)^(i+j) (i+j-1) C(n+i-1, n-j) C(n+j-1, n-i) C(i+j-2, i-1)^2. */
static double hilbert_inverse(int n, int i, int j)
{
    i128 v = (i128)(i + j - 1) * binom(n + i - 1, n - j);
    v *= binom(n + j - 1, n - i);
    v *= (i128)binom(i + j - 2, i - 1) * binom(i + j - 2, i - 1);
    double d = (double)v;
    return (i + j) % 2 ? -d : d;
}

static double *hilbert(int n)
{
    double *H = malloc((size_t)n * n * sizeof *H);
    assert_non_null(H);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            H[i * n + j] = 1.0 / (i + j + 1);
    return H;
}

/* Tridiagonal chain matrices: K = k tridiag(-1, 2, -1), last diagonal 1 when
 * the right end is free; M = m I. */
static void chain(int n, double k, double m, int free_end, double *K, double *M)
{
    memset(K, 0, (size_t)n * n * sizeof *K);
    memset(M, 0, (size_t)n * n * sizeof *M);
    for (int i = 0; i < n; i++) {
        K[i * n + i] = 2 * k;
        if (i > 0) K[i * n + i - 1] = K[(i - 1) * n + i] = -k;
        M[i * n + i] = m;
    }
    if (free_end)
        K[(n - 1) * n + n - 1] = k;
}

/* V^T M V = I and V^T K V = diag(lambda) for nev modes stored in columns of
 * the n x nev V.  Tolerance: entries of K, M are O(scale); products of
 * normalised vectors carry ~n eps scale of rounding, so 1e3 n eps scale. */
static void check_modes_orthonormal(int n, int nev, const double *K, const double *M,
                                    const double *lambda, const double *V)
{
    double kmax = 0;
    for (int i = 0; i < n * n; i++)
        kmax = fmax(kmax, fabs(K[i]));
    double mmax = 0;
    for (int i = 0; i < n * n; i++)
        mmax = fmax(mmax, fabs(M[i]));
    for (int a = 0; a < nev; a++)
        for (int b = 0; b < nev; b++) {
            double vmv = 0, vkv = 0;
            for (int i = 0; i < n; i++)
                for (int j = 0; j < n; j++) {
                    vmv += V[i * nev + a] * M[i * n + j] * V[j * nev + b];
                    vkv += V[i * nev + a] * K[i * n + j] * V[j * nev + b];
                }
            check_abs(vmv, a == b ? 1.0 : 0.0, 1e3 * n * EPS,
                      "mass normalisation / M-orthogonality v^T M v");
            /* scale of v^T K v: kmax/mmax (v ~ 1/sqrt(m)) */
            check_abs(vkv, a == b ? lambda[a] : 0.0, 1e3 * n * EPS * kmax / mmax,
                      "K-orthogonality v^T K v = lambda delta");
        }
}

/* ==== linear systems ================================================================ */

static void solve_should_reproduce_the_book_example_exactly(void **state)
{
    (void)state;
    const double A[9] = {1, 2, 3, 4, 5, 6, 7, 8, 10}, b[3] = {10, 0, 1000};
    /* Cramer's rule by hand: det A = -3, x = (2980/3, -6020/3, 1010) */
    const double want[3] = {2980.0 / 3, -6020.0 / 3, 1010};
    double x[3];
    mm_linalg_solve_info info;
    mm_error err;
    assert_int_equal(mm_linalg_solve(3, 1, A, b, x, &info, &err), MM_OK);
    /* cond(A) ~ 88, so rounding in the solve costs ~ 88 eps ~ 2e-14 */
    for (int i = 0; i < 3; i++)
        check_rel(x[i], want[i], 1e-13, "x of the book's 3x3 system");
    assert_int_equal(info.warn, 0);
    assert_true(info.rcond > 1e-3 && info.rcond < 1.0);
    /* residual: |b| = 1000, stable solve leaves a few ulps of it */
    check_abs(info.residual, 0.0, 1e3 * 1e3 * EPS, "residual ||b - A x||");
    check_abs(info.backward_error, 0.0, 10 * EPS, "backward error of a stable solve");
    /* 2-norm condition number, reference: mpmath SVD at 50 digits */
    double c2;
    assert_int_equal(mm_linalg_cond2(3, 3, A, &c2, &err), MM_OK);
    check_rel(c2, 88.448279920698623522, 1e-13, "cond(A) 2-norm (SVD backward error ~ eps cond)");
}

static void solve_should_handle_several_right_hand_sides_in_place(void **state)
{
    (void)state;
    /* B = A X for an integer X: every entry of B is an exact integer */
    const double A[9] = {4, -2, 1, -2, 4, -2, 1, -2, 4};
    const double X0[6] = {1, -1, 2, 3, -5, 0.5};          /* 3 x 2 */
    double B[6];
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 2; k++) {
            double s = 0;
            for (int j = 0; j < 3; j++)
                s += A[i * 3 + j] * X0[j * 2 + k];
            B[i * 2 + k] = s;
        }
    mm_linalg_solve_info info;
    /* X may be the same array as B */
    assert_int_equal(mm_linalg_solve(3, 2, A, B, B, &info, NULL), MM_OK);
    for (int i = 0; i < 6; i++)      /* cond ~ 4: a few ulps */
        check_abs(B[i], X0[i], 1e-14, "column-by-column solution, B overwritten by X");
}

static void hilbert_10_should_be_warned_with_small_residual_and_bounded_error(void **state)
{
    (void)state;
    const int n = 10;
    double *H = hilbert(n), b[10] = {1}, x[10];
    mm_linalg_solve_info info;
    assert_int_equal(mm_linalg_solve(n, 1, H, b, x, &info, NULL), MM_OK);
    assert_int_equal(info.warn, 1);                 /* rcond ~ 3e-14 < 1e-10 */
    /* exact answer: first column of the closed-form inverse (integers) */
    double emax = 0, xmax = 0, hinv = 0, hn = 0;
    for (int i = 0; i < n; i++) {
        double xi = hilbert_inverse(n, i + 1, 1);
        emax = fmax(emax, fabs(x[i] - xi));
        xmax = fmax(xmax, fabs(xi));
        double rs = 0, hs = 0;
        for (int j = 0; j < n; j++) {
            rs += fabs(hilbert_inverse(n, i + 1, j + 1));
            hs += fabs(H[i * n + j]);
        }
        hinv = fmax(hinv, rs);
        hn = fmax(hn, hs);
    }
    double kappa = hn * hinv;                       /* exact cond_inf ~ 3.5e13 */
    print_message("hilbert(10): rel. error %.3g, cond_inf %.3g, cond*eps %.3g, "
                  "ferr %.3g, rcond %.3g, backward error %.3g\n",
                  emax / xmax, kappa, kappa * EPS, info.ferr, info.rcond,
                  info.backward_error);
    /* forward error <= cond * (relative perturbation): the stored H is
     * H + dH with |dH| <= eps/2 |H|, plus the solve's backward error */
    assert_true(emax / xmax <= kappa * EPS);
    assert_true(emax / xmax > 1e-8);                /* digits really are lost */
    assert_true(info.ferr >= emax / xmax);          /* LAPACK's bound holds */
    /* ... and yet the residual is at rounding level: a small residual does
     * not mean an accurate x */
    check_abs(info.backward_error, 0.0, 10 * EPS, "backward error, ill-conditioned");
    /* rcond estimates 1/cond_1 within a factor 10 (it is an estimate,
     * and of the equilibrated matrix) */
    assert_true(info.rcond > 0.1 / kappa && info.rcond < 10 / kappa);
    free(H);
}

static void hilbert_12_should_be_warned_with_a_small_residual(void **state)
{
    (void)state;
    double *H = hilbert(12), b[12] = {1}, x[12];
    mm_linalg_solve_info info;
    mm_error err;
    /* cond(H12) ~ 1.7e16 > 1/(12 eps): no digit of x can be trusted, and
     * we say so (untrusted), yet LU with partial pivoting is backward
     * stable: the residual stays at the level of eps ||A|| ||x||. */
    assert_int_equal(mm_linalg_solve(12, 1, H, b, x, &info, &err), MM_OK);
    assert_true(info.rcond < 12 * EPS);
    assert_int_equal(info.warn, 1);
    assert_int_equal(info.untrusted, 1);
    /* backward error: a few eps (Higham, Accuracy and Stability, ch. 9) */
    assert_true(info.backward_error < 100 * EPS);
    free(H);
}

static void singular_matrices_should_give_no_solution(void **state)
{
    (void)state;
    mm_error err;
    double x[3];
    /* exactly dependent rows, exact zero pivot */
    const double A2[4] = {1, 2, 2, 4}, b2[2] = {1, 2};
    assert_int_equal(mm_linalg_solve(2, 1, A2, b2, x, NULL, &err), MM_ESINGULAR);
    assert_string_equal(err.param, "A");
    assert_non_null(strstr(err.msg, "no unique solution"));
    /* the classic [1 2 3;4 5 6;7 8 9]: after dgesvx's equilibration the
     * last pivot comes out exactly zero, so it is refused as singular */
    const double A3[9] = {1, 2, 3, 4, 5, 6, 7, 8, 9}, b3[3] = {1, 2, 3};
    assert_int_equal(mm_linalg_solve(3, 1, A3, b3, x, NULL, &err), MM_ESINGULAR);
    assert_string_equal(err.param, "A");
    /* well conditioned after equilibration, but x1 = 1e300 / 1e-300 */
    const double As[4] = {1e-300, 0, 0, 1}, bs[2] = {1e300, 1};
    assert_int_equal(mm_linalg_solve(2, 1, As, bs, x, NULL, &err), MM_ENONFINITE);
    /* cond2 of a matrix with an exactly zero singular value */
    const double D[4] = {1, 0, 0, 0};
    double c;
    assert_int_equal(mm_linalg_cond2(2, 2, D, &c, &err), MM_ESINGULAR);
    assert_true(isinf(c));
}

static void cond2_of_hilbert_should_match_published_values(void **state)
{
    (void)state;
    double c, *H5 = hilbert(5), *H10 = hilbert(10);
    assert_int_equal(mm_linalg_cond2(5, 5, H5, &c, NULL), MM_OK);
    /* published cond(hilb(5)) = 4.766e5 (4 digits); mpmath SVD of the
     * same rounded matrix: 476607.25024198780 — backward-stable SVD moves
     * sigma_min by ~ n eps sigma_max, i.e. cond by ~ n eps cond = 5e-10 */
    check_rel(c, 4.766e5, 1e-4, "cond(H5) vs published 4.766e5");
    check_rel(c, 476607.25024198780, 1e-9, "cond(H5) vs mpmath");
    assert_int_equal(mm_linalg_cond2(10, 10, H10, &c, NULL), MM_OK);
    /* published 1.6025e13 is cond of the double-rounded H10 (the exact
     * H10 has 1.60263e13); mpmath on the rounded matrix: 1.60248412588533e13.
     * Worst-case bound n eps cond ~ 3.5e-2; the SVD does far better */
    check_rel(c, 1.6025e13, 1e-4, "cond(H10) vs published 1.6025e13");
    check_rel(c, 1.60248412588533e13, 1e-3, "cond(H10) vs mpmath");
    free(H5);
    free(H10);
}

/* ==== least squares ================================================================== */

static void lstsq_should_match_the_normal_equations_by_hand(void **state)
{
    (void)state;
    /* line through (1,10), (3,18), (10,37): normal equations
     * [110 14; 14 3] [a; b] = [434; 65] -> a = 196/67, b = 537/67;
     * residuals (-63, 81, -18)/67, norm sqrt(10854)/67 */
    const double A[6] = {1, 1, 3, 1, 10, 1}, b[3] = {10, 18, 37};
    double x[2], res, sv[2];
    int rank;
    assert_int_equal(mm_linalg_lstsq(3, 2, 1, A, b, 0, x, &rank, &res, sv, NULL), MM_OK);
    check_rel(x[0], 196.0 / 67, 1e-14, "slope (cond ~ 10)");
    check_rel(x[1], 537.0 / 67, 1e-14, "intercept");
    check_rel(res, sqrt(10854.0) / 67, 1e-14, "residual norm");
    assert_int_equal(rank, 2);
    assert_true(sv[0] >= sv[1] && sv[1] > 0);
}

static void lstsq_should_return_minimum_norm_for_rank_deficient_a(void **state)
{
    (void)state;
    /* columns equal: x1 + x2 = 1 fits exactly; least norm is (1/2, 1/2) */
    const double A[6] = {1, 1, 2, 2, 3, 3}, b[3] = {1, 2, 3};
    double x[2], res;
    int rank;
    assert_int_equal(mm_linalg_lstsq(3, 2, 1, A, b, -1, x, &rank, &res, NULL, NULL), MM_OK);
    assert_int_equal(rank, 1);
    check_abs(x[0], 0.5, 1e-14, "minimum-norm x1");
    check_abs(x[1], 0.5, 1e-14, "minimum-norm x2");
    check_abs(res, 0.0, 1e-14, "consistent system: zero residual");
}

/* ==== generalized symmetric eigenproblem =========================================== */

static void num_eigen_default_should_give_the_chain_frequencies(void **state)
{
    (void)state;
    /* API.md num-eigen default: a fixed-free chain of 3 unit masses, k = 100.
     * Fixed-free chain of n masses m, springs k: u_i = sin(i theta) solves
     * the interior rows with lambda = (4k/m) sin^2(theta/2); the free end
     * needs u_{n+1} = u_n, i.e. theta_j = (2j-1) pi / (2n+1), so
     *     omega_j = 2 sqrt(k/m) sin((2j-1) pi / (2(2n+1))). */
    const double K[9] = {200, -100, 0, -100, 200, -100, 0, -100, 100};
    const double M[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    double lam[3], V[9];
    assert_int_equal(mm_linalg_sygv(3, K, M, lam, V, NULL), MM_OK);
    for (int j = 1; j <= 3; j++) {
        double w = 20 * sin((2 * j - 1) * PI / 14);   /* 4.4504, 12.4698, 18.0194 */
        check_rel(sqrt(lam[j - 1]), w, 1e-14, "omega_j of the 3-mass chain");
    }
    check_modes_orthonormal(3, 3, K, M, lam, V);
}

/* Closed-form check of eigenpairs of a chain (fixed-fixed or fixed-free)
 * with mass m: frequencies and M-normalised mode shapes, first component
 * positive (the documented sign convention). */
static double chain_lambda(int n, double k, double m, int free_end, int j)
{
    double theta = free_end ? (2 * j - 1) * PI / (2 * n + 1) : j * PI / (n + 1);
    double s = sin(theta / 2);
    return 4 * k / m * s * s;
}

static void check_chain_modes(int n, int nev, double k, double m, int free_end,
                              const double *lam, const double *V)
{
    const double knorm = 4 * k / m;      /* ||M^-1 K||, the largest lambda */
    for (int j = 1; j <= nev; j++) {
        double theta = free_end ? (2 * j - 1) * PI / (2 * n + 1) : j * PI / (n + 1);
        double lj = chain_lambda(n, k, m, free_end, j);
        /* a backward-stable solver moves lambda by ~ eps ||K|| (Weyl), not
         * by eps lambda: 100 eps knorm absolute, i.e. relative
         * 100 eps knorm / lambda_j for lambda and half that for omega */
        check_rel(sqrt(lam[j - 1]), sqrt(lj), 1e-15 + 50 * EPS * knorm / lj,
                  "omega_j vs closed form");
        /* eigenvector error ~ eps ||K|| / gap (Davis-Kahan), gap to the
         * nearest other eigenvalue; entries are O(1/sqrt(n m)) */
        double gap = INFINITY;
        if (j > 1) gap = fmin(gap, lj - chain_lambda(n, k, m, free_end, j - 1));
        if (j < n) gap = fmin(gap, chain_lambda(n, k, m, free_end, j + 1) - lj);
        double vtol = 1e3 * EPS * knorm / gap;
        double norm = 0;
        for (int i = 1; i <= n; i++)
            norm += m * sin(i * theta) * sin(i * theta);
        norm = sqrt(norm);
        for (int i = 1; i <= n; i++)
            check_abs(V[(i - 1) * nev + (j - 1)], sin(i * theta) / norm, vtol,
                      "mode shape sin(i theta_j), M-normalised, first entry > 0");
    }
}

static void chains_should_match_closed_form_frequencies_and_shapes(void **state)
{
    (void)state;
    const int n = 50;
    const double k = 1e4, m = 2.5;      /* m != 1: normalisation is not trivial */
    double *K = malloc(n * n * sizeof *K), *M = malloc(n * n * sizeof *M);
    double *V = malloc(n * n * sizeof *V), lam[50];
    for (int free_end = 0; free_end <= 1; free_end++) {
        chain(n, k, m, free_end, K, M);
        assert_int_equal(mm_linalg_sygv(n, K, M, lam, V, NULL), MM_OK);
        for (int j = 1; j < n; j++)
            assert_true(lam[j] > lam[j - 1]);                    /* ascending */
        check_chain_modes(n, n, k, m, free_end, lam, V);
        check_modes_orthonormal(n, n, K, M, lam, V);
    }
    free(V); free(M); free(K);
}

static void selective_and_banded_should_match_closed_form_first_modes(void **state)
{
    (void)state;
    const int n = 200, nev = 10;
    const double k = 100, m = 1;
    double *K = malloc(n * n * sizeof *K), *M = malloc(n * n * sizeof *M);
    double *Vf = malloc(n * n * sizeof *Vf), *Vs = malloc(n * nev * sizeof *Vs);
    double *Vb = malloc(n * nev * sizeof *Vb), *Kb = malloc(n * 2 * sizeof *Kb);
    double *Mb = malloc(n * 2 * sizeof *Mb);
    double lf[200], ls[10], lb[10];
    chain(n, k, m, 1, K, M);
    mm_linalg_band_pack(n, 1, K, Kb);
    mm_linalg_band_pack(n, 1, M, Mb);
    assert_int_equal(mm_linalg_sygv(n, K, M, lf, Vf, NULL), MM_OK);
    assert_int_equal(mm_linalg_sygv_first(n, nev, K, M, ls, Vs, NULL), MM_OK);
    assert_int_equal(mm_linalg_sbgv_first(n, 1, nev, Kb, Mb, lb, Vb, NULL), MM_OK);
    /* independent: the closed form, for each solver */
    check_chain_modes(n, nev, k, m, 1, ls, Vs);
    check_chain_modes(n, nev, k, m, 1, lb, Vb);
    check_modes_orthonormal(n, nev, K, M, ls, Vs);
    check_modes_orthonormal(n, nev, K, M, lb, Vb);
    /* consistency: the three solvers agree on the first modes.  Each
     * eigenvalue is within a small multiple of eps ||K|| (||K|| = 4k) of
     * the truth (backward stability + Weyl), whatever its own size */
    for (int j = 0; j < nev; j++) {
        check_abs(ls[j], lf[j], 100 * EPS * 4 * k, "dense selective vs full (consistency)");
        check_abs(lb[j], lf[j], 100 * EPS * 4 * k, "banded vs full (consistency)");
        for (int i = 0; i < n; i++) {
            check_abs(Vs[i * nev + j], Vf[i * n + j], 1e-9, "selective mode vs full");
            check_abs(Vb[i * nev + j], Vf[i * n + j], 1e-9, "banded mode vs full");
        }
    }
    /* eigenvalues only */
    assert_int_equal(mm_linalg_sbgv_first(n, 1, nev, Kb, Mb, lb, NULL, NULL), MM_OK);
    check_abs(lb[0], lf[0], 100 * EPS * 4 * k, "banded, values only");
    free(Mb); free(Kb); free(Vb); free(Vs); free(Vf); free(M); free(K);
}

static void banded_consistent_mass_bar_should_match_discrete_closed_form(void **state)
{
    (void)state;
    /* Fixed-fixed bar, n interior nodes, linear elements of length h:
     * K = (EA/h) tridiag(-1,2,-1), consistent M = (rho A h/6) tridiag(1,4,1).
     * With u_i = sin(i theta): (EA/h)(2 - 2cos theta) = lambda (rho A h/6)
     * (4 + 2 cos theta), so lambda_j = (6E/(rho h^2)) (1 - cos theta_j) /
     * (2 + cos theta_j), theta_j = j pi/(n+1).  M is not diagonal: this
     * exercises the banded M of the generalized problem. */
    const int n = 39, nev = 6;
    const double E = 2.1e11, rho = 7850, A = 1e-4, L = 1, h = L / (n + 1);
    double *Kb = malloc(n * 2 * sizeof *Kb), *Mb = malloc(n * 2 * sizeof *Mb);
    double *V = malloc(n * nev * sizeof *V), lam[6];
    double *K = calloc(n * n, sizeof *K), *M = calloc(n * n, sizeof *M);
    for (int i = 0; i < n; i++) {
        Kb[i * 2] = 2 * E * A / h;
        Kb[i * 2 + 1] = -E * A / h;           /* padding at i = n-1 unused */
        Mb[i * 2] = 4 * rho * A * h / 6;
        Mb[i * 2 + 1] = rho * A * h / 6;
        K[i * n + i] = Kb[i * 2];
        M[i * n + i] = Mb[i * 2];
        if (i + 1 < n) {
            K[i * n + i + 1] = K[(i + 1) * n + i] = Kb[i * 2 + 1];
            M[i * n + i + 1] = M[(i + 1) * n + i] = Mb[i * 2 + 1];
        }
    }
    assert_int_equal(mm_linalg_sbgv_first(n, 1, nev, Kb, Mb, lam, V, NULL), MM_OK);
    for (int j = 1; j <= nev; j++) {
        double th = j * PI / (n + 1);
        double want = 6 * E / (rho * h * h) * (1 - cos(th)) / (2 + cos(th));
        check_rel(lam[j - 1], want, 1e-11, "bar lambda_j (n^2 eps relative, see chains)");
        /* shape: proportional to sin(i theta), positive first entry */
        double r = V[0 * nev + j - 1] / sin(th);
        for (int i = 1; i <= n; i++)
            check_abs(V[(i - 1) * nev + j - 1], r * sin(i * th), 1e-9 * fabs(r),
                      "bar mode shape sin(i theta_j)");
        assert_true(r > 0);
    }
    check_modes_orthonormal(n, nev, K, M, lam, V);
    free(M); free(K); free(V); free(Mb); free(Kb);
}

static void banded_should_separate_repeated_and_rigid_body_modes(void **state)
{
    (void)state;
    /* Two identical, unconnected free-free chains of 20 masses: every
     * eigenvalue is double, and lambda = 0 (rigid-body motion) appears
     * twice.  Inverse iteration must return M-orthonormal pairs. */
    const int n = 40, nev = 6, kd = 1;
    double *K = calloc(n * n, sizeof *K), *M = calloc(n * n, sizeof *M);
    double *Kb = malloc(n * (kd + 1) * sizeof *Kb), *Mb = malloc(n * (kd + 1) * sizeof *Mb);
    double *V = malloc(n * nev * sizeof *V), lam[6], ld[6];
    for (int c = 0; c < 2; c++)
        for (int i = 0; i < 20; i++) {
            int g = 20 * c + i;
            M[g * n + g] = 1.5;
            K[g * n + g] = (i == 0 || i == 19) ? 50 : 100;
            if (i + 1 < 20)
                K[g * n + g + 1] = K[(g + 1) * n + g] = -50;
        }
    mm_linalg_band_pack(n, kd, K, Kb);
    mm_linalg_band_pack(n, kd, M, Mb);
    assert_int_equal(mm_linalg_sbgv_first(n, kd, nev, Kb, Mb, lam, V, NULL), MM_OK);
    assert_int_equal(mm_linalg_sygv_first(n, nev, K, M, ld, NULL, NULL), MM_OK);
    /* free-free chain: lambda_j = (4k/m) sin^2(j pi / (2 N)), j = 0..N-1,
     * each twice here; lambda_0 = 0 to within n eps ||K|| */
    for (int j = 0; j < nev; j++) {
        double s = sin((j / 2) * PI / 40), want = 4 * 50 / 1.5 * s * s;
        check_abs(lam[j], want, 1e3 * EPS * 200 / 1.5, "double eigenvalues of two chains");
        check_abs(lam[j], ld[j], 1e3 * EPS * 200 / 1.5, "banded vs dense (consistency)");
    }
    check_modes_orthonormal(n, nev, K, M, lam, V);
    free(V); free(Mb); free(Kb); free(M); free(K);
}

static void banded_free_free_beam_should_give_rigid_and_elastic_modes(void **state)
{
    (void)state;
    /* Euler-Bernoulli beam, 20 Hermite-cubic elements, consistent mass, both
     * ends free: 42 DOFs (w, theta per node), half-bandwidth 3, two
     * rigid-body modes (lambda = 0 exactly in exact arithmetic).  This is
     * the case the finite-element module sends to the banded solver. */
    enum { NE = 20, N = 2 * (NE + 1), KD = 3, NEV = 5 };
    const double E = 2.1e11, I = 1e-8, rho = 7850, A = 1e-4, L = 1, h = L / NE;
    const double ke[4][4] = {{12, 6 * h, -12, 6 * h}, {6 * h, 4 * h * h, -6 * h, 2 * h * h},
                             {-12, -6 * h, 12, -6 * h}, {6 * h, 2 * h * h, -6 * h, 4 * h * h}};
    const double me[4][4] = {{156, 22 * h, 54, -13 * h}, {22 * h, 4 * h * h, 13 * h, -3 * h * h},
                             {54, 13 * h, 156, -22 * h}, {-13 * h, -3 * h * h, -22 * h, 4 * h * h}};
    double *K = calloc(N * N, sizeof *K), *M = calloc(N * N, sizeof *M);
    double *Kb = malloc(N * (KD + 1) * sizeof *Kb), *Mb = malloc(N * (KD + 1) * sizeof *Mb);
    double *V = malloc(N * NEV * sizeof *V), *Vd = malloc(N * NEV * sizeof *Vd);
    double lam[NEV], ld[NEV];
    for (int e = 0; e < NE; e++)
        for (int a = 0; a < 4; a++)
            for (int b = 0; b < 4; b++) {
                int i = 2 * e + a, j = 2 * e + b;
                K[i * N + j] += E * I / (h * h * h) * ke[a][b];
                M[i * N + j] += rho * A * h / 420 * me[a][b];
            }
    mm_linalg_band_pack(N, KD, K, Kb);
    mm_linalg_band_pack(N, KD, M, Mb);
    assert_int_equal(mm_linalg_sbgv_first(N, KD, NEV, Kb, Mb, lam, V, NULL), MM_OK);
    assert_int_equal(mm_linalg_sygv_first(N, NEV, K, M, ld, Vd, NULL), MM_OK);
    /* rigid-body modes: zero up to rounding, eps * ||K|| / ||M|| ~ 1e-3
     * here against lambda_3 ~ 1e6 */
    double scale = lam[2];
    for (int j = 0; j < 2; j++)
        check_abs(lam[j], 0.0, 1e-10 * scale, "rigid-body mode: lambda ~ 0");
    /* first elastic mode vs the continuous free-free beam, beta L =
     * 4.730040744862704; Hermite cubics with consistent mass converge like
     * h^4: 2e-6 relative at 20 elements, so 1e-5 */
    double bl = 4.730040744862704;
    check_rel(sqrt(lam[2]), bl * bl * sqrt(E * I / (rho * A)) / (L * L), 1e-5,
              "first elastic frequency vs Euler-Bernoulli");
    /* consistency with the dense solver for the elastic modes (the rigid
     * ones form a 2-D space whose basis is not unique).  Both are within a
     * few eps * lambda_max of the truth (lambda_max ~ 1e13 here: the
     * shortest element's rotation mode), not eps * lambda_j */
    double all[N];
    assert_int_equal(mm_linalg_sygv(N, K, M, all, NULL, NULL), MM_OK);
    for (int j = 2; j < NEV; j++) {
        check_abs(lam[j], ld[j], 100 * EPS * all[N - 1],
                  "elastic lambda banded vs dense (consistency)");
        double vmax = 0;
        for (int i = 0; i < N; i++)
            vmax = fmax(vmax, fabs(Vd[i * NEV + j]));
        for (int i = 0; i < N; i++)
            check_abs(V[i * NEV + j], Vd[i * NEV + j], 1e-8 * vmax, "elastic mode shapes agree");
    }
    check_modes_orthonormal(N, NEV, K, M, lam, V);
    free(Vd); free(V); free(Mb); free(Kb); free(M); free(K);
}

static void wider_band_should_agree_with_dense(void **state)
{
    (void)state;
    /* consistency check for kd = 3: an SPD band K (diagonally dominant)
     * and an SPD band M, no closed form */
    const int n = 60, kd = 3, nev = 8;
    double *K = calloc(n * n, sizeof *K), *M = calloc(n * n, sizeof *M);
    double *Kb = malloc(n * (kd + 1) * sizeof *Kb), *Mb = malloc(n * (kd + 1) * sizeof *Mb);
    double *Vb = malloc(n * nev * sizeof *Vb), *Vd = malloc(n * nev * sizeof *Vd);
    double lb[8], ld[8];
    for (int i = 0; i < n; i++)
        for (int d = 0; d <= kd && i + d < n; d++) {
            double kv = d == 0 ? 10 + 0.1 * i : -1.0 / (d + 1) - 0.01 * ((i * 7 + d) % 5);
            double mv = d == 0 ? 2 + 0.05 * (i % 3) : 0.2 / (d + 1);
            K[i * n + i + d] = K[(i + d) * n + i] = kv;
            M[i * n + i + d] = M[(i + d) * n + i] = mv;
        }
    mm_linalg_band_pack(n, kd, K, Kb);
    mm_linalg_band_pack(n, kd, M, Mb);
    assert_int_equal(mm_linalg_sbgv_first(n, kd, nev, Kb, Mb, lb, Vb, NULL), MM_OK);
    assert_int_equal(mm_linalg_sygv_first(n, nev, K, M, ld, Vd, NULL), MM_OK);
    for (int j = 0; j < nev; j++) {
        check_rel(lb[j], ld[j], 1e-12, "kd = 3: banded vs dense lambda (consistency)");
        for (int i = 0; i < n; i++)
            check_abs(Vb[i * nev + j], Vd[i * nev + j], 1e-9, "kd = 3: modes agree");
    }
    check_modes_orthonormal(n, nev, K, M, lb, Vb);
    free(Vd); free(Vb); free(Mb); free(Kb); free(M); free(K);
}

static void mass_matrix_not_positive_definite_should_be_singular(void **state)
{
    (void)state;
    const double K[4] = {2, -1, -1, 2}, M[4] = {1, 0, 0, -1};   /* a negative mass */
    const double Kb[4] = {2, -1, 2, 0}, Mb[4] = {1, 0, -1, 0};
    double lam[2], V[4];
    mm_error err;
    assert_int_equal(mm_linalg_sygv(2, K, M, lam, V, &err), MM_ESINGULAR);
    assert_string_equal(err.param, "M");
    assert_non_null(strstr(err.msg, "mass matrix is not positive definite"));
    assert_int_equal(mm_linalg_sygv_first(2, 1, K, M, lam, V, &err), MM_ESINGULAR);
    assert_string_equal(err.param, "M");
    assert_int_equal(mm_linalg_sbgv_first(2, 1, 1, Kb, Mb, lam, V, &err), MM_ESINGULAR);
    assert_string_equal(err.param, "M");
    assert_non_null(strstr(err.msg, "mass matrix is not positive definite"));
}

static void nonsymmetric_stiffness_should_be_a_bad_value(void **state)
{
    (void)state;
    const double K[4] = {2, -1, -1.5, 2}, M[4] = {1, 0, 0, 1};
    double lam[2];
    mm_error err;
    assert_int_equal(mm_linalg_sygv(2, K, M, lam, NULL, &err), MM_EVALUE);
    assert_string_equal(err.param, "K");
    assert_non_null(strstr(err.msg, "symmetric"));
}

/* ==== general eigenproblem =============================================================== */

static void geev_should_find_real_and_complex_eigenpairs(void **state)
{
    (void)state;
    /* block diag( [2 1; 1 2] (eigenvalues 1, 3), [0 -2; 2 0] (+-2i) ),
     * mixed by a permutation similarity so it is not block-shaped */
    const double A[16] = {2, 0, 1, 0,
                          0, 0, 0, -2,
                          1, 0, 2, 0,
                          0, 2, 0, 0};
    double wr[4], wi[4], VR[16];
    assert_int_equal(mm_linalg_geev(4, A, wr, wi, VR, NULL), MM_OK);
    int seen1 = 0, seen3 = 0, seenpair = 0;
    for (int j = 0; j < 4; j++) {
        if (wi[j] == 0) {
            /* real: A v = lambda v, ||v|| = 1 */
            double nrm = 0;
            for (int i = 0; i < 4; i++) {
                double s = 0;
                for (int k = 0; k < 4; k++)
                    s += A[i * 4 + k] * VR[k * 4 + j];
                check_abs(s, wr[j] * VR[i * 4 + j], 1e-14, "A v = lambda v (real)");
                nrm += VR[i * 4 + j] * VR[i * 4 + j];
            }
            check_abs(nrm, 1.0, 1e-14, "unit eigenvector");
            seen1 += fabs(wr[j] - 1) < 1e-14;
            seen3 += fabs(wr[j] - 3) < 1e-14;
        } else if (wi[j] > 0) {
            /* pair: v = VR(:,j) + i VR(:,j+1) for lambda = wr + i wi */
            assert_true(j + 1 < 4 && wi[j + 1] == -wi[j] && wr[j + 1] == wr[j]);
            check_abs(wr[j], 0.0, 1e-14, "Re of +-2i");
            check_abs(wi[j], 2.0, 1e-14, "Im of +-2i");
            for (int i = 0; i < 4; i++) {
                double sr = 0, si = 0;
                for (int k = 0; k < 4; k++) {
                    sr += A[i * 4 + k] * VR[k * 4 + j];
                    si += A[i * 4 + k] * VR[k * 4 + j + 1];
                }
                double vr = VR[i * 4 + j], vi = VR[i * 4 + j + 1];
                check_abs(sr, wr[j] * vr - wi[j] * vi, 1e-14, "Re(A v) = Re(lambda v)");
                check_abs(si, wr[j] * vi + wi[j] * vr, 1e-14, "Im(A v) = Im(lambda v)");
            }
            seenpair++;
        }
    }
    assert_int_equal(seen1, 1);
    assert_int_equal(seen3, 1);
    assert_int_equal(seenpair, 1);
    /* values only */
    assert_int_equal(mm_linalg_geev(4, A, wr, wi, NULL, NULL), MM_OK);
}

/* ==== input errors ========================================================================== */

static void non_finite_input_should_be_a_bad_value(void **state)
{
    (void)state;
    double A[4] = {1, 2, 3, 4}, b[2] = {1, 2}, x[2], lam[2], s[2];
    mm_error err;
    A[2] = NAN;
    assert_int_equal(mm_linalg_solve(2, 1, A, b, x, NULL, &err), MM_EVALUE);
    assert_string_equal(err.param, "A");
    assert_non_null(strstr(err.msg, "(2,1)"));
    A[2] = 3;
    b[1] = INFINITY;
    assert_int_equal(mm_linalg_solve(2, 1, A, b, x, NULL, &err), MM_EVALUE);
    assert_string_equal(err.param, "b");
    b[1] = 2;
    double K[4] = {2, -1, -1, 2}, M[4] = {1, 0, 0, NAN};
    assert_int_equal(mm_linalg_sygv(2, K, M, lam, NULL, &err), MM_EVALUE);
    assert_string_equal(err.param, "M");
    A[0] = -INFINITY;
    assert_int_equal(mm_linalg_geev(2, A, x, lam, NULL, &err), MM_EVALUE);
    assert_string_equal(err.param, "A");
    assert_int_equal(mm_linalg_svdvals(2, 2, A, s, &err), MM_EVALUE);
    assert_int_equal(mm_linalg_lstsq(2, 2, 1, A, b, 0, x, NULL, NULL, NULL, &err), MM_EVALUE);
    double Kb[4] = {2, -1, NAN, 0}, Mb[4] = {1, 0, 1, 0};
    assert_int_equal(mm_linalg_sbgv_first(2, 1, 1, Kb, Mb, lam, NULL, &err), MM_EVALUE);
    assert_string_equal(err.param, "K");
    /* band padding (i + d >= n) is never read, so NaN there is fine */
    Kb[2] = 2; Kb[3] = NAN;
    assert_int_equal(mm_linalg_sbgv_first(2, 1, 1, Kb, Mb, lam, NULL, &err), MM_OK);
}

static void sizes_over_the_limits_should_be_out_of_range(void **state)
{
    (void)state;
    double A[4] = {1, 0, 0, 1}, x[2], lam[2];
    mm_error err;
    /* the size checks come before any entry is read or memory allocated */
    assert_int_equal(mm_linalg_solve(0, 1, A, A, x, NULL, &err), MM_ERANGE);
    assert_string_equal(err.param, "n");
    assert_int_equal(mm_linalg_solve(MM_LINALG_MAX_N + 1, 1, A, A, x, NULL, &err), MM_ERANGE);
    assert_string_equal(err.param, "n");
    assert_int_equal(mm_linalg_solve(2, 0, A, A, x, NULL, &err), MM_ERANGE);
    assert_string_equal(err.param, "nrhs");
    assert_int_equal(mm_linalg_sygv(MM_LINALG_MAX_N + 1, A, A, lam, NULL, &err), MM_ERANGE);
    assert_int_equal(mm_linalg_sygv_first(2, 3, A, A, lam, NULL, &err), MM_ERANGE);
    assert_string_equal(err.param, "nev");
    assert_int_equal(mm_linalg_sbgv_first(2, 2, 1, A, A, lam, NULL, &err), MM_ERANGE);
    assert_string_equal(err.param, "kd");
    assert_int_equal(mm_linalg_sbgv_first(MM_LINALG_MAX_BAND_N + 1, 1, 1, A, A, lam, NULL, &err),
                     MM_ERANGE);
    assert_string_equal(err.param, "n");
    assert_int_equal(mm_linalg_sbgv_first(1000, 1, MM_LINALG_MAX_NEV + 1, A, A, lam, NULL, &err),
                     MM_ERANGE);
    assert_string_equal(err.param, "nev");
    assert_int_equal(mm_linalg_lstsq(MM_LINALG_MAX_ROWS, 100, 1, A, A, 0, x, NULL, NULL, NULL, &err),
                     MM_ERANGE);
    assert_int_equal(mm_linalg_geev(0, A, x, lam, NULL, &err), MM_ERANGE);
    assert_int_equal(mm_linalg_cond2(0, 2, A, x, &err), MM_ERANGE);
    assert_string_equal(err.param, "m");
}

/* ==== threads ================================================================================ */

typedef struct thread_job {
    const double *K, *M;
    double lam[60], V[60 * 60];
    int rc;
} thread_job;

static void *eigen_thread(void *p)
{
    thread_job *j = p;
    for (int r = 0; r < 20 && j->rc == MM_OK; r++)
        j->rc = mm_linalg_sygv(60, j->K, j->M, j->lam, j->V, NULL);
    return NULL;
}

static void solvers_should_give_identical_answers_from_many_threads(void **state)
{
    (void)state;
    /* the server calls these from a thread pool: no shared state, so each
     * thread must reproduce the single-thread answer bit for bit */
    enum { NT = 8, N = 60 };
    double *K = malloc(N * N * sizeof *K), *M = malloc(N * N * sizeof *M);
    chain(N, 100, 1, 1, K, M);
    thread_job *ref = calloc(1, sizeof *ref), *jobs = calloc(NT, sizeof *jobs);
    ref->K = K; ref->M = M;
    assert_int_equal(mm_linalg_sygv(N, K, M, ref->lam, ref->V, NULL), MM_OK);
    pthread_t th[NT];
    for (int t = 0; t < NT; t++) {
        jobs[t].K = K; jobs[t].M = M;
        assert_int_equal(pthread_create(&th[t], NULL, eigen_thread, &jobs[t]), 0);
    }
    for (int t = 0; t < NT; t++) {
        pthread_join(th[t], NULL);
        assert_int_equal(jobs[t].rc, MM_OK);
        assert_memory_equal(jobs[t].lam, ref->lam, sizeof ref->lam);
        assert_memory_equal(jobs[t].V, ref->V, sizeof ref->V);
    }
    free(jobs); free(ref); free(M); free(K);
}

/* ==== double-double routines: every digit, with a bound ============================ */

static void dd_eigenvalues_of_a_chain_should_be_right_to_the_last_digit(void **state)
{
    (void)state;
    /* fixed-free chain of 12 (k = 100, m = 1): lambda_j = 400 sin^2((2j-1) pi / 50);
     * the closed form in double is within 2 ulps, so the dd result with its
     * bound must land there */
    enum { N = 12 };
    double K[N * N], M[N * N], lam[N], le[N], V[N * N];
    chain(N, 100, 1, 1, K, M);
    assert_int_equal(mm_linalg_sygv_dd(N, K, M, lam, le, V, NULL), MM_OK);
    for (int j = 0; j < N; j++) {
        double s = sin((2 * j + 1) * PI / (4 * N + 2)), want = 400 * s * s;
        check_rel(lam[j], want, 4 * EPS, "lambda_j of the chain");
        assert_true(le[j] <= 2 * EPS * lam[j]);        /* the bound is a rounding, no more */
        assert_true(fabs(lam[j] - want) <= le[j] + 3 * EPS * want);
    }
    /* modes M-orthonormal to rounding */
    for (int j = 0; j < N; j++)
        for (int l = 0; l <= j; l++) {
            double g = 0;
            for (int i = 0; i < N; i++)
                g += V[i * N + j] * V[i * N + l];
            check_abs(g, j == l, 8 * N * EPS, "V^T M V = I");
        }
}

static void dd_eigenvalues_should_be_right_where_lapack_loses_them(void **state)
{
    (void)state;
    /* graded chain: eig in double is 4.8e-7 off lambda_min; mpmath at 40
     * digits: 0.49999999937499999987, 1e9, 1999999998.5000000006 */
    double K[9] = {1e9, -1, 0, -1, 1e9, -999999999, 0, -999999999, 999999999}, lam[3], le[3];
    assert_int_equal(mm_linalg_sygv_dd(3, K, NULL, lam, le, NULL, NULL), MM_OK);
    check_rel(lam[0], 0.49999999937499999987, EPS, "lambda_min of the graded chain");
    assert_true(fabs(lam[0] - 0.49999999937499999987) <= le[0] + EPS * lam[0] / 2);
    check_rel(lam[2], 1999999998.5000000006, EPS, "lambda_max");
    /* M = diag(1e6, 1e-6): lambda_min = 9.99999999999e-7 exactly (decimal) */
    double K2[4] = {2, -1, -1, 1}, M2[4] = {1e6, 0, 0, 1e-6};
    assert_int_equal(mm_linalg_sygv_dd(2, K2, M2, lam, le, NULL, NULL), MM_OK);
    check_rel(lam[0], 9.99999999999e-7, EPS, "small lambda beside a large one");
    /* free chain: the rigid-body eigenvalue is 0 within its bound */
    double K3[4] = {100, -100, -100, 100};
    assert_int_equal(mm_linalg_sygv_dd(2, K3, NULL, lam, le, NULL, NULL), MM_OK);
    assert_true(fabs(lam[0]) <= le[0] && le[0] < 1e-25);
    check_rel(lam[1], 200, EPS, "the elastic mode");
}

static void dd_should_reject_what_the_lapack_routines_reject(void **state)
{
    (void)state;
    double K[4] = {2, -1, -1.5, 2}, M[4] = {1, 0, 0, -1}, lam[2], le[2];
    mm_error err;
    assert_int_equal(mm_linalg_sygv_dd(2, K, NULL, lam, le, NULL, &err), MM_EVALUE);
    assert_string_equal(err.param, "K");
    double K2[4] = {2, -1, -1, 2};
    assert_int_equal(mm_linalg_sygv_dd(2, K2, M, lam, le, NULL, &err), MM_ESINGULAR);
    assert_string_equal(err.param, "M");
    assert_int_equal(mm_linalg_sygv_dd(MM_LINALG_DD_MAX_N + 1, K2, NULL, lam, le, NULL, &err), MM_ERANGE);
}

static void dd_singular_values_and_solve_should_be_right_for_hilbert_12(void **state)
{
    (void)state;
    /* Hilbert-12 (as doubles, cond 1.68e16): mpmath svd at 80 digits */
    enum { N = 12 };
    double H[N * N], s[N], se[N], x[N], xe[N], b[N], r;
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++)
            H[i * N + j] = 1.0 / (i + j + 1);
    assert_int_equal(mm_linalg_svdvals_dd(N, N, H, s, se, NULL), MM_OK);
    check_rel(s[0], 1.7953720595619973, EPS, "sigma_max of Hilbert-12");
    check_rel(s[N - 1], 1.0674897547441723e-16, 2 * EPS, "sigma_min of Hilbert-12, to its last digit");
    assert_true(fabs(s[N - 1] - 1.0674897547441723e-16) <= se[N - 1] + EPS * s[N - 1]);
    check_rel(s[0] / s[N - 1], 16818635041535031.93, 4 * EPS, "cond_2 of Hilbert-12 (LAPACK in double: 4 % off)");
    /* H x = H 1 has x = 1 exactly only if H 1 is exact: take b = H e_1, x = e_1 */
    for (int i = 0; i < N; i++)
        b[i] = H[i * N];
    assert_int_equal(mm_linalg_solve_dd(N, H, b, s[N - 1] - se[N - 1], x, xe, &r, NULL), MM_OK);
    for (int i = 0; i < N; i++) {
        check_abs(x[i], i == 0, xe[i], "x within its bound");
        assert_true(xe[i] < 1e-12);                      /* 32 digits less cond 1.7e16: ~1e-16 */
    }
    /* singular: no bound of sigma_min above 0 */
    double S[9] = {1, 2, 3, 4, 5, 6, 7, 8, 9}, s3[3], se3[3];
    assert_int_equal(mm_linalg_svdvals_dd(3, 3, S, s3, se3, NULL), MM_OK);
    assert_true(s3[2] - se3[2] <= 0);
    assert_int_equal(mm_linalg_solve_dd(3, S, b, s3[2] - se3[2], x, xe, NULL, NULL), MM_ESINGULAR);
}

static void one_symmetry_rule_should_serve_every_module(void **state)
{
    (void)state;
    double A[4] = {1, 2, 2 + 1e-13, 5}, B[4] = {1, 2, 2 + 1e-11, 5};
    int i = -1, j = -1;
    assert_true(mm_linalg_is_symmetric(2, A, &i, &j));           /* 2e-14 of max |a|: rounding */
    assert_false(mm_linalg_is_symmetric(2, B, &i, &j));          /* 2e-12: a typing error */
    assert_int_equal(i, 0);
    assert_int_equal(j, 1);
    double K[4] = {2, -1, -1 + 1e-11, 2}, lam[2];
    mm_error err;
    assert_int_equal(mm_linalg_sygv(2, K, A, lam, NULL, &err), MM_EVALUE);   /* the same rule in sygv */
    assert_string_equal(err.param, "K");
}

typedef struct solve_job {
    const double *A, *B;
    double X[80 * 80];
    int rc;
} solve_job;

static void *solve_thread(void *p)
{
    solve_job *j = p;
    for (int r = 0; r < 20 && j->rc == MM_OK; r++)
        j->rc = mm_linalg_solve(80, 80, j->A, j->B, j->X, NULL, NULL);
    return NULL;
}

static void blas3_from_many_threads_should_give_identical_answers(void **state)
{
    (void)state;
    /* LU of an 80 x 80 matrix with 80 right-hand sides goes through the
     * level-3 BLAS (dgemm, dtrsm), whose scratch buffers Debian's serial
     * OpenBLAS shares between threads without a lock: mm_linalg serialises
     * the calls.  Eight threads must reproduce the single-thread bits. */
    enum { NT = 8, N = 80 };
    double *A = malloc(N * N * sizeof *A), *B = malloc(N * N * sizeof *B);
    for (int i = 0; i < N * N; i++) {
        A[i] = sin(1.0 + i) + (i % (N + 1) == 0 ? N : 0);
        B[i] = cos(3.0 * i);
    }
    solve_job *ref = calloc(1, sizeof *ref), *jobs = calloc(NT, sizeof *jobs);
    assert_int_equal(mm_linalg_solve(N, N, A, B, ref->X, NULL, NULL), MM_OK);
    pthread_t th[NT];
    for (int t = 0; t < NT; t++) {
        jobs[t].A = A, jobs[t].B = B;
        assert_int_equal(pthread_create(&th[t], NULL, solve_thread, &jobs[t]), 0);
    }
    for (int t = 0; t < NT; t++) {
        pthread_join(th[t], NULL);
        assert_int_equal(jobs[t].rc, MM_OK);
        assert_memory_equal(jobs[t].X, ref->X, sizeof ref->X);
    }
    free(jobs); free(ref); free(B); free(A);
}

static void printed_modes_and_residuals_should_be_checked_to_their_rounding(void **state)
{
    (void)state;
    enum { N = 8 };
    double K[N * N], M[N * N], lam[N], le[N], V[N * N], r[N], mag[N], x[N], b[N];
    chain(N, 100, 2, 1, K, M);
    assert_int_equal(mm_linalg_sygv_dd(N, K, M, lam, le, V, NULL), MM_OK);
    double res, orth;
    mm_linalg_sygv_rounding(N, K, M, lam, le, V, &res, &orth);
    assert_true(res <= 1 && orth <= 1);              /* modes right to their last digit */
    V[3] *= 1 + 1e-12;                               /* one component off in its 12th digit */
    mm_linalg_sygv_rounding(N, K, M, lam, le, V, &res, &orth);
    assert_true(res > 10 && orth > 10);
    /* b = K x for integer x: the residual is exactly 0, and mag |K||x| + |b| */
    for (int i = 0; i < N; i++)
        x[i] = i + 1;
    for (int i = 0; i < N; i++) {
        b[i] = 0;
        for (int j = 0; j < N; j++)
            b[i] += K[i * N + j] * x[j];
    }
    mm_linalg_residual_dd(N, K, x, b, r, mag);
    for (int i = 0; i < N; i++)
        check_abs(r[i], 0, 0, "exact residual");
    check_rel(mm_linalg_norm2(2, (double[]){3e200, 4e200}), 5e200, EPS, "no overflow in the squares");
}

/* Selected eigenpairs of a symmetric tridiagonal matrix (mm_linalg_stev,
 * the Lanczos step's small problem): the second-difference matrix
 * tridiag(-1, 2, -1) of order n has eigenvalues 2 - 2 cos(j pi / (n + 1))
 * and eigenvectors sin(i j pi / (n + 1)).  The top five of n = 60 to 8 eps
 * of the largest, 4 (bisection to full accuracy), their
 * vectors to 1e-12 (unit-norm, up to sign: inverse iteration on separated
 * eigenvalues), and bad indices refused. */
static void tridiagonal_selected_eigenpairs_should_match_the_second_difference(void **state)
{
    (void)state;
    enum { N = 60, K = 5 };
    double d[N], e[N - 1], lam[K], Z[N * K];
    for (int i = 0; i < N; i++)
        d[i] = 2;
    for (int i = 0; i < N - 1; i++)
        e[i] = -1;
    mm_error err;
    assert_int_equal(mm_linalg_stev(N, d, e, N - K + 1, N, lam, Z, &err), MM_OK);
    for (int k = 0; k < K; k++) {
        int j = N - K + 1 + k;
        check_abs(lam[k], 2 - 2 * cos(j * PI / (N + 1)), 8 * DBL_EPSILON * 4, "tridiagonal eigenvalue");
        double nn = 0, dot = 0;
        for (int i = 0; i < N; i++) {
            double s = sin((i + 1) * j * PI / (N + 1));
            nn += s * s;
            dot += s * Z[k * N + i];
        }
        check_abs(fabs(dot) / sqrt(nn), 1, 1e-12, "tridiagonal eigenvector");
    }
    assert_int_equal(mm_linalg_stev(N, d, e, 3, 2, lam, Z, &err), MM_ERANGE);
    assert_int_equal(mm_linalg_stev(N, d, e, 1, N + 1, lam, Z, &err), MM_ERANGE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(solve_should_reproduce_the_book_example_exactly),
        cmocka_unit_test(solve_should_handle_several_right_hand_sides_in_place),
        cmocka_unit_test(hilbert_10_should_be_warned_with_small_residual_and_bounded_error),
        cmocka_unit_test(hilbert_12_should_be_warned_with_a_small_residual),
        cmocka_unit_test(singular_matrices_should_give_no_solution),
        cmocka_unit_test(cond2_of_hilbert_should_match_published_values),
        cmocka_unit_test(lstsq_should_match_the_normal_equations_by_hand),
        cmocka_unit_test(lstsq_should_return_minimum_norm_for_rank_deficient_a),
        cmocka_unit_test(num_eigen_default_should_give_the_chain_frequencies),
        cmocka_unit_test(chains_should_match_closed_form_frequencies_and_shapes),
        cmocka_unit_test(selective_and_banded_should_match_closed_form_first_modes),
        cmocka_unit_test(banded_consistent_mass_bar_should_match_discrete_closed_form),
        cmocka_unit_test(banded_should_separate_repeated_and_rigid_body_modes),
        cmocka_unit_test(banded_free_free_beam_should_give_rigid_and_elastic_modes),
        cmocka_unit_test(wider_band_should_agree_with_dense),
        cmocka_unit_test(mass_matrix_not_positive_definite_should_be_singular),
        cmocka_unit_test(nonsymmetric_stiffness_should_be_a_bad_value),
        cmocka_unit_test(geev_should_find_real_and_complex_eigenpairs),
        cmocka_unit_test(non_finite_input_should_be_a_bad_value),
        cmocka_unit_test(sizes_over_the_limits_should_be_out_of_range),
        cmocka_unit_test(solvers_should_give_identical_answers_from_many_threads),
        cmocka_unit_test(blas3_from_many_threads_should_give_identical_answers),
        cmocka_unit_test(dd_eigenvalues_of_a_chain_should_be_right_to_the_last_digit),
        cmocka_unit_test(dd_eigenvalues_should_be_right_where_lapack_loses_them),
        cmocka_unit_test(dd_should_reject_what_the_lapack_routines_reject),
        cmocka_unit_test(dd_singular_values_and_solve_should_be_right_for_hilbert_12),
        cmocka_unit_test(one_symmetry_rule_should_serve_every_module),
        cmocka_unit_test(printed_modes_and_residuals_should_be_checked_to_their_rounding),
        cmocka_unit_test(tridiagonal_selected_eigenpairs_should_match_the_second_difference),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
