/* mm_result.c — the result builder of mm_exercise.h over a bounded arena. */
#include "mm_result_impl.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { BLOCK_MIN = 16 * 1024, ALIGN = 16 };

void mm_result_init(mm_result *r, size_t cap)
{
    memset(r, 0, sizeof *r);
    r->cap = cap;
}

void mm_result_release(mm_result *r)
{
    mm_block *b = r->blocks;
    while (b) {
        mm_block *next = b->next;
        free(b);
        b = next;
    }
    r->blocks = NULL;
}

static size_t header_size(void) { return (sizeof(mm_block) + ALIGN - 1) / ALIGN * ALIGN; }

void *mm_res_alloc(mm_result *r, size_t bytes)
{
    size_t need = (bytes + ALIGN - 1) / ALIGN * ALIGN;
    if (need < bytes || need > r->cap) {           /* overflow, or hopeless */
        r->over_cap = 1;
        return NULL;
    }
    mm_block *b = r->blocks;
    if (!b || b->size - b->used < need) {
        size_t size = need > BLOCK_MIN ? need : BLOCK_MIN;
        if (b && size < 2 * b->size && 2 * b->size >= need)
            size = 2 * b->size;                    /* grow geometrically */
        if (r->total + size > r->cap) {
            size = need;                           /* last chance: exact fit */
            if (r->total + size > r->cap) {
                r->over_cap = 1;
                return NULL;
            }
        }
        b = malloc(header_size() + size);
        if (!b)
            return NULL;
        b->size = size;
        b->used = 0;
        b->next = r->blocks;
        r->blocks = b;
        r->total += size;
    }
    void *p = (char *)b + header_size() + b->used;
    b->used += need;
    memset(p, 0, need);
    return p;
}

char *mm_res_strdup(mm_result *r, const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = mm_res_alloc(r, n);
    if (d)
        memcpy(d, s, n);
    return d;
}

#define APPEND(list, node)                    \
    do {                                      \
        if ((list).tail)                      \
            (list).tail->next = (node);       \
        else                                  \
            (list).head = (node);             \
        (list).tail = (node);                 \
        (list).n++;                           \
    } while (0)

int mm_res_scalar_text(mm_result *r, const char *name, const char *label,
                       const char *unit, double value, const char *text)
{
    mm_scalar_node *s = mm_res_alloc(r, sizeof *s);
    if (!s)
        return MM_ENOMEM;
    s->name = name;
    s->label = label;
    s->unit = unit ? unit : "";
    s->text = text ? mm_res_strdup(r, text) : NULL;   /* copied: may be a stack buffer */
    if (text && !s->text)
        return MM_ENOMEM;
    s->value = value;
    APPEND(r->scalars, s);
    return MM_OK;
}

int mm_res_scalar(mm_result *r, const char *name, const char *label,
                  const char *unit, double value)
{
    return mm_res_scalar_text(r, name, label, unit, value, NULL);
}

mm_series *mm_res_series(mm_result *r, const char *name, const char *label,
                         const char *unit, const char *x_label,
                         const char *x_unit, int n)
{
    if (n < 0)
        return NULL;
    mm_series_node *s = mm_res_alloc(r, sizeof *s);
    double *xy = s ? mm_res_alloc(r, 2 * (size_t)n * sizeof(double) + 1) : NULL;
    if (!xy)
        return NULL;
    s->name = name;
    s->label = label;
    s->unit = unit ? unit : "";
    s->x_label = x_label;
    s->x_unit = x_unit ? x_unit : "";
    s->s.x = xy;
    s->s.y = xy + n;
    s->s.n = n;
    APPEND(r->series, s);
    return &s->s;
}

mm_table *mm_res_table(mm_result *r, const char *name, int nrows, int ncols,
                       const char *const *columns, const char *const *units)
{
    if (nrows < 0 || ncols <= 0)
        return NULL;
    size_t cells = (size_t)nrows * (size_t)ncols;
    mm_table_node *t = mm_res_alloc(r, sizeof *t);
    double *cell = t ? mm_res_alloc(r, cells * sizeof(double) + 1) : NULL;
    const char **text = cell ? mm_res_alloc(r, cells * sizeof(char *) + 1) : NULL;
    if (!text)
        return NULL;
    t->name = name;
    t->columns = columns;
    t->units = units;
    t->t.cell = cell;
    t->t.text = text;
    t->t.nrows = nrows;
    t->t.ncols = ncols;
    APPEND(r->tables, t);
    return &t->t;
}

static int add_check(mm_result *r, const char *name, double value,
                     double reference, double tol, int relative)
{
    mm_check_node *c = mm_res_alloc(r, sizeof *c);
    if (!c)
        return MM_ENOMEM;
    c->name = name;
    c->value = value;
    c->reference = reference;
    c->tolerance = tol;
    c->relative = relative;
    APPEND(r->checks, c);
    return MM_OK;
}

int mm_res_check_rel(mm_result *r, const char *name, double value,
                     double reference, double tol)
{
    return add_check(r, name, value, reference, tol, 1);
}

int mm_res_check_abs(mm_result *r, const char *name, double value,
                     double reference, double tol)
{
    return add_check(r, name, value, reference, tol, 0);
}

int mm_res_method(mm_result *r, const char *name, double step)
{
    r->method = name;
    r->step = step;
    return MM_OK;
}

int mm_res_method_stat(mm_result *r, const char *key, double value)
{
    mm_stat_node *s = mm_res_alloc(r, sizeof *s);
    if (!s)
        return MM_ENOMEM;
    s->key = key;
    s->value = value;
    APPEND(r->stats, s);
    return MM_OK;
}

int mm_res_warn(mm_result *r, const char *fmt, ...)
{
    char buf[300];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    mm_warn_node *w = mm_res_alloc(r, sizeof *w);
    if (!w || !(w->text = mm_res_strdup(r, buf)))
        return MM_ENOMEM;
    APPEND(r->warnings, w);
    return MM_OK;
}
