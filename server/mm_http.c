/* mm_http.c — libmicrohttpd glue: routing, bodies, static files, logging. */
#include "mm_http.h"

#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <malloc.h>
#include <microhttpd.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <arpa/inet.h>
#include <netinet/in.h>
#include <semaphore.h>
#include <time.h>
#include <unistd.h>

struct mm_server {
    struct MHD_Daemon *d;
    const mm_api *api;
    char web_real[PATH_MAX];
    char vendor_real[PATH_MAX];   /* "" when there is none */
    int quiet;
    int max_connections;
    atomic_int connections;
    int port;
    sem_t solving;                /* solves running at once: --threads */
};

/* Per-request state, from the first callback to the completion notice. */
typedef struct req {
    long long t0;
    mm_buf body;
    int too_large;
    int answered;
} req;

static long long now_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (long long)ts.tv_sec * 1000000 + ts.tv_nsec / 1000;
}

/* ---- static files ------------------------------------------------------- */

const char *mm_mime_type(const char *path)
{
    static const struct { const char *ext, *type; } types[] = {
        {".html", "text/html; charset=utf-8"},
        {".js", "text/javascript; charset=utf-8"},
        {".mjs", "text/javascript; charset=utf-8"},
        {".css", "text/css; charset=utf-8"},
        {".json", "application/json"},
        {".svg", "image/svg+xml"},
        {".png", "image/png"},
        {".ico", "image/x-icon"},
        {".woff2", "font/woff2"},
        {".woff", "font/woff"},
        {".ttf", "font/ttf"},
        {".md", "text/markdown; charset=utf-8"},
        {".txt", "text/plain; charset=utf-8"},
        {".map", "application/json"},
    };
    const char *dot = strrchr(path, '.');
    const char *slash = strrchr(path, '/');
    if (dot && (!slash || dot > slash))
        for (size_t i = 0; i < sizeof types / sizeof types[0]; i++)
            if (strcmp(dot, types[i].ext) == 0)
                return types[i].type;
    return "application/octet-stream";
}

int mm_static_resolve(const char *root_real, const char *url_path, char *out, size_t size)
{
    char path[PATH_MAX];
    if (url_path[0] != '/' || strchr(url_path, '\\'))
        return MM_ENOTFOUND;
    /* every segment must be a plain name: no "." or ".." anywhere */
    for (const char *s = url_path; *s;) {
        while (*s == '/')
            s++;
        const char *e = s;
        while (*e && *e != '/')
            e++;
        size_t n = (size_t)(e - s);
        if ((n == 1 && s[0] == '.') || (n == 2 && s[0] == '.' && s[1] == '.'))
            return MM_ENOTFOUND;
        s = e;
    }
    int len = snprintf(path, sizeof path, "%s%s", root_real, url_path);
    if (len < 0 || (size_t)len >= sizeof path - 16)
        return MM_ENOTFOUND;
    struct stat st;
    if (stat(path, &st) == 0 && S_ISDIR(st.st_mode))
        strcat(path, path[len - 1] == '/' ? "index.html" : "/index.html");
    char real[PATH_MAX];
    if (!realpath(path, real))
        return MM_ENOTFOUND;
    size_t rl = strlen(root_real);
    if (strncmp(real, root_real, rl) != 0 || real[rl] != '/')   /* left the root */
        return MM_ENOTFOUND;
    if (stat(real, &st) != 0 || !S_ISREG(st.st_mode))
        return MM_ENOTFOUND;
    if (strlen(real) >= size)
        return MM_ENOTFOUND;
    strcpy(out, real);
    return MM_OK;
}

/* ---- responses -------------------------------------------------------------- */

static void log_line(mm_server *s, req *r, const char *method, const char *url, int status)
{
    if (s->quiet)
        return;
    char line[512];
    int n = snprintf(line, sizeof line, "%s %.300s %d %lldus\n", method, url, status,
                     now_us() - r->t0);
    if (n > 0)
        (void)!write(2, line, (size_t)n < sizeof line ? (size_t)n : sizeof line - 1);
}

