/* mm_api.h — the public API of API.md, without HTTP.
 *
 * The HTTP layer (mm_http.c) routes a request here and sends back what this
 * writes.  Tests call the same functions in-process.  What never changes
 * while the server runs (health, catalog, every exercise's metadata with its
 * rendered theory) is built once by mm_api_alloc and served from memory.
 */
#ifndef MM_API_H
#define MM_API_H

#include <stddef.h>

#include "mm_exercise.h"
#include "mm_json.h"

#define MM_VERSION "0.1.0"

#define MM_REQ_MEM_CAP   (64u << 20)   /* arena cap of one solve, bytes */
#define MM_ANSWER_MAX    (32u << 20)   /* longest JSON answer, bytes */
#define MM_BODY_MAX      (1u << 20)    /* longest POST body, bytes */
#define MM_QUERY_MAX     (16u << 10)   /* longest query string, bytes */
#define MM_MAX_PARAMS    32            /* most parameters of one exercise */

typedef struct mm_api mm_api;

/* One name=value pair of a request (not NUL-terminated). */
typedef struct mm_input {
    const char *name, *text;
    size_t name_len, text_len;
} mm_input;

/* Build the cached documents.  root is the source tree (theory files are
 * read from root/<exercise theory path>); a missing theory file is logged
 * and served as empty.
 * Returns NULL on failure with err filled. */
mm_api *mm_api_alloc(const char *root, mm_error *err);
void mm_api_free(mm_api *api);

/* Cached JSON documents; the pointers live as long as api. */
const char *mm_api_health(const mm_api *api, size_t *len);
const char *mm_api_catalog(const mm_api *api, size_t *len);
/* NULL when there is no such exercise. */
const char *mm_api_meta(const mm_api *api, const char *id, size_t *len);

/* Solve ex with the given inputs (defaults for the rest).  Writes into out
 * either the answer or an error document; returns the HTTP status. */
int mm_api_solve(const mm_exercise *ex, const mm_input *in, int n_in, mm_buf *out);

/* The same with a JSON body {"params":{...}}: values are made into the text
 * forms of mm_params.h first, so GET and POST cannot disagree. */
int mm_api_solve_json(const mm_exercise *ex, const char *body, size_t len, mm_buf *out);

/* {"error":{"code":…,"param":…,"message":…}} for err; returns its status. */
int mm_api_error(mm_buf *out, const mm_error *err);

#endif
