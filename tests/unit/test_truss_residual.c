/* test_truss_residual.c — the joint and whole-body residuals of a truss
 * (mm_truss_joint_residual, mm_truss_body_residual): rounding for the
 * forces solved, and exactly the error put in when a member force or a
 * reaction is made wrong by a known amount; the term sizes summed by hand
 * for one triangle. */
#include "mm_test.h"

#include <float.h>

#include "mm_truss_fixture.h"

#define EPS DBL_EPSILON

static void solved_forces_should_leave_rounding_and_wrong_ones_their_error(void **state)
{
    (void)state;
    built b;
    pratt(&b, 6, 2, 1.5, 1000);
    mm_error err;
    assert_int_equal(mm_truss_solve(&b.t, &b.r, &err), MM_OK);
    double worst, scale, total, bw, bs;
    mm_truss_joint_residual(&b.t, b.force, b.reaction, &worst, &scale, &total);
    check_abs(worst, 0, 16 * EPS * scale, "joints in equilibrium to rounding");
    assert_true(total >= scale && scale > 0);
    mm_truss_body_residual(&b.t, b.reaction, &bw, &bs);
    check_abs(bw, 0, 16 * EPS * (bs + total), "whole truss in equilibrium to rounding");
    /* member 0 off by 7 N: both its joints are out of balance by 7 N */
    b.force[0] += 7;
    mm_truss_joint_residual(&b.t, b.force, b.reaction, &worst, &scale, &total);
    check_rel(worst, 7, 1e-12, "the joint residual is the error put in");
    b.force[0] -= 7;
    /* a reaction off by 5 N in y: the whole truss is out by 5 N */
    int j = b.sup[0];
    b.reaction[2 * j + 1] += 5;
    mm_truss_body_residual(&b.t, b.reaction, &bw, &bs);
    check_rel(bw, 5, 1e-12, "the body residual is the error put in");
}

static void the_term_sizes_should_be_the_sums_written_out(void **state)
{
    (void)state;
    /* a 3-4-5 triangle: pin at 0, roller at 1, 100 N down at 2 */
    built b;
    double xy[6] = {0, 0, 4, 0, 4, 3};
    int ends[6] = {0, 1, 1, 2, 0, 2}, sup[6] = {0, 1, 1, 1, 0, 1};
    memcpy(b.xy, xy, sizeof xy), memcpy(b.ends, ends, sizeof ends), memcpy(b.sup, sup, sizeof sup);
    b.lnode[0] = 2, b.lf[0] = 0, b.lf[1] = -100;
    bind(&b, 3, 3, 2, 1);
    mm_error err;
    assert_int_equal(mm_truss_solve(&b.t, &b.r, &err), MM_OK);
    /* by hand: the roller carries all 100 N (the load is above it), member
     * 1-2 is -100, the others 0 */
    double *F = b.force, *R = b.reaction, worst, scale, total, bw, bs;
    check_abs(R[3], 100, 1e-12, "roller reaction");
    mm_truss_joint_residual(&b.t, F, R, &worst, &scale, &total);
    double ab1 = fabs(F[0]) + fabs(F[1]) + fabs(R[2]) + fabs(R[3]), ab2 = fabs(F[1]) + fabs(F[2]) + 100;
    double ab0 = fabs(F[0]) + fabs(F[2]) + fabs(R[0]) + fabs(R[1]);
    check_rel(total, ab0 + ab1 + ab2, 4 * EPS, "total: every joint's |terms|");
    check_rel(scale, fmax(ab0, fmax(ab1, ab2)), 4 * EPS, "scale: the largest joint's");
    /* body: forces |0| + |100| + |R| and moments about joint 0 over arm 5 */
    mm_truss_body_residual(&b.t, R, &bw, &bs);
    double sf = 100 + fabs(R[0]) + fabs(R[1]) + fabs(R[2]) + fabs(R[3]), sm = (4 * 100 + 4 * fabs(R[3])) / 5;
    check_rel(bs, fmax(sf, sm), 4 * EPS, "the larger of the force and moment sums");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(solved_forces_should_leave_rounding_and_wrong_ones_their_error),
        cmocka_unit_test(the_term_sizes_should_be_the_sums_written_out),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
