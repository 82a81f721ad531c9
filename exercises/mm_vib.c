/* mm_vib.c — the vibration chapter's kit: drawings, animations and families of checks (mm_vib.h). */
#include "mm_vib.h"   /* before complex.h: mm_fem.h has a field named I */

#include <complex.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mm_complex.h"
#include "mm_exhelp.h"
#include "mm_mdof.h"
#include "mm_scene.h"

double mm_vib_big(const double *u, size_t n)
{
    double b = 0;
    for (size_t i = 0; i < n; i++)
        b = fmax(b, fabs(u[i]));
    return b > 0 ? b : 1;
}

int mm_vib_frames(double t_end, double period, int max_frames, double *t_show)
{
    if (max_frames > MM_ANIM_MAX_FRAMES)
        max_frames = MM_ANIM_MAX_FRAMES;
    if (max_frames < 2)
        max_frames = 2;
    *t_show = t_end;
    if (!(period > 0) || !isfinite(period))
        return max_frames / 2 < 2 ? 2 : max_frames / 2;
    double want = ceil(16 * t_end / period) + 1;
    if (want <= max_frames)
        return want < 2 ? 2 : (int)want;
    *t_show = (max_frames - 1) * period / 16;
    return max_frames;
}

/* A zigzag spring of MM_VIB_SPRING_POINTS points from (x0, y) to (x1, y). */
static void spring(mm_shape *s, int f, double x0, double x1, double y, double width)
{
    double len = x1 - x0, lead = len / 8, pitch = (len - 2 * lead) / 6;
    size_t o = (size_t)f * MM_VIB_SPRING_POINTS;
    s->x[o] = x0, s->y[o] = y;
    s->x[o + 1] = x0 + lead, s->y[o + 1] = y;
    for (int k = 0; k < 4; k++) {
        s->x[o + 2 + k] = x0 + lead + (k + 1) * 1.2 * pitch;
        s->y[o + 2 + k] = y + (k % 2 ? -0.5 : 0.5) * width;
    }
    s->x[o + 6] = x1 - lead, s->y[o + 6] = y;
    s->x[o + 7] = x1, s->y[o + 7] = y;
}

int mm_vib_masses_numbers(int n, const double *K)
{
    int springs = 0;
    for (int i = 0; i < n; i++) {
        double ground = 0;
        for (int j = 0; j < n; j++) {
            ground += K[i * n + j];
            springs += j > i && K[i * n + j] != 0;
        }
        springs += ground != 0;
    }
    return 2 * (springs * MM_VIB_SPRING_POINTS + n * MM_SCENE_BOX_POINTS);
}

void mm_vib_mode_frames(int n, const double *phi, int ld, int j, double omega, double A, int nf,
                        double *t, double *q)
{
    double T = omega > 0 ? 2 * M_PI / omega : 1;
    for (int f = 0; f < nf; f++) {
        double s = sin(2 * M_PI * f / (nf - 1));
        t[f] = T * f / (nf - 1);
        for (int i = 0; i < n; i++)
            q[(size_t)f * n + i] = A * phi[(size_t)i * ld + j] * s;
    }
}

