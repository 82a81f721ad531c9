/* four_bar.c — kin-four-bar: the crank O2B (a) turns at constant omega2,
 * the coupler BC (b) joins it to the rocker O4C (c); the ground O2O4 is d.
 *
 *     a cos th2 + b cos th3 - c cos th4 - d = 0
 *     a sin th2 + b sin th3 - c sin th4     = 0                              (1)
 *
 * Goal: the angles, angular velocities and accelerations of coupler and
 * rocker; Grashof's condition and the class it gives; the transmission
 * angle over the cycle (its extremes and where); the coupler curve of a
 * point P; the rocker's dead centres; toggles of a crank that cannot turn
 * round, and the change point of s + l = p + q where the two assemblies
 * cross.  Method: eq. (1) by Newton-Raphson (mm_mech) from frame to frame
 * (the assembly kept), velocities and accelerations by linear solves with
 * its Jacobian.  Checks: Freudenstein's equation (closed form of the
 * angles), the velocity and acceleration closed forms, central differences
 * of the positions, the toggles and dead centres of the closed form
 * against those the sweep located, the transmission angle by the law of
 * cosines.
 * Reference: R. L. Norton, Design of Machinery, 5th ed., sections 2.12
 * (Grashof), 4.5-4.10 (positions, Freudenstein), 6.7, 7.3; F. Freudenstein,
 * Trans. ASME 77 (1955) 853-861.
 * API.md: O2 = (0, 0), O4 = (d, 0); "open" puts C left of the directed line
 * from B to O4, "crossed" right of it.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "mm_geom.h"
#include "mm_kin.h"
#include "mm_mech.h"

enum { P_A, P_B, P_C, P_D, P_OMEGA2, P_THETA2, P_BRANCH, P_PX, P_PY, P_POINTS };

static const char *const branches[] = {"open", "crossed", NULL};

static const mm_param params[] = {
    [P_A] = {"a", "crank O2B", "m", MM_REAL, 0.2, 0.01, 10, .help = "the driven link, pivoted at O2 = (0, 0)"},
    [P_B] = {"b", "coupler BC", "m", MM_REAL, 0.5, 0.01, 10, .help = "the floating link"},
    [P_C] = {"c", "rocker O4C", "m", MM_REAL, 0.4, 0.01, 10, .help = "the output link, pivoted at O4 = (d, 0)"},
    [P_D] = {"d", "ground O2O4", "m", MM_REAL, 0.6, 0.01, 10, .help = "distance between the fixed pivots"},
    [P_OMEGA2] = {"omega2", "crank speed", "rad/s", MM_REAL, 10, -1e4, 1e4,
                  .help = "constant angular velocity of the crank, counter-clockwise positive"},
    [P_THETA2] = {"theta2", "crank angle", "rad", MM_REAL, 1, -100, 100,
                  .help = "the crank's angle from O2O4 at the instant asked"},
    [P_BRANCH] = {"branch", "assembly", "", MM_CHOICE, 0, 0, 1, .choices = branches,
                  .help = "open: C left of the line from B to O4; crossed: right of it"},
    [P_PX] = {"px", "coupler point along BC", "m", MM_REAL, 0.25, -10, 10,
              .help = "P's coordinate from B along BC: its path is the coupler curve"},
    [P_PY] = {"py", "coupler point across BC", "m", MM_REAL, 0.15, -10, 10,
              .help = "P's coordinate across BC, to its left"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 121, 13, 721,
                  .help = "crank angles of the plots over the turn (or over the range the crank can reach)"},
};

enum {
    O_TH3, O_TH4, O_OM3, O_OM4, O_AL3, O_AL4, O_GRASHOF, O_MU, O_MU_MIN, O_MU_MAX, O_TH_MUMIN, O_TH_MUMAX,
    O_SWING, O_TOG1, O_TOG2, O_VP, O_AP,
    O_S3, O_S4, O_SW3, O_SW4, O_SA3, O_SA4, O_SMU, O_SCOUP, O_FDV, O_FDA, O_ANIM
};

static const mm_output outputs[] = {
    [O_TH3] = MM_SCALAR("theta3", "coupler angle", "rad", .flags = MM_ANSWER | MM_EXACT),
    [O_TH4] = MM_SCALAR("theta4", "rocker angle", "rad", .flags = MM_ANSWER | MM_EXACT),
    [O_OM3] = MM_SCALAR("omega3", "coupler angular velocity", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_OM4] = MM_SCALAR("omega4", "rocker angular velocity", "rad/s", .flags = MM_ANSWER | MM_EXACT),
    [O_AL3] = MM_SCALAR("alpha3", "coupler angular acceleration", "rad/s^2", .flags = MM_ANSWER | MM_EXACT),
    [O_AL4] = MM_SCALAR("alpha4", "rocker angular acceleration", "rad/s^2", .flags = MM_ANSWER | MM_EXACT),
    [O_GRASHOF] = MM_SCALAR("grashof", "Grashof: s + l <= p + q (1) or not (0)", "", .flags = MM_ANSWER | MM_EXACT),
    [O_MU] = MM_SCALAR("mu", "transmission angle at theta2 (between coupler and rocker)", "rad",
                       .flags = MM_ANSWER | MM_EXACT),
    [O_MU_MIN] = MM_SCALAR("mu_min", "smallest transmission angle over the cycle", "rad", .flags = MM_ANSWER | MM_EXACT),
    [O_MU_MAX] = MM_SCALAR("mu_max", "largest transmission angle over the cycle", "rad", .flags = MM_ANSWER | MM_EXACT),
    [O_TH_MUMIN] = MM_SCALAR("theta2_mu_min", "crank angle of the smallest transmission angle", "rad", .flags = MM_EXACT),
    [O_TH_MUMAX] = MM_SCALAR("theta2_mu_max", "crank angle of the largest transmission angle", "rad", .flags = MM_EXACT),
    [O_SWING] = MM_SCALAR("rocker_swing", "the rocker's swing between its dead centres", "rad", .flags = MM_EXACT),
    [O_TOG1] = MM_SCALAR("theta2_toggle1", "crank angle of the first toggle (coupler and rocker in line)", "rad",
                         .flags = MM_EXACT),
    [O_TOG2] = MM_SCALAR("theta2_toggle2", "crank angle of the second toggle", "rad", .flags = MM_EXACT),
    [O_VP] = MM_SCALAR("v_P", "speed of the coupler point", "m/s", .flags = MM_EXACT),
    [O_AP] = MM_SCALAR("a_P", "acceleration of the coupler point", "m/s^2", .flags = MM_EXACT),
    [O_S3] = MM_SERIES("theta3", "coupler angle", "rad", "crank angle", "rad", .figure = "angles"),
    [O_S4] = MM_SERIES("theta4", "rocker angle", "rad", "crank angle", "rad", .figure = "angles"),
    [O_SW3] = MM_SERIES("omega3", "coupler angular velocity", "rad/s", "crank angle", "rad", .figure = "angular velocities"),
    [O_SW4] = MM_SERIES("omega4", "rocker angular velocity", "rad/s", "crank angle", "rad", .figure = "angular velocities"),
    [O_SA3] = MM_SERIES("alpha3", "coupler angular acceleration", "rad/s^2", "crank angle", "rad",
                        .figure = "angular accelerations"),
    [O_SA4] = MM_SERIES("alpha4", "rocker angular acceleration", "rad/s^2", "crank angle", "rad",
                        .figure = "angular accelerations"),
    [O_SMU] = MM_SERIES("mu", "transmission angle", "rad", "crank angle", "rad", .figure = "transmission angle"),
    [O_SCOUP] = MM_SERIES("coupler_curve", "path of the coupler point P", "m", "x", "m", .aspect = "equal",
                          .figure = "coupler curve"),
    [O_FDV] = MM_SERIES("fd_error_v", "worst error of the central difference of theta3, theta4 vs d/dtheta2", "rad",
                        "step h", "rad", .x_scale = "log", .y_scale = "log", .mark = "dots", .figure = "difference error"),
    [O_FDA] = MM_SERIES("fd_error_a", "worst error of the second difference vs d2/dtheta2^2", "rad", "step h", "rad",
                        .x_scale = "log", .y_scale = "log", .mark = "dots", .figure = "difference error"),
    [O_ANIM] = MM_ANIMATION("crank, coupler and rocker over the cycle, the coupler curve, the velocity and "
                            "acceleration of P"),
};

typedef struct fb {
    double a, b, c, d;
} fb;

/* ---- closed forms ------------------------------------------------------------------------- */

