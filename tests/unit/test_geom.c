/* test_geom.c — mm_geom against closed forms: rotations (elementary,
 * Rodrigues, their logarithm), all twelve Euler sequences and their gimbal
 * lock, angular velocity from Euler rates against the derivative of R,
 * circle-circle / line-circle / line-line intersections (tangency included),
 * the circle through three points, and a polygon's section properties. */
#include "mm_test.h"

#include <float.h>
#include <string.h>

#include "mm_geom.h"

#define EPS DBL_EPSILON

static const int sequences[12][3] = {
    {2, 1, 2}, {2, 0, 2}, {0, 1, 0}, {0, 2, 0}, {1, 0, 1}, {1, 2, 1},   /* proper Euler */
    {2, 1, 0}, {0, 1, 2}, {1, 2, 0}, {0, 2, 1}, {2, 0, 1}, {1, 0, 2},   /* Tait-Bryan */
};

static double mat_diff(const double *A, const double *B)
{
    double d = 0;
    for (int i = 0; i < 9; i++)
        d = fmax(d, fabs(A[i] - B[i]));
    return d;
}

/* ---- rotations ----------------------------------------------------------------------- */

static void elementary_rotations_should_match_rodrigues_about_the_axes(void **state)
{
    (void)state;
    const mm_v3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int a = 0; a < 3; a++)
        for (double ang = -3; ang <= 3; ang += 0.37) {
            double R1[9], R2[9];
            mm_geom_rot_axis(a, ang, R1);
            assert_int_equal(mm_geom_rot_axis_angle(axes[a], ang, R2, NULL), MM_OK);
            /* two roundings of sin and cos: a few eps */
            check_abs(mat_diff(R1, R2), 0, 4 * EPS, "R_axis(angle) against Rodrigues");
        }
    /* Rz(pi/2) takes x to y */
    double R[9];
    mm_geom_rot_axis(2, M_PI / 2, R);
    mm_v3 y = mm_geom_m3_apply(R, (mm_v3){1, 0, 0});
    check_abs(y.x, 0, EPS, "Rz(pi/2) x: x-component");
    check_abs(y.y, 1, EPS, "Rz(pi/2) x: y-component");
}

static void rodrigues_should_give_a_rotation_whose_log_is_the_axis_and_angle(void **state)
{
    (void)state;
    mm_v3 u = {1, -2, 2};                               /* |u| = 3 */
    const double angles[] = {1e-9, 0.3, 1.5, 3.0, M_PI - 1e-7, M_PI};
    for (size_t k = 0; k < sizeof angles / sizeof angles[0]; k++) {
        double R[9], det_err;
        assert_int_equal(mm_geom_rot_axis_angle(u, angles[k], R, NULL), MM_OK);
        /* orthogonality to a few eps: each entry sums three rounded products */
        check_abs(mm_geom_rot_orth_error(R, &det_err), 0, 8 * EPS, "R^T R = I");
        check_abs(det_err, 0, 8 * EPS, "det R = 1");
        mm_v3 ax;
        double ang;
        mm_geom_rot_log(R, &ax, &ang);
        check_abs(ang, angles[k], 8 * EPS * (1 + angles[k]), "angle of the rotation back");
        if (angles[k] > 1e-6) {
            /* near pi the axis comes from the symmetric part: digits of the
             * order of the entries, a few eps; near 1e-9 it is not asked */
            check_abs(ax.x, 1.0 / 3, 1e-8, "axis x");
            check_abs(ax.y, -2.0 / 3, 1e-8, "axis y");
            check_abs(ax.z, 2.0 / 3, 1e-8, "axis z");
        }
    }
    double R[9];
    assert_int_equal(mm_geom_rot_axis_angle((mm_v3){0, 0, 0}, 1, R, NULL), MM_EVALUE);
}

/* ---- Euler angles ---------------------------------------------------------------------- */

