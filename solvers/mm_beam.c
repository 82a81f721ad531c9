/* mm_beam.c — beams as piecewise polynomials.  The contract is in
 * mm_beam.h; equation numbers refer to exercises/sta/beam_diagrams.md. */
#include "mm_beam.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mm_dd.h"

struct mm_beam {
    double L, EI, a, b;
    mm_beam_kind kind;
    int nb;                    /* breakpoints; nb - 1 segments */
    double *xs;
    double *dV, *dM;           /* jumps at each breakpoint */
    double *q0, *q1;           /* per segment: q = q0 + q1 s */
    double *V0, *M0, *T0, *Y0; /* per segment: values just right of its start */
    int nr;
    double rx[2], ry[2], rc[2];
    double Vend, Mend, Vscale, Mscale;
    double Tend, Yend;
};

/* ==== checks ======================================================================= */

static int on_beam(double x, double L)
{
    return x >= 0 && x <= L;
}

int mm_beam_check(const mm_beam_problem *p, mm_error *err)
{
    if (!(p->L > 0) || !isfinite(p->L))
        return mm_error_set(err, MM_ERANGE, "L", "L must be a positive length; got %g", p->L);
    if (p->kind == MM_BEAM_TWO_SUPPORTS) {
        if (!on_beam(p->a, p->L))
            return mm_error_set(err, MM_ERANGE, "a", "the pin at a = %g m must be on the beam (0 to L = %g m)",
                                p->a, p->L);
        if (!on_beam(p->b, p->L))
            return mm_error_set(err, MM_ERANGE, "b",
                                "the roller at b = %g m must be on the beam (0 to L = %g m)", p->b, p->L);
        if (!(p->b > p->a))
            return mm_error_set(err, MM_ERANGE, "b",
                                "the roller at b = %g m must lie right of the pin at a = %g m", p->b, p->a);
    }
    if (p->n_point < 0 || p->n_point > MM_BEAM_MAX_LOADS || p->n_dist < 0 || p->n_dist > MM_BEAM_MAX_LOADS ||
        p->n_moment < 0 || p->n_moment > MM_BEAM_MAX_LOADS)
        return mm_error_set(err, MM_ERANGE, p->n_point > MM_BEAM_MAX_LOADS ? "point_loads"
                                            : p->n_dist > MM_BEAM_MAX_LOADS ? "distributed"
                                                                            : "moments",
                            "at most %d loads of each kind", MM_BEAM_MAX_LOADS);
    for (int i = 0; i < p->n_point; i++) {
        const double *r = p->point + 2 * i;
        if (!isfinite(r[0]) || !isfinite(r[1]))
            return mm_error_set(err, MM_EVALUE, "point_loads", "point load %d is not a number", i + 1);
        if (!on_beam(r[0], p->L))
            return mm_error_set(err, MM_ERANGE, "point_loads",
                                "point load %d at x = %g m is off the beam (0 to %g m)", i + 1, r[0], p->L);
    }
    for (int i = 0; i < p->n_dist; i++) {
        const double *r = p->dist + 4 * i;
        for (int k = 0; k < 4; k++)
            if (!isfinite(r[k]))
                return mm_error_set(err, MM_EVALUE, "distributed", "distributed load %d is not a number", i + 1);
        if (!on_beam(r[0], p->L) || !on_beam(r[1], p->L) || !(r[1] > r[0]))
            return mm_error_set(err, MM_ERANGE, "distributed",
                                "distributed load %d must run from x1 to x2 > x1 on the beam (0 to %g m); "
                                "got %g to %g m", i + 1, p->L, r[0], r[1]);
    }
    for (int i = 0; i < p->n_moment; i++) {
        const double *r = p->moment + 2 * i;
        if (!isfinite(r[0]) || !isfinite(r[1]))
            return mm_error_set(err, MM_EVALUE, "moments", "couple %d is not a number", i + 1);
        if (!on_beam(r[0], p->L))
            return mm_error_set(err, MM_ERANGE, "moments", "couple %d at x = %g m is off the beam (0 to %g m)",
                                i + 1, r[0], p->L);
    }
    if (!(p->EI >= 0) || !isfinite(p->EI))
        return mm_error_set(err, MM_ERANGE, "EI", "EI must be >= 0; got %g", p->EI);
    return MM_OK;
}

/* ==== building ====================================================================== */

static int cmp_double(const void *p, const void *q)
{
    double a = *(const double *)p, b = *(const double *)q;
    return (a > b) - (a < b);
}

