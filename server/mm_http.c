/* mm_http.c — libmicrohttpd glue: the route table, the event thread and
 * its solve workers, caching and compression, static files, metrics, the
 * access log (see mm_http.h for the threading model). */
#include "mm_http.h"
#include "mm_light.h"

#include <ctype.h>
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <malloc.h>
#include <microhttpd.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <arpa/inet.h>
#include <netinet/in.h>
#include <time.h>
#include <unistd.h>
#include <libdeflate.h>

#include "mm_assign.h"
#include "mm_cache.h"
#include "mm_hash.h"
#include "mm_script.h"

#define DISCARD_MAX   (16u << 20)   /* a body over the limit read and dropped up to this */
#define GZ_MIN        1024          /* smaller answers go as they are */
#define GZ_ANSWER     1             /* libdeflate level of answers: one per distinct answer,
                                       on a worker, so speed first.  libdeflate's level 1
                                       compresses vib-sdof-forced's default answer (42 KB) in
                                       72 us to 11.2 KB where zlib's level 1 took 126 us for
                                       12.3 KB, and zlib's 6 2.5 times that */
#define GZ_FILE       6             /* static files: once each, on first request */
#define GZ_DOC        9             /* documents: once, at start and reload */
#define STATIC_MEMO_MAX (64u << 20) /* bytes of static files kept in memory */
#define STATIC_FILE_MAX (16u << 20) /* larger files are sent from disk each time */
#define OUT_KEEP_GZ   ((size_t)256 << 10) /* a thread keeps its compression buffer up to this size */
#define ASSET_TOKEN   "__MM_ASSET_VERSION__"
#define YEAR_CACHE    "public, max-age=31536000, immutable"

/* The browser packages served under /vendor/ (package.json "dependencies"). */
static const char *const vendor_packages[] = {"katex", "d3", "@observablehq/plot", NULL};

/* ---- what a request is served from: the documents of one course ------------- */

typedef struct zdoc {              /* a document and its gzip form */
    const mm_doc *doc;
    char *gz;
    size_t gz_len;
    char gz_etag[MM_ETAG_SIZE + 4];
} zdoc;

typedef struct site {
    mm_api *api;
    atomic_int refs;
    zdoc health, catalog, course, openapi, assignments;
    zdoc *meta;                    /* one per exercise of the course */
    int n_meta;
    char base[256];                /* the course's base path without its last '/', "" for "/" */
    size_t base_len;
} site;

/* ---- metrics ------------------------------------------------------------------- */

enum { ST_200, ST_304, ST_400, ST_404, ST_405, ST_413, ST_422, ST_500, ST_503, ST_OTHER, N_ST };
static const int status_codes[N_ST] = {200, 304, 400, 404, 405, 413, 422, 500, 503, 0};
static const double solve_buckets[] = {1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 0.1, 0.3, 1, 3};
#define N_BUCKETS (int)(sizeof solve_buckets / sizeof solve_buckets[0])
#define MAX_ROUTES 24

typedef struct metrics {
    atomic_ullong requests[MAX_ROUTES][N_ST];
    atomic_ullong solve_hist[N_BUCKETS + 1];
    atomic_ullong solve_us_sum, solves, light_solves;
    atomic_ullong revalidated, bytes_out, busy;
    atomic_ullong reloads_ok, reloads_failed;
} metrics;

/* ---- the server ----------------------------------------------------------------- */

typedef struct job job;

typedef struct static_file {       /* a static file read into memory */
    char path[PATH_MAX];
    dev_t dev;
    ino_t ino;
    off_t size;
    struct timespec mtime;
    char *body, *gz;
    size_t len, gz_len;
    char etag[MM_ETAG_SIZE], gz_etag[MM_ETAG_SIZE + 4];
    const char *mime;
    int vendor;
    int current;                   /* as the asset version saw it (web files) */
    char url[256];                 /* the last URL path that led here ("" if long) */
    long long checked_us;          /* when that URL was last resolved to this file */
    atomic_int refs;               /* the list's and each response's */
    struct static_file *next;
} static_file;

typedef struct asset {             /* a web file as the asset version saw it */
    char *rel;
    off_t size;
    struct timespec mtime;
} asset;

#define MAX_IO 8

/* Light solves: made by the event thread that read the request (mm_light.h) */
#define LIGHT_SLOTS 256            /* exercise ids; past that, every solve goes to the workers */

typedef struct light {
    atomic_int ready;              /* id and weight are set */
    char id[64];
    atomic_int weight;             /* us, see mm_light.h */
} light;

struct mm_server {
    struct MHD_Daemon *d[MAX_IO];  /* the event threads, one daemon each */
    int n_io;
    _Atomic(site *) site;
    pthread_mutex_t site_lock;     /* serialises replacements */
    mm_cache *cache;
    char web_real[PATH_MAX];
    char vendor_real[PATH_MAX];    /* "" when there is none */
    int quiet;
    int max_connections;
    atomic_int connections, in_flight;
    int port;
    metrics m;

    /* static files (files under static_lock) and the asset version */
    pthread_mutex_t static_lock;
    static_file *files;
    size_t files_bytes;
    atomic_int files_stale;        /* set by a replacement: read them again */
    char asset_version[32];
    asset *assets;
    int n_assets;

    /* which exercises' solves run on the event threads (light_weight) */
    int light_us;                  /* mm_light.h; 0: none */
    pthread_mutex_t light_lock;
    light lights[LIGHT_SLOTS];

    /* solve workers */
    pthread_t *workers;
    int n_workers;
    pthread_mutex_t q_lock;
    pthread_cond_t q_cond;
    job **queue;
    int q_cap, q_head, q_len, stopping;
};

/* A job is a solve, or an assignment task (a check, a key, a class CSV):
 * work that solves the exercise once or many times and so is kept off
 * the event threads.  A task's answer goes through a private cache entry
 * (a key no other request has, never kept) so that it reaches its request
 * the way a solve does. */
enum { TASK_NONE, TASK_CHECK, TASK_KEY, TASK_CSV };

struct job {
    mm_solve *solve;
    mm_entry *entry;
    site *site;
    int want_gz;
    int task;                      /* TASK_NONE for a solve */
    const mm_assignment *asg;      /* a task's, alive while site is */
    char *text;                    /* a task's input: the body, or the student */
    size_t text_len;
    atomic_int *weight;            /* a solve's exercise's (light_weight), or NULL */
};

/* Per-request state, from the first callback to the completion notice. */
enum { R_NEW, R_BODY, R_WAIT };

typedef struct req {
    mm_server *s;
    site *site;
    struct MHD_Connection *c;
    long long t0;
    int state;
    int route;                     /* index in routes[], or -1 */
    mm_buf body;
    size_t discarded;
    int too_large, answered;
    mm_entry *entry;               /* R_WAIT: the answer being made */
    int shared;                    /* waited for another request's solve */
    int want_gz;
    size_t sent;
    const char *task_type;         /* R_WAIT on a task: its Content-Type, else NULL */
} req;

static long long now_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (long long)ts.tv_sec * 1000000 + ts.tv_nsec / 1000;
}

/* ---- sites ------------------------------------------------------------------------- */

static int gzip_bytes(const char *in, size_t n, int level, char **out, size_t *out_len);

static void site_unref(site *st)
{
    if (!st || atomic_fetch_sub_explicit(&st->refs, 1, memory_order_acq_rel) != 1)
        return;
    free(st->health.gz);
    free(st->catalog.gz);
    free(st->course.gz);
    free(st->openapi.gz);
    free(st->assignments.gz);
    for (int i = 0; i < st->n_meta; i++)
        free(st->meta[i].gz);
    free(st->meta);
    mm_api_free(st->api);
    free(st);
}

static site *site_ref(mm_server *s)
{
    pthread_mutex_lock(&s->site_lock);
    site *st = atomic_load(&s->site);
    atomic_fetch_add_explicit(&st->refs, 1, memory_order_relaxed);
    pthread_mutex_unlock(&s->site_lock);
    return st;
}

static void zdoc_make(zdoc *z, const mm_doc *d)
{
    z->doc = d;
    if (d->len >= GZ_MIN && gzip_bytes(d->text, d->len, GZ_DOC, &z->gz, &z->gz_len) == 0) {
        size_t n = strlen(d->etag);
        snprintf(z->gz_etag, sizeof z->gz_etag, "%.*s-gz\"", (int)(n - 1), d->etag);
    }
}

static site *site_new(mm_api *api)
{
    site *st = calloc(1, sizeof *st);
    if (!st)
        return NULL;
    st->api = api;
    atomic_init(&st->refs, 1);
    const mm_course *c = mm_api_course(api);
    st->n_meta = mm_course_exercise_count(c);
    st->meta = calloc((size_t)st->n_meta + 1, sizeof *st->meta);
    if (!st->meta) {
        free(st);
        return NULL;
    }
    zdoc_make(&st->health, mm_api_doc_health(api));
    zdoc_make(&st->catalog, mm_api_doc_catalog(api));
    zdoc_make(&st->course, mm_api_doc_course(api));
    zdoc_make(&st->openapi, mm_api_doc_openapi(api));
    zdoc_make(&st->assignments, mm_api_doc_assignments(api));
    for (int i = 0; i < st->n_meta; i++)
        zdoc_make(&st->meta[i], mm_api_doc_meta(api, mm_course_exercise(c, i)->id));
    snprintf(st->base, sizeof st->base, "%s", mm_course_base_path(c));
    st->base_len = strlen(st->base);
    if (st->base_len > 0 && st->base[st->base_len - 1] == '/')
        st->base[--st->base_len] = '\0';
    return st;
}

/* ---- small pieces: compression, validators, escaping ----------------------------- */

/* What a thread keeps from one answer to the next, made at its first use:
 * its compressor for answers (libdeflate at GZ_ANSWER) and that one's
 * output buffer: making one allocates its hash tables (a zlib stream took
 * about 270 KiB, four blocks over malloc's mmap threshold mapped and
 * unmapped each time: 300 us of a 2 KB answer's compression went there);
 * and for an event thread that makes light solves, the answer buffer and
 * the result block (mm_result_keep_blocks) that a worker keeps for the
 * same reason.  Freed when the thread ends (the key's destructor: the
 * event threads are libmicrohttpd's) or by kit_end. */
typedef struct kit {
    struct libdeflate_compressor *c;
    char *buf;
    size_t cap;
    mm_buf out;                    /* an event thread's, for light solves */
    int solving;                   /* out is set up, result blocks kept */
} kit;

static _Thread_local kit *kit_tl;
static pthread_key_t kit_key;
static pthread_once_t kit_once = PTHREAD_ONCE_INIT;

static void kit_free(void *p)
{
    kit *k = p;
    if (!k)
        return;
    libdeflate_free_compressor(k->c);
    free(k->buf);
    if (k->solving) {
        mm_buf_free(&k->out);
        mm_result_keep_blocks(0);
    }
    free(k);
}

static void kit_key_make(void) { (void)pthread_key_create(&kit_key, kit_free); }

