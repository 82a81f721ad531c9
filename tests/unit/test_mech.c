/* test_mech.c — mm_mech against closed forms:
 *   - the slider-crank x(phi) = r cos phi + sqrt(l^2 - (e - r sin phi)^2) and
 *     its derivatives, over a revolution, by the driven sweep;
 *   - the four-bar against Freudenstein's equation, in joint angles (own LU)
 *     and in body coordinates (9 x 9: LAPACK through mm_linalg);
 *   - Newton's quadratic convergence and its error estimate;
 *   - velocities against central differences of the positions (error ~ h^2);
 *   - a non-Grashof four-bar stops closing at the toggle of the closed form;
 *   - a crank-rocker's dead centres (rocker turning back) where crank and
 *     coupler are in line;
 *   - a parallelogram (change point) is carried through the crossing of the
 *     branches without leaving the parallelogram;
 *   - the Jacobian exactly singular (a toggle) refuses velocities;
 *   - an overconstrained but consistent linkage (double parallelogram):
 *     Newton by least squares, mobility 1 from the rank although
 *     Grubler-Kutzbach counts 0. */
#include "mm_test.h"

#include <float.h>
#include <string.h>

#include "mm_mech.h"

#define EPS DBL_EPSILON

/* ---- the slider-crank: q = (theta3, x), driver phi = t --------------------------- */

typedef struct sc {
    double r, l, e, omega;
} sc;

/* loop closure: r cos phi + l cos th3 - x = 0, r sin phi + l sin th3 - e = 0
 * (crank tip to slider pin along the rod), with phi = omega t */
static int sc_phi(const double *q, double t, double *F, void *pp)
{
    const sc *p = pp;
    double phi = p->omega * t;
    F[0] = p->r * cos(phi) + p->l * cos(q[0]) - q[1];
    F[1] = p->r * sin(phi) + p->l * sin(q[0]) - p->e;
    return 0;
}

static int sc_jac(const double *q, double t, double *J, void *pp)
{
    (void)t;
    const sc *p = pp;
    J[0] = -p->l * sin(q[0]), J[1] = -1;
    J[2] = p->l * cos(q[0]), J[3] = 0;
    return 0;
}

static int sc_nu(const double *q, double t, double *nu, void *pp)
{
    (void)q;
    const sc *p = pp;
    double phi = p->omega * t;
    nu[0] = p->r * p->omega * sin(phi);          /* -Phi_t */
    nu[1] = -p->r * p->omega * cos(phi);
    return 0;
}

static int sc_gamma(const double *q, const double *qd, double t, double *g, void *pp)
{
    const sc *p = pp;
    double phi = p->omega * t, w2 = p->omega * p->omega;
    g[0] = p->r * w2 * cos(phi) + p->l * cos(q[0]) * qd[0] * qd[0];
    g[1] = p->r * w2 * sin(phi) + p->l * sin(q[0]) * qd[0] * qd[0];
    return 0;
}

static const unsigned char sc_len[2] = {0, 1};

/* the closed form: x, v = dx/dt, a = d2x/dt2 (s = e - r sin phi) */
static void sc_exact(const sc *p, double phi, double *x, double *v, double *a)
{
    double w = p->omega, s = p->e - p->r * sin(phi), R = sqrt(p->l * p->l - s * s);
    double ds = -p->r * cos(phi), dds = p->r * sin(phi);        /* d/dphi */
    *x = p->r * cos(phi) + R;
    double dR = -s * ds / R, ddR = -(ds * ds + s * dds) / R - s * s * ds * ds / (R * R * R);
    *v = w * (-p->r * sin(phi) + dR);
    *a = w * w * (-p->r * cos(phi) + ddR);
}

