/* test_roots.c — mm_roots against roots known in closed form (k pi, 1/2,
 * cube roots) or computed independently (mpmath findroot at 50 digits),
 * and the failure modes it promises to report (poles, jumps, touching
 * roots, bad input, a callback that stops). */
#include "mm_test.h"

#include <float.h>
#include <string.h>

#include "mm_roots.h"

#define PI 3.14159265358979323846

static int f_book(double x, double *fx, void *params)
{
    (void)params;
    *fx = x * x * x + sin(x) - 2;
    return 0;
}

static int f_sin(double x, double *fx, void *params)
{
    (void)params;
    *fx = sin(x);
    return 0;
}

static int f_tan(double x, double *fx, void *params)
{
    (void)params;
    *fx = tan(x);
    return 0;
}

static int f_recip(double x, double *fx, void *params)
{
    (void)params;
    *fx = 1 / x;
    return 0;
}

static int f_shift(double x, double *fx, void *params)
{
    *fx = x - *(const double *)params;
    return 0;
}

static int f_cube(double x, double *fx, void *params)
{
    (void)params;
    *fx = x * x * x - 2;
    return 0;
}

static int f_step(double x, double *fx, void *params)
{
    (void)params;
    *fx = x > 0.3 ? 1.0 : -1.0;
    return 0;
}

static int f_square(double x, double *fx, void *params)
{
    (void)params;
    *fx = (x - 1) * (x - 1);
    return 0;
}

static int f_sqrt(double x, double *fx, void *params)
{
    (void)params;
    *fx = sqrt(x) - 0.5;          /* NaN for x < 0 */
    return 0;
}

static int f_fails(double x, double *fx, void *params)
{
    *fx = x;
    return x > 0.5 ? *(const int *)params : 0;
}

/* Run a search with default options except n and tol. */
static int run(mm_roots_fn f, void *params, double a, double b, int n, double tol,
               mm_roots_root *roots, int cap, double *poles, mm_roots_result *res,
               mm_error *err)
{
    mm_roots_problem prob = {f, params, a, b};
    mm_roots_options opt;
    mm_roots_options_init(&opt);
    opt.n = n;
    opt.tol = tol;
    *res = (mm_roots_result){.roots = roots, .cap = cap, .poles = poles, .pole_cap = poles ? 8 : 0};
    return mm_roots_solve(&prob, &opt, res, err);
}

static void book_example_should_find_the_single_root(void **state)
{
    (void)state;
    /* x^3 + sin x - 2 on [-1, 10], n = 100, tol = 1e-6 (API.md defaults);
     * mpmath findroot: 1.0433859882095546576 */
    mm_roots_root r[101];
    mm_roots_result res;
    assert_int_equal(run(f_book, NULL, -1, 10, 100, 1e-6, r, 101, NULL, &res, NULL), MM_OK);
    assert_int_equal(res.nroots, 1);
    check_abs(r[0].x, 1.0433859882095546576, 1e-6, "root within tol (the contract)");
    check_rel(r[0].x, 1.0434, 5e-5, "the book's 4 digits");
    assert_true(r[0].width <= 2 * (2 * DBL_EPSILON * 1.05 + 0.5e-6));
    assert_int_equal(r[0].flags, 0);
    assert_int_equal(res.npoles, 0);
    /* every call is counted: n+1 grid points plus one per iteration */
    assert_int_equal(res.nevals, 101 + r[0].iterations);
}

static void sine_should_give_all_seven_multiples_of_pi(void **state)
{
    (void)state;
    mm_roots_root r[101];
    mm_roots_result res;
    assert_int_equal(run(f_sin, NULL, -10, 10, 100, 1e-10, r, 101, NULL, &res, NULL), MM_OK);
    assert_int_equal(res.nroots, 7);
    for (int k = -3; k <= 3; k++)
        check_abs(r[k + 3].x, k * PI, 1e-10, "k pi, ascending, within tol");
    /* 0 = -10 + 20*50/100 is a grid point where sin is exactly 0 */
    assert_true(r[3].flags & MM_ROOTS_EXACT);
    assert_true(r[3].x == 0.0);
}