static kit *kit_get(void)
{
    if (kit_tl)
        return kit_tl;
    pthread_once(&kit_once, kit_key_make);
    kit *k = calloc(1, sizeof *k);
    if (!k)
        return NULL;
    k->c = libdeflate_alloc_compressor(GZ_ANSWER);
    if (!k->c || pthread_setspecific(kit_key, k) != 0) {
        kit_free(k);
        return NULL;
    }
    kit_tl = k;
    return k;
}

static void kit_end(void)
{
    if (!kit_tl)
        return;
    (void)pthread_setspecific(kit_key, NULL);
    kit_free(kit_tl);
    kit_tl = NULL;
}

/* An answer compressed by this thread's libdeflate compressor, into a block
 * of its own size; -1 when it does not shrink or without memory. */
static int gzip_answer(const char *in, size_t n, char **out, size_t *out_len)
{
    kit *g = kit_get();
    if (!g)
        return -1;
    size_t cap = libdeflate_gzip_compress_bound(g->c, n);
    if (g->cap < cap) {
        free(g->buf);
        g->buf = malloc(cap);
        g->cap = g->buf ? cap : 0;
        if (!g->buf)
            return -1;
    }
    size_t len = libdeflate_gzip_compress(g->c, in, n, g->buf, g->cap);
    char *copy = len > 0 && len < n ? malloc(len) : NULL;
    if (copy)
        memcpy(copy, g->buf, len);
    if (g->cap > OUT_KEEP_GZ) {
        free(g->buf);
        g->buf = NULL;
        g->cap = 0;
    }
    if (!copy)
        return -1;
    *out = copy;
    *out_len = len;
    return 0;
}

/* in compressed (gzip) at a libdeflate level, an answer's (GZ_ANSWER) by
 * this thread's compressor, a file's or a document's (once each) by one
 * made for it; -1 when it does not shrink or on failure. */
static int gzip_bytes(const char *in, size_t n, int level, char **out, size_t *out_len)
{
    if (level == GZ_ANSWER)
        return gzip_answer(in, n, out, out_len);
    struct libdeflate_compressor *c = libdeflate_alloc_compressor(level);
    if (!c)
        return -1;
    size_t cap = libdeflate_gzip_compress_bound(c, n);
    char *buf = malloc(cap);
    size_t len = buf ? libdeflate_gzip_compress(c, in, n, buf, cap) : 0;
    libdeflate_free_compressor(c);
    if (len == 0 || len >= n) {              /* no gain (or no memory): send it as it is */
        free(buf);
        return -1;
    }
    *out = buf;
    *out_len = len;
    return 0;
}

int mm_accepts_gzip(const char *ae)
{
    if (!ae)
        return 0;
    for (const char *s = ae; *s;) {
        while (*s == ' ' || *s == ',' || *s == '\t')
            s++;
        const char *t = s;
        while (*s && *s != ',' && *s != ';' && *s != ' ')
            s++;
        size_t n = (size_t)(s - t);
        int gz = (n == 4 && strncasecmp(t, "gzip", 4) == 0) || (n == 6 && strncasecmp(t, "x-gzip", 6) == 0) ||
                 (n == 1 && *t == '*');
        double q = 1;
        while (*s && *s != ',') {          /* parameters: ;q=0.5 */
            if (*s == ';') {
                s++;
                while (*s == ' ')
                    s++;
                if ((s[0] == 'q' || s[0] == 'Q') && s[1] == '=')
                    q = strtod(s + 2, NULL);
            }
            if (*s && *s != ',')
                s++;
        }
        if (gz && n > 0)
            return q > 0;
    }
    return 0;
}

int mm_etag_matches(const char *inm, const char *etag)
{
    if (!inm)
        return 0;
    size_t el = strlen(etag);              /* "abc" with its quotes */
    for (const char *s = inm; *s;) {
        while (*s == ' ' || *s == ',' || *s == '\t')
            s++;
        if (*s == '*')
            return 1;
        if (s[0] == 'W' && s[1] == '/')
            s += 2;
        const char *t = s;
        if (*s == '"') {
            s++;
            while (*s && *s != '"')
                s++;
            if (*s == '"')
                s++;
        } else {
            while (*s && *s != ',')
                s++;
        }
        size_t n = (size_t)(s - t);
        if (n == el && memcmp(t, etag, el) == 0)
            return 1;
        /* "abc-gz" for "abc": the same answer, compressed */
        if (n == el + 3 && memcmp(t, etag, el - 1) == 0 && memcmp(t + el - 1, "-gz\"", 4) == 0)
            return 1;
        while (*s && *s != ',')
            s++;
    }
    return 0;
}

size_t mm_log_escape(const char *s, char *out, size_t size)
{
    static const char hex[] = "0123456789abcdef";
    size_t k = 0;
    if (size == 0)
        return 0;
    for (const unsigned char *c = (const unsigned char *)s; *c; c++) {
        if (*c < 0x20 || *c >= 0x7f || *c == '"' || *c == '\\') {
            if (k + 5 >= size)
                break;
            out[k++] = '\\', out[k++] = 'x', out[k++] = hex[*c >> 4], out[k++] = hex[*c & 15];
        } else {
            if (k + 2 >= size)
                break;
            out[k++] = (char)*c;
        }
    }
    out[k] = '\0';
    return k;
}

/* ---- static files ------------------------------------------------------------------ */

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

static int is_text_asset(const char *path)
{
    const char *dot = strrchr(path, '.');
    return dot && (!strcmp(dot, ".html") || !strcmp(dot, ".js") || !strcmp(dot, ".mjs") || !strcmp(dot, ".css"));
}

static char *read_all(int fd, size_t size)
{
    char *b = malloc(size + 1);
    size_t got = 0;
    while (b && got < size) {
        ssize_t n = read(fd, b + got, size - got);
        if (n <= 0) {
            if (n < 0 && errno == EINTR)
                continue;
            free(b);
            return NULL;
        }
        got += (size_t)n;
    }
    if (b)
        b[size] = '\0';
    return b;
}

/* text with every ASSET_TOKEN replaced by the version; NULL when none */
static char *substitute(const char *text, size_t len, const char *version, size_t *out_len)
{
    size_t tl = strlen(ASSET_TOKEN), vl = strlen(version), count = 0;
    for (const char *p = text; (p = strstr(p, ASSET_TOKEN)); p += tl)
        count++;
    if (!count)
        return NULL;
    size_t n = len - count * tl + count * vl;
    char *out = malloc(n + 1), *w = out;
    if (!out)
        return NULL;
    const char *p = text;
    for (const char *q; (q = strstr(p, ASSET_TOKEN)); p = q + tl) {
        memcpy(w, p, (size_t)(q - p));
        w += q - p;
        memcpy(w, version, vl);
        w += vl;
    }
    memcpy(w, p, (size_t)(text + len - p));
    out[n] = '\0';
    *out_len = n;
    return out;
}

static void static_unref(void *cls)
{
    static_file *f = cls;
    if (atomic_fetch_sub_explicit(&f->refs, 1, memory_order_acq_rel) == 1) {
        free(f->body);
        free(f->gz);
        free(f);
    }
}

static void static_drop_all(mm_server *s)
{
    while (s->files) {
        static_file *f = s->files;
        s->files = f->next;
        static_unref(f);
    }
    s->files_bytes = 0;
}

/* The memory copy of the file at real, referenced (static_unref it): read
 * again when it changed on disk.  NULL when it cannot be read or is too
 * large to keep.  static_lock held. */
