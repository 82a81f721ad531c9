/* virtual_work.c — sta-virtual-work: the torque that holds a slider-crank
 * mechanism in equilibrium against a force on its slider, by the principle
 * of virtual work, against a direct force balance of its three bodies.
 *
 *     x_B = r cos(theta) + sqrt(l^2 - (e - r sin(theta))^2)           (1)
 *     M dtheta - P dx_B = 0  =>  M = P dx_B/dtheta                     (2)
 *
 * Goal: virtual work needs no reaction at all (pins, guide, rod force do
 * no work), only the geometry's derivative; the potential energy with M
 * held fixed shows the equilibrium and others, stable or unstable.
 * Checks: M by the eight equilibrium equations of crank, rod and slider
 * (eq. 4) against (2); dx_B/dtheta against a central difference of (1);
 * the equations' residual.  The other equilibria of the potential (5),
 * classified by its second derivative, are marked on its plot.
 * Reference: Hibbeler, Statics, 14th ed., sections 11.1-11.3; Meriam &
 * Kraige, Statics, articles 7/1-7/2.
 */
#include <float.h>
#include <math.h>

#include "mm_equil.h"
#include "mm_exhelp.h"
#include "mm_roots.h"
#include "mm_sta.h"

enum { P_R, P_L, P_E, P_THETA, P_P, P_POINTS };
static const mm_param params[] = {
    [P_R] = {"r", "crank length", "m", MM_REAL, 0.1, 1e-3, 10, .help = "from the pivot O to the crank pin A"},
    [P_L] = {"l", "rod length", "m", MM_REAL, 0.4, 1e-3, 100, .help = "from A to the slider pin B; l > r + |e|"},
    [P_E] = {"e", "offset of the slider's line", "m", MM_REAL, 0, -10, 10, .help = "the slider moves on y = e"},
    [P_THETA] = {"theta", "crank angle", "rad", MM_REAL, M_PI / 3, -10, 10, .help = "from the x axis, counter-clockwise"},
    [P_P] = {"P", "force on the slider", "N", MM_REAL, 1000, -1e7, 1e7,
             .help = "pushing the slider toward the crank (along -x); negative pulls it away"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 361, 37, 3601, .help = "samples over one turn"},
};

enum { O_M, O_DX, O_XB, O_FROD, O_N, O_V, O_STABLE, O_UNSTABLE, O_MREQ, O_ANIM };
static const mm_output outputs[] = {
    [O_M] = MM_SCALAR("M", "torque on the crank that holds it (counter-clockwise +)", "N m",
                      .flags = MM_ANSWER | MM_EXACT),
    [O_DX] = MM_SCALAR("dx_dtheta", "virtual displacement ratio dx_B/dtheta", "m", .flags = MM_EXACT),
    [O_XB] = MM_SCALAR("x_B", "slider position", "m", .flags = MM_EXACT),
    [O_FROD] = MM_SCALAR("F_rod", "force in the rod (tension +)", "N", .flags = MM_ANSWER),
    [O_N] = MM_SCALAR("N", "guide on the slider (+y)", "N"),
    [O_V] = MM_SERIES("V", "potential energy with M held: -M theta + P x_B", "J", "theta", "rad", .figure = "V"),
    [O_STABLE] = MM_SERIES("stable", "stable equilibria", "J", "theta", "rad", .figure = "V", .mark = "dots"),
    [O_UNSTABLE] = MM_SERIES("unstable", "unstable equilibria", "J", "theta", "rad", .figure = "V", .mark = "dots"),
    [O_MREQ] = MM_SERIES("M_hold", "torque that holds the crank at each angle", "N m", "theta", "rad", .figure = "M"),
    [O_ANIM] = MM_ANIMATION("the mechanism with the load, the holding torque and the virtual displacement"),
};

typedef struct mech { double r, l, e, P, M; } mech;

static double xB(const mech *m, double t, double *dx, double *d2x)
{
    double d = m->e - m->r * sin(t), s = sqrt((m->l - d) * (m->l + d)), c = cos(t), sn = sin(t);
    if (dx)
        *dx = -m->r * sn + d * m->r * c / s;                                     /* eq. (3) */
    if (d2x)
        *d2x = -m->r * c + m->r * (-m->r * c * c - d * sn) / s - d * d * m->r * m->r * c * c / (s * s * s);
    return m->r * c + s;                                                          /* eq. (1) */
}

static int dV_fn(double t, double *f, void *p)
{
    const mech *m = p;
    double dx;
    xB(m, t, &dx, NULL);
    *f = -m->M + m->P * dx;                                                       /* eq. (5) */
    return 0;
}

