/* moment.c — sta-moment: the moment of a force about a point and about an
 * axis, in space.
 *
 *     M_O = (r - O) x F                                               (1)
 *     M_axis = e . M_O,   e = u / |u|                                  (3)
 *
 * Goal: the cross product as the moment, its magnitude |F| d with d the
 * lever arm (2), its independence of where along its line the force acts
 * (transmissibility), and the moment about an axis as the part of M_O
 * along it.
 * Checks: M_O is perpendicular to F; |M_O| = |F| d with d found
 * geometrically (the foot of the perpendicular from O); the force slid
 * along its line gives the same moment; the moment about the axis again
 * from the parts of r - O and F perpendicular to the axis (eq. 4).
 * Reference: Hibbeler, Statics, 14th ed., sections 4.1-4.5.
 */
#include <math.h>

#include "mm_exhelp.h"
#include "mm_sta.h"

enum { P_F, P_R, P_O, P_U };
static const mm_param params[] = {
    [P_F] = {"F", "force (Fx, Fy, Fz)", "N", MM_VECTOR, 0, -1e9, 1e9, "10,-20,30", NULL, 0, 3,
             .help = "the force's three components"},
    [P_R] = {"r", "point of application (x, y, z)", "m", MM_VECTOR, 0, -1e4, 1e4, "2,1,0.5", NULL, 0, 3,
             .help = "where the force acts (any point of its line of action gives the same moment)"},
    [P_O] = {"O", "moment point (x, y, z)", "m", MM_VECTOR, 0, -1e4, 1e4, "0,0,0", NULL, 0, 3,
             .help = "the point the moment is taken about; the axis passes through it"},
    [P_U] = {"u", "axis direction (ux, uy, uz)", "", MM_VECTOR, 0, -1e4, 1e4, "0,0,1", NULL, 0, 3,
             .help = "direction of the axis through O (any length but zero)"},
};

enum { O_MX, O_MY, O_MZ, O_M, O_D, O_MAXIS, O_SLIDE, O_ANIM };
static const mm_output outputs[] = {
    [O_MX] = MM_SCALAR("Mx", "moment about O, x component", "N m", .flags = MM_ANSWER | MM_EXACT),
    [O_MY] = MM_SCALAR("My", "moment about O, y component", "N m", .flags = MM_ANSWER | MM_EXACT),
    [O_MZ] = MM_SCALAR("Mz", "moment about O, z component", "N m", .flags = MM_ANSWER | MM_EXACT),
    [O_M] = MM_SCALAR("M", "magnitude of the moment about O", "N m", .flags = MM_ANSWER | MM_EXACT),
    [O_D] = MM_SCALAR("d", "lever arm: distance from O to the line of action", "m", .flags = MM_EXACT),
    [O_MAXIS] = MM_SCALAR("M_axis", "moment about the axis through O along u", "N m", .flags = MM_ANSWER | MM_EXACT),
    [O_SLIDE] = MM_SERIES("M_sliding", "|M_O| with the force slid along its line", "N m", "distance slid", "m"),
    [O_ANIM] = MM_ANIMATION("the force, its point, the moment about O and the axis"),
};

