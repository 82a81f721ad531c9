/* coulomb.c — vib-coulomb: a mass on a spring sliding on a rough floor.
 *
 *     m x'' + k x = -mu m g sign(x'),   x(0) = x0,  x'(0) = v0          (1)
 *
 * Between two velocity zeros the mass swings on a harmonic arc about a
 * shifted centre, losing 2 mu m g / k of amplitude per half cycle, and it
 * stops for good where the spring can no longer beat static friction.
 * Goal: see the linear decay and the final stop away from x = 0, and learn
 * to integrate a discontinuous right-hand side honestly: integrate each
 * smooth piece (friction sign frozen), stop at the velocity zero as an
 * event (mm_ode's event location), decide there whether the mass sticks or
 * turns, and restart (mm_coulomb_integrate).  No step ever straddles the
 * switch, so nothing chatters.  The answers (stop time, final place, the rests, the plotted
 * motion) come from the exact piecewise solution, eqs. (3)-(6); the
 * event-driven integration is shown beside them with its error.
 * Reference: S. S. Rao, Mechanical Vibrations, 6th ed., section 2.9
 * (Coulomb damping); Hairer, Norsett, Wanner, Solving ODE I, section II.6
 * (dense output and event location).
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "mm_coulomb.h"
#include "mm_exhelp.h"
#include "mm_vib.h"

enum { P_M, P_K, P_MU, P_G, P_X0, P_V0, P_POINTS };

static const mm_param params[] = {
    [P_M] = {"m", "mass", "kg", MM_REAL, 1, 1e-3, 1e3,
             .help = "the sliding mass, 1 g to 1 t (a lab model to a machine)"},
    [P_K] = {"k", "stiffness", "N/m", MM_REAL, 100, 1e-2, 1e6,
             .help = "spring force per metre of stretch; with m it sets omega_n between 3e-3 and 3e4 rad/s"},
    [P_MU] = {"mu", "friction coefficient", "", MM_REAL, 0.1, 1e-3, 2,
              .help = "one coefficient for sticking and sliding: the friction force is at most mu m g; "
                      "real pairs of materials lie between 0.001 (lubricated) and 2"},
    [P_G] = {"g", "gravity", "m/s^2", MM_REAL, 9.81, 0.1, 100,
             .help = "acceleration of gravity, which presses the mass on the floor (the Moon's 1.6 to 10 g)"},
    [P_X0] = {"x0", "initial displacement", "m", MM_REAL, 0.1, -1, 1,
              .help = "stretch of the spring at t = 0; within 1 m, where a linear spring is a fair model"},
    [P_V0] = {"v0", "initial velocity", "m/s", MM_REAL, 0, -10, 10,
              .help = "dx/dt at t = 0; the number of swings is limited to 2000 (the work of one request)"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 501, 11, 4001,
                  .help = "samples of the time response returned for the plot (a plot shows no more)"},
};

enum { O_OMEGA_N, O_BAND, O_DECAY, O_STOP, O_XF, O_HALF, O_SPRING_F, O_FRIC, O_XT, O_VT, O_ERR, O_AMP,
       O_RESTS, O_ANIM };

static const char *const rest_cols[] = {"t", "x", "spring_over_friction", NULL};
static const char *const rest_units[] = {"s", "m", "", NULL};

static const mm_output outputs[] = {
    [O_OMEGA_N] = MM_SCALAR("omega_n", "natural frequency sqrt(k/m)", "rad/s", .flags = MM_EXACT),
    [O_BAND] = MM_SCALAR("friction_band", "friction band mu m g / k", "m", .flags = MM_EXACT),
    [O_DECAY] = MM_SCALAR("decay_per_cycle", "amplitude lost per cycle 4 mu m g / k", "m",
                          .flags = MM_ANSWER | MM_EXACT),
    [O_STOP] = MM_SCALAR("stop_time", "time the mass stops for good, eqs. (3)-(6)", "s", .flags = MM_ANSWER | MM_EXACT),
    [O_XF] = MM_SCALAR("x_final", "final position, eqs. (4)-(6)", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_HALF] = MM_SCALAR("half_cycles", "sliding arcs (half cycles) before the stop", "", .flags = MM_EXACT),
    [O_SPRING_F] = MM_SCALAR("spring_force_final", "spring force at the stop, |k x_final|", "N", .flags = MM_EXACT),
    [O_FRIC] = MM_SCALAR("friction_limit", "largest friction force mu m g", "N", .flags = MM_EXACT),
    [O_XT] = MM_SERIES("x", "displacement (exact)", "m", "t", "s", .figure = "response"),
    [O_VT] = MM_SERIES("v", "velocity (exact)", "m/s", "t", "s", .figure = "velocity"),
    [O_ERR] = MM_SERIES("error_events", "x integrated with events minus the exact x", "m", "t", "s", .figure = "error"),
    [O_AMP] = MM_SERIES("amplitude", "distance from x = 0 at each rest", "m", "t", "s", .figure = "response",
                        .mark = "dots", .role = "reference"),
    [O_RESTS] = MM_TABLE("rests", "the rests: time, place, spring force over the friction limit", rest_cols,
                         rest_units),
    [O_ANIM] = MM_ANIMATION("the block on its spring, sliding on the rough floor"),
};

/* Most sliding arcs (half cycles) one request may integrate. */
#define MAX_ARCS 2000

