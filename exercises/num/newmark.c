/* newmark.c — num-newmark: the equations of motion of a small mechanical
 * system integrated step by step by the Newmark family (the book's
 * `newmark` / `defphy` pair):
 *
 *     M q'' + C q' + K q = F cos(omega t) - knl q1^3 e1                  (1)
 *
 * Goal: what a fixed-step integrator does.  Average acceleration is stable
 * at any step and keeps the energy balance; linear acceleration and central
 * difference are stable only below a step set by the highest frequency;
 * HHT-alpha damps the highest modes on purpose; all are second order.
 * Checks (eq. numbers of newmark.md): a linear run against the exact
 * discrete solution of its scheme, the powers of the amplification matrix
 * (11) — a bound as tight as rounding; its error against the exact motion
 * (a transition matrix, 9) is then known and printed, with a warning when
 * it is large.  The observed order from a run at h/2; the energy balance
 * (7)-(8) of average acceleration.  With the cubic spring: DOP853 as the
 * reference and the error of the h-run against the Richardson estimate
 * from the h/2 run.
 * Reference: N. M. Newmark, J. Eng. Mech. Div. ASCE 85 (1959) 67-94;
 * T. J. R. Hughes, The Finite Element Method, Dover 2000, ch. 9.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mm_exhelp.h"
#include "mm_linalg.h"
#include "mm_mdof.h"
#include "mm_num.h"
#include "mm_scene.h"
#include "mm_vib.h"

#define MAXN 6
#define MAX_WORK 2.7e6      /* steps x (10 + (n + 1)^2) of the h-run: with its h/2 run, about
                               0.015 us a unit, 120 ms at the limit */
#define MAX_RADIANS 1e3     /* with the cubic spring: the reference's work (the script's ode45
                               at rtol 1e-10 takes ~9 ms of Octave a radian; ~160 periods) */

enum { P_M, P_C, P_K, P_F, P_OMEGA, P_Q0, P_V0, P_KNL, P_METHOD, P_ALPHA, P_H, P_TEND, P_POINTS };

static const char *const methods[] = {"average-acceleration", "linear-acceleration", "hht-alpha",
                                      "central-difference", NULL};
static const mm_newmark_method scheme[] = {MM_NEWMARK_AVERAGE, MM_NEWMARK_LINEAR, MM_NEWMARK_HHT,
                                           MM_NEWMARK_CENTRAL};

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
    [P_METHOD] = {"method", "integrator", "", MM_CHOICE, 0, 0, 0, .choices = methods,
                  .help = "the Newmark scheme: average acceleration (beta 1/4), linear acceleration "
                          "(beta 1/6), HHT-alpha, central difference (explicit)"},
    [P_ALPHA] = {"alpha", "HHT alpha", "", MM_REAL, -0.1, -1.0 / 3, 0,
                 .help = "numerical damping of hht-alpha: 0 is average acceleration, -1/3 damps the most"},
    [P_H] = {"h", "time step", "s", MM_REAL, 0.01, 1e-5, 1, .help = "the fixed step of the integrator"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 10, 1e-3, 1e4,
                .help = "simulated time; at most 2.7e6 / (10 + (n + 1)^2) steps (1.9e5 for one mass, 4.6e4 "
                        "for six) so that a request stays within a quarter of a second; with the cubic spring "
                        "also at most 1e3 radians of the fastest motion (the reference's work)"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 201, 11, 2001,
                  .help = "steps returned for the plot, spread evenly over the run"},
};

enum { O_N, O_WMAX, O_WMAXH, O_HSTAB, O_WTAN, O_ERR, O_RELERR, O_DISC, O_ORDER, O_ENERGY, O_WORK,
       O_DISS, O_NEWTON, O_NEWTON_STEP, O_MODES, O_Q, O_QREF, O_EB, O_ANIM };

static const char *const mcols[] = {"mode", "omega", "zeta", "omega_d", "omega_h", NULL};
static const char *const munits[] = {"", "rad/s", "", "rad/s", "", NULL};

