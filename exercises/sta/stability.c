/* stability.c — sta-stability: equilibria of a conservative system and
 * their stability from its potential energy: an upright rod hinged at its
 * foot, loaded by a weight W at its top and held by a horizontal spring k
 * at height a (the spring's far end slides in a vertical guide, so the
 * spring stays horizontal).
 *
 *     V(theta) = 1/2 k a^2 sin^2(theta) + W L cos(theta)              (1)
 *     V'(theta) = sin(theta) (k a^2 cos(theta) - W L) = 0             (2)
 *
 * Goal: equilibria where dV/dtheta = 0, stable where V'' > 0, unstable
 * where V'' < 0, neutral where V'' = 0 (then higher derivatives decide);
 * the critical load W_cr = k a^2 / L where the upright position loses its
 * stability (a bifurcation).
 * Method: the equilibria found numerically as the roots of V' (subdivide,
 * bracket, Brent), classified by V''.  Checks: the roots against the
 * closed forms 0, pi, +-acos(W L / (k a^2)) (within the final brackets);
 * V'' against a central difference of V' (with its truncation term); at
 * each equilibrium the rod's moment balance written with the forces as
 * vectors (a direct force balance, not the energy).
 * Reference: Hibbeler, Statics, 14th ed., sections 11.5-11.7; Meriam &
 * Kraige, Statics, articles 7/3-7/4.
 */
#include <float.h>
#include <math.h>

#include "mm_exhelp.h"
#include "mm_roots.h"
#include "mm_sta.h"

enum { P_L, P_W, P_K, P_A, P_POINTS };
static const mm_param params[] = {
    [P_L] = {"L", "rod length", "m", MM_REAL, 1, 1e-3, 100, .help = "from the hinge to the weight"},
    [P_W] = {"W", "weight at the top", "N", MM_REAL, 100, 0, 1e7, .help = "the load that tends to topple the rod"},
    [P_K] = {"k", "spring stiffness", "N/m", MM_REAL, 500, 0, 1e9, .help = "the horizontal spring"},
    [P_A] = {"a", "spring height", "m", MM_REAL, 0.5, 1e-3, 100, .help = "where the spring holds the rod"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 361, 37, 3601, .help = "samples of V over one turn"},
};

enum { O_WCR, O_RATIO, O_THEQ, O_NEQ, O_UP, O_EQ, O_V, O_STABLE, O_UNSTABLE, O_NEUTRAL, O_BRANCH, O_ANIM };
static const char *const eqcols[] = {"theta", "V", "d2V", "kind", NULL};
static const char *const equnits[] = {"rad", "J", "J", "", NULL};
static const mm_output outputs[] = {
    [O_WCR] = MM_SCALAR("W_cr", "critical load k a^2 / L", "N", .flags = MM_ANSWER | MM_EXACT),
    [O_RATIO] = MM_SCALAR("W_ratio", "W / W_cr", "", .flags = MM_EXACT),
    [O_THEQ] = MM_SCALAR("theta_eq", "tilted equilibrium acos(W / W_cr)", "rad", .flags = MM_ANSWER | MM_EXACT),
    [O_NEQ] = MM_SCALAR("n_equilibria", "equilibria in one turn", "", .flags = MM_EXACT),
    [O_UP] = MM_SCALAR("upright", "the upright position (1 stable, 0 neutral, -1 unstable)", "",
                       .flags = MM_ANSWER | MM_EXACT),
    [O_EQ] = MM_TABLE("equilibria", "equilibria and their stability", eqcols, equnits),
    [O_V] = MM_SERIES("V", "potential energy", "J", "theta", "rad", .figure = "V"),
    [O_STABLE] = MM_SERIES("stable", "stable equilibria", "J", "theta", "rad", .figure = "V", .mark = "dots"),
    [O_UNSTABLE] = MM_SERIES("unstable", "unstable equilibria", "J", "theta", "rad", .figure = "V", .mark = "dots"),
    [O_NEUTRAL] = MM_SERIES("neutral", "neutral to second order", "J", "theta", "rad", .figure = "V", .mark = "dots"),
    [O_BRANCH] = MM_SERIES("theta_of_W", "tilted equilibrium against the load W", "rad", "W", "N",
                           .figure = "bifurcation"),
    [O_ANIM] = MM_ANIMATION("the rod at a tilted equilibrium (or upright), spring, weight and hinge"),
};

typedef struct sys { double L, W, k, a; } sys;