static int check(const mm_value *in, mm_error *err)
{
    if (!(in[P_L].x > in[P_R].x + fabs(in[P_E].x)))
        return mm_error_set(err, MM_ERANGE, "l", "the rod must be longer than r + |e| = %g m for the crank to turn "
                            "a full circle; got %g", in[P_R].x + fabs(in[P_E].x), in[P_L].x);
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    mech m = {in[P_R].x, in[P_L].x, in[P_E].x, in[P_P].x, 0};
    double th = in[P_THETA].x, dx, x = xB(&m, th, &dx, NULL);
    m.M = m.P * dx;                                                               /* eq. (2) */
    mm_res_scalar(res, O_M, m.M);
    mm_res_scalar(res, O_DX, dx);
    mm_res_scalar(res, O_XB, x);
    /* eq. (4): crank, rod, slider; unknowns Ox Oy Ax Ay Bx By N M (A: rod on
     * crank, B: slider on rod) */
    double xa = m.r * cos(th), ya = m.r * sin(th), xb = x, yb = m.e;
    double A[64] = {
        1, 0, 1, 0, 0, 0, 0, 0,
        0, 1, 0, 1, 0, 0, 0, 0,
        0, 0, -ya, xa, 0, 0, 0, 1,
        0, 0, -1, 0, 1, 0, 0, 0,
        0, 0, 0, -1, 0, 1, 0, 0,
        0, 0, 0, 0, -(yb - ya), xb - xa, 0, 0,
        0, 0, 0, 0, -1, 0, 0, 0,
        0, 0, 0, 0, 0, -1, 1, 0,
    };
    double b[8] = {0, 0, 0, 0, 0, 0, m.P, 0}, u[8];
    mm_equil_result er;
    int rc = mm_equil_solve(8, 8, A, b, u, NULL, NULL, &er, err);
    if (rc != MM_OK)
        return rc;
    double scale = fabs(m.P) * (m.r + m.l), ferr = 4 * DBL_EPSILON * fabs(m.P) / er.rcond;
    double Frod = (u[4] * (xb - xa) + u[5] * (yb - ya)) / m.l;
    mm_res_scalar_err(res, O_FROD, Frod, ferr, MM_ERR_ESTIMATE);
    mm_res_scalar_err(res, O_N, u[6], ferr, MM_ERR_ESTIMATE);
    mm_res_check_abs(res, "M by the force balance of crank, rod and slider vs virtual work [N m]", u[7], m.M,
                     64 * DBL_EPSILON * scale / er.rcond);
    double res8, sc8;
    mm_equil_residual(8, 8, A, b, u, &res8, &sc8);
    mm_check_residual(res, "the eight equilibrium equations, largest residual", res8, sc8, 16);
    /* dx_B/dtheta against a central difference (truncation h^2 x'''/6, x''' by a difference of x'') */
    double h = 1e-5, hh = 1e-3, xp = xB(&m, th + h, NULL, NULL), xm = xB(&m, th - h, NULL, NULL), d2p, d2m;
    xB(&m, th + hh, NULL, &d2p), xB(&m, th - hh, NULL, &d2m);
    double x3 = fabs(d2p - d2m) / (2 * hh);        /* |x'''|, itself by a difference: doubled below */
    mm_res_check_abs(res, "dx_B/dtheta vs a central difference of x_B [m] (truncation and rounding)",
                     (xp - xm) / (2 * h), dx, h * h * (2 * x3 + m.r) / 6 + 4 * DBL_EPSILON * (m.r + m.l) / h);
    mm_res_method(res, "virtual work (closed form); force balance as a linear system", 0);
    /* the potential with M held, its equilibria over a turn (eq. 5) */
    int np = (int)in[P_POINTS].x;
    mm_series *sv = mm_res_series(res, O_V, np), *sm = mm_res_series(res, O_MREQ, np);
    if (!sv || !sm)
        return MM_ENOMEM;
    mm_linspace(0, 2 * M_PI, np, sv->x);
    mm_linspace(0, 2 * M_PI, np, sm->x);
    for (int i = 0; i < np; i++) {
        double d;
        sv->y[i] = -m.M * sv->x[i] + m.P * xB(&m, sv->x[i], &d, NULL);
        sm->y[i] = m.P * d;
    }
    if (m.P != 0) {
        enum { NSUB = 360 };
        mm_roots_root roots[NSUB + 1];
        mm_roots_result rr;
        if (mm_roots_scan(dV_fn, &m, 0, 2 * M_PI, NSUB, 1e-13, 0, roots, &rr, err) != MM_OK)
            rr.nroots = 0;                        /* the plot then marks theta only */
        /* the given angle is an equilibrium by construction (a double root
         * of V' where the torque curve peaks, so not always bracketed): put
         * it in, and leave out a root found at it */
        double eq[NSUB + 2];
        int ne = 0;
        eq[ne++] = remainder(th - M_PI, 2 * M_PI) + M_PI;
        for (int i = 0; i < rr.nroots; i++)
            if (fabs(remainder(roots[i].x - th, 2 * M_PI)) > 1e-9)
                eq[ne++] = roots[i].x;
        static const int outs[2] = {O_STABLE, O_UNSTABLE};
        int kind[NSUB + 2];
        double v[NSUB + 2];
        for (int i = 0; i < ne; i++) {
            double q;
            v[i] = -m.M * eq[i] + m.P * xB(&m, eq[i], NULL, &q);
            kind[i] = m.P * q > 0 ? 0 : 1;        /* V'' = P x_B'': 0 stable, 1 unstable */
        }
        mm_sta_equilibria(res, ne, eq, v, kind, 2, outs);
    }
    /* the drawing */
    mm_sta_fbd(res);
    mm_sta_slider_crank(res, m.r, m.l, m.e, th, xb, Frod, ferr, m.P, m.M, dx);
    return rc;
}

static const char *const references[] = {MM_STA_HIBBELER "sections 11.1-11.3", MM_STA_MERIAM "articles 7/1-7/2", NULL};

const mm_exercise mm_ex_sta_virtual_work = {
    .id = "sta-virtual-work", .chapter = 3, .section = "3.12",
    .title = "Virtual work: the torque that holds a slider-crank",
    .summary = "The holding torque of a slider-crank under a load, by virtual work in one line, against the "
               "force balance of its three bodies; the potential energy and its equilibria.",
    .tags = "statics, virtual work, mechanism, slider-crank, potential energy",
    .theory = "exercises/sta/virtual_work.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
