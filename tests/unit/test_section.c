/* test_section.c — plane areas against closed forms: rectangles,
 * triangles, an L, a rotated rectangle's principal axes, a square with a
 * hole; either orientation; far from the origin; the self-intersecting
 * polygons that must be refused, with the edges named. */
#include "mm_test.h"

#include <float.h>
#include <string.h>

#include "mm_section.h"

#define EPS DBL_EPSILON

static void rectangle_should_give_bh3_over_12_in_either_orientation(void **state)
{
    (void)state;
    const double b = 3, h = 0.5, x0 = 2, y0 = -1;
    double ccw[8] = {x0, y0, x0 + b, y0, x0 + b, y0 + h, x0, y0 + h}, cw[8];
    for (int k = 0; k < 4; k++)
        cw[2 * k] = ccw[2 * (3 - k)], cw[2 * k + 1] = ccw[2 * (3 - k) + 1];
    for (int pass = 0; pass < 2; pass++) {
        mm_section_props p;
        int o;
        assert_int_equal(mm_section_polygon(4, pass ? cw : ccw, &p, &o, NULL), MM_OK);
        assert_int_equal(o, pass ? -1 : 1);
        /* a handful of roundings of terms of size b^3 h: 16 eps */
        check_rel(p.A, b * h, 8 * EPS, "A = b h");
        check_rel(p.xc, x0 + b / 2, 8 * EPS, "xc at mid-width");
        check_rel(p.yc, y0 + h / 2, 8 * EPS, "yc at mid-height");
        check_rel(p.Ixx, b * h * h * h / 12, 32 * EPS, "Ixx = b h^3 / 12");
        check_rel(p.Iyy, h * b * b * b / 12, 32 * EPS, "Iyy = h b^3 / 12");
        check_abs(p.Ixy, 0, 32 * EPS * p.Iyy, "Ixy = 0 by symmetry");
        check_abs(p.alpha, M_PI / 2, 0, "I1 about the axis parallel to y");
    }
}

static void the_l_section_should_equal_its_two_rectangles(void **state)
{
    (void)state;
    /* sta-centroid's default: 4 x 1 foot and 1 x 2 leg above its left end */
    const double L[12] = {0, 0, 4, 0, 4, 1, 1, 1, 1, 3, 0, 3};
    mm_section_props p, r[2], c;
    assert_int_equal(mm_section_polygon(6, L, &p, NULL, NULL), MM_OK);
    /* by hand: A = 4 + 2 = 6, xc = (4*2 + 2*0.5)/6 = 1.5, yc = (4*0.5 + 2*2)/6 = 1 */
    check_rel(p.A, 6, 8 * EPS, "A by hand");
    check_rel(p.xc, 1.5, 8 * EPS, "xc by hand");
    check_rel(p.yc, 1, 8 * EPS, "yc by hand");
    /* Ixx = 4/12 + 4 (0.5)^2 + 1*8/12 + 2 (1)^2 = 1/3 + 1 + 2/3 + 2 = 4;
     * Iyy = 64/12 + 4 (0.5)^2 + 2/12 + 2 (1)^2 = 16/3 + 1 + 1/6 + 2 = 8.5;
     * Ixy = 4 (0.5)(-0.5) + 2 (-1)(1) = -3 */
    check_rel(p.Ixx, 4, 32 * EPS, "Ixx by the parallel-axis theorem");
    check_rel(p.Iyy, 8.5, 32 * EPS, "Iyy by the parallel-axis theorem");
    check_rel(p.Ixy, -3, 32 * EPS, "Ixy by the parallel-axis theorem");
    const double foot[8] = {0, 0, 4, 0, 4, 1, 0, 1}, leg[8] = {0, 1, 1, 1, 1, 3, 0, 3};
    mm_section_polygon(4, foot, &r[0], NULL, NULL);
    mm_section_polygon(4, leg, &r[1], NULL, NULL);
    int sign[2] = {1, 1};
    assert_int_equal(mm_section_combine(2, r, sign, &c, NULL), MM_OK);
    check_rel(c.Ixy, p.Ixy, 32 * EPS, "composite = polygon");
    /* principal: mean 6.25, R = hypot(-2.25, -3) = 3.75: I1 = 10, I2 = 2.5 */
    double m = (4 + 8.5) / 2, d = (4 - 8.5) / 2, R = hypot(d, 3);
    check_rel(R, 3.75, 4 * EPS, "Mohr's radius of the L");
    check_rel(p.I1, m + R, 32 * EPS, "I1 = mean + R (Mohr)");
    check_rel(p.I2, m - R, 64 * EPS, "I2 = mean - R (Mohr)");
    check_rel(p.alpha, 0.5 * atan2(6, 2 * d), 32 * EPS, "tan 2 alpha = -2 Ixy / (Ixx - Iyy)");
}

