/* mm_mdof.c — modes, exact and exact-discrete motion, modal superposition
 * of M q'' + C q' + K q = F(t) (see mm_mdof.h).
 */
#include "mm_mdof.h"

#include <complex.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mm_complex.h"
#include "mm_dd.h"
#include "mm_linalg.h"
#include "mm_ode.h"
#include "mm_sdof.h"

/* ==== small dense helpers (row-major) ======================================= */

/* C = A B, all N x N; C must not alias A or B. */
static void matmul(int N, const double *A, const double *B, double *C)
{
    memset(C, 0, (size_t)N * N * sizeof *C);
    for (int i = 0; i < N; i++)
        for (int k = 0; k < N; k++) {
            double a = A[(size_t)i * N + k];
            if (a == 0)
                continue;
            const double *b = B + (size_t)k * N;
            double *c = C + (size_t)i * N;
            for (int j = 0; j < N; j++)
                c[j] += a * b[j];
        }
}

static void matvec(int N, const double *A, const double *x, double *y)
{
    for (int i = 0; i < N; i++) {
        double s = 0;
        for (int j = 0; j < N; j++)
            s += A[(size_t)i * N + j] * x[j];
        y[i] = s;
    }
}

static double norm1(int N, const double *A)
{
    double best = 0;
    for (int j = 0; j < N; j++) {
        double s = 0;
        for (int i = 0; i < N; i++)
            s += fabs(A[(size_t)i * N + j]);
        best = fmax(best, s);
    }
    return best;
}

/* The balance frequency w = sqrt(max K_ii / M_ii) (1 without stiffness). */
static double balance_omega(const mm_mdof_system *s)
{
    double w2 = 0;
    for (int i = 0; i < s->n; i++)
        if (s->K)
            w2 = fmax(w2, s->K[(size_t)i * s->n + i] / s->M[(size_t)i * s->n + i]);
    return w2 > 0 && isfinite(w2) ? sqrt(w2) : 1.0;
}

/* ==== modes ================================================================ */

int mm_mdof_modes(const mm_mdof_system *s, int nmodes, double *omega, double *Phi,
                  int *n_rigid, mm_error *err)
{
    int n = s->n, rc;
    if (n < 1 || n > MM_MDOF_MAX_DOF)
        return mm_error_set(err, MM_ERANGE, "n", "the number of degrees of freedom must be "
                            "between 1 and %d; got %d", MM_MDOF_MAX_DOF, n);
    if (nmodes < 1 || nmodes > n)
        return mm_error_set(err, MM_ERANGE, "modes", "modes must be between 1 and n = %d; got %d",
                            n, nmodes);
    double *lam = malloc((size_t)n * sizeof *lam);
    double *V = Phi ? malloc((size_t)n * (size_t)(nmodes == n ? n : nmodes) * sizeof *V) : NULL;
    if (!lam || (Phi && !V)) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
        goto out;
    }
    rc = nmodes == n ? mm_linalg_sygv(n, s->K, s->M, lam, V, err)
                     : mm_linalg_sygv_first(n, nmodes, s->K, s->M, lam, V, err);
    if (rc)
        goto out;
    double scale = balance_omega(s);
    scale *= scale;
    int nr = 0;
    for (int j = 0; j < nmodes; j++) {
        if (lam[j] < -1e3 * MM_MDOF_RIGID_TOL * scale) {
            rc = mm_error_set(err, MM_ERANGE, "K", "K must be positive semidefinite (a stable "
                              "system): K phi = lambda M phi has lambda = %.4g", lam[j]);
            goto out;
        }
        if (lam[j] <= MM_MDOF_RIGID_TOL * scale) {
            omega[j] = 0;
            nr++;
        } else {
            omega[j] = sqrt(lam[j]);
        }
    }
    if (Phi) {
        int ld = nmodes == n ? n : nmodes;
        for (int i = 0; i < n; i++)
            for (int j = 0; j < nmodes; j++)
                Phi[(size_t)i * nmodes + j] = V[(size_t)i * ld + j];
    }
    if (n_rigid)
        *n_rigid = nr;
out:
    free(V);
    free(lam);
    return rc;
}

void mm_mdof_two_dof(double m1, double m2, double k1, double k2, double k3, double *omega,
                     double *phi)
{
    double a = (k1 + k2) / m1, d = (k2 + k3) / m2, b = k2 > 0 ? -k2 / sqrt(m1 * m2) : 0;
    /* p = (a - d)/2 from the exact products: a - d = (k1 m2 + k2 (m2 - m1)
     * - k3 m1)/(m1 m2) cancels when the two uncoupled frequencies are
     * close, and the rounding of a and d (eps a) would become an error of
     * eps a/|a - d| in the modes' smaller components */
    mm_dd n = mm_dd_add(mm_dd_sub(mm_dd_two_prod(k1, m2), mm_dd_two_prod(k3, m1)),
                        mm_dd_sub(mm_dd_two_prod(k2, m2), mm_dd_two_prod(k2, m1)));
    double p = n.hi / (2 * m1 * m2), h = hypot(p, b);
    double l2 = 0.5 * (a + d) + h;
    double l1 = l2 > 0 ? (k1 * k2 + k1 * k3 + k2 * k3) / (m1 * m2 * l2) : 0;
    /* (c, s), the upper mode, from whichever row of [a - l2, b; b, d - l2]
     * does not cancel: l2 - d = p + h for p >= 0, l2 - a = h - p for p < 0,
     * sums of terms of one sign, so every component to a few eps of itself.
     * cos and sin of atan2(2b, a - d)/2 lost the smaller component near
     * theta = pi/2: an error of eps in theta, eps/|cos theta| of the
     * component (5.5e-12 at a mass ratio of 5.6e5). */
    double u = p >= 0 ? p + h : b, v = p >= 0 ? b : h - p, r = hypot(u, v);
    double c = r > 0 ? u / r : 1, s = r > 0 ? v / r : 0;   /* r = 0: k2 = 0, a = d */
    double x[2][2] = {{-s, c}, {c, s}};          /* x[j]: mode j of [a b; b d] */
    omega[0] = sqrt(l1);
    omega[1] = sqrt(l2);
    for (int j = 0; j < 2; j++) {
        double sg = x[j][0] < 0 || (x[j][0] == 0 && x[j][1] < 0) ? -1 : 1;
        phi[j] = sg * x[j][0] / sqrt(m1);         /* phi = M^-1/2 x: phi^T M phi = 1 */
        phi[2 + j] = sg * x[j][1] / sqrt(m2);
    }
}