static void tangent_pole_should_not_be_a_root(void **state)
{
    (void)state;
    /* tan changes sign across pi/2 in [1, 2] but has no root there */
    mm_roots_root r[11];
    double poles[8];
    mm_roots_result res;
    assert_int_equal(run(f_tan, NULL, 1, 2, 10, 1e-8, r, 11, poles, &res, NULL), MM_OK);
    assert_int_equal(res.nroots, 0);
    assert_int_equal(res.npoles, 1);
    check_abs(poles[0], PI / 2, 1e-8, "pole located at pi/2");
    /* 1/x on [-1, 1] with no grid point at 0 */
    assert_int_equal(run(f_recip, NULL, -1, 1, 3, 1e-8, r, 11, poles, &res, NULL), MM_OK);
    assert_int_equal(res.nroots, 0);
    assert_int_equal(res.npoles, 1);
    check_abs(poles[0], 0.0, 1e-8, "pole of 1/x");
}

static void root_on_a_subdivision_point_should_be_reported_once(void **state)
{
    (void)state;
    mm_roots_root r[11];
    mm_roots_result res;
    double half = 0.5;
    /* x - 0.5 on [0, 1], n = 4: 0.5 is grid point 2, exactly */
    assert_int_equal(run(f_shift, &half, 0, 1, 4, 1e-12, r, 11, NULL, &res, NULL), MM_OK);
    assert_int_equal(res.nroots, 1);
    assert_true(r[0].x == 0.5 && r[0].fx == 0.0);
    assert_int_equal(r[0].flags, MM_ROOTS_EXACT);
    assert_int_equal(r[0].iterations, 0);
    assert_int_equal(res.nevals, 5);          /* no refinement needed */
    /* at an end of [a, b] as well */
    double zero = 0.0;
    assert_int_equal(run(f_shift, &zero, 0, 1, 4, 1e-12, r, 11, NULL, &res, NULL), MM_OK);
    assert_int_equal(res.nroots, 1);
    assert_true(r[0].x == 0.0);
    double one = 1.0;
    assert_int_equal(run(f_shift, &one, 0, 1, 4, 1e-12, r, 11, NULL, &res, NULL), MM_OK);
    assert_int_equal(res.nroots, 1);
    assert_true(r[0].x == 1.0);
}

static void brent_iterations_should_stay_bounded(void **state)
{
    (void)state;
    /* smooth simple root, bracket [0, 2], tol 1e-14: bisection would need
     * log2(2/1e-14) = 48 steps; Brent converges superlinearly */
    double x, fx, w;
    int iter = 0;
    long nev = 0;
    assert_int_equal(mm_roots_brent(f_cube, NULL, 0, 2, -2, 6, 1e-14, 100, &x, &fx, &w,
                                    &iter, &nev, NULL), MM_OK);
    check_abs(x, cbrt(2.0), 1e-14, "cube root of 2");
    print_message("x^3 - 2: %d iterations, %ld evaluations\n", iter, nev);
    assert_true(iter <= 12);
    assert_int_equal(nev, iter);
    /* a jump: interpolation is useless, Brent must fall back to bisection
     * and still finish in about log2(1/tol) steps (Brent's guarantee is at
     * most ~ (log2)^2; in practice close to bisection) */
    iter = 0;
    assert_int_equal(mm_roots_brent(f_step, NULL, 0, 1, -1, 1, 1e-12, 200, &x, &fx, &w,
                                    &iter, NULL, NULL), MM_OK);
    print_message("step: %d iterations\n", iter);
    check_abs(x, 0.3, 1e-12, "jump located");
    assert_true(iter <= 3 * 40);
    /* max_iter too small: no convergence, named parameter */
    mm_error err;
    iter = 0;
    assert_int_equal(mm_roots_brent(f_step, NULL, 0, 1, -1, 1, 1e-12, 5, &x, &fx, &w,
                                    &iter, NULL, &err), MM_ENOCONV);
    assert_string_equal(err.param, "max_iter");
    assert_int_equal(iter, 5);
}

static void jump_should_be_flagged_suspect(void **state)
{
    (void)state;
    mm_roots_root r[11];
    mm_roots_result res;
    assert_int_equal(run(f_step, NULL, 0, 1, 10, 1e-9, r, 11, NULL, &res, NULL), MM_OK);
    assert_int_equal(res.nroots, 1);
    assert_true(r[0].flags & MM_ROOTS_SUSPECT);       /* |f| = 1 at the "root" */
}

