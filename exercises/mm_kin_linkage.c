/* mm_kin_linkage.c — what the chapter's linkages need beyond their closed
 * forms (solvers/mm_linkage.c): a sweep of the four-bar over a grid from
 * the angle asked, the positions a difference study needs, and the
 * animations of the four-bar, the slider-crank and the quick return.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mm_kin.h"
#include "mm_kin_linkage.h"

/* ---- finite differences of the Newton positions ---- */

int mm_kin_link_fd_pos(int i, double h, double *q, double *qerr, void *ctx, mm_error *err)
{
    mm_kin_link_fd *c = ctx;
    mm_mech_info info;
    for (int j = 0; j < 2; j++)          /* Taylor's guess: Newton stays on the assembly */
        q[j] = c->q[2 * i + j] + h * c->qd[2 * i + j] + 0.5 * h * h * c->qdd[2 * i + j];
    int rc = mm_mech_position(c->p, c->o, c->w, c->t[i] + h, q, &info, err);
    *qerr = info.err_est;
    return rc;
}

void mm_kin_track(mm_kin_worst *w, double got, double ref, double tol)
{
    double r = fabs(got - ref) / tol;
    if (!(r <= w->ratio))
        *w = (mm_kin_worst){r, got, ref, tol};
}

/* ---- the four-bar: the sweep ---- */

/* Positions, velocities, accelerations (per unit crank rate) on the grid
 * x[0..n-1] (increasing), following the assembly q0 found at th2 forward
 * and backward from it.  MM_ENOCONV (theta2 named) if a sweep lost it. */