static const mm_output outputs[] = {
    [O_N] = MM_SCALAR("n", "degrees of freedom", "", .flags = MM_EXACT),
    [O_WMAX] = MM_SCALAR("omega_max", "highest natural frequency", "rad/s", .flags = MM_ANSWER),
    [O_WMAXH] = MM_SCALAR("omega_max_h", "omega_max h: radians of the fastest mode per step", ""),
    [O_HSTAB] = MM_SCALAR("h_stable", "stability limit of the scheme", "s", .flags = MM_ANSWER),
    [O_WTAN] = MM_SCALAR("omega_max_tangent", "highest frequency of the stiffened system (largest |q1|)", "rad/s"),
    [O_ERR] = MM_SCALAR("max_error", "largest |q - q_exact| at the plotted steps", "m", .flags = MM_ANSWER),
    [O_RELERR] = MM_SCALAR("relative_error", "max_error over the largest displacement", ""),
    [O_DISC] = MM_SCALAR("discrete_difference", "largest |q - exact discrete solution of the scheme| (rounding)", "m"),
    [O_ORDER] = MM_SCALAR("observed_order", "log2(error at h / error at h/2)", ""),
    [O_ENERGY] = MM_SCALAR("energy_residual", "largest |E - E0 - W + D| over the largest energy, eq. (7)", ""),
    [O_WORK] = MM_SCALAR("work_done", "work of the forces F cos(omega t) over the run", "J"),
    [O_DISS] = MM_SCALAR("energy_dissipated", "energy taken by the dampers over the run", "J"),
    [O_NEWTON] = MM_SCALAR("newton_iterations", "Newton corrections in all (0: linear, one solve per step)", "",
                           .flags = MM_EXACT),
    [O_NEWTON_STEP] = MM_SCALAR("newton_per_step", "Newton corrections per step", "", .flags = MM_EXACT),
    [O_MODES] = MM_TABLE("modes", "damped modes (complex eigenvalues of the state matrix)", mcols, munits),
    [O_Q] = MM_SERIES("q%d", "displacement q%d", "m", "t", "s", .first = 1, .last = MAXN, .figure = "response"),
    [O_QREF] = MM_SERIES("q%d_reference", "q%d exact (DOP853 with the cubic spring)", "m", "t", "s", .first = 1,
                         .last = MAXN, .figure = "response", .role = "reference"),
    [O_EB] = MM_SERIES("energy_residual", "energy balance residual E - E0 - W + D", "J", "t", "s"),
    [O_ANIM] = MM_ANIMATION("the masses on their springs, as the scheme moves them"),
};

/* ---- the system ------------------------------------------------------------------ */

typedef struct sys {
    int n;
    const double *M, *C, *K, *F, *q0, *v0;
    double w, knl;
} sys;

static sys sys_of(const mm_value *in)
{
    return (sys){.n = in[P_M].rows, .M = in[P_M].data, .C = in[P_C].data, .K = in[P_K].data,
                 .F = in[P_F].data, .q0 = in[P_Q0].data, .v0 = in[P_V0].data, .w = in[P_OMEGA].x,
                 .knl = in[P_KNL].x};
}

static int force(double t, const double *q, const double *qd, double *F, void *ctx)
{
    (void)qd;
    const sys *s = ctx;
    for (int i = 0; i < s->n; i++)
        F[i] = s->F[i] * cos(s->w * t);
    F[0] -= s->knl * q[0] * q[0] * q[0];
    return 0;
}

static int jacobian(double t, const double *q, const double *qd, double *dFdq, double *dFdqd, void *ctx)
{
    (void)t, (void)qd, (void)dFdqd;
    dFdq[0] = -3 * ((const sys *)ctx)->knl * q[0] * q[0];
    return 0;
}

/* omega_max of K (+ the cubic spring's tangent at |q1| = a) and M. */
static int top_omega(const sys *s, double a, double *wmax, mm_error *err)
{
    double Kt[MAXN * MAXN], w[MAXN];
    memcpy(Kt, s->K, sizeof(double) * s->n * s->n);
    Kt[0] += 3 * s->knl * a * a;
    mm_mdof_system ms = {s->n, s->M, NULL, Kt};
    int rc = mm_mdof_modes(&ms, s->n, w, NULL, NULL, err);
    *wmax = w[s->n - 1];
    return rc;
}

