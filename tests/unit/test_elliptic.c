/* test_elliptic.c — K, F and the Jacobi functions (mm_elliptic) against
 * closed forms at the singular values, 25-digit values (mpmath 1.3,
 * ellipk at 40 digits), their defining identities and their limits. */
#include "mm_test.h"

#include <float.h>

#include "mm_elliptic.h"

#define PI 3.14159265358979323846
#define EPS DBL_EPSILON

static void k_should_match_closed_forms_at_singular_values(void **state)
{
    (void)state;
    /* K(0) = pi/2; K(1/sqrt 2) = Gamma(1/4)^2 / (4 sqrt pi);
     * K(sin 15 deg) = 3^(1/4) Gamma(1/3)^3 / (2^(7/3) pi).  tgamma is good
     * to a few eps, so 16 eps */
    check_rel(mm_elliptic_K(0), PI / 2, 2 * EPS, "K(0) = pi/2");
    check_rel(mm_elliptic_Kc(sqrt(0.5)), tgamma(0.25) * tgamma(0.25) / (4 * sqrt(PI)), 16 * EPS,
              "K(1/sqrt 2) = Gamma(1/4)^2 / (4 sqrt pi)");
    double k = (sqrt(6) - sqrt(2)) / 4, kc = (sqrt(6) + sqrt(2)) / 4;   /* sin and cos of 15 degrees */
    double want = pow(3, 0.25) * pow(tgamma(1.0 / 3), 3) / (pow(2, 7.0 / 3) * PI);
    check_rel(mm_elliptic_Kc(kc), want, 16 * EPS, "K(sin 15 deg) = 3^(1/4) Gamma(1/3)^3 / (2^(7/3) pi)");
    check_rel(mm_elliptic_K(k), want, 16 * EPS, "K(k) from k itself, away from 1");
    assert_true(isinf(mm_elliptic_Kc(0)));
}

static void k_should_match_published_values(void **state)
{
    (void)state;
    /* parameter m = k^2 and K(m), 25 digits (mpmath ellipk) */
    static const struct { double m; double K; } tab[] = {
        {0.1, 1.612441348720219398229916}, {0.5, 1.85407467730137191843385},
        {0.9, 2.578092113348173188202571}, {0.99, 3.695637362989874677809954},
        {0.999999, 8.294051463615439985315519},
    };
    for (unsigned i = 0; i < sizeof tab / sizeof tab[0]; i++) {
        double kc = sqrt(1 - tab[i].m);      /* 1 - m is exact for these m; sqrt rounds once */
        /* the AGM to 4 eps, Carlson's R_F to 8 eps (relative); kc's own
         * rounding moves K by ~eps / (kc^2 K) relative: 1e-10 at m = 0.999999 */
        double tol = 8 * EPS + EPS / (kc * kc * tab[i].K);
        check_rel(mm_elliptic_Kc(kc), tab[i].K, tol, "K by the AGM vs mpmath");
        check_rel(mm_elliptic_RF(0, kc * kc, 1), tab[i].K, tol, "K = R_F(0, kc^2, 1) vs mpmath");
    }
}

static void agm_and_carlson_should_agree_to_round_off_up_to_the_separatrix(void **state)
{
    (void)state;
    for (double kc = 1; kc > 1e-300; kc *= 0.37) {
        double a = mm_elliptic_Kc(kc), b = mm_elliptic_RF(0, kc * kc > 0 ? kc * kc : 1e-300, 1);
        if (kc * kc < 1e-300)
            break;
        /* R_F's duplications add ~eps each: about log4(1/kc^2) of them */
        check_rel(a, b, EPS * (8 + 2 * log(1 / kc)), "K: AGM vs Carlson");
    }
    /* K ~ ln(4/kc) + O(kc^2 ln kc) near the separatrix */
    check_rel(mm_elliptic_Kc(1e-9), log(4e9), 1e-15, "K ~ ln(4/kc)");
}

