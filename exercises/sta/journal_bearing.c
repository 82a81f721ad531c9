/* journal_bearing.c — sta-journal-bearing: a pulley turning on a fixed
 * axle (a journal bearing) with dry friction; the pull needed to raise a
 * load over it, and the friction circle.
 *
 *     r_f = r sin(phi),  phi = atan(mu)                                  (2)
 *     T_raise = W (R + r_f) / (R - r_f),  T_lower = W (R - r_f) / (R + r_f)  (3)
 *
 * Goal: the friction circle: at impending rotation the bearing reaction
 * leans by the friction angle and its line is tangent to a circle of
 * radius r sin(phi); the range of pulls in which the pulley stays put;
 * the efficiency.
 * Checks: the contact problem solved without the friction circle: the
 * contact point's angle, the normal force and the pull from the three
 * equilibrium equations with friction at its limit, by Newton's method
 * (eq. 4), for raising and for lowering.
 * Reference: Hibbeler, Statics, 14th ed., section 8.7; Meriam & Kraige,
 * Statics, article 6/7.
 */
#include <float.h>
#include <math.h>

#include "mm_geom.h"
#include "mm_sta.h"

enum { P_W, P_R, P_RJ, P_MU };
static const mm_param params[] = {
    [P_W] = {"W", "load", "N", MM_REAL, 1000, 1e-3, 1e7, .help = "the weight on one side of the rope"},
    [P_R] = {"R", "pulley radius", "m", MM_REAL, 0.15, 1e-3, 10, .help = "where the rope runs"},
    [P_RJ] = {"r", "journal radius", "m", MM_REAL, 0.02, 1e-4, 10, .help = "the axle the pulley turns on; r < R"},
    [P_MU] = {"mu", "coefficient of friction", "", MM_REAL, 0.2, 0, 1, .help = "between the axle and the hub"},
};

enum { O_PHI, O_RF, O_TR, O_TL, O_MF, O_ETA, O_RFA, O_TRMU, O_TLMU, O_ANIM };
static const mm_output outputs[] = {
    [O_PHI] = MM_SCALAR("phi", "friction angle atan(mu)", "rad", .flags = MM_EXACT),
    [O_RF] = MM_SCALAR("r_f", "radius of the friction circle r sin(phi)", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_TR] = MM_SCALAR("T_raise", "pull that starts raising the load", "N", .flags = MM_ANSWER | MM_EXACT),
    [O_TL] = MM_SCALAR("T_lower", "pull below which the load starts down", "N", .flags = MM_ANSWER | MM_EXACT),
    [O_MF] = MM_SCALAR("M_f", "friction torque in the bearing while raising", "N m", .flags = MM_ANSWER | MM_EXACT),
    [O_ETA] = MM_SCALAR("efficiency", "W / T_raise", "", .flags = MM_EXACT),
    [O_RFA] = MM_SCALAR("r_f_approx", "small-friction approximation mu r", "m", .flags = MM_EXACT),
    [O_TRMU] = MM_SERIES("T_raise_mu", "pull to raise", "N", "mu", "", .figure = "T"),
    [O_TLMU] = MM_SERIES("T_lower_mu", "pull below which it runs down", "N", "mu", "", .figure = "T"),
    [O_ANIM] = MM_ANIMATION("the pulley on its axle: load, pull and the bearing reaction on the friction circle"),
};

static int check(const mm_value *in, mm_error *err)
{
    if (!(in[P_RJ].x < in[P_R].x))
        return mm_error_set(err, MM_ERANGE, "r", "the journal must be smaller than the pulley: r < R = %g m; got %g",
                            in[P_R].x, in[P_RJ].x);
    return MM_OK;
}

/* eq. (4): the hub on the axle at the contact angle th from straight below,
 * normal N, friction s mu N against the turning (s = +1 raising); unknowns
 * (N, th, T).  Newton's method from the frictionless guess. */
