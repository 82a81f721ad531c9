/* mm_dyn.c — see mm_dyn.h. */
#include "mm_dyn.h"

#include <float.h>
#include <math.h>

#include "mm_elliptic.h"
#include "mm_exhelp.h"
#include "mm_opt.h"
#include "mm_pendulum.h"
#include "mm_quad.h"
#include "mm_roots.h"
#include "mm_scene.h"

double mm_dyn_quantum(double size)
{
    if (!(size > 0) || !isfinite(size))
        return 1e-6;
    return pow(10, floor(log10(size * 1e-5)));
}

double mm_dyn_round(double x, double q)
{
    if (q < 1) {                       /* divide by an exact power of ten: the result is the
                                          double nearest the short decimal */
        double p = nearbyint(1 / q);
        return nearbyint(x * p) / p;
    }
    return nearbyint(x / q) * q;
}

void mm_dyn_round_shape(mm_shape *s, double q)
{
    size_t m = (size_t)s->frames * (size_t)s->npts;
    for (size_t k = 0; k < m; k++) {
        s->x[k] = mm_dyn_round(s->x[k], q);
        s->y[k] = mm_dyn_round(s->y[k], q);
    }
}

void mm_dyn_frame_times(mm_anim *a, double t_show)
{
    /* the last frame is t_show itself: t_show (nf - 1) / (nf - 1) rounds
     * to one ulp above it as often as not, and an integration to t_show
     * then refuses the frame (dyn-slider-crank answered 400 naming its
     * solver's t_out on 2-5 % of valid requests) */
    for (int f = 0; f < a->nframes; f++)
        a->t[f] = a->nframes > 1 ? t_show * f / (a->nframes - 1) : 0;
    if (a->nframes > 1)
        a->t[a->nframes - 1] = t_show;
}

/* ---- dyn-robot-2link: the planned move of the two-link arm ----------------- */



/* The time law s(tau), tau = t/T, and its derivatives (eq. 2 and 3). */
static void law(int quintic, double tau, double *s, double *ds, double *dds)
{
    if (quintic) {
        double u = 1 - tau;
        *s = tau * tau * tau * (10 - 15 * tau + 6 * tau * tau);
        *ds = 30 * tau * tau * u * u;
        *dds = 60 * tau * u * (1 - 2 * tau);
    } else {
        *s = tau * tau * (3 - 2 * tau);
        *ds = 6 * tau * (1 - tau);
        *dds = 6 - 12 * tau;
    }
}

/* The planned q, q', q'' at time t. */
void mm_dyn_plan_at(const mm_dyn_plan *p, double t, double *q, double *qd, double *qdd)
{
    double s, ds, dds;
    law(p->quintic, fmin(fmax(t / p->T, 0), 1), &s, &ds, &dds);
    for (int j = 0; j < 2; j++) {
        q[j] = p->q0[j] + p->dq[j] * s;
        qd[j] = p->dq[j] * ds / p->T;
        qdd[j] = p->dq[j] * dds / (p->T * p->T);
    }
}

void mm_dyn_plan_torque(const mm_dyn_plan *p, double t, double *tau)
{
    double q[2], qd[2], qdd[2];
    mm_dyn_plan_at(p, t, q, qd, qdd);
    mm_robot2_inverse(&p->arm, q, qd, qdd, tau);          /* eq. (1) */
}

/* Forward dynamics driven by the planned torques: y = (q1, q2, q1', q2'). */
int mm_dyn_plan_forward_rhs(double t, const double *y, double *dy, void *ctx)
{
    mm_dyn_plan *p = ctx;
    double tau[2], q[2], qd[2], qdd[2];
    mm_dyn_plan_at(p, t, q, qd, qdd);
    if (p->t_left < 0 && fmax(fabs(y[0] - q[0]), fabs(y[1] - q[1])) > 2 * M_PI) {
        p->t_left = t;                                    /* it fell off the path: stop */
        return MM_ENOCONV;
    }
    mm_dyn_plan_torque(p, t, tau);
    dy[0] = y[2];
    dy[1] = y[3];
    mm_robot2_forward(&p->arm, y, y + 2, tau, dy + 2);   /* eq. (5) */
    return 0;
}

/* ---- how unstable the open-loop arm is along the path ---------------------------- */

/* A cheap upper estimate of how unstable the open-loop arm is: the growth
 * rate of small errors at time t from the gravity stiffness (delta q'' =
 * -M^-1 dG/dq delta q: a positive eigenvalue mu gives e^(sqrt(mu) t), the
 * arm balancing above its joints) plus the joint speeds (the Coriolis and
 * centrifugal terms feed errors at about |q'|), integrated over the move by
 * Simpson's rule.  Used to bound the work before anything is integrated. */
static double growth_rate(const mm_dyn_plan *p, double t)
{
    double q[2], qd[2], qdd[2], M[4];
    mm_dyn_plan_at(p, t, q, qd, qdd);
    const mm_robot2 *s = &p->arm;
    mm_robot2_mass(s, q[1], M);
    double a = (0.5 * s->m1 + s->m2) * s->g * s->l1, b = 0.5 * s->m2 * s->g * s->l2;
    double s1 = sin(q[0]), s12 = sin(q[0] + q[1]);
    double K[4] = {a * s1 + b * s12, b * s12, b * s12, b * s12};   /* -dG/dq */
    double det = M[0] * M[3] - M[1] * M[2];
    double A[4] = {(M[3] * K[0] - M[1] * K[2]) / det, (M[3] * K[1] - M[1] * K[3]) / det,
                   (M[0] * K[2] - M[2] * K[0]) / det, (M[0] * K[3] - M[2] * K[1]) / det};
    double tr = A[0] + A[3], dt = A[0] * A[3] - A[1] * A[2], disc = tr * tr / 4 - dt;
    double mu = tr / 2 + sqrt(fmax(disc, 0));
    return sqrt(fmax(mu, 0)) + fabs(qd[0]) + fabs(qd[1]);
}