/* |O4 B|^2 - (b -+ c)^2 through products; the crank can be at th2 when
 * (b - c)^2 <= |O4 B|^2 <= (b + c)^2 */
static double fb_disc(const fb *m, double th2)
{
    double e = hypot(m->d - m->a * cos(th2), m->a * sin(th2));
    return (m->b + m->c - e) * (e - fabs(m->b - m->c));
}

/* Freudenstein: K1 cos th4 - K2 cos th2 + K3 = cos(th2 - th4), solved by the
 * half-angle substitution t = tan(th4/2): A t^2 + B t + C = 0, eq. (2),
 * in the stable form t = Q/A or C/Q with Q = -(B + sign(B) sqrt(B^2 - 4AC))/2
 * (A = 0 when a + c = b + d... e.g. a rhombus: then one root is th4 = pi);
 * the root that puts C left (side = +1) or right (-1) of B -> O4; then th3
 * from the loop, eq. (3).  *err (may be NULL) receives a first-order bound
 * of the rounding of th3 and th4: the coefficients' and the square root's,
 * carried through th4 = 2 atan2(y, x). */
static void freudenstein(const fb *m, double th2, int side, double *th3, double *th4, double *err)
{
    double a = m->a, b = m->b, c = m->c, d = m->d, c2 = cos(th2), s2 = sin(th2);
    double K1 = d / a, K2 = d / c, K3 = (a * a - b * b + c * c + d * d) / (2 * a * c);
    double A = c2 - K1 - K2 * c2 + K3, B = -2 * s2, C = K1 - (K2 + 1) * c2 + K3;
    double disc = B * B - 4 * A * C, big = B * B + 4 * fabs(A * C);
    double r = disc > 8 * DBL_EPSILON * big ? sqrt(disc) : 0;      /* a double root within rounding */
    double Q = -0.5 * (B + copysign(r, B));
    /* the two roots as (y, x) with t = y / x; a double root at B = r = 0 */
    double ys[2] = {Q, C}, xs[2] = {A, Q};
    if (Q == 0)
        ys[1] = -B, xs[1] = 2 * A;
    double Bx = a * c2, By = a * s2, best = -INFINITY, y = 0, x = 1;
    int kb = 0;
    for (int k = 0; k < 2; k++) {
        if (ys[k] == 0 && xs[k] == 0)
            continue;
        double t4 = 2 * atan2(ys[k], xs[k]);
        double Cx = d + c * cos(t4), Cy = c * sin(t4);
        double side_k = side * ((d - Bx) * (Cy - By) + By * (Cx - Bx));   /* cross(O4 - B, C - B) */
        if (side_k > best)
            best = side_k, *th4 = t4, y = ys[k], x = xs[k], kb = k;
    }
    double Cx = d + c * cos(*th4), Cy = c * sin(*th4);
    *th3 = mm_kin_wrap(atan2(Cy - By, Cx - Bx));
    *th4 = mm_kin_wrap(*th4);
    if (err) {
        double MA = fabs(c2) + fabs(K1) + fabs(K2 * c2) + fabs(K3), MC = fabs(K1) + fabs((K2 + 1) * c2) + fabs(K3);
        double dB = 2 * DBL_EPSILON * fabs(B), dA = 4 * DBL_EPSILON * MA, dC = 4 * DBL_EPSILON * MC;
        double ddisc = 4 * DBL_EPSILON * big + 2 * fabs(B) * dB + 4 * (fabs(A) * dC + fabs(C) * dA);
        double dr = r > 0 ? ddisc / (2 * r) : sqrt(ddisc);
        double dQ = 0.5 * (dB + dr) + DBL_EPSILON * fabs(Q);
        double dy = kb == 0 ? dQ : dC, dx = kb == 0 ? dA : dQ;
        if (Q == 0 && kb == 1)
            dy = dB + dr, dx = 2 * dA;
        double e4 = 2 * (fabs(x) * dy + fabs(y) * dx) / (x * x + y * y) + 4 * DBL_EPSILON;
        *err = e4 * fmax(1, c / b) + 4 * DBL_EPSILON;                 /* th3 moves with C */
    }
}

/* velocities and accelerations per unit crank rate (omega2 = 1), eqs. (4)-(5) */
static void fb_rates(const fb *m, double th2, double th3, double th4, double *w3, double *w4, double *a3, double *a4)
{
    *w3 = m->a * sin(th4 - th2) / (m->b * sin(th3 - th4));
    *w4 = m->a * sin(th2 - th3) / (m->c * sin(th4 - th3));
    double A = m->c * sin(th4), B = m->b * sin(th3), D = m->c * cos(th4), E = m->b * cos(th3);
    double C = m->a * cos(th2) + m->b * *w3 * *w3 * cos(th3) - m->c * *w4 * *w4 * cos(th4);
    double F = -m->a * sin(th2) - m->b * *w3 * *w3 * sin(th3) + m->c * *w4 * *w4 * sin(th4);
    *a3 = (C * D - A * F) / (A * E - B * D);
    *a4 = (C * E - B * F) / (A * E - B * D);
}

/* ---- eq. (1) for mm_mech: q = (th3, th4), t = th2 ---------------------------------------------- */

static int phi_fn(const double *q, double t, double *F, void *ctx)
{
    const fb *m = ctx;
    F[0] = m->a * cos(t) + m->b * cos(q[0]) - m->c * cos(q[1]) - m->d;
    F[1] = m->a * sin(t) + m->b * sin(q[0]) - m->c * sin(q[1]);
    return 0;
}

static int jac_fn(const double *q, double t, double *J, void *ctx)
{
    (void)t;
    const fb *m = ctx;
    J[0] = -m->b * sin(q[0]), J[1] = m->c * sin(q[1]);
    J[2] = m->b * cos(q[0]), J[3] = -m->c * cos(q[1]);
    return 0;
}