static int check(const mm_value *in, mm_error *err)
{
    static const char *const names[] = {"F", "r", "O", "u"};
    for (int k = 0; k < 4; k++)
        if (in[k].cols != 3)
            return mm_error_set(err, MM_ERANGE, names[k], "%s needs 3 components (x, y, z); got %d", names[k],
                                in[k].cols);
    if (mm_sta_norm(in[P_U].data) == 0)
        return mm_error_set(err, MM_ERANGE, "u", "the axis direction u must not be zero");
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    (void)err;
    const double *F = in[P_F].data, *r = in[P_R].data, *O = in[P_O].data, *u = in[P_U].data;
    double w[3] = {r[0] - O[0], r[1] - O[1], r[2] - O[2]}, M[3], e[3];
    mm_sta_cross(w, F, M);                                        /* eq. (1) */
    double Fn = mm_sta_norm(F), Mn = mm_sta_norm(M), un = mm_sta_norm(u);
    for (int k = 0; k < 3; k++)
        e[k] = u[k] / un;
    double Ma = mm_sta_dot(e, M);                                 /* eq. (3) */
    /* the lever arm: from O to the foot of the perpendicular on the line */
    double t = Fn > 0 ? mm_sta_dot(w, F) / (Fn * Fn) : 0, foot[3], d;
    for (int k = 0; k < 3; k++)
        foot[k] = w[k] - t * F[k];
    d = mm_sta_norm(foot);
    mm_res_scalar(res, O_MX, M[0]);
    mm_res_scalar(res, O_MY, M[1]);
    mm_res_scalar(res, O_MZ, M[2]);
    mm_res_scalar(res, O_M, Mn);
    mm_res_scalar(res, O_D, Fn > 0 ? d : 0);
    mm_res_scalar(res, O_MAXIS, Ma);

    double wn = mm_sta_norm(w), big = wn * Fn;
    /* check 1: the moment is perpendicular to the force */
    mm_check_residual(res, "M . F [N^2 m] (the moment is perpendicular to the force)", mm_sta_dot(M, F), big * Fn, 16);
    /* check 2: |M| = |F| d, eq. (2) */
    mm_check_residual(res, "|M| - |F| d, d the distance to the line of action [N m]", Mn - Fn * d, big, 16);
    /* check 3: slid along its line by 3 of its own length units, eq. (1) again */
    double w2[3], M2[3];
    for (int k = 0; k < 3; k++)
        w2[k] = w[k] + (Fn > 0 ? 3 * F[k] / Fn * fmax(wn, 1) : 0);
    mm_sta_cross(w2, F, M2);
    mm_check_residual(res, "transmissibility: |M(r + s F/|F|) - M(r)| [N m]",
                      hypot(hypot(M2[0] - M[0], M2[1] - M[1]), M2[2] - M[2]), (mm_sta_norm(w2) + wn) * Fn, 16);
    /* check 4: the moment about the axis from the parts across it, eq. (4) */
    double wp[3], Fp[3], Mp[3], we = mm_sta_dot(w, e), Fe = mm_sta_dot(F, e);
    for (int k = 0; k < 3; k++)
        wp[k] = w[k] - we * e[k], Fp[k] = F[k] - Fe * e[k];
    mm_sta_cross(wp, Fp, Mp);
    mm_check_residual(res, "M_axis by the parts across the axis vs e . M [N m]", mm_sta_dot(e, Mp) - Ma, 4 * big, 16);
    /* the moment as the force slides along its own line: it stays (transmissibility) */
    mm_series *sl = mm_res_series(res, O_SLIDE, 41);
    if (!sl)
        return MM_ENOMEM;
    for (int i = 0; i < 41; i++) {
        double sd = (i - 20) * 0.1 * fmax(wn, 1), p[3], q[3];
        for (int k = 0; k < 3; k++)
            p[k] = w[k] + (Fn > 0 ? sd * F[k] / Fn : 0);
        mm_sta_cross(p, F, q);
        sl->x[i] = sd, sl->y[i] = mm_sta_norm(q);
    }
    mm_res_method(res, "closed form (cross product)", 0);

    /* the drawing: axes at O, r - O, F at r, M at O, the axis */
    mm_sta_fbd(res);
    double size = fmax(wn, 1e-3), fs = Fn > 0 ? 0.6 * size / Fn : 0, ms = Mn > 0 ? 0.6 * size / Mn : 0;
    mm_sta_axes3(res, O, 0.5 * size);
    double a0[3], a1[3];
    for (int k = 0; k < 3; k++)
        a0[k] = O[k] - 0.7 * size * e[k], a1[k] = O[k] + 0.7 * size * e[k];
    mm_sta_line3(res, "axis u", a0, a1, "highlight");
    mm_sta_line3(res, "r - O", O, r, NULL);
    mm_sta_arrow3(res, "F", r, F, fs, 0, "N", NULL);
    mm_sta_arrow3(res, "M_O", O, M, ms, 0, "N m", "highlight");
    mm_sta_label3(res, O, "O");
    mm_sta_label3(res, r, "F = %.4g N", Fn);
    return MM_OK;
}

static const char *const references[] = {MM_STA_HIBBELER "sections 4.1-4.5", NULL};

const mm_exercise mm_ex_sta_moment = {
    .id = "sta-moment", .chapter = 3, .section = "3.1.2",
    .title = "Moment of a force about a point and an axis",
    .summary = "M = r x F in space, its lever arm, and the moment about an axis through the point.",
    .tags = "statics, moment, cross product, lever arm, axis", .theory = "exercises/sta/moment.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
