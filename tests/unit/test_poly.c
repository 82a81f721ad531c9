/* test_poly.c — mm_poly against references computed independently: exact
 * rationals by hand, roots from mpmath at 60 digits, polynomials built from
 * known roots, data generated from a known polynomial. */
#include "mm_test.h"

#include <float.h>
#include <string.h>

#include "mm_poly.h"

#define EPS DBL_EPSILON

/* ==== evaluation ================================================================= */
/* Hand values: the ratio |p(z)| / sum |p_k| |z|^(d-k) does not depend on the
 * scaling by max(1, |z|)^d the routine uses, so it is known exactly. */
static void backward_error_should_match_hand_values_without_overflow(void **state)
{
    (void)state;
    const double q1[] = {1, 0, 1};                       /* x^2 + 1 */
    assert_true(mm_poly_backward_error(3, q1, 0, 1) == 0.0);        /* i is exact */
    /* at 1 + i: p = 1 + 2i, |p| = sqrt 5; scale |z|^2 + 1 = 3 */
    check_rel(mm_poly_backward_error(3, q1, 1, 1), sqrt(5.0) / 3, 8 * EPS, "x^2 + 1 at 1 + i");
    /* at 0.5 (|z| < 1, the other branch): p = 1.25, scale 1.25: 1 */
    check_rel(mm_poly_backward_error(3, q1, 0.5, 0), 1.0, 4 * EPS, "x^2 + 1 at 0.5");
    /* x^2 - 1e300 x at 3e300 (p(z) = 6e600 would overflow unscaled): divided
     * by |z|^2, |p| = 2/3 and the scale 1 + 1/3, so the ratio is 1/2 */
    const double q2[] = {1, -1e300, 0};
    check_rel(mm_poly_backward_error(3, q2, 3e300, 0), 2.0 / 4.0, 8 * EPS, "x^2 - 1e300 x at 3e300");
    const double q3[] = {0, 0};
    assert_true(mm_poly_backward_error(2, q3, 5, 0) == 0.0);        /* the zero polynomial */
}


static void horner_bound_should_cover_the_actual_error(void **state)
{
    (void)state;
    /* (x-1)^5 expanded: near x = 1 Horner cancels catastrophically.  The
     * reference (x-1)^5 is computed from x-1, which is exact for x in
     * [0.5, 2] (Sterbenz), with a relative error of a few ulps only. */
    const double p[6] = {1, -5, 10, -10, 5, -1};
    for (int k = -50; k <= 50; k++) {
        double x = 1 + k * 1e-3, bound;
        double got = mm_poly_eval(6, p, x, &bound);
        double d = x - 1, want = d * d * d * d * d;
        assert_true(fabs(got - want) <= bound + 8 * EPS * fabs(want));
    }
    double bound;
    check_abs(mm_poly_eval(6, p, 3.0, &bound), 32.0, 0.0, "exact at integers");
    check_abs(mm_poly_eval(1, p, 7.0, &bound), 1.0, 0.0, "a constant");
    assert_true(bound == 0.0 || bound < EPS);
}

/* ==== roots ===================================================================== */

static void book_cubic_should_have_the_published_roots(void **state)
{
    (void)state;
    /* roots([1 2 3 4]): -1.6506, -0.1747 +- 1.5469i; references from mpmath
     * polyroots at 50 digits */
    const double p[4] = {1, 2, 3, 4};
    mm_poly_root r[3];
    int n;
    assert_int_equal(mm_poly_roots(4, p, r, &n, NULL), MM_OK);
    assert_int_equal(n, 3);
    /* well-conditioned (cond ~ 2): a few ulps */
    check_rel(r[0].re, -1.6506291914393882189, 4 * EPS, "real root");
    check_abs(r[0].im, 0.0, 0.0, "real root stays real");
    check_rel(r[1].re, -0.17468540428030589056, 4 * EPS, "Re of the pair");
    check_rel(r[1].im, 1.5468688872313962771, 4 * EPS, "Im, positive first");
    check_abs(r[2].re, r[1].re, 0.0, "conjugate pair: same real part");
    check_abs(r[2].im, -r[1].im, 0.0, "conjugate pair: opposite imaginary part");
    for (int i = 0; i < 3; i++) {
        assert_int_equal(r[i].multiplicity, 1);
        assert_int_equal(r[i].flags, 0);
        assert_true(r[i].err < 1e-14 && r[i].err > 0);
    }
}