static void every_euler_sequence_should_give_its_angles_back(void **state)
{
    (void)state;
    for (int s = 0; s < 12; s++) {
        const int *seq = sequences[s];
        assert_true(mm_geom_euler_check(seq));
        int proper = seq[0] == seq[2];
        for (int k = 0; k < 50; k++) {
            double ang[3] = {-3 + 0.12 * k, proper ? 0.05 + 0.06 * k : -1.5 + 0.06 * k, 2.9 - 0.11 * k}, R[9], back[9],
                   got[3], cond;
            mm_geom_euler_matrix(seq, ang, R);
            int lock = mm_geom_euler_angles(seq, R, got, 1e-8, &cond);
            assert_int_equal(lock, 0);
            for (int i = 0; i < 3; i++)
                /* the angles are cond-conditioned functions of R: a few
                 * eps times cond, cond <= 1/sin(0.04) = 25 here */
                check_abs(remainder(got[i] - ang[i], 2 * M_PI), 0, 16 * EPS * cond, "an angle back");
            mm_geom_euler_matrix(seq, got, back);
            check_abs(mat_diff(R, back), 0, 16 * EPS, "R from the angles back");
        }
    }
    int bad[3] = {0, 0, 1};
    assert_false(mm_geom_euler_check(bad));
}

static void gimbal_lock_should_be_flagged_and_still_reproduce_r(void **state)
{
    (void)state;
    for (int s = 0; s < 12; s++) {
        const int *seq = sequences[s];
        int proper = seq[0] == seq[2];
        /* the lock: b = 0 or pi (proper), +-pi/2 (Tait-Bryan) */
        double locks[2] = {proper ? 0 : M_PI / 2, proper ? M_PI : -M_PI / 2};
        for (int l = 0; l < 2; l++) {
            double ang[3] = {0.7, locks[l], -0.4}, R[9], got[3], back[9], cond, B[9];
            mm_geom_euler_matrix(seq, ang, R);
            assert_int_equal(mm_geom_euler_angles(seq, R, got, 1e-8, &cond), 1);
            check_abs(got[2], 0, 0, "c is set to 0 at the lock");
            check_abs(fabs(remainder(got[1] - locks[l], 2 * M_PI)), 0, 4e-8, "b at the lock");
            mm_geom_euler_matrix(seq, got, back);
            check_abs(mat_diff(R, back), 0, 1e-7, "R reproduced at the lock (b to sqrt(eps))");
            /* the rates matrix is singular there: det = +-sin b or +-cos b */
            mm_geom_euler_rates(seq, ang, 0, B);
            check_abs(mm_geom_m3_det(B), 0, 4 * EPS, "det of the Euler-rates matrix at the lock");
        }
        /* away from it |det B| = |sin b| (proper) or |cos b| (Tait-Bryan) */
        double ang[3] = {0.3, 0.9, 1.1}, B[9];
        mm_geom_euler_rates(seq, ang, 1, B);
        check_rel(fabs(mm_geom_m3_det(B)), proper ? sin(0.9) : cos(0.9), 8 * EPS, "|det B| in body components");
    }
}

/* omega from the rates against skew(omega) = R' R^T, R' by central
 * differences: the error must fall like h^2 */
static void euler_rates_should_give_the_angular_velocity_of_r(void **state)
{
    (void)state;
    for (int s = 0; s < 12; s++) {
        const int *seq = sequences[s];
        double a0[3] = {0.4, 0.8, -0.6}, rate[3] = {1.3, -0.7, 2.1}, B[9], Bb[9];
        mm_geom_euler_rates(seq, a0, 0, B);
        mm_geom_euler_rates(seq, a0, 1, Bb);
        mm_v3 w = mm_geom_m3_apply(B, (mm_v3){rate[0], rate[1], rate[2]});
        mm_v3 wb = mm_geom_m3_apply(Bb, (mm_v3){rate[0], rate[1], rate[2]});
        double R[9], Rt[9];
        mm_geom_euler_matrix(seq, a0, R);
        mm_geom_m3_transpose(R, Rt);
        mm_v3 wb_check = mm_geom_m3_apply(Rt, w);
        check_abs(mm_v3_norm(mm_v3_sub(wb, wb_check)), 0, 16 * EPS, "body omega = R^T space omega");
        double e[3];
        for (int k = 0; k < 3; k++) {
            double h = 1e-2 / (1 << (2 * k)), Rp[9], Rm[9], D[9], S[9], ap[3], am[3];
            for (int i = 0; i < 3; i++)
                ap[i] = a0[i] + h * rate[i], am[i] = a0[i] - h * rate[i];
            mm_geom_euler_matrix(seq, ap, Rp);
            mm_geom_euler_matrix(seq, am, Rm);
            for (int i = 0; i < 9; i++)
                D[i] = (Rp[i] - Rm[i]) / (2 * h);
            mm_geom_m3_mul(D, Rt, S);
            e[k] = mm_v3_norm(mm_v3_sub(mm_geom_unskew(S), w));
        }
        /* h^2: quartering h divides the error by 16 (13..19 allows the h^4 term) */
        assert_true(e[0] / e[1] > 13 && e[0] / e[1] < 19);
        assert_true(e[1] / e[2] > 13 && e[1] / e[2] < 19);
        check_abs(e[2], 0, 1e-5 * mm_v3_norm(w), "omega against R' R^T at h = 6e-4");
    }
}

