/* mm_symplectic.c — Gauss–Legendre collocation by fixed-point iteration
 * (see mm_symplectic.h). */
#include "mm_symplectic.h"

#include <assert.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>

#define SQ3_6 0.28867513459481288225     /* sqrt(3)/6 */

/* Butcher tableaux: c, A (row-major s x s), b (GNI table II.1.1 and eq. II.1.9) */
static const double c1[1] = {0.5}, a1[1] = {0.5}, b1[1] = {1};
static const double c2[2] = {0.5 - SQ3_6, 0.5 + SQ3_6};
static const double a2[4] = {0.25, 0.25 - SQ3_6, 0.25 + SQ3_6, 0.25};
static const double b2[2] = {0.5, 0.5};

struct mm_symp_work {
    size_t cap;
    double *y, *comp, *Z, *Znew, *k, *Y, *kbar, *scale;
    double *J;              /* n x n: df/dy at the step's start */
    double *Mat;            /* sn x sn: I - h A (x) J, LU-factored */
    double *f0;             /* n: f at the step's start */
    int *piv;               /* sn */
};

/* int_0^theta of the Lagrange polynomial l_j on the nodes c (s = 1 or 2):
 * the collocation polynomial is u(t0 + theta h) = y0 + h sum_j k_j L_j(theta) */
static double lagrange_int(int s, const double *c, int j, double th)
{
    if (s == 1)
        return th;
    double o = c[1 - j];
    return (0.5 * th * th - o * th) / (c[j] - o);
}

void mm_symp_options_init(mm_symp_options *opt)
{
    opt->method = MM_SYMP_GAUSS4;
    opt->h = 0.01;
    opt->max_steps = 1000000;
    opt->max_iter = 60;
}

const char *mm_symp_method_name(mm_symp_method method)
{
    switch (method) {
    case MM_SYMP_MIDPOINT:
        return "implicit-midpoint";
    case MM_SYMP_GAUSS4:
        return "gauss-legendre-4";
    }
    return "unknown";
}

int mm_symp_order(mm_symp_method method)
{
    return method == MM_SYMP_MIDPOINT ? 2 : method == MM_SYMP_GAUSS4 ? 4 : 0;
}

mm_symp_work *mm_symp_work_alloc(size_t n)
{
    if (n == 0 || n > MM_SYMP_MAX_DIM)
        return NULL;
    mm_symp_work *w = malloc(sizeof *w);
    double *p = calloc(13 * n + n * n + 4 * n * n, sizeof *p);
    int *piv = calloc(2 * n, sizeof *piv);
    if (!w || !p || !piv) {
        free(w);
        free(p);
        free(piv);
        return NULL;
    }
    w->piv = piv;
    w->f0 = p + 12 * n;
    w->J = p + 13 * n;
    w->Mat = p + 13 * n + n * n;
    w->cap = n;
    w->y = p;
    w->comp = p + n;
    w->Z = p + 2 * n;         /* 2 n */
    w->Znew = p + 4 * n;      /* 2 n */
    w->k = p + 6 * n;         /* 2 n */
    w->Y = p + 8 * n;
    w->kbar = p + 9 * n;
    w->scale = p + 10 * n;
    return w;
}

void mm_symp_work_free(mm_symp_work *w)
{
    if (!w)
        return;
    free(w->y);
    free(w->piv);
    free(w);
}

/* LU factorisation with partial pivoting of the m x m row-major A, in
 * place; -1 if singular. */
static int lu(int m, double *A, int *piv)
{
    for (int k = 0; k < m; k++) {
        int p = k;
        for (int i = k + 1; i < m; i++)
            if (fabs(A[i * m + k]) > fabs(A[p * m + k]))
                p = i;
        piv[k] = p;
        if (A[p * m + k] == 0)
            return -1;
        if (p != k)
            for (int j = 0; j < m; j++) {
                double t = A[k * m + j];
                A[k * m + j] = A[p * m + j];
                A[p * m + j] = t;
            }
        for (int i = k + 1; i < m; i++) {
            A[i * m + k] /= A[k * m + k];
            for (int j = k + 1; j < m; j++)
                A[i * m + j] -= A[i * m + k] * A[k * m + j];
        }
    }
    return 0;
}

