/* particle_cables.c — sta-particle-cables: a ring held in space by two or
 * three cables under a load; the cable tensions.
 *
 *     sum_i T_i u_i + P = 0,   u_i the unit vector from the ring to anchor i  (1)
 *
 * Goal: a particle's equilibrium as a linear system; why three cables hold
 * a ring in space, two only in their own plane; cables that would push.
 * Method: (1) as a 3x3 system (or 2x2 in the plane of two cables), solved by
 * mm_equil with its rank test.  Checks: the ring's sum of forces put back;
 * the tensions again by Cramer's rule as triple products (eq. 3; Lami's
 * theorem, eq. 4, for two cables).
 * Reference: Hibbeler, Statics, 14th ed., ch. 3.
 */
#include <float.h>
#include <math.h>

#include "mm_equil.h"
#include "mm_exhelp.h"
#include "mm_geom.h"
#include "mm_sta.h"

enum { P_ANCHORS, P_RING, P_LOAD };
static const mm_param params[] = {
    [P_ANCHORS] = {"anchors", "cable anchors (x, y, z per row)", "m", MM_MATRIX, 0, -1e4, 1e4,
                   "-2,-1,3;2,-1.5,3;0,2,3", NULL, 3, 3,
                   .help = "where each cable is tied: 3 rows hold the ring in space, 2 only in their plane"},
    [P_RING] = {"ring", "ring position (x, y, z)", "m", MM_VECTOR, 0, -1e4, 1e4, "0,0,0", NULL, 0, 3,
                .help = "where the cables meet"},
    [P_LOAD] = {"load", "load on the ring (Fx, Fy, Fz)", "N", MM_VECTOR, 0, -1e9, 1e9, "0,0,-1000", NULL, 0, 3,
                .help = "the weight hung on the ring (z up), or any force"},
};

enum { O_T, O_TMAX, O_TPLOT, O_ANIM };
static const mm_output outputs[] = {
    [O_T] = MM_SCALAR("T%d", "tension in cable %d", "N", .flags = MM_ANSWER, .first = 1, .last = 3),
    [O_TMAX] = MM_SCALAR("T_max", "largest tension", "N"),
    [O_TPLOT] = MM_SERIES("tension_by_cable", "cable tension", "N", "cable", "", .mark = "dots"),
    [O_ANIM] = MM_ANIMATION("the ring, its cables and the load"),
};

