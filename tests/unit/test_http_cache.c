/* test_http_cache.c — hosting a class, over HTTP against the real server:
 * caching by design (ETag, 304 without solving, identical requests solved
 * once, HEAD without a second solve, Server-Timing), gzip by Accept-Encoding,
 * light solves made by the event threads with the answers a worker makes,
 * versioned static files, /api/metrics in the Prometheus text format, the
 * access log that a %0a cannot forge, a 413 that a client sending 10 MB
 * reads instead of a reset, 2,000 idle keep-alive connections that do not
 * keep a new client waiting, the course file (narrowed limits, order,
 * refusal with line and reason, SIGHUP that keeps the old course when the
 * new file is bad) and the OpenAPI document, checked by an established
 * validator (@seriousme/openapi-schema-validator) and against the route
 * table.
 *
 * Whether a request was solved is read from the server's own counter
 * (mechmat_solve_seconds_count of /api/metrics), never from a time. */
#include "mm_test.h"

#include <arpa/inet.h>
#include <cJSON.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <pthread.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <zlib.h>

#include "mm_http.h"
#include "mm_server_fixture.h"

static mm_fixture server;
static char tmpdir[128];

static int setup(void **state)
{
    (void)state;
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mm-http-cache-XXXXXX");
    if (!mkdtemp(tmpdir))
        return -1;
    return mm_fixture_start(&server, NULL);
}

static int teardown(void **state)
{
    (void)state;
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpdir);
    int rc = system(cmd);
    return mm_fixture_stop(&server) == 0 && rc == 0 ? 0 : -1;
}

/* ---- helpers ------------------------------------------------------------------ */

/* One request with extra headers (NULL-terminated list, may be NULL); the
 * body as sent (no decoding). */
static void request(const mm_fixture *f, const char *method, const char *path, const char *const *hdrs,
                    const char *body, mm_reply *r)
{
    memset(r, 0, sizeof *r);
    r->body = calloc(1, 1);
    CURL *c = curl_easy_init();
    char url[4200];
    snprintf(url, sizeof url, "http://127.0.0.1:%d%s", f->port, path);
    curl_easy_setopt(c, CURLOPT_URL, url);
    curl_easy_setopt(c, CURLOPT_WRITEFUNCTION, mm_collect);
    curl_easy_setopt(c, CURLOPT_WRITEDATA, r);
    curl_easy_setopt(c, CURLOPT_HEADERFUNCTION, mm_collect_header);
    curl_easy_setopt(c, CURLOPT_HEADERDATA, r);
    curl_easy_setopt(c, CURLOPT_TIMEOUT, 60L);
    struct curl_slist *h = NULL;
    for (int i = 0; hdrs && hdrs[i]; i++)
        h = curl_slist_append(h, hdrs[i]);
    if (body) {
        h = curl_slist_append(h, "Content-Type: application/json");
        curl_easy_setopt(c, CURLOPT_POSTFIELDS, body);
    }
    curl_easy_setopt(c, CURLOPT_HTTPHEADER, h);
    if (method && strcmp(method, "HEAD") == 0)
        curl_easy_setopt(c, CURLOPT_NOBODY, 1L);
    else if (method)
        curl_easy_setopt(c, CURLOPT_CUSTOMREQUEST, method);
    assert_int_equal(curl_easy_perform(c), CURLE_OK);
    curl_easy_getinfo(c, CURLINFO_RESPONSE_CODE, &r->status);
    curl_slist_free_all(h);
    curl_easy_cleanup(c);
}

/* The value of header name in r (case-insensitive), copied; "" when absent. */
static const char *header_of(const mm_reply *r, const char *name, char *out, size_t size)
{
    out[0] = '\0';
    size_t n = strlen(name);
    for (const char *l = r->headers; *l;) {
        const char *e = strstr(l, "\r\n");
        size_t len = e ? (size_t)(e - l) : strlen(l);
        if (len > n + 1 && strncasecmp(l, name, n) == 0 && l[n] == ':') {
            const char *v = l + n + 1;
            while (*v == ' ')
                v++;
            size_t vl = (size_t)(l + len - v);
            snprintf(out, size, "%.*s", (int)(vl < size ? vl : size - 1), v);
            return out;
        }
        l = e ? e + 2 : l + len;
    }
    return out;
}

/* A sample of /api/metrics: the value of the first line that starts with
 * `name ` (or `name{...} ` when name holds the braces). */
static double metric(const mm_fixture *f, const char *name)
{
    mm_reply r;
    request(f, NULL, "/api/metrics", NULL, NULL, &r);
    assert_int_equal(r.status, 200);
    size_t n = strlen(name);
    double v = -1;
    for (const char *l = r.body; *l;) {
        const char *e = strchr(l, '\n');
        if (strncmp(l, name, n) == 0 && l[n] == ' ') {
            v = strtod(l + n + 1, NULL);
            break;
        }
        l = e ? e + 1 : l + strlen(l);
    }
    mm_reply_free(&r);
    return v;
}

static double solves(const mm_fixture *f) { return metric(f, "mechmat_solve_seconds_count"); }

static char *strip_elapsed(char *s)
{
    char *e = strstr(s, ",\"elapsed_us\"");
    if (e)
        *e = '\0';
    return s;
}

