/* mm_ode.c — explicit Runge–Kutta integrators with error control and
 * dense output (see mm_ode.h for the contract).
 *
 * One step of an s-stage explicit Runge–Kutta method from (t, y), step h:
 *     k_i   = f(t + c_i h, y + h sum_{j<i} a_ij k_j),   i = 1..s
 *     y_new = y + h sum_i b_i k_i
 * An embedded formula with other weights b^_i gives a second solution of
 * lower order from the same stages; their difference estimates the local
 * error, and the step-size controller keeps that estimate near the
 * tolerance.  Between steps a continuous extension (dense output), built
 * from the same stages, gives y at any time without shortening steps.
 *
 * Tableaux (indices 1-based, as in the book: dp5_a[4][3] is a_43):
 *   RK4     Kutta (1901); Abramowitz & Stegun 25.5.10.
 *   DOPRI5  Dormand & Prince, J. Comput. Appl. Math. 6 (1980) 19–26, with
 *           Shampine's (1986) dense output; Hairer, Nørsett & Wanner (HNW),
 *           "Solving Ordinary Differential Equations I", 2nd ed. 1993,
 *           Table II.5.2 and Hairer's code DOPRI5.
 *   DOP853  Dormand & Prince 8(5,3), described in HNW (2nd ed.) and given
 *           in Hairer's code DOP853 (version of 25 April 1996, corrected
 *           4 March 2002): the coefficients below are copied from it digit
 *           for digit.
 * Step-size control and starting step: HNW II.4.  PI control and stiffness
 * detection: Hairer & Wanner, "Solving Ordinary Differential Equations II"
 * (HW), 2nd ed. 1996, section IV.2.
 * The stages are written out term by term, as in Hairer's codes (zero
 * entries of a tableau skipped): for the small systems of mechanics, a loop
 * over a full tableau row costs twice the instructions per step.
 *
 * Stage arrays: w->k[1] always holds f(t, y) at the start of a step.  Each
 * method ends with a "first same as last" (FSAL) stage k[fsal] = f(t + h,
 * y_new); after an accepted step k[1] and k[fsal] swap pointers, so the next
 * step starts without a new call of f.
 */
#include "mm_ode.h"

#include <assert.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mm_roots.h"

/* ==== tableaux ============================================================ */

/* Classical RK4 (A&S 25.5.10):
 *     k1 = f(t, y),            k2 = f(t + h/2, y + h/2 k1),
 *     k3 = f(t + h/2, y + h/2 k2),   k4 = f(t + h, y + h k3),
 *     y_new = y + h/6 (k1 + 2 k2 + 2 k3 + k4).
 * Its coefficients are plain numbers in step_rk4.  With the FSAL stage
 * k5 = f(t + h, y_new), the weights (1/6, 1/3, 1/3, 0, 1/6) give a
 * 3rd-order companion at no extra cost per step, so
 *     y4 - y3 = h/6 (k4 - k5)
 * is a free local error estimate. */

/* Dormand–Prince 5(4) (HNW Table II.5.2).  Row 7 of a is b: stage 7 is
 * evaluated at y_new (FSAL).  e = b - b^ (5th- minus 4th-order weights). */
static const double dp5_c[8] = {[2] = 1.0 / 5, [3] = 3.0 / 10, [4] = 4.0 / 5,
                                [5] = 8.0 / 9, [6] = 1.0, [7] = 1.0};
static const double dp5_a[8][8] = {
    [2] = {[1] = 1.0 / 5},
    [3] = {[1] = 3.0 / 40, [2] = 9.0 / 40},
    [4] = {[1] = 44.0 / 45, [2] = -56.0 / 15, [3] = 32.0 / 9},
    [5] = {[1] = 19372.0 / 6561, [2] = -25360.0 / 2187, [3] = 64448.0 / 6561,
           [4] = -212.0 / 729},
    [6] = {[1] = 9017.0 / 3168, [2] = -355.0 / 33, [3] = 46732.0 / 5247,
           [4] = 49.0 / 176, [5] = -5103.0 / 18656},
    [7] = {[1] = 35.0 / 384, [3] = 500.0 / 1113, [4] = 125.0 / 192,
           [5] = -2187.0 / 6784, [6] = 11.0 / 84},
};
static const double dp5_e[8] = {
    [1] = 71.0 / 57600, [3] = -71.0 / 16695, [4] = 71.0 / 1920,
    [5] = -17253.0 / 339200, [6] = 22.0 / 525, [7] = -1.0 / 40,
};
/* Shampine's 4th-order continuous extension (Hairer's CONTD5 d_i). */
static const double dp5_d[8] = {
    [1] = -12715105075.0 / 11282082432, [3] = 87487479700.0 / 32700410799,
    [4] = -10690763975.0 / 1880347072, [5] = 701980252875.0 / 199316789632,
    [6] = -1453857185.0 / 822651844, [7] = 69997945.0 / 29380423,
};

/* Dormand–Prince 8(5,3) from Hairer's DOP853.  Stages 1..12 make the step
 * (stage 12 at c = 1), stage 13 is f(t + h, y_new) (FSAL), stages 14..16
 * exist only for the 7th-order dense output. */
static const double dop_c[17] = {
    [2] = 0.526001519587677318785587544488e-01, [3] = 0.789002279381515978178381316732e-01,
    [4] = 0.118350341907227396726757197510e+00, [5] = 0.281649658092772603273242802490e+00,
    [6] = 0.333333333333333333333333333333e+00, [7] = 0.25e+00,
    [8] = 0.307692307692307692307692307692e+00, [9] = 0.651282051282051282051282051282e+00,
    [10] = 0.6e+00, [11] = 0.857142857142857142857142857142e+00, [12] = 1.0, [13] = 1.0,
    [14] = 0.1e+00, [15] = 0.2e+00, [16] = 0.777777777777777777777777777778e+00,
};
static const double dop_a[17][17] = {
    [2] = {[1] = 5.26001519587677318785587544488e-2},
    [3] = {[1] = 1.97250569845378994544595329183e-2,
          [2] = 5.91751709536136983633785987549e-2},
    [4] = {[1] = 2.95875854768068491816892993775e-2,
          [3] = 8.87627564304205475450678981324e-2},
    [5] = {[1] = 2.41365134159266685502369798665e-1,
          [3] = -8.84549479328286085344864962717e-1,
          [4] = 9.24834003261792003115737966543e-1},
    [6] = {[1] = 3.7037037037037037037037037037e-2,
          [4] = 1.70828608729473871279604482173e-1,
          [5] = 1.25467687566822425016691814123e-1},
    [7] = {[1] = 3.7109375e-2, [4] = 1.70252211019544039314978060272e-1,
          [5] = 6.02165389804559606850219397283e-2, [6] = -1.7578125e-2},
    [8] = {[1] = 3.70920001185047927108779319836e-2,
          [4] = 1.70383925712239993810214054705e-1,
          [5] = 1.07262030446373284651809199168e-1,
          [6] = -1.53194377486244017527936158236e-2,
          [7] = 8.27378916381402288758473766002e-3},
    [9] = {[1] = 6.24110958716075717114429577812e-1,
          [4] = -3.36089262944694129406857109825e0,
          [5] = -8.68219346841726006818189891453e-1,
          [6] = 2.75920996994467083049415600797e1, [7] = 2.01540675504778934086186788979e1,
          [8] = -4.34898841810699588477366255144e1},
    [10] = {[1] = 4.77662536438264365890433908527e-1,
           [4] = -2.48811461997166764192642586468e0,
           [5] = -5.90290826836842996371446475743e-1,
           [6] = 2.12300514481811942347288949897e1,
           [7] = 1.52792336328824235832596922938e1,
           [8] = -3.32882109689848629194453265587e1,
           [9] = -2.03312017085086261358222928593e-2},
    [11] = {[1] = -9.3714243008598732571704021658e-1,
           [4] = 5.18637242884406370830023853209e0,
           [5] = 1.09143734899672957818500254654e0,
           [6] = -8.14978701074692612513997267357e0,
           [7] = -1.85200656599969598641566180701e1,
           [8] = 2.27394870993505042818970056734e1,
           [9] = 2.49360555267965238987089396762e0,
           [10] = -3.0467644718982195003823669022e0},
    [12] = {[1] = 2.27331014751653820792359768449e0,
           [4] = -1.05344954667372501984066689879e1,
           [5] = -2.00087205822486249909675718444e0,
           [6] = -1.79589318631187989172765950534e1,
           [7] = 2.79488845294199600508499808837e1,
           [8] = -2.85899827713502369474065508674e0,
           [9] = -8.87285693353062954433549289258e0,
           [10] = 1.23605671757943030647266201528e1,
           [11] = 6.43392746015763530355970484046e-1},
    [14] = {[1] = 5.61675022830479523392909219681e-2,
           [7] = 2.53500210216624811088794765333e-1,
           [8] = -2.46239037470802489917441475441e-1,
           [9] = -1.24191423263816360469010140626e-1,
           [10] = 1.5329179827876569731206322685e-1,
           [11] = 8.20105229563468988491666602057e-3,
           [12] = 7.56789766054569976138603589584e-3, [13] = -8.298e-3},
    [15] = {[1] = 3.18346481635021405060768473261e-2,
           [6] = 2.83009096723667755288322961402e-2,
           [7] = 5.35419883074385676223797384372e-2,
           [8] = -5.49237485713909884646569340306e-2,
           [11] = -1.08347328697249322858509316994e-4,
           [12] = 3.82571090835658412954920192323e-4,
           [13] = -3.40465008687404560802977114492e-4,
           [14] = 1.41312443674632500278074618366e-1},
    [16] = {[1] = -4.28896301583791923408573538692e-1,
           [6] = -4.69762141536116384314449447206e0,
           [7] = 7.68342119606259904184240953878e0,
           [8] = 4.06898981839711007970213554331e0,
           [9] = 3.56727187455281109270669543021e-1,
           [13] = -1.39902416515901462129418009734e-3,
           [14] = 2.9475147891527723389556272149e0,
           [15] = -9.15095847217987001081870187138e0},
};
/* 8th-order weights b. */
static const double dop_b[13] = {
    [1] = 5.42937341165687622380535766363e-2, [6] = 4.45031289275240888144113950566e0,
    [7] = 1.89151789931450038304281599044e0, [8] = -5.8012039600105847814672114227e0,
    [9] = 3.1116436695781989440891606237e-1, [10] = -1.52160949662516078556178806805e-1,
    [11] = 2.01365400804030348374776537501e-1, [12] = 4.47106157277725905176885569043e-2,
};
/* 3rd-order companion: its difference to the 8th-order increment is
 * sum b_i k_i - bhh1 k1 - bhh2 k9 - bhh3 k12. */
