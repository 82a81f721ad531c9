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
#include "mm_draw.h"
#include "mm_dtoa.h"
#include "mm_params.h"
#include "mm_result_impl.h"

static mm_rng rng = {0x2545F4914F6CDD1DULL};   /* the product's generator (mm_draw.h) */

/* A random value of p as parameter text in buf, and as JSON in json, or
 * NULL to keep the default (expressions keep theirs): mm_draw_text, whose
 * texts are JSON already but for choices (quoted) and arrays ("1,2;3,4"
 * becomes [[1,2],[3,4]]). */
static const char *draw(const mm_param *p, char *buf, size_t size, char *json, size_t jsize)
{
    if (p->kind == MM_EXPR || mm_draw_text(p, &rng, buf, size) != MM_OK)
        return NULL;
    size_t j = 0;
    if (p->kind == MM_CHOICE) {
        j = (size_t)snprintf(json, jsize, "\"%s\"", buf);
    } else if (p->kind == MM_VECTOR || p->kind == MM_MATRIX) {
        j += (size_t)snprintf(json + j, jsize - j, p->kind == MM_MATRIX ? "[[" : "[");
        for (const char *c = buf; *c && j + 4 < jsize; c++)
            j += (size_t)snprintf(json + j, jsize - j, "%s", *c == ';' ? "],[" : (char[2]){*c, 0});
        j += (size_t)snprintf(json + j, jsize - j, p->kind == MM_MATRIX ? "]]" : "]");
    } else {
        j = (size_t)snprintf(json, jsize, "%s", buf);
    }
    return j < jsize - 2 ? buf : NULL;
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