/* ---- intersections ------------------------------------------------------------------------ */

static void circles_should_meet_at_the_3_4_5_points_left_then_right(void **state)
{
    (void)state;
    mm_v2 p[2];
    double disc;
    /* centres (0,0) and (5,0), radii 4 and 3: the right angle at (3.2, +-2.4) */
    assert_int_equal(mm_geom_circle_circle((mm_v2){0, 0}, 4, (mm_v2){5, 0}, 3, p, &disc), 2);
    check_abs(p[0].x, 3.2, 4 * EPS * 5, "x of the left point");
    check_abs(p[0].y, 2.4, 4 * EPS * 5, "left of (0,0)->(5,0) is y > 0");
    check_abs(p[1].y, -2.4, 4 * EPS * 5, "then the right one");
    check_rel(disc, 4 * 25 * 2.4 * 2.4, 4 * EPS, "discriminant 4 d^2 h^2");
    /* reversed direction: the left point is now y < 0 */
    assert_int_equal(mm_geom_circle_circle((mm_v2){5, 0}, 3, (mm_v2){0, 0}, 4, p, NULL), 2);
    check_abs(p[0].y, -2.4, 4 * EPS * 5, "left of (5,0)->(0,0)");
}

static void tangent_apart_and_concentric_circles_should_be_told_apart(void **state)
{
    (void)state;
    mm_v2 p[2] = {{9, 9}, {9, 9}};
    double disc;
    /* externally tangent: one point, exactly */
    assert_int_equal(mm_geom_circle_circle((mm_v2){0, 0}, 1, (mm_v2){3, 0}, 2, p, &disc), 1);
    check_abs(p[0].x, 1, 4 * EPS, "external tangency at (1, 0)");
    check_abs(p[0].y, 0, 0, "on the line of centres");
    /* internally tangent */
    assert_int_equal(mm_geom_circle_circle((mm_v2){0, 0}, 3, (mm_v2){1, 0}, 2, p, NULL), 1);
    check_abs(p[0].x, 3, 4 * EPS * 3, "internal tangency at (3, 0)");
    /* apart, nested, concentric: none, p untouched */
    p[0] = (mm_v2){9, 9};
    assert_int_equal(mm_geom_circle_circle((mm_v2){0, 0}, 1, (mm_v2){3.1, 0}, 2, p, &disc), 0);
    assert_true(disc < 0);
    assert_int_equal(mm_geom_circle_circle((mm_v2){0, 0}, 3, (mm_v2){0.5, 0}, 1, p, NULL), 0);
    assert_int_equal(mm_geom_circle_circle((mm_v2){1, 1}, 1, (mm_v2){1, 1}, 1, p, NULL), 0);
    check_abs(p[0].x, 9, 0, "p untouched when there is no point");
}

static void near_tangency_the_half_chord_should_keep_its_digits(void **state)
{
    (void)state;
    /* r1 = r2 = 1, d = 2 - delta (delta a power of two, so d is exact):
     * h = sqrt(1 - (d/2)^2) = sqrt(delta (1 - delta/4)) */
    for (int k = 20; k <= 40; k += 4) {
        double delta = ldexp(1, -k), d = 2 - delta;
        mm_v2 p[2];
        assert_int_equal(mm_geom_circle_circle((mm_v2){0, 0}, 1, (mm_v2){d, 0}, 1, p, NULL), 2);
        double h = sqrt(delta * (1 - delta / 4));
        /* the product form keeps h to a few eps relative (the naive
         * r^2 - a^2 would lose half the digits) */
        check_rel(p[0].y, h, 8 * EPS, "half chord near tangency");
    }
    /* within rounding of tangency: one point */
    mm_v2 p[2];
    assert_int_equal(mm_geom_circle_circle((mm_v2){0, 0}, 1, (mm_v2){2 - ldexp(1, -51), 0}, 1, p, NULL), 1);
}

