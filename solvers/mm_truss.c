/* mm_truss.c — planar trusses: joint equations, diagnosis in words,
 * sections.  The contract is in mm_truss.h. */
#include "mm_truss.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ==== checks ==================================================================== */

static double extent(const mm_truss *t)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < t->n_nodes; i++)
        for (int d = 0; d < 2; d++) {
            lo[d] = fmin(lo[d], t->xy[2 * i + d]);
            hi[d] = fmax(hi[d], t->xy[2 * i + d]);
        }
    double e = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    return e > 0 ? e : 1;
}

int mm_truss_check(const mm_truss *t, mm_error *err)
{
    if (t->n_nodes < 1 || t->n_nodes > MM_TRUSS_MAX_NODES)
        return mm_error_set(err, MM_ERANGE, "nodes", "a truss has 1 to %d joints; got %d",
                            MM_TRUSS_MAX_NODES, t->n_nodes);
    if (t->n_members < 1 || t->n_members > MM_TRUSS_MAX_MEMBERS)
        return mm_error_set(err, MM_ERANGE, "members", "a truss has 1 to %d members; got %d",
                            MM_TRUSS_MAX_MEMBERS, t->n_members);
    if (t->n_supports < 0 || t->n_supports > MM_TRUSS_MAX_SUPPORTS)
        return mm_error_set(err, MM_ERANGE, "supports", "at most %d supports; got %d",
                            MM_TRUSS_MAX_SUPPORTS, t->n_supports);
    if (t->n_loads < 0 || t->n_loads > MM_TRUSS_MAX_LOADS)
        return mm_error_set(err, MM_ERANGE, "loads", "at most %d loads; got %d", MM_TRUSS_MAX_LOADS,
                            t->n_loads);
    for (int i = 0; i < 2 * t->n_nodes; i++)
        if (!isfinite(t->xy[i]))
            return mm_error_set(err, MM_EVALUE, "nodes", "joint %d has a coordinate that is not a number",
                                i / 2 + 1);
    double tiny = 1e-9 * extent(t);
    for (int e = 0; e < t->n_members; e++) {
        int a = t->ends[2 * e], b = t->ends[2 * e + 1];
        if (a < 0 || a >= t->n_nodes || b < 0 || b >= t->n_nodes)
            return mm_error_set(err, MM_ERANGE, "members",
                                "member %d joins joint %d to joint %d, but the joints are numbered 1 to %d",
                                e + 1, a + 1, b + 1, t->n_nodes);
        if (a == b)
            return mm_error_set(err, MM_ERANGE, "members", "member %d joins joint %d to itself", e + 1,
                                a + 1);
        double L = hypot(t->xy[2 * b] - t->xy[2 * a], t->xy[2 * b + 1] - t->xy[2 * a + 1]);
        if (!(L > tiny))
            return mm_error_set(err, MM_ERANGE, "members",
                                "member %d joins joints %d and %d, which are at the same point", e + 1,
                                a + 1, b + 1);
    }
    for (int s = 0; s < t->n_supports; s++) {
        const int *r = t->supports + 3 * s;
        if (r[0] < 0 || r[0] >= t->n_nodes)
            return mm_error_set(err, MM_ERANGE, "supports",
                                "support %d is at joint %d, but the joints are numbered 1 to %d", s + 1,
                                r[0] + 1, t->n_nodes);
        if ((r[1] != 0 && r[1] != 1) || (r[2] != 0 && r[2] != 1))
            return mm_error_set(err, MM_ERANGE, "supports",
                                "support %d: fix_x and fix_y are 1 (fixed) or 0 (free); got %d, %d", s + 1,
                                r[1], r[2]);
        if (r[1] == 0 && r[2] == 0)
            return mm_error_set(err, MM_ERANGE, "supports",
                                "support %d at joint %d fixes neither x nor y; leave it out", s + 1, r[0] + 1);
        for (int q = 0; q < s; q++)
            if (t->supports[3 * q] == r[0])
                return mm_error_set(err, MM_ERANGE, "supports",
                                    "joint %d has two supports (rows %d and %d); give one row with both fixes",
                                    r[0] + 1, q + 1, s + 1);
    }
    for (int l = 0; l < t->n_loads; l++) {
        if (t->load_node[l] < 0 || t->load_node[l] >= t->n_nodes)
            return mm_error_set(err, MM_ERANGE, "loads",
                                "load %d is at joint %d, but the joints are numbered 1 to %d", l + 1,
                                t->load_node[l] + 1, t->n_nodes);
        if (!isfinite(t->load_f[2 * l]) || !isfinite(t->load_f[2 * l + 1]))
            return mm_error_set(err, MM_EVALUE, "loads", "load %d is not a number", l + 1);
    }
    return MM_OK;
}