static void jacobi_functions_should_satisfy_their_identities(void **state)
{
    (void)state;
    const double kcs[] = {1, 0.8, 0.3, 1e-2, 1e-5, 1e-9};
    for (unsigned i = 0; i < sizeof kcs / sizeof kcs[0]; i++) {
        double kc = kcs[i], k = sqrt((1 - kc) * (1 + kc)), K = mm_elliptic_Kc(kc);
        for (double u = -3.3 * K; u < 3.3 * K; u += 0.173 * K) {
            double sn, cn, dn, am;
            mm_elliptic_jacobi(u, k, kc, &sn, &cn, &dn, &am);
            check_abs(sn * sn + cn * cn, 1, 8 * EPS, "sn^2 + cn^2 = 1");
            check_abs(dn * dn + k * k * sn * sn, 1, 8 * EPS, "dn^2 + k^2 sn^2 = 1");
            check_abs(sin(am), sn, 8 * EPS, "sn = sin am");
            /* d sn/du = cn dn by a central difference: O(h^2) = 1e-10 with h = 1e-5 K */
            double h = 1e-5 * fmin(K, 1), sp, sm;
            mm_elliptic_jacobi(u + h, k, kc, &sp, NULL, NULL, NULL);
            mm_elliptic_jacobi(u - h, k, kc, &sm, NULL, NULL, NULL);
            check_abs((sp - sm) / (2 * h), cn * dn, 1e-8, "d sn / du = cn dn");
        }
        double sn, cn, dn, am;
        mm_elliptic_jacobi(K, k, kc, &sn, &cn, &dn, &am);
        check_abs(sn, 1, 4 * EPS, "sn(K) = 1");
        check_abs(cn, 0, 4 * EPS, "cn(K) = 0");
        check_rel(dn, kc, 16 * EPS, "dn(K) = kc, to its relative accuracy");
        mm_elliptic_jacobi(0.5 * K, k, kc, &sn, NULL, NULL, NULL);
        check_rel(sn, 1 / sqrt(1 + kc), 8 * EPS, "sn(K/2) = 1/sqrt(1 + kc)");
        /* am is continuous: am(u + 2K) = am(u) + pi */
        double a1, a2;
        mm_elliptic_jacobi(0.3, k, kc, NULL, NULL, NULL, &a1);
        mm_elliptic_jacobi(0.3 + 2 * K, k, kc, NULL, NULL, NULL, &a2);
        check_abs(a2 - a1, PI, 16 * EPS * (1 + K), "am(u + 2K) = am(u) + pi");
        /* F inverts am */
        if (kc > 1e-4)
            for (double u = -2.1 * K; u < 2.1 * K; u += 0.37 * K) {
                mm_elliptic_jacobi(u, k, kc, NULL, NULL, NULL, &am);
                check_abs(mm_elliptic_F(am, k, kc), u, 64 * EPS * (1 + fabs(u)) / (kc * kc),
                          "F(am(u)) = u");
            }
    }
}

static void jacobi_functions_should_reach_their_limits(void **state)
{
    (void)state;
    for (double u = -4; u <= 4; u += 0.25) {
        double sn, cn, dn, am;
        mm_elliptic_jacobi(u, 0, 1, &sn, &cn, &dn, &am);
        check_abs(sn, sin(u), 4 * EPS, "k = 0: sn = sin");
        check_abs(cn, cos(u), 4 * EPS, "k = 0: cn = cos");
        check_abs(dn, 1, 0, "k = 0: dn = 1");
        check_abs(am, u, 4 * EPS * (1 + fabs(u)), "k = 0: am = u");
        mm_elliptic_jacobi(u, 1, 0, &sn, &cn, &dn, &am);
        check_abs(sn, tanh(u), 4 * EPS, "k = 1: sn = tanh");
        check_rel(cn, 1 / cosh(u), 4 * EPS, "k = 1: cn = sech");
        check_rel(dn, 1 / cosh(u), 4 * EPS, "k = 1: dn = sech");
        check_abs(am, 2 * atan(tanh(u / 2)), 8 * EPS, "k = 1: am = the Gudermannian");
        /* just below the separatrix the functions approach the limits:
         * sn - tanh = O(kc^2 (sinh u cosh u - u) sech^2 u) = O(1e-24) here */
        double kc = 1e-12;
        mm_elliptic_jacobi(u, sqrt((1 - kc) * (1 + kc)), kc, &sn, NULL, NULL, NULL);
        check_abs(sn, tanh(u), 8 * EPS, "kc = 1e-12: sn ~ tanh");
    }
}

static void pendulum_period_should_grow_by_one_percent_at_0_398_rad(void **state)
{
    (void)state;
    /* mpmath findroot of 2 K(sin(t/2)) / pi = 1.01: 0.3981767846748320688 */
    double th = 0.3981767846748320688;
    check_rel(2 * mm_elliptic_Kc(cos(th / 2)) / PI, 1.01, 4 * EPS, "T/T0 = 1.01 there");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(k_should_match_closed_forms_at_singular_values),
        cmocka_unit_test(k_should_match_published_values),
        cmocka_unit_test(agm_and_carlson_should_agree_to_round_off_up_to_the_separatrix),
        cmocka_unit_test(jacobi_functions_should_satisfy_their_identities),
        cmocka_unit_test(jacobi_functions_should_reach_their_limits),
        cmocka_unit_test(pendulum_period_should_grow_by_one_percent_at_0_398_rad),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