static void slider_crank_sweep_should_match_the_closed_form(void **state)
{
    (void)state;
    sc p = {0.1, 0.4, 0.03, 100};
    mm_mech_problem prob = {.n = 2, .m = 2, .phi = sc_phi, .jac = sc_jac, .nu = sc_nu, .gamma = sc_gamma,
                            .is_length = sc_len, .params = &p};
    mm_mech_options opt;
    mm_mech_options_init(&opt);
    opt.length = p.l;
    assert_int_equal(mm_mech_check(&prob, &opt, NULL), MM_OK);
    mm_mech_work *w = mm_mech_work_alloc(2, 2);
    enum { NT = 73 };
    double t[NT], q[2 * NT], qd[2 * NT], qdd[2 * NT];
    for (int i = 0; i < NT; i++)
        t[i] = 2 * M_PI * i / (NT - 1) / p.omega;
    q[0] = 0.1, q[1] = 0.5;                      /* a rough assembly guess */
    mm_mech_sweep s = {.nt = NT, .t = t, .q = q, .qd = qd, .qdd = qdd, .watch = 1};
    mm_error err;
    assert_int_equal(mm_mech_sweep_solve(&prob, &opt, w, &s, &err), MM_OK);
    assert_int_equal(s.solved, NT);
    double ex = 0, ev = 0, ea = 0;
    for (int i = 0; i < NT; i++) {
        double x, v, a;
        sc_exact(&p, p.omega * t[i], &x, &v, &a);
        ex = fmax(ex, fabs(q[2 * i + 1] - x));
        ev = fmax(ev, fabs(qd[2 * i + 1] - v));
        ea = fmax(ea, fabs(qdd[2 * i + 1] - a));
    }
    /* rounding only: |x| ~ 0.5 m, |v| ~ 10 m/s, |a| ~ 1300 m/s^2, cond ~ 10 */
    check_abs(ex, 0, 64 * EPS * 0.5, "x against the closed form, worst frame");
    check_abs(ev, 0, 64 * EPS * 10, "v against the closed form");
    check_abs(ea, 0, 64 * EPS * 1300, "a against the closed form");
    check_abs(s.err_est, 0, 1e-14, "Newton's own error estimate stays at rounding");
    /* the dead centres: v = 0 where crank and rod are in line,
     * phi = asin(e/(l+r)) and pi + asin(e/(l-r)) */
    assert_int_equal(s.n_turn, 2);
    check_abs(p.omega * s.t_turn[0], asin(p.e / (p.l + p.r)), 1e-9, "outer dead centre");
    check_abs(p.omega * s.t_turn[1], M_PI + asin(p.e / (p.l - p.r)), 1e-9, "inner dead centre");
    check_rel(s.q_turn[0], sqrt((p.l + p.r) * (p.l + p.r) - p.e * p.e), 1e-12, "x at the outer dead centre");
    assert_int_equal(s.n_sing, 0);
    mm_mech_work_free(w);
}

/* A slider-crank that only just turns round (l a hair longer than |e| + r):
 * near phi = -pi/2 the rod nearly stands square to the slide and the two
 * assemblies (x = r cos phi +- sqrt(l^2 - s^2)) pass within 2 sqrt(...) of
 * each other.  Frames a 24th of a turn apart once stepped across to the
 * other one (a random draw of kin-slider-crank found it); det changes sign
 * there, the bisection's midpoints leave the chord, and the step is cut. */
static void a_sweep_should_not_jump_between_assemblies_that_pass_close(void **state)
{
    (void)state;
    const double margins[] = {1.8e-3, 1e-4, 1e-6};
    for (int k = 0; k < 3; k++) {
        sc p = {2.3960861360947723, 0, -5.871475224137694, 1};
        p.l = fabs(p.e) + p.r + margins[k] * p.r;
        mm_mech_problem prob = {.n = 2, .m = 2, .phi = sc_phi, .jac = sc_jac, .nu = sc_nu, .gamma = sc_gamma,
                                .is_length = sc_len, .params = &p};
        mm_mech_options opt;
        mm_mech_options_init(&opt);
        opt.length = p.l;
        mm_mech_work *w = mm_mech_work_alloc(2, 2);
        enum { NT = 25 };
        double po = asin(p.e / (p.l + p.r)), t[NT], q[2 * NT], qd[2 * NT];
        for (int i = 0; i < NT; i++)
            t[i] = po + 0.25 + 2 * M_PI * i / (NT - 1);
        double x, v, a;
        sc_exact(&p, t[0], &x, &v, &a);
        q[0] = atan2(p.e - p.r * sin(t[0]), x - p.r * cos(t[0])), q[1] = x;
        mm_mech_sweep s = {.nt = NT, .t = t, .q = q, .qd = qd, .watch = 1};
        mm_error err;
        assert_int_equal(mm_mech_sweep_solve(&prob, &opt, w, &s, &err), MM_OK);
        assert_int_equal(s.solved, NT);
        double ex = 0;
        for (int i = 0; i < NT; i++) {
            sc_exact(&p, t[i], &x, &v, &a);
            ex = fmax(ex, fabs(q[2 * i + 1] - x));
        }
        /* the same assembly on every frame: rounding of x (~ 10 m), the
         * other assembly being at least 2 sqrt(l^2 - (|e| + r)^2) away */
        check_abs(ex, 0, 1e-9, "x on the assembly it started on, every frame");
        assert_int_equal(s.n_sing, 0);
        assert_int_equal(s.n_turn, 2);
        /* from po + 0.25: the inner dead centre first, then the outer a turn on */
        check_abs(s.t_turn[0], M_PI + asin(p.e / (p.l - p.r)), 1e-9, "inner dead centre");
        check_abs(s.t_turn[1], po + 2 * M_PI, 1e-9, "outer dead centre");
        mm_mech_work_free(w);
    }
}

