/* mm_answer.h — reading an exercise's answer back in the unit tests
 * (test_ex_kin.c, test_ex_dyn.c, test_ex_vib1.c, test_ex_vib3.c): scalars,
 * series, table cells, checks, warnings, refusals.  static inline: each
 * test file uses its own subset.  Include after mm_test.h. */
#ifndef MM_ANSWER_H
#define MM_ANSWER_H

#include <cJSON.h>
#include <stdlib.h>
#include <string.h>

#include "mm_pipeline.h"

/* ---- running a request ------------------------------------------------------ */


/* The item of doc's list ("scalars", "series", "tables", "checks") named
 * name: find gives NULL when there is none, named fails the test. */
static inline const cJSON *find(const cJSON *doc, const char *list, const char *name)
{
    const cJSON *s;
    cJSON_ArrayForEach(s, cJSON_GetObjectItem(doc, list)) {
        const cJSON *nm = cJSON_GetObjectItem(s, "name");
        if (cJSON_IsString(nm) && strcmp(nm->valuestring, name) == 0)
            return s;
    }
    return NULL;
}

static inline const cJSON *named(const cJSON *doc, const char *list, const char *name)
{
    const cJSON *s = find(doc, list, name);
    if (!s)
        fail_msg("no %s named %s", list, name);
    return s;
}

static inline double scalar(const cJSON *doc, const char *name)
{
    return cJSON_GetObjectItem(named(doc, "scalars", name), "value")->valuedouble;
}

/* The "error" a scalar carries (0 when exact). */
static inline double error_of(const cJSON *doc, const char *name)
{
    const cJSON *e = cJSON_GetObjectItem(named(doc, "scalars", name), "error");
    return cJSON_IsNumber(e) ? e->valuedouble : 0;
}

static inline int is_exact(const cJSON *doc, const char *name)
{
    return cJSON_IsTrue(cJSON_GetObjectItem(named(doc, "scalars", name), "exact"));
}

static inline int warned(const cJSON *doc, const char *text)
{
    const cJSON *w;
    cJSON_ArrayForEach(w, cJSON_GetObjectItem(doc, "warnings"))
        if (cJSON_IsString(w) && strstr(w->valuestring, text))
            return 1;
    return 0;
}

static inline int has_scalar(const cJSON *doc, const char *name)
{
    const cJSON *s;
    cJSON_ArrayForEach(s, cJSON_GetObjectItem(doc, "scalars"))
        if (strcmp(cJSON_GetObjectItem(s, "name")->valuestring, name) == 0)
            return 1;
    return 0;
}

/* A series' x and y as arrays (malloc'd; free both). */
static inline int series(const cJSON *doc, const char *name, double **x, double **y)
{
    const cJSON *s = named(doc, "series", name);
    const cJSON *xs = cJSON_GetObjectItem(s, "x"), *ys = cJSON_GetObjectItem(s, "y");
    int n = cJSON_GetArraySize(xs);
    *x = malloc((size_t)n * sizeof **x);
    *y = malloc((size_t)n * sizeof **y);
    for (int i = 0; i < n; i++) {
        (*x)[i] = cJSON_GetArrayItem(xs, i)->valuedouble;
        (*y)[i] = cJSON_GetArrayItem(ys, i)->valuedouble;
    }
    return n;
}

/* A series' y values (malloc'd) and its length. */
static inline int series_y(const cJSON *doc, const char *name, double **y)
{
    const cJSON *ys = cJSON_GetObjectItem(named(doc, "series", name), "y");
    int n = cJSON_GetArraySize(ys);
    *y = malloc((size_t)n * sizeof **y);
    for (int i = 0; i < n; i++)
        (*y)[i] = cJSON_GetArrayItem(ys, i)->valuedouble;
    return n;
}

/* A table's cell (row, column by name). */
static inline const cJSON *cell(const cJSON *doc, const char *table, int row, const char *col)
{
    const cJSON *t = named(doc, "tables", table);
    const cJSON *cols = cJSON_GetObjectItem(t, "columns");
    int k = -1;
    for (int j = 0; j < cJSON_GetArraySize(cols); j++)
        if (strcmp(cJSON_GetArrayItem(cols, j)->valuestring, col) == 0)
            k = j;
    assert_true(k >= 0);
    return cJSON_GetArrayItem(cJSON_GetArrayItem(cJSON_GetObjectItem(t, "rows"), row), k);
}

static inline int table_rows(const cJSON *doc, const char *table)
{
    return cJSON_GetArraySize(cJSON_GetObjectItem(named(doc, "tables", table), "rows"));
}

/* A figure of the answer's method object ("steps", "max_error", ...). */
static inline double stat(const cJSON *doc, const char *key)
{
    const cJSON *v = cJSON_GetObjectItem(cJSON_GetObjectItem(doc, "method"), key);
    if (!cJSON_IsNumber(v))
        fail_msg("no method figure %s", key);
    return v->valuedouble;
}

/* The check whose name starts with prefix. */
static inline const cJSON *check_named(const cJSON *doc, const char *prefix)
{
    const cJSON *c;
    cJSON_ArrayForEach(c, cJSON_GetObjectItem(doc, "checks"))
        if (strncmp(cJSON_GetObjectItem(c, "name")->valuestring, prefix, strlen(prefix)) == 0)
            return c;
    fail_msg("no check '%s...'", prefix);
    return NULL;
}

static inline void expect_refused(const char *id, const char *query, const char *param)
{
    answer a = solve(id, query);
    const cJSON *e = cJSON_GetObjectItem(a.doc, "error");
    if (a.status != 400 || strcmp(cJSON_GetObjectItem(e, "code")->valuestring, "out_of_range") != 0 ||
        strcmp(cJSON_GetObjectItem(e, "param")->valuestring, param) != 0) {
        char *s = cJSON_PrintUnformatted(a.doc);
        fail_msg("%s?%s: expected 400 out_of_range on %s, got %d %.300s", id, query, param, a.status, s);
    }
    cJSON_Delete(a.doc);
}

#endif
