/* frame.c — sta-frame: a three-hinged frame (or arch): two rigid bodies
 * pinned to the ground at A and B and to each other at C; the ground
 * reactions and the force in the crown hinge.
 *
 *     each body: sum Fx = 0, sum Fy = 0, sum M = 0                      (1)
 *
 * Goal: systems of rigid bodies: cut them apart at the hinge, equal and
 * opposite pin forces (Newton's third law), six equations for six
 * unknowns; the horizontal thrust an arch puts on its supports; why A, C
 * and B must not lie on one line.
 * Method: the six equations (1) with mm_equil's rank test.  Checks: (1)
 * put back for each body; the reactions again in closed form: the whole
 * frame's moments about A and the right body's about C give B alone
 * (eq. 3), then A and C follow by forces.
 * Reference: Hibbeler, Statics, 14th ed., section 6.6; Meriam & Kraige,
 * Statics, article 4/6.
 */
#include <float.h>
#include <math.h>

#include "mm_equil.h"
#include "mm_exhelp.h"
#include "mm_sta.h"

enum { P_A, P_B, P_C, P_LOADS };
static const mm_param params[] = {
    [P_A] = {"A", "left ground hinge (x, y)", "m", MM_VECTOR, 0, -1e4, 1e4, "0,0", NULL, 0, 2,
             .help = "the pin of the left body on the ground"},
    [P_B] = {"B", "right ground hinge (x, y)", "m", MM_VECTOR, 0, -1e4, 1e4, "8,0", NULL, 0, 2,
             .help = "the pin of the right body on the ground"},
    [P_C] = {"C", "crown hinge (x, y)", "m", MM_VECTOR, 0, -1e4, 1e4, "4,3", NULL, 0, 2,
             .help = "the pin joining the two bodies; loads left of it act on the left body"},
    [P_LOADS] = {"loads", "loads (x, y, Fx, Fy per row)", "", MM_MATRIX, 0, -1e9, 1e9,
                 "2,1.5,0,-10000;6,1.5,2000,-5000", NULL, 20, 4,
                 .help = "one row per force: its point (m) and components (N, y up); x < x_C on the left "
                         "body, x > x_C on the right, x = x_C on the hinge (counted with the left body)"},
};

enum { O_AX, O_AY, O_BX, O_BY, O_CX, O_CY, O_THRUST, O_ANIM };
static const mm_output outputs[] = {
    [O_AX] = MM_SCALAR("Ax", "reaction at A, x", "N", .flags = MM_ANSWER),
    [O_AY] = MM_SCALAR("Ay", "reaction at A, y", "N", .flags = MM_ANSWER),
    [O_BX] = MM_SCALAR("Bx", "reaction at B, x", "N", .flags = MM_ANSWER),
    [O_BY] = MM_SCALAR("By", "reaction at B, y", "N", .flags = MM_ANSWER),
    [O_CX] = MM_SCALAR("Cx", "force of the right body on the left at C, x", "N", .flags = MM_ANSWER),
    [O_CY] = MM_SCALAR("Cy", "force of the right body on the left at C, y", "N", .flags = MM_ANSWER),
    [O_THRUST] = MM_SERIES("Ax_of_rise", "A_x as the crown moves up or down", "N", "rise of C above the line AB", "m"),
    [O_ANIM] = MM_ANIMATION("the two bodies taken apart at C, with loads, reactions and pin forces"),
};