/* the breakpoint at x exactly (x is one of them) */
static int break_at(const mm_beam *b, double x)
{
    int lo = 0, hi = b->nb - 1;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (b->xs[mid] < x)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* ---- the loads' sums, exactly ---------------------------------------------------
 * A reaction is a sum of the loads' forces or moments (over b - a), and
 * those terms may cancel to a small part of themselves (a clamp couple of
 * 1.23 N m from moments of 1.5e6 N m): summed in double, each term's
 * rounding, 1e-16 of 1.5e6, was 5e-11 of the result, printed as exact.  So
 * the sums are kept exactly, as a sum of doubles that do not overlap
 * (Shewchuk's partials, the algorithm of Python's math.fsum), every term
 * split exactly into doubles first (a product by fma, a sum by TwoSum):
 * only the last division rounds.  Exact unless a product falls below
 * 1e-292 (it then loses bits to underflow, 1e-323 absolute each) or the
 * partials pass XS_MAX (see xs_add). */
enum { XS_MAX = 128 };
typedef struct xsum {
    int n;
    double p[XS_MAX];                  /* ascending magnitude, non-overlapping; their sum is exact */
} xsum;

/* s += x exactly.  The parts share no bit, so each takes one bit of the
 * exponent range at least: full (inputs spread over 2^128 in size, never
 * these loads), the two smallest are merged, rounding by less than 2^-170
 * of the largest part. */
static void xs_add(xsum *s, double x)
{
    if (s->n == XS_MAX) {
        s->p[1] += s->p[0];
        memmove(s->p, s->p + 1, (XS_MAX - 1) * sizeof *s->p);
        s->n--;
    }
    int j = 0;
    for (int i = 0; i < s->n; i++) {
        double y = s->p[i];
        if (fabs(x) < fabs(y)) {
            double t = x;
            x = y, y = t;
        }
        mm_dd t = mm_dd_fast(x, y);             /* x + y = hi + lo exactly (|x| >= |y|) */
        if (t.lo != 0)
            s->p[j++] = t.lo;
        x = t.hi;
    }
    s->p[j++] = x;
    s->n = j;
}

/* s += a b c exactly: a and b sums of doubles, c a double; each product of
 * two doubles is hi + lo exactly (mm_dd_two_prod), so a b c is 4 n_a n_b doubles */
static void xs_add_prod(xsum *s, const xsum *a, const xsum *b, double c)
{
    for (int i = 0; i < a->n; i++)
        for (int j = 0; j < b->n; j++) {
            mm_dd ab = mm_dd_two_prod(a->p[i], b->p[j]);
            mm_dd pc = mm_dd_two_prod(ab.hi, c), ec = mm_dd_two_prod(ab.lo, c);
            xs_add(s, pc.hi);
            xs_add(s, pc.lo);
            xs_add(s, ec.hi);
            xs_add(s, ec.lo);
        }
}

/* the exact sum of up to three doubles */
static xsum xs_of(int n, double x0, double x1, double x2)
{
    xsum s = {0};
    const double x[3] = {x0, x1, x2};
    for (int i = 0; i < n; i++)
        xs_add(&s, x[i]);
    return s;
}

/* the sum as double-double, within u^2 of it (u = 2^-53): the partials
 * compressed (Shewchuk's Compress: two sweeps of TwoSum, top down then
 * bottom up) so that the rest lies within half an ulp of the largest, then
 * the two largest.  (The partials as they stand need not: 1 - 0.11..1 in
 * binary is a tiny sum of two large parts.) */
static mm_dd xs_dd(const xsum *s)
{
    if (s->n == 0)
        return mm_dd_from(0);
    double g[XS_MAX], Q = s->p[s->n - 1];
    int bottom = s->n - 1;
    for (int i = s->n - 2; i >= 0; i--) {
        mm_dd t = mm_dd_two_sum(Q, s->p[i]);
        if (t.lo != 0)
            g[bottom--] = t.hi, Q = t.lo;
        else
            Q = t.hi;
    }
    g[bottom] = Q;
    double top = 0, next = 0;
    for (int i = bottom + 1; i < s->n; i++) {
        mm_dd t = mm_dd_two_sum(g[i], Q);
        if (t.lo != 0)
            next = t.lo;
        Q = t.hi;
    }
    top = Q;
    return (mm_dd){top, next};
}

/* The loads' resultant *F and six times their moment about o, *M6 (sum of
 * F (x - o), of the integrals of q (x - o), and of the couples), exactly.
 * A linear load from q1 at x1 to q2 at x2 (l = x2 - x1): resultant
 * l (q1 + q2) / 2 and moment l [q1 (2 x1 + x2 - 3 o) + q2 (x1 + 2 x2 - 3 o)] / 6
 * (eq. 3's integral; six times it has no division). */
static void load_sums(const mm_beam_problem *p, double o, xsum *F, xsum *M6)
{
    *F = (xsum){0}, *M6 = (xsum){0};
    const xsum one = xs_of(1, 1, 0, 0);
    for (int i = 0; i < p->n_point; i++) {
        const double *r = p->point + 2 * i;
        xs_add(F, r[1]);
        xsum arm = xs_of(2, r[0], -o, 0), f = xs_of(1, r[1], 0, 0);
        xs_add_prod(M6, &arm, &f, 6);
    }
    for (int i = 0; i < p->n_dist; i++) {
        const double *r = p->dist + 4 * i;
        xsum l = xs_of(2, r[1], -r[0], 0), q = xs_of(2, r[2], r[3], 0);
        xs_add_prod(F, &l, &q, 0.5);
        xsum a1 = xs_of(2, 2 * r[0], r[1], 0), a2 = xs_of(2, r[0], 2 * r[1], 0), o3 = xs_of(1, -o, 0, 0);
        xs_add_prod(&a1, &o3, &one, 3);
        xs_add_prod(&a2, &o3, &one, 3);
        xs_add_prod(M6, &l, &a1, r[2]);
        xs_add_prod(M6, &l, &a2, r[3]);
    }
    for (int i = 0; i < p->n_moment; i++) {
        xsum c = xs_of(1, p->moment[2 * i + 1], 0, 0);
        xs_add_prod(M6, &c, &one, 6);
    }
}

int mm_beam_solve(const mm_beam_problem *p, mm_beam **out, mm_error *err)
{
    *out = NULL;
    int rc = mm_beam_check(p, err);
    if (rc != MM_OK)
        return rc;
    int cap = 4 + p->n_point + 2 * p->n_dist + p->n_moment;
    mm_beam *b = calloc(1, sizeof *b);
    double *mem = calloc((size_t)cap * 15, sizeof *mem);
    if (!b || !mem) {
        free(b);
        free(mem);
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    }
    b->xs = mem;
    b->dV = mem + cap, b->dM = mem + 2 * cap;
    b->q0 = mem + 3 * cap, b->q1 = mem + 4 * cap;
    b->V0 = mem + 5 * cap, b->M0 = mem + 6 * cap, b->T0 = mem + 7 * cap, b->Y0 = mem + 8 * cap;
    double *Yp = mem + 9 * cap, *eV = mem + 10 * cap, *eM = mem + 11 * cap, *eq = mem + 12 * cap;
    double *sVf = mem + 13 * cap, *sMf = mem + 14 * cap;   /* the sweep from 0's scales per segment */
    b->L = p->L, b->EI = p->EI, b->a = p->a, b->b = p->b, b->kind = p->kind;

    /* the breakpoints */
    int n = 0;
    b->xs[n++] = 0;
    b->xs[n++] = p->L;
    if (p->kind == MM_BEAM_TWO_SUPPORTS) {
        b->xs[n++] = p->a;
        b->xs[n++] = p->b;
    }
    for (int i = 0; i < p->n_point; i++)
        b->xs[n++] = p->point[2 * i];
    for (int i = 0; i < p->n_dist; i++) {
        b->xs[n++] = p->dist[4 * i];
        b->xs[n++] = p->dist[4 * i + 1];
    }
    for (int i = 0; i < p->n_moment; i++)
        b->xs[n++] = p->moment[2 * i];
    qsort(b->xs, (size_t)n, sizeof *b->xs, cmp_double);
    int u = 0;
    for (int i = 0; i < n; i++)
        if (u == 0 || b->xs[i] != b->xs[u - 1])
            b->xs[u++] = b->xs[i];
    b->nb = u;

    /* the reactions, eqs. (2)-(3), each from the loads' sums taken exactly
     * (load_sums) and one division: right to rounding however much the
     * loads' terms cancel in it.  Pin and roller each from the moments
     * about the other support (not one from the other by eq. 2, which
     * would add the other's rounding).  Each is within half an ulp and
     * 1e-30 of itself (the double-double division) of the exact value */
    xsum F, M6;
    if (p->kind == MM_BEAM_TWO_SUPPORTS) {
        xsum Fb, M6b, gap = xs_of(2, p->b, -p->a, 0);
        load_sums(p, p->a, &F, &M6);
        load_sums(p, p->b, &Fb, &M6b);
        mm_dd d6 = mm_dd_mul_d(xs_dd(&gap), 6);  /* 6 (b - a) */
        b->nr = 2;
        b->rx[0] = p->a, b->rx[1] = p->b;
        b->ry[0] = mm_dd_val(mm_dd_div(xs_dd(&M6b), d6));            /* moments about the roller */
        b->ry[1] = -mm_dd_val(mm_dd_div(xs_dd(&M6), d6));            /* about the pin */
        b->rc[0] = b->rc[1] = 0;
    } else {
        load_sums(p, 0, &F, &M6);
        b->nr = 1;
        b->rx[0] = 0;
        b->ry[0] = -mm_dd_val(xs_dd(&F));
        b->rc[0] = -mm_dd_val(mm_dd_div(xs_dd(&M6), mm_dd_from(6)));  /* the clamp's couple */
    }

    /* jumps and the distributed intensity of each segment; eV and eM the
     * magnitudes each jump was computed from: a load's own, a reaction's
     * own too (it is right to rounding) */
    for (int i = 0; i < p->n_point; i++) {
        int j = break_at(b, p->point[2 * i]);
        b->dV[j] += p->point[2 * i + 1];
        eV[j] += fabs(p->point[2 * i + 1]);
    }
    for (int k = 0; k < b->nr; k++) {
        int j = break_at(b, b->rx[k]);
        b->dV[j] += b->ry[k];
        b->dM[j] -= b->rc[k];
        eV[j] += fabs(b->ry[k]);
        eM[j] += fabs(b->rc[k]);
    }
    for (int i = 0; i < p->n_moment; i++) {
        int j = break_at(b, p->moment[2 * i]);
        b->dM[j] -= p->moment[2 * i + 1];
        eM[j] += fabs(p->moment[2 * i + 1]);
    }
    for (int i = 0; i < p->n_dist; i++) {
        const double *r = p->dist + 4 * i;
        double slope = (r[3] - r[2]) / (r[1] - r[0]);
        for (int k = break_at(b, r[0]); k < b->nb - 1 && b->xs[k] < r[1]; k++) {
            b->q0[k] += r[2] + slope * (b->xs[k] - r[0]);
            b->q1[k] += slope;
            eq[k] += fabs(r[2]) + fabs(slope * (b->xs[k] - r[0]));   /* what q0 is summed from */
        }
    }

    /* sweep from x = 0: V and M just right of each breakpoint (eq. 5).
     * sV and sM: the magnitudes summed into V and M so far, each jump and
     * q0 counted by what it was itself summed from (eV, eM, eq), so that
     * their rounding, and the reactions', is in it; sVf and sMf keep them
     * per segment for the choice below.  V's error is carried
     * into M over a segment as V h: M's scale takes sV h, not |V| h (a load
     * next to a support, then a long span: V is the small difference of
     * the load and the reaction, its error that of the load) */
    double V = 0, M = 0, sV = 0, sM = 0;
    for (int k = 0; k < b->nb - 1; k++) {
        V += b->dV[k];
        M += b->dM[k];
        sV += eV[k];
        sM += eM[k];
        b->V0[k] = V, b->M0[k] = M;
        sVf[k] = sV, sMf[k] = sM;
        double h = b->xs[k + 1] - b->xs[k], q0 = b->q0[k], q1 = b->q1[k];
        double dVs = q0 * h + q1 * h * h / 2, dMs = V * h + q0 * h * h / 2 + q1 * h * h * h / 6;
        sM += sV * h + eq[k] * h * h / 2 + fabs(q1 * h * h * h / 6);
        sV += eq[k] * h + fabs(q1 * h * h / 2);
        V += dVs;
        M += dMs;
    }
    b->Vend = V + b->dV[b->nb - 1];
    b->Mend = M + b->dM[b->nb - 1];
    b->Vscale = sV + eV[b->nb - 1];
    b->Mscale = sM + eM[b->nb - 1];

    /* V and M again from x = L leftwards (eq. 4 with the part right of x
     * kept), with the same scales; each segment keeps, for V and for M, the
     * value of the sweep whose scale is smaller.  A sweep carries the
     * rounding of every term it has summed, the reactions' included, into
     * values that may be far smaller: right of supports b - a apart the
     * sweep from 0 has passed two reactions of about F L / (b - a) that
     * cancel to the loads beyond b, whose rounding in V, times up to L - b
     * in M, was L / (b - a) times M's own (1e-10 of M on an 87.3 m beam on
     * supports 1e-6 L apart; one ulp apart, all of it); past the last load
     * of a cantilever whose loads balance M is 0, and was their rounding
     * bent over the free arm (y off by 34 times its printed error).  The
     * sweep from 0 still ends past L for the closure check. */
    V = M = sV = sM = 0;                         /* right of L */
    for (int k = b->nb - 2; k >= 0; k--) {
        V -= b->dV[k + 1];                       /* just left of breakpoint k + 1 */
        M -= b->dM[k + 1];
        sV += eV[k + 1];
        sM += eM[k + 1];
        double h = b->xs[k + 1] - b->xs[k], q0 = b->q0[k], q1 = b->q1[k];
        V -= h * (q0 + h * q1 / 2);              /* segment k's start, eq. (6) */
        sV += eq[k] * h + fabs(q1 * h * h / 2);
        M -= h * (V + h * (q0 / 2 + h * q1 / 6));
        sM += sV * h + eq[k] * h * h / 2 + fabs(q1 * h * h * h / 6);
        if (sV < sVf[k])
            b->V0[k] = V;
        if (sM < sMf[k])
            b->M0[k] = M;
    }

    /* the deflection: a particular solution from y = y' = 0 at the clamp
     * or at the pin, swept right to L and back left to 0, then theta0 (x -
     * a) added to meet the roller (eq. 8).  Not from x = 0 with y0 + theta0
     * x fitted to both supports: the particular solution at a and b is then
     * the whole overhang's deflection, and its rounding, divided by b - a,
     * went into theta0 and out again times the overhang: L / (b - a) times
     * the rounding (74 eps of y_max on supports 0.031 m apart at x = 30 m).
     * From the pin, y(b) is summed over [a, b] alone: theta0 is as accurate
     * as the moment there, and y carries only its own terms' rounding. */
    if (p->EI > 0) {
        double EI = p->EI, xo = p->kind == MM_BEAM_TWO_SUPPORTS ? p->a : 0, T = 0, Y = 0;
        int ko = break_at(b, xo);
        for (int k = ko; k < b->nb - 1; k++) {   /* rightwards from the start */
            double h = b->xs[k + 1] - b->xs[k], q0 = b->q0[k], q1 = b->q1[k], V0 = b->V0[k], M0 = b->M0[k];
            b->T0[k] = T, b->Y0[k] = Y, Yp[k] = Y;
            double dT = h * (M0 + h * (V0 / 2 + h * (q0 / 6 + h * q1 / 24))) / EI;
            double dY = T * h + h * h * (M0 / 2 + h * (V0 / 6 + h * (q0 / 24 + h * q1 / 120))) / EI;
            T += dT;
            Y += dY;
        }
        Yp[b->nb - 1] = Y;
        double Tr = T, Yr = Y;
        T = Y = 0;
        for (int k = ko - 1; k >= 0; k--) {      /* leftwards: segment k's start from its end */
            double h = b->xs[k + 1] - b->xs[k], q0 = b->q0[k], q1 = b->q1[k], V0 = b->V0[k], M0 = b->M0[k];
            T -= h * (M0 + h * (V0 / 2 + h * (q0 / 6 + h * q1 / 24))) / EI;
            Y -= T * h + h * h * (M0 / 2 + h * (V0 / 6 + h * (q0 / 24 + h * q1 / 120))) / EI;
            b->T0[k] = T, b->Y0[k] = Y, Yp[k] = Y;
        }
        double th0 = p->kind == MM_BEAM_TWO_SUPPORTS ? -Yp[break_at(b, p->b)] / (p->b - p->a) : 0;
        for (int k = 0; k < b->nb - 1; k++) {
            b->T0[k] += th0;
            b->Y0[k] += th0 * (b->xs[k] - xo);
        }
        b->Tend = Tr + th0;
        b->Yend = Yr + th0 * (p->L - xo);
    }
    *out = b;
    return MM_OK;
}

void mm_beam_free(mm_beam *b)
{
    if (!b)
        return;
    free(b->xs);
    free(b);
}

/* ==== reading it ======================================================================= */

int mm_beam_reactions(const mm_beam *b, double *x, double *Ry, double *C)
{
    for (int k = 0; k < b->nr; k++)
        x[k] = b->rx[k], Ry[k] = b->ry[k], C[k] = b->rc[k];
    return b->nr;
}

int mm_beam_breaks(const mm_beam *b, const double **x)
{
    *x = b->xs;
    return b->nb;
}

void mm_beam_eval_segment(const mm_beam *b, int k, double s, mm_beam_value *v)
{
    if (k < 0)
        k = 0;
    if (k > b->nb - 2)
        k = b->nb - 2;
    double q0 = b->q0[k], q1 = b->q1[k], V0 = b->V0[k], M0 = b->M0[k];
    v->q = q0 + q1 * s;
    v->V = V0 + s * (q0 + s * q1 / 2);
    v->M = M0 + s * (V0 + s * (q0 / 2 + s * q1 / 6));
    if (b->EI > 0) {
        v->theta = b->T0[k] + s * (M0 + s * (V0 / 2 + s * (q0 / 6 + s * q1 / 24))) / b->EI;
        v->y = b->Y0[k] + b->T0[k] * s + s * s * (M0 / 2 + s * (V0 / 6 + s * (q0 / 24 + s * q1 / 120))) / b->EI;
    } else {
        v->theta = v->y = 0;
    }
}

void mm_beam_eval(const mm_beam *b, double x, int side, mm_beam_value *v)
{
    if (x < 0 || (x == 0 && side < 0)) {
        mm_beam_eval_segment(b, 0, 0, v);
        v->q = v->V = v->M = 0;
        return;
    }
    if (x > b->L || (x == b->L && side >= 0)) {
        mm_beam_eval_segment(b, b->nb - 2, b->xs[b->nb - 1] - b->xs[b->nb - 2], v);
        v->q = 0, v->V = b->Vend, v->M = b->Mend;
        return;
    }
    int lo = 0, hi = b->nb - 2;                  /* the segment holding x */
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (side < 0 ? b->xs[mid] < x : b->xs[mid] <= x)
            lo = mid;
        else
            hi = mid - 1;
    }
    mm_beam_eval_segment(b, lo, x - b->xs[lo], v);
}