int mm_kin_fb_sweep(const mm_kin_fb_run *r, double th2, const double *q0, int side, int singular, int n,
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
            mm_linkage_fb_assemble(r->m, t[0], side, q + 2 * skip);
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

/* ---- the four-bar: the animation ---- */

int mm_kin_fb_animate(const mm_kin_fb_run *r, const mm_fourbar_class *k, int side, double w2, double px, double py,
                      double th0, const double *q0, int singular, mm_result *res, mm_error *err)
{
    enum { NF = 72 };
    const mm_fourbar *m = r->m;
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
            mm_linkage_fb_assemble(m, t[0], leg ? -side : side, qq);
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
        mm_linkage_fb_coupler(m, px, py, th[f], q + 2 * f, qd + 2 * f, qdd + 2 * f, &P[f], &V[f], &A[f]);
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

/* ---- the slider-crank ---- */

int mm_kin_sc_animate(const mm_slider_crank *m, double omega, int partial, double lo, double hi,
                      const mm_mech_problem *prob, const mm_mech_options *opt, mm_mech_work *w, mm_result *res,
                      mm_error *err)
{
    /* full turn: 72 frames; partial: out on the right-hand assembly and back
     * on the other one through the toggles, 36 frames each way */
    enum { NF = 72 };
    double phis[NF], q[2 * NF], qd[2 * NF], qdd[2 * NF];
    int half = NF / 2;
    for (int side = 0; side < (partial ? 2 : 1); side++) {
        int nf = partial ? half : NF, off = side * half;
        double t[NF];
        double a0 = lo + 1e-9 * (hi - lo), a1 = hi - 1e-9 * (hi - lo);    /* off the double roots */
        for (int f = 0; f < nf; f++)
            t[f] = partial ? (side ? a1 - (a1 - a0) * f / (nf - 1) : a0 + (a1 - a0) * f / (nf - 1))
                           : 2 * M_PI * f / NF;
        mm_sc_pos g = mm_linkage_sc_closed(m, t[0], side ? -1 : 1);     /* the assembly to start from */
        double *qq = q + 2 * off;
        qq[0] = g.t, qq[1] = g.x;
        mm_mech_sweep s = {.nt = nf, .t = t, .q = qq, .qd = qd + 2 * off, .qdd = qdd + 2 * off, .watch = -1};
        int rc = mm_mech_sweep_solve(prob, opt, w, &s, err);
        if (rc != MM_OK)
            return rc;
        for (int f = s.solved; f < nf; f++) {              /* rounding at a toggle end: hold the last */
            memcpy(qq + 2 * f, qq + 2 * (s.solved - 1), 2 * sizeof *qq);
            memset(qd + 2 * (off + f), 0, 2 * sizeof *qd);
            memset(qdd + 2 * (off + f), 0, 2 * sizeof *qdd);
        }
        memcpy(phis + off, t, (size_t)nf * sizeof *t);
    }
    double xmax = -INFINITY, xmin = INFINITY, vmax = 0, amax = 0;
    for (int f = 0; f < NF; f++) {
        xmax = fmax(xmax, q[2 * f + 1]), xmin = fmin(xmin, q[2 * f + 1]);
        vmax = fmax(vmax, fabs(omega * qd[2 * f + 1]));
        amax = fmax(amax, fabs(omega * omega * qdd[2 * f + 1]));
    }
    mm_kin_draw d;
    mm_anim *a = mm_kin_draw_start(&d, res, NF, "crank angle travelled", "rad", xmax + m->r + fabs(m->e));
    mm_shape *slide = a ? mm_kin_shape(&d, "slide", MM_SHAPE_LINE, 0, 2) : NULL;
    mm_shape *piv = mm_kin_pivot(&d, "O", 0, 0);
    mm_shape *crank = mm_kin_shape(&d, "crank", MM_SHAPE_LINE, 1, 2);
    mm_shape *rod = mm_kin_shape(&d, "rod", MM_SHAPE_LINE, 1, 2);
    mm_shape *block = mm_kin_shape(&d, "slider", MM_SHAPE_POLYGON, 1, 4);
    mm_shape *mid = mm_kin_shape(&d, "rod midpoint path", MM_SHAPE_PATH, 0, NF + 1);
    mm_shape *va = mm_kin_arrow_shape(&d, "v", "m/s", vmax);
    mm_shape *aa = mm_kin_arrow_shape(&d, "a", "m/s^2", amax);
    if (!slide || !piv || !crank || !rod || !block || !mid || !va || !aa)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    slide->style = "ground";
    double bw = 0.3 * fmin(m->r, m->l) + 0.05 * (xmax - xmin);
    mm_kin_pt(slide, 0, 0, fmin(xmin, 0) - bw, m->e);
    mm_kin_pt(slide, 0, 1, xmax + bw, m->e);
    double travelled = 0;
    for (int f = 0; f < NF; f++) {
        if (f)
            travelled += fabs(phis[f] - phis[f - 1]);
        a->t[f] = travelled;
        double Ax = m->r * cos(phis[f]), Ay = m->r * sin(phis[f]), x = q[2 * f + 1];
        mm_kin_pt(crank, f, 0, 0, 0);
        mm_kin_pt(crank, f, 1, Ax, Ay);
        mm_kin_pt(rod, f, 0, Ax, Ay);
        mm_kin_pt(rod, f, 1, x, m->e);
        mm_kin_block(block, f, x, m->e, bw, 0.6 * bw, 0);
        mm_kin_pt(mid, 0, f, 0.5 * (Ax + x), 0.5 * (Ay + m->e));
        mm_kin_arrow(va, f, x, m->e + 0.3 * bw, omega * qd[2 * f + 1], 0);
        mm_kin_arrow(aa, f, x, m->e - 0.3 * bw, omega * omega * qdd[2 * f + 1], 0);
    }
    mm_kin_pt(mid, 0, NF, mid->x[0], mid->y[0]);          /* close the path */
    return mm_kin_draw_finish(&d);
}

/* ---- the quick return: the animation ---- */

int mm_kin_qr_animate(const mm_quick_return *m, double omega, double L, double stroke, const mm_mech_problem *prob,
                      const mm_mech_options *opt, mm_mech_work *w, const double *q0, mm_result *res, mm_error *err)
{
    enum { NF = 72 };
    double t[NF], qa[4 * NF], qva[4 * NF], vmax = 0;
    for (int f = 0; f < NF; f++)
        t[f] = 2 * M_PI * f / NF;
    memcpy(qa, q0, 4 * sizeof *qa);
    mm_mech_sweep sa2 = {.nt = NF, .t = t, .q = qa, .qd = qva, .watch = -1};
    int rc = mm_mech_sweep_solve(prob, opt, w, &sa2, err);
    if (rc != MM_OK)
        return rc;
    for (int f = 0; f < NF; f++)
        vmax = fmax(vmax, fabs(omega * qva[4 * f + 2]));
    mm_kin_draw d;
    double xr = stroke / 2;
    mm_anim *an = mm_kin_draw_start(&d, res, NF, "crank angle", "rad", fmax(L, 2 * xr) + 0.2 * m->H);
    mm_shape *p4 = an ? mm_kin_pivot(&d, "O4", 0, 0) : NULL, *p2 = mm_kin_pivot(&d, "O2", 0, m->d);
    mm_shape *guide = mm_kin_shape(&d, "ram guide", MM_SHAPE_LINE, 0, 2);
    mm_shape *crank = mm_kin_shape(&d, "crank", MM_SHAPE_LINE, 1, 2);
    mm_shape *lever = mm_kin_shape(&d, "lever", MM_SHAPE_LINE, 1, 2);
    mm_shape *blk = mm_kin_shape(&d, "slider block", MM_SHAPE_POLYGON, 1, 4);
    mm_shape *ram = mm_kin_shape(&d, "ram", MM_SHAPE_POLYGON, 1, 4);
    mm_shape *va = mm_kin_arrow_shape(&d, "v_ram", "m/s", vmax);
    if (!p4 || !p2 || !guide || !crank || !lever || !blk || !ram || !va)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    guide->style = "ground";
    double bh = 0.06 * m->H;
    mm_kin_pt(guide, 0, 0, -xr - 0.6 * m->H, m->H + bh), mm_kin_pt(guide, 0, 1, xr + 0.6 * m->H, m->H + bh);
    for (int f = 0; f < NF; f++) {
        an->t[f] = t[f];
        double *qf = qa + 4 * f, Ax = m->r * cos(t[f]), Ay = m->d + m->r * sin(t[f]);
        mm_kin_pt(crank, f, 0, 0, m->d), mm_kin_pt(crank, f, 1, Ax, Ay);
        mm_kin_pt(lever, f, 0, 0, 0), mm_kin_pt(lever, f, 1, L * cos(qf[0]), L * sin(qf[0]));
        mm_kin_block(blk, f, Ax, Ay, 0.08 * m->H, 0.04 * m->H, qf[0]);
        mm_kin_block(ram, f, qf[2], m->H, 0.5 * m->H, bh, 0);
        mm_kin_arrow(va, f, qf[2], m->H + 2 * bh, omega * qva[4 * f + 2], 0);
    }
    return mm_kin_draw_finish(&d);
}

/* ---- a crank that cannot turn round ---- */

void mm_kin_warn_reach(mm_result *res, const char *what, double lo, double hi, const double gaps[2])
{
    if (fabs(lo + 2 * M_PI - hi - gaps[1]) <= 1e-9)     /* one arc: the gap is the rest of the turn */
        mm_res_warn(res, "%s and cannot close from %.4g to %.4g rad", what, hi, lo + 2 * M_PI);
    else
        mm_res_warn(res, "%s and cannot close from %.4g to %.4g nor from %.4g to %.4g rad; the arc beyond those "
                         "gaps is another assembly, reached only by taking the linkage apart",
                    what, hi, hi + gaps[1], lo - gaps[0], lo);
}

int mm_kin_toggle_checks(mm_result *res, const mm_mech_problem *prob, const mm_mech_options *opt, mm_mech_work *w,
                         double lo, double hi, const double gaps[2], void (*assemble)(double t, double *q, void *ctx),
                         void *ctx, const char *why, mm_error *err)
{
    for (int end = 0; end < 2; end++) {
        enum { NT = 9 };
        double t[NT], qq[2 * NT];
        /* past the toggle, but never past the middle of the gap: beyond it
         * the linkage closes again, and a sweep could step across */
        double past = fmin(0.05, 0.5 * gaps[end]);
        double from = end ? hi - 0.1 * (hi - lo) : lo + 0.1 * (hi - lo), to = end ? hi + past : lo - past;
        for (int i = 0; i < NT; i++)
            t[i] = from + (to - from) * i / (NT - 1);
        assemble(t[0], qq, ctx);
        mm_mech_sweep s = {.nt = NT, .t = t, .q = qq, .watch = -1, .tol_t = 1e-13};
        int rc = mm_mech_sweep_solve(prob, opt, w, &s, err);
        if (rc != MM_OK)
            return rc;
        char name[200];
        snprintf(name, sizeof name, "%s toggle: where the sweep stops closing vs %s", end ? "second" : "first", why);
        mm_res_check_abs(res, name, s.t_limit, end ? hi : lo, 1e-9);
    }
    return MM_OK;
}

/* ---- a linkage in natural coordinates: the animation ---- */

int mm_kin_anim_linkage(mm_result *res, const mm_nat_model *m, int ntri, const int (*tri)[3], int nf, const double *t,
                        const double *Q, int solved, mm_error *err)
{
    const mm_nat_linkage *s = m->s;
    const int n = 2 * (s->npts - s->nfix);
    mm_kin_draw d;
    mm_anim *an = mm_kin_draw_start(&d, res, nf, s->amp > 0 ? "t" : "input angle", s->amp > 0 ? "s" : "rad", 1.3);
    if (!an)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    /* binary links as lines, ternary ones as triangles, pivots, the slide */
    for (int k2 = 0; k2 < s->nfix; k2++)
        if (!mm_kin_pivot(&d, "ground pivot", s->p[k2][0], s->p[k2][1]))
            return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_shape *lk[MM_NAT_MAXC] = {0}, *tr[2] = {0}, *blk = NULL;
    for (int c = 0; c < s->ncon; c++) {
        int in_tri = 0;
        for (int r = 0; r < ntri; r++) {
            int hits = 0;
            for (int v = 0; v < 3; v++)
                hits += tri[r][v] == s->con[c][0] || tri[r][v] == s->con[c][1];
            in_tri |= hits == 2;
        }
        if (!in_tri && !(lk[c] = mm_kin_shape(&d, "link", MM_SHAPE_LINE, 1, 2)))
            return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    }
    for (int r = 0; r < ntri; r++)
        if (!(tr[r] = mm_kin_shape(&d, "ternary link", MM_SHAPE_POLYGON, 1, 3)))
            return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    if (s->slide >= 0) {
        mm_shape *g = mm_kin_shape(&d, "slide", MM_SHAPE_LINE, 0, 2);
        blk = mm_kin_shape(&d, "slider", MM_SHAPE_POLYGON, 1, 4);
        if (!g || !blk)
            return mm_error_set(err, MM_ENOMEM, "", "out of memory");
        g->style = "ground";
        mm_kin_pt(g, 0, 0, -0.2, m->y_slide), mm_kin_pt(g, 0, 1, 0.7, m->y_slide);
    }
    for (int f = 0; f < nf; f++) {
        const double *qf = Q + (f < solved ? f : solved - 1) * n;
        double x, y;
        an->t[f] = t[f];
        for (int c = 0; c < s->ncon; c++)
            for (int e = 0; lk[c] && e < 2; e++) {
                mm_nat_point(m, qf, s->con[c][e], &x, &y);
                mm_kin_pt(lk[c], f, e, x, y);
            }
        for (int r = 0; r < ntri; r++)
            for (int v = 0; v < 3; v++) {
                mm_nat_point(m, qf, tri[r][v], &x, &y);
                mm_kin_pt(tr[r], f, v, x, y);
            }
        if (blk) {
            mm_nat_point(m, qf, s->slide, &x, &y);
            mm_kin_block(blk, f, x, y, 0.08, 0.05, 0);
        }
    }
    return mm_kin_draw_finish(&d);
}

/* ---- the Bennett linkage: the animation ---- */

int mm_kin_anim_bennett(mm_result *res, double a, double alpha, double beta, double *worst, mm_error *err)
{
    enum { NF = 72 };
    mm_kin_draw d;
    mm_anim *an = mm_kin_draw_start(&d, res, NF, "input angle", "rad", 0.9);
    mm_shape *loop = an ? mm_kin_shape(&d, "links", MM_SHAPE_POLYGON, 1, 4) : NULL, *ax[4];
    static const char *const axn[4] = {"axis 1", "axis 2", "axis 3", "axis 4"};
    for (int k = 0; k < 4; k++)
        ax[k] = mm_kin_shape(&d, axn[k], MM_SHAPE_LINE, 1, 2);
    if (!loop || !ax[3])
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    *worst = 0;
    for (int f = 0; f < NF; f++) {
        double th1 = 0.05 + (2 * M_PI - 0.1) * f / (NF - 1), g;   /* th1 = 0 folds the loop flat */
        mm_v3 o[4], z[4];
        an->t[f] = th1;
        mm_linkage_bennett(a, alpha, beta, th1, o, z, &g);
        *worst = fmax(*worst, g);
        for (int k = 0; k < 4; k++) {
            double x, y, x1, y1;
            mm_kin_iso(o[k], &x, &y);
            mm_kin_pt(loop, f, k, x, y);
            mm_kin_iso(mm_v3_sub(o[k], mm_v3_scale(z[k], 0.12)), &x, &y);
            mm_kin_iso(mm_v3_add(o[k], mm_v3_scale(z[k], 0.12)), &x1, &y1);
            mm_kin_pt(ax[k], f, 0, x, y), mm_kin_pt(ax[k], f, 1, x1, y1);
        }
    }
    return mm_kin_draw_finish(&d);
}