static void lu_solve(int m, const double *A, const int *piv, double *b)
{
    for (int k = 0; k < m; k++) {                     /* all the row interchanges first */
        double t = b[piv[k]];
        b[piv[k]] = b[k];
        b[k] = t;
    }
    for (int k = 0; k < m; k++)                       /* then L (unit diagonal) */
        for (int i = k + 1; i < m; i++)
            b[i] -= A[i * m + k] * b[k];
    for (int k = m - 1; k >= 0; k--) {
        for (int j = k + 1; j < m; j++)
            b[k] -= A[k * m + j] * b[j];
        b[k] /= A[k * m + k];
    }
}

/* The Newton matrix I - h A (x) J, LU-factored into w->Mat, with J = df/dy
 * at (t, yb) by forward differences.  MM_OK, MM_ESINGULAR, or f's code. */
static int newton_matrix(const mm_symp_problem *prob, mm_symp_work *w, int s, const double *A, double h,
                         double t, const double *yb, mm_symp_result *res)
{
    const size_t n = prob->n;
    const int sn = s * (int)n;
    double *yp = w->Znew;                             /* scratch (n values) */
    int rc = prob->f(t, yb, w->f0, prob->params);
    res->n_eval++;
    if (rc != 0)
        return rc;
    for (size_t j = 0; j < n; j++) {
        for (size_t i = 0; i < n; i++)
            yp[i] = yb[i];
        double dj = 1.4901161193847656e-08 * fmax(fabs(yb[j]), w->scale[j]);
        yp[j] += dj;
        rc = prob->f(t, yp, w->Y, prob->params);
        res->n_eval++;
        if (rc != 0)
            return rc;
        for (size_t i = 0; i < n; i++)
            w->J[i * n + j] = (w->Y[i] - w->f0[i]) / dj;
    }
    for (int i = 0; i < s; i++)
        for (int l = 0; l < s; l++)
            for (size_t a = 0; a < n; a++)
                for (size_t b = 0; b < n; b++)
                    w->Mat[((size_t)i * n + a) * (size_t)sn + (size_t)l * n + b] =
                        (i == l && a == b ? 1 : 0) - h * A[i * s + l] * w->J[a * n + b];
    return lu(sn, w->Mat, w->piv) == 0 ? MM_OK : MM_ESINGULAR;
}

static long step_count(const mm_symp_problem *prob, const mm_symp_options *opt)
{
    double N = ceil((prob->t_end - prob->t0) / opt->h);
    return N > (double)MM_SYMP_MAX_STEPS ? MM_SYMP_MAX_STEPS + 1 : (long)N;
}

int mm_symp_check(const mm_symp_problem *prob, const mm_symp_options *opt, mm_error *err)
{
    assert(prob && opt && prob->f && prob->y0);
    if (prob->n < 1 || prob->n > MM_SYMP_MAX_DIM)
        return mm_error_set(err, MM_ERANGE, "n", "n must be 1..%d equations; got %zu", MM_SYMP_MAX_DIM,
                            prob->n);
    if (!isfinite(prob->t0) || !isfinite(prob->t_end))
        return mm_error_set(err, MM_EVALUE, "t_end", "t0 and t_end must be finite");
    if (!(prob->t_end > prob->t0))
        return mm_error_set(err, MM_ERANGE, "t_end", "t_end must be after t0; got %g <= %g", prob->t_end,
                            prob->t0);
    for (size_t j = 0; j < prob->n; j++) {
        if (!isfinite(prob->y0[j]))
            return mm_error_set(err, MM_EVALUE, "y0", "y0[%zu] is not finite", j);
        if (prob->scale && !(prob->scale[j] > 0 && isfinite(prob->scale[j])))
            return mm_error_set(err, MM_ERANGE, "scale", "scale[%zu] must be a positive number", j);
    }
    if (opt->method != MM_SYMP_MIDPOINT && opt->method != MM_SYMP_GAUSS4)
        return mm_error_set(err, MM_ERANGE, "method", "unknown method %d", (int)opt->method);
    if (!isfinite(opt->h))
        return mm_error_set(err, MM_EVALUE, "h", "h must be finite");
    if (!(opt->h > 0))
        return mm_error_set(err, MM_ERANGE, "h", "h must be > 0; got %g", opt->h);
    if (opt->max_steps < 1 || opt->max_steps > MM_SYMP_MAX_STEPS)
        return mm_error_set(err, MM_ERANGE, "max_steps", "max_steps must be 1..%ld", MM_SYMP_MAX_STEPS);
    if (opt->max_iter < 2 || opt->max_iter > 200)
        return mm_error_set(err, MM_ERANGE, "max_iter", "max_iter must be 2..200; got %d", opt->max_iter);
    long N = step_count(prob, opt);
    if (N > opt->max_steps)
        return mm_error_set(err, MM_ERANGE, "h",
                            "h = %g needs %ld or more steps to reach t_end; at most %ld are allowed",
                            opt->h, N, opt->max_steps);
    double hh = (prob->t_end - prob->t0) / (double)N;
    if (prob->t0 + hh == prob->t0 || prob->t_end - hh == prob->t_end)
        return mm_error_set(err, MM_ERANGE, "h", "h = %g is too small to advance t in double precision",
                            opt->h);
    return MM_OK;
}