/* G = [0 I; -M^-1 K  -M^-1 C] (2n x 2n), or its balanced form with the
 * velocity scaled by 1/w when w > 0:  [0 wI; -M^-1 K / w  -M^-1 C]. */
static int state_matrix(const mm_mdof_system *s, double w, double *G, int ldg, mm_error *err)
{
    int n = s->n, rc;
    size_t nn = (size_t)n * n;
    double *MiK = malloc(nn * sizeof *MiK), *MiC = calloc(nn, sizeof *MiC);
    double *Z = calloc(nn, sizeof *Z);
    if (!MiK || !MiC || !Z) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
        goto out;
    }
    mm_linalg_solve_info info;
    if ((rc = mm_linalg_solve(n, n, s->M, s->K ? s->K : Z, MiK, &info, err)) ||
        (s->C && (rc = mm_linalg_solve(n, n, s->M, s->C, MiC, &info, err)))) {
        if (rc == MM_ESINGULAR)
            mm_error_set(err, rc, "M", "the mass matrix M is singular: some motion has no inertia");
        goto out;
    }
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            G[(size_t)i * ldg + j] = 0;
            G[(size_t)i * ldg + n + j] = i == j ? w : 0;
            G[(size_t)(n + i) * ldg + j] = -MiK[(size_t)i * n + j] / w;
            G[(size_t)(n + i) * ldg + n + j] = -MiC[(size_t)i * n + j];
        }
out:
    free(Z);
    free(MiC);
    free(MiK);
    return rc;
}

static int cmp_cmode(const void *a, const void *b)
{
    double x = ((const mm_mdof_cmode *)a)->omega, y = ((const mm_mdof_cmode *)b)->omega;
    return (x > y) - (x < y);
}

static int cmp_abs(const void *a, const void *b)
{
    double x = fabs(*(const double *)a), y = fabs(*(const double *)b);
    return (x > y) - (x < y);
}

/* A mode from its eigenvalue lambda = re + i im (im >= 0). */
static mm_mdof_cmode cmode(double re, double im)
{
    double w = hypot(re, im);
    return (mm_mdof_cmode){w, w > 0 ? -re / w : 0, im};
}

int mm_mdof_complex_modes(const mm_mdof_system *s, mm_mdof_cmode *modes, mm_error *err)
{
    int n = s->n, n2 = 2 * n, rc;
    if (n < 1 || n > MM_MDOF_MAX_STATE_DOF)
        return mm_error_set(err, MM_ERANGE, "n", "complex modes are computed for 1 to %d degrees "
                            "of freedom; got %d", MM_MDOF_MAX_STATE_DOF, n);
    int damped = 0;
    for (int i = 0; s->C && i < n * n; i++)
        damped |= s->C[i] != 0;
    if (!damped) {                         /* the real modes, exactly undamped */
        double *w = malloc((size_t)n * sizeof *w);
        if (!w)
            return mm_error_set(err, MM_ENOMEM, "", "out of memory");
        rc = mm_mdof_modes(s, n, w, NULL, NULL, err);
        for (int j = 0; rc == MM_OK && j < n; j++)
            modes[j] = (mm_mdof_cmode){w[j], 0, w[j]};
        free(w);
        return rc;
    }
    double *G = malloc((size_t)n2 * n2 * sizeof *G), *wr = malloc((size_t)n2 * sizeof *wr);
    double *wi = malloc((size_t)n2 * sizeof *wi), *re = malloc((size_t)n2 * sizeof *re);
    double *lr = malloc((size_t)n * sizeof *lr), *li = malloc((size_t)n * sizeof *li);
    if (!G || !wr || !wi || !re || !lr || !li) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
        goto out;
    }
    if ((rc = state_matrix(s, 1.0, G, n2, err)) || (rc = mm_linalg_geev(n2, G, wr, wi, NULL, err)))
        goto out;
    int m = 0, nre = 0;
    for (int j = 0; j < n2; j++) {
        if (wi[j] > 0 && m < n) {                 /* one of a pair: the other is its conjugate */
            lr[m] = wr[j], li[m] = wi[j];
            modes[m++] = cmode(wr[j], wi[j]);
        } else if (wi[j] == 0) {
            re[nre++] = wr[j];
        }
    }
    /* A defective (repeated) pair, as at C = diag(20, 0) with M = I,
     * K = [200 -100; -100 100], comes out split by about sqrt(eps); the
     * mean of a cluster is accurate to rounding.  Pairs closer than 1e-6
     * of their size are taken as one repeated value. */
    for (int i = 0; i < m; i++) {
        int c = 1;
        double sr = lr[i], si = li[i];
        for (int j = i + 1; j < m; j++)
            if (hypot(lr[j] - lr[i], li[j] - li[i]) <= 1e-6 * hypot(lr[i], li[i])) {
                sr += lr[j], si += li[j];
                c++;
            }
        if (c == 1)
            continue;
        for (int j = i; j < m; j++)
            if (hypot(lr[j] - lr[i], li[j] - li[i]) <= 1e-6 * hypot(lr[i], li[i]) && j != i)
                modes[j] = cmode(sr / c, si / c);
        modes[i] = cmode(sr / c, si / c);
    }
    qsort(re, (size_t)nre, sizeof *re, cmp_abs);
    for (int i = 0; i < nre / 2 && m < n; i++) {  /* nested pairs: smallest with largest */
        double l1 = re[i], l2 = re[nre - 1 - i], w = sqrt(fabs(l1 * l2));
        modes[m++] = (mm_mdof_cmode){w, w > 0 ? -(l1 + l2) / (2 * w) : 0, 0};
    }
    if (m != n) {
        rc = mm_error_set(err, MM_EINTERNAL, "", "the state matrix gave %d modes for %d degrees "
                          "of freedom", m, n);
        goto out;
    }
    qsort(modes, (size_t)n, sizeof *modes, cmp_cmode);
    rc = MM_OK;