static void a_right_triangle_should_give_its_textbook_moments(void **state)
{
    (void)state;
    const double b = 2, h = 3, t[6] = {0, 0, b, 0, 0, h};
    mm_section_props p, q;
    mm_section_triangle(t, t + 2, t + 4, &p);
    check_rel(p.A, b * h / 2, 4 * EPS, "A = b h / 2");
    check_rel(p.Ixx, b * h * h * h / 36, 16 * EPS, "Ixx = b h^3 / 36");
    check_rel(p.Iyy, h * b * b * b / 36, 16 * EPS, "Iyy = h b^3 / 36");
    check_rel(p.Ixy, -b * b * h * h / 72, 16 * EPS, "Ixy = -b^2 h^2 / 72");
    assert_int_equal(mm_section_polygon(3, t, &q, NULL, NULL), MM_OK);
    check_rel(q.Ixy, p.Ixy, 16 * EPS, "Green's theorem = the triangle formula");
}

static void a_rotated_rectangle_should_have_its_long_axis_principal(void **state)
{
    (void)state;
    const double b = 4, h = 1;
    for (int k = -5; k <= 5; k++) {
        double t = k * 0.3, c = cos(t), s = sin(t), xy[8];
        const double loc[8] = {-b / 2, -h / 2, b / 2, -h / 2, b / 2, h / 2, -b / 2, h / 2};
        for (int v = 0; v < 4; v++) {
            xy[2 * v] = 10 + c * loc[2 * v] - s * loc[2 * v + 1];
            xy[2 * v + 1] = 5 + s * loc[2 * v] + c * loc[2 * v + 1];
        }
        mm_section_props p;
        assert_int_equal(mm_section_polygon(4, xy, &p, NULL, NULL), MM_OK);
        check_rel(p.I1, h * b * b * b / 12, 64 * EPS, "I1 = h b^3 / 12 whatever the turn");
        check_rel(p.I2, b * h * h * h / 12, 256 * EPS, "I2 = b h^3 / 12");
        /* the I1 axis is across the long side: at t + pi/2, folded into (-pi/2, pi/2] */
        double want = t + M_PI / 2;
        while (want > M_PI / 2)
            want -= M_PI;
        check_abs(p.alpha, want, 64 * EPS, "alpha = t + pi/2 folded");
        assert_true(p.alpha > -M_PI / 2 && p.alpha <= M_PI / 2);
    }
}

static void a_polygon_far_from_the_origin_should_keep_its_digits(void **state)
{
    (void)state;
    const double off = 1e6, b = 2, h = 1;
    double xy[8] = {off, off, off + b, off, off + b, off + h, off, off + h};
    mm_section_props p;
    assert_int_equal(mm_section_polygon(4, xy, &p, NULL, NULL), MM_OK);
    /* relative to the mean vertex, the terms are of size b^3 h: 32 eps */
    check_rel(p.Ixx, b * h * h * h / 12, 32 * EPS, "Ixx at 1e6 m from the origin");
    check_rel(p.Iyy, h * b * b * b / 12, 32 * EPS, "Iyy at 1e6 m from the origin");
}

static void a_square_with_a_hole_should_lose_pi_r4_over_4(void **state)
{
    (void)state;
    const double a = 2, r = 0.5, sq[8] = {0, 0, a, 0, a, a, 0, a};
    mm_section_props part[2], c;
    mm_section_polygon(4, sq, &part[0], NULL, NULL);
    mm_section_disc(a / 2, a / 2, r, &part[1]);
    int sign[2] = {1, -1};
    assert_int_equal(mm_section_combine(2, part, sign, &c, NULL), MM_OK);
    check_rel(c.A, a * a - M_PI * r * r, 8 * EPS, "A = a^2 - pi r^2");
    check_rel(c.Ixx, a * a * a * a / 12 - M_PI * r * r * r * r / 4, 16 * EPS, "Ixx = a^4/12 - pi r^4/4");
    check_abs(c.alpha, 0, 0, "a square's axes are all principal: alpha = 0");
    int sign2[2] = {-1, -1};
    mm_error err;
    assert_int_equal(mm_section_combine(2, part, sign2, &c, &err), MM_ERANGE);
}

