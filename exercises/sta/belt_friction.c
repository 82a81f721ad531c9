/* belt_friction.c — sta-belt-friction: a belt or rope wrapped round a
 * drum on the verge of slipping, the capstan equation
 *
 *     T2 = T1 e^(mu theta / sin beta)                                   (3)
 *
 * (beta the half-angle of a V-groove; pi/2, the default, is a flat belt).
 * Goal: the exponential growth of the holding power with the wrap angle,
 * both slipping limits (T2 above T1 e^(mu theta) and below T1 e^(-mu theta)),
 * and the torque the belt passes to the drum.
 * Checks: a belt over n sharp pegs, each in equilibrium with Coulomb
 * friction at the limit (eq. 5), converges to (3) at order 2 (observed over
 * six halvings from where its d^4 term is small) and, with its Richardson
 * error estimate, meets (3); the torque on the drum equals the friction moment integrated along the
 * contact (eq. 6, Gauss-Legendre).
 * Reference: Hibbeler, Statics, 14th ed., section 8.5; Meriam & Kraige,
 * Statics, section 6/9.
 */
#include <float.h>
#include <math.h>

#include "mm_exhelp.h"
#include "mm_order.h"
#include "mm_quad.h"
#include "mm_sta.h"

enum { P_T1, P_MU, P_THETA, P_R, P_BETA, P_POINTS };
static const mm_param params[] = {
    [P_T1] = {"T1", "tension on the slack side", "N", MM_REAL, 100, 1e-3, 1e7,
              .help = "the smaller tension, where the belt leaves the drum on the side it is pulled from"},
    [P_MU] = {"mu", "coefficient of friction", "", MM_REAL, 0.3, 0, 1.5,
              .help = "belt on drum (static, at the limit); 1.5 is already rubber on rough steel"},
    [P_THETA] = {"theta", "angle of wrap", "rad", MM_REAL, M_PI, 0, 10 * M_PI,
                 .help = "contact angle; pi is half a turn, up to 5 turns (a capstan or a bollard)"},
    [P_R] = {"r", "drum radius", "m", MM_REAL, 0.1, 1e-3, 10, .help = "for the torque (T2 - T1) r"},
    [P_BETA] = {"beta", "groove half-angle", "rad", MM_REAL, M_PI / 2, 0.1, M_PI / 2,
                .help = "half the angle of a V-groove; pi/2 is a flat belt, 0.35 (20 deg) a V-belt"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 201, 11, 2001,
                  .help = "samples of the tension along the contact"},
};

enum { O_T2, O_T2MIN, O_RATIO, O_TORQUE, O_MUEFF, O_T, O_ANIM };
static const mm_output outputs[] = {
    [O_T2] = MM_SCALAR("T2", "tight-side tension at the slip limit", "N", .flags = MM_ANSWER | MM_EXACT),
    [O_T2MIN] = MM_SCALAR("T2_min", "smallest tight-side tension before slipping the other way", "N",
                          .flags = MM_ANSWER | MM_EXACT),
    [O_RATIO] = MM_SCALAR("ratio", "T2 / T1 = e^(mu theta / sin beta)", "", .flags = MM_EXACT),
    [O_TORQUE] = MM_SCALAR("torque", "torque on the drum (T2 - T1) r", "N m", .flags = MM_ANSWER | MM_EXACT),
    [O_MUEFF] = MM_SCALAR("mu_eff", "effective coefficient mu / sin beta", "", .flags = MM_EXACT),
    [O_T] = MM_SERIES("T", "tension along the contact", "N", "angle from the slack side", "rad"),
    [O_ANIM] = MM_ANIMATION("the drum with the belt, its two tensions and the torque"),
};

