/* thrust_bearing.c — sta-thrust-bearing: the friction torque of a flat
 * collar (or disc, R1 = 0) pressed axially against its seat, new (uniform
 * pressure) or worn in (uniform wear: pressure times radius constant).
 *
 *     new:  M = (2/3) mu P (R2^3 - R1^3) / (R2^2 - R1^2)                 (2)
 *     worn: M = (1/2) mu P (R1 + R2)                                     (4)
 *
 * Goal: friction torque as an integral of mu p r over the contact; why a
 * worn bearing has less torque than a new one; the pressure peak of the
 * worn one at the inner edge.
 * Checks: the pressure integrates to the load and the friction moment to
 * the closed form, both by Gauss-Legendre quadrature over the annulus
 * (exact for these integrands); M_worn < M_new.
 * Reference: Hibbeler, Statics, 14th ed., section 8.6; Meriam & Kraige,
 * Statics, article 6/8.
 */
#include <float.h>
#include <math.h>

#include "mm_exhelp.h"
#include "mm_quad.h"
#include "mm_sta.h"

enum { P_P, P_R1, P_R2, P_MU, P_WEAR, P_POINTS };
static const char *const wears[] = {"new", "worn", NULL};

static const mm_param params[] = {
    [P_P] = {"P", "axial load", "N", MM_REAL, 5000, 1e-3, 1e8, .help = "the force pressing the collar on its seat"},
    [P_R1] = {"R1", "inner radius", "m", MM_REAL, 0.02, 0, 10, .help = "of the contact ring; 0 for a solid disc"},
    [P_R2] = {"R2", "outer radius", "m", MM_REAL, 0.05, 1e-4, 10, .help = "of the contact ring; R2 > R1"},
    [P_MU] = {"mu", "coefficient of friction", "", MM_REAL, 0.1, 0, 1, .help = "between collar and seat"},
    [P_WEAR] = {"wear", "condition", "", MM_CHOICE, 0, 0, 0, NULL, wears,
                .help = "new: uniform pressure; worn: worn in until the wear, p times r, is uniform"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 101, 11, 1001, .help = "samples of the pressure over r"},
};

enum { O_M, O_MNEW, O_MWORN, O_PMAX, O_REFF, O_PNEW, O_PWORN, O_ANIM };
static const mm_output outputs[] = {
    [O_M] = MM_SCALAR("M", "friction torque in the chosen condition", "N m", .flags = MM_ANSWER | MM_EXACT),
    [O_MNEW] = MM_SCALAR("M_new", "friction torque, new (uniform pressure)", "N m", .flags = MM_EXACT),
    [O_MWORN] = MM_SCALAR("M_worn", "friction torque, worn (uniform wear)", "N m", .flags = MM_EXACT),
    [O_PMAX] = MM_SCALAR("p_max", "largest contact pressure in the chosen condition", "Pa",
                         .flags = MM_ANSWER | MM_EXACT),
    [O_REFF] = MM_SCALAR("r_eff", "friction radius M / (mu P)", "m", .flags = MM_EXACT),
    [O_PNEW] = MM_SERIES("p_new", "pressure, new", "Pa", "r", "m", .figure = "p"),
    [O_PWORN] = MM_SERIES("p_worn", "pressure, worn", "Pa", "r", "m", .figure = "p"),
    [O_ANIM] = MM_ANIMATION("the collar on its seat in section: load and contact pressure"),
};

