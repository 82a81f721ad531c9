/* test_beam_sample.c — the statics additions to mm_beam: the sampled
 * diagrams against the closed forms of a central point load (V = +-P/2,
 * M = P x / 2, y = P x (3 L^2 - 4 x^2) / (48 EI)) with the jump shown by
 * two points; the equilibrium residual against the terms summed by hand;
 * the derivative check within its tolerance on beams with every kind of
 * load. */
#include "mm_test.h"

#include <float.h>

#include "mm_beam.h"

#define EPS DBL_EPSILON

static mm_beam *solved(const mm_beam_problem *p)
{
    mm_beam *b;
    mm_error err;
    if (mm_beam_solve(p, &b, &err) != MM_OK)
        fail_msg("mm_beam_solve: %s", err.msg);
    return b;
}

static void the_sampled_diagrams_should_meet_the_closed_forms(void **state)
{
    (void)state;
    const double L = 4, P = 1000, EI = 2e6;
    double pt[2] = {L / 2, -P};
    mm_beam_problem p = {.L = L, .kind = MM_BEAM_TWO_SUPPORTS, .a = 0, .b = L, .n_point = 1, .point = pt, .EI = EI};
    mm_beam *b = solved(&p);
    int n = 41, total = mm_beam_sample_size(b, n), jumps = 0;
    assert_true(total >= 4 && total <= n);                  /* two segments, two ends each at least */
    double x[64], V[64], M[64], y[64];
    mm_beam_sample(b, n, x, V, M, y);
    check_abs(x[0], 0, 0, "starts at 0");
    check_abs(x[total - 1], L, 0, "ends at L");
    for (int i = 0; i < total; i++) {
        if (i > 0)
            assert_true(x[i] >= x[i - 1]);
        if (i > 0 && x[i] == x[i - 1]) {                    /* the jump under the load */
            jumps++;
            check_abs(x[i], L / 2, 0, "the jump is under the load");
            check_rel(V[i - 1] - V[i], P, 4 * EPS, "V drops by P there");
        }
        double s = x[i] <= L / 2 ? x[i] : L - x[i];          /* distance from the nearer support */
        check_rel(fabs(V[i]), P / 2, 4 * EPS, "|V| = P/2");
        check_abs(M[i], P * s / 2, 16 * EPS * P * L, "M = P s / 2");
        check_abs(y[i], -P * s * (3 * L * L - 4 * s * s) / (48 * EI), 64 * EPS * P * L * L * L / EI,
                  "y = -P s (3 L^2 - 4 s^2) / (48 EI)");
    }
    assert_int_equal(jumps, 1);
    mm_beam_sample(b, n, x, V, M, NULL);                     /* y may be left out */
    mm_beam_free(b);
}

static void the_residual_should_sum_the_terms_written_out(void **state)
{
    (void)state;
    /* P = 1000 down at 2, q from 0 to -600 N/m over [1, 4], C = 300 at 3 on a
     * 4 m simply supported beam: the sums of |terms| by hand */
    double pt[2] = {2, -1000}, d[4] = {1, 4, 0, -600}, c[2] = {3, 300};
    mm_beam_problem p = {.L = 4, .kind = MM_BEAM_TWO_SUPPORTS, .a = 0, .b = 4, .n_point = 1, .point = pt,
                         .n_dist = 1, .dist = d, .n_moment = 1, .moment = c};
    mm_beam *b = solved(&p);
    double x[2], R[2], C[2], Fy, Mo, sF, sM;
    mm_beam_reactions(b, x, R, C);
    mm_beam_residual(&p, b, &Fy, &Mo, &sF, &sM);
    /* the triangle 0..-600 over 3 m: W1 = 0 at x = 2, W2 = -900 at x = 3 */
    double wantF = fabs(R[0]) + fabs(R[1]) + 1000 + 900, wantM = fabs(R[1] * 4) + 2000 + 2700 + 300;
    check_rel(sF, wantF, 4 * EPS, "sum of |forces|");
    check_rel(sM, wantM, 4 * EPS, "sum of |moments|");
    check_abs(Fy, 0, 8 * EPS * sF, "sum Fy = 0 to rounding");
    check_abs(Mo, 0, 8 * EPS * sM, "sum M = 0 to rounding");
    /* the reactions in closed form: R_b 4 = 1000 * 2 + 900 * 3 - 300 */
    check_rel(R[1], (2000 + 2700 - 300) / 4.0, 8 * EPS, "roller reaction by moments about the pin");
    mm_beam_free(b);
}

/* Not a tautology: the tolerances are 16 eps of each segment's terms, so a
 * wrong Gauss-Legendre rule, or a central difference of M left with its
 * truncation d^2 q'/6 (q' = -120 N/m^2 on the first distributed load),
 * comes out far above 1: 4.7e4 for the latter on this beam. */
static void consistent_diagrams_should_pass_the_derivative_check(void **state)
{
    (void)state;
    double pt[4] = {1, -500, 3.3, 200}, d[8] = {0, 2.5, -100, -400, 2, 4, 50, 0}, c[2] = {1.7, -250};
    mm_beam_problem two = {.L = 4, .kind = MM_BEAM_TWO_SUPPORTS, .a = 0.5, .b = 3.5, .n_point = 2, .point = pt,
                           .n_dist = 2, .dist = d, .n_moment = 1, .moment = c};
    mm_beam_problem cant = two;
    cant.kind = MM_BEAM_CANTILEVER;
    const mm_beam_problem *ps[2] = {&two, &cant};
    for (int k = 0; k < 2; k++) {
        mm_beam *b = solved(ps[k]);
        double wi, wd;
        mm_beam_derivative_check(b, &wi, &wd);
        assert_true(wi <= 1 && wd <= 1);
        mm_beam_free(b);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_sampled_diagrams_should_meet_the_closed_forms),
        cmocka_unit_test(the_residual_should_sum_the_terms_written_out),
        cmocka_unit_test(consistent_diagrams_should_pass_the_derivative_check),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
