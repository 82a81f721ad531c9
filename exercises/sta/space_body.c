/* space_body.c — sta-space-body: a rigid body in space held by six links
 * (a plate on ball joints and rods, a shaft in bearings); the six
 * reactions from the six equilibrium equations.
 *
 *     sum_k R_k e_k + sum_i P_i = 0,   sum_k R_k p_k x e_k + sum_i r_i x P_i = 0   (1)
 *
 * Goal: the six equations of a body in space; six links hold it only when
 * no motion keeps all their lengths (a rank test); which motion is left
 * when they do not.
 * Method: (1) as a 6 x n linear system with mm_equil's rank test.  Checks:
 * (1) put back; each reaction again by virtual work: the rigid motion that
 * stretches link k alone (eq. 3), and the power of the loads on it (4).
 * Reference: Hibbeler, Statics, 14th ed., sections 5.5-5.7.
 */
#include <float.h>
#include <math.h>

#include "mm_equil.h"
#include "mm_exhelp.h"
#include "mm_sta.h"

#define MAXL 8

enum { P_LINKS, P_LOADS, P_BODY };
static const mm_param params[] = {
    [P_LINKS] = {"links", "support links (x, y, z, dx, dy, dz per row)", "", MM_MATRIX, 0, -1e4, 1e4,
                 "0,0,0,1,0,0;0,0,0,0,1,0;0,0,0,0,0,1;2,0,0,0,1,0;2,0,0,0,0,1;0,1,0,0,0,1", NULL, MAXL, 6,
                 .help = "one row per reaction component: its point (m) and direction; a ball joint is three "
                         "rows at one point, a journal bearing two across the shaft"},
    [P_LOADS] = {"loads", "loads (x, y, z, Fx, Fy, Fz per row)", "", MM_MATRIX, 0, -1e9, 1e9,
                 "1,0.5,0,0,0,-500;2,1,0,100,0,-300", NULL, 20, 6,
                 .help = "one row per force: its point (m) and components (N, z up)"},
    [P_BODY] = {"body", "outline of the body (x, y, z per row)", "m", MM_MATRIX, 0, -1e4, 1e4,
                "0,0,0;2,0,0;2,1,0;0,1,0", NULL, 50, 3, .help = "for the drawing only: a polygon in space"},
};

enum { O_R, O_RPLOT, O_ANIM };
static const mm_output outputs[] = {
    [O_R] = MM_SCALAR("R%d", "reaction of link %d (along its direction)", "N", .flags = MM_ANSWER, .first = 1,
                      .last = MAXL),
    [O_RPLOT] = MM_SERIES("reaction_by_link", "reaction along the link's direction", "N", "link", "", .mark = "dots"),
    [O_ANIM] = MM_ANIMATION("the body on its links with loads and reactions"),
};

