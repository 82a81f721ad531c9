/* mm_mech.c — constraint kinematics (see mm_mech.h). */
#include "mm_mech.h"

#include <assert.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mm_linalg.h"

struct mm_mech_work {
    int n, m;
    double *J, *F, *d;            /* Phi_q (m x n), Phi or a right side (m), a solution (n) */
    double *LU, *inv;             /* tiny square systems: factors and inverse (n x n) */
    int *piv;
    double *qa, *qb, *qc, *qp;    /* sweep: history and predictor (n each) */
    double *va, *vb;              /* sweep: velocities (n each) */
};

void mm_mech_options_init(mm_mech_options *opt)
{
    *opt = (mm_mech_options){.length = 1, .xtol = 1e-12, .max_iter = 60, .max_step = 0.5,
                             .sing_rcond = 1e-13};
}

int mm_mech_check(const mm_mech_problem *p, const mm_mech_options *opt, mm_error *err)
{
    if (p->n < 1 || p->n > MM_MECH_MAX_N)
        return mm_error_set(err, MM_ERANGE, "n", "coordinates must number 1 to %d; got %d", MM_MECH_MAX_N, p->n);
    if (p->m < p->n || p->m > MM_MECH_MAX_M)
        return mm_error_set(err, MM_ERANGE, "m", "constraint equations must number n = %d to %d; got %d",
                            p->n, MM_MECH_MAX_M, p->m);
    if (!p->phi || !p->jac)
        return mm_error_set(err, MM_EVALUE, "phi", "the constraints and their Jacobian are required");
    if (!(opt->length > 0) || !isfinite(opt->length) || !(opt->xtol > 0) || opt->max_iter < 1 ||
        !(opt->max_step > 0) || !(opt->sing_rcond >= 0))
        return mm_error_set(err, MM_EVALUE, "options", "length, xtol, max_step must be > 0 and max_iter >= 1");
    return MM_OK;
}

mm_mech_work *mm_mech_work_alloc(int n, int m)
{
    if (n < 1 || n > MM_MECH_MAX_N || m < 1 || m > MM_MECH_MAX_M)
        return NULL;
    mm_mech_work *w = calloc(1, sizeof *w);
    if (!w)
        return NULL;
    size_t N = (size_t)n, M = (size_t)m;
    w->n = n, w->m = m;
    w->J = malloc(M * N * sizeof *w->J);
    w->F = malloc(M * sizeof *w->F);
    w->d = malloc((M > N ? M : N) * sizeof *w->d);   /* room for a least-squares right side */
    w->LU = malloc(N * N * sizeof *w->LU);
    w->inv = malloc(N * N * sizeof *w->inv);
    w->piv = malloc(N * sizeof *w->piv);
    w->qa = malloc(6 * N * sizeof *w->qa);
    if (!w->J || !w->F || !w->d || !w->LU || !w->inv || !w->piv || !w->qa) {
        mm_mech_work_free(w);
        return NULL;
    }
    w->qb = w->qa + N, w->qc = w->qb + N, w->qp = w->qc + N, w->va = w->qp + N, w->vb = w->va + N;
    return w;
}

void mm_mech_work_free(mm_mech_work *w)
{
    if (!w)
        return;
    free(w->J);
    free(w->F);
    free(w->d);
    free(w->LU);
    free(w->inv);
    free(w->piv);
    free(w->qa);
    free(w);
}

/* |v|_w: lengths divided by opt->length, angles as they are */
static double wnorm(const mm_mech_problem *p, const mm_mech_options *o, const double *v)
{
    double s = 0;
    for (int i = 0; i < p->n; i++)
        s = fmax(s, fabs(v[i]) / (p->is_length && p->is_length[i] ? o->length : 1));
    return s;
}

static double wdist(const mm_mech_problem *p, const mm_mech_options *o, const double *a, const double *b)
{
    double s = 0;
    for (int i = 0; i < p->n; i++)
        s = fmax(s, fabs(a[i] - b[i]) / (p->is_length && p->is_length[i] ? o->length : 1));
    return s;
}