/* gunzip a body */
static char *gunzip(const char *in, size_t n, size_t *out_len)
{
    size_t cap = 64u << 20;
    char *out = malloc(cap);
    z_stream z;
    memset(&z, 0, sizeof z);
    assert_int_equal(inflateInit2(&z, 15 + 16), Z_OK);
    z.next_in = (Bytef *)(uintptr_t)in;
    z.avail_in = (uInt)n;
    z.next_out = (Bytef *)out;
    z.avail_out = (uInt)cap;
    assert_int_equal(inflate(&z, Z_FINISH), Z_STREAM_END);
    *out_len = cap - z.avail_out;
    inflateEnd(&z);
    out[*out_len] = '\0';
    return out;
}

/* ---- caching by design ----------------------------------------------------------- */

static void the_same_request_should_be_solved_once_and_revalidated_without_a_solve(void **state)
{
    (void)state;
    const char *path = "/api/exercises/vib-sdof-forced/solve?m=1.25&k=80";
    double s0 = solves(&server);
    mm_reply a, b, c;
    request(&server, NULL, path, NULL, NULL, &a);
    assert_int_equal(a.status, 200);
    char etag[64], timing[200], cc[100];
    header_of(&a, "ETag", etag, sizeof etag);
    assert_true(etag[0] == '"' && strlen(etag) > 10);
    assert_non_null(strstr(header_of(&a, "Server-Timing", timing, sizeof timing), "cache;desc=\"miss\""));
    assert_string_equal(header_of(&a, "Cache-Control", cc, sizeof cc), "no-cache");
    assert_true(solves(&server) == s0 + 1);

    request(&server, NULL, path, NULL, NULL, &b);               /* from the cache: same bytes */
    assert_int_equal(b.status, 200);
    assert_string_equal(a.body, b.body);
    assert_non_null(strstr(header_of(&b, "Server-Timing", timing, sizeof timing), "cache;desc=\"hit\""));
    char etag2[64];
    assert_string_equal(header_of(&b, "ETag", etag2, sizeof etag2), etag);

    char inm[100];
    snprintf(inm, sizeof inm, "If-None-Match: %s", etag);
    const char *h[] = {inm, NULL};
    request(&server, NULL, path, h, NULL, &c);                  /* 304, no body */
    assert_int_equal(c.status, 304);
    assert_int_equal(c.len, 0);
    assert_string_equal(header_of(&c, "ETag", etag2, sizeof etag2), etag);
    assert_true(solves(&server) == s0 + 1);
    mm_reply_free(&a);
    mm_reply_free(&b);
    mm_reply_free(&c);
}

static void an_etag_should_follow_the_resolved_parameters_not_their_spelling(void **state)
{
    (void)state;
    const char *same[] = {
        "/api/exercises/vib-sdof-forced/solve?m=2&k=50",
        "/api/exercises/vib-sdof-forced/solve?k=50.0&m=2e0",
        "/api/exercises/vib-sdof-forced/solve?m=4/2&k=50&c=2",      /* c=2 is the default */
    };
    char first[64] = "", e[64];
    for (unsigned i = 0; i < sizeof same / sizeof same[0]; i++) {
        mm_reply r;
        request(&server, NULL, same[i], NULL, NULL, &r);
        assert_int_equal(r.status, 200);
        header_of(&r, "ETag", e, sizeof e);
        if (i == 0)
            snprintf(first, sizeof first, "%s", e);
        else if (strcmp(e, first) != 0)
            fail_msg("%s: ETag %s, wanted %s", same[i], e, first);
        mm_reply_free(&r);
    }
    mm_reply r;                      /* a POST of the same values: the same answer, the same ETag */
    request(&server, "POST", "/api/exercises/vib-sdof-forced/solve", NULL, "{\"params\":{\"m\":2,\"k\":\"50\"}}", &r);
    assert_int_equal(r.status, 200);
    assert_string_equal(header_of(&r, "ETag", e, sizeof e), first);
    mm_reply_free(&r);
    request(&server, NULL, "/api/exercises/vib-sdof-forced/solve?m=2&k=51", NULL, NULL, &r);
    assert_string_not_equal(header_of(&r, "ETag", e, sizeof e), first);
    mm_reply_free(&r);
    /* a refusal is not cached: no ETag, no-store */
    request(&server, NULL, "/api/exercises/vib-sdof-forced/solve?m=-1", NULL, NULL, &r);
    assert_int_equal(r.status, 400);
    assert_string_equal(header_of(&r, "ETag", e, sizeof e), "");
    assert_string_equal(header_of(&r, "Cache-Control", e, sizeof e), "no-store");
    mm_reply_free(&r);
}

static void head_should_never_solve_twice(void **state)
{
    (void)state;
    const char *path = "/api/exercises/vib-sdof-forced/solve?m=3.5";
    double s0 = solves(&server);
    mm_reply h, g, h2;
    request(&server, "HEAD", path, NULL, NULL, &h);              /* solves, keeps the answer */
    assert_int_equal(h.status, 200);
    assert_int_equal(h.len, 0);
    request(&server, NULL, path, NULL, NULL, &g);                /* from the cache */
    request(&server, "HEAD", path, NULL, NULL, &h2);
    assert_int_equal(g.status, 200);
    char e1[64], e2[64], l1[32], l2[32];
    assert_string_equal(header_of(&h, "ETag", e1, sizeof e1), header_of(&g, "ETag", e2, sizeof e2));
    assert_string_equal(header_of(&h2, "Content-Length", l1, sizeof l1), header_of(&g, "Content-Length", l2, sizeof l2));
    assert_true(solves(&server) == s0 + 1);
    mm_reply_free(&h);
    mm_reply_free(&g);
    mm_reply_free(&h2);
}