static static_file *static_get_locked(mm_server *s, const char *real, const struct stat *st, int vendor)
{
    if (atomic_exchange(&s->files_stale, 0))
        static_drop_all(s);
    static_file **pp = &s->files;
    for (static_file *f = s->files; f; pp = &f->next, f = f->next) {
        if (strcmp(f->path, real) != 0)
            continue;
        if (f->dev == st->st_dev && f->ino == st->st_ino && f->size == st->st_size &&
            f->mtime.tv_sec == st->st_mtim.tv_sec && f->mtime.tv_nsec == st->st_mtim.tv_nsec) {
            atomic_fetch_add_explicit(&f->refs, 1, memory_order_relaxed);
            return f;
        }
        *pp = f->next;                       /* changed: read it again */
        s->files_bytes -= f->len + f->gz_len;
        static_unref(f);
        break;
    }
    if (st->st_size > STATIC_FILE_MAX || s->files_bytes + (size_t)st->st_size > STATIC_MEMO_MAX)
        return NULL;
    int fd = open(real, O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return NULL;
    char *body = read_all(fd, (size_t)st->st_size);
    close(fd);
    if (!body)
        return NULL;
    static_file *f = calloc(1, sizeof *f);
    if (!f) {
        free(body);
        return NULL;
    }
    snprintf(f->path, sizeof f->path, "%s", real);
    f->dev = st->st_dev, f->ino = st->st_ino, f->size = st->st_size, f->mtime = st->st_mtim;
    f->body = body;
    f->len = (size_t)st->st_size;
    f->vendor = vendor;
    atomic_init(&f->refs, 1);
    f->mime = mm_mime_type(real);
    if (!vendor && is_text_asset(real)) {
        size_t n;
        char *sub = substitute(body, f->len, s->asset_version, &n);
        if (sub) {
            free(f->body);
            f->body = sub;
            f->len = n;
        }
    }
    char d[MM_DIGEST_SIZE];
    mm_digest(f->body, f->len, d);
    snprintf(f->etag, sizeof f->etag, "\"%s\"", d);
    if (f->len >= GZ_MIN && strncmp(f->mime, "image/png", 9) && strncmp(f->mime, "font/woff", 9) &&
        gzip_bytes(f->body, f->len, GZ_FILE, &f->gz, &f->gz_len) == 0)
        snprintf(f->gz_etag, sizeof f->gz_etag, "\"%s-gz\"", d);
    f->next = s->files;
    s->files = f;
    s->files_bytes += f->len + f->gz_len;
    atomic_fetch_add_explicit(&f->refs, 1, memory_order_relaxed);   /* the caller's */
    return f;
}

static int asset_current(const mm_server *s, const char *real, const struct stat *st);

#define RECHECK_US 1000000          /* a URL is resolved on disk again after 1 s */

static static_file *static_get(mm_server *s, const char *url, const char *real, const struct stat *st, int vendor)
{
    pthread_mutex_lock(&s->static_lock);
    static_file *f = static_get_locked(s, real, st, vendor);
    if (f) {
        f->current = vendor || asset_current(s, real, st);
        snprintf(f->url, sizeof f->url, "%s", strlen(url) < sizeof f->url ? url : "");
        f->checked_us = now_us();
    }
    pthread_mutex_unlock(&s->static_lock);
    return f;
}

/* The file a URL led to less than RECHECK_US ago, referenced; NULL when
 * it must be resolved again.  A class opening one page asks for the same
 * few files hundreds of times a second: this spares each request the
 * realpath (a system call per path segment) and two stats. */
static static_file *static_recent(mm_server *s, const char *url, int vendor)
{
    static_file *found = NULL;
    long long now = now_us();
    pthread_mutex_lock(&s->static_lock);
    if (!atomic_load(&s->files_stale))
        for (static_file *f = s->files; f && !found; f = f->next)
            if (f->vendor == vendor && f->url[0] && strcmp(f->url, url) == 0 && now - f->checked_us < RECHECK_US) {
                atomic_fetch_add_explicit(&f->refs, 1, memory_order_relaxed);
                found = f;
            }
    pthread_mutex_unlock(&s->static_lock);
    return found;
}

/* ---- the asset version --------------------------------------------------------------- */

typedef struct walk {
    mm_hasher h;
    asset *list;
    int n, cap;
} walk;

static void walk_dir(walk *w, const char *root, const char *rel, int depth)
{
    char dir[PATH_MAX];
    snprintf(dir, sizeof dir, "%s%s", root, rel);
    struct dirent **names;
    int n = depth < 16 ? scandir(dir, &names, NULL, alphasort) : -1;
    for (int i = 0; i < n; i++) {
        const char *nm = names[i]->d_name;
        char r[PATH_MAX], full[PATH_MAX];
        if (nm[0] == '.' || snprintf(r, sizeof r, "%s/%s", rel, nm) >= (int)sizeof r) {
            free(names[i]);
            continue;
        }
        snprintf(full, sizeof full, "%s%s", root, r);
        struct stat st;
        if (stat(full, &st) == 0 && S_ISDIR(st.st_mode)) {
            walk_dir(w, root, r, depth + 1);
        } else if (stat(full, &st) == 0 && S_ISREG(st.st_mode)) {
            mm_hash_part(&w->h, r, strlen(r));
            int fd = open(full, O_RDONLY | O_CLOEXEC);
            char *b = fd >= 0 && st.st_size <= STATIC_FILE_MAX ? read_all(fd, (size_t)st.st_size) : NULL;
            if (fd >= 0)
                close(fd);
            if (b)
                mm_hash_part(&w->h, b, (size_t)st.st_size);
            free(b);
            if (w->n == w->cap) {
                int cap = w->cap ? 2 * w->cap : 64;
                asset *l = realloc(w->list, (size_t)cap * sizeof *l);
                if (l)
                    w->list = l, w->cap = cap;
            }
            if (w->n < w->cap)
                w->list[w->n++] = (asset){strdup(r), st.st_size, st.st_mtim};
        }
        free(names[i]);
    }
    if (n >= 0)
        free(names);
}

static void asset_scan(const char *web_root, const char *vendor_root, char out[32], asset **list, int *n)
{
    char path[PATH_MAX + 32];
    out[0] = '\0';
    snprintf(path, sizeof path, "%s/.asset-version", web_root ? web_root : "");
    FILE *f = web_root ? fopen(path, "r") : NULL;
    walk w = {.list = NULL};
    mm_hash_init(&w.h);
    if (web_root)
        walk_dir(&w, web_root, "", 0);
    for (int i = 0; vendor_root && vendor_packages[i]; i++) {
        snprintf(path, sizeof path, "%s/%s/package.json", vendor_root, vendor_packages[i]);
        FILE *p = fopen(path, "rb");
        char buf[65536];
        size_t k = p ? fread(buf, 1, sizeof buf, p) : 0;
        if (p)
            fclose(p);
        mm_hash_part(&w.h, buf, k);
    }
    mm_hash_final(&w.h, out);
    if (f) {                                   /* the installer's: it wins */
        char v[32] = "";
        if (fgets(v, sizeof v, f)) {
            v[strcspn(v, " \t\r\n")] = '\0';
            if (v[0])
                snprintf(out, 32, "%s", v);
        }
        fclose(f);
    }
    if (list) {
        *list = w.list;
        *n = w.n;
    } else {
        for (int i = 0; i < w.n; i++)
            free(w.list[i].rel);
        free(w.list);
    }
}

void mm_asset_version(const char *web_root, const char *vendor_root, char out[32])
{
    asset_scan(web_root, vendor_root, out, NULL, NULL);
}

static void assets_free(mm_server *s)
{
    for (int i = 0; i < s->n_assets; i++)
        free(s->assets[i].rel);
    free(s->assets);
    s->assets = NULL;
    s->n_assets = 0;
}

/* May this web file be cached for a year under ?v=<version>: is it as the
 * version saw it? */
static int asset_current(const mm_server *s, const char *real, const struct stat *st)
{
    size_t rl = strlen(s->web_real);
    if (strncmp(real, s->web_real, rl) != 0)
        return 0;
    const char *rel = real + rl;
    int lo = 0, hi = s->n_assets - 1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2, c = strcmp(s->assets[mid].rel, rel);
        if (c == 0)
            return s->assets[mid].size == st->st_size && s->assets[mid].mtime.tv_sec == st->st_mtim.tv_sec &&
                   s->assets[mid].mtime.tv_nsec == st->st_mtim.tv_nsec;
        if (c < 0)
            lo = mid + 1;
        else
            hi = mid - 1;
    }
    return 0;
}

static int asset_cmp(const void *a, const void *b)
{
    return strcmp(((const asset *)a)->rel, ((const asset *)b)->rel);
}

/* ---- metrics -------------------------------------------------------------------------- */

static int status_index(int status)
{
    for (int i = 0; i < N_ST - 1; i++)
        if (status_codes[i] == status)
            return i;
    return ST_OTHER;
}

static void count(mm_server *s, int route, int status, size_t bytes)
{
    int r = route >= 0 && route < MAX_ROUTES - 1 ? route : MAX_ROUTES - 1;
    atomic_fetch_add_explicit(&s->m.requests[r][status_index(status)], 1, memory_order_relaxed);
    atomic_fetch_add_explicit(&s->m.bytes_out, bytes, memory_order_relaxed);
}

static void observe_solve(mm_server *s, long long us)
{
    double sec = (double)us * 1e-6;
    int b = 0;
    while (b < N_BUCKETS && sec > solve_buckets[b])
        b++;
    atomic_fetch_add_explicit(&s->m.solve_hist[b], 1, memory_order_relaxed);
    atomic_fetch_add_explicit(&s->m.solve_us_sum, (unsigned long long)(us > 0 ? us : 0), memory_order_relaxed);
    atomic_fetch_add_explicit(&s->m.solves, 1, memory_order_relaxed);
}

/* ---- answering ------------------------------------------------------------------------ */

typedef struct answer {
    int status;
    const char *type;
    const char *body;
    size_t len;
    MHD_ContentReaderFreeCallback free_fn;   /* with free_cls, once the response is gone */
    void *free_cls;
    const char *etag;                        /* NULL: none */
    const char *cache_control;
    int gzip, vary;
    const char *timing;                      /* Server-Timing */
    const char *allow;
} answer;

static const char *route_name(int i);

static void log_line(mm_server *s, req *r, const char *method, const char *url, int status, size_t bytes,
                     const char *how)
{
    if (s->quiet)
        return;
    char m[48], u[700], line[900];
    mm_log_escape(method, m, sizeof m);
    mm_log_escape(url, u, sizeof u);
    int n = snprintf(line, sizeof line, "%s %s %d %zu %lldus %s\n", m, u, status, bytes, now_us() - r->t0,
                     how ? how : "-");
    if (n > 0)
        (void)!write(2, line, (size_t)n < sizeof line ? (size_t)n : sizeof line - 1);
}

static enum MHD_Result send_answer(req *r, const char *method, const char *url, const answer *a,
                                   const char *how)
{
    struct MHD_Response *resp;
    if (a->free_fn)
        resp = MHD_create_response_from_buffer_with_free_callback_cls(a->len, (void *)(uintptr_t)a->body,
                                                                      a->free_fn, a->free_cls);
    else
        resp = MHD_create_response_from_buffer(a->len, (void *)(uintptr_t)a->body, MHD_RESPMEM_PERSISTENT);
    if (!resp) {
        if (a->free_fn)
            a->free_fn(a->free_cls);
        return MHD_NO;
    }
    if (a->type)
        MHD_add_response_header(resp, MHD_HTTP_HEADER_CONTENT_TYPE, a->type);
    MHD_add_response_header(resp, "X-Content-Type-Options", "nosniff");
    if (a->etag)
        MHD_add_response_header(resp, MHD_HTTP_HEADER_ETAG, a->etag);
    if (a->cache_control)
        MHD_add_response_header(resp, MHD_HTTP_HEADER_CACHE_CONTROL, a->cache_control);
    if (a->gzip)
        MHD_add_response_header(resp, MHD_HTTP_HEADER_CONTENT_ENCODING, "gzip");
    if (a->vary)
        MHD_add_response_header(resp, MHD_HTTP_HEADER_VARY, "Accept-Encoding");
    if (a->allow)
        MHD_add_response_header(resp, MHD_HTTP_HEADER_ALLOW, a->allow);
    char timing[160];
    long long us = now_us() - r->t0;           /* milliseconds to 3 decimals, without printf's floating point */
    snprintf(timing, sizeof timing, "%s%stotal;dur=%lld.%03lld", a->timing ? a->timing : "",
             a->timing ? ", " : "", us / 1000, us % 1000);
    MHD_add_response_header(resp, "Server-Timing", timing);
    enum MHD_Result ret = MHD_queue_response(r->c, (unsigned)a->status, resp);
    MHD_destroy_response(resp);
    r->answered = 1;
    count(r->s, r->route, a->status, a->len);
    log_line(r->s, r, method, url, a->status, a->len, how);
    return ret;
}

static void free_text(void *p) { free(p); }

/* An error document (malloc'd, NULL without memory) and its HTTP status. */
static char *error_doc(int code, const char *param, const char *msg, int *status, size_t *len)
{
    mm_buf b;
    mm_error err;
    mm_buf_init(&b, 4096);
    mm_error_set(&err, code, param, "%s", msg);
    *status = mm_api_error(&b, &err);
    return mm_buf_take(&b, len);
}

static enum MHD_Result send_error(req *r, const char *method, const char *url, int code, const char *param,
                                  const char *msg, const char *allow)
{
    size_t len;
    int status;
    char *text = error_doc(code, param, msg, &status, &len);
    if (!text)
        return MHD_NO;
    if (code == MM_EBUSY)
        atomic_fetch_add_explicit(&r->s->m.busy, 1, memory_order_relaxed);
    answer a = {.status = status, .type = "application/json", .body = text, .len = len, .free_fn = free_text,
                .free_cls = text, .cache_control = "no-store", .allow = allow};
    return send_answer(r, method, url, &a, "error");
}

static enum MHD_Result send_not_modified(req *r, const char *method, const char *url, const char *etag,
                                         const char *cache_control, int vary)
{
    atomic_fetch_add_explicit(&r->s->m.revalidated, 1, memory_order_relaxed);
    answer a = {.status = 304, .body = "", .len = 0, .etag = etag, .cache_control = cache_control,
                .vary = vary, .timing = "cache;desc=\"revalidated\""};
    return send_answer(r, method, url, &a, "304");
}

static const char *header(req *r, const char *name)
{
    return MHD_lookup_connection_value(r->c, MHD_HEADER_KIND, name);
}