__extension__ typedef __int128 i128;   /* GCC: 20! needs more than 64 bits */

/* Coefficients of (x-1)(x-2)...(x-20), exact in 128-bit integers, then
 * rounded to double as a user typing them would get. */
static void wilkinson(double *p)
{
    i128 c[21] = {1};
    for (int k = 1; k <= 20; k++)
        for (int j = k; j >= 1; j--)
            c[j] -= (i128)k * c[j - 1];
    for (int i = 0; i <= 20; i++)
        p[i] = (double)c[i];
}

static void wilkinson_roots_should_come_with_error_bounds_that_hold(void **state)
{
    (void)state;
    /* Exact roots of the double-rounded polynomial, mpmath polyroots at 60
     * digits (the rounding of the big coefficients alone moves root 14 by
     * 5e-4: Wilkinson's point). */
    static const double exact_of_rounded[20] = {
        20.000000223546402, 18.999996997743891, 18.000018751706041,
        16.999927734617732, 16.000192083038473, 14.999626582170548,
        14.0005479886738, 12.999380734557897, 12.000543743635912,
        10.999628430240644, 10.000196964905369, 8.999920011868348,
        8.0000244325689386, 6.9999945554484521, 6.0000008457166073,
        4.9999999147341429, 4.0000000049594407, 2.9999999998663996,
        2.0000000000009596, 1.0000000000000013};
    double p[21];
    wilkinson(p);
    mm_poly_root r[20];
    int n;
    assert_int_equal(mm_poly_roots(21, p, r, &n, NULL), MM_OK);
    assert_int_equal(n, 20);
    for (int i = 0; i < 20; i++) {
        double k = 20 - i, actual = hypot(r[i].re - k, r[i].im);
        print_message("root %2.0f: %.15f%+.1ei  actual error %.2e  reported %.2e\n",
                      k, r[i].re, r[i].im, actual, r[i].err);
        /* the reported error bounds the distance to the true integer root */
        assert_true(actual <= r[i].err);
        /* and is informative: not more than ~1e4 times too pessimistic
         * (it assumes every coefficient rounded the worst way) */
        assert_true(r[i].err <= 1e4 * fmax(actual, EPS * k));
        /* the polished root is the root of the given coefficients to a few
         * ulps: Newton with double-double evaluation leaves an error
         * ~ u^2 sum|p_k||z|^k / |p'(z)|, far below an ulp */
        check_rel(r[i].re, exact_of_rounded[i], 4 * EPS, "root of the rounded polynomial");
        assert_int_equal(r[i].multiplicity, 1);
    }
    /* roots 5..20 have lost more than half their digits, 1..3 have not */
    for (int i = 0; i <= 15; i++)
        assert_true(r[i].flags & MM_POLY_ROOT_ILLCOND);
    for (int i = 17; i < 20; i++)
        assert_int_equal(r[i].flags, 0);
    assert_true(r[6].cond > 1e13);          /* root 14: cond ~ 5e13 */
}

static void triple_root_should_report_eps_to_the_one_third(void **state)
{
    (void)state;
    /* (x-1)^3 (x+2) = x^4 - x^3 - 3x^2 + 5x - 2, exact coefficients */
    const double p[5] = {1, -1, -3, 5, -2};
    const double e13 = cbrt(EPS);           /* 6.1e-6 */
    mm_poly_root r[4];
    int n;
    assert_int_equal(mm_poly_roots(5, p, r, &n, NULL), MM_OK);
    assert_int_equal(n, 4);
    check_rel(r[0].re, -2.0, 4 * EPS, "the simple root -2");
    assert_int_equal(r[0].multiplicity, 1);
    assert_true(r[0].err < 1e-15);
    for (int i = 1; i < 4; i++) {
        double actual = hypot(r[i].re - 1, r[i].im);
        print_message("near 1: %.15f%+.2ei  actual %.2e  reported %.2e\n",
                      r[i].re, r[i].im, actual, r[i].err);
        assert_int_equal(r[i].multiplicity, 3);
        assert_true(r[i].flags & MM_POLY_ROOT_MULTIPLE);
        assert_true(r[i].flags & MM_POLY_ROOT_ILLCOND);
        assert_true(actual <= r[i].err);
        /* reported accuracy ~ eps^(1/3): within a factor 10 either way */
        assert_true(r[i].err > e13 / 10 && r[i].err < 10 * e13);
    }
}

