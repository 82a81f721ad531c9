/* newmark.c — num-newmark: the equations of motion of a small mechanical
 * system, M q'' + C q' + K q = F(q, q', t), integrated step by step by the
 * Newmark family (the book's `newmark` / `defphy` pair).
 *
 *     M q'' + C q' + K q = F cos(omega t) - knl q1^3 e1                  (1)
 *
 * The system is given by its mass, damping and stiffness matrices (default:
 * two masses in a chain, wall-k-m-k-m), driven by harmonic forces, with an
 * optional hardening cubic spring on the first coordinate that makes the
 * problem nonlinear (each implicit step is then solved by Newton's method).
 * Goal: what a fixed-step implicit integrator does: average acceleration is
 * stable at any step and conserves energy, linear acceleration and central
 * difference are stable only below a step limit set by the highest
 * frequency, HHT-alpha damps the highest frequencies on purpose; all are
 * second order, so halving h divides the error by four.
 * Checks: the linear response against its exact solution by (complex,
 * state-space) modal superposition, or against DOP853 at a tight tolerance
 * when there is none (nonlinear spring, defective modes, undamped
 * resonance), with the a-priori error bound of the scheme as tolerance;
 * the observed order from a second run at h/2; the energy balance
 * recomputed from the trajectory (exact for average acceleration).  Beside
 * these independent checks, a consistency check (labelled so): the
 * equation of motion the scheme solved, recomputed at every step.
 * Reference: N. M. Newmark, J. Eng. Mech. Div. ASCE 85 (1959) 67-94;
 * T. J. R. Hughes, The Finite Element Method, Dover 2000, ch. 9;
 * H. M. Hilber, T. J. R. Hughes, R. L. Taylor, Earthq. Eng. Struct. Dyn. 5
 * (1977) 283-292.
 */
#include <complex.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mm_complex.h"
#include "mm_exhelp.h"
#include "mm_linalg.h"
#include "mm_newmark.h"
#include "mm_ode.h"

#define MAXN 6
#define MAX_STEPS 50000L     /* steps of one run */
#define MAX_WORK 450000.0    /* steps x (n + 1)^2, times 3 with the cubic spring (Newton) */
#define ERR_SAMPLES 2000     /* step points where the error is measured */

enum { P_M, P_C, P_K, P_F, P_OMEGA, P_Q0, P_V0, P_KNL, P_METHOD, P_ALPHA, P_H, P_TEND, P_POINTS };
enum { ME_AVERAGE, ME_LINEAR, ME_HHT, ME_CENTRAL };

static const char *const methods[] = {"average-acceleration", "linear-acceleration", "hht-alpha",
                                      "central-difference", NULL};

static const mm_param params[] = {
    [P_M] = {"M", "mass matrix", "kg", MM_MATRIX, 0, -1e4, 1e4, "1,0;0,1", NULL, MAXN, MAXN,
             .help = "symmetric positive definite, n x n (n <= 6); diagonal for point masses"},
    [P_C] = {"C", "damping matrix", "N s/m", MM_MATRIX, 0, -1e4, 1e4, "1,-0.5;-0.5,0.5", NULL, MAXN, MAXN,
             .help = "symmetric, positive semidefinite, n x n; the default is 0.005 K"},
    [P_K] = {"K", "stiffness matrix", "N/m", MM_MATRIX, 0, -1e7, 1e7, "200,-100;-100,100", NULL, MAXN, MAXN,
             .help = "symmetric, positive semidefinite, n x n; the default is a chain wall-k-m-k-m, k = 100 N/m"},
    [P_F] = {"F", "force amplitudes", "N", MM_VECTOR, 0, -1e4, 1e4, "0,1", NULL, 0, MAXN,
             .help = "the force on each coordinate is F_i cos(omega t); n values"},
    [P_OMEGA] = {"omega", "forcing frequency", "rad/s", MM_REAL, 5, 0, 1e3,
                 .help = "angular frequency of the forces; 0 gives a constant (step) load"},
    [P_Q0] = {"q0", "initial displacements", "m", MM_VECTOR, 0, -10, 10, "0,0", NULL, 0, MAXN,
              .help = "q at t = 0; n values"},
    [P_V0] = {"v0", "initial velocities", "m/s", MM_VECTOR, 0, -1e3, 1e3, "0,0", NULL, 0, MAXN,
              .help = "dq/dt at t = 0; n values"},
    [P_KNL] = {"knl", "cubic spring on q1", "N/m^3", MM_REAL, 0, 0, 1e6,
               .help = "a hardening spring force -knl q1^3 on the first coordinate: the problem becomes "
                       "nonlinear and each implicit step is solved by Newton's method"},
    [P_METHOD] = {"method", "integrator", "", MM_CHOICE, ME_AVERAGE, 0, 0, .choices = methods,
                  .help = "the Newmark scheme: average acceleration (beta 1/4), linear acceleration "
                          "(beta 1/6), HHT-alpha, central difference (explicit)"},
    [P_ALPHA] = {"alpha", "HHT alpha", "", MM_REAL, -0.1, -1.0 / 3, 0,
                 .help = "numerical damping of hht-alpha: 0 is average acceleration, -1/3 damps the most"},
    [P_H] = {"h", "time step", "s", MM_REAL, 0.01, 1e-5, 1, .help = "the fixed step of the integrator"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 10, 1e-3, 1e3,
                .help = "simulated time; at most 1e4 radians of the fastest motion and 5e4 steps (fewer for "
                        "larger systems and with the cubic spring)"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 501, 11, 2001,
                  .help = "steps returned for the plot, spread evenly over the run"},
};

/* ---- the system ---------------------------------------------------------------- */

typedef struct sys {
    int n;
    const double *M, *C, *K, *F, *q0, *v0;
    double w, knl;
    double Minv[MAXN * MAXN];   /* for the DOP853 reference */
} sys;

