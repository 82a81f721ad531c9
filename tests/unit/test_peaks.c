/* test_peaks.c — mm_peaks against signals whose extrema are known: the
 * peaks of cos(t) (at k pi, of height +-1) from 32 samples a period, to the
 * interpolation's error; a parabola's minimum placed exactly; minima
 * within the gap merged, above the level ignored. */
#include "mm_test.h"

#include <float.h>

#include "mm_peaks.h"

static void hermite_peaks_of_a_cosine_should_be_at_k_pi(void **state)
{
    (void)state;
    enum { N = 3 * 32 + 1, CAP = 16 };
    double t[N], x[N], v[N], tp[CAP], xp[CAP], h = 2 * M_PI / 32;
    for (int i = 0; i < N; i++) {
        t[i] = 0.1 + h * i;                       /* not on an extremum */
        x[i] = cos(t[i]);
        v[i] = -sin(t[i]);
    }
    int np = mm_peaks_hermite(N, t, x, v, 0, CAP, tp, xp);
    assert_int_equal(np, 6);                      /* pi .. 6 pi over (0.1, 0.1 + 6 pi) */
    for (int k = 0; k < np; k++) {
        /* v's linear zero is off by O(h^3) (v'' vanishes at v's zero):
         * measured 5.9e-6, h^3/256 = 3e-5; the Hermite value off by that
         * squared over 2 and the cubic's own error, O(h^4): measured 3.9e-6 */
        check_abs(tp[k], (k + 1) * M_PI, h * h * h / 256, "peak time");
        check_abs(xp[k], k % 2 ? 1 : -1, h * h * h * h / 128 + h * h * h * h / 384, "peak value");
    }
    /* from t_from on, and at most cap */
    assert_int_equal(mm_peaks_hermite(N, t, x, v, 2 * M_PI, CAP, tp, xp), 4);
    assert_int_equal(mm_peaks_hermite(N, t, x, v, 0, 2, tp, xp), 2);
}

static void minima_should_sit_at_the_parabolas_vertex(void **state)
{
    (void)state;
    /* y = (t - 1.3)^2 + 0.5 sampled about 1.3; two dips 0.45 apart about
     * 4.2 (one when the gap is 1); y = (t - 8)^2 + 3 about 8 (above level 2) */
    double t[] = {0.7, 1.1, 1.5, 2.2, 3.8, 4.0, 4.1, 4.3, 4.45, 4.6, 7.6, 8.1, 8.9};
    double y[13] = {0, 0, 0, 0, 1.0, 0.3, 0.5, 0.4, 0.2, 0.9};
    for (int i = 0; i < 4; i++)
        y[i] = (t[i] - 1.3) * (t[i] - 1.3) + 0.5;
    for (int i = 10; i < 13; i++)
        y[i] = (t[i] - 8) * (t[i] - 8) + 3;
    double tm[4], ym[4];
    int nm = mm_peaks_minima(13, t, y, 2, 1, 4, tm, ym);
    assert_int_equal(nm, 2);
    check_abs(tm[0], 1.3, 8 * DBL_EPSILON, "the vertex of the sampled parabola");
    assert_true(ym[0] == y[1]);
    assert_true(tm[1] > 4.3 && tm[1] < 4.6 && ym[1] == 0.2);              /* the lower of the two dips */
    assert_int_equal(mm_peaks_minima(13, t, y, 2, 0.1, 4, tm, ym), 3);    /* a small gap keeps both */
    /* Numerical Recipes' form (10.3.1): b - (1/2) [(b-a)^2 (fb-fc) - (b-c)^2 (fb-fa)] /
     * [(b-a)(fb-fc) - (b-c)(fb-fa)] through (3.8, 1), (4, 0.3), (4.1, 0.5) */
    double num = 0.2 * 0.2 * (0.3 - 0.5) - 0.1 * 0.1 * (0.3 - 1.0), den = 0.2 * (0.3 - 0.5) + 0.1 * (0.3 - 1.0);
    check_abs(tm[1], 4.0 - 0.5 * num / den, 16 * DBL_EPSILON, "the first dip's vertex, written out");
    assert_int_equal(mm_peaks_minima(13, t, y, 10, 1, 4, tm, ym), 3);     /* a high level lets 8 in */
    check_abs(tm[2], 8, 16 * DBL_EPSILON, "the vertex of the third parabola");
    assert_int_equal(mm_peaks_minima(13, t, y, 10, 1, 2, tm, ym), 2);     /* at most cap */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(hermite_peaks_of_a_cosine_should_be_at_k_pi),
        cmocka_unit_test(minima_should_sit_at_the_parabolas_vertex),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
