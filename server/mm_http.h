/* mm_http.h — the HTTP server: the routes of docs/API.md over libmicrohttpd.
 *
 * Threads.  Event threads (--io-threads, 2 by default: each a
 * libmicrohttpd daemon with its own epoll thread, all on one port with
 * SO_REUSEPORT) hold every connection, read every request and send every
 * answer.  What they answer themselves, at once: documents built at start
 * (health, catalog, metadata, OpenAPI), static files (from memory after
 * their first read), answers found in the response cache, 304s, errors,
 * and the solves of light exercises: those whose recent solves took under
 * 300 us of CPU on average (num-complex, a default vib-sdof-forced), for
 * which a worker's wake-up and the connection's suspension cost more than
 * the solve (mm_light.h); a heavy solve sends the exercise back to the
 * workers for a while.  Any other solve that is not in the cache suspends
 * its connection and goes to a
 * fixed pool of --threads solve workers through a bounded queue (503 busy
 * when it is full); the worker runs it, writes the answer, puts it in the
 * cache and resumes every connection that waits for that key (identical
 * requests in flight are solved once: mm_cache.h, the light ones too).
 * So thousands of idle
 * keep-alive connections cost memory, not threads, and a new client is
 * answered while every worker solves.
 *
 * Static files come from web_root only; /vendor/<package>/<file> from
 * vendor_root (node_modules/ of the source tree, or the installed copy),
 * for the browser packages only.
 */
#ifndef MM_HTTP_H
#define MM_HTTP_H

#include "mm_api.h"
#include "mm_status.h"

typedef struct mm_server_opts {
    const char *host;       /* address to listen on, "127.0.0.1" */
    int port;               /* 0 picks a free port (see mm_server_port) */
    int threads;            /* solve workers; 0 = number of cores */
    int io_threads;         /* event threads; 0 = 2 (1 on one core) */
    const char *web_root;   /* the web/ folder */
    const char *vendor_root;/* node_modules/, or NULL for none */
    int max_connections;    /* over this many open, a request gets 503 busy; 0 = 10000 */
    int queue;              /* solves waiting for a worker, at most; 0 = 1024 */
    long cache_mb;          /* response cache in MiB; <0 = default 64, 0 = keep nothing */
    int quiet;              /* 1: no access log */
    int light_us;           /* light solves, made on the event threads (mm_light.h):
                               CPU us; 0 = the default 300, < 0 = none */
} mm_server_opts;

typedef struct mm_server mm_server;

/* Start serving api (the server owns it from here on, and frees it on
 * failure too).  NULL on failure, err set. */
mm_server *mm_server_start(const mm_server_opts *opts, mm_api *api, mm_error *err);
int mm_server_port(const mm_server *s);

/* Serve api from now on (owned by the server): requests already running
 * finish with the one they started with, which is freed after them.  The
 * response cache is kept (answers depend on the resolved parameters, not
 * on the course), static files are read again. */
void mm_server_replace(mm_server *s, mm_api *api);

/* Count a course reload for /api/metrics. */
void mm_server_note_reload(mm_server *s, int ok);

/* Stop accepting, finish what runs, free everything.  s may be NULL. */
void mm_server_stop(mm_server *s);

/* The version of the static files (22 characters): the digest of every
 * file under web_root and of the browser packages' package.json, or the
 * content of web_root/.asset-version when the installer wrote one.  A
 * static URL with ?v=<this> is cached by browsers for a year; the text
 * __MM_ASSET_VERSION__ in .html, .js, .mjs and .css files is replaced by it
 * when they are served.  NULL-safe: "" when web_root cannot be read. */
void mm_asset_version(const char *web_root, const char *vendor_root, char out[32]);

/* The routes, for tests and the OpenAPI check: method set ("GET HEAD"),
 * path pattern ("/api/exercises/{id}/solve"); n is set to their count. */
typedef struct mm_route_info {
    const char *methods, *pattern;
} mm_route_info;
const mm_route_info *mm_http_routes(int *n);

/* Resolve a URL path under root to a regular file inside root, or return
 * MM_ENOTFOUND: "..", "." segments, backslashes, NUL, paths that leave root
 * through a symlink, and anything not a regular file are all not found.
 * A directory maps to its index.html.  out gets the real path. */
int mm_static_resolve(const char *root_real, const char *url_path, char *out, size_t size);

/* Percent-decode s in place (path or query text); %00 becomes a backslash
 * instead of ending the text, so that it can never hide what follows.
 * Returns the new length.  Cannot fail. */
size_t mm_http_unescape(char *s);

/* The MIME type of a file name, by extension. */
const char *mm_mime_type(const char *path);

/* An access log line's text: every byte that could forge a line or a
 * field (control bytes, DEL, '"', '\\', bytes >= 0x80) written \xHH, cut
 * to fit size.  Returns the length written. */
size_t mm_log_escape(const char *s, char *out, size_t size);

/* Does an Accept-Encoding header value accept gzip (q > 0)? */
int mm_accepts_gzip(const char *accept_encoding);

/* Does an If-None-Match header value match etag ("digest" with quotes;
 * its "digest-gz" form, a weak W/ form and * match too)? */
int mm_etag_matches(const char *if_none_match, const char *etag);

#endif