/* ==== the joint equations ========================================================= */

/* Joint order along the longer side of the truss (then the other), so that
 * neighbouring joints get neighbouring equations. */
typedef struct key {
    double a, b;
    int i;
} key;

static int cmp_key(const void *p, const void *q)
{
    const key *x = p, *y = q;
    if (x->a != y->a)
        return x->a < y->a ? -1 : 1;
    if (x->b != y->b)
        return x->b < y->b ? -1 : 1;
    return x->i - y->i;
}

static int order_joints(const mm_truss *t, int *pos)
{
    int n = t->n_nodes;
    key *k = malloc((size_t)n * sizeof *k);
    if (!k)
        return MM_ENOMEM;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < n; i++)
        for (int d = 0; d < 2; d++) {
            lo[d] = fmin(lo[d], t->xy[2 * i + d]);
            hi[d] = fmax(hi[d], t->xy[2 * i + d]);
        }
    int major = hi[1] - lo[1] > hi[0] - lo[0];
    for (int i = 0; i < n; i++)
        k[i] = (key){t->xy[2 * i + major], t->xy[2 * i + !major], i};
    qsort(k, (size_t)n, sizeof *k, cmp_key);
    for (int r = 0; r < n; r++)
        pos[k[r].i] = r;
    free(k);
    return MM_OK;
}

/* ==== the diagnosis in words ======================================================== */

static const char *direction_words(double ang, char *buf, size_t size)
{
    double deg = ang * 180 / M_PI;               /* in (-90, 90] */
    if (fabs(deg) < 1)
        return "sideways (along x)";
    if (fabs(fabs(deg) - 90) < 1)
        return "up and down (along y)";
    snprintf(buf, size, "along a line at %.0f deg to x", deg);
    return buf;
}

/* The line angle of (ux, uy) in (-pi/2, pi/2]. */
static double line_angle(double ux, double uy)
{
    double a = atan2(uy, ux);
    if (a > M_PI / 2)
        a -= M_PI;
    if (a <= -M_PI / 2)
        a += M_PI;
    return a;
}

static void mechanism_words(const mm_truss *t, const double *u, mm_truss_result *res)
{
    int n = t->n_nodes;
    double cx = 0, cy = 0;
    for (int i = 0; i < n; i++)
        cx += t->xy[2 * i], cy += t->xy[2 * i + 1];
    cx /= n, cy /= n;
    double a = 0, b = 0, num = 0, den = 0, uu = 0, rmax = 0;
    for (int i = 0; i < n; i++) {
        double dx = t->xy[2 * i] - cx, dy = t->xy[2 * i + 1] - cy;
        a += u[2 * i], b += u[2 * i + 1];
        num += dx * u[2 * i + 1] - dy * u[2 * i];
        den += dx * dx + dy * dy;
        uu += u[2 * i] * u[2 * i] + u[2 * i + 1] * u[2 * i + 1];
        rmax = fmax(rmax, hypot(dx, dy));
    }
    a /= n, b /= n;
    double w = den > 0 ? num / den : 0, miss = 0;
    for (int i = 0; i < n; i++) {
        double dx = t->xy[2 * i] - cx, dy = t->xy[2 * i + 1] - cy;
        miss += pow(u[2 * i] - (a - w * dy), 2) + pow(u[2 * i + 1] - (b + w * dx), 2);
    }
    res->rigid = miss <= 1e-12 * uu;
    res->rigid_turns = res->rigid && fabs(w) * rmax > 1e-6 * hypot(a, b);
    if (res->rigid_turns) {
        res->pivot[0] = cx - b / w;
        res->pivot[1] = cy + a / w;
    }
    int k = 0;
    for (int i = 1; i < n; i++)
        if (hypot(u[2 * i], u[2 * i + 1]) > hypot(u[2 * k], u[2 * k + 1]) * (1 + 1e-9))
            k = i;
    res->free_joint = k;
    res->free_dir = res->rigid && !res->rigid_turns ? line_angle(a, b) : line_angle(u[2 * k], u[2 * k + 1]);
}