static void newton_should_converge_quadratically_with_an_honest_error_estimate(void **state)
{
    (void)state;
    sc p = {0.1, 0.4, 0, 1};
    mm_mech_problem prob = {.n = 2, .m = 2, .phi = sc_phi, .jac = sc_jac, .is_length = sc_len, .params = &p};
    mm_mech_options opt;
    mm_mech_options_init(&opt);
    opt.length = 0.4;
    mm_mech_work *w = mm_mech_work_alloc(2, 2);
    double x, v, a, phi = 0.7;
    sc_exact(&p, phi, &x, &v, &a);
    double th3 = asin(-p.r * sin(phi) / p.l);
    /* a guess 0.2 rad and 5 cm off */
    double q[2] = {th3 + 0.2, x + 0.05};
    mm_mech_info info;
    assert_int_equal(mm_mech_position(&prob, &opt, w, phi, q, &info, NULL), MM_OK);
    assert_true(info.iterations <= 6);           /* quadratic: 0.2 -> 1e-2 -> 1e-4 -> 1e-8 -> 1e-16 */
    double e = fmax(fabs(q[0] - th3), fabs(q[1] - x) / 0.4);
    check_abs(e, 0, 8 * EPS, "Newton's solution against the closed form (weighted)");
    assert_true(e <= info.err_est + 4 * EPS);    /* the estimate bounds what was made */
    check_abs(info.residual, 0, 4 * EPS * 0.5, "residual at rounding");
    assert_true(info.rcond > 0.1);
    mm_mech_work_free(w);
}

/* ---- the four-bar in joint angles: q = (theta2, theta3, theta4), theta2 = t ------ */

typedef struct fb {
    double a, b, c, d;
} fb;

static int fb_phi(const double *q, double t, double *F, void *pp)
{
    const fb *p = pp;
    F[0] = p->a * cos(q[0]) + p->b * cos(q[1]) - p->c * cos(q[2]) - p->d;
    F[1] = p->a * sin(q[0]) + p->b * sin(q[1]) - p->c * sin(q[2]);
    F[2] = q[0] - t;
    return 0;
}

static int fb_jac(const double *q, double t, double *J, void *pp)
{
    (void)t;
    const fb *p = pp;
    double Jv[9] = {-p->a * sin(q[0]), -p->b * sin(q[1]), p->c * sin(q[2]),
                    p->a * cos(q[0]), p->b * cos(q[1]), -p->c * cos(q[2]), 1, 0, 0};
    memcpy(J, Jv, sizeof Jv);
    return 0;
}

static int fb_nu(const double *q, double t, double *nu, void *pp)
{
    (void)q, (void)t, (void)pp;
    nu[0] = nu[1] = 0, nu[2] = 1;
    return 0;
}

static int fb_gamma(const double *q, const double *qd, double t, double *g, void *pp)
{
    (void)t;
    const fb *p = pp;
    double w2 = qd[0] * qd[0], w3 = qd[1] * qd[1], w4 = qd[2] * qd[2];
    g[0] = p->a * cos(q[0]) * w2 + p->b * cos(q[1]) * w3 - p->c * cos(q[2]) * w4;
    g[1] = p->a * sin(q[0]) * w2 + p->b * sin(q[1]) * w3 - p->c * sin(q[2]) * w4;
    g[2] = 0;
    return 0;
}

/* theta4 by Freudenstein's equation K1 cos t4 - K2 cos t2 + K3 = cos(t2 - t4),
 * solved by the half-angle substitution; the root nearest `near` */
static double freudenstein(const fb *p, double t2, double near)
{
    double K1 = p->d / p->a, K2 = p->d / p->c;
    double K3 = (p->a * p->a - p->b * p->b + p->c * p->c + p->d * p->d) / (2 * p->a * p->c);
    double A = cos(t2) - K1 - K2 * cos(t2) + K3, B = -2 * sin(t2), C = K1 - (K2 + 1) * cos(t2) + K3;
    double D = sqrt(fmax(B * B - 4 * A * C, 0));
    double r1 = 2 * atan2(-B - D, 2 * A), r2 = 2 * atan2(-B + D, 2 * A);
    return fabs(remainder(r1 - near, 2 * M_PI)) < fabs(remainder(r2 - near, 2 * M_PI)) ? r1 : r2;
}

