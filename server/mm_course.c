/* mm_course.c — the course file (see mm_course.h). */
#include "mm_course.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mm_dtoa.h"
#include "mm_hash.h"
#include "mm_json.h"
#include "mm_params.h"
#include "mm_result_impl.h"

typedef struct ex_view {
    mm_exercise ex;               /* a copy of the registry's, params replaced */
    mm_param *params;             /* owned */
} ex_view;

typedef struct node_line {
    const cJSON *node;
    int line;
} node_line;

struct mm_course {
    cJSON *root;                  /* the file, parsed; NULL for the built-in course */
    char title[256], language[40], base_path[256];
    char digest[MM_DIGEST_SIZE];
    ex_view *views;
    int n_views;
    const cJSON **assignments;
    int n_assignments;
    char **strings;               /* texts the views point to */
    int n_strings, cap_strings;
    node_line *lines;             /* every node of the file and its line */
    int n_lines, cap_lines;
};

/* ---- where things are in the file ------------------------------------------ */

/* cJSON keeps no positions, but it keeps document order: a pre-order walk
 * of the tree meets the values in the order they stand in the text.  So
 * the text is scanned once more, in step with the tree, and every node
 * gets the line where it starts (for a member of an object: its key). */
typedef struct scanner {
    const char *p, *end;
    int line;
    mm_course *c;
} scanner;

/* White space as cJSON reads it: every byte up to ' ' (it accepts a stray
 * control character between values, so the scanner must step over it too) */
static void skip_ws(scanner *s)
{
    while (s->p < s->end && (unsigned char)*s->p <= ' ') {
        if (*s->p == '\n')
            s->line++;
        s->p++;
    }
}

static void skip_string(scanner *s)
{
    s->p++;                                    /* the opening quote */
    while (s->p < s->end && *s->p != '"')
        s->p += *s->p == '\\' ? 2 : 1;
    s->p++;
}

static void note_line(mm_course *c, const cJSON *node, int line)
{
    if (c->n_lines == c->cap_lines) {
        int cap = c->cap_lines ? 2 * c->cap_lines : 256;
        node_line *l = realloc(c->lines, (size_t)cap * sizeof *l);
        if (!l)
            return;                            /* lines are for messages only */
        c->lines = l;
        c->cap_lines = cap;
    }
    c->lines[c->n_lines++] = (node_line){node, line};
}

static void scan_value(scanner *s, const cJSON *node, int line)
{
    skip_ws(s);
    note_line(s->c, node, line ? line : s->line);
    if (s->p >= s->end || !node)
        return;
    char open = *s->p;
    if (open == '{' || open == '[') {
        s->p++;
        const cJSON *child = node->child;
        for (const char *was = NULL; s->p != was;) {   /* every round moves on, or the scan ends */
            was = s->p;
            skip_ws(s);
            if (s->p >= s->end || *s->p == '}' || *s->p == ']') {
                s->p++;
                return;
            }
            int at = s->line;
            if (open == '{') {                 /* "key" : value */
                skip_string(s);
                skip_ws(s);
                s->p++;                        /* the colon */
            }
            scan_value(s, child, open == '{' ? at : 0);
            child = child ? child->next : NULL;
            skip_ws(s);
            if (s->p < s->end && *s->p == ',')
                s->p++;
        }
    }
    if (open == '"') {
        skip_string(s);
        return;
    }
    while (s->p < s->end && !strchr(",]} \t\r\n", *s->p))
        s->p++;
}

int mm_course_line(const mm_course *c, const cJSON *node)
{
    for (int i = 0; c && i < c->n_lines; i++)
        if (c->lines[i].node == node)
            return c->lines[i].line;
    return 0;
}

/* ---- errors ------------------------------------------------------------------ */

typedef struct ctx {
    mm_course *c;
    const char *name;             /* the file, for messages */
    mm_error *err;
} ctx;

