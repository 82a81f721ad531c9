/* test_geom_angle.c — mm_geom_angle3, the angle between two vectors in
 * space, against angles known in closed form, including the tiny and
 * nearly straight ones where acos of the cosine fails. */
#include "mm_test.h"

#include <float.h>

#include "mm_geom.h"

#define EPS DBL_EPSILON

static void known_angles_should_come_out(void **state)
{
    (void)state;
    double x[3] = {1, 0, 0}, y[3] = {0, 2, 0}, d[3] = {1, 1, 0}, s[3] = {1, sqrt(3.0), 0}, mx[3] = {-3, 0, 0};
    double g[3] = {1, 1, 1}, z[3] = {0, 0, 5};
    /* a few eps: atan2 and the rounding of the inputs (sqrt 3) */
    check_abs(mm_geom_angle3(x, y), M_PI / 2, 4 * EPS, "x and y: a right angle");
    check_abs(mm_geom_angle3(x, d), M_PI / 4, 4 * EPS, "x and the diagonal of the xy square");
    check_abs(mm_geom_angle3(x, s), M_PI / 3, 4 * EPS, "x and (1, sqrt 3, 0): 60 degrees");
    check_abs(mm_geom_angle3(s, x), M_PI / 3, 4 * EPS, "symmetric in a and b");
    check_abs(mm_geom_angle3(x, mx), M_PI, 4 * EPS, "opposite: pi");
    check_abs(mm_geom_angle3(x, x), 0, 0, "a vector with itself: exactly 0");
    /* the diagonal of the cube and an edge: acos(1/sqrt 3) */
    check_abs(mm_geom_angle3(g, z), acos(1 / sqrt(3.0)), 8 * EPS, "cube diagonal and edge");
}

static void tiny_and_nearly_straight_angles_should_keep_their_digits(void **state)
{
    (void)state;
    /* (1, t, 0) makes atan(t) with x; acos(cos) would return 0 below t = 1e-8.
     * Down to 1e-143: below 1e-154 the square of |a x b| in its norm is
     * subnormal (the documented limit) */
    for (double t = 1e-3; t > 1e-150; t *= 1e-7) {
        double a[3] = {1, 0, 0}, b[3] = {1, t, 0}, c[3] = {-1, t, 0};
        check_rel(mm_geom_angle3(a, b), atan(t), 4 * EPS, "tiny angle atan(t), to a few eps relative");
        check_abs(M_PI - mm_geom_angle3(a, c), atan(t), 4 * EPS * M_PI, "pi less a tiny angle");
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(known_angles_should_come_out),
        cmocka_unit_test(tiny_and_nearly_straight_angles_should_keep_their_digits),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
