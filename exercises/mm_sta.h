/* mm_sta.h — the statics kit (chapter 3): drawing free-body diagrams, the
 * standard figures of the chapter's exercises, and the idioms their answers
 * and checks share (the numerics they use live in solvers/).
 *
 * The drawings are one-frame animations (mm_exercise.h) of bodies, members,
 * supports, forces and couples, with the conventions every statics answer
 * shares:
 *
 *   - forces are arrows (kind "arrow") in metres per newton `scale`, with
 *     the force's magnitude as `value` and "N" as unit; an applied load
 *     points AT its point of application (the head touches the body), a
 *     reaction pushes on the body from outside the same way;
 *   - members carry their axial force as `value`, styled "tension" or
 *     "compression" (a zero-force member gets no style);
 *   - supports and ground are styled "ground";
 *   - couples are an arc (kind "line", value in N m) with an arrow head.
 *
 * Every drawing function adds shapes to res's animation, which the caller
 * started with mm_sta_fbd(); each returns MM_OK or MM_ENOMEM.  A failure is
 * recorded in res (sticky: mm_result_status, and the server refuses the
 * answer), and every later call is safe, so a drawing is a plain list of
 * calls whose returns need no checking.  Texts are copied into the arena.
 */
#ifndef MM_STA_H
#define MM_STA_H

#include "mm_beam.h"
#include "mm_equil.h"
#include "mm_exercise.h"
#include "mm_section.h"
#include "mm_truss.h"

/* ---- drawing: the free-body diagram and its parts ----------------------------------- */

/* Start a one-frame animation (the free-body diagram); t = 0. */
int mm_sta_fbd(mm_result *res);

/* Metres of arrow per newton so that the largest force, fmax [N], is drawn
 * frac of the drawing's size [m] long (fmax <= 0: 0). */
double mm_sta_scale(double fmax, double size, double frac);

/* A force (Fx, Fy) [N] at (px, py) [m], drawn at `scale` m/N with its head
 * on the point (head = 1) or its tail on it (head = 0).  value is |F|. */
int mm_sta_force(mm_result *res, const char *name, double px, double py, double Fx, double Fy,
                 double scale, int head);

/* A straight member or link from (x0, y0) to (x1, y1); style NULL,
 * "tension", "compression", "ground" or "highlight"; value, if has_value,
 * the axial force [N]. */
int mm_sta_line(mm_result *res, const char *name, double x0, double y0, double x1, double y1,
                const char *style, int has_value, double value);

/* A member coloured by its axial force F: "tension" for F > tol, else
 * "compression" for F < -tol, else no style. */
int mm_sta_member(mm_result *res, const char *name, double x0, double y0, double x1, double y1, double F,
                  double tol);

/* A closed body of n vertices xy[2n]. */
int mm_sta_polygon(mm_result *res, const char *name, int n, const double *xy, const char *style);

/* A polyline of n points xy[2n]. */
int mm_sta_path(mm_result *res, const char *name, int n, const double *xy, const char *style);

/* A circle of radius r at (x, y). */
int mm_sta_circle(mm_result *res, const char *name, double x, double y, double r, const char *style);