static const double dop_bhh1 = 0.244094488188976377952755905512e+00;
static const double dop_bhh2 = 0.733846688281611857341361741547e+00;
static const double dop_bhh3 = 0.220588235294117647058823529412e-01;
/* 5th-order error weights er = b - b^(5). */
static const double dop_er[13] = {
    [1] = 0.1312004499419488073250102996e-01, [6] = -0.1225156446376204440720569753e+01,
    [7] = -0.4957589496572501915214079952e+00, [8] = 0.1664377182454986536961530415e+01,
    [9] = -0.3503288487499736816886487290e+00, [10] = 0.3341791187130174790297318841e+00,
    [11] = 0.8192320648511571246570742613e-01, [12] = -0.2235530786388629525884427845e-01,
};
/* Dense output: Hairer's rows D4*, D5*, D6*, D7* over stages 1..16. */
static const double dop_d[4][17] = {
    {[1] = -0.84289382761090128651353491142e+01, [6] = 0.56671495351937776962531783590e+00,
     [7] = -0.30689499459498916912797304727e+01, [8] = 0.23846676565120698287728149680e+01,
     [9] = 0.21170345824450282767155149946e+01,
     [10] = -0.87139158377797299206789907490e+00,
     [11] = 0.22404374302607882758541771650e+01,
     [12] = 0.63157877876946881815570249290e+00,
     [13] = -0.88990336451333310820698117400e-01,
     [14] = 0.18148505520854727256656404962e+02,
     [15] = -0.91946323924783554000451984436e+01,
     [16] = -0.44360363875948939664310572000e+01},
    {[1] = 0.10427508642579134603413151009e+02, [6] = 0.24228349177525818288430175319e+03,
     [7] = 0.16520045171727028198505394887e+03, [8] = -0.37454675472269020279518312152e+03,
     [9] = -0.22113666853125306036270938578e+02,
     [10] = 0.77334326684722638389603898808e+01,
     [11] = -0.30674084731089398182061213626e+02,
     [12] = -0.93321305264302278729567221706e+01,
     [13] = 0.15697238121770843886131091075e+02,
     [14] = -0.31139403219565177677282850411e+02,
     [15] = -0.93529243588444783865713862664e+01,
     [16] = 0.35816841486394083752465898540e+02},
    {[1] = 0.19985053242002433820987653617e+02, [6] = -0.38703730874935176555105901742e+03,
     [7] = -0.18917813819516756882830838328e+03, [8] = 0.52780815920542364900561016686e+03,
     [9] = -0.11573902539959630126141871134e+02,
     [10] = 0.68812326946963000169666922661e+01,
     [11] = -0.10006050966910838403183860980e+01,
     [12] = 0.77771377980534432092869265740e+00,
     [13] = -0.27782057523535084065932004339e+01,
     [14] = -0.60196695231264120758267380846e+02,
     [15] = 0.84320405506677161018159903784e+02, [16] = 0.11992291136182789328035130030e+02},
    {[1] = -0.25693933462703749003312586129e+02,
     [6] = -0.15418974869023643374053993627e+03,
     [7] = -0.23152937917604549567536039109e+03, [8] = 0.35763911791061412378285349910e+03,
     [9] = 0.93405324183624310003907691704e+02,
     [10] = -0.37458323136451633156875139351e+02,
     [11] = 0.10409964950896230045147246184e+03,
     [12] = 0.29840293426660503123344363579e+02,
     [13] = -0.43533456590011143754432175058e+02,
     [14] = 0.96324553959188282948394950600e+02,
     [15] = -0.39177261675615439165231486172e+02,
     [16] = -0.14972683625798562581422125276e+03},
};

/* ==== per-method constants ================================================= */

typedef struct method_info {
    const char *name;
    int fsal;         /* the stage holding f(t + h, y_new) */
    int stiff_stage;  /* the stage at c = 1 before y_new (stiffness test), or 0 */
    int dense_rows;   /* rows of the continuous extension */
    double q;         /* local error estimate ~ h^q: the controller's order */
    double safe;      /* safety factor of the step-size prediction */
    double fac_min;   /* h_new / h >= fac_min ... */
    double fac_max;   /* ... and <= fac_max */
    double beta;      /* PI control: weight of the previous error (HW IV.2) */
    double stiff_lim; /* h |lambda| on the stability boundary (HW IV.2) */
    double first;     /* 2^(p-1), p the lowest power of h in the estimate:
                         the first step's check (see "The first step") */
} method_info;

/* Controller constants are Hairer's defaults (DOPRI5: safe 0.9, h_new/h in
 * 0.2..10, beta 0.04; DOP853: safe 0.9, 0.333..6).  DOP853 gets the PI term
 * too (Hairer's code defaults to beta = 0; HW IV.2 suggests 0.04..0.08):
 * on the forced oscillator it saved 15-20 % of the calls of f at equal
 * achieved error.  The stability boundaries are Hairer's (3.25, 6.1). */
static const method_info methods[] = {
    [MM_ODE_RK4]    = {"rk4", 5, 0, 4, 4.0, 0.9, 0.2, 10.0, 0.0, 0.0, 0.0},
    [MM_ODE_DOPRI5] = {"dopri5", 7, 6, 5, 5.0, 0.9, 0.2, 10.0, 0.04, 3.25, 16.0},
    [MM_ODE_DOP853] = {"dop853", 13, 12, 8, 8.0, 0.9, 0.333, 6.0, 0.04, 6.1, 32.0},
};