static enum MHD_Result reply(struct MHD_Connection *c, mm_server *s, req *r,
                             const char *method, const char *url, int status,
                            struct MHD_Response *resp, const char *type)
{
    if (!resp)
        return MHD_NO;
    if (type)
        MHD_add_response_header(resp, MHD_HTTP_HEADER_CONTENT_TYPE, type);
    MHD_add_response_header(resp, "X-Content-Type-Options", "nosniff");
    enum MHD_Result ret = MHD_queue_response(c, (unsigned)status, resp);
    MHD_destroy_response(resp);
    r->answered = 1;
    log_line(s, r, method, url, status);
    return ret;
}

static enum MHD_Result send_static_text(struct MHD_Connection *c, mm_server *s, req *r,
                                        const char *method, const char *url,
                                        const char *text, size_t len)
{
    struct MHD_Response *resp =
        MHD_create_response_from_buffer(len, (void *)(uintptr_t)text, MHD_RESPMEM_PERSISTENT);
    return reply(c, s, r, method, url, 200, resp, "application/json");
}

static enum MHD_Result send_buf(struct MHD_Connection *c, mm_server *s, req *r,
                                const char *method, const char *url, int status, mm_buf *b)
{
    size_t len;
    char *text = mm_buf_take(b, &len);
    if (!text)
        return MHD_NO;
    struct MHD_Response *resp =
        MHD_create_response_from_buffer_with_free_callback(len, text, free);
    if (!resp) {
        free(text);
        return MHD_NO;
    }
    return reply(c, s, r, method, url, status, resp, "application/json");
}

static enum MHD_Result send_error(struct MHD_Connection *c, mm_server *s, req *r,
                                  const char *method, const char *url, int code,
                                  const char *param, const char *msg, const char *allow)
{
    mm_buf b;
    mm_error err;
    mm_buf_init(&b, 4096);
    mm_error_set(&err, code, param, "%s", msg);
    int status = mm_api_error(&b, &err);
    size_t len;
    char *text = mm_buf_take(&b, &len);
    if (!text)
        return MHD_NO;
    struct MHD_Response *resp =
        MHD_create_response_from_buffer_with_free_callback(len, text, free);
    if (!resp) {
        free(text);
        return MHD_NO;
    }
    if (allow)
        MHD_add_response_header(resp, MHD_HTTP_HEADER_ALLOW, allow);
    return reply(c, s, r, method, url, status, resp, "application/json");
}

static enum MHD_Result send_file(struct MHD_Connection *c, mm_server *s, req *r,
                                 const char *method, const char *url, const char *root,
                                 const char *path)
{
    char real[PATH_MAX];
    if (!root[0] || mm_static_resolve(root, path, real, sizeof real) != MM_OK)
        return send_error(c, s, r, method, url, MM_ENOTFOUND, "", "no such page", NULL);
    int fd = open(real, O_RDONLY | O_CLOEXEC);
    struct stat st;
    if (fd < 0 || fstat(fd, &st) != 0) {
        if (fd >= 0)
            close(fd);
        return send_error(c, s, r, method, url, MM_ENOTFOUND, "", "no such page", NULL);
    }
    struct MHD_Response *resp = MHD_create_response_from_fd((uint64_t)st.st_size, fd);
    if (!resp) {
        close(fd);
        return MHD_NO;
    }
    MHD_add_response_header(resp, MHD_HTTP_HEADER_CACHE_CONTROL, "no-cache");
    return reply(c, s, r, method, url, 200, resp, mm_mime_type(real));
}

/* ---- query arguments -------------------------------------------------------- */

typedef struct args {
    mm_input in[MM_MAX_PARAMS];
    int n;
    size_t bytes;
    int too_many, has_nul;
} args;

static enum MHD_Result collect_arg(void *cls, enum MHD_ValueKind kind, const char *key,
                                   size_t key_size, const char *value, size_t value_size)
{
    (void)kind;
    args *a = cls;
    a->bytes += key_size + value_size + 2;
    if (memchr(key, '\0', key_size) || (value && memchr(value, '\0', value_size)))
        a->has_nul = 1;
    if (key_size == 0 && value_size == 0)   /* an empty pair: "?&m=2", "m=2&&k=3" */
        return MHD_YES;
    if (a->n >= MM_MAX_PARAMS) {
        a->too_many = 1;
        return MHD_YES;
    }
    a->in[a->n++] = (mm_input){key, value ? value : "", key_size, value ? value_size : 0};
    return MHD_YES;
}