static void self_intersecting_polygons_should_be_refused_with_the_edges_named(void **state)
{
    (void)state;
    mm_error err;
    mm_section_props p;
    const double bowtie[8] = {0, 0, 2, 2, 2, 0, 0, 2};
    assert_int_equal(mm_section_polygon(4, bowtie, &p, NULL, &err), MM_ERANGE);
    assert_string_equal(err.param, "polygon");
    assert_non_null(strstr(err.msg, "crosses itself"));
    assert_non_null(strstr(err.msg, "edge 1-2 meets edge 3-4 at (1, 1)"));
    mm_section_fault f;
    assert_int_equal(mm_section_simple(4, bowtie, &f), 0);
    check_abs(f.x, 1, 0, "crossing x");
    /* a vertex touching another edge */
    const double touch[10] = {0, 0, 4, 0, 4, 2, 2, 0, 0, 2};
    assert_int_equal(mm_section_simple(5, touch, NULL), 0);
    /* a repeated vertex */
    const double rep[8] = {0, 0, 1, 0, 1, 0, 0, 1};
    assert_int_equal(mm_section_polygon(4, rep, &p, NULL, &err), MM_ERANGE);
    assert_non_null(strstr(err.msg, "same point"));
    /* all on one line */
    const double flat[6] = {0, 0, 1, 1, 2, 2};
    assert_int_equal(mm_section_polygon(3, flat, &p, NULL, &err), MM_ERANGE);
    /* an edge folding back on the previous one */
    const double fold[8] = {0, 0, 2, 0, 1, 0, 1, 1};
    assert_int_equal(mm_section_simple(4, fold, NULL), 0);
    assert_int_equal(mm_section_polygon(2, flat, &p, NULL, &err), MM_ERANGE);
}

static void ear_clipping_should_tile_a_comb_exactly(void **state)
{
    (void)state;
    /* a comb: a base 9 x 1 with five teeth 1 wide and 2 high, counter-clockwise */
    const double full[40] = {0, 0, 9, 0, 9, 3, 8, 3, 8, 1, 7, 1, 7, 3, 6, 3, 6, 1, 5, 1,
                             5, 3, 4, 3, 4, 1, 3, 1, 3, 3, 2, 3, 2, 1, 1, 1, 1, 3, 0, 3};
    int n = 20;
    mm_section_props g, parts[40], c;
    assert_int_equal(mm_section_polygon(n, full, &g, NULL, NULL), MM_OK);
    check_rel(g.A, 9 + 5 * 2, 16 * EPS, "comb area 9 + 5 teeth of 2");
    int tri[3 * 40], sign[40];
    int nt = mm_section_triangulate(n, full, tri);
    assert_int_equal(nt, n - 2);
    for (int k = 0; k < nt; k++) {
        mm_section_triangle(full + 2 * tri[3 * k], full + 2 * tri[3 * k + 1], full + 2 * tri[3 * k + 2], &parts[k]);
        sign[k] = 1;
    }
    assert_int_equal(mm_section_combine(nt, parts, sign, &c, NULL), MM_OK);
    check_rel(c.A, g.A, 64 * EPS, "the triangles tile the comb");
    check_rel(c.Ixx, g.Ixx, 256 * EPS, "Ixx by triangles = Green");
    check_rel(c.Iyy, g.Iyy, 256 * EPS, "Iyy by triangles = Green");
    check_abs(c.Ixy, g.Ixy, 256 * EPS * g.Iyy, "Ixy by triangles = Green");
}

static void inside_should_tell_a_hole_from_a_point_outside(void **state)
{
    (void)state;
    const double sq[8] = {0, 0, 2, 0, 2, 2, 0, 2};
    double d;
    assert_int_equal(mm_section_inside(4, sq, 1, 1, &d), 1);
    check_abs(d, 1, 0, "centre: 1 from every edge");
    assert_int_equal(mm_section_inside(4, sq, 3, 1, &d), 0);
    check_abs(d, 1, 0, "outside: 1 from the right edge");
    assert_int_equal(mm_section_inside(4, sq, 2, 1, &d), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(rectangle_should_give_bh3_over_12_in_either_orientation),
        cmocka_unit_test(the_l_section_should_equal_its_two_rectangles),
        cmocka_unit_test(a_right_triangle_should_give_its_textbook_moments),
        cmocka_unit_test(a_rotated_rectangle_should_have_its_long_axis_principal),
        cmocka_unit_test(a_polygon_far_from_the_origin_should_keep_its_digits),
        cmocka_unit_test(a_square_with_a_hole_should_lose_pi_r4_over_4),
        cmocka_unit_test(self_intersecting_polygons_should_be_refused_with_the_edges_named),
        cmocka_unit_test(ear_clipping_should_tile_a_comb_exactly),
        cmocka_unit_test(inside_should_tell_a_hole_from_a_point_outside),
    };
    return cmocka_run_group_tests_name("section", tests, NULL, NULL);
}
