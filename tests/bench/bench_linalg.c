/* bench_linalg.c — what mm_linalg costs, beside GSL's own routines.
 *
 * Tables:
 *   1. A x = b for n = 3, 10, 100, 300: mm_linalg_solve (LAPACK dgesvx:
 *      equilibration, LU, condition estimate, one refinement step, plus
 *      our residual) against GSL's plain LU (gsl_linalg_LU_decomp +
 *      LU_solve, no condition estimate), and mm_linalg_cond2 (an SVD);
 *      with the error of x against a known solution.
 *   2. The generalized symmetric eigenproblem K v = lambda M v of a
 *      fixed-free chain of n masses (tridiagonal K, diagonal M), n = 10 ..
 *      1000: all modes (dsygvd) against the first 10 only, dense (dsygvx)
 *      and banded (dsbgvx + inverse iteration), and GSL's
 *      gsl_eigen_gensymmv (all modes) up to n = 300; with the largest
 *      relative error of the first 10 omega against the closed form
 *      omega_j = 2 sqrt(k/m) sin((2j-1) pi / (2(2n+1))).
 *
 * The BLAS is Debian's serial OpenBLAS: everything runs in the calling
 * thread, which is what a thread-pool server wants.
 * Wall time: best of 5 batches, each repeated for at least 20 ms (one call
 * per batch when a call takes longer).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_matrix.h>

#include "mm_linalg.h"

#define PI 3.14159265358979323846

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

typedef int (*job_fn)(void *ctx);

/* Seconds per call: best of 5 batches of >= 20 ms (>= 1 call). */
static double time_job(job_fn job, void *ctx)
{
    double best = INFINITY;
    int reps = 1;
    for (int batch = 0; batch < 5; batch++) {
        double t0 = now(), t;
        int done = 0;
        do {
            for (int r = 0; r < reps; r++)
                if (job(ctx) != 0) {
                    fprintf(stderr, "bench job failed\n");
                    exit(1);
                }
            done += reps;
            t = now() - t0;
            if (t < 0.02)
                reps *= 2;
        } while (t < 0.02);
        if (t / done < best)
            best = t / done;
        if (t > 1.0 && batch >= 1)       /* slow cases: 2 batches are enough */
            break;
    }
    return best;
}

/* ---- table 1: linear systems ------------------------------------------------- */

typedef struct solve_ctx {
    int n;
    double *A, *b, *x;
    gsl_matrix *LU;
    gsl_vector *gb, *gx;
    gsl_permutation *perm;
} solve_ctx;

static int job_mm_solve(void *p)
{
    solve_ctx *c = p;
    mm_linalg_solve_info info;
    return mm_linalg_solve(c->n, 1, c->A, c->b, c->x, &info, NULL);
}

static int job_gsl_lu(void *p)
{
    solve_ctx *c = p;
    int sign;
    memcpy(c->LU->data, c->A, (size_t)c->n * (size_t)c->n * sizeof(double));
    if (gsl_linalg_LU_decomp(c->LU, c->perm, &sign))
        return 1;
    return gsl_linalg_LU_solve(c->LU, c->perm, c->gb, c->gx);
}

static int job_cond2(void *p)
{
    solve_ctx *c = p;
    double k;
    return mm_linalg_cond2(c->n, c->n, c->A, &k, NULL);
}

static double urand(uint64_t *s)          /* xorshift64, in [-1, 1) */
{
    *s ^= *s << 13; *s ^= *s >> 7; *s ^= *s << 17;
    return (double)(*s >> 11) / 4503599627370496.0 - 1.0;
}