static void double_root_should_report_eps_to_the_one_half(void **state)
{
    (void)state;
    /* (x-3)^2 (x+1) = x^3 - 5x^2 + 3x + 9 */
    const double p[4] = {1, -5, 3, 9};
    mm_poly_root r[3];
    int n;
    assert_int_equal(mm_poly_roots(4, p, r, &n, NULL), MM_OK);
    assert_int_equal(n, 3);
    for (int i = 0; i < 2; i++) {
        double actual = hypot(r[i].re - 3, r[i].im);
        assert_int_equal(r[i].multiplicity, 2);
        assert_true(actual <= r[i].err);
        /* ~ sqrt(eps) * sqrt(sum|p_k| 3^k / |p''/2|) ~ 1.5e-8 * 2: factor 30 */
        assert_true(r[i].err < 30 * sqrt(EPS) && r[i].err > sqrt(EPS) / 30);
    }
    check_rel(r[2].re, -1.0, 4 * EPS, "the simple root -1");
    assert_int_equal(r[2].multiplicity, 1);
}

static void zero_coefficients_at_either_end_should_be_handled(void **state)
{
    (void)state;
    mm_poly_root r[8];
    int n;
    /* leading zeros lower the degree: 0 0 1 -3 2 -> x^2 - 3x + 2 */
    const double a[5] = {0, 0, 1, -3, 2};
    assert_int_equal(mm_poly_roots(5, a, r, &n, NULL), MM_OK);
    assert_int_equal(n, 2);
    check_rel(r[0].re, 2.0, 2 * EPS, "root 2");
    check_rel(r[1].re, 1.0, 2 * EPS, "root 1");
    /* trailing zeros: x^2 (x^2 - 3x + 2) -> 2, 1, 0, 0 with exact zeros */
    const double b[5] = {1, -3, 2, 0, 0};
    assert_int_equal(mm_poly_roots(5, b, r, &n, NULL), MM_OK);
    assert_int_equal(n, 4);
    check_rel(r[0].re, 2.0, 2 * EPS, "root 2");
    check_rel(r[1].re, 1.0, 2 * EPS, "root 1");
    for (int i = 2; i < 4; i++) {
        assert_true(r[i].re == 0 && r[i].im == 0 && r[i].err == 0);
        assert_int_equal(r[i].multiplicity, 2);
        assert_true(r[i].flags & MM_POLY_ROOT_MULTIPLE);
    }
    /* x^3: only zero roots, no eigenvalue problem at all */
    const double c[4] = {2, 0, 0, 0};
    assert_int_equal(mm_poly_roots(4, c, r, &n, NULL), MM_OK);
    assert_int_equal(n, 3);
    /* a nonzero constant (after leading zeros) has no roots */
    const double d[3] = {0, 0, 5};
    assert_int_equal(mm_poly_roots(3, d, r, &n, NULL), MM_OK);
    assert_int_equal(n, 0);
    /* x^2 + 1: +-i */
    const double e[3] = {1, 0, 1};
    assert_int_equal(mm_poly_roots(3, e, r, &n, NULL), MM_OK);
    assert_int_equal(n, 2);
    check_abs(r[0].re, 0.0, 2 * EPS, "Re i");
    check_rel(r[0].im, 1.0, 2 * EPS, "Im i first");
    check_rel(r[1].im, -1.0, 2 * EPS, "then -i");
}