static int fail(ctx *x, const cJSON *at, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static int fail(ctx *x, const cJSON *at, const char *fmt, ...)
{
    char why[sizeof x->err->msg];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(why, sizeof why, fmt, ap);
    va_end(ap);
    int line = mm_course_line(x->c, at);
    if (line > 0)
        return mm_error_set(x->err, MM_EVALUE, "", "%s:%d: %s", x->name, line, why);
    return mm_error_set(x->err, MM_EVALUE, "", "%s: %s", x->name, why);
}

static const char *keep(mm_course *c, const char *text)
{
    if (c->n_strings == c->cap_strings) {
        int cap = c->cap_strings ? 2 * c->cap_strings : 16;
        char **s = realloc(c->strings, (size_t)cap * sizeof *s);
        if (!s)
            return NULL;
        c->strings = s;
        c->cap_strings = cap;
    }
    char *copy = strdup(text);
    if (copy)
        c->strings[c->n_strings++] = copy;
    return copy;
}

/* An object's members: no key twice, every key one of `allowed`
 * (space-separated). */
static int check_keys(ctx *x, const cJSON *obj, const char *what, const char *allowed)
{
    for (const cJSON *e = obj->child; e; e = e->next) {
        for (const cJSON *f = obj->child; f != e; f = f->next)
            if (strcmp(f->string, e->string) == 0)
                return fail(x, e, "%s: \"%s\" is given twice", what, e->string);
        size_t n = strlen(e->string);
        int ok = 0;
        for (const char *a = allowed; *a && !ok;) {
            const char *sp = strchr(a, ' ');
            size_t l = sp ? (size_t)(sp - a) : strlen(a);
            ok = l == n && strncmp(a, e->string, n) == 0;
            a += l + (sp ? 1 : 0);
        }
        if (!ok)
            return fail(x, e, "%s: unknown key \"%.40s\" (the keys are: %s)", what, e->string, allowed);
    }
    return MM_OK;
}

/* ---- parameter overrides ------------------------------------------------------ */

/* A JSON default as parameter text: numbers in shortest form, arrays joined
 * by ',' and rows by ';' (the forms of mm_params.h). */
static int default_text(ctx *x, const cJSON *v, mm_buf *t, int depth, const char *name)
{
    char num[MM_DTOA_BUFSIZE];
    if (cJSON_IsNumber(v) && isfinite(v->valuedouble)) {
        mm_buf_put(t, num, (size_t)mm_dtoa(v->valuedouble, num));
        return MM_OK;
    }
    if (cJSON_IsString(v) && depth == 0) {
        mm_buf_puts(t, v->valuestring);
        return MM_OK;
    }
    if (cJSON_IsArray(v) && depth < 2) {
        int i = 0;
        for (const cJSON *e = v->child; e; e = e->next, i++) {
            if (i)
                mm_buf_char(t, depth == 0 && cJSON_IsArray(e) ? ';' : ',');
            if (default_text(x, e, t, depth + 1, name) != MM_OK)
                return x->err->code;
        }
        return MM_OK;
    }
    return fail(x, v, "%s: the default must be a number, a text or an array of numbers", name);
}

static int number_field(ctx *x, const cJSON *o, const char *key, const char *pname, double *out, int *given)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    *given = v != NULL;
    if (!v)
        return MM_OK;
    if (!cJSON_IsNumber(v) || !isfinite(v->valuedouble))
        return fail(x, v, "%s: \"%s\" must be a number", pname, key);
    *out = v->valuedouble;
    return MM_OK;
}