static int check(const mm_value *in, mm_error *err)
{
    static const char *const nm[] = {"A", "B", "C"};
    for (int k = 0; k < 3; k++)
        if (in[k].cols != 2)
            return mm_error_set(err, MM_ERANGE, nm[k], "%s needs 2 coordinates (x, y)", nm[k]);
    if (in[P_LOADS].cols != 4)
        return mm_error_set(err, MM_ERANGE, "loads", "each load is one row x,y,Fx,Fy; got %d numbers", in[P_LOADS].cols);
    const double *A = in[P_A].data, *B = in[P_B].data, *C = in[P_C].data;
    if (!(A[0] < C[0] && C[0] < B[0]))
        return mm_error_set(err, MM_ERANGE, "C", "the crown hinge must lie between the ground hinges in x "
                            "(x_A < x_C < x_B); got %g, %g, %g", A[0], C[0], B[0]);
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    const double *A = in[P_A].data, *B = in[P_B].data, *C = in[P_C].data;
    const mm_value *Ld = &in[P_LOADS];
    /* the loads of each body: force and moment about the origin */
    double PL[3] = {0}, PR[3] = {0}, Fs = 0, size = fmax(hypot(B[0] - A[0], B[1] - A[1]), 1e-3);
    for (int i = 0; i < Ld->rows; i++) {
        const double *p = Ld->data + 4 * i;
        double *S = p[0] <= C[0] ? PL : PR;
        S[0] += p[2], S[1] += p[3], S[2] += p[0] * p[3] - p[1] * p[2];
        Fs += hypot(p[2], p[3]);
    }
    /* eq. (1): unknowns Ax Ay Bx By Cx Cy; rows: left Fx Fy M, right Fx Fy M */
    double M[36] = {
        1, 0, 0, 0, 1, 0,
        0, 1, 0, 0, 0, 1,
        -A[1], A[0], 0, 0, -C[1], C[0],
        0, 0, 1, 0, -1, 0,
        0, 0, 0, 1, 0, -1,
        0, 0, -B[1], B[0], C[1], -C[0],
    };
    double b[6] = {-PL[0], -PL[1], -PL[2], -PR[0], -PR[1], -PR[2]}, x[6];
    mm_equil_result er;
    int rc = mm_equil_solve(6, 6, M, b, x, NULL, NULL, &er, err);
    if (rc == MM_ESINGULAR)
        return mm_error_set(err, MM_ESINGULAR, "C", "the hinges A, C and B lie on one line: C can move across it "
                            "without turning either body much (a mechanism); move C off the line AB");
    if (rc != MM_OK)
        return rc;
    double xerr = 4 * DBL_EPSILON * Fs / er.rcond, Xmax = 0;
    for (int k = 0; k < 6; k++) {
        mm_res_scalar_err(res, O_AX + k, mm_sta_shown(x[k], xerr), xerr, MM_ERR_ESTIMATE);
        Xmax = fmax(Xmax, fabs(x[k]));
    }
    /* check 1: each body, eq. (1) put back */
    double worst = 0, scale = Fs + Xmax;
    for (int r = 0; r < 6; r++) {
        double s = -b[r];
        for (int c = 0; c < 6; c++)
            s += M[6 * r + c] * x[c];
        worst = fmax(worst, fabs(s) / (r % 3 == 2 ? size + hypot(C[0], C[1]) : 1));
    }
    mm_check_residual(res, "each body: sum Fx, sum Fy, sum M / size, largest [N]", worst, scale, 32);
    /* check 2: closed form, eq. (3): moments of the whole frame about A and
     * of the right body about C give Bx, By */
    double MA = PL[2] + PR[2] - (A[0] * (PL[1] + PR[1]) - A[1] * (PL[0] + PR[0]));
    double MC = PR[2] - (C[0] * PR[1] - C[1] * PR[0]);
    double a11 = -(B[1] - A[1]), a12 = B[0] - A[0], a21 = -(B[1] - C[1]), a22 = B[0] - C[0];
    double det = a11 * a22 - a12 * a21;
    double Bx = (-MA * a22 + MC * a12) / det, By = (-MC * a11 + MA * a21) / det;
    double cf[6] = {-Bx - PL[0] - PR[0], -By - PL[1] - PR[1], Bx, By, Bx + PR[0], By + PR[1]};
    int wk = mm_sta_worst(6, cf, x, 0);
    static const char *const names[] = {"Ax", "Ay", "Bx", "By", "Cx", "Cy"};
    mm_sta_check_absf(res, cf[wk], x[wk], 64 * DBL_EPSILON * (Fs + Xmax) / er.rcond,
                      "%s by moments about A (whole frame) and C (right body) vs the linear solve [N]", names[wk]);
    /* the thrust against the rise of the crown, by the closed form (3) */
    double yl = A[1] + (B[1] - A[1]) * (C[0] - A[0]) / (B[0] - A[0]), h0 = C[1] - yl;
    mm_series *th = mm_res_series(res, O_THRUST, 60);
    if (!th)
        return MM_ENOMEM;
    for (int i = 0; i < 60; i++) {
        double hh = h0 * (0.2 + 2.8 * i / 59), Cy = yl + hh;
        double MCi = PR[2] - (C[0] * PR[1] - Cy * PR[0]);
        double b21 = -(B[1] - Cy), dt = a11 * a22 - a12 * b21;
        double Bxi = (-MA * a22 + MCi * a12) / dt;
        th->x[i] = hh, th->y[i] = -Bxi - PL[0] - PR[0];
    }
    mm_res_method(res, "six equilibrium equations of the two bodies, LU with the rank test", 0);
    /* the drawing: the bodies taken apart at C (the right one moved right) */
    mm_sta_fbd(res);
    mm_sta_frame_apart(res, A, B, C, x, Ld->rows, Ld->data, size, mm_sta_scale(fmax(Fs, Xmax), size, 0.2));
    return rc;
}

static const char *const references[] = {MM_STA_HIBBELER "section 6.6", MM_STA_MERIAM "article 4/6", NULL};

const mm_exercise mm_ex_sta_frame = {
    .id = "sta-frame", .chapter = 3, .section = "3.6",
    .title = "A three-hinged frame: systems of rigid bodies",
    .summary = "Two bodies pinned to the ground and to each other: ground reactions and the hinge force from "
               "six equations, the arch's horizontal thrust.",
    .tags = "statics, frame, arch, three-hinged, systems of bodies, pin forces", .theory = "exercises/sta/frame.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
