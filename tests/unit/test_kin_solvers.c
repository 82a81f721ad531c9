/* test_kin_solvers.c — the functions the kinematics chapter appended to
 * shared solver modules (each in a block headed "added for the kinematics
 * chapter"), against closed forms, identities and second methods:
 *   - mm_quad: the 5-point Gauss-Legendre nodes and weights;
 *   - mm_elliptic: E(k), the complete integral of the second kind;
 *   - mm_geom: the length of a trochoid's arch, the rotation matrix of
 *     Euler angles by quaternions, the largest entry of a difference. */
#include "mm_test.h"

#include <float.h>

#include "mm_elliptic.h"
#include "mm_geom.h"
#include "mm_quad.h"

#define PI 3.14159265358979323846
#define EPS DBL_EPSILON

/* ---- mm_quad_gl5_node, mm_quad_gl5_weight ------------------------------------------ */

static double legendre5(double x, double *dp)
{
    /* P5 = (63 x^5 - 70 x^3 + 15 x) / 8 */
    *dp = (315 * x * x * x * x - 210 * x * x + 15) / 8;
    return (63 * x * x * x * x * x - 70 * x * x * x + 15 * x) / 8;
}

static void gl5_nodes_should_be_the_roots_of_p5_with_their_weights(void **state)
{
    (void)state;
    for (int i = 0; i < 5; i++) {
        double x = mm_quad_gl5_node[i], dp, p = legendre5(x, &dp);
        check_abs(p, 0, 16 * EPS, "P5 vanishes at the node (terms up to 63/8 x^5, about 5)");
        /* w_i = 2 / ((1 - x_i^2) P5'(x_i)^2) */
        check_rel(mm_quad_gl5_weight[i], 2 / ((1 - x * x) * dp * dp), 8 * EPS, "the Gauss weight of the node");
        check_abs(mm_quad_gl5_node[i], -mm_quad_gl5_node[4 - i], 0, "nodes symmetric");
    }
}

static void gl5_should_integrate_degree_9_exactly_and_not_degree_10(void **state)
{
    (void)state;
    for (int p = 0; p <= 10; p++) {
        double q = 0;
        for (int i = 0; i < 5; i++)
            q += mm_quad_gl5_weight[i] * pow(mm_quad_gl5_node[i], p);
        double want = p % 2 ? 0 : 2.0 / (p + 1);
        if (p <= 9)
            check_abs(q, want, 8 * EPS, "x^p over [-1, 1], p <= 9: exact to rounding");
        else    /* the rule's error for f = x^10: 2^11 (5!)^4 / (11 (10!)^3) f^(10) = 0.0029318... */
            check_rel(want - q, 2048 * pow(120, 4) / (11 * pow(3628800, 3)) * 3628800, 1e-12,
                      "x^10: the error of the 5-point rule's closed form");
    }
}

/* ---- mm_elliptic_E ------------------------------------------------------------------- */

static void e_should_meet_its_limits_and_the_singular_value(void **state)
{
    (void)state;
    check_rel(mm_elliptic_E(0), PI / 2, 2 * EPS, "E(0) = pi/2");
    check_rel(mm_elliptic_E(1), 1, 2 * EPS, "E(1) = 1 (the AGM of 1 and 0 does not converge)");
    check_rel(mm_elliptic_E(1 - 1e-12), 1, 1e-10, "E near 1: 1 + kc^2 (ln(4/kc) - 1/2) / 2, kc = 1.4e-6");
    /* k = 1/sqrt 2: E = K/2 + pi/(4K), K = Gamma(1/4)^2 / (4 sqrt pi); tgamma to a few eps */
    double K = tgamma(0.25) * tgamma(0.25) / (4 * sqrt(PI));
    check_rel(mm_elliptic_E(sqrt(0.5)), K / 2 + PI / (4 * K), 16 * EPS, "E(1/sqrt 2) = K/2 + pi/(4K)");
}

static void e_should_satisfy_legendres_relation(void **state)
{
    (void)state;
    /* E K' + E' K - K K' = pi/2, with K from mm_elliptic_Kc (the AGM of K,
     * which does not use E's series) */
    for (double k = 0.05; k < 1; k += 0.1) {
        double kc = sqrt((1 - k) * (1 + k));
        double K = mm_elliptic_Kc(kc), Kp = mm_elliptic_Kc(k), E = mm_elliptic_E(k), Ep = mm_elliptic_E(kc);
        check_rel(E * Kp + Ep * K - K * Kp, PI / 2, 32 * EPS, "Legendre's relation");
    }
}

static int e_integrand(double t, double *f, void *ctx)
{
    double k = *(double *)ctx, s = sin(t);
    *f = sqrt(1 - k * k * s * s);
    return 0;
}

static void e_should_match_its_integral_by_gauss_kronrod(void **state)
{
    (void)state;
    mm_quad_options opt;
    mm_quad_options_init(&opt);
    opt.rtol = 1e-15;
    for (double k = 0; k <= 0.99; k += 0.11) {
        mm_quad_result r;
        assert_int_equal(mm_quad_gk(e_integrand, &k, 0, PI / 2, &opt, NULL, &r, NULL), MM_OK);
        check_abs(mm_elliptic_E(k), r.value, r.err + 8 * EPS, "E(k) vs its defining integral");
    }
}