static void site_unref_cb(void *cls) { site_unref(cls); }

/* A document of the site (health, catalog, metadata, OpenAPI): 304, or the
 * text (gzip when accepted), the site kept alive while it is sent. */
static enum MHD_Result send_doc(req *r, const char *method, const char *url, const zdoc *z)
{
    int gz = z->gz && mm_accepts_gzip(header(r, MHD_HTTP_HEADER_ACCEPT_ENCODING));
    if (mm_etag_matches(header(r, MHD_HTTP_HEADER_IF_NONE_MATCH), z->doc->etag))
        return send_not_modified(r, method, url, gz ? z->gz_etag : z->doc->etag, "no-cache", z->gz != NULL);
    atomic_fetch_add_explicit(&r->site->refs, 1, memory_order_relaxed);
    answer a = {.status = 200, .type = "application/json", .body = gz ? z->gz : z->doc->text,
                .len = gz ? z->gz_len : z->doc->len, .free_fn = site_unref_cb, .free_cls = r->site,
                .etag = gz ? z->gz_etag : z->doc->etag, .cache_control = "no-cache", .gzip = gz,
                .vary = z->gz != NULL, .timing = "cache;desc=\"document\""};
    return send_answer(r, method, url, &a, "doc");
}

static void entry_unref_cb(void *cls) { mm_cache_unref(cls); }

/* An answer from the cache; takes over the reference to e. */
static enum MHD_Result send_entry(req *r, const char *method, const char *url, mm_entry *e, const char *how)
{
    int gz = 0;
    char *gz_body = NULL;
    size_t gz_len = 0;
    if (r->want_gz && e->len >= GZ_MIN) {
        mm_cache_get_gz(r->s->cache, e, &gz_body, &gz_len);
        if (!gz_body && e->status == 200) {  /* first asked compressed: made once */
            char *z;
            size_t zl;
            if (gzip_bytes(e->body, e->len, GZ_ANSWER, &z, &zl) == 0)
                mm_cache_set_gz(r->s->cache, e, z, zl);
            mm_cache_get_gz(r->s->cache, e, &gz_body, &gz_len);
        }
        gz = gz_body != NULL;
    }
    char etag[MM_ETAG_SIZE + 4], timing[96];
    size_t el = strlen(e->etag);               /* "abc" -> "abc-gz": the same with -gz before the quote */
    memcpy(etag, e->etag, el + 1);
    if (gz && el >= 2 && el + 3 < sizeof etag)
        memcpy(etag + el - 1, "-gz\"", 5);
    if (strcmp(how, "hit") == 0)
        snprintf(timing, sizeof timing, "cache;desc=\"hit\"");
    else
        snprintf(timing, sizeof timing, "cache;desc=\"%s\", solve;dur=%.3f", how, (double)e->solve_us * 1e-3);
    int ok = (e->status == 200 || mm_http_status(MM_ESINGULAR) == e->status) && !r->task_type;
    const char *type = r->task_type && e->status == 200 ? r->task_type : "application/json";
    r->task_type = NULL;
    answer a = {.status = e->status, .type = type, .body = gz ? gz_body : e->body,
                .len = gz ? gz_len : e->len, .free_fn = entry_unref_cb, .free_cls = e,
                .etag = ok ? etag : NULL, .cache_control = ok ? "no-cache" : "no-store", .gzip = gz,
                .vary = 1, .timing = timing};
    return send_answer(r, method, url, &a, how);
}

/* ---- the solve workers ------------------------------------------------------------------ */

static void wake(void *who)
{
    req *r = who;
    MHD_resume_connection(r->c);
}

static void run_task(mm_server *s, job *j)
{
    mm_buf out;
    mm_buf_init(&out, j->task == TASK_CSV ? 64u << 20 : MM_ANSWER_MAX);
    long long t0 = now_us();
    int status = j->task == TASK_CHECK ? mm_assign_check_json(j->asg, j->text, j->text_len, &out)
                 : j->task == TASK_KEY ? mm_assign_key_json(j->asg, j->text, &out)
                                       : mm_assign_csv(j->asg, j->text, j->text_len, &out);
    size_t len = 0;
    char *body = out.failed ? NULL : mm_buf_take(&out, &len);
    if (!body) {
        body = strdup("{\"error\":{\"code\":\"too_large\",\"param\":null,\"message\":\"the answer is too large\"}}");
        len = body ? strlen(body) : 0;
        status = 413;
    }
    mm_cache_fill(s->cache, j->entry, status, body, len, NULL, 0, now_us() - t0, 0, wake);
    mm_buf_free(&out);
    free(j->text);
    mm_cache_unref(j->entry);
    site_unref(j->site);
    free(j);
}

#define OUT_KEEP ((size_t)1 << 20)   /* a worker keeps its answer buffer up to this size */

/* A copy of the n bytes at p in a block of its own size, NUL-terminated. */
static char *dup_exact(const char *p, size_t n)
{
    char *d = malloc(n + 1);
    if (d) {
        memcpy(d, p, n);
        d[n] = '\0';
    }
    return d;
}

/* The weight of the exercise id (mm_light.h), made at its first solve;
 * NULL when the table is full or the id too long.  Read without the lock:
 * a slot is written once, under the lock, and then published by its flag. */
static atomic_int *light_weight(mm_server *s, const char *id)
{
    size_t n = strlen(id);
    if (n >= sizeof s->lights[0].id)
        return NULL;
    uint64_t h = mm_hash_fnv1a(id, n);
    for (int locked = 0; locked < 2; locked++) {
        if (locked)
            pthread_mutex_lock(&s->light_lock);
        for (int k = 0; k < LIGHT_SLOTS; k++) {
            light *l = &s->lights[(h + (uint64_t)k) % LIGHT_SLOTS];
            if (!atomic_load_explicit(&l->ready, memory_order_acquire)) {
                if (!locked)
                    break;                     /* not there: again under the lock */
                memcpy(l->id, id, n + 1);
                atomic_init(&l->weight, mm_light_start(s->light_us));
                atomic_store_explicit(&l->ready, 1, memory_order_release);
            }
            if (strcmp(l->id, id) == 0) {
                if (locked)
                    pthread_mutex_unlock(&s->light_lock);
                return &l->weight;
            }
        }
        if (locked)
            pthread_mutex_unlock(&s->light_lock);
    }
    return NULL;
}

/* this thread's CPU time: a solve's weight, not the time it waited for a core */
static long long thread_cpu_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (long long)ts.tv_sec * 1000000 + ts.tv_nsec / 1000;
}

/* Solve sv, write its answer (and its gzip form when wanted) and fill the
 * pending entry e with it, which wakes whoever waits for it; how long that
 * took goes to weight.  out: the thread's own buffer, written into and kept
 * from one solve to the next; what goes into the cache is a copy of the
 * answer's own size.  A fresh buffer per answer (and one for the
 * compressed form) was a block over malloc's mmap threshold each time,
 * mapped, faulted in page by page and unmapped on eviction (see
 * mm_result_keep_blocks). */
static void make_answer(mm_server *s, mm_solve *sv, mm_entry *e, int want_gz, mm_buf *out, atomic_int *weight)
{
    long long t0 = thread_cpu_us();
    mm_buf_reset(out);
    if (sv->rc == MM_OK)
        mm_api_run(sv);
    int status = mm_api_write(sv, out);
    if (sv->ran)
        observe_solve(s, sv->elapsed_us);
    size_t len = out->len;
    char *body = out->failed || !out->p ? NULL : dup_exact(out->p, len);
    if (out->cap > OUT_KEEP)
        mm_buf_free(out);
    if (!body) {                           /* no memory even for the error */
        body = strdup("{\"error\":{\"code\":\"internal\",\"param\":null,\"message\":\"out of memory\"}}");
        len = body ? strlen(body) : 0;
        status = 500;
    }
    char *gz = NULL;
    size_t gz_len = 0;
    if (want_gz && status == 200 && len >= GZ_MIN && gzip_bytes(body, len, GZ_ANSWER, &gz, &gz_len) != 0)
        gz = NULL, gz_len = 0;
    int keep = status == 200 || status == mm_http_status(MM_ESINGULAR);
    mm_light_note(weight, thread_cpu_us() - t0);
    mm_cache_fill(s->cache, e, status, body, len, gz, gz_len, sv->elapsed_us, keep, wake);
}

static void run_job(mm_server *s, job *j, mm_buf *out)
{
    if (j->task != TASK_NONE) {
        run_task(s, j);
        return;
    }
    make_answer(s, j->solve, j->entry, j->want_gz, out, j->weight);
    mm_solve_free(j->solve);
    free(j->solve);
    mm_cache_unref(j->entry);
    site_unref(j->site);
    free(j);
}

/* This event thread's kit, ready for light solves; NULL without memory */
static kit *kit_for_solving(void)
{
    kit *k = kit_get();
    if (k && !k->solving) {
        mm_buf_init(&k->out, MM_ANSWER_MAX);
        mm_result_keep_blocks(1);
        k->solving = 1;
    }
    return k;
}

static void *worker_main(void *arg)
{
    mm_server *s = arg;
    mm_buf out;
    mm_buf_init(&out, MM_ANSWER_MAX);
    mm_result_keep_blocks(1);
    pthread_mutex_lock(&s->q_lock);
    for (;;) {
        while (s->q_len == 0 && !s->stopping)
            pthread_cond_wait(&s->q_cond, &s->q_lock);
        if (s->q_len == 0 && s->stopping)
            break;
        job *j = s->queue[s->q_head];
        s->q_head = (s->q_head + 1) % s->q_cap;
        s->q_len--;
        pthread_mutex_unlock(&s->q_lock);
        run_job(s, j, &out);
        pthread_mutex_lock(&s->q_lock);
    }
    pthread_mutex_unlock(&s->q_lock);
    mm_result_keep_blocks(0);
    mm_buf_free(&out);
    kit_end();
    return NULL;
}

static int enqueue(mm_server *s, job *j)
{
    pthread_mutex_lock(&s->q_lock);
    if (s->q_len == s->q_cap || s->stopping) {
        pthread_mutex_unlock(&s->q_lock);
        return -1;
    }
    s->queue[(s->q_head + s->q_len) % s->q_cap] = j;
    s->q_len++;
    pthread_cond_signal(&s->q_cond);
    pthread_mutex_unlock(&s->q_lock);
    return 0;
}

static int queue_full(mm_server *s)
{
    pthread_mutex_lock(&s->q_lock);
    int full = s->q_len >= s->q_cap;
    pthread_mutex_unlock(&s->q_lock);
    return full;
}

/* ---- routes ------------------------------------------------------------------------------ */

typedef struct ctx {
    req *r;
    const char *method, *url;      /* url: the path after the base path */
    const char *full_url;          /* for the log */
    int head;
    char id[96];                   /* {id} or {name} of the pattern */
} ctx;

typedef enum MHD_Result (*handler)(ctx *x);

