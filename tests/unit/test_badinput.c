/* test_badinput.c — the catalogue of bad input, over HTTP against the real
 * server: what learners type and what the open internet sends.
 *
 * Every answer, whatever the request, is checked the same way (expect()):
 *   - its status is one of API.md's, and never 500;
 *   - its body is valid UTF-8 and parses as JSON (cJSON);
 *   - it holds no nan/inf token and no null but an error's "param";
 *   - an error has the documented error.code and, where a parameter is
 *     concerned, error.param naming it;
 *   - it came within a time bound (nothing hangs).
 * The catalogue: empty values; huge numbers, 1e999, nan, inf in every
 * numeric parameter of several exercises; negative sizes; invalid UTF-8 in a
 * query value, a query name, a JSON string and a JSON key; NUL bytes in the
 * query and in JSON; duplicate and unknown parameters (query and JSON);
 * bodies of 10 MB (with and without Content-Length) and a query far over
 * its limit; a matrix of 1e6 elements by POST (nested arrays and text);
 * expressions that divide by zero and the longest, most deeply nested
 * ones (muParser has no loops: their cost is bounded, measured here); path
 * traversal in further encodings than test_http.c's.  Then determinism:
 * the same request from 8 threads x 20 gives byte-identical answers (but
 * for elapsed_us), for every exercise of the catalog.
 *
 * (test_http.c already covers: m=-1, m=abc, m=1e999, m=nan, m=, m=1%00,
 * m=1&m=2, mass=1, a 17 kB query, 100000 nested '[', a 10 MB body with its
 * Content-Length, and the first list of traversal attacks.)
 *
 * Not run under valgrind (tests/valgrind.sh skips it by name): it sends
 * megabytes and times its answers. */
#include "mm_test.h"

#include <cJSON.h>
#include <pthread.h>
#include <time.h>

#include "mm_server_fixture.h"

static mm_fixture server;
static double time_bound_s;          /* the longest any answer may take */

static int setup(void **state)
{
    (void)state;
    /* generous: ASan/UBSan runs (make asan) are several times slower */
    time_bound_s = getenv("ASAN") ? 20.0 : 2.0;
    return mm_fixture_start(&server, NULL);
}

