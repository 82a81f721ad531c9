/* test_truss.c — planar trusses against forces known in closed form, and
 * the hard cases: a mechanism, a redundant member, a loaded joint with no
 * member, nearly and exactly collinear members, supports that let the
 * truss slide or turn. */
#include "mm_test.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "mm_truss_fixture.h"

#define EPS DBL_EPSILON

/* ---- trusses ------------------------------------------------------------------------ */

/* The 7-member Warren truss of sta-truss's default: joints 1 (0,0), 2 (4,0),
 * 3 (8,0), 4 (2,3), 5 (6,3); pin at 1, roller at 3; 10 kN down at 2. */
static void warren(built *b)
{
    static const double xy[] = {0, 0, 4, 0, 8, 0, 2, 3, 6, 3};
    static const int ends[] = {0, 1, 1, 2, 3, 4, 0, 3, 3, 1, 1, 4, 4, 2};
    memcpy(b->xy, xy, sizeof xy);
    memcpy(b->ends, ends, sizeof ends);
    int sup[] = {0, 1, 1, 2, 0, 1};
    memcpy(b->sup, sup, sizeof sup);
    b->lnode[0] = 1;
    b->lf[0] = 0, b->lf[1] = -10000;
    bind(b, 5, 7, 2, 1);
}

/* ---- determinate trusses ------------------------------------------------------------- */

static void the_warren_truss_should_give_its_hand_computed_forces(void **state)
{
    (void)state;
    built b;
    warren(&b);
    mm_error err;
    assert_int_equal(mm_truss_solve(&b.t, &b.r, &err), MM_OK);
    assert_int_equal(b.r.determinacy, 0);
    assert_int_equal(b.r.n_reactions, 3);
    /* by joints 1 and 4 (and symmetry): chords 10000/3 and -20000/3,
     * diagonals -+5000 sqrt(13)/3 */
    const double d = 5000 * sqrt(13.0) / 3;
    const double want[7] = {10000.0 / 3, 10000.0 / 3, -20000.0 / 3, -d, d, d, -d};
    for (int e = 0; e < 7; e++)
        check_abs(b.force[e], want[e], 16 * EPS * 10000, "Warren member force by hand");
    check_abs(b.reaction[0], 0, 16 * EPS * 10000, "no horizontal reaction");
    check_abs(b.reaction[1], 5000, 16 * EPS * 10000, "half the load at the pin");
    check_abs(b.reaction[5], 5000, 16 * EPS * 10000, "half at the roller");
    check_abs(b.r.eq.residual, 0, 8 * EPS * b.r.eq.scale, "joint residual at round-off");
}

static void a_50_joint_pratt_truss_should_give_chord_forces_m_over_h(void **state)
{
    (void)state;
    enum { N = 25 };
    const double a = 2, h = 3, P = 1000;
    built b;
    pratt(&b, N, a, h, P);
    assert_int_equal(b.t.n_nodes, 50);
    assert_int_equal(b.t.n_members, 97);
    mm_error err;
    assert_int_equal(mm_truss_solve(&b.t, &b.r, &err), MM_OK);
    /* bottom chord of panel i by a section and moments about the top joint
     * where the top chord and the diagonal meet: F = M(x) / h, with the
     * simply supported beam's M(x_k) = P a k (N - k) / 2 at that joint */
    double Mmax = P * a * (N / 2) * (N - N / 2) / 2.0;
    for (int i = 0; i < N; i++) {
        /* the joint above which the top chord and the diagonal meet: panel 0
         * and right-half panels at their right end, left-half panels and
         * the last at their left end */
        int k = i == 0 ? 1 : i == N - 1 ? N - 1 : 2 * i < N ? i : i + 1;
        double want = P * a * k * (N - k) / 2.0 / h;
        check_abs(b.force[i], want, 64 * EPS * Mmax / h, "bottom chord = M / h");
    }
    check_abs(b.reaction[1], P * (N - 1) / 2.0, 64 * EPS * P * N, "reaction = half the load");
}

static void sections_and_rigid_body_reactions_should_agree_with_the_joints(void **state)
{
    (void)state;
    built b;
    pratt(&b, 8, 1.5, 2, 700);
    mm_error err;
    assert_int_equal(mm_truss_solve(&b.t, &b.r, &err), MM_OK);
    double R[2 * MM_TRUSS_MAX_NODES];
    assert_int_equal(mm_truss_reactions_rigid(&b.t, R), 1);
    for (int i = 0; i < 2 * b.t.n_nodes; i++)
        check_abs(R[i], b.reaction[i], 16 * EPS * 700 * 8, "whole-body reactions = joint reactions");
    double F[MM_TRUSS_MAX_MEMBERS], sc[MM_TRUSS_MAX_MEMBERS];
    int cnt[MM_TRUSS_MAX_MEMBERS];
    int cuts = mm_truss_sections(&b.t, R, F, cnt, sc);
    /* 8 vertical cuts, one per panel: the end panels cross only two members */
    assert_int_equal(cuts, 6);
    int found = 0;
    for (int e = 0; e < b.t.n_members; e++)
        if (cnt[e]) {
            found++;
            check_abs(F[e], b.force[e], 64 * EPS * (sc[e] + fabs(b.force[e])), "section = joints");
        }
    assert_true(found >= 16);
}

