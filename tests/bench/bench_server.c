/* bench_server.c — where the server's time goes for one request, in
 * process, per exercise at its defaults: resolve (parameters parsed and
 * checked, the canonical key), the ETag, run (the exercise's solve),
 * write (the JSON), gzip (once per answer, when a client accepts it), and
 * a cache hit (lookup and reference).  Also each default answer's size,
 * plain and compressed (an exercise's default answer should be at most
 * 64 KB before compression).  Medians of 9 batches, microseconds of this
 * thread's CPU time (the machine is shared: wall time counts the others). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <libdeflate.h>

#include "mm_api.h"
#include "mm_cache.h"

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

typedef struct parts {
    double resolve, etag, run, write, gzip, hit;
    size_t bytes, gz_bytes;
} parts;

static const mm_exercise *cur;
static mm_cache *cache;

/* as the server does it: one libdeflate compressor per thread at the
 * answers' level (mm_http.c gzip_answer) */
static struct libdeflate_compressor *gz;
static size_t gz_size(const char *p, size_t n)
{
    size_t cap = libdeflate_gzip_compress_bound(gz, n);
    void *out = malloc(cap);
    size_t len = libdeflate_gzip_compress(gz, p, n, out, cap);
    free(out);
    return len;
}

/* one request's parts, timed by repetition */
static void once(parts *t, int reps)
{
    mm_solve s;
    mm_buf out;
    char etag[MM_ETAG_SIZE];
    double a = now_s();
    for (int i = 0; i < reps; i++) {
        mm_solve_init(&s, cur);
        mm_api_resolve(&s, NULL, 0);
        if (i + 1 < reps)
            mm_solve_free(&s);
    }
    double b = now_s();
    for (int i = 0; i < reps; i++)
        mm_api_answer_etag(s.key.p, s.key.len, etag);
    double c = now_s();
    mm_solve_free(&s);
    double run = 0, write = 0;
    mm_buf_init(&out, MM_ANSWER_MAX);
    for (int i = 0; i < reps; i++) {
        mm_solve_init(&s, cur);
        mm_api_resolve(&s, NULL, 0);
        double r0 = now_s();
        mm_api_run(&s);
        double r1 = now_s();
        mm_api_write(&s, &out);
        double r2 = now_s();
        run += r1 - r0, write += r2 - r1;
        mm_solve_free(&s);
    }
    double g0 = now_s();
    size_t gzb = 0;
    for (int i = 0; i < reps; i++)
        gzb = gz_size(out.p, out.len);
    double g1 = now_s();
    mm_solve_init(&s, cur);
    mm_api_resolve(&s, NULL, 0);
    mm_entry *e;
    int who;
    if (mm_cache_get(cache, s.key.p, s.key.len, &who, &e) == MM_CACHE_MISS)
        mm_cache_fill(cache, e, 200, strdup(out.p), out.len, NULL, 0, 0, 1, NULL);
    mm_cache_unref(e);
    double h0 = now_s();
    for (int i = 0; i < reps; i++)
        mm_cache_unref(mm_cache_lookup(cache, s.key.p, s.key.len));
    double h1 = now_s();
    mm_solve_free(&s);
    t->resolve = (b - a) / reps * 1e6;
    t->etag = (c - b) / reps * 1e6;
    t->run = run / reps * 1e6;
    t->write = write / reps * 1e6;
    t->gzip = (g1 - g0) / reps * 1e6;
    t->hit = (h1 - h0) / reps * 1e6;
    t->bytes = out.len;
    t->gz_bytes = gzb;
    mm_buf_free(&out);
}

int main(int argc, char **argv)
{
    cache = mm_cache_new(256u << 20);
    gz = libdeflate_alloc_compressor(1);                                /* the server's level for answers */
    printf("== one request's parts at the defaults, in process (median of 9 batches, us)\n");
    printf("%-26s %8s %6s %9s %8s %8s %6s %10s %9s\n", "exercise", "resolve", "etag", "run", "write", "gzip", "hit",
           "bytes", "gz bytes");
    int over = 0;
    for (int i = 0; i < mm_exercise_count; i++) {
        cur = mm_exercises[i];
        int want = argc < 2;                        /* bench_server [id...]: only those */
        for (int a = 1; a < argc; a++)
            want |= strcmp(argv[a], cur->id) == 0;
        if (!want)
            continue;
        parts p[9];
        int reps = 1;
        for (double dt = 0; dt < 0.01; reps *= 2) {
            double t0 = now_s();
            parts tmp;
            once(&tmp, reps);
            dt = now_s() - t0;
        }
        for (int b = 0; b < 9; b++)
            once(&p[b], reps);
        double v[6][9];
        for (int b = 0; b < 9; b++) {
            v[0][b] = p[b].resolve, v[1][b] = p[b].etag, v[2][b] = p[b].run;
            v[3][b] = p[b].write, v[4][b] = p[b].gzip, v[5][b] = p[b].hit;
        }
        for (int k = 0; k < 6; k++)
            qsort(v[k], 9, sizeof(double), cmp);
        printf("%-26s %8.1f %6.2f %9.1f %8.1f %8.1f %6.2f %10zu %9zu%s\n", cur->id, v[0][4], v[1][4], v[2][4],
               v[3][4], v[4][4], v[5][4], p[0].bytes, p[0].gz_bytes, p[0].bytes > 65536 ? "  > 64 KB" : "");
        over += p[0].bytes > 65536;
    }
    printf("default answers over 64 KB before compression: %d of %d\n", over, mm_exercise_count);
    mm_cache_free(cache);
    libdeflate_free_compressor(gz);
    return 0;
}