static mm_mech_problem fb_problem(fb *p)
{
    return (mm_mech_problem){.n = 3, .m = 3, .phi = fb_phi, .jac = fb_jac, .nu = fb_nu, .gamma = fb_gamma,
                             .params = p};
}

/* t2 = 0.3 rad open assembly of a four-bar, from the circle intersection */
static void fb_assemble(const fb *p, double t2, int left, double *q)
{
    double Bx = p->a * cos(t2), By = p->a * sin(t2), ex = p->d - Bx, ey = -By, e = hypot(ex, ey);
    double al = acos((p->b * p->b + e * e - p->c * p->c) / (2 * p->b * e));
    double th3 = atan2(ey, ex) + (left ? al : -al);
    double Cx = Bx + p->b * cos(th3), Cy = By + p->b * sin(th3);
    q[0] = t2, q[1] = th3, q[2] = atan2(Cy, Cx - p->d);
}

static void four_bar_should_match_freudenstein_and_differences_of_its_positions(void **state)
{
    (void)state;
    fb p = {0.2, 0.5, 0.4, 0.6};                  /* API.md's default: a crank-rocker */
    mm_mech_problem prob = fb_problem(&p);
    mm_mech_options opt;
    mm_mech_options_init(&opt);
    mm_mech_work *w = mm_mech_work_alloc(3, 3);
    enum { NT = 121 };
    double t[NT], q[3 * NT], qd[3 * NT], qdd[3 * NT];
    for (int i = 0; i < NT; i++)
        t[i] = 2 * M_PI * i / (NT - 1);
    fb_assemble(&p, 0, 1, q);
    mm_mech_sweep s = {.nt = NT, .t = t, .q = q, .qd = qd, .qdd = qdd, .watch = 2};
    assert_int_equal(mm_mech_sweep_solve(&prob, &opt, w, &s, NULL), MM_OK);
    assert_int_equal(s.solved, NT);
    assert_int_equal(s.n_sing, 0);
    double worst = 0;
    for (int i = 0; i < NT; i++)
        worst = fmax(worst, fabs(remainder(q[3 * i + 2] - freudenstein(&p, t[i], q[3 * i + 2]), 2 * M_PI)));
    /* rounding in two methods with cond ~ 1/sin(transmission angle) <= 5 */
    check_abs(worst, 0, 64 * EPS, "theta4 against Freudenstein, worst frame");
    /* omega4 = d theta4 / d theta2 against central differences: h^2 */
    int i = 20;
    double e[3];
    for (int k = 0; k < 3; k++) {
        double h = 0.02 / (1 << k), qp[3], qm[3];
        memcpy(qp, q + 3 * i, sizeof qp);
        memcpy(qm, q + 3 * i, sizeof qm);
        assert_int_equal(mm_mech_position(&prob, &opt, w, t[i] + h, qp, NULL, NULL), MM_OK);
        assert_int_equal(mm_mech_position(&prob, &opt, w, t[i] - h, qm, NULL, NULL), MM_OK);
        e[k] = fabs((qp[2] - qm[2]) / (2 * h) - qd[3 * i + 2]);
    }
    check_rel(e[0] / e[1], 4, 0.05, "halving h quarters the difference error");
    check_rel(e[1] / e[2], 4, 0.05, "and again");
    /* the rocker's dead centres: crank and coupler in line, |O4 C| = c with
     * |O2 C| = b + a and b - a: cos theta2 from the triangle O2 O4 C */
    assert_int_equal(s.n_turn, 2);
    for (int k = 0; k < 2; k++) {
        double L = k == 0 ? p.b + p.a : p.b - p.a;
        double phi = acos((L * L + p.d * p.d - p.c * p.c) / (2 * L * p.d));   /* angle of O2C */
        double t2 = k == 0 ? phi : phi + M_PI;                                 /* crank along or against */
        int j = fabs(remainder(s.t_turn[0] - t2, 2 * M_PI)) < fabs(remainder(s.t_turn[1] - t2, 2 * M_PI)) ? 0 : 1;
        check_abs(remainder(s.t_turn[j] - t2, 2 * M_PI), 0, 1e-9, "a dead centre of the rocker");
    }
    mm_mech_work_free(w);
}

