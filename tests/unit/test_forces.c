/* test_forces.c — mm_forces_resultant against what statics says of any
 * force system: a couple's moment is F d about every point, a force has no
 * moment about a point of its line, the moment moves by (B1 - B2) x R
 * between two points (the transfer theorem), and the term sizes are the
 * sums written out. */
#include "mm_test.h"

#include <float.h>

#include "mm_forces.h"

#define EPS DBL_EPSILON

static void a_couple_should_have_the_same_moment_about_every_point(void **state)
{
    (void)state;
    /* +F z at (0, 0, 0) and -F z at (d, 0, 0): R = 0, M = (0, F d, 0) */
    double F = 300, d = 0.7, f[12] = {0, 0, 0, 0, 0, F, d, 0, 0, 0, 0, -F};
    double pts[3][3] = {{0, 0, 0}, {5, -2, 1}, {-1e3, 4e2, 7}};
    for (int k = 0; k < 3; k++) {
        mm_forces_sum s;
        mm_forces_resultant(2, f, 0, NULL, pts[k], &s);
        check_abs(s.R[0] + fabs(s.R[1]) + fabs(s.R[2]), 0, 0, "R = 0 exactly");
        check_abs(s.M[0], 0, 4 * EPS * s.sum_M, "Mx");
        check_rel(s.M[1], F * d, 4 * EPS * s.sum_M / (F * d), "My = F d");
        check_abs(s.M[2], 0, 4 * EPS * s.sum_M, "Mz");
    }
}

static void a_force_should_have_no_moment_about_its_line(void **state)
{
    (void)state;
    double f[6] = {1, 2, 3, 4, -5, 6};
    for (double t = -2; t <= 2; t += 0.5) {
        double B[3] = {1 + t * 4, 2 - t * 5, 3 + t * 6};
        mm_forces_sum s;
        mm_forces_resultant(1, f, 0, NULL, B, &s);
        /* B on the line: r - B = -t F, rounded to a few eps of |r| + |t F| */
        double big = sqrt(14.0) + fabs(t) * sqrt(77.0);
        for (int k = 0; k < 3; k++)
            check_abs(s.M[k], 0, 8 * EPS * big * sqrt(77.0), "moment about a point of the line");
        check_abs(s.reach, fabs(t) * sqrt(77.0), 8 * EPS * big, "reach |r - B| = |t| |F|");
    }
}

static void the_moment_should_move_by_the_transfer_theorem(void **state)
{
    (void)state;
    double f[18] = {0, 0, 0, 0, 0, 100, 2, 0, 0, 0, 50, 0, 0, 1, 0, 30, 0, 0}, c[3] = {5, -7, 11};
    double B1[3] = {0.3, -1.2, 2.5}, B2[3] = {-4, 0.5, 1};
    mm_forces_sum s1, s2;
    mm_forces_resultant(3, f, 1, c, B1, &s1);
    mm_forces_resultant(3, f, 1, c, B2, &s2);
    /* M_B2 = M_B1 + (B1 - B2) x R */
    double d[3] = {B1[0] - B2[0], B1[1] - B2[1], B1[2] - B2[2]}, *R = s1.R;
    double want[3] = {s1.M[0] + d[1] * R[2] - d[2] * R[1], s1.M[1] + d[2] * R[0] - d[0] * R[2],
                      s1.M[2] + d[0] * R[1] - d[1] * R[0]};
    for (int k = 0; k < 3; k++)
        check_abs(s2.M[k], want[k], 16 * EPS * (s1.sum_M + s2.sum_M), "transfer theorem");
    check_abs(s1.R[0], 30, 0, "Rx exact"), check_abs(s1.R[1], 50, 0, "Ry"), check_abs(s1.R[2], 100, 0, "Rz");
    check_abs(s1.sum_F, 180, 0, "sum of |F| = 100 + 50 + 30");
    check_rel(s1.sum_M, sqrt(0.09 + 1.44 + 6.25) * 100 + sqrt(2.89 + 1.44 + 6.25) * 50 +
                            sqrt(0.09 + 4.84 + 6.25) * 30 + sqrt(25 + 49 + 121.0), 4 * EPS, "sum of the terms' sizes");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_couple_should_have_the_same_moment_about_every_point),
        cmocka_unit_test(a_force_should_have_no_moment_about_its_line),
        cmocka_unit_test(the_moment_should_move_by_the_transfer_theorem),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