out:
    free(li);
    free(lr);
    free(re);
    free(wi);
    free(wr);
    free(G);
    return rc;
}

/* ==== the matrix exponential ================================================ */

/* E = e^A (N x N) by scaling and squaring of the [13/13] Pade approximant
 * (N. J. Higham, SIAM J. Matrix Anal. Appl. 26 (2005) 1179-1193): exact to
 * a few eps of ||A|| for any A. */
static int expm(int N, const double *A, double *E, mm_error *err)
{
    static const double b[14] = {64764752532480000.0, 32382376266240000.0, 7771770303897600.0,
                                 1187353796428800.0,  129060195264000.0,   10559470521600.0,
                                 670442572800.0,      33522128640.0,       1323241920.0,
                                 40840800.0,          960960.0,            16380.0,
                                 182.0,               1.0};
    const double theta13 = 5.371920351148152;
    size_t NN = (size_t)N * N;
    double nrm = norm1(N, A);
    int sq = nrm > theta13 ? (int)ceil(log2(nrm / theta13)) : 0;
    double scale = ldexp(1.0, -sq);
    double *W = calloc(8 * NN, sizeof *W);
    if (!W)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    double *S = W, *A2 = W + NN, *A4 = W + 2 * NN, *A6 = W + 3 * NN, *U = W + 4 * NN,
           *V = W + 5 * NN, *T = W + 6 * NN, *P = W + 7 * NN;
    for (size_t i = 0; i < NN; i++)
        S[i] = A[i] * scale;
    matmul(N, S, S, A2);
    matmul(N, A2, A2, A4);
    matmul(N, A4, A2, A6);
    for (size_t i = 0; i < NN; i++)
        T[i] = b[13] * A6[i] + b[11] * A4[i] + b[9] * A2[i];
    matmul(N, A6, T, U);
    for (size_t i = 0; i < NN; i++)
        U[i] += b[7] * A6[i] + b[5] * A4[i] + b[3] * A2[i];
    for (int i = 0; i < N; i++)
        U[(size_t)i * N + i] += b[1];
    memcpy(T, U, NN * sizeof *T);
    matmul(N, S, T, U);                        /* U = A (...) */
    for (size_t i = 0; i < NN; i++)
        T[i] = b[12] * A6[i] + b[10] * A4[i] + b[8] * A2[i];
    matmul(N, A6, T, V);
    for (size_t i = 0; i < NN; i++)
        V[i] += b[6] * A6[i] + b[4] * A4[i] + b[2] * A2[i];
    for (int i = 0; i < N; i++)
        V[(size_t)i * N + i] += b[0];
    for (size_t i = 0; i < NN; i++) {          /* (V - U) E = V + U */
        T[i] = V[i] - U[i];
        P[i] = V[i] + U[i];
    }
    mm_error e2;
    int rc = mm_linalg_solve(N, N, T, P, E, NULL, &e2);
    if (rc) {
        free(W);
        return mm_error_set(err, rc == MM_ESINGULAR ? MM_ENONFINITE : rc, "h",
                            "the transition matrix could not be formed (%s)", e2.msg);
    }
    for (int k = 0; k < sq; k++) {
        matmul(N, E, E, T);
        memcpy(E, T, NN * sizeof *E);
    }
    free(W);
    return MM_OK;
}

/* P^g by repeated squaring into R (N x N); T1, T2 scratch. */
static void matpow(int N, const double *P, long g, double *R, double *T1, double *T2)
{
    size_t NN = (size_t)N * N;
    memset(R, 0, NN * sizeof *R);
    for (int i = 0; i < N; i++)
        R[(size_t)i * N + i] = 1;
    memcpy(T1, P, NN * sizeof *T1);
    while (g > 0) {
        if (g & 1) {
            matmul(N, R, T1, T2);
            memcpy(R, T2, NN * sizeof *R);
        }
        g >>= 1;
        if (g > 0) {
            matmul(N, T1, T1, T2);
            memcpy(T1, T2, NN * sizeof *T1);
        }
    }
}

/* ==== carrying a state from sample to sample ================================== */