static int check(const mm_value *in, mm_error *err)
{
    if (in[P_LINKS].cols != 6)
        return mm_error_set(err, MM_ERANGE, "links", "each link is one row x,y,z,dx,dy,dz; got %d numbers",
                            in[P_LINKS].cols);
    for (int k = 0; k < in[P_LINKS].rows; k++)
        if (mm_sta_norm(in[P_LINKS].data + 6 * k + 3) == 0)
            return mm_error_set(err, MM_ERANGE, "links", "link %d has no direction", k + 1);
    if (in[P_LOADS].cols != 6)
        return mm_error_set(err, MM_ERANGE, "loads", "each load is one row x,y,z,Fx,Fy,Fz; got %d numbers",
                            in[P_LOADS].cols);
    if (in[P_BODY].cols != 3 || in[P_BODY].rows < 2)
        return mm_error_set(err, MM_ERANGE, "body", "the outline needs rows x,y,z, at least 2");
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    const mm_value *Lk = &in[P_LINKS], *Ld = &in[P_LOADS];
    int n = Lk->rows;
    double A[6 * MAXL], W[6] = {0}, b[6], R[MAXL], mech[6], self[MAXL], Fs = 0, size = 1e-3;
    for (int k = 0; k < n; k++) {                        /* column k: (e_k, p_k x e_k), eq. (1) */
        const double *l = Lk->data + 6 * k;
        double e[3], m[3], len = mm_sta_norm(l + 3);
        for (int c = 0; c < 3; c++)
            e[c] = l[3 + c] / len;
        mm_sta_cross(l, e, m);
        for (int c = 0; c < 3; c++)
            A[c * n + k] = e[c], A[(3 + c) * n + k] = m[c];
        size = fmax(size, mm_sta_norm(l));
    }
    for (int i = 0; i < Ld->rows; i++) {
        const double *p = Ld->data + 6 * i;
        double m[3];
        mm_sta_cross(p, p + 3, m);
        for (int c = 0; c < 3; c++)
            W[c] += p[3 + c], W[3 + c] += m[c];
        Fs += mm_sta_norm(p + 3);
        size = fmax(size, mm_sta_norm(p));
    }
    for (int c = 0; c < 6; c++)
        b[c] = -W[c];
    mm_equil_result er;
    mm_error e2;
    int rc = mm_equil_solve(6, n, A, b, R, mech, self, &er, &e2);
    if (rc == MM_ESINGULAR)
        return mm_sta_improper3(&er, n, mech, self, err);     /* the motion the links allow, or a redundant one */
    if (rc != MM_OK) {
        *err = e2;
        return rc;
    }
    double Rmax = mm_sta_reactions(res, O_R, O_RPLOT, n, R, 4 * DBL_EPSILON * Fs / er.rcond);
    /* check 1: eq. (1) put back */
    double worst = 0, scale = 0;
    for (int c = 0; c < 6; c++) {
        double s = W[c], a = fabs(W[c]);
        for (int k = 0; k < 6; k++)
            s += A[c * 6 + k] * R[k], a += fabs(A[c * 6 + k] * R[k]);
        worst = fmax(worst, fabs(s) / (c < 3 ? 1 : size));
        scale = fmax(scale, a / (c < 3 ? 1 : size));
    }
    mm_check_residual(res, "sum F and sum M / size, largest component [N]", worst, scale, 32);
    /* check 2: virtual work, eqs. (3)-(4): the motion xi_k with A^T xi_k =
     * e_k stretches link k alone; R_k = -(power of the loads on it) */
    double At[36], xi[6], Rv[6];
    for (int r = 0; r < 6; r++)
        for (int c = 0; c < 6; c++)
            At[r * 6 + c] = A[c * 6 + r];
    for (int k = 0; k < 6; k++) {
        double ek[6] = {0};
        ek[k] = 1;
        mm_equil_result e3;
        if (mm_equil_solve(6, 6, At, ek, xi, NULL, NULL, &e3, &e2) != MM_OK) {
            *err = e2;
            return MM_EINTERNAL;
        }
        double pw = 0;
        for (int c = 0; c < 6; c++)
            pw += W[c] * xi[c];
        Rv[k] = -pw;
    }
    int wk = mm_sta_worst(6, Rv, R, 1);
    mm_sta_check_absf(res, Rv[wk], R[wk], 64 * DBL_EPSILON * (Fs + Rmax) / er.rcond,
                      "link %d by virtual work (the motion that stretches it alone) vs the linear solve [N]", wk + 1);
    mm_res_method(res, "six equilibrium equations, LU with the rank test", 0);
    /* the drawing */
    mm_sta_fbd(res);
    double sc = mm_sta_scale(fmax(Rmax, Fs), size, 0.3);
    mm_sta_polygon3(res, "body", in[P_BODY].rows, in[P_BODY].data, NULL);
    mm_sta_links3(res, n, Lk->data, R, size, sc);
    for (int i = 0; i < Ld->rows; i++)
        mm_sta_arrow3(res, "load", Ld->data + 6 * i, Ld->data + 6 * i + 3, sc, 1, "N", NULL);
    return rc;
}

static const char *const references[] = {MM_STA_HIBBELER "sections 5.5-5.7", NULL};

const mm_exercise mm_ex_sta_space_body = {
    .id = "sta-space-body", .chapter = 3, .section = "3.5",
    .title = "A rigid body in space on six links",
    .summary = "A plate or a shaft held by ball joints, bearings and rods: six reactions from six equations, "
               "checked by virtual work; improper supports named by the motion they allow.",
    .tags = "statics, rigid body, space, reactions, six links, virtual work", .theory = "exercises/sta/space_body.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