static int all_finite(const double *v, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return 0;
    return 1;
}

static int callback_failed(int rc, const char *what, mm_error *err)
{
    if (rc >= MM_EVALUE && rc < MM_STATUS_COUNT)
        return err && err->code == rc ? rc : mm_error_set(err, rc, "q", "the %s could not be evaluated", what);
    return mm_error_set(err, MM_EVALUE, "q", "the %s could not be evaluated", what);
}

/* ---- the linear solves -------------------------------------------------------------- */

/* LU with partial pivoting of the n x n A into w->LU; det into *det.
 * Returns 0 when a pivot is exactly zero. */
static int lu_factor(mm_mech_work *w, const double *A, double *det)
{
    int n = w->n;
    double *L = w->LU;
    memcpy(L, A, (size_t)n * (size_t)n * sizeof *L);
    double dt = 1;
    for (int k = 0; k < n; k++) {
        int r = k;
        for (int i = k + 1; i < n; i++)
            if (fabs(L[i * n + k]) > fabs(L[r * n + k]))
                r = i;
        w->piv[k] = r;
        if (r != k) {
            for (int j = 0; j < n; j++) {
                double x = L[k * n + j];
                L[k * n + j] = L[r * n + j];
                L[r * n + j] = x;
            }
            dt = -dt;
        }
        double pv = L[k * n + k];
        dt *= pv;
        if (pv == 0) {
            *det = 0;
            return 0;
        }
        for (int i = k + 1; i < n; i++) {
            double f = L[i * n + k] /= pv;
            for (int j = k + 1; j < n; j++)
                L[i * n + j] -= f * L[k * n + j];
        }
    }
    *det = dt;
    return 1;
}

static void lu_solve(const mm_mech_work *w, double *x)
{
    int n = w->n;
    const double *L = w->LU;
    for (int k = 0; k < n; k++) {              /* whole rows were swapped: P b first */
        int r = w->piv[k];
        double t = x[k];
        x[k] = x[r];
        x[r] = t;
    }
    for (int k = 0; k < n; k++)
        for (int i = k + 1; i < n; i++)
            x[i] -= L[i * n + k] * x[k];
    for (int i = n - 1; i >= 0; i--) {
        for (int j = i + 1; j < n; j++)
            x[i] -= L[i * n + j] * x[j];
        x[i] /= L[i * n + i];
    }
}

/* 1 / (|A|_1 |A^-1|_1), from the inverse (tiny systems only); the
 * weighted infinity norm max_i w_i sum_j |A^-1_ij| into *inv, so that
 * |A^-1 b|_w <= *inv |b|_inf */
static double lu_rcond(const mm_mech_problem *p, const mm_mech_options *o, mm_mech_work *w, const double *A,
                       double *inv)
{
    int n = w->n;
    double na = 0, ni = 0, rows[MM_MECH_TINY] = {0};
    for (int j = 0; j < n; j++) {
        double *col = w->inv + (size_t)j * (size_t)n;   /* column j of A^-1, stored as a row */
        for (int i = 0; i < n; i++)
            col[i] = i == j;
        lu_solve(w, col);
        double sa = 0, si = 0;
        for (int i = 0; i < n; i++) {
            sa += fabs(A[i * n + j]);
            si += fabs(col[i]);
            rows[i] += fabs(col[i]);
        }
        na = fmax(na, sa);
        ni = fmax(ni, si);
    }
    *inv = 0;
    for (int i = 0; i < n; i++)
        *inv = fmax(*inv, rows[i] / (p->is_length && p->is_length[i] ? o->length : 1));
    double r = 1 / (na * ni);
    return isfinite(r) ? r : 0;
}