static void a_non_grashof_four_bar_should_stop_at_its_toggle(void **state)
{
    (void)state;
    fb p = {0.5, 0.3, 0.4, 0.35};                 /* s + l = 0.8 > p + q = 0.75 */
    mm_mech_problem prob = fb_problem(&p);
    mm_mech_options opt;
    mm_mech_options_init(&opt);
    mm_mech_work *w = mm_mech_work_alloc(3, 3);
    /* toggle where |O4 B| = b + c: cos t2 = (a^2 + d^2 - (b + c)^2) / (2 a d) */
    double tog = acos((p.a * p.a + p.d * p.d - (p.b + p.c) * (p.b + p.c)) / (2 * p.a * p.d));
    enum { NT = 41 };
    double t[NT], q[3 * NT], qd[3 * NT];
    for (int i = 0; i < NT; i++)
        t[i] = 0.3 + 2.0 * i / (NT - 1);
    fb_assemble(&p, t[0], 1, q);
    mm_mech_sweep s = {.nt = NT, .t = t, .q = q, .qd = qd, .watch = -1, .tol_t = 1e-13};
    assert_int_equal(mm_mech_sweep_solve(&prob, &opt, w, &s, NULL), MM_OK);
    assert_true(s.solved < NT);
    assert_true(t[s.solved - 1] < tog && t[s.solved] > tog);
    /* located by halving steps to 1e-13: near the toggle Newton's
     * reach is limited by the double root (sqrt of rounding ~ 1e-8 in q,
     * 1e-16 in t); 1e-10 leaves room */
    check_abs(s.t_limit, tog, 1e-10, "where the four-bar stops closing");
    assert_int_equal(mm_mech_sweep_solve(&prob, &opt, w, &s, NULL), MM_OK);
    mm_mech_work_free(w);
}

static void a_parallelogram_should_stay_a_parallelogram_through_the_change_point(void **state)
{
    (void)state;
    fb p = {0.3, 0.6, 0.3, 0.6};                  /* s + l = p + q: a change point at theta2 = 0, pi */
    mm_mech_problem prob = fb_problem(&p);
    mm_mech_options opt;
    mm_mech_options_init(&opt);
    mm_mech_work *w = mm_mech_work_alloc(3, 3);
    enum { NT = 73 };
    double t[NT], q[3 * NT], qd[3 * NT];
    for (int i = 0; i < NT; i++)
        t[i] = 0.1 + 2 * M_PI * i / (NT - 1);     /* passes pi and 2 pi between frames */
    q[0] = t[0], q[1] = 0.02, q[2] = t[0] + 0.02;  /* near the parallelogram */
    mm_mech_sweep s = {.nt = NT, .t = t, .q = q, .qd = qd, .watch = -1};
    assert_int_equal(mm_mech_sweep_solve(&prob, &opt, w, &s, NULL), MM_OK);
    assert_int_equal(s.solved, NT);
    double worst = 0;
    for (int i = 0; i < NT; i++) {
        worst = fmax(worst, fabs(remainder(q[3 * i + 1], 2 * M_PI)));                  /* coupler level */
        worst = fmax(worst, fabs(remainder(q[3 * i + 2] - t[i], 2 * M_PI)));           /* rocker = crank */
        worst = fmax(worst, fabs(qd[3 * i + 2] - 1));                                  /* omega4 = omega2 */
    }
    /* near the crossings the Jacobian's cond grows like 1/|sin theta2|:
     * at 0.1 rad from them, 10 eps-ish per solve */
    check_abs(worst, 0, 1e-12, "theta3 = 0, theta4 = theta2, omega4 = omega2 on every frame");
    /* det Phi_q = -a c sin(theta4 - theta3) b... changes sign at pi and 2 pi */
    assert_int_equal(s.n_sing, 2);
    check_abs(s.t_sing[0], M_PI, 1e-9, "the change point at pi");
    check_abs(s.t_sing[1], 2 * M_PI, 1e-9, "and at 2 pi");

    /* a frame exactly on the change point, links 1000 : 1 (make bench found
     * it): Newton stops there at the rounding floor, and the solution says
     * nothing of which way the motion goes on; the predictor must keep to
     * the frames before it, or the next steps land on the other assembly
     * and the sweep stalls */
    fb big = {10, 0.01, 10, 0.01};
    prob = fb_problem(&big);
    for (int i = 0; i < NT; i++)
        t[i] = M_PI / 2 + M_PI * i / (NT - 1);
    t[(NT - 1) / 2] = M_PI;
    q[0] = t[0], q[1] = 0.02, q[2] = t[0] + 0.02;
    mm_mech_sweep s2 = {.nt = NT, .t = t, .q = q, .qd = qd, .watch = -1};
    assert_int_equal(mm_mech_sweep_solve(&prob, &opt, w, &s2, NULL), MM_OK);
    assert_int_equal(s2.solved, NT);
    worst = 0;
    for (int i = 0; i < NT; i++)
        if (i != (NT - 1) / 2) {
            worst = fmax(worst, fabs(remainder(q[3 * i + 1], 2 * M_PI)));
            worst = fmax(worst, fabs(remainder(q[3 * i + 2] - t[i], 2 * M_PI)));
        }
    /* the frames next to pi are pi/72 from it: cond ~ a / (b |sin|) ~ 2e4 */
    check_abs(worst, 0, 1e-10, "a parallelogram on both sides of the frame on the change point");
    assert_int_equal(s2.n_sing, 1);
    mm_mech_work_free(w);
}