double mm_dyn_plan_growth(const mm_dyn_plan *p)
{
    enum { NS = 64 };
    double sum = 0;
    for (int i = 0; i <= NS; i++)
        sum += (i == 0 || i == NS ? 1 : i % 2 ? 4 : 2) * growth_rate(p, p->T * i / NS);
    return sum * p->T / (3 * NS);
}

/* The variational equations along the planned path: Phi' = J(t) Phi,
 * Phi(0) = I, with J the Jacobian of the forward dynamics (eq. 5) at the
 * planned state, by central differences.  y = Phi, 16 values row-major. */
int mm_dyn_plan_variational_rhs(double t, const double *y, double *dy, void *ctx)
{
    mm_dyn_plan *p = ctx;
    double q[2], qd[2], qdd[2], x[4], J[16];
    mm_dyn_plan_at(p, t, q, qd, qdd);
    x[0] = q[0], x[1] = q[1], x[2] = qd[0], x[3] = qd[1];
    for (int k = 0; k < 4; k++) {
        double h = 1e-6 * (1 + fabs(x[k])), xp[4], xm[4], fp[4], fm[4];
        for (int j = 0; j < 4; j++)
            xp[j] = xm[j] = x[j];
        xp[k] += h, xm[k] -= h;
        mm_dyn_plan_forward_rhs(t, xp, fp, ctx);
        mm_dyn_plan_forward_rhs(t, xm, fm, ctx);
        for (int i = 0; i < 4; i++)
            J[4 * i + k] = (fp[i] - fm[i]) / (2 * h);
    }
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double v = 0;
            for (int k = 0; k < 4; k++)
                v += J[4 * i + k] * y[4 * k + j];
            dy[4 * i + j] = v;
        }
    return 0;
}

/* ---- the largest |tau_j| ------------------------------------------------------ */

typedef struct peak_ctx {
    const mm_dyn_plan *p;
    int j;
} peak_ctx;

static double abs_tau(const peak_ctx *c, double t)
{
    double tau[2];
    mm_dyn_plan_torque(c->p, t, tau);
    return fabs(tau[c->j]);
}

static int abs_tau_fn(double t, double *f, void *ctx)
{
    *f = abs_tau(ctx, t);
    return 0;
}

/* Sample on 2001 points, then golden-section search around the best
 * sample (mm_opt_scan_golden_max).  The maximum found is attained (a lower
 * bound); the true one exceeds it by at most |tau''| w^2 / 8 over the final
 * bracket w, estimated from second differences. */
double mm_dyn_plan_peak(const mm_dyn_plan *p, int j, double *t_at, double *err)
{
    peak_ctx c = {p, j};
    enum { NT = 2001 };
    mm_opt_result o;
    mm_error e = {0};
    if (mm_opt_scan_golden_max(abs_tau_fn, &c, p->T / (NT - 1), NT - 1, 4 * DBL_EPSILON * p->T, 200, &o, &e) != MM_OK)
        return *t_at = NAN, *err = NAN, NAN;      /* a torque that is not finite */
    double t = o.x, v = o.fx;
    double h = 1e-3 * p->T, tm = fmax(t - h, 0), tp = fmin(t + h, p->T);
    double curv = fabs(abs_tau(&c, tp) - 2 * abs_tau(&c, 0.5 * (tm + tp)) + abs_tau(&c, tm)) /
                  (0.25 * (tp - tm) * (tp - tm));
    double w = fmax(o.bracket, 4 * DBL_EPSILON * p->T);
    *t_at = t;
    *err = curv * w * w / 8 + 4 * DBL_EPSILON * v;
    return v;
}

/* ---- dyn-slider-crank ------------------------------------------------------- */

/* The extremes of the effective inertia J(phi) (eq. 5) over a turn: 361
 * samples of half a turn (J is even about 0 and pi, so half is enough),
 * the largest and the smallest each refined by golden sections
 * (mm_opt_scan_golden_max). */
typedef struct inertia_ctx {
    const mm_sc_model *s;
    double sign;
} inertia_ctx;

static int signed_inertia(double phi, double *f, void *ctx)
{
    const inertia_ctx *c = ctx;
    *f = c->sign * mm_sc_inertia(c->s, phi, NULL);
    return 0;
}

void mm_dyn_sc_inertia_range(const mm_sc_model *s, double *Jmin, double *Jmax)
{
    enum { NS = 360 };
    for (int k = 0; k < 2; k++) {
        inertia_ctx c = {s, k ? 1 : -1};
        mm_opt_result o;
        mm_error e = {0};
        double v = mm_opt_scan_golden_max(signed_inertia, &c, M_PI / NS, NS, 4 * DBL_EPSILON * M_PI, 200, &o, &e) == MM_OK
                       ? c.sign * o.fx : NAN;
        *(k ? Jmax : Jmin) = v;
    }
}

/* The error of reading an extreme off the samples: the parabola through
 * the best sample and its neighbours moves it by this much (an estimate). */
double mm_dyn_extreme_error(const double *v, int n, int i)
{
    if (i <= 0 || i >= n - 1)
        return 0;                                   /* at an end of the run: the run's own value */
    double c = 2 * v[i] - v[i - 1] - v[i + 1], d = v[i + 1] - v[i - 1];
    return c != 0 ? d * d / (8 * fabs(c)) : 0;
}


/* ---- dyn-double-pendulum ---------------------------------------------------- */

/* The fastest rate of the motion [1/s]: the fast small-oscillation
 * frequency, or the largest angular speed the energy allows:
 * w^T M w <= 2 (E - V_min) with the smallest eigenvalue of M at least
 * det M / trace M = m1 m2 l1^2 l2^2 / ((m1+m2) l1^2 + m2 l2^2). */
double mm_dyn_dpend_rate(const mm_dpend *s, const double *y0)
{
    double ws, wf, E = mm_dpend_energy(s, y0, NULL);
    mm_dpend_linear(s, &ws, &wf);
    double Vmin = -(s->m1 + s->m2) * s->g * s->l1 - s->m2 * s->g * s->l2;
    double lmin = s->m1 * s->m2 * s->l1 * s->l1 * s->l2 * s->l2 /
                  ((s->m1 + s->m2) * s->l1 * s->l1 + s->m2 * s->l2 * s->l2);
    return fmax(wf, sqrt(2 * fmax(E - Vmin, 0) / lmin));
}