static void touching_root_should_not_be_found(void **state)
{
    (void)state;
    /* (x-1)^2 >= 0: no sign change, as the header warns (n = 7 keeps 1
     * off the grid) */
    mm_roots_root r[11];
    mm_roots_result res;
    assert_int_equal(run(f_square, NULL, 0, 3, 7, 1e-9, r, 11, NULL, &res, NULL), MM_OK);
    assert_int_equal(res.nroots, 0);
}

static void non_finite_values_should_skip_parts(void **state)
{
    (void)state;
    /* sqrt(x) - 0.5 on [-1, 1]: NaN left of 0 */
    mm_roots_root r[21];
    mm_roots_result res;
    assert_int_equal(run(f_sqrt, NULL, -1, 1, 20, 1e-12, r, 21, NULL, &res, NULL), MM_OK);
    assert_int_equal(res.nroots, 1);
    check_abs(r[0].x, 0.25, 1e-12, "root of sqrt(x) = 1/2");
    assert_true(res.nskipped >= 1);
}

static void bad_input_should_name_the_parameter(void **state)
{
    (void)state;
    mm_roots_root r[4];
    mm_roots_result res;
    mm_error err;
    assert_int_equal(run(f_sin, NULL, 1, 1, 10, 1e-6, r, 4, NULL, &res, &err), MM_ERANGE);
    assert_string_equal(err.param, "b");
    assert_int_equal(run(f_sin, NULL, NAN, 1, 10, 1e-6, r, 4, NULL, &res, &err), MM_EVALUE);
    assert_string_equal(err.param, "a");
    assert_int_equal(run(f_sin, NULL, 0, INFINITY, 10, 1e-6, r, 4, NULL, &res, &err), MM_EVALUE);
    assert_string_equal(err.param, "b");
    assert_int_equal(run(f_sin, NULL, -DBL_MAX, DBL_MAX, 10, 1e-6, r, 4, NULL, &res, &err),
                     MM_ERANGE);                      /* b - a overflows */
    assert_string_equal(err.param, "b");
    assert_int_equal(run(f_sin, NULL, 0, 1, 0, 1e-6, r, 4, NULL, &res, &err), MM_ERANGE);
    assert_string_equal(err.param, "n");
    assert_int_equal(run(f_sin, NULL, 0, 1, MM_ROOTS_MAX_N + 1, 1e-6, r, 4, NULL, &res, &err),
                     MM_ERANGE);
    assert_string_equal(err.param, "n");
    assert_int_equal(run(f_sin, NULL, 0, 1, 10, 0, r, 4, NULL, &res, &err), MM_ERANGE);
    assert_string_equal(err.param, "tol");
    assert_int_equal(run(f_sin, NULL, 0, 1, 10, NAN, r, 4, NULL, &res, &err), MM_ERANGE);
    assert_string_equal(err.param, "tol");
    assert_int_equal(res.nevals, 0);                 /* checked before any call */
    mm_roots_problem prob = {f_sin, NULL, 0, 1};
    mm_roots_options opt;
    mm_roots_options_init(&opt);
    opt.max_iter = 0;
    assert_int_equal(mm_roots_check(&prob, &opt, &err), MM_ERANGE);
    assert_string_equal(err.param, "max_iter");
    /* more roots than room: sin on [-10, 10] has 7, give room for 3 */
    assert_int_equal(run(f_sin, NULL, -10, 10, 100, 1e-6, r, 3, NULL, &res, &err), MM_ERANGE);
    assert_string_equal(err.param, "n");
    assert_int_equal(res.nroots, 3);
}

static void callback_failure_should_stop_the_search(void **state)
{
    (void)state;
    mm_roots_root r[11];
    mm_roots_result res;
    mm_error err;
    int code = MM_ENONFINITE;
    assert_int_equal(run(f_fails, &code, -1, 1, 10, 1e-6, r, 11, NULL, &res, &err), MM_ENONFINITE);
    assert_string_equal(err.param, "f");
    code = 42;                                       /* not an MM_E* code */
    assert_int_equal(run(f_fails, &code, -1, 1, 10, 1e-6, r, 11, NULL, &res, &err), MM_EVALUE);
    assert_non_null(strstr(err.msg, "could not be evaluated"));
}

static int f_triple(double x, double *fx, void *params)
{
    (void)params;
    *fx = (x - 1) * (x - 1) * (x - 1);
    return 0;
}

static int f_sinpi(double x, double *fx, void *params)
{
    (void)params;
    *fx = sin(PI * x);
    return 0;
}

