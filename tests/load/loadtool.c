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
 * The closing line of verify: "verify: N compared, M differed, E errors".
 *
 *   loadtool class BASE_URL CLIENTS SPREAD_S EXERCISE
 *                             a class start: CLIENTS browsers, their starts
 *                             spread evenly over SPREAD_S seconds, each
 *                             loading one exercise page as a browser does:
 *                             the HTML, then (in parallel, up to 6
 *                             connections) what it links (style sheets,
 *                             scripts, modules, the icon), KaTeX's module
 *                             and two of its fonts, the catalog, the
 *                             exercise's metadata and its default solve;
 *                             with Accept-Encoding: gzip, each browser its
 *                             own connections.  EXERCISE "all" gives each
 *                             browser the next exercise of the catalog.
 *                             Prints counts and latency percentiles of
 *                             requests and of whole pages; exit status 1
 *                             when a request failed or was not a 200. */
#include <arpa/inet.h>
#include <curl/curl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>
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

/* ---- a class start ------------------------------------------------------------- */

typedef struct client {
    CURLSH *share;             /* its own connections */
    double start, end;         /* of its page: first request sent, last answered */
    int pending;
    char exercise[80];
} client;

typedef struct hctx {          /* a request in flight: whose, and its body */
    int client, phase;
    body b;
} hctx;

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double pct(const double *v, int n, double p)
{
    if (n == 0)
        return 0;
    int k = (int)(p / 100.0 * (n - 1) + 0.5);
    return v[k < n ? k : n - 1];
}

/* This thread's time on a CPU and time waiting for one, in ms (Linux
 * schedstat): a client that waited long measured its own starvation. */
static void cpu_times(double *run_ms, double *wait_ms)
{
    unsigned long long run = 0, wait = 0;
    FILE *f = fopen("/proc/thread-self/schedstat", "r");
    if (f) {
        if (fscanf(f, "%llu %llu", &run, &wait) != 2)
            run = wait = 0;
        fclose(f);
    }
    *run_ms = (double)run * 1e-6;
    *wait_ms = (double)wait * 1e-6;
}

/* What a page links: href="/x.y" and src="/x.y" (files, not pages). */
static int page_links(const char *html, char links[][200], int max)
{
    int n = 0;
    for (const char *p = html; (p = strstr(p, "=\"/")) && n < max; p += 3) {
        int attr = (p >= html + 4 && strncmp(p - 4, "href", 4) == 0) || (p >= html + 3 && strncmp(p - 3, "src", 3) == 0);
        const char *e = strchr(p + 2, '"');
        size_t len = e ? (size_t)(e - (p + 2)) : 0;
        if (!attr || len <= 1 || len >= 200 || !memchr(p + 2, '.', len))
            continue;
        memcpy(links[n], p + 2, len);
        links[n][len] = '\0';
        n++;
    }
    return n;
}

/* a body counted, not kept: the client must cost less than the server */
static size_t discard(char *p, size_t size, size_t n, void *ud)
{
    (void)p;
    ((body *)ud)->n += size * n;
    return size * n;
}

static struct curl_slist *gzip_header;

static void add_get(CURLM *m, client *cl, int ci, int phase, const char *base, const char *path)
{
    CURL *c = curl_easy_init();
    char url[600];
    snprintf(url, sizeof url, "%s%s", base, path);
    hctx *h = malloc(sizeof *h);
    *h = (hctx){ci, phase, {calloc(1, 1), 0}};
    curl_easy_setopt(c, CURLOPT_URL, url);
    curl_easy_setopt(c, CURLOPT_SHARE, cl[ci].share);
    curl_easy_setopt(c, CURLOPT_HTTPHEADER, gzip_header);   /* asked for, received as is */
    curl_easy_setopt(c, CURLOPT_WRITEFUNCTION, discard);
    curl_easy_setopt(c, CURLOPT_WRITEDATA, &h->b);
    curl_easy_setopt(c, CURLOPT_PRIVATE, h);
    curl_easy_setopt(c, CURLOPT_TIMEOUT, 30L);
    curl_multi_add_handle(m, c);
    cl[ci].pending++;
}

