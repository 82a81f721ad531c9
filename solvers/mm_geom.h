/* mm_geom.h — planar and spatial geometry for kinematics and statics:
 * vectors, rotation matrices, Euler angles (with gimbal lock), the
 * intersections that close a linkage (circle-circle, line-circle,
 * line-line), the circle through three points, and a polygon's area,
 * centroid and second moments.
 *
 * Conventions, once for all:
 *   - SI units; angles in radians, counter-clockwise positive (planar), right
 *     hand rule (spatial).
 *   - A 3x3 matrix is 9 doubles, ROW-MAJOR: R(i,j) = R[3*i + j].  A rotation
 *     matrix maps body components to space components: v_space = R v_body.
 *   - Euler angles are INTRINSIC (each rotation about an axis of the frame
 *     already turned): sequence (i, j, k) with angles (a, b, c) gives
 *     R = R_i(a) R_j(b) R_k(c), axes numbered 0 = x, 1 = y, 2 = z.  With
 *     i == k it is a proper Euler sequence (z-y-z, z-x-z, ...), with i, j, k
 *     all different a Tait-Bryan one (z-y-x is yaw, pitch, roll).
 *   - No globals, no allocation, nothing fails but where a status is
 *     returned; safe from any number of threads.
 *
 * References: J. J. Craig, Introduction to Robotics, 3rd ed., ch. 2 and
 * appendix B (Euler angle sets); K. Shoemake, "Euler angle conversion",
 * Graphics Gems IV, 1994 (the one routine for all twelve sequences);
 * E. J. Haug, Computer Aided Kinematics and Dynamics of Mechanical Systems,
 * 1989, ch. 6 (angular velocity from Euler angle rates).
 */
#ifndef MM_GEOM_H
#define MM_GEOM_H

#include <math.h>

#include "mm_status.h"

/* ---- vectors ----------------------------------------------------------------- */

typedef struct mm_v2 {
    double x, y;
} mm_v2;

typedef struct mm_v3 {
    double x, y, z;
} mm_v3;

static inline mm_v2 mm_v2_make(double x, double y) { return (mm_v2){x, y}; }
static inline mm_v2 mm_v2_add(mm_v2 a, mm_v2 b) { return (mm_v2){a.x + b.x, a.y + b.y}; }
static inline mm_v2 mm_v2_sub(mm_v2 a, mm_v2 b) { return (mm_v2){a.x - b.x, a.y - b.y}; }
static inline mm_v2 mm_v2_scale(mm_v2 a, double s) { return (mm_v2){s * a.x, s * a.y}; }
static inline double mm_v2_dot(mm_v2 a, mm_v2 b) { return a.x * b.x + a.y * b.y; }
/* the z-component of a x b */
static inline double mm_v2_cross(mm_v2 a, mm_v2 b) { return a.x * b.y - a.y * b.x; }
static inline double mm_v2_norm(mm_v2 a) { return hypot(a.x, a.y); }
/* a turned by +90 degrees: k x a */
static inline mm_v2 mm_v2_perp(mm_v2 a) { return (mm_v2){-a.y, a.x}; }
/* the unit vector at angle theta from x */
static inline mm_v2 mm_v2_polar(double r, double theta) { return (mm_v2){r * cos(theta), r * sin(theta)}; }
/* a turned by theta */
static inline mm_v2 mm_v2_rotate(mm_v2 a, double theta)
{
    double c = cos(theta), s = sin(theta);
    return (mm_v2){c * a.x - s * a.y, s * a.x + c * a.y};
}