static int nu_fn(const double *q, double t, double *nu, void *ctx)
{
    (void)q;
    const fb *m = ctx;
    nu[0] = m->a * sin(t), nu[1] = -m->a * cos(t);
    return 0;
}

static int gamma_fn(const double *q, const double *qd, double t, double *g, void *ctx)
{
    const fb *m = ctx;
    double w3 = qd[0] * qd[0], w4 = qd[1] * qd[1];
    g[0] = m->a * cos(t) + m->b * cos(q[0]) * w3 - m->c * cos(q[1]) * w4;
    g[1] = m->a * sin(t) + m->b * sin(q[0]) * w3 - m->c * sin(q[1]) * w4;
    return 0;
}

/* ---- Grashof and the reachable crank angles -------------------------------------------------- */

typedef struct fb_class {
    int grashof;         /* s + l <= p + q (equality within 4 ulps of the sum) */
    int change_point;    /* s + l = p + q */
    int full;            /* the crank turns round */
    int shortest;        /* 0 a, 1 b, 2 c, 3 d */
    double lo, hi;       /* else: the arc holding theta2, between toggles, */
    double gap[2];       /* and the widths of the unreachable arcs below lo and above hi */
    const char *name;
} fb_class;

static fb_class classify(const fb *m, double th2)
{
    fb_class k = {0};
    double L[4] = {m->a, m->b, m->c, m->d}, s = L[0], l = L[0], sum = 0;
    int is = 0;
    for (int i = 0; i < 4; i++) {
        sum += L[i];
        if (L[i] < s)
            s = L[i], is = i;
        l = fmax(l, L[i]);
    }
    double excess = s + l - (sum - s - l), tol = 4 * DBL_EPSILON * sum;
    k.change_point = fabs(excess) <= tol;
    k.shortest = is;
    k.grashof = excess <= tol;
    static const char *const grashof_names[4] = {"crank-rocker", "double rocker (Grashof)", "rocker-crank",
                                                 "double crank (drag link)"};
    k.name = k.change_point ? "change point" : k.grashof ? grashof_names[is] : "triple rocker (non-Grashof)";
    /* the crank turns round when |O4 B| stays within [|b - c|, b + c] */
    double g1 = fabs(m->d - m->a) - fabs(m->b - m->c), g2 = m->b + m->c - m->d - m->a;
    g1 = fabs(g1) <= tol ? 0 : g1, g2 = fabs(g2) <= tol ? 0 : g2;
    k.full = g1 >= 0 && g2 >= 0;
    if (k.full)
        return k;
    double uhi = (m->a * m->a + m->d * m->d - (m->b - m->c) * (m->b - m->c)) / (2 * m->a * m->d);
    double ulo = (m->a * m->a + m->d * m->d - (m->b + m->c) * (m->b + m->c)) / (2 * m->a * m->d);
    double Ahi = uhi < 1 ? acos(uhi) : 0, Alo = ulo > -1 ? acos(ulo) : M_PI;   /* reach: Ahi <= |th2| <= Alo */
    double w = mm_kin_wrap(th2);
    if (uhi < 1 && ulo > -1) {             /* two arcs: [Ahi, Alo] and [-Alo, -Ahi] */
        k.lo = w >= 0 ? Ahi : -Alo, k.hi = w >= 0 ? Alo : -Ahi;
        k.gap[0] = w >= 0 ? 2 * Ahi : 2 * M_PI - 2 * Alo, k.gap[1] = w >= 0 ? 2 * M_PI - 2 * Alo : 2 * Ahi;
    } else if (ulo > -1) {                 /* one arc about 0 */
        k.lo = -Alo, k.hi = Alo;
        k.gap[0] = k.gap[1] = 2 * M_PI - 2 * Alo;
    } else {                               /* one arc about pi */
        k.lo = Ahi, k.hi = 2 * M_PI - Ahi;
        k.gap[0] = k.gap[1] = 2 * Ahi;
        if (w < 0)
            w += 2 * M_PI;
    }
    k.lo += th2 - w, k.hi += th2 - w;      /* the arc next to the angle asked */
    return k;
}

static int check(const mm_value *in, mm_error *err)
{
    fb m = {in[P_A].x, in[P_B].x, in[P_C].x, in[P_D].x};
    const char *names[4] = {"a", "b", "c", "d"};
    double L[4] = {m.a, m.b, m.c, m.d}, sum = m.a + m.b + m.c + m.d;
    for (int i = 0; i < 4; i++)
        if (L[i] > sum - L[i])
            return mm_error_set(err, MM_ERANGE, names[i],
                                "the four links cannot close: %s = %g m is longer than the other three together "
                                "(%g m)", names[i], L[i], sum - L[i]);
    double th2 = in[P_THETA2].x, tiny = 8 * DBL_EPSILON * sum * sum;
    if (fb_disc(&m, th2) < -tiny) {
        fb_class k = classify(&m, th2);
        return mm_error_set(err, MM_ERANGE, "theta2",
                            "the linkage cannot close at theta2 = %g rad: B is out of the coupler and rocker's "
                            "reach there; the crank can reach %.6g to %.6g rad (toggles at the ends)", th2,
                            k.lo, k.hi);
    }
    return MM_OK;
}

/* ---- the sweeps ------------------------------------------------------------------------------ */

typedef struct fb_run {
    const fb *m;
    const mm_mech_problem *prob;
    const mm_mech_options *opt;
    mm_mech_work *w;
} fb_run;

/* the assembly of a side at th2: C from the circles about B and O4 */
static void assemble(const fb *m, double th2, int side, double *q)
{
    mm_v2 B = mm_v2_polar(m->a, th2), O4 = {m->d, 0}, P[2];
    int n = mm_geom_circle_circle(B, m->b, O4, m->c, P, NULL);
    mm_v2 C = n ? P[side > 0 ? 0 : 1] : mm_v2_add(B, mm_v2_scale(mm_v2_sub(O4, B), m->b / (m->b + m->c)));
    q[0] = atan2(C.y - B.y, C.x - B.x);
    q[1] = atan2(C.y, C.x - m->d);
}

/* Positions, velocities, accelerations (per unit crank rate) on the grid
 * x[0..n-1] (increasing), following the assembly q0 found at th2 forward
 * and backward from it.  Returns MM_OK; *stopped = 1 if a sweep lost it. */