static void sys_of(const mm_value *in, sys *s)
{
    memset(s, 0, sizeof *s);
    s->n = in[P_M].rows;
    s->M = in[P_M].data;
    s->C = in[P_C].data;
    s->K = in[P_K].data;
    s->F = in[P_F].data;
    s->q0 = in[P_Q0].data;
    s->v0 = in[P_V0].data;
    s->w = in[P_OMEGA].x;
    s->knl = in[P_KNL].x;
}

static int force(double t, const double *q, const double *qd, double *F, void *ctx)
{
    (void)qd;
    const sys *s = ctx;
    double c = cos(s->w * t);
    for (int i = 0; i < s->n; i++)
        F[i] = s->F[i] * c;
    F[0] -= s->knl * q[0] * q[0] * q[0];
    return 0;
}

static int jacobian(double t, const double *q, const double *qd, double *dFdq, double *dFdqd, void *ctx)
{
    (void)t;
    (void)qd;
    (void)dFdqd;
    const sys *s = ctx;
    dFdq[0] = -3 * s->knl * q[0] * q[0];
    return 0;
}

static int symmetric(const char *name, const mm_value *v, mm_error *err)
{
    int n = v->rows;
    double big = mm_maxabs(v->data, n * n);
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            if (fabs(v->data[i * n + j] - v->data[j * n + i]) > 1e-12 * big)
                return mm_error_set(err, MM_EVALUE, name, "%s must be symmetric, but %s(%d,%d) = %g and "
                                    "%s(%d,%d) = %g", name, name, i + 1, j + 1, v->data[i * n + j], name,
                                    j + 1, i + 1, v->data[j * n + i]);
    return MM_OK;
}

/* Natural frequencies omega_j^2 = lambda_j of K phi = lambda M phi (ascending)
 * and the mass-normalised modes; also checks that M is positive definite and
 * K, C positive semidefinite.  Kt: the stiffness to use (K, or a tangent). */
static int modes(const sys *s, const double *Kt, double *lam, double *Phi, int check_c, mm_error *err)
{
    int n = s->n;
    int rc = mm_linalg_sygv(n, Kt, s->M, lam, Phi, err);
    if (rc == MM_ESINGULAR)
        return mm_error_set(err, MM_ERANGE, "M", "M must be positive definite (every motion needs kinetic "
                            "energy); this one is not");
    if (rc != MM_OK)
        return rc;
    if (lam[0] < -1e-10 * fabs(lam[n - 1]))
        return mm_error_set(err, MM_ERANGE, "K", "K must be positive semidefinite (a stable system); its "
                            "lowest eigenvalue K phi = lambda M phi is %g", lam[0]);
    if (check_c) {
        double tmp[MAXN];
        rc = mm_linalg_sygv(n, s->C, s->M, tmp, NULL, err);
        if (rc != MM_OK)
            return rc;
        if (tmp[0] < -1e-10 * fabs(tmp[n - 1]))
            return mm_error_set(err, MM_ERANGE, "C", "C must be positive semidefinite (a damper takes energy "
                                "out, never puts it in); its lowest eigenvalue C phi = c M phi is %g", tmp[0]);
    }
    return MM_OK;
}

/* The fastest rate of the linearised system with stiffness Kt: the largest
 * |lambda| of A = [0 I; -M^-1 Kt  -M^-1 C] (omega_max when lightly damped,
 * the fast decay rate when a mode is overdamped). */
static int fastest_rate(const sys *s, const double *Kt, double *rate, mm_error *err)
{
    int n = s->n, n2 = 2 * n, rc;
    double MiK[MAXN * MAXN], MiC[MAXN * MAXN], A[4 * MAXN * MAXN], wr[2 * MAXN], wi[2 * MAXN];
    if ((rc = mm_linalg_solve(n, n, s->M, Kt, MiK, NULL, err)) != MM_OK ||
        (rc = mm_linalg_solve(n, n, s->M, s->C, MiC, NULL, err)) != MM_OK)
        return rc;
    memset(A, 0, sizeof A);
    for (int i = 0; i < n; i++) {
        A[i * n2 + n + i] = 1;
        for (int j = 0; j < n; j++) {
            A[(n + i) * n2 + j] = -MiK[i * n + j];
            A[(n + i) * n2 + n + j] = -MiC[i * n + j];
        }
    }
    if ((rc = mm_linalg_geev(n2, A, wr, wi, NULL, err)) != MM_OK)
        return rc;
    *rate = 0;
    for (int j = 0; j < n2; j++)
        *rate = fmax(*rate, hypot(wr[j], wi[j]));
    return MM_OK;
}

/* The highest omega h a scheme tolerates (undamped): central difference 2,
 * linear acceleration 2 sqrt(3); 0 = unconditionally stable. */
static double omega_h_limit(int method)
{
    return method == ME_CENTRAL ? 2 : method == ME_LINEAR ? 2 * sqrt(3.0) : 0;
}