/* Issue 10 #5: a triple root to 1e-12 needed 109-146 Brent steps, over the
 * cap of 100; with the forced bisection it takes at most 4 log2(w / tol) + 4 */
static void multiple_roots_should_converge_within_the_bisection_bound(void **state)
{
    (void)state;
    double x, fx, w;
    int iter = 0;
    double lo = 0.98, hi = 1.09, tol = 1e-12, f0, f1;
    f_triple(lo, &f0, NULL);
    f_triple(hi, &f1, NULL);
    assert_int_equal(mm_roots_brent(f_triple, NULL, lo, hi, f0, f1, tol, 1000, &x, &fx, &w, &iter, NULL, NULL),
                     MM_OK);
    check_abs(x, 1, tol, "the triple root");
    assert_true(iter <= 4 * ceil(log2((hi - lo) / tol)) + 4);
    /* through the scan with the default options: no MM_ENOCONV */
    mm_roots_problem prob = {.f = f_triple, .a = -1, .b = 10};
    mm_roots_options opt;
    mm_roots_options_init(&opt);
    opt.tol = tol;
    mm_roots_root r[101];
    mm_roots_result res = {.roots = r, .cap = 101};
    assert_int_equal(mm_roots_solve(&prob, &opt, &res, NULL), MM_OK);
    assert_int_equal(res.nroots, 1);
    check_abs(r[0].x, 1, tol, "the triple root, scanned");
    assert_int_equal(r[0].part, 18);                 /* -1 + 11 * 18 / 100 = 0.98 <= 1 < 1.09 */
}

/* Issue 10 #5: sin(pi x) at the integers is 1.2e-16 k, not 0 (pi is
 * rounded): tiny values at the ends of the parts are not a jump */
static void roots_beside_rounding_noise_should_not_be_suspect(void **state)
{
    (void)state;
    mm_roots_problem prob = {.f = f_sinpi, .a = -1, .b = 10};
    mm_roots_options opt;
    mm_roots_options_init(&opt);
    opt.n = 11;
    opt.tol = 1e-12;
    mm_roots_root r[12];
    mm_roots_result res = {.roots = r, .cap = 12};
    assert_int_equal(mm_roots_solve(&prob, &opt, &res, NULL), MM_OK);
    for (int i = 0; i < res.nroots; i++) {
        assert_false(r[i].flags & MM_ROOTS_SUSPECT);
        check_abs(r[i].x, round(r[i].x), 1e-12, "a root at an integer");
    }
}

static int f_cube_err(double x, double *fx, double *err, void *params)
{
    (void)params;
    *fx = (x - 1) * (x - 1) * (x - 1);
    *err = 1e-16;                                   /* a rounding level for f */
    return 0;
}

static void bisection_and_the_rounding_band_should_bound_the_root(void **state)
{
    (void)state;
    double x, f0;
    f_book(0, &f0, NULL);
    assert_int_equal(mm_roots_bisect(f_book, NULL, 0, 2, f0, 1e-10, &x, NULL), MM_OK);
    check_abs(x, 1.0433859882095546576, 1e-10, "bisection to 1e-10");
    /* a triple root with f known to 1e-16: its sign is blurred within about
     * (1e-16)^(1/3) = 4.6e-6 of the root */
    double band = mm_roots_band(f_cube_err, NULL, 1, 1e-12, 0, 2);
    assert_true(band >= 4.6e-6 && band <= 4 * 4.6e-6);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(book_example_should_find_the_single_root),
        cmocka_unit_test(sine_should_give_all_seven_multiples_of_pi),
        cmocka_unit_test(tangent_pole_should_not_be_a_root),
        cmocka_unit_test(root_on_a_subdivision_point_should_be_reported_once),
        cmocka_unit_test(brent_iterations_should_stay_bounded),
        cmocka_unit_test(jump_should_be_flagged_suspect),
        cmocka_unit_test(multiple_roots_should_converge_within_the_bisection_bound),
        cmocka_unit_test(roots_beside_rounding_noise_should_not_be_suspect),
        cmocka_unit_test(bisection_and_the_rounding_band_should_bound_the_root),
        cmocka_unit_test(touching_root_should_not_be_found),
        cmocka_unit_test(non_finite_values_should_skip_parts),
        cmocka_unit_test(bad_input_should_name_the_parameter),
        cmocka_unit_test(callback_failure_should_stop_the_search),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
