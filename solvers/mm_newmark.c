/* mm_newmark.c — fixed-step integrators for M q'' + C q' + K q = F(t, q, q').
 *
 * One step of every scheme advances the state (q_k, v_k, a_k) at t_k to
 * (q_{k+1}, v_{k+1}, a_{k+1}) at t_{k+1} = t_k + h, where v = q' and a = q''.
 *
 * Newmark family (N. M. Newmark, 1959):
 *     q_{k+1} = q_k + h v_k + h^2 [(1/2 - beta) a_k + beta a_{k+1}]      (N1)
 *     v_{k+1} = v_k + h [(1 - gamma) a_k + gamma a_{k+1}]                (N2)
 * with the equation of motion written between t_k and t_{k+1}
 * (generalized-alpha, J. Chung and G. M. Hulbert, 1993):
 *     (1 - am) M a_{k+1} + am M a_k
 *       + (1 - af) (C v_{k+1} + K q_{k+1} - F_{k+1})
 *       + af (C v_k + K q_k - F_k) = 0                                   (G)
 * Plain Newmark is am = af = 0; HHT-alpha (Hilber, Hughes and Taylor,
 * 1977) is am = 0, af = -alpha.  (G) is solved for a_{k+1}: directly when
 * F depends on t only, by Newton's method otherwise.
 *
 * Central difference is Newmark with beta = 0, gamma = 1/2, which is the
 * same as  M (q_{k+1} - 2 q_k + q_{k-1}) / h^2 + C (q_{k+1} - q_{k-1}) / 2h
 * + K q_k = F_k.  Velocity Verlet is the kick-drift-kick splitting.
 *
 * Linear algebra is a small dense LU with partial pivoting and a Cholesky
 * factorisation, written here because n <= MM_NEWMARK_MAX_DOF is small.
 */
#include "mm_newmark.h"

#include "mm_linalg.h"

#include <assert.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mm_linalg.h"

/* ======================================================================== */
/* Small dense linear algebra (row-major n x n)                             */
/* ======================================================================== */

/* y = A x, or y = 0 when A is NULL (an absent C or K). */
static void matvec(int n, const double *A, const double *x, double *y)
{
    for (int i = 0; i < n; i++) {
        double s = 0.0;
        if (A)
            for (int j = 0; j < n; j++)
                s += A[i * n + j] * x[j];
        y[i] = s;
    }
}

/* y = A^T x (A not NULL). */
static void matvec_t(int n, const double *A, const double *x, double *y)
{
    for (int j = 0; j < n; j++)
        y[j] = 0.0;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            y[j] += A[i * n + j] * x[i];
}

static double dot(int n, const double *x, const double *y)
{
    double s = 0.0;
    for (int i = 0; i < n; i++)
        s += x[i] * y[i];
    return s;
}

static double norm_inf(int n, const double *x)
{
    double m = 0.0;
    for (int i = 0; i < n; i++)
        if (fabs(x[i]) > m)
            m = fabs(x[i]);
    return m;
}

static int all_finite(int n, const double *x)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(x[i]))
            return 0;
    return 1;
}

/* LU factorisation with partial pivoting, in place: P A = L U with L unit
 * lower triangular.  piv[k] is the row swapped with row k at stage k.
 * Returns 0, or k+1 when column k has no usable pivot (singular). */
static int lu_factor(int n, double *A, int *piv)
{
    double amax = norm_inf(n * n, A);
    double tiny = n * DBL_EPSILON * amax;   /* pivots below this are round-off */

    for (int k = 0; k < n; k++) {
        int p = k;
        for (int i = k + 1; i < n; i++)
            if (fabs(A[i * n + k]) > fabs(A[p * n + k]))
                p = i;
        piv[k] = p;
        if (!(fabs(A[p * n + k]) > tiny))
            return k + 1;
        if (p != k)
            for (int j = 0; j < n; j++) {
                double s = A[k * n + j];
                A[k * n + j] = A[p * n + j];
                A[p * n + j] = s;
            }
        for (int i = k + 1; i < n; i++) {
            double l = A[i * n + k] /= A[k * n + k];
            for (int j = k + 1; j < n; j++)
                A[i * n + j] -= l * A[k * n + j];
        }
    }
    return 0;
}

/* Solve A x = b with the factors from lu_factor; b is overwritten by x. */
static void lu_solve(int n, const double *LU, const int *piv, double *b)
{
    for (int k = 0; k < n; k++) {             /* b <- P b */
        double s = b[k];
        b[k] = b[piv[k]];
        b[piv[k]] = s;
    }
    for (int i = 1; i < n; i++)               /* L y = b, unit diagonal */
        for (int j = 0; j < i; j++)
            b[i] -= LU[i * n + j] * b[j];
    for (int i = n - 1; i >= 0; i--) {        /* U x = y */
        for (int j = i + 1; j < n; j++)
            b[i] -= LU[i * n + j] * b[j];
        b[i] /= LU[i * n + i];
    }
}

/* Cholesky A = L L^T of a symmetric matrix (lower triangle of L written,
 * upper set to 0).  Returns 0, or k+1 when the k-th pivot is not clearly
 * positive: A is not positive definite. */
static int cholesky(int n, const double *A, double *L)
{
    memset(L, 0, (size_t)n * (size_t)n * sizeof *L);
    for (int j = 0; j < n; j++) {
        double d = A[j * n + j];
        for (int k = 0; k < j; k++)
            d -= L[j * n + k] * L[j * n + k];
        if (!(d > n * DBL_EPSILON * fabs(A[j * n + j])))
            return j + 1;
        L[j * n + j] = sqrt(d);
        for (int i = j + 1; i < n; i++) {
            double s = A[i * n + j];
            for (int k = 0; k < j; k++)
                s -= L[i * n + k] * L[j * n + k];
            L[i * n + j] = s / L[j * n + j];
        }
    }
    return 0;
}

/* ======================================================================== */
/* Workspace                                                                */
/* ======================================================================== */

enum { NVEC = 19 };   /* vectors a run needs: see struct run */

struct mm_newmark_work {
    int cap;          /* largest n served */
    double *mat;      /* 4 matrices cap x cap: S, L, Jq, Jv */
    double *vec;      /* NVEC vectors of length cap */
    int *piv;         /* pivots of the LU of S */
};