static int check(const mm_value *in, mm_error *err)
{
    const mm_value *M = &in[P_M];
    int n = M->rows;
    if (M->cols != n)
        return mm_error_set(err, MM_ERANGE, "M", "M must be square; got %d x %d", n, M->cols);
    static const int mat[2] = {P_C, P_K};
    static const char *const mname[2] = {"C", "K"};
    for (int k = 0; k < 2; k++)
        if (in[mat[k]].rows != n || in[mat[k]].cols != n)
            return mm_error_set(err, MM_ERANGE, mname[k], "%s must be %d x %d like M; got %d x %d", mname[k], n,
                                n, in[mat[k]].rows, in[mat[k]].cols);
    static const int vec[3] = {P_F, P_Q0, P_V0};
    static const char *const vname[3] = {"F", "q0", "v0"};
    for (int k = 0; k < 3; k++)
        if (in[vec[k]].cols != n)
            return mm_error_set(err, MM_ERANGE, vname[k], "%s must have %d values, one per coordinate; got %d",
                                vname[k], n, in[vec[k]].cols);
    int rc;
    if ((rc = symmetric("M", M, err)) || (rc = symmetric("C", &in[P_C], err)) || (rc = symmetric("K", &in[P_K], err)))
        return rc;

    sys s;
    sys_of(in, &s);
    double lam[MAXN];
    if ((rc = modes(&s, s.K, lam, NULL, 1, err)) != MM_OK)
        return rc;
    /* the tangent stiffness at the start, with the cubic spring */
    double Kt[MAXN * MAXN];
    memcpy(Kt, s.K, sizeof(double) * n * n);
    Kt[0] += 3 * s.knl * s.q0[0] * s.q0[0];
    if ((rc = mm_linalg_sygv(n, Kt, s.M, lam, NULL, err)) != MM_OK)
        return rc;
    double wmax = sqrt(fmax(lam[n - 1], 0)), h = in[P_H].x, t_end = in[P_TEND].x, fast;
    if ((rc = fastest_rate(&s, Kt, &fast, err)) != MM_OK)
        return rc;
    double rate = fmax(fmax(wmax, fast), s.w);
    double per_step = (n + 1) * (n + 1) * (s.knl > 0 ? 3 : 1);
    double max_steps = fmin((double)MAX_STEPS, MAX_WORK / per_step);
    if (t_end / h > max_steps)
        return mm_error_set(err, MM_ERANGE, "h", "h = %g s takes %.3g steps to cover t_end = %g s; at most %.0f "
                            "fit one request for %d coordinates%s: make h at least %.3g s", h, t_end / h, t_end,
                            max_steps, n, s.knl > 0 ? " with Newton" : "", t_end / max_steps);
    if (t_end * rate > 1e4)
        return mm_error_set(err, MM_ERANGE, "t_end", "t_end = %g s spans %.3g radians of the fastest motion "
                            "(%.4g rad/s); at most 1e4 fit one request: make t_end at most %.4g s", t_end,
                            t_end * rate, rate, 1e4 / rate);
    int method = (int)in[P_METHOD].x;
    double lim = omega_h_limit(method);
    if (lim > 0 && wmax * h >= lim)
        return mm_error_set(err, MM_ERANGE, "h", "%s is stable only for omega_max h < %.4g; with omega_max = "
                            "%.4g rad/s that is h < %.4g s (got %g s); or take average-acceleration",
                            methods[method], lim, wmax, lim / wmax, h);
    return MM_OK;
}

/* ---- the references ------------------------------------------------------------- */

/* The steady response Re(X e^{i omega t}) to F cos(omega t), eq. (9):
 * [K - w^2 M, -w C; w C, K - w^2 M] [Xr; Xi] = [F; 0] into X = (Xr, Xi).
 * MM_ESINGULAR when there is none to be trusted (undamped resonance, a
 * free rigid-body mode under a constant load). */
static int particular(const sys *s, double *X, mm_error *err)
{
    int n = s->n, n2 = 2 * n, rc;
    double Z[4 * MAXN * MAXN], b[2 * MAXN];
    mm_linalg_solve_info info;
    for (int i = 0; i < n; i++) {
        b[i] = s->F[i];
        b[n + i] = 0;
        for (int j = 0; j < n; j++) {
            double d = s->K[i * n + j] - s->w * s->w * s->M[i * n + j], e = s->w * s->C[i * n + j];
            Z[i * n2 + j] = d;
            Z[i * n2 + n + j] = -e;
            Z[(n + i) * n2 + j] = e;
            Z[(n + i) * n2 + n + j] = d;
        }
    }
    if (!(mm_maxabs(s->F, n) > 0)) {
        memset(X, 0, sizeof(double) * n2);
        return MM_OK;
    }
    mm_error e2;
    rc = mm_linalg_solve(n2, 1, Z, b, X, &info, &e2);
    if (rc == MM_ESINGULAR || (rc == MM_OK && info.warn))
        return MM_ESINGULAR;
    if (rc != MM_OK)
        return mm_error_set(err, rc, e2.param, "%s", e2.msg);
    return MM_OK;
}

/* Exact solution of the linear system by superposition of the complex modes
 * of the state-space form y' = A y, A = [0 I; -M^-1 K  -M^-1 C] (eq. 9),
 * plus the particular solution Re(X e^{i omega t}), (K - omega^2 M + i omega C) X = F.
 * Returns MM_OK, or MM_ESINGULAR when there is none to be trusted (a
 * resonance without damping, defective modes: critical damping, rigid
 * body motion). */
typedef struct modal {
    int n2;
    double complex lam[2 * MAXN], c[2 * MAXN], V[2 * MAXN * 2 * MAXN];
    double Xr[MAXN], Xi[MAXN];
} modal;