static int sweep_grid(const fb_run *r, double th2, const double *q0, int side, int singular, int n,
                      const double *x, double *Q, double *QD, double *QDD, mm_result *res, mm_error *err)
{
    int j = 0;                                      /* first grid point above th2 */
    while (j < n && x[j] <= th2)
        j++;
    double *t = mm_res_alloc(res, (size_t)(n + 1) * sizeof *t), *q = mm_res_alloc(res, 2 * (size_t)(n + 1) * sizeof *q);
    double *qd = mm_res_alloc(res, 2 * (size_t)(n + 1) * sizeof *qd), *qdd = mm_res_alloc(res, 2 * (size_t)(n + 1) * sizeof *qdd);
    if (!t || !q || !qd || !qdd)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (int dir = 0; dir < 2; dir++) {             /* forward over x[j..n-1], backward over x[j-1..0] */
        int cnt = dir ? j : n - j;
        if (cnt == 0)
            continue;
        for (int i = 0; i < cnt; i++)
            t[i + 1] = dir ? x[j - 1 - i] : x[j + i];
        /* a sweep cannot leave a singular point (a toggle or the crossing of
         * a change point): start it a hair away, on the same side */
        double hair = singular ? (dir ? -1 : 1) * fmin(1e-6, 0.1 * fabs(t[1] - th2)) : 0;
        t[0] = th2 + hair;
        int skip = fabs(t[1] - t[0]) < 1e-12 ? 1 : 0;   /* th2 on a grid point */
        if (singular)
            assemble(r->m, t[0], side, q + 2 * skip);
        else
            memcpy(q + 2 * skip, q0, 2 * sizeof *q);
        mm_mech_sweep s = {.nt = cnt + 1 - skip, .t = t + skip, .q = q + 2 * skip, .qd = qd + 2 * skip,
                           .qdd = qdd + 2 * skip, .watch = -1};
        if (s.nt < 2) {                              /* only th2 itself */
            memcpy(q + 2, q0, 2 * sizeof *q);
            mm_mech_velocity(r->prob, r->opt, r->w, t[1], q + 2, qd + 2, NULL, NULL);
            mm_mech_acceleration(r->prob, r->opt, r->w, t[1], q + 2, qd + 2, qdd + 2, NULL, NULL);
        } else {
            int rc = mm_mech_sweep_solve(r->prob, r->opt, r->w, &s, err);
            if (rc != MM_OK)
                return rc;
            if (s.solved < s.nt)
                return mm_error_set(err, MM_ENOCONV, "theta2", "the sweep lost the linkage at theta2 = %g rad",
                                    s.t_limit);
        }
        for (int i = 0; i < cnt; i++) {
            int g = dir ? j - 1 - i : j + i;
            memcpy(Q + 2 * g, q + 2 * (i + 1), 2 * sizeof *Q);
            memcpy(QD + 2 * g, qd + 2 * (i + 1), 2 * sizeof *QD);
            memcpy(QDD + 2 * g, qdd + 2 * (i + 1), 2 * sizeof *QDD);
        }
    }
    return MM_OK;
}

/* the coupler point P and its velocity, acceleration per unit crank rate */
static void coupler(const fb *m, double px, double py, double th2, const double *q, const double *qd,
                    const double *qdd, mm_v2 *P, mm_v2 *V, mm_v2 *A)
{
    mm_v2 rp = mm_v2_rotate((mm_v2){px, py}, q[0]);          /* B to P */
    *P = mm_v2_add(mm_v2_polar(m->a, th2), rp);
    *V = mm_v2_add(mm_v2_perp(mm_v2_polar(m->a, th2)), mm_v2_scale(mm_v2_perp(rp), qd[0]));
    *A = mm_v2_add(mm_v2_scale(mm_v2_polar(m->a, th2), -1),
                   mm_v2_sub(mm_v2_scale(mm_v2_perp(rp), qdd[0]), mm_v2_scale(rp, qd[0] * qd[0])));
}

typedef struct fd_ctx {
    const fb_run *r;
    const double *th, *q;         /* the samples and their solved positions, */
    const double *qd, *qdd;       /* velocities and accelerations per unit crank rate */
} fd_ctx;

static int fd_pos(int i, double h, double *q, double *qerr, void *ctx, mm_error *err)
{
    fd_ctx *c = ctx;
    mm_mech_info info;
    for (int j = 0; j < 2; j++)          /* Taylor's guess: Newton stays on the assembly */
        q[j] = c->q[2 * i + j] + h * c->qd[2 * i + j] + 0.5 * h * h * c->qdd[2 * i + j];
    int rc = mm_mech_position(c->r->prob, c->r->opt, c->r->w, c->th[i] + h, q, &info, err);
    *qerr = info.err_est;
    return rc;
}

/* rounding bounds of one frame, given the error dth of its angles: the
 * rates inherit it through the solves (whose condition is kappa =
 * 1/|sin mu|, the Jacobian's smallest singular value being about
 * min(b, c) |sin mu|) */
static void frame_tol(const fb *m, const double *q, const double *qd, const double *qdd, double dth, double tol[3])
{
    double mn = fmin(m->b, m->c);
    double kappa = 1 / fmax(fabs(sin(q[1] - q[0])), 1e-300);
    double W = fabs(qd[0]) + fabs(qd[1]) + m->a / mn;
    double L = fabs(qdd[0]) + fabs(qdd[1]) + (m->a + m->b * qd[0] * qd[0] + m->c * qd[1] * qd[1]) / mn;
    double dw = (16 * DBL_EPSILON + 2 * dth) * kappa * W;
    tol[0] = dth;
    tol[1] = dw;
    tol[2] = (16 * DBL_EPSILON + 2 * dth) * kappa * L + 2 * dw * kappa * (m->b * fabs(qd[0]) + m->c * fabs(qd[1])) / mn;
}

/* Newton's angles: a residual of eps S over the smallest singular value */
static double newton_err(const fb *m, const double *q, double err_est)
{
    double S = m->a + m->b + m->c + m->d;
    return 16 * DBL_EPSILON * S / (fmin(m->b, m->c) * fmax(fabs(sin(q[1] - q[0])), 1e-300)) + 2 * err_est;
}

/* ---- the animation ------------------------------------------------------------------------------ */