static enum MHD_Result h_health(ctx *x) { return send_doc(x->r, x->method, x->full_url, &x->r->site->health); }
static enum MHD_Result h_catalog(ctx *x) { return send_doc(x->r, x->method, x->full_url, &x->r->site->catalog); }
static enum MHD_Result h_course(ctx *x) { return send_doc(x->r, x->method, x->full_url, &x->r->site->course); }
static enum MHD_Result h_openapi(ctx *x) { return send_doc(x->r, x->method, x->full_url, &x->r->site->openapi); }
static enum MHD_Result h_metrics(ctx *x);
static enum MHD_Result h_meta(ctx *x);
static enum MHD_Result h_solve(ctx *x);
static enum MHD_Result h_script(ctx *x);
static enum MHD_Result h_assignments(ctx *x);
static enum MHD_Result h_variant(ctx *x);
static enum MHD_Result h_check(ctx *x);
static enum MHD_Result h_key(ctx *x);
static enum MHD_Result h_csv(ctx *x);
static enum MHD_Result h_vendor(ctx *x);
static enum MHD_Result h_static(ctx *x);

/* The route table, tried in order.  A pattern's {name} matches one path
 * segment (x->id); a final "*" matches the rest.  A path that matches with
 * another method gets 405 with the route's methods in Allow.  A new route
 * goes above the static catch-all (the last row) and into mm_openapi.c. */
typedef struct route {
    const char *methods;           /* "GET HEAD" or "GET HEAD POST" */
    const char *pattern;
    handler fn;
    const char *name;              /* for /api/metrics */
} route;

static const route routes[] = {
    {"GET HEAD", "/api/health", h_health, "health"},
    {"GET HEAD", "/api/exercises", h_catalog, "catalog"},
    {"GET HEAD", "/api/course", h_course, "course"},
    {"GET HEAD", "/api/openapi.json", h_openapi, "openapi"},
    {"GET HEAD", "/api/metrics", h_metrics, "metrics"},
    {"GET HEAD", "/api/exercises/{id}", h_meta, "metadata"},
    {"GET HEAD", "/api/exercises/{id}/script.m", h_script, "script"},
    {"GET HEAD", "/api/assignments", h_assignments, "assignments"},
    {"GET HEAD", "/api/assignments/{id}/variant", h_variant, "variant"},
    {"POST", "/api/assignments/{id}/check", h_check, "check"},
    {"GET HEAD", "/api/assignments/{id}/key", h_key, "key"},
    {"POST", "/api/assignments/{id}/csv", h_csv, "csv"},
    {"GET HEAD POST", "/api/exercises/{id}/solve", h_solve, "solve"},
    {"GET HEAD", "/vendor/*", h_vendor, "vendor"},
    {"GET HEAD", "/*", h_static, "static"},
};
#define N_ROUTES (int)(sizeof routes / sizeof routes[0])
_Static_assert(sizeof routes / sizeof routes[0] < MAX_ROUTES, "MAX_ROUTES must exceed the routes");

static const char *route_name(int i) { return i >= 0 && i < N_ROUTES ? routes[i].name : "other"; }

const mm_route_info *mm_http_routes(int *n)
{
    static mm_route_info info[N_ROUTES];
    for (int i = 0; i < N_ROUTES; i++)
        info[i] = (mm_route_info){routes[i].methods, routes[i].pattern};
    *n = N_ROUTES;
    return info;
}

/* Does path match pattern?  Fills id from a {..} segment. */
static int match(const char *pattern, const char *path, char *id, size_t id_size)
{
    const char *p = pattern, *u = path;
    while (*p) {
        if (p[0] == '*')
            return 1;
        if (p[0] == '{') {
            const char *close = strchr(p, '}');
            const char *end = u;
            while (*end && *end != '/')
                end++;
            size_t n = (size_t)(end - u);
            if (n == 0 || n >= id_size)
                return n >= id_size ? 2 : 0;     /* 2: too long an id, not found */
            memcpy(id, u, n);
            id[n] = '\0';
            u = end;
            p = close + 1;
            continue;
        }
        if (*p != *u)
            return 0;
        p++, u++;
    }
    return *u == '\0';
}

static int method_in(const char *set, const char *method)
{
    size_t n = strlen(method);
    for (const char *s = set; *s;) {
        const char *sp = strchr(s, ' ');
        size_t l = sp ? (size_t)(sp - s) : strlen(s);
        if (l == n && strncmp(s, method, n) == 0)
            return 1;
        s += l + (sp ? 1 : 0);
    }
    return 0;
}

static void allow_text(const char *set, char *out, size_t size)
{
    size_t k = 0;
    for (const char *s = set; *s && k + 3 < size; s++)
        k += (size_t)snprintf(out + k, size - k, *s == ' ' ? ", " : "%c", *s);
}

/* 301 to the base path with its slash (the query is dropped: a page's own). */
static enum MHD_Result send_redirect(req *r, const char *method, const char *url, const char *base)
{
    char to[300];
    snprintf(to, sizeof to, "%s/", base);
    struct MHD_Response *resp = MHD_create_response_from_buffer(0, (void *)"", MHD_RESPMEM_PERSISTENT);
    if (!resp)
        return MHD_NO;
    MHD_add_response_header(resp, MHD_HTTP_HEADER_LOCATION, to);
    MHD_add_response_header(resp, MHD_HTTP_HEADER_CACHE_CONTROL, "no-cache");
    enum MHD_Result ret = MHD_queue_response(r->c, MHD_HTTP_MOVED_PERMANENTLY, resp);
    MHD_destroy_response(resp);
    r->answered = 1;
    count(r->s, r->route, 301, 0);
    log_line(r->s, r, method, url, 301, 0, "redirect");
    return ret;
}

static enum MHD_Result route_request(req *r, const char *method, const char *full_url)
{
    ctx x = {.r = r, .method = method, .full_url = full_url};
    const char *url = full_url;
    site *st = r->site;
    if (st->base_len) {                      /* the course lives under a base path */
        if (strncmp(url, st->base, st->base_len) != 0 || (url[st->base_len] && url[st->base_len] != '/'))
            return send_error(r, method, full_url, MM_ENOTFOUND, "", "no such page", NULL);
        url += st->base_len;
        if (!*url)                           /* "/mech": the page's relative URLs need "/mech/" */
            return send_redirect(r, method, full_url, st->base);
    }
    x.url = url;
    x.head = strcmp(method, "HEAD") == 0;
    for (int i = 0; i < N_ROUTES; i++) {
        int m = match(routes[i].pattern, url, x.id, sizeof x.id);
        if (!m)
            continue;
        if (strcmp(routes[i].pattern, "/*") == 0 && strncmp(url, "/api/", 5) == 0)
            break;                           /* no static file under /api/ */
        r->route = i;
        if (m == 2)
            return send_error(r, method, full_url, MM_ENOTFOUND, "", "no such exercise", NULL);
        if (!method_in(routes[i].methods, method)) {
            char allow[64], msg[96];
            allow_text(routes[i].methods, allow, sizeof allow);
            snprintf(msg, sizeof msg, "%s answers %s only", strncmp(url, "/api/", 5) ? "a static page" : "this route",
                     allow);
            return send_error(r, method, full_url, MM_EMETHOD, "", msg, allow);
        }
        return routes[i].fn(&x);
    }
    return send_error(r, method, full_url, MM_ENOTFOUND, "", "no such route; see /api/exercises", NULL);
}

static enum MHD_Result h_meta(ctx *x)
{
    site *st = x->r->site;
    const mm_course *c = mm_api_course(st->api);
    for (int i = 0; i < st->n_meta; i++)
        if (strcmp(mm_course_exercise(c, i)->id, x->id) == 0)
            return send_doc(x->r, x->method, x->full_url, &st->meta[i]);
    char msg[128];
    snprintf(msg, sizeof msg, "no exercise '%.60s'; GET /api/exercises lists them", x->id);
    return send_error(x->r, x->method, x->full_url, MM_ENOTFOUND, "", msg, NULL);
}

/* query arguments */
typedef struct args {
    mm_input in[MM_MAX_PARAMS];
    int n;
    size_t bytes;
    int too_many, has_nul;
} args;

static enum MHD_Result collect_arg(void *cls, enum MHD_ValueKind kind, const char *key, size_t key_size,
                                   const char *value, size_t value_size)
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

/* Resolve a GET's query into sv (the failure, if any, in sv->rc/err). */
static void resolve_query(req *r, mm_solve *sv)
{
    args a = {0};
    MHD_get_connection_values_n(r->c, MHD_GET_ARGUMENT_KIND, collect_arg, &a);
    if (a.bytes > MM_QUERY_MAX)
        mm_error_set(&sv->err, MM_ETOOBIG, "", "the query is too long (at most 16 KiB); send large values by POST");
    else if (a.has_nul)
        mm_error_set(&sv->err, MM_EVALUE, "", "the query contains a NUL byte");
    else if (a.too_many)
        mm_error_set(&sv->err, MM_EPARAM, "", "too many parameters; %s has %d", sv->ex->id, sv->ex->n_params);
    if (sv->err.code)
        sv->rc = sv->err.code;
    else
        mm_api_resolve(sv, a.in, a.n);
}

static enum MHD_Result h_solve(ctx *x)
{
    req *r = x->r;
    mm_server *s = r->s;
    const mm_exercise *ex = mm_api_exercise(r->site->api, x->id);
    if (!ex) {
        char msg[128];
        snprintf(msg, sizeof msg, "no exercise '%.60s'; GET /api/exercises lists them", x->id);
        return send_error(r, x->method, x->full_url, MM_ENOTFOUND, "", msg, NULL);
    }
    mm_solve *sv = malloc(sizeof *sv);
    if (!sv)
        return MHD_NO;
    mm_solve_init(sv, ex);
    if (strcmp(x->method, "POST") == 0) {
        mm_api_resolve_json(sv, r->body.p ? r->body.p : "", r->body.len);
    } else {
        resolve_query(r, sv);
    }
    if (sv->rc != MM_OK) {                   /* a 400: answered now, never cached */
        mm_buf out;
        mm_buf_init(&out, 1 << 16);
        int status = mm_api_write(sv, &out);
        size_t len;
        char *text = mm_buf_take(&out, &len);
        mm_solve_free(sv);
        free(sv);
        if (!text)
            return MHD_NO;
        answer a = {.status = status, .type = "application/json", .body = text, .len = len,
                    .free_fn = free_text, .free_cls = text, .cache_control = "no-store"};
        return send_answer(r, x->method, x->full_url, &a, "refused");
    }