typedef struct carrier {
    int N;                 /* order of the augmented state */
    int exact;             /* 1: e^{G g h}; 0: P^g */
    const double *G;       /* generator times h (exact) or one step's P (discrete) */
} carrier;

static int gap_matrix(const carrier *c, long g, double *R, double *T1, double *T2, mm_error *err)
{
    size_t NN = (size_t)c->N * c->N;
    if (!c->exact) {
        matpow(c->N, c->G, g, R, T1, T2);
        return MM_OK;
    }
    for (size_t i = 0; i < NN; i++)
        T1[i] = c->G[i] * (double)g;
    return expm(c->N, T1, R, err);
}

/* w_i = (gap matrix) w_{i-1}; rows[i * N ..] receive each sample's state. */
static int carry(const carrier *c, const double *w0, int nt, const long *k, double *rows,
                 mm_error *err)
{
    int N = c->N, rc = MM_OK;
    size_t NN = (size_t)N * N;
    double *R = malloc(3 * NN * sizeof *R), *w = malloc((size_t)N * sizeof *w);
    if (!R || !w) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
        goto out;
    }
    long have = -1;                    /* the gap R holds */
    if (k[0] > 0) {
        if ((rc = gap_matrix(c, k[0], R, R + NN, R + 2 * NN, err)))
            goto out;
        matvec(N, R, w0, rows);
        have = k[0];
    } else {
        memcpy(rows, w0, (size_t)N * sizeof *rows);
    }
    for (int i = 1; i < nt; i++) {
        long g = k[i] - k[i - 1];
        if (g == 0) {
            memcpy(rows + (size_t)i * N, rows + (size_t)(i - 1) * N, (size_t)N * sizeof *rows);
            continue;
        }
        if (g != have) {
            if ((rc = gap_matrix(c, g, R, R + NN, R + 2 * NN, err)))
                goto out;
            have = g;
        }
        matvec(N, R, rows + (size_t)(i - 1) * N, rows + (size_t)i * N);
        for (int j = 0; j < N; j++)
            if (!isfinite(rows[(size_t)i * N + j])) {
                rc = mm_error_set(err, MM_ENONFINITE, "h", "the motion overflows by step %ld", k[i]);
                goto out;
            }
    }
out:
    free(w);
    free(R);
    return rc;
}

static int check_samples(const mm_mdof_system *s, double h, int nt, const long *k, mm_error *err)
{
    if (s->n < 1 || s->n > MM_MDOF_MAX_STATE_DOF)
        return mm_error_set(err, MM_ERANGE, "n", "exact responses are computed for 1 to %d degrees "
                            "of freedom; got %d", MM_MDOF_MAX_STATE_DOF, s->n);
    if (!(h > 0) || !isfinite(h))
        return mm_error_set(err, MM_ERANGE, "h", "the time unit h must be > 0; got %g", h);
    if (nt < 1 || k[0] < 0)
        return mm_error_set(err, MM_ERANGE, "h", "no sample times");
    for (int i = 1; i < nt; i++)
        if (k[i] < k[i - 1])
            return mm_error_set(err, MM_ERANGE, "h", "sample steps must not decrease");
    return MM_OK;
}

/* The load's columns: (cos, sin) at the end of the state, coupled to the
 * rows of a (discrete) or v (exact) through the vector f. */
int mm_mdof_exact(const mm_mdof_system *s, const mm_mdof_motion *mo, double h, int nt,
                  const long *k, double *q, double *v, mm_error *err)
{
    int rc = check_samples(s, h, nt, k, err);
    if (rc)
        return rc;
    int n = s->n, N = 2 * n + 2;
    double w = balance_omega(s);
    double *G = calloc((size_t)N * N, sizeof *G), *rows = malloc((size_t)nt * N * sizeof *rows);
    double *f = calloc((size_t)n, sizeof *f), *w0 = calloc((size_t)N, sizeof *w0);
    if (!G || !rows || !f || !w0) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
        goto out;
    }
    if ((rc = state_matrix(s, w, G, N, err)))
        goto out;
    /* the load's state is (sg cos, sg sin): sg = 1, or where the load's
     * column of G, f / w, would be larger than w (the mechanics' rate), the
     * power of 2 just above the static deflection max|f| / w^2, so that the
     * column f / (w sg) is at most w.  With sg = 1 a large force set
     * ||G k h||, and expm's squarings, each adding its rounding to the whole
     * matrix, grew with the force: 12 squarings and an error of 3400 eps of
     * the motion at a chain of 1 g masses pushed by 3e3 N
     * (vib-ndof-transient), where the mechanics alone needs one */
    double sg = 1;
    if (mo->F) {                                        /* f = M^-1 F / (w sg) */
        mm_linalg_solve_info info;
        if ((rc = mm_linalg_solve(n, 1, s->M, mo->F, f, &info, err)))
            goto out;
        double fmx = 0;
        for (int i = 0; i < n; i++)
            fmx = fmax(fmx, fabs(f[i]));
        if (fmx / (w * w) > 1 && isfinite(fmx / (w * w)))
            sg = ldexp(1.0, ilogb(fmx / (w * w)) + 1);
        for (int i = 0; i < n; i++)
            G[(size_t)(n + i) * N + 2 * n] = f[i] / w / sg;
    }
    G[(size_t)(2 * n) * N + 2 * n + 1] = -mo->omega;    /* c' = -omega s, s' = omega c */
    G[(size_t)(2 * n + 1) * N + 2 * n] = mo->omega;
    for (size_t i = 0; i < (size_t)N * N; i++)
        G[i] *= h;
    for (int i = 0; i < n; i++) {
        w0[i] = mo->q0 ? mo->q0[i] : 0;
        w0[n + i] = mo->v0 ? mo->v0[i] / w : 0;
    }
    w0[2 * n] = sg;
    carrier c = {N, 1, G};
    if ((rc = carry(&c, w0, nt, k, rows, err)))
        goto out;
    for (int i = 0; i < nt; i++)
        for (int j = 0; j < n; j++) {
            q[(size_t)i * n + j] = rows[(size_t)i * N + j];
            if (v)
                v[(size_t)i * n + j] = rows[(size_t)i * N + n + j] * w;
        }