static int teardown(void **state)
{
    (void)state;
    return mm_fixture_stop(&server) == 0 ? 0 : -1;   /* alive, and stops cleanly */
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---- what every answer must be ------------------------------------------------------ */

/* Strict UTF-8: no overlong forms, no surrogates, nothing over U+10FFFF. */
static int utf8_valid(const unsigned char *s, size_t n)
{
    for (size_t i = 0; i < n;) {
        unsigned c = s[i];
        size_t len;
        unsigned cp, min;
        if (c < 0x80) {
            i++;
            continue;
        } else if ((c & 0xE0) == 0xC0) {
            len = 2, cp = c & 0x1F, min = 0x80;
        } else if ((c & 0xF0) == 0xE0) {
            len = 3, cp = c & 0x0F, min = 0x800;
        } else if ((c & 0xF8) == 0xF0) {
            len = 4, cp = c & 0x07, min = 0x10000;
        } else {
            return 0;
        }
        if (i + len > n)
            return 0;
        for (size_t k = 1; k < len; k++) {
            if ((s[i + k] & 0xC0) != 0x80)
                return 0;
            cp = (cp << 6) | (s[i + k] & 0x3F);
        }
        if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
            return 0;
        i += len;
    }
    return 1;
}

/* A bare nan/inf/NaN/Infinity token outside strings? */
static int has_nonfinite_token(const char *s)
{
    int in_str = 0;
    for (const char *p = s; *p; p++) {
        if (in_str) {
            if (*p == '\\' && p[1])
                p++;
            else if (*p == '"')
                in_str = 0;
        } else if (*p == '"') {
            in_str = 1;
        } else if (!strncmp(p, "nan", 3) || !strncmp(p, "NaN", 3) || !strncmp(p, "inf", 3) ||
                   !strncmp(p, "Inf", 3) || !strncmp(p, "-nan", 4)) {
            return 1;
        }
    }
    return 0;
}

/* Every number finite; null only as an error's "param". */
static const char *bad_value_in(const cJSON *j, int in_error)
{
    for (const cJSON *e = j->child; e; e = e->next) {
        if (cJSON_IsNull(e) && !(in_error && e->string && strcmp(e->string, "param") == 0))
            return e->string ? e->string : "(array element)";
        if (cJSON_IsNumber(e) && !isfinite(e->valuedouble))
            return e->string ? e->string : "(array element)";
        if (cJSON_IsArray(e) || cJSON_IsObject(e)) {
            const char *w = bad_value_in(e, e->string && strcmp(e->string, "error") == 0);
            if (w)
                return w;
        }
    }
    return NULL;
}

static int status_documented(long s)
{
    static const long ok[] = {200, 400, 404, 405, 413, 422, 503};   /* 500 is never right */
    for (size_t i = 0; i < sizeof ok / sizeof ok[0]; i++)
        if (s == ok[i])
            return 1;
    return 0;
}

/* Check r; want_status 0 = any documented one; code NULL = any (or none for
 * a 200), else one of "a|b"; param NULL = not checked, "" = must be null. */
static cJSON *check_reply(const char *what, const mm_reply *r, double secs, long want_status,
                          const char *code, const char *param)
{
    if (!status_documented(r->status))
        fail_msg("%s: status %ld is not one of API.md's: %.300s", what, r->status, r->body);
    if (want_status && r->status != want_status)
        fail_msg("%s: status %ld, wanted %ld: %.300s", what, r->status, want_status, r->body);
    if (secs > time_bound_s)
        fail_msg("%s: answered in %.2f s (bound %.1f s)", what, secs, time_bound_s);
    if (!strstr(r->headers, "application/json"))
        fail_msg("%s: not application/json: %.200s", what, r->headers);
    if (!utf8_valid((const unsigned char *)r->body, r->len))
        fail_msg("%s: the answer is not valid UTF-8: %.300s", what, r->body);
    if (strlen(r->body) != r->len)
        fail_msg("%s: the answer holds a NUL byte", what);
    cJSON *j = cJSON_ParseWithLength(r->body, r->len);
    if (!j)
        fail_msg("%s: the answer is not JSON: %.300s", what, r->body);
    if (has_nonfinite_token(r->body))
        fail_msg("%s: nan/inf in the answer: %.300s", what, r->body);
    const char *bad = bad_value_in(j, 0);
    if (bad)
        fail_msg("%s: null or non-finite value at \"%s\": %.300s", what, bad, r->body);
    const cJSON *e = cJSON_GetObjectItem(j, "error");
    if (r->status == 200) {
        if (e)
            fail_msg("%s: a 200 with an error: %.300s", what, r->body);
        return j;
    }
    if (!e)
        fail_msg("%s: status %ld without an error object: %.300s", what, r->status, r->body);
    const cJSON *c = cJSON_GetObjectItem(e, "code"), *p = cJSON_GetObjectItem(e, "param"),
                *m = cJSON_GetObjectItem(e, "message");
    if (!cJSON_IsString(c) || !cJSON_IsString(m) || !(cJSON_IsString(p) || cJSON_IsNull(p)))
        fail_msg("%s: error without code, param or message: %.300s", what, r->body);
    if (code) {
        int found = 0;
        size_t n = strlen(c->valuestring);
        for (const char *s = code; *s;) {
            size_t k = strcspn(s, "|");
            if (k == n && strncmp(s, c->valuestring, n) == 0)
                found = 1;
            s += k + (s[k] == '|');
        }
        if (!found)
            fail_msg("%s: error code %s, wanted %s: %.300s", what, c->valuestring, code, r->body);
    }
    if (param && param[0] && !(cJSON_IsString(p) && strcmp(p->valuestring, param) == 0))
        fail_msg("%s: error.param is not \"%s\": %.300s", what, param, r->body);
    if (param && !param[0] && !cJSON_IsNull(p))
        fail_msg("%s: error.param should be null: %.300s", what, r->body);
    return j;
}

/* GET path; the parsed answer (caller deletes) after check_reply. */
static cJSON *get(const char *path, long status, const char *code, const char *param)
{
    mm_reply r;
    double t0 = now_s();
    if (mm_http(&server, NULL, path, NULL, 0, &r) != 0)
        fail_msg("GET %.200s: no answer (the server died or hung?)", path);
    cJSON *j = check_reply(path, &r, now_s() - t0, status, code, param);
    mm_reply_free(&r);
    return j;
}

static void get_ok(const char *path, long status, const char *code, const char *param)
{
    cJSON_Delete(get(path, status, code, param));
}

/* POST body (len bytes) to /api/exercises/ID/solve. */
static cJSON *post(const char *id, const char *body, size_t len, long status, const char *code,
                   const char *param)
{
    char path[160], what[400];
    snprintf(path, sizeof path, "/api/exercises/%s/solve", id);
    snprintf(what, sizeof what, "POST %s %.200s%s", id, body, len > 200 ? "..." : "");
    mm_reply r;
    double t0 = now_s();
    if (mm_http(&server, "POST", path, body, len, &r) != 0)
        fail_msg("%s: no answer (the server died or hung?)", what);
    cJSON *j = check_reply(what, &r, now_s() - t0, status, code, param);
    mm_reply_free(&r);
    return j;
}

static void post_ok(const char *id, const char *body, long status, const char *code, const char *param)
{
    cJSON_Delete(post(id, body, strlen(body), status, code, param));
}

/* ---- what the server has ---------------------------------------------------------------- */

static int registered(const char *id)
{
    char path[160];
    snprintf(path, sizeof path, "/api/exercises/%s", id);
    mm_reply r;
    assert_int_equal(mm_http(&server, NULL, path, NULL, 0, &r), 0);
    int yes = r.status == 200;
    mm_reply_free(&r);
    if (!yes)
        print_message("   (%s is not registered yet: its cases are skipped)\n", id);
    return yes;
}

/* The metadata's params of an exercise (caller deletes the document). */
static cJSON *meta(const char *id, const cJSON **params)
{
    char path[160];
    snprintf(path, sizeof path, "/api/exercises/%s", id);
    cJSON *m = get(path, 200, NULL, NULL);
    *params = cJSON_GetObjectItem(m, "params");
    return m;
}

static const char *kind_of(const cJSON *p) { return cJSON_GetObjectItem(p, "kind")->valuestring; }
static const char *name_of(const cJSON *p) { return cJSON_GetObjectItem(p, "name")->valuestring; }

static int is_numeric(const cJSON *p)
{
    return strcmp(kind_of(p), "real") == 0 || strcmp(kind_of(p), "integer") == 0;
}

/* ---- empty values ------------------------------------------------------------------------- */

static void empty_values_should_be_bad_values_naming_the_parameter(void **state)
{
    (void)state;
    const char *ids[] = {"vib-sdof-forced", "vib-dft", "num-linear-system", "num-nonlinear-roots",
                         "vib-fourier-series", "num-polyfit"};
    for (size_t i = 0; i < sizeof ids / sizeof ids[0]; i++) {
        if (!registered(ids[i]))
            continue;
        const cJSON *params, *p;
        cJSON *m = meta(ids[i], &params);
        cJSON_ArrayForEach(p, params) {
            const char *name = name_of(p);
            /* empty, blanks only, separators only (arrays) */
            const char *texts[] = {"", "%20%20", "%09", ",", ";;", "[]", "[%20]"};
            int n = strcmp(kind_of(p), "vector") == 0 || strcmp(kind_of(p), "matrix") == 0 ? 7 : 3;
            for (int k = 0; k < n; k++) {
                char path[256];
                snprintf(path, sizeof path, "/api/exercises/%s/solve?%s=%s", ids[i], name, texts[k]);
                get_ok(path, 400, "bad_value", name);
            }
            const char *bodies[] = {"\"\"", "\"   \"", "[]", "[[]]", "null", "{}", "true"};
            for (int k = 0; k < 7; k++) {
                char body[160];
                snprintf(body, sizeof body, "{\"params\":{\"%s\":%s}}", name, bodies[k]);
                post_ok(ids[i], body, 400, "bad_value", name);
            }
        }
        cJSON_Delete(m);
    }
}

/* ---- huge numbers, 1e999, nan, inf ---------------------------------------------------------- */

static void huge_and_non_finite_numbers_should_be_refused_in_every_numeric_parameter(void **state)
{
    (void)state;
    const char *ids[] = {"vib-sdof-forced", "vib-dft", "num-nonlinear-roots", "vib-fourier-series",
                         "vib-coulomb", "num-plot"};
    /* above every max (API limits are far below 1e300): out_of_range */
    const char *huge[] = {"1e308", "1.7976931348623157e308", "1e999", "1e99999999999",
                          "99999999999999999999999999999999", "1e400"};
    const char *neg_huge[] = {"-1e308", "-1e999", "-99999999999999999999999999999999"};
    /* not numbers, or constant expressions that are not finite: bad_value */
    const char *nonfinite[] = {"nan", "NaN", "-nan", "nan(0x1)", "inf", "-inf", "Infinity", "+Infinity",
                               "INF", "1/0", "-1/0", "0/0", "sqrt(-1)", "exp(1000)", "2^1024", "ln(0)",
                               "0x1p3", "1e", "1e+", "--1", "1..2", "%2B", "-", "1%201", "1,5"};
    int cases = 0;
    for (size_t i = 0; i < sizeof ids / sizeof ids[0]; i++) {
        if (!registered(ids[i]))
            continue;
        const cJSON *params, *p;
        cJSON *m = meta(ids[i], &params);
        cJSON_ArrayForEach(p, params) {
            if (!is_numeric(p))
                continue;
            const char *name = name_of(p);
            double max = cJSON_GetObjectItem(p, "max")->valuedouble;
            double min = cJSON_GetObjectItem(p, "min")->valuedouble;
            char path[256], body[256];
            for (size_t k = 0; k < sizeof huge / sizeof huge[0]; k++) {
                if (strtod(huge[k], NULL) <= max)
                    continue;
                snprintf(path, sizeof path, "/api/exercises/%s/solve?%s=%s", ids[i], name, huge[k]);
                get_ok(path, 400, "out_of_range", name);
                snprintf(body, sizeof body, "{\"params\":{\"%s\":%s}}", name, huge[k]);   /* a JSON number */
                post_ok(ids[i], body, 400, "out_of_range", name);
                snprintf(body, sizeof body, "{\"params\":{\"%s\":\"%s\"}}", name, huge[k]); /* text */
                post_ok(ids[i], body, 400, "out_of_range", name);
                cases += 3;
            }
            for (size_t k = 0; k < sizeof neg_huge / sizeof neg_huge[0]; k++) {
                if (strtod(neg_huge[k], NULL) >= min)
                    continue;
                snprintf(path, sizeof path, "/api/exercises/%s/solve?%s=%s", ids[i], name, neg_huge[k]);
                get_ok(path, 400, "out_of_range", name);
                snprintf(body, sizeof body, "{\"params\":{\"%s\":%s}}", name, neg_huge[k]);
                post_ok(ids[i], body, 400, "out_of_range", name);
                cases += 2;
            }
            for (size_t k = 0; k < sizeof nonfinite / sizeof nonfinite[0]; k++) {
                snprintf(path, sizeof path, "/api/exercises/%s/solve?%s=%s", ids[i], name, nonfinite[k]);
                get_ok(path, 400, "bad_value", name);
                cases++;
            }
            /* JSON has no NaN or Infinity literal: the body is not JSON */
            snprintf(body, sizeof body, "{\"params\":{\"%s\":NaN}}", name);
            post_ok(ids[i], body, 400, "bad_json", "");
            snprintf(body, sizeof body, "{\"params\":{\"%s\":Infinity}}", name);
            post_ok(ids[i], body, 400, "bad_json", "");
            snprintf(body, sizeof body, "{\"params\":{\"%s\":\"nan\"}}", name);
            post_ok(ids[i], body, 400, "bad_value", name);
            /* underflow reads as 0: accepted when 0 is allowed, else out of range */
            snprintf(path, sizeof path, "/api/exercises/%s/solve?%s=1e-999", ids[i], name);
            cJSON *j = get(path, 0, "out_of_range|no_solution", name);
            cJSON_Delete(j);
            cases += 4;
        }
        cJSON_Delete(m);
    }
    print_message("   %d requests with huge or non-finite numbers\n", cases);
    assert_true(cases > 100);
}

/* ---- negative sizes ------------------------------------------------------------------------- */

static void negative_sizes_should_be_out_of_range(void **state)
{
    (void)state;
    const struct { const char *id, *param; } sizes[] = {
        {"vib-sdof-forced", "points"}, {"vib-sdof-free", "points"}, {"vib-coulomb", "points"},
        {"vib-dft", "N"}, {"num-nonlinear-roots", "n"}, {"vib-fourier-series", "terms"},
        {"num-polyfit", "degree"}, {"num-plot", "points"}, {"vib-fourier-transform", "N"},
    };
    const char *values[] = {"-5", "-1", "0", "-65536", "-2147483648", "-9223372036854775808", "-1e9"};
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        if (!registered(sizes[i].id))
            continue;
        for (size_t k = 0; k < sizeof values / sizeof values[0]; k++) {
            char path[200], body[200];
            snprintf(path, sizeof path, "/api/exercises/%s/solve?%s=%s", sizes[i].id, sizes[i].param, values[k]);
            /* 0 may be allowed (degree 0 is a constant fit) */
            cJSON *j = get(path, strcmp(values[k], "0") ? 400 : 0,
                           strcmp(values[k], "0") ? "out_of_range" : NULL, sizes[i].param);
            cJSON_Delete(j);
            snprintf(body, sizeof body, "{\"params\":{\"%s\":%s}}", sizes[i].param, values[k]);
            j = post(sizes[i].id, body, strlen(body), strcmp(values[k], "0") ? 400 : 0,
                     strcmp(values[k], "0") ? "out_of_range" : NULL, sizes[i].param);
            cJSON_Delete(j);
        }
        char path[200];                      /* a size that is not whole */
        snprintf(path, sizeof path, "/api/exercises/%s/solve?%s=-2.5", sizes[i].id, sizes[i].param);
        get_ok(path, 400, "bad_value|out_of_range", sizes[i].param);
    }
}

