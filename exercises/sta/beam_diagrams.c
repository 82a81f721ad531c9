/* beam_diagrams.c — sta-beam-diagrams: shear force and bending moment
 * diagrams of a simply supported, overhanging or cantilever beam under
 * point loads anywhere, uniform or linearly varying distributed loads and
 * couples; with EI, the deflection line.
 *
 * Goal: V and M as exact piecewise polynomials (eqs. 4-5 of
 * beam_diagrams.md): where they jump, where they peak, dV/dx = q and
 * dM/dx = V; the deflection by EI y'' = M (7).
 * Checks: the whole beam's two equilibrium equations with the reactions;
 * the diagrams summed load by load must close to zero past x = L; dV/dx =
 * q and dM/dx = V in integral form on every segment (Gauss-Legendre, exact
 * here) and by central differences at its middle (with the difference's
 * own truncation error); with EI, the largest deflection again by virtual
 * work (the unit-load method, eq. 9) and y = 0 at the supports.
 * Reference: Hibbeler, Statics, 14th ed., ch. 7; J. M. Gere, B. J. Goodno,
 * Mechanics of Materials, ch. 4 and 9.
 */
#include <float.h>
#include <math.h>

#include "mm_beam.h"
#include "mm_exhelp.h"
#include "mm_sta.h"

enum { P_L, P_SUPPORTS, P_A, P_B, P_POINT, P_DIST, P_MOMENTS, P_EI, P_POINTS };
static const char *const support_kinds[] = {"simply-supported", "cantilever", "overhanging", NULL};
static const mm_param params[] = {
    [P_L] = {"L", "length", "m", MM_REAL, 4, 0.01, 100, .help = "the beam runs from x = 0 to x = L"},
    [P_SUPPORTS] = {"supports", "supports", "", MM_CHOICE, 0, 0, 0, NULL, support_kinds,
                    .help = "a pin at a and a roller at b (simply supported: a = 0, b = L; overhanging: "
                            "anywhere), or a cantilever clamped at x = 0"},
    [P_A] = {"a", "pin position", "m", MM_REAL, 0, 0, 100, .help = "x of the pin (not used by a cantilever)"},
    [P_B] = {"b", "roller position", "m", MM_REAL, 4, 0, 100,
             .help = "x of the roller, right of the pin (not used by a cantilever)"},
    [P_POINT] = {"point_loads", "point loads (x, Fy per row)", "N", MM_MATRIX, 0, -1e9, 1e9, "2,-1000", NULL, 50,
                 2, .help = "one row per force: where (m) and how much (N, up positive); anywhere on the beam"},
    [P_DIST] = {"distributed", "distributed loads (x1, x2, q1, q2 per row)", "N/m", MM_MATRIX, 0, -1e9, 1e9, "",
                NULL, 20, 4,
                .help = "one row per load varying linearly from q1 at x1 to q2 at x2 (N/m, up positive); "
                        "none by default"},
    [P_MOMENTS] = {"moments", "couples (x, C per row)", "N m", MM_MATRIX, 0, -1e9, 1e9, "", NULL, 20, 2,
                   .help = "one row per couple: where and how much (counter-clockwise positive); none by default"},
    [P_EI] = {"EI", "bending stiffness", "N m^2", MM_REAL, 0, 0, 1e12,
              .help = "E times I; 0 leaves out the deflection (a steel IPE 200 has about 4e6)"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 401, 51, 2001,
                  .help = "samples of the diagrams (each jump is shown by both its one-sided values)"},
};

