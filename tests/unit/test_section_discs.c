/* test_section_discs.c — a polygon with discs added or cut out
 * (mm_section_with_discs) against the closed forms of a square with a
 * central hole and with a disc beside it (parallel axes written out), and
 * the validity test of the discs (mm_section_discs_check) on each fault. */
#include "mm_test.h"

#include <float.h>
#include <string.h>

#include "mm_section.h"

#define EPS DBL_EPSILON

static const double square[8] = {0, 0, 2, 0, 2, 2, 0, 2};   /* side 2, centroid (1, 1), I = 16/12 */

static void a_hole_and_a_disc_should_meet_their_closed_forms(void **state)
{
    (void)state;
    mm_section_props sq, p;
    assert_int_equal(mm_section_polygon(4, square, &sq, NULL, NULL), MM_OK);
    double hole[3] = {1, 1, -0.5}, a = M_PI * 0.25, J = M_PI * pow(0.5, 4) / 4;
    assert_int_equal(mm_section_with_discs(&sq, 1, hole, &p, NULL), MM_OK);
    check_rel(p.A, 4 - a, 8 * EPS, "area: square less the hole");
    check_abs(p.xc, 1, 8 * EPS, "centroid stays in the middle"), check_abs(p.yc, 1, 8 * EPS, "yc");
    check_rel(p.Ixx, 16.0 / 12 - J, 16 * EPS, "Ixx = a^4/12 - pi r^4/4");
    check_rel(p.Iyy, 16.0 / 12 - J, 16 * EPS, "Iyy");
    check_abs(p.Ixy, 0, 16 * EPS, "Ixy: symmetric");
    /* a disc r = 0.5 at (4, 1): xc = (4 * 1 + a * 4) / (4 + a) */
    double disc[3] = {4, 1, 0.5}, A = 4 + a, xc = (4 + 4 * a) / A;
    assert_int_equal(mm_section_with_discs(&sq, 1, disc, &p, NULL), MM_OK);
    check_rel(p.A, A, 8 * EPS, "area: square and disc");
    check_rel(p.xc, xc, 8 * EPS, "centroid between them");
    check_rel(p.Ixx, 16.0 / 12 + J, 16 * EPS, "Ixx: both centred on y = 1");
    check_rel(p.Iyy, 16.0 / 12 + 4 * (1 - xc) * (1 - xc) + J + a * (4 - xc) * (4 - xc), 16 * EPS,
              "Iyy by the parallel-axis theorem");
    check_abs(p.Ixy, 0, 64 * EPS, "Ixy: symmetric about y = 1");
}

static void each_fault_of_the_discs_should_be_named(void **state)
{
    (void)state;
    mm_error err;
    double ok[6] = {1, 1, -0.5, 4, 1, 0.5};
    assert_int_equal(mm_section_discs_check(4, square, 2, ok, &err), MM_OK);
    struct { double d[6]; int n; const char *needle; } bad[] = {
        {{1, 1, 0}, 1, "disc 1 has radius 0"},
        {{1, 1, -1.2}, 1, "it reaches 0.2 m past an edge"},         /* the hole pokes out 0.2 */
        {{3, 3, -0.5}, 1, "hole 1 (radius 0.5 at 3, 3) must lie inside"},
        {{2.3, 1, 0.5}, 1, "disc 1 (radius 0.5 at 2.3, 1) must lie outside"},
        {{1, 1, 0.2}, 1, "must lie outside the polygon"},
        {{4, 1, 0.5, 4.8, 1, 0.5}, 2, "discs 1 and 2 overlap"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        assert_int_equal(mm_section_discs_check(4, square, bad[i].n, bad[i].d, &err), MM_ERANGE);
        assert_string_equal(err.param, "circles");
        if (!strstr(err.msg, bad[i].needle))
            fail_msg("case %zu: \"%s\" lacks \"%s\"", i, err.msg, bad[i].needle);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_hole_and_a_disc_should_meet_their_closed_forms),
        cmocka_unit_test(each_fault_of_the_discs_should_be_named),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
