/* test_equil.c — the equilibrium solver and its rank test, against
 * systems whose solutions and null spaces are known by construction. */
#include "mm_test.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "mm_equil.h"

/* ---- small helpers --------------------------------------------------------------- */

static unsigned long long seed = 88172645463325252ULL;

static double urand(void)
{
    seed ^= seed << 13;
    seed ^= seed >> 7;
    seed ^= seed << 17;
    return (double)(seed >> 11) / 9007199254740992.0;
}

/* max_i |(A v)_i| / (max|A| max|v|) and the same for u^T A */
static double null_defect(int m, int n, const double *A, const double *v)
{
    double worst = 0, amax = 0, vmax = 0;
    for (int k = 0; k < m * n; k++)
        amax = fmax(amax, fabs(A[k]));
    for (int j = 0; j < n; j++)
        vmax = fmax(vmax, fabs(v[j]));
    for (int i = 0; i < m; i++) {
        double s = 0;
        for (int j = 0; j < n; j++)
            s += A[i * n + j] * v[j];
        worst = fmax(worst, fabs(s));
    }
    return worst / (amax * vmax);
}

static double left_null_defect(int m, int n, const double *A, const double *u)
{
    double *At = malloc((size_t)m * n * sizeof *At);
    for (int i = 0; i < m; i++)
        for (int j = 0; j < n; j++)
            At[j * m + i] = A[i * n + j];
    double d = null_defect(n, m, At, u);
    free(At);
    return d;
}

/* ---- determinate systems ------------------------------------------------------------ */

static void a_3x3_system_should_be_solved_to_its_exact_solution(void **state)
{
    (void)state;
    /* x = (1, -2, 3) exactly; entries small integers so b is exact */
    const double A[9] = {2, 1, 0, 1, 3, 1, 0, 1, 4}, x0[3] = {1, -2, 3};
    double b[3], x[3];
    for (int i = 0; i < 3; i++)
        b[i] = A[3 * i] * x0[0] + A[3 * i + 1] * x0[1] + A[3 * i + 2] * x0[2];
    mm_equil_result r;
    assert_int_equal(mm_equil_solve(3, 3, A, b, x, NULL, NULL, &r, NULL), MM_OK);
    assert_int_equal(r.kind, MM_EQUIL_DETERMINATE);
    assert_int_equal(r.rank, 3);
    /* cond_1 of this SPD matrix is about 3.5: a few eps of error at most */
    for (int j = 0; j < 3; j++)
        check_abs(x[j], x0[j], 8 * DBL_EPSILON * 3, "x of a well-conditioned 3x3");
    check_abs(r.residual, 0, 4 * DBL_EPSILON * r.scale, "residual at round-off of the terms");
    assert_true(r.rcond > 0.1 && r.rcond <= 1);
}

static void a_sparse_banded_system_of_order_300_should_be_solved_to_round_off(void **state)
{
    (void)state;
    /* a random sparse matrix with 4 entries a column near the diagonal and a
     * dominant diagonal, columns given in a scrambled order: the ordering
     * and the sparse elimination must still give x to round-off */
    enum { N = 300 };
    double *A = calloc(N * N, sizeof *A), *b = calloc(N, sizeof *b), *x = calloc(N, sizeof *x);
    double x0[N];
    int perm[N];
    for (int j = 0; j < N; j++)
        perm[j] = j;
    for (int j = N - 1; j > 0; j--) {
        int k = (int)(urand() * (j + 1)), t = perm[j];
        perm[j] = perm[k], perm[k] = t;
    }
    for (int j = 0; j < N; j++) {
        int c = perm[j];
        A[j * N + c] = 4 + urand();
        for (int t = 0; t < 3; t++) {
            int i = j + (int)(urand() * 7) - 3;
            if (i >= 0 && i < N && i != j)
                A[i * N + c] += urand() - 0.5;
        }
        x0[j] = urand() - 0.5;
    }
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++)
            b[i] += A[i * N + j] * x0[j];
    mm_equil_result r;
    assert_int_equal(mm_equil_solve(N, N, A, b, x, NULL, NULL, &r, NULL), MM_OK);
    double worst = 0;
    for (int j = 0; j < N; j++)
        worst = fmax(worst, fabs(x[j] - x0[j]));
    /* diagonally dominant: cond ~ 10, so |dx| ~ 10 eps; 100 eps leaves room */
    check_abs(worst, 0, 100 * DBL_EPSILON, "x of a sparse diagonally dominant system");
    check_abs(r.residual, 0, 8 * DBL_EPSILON * r.scale, "residual at round-off");
    free(A), free(b), free(x);
}

