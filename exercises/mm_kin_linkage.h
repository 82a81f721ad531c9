/* mm_kin_linkage.h — sweeps, difference samples and animations of the
 * chapter's linkages: kin-four-bar, kin-slider-crank, kin-quick-return
 * (their closed forms are in solvers/mm_linkage.h).  Results go into the
 * answer's arena. */
#ifndef MM_KIN_LINKAGE_H
#define MM_KIN_LINKAGE_H

#include "mm_exercise.h"
#include "mm_linkage.h"
#include "mm_mech.h"
#include "mm_natural.h"

/* the positions a difference study asks for (mm_kin_fd_study's pos
 * callback): Newton from the Taylor guess of sample i at t[i] + h */
typedef struct mm_kin_link_fd {
    const mm_mech_problem *p;
    const mm_mech_options *o;
    mm_mech_work *w;
    const double *t, *q;          /* the samples and their solved positions, */
    const double *qd, *qdd;       /* velocities and accelerations per unit crank rate */
} mm_kin_link_fd;

int mm_kin_link_fd_pos(int i, double h, double *q, double *qerr, void *ctx, mm_error *err);

/* the frame of a per-frame check nearest its bound (ratio starts at -1) */
typedef struct mm_kin_worst {
    double ratio, got, ref, tol;
} mm_kin_worst;

void mm_kin_track(mm_kin_worst *w, double got, double ref, double tol);

typedef struct mm_kin_fb_run {
    const mm_fourbar *m;
    const mm_mech_problem *prob;
    const mm_mech_options *opt;
    mm_mech_work *w;
} mm_kin_fb_run;

/* Positions, velocities, accelerations (per unit crank rate) of the
 * four-bar on the grid x[0..n-1] (increasing), following the assembly q0
 * found at th2 (singular: th2 is a toggle or change point, start a hair
 * off it) forward and backward */
int mm_kin_fb_sweep(const mm_kin_fb_run *r, double th2, const double *q0, int side, int singular, int n,
                    const double *x, double *Q, double *QD, double *QDD, mm_result *res, mm_error *err);

/* the four-bar over a turn (or out and back between toggles) with the
 * coupler point (px, py) on BC, its curve, velocity and acceleration */
int mm_kin_fb_animate(const mm_kin_fb_run *r, const mm_fourbar_class *k, int side, double w2, double px, double py,
                      double th0, const double *q0, int singular, mm_result *res, mm_error *err);

/* the slider-crank over a turn, or (partial) out and back between the
 * toggles lo, hi on the two assemblies */
int mm_kin_sc_animate(const mm_slider_crank *m, double omega, int partial, double lo, double hi,
                      const mm_mech_problem *prob, const mm_mech_options *opt, mm_mech_work *w, mm_result *res,
                      mm_error *err);

/* ---- a crank that cannot turn round ---- */

/* The warning of a crank that reaches only [lo, hi], between two toggles:
 * what (the sentence that says so, formatted) followed by the arcs it
 * cannot close: the rest of the turn, or (two gaps, gaps[0] below lo and
 * gaps[1] above hi) both and the arc beyond them, another assembly. */
void mm_kin_warn_reach(mm_result *res, const char *what, double lo, double hi, const double gaps[2]);

/* The sweep run past each toggle lo, hi stops where the closed form says:
 * 9 frames from a tenth of the arc inside to 0.05 rad past it (never past
 * the middle of the gap, where the linkage closes again and a sweep could
 * step across), from the assembly assemble(t) gives; checks named
 * "first/second toggle: where the sweep stops closing vs <why>".  MM_OK or
 * the sweep's code. */
int mm_kin_toggle_checks(mm_result *res, const mm_mech_problem *prob, const mm_mech_options *opt, mm_mech_work *w,
                         double lo, double hi, const double gaps[2], void (*assemble)(double t, double *q, void *ctx),
                         void *ctx, const char *why, mm_error *err);

/* kin-mobility: a linkage in natural coordinates (m) over nf frames, frame
 * f at t[f] (the drivers' time when they rock, their angle when they turn
 * round) in the positions Q + f n (n = 2 (npts - nfix); the last solved
 * one from frame `solved` on): pivots at its fixed points, bars as lines
 * (those of a ternary link, tri[0..ntri-1], drawn as its triangle), the
 * slide and the slider. */
int mm_kin_anim_linkage(mm_result *res, const mm_nat_model *m, int ntri, const int (*tri)[3], int nf, const double *t,
                        const double *Q, int solved, mm_error *err);

/* kin-mobility's Bennett linkage (mm_linkage_bennett: a, alpha, beta)
 * moved round its first joint (72 frames), seen isometrically: the loop of
 * the joints' origins and their axes.  *worst receives the largest
 * closing error max |T1 T2 T3 T4 - I| over the frames (for the check). */
int mm_kin_anim_bennett(mm_result *res, double a, double alpha, double beta, double *worst, mm_error *err);

/* kin-quick-return over a turn of the crank (72 frames) from the assembly
 * q0 (the solved positions at theta2 = 0): the pivots O4, O2, the ram's
 * guide, the crank, the lever drawn to length L, the block in its slot,
 * the ram and its velocity at crank speed omega; stroke the ram's */
int mm_kin_qr_animate(const mm_quick_return *m, double omega, double L, double stroke, const mm_mech_problem *prob,
                      const mm_mech_options *opt, mm_mech_work *w, const double *q0, mm_result *res, mm_error *err);

#endif