/* |A|_1 of the m x n row-major A */
static double norm1(const double *A, int m, int n)
{
    double best = 0;
    for (int j = 0; j < n; j++) {
        double s = 0;
        for (int i = 0; i < m; i++)
            s += fabs(A[i * n + j]);
        best = fmax(best, s);
    }
    return best;
}

/* the largest weight of the norm: converts an unweighted bound to |.|_w */
static double wmax(const mm_mech_problem *p, const mm_mech_options *o)
{
    for (int i = 0; p->is_length && i < p->n; i++)
        if (p->is_length[i] && o->length < 1)
            return 1 / o->length;
    return 1;
}

/* Solve Phi_q x = rhs (m values) into x (n values), Phi_q in w->J.  With
 * lstsq = 1 a singular square system gets the minimum-norm least-squares
 * solution instead of a failure.  info gets rcond, det, rank. */
static int jsolve(const mm_mech_problem *p, const mm_mech_options *o, mm_mech_work *w, const double *rhs,
                  double *x, int lstsq, mm_mech_info *info, mm_error *err)
{
    int n = p->n, m = p->m;
    info->det = 0;
    info->rank = n;
    if (m == n && n <= MM_MECH_TINY) {
        double det;
        int ok = lu_factor(w, w->J, &det);
        info->det = det;
        info->rcond = ok ? lu_rcond(p, o, w, w->J, &info->inv_norm) : 0;
        if (ok && info->rcond >= o->sing_rcond) {
            memcpy(x, rhs, (size_t)n * sizeof *x);
            lu_solve(w, x);
            return MM_OK;
        }
    } else if (m == n) {
        mm_linalg_solve_info li;
        int rc = mm_linalg_solve(n, 1, w->J, rhs, x, &li, err);
        info->rcond = li.rcond;
        info->inv_norm = n * wmax(p, o) / fmax(li.rcond * norm1(w->J, m, n), DBL_MIN);
        if (rc == MM_OK && li.rcond >= o->sing_rcond)
            return MM_OK;
        if (rc != MM_OK && rc != MM_ESINGULAR)
            return rc;
    }
    /* singular or non-square: least squares, minimum norm */
    double sv[MM_MECH_MAX_N];
    int rank;
    int rc = mm_linalg_lstsq(m, n, 1, w->J, rhs, 0, x, &rank, NULL, sv, err);
    if (rc != MM_OK)
        return rc;
    info->rank = rank;
    info->rcond = sv[0] > 0 ? sv[n - 1] / sv[0] : 0;
    info->inv_norm = wmax(p, o) * sqrt((double)m) / fmax(sv[n - 1], DBL_MIN);
    if (!lstsq && (rank < n || info->rcond < o->sing_rcond))
        return mm_error_set(err, MM_ESINGULAR, "q",
                            "the constraint Jacobian is singular here (rank %d of %d): a toggle or "
                            "change point, where the driver cannot set the motion", rank, n);
    return MM_OK;
}

/* ---- positions, velocities, accelerations ------------------------------------------- */

