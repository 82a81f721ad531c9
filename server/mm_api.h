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

#include "mm_course.h"
#include "mm_exercise.h"
#include "mm_hash.h"
#include "mm_json.h"
#include "mm_result_impl.h"

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

#define MM_ETAG_SIZE 32                /* "digest" with quotes, or "digest-gz" */

/* A document built once: its text and its ETag (from its bytes). */
typedef struct mm_doc {
    const char *text;
    size_t len;
    char etag[MM_ETAG_SIZE];
} mm_doc;

/* Build the cached documents of the built-in course (every exercise, in
 * book order).  root is the source tree (theory files are read from
 * root/<exercise theory path>); a missing theory file is logged and served
 * as empty.  Returns NULL on failure with err filled. */
mm_api *mm_api_alloc(const char *root, mm_error *err);

/* The same for a course (mm_course.h); api owns course from here on, and
 * frees it on failure too. */
mm_api *mm_api_alloc_course(const char *root, mm_course *course, mm_error *err);
void mm_api_free(mm_api *api);

const mm_course *mm_api_course(const mm_api *api);

/* The body of an exercise's Octave/MATLAB script (its <name>.m beside the
 * theory), read at start; NULL when it has none. */
const char *mm_api_script_body(const mm_api *api, const char *id);

/* The course's assignments, loaded and checked with the course (a bad one
 * makes the whole course fail with its line); NULL when there is none of
 * that name.  mm_assign.h has what can be done with one. */
typedef struct mm_assignment mm_assignment;
const mm_assignment *mm_api_assignment(const mm_api *api, const char *name);
/* GET /api/assignments: [{"name","title","exercise"}] */
const mm_doc *mm_api_doc_assignments(const mm_api *api);
/* An exercise of the course (its overrides applied), NULL when the course
 * has none of that id. */
const mm_exercise *mm_api_exercise(const mm_api *api, const char *id);

/* Cached JSON documents; the pointers live as long as api. */
const mm_doc *mm_api_doc_health(const mm_api *api);
const mm_doc *mm_api_doc_catalog(const mm_api *api);
const mm_doc *mm_api_doc_course(const mm_api *api);   /* GET /api/course */
const mm_doc *mm_api_doc_openapi(const mm_api *api);  /* GET /api/openapi.json */
const mm_doc *mm_api_doc_meta(const mm_api *api, const char *id);   /* NULL: no such */
const char *mm_api_health(const mm_api *api, size_t *len);
const char *mm_api_catalog(const mm_api *api, size_t *len);
/* NULL when there is no such exercise. */
const char *mm_api_meta(const mm_api *api, const char *id, size_t *len);

/* ---- a solve: resolve -> run -> write ---------------------------------------
 *
 * resolve   the request's values parsed and checked against the exercise's
 *           table (defaults for the rest) and its joint check, and the
 *           canonical text of the resolved parameters written to key:
 *               <id>?<name>=<value>&<name>=<value>...
 *           every parameter in table order, numbers in their shortest
 *           round-trip form, vectors 1,2,3, matrices 1,2;3,4, choices and
 *           expressions as text with separators and non-printing bytes
 *           written %XX.  Two requests with the same key get the same
 *           answer (API.md "Caching"): the key is what a cache, an ETag and
 *           an assignment's variant are made from.
 *   run     the exercise's solve, timed;
 *   write   the answer (or the error of whichever step failed) as JSON.
 * Another writer (the Octave script) takes the resolved values instead of
 * write.  Each step may be called from any thread; one mm_solve belongs to
 * one thread at a time. */
typedef struct mm_solve {
    const mm_exercise *ex;
    mm_value vals[MM_MAX_PARAMS];  /* after resolve: one per parameter */
    mm_result res;                 /* the arena of the values, then the result */
    mm_buf key;                    /* after resolve: the canonical text */
    mm_error err;                  /* the failure, when rc != MM_OK */
    int rc;                        /* MM_OK, or the first failure */
    int resolved, ran;
    long long elapsed_us;          /* of run */
} mm_solve;

void mm_solve_init(mm_solve *s, const mm_exercise *ex);
void mm_solve_free(mm_solve *s);
/* Returns MM_OK or the failure (in s->err): 400 kinds only. */
int mm_api_resolve(mm_solve *s, const mm_input *in, int n_in);
/* The same with a JSON body {"params":{...}}: values are made into the
 * text forms of mm_params.h first, so GET and POST cannot disagree. */
int mm_api_resolve_json(mm_solve *s, const char *body, size_t len);
/* Returns MM_OK or the failure: 422 kinds, or 413/500. */
int mm_api_run(mm_solve *s);
/* The answer, or the error document of the first failure; returns the
 * HTTP status.  Runs first when resolved and not yet run. */
int mm_api_write(mm_solve *s, mm_buf *out);

/* The canonical text of one resolved value (as in the key, unescaped
 * numbers and arrays). */
void mm_api_canonical_value(mm_buf *b, const mm_param *p, const mm_value *v);

/* Solve ex with the given inputs (defaults for the rest): resolve, run and
 * write in one.  Writes into out either the answer or an error document;
 * returns the HTTP status. */
int mm_api_solve(const mm_exercise *ex, const mm_input *in, int n_in, mm_buf *out);
int mm_api_solve_json(const mm_exercise *ex, const char *body, size_t len, mm_buf *out);

/* The ETag of an answer: the build (mm_api_build_id) and the key. */
void mm_api_answer_etag(const char *key, size_t len, char out[MM_ETAG_SIZE]);

/* The digest of the running binary and MM_VERSION (22 characters). */
const char *mm_api_build_id(void);

/* {"error":{"code":…,"param":…,"message":…}} for err; returns its status. */
int mm_api_error(mm_buf *out, const mm_error *err);

#endif