static int apply_override(ctx *x, const mm_exercise *ex, mm_param *p, const mm_param *orig,
                          const cJSON *o)
{
    char what[160];
    snprintf(what, sizeof what, "%s: %s", ex->id, p->name);
    if (!cJSON_IsObject(o))
        return fail(x, o, "%s: an override is an object such as {\"default\": 2, \"min\": 1, \"max\": 5}", what);
    const char *keys = "default";
    if (p->kind == MM_REAL || p->kind == MM_INT)
        keys = "default min max";
    else if (p->kind == MM_VECTOR)
        keys = "default min max max_length";
    else if (p->kind == MM_MATRIX)
        keys = "default min max max_rows max_cols";
    if (check_keys(x, o, what, keys) != MM_OK)
        return x->err->code;

    double lo = p->min, hi = p->max;
    int has_lo, has_hi;
    if (number_field(x, o, "min", what, &lo, &has_lo) != MM_OK ||
        number_field(x, o, "max", what, &hi, &has_hi) != MM_OK)
        return x->err->code;
    if (has_lo && lo < orig->min)
        return fail(x, cJSON_GetObjectItemCaseSensitive(o, "min"),
                    "%s: min %.10g is below the built-in %.10g (a course may only narrow the limits)",
                    what, lo, orig->min);
    if (has_hi && hi > orig->max)
        return fail(x, cJSON_GetObjectItemCaseSensitive(o, "max"),
                    "%s: max %.10g is above the built-in %.10g (a course may only narrow the limits)",
                    what, hi, orig->max);
    if (lo > hi)
        return fail(x, o, "%s: min %.10g is above max %.10g", what, lo, hi);
    p->min = lo, p->max = hi;

    static const struct { const char *key; int matrix_rows; } sizes[] = {
        {"max_length", 0}, {"max_cols", 0}, {"max_rows", 1}};
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, sizes[i].key);
        if (!v)
            continue;
        int *field = sizes[i].matrix_rows ? &p->max_rows : &p->max_cols;
        int builtin = sizes[i].matrix_rows ? orig->max_rows : orig->max_cols;
        if (!cJSON_IsNumber(v) || v->valuedouble != floor(v->valuedouble) || v->valuedouble < 1)
            return fail(x, v, "%s: \"%s\" must be a whole number from 1", what, sizes[i].key);
        if (v->valuedouble > builtin)
            return fail(x, v, "%s: %s %g is above the built-in %d (a course may only narrow the limits)",
                        what, sizes[i].key, v->valuedouble, builtin);
        *field = (int)v->valuedouble;
    }

    /* the default: given, or the built-in one, must lie inside the new limits */
    const cJSON *d = cJSON_GetObjectItemCaseSensitive(o, "default");
    mm_buf t;
    mm_buf_init(&t, MM_PARAM_TEXT_MAX);
    int rc = MM_OK;
    if (d && (rc = default_text(x, d, &t, 0, what)) != MM_OK) {
        mm_buf_free(&t);
        return rc;
    }
    mm_result arena;
    mm_result_init(&arena, 1 << 22);
    mm_value v;
    mm_error perr;
    mm_error_clear(&perr);
    if (d)
        rc = mm_param_parse(p, t.p ? t.p : "", t.len, &v, &arena, &perr);
    else if ((p->kind == MM_REAL || p->kind == MM_INT) && !(p->def >= p->min && p->def <= p->max))
        rc = MM_ERANGE;
    else
        rc = mm_param_default(p, &v, &arena, &perr);
    if (rc != MM_OK) {
        mm_result_release(&arena);
        mm_buf_free(&t);
        if (d)
            return fail(x, d, "%s: the default does not fit: %s", what, perr.msg);
        return fail(x, o, "%s: the built-in default lies outside the course's limits; give a \"default\"",
                    what);
    }
    if (d) {
        if (p->kind == MM_REAL || p->kind == MM_INT || p->kind == MM_CHOICE) {
            p->def = v.x;
        } else {
            const char *s = keep(x->c, t.p ? t.p : "");
            if (!s)
                rc = mm_error_set(x->err, MM_ENOMEM, "", "out of memory");
            p->def_text = s;
        }
    }
    mm_result_release(&arena);
    mm_buf_free(&t);
    return rc;
}