out:
    free(w0);
    free(f);
    free(rows);
    free(G);
    return rc;
}

int mm_mdof_newmark_exact(const mm_mdof_system *s, const mm_mdof_motion *mo,
                          const mm_newmark_options *o, int nt, const long *k, double *q,
                          double *v, mm_error *err)
{
    int rc = check_samples(s, o->h, nt, k, err);
    if (rc)
        return rc;
    int n = s->n, n3 = 3 * n, N = n3 + 2;
    double w = balance_omega(s), h = o->h;
    double *A = malloc((size_t)n3 * n3 * sizeof *A), *B0 = malloc((size_t)n3 * n * sizeof *B0);
    double *B1 = malloc((size_t)n3 * n * sizeof *B1), *P = calloc((size_t)N * N, sizeof *P);
    double *rows = malloc((size_t)nt * N * sizeof *rows), *w0 = calloc((size_t)N, sizeof *w0);
    double *r = calloc((size_t)n, sizeof *r);
    if (!A || !B0 || !B1 || !P || !rows || !w0 || !r) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
        goto out;
    }
    if ((rc = mm_newmark_amplification(n, s->M, s->C, s->K, o, A, B0, B1, err)))
        goto out;
    /* balanced state (q, v/w, a/w^2, cos, sin): P = D A D^-1 */
    const double d[3] = {1, 1 / w, 1 / (w * w)};
    double co = cos(mo->omega * h), si = sin(mo->omega * h);
    for (int i = 0; i < n3; i++) {
        for (int j = 0; j < n3; j++)
            P[(size_t)i * N + j] = A[(size_t)i * n3 + j] * d[i / n] / d[j / n];
        double bc = 0, bs = 0;
        if (mo->F)
            for (int j = 0; j < n; j++) {
                bc += (B0[(size_t)i * n + j] + B1[(size_t)i * n + j] * co) * mo->F[j];
                bs -= B1[(size_t)i * n + j] * si * mo->F[j];
            }
        P[(size_t)i * N + n3] = bc * d[i / n];
        P[(size_t)i * N + n3 + 1] = bs * d[i / n];
    }
    P[(size_t)n3 * N + n3] = co, P[(size_t)n3 * N + n3 + 1] = -si;
    P[(size_t)(n3 + 1) * N + n3] = si, P[(size_t)(n3 + 1) * N + n3 + 1] = co;
    /* the start: q''(0) from (1), as mm_newmark_solve takes it */
    for (int i = 0; i < n; i++) {
        double acc = mo->F ? mo->F[i] : 0;
        for (int j = 0; j < n; j++) {
            size_t ij = (size_t)i * n + j;
            acc -= (s->K ? s->K[ij] : 0) * (mo->q0 ? mo->q0[j] : 0) +
                   (s->C ? s->C[ij] : 0) * (mo->v0 ? mo->v0[j] : 0);
        }
        r[i] = acc;
    }
    mm_linalg_solve_info info;
    if ((rc = mm_linalg_solve(n, 1, s->M, r, r, &info, err)))
        goto out;
    for (int i = 0; i < n; i++) {
        w0[i] = mo->q0 ? mo->q0[i] : 0;
        w0[n + i] = (mo->v0 ? mo->v0[i] : 0) / w;
        w0[2 * n + i] = r[i] / (w * w);
    }
    w0[n3] = 1;                                         /* cos(omega 0) */
    carrier c = {N, 0, P};
    if ((rc = carry(&c, w0, nt, k, rows, err)))
        goto out;
    for (int i = 0; i < nt; i++)
        for (int j = 0; j < n; j++) {
            q[(size_t)i * n + j] = rows[(size_t)i * N + j];
            if (v)
                v[(size_t)i * n + j] = rows[(size_t)i * N + n + j] * w;
        }
out:
    free(r);
    free(w0);
    free(rows);
    free(P);
    free(B1);
    free(B0);
    free(A);
    return rc;
}

/* ==== a general force: DOP853 ================================================== */

typedef struct ode_ctx {
    const mm_mdof_system *s;
    mm_newmark_force_fn force;
    void *params;
    double *Minv, *r;
    long evals;
} ode_ctx;

/* y = (q, q'): y' = (q', M^-1 (F - C q' - K q)). */
static int ode_rhs(double t, const double *y, double *dy, void *p)
{
    ode_ctx *c = p;
    const mm_mdof_system *s = c->s;
    int n = s->n, rc = c->force(t, y, y + n, c->r, c->params);
    c->evals++;
    if (rc)
        return rc;
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < n; j++)
            c->r[i] -= (s->C ? s->C[i * n + j] * y[n + j] : 0) + (s->K ? s->K[i * n + j] * y[j] : 0);
        dy[i] = y[n + i];
    }
    matvec(n, c->Minv, c->r, dy + n);
    return 0;
}