/* DOP853 or DOPRI5 of Lagrange's equations (eq. 3) on the grid t[0..n-1];
 * y receives n x 4 values. */
int mm_dyn_dpend_run(const mm_dpend *s, const double *y0, double t_end, int n, const double *t,
                     mm_ode_method m, double rtol, double *y, mm_ode_result *r, mm_error *err)
{
    mm_ode_problem prob = {.n = 4, .f = mm_dpend_rhs_lagrange, .params = (void *)s, .t0 = 0, .t_end = t_end,
                           .y0 = y0};
    mm_ode_options opt = mm_ode_options_adaptive(m, rtol, rtol, 2000000);
    *r = (mm_ode_result){.t_out = t, .nout = (size_t)n, .y_out = y};
    int rc = mm_ode_run(&prob, &opt, r, err);
    return rc;
}

/* The distance of two states in the state space, angles in radians and
 * angular velocities in units of the fast frequency. */
double mm_dyn_dpend_distance(const double *a, const double *b, double wf)
{
    double d0 = a[0] - b[0], d1 = a[1] - b[1], d2 = (a[2] - b[2]) / wf, d3 = (a[3] - b[3]) / wf;
    return sqrt(d0 * d0 + d1 * d1 + d2 * d2 + d3 * d3);
}


double mm_dyn_sc_energy_bound(const mm_sc_model *s, const double *q, const double *qd, const double *qr,
                              const double *qdr, double tol_ref, double *bJ)
{
    /* |a^2 - b^2| / 2 <= max(|a|, |b|) |a - b|: exact, at any distance */
    const double M[MM_SC_NQ] = {s->J_crank, s->m_rod, s->m_rod, s->J_rod, s->m_piston};
    double b = fabs(s->torque) * fabs(q[0] - qr[0]);
    for (int j = 0; j < MM_SC_NQ; j++)
        b += M[j] * fmax(fabs(qd[j]), fabs(qdr[j])) * fabs(qd[j] - qdr[j]);
    /* J(phi) w^2 / 2 - torque phi: (J_a - J_b) w_a^2 / 2 + J_b (w_a^2 - w_b^2) / 2 */
    double dJ, Ja = mm_sc_inertia(s, q[0], NULL), Jb = mm_sc_inertia(s, qr[0], &dJ);
    double w = fmax(fabs(qd[0]), fabs(qdr[0]));
    *bJ = 0.5 * fabs(Ja - Jb) * qd[0] * qd[0] + Jb * w * fabs(qd[0] - qdr[0]) + fabs(s->torque) * fabs(q[0] - qr[0]);
    /* the reference's own error: tol_ref on the crank angle and speed (absolute and relative) */
    double e_ref = tol_ref * ((fabs(0.5 * dJ * w * w) + fabs(s->torque)) * (1 + fabs(qr[0])) + Jb * w * (1 + w));
    *bJ += e_ref;
    return b + e_ref;
}

/* ---- dyn-double-pendulum: the animation of the twins ------------------------- */

int mm_dyn_dpend_animate(const mm_dpend *s, double t_end, const double *y0, const double *y0b, double rtol,
                         mm_result *res, mm_error *err)
{
    double ws, wf, t_show;
    mm_dpend_linear(s, &ws, &wf);
    int nf = mm_scene_frames(t_end, 2 * M_PI / mm_dyn_dpend_rate(s, y0), &t_show);
    if (nf > 120) {                            /* 5 s of play at 24 frames a second is enough to see */
        t_show *= 119.0 / (nf - 1);            /* the twins part; the answer stays small */
        nf = 120;
    }
    mm_anim *a = mm_res_animation(res, nf, "t", "s");
    double *ya = mm_res_alloc(res, (size_t)nf * 4 * sizeof *ya), *yb = mm_res_alloc(res, (size_t)nf * 4 * sizeof *yb);
    if (!a || !ya || !yb)
        return MM_ENOMEM;
    mm_dyn_frame_times(a, t_show);
    mm_ode_result r;
    double te = a->t[nf - 1] > 0 ? a->t[nf - 1] : t_end;
    int rc = mm_dyn_dpend_run(s, y0, te, nf, a->t, MM_ODE_DOP853, rtol, ya, &r, err);
    if (rc == MM_OK)
        rc = mm_dyn_dpend_run(s, y0b, te, nf, a->t, MM_ODE_DOP853, rtol, yb, &r, err);
    if (rc != MM_OK)
        return rc;
    enum { NPATH = 400 };
    int np = nf < NPATH ? nf : NPATH;
    double L = s->l1 + s->l2, q = mm_dyn_quantum(2 * L);
    mm_shape *pivot = mm_anim_shape(res, "pivot", MM_SHAPE_POLYGON, 1, 3);
    mm_shape *path = mm_anim_shape(res, "path", MM_SHAPE_PATH, 1, np);
    mm_shape *twin = mm_anim_shape(res, "twin", MM_SHAPE_LINE, nf, 3);
    mm_shape *rods = mm_anim_shape(res, "rods", MM_SHAPE_LINE, nf, 3);
    mm_shape *bob1 = mm_anim_shape(res, "bob1", MM_SHAPE_CIRCLE, nf, 1);
    mm_shape *bob2 = mm_anim_shape(res, "bob2", MM_SHAPE_CIRCLE, nf, 1);
    if (!pivot || !path || !twin || !rods || !bob1 || !bob2)
        return MM_ENOMEM;
    pivot->style = "ground";
    const double tri[3][2] = {{0, 0}, {-0.04, 0.05}, {0.04, 0.05}};
    for (int k = 0; k < 3; k++)
        pivot->x[k] = tri[k][0] * L, pivot->y[k] = tri[k][1] * L;
    twin->style = "highlight";
    bob1->radius = 0.04 * L * cbrt(s->m1 / fmax(s->m1, s->m2));
    bob2->radius = 0.04 * L * cbrt(s->m2 / fmax(s->m1, s->m2));
    for (int f = 0; f < nf; f++) {
        double x1, y1, x2, y2;
        mm_dpend_points(s, ya[4 * f], ya[4 * f + 1], &x1, &y1, &x2, &y2);
        rods->x[3 * f] = 0, rods->y[3 * f] = 0, rods->x[3 * f + 1] = x1, rods->y[3 * f + 1] = y1;
        rods->x[3 * f + 2] = x2, rods->y[3 * f + 2] = y2;
        bob1->x[f] = x1, bob1->y[f] = y1, bob2->x[f] = x2, bob2->y[f] = y2;
        if (f < np)
            path->x[f] = x2, path->y[f] = y2;
        mm_dpend_points(s, yb[4 * f], yb[4 * f + 1], &x1, &y1, &x2, &y2);
        twin->x[3 * f] = 0, twin->y[3 * f] = 0, twin->x[3 * f + 1] = x1, twin->y[3 * f + 1] = y1;
        twin->x[3 * f + 2] = x2, twin->y[3 * f + 2] = y2;
    }
    mm_dyn_round_shape(path, q);
    mm_dyn_round_shape(twin, q);
    mm_dyn_round_shape(rods, q);
    mm_dyn_round_shape(bob1, q);
    mm_dyn_round_shape(bob2, q);
    a->bounds[0] = a->bounds[1] = -1.1 * L;
    a->bounds[2] = a->bounds[3] = 1.1 * L;
    return MM_OK;
}

