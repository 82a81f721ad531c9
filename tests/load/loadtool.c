/* loadtool.c — helper of `make loadtest`.
 *
 *   loadtool gen N FILE       write N requests: every exercise at its
 *                             defaults and at random parameters inside its
 *                             limits that its joint check accepts (seeded);
 *                             a line is a path to GET, or, one round of the
 *                             exercises in four, "POST path {json body}"
 *   loadtool verify PORT FILE SECONDS
 *                             take every 10th round of FILE's paths (one
 *                             path per exercise a round), ask each alone
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

/* A random value of p as parameter text in buf, and as JSON in json, or
 * NULL to keep the default (expressions keep theirs).  Numbers as in
 * test_exercises.c (log-uniform over wide positive ranges); arrays keep the
 * default's shape, each element scaled by a factor in [0.5, 1.5] (a
 * symmetric matrix stays symmetric), clamped to the limits. */
static const char *draw(const mm_param *p, char *buf, size_t size, char *json, size_t jsize)
{
    if (p->kind == MM_CHOICE) {
        int n = 0;
        while (p->choices[n])
            n++;
        snprintf(buf, size, "%s", p->choices[(int)(urand() * n) % n]);
        snprintf(json, jsize, "\"%s\"", buf);
        return buf;
    }
    if (p->kind == MM_REAL || p->kind == MM_INT) {
        double v = p->min > 0 && p->max / p->min > 100 ? p->min * pow(p->max / p->min, urand())
                                                        : p->min + (p->max - p->min) * urand();
        if (p->kind == MM_INT)
            v = floor(v + 0.5);
        mm_dtoa(fmin(fmax(v, p->min), p->max), buf);
        snprintf(json, jsize, "%s", buf);
        return buf;
    }
    if (p->kind != MM_VECTOR && p->kind != MM_MATRIX)
        return NULL;
    mm_result arena;
    mm_value v;
    mm_error err;
    mm_result_init(&arena, 1 << 22);
    if (mm_param_default(p, &v, &arena, &err) != MM_OK || v.rows * v.cols > 1024) {
        mm_result_release(&arena);
        return NULL;
    }
    int sym = p->kind == MM_MATRIX && v.rows == v.cols;
    for (int i = 0; sym && i < v.rows; i++)
        for (int j = 0; j < i; j++)
            sym &= v.data[i * v.cols + j] == v.data[j * v.cols + i];
    double f[1024];
    for (int k = 0; k < v.rows * v.cols; k++)
        f[k] = 0.5 + urand();
    size_t len = 0, jlen = 0;
    char num[MM_DTOA_BUFSIZE];
    if (p->kind == MM_MATRIX)
        jlen += (size_t)snprintf(json + jlen, jsize - jlen, "[");
    for (int i = 0; i < v.rows; i++) {
        jlen += (size_t)snprintf(json + jlen, jsize - jlen, "%s[", i ? "," : "");
        for (int j = 0; j < v.cols; j++) {
            int kf = sym && j < i ? j * v.cols + i : i * v.cols + j;
            mm_dtoa(fmin(fmax(v.data[i * v.cols + j] * f[kf], p->min), p->max), num);
            len += (size_t)snprintf(buf + len, size - len, "%s%s", j ? "," : i ? ";" : "", num);
            jlen += (size_t)snprintf(json + jlen, jsize - jlen, "%s%s", j ? "," : "", num);
        }
        jlen += (size_t)snprintf(json + jlen, jsize - jlen, "]");
    }
    if (p->kind == MM_MATRIX)
        snprintf(json + jlen, jsize - jlen, "]");
    mm_result_release(&arena);
    return len < size - 1 && jlen < jsize - 2 ? buf : NULL;
}

/* Append text to a query, '+' written %2B (a '+' in a query is a space). */
static int put_query(char *out, size_t size, int len, const char *text)
{
    for (const char *c = text; *c && (size_t)len + 4 < size; c++)
        len += *c == '+' ? snprintf(out + len, size - (size_t)len, "%%2B")
                         : snprintf(out + len, size - (size_t)len, "%c", *c);
    return len;
}

