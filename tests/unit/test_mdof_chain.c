/* test_mdof_chain.c — the chain of n equal masses of mm_mdof (vibration
 * chapter): the closed-form angles theta_j against the eigenvalues and
 * eigenvectors LAPACK finds in the assembled matrices (dense and banded),
 * for both ends, and the matrices written out by hand for n = 3; the static
 * residual of modal truncation against the modes left out; the chain's
 * modes dense and banded against each other. */
#include "mm_test.h"

#include <float.h>
#include <stdlib.h>

#include "mm_linalg.h"
#include "mm_mdof.h"

#define EPS DBL_EPSILON

/* n = 3, m = 2, k = 5, written out: M = 2 I, K = [10 -5 0; -5 10 -5; 0 -5 10 or 5]. */
static void matrices_should_be_the_chain_written_out(void **state)
{
    (void)state;
    for (int fe = 0; fe < 2; fe++) {
        double M[9], K[9], Mb[6], Kb[6];
        for (int i = 0; i < 9; i++)
            M[i] = K[i] = 99;                     /* every entry must be written */
        double Kx[9] = {10, -5, 0, -5, 10, -5, 0, -5, fe ? 5 : 10};
        mm_mdof_chain_matrices(3, 2, 5, fe, M, K);
        mm_mdof_chain_band(3, 2, 5, fe, Mb, Kb);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                assert_true(K[3 * i + j] == Kx[3 * i + j]);
                assert_true(M[3 * i + j] == (i == j ? 2 : 0));
            }
        double Kbx[6] = {10, -5, 10, -5, fe ? 5 : 10, 0}, Mbx[6] = {2, 0, 2, 0, 2, 0};
        for (int i = 0; i < 6; i++) {
            assert_true(Kb[i] == Kbx[i]);
            assert_true(Mb[i] == Mbx[i]);
        }
    }
}

/* omega_j = 2 sqrt(k/m) sin(theta_j) against LAPACK's dsygvd on the
 * assembled pencil: eigenvalues good to a few eps lambda_max (a symmetric
 * solver's backward error); modes the sampled sines sin(2 (i + 1) theta_j)
 * to a few eps lambda_max / gap (gap: to the nearest other eigenvalue). */
static void theta_should_give_the_eigenpairs_of_the_assembled_chain(void **state)
{
    (void)state;
    enum { N = 25 };
    double m = 3, k = 75, w0 = 2 * sqrt(k / m), *M = malloc(N * N * sizeof *M), *K = malloc(N * N * sizeof *K);
    double *V = malloc(N * N * sizeof *V), lam[N];
    mm_error err;
    for (int fe = 0; fe < 2; fe++) {
        mm_mdof_chain_matrices(N, m, k, fe, M, K);
        assert_int_equal(mm_linalg_sygv(N, K, M, lam, V, &err), MM_OK);
        for (int j = 0; j < N; j++) {
            double th = mm_mdof_chain_theta(N, j, fe), ex = w0 * sin(th);
            /* measured: 1.9 eps lambda_max */
            check_abs(lam[j], ex * ex, 8 * EPS * w0 * w0, "lambda_j against the closed form");
            double s2 = 0, dot = 0, worst = 0, big = 0, gap = INFINITY;
            for (int i = 0; i < N; i++) {
                double sn = sin(2 * (i + 1) * th);
                s2 += sn * sn, dot += sn * V[i * N + j];
            }
            for (int i = 0; i < N; i++) {   /* the sine normalised to phi^T M phi = 1, signed as V */
                double sn = sin(2 * (i + 1) * th) / sqrt(m * s2) * (dot < 0 ? -1 : 1);
                big = fmax(big, fabs(sn));
                worst = fmax(worst, fabs(V[i * N + j] - sn));
            }
            for (int d = -1; d <= 1; d += 2)
                if (j + d >= 0 && j + d < N) {
                    double o = w0 * sin(mm_mdof_chain_theta(N, j + d, fe));
                    gap = fmin(gap, fabs(o * o - ex * ex));
                }
            /* measured: 2.2 eps lambda_max / gap |phi| at worst */
            check_abs(worst, 0, 8 * EPS * w0 * w0 / gap * big, "mode j against the sampled sine");
        }
    }
    free(M), free(K), free(V);
}

/* The banded pencil gives the same lowest eigenvalues (dsbgvx): the band
 * storage holds the same chain. */
