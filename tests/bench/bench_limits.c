/* bench_limits.c — is every exercise bounded by design?  For every exercise
 * of the registry, time whole requests (parse, validate, solve, write JSON:
 * what one request costs a server thread) at
 *   - its defaults;
 *   - each real/integer parameter alone at its min and at its max;
 *   - each choice value;
 *   - each vector at its max length and each matrix at its max size (the
 *     default repeated, and a symmetric diagonally dominant one);
 *   - each expression at its longest (the default repeated up to the length
 *     limit: as much work per evaluation as a valid text can ask for);
 *   - "everything at its heaviest": every integer parameter at its max,
 *     arrays at their max size, expressions at their longest (and the same
 *     with every real parameter at its max, and at its min);
 *   - MM_LIMIT_DRAWS (default 200) random draws inside the limits: half as
 *     in test_exercises.c (log-uniform over wide positive ranges), half
 *     pulled to the corners (each parameter at min, max or a random value,
 *     a third each) where the most expensive combinations live;
 * then re-time the slowest of each exercise (median of 3) and report it with
 * the parameters that made it.  Flags: over MM_LIMIT_MS (default 250 ms), a
 * 5xx, a 422 for a non-finite result that the exercise let through to the
 * JSON writer (an exercise's own 422 for an f that is nowhere finite is a
 * fair answer), an answer that is not JSON or holds a nan/inf.  Exit status 1 when anything is flagged (make bench goes on).
 * MM_SEED seeds the draws; MM_LIMIT_ONLY=id runs one exercise. */
#include <cJSON.h>
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

#define TEXT_MAX 8192            /* one value as text: 12x12 matrices and the like */

static mm_rng rng;                /* the product's generator (mm_draw.h) */

static double urand(void) { return mm_rng_uniform(&rng); }

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---- a request: one text per parameter, NULL = the default ---------------------- */

typedef struct request {
    char *text[MM_MAX_PARAMS];
    char label[96];
} request;

static void req_clear(request *r)
{
    for (int k = 0; k < MM_MAX_PARAMS; k++) {
        free(r->text[k]);
        r->text[k] = NULL;
    }
    r->label[0] = '\0';
}

static void req_set(request *r, int k, const char *text)
{
    free(r->text[k]);
    r->text[k] = text ? strdup(text) : NULL;
}

static void req_copy(request *dst, const request *src)
{
    req_clear(dst);
    for (int k = 0; k < MM_MAX_PARAMS; k++)
        dst->text[k] = src->text[k] ? strdup(src->text[k]) : NULL;
    snprintf(dst->label, sizeof dst->label, "%s", src->label);
}

/* ---- values -------------------------------------------------------------------- */

static void num_text(double v, char *buf) { mm_dtoa(v, buf); }

static int n_choices(const mm_param *p)
{
    int n = 0;
    while (p->choices && p->choices[n])
        n++;
    return n;
}

/* A number inside p's limits, drawn as test_exercises.c does. */
static double draw_number(const mm_param *p) { return mm_draw_number(p, &rng); }

/* The default of an array parameter as numbers (rows x cols). */
static int array_default(const mm_param *p, double **data, int *rows, int *cols)
{
    mm_result arena;
    mm_value v;
    mm_error err;
    mm_result_init(&arena, 1 << 22);
    int rc = mm_param_default(p, &v, &arena, &err);
    if (rc == MM_OK) {
        *rows = v.rows;
        *cols = v.cols;
        *data = malloc((size_t)(v.rows * v.cols) * sizeof(double));
        memcpy(*data, v.data, (size_t)(v.rows * v.cols) * sizeof(double));
    }
    mm_result_release(&arena);
    return rc;
}