static int contact(double W, double R, double r, double mu, double s, double *x, int *iters)
{
    x[0] = 2 * W, x[1] = 0, x[2] = W;
    for (int it = 1; it <= 50; it++) {
        double N = x[0], c = cos(x[1]), sn = sin(x[1]), m = s * mu;
        double f[3] = {-N * sn + m * N * c, N * c + m * N * sn - x[2] - W, W * R - x[2] * R + m * N * r};
        double J[9] = {-sn + m * c, -N * c - m * N * sn, 0,
                       c + m * sn, -N * sn + m * N * c, -1,
                       m * r, 0, -R};
        double det = mm_geom_m3_det(J), d[3];
        for (int k = 0; k < 3; k++) {                    /* Cramer on the 3x3 */
            double Mk[9];
            for (int i = 0; i < 9; i++)
                Mk[i] = i % 3 == k ? -f[i / 3] : J[i];
            d[k] = mm_geom_m3_det(Mk) / det;
        }
        for (int k = 0; k < 3; k++)
            x[k] += d[k];
        *iters = it;
        if (fabs(d[0]) <= 4 * DBL_EPSILON * fabs(x[0]) && fabs(d[1]) <= 4 * DBL_EPSILON &&
            fabs(d[2]) <= 4 * DBL_EPSILON * fabs(x[2]))
            return MM_OK;
    }
    return MM_ENOCONV;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    double W = in[P_W].x, R = in[P_R].x, r = in[P_RJ].x, mu = in[P_MU].x;
    double phi = atan(mu), rf = r * sin(phi);                         /* eq. (2) */
    double Tr = W * (R + rf) / (R - rf), Tl = W * (R - rf) / (R + rf);  /* eq. (3) */
    mm_res_scalar(res, O_PHI, phi);
    mm_res_scalar(res, O_RF, rf);
    mm_res_scalar(res, O_TR, Tr);
    mm_res_scalar(res, O_TL, Tl);
    mm_res_scalar(res, O_MF, (Tr + W) * rf);
    mm_res_scalar(res, O_ETA, W / Tr);
    mm_res_scalar(res, O_RFA, mu * r);
    double xr[3], xl[3];                                  /* the check: eq. (4), raising and lowering */
    int ir, il;
    if (contact(W, R, r, mu, 1, xr, &ir) != MM_OK || contact(W, R, r, mu, -1, xl, &il) != MM_OK)
        return mm_error_set(err, MM_ENOCONV, "mu", "the contact equations did not converge");
    /* Newton on well-scaled equations: a few eps of the forces */
    mm_res_check_rel(res, "T_raise by the contact equations (Newton) vs eq. (3)", xr[2], Tr, 32 * DBL_EPSILON);
    mm_res_check_rel(res, "T_lower by the contact equations (Newton) vs eq. (3)", xl[2], Tl, 32 * DBL_EPSILON);
    mm_res_check_abs(res, "contact angle from straight below while raising vs phi [rad]", xr[1], phi, 32 * DBL_EPSILON);
    mm_res_check_abs(res, "the reaction's line: its distance from the centre vs r_f [m]", r * sin(xr[1]), rf,
                     32 * DBL_EPSILON * r);
    mm_series *s1 = mm_res_series(res, O_TRMU, 101), *s2 = mm_res_series(res, O_TLMU, 101);
    if (!s1 || !s2)
        return MM_ENOMEM;
    for (int i = 0; i <= 100; i++) {
        double m = i / 100.0, f = r * sin(atan(m));
        s1->x[i] = s2->x[i] = m;
        s1->y[i] = W * (R + f) / (R - f), s2->y[i] = W * (R - f) / (R + f);
    }
    mm_res_method(res, "friction circle (closed form); contact equations by Newton's method as a check", 0);
    mm_res_method_stat(res, "newton_iterations", ir + il);
    if (mu > 0.3)
        mm_res_warn(res, "mu r = %.4g m overestimates r_f = r sin(phi) = %.4g m by %.1f %%: the small-friction "
                         "approximation fails here", mu * r, rf, 100 * (mu * r / rf - 1));

    /* the drawing */
    mm_sta_fbd(res);
    double sc = mm_sta_scale(Tr + W, R, 0.6), rope = 1.6 * R;
    double ropeL[4] = {-R, 0, -R, -rope}, ropeR[4] = {R, 0, R, -rope};
    mm_sta_circle(res, "pulley", 0, 0, R, NULL);
    mm_sta_circle(res, "axle", 0, 0, r, "ground");
    if (rf > 0)
        mm_sta_circle(res, "friction circle", 0, 0, rf, "highlight");
    mm_sta_path(res, "rope to the load", 2, ropeL, "tension");
    mm_sta_path(res, "rope pulled", 2, ropeR, "tension");
    mm_sta_force(res, "W", -R, -rope, 0, -W, sc, 0);
    mm_sta_force(res, "T", R, -rope, 0, -Tr, sc, 0);
    mm_sta_force(res, "bearing reaction", r * sin(phi), -r * cos(phi), 0, Tr + W, sc, 0);
    mm_sta_label(res, R, -rope - sc * Tr, "T = %.4g N", Tr);
    mm_sta_label(res, -R, -rope - sc * W, "W = %.4g N", W);
    return MM_OK;
}

static const char *const references[] = {MM_STA_HIBBELER "section 8.7", MM_STA_MERIAM "article 6/7", NULL};

const mm_exercise mm_ex_sta_journal_bearing = {
    .id = "sta-journal-bearing", .chapter = 3, .section = "3.8.1",
    .title = "Journal bearing: the friction circle",
    .summary = "A pulley on an axle with friction: the pull that raises a load, the friction circle, the "
               "efficiency; checked by solving the contact equations.",
    .tags = "statics, friction, journal bearing, friction circle, pulley, efficiency",
    .theory = "exercises/sta/journal_bearing.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
