/* slider_crank.c — dyn-slider-crank: the slider-crank mechanism as a
 * constrained multibody system, coasting through its dead centres.
 *
 *     M q'' + Phi_q^T lambda = Q,      Phi(q) = 0                          (1)
 *
 * Three bodies (crank with flywheel, connecting rod, piston) in five
 * absolute coordinates tied by four pin constraints.  The constraints are
 * differentiated twice (index reduction) and solved with the equations of
 * motion for the accelerations and the Lagrange multipliers, which are the
 * joint forces.  Integrating the accelerations lets the constraints drift;
 * Baumgarte's stabilisation pulls them back (method "baumgarte"), or the
 * crank angle alone is integrated and the other coordinates recovered from
 * the constraints at every step (coordinate partitioning, "partitioning"),
 * which leaves no drift at all.  The check is the energy balance: with a
 * constant torque the kinetic energy grows by the torque's work, and with
 * zero torque it is conserved, through every dead centre.
 * Reference: P. E. Nikravesh, Computer-Aided Analysis of Mechanical Systems,
 * Prentice Hall 1988, ch. 11-13; J. Baumgarte, Comput. Methods Appl. Mech.
 * Eng. 1 (1972) 1-16; R. A. Wehage, E. J. Haug, J. Mech. Des. 104 (1982).
 */
#include <float.h>
#include <math.h>

#include "mm_dyn.h"
#include "mm_exhelp.h"
#include "mm_multibody.h"
#include "mm_scene.h"

enum { P_R, P_L, P_JC, P_MR, P_JR, P_MP, P_TORQUE, P_OMEGA0, P_TEND, P_METHOD, P_ALPHA, P_RTOL, P_POINTS };

static const char *const methods[] = {"baumgarte", "partitioning", NULL};

static const mm_param params[] = {
    [P_R] = {"r", "crank radius", "m", MM_REAL, 0.1, 0.01, 1, .help = "crank pivot to crank pin; the stroke is 2r"},
    [P_L] = {"l", "connecting rod length", "m", MM_REAL, 0.4, 0.02, 4,
             .help = "crank pin to piston pin; must exceed r"},
    [P_JC] = {"J_crank", "crank and flywheel inertia", "kg m^2", MM_REAL, 0.05, 1e-4, 100,
              .help = "about the crank axis (the crank's centre of mass is on the axis)"},
    [P_MR] = {"m_rod", "rod mass", "kg", MM_REAL, 1, 0.01, 100, .help = "centre of mass at mid-length"},
    [P_JR] = {"J_rod", "rod inertia", "kg m^2", MM_REAL, 0.015, 1e-6, 100,
              .help = "about the rod's centre of mass (a uniform rod has m_rod l^2 / 12)"},
    [P_MP] = {"m_piston", "piston mass", "kg", MM_REAL, 1, 0.01, 100, .help = "slides on the x axis"},
    [P_TORQUE] = {"torque", "driving torque", "N m", MM_REAL, 0, -1000, 1000,
                  .help = "constant torque on the crank; 0: the mechanism coasts and keeps its energy"},
    [P_OMEGA0] = {"omega0", "initial crank speed", "rad/s", MM_REAL, 100, -1000, 1000,
                  .help = "at t = 0, at head-end dead centre (crank angle 0, piston at x = r + l)"},
    [P_TEND] = {"t_end", "duration", "s", MM_REAL, 0.5, 1e-3, 10,
                .help = "simulated time; at most 300 crank revolutions"},
    [P_METHOD] = {"method", "how the constraints are kept", "", MM_CHOICE, 0, 0, 0, .choices = methods,
                  .help = "baumgarte: all coordinates integrated, drift pulled back; partitioning: the crank "
                          "angle integrated, the rest solved from the constraints"},
    [P_ALPHA] = {"alpha", "Baumgarte constant", "1/s", MM_REAL, 20, 0, 1000,
                 .help = "constraint errors decay like e^(-alpha t) (alpha = beta); 0 switches the "
                         "stabilisation off and the drift grows"},
    [P_RTOL] = {"rtol", "integration tolerance", "", MM_REAL, 1e-10, 1e-12, 1e-3,
                .help = "relative tolerance of the integrator (DOP853); raise it to see the constraints drift"},
    [P_POINTS] = {"points", "plot points", "", MM_INT, 201, 11, 2001, .help = "samples returned for the plots"},
};

