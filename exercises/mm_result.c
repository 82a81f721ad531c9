/* mm_result.c — the result builder of mm_exercise.h over a bounded arena. */
#include "mm_result_impl.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { BLOCK_MIN = 16 * 1024, ALIGN = 16 };
#define SPARE_MAX ((size_t)1 << 20)     /* a thread keeps one block up to this size */

/* The block a thread keeps between results (mm_result_keep_blocks): the
 * server's workers solve one request after another, and a block of 64 KiB
 * or more is mapped and unmapped by malloc each time (mm_http.c sets the
 * threshold), a system call, a page fault per 4 KiB touched and, on
 * munmap, a TLB shootdown across the cores: about half of a default
 * vib-sdof-forced request's server time went there. */
static _Thread_local struct {
    int on;
    mm_block *spare;
} keep;

void mm_result_keep_blocks(int on)
{
    keep.on = on;
    if (!on) {
        free(keep.spare);
        keep.spare = NULL;
    }
}

void mm_result_init(mm_result *r, size_t cap)
{
    memset(r, 0, sizeof *r);
    r->cap = cap;
}

void mm_result_bind(mm_result *r, const mm_exercise *ex) { r->ex = ex; }

void mm_result_release(mm_result *r)
{
    mm_block *b = r->blocks;
    while (b) {
        mm_block *next = b->next;
        if (keep.on && b->size <= SPARE_MAX && (!keep.spare || keep.spare->size < b->size)) {
            free(keep.spare);                  /* the largest is kept */
            keep.spare = b;
        } else {
            free(b);
        }
        b = next;
    }
    r->blocks = NULL;
}

int mm_result_status(const mm_result *r)
{
    if (r->over_cap)
        return MM_ETOOBIG;
    return r->failed;
}

/* Remember the first failure; later ones follow from it. */
static void fail(mm_result *r, int code, const char *what, const char *name)
{
    if (r->failed)
        return;
    r->failed = code;
    snprintf(r->failure, sizeof r->failure, "%s%s%.60s", what, name ? ": " : "", name ? name : "");
}

static size_t header_size(void) { return (sizeof(mm_block) + ALIGN - 1) / ALIGN * ALIGN; }

void *mm_res_alloc(mm_result *r, size_t bytes)
{
    size_t need = (bytes + ALIGN - 1) / ALIGN * ALIGN;
    if (need < bytes || need > r->cap) {           /* overflow, or hopeless */
        r->over_cap = 1;
        fail(r, MM_ENOMEM, "over the request's memory cap", NULL);
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
                fail(r, MM_ENOMEM, "over the request's memory cap", NULL);
                return NULL;
            }
        }
        if (keep.spare && keep.spare->size >= size && r->total + keep.spare->size <= r->cap) {
            b = keep.spare;                    /* this thread's block of the last result */
            keep.spare = NULL;
            size = b->size;
        } else {
            b = malloc(header_size() + size);
        }
        if (!b) {
            fail(r, MM_ENOMEM, "malloc failed", NULL);
            return NULL;
        }
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