typedef struct racer {
    const char *path;
    char *body;
    long status;
} racer;

static void *race(void *arg)
{
    racer *x = arg;
    mm_reply r;
    request(&server, NULL, x->path, NULL, NULL, &r);
    x->status = r.status;
    x->body = strip_elapsed(r.body);
    return NULL;
}

static void identical_requests_in_flight_should_be_solved_once(void **state)
{
    (void)state;
    /* a solve of several milliseconds, asked by 16 clients at once: the
     * first solves it, the others wait for its answer or find it cached */
    const char *path = "/api/exercises/vib-integrators/solve";
    double s0 = solves(&server);
    enum { N = 16 };
    pthread_t th[N];
    racer x[N];
    for (int i = 0; i < N; i++) {
        x[i] = (racer){path, NULL, 0};
        pthread_create(&th[i], NULL, race, &x[i]);
    }
    for (int i = 0; i < N; i++)
        pthread_join(th[i], NULL);
    for (int i = 0; i < N; i++) {
        assert_int_equal(x[i].status, 200);
        assert_string_equal(x[i].body, x[0].body);
    }
    for (int i = 0; i < N; i++)
        free(x[i].body);
    assert_true(solves(&server) == s0 + 1);
}

static void answers_should_be_compressed_for_clients_that_accept_gzip(void **state)
{
    (void)state;
    const char *path = "/api/exercises/vib-sdof-forced/solve?m=1.5";
    const char *gz[] = {"Accept-Encoding: gzip, deflate", NULL};
    const char *no[] = {"Accept-Encoding: gzip;q=0, identity", NULL};
    mm_reply z, p, q;
    request(&server, NULL, path, gz, NULL, &z);
    request(&server, NULL, path, no, NULL, &p);
    request(&server, NULL, "/api/exercises", gz, NULL, &q);
    assert_int_equal(z.status, 200);
    char v[100], e1[64], e2[64];
    assert_string_equal(header_of(&z, "Content-Encoding", v, sizeof v), "gzip");
    assert_string_equal(header_of(&z, "Vary", v, sizeof v), "Accept-Encoding");
    assert_string_equal(header_of(&p, "Content-Encoding", v, sizeof v), "");
    /* the compressed form has its own ETag: the plain one with -gz */
    header_of(&z, "ETag", e1, sizeof e1);
    header_of(&p, "ETag", e2, sizeof e2);
    assert_int_equal(strlen(e1), strlen(e2) + 3);
    assert_memory_equal(e1, e2, strlen(e2) - 1);
    size_t n;
    char *plain = gunzip(z.body, z.len, &n);
    assert_int_equal(n, p.len);
    assert_memory_equal(plain, p.body, n);
    assert_true(z.len * 2 < p.len);                /* JSON of numbers: at least half off */
    free(plain);
    assert_string_equal(header_of(&q, "Content-Encoding", v, sizeof v), "gzip");
    /* If-None-Match with the gzip ETag matches the plain answer too */
    char inm[100];
    snprintf(inm, sizeof inm, "If-None-Match: %s", e1);
    const char *h[] = {inm, NULL};
    mm_reply r;
    request(&server, NULL, path, h, NULL, &r);
    assert_int_equal(r.status, 304);
    mm_reply_free(&r);
    mm_reply_free(&z);
    mm_reply_free(&p);
    mm_reply_free(&q);
}

static void documents_and_static_files_should_have_etags_and_304s(void **state)
{
    (void)state;
    const char *paths[] = {"/api/health", "/api/exercises", "/api/exercises/vib-sdof-free", "/api/openapi.json",
                           "/api/course", "/index.html", "/js/exercise.js", "/css/style.css"};
    for (unsigned i = 0; i < sizeof paths / sizeof paths[0]; i++) {
        mm_reply r, m;
        request(&server, NULL, paths[i], NULL, NULL, &r);
        assert_int_equal(r.status, 200);
        char etag[64], inm[100], cc[100];
        header_of(&r, "ETag", etag, sizeof etag);
        if (!etag[0])
            fail_msg("%s: no ETag", paths[i]);
        assert_string_equal(header_of(&r, "Cache-Control", cc, sizeof cc), "no-cache");
        snprintf(inm, sizeof inm, "If-None-Match: %s", etag);
        const char *h[] = {inm, NULL};
        request(&server, NULL, paths[i], h, NULL, &m);
        if (m.status != 304)
            fail_msg("%s with If-None-Match %s: %ld", paths[i], etag, m.status);
        mm_reply_free(&r);
        mm_reply_free(&m);
    }
}

static void versioned_static_files_should_be_cached_for_a_year(void **state)
{
    (void)state;
    /* the version: what the server substitutes for __MM_ASSET_VERSION__ */
    char v[32], path[128], cc[100];
    mm_asset_version("web", "node_modules", v);
    assert_int_equal(strlen(v), 22);
    mm_reply r;
    snprintf(path, sizeof path, "/js/exercise.js?v=%s", v);
    request(&server, NULL, path, NULL, NULL, &r);
    assert_int_equal(r.status, 200);
    assert_string_equal(header_of(&r, "Cache-Control", cc, sizeof cc), "public, max-age=31536000, immutable");
    mm_reply_free(&r);
    request(&server, NULL, "/js/exercise.js?v=stale", NULL, NULL, &r);
    assert_string_equal(header_of(&r, "Cache-Control", cc, sizeof cc), "no-cache");
    mm_reply_free(&r);
    snprintf(path, sizeof path, "/vendor/katex/dist/katex.min.css?v=%s", v);
    request(&server, NULL, path, NULL, NULL, &r);
    assert_int_equal(r.status, 200);
    assert_string_equal(header_of(&r, "Cache-Control", cc, sizeof cc), "public, max-age=31536000, immutable");
    mm_reply_free(&r);
    /* only the browser packages are served from node_modules */
    request(&server, NULL, "/vendor/playwright-core/package.json", NULL, NULL, &r);
    assert_int_equal(r.status, 404);
    mm_reply_free(&r);
}