#define N_STAGES_MAX 16
#define DENSE_ROWS_MAX 8
#define STIFF_EVERY 1000   /* Hairer's NSTIFF: test every 1000 accepted steps */

/* ==== workspace ============================================================ */

struct mm_ode_work {
    size_t n;                  /* capacity: largest system */
    double *y;                 /* accepted state at t */
    double *ynew;              /* trial state at t + h */
    double *ytmp;              /* stage argument */
    double *ysti;              /* argument of the stage at c = 1 */
    double *k[N_STAGES_MAX + 1]; /* stage derivatives k[1..16]; k[0] unused */
    double *cont;              /* dense output: dense_rows x n */
    double *block;             /* the one allocation behind all of the above */
};

mm_ode_work *mm_ode_work_alloc(size_t n)
{
    if (n == 0 || n > (size_t)MM_ODE_MAX_DIM)
        return NULL;
    mm_ode_work *w = malloc(sizeof *w);
    if (!w)
        return NULL;
    size_t nvec = 4 + N_STAGES_MAX + DENSE_ROWS_MAX;
    w->block = calloc(nvec * n, sizeof(double));
    if (!w->block) {
        free(w);
        return NULL;
    }
    w->n = n;
    double *p = w->block;
    w->y = p;    p += n;
    w->ynew = p; p += n;
    w->ytmp = p; p += n;
    w->ysti = p; p += n;
    w->k[0] = NULL;
    for (int i = 1; i <= N_STAGES_MAX; i++) {
        w->k[i] = p;
        p += n;
    }
    w->cont = p;
    return w;
}

void mm_ode_work_free(mm_ode_work *w)
{
    if (!w)
        return;
    free(w->block);
    free(w);
}

/* ==== options, names, validation ========================================== */

void mm_ode_options_init(mm_ode_options *opt)
{
    assert(opt);
    opt->method = MM_ODE_DOPRI5;
    opt->rtol = 1e-6;
    opt->atol = 1e-9;
    opt->h = 0.0;
    opt->h_init = 0.0;
    opt->h_max = 0.0;
    opt->max_steps = 100000;
    opt->pi_control = 1;
}

const char *mm_ode_method_name(mm_ode_method method)
{
    if ((unsigned)method < sizeof methods / sizeof methods[0])
        return methods[method].name;
    return "unknown";
}

/* Equal fixed steps: N = ceil(T / h), each step T / N <= h.  The 1e-12
 * slack keeps T / h = 100.00000000000001 (rounding) at 100 steps. */
double mm_ode_fixed_steps(double T, double h)
{
    double N = ceil(T / h * (1.0 - 1e-12));
    return N < 1.0 ? 1.0 : N;
}

static int is_fixed(const mm_ode_options *opt)
{
    return opt->method == MM_ODE_RK4 || opt->h > 0.0;
}

static int check_finite(mm_error *err, const char *field, const char *what,
                        double x)
{
    if (isfinite(x))
        return MM_OK;
    return mm_error_set(err, MM_EVALUE, field,
                        "%s '%s' must be a finite number, got %g", what, field, x);
}

static int check_nonneg(mm_error *err, const char *field, const char *what,
                        double x)
{
    int rc = check_finite(err, field, what, x);
    if (rc)
        return rc;
    if (x < 0.0)
        return mm_error_set(err, MM_ERANGE, field,
                            "%s '%s' must be >= 0, got %g", what, field, x);
    return MM_OK;
}

int mm_ode_check(const mm_ode_problem *prob, const mm_ode_options *opt,
                 const mm_ode_result *res, mm_error *err)
{
    int rc;
    assert(prob && opt);
    assert(prob->f && prob->y0);

    if (prob->n == 0 || prob->n > (size_t)MM_ODE_MAX_DIM)
        return mm_error_set(err, MM_ERANGE, "n",
                            "the system must have 1 to %ld equations, got %zu",
                            MM_ODE_MAX_DIM, prob->n);
    if ((rc = check_finite(err, "t0", "start time", prob->t0)) ||
        (rc = check_finite(err, "t_end", "end time", prob->t_end)))
        return rc;
    if (!(prob->t_end > prob->t0))
        return mm_error_set(err, MM_ERANGE, "t_end",
                            "end time 't_end' must be greater than the start "
                            "time t0 = %g s, got %g", prob->t0, prob->t_end);
    for (size_t i = 0; i < prob->n; i++)
        if (!isfinite(prob->y0[i]))
            return mm_error_set(err, MM_EVALUE, "y0",
                                "initial value y0[%zu] must be a finite number, "
                                "got %g", i, prob->y0[i]);

    if (prob->event_dir < -1 || prob->event_dir > 1)
        return mm_error_set(err, MM_ERANGE, "event_dir",
                            "event direction must be -1, 0 or +1, got %d",
                            prob->event_dir);
    if ((unsigned)opt->method >= sizeof methods / sizeof methods[0])
        return mm_error_set(err, MM_ERANGE, "method",
                            "unknown method %d (expected rk4, dopri5 or dop853)",
                            (int)opt->method);
    if ((rc = check_finite(err, "rtol", "relative tolerance", opt->rtol)))
        return rc;
    if (opt->rtol < MM_ODE_RTOL_MIN || opt->rtol > 1.0)
        return mm_error_set(err, MM_ERANGE, "rtol",
                            "relative tolerance 'rtol' must be between %g and 1, "
                            "got %g", MM_ODE_RTOL_MIN, opt->rtol);
    if ((rc = check_finite(err, "atol", "absolute tolerance", opt->atol)))
        return rc;
    if (!(opt->atol > 0.0))      /* Hairer: atol > 0, or y = 0 has no scale */
        return mm_error_set(err, MM_ERANGE, "atol",
                            "absolute tolerance 'atol' must be > 0 (use a tiny "
                            "value such as 1e-12 for relative accuracy), got %g",
                            opt->atol);
    if ((rc = check_nonneg(err, "h", "step", opt->h)) ||
        (rc = check_nonneg(err, "h_init", "first step", opt->h_init)) ||
        (rc = check_nonneg(err, "h_max", "largest step", opt->h_max)))
        return rc;
    if (opt->max_steps < 1 || opt->max_steps > MM_ODE_MAX_STEPS)
        return mm_error_set(err, MM_ERANGE, "max_steps",
                            "'max_steps' must be between 1 and %ld, got %ld",
                            MM_ODE_MAX_STEPS, opt->max_steps);

    double T = prob->t_end - prob->t0;
    double tmag = fmax(fabs(prob->t0), fabs(prob->t_end));
    if (opt->method == MM_ODE_RK4 && !(opt->h > 0.0))
        return mm_error_set(err, MM_ERANGE, "h",
                            "rk4 takes fixed steps: step 'h' must be > 0, got %g",
                            opt->h);
    if (is_fixed(opt)) {
        double N = mm_ode_fixed_steps(T, opt->h);
        if (N > (double)opt->max_steps)
            return mm_error_set(err, MM_ERANGE, "h",
                                "step h = %g s needs %.0f steps to cover %g s, "
                                "more than max_steps = %ld; use a larger step",
                                opt->h, N, T, opt->max_steps);
        if (T / N <= 10.0 * DBL_EPSILON * tmag)
            return mm_error_set(err, MM_ERANGE, "h",
                                "step h = %g s is too small to advance t "
                                "near %g s in double precision", opt->h, tmag);
    }

    if (!res)
        return MM_OK;
    assert(res->steps_cap == 0 || (res->t_steps && res->y_steps));
    if (res->nout == 0)
        return MM_OK;
    assert(res->t_out && res->y_out);
    for (size_t i = 0; i < res->nout; i++) {
        double ti = res->t_out[i];
        if (!isfinite(ti))
            return mm_error_set(err, MM_EVALUE, "t_out",
                                "output time t_out[%zu] must be a finite number, "
                                "got %g", i, ti);
        if (ti < prob->t0 || ti > prob->t_end)
            return mm_error_set(err, MM_ERANGE, "t_out",
                                "output time t_out[%zu] = %g s is outside the "
                                "interval [%g, %g] s", i, ti, prob->t0, prob->t_end);
        if (i > 0 && ti < res->t_out[i - 1])
            return mm_error_set(err, MM_ERANGE, "t_out",
                                "output times must be in increasing order: "
                                "t_out[%zu] = %g s comes after %g s",
                                i, ti, res->t_out[i - 1]);
    }
    return MM_OK;
}

