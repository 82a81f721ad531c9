/* mm_exhelp.c — helpers shared by exercises (see mm_exhelp.h). */
#include "mm_exhelp.h"

#include <float.h>
#include <math.h>

#include "mm_ode.h"

void mm_linspace(double a, double b, int n, double *x)
{
    for (int i = 0; i < n; i++)
        x[i] = a + (b - a) * i / (n - 1);
    x[n - 1] = b;
}

double mm_maxabs(const double *y, int n)
{
    double m = 0;
    for (int i = 0; i < n; i++)
        if (fabs(y[i]) > m)
            m = fabs(y[i]);
    return m;
}

int mm_ex_ode_grid(size_t n, mm_ode_rhs f, void *ctx, const double *y0, double t_end,
                   int nt, const double *t, double rtol, double atol, double h_max,
                   double *x, double *v, mm_ode_result *r, mm_result *res, mm_error *err)
{
    double *y = mm_res_alloc(res, n * (size_t)nt * sizeof *y);
    if (!y)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_ode_problem prob = {.n = n, .f = f, .params = ctx, .t0 = 0, .t_end = t_end, .y0 = y0};
    mm_ode_options opt;
    mm_ode_options_init(&opt);
    opt.method = MM_ODE_DOP853;
    opt.rtol = rtol;
    opt.atol = atol > 0 ? atol : rtol;
    opt.h_max = h_max;
    opt.max_steps = 1000000;
    *r = (mm_ode_result){0};
    r->t_out = t;
    r->nout = (size_t)nt;
    r->y_out = y;
    int rc = mm_ode_check(&prob, &opt, r, err);
    mm_ode_work *w = rc == MM_OK ? mm_ode_work_alloc(n) : NULL;
    if (rc == MM_OK)
        rc = mm_ode_solve(&prob, &opt, w, r, err);
    mm_ode_work_free(w);
    if (rc != MM_OK)
        return rc;
    for (int i = 0; i < nt; i++) {
        if (x)
            x[i] = y[n * (size_t)i];
        if (v && n > 1)
            v[i] = y[n * (size_t)i + 1];
    }
    return MM_OK;
}

/* m x'' + c x' + k x = F0 cos(omega t) as y = (x, v). */
static int sdof_rhs(double t, const double *y, double *dy, void *params)
{
    const mm_sdof *s = params;
    dy[0] = y[1];
    dy[1] = (s->F0 * cos(s->omega * t) - s->c * y[1] - s->k * y[0]) / s->m;
    return 0;
}

/* The fastest rate of the motion [1/s]: omega_n, omega, and the fast decay
 * rate of an overdamped system. */
static double work_rate(const mm_sdof *s)
{
    mm_sdof_props p;
    mm_sdof_props_get(s, &p);
    double rate = fmax(p.omega_n, s->omega);
    if (p.zeta > 1)                                  /* fast overdamped mode */
        rate = fmax(rate, p.omega_n * (p.zeta + sqrt((p.zeta - 1) * (p.zeta + 1))));
    return rate;
}

int mm_ex_sdof_work_check(const mm_sdof *s, double t_end, mm_error *err)
{
    double rate = work_rate(s);
    double work = t_end * rate;
    if (work > MM_SDOF_MAX_RADIANS)
        return mm_error_set(err, MM_ERANGE, "t_end",
                            "t_end = %g s spans %.3g radians of the fastest motion (rate %.4g 1/s); "
                            "at most %g fit one request: make t_end at most %.4g s",
                            t_end, work, rate, MM_SDOF_MAX_RADIANS, MM_SDOF_MAX_RADIANS / rate);
    return MM_OK;
}