int mm_mdof_ode(const mm_mdof_system *s, mm_newmark_force_fn force, void *params, const double *q0,
                const double *v0, int nt, const double *t, double rtol, double scale, double *q,
                long *evals, mm_error *err)
{
    int n = s->n, rc;
    if (n < 1 || n > MM_MDOF_MAX_STATE_DOF)
        return mm_error_set(err, MM_ERANGE, "n", "the reference is computed for 1 to %d degrees of "
                            "freedom; got %d", MM_MDOF_MAX_STATE_DOF, n);
    size_t nn = (size_t)n * n;
    double *Minv = malloc(nn * sizeof *Minv), *Id = calloc(nn, sizeof *Id);
    double *y = malloc((size_t)nt * 2 * n * sizeof *y), *y0 = malloc(2 * (size_t)n * sizeof *y0);
    double *r = malloc((size_t)n * sizeof *r);
    mm_ode_work *w = mm_ode_work_alloc((size_t)(2 * n));
    ode_ctx c = {s, force, params, Minv, r, 0};
    if (!Minv || !Id || !y || !y0 || !r || !w) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
        goto out;
    }
    for (int i = 0; i < n; i++) {
        Id[(size_t)i * n + i] = 1;
        y0[i] = q0 ? q0[i] : 0;
        y0[n + i] = v0 ? v0[i] : 0;
    }
    if ((rc = mm_linalg_solve(n, n, s->M, Id, Minv, NULL, err)))
        goto out;
    mm_ode_problem prob = {.n = (size_t)(2 * n), .f = ode_rhs, .params = &c, .t0 = 0,
                           .t_end = t[nt - 1] > 0 ? t[nt - 1] : 1, .y0 = y0};
    mm_ode_options opt;
    mm_ode_options_init(&opt);
    opt.method = MM_ODE_DOP853;
    opt.rtol = rtol;
    opt.atol = rtol * scale;
    opt.max_steps = 1000000;
    mm_ode_result res = {.t_out = t, .nout = (size_t)nt, .y_out = y};
    if ((rc = mm_ode_check(&prob, &opt, &res, err)) || (rc = mm_ode_solve(&prob, &opt, w, &res, err)))
        goto out;
    for (int k = 0; k < nt; k++)
        memcpy(q + (size_t)k * n, y + (size_t)k * 2 * n, (size_t)n * sizeof *q);
out:
    if (evals)
        *evals = c.evals;
    mm_ode_work_free(w);
    free(r);
    free(y0);
    free(y);
    free(Id);
    free(Minv);
    return rc;
}

/* ==== one modal coordinate ===================================================== */

/* eta'' + c eta' + omega^2 eta = p cos(Omega t), no switching off. */
static double sdof_harmonic(double omega, double c, double e0, double ed0, double p, double Omega,
                            double t, double *etad)
{
    if (omega > 0 && c > 4 * omega) {
        /* strongly overdamped (zeta > 2): two decaying exponentials, which
         * never overflow (cosh and e^{-zeta omega t} would, at large t) */
        double hc = 0.5 * c, sq = hc * sqrt((1 - 2 * omega / c) * (1 + 2 * omega / c));
        double r1 = -(hc + sq), r2 = -omega * omega / (hc + sq);      /* fast, slow: no cancellation */
        double complex P = p / mm_cmplx(omega * omega - Omega * Omega, c * Omega), e = cexp(mm_cmplx(0, Omega * t));
        double xp0 = creal(P), vp0 = -Omega * cimag(P);
        double A = ((ed0 - vp0) - r2 * (e0 - xp0)) / (r1 - r2), B = (e0 - xp0) - A;
        double e1 = exp(r1 * t), e2 = exp(r2 * t);
        if (etad)
            *etad = A * r1 * e1 + B * r2 * e2 + creal(mm_cmplx(0, Omega) * P * e);
        return A * e1 + B * e2 + creal(P * e);
    }
    if (omega > 0) {
        mm_sdof s = {.m = 1, .c = c, .k = omega * omega, .F0 = p, .omega = Omega, .x0 = e0, .v0 = ed0};
        mm_sdof_props pr;
        mm_sdof_props_get(&s, &pr);
        return mm_sdof_x(&s, &pr, t, etad);
    }
    /* a rigid-body mode: eta'' + c eta' = p cos(Omega t) */
    if (c == 0) {
        double x, v;
        if (Omega == 0) {
            x = e0 + ed0 * t + 0.5 * p * t * t;
            v = ed0 + p * t;
        } else {
            double st = sin(0.5 * Omega * t);
            x = e0 + ed0 * t + 2 * p * st * st / (Omega * Omega);    /* (1 - cos)/Omega^2 */
            v = ed0 + p * sin(Omega * t) / Omega;
        }
        if (etad)
            *etad = v;
        return x;
    }
    double em = -expm1(-c * t);                                      /* 1 - e^{-ct} */
    if (Omega == 0) {                                                /* u = eta' -> p/c */
        double u = p / c;
        if (etad)
            *etad = u + (ed0 - u) * (1 - em);
        return e0 + u * t + (ed0 - u) * em / c;
    }
    double complex P = p / mm_cmplx(-Omega * Omega, c * Omega);     /* eta_p = Re(P e^{i Omega t}) */
    double complex e = cexp(mm_cmplx(0, Omega * t));
    double xp0 = creal(P), vp0 = -Omega * cimag(P);
    double B = -(ed0 - vp0) / c;                                     /* eta_h = A + B e^{-ct} */
    if (etad)
        *etad = -c * B * (1 - em) + creal(mm_cmplx(0, Omega) * P * e);
    return (e0 - xp0) - B * em + creal(P * e);                       /* A + B e^{-ct} = e0 - xp0 - B (1 - e^{-ct}) */
}