/* ---- routing -------------------------------------------------------------------- */

/* Each connection has its thread (see mm_server_start); at most --threads
 * of them solve at once, the others wait here, so that CPU and memory
 * (each solve's arena may reach MM_REQ_MEM_CAP) stay bounded however many
 * connections are open. */
static void solve_gate(mm_server *s, int enter)
{
    if (!enter)
        sem_post(&s->solving);
    else
        while (sem_wait(&s->solving) != 0)
            ;                          /* EINTR: wait again */
}

static enum MHD_Result route(mm_server *s, struct MHD_Connection *c, req *r,
                             const char *url, const char *method)
{
    int is_get = strcmp(method, "GET") == 0 || strcmp(method, "HEAD") == 0;
    int is_post = strcmp(method, "POST") == 0;

    if (strncmp(url, "/api/", 5) != 0) {
        if (strncmp(url, "/vendor/", 8) == 0 && is_get)
            return send_file(c, s, r, method, url, s->vendor_real, url + 7);
        if (!is_get)
            return send_error(c, s, r, method, url, MM_EMETHOD, "",
                              "static pages answer GET and HEAD only", "GET, HEAD");
        return send_file(c, s, r, method, url, s->web_real, url);
    }

    if (strcmp(url, "/api/health") == 0 || strcmp(url, "/api/exercises") == 0) {
        if (!is_get)
            return send_error(c, s, r, method, url, MM_EMETHOD, "", "use GET", "GET, HEAD");
        size_t len;
        const char *doc = url[5] == 'h' ? mm_api_health(s->api, &len) : mm_api_catalog(s->api, &len);
        return send_static_text(c, s, r, method, url, doc, len);
    }

    if (strncmp(url, "/api/exercises/", 15) == 0) {
        const char *id = url + 15;
        const char *slash = strchr(id, '/');
        char idbuf[64];
        size_t idlen = slash ? (size_t)(slash - id) : strlen(id);
        if (idlen == 0 || idlen >= sizeof idbuf)
            return send_error(c, s, r, method, url, MM_ENOTFOUND, "", "no such exercise", NULL);
        memcpy(idbuf, id, idlen);
        idbuf[idlen] = '\0';
        const mm_exercise *ex = mm_exercise_find(idbuf);
        if (!ex) {
            char msg[128];
            snprintf(msg, sizeof msg, "no exercise '%.60s'; GET /api/exercises lists them", idbuf);
            return send_error(c, s, r, method, url, MM_ENOTFOUND, "", msg, NULL);
        }
        if (!slash) {
            if (!is_get)
                return send_error(c, s, r, method, url, MM_EMETHOD, "", "use GET", "GET, HEAD");
            size_t len;
            const char *doc = mm_api_meta(s->api, idbuf, &len);
            return send_static_text(c, s, r, method, url, doc, len);
        }
        if (strcmp(slash, "/solve") == 0) {
            mm_buf out;
            mm_buf_init(&out, MM_ANSWER_MAX);
            int status;
            if (is_get) {
                args a = {0};
                MHD_get_connection_values_n(c, MHD_GET_ARGUMENT_KIND, collect_arg, &a);
                if (a.bytes > MM_QUERY_MAX)
                    return send_error(c, s, r, method, url, MM_ETOOBIG, "",
                                      "the query is too long (at most 16 KiB); send large values by POST", NULL);
                if (a.has_nul)
                    return send_error(c, s, r, method, url, MM_EVALUE, "",
                                      "the query contains a NUL byte", NULL);
                if (a.too_many) {
                    char msg[96];
                    snprintf(msg, sizeof msg, "too many parameters; %s has %d", ex->id, ex->n_params);
                    return send_error(c, s, r, method, url, MM_EPARAM, "", msg, NULL);
                }
                solve_gate(s, 1);
                status = mm_api_solve(ex, a.in, a.n, &out);
                solve_gate(s, 0);
            } else if (is_post) {
                solve_gate(s, 1);
                status = mm_api_solve_json(ex, r->body.p ? r->body.p : "", r->body.len, &out);
                solve_gate(s, 0);
            } else {
                return send_error(c, s, r, method, url, MM_EMETHOD, "", "use GET or POST",
                                  "GET, HEAD, POST");
            }
            enum MHD_Result ret = send_buf(c, s, r, method, url, status, &out);
            mm_buf_free(&out);
            return ret;
        }
    }
    return send_error(c, s, r, method, url, MM_ENOTFOUND, "", "no such route; see /api/exercises", NULL);
}

