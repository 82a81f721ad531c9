/* mm_cam.c — the follower's motion of a disc cam with a roller follower:
 * the four rise laws of exercises/kin/cam_follower.md eq. (1) and their
 * peaks, the motion over a turn (rise, dwell, return, dwell), the pressure
 * angle (2), the pitch curve's radius of curvature (3), the roller centre
 * and contact point, and where the law's derivatives jump.
 */
#include <math.h>

#include "mm_cam.h"
#include "mm_opt.h"

/* a rise of 1 over u in [0, 1]: the law and its derivatives by u, eq. (1) */
void mm_cam_rise(int law, double u, double d[4])
{
    double c, sn;
    switch (law) {
    case 0:                                                  /* cycloidal */
        c = cos(2 * M_PI * u), sn = sin(2 * M_PI * u);
        d[0] = u - sn / (2 * M_PI), d[1] = 1 - c, d[2] = 2 * M_PI * sn, d[3] = 4 * M_PI * M_PI * c;
        break;
    case 1:                                                  /* harmonic */
        c = cos(M_PI * u), sn = sin(M_PI * u);
        d[0] = 0.5 * (1 - c), d[1] = 0.5 * M_PI * sn, d[2] = 0.5 * M_PI * M_PI * c, d[3] = -0.5 * M_PI * M_PI * M_PI * sn;
        break;
    case 2:                                                  /* 3-4-5 polynomial */
        d[0] = u * u * u * (10 - 15 * u + 6 * u * u), d[1] = 30 * u * u * (1 - 2 * u + u * u);
        d[2] = 60 * u * (1 - 3 * u + 2 * u * u), d[3] = 60 * (1 - 6 * u + 6 * u * u);
        break;
    default:                                                 /* constant acceleration */
        if (u < 0.5)
            d[0] = 2 * u * u, d[1] = 4 * u, d[2] = 4, d[3] = 0;
        else
            d[0] = 1 - 2 * (1 - u) * (1 - u), d[1] = 4 * (1 - u), d[2] = -4, d[3] = 0;
    }
}

/* the peaks of |d1| and |d2| of a rise of 1 over u in [0, 1] */
void mm_cam_peaks(int law, double *p1, double *p2)
{
    static const double P1[4] = {2, M_PI / 2, 1.875, 2};
    static const double P2[4] = {2 * M_PI, M_PI * M_PI / 2, 5.773502691896257645, 4};   /* 10 sqrt(3) / 3 */
    *p1 = P1[law], *p2 = P2[law];
}

/* s and its derivatives by theta over the whole turn; *seg = 0 rise, 1 top
 * dwell, 2 return, 3 bottom dwell */
void mm_cam_motion(const mm_cam *m, double theta, double d[4], int *seg)
{
    double th = theta - 2 * M_PI * floor(theta / (2 * M_PI)), r[4];
    double b1 = m->br, b2 = b1 + m->bd, b3 = b2 + m->bt;
    if (th < b1) {
        mm_cam_rise(m->law, th / m->br, r);
        for (int k = 0; k < 4; k++)
            d[k] = m->h * r[k] / pow(m->br, k);
        *seg = 0;
    } else if (th < b2) {
        d[0] = m->h, d[1] = d[2] = d[3] = 0, *seg = 1;
    } else if (th < b3) {
        mm_cam_rise(m->law, (th - b2) / m->bt, r);                 /* the return mirrors a rise */
        d[0] = m->h * (1 - r[0]);
        for (int k = 1; k < 4; k++)
            d[k] = -m->h * r[k] / pow(m->bt, k);
        *seg = 2;
    } else {
        d[0] = d[1] = d[2] = d[3] = 0, *seg = 3;
    }
}

/* the pressure angle, eq. (2), and the pitch curve's radius of curvature,
 * eq. (3) (positive where the curve is convex, seen from outside) */
double mm_cam_pressure(const mm_cam *m, const double *d)
{
    return atan2(d[1] - m->e, m->s0 + d[0]);
}

double mm_cam_rho_pitch(const mm_cam *m, const double *d)
{
    double y = m->s0 + d[0], tx = y, ty = d[1] - m->e;          /* tau = c' - k x c */
    double wx = 2 * d[1] - m->e, wy = d[2] - y;                  /* tau' - k x tau */
    double t = hypot(tx, ty), cr = tx * wy - ty * wx;
    return cr != 0 ? -t * t * t / cr : INFINITY;
}

/* the roller centre (pitch point) and the contact point, in the mm_cam's frame */
void mm_cam_points(const mm_cam *m, double theta, mm_v2 *P, mm_v2 *K)
{
    double d[4];
    int seg;
    mm_cam_motion(m, theta, d, &seg);
    mm_v2 C = {m->e, m->s0 + d[0]}, n = {m->e - d[1], m->s0 + d[0]};          /* normal, away from the mm_cam */
    mm_v2 Kf = mm_v2_sub(C, mm_v2_scale(n, m->Rr / mm_v2_norm(n)));
    *P = mm_v2_rotate(C, -theta);
    *K = mm_v2_rotate(Kf, -theta);
}

