/* bench_api.c — the cost of one solve in-process, split into its parts:
 * parameter parsing + solve + JSON writing (the whole pipeline), and the
 * solve alone, for every exercise at its defaults.  Figures in microseconds
 * per request, medians of repeated batches. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "mm_api.h"
#include "mm_params.h"
#include "mm_result_impl.h"

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Median over 9 batches of the time per call of f, in microseconds. */
static double per_call_us(void (*f)(const mm_exercise *, size_t *), const mm_exercise *ex, size_t *bytes)
{
    double t[9];
    int reps = 1;
    for (double dt = 0; dt < 0.02; reps *= 2) {           /* batches of >= 20 ms */
        double t0 = now_s();
        for (int i = 0; i < reps; i++)
            f(ex, bytes);
        dt = now_s() - t0;
        if (dt >= 0.02)
            break;
    }
    for (int b = 0; b < 9; b++) {
        double t0 = now_s();
        for (int i = 0; i < reps; i++)
            f(ex, bytes);
        t[b] = (now_s() - t0) / reps * 1e6;
    }
    qsort(t, 9, sizeof t[0], cmp);
    return t[4];
}

static void whole(const mm_exercise *ex, size_t *bytes)
{
    mm_buf out;
    mm_buf_init(&out, MM_ANSWER_MAX);
    mm_api_solve(ex, NULL, 0, &out);
    *bytes = out.len;
    mm_buf_free(&out);
}

static void solve_only(const mm_exercise *ex, size_t *bytes)
{
    mm_result res;
    mm_value v[MM_MAX_PARAMS];
    mm_error err;
    mm_result_init(&res, MM_REQ_MEM_CAP);
    for (int k = 0; k < ex->n_params; k++)
        mm_param_default(&ex->params[k], &v[k], &res, &err);
    ex->solve(v, &res, &err);
    mm_result_release(&res);
    (void)bytes;
}

int main(void)
{
    printf("== in-process cost of one request at the defaults (median of 9 batches)\n");
    printf("%-26s %12s %12s %12s %10s\n", "exercise", "whole [us]", "solve [us]", "JSON etc [us]", "bytes");
    for (int i = 0; i < mm_exercise_count; i++) {
        const mm_exercise *ex = mm_exercises[i];
        size_t bytes = 0;
        double w = per_call_us(whole, ex, &bytes);
        double s = per_call_us(solve_only, ex, &bytes);
        printf("%-26s %12.1f %12.1f %12.1f %10zu\n", ex->id, w, s, w - s, bytes);
    }
    return 0;
}