static int check(const mm_value *in, mm_error *err)
{
    const mm_value *vec[3] = {&in[P_F], &in[P_Q0], &in[P_V0]};
    static const char *const vname[3] = {"F", "q0", "v0"};
    int n = in[P_M].rows, rc = mm_vib_check_system(&in[P_M], &in[P_C], &in[P_K], 3, vec, vname, err);
    if (rc != MM_OK)
        return rc;
    sys s = sys_of(in);
    double wmax;
    if ((rc = top_omega(&s, s.q0[0], &wmax, err)) != MM_OK)
        return rc;
    double h = in[P_H].x, t_end = in[P_TEND].x, max_steps = floor(MAX_WORK / (10 + (n + 1) * (n + 1)));
    if (t_end / h > max_steps)
        return mm_error_set(err, MM_ERANGE, "h", "h = %g s takes %.3g steps to cover t_end = %g s; at most "
                            "%.0f fit one request for %d coordinates: make h at least %.3g s", h, t_end / h,
                            t_end, max_steps, n, t_end / max_steps);
    double rate = fmax(wmax, s.w);
    if (s.knl > 0 && t_end * rate > MAX_RADIANS)
        return mm_error_set(err, MM_ERANGE, "t_end", "with the cubic spring t_end = %g s spans %.3g radians of "
                            "the fastest motion (%.4g rad/s); at most 1e3 fit the reference integration: make "
                            "t_end at most %.4g s", t_end, t_end * rate, rate, MAX_RADIANS / rate);
    mm_newmark_options o = {.method = scheme[(int)in[P_METHOD].x]};
    double lim = mm_newmark_omega_h_limit(&o);
    if (lim > 0 && wmax * h >= lim)
        return mm_error_set(err, MM_ERANGE, "h", "%s is stable only for omega_max h < %.4g; with omega_max = "
                            "%.4g rad/s that is h < %.4g s (got %g s); or take average-acceleration",
                            methods[(int)in[P_METHOD].x], lim, wmax, lim / wmax, h);
    return MM_OK;
}

/* ---- the runs --------------------------------------------------------------------- */

/* N steps of h (mm_num_newmark_run) of eq. (1) from the start, the work of
 * F and C by the trapezoidal rule in q, eq. (8): exact for average
 * acceleration on a linear system */
static int run(sys *s, const mm_newmark_options *base, double h, long N, long stride, int points,
               mm_num_newmark_rows *o, mm_result *res, mm_error *err)
{
    mm_newmark_problem prob = {.n = s->n, .M = s->M, .C = s->C, .K = s->K, .force = force,
                               .jacobian = s->knl > 0 ? jacobian : NULL,
                               .force_kind = s->knl > 0 ? MM_NEWMARK_FORCE_POSITION : MM_NEWMARK_FORCE_TIME,
                               .params = s, .q0 = s->q0, .qd0 = s->v0, .t0 = 0};
    int rc = mm_num_newmark_run(&prob, base, h, N, stride, points, o, res, err);
    if (rc == MM_ENOCONV || rc == MM_ENONFINITE)
        return mm_error_set(err, MM_ERANGE, "h", "at h = %g s the cubic spring changes too much within a step "
                            "(%s): reduce h or knl", h, rc == MM_ENOCONV ? "Newton did not converge" :
                            "the motion grew without bound");
    return rc;
}

static double worst_diff(int m, const double *a, const double *b)
{
    double w = 0;
    for (int i = 0; i < m; i++)
        w = fmax(w, fabs(a[i] - b[i]));
    return w;
}

/* The masses on their springs over the first t_show seconds (the frames
 * of mm_vib_frames at the fastest motion wfast): a short run of the same
 * scheme, sampled at the animation's frames. */
static int animate(sys *s, const mm_newmark_options *o, double h, double t_end, double wfast, mm_result *res,
                   mm_error *err)
{
    double t_show;
    int nf = mm_vib_frames(t_end, 2 * M_PI / wfast, 1500 / mm_vib_masses_numbers(s->n, s->K), &t_show);
    long steps = (long)ceil(t_show / h * (1 - 1e-12));
    if (steps < nf - 1)
        nf = (int)steps + 1;
    mm_num_newmark_rows a;
    int rc = run(s, o, h, steps, 1, nf < 2 ? 2 : nf, &a, res, err);
    return rc != MM_OK ? rc : mm_num_newmark_draw(res, s->n, s->K, &a);
}