void mm_beam_closure(const mm_beam *b, double *V_end, double *M_end, double *V_scale, double *M_scale)
{
    *V_end = b->Vend, *M_end = b->Mend;
    *V_scale = b->Vscale, *M_scale = b->Mscale;
}

/* ==== extremes =========================================================================== */

/* Candidates in order of x; pick the first whose magnitude is within 1e-12
 * of the largest. */
typedef struct pick {
    double big, best, x;
    int pass;                  /* 0: find the largest magnitude; 1: the first near it */
    int done;
} pick;

static void consider(pick *p, double value, double x)
{
    if (p->pass == 0) {
        if (fabs(value) > p->big)
            p->big = fabs(value);
    } else if (!p->done && fabs(value) >= p->big * (1 - 1e-12)) {
        p->best = value, p->x = x, p->done = 1;
    }
}

/* roots of c + b s + a s^2 in (0, h), ascending, into r; returns the count */
static int quad_roots(double a, double bq, double c, double h, double *r)
{
    int n = 0;
    double t[2];
    if (a == 0) {
        if (bq != 0)
            t[n++] = -c / bq;
    } else {
        double disc = bq * bq - 4 * a * c;
        if (disc >= 0) {
            double w = -0.5 * (bq + copysign(sqrt(disc), bq));
            if (w != 0) {
                t[n++] = w / a;
                t[n++] = c / w;
            } else {
                t[n++] = 0;
            }
        }
    }
    int m = 0;
    for (int i = 0; i < n; i++)
        if (t[i] > 0 && t[i] < h)
            r[m++] = t[i];
    if (m == 2 && r[0] > r[1]) {
        double s = r[0];
        r[0] = r[1], r[1] = s;
    }
    return m;
}

