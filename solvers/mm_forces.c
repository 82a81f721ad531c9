/* mm_forces.c — force systems summed about a point (see mm_forces.h). */
#include "mm_forces.h"

#include <math.h>

#include "mm_geom.h"

void mm_forces_resultant(int n, const double *forces, int nc, const double *couples, const double B[3],
                         mm_forces_sum *s)
{
    *s = (mm_forces_sum){{0, 0, 0}, {0, 0, 0}, 0, 0, 0};
    for (int i = 0; i < n; i++) {
        const double *f = forces + 6 * i;
        mm_v3 w = {f[0] - B[0], f[1] - B[1], f[2] - B[2]}, F = {f[3], f[4], f[5]}, m = mm_v3_cross(w, F);
        s->R[0] += F.x, s->R[1] += F.y, s->R[2] += F.z;
        s->M[0] += m.x, s->M[1] += m.y, s->M[2] += m.z;
        s->sum_F += mm_v3_norm(F);
        s->sum_M += mm_v3_norm(w) * mm_v3_norm(F);
        s->reach = fmax(s->reach, mm_v3_norm(w));
    }
    for (int j = 0; j < nc; j++) {
        const double *c = couples + 3 * j;
        mm_v3 C = {c[0], c[1], c[2]};
        s->M[0] += C.x, s->M[1] += C.y, s->M[2] += C.z;
        s->sum_M += mm_v3_norm(C);
    }
}