static enum MHD_Result on_request(void *cls, struct MHD_Connection *c, const char *url,
                                  const char *method, const char *version,
                                  const char *upload_data, size_t *upload_size, void **req_cls)
{
    (void)version;
    mm_server *s = cls;
    req *r = *req_cls;

    if (!r) {                          /* first call: headers only */
        r = calloc(1, sizeof *r);
        if (!r)
            return MHD_NO;
        r->t0 = now_us();
        mm_buf_init(&r->body, MM_BODY_MAX);
        *req_cls = r;
        if (atomic_load(&s->connections) > s->max_connections)
            return send_error(c, s, r, method, url, MM_EBUSY, "", "busy", NULL);
        if (strcmp(method, "POST") == 0) {
            const char *cl = MHD_lookup_connection_value(c, MHD_HEADER_KIND,
                                                         MHD_HTTP_HEADER_CONTENT_LENGTH);
            if (cl && strtoull(cl, NULL, 10) > MM_BODY_MAX)
                return send_error(c, s, r, method, url, MM_ETOOBIG, "",
                                  "the body is over 1 MiB", NULL);
        }
        return MHD_YES;                /* answer on a later call: keeps keep-alive */
    }
    if (r->answered) {                 /* a body still arriving after an answer */
        *upload_size = 0;
        return MHD_YES;
    }
    if (*upload_size) {
        if (!r->too_large) {
            mm_buf_put(&r->body, upload_data, *upload_size);
            if (r->body.failed)
                r->too_large = 1;
        }
        *upload_size = 0;
        return MHD_YES;
    }
    if (r->too_large)
        return send_error(c, s, r, method, url, MM_ETOOBIG, "", "the body is over 1 MiB", NULL);
    return route(s, c, r, url, method);
}

static void on_completed(void *cls, struct MHD_Connection *c, void **req_cls,
                         enum MHD_RequestTerminationCode toe)
{
    (void)cls, (void)c, (void)toe;
    req *r = *req_cls;
    if (r) {
        mm_buf_free(&r->body);
        free(r);
        *req_cls = NULL;
    }
}

static void on_connection(void *cls, struct MHD_Connection *c, void **socket_ctx,
                          enum MHD_ConnectionNotificationCode toe)
{
    (void)c, (void)socket_ctx;
    mm_server *s = cls;
    if (toe == MHD_CONNECTION_NOTIFY_STARTED)
        atomic_fetch_add(&s->connections, 1);
    else
        atomic_fetch_sub(&s->connections, 1);
}

/* Percent-decoding of the path and the query, in place.  Unlike the
 * default, a %00 does not cut the text short (that would make
 * "/index.html%00.txt" read as "/index.html"): it becomes a backslash,
 * which no path and no number accepts, so the request fails as it should. */
size_t mm_http_unescape(char *s)
{
    char *w = s;
    for (const char *r = s; *r; r++) {
        if (r[0] == '%' && isxdigit((unsigned char)r[1]) && isxdigit((unsigned char)r[2])) {
            char hex[3] = {r[1], r[2], '\0'};
            char byte = (char)strtol(hex, NULL, 16);
            *w++ = byte ? byte : '\\';
            r += 2;
        } else {
            *w++ = *r;
        }
    }
    *w = '\0';
    return (size_t)(w - s);
}

static size_t unescape(void *cls, struct MHD_Connection *c, char *s)
{
    (void)cls, (void)c;
    return mm_http_unescape(s);
}

/* ---- life cycle -------------------------------------------------------------- */