static void velocities_should_be_refused_exactly_at_a_toggle(void **state)
{
    (void)state;
    fb p = {0.5, 0.3, 0.4, 0.35};
    mm_mech_problem prob = fb_problem(&p);
    mm_mech_options opt;
    mm_mech_options_init(&opt);
    mm_mech_work *w = mm_mech_work_alloc(3, 3);
    /* at the toggle coupler and rocker lie along O4 B: theta3 = theta4 = its angle */
    double tog = acos((p.a * p.a + p.d * p.d - 0.49) / (2 * p.a * p.d));
    double Bx = p.a * cos(tog), By = p.a * sin(tog), ang = atan2(By, Bx - p.d) + M_PI;
    double q[3] = {tog, ang, ang + M_PI}, qd[3];
    /* coupler from B towards O4, rocker from O4 towards B: theta4 = theta3 + pi */
    q[2] = atan2(By, Bx - p.d);
    q[1] = q[2] + M_PI;
    mm_error err;
    mm_mech_info info;
    assert_int_equal(mm_mech_velocity(&prob, &opt, w, tog, q, qd, &info, &err), MM_ESINGULAR);
    assert_string_equal(err.param, "q");
    assert_true(info.rcond < 1e-13);
    mm_mech_work_free(w);
}

/* ---- the four-bar in body coordinates (9 x 9: LAPACK) ------------------------------ */

/* bodies 1 crank, 2 coupler, 3 rocker: (x_i, y_i, phi_i) of each link's start;
 * crank at O2, rocker at O4, pins at the ends; driver phi_1 = t */
static int bf_phi(const double *q, double t, double *F, void *pp)
{
    const fb *p = pp;
    F[0] = q[0], F[1] = q[1];                                         /* crank pinned at O2 */
    F[2] = q[0] + p->a * cos(q[2]) - q[3], F[3] = q[1] + p->a * sin(q[2]) - q[4];   /* pin B */
    F[4] = q[3] + p->b * cos(q[5]) - q[6] - p->c * cos(q[8]);         /* pin C */
    F[5] = q[4] + p->b * sin(q[5]) - q[7] - p->c * sin(q[8]);
    F[6] = q[6] - p->d, F[7] = q[7];                                  /* rocker pinned at O4 */
    F[8] = q[2] - t;                                                  /* driver */
    return 0;
}

static int bf_jac(const double *q, double t, double *J, void *pp)
{
    (void)t;
    const fb *p = pp;
    memset(J, 0, 81 * sizeof *J);
    J[0 * 9 + 0] = 1, J[1 * 9 + 1] = 1;
    J[2 * 9 + 0] = 1, J[2 * 9 + 2] = -p->a * sin(q[2]), J[2 * 9 + 3] = -1;
    J[3 * 9 + 1] = 1, J[3 * 9 + 2] = p->a * cos(q[2]), J[3 * 9 + 4] = -1;
    J[4 * 9 + 3] = 1, J[4 * 9 + 5] = -p->b * sin(q[5]), J[4 * 9 + 6] = -1, J[4 * 9 + 8] = p->c * sin(q[8]);
    J[5 * 9 + 4] = 1, J[5 * 9 + 5] = p->b * cos(q[5]), J[5 * 9 + 7] = -1, J[5 * 9 + 8] = -p->c * cos(q[8]);
    J[6 * 9 + 6] = 1, J[7 * 9 + 7] = 1, J[8 * 9 + 2] = 1;
    return 0;
}

static int bf_nu(const double *q, double t, double *nu, void *pp)
{
    (void)q, (void)t, (void)pp;
    memset(nu, 0, 9 * sizeof *nu);
    nu[8] = 1;
    return 0;
}

static int bf_gamma(const double *q, const double *qd, double t, double *g, void *pp)
{
    (void)t;
    const fb *p = pp;
    memset(g, 0, 9 * sizeof *g);
    g[2] = p->a * cos(q[2]) * qd[2] * qd[2], g[3] = p->a * sin(q[2]) * qd[2] * qd[2];
    g[4] = p->b * cos(q[5]) * qd[5] * qd[5] - p->c * cos(q[8]) * qd[8] * qd[8];
    g[5] = p->b * sin(q[5]) * qd[5] * qd[5] - p->c * sin(q[8]) * qd[8] * qd[8];
    return 0;
}

