/* bench_fem.c — how long a modal analysis and a Fourier synthesis take.
 *
 * 1. Cantilever beams of 10 ... 1000 elements: all modes by the dense
 *    solver (LAPACK dsygvd through mm_linalg_sygv) against the first ten by
 *    the banded selective one (dsbgvx + inverse iteration), by subspace
 *    iteration (banded Cholesky of K, a Ritz step) and by shift-invert
 *    Lanczos (the same Cholesky, a Krylov space of K^-1 M), all through
 *    mm_fem_modes_solve, so assembly and the Rayleigh-quotient refinement
 *    are included.  Also the error of mode 1 against the closed form
 *    (beta_1 L = 1.8751...), to show what each answer is worth.
 * 2. A 200-term Fourier partial sum of a square wave on 4096 points
 *    (PERFORMANCE.md: Octave 7.3 takes 14.7 ms in-process).
 * 3. vib-beam-modes against Octave's 3.7 ms for a 100-element cantilever,
 *    assemble + eig(K, M) (PERFORMANCE.md; goal: at least 10x faster): the
 *    same work through mm_fem_modes_solve (every mode, dense; the modes
 *    the exercise shows, by the driver AUTO picks), and the whole request
 *    (validation, the solve, the convergence study of 5 more meshes, the
 *    JSON answer).
 *
 * Times are the best of several runs (the machine is noisy, +-30 %); only
 * ratios measured in one run mean much.  Exits 0.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "mm_api.h"
#include "mm_fem.h"
#include "mm_fourier.h"
#include "mm_json.h"

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Best time of reps runs of one modal solve; *err1 = relative error of
 * mode 1.  Returns < 0 on failure. */
static double time_modes(size_t n_el, mm_fem_method method, size_t nmodes,
                         int reps, double *err1, mm_fem_method *used)
{
    mm_fem_problem p = {MM_FEM_BEAM, MM_FEM_FIXED_FREE, MM_FEM_CONSISTENT, n_el,
                        {1.0, 2.1e11, 1e-4, 1e-8, 7850}, NULL};
    mm_fem_options opt;
    mm_fem_options_init(&opt);
    opt.method = method;
    size_t ndof = mm_fem_ndof(&p);
    double *omega = malloc(nmodes * sizeof *omega);
    double *shape = malloc(nmodes * ndof * sizeof *shape), exact;
    double best = INFINITY;
    mm_error err;
    for (int r = 0; r < reps; r++) {
        mm_fem_modes res = {omega, shape, 0, 0, 0, MM_FEM_AUTO};
        double t0 = now_s();
        int rc = mm_fem_modes_solve(&p, nmodes, &opt, &res, &err);
        double t = now_s() - t0;
        if (rc) {
            fprintf(stderr, "n_el %zu: %s\n", n_el, err.msg);
            best = -1;
            break;
        }
        *used = res.method;
        if (t < best)
            best = t;
    }
    mm_fem_exact_omegas(&p, 1, &exact, &err);
    *err1 = omega[0] / exact - 1;
    free(shape);
    free(omega);
    return best;
}

