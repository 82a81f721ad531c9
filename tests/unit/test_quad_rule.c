/* test_quad_rule.c — mm_quad_gl5_nodes, the nodes and weights of
 * composite 5-point Gauss-Legendre, against closed-form integrals: exact
 * up to degree 9, and at degree 10 off by exactly the rule's error term
 * (b - a)^11 (5!)^4 / (11 (10!)^3) f^(10) on each piece, which only the
 * right nodes and weights give; the pieces laid as documented. */
#include "mm_test.h"

#include <float.h>

#include "mm_quad.h"

#define EPS DBL_EPSILON

static double rule_sum(int m, const double *x, const double *w, int deg)
{
    double s = 0;
    for (int i = 0; i < 5 * m; i++)
        s += w[i] * pow(x[i], deg);
    return s;
}

static void monomials_up_to_degree_9_should_be_integrated_exactly(void **state)
{
    (void)state;
    double x[15], w[15], a = -0.7, b = 1.9;
    for (int m = 1; m <= 3; m += 2) {
        mm_quad_gl5_nodes(a, b, m, x, w);
        for (int n = 0; n <= 9; n++) {
            double want = (pow(b, n + 1) - pow(a, n + 1)) / (n + 1);
            double size = (pow(fabs(b), n + 1) + pow(fabs(a), n + 1)) / (n + 1);   /* integral of |x^n| */
            /* rounding only: 5 m terms, weights within 2e-16 of the rule's */
            check_abs(rule_sum(m, x, w, n), want, 16 * m * EPS * size, "integral of x^n, n <= 9");
        }
    }
}

static void degree_10_should_miss_by_the_rule_error_term(void **state)
{
    (void)state;
    /* on [0, 1] in m pieces of h = 1/m: the error is m h^11 (5!)^4 / (11
     * (10!)^3) 10! = E / m^10, E = 120^4 / (11 * 10!^2) = 1.4316e-6 */
    double x[10], w[10], f10 = 3628800, E = pow(120, 4) / (11 * f10 * f10);
    for (int m = 1; m <= 2; m++) {
        mm_quad_gl5_nodes(0, 1, m, x, w);
        check_abs(rule_sum(m, x, w, 10), 1.0 / 11 - E / pow(m, 10), 8 * EPS,
                  "integral of x^10: 1/11 less the error term (rounding of 10 terms of size < 1)");
    }
}

static void a_smooth_integrand_should_meet_its_closed_form(void **state)
{
    (void)state;
    /* e^x on [0, 3], 8 pieces: the error term is below 8 (3/8)^11 3.95e-13 e^3
     * = 1.3e-15; rounding adds a few eps of e^3 - 1 */
    double x[40], w[40], s = 0;
    mm_quad_gl5_nodes(0, 3, 8, x, w);
    for (int i = 0; i < 40; i++)
        s += w[i] * exp(x[i]);
    check_abs(s, expm1(3.0), 1.3e-15 + 16 * EPS * expm1(3.0), "integral of e^x over [0, 3]");
}

static void the_nodes_should_lie_in_their_pieces_in_the_documented_order(void **state)
{
    (void)state;
    double x[20], w[20], a = 2, b = 5, ws = 0;
    mm_quad_gl5_nodes(a, b, 4, x, w);
    for (int k = 0; k < 4; k++) {
        double lo = a + (b - a) * k / 4, hi = a + (b - a) * (k + 1) / 4, mid = 0.5 * (lo + hi);
        check_abs(x[5 * k], mid, 4 * EPS * b, "first node of a piece: its middle");
        assert_true(x[5 * k + 1] > mid && x[5 * k + 2] < mid);              /* +-0.538 */
        assert_true(x[5 * k + 3] > x[5 * k + 1] && x[5 * k + 3] < hi);      /* +0.906 */
        assert_true(x[5 * k + 4] < x[5 * k + 2] && x[5 * k + 4] > lo);      /* -0.906 */
        check_rel(x[5 * k + 1] - mid, mid - x[5 * k + 2], 1e-14, "symmetric about the middle");
        for (int g = 0; g < 5; g++) {
            assert_true(w[5 * k + g] > 0);
            ws += w[5 * k + g];
        }
    }
    check_rel(ws, b - a, 8 * EPS, "the weights add up to the length");
}

/* One table of nodes and weights in the code base (mm_quad_gl5_node,
 * mm_quad_gl5_weight, correctly rounded); on [-1, 1] the rule is that
 * table, mid, then +-0.538, +-0.906.  Its own 16-digit copy had the
 * weights 0.2369... and 0.4786... 1 ulp high. */
static void the_rule_should_be_the_one_table(void **state)
{
    (void)state;
    static const int order[5] = {2, 3, 1, 4, 0};
    double x[5], w[5];
    mm_quad_gl5_nodes(-1, 1, 1, x, w);
    for (int g = 0; g < 5; g++) {
        check_abs(x[g], mm_quad_gl5_node[order[g]], 0, "the table's node");
        check_abs(w[g], mm_quad_gl5_weight[order[g]], 0, "the table's weight");
    }
    check_abs(mm_quad_gl5_weight[0], 0.236926885056189087514264040719918, 0, "correctly rounded");
    check_abs(mm_quad_gl5_weight[1], 0.478628670499366468041291514835639, 0, "correctly rounded");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(monomials_up_to_degree_9_should_be_integrated_exactly),
        cmocka_unit_test(degree_10_should_miss_by_the_rule_error_term),
        cmocka_unit_test(a_smooth_integrand_should_meet_its_closed_form),
        cmocka_unit_test(the_nodes_should_lie_in_their_pieces_in_the_documented_order),
        cmocka_unit_test(the_rule_should_be_the_one_table),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