static int add_view(ctx *x, const mm_exercise *ex, const cJSON *entry)
{
    mm_course *c = x->c;
    for (int i = 0; i < c->n_views; i++)
        if (strcmp(c->views[i].ex.id, ex->id) == 0)
            return fail(x, entry, "exercise %s is listed twice", ex->id);
    ex_view *v = &c->views[c->n_views];
    v->ex = *ex;
    v->params = calloc((size_t)(ex->n_params > 0 ? ex->n_params : 1), sizeof *v->params);
    if (!v->params)
        return mm_error_set(x->err, MM_ENOMEM, "", "out of memory");
    memcpy(v->params, ex->params, (size_t)ex->n_params * sizeof *v->params);
    v->ex.params = v->params;
    c->n_views++;

    const cJSON *params = entry ? cJSON_GetObjectItemCaseSensitive(entry, "params") : NULL;
    if (!params)
        return MM_OK;
    if (!cJSON_IsObject(params))
        return fail(x, params, "%s: \"params\" must be an object of overrides by parameter name", ex->id);
    for (const cJSON *o = params->child; o; o = o->next) {
        for (const cJSON *f = params->child; f != o; f = f->next)
            if (strcmp(f->string, o->string) == 0)
                return fail(x, o, "%s: %s is given twice", ex->id, o->string);
        int k = -1;
        for (int i = 0; i < ex->n_params; i++)
            if (strcmp(ex->params[i].name, o->string) == 0)
                k = i;
        if (k < 0) {
            char list[200] = "";
            for (int i = 0; i < ex->n_params; i++) {
                size_t l = strlen(list);
                snprintf(list + l, sizeof list - l, "%s%s", i ? ", " : "", ex->params[i].name);
            }
            return fail(x, o, "%s has no parameter \"%.40s\"; its parameters are %s", ex->id, o->string, list);
        }
        if (apply_override(x, ex, &v->params[k], &ex->params[k], o) != MM_OK)
            return x->err->code;
    }
    mm_error perr;
    if (mm_params_check(&v->ex, &perr) != MM_OK)
        return fail(x, params, "%s", perr.msg);
    return MM_OK;
}

/* ---- the file ---------------------------------------------------------------------- */

static int text_field(ctx *x, const cJSON *root, const char *key, char *out, size_t size)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(root, key);
    if (!v)
        return MM_OK;
    if (!cJSON_IsString(v))
        return fail(x, v, "\"%s\" must be a text", key);
    if (strlen(v->valuestring) >= size)
        return fail(x, v, "\"%s\" is too long (at most %zu characters)", key, size - 1);
    snprintf(out, size, "%s", v->valuestring);
    return MM_OK;
}

static int check_base_path(ctx *x, const cJSON *at, char *bp, size_t size)
{
    size_t n = strlen(bp);
    if (bp[0] != '/')
        return fail(x, at, "\"base_path\" must start with '/': \"/\" or \"/mechanics/\"");
    for (size_t i = 0; i < n; i++)
        if (!(isalnum((unsigned char)bp[i]) || strchr("/-._~", bp[i])))
            return fail(x, at, "\"base_path\" may hold letters, digits and / - . _ ~ only");
    if (strstr(bp, "//") || strstr(bp, "/./") || strstr(bp, "/../") ||
        (n >= 2 && strcmp(bp + n - 2, "/.") == 0) || (n >= 3 && strcmp(bp + n - 3, "/..") == 0))
        return fail(x, at, "\"base_path\" must not hold \"//\", \".\" or \"..\" segments");
    if (bp[n - 1] != '/') {
        if (n + 2 > size)
            return fail(x, at, "\"base_path\" is too long");
        bp[n] = '/', bp[n + 1] = '\0';
    }
    return MM_OK;
}

static int name_ok(const char *s)
{
    size_t n = strlen(s);
    if (n == 0 || n > 64)
        return 0;
    for (size_t i = 0; i < n; i++)
        if (!(isalnum((unsigned char)s[i]) || s[i] == '-' || s[i] == '_'))
            return 0;
    return 1;
}