static void table_solve(void)
{
    const int sizes[] = {3, 10, 100, 300};
    printf("Table 1. A x = b, one right-hand side (random A, cond ~ 10..1e3)\n");
    printf("%5s %14s %14s %8s %14s %11s %11s %9s\n", "n", "mm_solve [us]",
           "GSL LU [us]", "ratio", "cond2 [us]", "err mm", "err GSL", "rcond");
    for (unsigned s = 0; s < sizeof sizes / sizeof *sizes; s++) {
        int n = sizes[s];
        uint64_t seed = 88172645463325252ull;
        solve_ctx c = {.n = n};
        c.A = malloc((size_t)n * n * sizeof *c.A);
        c.b = malloc((size_t)n * sizeof *c.b);
        c.x = malloc((size_t)n * sizeof *c.x);
        double *xt = malloc((size_t)n * sizeof *xt);
        for (int i = 0; i < n * n; i++)
            c.A[i] = urand(&seed);
        for (int i = 0; i < n; i++) {
            c.A[i * n + i] += 0.5 * sqrt((double)n);  /* keep it well-conditioned */
            xt[i] = urand(&seed);
        }
        for (int i = 0; i < n; i++) {
            double sum = 0;
            for (int j = 0; j < n; j++)
                sum += c.A[i * n + j] * xt[j];
            c.b[i] = sum;
        }
        c.LU = gsl_matrix_alloc((size_t)n, (size_t)n);
        c.perm = gsl_permutation_alloc((size_t)n);
        gsl_vector_view bv = gsl_vector_view_array(c.b, (size_t)n);
        c.gb = &bv.vector;
        c.gx = gsl_vector_alloc((size_t)n);

        double t_mm = time_job(job_mm_solve, &c);
        double t_gsl = time_job(job_gsl_lu, &c);
        double t_c2 = time_job(job_cond2, &c);
        mm_linalg_solve_info info;
        mm_linalg_solve(n, 1, c.A, c.b, c.x, &info, NULL);
        job_gsl_lu(&c);
        double e_mm = 0, e_gsl = 0;
        for (int i = 0; i < n; i++) {
            e_mm = fmax(e_mm, fabs(c.x[i] - xt[i]));
            e_gsl = fmax(e_gsl, fabs(gsl_vector_get(c.gx, (size_t)i) - xt[i]));
        }
        printf("%5d %14.2f %14.2f %8.2f %14.2f %11.2e %11.2e %9.2e\n", n, 1e6 * t_mm,
               1e6 * t_gsl, t_mm / t_gsl, 1e6 * t_c2, e_mm, e_gsl, info.rcond);
        gsl_vector_free(c.gx);
        gsl_permutation_free(c.perm);
        gsl_matrix_free(c.LU);
        free(xt); free(c.x); free(c.b); free(c.A);
    }
    printf("\n");
}

/* ---- table 2: chain eigenproblem ---------------------------------------------------- */

typedef struct eig_ctx {
    int n, nev;
    double *K, *M, *Kb, *Mb, *lam, *V;
    gsl_matrix *gK, *gM, *gV;
    gsl_vector *geval;
    gsl_eigen_gensymmv_workspace *gw;
} eig_ctx;

static int job_full(void *p)
{
    eig_ctx *c = p;
    return mm_linalg_sygv(c->n, c->K, c->M, c->lam, c->V, NULL);
}

static int job_first(void *p)
{
    eig_ctx *c = p;
    return mm_linalg_sygv_first(c->n, c->nev, c->K, c->M, c->lam, c->V, NULL);
}

static int job_band(void *p)
{
    eig_ctx *c = p;
    return mm_linalg_sbgv_first(c->n, 1, c->nev, c->Kb, c->Mb, c->lam, c->V, NULL);
}

static int job_gsl_eig(void *p)
{
    eig_ctx *c = p;
    gsl_matrix_view K = gsl_matrix_view_array(c->K, (size_t)c->n, (size_t)c->n);
    gsl_matrix_view M = gsl_matrix_view_array(c->M, (size_t)c->n, (size_t)c->n);
    gsl_matrix_memcpy(c->gK, &K.matrix);           /* GSL destroys its input */
    gsl_matrix_memcpy(c->gM, &M.matrix);
    return gsl_eigen_gensymmv(c->gK, c->gM, c->geval, c->gV, c->gw);
}