    /* the validator first: a matching ETag needs no answer at all (hashed
     * only when asked: an answer carries its entry's own copy) */
    const char *inm = header(r, MHD_HTTP_HEADER_IF_NONE_MATCH);
    if (inm) {
        char etag[MM_ETAG_SIZE];
        mm_api_answer_etag(sv->key.p, sv->key.len, etag);
        if (mm_etag_matches(inm, etag)) {
            mm_solve_free(sv);
            free(sv);
            return send_not_modified(r, x->method, x->full_url, etag, "no-cache", 1);
        }
    }
    mm_entry *e = mm_cache_lookup(s->cache, sv->key.p, sv->key.len);
    if (e) {
        mm_solve_free(sv);
        free(sv);
        return send_entry(r, x->method, x->full_url, e, "hit");
    }
    atomic_int *weight = s->light_us > 0 ? light_weight(s, ex->id) : NULL;
    kit *it;
    if (mm_light_now(weight, s->light_us) && (it = kit_for_solving()) != NULL) {
        /* light: made here and now, unless another request is making it */
        int rc = mm_cache_get(s->cache, sv->key.p, sv->key.len, NULL, &e);
        if (rc == MM_CACHE_MISS) {
            make_answer(s, sv, e, r->want_gz, &it->out, weight);
            atomic_fetch_add_explicit(&s->m.light_solves, 1, memory_order_relaxed);
        }
        if (rc == MM_CACHE_MISS || rc == MM_CACHE_HIT) {
            mm_solve_free(sv);
            free(sv);
            return send_entry(r, x->method, x->full_url, e, rc == MM_CACHE_HIT ? "hit" : "miss");
        }
    }
    if (queue_full(s)) {
        mm_solve_free(sv);
        free(sv);
        return send_error(r, x->method, x->full_url, MM_EBUSY, "", "busy", NULL);
    }

    /* not there: wait for it, made by this request or by one already at it */
    MHD_suspend_connection(r->c);
    int rc = mm_cache_get(s->cache, sv->key.p, sv->key.len, r, &e);
    if (rc < 0) {
        MHD_resume_connection(r->c);
        mm_solve_free(sv);
        free(sv);
        return MHD_NO;
    }
    r->entry = e;
    r->state = R_WAIT;
    if (rc == MM_CACHE_HIT) {                /* filled between the lookup and now */
        mm_solve_free(sv);
        free(sv);
        MHD_resume_connection(r->c);
        return MHD_YES;
    }
    if (rc == MM_CACHE_WAIT) {
        r->shared = 1;
        mm_solve_free(sv);
        free(sv);
        return MHD_YES;
    }
    job *j = malloc(sizeof *j);
    if (j) {
        atomic_fetch_add_explicit(&r->site->refs, 1, memory_order_relaxed);
        atomic_fetch_add_explicit(&e->refs, 1, memory_order_relaxed);
        *j = (job){.solve = sv, .entry = e, .site = r->site, .want_gz = r->want_gz, .weight = weight};
    }
    if (!j || enqueue(s, j) != 0) {          /* no room after all: the waiters get 503 */
        if (j) {
            site_unref(j->site);
            mm_cache_unref(j->entry);
            free(j);
        }
        mm_error_set(&sv->err, MM_EBUSY, "", "busy");
        sv->rc = MM_EBUSY;
        mm_buf out;
        mm_buf_init(&out, 4096);
        int status = mm_api_write(sv, &out);
        size_t len;
        char *text = mm_buf_take(&out, &len);
        mm_solve_free(sv);
        free(sv);
        mm_cache_fill(s->cache, e, status, text, text ? len : 0, NULL, 0, 0, 0, wake);
    }
    return MHD_YES;
}

/* ---- scripts and assignments ---------------------------------------------------------- */

static enum MHD_Result send_text(ctx *x, int status, const char *type, mm_buf *b, const char *etag,
                                 const char *how)
{
    size_t len;
    char *text = mm_buf_take(b, &len);
    if (!text)
        return send_error(x->r, x->method, x->full_url, MM_ETOOBIG, "", "the answer is too large", NULL);
    answer a = {.status = status, .type = type, .body = text, .len = len, .free_fn = free_text,
                .free_cls = text, .etag = etag, .cache_control = etag ? "no-cache" : "no-store"};
    return send_answer(x->r, x->method, x->full_url, &a, how);
}

/* GET /api/exercises/{id}/script.m?...: the parameters resolved as for a
 * solve, then the Octave script instead of the solve (no solve runs). */
static enum MHD_Result h_script(ctx *x)
{
    req *r = x->r;
    const mm_exercise *ex = mm_api_exercise(r->site->api, x->id);
    const char *body = ex ? mm_api_script_body(r->site->api, x->id) : NULL;
    char msg[160];
    if (!ex || !body) {
        snprintf(msg, sizeof msg, ex ? "%.60s has no Octave script yet" : "no exercise '%.60s'; GET /api/exercises lists them",
                 x->id);
        return send_error(r, x->method, x->full_url, MM_ENOTFOUND, "", msg, NULL);
    }
    mm_solve sv;
    mm_solve_init(&sv, ex);
    resolve_query(r, &sv);
    mm_buf out;
    mm_buf_init(&out, 1u << 22);
    enum MHD_Result ret;
    if (sv.rc != MM_OK) {
        int status = mm_api_write(&sv, &out);
        ret = send_text(x, status, "application/json", &out, NULL, "refused");
    } else {
        char etag[MM_ETAG_SIZE + 8];
        mm_buf_put(&sv.key, "#script.m", 9);
        mm_api_answer_etag(sv.key.p, sv.key.len, etag);
        const char *q = memchr(sv.key.p, '?', sv.key.len);
        sv.key.p[sv.key.len - 9] = '\0';       /* the canonical query again */
        if (mm_etag_matches(header(r, MHD_HTTP_HEADER_IF_NONE_MATCH), etag))
            ret = send_not_modified(r, x->method, x->full_url, etag, "no-cache", 0);
        else if (mm_script_write(ex, sv.vals, body, q ? q + 1 : "", MM_VERSION, &out) != MM_OK)
            ret = send_error(r, x->method, x->full_url, MM_ETOOBIG, "", "the script is too large", NULL);
        else
            ret = send_text(x, 200, "text/plain; charset=utf-8", &out, etag, "script");
    }
    mm_buf_free(&out);
    mm_solve_free(&sv);
    return ret;
}

static enum MHD_Result h_assignments(ctx *x)
{
    return send_doc(x->r, x->method, x->full_url, &x->r->site->assignments);
}

static const mm_assignment *find_assignment(ctx *x)
{
    return mm_api_assignment(x->r->site->api, x->id);
}

static enum MHD_Result no_assignment(ctx *x)
{
    char msg[128];
    snprintf(msg, sizeof msg, "no assignment '%.60s'; GET /api/assignments lists them", x->id);
    return send_error(x->r, x->method, x->full_url, MM_ENOTFOUND, "", msg, NULL);
}

static enum MHD_Result h_variant(ctx *x)
{
    const mm_assignment *a = find_assignment(x);
    if (!a)
        return no_assignment(x);
    const char *student = MHD_lookup_connection_value(x->r->c, MHD_GET_ARGUMENT_KIND, "student");
    mm_buf out;
    mm_buf_init(&out, 1u << 20);
    int status = mm_assign_variant_json(a, student ? student : "", &out);
    return send_text(x, status, "application/json", &out, NULL, "variant");
}

/* A task for the workers: the request waits on a private entry. */
static enum MHD_Result start_task(ctx *x, int task, const mm_assignment *a, char *text, size_t len,
                                  const char *type)
{
    static atomic_ullong serial;
    req *r = x->r;
    mm_server *s = r->s;
    if (!text)
        return MHD_NO;
    if (queue_full(s)) {
        free(text);
        return send_error(r, x->method, x->full_url, MM_EBUSY, "", "busy", NULL);
    }
    char key[48];
    int kl = snprintf(key, sizeof key, "\001task %llu", atomic_fetch_add(&serial, 1));
    mm_entry *e = NULL;
    MHD_suspend_connection(r->c);
    if (mm_cache_get(s->cache, key, (size_t)kl, r, &e) != MM_CACHE_MISS) {   /* only out of memory */
        MHD_resume_connection(r->c);
        mm_cache_unref(e);
        free(text);
        return MHD_NO;
    }
    r->entry = e;
    r->state = R_WAIT;
    r->task_type = type;
    job *j = malloc(sizeof *j);
    if (j) {
        atomic_fetch_add_explicit(&r->site->refs, 1, memory_order_relaxed);
        atomic_fetch_add_explicit(&e->refs, 1, memory_order_relaxed);
        *j = (job){.entry = e, .site = r->site, .task = task, .asg = a, .text = text, .text_len = len};
    }
    if (!j || enqueue(s, j) != 0) {          /* no room after all: 503 */
        if (j) {
            site_unref(j->site);
            mm_cache_unref(j->entry);
            free(j);
        }
        free(text);
        int status;
        size_t bl = 0;
        char *body = error_doc(MM_EBUSY, "", "busy", &status, &bl);
        mm_cache_fill(s->cache, e, status, body, body ? bl : 0, NULL, 0, 0, 0, wake);
    }
    return MHD_YES;
}

static char *copy_body(req *r, size_t *len)
{
    *len = r->body.len;
    char *t = malloc(r->body.len + 1);
    if (t) {
        if (r->body.len)
            memcpy(t, r->body.p, r->body.len);
        t[r->body.len] = '\0';
    }
    return t;
}

static enum MHD_Result h_check(ctx *x)
{
    const mm_assignment *a = find_assignment(x);
    if (!a)
        return no_assignment(x);
    size_t len;
    char *t = copy_body(x->r, &len);
    return start_task(x, TASK_CHECK, a, t, len, "application/json");
}

/* The instructor's routes need the assignment's instructor_key as ?key=. */
static int key_ok(ctx *x, const mm_assignment *a, const char **why)
{
    const char *want = mm_assign_key(a);
    const char *got = MHD_lookup_connection_value(x->r->c, MHD_GET_ARGUMENT_KIND, "key");
    if (!want) {
        *why = "this assignment has no \"instructor_key\" in the course file, so its key and class sheet are off";
        return 0;
    }
    size_t n = strlen(want), m = got ? strlen(got) : 0;
    unsigned diff = (unsigned)(n != m);
    for (size_t i = 0; i < n; i++)          /* the same time for every wrong key */
        diff |= (unsigned char)want[i] ^ (unsigned char)(i < m ? got[i] : 0);
    *why = "the instructor key (?key=) is missing or wrong";
    return diff == 0;
}

static enum MHD_Result h_key(ctx *x)
{
    const mm_assignment *a = find_assignment(x);
    if (!a)
        return no_assignment(x);
    const char *why;
    if (!key_ok(x, a, &why))
        return send_error(x->r, x->method, x->full_url, MM_EFORBIDDEN, "key", why, NULL);
    const char *student = MHD_lookup_connection_value(x->r->c, MHD_GET_ARGUMENT_KIND, "student");
    char *t = strdup(student ? student : "");
    return start_task(x, TASK_KEY, a, t, t ? strlen(t) : 0, "application/json");
}

static enum MHD_Result h_csv(ctx *x)
{
    const mm_assignment *a = find_assignment(x);
    if (!a)
        return no_assignment(x);
    const char *why;
    if (!key_ok(x, a, &why))
        return send_error(x->r, x->method, x->full_url, MM_EFORBIDDEN, "key", why, NULL);
    size_t len;
    char *t = copy_body(x->r, &len);
    return start_task(x, TASK_CSV, a, t, len, "text/csv; charset=utf-8");
}