int mm_vib_masses_draw(mm_result *res, int n, const double *K, int nf, const double *q,
                       double gap)
{
    double w = 0.5 * gap, H = 0.5 * gap, big = 0;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            big = fmax(big, fabs(K[i * n + j]));
    int wall[2] = {0, 0};
    char name[32];
    for (int i = 0; i < n; i++) {
        double ground = 0;
        for (int j = 0; j < n; j++)
            ground += K[i * n + j];
        int right = 2 * i + 1 > n;                    /* tie to the nearer wall */
        if (fabs(ground) > 1e-12 * big) {
            wall[right] = 1;
            snprintf(name, sizeof name, right ? "spring %d-wall" : "spring wall-%d", i + 1);
            mm_shape *s = mm_anim_shape(res, name, MM_SHAPE_LINE, nf, MM_VIB_SPRING_POINTS);
            if (!s)
                return MM_ENOMEM;
            for (int f = 0; f < nf; f++) {
                double xi = (i + 1) * gap + q[(size_t)f * n + i];
                if (right)
                    spring(s, f, xi + w / 2, (n + 1) * gap, 0, 0.4 * H);
                else
                    spring(s, f, 0, xi - w / 2, 0, 0.4 * H);
            }
        }
        for (int j = i + 1; j < n; j++) {
            if (!(fabs(K[i * n + j]) > 1e-12 * big))
                continue;
            snprintf(name, sizeof name, "spring %d-%d", i + 1, j + 1);
            int adj = j == i + 1;
            mm_shape *s = mm_anim_shape(res, name, MM_SHAPE_LINE, nf, adj ? MM_VIB_SPRING_POINTS : 4);
            if (!s)
                return MM_ENOMEM;
            for (int f = 0; f < nf; f++) {
                double xi = (i + 1) * gap + q[(size_t)f * n + i], xj = (j + 1) * gap + q[(size_t)f * n + j];
                if (adj) {
                    spring(s, f, xi + w / 2, xj - w / 2, 0, 0.4 * H);
                } else {                               /* an arch above the row */
                    double y = H * (0.8 + 0.3 * (j - i));
                    size_t o = (size_t)f * 4;
                    s->x[o] = xi, s->y[o] = H / 2;
                    s->x[o + 1] = xi, s->y[o + 1] = y;
                    s->x[o + 2] = xj, s->y[o + 2] = y;
                    s->x[o + 3] = xj, s->y[o + 3] = H / 2;
                }
            }
        }
    }
    for (int side = 0; side < 2; side++) {
        if (!wall[side])
            continue;
        mm_shape *s = mm_anim_shape(res, side ? "wall right" : "wall left", MM_SHAPE_LINE, 1, 2);
        if (!s)
            return MM_ENOMEM;
        s->style = "ground";
        s->x[0] = s->x[1] = side ? (n + 1) * gap : 0;
        s->y[0] = -H, s->y[1] = H;
    }
    for (int i = 0; i < n; i++) {
        snprintf(name, sizeof name, "mass %d", i + 1);
        mm_shape *s = mm_anim_shape(res, name, MM_SHAPE_POLYGON, nf, MM_SCENE_BOX_POINTS);
        if (!s)
            return MM_ENOMEM;
        for (int f = 0; f < nf; f++)
            mm_scene_box(s, f, (i + 1) * gap + q[(size_t)f * n + i], 0, w, H, 0);
    }
    return MM_OK;
}

/* w(x) or u(x) of the displacement vector u at x, by the element's shape functions. */
static double field_at(const mm_fem_problem *p, const double *u, double x)
{
    double L = p->uniform.L, Le = L / (double)p->n_el;
    size_t e = (size_t)fmin(floor(x / Le), (double)p->n_el - 1);
    double xi = x / Le - (double)e;
    if (p->kind == MM_FEM_BAR)
        return (1 - xi) * u[e] + xi * u[e + 1];
    const double *v = u + 2 * e;
    double x2 = xi * xi, x3 = x2 * xi;
    return (1 - 3 * x2 + 2 * x3) * v[0] + Le * (xi - 2 * x2 + x3) * v[1] + (3 * x2 - 2 * x3) * v[2] +
           Le * (x3 - x2) * v[3];
}