/* the nearest place to th where the law's derivatives jump: the ends of
 * the segments (a turn included), and the middle of a constant-acceleration
 * rise or return */
double mm_cam_near_jump(const mm_cam *m, double th)
{
    double b[7] = {0, m->br, m->br + m->bd, m->br + m->bd + m->bt, 2 * M_PI,
                   m->law == 3 ? 0.5 * m->br : 0, m->law == 3 ? m->br + m->bd + 0.5 * m->bt : 0};
    double best = b[0];
    for (int k = 1; k < 7; k++)
        if (fabs(th - b[k]) < fabs(th - best))
            best = b[k];
    return best;
}

/* ---- the extremes over a turn, added for kin-cam-follower ---- */

/* the quantity whose extreme is sought: |pressure angle| (which = 0), or
 * -rho of the pitch curve where it is convex (which = 1; -inf elsewhere) */
typedef struct ext_ctx {
    const mm_cam *m;
    int which;
} ext_ctx;

static int ext_fn(double th, double *f, void *ctx)
{
    const ext_ctx *c = ctx;
    double d[4];
    int seg;
    mm_cam_motion(c->m, th, d, &seg);
    if (c->which == 0) {
        *f = fabs(mm_cam_pressure(c->m, d));
    } else {
        double rp = mm_cam_rho_pitch(c->m, d);
        *f = rp > 0 ? -rp : -INFINITY;
    }
    return 0;
}

/* The largest value over the turn: a scan of 3600 cam angles, a
 * golden-section search between the best sample's neighbours, and both
 * sides of every place where the law's s'' jumps (rho jumps there).  *at
 * receives the place; *err an estimate: how much the value changes over
 * the search's final bracket, at least 1e-12 of it. */
static double extreme(const mm_cam *m, int which, double *at, double *err)
{
    enum { NS = 3600 };
    ext_ctx c = {m, which};
    double best = -INFINITY, f, step = 2 * M_PI / NS;
    int kb = 0;
    for (int k = 0; k < NS; k++) {
        ext_fn(step * k, &f, &c);
        if (f > best)
            best = f, kb = k;
    }
    *at = step * kb, *err = 0;
    if (!isfinite(best))
        return best;
    mm_opt_result r;
    if (mm_opt_golden_max(ext_fn, &c, step * (kb - 1), step * (kb + 1), 1e-10, 200, &r, NULL) == MM_OK &&
        r.fx > best) {
        double fl, fr;
        ext_fn(r.x - r.bracket, &fl, &c), ext_fn(r.x + r.bracket, &fr, &c);
        best = r.fx, *at = r.x;
        *err = fmax(fabs(r.fx - fl), fabs(r.fx - fr));
    }
    double jumps[7] = {0, m->br, m->br + m->bd, m->br + m->bd + m->bt, 2 * M_PI, 0.5 * m->br,
                       m->br + m->bd + 0.5 * m->bt};
    int near = 0;
    for (int k = 0; k < 7 && which == 1; k++) {
        near |= fabs(*at - jumps[k]) < 1e-6;
        for (int side = -1; side <= 1; side += 2) {
            ext_fn(jumps[k] + side * 1e-9, &f, &c);
            if (f > best)
                best = f, *at = jumps[k] + side * 1e-9, *err = 0, near = 1;
        }
    }
    /* at a jump the extreme is a one-sided limit, reached to within the
     * search's last step: 1e-6 of the value covers that */
    *err = fmax(*err, (near ? 1e-6 : 1e-12) * fabs(best));
    return best;
}

double mm_cam_pressure_max(const mm_cam *m, double *at, double *err)
{
    return extreme(m, 0, at, err);
}

double mm_cam_rho_pitch_min(const mm_cam *m, double *at, double *err)
{
    return -extreme(m, 1, at, err);
}

typedef struct peak_ctx {
    const mm_cam *m;
    int k, seg;            /* which derivative, and which segment's peak */
} peak_ctx;

static int peak_fn(double th, double *f, void *ctx)
{
    peak_ctx *c = ctx;
    double d[4];
    int seg;
    mm_cam_motion(c->m, th, d, &seg);
    *f = seg == c->seg ? fabs(d[c->k]) : 0;
    return 0;
}

int mm_cam_peak_search(const mm_cam *m, int k, int seg, double a, double b, double tol, mm_opt_result *r,
                       mm_error *err)
{
    peak_ctx pc = {m, k, seg};
    return mm_opt_golden_max(peak_fn, &pc, a, b, tol, 200, r, err);
}