mm_newmark_work *mm_newmark_work_alloc(int n)
{
    if (n < 1 || n > MM_NEWMARK_MAX_DOF)
        return NULL;
    mm_newmark_work *w = calloc(1, sizeof *w);
    if (!w)
        return NULL;
    size_t nn = (size_t)n * (size_t)n;
    w->cap = n;
    w->mat = malloc(4 * nn * sizeof *w->mat);
    w->vec = malloc((size_t)NVEC * (size_t)n * sizeof *w->vec);
    w->piv = malloc((size_t)n * sizeof *w->piv);
    if (!w->mat || !w->vec || !w->piv) {
        mm_newmark_work_free(w);
        return NULL;
    }
    return w;
}

void mm_newmark_work_free(mm_newmark_work *w)
{
    if (!w)
        return;
    free(w->piv);
    free(w->vec);
    free(w->mat);
    free(w);
}

/* ======================================================================== */
/* Options, validation, step and row counts                                 */
/* ======================================================================== */

void mm_newmark_options_init(mm_newmark_options *o)
{
    assert(o);
    memset(o, 0, sizeof *o);
    o->method = MM_NEWMARK_AVERAGE;
    o->h = 0.0;                 /* no sensible default: the caller chooses */
    o->beta = 0.25;
    o->gamma = 0.5;
    o->alpha = -0.1;
    o->rho_inf = 0.8;
    o->stride = 1;
    o->points = 0;
    o->newton_tol = 1e-10;
    o->newton_max_iter = 20;
    o->max_steps = MM_NEWMARK_DEFAULT_MAX_STEPS;
}

const char *mm_newmark_method_name(mm_newmark_method method)
{
    switch (method) {
    case MM_NEWMARK_AVERAGE:           return "newmark-average-acceleration";
    case MM_NEWMARK_LINEAR:            return "newmark-linear-acceleration";
    case MM_NEWMARK_BETA_GAMMA:        return "newmark-beta-gamma";
    case MM_NEWMARK_HHT:               return "hht-alpha";
    case MM_NEWMARK_GENERALIZED_ALPHA: return "generalized-alpha";
    case MM_NEWMARK_CENTRAL:           return "central-difference";
    case MM_NEWMARK_VERLET:            return "stormer-verlet";
    default:                           return "unknown";
    }
}

/* Steps needed to cover the span, as a double (may be huge or inf).  The
 * factor (1 - 1e-12) keeps 10/0.001 = 10000.000000000002 from asking for a
 * step past t_end. */
static double steps_needed(const mm_newmark_problem *p, const mm_newmark_options *o)
{
    double r = (p->t_end - p->t0) / o->h;
    double s = ceil(r * (1.0 - 1e-12));
    return s < 1.0 ? 1.0 : s;
}

long mm_newmark_step_count(const mm_newmark_problem *p, const mm_newmark_options *o)
{
    return (long)steps_needed(p, o);
}

int mm_newmark_output_rows(const mm_newmark_problem *p, const mm_newmark_options *o)
{
    long N = mm_newmark_step_count(p, o);
    if (o->points > 0)
        return o->points < N + 1 ? o->points : (int)(N + 1);
    return (int)(N / o->stride + 1 + (N % o->stride != 0));
}

/* Step index stored in row `row` of `rows`. */
static long row_step(const mm_newmark_options *o, long N, int rows, int row)
{
    if (o->points > 0) {    /* evenly spread, rounded to the nearest step */
        long long m = rows - 1;
        return (long)((2LL * row * N + m) / (2 * m));
    }
    long k = row * o->stride;
    return k < N ? k : N;
}

/* MM_EVALUE if an n x m array has a NaN or Inf. */
static int check_finite(const double *A, int rows, int cols, const char *name,
                        const char *what, mm_error *err)
{
    if (!A)
        return MM_OK;
    for (int i = 0; i < rows; i++)
        for (int j = 0; j < cols; j++)
            if (!isfinite(A[i * cols + j])) {
                if (rows == 1)
                    return mm_error_set(err, MM_EVALUE, name,
                        "%s '%s' has a non-finite entry at position %d",
                        what, name, j + 1);
                return mm_error_set(err, MM_EVALUE, name,
                    "%s '%s' has a non-finite entry at row %d, column %d",
                    what, name, i + 1, j + 1);
            }
    return MM_OK;
}