static void a_line_should_cut_a_circle_at_the_stable_roots(void **state)
{
    (void)state;
    double t[2], disc;
    /* the x-axis through the unit circle centred at (0.5, 0.3) */
    assert_int_equal(mm_geom_line_circle((mm_v2){-2, 0}, (mm_v2){2, 0}, (mm_v2){0.5, 0.3}, 1, t, &disc), 2);
    double h = sqrt(1 - 0.09);
    check_abs(-2 + 2 * t[0], 0.5 - h, 8 * EPS, "first point x");
    check_abs(-2 + 2 * t[1], 0.5 + h, 8 * EPS, "second point x");
    check_abs(disc, 0.91, 4 * EPS, "r^2 - distance^2");
    assert_int_equal(mm_geom_line_circle((mm_v2){0, 1.3}, (mm_v2){1, 0}, (mm_v2){0.5, 0.3}, 1, t, NULL), 1);
    check_abs(t[0], 0.5, 4 * EPS, "tangent line touches above the centre");
    assert_int_equal(mm_geom_line_circle((mm_v2){0, 1.31}, (mm_v2){1, 0}, (mm_v2){0.5, 0.3}, 1, t, &disc), 0);
    assert_true(disc < 0);
}

static void lines_should_meet_unless_parallel(void **state)
{
    (void)state;
    mm_v2 x;
    assert_int_equal(mm_geom_line_line((mm_v2){0, 1}, (mm_v2){1, 1}, (mm_v2){4, 0}, (mm_v2){0, 1}, &x), 1);
    check_abs(x.x, 4, 4 * EPS * 4, "x of y = x + 1 and x = 4");
    check_abs(x.y, 5, 4 * EPS * 5, "y of the intersection");
    assert_int_equal(mm_geom_line_line((mm_v2){0, 1}, (mm_v2){1, 1}, (mm_v2){4, 0}, (mm_v2){-2, -2}, &x), 0);
}

static void three_points_should_give_the_radius_of_curvature(void **state)
{
    (void)state;
    mm_v2 c;
    double R;
    /* three points of the circle of radius 2 about (1, -1) */
    assert_int_equal(mm_geom_circumcircle((mm_v2){3, -1}, (mm_v2){1, 1}, (mm_v2){1 - sqrt(2), -1 - sqrt(2)}, &c, &R), 1);
    check_abs(R, 2, 16 * EPS, "radius of the circle through three of its points");
    check_abs(c.x, 1, 16 * EPS, "centre x");
    check_abs(c.y, -1, 16 * EPS, "centre y");
    assert_int_equal(mm_geom_circumcircle((mm_v2){0, 0}, (mm_v2){1, 1}, (mm_v2){2, 2}, &c, &R), 0);
    /* y = x^2 / 2 has radius of curvature 1 at its vertex: the circle
     * through (-h, h^2/2), (0, 0), (h, h^2/2) has R = 1 + h^2/4 exactly */
    for (double h = 0.1; h > 1e-3; h /= 4) {
        assert_int_equal(mm_geom_circumcircle((mm_v2){-h, h * h / 2}, (mm_v2){0, 0}, (mm_v2){h, h * h / 2}, &c, &R), 1);
        check_rel(R, 1 + h * h / 4, 64 * EPS / (h * h), "R = 1 + h^2/4 (rounding grows like eps / h^2)");
    }
}

/* The bound of the three-point radius: it holds, and it is not far above
 * what rounding can do.  On the parabola y = x^2 / 2 through (-h, h^2/2),
 * (0, 0), (h, h^2/2) the circle has R = 1 + h^2/4 exactly; the points,
 * turned by phi and rounded, are known within 4 u (|x| + |y|) a component.
 * Unturned, the error across the curve is that of y = h^2/2 alone and R is
 * good to a few u R (the bound within 50 u R); turned, the rounding of the
 * large component x ~ h leaks across it, u h, and moves R by u h R^2 / h^2
 * (the bound within 50 u R^2 / h).  And with exact points on a circle
 * (5, 0), (3, 4), (0, 5) about 0, R = 5: the bound is the formula's own
 * rounding alone, under 16 u R. */