static void metrics_should_be_prometheus_text(void **state)
{
    (void)state;
    mm_reply r;
    request(&server, NULL, "/api/metrics", NULL, NULL, &r);
    assert_int_equal(r.status, 200);
    char t[100];
    assert_non_null(strstr(header_of(&r, "Content-Type", t, sizeof t), "text/plain; version=0.0.4"));
    /* every line a comment (# HELP / # TYPE) or `name{labels} value` */
    int samples = 0;
    for (char *l = r.body; *l;) {
        char *e = strchr(l, '\n');
        assert_non_null(e);                        /* the text ends with a new line */
        *e = '\0';
        if (l[0] == '#') {
            assert_true(strncmp(l, "# HELP mechmat_", 15) == 0 || strncmp(l, "# TYPE mechmat_", 15) == 0);
        } else {
            char name[128];
            double v;
            assert_true(sscanf(l, "%127[a-z_]", name) == 1);
            assert_true(strncmp(name, "mechmat_", 8) == 0);
            const char *sp = strrchr(l, ' ');
            assert_non_null(sp);
            v = strtod(sp + 1, NULL);
            assert_true(v >= 0);
            samples++;
        }
        l = e + 1;
    }
    assert_true(samples > 20);
    mm_reply_free(&r);
    assert_int_equal(mm_http(&server, NULL, "/api/health", NULL, 0, &r), 0);
    mm_reply_free(&r);
    assert_true(metric(&server, "mechmat_requests_total{route=\"health\",status=\"200\"}") >= 1);
    assert_true(metric(&server, "mechmat_cache_hits_total") >= 1);
    assert_true(metric(&server, "mechmat_connections") >= 1);
    assert_true(metric(&server, "mechmat_solve_seconds_bucket{le=\"+Inf\"}") == solves(&server));
}

/* ---- light solves, made by the event thread at once (mm_light.h) ------------------ */

/* num-complex at a = a_re + i as the server would answer it, solved here */
static char *complex_here(const char *a_re)
{
    mm_input in[1] = {{"a_re", a_re, 4, strlen(a_re)}};
    mm_buf out;
    mm_buf_init(&out, MM_ANSWER_MAX);
    assert_int_equal(mm_api_solve(mm_exercise_find("num-complex"), in, 1, &out), 200);
    char *t = strip_elapsed(mm_buf_take(&out, NULL));
    mm_buf_free(&out);
    return t;
}

/* distinct num-complex requests (a_re = base + k/1000) until one is a light
 * solve; returns how many it took, at most limit */
static int until_light(const mm_fixture *f, int base, int *k, int limit)
{
    double l0 = metric(f, "mechmat_light_solves_total");
    int n = 0;
    while (n < limit && metric(f, "mechmat_light_solves_total") == l0) {
        char path[128];
        snprintf(path, sizeof path, "/api/exercises/num-complex/solve?a_re=%d.%03d", base, (*k)++);
        mm_reply r;
        request(f, NULL, path, NULL, NULL, &r);
        assert_int_equal(r.status, 200);
        mm_reply_free(&r);
        n++;
    }
    return n;
}

static void a_light_exercise_should_be_solved_at_once_with_the_same_answer(void **state)
{
    (void)state;
    /* light under 100 ms: num-complex (7 us, under ThreadSanitizer some
     * hundreds) is light here in every build, once the workers have
     * weighed its first ~45 solves */
    mm_fixture f;
    const char *extra[] = {"--light-us", "100000", NULL};
    assert_int_equal(mm_fixture_start(&f, extra), 0);
    int k = 0;
    int n = until_light(&f, 3, &k, 200);
    assert_true(n >= 40 && n < 60);
    /* now each distinct request is one light solve, with the answer a
     * worker gives, plain and compressed */
    for (int gz = 0; gz < 2; gz++) {
        double l0 = metric(&f, "mechmat_light_solves_total"), s0 = solves(&f);
        char a_re[16], path[128];
        snprintf(a_re, sizeof a_re, "4.%03d", gz);
        snprintf(path, sizeof path, "/api/exercises/num-complex/solve?a_re=%s", a_re);
        const char *hdrs[] = {"Accept-Encoding: gzip", NULL};
        mm_reply r;
        request(&f, NULL, path, gz ? hdrs : NULL, NULL, &r);
        assert_int_equal(r.status, 200);
        char t[100];
        assert_non_null(strstr(header_of(&r, "Server-Timing", t, sizeof t), "cache;desc=\"miss\""));
        char *body = r.body;
        if (gz) {
            assert_string_equal(header_of(&r, "Content-Encoding", t, sizeof t), "gzip");
            size_t n_out;
            body = gunzip(r.body, r.len, &n_out);
        }
        char *here = complex_here(a_re);
        assert_string_equal(strip_elapsed(body), here);
        free(here);
        if (gz)
            free(body);
        mm_reply_free(&r);
        assert_true(metric(&f, "mechmat_light_solves_total") == l0 + 1);
        assert_true(solves(&f) == s0 + 1);
    }
    assert_int_equal(mm_fixture_stop(&f), 0);
}