int mm_newmark_check(const mm_newmark_problem *p, const mm_newmark_options *o,
                     mm_error *err)
{
    assert(p && o);
    int n = p->n, rc;

    if (n < 1 || n > MM_NEWMARK_MAX_DOF)
        return mm_error_set(err, MM_ERANGE, "n",
            "the number of degrees of freedom 'n' must be between 1 and %d, got %d",
            MM_NEWMARK_MAX_DOF, n);
    assert(p->M);   /* a mass matrix is not optional: our bug if missing */
    if ((rc = check_finite(p->M, n, n, "M", "mass matrix", err)) ||
        (rc = check_finite(p->C, n, n, "C", "damping matrix", err)) ||
        (rc = check_finite(p->K, n, n, "K", "stiffness matrix", err)) ||
        (rc = check_finite(p->q0, 1, n, "q0", "initial displacement", err)) ||
        (rc = check_finite(p->qd0, 1, n, "qd0", "initial velocity", err)))
        return rc;

    for (int i = 0; i < n; i++)
        if (!(p->M[i * n + i] > 0.0))
            return mm_error_set(err, MM_ESINGULAR, "M",
                "mass matrix 'M' needs a positive diagonal (every degree of "
                "freedom needs mass): M(%d,%d) = %g", i + 1, i + 1, p->M[i * n + i]);
    int si, sj;
    if (!mm_linalg_is_symmetric(n, p->M, &si, &sj))   /* the project's one rule */
        return mm_error_set(err, MM_EVALUE, "M",
            "mass matrix 'M' must be symmetric: M(%d,%d) = %g but M(%d,%d) = %g",
            si + 1, sj + 1, p->M[si * n + sj], sj + 1, si + 1, p->M[sj * n + si]);
    if (p->force_kind < MM_NEWMARK_FORCE_STATE || p->force_kind > MM_NEWMARK_FORCE_TIME)
        return mm_error_set(err, MM_ERANGE, "force_kind",
            "'force_kind' must be state, position or time, got %d", (int)p->force_kind);

    if (!isfinite(p->t0) || !isfinite(p->t_end) || !(p->t_end > p->t0))
        return mm_error_set(err, MM_ERANGE, "t_end",
            "'t_end' must be greater than 't0' (got t0 = %g s, t_end = %g s)",
            p->t0, p->t_end);
    if (!isfinite(o->h) || !(o->h > 0.0))
        return mm_error_set(err, MM_ERANGE, "h",
            "the time step 'h' must be > 0, got %g s", o->h);

    switch (o->method) {
    case MM_NEWMARK_BETA_GAMMA:
        if (!(o->beta >= 0.0 && o->beta <= 0.5))
            return mm_error_set(err, MM_ERANGE, "beta",
                "'beta' must be between 0 and 0.5, got %g", o->beta);
        if (!(o->gamma >= 0.5 && o->gamma <= 1.0))
            return mm_error_set(err, MM_ERANGE, "gamma",
                "'gamma' must be between 0.5 and 1 (below 0.5 the scheme "
                "creates energy), got %g", o->gamma);
        break;
    case MM_NEWMARK_HHT:
        if (!(o->alpha >= -1.0 / 3.0 - 1e-12 && o->alpha <= 0.0))
            return mm_error_set(err, MM_ERANGE, "alpha",
                "'alpha' of hht-alpha must be between -1/3 and 0, got %g", o->alpha);
        break;
    case MM_NEWMARK_GENERALIZED_ALPHA:
        if (!(o->rho_inf >= 0.0 && o->rho_inf <= 1.0))
            return mm_error_set(err, MM_ERANGE, "rho_inf",
                "'rho_inf' must be between 0 and 1, got %g", o->rho_inf);
        break;
    case MM_NEWMARK_AVERAGE:
    case MM_NEWMARK_LINEAR:
    case MM_NEWMARK_CENTRAL:
    case MM_NEWMARK_VERLET:
        break;
    default:
        return mm_error_set(err, MM_ERANGE, "method",
            "'method' must be one of the %d integrators, got %d",
            (int)MM_NEWMARK_METHOD_COUNT, (int)o->method);
    }

    if (o->stride < 1)
        return mm_error_set(err, MM_ERANGE, "stride",
            "'stride' must be at least 1, got %ld", o->stride);
    if (o->points < 0 || o->points == 1)
        return mm_error_set(err, MM_ERANGE, "points",
            "'points' must be 0 (store every 'stride' steps) or at least 2, got %d",
            o->points);
    if (!(o->newton_tol >= 1e-14 && o->newton_tol <= 1e-2))
        return mm_error_set(err, MM_ERANGE, "newton_tol",
            "'newton_tol' must be between 1e-14 and 1e-2, got %g", o->newton_tol);
    if (o->newton_max_iter < 1 || o->newton_max_iter > MM_NEWMARK_MAX_NEWTON)
        return mm_error_set(err, MM_ERANGE, "newton_max_iter",
            "'newton_max_iter' must be between 1 and %d, got %d",
            MM_NEWMARK_MAX_NEWTON, o->newton_max_iter);
    if (o->max_steps < 1 || o->max_steps > MM_NEWMARK_STEPS_CEILING)
        return mm_error_set(err, MM_ERANGE, "max_steps",
            "'max_steps' must be between 1 and %ld, got %ld",
            MM_NEWMARK_STEPS_CEILING, o->max_steps);

    double N = steps_needed(p, o);   /* before anything is allocated */
    if (!(N <= (double)o->max_steps))
        return mm_error_set(err, MM_ERANGE, "h",
            "covering %g s with steps of h = %g s takes %.3g steps, more than "
            "the limit of %ld: increase 'h' or shorten the time span",
            p->t_end - p->t0, o->h, N, o->max_steps);
    return MM_OK;
}

/* ======================================================================== */
/* The state of one run                                                     */
/* ======================================================================== */

typedef struct run {
    const mm_newmark_problem *p;
    const mm_newmark_options *o;
    mm_newmark_result *res;
    mm_error *err;
    int n;
    double h;
    double beta, gamma;     /* Newmark parameters of (N1), (N2) */
    double am, af;          /* weights of (G); 0 for plain Newmark */
    int linear;             /* F depends on t only: one direct solve per step */
    int k_nonsym;           /* K has a circulatory (antisymmetric) part */

    /* state at t_k and at t_{k+1}, with the products that (G) needs;
       the two sets swap places after each step */
    double *q, *v, *a, *F, *Kq, *Cv, *Ma;
    double *q1, *v1, *a1, *F1, *Kq1, *Cv1, *Ma1;
    double *qt, *vt;        /* predictors: (N1), (N2) without the a_{k+1} terms */
    double *r, *x, *y;      /* residual and scratch */
    double *S;              /* effective matrix, then its LU factors */
    double *L;              /* Cholesky factor of M */
    double *Jq, *Jv;        /* dF/dq and dF/dq' */
    int *piv;

    double E0, work, diss;  /* energy bookkeeping */
    double escale;          /* largest |E0|, |E|, |work|, |dissipated| seen */
} run;

/* A callback returned nonzero: pass its code on when it is one of ours. */
static int callback_failed(run *r, int rc, const char *what, double t)
{
    int code = (rc > 0 && rc < MM_STATUS_COUNT) ? rc : MM_EINTERNAL;
    return mm_error_set(r->err, code, "force",
        "the %s function stopped the run at t = %g s (it returned %d)", what, t, rc);
}

/* F = F(t, q, v), or 0 without a force. */
static int eval_force(run *r, double t, const double *q, const double *v, double *F)
{
    const mm_newmark_problem *p = r->p;
    if (!p->force) {
        memset(F, 0, (size_t)r->n * sizeof *F);
        return MM_OK;
    }
    r->res->force_evals++;
    int rc = p->force(t, q, v, F, p->params);
    if (rc)
        return callback_failed(r, rc, "force", t);
    for (int i = 0; i < r->n; i++)
        if (!isfinite(F[i]))
            return mm_error_set(r->err, MM_ENONFINITE, "force",
                "the force F returned %g in component %d at t = %g s", F[i], i + 1, t);
    return MM_OK;
}

/* Jq = dF/dq and Jv = dF/dq' at (t, q, v), where F = F(t, q, v) is known.
 * From the callback if there is one, otherwise by forward differences with
 * a relative step sqrt(eps) (q and v are perturbed and restored exactly). */