/* V (eq. 1), V' (eq. 2), V'' (eq. 3) and V'''' */
static double V(const sys *s, double t) { return 0.5 * s->k * s->a * s->a * sin(t) * sin(t) + s->W * s->L * cos(t); }
static double dV(const sys *s, double t) { return sin(t) * (s->k * s->a * s->a * cos(t) - s->W * s->L); }
static double d2V(const sys *s, double t) { return s->k * s->a * s->a * cos(2 * t) - s->W * s->L * cos(t); }
static double d4V(const sys *s, double t) { return -4 * s->k * s->a * s->a * cos(2 * t) + s->W * s->L * cos(t); }

static int dV_fn(double t, double *f, void *p)
{
    *f = dV(p, t);
    return 0;
}

static int check(const mm_value *in, mm_error *err)
{
    if (in[P_K].x == 0 && in[P_W].x == 0)
        return mm_error_set(err, MM_ERANGE, "W", "with k = 0 and W = 0 there is no potential: every position "
                            "is an equilibrium; give W or k");
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    sys s = {in[P_L].x, in[P_W].x, in[P_K].x, in[P_A].x};
    double ka2 = s.k * s.a * s.a, WL = s.W * s.L, big = ka2 + WL;
    double Wcr = ka2 / s.L, c = ka2 > 0 ? WL / ka2 : INFINITY;
    mm_res_scalar(res, O_WCR, Wcr);
    if (Wcr > 0)
        mm_res_scalar(res, O_RATIO, s.W / Wcr);
    if (c < 1)
        mm_res_scalar(res, O_THEQ, acos(c));
    /* the equilibria: roots of V' over one turn, from -pi + 0.1 so that
     * theta = pi is inside (then folded into (-pi, pi]) */
    enum { NSUB = 720 };
    mm_roots_root roots[NSUB + 1];
    mm_roots_result rr;
    int rc = mm_roots_scan(dV_fn, &s, -M_PI + 0.1, M_PI + 0.1, NSUB, 1e-15, 200, roots, &rr, err);
    if (rc != MM_OK)
        return rc;
    int n = rr.nroots;
    double th[NSUB + 1], w[NSUB + 1], d2[NSUB + 1], v[NSUB + 1];
    int kind[NSUB + 1];
    static const char *const kinds[] = {"unstable", "neutral", "stable"};
    for (int i = 0; i < n; i++) {
        th[i] = roots[i].x > M_PI ? roots[i].x - 2 * M_PI : roots[i].x;
        /* the root lies within its final bracket; when Brent stopped on an
         * exact zero of the computed V', within the rounding of V' over V'' */
        w[i] = roots[i].fx != 0 ? roots[i].width : 4 * DBL_EPSILON * big / fmax(fabs(d2V(&s, roots[i].x)), 1e-300);
        /* a neutral (triple) root: cos(theta) - 1 rounds to 0 below sqrt(2 eps) */
        if (roots[i].fx == 0)
            w[i] = fmin(w[i], 4 * sqrt(DBL_EPSILON));
        d2[i] = d2V(&s, th[i]);
        /* neutral: V'' at rounding level of its terms; then V'''' decides */
        kind[i] = fabs(d2[i]) <= 1e-9 * big ? 1 : d2[i] > 0 ? 2 : 0;
        v[i] = V(&s, th[i]);
    }
    mm_res_scalar(res, O_NEQ, n);
    mm_table *t = mm_res_table(res, O_EQ, n);
    if (!t)
        return MM_ENOMEM;
    int up = 0, ns[3] = {0, 0, 0};
    for (int i = 0; i < n; i++) {
        t->cell[4 * i] = th[i], t->cell[4 * i + 1] = v[i], t->cell[4 * i + 2] = d2[i];
        const char *txt = kinds[kind[i]];
        if (kind[i] == 1)
            txt = d4V(&s, th[i]) > 0 ? "neutral (V'' = 0); stable by V''''" : "neutral (V'' = 0); unstable by V''''";
        t->text[4 * i + 3] = txt;
        if (fabs(th[i]) < 1e-6)
            up = kind[i] - 1;
        ns[kind[i]]++;
    }
    mm_res_scalar_text(res, O_UP, up, up > 0 ? "stable" : up < 0 ? "unstable" : "neutral");
    /* check 1: the roots against the closed forms 0, pi, +-acos(c) */
    double cf[4] = {0, M_PI, acos(c), -acos(c)};
    int ncf = c < 1 && acos(c) > 0 ? 4 : 2;             /* the tilted pair only below W_cr */
    double worst = 0, wtol = 0;
    for (int j = 0; j < ncf; j++) {
        int best = -1;                                   /* the root found nearest to cf[j] */
        double d = INFINITY;
        for (int i = 0; i < n; i++)
            if (fabs(remainder(th[i] - cf[j], 2 * M_PI)) < d)
                d = fabs(remainder(th[i] - cf[j], 2 * M_PI)), best = i;
        double tol = best >= 0 ? w[best] + 8 * DBL_EPSILON * M_PI : 0;   /* and the rounding of the closed form */
        if (d / (tol + 1e-300) >= worst / (wtol + 1e-300))
            worst = d, wtol = tol;
    }
    mm_res_check_abs(res, "equilibria: the roots of V' found vs 0, pi, +-acos(W L / k a^2): worst distance "
                          "(tolerance: its bracket or rounding) [rad]", worst, 0, wtol);
    mm_res_check_abs(res, "equilibria: as many found as the closed forms give", n, ncf, 0);
    /* check 2: V'' against a central difference of V': the difference is
     * V'' + h^2 V''''/6 + h^4 V^(6)/120 + ..., so with the h^2 term taken off
     * what is left is below h^4 (16 k a^2 + W L)/120 and the rounding */
    double h = 1e-4, wr = 0;
    for (int i = 0; i < n; i++) {
        double fd = (dV(&s, th[i] + h) - dV(&s, th[i] - h)) / (2 * h) - h * h * d4V(&s, th[i]) / 6;
        double tol = pow(h, 4) * (16 * s.k * s.a * s.a + s.W * s.L) / 120 + 8 * DBL_EPSILON * big / h;
        wr = fmax(wr, fabs(fd - d2[i]) / tol);
    }
    mm_res_check_abs(res, "V'' analytic vs a central difference of V' (less its h^2 V''''/6): worst difference / "
                          "(h^4 term + rounding)", wr, 0, 1);
    /* check 3: the rod's moment balance about the hinge, forces as vectors */
    double wm = 0;
    for (int i = 0; i < n; i++) {
        double rs[2] = {s.a * sin(th[i]), s.a * cos(th[i])}, rt[2] = {s.L * sin(th[i]), s.L * cos(th[i])};
        double Fs[2] = {-s.k * rs[0], 0}, Fw[2] = {0, -s.W};         /* spring pulls back, weight down */
        double M = rs[0] * Fs[1] - rs[1] * Fs[0] + rt[0] * Fw[1] - rt[1] * Fw[0];
        wm = fmax(wm, fabs(M));
    }
    mm_check_residual(res, "force balance: moment about the hinge at every equilibrium [N m]", wm, big, 16);
    mm_res_method(res, "roots of dV/dtheta (subdivide, bracket, Brent), classified by d2V/dtheta2", 0);
    mm_res_method_stat(res, "evaluations", (double)rr.nevals);
    /* the curves */
    int np = (int)in[P_POINTS].x;
    mm_series *sv = mm_res_series(res, O_V, np);
    if (!sv)
        return MM_ENOMEM;
    mm_linspace(-M_PI, M_PI, np, sv->x);
    for (int i = 0; i < np; i++)
        sv->y[i] = V(&s, sv->x[i]);
    static const int outs[3] = {O_UNSTABLE, O_NEUTRAL, O_STABLE};
    if (mm_sta_equilibria(res, n, th, v, kind, 3, outs) != MM_OK)
        return MM_ENOMEM;
    if (Wcr > 0) {
        mm_series *b = mm_res_series(res, O_BRANCH, 101);
        if (!b)
            return MM_ENOMEM;
        mm_linspace(0, Wcr, 101, b->x);
        for (int i = 0; i <= 100; i++)
            b->y[i] = acos(fmin(1, b->x[i] / Wcr));
    }
    if (ns[1])
        mm_res_warn(res, "W = W_cr: the upright position is neutral to second order; the fourth derivative "
                         "V'''' = -3 k a^2 < 0 makes it unstable");

    /* the drawing at the tilted equilibrium, or upright */
    double q = c < 1 ? acos(c) : 0;
    mm_sta_fbd(res);
    mm_sta_rod_spring(res, s.L, s.a, s.k, s.W, q,
                      q != 0 ? "unstable" : up > 0 ? "stable" : up < 0 ? "unstable" : "neutral");
    return rc;
}

static const char *const references[] = {MM_STA_HIBBELER "sections 11.5-11.7", MM_STA_MERIAM "articles 7/3-7/4", NULL};

const mm_exercise mm_ex_sta_stability = {
    .id = "sta-stability", .chapter = 3, .section = "3.11",
    .title = "Stability of equilibrium from the potential energy",
    .summary = "An upright rod held by a spring: equilibria where dV/dtheta = 0, stable or unstable by the "
               "second derivative, and the critical load where the upright position buckles.",
    .tags = "statics, potential energy, stability, equilibrium, buckling, bifurcation",
    .theory = "exercises/sta/stability.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