static int gen(int n, const char *file)
{
    FILE *f = fopen(file, "w");
    if (!f)
        return 1;
    enum { TEXT = 2048, LINE = 8192 };
    char (*text)[TEXT] = malloc(MM_MAX_PARAMS * TEXT), *path = malloc(LINE), *json = malloc(LINE);
    char jv[TEXT];
    for (int i = 0; i < n; i++) {
        const mm_exercise *ex = mm_exercises[i % mm_exercise_count];
        if (i < mm_exercise_count) {                  /* each at its defaults once */
            fprintf(f, "/api/exercises/%s/solve\n", ex->id);
            continue;
        }
        int by_post = (i / mm_exercise_count) % 4 == 3;   /* a round in four as JSON bodies */
        for (int tries = 0; tries < 100; tries++) {
            mm_input in[MM_MAX_PARAMS];
            int k = 0, len = snprintf(path, LINE, "/api/exercises/%s/solve?", ex->id);
            int jlen = snprintf(json, LINE, "{\"params\":{");
            for (int j = 0; j < ex->n_params; j++) {
                const char *t = draw(&ex->params[j], text[k], TEXT, jv, sizeof jv);
                if (!t)
                    continue;
                in[k] = (mm_input){ex->params[j].name, t, strlen(ex->params[j].name), strlen(t)};
                len += snprintf(path + len, LINE - (size_t)len, "%s%s=", k ? "&" : "", ex->params[j].name);
                len = put_query(path, LINE, len, t);
                jlen += snprintf(json + jlen, LINE - (size_t)jlen, "%s\"%s\":%s", k ? "," : "",
                                 ex->params[j].name, jv);
                k++;
            }
            snprintf(json + jlen, LINE - (size_t)jlen, "}}");
            mm_buf out;                               /* keep draws that solve */
            mm_buf_init(&out, MM_ANSWER_MAX);
            int status = mm_api_solve(ex, in, k, &out);
            mm_buf_free(&out);
            if (status == 200 && len < LINE - 8 && jlen < LINE - 8) {
                if (by_post)
                    fprintf(f, "POST /api/exercises/%s/solve %s\n", ex->id, json);
                else
                    fprintf(f, "%s\n", path);
                break;
            }
        }
    }
    free(text);
    free(path);
    free(json);
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

/* One line of the mix: a path to GET, or "POST path json".  The answer
 * without its elapsed_us, or NULL on an error. */
static char *fetch(CURL *c, int port, const char *line, long *status)
{
    char url[8300];
    const char *json = NULL;
    size_t plen = strlen(line);
    if (strncmp(line, "POST ", 5) == 0) {
        line += 5;
        json = strchr(line, ' ');
        plen = json ? (size_t)(json - line) : strlen(line);
        json = json ? json + 1 : "";
    }
    snprintf(url, sizeof url, "http://127.0.0.1:%d%.*s", port, (int)plen, line);
    body b = {calloc(1, 1), 0};
    static struct curl_slist *h;
    if (!h)
        h = curl_slist_append(curl_slist_append(NULL, "Content-Type: application/json"), "Expect:");
    if (json) {
        curl_easy_setopt(c, CURLOPT_POSTFIELDS, json);
        curl_easy_setopt(c, CURLOPT_HTTPHEADER, h);
    } else {
        curl_easy_setopt(c, CURLOPT_HTTPGET, 1L);
        curl_easy_setopt(c, CURLOPT_HTTPHEADER, NULL);
    }
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
    char line[8300];
    char *paths[4096], *want[4096];
    int n = 0, i = 0;
    CURL *c = curl_easy_init();
    while (fgets(line, sizeof line, f) && n < 4096) {
        if ((i++ / mm_exercise_count) % 10)       /* every 10th round of the exercises: */
            continue;                            /* each exercise as often as the others */
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
