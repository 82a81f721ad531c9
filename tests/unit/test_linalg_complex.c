/* test_linalg_complex.c — mm_linalg_solve_complex (vibration chapter:
 * steady amplitudes) against Cramer's rule in C99 complex arithmetic for a
 * 2 x 2 system, against the residual of a 4 x 4 one, and a singular
 * system refused. */
#include "mm_test.h"

#include <complex.h>
#include <float.h>

#include "mm_complex.h"
#include "mm_linalg.h"

#define EPS DBL_EPSILON

/* A damped 2-DOF dynamic stiffness (the absorber's), F = (3, 0). */
static void two_by_two_should_be_cramers_rule(void **state)
{
    (void)state;
    double Are[4] = {110 - 64, -10, -10, 10 - 6.4}, Aim[4] = {2.4, -2.4, -2.4, 2.4}, bre[2] = {3, 0}, bim[2] = {0, 0};
    double xr[2], xi[2];
    mm_linalg_solve_info info;
    mm_error err;
    assert_int_equal(mm_linalg_solve_complex(2, Are, Aim, bre, bim, xr, xi, &info, &err), MM_OK);
    double complex a = mm_cmplx(Are[0], Aim[0]), b = mm_cmplx(Are[1], Aim[1]), c = mm_cmplx(Are[2], Aim[2]);
    double complex d = mm_cmplx(Are[3], Aim[3]), det = a * d - b * c, x1 = 3 * d / det, x2 = -3 * c / det;
    /* both to rounding: the forward bound eps |x| / rcond (measured: 0.05 of it) */
    double tol = EPS * fmax(cabs(x1), cabs(x2)) / info.rcond;
    check_abs(cabs(mm_cmplx(xr[0], xi[0]) - x1), 0, tol, "x1 vs Cramer");
    check_abs(cabs(mm_cmplx(xr[1], xi[1]) - x2), 0, tol, "x2 vs Cramer");
}

static void four_by_four_should_leave_a_small_residual(void **state)
{
    (void)state;
    enum { N = 4 };
    double Are[N * N], Aim[N * N], bre[N], bim[N], xr[N], xi[N], big = 0, worst = 0;
    for (int i = 0; i < N; i++) {
        for (int j = 0; j < N; j++) {
            Are[N * i + j] = (i == j ? 5 : 0) + sin(1.0 + i + 2 * j);
            Aim[N * i + j] = cos(3.0 * i - j);
        }
        bre[i] = i + 1, bim[i] = 1 - i;
    }
    mm_error err;
    assert_int_equal(mm_linalg_solve_complex(N, Are, Aim, bre, bim, xr, xi, NULL, &err), MM_OK);
    for (int i = 0; i < N; i++) {
        double complex r = -mm_cmplx(bre[i], bim[i]);
        for (int j = 0; j < N; j++) {
            double complex t = mm_cmplx(Are[N * i + j], Aim[N * i + j]) * mm_cmplx(xr[j], xi[j]);
            r += t;
            big = fmax(big, cabs(t));
        }
        worst = fmax(worst, cabs(r));
    }
    /* backward stable: the residual a few eps of the terms summed (measured 0.6 eps) */
    check_abs(worst, 0, 4 * EPS * big, "|A x - b|");
}

static void singular_should_be_refused(void **state)
{
    (void)state;
    double Are[4] = {1, 2, 2, 4}, Aim[4] = {0, 0, 0, 0}, b[2] = {1, 1}, z[2] = {0, 0}, xr[2], xi[2];
    mm_error err;
    assert_int_equal(mm_linalg_solve_complex(2, Are, Aim, b, z, xr, xi, NULL, &err), MM_ESINGULAR);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(two_by_two_should_be_cramers_rule),
        cmocka_unit_test(four_by_four_should_leave_a_small_residual),
        cmocka_unit_test(singular_should_be_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
