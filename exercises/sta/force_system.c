/* force_system.c — sta-force-system: any system of forces and couples in
 * space reduced to a force and a couple at a point, then to its simplest
 * equivalent: nothing (equilibrium), a couple, a single force, or a
 * wrench (a force and a couple along it).
 *
 *     R = sum F_i,   M_O = sum (r_i - O) x F_i + sum C_j               (1)
 *     M_B = M_O + (O - B) x R                                          (2)
 *     p = R . M_O / |R|^2,   P = O + R x M_O / |R|^2                    (4)
 *
 * Goal: equivalence of force systems, the moment transfer (2), the
 * invariant R . M, and the central axis.
 * Checks: the moment at P summed directly from the forces is parallel to R
 * and equals p R; R . M at P equals R . M at O; the transfer (2) to the
 * first force's point against the direct sum there.
 * Reference: Hibbeler, Statics, 14th ed., sections 4.7-4.8; Meriam &
 * Kraige, Statics, article 2/9.
 */
#include <float.h>
#include <math.h>

#include "mm_exhelp.h"
#include "mm_forces.h"
#include "mm_sta.h"

#define MAXF 20

enum { P_FORCES, P_COUPLES, P_O };
static const mm_param params[] = {
    [P_FORCES] = {"forces", "forces (x, y, z, Fx, Fy, Fz per row)", "", MM_MATRIX, 0, -1e9, 1e9,
                  "0,0,0,0,0,100;2,0,0,0,50,0;0,1,0,30,0,0", NULL, MAXF, 6,
                  .help = "one row per force: its point (m) and components (N); at most 20"},
    [P_COUPLES] = {"couples", "couples (Cx, Cy, Cz per row)", "N m", MM_MATRIX, 0, -1e9, 1e9, "", NULL, MAXF, 3,
                   .help = "free couples (their point does not matter); none by default"},
    [P_O] = {"O", "reduction point (x, y, z)", "m", MM_VECTOR, 0, -1e4, 1e4, "0,0,0", NULL, 0, 3,
             .help = "the point the system is reduced to"},
};

enum { O_RX, O_RY, O_RZ, O_R, O_MX, O_MY, O_MZ, O_PITCH, O_PX, O_PY, O_PZ, O_MW, O_KIND, O_MLINE, O_ANIM };
static const mm_output outputs[] = {
    [O_RX] = MM_SCALAR("Rx", "resultant force, x", "N", .flags = MM_ANSWER | MM_EXACT),
    [O_RY] = MM_SCALAR("Ry", "resultant force, y", "N", .flags = MM_ANSWER | MM_EXACT),
    [O_RZ] = MM_SCALAR("Rz", "resultant force, z", "N", .flags = MM_ANSWER | MM_EXACT),
    [O_R] = MM_SCALAR("R", "magnitude of the resultant", "N", .flags = MM_EXACT),
    [O_MX] = MM_SCALAR("MOx", "resultant moment about O, x", "N m", .flags = MM_ANSWER | MM_EXACT),
    [O_MY] = MM_SCALAR("MOy", "resultant moment about O, y", "N m", .flags = MM_ANSWER | MM_EXACT),
    [O_MZ] = MM_SCALAR("MOz", "resultant moment about O, z", "N m", .flags = MM_ANSWER | MM_EXACT),
    [O_PITCH] = MM_SCALAR("pitch", "pitch of the wrench R . M / |R|^2", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_PX] = MM_SCALAR("Px", "central axis: point nearest O, x", "m", .flags = MM_EXACT),
    [O_PY] = MM_SCALAR("Py", "central axis: point nearest O, y", "m", .flags = MM_EXACT),
    [O_PZ] = MM_SCALAR("Pz", "central axis: point nearest O, z", "m", .flags = MM_EXACT),
    [O_MW] = MM_SCALAR("M_wrench", "couple of the wrench along R (pitch times |R|)", "N m", .flags = MM_EXACT),
    [O_KIND] = MM_SCALAR("kind", "simplest equivalent (0 equilibrium, 1 couple, 2 single force, 3 wrench)", "",
                         .flags = MM_ANSWER | MM_EXACT),
    [O_MLINE] = MM_SERIES("M_along", "|M_B| for B on the line from O through P", "N m", "t (B = O + t (P - O))", ""),
    [O_ANIM] = MM_ANIMATION("the forces, and the wrench on its central axis"),
};