static void the_three_point_radius_should_come_with_a_bound_that_holds(void **state)
{
    (void)state;
    const double u = EPS / 2;
    for (double h = 0.1; h > 1e-4; h /= 10)
        for (int k = 0; k < 3; k++) {
            double phi = 0.4 * k, c = cos(phi), sn = sin(phi), R, Rx = 1 + h * h / 4;
            mm_v2 P[3], E[3], ctr;
            for (int j = 0; j < 3; j++) {
                double x = (j - 1) * h, y = x * x / 2;
                P[j] = (mm_v2){c * x - sn * y, sn * x + c * y};
                double e = k == 0 ? u * y : 4 * u * (fabs(x) + fabs(y));
                E[j] = (mm_v2){e, e};
            }
            assert_int_equal(mm_geom_circumcircle(P[0], P[1], P[2], &ctr, &R), 1);
            double b = mm_geom_circumradius_err(P[0], P[1], P[2], E[0], E[1], E[2]);
            if (!(fabs(R - Rx) <= b + u * Rx))
                fail_msg("h = %g, phi = %g: R - R_exact = %.3g outside the bound %.3g", h, phi, R - Rx, b);
            double loose = k == 0 ? 50 * u * Rx : 50 * u * Rx * Rx / h;
            if (!(b <= loose))
                fail_msg("h = %g, phi = %g: bound %.3g above %.3g", h, phi, b, loose);
        }
    mm_v2 a = {5, 0}, b = {3, 4}, c = {0, 5}, z = {0, 0}, ctr;
    double R, e = mm_geom_circumradius_err(a, b, c, z, z, z);
    assert_int_equal(mm_geom_circumcircle(a, b, c, &ctr, &R), 1);
    check_abs(R, 5, e, "the circle of radius 5 through three exact points, within its bound");
    assert_true(e > 0 && e < 16 * u * 5);
    assert_true(isinf(mm_geom_circumradius_err(z, b, mm_v2_scale(b, 2), z, z, z)));    /* collinear */
}

/* ---- curves ------------------------------------------------------------------------------------ */

static int helix(double t, double *out, void *params)
{
    (void)params;
    out[0] = 2 * cos(t), out[1] = sin(3 * t), out[2] = exp(0.5 * t);
    return 0;
}

static int cardioid(double t, double *out, void *params)
{
    (void)params;
    out[0] = 2 * cos(t) - cos(2 * t), out[1] = 2 * sin(t) - sin(2 * t);
    return 0;
}

static int bad_curve(double t, double *out, void *params)
{
    (void)params;
    out[0] = 1 / (t - 1), out[1] = out[2] = 0;
    return t > 0.9 && t < 1.1 ? 0 : 0;
}

static void ridders_should_give_derivatives_with_honest_error_estimates(void **state)
{
    (void)state;
    for (double t = -2; t <= 2; t += 0.25) {
        double d1[3], e1[3], d2[3], e2[3];
        assert_int_equal(mm_geom_curve_derivs(helix, NULL, 3, t, 0.1, d1, e1, d2, e2, NULL), MM_OK);
        double x1[3] = {-2 * sin(t), 3 * cos(3 * t), 0.5 * exp(0.5 * t)};
        double x2[3] = {-2 * cos(t), -9 * sin(3 * t), 0.25 * exp(0.5 * t)};
        for (int c = 0; c < 3; c++) {
            double big1 = fabs(x1[c]) + 3, big2 = fabs(x2[c]) + 9;
            /* first derivative to ~1e-13 of its size, second to ~1e-10 (the
             * second difference loses twice the digits to rounding) */
            check_abs(d1[c], x1[c], 1e-12 * big1, "first derivative by Ridders");
            check_abs(d2[c], x2[c], 1e-9 * big2, "second derivative by Ridders");
            /* the estimates cover the error made (they are estimates: allow
             * the rounding of the comparison itself) */
            assert_true(fabs(d1[c] - x1[c]) <= e1[c] + 4 * EPS * big1);
            assert_true(fabs(d2[c] - x2[c]) <= e2[c] + 4 * EPS * big2);
            assert_true(e1[c] < 1e-11 * big1);
        }
    }
    /* dfridr's own rule stopped here after two columns, on a chance
     * agreement, 1.6e-7 off with an estimate of 3e-8; four columns first */
    double t = -4.8377930460886489, c1[2], ce[2];
    assert_int_equal(mm_geom_curve_derivs(cardioid, NULL, 2, t, 0.05, c1, ce, NULL, NULL, NULL), MM_OK);
    check_abs(c1[0], -2 * sin(t) + 2 * sin(2 * t), 1e-12, "the cardioid where the early stop failed");
    assert_true(fabs(c1[0] - (-2 * sin(t) + 2 * sin(2 * t))) <= ce[0]);
    double d1[3], e1[3];
    mm_error err;
    assert_int_equal(mm_geom_curve_derivs(bad_curve, NULL, 3, 1, 0.1, d1, e1, NULL, NULL, &err), MM_ENONFINITE);
    assert_string_equal(err.param, "t");
    /* the curvature of a circle of radius 2 run at any speed is 1/2 */
    check_rel(mm_geom_curvature((mm_v2){0, 3}, (mm_v2){-4.5, 0}), 0.5, 4 * EPS, "circle r = 2, |v| = 3");
    check_abs(mm_geom_curvature((mm_v2){0, 0}, (mm_v2){1, 0}), 0, 0, "a cusp has none");
}