/* ---- dyn-slider-crank: the state and the animation ------------------------------ */

void mm_dyn_sc_state(const mm_sc_model *s, int partition, const double *y, double *q, double *qd)
{
    if (partition) {
        mm_sc_assemble(s, y[0], y[1], q, qd);
    } else {
        for (int j = 0; j < MM_SC_NQ; j++)
            q[j] = y[j], qd[j] = y[MM_SC_NQ + j];
    }
}

int mm_dyn_sc_animate(const mm_sc_model *s, int partition, int ny, double t_end, double wmax, double rtol,
                      double h_max, const double *y0, mm_sc_system *sys, mm_result *res, mm_error *err)
{
    /* 24 frames a turn, over the first 4 turns at most: the turns that follow
     * look the same, and the answer stays small */
    double t_show, per = wmax > 0 ? 2 * M_PI / wmax : 0;
    int nf = mm_scene_frames(fmin(t_end, per > 0 ? 4 * per : t_end), per, &t_show);
    mm_anim *a = mm_res_animation(res, nf, "t", "s");
    double *yf = mm_res_alloc(res, (size_t)nf * (size_t)ny * sizeof *yf);
    if (!a || !yf)
        return MM_ENOMEM;
    mm_dyn_frame_times(a, t_show);
    mm_ode_problem prob = {.n = (size_t)ny, .f = partition ? mm_sc_rhs_reduced : mm_sc_rhs_baumgarte,
                           .params = sys, .t0 = 0, .t_end = t_show > 0 ? t_show : t_end, .y0 = y0};
    mm_ode_options opt = mm_ode_options_adaptive(MM_ODE_DOP853, rtol, rtol, 1000000);
    opt.h_max = h_max;
    mm_ode_result r = {.t_out = a->t, .nout = (size_t)nf, .y_out = yf};
    int rc = mm_ode_run(&prob, &opt, &r, err);
    if (rc != MM_OK)
        return rc;
    double R = s->r, L = s->l, q = mm_dyn_quantum(10 * (R + L));
    mm_shape *guide = mm_anim_shape(res, "guide", MM_SHAPE_LINE, 1, 4);
    mm_shape *fly = mm_anim_shape(res, "flywheel", MM_SHAPE_CIRCLE, 1, 1);
    mm_shape *crank = mm_anim_shape(res, "crank", MM_SHAPE_LINE, nf, 2);
    mm_shape *mark = mm_anim_shape(res, "rim mark", MM_SHAPE_CIRCLE, nf, 1);
    mm_shape *rod = mm_anim_shape(res, "rod", MM_SHAPE_LINE, nf, 2);
    mm_shape *piston = mm_anim_shape(res, "piston", MM_SHAPE_POLYGON, nf, MM_SCENE_BOX_POINTS);
    if (!guide || !fly || !crank || !mark || !rod || !piston)
        return MM_ENOMEM;
    double hp = 0.5 * R, wp = 0.7 * R;                         /* piston height and width */
    guide->style = "ground";
    const double gx[4] = {L - R - 0.5 * wp, L + R + 0.5 * wp, L + R + 0.5 * wp, L - R - 0.5 * wp};
    const double gy[4] = {0.5 * hp, 0.5 * hp, -0.5 * hp, -0.5 * hp};
    for (int k = 0; k < 4; k++)
        guide->x[k] = gx[k], guide->y[k] = gy[k] * 1.15;
    fly->x[0] = fly->y[0] = 0;
    fly->radius = 1.3 * R;
    mark->radius = 0.12 * R;
    for (int f = 0; f < nf; f++) {
        double qq[MM_SC_NQ], qd[MM_SC_NQ];
        mm_dyn_sc_state(s, partition, yf + (size_t)f * (size_t)ny, qq, qd);
        double ax = R * cos(qq[0]), ay = R * sin(qq[0]);
        crank->x[2 * f] = 0, crank->y[2 * f] = 0, crank->x[2 * f + 1] = ax, crank->y[2 * f + 1] = ay;
        mark->x[f] = -1.1 * R * cos(qq[0]), mark->y[f] = -1.1 * R * sin(qq[0]);
        rod->x[2 * f] = ax, rod->y[2 * f] = ay, rod->x[2 * f + 1] = qq[4], rod->y[2 * f + 1] = 0;
        mm_scene_box(piston, f, qq[4], 0, wp, hp, 0);
    }
    mm_dyn_round_shape(guide, q);
    mm_dyn_round_shape(crank, q);
    mm_dyn_round_shape(mark, q);
    mm_dyn_round_shape(rod, q);
    mm_dyn_round_shape(piston, q);
    a->bounds[0] = -1.45 * R, a->bounds[1] = -1.45 * R, a->bounds[2] = L + R + 0.6 * wp, a->bounds[3] = 1.45 * R;
    return MM_OK;
}