/* e^50 = 5e21: beyond it the belt holds any load no belt could carry */
static int check(const mm_value *in, mm_error *err)
{
    double a = in[P_MU].x * in[P_THETA].x / sin(in[P_BETA].x);
    if (a > 50)
        return mm_error_set(err, MM_ERANGE, "mu", "mu theta / sin(beta) = %.3g would make T2/T1 = e^%.3g; keep "
                            "it at most 50 (a ratio of 5e21): lower mu or theta", a, a);
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    (void)err;
    double T1 = in[P_T1].x, mu = in[P_MU].x, theta = in[P_THETA].x, r = in[P_R].x, beta = in[P_BETA].x;
    int n = (int)in[P_POINTS].x;
    double mue = mu / sin(beta), ratio = exp(mue * theta), T2 = T1 * ratio;   /* eq. (3) */
    mm_res_scalar(res, O_T2, T2);
    mm_res_scalar(res, O_T2MIN, T1 / ratio);                                  /* eq. (4) */
    mm_res_scalar(res, O_RATIO, ratio);
    mm_res_scalar(res, O_TORQUE, (T2 - T1) * r);
    mm_res_scalar(res, O_MUEFF, mue);
    mm_series *s = mm_res_series(res, O_T, n);
    if (!s)
        return MM_ENOMEM;
    mm_linspace(0, theta, n, s->x);
    for (int i = 0; i < n; i++)
        s->y[i] = T1 * exp(mue * s->x[i]);                                    /* eq. (2) */
    /* check 1: the peg belt converges to (3) at order 2.  With d = theta / n
     * and s = mu_e sin(d/2), log(T_n / T2) = n 2 atanh(s) - mu_e theta =
     * c1 d^2 + c2 d^4 + ..., c1 = theta (mu_e^3/12 - mu_e/24) and c2 = theta
     * (mu_e/1920 - mu_e^3/96 + mu_e^5/80), so T_n - T2 = T2 c1 d^2 (1 + B d^2
     * + ...) with B = (c2 + c1^2/2) / c1.  The order 2 is seen only while
     * |B| d^2 is small: mu_e d small is not enough (a small mu_e on a long
     * wrap gave d = 3 rad a peg, |B| d^2 = 0.5 and an order of 1.90).  The
     * coarsest level is taken where |B| d0^2 <= 0.02, B bounded without its
     * cancellations (|c2| summed term by term, |c1| at least its value where
     * the check is made) */
    enum { K = 6 };
    double mt = mue * theta, c1 = fabs(mue * mue * mue / 12 - mue / 24) * theta, c1min = 0.05 * mue * theta / 24;
    double c2 = (mue / 1920 + mue * mue * mue / 96 + pow(mue, 5) / 80) * theta;
    double B = (c2 + 0.5 * c1 * c1) / fmax(c1, c1min);
    int n0 = (int)fmax(fmax(8, ceil(5 * mt)), ceil(theta * sqrt(B / 0.02)));
    /* The belt over np sharp pegs spread evenly over theta: at each, it
     * turns by d = theta / np, the peg pushes with N = (T_in + T_out) sin(d/2)
     * and friction mu_e N makes up the difference (eq. 5), so each peg
     * multiplies the tension by (1 + s) / (1 - s) = e^(2 atanh s), s =
     * mu_e sin(d/2).  Through atanh the product of np factors rounds like one
     * exponential, (6 mu_e theta + 4) eps relative at most, where pow((1 + s)
     * / (1 - s), np) rounded at np eps. */
    double h[K], e[K], Tn[K];
    for (int k = 0; k < K; k++) {
        int np = n0 << k;
        Tn[k] = T1 * exp(2.0 * np * atanh(mue * sin(theta / (2.0 * np))));
        h[k] = theta / np;
        e[k] = fabs(Tn[k] - T2);
    }
    /* rounding of T_n and T2 together: (6.5 mt + 6) eps T2 < 8 (1 + mt) eps T2 */
    double rnd = 8 * (1 + mt) * DBL_EPSILON * T2;
    /* the order is measured only where c1 is not near its zero at mu_e^2 =
     * 1/2 (where the order is 4) and the finest error is 1e4 roundings; the
     * tolerance is twice the slope's drift from the d^4 term (measured over
     * 2e5 draws: at most 0.9993 of it) plus what rounding can move the slope */
    if (c1 > c1min && e[K - 1] > 1e4 * rnd)
        mm_check_order(res, "n-peg belt -> T1 e^(mu theta / sin beta): observed order (tolerance: 2 x the "
                            "drift of its d^4 term)", K, h, e, 2,
                       2 * (mm_order_drift_h2(B * h[0] * h[0], K) + mm_order_rounding_drift(K, h, e, rnd)));
    /* check 2: the finest peg belt meets (3) within its Richardson estimate */
    double est = fabs(Tn[K - 1] - Tn[K - 2]) / 3;    /* plus rounding: once in T_n and T2, once more in est */
    mm_sta_check_absf(res, Tn[K - 1], T2, 1.5 * est + 2 * rnd, "%d-peg belt vs T1 e^(mu theta / sin beta) [N] "
                      "(tolerance: 1.5 x its Richardson error estimate)", n0 << (K - 1));
    /* check 3: the drum's moment balance: (T2 - T1) r against the friction
     * moment integral of mu_e T(phi) r dphi (eq. 6), 5-point Gauss-Legendre
     * on pieces where mu_e phi grows by at most 1/2 (relative error < 1e-15) */
    int pieces = (int)fmax(8, ceil(2 * mue * theta));       /* at most 101: mu_e theta <= 50 (check) */
    double gp[5 * 101], gw[5 * 101], Mf = 0;
    mm_quad_gl5_nodes(0, theta, pieces, gp, gw);
    for (int i = 0; i < 5 * pieces; i++)
        Mf += gw[i] * mue * T1 * exp(mue * gp[i]) * r;
    mm_res_check_abs(res, "drum: (T2 - T1) r vs the integral of the friction moment [N m]", Mf, (T2 - T1) * r,
                     64 * DBL_EPSILON * T2 * r);
    mm_res_method(res, "closed form (capstan equation); peg belt and quadrature as checks", 0);
    if (theta > 2 * M_PI)
        mm_res_warn(res, "theta = %.3g rad is %.2f turns: the drawing shows one", theta, theta / (2 * M_PI));
    mm_sta_fbd(res);
    return mm_sta_belt(res, T1, T2, theta, r, (T2 - T1) * r);
}

static const char *const references[] = {MM_STA_HIBBELER "section 8.5", MM_STA_MERIAM "article 6/9", NULL};

const mm_exercise mm_ex_sta_belt_friction = {
    .id = "sta-belt-friction", .chapter = 3, .section = "3.8.4",
    .title = "Belt friction: the capstan equation",
    .summary = "A belt on a drum at the verge of slipping: T2 = T1 e^(mu theta), both slip limits and the "
               "torque, checked by a belt over many pegs.",
    .tags = "statics, friction, belt, capstan, slipping", .theory = "exercises/sta/belt_friction.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