void mm_beam_extreme_V(const mm_beam *b, double *value, double *x)
{
    pick p = {0};
    for (p.pass = 0; p.pass < 2; p.pass++)
        for (int k = 0; k < b->nb - 1; k++) {
            double h = b->xs[k + 1] - b->xs[k];
            mm_beam_value v;
            mm_beam_eval_segment(b, k, 0, &v);
            consider(&p, v.V, b->xs[k]);
            if (b->q1[k] != 0) {                 /* q = 0 inside: V stationary */
                double s = -b->q0[k] / b->q1[k];
                if (s > 0 && s < h) {
                    mm_beam_eval_segment(b, k, s, &v);
                    consider(&p, v.V, b->xs[k] + s);
                }
            }
            mm_beam_eval_segment(b, k, h, &v);
            consider(&p, v.V, b->xs[k + 1]);
        }
    *value = p.best, *x = p.x;
}

void mm_beam_extreme_M(const mm_beam *b, double *value, double *x)
{
    pick p = {0};
    for (p.pass = 0; p.pass < 2; p.pass++)
        for (int k = 0; k < b->nb - 1; k++) {
            double h = b->xs[k + 1] - b->xs[k], r[2];
            mm_beam_value v;
            mm_beam_eval_segment(b, k, 0, &v);
            consider(&p, v.M, b->xs[k]);
            int nr = quad_roots(b->q1[k] / 2, b->q0[k], b->V0[k], h, r);   /* V = 0 inside */
            for (int i = 0; i < nr; i++) {
                mm_beam_eval_segment(b, k, r[i], &v);
                consider(&p, v.M, b->xs[k] + r[i]);
            }
            mm_beam_eval_segment(b, k, h, &v);
            consider(&p, v.M, b->xs[k + 1]);
        }
    *value = p.best, *x = p.x;
}

