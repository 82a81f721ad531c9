/* mobility.c — kin-mobility: the degrees of freedom of a linkage, counted
 * by Grubler and Kutzbach and measured from its constraint equations.
 *
 *     planar:  M = 3 (n - 1) - 2 j1 - j2                                      (1)
 *     spatial: M = 6 (n - 1) - sum over joints (6 - f)                       (2)
 *     M = (coordinates) - rank(Phi_q)                                          (3)
 *
 * Goal: count the mobility of a described linkage (n links with the ground,
 * j1 full joints of one freedom, j2 half joints of two) and see where the
 * count is wrong: an overconstrained linkage (the double parallelogram, the
 * Bennett linkage) moves although the count says it cannot, because its
 * special proportions make some constraints repeat others.
 * Method: planar presets in natural coordinates (the positions of the
 * joints; each link a distance, a slider a line); the rank of the
 * constraint Jacobian by its singular values (mm_mech_rank, LAPACK), with
 * the gap that separates zero from non-zero; the Bennett linkage by the
 * rank of its four joint twists.  The linkage is then moved with as many
 * drivers as the rank says (mm_mech sweep: Newton, least squares when
 * overconstrained).
 * Checks: the count (1) against coordinates minus constraints (the same
 * bookkeeping done twice); the rank decision (the zero singular values at
 * rounding, the others well clear); the driven Jacobian of full rank; the
 * sweep through every frame; the Bennett loop closing on every frame.
 * Reference: R. L. Norton, Design of Machinery, 5th ed., sections 2.5-2.8;
 * G. T. Bennett, Engineering 76 (1903) 777; K. J. Waldron, The constraint
 * analysis of mechanisms, J. Mechanisms 1 (1966) 101-114.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mm_geom.h"
#include "mm_kin.h"
#include "mm_kin_linkage.h"
#include "mm_linalg.h"
#include "mm_linkage.h"
#include "mm_mech.h"
#include "mm_natural.h"

enum { P_LINKAGE, P_LINKS, P_J1, P_J2 };

static const char *const linkages[] = {"four-bar", "slider-crank", "five-bar", "watt-six-bar", "stephenson-six-bar",
                                       "double-parallelogram", "triangle", "bennett", "custom", NULL};
enum { K_BENNETT = 7, K_CUSTOM = 8 };

static const mm_param params[] = {
    [P_LINKAGE] = {"linkage", "linkage", "", MM_CHOICE, 0, 0, 8, .choices = linkages,
                   .help = "a described linkage, or custom: then the counts below"},
    [P_LINKS] = {"links", "links, the ground included (custom)", "", MM_INT, 4, 1, 50,
                 .help = "used only by custom: n of eq. (1)"},
    [P_J1] = {"j1", "full joints: pins and sliders (custom)", "", MM_INT, 4, 0, 100,
              .help = "joints of one freedom; a pin joining k links counts k - 1 times"},
    [P_J2] = {"j2", "half joints: cam and gear contacts (custom)", "", MM_INT, 0, 0, 100,
              .help = "joints of two freedoms: rolling with slipping"},
};

enum { O_GK, O_M, O_NQ, O_NC, O_RANK, O_OVER, O_PAIRS, O_SV, O_ANIM };

static const char *const pcols[] = {"joint", "kind", "freedom", NULL}, *const punits[] = {"", "", "", NULL};

static const mm_output outputs[] = {
    [O_GK] = MM_SCALAR("gruebler", "Grubler-Kutzbach count, eq. (1) or (2)", "", .flags = MM_ANSWER | MM_EXACT),
    [O_M] = MM_SCALAR("mobility", "mobility from the rank of the constraints, eq. (3)", "", .flags = MM_ANSWER | MM_EXACT),
    [O_NQ] = MM_SCALAR("coordinates", "coordinates of the model", "", .flags = MM_EXACT),
    [O_NC] = MM_SCALAR("constraints", "constraint equations of the model", "", .flags = MM_EXACT),
    [O_RANK] = MM_SCALAR("rank", "rank of the constraint Jacobian", "", .flags = MM_EXACT),
    [O_OVER] = MM_SCALAR("count_wrong", "the count is wrong: an overconstrained linkage (1) or not (0)", "",
                         .flags = MM_ANSWER | MM_EXACT),
    [O_PAIRS] = MM_TABLE("joints", "the joints (kinematic pairs)", pcols, punits),
    [O_SV] = MM_SERIES("singular_values", "singular values of the constraint Jacobian", "", "index", "", .mark = "bars",
                       .y_scale = "log", .figure = "singular values"),
    [O_ANIM] = MM_ANIMATION("the linkage moved by as many drivers as it has freedoms"),
};

/* ---- planar presets in natural coordinates (mm_natural) ------------------------------------ */