/* ==== small numeric helpers ================================================ */

/* One run's bookkeeping: what every step needs to see. */
typedef struct run {
    const mm_ode_problem *p;
    mm_ode_work *w;
    size_t n;
    double rtol, atol;
    long nfev;       /* calls of f */
    double t_call;   /* t of the latest call of f (for messages) */
} run;

static int eval(run *r, double t, const double *y, double *dydt)
{
    r->nfev++;
    r->t_call = t;
    return r->p->f(t, y, dydt, r->p->params);
}

/* max without fmax's NaN rules: fmax is a library call, this is one
 * instruction, and NaN is caught separately (all_finite). */
static inline double maxd(double a, double b) { return a > b ? a : b; }
static inline double mind(double a, double b) { return a < b ? a : b; }

/* out = sum_{j=1..s} a[j] k[j]: a weighted sum of stage derivatives. */
static void wsum(size_t n, double *restrict out, const double *restrict a,
                 double *const *restrict k, int s)
{
    for (size_t i = 0; i < n; i++) {
        double sum = 0.0;
        for (int j = 1; j <= s; j++)
            sum += a[j] * k[j][i];
        out[i] = sum;
    }
}

static int all_finite(size_t n, const double *v)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return 0;
    return 1;
}

/* Error weight of component i: atol + rtol max(|y|, |y_new|) (HNW II.4). */
static double weight(const run *r, size_t i)
{
    const mm_ode_work *w = r->w;
    return r->atol + r->rtol * maxd(fabs(w->y[i]), fabs(w->ynew[i]));
}

/* What a step reports about its local error. */
typedef struct estimate {
    double err2;  /* square of the weighted RMS norm: accept when <= 1 (the
                     controller works with its logarithm, so no square root) */
    double abs;   /* max norm in units of y */
} estimate;

/* One step from (t, w->y) with step h: fills w->ynew and the estimate.
 * Expects k[1] = f(t, y); returns nonzero when f does. */
typedef int (*step_fn)(run *r, double t, double h, estimate *est);

/* ==== the three steps ====================================================== */

/* Classical RK4 (A&S 25.5.10) plus the FSAL evaluation k5 = f(t+h, y_new)
 * used for the error estimate and the Hermite dense output. */
static int step_rk4(run *r, double t, double h, estimate *est)
{
    mm_ode_work *w = r->w;
    const size_t n = r->n;
    const double *y = w->y;
    double *k1 = w->k[1], *k2 = w->k[2], *k3 = w->k[3], *k4 = w->k[4],
           *k5 = w->k[5], *yt = w->ytmp, *yn = w->ynew;
    int rc;

    for (size_t i = 0; i < n; i++)
        yt[i] = y[i] + 0.5 * h * k1[i];
    if ((rc = eval(r, t + 0.5 * h, yt, k2)))
        return rc;
    for (size_t i = 0; i < n; i++)
        yt[i] = y[i] + 0.5 * h * k2[i];
    if ((rc = eval(r, t + 0.5 * h, yt, k3)))
        return rc;
    for (size_t i = 0; i < n; i++)
        yt[i] = y[i] + h * k3[i];
    if ((rc = eval(r, t + h, yt, k4)))
        return rc;
    for (size_t i = 0; i < n; i++)
        yn[i] = y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    if ((rc = eval(r, t + h, yn, k5)))                /* FSAL */
        return rc;

    double sum = 0.0, mx = 0.0;
    for (size_t i = 0; i < n; i++) {
        double e = h / 6.0 * (k4[i] - k5[i]);          /* y4 - y3 */
        double q = e / weight(r, i);
        sum += q * q;
        mx = maxd(mx, fabs(e));
    }
    est->err2 = sum / (double)n;
    est->abs = mx;
    return 0;
}

/* Dormand–Prince 5(4): stages 2..6, y_new from row 7 (5th order), FSAL
 * stage 7 at y_new, error y5 - y4 = h sum e_i k_i. */
static int step_dopri5(run *r, double t, double h, estimate *est)
{
    mm_ode_work *w = r->w;
    const size_t n = r->n;
    const double *y = w->y, (*a)[8] = dp5_a, *c = dp5_c;
    double *k1 = w->k[1], *k2 = w->k[2], *k3 = w->k[3], *k4 = w->k[4],
           *k5 = w->k[5], *k6 = w->k[6], *k7 = w->k[7];
    double *yt = w->ytmp, *yn = w->ynew, *ys = w->ysti;
    int rc;

    for (size_t i = 0; i < n; i++)
        yt[i] = y[i] + h * a[2][1] * k1[i];
    if ((rc = eval(r, t + c[2] * h, yt, k2)))
        return rc;
    for (size_t i = 0; i < n; i++)
        yt[i] = y[i] + h * (a[3][1] * k1[i] + a[3][2] * k2[i]);
    if ((rc = eval(r, t + c[3] * h, yt, k3)))
        return rc;
    for (size_t i = 0; i < n; i++)
        yt[i] = y[i] + h * (a[4][1] * k1[i] + a[4][2] * k2[i] + a[4][3] * k3[i]);
    if ((rc = eval(r, t + c[4] * h, yt, k4)))
        return rc;
    for (size_t i = 0; i < n; i++)
        yt[i] = y[i] + h * (a[5][1] * k1[i] + a[5][2] * k2[i] + a[5][3] * k3[i]
                            + a[5][4] * k4[i]);
    if ((rc = eval(r, t + c[5] * h, yt, k5)))
        return rc;
    for (size_t i = 0; i < n; i++)                     /* stage 6 sits at c = 1 */
        ys[i] = y[i] + h * (a[6][1] * k1[i] + a[6][2] * k2[i] + a[6][3] * k3[i]
                            + a[6][4] * k4[i] + a[6][5] * k5[i]);
    if ((rc = eval(r, t + h, ys, k6)))
        return rc;
    for (size_t i = 0; i < n; i++)                     /* 5th-order solution */
        yn[i] = y[i] + h * (a[7][1] * k1[i] + a[7][3] * k3[i] + a[7][4] * k4[i]
                            + a[7][5] * k5[i] + a[7][6] * k6[i]);
    if ((rc = eval(r, t + h, yn, k7)))                 /* FSAL */
        return rc;

    const double *e = dp5_e;
    double sum = 0.0, mx = 0.0;
    for (size_t i = 0; i < n; i++) {
        double ei = h * (e[1] * k1[i] + e[3] * k3[i] + e[4] * k4[i] + e[5] * k5[i]
                         + e[6] * k6[i] + e[7] * k7[i]);   /* y5 - y4 */
        double q = ei / weight(r, i);
        sum += q * q;
        mx = maxd(mx, fabs(ei));
    }
    est->err2 = sum / (double)n;
    est->abs = mx;
    return 0;
}

/* Dormand–Prince 8(5,3): 12 stages.  The error estimate combines the 5th-
 * and 3rd-order embedded differences, as Hairer's DOP853 does:
 *     err = err5^2 / sqrt(err5^2 + 0.01 err3^2),
 * which behaves like O(h^8) and stays honest when err5 happens to be small.
 * The FSAL stage 13 is evaluated only once the step is accepted. */