/* a root of the slope on segment k between sa and sb (a sign change), by
 * bisection to the last bit */
static double slope_root(const mm_beam *b, int k, double sa, double sb)
{
    mm_beam_value va, vm;
    mm_beam_eval_segment(b, k, sa, &va);
    for (int it = 0; it < 200; it++) {
        double sm = 0.5 * (sa + sb);
        if (sm <= sa || sm >= sb)
            break;
        mm_beam_eval_segment(b, k, sm, &vm);
        if ((vm.theta > 0) == (va.theta > 0)) {
            sa = sm;
            va = vm;
        } else {
            sb = sm;
        }
    }
    return 0.5 * (sa + sb);
}

void mm_beam_extreme_y(const mm_beam *b, double *value, double *x)
{
    *value = *x = 0;
    if (!(b->EI > 0))
        return;
    enum { SUB = 64 };
    pick p = {0};
    for (p.pass = 0; p.pass < 2; p.pass++)
        for (int k = 0; k < b->nb - 1; k++) {
            double h = b->xs[k + 1] - b->xs[k];
            mm_beam_value v, w;
            mm_beam_eval_segment(b, k, 0, &v);
            consider(&p, v.y, b->xs[k]);
            for (int i = 1; i <= SUB; i++) {
                double s0 = h * (i - 1) / SUB, s1 = i == SUB ? h : h * i / SUB;
                mm_beam_eval_segment(b, k, s1, &w);
                if ((v.theta > 0 && w.theta < 0) || (v.theta < 0 && w.theta > 0)) {
                    double s = slope_root(b, k, s0, s1);
                    mm_beam_value e;
                    mm_beam_eval_segment(b, k, s, &e);
                    consider(&p, e.y, b->xs[k] + s);
                }
                v = w;
            }
            consider(&p, v.y, b->xs[k + 1]);
        }
    *value = p.best, *x = p.x;
}