typedef struct preset {
    int links, j1, j2;            /* for eq. (1) */
    mm_nat_linkage g;             /* points (an assembly), bars, slider, drivers */
    int ntri, tri[2][3];          /* ternary links, drawn as triangles */
    const char *joints;           /* "name:kind:f,..." */
    const char *note;
} preset;

/* an overconstrained double parallelogram: O2 A B O4 a parallelogram, O6 E parallel to O2 A */
#define DPA 0.10806046117362795, 0.16829419696157930
static const preset presets[7] = {
    {4, 4, 0, {2, 4, {{0, 0}, {0.6, 0}, {0.10806046117362795, 0.16829419696157930}, {0.55, 0.4}},
     3, {{0, 2}, {2, 3}, {1, 3}}, -1, 1, {{0, 2}}, 0}, 0, {{0}},
     "O2:pin:1,A:pin:1,B:pin:1,O4:pin:1", "the count is right: a four-bar has one freedom"},
    {4, 4, 0, {1, 3, {{0, 0}, {0.054030230586813977, 0.084147098480789651}, {0.45, 0}},
     2, {{0, 1}, {1, 2}}, 2, 1, {{0, 1}}, 0}, 0, {{0}},
     "O:pin:1,A:pin:1,B:pin:1,B:slider:1", "the count is right: a slider-crank has one freedom"},
    {5, 5, 0, {2, 5, {{0, 0}, {0.5, 0}, {0.054353, 0.139806}, {0.25, 0.45}, {0.465919, 0.146089}},
     4, {{0, 2}, {2, 3}, {3, 4}, {4, 1}}, -1, 2, {{0, 2}, {1, 4}}, 0.35}, 0, {{0}},
     "O1:pin:1,A:pin:1,B:pin:1,C:pin:1,O2:pin:1", "the count is right: a five-bar needs two inputs"},
    {6, 7, 0, {3, 7, {{0, 0}, {0.6, 0}, {1.1, 0.1}, {0.10806046117362795, 0.16829419696157930}, {0.55, 0.4},
                      {0.8, 0.3}, {1.0, 0.55}},
     7, {{0, 3}, {3, 4}, {1, 4}, {1, 5}, {4, 5}, {5, 6}, {6, 2}}, -1, 1, {{0, 3}}, 0.35}, 1, {{1, 4, 5}},
     "O2:pin:1,A:pin:1,B:pin:1,O4:pin:1,C:pin:1,D:pin:1,O6:pin:1",
     "the count is right: Watt's chain (two ternary links joined) has one freedom"},
    {6, 7, 0, {3, 7, {{0, 0}, {0.6, 0}, {0.9, 0.3}, {0.10806046117362795, 0.16829419696157930}, {0.55, 0.4},
                      {0.35, 0.55}, {0.75, 0.75}},
     7, {{0, 3}, {3, 4}, {1, 4}, {3, 5}, {4, 5}, {5, 6}, {6, 2}}, -1, 1, {{0, 3}}, 0.35}, 1, {{3, 4, 5}},
     "O2:pin:1,A:pin:1,B:pin:1,O4:pin:1,C:pin:1,D:pin:1,O6:pin:1",
     "the count is right: Stephenson's chain (ternary links apart) has one freedom"},
    {5, 6, 0, {3, 6, {{0, 0}, {0.6, 0}, {0.3, 0.1}, {DPA}, {0.70806046117362795, 0.16829419696157930},
                      {0.40806046117362795, 0.26829419696157930}},
     6, {{0, 3}, {1, 4}, {2, 5}, {3, 4}, {3, 5}, {4, 5}}, -1, 1, {{0, 3}}, 0}, 1, {{3, 4, 5}},
     "O2:pin:1,A:pin:1,B:pin:1,O4:pin:1,E:pin:1,O6:pin:1",
     "the count is WRONG: it says 0 (a structure), but the third crank is parallel and equal to the other two, "
     "so its constraint repeats theirs and the linkage moves with one freedom (overconstrained)"},
    {3, 3, 0, {2, 3, {{0, 0}, {0.6, 0}, {0.25, 0.4}}, 2, {{0, 2}, {1, 2}}, -1, 0, {{0}}, 0}, 0, {{0}},
     "O1:pin:1,A:pin:1,O2:pin:1", "the count is right: a triangle is a structure, it cannot move"},
};

