/* mm_natural.h — a planar linkage in natural coordinates: the unknowns
 * are the positions of its moving points, each link a bar of fixed length
 * between two points, a slider a point held on a horizontal line, and a
 * driver a bar from a fixed point turned to a given angle (J. Garcia de
 * Jalon, E. Bayo, Kinematic and Dynamic Simulation of Multibody Systems,
 * Springer 1994, ch. 2).  The constraints, with q the moving points' x, y:
 *
 *     |P_i - P_j|^2 - L_ij^2 = 0                 (each bar)
 *     y_s - y_s0 = 0                             (the slider)
 *     (A - O) x (cos th, sin th) = 0             (each driver, driven only)
 *
 * and their Jacobian, for mm_mech (rank, Newton, sweeps).  The lengths,
 * the slide's height and the drivers' starting angles come from an
 * assembly.  Pure functions, no allocation. */
#ifndef MM_NATURAL_H
#define MM_NATURAL_H

#include "mm_mech.h"

#define MM_NAT_MAXP 8                 /* points */
#define MM_NAT_MAXC 12                /* bars */

typedef struct mm_nat_linkage {
    int nfix, npts;                   /* points: the first nfix are fixed */
    double p[MM_NAT_MAXP][2];         /* an assembly; the lengths come from it */
    int ncon, con[MM_NAT_MAXC][2];    /* bars between points */
    int slide;                        /* a point that runs on the line y = its own y (or -1) */
    int ndrv, drv[2][2];              /* drivers: (fixed pivot, moving point), turning by angle */
    double amp;                       /* 0: the drivers turn round (th0 + t); else they rock, th0 + amp sin t */
} mm_nat_linkage;

typedef struct mm_nat_model {
    const mm_nat_linkage *s;
    double L2[MM_NAT_MAXC];           /* squared lengths */
    double y_slide;
    double th0[2];                    /* drivers' angles at the start */
    int driven;                       /* 1: the drivers' constraints too */
} mm_nat_model;

/* The model of s (lengths, slide and driver angles from its assembly),
 * with (driven = 1) or without its drivers' constraints; the unknowns at
 * the assembly into q (2 (npts - nfix) values, may be NULL).  Cannot fail. */
void mm_nat_init(mm_nat_model *m, const mm_nat_linkage *s, int driven, double *q);

/* The problem for mm_mech: n = 2 (npts - nfix) unknowns, m = ncon +
 * (slide >= 0) (+ ndrv when driven) constraints; t is the drivers' time
 * (their angle's argument).  m must outlive prob. */
void mm_nat_problem(const mm_nat_model *m, mm_mech_problem *prob);

/* Point i's x, y: fixed from the assembly, moving from q. */
void mm_nat_point(const mm_nat_model *m, const double *q, int i, double *x, double *y);

#endif
