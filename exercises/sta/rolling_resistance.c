/* rolling_resistance.c — sta-rolling-resistance: a wheel on a soft
 * surface; the pull at the axle that starts it rolling, against the pull
 * that would make it slide.
 *
 *     P_roll = W a / (h cos(theta) + a sin(theta)),  h = sqrt(r^2 - a^2)   (2)
 *     P_slide = mu W / (cos(theta) + mu sin(theta))                        (3)
 *
 * Goal: rolling resistance as a forward shift a of the normal force (the
 * coefficient of rolling resistance, a length); when a wheel rolls and
 * when it slides; the approximation P = W a / r.
 * Checks: the wheel's three equilibrium equations at the rolling limit,
 * solved as a linear system for P, N and the friction F (eq. 4); the
 * friction it needs must be below mu N exactly when it rolls first.
 * Reference: Hibbeler, Statics, 14th ed., section 8.8; Meriam & Kraige,
 * Statics, article 6/10.
 */
#include <float.h>
#include <math.h>

#include "mm_equil.h"
#include "mm_exhelp.h"
#include "mm_sta.h"

enum { P_W, P_R, P_A, P_MU, P_THETA, P_POINTS };
static const mm_param params[] = {
    [P_W] = {"W", "load on the wheel", "N", MM_REAL, 1000, 1e-3, 1e7, .help = "weight plus what it carries"},
    [P_R] = {"r", "wheel radius", "m", MM_REAL, 0.3, 1e-3, 10, .help = "of the wheel"},
    [P_A] = {"a", "coefficient of rolling resistance", "m", MM_REAL, 0.005, 0, 1,
             .help = "how far ahead of the axle the ground's push acts: steel on steel 0.0005 m, a tyre on "
                     "asphalt 0.005 m, on sand 0.05 m; a < r"},
    [P_MU] = {"mu", "coefficient of friction", "", MM_REAL, 0.3, 0, 1.5, .help = "wheel on ground, static"},
    [P_THETA] = {"theta", "angle of the pull above horizontal", "rad", MM_REAL, 0, 0, 1.4,
                 .help = "the pull acts at the axle"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 91, 11, 1001, .help = "samples over the pull angle"},
};

enum { O_PROLL, O_PSLIDE, O_MODE, O_PAPPROX, O_MUB, O_ROLL, O_SLIDE, O_ANIM };
static const mm_output outputs[] = {
    [O_PROLL] = MM_SCALAR("P_roll", "pull that starts the wheel rolling", "N", .flags = MM_ANSWER | MM_EXACT),
    [O_PSLIDE] = MM_SCALAR("P_slide", "pull that would make it slide", "N", .flags = MM_ANSWER | MM_EXACT),
    [O_MODE] = MM_SCALAR("mode", "what the growing pull does first (1 rolls, 2 slides, 3 both)", "",
                         .flags = MM_ANSWER | MM_EXACT),
    [O_PAPPROX] = MM_SCALAR("P_approx", "the usual approximation W a / r (theta = 0)", "N", .flags = MM_EXACT),
    [O_MUB] = MM_SCALAR("mu_boundary", "friction below which it slides instead of rolling", "", .flags = MM_EXACT),
    [O_ROLL] = MM_SERIES("P_roll_theta", "pull to roll", "N", "theta", "rad", .figure = "P"),
    [O_SLIDE] = MM_SERIES("P_slide_theta", "pull to slide", "N", "theta", "rad", .figure = "P"),
    [O_ANIM] = MM_ANIMATION("the wheel at the rolling limit: weight, pull and the ground's reaction"),
};

static int check(const mm_value *in, mm_error *err)
{
    if (!(in[P_A].x < in[P_R].x))
        return mm_error_set(err, MM_ERANGE, "a", "the ground's push must act under the wheel: a < r = %g m; got %g",
                            in[P_R].x, in[P_A].x);
    return MM_OK;
}

static double p_roll(double W, double r, double a, double th)
{
    double h = sqrt((r - a) * (r + a));
    return W * a / (h * cos(th) + a * sin(th));       /* eq. (2) */
}

