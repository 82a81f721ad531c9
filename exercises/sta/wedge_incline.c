/* wedge_incline.c — sta-wedge-incline: dry friction at its limit on two
 * classics: a block on an incline pushed up the slope (does it slide or
 * tip first?), and a wedge driven under a load guided by a wall.
 *
 * Block: P_up = W (sin a + mu cos a), P_hold = W (sin a - mu cos a) (or 0),
 *        P_tip = W (w cos a + h sin a) / (2 hP)                  (2)-(4)
 * Wedge: P_in = W tan(beta + 2 phi), P_out = W tan(beta - 2 phi),
 *        phi = atan mu                                            (6)-(7)
 * Goal: the tipping/slipping boundary found and named, self-locking, the
 * friction angle; closed forms beside the numbers.
 * Method and checks: the closed forms are printed; the same equilibrium is
 * solved as a linear system with friction at its limit (mm_equil), and
 * for the block the position of the normal force tells whether it slides
 * or tips (eq. 5), in agreement with comparing P_up and P_tip.
 * Reference: Hibbeler, Statics, 14th ed., sections 8.1-8.3; Meriam &
 * Kraige, Statics, articles 6/3-6/5.
 */
#include <float.h>
#include <math.h>

#include "mm_equil.h"
#include "mm_exhelp.h"
#include "mm_sta.h"

enum { P_SETUP, P_W, P_MU, P_ALPHA, P_WIDTH, P_H, P_HP, P_BETA };
static const char *const setups[] = {"block", "wedge", NULL};

static const mm_param params[] = {
    [P_SETUP] = {"setup", "setup", "", MM_CHOICE, 0, 0, 0, NULL, setups,
                 .help = "a block pushed up an incline, or a wedge driven under a load against a wall"},
    [P_W] = {"W", "weight", "N", MM_REAL, 1000, 1e-3, 1e7, .help = "of the block, or of the load on the wedge"},
    [P_MU] = {"mu", "coefficient of friction", "", MM_REAL, 0.4, 0, 1.5,
              .help = "static, the same on every surface; the friction angle is atan(mu)"},
    [P_ALPHA] = {"alpha", "incline angle", "rad", MM_REAL, 0.3, 0, 1.4, .help = "block: the slope of the incline"},
    [P_WIDTH] = {"w", "block length along the slope", "m", MM_REAL, 0.5, 1e-3, 100, .help = "block: its base"},
    [P_H] = {"h", "block height", "m", MM_REAL, 0.8, 1e-3, 100, .help = "block: across the slope"},
    [P_HP] = {"hP", "height of the push", "m", MM_REAL, 0.4, 0, 100,
              .help = "block: how far above the slope the push (parallel to it) acts on the lower face"},
    [P_BETA] = {"beta", "wedge angle", "rad", MM_REAL, 0.2, 0.01, 1.0, .help = "wedge: the angle of its sloped face"},
};

enum { O_PUP, O_PHOLD, O_PTIP, O_FIRST, O_ASLIP, O_ATIP, O_PIN, O_POUT, O_LOCK, O_N1, O_N2, O_N3, O_SUP, O_STIP,
       O_SIN, O_SOUT, O_ANIM };
static const mm_output outputs[] = {
    [O_PUP] = MM_SCALAR("P_up", "push that starts the block sliding up", "N", .flags = MM_ANSWER | MM_EXACT),
    [O_PHOLD] = MM_SCALAR("P_hold", "least push that keeps it from sliding down", "N", .flags = MM_ANSWER | MM_EXACT),
    [O_PTIP] = MM_SCALAR("P_tip", "push that tips it over its upper edge", "N", .flags = MM_ANSWER | MM_EXACT),
    [O_FIRST] = MM_SCALAR("first", "as the push grows (1 slides up, 2 tips, 3 both at once)", "",
                          .flags = MM_ANSWER | MM_EXACT),
    [O_ASLIP] = MM_SCALAR("alpha_slip", "incline at which the block slides down by itself, atan(mu)", "rad",
                          .flags = MM_EXACT),
    [O_ATIP] = MM_SCALAR("alpha_tip", "incline at which it tips over by itself, atan(w/h)", "rad", .flags = MM_EXACT),
    [O_PIN] = MM_SCALAR("P_in", "push that drives the wedge in and lifts the load", "N", .flags = MM_ANSWER | MM_EXACT),
    [O_POUT] = MM_SCALAR("P_out", "push at which the wedge starts to slip out (negative: a pull is needed)", "N",
                         .flags = MM_ANSWER | MM_EXACT),
    [O_LOCK] = MM_SCALAR("self_locking", "the wedge stays when the push is removed (1) or slips out (0)", "",
                         .flags = MM_ANSWER | MM_EXACT),
    [O_N1] = MM_SCALAR("N1", "floor on wedge, normal force (driving in)", "N"),
    [O_N2] = MM_SCALAR("N2", "wedge on load, normal force (driving in)", "N"),
    [O_N3] = MM_SCALAR("N3", "wall on load, normal force (driving in)", "N"),
    [O_SUP] = MM_SERIES("P_up_alpha", "push to slide up", "N", "alpha", "rad", .figure = "block"),
    [O_STIP] = MM_SERIES("P_tip_alpha", "push to tip", "N", "alpha", "rad", .figure = "block"),
    [O_SIN] = MM_SERIES("P_in_beta", "push to drive the wedge in", "N", "beta", "rad", .figure = "wedge"),
    [O_SOUT] = MM_SERIES("P_out_beta", "push at which it slips out (negative: pull)", "N", "beta", "rad",
                         .figure = "wedge"),
    [O_ANIM] = MM_ANIMATION("the free-body diagram at the slipping or tipping limit"),
};