static int modal_init(const sys *s, modal *md, double *rcond, mm_error *err)
{
    int n = s->n, n2 = 2 * n;
    md->n2 = n2;
    double MiK[MAXN * MAXN], MiC[MAXN * MAXN], A[4 * MAXN * MAXN], wr[2 * MAXN], wi[2 * MAXN],
        VR[4 * MAXN * MAXN];
    mm_linalg_solve_info info;
    int rc;
    if ((rc = mm_linalg_solve(n, n, s->M, s->K, MiK, &info, err)) != MM_OK ||
        (rc = mm_linalg_solve(n, n, s->M, s->C, MiC, &info, err)) != MM_OK)
        return rc;
    memset(A, 0, sizeof A);
    for (int i = 0; i < n; i++) {
        A[i * n2 + n + i] = 1;
        for (int j = 0; j < n; j++) {
            A[(n + i) * n2 + j] = -MiK[i * n + j];
            A[(n + i) * n2 + n + j] = -MiC[i * n + j];
        }
    }
    if ((rc = mm_linalg_geev(n2, A, wr, wi, VR, err)) != MM_OK)
        return rc;
    for (int j = 0; j < n2; j++) {
        md->lam[j] = mm_cmplx(wr[j], wi[j]);
        if (wi[j] > 0 && j + 1 < n2) {      /* a pair: columns j, j+1 are Re, Im */
            md->lam[j + 1] = mm_cmplx(wr[j + 1], wi[j + 1]);
            for (int i = 0; i < n2; i++) {
                md->V[i * n2 + j] = mm_cmplx(VR[i * n2 + j], VR[i * n2 + j + 1]);
                md->V[i * n2 + j + 1] = mm_cmplx(VR[i * n2 + j], -VR[i * n2 + j + 1]);
            }
            j++;
        } else {
            for (int i = 0; i < n2; i++)
                md->V[i * n2 + j] = VR[i * n2 + j];
        }
    }

    double X[2 * MAXN];
    if ((rc = particular(s, X, err)) != MM_OK)
        return rc;
    memcpy(md->Xr, X, sizeof(double) * n);
    memcpy(md->Xi, X + n, sizeof(double) * n);

    /* coefficients: V c = y(0) - y_p(0), as a real system of order 4n */
    int n4 = 2 * n2;
    double B[16 * MAXN * MAXN], rhs[4 * MAXN], cc[4 * MAXN];
    for (int i = 0; i < n2; i++) {
        for (int j = 0; j < n2; j++) {
            double vr = creal(md->V[i * n2 + j]), vi = cimag(md->V[i * n2 + j]);
            B[i * n4 + j] = vr;
            B[i * n4 + n2 + j] = -vi;
            B[(n2 + i) * n4 + j] = vi;
            B[(n2 + i) * n4 + n2 + j] = vr;
        }
        rhs[n2 + i] = 0;
    }
    for (int i = 0; i < n; i++) {
        rhs[i] = s->q0[i] - md->Xr[i];                 /* q_p(0) = Xr */
        rhs[n + i] = s->v0[i] + s->w * md->Xi[i];      /* q_p'(0) = -w Xi */
    }
    mm_error e3;
    rc = mm_linalg_solve(n4, 1, B, rhs, cc, &info, &e3);
    *rcond = info.rcond;
    if (rc == MM_ESINGULAR || (rc == MM_OK && info.warn))
        return MM_ESINGULAR;
    if (rc != MM_OK)
        return mm_error_set(err, rc, e3.param, "%s", e3.msg);
    for (int j = 0; j < n2; j++)
        md->c[j] = mm_cmplx(cc[j], cc[n2 + j]);
    return MM_OK;
}

static void modal_eval(const sys *s, const modal *md, double t, double *q, double *v)
{
    int n = s->n, n2 = md->n2;
    double complex e[2 * MAXN];
    for (int j = 0; j < n2; j++)
        e[j] = md->c[j] * cexp(md->lam[j] * t);
    double cw = cos(s->w * t), sw = sin(s->w * t);
    for (int i = 0; i < n; i++) {
        double complex yq = 0, yv = 0;
        for (int j = 0; j < n2; j++) {
            yq += md->V[i * n2 + j] * e[j];
            yv += md->V[(n + i) * n2 + j] * e[j];
        }
        q[i] = creal(yq) + md->Xr[i] * cw - md->Xi[i] * sw;
        v[i] = creal(yv) - s->w * (md->Xr[i] * sw + md->Xi[i] * cw);
    }
}

/* Eq. (1) as a first-order system y = (q, v) for DOP853. */
static int rhs(double t, const double *y, double *dy, void *ctx)
{
    const sys *s = ctx;
    int n = s->n;
    double r[MAXN];
    force(t, y, y + n, r, (void *)s);
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < n; j++)
            r[i] -= s->C[i * n + j] * y[n + j] + s->K[i * n + j] * y[j];
        dy[i] = y[n + i];
    }
    for (int i = 0; i < n; i++) {
        double a = 0;
        for (int j = 0; j < n; j++)
            a += s->Minv[i * n + j] * r[j];
        dy[n + i] = a;
    }
    return 0;
}

/* The second method: DOP853 at rtol 1e-11, dense output at the times t. */
static int dop853_ref(sys *s, int nt, const double *t, double t_end, double scale, double *q, double *v,
                      long *evals, mm_result *res, mm_error *err)
{
    int n = s->n, rc;
    double Id[MAXN * MAXN] = {0};
    for (int i = 0; i < n; i++)
        Id[i * n + i] = 1;
    if ((rc = mm_linalg_solve(n, n, s->M, Id, s->Minv, NULL, err)) != MM_OK)
        return rc;
    double y0[2 * MAXN];
    for (int i = 0; i < n; i++) {
        y0[i] = s->q0[i];
        y0[n + i] = s->v0[i];
    }
    double *y = mm_res_alloc(res, (size_t)nt * 2 * n * sizeof *y);
    if (!y)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_ode_problem prob = {.n = (size_t)(2 * n), .f = rhs, .params = s, .t0 = 0, .t_end = t_end, .y0 = y0};
    mm_ode_options opt;
    mm_ode_options_init(&opt);
    opt.method = MM_ODE_DOP853;
    opt.rtol = 1e-11;
    opt.atol = 1e-11 * scale;
    opt.max_steps = 100000;
    mm_ode_result r = {0};
    r.t_out = t;
    r.nout = (size_t)nt;
    r.y_out = y;
    rc = mm_ode_check(&prob, &opt, &r, err);
    mm_ode_work *w = rc == MM_OK ? mm_ode_work_alloc((size_t)(2 * n)) : NULL;
    if (rc == MM_OK)
        rc = w ? mm_ode_solve(&prob, &opt, w, &r, err) : mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_ode_work_free(w);
    *evals = r.n_eval;
    if (rc == MM_ENOCONV)
        return mm_error_set(err, MM_ERANGE, "knl", "the cubic spring stiffens the system so much that the "
                            "reference integration needs more than 1e5 steps; lower knl, the forces or t_end");
    if (rc != MM_OK)
        return rc;
    for (int k = 0; k < nt; k++)
        for (int i = 0; i < n; i++) {
            q[k * n + i] = y[k * 2 * n + i];
            v[k * n + i] = y[k * 2 * n + n + i];
        }
    return MM_OK;
}

/* ---- the Newmark runs ------------------------------------------------------------ */

typedef struct run_out {
    long steps, force_evals, newton_iters, factorizations;
    int rows;
    double *t, *q, *v, *a;      /* every step: rows x n */
} run_out;