/* ---- invalid UTF-8 -------------------------------------------------------------------------- */

static void invalid_utf8_should_come_back_as_valid_json(void **state)
{
    (void)state;
    /* stray continuation, truncated, overlong '/', overlong NUL, surrogate,
     * over U+10FFFF, 0xFE/0xFF, and a valid 'é' for contrast */
    const char *bytes[] = {"%80", "%ff%fe", "%c3", "%e2%82", "%c0%af", "%c0%80", "%ed%a0%80",
                           "%f4%90%80%80", "%fe", "%f8%88%80%80%80", "%c3%a9", "a%ffb%c3(c"};
    if (registered("vib-dft")) {
        for (size_t k = 0; k < sizeof bytes / sizeof bytes[0]; k++) {
            char path[256];
            snprintf(path, sizeof path, "/api/exercises/vib-dft/solve?window=%s", bytes[k]);
            get_ok(path, 400, "bad_value", "window");                 /* a choice echoes the text */
            snprintf(path, sizeof path, "/api/exercises/vib-dft/solve?signal=sin(t)%s", bytes[k]);
            get_ok(path, 400, "bad_value", "signal");                 /* an expression too */
            snprintf(path, sizeof path, "/api/exercises/vib-dft/solve?fs=1%s", bytes[k]);
            get_ok(path, 400, "bad_value", "fs");                     /* a number */
            snprintf(path, sizeof path, "/api/exercises/vib-dft/solve?%s=1", bytes[k]);
            get_ok(path, 400, "unknown_param", NULL);                  /* a name */
            snprintf(path, sizeof path, "/api/exercises/vib-dft/solve?N%s=1", bytes[k]);
            get_ok(path, 400, "unknown_param", NULL);
        }
        /* the same raw bytes inside JSON strings: values and keys */
        const char *raw[] = {"\x80", "\xff\xfe", "\xc3", "\xe2\x82", "\xc0\xaf", "\xed\xa0\x80",
                             "\xf4\x90\x80\x80", "\xfe", "a\xff" "b\xc3(c"};
        for (size_t k = 0; k < sizeof raw / sizeof raw[0]; k++) {
            char body[256];
            snprintf(body, sizeof body, "{\"params\":{\"window\":\"%s\"}}", raw[k]);
            post_ok("vib-dft", body, 400, "bad_value", "window");
            snprintf(body, sizeof body, "{\"params\":{\"signal\":\"%s\"}}", raw[k]);
            post_ok("vib-dft", body, 400, "bad_value", "signal");
            snprintf(body, sizeof body, "{\"params\":{\"%s\":1}}", raw[k]);
            post_ok("vib-dft", body, 400, "unknown_param", NULL);
            snprintf(body, sizeof body, "{\"params\":{\"N\":\"8%s\"}}", raw[k]);
            post_ok("vib-dft", body, 400, "bad_value", "N");
            snprintf(body, sizeof body, "{\"params\":{\"N\":8},\"%s\":1}", raw[k]);
            post_ok("vib-dft", body, 400, "bad_json", "");
        }
        /* escapes that are not characters: a lone surrogate is not JSON for cJSON */
        post_ok("vib-dft", "{\"params\":{\"window\":\"\\ud800\"}}", 400, "bad_json|bad_value", NULL);
        post_ok("vib-dft", "{\"params\":{\"window\":\"\\udc00x\"}}", 400, "bad_json|bad_value", NULL);
        post_ok("vib-dft", "{\"params\":{\"window\":\"\\u00e9\"}}", 400, "bad_value", "window");
    }
    /* a body that is not UTF-8 at all, and one in UTF-16 */
    post_ok("vib-sdof-forced", "\xff\xfe{\x00}\x00", 400, "bad_json|bad_value", NULL);
    post_ok("vib-sdof-forced", "\xef\xbb\xbf{\"params\":{}}", 0, "bad_json", "");   /* a BOM: cJSON skips it */
}