/* ---- solve ------------------------------------------------------------------------- */

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    sys s = sys_of(in);
    const int n = s.n, method = (int)in[P_METHOD].x, np = (int)in[P_POINTS].x, linear = s.knl == 0;
    const double h = in[P_H].x, t_end = in[P_TEND].x, eps = DBL_EPSILON;
    mm_newmark_options o;
    mm_newmark_options_init(&o);
    o.method = scheme[method], o.alpha = in[P_ALPHA].x, o.newton_tol = 1e-12, o.newton_max_iter = 50;
    o.max_steps = MM_NEWMARK_STEPS_CEILING;
    int rc;

    /* ---- modes: undamped omega_max, cond(M), damped modes for the table ---- */
    double wmax, kappa;
    mm_mdof_system ms = {n, s.M, s.C, s.K};
    if ((rc = mm_num_newmark_modes(res, O_MODES, n, s.M, s.C, s.K, h, &wmax, &kappa, err)) != MM_OK)
        return rc;
    double werr = 8 * n * eps * kappa * wmax;     /* a symmetric pencil's backward error */
    mm_res_scalar(res, O_N, n);
    mm_res_scalar_err(res, O_WMAX, wmax, werr, MM_ERR_ESTIMATE);
    mm_res_scalar_err(res, O_WMAXH, wmax * h, werr * h, MM_ERR_ESTIMATE);
    double lim = mm_newmark_omega_h_limit(&o);
    if (lim > 0)
        mm_res_scalar_err(res, O_HSTAB, lim / wmax, lim / wmax * werr / wmax, MM_ERR_ESTIMATE);

    /* ---- the run, followed at every step, sampled at the plotted ones ---- */
    mm_newmark_problem pr = {.n = n, .M = s.M, .t0 = 0, .t_end = t_end};
    o.h = h;
    long N = mm_newmark_step_count(&pr, &o), stride = (N + np - 2) / (np - 1);
    mm_num_newmark_rows r1;
    if ((rc = run(&s, &o, h, N, stride, 0, &r1, res, err)) != MM_OK)
        return rc;
    int ns = r1.r.rows;
    long *ks = mm_res_alloc(res, (size_t)ns * sizeof *ks);
    double *q1 = r1.q, *qx = mm_res_alloc(res, (size_t)ns * n * sizeof *qx),
           *qd = mm_res_alloc(res, (size_t)ns * n * sizeof *qd);
    if (!ks || !qx || !qd)
        return MM_ENOMEM;
    for (int k = 0; k < ns; k++)
        ks[k] = k < ns - 1 ? k * stride : N;
    double A = mm_maxabs(q1, ns * n), err_ref;
    long ref_evals = 0;
    mm_mdof_motion mo = {s.q0, s.v0, s.F, s.w};
    if (linear) {
        /* eq. (11): the exact discrete solution; the run must equal it */
        if ((rc = mm_mdof_newmark_exact(&ms, &mo, &o, ns, ks, qd, NULL, err)) != MM_OK ||
            (rc = mm_mdof_exact(&ms, &mo, h, ns, ks, qx, NULL, err)) != MM_OK)
            return rc;
        double dd = worst_diff(ns * n, q1, qd), big = fmax(A, mm_maxabs(qd, ns * n));
        /* rounding: a few eps of the state per step in the run, per
         * squaring in the powers, and of the phase omega t of the force */
        double tol = 4 * eps * ((double)N + 64.0 * ns + 2 * s.w * N * h) * big + 1e-300;
        mm_res_scalar_err(res, O_DISC, dd, tol, MM_ERR_BOUND);
        mm_res_check_abs(res, "q(t) vs the exact discrete solution of the scheme, powers of its amplification "
                              "matrix (11): worst difference [m] (rounding)", dd, 0, tol);
        /* the transition matrix's rounding per plotted step, and omega t's phase in double (eps a
         * radian of force or mode: a run over 141 rad was 1.26x over 8 eps ns A, tests/ref) */
        err_ref = eps * (8.0 * ns + 2 * (s.w + wmax) * (double)N * h) * fmax(A, mm_maxabs(qx, ns * n));
    } else {
        rc = mm_mdof_ode(&ms, force, &s, s.q0, s.v0, ns, r1.t, 1e-11, fmax(A, 1e-300), qx, &ref_evals, err);
        if (rc == MM_ENOCONV)
            return mm_error_set(err, MM_ERANGE, "knl", "the cubic spring stiffens the system so much that the "
                                "reference needs over 1e6 steps; lower knl or t_end");
        if (rc != MM_OK)
            return rc;
        err_ref = 1e-9 * fmax(A, mm_maxabs(qx, ns * n));      /* rtol 1e-11 over the run: seen below 1e-10 */
        double wt;
        if ((rc = top_omega(&s, mm_maxabs(qx, ns * n), &wt, err)) != MM_OK)   /* |q1| at its largest */
            return rc;
        mm_res_scalar_err(res, O_WTAN, wt, 8 * n * eps * kappa * wt, MM_ERR_ESTIMATE);
        if (lim > 0 && wt * h >= lim)
            return mm_error_set(err, MM_ERANGE, "h", "the cubic spring raises the highest frequency to %.4g "
                                "rad/s, where %s needs h < %.4g s (got %g s): reduce h or take "
                                "average-acceleration", wt, methods[method], lim / wt, h);
        wmax = fmax(wmax, wt);
    }
    double e1 = worst_diff(ns * n, q1, qx), Aref = fmax(mm_maxabs(qx, ns * n), 1e-300);
    mm_res_scalar_err(res, O_ERR, e1, err_ref, MM_ERR_ESTIMATE);
    /* e1 / Aref: the reference's error enters both, err_ref (1 + e1 / Aref) / Aref
     * (a run that grew far past the motion divides by a reference off by err_ref) */
    mm_res_scalar_err(res, O_RELERR, e1 / Aref, err_ref / Aref * (1 + e1 / Aref), MM_ERR_ESTIMATE);
    if (e1 > 0.01 * Aref)
        mm_res_warn(res, "the run is %.3g %% off the exact motion: omega_max h = %.3g, and over %.3g radians of "
                         "the fastest motion the phase error (6) of about (omega h)^2/12 per radian adds up; "
                         "stable is not accurate: reduce h", 100 * e1 / Aref, wmax * h, wmax * N * h);

    /* ---- energy, eqs. (7)-(8), over every step ---- */
    double bal = r1.r.energy_error;
    mm_res_scalar_err(res, O_ENERGY, bal, 4 * eps * (double)N, MM_ERR_ESTIMATE);
    int independent = linear;
    if (method == 0 && linear)          /* eq. (8): kept step by step */
        mm_res_check_abs(res, "average acceleration: energy balance (7) over every step, relative (rounding)", bal,
                         0, 1e-13 * (double)(N + 10));

    /* ---- the order: a second run at h/2 over the same steps, where the
     * error is in its asymptotic range: above the reference's error,
     * under 1 % of the motion, a step resolving the fastest motion ---- */
    double wf = fmax(wmax, s.w);
    if (e1 > 1e4 * err_ref && e1 < 1e-2 * Aref && wf * h <= 0.5) {
        mm_num_newmark_rows r2;
        if ((rc = run(&s, &o, h / 2, 2 * N, 2 * stride, 0, &r2, res, err)) != MM_OK)
            return rc;
        double e2 = worst_diff(ns * n, r2.q, qx), p = log2(e1 / e2);
        mm_res_scalar_err(res, O_ORDER, p, 2 * err_ref / (e2 * M_LN2), MM_ERR_ESTIMATE);
        mm_res_check_abs(res, "observed order from a second run at h/2 vs 2", p, 2, 0.35);
        if (!linear) {
            /* Richardson: q_h - q_h/2 = 3/4 of the h-run's error, to (omega h)^2 */
            double est = 4.0 / 3 * worst_diff(ns * n, q1, r2.q);
            mm_res_check_abs(res, "q(t) vs DOP853 at rtol 1e-11: worst error within 1.5 x its Richardson "
                                  "estimate 4/3 |q_h - q_h/2| [m]", e1, 0, 1.5 * est + 2 * err_ref);
        }
        /* W and D: the h/2 run's differ by 3/4 of the h-run's error */
        const mm_newmark_energy *a = &r1.r.energy_end, *b = &r2.r.energy_end;
        mm_res_scalar_err(res, O_WORK, a->work, 4.0 / 3 * fabs(a->work - b->work), MM_ERR_ESTIMATE);
        mm_res_scalar_err(res, O_DISS, a->dissipated, 4.0 / 3 * fabs(a->dissipated - b->dissipated),
                          MM_ERR_ESTIMATE);
        independent = 1;
    }
    if (!independent)
        mm_res_warn(res, "no independent check applies: without an exact solution (the cubic spring) the error "
                         "is measured against DOP853 (max_error) but cannot be checked against a bound here: at "
                         "omega h = %.3g the step does not resolve the fastest motion well enough for the order "
                         "and Richardson's estimate; lower h below %.3g s to have it checked", wf * h, 0.5 / wf);

    /* ---- the plots ---- */
    mm_series *sb = mm_res_series(res, O_EB, ns);
    if (!sb)
        return MM_ENOMEM;
    for (int i = 0; i < n; i++) {
        mm_series *sq = mm_res_series_i(res, O_Q, i + 1, ns), *sr = mm_res_series_i(res, O_QREF, i + 1, ns);
        if (!sq || !sr)
            return MM_ENOMEM;
        for (int k = 0; k < ns; k++) {
            sq->x[k] = sr->x[k] = r1.t[k];
            sq->y[k] = q1[k * n + i];
            sr->y[k] = qx[k * n + i];
        }
    }
    for (int k = 0; k < ns; k++) {
        const mm_newmark_energy *e = &r1.e[k];
        sb->x[k] = r1.t[k];
        sb->y[k] = e->kinetic + e->potential - r1.r.energy_start - e->work + e->dissipated;
    }
    const mm_newmark_result *R = &r1.r;
    mm_res_method(res, mm_newmark_method_name(o.method), h);
    mm_res_method_stat(res, "steps", (double)N);
    mm_res_method_stat(res, "evaluations", (double)R->force_evals);
    mm_res_method_stat(res, "factorizations", (double)R->factorizations);
    if (!linear)
        mm_res_method_stat(res, "reference_evaluations", (double)ref_evals);
    mm_res_scalar(res, O_NEWTON, (double)R->newton_iters);
    if (!linear)
        mm_res_scalar(res, O_NEWTON_STEP, (double)R->newton_iters / N);
    return animate(&s, &o, h, t_end, wf, res, err);
}

