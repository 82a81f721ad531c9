/* mm_status.h — the one list of error codes shared by every layer.
 *
 * Each row of MM_STATUS_LIST gives the code, the HTTP status the server
 * answers with, the API.md error code and a short text.  The enum,
 * mm_strerror(), mm_http_status() and mm_api_code() are all generated from
 * the table, so they cannot fall out of step.
 *
 * Errors carry details in an mm_error the caller owns (never a global
 * "last error"): the code, the parameter it concerns (may be empty) and a
 * message written for a learner: name the field, what was expected, what
 * arrived.  Solvers fill it; the server turns it into JSON.
 */
#ifndef MM_STATUS_H
#define MM_STATUS_H

#include <stddef.h>

/*  code           HTTP  API code          short text */
#define MM_STATUS_LIST(X)                                                    \
    X(MM_OK,          200, "ok",             "success")                      \
    X(MM_EVALUE,      400, "bad_value",      "value does not parse")         \
    X(MM_ERANGE,      400, "out_of_range",   "value outside its limits")     \
    X(MM_EPARAM,      400, "unknown_param",  "unknown parameter")            \
    X(MM_EJSON,       400, "bad_json",       "body is not valid JSON")       \
    X(MM_ENOTFOUND,   404, "not_found",      "not found")                    \
    X(MM_EFORBIDDEN,  403, "forbidden",      "forbidden")                    \
    X(MM_EMETHOD,     405, "method_not_allowed", "method not allowed")       \
    X(MM_ETOOBIG,     413, "too_large",      "request too large")            \
    X(MM_ESINGULAR,   422, "no_solution",    "the problem has no solution")  \
    X(MM_ENOCONV,     422, "no_solution",    "no convergence")               \
    X(MM_ENONFINITE,  422, "no_solution",    "result not finite")            \
    X(MM_ENOMEM,      500, "internal",       "out of memory")                \
    X(MM_EINTERNAL,   500, "internal",       "internal error")               \
    X(MM_EBUSY,       503, "busy",           "server busy")

enum mm_status {
#define MM_X_ENUM(code, http, api, text) code,
    MM_STATUS_LIST(MM_X_ENUM)
#undef MM_X_ENUM
    MM_STATUS_COUNT
};

/* Error details, owned by the caller.  param is "" when no parameter is
 * concerned.  Sizes are fixed so that filling one never allocates. */
typedef struct mm_error {
    int code;          /* an enum mm_status value */
    char param[48];    /* the parameter or field concerned, or "" */
    char msg[200];     /* message for the learner, lower case, no file names */
} mm_error;

/* Short text, HTTP status and API.md code of a status.  Unknown codes map
 * to MM_EINTERNAL's values.  Cannot fail. */
const char *mm_strerror(int code);
int mm_http_status(int code);
const char *mm_api_code(int code);

/* Clear err (code MM_OK, empty strings).  err may be NULL. */
void mm_error_clear(mm_error *err);

/* Fill err with code, param (may be NULL) and a printf-style message, cut to
 * fit.  Returns code, so that `return mm_error_set(err, ...)` reads well.
 * err may be NULL (then only the code is returned). */
int mm_error_set(mm_error *err, int code, const char *param,
                 const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

#endif
