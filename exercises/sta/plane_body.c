/* plane_body.c — sta-plane-body: a rigid body in a plane on supports
 * modelled as links (a roller is one link normal to its surface, a pin
 * two); the reactions from the three equilibrium equations.
 *
 *     sum Fx = 0,  sum Fy = 0,  sum M_O = 0                           (1)
 *
 * Goal: the three equations of a plane body; why three links hold it only
 * when they are neither concurrent nor all parallel (improper supports),
 * and what extra links mean (statical indeterminacy).
 * Method: (1) as a linear system with mm_equil's rank test; a failure is
 * told as the motion the links allow or the link that is redundant.
 * Checks: (1) put back; each reaction again by moments about the point
 * where the other two links' lines meet (eq. 3), independent of the system.
 * Reference: Hibbeler, Statics, 14th ed., sections 5.1-5.7.
 */
#include <float.h>
#include <math.h>

#include "mm_equil.h"
#include "mm_exhelp.h"
#include "mm_sta.h"

#define MAXL 6

enum { P_LINKS, P_LOADS, P_C, P_BODY };
static const mm_param params[] = {
    [P_LINKS] = {"links", "support links (x, y, dx, dy per row)", "", MM_MATRIX, 0, -1e4, 1e4,
                 "0,0,1,0;0,0,0,1;4,0,-1,2", NULL, MAXL, 4,
                 .help = "one row per reaction component: its point (m) and line direction (any length); "
                         "a pin is two rows, a roller one row normal to its surface"},
    [P_LOADS] = {"loads", "loads (x, y, Fx, Fy per row)", "", MM_MATRIX, 0, -1e9, 1e9,
                 "1.5,0,0,-2000;4,1,800,0", NULL, 20, 4,
                 .help = "one row per force: its point (m) and components (N, y up)"},
    [P_C] = {"C", "applied couple", "N m", MM_REAL, 0, -1e9, 1e9,
             .help = "the sum of couples on the body, counter-clockwise positive"},
    [P_BODY] = {"body", "outline of the body (x, y per row)", "m", MM_MATRIX, 0, -1e4, 1e4,
                "0,-0.1;4.1,-0.1;4.1,1.2;3.9,1.2;3.9,0.1;0,0.1", NULL, 50, 2,
                .help = "for the drawing only: the body as a polygon"},
};

enum { O_R, O_RPLOT, O_ANIM };
static const mm_output outputs[] = {
    [O_R] = MM_SCALAR("R%d", "reaction of link %d (along its direction)", "N", .flags = MM_ANSWER, .first = 1,
                      .last = MAXL),
    [O_RPLOT] = MM_SERIES("reaction_by_link", "reaction along the link's direction", "N", "link", "", .mark = "dots"),
    [O_ANIM] = MM_ANIMATION("the body on its supports with loads and reactions"),
};