static int read_course(ctx *x, const cJSON *root)
{
    mm_course *c = x->c;
    if (!cJSON_IsObject(root))
        return fail(x, root, "a course is one JSON object {\"title\": ..., \"exercises\": [...]}");
    if (check_keys(x, root, "course", "title language base_path exercises assignments") != MM_OK ||
        text_field(x, root, "title", c->title, sizeof c->title) != MM_OK ||
        text_field(x, root, "language", c->language, sizeof c->language) != MM_OK ||
        text_field(x, root, "base_path", c->base_path, sizeof c->base_path) != MM_OK)
        return x->err->code;
    const cJSON *lang = cJSON_GetObjectItemCaseSensitive(root, "language");
    for (const char *s = c->language; *s; s++)
        if (!(isalnum((unsigned char)*s) || *s == '-'))
            return fail(x, lang, "\"language\" must be a language tag such as \"en\" or \"de-CH\"");
    if (!c->language[0])
        return fail(x, lang, "\"language\" must be a language tag such as \"en\" or \"de-CH\"");
    const cJSON *bp = cJSON_GetObjectItemCaseSensitive(root, "base_path");
    if (check_base_path(x, bp, c->base_path, sizeof c->base_path) != MM_OK)
        return x->err->code;

    const cJSON *list = cJSON_GetObjectItemCaseSensitive(root, "exercises");
    if (list && !cJSON_IsArray(list))
        return fail(x, list, "\"exercises\" must be an array of exercise ids (or {\"id\": ..., \"params\": ...})");
    if (list && cJSON_GetArraySize(list) == 0)
        return fail(x, list, "\"exercises\" is empty; leave it out to show every exercise");
    int n = list ? cJSON_GetArraySize(list) : mm_exercise_count;
    if (n > 4 * mm_exercise_count + 16)
        return fail(x, list, "\"exercises\" lists %d entries; there are %d exercises", n, mm_exercise_count);
    c->views = calloc((size_t)n + 1, sizeof *c->views);
    if (!c->views)
        return mm_error_set(x->err, MM_ENOMEM, "", "out of memory");
    if (!list) {
        for (int i = 0; i < mm_exercise_count; i++)
            if (add_view(x, mm_exercises[i], NULL) != MM_OK)
                return x->err->code;
    } else {
        for (const cJSON *e = list->child; e; e = e->next) {
            const cJSON *id = e;
            if (cJSON_IsObject(e)) {
                if (check_keys(x, e, "an exercise entry", "id params") != MM_OK)
                    return x->err->code;
                id = cJSON_GetObjectItemCaseSensitive(e, "id");
            }
            if (!cJSON_IsString(id))
                return fail(x, e, "an exercise is its id (\"vib-sdof-free\") or {\"id\": ..., \"params\": {...}}");
            const mm_exercise *ex = mm_exercise_find(id->valuestring);
            if (!ex)
                return fail(x, id, "no exercise \"%.60s\" (GET /api/exercises lists them)", id->valuestring);
            if (add_view(x, ex, cJSON_IsObject(e) ? e : NULL) != MM_OK)
                return x->err->code;
        }
    }

    const cJSON *as = cJSON_GetObjectItemCaseSensitive(root, "assignments");
    if (as && !cJSON_IsArray(as))
        return fail(x, as, "\"assignments\" must be an array of objects, each with a \"name\"");
    int na = as ? cJSON_GetArraySize(as) : 0;
    c->assignments = calloc((size_t)na + 1, sizeof *c->assignments);
    if (!c->assignments)
        return mm_error_set(x->err, MM_ENOMEM, "", "out of memory");
    for (const cJSON *a = as ? as->child : NULL; a; a = a->next) {
        const cJSON *name = cJSON_IsObject(a) ? cJSON_GetObjectItemCaseSensitive(a, "name") : NULL;
        if (!cJSON_IsString(name) || !name_ok(name->valuestring))
            return fail(x, name ? name : a, "an assignment is an object with a \"name\" of letters, digits, "
                        "'-' and '_' (at most 64)");
        for (int i = 0; i < c->n_assignments; i++)
            if (strcmp(mm_course_assignment_name(c, i), name->valuestring) == 0)
                return fail(x, name, "assignment \"%s\" is defined twice", name->valuestring);
        c->assignments[c->n_assignments++] = a;
    }
    return MM_OK;
}