static int animate(const fb_run *r, const fb_class *k, int side, double w2, double px, double py, double th0,
                   const double *q0, int singular, mm_result *res, mm_error *err)
{
    enum { NF = 72 };
    const fb *m = r->m;
    double th[NF], q[2 * NF], qd[2 * NF], qdd[2 * NF];
    int legs = k->full ? 1 : 2, per = NF / legs;
    for (int leg = 0; leg < legs; leg++) {
        double t[NF];
        double a0 = k->lo + 1e-9 * (k->hi - k->lo), a1 = k->hi - 1e-9 * (k->hi - k->lo);
        /* a full turn from the angle asked (a hair past it if that is singular) */
        double start = th0 + (singular ? 1e-6 : 0);
        for (int f = 0; f < per; f++)
            t[f] = k->full ? start + 2 * M_PI * f / NF : leg ? a1 - (a1 - a0) * f / (per - 1) : a0 + (a1 - a0) * f / (per - 1);
        double *qq = q + 2 * leg * per;
        if (k->full && !singular)
            memcpy(qq, q0, 2 * sizeof *qq);
        else
            assemble(m, t[0], leg ? -side : side, qq);
        mm_mech_sweep s = {.nt = per, .t = t, .q = qq, .qd = qd + 2 * leg * per, .qdd = qdd + 2 * leg * per, .watch = -1};
        int rc = mm_mech_sweep_solve(r->prob, r->opt, r->w, &s, err);
        if (rc != MM_OK)
            return rc;
        for (int f = s.solved; f < per; f++) {          /* rounding at a toggle end: hold the last */
            memcpy(qq + 2 * f, qq + 2 * (s.solved - 1), 2 * sizeof *qq);
            memset(qd + 2 * (leg * per + f), 0, 2 * sizeof *qd);
            memset(qdd + 2 * (leg * per + f), 0, 2 * sizeof *qdd);
        }
        memcpy(th + leg * per, t, (size_t)per * sizeof *t);
    }
    mm_v2 P[NF], V[NF], A[NF];
    double vmax = 0, amax = 0, size = m->d + m->a + fmax(m->b, m->c) + hypot(px, py);
    for (int f = 0; f < NF; f++) {
        coupler(m, px, py, th[f], q + 2 * f, qd + 2 * f, qdd + 2 * f, &P[f], &V[f], &A[f]);
        vmax = fmax(vmax, fabs(w2) * mm_v2_norm(V[f]));
        amax = fmax(amax, w2 * w2 * mm_v2_norm(A[f]));
    }
    mm_kin_draw d;
    mm_anim *an = mm_kin_draw_start(&d, res, NF, "crank angle travelled", "rad", size);
    mm_shape *g = an ? mm_kin_shape(&d, "ground", MM_SHAPE_LINE, 0, 2) : NULL;
    mm_shape *p2 = mm_kin_pivot(&d, "O2", 0, 0), *p4 = mm_kin_pivot(&d, "O4", m->d, 0);
    mm_shape *crank = mm_kin_shape(&d, "crank", MM_SHAPE_LINE, 1, 2);
    mm_shape *coup = mm_kin_shape(&d, "coupler", MM_SHAPE_POLYGON, 1, 3);
    mm_shape *rock = mm_kin_shape(&d, "rocker", MM_SHAPE_LINE, 1, 2);
    mm_shape *curve = mm_kin_shape(&d, "coupler curve", MM_SHAPE_PATH, 0, NF + 1);
    mm_shape *va = mm_kin_arrow_shape(&d, "v_P", "m/s", vmax), *aa = mm_kin_arrow_shape(&d, "a_P", "m/s^2", amax);
    if (!g || !p2 || !p4 || !crank || !coup || !rock || !curve || !va || !aa)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    g->style = "ground";
    mm_kin_pt(g, 0, 0, 0, 0);
    mm_kin_pt(g, 0, 1, m->d, 0);
    double travelled = 0;
    for (int f = 0; f < NF; f++) {
        if (f)
            travelled += fabs(th[f] - th[f - 1]);
        an->t[f] = travelled;
        mm_v2 B = mm_v2_polar(m->a, th[f]), C = mm_v2_add(B, mm_v2_polar(m->b, q[2 * f]));
        mm_kin_pt(crank, f, 0, 0, 0);
        mm_kin_pt(crank, f, 1, B.x, B.y);
        mm_kin_pt(coup, f, 0, B.x, B.y);
        mm_kin_pt(coup, f, 1, C.x, C.y);
        mm_kin_pt(coup, f, 2, P[f].x, P[f].y);
        mm_kin_pt(rock, f, 0, m->d, 0);
        mm_kin_pt(rock, f, 1, C.x, C.y);
        mm_kin_pt(curve, 0, f, P[f].x, P[f].y);
        mm_kin_arrow(va, f, P[f].x, P[f].y, w2 * V[f].x, w2 * V[f].y);
        mm_kin_arrow(aa, f, P[f].x, P[f].y, w2 * w2 * A[f].x, w2 * w2 * A[f].y);
    }
    mm_kin_pt(curve, 0, NF, P[0].x, P[0].y);
    return mm_kin_draw_finish(&d);
}

/* ---- the answer ------------------------------------------------------------------------------ */

/* a closed-form value: exact while its rounding bound stays below 1e-12 of
 * its size (or 1e-15 absolute), else printed with that bound as estimate */
static void put(mm_result *res, int o, double v, double bound)
{
    mm_scalar *s = mm_res_scalar(res, o, v + 0.0);                    /* no -0 */
    if (bound > 1e-12 * fabs(v) && bound > 1e-15) {
        s->exact = 0;
        s->error = bound;
        s->error_kind = MM_ERR_ESTIMATE;
    }
}

/* the transmission angle from |O4 B| by the law of cosines, eq. (6) */
static double mu_of(const fb *m, double th2)
{
    double e2 = m->a * m->a + m->d * m->d - 2 * m->a * m->d * cos(th2);
    return acos(fmax(-1, fmin(1, (m->b * m->b + m->c * m->c - e2) / (2 * m->b * m->c))));
}

/* worst-ratio bookkeeping of a per-frame check */
typedef struct worst {
    double ratio, got, ref, tol;
} worst;