/* ---- NUL bytes ---------------------------------------------------------------------------------- */

static void nul_bytes_should_never_cut_a_value_short(void **state)
{
    (void)state;
    const char *base = "/api/exercises/vib-sdof-forced/solve";
    char path[256];
    snprintf(path, sizeof path, "%s?%%00=1", base);                 /* in a name */
    get_ok(path, 400, "bad_value|unknown_param", NULL);
    snprintf(path, sizeof path, "%s?m%%00=1", base);
    get_ok(path, 400, "bad_value|unknown_param", NULL);
    snprintf(path, sizeof path, "%s?m=%%00", base);
    get_ok(path, 400, "bad_value", NULL);
    snprintf(path, sizeof path, "%s?m=2%%00junk", base);
    get_ok(path, 400, "bad_value", NULL);
    if (registered("vib-dft")) {
        get_ok("/api/exercises/vib-dft/solve?window=rect%00junk", 400, "bad_value", NULL);
        get_ok("/api/exercises/vib-dft/solve?signal=sin(t)%00*0", 400, "bad_value", NULL);
        get_ok("/api/exercises/vib-dft%00/solve", 404, "not_found", "");
    }
    /* in JSON: the \u0000 escape, and a raw NUL byte, in values and keys:
     * "2\u0000junk" must not read as "2" */
    post_ok("vib-sdof-forced", "{\"params\":{\"m\":\"2\\u0000junk\"}}", 400, "bad_value", "m");
    post_ok("vib-sdof-forced", "{\"params\":{\"m\":\"\\u0000\"}}", 400, "bad_value", "m");
    post_ok("vib-sdof-forced", "{\"params\":{\"k\":1,\"m\":\"2\\u0000\"}}", 400, "bad_value", "m");
    post_ok("vib-sdof-forced", "{\"params\":{\"m\\u0000x\":2}}", 400, "bad_value|unknown_param", NULL);
    post_ok("vib-sdof-forced", "{\"params\":{\"m\":\"2\\\\u0000\"}}", 400, "bad_value", "m"); /* "\\u0000": text */
    static const char raw[] = "{\"params\":{\"m\":\"2\0junk\"}}";
    cJSON_Delete(post("vib-sdof-forced", raw, sizeof raw - 1, 400, "bad_value|bad_json", NULL));
    static const char raw_out[] = "{\"params\":{\"m\":2}}\0{\"params\":{\"m\":3}}";
    cJSON_Delete(post("vib-sdof-forced", raw_out, sizeof raw_out - 1, 400, "bad_json", NULL));
    if (registered("num-linear-system"))
        post_ok("num-linear-system", "{\"params\":{\"A\":[[\"1\\u0000\",2],[3,4]],\"b\":[1,2]}}", 400,
                "bad_value", "A");
    if (registered("vib-dft"))
        post_ok("vib-dft", "{\"params\":{\"window\":\"rect\\u0000junk\"}}", 400, "bad_value", "window");
}

/* ---- duplicate and unknown parameters ---------------------------------------------------------- */

static void duplicate_parameters_should_be_refused_in_the_query_and_in_json(void **state)
{
    (void)state;
    const char *base = "/api/exercises/vib-sdof-forced/solve";
    const char *queries[] = {"m=1&m=1", "m=1&m=2", "m=1&%6d=2", "m=1&k=3&m=1", "points=11&points=11"};
    const char *names[] = {"m", "m", "m", "m", "points"};
    for (size_t k = 0; k < sizeof queries / sizeof queries[0]; k++) {
        char path[256];
        snprintf(path, sizeof path, "%s?%s", base, queries[k]);
        get_ok(path, 400, "bad_value", names[k]);
    }
    post_ok("vib-sdof-forced", "{\"params\":{\"m\":1,\"m\":1}}", 400, "bad_value", "m");
    post_ok("vib-sdof-forced", "{\"params\":{\"m\":1,\"k\":5,\"m\":\"2\"}}", 400, "bad_value", "m");
    post_ok("vib-sdof-forced", "{\"params\":{\"m\":1},\"params\":{\"m\":2}}", 400, "bad_json", "");
    if (registered("vib-dft"))
        post_ok("vib-dft", "{\"params\":{\"window\":\"rect\",\"window\":\"hann\"}}", 400, "bad_value", "window");
}