int mm_vib_member_draw(mm_result *res, const mm_fem_problem *p, int nf, const double *u,
                       double scale)
{
    size_t ndof = mm_fem_ndof(p);
    double L = p->uniform.L;
    int beam = p->kind == MM_FEM_BEAM, per = beam ? 2 : 1, cap = beam ? 61 : 51;
    int np = per * (int)p->n_el + 1 < cap ? per * (int)p->n_el + 1 : cap;
    mm_shape *m = mm_anim_shape(res, beam ? "member" : "u(x)", MM_SHAPE_LINE, nf, np);
    if (!m)
        return MM_ENOMEM;
    double y0 = beam ? 0 : 0.25 * L;                     /* a bar's u(x) is drawn above its axis */
    for (int f = 0; f < nf; f++)
        for (int k = 0; k < np; k++) {
            double x = L * k / (np - 1);
            m->x[(size_t)f * np + k] = x;
            m->y[(size_t)f * np + k] = y0 + scale * field_at(p, u + (size_t)f * ndof, x);
        }
    if (!beam) {
        mm_shape *axis = mm_anim_shape(res, "member", MM_SHAPE_LINE, 1, 2);
        if (!axis)
            return MM_ENOMEM;
        axis->x[0] = 0, axis->x[1] = L;
        axis->y[0] = axis->y[1] = 0;
        int nt = p->n_el + 1 < 11 ? (int)p->n_el + 1 : 11;
        for (int k = 0; k < nt; k++) {
            size_t node = (size_t)llround((double)p->n_el * k / (nt - 1));
            char name[24];
            snprintf(name, sizeof name, "node %zu", node);
            mm_shape *c = mm_anim_shape(res, name, MM_SHAPE_CIRCLE, nf, 1);
            if (!c)
                return MM_ENOMEM;
            c->radius = 0.01 * L;
            for (int f = 0; f < nf; f++) {
                c->x[f] = L * (double)node / (double)p->n_el + scale * u[(size_t)f * ndof + node];
                c->y[f] = 0;
            }
        }
    }
    /* supports: a wall for a clamped or fixed end, a wedge for a pin */
    int left = p->bc != MM_FEM_FREE_FREE, right = p->bc == MM_FEM_FIXED_FIXED ||
                                                  p->bc == MM_FEM_PINNED_PINNED || p->bc == MM_FEM_FIXED_PINNED;
    for (int side = 0; side < 2; side++) {
        if (!(side ? right : left))
            continue;
        int pin = p->bc == MM_FEM_PINNED_PINNED || (side && p->bc == MM_FEM_FIXED_PINNED);
        mm_shape *s = mm_anim_shape(res, side ? "support right" : "support left",
                                    pin ? MM_SHAPE_POLYGON : MM_SHAPE_LINE, 1, pin ? 3 : 2);
        if (!s)
            return MM_ENOMEM;
        s->style = "ground";
        double x = side ? L : 0, d = 0.04 * L;
        if (pin) {
            s->x[0] = x, s->y[0] = 0;
            s->x[1] = x - d, s->y[1] = -1.5 * d;
            s->x[2] = x + d, s->y[2] = -1.5 * d;
        } else {
            s->x[0] = s->x[1] = x;
            s->y[0] = -2 * d, s->y[1] = 2 * d;
        }
    }
    return MM_OK;
}

int mm_vib_check_system(const mm_value *M, const mm_value *C, const mm_value *K, int nvec,
                        const mm_value *const *vec, const char *const *vnames, mm_error *err)
{
    int n = M->rows;
    const mm_value *sq[3] = {M, C, K};
    static const char *const sname[3] = {"M", "C", "K"};
    for (int k = 0; k < 3; k++) {
        const mm_value *v = sq[k];
        if (!v)
            continue;
        if (v->rows != n || v->cols != n)
            return mm_error_set(err, MM_ERANGE, sname[k], "%s must be square and n x n like M (n = %d); got "
                                "%d x %d", sname[k], n, v->rows, v->cols);
        double big = mm_vib_big(v->data, (size_t)n * n);
        for (int i = 0; i < n; i++)
            for (int j = i + 1; j < n; j++)
                if (fabs(v->data[i * n + j] - v->data[j * n + i]) > 1e-12 * big)
                    return mm_error_set(err, MM_EVALUE, sname[k], "%s must be symmetric, but %s(%d,%d) = %g "
                                        "and %s(%d,%d) = %g", sname[k], sname[k], i + 1, j + 1,
                                        v->data[i * n + j], sname[k], j + 1, i + 1, v->data[j * n + i]);
    }
    for (int k = 0; k < nvec; k++)
        if (vec[k]->cols != n)
            return mm_error_set(err, MM_ERANGE, vnames[k], "%s must have %d values, one per coordinate; got %d",
                                vnames[k], n, vec[k]->cols);
    double w[MM_MDOF_MAX_STATE_DOF];
    for (int k = 1; k < 3 && n <= MM_MDOF_MAX_STATE_DOF; k++) {
        if (!sq[k])
            continue;
        mm_mdof_system ms = {n, M->data, NULL, sq[k]->data};
        int rc = mm_mdof_modes(&ms, n, w, NULL, NULL, err);
        if (rc == MM_ESINGULAR)
            return mm_error_set(err, MM_ERANGE, "M", "M must be positive definite (every motion needs "
                                "kinetic energy); this one is not");
        if (rc == MM_ERANGE && k == 1)
            return mm_error_set(err, MM_ERANGE, "C", "C must be positive semidefinite (a damper takes energy "
                                "out, never puts it in)");
        if (rc)
            return rc;
    }
    return MM_OK;
}