static int step_dop853(run *r, double t, double h, estimate *est)
{
    mm_ode_work *w = r->w;
    const size_t n = r->n;
    const double *y = w->y, (*a)[17] = dop_a, *c = dop_c;
    double *k1 = w->k[1], *k2 = w->k[2], *k3 = w->k[3], *k4 = w->k[4],
           *k5 = w->k[5], *k6 = w->k[6], *k7 = w->k[7], *k8 = w->k[8],
           *k9 = w->k[9], *k10 = w->k[10], *k11 = w->k[11], *k12 = w->k[12];
    double *yt = w->ytmp, *yn = w->ynew, *ys = w->ysti;
    int rc;

    for (size_t i = 0; i < n; i++)
        yt[i] = y[i] + h * a[2][1] * k1[i];
    if ((rc = eval(r, t + c[2] * h, yt, k2)))
        return rc;
    for (size_t i = 0; i < n; i++)
        yt[i] = y[i] + h * (a[3][1] * k1[i] + a[3][2] * k2[i]);
    if ((rc = eval(r, t + c[3] * h, yt, k3)))
        return rc;
    for (size_t i = 0; i < n; i++)
        yt[i] = y[i] + h * (a[4][1] * k1[i] + a[4][3] * k3[i]);
    if ((rc = eval(r, t + c[4] * h, yt, k4)))
        return rc;
    for (size_t i = 0; i < n; i++)
        yt[i] = y[i] + h * (a[5][1] * k1[i] + a[5][3] * k3[i] + a[5][4] * k4[i]);
    if ((rc = eval(r, t + c[5] * h, yt, k5)))
        return rc;
    for (size_t i = 0; i < n; i++)
        yt[i] = y[i] + h * (a[6][1] * k1[i] + a[6][4] * k4[i] + a[6][5] * k5[i]);
    if ((rc = eval(r, t + c[6] * h, yt, k6)))
        return rc;
    for (size_t i = 0; i < n; i++)
        yt[i] = y[i] + h * (a[7][1] * k1[i] + a[7][4] * k4[i] + a[7][5] * k5[i]
                            + a[7][6] * k6[i]);
    if ((rc = eval(r, t + c[7] * h, yt, k7)))
        return rc;
    for (size_t i = 0; i < n; i++)
        yt[i] = y[i] + h * (a[8][1] * k1[i] + a[8][4] * k4[i] + a[8][5] * k5[i]
                            + a[8][6] * k6[i] + a[8][7] * k7[i]);
    if ((rc = eval(r, t + c[8] * h, yt, k8)))
        return rc;
    for (size_t i = 0; i < n; i++)
        yt[i] = y[i] + h * (a[9][1] * k1[i] + a[9][4] * k4[i] + a[9][5] * k5[i]
                            + a[9][6] * k6[i] + a[9][7] * k7[i] + a[9][8] * k8[i]);
    if ((rc = eval(r, t + c[9] * h, yt, k9)))
        return rc;
    for (size_t i = 0; i < n; i++)
        yt[i] = y[i] + h * (a[10][1] * k1[i] + a[10][4] * k4[i] + a[10][5] * k5[i]
                            + a[10][6] * k6[i] + a[10][7] * k7[i] + a[10][8] * k8[i]
                            + a[10][9] * k9[i]);
    if ((rc = eval(r, t + c[10] * h, yt, k10)))
        return rc;
    for (size_t i = 0; i < n; i++)
        yt[i] = y[i] + h * (a[11][1] * k1[i] + a[11][4] * k4[i] + a[11][5] * k5[i]
                            + a[11][6] * k6[i] + a[11][7] * k7[i] + a[11][8] * k8[i]
                            + a[11][9] * k9[i] + a[11][10] * k10[i]);
    if ((rc = eval(r, t + c[11] * h, yt, k11)))
        return rc;
    for (size_t i = 0; i < n; i++)                     /* stage 12 sits at c = 1 */
        ys[i] = y[i] + h * (a[12][1] * k1[i] + a[12][4] * k4[i] + a[12][5] * k5[i]
                            + a[12][6] * k6[i] + a[12][7] * k7[i] + a[12][8] * k8[i]
                            + a[12][9] * k9[i] + a[12][10] * k10[i]
                            + a[12][11] * k11[i]);
    if ((rc = eval(r, t + h, ys, k12)))
        return rc;

    const double *b = dop_b, *er = dop_er;
    double s5 = 0.0, s3 = 0.0, m5 = 0.0, m3 = 0.0;
    for (size_t i = 0; i < n; i++) {
        double inc = b[1] * k1[i] + b[6] * k6[i] + b[7] * k7[i] + b[8] * k8[i]
                     + b[9] * k9[i] + b[10] * k10[i] + b[11] * k11[i]
                     + b[12] * k12[i];                 /* (y8 - y) / h */
        double e5 = er[1] * k1[i] + er[6] * k6[i] + er[7] * k7[i] + er[8] * k8[i]
                    + er[9] * k9[i] + er[10] * k10[i] + er[11] * k11[i]
                    + er[12] * k12[i];                 /* (y8 - y5) / h */
        double e3 = inc - dop_bhh1 * k1[i] - dop_bhh2 * k9[i]
                    - dop_bhh3 * k12[i];               /* (y8 - y3) / h */
        yn[i] = y[i] + h * inc;                        /* 8th-order solution */
        double inv_sk = 1.0 / weight(r, i);
        s5 += (e5 * inv_sk) * (e5 * inv_sk);
        s3 += (e3 * inv_sk) * (e3 * inv_sk);
        m5 = maxd(m5, fabs(e5));
        m3 = maxd(m3, fabs(e3));
    }
    /* err = |h| s5 / sqrt(n (s5 + 0.01 s3)), with s5, s3 sums of squares */
    double deno = s5 + 0.01 * s3;
    if (deno <= 0.0)
        deno = 1.0;
    est->err2 = h * h * s5 * s5 / ((double)n * deno);
    deno = m5 * m5 + 0.01 * m3 * m3;
    est->abs = deno > 0.0 ? fabs(h) * m5 * m5 / sqrt(deno) : 0.0;
    return 0;
}

static const step_fn steppers[] = {
    [MM_ODE_RK4] = step_rk4,
    [MM_ODE_DOPRI5] = step_dopri5,
    [MM_ODE_DOP853] = step_dop853,
};

/* ==== dense output ========================================================= */

/* Every continuous extension here is written in Hairer's nested form
 *     y(t + theta h) = c0 + th (c1 + th1 (c2 + th (c3 + th1 (c4 + th (c5
 *                      + th1 (c6 + th c7))))))        th1 = 1 - th,
 * where c0..c3 alone are the cubic Hermite interpolant through y, y_new
 * with slopes f(t, y), f(t+h, y_new) (enough for RK4: 3rd order, error
 * O(h^4) like RK4 itself), and the further rows correct it to 4th order
 * (DOPRI5, one row) or 7th order (DOP853, four rows). */