static int check(const mm_value *in, mm_error *err)
{
    if (in[P_ANCHORS].cols != 3 || in[P_ANCHORS].rows < 2)
        return mm_error_set(err, MM_ERANGE, "anchors", "give 2 or 3 anchors, one row x,y,z each");
    if (in[P_RING].cols != 3)
        return mm_error_set(err, MM_ERANGE, "ring", "the ring needs 3 coordinates");
    if (in[P_LOAD].cols != 3)
        return mm_error_set(err, MM_ERANGE, "load", "the load needs 3 components");
    for (int i = 0; i < in[P_ANCHORS].rows; i++) {
        const double *a = in[P_ANCHORS].data + 3 * i, *r = in[P_RING].data;
        if (hypot(hypot(a[0] - r[0], a[1] - r[1]), a[2] - r[2]) == 0)
            return mm_error_set(err, MM_ERANGE, "anchors", "anchor %d is at the ring: a cable of no length", i + 1);
    }
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    int n = in[P_ANCHORS].rows;
    const double *ring = in[P_RING].data, *P = in[P_LOAD].data;
    double u[3][3], L, T[3] = {0, 0, 0}, Tc[3], Pn = mm_sta_norm(P);   /* Tc: the second route */
    for (int i = 0; i < n; i++) {
        for (int k = 0; k < 3; k++)
            u[i][k] = in[P_ANCHORS].data[3 * i + k] - ring[k];
        L = mm_sta_norm(u[i]);
        for (int k = 0; k < 3; k++)
            u[i][k] /= L;
    }
    mm_equil_result er;
    if (n == 3) {
        double A[9], b[3] = {-P[0], -P[1], -P[2]};     /* eq. (2): the columns are the cables' unit vectors */
        for (int k = 0; k < 3; k++)
            for (int i = 0; i < 3; i++)
                A[3 * k + i] = u[i][k];
        int rc = mm_equil_solve(3, 3, A, b, T, NULL, NULL, &er, err);
        if (rc == MM_ESINGULAR)
            return mm_error_set(err, MM_ESINGULAR, "anchors", "the three cables lie in one plane: the ring can "
                                "move across it; move an anchor out of that plane");
        if (rc != MM_OK)
            return rc;
        for (int i = 0; i < 3; i++) {                   /* eq. (3), Cramer */
            double c[3];
            mm_sta_cross(u[(i + 1) % 3], u[(i + 2) % 3], c);
            Tc[i] = -mm_sta_dot(P, c) / mm_sta_dot(u[i], c);
        }
    } else {
        double nrm[3], e2[3];
        mm_sta_cross(u[0], u[1], nrm);
        double nn = mm_sta_norm(nrm);
        if (nn < 1e-9)
            return mm_error_set(err, MM_ESINGULAR, "anchors",
                                "the two cables lie on one line: they cannot hold a load across it");
        for (int k = 0; k < 3; k++)
            nrm[k] /= nn;
        if (fabs(mm_sta_dot(P, nrm)) > 1e-9 * Pn)
            return mm_error_set(err, MM_ESINGULAR, "load", "the load has %.4g N across the plane of the two "
                                "cables: the ring would swing out of it; add a third cable", mm_sta_dot(P, nrm));
        mm_sta_cross(nrm, u[0], e2);
        double A[4] = {1, mm_sta_dot(u[1], u[0]), 0, mm_sta_dot(u[1], e2)}, b[2] = {-mm_sta_dot(P, u[0]), -mm_sta_dot(P, e2)};
        int rc = mm_equil_solve(2, 2, A, b, T, NULL, NULL, &er, err);
        if (rc != MM_OK)
            return rc;
        /* eq. (4), Lami: each tension over the sine of the angle opposite */
        double a12 = mm_geom_angle3(u[0], u[1]), mP[3] = {-P[0], -P[1], -P[2]};   /* atan2: accurate near 0, pi */
        Tc[0] = Pn * sin(mm_geom_angle3(u[1], mP)) / sin(a12);
        Tc[1] = Pn * sin(mm_geom_angle3(u[0], mP)) / sin(a12);
    }
    double rerr = 4 * DBL_EPSILON * Pn / er.rcond;      /* cond * eps of the load */
    for (int i = 0; i < n; i++) {
        if (T[i] < -1e-9 * Pn)
            return mm_error_set(err, MM_ESINGULAR, "anchors",
                                "cable %d would have to push (T = %.4g N): a cable can only pull; the load must "
                                "point away from the anchors, inside the cone of the cables", i + 1, T[i]);
        if (fabs(T[i]) <= rerr)
            T[i] = 0;                                   /* a slack cable: 0, not rounding */
    }
    double Tmax = mm_sta_reactions(res, O_T, O_TPLOT, n, T, rerr);   /* no cable pushes: largest |T| = largest T */
    mm_res_scalar_err(res, O_TMAX, Tmax, rerr, MM_ERR_ESTIMATE);
    /* check 1: the ring in equilibrium, eq. (1) */
    double sum[3] = {P[0], P[1], P[2]}, scale = Pn;
    for (int i = 0; i < n; i++) {
        for (int k = 0; k < 3; k++)
            sum[k] += T[i] * u[i][k];
        scale += fabs(T[i]);
    }
    mm_check_residual(res, "ring: |sum of forces| [N]", mm_sta_norm(sum), scale, 16);
    /* check 2: the tensions by the closed form */
    int wi = mm_sta_worst(n, Tc, T, 1);
    mm_sta_check_absf(res, Tc[wi], T[wi], 16 * DBL_EPSILON * Pn / er.rcond, "cable %d: %s vs the linear solve [N]",
                      wi + 1, n == 3 ? "Cramer's rule (triple products, eq. 3)" : "Lami's theorem (eq. 4)");
    mm_res_method(res, "equilibrium of the ring as a linear system (LU with the rank test)", 0);
    if (er.rcond < 1e-3)
        mm_res_warn(res, "the cables are nearly in one plane (condition %.2g): small changes of the load "
                         "change the tensions a lot", 1 / er.rcond);
    /* the drawing */
    mm_sta_fbd(res);
    mm_sta_cables3(res, n, ring, in[P_ANCHORS].data, T, u, P, fmax(Pn, Tmax), 1e-9 * Pn);
    return MM_OK;
}

static const char *const references[] = {MM_STA_HIBBELER "ch. 3", NULL};

const mm_exercise mm_ex_sta_particle_cables = {
    .id = "sta-particle-cables", .chapter = 3, .section = "3.3",
    .title = "A ring held by cables",
    .summary = "Equilibrium of a particle in space: the tensions in two or three cables holding a loaded ring.",
    .tags = "statics, particle, equilibrium, cables, tension, space", .theory = "exercises/sta/particle_cables.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