/* A text at (x, y). */
int mm_sta_label(mm_result *res, double x, double y, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* An arrow from (x0, y0) to (x1, y1) [m] for a quantity that is not a
 * force in N: a pressure drawn at `scale` m/Pa, a weight per unit areal
 * weight...; value its size in unit. */
int mm_sta_arrow(mm_result *res, const char *name, double x0, double y0, double x1, double y1, const char *unit,
                 double scale, double value);

/* Supports, `size` [m] across, under the point (x, y) with the ground
 * turned by angle [rad] (0: ground below, the support pushes up):
 * a pin (a triangle on a ground line), a roller (a triangle on two wheels
 * on a ground line), a clamp (a wall with hatching) facing +x at (x, y). */
int mm_sta_pin(mm_result *res, const char *name, double x, double y, double size, double angle);
int mm_sta_roller(mm_result *res, const char *name, double x, double y, double size, double angle);
int mm_sta_clamp(mm_result *res, const char *name, double x, double y, double size);

/* A couple C [N m] (counter-clockwise positive) drawn round (x, y) with
 * radius r: a 3/4 arc whose arrow head shows the sense. */
int mm_sta_couple(mm_result *res, const char *name, double x, double y, double r, double C);

/* ---- drawing in space (an oblique projection) --------------------------------------- */

/* Oblique projection of a point in space for 3-D diagrams: x toward the
 * viewer and left, y right, z up, into the drawing's (u, v). */
void mm_sta_project(double x, double y, double z, double *u, double *v);

/* 3-D diagrams in that projection: a straight line from a to b, and a
 * force or moment v [unit] at p drawn at `scale` per unit, its tail on p
 * (head = 0) or its head on p (head = 1, a load pushing on the body);
 * value |v|.  style as mm_sta_line. */
int mm_sta_line3(mm_result *res, const char *name, const double *a, const double *b, const char *style);
int mm_sta_arrow3(mm_result *res, const char *name, const double *p, const double *v, double scale, int head,
                  const char *unit, const char *style);

/* A text at the point p in space (mm_sta_project). */
int mm_sta_label3(mm_result *res, const double *p, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* The axes x, y, z drawn from O, len long, each with its name at its tip. */
int mm_sta_axes3(mm_result *res, const double *O, double len);

/* A closed body of n vertices in space (rows x, y, z), projected. */
int mm_sta_polygon3(mm_result *res, const char *name, int n, const double *xyz, const char *style);

/* ---- answers and checks: the idioms of the chapter ---------------------------------- */

/* A matrix parameter v (named param) must have rows of `cols` numbers (an
 * empty one passes: the server lets only a matrix whose default is empty
 * be empty): MM_OK, or MM_ERANGE with "each <what> is one row <row>; got
 * <n> numbers". */
int mm_sta_rows(const mm_value *v, const char *param, const char *what, const char *row, int cols, mm_error *err);

/* A force within its rounding error err of zero is zero (a zero-force
 * member, a reaction the loads do not need): v, or 0 when |v| <= err, so
 * that the answer prints 0, not the rounding noise. */
double mm_sta_shown(double v, double err);

/* Support reactions or member forces R[0..n-1] with the error estimate
 * rerr (cond x eps of the loads): the scalars out_1..out_n, a value within
 * rerr of zero printed as 0, and the series out_plot (x = 1..n) of the
 * same.  R itself is left as it is.  Returns the largest |R[k]| (the series
 * lost to memory is recorded in res). */
double mm_sta_reactions(mm_result *res, int out, int out_plot, int n, const double *R, double rerr);

/* A check against ref within the absolute tolerance tol (mm_res_check_abs)
 * whose name is printf-formatted, for names that say which member, link or
 * cable was the worst.  Returns MM_OK or MM_ENOMEM (sticky, in res). */
int mm_sta_check_absf(mm_result *res, double value, double ref, double tol, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 5, 6)))
#endif
    ;

/* The index of the largest |a[k] - b[k]| over n >= 1 values, the check
 * that names the worst of several: the last of equal ones when last, else
 * the first (0 when none is a number). */
int mm_sta_worst(int n, const double *a, const double *b, int last);

/* Why mm_equil_solve found the links of a body singular (MM_ESINGULAR with
 * the result r, the free motion mech and the self-stress self it returned),
 * in mechanics words: the motion the n links allow (in the plane: the
 * point the body can turn about, or the direction it can slide in, from
 * mech = (vx, vy of the origin, turn w); in space: the axis it can turn
 * about, or the direction it can slide in, from mech = (v of the origin,
 * angular velocity w)), else the link that is redundant (the largest
 * |self|).  Fills err (param "links"); returns MM_ESINGULAR. */