static void self_stress_words(const mm_truss *t, const double *s, const int *rnode,
                              mm_truss_result *res)
{
    int m = t->n_members, r = res->n_reactions, k = 0, count = 0;
    for (int q = 0; q < m + r; q++) {
        if (fabs(s[q]) > 1e-9)
            count++;
        if (fabs(s[q]) > fabs(s[k]) * (1 + 1e-9))
            k = q;
    }
    res->redundant_count = count;
    if (k < m)
        res->redundant_member = k;
    else
        res->redundant_support = rnode[k - m];
}

static int members_at(const mm_truss *t, int joint)
{
    int c = 0;
    for (int e = 0; e < t->n_members; e++)
        c += (t->ends[2 * e] == joint) + (t->ends[2 * e + 1] == joint);
    return c;
}

/* err->msg: what is wrong, in the words of a statics course (param "members"). */
static int describe(const mm_truss *t, const mm_truss_result *res, mm_error *err)
{
    char dir[48], what[200] = "", extra[200] = "";
    int d = res->determinacy;
    int mech = res->free_joint >= 0, red = res->redundant_member >= 0 || res->redundant_support >= 0;
    if (mech) {
        int j = res->free_joint;
        if (res->rigid && res->rigid_turns) {
            int at = -1;
            double ext = extent(t);
            for (int i = 0; i < t->n_nodes; i++)
                if (hypot(t->xy[2 * i] - res->pivot[0], t->xy[2 * i + 1] - res->pivot[1]) < 1e-6 * ext)
                    at = i;
            if (at >= 0)
                snprintf(what, sizeof what, "the supports let the whole truss turn about joint %d", at + 1);
            else
                snprintf(what, sizeof what, "the supports let the whole truss turn about (%.3g, %.3g)",
                         res->pivot[0], res->pivot[1]);
        } else if (res->rigid) {
            snprintf(what, sizeof what, "the supports let the whole truss slide %s",
                     direction_words(res->free_dir, dir, sizeof dir));
        } else {
            int c = members_at(t, j);
            if (c == 0)
                snprintf(what, sizeof what, "joint %d is joined to no member, so nothing holds it", j + 1);
            else
                snprintf(what, sizeof what, "joint %d%s can move %s without stretching any member", j + 1,
                         c == 1 ? " (one member only)" : "", direction_words(res->free_dir, dir, sizeof dir));
        }
    }
    if (red) {
        if (res->redundant_member >= 0) {
            int e = res->redundant_member;
            snprintf(extra, sizeof extra,
                     "member %d (joints %d-%d) is redundant: it and %d other forces can be nonzero with no "
                     "load (a self-stress)",
                     e + 1, t->ends[2 * e] + 1, t->ends[2 * e + 1] + 1, res->redundant_count - 1);
        } else {
            snprintf(extra, sizeof extra, "the support at joint %d is redundant", res->redundant_support + 1);
        }
    }
    if (d < 0)
        return mm_error_set(err, MM_ESINGULAR, "members",
                            "a mechanism: m + r - 2j = %d; %s; add a member or a support", d,
                            mech ? what : "it cannot carry every load");
    if (d > 0)
        return mm_error_set(err, MM_ESINGULAR, "members",
                            "statically indeterminate: m + r - 2j = %d; %s%s%s", d,
                            red ? extra : "equilibrium alone cannot share the load",
                            mech ? "; also " : "", mech ? what : "");
    return mm_error_set(err, MM_ESINGULAR, "members",
                        "a mechanism although m + r - 2j = 0: %s; and %s (a critical form)",
                        mech ? what : "the equations are dependent",
                        red ? extra : "a member is redundant");
}

/* ==== the solve ========================================================================= */