/* ==== virtual work ========================================================================= */

int mm_beam_unit_load(const mm_beam *b, double x0, double *y, double *scale, mm_error *err)
{
    if (!(b->EI > 0))
        return mm_error_set(err, MM_EVALUE, "EI", "the deflection needs EI > 0");
    double unit[2] = {x0, 1.0};
    mm_beam_problem up = {.L = b->L, .kind = b->kind, .a = b->a, .b = b->b, .n_point = 1, .point = unit};
    mm_beam *ub;
    int rc = mm_beam_solve(&up, &ub, err);
    if (rc != MM_OK)
        return rc;
    /* the pieces: every breakpoint of either beam */
    double *xs = malloc((size_t)(b->nb + ub->nb) * sizeof *xs);
    if (!xs) {
        mm_beam_free(ub);
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    }
    memcpy(xs, b->xs, (size_t)b->nb * sizeof *xs);
    memcpy(xs + b->nb, ub->xs, (size_t)ub->nb * sizeof *xs);
    int n = b->nb + ub->nb;
    qsort(xs, (size_t)n, sizeof *xs, cmp_double);
    static const double gx[3] = {-0.77459666924148337704, 0, 0.77459666924148337704};
    static const double gw[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
    double sum = 0, abs_sum = 0;
    for (int i = 0; i + 1 < n; i++) {
        double u = xs[i], v = xs[i + 1];
        if (!(v > u))
            continue;
        for (int g = 0; g < 3; g++) {
            double xg = 0.5 * (u + v) + 0.5 * (v - u) * gx[g];
            mm_beam_value M, m;
            mm_beam_eval(b, xg, 1, &M);
            mm_beam_eval(ub, xg, 1, &m);
            sum += 0.5 * (v - u) * gw[g] * M.M * m.M;
            abs_sum += 0.5 * (v - u) * gw[g] * fabs(M.M * m.M);
        }
    }
    *y = sum / b->EI;                            /* eq. (9) */
    if (scale)
        *scale = abs_sum / b->EI;
    free(xs);
    mm_beam_free(ub);
    return MM_OK;
}

/* ---- statics (chapter 3): the diagrams sampled, and the checks' numerics ------ */

static int sample_count(const mm_beam *b, int n, int k)
{
    int c = 2 + (int)((n - 2 * (b->nb - 1)) * (b->xs[k + 1] - b->xs[k]) / b->L);
    return c < 2 ? 2 : c;
}

int mm_beam_sample_size(const mm_beam *b, int n)
{
    int total = 0;
    for (int k = 0; k + 1 < b->nb; k++)
        total += sample_count(b, n, k);
    return total;
}

void mm_beam_sample(const mm_beam *b, int n, double *x, double *V, double *M, double *y)
{
    int i = 0;
    for (int k = 0; k + 1 < b->nb; k++) {
        double h = b->xs[k + 1] - b->xs[k];
        int cnt = sample_count(b, n, k);
        for (int j = 0; j < cnt; j++, i++) {
            double s = j == cnt - 1 ? h : h * j / (cnt - 1);
            mm_beam_value v;
            mm_beam_eval_segment(b, k, s, &v);
            x[i] = j == cnt - 1 ? b->xs[k + 1] : b->xs[k] + s;
            V[i] = v.V, M[i] = v.M;
            if (y)
                y[i] = v.y;
        }
    }
}

void mm_beam_residual(const mm_beam_problem *p, const mm_beam *b, double *Fy, double *Mo, double *sF, double *sM)
{
    double fy = 0, mo = 0, f = 0, m = 0;
    for (int k = 0; k < b->nr; k++) {
        fy += b->ry[k], mo += b->ry[k] * b->rx[k] + b->rc[k];
        f += fabs(b->ry[k]), m += fabs(b->ry[k] * b->rx[k]) + fabs(b->rc[k]);
    }
    for (int i = 0; i < p->n_point; i++) {
        fy += p->point[2 * i + 1], mo += p->point[2 * i + 1] * p->point[2 * i];
        f += fabs(p->point[2 * i + 1]), m += fabs(p->point[2 * i + 1] * p->point[2 * i]);
    }
    for (int i = 0; i < p->n_dist; i++) {          /* each piece by the trapezoid's centroid */
        const double *d = p->dist + 4 * i;
        double l = d[1] - d[0], W1 = d[2] * l / 2, W2 = d[3] * l / 2;
        fy += W1 + W2, mo += W1 * (d[0] + l / 3) + W2 * (d[0] + 2 * l / 3);
        f += fabs(W1) + fabs(W2), m += fabs(W1 * (d[0] + l / 3)) + fabs(W2 * (d[0] + 2 * l / 3));
    }
    for (int i = 0; i < p->n_moment; i++)
        mo += p->moment[2 * i + 1], m += fabs(p->moment[2 * i + 1]);
    *Fy = fy, *Mo = mo, *sF = f, *sM = m;
}

void mm_beam_derivative_check(const mm_beam *b, double *wi, double *wd)
{
    static const double gx[3] = {-0.77459666924148337704, 0, 0.77459666924148337704};
    static const double gw[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
    *wi = *wd = 0;
    for (int k = 0; k + 1 < b->nb; k++) {
        double hk = b->xs[k + 1] - b->xs[k], I = 0, Iq = 0;
        mm_beam_value v0, v1, vg;
        mm_beam_eval_segment(b, k, 0, &v0);
        mm_beam_eval_segment(b, k, hk, &v1);
        double q1 = (v1.q - v0.q) / hk;
        double Vs = fabs(v0.V) + fabs(v0.q) * hk + fabs(q1) * hk * hk / 2 + 1e-300;
        double Ms = fabs(v0.M) + fabs(v0.V) * hk + fabs(v0.q) * hk * hk / 2 + fabs(q1) * hk * hk * hk / 6 + 1e-300;
        for (int g = 0; g < 3; g++) {
            mm_beam_eval_segment(b, k, 0.5 * hk * (1 + gx[g]), &vg);
            I += 0.5 * hk * gw[g] * vg.V;
            Iq += 0.5 * hk * gw[g] * vg.q;
        }
        *wi = fmax(*wi, fmax(fabs(v1.M - v0.M - I) / (16 * DBL_EPSILON * Ms),
                             fabs(v1.V - v0.V - Iq) / (16 * DBL_EPSILON * Vs)));
        double d = 1e-3 * hk;
        mm_beam_value m, lo, hi;
        mm_beam_eval_segment(b, k, 0.5 * hk, &m);
        mm_beam_eval_segment(b, k, 0.5 * hk - d, &lo);
        mm_beam_eval_segment(b, k, 0.5 * hk + d, &hi);
        /* the difference of a cubic is off by exactly d^2 M'''/6 = d^2 q1/6 */
        double tol = 16 * DBL_EPSILON * Ms / d, tolV = 16 * DBL_EPSILON * Vs / d;
        *wd = fmax(*wd, fmax(fabs(0.5 * (hi.M - lo.M) / d - d * d * q1 / 6 - m.V) / tol,
                             fabs(0.5 * (hi.V - lo.V) / d - m.q) / tolV));
    }
}