/* Write rows x cols numbers f(i, j) clamped to p's limits as text. */
static void array_text(const mm_param *p, int rows, int cols, const double *d, double scale,
                       char *out, size_t size)
{
    size_t len = 0;
    char num[MM_DTOA_BUFSIZE];
    out[0] = '\0';
    for (int i = 0; i < rows; i++) {
        for (int j = 0; j < cols; j++) {
            double x = fmin(fmax(d[i * cols + j] * scale, p->min), p->max);
            num_text(x, num);
            len += (size_t)snprintf(out + len, len < size ? size - len : 0, "%s%s", j ? "," : "", num);
        }
        if (i + 1 < rows)
            len += (size_t)snprintf(out + len, len < size ? size - len : 0, "%s",
                                    p->kind == MM_MATRIX ? ";" : ",");
    }
}

/* An array at its max size: variant 0 repeats the default cyclically,
 * variant 1 is symmetric and diagonally dominant (a valid stiffness or mass
 * matrix, a non-singular system) where the limits allow it. */
static void array_max(const mm_param *p, int variant, char *out, size_t size)
{
    double *def = NULL;
    int dr = 1, dc = 1;
    if (array_default(p, &def, &dr, &dc) != MM_OK || dr * dc == 0) {
        snprintf(out, size, "%s", p->def_text ? p->def_text : "1");
        free(def);
        return;
    }
    int rows = p->kind == MM_MATRIX ? p->max_rows : 1, cols = p->max_cols;
    if (p->kind == MM_MATRIX && variant == 1 && rows != cols)
        rows = cols = rows < cols ? rows : cols;
    double *d = malloc((size_t)rows * (size_t)cols * sizeof(double));
    double big = fmin(p->max, 2.0 * cols + 2), small = p->min < 0 ? fmax(p->min, -1.0) : fmin(p->max, 0.5 + p->min);
    for (int i = 0; i < rows; i++)
        for (int j = 0; j < cols; j++) {
            if (variant == 0)
                d[i * cols + j] = def[(i % dr) * dc + (j % dc)];
            else if (p->kind == MM_VECTOR)
                d[i * cols + j] = p->min + (p->max - p->min) * ((j % 7) + 1) / 8.0;
            else
                d[i * cols + j] = i == j ? big : (abs(i - j) == 1 ? small : 0.0);
        }
    array_text(p, rows, cols, d, 1.0, out, size);
    free(d);
    free(def);
}

/* The first variable of an expression parameter ("x"). */
static void first_var(const mm_param *p, char *v, size_t size)
{
    const char *s = p->vars ? p->vars : "x";
    while (*s == ' ' || *s == ',')
        s++;
    size_t n = strcspn(s, ", ");
    if (n == 0 || n >= size)
        s = "x", n = 1;
    memcpy(v, s, n);
    v[n] = '\0';
}

/* Expressions at the length limit, heaviest first found by hand (see
 * test_expr.c for the cost per evaluation):
 *   0  the default repeated, "(f)+(f)+...": this exercise's own text;
 *   1  a power tower "x^x^...^x": about 3.6 us per evaluation, the most
 *      expensive text per character found (pow on every second character);
 *   2  "sign(sin(3141.59*x))+0*x^x^...^x": the tower, plus a jump through
 *      zero every 1e-3 in x: root finders bisect every one of them. */
enum { EXPR_FORMS = 3 };
static const char *const expr_form_name[EXPR_FORMS] = {"default repeated", "power tower",
                                                        "jumps + power tower"};

static void expr_longest(const mm_param *p, int form, char *out, size_t size)
{
    size_t max = MM_PARAM_EXPR_MAX < size - 1 ? MM_PARAM_EXPR_MAX : size - 1, len = 0;
    char v[40];
    first_var(p, v, sizeof v);
    out[0] = '\0';
    if (form == 0) {
        const char *f = p->def_text ? p->def_text : v;
        size_t flen = strlen(f);
        while (len + flen + 2 + (len ? 1 : 0) <= max)
            len += (size_t)snprintf(out + len, size - len, "%s(%s)", len ? "+" : "", f);
        if (len == 0)
            snprintf(out, size, "%s", f);
        return;
    }
    if (form == 2)
        len = (size_t)snprintf(out, size, "sign(sin(3141.59*%s))+0*", v);
    size_t vl = strlen(v);
    for (int first = 1; len + vl + (first ? 0 : 1) <= max; first = 0)
        len += (size_t)snprintf(out + len, size - len, "%s%s", first ? "" : "^", v);
}

