/* test_natural.c — mm_natural's planar linkages in natural coordinates
 * against what they must satisfy: the constraints vanish at the assembly,
 * the Jacobian is their derivative (central differences), a four-bar has
 * one freedom (rank 3 of 4 unknowns), and a four-bar driven round its
 * crank by Newton (mm_mech) lands on Freudenstein's closed form
 * (mm_linkage), an independent solution; a slider stays on its line. */
#include "mm_test.h"

#include <float.h>

#include "mm_linkage.h"
#include "mm_natural.h"

#define EPS DBL_EPSILON

/* kin-mobility's four-bar: O2 (0, 0), O4 (0.6, 0), A, B; bars O2A, AB, O4B; the crank O2A driven */
static const mm_nat_linkage four_bar = {2, 4,
                                        {{0, 0}, {0.6, 0}, {0.10806046117362795, 0.16829419696157930}, {0.55, 0.4}},
                                        3, {{0, 2}, {2, 3}, {1, 3}}, -1, 1, {{0, 2}}, 0};
/* its slider-crank: O, A, B with B on y = 0 */
static const mm_nat_linkage slider = {1, 3, {{0, 0}, {0.054030230586813977, 0.084147098480789651}, {0.45, 0}},
                                      2, {{0, 1}, {1, 2}}, 2, 1, {{0, 1}}, 0};

static void the_constraints_should_vanish_at_the_assembly_and_differentiate(void **state)
{
    (void)state;
    const mm_nat_linkage *ls[2] = {&four_bar, &slider};
    for (int l = 0; l < 2; l++) {
        mm_nat_model m;
        mm_mech_problem p;
        double q[2 * MM_NAT_MAXP], F[MM_NAT_MAXC + 3], J[(MM_NAT_MAXC + 3) * 2 * MM_NAT_MAXP];
        mm_nat_init(&m, ls[l], 1, q);
        mm_nat_problem(&m, &p);
        assert_int_equal(p.n, 2 * (ls[l]->npts - ls[l]->nfix));
        assert_int_equal(p.m, ls[l]->ncon + (ls[l]->slide >= 0) + ls[l]->ndrv);
        p.phi(q, 0, F, p.params);
        for (int r = 0; r < p.m; r++)
            check_abs(F[r], 0, 4 * EPS, "every constraint holds at the assembly (t = 0: the drivers' start)");
        /* the Jacobian against central differences at a point off the assembly */
        for (int c = 0; c < p.n; c++)
            q[c] += 0.01 * (c + 1);
        p.jac(q, 0.3, J, p.params);
        for (int c = 0; c < p.n; c++) {
            const double h = 1e-6;
            double qp[2 * MM_NAT_MAXP], Fp[MM_NAT_MAXC + 3], Fm[MM_NAT_MAXC + 3];
            for (int e = 0; e < p.n; e++)
                qp[e] = q[e];
            qp[c] = q[c] + h, p.phi(qp, 0.3, Fp, p.params);
            qp[c] = q[c] - h, p.phi(qp, 0.3, Fm, p.params);
            for (int r = 0; r < p.m; r++)   /* the constraints are quadratic: exact to rounding, eps / h */
                check_abs((Fp[r] - Fm[r]) / (2 * h), J[r * p.n + c], 1e-9, "Jacobian vs central difference");
        }
    }
}

static void a_four_bar_should_have_one_freedom_and_follow_freudenstein(void **state)
{
    (void)state;
    mm_nat_model m, md;
    mm_mech_problem free_, prob;
    double q[2 * MM_NAT_MAXP], sv[4];
    mm_nat_init(&m, &four_bar, 0, q);
    mm_nat_init(&md, &four_bar, 1, NULL);
    mm_nat_problem(&m, &free_);
    mm_nat_problem(&md, &prob);
    mm_mech_work *wf = mm_mech_work_alloc(4, 3), *w = mm_mech_work_alloc(4, 4);
    assert_true(wf && w);
    int rank = 0;
    assert_int_equal(mm_mech_rank(&free_, wf, 0, q, 0, sv, &rank, NULL), MM_OK);
    mm_mech_work_free(wf);
    assert_int_equal(rank, 3);                                  /* 4 unknowns - 3 bars: one freedom */
    /* the crank driven round: theta2 = th0 + t; the link lengths of the assembly */
    enum { NF = 24 };
    double t[NF], Q[4 * NF];
    for (int f = 0; f < NF; f++)
        t[f] = 2 * 3.14159265358979323846 * f / NF;
    for (int e = 0; e < 4; e++)
        Q[e] = q[e];
    mm_mech_options opt;
    mm_mech_options_init(&opt);
    mm_mech_sweep sw = {.nt = NF, .t = t, .q = Q, .watch = -1};
    assert_int_equal(mm_mech_sweep_solve(&prob, &opt, w, &sw, NULL), MM_OK);
    assert_int_equal(sw.solved, NF);
    const double *A = four_bar.p[2], *B = four_bar.p[3];
    mm_fourbar fb = {hypot(A[0], A[1]), hypot(B[0] - A[0], B[1] - A[1]), hypot(B[0] - 0.6, B[1]), 0.6};
    for (int f = 0; f < NF; f++) {
        double *qf = Q + 4 * f, th2 = md.th0[0] + t[f], th3, th4, ferr;
        mm_linkage_fb_angles(&fb, th2, 1, &th3, &th4, &ferr);      /* the open assembly, as drawn */
        /* Newton to rounding: at most 2.2e-16 measured */
        check_abs(qf[0], fb.a * cos(th2), 16 * EPS, "A on the crank circle at theta2");
        check_abs(qf[1], fb.a * sin(th2), 16 * EPS, "A on the crank circle at theta2");
        check_abs(qf[2], 0.6 + fb.c * cos(th4), 16 * EPS, "B where Freudenstein puts it");
        check_abs(qf[3], fb.c * sin(th4), 16 * EPS, "B where Freudenstein puts it");
    }
    mm_mech_work_free(w);
}

static void a_slider_should_stay_on_its_line(void **state)
{
    (void)state;
    mm_nat_model md;
    mm_mech_problem prob;
    double q[2 * MM_NAT_MAXP];
    mm_nat_init(&md, &slider, 1, q);
    mm_nat_problem(&md, &prob);
    mm_mech_work *w = mm_mech_work_alloc(prob.n, prob.m);
    mm_mech_options opt;
    mm_mech_options_init(&opt);
    mm_mech_info info;
    assert_int_equal(mm_mech_position(&prob, &opt, w, 1.0, q, &info, NULL), MM_OK);
    double x, y, ax, ay;
    mm_nat_point(&md, q, 2, &x, &y);
    mm_nat_point(&md, q, 1, &ax, &ay);
    check_abs(y, 0, 0, "the slider on y = 0 (a linear constraint: exact)");
    check_abs(atan2(ay, ax), md.th0[0] + 1.0, 4 * EPS, "the crank at th0 + t");
    check_rel(hypot(x - ax, y - ay), hypot(0.45 - 0.054030230586813977, 0.084147098480789651), 16 * EPS,
              "the rod keeps its length");
    mm_mech_work_free(w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_constraints_should_vanish_at_the_assembly_and_differentiate),
        cmocka_unit_test(a_four_bar_should_have_one_freedom_and_follow_freudenstein),
        cmocka_unit_test(a_slider_should_stay_on_its_line),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