mm_server *mm_server_start(const mm_server_opts *o, const mm_api *api, mm_error *err)
{
    mm_server *s = calloc(1, sizeof *s);
    if (!s) {
        mm_error_set(err, MM_ENOMEM, "", "out of memory");
        return NULL;
    }
    s->api = api;
    s->quiet = o->quiet;
    s->max_connections = o->max_connections > 0 ? o->max_connections : 512;
    if (!realpath(o->web_root, s->web_real)) {
        mm_error_set(err, MM_EVALUE, "web-root", "web root %s: %s", o->web_root, strerror(errno));
        free(s);
        return NULL;
    }
    if (!o->vendor_root || !realpath(o->vendor_root, s->vendor_real))
        s->vendor_real[0] = '\0';

    struct sockaddr_in addr;
    memset(&addr, 0, sizeof addr);
    addr.sin_family = AF_INET;
    addr.sin_port = htons((uint16_t)o->port);
    if (inet_pton(AF_INET, o->host, &addr.sin_addr) != 1) {
        mm_error_set(err, MM_EVALUE, "host", "host must be an IPv4 address such as 127.0.0.1; got %.60s",
                     o->host);
        free(s);
        return NULL;
    }
#ifdef M_MMAP_THRESHOLD
    /* Blocks of 64 KiB and more (answers, result arenas, FFT arrays) are
     * mapped and unmapped one by one, so that the resident size follows the
     * requests in flight.  By default glibc raises its mmap threshold (up to
     * 32 MiB) at the first large free, and from then on keeps such blocks in
     * its per-thread arenas once freed: after a load test 40 of 49 MiB of
     * arena memory were free but resident, and the resident size after a
     * minute of load wandered between -30 % and +14 % of its size after
     * the warm-up, depending on the fragmentation of the moment. */
    mallopt(M_MMAP_THRESHOLD, 64 * 1024);
    mallopt(M_TRIM_THRESHOLD, 256 * 1024);
#endif
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    unsigned threads = (unsigned)(o->threads > 0 ? o->threads : (cores > 0 ? cores : 2));

    if (sem_init(&s->solving, 0, threads) != 0) {
        mm_error_set(err, MM_EINTERNAL, "", "semaphore: %s", strerror(errno));
        free(s);
        return NULL;
    }

    /* A thread per connection (poll), not a pool of epoll threads: with
     * MHD_USE_EPOLL_INTERNAL_THREAD and a thread pool, libmicrohttpd 0.9.75
     * now and then stops serving every connection at once under load (all
     * requests unread in the sockets' receive queues, every worker in
     * epoll_wait until the 30 s connection timeout; about once in 150-200 s
     * at 256 connections, with or without MHD_USE_TURBO; reproduced by
     * tests/load/stall_hunt.sh), and the pool with poll starves some
     * connections (p99 7.8 s).  Per connection: no stall in 28 rounds of the
     * same hunt, for 20 % less throughput on the mix and 40 % less on
     * /api/health (still about 100 000 req/s).  The solves themselves go
     * through solve_gate, --threads at a time. */
    s->d = MHD_start_daemon(
        MHD_USE_THREAD_PER_CONNECTION | MHD_USE_INTERNAL_POLLING_THREAD | MHD_USE_POLL |
            MHD_USE_ERROR_LOG,
        (uint16_t)o->port, NULL, NULL, on_request, s,
        MHD_OPTION_SOCK_ADDR, (struct sockaddr *)&addr,
        MHD_OPTION_CONNECTION_LIMIT, (unsigned)(s->max_connections * 2 + 64),
        MHD_OPTION_CONNECTION_TIMEOUT, (unsigned)30,
        MHD_OPTION_CONNECTION_MEMORY_LIMIT, (size_t)(64 * 1024),
        MHD_OPTION_LISTEN_BACKLOG_SIZE, (unsigned)1024,
        MHD_OPTION_NOTIFY_COMPLETED, on_completed, s,
        MHD_OPTION_NOTIFY_CONNECTION, on_connection, s,
        MHD_OPTION_UNESCAPE_CALLBACK, unescape, NULL,
        MHD_OPTION_END);
    if (!s->d) {
        mm_error_set(err, MM_EINTERNAL, "port", "could not listen on %s:%d (in use?)", o->host, o->port);
        sem_destroy(&s->solving);
        free(s);
        return NULL;
    }
    const union MHD_DaemonInfo *info = MHD_get_daemon_info(s->d, MHD_DAEMON_INFO_BIND_PORT);
    s->port = info ? info->port : o->port;
    return s;
}

int mm_server_port(const mm_server *s) { return s->port; }

void mm_server_stop(mm_server *s)
{
    if (!s)
        return;
    if (s->d)
        MHD_stop_daemon(s->d);
    sem_destroy(&s->solving);
    free(s);
}