static int newmark_run(sys *s, int method, double alpha, double h, double t_end, long stride, run_out *o,
                       mm_result *res, mm_error *err)
{
    int n = s->n;
    mm_newmark_problem prob = {.n = n, .M = s->M, .C = s->C, .K = s->K, .force = force,
                               .jacobian = s->knl > 0 ? jacobian : NULL,
                               .force_kind = s->knl > 0 ? MM_NEWMARK_FORCE_POSITION : MM_NEWMARK_FORCE_TIME,
                               .params = s, .q0 = s->q0, .qd0 = s->v0, .t0 = 0, .t_end = t_end};
    mm_newmark_options opt;
    mm_newmark_options_init(&opt);
    static const mm_newmark_method mm[4] = {MM_NEWMARK_AVERAGE, MM_NEWMARK_LINEAR, MM_NEWMARK_HHT,
                                            MM_NEWMARK_CENTRAL};
    opt.method = mm[method];
    opt.alpha = alpha;
    opt.h = h;
    opt.stride = stride;
    opt.newton_tol = 1e-12;
    opt.newton_max_iter = 50;
    opt.max_steps = 2 * MAX_STEPS + 1;
    int rc = mm_newmark_check(&prob, &opt, err);
    if (rc != MM_OK)
        return rc;
    int rows = mm_newmark_output_rows(&prob, &opt);
    o->t = mm_res_alloc(res, (size_t)rows * sizeof *o->t);
    o->q = mm_res_alloc(res, (size_t)rows * n * sizeof *o->q);
    o->v = mm_res_alloc(res, (size_t)rows * n * sizeof *o->v);
    o->a = mm_res_alloc(res, (size_t)rows * n * sizeof *o->a);
    if (!o->t || !o->q || !o->v || !o->a)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_newmark_result r = {.t = o->t, .q = o->q, .qd = o->v, .qdd = o->a, .max_rows = rows};
    mm_newmark_work *w = mm_newmark_work_alloc(n);
    if (!w)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    rc = mm_newmark_solve(&prob, &opt, w, &r, err);
    mm_newmark_work_free(w);
    o->steps = r.steps;
    o->force_evals = r.force_evals;
    o->newton_iters = r.newton_iters;
    o->factorizations = r.factorizations;
    o->rows = r.rows;
    if (rc == MM_ENOCONV)
        return mm_error_set(err, MM_ERANGE, "h", "Newton's method did not converge within 50 iterations at "
                            "h = %g s: the cubic spring changes too much within a step; reduce h or knl", h);
    if (rc == MM_ENONFINITE)
        return mm_error_set(err, MM_ERANGE, "h", "the solution grew without bound at h = %g s: the cubic "
                            "spring stiffened the system past the scheme's stability limit; reduce h", h);
    return rc;
}

/* ---- solve ---------------------------------------------------------------------- */

static double dotv(int n, const double *a, const double *b)
{
    double s = 0;
    for (int i = 0; i < n; i++)
        s += a[i] * b[i];
    return s;
}