static void bad_coefficients_should_be_rejected(void **state)
{
    (void)state;
    mm_poly_root r[4];
    int n;
    mm_error err;
    const double z[3] = {0, 0, 0};
    assert_int_equal(mm_poly_roots(3, z, r, &n, &err), MM_EVALUE);
    assert_string_equal(err.param, "p");
    assert_non_null(strstr(err.msg, "all coefficients are zero"));
    const double nan[3] = {1, NAN, 2};
    assert_int_equal(mm_poly_roots(3, nan, r, &n, &err), MM_EVALUE);
    assert_string_equal(err.param, "p");
    assert_int_equal(mm_poly_roots(0, nan, r, &n, &err), MM_ERANGE);
    assert_string_equal(err.param, "p");
    assert_int_equal(mm_poly_roots(MM_POLY_MAX_DEGREE + 2, nan, r, &n, &err), MM_ERANGE);
    assert_string_equal(err.param, "p");
    /* roots that overflow: 1e-300 x^2 + 1e300 */
    const double o[3] = {1e-300, 0, 1e300};
    assert_int_equal(mm_poly_roots(3, o, r, &n, &err), MM_ENONFINITE);
}

/* ==== polyfit ===================================================================== */

static void polyfit_should_match_the_book_line(void **state)
{
    (void)state;
    /* (1,10), (3,18), (10,37), degree 1.  Normal equations by hand:
     * [110 14; 14 3][a; b] = [434; 65] -> a = 196/67 = 2.92537,
     * b = 537/67 = 8.01493; residuals (-63, 81, -18)/67, so
     * rms = sqrt((63^2 + 81^2 + 18^2) / 67^2 / 3) = sqrt(3618)/67 */
    const double x[3] = {1, 3, 10}, y[3] = {10, 18, 37};
    double p[2];
    mm_poly_fit_info info;
    assert_int_equal(mm_poly_fit(3, x, y, 1, p, &info, NULL), MM_OK);
    /* scaled fit (cond ~ 1.5) plus the expansion back to x: a few ulps
     * times |mu/scale| ~ 1 */
    check_rel(p[0], 196.0 / 67, 1e-14, "slope, highest power first");
    check_rel(p[1], 537.0 / 67, 1e-14, "intercept");
    check_rel(info.rms, sqrt(3618.0) / 67, 1e-14, "rms residual sqrt(sum r^2 / n)");
    assert_int_equal(info.rank, 2);
    check_rel(info.mu, 14.0 / 3, 1e-15, "centre: mean of x");
}

/* Fit the cubic 2x^3 - 3x^2 + 0.5x + 7 to its exact values at x0, x0+1,
 * ..., x0+10 and compare coefficient by coefficient.  Error budget: the
 * SVD solution in t has absolute error ~ cond * eps * ||y|| (backward
 * stable least squares on exact data), and expanding c(t), t = (x-mu)/s,
 * back to x multiplies the error of the x^k coefficient by at most
 * (1 + |mu|/s)^3 / s^k (binomial sums).  Factor 10 for the constants. */
static void fit_cubic_on(double x0)
{
    const double c[4] = {2, -3, 0.5, 7};
    double x[11], y[11], p[4], ynorm = 0;
    mm_poly_fit_info info;
    for (int i = 0; i <= 10; i++) {
        x[i] = x0 + i;
        y[i] = ((2.0 * x[i] - 3) * x[i] + 0.5) * x[i] + 7;   /* exact */
        ynorm += y[i] * y[i];
    }
    ynorm = sqrt(ynorm);
    assert_int_equal(mm_poly_fit(11, x, y, 3, p, &info, NULL), MM_OK);
    double E = 10 * info.cond * EPS * ynorm;
    double amp = pow(1 + fabs(info.mu) / info.scale, 3);
    for (int k = 0; k < 4; k++) {
        double tol = E * amp / pow(info.scale, 3 - k);
        print_message("x0 = %g: p[%d] = %.17g, error %.2e, budget %.2e\n",
                      x0, k, p[k], fabs(p[k] - c[k]), tol);
        check_abs(p[k], c[k], tol, "cubic coefficient from exact data");
    }
    check_abs(info.rms, 0.0, E, "exact data: rms at rounding level");
    assert_int_equal(info.rank, 4);
}