int mm_ex_sdof_run(const mm_sdof *s, double t_end, int n, const double *t,
                   double *x, double *v, int stride, mm_result *res, mm_error *err)
{
    double y0[2] = {s->x0, s->v0};
    mm_sdof_props p;
    mm_sdof_props_get(s, &p);
    /* A first guess of the motion's size for the absolute tolerance; after
     * the run, if the motion turned out much smaller, run again scaled to
     * what it was (the integration scales itself; no reference is used). */
    double forced = fabs(p.X);
    if (s->c == 0 && s->F0 != 0)   /* undamped: the beat never passes F0 t/(m (wn + w)) */
        forced = fmin(p.resonant ? INFINITY : 2 * fabs(p.X),
                      fabs(s->F0) * t_end / (s->m * (p.omega_n + s->omega)));
    double scale = fmax(fmax(fabs(s->x0), fabs(s->v0) / fmax(p.omega_n, 1 / t_end)), forced);
    if (!(scale > 0))
        scale = 1;
    /* at most one radian of the fastest motion per step: larger steps stay
     * stable but the error estimate of a step that long undervalues the
     * fast mode (an overdamped case lost 7e-7 of its size at 11 s steps) */
    const double rtol = 1e-8, h_max = 1.0 / work_rate(s);
    mm_ode_result r;
    int rc = mm_ex_ode_grid(2, sdof_rhs, (void *)s, y0, t_end, n, t, rtol, rtol * scale, h_max,
                            x, v, &r, res, err);
    double peak = rc == MM_OK ? mm_maxabs(x, n) : 0;
    long first_steps = 0, first_evals = 0;
    if (rc == MM_OK && peak > 0 && peak < 0.5 * scale) {
        first_steps = r.n_accepted + r.n_rejected;
        first_evals = r.n_eval;
        rc = mm_ex_ode_grid(2, sdof_rhs, (void *)s, y0, t_end, n, t, rtol, rtol * peak, h_max,
                            x, v, &r, res, err);
    }
    if (rc != MM_OK)
        return rc;

    if (stride <= 0)
        return MM_OK;

    mm_res_method(res, "dop853 (Dormand-Prince 8(5,3), dense output)", 0);
    mm_res_method_stat(res, "rtol", rtol);
    mm_res_method_stat(res, "steps", (double)r.n_accepted);
    mm_res_method_stat(res, "rejected", (double)r.n_rejected);
    mm_res_method_stat(res, "evaluations", (double)(r.n_eval + first_evals));
    if (first_evals)             /* the cost of the run that found the scale */
        mm_res_method_stat(res, "scaling_run_steps", (double)first_steps);
    mm_res_method_stat(res, "error_estimate", r.err_sum);

    /* the whole response against the closed form: the worst point */
    double worst = -1, xn = 0, xr = 0;
    peak = 0;
    for (int i = 0; i < n; i += stride) {
        double ref = mm_sdof_x(s, &p, t[i], NULL);
        peak = fmax(peak, fabs(ref));
        if (fabs(x[i] - ref) > worst) {
            worst = fabs(x[i] - ref);
            xn = x[i];
            xr = ref;
        }
    }
    mm_res_method_stat(res, "max_error", worst);
    /* DOP853 at rtol 1e-8 keeps the global error near 1e-7 of the motion's
     * size (measured: 1.2e-7 at the defaults) over runs up to the 1e4-radian
     * work bound; 1e-6 of the reference's own peak leaves room.  (Never a
     * scale of our own: a near-resonant X of 1e17 would make any error pass.) */
    return mm_res_check_abs(res, "x(t) vs closed form (worst sampled point)", xn, xr,
                            1e-6 * peak + 1e-300);
}

int mm_ex_grid_refined(double a, double b, int n, double c, double half, int nwin, double *x)
{
    double lo = fmax(a, c - half), hi = fmin(b, c + half);
    if (!(hi > lo))
        nwin = 0;
    /* merge the two sorted grids */
    int i = 0, j = 0, m = 0;
    while (i < n || j < nwin) {
        double u = i < n ? (i == n - 1 ? b : a + (b - a) * i / (n - 1)) : INFINITY;
        double w = j < nwin ? (nwin == 1 ? lo : (j == nwin - 1 ? hi : lo + (hi - lo) * j / (nwin - 1)))
                            : INFINITY;
        double v = u <= w ? u : w;
        if (u <= w)
            i++;
        else
            j++;
        if (m == 0 || v > x[m - 1])
            x[m++] = v;
    }
    return m;
}

double mm_check_curve(mm_result *res, const char *name, int n, const double *got,
                      const double *ref, double tol_peak)
{
    double worst = -1, peak = 0, g = 0, r = 0;
    for (int i = 0; i < n; i++) {
        peak = fmax(peak, fabs(ref[i]));
        if (!(fabs(got[i] - ref[i]) <= worst)) {     /* NaN is the worst */
            worst = fabs(got[i] - ref[i]);
            g = got[i];
            r = ref[i];
        }
    }
    mm_res_check_abs(res, name, g, r, tol_peak * peak);
    return worst;
}

int mm_check_residual(mm_result *res, const char *name, double residual, double scale,
                      double ulps)
{
    return mm_res_check_abs(res, name, residual, 0, ulps * DBL_EPSILON * fabs(scale));
}

double mm_check_order(mm_result *res, const char *name, int n, const double *h,
                      const double *e, double expected, double tol)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int i = 0; i < n; i++) {
        double x = log(h[i]), y = log(e[i]);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    mm_res_check_abs(res, name, slope, expected, tol);
    return slope;
}