enum {
    O_J0, O_JMIN, O_JMAX, O_WMIN, O_WMAX, O_WEND, O_FLUCT, O_REV, O_FMAX_A, O_FMAX_B, O_NMAX,
    O_OMEGA, O_FO, O_FA, O_FB, O_N, O_DRIFT_S, O_ANIM
};

static const mm_output outputs[] = {
    [O_J0] = MM_SCALAR("J_dead_centre", "effective inertia at the dead centres", "kg m^2", .flags = MM_EXACT),
    [O_JMIN] = MM_SCALAR("J_min", "smallest effective inertia over a turn", "kg m^2"),
    [O_JMAX] = MM_SCALAR("J_max", "largest effective inertia over a turn", "kg m^2"),
    [O_WMIN] = MM_SCALAR("omega_min", "lowest crank speed", "rad/s", .flags = MM_ANSWER),
    [O_WMAX] = MM_SCALAR("omega_max", "highest crank speed", "rad/s", .flags = MM_ANSWER),
    [O_WEND] = MM_SCALAR("omega_end", "crank speed at t_end", "rad/s", .flags = MM_ANSWER),
    [O_FLUCT] = MM_SCALAR("fluctuation", "coefficient of speed fluctuation (omega_max - omega_min) / omega_mean",
                          "", .flags = MM_ANSWER),
    [O_REV] = MM_SCALAR("revolutions", "crank turns over the run", ""),
    [O_FMAX_A] = MM_SCALAR("F_A_max", "largest crank-pin force", "N", .flags = MM_ANSWER),
    [O_FMAX_B] = MM_SCALAR("F_B_max", "largest piston-pin force", "N", .flags = MM_ANSWER),
    [O_NMAX] = MM_SCALAR("N_max", "largest guide force on the piston", "N"),
    [O_OMEGA] = MM_SERIES("omega", "crank speed", "rad/s", "t", "s", .figure = "speed"),
    [O_FO] = MM_SERIES("F_O", "main bearing force |F_O| on the crank", "N", "t", "s", .figure = "forces"),
    [O_FA] = MM_SERIES("F_A", "crank-pin force |F_A|", "N", "t", "s", .figure = "forces"),
    [O_FB] = MM_SERIES("F_B", "piston-pin force |F_B|", "N", "t", "s", .figure = "forces"),
    [O_N] = MM_SERIES("N", "guide force on the piston (+y)", "N", "t", "s", .figure = "forces"),
    [O_DRIFT_S] = MM_SERIES("drift", "constraint violation |Phi| (position level)", "m", "t", "s",
                            .figure = "drift", .y_scale = "log"),
    [O_ANIM] = MM_ANIMATION("the slider-crank turning, with its flywheel"),
};

#define MAX_REV 300

static mm_sc_model mech_of(const mm_value *in)
{
    return (mm_sc_model){.r = in[P_R].x, .l = in[P_L].x, .J_crank = in[P_JC].x, .m_rod = in[P_MR].x,
                             .J_rod = in[P_JR].x, .m_piston = in[P_MP].x, .torque = in[P_TORQUE].x};
}

/* A bound of the crank speed over the run from the energy (eq. 6): with
 * J >= Jmin, J w^2 / 2 <= J0 w0^2 / 2 + |torque| w_max t. */
static double speed_bound(const mm_sc_model *s, double w0, double t_end, double Jmin)
{
    double J0 = mm_sc_inertia(s, 0, NULL), a = fabs(s->torque) * t_end / Jmin;
    return a + sqrt(a * a + J0 * w0 * w0 / Jmin);
}

