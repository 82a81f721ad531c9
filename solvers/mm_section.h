/* mm_section.h — plane areas: polygons, triangles, discs and composites of
 * them; area, centroid, second moments about centroidal axes, principal
 * moments and axes; the test that a polygon is simple (does not cross or
 * touch itself) and its triangulation.
 *
 * Definitions (A the region, (xc, yc) its centroid):
 *   A   = integral dA,    xc = (1/A) integral x dA,   yc = (1/A) integral y dA,
 *   Ixx = integral (y - yc)^2 dA   (about the centroidal axis parallel to x),
 *   Iyy = integral (x - xc)^2 dA,  Ixy = integral (x - xc)(y - yc) dA,
 *   I(t) about the centroidal axis at angle t from x:
 *         Ixx cos^2 t - 2 Ixy sin t cos t + Iyy sin^2 t,
 *   I1 >= I2 its largest and smallest values, alpha in (-pi/2, pi/2] the
 *   angle of the I1 axis: tan 2 alpha = -2 Ixy / (Ixx - Iyy).
 *
 * Polygons are given as n vertices (x, y), in either orientation, without
 * repeating the first at the end.  Their integrals come from Green's
 * theorem over the edges (exact for straight edges), in coordinates
 * relative to the mean vertex so that a polygon far from the origin loses
 * no digits to cancellation.
 *
 * No globals; arrays belong to the caller; scratch on the stack up to
 * MM_SECTION_MAX_VERTICES.
 */
#ifndef MM_SECTION_H
#define MM_SECTION_H

#include "mm_status.h"

#define MM_SECTION_MAX_VERTICES 500

typedef struct mm_section_props {
    double A;                  /* area [m^2], > 0 for a region (a hole: subtracted when combined) */
    double xc, yc;             /* centroid [m] */
    double Ixx, Iyy, Ixy;      /* centroidal second moments [m^4] (definitions above) */
    double I1, I2, alpha;      /* principal moments [m^4] and the I1 axis angle [rad] */
} mm_section_props;

/* Why a polygon is not simple: the two edges (0-based: edge k runs from
 * vertex k to vertex k+1 mod n) that cross or touch, and a point where they
 * meet; or, for a repeated vertex, e1 = e2 = that vertex. */
typedef struct mm_section_fault {
    int e1, e2;
    double x, y;
} mm_section_fault;

/* 1 when the polygon is simple: at least 3 vertices, no two consecutive
 * vertices at the same point, no two edges that cross or touch other than
 * neighbours at their shared vertex, no edge folding back along the
 * previous one, and a nonzero area.  0 otherwise, with fault filled (may
 * be NULL).  O(n^2).  Cannot fail otherwise. */
int mm_section_simple(int n, const double *xy, mm_section_fault *fault);

/* The properties of a simple polygon by Green's theorem; *orientation
 * (may be NULL) receives +1 for counter-clockwise vertices, -1 for
 * clockwise.  Fails with MM_ERANGE (param "polygon") when n is outside
 * 3..MM_SECTION_MAX_VERTICES or the polygon is not simple (the message
 * names the edges and where they meet), MM_EVALUE for a non-finite
 * coordinate. */
int mm_section_polygon(int n, const double *xy, mm_section_props *p, int *orientation, mm_error *err);

/* Triangulate a simple polygon by ear clipping into n - 2 triangles:
 * tri[3 k .. 3 k + 2] are vertex indices, counter-clockwise.  Returns the
 * number of triangles, or -1 when no ear is found (a polygon that is not
 * simple, or one so thin that rounding hides its ears).  O(n^3) at worst. */
int mm_section_triangulate(int n, const double *xy, int *tri);

/* A triangle's properties in closed form (centroid the mean of the
 * vertices, Ixx = A/12 sum (y_i - yc)^2, Ixy = A/12 sum (x_i - xc)(y_i - yc));
 * A is positive whatever the vertex order.  Cannot fail. */
void mm_section_triangle(const double *p0, const double *p1, const double *p2, mm_section_props *p);

/* A disc of radius r > 0 centred at (x, y): A = pi r^2, Ixx = Iyy = pi r^4 / 4,
 * Ixy = 0.  Cannot fail. */
void mm_section_disc(double x, double y, double r, mm_section_props *p);

/* The composite of n parts, part k added (sign[k] = +1) or cut out
 * (sign[k] = -1, a hole): areas and first moments add, second moments move
 * to the composite centroid by the parallel-axis theorem.  The composite's
 * principal values are filled.  Fails with MM_ERANGE (param "circles")
 * when the net area is not positive. */
int mm_section_combine(int n, const mm_section_props *part, const int *sign, mm_section_props *out,
                       mm_error *err);

/* I1, I2 and alpha from Ixx, Iyy, Ixy (a product below 64 eps of
 * Ixx + Iyy counts as zero, so symmetric shapes get alpha 0 or pi/2, not
 * a rounding accident).  Cannot fail. */
void mm_section_principal(mm_section_props *p);

/* 1 when (x, y) is strictly inside the polygon (crossing number), 0
 * otherwise; the distance from (x, y) to the nearest edge into *dist (may
 * be NULL).  Cannot fail. */
int mm_section_inside(int n, const double *xy, double x, double y, double *dist);

/* ---- statics (chapter 3): a polygon with discs added or cut out ------------- */

#define MM_SECTION_MAX_DISCS 100

/* The n_disc discs (rows x, y, r) of a composite made on a simple polygon
 * of n vertices: r > 0 a disc added outside the polygon, r < 0 a hole of
 * radius |r| cut inside it; no two may overlap (their areas would count
 * twice).  MM_OK, or MM_ERANGE (param "circles") naming the first fault in
 * row order: a radius 0, a hole that reaches past an edge (and by how
 * much), a disc that reaches into the polygon, two discs that overlap. */
int mm_section_discs_check(int n, const double *xy, int n_disc, const double *disc, mm_error *err);

/* The composite of the region poly (a polygon's properties, or any) with
 * the n_disc <= MM_SECTION_MAX_DISCS discs (rows x, y, r as above) added
 * or cut out, by mm_section_combine.  Fails as it does (err may be NULL),
 * or with MM_ERANGE (param "circles") for too many discs. */
int mm_section_with_discs(const mm_section_props *poly, int n_disc, const double *disc, mm_section_props *out,
                          mm_error *err);

#endif