/* ---- the animations of dyn-robot-2link and dyn-pendulum --------------------- */

int mm_dyn_plan_animate(const mm_dyn_plan *p, mm_result *res)
{
    double t_show;
    int nf = mm_scene_frames(p->T, p->T / 5, &t_show);
    mm_anim *a = mm_res_animation(res, nf, "t", "s");
    if (!a)
        return MM_ENOMEM;
    mm_dyn_frame_times(a, t_show);
    enum { NP = 161 };
    double reach = p->arm.l1 + p->arm.l2, q = mm_dyn_quantum(2 * reach);
    mm_shape *base = mm_anim_shape(res, "base", MM_SHAPE_POLYGON, 1, 4);
    mm_shape *path = mm_anim_shape(res, "path", MM_SHAPE_PATH, 1, NP);
    mm_shape *arm = mm_anim_shape(res, "arm", MM_SHAPE_LINE, nf, 3);
    mm_shape *elbow = mm_anim_shape(res, "elbow", MM_SHAPE_CIRCLE, nf, 1);
    mm_shape *tip = mm_anim_shape(res, "tip", MM_SHAPE_CIRCLE, nf, 1);
    if (!base || !path || !arm || !elbow || !tip)
        return MM_ENOMEM;
    base->style = "ground";
    mm_scene_box(base, 0, 0, -0.04 * reach, 0.16 * reach, 0.08 * reach, 0);
    path->style = "highlight";
    for (int k = 0; k < NP; k++) {
        double qq[2], qd[2], qdd[2], x[3], y[3];
        mm_dyn_plan_at(p, p->T * k / (NP - 1), qq, qd, qdd);
        mm_robot2_points(&p->arm, qq, x, y);
        path->x[k] = x[2], path->y[k] = y[2];
    }
    elbow->radius = tip->radius = 0.025 * reach;
    for (int f = 0; f < nf; f++) {
        double qq[2], qd[2], qdd[2], x[3], y[3];
        mm_dyn_plan_at(p, a->t[f], qq, qd, qdd);
        mm_robot2_points(&p->arm, qq, x, y);
        for (int k = 0; k < 3; k++)
            arm->x[3 * f + k] = x[k], arm->y[3 * f + k] = y[k];
        elbow->x[f] = x[1], elbow->y[f] = y[1];
        tip->x[f] = x[2], tip->y[f] = y[2];
    }
    mm_dyn_round_shape(path, q);
    mm_dyn_round_shape(arm, q);
    mm_dyn_round_shape(elbow, q);
    mm_dyn_round_shape(tip, q);
    a->bounds[0] = a->bounds[1] = -1.1 * reach;
    a->bounds[2] = a->bounds[3] = 1.1 * reach;
    return MM_OK;
}

int mm_dyn_pend_animate(const mm_pendulum_motion *p, double t_end, int n, const double *t, const double *th,
                        mm_result *res)
{
    double t_show;
    double shortest = isfinite(p->T) ? fmin(p->T, p->T0) : p->T0;
    int nf = mm_scene_frames(t_end, shortest, &t_show);
    mm_anim *a = mm_res_animation(res, nf, "t", "s");
    if (!a)
        return MM_ENOMEM;
    mm_dyn_frame_times(a, t_show);
    /* the path: the bob's positions over the frames' span, at most 360 points */
    int np = 0;
    while (np < n && t[np] <= t_show * (1 + 1e-12))
        np++;
    int stride = np > 360 ? (np + 359) / 360 : 1, npath = (np + stride - 1) / stride;
    mm_shape *pivot = mm_anim_shape(res, "pivot", MM_SHAPE_POLYGON, 1, 3);
    mm_shape *path = mm_anim_shape(res, "path", MM_SHAPE_PATH, 1, npath);
    mm_shape *rod = mm_anim_shape(res, "rod", MM_SHAPE_LINE, nf, 2);
    mm_shape *bob = mm_anim_shape(res, "bob", MM_SHAPE_CIRCLE, nf, 1);
    if (!pivot || !path || !rod || !bob)
        return MM_ENOMEM;
    double L = p->L, q = mm_dyn_quantum(2 * L);
    pivot->style = "ground";
    const double tri[3][2] = {{0, 0}, {-0.06, 0.08}, {0.06, 0.08}};
    for (int k = 0; k < 3; k++)
        pivot->x[k] = tri[k][0] * L, pivot->y[k] = tri[k][1] * L;
    for (int j = 0; j < npath; j++) {
        double a0 = th[j * stride];
        path->x[j] = L * sin(a0), path->y[j] = -L * cos(a0);
    }
    bob->radius = 0.06 * L;
    for (int f = 0; f < nf; f++) {
        double w, a0 = mm_pendulum_exact(p, a->t[f], &w);    /* frames between grid points: the closed form */
        double x = L * sin(a0), y = -L * cos(a0);
        rod->x[2 * f] = 0, rod->y[2 * f] = 0;
        rod->x[2 * f + 1] = x, rod->y[2 * f + 1] = y;
        bob->x[f] = x, bob->y[f] = y;
    }
    mm_dyn_round_shape(path, q);
    mm_dyn_round_shape(rod, q);
    mm_dyn_round_shape(bob, q);
    a->bounds[0] = -1.15 * L, a->bounds[1] = -1.15 * L, a->bounds[2] = 1.15 * L, a->bounds[3] = 1.15 * L;
    return MM_OK;
}

/* ---- dyn-double-pendulum's symplectic run ----------------------------------- */

/* the observer: the energy error at every step, its maximum over each half
 * of the run, and the plotted samples */
typedef struct symp_obs {
    const mm_dpend *s;
    double E0, scale;
    long N, stride;
    double max_first, max_second;
    double rate_first, rate_second;   /* the fastest the motion went in each half, |theta1'| + |theta2'| */
    mm_series *out;
    int k;
} symp_obs;