int mm_vib_chain_draw(mm_result *res, int n, int right_wall, int nf, const double *q, double gap)
{
    int step = (n + 59) / 60, nm = (n + step - 1) / step, cs = (n + 119) / 120, nc = (n + cs - 1) / cs;
    double L = (n + 1) * gap, big = mm_vib_big(q, (size_t)nf * n), H = 0.3 * L;
    mm_shape *line = mm_anim_shape(res, "springs", MM_SHAPE_LINE, nf, nm + 1 + right_wall);
    mm_shape *across = mm_anim_shape(res, "u across", MM_SHAPE_LINE, nf, nc + 1 + right_wall);
    if (!line || !across)
        return MM_ENOMEM;
    for (int f = 0; f < nf; f++) {
        const double *u = q + (size_t)f * n;
        size_t o = (size_t)f * line->npts, p = (size_t)f * across->npts;
        line->x[o] = 0, line->y[o] = 0;
        across->x[p] = 0, across->y[p] = H;
        for (int k = 0; k < nm; k++) {
            int i = k * step;
            line->x[o + 1 + k] = (i + 1) * gap + u[i], line->y[o + 1 + k] = 0;
        }
        for (int k = 0; k < nc; k++) {
            int i = k * cs;
            across->x[p + 1 + k] = (i + 1) * gap, across->y[p + 1 + k] = H + 0.15 * L * u[i] / big;
        }
        if (right_wall) {
            line->x[o + nm + 1] = L, line->y[o + nm + 1] = 0;
            across->x[p + nc + 1] = L, across->y[p + nc + 1] = H;
        }
    }
    char name[24];
    for (int k = 0; k < nm; k++) {
        int i = k * step;
        snprintf(name, sizeof name, "mass %d", i + 1);
        mm_shape *c = mm_anim_shape(res, name, MM_SHAPE_CIRCLE, nf, 1);
        if (!c)
            return MM_ENOMEM;
        c->radius = 0.2 * gap * step;
        for (int f = 0; f < nf; f++)
            c->x[f] = (i + 1) * gap + q[(size_t)f * n + i], c->y[f] = 0;
    }
    for (int side = 0; side <= right_wall; side++) {
        mm_shape *w = mm_anim_shape(res, side ? "wall right" : "wall left", MM_SHAPE_LINE, 1, 2);
        if (!w)
            return MM_ENOMEM;
        w->style = "ground";
        w->x[0] = w->x[1] = side ? L : 0;
        w->y[0] = -0.5 * gap * step, w->y[1] = 0.5 * gap * step;
    }
    return MM_OK;
}

static int vib_force(double t, const double *q, const double *qd, double *F, void *ctx)
{
    (void)q, (void)qd;
    const double *p = ctx;          /* n, W, F[n] */
    for (int i = 0; i < (int)p[0]; i++)
        F[i] = p[2 + i] * cos(p[1] * t);
    return 0;
}