static int check(const mm_value *in, mm_error *err)
{
    if (!(in[P_R1].x < in[P_R2].x))
        return mm_error_set(err, MM_ERANGE, "R2", "the outer radius must exceed the inner one: R2 > R1 = %g m; got %g",
                            in[P_R1].x, in[P_R2].x);
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    (void)err;
    double P = in[P_P].x, R1 = in[P_R1].x, R2 = in[P_R2].x, mu = in[P_MU].x;
    int worn = (int)in[P_WEAR].x;
    /* eq. (2) with R2 - R1 divided out, and R2^2 - R1^2 as (R2 - R1)(R2 + R1):
     * a thin ring (R2 - R1 = 1.2 mm at R1 = 5.6 m) made R2^2 - R1^2 lose
     * R/(2 (R2 - R1)) = 2400 ulps, and p_new and M_new 215 and 70 ulps;
     * R2 - R1 is exact (Sterbenz) when it is small, so these keep every bit */
    double Mnew = 2.0 / 3 * mu * P * (R2 * R2 + R1 * R2 + R1 * R1) / (R1 + R2);
    double Mworn = 0.5 * mu * P * (R1 + R2);                                             /* eq. (4) */
    double pnew = P / (M_PI * (R2 - R1) * (R2 + R1)), C = P / (2 * M_PI * (R2 - R1));   /* eqs. (1), (3) */
    double M = worn ? Mworn : Mnew;
    mm_res_scalar(res, O_M, M);
    mm_res_scalar(res, O_MNEW, Mnew);
    mm_res_scalar(res, O_MWORN, Mworn);
    if (!worn || R1 > 0)
        mm_res_scalar(res, O_PMAX, worn ? C / R1 : pnew);
    else
        mm_res_warn(res, "a worn solid disc: the pressure C / r has no upper bound at the centre (in reality the "
                         "centre wears no more and carries little)");
    if (mu > 0)
        mm_res_scalar(res, O_REFF, M / (mu * P));

    /* checks: 5-point Gauss-Legendre on 8 rings: exact for these
     * polynomials (r^2 and r), so rounding only */
    double gr[40], gw[40], F = 0, Mq = 0;
    mm_quad_gl5_nodes(R1, R2, 8, gr, gw);
    for (int i = 0; i < 40; i++) {
        double r = gr[i], p = worn ? C / r : pnew;
        F += gw[i] * p * 2 * M_PI * r;                  /* eq. (1): the ring 2 pi r dr */
        Mq += gw[i] * mu * p * 2 * M_PI * r * r;        /* its friction moment */
    }
    mm_res_check_rel(res, "integral of p over the contact vs P (quadrature)", F, P, 64 * DBL_EPSILON);
    mm_res_check_abs(res, "integral of mu p r over the contact vs the closed form [N m] (quadrature)", Mq, M,
                     64 * DBL_EPSILON * mu * P * R2);
    mm_res_check_abs(res, "M_worn <= M_new (1 = yes)", Mworn <= Mnew * (1 + 1e-14), 1, 0);
    mm_res_method(res, "closed forms; Gauss-Legendre quadrature as a check", 0);

    int n = (int)in[P_POINTS].x;
    mm_series *sn = mm_res_series(res, O_PNEW, n), *sw = mm_res_series(res, O_PWORN, n);
    if (!sn || !sw)
        return MM_ENOMEM;
    double r0 = R1 > 0 ? R1 : R2 / n;                   /* a solid worn disc: start one step out */
    mm_linspace(r0, R2, n, sn->x);
    mm_linspace(r0, R2, n, sw->x);
    for (int i = 0; i < n; i++)
        sn->y[i] = pnew, sw->y[i] = C / sw->x[i];

    /* the drawing: the section through the axis */
    mm_sta_fbd(res);
    double H = R2, shaft[8] = {-R1 * 0.9, 0, R1 * 0.9, 0, R1 * 0.9, 2 * H, -R1 * 0.9, 2 * H};
    double collar[8] = {-R2, 0, R2, 0, R2, 0.3 * H, -R2, 0.3 * H};
    double seat[8] = {-1.3 * R2, -0.3 * H, 1.3 * R2, -0.3 * H, 1.3 * R2, 0, -1.3 * R2, 0};
    mm_sta_polygon(res, "seat", 4, seat, "ground");
    mm_sta_polygon(res, "collar", 4, collar, NULL);
    if (R1 > 0)
        mm_sta_polygon(res, "shaft", 4, shaft, NULL);
    double pm = worn && R1 > 0 ? C / R1 : worn ? C / r0 : pnew, ps = 0.4 * H / pm;
    mm_sta_force(res, "P", 0, 2 * H + 0.5 * H, 0, -P, 0.5 * H / P, 0);
    for (int k = 0; k <= 6; k++) {
        double r = R1 + (R2 - R1) * k / 6;
        if (r <= 0)
            continue;
        double p = worn ? C / r : pnew;
        for (int side = -1; side <= 1; side += 2)
            mm_sta_arrow(res, "pressure", side * r, -ps * p, side * r, 0, "Pa", ps, p);
    }
    mm_sta_label(res, R2, 0.3 * H, "M = %.4g N m (%s)", M, wears[worn]);
    return MM_OK;
}

static const char *const references[] = {MM_STA_HIBBELER "section 8.6", MM_STA_MERIAM "article 6/8", NULL};

const mm_exercise mm_ex_sta_thrust_bearing = {
    .id = "sta-thrust-bearing", .chapter = 3, .section = "3.8.2",
    .title = "Thrust bearing: friction on a collar",
    .summary = "The friction torque of a collar or disc pressed on its seat, new (uniform pressure) or worn "
               "(uniform wear), as integrals over the contact.",
    .tags = "statics, friction, thrust bearing, collar, disc clutch, wear", .theory = "exercises/sta/thrust_bearing.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