static int observe(long step, double t, const double *y, void *ctx)
{
    symp_obs *o = ctx;
    double yw[4];
    mm_dpend_to_velocities(o->s, y, yw);
    double e = fabs(mm_dpend_energy(o->s, yw, NULL) - o->E0) / o->scale, rate = fabs(yw[2]) + fabs(yw[3]);
    if (2 * step <= o->N)
        o->max_first = fmax(o->max_first, e), o->rate_first = fmax(o->rate_first, rate);
    else
        o->max_second = fmax(o->max_second, e), o->rate_second = fmax(o->rate_second, rate);
    if (step % o->stride == 0 && o->k < o->out->n) {
        o->out->x[o->k] = t;
        o->out->y[o->k] = fmax(e, DBL_EPSILON);            /* a log axis needs a floor */
        o->k++;
    }
    return 0;
}

int mm_dyn_dpend_symplectic(const mm_dpend *s, const double *y0, double t_end, double h, mm_symp_method m,
                            long max_steps, double E0, double Es, int out, int n, double *max_first,
                            double *max_second, double *faster, mm_result *res, mm_error *err)
{
    double yp0[4], scale[4];
    mm_dpend_to_momenta(s, y0, yp0);
    double pscale = (s->m1 + s->m2) * s->l1 * s->l1 * mm_dyn_dpend_rate(s, y0);
    scale[0] = scale[1] = 1, scale[2] = scale[3] = pscale;
    mm_symp_problem sp = {.n = 4, .f = mm_dpend_rhs_hamilton, .params = (void *)s, .t0 = 0, .t_end = t_end,
                          .y0 = yp0, .scale = scale};
    mm_symp_options so;
    mm_symp_options_init(&so);
    so.method = m;
    so.h = h;
    so.max_steps = max_steps;
    so.max_iter = 200;
    long N = (long)ceil(t_end / h);
    mm_series *ssy = mm_res_series(res, out, (int)fmin(n, N + 1));
    if (!ssy)
        return MM_ENOMEM;
    symp_obs ob = {.s = s, .E0 = E0, .scale = Es, .N = N, .stride = (N + ssy->n - 2) / (ssy->n - 1), .out = ssy};
    if (ob.stride < 1)
        ob.stride = 1;
    mm_symp_work *sw = mm_symp_work_alloc(4);
    mm_symp_result sres;
    int rc = mm_symp_solve(&sp, &so, sw, observe, &ob, NULL, &sres, err);
    mm_symp_work_free(sw);
    if (rc != MM_OK)
        return rc;
    ssy->n = ob.k;
    mm_res_method_stat(res, "symplectic_h", sres.h);
    mm_res_method_stat(res, "symplectic_steps", (double)sres.n_steps);
    mm_res_method_stat(res, "symplectic_evaluations", (double)sres.n_eval);
    mm_res_method_stat(res, "symplectic_iterations_mean", sres.iter_mean);
    *max_first = ob.max_first;
    *max_second = ob.max_second;
    *faster = ob.rate_first > 0 ? ob.rate_second / ob.rate_first : 1;
    return MM_OK;
}

double mm_dyn_dpend_separation(const double *ya, const double *yb, int n, const double *x, double wf, double d0,
                               double *d, double *plot)
{
    double t_h = -1;
    for (int i = 0; i < n; i++) {
        d[i] = mm_dyn_dpend_distance(ya + 4 * i, yb + 4 * i, wf);
        plot[i] = fmax(d[i], DBL_EPSILON * d0);
        if (t_h < 0 && d[i] > 1e-3 && i == 0)
            t_h = x[0];                 /* apart by more already at the start: no point before it to read */
        else if (t_h < 0 && d[i] > 1e-3) {
            double dp = mm_dyn_dpend_distance(ya + 4 * (i - 1), yb + 4 * (i - 1), wf);
            /* log-linear interpolation between the two grid points */
            t_h = x[i - 1] + (x[i] - x[i - 1]) * log(1e-3 / dp) / log(d[i] / dp);
        }
    }
    return t_h;
}

/* ---- dyn-slider-crank: the reference runs and the comparison with them ----------- */

int mm_dyn_sc_reference_runs(mm_sc_system *sys, double w0, double t_end, int n, const double *x,
                             const mm_ode_options *opt, const mm_ode_result *r, double **yref, double **yalt,
                             double *tol_ref, mm_result *res, mm_error *err)
{
    double *yr = mm_res_alloc(res, (size_t)n * 2 * sizeof *yr), *ya = mm_res_alloc(res, (size_t)n * 2 * sizeof *ya);
    if (!yr || !ya)
        return MM_ENOMEM;
    double y0r[2] = {0, w0};
    mm_ode_problem pr = {.n = 2, .f = mm_sc_rhs_reduced, .params = sys, .t0 = 0, .t_end = t_end, .y0 = y0r};
    mm_ode_options orf = *opt;
    orf.rtol = orf.atol = fmax(1e-13, fmin(1e-12, 1e-3 * opt->rtol));   /* DOP853 struggles below 1e-13 */
    /* and at most half the run's largest step: a short run (t_end 0.009
     * s, 0.185 rad of the crank) was one step for the run, the reference
     * and the third alike, each accepted on an estimate below 1e-12 while
     * the step erred 2.4e-12 rad in the crank angle (mpmath): the three
     * agreed, and revolutions was printed with 1/13 of its error.  Half the
     * step errs ~2^-8 as much (DOP853), so the distance from the reference
     * measures the run's own error; a reference at 1000 times the run's
     * tolerance takes such steps anyway (1000^(1/8) = 2.4 times shorter) */
    if (r->h_largest > 0)
        orf.h_max = opt->h_max > 0 ? fmin(opt->h_max, 0.5 * r->h_largest) : 0.5 * r->h_largest;
    mm_ode_result rref = {.t_out = x, .nout = (size_t)n, .y_out = yr};
    int rc = mm_ode_run(&pr, &orf, &rref, err);
    if (rc != MM_OK)
        return rc;
    mm_ode_options oalt = *opt;
    oalt.rtol = oalt.atol = 0.5 * opt->rtol;
    /* the run at half the tolerance needs about 1.1 times the run's steps
     * (DOP853: rtol^(1/8)); the budget ends a run that went astray before
     * it costs seconds (its failure is not the answer's) */
    oalt.max_steps = 4 * (r->n_accepted + r->n_rejected) + 1000;
    mm_ode_result ralt = {.t_out = x, .nout = (size_t)n, .y_out = ya};
    mm_error ealt = {0};
    rc = mm_ode_run(&pr, &oalt, &ralt, &ealt);
    if (rc == MM_ENOMEM || rc == MM_EINTERNAL)
        return rc;
    if (rc != MM_OK)                        /* no second sample: the reference's stands for it */
        for (int i = 0; i < 2 * n; i++)
            ya[i] = yr[i];
    *yref = yr;
    *yalt = ya;
    *tol_ref = orf.rtol * (double)rref.n_accepted;
    return MM_OK;
}