int mm_mech_position(const mm_mech_problem *p, const mm_mech_options *o, mm_mech_work *w,
                     double t, double *q, mm_mech_info *info, mm_error *err)
{
    assert(w && w->n == p->n && w->m == p->m);
    mm_mech_info loc;
    if (!info)
        info = &loc;
    *info = (mm_mech_info){0};
    int n = p->n, m = p->m, rc;
    double prev = INFINITY, s = INFINITY;
    for (int it = 1; it <= o->max_iter; it++) {
        if ((rc = p->phi(q, t, w->F, p->params)) != 0)
            return callback_failed(rc, "constraint equations", err);
        if ((rc = p->jac(q, t, w->J, p->params)) != 0)
            return callback_failed(rc, "constraint Jacobian", err);
        if (!all_finite(w->F, m) || !all_finite(w->J, m * n))
            return mm_error_set(err, MM_ENONFINITE, "q", "the constraints are not finite at this position");
        rc = jsolve(p, o, w, w->F, w->d, 1, info, err);
        if (rc != MM_OK)
            return rc;
        s = wnorm(p, o, w->d);
        double cut = s > o->max_step ? o->max_step / s : 1;
        for (int i = 0; i < n; i++)
            q[i] -= cut * w->d[i];                       /* q <- q - Phi_q^-1 Phi */
        info->iterations = it;
        info->step = s;
        /* near a toggle the rounding of Phi moves q by about eps / rcond:
         * no step can be smaller, so that is the tolerance there */
        double floor_ = 8 * DBL_EPSILON * (wnorm(p, o, q) + 1) / fmax(info->rcond, DBL_EPSILON);
        if (s <= fmax(o->xtol, floor_)) {
            if ((rc = p->phi(q, t, w->F, p->params)) != 0)
                return callback_failed(rc, "constraint equations", err);
            double res = 0;
            for (int i = 0; i < m; i++)
                res = fmax(res, fabs(w->F[i]));
            info->residual = res;
            /* the geometric tail of the steps, and what Phi's rounding allows */
            double r = s / prev, scale = o->phi_scale > 0 ? o->phi_scale : o->length;
            info->err_est = (r < 1 ? s * r / (1 - r) : s) +
                            (res + 4 * DBL_EPSILON * scale) * fmin(info->inv_norm, 1 / DBL_MIN);
            return all_finite(q, n) ? MM_OK
                                    : mm_error_set(err, MM_ENONFINITE, "q", "the position is not finite");
        }
        prev = s;
    }
    return mm_error_set(err, MM_ENOCONV, "q",
                        "Newton did not converge in %d iterations (last step %.3g): the mechanism "
                        "cannot be assembled near this guess", o->max_iter, s);
}

int mm_mech_velocity(const mm_mech_problem *p, const mm_mech_options *o, mm_mech_work *w,
                     double t, const double *q, double *qd, mm_mech_info *info, mm_error *err)
{
    mm_mech_info loc;
    if (!info)
        info = &loc;
    *info = (mm_mech_info){0};
    int rc;
    if ((rc = p->jac(q, t, w->J, p->params)) != 0)
        return callback_failed(rc, "constraint Jacobian", err);
    if (p->nu) {
        if ((rc = p->nu(q, t, w->F, p->params)) != 0)
            return callback_failed(rc, "velocity right side", err);
    } else {
        memset(w->F, 0, (size_t)p->m * sizeof *w->F);
    }
    rc = jsolve(p, o, w, w->F, qd, 0, info, err);
    if (rc == MM_OK && !all_finite(qd, p->n))
        rc = mm_error_set(err, MM_ENONFINITE, "q", "the velocities are not finite");
    return rc;
}

int mm_mech_acceleration(const mm_mech_problem *p, const mm_mech_options *o, mm_mech_work *w,
                         double t, const double *q, const double *qd, double *qdd, mm_mech_info *info,
                         mm_error *err)
{
    mm_mech_info loc;
    if (!info)
        info = &loc;
    *info = (mm_mech_info){0};
    assert(p->gamma);
    int rc;
    if ((rc = p->jac(q, t, w->J, p->params)) != 0)
        return callback_failed(rc, "constraint Jacobian", err);
    if ((rc = p->gamma(q, qd, t, w->F, p->params)) != 0)
        return callback_failed(rc, "acceleration right side", err);
    rc = jsolve(p, o, w, w->F, qdd, 0, info, err);
    if (rc == MM_OK && !all_finite(qdd, p->n))
        rc = mm_error_set(err, MM_ENONFINITE, "q", "the accelerations are not finite");
    return rc;
}