/* ---- the hard cases ---------------------------------------------------------------- */

static void a_square_without_a_diagonal_should_be_a_mechanism_naming_a_joint(void **state)
{
    (void)state;
    built b;
    static const double xy[] = {0, 0, 2, 0, 2, 2, 0, 2};
    static const int ends[] = {0, 1, 1, 2, 2, 3, 3, 0};
    memcpy(b.xy, xy, sizeof xy);
    memcpy(b.ends, ends, sizeof ends);
    int sup[] = {0, 1, 1, 1, 0, 1};
    memcpy(b.sup, sup, sizeof sup);
    b.lnode[0] = 2, b.lf[0] = 100, b.lf[1] = 0;
    bind(&b, 4, 4, 2, 1);
    mm_error err;
    assert_int_equal(mm_truss_solve(&b.t, &b.r, &err), MM_ESINGULAR);
    assert_int_equal(b.r.determinacy, -1);
    assert_string_equal(err.param, "members");
    assert_non_null(strstr(err.msg, "a mechanism"));
    assert_non_null(strstr(err.msg, "without stretching any member"));
    /* the panel shears: the top joints 3 and 4 move sideways */
    assert_true(b.r.free_joint == 2 || b.r.free_joint == 3);
    check_abs(b.r.free_dir, 0, 1e-9, "the top moves along x");
    assert_non_null(strstr(err.msg, "sideways"));
}

static void a_square_with_both_diagonals_should_name_a_redundant_member(void **state)
{
    (void)state;
    built b;
    static const double xy[] = {0, 0, 2, 0, 2, 2, 0, 2};
    static const int ends[] = {0, 1, 1, 2, 2, 3, 3, 0, 0, 2, 1, 3};
    memcpy(b.xy, xy, sizeof xy);
    memcpy(b.ends, ends, sizeof ends);
    int sup[] = {0, 1, 1, 1, 0, 1};
    memcpy(b.sup, sup, sizeof sup);
    b.lnode[0] = 2, b.lf[0] = 100, b.lf[1] = 0;
    bind(&b, 4, 6, 2, 1);
    mm_error err;
    assert_int_equal(mm_truss_solve(&b.t, &b.r, &err), MM_ESINGULAR);
    assert_int_equal(b.r.determinacy, 1);
    assert_non_null(strstr(err.msg, "statically indeterminate"));
    assert_non_null(strstr(err.msg, "is redundant"));
    /* the self-stress of a braced square involves all six members */
    assert_true(b.r.redundant_member >= 0);
    assert_int_equal(b.r.redundant_count, 6);
}

static void a_loaded_joint_with_no_member_should_be_named_as_free(void **state)
{
    (void)state;
    built b;
    warren(&b);
    b.xy[10] = 10, b.xy[11] = 3;                   /* joint 6, alone */
    b.lnode[1] = 5, b.lf[2] = 0, b.lf[3] = -500;
    bind(&b, 6, 7, 2, 2);
    mm_error err;
    assert_int_equal(mm_truss_solve(&b.t, &b.r, &err), MM_ESINGULAR);
    assert_int_equal(b.r.determinacy, -2);
    assert_int_equal(b.r.free_joint, 5);
    assert_non_null(strstr(err.msg, "joint 6 is joined to no member"));
}

static void nearly_collinear_members_should_give_p_over_2_sin_delta(void **state)
{
    (void)state;
    /* two bars from pins at (-1, 0) and (1, 0) to a joint sagging by
     * tan(delta): a load P down gives tension P / (2 sin delta) in each */
    double delta = 0.5 * M_PI / 180, P = 1000;
    built b;
    double xy[] = {-1, 0, 1, 0, 0, -tan(delta)};
    int ends[] = {0, 2, 1, 2};
    memcpy(b.xy, xy, sizeof xy);
    memcpy(b.ends, ends, sizeof ends);
    int sup[] = {0, 1, 1, 1, 1, 1};
    memcpy(b.sup, sup, sizeof sup);
    b.lnode[0] = 2, b.lf[0] = 0, b.lf[1] = -P;
    bind(&b, 3, 2, 2, 1);
    mm_error err;
    assert_int_equal(mm_truss_solve(&b.t, &b.r, &err), MM_OK);
    /* cond ~ 1/sin(delta) = 115: error ~ 115 eps of the force */
    double want = P / (2 * sin(delta));
    check_rel(b.force[0], want, 1e3 * EPS, "left bar: P / (2 sin delta)");
    check_rel(b.force[1], want, 1e3 * EPS, "right bar: P / (2 sin delta)");
    assert_true(b.r.eq.growth > 50);
    double spread[3];
    mm_truss_spread(&b.t, spread);
    check_abs(spread[2], 2 * delta, 1e-12, "the bars meet at 2 delta from one line");
}