/* A random valid text for p: corner = 0 as test_exercises.c, 1 = pulled to
 * the limits (min, max or random, a third each; arrays and expressions at
 * their heaviest a third of the time). */
static void draw(const mm_param *p, int corner, char *out, size_t size)
{
    double u = corner ? urand() : 1.0;
    switch (p->kind) {
    case MM_REAL:
    case MM_INT:
        num_text(u < 1.0 / 3 ? p->min : u < 2.0 / 3 ? p->max : draw_number(p), out);
        break;
    case MM_CHOICE: {
        int n = n_choices(p);
        snprintf(out, size, "%s", p->choices[(int)(urand() * n) % n]);
        break;
    }
    case MM_EXPR:
        if (u < 1.0 / 3)
            expr_longest(p, (int)(urand() * EXPR_FORMS) % EXPR_FORMS, out, size);
        else
            snprintf(out, size, "%s", p->def_text);
        break;
    case MM_VECTOR:
    case MM_MATRIX:
        if (u < 1.0 / 3) {
            array_max(p, 0, out, size);
        } else {                          /* the default's shape, each element scaled */
            double *def = NULL;
            int r = 1, c = 1;
            if (array_default(p, &def, &r, &c) != MM_OK) {
                snprintf(out, size, "%s", p->def_text);
                break;
            }
            int sym = p->kind == MM_MATRIX && r == c;
            for (int i = 0; sym && i < r; i++)
                for (int j = 0; j < i; j++)
                    if (def[i * c + j] != def[j * c + i])
                        sym = 0;
            double *f = malloc((size_t)(r * c) * sizeof(double));
            for (int k = 0; k < r * c; k++)
                f[k] = 0.5 + urand();
            for (int i = 0; i < r; i++)
                for (int j = 0; j < c; j++) {
                    int kf = sym && j < i ? j * c + i : i * c + j;
                    def[i * c + j] *= f[kf];
                }
            array_text(p, r, c, def, 1.0, out, size);
            free(f);
            free(def);
        }
        break;
    }
}

/* ---- running one request ------------------------------------------------------------ */

typedef struct outcome {
    int status;
    double ms;
    size_t bytes;
    char code[32], message[200];
    int bad_json, nonfinite_text;
} outcome;

/* A number token spelt nan/inf/NaN/Infinity outside strings? */
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
        } else if (strncmp(p, "nan", 3) == 0 || strncmp(p, "NaN", 3) == 0 ||
                   strncmp(p, "inf", 3) == 0 || strncmp(p, "Inf", 3) == 0) {
            return 1;
        }
    }
    return 0;
}

static outcome run(const mm_exercise *ex, const request *r)
{
    mm_input in[MM_MAX_PARAMS];
    int n = 0;
    for (int k = 0; k < ex->n_params; k++)
        if (r->text[k])
            in[n++] = (mm_input){ex->params[k].name, r->text[k], strlen(ex->params[k].name),
                                 strlen(r->text[k])};
    outcome o = {0};
    mm_buf out;
    mm_buf_init(&out, MM_ANSWER_MAX);
    double t0 = now_s();
    o.status = mm_api_solve(ex, in, n, &out);
    o.ms = (now_s() - t0) * 1e3;
    o.bytes = out.len;
    cJSON *doc = out.p ? cJSON_ParseWithLength(out.p, out.len) : NULL;
    if (!doc) {
        o.bad_json = 1;
    } else {
        const cJSON *e = cJSON_GetObjectItem(doc, "error");
        const cJSON *c = cJSON_GetObjectItem(e, "code"), *m = cJSON_GetObjectItem(e, "message");
        if (cJSON_IsString(c))
            snprintf(o.code, sizeof o.code, "%s", c->valuestring);
        if (cJSON_IsString(m))
            snprintf(o.message, sizeof o.message, "%s", m->valuestring);
        cJSON_Delete(doc);
    }
    o.nonfinite_text = out.p && has_nonfinite_token(out.p);
    mm_buf_free(&out);
    return o;
}