static void light_us_0_should_send_every_solve_to_the_workers(void **state)
{
    (void)state;
    mm_fixture f;
    const char *extra[] = {"--light-us", "0", NULL};
    assert_int_equal(mm_fixture_start(&f, extra), 0);
    int k = 0;
    assert_int_equal(until_light(&f, 5, &k, 100), 100);
    assert_true(metric(&f, "mechmat_light_solves_total") == 0);
    assert_true(solves(&f) == 100);
    assert_int_equal(mm_fixture_stop(&f), 0);
}

/* ---- bodies over the limit ---------------------------------------------------------- */

static int connect_to(int port)
{
    int fd = socket(AF_INET, SOCK_STREAM, 0);
    struct sockaddr_in a = {.sin_family = AF_INET, .sin_port = htons((uint16_t)port)};
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (fd < 0 || connect(fd, (struct sockaddr *)&a, sizeof a) != 0)
        return -1;
    return fd;
}

/* Read one HTTP response (headers and a Content-Length body) from fd. */
static int read_response(int fd, char *buf, size_t size)
{
    size_t got = 0;
    long want = -1;
    while (got + 1 < size) {
        ssize_t n = recv(fd, buf + got, size - 1 - got, 0);
        if (n <= 0)
            return -1;
        got += (size_t)n;
        buf[got] = '\0';
        char *end = strstr(buf, "\r\n\r\n");
        if (end && want < 0) {
            char *cl = NULL;
            for (char *q = buf; q < end && !cl; q++)
                if (strncasecmp(q, "Content-Length:", 15) == 0)
                    cl = q;
            want = (long)(end + 4 - buf) + (cl ? atol(cl + 15) : 0);
        }
        if (want >= 0 && (long)got >= want)
            return (int)got;
    }
    return -1;
}

static void a_body_over_the_limit_should_get_a_readable_413_not_a_reset(void **state)
{
    (void)state;
    int fd = connect_to(server.port);
    assert_true(fd >= 0);
    size_t big = 10u << 20;
    char head[256];
    int hl = snprintf(head, sizeof head,
                      "POST /api/exercises/vib-sdof-forced/solve HTTP/1.1\r\nHost: x\r\n"
                      "Content-Type: application/json\r\nContent-Length: %zu\r\n\r\n", big);
    assert_int_equal(send(fd, head, (size_t)hl, MSG_NOSIGNAL), hl);
    char *body = malloc(1 << 16);
    memset(body, ' ', 1 << 16);
    for (size_t sent = 0; sent < big;) {          /* every byte goes in: no broken pipe */
        size_t n = big - sent < (1u << 16) ? big - sent : 1u << 16;
        ssize_t k = send(fd, body, n, MSG_NOSIGNAL);
        if (k <= 0)
            fail_msg("send failed after %zu bytes: %s", sent, strerror(errno));
        sent += (size_t)k;
    }
    free(body);
    char resp[8192];
    assert_true(read_response(fd, resp, sizeof resp) > 0);
    assert_true(strncmp(resp, "HTTP/1.1 413", 12) == 0);
    assert_non_null(strstr(resp, "\"too_large\""));
    /* and the connection goes on */
    const char *again = "GET /api/health HTTP/1.1\r\nHost: x\r\n\r\n";
    assert_int_equal(send(fd, again, strlen(again), MSG_NOSIGNAL), (ssize_t)strlen(again));
    assert_true(read_response(fd, resp, sizeof resp) > 0);
    assert_true(strncmp(resp, "HTTP/1.1 200", 12) == 0);
    close(fd);

    /* a client that asks first is told before it sends */
    fd = connect_to(server.port);
    hl = snprintf(head, sizeof head,
                  "POST /api/exercises/vib-sdof-forced/solve HTTP/1.1\r\nHost: x\r\nExpect: 100-continue\r\n"
                  "Content-Type: application/json\r\nContent-Length: %zu\r\n\r\n", big);
    assert_int_equal(send(fd, head, (size_t)hl, MSG_NOSIGNAL), hl);
    assert_true(read_response(fd, resp, sizeof resp) > 0);
    assert_true(strncmp(resp, "HTTP/1.1 413", 12) == 0);
    close(fd);
}

/* ---- many idle connections -------------------------------------------------------------- */