static inline mm_v3 mm_v3_make(double x, double y, double z) { return (mm_v3){x, y, z}; }
static inline mm_v3 mm_v3_add(mm_v3 a, mm_v3 b) { return (mm_v3){a.x + b.x, a.y + b.y, a.z + b.z}; }
static inline mm_v3 mm_v3_sub(mm_v3 a, mm_v3 b) { return (mm_v3){a.x - b.x, a.y - b.y, a.z - b.z}; }
static inline mm_v3 mm_v3_scale(mm_v3 a, double s) { return (mm_v3){s * a.x, s * a.y, s * a.z}; }
static inline double mm_v3_dot(mm_v3 a, mm_v3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline mm_v3 mm_v3_cross(mm_v3 a, mm_v3 b)
{
    return (mm_v3){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
static inline double mm_v3_norm(mm_v3 a) { return sqrt(a.x * a.x + a.y * a.y + a.z * a.z); }

/* ---- 3x3 matrices and rotations ------------------------------------------------ */

/* C = A B.  C may be the same array as A or B.  Cannot fail. */
void mm_geom_m3_mul(const double A[9], const double B[9], double C[9]);

/* T = A^T.  T may be A.  Cannot fail. */
void mm_geom_m3_transpose(const double A[9], double T[9]);

/* A v.  Cannot fail. */
mm_v3 mm_geom_m3_apply(const double A[9], mm_v3 v);

/* det A.  Cannot fail. */
double mm_geom_m3_det(const double A[9]);

/* The rotation by angle about coordinate axis 0 (x), 1 (y) or 2 (z).
 * Cannot fail (axis is asserted). */
void mm_geom_rot_axis(int axis, double angle, double R[9]);

/* The rotation by angle about the direction u (Rodrigues' formula,
 * R = I + sin(angle) [u]x + (1 - cos(angle)) [u]x^2 with u normalised).
 * MM_EVALUE ("axis") when u is zero or not finite; R is then left alone. */
int mm_geom_rot_axis_angle(mm_v3 u, double angle, double R[9], mm_error *err);

/* The axis (unit) and angle in [0, pi] of the rotation R (the inverse of
 * mm_geom_rot_axis_angle), accurate also near angle = 0 (the axis is then
 * ill-determined: any unit vector is returned for R = I) and near pi.
 * R is assumed orthogonal.  Cannot fail. */
void mm_geom_rot_log(const double R[9], mm_v3 *axis, double *angle);

/* How far R is from a rotation: max |(R^T R - I)_ij|, and det R - 1 into
 * *det_err (may be NULL).  Cannot fail. */
double mm_geom_rot_orth_error(const double R[9], double *det_err);

/* [w]x, the matrix of the cross product w x (.), and back: the w of a skew
 * matrix S (from its antisymmetric part, (S - S^T)/2).  Cannot fail. */
void mm_geom_skew(mm_v3 w, double S[9]);
mm_v3 mm_geom_unskew(const double S[9]);

/* ---- Euler angles ---------------------------------------------------------------- */

/* A sequence of three axes (i, j, k), i != j, j != k: proper Euler when
 * i == k, Tait-Bryan when all differ.  mm_geom_euler_check says whether
 * seq is one. */
int mm_geom_euler_check(const int seq[3]);

/* R = R_i(a) R_j(b) R_k(c) for ang = (a, b, c).  Cannot fail. */
void mm_geom_euler_matrix(const int seq[3], const double ang[3], double R[9]);

/* The angles of R in the sequence seq:
 *   proper Euler:  b in [0, pi],          a, c in (-pi, pi];
 *   Tait-Bryan:    b in [-pi/2, pi/2],    a, c in (-pi, pi].
 * Gimbal lock is where the first and third axes line up: sin b = 0
 * (proper) or cos b = 0 (Tait-Bryan).  There only a + c or a - c is
 * determined; when the lock measure (|sin b| or |cos b|) is below
 * lock_tol the function sets c = 0, puts the whole turn into a and
 * returns 1; otherwise it returns 0.  *cond (may be NULL) receives
 * 1 / (lock measure): near the lock, a and c carry errors of about
 * cond * DBL_EPSILON (they are ill-conditioned functions of R).
 * R is assumed a rotation; seq must pass mm_geom_euler_check. */
int mm_geom_euler_angles(const int seq[3], const double R[9], double ang[3], double lock_tol,
                         double *cond);

/* The matrix B with omega = B (a', b', c'): the angular velocity of the
 * turning frame from the angle rates, in SPACE components (omega_space)
 * when body == 0, in BODY components (R^T omega_space) when body == 1.
 * Its columns are the three rotation axes as they stand; det B is
 * +-sin b (proper) or +-cos b (Tait-Bryan), zero at gimbal lock, where the
 * rates cannot be recovered from omega.  Cannot fail. */
void mm_geom_euler_rates(const int seq[3], const double ang[3], int body, double B[9]);

/* ---- intersections in the plane --------------------------------------------------- */

/* The points at distance r1 from c1 and r2 from c2.  p[0] lies to the
 * LEFT of the directed line c1 -> c2, p[1] to the right.  Returns 2, 1
 * (tangent circles: p[0] = p[1], the discriminant is zero to within
 * rounding, see below) or 0 (apart, nested or concentric; p untouched).
 * *disc (may be NULL) receives the discriminant 4 d^2 h^2 =
 * ((r1+r2)^2 - d^2) (d^2 - (r1-r2)^2), d = |c2 - c1|, h the half chord,
 * computed as a product of sums and differences so that it keeps its
 * relative accuracy near tangency; negative when the circles miss.  It
 * counts as zero when |disc| <= 2 eps (r1 + r2 + d)^4 (its rounding error
 * is below a quarter of that).  Cannot fail. */
int mm_geom_circle_circle(mm_v2 c1, double r1, mm_v2 c2, double r2, mm_v2 p[2], double *disc);

/* The parameters t of the points p0 + t u (u != 0, any length) on the
 * circle of centre c and radius r, t[0] <= t[1] (stable quadratic
 * formula).  Returns 2, 1 (tangent within rounding: t[0] = t[1]) or 0
 * (the line misses: t untouched).  *disc (may be NULL) receives
 * r^2 - (distance of c from the line)^2, negative when it misses. */
int mm_geom_line_circle(mm_v2 p0, mm_v2 u, mm_v2 c, double r, double t[2], double *disc);

/* The intersection x of the lines p1 + s u1 and p2 + t u2.  Returns 1, or
 * 0 when they are parallel (|u1 x u2| <= 8 eps |u1| |u2|; x untouched).
 * Cannot fail. */
int mm_geom_line_line(mm_v2 p1, mm_v2 u1, mm_v2 p2, mm_v2 u2, mm_v2 *x);

/* The circle through a, b, c: its centre and radius.  Returns 1, or 0
 * when the points are collinear (within rounding: the radius would pass
 * 1e15 times the largest side; centre and radius untouched).  Used to
 * measure a curve's radius of curvature from three close points. */
int mm_geom_circumcircle(mm_v2 a, mm_v2 b, mm_v2 c, mm_v2 *centre, double *radius);

/* A bound of how far the radius mm_geom_circumcircle gives for a, b, c can
 * be from the radius of the circle through the exact points, each known
 * within ea, eb, ec (componentwise: |x error| <= e.x, |y error| <= e.y):
 * the points' errors through the radius's gradient (first order, 1.01 of
 * it), plus its own rounding, measured against the same operations in
 * double-double.  Through close points on a curve that gradient is
 * lopsided: R ~ s^2 / (2 sagitta) for points s apart, so an error d across
 * the curve moves R by about d R^2 / s^2, one along it by d R / s only.
 * Returns +inf for points mm_geom_circumcircle finds collinear.  Cannot
 * fail. */
double mm_geom_circumradius_err(mm_v2 a, mm_v2 b, mm_v2 c, mm_v2 ea, mm_v2 eb, mm_v2 ec);

/* ---- a parametric curve: derivatives and curvature ---------------------------------- */

/* The k components of a curve at t into out (k <= MM_GEOM_CURVE_MAX).
 * Return 0, or an MM_E* code to stop. */
typedef int (*mm_geom_curve_fn)(double t, double *out, void *params);

#define MM_GEOM_CURVE_MAX 3
#define MM_GEOM_RIDDERS_LEVELS 10   /* steps h0, h0/1.4, ..., 20 evaluations besides f(t) */

/* First and second derivatives of the k components of f at t, by
 * Ridders' extrapolation of central differences (W. H. Press et al.,
 * Numerical Recipes, 3rd ed., section 5.7, dfridr): the differences
 *     D1(h) = (f(t+h) - f(t-h)) / (2h),  D2(h) = (f(t+h) - 2 f(t) + f(t-h)) / h^2,
 * both even in h, are taken at h0, h0/1.4, h0/1.4^2, ... and extrapolated
 * to h = 0 in a Neville table; the entry whose difference from its
 * neighbours is smallest is returned, and 4 times that difference is its
 * error estimate e1 (e2) (dfridr's own stopping rule waits for four
 * columns: earlier, a chance agreement of two extrapolations could stop it
 * with errors 30 times its estimate): an ESTIMATE, usually pessimistic by
 * a factor 1-100,
 * to which the rounding of the differences at the step used is added
 * (that of f's values, and |f'| eps |t| from rounding t +- h).  h0 should be a step over
 * which the curve changes appreciably (a tenth of its time scale).  d2 and
 * e2 may be NULL.  Fails with MM_ENONFINITE ("t") when f is not finite at a
 * point it needed, or f's own code. */
int mm_geom_curve_derivs(mm_geom_curve_fn f, void *params, int k, double t, double h0, double *d1,
                         double *e1, double *d2, double *e2, mm_error *err);

/* Curvature of a plane curve from its first and second derivatives:
 * kappa = (v x a) / |v|^3, signed (positive turning left).  Returns 0 when
 * v = 0 (a cusp: no curvature).  Cannot fail. */
double mm_geom_curvature(mm_v2 v, mm_v2 a);

/* ---- polygons --------------------------------------------------------------------- */

typedef struct mm_geom_polygon_props {
    double area;      /* > 0 whichever the orientation [m^2] */
    double xc, yc;    /* centroid [m] */
    double Ixx, Iyy, Ixy; /* second moments about centroidal axes parallel to x, y [m^4]:
                             Ixx = int (y - yc)^2 dA, Ixy = int (x - xc)(y - yc) dA */
    int orientation;  /* +1 counter-clockwise, -1 clockwise */
} mm_geom_polygon_props;

/* Area, centroid and second moments of the simple polygon with n >= 3
 * vertices xy[2*i], xy[2*i + 1] (Green's theorem over its edges, taken
 * about the first vertex to keep the digits of far-off polygons).
 * MM_EVALUE ("polygon") when n < 3, a coordinate is not finite or the area
 * is zero.  Self-intersection is not detected (check it beforehand). */
int mm_geom_polygon(const double *xy, int n, mm_geom_polygon_props *p, mm_error *err);

/* The standard Denavit-Hartenberg transform of a joint angle th, link
 * length a and twist al: Rz(th) Tx(a) Rx(al) as [R | p], row-major 3 x 4. */
void mm_geom_dh(double th, double a, double al, double T[12]);

/* C = A B for transforms [R | p] stored row-major 3 x 4; C may alias A or B. */
void mm_geom_frame_mul(const double A[12], const double B[12], double C[12]);

/* ---- added for the kinematics chapter ------------------------------------------------ */

/* The rotation matrix of the Euler angles ang about the axes seq (as
 * mm_geom_euler_matrix) built the other way: the product of the three
 * unit quaternions q_i(a) q_j(b) q_k(c), q_i(a) = (cos a/2, sin a/2 e_i),
 * turned into a matrix.  An independent construction to check
 * mm_geom_euler_matrix against.  Cannot fail. */
void mm_geom_euler_quat_matrix(const int seq[3], const double ang[3], double R[9]);

/* The largest entry of |A - B| (0 for equal matrices; NaN entries are
 * skipped, as fmax does).  Cannot fail. */
double mm_geom_m3_maxdiff(const double A[9], const double B[9]);

/* The length of one arch of the trochoid traced by a point at distance
 * b >= 0 from the centre of a circle of radius R > 0 rolling on a line:
 * |dP/dphi| = sqrt((R - b)^2 + 4 R b sin^2(phi/2)) integrated over a
 * turn, as twice the integral over [0, pi] by 5-point Gauss-Legendre on
 * 49 panels that halve towards phi = 0 (where, for b near R, the
 * integrand has a near-corner of width |R - b| / sqrt(R b); a corner for
 * the cycloid), each panel cut in two: the value returned.  *err (if not
 * NULL) gets the sum over the panels of |Q2 - Q1| + 2 |Q4 - Q2|, Qm the
 * panel cut in m: an estimate of the error, larger by about 2^10 where
 * the rule has reached its order.  The second term covers a panel where
 * Q1 errs like Q2 by chance (at b = 7.913 R on [pi/2, pi], both by
 * -1.7e-14 L).  Summed panel by panel, not
 * as the difference of the two totals, because the panels' errors have
 * either sign: at b = 2.5837 R the whole-panel rule errs -4.4e-12 L and
 * +4.6e-12 L on [pi/2, pi] and [pi/4, pi/2], so the two totals agree to
 * 3e-15 L while the halved rule errs 1.6e-13 L.  The closed form is
 * 4 (R + b) E(k), k = 2 sqrt(R b) / (R + b) (mm_elliptic_E); 8 R for the
 * cycloid.  Cannot fail. */
double mm_geom_trochoid_arch(double R, double b, double *err);

/* ---- statics (chapter 3) ------------------------------------------------------ */

/* The angle in [0, pi] between the vectors a and b (three doubles each, not
 * both zero) as atan2(|a x b|, a . b): accurate near 0 and pi, where acos
 * of the cosine loses half the digits (while |a x b|^2 stays a normal
 * double: for unit vectors, angles above 1e-154).  Cannot fail. */
double mm_geom_angle3(const double a[3], const double b[3]);

#endif