int mm_truss_solve(const mm_truss *t, mm_truss_result *res, mm_error *err)
{
    int rc = mm_truss_check(t, err);
    if (rc != MM_OK)
        return rc;
    int n = t->n_nodes, m = t->n_members, r = 0;
    for (int s = 0; s < t->n_supports; s++)
        r += t->supports[3 * s + 1] + t->supports[3 * s + 2];
    res->n_reactions = r;
    res->determinacy = m + r - 2 * n;
    res->free_joint = res->redundant_member = res->redundant_support = -1;
    res->rigid = res->rigid_turns = 0;
    res->redundant_count = 0;
    memset(&res->eq, 0, sizeof res->eq);

    int neq = 2 * n, nunk = m + r, nnz = 4 * m + r, q = 0;
    int *ri = malloc((size_t)nnz * sizeof *ri), *ci = malloc((size_t)nnz * sizeof *ci);
    double *va = malloc((size_t)nnz * sizeof *va);
    double *b = calloc((size_t)neq, sizeof *b), *x = calloc((size_t)nunk, sizeof *x);
    double *mech = calloc((size_t)neq, sizeof *mech), *self = calloc((size_t)nunk, sizeof *self);
    double *u = calloc((size_t)neq, sizeof *u);
    int *pos = malloc((size_t)n * sizeof *pos), *rnode = malloc((size_t)(r ? r : 1) * sizeof *rnode);
    if (!ri || !ci || !va || !b || !x || !mech || !self || !u || !pos || !rnode) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
        goto out;
    }
    if ((rc = order_joints(t, pos)) != MM_OK) {
        mm_error_set(err, rc, "", "out of memory");
        goto out;
    }
#define PUT(row, col, val) (ri[q] = (row), ci[q] = (col), va[q] = (val), q++)
    /* eq. (1): member e pulls joint a toward c with F_e u_ac when in tension */
    for (int e = 0; e < m; e++) {
        int a = t->ends[2 * e], c = t->ends[2 * e + 1];
        double dx = t->xy[2 * c] - t->xy[2 * a], dy = t->xy[2 * c + 1] - t->xy[2 * a + 1];
        double L = hypot(dx, dy), ux = dx / L, uy = dy / L;
        PUT(2 * pos[a], e, ux);
        PUT(2 * pos[a] + 1, e, uy);
        PUT(2 * pos[c], e, -ux);
        PUT(2 * pos[c] + 1, e, -uy);
    }
    int k = m;
    for (int s = 0; s < t->n_supports; s++)
        for (int d = 0; d < 2; d++)
            if (t->supports[3 * s + 1 + d]) {
                PUT(2 * pos[t->supports[3 * s]] + d, k, 1.0);
                rnode[k - m] = t->supports[3 * s];
                k++;
            }
#undef PUT
    for (int l = 0; l < t->n_loads; l++)
        for (int d = 0; d < 2; d++)
            b[2 * pos[t->load_node[l]] + d] -= t->load_f[2 * l + d];

    mm_error eerr;
    rc = mm_equil_solve_sparse(neq, nunk, q, ri, ci, va, b, x, mech, self, &res->eq, &eerr);
    if (rc == MM_OK) {
        memcpy(res->force, x, (size_t)m * sizeof *x);
        memset(res->reaction, 0, (size_t)neq * sizeof *res->reaction);
        k = m;
        for (int s = 0; s < t->n_supports; s++)
            for (int d = 0; d < 2; d++)
                if (t->supports[3 * s + 1 + d])
                    res->reaction[2 * t->supports[3 * s] + d] = x[k++];
    } else if (rc == MM_ESINGULAR) {
        if (res->eq.n_mech > 0) {
            for (int i = 0; i < n; i++)
                u[2 * i] = mech[2 * pos[i]], u[2 * i + 1] = mech[2 * pos[i] + 1];
            mechanism_words(t, u, res);
        }
        if (res->eq.n_self > 0)
            self_stress_words(t, self, rnode, res);
        rc = describe(t, res, err);
    } else {
        *err = eerr;
        if (rc == MM_ENONFINITE)
            mm_error_set(err, rc, "members",
                         "the member forces overflow: the truss is too close to a mechanism");
    }