static int dense_prepare(run *r, const method_info *m, mm_ode_method method,
                         double t, double h)
{
    mm_ode_work *w = r->w;
    size_t n = r->n;
    double *c = w->cont;
    const double *f1 = w->k[m->fsal];
    int rc;

    if (method == MM_ODE_DOP853) {        /* three extra stages 14, 15, 16 */
        const double *y = w->y, (*a)[17] = dop_a, *cc = dop_c;
        double *const *k = w->k, *yt = w->ytmp;
        for (size_t i = 0; i < n; i++)
            yt[i] = y[i] + h * (a[14][1] * k[1][i] + a[14][7] * k[7][i]
                                + a[14][8] * k[8][i] + a[14][9] * k[9][i]
                                + a[14][10] * k[10][i] + a[14][11] * k[11][i]
                                + a[14][12] * k[12][i] + a[14][13] * k[13][i]);
        if ((rc = eval(r, t + cc[14] * h, yt, k[14])))
            return rc;
        for (size_t i = 0; i < n; i++)
            yt[i] = y[i] + h * (a[15][1] * k[1][i] + a[15][6] * k[6][i]
                                + a[15][7] * k[7][i] + a[15][8] * k[8][i]
                                + a[15][11] * k[11][i] + a[15][12] * k[12][i]
                                + a[15][13] * k[13][i] + a[15][14] * k[14][i]);
        if ((rc = eval(r, t + cc[15] * h, yt, k[15])))
            return rc;
        for (size_t i = 0; i < n; i++)
            yt[i] = y[i] + h * (a[16][1] * k[1][i] + a[16][6] * k[6][i]
                                + a[16][7] * k[7][i] + a[16][8] * k[8][i]
                                + a[16][9] * k[9][i] + a[16][13] * k[13][i]
                                + a[16][14] * k[14][i] + a[16][15] * k[15][i]);
        if ((rc = eval(r, t + cc[16] * h, yt, k[16])))
            return rc;
    }
    for (size_t i = 0; i < n; i++) {              /* cubic Hermite part */
        double ydiff = w->ynew[i] - w->y[i];
        double bspl = h * w->k[1][i] - ydiff;
        c[i] = w->y[i];
        c[n + i] = ydiff;
        c[2 * n + i] = bspl;
        c[3 * n + i] = ydiff - h * f1[i] - bspl;
    }
    int extra = 0;                                /* correction rows */
    if (method == MM_ODE_DOPRI5) {
        wsum(n, c + 4 * n, dp5_d, w->k, 7);
        extra = 1;
    } else if (method == MM_ODE_DOP853) {
        /* stages 2-5 have no weight in any row: summing from 6 on gives the
         * same numbers (their terms were exact zeros) for 3/4 of the work */
        for (int row = 0; row < 4; row++) {
            const double *d = dop_d[row];
            double *out = c + (size_t)(4 + row) * n;
            for (size_t i = 0; i < n; i++) {
                double sum = 0.0 + d[1] * w->k[1][i];
                for (int j = 6; j <= 16; j++)
                    sum += d[j] * w->k[j][i];
                out[i] = sum;
            }
        }
        extra = 4;
    }
    for (size_t i = 4 * n; i < (size_t)(4 + extra) * n; i++)
        c[i] *= h;
    return 0;
}

/* Evaluate the prepared extension at theta in [0, 1] into out (n values). */
static void dense_eval(const mm_ode_work *w, size_t n, int rows, double theta,
                       double *out)
{
    const double *c = w->cont;
    double th1 = 1.0 - theta;
    for (size_t i = 0; i < n; i++) {
        double acc = c[(size_t)(rows - 1) * n + i];
        for (int row = rows - 2; row >= 0; row--)   /* factors th, th1, th, ... */
            acc = c[(size_t)row * n + i] + ((row % 2 == 0) ? theta : th1) * acc;
        out[i] = acc;
    }
}

/* ==== initial step (Hairer's HINIT, HNW II.4) ============================== */

/* Choose h so that an Euler step changes y by about 1 % of its weight, and
 * h^q max(|f|, |f'|) ~ 0.01.  Uses k[2] as scratch; one call of f. */
static int initial_step(run *r, double t, double q, double hmax, double *h_out)
{
    mm_ode_work *w = r->w;
    size_t n = r->n;
    const double *f0 = w->k[1];
    double dnf = 0.0, dny = 0.0;
    for (size_t i = 0; i < n; i++) {
        double sk = r->atol + r->rtol * fabs(w->y[i]);
        dnf += (f0[i] / sk) * (f0[i] / sk);
        dny += (w->y[i] / sk) * (w->y[i] / sk);
    }
    double h = (dnf <= 1e-10 || dny <= 1e-10) ? 1e-6 : sqrt(dny / dnf) * 0.01;
    h = fmin(h, hmax);
    for (size_t i = 0; i < n; i++)                    /* explicit Euler step */
        w->ytmp[i] = w->y[i] + h * f0[i];
    int rc = eval(r, t + h, w->ytmp, w->k[2]);
    if (rc)
        return rc;
    double der2 = 0.0;                                /* |y''| estimate */
    for (size_t i = 0; i < n; i++) {
        double sk = r->atol + r->rtol * fabs(w->y[i]);
        double d = (w->k[2][i] - f0[i]) / sk;
        der2 += d * d;
    }
    der2 = sqrt(der2) / h;
    double der12 = fmax(der2, sqrt(dnf));
    double h1 = (der12 <= 1e-15) ? fmax(1e-6, h * 1e-3)
                                 : pow(0.01 / der12, 1.0 / q);
    *h_out = fmin(100.0 * h, fmin(h1, hmax));         /* fmin drops a NaN h1 */
    return 0;
}

/* ==== the driver =========================================================== */

static int stopped_by_f(mm_error *err, int rc, double t)
{
    int code = (rc > 0 && rc < MM_STATUS_COUNT) ? rc : MM_EINTERNAL;
    return mm_error_set(err, code, "f",
                        "the right-hand side stopped the integration at "
                        "t = %.6g s (it returned %d)", t, rc);
}

static void swap(double **a, double **b)
{
    double *tmp = *a;
    *a = *b;
    *b = tmp;
}

/* Hairer's stiffness test (HW IV.2): h |lambda| estimated from the last
 * two stages at c = 1, |f(y_new) - f(y_sti)| / |y_new - y_sti|.  When it
 * exceeds the stability boundary for 15 accepted steps, the step size is
 * being held by stability, not accuracy: the problem is stiff. */
typedef struct stiffness {
    int iasti, nonsti;   /* steps at / off the boundary (Hairer's names) */
    int stiff;
} stiffness;

static void stiffness_test(stiffness *st, const mm_ode_work *w, size_t n,
                           const method_info *m, double h)
{
    double num = 0.0, den = 0.0;
    for (size_t i = 0; i < n; i++) {
        double df = w->k[m->fsal][i] - w->k[m->stiff_stage][i];
        double dy = w->ynew[i] - w->ysti[i];
        num += df * df;
        den += dy * dy;
    }
    double hlamb = den > 0.0 ? h * sqrt(num / den) : 0.0;
    if (hlamb > m->stiff_lim) {
        st->nonsti = 0;
        if (++st->iasti >= 15)
            st->stiff = 1;
    } else if (++st->nonsti == 6) {
        st->iasti = 0;
    }
}

/* Fill the grid rows with t_out in (t, t_stop] from the step just accepted
 * (y at t, y_new at t + h; t_stop is passed as such because t + h may
 * round to a neighbour of t_end, and an event may end the step early):
 * prepare the continuous extension once per step (*prepared says it is
 * ready), then evaluate it at each point, advancing res->nout_done.
 * Returns f's nonzero value with *f_failed set (DOP853 calls f three more
 * times), or MM_ENONFINITE. */
static int write_grid(run *r, const method_info *m, mm_ode_method method,
                      mm_ode_result *res, double t, double t_stop, double h,
                      int *prepared, int *f_failed, mm_error *err)
{
    const size_t n = r->n;
    size_t io = res->nout_done;
    if (io >= res->nout || res->t_out[io] > t_stop)
        return MM_OK;                          /* no grid point in this step */
    if (!*prepared) {
        int rc = dense_prepare(r, m, method, t, h);
        if (rc) {
            *f_failed = 1;
            return rc;
        }
        *prepared = 1;
    }
    for (; io < res->nout && res->t_out[io] <= t_stop; io++) {
        double *row = res->y_out + io * n;
        dense_eval(r->w, n, m->dense_rows, (res->t_out[io] - t) / h, row);
        if (!all_finite(n, row))
            return mm_error_set(err, MM_ENONFINITE, "y",
                                "the interpolated solution is not finite at "
                                "t = %.6g s", res->t_out[io]);
        res->nout_done = io + 1;
    }
    return MM_OK;
}

/* ==== events =============================================================== */

/* Did g cross zero from g0 to g1 in the direction dir (see mm_ode.h)? */
static int crossed(int dir, double g0, double g1)
{
    return (dir <= 0 && g0 > 0.0 && g1 <= 0.0) || (dir >= 0 && g0 < 0.0 && g1 >= 0.0);
}

/* g on the continuous extension of the step from t of length h. */
typedef struct event_arg {
    run *r;
    int rows;
    double t, h;
    double *y;       /* scratch: the interpolated state */
    long evals;
    int rc;          /* the event function's own nonzero return */
} event_arg;