static int f_code(int rc)
{
    return rc > MM_OK && rc < MM_STATUS_COUNT ? rc : MM_EINTERNAL;
}

int mm_symp_solve(const mm_symp_problem *prob, const mm_symp_options *opt, mm_symp_work *w,
                  mm_symp_observer observe, void *obs_params, double *y_end,
                  mm_symp_result *res, mm_error *err)
{
    mm_symp_result dummy;
    if (!res)
        res = &dummy;
    *res = (mm_symp_result){.t_reached = prob->t0};
    int rc = mm_symp_check(prob, opt, err);
    if (rc != MM_OK)
        return rc;
    if (!w)
        return mm_error_set(err, MM_ENOMEM, "", "no workspace");
    assert(w->cap >= prob->n);

    const size_t n = prob->n;
    const int s = opt->method == MM_SYMP_MIDPOINT ? 1 : 2;
    const double *c = s == 1 ? c1 : c2, *A = s == 1 ? a1 : a2, *b = s == 1 ? b1 : b2;
    const long N = step_count(prob, opt);
    const double h = (prob->t_end - prob->t0) / (double)N;
    res->h = h;

    for (size_t j = 0; j < n; j++) {
        w->y[j] = prob->y0[j];
        w->comp[j] = 0;
        w->scale[j] = prob->scale ? prob->scale[j] : fmax(fabs(prob->y0[j]), 1.0);
    }
    /* the first guess of the stages: h c_i f(t0, y0); later ones extrapolate
     * the previous step's collocation polynomial (GNI VIII.6.1) */
    double B[4];
    for (int i = 0; i < s; i++)
        for (int j = 0; j < s; j++)
            B[i * s + j] = lagrange_int(s, c, j, 1 + c[i]) - lagrange_int(s, c, j, 1);
    rc = prob->f(prob->t0, w->y, w->kbar, prob->params);
    res->n_eval++;
    if (rc != 0)
        return mm_error_set(err, f_code(rc), "f", "the right-hand side stopped at t = %g", prob->t0);
    if (observe && (rc = observe(0, prob->t0, w->y, obs_params)) != 0)
        return mm_error_set(err, f_code(rc), "observer", "the observer stopped at t = %g", prob->t0);

    long iter_sum = 0;
    for (long step = 1; step <= N; step++) {
        double t = prob->t0 + (double)(step - 1) * h;
        for (int i = 0; i < s; i++)
            for (size_t j = 0; j < n; j++) {
                double z = 0;
                if (step == 1)
                    z = c[i] * w->kbar[j];
                else
                    for (int l = 0; l < s; l++)
                        z += B[i * s + l] * w->k[l * n + j];
                w->Z[i * n + j] = h * z;
            }
        /* simplified Newton iteration on Z - h A F(Z) = 0 with the Jacobian
         * at the step's start, (I - h A (x) J) dZ = -(Z - h A F(Z)), until
         * round-off (GNI VIII.6.2); it converges also where plain fixed-point
         * iteration would not (h L near 1) */
        const int sn = s * (int)n;
        rc = newton_matrix(prob, w, s, A, h, t, w->y, res);
        if (rc != MM_OK)
            return rc == MM_ESINGULAR
                       ? mm_error_set(err, MM_ENOCONV, "h",
                                      "the Newton matrix of the stage equations is singular at t = %.6g s; "
                                      "lower h", t)
                       : mm_error_set(err, f_code(rc), "f", "the right-hand side stopped at t = %g", t);
        double dprev = INFINITY;
        int it = 0, done = 0, updates = 0;
        while (!done) {
            if (++it > opt->max_iter)
                return mm_error_set(err, MM_ENOCONV, "h",
                                    "the implicit stage equations did not converge in %d iterations at "
                                    "t = %.6g s: the step h = %g is too large for the fastest motion; lower h",
                                    opt->max_iter, t, h);
            for (int i = 0; i < s; i++) {
                for (size_t j = 0; j < n; j++)
                    w->Y[j] = w->y[j] + w->Z[i * n + j];
                rc = prob->f(t + c[i] * h, w->Y, w->k + i * n, prob->params);
                res->n_eval++;
                if (rc != 0)
                    return mm_error_set(err, f_code(rc), "f", "the right-hand side stopped at t = %g",
                                        t + c[i] * h);
            }
            for (int i = 0; i < s; i++)                    /* -(Z - h A F(Z)) */
                for (size_t j = 0; j < n; j++) {
                    double z = 0;
                    for (int l = 0; l < s; l++)
                        z += A[i * s + l] * w->k[l * n + j];
                    w->Znew[i * n + j] = h * z - w->Z[i * n + j];
                }
            lu_solve(sn, w->Mat, w->piv, w->Znew);
            double d = 0;
            for (int i = 0; i < s; i++)
                for (size_t j = 0; j < n; j++) {
                    d = fmax(d, fabs(w->Znew[i * n + j]) / (fabs(w->y[j]) + w->scale[j]));
                    w->Z[i * n + j] += w->Znew[i * n + j];
                }
            if (!(d < INFINITY))
                return mm_error_set(err, MM_ENONFINITE, "h",
                                    "the state became infinite or NaN at t = %.6g s; lower h", t);
            if (d <= 2 * DBL_EPSILON || (d >= dprev && d < 1e-10)) {
                done = 1;                           /* round-off reached */
            } else if (d > 1e3 || (d > 0.25 * dprev && d > 1e-8)) {
                /* slow or no convergence: the Jacobian of the step's start is
                 * too far from the stages' (strongly nonlinear f): take it
                 * at the mean stage instead, a few times at most */
                if (d > 1e3 && ++updates > 4)
                    return mm_error_set(err, MM_ENOCONV, "h",
                                        "the implicit stage equations diverge at t = %.6g s: the step h = %g "
                                        "is too large for the fastest motion; lower h", t, h);
                if (updates < 8) {
                    for (size_t j = 0; j < n; j++) {
                        double z = 0;
                        for (int i = 0; i < s; i++)
                            z += w->Z[i * n + j];
                        w->kbar[j] = w->y[j] + z / s;    /* kbar: scratch until the step ends */
                    }
                    rc = newton_matrix(prob, w, s, A, h, t + 0.5 * h, w->kbar, res);
                    if (rc != MM_OK)
                        return mm_error_set(err, rc == MM_ESINGULAR ? MM_ENOCONV : f_code(rc), "h",
                                            "the stage equations could not be solved at t = %.6g s; lower h", t);
                    updates += d <= 1e3;
                }
                if (d > 1e3)                       /* restart from the step's start */
                    for (size_t q = 0; q < (size_t)s * n; q++)
                        w->Z[q] = 0;
            }
            dprev = d > 1e3 ? INFINITY : d;
        }
        /* k now holds f at the stages of the last iterate; the final update
         * of Z changed them by round-off only, so no extra evaluation */
        iter_sum += it;
        if (it > res->iter_max)
            res->iter_max = it;
        /* y1 = y0 + h sum b_i k_i, summed with Kahan's compensation */
        for (size_t j = 0; j < n; j++) {
            double inc = 0;
            for (int i = 0; i < s; i++)
                inc += b[i] * w->k[i * n + j];
            w->kbar[j] = inc;                       /* next step's first guess */
            double yk = inc * h - w->comp[j], sum = w->y[j] + yk;
            w->comp[j] = (sum - w->y[j]) - yk;
            w->y[j] = sum;
            if (!isfinite(sum))
                return mm_error_set(err, MM_ENONFINITE, "h",
                                    "the state became infinite or NaN at t = %.6g s; lower h", t + h);
        }
        res->n_steps = step;
        res->t_reached = step == N ? prob->t_end : prob->t0 + (double)step * h;
        res->iter_mean = (double)iter_sum / (double)step;
        if (observe && (rc = observe(step, res->t_reached, w->y, obs_params)) != 0)
            return mm_error_set(err, f_code(rc), "observer", "the observer stopped at t = %g",
                                res->t_reached);
    }
    if (y_end)
        for (size_t j = 0; j < n; j++)
            y_end[j] = w->y[j];
    return MM_OK;
}
