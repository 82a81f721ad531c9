/* truss.c — sta-truss: any planar truss by the method of joints, written
 * as one linear system (eq. 1 of truss.md), with the determinacy count
 * m + r - 2j (eq. 2) and the rank test (eq. 3) that tells a mechanism from
 * a redundant member in mechanics words.
 *
 * Goal: see a truss carry its load by tension and compression alone; learn
 * why m + r = 2j is needed but not enough (collinear members, a panel
 * without a diagonal), and why nearly collinear members need huge forces.
 * Checks: every joint's sum of forces recomputed from the forces found
 * (round-off), the whole truss's three equilibrium equations, the
 * reactions by the whole truss as one rigid body (Ritter's moments, when
 * the supports give three components), and the method of sections on
 * every straight cut through three members (Ritter), independent of the
 * joint equations.
 * Reference: R. C. Hibbeler, Engineering Mechanics: Statics, 14th ed.,
 * ch. 6; J. L. Meriam, L. G. Kraige, Engineering Mechanics: Statics,
 * ch. 4.
 */
#include <float.h>
#include <math.h>

#include "mm_exhelp.h"
#include "mm_sta.h"
#include "mm_truss.h"

enum { P_NODES, P_MEMBERS, P_SUPPORTS, P_LOADS };
static const mm_param params[] = {
    [P_NODES] = {"nodes", "joints (x, y per row)", "m", MM_MATRIX, 0, -1e4, 1e4, "0,0;4,0;8,0;2,3;6,3", NULL,
                 MM_TRUSS_MAX_NODES, 2,
                 .help = "one row x,y per joint, numbered from 1 in this order; at most 100 joints "
                         "(the rank test is cubic in their number)"},
    [P_MEMBERS] = {"members", "members (joint i, joint j per row)", "", MM_MATRIX, 0, 1, MM_TRUSS_MAX_NODES,
                   "1,2;2,3;4,5;1,4;4,2;2,5;5,3", NULL, MM_TRUSS_MAX_MEMBERS, 2,
                   .help = "one row i,j per straight two-force member between joints i and j; at most 300"},
    [P_SUPPORTS] = {"supports", "supports (joint, fix_x, fix_y per row)", "", MM_MATRIX, 0, 0,
                    MM_TRUSS_MAX_NODES, "1,1,1;3,0,1", NULL, MM_TRUSS_MAX_SUPPORTS, 3,
                    .help = "one row per supported joint: 1,1 a pin (fixes x and y), 0,1 a roller on "
                            "level ground, 1,0 a roller on a wall"},
    [P_LOADS] = {"loads", "loads (joint, Fx, Fy per row)", "N", MM_MATRIX, 0, -1e9, 1e9, "2,0,-10000", NULL,
                 MM_TRUSS_MAX_LOADS, 3,
                 .help = "one row per load: the joint it acts on and its components (+y up); at most 100 rows"},
};

enum { O_DET, O_NJ, O_NM, O_NR, O_TMAX, O_CMAX, O_MEMBERS, O_REACT, O_FPLOT, O_ANIM };
static const char *const mcols[] = {"member", "force", "joint_i", "joint_j", "length", "state", NULL};
static const char *const munits[] = {"", "N", "", "", "m", "", NULL};
static const char *const rcols[] = {"node", "Rx", "Ry", NULL};
static const char *const runits[] = {"", "N", "N", NULL};
static const mm_output outputs[] = {
    [O_DET] = MM_SCALAR("determinacy", "determinacy m + r - 2j", "", .flags = MM_ANSWER | MM_EXACT),
    [O_NJ] = MM_SCALAR("n_joints", "joints j", "", .flags = MM_EXACT),
    [O_NM] = MM_SCALAR("n_members", "members m", "", .flags = MM_EXACT),
    [O_NR] = MM_SCALAR("n_reactions", "reaction components r", "", .flags = MM_EXACT),
    [O_TMAX] = MM_SCALAR("max_tension", "largest tension (0 if none)", "N", .flags = MM_ANSWER),
    [O_CMAX] = MM_SCALAR("max_compression", "largest compression (most negative force, 0 if none)", "N",
                         .flags = MM_ANSWER),
    [O_MEMBERS] = MM_TABLE("members", "member forces (tension positive)", mcols, munits),
    [O_REACT] = MM_TABLE("reactions", "support reactions", rcols, runits),
    [O_FPLOT] = MM_SERIES("force_by_member", "member force (tension +)", "N", "member", "", .mark = "dots"),
    [O_ANIM] = MM_ANIMATION("the truss: members in tension and compression, loads and reactions"),
};

/* The truss from the parameters: joints numbered from 1 turned into 0-based
 * indices, with the storage the mm_truss points into. */
typedef struct model {
    int ends[2 * MM_TRUSS_MAX_MEMBERS], sup[3 * MM_TRUSS_MAX_SUPPORTS], lnode[MM_TRUSS_MAX_LOADS];
    double lf[2 * MM_TRUSS_MAX_LOADS];
    mm_truss t;
} model;