/* ---- polygons --------------------------------------------------------------------------------- */

static void the_l_section_should_have_its_closed_form_properties(void **state)
{
    (void)state;
    /* API.md's sta-centroid default: area 6, centroid (1.5, 1), Ixx 4,
     * Iyy 8.5, Ixy -3 (two rectangles and the parallel-axis theorem) */
    double xy[12] = {0, 0, 4, 0, 4, 1, 1, 1, 1, 3, 0, 3}, rev[12];
    for (int i = 0; i < 6; i++)
        rev[2 * i] = xy[2 * (5 - i)], rev[2 * i + 1] = xy[2 * (5 - i) + 1];
    for (int k = 0; k < 2; k++) {
        mm_geom_polygon_props p;
        assert_int_equal(mm_geom_polygon(k ? rev : xy, 6, &p, NULL), MM_OK);
        assert_int_equal(p.orientation, k ? -1 : 1);
        check_rel(p.area, 6, 4 * EPS, "area");
        check_rel(p.xc, 1.5, 4 * EPS, "xc");
        check_rel(p.yc, 1, 4 * EPS, "yc");
        check_rel(p.Ixx, 4, 16 * EPS, "Ixx");
        check_rel(p.Iyy, 8.5, 16 * EPS, "Iyy");
        check_rel(p.Ixy, -3, 16 * EPS, "Ixy");
    }
    /* far from the origin: the same moments (taken about a vertex) */
    double far[12];
    for (int i = 0; i < 12; i++)
        far[i] = xy[i] + 1e6;
    mm_geom_polygon_props p;
    assert_int_equal(mm_geom_polygon(far, 6, &p, NULL), MM_OK);
    check_rel(p.Ixx, 4, 1e-12, "Ixx of the L-section moved by 1e6");
    check_rel(p.xc, 1e6 + 1.5, 4 * EPS, "xc moved");
    double line[6] = {0, 0, 1, 1, 2, 2};
    mm_error err;
    assert_int_equal(mm_geom_polygon(line, 3, &p, &err), MM_EVALUE);
    assert_string_equal(err.param, "polygon");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(elementary_rotations_should_match_rodrigues_about_the_axes),
        cmocka_unit_test(rodrigues_should_give_a_rotation_whose_log_is_the_axis_and_angle),
        cmocka_unit_test(every_euler_sequence_should_give_its_angles_back),
        cmocka_unit_test(gimbal_lock_should_be_flagged_and_still_reproduce_r),
        cmocka_unit_test(euler_rates_should_give_the_angular_velocity_of_r),
        cmocka_unit_test(circles_should_meet_at_the_3_4_5_points_left_then_right),
        cmocka_unit_test(tangent_apart_and_concentric_circles_should_be_told_apart),
        cmocka_unit_test(near_tangency_the_half_chord_should_keep_its_digits),
        cmocka_unit_test(a_line_should_cut_a_circle_at_the_stable_roots),
        cmocka_unit_test(lines_should_meet_unless_parallel),
        cmocka_unit_test(three_points_should_give_the_radius_of_curvature),
        cmocka_unit_test(the_three_point_radius_should_come_with_a_bound_that_holds),
        cmocka_unit_test(ridders_should_give_derivatives_with_honest_error_estimates),
        cmocka_unit_test(the_l_section_should_have_its_closed_form_properties),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