/* the Bennett linkage (mm_linkage_bennett): a, alpha of links 1 and 3; b from sin(alpha)/a = sin(beta)/b */
static const double BA = 0.3, BAL = M_PI / 3, BBE = M_PI / 4;

static int planar(const preset *ps, mm_result *res, mm_error *err)
{
    const mm_nat_linkage *s = &ps->g;
    mm_nat_model m, md;                                    /* without and with the drivers */
    double q[2 * MM_NAT_MAXP], sv[2 * MM_NAT_MAXP];
    mm_nat_init(&m, s, 0, q);
    mm_nat_init(&md, s, 1, NULL);
    mm_mech_problem free_, prob;
    mm_nat_problem(&m, &free_);
    mm_nat_problem(&md, &prob);
    const int n = free_.n, nc = free_.m;
    mm_mech_work *w = mm_mech_work_alloc(n, nc);
    if (!w)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    int rank = 0, k = nc < n ? nc : n;
    int rc = mm_mech_rank(&free_, w, 0, q, 0, sv, &rank, err);
    mm_mech_work_free(w);
    if (rc != MM_OK)
        return rc;
    int gk = 3 * (ps->links - 1) - 2 * ps->j1 - ps->j2, M = n - rank;
    mm_res_scalar(res, O_GK, gk);
    mm_res_scalar(res, O_M, M);
    mm_res_scalar(res, O_NQ, n), mm_res_scalar(res, O_NC, nc), mm_res_scalar(res, O_RANK, rank);
    mm_res_scalar_text(res, O_OVER, M != gk, ps->note);
    mm_res_check_abs(res, "Grubler-Kutzbach count (1) vs coordinates minus constraint equations", gk, n - nc, 0);
    mm_kin_rank_checks(res, sv, k, rank, nc, n);
    mm_series *ss = mm_res_series(res, O_SV, k);
    if (!ss)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (int i = 0; i < k; i++)
        ss->x[i] = i + 1, ss->y[i] = fmax(sv[i], 1e-300);
    if ((rc = mm_kin_joints_table(res, O_PAIRS, ps->joints, err)) != MM_OK)
        return rc;
    if (M != gk)
        mm_res_warn(res, "%s", ps->note);

    /* ---- moving it: one driver per freedom ---- */
    enum { NF = 72 };
    double Q[NF * 2 * MM_NAT_MAXP], t[NF];
    for (int f = 0; f < NF; f++)
        t[f] = 2 * M_PI * f / NF;
    memcpy(Q, q, (size_t)n * sizeof *Q);
    int solved = 1;
    if (s->ndrv > 0) {
        mm_mech_options opt;
        mm_mech_options_init(&opt);
        mm_mech_work *wd = mm_mech_work_alloc(n, prob.m);
        if (!wd)
            return mm_error_set(err, MM_ENOMEM, "", "out of memory");
        int r2 = 0;
        double sv2[2 * MM_NAT_MAXP];
        rc = mm_mech_rank(&prob, wd, 0, q, 0, sv2, &r2, err);
        mm_mech_sweep sw = {.nt = NF, .t = t, .q = Q, .watch = -1};
        if (rc == MM_OK)
            rc = mm_mech_sweep_solve(&prob, &opt, wd, &sw, err);
        mm_mech_work_free(wd);
        if (rc != MM_OK)
            return rc;
        mm_res_method_stat(res, "sweep_steps", sw.steps);
        mm_res_method_stat(res, "newton_iterations", sw.newton);
        mm_res_check_abs(res, "with one driver per freedom the Jacobian has full rank (every coordinate set)", r2, n, 0);
        mm_res_check_abs(res, "the drivers moved the linkage through every frame (Newton, least squares if "
                              "overconstrained)", sw.solved, NF, 0);
        solved = sw.solved;
    } else {
        for (int f = 1; f < NF; f++)
            memcpy(Q + f * n, q, (size_t)n * sizeof *Q);
    }
    return mm_kin_anim_linkage(res, &m, ps->ntri, ps->tri, NF, t, Q, solved, err);
}