static void track(worst *w, double got, double ref, double tol)
{
    double r = fabs(got - ref) / tol;
    if (!(r <= w->ratio))
        *w = (worst){r, got, ref, tol};
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    fb m = {in[P_A].x, in[P_B].x, in[P_C].x, in[P_D].x};
    const double w2 = in[P_OMEGA2].x, th2 = in[P_THETA2].x, px = in[P_PX].x, py = in[P_PY].x;
    const int side = in[P_BRANCH].x == 0 ? 1 : -1, n = (int)in[P_POINTS].x;
    const double S = m.a + m.b + m.c + m.d, tiny = 8 * DBL_EPSILON * S * S;
    mm_mech_problem prob = {.n = 2, .m = 2, .phi = phi_fn, .jac = jac_fn, .nu = nu_fn, .gamma = gamma_fn, .params = &m};
    mm_mech_options opt;
    mm_mech_options_init(&opt);
    opt.phi_scale = S;
    mm_mech_work *w = mm_mech_work_alloc(2, 2);
    if (!w)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    fb_run run = {&m, &prob, &opt, w};
    fb_class k = classify(&m, th2);
    int rc = MM_OK;
    mm_res_scalar_text(res, O_GRASHOF, k.grashof, k.name);

    /* ---- at theta2: Freudenstein printed, Newton and the Jacobian solves checked ---- */
    double t3, t4, q[2], qd[2], qdd[2], tol[3], ferr;
    freudenstein(&m, th2, side, &t3, &t4, &ferr);
    int singular = fb_disc(&m, th2) <= tiny;
    assemble(&m, th2, side, q);
    mm_mech_info info;
    if ((rc = mm_mech_position(&prob, &opt, w, th2, q, &info, err)) != MM_OK)
        goto out;
    double w3 = 0, w4 = 0, a3 = 0, a4 = 0;
    if (!singular)
        fb_rates(&m, th2, t3, t4, &w3, &w4, &a3, &a4);
    double r1[2] = {w3, w4}, r2[2] = {a3, a4}, qq[2] = {t3, t4};
    frame_tol(&m, qq, r1, r2, newton_err(&m, qq, info.err_est) + ferr, tol);
    if (singular) {
        /* a toggle or a change point: the discriminant is zero within its
         * rounding, the angles known to sqrt of it */
        double b = sqrt(2 * tiny) / fmin(m.b, m.c);
        mm_res_scalar_err(res, O_TH3, t3, b, MM_ERR_BOUND);
        mm_res_scalar_err(res, O_TH4, t4, b, MM_ERR_BOUND);
        tol[0] = b;
        mm_res_warn(res, "theta2 = %g rad is a %s: coupler and rocker lie in line, the Jacobian of eq. (1) is "
                         "singular, the crank cannot drive the linkage through at constant speed, and omega3, "
                         "omega4, alpha3, alpha4 are not defined there (left out)", th2,
                    k.change_point ? "change point (all four links in line)" : "toggle");
    } else {
        put(res, O_TH3, t3, tol[0]);
        put(res, O_TH4, t4, tol[0]);
    }
    mm_res_check_abs(res, "theta3 at theta2: Newton on eq. (1) vs Freudenstein (2)", mm_kin_near(q[0], t3), t3, tol[0]);
    mm_res_check_abs(res, "theta4 at theta2: Newton on eq. (1) vs Freudenstein (3)", mm_kin_near(q[1], t4), t4, tol[0]);
    /* mu by the law of cosines: its cosine carries a few eps of the terms,
     * which near 0 or pi (a toggle) move mu by up to sqrt of that */
    double mu = mu_of(&m, th2);
    double dx = 4 * DBL_EPSILON * (m.a * m.a + m.d * m.d + 2 * m.a * m.d + m.b * m.b + m.c * m.c) / (2 * m.b * m.c);
    put(res, O_MU, mu, fmin(dx / fmax(sin(mu), 1e-300), sqrt(2 * dx)));
    if (!singular) {
        put(res, O_OM3, w2 * w3, fabs(w2) * tol[1]);
        put(res, O_OM4, w2 * w4, fabs(w2) * tol[1]);
        put(res, O_AL3, w2 * w2 * a3, w2 * w2 * tol[2]);
        put(res, O_AL4, w2 * w2 * a4, w2 * w2 * tol[2]);
        if ((rc = mm_mech_velocity(&prob, &opt, w, th2, q, qd, &info, err)) != MM_OK ||
            (rc = mm_mech_acceleration(&prob, &opt, w, th2, q, qd, qdd, &info, err)) != MM_OK)
            goto out;
        mm_res_check_abs(res, "omega3: Jacobian solve (4) vs closed form (4)", w2 * qd[0], w2 * w3, fabs(w2) * tol[1]);
        mm_res_check_abs(res, "omega4: Jacobian solve (4) vs closed form (4)", w2 * qd[1], w2 * w4, fabs(w2) * tol[1]);
        mm_res_check_abs(res, "alpha3: Jacobian solve (5) vs closed form (5)", w2 * w2 * qdd[0], w2 * w2 * a3,
                         w2 * w2 * tol[2]);
        mm_res_check_abs(res, "alpha4: Jacobian solve (5) vs closed form (5)", w2 * w2 * qdd[1], w2 * w2 * a4,
                         w2 * w2 * tol[2]);
        mm_v2 P, V, A;
        coupler(&m, px, py, th2, qq, r1, r2, &P, &V, &A);
        double L = hypot(px, py) + m.a;
        put(res, O_VP, fabs(w2) * mm_v2_norm(V), fabs(w2) * (tol[1] * L + 4 * DBL_EPSILON * mm_v2_norm(V)));
        put(res, O_AP, w2 * w2 * mm_v2_norm(A), w2 * w2 * (tol[2] * L + 4 * DBL_EPSILON * mm_v2_norm(A)));
    }

    /* ---- the cycle: a full turn, or the arc the crank can reach ---- */
    double lo = k.full ? 0 : k.lo, hi = k.full ? 2 * M_PI : k.hi, inset = k.full ? 0 : 1e-3 * (hi - lo);
    double th0 = k.full ? th2 - 2 * M_PI * floor(th2 / (2 * M_PI)) : th2;   /* th2 in [0, 2 pi) */
    mm_series *ser[7];
    for (int i = 0; i < 7; i++)
        if (!(ser[i] = mm_res_series(res, O_S3 + i, n))) {
            rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
            goto out;
        }
    mm_series *cc = mm_res_series(res, O_SCOUP, n);
    double *Q = mm_res_alloc(res, 2 * (size_t)n * sizeof *Q), *QD = mm_res_alloc(res, 2 * (size_t)n * sizeof *QD);
    double *QDD = mm_res_alloc(res, 2 * (size_t)n * sizeof *QDD), *x = ser[0]->x;
    if (!cc || !Q || !QD || !QDD) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
        goto out;
    }
    mm_kin_grid(lo + inset, hi - inset, n, x);
    if ((rc = sweep_grid(&run, th0, q, side, singular, n, x, Q, QD, QDD, res, err)) != MM_OK)
        goto out;
    worst e3 = {-1, 0, 0, 0}, e4 = e3, ew = e3, ea = e3, emu = e3;
    for (int i = 0; i < n; i++) {
        double *qi = Q + 2 * i, f3, f4, v3, v4, c3, c4;
        for (int j = 1; j < 7; j++)
            ser[j]->x[i] = x[i];
        ser[0]->y[i] = qi[0], ser[1]->y[i] = qi[1];
        ser[2]->y[i] = w2 * QD[2 * i], ser[3]->y[i] = w2 * QD[2 * i + 1];
        ser[4]->y[i] = w2 * w2 * QDD[2 * i], ser[5]->y[i] = w2 * w2 * QDD[2 * i + 1];
        double mu_q = fabs(mm_kin_wrap(qi[1] - qi[0]));                  /* the angle at C */
        ser[6]->y[i] = mu_q;
        mm_v2 P, V, A;
        coupler(&m, px, py, x[i], qi, QD + 2 * i, QDD + 2 * i, &P, &V, &A);
        cc->x[i] = P.x, cc->y[i] = P.y;
        /* the closed form of the same assembly: the Freudenstein root nearest */
        double g3, g4, h3, h4, ge, he;
        freudenstein(&m, x[i], 1, &g3, &g4, &ge);
        freudenstein(&m, x[i], -1, &h3, &h4, &he);
        int near1 = fabs(mm_kin_wrap(qi[1] - g4)) + fabs(mm_kin_wrap(qi[0] - g3)) <=
                    fabs(mm_kin_wrap(qi[1] - h4)) + fabs(mm_kin_wrap(qi[0] - h3));
        f3 = near1 ? g3 : h3, f4 = near1 ? g4 : h4;
        fb_rates(&m, x[i], f3, f4, &v3, &v4, &c3, &c4);
        double fq[2] = {f3, f4}, fv[2] = {v3, v4}, fa[2] = {c3, c4};
        frame_tol(&m, fq, fv, fa, newton_err(&m, fq, 0) + (near1 ? ge : he), tol);
        track(&e3, mm_kin_near(qi[0], f3), f3, tol[0]);
        track(&e4, mm_kin_near(qi[1], f4), f4, tol[0]);
        /* a frame exactly at a change point has no rates (the sweep leaves
         * zeros there: B moves, so omega3 = omega4 = 0 cannot happen else) */
        int sing = (QD[2 * i] == 0 && QD[2 * i + 1] == 0) || !isfinite(v3 + v4 + c3 + c4);
        if (!sing) {
            track(&ew, QD[2 * i + (fabs(QD[2 * i] - v3) < fabs(QD[2 * i + 1] - v4))],
                  fabs(QD[2 * i] - v3) < fabs(QD[2 * i + 1] - v4) ? v4 : v3, tol[1]);
            track(&ea, QDD[2 * i + (fabs(QDD[2 * i] - c3) < fabs(QDD[2 * i + 1] - c4))],
                  fabs(QDD[2 * i] - c3) < fabs(QDD[2 * i + 1] - c4) ? c4 : c3, tol[2]);
        }
        track(&emu, mu_q, mu_of(&m, x[i]), 2 * tol[0] + 8 * DBL_EPSILON / fmax(sin(mu_q), 1e-300));
    }
    mm_res_check_abs(res, "sweep: theta3 vs Freudenstein, the frame nearest its bound (the assembly kept)", e3.got, e3.ref, e3.tol);
    mm_res_check_abs(res, "sweep: theta4 vs Freudenstein, the frame nearest its bound", e4.got, e4.ref, e4.tol);
    mm_res_check_abs(res, "sweep: omega3, omega4 per unit omega2 vs closed form (4), the frame nearest its bound",
                     ew.got, ew.ref, ew.tol);
    mm_res_check_abs(res, "sweep: alpha3, alpha4 per unit omega2^2 vs closed form (5), the frame nearest its bound",
                     ea.got, ea.ref, ea.tol);
    mm_res_check_abs(res, "sweep: transmission angle from theta4 - theta3 vs the law of cosines (6)", emu.got,
                     emu.ref, emu.tol);

    /* ---- differences of the positions, one frame in four, clear of toggles ---- */
    {
        double h0 = k.full ? 0.05 : fmin(0.05, 0.02 * (hi - lo));
        double *th = mm_res_alloc(res, (size_t)n * sizeof *th), *qs = mm_res_alloc(res, 2 * (size_t)n * sizeof *qs);
        double *d1 = mm_res_alloc(res, 2 * (size_t)n * sizeof *d1), *d2 = mm_res_alloc(res, 2 * (size_t)n * sizeof *d2);
        if (!th || !qs || !d1 || !d2) {
            rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
            goto out;
        }
        int ns = 0;
        double derr1 = 0, derr2 = 0;
        for (int i = 0; i < n; i += 4) {
            /* keep 4 h0 inside the arc between the toggles (a gap narrower
             * than 8 h0 would hide between two tests of its ends) and away
             * from where the Jacobian is near singular */
            if ((!k.full && (x[i] - 4 * h0 < lo || x[i] + 4 * h0 > hi)) || fabs(sin(Q[2 * i + 1] - Q[2 * i])) < 0.05)
                continue;
            th[ns] = x[i];
            memcpy(qs + 2 * ns, Q + 2 * i, 2 * sizeof *qs);
            memcpy(d1 + 2 * ns, QD + 2 * i, 2 * sizeof *d1);
            memcpy(d2 + 2 * ns, QDD + 2 * i, 2 * sizeof *d2);
            double ft[3];
            frame_tol(&m, Q + 2 * i, QD + 2 * i, QDD + 2 * i, newton_err(&m, Q + 2 * i, 0), ft);
            derr1 = fmax(derr1, ft[1]), derr2 = fmax(derr2, ft[2]);
            ns++;
        }
        fd_ctx fc = {&run, th, qs, d1, d2};
        mm_kin_fd fd;
        if (ns > 0 && ((rc = mm_kin_fd_study(res, O_FDV, "dtheta/dtheta2", fd_pos, &fc, 2, NULL, ns, d1, 1, h0, 24,
                                             derr1, &fd, err)) != MM_OK ||
                       (rc = mm_kin_fd_study(res, O_FDA, "d2theta/dtheta2^2", fd_pos, &fc, 2, NULL, ns, d2, 2, h0, 18,
                                             derr2, &fd, err)) != MM_OK))
            goto out;
    }

    /* ---- transmission angle extremes, eq. (6): at the ends of |O4 B|'s range ---- */
    {
        double cand[4] = {lo, hi, 0, M_PI}, mn = INFINITY, mx = -INFINITY, tmn = 0, tmx = 0;
        for (int i = 0; i < 4; i++) {
            double t = i < 2 ? cand[i] : cand[i] + 2 * M_PI * ceil((lo - cand[i]) / (2 * M_PI));   /* first one >= lo */
            if (t > hi + 1e-12 || (k.full && i < 2))
                continue;
            /* at a toggle coupler and rocker lie in line: mu is 0 or pi
             * exactly (the law of cosines would give sqrt(eps) there) */
            double v = mu_of(&m, t);
            if (i < 2)
                v = v < M_PI / 2 ? 0 : M_PI;
            double where = i < 2 ? mm_kin_wrap(t) : cand[i];       /* 0 and pi as themselves */
            if (v < mn)
                mn = v, tmn = where;
            if (v > mx)
                mx = v, tmx = where;
        }
        mm_res_scalar(res, O_MU_MIN, mn);
        mm_res_scalar(res, O_MU_MAX, mx);
        mm_res_scalar(res, O_TH_MUMIN, tmn);
        mm_res_scalar(res, O_TH_MUMAX, tmx);
        double dev = fmax(fabs(M_PI / 2 - mn), fabs(mx - M_PI / 2));
        if (k.full && dev > M_PI / 2 - 40 * M_PI / 180)
            mm_res_warn(res, "the transmission angle strays more than 50 degrees from 90 (%.1f to %.1f degrees): "
                             "the coupler pushes the rocker along itself more than it turns it",
                        mn * 180 / M_PI, mx * 180 / M_PI);
    }

    /* ---- events: dead centres of the rocker, toggles, change points ---- */
    if (k.full) {
        enum { NT = 49 };
        double t[NT], qq2[2 * NT], vv[2 * NT];
        for (int i = 0; i < NT; i++)
            t[i] = 0.123 + 2 * M_PI * i / (NT - 1);
        int j = 0;
        while (j + 1 < n && x[j + 1] <= t[0])
            j++;
        memcpy(qq2, Q + 2 * j, 2 * sizeof *qq2);
        mm_mech_sweep s = {.nt = NT, .t = t, .q = qq2, .qd = vv, .watch = 1};
        if ((rc = mm_mech_sweep_solve(&prob, &opt, w, &s, err)) != MM_OK)
            goto out;
        /* crank and coupler in line: |O2 C| = b + a or |b - a|, C on the rocker's circle */
        double dc[4], dq[4], dce[4];
        int nd = 0;
        for (int e = 0; e < 2; e++) {
            double L = e ? fabs(m.b - m.a) : m.b + m.a, cs = (L * L + m.d * m.d - m.c * m.c) / (2 * L * m.d);
            if (fabs(cs) > 1 || L == 0)
                continue;
            for (int sg = -1; sg <= 1; sg += 2) {
                double ang = sg * acos(cs);                                  /* the direction of O2 C */
                dc[nd] = e && m.b < m.a ? ang : (e ? ang + M_PI : ang);      /* the crank along or against */
                dq[nd] = atan2(L * sin(ang), L * cos(ang) - m.d);            /* theta4 there */
                /* acos magnifies the rounding of cs by 1 / sin(ang) */
                dce[nd++] = 8 * DBL_EPSILON * (1 + fabs(cs)) / fmax(sqrt(1 - cs * cs), DBL_EPSILON);
            }
        }
        for (int i = 0; i < s.n_turn && i < 2; i++) {
            int best = 0;
            for (int c = 1; c < nd; c++)
                if (fabs(mm_kin_wrap(s.t_turn[i] - dc[c])) < fabs(mm_kin_wrap(s.t_turn[i] - dc[best])))
                    best = c;
            double want = nd ? mm_kin_near(dc[best], s.t_turn[i]) : 0;
            /* the sweep ends on the secant of q4' (rounding of theta2) */
            mm_res_check_abs(res, i ? "second dead centre of the rocker: located by the sweep vs crank and coupler in line"
                                    : "first dead centre of the rocker: located by the sweep vs crank and coupler in line",
                             s.t_turn[i], want, 64 * DBL_EPSILON * (1 + fabs(want)) + (nd ? dce[best] : 0));
        }
        (void)dq;
        /* a crank-rocker's swing: theta4 where crank and coupler lie in line,
         * stretched (|O2 C| = b + a) and folded (b - a), each on the side of
         * B -> O4 the assembly keeps */
        if (!k.change_point && k.shortest == 0) {
            double th4[2];
            for (int e = 0; e < 2; e++) {
                double L = e ? m.b - m.a : m.b + m.a, ang = acos((L * L + m.d * m.d - m.c * m.c) / (2 * L * m.d));
                double best = -INFINITY;
                for (int sg = -1; sg <= 1; sg += 2) {
                    mm_v2 C = mm_v2_polar(L, sg * ang), B = mm_v2_scale(C, (e ? -m.a : m.a) / L);
                    double sd = side * mm_v2_cross(mm_v2_sub((mm_v2){m.d, 0}, B), mm_v2_sub(C, B));
                    if (sd > best)
                        best = sd, th4[e] = atan2(C.y, C.x - m.d);
                }
            }
            mm_res_scalar(res, O_SWING, fabs(mm_kin_wrap(th4[0] - th4[1])));
        }
        if (k.change_point) {
            /* all four links in line where |O4 B| = |b - c| (th2 = 0) or b + c
             * (th2 = pi); each one must be met as a sign change of det(Phi_q)
             * by the sweep, whose frames miss them (0.123 + k pi/24): bisected
             * to 1e-5 of the turn and a parabola through det (measured within
             * 5e-11; det's sign is lost within ~sqrt(eps) of the crossing).
             * The angles there carry eps S / (min(b, c) |sin mu|) of rounding,
             * |sin mu| ~ 1e-5 of the turn away: links of very unequal lengths
             * move the zero by that much */
            double tol_g = 4 * DBL_EPSILON * S;
            double tol_cp = 1e-9 + 4 * DBL_EPSILON * S / (fmin(m.b, m.c) * 1e-5 * 2 * M_PI);
            double want[2] = {fabs(fabs(m.d - m.a) - fabs(m.b - m.c)) <= tol_g ? 0 : -1,
                              fabs(m.b + m.c - m.d - m.a) <= tol_g ? M_PI : -1};
            for (int e = 0; e < 2; e++) {
                if (want[e] < 0)
                    continue;
                double cp = want[e] < t[0] ? want[e] + 2 * M_PI : want[e], got = INFINITY;   /* in the sweep's turn */
                for (int i = 0; i < s.n_sing; i++)
                    if (fabs(s.t_sing[i] - cp) < fabs(got - cp))
                        got = s.t_sing[i];
                mm_res_check_abs(res, "change point: located by the sweep (det = 0) vs all links in line",
                                 isfinite(got) ? got : t[NT - 1], cp, tol_cp);
            }
            mm_res_warn(res, "s + l = p + q: a change point. Where all four links lie in line the open and crossed "
                             "assemblies meet; the motion shown carries straight on through them, and past such a "
                             "point it is the assembly the other label describes");
        }
    } else {
        mm_res_scalar(res, O_TOG1, lo);
        mm_res_scalar(res, O_TOG2, hi);
        if (fabs(lo + 2 * M_PI - hi - k.gap[1]) <= 1e-9)     /* one arc: the gap is the rest of the turn */
            mm_res_warn(res, "%s: the crank cannot turn round; it rocks between the toggles at %.4g and %.4g "
                             "rad, where coupler and rocker lie in line, and cannot close from %.4g to %.4g rad",
                        k.name, lo, hi, hi, lo + 2 * M_PI);
        else
            mm_res_warn(res, "%s: the crank cannot turn round; it rocks between the toggles at %.4g and %.4g "
                             "rad, where coupler and rocker lie in line, and cannot close from %.4g to %.4g nor "
                             "from %.4g to %.4g rad; the arc beyond those gaps is another assembly, reached only "
                             "by taking the linkage apart",
                        k.name, lo, hi, hi, hi + k.gap[1], lo - k.gap[0], lo);
        for (int end = 0; end < 2; end++) {
            enum { NT = 9 };
            double t[NT], qq2[2 * NT];
            /* past the toggle, but never past the middle of the gap: beyond it
             * the linkage closes again, and a sweep could step across */
            double past = fmin(0.05, 0.5 * k.gap[end]);
            double from = end ? hi - 0.1 * (hi - lo) : lo + 0.1 * (hi - lo), to = end ? hi + past : lo - past;
            for (int i = 0; i < NT; i++)
                t[i] = from + (to - from) * i / (NT - 1);
            assemble(&m, t[0], side, qq2);
            mm_mech_sweep s = {.nt = NT, .t = t, .q = qq2, .watch = -1, .tol_t = 1e-13};
            if ((rc = mm_mech_sweep_solve(&prob, &opt, w, &s, err)) != MM_OK)
                goto out;
            mm_res_check_abs(res, end ? "second toggle: where the sweep stops closing vs |O4 B| = b + c or |b - c|"
                                      : "first toggle: where the sweep stops closing vs |O4 B| = b + c or |b - c|",
                             s.t_limit, end ? hi : lo, 1e-9);
        }
    }
    mm_res_method(res, "Newton-Raphson on the loop closure, Jacobian solves for velocity and acceleration", 0);
    mm_res_method_stat(res, "error_estimate", info.err_est);
    rc = animate(&run, &k, side, w2, px, py, th0, q, singular, res, err);
out:
    mm_mech_work_free(w);
    return rc;
}

static const char *const references[] = {
    "R. L. Norton, Design of Machinery, 5th ed., McGraw-Hill 2012, sections 2.12, 4.5-4.10, 6.7, 7.3",
    "F. Freudenstein, Approximate synthesis of four-bar linkages, Trans. ASME 77 (1955) 853-861",
    NULL,
};

const mm_exercise mm_ex_kin_four_bar = {
    .id = "kin-four-bar",
    .chapter = 2,
    .section = "2.4.4",
    .title = "Four-bar linkage",
    .summary = "Angles, angular velocities and accelerations of coupler and rocker; Grashof's condition, "
               "transmission angle, coupler curve, toggles and change points.",
    .tags = "kinematics, mechanism, four-bar, Grashof, Freudenstein, transmission angle, coupler curve",
    .theory = "exercises/kin/four_bar.md",
    .params = params,
    .n_params = MM_COUNT(params),
    .outputs = outputs,
    .n_outputs = MM_COUNT(outputs),
    .references = references,
    .check = check,
    .solve = solve,
};