/* ---- mm_geom_trochoid_arch ------------------------------------------------------------ */

static void trochoid_arch_should_match_its_closed_forms(void **state)
{
    (void)state;
    /* the cycloid (b = R): 8 R, though |dP/dphi| has a corner at phi = 0 */
    check_rel(mm_geom_trochoid_arch(0.5, 0.5, NULL), 4, 16 * EPS, "cycloid: 8 R");
    /* b = 0: the centre's straight path over a turn, 2 pi R */
    check_rel(mm_geom_trochoid_arch(0.3, 0, NULL), 2 * PI * 0.3, 16 * EPS, "b = 0: 2 pi R");
    /* curtate, prolate, and b a hair from R: 4 (R + b) E(k) by the AGM;
     * the panels' |Q(2n) - Q(n)| + 2 |Q(4n) - Q(2n)| summed, with rounding,
     * bound the error.
     * b = 2.5837 R (kin-rolling-wheel's tolerance study: R = 1.71498,
     * b = 4.43105) guards the summing panel by panel: there the whole-panel
     * rule errs -4.4e-12 L on [pi/2, pi] and +4.6e-12 L on [pi/4, pi/2],
     * the two totals agree to 3e-15 L, and the halved rule errs 1.6e-13 L,
     * 9.0 times |Q(2n) - Q(n)| of the totals plus rounding.  b = 7.913 R:
     * on [pi/2, pi] the whole and the halved rule err alike, -1.7e-14 L */
    static const double Rs[] = {0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 1.7149824527727189, 1};
    static const double bs[] = {0.1, 0.45, 0.4999, 0.5001, 0.9, 3, 4.431045309982973, 7.913220551378446};
    for (unsigned i = 0; i < sizeof bs / sizeof bs[0]; i++) {
        double R = Rs[i], b = bs[i], k = 2 * sqrt(R * b) / (R + b), L = 4 * (R + b) * mm_elliptic_E(k);
        double e, q = mm_geom_trochoid_arch(R, b, &e);
        check_abs(q, L, e + 64 * EPS * L, "arch vs 4 (R + b) E(k)");
        assert_true(fabs(q - L) < 1e-12 * L);
    }
}

/* ---- mm_geom_euler_quat_matrix -------------------------------------------------------- */

static void euler_by_quaternions_should_match_the_matrix_product(void **state)
{
    (void)state;
    /* the twelve sequences: R_i(a) R_j(b) R_k(c) by matrices (mm_geom_euler_matrix) */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++) {
                const int seq[3] = {i, j, k};
                if (!mm_geom_euler_check(seq))
                    continue;
                const double ang[3] = {0.5 + i, -0.8 + 0.3 * j, 2.9 - k};
                double R[9], Q[9], Rt[9], I[9];
                mm_geom_euler_matrix(seq, ang, R);
                mm_geom_euler_quat_matrix(seq, ang, Q);
                for (int e = 0; e < 9; e++)
                    check_abs(Q[e], R[e], 8 * EPS, "quaternions vs matrices, entry by entry");
                mm_geom_m3_transpose(Q, Rt);
                mm_geom_m3_mul(Rt, Q, I);
                for (int e = 0; e < 9; e++)
                    check_abs(I[e], e % 4 == 0, 8 * EPS, "Q^T Q = I");
            }
    /* a quarter turn about z: x to y */
    const int zyx[3] = {2, 1, 0};
    const double quarter[3] = {PI / 2, 0, 0};
    double Q[9];
    mm_geom_euler_quat_matrix(zyx, quarter, Q);
    check_abs(Q[3], 1, 2 * EPS, "R e_x = e_y: entry (2, 1)");
    check_abs(Q[1], -1, 2 * EPS, "R e_y = -e_x: entry (1, 2)");
}

static void m3_maxdiff_should_give_the_largest_entry(void **state)
{
    (void)state;
    const double A[9] = {1, 2, 3, 4, 5, 6, 7, 8, 9}, B[9] = {1, 2, 3.5, 4, 5, 6, 7, 7, 9};
    check_abs(mm_geom_m3_maxdiff(A, A), 0, 0, "equal matrices");
    check_abs(mm_geom_m3_maxdiff(A, B), 1, 0, "entry (3, 2) differs by 1, (1, 3) by 0.5");
    check_abs(mm_geom_m3_maxdiff(B, A), 1, 0, "symmetric");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(gl5_nodes_should_be_the_roots_of_p5_with_their_weights),
        cmocka_unit_test(gl5_should_integrate_degree_9_exactly_and_not_degree_10),
        cmocka_unit_test(e_should_meet_its_limits_and_the_singular_value),
        cmocka_unit_test(e_should_satisfy_legendres_relation),
        cmocka_unit_test(e_should_match_its_integral_by_gauss_kronrod),
        cmocka_unit_test(trochoid_arch_should_match_its_closed_forms),
        cmocka_unit_test(euler_by_quaternions_should_match_the_matrix_product),
        cmocka_unit_test(m3_maxdiff_should_give_the_largest_entry),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