static void polyfit_should_recover_a_cubic_from_exact_data(void **state)
{
    (void)state;
    fit_cubic_on(0);      /* x = 0..10 */
    fit_cubic_on(100);    /* x = 100..110: original-variable coefficients
                             are ill-conditioned, the fit in t is not */
}

static void polyfit_rms_should_match_a_hand_computation(void **state)
{
    (void)state;
    /* degree 0 fits the mean 2.5 of y = 1, 2, 3, 4; residuals -1.5, -0.5,
     * 0.5, 1.5, rms = sqrt(5/4) */
    const double x[4] = {0, 1, 2, 3}, y[4] = {1, 2, 3, 4};
    double p[1];
    mm_poly_fit_info info;
    assert_int_equal(mm_poly_fit(4, x, y, 0, p, &info, NULL), MM_OK);
    check_rel(p[0], 2.5, 2 * EPS, "mean");
    check_rel(info.rms, sqrt(1.25), 2 * EPS, "rms of degree 0");
    /* degree 2 through (0,0), (1,1), (2,0), (3,1), by hand in t = x - 1.5:
     * sums t: 0, t^2: 5, t^3: 0, t^4: 10.25; y: 2, t y: 1, t^2 y: 2.5.
     * Normal equations [4 0 5; 0 5 0; 5 0 10.25] (a b c) = (2 1 2.5) give
     * b = 0.2, c = 0, a = 0.5: the fit is 0.2 x + 0.2 (the x^2 term
     * vanishes), residuals (-0.2, 0.6, -0.6, 0.2), rms = sqrt(0.8/4) */
    const double y2[4] = {0, 1, 0, 1};
    double q[3];
    assert_int_equal(mm_poly_fit(4, x, y2, 2, q, &info, NULL), MM_OK);
    /* cond of the scaled Vandermonde ~ 3; expansion back multiplies by
     * (1 + mu/scale)^2 = 4: 1e-14 absolute */
    check_abs(q[0], 0.0, 1e-14, "x^2 coefficient by hand");
    check_abs(q[1], 0.2, 1e-14, "x coefficient by hand");
    check_abs(q[2], 0.2, 1e-14, "constant by hand");
    check_rel(info.rms, sqrt(0.2), 1e-14, "rms sqrt(sum r^2 / n) by hand");
    assert_int_equal(info.rank, 3);
}

static void polyfit_degree_too_high_should_name_the_parameter(void **state)
{
    (void)state;
    const double x[3] = {1, 1, 2}, y[3] = {1, 2, 3};
    double p[4];
    mm_error err;
    /* two distinct x values fix at most a line */
    assert_int_equal(mm_poly_fit(3, x, y, 2, p, NULL, &err), MM_ERANGE);
    assert_string_equal(err.param, "degree");
    assert_non_null(strstr(err.msg, "distinct"));
    assert_int_equal(mm_poly_fit(3, x, y, 1, p, NULL, &err), MM_OK);
    assert_int_equal(mm_poly_fit(3, x, y, -1, p, NULL, &err), MM_ERANGE);
    assert_string_equal(err.param, "degree");
    assert_int_equal(mm_poly_fit(3, x, y, MM_POLY_MAX_FIT_DEGREE + 1, p, NULL, &err), MM_ERANGE);
    assert_string_equal(err.param, "degree");
    assert_int_equal(mm_poly_fit(0, x, y, 0, p, NULL, &err), MM_ERANGE);
    assert_string_equal(err.param, "x");
    const double yn[3] = {1, INFINITY, 3};
    assert_int_equal(mm_poly_fit(3, x, yn, 1, p, NULL, &err), MM_EVALUE);
    assert_string_equal(err.param, "y");
}

/* ==== the fit in double-double ===================================================== */