int mm_vib_transient_run(mm_result *res, int n, const double *M, const double *K, const double *omega,
                         const double *Phi, const double *c, int m, const double *q0, const double *v0,
                         const double *F, double W, double h, double t_end, int points,
                         mm_vib_transient *o, mm_error *err)
{
    size_t nn = (size_t)n * n;
    double *C = mm_res_alloc(res, nn * sizeof *C), *MP = mm_res_alloc(res, nn * sizeof *MP);
    double *fp = mm_res_alloc(res, (size_t)(n + 2) * sizeof *fp);
    if (!C || !MP || !fp)
        return MM_ENOMEM;
    for (int i = 0; i < n; i++)                 /* M Phi */
        for (int j = 0; j < n; j++)
            for (int k = 0; k < n; k++)
                MP[i * n + j] += M[i * n + k] * Phi[k * n + j];
    for (int i = 0; i < n; i++)                 /* C = (M Phi) diag(c) (M Phi)^T */
        for (int k = 0; k < n; k++)
            for (int j = 0; j < n; j++)
                C[i * n + k] += MP[i * n + j] * c[j] * MP[k * n + j];
    fp[0] = n, fp[1] = W;
    memcpy(fp + 2, F, (size_t)n * sizeof *F);

    /* the direct run */
    mm_newmark_problem pr = {.n = n, .M = M, .C = C, .K = K, .force = vib_force,
                             .force_kind = MM_NEWMARK_FORCE_TIME, .params = fp, .q0 = q0, .qd0 = v0,
                             .t0 = 0, .t_end = t_end};
    mm_newmark_options opt;
    mm_newmark_options_init(&opt);
    opt.h = h;
    o->steps = mm_newmark_step_count(&pr, &opt);
    o->stride = (o->steps + points - 2) / (points - 1);
    opt.stride = o->stride;
    int rc = mm_newmark_check(&pr, &opt, err), ns = mm_newmark_output_rows(&pr, &opt);
    if (rc)
        return rc;
    o->ns = ns;
    o->t = mm_res_alloc(res, (size_t)ns * sizeof *o->t);
    o->q_nm = mm_res_alloc(res, (size_t)ns * n * sizeof *o->q_nm);
    o->q_ex = mm_res_alloc(res, (size_t)ns * n * sizeof *o->q_ex);
    o->q_m = mm_res_alloc(res, (size_t)ns * n * sizeof *o->q_m);
    double *qd = mm_res_alloc(res, (size_t)ns * n * sizeof *qd), *qt = mm_res_alloc(res, (size_t)ns * n * sizeof *qt);
    double *eta = mm_res_alloc(res, (size_t)ns * sizeof *eta);
    long *ks = mm_res_alloc(res, (size_t)ns * sizeof *ks);
    mm_newmark_work *w = mm_newmark_work_alloc(n);
    if (!o->t || !o->q_nm || !o->q_ex || !o->q_m || !qd || !qt || !eta || !ks || !w) {
        mm_newmark_work_free(w);
        return MM_ENOMEM;
    }
    double *vv = mm_res_alloc(res, (size_t)ns * n * sizeof *vv), *aa = mm_res_alloc(res, (size_t)ns * n * sizeof *aa);
    if (!vv || !aa)
        return MM_ENOMEM;
    mm_newmark_result r = {.t = o->t, .q = o->q_nm, .qd = vv, .qdd = aa, .max_rows = ns};
    rc = mm_newmark_solve(&pr, &opt, w, &r, err);
    mm_newmark_work_free(w);
    if (rc)
        return rc;
    for (int i = 0; i < ns; i++)
        ks[i] = i < ns - 1 ? i * o->stride : o->steps;

    /* modal superposition, exact: all modes, and the first m */
    mm_mdof_pulse g = {1, W, INFINITY};
    if ((rc = mm_mdof_modal_response(n, n, omega, c, Phi, n, M, q0, v0, F, &g, ns, o->t, o->q_ex, err)) ||
        (rc = mm_mdof_modal_response(n, m, omega, c, Phi, n, M, q0, v0, F, &g, ns, o->t, o->q_m, err)))
        return rc;
    /* every mode's exact discrete Newmark solution, superposed */
    memset(qd, 0, (size_t)ns * n * sizeof *qd);
    for (int j = 0; j < n; j++) {
        double one = 1, k2 = omega[j] * omega[j], pj = 0, e0 = 0, ed0 = 0;
        for (int i = 0; i < n; i++) {
            pj += Phi[i * n + j] * F[i];
            e0 += MP[i * n + j] * (q0 ? q0[i] : 0);
            ed0 += MP[i * n + j] * (v0 ? v0[i] : 0);
        }
        mm_mdof_system s1 = {1, &one, &c[j], &k2};
        mm_mdof_motion mo = {&e0, &ed0, &pj, W};
        if ((rc = mm_mdof_newmark_exact(&s1, &mo, &opt, ns, ks, eta, NULL, err)))
            return rc;
        for (int k = 0; k < ns; k++)
            for (int i = 0; i < n; i++)
                qd[k * n + i] += Phi[i * n + j] * eta[k];
    }
    /* the coupled system's transition matrix */
    mm_mdof_system sys = {n, M, C, K};
    mm_mdof_motion mo = {q0, v0, F, W};
    if ((rc = mm_mdof_exact(&sys, &mo, h, ns, ks, qt, NULL, err)))
        return rc;
    /* the sizes rounding is relative to.  A Newmark step adds up q + h v +
     * h^2 a (its terms cancel where omega h >> 1) and rounds each of q, v
     * and a by a few eps; a displacement error stays that size, but an
     * error dv in v moves q on by dv sin(omega_1 t) / omega_1, up to
     * dv min(t_end, 1 / omega_1): a soft chain drifts (omega_1 t_end = 0.055
     * and v t_end = 230 times q + h v + h^2 a at a draw whose run differed
     * by 6.1e5 eps of the latter).  The transition matrix carries q and
     * v / w (w = sqrt(max K_ii/M_ii)) */
    double big = 0, dd = 0, ds = 0, snm = 0, sex = 0, w2 = 0, w1 = INFINITY, vm = 0, am = 0;
    for (int i = 0; i < n; i++) {
        w2 = fmax(w2, K[i * n + i] / M[i * n + i]);
        w1 = fmin(w1, omega[i]);
    }
    for (int i = 0; i < ns * n; i++) {
        snm = fmax(snm, fabs(o->q_nm[i]) + h * fabs(vv[i]) + h * h * fabs(aa[i]));
        sex = fmax(sex, fabs(o->q_nm[i]) + (w2 > 0 ? fabs(vv[i]) / sqrt(w2) : 0));
        vm = fmax(vm, fabs(vv[i]));
        am = fmax(am, fabs(aa[i]));
    }
    double drift = w1 > 1 / t_end ? 1 / w1 : t_end;
    snm += drift * (vm + h * am);
    o->err_max = o->trunc_max = 0;
    for (int i = 0; i < ns * n; i++) {
        big = fmax(big, fmax(fabs(o->q_ex[i]), fabs(o->q_nm[i])));
        dd = fmax(dd, fabs(o->q_nm[i] - qd[i]));
        ds = fmax(ds, fabs(o->q_ex[i] - qt[i]));
        o->err_max = fmax(o->err_max, fabs(o->q_nm[i] - o->q_ex[i]));
        o->trunc_max = fmax(o->trunc_max, fabs(o->q_m[i] - o->q_ex[i]));
    }
    /* the transition matrix e^{G D} over a gap D = stride h carries the
     * rounding of its scaling and squaring, about eps ||G D||, into each
     * of the ns samples: 16 eps of that a sample (the difference reached
     * 1.3 eps a sample over 2,000 draws of each transient exercise; 64
     * was 181 times the error at the defaults) */
    double cmax = 0;
    for (int j = 0; j < n; j++)
        cmax = fmax(cmax, c[j]);
    double gd = 1 + (sqrt(w2) + cmax + W) * h * (double)o->stride;
    o->round = 16 * DBL_EPSILON * ns * fmax(big, sex) * gd;
    /* the run and the modes' exact discrete solutions: 64 eps of the
     * state for a run's first steps, where the h^2 a terms of a long step
     * cancel (46 eps measured over runs of 1 or 2 steps), then 4 eps a
     * step and a sample: the run's steps, and the powers' products,
     * ns (1 + log2 stride) <= steps + ns (measured: at most 1 a step over
     * runs of 3 to 10 steps, 0.1 over runs of 1,000 and more; 2,000 draws
     * of each transient exercise).  Then the phase of cos(W t): the run
     * evaluates it at W t_k, the powers rotate it, the two differ by eps
     * W t each (up to 1e7 radians here) */
    double tnm = DBL_EPSILON * (64 + 4.0 * ((double)o->steps + ns) + 2 * W * t_end) * snm + 1e-300;
    o->round_nm = o->round + tnm;         /* q_nm - q_ex: the run's rounding and the exact's */
    mm_res_check_abs(res, "direct Newmark run vs every mode's exact discrete Newmark solution, superposed: worst "
                          "difference [m] (rounding)", dd, 0, tnm);
    mm_res_check_abs(res, "modal superposition (every mode exact) vs the coupled system's transition matrix: worst "
                          "difference [m] (rounding)", ds, 0, o->round + 1e-300);
    return MM_OK;
}

