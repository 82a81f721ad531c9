/* mm_cam.h — a disc cam turning counter-clockwise by theta with a
 * translating roller follower on the line x = e (the cam's frame turns
 * with it): rise over beta_rise, dwell at the top, return, dwell at the
 * bottom.  Equation numbers are those of exercises/kin/cam_follower.md.
 * Pure functions: thread-safe, no allocation. */
#ifndef MM_CAM_H
#define MM_CAM_H

#include "mm_geom.h"
#include "mm_opt.h"

enum { MM_CAM_CYCLOIDAL, MM_CAM_HARMONIC, MM_CAM_POLY345, MM_CAM_CONST_ACC };

typedef struct mm_cam {
    int law;                  /* MM_CAM_* */
    double h;                 /* lift [m] */
    double br, bd, bt;        /* rise, top dwell and return angles [rad] */
    double Rb, Rr, e;         /* base circle and roller radii, offset [m] */
    double s0;                /* sqrt((Rb + Rr)^2 - e^2): the roller centre's height at s = 0 */
} mm_cam;

/* a rise of 1 over u in [0, 1] by the law: d = (s, s', s'', s''') by u, eq. (1) */
void mm_cam_rise(int law, double u, double d[4]);

/* the peaks of |s'| and |s''| of a rise of 1 over u in [0, 1] (closed forms) */
void mm_cam_peaks(int law, double *p1, double *p2);

/* s and its derivatives by theta over the whole turn; *seg = 0 rise,
 * 1 top dwell, 2 return, 3 bottom dwell */
void mm_cam_motion(const mm_cam *m, double theta, double d[4], int *seg);

/* the pressure angle, eq. (2), from d = (s, s', ...) */
double mm_cam_pressure(const mm_cam *m, const double *d);

/* the pitch curve's radius of curvature, eq. (3): positive where it is
 * convex seen from outside, INFINITY where straight */
double mm_cam_rho_pitch(const mm_cam *m, const double *d);

/* the roller centre P and the contact point K at theta, in the cam's frame */
void mm_cam_points(const mm_cam *m, double theta, mm_v2 *P, mm_v2 *K);

/* the nearest place to th where the law's derivatives jump: the segments'
 * ends (a turn included), the middle of a constant-acceleration rise or return */
double mm_cam_near_jump(const mm_cam *m, double th);

/* The largest |pressure angle| over the turn, and the smallest radius of
 * curvature of the pitch curve where it is convex (INFINITY when it is
 * nowhere convex): a scan of 3600 cam angles, a golden-section search
 * between the best sample's neighbours, and both sides of every place
 * where the law's s'' jumps (rho jumps there).  *at receives the place;
 * *err an estimate: how much the value changes over the search's final
 * bracket, at least 1e-12 of it (1e-6 at a jump, where the extreme is a
 * one-sided limit reached to within the search's last step). */
double mm_cam_pressure_max(const mm_cam *m, double *at, double *err);
double mm_cam_rho_pitch_min(const mm_cam *m, double *at, double *err);

/* The largest |s^(k)| (k = 1, 2) over [a, b] within the segment seg (0
 * the rise, 2 the return; 0 outside it) by golden section (mm_opt) to tol:
 * a measurement of the law's peak independent of mm_cam_peaks.  Returns
 * mm_opt_golden_max's code. */
int mm_cam_peak_search(const mm_cam *m, int k, int seg, double a, double b, double tol, mm_opt_result *r,
                       mm_error *err);

#endif