static int eval_jacobian(run *r, double t, double *q, double *v, const double *F)
{
    const mm_newmark_problem *p = r->p;
    const int n = r->n;
    size_t nn = (size_t)n * (size_t)n;
    int rc;

    memset(r->Jq, 0, nn * sizeof *r->Jq);
    memset(r->Jv, 0, nn * sizeof *r->Jv);
    if (!p->force || p->force_kind == MM_NEWMARK_FORCE_TIME)
        return MM_OK;

    if (p->jacobian) {
        r->res->jacobian_evals++;
        rc = p->jacobian(t, q, v, r->Jq, r->Jv, p->params);
        if (rc)
            return callback_failed(r, rc, "jacobian", t);
        if (!all_finite((int)nn, r->Jq) || !all_finite((int)nn, r->Jv))
            return mm_error_set(r->err, MM_ENONFINITE, "force",
                "the jacobian of F returned a non-finite value at t = %g s", t);
    } else {
        const double eps = sqrt(DBL_EPSILON);
        double qs = norm_inf(n, q) + r->h * norm_inf(n, v);  /* size of q */
        if (qs == 0.0)
            qs = 1.0;           /* nothing to scale by: 1 in the units of q */
        double vs = norm_inf(n, v) + qs / r->h;              /* size of q' */
        for (int j = 0; j < n; j++) {
            double old = q[j];
            q[j] = old + eps * (fabs(old) + qs);
            double d = q[j] - old;          /* the step actually taken */
            rc = eval_force(r, t, q, v, r->y);
            q[j] = old;
            if (rc)
                return rc;
            for (int i = 0; i < n; i++)
                r->Jq[i * n + j] = (r->y[i] - F[i]) / d;
        }
        if (p->force_kind == MM_NEWMARK_FORCE_STATE)
            for (int j = 0; j < n; j++) {
                double old = v[j];
                v[j] = old + eps * (fabs(old) + vs);
                double d = v[j] - old;
                rc = eval_force(r, t, q, v, r->y);
                v[j] = old;
                if (rc)
                    return rc;
                for (int i = 0; i < n; i++)
                    r->Jv[i * n + j] = (r->y[i] - F[i]) / d;
            }
    }
    if (p->force_kind == MM_NEWMARK_FORCE_POSITION)   /* F(t, q): no dF/dq' */
        memset(r->Jv, 0, nn * sizeof *r->Jv);
    return MM_OK;
}

/* Kinetic and potential energy of (q, v); Kq = K q is given. */
static double energy_of(run *r, const double *q, const double *v,
                        const double *Kq, mm_newmark_energy *e)
{
    matvec(r->n, r->p->M, v, r->x);
    e->kinetic = 0.5 * dot(r->n, v, r->x);
    e->potential = 0.5 * dot(r->n, q, Kq);
    e->work = r->work;
    e->dissipated = r->diss;
    return e->kinetic + e->potential;
}

/* Add the step's work and dissipation, integrating the powers q'.F and
 * q'.C q' by the trapezoidal rule, and update the balance figures.
 * Returns 0 if the energy overflowed. */
static int account_energy(run *r)
{
    const int n = r->n;
    const double h = r->h;
    double dW, dD;
    if (r->o->work_in_q) {  /* the trapezoidal rule in q: (q1 - q) . (F + F1)/2 */
        dW = dD = 0;
        for (int i = 0; i < n; i++) {
            double dq = r->q1[i] - r->q[i];
            dW += 0.5 * dq * (r->F[i] + r->F1[i]);
            dD += 0.5 * dq * (r->Cv[i] + r->Cv1[i]);
        }
    } else {                /* the trapezoidal rule in t: h (q'.F + q1'.F1)/2 */
        dW = 0.5 * h * (dot(n, r->v, r->F) + dot(n, r->v1, r->F1));
        dD = 0.5 * h * (dot(n, r->v, r->Cv) + dot(n, r->v1, r->Cv1));
    }
    if (r->k_nonsym) {      /* the circulatory force -(K - K^T)/2 q does work */
        matvec_t(n, r->p->K, r->q, r->x);
        matvec_t(n, r->p->K, r->q1, r->y);
        for (int i = 0; i < n; i++) {
            double ka0 = 0.5 * (r->Kq[i] - r->x[i]), ka1 = 0.5 * (r->Kq1[i] - r->y[i]);
            double w = r->o->work_in_q ? 0.5 * (r->q1[i] - r->q[i]) : 0.5 * h;
            dW -= r->o->work_in_q ? w * (ka0 + ka1) : w * (r->v[i] * ka0 + r->v1[i] * ka1);
        }
    }
    r->work += dW;
    r->diss += dD;

    mm_newmark_energy e;
    double E = energy_of(r, r->q1, r->v1, r->Kq1, &e);
    double bal = fabs(E - r->E0 - r->work + r->diss);
    double scale = fmax(fmax(fabs(r->E0), fabs(E)), fmax(fabs(r->work), fabs(r->diss)));
    mm_newmark_result *res = r->res;
    if (bal > res->energy_balance)
        res->energy_balance = bal;
    if (scale > r->escale)
        r->escale = scale;
    res->energy_end = e;
    return isfinite(E) && isfinite(bal);
}

static void store_row(run *r, int row, double t, const double *q,
                      const double *v, const double *a, const double *Kq)
{
    mm_newmark_result *res = r->res;
    size_t off = (size_t)row * (size_t)r->n, bytes = (size_t)r->n * sizeof(double);
    if (res->t)
        res->t[row] = t;
    if (res->q)
        memcpy(res->q + off, q, bytes);
    if (res->qd)
        memcpy(res->qd + off, v, bytes);
    if (res->qdd)
        memcpy(res->qdd + off, a, bytes);
    if (res->energy)
        energy_of(r, q, v, Kq, &res->energy[row]);
    res->rows = row + 1;
}

/* ======================================================================== */
/* Stability limit                                                          */
/* ======================================================================== */

/* Omega = omega h above which the scheme is unstable (undamped, linear). */
static double omega_h_crit(const run *r)
{
    return mm_newmark_omega_h_limit(r->o);
}

double mm_newmark_omega_h_limit(const mm_newmark_options *o)
{
    switch (o->method) {
    case MM_NEWMARK_CENTRAL:
    case MM_NEWMARK_VERLET:
        return 2.0;
    case MM_NEWMARK_LINEAR:
        return 2.0 * sqrt(3.0);                 /* 1 / sqrt(1/4 - 1/6) */
    case MM_NEWMARK_BETA_GAMMA:
        if (2.0 * o->beta < o->gamma)
            return 1.0 / sqrt(0.5 * o->gamma - o->beta);
        return 0.0;
    default:
        return 0.0;
    }
}

/* The largest omega^2 of Ks phi = omega^2 M phi (Ks: the symmetric part of
 * K - dF/dq, which the caller left in Jq), from all eigenvalues of the
 * pencil: exact to rounding.  (A power iteration stops short from below:
 * its stable step came out too large, 0.0100196 s against 0.0100005 s for
 * a 160-mass chain.)  Returns omega_max, or 0 without positive stiffness;
 * a negative code when the eigen solver failed. */