static int check(const mm_value *in, mm_error *err)
{
    if ((int)in[P_SETUP].x == 0 && in[P_HP].x > in[P_H].x)
        return mm_error_set(err, MM_ERANGE, "hP", "the push must act on the block's face: hP <= h = %g m; got %g",
                            in[P_H].x, in[P_HP].x);
    if ((int)in[P_SETUP].x == 0 && in[P_HP].x == 0)
        return mm_error_set(err, MM_ERANGE, "hP", "a push at hP = 0 can never tip the block; give hP > 0");
    if ((int)in[P_SETUP].x == 1 && in[P_BETA].x + 2 * atan(in[P_MU].x) >= M_PI / 2 - 1e-3)
        return mm_error_set(err, MM_ERANGE, "mu",
                            "the wedge jams: beta + 2 atan(mu) = %.4g rad reaches pi/2, so no push can drive "
                            "it; lower mu or beta", in[P_BETA].x + 2 * atan(in[P_MU].x));
    return MM_OK;
}

/* ---- the block, in the slope frame: s up the slope, n across it; the
 * block's downhill bottom corner at the origin, its base from s = 0 to w */
static int block(const mm_value *in, mm_result *res, mm_error *err)
{
    double W = in[P_W].x, mu = in[P_MU].x, a = in[P_ALPHA].x, w = in[P_WIDTH].x, h = in[P_H].x, hP = in[P_HP].x;
    double sa = sin(a), ca = cos(a);
    double Pup = W * (sa + mu * ca);                                   /* eq. (2) */
    double down = sa - mu * ca, lim = 8 * DBL_EPSILON * (sa + mu * ca), Phold = down > lim ? W * down : 0; /* (3) */
    double Ptip = W * (w * ca + h * sa) / (2 * hP);                    /* eq. (4) */
    int first = fabs(Pup - Ptip) <= 1e-12 * Pup ? 3 : Pup < Ptip ? 1 : 2;
    static const char *const firsts[] = {"", "slides up", "tips over its upper edge", "slides and tips at once"};
    mm_res_scalar(res, O_PUP, Pup);
    mm_res_scalar_text(res, O_PHOLD, Phold, down > lim           ? "it would slide down without it"
                                            : fabs(down) <= lim ? "at the slip limit: mu = tan(alpha)"
                                                                : "self-locking: it stays without a push");
    mm_res_scalar(res, O_PTIP, Ptip);
    mm_res_scalar_text(res, O_FIRST, first, firsts[first]);
    mm_res_scalar(res, O_ASLIP, atan(mu));
    mm_res_scalar(res, O_ATIP, atan(w / h));
    /* route 2, eq. (5): sliding up, friction mu N down the slope; unknowns
     * P, N and m = N x_N (x_N where N acts on the base) */
    double A[9] = {1, -mu, 0, 0, 1, 0, -hP, 0, 1};
    /* tipping: N at the upper edge x_N = w, friction F unknown (below its limit) */
    double B[9] = {1, 0, -1, 0, 1, 0, -hP, w, 0};
    double b[3] = {W * sa, W * ca, W * w * ca / 2 - W * h * sa / 2}, x[3], t[3];
    mm_equil_result er;
    int rc = mm_equil_solve(3, 3, A, b, x, NULL, NULL, &er, err);
    if (rc == MM_OK)
        rc = mm_equil_solve(3, 3, B, b, t, NULL, NULL, &er, err);
    if (rc != MM_OK)
        return rc;
    mm_res_check_rel(res, "P_up by the equilibrium equations with friction at its limit vs eq. (2)", x[0], Pup,
                     16 * DBL_EPSILON);
    mm_res_check_rel(res, "P_tip by the equilibrium equations with N at the upper edge vs eq. (4)", t[0], Ptip,
                     16 * DBL_EPSILON);
    /* the slide-or-tip decision twice: tips first <=> at P_up, N would act
     * beyond the upper edge <=> at P_tip, friction is still below mu N */
    double xN = x[2] / x[1];
    if (first != 3) {
        mm_res_check_abs(res, "tips first (1/0): N beyond the upper edge at P_up, vs P_tip < P_up", xN > w,
                         first == 2, 0);
        mm_res_check_abs(res, "tips first (1/0): friction below mu N at P_tip, vs P_tip < P_up", t[2] < mu * t[1],
                         first == 2, 0);
    }
    mm_res_method(res, "closed forms; equilibrium with friction at the limit as a linear system", 0);
    mm_series *s1 = mm_res_series(res, O_SUP, 141), *s2 = mm_res_series(res, O_STIP, 141);
    if (!s1 || !s2)
        return MM_ENOMEM;
    for (int i = 0; i <= 140; i++) {
        double q = i / 100.0;
        s1->x[i] = s2->x[i] = q;
        s1->y[i] = W * (sin(q) + mu * cos(q));
        s2->y[i] = W * (w * cos(q) + h * sin(q)) / (2 * hP);
    }
    /* the drawing at the first limit: friction F down the slope, N where it acts */
    double P = first == 2 ? Ptip : Pup;
    mm_sta_fbd(res);
    mm_sta_block_incline(res, a, w, h, hP, W, P, W * ca, P - W * sa, first == 2 ? w : xN, firsts[first]);
    return rc;
}