static int class_start(const char *base, int n_clients, double spread, const char *exercise)
{
    CURL *c = curl_easy_init();                  /* the page once, for what it links */
    char url[600];
    body html = {calloc(1, 1), 0};
    snprintf(url, sizeof url, "%s/exercise.html", base);
    curl_easy_setopt(c, CURLOPT_URL, url);
    curl_easy_setopt(c, CURLOPT_WRITEFUNCTION, collect);
    curl_easy_setopt(c, CURLOPT_WRITEDATA, &html);
    if (curl_easy_perform(c) != CURLE_OK) {
        fprintf(stderr, "class: %s does not answer\n", url);
        return 1;
    }
    curl_easy_cleanup(c);
    static char links[64][200];
    int n_links = page_links(html.p, links, 56);
    free(html.p);
    const char *extra[] = {"/vendor/katex/dist/katex.mjs", "/vendor/katex/dist/fonts/KaTeX_Main-Regular.woff2",
                           "/vendor/katex/dist/fonts/KaTeX_Math-Italic.woff2", "/api/exercises"};
    for (size_t i = 0; i < sizeof extra / sizeof extra[0]; i++)
        snprintf(links[n_links++], sizeof links[0], "%s", extra[i]);

    gzip_header = curl_slist_append(NULL, "Accept-Encoding: gzip");
    client *cl = calloc((size_t)n_clients, sizeof *cl);
    for (int i = 0; i < n_clients; i++) {
        cl[i].share = curl_share_init();
        curl_share_setopt(cl[i].share, CURLSHOPT_SHARE, CURL_LOCK_DATA_CONNECT);
        cl[i].start = spread * i / n_clients;
        const mm_exercise *ex = strcmp(exercise, "all") == 0 ? mm_exercises[i % mm_exercise_count] : NULL;
        snprintf(cl[i].exercise, sizeof cl[i].exercise, "%s", ex ? ex->id : exercise);
    }
    CURLM *m = curl_multi_init();
    curl_multi_setopt(m, CURLMOPT_MAX_HOST_CONNECTIONS, 6L * n_clients);
    int per_page = n_links + 3;
    double *lat = malloc(sizeof(double) * (size_t)n_clients * (size_t)(per_page + 1));
    double *pages = malloc(sizeof(double) * (size_t)n_clients);
    int n_lat = 0, n_pages = 0, started = 0, failed = 0, running = 0, done = 0;
    double bytes = 0;
    double t0 = now_s(), slowest = 0, run0, wait0, run1, wait1;
    char slowest_url[300] = "";
    cpu_times(&run0, &wait0);
    /* until every page is complete: curl's running count misses the
     * requests a page's HTML added after curl_multi_perform (the last
     * browser's six, and with one browser, the instructor's, whose visit
     * then warmed no answer) */
    while (started < n_clients || running || done < n_clients) {
        double t = now_s() - t0;
        while (started < n_clients && cl[started].start <= t) {     /* a browser opens the page */
            char path[300];
            snprintf(path, sizeof path, "/exercise.html?id=%s", cl[started].exercise);
            cl[started].start = now_s();
            add_get(m, cl, started, 0, base, path);
            started++;
        }
        curl_multi_perform(m, &running);
        CURLMsg *msg;
        int left;
        while ((msg = curl_multi_info_read(m, &left))) {
            if (msg->msg != CURLMSG_DONE)
                continue;
            CURL *e = msg->easy_handle;
            hctx *h;
            long status = 0;
            double total = 0;
            char *eff = NULL;
            curl_easy_getinfo(e, CURLINFO_PRIVATE, (char **)&h);
            curl_easy_getinfo(e, CURLINFO_RESPONSE_CODE, &status);
            curl_easy_getinfo(e, CURLINFO_TOTAL_TIME, &total);
            curl_easy_getinfo(e, CURLINFO_EFFECTIVE_URL, &eff);
            if (msg->data.result != CURLE_OK || status != 200) {
                failed++;
                fprintf(stderr, "class: %s: %s, status %ld\n", eff ? eff : "?",
                        curl_easy_strerror(msg->data.result), status);
            }
            lat[n_lat++] = total * 1e3;
            if (total * 1e3 > slowest) {
                slowest = total * 1e3;
                snprintf(slowest_url, sizeof slowest_url, "%s", eff ? eff : "?");
            }
            client *k = &cl[h->client];
            k->pending--;
            bytes += (double)h->b.n;
            if (h->phase == 0) {                 /* the HTML came: what it needs, in parallel */
                for (int i = 0; i < n_links; i++)
                    add_get(m, cl, h->client, 1, base, links[i]);
                char path[300];
                snprintf(path, sizeof path, "/api/exercises/%s", k->exercise);
                add_get(m, cl, h->client, 1, base, path);
                snprintf(path, sizeof path, "/api/exercises/%s/solve", k->exercise);
                add_get(m, cl, h->client, 1, base, path);
            } else if (k->pending == 0) {
                done++;
                k->end = now_s();
                pages[n_pages++] = (k->end - k->start) * 1e3;
            }
            free(h->b.p);
            free(h);
            curl_multi_remove_handle(m, e);
            curl_easy_cleanup(e);
        }
        curl_multi_poll(m, NULL, 0, 1, NULL);
    }
    double wall = now_s() - t0;
    cpu_times(&run1, &wait1);
    qsort(lat, (size_t)n_lat, sizeof *lat, cmp_double);
    qsort(pages, (size_t)n_pages, sizeof *pages, cmp_double);
    printf("class: %d browsers over %.1f s (%s), %d requests each, %d requests in %.2f s: %d failed; "
           "%.0f kB a page as sent (gzip)\n", n_clients, spread, exercise, per_page, n_lat, wall, failed,
           bytes / n_clients / 1e3);
    printf("class: request latency ms: p50 %.1f  p90 %.1f  p99 %.1f  max %.1f (%s)\n", pct(lat, n_lat, 50),
           pct(lat, n_lat, 90), pct(lat, n_lat, 99), lat[n_lat - 1], slowest_url);
    printf("class: whole page ms:      p50 %.1f  p90 %.1f  p99 %.1f  max %.1f\n", pct(pages, n_pages, 50),
           pct(pages, n_pages, 90), pct(pages, n_pages, 99), n_pages ? pages[n_pages - 1] : 0);
    printf("class: the client ran %.0f ms and waited %.0f ms for a CPU\n", run1 - run0, wait1 - wait0);
    printf("class-figures: answered=%d failed=%d p99_ms=%.1f page_p99_ms=%.1f\n", n_lat - failed, failed,
           pct(lat, n_lat, 99), pct(pages, n_pages, 99));
    for (int i = 0; i < n_clients; i++)
        curl_share_cleanup(cl[i].share);
    curl_multi_cleanup(m);
    free(cl);
    free(lat);
    free(pages);
    return failed || n_pages != n_clients ? 1 : 0;
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
    if (argc == 2 && strcmp(argv[1], "freeport") == 0) {    /* a port the OS says is free */
        int fd = socket(AF_INET, SOCK_STREAM, 0);
        struct sockaddr_in a = {.sin_family = AF_INET};
        a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        socklen_t len = sizeof a;
        if (fd < 0 || bind(fd, (struct sockaddr *)&a, sizeof a) != 0 ||
            getsockname(fd, (struct sockaddr *)&a, &len) != 0)
            return 1;
        printf("%d\n", ntohs(a.sin_port));
        close(fd);
        return 0;
    }
    if (argc == 6 && strcmp(argv[1], "class") == 0) {
        curl_global_init(CURL_GLOBAL_DEFAULT);
        int rc = class_start(argv[2], atoi(argv[3]), atof(argv[4]), argv[5]);
        curl_global_cleanup();
        return rc;
    }
    fprintf(stderr, "usage: loadtool gen N FILE | loadtool verify PORT FILE SECONDS\n"
                    "       loadtool class BASE_URL CLIENTS SPREAD_S EXERCISE|all\n");
    return 2;
}