/* A joint number: a whole number from 1 to nj, as a 0-based index. */
static int joint(double v, int nj, int *out)
{
    if (!(v == floor(v)) || v < 1 || v > nj)
        return 0;
    *out = (int)v - 1;
    return 1;
}

static int load_model(const mm_value *in, model *m, mm_error *err)
{
    const mm_value *N = &in[P_NODES], *E = &in[P_MEMBERS], *S = &in[P_SUPPORTS], *F = &in[P_LOADS];
    int nj = N->rows;
    if (N->cols != 2)
        return mm_error_set(err, MM_ERANGE, "nodes", "each joint is one row x,y; got rows of %d numbers", N->cols);
    if (E->cols != 2)
        return mm_error_set(err, MM_ERANGE, "members", "each member is one row i,j; got rows of %d numbers",
                            E->cols);
    if (S->cols != 3)
        return mm_error_set(err, MM_ERANGE, "supports",
                            "each support is one row joint,fix_x,fix_y; got rows of %d numbers", S->cols);
    if (F->cols != 3)
        return mm_error_set(err, MM_ERANGE, "loads", "each load is one row joint,Fx,Fy; got rows of %d numbers",
                            F->cols);
    for (int e = 0; e < E->rows; e++)
        for (int k = 0; k < 2; k++)
            if (!joint(E->data[2 * e + k], nj, &m->ends[2 * e + k]))
                return mm_error_set(err, MM_ERANGE, "members",
                                    "member %d: joint %g is not one of the joints 1 to %d", e + 1,
                                    E->data[2 * e + k], nj);
    for (int s = 0; s < S->rows; s++) {
        const double *r = S->data + 3 * s;
        if (!joint(r[0], nj, &m->sup[3 * s]))
            return mm_error_set(err, MM_ERANGE, "supports", "support %d: joint %g is not one of the joints 1 to %d",
                                s + 1, r[0], nj);
        for (int k = 1; k < 3; k++) {
            if (r[k] != 0 && r[k] != 1)
                return mm_error_set(err, MM_ERANGE, "supports",
                                    "support %d: fix_x and fix_y are 1 (fixed) or 0 (free); got %g", s + 1, r[k]);
            m->sup[3 * s + k] = (int)r[k];
        }
    }
    for (int l = 0; l < F->rows; l++) {
        if (!joint(F->data[3 * l], nj, &m->lnode[l]))
            return mm_error_set(err, MM_ERANGE, "loads", "load %d: joint %g is not one of the joints 1 to %d",
                                l + 1, F->data[3 * l], nj);
        m->lf[2 * l] = F->data[3 * l + 1], m->lf[2 * l + 1] = F->data[3 * l + 2];
    }
    m->t = (mm_truss){nj, N->data, E->rows, m->ends, S->rows, m->sup, F->rows, m->lnode, m->lf};
    return mm_truss_check(&m->t, err);
}