/* largest relative error of the first nev omega against the closed form */
static double omega_error(const eig_ctx *c, const double *lam)
{
    double e = 0;
    for (int j = 1; j <= c->nev; j++) {
        double w = 2 * sqrt(100.0 / 1.0) * sin((2 * j - 1) * PI / (2 * (2 * c->n + 1)));
        e = fmax(e, fabs(sqrt(lam[j - 1]) - w) / w);
    }
    return e;
}

static void table_eigen(void)
{
    const int sizes[] = {10, 30, 100, 300, 1000};
    printf("Table 2. K v = lambda M v, fixed-free chain (k = 100, m = 1), modes with vectors\n");
    printf("%5s %13s %13s %13s %13s %8s %8s %10s %10s %10s\n", "n", "all [ms]",
           "first10 [ms]", "band10 [ms]", "GSL all [ms]", "all/1st", "all/band",
           "err all", "err 1st", "err band");
    for (unsigned s = 0; s < sizeof sizes / sizeof *sizes; s++) {
        int n = sizes[s];
        eig_ctx c = {.n = n, .nev = 10};
        size_t nn = (size_t)n * (size_t)n;
        c.K = calloc(nn, sizeof *c.K);
        c.M = calloc(nn, sizeof *c.M);
        c.Kb = malloc((size_t)n * 2 * sizeof *c.Kb);
        c.Mb = malloc((size_t)n * 2 * sizeof *c.Mb);
        c.lam = malloc((size_t)n * sizeof *c.lam);
        c.V = malloc(nn * sizeof *c.V);
        for (int i = 0; i < n; i++) {
            c.K[i * n + i] = i == n - 1 ? 100 : 200;
            if (i + 1 < n)
                c.K[i * n + i + 1] = c.K[(i + 1) * n + i] = -100;
            c.M[i * n + i] = 1;
        }
        mm_linalg_band_pack(n, 1, c.K, c.Kb);
        mm_linalg_band_pack(n, 1, c.M, c.Mb);

        double t_full = time_job(job_full, &c);
        double e_full = omega_error(&c, c.lam);
        double t_first = time_job(job_first, &c);
        double e_first = omega_error(&c, c.lam);
        double t_band = time_job(job_band, &c);
        double e_band = omega_error(&c, c.lam);
        double t_gsl = NAN;
        if (n <= 300) {
            c.gK = gsl_matrix_alloc((size_t)n, (size_t)n);
            c.gM = gsl_matrix_alloc((size_t)n, (size_t)n);
            c.gV = gsl_matrix_alloc((size_t)n, (size_t)n);
            c.geval = gsl_vector_alloc((size_t)n);
            c.gw = gsl_eigen_gensymmv_alloc((size_t)n);
            t_gsl = time_job(job_gsl_eig, &c);
            gsl_eigen_gensymmv_free(c.gw);
            gsl_vector_free(c.geval);
            gsl_matrix_free(c.gV);
            gsl_matrix_free(c.gM);
            gsl_matrix_free(c.gK);
        }
        char gsl_txt[32];
        if (isnan(t_gsl))
            snprintf(gsl_txt, sizeof gsl_txt, "%13s", "-");
        else
            snprintf(gsl_txt, sizeof gsl_txt, "%13.3f", 1e3 * t_gsl);
        printf("%5d %13.3f %13.3f %13.3f %s %8.1f %8.1f %10.1e %10.1e %10.1e\n", n,
               1e3 * t_full, 1e3 * t_first, 1e3 * t_band, gsl_txt, t_full / t_first,
               t_full / t_band, e_full, e_first, e_band);
        free(c.V); free(c.lam); free(c.Mb); free(c.Kb); free(c.M); free(c.K);
    }
    printf("\n(err = largest relative error of omega_1..omega_10 against the closed "
           "form;\n the floor ~ eps ||K|| / lambda_1 grows like n^2.)\n");
}

int main(void)
{
    gsl_set_error_handler_off();
    table_solve();
    table_eigen();
    return 0;
}