static void body_coordinates_through_lapack_should_agree_with_joint_angles(void **state)
{
    (void)state;
    fb p = {0.2, 0.5, 0.4, 0.6};
    static const unsigned char len[9] = {1, 1, 0, 1, 1, 0, 1, 1, 0};
    mm_mech_problem big = {.n = 9, .m = 9, .phi = bf_phi, .jac = bf_jac, .nu = bf_nu, .gamma = bf_gamma,
                           .is_length = len, .params = &p};
    mm_mech_problem small = fb_problem(&p);
    mm_mech_options opt;
    mm_mech_options_init(&opt);
    opt.length = 0.6;
    mm_mech_work *wb = mm_mech_work_alloc(9, 9), *ws = mm_mech_work_alloc(3, 3);
    double worst = 0;
    for (double t2 = 0; t2 < 6.28; t2 += 0.5) {
        double qs[3], qds[3], qdds[3];
        fb_assemble(&p, t2, 1, qs);
        assert_int_equal(mm_mech_position(&small, &opt, ws, t2, qs, NULL, NULL), MM_OK);
        assert_int_equal(mm_mech_velocity(&small, &opt, ws, t2, qs, qds, NULL, NULL), MM_OK);
        assert_int_equal(mm_mech_acceleration(&small, &opt, ws, t2, qs, qds, qdds, NULL, NULL), MM_OK);
        /* a guess off by a few degrees and millimetres */
        double q[9] = {0.001, -0.002, t2 + 0.03, p.a * cos(t2), p.a * sin(t2) + 0.01, qs[1] - 0.05, p.d, 0,
                       qs[2] + 0.04}, qd[9], qdd[9];
        mm_mech_info info;
        assert_int_equal(mm_mech_position(&big, &opt, wb, t2, q, &info, NULL), MM_OK);
        assert_int_equal(mm_mech_velocity(&big, &opt, wb, t2, q, qd, NULL, NULL), MM_OK);
        assert_int_equal(mm_mech_acceleration(&big, &opt, wb, t2, q, qd, qdd, NULL, NULL), MM_OK);
        worst = fmax(worst, fabs(remainder(q[8] - qs[2], 2 * M_PI)));
        worst = fmax(worst, fabs(qd[8] - qds[2]) / (1 + fabs(qds[2])));
        worst = fmax(worst, fabs(qdd[8] - qdds[2]) / (1 + fabs(qdds[2])));
        assert_true(info.rcond > 1e-3);
    }
    /* both at rounding, cond of the body system ~ 100 */
    check_abs(worst, 0, 1e-13, "rocker angle, velocity, acceleration: 9 body coordinates vs 3 angles");
    mm_mech_work_free(wb);
    mm_mech_work_free(ws);
}

/* ---- an overconstrained linkage: the double parallelogram ------------------------------ */

/* a parallelogram O2 B C O4 (a = c, b = d) with a third link of length a from
 * (e, 0) to the coupler point at e from B: q = (t2, t3, t4, t5) */
typedef struct dp {
    double a, b, e;
    int driven;
} dp;

static int dp_phi(const double *q, double t, double *F, void *pp)
{
    const dp *p = pp;
    F[0] = p->a * cos(q[0]) + p->b * cos(q[1]) - p->a * cos(q[2]) - p->b;
    F[1] = p->a * sin(q[0]) + p->b * sin(q[1]) - p->a * sin(q[2]);
    F[2] = p->a * cos(q[0]) + p->e * cos(q[1]) - p->a * cos(q[3]) - p->e;
    F[3] = p->a * sin(q[0]) + p->e * sin(q[1]) - p->a * sin(q[3]);
    if (p->driven)
        F[4] = q[0] - t;
    return 0;
}

static int dp_jac(const double *q, double t, double *J, void *pp)
{
    (void)t;
    const dp *p = pp;
    double a = p->a, b = p->b, e = p->e;
    double Jv[20] = {-a * sin(q[0]), -b * sin(q[1]), a * sin(q[2]), 0,
                     a * cos(q[0]), b * cos(q[1]), -a * cos(q[2]), 0,
                     -a * sin(q[0]), -e * sin(q[1]), 0, a * sin(q[3]),
                     a * cos(q[0]), e * cos(q[1]), 0, -a * cos(q[3]),
                     1, 0, 0, 0};
    memcpy(J, Jv, (size_t)(p->driven ? 20 : 16) * sizeof *J);
    return 0;
}

