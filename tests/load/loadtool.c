/* loadtool.c — helper of `make loadtest`.
 *
 *   loadtool gen N FILE       write N request paths: every exercise at its
 *                             defaults and at random parameters inside its
 *                             limits that its joint check accepts (seeded)
 *   loadtool verify PORT FILE SECONDS
 *                             take every 10th path of FILE, ask each alone
 *                             first, then again and again for SECONDS while
 *                             the load runs; count answers that differ
 *                             (elapsed_us aside), errors and 5xx.
 * The closing line of verify: "verify: N compared, M differed, E errors". */
#include <curl/curl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "mm_api.h"
#include "mm_dtoa.h"
#include "mm_params.h"
#include "mm_result_impl.h"

static unsigned long long rng = 0x2545F4914F6CDD1DULL;

static double urand(void)
{
    rng ^= rng >> 12, rng ^= rng << 25, rng ^= rng >> 27;
    return (double)((rng * 2685821657736338717ULL) >> 11) / 9007199254740992.0;
}

/* A random value of a real/integer/choice parameter as URL text, or NULL to
 * keep the default (arrays and expressions keep theirs). */
static const char *draw(const mm_param *p, char *buf)
{
    if (p->kind == MM_CHOICE) {
        int n = 0;
        while (p->choices[n])
            n++;
        return p->choices[(int)(urand() * n) % n];
    }
    if (p->kind != MM_REAL && p->kind != MM_INT)
        return NULL;
    double v = p->min > 0 && p->max / p->min > 100 ? p->min * pow(p->max / p->min, urand())
                                                    : p->min + (p->max - p->min) * urand();
    if (p->kind == MM_INT)
        v = floor(v + 0.5);
    mm_dtoa(fmin(fmax(v, p->min), p->max), buf);
    return buf;
}

static int gen(int n, const char *file)
{
    FILE *f = fopen(file, "w");
    if (!f)
        return 1;
    for (int i = 0; i < n; i++) {
        const mm_exercise *ex = mm_exercises[i % mm_exercise_count];
        if (i < mm_exercise_count) {                  /* each at its defaults once */
            fprintf(f, "/api/exercises/%s/solve\n", ex->id);
            continue;
        }
        for (int tries = 0; tries < 100; tries++) {
            char text[MM_MAX_PARAMS][40], path[4096];
            mm_input in[MM_MAX_PARAMS];
            int k = 0, len = snprintf(path, sizeof path, "/api/exercises/%s/solve?", ex->id);
            for (int j = 0; j < ex->n_params; j++) {
                const char *t = draw(&ex->params[j], text[k]);
                if (!t)
                    continue;
                in[k] = (mm_input){ex->params[j].name, t, strlen(ex->params[j].name), strlen(t)};
                len += snprintf(path + len, sizeof path - (size_t)len, "%s%s=%s", k ? "&" : "",
                                ex->params[j].name, t);
                k++;
            }
            mm_buf out;                               /* keep draws that solve */
            mm_buf_init(&out, MM_ANSWER_MAX);
            int status = mm_api_solve(ex, in, k, &out);
            mm_buf_free(&out);
            if (status == 200) {
                fprintf(f, "%s\n", path);
                break;
            }
        }
    }
    fclose(f);
    return 0;
}

typedef struct body { char *p; size_t n; } body;

static size_t collect(char *p, size_t size, size_t n, void *ud)
{
    body *b = ud;
    char *q = realloc(b->p, b->n + size * n + 1);
    if (!q)
        return 0;
    memcpy(q + b->n, p, size * n);
    b->p = q;
    b->n += size * n;
    b->p[b->n] = '\0';
    return size * n;
}

/* GET the path; the body without its elapsed_us, or NULL on an error. */
static char *fetch(CURL *c, int port, const char *path, long *status)
{
    char url[4200];
    snprintf(url, sizeof url, "http://127.0.0.1:%d%s", port, path);
    body b = {calloc(1, 1), 0};
    curl_easy_setopt(c, CURLOPT_URL, url);
    curl_easy_setopt(c, CURLOPT_WRITEFUNCTION, collect);
    curl_easy_setopt(c, CURLOPT_WRITEDATA, &b);
    curl_easy_setopt(c, CURLOPT_TIMEOUT, 20L);
    if (curl_easy_perform(c) != CURLE_OK) {
        free(b.p);
        return NULL;
    }
    curl_easy_getinfo(c, CURLINFO_RESPONSE_CODE, status);
    char *e = strstr(b.p, ",\"elapsed_us\"");
    if (e)
        *e = '\0';
    return b.p;
}

static int verify(int port, const char *file, double seconds)
{
    FILE *f = fopen(file, "r");
    if (!f)
        return 1;
    char line[4200];
    char *paths[4096], *want[4096];
    int n = 0, i = 0;
    CURL *c = curl_easy_init();
    while (fgets(line, sizeof line, f) && n < 4096) {
        if (i++ % 10)
            continue;
        line[strcspn(line, "\n")] = '\0';
        long status = 0;
        paths[n] = strdup(line);
        want[n] = fetch(c, port, line, &status);   /* alone, before the load */
        if (!want[n] || status != 200) {
            fprintf(stderr, "verify: %s answered %ld alone\n", line, status);
            return 1;
        }
        n++;
    }
    fclose(f);
    printf("verify: %d sampled requests answered alone; now comparing under load\n", n);
    fflush(stdout);
    long compared = 0, differed = 0, errors = 0;
    struct timespec t0, t;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    do {
        for (int k = 0; k < n; k++) {
            long status = 0;
            char *got = fetch(c, port, paths[k], &status);
            if (!got || status != 200)
                errors++;
            else if (strcmp(got, want[k]) != 0)
                differed++;
            compared++;
            free(got);
        }
        clock_gettime(CLOCK_MONOTONIC, &t);
    } while ((double)(t.tv_sec - t0.tv_sec) + 1e-9 * (double)(t.tv_nsec - t0.tv_nsec) < seconds);
    for (int k = 0; k < n; k++) {
        free(paths[k]);
        free(want[k]);
    }
    curl_easy_cleanup(c);
    printf("verify: %ld compared, %ld differed, %ld errors\n", compared, differed, errors);
    return differed || errors;
}

int main(int argc, char **argv)
{
    if (argc == 4 && strcmp(argv[1], "gen") == 0)
        return gen(atoi(argv[2]), argv[3]);
    if (argc == 5 && strcmp(argv[1], "verify") == 0) {
        curl_global_init(CURL_GLOBAL_DEFAULT);
        int rc = verify(atoi(argv[2]), argv[3], atof(argv[4]));
        curl_global_cleanup();
        return rc;
    }
    fprintf(stderr, "usage: loadtool gen N FILE | loadtool verify PORT FILE SECONDS\n");
    return 2;
}