static int check(const mm_value *in, mm_error *err)
{
    model m;
    return load_model(in, &m, err);
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    model md;
    int rc = load_model(in, &md, err);
    if (rc != MM_OK)
        return rc;
    const mm_truss *t = &md.t;
    int m = t->n_members, nj = t->n_nodes;
    double *F = mm_res_alloc(res, (size_t)m * sizeof *F), *R = mm_res_alloc(res, 2 * (size_t)nj * sizeof *R);
    if (!F || !R)
        return MM_ENOMEM;
    mm_truss_result tr = {.force = F, .reaction = R};
    rc = mm_truss_solve(t, &tr, err);
    if (rc != MM_OK)
        return rc;                     /* a mechanism or indeterminate: 422 in mechanics words */
    double Fbig = 0, pmax = 0, tmax = 0, cmax = 0;
    for (int e = 0; e < m; e++) {
        Fbig = fmax(Fbig, fabs(F[e]));
        tmax = fmax(tmax, F[e]);
        cmax = fmin(cmax, F[e]);
    }
    for (int l = 0; l < t->n_loads; l++)
        pmax = fmax(pmax, hypot(t->load_f[2 * l], t->load_f[2 * l + 1]));
    /* forward error of the forces: cond * eps * |F| (rcond estimated, eq. 4) */
    double ferr = 4 * DBL_EPSILON * Fbig / tr.eq.rcond, ftol = 1e-9 * fmax(pmax, Fbig);
    mm_scalar *d = mm_res_scalar(res, O_DET, tr.determinacy);
    d->text = "determinate";
    mm_res_scalar(res, O_NJ, nj);
    mm_res_scalar(res, O_NM, m);
    mm_res_scalar(res, O_NR, tr.n_reactions);
    mm_res_scalar_err(res, O_TMAX, tmax, ferr, MM_ERR_ESTIMATE);
    mm_res_scalar_err(res, O_CMAX, cmax, ferr, MM_ERR_ESTIMATE);
    if (mm_sta_truss_tables(res, t, F, R, ferr, ftol, O_MEMBERS, O_FPLOT, O_REACT) != MM_OK)
        return MM_ENOMEM;
    mm_res_method(res, "method of joints: sparse LU with partial pivoting, rank test by QR", 0);
    mm_res_method_stat(res, "rcond", tr.eq.rcond);

    /* check 1: every joint, the forces put back into eq. (1) */
    double worst, scale, total;
    mm_truss_joint_residual(t, F, R, &worst, &scale, &total);
    mm_check_residual(res, "joints: largest |sum F| at a joint [N] (scale: its largest sum of |terms|)", worst,
                      scale, 16);
    /* check 2: the whole truss as one body; it is the sum of the joint
     * equations, so it inherits their rounding (scale: every joint's terms) */
    mm_truss_body_residual(t, R, &worst, &scale);
    mm_check_residual(res, "whole truss: sum Fx, sum Fy, sum M / size of loads and reactions [N]", worst,
                      scale + total, 16);
    /* check 3: reactions by Ritter's moments on the whole truss, eq. (5) */
    double *Rr = mm_res_alloc(res, 2 * (size_t)nj * sizeof *Rr);
    if (!Rr)
        return MM_ENOMEM;
    int rigid = mm_truss_reactions_rigid(t, Rr);
    if (rigid) {
        double dw = 0;
        for (int k = 0; k < 2 * nj; k++)
            dw = fmax(dw, fabs(Rr[k] - R[k]));
        mm_res_check_abs(res, "reactions: whole truss by moments (Ritter) vs joints, largest difference [N]", dw,
                         0, 64 * DBL_EPSILON * (Fbig + pmax) / tr.eq.rcond);
    }
    /* check 4: the method of sections, eq. (6), independent of eq. (1)
     * when the reactions came from check 3 */
    double *Fs = mm_res_alloc(res, (size_t)m * sizeof *Fs), *Ss = mm_res_alloc(res, (size_t)m * sizeof *Ss);
    int *cnt = mm_res_alloc(res, (size_t)m * sizeof *cnt);
    if (!Fs || !Ss || !cnt)
        return MM_ENOMEM;
    int cuts = mm_truss_sections(t, rigid ? Rr : R, Fs, cnt, Ss);
    if (cuts > 0) {
        int worst_e = -1, found = 0;
        double ratio = -1, tol_w = 0;
        for (int e = 0; e < m; e++) {
            if (!cnt[e])
                continue;
            found++;
            double tol = 64 * DBL_EPSILON * (Ss[e] + (Fbig + pmax) / tr.eq.rcond);
            double r = fabs(Fs[e] - F[e]) / tol;
            if (r > ratio)
                ratio = r, worst_e = e, tol_w = tol;
        }
        mm_sta_check_absf(res, Fs[worst_e], F[worst_e], tol_w, "method of sections: %d cut%s, %d member%s; member %d "
                          "by the section vs the joints [N]", cuts, cuts > 1 ? "s" : "", found, found > 1 ? "s" : "",
                          worst_e + 1);
    } else {
        mm_res_warn(res, "no straight cut crosses exactly three members here, so the method of sections "
                         "is not shown; the joint and whole-truss checks still apply");
    }
    /* nearly collinear joints: forces of about 1/sin(spread) times the load */
    double spread[MM_TRUSS_MAX_NODES];
    mm_truss_spread(t, spread);
    for (int j = 0, shown = 0; j < nj && shown < 5; j++)
        if (spread[j] > 0 && spread[j] < 5 * M_PI / 180) {
            mm_res_warn(res, "joint %d: its members lie within %.3g deg of one line, so a load across that "
                             "line needs forces about %.0f times larger (1/sin %.3g deg)",
                        j + 1, spread[j] * 180 / M_PI, 1 / sin(spread[j]), spread[j] * 180 / M_PI);
            shown++;
        }
    if (tr.eq.rcond < 1e-8)
        mm_res_warn(res, "the joint equations are nearly singular (condition about %.1e): the forces have "
                         "about %.0f correct digits",
                    1 / tr.eq.rcond, fmax(0, 16 - log10(1 / tr.eq.rcond)));
    mm_sta_fbd(res);
    return mm_sta_truss(res, t, F, R, pmax, ftol);
}

static const char *const references[] = {
    MM_STA_HIBBELER "ch. 6 (trusses)",
    MM_STA_MERIAM "ch. 4",
    "S. Pellegrino, C. R. Calladine, Matrix analysis of statically and kinematically indeterminate frameworks, "
    "Int. J. Solids Structures 22 (1986) 409-428",
    NULL,
};

const mm_exercise mm_ex_sta_truss = {
    .id = "sta-truss", .chapter = 3, .section = "3.7",
    .title = "Plane trusses by the method of joints",
    .summary = "Any planar truss: member forces in tension and compression, reactions, and whether it is a "
               "mechanism or has a redundant member.",
    .tags = "statics, truss, method of joints, method of sections, determinacy, mechanism",
    .theory = "exercises/sta/truss.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