static void unknown_parameters_should_be_named(void **state)
{
    (void)state;
    const char *base = "/api/exercises/vib-sdof-forced/solve";
    char path[4096];
    snprintf(path, sizeof path, "%s?mass=1", base);
    get_ok(path, 400, "unknown_param", "mass");
    snprintf(path, sizeof path, "%s?M=1", base);                     /* names are case-sensitive */
    get_ok(path, 400, "unknown_param", "M");
    snprintf(path, sizeof path, "%s?m%%20=1", base);
    get_ok(path, 400, "unknown_param", "m ");
    snprintf(path, sizeof path, "%s?=1", base);
    get_ok(path, 400, "unknown_param", "");
    snprintf(path, sizeof path, "%s?&&m=2&&", base);                 /* empty pairs are nothing */
    get_ok(path, 200, NULL, NULL);
    int n = snprintf(path, sizeof path, "%s?", base);                /* a 2000-character name */
    memset(path + n, 'z', 2000);
    strcpy(path + n + 2000, "=1");
    cJSON *j = get(path, 400, "unknown_param", NULL);
    const cJSON *p = cJSON_GetObjectItem(cJSON_GetObjectItem(j, "error"), "param");
    assert_true(cJSON_IsString(p) && strlen(p->valuestring) < 48);  /* echoed, cut short */
    cJSON_Delete(j);
    n = snprintf(path, sizeof path, "%s?", base);                    /* 40 parameters */
    for (int i = 0; i < 40; i++)
        n += snprintf(path + n, sizeof path - (size_t)n, "%sp%d=1", i ? "&" : "", i);
    get_ok(path, 400, "unknown_param", NULL);

    post_ok("vib-sdof-forced", "{\"params\":{\"mass\":1}}", 400, "unknown_param", "mass");
    post_ok("vib-sdof-forced", "{\"params\":{\"\":1}}", 400, "unknown_param", "");
    post_ok("vib-sdof-forced", "{\"params\":{\"m\":1},\"extra\":1}", 400, "bad_json", "");
    post_ok("vib-sdof-forced", "{\"parameters\":{\"m\":1}}", 400, "bad_json", "");
    char body[8192];
    n = snprintf(body, sizeof body, "{\"params\":{");
    for (int i = 0; i < 40; i++)
        n += snprintf(body + n, sizeof body - (size_t)n, "%s\"p%d\":1", i ? "," : "", i);
    snprintf(body + n, sizeof body - (size_t)n, "}}");
    post_ok("vib-sdof-forced", body, 400, "unknown_param", NULL);
}

/* ---- large things -------------------------------------------------------------------------------- */

static void huge_bodies_and_queries_should_get_413_and_leave_the_server_up(void **state)
{
    (void)state;
    /* 10 MB sent chunked (no Content-Length): the size is found while reading */
    size_t big = 10u << 20;
    char *body = malloc(big + 1);
    memset(body, ' ', big);
    body[0] = '{';
    body[big - 1] = '}';
    body[big] = '\0';
    CURL *c = curl_easy_init();
    char url[128];
    snprintf(url, sizeof url, "http://127.0.0.1:%d/api/exercises/vib-sdof-forced/solve", server.port);
    mm_reply r;
    memset(&r, 0, sizeof r);
    r.body = calloc(1, 1);
    struct curl_slist *h = curl_slist_append(NULL, "Transfer-Encoding: chunked");
    h = curl_slist_append(h, "Content-Type: application/json");
    h = curl_slist_append(h, "Expect:");
    curl_easy_setopt(c, CURLOPT_URL, url);
    curl_easy_setopt(c, CURLOPT_POST, 1L);
    curl_easy_setopt(c, CURLOPT_POSTFIELDS, body);
    curl_easy_setopt(c, CURLOPT_HTTPHEADER, h);
    curl_easy_setopt(c, CURLOPT_WRITEFUNCTION, mm_collect);
    curl_easy_setopt(c, CURLOPT_WRITEDATA, &r);
    curl_easy_setopt(c, CURLOPT_HEADERFUNCTION, mm_collect_header);
    curl_easy_setopt(c, CURLOPT_HEADERDATA, &r);
    curl_easy_setopt(c, CURLOPT_TIMEOUT, 30L);
    double t0 = now_s();
    assert_int_equal(curl_easy_perform(c), CURLE_OK);
    curl_easy_getinfo(c, CURLINFO_RESPONSE_CODE, &r.status);
    cJSON_Delete(check_reply("10 MB chunked", &r, now_s() - t0, 413, "too_large", ""));
    mm_reply_free(&r);
    curl_slist_free_all(h);
    curl_easy_cleanup(c);

    /* a valid body just over 1 MiB: a long text value */
    size_t n = (1u << 20) + 100;
    int k = snprintf(body, big, "{\"params\":{\"m\":\"");
    memset(body + k, '1', n);
    strcpy(body + k + n, "\"}}");
    cJSON_Delete(post("vib-sdof-forced", body, strlen(body), 413, "too_large", ""));
    /* and just under it: refused for what it says, not for its size */
    n = (1u << 20) - 100;
    memset(body + k, '1', n);
    strcpy(body + k + n, "\"}}");
    cJSON_Delete(post("vib-sdof-forced", body, strlen(body), 400, "out_of_range|bad_value", "m"));

    /* queries: over our 16 KiB limit -> 413 as JSON, up to the connection
     * memory of libmicrohttpd (32 KiB with the headers: see mm_http.c) */
    char *path = body;
    k = snprintf(path, big, "/api/exercises/vib-sdof-forced/solve?m=");
    for (size_t len = 17u << 10; len <= (30u << 10); len += 13u << 10) {
        memset(path + k, '1', len);
        path[k + len] = '\0';
        get_ok(path, 413, "too_large", "");
    }
    /* far over it (4 MB; curl sends no URL over 8 MB): libmicrohttpd itself
     * refuses it before our code sees it, with 414 and a small HTML page
     * (its own, not configurable in 0.9.75); what matters is that the
     * server stays up */
    size_t huge = 4u << 20;
    memset(path + k, '1', huge - (size_t)k - 1);
    path[huge - 1] = '\0';
    int rc = mm_http(&server, NULL, path, NULL, 0, &r);
    print_message("   4 MB query: %s, status %ld\n", rc == 0 ? "answered" : "connection closed", r.status);
    assert_true(rc != 0 || r.status == 413 || r.status == 414 || r.status == 431);
    mm_reply_free(&r);
    free(body);
    get_ok("/api/health", 200, NULL, NULL);
}