enum { O_VEXT, O_XV, O_MEXT, O_XM, O_YMAX, O_XY, O_V, O_M, O_Y, O_VPT, O_MPT, O_REACT, O_ANIM };
static const char *const rcols[] = {"x", "Ry", "C", NULL};
static const char *const runits[] = {"m", "N", "N m", NULL};
static const mm_output outputs[] = {
    [O_VEXT] = MM_SCALAR("V_extreme", "shear force of largest magnitude", "N", .flags = MM_ANSWER | MM_EXACT),
    [O_XV] = MM_SCALAR("x_V_extreme", "where it occurs", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_MEXT] = MM_SCALAR("M_extreme", "bending moment of largest magnitude", "N m", .flags = MM_ANSWER | MM_EXACT),
    [O_XM] = MM_SCALAR("x_M_extreme", "where it occurs", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_YMAX] = MM_SCALAR("y_max", "deflection of largest magnitude (up positive)", "m", .flags = MM_ANSWER),
    [O_XY] = MM_SCALAR("x_y_max", "where it occurs", "m", .flags = MM_ANSWER),
    [O_V] = MM_SERIES("V", "shear force V: sum of the forces left of x (up +)", "N", "x", "m", .figure = "V"),
    [O_M] = MM_SERIES("M", "bending moment M (sagging +)", "N m", "x", "m", .figure = "M"),
    [O_Y] = MM_SERIES("y", "deflection (up +)", "m", "x", "m", .figure = "y"),
    [O_VPT] = MM_SERIES("V_extreme_point", "largest |V|", "N", "x", "m", .figure = "V", .mark = "dots"),
    [O_MPT] = MM_SERIES("M_extreme_point", "largest |M|", "N m", "x", "m", .figure = "M", .mark = "dots"),
    [O_REACT] = MM_TABLE("reactions", "support reactions (Ry up +, C counter-clockwise +)", rcols, runits),
    [O_ANIM] = MM_ANIMATION("the beam with its supports, loads and reactions"),
};

static int problem(const mm_value *in, mm_beam_problem *p, mm_error *err)
{
    if (mm_sta_rows(&in[P_POINT], "point_loads", "point load", "x,Fy", 2, err) ||
        mm_sta_rows(&in[P_DIST], "distributed", "distributed load", "x1,x2,q1,q2", 4, err) ||
        mm_sta_rows(&in[P_MOMENTS], "moments", "couple", "x,C", 2, err))
        return MM_ERANGE;
    *p = (mm_beam_problem){.L = in[P_L].x, .a = in[P_A].x, .b = in[P_B].x,
                           .kind = (int)in[P_SUPPORTS].x == 1 ? MM_BEAM_CANTILEVER : MM_BEAM_TWO_SUPPORTS,
                           .n_point = in[P_POINT].rows, .point = in[P_POINT].data,
                           .n_dist = in[P_DIST].rows, .dist = in[P_DIST].data, .n_moment = in[P_MOMENTS].rows,
                           .moment = in[P_MOMENTS].data, .EI = in[P_EI].x};
    return mm_beam_check(p, err);
}