static void two_thousand_idle_connections_should_not_keep_a_new_client_waiting(void **state)
{
    (void)state;
    enum { IDLE = 2000 };
    struct rlimit rl;
    getrlimit(RLIMIT_NOFILE, &rl);
    if (rl.rlim_cur < IDLE + 200) {
        rl.rlim_cur = rl.rlim_max < IDLE + 200 ? rl.rlim_max : IDLE + 200;
        setrlimit(RLIMIT_NOFILE, &rl);
    }
    getrlimit(RLIMIT_NOFILE, &rl);
    if (rl.rlim_cur < IDLE + 100) {       /* a machine that allows no 2,000 open files */
        print_message("   skipped: the open-file limit is %lu\n", (unsigned long)rl.rlim_cur);
        skip();
    }
    int *fds = malloc(IDLE * sizeof *fds);
    const char *get = "GET /api/health HTTP/1.1\r\nHost: x\r\n\r\n";
    char resp[4096];
    for (int i = 0; i < IDLE; i++) {
        fds[i] = connect_to(server.port);
        assert_true(fds[i] >= 0);
        /* one request answered on each: a keep-alive connection, now idle */
        assert_int_equal(send(fds[i], get, strlen(get), MSG_NOSIGNAL), (ssize_t)strlen(get));
        if (read_response(fds[i], resp, sizeof resp) <= 0 || strncmp(resp, "HTTP/1.1 200", 12) != 0)
            fail_msg("connection %d was not answered: %.40s", i, resp);
    }
    assert_true(metric(&server, "mechmat_connections") >= IDLE);
    /* a new client, and a solve, while all of them stay open */
    mm_reply r;
    request(&server, NULL, "/api/exercises/vib-sdof-free/solve?m=2", NULL, NULL, &r);
    assert_int_equal(r.status, 200);
    mm_reply_free(&r);
    /* the idle ones still work */
    for (int i = 0; i < IDLE; i += 250) {
        assert_int_equal(send(fds[i], get, strlen(get), MSG_NOSIGNAL), (ssize_t)strlen(get));
        assert_true(read_response(fds[i], resp, sizeof resp) > 0);
    }
    for (int i = 0; i < IDLE; i++)
        close(fds[i]);
    free(fds);
}

/* ---- the access log --------------------------------------------------------------------- */

/* Start the server with its log (stderr) in log_path and more arguments. */
static int start_logged(mm_fixture *f, const char *log_path, const char *const *extra)
{
    const char *bin = getenv("MM_SERVER") ? getenv("MM_SERVER") : "build/mechmat-server";
    int fds[2];
    if (pipe(fds) != 0)
        return -1;
    const char *argv[32] = {bin, "--port", "0", "--threads", "2"};
    int n = 5;
    for (int i = 0; extra && extra[i] && n < 30; i++)
        argv[n++] = extra[i];
    argv[n] = NULL;
    f->pid = fork();
    if (f->pid == 0) {
        int log = open(log_path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        dup2(fds[1], 1);
        dup2(log, 2);
        close(fds[0]);
        close(fds[1]);
        execv(bin, (char *const *)argv);
        _exit(127);
    }
    close(fds[1]);
    f->out = fdopen(fds[0], "r");
    char line[512];
    if (!fgets(line, sizeof line, f->out))
        return -1;
    const char *p = strstr(line, "127.0.0.1:");
    f->port = p ? atoi(p + 10) : 0;
    return f->port > 0 ? 0 : -1;
}

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    char *b = calloc(1, 1 << 20);
    size_t n = fread(b, 1, (1 << 20) - 1, f);
    b[n] = '\0';
    fclose(f);
    return b;
}

static void a_newline_in_a_url_should_not_forge_a_log_line(void **state)
{
    (void)state;
    char log[256];
    snprintf(log, sizeof log, "%s/access.log", tmpdir);
    mm_fixture f;
    assert_int_equal(start_logged(&f, log, NULL), 0);
    mm_reply r;
    request(&f, NULL, "/x%0aGET%20/forged%20200%200%201us%20hit%0d%0a%22%5c", NULL, NULL, &r);
    assert_int_equal(r.status, 404);
    mm_reply_free(&r);
    request(&f, NULL, "/api/health", NULL, NULL, &r);    /* a line after it */
    mm_reply_free(&r);
    assert_int_equal(mm_fixture_stop(&f), 0);            /* the log is complete */
    char *text = slurp(log);
    assert_non_null(text);
    int lines = 0;
    for (char *l = text; *l;) {
        char *e = strchr(l, '\n');
        if (!e)
            break;
        *e = '\0';
        if (strncmp(l, "GET /forged", 11) == 0)
            fail_msg("a forged log line: %s", l);
        if (strncmp(l, "GET /x", 6) == 0) {
            assert_non_null(strstr(l, "/x\\x0aGET /forged"));
            assert_non_null(strstr(l, "\\x0d\\x0a\\x22\\x5c 404"));
        }
        if (strncmp(l, "GET ", 4) == 0)
            lines++;
        l = e + 1;
    }
    assert_int_equal(lines, 2);
    free(text);
}

/* ---- the course file --------------------------------------------------------------------- */

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static const char GOOD_COURSE[] =
    "{\n"
    "  \"title\": \"Vibrations, autumn term\",\n"
    "  \"language\": \"en\",\n"
    "  \"exercises\": [\n"
    "    {\"id\": \"vib-sdof-forced\",\n"
    "     \"params\": {\"m\": {\"default\": 2, \"min\": 0.5, \"max\": 10}}},\n"
    "    \"vib-sdof-free\"\n"
    "  ],\n"
    "  \"assignments\": [{\"name\": \"hw1\", \"title\": \"Forced vibration\", \"exercise\": \"vib-sdof-forced\",\n"
    "                   \"params\": {\"k\": {\"min\": 100, \"max\": 500, \"step\": 100}},\n"
    "                   \"ask\": [{\"name\": \"X\", \"rel\": 0.01}]}]\n"
    "}\n";