static void a_matrix_of_a_million_elements_should_be_refused_quickly(void **state)
{
    (void)state;
    if (!registered("num-linear-system"))
        return;
    /* 1000 x 1000 as nested JSON arrays (2 MB): over the body limit */
    size_t cap = 8u << 20;
    char *body = malloc(cap);
    size_t n = (size_t)snprintf(body, cap, "{\"params\":{\"A\":[");
    for (int i = 0; i < 1000; i++) {
        body[n++] = i ? ',' : ' ';
        body[n++] = '[';
        for (int j = 0; j < 1000; j++) {
            if (j)
                body[n++] = ',';
            body[n++] = (char)('0' + (i == j));
        }
        body[n++] = ']';
    }
    n += (size_t)snprintf(body + n, cap - n, "]}}");
    cJSON_Delete(post("num-linear-system", body, n, 413, "too_large", ""));

    /* the same as MATLAB text in a JSON string */
    n = (size_t)snprintf(body, cap, "{\"params\":{\"A\":\"");
    for (int i = 0; i < 1000; i++)
        for (int j = 0; j < 1000; j++) {
            body[n++] = (char)('0' + (i == j));
            body[n++] = j < 999 ? ',' : ';';
        }
    n += (size_t)snprintf(body + n, cap - n, "\"}}");
    cJSON_Delete(post("num-linear-system", body, n, 413, "too_large", ""));

    /* 500 x 500 = 250 000 elements, under the body limit: the size limit
     * of A answers, naming it */
    n = (size_t)snprintf(body, cap, "{\"params\":{\"A\":[");
    for (int i = 0; i < 500; i++) {
        body[n++] = i ? ',' : ' ';
        body[n++] = '[';
        for (int j = 0; j < 500; j++) {
            if (j)
                body[n++] = ',';
            body[n++] = (char)('0' + (i == j));
        }
        body[n++] = ']';
    }
    n += (size_t)snprintf(body + n, cap - n, "]}}");
    cJSON_Delete(post("num-linear-system", body, n, 400, "out_of_range", "A"));
    /* as text, and as one long row, and as a column */
    n = (size_t)snprintf(body, cap, "{\"params\":{\"A\":\"");
    for (int i = 0; i < 250000; i++) {
        body[n++] = '1';
        body[n++] = i % 500 == 499 ? ';' : ',';
    }
    n += (size_t)snprintf(body + n, cap - n, "\"}}");
    cJSON_Delete(post("num-linear-system", body, n, 400, "out_of_range", "A"));
    n = (size_t)snprintf(body, cap, "{\"params\":{\"A\":[[");
    for (int i = 0; i < 400000; i++) {
        body[n++] = i ? ',' : ' ';
        body[n++] = '1';
    }
    n += (size_t)snprintf(body + n, cap - n, "]]}}");
    cJSON_Delete(post("num-linear-system", body, n, 400, "out_of_range", "A"));
    n = (size_t)snprintf(body, cap, "{\"params\":{\"b\":[");
    for (int i = 0; i < 400000; i++) {
        body[n++] = i ? ',' : ' ';
        body[n++] = '1';
    }
    n += (size_t)snprintf(body + n, cap - n, "]}}");
    cJSON_Delete(post("num-linear-system", body, n, 400, "out_of_range", "b"));
    /* one row over the limit, and arrays nested three deep */
    post_ok("num-linear-system", "{\"params\":{\"A\":\"1,2,3,4,5,6,7,8,9,10,11,12,13\"}}", 400, "out_of_range", "A");
    post_ok("num-linear-system", "{\"params\":{\"A\":[[[1]]]}}", 400, "bad_value", "A");
    /* deep nesting inside a parameter: cJSON's nesting limit answers */
    n = (size_t)snprintf(body, cap, "{\"params\":{\"A\":");
    for (int i = 0; i < 5000; i++)
        body[n++] = '[';
    for (int i = 0; i < 5000; i++)
        body[n++] = ']';
    n += (size_t)snprintf(body + n, cap - n, "}}");
    cJSON_Delete(post("num-linear-system", body, n, 400, "bad_json|bad_value", NULL));
    n = (size_t)snprintf(body, cap, "{\"params\":");
    for (int i = 0; i < 5000; i++)
        n += (size_t)snprintf(body + n, cap - n, "{\"a\":");
    body[n++] = '1';
    for (int i = 0; i < 5000; i++)
        body[n++] = '}';
    body[n++] = '}';
    cJSON_Delete(post("num-linear-system", body, n, 400, "bad_json|bad_value|unknown_param", NULL));
    free(body);
}

/* ---- expressions ------------------------------------------------------------------------------------ */

/* The longest texts an expression may be, each bounded in cost: muParser
 * compiles to linear bytecode with no loops and no recursion. */
static void longest_texts(const char *v, char out[4][600])
{
    size_t vl = strlen(v);
    out[0][0] = out[1][0] = out[2][0] = out[3][0] = '\0';
    for (int i = 0; i < 255; i++)
        strcat(out[0], "(");                         /* 255 nested parentheses */
    strcat(out[0], v);
    for (int i = 0; i < 255; i++)
        strcat(out[0], ")");
    for (int i = 0; i < 102; i++)
        strcat(out[1], "sin(");                      /* 102 nested calls */
    strcat(out[1], v);
    for (int i = 0; i < 102; i++)
        strcat(out[1], ")");
    for (size_t len = 0; len + vl + (len ? 1 : 0) <= 512; len = strlen(out[2])) {
        if (len)
            strcat(out[2], "^");                     /* a power tower: pow on every 2nd char */
        strcat(out[2], v);
    }
    strcpy(out[3], "sign(sin(3141.59*");             /* a jump every 1e-3, and the tower */
    strcat(out[3], v);
    strcat(out[3], "))+0*");
    for (size_t len = strlen(out[3]), first = 1; len + vl + !first <= 512; len = strlen(out[3]), first = 0) {
        if (!first)
            strcat(out[3], "^");
        strcat(out[3], v);
    }
}