static int dp_nu(const double *q, double t, double *nu, void *pp)
{
    (void)q, (void)t, (void)pp;
    nu[0] = nu[1] = nu[2] = nu[3] = 0, nu[4] = 1;
    return 0;
}

static void an_overconstrained_double_parallelogram_should_move_with_mobility_one(void **state)
{
    (void)state;
    dp p = {0.3, 0.8, 0.35, 1};
    mm_mech_problem prob = {.n = 4, .m = 5, .phi = dp_phi, .jac = dp_jac, .nu = dp_nu, .params = &p};
    mm_mech_options opt;
    mm_mech_options_init(&opt);
    assert_int_equal(mm_mech_check(&prob, &opt, NULL), MM_OK);
    mm_mech_work *w = mm_mech_work_alloc(4, 5);
    double q[4] = {1.0, 0.03, 1.02, 0.97}, qd[4];
    mm_mech_info info;
    assert_int_equal(mm_mech_position(&prob, &opt, w, 1.0, q, &info, NULL), MM_OK);
    check_abs(q[1], 0, 1e-14, "the coupler stays level");
    check_abs(q[2] - 1, 0, 1e-14, "the rocker follows the crank");
    check_abs(q[3] - 1, 0, 1e-14, "and so does the third link");
    assert_int_equal(info.rank, 4);
    assert_int_equal(mm_mech_velocity(&prob, &opt, w, 1.0, q, qd, NULL, NULL), MM_OK);
    check_abs(qd[3], 1, 1e-13, "omega5 = omega2 (least squares of a consistent system)");
    /* without the driver: 4 equations in 4 unknowns, Grubler-Kutzbach says
     * 3 (5 - 1) - 2 * 6 = 0, but the rank is 3: mobility 1 */
    dp free = p;
    free.driven = 0;
    mm_mech_problem pf = {.n = 4, .m = 4, .phi = dp_phi, .jac = dp_jac, .params = &free};
    mm_mech_work *wf = mm_mech_work_alloc(4, 4);
    int rank;
    double sv[4];
    assert_int_equal(mm_mech_rank(&pf, wf, 0, q, 0, sv, &rank, NULL), MM_OK);
    assert_int_equal(rank, 3);
    assert_int_equal(4 - rank, 1);
    check_abs(sv[3], 0, 8 * EPS * sv[0], "the smallest singular value is rounding");
    mm_mech_work_free(w);
    mm_mech_work_free(wf);
}

static void bad_problems_should_be_refused(void **state)
{
    (void)state;
    fb p = {0.2, 0.5, 0.4, 0.6};
    mm_mech_problem prob = fb_problem(&p);
    mm_mech_options opt;
    mm_mech_options_init(&opt);
    mm_error err;
    prob.n = 0;
    assert_int_equal(mm_mech_check(&prob, &opt, &err), MM_ERANGE);
    assert_string_equal(err.param, "n");
    prob = fb_problem(&p);
    prob.m = 2;
    assert_int_equal(mm_mech_check(&prob, &opt, &err), MM_ERANGE);
    assert_null(mm_mech_work_alloc(3, 0));
    assert_null(mm_mech_work_alloc(MM_MECH_MAX_N + 1, MM_MECH_MAX_N + 1));
    mm_mech_work_free(NULL);
    /* a four-bar that cannot close anywhere: a > b + c + d */
    fb no = {2, 0.3, 0.3, 0.3};
    prob = fb_problem(&no);
    mm_mech_work *w = mm_mech_work_alloc(3, 3);
    double q[3] = {1, 0.5, 2};
    assert_int_equal(mm_mech_position(&prob, &opt, w, 1, q, NULL, &err), MM_ENOCONV);
    assert_string_equal(err.param, "q");
    mm_mech_work_free(w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(slider_crank_sweep_should_match_the_closed_form),
        cmocka_unit_test(a_sweep_should_not_jump_between_assemblies_that_pass_close),
        cmocka_unit_test(newton_should_converge_quadratically_with_an_honest_error_estimate),
        cmocka_unit_test(four_bar_should_match_freudenstein_and_differences_of_its_positions),
        cmocka_unit_test(a_non_grashof_four_bar_should_stop_at_its_toggle),
        cmocka_unit_test(a_parallelogram_should_stay_a_parallelogram_through_the_change_point),
        cmocka_unit_test(velocities_should_be_refused_exactly_at_a_toggle),
        cmocka_unit_test(body_coordinates_through_lapack_should_agree_with_joint_angles),
        cmocka_unit_test(an_overconstrained_double_parallelogram_should_move_with_mobility_one),
        cmocka_unit_test(bad_problems_should_be_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