out:
    free(ri), free(ci), free(va), free(b), free(x), free(mech), free(self), free(u), free(pos), free(rnode);
    return rc;
}

/* ==== second routes: the whole truss, sections ======================================== */

/* The meeting point of the lines p1 + s u1 and p2 + t u2, or 0 when they are
 * (nearly) parallel. */
static int meet(const double *p1, const double *u1, const double *p2, const double *u2, double *P)
{
    double den = u1[0] * u2[1] - u1[1] * u2[0];
    if (fabs(den) < 1e-9)
        return 0;
    double s = ((p2[0] - p1[0]) * u2[1] - (p2[1] - p1[1]) * u2[0]) / den;
    P[0] = p1[0] + s * u1[0];
    P[1] = p1[1] + s * u1[1];
    return 1;
}

/* Three unknown forces along lines (p_k, u_k) in equilibrium with a known
 * force (Fx, Fy) whose moment about a point P is mom(P): Ritter's
 * solution, each by moments about the meeting point of the other two (by
 * forces across them when they are parallel).  ext[] holds the known
 * forces: npts points with forces.  Returns the number found; F[k] and
 * scale[k] (the size of the terms over the lever arm, for round-off) for
 * ok[k] = 1. */
static int ritter(const double p[3][2], const double u[3][2], int npts, const double *pts,
                  const double *frc, double ext_len, double *F, double *scale, int *ok)
{
    int found = 0;
    double Fx = 0, Fy = 0, Fs = 0;
    for (int q = 0; q < npts; q++) {
        Fx += frc[2 * q], Fy += frc[2 * q + 1];
        Fs += fabs(frc[2 * q]) + fabs(frc[2 * q + 1]);
    }
    for (int k = 0; k < 3; k++) {
        int a = (k + 1) % 3, c = (k + 2) % 3;
        double P[2];
        ok[k] = 0;
        if (meet(p[a], u[a], p[c], u[c], P)) {
            double arm = (p[k][0] - P[0]) * u[k][1] - (p[k][1] - P[1]) * u[k][0];
            if (fabs(arm) < 1e-3 * ext_len)
                continue;
            double M = 0, Ms = 0;
            for (int q = 0; q < npts; q++) {
                double mq = (pts[2 * q] - P[0]) * frc[2 * q + 1] - (pts[2 * q + 1] - P[1]) * frc[2 * q];
                M += mq;
                Ms += fabs(mq);
            }
            F[k] = -M / arm;
            scale[k] = Ms / fabs(arm);
        } else {
            double nx = -u[a][1], ny = u[a][0], den = u[k][0] * nx + u[k][1] * ny;
            if (fabs(den) < 1e-3)
                continue;
            F[k] = -(Fx * nx + Fy * ny) / den;
            scale[k] = Fs / fabs(den);
        }
        ok[k] = 1;
        found++;
    }
    return found;
}

int mm_truss_reactions_rigid(const mm_truss *t, double *reaction)
{
    double p[3][2], u[3][2];
    int node[3], dir[3], r = 0;
    for (int s = 0; s < t->n_supports; s++)
        for (int d = 0; d < 2; d++)
            if (t->supports[3 * s + 1 + d]) {
                if (r == 3)
                    return 0;
                node[r] = t->supports[3 * s], dir[r] = d;
                p[r][0] = t->xy[2 * node[r]], p[r][1] = t->xy[2 * node[r] + 1];
                u[r][0] = d == 0, u[r][1] = d == 1;
                r++;
            }
    if (r != 3 || t->n_loads > MM_TRUSS_MAX_LOADS)
        return 0;
    double pts[2 * MM_TRUSS_MAX_LOADS], frc[2 * MM_TRUSS_MAX_LOADS], F[3], scale[3];
    int ok[3];
    for (int l = 0; l < t->n_loads; l++) {
        pts[2 * l] = t->xy[2 * t->load_node[l]], pts[2 * l + 1] = t->xy[2 * t->load_node[l] + 1];
        frc[2 * l] = t->load_f[2 * l], frc[2 * l + 1] = t->load_f[2 * l + 1];
    }
    if (ritter((const double(*)[2])p, (const double(*)[2])u, t->n_loads, pts, frc, extent(t), F, scale,
               ok) != 3)
        return 0;
    memset(reaction, 0, 2 * (size_t)t->n_nodes * sizeof *reaction);
    for (int k = 0; k < 3; k++)
        reaction[2 * node[k] + dir[k]] = F[k];
    return 1;
}