typedef mm_coulomb model;

static model model_of(const mm_value *in)
{
    return mm_coulomb_make(in[P_M].x, in[P_K].x, in[P_MU].x, in[P_G].x, in[P_X0].x, in[P_V0].x);
}

static int check(const mm_value *in, mm_error *err)
{
    model s = model_of(in);
    double n = mm_coulomb_arc_count(&s);
    if (n > MAX_ARCS)
        return mm_error_set(err, MM_ERANGE, "mu",
                            "the mass would slide %.3g half cycles before it stops (each loses "
                            "2 mu m g/k = %.3g m); at most %d fit one request: raise mu or start "
                            "nearer rest", n, 2 * s.d, MAX_ARCS);
    return MM_OK;
}

/* The numerical rests against the exact ones and against the energy
 * balance (7).  Each arc maps its start from rest x_s to its end 2 c - x_s
 * (eq. 4), an affine map of slope -1: the error of the n-th rest is the
 * alternating sum of the errors made on each arc, at most the sum of their
 * sizes; each is estimated by the same arc integrated again from the same
 * start at rtol 1e-14.  Two whole runs at rtol and rtol / 100 give no
 * estimate: on long decays both made the same ~1e-12 relative error an arc
 * (measured: 7.2e-12 m on 7.9 m arcs at rtol 1e-10 and 1e-12 alike, 8.8e-14
 * at 1e-14), and 1900 such arcs put x_final 7.3e-9 m off where their
 * difference said 2.5e-10.
 * The arc times add up, and so do the arcs' energy residuals.  Each check
 * allows ten times that sum, plus round-off.
 *
 * The knife edge of eq. (6): a rest within the integrated position's error
 * of the band's edge |x| = d may be decided either way, and the run that
 * turns slides one more arc of amplitude |x| - d (below that error: x0 =
 * 25 d came back at d (1 + 1.9e-9), 7.6e-12 m out, at rtol 1e-10), so the
 * stop time jumps by half a period.  The counts may then differ by one,
 * and the stop time and place are compared at the last rest both runs
 * have; the answer says so. */