/* ---- the transient exercises (5.10.2, 5.11.1): what they show ---------------- */

int mm_vib_transient_show(mm_result *res, const mm_vib_transient *tr, int n, double h, int out_err,
                          int out_trunc, int nc, const int *coord, const int *out, int sets)
{
    mm_res_scalar_err(res, out_err, tr->err_max, tr->round_nm, MM_ERR_ESTIMATE);
    mm_res_scalar_err(res, out_trunc, tr->trunc_max, tr->round, MM_ERR_ESTIMATE);
    const double *src[3] = {tr->q_nm, tr->q_ex, tr->q_m};
    for (int s = 0; s < sets; s++)
        for (int i = 0; i < nc; i++) {
            mm_series *se = mm_res_series(res, out[s * nc + i], tr->ns);
            if (!se)
                return MM_ENOMEM;
            for (int k = 0; k < tr->ns; k++)
                se->x[k] = tr->t[k], se->y[k] = src[s][(size_t)k * n + coord[i]];
        }
    mm_res_method(res, mm_newmark_method_name(MM_NEWMARK_AVERAGE), h);
    mm_res_method_stat(res, "steps", (double)tr->steps);
    return MM_OK;
}

int mm_vib_modal_frames(mm_result *res, int n, const double *M, const double *omega, const double *c,
                        const double *Phi, const double *q0, const double *v0, const double *F, double W,
                        double t_end, double period, int max_frames, int *nf, double **q, mm_error *err)
{
    double t_show;
    *nf = mm_vib_frames(t_end, period, max_frames, &t_show);
    mm_anim *a = mm_res_animation(res, *nf, "t", "s");
    double *t = mm_res_alloc(res, (size_t)*nf * sizeof *t);
    *q = mm_res_alloc(res, (size_t)*nf * n * sizeof **q);
    if (!a || !t || !*q)
        return MM_ENOMEM;
    for (int f = 0; f < *nf; f++)
        t[f] = a->t[f] = t_show * f / (*nf - 1);
    mm_mdof_pulse g = {1, W, INFINITY};
    return mm_mdof_modal_response(n, n, omega, c, Phi, n, M, q0, v0, F, &g, *nf, t, *q, err);
}