static int check(const mm_value *in, mm_error *err)
{
    mm_sc_model s = mech_of(in);
    if (!(s.l > 1.05 * s.r))
        return mm_error_set(err, MM_ERANGE, "l",
                            "the rod (l = %g m) must be longer than the crank (r = %g m), by 5 %% at least, or the "
                            "piston cannot follow a full turn: make l at least %.4g m", s.l, s.r, 1.05 * s.r);
    double Jmin, Jmax;
    mm_dyn_sc_inertia_range(&s, &Jmin, &Jmax);
    double w = speed_bound(&s, in[P_OMEGA0].x, in[P_TEND].x, Jmin), rev = w * in[P_TEND].x / (2 * M_PI);
    if (rev > MAX_REV)
        return mm_error_set(err, MM_ERANGE, "t_end",
                            "the crank could turn up to %.0f times in t_end = %g s; at most %d turns fit one "
                            "request: make t_end at most %.3g s", rev, in[P_TEND].x, MAX_REV,
                            in[P_TEND].x * MAX_REV / rev);
    return MM_OK;
}

/* The largest step of every run: 1/16 of a turn at the highest speed the
 * energy balance allows (speed_bound, eq. 6).  At a loose rtol DOP853 lets the step
 * grow to a tenth of a turn and more; the right-hand side is smooth (it
 * agrees with the closed form J(phi), J'(phi) to 4e-13), but h w J'/J then
 * nears the edge of DOP853's stability region, the error estimate no
 * longer sees the error, the run leaves its energy level and
 * w' = -J'/(2J) w^2 carries it to infinity: "step size below round-off"
 * (422) at rtol 1.3e-4 on a draw that rtol 1e-12 integrates in 20000
 * steps.  0 (no cap) when nothing moves. */
static double step_cap(const mm_sc_model *s, double w0, double t_end, double Jmin)
{
    double W = speed_bound(s, w0, t_end, Jmin);
    return W > 0 ? 2 * M_PI / (16 * W) : 0;
}