static const char *const references[] = {
    "N. M. Newmark, A method of computation for structural dynamics, J. Eng. Mech. Div. ASCE 85 (1959) 67-94",
    "T. J. R. Hughes, The Finite Element Method, Dover 2000, ch. 9",
    "H. M. Hilber, T. J. R. Hughes, R. L. Taylor, Improved numerical dissipation for time integration "
    "algorithms in structural dynamics, Earthq. Eng. Struct. Dyn. 5 (1977) 283-292",
    "C. Moler, C. Van Loan, Nineteen dubious ways to compute the exponential of a matrix, twenty-five years "
    "later, SIAM Review 45 (2003) 3-49",
    NULL,
};

const mm_exercise mm_ex_num_newmark = {
    .id = "num-newmark", .chapter = 1, .section = "1.4.2",
    .title = "Equations of motion step by step: the Newmark method",
    .summary = "M q'' + C q' + K q = F(q, q', t) for a small system by Newmark, HHT-alpha or central difference.",
    .tags = "numerical methods, time integration, Newmark, HHT-alpha, central difference, Newton, energy",
    .theory = "exercises/num/newmark.md", .params = params, .n_params = MM_COUNT(params), .outputs = outputs,
    .n_outputs = MM_COUNT(outputs), .references = references, .check = check, .solve = solve,
};
