/* mm_http.h — the HTTP server: routes of API.md over libmicrohttpd.
 *
 * A pool of epoll threads (one per core by default) answers requests; each
 * request is handled start to end on one thread.  Static files come from
 * web_root only; /vendor/<package>/<file> comes from node_modules of the
 * source tree (the browser libraries installed from the lock file).
 */
#ifndef MM_HTTP_H
#define MM_HTTP_H

#include "mm_api.h"
#include "mm_status.h"

typedef struct mm_server_opts {
    const char *host;       /* address to listen on, "127.0.0.1" */
    int port;               /* 0 picks a free port (see mm_server_port) */
    int threads;            /* worker threads; 0 = number of cores */
    const char *web_root;   /* the web/ folder */
    const char *vendor_root;/* node_modules/, or NULL for none */
    int max_connections;    /* over this, requests get 503 busy */
    int quiet;              /* 1: no access log */
} mm_server_opts;

typedef struct mm_server mm_server;

/* Start serving; api must outlive the server.  NULL on failure, err set. */
mm_server *mm_server_start(const mm_server_opts *opts, const mm_api *api, mm_error *err);
int mm_server_port(const mm_server *s);
/* Stop accepting, finish what runs, free everything.  s may be NULL. */
void mm_server_stop(mm_server *s);

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

#endif