static void a_course_should_choose_order_and_narrow_limits(void **state)
{
    (void)state;
    char path[256], log[256];
    snprintf(path, sizeof path, "%s/course.json", tmpdir);
    snprintf(log, sizeof log, "%s/course.log", tmpdir);
    write_text(path, GOOD_COURSE);
    mm_fixture f;
    const char *extra[] = {"--course", path, "--quiet", NULL};
    assert_int_equal(start_logged(&f, log, extra), 0);

    mm_reply r;
    request(&f, NULL, "/api/exercises", NULL, NULL, &r);
    cJSON *cat = cJSON_Parse(r.body);
    assert_int_equal(cJSON_GetArraySize(cat), 2);
    assert_string_equal(cJSON_GetObjectItem(cJSON_GetArrayItem(cat, 0), "id")->valuestring, "vib-sdof-forced");
    assert_string_equal(cJSON_GetObjectItem(cJSON_GetArrayItem(cat, 1), "id")->valuestring, "vib-sdof-free");
    cJSON_Delete(cat);
    mm_reply_free(&r);

    request(&f, NULL, "/api/exercises/vib-sdof-forced", NULL, NULL, &r);
    cJSON *meta = cJSON_Parse(r.body);
    const cJSON *m = cJSON_GetArrayItem(cJSON_GetObjectItem(meta, "params"), 0);
    assert_string_equal(cJSON_GetObjectItem(m, "name")->valuestring, "m");
    assert_true(cJSON_GetObjectItem(m, "default")->valuedouble == 2);
    assert_true(cJSON_GetObjectItem(m, "min")->valuedouble == 0.5);
    assert_true(cJSON_GetObjectItem(m, "max")->valuedouble == 10);
    cJSON_Delete(meta);
    mm_reply_free(&r);

    request(&f, NULL, "/api/exercises/vib-sdof-forced/solve", NULL, NULL, &r);   /* the course's default */
    cJSON *ans = cJSON_Parse(r.body);
    assert_true(cJSON_GetObjectItem(cJSON_GetObjectItem(ans, "params"), "m")->valuedouble == 2);
    cJSON_Delete(ans);
    mm_reply_free(&r);
    request(&f, NULL, "/api/exercises/vib-sdof-forced/solve?m=20", NULL, NULL, &r);   /* built-in allows 1000 */
    assert_int_equal(r.status, 400);
    assert_non_null(strstr(r.body, "out_of_range"));
    mm_reply_free(&r);
    request(&f, NULL, "/api/exercises/num-linear-system/solve", NULL, NULL, &r);     /* not in the course */
    assert_int_equal(r.status, 404);
    mm_reply_free(&r);
    request(&f, NULL, "/api/course", NULL, NULL, &r);
    cJSON *c = cJSON_Parse(r.body);
    assert_string_equal(cJSON_GetObjectItem(c, "title")->valuestring, "Vibrations, autumn term");
    assert_int_equal(cJSON_GetObjectItem(c, "assignments")->valueint, 1);
    cJSON_Delete(c);
    mm_reply_free(&r);

    /* a bad file on SIGHUP: refused, the course stays */
    write_text(path, "{\n  \"title\": \"x\",\n  \"exercises\": [\"vib-no-such\"]\n}\n");
    kill(f.pid, SIGHUP);
    for (int i = 0; i < 1000 && metric(&f, "mechmat_course_reloads_total{result=\"failed\"}") < 1; i++)
        usleep(10000);                   /* polling the server's own counter, not a delay */
    assert_true(metric(&f, "mechmat_course_reloads_total{result=\"failed\"}") == 1);
    request(&f, NULL, "/api/exercises", NULL, NULL, &r);
    cat = cJSON_Parse(r.body);
    assert_int_equal(cJSON_GetArraySize(cat), 2);
    cJSON_Delete(cat);
    mm_reply_free(&r);

    /* a good one, under a base path: served from the next request on */
    write_text(path, "{\"title\": \"Statics\", \"base_path\": \"/statics\", \"exercises\": [\"num-linear-system\"]}");
    kill(f.pid, SIGHUP);
    for (int i = 0; i < 1000; i++) {     /* until the new course answers: polled, not a delay */
        request(&f, NULL, "/statics/api/health", NULL, NULL, &r);
        long st = r.status;
        mm_reply_free(&r);
        if (st == 200)
            break;
        usleep(10000);
    }
    request(&f, NULL, "/api/exercises", NULL, NULL, &r);
    assert_int_equal(r.status, 404);     /* outside the base path */
    mm_reply_free(&r);
    request(&f, NULL, "/statics/api/exercises", NULL, NULL, &r);
    cat = cJSON_Parse(r.body);
    assert_int_equal(cJSON_GetArraySize(cat), 1);
    assert_string_equal(cJSON_GetObjectItem(cJSON_GetArrayItem(cat, 0), "id")->valuestring, "num-linear-system");
    cJSON_Delete(cat);
    mm_reply_free(&r);
    request(&f, NULL, "/statics", NULL, NULL, &r);      /* the pages' relative URLs need the slash */
    assert_int_equal(r.status, 301);
    assert_non_null(strstr(r.headers, "Location: /statics/\r\n"));
    mm_reply_free(&r);
    assert_int_equal(mm_fixture_stop(&f), 0);
    char *text = slurp(log);
    assert_non_null(strstr(text, "course.json:3: no exercise \"vib-no-such\""));
    free(text);
}