double mm_mdof_sdof_pulse(double omega, double c, double e0, double ed0,
                          const mm_mdof_pulse *load, double t, double *etad)
{
    if (t < load->t_off)
        return sdof_harmonic(omega, c, e0, ed0, load->p, load->Omega, t, etad);
    double v1, x1 = sdof_harmonic(omega, c, e0, ed0, load->p, load->Omega, load->t_off, &v1);
    return sdof_harmonic(omega, c, x1, v1, 0, 0, t - load->t_off, etad);
}

/* phi_j(z) = sum_i z^i / (i + j)!, j = 0..5: the series for |z| < 1, else
 * phi_0 = e^z and phi_{j+1} = (phi_j - 1/j!) / z (no cancellation there). */
static void phi_functions(double complex z, double complex ph[6])
{
    if (cabs(z) < 1) {
        for (int j = 0; j < 6; j++) {
            double complex sum = 0, term = 1;
            double f = 1;
            for (int k = 2; k <= j; k++)
                f *= k;
            term = 1 / f;                              /* z^0 / j! */
            for (int i = 0; i < 30 && term != 0; i++) {
                sum += term;
                term *= z / (i + j + 1);
            }
            ph[j] = sum;
        }
        return;
    }
    double f = 1;
    ph[0] = cexp(z);
    for (int j = 0; j < 5; j++) {
        if (j > 1)
            f *= j;                                    /* j! */
        ph[j + 1] = (ph[j] - 1 / f) / z;
    }
}

/* the augmented system y = (omega eta, eta', u_0..u_3), u_k = (tau/dt)^k / k!,
 * by the matrix exponential: the fallback near critical damping */
static void sdof_poly_expm(double omega, double c, const double a[4], double dt, double *eta, double *etad)
{
    double A[36] = {0}, E[36], y0[6] = {omega * *eta, *etad, 1, 0, 0, 0}, dk = dt;
    A[1] = omega * dt;
    A[6] = -omega * dt, A[7] = -c * dt;
    for (int k = 0; k < 4; k++, dk *= dt)
        A[8 + k] = a[k] * dk * (k == 3 ? 6 : k == 2 ? 2 : 1);     /* a_k k! dt^{k+1} */
    for (int k = 1; k < 4; k++)
        A[(2 + k) * 6 + 1 + k] = 1;                    /* du_k = u_{k-1} d(tau/dt) */
    mm_error e;
    if (expm(6, A, E, &e) != MM_OK) {                  /* out of memory only */
        *eta = *etad = NAN;
        return;
    }
    double y[2] = {0, 0};
    for (int r = 0; r < 2; r++)
        for (int k = 0; k < 6; k++)
            y[r] += E[r * 6 + k] * y0[k];
    *eta = y[0] / omega;
    *etad = y[1];
}

void mm_mdof_sdof_poly(double omega, double c, const double a[4], double dt, double *eta,
                       double *etad)
{
    if (omega > 0) {
        /* the free motion, then the load's response from rest,
         *   sum_k a_k k! dt^{k+1} (phi_{k+1}(r1 dt) - phi_{k+1}(r2 dt)) / (r1 - r2)
         * with the roots r1, r2 of r^2 + c r + omega^2: no cancellation
         * however fast the load changes, while the roots are apart */
        double zeta = 0.5 * c / omega, hc = 0.5 * c;
        if (fabs(zeta - 1) < 0.1) {
            sdof_poly_expm(omega, c, a, dt, eta, etad);
            return;
        }
        double complex r1, r2;
        if (zeta > 1) {
            double sq = hc * sqrt((1 - omega / hc) * (1 + omega / hc));
            r1 = -(hc + sq), r2 = -omega * omega / (hc + sq);
        } else {
            double wd = omega * sqrt((1 - zeta) * (1 + zeta));
            r1 = mm_cmplx(-hc, wd), r2 = mm_cmplx(-hc, -wd);
        }
        double vh, xh = sdof_harmonic(omega, c, *eta, *etad, 0, 0, dt, &vh);
        double complex p1[6], p2[6], fe = 0, fv = 0;
        phi_functions(r1 * dt, p1);
        phi_functions(r2 * dt, p2);
        double fk = 1, dk = dt;
        for (int k = 0; k < 4; k++) {
            if (k > 1)
                fk *= k;
            if (a[k] != 0) {
                fe += a[k] * fk * dk * (p1[k + 1] - p2[k + 1]);
                fv += a[k] * fk * dk * (r1 * p1[k + 1] - r2 * p2[k + 1]);
            }
            dk *= dt;
        }
        *eta = xh + creal(fe / (r1 - r2));
        *etad = vh + creal(fv / (r1 - r2));
        return;
    }
    if (c == 0) {                     /* integrate the load twice */
        double d2 = dt * dt;
        *eta += *etad * dt + d2 * (a[0] / 2 + dt * (a[1] / 6 + dt * (a[2] / 12 + dt * a[3] / 20)));
        *etad += dt * (a[0] + dt * (a[1] / 2 + dt * (a[2] / 3 + dt * a[3] / 4)));
        return;
    }
    /* a rigid-body mode: u = eta', u' + c u = p; from rest by the same
     * functions, u: sum_k a_k k! dt^{k+1} phi_{k+1}(-c dt), and eta, the
     * response of eta'' + c eta' = p: sum_k a_k k! dt^{k+2} phi_{k+2}(-c dt) */
    double complex ph[6];
    phi_functions(-c * dt, ph);
    double em = -expm1(-c * dt), u0 = *etad, fu = 0, fx = 0, fk = 1, dk = dt;
    for (int k = 0; k < 4; k++) {
        if (k > 1)
            fk *= k;
        fu += a[k] * fk * dk * creal(ph[k + 1]);
        fx += a[k] * fk * dk * dt * creal(ph[k + 2]);
        dk *= dt;
    }
    *eta += u0 * em / c + fx;
    *etad = u0 * (1 - em) + fu;
}