static void expressions_that_divide_by_zero_or_never_end_should_be_bounded(void **state)
{
    (void)state;
    int roots = registered("num-nonlinear-roots"), dft = registered("vib-dft");
    const char *divs[] = {"1/0", "x/0", "0/0", "1/(x-x)", "ln(0)", "sqrt(-1-x^2)", "exp(1e6)", "0*1/0"};
    char path[2048];
    for (size_t k = 0; roots && k < sizeof divs / sizeof divs[0]; k++) {
        char *enc = curl_easy_escape(NULL, divs[k], 0);
        snprintf(path, sizeof path, "/api/exercises/num-nonlinear-roots/solve?f=%s", enc);
        /* f nowhere finite: an error naming f, or an answer that says so */
        cJSON *j = get(path, 0, "bad_value|no_solution", NULL);
        if (!cJSON_GetObjectItem(j, "error")) {
            const cJSON *w = cJSON_GetObjectItem(j, "warnings");
            if (cJSON_GetArraySize(w) == 0 || !strstr(cJSON_GetArrayItem(w, 0)->valuestring, "not finite"))
                fail_msg("%s: a 200 that does not say f is not finite", path);
        }
        cJSON_Delete(j);
        curl_free(enc);
    }
    if (roots) {
        get_ok("/api/exercises/num-nonlinear-roots/solve?f=1%2Fx", 200, NULL, NULL);   /* a pole, not a root */
        get_ok("/api/exercises/num-nonlinear-roots/solve?f=tan(x)&n=1000", 200, NULL, NULL);
        get_ok("/api/exercises/num-nonlinear-roots/solve?f=x%3D1", 400, "bad_value", "f");
        get_ok("/api/exercises/num-nonlinear-roots/solve?f=x,1", 400, "bad_value", "f");
        get_ok("/api/exercises/num-nonlinear-roots/solve?f=y", 400, "bad_value", "f");
        get_ok("/api/exercises/num-nonlinear-roots/solve?f=system(1)", 400, "bad_value", "f");
    }
    const char *sdivs[] = {"1/0", "1/t", "0/0", "t/(t-t)", "ln(t)", "sqrt(-1)"};
    for (size_t k = 0; dft && k < sizeof sdivs / sizeof sdivs[0]; k++) {
        char *enc = curl_easy_escape(NULL, sdivs[k], 0);
        snprintf(path, sizeof path, "/api/exercises/vib-dft/solve?signal=%s", enc);
        get_ok(path, 0, "bad_value|no_solution", "signal");
        curl_free(enc);
    }

    /* the longest texts, with the most work the limits allow */
    char texts[4][600];
    const char *what[] = {"255 nested parentheses", "102 nested sin", "a power tower", "jumps + tower"};
    for (int k = 0; k < 4; k++) {
        char *enc;
        double t0;
        /* n (N) times the length of the text is a joint limit: over it, a
         * 400 naming n (N) before any work; at it, the answer in bounded time */
        if (roots) {
            longest_texts("x", texts);
            enc = curl_easy_escape(NULL, texts[k], 0);
            double len = fmax((double)strlen(texts[k]), 16);
            snprintf(path, sizeof path, "/api/exercises/num-nonlinear-roots/solve?f=%s&a=0.0001&b=1&n=1000&tol=1e-15",
                     enc);
            get_ok(path, 400, "out_of_range", "n");
            int nmax = (int)floor(120000 / len);
            snprintf(path, sizeof path, "/api/exercises/num-nonlinear-roots/solve?f=%s&a=0.0001&b=1&n=%d&tol=1e-15",
                     enc, nmax);
            t0 = now_s();
            get_ok(path, 0, "bad_value|no_solution", "f");
            print_message("   num-nonlinear-roots, %-22s (%zu chars), n=%d: %6.1f ms\n", what[k],
                          strlen(texts[k]), nmax, 1e3 * (now_s() - t0));
            curl_free(enc);
        }
        if (dft) {
            longest_texts("t", texts);
            enc = curl_easy_escape(NULL, texts[k], 0);
            double len = fmax((double)strlen(texts[k]), 32);
            snprintf(path, sizeof path, "/api/exercises/vib-dft/solve?signal=%s&N=65536&fs=1e6", enc);
            get_ok(path, 400, "out_of_range", "N");
            int nmax = (int)floor(8e6 / len);
            snprintf(path, sizeof path, "/api/exercises/vib-dft/solve?signal=%s&N=%d&fs=1e6", enc, nmax);
            t0 = now_s();
            get_ok(path, 0, "bad_value|no_solution", "signal");
            print_message("   vib-dft, %-22s (%zu chars), N=%d: %6.1f ms\n", what[k], strlen(texts[k]), nmax,
                          1e3 * (now_s() - t0));
            curl_free(enc);
        }
    }
    /* one character over the limit, and deeper nesting than the limit allows */
    if (roots) {
        char over[600] = "";
        for (int i = 0; i < 256; i++)
            strcat(over, "(");
        strcat(over, "x");
        for (int i = 0; i < 256; i++)
            strcat(over, ")");
        snprintf(path, sizeof path, "/api/exercises/num-nonlinear-roots/solve?f=%s", over);
        get_ok(path, 400, "out_of_range", "f");
        char unbalanced[600] = "";
        for (int i = 0; i < 500; i++)
            strcat(unbalanced, "(");
        strcat(unbalanced, "x");
        snprintf(path, sizeof path, "/api/exercises/num-nonlinear-roots/solve?f=%s", unbalanced);
        get_ok(path, 400, "bad_value", "f");
    }
}

/* ---- path traversal, further encodings ---------------------------------------------------------- */