static int check(const mm_value *in, mm_error *err)
{
    if (mm_sta_rows(&in[P_FORCES], "forces", "force", "x,y,z,Fx,Fy,Fz", 6, err) ||
        mm_sta_rows(&in[P_COUPLES], "couples", "couple", "Cx,Cy,Cz", 3, err))
        return MM_ERANGE;
    if (in[P_O].cols != 3)
        return mm_error_set(err, MM_ERANGE, "O", "O needs 3 coordinates; got %d", in[P_O].cols);
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    (void)err;
    const mm_value *Fs = &in[P_FORCES], *Cs = &in[P_COUPLES];
    const double *O = in[P_O].data;
    mm_forces_sum so, sp, sb, st;                      /* eq. (1) about O, P, B and along a line */
    mm_forces_resultant(Fs->rows, Fs->data, Cs->rows, Cs->data, O, &so);
    const double *R = so.R, *M = so.M;
    double Rs = so.sum_F, Ms = so.sum_M, Rn = mm_sta_norm(R), Mn = mm_sta_norm(M);
    const double out[] = {R[0], R[1], R[2], Rn, M[0], M[1], M[2]};      /* O_RX ... O_MZ */
    for (int k = 0; k < 7; k++)
        mm_res_scalar(res, O_RX + k, out[k]);
    /* the simplest equivalent: R and M vanish to rounding, or R . M does */
    double tolR = 64 * DBL_EPSILON * Rs, tolM = 64 * DBL_EPSILON * Ms, RM = mm_sta_dot(R, M);
    int kind = Rn <= tolR ? (Mn <= tolM ? 0 : 1) : fabs(RM) <= 64 * DBL_EPSILON * Rs * Ms ? 2 : 3;
    double P[3] = {O[0], O[1], O[2]}, pitch = kind == 3 ? RM / (Rn * Rn) : 0;       /* eq. (4) */
    static const char *const kinds[] = {"in equilibrium", "a couple", "a single force", "a wrench"};
    mm_res_scalar_text(res, O_KIND, kind, kinds[kind]);
    if (Rn > tolR) {
        double RxM[3];
        mm_sta_cross(R, M, RxM);
        for (int k = 0; k < 3; k++)
            P[k] = O[k] + RxM[k] / (Rn * Rn);              /* eq. (4) */
        const double axis[] = {pitch, P[0], P[1], P[2], pitch * Rn};     /* O_PITCH ... O_MW */
        for (int k = 0; k < 5; k++)
            mm_res_scalar(res, O_PITCH + k, axis[k]);
        /* check 1: summed directly at P, the moment lies along R: |M_P x R| */
        mm_forces_resultant(Fs->rows, Fs->data, Cs->rows, Cs->data, P, &sp);
        double *MP = sp.M, MPs = sp.sum_M, c[3];
        mm_sta_cross(MP, R, c);
        mm_check_residual(res, "moment summed at the central axis point P, across R: |M_P x R| / |R| [N m]",
                          mm_sta_norm(c) / Rn, MPs + Ms, 64);
        /* check 2: the invariant R . M */
        mm_check_residual(res, "R . M at P vs at O [N^2 m]", mm_sta_dot(R, MP) - RM, Rs * (MPs + Ms), 64);
        /* check 3: it is the wrench's couple p R */
        double d[3];
        for (int k = 0; k < 3; k++)
            d[k] = MP[k] - pitch * R[k];
        mm_check_residual(res, "M_P - p R [N m]", mm_sta_norm(d), MPs + Ms, 64);
    } else {
        mm_res_warn(res, "R = 0: the system is %s; its moment is the same about every point", kinds[kind]);
    }
    /* check 4: the transfer theorem (2) to the first force's point */
    const double *B = Fs->data;
    double OB[3] = {O[0] - B[0], O[1] - B[1], O[2] - B[2]}, t[3];
    mm_forces_resultant(Fs->rows, Fs->data, Cs->rows, Cs->data, B, &sb);
    mm_sta_cross(OB, R, t);
    for (int k = 0; k < 3; k++)
        t[k] += M[k] - sb.M[k];
    mm_check_residual(res, "M_B = M_O + (O - B) x R at B, the first force's point [N m]", mm_sta_norm(t),
                      Ms + sb.sum_M + mm_sta_norm(OB) * Rs, 64);
    /* the couple's size at points B from O toward P: smallest on the central axis */
    mm_series *ml = mm_res_series(res, O_MLINE, 61);
    if (!ml)
        return MM_ENOMEM;
    double dir[3] = {P[0] - O[0], P[1] - O[1], P[2] - O[2]};
    if (mm_sta_norm(dir) == 0)
        dir[0] = 1;                                  /* P = O (or R = 0): along x */
    for (int i = 0; i < 61; i++) {
        double tt = -1 + 3.0 * i / 60, Bt[3] = {O[0] + tt * dir[0], O[1] + tt * dir[1], O[2] + tt * dir[2]};
        mm_forces_resultant(Fs->rows, Fs->data, Cs->rows, Cs->data, Bt, &st);
        ml->x[i] = tt, ml->y[i] = mm_sta_norm(st.M);
    }
    mm_res_method(res, "closed form (sums of forces and cross products)", 0);
    /* the drawing */
    mm_sta_fbd(res);
    mm_sta_reduced3(res, Fs->rows, Fs->data, O, R, M, P, pitch, kind, so.reach, kinds[kind]);
    return MM_OK;
}

static const char *const references[] = {MM_STA_HIBBELER "sections 4.7-4.8", MM_STA_MERIAM "article 2/9", NULL};

const mm_exercise mm_ex_sta_force_system = {
    .id = "sta-force-system", .chapter = 3, .section = "3.2.3",
    .title = "Reducing a force system: resultant, couple and wrench",
    .summary = "Forces and couples in space reduced to a force and a couple at a point, and to their simplest "
               "equivalent: a single force, a couple or a wrench on its central axis.",
    .tags = "statics, force system, resultant, couple, wrench, equivalence, central axis",
    .theory = "exercises/sta/force_system.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