static int spatial_bennett(mm_result *res, mm_error *err)
{
    /* the joint twists (z_k ; o_k x z_k): the loop's velocities are their
     * combinations summing to zero, so M = joints - rank */
    mm_v3 o[4], z[4];
    double gap, S[24], sv[4];
    mm_linkage_bennett(BA, BAL, BBE, 1.0, o, z, &gap);
    for (int k = 0; k < 4; k++) {
        mm_v3 m = mm_v3_cross(o[k], z[k]);
        double col[6] = {z[k].x, z[k].y, z[k].z, m.x, m.y, m.z};
        for (int r = 0; r < 6; r++)
            S[4 * r + k] = col[r];
    }
    int rc = mm_linalg_svdvals(6, 4, S, sv, err);
    if (rc != MM_OK)
        return rc;
    int rank = 0;
    for (int k = 0; k < 4; k++)
        rank += sv[k] > 6 * DBL_EPSILON * sv[0];
    int gk = 6 * (4 - 1) - 4 * (6 - 1), M = 4 - rank;                 /* eq. (2) */
    mm_res_scalar(res, O_GK, gk);
    mm_res_scalar(res, O_M, M);
    mm_res_scalar(res, O_NQ, 4), mm_res_scalar(res, O_NC, 6), mm_res_scalar(res, O_RANK, rank);
    const char *note = "the count is WRONG: it says -2 (a structure with two redundant constraints), but with "
                       "a1 = a3, a2 = a4, alpha1 = alpha3, alpha2 = alpha4 and sin(alpha1)/a1 = sin(alpha2)/a2 "
                       "the four axes keep meeting the same conditions and the loop moves with one freedom "
                       "(Bennett 1903)";
    mm_res_scalar_text(res, O_OVER, M != gk, note);
    mm_res_warn(res, "%s", note);
    mm_kin_rank_checks(res, sv, 4, rank, 6, 4);
    mm_series *ss = mm_res_series(res, O_SV, 4);
    if (!ss || mm_kin_joints_table(res, O_PAIRS, "1:revolute:1,2:revolute:1,3:revolute:1,4:revolute:1", err) != MM_OK)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    for (int k = 0; k < 4; k++)
        ss->x[k] = k + 1, ss->y[k] = fmax(sv[k], 1e-300);
    /* move it: th1 round the turn, th2 by Bennett's relation; the loop closes */
    double worst;
    if ((rc = mm_kin_anim_bennett(res, BA, BAL, BBE, &worst, err)) != MM_OK)
        return rc;
    /* twelve products of four transforms of size ~1: a few dozen eps */
    mm_res_check_abs(res, "Bennett's loop closes on every frame: |T1 T2 T3 T4 - I|", worst, 0, 64 * DBL_EPSILON);
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    int k = (int)in[P_LINKAGE].x;
    int rc;
    if (k == K_CUSTOM) {
        int n = (int)in[P_LINKS].x, j1 = (int)in[P_J1].x, j2 = (int)in[P_J2].x;
        int gk = 3 * (n - 1) - 2 * j1 - j2;
        mm_res_scalar(res, O_GK, gk);
        char text[200];
        snprintf(text, sizeof text, "%s", gk > 0 ? "a mechanism, if no constraint repeats another"
                                  : gk == 0 ? "a structure, unless special proportions let it move (overconstrained)"
                                            : "a structure with redundant constraints, unless special proportions "
                                              "let it move");
        mm_res_warn(res, "%d links, %d full and %d half joints: M = 3 (n - 1) - 2 j1 - j2 = %d: %s. The count sees "
                         "only the numbers; describe a preset to let the geometry speak", n, j1, j2, gk, text);
        mm_res_method(res, "Grubler-Kutzbach count", 0);
        return MM_OK;
    }
    rc = k == K_BENNETT ? spatial_bennett(res, err) : planar(&presets[k], res, err);
    mm_res_method(res, k == K_BENNETT ? "rank of the joint twists by singular values (LAPACK)"
                                      : "rank of the constraint Jacobian by singular values (LAPACK); motion by Newton",
                  0);
    return rc;
}

static const char *const references[] = {
    "R. L. Norton, Design of Machinery, 5th ed., McGraw-Hill 2012, sections 2.5-2.8",
    "G. T. Bennett, A new mechanism, Engineering 76 (1903) 777-778",
    "K. J. Waldron, The constraint analysis of mechanisms, J. Mechanisms 1 (1966) 101-114", NULL,
};

const mm_exercise mm_ex_kin_mobility = {
    .id = "kin-mobility", .chapter = 2, .section = "2.4.2",
    .title = "Mobility: counting degrees of freedom",
    .summary = "The Grubler-Kutzbach count of a linkage against the rank of its constraint equations: where the "
               "count is right, and the overconstrained linkages where it is wrong.",
    .tags = "kinematics, mechanism, mobility, degrees of freedom, Grubler, Kutzbach, overconstrained, Bennett",
    .theory = "exercises/kin/mobility.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .solve = solve,
};