static void the_condition_estimate_should_follow_an_ill_conditioned_2x2(void **state)
{
    (void)state;
    /* A = [1 1; 1 1+d]: cond_1 = ||A||_1 ||A^-1||_1 = (2+d)^2 / d exactly,
     * and equilibration leaves it alone (every entry ~ 1) */
    double d = 1e-8, A[4] = {1, 1, 1, 1 + d}, b[2] = {2, 2 + d}, x[2];
    mm_equil_result r;
    assert_int_equal(mm_equil_solve(2, 2, A, b, x, NULL, NULL, &r, NULL), MM_OK);
    /* the estimator is exact for n = 2 up to the rounding of 1 + d */
    check_rel(1 / r.rcond, (2 + d) * (2 + d) / d, 1e-7, "cond_1 of [1 1; 1 1+d]");
    /* x = (1, 1): error about cond * eps = 4e8 * 1.1e-16 = 4e-8 */
    check_abs(x[0], 1, 1e-7, "x1 with cond 4e8");
    check_abs(x[1], 1, 1e-7, "x2 with cond 4e8");
}

static void scaling_rows_and_columns_should_not_change_the_decisions(void **state)
{
    (void)state;
    /* equations in N and in N mm (moments), unknowns in N and kN: the same
     * 3x3 with rows and columns scaled by 1e6 and 1e-6 is still determinate */
    const double A0[9] = {1, 0, 1, 0, 1, 1, 0, 0, 2};
    double A[9], b[3] = {1e6, 2, 3e-6}, x[3];
    const double rs[3] = {1e6, 1, 1e-6}, cs[3] = {1, 1e-6, 1e6};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            A[3 * i + j] = rs[i] * A0[3 * i + j] * cs[j];
    mm_equil_result r;
    assert_int_equal(mm_equil_solve(3, 3, A, b, x, NULL, NULL, &r, NULL), MM_OK);
    assert_true(r.rcond > 0.05);
    /* unscaled: y = (1, 2, 3) solves A0 y = (1+3, 2+3, 6)/... check the scaled one directly */
    double res, sc;
    mm_equil_residual(3, 3, A, b, x, &res, &sc);
    check_abs(res, 0, 8 * DBL_EPSILON * sc, "residual of the scaled system");
}

/* ---- the rank test ---------------------------------------------------------------- */

static void a_square_singular_system_should_be_a_critical_form_with_both_null_vectors(void **state)
{
    (void)state;
    /* rank 3 of 4: the last row is the sum of the first two, the last
     * column the difference of the first and third */
    double A[16] = {1, 2, 0, 0, 0, 1, 3, 0, 2, 0, 1, 1, 1, 3, 3, 0};
    for (int i = 0; i < 4; i++)
        A[4 * i + 3] = A[4 * i] - A[4 * i + 2];
    double b[4] = {1, 1, 1, 1}, x[4], u[4], s[4];
    mm_equil_result r;
    mm_error err;
    assert_int_equal(mm_equil_solve(4, 4, A, b, x, u, s, &r, &err), MM_ESINGULAR);
    assert_int_equal(r.kind, MM_EQUIL_CRITICAL);
    assert_int_equal(r.rank, 3);
    assert_int_equal(r.n_mech, 1);
    assert_int_equal(r.n_self, 1);
    /* the null vectors to round-off of the entries (QR is backward stable) */
    check_abs(null_defect(4, 4, A, s), 0, 32 * DBL_EPSILON, "A s = 0 (self-stress)");
    check_abs(left_null_defect(4, 4, A, u), 0, 32 * DBL_EPSILON, "u^T A = 0 (mechanism)");
    /* normalised: largest entry +1 */
    double smax = 0, umax = 0;
    for (int k = 0; k < 4; k++)
        smax = fmax(smax, s[k]), umax = fmax(umax, u[k]);
    check_abs(smax, 1, 0, "self-stress scaled to a largest entry of 1");
    check_abs(umax, 1, 0, "mechanism scaled to a largest entry of 1");
    assert_non_null(strstr(err.msg, "mechanism and statically indeterminate"));
}

static void more_equations_than_unknowns_should_be_a_mechanism(void **state)
{
    (void)state;
    /* 3 equations, 2 independent unknowns: one motion left free */
    const double A[6] = {1, 0, 0, 1, 1, 1};
    double b[3] = {0, 0, 1}, x[2], u[3], s[2];
    mm_equil_result r;
    assert_int_equal(mm_equil_solve(3, 2, A, b, x, u, s, &r, NULL), MM_ESINGULAR);
    assert_int_equal(r.kind, MM_EQUIL_MECHANISM);
    assert_int_equal(r.n_mech, 1);
    assert_int_equal(r.n_self, 0);
    /* u = (-1, -1, 1) up to sign: all three entries tie for the largest */
    check_abs(fabs(u[0]), 1, 4 * DBL_EPSILON, "mechanism |u1| = 1");
    check_abs(u[1], u[0], 4 * DBL_EPSILON, "mechanism u2 = u1");
    check_abs(u[2], -u[0], 4 * DBL_EPSILON, "mechanism u3 = -u1");
    check_abs(s[0], 0, 0, "no self-stress");
}