static int check(const mm_value *in, mm_error *err)
{
    if (in[P_LINKS].cols != 4)
        return mm_error_set(err, MM_ERANGE, "links", "each link is one row x,y,dx,dy; got %d numbers", in[P_LINKS].cols);
    for (int k = 0; k < in[P_LINKS].rows; k++)
        if (hypot(in[P_LINKS].data[4 * k + 2], in[P_LINKS].data[4 * k + 3]) == 0)
            return mm_error_set(err, MM_ERANGE, "links", "link %d has no direction (dx = dy = 0)", k + 1);
    if (in[P_LOADS].cols != 4)
        return mm_error_set(err, MM_ERANGE, "loads", "each load is one row x,y,Fx,Fy; got %d numbers", in[P_LOADS].cols);
    if (in[P_BODY].cols != 2 || in[P_BODY].rows < 2)
        return mm_error_set(err, MM_ERANGE, "body", "the outline needs rows x,y, at least 2");
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    const mm_value *Lk = &in[P_LINKS], *Ld = &in[P_LOADS];
    int n = Lk->rows;
    double A[3 * MAXL], b[3] = {0, 0, -in[P_C].x}, e[MAXL][2], R[MAXL], mech[3], self[MAXL];
    double Fs = fabs(in[P_C].x), size = 1e-3;
    for (int k = 0; k < n; k++) {                      /* eq. (1), row-major 3 x n */
        const double *l = Lk->data + 4 * k;
        double len = hypot(l[2], l[3]);
        e[k][0] = l[2] / len, e[k][1] = l[3] / len;
        A[0 * n + k] = e[k][0];
        A[1 * n + k] = e[k][1];
        A[2 * n + k] = l[0] * e[k][1] - l[1] * e[k][0];
        size = fmax(size, hypot(l[0], l[1]));
    }
    for (int i = 0; i < Ld->rows; i++) {
        const double *p = Ld->data + 4 * i;
        b[0] -= p[2], b[1] -= p[3], b[2] -= p[0] * p[3] - p[1] * p[2];
        Fs += hypot(p[2], p[3]);
        size = fmax(size, hypot(p[0], p[1]));
    }
    mm_equil_result er;
    mm_error e2;
    int rc = mm_equil_solve(3, n, A, b, R, mech, self, &er, &e2);
    if (rc == MM_ESINGULAR)
        return mm_sta_improper2(&er, n, mech, self, err);     /* the motion the links allow, or a redundant one */
    if (rc != MM_OK) {
        *err = e2;
        return rc;
    }
    double Rmax = mm_sta_reactions(res, O_R, O_RPLOT, n, R, 4 * DBL_EPSILON * Fs / er.rcond);
    /* check 1: eq. (1) put back, forces and moment about the origin */
    double fx = -b[0], fy = -b[1], mz = -b[2], sf = Fs, sm = Fs * size;
    for (int k = 0; k < n; k++) {
        fx += R[k] * A[k], fy += R[k] * A[n + k], mz += R[k] * A[2 * n + k];
        sf += fabs(R[k]), sm += fabs(R[k] * A[2 * n + k]);
    }
    mm_check_residual(res, "sum Fx, sum Fy [N]", hypot(fx, fy), sf, 16);
    mm_check_residual(res, "sum M about the origin [N m]", mz, sm + sf * size, 16);
    /* check 2: Ritter, eq. (3): moments about the meeting point of the
     * other two lines (forces across them when they are parallel) */
    double Rr[3];
    for (int k = 0; k < 3; k++) {
        int a = (k + 1) % 3, c = (k + 2) % 3;
        const double *pa = Lk->data + 4 * a, *pc = Lk->data + 4 * c, *pk = Lk->data + 4 * k;
        double den = e[a][0] * e[c][1] - e[a][1] * e[c][0], num, arm;
        if (fabs(den) > 1e-9) {
            double s = ((pc[0] - pa[0]) * e[c][1] - (pc[1] - pa[1]) * e[c][0]) / den;
            double X = pa[0] + s * e[a][0], Y = pa[1] + s * e[a][1];
            num = -in[P_C].x;
            for (int i = 0; i < Ld->rows; i++)
                num -= (Ld->data[4 * i] - X) * Ld->data[4 * i + 3] - (Ld->data[4 * i + 1] - Y) * Ld->data[4 * i + 2];
            arm = (pk[0] - X) * e[k][1] - (pk[1] - Y) * e[k][0];
        } else {
            double nx = -e[a][1], ny = e[a][0];
            num = 0;
            for (int i = 0; i < Ld->rows; i++)
                num -= Ld->data[4 * i + 2] * nx + Ld->data[4 * i + 3] * ny;
            arm = e[k][0] * nx + e[k][1] * ny;
        }
        Rr[k] = num / arm;
    }
    int wk = mm_sta_worst(3, Rr, R, 1);
    mm_sta_check_absf(res, Rr[wk], R[wk], 64 * DBL_EPSILON * (Fs + Rmax) / er.rcond,
                      "link %d by moments about where the other two meet (Ritter) vs the linear solve [N]", wk + 1);
    mm_res_method(res, "three equilibrium equations, LU with the rank test", 0);
    /* the drawing */
    mm_sta_fbd(res);
    double sc = mm_sta_scale(fmax(Rmax, Fs), size, 0.25);
    mm_sta_polygon(res, "body", in[P_BODY].rows, in[P_BODY].data, NULL);
    mm_sta_links2(res, n, Lk->data, R, size, sc);
    mm_sta_loads2(res, Ld->rows, Ld->data, sc);
    if (in[P_C].x != 0)
        mm_sta_couple(res, "couple", 0.5 * size, 0, 0.08 * size, in[P_C].x);
    return rc;
}

static const char *const references[] = {MM_STA_HIBBELER "sections 5.1-5.7", NULL};

const mm_exercise mm_ex_sta_plane_body = {
    .id = "sta-plane-body", .chapter = 3, .section = "3.4",
    .title = "A rigid body in a plane on its supports",
    .summary = "Reactions of a plane body held by pins and rollers (links), from three equilibrium equations; "
               "improper and redundant supports named.",
    .tags = "statics, rigid body, plane, reactions, supports, equilibrium", .theory = "exercises/sta/plane_body.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