static int event_at(double theta, double *g, void *ctx)
{
    event_arg *e = ctx;
    const mm_ode_problem *p = e->r->p;
    dense_eval(e->r->w, e->r->n, e->rows, theta, e->y);
    e->evals++;
    e->rc = p->event(e->t + theta * e->h, e->y, g, p->params);
    return e->rc;
}

static int stopped_by_event(mm_error *err, int rc, double t)
{
    int code = (rc > 0 && rc < MM_STATUS_COUNT) ? rc : MM_EINTERNAL;
    return mm_error_set(err, code, "event",
                        "the event function stopped the integration at "
                        "t = %.6g s (it returned %d)", t, rc);
}

/* After an accepted step from (t, y) to (t + h, y_new): has the event
 * fired?  g_old holds g at t and receives g at the end.  On a crossing the
 * zero is located on the continuous extension (Brent in theta to a few
 * eps of t), *t_stop receives its time and y_new the state there. */
static int event_step(run *r, const method_info *m, mm_ode_method method, double t,
                      double t_new, double h, double *g_old, int *hit, double *t_stop,
                      int *prepared, long *g_evals, mm_error *err)
{
    const mm_ode_problem *p = r->p;
    mm_ode_work *w = r->w;
    double g_new;
    (*g_evals)++;
    int rc = p->event(t_new, w->ynew, &g_new, p->params);
    if (rc)
        return stopped_by_event(err, rc, t_new);
    if (!isfinite(g_new))
        return mm_error_set(err, MM_ENONFINITE, "event",
                            "the event function is not finite at t = %.6g s", t_new);
    *hit = crossed(p->event_dir, *g_old, g_new);
    *t_stop = t_new;
    if (*hit && g_new != 0.0) {
        if (!*prepared) {
            if ((rc = dense_prepare(r, m, method, t, h)))
                return stopped_by_f(err, rc, r->t_call);
            *prepared = 1;
        }
        event_arg ea = {.r = r, .rows = m->dense_rows, .t = t, .h = h, .y = w->ytmp};
        double theta, g_at, width;
        rc = mm_roots_brent(event_at, &ea, 0.0, 1.0, *g_old, g_new,
                            2.0 * DBL_EPSILON * fabs(t_new) / h, 200, &theta, &g_at,
                            &width, NULL, NULL, err);
        *g_evals += ea.evals;
        if (rc)
            return ea.rc ? stopped_by_event(err, ea.rc, t + theta * h) : rc;
        if (theta < 1.0) {
            *t_stop = t + theta * h;
            dense_eval(w, r->n, m->dense_rows, theta, w->ynew);   /* the state at the zero */
        }
    }
    *g_old = g_new;
    return MM_OK;
}

