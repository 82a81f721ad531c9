/* mm_natural.c — a planar linkage in natural coordinates (see mm_natural.h). */
#include "mm_natural.h"

#include <math.h>
#include <string.h>

void mm_nat_init(mm_nat_model *m, const mm_nat_linkage *s, int driven, double *q)
{
    *m = (mm_nat_model){.s = s, .y_slide = s->slide >= 0 ? s->p[s->slide][1] : 0, .driven = driven};
    for (int k = 0; k < s->ncon; k++) {
        double dx = s->p[s->con[k][0]][0] - s->p[s->con[k][1]][0], dy = s->p[s->con[k][0]][1] - s->p[s->con[k][1]][1];
        m->L2[k] = dx * dx + dy * dy;
    }
    for (int k = 0; k < s->ndrv; k++)
        m->th0[k] = atan2(s->p[s->drv[k][1]][1] - s->p[s->drv[k][0]][1], s->p[s->drv[k][1]][0] - s->p[s->drv[k][0]][0]);
    for (int i = s->nfix; q && i < s->npts; i++)
        q[2 * (i - s->nfix)] = s->p[i][0], q[2 * (i - s->nfix) + 1] = s->p[i][1];
}

/* q holds the moving points' x, y: point i >= nfix at q[2 (i - nfix)] */
void mm_nat_point(const mm_nat_model *m, const double *q, int i, double *x, double *y)
{
    if (i < m->s->nfix)
        *x = m->s->p[i][0], *y = m->s->p[i][1];
    else
        *x = q[2 * (i - m->s->nfix)], *y = q[2 * (i - m->s->nfix) + 1];
}

static double drive(const mm_nat_model *m, int k, double t)
{
    double a = m->s->amp;
    return m->th0[k] + (a > 0 ? a * sin(t) : t);
}

static int phi_fn(const double *q, double t, double *F, void *ctx)
{
    const mm_nat_model *m = ctx;
    const mm_nat_linkage *s = m->s;
    int r = 0;
    for (int k = 0; k < s->ncon; k++) {
        double xi, yi, xj, yj;
        mm_nat_point(m, q, s->con[k][0], &xi, &yi), mm_nat_point(m, q, s->con[k][1], &xj, &yj);
        F[r++] = (xi - xj) * (xi - xj) + (yi - yj) * (yi - yj) - m->L2[k];
    }
    if (s->slide >= 0)
        F[r++] = q[2 * (s->slide - s->nfix) + 1] - m->y_slide;
    for (int k = 0; m->driven && k < s->ndrv; k++) {
        double xo, yo, xa, ya, th = drive(m, k, t);
        mm_nat_point(m, q, s->drv[k][0], &xo, &yo), mm_nat_point(m, q, s->drv[k][1], &xa, &ya);
        F[r++] = (xa - xo) * sin(th) - (ya - yo) * cos(th);      /* A on the ray at th */
    }
    return 0;
}

static int jac_fn(const double *q, double t, double *J, void *ctx)
{
    const mm_nat_model *m = ctx;
    const mm_nat_linkage *s = m->s;
    int n = 2 * (s->npts - s->nfix), r = 0;
    int rows = s->ncon + (s->slide >= 0) + (m->driven ? s->ndrv : 0);
    memset(J, 0, (size_t)rows * (size_t)n * sizeof *J);
    for (int k = 0; k < s->ncon; k++, r++) {
        int i = s->con[k][0], j = s->con[k][1];
        double xi, yi, xj, yj;
        mm_nat_point(m, q, i, &xi, &yi), mm_nat_point(m, q, j, &xj, &yj);
        if (i >= s->nfix)
            J[r * n + 2 * (i - s->nfix)] = 2 * (xi - xj), J[r * n + 2 * (i - s->nfix) + 1] = 2 * (yi - yj);
        if (j >= s->nfix)
            J[r * n + 2 * (j - s->nfix)] = -2 * (xi - xj), J[r * n + 2 * (j - s->nfix) + 1] = -2 * (yi - yj);
    }
    if (s->slide >= 0)
        J[r * n + 2 * (s->slide - s->nfix) + 1] = 1, r++;
    for (int k = 0; m->driven && k < s->ndrv; k++, r++) {
        double th = drive(m, k, t);
        int a = s->drv[k][1] - s->nfix;
        J[r * n + 2 * a] = sin(th), J[r * n + 2 * a + 1] = -cos(th);
    }
    return 0;
}

void mm_nat_problem(const mm_nat_model *m, mm_mech_problem *prob)
{
    const mm_nat_linkage *s = m->s;
    *prob = (mm_mech_problem){.n = 2 * (s->npts - s->nfix), .m = s->ncon + (s->slide >= 0) + (m->driven ? s->ndrv : 0),
                              .phi = phi_fn, .jac = jac_fn, .params = (void *)m};
}