static void matv(int n, const double *A, const double *x, double *y)
{
    for (int i = 0; i < n; i++)
        y[i] = dotv(n, A + i * n, x);
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    sys s;
    sys_of(in, &s);
    const int n = s.n, method = (int)in[P_METHOD].x, np = (int)in[P_POINTS].x;
    const double h = in[P_H].x, t_end = in[P_TEND].x, alpha = in[P_ALPHA].x;
    int rc;

    /* ---- natural frequencies ---- */
    double lam[MAXN], Phi[MAXN * MAXN];
    if ((rc = modes(&s, s.K, lam, Phi, 0, err)) != MM_OK)
        return rc;
    static const char *const mcols[] = {"mode", "omega", "zeta", "omega_h"};
    static const char *const munits[] = {"", "rad/s", "", ""};
    mm_table *mt = mm_res_table_v1(res, "modes", n, 4, mcols, munits);
    if (!mt)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    double Q = 1;     /* the largest dynamic magnification of a mode at omega */
    for (int j = 0; j < n; j++) {
        double wj = sqrt(fmax(lam[j], 0)), phi[MAXN], Cphi[MAXN];
        for (int i = 0; i < n; i++)
            phi[i] = Phi[i * n + j];
        matv(n, s.C, phi, Cphi);
        double cj = dotv(n, phi, Cphi);                  /* modal damping phi^T C phi */
        mt->cell[4 * j] = j + 1;
        mt->cell[4 * j + 1] = wj;
        mt->cell[4 * j + 2] = wj > 0 ? cj / (2 * wj) : 0;
        mt->cell[4 * j + 3] = wj * h;
        if (mm_maxabs(s.F, n) > 0) {
            double d = hypot(lam[j] - s.w * s.w, s.w * cj);
            Q = fmax(Q, d > 0 ? fmax(lam[j], s.w * s.w) / d : 1e300);
        }
    }
    double wmax = sqrt(fmax(lam[n - 1], 0));
    mm_res_scalar_v1(res, "n", "degrees of freedom", "", n);
    mm_res_scalar_v1(res, "omega_max", "highest natural frequency", "rad/s", wmax);
    mm_res_scalar_v1(res, "omega_max_h", "omega_max h: radians of the fastest mode per step", "", wmax * h);
    double lim = omega_h_limit(method);
    if (lim > 0)
        mm_res_scalar_v1(res, "h_stable", "stability limit of the scheme", "s", lim / wmax);

    /* ---- the integration ---- */
    run_out o;
    if ((rc = newmark_run(&s, method, alpha, h, t_end, 1, &o, res, err)) != MM_OK)
        return rc;
    long N = o.steps;

    /* the step points where the error is measured, and those plotted */
    long se = (N + ERR_SAMPLES - 1) / ERR_SAMPLES, sp = (N + np - 2) / (np - 1);
    if (se < 1)
        se = 1;
    if (sp < 1)
        sp = 1;
    int ns = 0;
    long *idx = mm_res_alloc(res, (size_t)(ERR_SAMPLES + np + 4) * sizeof *idx);
    double *ts = mm_res_alloc(res, (size_t)(ERR_SAMPLES + np + 4) * sizeof *ts);
    if (!idx || !ts)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (long k = 0; k <= N; k++)
        if (k % se == 0 || k % sp == 0 || k == N) {
            idx[ns] = k;
            ts[ns++] = o.t[k];
        }
    double *qr = mm_res_alloc(res, (size_t)ns * n * sizeof *qr), *vr = mm_res_alloc(res, (size_t)ns * n * sizeof *vr);
    if (!qr || !vr)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");

    /* ---- the reference: exact modal superposition, else DOP853 ---- */
    int exact = 0;
    long ref_evals = 0;
    double rcond = 0;
    modal *mdp = mm_res_alloc(res, sizeof *mdp);
    if (!mdp)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    if (s.knl == 0) {
        rc = modal_init(&s, mdp, &rcond, err);
        if (rc == MM_OK)
            exact = 1;
        else if (rc != MM_ESINGULAR)
            return rc;
    }
    double A = 0, V = 0;
    for (int k = 0; k < ns; k++)
        for (int i = 0; i < n; i++) {
            A = fmax(A, fabs(o.q[idx[k] * n + i]));
            V = fmax(V, fabs(o.v[idx[k] * n + i]));
        }
    if (exact) {
        for (int k = 0; k < ns; k++)
            modal_eval(&s, mdp, ts[k], qr + k * n, vr + k * n);
    } else if ((rc = dop853_ref(&s, ns, ts, ts[ns - 1], fmax(A, 1e-300), qr, vr, &ref_evals, res, err)) != MM_OK) {
        return rc;
    }
    A = V = 0;
    for (int k = 0; k < ns * n; k++) {
        A = fmax(A, fabs(qr[k]));
        V = fmax(V, fabs(vr[k]));
    }
    /* The size of the parts the motion is made of: a scheme's error grows
     * with the steady response and the free vibration separately, and the
     * two may nearly cancel (a step load early on). */
    double Ap = 0, Vp = 0, Ah = 0, Vh = 0;
    if (exact) {
        for (int i = 0; i < n; i++) {
            double sq = 0, sv = 0;
            for (int j = 0; j < mdp->n2; j++) {
                sq += cabs(mdp->c[j] * mdp->V[i * mdp->n2 + j]);
                sv += cabs(mdp->c[j] * mdp->V[(n + i) * mdp->n2 + j]);
            }
            Ap = fmax(Ap, hypot(mdp->Xr[i], mdp->Xi[i]));
            Ah = fmax(Ah, sq);
            Vh = fmax(Vh, sv);
        }
        Vp = s.w * Ap;
    } else {
        double X[2 * MAXN], t_slow = lam[0] > 0 ? fmin(o.t[N], 1 / sqrt(lam[0])) : o.t[N];
        mm_error e2;
        if (particular(&s, X, &e2) == MM_OK)
            for (int i = 0; i < n; i++) {
                Ap = fmax(Ap, hypot(X[i], X[n + i]));
                Ah = fmax(Ah, fabs(s.q0[i] - X[i]) + fabs(s.v0[i] + s.w * X[n + i]) * t_slow);
                Vh = fmax(Vh, fabs(s.v0[i] + s.w * X[n + i]));
            }
        Vp = s.w * Ap;
    }
    double A_eff = fmax(A, Ap + Ah), V_eff = fmax(V, Vp + Vh);

    /* the fastest motion along the way: with the cubic spring the tangent
     * stiffness grows with |q1| */
    double fast;
    if ((rc = fastest_rate(&s, s.K, &fast, err)) != MM_OK)
        return rc;
    double w_eff = fmax(fmax(wmax, fast), s.w);
    if (s.knl > 0) {
        double q1 = 0, Kt[MAXN * MAXN], lt[MAXN];
        for (int k = 0; k < ns; k++)
            q1 = fmax(q1, fabs(qr[k * n]));
        memcpy(Kt, s.K, sizeof(double) * n * n);
        Kt[0] += 3 * s.knl * q1 * q1;
        if ((rc = mm_linalg_sygv(n, Kt, s.M, lt, NULL, err)) != MM_OK)
            return rc;
        double wt = sqrt(fmax(lt[n - 1], 0));
        if ((rc = fastest_rate(&s, Kt, &fast, err)) != MM_OK)
            return rc;
        w_eff = fmax(w_eff, fmax(wt, fast));
        mm_res_scalar_v1(res, "omega_max_tangent", "highest frequency of the stiffened system (largest |q1|)",
                      "rad/s", wt);
        if (lim > 0 && wt * h >= lim)
            return mm_error_set(err, MM_ERANGE, "h", "the cubic spring raises the highest frequency to %.4g "
                                "rad/s, where %s needs h < %.4g s (got %g s): reduce h or take "
                                "average-acceleration", wt, methods[method], lim / wt, h);
    }

    /* ---- the error against the reference ---- */
    double worst = 0;
    for (int k = 0; k < ns; k++)
        if (idx[k] % se == 0 || idx[k] == N)
            for (int i = 0; i < n; i++)
                worst = fmax(worst, fabs(o.q[idx[k] * n + i] - qr[k * n + i]));
    /* the a-priori estimate, eq. (10): phase error c (w h)^2 per radian of
     * the fastest motion, and a relative error c (w h)^2 Q of forced
     * amplitudes (Q: the largest dynamic magnification); it holds while it is
     * small, i.e. while the step resolves the motion */
    static const double cm[4] = {1.0 / 12, 1.0 / 24, 1.0 / 12, 1.0 / 24};
    double c = cm[method] + (method == ME_HHT ? 0.25 * fabs(alpha) : 0);
    double wh2 = (w_eff * h) * (w_eff * h), T_run = o.t[N];
    double est = c * wh2 * (w_eff * T_run + 1 + fmin(Q, 1e6)) * A_eff / fmax(A, 1e-300);   /* relative */
    double bound = 3 * c * wh2 * (T_run * V_eff + A_eff * (1 + fmin(Q, 1e6))) + 1e-9 * A + 1e-300;
    mm_res_scalar_v1(res, "max_error", "largest |q - q_reference| at the measured steps", "m", worst);
    mm_res_scalar_v1(res, "relative_error", "largest error over the largest displacement", "", worst / fmax(A, 1e-300));
    mm_res_scalar_v1(res, "error_estimate", "a-priori relative error of the scheme, eq. (10)", "", est);
    char name[160];
    int independent = 0;        /* independent checks made: reference, order, energy */
    if (w_eff * h <= 0.5) {     /* at least 12 steps per period of the fastest motion */
        mm_res_scalar_v1(res, "error_bound", "a-priori error bound of the scheme (eq. 10)", "m", bound);
        snprintf(name, sizeof name, "q(t) vs %s (worst measured step) within the a-priori bound (10)",
                 exact ? "exact modal superposition" : "DOP853 at rtol 1e-11");
        mm_res_check_abs(res, mm_res_strdup(res, name), worst, 0, bound);
        independent++;
    } else {
        mm_res_warn(res, "omega h = %.3g: fewer than 12 steps per period of the fastest motion; the error "
                         "theory (10) does not hold and the error is not checked against a bound (stable is not "
                         "accurate)", w_eff * h);
    }
    /* ---- the order: a second run at h/2 ---- */
    double per_step = (n + 1) * (n + 1) * (s.knl > 0 ? 3 : 1);
    /* only where the error is in its asymptotic regime: above round-off and
     * the reference's error, and the fastest motion's phase error (6) under
     * one radian (beyond, errors saturate and stop falling like h^2) */
    double phase_fast = c * wh2 * w_eff * T_run;
    if (worst > 1e-8 * A && worst < 1e-2 * A && w_eff * h <= 0.5 && phase_fast <= 1 &&
        4 * N * per_step <= MAX_WORK) {
        run_out o2;
        /* over exactly the same steps: to the h-run's last step N h */
        if ((rc = newmark_run(&s, method, alpha, h / 2, o.t[N], 2, &o2, res, err)) != MM_OK)
            return rc;
        double worst2 = 0;
        for (int k = 0; k < ns; k++)
            if ((idx[k] % se == 0 || idx[k] == N) && idx[k] < o2.rows)
                for (int i = 0; i < n; i++)
                    worst2 = fmax(worst2, fabs(o2.q[idx[k] * n + i] - qr[k * n + i]));
        double p = log2(worst / worst2);
        mm_res_scalar_v1(res, "observed_order", "log2(error at h / error at h/2)", "", p);
        mm_res_check_abs(res, "observed order from a second run at h/2 vs 2", p, 2, 0.35);
        independent++;
    }

    /* ---- consistency: the equation of motion at every step, recomputed:
     * R = M a + C v + K q - F(t, q) = 0 at t_k (average and linear
     * acceleration, central difference), or (1 + alpha) R_{k+1} - alpha R_k +
     * alpha M (a_{k+1} - a_k) = 0 for HHT-alpha, eq. (4).  The scheme solved
     * exactly this equation for a_k, so this is NOT an independent check of
     * the motion: it only confirms that the stored q, v, a belong together
     * and that Newton converged.  The independent ones are the reference,
     * the order and the energy balance. ---- */
    {
        double Rp[MAXN], Rk[MAXN], Ma[MAXN], tmp[MAXN], Fq[MAXN];
        double worst_r = 0, fscale = 0;
        for (long k = 0; k <= N; k++) {
            const double *q = o.q + k * n, *v = o.v + k * n, *a = o.a + k * n;
            force(o.t[k], q, v, Fq, &s);
            matv(n, s.M, a, Ma);
            matv(n, s.C, v, tmp);
            for (int i = 0; i < n; i++)
                Rk[i] = tmp[i] - Fq[i];
            fscale = fmax(fscale, fmax(mm_maxabs(Ma, n), fmax(mm_maxabs(tmp, n), mm_maxabs(Fq, n))));
            matv(n, s.K, q, tmp);
            fscale = fmax(fscale, mm_maxabs(tmp, n));
            for (int i = 0; i < n; i++)
                Rk[i] += tmp[i];
            for (int i = 0; i < n; i++) {
                double r = method == ME_HHT && k > 0
                               ? Ma[i] + (1 + alpha) * Rk[i] - alpha * Rp[i]
                               : Ma[i] + Rk[i];
                worst_r = fmax(worst_r, fabs(r));
            }
            memcpy(Rp, Rk, sizeof Rp);
        }
        mm_res_scalar_v1(res, "motion_residual", "largest residual of the equation of motion at a step", "N", worst_r);
        /* Newton stops at 1e-12 of the force scale; round-off adds a few eps */
        mm_res_check_abs(res, method == ME_HHT
                                  ? "consistency check (not independent): the HHT-weighted equation of motion the "
                                    "scheme solved, recomputed from the stored q, v, a at every step: worst residual [N]"
                                  : "consistency check (not independent): the equation of motion the scheme solved, "
                                    "recomputed from the stored q, v, a at every step: worst residual [N]",
                         worst_r, 0, 1e-10 * fscale + 1e-300);
    }

    /* ---- energy, recomputed from the trajectory, eq. (7) ---- */
    double E0 = 0, W = 0, D = 0, Emax = 0, bal = 0;
    double Fa[MAXN], Fb[MAXN], Ca[MAXN], Cb[MAXN], Kq[MAXN], Mv[MAXN];
    double *eb = mm_res_alloc(res, (size_t)(N + 1) * sizeof *eb);
    if (!eb)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (long k = 0; k <= N; k++) {
        const double *q = o.q + k * n, *v = o.v + k * n;
        for (int i = 0; i < n; i++)
            Fb[i] = s.F[i] * cos(s.w * o.t[k]);        /* the harmonic forces */
        matv(n, s.C, v, Cb);
        if (k > 0) {
            const double *qp = o.q + (k - 1) * n;
            for (int i = 0; i < n; i++) {
                double dq = q[i] - qp[i];
                W += dq * 0.5 * (Fa[i] + Fb[i]);
                D += dq * 0.5 * (Ca[i] + Cb[i]);
            }
        }
        matv(n, s.K, q, Kq);
        matv(n, s.M, v, Mv);
        double E = 0.5 * dotv(n, v, Mv) + 0.5 * dotv(n, q, Kq) + 0.25 * s.knl * q[0] * q[0] * q[0] * q[0];
        if (k == 0)
            E0 = E;
        eb[k] = E - E0 - W + D;
        bal = fmax(bal, fabs(eb[k]));
        Emax = fmax(Emax, fmax(fabs(E), fmax(fabs(W), fabs(D))));
        memcpy(Fa, Fb, sizeof Fa);
        memcpy(Ca, Cb, sizeof Ca);
    }
    mm_res_scalar_v1(res, "energy_residual", "largest |E - E0 - W + D| over the largest energy, eq. (7)", "",
                  bal / fmax(Emax, 1e-300));
    mm_res_scalar_v1(res, "work_done", "work of the forces F cos(omega t) over the run", "J", W);
    mm_res_scalar_v1(res, "energy_dissipated", "energy taken by the dampers over the run", "J", D);
    if (method == ME_AVERAGE && s.knl == 0) {
        /* average acceleration satisfies the trapezoidal energy balance step
         * by step (eq. 8); only round-off remains, growing with the steps */
        mm_res_check_abs(res, "average acceleration: energy balance (7) recomputed from the trajectory [J]", bal,
                         0, 1e-13 * (double)(N + 10) * Emax + 1e-300);
        independent++;
    }
    if (!independent)
        mm_res_warn(res, "no independent check applies here: at omega h = %.3g the error bound (10) and the order "
                    "do not hold, and the energy balance is exact only for average acceleration on a linear "
                    "system. The one check left is a consistency check, which cannot tell whether the motion is "
                    "right: compare q with its reference (max_error), or lower h below %.3g s to have it checked",
                    w_eff * h, 0.5 / w_eff);

    /* ---- the plot ---- */
    int nplot = 0;
    for (int k = 0; k < ns; k++)
        if (idx[k] % sp == 0 || idx[k] == N)
            nplot++;
    for (int i = 0; i < n; i++) {
        char nm[32], lb[64];
        snprintf(nm, sizeof nm, "q%d", i + 1);
        snprintf(lb, sizeof lb, "displacement q%d", i + 1);
        mm_series *sq = mm_res_series_v1(res, mm_res_strdup(res, nm), mm_res_strdup(res, lb), "m", "t", "s", nplot);
        snprintf(nm, sizeof nm, "q%d_reference", i + 1);
        snprintf(lb, sizeof lb, "q%d, %s", i + 1, exact ? "exact" : "DOP853");
        mm_series *sr = mm_res_series_v1(res, mm_res_strdup(res, nm), mm_res_strdup(res, lb), "m", "t", "s", nplot);
        if (!sq || !sr)
            return mm_error_set(err, MM_ENOMEM, "", "out of memory");
        for (int k = 0, m = 0; k < ns; k++)
            if (idx[k] % sp == 0 || idx[k] == N) {
                sq->x[m] = sr->x[m] = ts[k];
                sq->y[m] = o.q[idx[k] * n + i];
                sr->y[m++] = qr[k * n + i];
            }
    }
    mm_series *sb = mm_res_series_v1(res, "energy_residual", "energy balance residual E - E0 - W + D", "J", "t", "s",
                                  nplot);
    if (!sb)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (int k = 0, m = 0; k < ns; k++)
        if (idx[k] % sp == 0 || idx[k] == N) {
            sb->x[m] = ts[k];
            sb->y[m++] = eb[idx[k]];
        }

    static const mm_newmark_method mm[4] = {MM_NEWMARK_AVERAGE, MM_NEWMARK_LINEAR, MM_NEWMARK_HHT,
                                            MM_NEWMARK_CENTRAL};
    mm_res_method(res, mm_newmark_method_name(mm[method]), h);
    mm_res_method_stat(res, "steps", (double)N);
    mm_res_method_stat(res, "evaluations", (double)o.force_evals);
    mm_res_method_stat(res, "newton_iterations", (double)o.newton_iters);
    mm_res_method_stat(res, "factorizations", (double)o.factorizations);
    mm_res_method_stat(res, "error_estimate", est * A);
    mm_res_method_stat(res, "max_error", worst);
    if (!exact)
        mm_res_method_stat(res, "reference_evaluations", (double)ref_evals);
    mm_res_scalar_v1(res, "newton_iterations", "Newton corrections in all (0: linear, one solve per step)", "",
                  (double)o.newton_iters);
    if (s.knl > 0)
        mm_res_scalar_v1(res, "newton_per_step", "Newton corrections per step", "", (double)o.newton_iters / N);
    return MM_OK;
}

static const char *const references[] = {
    "N. M. Newmark, A method of computation for structural dynamics, J. Eng. Mech. Div. ASCE 85 (1959) 67-94",
    "T. J. R. Hughes, The Finite Element Method, Dover 2000, ch. 9",
    "H. M. Hilber, T. J. R. Hughes, R. L. Taylor, Improved numerical dissipation for time integration "
    "algorithms in structural dynamics, Earthq. Eng. Struct. Dyn. 5 (1977) 283-292",
    NULL,
};

const mm_exercise mm_ex_num_newmark = {
    .id = "num-newmark",
    .chapter = 1,
    .section = "1.4.2",
    .title = "Equations of motion step by step: the Newmark method",
    .summary = "M q'' + C q' + K q = F(q, q', t) for a small system by Newmark, HHT-alpha or central difference.",
    .tags = "numerical methods, time integration, Newmark, HHT-alpha, central difference, Newton, energy",
    .theory = "exercises/num/newmark.md",
    .params = params,
    .n_params = MM_COUNT(params),
    .references = references,
    .check = check,
    .solve = solve,
};
