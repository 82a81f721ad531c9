/* test_coulomb_run.c — mm_coulomb_integrate (the block on its rough floor
 * integrated arc by arc with events) against the exact rests of
 * mm_coulomb_arcs: the same number of arcs, the same rests and the same
 * plotted motion to the integrator's tolerance, the energy balance (7)
 * closing, the per-arc error estimate of a finer run of the right size;
 * a block released inside the band never moves; an exact arc's energy
 * residual (7) vanishes, a short one's is what the spring keeps. */
#include "mm_test.h"

#include <float.h>
#include <stdlib.h>

#include "mm_coulomb.h"

enum { CAP = 64, NP = 400 };

static void run(const mm_coulomb *s, double rtol_ref, double *tg, mm_coulomb_run *o)
{
    static double t[CAP + 1], x[CAP + 1], xg[NP];
    *o = (mm_coulomb_run){.t = t, .x = x, .xg = xg, .rtol_ref = rtol_ref};
    mm_error err;
    for (int i = 0; i < NP; i++)
        tg[i] = 4.0 * i / (NP - 1);
    assert_int_equal(mm_coulomb_integrate(s, 1e-10, CAP, NP, tg, o, &err), MM_OK);
}

static void integrated_rests_should_be_the_exact_ones(void **state)
{
    (void)state;
    /* m = 2, k = 800 (omega 20), d = 5 mm; a push as well as the release */
    mm_coulomb s = mm_coulomb_make(2, 800, 0.2, 10, 0.0525, 0.3);
    double te[CAP + 1], xe[CAP + 1], sge[CAP + 1], tg[NP];
    int ne = mm_coulomb_arcs(&s, te, xe, sge, CAP + 1);
    mm_coulomb_run o;
    run(&s, 1e-14, tg, &o);
    assert_int_equal(o.n, ne);
    double size = fabs(s.x0) + fabs(s.v0) / s.w + s.d;   /* the largest excursion */
    for (int j = 0; j < ne; j++) {
        /* rtol 1e-10 of the motion's size, a few arcs carried over */
        check_abs(o.x[j], xe[j], 1e-10 * size * (j + 1), "rest place");
        check_abs(o.t[j], te[j], 1e-10 * (j + 1) / s.w, "rest time");
    }
    double worst = 0;
    for (int i = 0; i < NP; i++) {
        double v;
        worst = fmax(worst, fabs(o.xg[i] - mm_coulomb_x(&s, te, xe, sge, ne, tg[i], &v)));
    }
    check_abs(worst, 0, 1e-10 * size * ne, "plotted x against the exact motion");
    /* the arcs' errors, estimated by each arc again at 1e-14: the size of the
     * rests' actual errors, not orders off */
    double dx = 0;
    for (int j = 0; j < ne; j++)
        dx = fmax(dx, fabs(o.x[j] - xe[j]));
    assert_true(o.sum_dx > 0 && o.sum_dx < 1e-9 * size);
    assert_true(dx <= 10 * o.sum_dx + 1e-15 * size);
    /* energy (7): friction takes mu m g per metre slid, to the run's error */
    double E0 = 0.5 * s.k * s.x0 * s.x0 + 0.5 * s.m * s.v0 * s.v0;
    check_abs(mm_coulomb_energy_residual(&s, o.n, o.x), 0, 10 * o.sum_de + 1e-13 * E0, "energy balance (7)");
    check_abs(mm_coulomb_energy_residual(&s, ne, xe), 0, 1e-14 * E0, "the exact rests close it to rounding");
    assert_true(o.steps > 0 && o.evals > o.steps && o.event_evals > 0);
}

/* An arc far below the tolerance is still found: released 7.6e-12 m outside
 * the band (where the rtol 1e-10 run of x0 = 25 d came back), the block
 * slides one arc of that amplitude, to the other side of the centre, and
 * stops half a period later (it used to be one step over the whole arc,
 * the velocity zero unseen). */
static void a_tiny_arc_should_end_at_its_velocity_zero(void **state)
{
    (void)state;
    mm_coulomb s = mm_coulomb_make(20, 4905, 0.1, 9.81, 0.0040000000076379294, 0);
    double tg[NP];
    mm_coulomb_run o;
    run(&s, 0, tg, &o);
    assert_int_equal(o.n, 1);
    /* the zero of a velocity of amplitude A w = 1.2e-10 m/s, slope A w^2,
     * found to the run's absolute tolerance (rtol |x0| ~ 4e-13) over that
     * slope: ~2e-4 s; the place to that tolerance */
    double A = s.x0 - s.d, tol_v = 1e-10 * 2 * s.x0;
    check_abs(o.t[0], M_PI / s.w, tol_v / (A * s.w * s.w), "half a period");
    check_abs(o.x[0], 2 * s.d - s.x0, tol_v / s.w + 1e-17, "x1 = 2 d - x0: as far inside the band as x0 was outside");
    assert_true(fabs(o.x[0]) < s.d);
}

static void a_block_inside_the_band_should_never_move(void **state)
{
    (void)state;
    mm_coulomb s = mm_coulomb_make(2, 800, 0.2, 10, 0.004, 0);    /* |x0| < d = 5 mm */
    double tg[NP];
    mm_coulomb_run o;
    run(&s, 0, tg, &o);
    assert_int_equal(o.n, 0);
    for (int i = 0; i < NP; i++)
        assert_true(o.xg[i] == 0.004);
    assert_true(mm_coulomb_energy_residual(&s, 0, o.x) == 0);
}

/* Eq. (7) over an exact arc: from rest at x0 the block stops at -(x0 - 2 d),
 * losing k (x0^2 - x1^2) / 2 = mu m g |x1 - x0|: the arc's energy residual
 * is 0 but for rounding; a wrong end leaves k (x1^2 - x1'^2)/2 + ... */
static void arc_energy_should_vanish_on_an_exact_arc(void **state)
{
    (void)state;
    mm_coulomb s = mm_coulomb_make(2, 800, 0.2, 10, 0.0525, 0);     /* d = 5 mm */
    double x1 = -(0.0525 - 2 * 0.005), E0 = 0.5 * 800 * 0.0525 * 0.0525;
    check_abs(mm_coulomb_arc_energy(&s, 0.0525, 0, x1), 0, 8 * DBL_EPSILON * E0, "exact arc: 0");
    /* 1 mm short: the spring keeps 800 (0.0425^2 - 0.0415^2)/2 more, friction takes 2 m g mu 1 mm less */
    double short_by = mm_coulomb_arc_energy(&s, 0.0525, 0, x1 + 0.001);
    check_rel(short_by, 0.5 * 800 * (0.0425 * 0.0425 - 0.0415 * 0.0415) + 0.2 * 2 * 10 * 0.001, 1e-13,
              "an arc that stops 1 mm short");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(integrated_rests_should_be_the_exact_ones),
        cmocka_unit_test(a_block_inside_the_band_should_never_move),
        cmocka_unit_test(a_tiny_arc_should_end_at_its_velocity_zero),
        cmocka_unit_test(arc_energy_should_vanish_on_an_exact_arc),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