static int exact_omega_max(run *r, double *omega_max)
{
    const int n = r->n;
    double *lam = malloc((size_t)n * sizeof *lam);
    if (!lam)
        return mm_error_set(r->err, MM_ENOMEM, "", "out of memory");
    mm_error e2;
    int rc = mm_linalg_sygv(n, r->Jq, r->p->M, lam, NULL, &e2);
    if (rc == MM_OK)
        *omega_max = lam[n - 1] > 0 ? sqrt(lam[n - 1]) : 0.0;
    free(lam);
    if (rc == MM_ESINGULAR)
        return mm_error_set(r->err, MM_ESINGULAR, "M",
            "the mass matrix 'M' is not positive definite: some motion would "
            "have no kinetic energy");
    if (rc != MM_OK)
        return mm_error_set(r->err, rc, e2.param, "%s", e2.msg);
    return MM_OK;
}

/* ======================================================================== */
/* One step of each scheme                                                  */
/* ======================================================================== */

/* (N1), (N2): q_{k+1}, v_{k+1} from the predictors and a_{k+1}. */
static void newmark_update(run *r)
{
    double bh2 = r->beta * r->h * r->h, gh = r->gamma * r->h;
    for (int i = 0; i < r->n; i++) {
        r->q1[i] = r->qt[i] + bh2 * r->a1[i];
        r->v1[i] = r->vt[i] + gh * r->a1[i];
    }
}

/* M a, K q and C v at t_{k+1}. */
static void products1(run *r)
{
    matvec(r->n, r->p->M, r->a1, r->Ma1);
    matvec(r->n, r->p->K, r->q1, r->Kq1);
    matvec(r->n, r->p->C, r->v1, r->Cv1);
}

/* Residual of (G) into r->r; returns the size of its terms, the scale the
 * Newton tolerance is relative to. */
static double residual(run *r)
{
    const double am = r->am, af = r->af;
    double scale = (1.0 - am) * norm_inf(r->n, r->Ma1) + am * norm_inf(r->n, r->Ma)
                 + (1.0 - af) * (norm_inf(r->n, r->Cv1) + norm_inf(r->n, r->Kq1)
                                 + norm_inf(r->n, r->F1))
                 + af * (norm_inf(r->n, r->Cv) + norm_inf(r->n, r->Kq)
                         + norm_inf(r->n, r->F));
    for (int i = 0; i < r->n; i++)
        r->r[i] = (1.0 - am) * r->Ma1[i] + am * r->Ma[i]
                + (1.0 - af) * (r->Cv1[i] + r->Kq1[i] - r->F1[i])
                + af * (r->Cv[i] + r->Kq[i] - r->F[i]);
    return scale;
}

/* S = (1-am) M + (1-af) [gamma h (C - Jv) + beta h^2 (K - Jq)], factored:
 * the derivative of (G) with respect to a_{k+1}.  newton says whether it is
 * Newton's matrix (Jq, Jv from F) or the constant one of a linear problem. */
static int build_effective(run *r, int newton, double t)
{
    const int n = r->n;
    const mm_newmark_problem *p = r->p;
    double cm = 1.0 - r->am, cf = 1.0 - r->af;
    double gh = r->gamma * r->h, bh2 = r->beta * r->h * r->h;
    for (int i = 0; i < n * n; i++) {
        double c = (p->C ? p->C[i] : 0.0) - r->Jv[i];
        double k = (p->K ? p->K[i] : 0.0) - r->Jq[i];
        r->S[i] = cm * p->M[i] + cf * (gh * c + bh2 * k);
    }
    r->res->factorizations++;
    if (!lu_factor(n, r->S, r->piv))
        return MM_OK;
    if (newton)
        return mm_error_set(r->err, MM_ESINGULAR, "h",
            "the newton matrix M + gamma h (C - dF/dq') + beta h^2 (K - dF/dq) is "
            "singular at t = %g s: reduce 'h'", t);
    return mm_error_set(r->err, MM_ESINGULAR, "h",
        "the effective matrix M + gamma h C + beta h^2 K is singular for h = %g s "
        "(negative stiffness?): change 'h'", r->h);
}

/* Newmark, HHT-alpha, generalized-alpha: solve (G) for a_{k+1}. */
static int step_implicit(run *r, double t1)
{
    const int n = r->n;
    const double h = r->h;
    int rc;

    for (int i = 0; i < n; i++) {
        r->qt[i] = r->q[i] + h * r->v[i] + h * h * (0.5 - r->beta) * r->a[i];
        r->vt[i] = r->v[i] + h * (1.0 - r->gamma) * r->a[i];
        r->a1[i] = r->a[i];     /* first guess: constant acceleration */
    }
    for (int it = 0;; it++) {
        newmark_update(r);
        if (it == 0 || !r->linear)
            if ((rc = eval_force(r, t1, r->q1, r->v1, r->F1)))
                return rc;
        products1(r);
        double scale = residual(r);

        if (r->linear) {        /* (G) is linear in a_{k+1}: S was factored once */
            for (int i = 0; i < n; i++)
                r->r[i] = -r->r[i];
            lu_solve(n, r->S, r->piv, r->r);
            for (int i = 0; i < n; i++)
                r->a1[i] += r->r[i];
            newmark_update(r);
            products1(r);
            return MM_OK;
        }

        double res_norm = norm_inf(n, r->r);
        if (res_norm <= r->o->newton_tol * scale)
            return MM_OK;       /* Newton converged */
        if (it == r->o->newton_max_iter)
            return mm_error_set(r->err, MM_ENOCONV, "h",
                "newton iterations did not converge at t = %g s within %d "
                "iterations (residual %.3g of force scale %.3g): reduce the step 'h'",
                t1, r->o->newton_max_iter, res_norm, scale);

        /* Newton: S da = -R with S = dR/da_{k+1} */
        if ((rc = eval_jacobian(r, t1, r->q1, r->v1, r->F1)) ||
            (rc = build_effective(r, 1, t1)))
            return rc;
        for (int i = 0; i < n; i++)
            r->r[i] = -r->r[i];
        lu_solve(n, r->S, r->piv, r->r);
        for (int i = 0; i < n; i++)
            r->a1[i] += r->r[i];
        r->res->newton_iters++;
    }
}

/* The second half shared by the explicit schemes (central difference and
 * Verlet), once q_{k+1} = q1, the half-step velocity vt and F1 are known:
 *   M a_{k+1} = F1 - K q_{k+1} - C v_{k+1/2}       (S holds the LU of M, or
 *                                                   of M + h/2 C)
 *   v_{k+1}   = v_{k+1/2} + h/2 a_{k+1}            final half kick
 * and M a_{k+1}, C v_{k+1} for the energy balance. */