static int cmp_double(const void *p, const void *q)
{
    double a = *(const double *)p, b = *(const double *)q;
    return (a > b) - (a < b);
}

int mm_truss_sections(const mm_truss *t, const double *reaction, double *sec_force, int *sec_count,
                      double *sec_scale)
{
    int n = t->n_nodes, m = t->n_members, cuts = 0;
    double c[MM_TRUSS_MAX_NODES];
    double pts[2 * (MM_TRUSS_MAX_NODES + MM_TRUSS_MAX_LOADS)], frc[2 * (MM_TRUSS_MAX_NODES + MM_TRUSS_MAX_LOADS)];
    double ext = extent(t);
    memset(sec_count, 0, (size_t)m * sizeof *sec_count);
    memset(sec_force, 0, (size_t)m * sizeof *sec_force);
    if (sec_scale)
        memset(sec_scale, 0, (size_t)m * sizeof *sec_scale);
    for (int dir = 0; dir < 2; dir++) {
        for (int i = 0; i < n; i++)
            c[i] = t->xy[2 * i + dir];
        qsort(c, (size_t)n, sizeof *c, cmp_double);
        for (int g = 0; g + 1 < n; g++) {
            if (!(c[g + 1] - c[g] > 1e-9 * ext))
                continue;
            double cut = 0.5 * (c[g] + c[g + 1]);
            int cross[3], nc = 0;
            for (int e = 0; e < m && nc <= 3; e++) {
                double a = t->xy[2 * t->ends[2 * e] + dir], b = t->xy[2 * t->ends[2 * e + 1] + dir];
                if ((a < cut) != (b < cut)) {
                    if (nc < 3)
                        cross[nc] = e;
                    nc++;
                }
            }
            if (nc != 3)
                continue;
            /* the part below the cut: its joints' loads and reactions */
            int np = 0;
            for (int i = 0; i < n; i++)
                if (t->xy[2 * i + dir] < cut && (reaction[2 * i] != 0 || reaction[2 * i + 1] != 0)) {
                    pts[2 * np] = t->xy[2 * i], pts[2 * np + 1] = t->xy[2 * i + 1];
                    frc[2 * np] = reaction[2 * i], frc[2 * np + 1] = reaction[2 * i + 1];
                    np++;
                }
            for (int l = 0; l < t->n_loads; l++) {
                int i = t->load_node[l];
                if (t->xy[2 * i + dir] < cut) {
                    pts[2 * np] = t->xy[2 * i], pts[2 * np + 1] = t->xy[2 * i + 1];
                    frc[2 * np] = t->load_f[2 * l], frc[2 * np + 1] = t->load_f[2 * l + 1];
                    np++;
                }
            }
            /* each cut member pulls the part toward its far joint when in tension */
            double p[3][2], u[3][2], F[3], scale[3];
            int ok[3];
            for (int k = 0; k < 3; k++) {
                int e = cross[k], a = t->ends[2 * e], b = t->ends[2 * e + 1];
                if (t->xy[2 * a + dir] >= cut) {
                    int s = a;
                    a = b, b = s;
                }
                double dx = t->xy[2 * b] - t->xy[2 * a], dy = t->xy[2 * b + 1] - t->xy[2 * a + 1];
                double L = hypot(dx, dy);
                p[k][0] = t->xy[2 * a], p[k][1] = t->xy[2 * a + 1];
                u[k][0] = dx / L, u[k][1] = dy / L;
            }
            if (ritter((const double(*)[2])p, (const double(*)[2])u, np, pts, frc, ext, F, scale, ok) == 0)
                continue;
            cuts++;
            for (int k = 0; k < 3; k++)
                if (ok[k]) {
                    if (sec_count[cross[k]] == 0) {
                        sec_force[cross[k]] = F[k];
                        if (sec_scale)
                            sec_scale[cross[k]] = scale[k];
                    }
                    sec_count[cross[k]]++;
                }
        }
    }
    return cuts;
}