static void exactly_collinear_members_should_be_a_critical_form(void **state)
{
    (void)state;
    built b;
    double xy[] = {-1, 0, 1, 0, 0, 0};
    int ends[] = {0, 2, 1, 2};
    memcpy(b.xy, xy, sizeof xy);
    memcpy(b.ends, ends, sizeof ends);
    int sup[] = {0, 1, 1, 1, 1, 1};
    memcpy(b.sup, sup, sizeof sup);
    b.lnode[0] = 2, b.lf[0] = 0, b.lf[1] = -1000;
    bind(&b, 3, 2, 2, 1);
    mm_error err;
    assert_int_equal(mm_truss_solve(&b.t, &b.r, &err), MM_ESINGULAR);
    assert_int_equal(b.r.determinacy, 0);
    assert_int_equal(b.r.free_joint, 2);
    check_abs(fabs(b.r.free_dir), M_PI / 2, 1e-9, "the middle joint moves up and down");
    assert_non_null(strstr(err.msg, "although m + r - 2j = 0"));
    assert_non_null(strstr(err.msg, "up and down"));
    assert_non_null(strstr(err.msg, "redundant"));
}

static void supports_that_let_the_truss_slide_or_turn_should_say_so(void **state)
{
    (void)state;
    built b;
    warren(&b);
    int slide[] = {0, 0, 1, 2, 0, 1};                 /* two rollers: slides along x */
    memcpy(b.sup, slide, sizeof slide);
    mm_error err;
    assert_int_equal(mm_truss_solve(&b.t, &b.r, &err), MM_ESINGULAR);
    assert_int_equal(b.r.rigid, 1);
    assert_int_equal(b.r.rigid_turns, 0);
    assert_non_null(strstr(err.msg, "slide sideways"));

    warren(&b);
    b.t.n_supports = 1;                                /* the pin alone: turns about joint 1 */
    assert_int_equal(mm_truss_solve(&b.t, &b.r, &err), MM_ESINGULAR);
    assert_int_equal(b.r.rigid_turns, 1);
    check_abs(b.r.pivot[0], 0, 1e-9, "pivot x at joint 1");
    check_abs(b.r.pivot[1], 0, 1e-9, "pivot y at joint 1");
    assert_non_null(strstr(err.msg, "turn about joint 1"));
}

static void bad_trusses_should_be_refused_naming_the_parameter(void **state)
{
    (void)state;
    built b;
    mm_error err;
    warren(&b);
    b.ends[0] = 9;
    assert_int_equal(mm_truss_check(&b.t, &err), MM_ERANGE);
    assert_string_equal(err.param, "members");
    warren(&b);
    b.ends[1] = b.ends[0];
    assert_int_equal(mm_truss_check(&b.t, &err), MM_ERANGE);
    assert_non_null(strstr(err.msg, "to itself"));
    warren(&b);
    b.xy[2] = 0;                                      /* joint 2 onto joint 1 */
    assert_int_equal(mm_truss_check(&b.t, &err), MM_ERANGE);
    assert_non_null(strstr(err.msg, "same point"));
    warren(&b);
    b.sup[4] = 2;
    assert_int_equal(mm_truss_check(&b.t, &err), MM_ERANGE);
    assert_string_equal(err.param, "supports");
    warren(&b);
    b.sup[3] = 0;                                     /* both supports at joint 1 */
    assert_int_equal(mm_truss_check(&b.t, &err), MM_ERANGE);
    warren(&b);
    b.lnode[0] = 7;
    assert_int_equal(mm_truss_check(&b.t, &err), MM_ERANGE);
    assert_string_equal(err.param, "loads");
    warren(&b);
    b.xy[3] = NAN;
    assert_int_equal(mm_truss_check(&b.t, &err), MM_EVALUE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_warren_truss_should_give_its_hand_computed_forces),
        cmocka_unit_test(a_50_joint_pratt_truss_should_give_chord_forces_m_over_h),
        cmocka_unit_test(sections_and_rigid_body_reactions_should_agree_with_the_joints),
        cmocka_unit_test(a_square_without_a_diagonal_should_be_a_mechanism_naming_a_joint),
        cmocka_unit_test(a_square_with_both_diagonals_should_name_a_redundant_member),
        cmocka_unit_test(a_loaded_joint_with_no_member_should_be_named_as_free),
        cmocka_unit_test(nearly_collinear_members_should_give_p_over_2_sin_delta),
        cmocka_unit_test(exactly_collinear_members_should_be_a_critical_form),
        cmocka_unit_test(supports_that_let_the_truss_slide_or_turn_should_say_so),
        cmocka_unit_test(bad_trusses_should_be_refused_naming_the_parameter),
    };
    return cmocka_run_group_tests_name("truss", tests, NULL, NULL);
}