static mm_course *course_new(void)
{
    mm_course *c = calloc(1, sizeof *c);
    if (!c)
        return NULL;
    snprintf(c->title, sizeof c->title, "mechmat");
    snprintf(c->language, sizeof c->language, "en");
    snprintf(c->base_path, sizeof c->base_path, "/");
    return c;
}

/* The built-in course: every exercise, and two example assignments that
 * show an instructor the form (API.md: the built-in course has at least
 * one).  No instructor key: the answer key and class sheet need a course
 * file of one's own. */
static const char builtin_text[] =
    "{\"title\": \"mechmat\", \"language\": \"en\", \"base_path\": \"/\",\n"
    " \"assignments\": [\n"
    "  {\"name\": \"belt-1\", \"title\": \"A rope around a bollard\",\n"
    "   \"exercise\": \"sta-belt-friction\",\n"
    "   \"params\": {\"T1\": {\"min\": 50, \"max\": 500, \"step\": 10},\n"
    "              \"mu\": {\"values\": [0.2, 0.25, 0.3, 0.35]},\n"
    "              \"theta\": {\"min\": 1, \"max\": 4, \"sig\": 2}},\n"
    "   \"ask\": [{\"name\": \"T2\", \"unit\": \"N\", \"rel\": 0.01},\n"
    "           {\"name\": \"torque\", \"unit\": \"N m\", \"sig\": 3}],\n"
    "   \"class_size\": 300},\n"
    "  {\"name\": \"forced-1\", \"title\": \"Steady forced vibration\",\n"
    "   \"exercise\": \"vib-sdof-forced\",\n"
    "   \"params\": {\"m\": {\"min\": 0.5, \"max\": 5, \"step\": 0.5},\n"
    "              \"k\": {\"min\": 100, \"max\": 2000, \"step\": 100},\n"
    "              \"c\": {\"min\": 1, \"max\": 20, \"step\": 1},\n"
    "              \"omega\": {\"min\": 2, \"max\": 40, \"step\": 2}},\n"
    "   \"ask\": [{\"name\": \"X\", \"unit\": \"mm\", \"rel\": 0.01},\n"
    "           {\"name\": \"phase\", \"unit\": \"deg\", \"abs\": 0.5}],\n"
    "   \"class_size\": 300}]}\n";

mm_course *mm_course_builtin(void)
{
    mm_error err;
    mm_course *c = mm_course_parse(builtin_text, sizeof builtin_text - 1, "built-in course", &err);
    if (c)
        snprintf(c->digest, sizeof c->digest, "builtin");
    else
        fprintf(stderr, "mechmat: the built-in course: %s\n", err.msg);
    return c;
}

mm_course *mm_course_parse(const char *text, size_t len, const char *name, mm_error *err)
{
    mm_error_clear(err);
    if (len > MM_COURSE_MAX_BYTES) {
        mm_error_set(err, MM_EVALUE, "", "%s: the file is over %u MiB", name, MM_COURSE_MAX_BYTES >> 20);
        return NULL;
    }
    if (memchr(text, '\0', len)) {
        mm_error_set(err, MM_EVALUE, "", "%s: the file holds a NUL byte; a course file is UTF-8 text", name);
        return NULL;
    }
    mm_course *c = course_new();
    if (!c) {
        mm_error_set(err, MM_ENOMEM, "", "out of memory");
        return NULL;
    }
    mm_digest(text, len, c->digest);
    const char *end = NULL;
    c->root = cJSON_ParseWithLengthOpts(text, len, &end, 0);
    size_t tail = end ? (size_t)(end - text) : len;
    if (c->root)
        while (tail < len && strchr(" \t\r\n", text[tail]))
            tail++;
    if (!c->root || tail < len) {
        size_t at = end && (size_t)(end - text) <= len ? (size_t)(end - text) : 0;
        if (c->root)
            at = tail;
        int line = 1, col = 1;
        for (size_t i = 0; i < at; i++)
            text[i] == '\n' ? (line++, col = 1) : col++;
        mm_error_set(err, MM_EVALUE, "", "%s:%d: %s (column %d)", name, line,
                     c->root ? "text after the end of the course object" : "not valid JSON", col);
        mm_course_free(c);
        return NULL;
    }
    scanner s = {text, text + len, 1, c};
    scan_value(&s, c->root, 0);
    ctx x = {c, name, err};
    if (read_course(&x, c->root) != MM_OK) {
        mm_course_free(c);
        return NULL;
    }
    return c;
}