static void band_should_give_the_same_lowest_frequencies(void **state)
{
    (void)state;
    enum { N = 200, NEV = 6 };
    double Mb[2 * N], Kb[2 * N], lam[NEV], m = 0.5, k = 20, w0 = 2 * sqrt(k / m);
    mm_error err;
    for (int fe = 0; fe < 2; fe++) {
        mm_mdof_chain_band(N, m, k, fe, Mb, Kb);
        assert_int_equal(mm_linalg_sbgv_first(N, 1, NEV, Kb, Mb, lam, NULL, &err), MM_OK);
        for (int j = 0; j < NEV; j++) {
            double ex = w0 * sin(mm_mdof_chain_theta(N, j, fe));
            check_abs(lam[j], ex * ex, 2 * EPS * w0 * w0, "lowest lambda_j, banded (measured 0.17 eps lambda_max)");
        }
    }
}

/* K^-1 = sum_j phi_j phi_j^T / omega_j^2 over every mode, so the static
 * deflection the first m modes miss is the sum over the modes left out,
 * sum_{j >= m} phi_j phi_j^T F / omega_j^2: a second formula that uses no
 * solve; and nothing is missed when m = n. */
static void static_residual_should_be_what_the_left_out_modes_carry(void **state)
{
    (void)state;
    enum { N = 12, P = 7 };
    double M[N * N], K[N * N], Phi[N * N], w[N], r[N], Fp = 3.5;
    mm_error err;
    for (int fe = 0; fe < 2; fe++) {
        mm_mdof_chain_matrices(N, 2, 400, fe, M, K);
        mm_mdof_system s = {N, M, NULL, K};
        assert_int_equal(mm_mdof_modes(&s, N, w, Phi, NULL, &err), MM_OK);
        double big = 0, worst = 0;
        for (int m = 1; m <= N; m++) {
            assert_int_equal(mm_mdof_static_residual(N, m, K, w, Phi, P, Fp, r, &err), MM_OK);
            for (int i = 0; i < N; i++) {
                double left = 0;
                for (int j = m; j < N; j++)
                    left += Phi[i * N + j] * Phi[P * N + j] * Fp / (w[j] * w[j]);
                worst = fmax(worst, fabs(r[i] - left));
                big = fmax(big, fabs(r[i]));
            }
        }
        /* rounding of the solve and of the modes, relative to the largest
         * residual: eps times the condition number of K, (omega_n/omega_1)^2
         * (measured 1.7 and 6.2 times that) */
        double cond = (w[N - 1] / w[0]) * (w[N - 1] / w[0]);
        check_abs(worst / big, 0, 16 * EPS * cond, "r against the modes left out, relative");
    }
}

/* mm_mdof_chain_modes, both ways: every mode dense, the lowest banded, each
 * against the closed form (eps lambda_max), and the banded modes against
 * the dense ones (to a few eps lambda_max / gap, up to sign). */
static void chain_modes_should_agree_dense_and_banded(void **state)
{
    (void)state;
    enum { N = 30, NEV = 5 };
    double m = 1.5, k = 60, w0 = 2 * sqrt(k / m), lam[N], lb[NEV], *V = malloc(N * N * sizeof *V), Vb[N * NEV];
    mm_error err;
    for (int fe = 0; fe < 2; fe++) {
        assert_int_equal(mm_mdof_chain_modes(N, m, k, fe, 0, lam, V, &err), MM_OK);
        assert_int_equal(mm_mdof_chain_modes(N, m, k, fe, NEV, lb, Vb, &err), MM_OK);
        for (int j = 0; j < N; j++) {
            double ex = w0 * sin(mm_mdof_chain_theta(N, j, fe));
            check_abs(lam[j], ex * ex, 8 * EPS * w0 * w0, "dense lambda_j (eps lambda_max)");
            if (j >= NEV)
                continue;
            check_abs(lb[j], ex * ex, 8 * EPS * w0 * w0, "banded lambda_j (eps lambda_max)");
            double o = w0 * sin(mm_mdof_chain_theta(N, j + 1, fe)), gap = o * o - ex * ex, sg = 0, worst = 0;
            for (int i = 0; i < N; i++)
                sg += V[i * N + j] * Vb[i * NEV + j];
            for (int i = 0; i < N; i++)
                worst = fmax(worst, fabs(Vb[i * NEV + j] - (sg < 0 ? -1 : 1) * V[i * N + j]));
            check_abs(worst, 0, 16 * EPS * w0 * w0 / gap, "banded mode j against the dense one");
        }
    }
    free(V);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(matrices_should_be_the_chain_written_out),
        cmocka_unit_test(theta_should_give_the_eigenpairs_of_the_assembled_chain),
        cmocka_unit_test(band_should_give_the_same_lowest_frequencies),
        cmocka_unit_test(static_residual_should_be_what_the_left_out_modes_carry),
        cmocka_unit_test(chain_modes_should_agree_dense_and_banded),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