int mm_dyn_sc_compare(const mm_sc_model *s, int partition, int ny, int n, const double *y, const double *yref,
                      const double *yalt, double tol_ref, const double *fa, const double *fb, const double *N,
                      double *absn, mm_dyn_sc_cmp *c, mm_error *err)
{
    *c = (mm_dyn_sc_cmp){0};
    for (int i = 0; i < n; i++) {
        double q[MM_SC_NQ], qd[MM_SC_NQ], qdd[MM_SC_NQ], lam[MM_SC_NC];
        double qa[MM_SC_NQ], qda[MM_SC_NQ], qdda[MM_SC_NQ], la[MM_SC_NC];
        mm_sc_assemble(s, yref[2 * i], yref[2 * i + 1], q, qd);
        if (mm_sc_accel(s, q, qd, 0, 0, qdd, lam) != MM_OK)
            return mm_error_set(err, MM_ESINGULAR, "l", "the constraints became dependent: the rod stood vertical");
        c->ra = fmax(c->ra, hypot(lam[0], lam[1])), c->rb = fmax(c->rb, hypot(lam[2], lam[3]));
        c->rn = fmax(c->rn, fabs(lam[3]));
        mm_sc_assemble(s, yalt[2 * i], yalt[2 * i + 1], qa, qda);
        if (mm_sc_accel(s, qa, qda, 0, 0, qdda, la) != MM_OK)
            return mm_error_set(err, MM_ESINGULAR, "l", "the constraints became dependent: the rod stood vertical");
        double fr = hypot(lam[0], lam[1]), br = hypot(lam[2], lam[3]);
        c->aa = fmax(c->aa, fmax(fabs(fa[i] - fr), 2 * fabs(hypot(la[0], la[1]) - fr)));
        c->ab = fmax(c->ab, fmax(fabs(fb[i] - br), 2 * fabs(hypot(la[2], la[3]) - br)));
        c->an = fmax(c->an, fmax(fabs(fabs(N[i]) - fabs(lam[3])), 2 * fabs(fabs(la[3]) - fabs(lam[3]))));
        double qm[MM_SC_NQ], qdm[MM_SC_NQ], bJ;
        mm_dyn_sc_state(s, partition, y + (size_t)i * (size_t)ny, qm, qdm);
        c->eb = fmax(c->eb, mm_dyn_sc_energy_bound(s, qm, qdm, q, qd, tol_ref, &bJ));
        c->ebJ = fmax(c->ebJ, bJ);
        absn[i] = fabs(N[i]);
        if (fa[i] > fa[c->ia])
            c->ia = i;
        if (fb[i] > fb[c->ib])
            c->ib = i;
        if (absn[i] > absn[c->in])
            c->in = i;
    }
    return MM_OK;
}

/* ---- dyn-robot-2link: the work of the motors and the arm's amplification ------- */

double mm_dyn_plan_work(const mm_dyn_plan *p, double *wabs)
{
    const double *gx = mm_quad_gl5_node, *gw = mm_quad_gl5_weight;
    double work = 0;
    *wabs = 0;
    for (int k = 0; k < 64; k++) {
        double a = p->T * k / 64, b = p->T * (k + 1) / 64;
        for (int i = 0; i < 5; i++) {
            double t = 0.5 * (a + b) + 0.5 * (b - a) * gx[i], q[2], qd[2], qdd[2], tau[2];
            mm_dyn_plan_at(p, t, q, qd, qdd);
            mm_robot2_inverse(&p->arm, q, qd, qdd, tau);
            double pw = tau[0] * qd[0] + tau[1] * qd[1];
            work += 0.5 * (b - a) * gw[i] * pw;
            *wabs += 0.5 * (b - a) * gw[i] * (fabs(tau[0] * qd[0]) + fabs(tau[1] * qd[1]));
        }
    }
    return work;
}

/* How much the open-loop arm amplifies small errors over the move: the
 * largest norm ||Phi(t)||_inf (max row sum) of the fundamental matrix on a
 * grid of 33 times (an estimate: an error made at t0 > 0 grows by
 * Phi(t) Phi(t0)^-1, which is smaller while errors only grow). */
