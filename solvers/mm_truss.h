/* mm_truss.h — planar pin-jointed trusses: the method of joints as one
 * linear system, the determinacy count and the rank test in mechanics
 * words, the method of sections as a second route.
 *
 * The model: straight members joined by frictionless pins at the joints,
 * loads and reactions at the joints only, so every member is a two-force
 * member carrying an axial force F (tension positive).  Each joint j gives
 * two equations (eq. 1 of sta/truss.md):
 *
 *     sum over members e at j of F_e u_je  +  R_j  +  P_j  =  0,
 *
 * u_je the unit vector from j along member e, R_j the reaction components
 * at j (a support fixes x, y or both), P_j the applied load.  With m
 * members, r reaction components and j joints, the count m + r - 2j is the
 * determinacy: < 0 a mechanism, > 0 statically indeterminate, 0 determinate
 * if the equations are also independent (the rank test of mm_equil.h).
 *
 * Unknowns are ordered: the m member forces, then the reaction components
 * support by support (x before y).  Equations are the joints' x and y sums,
 * ordered along the truss's longer side so that the sparse elimination of
 * mm_equil stays inside a narrow band.
 *
 * No globals; caller-owned arrays; scratch allocated and freed inside.
 */
#ifndef MM_TRUSS_H
#define MM_TRUSS_H

#include "mm_equil.h"
#include "mm_status.h"

#define MM_TRUSS_MAX_NODES     100
#define MM_TRUSS_MAX_MEMBERS   300
#define MM_TRUSS_MAX_SUPPORTS  100
#define MM_TRUSS_MAX_LOADS     100

typedef struct mm_truss {
    int n_nodes;
    const double *xy;          /* n_nodes x 2: x, y of each joint [m] */
    int n_members;
    const int *ends;           /* n_members x 2: its two joints, 0-based */
    int n_supports;
    const int *supports;       /* n_supports x 3: joint (0-based), fix_x, fix_y (0 or 1) */
    int n_loads;
    const int *load_node;      /* n_loads: the loaded joint, 0-based */
    const double *load_f;      /* n_loads x 2: Fx, Fy [N] */
} mm_truss;

typedef struct mm_truss_result {
    double *force;             /* [n_members], caller's: axial force, tension positive [N] */
    double *reaction;          /* [2 n_nodes], caller's: Rx, Ry at each joint (0 where free) [N] */
    int n_reactions;           /* r: reaction components */
    int determinacy;           /* m + r - 2j */
    mm_equil_result eq;        /* rank, rcond, residual, scale, growth of the joint equations */
    /* when the truss is singular (MM_ESINGULAR), the diagnosis: */
    int free_joint;            /* the joint that moves most in a mechanism motion, or -1 */
    double free_dir;           /* its direction of motion [rad], in (-pi/2, pi/2] */
    int rigid;                 /* 1: the motion is the whole truss moving as a rigid body */
    int rigid_turns;           /* with rigid: 1 turning about pivot, 0 sliding along free_dir */
    double pivot[2];           /* with rigid_turns: the centre of the rotation [m] */
    int redundant_member;      /* a member of a self-stress (the largest), or -1 */
    int redundant_support;     /* else a support's joint, or -1 */
    int redundant_count;       /* members and reaction components in that self-stress */
} mm_truss_result;

/* Sizes within the MM_TRUSS_MAX_* limits, joints numbered within range, a
 * member between two different joints of nonzero length and listed once,
 * support flags 0 or 1 with a joint listed once, finite coordinates and
 * loads.  Parameter names in err: "nodes", "members", "supports", "loads"
 * (messages number joints and members from 1, as a learner does).
 * Returns MM_OK, MM_ERANGE or MM_EVALUE.  No side effects. */
int mm_truss_check(const mm_truss *t, mm_error *err);

/* Solve the joint equations.  MM_OK: res->force and res->reaction filled,
 * res->eq says how well (rcond, residual).  MM_ESINGULAR: a mechanism or
 * statically indeterminate truss (by the count or by the rank); the
 * diagnosis fields are filled and err->msg says in mechanics words which
 * joint can move and how, or which member or support is redundant (param
 * "members").  Other failures: those of mm_truss_check, MM_ENONFINITE,
 * MM_ENOMEM. */
int mm_truss_solve(const mm_truss *t, mm_truss_result *res, mm_error *err);

/* The reactions by the equilibrium of the whole truss as one rigid body,
 * when the supports give exactly three reaction components whose lines are
 * neither concurrent nor all parallel: each component by moments about the
 * meeting point of the other two lines (Ritter), independent of the joint
 * equations.  reaction[2 n_nodes] as in mm_truss_result.  Returns 1 when
 * done, 0 when the supports do not allow it.  Cannot fail otherwise. */
int mm_truss_reactions_rigid(const mm_truss *t, double *reaction);

/* The method of sections: every straight cut x = c between neighbouring
 * joint abscissae, and every cut y = c between ordinates, that crosses
 * exactly three members whose lines are not concurrent; each of the three
 * forces by moments about the meeting point of the other two (or by forces
 * across two parallel ones) from the loads and reactions on one side.
 * reaction[2 n_nodes] are the reactions to use.  sec_force[n_members]
 * receives the force of each member found by some cut (the first),
 * sec_count[n_members] how many cuts found it (0: none; sec_force is then
 * 0), and sec_scale[n_members] (may be NULL) the size of the terms of that
 * moment sum over its lever arm: the scale of its round-off.  Returns the
 * number of cuts used.  Cannot fail (scratch on the stack up to
 * MM_TRUSS_MAX_NODES). */
int mm_truss_sections(const mm_truss *t, const double *reaction, double *sec_force, int *sec_count,
                      double *sec_scale);

/* For each joint, the largest angle between the lines of its members and
 * its support directions, in [0, pi/2] [rad], into spread[n_nodes].  A
 * joint whose lines all lie within a small angle of one line can resist a
 * load across that line only with forces of about 1/sin(spread) times the
 * load.  Joints with fewer than two lines get 0.  Cannot fail. */
void mm_truss_spread(const mm_truss *t, double *spread);

/* ---- statics (chapter 3): the equilibrium put back, for the checks ------------- */

/* Every joint's sum of forces recomputed from the geometry with the member
 * forces F[n_members] and reactions R[2 n_nodes] (eq. 1), independent of
 * how they were found: *worst the largest |sum F| at a joint, *scale the
 * largest sum of |terms| at a joint, *total the sum of |terms| over all
 * joints.  Cannot fail. */
void mm_truss_joint_residual(const mm_truss *t, const double *F, const double *R, double *worst, double *scale,
                             double *total);

/* The whole truss as one body: sum Fx, sum Fy and sum M about the first
 * joint of the loads and reactions R[2 n_nodes]; *worst the largest of
 * |(sum Fx, sum Fy)| and |sum M| / arm, *scale the larger of the sums of
 * their |terms| (forces, and moments over arm), arm the largest distance
 * of a joint from the first (at least 1 m).  Cannot fail. */
void mm_truss_body_residual(const mm_truss *t, const double *R, double *worst, double *scale);

#endif