int mm_sta_improper2(const mm_equil_result *r, int n, const double *mech, const double *self, mm_error *err);
int mm_sta_improper3(const mm_equil_result *r, int n, const double *mech, const double *self, mm_error *err);

/* Equilibria marked on a plot of the potential: the n points (x[i], y[i])
 * of kind k (kind[i] = k, 0 <= k < nk) as the series outs[k], made in the
 * order of k and only for a kind that has points.  Returns MM_OK or
 * MM_ENOMEM. */
int mm_sta_equilibria(mm_result *res, int n, const double *x, const double *y, const int *kind, int nk,
                      const int *outs);

/* The truss's answer as tables: the members (number, force shown to
 * ferr, joints, length, state: tension or compression beyond ftol, else
 * zero-force) into the table out_members and the series out_plot (force
 * against member number), the supports' reactions into the table
 * out_react.  Returns MM_OK or MM_ENOMEM. */
int mm_sta_truss_tables(mm_result *res, const mm_truss *t, const double *F, const double *R, double ferr,
                        double ftol, int out_members, int out_plot, int out_react);

/* ---- the standard figures of the exercises ------------------------------------------ */

/* n support links (rows x, y, dx, dy in the plane; x, y, z, dx, dy, dz in
 * space) of a body of the given size: each link a short stroke on the side
 * its reaction R[k] (along the direction) pushes from, the reaction drawn
 * at sc m/N unless it is 0, and its label Rk. */
int mm_sta_links2(mm_result *res, int n, const double *links, const double *R, double size, double sc);
int mm_sta_links3(mm_result *res, int n, const double *links, const double *R, double size, double sc);

/* n loads (rows x, y, Fx, Fy) pushing on a body, at sc m/N. */
int mm_sta_loads2(mm_result *res, int n, const double *loads, double sc);

/* A three-hinged frame of span `size` taken apart at its crown hinge C:
 * the left body from A to C, the right one from C to B moved right by a
 * gap of 0.08 size, pins at A and B, the reactions R[0..3] (Ax, Ay, Bx, By)
 * and the pin force R[4..5] on the left body (its opposite on the right
 * one), the n loads (rows x, y, Fx, Fy; those right of C moved with the
 * right body), all at sc m/N, and the labels A, B, C. */
int mm_sta_frame_apart(mm_result *res, const double *A, const double *B, const double *C, const double *R, int n,
                       const double *loads, double size, double sc);

/* A ring at `ring` held by n cables to the anchors (rows x, y, z) in space,
 * u[i] the unit vector from the ring to anchor i: each cable coloured by its
 * tension T[i] (within tol of 0: no colour), a small block at its anchor,
 * its pull on the ring when T[i] > 0 and its label; the ring and the load
 * P on it, drawn to the size of the longest cable; Fmax, the largest
 * force, 0.4 of it long. */
int mm_sta_cables3(mm_result *res, int n, const double *ring, const double *anchors, const double *T,
                   const double (*u)[3], const double *P, double Fmax, double tol);

/* A belt on a drum of radius r wrapped over theta (at most one turn shown,
 * symmetric about the top): the belt, the slack-side tension T1 and the
 * tight-side T2 along the tangents where it leaves, and the torque on the
 * drum as a couple. */
int mm_sta_belt(mm_result *res, double T1, double T2, double theta, double r, double torque);

/* A slider-crank held by a torque: pivot O at the origin, the crank r at
 * angle th to the pin A, the rod l (axial force Frod, zero within ftol) to
 * the slider B = (xb, e) on its guide y = e, the load P on the slider
 * along -x, the torque M on the crank and the virtual displacement
 * dx_B/dtheta = dx drawn beside the slider; the label M = P dx_B/dtheta. */
int mm_sta_slider_crank(mm_result *res, double r, double l, double e, double th, double xb, double Frod,
                        double ftol, double P, double M, double dx);