static void a_bad_course_file_should_be_refused_at_start_with_line_and_reason(void **state)
{
    (void)state;
    char path[256], log[256], cmd[900];
    snprintf(path, sizeof path, "%s/bad.json", tmpdir);
    snprintf(log, sizeof log, "%s/bad.log", tmpdir);
    write_text(path, "{\n  \"title\": \"x\",\n  \"exercises\": [\n    {\"id\": \"vib-sdof-forced\",\n"
                     "     \"params\": {\"m\": {\"min\": 0.0001}}}\n  ]\n}\n");
    const char *bin = getenv("MM_SERVER") ? getenv("MM_SERVER") : "build/mechmat-server";
    snprintf(cmd, sizeof cmd, "%s --port 0 --course %s > /dev/null 2> %s", bin, path, log);
    int rc = system(cmd);
    assert_true(WIFEXITED(rc) && WEXITSTATUS(rc) == 1);
    char *text = slurp(log);
    if (!strstr(text, "bad.json:5: vib-sdof-forced: m: min 0.0001 is below the built-in 0.001"))
        fail_msg("message: %s", text);
    free(text);
}

/* ---- OpenAPI ------------------------------------------------------------------------------- */

static void the_openapi_document_should_validate_and_list_every_route(void **state)
{
    (void)state;
    mm_reply r;
    request(&server, NULL, "/api/openapi.json", NULL, NULL, &r);
    assert_int_equal(r.status, 200);
    char path[256], cmd[600];
    snprintf(path, sizeof path, "%s/openapi.json", tmpdir);
    FILE *f = fopen(path, "w");
    fwrite(r.body, 1, r.len, f);
    fclose(f);
    snprintf(cmd, sizeof cmd, "node tests/unit/openapi_check.mjs %s", path);
    int rc = system(cmd);
    assert_int_equal(rc, 0);

    cJSON *doc = cJSON_Parse(r.body);
    assert_string_equal(cJSON_GetObjectItem(doc, "openapi")->valuestring, "3.1.0");
    const cJSON *paths = cJSON_GetObjectItem(doc, "paths");
    int n;
    const mm_route_info *routes = mm_http_routes(&n);
    for (int i = 0; i < n; i++) {
        if (strchr(routes[i].pattern, '*'))       /* static files: not the API */
            continue;
        const char *p = routes[i].pattern;
        char concrete[200];
        if (strncmp(p, "/api/assignments/{id}/", 22) == 0) {   /* named {name} there */
            snprintf(concrete, sizeof concrete, "/api/assignments/{name}/%s", p + 22);
            p = concrete;
        } else if (strstr(p, "/script.m")) {      /* one templated path */
        } else if (strstr(p, "{id}/")) {          /* one path per exercise */
            snprintf(concrete, sizeof concrete, "/api/exercises/vib-sdof-forced%s", strstr(p, "{id}/") + 4);
            p = concrete;
        }
        if (!cJSON_GetObjectItem(paths, p))
            fail_msg("route %s has no path in the OpenAPI document", routes[i].pattern);
    }
    /* a parameter with its limits and unit, and the declared outputs */
    const cJSON *solve = cJSON_GetObjectItem(paths, "/api/exercises/vib-sdof-forced/solve");
    const cJSON *prm;
    int found = 0;
    cJSON_ArrayForEach(prm, cJSON_GetObjectItem(cJSON_GetObjectItem(solve, "get"), "parameters")) {
        const cJSON *name = cJSON_GetObjectItem(prm, "name");
        if (cJSON_IsString(name) && strcmp(name->valuestring, "m") == 0) {
            const cJSON *sc = cJSON_GetObjectItem(prm, "schema");
            assert_true(cJSON_GetObjectItem(sc, "minimum")->valuedouble == 1e-3);
            assert_string_equal(cJSON_GetObjectItem(sc, "x-unit")->valuestring, "kg");
            found = 1;
        }
    }
    assert_true(found);
    char *outs = cJSON_PrintUnformatted(cJSON_GetObjectItem(solve, "x-outputs"));
    assert_non_null(strstr(outs, "\"name\":\"omega_n\""));
    free(outs);
    cJSON_Delete(doc);
    mm_reply_free(&r);
}

int main(void)
{
    curl_global_init(CURL_GLOBAL_DEFAULT);
    signal(SIGPIPE, SIG_IGN);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_same_request_should_be_solved_once_and_revalidated_without_a_solve),
        cmocka_unit_test(an_etag_should_follow_the_resolved_parameters_not_their_spelling),
        cmocka_unit_test(head_should_never_solve_twice),
        cmocka_unit_test(identical_requests_in_flight_should_be_solved_once),
        cmocka_unit_test(answers_should_be_compressed_for_clients_that_accept_gzip),
        cmocka_unit_test(documents_and_static_files_should_have_etags_and_304s),
        cmocka_unit_test(versioned_static_files_should_be_cached_for_a_year),
        cmocka_unit_test(metrics_should_be_prometheus_text),
        cmocka_unit_test(a_light_exercise_should_be_solved_at_once_with_the_same_answer),
        cmocka_unit_test(light_us_0_should_send_every_solve_to_the_workers),
        cmocka_unit_test(a_body_over_the_limit_should_get_a_readable_413_not_a_reset),
        cmocka_unit_test(two_thousand_idle_connections_should_not_keep_a_new_client_waiting),
        cmocka_unit_test(a_newline_in_a_url_should_not_forge_a_log_line),
        cmocka_unit_test(a_course_should_choose_order_and_narrow_limits),
        cmocka_unit_test(a_bad_course_file_should_be_refused_at_start_with_line_and_reason),
        cmocka_unit_test(the_openapi_document_should_validate_and_list_every_route),
    };
    int rc = cmocka_run_group_tests_name("http-cache", tests, setup, teardown);
    curl_global_cleanup();
    return rc;
}
