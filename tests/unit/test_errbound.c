/* test_errbound.c — mm_errbound against closed forms: the true deviation of
 * a quotient, a root or a solution worked out by hand must lie within the
 * bound, and the bound within a few percent of it. */
#include "mm_test.h"

#include <float.h>

#include "mm_errbound.h"

#define U (DBL_EPSILON / 2)

/* kappa = 4 / 1 with both singular values off by a = 1e-10: the worst
 * exact quotient is (4 + a) / (1 - a) = 4 + 5a / (1 - a); the bound is
 * first order, 4 (a / 4 + a / (1 - a)), plus the division's rounding 4u,
 * which here is far above the second-order term it leaves out (4 a^2) */
static void cond_bound_should_cover_the_worst_quotient(void **state)
{
    (void)state;
    double a = 1e-10, worst = 5 * a / (1 - a), b = mm_errbound_cond(4, a, 1, a);
    assert_true(b >= worst);
    check_rel(b, worst + 4 * U, 1e-10, "first order and the rounding (second order: 2e-11 relative)");
    /* exact singular values: the division's rounding alone, (1 + 8u) 4 u */
    check_rel(mm_errbound_cond(4, 0, 1, 0), 4 * U, 1e-14, "rounding of s1 / sn");
}

/* A = [2 1; 1 3], b = [3 4]: x = [1 1].  sigma_min = (5 - sqrt 5) / 2 */
static void solve_bound_should_follow_the_residual(void **state)
{
    (void)state;
    const double A[] = {2, 1, 1, 3}, b[] = {3, 4}, x[] = {1, 1}, xc[] = {1 + 0x1p-33, 1};
    double work[4], omega, smin = (5 - sqrt(5.0)) / 2;
    double bound = mm_errbound_solve(2, A, b, x, smin, &omega, work);
    assert_true(omega == 0.0);                          /* the exact solution: r = 0 */
    /* only the residual's own rounding: 4 eps_dd n ||mag|| / sigma_min = 2.9e-30 */
    check_rel(bound, 4 * 4.93038065763132e-32 * 2 * 10 / smin, 1e-15, "double-double's rounding");
    /* xc off by e = 2^-33 in x1: r = -A e = -(2e, e), ||r|| = sqrt 5 e, so the
     * bound is sqrt 5 e / sigma_min = 1.618 e, above the true error e; the
     * componentwise backward error is max(2e / 6, e / 7) = e / 3 */
    double e = 0x1p-33;
    bound = mm_errbound_solve(2, A, b, xc, smin, &omega, work);
    check_rel(bound, sqrt(5.0) * e / smin, 1e-15, "||r|| / sigma_min");
    assert_true(bound >= e);
    check_rel(omega, (2 * e) / (2 * (1 + e) + 1 + 3), 1e-15, "max |r_i| / (|A||xc| + |b|)_i");
}

static void rounded_residual_should_be_the_rounding_of_x(void **state)
{
    (void)state;
    const double A[] = {1, -2, 3, 4}, x[] = {1, 2}, xe[] = {0, 1e-20};
    double work[2];
    /* |A| (u |x| + xe) = (u + 2 (2u + 1e-20), 3u + 4 (2u + 1e-20)) */
    double r1 = 5 * U + 2e-20, r2 = 11 * U + 4e-20;
    check_rel(mm_errbound_rounded_residual(2, A, x, xe, work), sqrt(r1 * r1 + r2 * r2), 4 * U, "by hand");
}

static void symmetric_extremes_should_bracket_the_eigenvalues(void **state)
{
    (void)state;
    const double a[] = {2, 1, 1, 2};                    /* eigenvalues 1 and 3 */
    double work[4];
    mm_errbound_sym b;
    assert_int_equal(mm_errbound_sym_extremes(2, a, work, &b, NULL), MM_OK);
    check_abs(b.min, 1, U, "smallest eigenvalue");
    check_abs(b.max, 3, 2 * U, "largest eigenvalue");
    /* bounds 3 + e and 1 - e with e at double-double's level (~1e-30): in double, 3 and 1 */
    assert_true(b.norm_hi == 3.0 && b.min_lo == 1.0);
    check_abs(work[2], 0, 1e-29, "the bound of the smallest eigenvalue");
    const double c[] = {1, 2, 2, 1};                    /* eigenvalues -1 and 3: indefinite */
    assert_int_equal(mm_errbound_sym_extremes(2, c, work, &b, NULL), MM_OK);
    assert_true(b.min_lo < 0 && b.norm_hi >= 3);
}

static void sqrt_bound_should_cover_the_interval_of_roots(void **state)
{
    (void)state;
    double e, om = mm_errbound_sqrt(4, 1e-10, &e);
    assert_true(om == 2.0);
    /* |sqrt(4 - 1e-10) - 2| = 2.5e-11 (1 + 6e-12): the wider side */
    double worst = 2 - sqrt(4 - 1e-10);
    assert_true(e >= worst);
    check_rel(e, worst + 2 * U, 1e-5, "1e-10 / 4 and u omega");
    /* lambda = 0 within 1e-10 (a rigid-body mode): omega within sqrt(1e-10) = 1e-5 */
    om = mm_errbound_sqrt(0, 1e-10, &e);
    assert_true(om == 0.0);
    check_rel(e, 1e-5, 1e-15, "the root of the interval's top");
}

