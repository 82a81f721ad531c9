/* test_samples.c — mm_samples against closed forms: the chord of x^2, the
 * peak of sin x, the trapezoid rule on a line (exact) and on x^2 (its
 * error term (b - a) h^2 f'' / 12). */
#include "mm_test.h"

#include <float.h>

#include "mm_samples.h"

static int square(double x, double *fx, void *ctx)
{
    ++*(int *)ctx;
    *fx = x * x;
    return 0;
}

static double sine(double x, double *err, void *ctx)
{
    (void)ctx;
    if (err)
        *err = DBL_EPSILON;
    return sin(x);
}

/* x^2 sampled at 0, 1, 2: at the fraction g of a unit step the chord is
 * above the parabola by g (1 - g), the same on both steps (the first wins) */
static void chord_deviation_of_a_parabola_should_be_g_times_one_minus_g(void **state)
{
    (void)state;
    const double x[] = {0, 1, 2, 3}, y[] = {0, 1, 4, NAN};
    const double g = (3 - sqrt(5.0)) / 2;
    int calls = 0;
    double at, dev = mm_samples_chord_deviation(square, &calls, 4, x, y, &at);
    check_rel(dev, g * (1 - g), 1e-14, "g (1 - g)");
    check_rel(at, g, 1e-15, "on the first step");
    assert_int_equal(calls, 2);                         /* no call beside the NaN sample */
}

/* sin x sampled every 0.5 on [0, 2 pi]: the largest sample is at 1.5, the
 * refined peak pi / 2 with the value 1 */
static void the_best_candidate_should_refine_to_the_peak(void **state)
{
    (void)state;
    mm_samples_cand cd[2][MM_SAMPLES_NCAND] = {{{0}}};
    enum { N = 13 };
    double x[N], y[N];
    for (int i = 0; i < N; i++) {
        x[i] = 0.5 * i;
        y[i] = sin(x[i]);
    }
    mm_samples_offer_scan(cd, N, x, y, 0.5, 1);
    check_abs(cd[0][0].x, 1.5, 0, "the largest sample");
    check_abs(cd[1][0].x, 4.5, 0, "the smallest sample (sin 4.5 = -0.977)");
    check_abs(cd[0][1].x, 6, 0, "the end x = 6 beats its one neighbour: a local maximum too");
    assert_true(cd[0][2].h == 0);                       /* and no other */
    double xm = 1.5, vm = y[3], xe, ve;
    int from_plot;
    mm_samples_best(sine, NULL, 1, cd[0], 0, 6, &xm, &vm, &xe, &ve, &from_plot);
    check_abs(xm, M_PI / 2, fmax(xe, 1e-7), "x of the peak within its error");
    check_abs(vm, 1, fmax(ve, 4 * DBL_EPSILON), "the peak value");
    assert_true(xe < 1e-6);                             /* flat top: sqrt(4 eps / 1) = 3e-8 */
    assert_int_equal(from_plot, 1);
    /* a sample that is not finite is no candidate, and its neighbours see an
     * end there: with sin 1.5 left out, 1.0 and 2.0 both become maxima */
    mm_samples_cand c2[2][MM_SAMPLES_NCAND] = {{{0}}};
    y[3] = NAN;
    mm_samples_offer_scan(c2, N, x, y, 0.5, 0);
    check_abs(c2[0][0].x, 2.0, 0, "sin 2 = 0.909 > sin 1 = 0.841");
    check_abs(c2[0][1].x, 1.0, 0, "sin 1 beside the gap");
    assert_int_equal(c2[0][0].from_plot, 0);
    /* an empty list leaves the sample as it was */
    mm_samples_cand none[MM_SAMPLES_NCAND] = {{0}};
    xm = 1.5;
    mm_samples_best(sine, NULL, 1, none, 0, 6, &xm, &vm, &xe, &ve, &from_plot);
    assert_true(xm == 1.5 && xe == 0 && ve == 0 && from_plot == 1);
}

static void trapezoid_should_follow_its_error_term(void **state)
{
    (void)state;
    enum { N = 11 };
    double y[N], e;
    for (int i = 0; i < N; i++)
        y[i] = 0.1 * i;                                 /* y = x on [0, 1]: exact, 1/2 */
    double t = mm_samples_trapezoid(N, 0, 1, y, 0, &e);
    check_abs(t, 0.5, e, "a line, within the rounding");
    assert_true(e < 2 * DBL_EPSILON);
    for (int i = 0; i < N; i++)
        y[i] = 0.01 * i * i;                            /* x^2: 1/3 + h^2 / 6 = 1/3 + 1/600 */
    t = mm_samples_trapezoid(N, 0, 1, y, 1e-10, &e);
    check_rel(t, 1.0 / 3 + 1.0 / 600, 1e-15, "(b - a) h^2 f'' / 12");
    check_rel(e, 2e-10, 1e-5, "twice the samples' rounding over b - a dominates");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(chord_deviation_of_a_parabola_should_be_g_times_one_minus_g),
        cmocka_unit_test(the_best_candidate_should_refine_to_the_peak),
        cmocka_unit_test(trapezoid_should_follow_its_error_term),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