int mm_mech_rank(const mm_mech_problem *p, mm_mech_work *w, double t, const double *q, double tol,
                 double *sv, int *rank, mm_error *err)
{
    double s[MM_MECH_MAX_N];
    assert(w && w->n == p->n && w->m == p->m);
    int rc = p->jac(q, t, w->J, p->params);
    if (rc != 0)
        return callback_failed(rc, "constraint Jacobian", err);
    int k = p->m < p->n ? p->m : p->n;
    if ((rc = mm_linalg_svdvals(p->m, p->n, w->J, s, err)) != MM_OK)
        return rc;
    if (!(tol > 0))
        tol = (p->m > p->n ? p->m : p->n) * DBL_EPSILON;
    int r = 0;
    for (int i = 0; i < k; i++)
        r += s[i] > tol * s[0];
    *rank = r;
    if (sv)
        memcpy(sv, s, (size_t)k * sizeof *sv);
    return MM_OK;
}

/* ---- the sweep ---------------------------------------------------------------------- */

typedef struct sweep_ctx {
    const mm_mech_problem *p;
    const mm_mech_options *o;
    mm_mech_work *w;
    mm_mech_sweep *s;
    mm_error *err;
    double tau;                      /* the smallest step in t */
    double range;                    /* |t_last - t_first| */
    double cross;                    /* the longest step accepted across a sign change of det */
} sweep_ctx;

/* Newton at t from the predictor qp into q; 1 if it converged (0 if not),
 * or -code for a hard failure (a callback). */
static int corrector(sweep_ctx *c, double t, const double *qp, double *q, mm_mech_info *info)
{
    memcpy(q, qp, (size_t)c->p->n * sizeof *q);
    mm_error e;
    int rc = mm_mech_position(c->p, c->o, c->w, t, q, info, &e);
    c->s->newton += info->iterations;
    if (rc == MM_OK)
        return 1;
    if (rc == MM_ENOCONV || rc == MM_ENONFINITE || rc == MM_ESINGULAR)
        return 0;
    if (c->err)
        *c->err = e;
    return -rc;
}

/* det Phi_q at a solved q (0 when not available) */
static double det_at(sweep_ctx *c, double t, const double *q)
{
    const mm_mech_problem *p = c->p;
    if (p->m != p->n || p->n > MM_MECH_TINY || p->jac(q, t, c->w->J, p->params) != 0)
        return 0;
    double det;
    lu_factor(c->w, c->w->J, &det);
    return det;
}

/* q'_watch at a solved q (0 when it cannot be solved) */
static double watch_at(sweep_ctx *c, double t, const double *q)
{
    double v[MM_MECH_MAX_N];
    mm_mech_info info;
    if (c->s->watch < 0 || !c->p->nu || mm_mech_velocity(c->p, c->o, c->w, t, q, v, &info, NULL) != MM_OK)
        return 0;
    return v[c->s->watch];
}

/* Bisect [ta, tb] (solutions qa, qb) for the sign change of det (kind 0)
 * or of q'_watch (kind 1); the place into *tz, q_watch there into *qz.
 * Each midpoint is corrected from the interpolation of its neighbours; for
 * det it is kept only if it stays near it (where branches cross, Newton
 * could land on the other one); when it does not, the secant of g ends the
 * search.  A turning point is no singular point: no such guard there. */