char *mm_res_printf(mm_result *r, const char *fmt, ...)
{
    char buf[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    return mm_res_strdup(r, buf);
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

/* ---- the output table ------------------------------------------------------ */

/* Where a family's "%d" or "%s" is in text, or NULL. */
static const char *hole(const char *text, char *kind)
{
    for (const char *p = text ? strchr(text, '%') : NULL; p; p = strchr(p + 1, '%'))
        if (p[1] == 'd' || p[1] == 's') {
            *kind = p[1];
            return p;
        }
    return NULL;
}

static int is_family(const mm_output *o)
{
    char k;
    return hole(o->name, &k) != NULL;
}

int mm_output_count(const mm_output *o)
{
    char k;
    if (!hole(o->name, &k))
        return 1;
    if (k == 'd')
        return o->last >= o->first ? o->last - o->first + 1 : 0;
    int n = 0;
    while (o->keys && o->keys[n])
        n++;
    return n;
}

int mm_output_index(const mm_output *o, int k)
{
    char kind;
    if (!hole(o->name, &kind))
        return 0;
    return kind == 'd' ? o->first + k : k;
}

/* text with its hole filled by member i */
static int fill(const mm_output *o, const char *text, int i, char *buf, size_t size)
{
    char kind;
    const char *h = hole(text, &kind);
    if (!h) {
        snprintf(buf, size, "%s", text ? text : "");
        return 0;
    }
    char member[64];
    if (kind == 'd') {
        if (i < o->first || i > o->last)
            return -1;
        snprintf(member, sizeof member, "%d", i);
    } else {
        int n = mm_output_count(o);
        if (i < 0 || i >= n)
            return -1;
        snprintf(member, sizeof member, "%s", o->keys[i]);
    }
    snprintf(buf, size, "%.*s%s%s", (int)(h - text), text, member, h + 2);
    return 0;
}

int mm_output_member(const mm_output *o, int i, char *buf, size_t size)
{
    return fill(o, o->name, i, buf, size);
}

/* The declaration of output `out`, if it has the kind wanted. */
static const mm_output *decl(mm_result *r, int out, mm_output_kind kind, int family)
{
    static const char *const kinds[] = {"", "scalar", "series", "table", "animation"};
    if (!r->ex || out < 0 || out >= r->ex->n_outputs) {
        fail(r, MM_EINTERNAL, "no such output", r->ex ? r->ex->id : NULL);
        return NULL;
    }
    const mm_output *o = &r->ex->outputs[out];
    if (o->kind != kind) {
        fail(r, MM_EINTERNAL, kinds[kind], o->name);
        return NULL;
    }
    if (is_family(o) != family) {
        fail(r, MM_EINTERNAL, family ? "not a family" : "a family needs an index", o->name);
        return NULL;
    }
    return o;
}

/* name and label of member i, in the arena (the declared strings when o is
 * not a family) */
static int member_names(mm_result *r, const mm_output *o, int i, const char **name,
                        const char **label)
{
    if (!is_family(o)) {
        *name = o->name;
        *label = o->label;
        return 0;
    }
    char buf[160];
    if (fill(o, o->name, i, buf, sizeof buf) != 0) {
        fail(r, MM_EINTERNAL, "index outside the family", o->name);
        return -1;
    }
    *name = mm_res_strdup(r, buf);
    fill(o, o->label, i, buf, sizeof buf);
    *label = mm_res_strdup(r, buf);
    return *name && *label ? 0 : -1;
}

/* ---- scalars, series, tables ---------------------------------------------------- */

static mm_scalar *add_scalar(mm_result *r, const mm_output *o, int i, double value)
{
    mm_scalar_node *s = o ? mm_res_alloc(r, sizeof *s) : NULL;
    if (!s || member_names(r, o, i, &s->name, &s->label) != 0) {
        memset(&r->sink, 0, sizeof r->sink);
        return &r->sink;
    }
    s->unit = o->unit ? o->unit : "";
    s->decl = o;
    s->s.value = value;
    s->s.exact = (o->flags & MM_EXACT) != 0;
    APPEND(r->scalars, s);
    return &s->s;
}

mm_scalar *mm_res_scalar(mm_result *r, int out, double value)
{
    return add_scalar(r, decl(r, out, MM_OUT_SCALAR, 0), 0, value);
}

mm_scalar *mm_res_scalar_i(mm_result *r, int out, int i, double value)
{
    return add_scalar(r, decl(r, out, MM_OUT_SCALAR, 1), i, value);
}

mm_scalar *mm_res_scalar_err(mm_result *r, int out, double value, double error, mm_err_kind kind)
{
    mm_scalar *s = mm_res_scalar(r, out, value);
    s->exact = 0;
    s->error = error;
    s->error_kind = kind;
    return s;
}

mm_scalar *mm_res_scalar_text(mm_result *r, int out, double value, const char *text)
{
    mm_scalar *s = mm_res_scalar(r, out, value);
    if (s != &r->sink)
        s->text = text ? mm_res_strdup(r, text) : NULL;
    return s;
}

static mm_series *add_series(mm_result *r, const mm_output *o, int i, int n)
{
    if (!o)
        return NULL;
    if (n < 0) {
        fail(r, MM_EINTERNAL, "negative series length", o->name);
        return NULL;
    }
    mm_series_node *s = mm_res_alloc(r, sizeof *s);
    double *xy = s ? mm_res_alloc(r, 2 * (size_t)n * sizeof(double) + 1) : NULL;
    if (!xy || member_names(r, o, i, &s->name, &s->label) != 0)
        return NULL;
    s->unit = o->unit ? o->unit : "";
    s->x_label = o->x_label ? o->x_label : "";
    s->x_unit = o->x_unit ? o->x_unit : "";
    s->decl = o;
    s->s.x = xy;
    s->s.y = xy + n;
    s->s.n = n;
    APPEND(r->series, s);
    return &s->s;
}

mm_series *mm_res_series(mm_result *r, int out, int n)
{
    return add_series(r, decl(r, out, MM_OUT_SERIES, 0), 0, n);
}

mm_series *mm_res_series_i(mm_result *r, int out, int i, int n)
{
    return add_series(r, decl(r, out, MM_OUT_SERIES, 1), i, n);
}

static int count_columns(const char *const *c)
{
    int n = 0;
    while (c && c[n])
        n++;
    return n;
}

static mm_table *add_table(mm_result *r, const char *name, const char *label, int nrows, int ncols,
                           const char *const *columns, const char *const *units)
{
    if (nrows < 0 || ncols <= 0) {
        fail(r, MM_EINTERNAL, "bad table size", name);
        return NULL;
    }
    size_t cells = (size_t)nrows * (size_t)ncols;
    mm_table_node *t = mm_res_alloc(r, sizeof *t);
    double *cell = t ? mm_res_alloc(r, cells * sizeof(double) + 1) : NULL;
    const char **text = cell ? mm_res_alloc(r, cells * sizeof(char *) + 1) : NULL;
    if (!text)
        return NULL;
    t->name = name;
    t->label = label;
    t->columns = columns;
    t->units = units;
    t->t.cell = cell;
    t->t.text = text;
    t->t.nrows = nrows;
    t->t.ncols = ncols;
    APPEND(r->tables, t);
    return &t->t;
}

mm_table *mm_res_table(mm_result *r, int out, int nrows)
{
    const mm_output *o = decl(r, out, MM_OUT_TABLE, 0);
    if (!o)
        return NULL;
    return add_table(r, o->name, o->label, nrows, count_columns(o->columns), o->columns, o->units);
}

/* ---- checks, method, warnings -------------------------------------------------------- */

static int add_check(mm_result *r, const char *name, double value,
                     double reference, double tol, int relative)
{
    mm_check_node *c = mm_res_alloc(r, sizeof *c);
    if (!c || !(c->name = mm_res_strdup(r, name)))
        return MM_ENOMEM;
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
    if (!(r->method = mm_res_strdup(r, name)))
        return MM_ENOMEM;
    r->step = step;
    return MM_OK;
}

int mm_res_method_stat(mm_result *r, const char *key, double value)
{
    mm_stat_node *s = mm_res_alloc(r, sizeof *s);
    if (!s || !(s->key = mm_res_strdup(r, key)))
        return MM_ENOMEM;
    s->value = value;
    APPEND(r->stats, s);
    return MM_OK;
}

int mm_res_warn(mm_result *r, const char *fmt, ...)
{
    char buf[400];
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

/* ---- animation ------------------------------------------------------------------------- */

mm_anim *mm_res_animation(mm_result *r, int nframes, const char *t_label, const char *t_unit)
{
    int declared = 0;
    for (int i = 0; r->ex && i < r->ex->n_outputs; i++)
        declared |= r->ex->outputs[i].kind == MM_OUT_ANIMATION;
    if (!declared || r->anim || nframes < 1 || nframes > MM_ANIM_MAX_FRAMES) {
        fail(r, MM_EINTERNAL, !declared ? "animation not declared" : r->anim ? "second animation"
                                                                             : "animation frame count",
             r->ex ? r->ex->id : NULL);
        return NULL;
    }
    mm_anim *a = mm_res_alloc(r, sizeof *a);
    double *t = a ? mm_res_alloc(r, (size_t)nframes * sizeof *t) : NULL;
    if (!t || !(r->anim_t_label = mm_res_strdup(r, t_label)) || !(r->anim_t_unit = mm_res_strdup(r, t_unit)))
        return NULL;
    a->t = t;
    a->nframes = nframes;
    r->anim = a;
    return a;
}

mm_shape *mm_anim_shape(mm_result *r, const char *name, mm_shape_kind kind, int frames, int npts)
{
    if (!r->anim) {
        fail(r, MM_EINTERNAL, "shape before mm_res_animation", name);
        return NULL;
    }
    if ((frames != 1 && frames != r->anim->nframes) || npts < 1 || npts > 100000 ||
        (kind == MM_SHAPE_ARROW && npts != 2) ||
        ((kind == MM_SHAPE_CIRCLE || kind == MM_SHAPE_LABEL) && npts != 1)) {
        fail(r, MM_EINTERNAL, "shape size", name);
        return NULL;
    }
    size_t n = (size_t)frames * (size_t)npts;
    mm_shape_node *s = mm_res_alloc(r, sizeof *s);
    double *xy = s ? mm_res_alloc(r, 2 * n * sizeof(double)) : NULL;
    if (!xy || !(s->name = mm_res_strdup(r, name)))
        return NULL;
    s->kind = kind;
    s->s.x = xy;
    s->s.y = xy + n;
    s->s.frames = frames;
    s->s.npts = npts;
    APPEND(r->shapes, s);
    return &s->s;
}

double *mm_shape_values(mm_result *r, mm_shape *s)
{
    if (!s)
        return NULL;
    if (!s->value)
        s->value = mm_res_alloc(r, (size_t)s->frames * sizeof(double));
    return s->value;
}