static void trace_tolerance_should_sum_the_bounds(void **state)
{
    (void)state;
    const double MK[] = {2, 0.5, 0, 3}, lam[] = {2, 3}, le[] = {1e-15, 2e-15};
    double tr, sum, tol = mm_errbound_trace(2, MK, 1e-16, lam, le, &tr, &sum);
    assert_true(tr == 5.0 && sum == 5.0);
    /* the eigenvalues' bounds, ferr times each column's largest entry (2, 3),
     * and 2 n u (|lambda_j| + |MK_jj|) */
    check_rel(tol, 3e-15 + 1e-16 * 5 + 4 * U * 10, 1e-14, "by hand");
}

static void ulp_should_be_the_spacing_of_doubles(void **state)
{
    (void)state;
    assert_true(mm_errbound_ulp(1.0) == DBL_EPSILON);
    assert_true(mm_errbound_ulp(-3.0) == 2 * DBL_EPSILON);       /* 2 <= 3 < 4 */
    assert_true(mm_errbound_ulp(0x1p-60) == 0x1p-112);
    assert_true(mm_errbound_ulp(0.0) == 0.0);
    assert_true(nextafter(10.0, 11.0) - 10.0 == mm_errbound_ulp(10.0));
}

static void arg_should_be_atan2_with_its_bound(void **state)
{
    (void)state;
    double e, a = mm_errbound_arg(mm_cdd_exact(1, 1), &e);
    check_abs(a, M_PI / 4, e, "arg(1 + i) = pi/4 within the bound");
    assert_true(e <= 2 * mm_errbound_ulp(M_PI / 4));              /* exact input: atan2's rounding */
    a = mm_errbound_arg(mm_cdd_exact(-2, 0), &e);
    check_abs(a, M_PI, e, "arg(-2) = pi, not -pi");
    a = mm_errbound_arg(mm_cdd_exact(0, 0), &e);
    assert_true(a == 0.0 && e == 0.0);                             /* 0 by convention, exactly */
    /* the low parts count: 1 + i (1e-10 + 1e-27) has the argument
     * 1e-10 + 1e-27 - (1e-10)^3 / 3 to 1e-40 */
    mm_cdd z = {mm_dd_from(1), {1e-10, 1e-27}, 0};
    a = mm_errbound_arg(z, &e);
    check_abs(a, 1e-10 + 1e-27 - 1e-30 / 3, e, "arg with the low part of im");
    /* z within 1e-3 of 1: the angle within about 2e-3 */
    z.err = 1e-3;
    a = mm_errbound_arg(z, &e);
    assert_true(e >= 1e-3 && e <= 2.1e-3);
    z = mm_cdd_exact(0, 0);
    z.err = 1e-20;
    mm_errbound_arg(z, &e);
    check_abs(e, M_PI, 0, "a zero that may not be zero: any angle");
}

/* the cube roots of 8: 2 and -1 +- i sqrt 3 */
static void roots_of_eight_should_be_the_closed_form(void **state)
{
    (void)state;
    double re[3], im[3], back, back_tol, sum, sum_tol, s3 = sqrt(3.0);
    mm_errbound_roots(mm_cdd_exact(8, 0), 8, 0, 3, re, im, &back, &back_tol, &sum, &sum_tol);
    const double want[3][2] = {{2, 0}, {-1, s3}, {-1, -s3}};
    for (int k = 0; k < 3; k++) {
        check_abs(re[k], want[k][0], U, "real part of a cube root of 8, rounded");
        check_abs(im[k], want[k][1], 2 * U, "imaginary part, rounded (sqrt 3 within 1/2 ulp of 1.7)");
    }
    /* the bounds: 1.01 n |w|^(n-1) |rounding of w| = 1.01 * 3 * 4 * sqrt 2 u 2 = 3.8e-15, and
     * 1.01 (3 sqrt 2 u 2 + 2u (2 + 1 + 1 + sqrt 3)) = 2.0e-15 */
    assert_true(back <= back_tol && back_tol < 4e-15);
    assert_true(sum <= sum_tol && sum_tol < 2.1e-15);
}

/* (2 + i)^2 = 3 + 4i by the polar form in double, within the bound */
static void polar_bound_should_cover_a_square_in_polar_form(void **state)
{
    (void)state;
    check_rel(mm_errbound_polar(1, 1, 0), 12 * U * M_SQRT2, 1e-15, "(8 u + 4 u) sqrt 2 at r = 1, theta = 0");
    double r = hypot(2, 1), t = atan2(1, 2), rp = pow(r, 2), tp = 2 * t;
    double dev = hypot(rp * cos(tp) - 3, rp * sin(tp) - 4), b = mm_errbound_polar(rp, 2, fabs(t));
    assert_true(dev <= b);
    assert_true(b < 100 * U * 5);                       /* a few tens of u of |z| = 5 */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(cond_bound_should_cover_the_worst_quotient),
        cmocka_unit_test(solve_bound_should_follow_the_residual),
        cmocka_unit_test(rounded_residual_should_be_the_rounding_of_x),
        cmocka_unit_test(symmetric_extremes_should_bracket_the_eigenvalues),
        cmocka_unit_test(sqrt_bound_should_cover_the_interval_of_roots),
        cmocka_unit_test(trace_tolerance_should_sum_the_bounds),
        cmocka_unit_test(ulp_should_be_the_spacing_of_doubles),
        cmocka_unit_test(arg_should_be_atan2_with_its_bound),
        cmocka_unit_test(roots_of_eight_should_be_the_closed_form),
        cmocka_unit_test(polar_bound_should_cover_a_square_in_polar_form),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