void mm_truss_spread(const mm_truss *t, double *spread)
{
    for (int j = 0; j < t->n_nodes; j++) {
        double ang[MM_TRUSS_MAX_MEMBERS + 2];
        int k = 0;
        for (int e = 0; e < t->n_members; e++) {
            int a = t->ends[2 * e], b = t->ends[2 * e + 1];
            if (a != j && b != j)
                continue;
            ang[k++] = line_angle(t->xy[2 * b] - t->xy[2 * a], t->xy[2 * b + 1] - t->xy[2 * a + 1]);
        }
        for (int s = 0; s < t->n_supports; s++)
            if (t->supports[3 * s] == j) {
                if (t->supports[3 * s + 1])
                    ang[k++] = 0;
                if (t->supports[3 * s + 2])
                    ang[k++] = M_PI / 2;
            }
        double worst = 0;
        for (int p = 0; p < k; p++)
            for (int q = p + 1; q < k; q++) {
                double d = fabs(ang[p] - ang[q]);
                worst = fmax(worst, fmin(d, M_PI - d));
            }
        spread[j] = worst;
    }
}

/* ---- statics (chapter 3): the equilibrium put back, for the checks ------------- */

void mm_truss_joint_residual(const mm_truss *t, const double *F, const double *R, double *worst, double *scale,
                             double *total)
{
    double sx[MM_TRUSS_MAX_NODES] = {0}, sy[MM_TRUSS_MAX_NODES] = {0}, ab[MM_TRUSS_MAX_NODES] = {0};
    for (int e = 0; e < t->n_members; e++) {
        int a = t->ends[2 * e], b = t->ends[2 * e + 1];
        double dx = t->xy[2 * b] - t->xy[2 * a], dy = t->xy[2 * b + 1] - t->xy[2 * a + 1], L = hypot(dx, dy);
        double fx = F[e] * dx / L, fy = F[e] * dy / L;
        sx[a] += fx, sy[a] += fy, sx[b] -= fx, sy[b] -= fy;
        ab[a] += fabs(F[e]), ab[b] += fabs(F[e]);
    }
    for (int l = 0; l < t->n_loads; l++) {
        int j = t->load_node[l];
        sx[j] += t->load_f[2 * l], sy[j] += t->load_f[2 * l + 1];
        ab[j] += fabs(t->load_f[2 * l]) + fabs(t->load_f[2 * l + 1]);
    }
    *worst = *scale = *total = 0;
    for (int j = 0; j < t->n_nodes; j++) {
        sx[j] += R[2 * j], sy[j] += R[2 * j + 1];
        ab[j] += fabs(R[2 * j]) + fabs(R[2 * j + 1]);
        *worst = fmax(*worst, hypot(sx[j], sy[j]));
        *scale = fmax(*scale, ab[j]);
        *total += ab[j];
    }
}

void mm_truss_body_residual(const mm_truss *t, const double *R, double *worst, double *scale)
{
    double fx = 0, fy = 0, mz = 0, sf = 0, sm = 0, x0 = t->xy[0], y0 = t->xy[1];
    for (int k = 0; k < t->n_loads + t->n_nodes; k++) {
        int j = k < t->n_loads ? t->load_node[k] : k - t->n_loads;
        double px = k < t->n_loads ? t->load_f[2 * k] : R[2 * j];
        double py = k < t->n_loads ? t->load_f[2 * k + 1] : R[2 * j + 1];
        double m = (t->xy[2 * j] - x0) * py - (t->xy[2 * j + 1] - y0) * px;
        fx += px, fy += py, mz += m;
        sf += fabs(px) + fabs(py), sm += fabs(m);
    }
    double arm = 1;
    for (int j = 0; j < t->n_nodes; j++)
        arm = fmax(arm, hypot(t->xy[2 * j] - x0, t->xy[2 * j + 1] - y0));
    *worst = fmax(hypot(fx, fy), fabs(mz) / arm);
    *scale = fmax(sf, sm / arm);
}