int mm_mdof_modal_response(int n, int m, const double *omega, const double *c,
                           const double *Phi, int ld, const double *M, const double *q0,
                           const double *v0, const double *F, const mm_mdof_pulse *g,
                           int nt, const double *t, double *q, mm_error *err)
{
    if (m < 1 || m > ld)
        return mm_error_set(err, MM_ERANGE, "modes", "modes retained must be between 1 and %d; "
                            "got %d", ld, m);
    double *e = calloc((size_t)3 * m, sizeof *e), *Mx = malloc((size_t)n * sizeof *Mx);
    if (!e || !Mx) {
        free(Mx);
        free(e);
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    }
    double *e0 = e, *ed0 = e + m, *p = e + 2 * m;
    for (int pass = 0; pass < 2; pass++) {       /* phi^T M q0, phi^T M v0 */
        const double *x = pass == 0 ? q0 : v0;
        if (!x || !M)
            continue;
        matvec(n, M, x, Mx);
        for (int j = 0; j < m; j++) {
            double sum = 0;
            for (int i = 0; i < n; i++)
                sum += Phi[(size_t)i * ld + j] * Mx[i];
            (pass == 0 ? e0 : ed0)[j] = sum;
        }
    }
    if (F)
        for (int j = 0; j < m; j++) {
            double sum = 0;
            for (int i = 0; i < n; i++)
                sum += Phi[(size_t)i * ld + j] * F[i];
            p[j] = sum;
        }
    memset(q, 0, (size_t)nt * n * sizeof *q);
    for (int j = 0; j < m; j++) {
        mm_mdof_pulse gj = {p[j] * g->p, g->Omega, g->t_off};
        for (int k = 0; k < nt; k++) {
            double eta = mm_mdof_sdof_pulse(omega[j], c ? c[j] : 0, e0[j], ed0[j], &gj, t[k], NULL);
            for (int i = 0; i < n; i++)
                q[(size_t)k * n + i] += Phi[(size_t)i * ld + j] * eta;
        }
    }
    free(Mx);
    free(e);
    return MM_OK;
}

/* ==== a chain of n equal masses (chapter 5, vibrations) ======================= */

double mm_mdof_chain_theta(int n, int j, int free_end)
{
    return free_end ? (2 * j + 1) * M_PI / (2 * (2 * n + 1.0)) : (j + 1) * M_PI / (2 * (n + 1.0));
}

void mm_mdof_chain_matrices(int n, double m, double k, int free_end, double *M, double *K)
{
    memset(M, 0, (size_t)n * n * sizeof *M);
    memset(K, 0, (size_t)n * n * sizeof *K);
    for (int i = 0; i < n; i++) {
        M[(size_t)i * n + i] = m;
        K[(size_t)i * n + i] = i == n - 1 && free_end ? k : 2 * k;
        if (i + 1 < n)
            K[(size_t)i * n + i + 1] = K[(size_t)(i + 1) * n + i] = -k;
    }
}

void mm_mdof_chain_band(int n, double m, double k, int free_end, double *Mb, double *Kb)
{
    for (int i = 0; i < n; i++) {
        Kb[2 * i] = i == n - 1 && free_end ? k : 2 * k;
        Kb[2 * i + 1] = i < n - 1 ? -k : 0;
        Mb[2 * i] = m;
        Mb[2 * i + 1] = 0;
    }
}

int mm_mdof_static_residual(int n, int m, const double *K, const double *omega, const double *Phi, int p,
                            double Fp, double *r, mm_error *err)
{
    double *F = calloc((size_t)n, sizeof *F);
    if (!F)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    F[p] = Fp;
    mm_linalg_solve_info info;
    int rc = mm_linalg_solve(n, 1, K, F, r, &info, err);
    free(F);
    if (rc)
        return rc;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < m; j++)
            r[i] -= Phi[(size_t)i * n + j] * Phi[(size_t)p * n + j] * Fp / (omega[j] * omega[j]);
    return MM_OK;
}

int mm_mdof_chain_modes(int n, double m, double k, int free_end, int nev, double *lambda, double *V,
                        mm_error *err)
{
    int dense = nev == 0, rc;
    size_t size = dense ? (size_t)n * n : 2 * (size_t)n;
    double *Mx = malloc(size * sizeof *Mx), *Kx = malloc(size * sizeof *Kx);
    if (!Mx || !Kx) {
        rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
    } else if (dense) {
        mm_mdof_chain_matrices(n, m, k, free_end, Mx, Kx);
        rc = mm_linalg_sygv(n, Kx, Mx, lambda, V, err);
    } else {
        mm_mdof_chain_band(n, m, k, free_end, Mx, Kx);
        rc = mm_linalg_sbgv_first(n, 1, nev, Kx, Mx, lambda, V, err);
    }
    free(Mx);
    free(Kx);
    return rc;
}
