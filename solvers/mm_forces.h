/* mm_forces.h — a system of forces and couples in space summed about a
 * point: the resultant force R = sum F_i and the resultant moment
 *
 *     M_B = sum (r_i - B) x F_i + sum C_j,
 *
 * with the sizes of the terms that were summed (what the rounding of R and
 * M is measured against).  Pure function of its arguments: thread-safe,
 * no allocation, cannot fail.
 */
#ifndef MM_FORCES_H
#define MM_FORCES_H

typedef struct mm_forces_sum {
    double R[3];      /* sum of the forces */
    double M[3];      /* the moment about B, eq. above */
    double sum_F;     /* sum of |F_i| */
    double sum_M;     /* sum of |r_i - B| |F_i| and of |C_j|: the size of M's terms */
    double reach;     /* largest |r_i - B| (0 without forces) */
} mm_forces_sum;

/* n forces (rows x, y, z, Fx, Fy, Fz) and nc couples (rows Cx, Cy, Cz)
 * about the point B.  Each component is summed in row order, forces before
 * couples. */
void mm_forces_resultant(int n, const double *forces, int nc, const double *couples, const double B[3],
                         mm_forces_sum *s);

#endif
