/* mm_linkage.h — closed forms of the four-bar and the offset slider-crank,
 * and their loop-closure equations as mm_mech problems.
 *
 * Four-bar: crank O2B = a at theta2, coupler BC = b (theta3), rocker
 * O4C = c (theta4), ground O2O4 = d along +x:
 *     a cos th2 + b cos th3 - c cos th4 - d = 0
 *     a sin th2 + b sin th3 - c sin th4     = 0                      (1)
 * side = +1 puts C left of the directed line B -> O4 ("open"), -1 right.
 *
 * Slider-crank: crank OA = r at phi, rod AB = l at theta3, slider B on
 * the line y = e at x:
 *     r cos phi + l cos theta3 - x = 0,  r sin phi + l sin theta3 - e = 0
 * side = +1: the slider right of A.
 *
 * Pure functions of their arguments: thread-safe, no allocation.  The
 * problems keep a pointer to the linkage, which must outlive them.
 */
#ifndef MM_LINKAGE_H
#define MM_LINKAGE_H

#include "mm_geom.h"
#include "mm_mech.h"

typedef struct mm_fourbar {
    double a, b, c, d;
} mm_fourbar;

typedef struct mm_fourbar_class {
    int grashof;         /* s + l <= p + q (equality within 4 ulps of the sum) */
    int change_point;    /* s + l = p + q */
    int full;            /* the crank turns round */
    int shortest;        /* 0 a, 1 b, 2 c, 3 d */
    double lo, hi;       /* else: the arc holding theta2, between toggles, */
    double gap[2];       /* and the widths of the unreachable arcs below lo and above hi */
    const char *name;    /* "crank-rocker", ..., "change point", "triple rocker (non-Grashof)" */
} mm_fourbar_class;

/* (b + c - |O4 B|)(|O4 B| - |b - c|): >= 0 where the linkage closes */
double mm_linkage_fb_disc(const mm_fourbar *m, double th2);

/* theta3, theta4 of the assembly side at th2 by Freudenstein's equation
 * (the stable root form); *err (may be NULL): a bound of their rounding.
 * Where every theta4 closes the loop (B on O4 with b = c: a rhombus at
 * th2 = 0) theta4 = 0 is taken. */
void mm_linkage_fb_angles(const mm_fourbar *m, double th2, int side, double *th3, double *th4, double *err);

/* omega3, omega4, alpha3, alpha4 per unit crank rate (omega2 = 1) */
void mm_linkage_fb_rates(const mm_fourbar *m, double th2, double th3, double th4, double *w3, double *w4,
                         double *a3, double *a4);

/* Grashof's class, and unless the crank turns round the arc of crank
 * angles next to th2 it can reach, between toggles */
mm_fourbar_class mm_linkage_fb_classify(const mm_fourbar *m, double th2);

/* q = (theta3, theta4) of the side at th2 from two circles (a guess for
 * Newton; the midpoint of B O4's reach where they do not meet) */
void mm_linkage_fb_assemble(const mm_fourbar *m, double th2, int side, double *q);

/* the coupler point P = B + (px, py) turned by theta3, its velocity and
 * acceleration per unit crank rate, from q, q', q'' */
void mm_linkage_fb_coupler(const mm_fourbar *m, double px, double py, double th2, const double *q, const double *qd,
                           const double *qdd, mm_v2 *P, mm_v2 *V, mm_v2 *A);

/* rounding bounds of the angles, rates and accelerations of one frame
 * whose angles carry the error dth (tol[0..2]) */
void mm_linkage_fb_frame_tol(const mm_fourbar *m, const double *q, const double *qd, const double *qdd, double dth,
                             double tol[3]);

/* the error of Newton's angles: eps S over the Jacobian's smallest singular value, plus 2 err_est */
double mm_linkage_fb_newton_err(const mm_fourbar *m, const double *q, double err_est);

/* the transmission angle at th2 by the law of cosines, in [0, pi] */
double mm_linkage_fb_mu(const mm_fourbar *m, double th2);

/* the Freudenstein root (either side) nearest q: f = (theta3, theta4), *err its rounding */
void mm_linkage_fb_nearest(const mm_fourbar *m, double th2, const double *q, double *f, double *err);