static int locate(sweep_ctx *c, int kind, double ta, const double *qa, double ga, double tb,
                  const double *qb, double gb, double *tz, double *qz, int *jumped)
{
    int n = c->p->n;
    double A[MM_MECH_MAX_N], B[MM_MECH_MAX_N], M[MM_MECH_MAX_N], P[MM_MECH_MAX_N];
    memcpy(A, qa, (size_t)n * sizeof *A);
    memcpy(B, qb, (size_t)n * sizeof *B);
    mm_mech_info info;
    /* det near a change point: the positions there carry eps / |t - t*|
     * of rounding, so det's sign is reliable only down to about sqrt(eps):
     * bisect to 1e-5 of the range, then a parabola through three values */
    double stop = kind == 0 ? fmax(c->tau, 1e-5 * c->range) : c->tau, tm = 0, gm = 0;
    int have_m = 0;
    for (int it = 0; it < 200 && fabs(tb - ta) > stop; it++) {
        tm = 0.5 * (ta + tb);
        for (int i = 0; i < n; i++)
            P[i] = 0.5 * (A[i] + B[i]);
        int ok = corrector(c, tm, P, M, &info);
        if (ok < 0)
            return -ok;
        if (!ok)
            break;
        if (kind == 0 && wdist(c->p, c->o, M, P) > 0.3 * wdist(c->p, c->o, A, B) + 1e3 * c->o->xtol) {
            if (jumped)
                *jumped = 1;
            break;
        }
        double g = kind == 0 ? det_at(c, tm, M) : watch_at(c, tm, M);
        if (g == 0) {
            ta = tb = tm;
            memcpy(A, M, (size_t)n * sizeof *A);
            memcpy(B, M, (size_t)n * sizeof *B);
            break;
        }
        if ((g > 0) == (ga > 0)) {
            ta = tm, ga = g;
            memcpy(A, M, (size_t)n * sizeof *A);
        } else {
            tb = tm, gb = g;
            memcpy(B, M, (size_t)n * sizeof *B);
        }
    }
    double f = ta == tb || ga == gb ? 0.5 : ga / (ga - gb);   /* the secant's zero */
    *tz = ta + f * (tb - ta);
    if (kind == 0 && tb != ta) {                               /* the parabola's zero */
        tm = 0.5 * (ta + tb);
        for (int i = 0; i < n; i++)
            P[i] = 0.5 * (A[i] + B[i]);
        if (corrector(c, tm, P, M, &info) == 1) {
            gm = det_at(c, tm, M);
            have_m = 1;
        }
        if (have_m) {
            /* g(u) on u in [-1, 1]: ga at -1, gm at 0, gb at 1 */
            double q2 = 0.5 * (ga + gb) - gm, q1 = 0.5 * (gb - ga), q0 = gm, u;
            double disc = q1 * q1 - 4 * q2 * q0;
            if (q2 == 0 || disc < 0)
                u = -q0 / q1;
            else {
                double r = -0.5 * (q1 + copysign(sqrt(disc), q1));   /* stable roots */
                double u1 = r / q2, u2 = q0 / r;
                u = fabs(u1) <= fabs(u2) ? u1 : u2;
            }
            if (fabs(u) <= 1)
                *tz = tm + u * 0.5 * (tb - ta);
        }
    }
    if (qz && c->s->watch >= 0)
        *qz = A[c->s->watch] + f * (B[c->s->watch] - A[c->s->watch]);
    return MM_OK;
}

/* the predictor at t from up to three solved points (Lagrange extrapolation) */
static void predict(int n, int have, double t, const double *tt, double *const *qq, double *qp)
{
    for (int i = 0; i < n; i++) {
        if (have == 1) {
            qp[i] = qq[0][i];
        } else if (have == 2) {
            double l = (t - tt[0]) / (tt[1] - tt[0]);
            qp[i] = qq[0][i] + l * (qq[1][i] - qq[0][i]);
        } else {
            double l0 = (t - tt[1]) * (t - tt[2]) / ((tt[0] - tt[1]) * (tt[0] - tt[2]));
            double l1 = (t - tt[0]) * (t - tt[2]) / ((tt[1] - tt[0]) * (tt[1] - tt[2]));
            double l2 = (t - tt[0]) * (t - tt[1]) / ((tt[2] - tt[0]) * (tt[2] - tt[1]));
            qp[i] = l0 * qq[0][i] + l1 * qq[1][i] + l2 * qq[2][i];
        }
    }
}