void mm_vib_scale(double *q, size_t n, double largest)
{
    double big = 0;
    for (size_t i = 0; i < n; i++)
        big = fmax(big, fabs(q[i]));
    if (!(big > 0))
        return;
    for (size_t i = 0; i < n; i++)
        q[i] *= largest / big;
}

/* ---- the 1-DOF exercises (5.9): the block moving, the steady state measured ---- */

int mm_vib_sdof_animate(mm_result *res, const mm_sdof *s, const mm_sdof_props *p, double t_end, double period,
                        int npts, int force, const double *Y, int damper)
{
    double t_show;
    int nf = mm_ex_anim_frames(t_end, period, npts, &t_show);
    double *t = mm_res_alloc(res, 4 * (size_t)nf * sizeof *t), *x = t + nf, *F = x + nf, *y = F + nf;
    if (!t)
        return MM_ENOMEM;
    for (int f = 0; f < nf; f++) {
        t[f] = t_show * f / (nf - 1);
        x[f] = mm_sdof_x(s, p, t[f], NULL);
        F[f] = s->F0 * cos(s->omega * t[f]);
        y[f] = Y ? *Y * cos(s->omega * t[f]) : 0;
    }
    return mm_ex_animate_oscillator(res, nf, t, x, Y ? y : NULL, force && s->F0 != 0 ? F : NULL, "F", damper, 0);
}

int mm_vib_steady_check(mm_result *res, const mm_sdof *s, const mm_sdof_props *p, double G, double A,
                        double phase, const char *x_ref, mm_error *err)
{
    if (!(4 * M_PI / s->omega * mm_sdof_fastest_rate(s, p) <= MM_SDOF_MAX_RADIANS))
        return MM_OK;
    double Xm, phm, Xe, phe, rnd = mm_ex_roundoff(4 * M_PI, 1);     /* two periods of round-off */
    int rc = mm_ex_sdof_steady_measure(s, p, 2, phase, &Xm, &phm, &Xe, &phe, res, err);
    if (rc != MM_OK)
        return rc;
    char name[160];
    snprintf(name, sizeof name, "X: measured on the steady orbit vs %s, within 10 times DOP853's error estimated "
             "at rtol/10", x_ref);
    mm_res_check_abs(res, name, Xm, G * A, 10 * Xe + rnd * G * A);
    mm_res_check_abs(res, "phase: measured on the steady orbit vs eq. (4), within 10 times DOP853's error "
                          "estimated at rtol/10", phm, phase, 10 * phe + rnd);
    return MM_OK;
}