/* ---- solve ------------------------------------------------------------------------ */

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    mm_sc_model s = mech_of(in);
    double w0 = in[P_OMEGA0].x, t_end = in[P_TEND].x, alpha = in[P_ALPHA].x, RTOL = in[P_RTOL].x;
    int partition = (int)in[P_METHOD].x == 1, n = (int)in[P_POINTS].x;
    mm_sc_system sys = {.sc = s, .alpha = alpha, .beta = alpha};

    double J0 = mm_sc_inertia(&s, 0, NULL), Jmin, Jmax;
    mm_dyn_sc_inertia_range(&s, &Jmin, &Jmax);
    mm_res_scalar(res, O_J0, J0);
    mm_res_scalar_err(res, O_JMIN, Jmin, 1e-14 * Jmax, MM_ERR_ESTIMATE);
    mm_res_scalar_err(res, O_JMAX, Jmax, 1e-14 * Jmax, MM_ERR_ESTIMATE);

    /* the start: head-end dead centre, phi1 = 0, x3 = r + l */
    double q0[MM_SC_NQ], qd0[MM_SC_NQ], y0[2 * MM_SC_NQ];
    mm_sc_assemble(&s, 0, w0, q0, qd0);
    int ny = partition ? 2 : 2 * MM_SC_NQ;
    if (partition) {
        y0[0] = 0, y0[1] = w0;
    } else {
        for (int j = 0; j < MM_SC_NQ; j++)
            y0[j] = q0[j], y0[MM_SC_NQ + j] = qd0[j];
    }

    mm_series *so = mm_res_series(res, O_OMEGA, n);
    mm_series *sfo = mm_res_series(res, O_FO, n), *sfa = mm_res_series(res, O_FA, n);
    mm_series *sfb = mm_res_series(res, O_FB, n), *sn = mm_res_series(res, O_N, n);
    mm_series *sd = mm_res_series(res, O_DRIFT_S, n);
    double *y = mm_res_alloc(res, (size_t)n * (size_t)ny * sizeof *y);
    if (!so || !sfo || !sfa || !sfb || !sn || !sd || !y)
        return MM_ENOMEM;
    mm_linspace(0, t_end, n, so->x);

    mm_ode_problem prob = {.n = (size_t)ny, .f = partition ? mm_sc_rhs_reduced : mm_sc_rhs_baumgarte,
                           .params = &sys, .t0 = 0, .t_end = t_end, .y0 = y0};
    mm_ode_options opt = mm_ode_options_adaptive(MM_ODE_DOP853, RTOL, RTOL, 1000000);
    opt.h_max = step_cap(&s, w0, t_end, Jmin);
    mm_ode_result r = {.t_out = so->x, .nout = (size_t)n, .y_out = y};
    int rc = mm_ode_run(&prob, &opt, &r, err);
    if (rc != MM_OK)
        return rc;
    if (partition)
        mm_res_method(res, "coordinate partitioning: the crank angle by dop853, the other coordinates from the "
                           "constraints at every evaluation", 0);
    else
        mm_res_method(res, "Lagrange multipliers, index reduction to the acceleration level with Baumgarte's "
                           "stabilisation, dop853", 0);
    mm_res_method_stat(res, "rtol", RTOL);
    if (!partition)
        mm_res_method_stat(res, "alpha", alpha);
    mm_res_method_stat(res, "steps", (double)r.n_accepted);
    mm_res_method_stat(res, "evaluations", (double)r.n_eval);

    /* every output point: speed, energy, joint forces, drift, momentum */
    double T0 = mm_sc_kinetic(&s, q0, qd0), Eworst = 0, Escale = T0, drift = 0, wlo = INFINITY, whi = -INFINITY;
    double fa_max = 0, fb_max = 0, n_max = 0, wE_worst = 0, TJ_worst = 0, mom_worst = 0, mom_scale = 0, wsum = 0;
    for (int i = 0; i < n; i++) {
        double q[MM_SC_NQ], qd[MM_SC_NQ], qdd[MM_SC_NQ], lam[MM_SC_NC];
        mm_dyn_sc_state(&s, partition, y + (size_t)i * (size_t)ny, q, qd);
        rc = mm_sc_accel(&s, q, qd, partition ? 0 : alpha, partition ? 0 : alpha, qdd, lam);
        if (rc != MM_OK)
            return mm_error_set(err, rc, "l", "the constraints became dependent: the rod stood vertical");
        double t = so->x[i], wk = qd[0], dphi = q[0];
        /* eq. (6): kinetic energy = T0 + torque (phi - phi0) */
        double Tk = mm_sc_kinetic(&s, q, qd), work = s.torque * dphi;
        Eworst = fmax(Eworst, fabs(Tk - T0 - work));
        Escale = fmax(Escale, fmax(Tk, fabs(work)));
        /* the speed the energy balance gives at this crank angle, with the
         * closed-form effective inertia (eq. 5) */
        double J = mm_sc_inertia(&s, q[0], NULL);
        TJ_worst = fmax(TJ_worst, fabs(0.5 * J * wk * wk - T0 - work));
        /* the speed error that an energy error means: dw = dE / (J |w|) */
        wE_worst = fmax(wE_worst, fabs(Tk - T0 - work) / (J * fmax(fabs(wk), 1e-300)));
        double d = mm_sc_drift(&s, q);
        drift = fmax(drift, d);
        /* joint forces (see mm_multibody.h for the signs) */
        double fa = hypot(lam[0], lam[1]), fb = hypot(lam[2], lam[3]), N = -lam[3];
        so->y[i] = wk;
        sfo->x[i] = sfa->x[i] = sfb->x[i] = sn->x[i] = sd->x[i] = t;
        sfo->y[i] = fa, sfa->y[i] = fa, sfb->y[i] = fb, sn->y[i] = N;
        sd->y[i] = fmax(d, DBL_EPSILON * (s.r + s.l));       /* a log axis needs a floor */
        fa_max = fmax(fa_max, fa), fb_max = fmax(fb_max, fb), n_max = fmax(n_max, fabs(N));
        wlo = fmin(wlo, wk), whi = fmax(whi, wk);
        wsum += (i == 0 || i == n - 1 ? 0.5 : 1) * wk;
        /* momentum: the bearing force on the crank and the guide force on the
         * piston accelerate the rod's and the piston's centres of mass */
        double msc, mres = mm_sc_momentum_residual(&s, qdd, lam, &msc);
        mom_worst = fmax(mom_worst, mres);
        mom_scale = fmax(mom_scale, msc);
    }
    double wmean = wsum / (n - 1);
    /* the error of the speeds read off the run: a second run of the reduced
     * equation at a tolerance 1000 times tighter is the reference (its own
     * error is then negligible), plus the sampling of an extreme.  The run's
     * distance from it is one sample of its error; a third run at half the
     * tolerance (another step sequence), doubled, is a second; the larger is
     * stated (with the first alone, reordering DOP853's stage sums moved
     * revolutions by 4.7 times its stated error) */
    double *yref, *yalt, tol_ref;
    if ((rc = mm_dyn_sc_reference_runs(&sys, w0, t_end, n, so->x, &opt, &r, &yref, &yalt, &tol_ref, res, err)))
        return rc;
    double rlo = INFINITY, rhi = -INFINITY, rsum = 0, alo = INFINITY, ahi = -INFINITY;
    for (int i = 0; i < n; i++) {
        rlo = fmin(rlo, yref[2 * i + 1]), rhi = fmax(rhi, yref[2 * i + 1]);
        alo = fmin(alo, yalt[2 * i + 1]), ahi = fmax(ahi, yalt[2 * i + 1]);
        rsum += (i == 0 || i == n - 1 ? 0.5 : 1) * yref[2 * i + 1];
    }
    int ilo = 0, ihi = 0;
    for (int i = 0; i < n; i++) {
        if (so->y[i] < so->y[ilo])
            ilo = i;
        if (so->y[i] > so->y[ihi])
            ihi = i;
    }
    double fl = 1e-12 * fmax(fabs(whi), fabs(wlo));            /* the reference's own error */
    double elo = fmax(fabs(wlo - rlo), 2 * fabs(alo - rlo)) + mm_dyn_extreme_error(so->y, n, ilo) + fl;
    double ehi = fmax(fabs(whi - rhi), 2 * fabs(ahi - rhi)) + mm_dyn_extreme_error(so->y, n, ihi) + fl;
    mm_res_scalar_err(res, O_WMIN, wlo, elo, MM_ERR_ESTIMATE);
    mm_res_scalar_err(res, O_WMAX, whi, ehi, MM_ERR_ESTIMATE);
    mm_res_scalar_err(res, O_WEND, so->y[n - 1],
                      fmax(fabs(so->y[n - 1] - yref[2 * n - 1]), 2 * fabs(yalt[2 * n - 1] - yref[2 * n - 1])) + fl,
                      MM_ERR_ESTIMATE);
    if (wlo > 0 || whi < 0) {                       /* the crank never stopped */
        double fr = (whi - wlo) / fabs(wmean), fref = (rhi - rlo) / fabs(rsum / (n - 1));
        mm_res_scalar_err(res, O_FLUCT, fr, fabs(fr - fref) + (elo + ehi) / fabs(wmean), MM_ERR_ESTIMATE);
    }
    double phi_end = y[(size_t)(n - 1) * (size_t)ny];
    mm_res_scalar_err(res, O_REV, phi_end / (2 * M_PI),
                      (fmax(fabs(phi_end - yref[2 * (n - 1)]), 2 * fabs(yalt[2 * (n - 1)] - yref[2 * (n - 1)])) +
                       1e-12 * fabs(phi_end)) / (2 * M_PI), MM_ERR_ESTIMATE);
    /* the joint forces of the reference run and of the third, for the error
     * of their maxima; the energy error the run's distance from the
     * reference can make */
    double *absn = mm_res_alloc(res, (size_t)n * sizeof *absn);
    if (!absn)
        return MM_ENOMEM;
    mm_dyn_sc_cmp c;
    if ((rc = mm_dyn_sc_compare(&s, partition, ny, n, y, yref, yalt, tol_ref, sfa->y, sfb->y, sn->y, absn, &c, err)))
        return rc;
    mm_res_scalar_err(res, O_FMAX_A, fa_max, fmax(fabs(fa_max - c.ra), c.aa) + mm_dyn_extreme_error(sfa->y, n, c.ia) +
                      1e-12 * fa_max, MM_ERR_ESTIMATE);
    mm_res_scalar_err(res, O_FMAX_B, fb_max, fmax(fabs(fb_max - c.rb), c.ab) + mm_dyn_extreme_error(sfb->y, n, c.ib) +
                      1e-12 * fb_max, MM_ERR_ESTIMATE);
    mm_res_scalar_err(res, O_NMAX, n_max, fmax(fabs(n_max - c.rn), c.an) + mm_dyn_extreme_error(absn, n, c.in) +
                      1e-12 * fb_max, MM_ERR_ESTIMATE);

    double rad = 1 + fabs(y[(size_t)(n - 1) * (size_t)ny]);
    /* the energy error the run's measured state error can make (eq. 8): the
     * gradient of the energy times the distance from the reference run plus
     * the reference's own error, doubled, and a few eps of the energy for
     * its round-off */
    double floor_E = 64 * DBL_EPSILON * Escale;
    mm_res_check_abs(res, "energy balance: kinetic energy - T0 - torque (phi - phi0), worst point [J]", Eworst, 0,
                     2 * c.eb + floor_E);
    mm_res_check_abs(res, "J(phi) w^2 / 2 with the closed-form inertia (eq. 5) vs T0 + torque (phi - phi0) [J]",
                     TJ_worst, 0, 2 * c.ebJ + floor_E);
    mm_check_residual(res, "joint forces: bearing + guide forces vs the rate of momentum [N] "
                           "(scale: sum of the forces and inertia forces)", mom_worst, mom_scale, 16);
    if (partition)
        mm_check_residual(res, "constraint drift under coordinate partitioning: round-off only [m] "
                               "(scale: r + l)", drift, s.r + s.l, 64);
    else
        mm_res_check_abs(res, "constraint drift under Baumgarte's stabilisation [m]", drift, 0,
                         RTOL * rad * (s.r + s.l) * sqrt(Jmax / Jmin));
    if (wlo < 0 && whi > 0)
        mm_res_warn(res, "the crank stopped and turned back: the torque could not carry it through");
    if (!partition && alpha == 0)
        mm_res_warn(res, "alpha = 0: nothing pulls the constraints back, and the drift grows with time");
    return mm_dyn_sc_animate(&s, partition, ny, t_end, fmax(fabs(whi), fabs(wlo)), RTOL, opt.h_max, y0, &sys, res, err);
}

static const char *const references[] = {
    "P. E. Nikravesh, Computer-Aided Analysis of Mechanical Systems, Prentice Hall 1988, ch. 11-13",
    "J. Baumgarte, Stabilization of constraints and integrals of motion in dynamical systems, Comput. Methods "
    "Appl. Mech. Eng. 1 (1972) 1-16",
    "R. A. Wehage, E. J. Haug, Generalized coordinate partitioning for dimension reduction in analysis of "
    "constrained dynamic systems, J. Mech. Des. 104 (1982) 247-255",
    NULL,
};

const mm_exercise mm_ex_dyn_slider_crank = {
    .id = "dyn-slider-crank", .chapter = 4, .section = "4.4.3", .title = "Dynamics of a slider-crank mechanism",
    .summary = "The constrained equations with Lagrange multipliers (Baumgarte or coordinate partitioning), "
               "joint forces, the flywheel's speed through the dead centres, energy balance and drift.",
    .tags = "dynamics, mechanism, slider-crank, constraints, Lagrange multipliers, flywheel",
    .theory = "exercises/dyn/slider_crank.md", .params = params, .n_params = MM_COUNT(params), .outputs = outputs,
    .n_outputs = MM_COUNT(outputs), .references = references, .check = check, .solve = solve,
};