static void polyfit_dd_should_give_the_exact_least_squares_line(void **state)
{
    (void)state;
    /* the book's line: 196/67 x + 537/67 (exact rationals by hand) */
    const double x[3] = {1, 3, 10}, y[3] = {10, 18, 37};
    double c[2], ce[2], fit[3], fe[3], se[2];
    mm_poly_fit_dd_info info;
    assert_int_equal(mm_poly_fit_dd(3, x, y, 1, c, ce, fit, fe, se, NULL, &info, NULL), MM_OK);
    check_rel(c[0], 196.0 / 67, EPS / 2, "slope, correctly rounded");
    check_rel(c[1], 537.0 / 67, EPS / 2, "intercept, correctly rounded");
    assert_true(fabs(c[0] - 196.0 / 67) <= ce[0] + EPS * c[0]);
    /* rms with the exact line: sqrt(sum r^2 / 3), r = (-63, 81, -18) / 67 */
    check_rel(info.rms, sqrt((63.0 * 63 + 81.0 * 81 + 18.0 * 18) / (3 * 67.0 * 67)), 2 * EPS, "rms");
    check_rel(fit[1], 1125.0 / 67, EPS, "fitted value at x = 3");
    assert_int_equal(info.dof, 1);
    assert_true(se[0] > 0 && se[1] > 0);
}

static void polyfit_dd_should_survive_powers_that_cancel(void **state)
{
    (void)state;
    /* exact data of (x - 1000)^3 sampled at 1000..1005: the coefficients of
     * powers of x are 1, -3000, 3e6, -1e9, which cancel to 0..125 at the
     * data; in double-double they come out exact */
    double x[6], y[6], c[4], ce[4], fit[6], fe[6];
    for (int i = 0; i < 6; i++) {
        x[i] = 1000 + i;
        y[i] = (double)i * i * i;
    }
    mm_poly_fit_dd_info info;
    assert_int_equal(mm_poly_fit_dd(6, x, y, 3, c, ce, fit, fe, NULL, NULL, &info, NULL), MM_OK);
    const double want[4] = {1, -3000, 3e6, -1e9};
    for (int k = 0; k < 4; k++) {
        check_rel(c[k], want[k], EPS, "coefficient of (x - 1000)^3");
        assert_true(fabs(c[k] - want[k]) <= ce[k] + EPS * fabs(want[k]) / 2);
    }
    for (int i = 0; i < 6; i++)
        check_abs(fit[i], y[i], fe[i], "interpolates exact data");
    check_abs(info.rms, 0, info.rms_err, "rms 0 within its bound");
}

static void fitted_values_in_double_should_agree_by_both_routes(void **state)
{
    (void)state;
    /* the book's line: fitted values 733/67, 1125/67, 2497/67 */
    const double x[3] = {1, 3, 10}, y[3] = {10, 18, 37}, want[3] = {733.0 / 67, 1125.0 / 67, 2497.0 / 67};
    double fs[3], fn[3], bs, bn;
    assert_int_equal(mm_poly_fit_values(3, x, y, 1, 14.0 / 3, 16.0 / 3, fs, fn, &bs, &bn, NULL), MM_OK);
    for (int i = 0; i < 3; i++) {
        check_rel(fs[i], want[i], 8 * EPS, "fitted value by the SVD");
        check_rel(fn[i], want[i], 8 * EPS, "fitted value by the normal equations (cond^2 ~ 2)");
    }
    assert_true(bs > 0 && bn > 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(horner_bound_should_cover_the_actual_error),
        cmocka_unit_test(backward_error_should_match_hand_values_without_overflow),
        cmocka_unit_test(book_cubic_should_have_the_published_roots),
        cmocka_unit_test(wilkinson_roots_should_come_with_error_bounds_that_hold),
        cmocka_unit_test(triple_root_should_report_eps_to_the_one_third),
        cmocka_unit_test(double_root_should_report_eps_to_the_one_half),
        cmocka_unit_test(zero_coefficients_at_either_end_should_be_handled),
        cmocka_unit_test(bad_coefficients_should_be_rejected),
        cmocka_unit_test(polyfit_should_match_the_book_line),
        cmocka_unit_test(polyfit_should_recover_a_cubic_from_exact_data),
        cmocka_unit_test(polyfit_rms_should_match_a_hand_computation),
        cmocka_unit_test(polyfit_degree_too_high_should_name_the_parameter),
        cmocka_unit_test(polyfit_dd_should_give_the_exact_least_squares_line),
        cmocka_unit_test(polyfit_dd_should_survive_powers_that_cancel),
        cmocka_unit_test(fitted_values_in_double_should_agree_by_both_routes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