/* ---- the wedge.  Eq. (8): wedge moving +x under the load, which rises
 * against a wall on its right; s = +1 driving in, -1 starting out (every
 * friction reversed).  Unknowns N1 (floor), N2 (incline), N3 (wall), P. */
static int wedge_solve(double W, double mu, double be, double s, double *x, mm_equil_result *er, mm_error *err)
{
    double sb = sin(be), cb = cos(be), m = s * mu;
    double A[16] = {
        0, sb + m * cb, -1, 0,                 /* load x */
        0, cb - m * sb, -m, 0,                 /* load y */
        -m, -(sb + m * cb), 0, 1,              /* wedge x */
        1, -(cb - m * sb), 0, 0,               /* wedge y */
    };
    double b[4] = {0, W, 0, 0};
    return mm_equil_solve(4, 4, A, b, x, NULL, NULL, er, err);
}

static int wedge(const mm_value *in, mm_result *res, mm_error *err)
{
    double W = in[P_W].x, mu = in[P_MU].x, be = in[P_BETA].x, phi = atan(mu);
    double Pin = W * tan(be + 2 * phi), Pout = W * tan(be - 2 * phi);   /* eqs. (6)-(7) */
    int lock = be < 2 * phi;
    mm_res_scalar(res, O_PIN, Pin);
    mm_res_scalar(res, O_POUT, Pout);
    mm_res_scalar_text(res, O_LOCK, lock, lock ? "self-locking: beta < 2 atan(mu)" : "slips out by itself");
    double x[4], y[4];
    mm_equil_result er, eo;
    int rc = wedge_solve(W, mu, be, 1, x, &er, err);
    if (rc == MM_OK)
        rc = wedge_solve(W, mu, be, -1, y, &eo, err);
    if (rc != MM_OK)
        return rc;
    double e = 4 * DBL_EPSILON * W / er.rcond;
    for (int k = 0; k < 3; k++)
        mm_res_scalar_err(res, O_N1 + k, x[k], e, MM_ERR_ESTIMATE);
    mm_res_check_rel(res, "P_in by the two bodies' equilibrium with friction at the limit vs W tan(beta + 2 phi)",
                     x[3], Pin, 64 * DBL_EPSILON / er.rcond);
    mm_res_check_abs(res, "P_out the same way vs W tan(beta - 2 phi) [N]", y[3], Pout,
                     64 * DBL_EPSILON * W / eo.rcond);
    mm_res_method(res, "closed forms with the friction angle; equilibrium as a linear system", 0);
    double bmax = fmin(1.0, M_PI / 2 - 2 * phi - 0.02);
    mm_series *s1 = mm_res_series(res, O_SIN, 101), *s2 = mm_res_series(res, O_SOUT, 101);
    if (!s1 || !s2)
        return MM_ENOMEM;
    for (int i = 0; i <= 100; i++) {
        double q = 0.01 + (bmax - 0.01) * i / 100;
        s1->x[i] = s2->x[i] = q;
        s1->y[i] = W * tan(q + 2 * phi), s2->y[i] = W * tan(q - 2 * phi);
    }
    /* the drawing: floor, wall, wedge (thick end left), load box */
    mm_sta_fbd(res);
    mm_sta_wedge(res, be, W, Pin, Pout, x);
    return rc;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    return (int)in[P_SETUP].x == 0 ? block(in, res, err) : wedge(in, res, err);
}

static const char *const references[] = {MM_STA_HIBBELER "sections 8.1-8.3", MM_STA_MERIAM "articles 6/3-6/5", NULL};

const mm_exercise mm_ex_sta_wedge_incline = {
    .id = "sta-wedge-incline", .chapter = 3, .section = "3.8",
    .title = "Dry friction: a block on an incline and a wedge",
    .summary = "Does the pushed block slide or tip first? What push drives a wedge, and is it self-locking? "
               "Dry friction at its limit, closed forms beside the numbers.",
    .tags = "statics, friction, incline, wedge, tipping, self-locking", .theory = "exercises/sta/wedge_incline.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