int mm_ode_solve(const mm_ode_problem *prob, const mm_ode_options *opt,
                 mm_ode_work *w, mm_ode_result *res, mm_error *err)
{
    assert(res);
    int rc = mm_ode_check(prob, opt, res, err);
    if (rc)
        return rc;
    mm_error_clear(err);

    const size_t n = prob->n;
    const mm_ode_method method = opt->method;
    const method_info *m = &methods[method];
    const step_fn step = steppers[method];
    const int fixed = is_fixed(opt);
    const double t0 = prob->t0, t_end = prob->t_end;

    /* Counters live in locals during the run and go to res at the end. */
    long n_acc = 0, n_rej = 0, attempts = 0, n_half = 0;
    double h_small = 0.0, h_large = 0.0, err_max = 0.0, err_sum = 0.0;
    stiffness st = {0, 0, 0};
    double t = t0;
    double g_old = 0.0;          /* the event function at t */
    long g_evals = 0;
    res->event = 0;
    res->nout_done = 0;
    res->n_stored = 0;
    run r = {.p = prob, .w = w, .n = n, .rtol = opt->rtol, .atol = opt->atol};
    if (!w) {
        rc = mm_error_set(err, MM_ENOMEM, "",
                          "not enough memory for the integrator's workspace");
        goto out;
    }
    assert(w->n >= n);
    memcpy(w->y, prob->y0, n * sizeof(double));

    /* Start: f at t0, grid rows at t0, the first recorded state. */
    if ((rc = eval(&r, t, w->y, w->k[1]))) {
        rc = stopped_by_f(err, rc, t);
        goto out;
    }
    if (!all_finite(n, w->k[1])) {
        rc = mm_error_set(err, MM_ENONFINITE, "f",
                          "the right-hand side is not finite at t0 = %g s", t0);
        goto out;
    }
    if (prob->event) {
        g_evals++;
        if ((rc = prob->event(t, w->y, &g_old, prob->params))) {
            rc = stopped_by_event(err, rc, t);
            goto out;
        }
        if (!isfinite(g_old)) {
            rc = mm_error_set(err, MM_ENONFINITE, "event",
                              "the event function is not finite at t0 = %g s", t0);
            goto out;
        }
    }
    while (res->nout_done < res->nout && res->t_out[res->nout_done] <= t0) {
        memcpy(res->y_out + res->nout_done * n, w->y, n * sizeof(double));
        res->nout_done++;
    }
    if (res->steps_cap > 0) {
        res->t_steps[0] = t0;
        memcpy(res->y_steps, w->y, n * sizeof(double));
        res->n_stored = 1;
    }

    /* Step size: equal fixed steps, or h_init / HINIT for adaptive runs. */
    const double hmax = opt->h_max > 0.0 ? fmin(opt->h_max, t_end - t0)
                                         : t_end - t0;
    long n_fixed = 0;
    double h;
    if (fixed) {
        n_fixed = (long)mm_ode_fixed_steps(t_end - t0, opt->h);
        h = (t_end - t0) / (double)n_fixed;
    } else if (opt->h_init > 0.0) {
        h = fmin(opt->h_init, hmax);
    } else if ((rc = initial_step(&r, t, m->q, hmax, &h))) {
        rc = stopped_by_f(err, rc, r.t_call);
        goto out;
    }

    /* The first step.  HINIT sizes it from f and f' alone (a caller's
     * h_init from whatever the caller knew), so nothing says it is short
     * enough for the error estimate to be asymptotic: ~h^8 for DOP853 (h^6
     * where its 5th-order part dominates), h^5 for DOPRI5.  Beyond that the
     * estimate, a polynomial in h, can pass through zero and pass a step
     * that errs far over the tolerance: dyn-double-pendulum's reference
     * (DOP853, rtol 1e-10) guessed 0.0157 s, estimate 0.43, true error 43
     * (same weighted norm), and its energy kept that error, 1.1e-8, for the
     * whole run.  Later steps are sized by the controller from estimates of
     * steps already taken.  So until a step is accepted, each trial also
     * takes its first half, whose estimate should be 2^-8..2^-6 (DOP853) or
     * 2^-5 (DOPRI5) of the whole step's, and the trial counts as erring at
     * least m->first = 2^(p-1) times the half's estimate (p = 6, 5: 32, 16,
     * half the least asymptotic ratio): an asymptotic estimate stands as it
     * is, and so does one at round-off (both tiny); one that did not shrink
     * with h is replaced, for the test and for sizing the next step.  In
     * the example the half's estimate was 3.96, above the whole step's:
     * counted as 127, rejected; then 0.0089 s (7.9) and 0.0066 s (1.15)
     * were rejected on their own estimates, and the run began with 0.0059
     * s: estimate 0.44, half 0.0014, true error 0.0025.  Cost: one step's
     * calls of f per trial of the first step (n_first_halves). */

    /* PI controller (HW IV.2, Gustafsson's form as in Hairer's codes):
     *   h_new = h * safe * err_n^(-alpha) * err_{n-1}^beta,
     *   alpha = 1/q - 0.75 beta;  beta = 0 gives the elementary controller.
     * Worked in logarithms: one log and one exp per step. */
    const double beta = opt->pi_control ? m->beta : 0.0;
    const double alpha = 1.0 / m->q - 0.75 * beta;
    const double log_floor = log(1e-4);   /* Hairer's FACOLD: err_{n-1} >= 1e-4 */
    double log_err_old = log_floor;
    int rejected_last = 0, nonfinite_last = 0;

    for (;;) {
        /* --- choose the step ---------------------------------------------- */
        int last = 0;
        double t_new;
        if (fixed) {
            last = (n_acc + 1 == n_fixed);
            t_new = last ? t_end : t0 + (double)(n_acc + 1) * h;
        } else {
            if (attempts >= opt->max_steps) {
                if (st.stiff)
                    rc = mm_error_set(err, MM_ENOCONV, "max_steps",
                        "stopped after %ld steps at t = %.4g s of %.4g s: the "
                        "problem is stiff (steps held near %.3g s by the stability "
                        "limit); shorten the interval or use an implicit method",
                        attempts, t, t_end, h);
                else
                    rc = mm_error_set(err, MM_ENOCONV, "max_steps",
                        "stopped after %ld steps at t = %.4g s of %.4g s: the "
                        "problem may be stiff or the tolerance too strict; raise "
                        "the tolerance, shorten the interval or raise max_steps",
                        attempts, t, t_end);
                goto out;
            }
            if (h <= 10.0 * DBL_EPSILON * fabs(t) || h < DBL_MIN) {
                if (nonfinite_last)
                    rc = mm_error_set(err, MM_ENONFINITE, "y",
                        "the solution becomes infinite or nan near t = %.6g s: "
                        "steps down to %.3g s could not avoid it (does it blow "
                        "up there?)", t, h);
                else
                    rc = mm_error_set(err, MM_ENOCONV, "rtol",
                        "the step size fell to %.3g s at t = %.6g s, below what "
                        "double precision resolves: the tolerance may be too "
                        "strict, or the solution is singular there", h, t);
                goto out;
            }
            if (t + 1.01 * h >= t_end) {     /* stretch up to 1 % to land on t_end */
                h = t_end - t;
                last = 1;
            }
            t_new = last ? t_end : t + h;
        }
        const double hs = t_new - t;          /* the step actually taken */
        attempts++;

        /* --- take it, test it ---------------------------------------------- */
        estimate est, half = {0.0, 0.0};
        const int first = !fixed && n_acc == 0;   /* no estimate vouches for h yet */
        if (first) {                          /* the step's first half, for its estimate */
            n_half++;
            if ((rc = step(&r, t, 0.5 * hs, &half))) {
                rc = stopped_by_f(err, rc, r.t_call);
                goto out;
            }
        }
        if ((rc = step(&r, t, hs, &est))) {
            rc = stopped_by_f(err, rc, r.t_call);
            goto out;
        }
        int finite = isfinite(est.err2) && all_finite(n, w->ynew);
        if (first) {                          /* see "The first step" above */
            finite = finite && isfinite(half.err2);
            est.err2 = maxd(est.err2, m->first * m->first * half.err2);
            est.abs = maxd(est.abs, m->first * half.abs);
        }
        double h_next = hs;
        if (fixed) {
            if (!finite) {
                rc = mm_error_set(err, MM_ENONFINITE, "h",
                    "the solution became infinite or nan in the step from "
                    "t = %.6g s: the step h = %.3g s may be too large for the "
                    "method's stability", t, hs);
                goto out;
            }
        } else if (!finite) {                 /* overflow in a trial: shrink hard */
            n_rej++;
            nonfinite_last = 1;
            rejected_last = 1;
            h = 0.25 * hs;
            continue;
        } else {
            /* h_new / h = safe err^-alpha err_old^beta, limited to
             * [fac_min, fac_max]; written as exp(log) without divisions, as
             * the next step waits for it. */
            double log_err = 0.5 * log(est.err2);  /* -inf for err = 0: fine */
            double ratio = m->safe * exp(beta * log_err_old - alpha * log_err);
            h_next = hs * maxd(m->fac_min, mind(m->fac_max, ratio));
            if (est.err2 > 1.0) {             /* reject: retry smaller, no PI memory */
                n_rej++;
                nonfinite_last = 0;
                rejected_last = 1;
                h = hs * maxd(m->fac_min, m->safe * exp(-alpha * log_err));
                continue;
            }
            log_err_old = maxd(log_err, log_floor);
        }
        nonfinite_last = 0;

        /* --- accepted: FSAL stage, stiffness, outputs ---------------------- */
        if (method == MM_ODE_DOP853 &&        /* FSAL stage 13 */
            (rc = eval(&r, t_new, w->ynew, w->k[13]))) {
            rc = stopped_by_f(err, rc, r.t_call);
            goto out;
        }
        if (!fixed && m->stiff_stage > 0 &&
            ((n_acc + 1) % STIFF_EVERY == 0 || st.iasti > 0))
            stiffness_test(&st, w, n, m, hs);
        int f_failed = 0, prepared = 0, hit = 0;
        double t_stop = t_new;
        if (prob->event && (rc = event_step(&r, m, method, t, t_new, hs, &g_old, &hit, &t_stop,
                                            &prepared, &g_evals, err)))
            goto out;
        if ((rc = write_grid(&r, m, method, res, t, t_stop, hs, &prepared, &f_failed, err))) {
            if (f_failed)
                rc = stopped_by_f(err, rc, r.t_call);
            goto out;
        }
        if (res->steps_cap > 0) {
            if (res->n_stored >= res->steps_cap) {
                rc = mm_error_set(err, MM_ETOOBIG, "steps",
                    "recording every step needs room for more than %zu steps "
                    "(reached t = %.4g s of %.4g s); ask for an output grid "
                    "instead, or loosen the tolerance", res->steps_cap, t, t_end);
                goto out;
            }
            res->t_steps[res->n_stored] = t_stop;
            memcpy(res->y_steps + res->n_stored * n, w->ynew, n * sizeof(double));
            res->n_stored++;
        }

        /* --- move on: y <- y_new, f(t, y) <- the FSAL stage ---------------- */
        n_acc++;
        h_small = n_acc == 1 ? hs : mind(h_small, hs);
        h_large = maxd(h_large, hs);
        err_max = maxd(err_max, est.abs);
        err_sum += est.abs;
        swap(&w->y, &w->ynew);
        swap(&w->k[1], &w->k[m->fsal]);
        t = t_stop;
        if (hit) {                            /* stopped by the event */
            res->event = 1;
            res->t_event = t;
            break;
        }
        if (last)
            break;
        if (!fixed) {
            h = mind(h_next, hmax);
            if (rejected_last)                /* no growth right after a rejection */
                h = mind(h, hs);
            rejected_last = 0;
        }
    }
    assert(res->event || res->nout_done == res->nout);   /* every t_out <= t_end was reached */
    rc = MM_OK;

out:
    res->t_reached = t;
    res->n_accepted = n_acc;
    res->n_rejected = n_rej;
    res->n_eval = r.nfev;
    res->h_smallest = h_small;
    res->h_largest = h_large;
    res->err_local_max = err_max;
    res->err_sum = err_sum;
    res->stiff = st.stiff;
    res->n_event_evals = g_evals;
    res->n_first_halves = n_half;
    if (res->y_end && w)
        memcpy(res->y_end, w->y, n * sizeof(double));
    return rc;
}

int mm_ode_run(const mm_ode_problem *prob, const mm_ode_options *opt, mm_ode_result *res, mm_error *err)
{
    int rc = mm_ode_check(prob, opt, res, err);
    if (rc != MM_OK)
        return rc;
    mm_ode_work *w = mm_ode_work_alloc(prob->n);
    rc = mm_ode_solve(prob, opt, w, res, err);
    mm_ode_work_free(w);
    return rc;
}

mm_ode_options mm_ode_options_adaptive(mm_ode_method m, double rtol, double atol, long max_steps)
{
    mm_ode_options o;
    mm_ode_options_init(&o);
    o.method = m;
    o.rtol = rtol;
    o.atol = atol;
    o.max_steps = max_steps;
    return o;
}