static void print_params(FILE *f, const mm_exercise *ex, const request *r, size_t max_value)
{
    int any = 0;
    for (int k = 0; k < ex->n_params; k++) {
        if (!r->text[k])
            continue;
        size_t len = strlen(r->text[k]);
        if (len > max_value)
            fprintf(f, "%s%s=%.*s...(%zu chars)", any ? "&" : "", ex->params[k].name,
                    (int)(max_value - 20), r->text[k], len);
        else
            fprintf(f, "%s%s=%s", any ? "&" : "", ex->params[k].name, r->text[k]);
        any = 1;
    }
    if (!any)
        fprintf(f, "(defaults)");
}

/* ---- one exercise ------------------------------------------------------------------- */

typedef struct summary {
    int cases, refused, ok, e4xx, e422, e5xx, flagged;
    double worst_ms;
    request worst;
    outcome worst_o;
} summary;

static double limit_ms;

static void consider(const mm_exercise *ex, summary *s, request *r)
{
    outcome o = run(ex, r);
    s->cases++;
    if (o.status == 200)
        s->ok++;
    else if (o.status == 422)
        s->e422++;
    else if (o.status >= 500)
        s->e5xx++;
    else
        s->e4xx++;
    if (o.status == 400 && strcmp(o.code, "out_of_range") == 0 && ex->check)
        s->refused++;
    const char *why = NULL;
    if (o.bad_json)
        why = "the answer is not JSON";
    else if (o.nonfinite_text)
        why = "nan/inf in the JSON";
    else if (o.status >= 500)
        why = "5xx";
    else if (o.status == 422 && strncmp(o.message, "the result '", 12) == 0)
        why = "422 for a non-finite result";      /* mm_api.c: a NaN/inf the exercise let through */
    if (why) {
        s->flagged++;
        printf("  FLAG %s: %s %d %s [%s] \"%s\"\n    request: ", ex->id, why, o.status, o.code,
               r->label, o.message);
        print_params(stdout, ex, r, 400);
        printf("\n");
    }
    if (o.ms > s->worst_ms) {
        s->worst_ms = o.ms;
        req_copy(&s->worst, r);
        s->worst_o = o;
    }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Worst cases found by hand, kept so that they stay measured: exercise id
 * and query text; "@TOWER(v)" stands for the power tower of v filling the
 * rest of the length limit.  A case whose exercise or parameter is missing
 * is skipped. */
static const struct { const char *id, *query; } by_hand[] = {
    /* a jump through zero in each of the 1000 parts, a costly f: Brent and
     * the bisection check both bisect to tol in every part */
    {"num-nonlinear-roots", "f=sign(sin(3141.59*x))+0*@TOWER(x)&a=0.0001&b=1&n=1000&tol=1e-15"},
    {"num-nonlinear-roots", "f=sin(3141.59*x)^3+0*@TOWER(x)&a=0.0001&b=1&n=1000&tol=1e-9"},
    {"num-nonlinear-roots", "f=tan(1570.8*x)+0*@TOWER(x)&a=0.0001&b=1&n=1000&tol=1e-15"},
    /* the most samples of the costliest signal, with the finest time step */
    {"vib-dft", "signal=@TOWER(t)&N=65536&fs=1e6&window=hann"},
    {"vib-dft", "signal=@TOWER(t)&N=65521&fs=1e6"},
    {"num-plot", "f=@TOWER(x)&a=0.001&b=1&points=2001"},
};

/* name=value&... into r; 0 when a name is not a parameter of ex. */
static int parse_query(const mm_exercise *ex, const char *query, request *r)
{
    char *q = strdup(query), *save = NULL;
    int ok = 1;
    for (char *tok = strtok_r(q, "&", &save); tok && ok; tok = strtok_r(NULL, "&", &save)) {
        char *eq = strchr(tok, '=');
        if (!eq) {
            ok = 0;
            break;
        }
        *eq = '\0';
        int k = -1;
        for (int i = 0; i < ex->n_params; i++)
            if (strcmp(ex->params[i].name, tok) == 0)
                k = i;
        if (k < 0) {
            ok = 0;
            break;
        }
        char value[MM_PARAM_EXPR_MAX + 64];
        const char *at = strstr(eq + 1, "@TOWER(");
        if (at) {
            size_t pre = (size_t)(at - (eq + 1));
            char v[32];
            snprintf(v, sizeof v, "%.*s", (int)strcspn(at + 7, ")"), at + 7);
            snprintf(value, sizeof value, "%.*s", (int)pre, eq + 1);
            size_t len = strlen(value), vl = strlen(v);
            for (int first = 1; len + vl + (first ? 0 : 1) <= MM_PARAM_EXPR_MAX; first = 0)
                len += (size_t)snprintf(value + len, sizeof value - len, "%s%s", first ? "" : "^", v);
        } else {
            snprintf(value, sizeof value, "%s", eq + 1);
        }
        req_set(r, k, value);
    }
    free(q);
    return ok;
}

static int bench_exercise(const mm_exercise *ex, int draws, FILE *detail)
{
    summary s;
    memset(&s, 0, sizeof s);
    request r;
    memset(&r, 0, sizeof r);
    char *text = malloc(TEXT_MAX), num[MM_DTOA_BUFSIZE];

    snprintf(r.label, sizeof r.label, "defaults");
    consider(ex, &s, &r);

    for (int k = 0; k < ex->n_params; k++) {
        const mm_param *p = &ex->params[k];
        req_clear(&r);
        switch (p->kind) {
        case MM_REAL:
        case MM_INT:
            num_text(p->min, num);
            req_set(&r, k, num);
            snprintf(r.label, sizeof r.label, "%s at min", p->name);
            consider(ex, &s, &r);
            num_text(p->max, num);
            req_set(&r, k, num);
            snprintf(r.label, sizeof r.label, "%s at max", p->name);
            consider(ex, &s, &r);
            break;
        case MM_CHOICE:
            for (int c = 0; c < n_choices(p); c++) {
                req_set(&r, k, p->choices[c]);
                snprintf(r.label, sizeof r.label, "%s=%s", p->name, p->choices[c]);
                consider(ex, &s, &r);
            }
            break;
        case MM_VECTOR:
        case MM_MATRIX:
            for (int v = 0; v < 2; v++) {
                array_max(p, v, text, TEXT_MAX);
                req_set(&r, k, text);
                snprintf(r.label, sizeof r.label, "%s at max size (%s)", p->name,
                         v ? "diagonally dominant" : "default repeated");
                consider(ex, &s, &r);
            }
            break;
        case MM_EXPR:
            for (int f = 0; f < EXPR_FORMS; f++) {
                expr_longest(p, f, text, TEXT_MAX);
                req_set(&r, k, text);
                snprintf(r.label, sizeof r.label, "%s at its longest (%s)", p->name, expr_form_name[f]);
                consider(ex, &s, &r);
            }
            break;
        }
    }

    /* everything at its heaviest, with the reals at default / max / min */
    for (int variant = 0; variant < 3 * 2 * EXPR_FORMS; variant++) {
        req_clear(&r);
        int reals = variant % 3, arrays = variant / 3 % 2, form = variant / 6;
        for (int k = 0; k < ex->n_params; k++) {
            const mm_param *p = &ex->params[k];
            if (p->kind == MM_INT || (p->kind == MM_REAL && reals)) {
                num_text(p->kind == MM_INT || reals == 1 ? p->max : p->min, num);
                req_set(&r, k, num);
            } else if (p->kind == MM_VECTOR || p->kind == MM_MATRIX) {
                array_max(p, arrays, text, TEXT_MAX);
                req_set(&r, k, text);
            } else if (p->kind == MM_EXPR) {
                expr_longest(p, form, text, TEXT_MAX);
                req_set(&r, k, text);
            }
        }
        snprintf(r.label, sizeof r.label, "heaviest: integers at max, reals at %s, arrays %s, expressions %s",
                 reals == 0 ? "default" : reals == 1 ? "max" : "min",
                 arrays ? "diagonally dominant" : "default repeated", expr_form_name[form]);
        consider(ex, &s, &r);
    }

    for (int d = 0; d < draws; d++) {
        req_clear(&r);
        int corner = d % 2;
        for (int k = 0; k < ex->n_params; k++) {
            draw(&ex->params[k], corner, text, TEXT_MAX);
            req_set(&r, k, text);
        }
        snprintf(r.label, sizeof r.label, "random draw %d (%s)", d, corner ? "corners" : "inside");
        consider(ex, &s, &r);
    }

    for (size_t h = 0; h < sizeof by_hand / sizeof by_hand[0]; h++) {
        req_clear(&r);
        if (strcmp(by_hand[h].id, ex->id) != 0 || !parse_query(ex, by_hand[h].query, &r))
            continue;
        snprintf(r.label, sizeof r.label, "worst case found by hand #%zu", h + 1);
        consider(ex, &s, &r);
    }

    /* the slowest again, twice more: report the median */
    double t[3] = {s.worst_ms, run(ex, &s.worst).ms, run(ex, &s.worst).ms};
    qsort(t, 3, sizeof t[0], cmp_double);
    int over = t[1] > limit_ms;
    printf("%-26s %5d %5d %4d %4d %4d %9.2f %9.2f %8zu  %s%s\n", ex->id, s.cases, s.ok, s.e4xx,
           s.e422, s.e5xx, t[1], s.worst_ms, s.worst_o.bytes, over ? "OVER " : "", s.worst.label);
    fprintf(detail, "%s  %.2f ms (median of 3; first %.2f ms)  status %d %s  [%s]\n    ", ex->id, t[1],
            s.worst_ms, s.worst_o.status, s.worst_o.code, s.worst.label);
    print_params(detail, ex, &s.worst, 200);
    fprintf(detail, "\n");
    req_clear(&r);
    req_clear(&s.worst);
    free(text);
    return s.flagged + over;
}

int main(void)
{
    const char *seed = getenv("MM_SEED"), *draws_env = getenv("MM_LIMIT_DRAWS");
    const char *only = getenv("MM_LIMIT_ONLY"), *lim = getenv("MM_LIMIT_MS");
    int draws = draws_env ? atoi(draws_env) : 200;
    limit_ms = lim ? atof(lim) : 250.0;

    printf("== worst case of every exercise inside its limits (whole request in-process: parse, solve, JSON)\n");
    printf("   defaults, each number at min and max, each choice, arrays at max size, expressions at\n");
    printf("   their longest, all at their heaviest, %d random draws; slowest re-timed (median of 3);\n", draws);
    printf("   limit %.0f ms\n", limit_ms);
    printf("%-26s %5s %5s %4s %4s %4s %9s %9s %8s  %s\n", "exercise", "cases", "200", "400", "422", "5xx",
           "worst ms", "first ms", "bytes", "slowest case");
    FILE *detail = tmpfile();
    int flagged = 0, n = 0;
    double t0 = now_s();
    for (int i = 0; i < mm_exercise_count; i++) {
        const mm_exercise *ex = mm_exercises[i];
        if (only && strcmp(only, ex->id) != 0)
            continue;
        mm_rng_seed(&rng, seed ? strtoull(seed, NULL, 10) : 0x9E3779B97F4A7C15ULL ^ (unsigned long long)(i + 1));
        flagged += bench_exercise(ex, draws, detail) > 0;
        fflush(stdout);
        n++;
    }
    printf("\n== the slowest request of each exercise, as parameters\n");
    rewind(detail);
    char line[4096];
    while (fgets(line, sizeof line, detail))
        fputs(line, stdout);
    fclose(detail);
    printf("\nlimits: %d exercises in %.1f s, %d flagged (over %.0f ms, 5xx, non-finite or not JSON)\n", n,
           now_s() - t0, flagged, limit_ms);
    return flagged ? 1 : 0;
}