/* the least and greatest transmission angle over [lo, hi] (full: a turn)
 * and the crank angles where (toggles: 0 or pi exactly) */
void mm_linkage_fb_mu_extremes(const mm_fourbar *m, int full, double lo, double hi, double *mn, double *tmn,
                               double *mx, double *tmx);

/* the crank angles of the rocker's dead centres (crank and coupler in
 * line) and their rounding bounds; returns how many, at most 4 */
int mm_linkage_fb_dead_centres(const mm_fourbar *m, double dc[4], double dce[4]);

/* a crank-rocker's swing angle between its dead centres (side: the assembly) */
double mm_linkage_fb_swing(const mm_fourbar *m, int side);

/* eq. (1) with q = (theta3, theta4), t = theta2 */
void mm_linkage_fb_problem(const mm_fourbar *m, mm_mech_problem *prob);

typedef struct mm_slider_crank {
    double r, l, e;
} mm_slider_crank;

typedef struct mm_sc_pos {
    double x, x1, x2;         /* x and its derivatives by phi */
    double t, t1, t2;         /* theta3 and its derivatives by phi */
    double R;                 /* l cos theta3: the rod's run along the slide */
} mm_sc_pos;

/* l^2 - (e - r sin phi)^2 as a product: >= 0 where the rod reaches the slide */
double mm_linkage_sc_disc(const mm_slider_crank *m, double phi);

/* the closed form of the side at phi (derivatives 0 at a toggle) */
mm_sc_pos mm_linkage_sc_closed(const mm_slider_crank *m, double phi, int side);

/* 0: the crank turns round; 1: [lo, hi] is the arc between toggles
 * holding phi0 (gaps, may be NULL: the unreachable arcs below and above);
 * -1: phi0 cannot be reached */
int mm_linkage_sc_reach(const mm_slider_crank *m, double phi0, double *lo, double *hi, double *gaps);

/* eq. (1) with q = (theta3, x), t = phi */
void mm_linkage_sc_problem(const mm_slider_crank *m, mm_mech_problem *prob);

/* The Bennett linkage: links 1, 3 of length a and twist alpha, links 2, 4
 * of length b = a sin(beta) / sin(alpha) and twist beta, joint angles
 * (th1, th2, -th1, -th2) with tan(th1/2) tan(th2/2) = sin((beta + alpha)/2)
 * / sin((beta - alpha)/2).  The origins o[k] and axes z[k] of the four
 * joints at th1 (standard Denavit-Hartenberg), and the loop's closing error
 * max |T1 T2 T3 T4 - I| into *gap. */
void mm_linkage_bennett(double a, double alpha, double beta, double th1, mm_v3 o[4], mm_v3 z[4], double *gap);

/* ==== the quick-return mechanism (crank and slotted lever), added for kin-quick-return ==== */

/* The crank O2A (r) turns about O2 = (0, d); its pin A slides in the slot
 * of a lever pivoted at O4 = (0, 0), whose slot drives a block on the ram
 * along y = H (H > d + r, r < d). */
typedef struct mm_quick_return {
    double r, d, H;
} mm_quick_return;

typedef struct mm_qr_pos {
    double t4, t4p, t4pp;     /* the lever's angle and its derivatives by th2 */
    double X, Xp, Xpp;        /* the ram's position and its derivatives by th2 */
} mm_qr_pos;

/* The closed form at the crank angle th2:
 *     th4 = atan2(d + r sin th2, r cos th2),  X = H r cos th2 / (d + r sin th2) */
mm_qr_pos mm_linkage_qr_closed(const mm_quick_return *m, double th2);

/* The loop closure with q = (th4, s, X, s2), t = th2 (s = |O4 A|, s2 the
 * block's distance from O4 along the lever):
 *     s cos th4 = r cos th2,   s sin th4 = d + r sin th2,
 *     s2 cos th4 = X,          s2 sin th4 = H */
void mm_linkage_qr_problem(const mm_quick_return *m, mm_mech_problem *prob);

/* A rough first guess of q at th2 (the closed form, each coordinate off
 * by about 1 %), for Newton to start from. */
void mm_linkage_qr_guess(const mm_quick_return *m, double th2, double *q);

#endif