/* A force system in space and its simplest equivalent: the n forces (rows
 * x, y, z, Fx, Fy, Fz) as arrows from their points; for kind 2 or 3 (a
 * single force, a wrench) the resultant R at P on its central axis, and
 * for 3 the wrench's couple pitch R along it; for kind 1 (a couple) the
 * couple M at O; the label "O: what".  reach (the largest distance of a
 * force from O, at least 1e-3 m) sets the size. */
int mm_sta_reduced3(mm_result *res, int n, const double *forces, const double *O, const double *R, const double *M,
                    const double *P, double pitch, int kind, double reach, const char *what);

/* An area: the polygon of n vertices xy, the nd discs (rows x, y, r; r < 0
 * a hole), the principal axes 1 and 2 of p through its centroid C, C
 * itself, and the weight of a uniform plate of this shape acting at C
 * (per unit areal weight: the arrow's value is the area). */
int mm_sta_area(mm_result *res, int n, const double *xy, int nd, const double *discs, const mm_section_props *p);

/* A block w long and h high on an incline at angle a, pushed up the slope
 * by P at height hP on its lower face: the incline, the block, its weight
 * W, the push, the normal force N at xn along its base and the friction F
 * there (down the slope when positive; none when 0), all at the limit,
 * and the label "what at P = ...". */
int mm_sta_block_incline(mm_result *res, double a, double w, double h, double hP, double W, double P, double N,
                         double F, double xn, const char *what);

/* A wedge of angle be driven by Pin under a load W that a wall guides:
 * floor, wall, wedge, load, the push, the weight and the normal forces
 * N[0] (floor on wedge), N[1] (wedge on load), N[2] (wall on load); the
 * label gives Pin and Pout. */
int mm_sta_wedge(mm_result *res, double be, double W, double Pin, double Pout, const double *N);

/* A rod L long hinged at its foot, tilted by q from upright, a weight W at
 * its top and a horizontal spring k at height a whose far end slides in a
 * vertical guide: hinge, rod, guide, spring, the weight, the spring force
 * (when tilted) and the hinge reaction; the label "theta = q (what)". */
int mm_sta_rod_spring(mm_result *res, double L, double a, double k, double W, double q, const char *what);

/* A beam with its supports (pin and roller, or a clamp), the reactions
 * of b, the point loads, the distributed loads (their outline and arrows),
 * the couples, and the labels: the extreme moment Mext at xM and the sign
 * conventions. */
int mm_sta_beam(mm_result *res, const mm_beam_problem *p, const mm_beam *b, double Mext, double xM);

/* The diagrams of b as series of about n points (mm_beam_sample: every
 * jump by both its one-sided values): V into out_V, M into out_M and, when
 * with_y, the deflection into out_y.  Returns MM_OK or MM_ENOMEM. */
int mm_sta_beam_diagrams(mm_result *res, const mm_beam *b, int n, int with_y, int out_V, int out_M, int out_y);

/* A plane truss: each member coloured by its force F[e] (tension,
 * compression, or none within ftol), pins and rollers at the supports with
 * the reactions R[2 n_nodes] larger than ftol, the loads, and the joints'
 * numbers; forces drawn so that the largest of pmax (largest load) and
 * the reactions is 0.2 of the truss's extent. */
int mm_sta_truss(mm_result *res, const mm_truss *t, const double *F, const double *R, double pmax, double ftol);

/* ---- references and vectors --------------------------------------------------------- */

/* The textbooks the chapter cites, to be followed by the section:
 * MM_STA_HIBBELER "section 8.6". */
#define MM_STA_HIBBELER "R. C. Hibbeler, Engineering Mechanics: Statics, 14th ed., Pearson 2016, "
#define MM_STA_MERIAM "J. L. Meriam, L. G. Kraige, Engineering Mechanics: Statics, 8th ed., Wiley 2015, "

/* Vectors in space as three doubles: c = a x b (c must not alias a or b),
 * a . b and |a|. */
void mm_sta_cross(const double *a, const double *b, double *c);
double mm_sta_dot(const double *a, const double *b);
double mm_sta_norm(const double *a);

#endif
