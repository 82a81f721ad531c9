/* mm_exhelp.c — helpers shared by exercises (see mm_exhelp.h). */
#include "mm_exhelp.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "mm_fourier.h"
#include "mm_newmark.h"
#include "mm_ode.h"
#include "mm_scene.h"

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
    mm_ode_options opt = mm_ode_options_adaptive(MM_ODE_DOP853, rtol, atol > 0 ? atol : rtol, 1000000);
    opt.h_max = h_max;
    *r = (mm_ode_result){0};
    r->t_out = t;
    r->nout = (size_t)nt;
    r->y_out = y;
    int rc = mm_ode_run(&prob, &opt, r, err);
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

/* The fastest rate of the motion [1/s]: omega_n, omega, and the fast decay
 * rate of an overdamped system. */
static double work_rate(const mm_sdof *s)
{
    mm_sdof_props p;
    mm_sdof_props_get(s, &p);
    return mm_sdof_fastest_rate(s, &p);
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

int mm_ex_sdof_integrate(const mm_sdof *s, double t_end, int n, const double *t, double *x,
                         double *v, double rtol, double h_max, mm_ode_result *r, mm_result *res,
                         mm_error *err)
{
    double y0[2] = {s->x0, s->v0};
    mm_sdof_props p;
    mm_sdof_props_get(s, &p);
    /* A first guess of the motion's size for the absolute tolerance; after
     * the run, if the motion turned out much smaller, run again scaled to
     * what it was (the integration scales itself; no reference is used). */
    double forced = fabs(p.X);
    if (s->c == 0 && (s->F0 != 0 || s->G0 != 0))  /* undamped: the beat never passes F t/(m (wn + w)) */
        forced = fmin(p.resonant ? INFINITY : 2 * fabs(p.X),
                      hypot(s->F0, s->G0) * t_end / (s->m * (p.omega_n + s->omega)));
    double scale = fmax(fmax(fabs(s->x0), fabs(s->v0) / fmax(p.omega_n, 1 / t_end)), forced);
    if (!(scale > 0))
        scale = 1;
    /* at most one radian of the fastest motion per step: larger steps stay
     * stable but the error estimate of a step that long undervalues the
     * fast mode (an overdamped case lost 7e-7 of its size at 11 s steps) */
    if (!(h_max > 0))
        h_max = 1.0 / mm_sdof_fastest_rate(s, &p);
    double *xs = x;
    int rc = mm_ex_ode_grid(2, mm_sdof_rhs, (void *)s, y0, t_end, n, t, rtol, rtol * scale, h_max,
                            xs, v, r, res, err);
    double peak = rc == MM_OK ? mm_maxabs(x, n) : 0;
    long first_evals = r->n_eval;
    if (rc == MM_OK && peak > 0 && peak < 0.5 * scale) {
        rc = mm_ex_ode_grid(2, mm_sdof_rhs, (void *)s, y0, t_end, n, t, rtol, rtol * peak, h_max,
                            x, v, r, res, err);
        r->n_eval += first_evals;            /* the cost of the run that found the scale */
    }
    return rc;
}

/* int mm_ex_sdof_run: kept for its callers; the closed form at every
 * stride-th point checked as mm_ex_sdof_response does. */
int mm_ex_sdof_run(const mm_sdof *s, double t_end, int n, const double *t,
                   double *x, double *v, int stride, mm_result *res, mm_error *err)
{
    const double rtol = 1e-8;
    mm_ode_result r;
    int rc = mm_ex_sdof_integrate(s, t_end, n, t, x, v, rtol, 0, &r, res, err);
    if (rc != MM_OK || stride <= 0)
        return rc;
    mm_sdof_props p;
    mm_sdof_props_get(s, &p);
    mm_res_method(res, "dop853 (Dormand-Prince 8(5,3), dense output)", 0);
    mm_res_method_stat(res, "rtol", rtol);
    mm_res_method_stat(res, "steps", (double)r.n_accepted);
    mm_res_method_stat(res, "rejected", (double)r.n_rejected);
    mm_res_method_stat(res, "evaluations", (double)r.n_eval);
    mm_res_method_stat(res, "error_estimate", r.err_sum);
    double worst = -1, xn = 0, xr = 0, peak = 0;
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
    return mm_res_check_abs(res, "x(t) vs closed form (worst sampled point)", xn, xr,
                            1e-6 * peak + 1e-300);
}

double mm_ex_roundoff(double radians, double peak)
{
    /* the closed form's cosines carry eps of their argument, the
     * integrator's sum eps a step: a few eps of the peak per radian */
    return 16 * DBL_EPSILON * (1 + radians) * peak;
}

int mm_ex_sdof_response(const mm_sdof *s, const mm_sdof_props *p, double t_end, int n,
                        const double *t, double *x, double *xi, double *worst, mm_result *res,
                        mm_error *err)
{
    mm_sdof_x_many(s, p, n, t, x);
    double *xf = mm_res_alloc(res, (size_t)n * sizeof *xf);
    if (!xf)
        return MM_ENOMEM;
    /* the run shown, and the error estimate: a run at rtol / MM_EX_SDOF_REF
     * with at least 8 steps (a short run may be one step at both tolerances) */
    double h_max = 1 / mm_sdof_fastest_rate(s, p);
    mm_ode_result r, rf;
    int rc = mm_ex_sdof_integrate(s, t_end, n, t, xi, NULL, MM_EX_SDOF_RTOL, fmin(h_max, t_end / 4), &r,
                                  res, err);
    if (rc == MM_OK)
        rc = mm_ex_sdof_integrate(s, t_end, n, t, xf, NULL, MM_EX_SDOF_RTOL / MM_EX_SDOF_REF, fmin(h_max, t_end / 8),
                                  &rf, res, err);
    if (rc != MM_OK)
        return rc;
    double est = 0;
    for (int i = 0; i < n; i++)
        est = fmax(est, fabs(xi[i] - xf[i]));
    mm_res_method(res, "closed form; dop853 (Dormand-Prince 8(5,3), dense output) beside it", 0);
    mm_res_method_stat(res, "rtol", MM_EX_SDOF_RTOL);
    mm_res_method_stat(res, "steps", (double)r.n_accepted);
    mm_res_method_stat(res, "rejected", (double)r.n_rejected);
    mm_res_method_stat(res, "evaluations", (double)r.n_eval);
    mm_res_method_stat(res, "error_estimate", est);
    mm_res_method_stat(res, "estimate_evaluations", (double)rf.n_eval);
    /* round-off: of the closed form's terms, which may be far larger than
     * the motion (a slow oscillator forced from rest: X - X cos) */
    double radians = t_end * mm_sdof_fastest_rate(s, p), peak = mm_maxabs(x, n);
    double terms = fmax(peak, fabs(p->X) + fabs(s->x0) + fabs(s->v0) / p->omega_n);
    double tol = 10 * est + mm_ex_roundoff(radians, terms);
    *worst = mm_check_curve(res, "x(t): DOP853 vs the closed form (worst plotted point), within 10 times "
                            "its error estimated by a run at rtol/10", n, xi, x,
                            peak > 0 ? tol / peak : 0);
    mm_res_method_stat(res, "max_error", *worst);
    return MM_OK;
}

int mm_ex_sdof_flow_check(const mm_sdof *s, const mm_sdof_props *p, double t_end, mm_result *res)
{
    enum { J = 64 };
    if (p->resonant)
        return MM_OK;
    double w = mm_sdof_fastest_rate(s, p), tau = t_end / J, Phi[4];
    int q;
    mm_sdof_flow(s, w, tau, Phi, &q);
    double lg = p->phase - atan2(-s->G0, s->F0);          /* x_p = X cos(omega t - lg) */
    double worst = 0, big = 0, x0 = 0, u0 = 0;
    for (int j = 0; j <= J; j++) {
        double t = tau * j, v, x = mm_sdof_x(s, p, t, &v), arg = s->omega * t - lg;
        double hx = x - p->X * cos(arg), hu = (v + p->X * s->omega * sin(arg)) / w;   /* y - y_p, scaled */
        big = fmax(big, fabs(x) + fabs(v) / w + fabs(p->X) * (1 + s->omega / w));
        if (j > 0) {
            double ex = hx - (Phi[0] * x0 + Phi[1] * u0), eu = hu - (Phi[2] * x0 + Phi[3] * u0);
            worst = fmax(worst, fabs(ex) + fabs(eu));
        }
        x0 = hx, u0 = hu;
    }
    /* the closed form's own rounding: its cosines carry about an eps of
     * their argument, up to t_end w radians, and its sums a few eps of the
     * terms' sizes; carried by Phi (norm at most ~1 for a damped motion)
     * and Phi's rounding, an eps of ||Phi|| a squaring (over 927 random
     * draws of vib-sdof-forced the worst used 0.14 of this, the median 0.04) */
    double nphi = fmax(fabs(Phi[0]) + fabs(Phi[1]), fabs(Phi[2]) + fabs(Phi[3]));
    double tol = (1 + nphi) * 4 * DBL_EPSILON * (1 + t_end * w) * big + (q + 25) * DBL_EPSILON * nphi * big;
    mm_res_check_abs(res, "closed form vs the flow of eq. (1): x - x_p carried over each of 64 steps by "
                          "exp(tau A), worst |dx| + |dv|/w [m]", worst, 0, tol);
    double v, x = mm_sdof_x(s, p, 0, &v);
    return mm_res_check_abs(res, "closed form at t = 0 vs x0, v0: |dx| + |dv|/w [m]",
                            fabs(x - s->x0) + fabs(v - s->v0) / w, 0,
                            mm_ex_roundoff(0, fabs(s->x0) + fabs(s->v0) / w + 2 * fabs(p->X)));
}

int mm_ex_sdof_plot(const mm_sdof *s, const mm_sdof_props *p, double t_end, mm_series *sx, mm_series *se,
                    mm_result *res, mm_error *err)
{
    int n = sx ? sx->n : 0;
    double *xi = sx && se ? mm_res_alloc(res, (size_t)n * sizeof *xi) : NULL;
    if (!xi)
        return MM_ENOMEM;
    mm_linspace(0, t_end, n, sx->x);
    double worst;
    int rc = mm_ex_sdof_response(s, p, t_end, n, sx->x, sx->y, xi, &worst, res, err);
    if (rc != MM_OK)
        return rc;
    for (int i = 0; i < n; i++) {
        se->x[i] = sx->x[i];
        se->y[i] = xi[i] - sx->y[i];
    }
    mm_ex_round_sig(se->y, n, 3);
    return MM_OK;
}

/* One measurement of the steady state at rtol (see mm_ex_sdof_steady_measure). */
static int steady_once(const mm_sdof *s, const mm_sdof_props *p, int periods, double rtol,
                       double *X, double *lag, mm_result *res, mm_error *err)
{
    enum { PER = 64 };
    int n = PER * periods;
    double T = 2 * M_PI / s->omega;
    double *t = mm_res_alloc(res, 2 * (size_t)(n + 1) * sizeof *t), *x = t + n + 1;
    if (!t)
        return MM_ENOMEM;
    mm_sdof st = *s;
    double lg = p->phase - atan2(-s->G0, s->F0);          /* x_p = X cos(w t - lg) */
    st.x0 = p->X * cos(lg);
    st.v0 = p->X * s->omega * sin(lg);
    mm_linspace(0, periods * T, n + 1, t);
    mm_ode_result r;
    int rc = mm_ex_sdof_integrate(&st, periods * T, n + 1, t, x, NULL, rtol,
                                  fmin(1 / mm_sdof_fastest_rate(s, p), T / 8) * (rtol < MM_EX_SDOF_RTOL ? 0.5 : 1),
                                  &r, res, err);
    if (rc == MM_OK)
        rc = mm_fourier_harmonic(x, (size_t)n, PER, X, lag, err);   /* the last point repeats the first */
    return rc;
}

int mm_ex_sdof_steady_measure(const mm_sdof *s, const mm_sdof_props *p, int periods,
                              double lag_near, double *X, double *lag, double *X_est,
                              double *lag_est, mm_result *res, mm_error *err)
{
    double Xf, lagf;
    int rc = steady_once(s, p, periods, MM_EX_SDOF_RTOL, X, lag, res, err);
    if (rc == MM_OK)
        rc = steady_once(s, p, periods, MM_EX_SDOF_RTOL / MM_EX_SDOF_REF, &Xf, &lagf, res, err);
    if (rc != MM_OK)
        return rc;
    *lag = lag_near + remainder(*lag - lag_near, 2 * M_PI);      /* compare angles, not numbers */
    /* the error is one complex number d in the measured X e^{-i lag}: the
     * runs' difference estimates its size |d|, and each part is within it,
     * dX <= |d| and d lag <= |d| / X.  Not the parts' own differences: a
     * small part of d need not shrink with rtol (an overdamped case had its
     * lag off by 1.77e-13 at rtol and at rtol/10 alike, while |d| fell
     * from 2.5e-13 X to 2.3e-14 X), so |lag - lagf| = 1e-15 missed it */
    double dl = remainder(*lag - lagf, 2 * M_PI), d = hypot(*X - Xf, 2 * sqrt(*X * Xf) * sin(0.5 * dl));
    *X_est = d;
    *lag_est = *X > 0 ? d / *X : fabs(dl);
    return MM_OK;
}

int mm_ex_warn_aliasing(mm_result *res, int n, double span, double omega, const char *remedy)
{
    double per_period = (n - 1) / (span * omega / (2 * M_PI));
    if (!(omega > 0) || per_period >= 8)
        return 0;
    mm_res_warn(res, "the plot has %.1f points per period of the fastest motion: it cannot show the "
                     "oscillation (it aliases); %s", per_period, remedy);
    return 1;
}

mm_scalar *mm_ex_scalar_beside(mm_result *res, int out, double value, double exact, double exact_err)
{
    return mm_res_scalar_err(res, out, value, fabs(value - exact) + exact_err, MM_ERR_BOUND);
}

int mm_ex_anim_frames(double t_end, double period, int npts, double *t_show)
{
    int cap = MM_EX_ANIM_POINTS / (npts > 0 ? npts : 1);
    if (cap > MM_ANIM_MAX_FRAMES)
        cap = MM_ANIM_MAX_FRAMES;
    if (cap < 2)
        cap = 2;
    *t_show = t_end;
    if (!(period > 0) || !isfinite(period))
        return cap / 2 < 2 ? 2 : cap / 2;
    double want = ceil(24 * t_end / period) + 1;
    if (want <= cap)
        return want < 2 ? 2 : (int)want;
    *t_show = (cap - 1) * period / 24;
    return cap;
}

/* nearbyint(x p) / p, with nearbyint done inline where it can be: below
 * 2^51, adding and taking away 1.5 2^52 rounds to the nearest integer (ties
 * to even, as nearbyint in the default mode) and copysign keeps the sign of
 * a zero; libm's nearbyint is a call through the PLT on this baseline ISA. */
static double round_scaled(double x, double p)
{
    double y = x * p;
    if (fabs(y) < 0x1p51)
        y = copysign((y + 0x1.8p52) - 0x1.8p52, y);
    else
        y = nearbyint(y);
    return y / p;
}

/* 10^decimals, exact for 0 <= decimals <= 22. */
static double pow10_exact(int decimals)
{
    double p = 1;
    for (int i = 0; i < decimals; i++)
        p *= 10;
    return p;
}

/* x rounded to `decimals` digits after the point, as the double nearest
 * that short decimal (so that the answer prints it short): an integer over
 * an exact power of ten is correctly rounded. */
static double round_decimals(double x, int decimals)
{
    if (decimals >= 0 && decimals <= 22)
        return round_scaled(x, pow10_exact(decimals));
    char buf[64];
    snprintf(buf, sizeof buf, "%.*f", decimals, x);
    return strtod(buf, NULL);
}

double mm_ex_nice_up(double x)
{
    if (!(x > 0) || !isfinite(x))
        return x;
    double e = pow(10, floor(log10(x)) - 1);          /* two significant digits */
    return ceil(x / e * (1 - 1e-12)) * e;
}

void mm_ex_time_grid(double t_end, int n, double *t)
{
    mm_linspace(0, t_end, n, t);
    double step = t_end / (n - 1);
    for (int k = 0; k <= 15; k++) {                   /* the decimals of the step, if it has few */
        double p = pow(10, k), m = step * p;
        if (fabs(m - nearbyint(m)) <= 8 * DBL_EPSILON * m) {      /* a whole number to rounding */
            for (int i = 0; i < n; i++)
                t[i] = round_decimals(t[i], k);
            return;
        }
    }
}

void mm_ex_round_sig(double *y, int n, int digits)
{
    char buf[48];
    for (int i = 0; i < n; i++) {
        snprintf(buf, sizeof buf, "%.*e", digits - 1, y[i]);
        y[i] = strtod(buf, NULL);
    }
}

/* Round the coordinates of s to `decimals` digits after the point. */
static void round_shape(mm_shape *s, int decimals)
{
    size_t n = (size_t)s->frames * (size_t)s->npts;
    if (decimals >= 0 && decimals <= 22) {
        double p = pow10_exact(decimals);
        for (size_t i = 0; i < n; i++) {
            s->x[i] = round_scaled(s->x[i], p);
            s->y[i] = round_scaled(s->y[i], p);
        }
        return;
    }
    for (size_t i = 0; i < n; i++) {
        s->x[i] = round_decimals(s->x[i], decimals);
        s->y[i] = round_decimals(s->y[i], decimals);
    }
}

int mm_ex_animate_oscillator(mm_result *res, int nf, const double *t, const double *x,
                             const double *y, const double *F, const char *force_name, int damper,
                             int on_floor)
{
    mm_anim *a = mm_res_animation(res, nf, "t", "s");
    if (!a)
        return MM_ENOMEM;
    double big = 0, Fmax = 0;
    for (int f = 0; f < nf; f++) {
        a->t[f] = t[f];
        big = fmax(big, fmax(fabs(x[f]), y ? fabs(y[f]) : 0));
        Fmax = fmax(Fmax, F ? fabs(F[f]) : 0);
    }
    double L = 5 * (big > 0 ? big : 1), H = 0.6 * L;   /* rest length, block height */
    int q = 3 - (int)floor(log10(L));                  /* decimals: 1e-3 of the drawing's size */
    mm_shape *wall = mm_anim_shape(res, y ? "support" : "wall", MM_SHAPE_LINE, y ? nf : 1, 2);
    mm_shape *spring = mm_anim_shape(res, "spring", MM_SHAPE_LINE, nf, MM_SCENE_SPRING_POINTS);
    /* the damper's cylinder is fixed to the support: one frame when that stands still */
    mm_shape *cup = damper ? mm_anim_shape(res, "damper", MM_SHAPE_LINE, y ? nf : 1, MM_SCENE_CUP_POINTS) : NULL;
    mm_shape *piston = damper ? mm_anim_shape(res, "piston", MM_SHAPE_LINE, nf, MM_SCENE_PISTON_POINTS)
                              : NULL;
    mm_shape *mass = mm_anim_shape(res, "mass", MM_SHAPE_POLYGON, nf, MM_SCENE_BOX_POINTS);
    mm_shape *ground = on_floor ? mm_anim_shape(res, "floor", MM_SHAPE_LINE, 1, 2) : NULL;
    mm_shape *arrow = F ? mm_anim_shape(res, force_name, MM_SHAPE_ARROW, nf, 2) : NULL;
    double *Fv = F ? mm_shape_values(res, arrow) : NULL;
    if (!wall || !spring || (damper && (!cup || !piston)) || !mass || (on_floor && !ground) || (F && !Fv))
        return MM_ENOMEM;
    wall->style = "ground";
    double ys = on_floor ? 0.5 * H : 0;                     /* the block's centre height */
    for (int f = 0; f < wall->frames; f++) {
        double yw = y ? y[f] : 0;
        wall->x[2 * f] = wall->x[2 * f + 1] = yw;
        wall->y[2 * f] = ys - 0.7 * H, wall->y[2 * f + 1] = ys + 0.7 * H;
    }
    if (ground) {
        ground->style = "ground";
        ground->x[0] = -0.2 * L, ground->x[1] = 2.6 * L + H;
        ground->y[0] = ground->y[1] = 0;
    }
    if (arrow) {
        arrow->unit = "N";
        arrow->scale = Fmax > 0 ? 0.8 * L / Fmax : 0;
    }
    for (int f = 0; f < nf; f++) {
        double x0 = y ? y[f] : 0, xm = L + x[f];          /* the support; the block's left face */
        double ysp = damper ? ys + 0.25 * H : ys, ydp = ys - 0.25 * H;
        mm_scene_spring(spring, f, x0, ysp, xm, ysp, 0.2 * H);
        if (damper)
            mm_scene_damper(cup, piston, f, x0, ydp, xm, ydp, 0.2 * H, L);
        mm_scene_box(mass, f, xm + 0.5 * H, ys, H, H, 0);
        if (arrow) {
            Fv[f] = F[f];
            double xa = F[f] >= 0 ? xm + H : xm;          /* pushes from its side */
            arrow->x[2 * f] = xa, arrow->y[2 * f] = on_floor ? 0.15 * H : ys;
            arrow->x[2 * f + 1] = xa + arrow->scale * F[f], arrow->y[2 * f + 1] = arrow->y[2 * f];
        }
    }
    round_shape(wall, q);
    round_shape(spring, q);
    round_shape(mass, q);
    if (damper) {
        round_shape(cup, q);
        round_shape(piston, q);
    }
    if (ground)
        round_shape(ground, q);
    if (arrow)
        round_shape(arrow, q);
    return MM_OK;
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

int mm_ex_observed_order(const double *h, const double *e, int n, double lo, double hi, double *order,
                         double *spread)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0, lx[4], ly[4];
    int k = 0;
    for (int i = n - 1; i >= 0 && k < 4; i--) {
        if (!(e[i] <= hi && e[i] >= lo))
            continue;
        lx[k] = log(h[i]), ly[k] = log(e[i]);
        sx += lx[k], sy += ly[k], sxx += lx[k] * lx[k], sxy += lx[k] * ly[k];
        k++;
    }
    if (k < 3)
        return k;
    *order = (k * sxy - sx * sy) / (k * sxx - sx * sx);
    *spread = 0;
    for (int j = 1; j < k; j++)
        *spread = fmax(*spread, fabs((ly[j] - ly[j - 1]) / (lx[j] - lx[j - 1]) - *order));
    return k;
}

static int force_cos(double t, const double *q, const double *qd, double *F, void *ctx)
{
    (void)q;
    (void)qd;
    const mm_sdof *s = ctx;
    F[0] = s->F0 * cos(s->omega * t);
    return 0;
}

int mm_ex_sdof_method(const mm_sdof *s, int m, double h, double rtol, double atol, double t_end, long stride,
                      int cap, double *t, double *x, double *v, mm_ex_run *o, mm_result *res, mm_error *err)
{
    int rc;
    long N = m <= MM_EX_RK4 ? (long)mm_ode_fixed_steps(t_end, h) : 0, max_steps = (long)(cap - 1) * stride;
    *o = (mm_ex_run){.h = m <= MM_EX_RK4 ? t_end / (double)N : 0};
    if (m <= MM_EX_VERLET) {
        double M = s->m, C = s->c, K = s->k, q0 = s->x0, v0 = s->v0;
        mm_newmark_problem prob = {.n = 1, .M = &M, .C = &C, .K = &K, .force = s->F0 ? force_cos : NULL,
                                   .force_kind = MM_NEWMARK_FORCE_TIME, .params = (void *)s, .q0 = &q0,
                                   .qd0 = &v0, .t0 = 0, .t_end = t_end};
        mm_newmark_options opt;
        mm_newmark_options_init(&opt);
        opt.method = m == MM_EX_CENTRAL ? MM_NEWMARK_CENTRAL : m == MM_EX_AVERAGE ? MM_NEWMARK_AVERAGE
                                                                                  : MM_NEWMARK_VERLET;
        opt.h = o->h;                   /* t_end / N: mm_newmark steps with the h it is given */
        opt.stride = stride;
        opt.max_steps = max_steps;
        mm_newmark_result r = {.t = t, .q = x, .qd = v, .max_rows = cap};
        rc = mm_newmark_check(&prob, &opt, err);
        mm_newmark_work *w = rc == MM_OK ? mm_newmark_work_alloc(1) : NULL;
        if (rc == MM_OK)
            rc = w ? mm_newmark_solve(&prob, &opt, w, &r, err) : MM_ENOMEM;
        mm_newmark_work_free(w);
        o->steps = r.steps;
        o->evals = r.force_evals ? r.force_evals : r.steps + 1;   /* F = 0: the force is still "evaluated" */
        o->rows = r.rows;
    } else {
        double y0[2] = {s->x0, s->v0}, *ys = mm_res_alloc(res, 2 * (size_t)cap * sizeof *ys);
        if (!ys)
            return MM_ENOMEM;
        mm_ode_problem prob = {.n = 2, .f = mm_sdof_rhs, .params = (void *)s, .t0 = 0, .t_end = t_end, .y0 = y0};
        mm_ode_options opt;
        mm_ode_options_init(&opt);
        opt.method = m == MM_EX_RK4 ? MM_ODE_RK4 : m == MM_EX_DOPRI5 ? MM_ODE_DOPRI5 : MM_ODE_DOP853;
        opt.h = m == MM_EX_RK4 ? h : 0;
        opt.rtol = rtol;
        opt.atol = atol;
        opt.max_steps = max_steps;
        mm_ode_result r = {0};
        if (stride > 1) {                              /* the state at step multiples: grid output */
            o->rows = (int)(N / stride + 1 + (N % stride != 0));
            for (int i = 0; i < o->rows; i++)
                t[i] = (double)(i * stride < N ? i * stride : N) * o->h;
            r.t_out = t, r.nout = (size_t)o->rows, r.y_out = ys;
        } else {
            r.t_steps = t, r.y_steps = ys, r.steps_cap = (size_t)cap;
        }
        rc = mm_ode_run(&prob, &opt, &r, err);
        o->steps = r.n_accepted;
        o->evals = r.n_eval;
        o->rejected = r.n_rejected;
        if (m != MM_EX_RK4)
            o->h = r.n_accepted ? r.t_reached / r.n_accepted : 0;
        if (stride <= 1)
            o->rows = (int)r.n_stored;
        for (int i = 0; i < o->rows; i++) {
            x[i] = ys[2 * i];
            if (v)
                v[i] = ys[2 * i + 1];
        }
        if (m != MM_EX_RK4 && rc == MM_ENOCONV)
            rc = MM_ENONFINITE;                        /* out of steps: reported like a blow-up */
    }
    o->failed = rc == MM_ENONFINITE;
    return o->failed ? MM_OK : rc;
}