static int explicit_finish(run *r)
{
    const int n = r->n;
    const double h = r->h;
    matvec(n, r->p->K, r->q1, r->Kq1);
    matvec(n, r->p->C, r->vt, r->y);
    for (int i = 0; i < n; i++)
        r->a1[i] = r->F1[i] - r->Kq1[i] - r->y[i];
    lu_solve(n, r->S, r->piv, r->a1);
    for (int i = 0; i < n; i++)
        r->v1[i] = r->vt[i] + 0.5 * h * r->a1[i];
    matvec(n, r->p->M, r->a1, r->Ma1);
    matvec(n, r->p->C, r->v1, r->Cv1);
    return MM_OK;
}

/* Central difference = Newmark beta = 0, gamma = 1/2:
 *   q_{k+1} = q_k + h v_k + h^2/2 a_k
 *   (M + h/2 C) a_{k+1} = F_{k+1} - K q_{k+1} - C (v_k + h/2 a_k)
 *   v_{k+1} = v_k + h/2 (a_k + a_{k+1})
 * S holds the LU of M + h/2 C.  A force that depends on q' gets the
 * predicted velocity v_k + h a_k (keeps second order, stays explicit). */
static int step_central(run *r, double t1)
{
    const int n = r->n;
    const double h = r->h;
    int rc;
    for (int i = 0; i < n; i++) {
        r->q1[i] = r->q[i] + h * r->v[i] + 0.5 * h * h * r->a[i];
        r->vt[i] = r->v[i] + 0.5 * h * r->a[i];
        r->x[i] = r->v[i] + h * r->a[i];
    }
    if ((rc = eval_force(r, t1, r->q1, r->x, r->F1)))
        return rc;
    return explicit_finish(r);
}

/* Velocity (Stormer-) Verlet, kick-drift-kick:
 *   v_{k+1/2} = v_k + h/2 a_k                      kick
 *   q_{k+1}   = q_k + h v_{k+1/2}                  drift
 *   M a_{k+1} = F(t_{k+1}, q_{k+1}) - K q_{k+1}
 *   v_{k+1}   = v_{k+1/2} + h/2 a_{k+1}            kick
 * S holds the LU of M.  Damping C and forces that depend on q' see the
 * half-step velocity v_{k+1/2}: the scheme then loses symplecticity and
 * drops to first order. */
static int step_verlet(run *r, double t1)
{
    const int n = r->n;
    const double h = r->h;
    int rc;
    for (int i = 0; i < n; i++) {
        r->vt[i] = r->v[i] + 0.5 * h * r->a[i];
        r->q1[i] = r->q[i] + h * r->vt[i];
    }
    if ((rc = eval_force(r, t1, r->q1, r->vt, r->F1)))
        return rc;
    return explicit_finish(r);
}

/* The message for a run that overflowed. */
static int blew_up(run *r, double t)
{
    double hs = r->res->h_stable;
    const char *name = mm_newmark_method_name(r->o->method);
    if (hs > 0.0 && r->h > hs)
        return mm_error_set(r->err, MM_ENONFINITE, "h",
            "the solution grew without bound by t = %g s: h = %g s is above the "
            "stability limit h < %.3g/omega_max = %.4g s of %s; reduce 'h'",
            t, r->h, omega_h_crit(r), hs, name);
    if (hs > 0.0)
        return mm_error_set(r->err, MM_ENONFINITE, "h",
            "the solution became infinite by t = %g s although h = %g s is below "
            "the estimated limit %.4g s of %s: stiffening forces? reduce 'h'",
            t, r->h, hs, name);
    return mm_error_set(r->err, MM_ENONFINITE, "h",
        "the solution became infinite or nan by t = %g s: reduce the step 'h' "
        "or check the forces", t);
}

/* ======================================================================== */
/* The driver                                                               */
/* ======================================================================== */

/* Point the run's arrays into the workspace. */
static void carve(run *r, mm_newmark_work *w)
{
    const int n = r->n;
    size_t nn = (size_t)n * (size_t)n;
    double *m = w->mat, *v = w->vec;
    double **vecs[NVEC] = {
        &r->q, &r->v, &r->a, &r->F, &r->Kq, &r->Cv, &r->Ma,
        &r->q1, &r->v1, &r->a1, &r->F1, &r->Kq1, &r->Cv1, &r->Ma1,
        &r->qt, &r->vt, &r->r, &r->x, &r->y,
    };
    r->S = m;
    r->L = m + nn;
    r->Jq = m + 2 * nn;
    r->Jv = m + 3 * nn;
    for (int i = 0; i < NVEC; i++)
        *vecs[i] = v + (size_t)i * (size_t)n;
    r->piv = w->piv;
}

/* Swap the roles of the t_k and t_{k+1} arrays. */
static void swap_states(run *r)
{
    double *s;
#define SWAP(a, b) (s = (a), (a) = (b), (b) = s)
    SWAP(r->q, r->q1); SWAP(r->v, r->v1); SWAP(r->a, r->a1); SWAP(r->F, r->F1);
    SWAP(r->Kq, r->Kq1); SWAP(r->Cv, r->Cv1); SWAP(r->Ma, r->Ma1);
#undef SWAP
}

/* Scheme parameters of (N1), (N2), (G). */
static void set_parameters(run *r)
{
    const mm_newmark_options *o = r->o;
    r->am = r->af = 0.0;
    switch (o->method) {
    case MM_NEWMARK_AVERAGE:            /* trapezoidal rule */
        r->beta = 0.25; r->gamma = 0.5;
        break;
    case MM_NEWMARK_LINEAR:             /* a varies linearly over the step */
        r->beta = 1.0 / 6.0; r->gamma = 0.5;
        break;
    case MM_NEWMARK_BETA_GAMMA:
        r->beta = o->beta; r->gamma = o->gamma;
        break;
    case MM_NEWMARK_HHT:                /* af = -alpha, optimal beta, gamma */
        r->af = -o->alpha;
        r->gamma = 0.5 - o->alpha;
        r->beta = 0.25 * (1.0 - o->alpha) * (1.0 - o->alpha);
        break;
    case MM_NEWMARK_GENERALIZED_ALPHA: {  /* Chung-Hulbert from rho_inf */
        double rho = o->rho_inf;
        r->am = (2.0 * rho - 1.0) / (rho + 1.0);
        r->af = rho / (rho + 1.0);
        r->gamma = 0.5 - r->am + r->af;
        r->beta = 0.25 * (1.0 - r->am + r->af) * (1.0 - r->am + r->af);
        break;
    }
    case MM_NEWMARK_CENTRAL:
    case MM_NEWMARK_VERLET:
    default:
        r->beta = 0.0; r->gamma = 0.5;
        break;
    }
}