static void no_encoding_of_a_traversal_should_leave_the_web_root(void **state)
{
    (void)state;
    const char *attacks[] = {
        "/.%2e/Makefile", "/%2e./Makefile", "/..%2FMakefile", "/%2E%2e%2FMakefile", "/..%5CMakefile",
        "/%252e%252e%252fMakefile", "/%25252e%25252e/Makefile", "/%c0%ae%c0%ae/Makefile",
        "/%c0%ae%c0%ae%c0%afMakefile", "/%e0%80%ae%e0%80%ae/Makefile", "/%f0%80%80%ae%f0%80%80%ae/Makefile",
        "/%u002e%u002e/Makefile", "/%u002e%u002e%u2215Makefile", "/%ef%bc%8e%ef%bc%8e%ef%bc%8fMakefile",
        "/..;/Makefile", "/..%00/Makefile", "/..%0d%0a/Makefile", "/..%09/Makefile", "/.%00./Makefile",
        "/./././../Makefile", "//../Makefile", "///..//..//Makefile", "/.../Makefile", "/..../Makefile",
        "/js/../../Makefile", "/js/..%2f..%2fMakefile", "/css/%2e%2e/%2e%2e/server/mm_http.c",
        "/%2e%2e/%2e%2e/%2e%2e/%2e%2e/%2e%2e/etc/passwd", "/..%2f..%2f..%2f..%2f..%2fetc%2fpasswd",
        "/vendor/..%2f..%2fMakefile", "/vendor/%2e%2e/Makefile", "/vendor/%252e%252e/Makefile",
        "/vendor/katex/../../Makefile", "/api/../Makefile", "/api/..%2fMakefile",
        "/api/exercises/..%2f..%2fMakefile", "/api/exercises/%2e%2e%2f%2e%2e%2fMakefile/solve",
        "/api/exercises/../../Makefile/solve", "/api/exercises/%2e%2e", "/api/exercises/.",
        "/api/exercises/vib-sdof-forced/../../../Makefile", "/Makefile", "/README.md", "/server/mm_http.c",
        "/web/index.html", "/.git/config", "/%2egit/config", "/exercises/vib/sdof_forced.c",
        "/index.html/../../Makefile", "/index.html%2f..%2f..%2fMakefile", "/C:%5cwindows%5cwin.ini",
        "/file:///etc/passwd", "/%2fetc%2fpasswd", "/%2F%2Fetc%2Fpasswd",
    };
    for (size_t i = 0; i < sizeof attacks / sizeof attacks[0]; i++) {
        mm_reply r;
        if (mm_http(&server, NULL, attacks[i], NULL, 0, &r) != 0)
            fail_msg("%s: no answer", attacks[i]);
        if (strstr(r.body, "non-recursive Makefile") || strstr(r.body, "root:x:") ||
            strstr(r.body, "[core]") || strstr(r.body, "#include") || strstr(r.body, "[fonts]") ||
            strstr(r.body, "# mechmat"))
            fail_msg("%s was served: %ld %.80s", attacks[i], r.status, r.body);
        if (r.status != 404 && r.status != 400)
            fail_msg("%s: status %ld", attacks[i], r.status);
        cJSON_Delete(check_reply(attacks[i], &r, 0, 0, "not_found|bad_value", NULL));
        mm_reply_free(&r);
    }
}

/* ---- determinism across threads -------------------------------------------------------------------- */

typedef struct job {
    const char *path, *want;
    int differed, errors;
} job;

static void strip_elapsed(char *s)
{
    char *e = strstr(s, ",\"elapsed_us\":");
    if (e)
        *e = '\0';
}

static void *ask_again(void *arg)
{
    job *j = arg;
    for (int i = 0; i < 20; i++) {
        mm_reply r;
        if (mm_http(&server, NULL, j->path, NULL, 0, &r) != 0 || r.status != 200) {
            j->errors++;
        } else {
            strip_elapsed(r.body);
            j->differed += strcmp(r.body, j->want) != 0;
        }
        mm_reply_free(&r);
    }
    return NULL;
}

static void one_request_from_eight_threads_should_give_identical_bytes(void **state)
{
    (void)state;
    cJSON *cat = get("/api/exercises", 200, NULL, NULL);
    int n = cJSON_GetArraySize(cat), total = 0;
    /* every exercise at its defaults, and a few with sizes that differ
     * from the defaults (FFT plans made while other threads use theirs) */
    char paths[64 + 8][200];
    int np = 0;
    const cJSON *row;
    cJSON_ArrayForEach(row, cat) if (np < 64) snprintf(paths[np++], sizeof paths[0], "/api/exercises/%s/solve",
                                                       cJSON_GetObjectItem(row, "id")->valuestring);
    const char *more[] = {"/api/exercises/vib-dft/solve?N=1000&window=hann",
                          "/api/exercises/vib-dft/solve?N=4097&fs=1000",
                          "/api/exercises/vib-sdof-forced/solve?m=2&k=50&c=1&F0=3&omega=4",
                          "/api/exercises/num-linear-system/solve?A=4,1;1,3&b=1,2",
                          "/api/exercises/num-nonlinear-roots/solve?f=sin(x)&a=-10&b=10"};
    for (size_t k = 0; k < sizeof more / sizeof more[0]; k++)
        snprintf(paths[np++], sizeof paths[0], "%s", more[k]);
    cJSON_Delete(cat);

    for (int p = 0; p < np; p++) {
        mm_reply ref;
        assert_int_equal(mm_http(&server, NULL, paths[p], NULL, 0, &ref), 0);
        if (ref.status == 404) {                  /* one of `more` not registered */
            mm_reply_free(&ref);
            continue;
        }
        cJSON_Delete(check_reply(paths[p], &ref, 0, 200, NULL, NULL));
        strip_elapsed(ref.body);
        enum { T = 8 };
        pthread_t th[T];
        job jobs[T];
        for (int t = 0; t < T; t++) {
            jobs[t] = (job){paths[p], ref.body, 0, 0};
            pthread_create(&th[t], NULL, ask_again, &jobs[t]);
        }
        int differed = 0, errors = 0;
        for (int t = 0; t < T; t++) {
            pthread_join(th[t], NULL);
            differed += jobs[t].differed;
            errors += jobs[t].errors;
        }
        if (differed || errors)
            fail_msg("%s: %d of %d answers differed, %d errors", paths[p], differed, T * 20, errors);
        total += T * 20;
        mm_reply_free(&ref);
    }
    print_message("   %d exercises + %d more requests, %d answers from 8 threads, all byte-identical\n", n,
                  np - n, total);
}

int main(void)
{
    curl_global_init(CURL_GLOBAL_DEFAULT);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(empty_values_should_be_bad_values_naming_the_parameter),
        cmocka_unit_test(huge_and_non_finite_numbers_should_be_refused_in_every_numeric_parameter),
        cmocka_unit_test(negative_sizes_should_be_out_of_range),
        cmocka_unit_test(invalid_utf8_should_come_back_as_valid_json),
        cmocka_unit_test(nul_bytes_should_never_cut_a_value_short),
        cmocka_unit_test(duplicate_parameters_should_be_refused_in_the_query_and_in_json),
        cmocka_unit_test(unknown_parameters_should_be_named),
        cmocka_unit_test(huge_bodies_and_queries_should_get_413_and_leave_the_server_up),
        cmocka_unit_test(a_matrix_of_a_million_elements_should_be_refused_quickly),
        cmocka_unit_test(expressions_that_divide_by_zero_or_never_end_should_be_bounded),
        cmocka_unit_test(no_encoding_of_a_traversal_should_leave_the_web_root),
        cmocka_unit_test(one_request_from_eight_threads_should_give_identical_bytes),
    };
    int rc = cmocka_run_group_tests_name("bad input", tests, setup, teardown);
    curl_global_cleanup();
    return rc;
}