static int check(const mm_value *in, mm_error *err)
{
    mm_beam_problem p;
    return problem(in, &p, err);
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    mm_beam_problem p;
    int rc = problem(in, &p, err);
    if (rc != MM_OK)
        return rc;
    mm_beam *b;
    if ((rc = mm_beam_solve(&p, &b, err)) != MM_OK)
        return rc;
    double Vext, xV, Mext, xM;
    mm_beam_extreme_V(b, &Vext, &xV);
    mm_beam_extreme_M(b, &Mext, &xM);
    const double ext[] = {Vext, xV, Mext, xM};                      /* O_VEXT ... O_XM */
    for (int k = 0; k < 4; k++)
        mm_res_scalar(res, O_VEXT + k, ext[k]);
    double rx[2], ry[2], rcpl[2];
    int nr = mm_beam_reactions(b, rx, ry, rcpl);
    mm_table *rt = mm_res_table(res, O_REACT, nr);          /* NULL: the failure is kept in res */
    for (int k = 0; rt && k < nr; k++)
        rt->cell[3 * k] = rx[k], rt->cell[3 * k + 1] = ry[k], rt->cell[3 * k + 2] = rcpl[k];
    /* check 1: the whole beam, eqs. (2)-(3) with the reactions found */
    double Fy, Mo, sF, sM;
    mm_beam_residual(&p, b, &Fy, &Mo, &sF, &sM);
    mm_check_residual(res, "whole beam: sum Fy of loads and reactions [N]", Fy, sF, 32);
    mm_check_residual(res, "whole beam: sum M about x = 0 [N m]", Mo, sM, 32);
    /* check 2: the diagrams summed load by load close past x = L */
    double Ve, Me, Vsum, Msum;
    mm_beam_closure(b, &Ve, &Me, &Vsum, &Msum);
    mm_check_residual(res, "V just right of x = L, after every load [N]", Ve, Vsum, 32);
    mm_check_residual(res, "M just right of x = L, after every load [N m]", Me, Msum, 32);
    /* check 3: dV/dx = q and dM/dx = V on every segment, integrated (exact
     * Gauss-Legendre) and by central differences at its middle (less their
     * truncation), each against the rounding of the segment's terms */
    const double *xs;
    int nb = mm_beam_breaks(b, &xs);
    double wi, wd;
    mm_beam_derivative_check(b, &wi, &wd);
    mm_res_check_abs(res, "dM/dx = V, dV/dx = q integrated over every segment (Gauss-Legendre): worst "
                          "difference / its rounding tolerance", wi, 0, 1);
    mm_res_check_abs(res, "dM/dx = V, dV/dx = q by central differences at every segment's middle: worst "
                          "difference (less the truncation h^2 q'/6) / its rounding tolerance", wd, 0, 1);
    int n = (int)in[P_POINTS].x;
    double ymax = 0, xy = 0;
    if (p.EI > 0) {
        mm_beam_extreme_y(b, &ymax, &xy);
        double yv, yscale;
        if ((rc = mm_beam_unit_load(b, xy, &yv, &yscale, err)) != MM_OK) {
            mm_beam_free(b);
            return rc;
        }
        /* y_max: a root of the slope bisected to the last bit, the
         * polynomial evaluated there: rounding of its terms */
        mm_res_scalar_err(res, O_YMAX, ymax, 64 * DBL_EPSILON * yscale, MM_ERR_ESTIMATE);
        mm_res_scalar_err(res, O_XY, xy, 64 * DBL_EPSILON * p.L, MM_ERR_ESTIMATE);
        mm_res_check_abs(res, "y_max by virtual work (unit load at x_y_max) vs the integrated line [m]", yv, ymax,
                         64 * DBL_EPSILON * yscale);
        double worst = 0;
        for (int k = 0; k < (p.kind == MM_BEAM_CANTILEVER ? 1 : 2); k++) {
            mm_beam_value v;
            mm_beam_eval(b, p.kind == MM_BEAM_CANTILEVER ? 0 : (k ? p.b : p.a), 1, &v);
            worst = fmax(worst, fabs(v.y));
        }
        mm_check_residual(res, "y at the supports [m]", worst, yscale, 64.0 * nb);
    }
    /* the diagrams, each jump by both its one-sided values */
    mm_series *vp = mm_res_series(res, O_VPT, 1), *mp = mm_res_series(res, O_MPT, 1);
    if (!vp || !mp || mm_sta_beam_diagrams(res, b, n, p.EI > 0, O_V, O_M, O_Y) != MM_OK) {
        mm_beam_free(b);
        return MM_ENOMEM;
    }
    vp->x[0] = xV, vp->y[0] = Vext;
    mp->x[0] = xM, mp->y[0] = Mext;
    int kind = (int)in[P_SUPPORTS].x;
    if (kind == 0 && (p.a != 0 || p.b != p.L))
        mm_res_warn(res, "the supports at a = %g m and b = %g m are not at the ends (0 and %g m): the beam "
                         "overhangs", p.a, p.b, p.L);
    if (kind == 1 && (p.a != 0 || p.b != 4))
        mm_res_warn(res, "a cantilever is clamped at x = 0: a and b are not used");
    mm_res_method(res, "exact piecewise polynomials between the load points (V quadratic, M cubic, y quintic)", 0);
    mm_sta_fbd(res);
    rc = mm_sta_beam(res, &p, b, Mext, xM);
    mm_beam_free(b);
    return rc;
}

static const char *const references[] = {
    MM_STA_HIBBELER "ch. 7", "J. M. Gere, B. J. Goodno, Mechanics of Materials, 8th ed., Cengage 2013, ch. 4 and 9",
    NULL,
};

const mm_exercise mm_ex_sta_beam_diagrams = {
    .id = "sta-beam-diagrams", .chapter = 3, .section = "3.10",
    .title = "Shear force and bending moment diagrams",
    .summary = "Simply supported, overhanging or cantilever beams under point, distributed and couple loads: "
               "exact V and M diagrams, their extremes and the deflection.",
    .tags = "statics, beam, shear force, bending moment, internal forces, deflection",
    .theory = "exercises/sta/beam_diagrams.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