static void more_unknowns_than_equations_should_be_indeterminate(void **state)
{
    (void)state;
    /* two bars in parallel holding one load: F1 + F2 = P */
    const double A[2] = {1, 1};
    double b[1] = {10}, x[2], u[1], s[2];
    mm_equil_result r;
    assert_int_equal(mm_equil_solve(1, 2, A, b, x, u, s, &r, NULL), MM_ESINGULAR);
    assert_int_equal(r.kind, MM_EQUIL_INDETERMINATE);
    assert_int_equal(r.n_self, 1);
    check_abs(fabs(s[0]), 1, 4 * DBL_EPSILON, "self-stress: one bar pulls");
    check_abs(s[0] + s[1], 0, 4 * DBL_EPSILON, "the other pushes as much");
}

static void a_zero_column_should_be_an_unknown_in_no_equation(void **state)
{
    (void)state;
    const double A[4] = {1, 0, 2, 0};
    double b[2] = {1, 2}, x[2], u[2], s[2];
    mm_equil_result r;
    assert_int_equal(mm_equil_solve(2, 2, A, b, x, u, s, &r, NULL), MM_ESINGULAR);
    assert_int_equal(r.rank, 1);
    check_abs(s[1], 1, 0, "the idle unknown is the self-stress");
    check_abs(s[0], 0, 0, "alone");
}

static void an_exactly_singular_large_sparse_system_should_be_found_singular(void **state)
{
    (void)state;
    /* a chain of springs with no support: the 1D truss of N bars and N+1
     * joints with one support removed is a rigid-body mechanism (slides) */
    enum { N = 60 };
    double *A = calloc((N + 1) * (N + 1), sizeof *A), b[N + 1] = {0}, x[N + 1], u[N + 1];
    for (int e = 0; e < N; e++) {            /* bar e between joints e and e+1 */
        A[e * (N + 1) + e] = 1;
        A[(e + 1) * (N + 1) + e] = -1;
    }
    A[0 * (N + 1) + N] = 0;                  /* the support column, but placed nowhere */
    b[N] = 1;
    mm_equil_result r;
    assert_int_equal(mm_equil_solve(N + 1, N + 1, A, b, x, u, NULL, &r, NULL), MM_ESINGULAR);
    /* the motion: every joint the same displacement */
    for (int i = 0; i <= N; i++)
        check_abs(u[i], 1, 64 * DBL_EPSILON, "the whole chain slides");
    free(A);
}

static void bad_input_should_be_refused_before_any_work(void **state)
{
    (void)state;
    double A[4] = {1, 0, 0, NAN}, b[2] = {1, 1}, x[2];
    mm_error err;
    assert_int_equal(mm_equil_solve(2, 2, A, b, x, NULL, NULL, NULL, &err), MM_EVALUE);
    assert_string_equal(err.param, "A");
    A[3] = 1;
    b[1] = INFINITY;
    assert_int_equal(mm_equil_solve(2, 2, A, b, x, NULL, NULL, NULL, &err), MM_EVALUE);
    assert_string_equal(err.param, "b");
    assert_int_equal(mm_equil_solve(0, 2, A, b, x, NULL, NULL, NULL, &err), MM_ERANGE);
    assert_int_equal(mm_equil_solve(MM_EQUIL_MAX_N + 1, 2, A, b, x, NULL, NULL, NULL, &err), MM_ERANGE);
    assert_string_equal(mm_equil_kind_name(MM_EQUIL_INDETERMINATE), "statically indeterminate");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_3x3_system_should_be_solved_to_its_exact_solution),
        cmocka_unit_test(a_sparse_banded_system_of_order_300_should_be_solved_to_round_off),
        cmocka_unit_test(the_condition_estimate_should_follow_an_ill_conditioned_2x2),
        cmocka_unit_test(scaling_rows_and_columns_should_not_change_the_decisions),
        cmocka_unit_test(a_square_singular_system_should_be_a_critical_form_with_both_null_vectors),
        cmocka_unit_test(more_equations_than_unknowns_should_be_a_mechanism),
        cmocka_unit_test(more_unknowns_than_equations_should_be_indeterminate),
        cmocka_unit_test(a_zero_column_should_be_an_unknown_in_no_equation),
        cmocka_unit_test(an_exactly_singular_large_sparse_system_should_be_found_singular),
        cmocka_unit_test(bad_input_should_be_refused_before_any_work),
    };
    return cmocka_run_group_tests_name("equil", tests, NULL, NULL);
}