mm_course *mm_course_load(const char *path, mm_error *err)
{
    mm_error_clear(err);
    FILE *f = fopen(path, "rb");
    if (!f) {
        mm_error_set(err, MM_ENOTFOUND, "", "%s: %s", path, strerror(errno));
        return NULL;
    }
    mm_buf b;
    mm_buf_init(&b, MM_COURSE_MAX_BYTES + 1);
    char chunk[8192];
    size_t n;
    while ((n = fread(chunk, 1, sizeof chunk, f)) > 0)
        mm_buf_put(&b, chunk, n);
    int bad = ferror(f);
    fclose(f);
    mm_course *c = NULL;
    if (bad)
        mm_error_set(err, MM_ENOTFOUND, "", "%s: could not be read", path);
    else if (b.failed)
        mm_error_set(err, MM_EVALUE, "", "%s: the file is over %u MiB", path, MM_COURSE_MAX_BYTES >> 20);
    else
        c = mm_course_parse(b.p ? b.p : "", b.len, path, err);
    mm_buf_free(&b);
    return c;
}

void mm_course_free(mm_course *c)
{
    if (!c)
        return;
    for (int i = 0; i < c->n_views; i++)
        free(c->views[i].params);
    free(c->views);
    for (int i = 0; i < c->n_strings; i++)
        free(c->strings[i]);
    free(c->strings);
    free(c->assignments);
    free(c->lines);
    cJSON_Delete(c->root);
    free(c);
}

const char *mm_course_title(const mm_course *c) { return c->title; }
const char *mm_course_language(const mm_course *c) { return c->language; }
const char *mm_course_base_path(const mm_course *c) { return c->base_path; }
const char *mm_course_digest(const mm_course *c) { return c->digest; }
int mm_course_exercise_count(const mm_course *c) { return c->n_views; }

const mm_exercise *mm_course_exercise(const mm_course *c, int i)
{
    return i >= 0 && i < c->n_views ? &c->views[i].ex : NULL;
}

const mm_exercise *mm_course_find(const mm_course *c, const char *id)
{
    for (int i = 0; i < c->n_views; i++)
        if (strcmp(c->views[i].ex.id, id) == 0)
            return &c->views[i].ex;
    return NULL;
}

int mm_course_assignment_count(const mm_course *c) { return c->n_assignments; }

const cJSON *mm_course_assignment(const mm_course *c, int i)
{
    return i >= 0 && i < c->n_assignments ? c->assignments[i] : NULL;
}

const char *mm_course_assignment_name(const mm_course *c, int i)
{
    const cJSON *a = mm_course_assignment(c, i);
    const cJSON *n = a ? cJSON_GetObjectItemCaseSensitive(a, "name") : NULL;
    return cJSON_IsString(n) ? n->valuestring : NULL;
}

const cJSON *mm_course_assignment_find(const mm_course *c, const char *name)
{
    for (int i = 0; i < c->n_assignments; i++)
        if (strcmp(mm_course_assignment_name(c, i), name) == 0)
            return c->assignments[i];
    return NULL;
}