static double p_slide(double W, double mu, double th)
{
    return mu * W / (cos(th) + mu * sin(th));         /* eq. (3) */
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    double W = in[P_W].x, r = in[P_R].x, a = in[P_A].x, mu = in[P_MU].x, th = in[P_THETA].x;
    double h = sqrt((r - a) * (r + a)), Pr = p_roll(W, r, a, th), Ps = p_slide(W, mu, th);
    int mode = fabs(Pr - Ps) <= 1e-12 * fmax(Pr, Ps) ? 3 : Pr < Ps ? 1 : 2;
    static const char *const modes[] = {"", "rolls", "slides", "rolls and slides at once"};
    mm_res_scalar(res, O_PROLL, Pr);
    mm_res_scalar(res, O_PSLIDE, Ps);
    mm_res_scalar_text(res, O_MODE, mode, modes[mode]);
    mm_res_scalar(res, O_PAPPROX, W * a / r);
    /* P_roll = P_slide: the friction the rolling wheel needs, F/N at the limit */
    double F_over_N = Pr * cos(th) / (W - Pr * sin(th));
    mm_res_scalar(res, O_MUB, F_over_N);

    /* eq. (4): at the rolling limit N acts a ahead of the axle at depth h;
     * unknowns P, N, F; the axle at the origin */
    double A[9] = {cos(th), 0, -1, sin(th), 1, 0, 0, a, -h};
    double b[3] = {0, W, 0}, x[3];
    mm_equil_result er;
    int rc = mm_equil_solve(3, 3, A, b, x, NULL, NULL, &er, err);
    if (rc != MM_OK)
        return rc;
    mm_res_check_rel(res, "P_roll by the wheel's three equilibrium equations vs eq. (2)", x[0], Pr,
                     32 * DBL_EPSILON / er.rcond);
    if (mode != 3)
        mm_res_check_abs(res, "rolls first (1/0): the friction needed at P_roll is below mu N, vs P_roll < P_slide",
                         x[2] < mu * x[1], mode == 1, 0);
    /* the sliding limit: F = mu N, equilibrium of forces */
    mm_res_check_rel(res, "P_slide by the force balance with F = mu N vs eq. (3)",
                     mu * (W - Ps * sin(th)) / cos(th), Ps, 16 * DBL_EPSILON);
    mm_res_method(res, "closed forms; the wheel's equilibrium as a linear system", 0);

    int n = (int)in[P_POINTS].x;
    mm_series *sr = mm_res_series(res, O_ROLL, n), *ss = mm_res_series(res, O_SLIDE, n);
    if (!sr || !ss)
        return MM_ENOMEM;
    mm_linspace(0, 1.4, n, sr->x);
    mm_linspace(0, 1.4, n, ss->x);
    for (int i = 0; i < n; i++)
        sr->y[i] = p_roll(W, r, a, sr->x[i]), ss->y[i] = p_slide(W, mu, ss->x[i]);

    /* the drawing at the first limit */
    double P = mode == 2 ? Ps : Pr, N = W - P * sin(th), F = P * cos(th);
    double xN = mode == 2 ? 0 : a, sc = mm_sta_scale(fmax(W, P), r, 1.0);
    double ground[4] = {-1.5 * r, -h, 1.5 * r, -h};
    mm_sta_fbd(res);
    mm_sta_path(res, "ground", 2, ground, "ground");
    mm_sta_circle(res, "wheel", 0, 0, r, NULL);
    mm_sta_force(res, "W", 0, 0, 0, -W, sc, 0);
    mm_sta_force(res, "P", 0, 0, P * cos(th), P * sin(th), sc, 0);
    mm_sta_force(res, "N", xN, -h, 0, N, sc, 1);
    mm_sta_force(res, "friction", xN, -h, -F, 0, sc, 1);
    mm_sta_label(res, -r, r * 1.1, "%s first, at P = %.4g N", modes[mode], P);
    return rc;
}

static const char *const references[] = {MM_STA_HIBBELER "section 8.8", MM_STA_MERIAM "article 6/10", NULL};

const mm_exercise mm_ex_sta_rolling_resistance = {
    .id = "sta-rolling-resistance", .chapter = 3, .section = "3.8.3",
    .title = "Rolling resistance: roll or slide?",
    .summary = "The pull that starts a wheel rolling on a soft surface against the one that would make it "
               "slide; the boundary between them.",
    .tags = "statics, friction, rolling resistance, wheel, sliding", .theory = "exercises/sta/rolling_resistance.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