int mm_dyn_plan_amplification(const mm_dyn_plan *p, mm_result *res, double *A, mm_error *err)
{
    enum { NA = 33 };
    double t[NA], y0[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    double *y = mm_res_alloc(res, NA * 16 * sizeof *y);
    if (!y)
        return MM_ENOMEM;
    mm_linspace(0, p->T, NA, t);
    mm_dyn_plan pp = *p;
    pp.t_left = 1;                                        /* no divergence test here */
    mm_ode_problem prob = {.n = 16, .f = mm_dyn_plan_variational_rhs, .params = &pp, .t0 = 0, .t_end = p->T,
                           .y0 = y0};
    mm_ode_options opt = mm_ode_options_adaptive(MM_ODE_DOP853, 1e-6, 1e-6, 100000);
    mm_ode_result r = {.t_out = t, .nout = NA, .y_out = y};
    int rc = mm_ode_run(&prob, &opt, &r, err);
    if (rc != MM_OK)
        return rc;
    *A = 1;
    for (int k = 0; k < NA; k++)
        for (int i = 0; i < 4; i++) {
            double row = 0;
            for (int j = 0; j < 4; j++)
                row += fabs(y[16 * k + 4 * i + j]);
            *A = fmax(*A, row);
        }
    return MM_OK;
}

/* q2(t) - 0 for Brent */
static int q2_of(double t, double *f, void *ctx)
{
    const mm_dyn_plan *p = ctx;
    double q[2], qd[2], qdd[2];
    mm_dyn_plan_at(p, t, q, qd, qdd);
    *f = q[1];
    return 0;
}

int mm_dyn_plan_stretched(const mm_dyn_plan *p, double *t_s, double *err_ts, mm_error *err)
{
    double qa = p->q0[1], qb = p->q0[1] + p->dq[1], fx, width;
    *t_s = 0, *err_ts = 0;
    if (qa == 0 || qb == 0) {
        *t_s = qa == 0 ? 0 : p->T;
        return MM_OK;
    }
    int iter = 0;
    int rc = mm_roots_brent(q2_of, (void *)p, 0, p->T, qa, qb, 1e-14 * p->T, 200, t_s, &fx, &width, &iter, NULL,
                            err);
    if (rc != MM_OK)
        return rc;
    /* an exact zero of the computed q2(t) ends Brent early: then the root is
     * off by the rounding of q2 over its speed there */
    double q[2], qd[2], qdd[2];
    mm_dyn_plan_at(p, *t_s, q, qd, qdd);
    double e = fx == 0 ? 4 * DBL_EPSILON * (fabs(qa) + fabs(qb)) / fabs(qd[1]) : width;
    *err_ts = e + 1e-14 * p->T;
    return MM_OK;
}

/* ---- dyn-pendulum: the period measured, and against the amplitude --------------- */

/* The period measured from the integration, where it is well conditioned:
 * the times of two successive passages through the bottom (theta = 0 mod
 * 2 pi, where |theta'| is largest), each located by one Newton step from
 * the integrated state at the closed form's prediction.  Half a period
 * apart for a swing, a whole one for a turn over the top. */
int mm_dyn_pend_measure_period(const mm_pendulum_motion *p, mm_ode_rhs f, double rtol, double h_max, mm_result *res,
                               double *Tm, double *dE, mm_error *err)
{
    double K = mm_elliptic_Kc(p->kc), ta, tb, target_a, target_b, half;
    if (p->motion == MM_PENDULUM_SWING) {
        ta = (2 * K - p->u0) / p->wn;               /* u = 2K: sn = 0 */
        half = 2 * K / p->wn;                       /* T/2 */
        target_a = target_b = 0;
    } else {
        double v = p->kk * p->wn;                   /* v = sg kk wn t + u0 = 2K j */
        ta = p->sg > 0 ? (2 * K - p->u0) / v : p->u0 / v;
        half = 2 * K / v;                           /* T */
        target_a = p->sg > 0 ? 2 * M_PI : 0;
        target_b = target_a + 2 * M_PI * p->sg;
    }
    tb = ta + half;
    double y0[2] = {p->theta0, p->omega0}, tt[2] = {ta, tb}, x[2], v[2];
    mm_ode_result r;
    int rc = mm_ex_ode_grid(2, f, (void *)p, y0, tb, 2, tt, rtol, rtol, h_max, x, v, &r, res, err);
    if (rc != MM_OK)
        return rc;
    double ca = ta - (x[0] - target_a) / v[0], cb = tb - (x[1] - target_b) / v[1];
    *Tm = (cb - ca) * (p->motion == MM_PENDULUM_SWING ? 2 : 1);
    double E0 = mm_pendulum_energy(p, p->theta0, p->omega0);
    *dE = fmax(fabs(mm_pendulum_energy(p, x[0], v[0]) - E0), fabs(mm_pendulum_energy(p, x[1], v[1]) - E0));
    return MM_OK;
}

int mm_dyn_pend_period_curve(mm_result *res, int curve, int series)
{
    enum { NC = 200 };
    mm_series *sc = mm_res_series(res, curve, NC), *ss = mm_res_series(res, series, NC);
    if (!sc || !ss)
        return MM_ENOMEM;
    for (int i = 0; i < NC; i++) {
        double a0 = 3.1 * i / (NC - 1);          /* up to 3.1 rad: the ratio is 4.5 there */
        sc->x[i] = ss->x[i] = a0;
        sc->y[i] = mm_pendulum_period_ratio(a0);
        ss->y[i] = 1 + a0 * a0 / 16;
    }
    return MM_OK;
}

/* ---- dyn-double-pendulum's reference run ---------------------------------------- */

/* The watch over the reference's own steps: mm_ode calls an event function
 * at the end of every accepted step (and only there while it never changes
 * sign), so a g that stays 1 is an observer. */
typedef struct ref_watch {
    mm_dpend s;             /* first: mm_dpend_rhs_lagrange reads it as its params */
    double E0, Es, rtol, drift, allow;
} ref_watch;

static int watch_step(double t, const double *y, double *g, void *p)
{
    (void)t;
    ref_watch *w = p;
    w->drift = fmax(w->drift, fabs(mm_dpend_energy(&w->s, y, NULL) - w->E0) / w->Es);
    w->allow = fmax(w->allow, mm_dpend_energy_allowance(&w->s, y, w->rtol) / w->Es);   /* eq. (7) */
    *g = 1;
    return 0;
}

int mm_dyn_dpend_reference(const mm_dpend *s, const double *y0, double t_end, double rtol, int n, const double *t,
                           double E0, double Es, double *y, mm_ode_result *r, double *drift, double *allow,
                           mm_error *err)
{
    *r = (mm_ode_result){.t_out = t, .nout = (size_t)n, .y_out = y};
    ref_watch watch = {.s = *s, .E0 = E0, .Es = Es, .rtol = rtol};
    mm_ode_problem pref = {.n = 4, .f = mm_dpend_rhs_lagrange, .params = &watch, .t0 = 0, .t_end = t_end,
                           .y0 = y0, .event = watch_step};
    mm_ode_options oref = mm_ode_options_adaptive(MM_ODE_DOP853, rtol, rtol, 2000000);
    int rc = mm_ode_run(&pref, &oref, r, err);
    *drift = watch.drift;
    *allow = watch.allow;
    return rc;
}