int mm_newmark_solve(const mm_newmark_problem *p, const mm_newmark_options *o,
                     mm_newmark_work *w, mm_newmark_result *res, mm_error *err)
{
    assert(p && o && w && res);
    int rc = mm_newmark_check(p, o, err);

    /* counters first, so that a failed run reports what it did */
    res->rows = 0;
    res->steps = res->force_evals = res->jacobian_evals = 0;
    res->newton_iters = res->factorizations = 0;
    res->omega_max = res->h_stable = 0.0;
    res->energy_start = res->energy_balance = res->energy_error = 0.0;
    memset(&res->energy_end, 0, sizeof res->energy_end);
    if (rc)
        return rc;
    assert(w->cap >= p->n);

    const int n = p->n;
    const long N = mm_newmark_step_count(p, o);
    const int rows = mm_newmark_output_rows(p, o);
    if ((res->t || res->q || res->qd || res->qdd || res->energy) && res->max_rows < rows)
        return mm_error_set(err, MM_EINTERNAL, "points",
            "the result arrays hold %d rows but the run stores %d", res->max_rows, rows);

    run r = {0};
    r.p = p; r.o = o; r.res = res; r.err = err;
    r.n = n;
    r.h = o->h;
    r.linear = !p->force || p->force_kind == MM_NEWMARK_FORCE_TIME;
    carve(&r, w);
    set_parameters(&r);
    if (p->K)
        for (int i = 0; i < n && !r.k_nonsym; i++)
            for (int j = i + 1; j < n; j++)
                if (p->K[i * n + j] != p->K[j * n + i]) {
                    r.k_nonsym = 1;
                    break;
                }

    /* M must be positive definite: every motion has positive kinetic energy */
    int bad = cholesky(n, p->M, r.L);
    if (bad)
        return mm_error_set(err, MM_ESINGULAR, "M",
            "the mass matrix 'M' is not positive definite (pivot %d): some "
            "motion would have no kinetic energy", bad);

    /* initial state, and a_0 from the equation of motion: M a0 = F0 - C v0 - K q0 */
    for (int i = 0; i < n; i++) {
        r.q[i] = p->q0 ? p->q0[i] : 0.0;
        r.v[i] = p->qd0 ? p->qd0[i] : 0.0;
    }
    if ((rc = eval_force(&r, p->t0, r.q, r.v, r.F)))
        return rc;
    matvec(n, p->K, r.q, r.Kq);
    matvec(n, p->C, r.v, r.Cv);
    for (int i = 0; i < n; i++)
        r.a[i] = r.F[i] - r.Cv[i] - r.Kq[i];
    memcpy(r.S, p->M, (size_t)n * (size_t)n * sizeof *r.S);
    res->factorizations++;
    if (lu_factor(n, r.S, r.piv))   /* cannot happen after Cholesky; kept honest */
        return mm_error_set(err, MM_ESINGULAR, "M", "the mass matrix 'M' is singular");
    lu_solve(n, r.S, r.piv, r.a);
    matvec(n, p->M, r.a, r.Ma);

    /* highest natural frequency of the tangent system at t0, for the limit */
    if ((rc = eval_jacobian(&r, p->t0, r.q, r.v, r.F)))
        return rc;
    for (int i = 0; i < n; i++)
        for (int j = 0; j <= i; j++) {
            double kij = (p->K ? p->K[i * n + j] : 0.0) - r.Jq[i * n + j];
            double kji = (p->K ? p->K[j * n + i] : 0.0) - r.Jq[j * n + i];
            r.Jq[i * n + j] = r.Jq[j * n + i] = 0.5 * (kij + kji);
        }
    if ((rc = exact_omega_max(&r, &res->omega_max)))
        return rc;
    if (omega_h_crit(&r) > 0.0 && res->omega_max > 0.0)
        res->h_stable = omega_h_crit(&r) / res->omega_max;

    /* the matrix each step solves with, when it does not change */
    const double h = o->h;
    if (o->method == MM_NEWMARK_CENTRAL) {           /* M + h/2 C */
        for (int i = 0; i < n * n; i++)
            r.S[i] = p->M[i] + (p->C ? 0.5 * h * p->C[i] : 0.0);
        res->factorizations++;
        if (lu_factor(n, r.S, r.piv))
            return mm_error_set(err, MM_ESINGULAR, "h",
                "the matrix M + h/2 C of central difference is singular for h = %g s: "
                "change 'h'", h);
    } else if (o->method != MM_NEWMARK_VERLET && r.linear) {
        memset(r.Jq, 0, (size_t)n * (size_t)n * sizeof *r.Jq);
        memset(r.Jv, 0, (size_t)n * (size_t)n * sizeof *r.Jv);
        if ((rc = build_effective(&r, 0, p->t0)))
            return rc;
    }                               /* Verlet keeps the LU of M from above */

    /* energy at t0 and row 0 */
    mm_newmark_energy e0;
    r.E0 = energy_of(&r, r.q, r.v, r.Kq, &e0);
    res->energy_start = r.E0;
    res->energy_end = e0;
    r.escale = fabs(r.E0);
    int storing = res->t || res->q || res->qd || res->qdd || res->energy;
    if (storing)
        store_row(&r, 0, p->t0, r.q, r.v, r.a, r.Kq);
    if (res->observe && (rc = res->observe(0, p->t0, r.q, r.v, r.a, res->observe_params))) {
        rc = callback_failed(&r, rc, "observer", p->t0);
        goto out;
    }
    int next_row = 1;
    long next_step = rows > 1 ? row_step(o, N, rows, 1) : -1;

    for (long k = 0; k < N; k++) {
        double t1 = p->t0 + (double)(k + 1) * h;    /* t_k = t0 + k h, not summed */
        if (o->method == MM_NEWMARK_CENTRAL)
            rc = step_central(&r, t1);
        else if (o->method == MM_NEWMARK_VERLET)
            rc = step_verlet(&r, t1);
        else
            rc = step_implicit(&r, t1);
        if (rc)
            goto out;
        if (!all_finite(n, r.q1) || !all_finite(n, r.v1) || !all_finite(n, r.a1) ||
            !account_energy(&r)) {
            rc = blew_up(&r, t1);
            goto out;
        }
        swap_states(&r);
        res->steps = k + 1;
        if (res->observe && (rc = res->observe(k + 1, t1, r.q, r.v, r.a, res->observe_params))) {
            rc = callback_failed(&r, rc, "observer", t1);
            goto out;
        }
        if (k + 1 == next_step) {
            if (storing)
                store_row(&r, next_row, t1, r.q, r.v, r.a, r.Kq);
            next_row++;
            next_step = next_row < rows ? row_step(o, N, rows, next_row) : -1;
        }
    }
    rc = MM_OK;
out:
    res->energy_error = r.escale > 0.0 ? res->energy_balance / r.escale : 0.0;
    return rc;
}