static enum MHD_Result send_file(ctx *x, const char *root, const char *path, int vendor)
{
    req *r = x->r;
    mm_server *s = r->s;
    char real[PATH_MAX];
    struct stat st;
    const char *v = MHD_lookup_connection_value(r->c, MHD_GET_ARGUMENT_KIND, "v");
    static_file *f = static_recent(s, path, vendor);
    if (!f) {
        if (!root[0] || mm_static_resolve(root, path, real, sizeof real) != MM_OK || stat(real, &st) != 0)
            return send_error(r, x->method, x->full_url, MM_ENOTFOUND, "", "no such page", NULL);
        f = static_get(s, path, real, &st, vendor);
    }
    int versioned = v && strcmp(v, s->asset_version) == 0 && f && f->current;
    const char *cc = versioned ? YEAR_CACHE : "no-cache";
    if (!f) {                                /* too large to keep: from disk */
        int fd = open(real, O_RDONLY | O_CLOEXEC);
        if (fd < 0)
            return send_error(r, x->method, x->full_url, MM_ENOTFOUND, "", "no such page", NULL);
        struct MHD_Response *resp = MHD_create_response_from_fd((size_t)st.st_size, fd);
        if (!resp) {
            close(fd);
            return MHD_NO;
        }
        MHD_add_response_header(resp, MHD_HTTP_HEADER_CONTENT_TYPE, mm_mime_type(real));
        MHD_add_response_header(resp, MHD_HTTP_HEADER_CACHE_CONTROL, cc);
        MHD_add_response_header(resp, "X-Content-Type-Options", "nosniff");
        enum MHD_Result ret = MHD_queue_response(r->c, 200, resp);
        MHD_destroy_response(resp);
        r->answered = 1;
        count(s, r->route, 200, (size_t)st.st_size);
        log_line(s, r, x->method, x->full_url, 200, (size_t)st.st_size, "file");
        return ret;
    }
    int gz = f->gz && mm_accepts_gzip(header(r, MHD_HTTP_HEADER_ACCEPT_ENCODING));
    if (mm_etag_matches(header(r, MHD_HTTP_HEADER_IF_NONE_MATCH), f->etag)) {
        char etag[MM_ETAG_SIZE + 4];
        snprintf(etag, sizeof etag, "%s", gz ? f->gz_etag : f->etag);
        int vary = f->gz != NULL;
        static_unref(f);
        return send_not_modified(r, x->method, x->full_url, etag, cc, vary);
    }
    /* the reference goes with the response, dropped when it is gone */
    answer a = {.status = 200, .type = f->mime, .body = gz ? f->gz : f->body, .len = gz ? f->gz_len : f->len,
                .free_fn = static_unref, .free_cls = f,
                .etag = gz ? f->gz_etag : f->etag, .cache_control = cc, .gzip = gz, .vary = f->gz != NULL,
                .timing = "cache;desc=\"file\""};
    return send_answer(r, x->method, x->full_url, &a, "file");
}

static enum MHD_Result h_vendor(ctx *x)
{
    const char *rest = x->url + 7;           /* "/d3/dist/d3.min.js" */
    for (int i = 0; vendor_packages[i]; i++) {
        size_t n = strlen(vendor_packages[i]);
        if (strncmp(rest + 1, vendor_packages[i], n) == 0 && rest[1 + n] == '/')
            return send_file(x, x->r->s->vendor_real, rest, 1);
    }
    return send_error(x->r, x->method, x->full_url, MM_ENOTFOUND, "", "no such page", NULL);
}

static enum MHD_Result h_static(ctx *x)
{
    return send_file(x, x->r->s->web_real, x->url, 0);
}

/* ---- /api/metrics (Prometheus text format 0.0.4) ---------------------------------------- */

static enum MHD_Result h_metrics(ctx *x)
{
    mm_server *s = x->r->s;
    mm_buf b;
    mm_buf_init(&b, 1u << 20);
    char line[256];
#define LINE(...) (snprintf(line, sizeof line, __VA_ARGS__), mm_buf_puts(&b, line))
    LINE("# HELP mechmat_requests_total Requests answered, by route and status.\n"
         "# TYPE mechmat_requests_total counter\n");
    for (int i = 0; i < MAX_ROUTES; i++)
        for (int k = 0; k < N_ST; k++) {
            unsigned long long v = atomic_load_explicit(&s->m.requests[i][k], memory_order_relaxed);
            if (!v)
                continue;
            if (k == ST_OTHER)
                LINE("mechmat_requests_total{route=\"%s\",status=\"other\"} %llu\n",
                     route_name(i < N_ROUTES ? i : -1), v);
            else
                LINE("mechmat_requests_total{route=\"%s\",status=\"%d\"} %llu\n",
                     route_name(i < N_ROUTES ? i : -1), status_codes[k], v);
        }
    mm_cache_stats cs;
    mm_cache_get_stats(s->cache, &cs);
    LINE("# HELP mechmat_cache_hits_total Answers served from the response cache.\n"
         "# TYPE mechmat_cache_hits_total counter\nmechmat_cache_hits_total %llu\n", cs.hits);
    LINE("# HELP mechmat_cache_misses_total Answers solved because the cache did not have them.\n"
         "# TYPE mechmat_cache_misses_total counter\nmechmat_cache_misses_total %llu\n", cs.misses);
    LINE("# HELP mechmat_cache_shared_total Requests that waited for an identical request's solve.\n"
         "# TYPE mechmat_cache_shared_total counter\nmechmat_cache_shared_total %llu\n", cs.shared);
    LINE("# HELP mechmat_cache_revalidated_total 304 answers (If-None-Match matched; nothing solved).\n"
         "# TYPE mechmat_cache_revalidated_total counter\nmechmat_cache_revalidated_total %llu\n",
         atomic_load(&s->m.revalidated));
    LINE("# HELP mechmat_cache_evictions_total Answers dropped to keep the cache in its bound.\n"
         "# TYPE mechmat_cache_evictions_total counter\nmechmat_cache_evictions_total %llu\n", cs.evictions);
    LINE("# HELP mechmat_cache_entries Answers in the cache.\n# TYPE mechmat_cache_entries gauge\n"
         "mechmat_cache_entries %zu\n", cs.entries);
    LINE("# HELP mechmat_cache_bytes Bytes the cache holds.\n# TYPE mechmat_cache_bytes gauge\n"
         "mechmat_cache_bytes %zu\n", cs.bytes);
    LINE("# HELP mechmat_cache_max_bytes The cache's bound.\n# TYPE mechmat_cache_max_bytes gauge\n"
         "mechmat_cache_max_bytes %zu\n", cs.max_bytes);
    LINE("# HELP mechmat_solve_seconds Time of each solve (the exercise's own work).\n"
         "# TYPE mechmat_solve_seconds histogram\n");
    unsigned long long cum = 0;
    for (int i = 0; i <= N_BUCKETS; i++) {
        cum += atomic_load_explicit(&s->m.solve_hist[i], memory_order_relaxed);
        if (i < N_BUCKETS)
            LINE("mechmat_solve_seconds_bucket{le=\"%g\"} %llu\n", solve_buckets[i], cum);
        else
            LINE("mechmat_solve_seconds_bucket{le=\"+Inf\"} %llu\n", cum);
    }
    LINE("mechmat_solve_seconds_sum %.6f\nmechmat_solve_seconds_count %llu\n",
         (double)atomic_load(&s->m.solve_us_sum) * 1e-6, atomic_load(&s->m.solves));
    LINE("# HELP mechmat_light_solves_total Solves made by an event thread, not a worker (light exercises).\n"
         "# TYPE mechmat_light_solves_total counter\nmechmat_light_solves_total %llu\n",
         atomic_load(&s->m.light_solves));
    LINE("# HELP mechmat_connections Open connections.\n# TYPE mechmat_connections gauge\n"
         "mechmat_connections %d\n", atomic_load(&s->connections));
    LINE("# HELP mechmat_requests_in_flight Requests begun and not yet answered (this one included).\n"
         "# TYPE mechmat_requests_in_flight gauge\nmechmat_requests_in_flight %d\n", atomic_load(&s->in_flight));
    pthread_mutex_lock(&s->q_lock);
    int q = s->q_len;
    pthread_mutex_unlock(&s->q_lock);
    LINE("# HELP mechmat_queue_length Solves waiting for a worker.\n# TYPE mechmat_queue_length gauge\n"
         "mechmat_queue_length %d\n", q);
    LINE("# HELP mechmat_workers Solve workers.\n# TYPE mechmat_workers gauge\nmechmat_workers %d\n",
         s->n_workers);
    LINE("# HELP mechmat_busy_total Requests answered 503 busy.\n# TYPE mechmat_busy_total counter\n"
         "mechmat_busy_total %llu\n", atomic_load(&s->m.busy));
    LINE("# HELP mechmat_response_bytes_total Bytes of answer bodies sent.\n"
         "# TYPE mechmat_response_bytes_total counter\nmechmat_response_bytes_total %llu\n",
         atomic_load(&s->m.bytes_out));
    LINE("# HELP mechmat_course_reloads_total Course reloads (SIGHUP), by result.\n"
         "# TYPE mechmat_course_reloads_total counter\n"
         "mechmat_course_reloads_total{result=\"ok\"} %llu\nmechmat_course_reloads_total{result=\"failed\"} %llu\n",
         atomic_load(&s->m.reloads_ok), atomic_load(&s->m.reloads_failed));
    LINE("# HELP mechmat_build_info The running build and course.\n# TYPE mechmat_build_info gauge\n"
         "mechmat_build_info{version=\"%s\",build=\"%s\",course=\"%s\"} 1\n", MM_VERSION, mm_api_build_id(),
         mm_course_digest(mm_api_course(x->r->site->api)));
#undef LINE
    size_t len;
    char *text = mm_buf_take(&b, &len);
    if (!text)
        return MHD_NO;
    answer a = {.status = 200, .type = "text/plain; version=0.0.4; charset=utf-8", .body = text, .len = len,
                .free_fn = free_text, .free_cls = text, .cache_control = "no-store"};
    return send_answer(x->r, x->method, x->full_url, &a, "metrics");
}

/* ---- libmicrohttpd callbacks -------------------------------------------------------------- */