static void checks(const model *s, const mm_coulomb_run *a, const double *te, const double *xe, int ne, double size,
                   mm_result *res)
{
    double fric = s->mu * s->m * s->g, rt = mm_ex_roundoff(a->n * M_PI, 1);
    double tol_x = 10 * a->sum_dx + rt * size;
    int m = a->n < ne ? a->n : ne;                 /* rests both runs have */
    int knife = abs(a->n - ne) == 1 && m > 0 && fabs(fabs(xe[m - 1]) - s->d) <= tol_x;
    if (knife)
        mm_res_warn(res, "knife edge of eq. (6): the rest at t = %.6g s lies %.2g m from the edge of the sticking band "
                         "|x| <= mu m g/k, within the integration's error (%.2g m): the exact solution %s there, the "
                         "integrated run %s; the stop time jumps by half a period (%.4g s) across this edge",
                    te[m - 1], fabs(fabs(xe[m - 1]) - s->d), tol_x, ne == m ? "stops" : "slides one more half cycle",
                    a->n == m ? "stops" : "slides one more half cycle", M_PI / s->w);
    int last = knife ? m : a->n, last_e = knife ? m : ne;
    double xf = last ? a->x[last - 1] : s->x0, tf = last ? a->t[last - 1] : 0;
    mm_res_check_abs(res, "half cycles: counted by events vs the exact solution", a->n, ne, knife);
    mm_res_check_abs(res, "stop time: located by events vs the exact solution, within 10 times the sum of the "
                          "arcs' errors, each arc again at rtol 1e-14", tf, last_e ? te[last_e - 1] : 0,
                     10 * a->sum_dt + rt * (tf + 1 / s->w));
    mm_res_check_abs(res, "x_final: located by events vs the exact solution, within 10 times the sum of the "
                          "arcs' errors, each arc again at rtol 1e-14", xf, last_e ? xe[last_e - 1] : s->x0, tol_x);
    /* energy (7): what is gone is friction force times path length (the path
     * of one arc is |x_end - x_start|: the velocity keeps its sign on an arc) */
    if (a->n > 0) {
        double E0 = 0.5 * s->k * s->x0 * s->x0 + 0.5 * s->m * s->v0 * s->v0;
        mm_res_check_abs(res, "energy (7): E(0) - E(stop) - mu m g times the path slid, from the events, within "
                              "10 times the sum of the arcs' errors, each arc again at rtol 1e-14 [J]",
                         mm_coulomb_energy_residual(s, a->n, a->x), 0, 10 * a->sum_de + rt * (E0 + fric * size * a->n));
    }
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    model s = model_of(in);
    int np = (int)in[P_POINTS].x;
    double fric = s.mu * s.m * s.g, size = fabs(s.x0) + fabs(s.v0) / s.w + s.d;

    /* the exact solution, eqs. (3)-(6) */
    double *te = mm_res_alloc(res, 3 * (MAX_ARCS + 1) * sizeof *te), *xe = te + MAX_ARCS + 1,
           *sge = xe + MAX_ARCS + 1;
    if (!te)
        return MM_ENOMEM;
    int ne = mm_coulomb_arcs(&s, te, xe, sge, MAX_ARCS + 1);
    double stop = ne ? te[ne - 1] : 0, xf = ne ? xe[ne - 1] : s.x0;
    mm_res_scalar(res, O_OMEGA_N, s.w);
    mm_res_scalar(res, O_BAND, s.d);
    mm_res_scalar(res, O_DECAY, 4 * s.d);
    mm_res_scalar(res, O_STOP, stop);
    /* from rest the rests are |x0| - 2 j d, exact but for one rounding; a
     * moving start goes through x1 = c + R, rounded to a few eps of |x1|,
     * which a long decay to a small x_final makes a large part of it */
    double xf_err = s.v0 != 0 && ne ? 8 * DBL_EPSILON * (fabs(xe[0]) + s.d) : 0;
    if (xf_err > 0) {
        mm_res_scalar_err(res, O_XF, xf, xf_err, MM_ERR_BOUND);
        mm_res_scalar_err(res, O_SPRING_F, fabs(s.k * xf), s.k * xf_err, MM_ERR_BOUND);
    } else {
        mm_res_scalar(res, O_XF, xf);
        mm_res_scalar(res, O_SPRING_F, fabs(s.k * xf));
    }
    mm_res_scalar(res, O_HALF, ne);
    mm_res_scalar(res, O_FRIC, fric);

    /* the plot: to a little past the stop, or one period when it never moves */
    double t_plot = mm_ex_nice_up(ne ? 1.15 * stop : 2 * M_PI / s.w);
    mm_series *sx = mm_res_series(res, O_XT, np), *sv = mm_res_series(res, O_VT, np);
    mm_series *se = mm_res_series(res, O_ERR, np), *amp = mm_res_series(res, O_AMP, ne + 1);
    mm_table *tab = mm_res_table(res, O_RESTS, ne);
    mm_coulomb_run a = {.t = mm_res_alloc(res, 2 * (MAX_ARCS + 1) * sizeof(double)), .xg = se ? se->y : NULL,
             .rtol_ref = 1e-14};
    mm_coulomb_run f = {.t = mm_res_alloc(res, 2 * (MAX_ARCS + 1) * sizeof(double)),
             .xg = mm_res_alloc(res, (size_t)np * sizeof(double))};
    if (!sx || !sv || !se || !amp || !tab || !a.t || !f.t || !f.xg)
        return MM_ENOMEM;
    a.x = a.t + MAX_ARCS + 1;
    f.x = f.t + MAX_ARCS + 1;
    mm_ex_time_grid(t_plot, np, sx->x);
    for (int i = 0; i < np; i++) {
        sv->x[i] = se->x[i] = sx->x[i];
        sx->y[i] = mm_coulomb_x(&s, te, xe, sge, ne, sx->x[i], &sv->y[i]);
    }
    amp->x[0] = 0, amp->y[0] = fabs(s.x0);
    for (int j = 0; j < ne; j++) {
        tab->cell[3 * j] = te[j];
        tab->cell[3 * j + 1] = xe[j];
        tab->cell[3 * j + 2] = fabs(s.k * xe[j]) / fric;
        amp->x[j + 1] = te[j], amp->y[j + 1] = fabs(xe[j]);
    }

    /* the same integrated arc by arc with events (each arc again at rtol
     * 1e-14 for the checks), and the whole again at rtol / 100 */
    int rc = mm_coulomb_integrate(&s, 1e-10, MAX_ARCS, np, sx->x, &a, err);
    if (rc == MM_OK)
        rc = mm_coulomb_integrate(&s, 1e-12, MAX_ARCS, np, sx->x, &f, err);
    if (rc != MM_OK)
        return rc;
    double rnd = mm_ex_roundoff(ne * M_PI, 1);
    double worst = 0, est = 0;
    for (int i = 0; i < np; i++) {
        est = fmax(est, fabs(a.xg[i] - f.xg[i]));
        a.xg[i] -= sx->y[i];                                          /* the error series */
        worst = fmax(worst, fabs(a.xg[i]));
    }
    mm_ex_round_sig(se->y, np, 3);                                    /* an error needs no more digits */
    mm_res_method(res, "exact piecewise solution; dop853 per sliding arc, stopped at the velocity zero "
                       "(mm_ode event location), beside it", 0);
    static const char *const stat[] = {"rtol", "steps", "evaluations", "events", "event_evaluations",
                                       "error_estimate", "max_error"};
    double val[] = {1e-10, (double)a.steps, (double)a.evals, a.n, (double)a.event_evals, est, worst};
    for (int i = 0; i < 7; i++)
        mm_res_method_stat(res, stat[i], val[i]);
    checks(&s, &a, te, xe, ne, size, res);
    /* a plotted point of arc j carries the error of its start (at most the
     * sum over the arcs before) and the dense output's own */
    mm_res_check_abs(res, "x(t): integrated with events vs the exact solution (worst plotted point), within "
                          "10 times the error estimated by a run at rtol/100 plus the arcs' errors", worst, 0,
                     10 * (est + a.sum_dx) + rnd * size);
    mm_ex_warn_aliasing(res, np, t_plot, ne ? s.w : 0, "raise points");
    return mm_vib_coulomb_animate(res, &s, te, xe, sge, ne, t_plot);
}

static const char *const references[] = {
    "S. S. Rao, Mechanical Vibrations, 6th ed., Pearson 2017, section 2.9 (Coulomb damping)",
    "E. Hairer, S. P. Norsett, G. Wanner, Solving Ordinary Differential Equations I, Springer 1993, "
    "sections II.5-II.6 (DOPRI5, dense output, event location)",
    "R. P. Brent, Algorithms for Minimization without Derivatives, Prentice-Hall 1973, ch. 4",
    NULL,
};

const mm_exercise mm_ex_vib_coulomb = {
    .id = "vib-coulomb", .chapter = 5, .section = "5.9.7", .title = "Vibration with Coulomb friction",
    .summary = "A mass on a spring sliding on a rough floor: straight-line decay and a stop away from zero.",
    .tags = "vibration, 1 DOF, dry friction, Coulomb, events, nonsmooth", .theory = "exercises/vib/coulomb.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