int main(void)
{
    size_t sizes[] = {10, 30, 100, 300, 1000};
    printf("cantilever beam, modal analysis (assembly + eigen solve + refinement)\n");
    printf("%8s %6s | %12s %11s | %12s %11s | %12s %11s | %12s %11s\n", "elements", "DOFs",
           "dense all", "mode-1 err", "banded 10", "mode-1 err", "subspace 10", "mode-1 err", "Lanczos 10",
           "mode-1 err");
    for (size_t i = 0; i < sizeof sizes / sizeof *sizes; i++) {
        size_t n = sizes[i], nf = 2 * n;
        int reps = n <= 30 ? 200 : n <= 100 ? 30 : n <= 300 ? 5 : 2;
        double e_dense, e_band;
        mm_fem_method u1, u2;
        /* dense: ask for up to 100 modes; dsygvd computes all of them */
        size_t all = nf < MM_FEM_MAX_MODES ? nf : MM_FEM_MAX_MODES;
        double td = time_modes(n, MM_FEM_DENSE, all, reps, &e_dense, &u1);
        double tb = time_modes(n, MM_FEM_BANDED, 10, reps * 4, &e_band, &u2);
        double e_sub, ts = time_modes(n, MM_FEM_SUBSPACE, 10, reps * 4, &e_sub, &u2);
        double e_lz, tl = time_modes(n, MM_FEM_LANCZOS, 10, reps * 4, &e_lz, &u2);
        if (td < 0 || tb < 0 || ts < 0 || tl < 0)
            return 0;
        printf("%8zu %6zu | %9.3f ms %+11.2e | %9.3f ms %+11.2e | %9.3f ms %+11.2e | %9.3f ms %+11.2e\n", n, nf,
               1e3 * td, e_dense, 1e3 * tb, e_band, 1e3 * ts, e_sub, 1e3 * tl, e_lz);
    }
    printf("(Octave 7.3: 100-element cantilever, assemble + eig(K,M): 3.7 ms)\n\n");

    /* vib-beam-modes, 100 elements, against Octave's 3.7 ms */
    {
        const double octave_ms = 3.7;
        double e1;
        mm_fem_method used;
        double td = time_modes(100, MM_FEM_DENSE, 100, 30, &e1, &used);
        double tb = time_modes(100, MM_FEM_AUTO, 5, 100, &e1, &used);
        const mm_exercise *ex = mm_exercise_find("vib-beam-modes");
        mm_input in[1] = {{"elements", "100", 8, 3}};
        double best = INFINITY;
        for (int r = 0; r < 30 && ex; r++) {
            mm_buf out;
            mm_buf_init(&out, MM_ANSWER_MAX);
            double t0 = now_s();
            int st = mm_api_solve(ex, in, 1, &out);
            double dt = now_s() - t0;
            mm_buf_free(&out);
            if (st != 200)
                break;
            if (dt < best)
                best = dt;
        }
        printf("vib-beam-modes, 100-element cantilever, against Octave's %.1f ms (assemble + eig(K,M)):\n",
               octave_ms);
        printf("  assemble + every mode (dense, refined):   %7.3f ms  %6.1fx faster\n", 1e3 * td,
               octave_ms / (1e3 * td));
        printf("  assemble + the 5 modes shown (%s): %7.3f ms  %6.1fx faster\n",
               used == MM_FEM_LANCZOS    ? "Lanczos "
               : used == MM_FEM_SUBSPACE ? "subspace"
               : used == MM_FEM_BANDED   ? "banded  "
                                         : "dense   ",
               1e3 * tb,
               octave_ms / (1e3 * tb));
        printf("  the whole request (+ convergence, JSON):  %7.3f ms  %6.1fx faster\n\n", 1e3 * best,
               octave_ms / (1e3 * best));
    }

    /* Fourier synthesis: S_200(t) of a square wave, 4096 points */
    enum { K = 200, NT = 4096 };
    static double a[K + 1], b[K + 1], t[NT], s[NT];
    for (size_t k = 1; k <= K; k += 2)
        b[k] = 4 / (3.14159265358979323846 * (double)k);
    for (size_t i = 0; i < NT; i++)
        t[i] = (double)i / NT;
    double best = INFINITY;
    mm_error err;
    for (int r = 0; r < 50; r++) {
        double t0 = now_s();
        if (mm_fourier_series_eval(a, b, K, 1.0, t, NT, s, &err)) {
            fprintf(stderr, "%s\n", err.msg);
            return 0;
        }
        double dt = now_s() - t0;
        if (dt < best)
            best = dt;
    }
    /* the same from samples: FFT of one period, then the synthesis */
    static double x[NT];
    for (size_t i = 0; i < NT; i++)
        x[i] = (i == 0 || 2 * i == NT) ? 0.0 : (2 * i < NT ? 1.0 : -1.0);
    double best2 = INFINITY;
    for (int r = 0; r < 50; r++) {
        double t0 = now_s();
        if (mm_fourier_series_coeffs(x, NT, K, a, b, &err) ||
            mm_fourier_series_eval(a, b, K, 1.0, t, NT, s, &err)) {
            fprintf(stderr, "%s\n", err.msg);
            return 0;
        }
        double dt = now_s() - t0;
        if (dt < best2)
            best2 = dt;
    }
    printf("Fourier series of a square wave, K = %d terms on %d points\n", K, NT);
    printf("  synthesis from closed-form coefficients: %7.3f ms\n", 1e3 * best);
    printf("  FFT of one sampled period + synthesis:   %7.3f ms\n", 1e3 * best2);
    printf("  (Octave 7.3 in-process: 14.7 ms)\n");
    mm_fourier_cleanup();
    return 0;
}