int mm_mech_sweep_solve(const mm_mech_problem *p, const mm_mech_options *o, mm_mech_work *w,
                        mm_mech_sweep *s, mm_error *err)
{
    int n = p->n, rc;
    if (s->nt < 2 || !s->t || !s->q || s->watch >= n)
        return mm_error_set(err, MM_ERANGE, "nt", "a sweep needs at least 2 frames and room for them");
    double dir = s->t[s->nt - 1] > s->t[0] ? 1 : -1;
    for (int f = 1; f < s->nt; f++)
        if (!((s->t[f] - s->t[f - 1]) * dir > 0))
            return mm_error_set(err, MM_ERANGE, "t", "the sweep's values must be strictly monotonic");
    double range = fabs(s->t[s->nt - 1] - s->t[0]);
    sweep_ctx c = {p, o, w, s, err, s->tol_t > 0 ? s->tol_t : 1e-11 * range, range, 0};
    c.cross = fmax(1e-6 * range, c.tau);
    s->solved = 0, s->t_limit = s->t[0], s->n_sing = s->n_turn = 0;
    s->steps = s->newton = s->singular_frames = 0;
    s->err_est = 0;

    /* the assembly at t[0] */
    mm_mech_info info;
    int ok = corrector(&c, s->t[0], s->q, w->qa, &info);
    if (ok < 0)
        return -ok;
    if (!ok)
        return mm_error_set(err, MM_ENOCONV, "q", "the mechanism cannot be assembled at the start of the sweep");
    memcpy(s->q, w->qa, (size_t)n * sizeof *s->q);
    s->err_est = info.err_est;
    double err_c = info.err_est, rcond_c = info.rcond;   /* of the newest solution in the history */
    double qlast[MM_MECH_MAX_N];                         /* the newest solution */
    memcpy(qlast, w->qa, (size_t)n * sizeof *qlast);

    /* history: hq[0] oldest .. hq[have-1] newest */
    double *hq[3] = {w->qa, w->qb, w->qc}, ht[3] = {s->t[0], 0, 0};
    int have = 1;
    double tc = s->t[0], h = s->t[1] - s->t[0];
    double det_c = det_at(&c, tc, hq[0]), g_c = watch_at(&c, tc, hq[0]);
    double qtry[MM_MECH_MAX_N];
    int max_steps = 200 * s->nt + 4000;

    int stopped = 0;
    for (int f = 1; f < s->nt && !stopped; f++) {
        while ((s->t[f] - tc) * dir > 0) {
            if (++s->steps > max_steps)
                return mm_error_set(err, MM_ENOCONV, "t", "the sweep took too many steps");
            double dt = (s->t[f] - tc) * dir < fabs(h) ? s->t[f] - tc : h;
            double tn = tc + dt;
            if ((s->t[f] - tn) * dir < 0.5 * c.tau)   /* do not leave a sliver before the frame */
                tn = s->t[f], dt = tn - tc;
            predict(n, have, tn, ht, hq, w->qp);
            ok = corrector(&c, tn, w->qp, qtry, &info);
            if (ok < 0)
                return -ok;
            const double *qcur = hq[have - 1];
            const double ta = ht[have - 1];            /* tc, or before a point left out */
            double corr = wdist(p, o, qtry, w->qp), move = wdist(p, o, qtry, qcur);
            /* a branch jump moves far from the predictor; the first step has
             * no predictor and may move at most a tenth of a radian.  The
             * solutions' own errors (large on a frame exactly at a change
             * point, where Newton stops at the rounding floor) are no jump */
            double slack = 1e3 * o->xtol + 2 * (err_c + info.err_est);
            int accept = ok && (have > 1 ? corr <= 0.3 * move + slack : move <= 0.1 + slack);
            if (!accept) {
                h = 0.5 * dt;
                if (fabs(h) < c.tau) {                    /* it stops closing here */
                    s->t_limit = tc + 0.5 * dt;
                    s->solved = f;
                    stopped = 1;
                    break;
                }
                continue;
            }
            double det_n = det_at(&c, tn, qtry), g_n = watch_at(&c, tn, qtry);
            /* det changes sign only through a singular point.  Where two
             * assemblies pass close (near a toggle) a long step can land on
             * the other one, whose det has the other sign: shrink the step
             * until it either stays on this side or is short enough to be
             * the crossing of a change point */
            if (det_c != 0 && det_n != 0 && (det_c > 0) != (det_n > 0)) {
                /* det changes sign only through a singular point.  Where two
                 * assemblies pass close (near a toggle) a long step can land
                 * on the other one, whose det has the other sign: then the
                 * bisection's midpoints leave the chord between the ends,
                 * and the step is halved until it stays on its own side (or
                 * is short enough to be the crossing of a change point) */
                double tz;
                int jumped = 0;
                if ((rc = locate(&c, 0, ta, qcur, det_c, tn, qtry, det_n, &tz, NULL, &jumped)) != MM_OK)
                    return rc;
                if (jumped && fabs(dt) > c.cross) {
                    h = 0.5 * dt;
                    continue;
                }
                if (s->n_sing < MM_MECH_MAX_EVENTS)
                    s->t_sing[s->n_sing++] = tz;
            }
            if (g_c != 0 && g_n != 0 && (g_c > 0) != (g_n > 0) && s->n_turn < MM_MECH_MAX_EVENTS) {
                if ((rc = locate(&c, 1, ta, qcur, g_c, tn, qtry, g_n, &s->t_turn[s->n_turn], &s->q_turn[s->n_turn], NULL)) !=
                    MM_OK)
                    return rc;
                s->n_turn++;
            }
            s->err_est = fmax(s->err_est, info.err_est);
            memcpy(qlast, qtry, (size_t)n * sizeof *qtry);
            tc = tn;
            /* a solution (almost) on a change point, where the Jacobian's
             * condition has collapsed beside the last one's, is good to
             * draw but says nothing of which way the motion goes on: the
             * predictor keeps to the solutions before it */
            if (!(have > 1 && info.rcond < 1e-3 * rcond_c)) {
                /* shift the history */
                if (have == 3) {
                    double *old = hq[0];
                    hq[0] = hq[1], hq[1] = hq[2], hq[2] = old;
                    ht[0] = ht[1], ht[1] = ht[2];
                    have = 2;
                }
                memcpy(hq[have], qtry, (size_t)n * sizeof *qtry);
                ht[have] = tn;
                have++;
                det_c = det_n, g_c = g_n != 0 ? g_n : g_c;
                err_c = info.err_est, rcond_c = info.rcond;
            }
            h = 2 * dt;                                   /* grow back after a cut */
            if (fabs(h) > fabs(s->t[f] - s->t[f - 1]))
                h = s->t[f] - s->t[f - 1];
            if (f + 1 < s->nt && fabs(h) > fabs(s->t[f + 1] - s->t[f]))
                h = s->t[f + 1] - s->t[f];
        }
        if (!stopped)
            memcpy(s->q + (size_t)f * (size_t)n, qlast, (size_t)n * sizeof *s->q);
    }
    if (!stopped) {
        s->solved = s->nt;
        s->t_limit = s->t[s->nt - 1];
    }

    /* velocities and accelerations of every frame solved */
    for (int f = 0; f < s->solved && (s->qd || s->qdd); f++) {
        const double *q = s->q + (size_t)f * (size_t)n;
        double *qd = s->qd ? s->qd + (size_t)f * (size_t)n : w->va;
        mm_error e;
        rc = mm_mech_velocity(p, o, w, s->t[f], q, qd, &info, &e);
        if (rc == MM_OK && s->qdd && p->gamma)
            rc = mm_mech_acceleration(p, o, w, s->t[f], q, qd, s->qdd + (size_t)f * (size_t)n, &info, &e);
        if (rc == MM_ESINGULAR) {
            s->singular_frames++;
            memset(qd, 0, (size_t)n * sizeof *qd);
            if (s->qdd)
                memset(s->qdd + (size_t)f * (size_t)n, 0, (size_t)n * sizeof *s->qdd);
        } else if (rc != MM_OK) {
            if (err)
                *err = e;
            return rc;
        }
    }
    return MM_OK;
}