static enum MHD_Result on_request(void *cls, struct MHD_Connection *c, const char *url, const char *method,
                                  const char *version, const char *upload_data, size_t *upload_size,
                                  void **req_cls)
{
    (void)version;
    mm_server *s = cls;
    req *r = *req_cls;

    if (!r) {                          /* first call: headers only */
        r = calloc(1, sizeof *r);
        if (!r)
            return MHD_NO;
        r->s = s;
        r->c = c;
        r->t0 = now_us();
        r->route = -1;
        r->site = site_ref(s);
        mm_buf_init(&r->body, MM_BODY_MAX);
        atomic_fetch_add_explicit(&s->in_flight, 1, memory_order_relaxed);
        *req_cls = r;
        r->want_gz = mm_accepts_gzip(header(r, MHD_HTTP_HEADER_ACCEPT_ENCODING));
        if (atomic_load(&s->connections) > s->max_connections)
            return send_error(r, method, url, MM_EBUSY, "", "busy", NULL);
        const char *cl = header(r, MHD_HTTP_HEADER_CONTENT_LENGTH);
        if (cl && strtoull(cl, NULL, 10) > MM_BODY_MAX) {
            /* A client that asked first (Expect: 100-continue) is told now and
             * sends nothing; one that sends anyway has its body read and
             * dropped (up to DISCARD_MAX) so that it reads the 413 instead of
             * a reset connection, as nginx's lingering close does. */
            const char *expect = header(r, MHD_HTTP_HEADER_EXPECT);
            if ((expect && strcasecmp(expect, "100-continue") == 0) || strtoull(cl, NULL, 10) > DISCARD_MAX)
                return send_error(r, method, url, MM_ETOOBIG, "", "the body is over 1 MiB", NULL);
            r->too_large = 1;
        }
        return MHD_YES;                /* answer on a later call: keeps keep-alive */
    }
    if (r->state == R_WAIT) {          /* resumed: the answer is made */
        mm_entry *e = r->entry;
        r->entry = NULL;
        r->state = R_NEW;
        return send_entry(r, method, url, e, r->shared ? "shared" : "miss");
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
        if (r->too_large) {
            r->discarded += *upload_size;
            if (r->discarded > DISCARD_MAX) {
                *upload_size = 0;
                return send_error(r, method, url, MM_ETOOBIG, "", "the body is over 1 MiB", NULL);
            }
        }
        *upload_size = 0;
        return MHD_YES;
    }
    if (r->too_large)
        return send_error(r, method, url, MM_ETOOBIG, "", "the body is over 1 MiB", NULL);
    return route_request(r, method, url);
}

static void on_completed(void *cls, struct MHD_Connection *c, void **req_cls,
                         enum MHD_RequestTerminationCode toe)
{
    (void)c, (void)toe;
    mm_server *s = cls;
    req *r = *req_cls;
    if (r) {
        mm_cache_unref(r->entry);
        mm_buf_free(&r->body);
        site_unref(r->site);
        free(r);
        *req_cls = NULL;
        atomic_fetch_sub_explicit(&s->in_flight, 1, memory_order_relaxed);
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

/* ---- life cycle ---------------------------------------------------------------------------- */

void mm_server_replace(mm_server *s, mm_api *api)
{
    site *st = site_new(api);
    if (!st) {
        mm_api_free(api);
        return;
    }
    pthread_mutex_lock(&s->site_lock);
    site *old = atomic_exchange(&s->site, st);
    pthread_mutex_unlock(&s->site_lock);
    site_unref(old);
    atomic_store(&s->files_stale, 1);
}

void mm_server_note_reload(mm_server *s, int ok)
{
    atomic_fetch_add(ok ? &s->m.reloads_ok : &s->m.reloads_failed, 1);
}

static void server_free(mm_server *s)
{
    if (!s)
        return;
    site_unref(atomic_load(&s->site));
    mm_cache_free(s->cache);
    static_drop_all(s);
    assets_free(s);
    free(s->queue);
    free(s->workers);
    pthread_mutex_destroy(&s->q_lock);
    pthread_cond_destroy(&s->q_cond);
    pthread_mutex_destroy(&s->site_lock);
    pthread_mutex_destroy(&s->light_lock);
    pthread_mutex_destroy(&s->static_lock);
    free(s);
}

mm_server *mm_server_start(const mm_server_opts *o, mm_api *api, mm_error *err)
{
    mm_server *s = calloc(1, sizeof *s);
    if (!s) {
        mm_api_free(api);
        mm_error_set(err, MM_ENOMEM, "", "out of memory");
        return NULL;
    }
    pthread_mutex_init(&s->q_lock, NULL);
    pthread_cond_init(&s->q_cond, NULL);
    pthread_mutex_init(&s->site_lock, NULL);
    pthread_mutex_init(&s->light_lock, NULL);
    pthread_mutex_init(&s->static_lock, NULL);
    site *st = site_new(api);
    if (!st) {
        mm_api_free(api);
        server_free(s);
        mm_error_set(err, MM_ENOMEM, "", "out of memory");
        return NULL;
    }
    atomic_init(&s->site, st);
    s->quiet = o->quiet;
    s->light_us = o->light_us == 0 ? MM_LIGHT_US : o->light_us < 0 ? 0 : o->light_us;
    s->max_connections = o->max_connections > 0 ? o->max_connections : 10000;
    s->cache = mm_cache_new(o->cache_mb < 0 ? (size_t)64 << 20 : (size_t)o->cache_mb << 20);
    s->q_cap = o->queue > 0 ? o->queue : 1024;
    s->queue = calloc((size_t)s->q_cap, sizeof *s->queue);
    if (!s->cache || !s->queue) {
        server_free(s);
        mm_error_set(err, MM_ENOMEM, "", "out of memory");
        return NULL;
    }
    if (!realpath(o->web_root, s->web_real)) {
        mm_error_set(err, MM_EVALUE, "web-root", "web root %s: %s", o->web_root, strerror(errno));
        server_free(s);
        return NULL;
    }
    if (!o->vendor_root || !realpath(o->vendor_root, s->vendor_real))
        s->vendor_real[0] = '\0';
    asset_scan(s->web_real, s->vendor_real[0] ? s->vendor_real : NULL, s->asset_version, &s->assets,
               &s->n_assets);
    qsort(s->assets, (size_t)s->n_assets, sizeof *s->assets, asset_cmp);

    struct sockaddr_in addr;
    memset(&addr, 0, sizeof addr);
    addr.sin_family = AF_INET;
    addr.sin_port = htons((uint16_t)o->port);
    if (inet_pton(AF_INET, o->host, &addr.sin_addr) != 1) {
        mm_error_set(err, MM_EVALUE, "host", "host must be an IPv4 address such as 127.0.0.1; got %.60s",
                     o->host);
        server_free(s);
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
    s->n_workers = o->threads > 0 ? o->threads : (cores > 0 ? (int)cores : 2);
    s->workers = calloc((size_t)s->n_workers, sizeof *s->workers);
    if (!s->workers) {
        server_free(s);
        mm_error_set(err, MM_ENOMEM, "", "out of memory");
        return NULL;
    }
    for (int i = 0; i < s->n_workers; i++)
        if (pthread_create(&s->workers[i], NULL, worker_main, s) != 0) {
            s->n_workers = i;
            mm_server_stop(s);
            mm_error_set(err, MM_EINTERNAL, "", "could not start the solve workers");
            return NULL;
        }

    /* Event threads: one libmicrohttpd daemon each, one epoll thread per
     * daemon, all listening on the same port with SO_REUSEPORT, so that the
     * kernel spreads the connections (see mm_http.h); none of them ever
     * blocks on a solve.  Until issue 16 each connection had a thread of
     * its own, because libmicrohttpd 0.9.75's own pool of epoll threads
     * (MHD_USE_EPOLL_INTERNAL_THREAD + MHD_OPTION_THREAD_POOL_SIZE, one
     * listening socket shared by the pool) now and then stopped serving
     * every connection at once under load (tests/load/stall_hunt.sh found
     * it: about once in 150-200 s at 256 connections).  Independent
     * daemons do not share that code: README, "Hosting it for a class",
     * gives the hunt's figures for this arrangement. */
    s->n_io = o->io_threads > 0 ? o->io_threads : (cores >= 2 ? 2 : 1);
    if (s->n_io > MAX_IO)
        s->n_io = MAX_IO;
    unsigned limit = (unsigned)s->max_connections + 64;
    for (int i = 0; i < s->n_io; i++) {
        if (i > 0)
            addr.sin_port = htons((uint16_t)s->port);
        s->d[i] = MHD_start_daemon(
            MHD_USE_INTERNAL_POLLING_THREAD | MHD_USE_EPOLL | MHD_ALLOW_SUSPEND_RESUME | MHD_USE_ERROR_LOG,
            (uint16_t)(i ? s->port : o->port), NULL, NULL, on_request, s,
            MHD_OPTION_SOCK_ADDR, (struct sockaddr *)&addr,
            MHD_OPTION_LISTENING_ADDRESS_REUSE, (unsigned)(s->n_io > 1),
            MHD_OPTION_CONNECTION_LIMIT, limit,
            MHD_OPTION_CONNECTION_TIMEOUT, (unsigned)30,
            /* 32 KiB: queries to about 30 KiB get our 413, longer ones
             * libmicrohttpd's 414.  A pool over 32 KiB is mmap()ed by
             * libmicrohttpd for each connection, then zeroed (a page fault
             * per 4 KiB) and unmapped at its close: at a class start, 1,800
             * new connections in a second, that was 60 % of the server's
             * time; 32 KiB comes from malloc and is reused. */
            MHD_OPTION_CONNECTION_MEMORY_LIMIT, (size_t)(32 * 1024),
            MHD_OPTION_LISTEN_BACKLOG_SIZE, (unsigned)4096,
            MHD_OPTION_NOTIFY_COMPLETED, on_completed, s,
            MHD_OPTION_NOTIFY_CONNECTION, on_connection, s,
            MHD_OPTION_UNESCAPE_CALLBACK, unescape, NULL,
            MHD_OPTION_END);
        if (!s->d[i]) {
            mm_error_set(err, MM_EINTERNAL, "port", "could not listen on %s:%d (in use?)", o->host,
                         i ? s->port : o->port);
            mm_server_stop(s);
            return NULL;
        }
        if (i == 0) {
            const union MHD_DaemonInfo *info = MHD_get_daemon_info(s->d[0], MHD_DAEMON_INFO_BIND_PORT);
            s->port = info ? info->port : o->port;
        }
    }
    return s;
}

int mm_server_port(const mm_server *s) { return s->port; }

void mm_server_stop(mm_server *s)
{
    if (!s)
        return;
    for (int i = 0; i < s->n_io; i++) { /* no new connections from here on */
        MHD_socket fd = s->d[i] ? MHD_quiesce_daemon(s->d[i]) : MHD_INVALID_SOCKET;
        if (fd != MHD_INVALID_SOCKET)
            close(fd);
    }
    pthread_mutex_lock(&s->q_lock);    /* the workers finish the queue, then stop */
    s->stopping = 1;
    pthread_cond_broadcast(&s->q_cond);
    pthread_mutex_unlock(&s->q_lock);
    for (int i = 0; i < s->n_workers; i++)
        pthread_join(s->workers[i], NULL);
    /* every suspended connection has been resumed; give the answers a
     * moment to leave (at most 2 s) */
    for (int i = 0; s->d[0] && i < 200 && atomic_load(&s->in_flight) > 0; i++) {
        struct timespec ts = {0, 10 * 1000 * 1000};
        nanosleep(&ts, NULL);
    }
    for (int i = 0; i < s->n_io; i++)
        if (s->d[i])
            MHD_stop_daemon(s->d[i]);
    server_free(s);
}