/* ======================================================================== */
/* The amplification matrix                                                 */
/* ======================================================================== */

/* Every scheme's step on a linear system, written from (N1), (N2), (G):
 *   q_{k+1} = q_k + h v_k + h^2 (1/2 - beta) a_k + beta h^2 a_{k+1}
 *   v_{k+1} = v_k + h (1 - gamma) a_k + gamma h a_{k+1}
 *   S a_{k+1} = -K q_k - Rv v_k - Ra a_k + af F_k + (1 - af) F_{k+1}
 * with, from (G),
 *   S  = (1 - am) M + (1 - af) (gamma h C + beta h^2 K)
 *   Rv = C + (1 - af) h K
 *   Ra = am M + (1 - af) (h (1 - gamma) C + h^2 (1/2 - beta) K).
 * Central difference is beta = 0, gamma = 1/2.  Verlet is the same but its
 * damping force sees the half-step velocity v_k + h/2 a_k, not v_{k+1}, so
 * its S is M alone. */
int mm_newmark_amplification(int n, const double *M, const double *C, const double *K,
                             const mm_newmark_options *o, double *A, double *B0,
                             double *B1, mm_error *err)
{
    assert(M && o && A);
    if (n < 1 || n > MM_NEWMARK_MAX_DOF)
        return mm_error_set(err, MM_ERANGE, "n",
            "the number of degrees of freedom 'n' must be between 1 and %d, got %d",
            MM_NEWMARK_MAX_DOF, n);
    mm_newmark_problem p = {.n = n, .M = M, .C = C, .K = K, .t0 = 0, .t_end = o->h};
    mm_newmark_options oo = *o;
    oo.stride = 1;
    oo.points = 0;
    int rc = mm_newmark_check(&p, &oo, err);
    if (rc)
        return rc;
    run r = {.o = o};
    set_parameters(&r);
    const double h = o->h, be = r.beta, ga = r.gamma, am = r.am, af = r.af;
    const size_t nn = (size_t)n * (size_t)n;
    const int n3 = 3 * n;
    double *S = malloc(nn * sizeof *S), *R = malloc(3 * nn * sizeof *R);
    int *piv = malloc((size_t)n * sizeof *piv);
    if (!S || !R || !piv) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
        goto out;
    }
    /* R = [K | Rv | Ra], n x 3n, row-major */
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            size_t ij = (size_t)i * n + j;
            double k = K ? K[ij] : 0.0, c = C ? C[ij] : 0.0, m = M[ij];
            S[ij] = o->method == MM_NEWMARK_VERLET
                        ? m
                        : (1 - am) * m + (1 - af) * (ga * h * c + be * h * h * k);
            R[(size_t)i * n3 + j] = k;
            R[(size_t)i * n3 + n + j] = c + (1 - af) * h * k;
            R[(size_t)i * n3 + 2 * n + j] = am * m + (1 - af) * (h * (1 - ga) * c + h * h * (0.5 - be) * k);
        }
    if (lu_factor(n, S, piv)) {
        rc = mm_error_set(err, MM_ESINGULAR, "h",
            "the matrix a step of %s solves with is singular at h = %g s",
            mm_newmark_method_name(o->method), h);
        goto out;
    }
    /* the rows of a_{k+1}: -S^-1 R, column by column */
    double *col = malloc((size_t)n * sizeof *col);
    if (!col) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
        goto out;
    }
    memset(A, 0, (size_t)n3 * n3 * sizeof *A);
    for (int j = 0; j < n3; j++) {
        for (int i = 0; i < n; i++)
            col[i] = -R[(size_t)i * n3 + j];
        lu_solve(n, S, piv, col);
        for (int i = 0; i < n; i++)
            A[(size_t)(2 * n + i) * n3 + j] = col[i];
    }
    /* the rows of q_{k+1} and v_{k+1} */
    for (int i = 0; i < n; i++) {
        double *aq = A + (size_t)i * n3, *av = A + (size_t)(n + i) * n3;
        const double *aa = A + (size_t)(2 * n + i) * n3;
        for (int j = 0; j < n3; j++) {
            aq[j] = be * h * h * aa[j];
            av[j] = ga * h * aa[j];
        }
        aq[i] += 1;
        aq[n + i] += h;
        aq[2 * n + i] += h * h * (0.5 - be);
        av[n + i] += 1;
        av[2 * n + i] += h * (1 - ga);
    }
    /* the load: a_{k+1} gains S^-1 (af F_k + (1 - af) F_{k+1}) */
    for (int b = 0; b < 2; b++) {
        double *B = b == 0 ? B0 : B1, w = b == 0 ? af : 1 - af;
        if (!B)
            continue;
        memset(B, 0, (size_t)n3 * n * sizeof *B);
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++)
                col[i] = i == j ? w : 0.0;
            lu_solve(n, S, piv, col);
            for (int i = 0; i < n; i++) {
                B[(size_t)(2 * n + i) * n + j] = col[i];
                B[(size_t)i * n + j] = be * h * h * col[i];
                B[(size_t)(n + i) * n + j] = ga * h * col[i];
            }
        }
    }
    free(col);
    rc = MM_OK;
out:
    free(piv);
    free(R);
    free(S);
    return rc;
}

double mm_newmark_spectral_radius(const mm_newmark_options *o, double omega, double zeta)
{
    double M = 1, C = 2 * zeta * omega, K = omega * omega, A[9], wr[3], wi[3];
    mm_error err;
    if (!(omega >= 0) || !(zeta >= 0) ||
        mm_newmark_amplification(1, &M, &C, &K, o, A, NULL, NULL, &err) != MM_OK ||
        mm_linalg_geev(3, A, wr, wi, NULL, &err) != MM_OK)
        return NAN;
    double rho = 0;
    for (int i = 0; i < 3; i++)
        rho = fmax(rho, hypot(wr[i], wi[i]));
    return rho;
}