int mm_vib_sdof_check(const mm_sdof *s, double t_end, int forced, const char *what, mm_error *err)
{
    mm_sdof_props p;
    mm_sdof_props_get(s, &p);
    if (p.resonant && forced)
        return mm_error_set(err, MM_ERANGE, "omega", "omega = omega_n = %g rad/s with c = 0 has no steady state (the "
                            "%s grows without bound); add damping or move omega (see vib-resonance)", p.omega_n, what);
    return mm_ex_sdof_work_check(s, t_end, err);
}

int mm_vib_coulomb_animate(mm_result *res, const mm_coulomb *s, const double *te, const double *xe,
                           const double *sge, int ne, double t_plot)
{
    double t_show;
    int nf = mm_ex_anim_frames(t_plot, 2 * M_PI / s->w, 26, &t_show);
    double *t = mm_res_alloc(res, 3 * (size_t)nf * sizeof *t), *x = t + nf, *F = x + nf;
    if (!t)
        return MM_ENOMEM;
    for (int f = 0; f < nf; f++) {
        double v;
        t[f] = t_show * f / (nf - 1);
        x[f] = mm_coulomb_x(s, te, xe, sge, ne, t[f], &v);
        F[f] = v != 0 ? (v > 0 ? -1 : 1) * s->mu * s->m * s->g : s->k * x[f];
    }
    return mm_ex_animate_oscillator(res, nf, t, x, NULL, F, "friction", 0, 1);
}

/* ---- the finite-element exercises (5.12) ---------------------------------------- */

const char *mm_vib_fem_method(mm_fem_method m)
{
    return m == MM_FEM_DENSE     ? "LAPACK dsygvd, dense: every mode of the mesh"
           : m == MM_FEM_BANDED  ? "LAPACK dsbgvx, banded: only the modes shown"
           : m == MM_FEM_LANCZOS ? "shift-invert Lanczos with K^-1 M, banded: only the modes shown"
                                 : "subspace iteration with K^-1 M, banded: only the modes shown";
}

int mm_vib_member_mode(mm_result *res, const mm_fem_problem *p, const double *shape, double omega, int nf,
                       double scale)
{
    size_t nd = mm_fem_ndof(p);
    mm_anim *a = mm_res_animation(res, nf, "t", "s");
    double *u = mm_res_alloc(res, (size_t)nf * nd * sizeof *u);
    if (!a || !u)
        return MM_ENOMEM;
    mm_vib_mode_frames((int)nd, shape, 1, 0, omega, 1, nf, a->t, u);
    return mm_vib_member_draw(res, p, nf, u, scale);
}

int mm_vib_member_snaps(mm_result *res, const mm_fem_problem *p, int nf, const long *snap, double h, const double *u,
                        double frac)
{
    size_t nd = mm_fem_ndof(p), step = p->kind == MM_FEM_BEAM ? 2 : 1;
    mm_anim *a = mm_res_animation(res, nf, "t", "s");
    double big = 0;
    if (!a)
        return MM_ENOMEM;
    for (int f = 0; f < nf; f++) {
        a->t[f] = h * (double)snap[f];
        for (size_t g = 0; g < nd; g += step)
            big = fmax(big, fabs(u[(size_t)f * nd + g]));
    }
    return mm_vib_member_draw(res, p, nf, u, big > 0 ? frac * p->uniform.L / big : 1);
}

/* ---- the absorber (5.10.1): a steady motion of complex amplitudes ------------- */

int mm_vib_masses_steady(mm_result *res, int n, const double *K, const _Complex double *X, double omega, int nf)
{
    mm_anim *an = mm_res_animation(res, nf, "t", omega > 0 ? "s" : "periods");
    double *q = mm_res_alloc(res, (size_t)nf * n * sizeof *q), big = 0;
    if (!an || !q)
        return MM_ENOMEM;
    for (int i = 0; i < n; i++)
        big = fmax(big, cabs(X[i]));
    double sc = isfinite(big) && big > 0 ? 0.25 / big : 0;
    for (int fr = 0; fr < nf; fr++) {
        double ph = 2 * M_PI * fr / (nf - 1);
        an->t[fr] = omega > 0 ? ph / omega : ph / (2 * M_PI);
        for (int i = 0; i < n; i++)
            q[(size_t)fr * n + i] = sc * creal(X[i] * cexp(mm_cmplx(0, ph)));
    }
    return mm_vib_masses_draw(res, n, K, nf, q, 1.0);
}
