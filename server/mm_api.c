/* mm_api.c — API.md's documents and the solve pipeline (see mm_api.h). */
#include "mm_api.h"

#include "mm_assign.h"

#include <cJSON.h>
#include <math.h>
#ifdef __SSE2__
#include <emmintrin.h>
#endif
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "mm_dtoa.h"
#include "mm_hash.h"
#include "mm_openapi.h"
#include "mm_params.h"
#include "mm_result_impl.h"
#include "mm_theory.h"

struct mm_api {
    mm_course *course;           /* owned */
    mm_doc health, catalog, course_doc, openapi, assignments_doc;
    mm_doc *meta;                /* one document per exercise of the course */
    char **scripts;              /* one script body per exercise, or NULL */
    mm_assignment **assign;      /* the course's assignments, in file order */
    int n_assign;
};

static long long now_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (long long)ts.tv_sec * 1000000 + ts.tv_nsec / 1000;
}

/* ---- writing pieces ------------------------------------------------------ */

/* ,"key":"text" and ,"key":number — the pieces most of a document is made of */
static void field_str(mm_buf *b, const char *key, const char *text)
{
    mm_buf_char(b, ',');
    mm_buf_key(b, key);
    mm_buf_str(b, text);
}

static void field_num(mm_buf *b, const char *key, double v, const char *where)
{
    mm_buf_char(b, ',');
    mm_buf_key(b, key);
    mm_buf_num(b, v, where);
}


int mm_api_error(mm_buf *out, const mm_error *err)
{
    int code = err->code == MM_OK ? MM_EINTERNAL : err->code;
    mm_buf_reset(out);
    mm_buf_puts(out, "{\"error\":{\"code\":");
    mm_buf_str(out, mm_api_code(code));
    field_str(out, "param", err->param[0] ? err->param : NULL);
    mm_buf_puts(out, ",\"message\":");
    if (mm_http_status(code) >= 500)   /* our fault: the details go to the log */
        mm_buf_str(out, code == MM_EBUSY ? "the server is busy; try again in a moment"
                                         : "internal error; the details are in the server log");
    else
        mm_buf_str(out, err->msg[0] ? err->msg : mm_strerror(code));
    mm_buf_puts(out, "}}");
    return mm_http_status(code);
}

static void write_tags(mm_buf *b, const char *tags)
{
    mm_buf_char(b, '[');
    int first = 1;
    for (const char *s = tags ? tags : ""; *s;) {
        while (*s == ',' || *s == ' ')
            s++;
        const char *e = s;
        while (*e && *e != ',')
            e++;
        const char *t = e;
        while (t > s && t[-1] == ' ')
            t--;
        if (t > s) {
            if (!first)
                mm_buf_char(b, ',');
            mm_buf_strn(b, s, (size_t)(t - s));
            first = 0;
        }
        s = e;
    }
    mm_buf_char(b, ']');
}

static void write_catalog_fields(mm_buf *b, const mm_exercise *ex)
{
    mm_buf_puts(b, "\"id\":");
    mm_buf_str(b, ex->id);
    mm_buf_puts(b, ",\"chapter\":");
    mm_buf_int(b, ex->chapter);
    field_str(b, "chapter_title", mm_chapter_title(ex->chapter));
    field_str(b, "section", ex->section);
    field_str(b, "section_title", mm_section_title(ex->section));
    field_str(b, "title", ex->title);
    field_str(b, "summary", ex->summary);
    mm_buf_puts(b, ",\"tags\":");
    write_tags(b, ex->tags);
}

/* A value as it was resolved: numbers, nested arrays, or text. */
static void write_value(mm_buf *b, const mm_param *p, const mm_value *v)
{
    switch (p->kind) {
    case MM_REAL:
    case MM_INT:
        mm_buf_num(b, v->x, p->name);
        break;
    case MM_CHOICE:
    case MM_EXPR:
        mm_buf_str(b, v->text);
        break;
    case MM_VECTOR:
    case MM_MATRIX:
        if (p->kind == MM_MATRIX)
            mm_buf_char(b, '[');
        for (int i = 0; i < v->rows; i++) {
            if (i)
                mm_buf_char(b, ',');
            mm_buf_char(b, '[');
            for (int j = 0; j < v->cols; j++) {
                if (j)
                    mm_buf_char(b, ',');
                mm_buf_num(b, v->data[i * v->cols + j], p->name);
            }
            mm_buf_char(b, ']');
        }
        if (p->kind == MM_MATRIX)
            mm_buf_char(b, ']');
        break;
    }
}

static void write_param_meta(mm_buf *b, const mm_param *p)
{
    mm_buf_puts(b, "{\"name\":");
    mm_buf_str(b, p->name);
    field_str(b, "label", p->label);
    field_str(b, "unit", p->unit ? p->unit : "");
    field_str(b, "kind", mm_param_kind_name(p->kind));
    mm_buf_puts(b, ",\"default\":");
    if (p->kind == MM_REAL || p->kind == MM_INT)
        mm_buf_num(b, p->def, p->name);
    else if (p->kind == MM_CHOICE)
        mm_buf_str(b, p->choices[(int)p->def]);
    else
        mm_buf_str(b, p->def_text);
    if (p->kind != MM_CHOICE && p->kind != MM_EXPR) {
        field_num(b, "min", p->min, p->name);
        field_num(b, "max", p->max, p->name);
    }
    if (p->kind == MM_CHOICE) {
        mm_buf_puts(b, ",\"choices\":[");
        for (int i = 0; p->choices[i]; i++) {
            if (i)
                mm_buf_char(b, ',');
            mm_buf_str(b, p->choices[i]);
        }
        mm_buf_char(b, ']');
    }
    if (p->kind == MM_VECTOR) {
        mm_buf_puts(b, ",\"max_length\":");
        mm_buf_int(b, p->max_cols);
    }
    if (p->kind == MM_MATRIX) {
        mm_buf_puts(b, ",\"max_rows\":");
        mm_buf_int(b, p->max_rows);
        mm_buf_puts(b, ",\"max_cols\":");
        mm_buf_int(b, p->max_cols);
    }
    if (p->kind == MM_EXPR) {
        mm_buf_puts(b, ",\"variables\":");
        write_tags(b, p->vars);
        mm_buf_puts(b, ",\"max_length\":");
        mm_buf_int(b, MM_PARAM_EXPR_MAX);
    }
    field_str(b, "help", p->help);
    mm_buf_char(b, '}');
}

static void write_strings(mm_buf *b, const char *const *list, int n)
{
    mm_buf_char(b, '[');
    for (int i = 0; i < n; i++) {
        if (i)
            mm_buf_char(b, ',');
        mm_buf_str(b, list && list[i] ? list[i] : "");
    }
    mm_buf_char(b, ']');
}

/* The figure hints of a series (API.md "Additions"), those declared. */
static void write_hints(mm_buf *b, const mm_output *o)
{
    if (!o)
        return;
    const struct { const char *key, *value; } h[] = {
        {"figure", o->figure}, {"mark", o->mark}, {"role", o->role},
        {"x_scale", o->x_scale}, {"y_scale", o->y_scale}, {"aspect", o->aspect},
    };
    for (size_t i = 0; i < sizeof h / sizeof h[0]; i++)
        if (h[i].value)
            field_str(b, h[i].key, h[i].value);
}

static void write_nums(mm_buf *b, const double *v, int n, const char *where)
{
    mm_buf_nums(b, v, n > 0 ? (size_t)n : 0, where);
}

/* one array of point coordinates per frame */
static void write_frames(mm_buf *b, const double *v, const mm_shape *s, const char *where)
{
    mm_buf_rows(b, v, s->frames > 0 ? (size_t)s->frames : 0, s->npts > 0 ? (size_t)s->npts : 0, where);
}

/* smallest and largest of v[0..n) into lo, hi (finite: the writer refuses
 * others; no fmin/fmax calls).  Two at a time where SSE2 is (x86-64
 * always): minpd/maxpd pick as the comparisons below do, and the order in
 * which the lanes meet can only change the sign of a zero, which the
 * bounds do not show (they are moved by a margin > 0). */
static void min_max(const double *v, size_t n, double *lo, double *hi)
{
    double l = *lo, h = *hi;
    size_t k = 0;
#ifdef __SSE2__
    if (n >= 4) {
        __m128d l2 = _mm_set1_pd(l), h2 = _mm_set1_pd(h);
        for (; k + 2 <= n; k += 2) {
            __m128d x = _mm_loadu_pd(v + k);
            l2 = _mm_min_pd(x, l2);           /* x < l2 ? x : l2 */
            h2 = _mm_max_pd(x, h2);           /* x > h2 ? x : h2 */
        }
        double a[2], b[2];
        _mm_storeu_pd(a, l2);
        _mm_storeu_pd(b, h2);
        l = a[1] < a[0] ? a[1] : a[0];
        h = b[1] > b[0] ? b[1] : b[0];
    }
#endif
    for (; k < n; k++) {
        l = v[k] < l ? v[k] : l;
        h = v[k] > h ? v[k] : h;
    }
    *lo = l, *hi = h;
}

/* bounds from the shapes when the exercise gave none: every point, every
 * circle's extent, with a margin of 5 % of the larger side.  A circle's
 * radius is taken off the smallest coordinate and added to the largest
 * once, not at every point: the same numbers, as rounding is monotonic
 * (min (x - r) = min x - r), for a third of the work. */
static void anim_bounds(const mm_result *r, double bb[4])
{
    memcpy(bb, r->anim->bounds, 4 * sizeof *bb);
    if (bb[0] != 0 || bb[1] != 0 || bb[2] != 0 || bb[3] != 0)
        return;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (const mm_shape_node *n = r->shapes.head; n; n = n->next) {
        if (n->kind == MM_SHAPE_LABEL)
            continue;
        size_t m = (size_t)n->s.frames * (size_t)n->s.npts;
        if (m == 0)
            continue;
        double rad = n->kind == MM_SHAPE_CIRCLE ? n->s.radius : 0;
        if (!isfinite(rad)) {                 /* (an error answer: as it always was) */
            for (size_t k = 0; k < m; k++) {
                double xl = n->s.x[k] - rad, xh = n->s.x[k] + rad, yl = n->s.y[k] - rad, yh = n->s.y[k] + rad;
                lo[0] = xl < lo[0] ? xl : lo[0], hi[0] = xh > hi[0] ? xh : hi[0];
                lo[1] = yl < lo[1] ? yl : lo[1], hi[1] = yh > hi[1] ? yh : hi[1];
            }
            continue;
        }
        double sl[2] = {INFINITY, INFINITY}, sh[2] = {-INFINITY, -INFINITY};
        min_max(n->s.x, m, &sl[0], &sh[0]);
        min_max(n->s.y, m, &sl[1], &sh[1]);
        for (int c = 0; c < 2; c++) {
            double l = sl[c] - rad, h = sh[c] + rad;
            lo[c] = l < lo[c] ? l : lo[c], hi[c] = h > hi[c] ? h : hi[c];
        }
    }
    if (!(lo[0] <= hi[0])) {
        lo[0] = lo[1] = -1, hi[0] = hi[1] = 1;
    }
    double side = fmax(fmax(hi[0] - lo[0], hi[1] - lo[1]), 1e-9), pad = 0.05 * side;
    bb[0] = lo[0] - pad, bb[1] = lo[1] - pad, bb[2] = hi[0] + pad, bb[3] = hi[1] + pad;
}

/* API.md "animation" */
static void write_animation(mm_buf *b, const mm_result *r)
{
    static const char *const kinds[] = {"line", "polygon", "circle", "arrow", "path", "label"};
    double bb[4];
    anim_bounds(r, bb);
    mm_buf_puts(b, ",\"animation\":{\"t\":");
    write_nums(b, r->anim->t, r->anim->nframes, "animation");
    field_str(b, "t_label", r->anim_t_label);
    field_str(b, "t_unit", r->anim_t_unit);
    mm_buf_puts(b, ",\"bounds\":");
    write_nums(b, bb, 4, "animation");
    mm_buf_puts(b, ",\"shapes\":[");
    for (const mm_shape_node *n = r->shapes.head; n; n = n->next) {
        if (n != r->shapes.head)
            mm_buf_char(b, ',');
        mm_buf_puts(b, "{\"name\":");
        mm_buf_str(b, n->name);
        field_str(b, "kind", kinds[n->kind]);
        mm_buf_puts(b, ",\"x\":");
        write_frames(b, n->s.x, &n->s, n->name);
        mm_buf_puts(b, ",\"y\":");
        write_frames(b, n->s.y, &n->s, n->name);
        if (n->kind == MM_SHAPE_CIRCLE)
            field_num(b, "r", n->s.radius, n->name);
        if (n->s.value) {
            mm_buf_puts(b, ",\"value\":");
            write_nums(b, n->s.value, n->s.frames, n->name);
        }
        if (n->s.style)
            field_str(b, "style", n->s.style);
        if (n->kind == MM_SHAPE_ARROW) {
            field_str(b, "unit", n->s.unit ? n->s.unit : "");
            field_num(b, "scale", n->s.scale, n->name);
        }
        if (n->s.text)
            field_str(b, "text", n->s.text);
        mm_buf_char(b, '}');
    }
    mm_buf_puts(b, "]}");
}

/* The answer of a solve (API.md "A solve answer"). */
static void write_answer(mm_buf *b, const mm_exercise *ex, const mm_value *vals,
                         const mm_result *r, long long elapsed_us)
{
    mm_buf_puts(b, "{\"id\":");
    mm_buf_str(b, ex->id);

    mm_buf_puts(b, ",\"params\":{");
    for (int i = 0; i < ex->n_params; i++) {
        if (i)
            mm_buf_char(b, ',');
        mm_buf_key(b, ex->params[i].name);
        write_value(b, &ex->params[i], &vals[i]);
    }

    mm_buf_puts(b, "},\"scalars\":[");
    for (const mm_scalar_node *s = r->scalars.head; s; s = s->next) {
        if (s != r->scalars.head)
            mm_buf_char(b, ',');
        mm_buf_puts(b, "{\"name\":");
        mm_buf_str(b, s->name);
        field_str(b, "label", s->label);
        field_str(b, "unit", s->unit);
        field_num(b, "value", s->s.value, s->name);
        if (s->s.text)
            field_str(b, "text", s->s.text);
        if (s->s.exact)
            mm_buf_puts(b, ",\"exact\":true");
        else if (s->s.error_kind != MM_ERR_NONE) {
            field_num(b, "error", s->s.error, s->name);
            field_str(b, "error_kind", s->s.error_kind == MM_ERR_BOUND ? "bound" : "estimate");
        }
        mm_buf_char(b, '}');
    }

    mm_buf_puts(b, "],\"series\":[");
    for (const mm_series_node *s = r->series.head; s; s = s->next) {
        if (s != r->series.head)
            mm_buf_char(b, ',');
        mm_buf_puts(b, "{\"name\":");
        mm_buf_str(b, s->name);
        field_str(b, "label", s->label);
        field_str(b, "x_label", s->x_label);
        field_str(b, "x_unit", s->x_unit);
        field_str(b, "unit", s->unit);
        write_hints(b, s->decl);
        mm_buf_puts(b, ",\"x\":");
        write_nums(b, s->s.x, s->s.n, s->name);
        mm_buf_puts(b, ",\"y\":");
        write_nums(b, s->s.y, s->s.n, s->name);
        mm_buf_char(b, '}');
    }

    mm_buf_puts(b, "],\"tables\":[");
    for (const mm_table_node *t = r->tables.head; t; t = t->next) {
        if (t != r->tables.head)
            mm_buf_char(b, ',');
        mm_buf_puts(b, "{\"name\":");
        mm_buf_str(b, t->name);
        if (t->label && t->label[0])
            field_str(b, "label", t->label);
        mm_buf_puts(b, ",\"columns\":");
        write_strings(b, t->columns, t->t.ncols);
        mm_buf_puts(b, ",\"units\":");
        write_strings(b, t->units, t->t.ncols);
        mm_buf_puts(b, ",\"rows\":[");
        for (int i = 0; i < t->t.nrows; i++) {
            if (i)
                mm_buf_char(b, ',');
            mm_buf_char(b, '[');
            for (int j = 0; j < t->t.ncols; j++) {
                int k = i * t->t.ncols + j;
                if (j)
                    mm_buf_char(b, ',');
                if (t->t.text[k])
                    mm_buf_str(b, t->t.text[k]);
                else
                    mm_buf_num(b, t->t.cell[k], t->name);
            }
            mm_buf_char(b, ']');
        }
        mm_buf_puts(b, "]}");
    }

    mm_buf_puts(b, "],\"checks\":[");
    for (const mm_check_node *c = r->checks.head; c; c = c->next) {
        double abs_err = fabs(c->value - c->reference);
        /* relative to a reference of (nearly) zero is undefined: left out */
        double rel_err = abs_err / fabs(c->reference);
        double limit = c->relative ? c->tolerance * fabs(c->reference) : c->tolerance;
        int passed = abs_err <= limit;
        if (c != r->checks.head)
            mm_buf_char(b, ',');
        mm_buf_puts(b, "{\"name\":");
        mm_buf_str(b, c->name);
        field_num(b, "value", c->value, c->name);
        field_num(b, "reference", c->reference, c->name);
        field_num(b, "abs_error", abs_err, c->name);
        if (isfinite(rel_err)) {
            field_num(b, "rel_error", rel_err, c->name);
        }
        field_num(b, "tolerance", c->tolerance, c->name);
        mm_buf_puts(b, c->relative ? ",\"tolerance_kind\":\"relative\"" : ",\"tolerance_kind\":\"absolute\"");
        mm_buf_puts(b, passed ? ",\"passed\":true}" : ",\"passed\":false}");
    }

    mm_buf_puts(b, "],\"method\":{\"name\":");
    mm_buf_str(b, r->method ? r->method : "closed-form");
    field_num(b, "step", r->step, "method");
    for (const mm_stat_node *s = r->stats.head; s; s = s->next) {
        mm_buf_char(b, ',');
        mm_buf_key(b, s->key);
        mm_buf_num(b, s->value, s->key);
    }

    mm_buf_puts(b, "},\"warnings\":[");
    for (const mm_warn_node *w = r->warnings.head; w; w = w->next) {
        if (w != r->warnings.head)
            mm_buf_char(b, ',');
        mm_buf_str(b, w->text);
    }
    mm_buf_char(b, ']');
    if (r->anim)
        write_animation(b, r);
    mm_buf_puts(b, ",\"elapsed_us\":");
    mm_buf_int(b, elapsed_us);
    mm_buf_char(b, '}');
}

/* ---- solving --------------------------------------------------------------- */

static int find_param(const mm_exercise *ex, const char *name, size_t len)
{
    for (int i = 0; i < ex->n_params; i++)
        if (strlen(ex->params[i].name) == len && memcmp(ex->params[i].name, name, len) == 0)
            return i;
    return -1;
}

static int unknown_param(const mm_exercise *ex, const mm_input *in, mm_error *err)
{
    char shown[40], list[120] = "";
    size_t n = in->name_len < sizeof shown - 1 ? in->name_len : sizeof shown - 1;
    for (size_t i = 0; i < n; i++)
        shown[i] = (in->name[i] >= 0x20 && in->name[i] < 0x7f) ? in->name[i] : '?';
    shown[n] = '\0';
    for (int i = 0; i < ex->n_params; i++) {
        size_t l = strlen(list);
        snprintf(list + l, sizeof list - l, "%s%s", i ? ", " : "", ex->params[i].name);
    }
    return mm_error_set(err, MM_EPARAM, shown, "%s has no parameter '%s'; its parameters are %s",
                        ex->id, shown, list);
}

/* ---- resolve -> run -> write ------------------------------------------------ */

void mm_solve_init(mm_solve *s, const mm_exercise *ex)
{
    memset(s, 0, sizeof *s);
    s->ex = ex;
    mm_error_clear(&s->err);
    mm_result_init(&s->res, MM_REQ_MEM_CAP);
    mm_result_bind(&s->res, ex);
    mm_buf_init(&s->key, MM_BODY_MAX + MM_QUERY_MAX);
}

void mm_solve_free(mm_solve *s)
{
    if (!s)
        return;
    mm_result_release(&s->res);
    mm_buf_free(&s->key);
    s->ex = NULL;
}

/* One value of the canonical text: a byte that could be read as a
 * separator, or that does not print, is written %XX. */
static void key_text(mm_buf *b, const char *s)
{
    static const char hex[] = "0123456789ABCDEF";
    for (const unsigned char *c = (const unsigned char *)s; *c; c++) {
        if (*c <= 0x20 || *c >= 0x7f || *c == '%' || *c == '&' || *c == '=' || *c == '+' ||
            *c == '#' || *c == ';' || *c == ',') {
            char e[3] = {'%', hex[*c >> 4], hex[*c & 15]};
            mm_buf_put(b, e, 3);
        } else {
            mm_buf_char(b, (char)*c);
        }
    }
}

void mm_api_canonical_value(mm_buf *b, const mm_param *p, const mm_value *v)
{
    char num[MM_DTOA_BUFSIZE];
    switch (p->kind) {
    case MM_REAL:
    case MM_INT:
        mm_buf_put(b, num, (size_t)mm_dtoa(v->x, num));
        break;
    case MM_CHOICE:
    case MM_EXPR:
        key_text(b, v->text ? v->text : "");
        break;
    case MM_VECTOR:
    case MM_MATRIX:
        for (int i = 0; i < v->rows; i++) {
            if (i)
                mm_buf_char(b, ';');
            for (int j = 0; j < v->cols; j++) {
                if (j)
                    mm_buf_char(b, ',');
                mm_buf_put(b, num, (size_t)mm_dtoa(v->data[i * v->cols + j], num));
            }
        }
        break;
    }
}

int mm_api_resolve(mm_solve *s, const mm_input *in, int n_in)
{
    const mm_exercise *ex = s->ex;
    int given[MM_MAX_PARAMS] = {0};
    int rc = MM_OK;
    if (n_in > MM_MAX_PARAMS)
        rc = mm_error_set(&s->err, MM_EPARAM, "", "%d parameters given; %s has %d", n_in, ex->id,
                          ex->n_params);
    for (int i = 0; i < n_in && rc == MM_OK; i++) {
        int k = find_param(ex, in[i].name, in[i].name_len);
        if (k < 0)
            rc = unknown_param(ex, &in[i], &s->err);
        else if (given[k]++)
            rc = mm_error_set(&s->err, MM_EVALUE, ex->params[k].name, "%s is given twice; give it once",
                              ex->params[k].name);
        else
            rc = mm_param_parse(&ex->params[k], in[i].text, in[i].text_len, &s->vals[k], &s->res, &s->err);
    }
    for (int k = 0; k < ex->n_params && rc == MM_OK; k++)
        if (!given[k])
            rc = mm_param_default(&ex->params[k], &s->vals[k], &s->res, &s->err);
    if (rc == MM_OK && ex->check)
        rc = ex->check(s->vals, &s->err);
    if (rc == MM_OK) {
        mm_buf_reset(&s->key);
        mm_buf_puts(&s->key, ex->id);
        for (int k = 0; k < ex->n_params; k++) {
            mm_buf_char(&s->key, k ? '&' : '?');
            mm_buf_puts(&s->key, ex->params[k].name);
            mm_buf_char(&s->key, '=');
            mm_api_canonical_value(&s->key, &ex->params[k], &s->vals[k]);
        }
        if (s->key.failed)
            rc = mm_error_set(&s->err, MM_ETOOBIG, "", "the parameters are too long");
    }
    if (rc != MM_OK && s->err.code == MM_OK)
        s->err.code = rc;
    s->rc = rc;
    s->resolved = rc == MM_OK;
    return rc;
}

int mm_api_run(mm_solve *s)
{
    if (!s->resolved)
        return s->rc ? s->rc : mm_error_set(&s->err, MM_EINTERNAL, "", "run before resolve");
    long long t0 = now_us();
    int rc = s->ex->solve(s->vals, &s->res, &s->err);
    s->elapsed_us = now_us() - t0;
    int failed = mm_result_status(&s->res);   /* sticky: a builder failed, whatever solve said */
    if (failed == MM_ETOOBIG) {
        mm_error_set(&s->err, MM_ETOOBIG, "", "this request needs more than %u MB of memory; "
                     "choose smaller sizes", MM_REQ_MEM_CAP >> 20);
        rc = MM_ETOOBIG;
    } else if (failed != MM_OK) {
        mm_error_set(&s->err, failed, "", "the answer could not be built (%s)", s->res.failure);
        rc = failed;
    }
    if (rc != MM_OK && s->err.code == MM_OK)
        s->err.code = rc;
    /* a refusal from inside the solve that names no parameter of the
     * exercise (a solver's own argument: "t_out") is the exercise's fault,
     * not the request's: a 500 that says so, never a 400 blaming the user */
    if (rc != MM_OK && s->err.param[0] && mm_http_status(rc) == 400) {
        int known = 0;
        for (int k = 0; k < s->ex->n_params && !known; k++)
            known = strcmp(s->ex->params[k].name, s->err.param) == 0;
        if (!known) {
            char param[sizeof s->err.param], msg[sizeof s->err.msg];
            snprintf(param, sizeof param, "%s", s->err.param);
            snprintf(msg, sizeof msg, "%s", s->err.msg);
            mm_error_set(&s->err, MM_EINTERNAL, "", "the exercise failed inside (%s: %.120s); please report it",
                         param, msg);
            rc = MM_EINTERNAL;
        }
    }
    s->rc = rc;
    s->ran = 1;
    return rc;
}

int mm_api_write(mm_solve *s, mm_buf *out)
{
    mm_buf_reset(out);
    if (s->rc == MM_OK && !s->ran)
        mm_api_run(s);
    int rc = s->rc;
    if (rc == MM_OK) {
        write_answer(out, s->ex, s->vals, &s->res, s->elapsed_us);
        if (out->nonfinite) {
            char where[sizeof out->where];
            memcpy(where, out->where, sizeof where);
            mm_error_set(&s->err, MM_ENONFINITE, "", "the result '%s' is not a finite number "
                         "(an overflow or an unstable step); change the parameters", where);
            rc = MM_ENONFINITE;
        } else if (out->failed) {
            mm_error_set(&s->err, MM_ETOOBIG, "", "the answer would be over %u MB; choose smaller sizes",
                         MM_ANSWER_MAX >> 20);
            rc = MM_ETOOBIG;
        }
        s->rc = rc;
    }
    if (rc == MM_OK)
        return 200;
    if (s->err.code == MM_OK)
        s->err.code = rc;
    if (mm_http_status(rc) >= 500)
        fprintf(stderr, "mechmat: %s: internal error: %s (%s)\n", s->ex->id, s->err.msg,
                mm_strerror(rc));
    return mm_api_error(out, &s->err);
}

int mm_api_solve(const mm_exercise *ex, const mm_input *in, int n_in, mm_buf *out)
{
    mm_solve s;
    mm_solve_init(&s, ex);
    if (mm_api_resolve(&s, in, n_in) == MM_OK)
        mm_api_run(&s);
    int status = mm_api_write(&s, out);
    mm_solve_free(&s);
    return status;
}

/* A JSON value as parameter text (mm_params.h): numbers in shortest form,
 * arrays joined by ',' and rows by ';'. */
static int json_to_text(const cJSON *v, mm_buf *t, int depth, const char *name, mm_error *err)
{
    char num[MM_DTOA_BUFSIZE];
    if (cJSON_IsNumber(v)) {
        if (!isfinite(v->valuedouble))   /* 1e999 overflows in cJSON: as in a query, out of range */
            mm_buf_puts(t, v->valuedouble < 0 ? "-1e999" : "1e999");
        else
            mm_buf_put(t, num, (size_t)mm_dtoa(v->valuedouble, num));
        return MM_OK;
    }
    if (cJSON_IsString(v)) {
        mm_buf_puts(t, v->valuestring);
        return MM_OK;
    }
    if (cJSON_IsArray(v) && depth < 2) {
        int i = 0;
        for (const cJSON *e = v->child; e; e = e->next, i++) {
            if (i)
                mm_buf_char(t, depth == 0 && cJSON_IsArray(e) ? ';' : ',');
            if (depth == 1 && cJSON_IsArray(e))
                return mm_error_set(err, MM_EVALUE, name,
                                    "%s: arrays nest at most two deep (rows of numbers)", name);
            int rc = json_to_text(e, t, depth + 1, name, err);
            if (rc != MM_OK)
                return rc;
        }
        return MM_OK;
    }
    return mm_error_set(err, MM_EVALUE, name,
                        "%s must be a number, a text or an array of numbers", name);
}

/* cJSON turns the escape \u0000 into a NUL byte that ends the C string, so
 * "1\u0000junk" would read as "1": find such an escape, or a raw NUL byte
 * in a string, before parsing.
 * Returns 1 when a string holds one, with *param the parameter whose value
 * it is in (the last key met two objects deep; "" when the NUL is in a key
 * or outside params), printable ASCII only. */
static int json_has_nul(const char *s, size_t n, char *param, size_t size)
{
    int depth = 0, in_str = 0;
    size_t start = 0;
    param[0] = '\0';
    for (size_t i = 0; i < n; i++) {
        char c = s[i];
        if (!in_str) {
            if (c == '"')
                in_str = 1, start = i + 1;
            else if (c == '{' || c == '[')
                depth++;
            else if (c == '}' || c == ']')
                depth--;
            continue;
        }
        if (c == '\0' || c == '\\') {
            if (c == '\0' || (i + 5 < n && s[i + 1] == 'u' && memcmp(s + i + 2, "0000", 4) == 0)) {
                size_t j = i + 1;              /* a key itself?  then no parameter */
                while (j < n && s[j] != '"')
                    j += s[j] == '\\' ? 2 : 1;
                for (j++; j < n && (s[j] == ' ' || s[j] == '\t' || s[j] == '\n' || s[j] == '\r'); j++)
                    ;
                if (j < n && s[j] == ':')
                    param[0] = '\0';
                return 1;
            }
            i++;
        } else if (c == '"') {
            in_str = 0;
            size_t j = i + 1;
            while (j < n && (s[j] == ' ' || s[j] == '\t' || s[j] == '\n' || s[j] == '\r'))
                j++;
            if (j < n && s[j] == ':' && depth == 2) {     /* a key of params */
                size_t k = 0;
                for (size_t q = start; q < i && k + 1 < size; q++)
                    param[k++] = s[q] >= 0x20 && s[q] < 0x7f ? s[q] : '?';
                param[k] = '\0';
            } else if (j < n && s[j] == ':') {
                param[0] = '\0';
            }
        }
    }
    return 0;
}

int mm_api_resolve_json(mm_solve *s, const char *body, size_t len)
{
    const mm_exercise *ex = s->ex;
    mm_error *err = &s->err;
    char nul_param[sizeof err->param];
    if (json_has_nul(body, len, nul_param, sizeof nul_param)) {
        if (nul_param[0])
            mm_error_set(err, MM_EVALUE, nul_param, "%s contains a NUL character (\\u0000)", nul_param);
        else
            mm_error_set(err, MM_EVALUE, "", "the body contains a NUL character (\\u0000) in a text");
        return s->rc = err->code;
    }
    const char *end = NULL;
    cJSON *root = cJSON_ParseWithLengthOpts(body, len, &end, 0);
    if (!root) {
        size_t at = end ? (size_t)(end - body) : 0;
        mm_error_set(err, MM_EJSON, "", "the body is not valid JSON (at byte %zu); "
                     "send {\"params\":{\"name\":value,...}}", at);
        return s->rc = err->code;
    }
    const cJSON *params = NULL;
    size_t tail = end ? (size_t)(end - body) : len;   /* only white space may follow */
    while (tail < len && (body[tail] == ' ' || body[tail] == '\t' || body[tail] == '\n' || body[tail] == '\r'))
        tail++;
    if (tail < len) {
        mm_error_set(err, MM_EJSON, "", "the body goes on after its JSON value (at byte %zu); "
                     "send one object {\"params\":{...}}", tail);
    } else if (!cJSON_IsObject(root)) {
        mm_error_set(err, MM_EJSON, "", "the body must be an object {\"params\":{...}}");
    } else {
        for (const cJSON *e = root->child; e && !err->code; e = e->next) {
            if (strcmp(e->string, "params") == 0 && cJSON_IsObject(e) && params)
                mm_error_set(err, MM_EJSON, "", "\"params\" is given twice; give it once");
            else if (strcmp(e->string, "params") == 0 && cJSON_IsObject(e))
                params = e;
            else
                mm_error_set(err, MM_EJSON, "", "the body must be {\"params\":{...}}; "
                             "'%.40s' is not expected there", e->string);
        }
    }
    if (err->code) {
        cJSON_Delete(root);
        return s->rc = err->code;
    }

    int n = cJSON_GetArraySize(params);
    if (n > MM_MAX_PARAMS) {
        cJSON_Delete(root);
        mm_error_set(err, MM_EPARAM, "", "%d parameters given; %s has %d", n, ex->id, ex->n_params);
        return s->rc = err->code;
    }
    mm_input in[MM_MAX_PARAMS] = {{0}};
    mm_buf text[MM_MAX_PARAMS];
    int k = 0, rc = MM_OK;
    for (const cJSON *e = params ? params->child : NULL; e && rc == MM_OK; e = e->next, k++) {
        mm_buf_init(&text[k], MM_BODY_MAX);
        rc = json_to_text(e, &text[k], 0, e->string, err);
        in[k].name = e->string;
        in[k].name_len = strlen(e->string);
        in[k].text = text[k].p ? text[k].p : "";
        in[k].text_len = text[k].len;
    }
    if (rc == MM_OK)
        rc = mm_api_resolve(s, in, k);
    else
        s->rc = rc;
    for (int i = 0; i < k; i++)
        mm_buf_free(&text[i]);
    cJSON_Delete(root);
    return rc;
}

int mm_api_solve_json(const mm_exercise *ex, const char *body, size_t len, mm_buf *out)
{
    mm_solve s;
    mm_solve_init(&s, ex);
    if (mm_api_resolve_json(&s, body, len) == MM_OK)
        mm_api_run(&s);
    int status = mm_api_write(&s, out);
    mm_solve_free(&s);
    return status;
}

/* ---- cached documents -------------------------------------------------------- */

static char *read_file(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    mm_buf b;
    mm_buf_init(&b, 4u << 20);
    char chunk[8192];
    size_t n;
    while ((n = fread(chunk, 1, sizeof chunk, f)) > 0)
        mm_buf_put(&b, chunk, n);
    fclose(f);
    if (b.failed) {
        mm_buf_free(&b);
        return NULL;
    }
    return mm_buf_take(&b, len);
}

/* Outputs of an exercise without an output table (the transition): what
 * the default solve produces.  Goes with the last such exercise. */
static void discover_outputs(mm_buf *b, const mm_exercise *ex)
{
    mm_result res;
    mm_value vals[MM_MAX_PARAMS];
    mm_error err;
    mm_error_clear(&err);
    mm_result_init(&res, MM_REQ_MEM_CAP);
    int rc = MM_OK;
    for (int k = 0; k < ex->n_params && rc == MM_OK; k++)
        rc = mm_param_default(&ex->params[k], &vals[k], &res, &err);
    if (rc == MM_OK)
        rc = ex->solve(vals, &res, &err);
    if (rc != MM_OK)
        fprintf(stderr, "mechmat: %s: the default solve fails: %s\n", ex->id, err.msg);
    int first = 1;
    for (const mm_scalar_node *s = rc ? NULL : res.scalars.head; s; s = s->next, first = 0) {
        mm_buf_puts(b, first ? "{\"kind\":\"scalar\",\"name\":" : ",{\"kind\":\"scalar\",\"name\":");
        mm_buf_str(b, s->name);
        mm_buf_puts(b, ",\"label\":");
        mm_buf_str(b, s->label);
        mm_buf_puts(b, ",\"unit\":");
        mm_buf_str(b, s->unit);
        mm_buf_char(b, '}');
    }
    for (const mm_series_node *s = rc ? NULL : res.series.head; s; s = s->next, first = 0) {
        mm_buf_puts(b, first ? "{\"kind\":\"series\",\"name\":" : ",{\"kind\":\"series\",\"name\":");
        mm_buf_str(b, s->name);
        mm_buf_puts(b, ",\"label\":");
        mm_buf_str(b, s->label);
        mm_buf_puts(b, ",\"unit\":");
        mm_buf_str(b, s->unit);
        mm_buf_puts(b, ",\"x_label\":");
        mm_buf_str(b, s->x_label);
        mm_buf_puts(b, ",\"x_unit\":");
        mm_buf_str(b, s->x_unit);
        mm_buf_char(b, '}');
    }
    for (const mm_table_node *t = rc ? NULL : res.tables.head; t; t = t->next, first = 0) {
        mm_buf_puts(b, first ? "{\"kind\":\"table\",\"name\":" : ",{\"kind\":\"table\",\"name\":");
        mm_buf_str(b, t->name);
        mm_buf_puts(b, ",\"columns\":");
        write_strings(b, t->columns, t->t.ncols);
        mm_buf_puts(b, ",\"units\":");
        write_strings(b, t->units, t->t.ncols);
        mm_buf_char(b, '}');
    }
    mm_result_release(&res);

}

/* The declared outputs, every member of a family by its name. */
static void write_outputs_meta(mm_buf *b, const mm_exercise *ex)
{
    static const char *const kinds[] = {"", "scalar", "series", "table", "animation"};
    int first = 1;
    for (int i = 0; i < ex->n_outputs; i++) {
        const mm_output *o = &ex->outputs[i];
        int n = mm_output_count(o);
        for (int k = 0; k < n; k++, first = 0) {
            char name[160], label[320];
            mm_output_member(o, mm_output_index(o, k), name, sizeof name);
            snprintf(label, sizeof label, "%s", o->label);
            if (n > 1 || strchr(o->name, '%')) {          /* the label's hole too */
                mm_output tmp = *o;
                tmp.name = o->label;
                if (mm_output_member(&tmp, mm_output_index(o, k), label, sizeof label) != 0)
                    snprintf(label, sizeof label, "%s", o->label);
            }
            mm_buf_puts(b, first ? "{\"kind\":" : ",{\"kind\":");
            mm_buf_str(b, kinds[o->kind]);
            field_str(b, "name", name);
            field_str(b, "label", label);
            if (o->kind != MM_OUT_TABLE && o->kind != MM_OUT_ANIMATION)
                field_str(b, "unit", o->unit ? o->unit : "");
            if (strchr(o->name, '%'))
                field_str(b, "family", o->name);
            if (o->flags & MM_ANSWER)
                mm_buf_puts(b, ",\"answer\":true");
            if (o->flags & MM_EXACT)
                mm_buf_puts(b, ",\"exact\":true");
            if (o->kind == MM_OUT_SERIES) {
                field_str(b, "x_label", o->x_label);
                field_str(b, "x_unit", o->x_unit ? o->x_unit : "");
                write_hints(b, o);
            }
            if (o->kind == MM_OUT_TABLE) {
                int nc = 0;
                while (o->columns[nc])
                    nc++;
                mm_buf_puts(b, ",\"columns\":");
                write_strings(b, o->columns, nc);
                mm_buf_puts(b, ",\"units\":");
                write_strings(b, o->units, nc);
            }
            mm_buf_char(b, '}');
        }
    }
}

/* Metadata of one exercise. */
static char *build_meta(const mm_exercise *ex, const char *root, size_t *len)
{
    mm_buf b;
    mm_buf_init(&b, 8u << 20);

    char path[4096];
    size_t md_len = 0;
    snprintf(path, sizeof path, "%s/%s", root, ex->theory ? ex->theory : "");
    char *md = ex->theory ? read_file(path, &md_len) : NULL;
    if (!md)
        fprintf(stderr, "mechmat: %s: no theory text at %s\n", ex->id, path);
    char *html = md ? mm_theory_html(md, md_len) : NULL;

    mm_buf_char(&b, '{');
    write_catalog_fields(&b, ex);
    mm_buf_puts(&b, ",\"theory\":");
    mm_buf_str(&b, md ? md : "");
    mm_buf_puts(&b, ",\"theory_html\":");
    mm_buf_str(&b, html ? html : "");
    free(md);
    free(html);

    mm_buf_puts(&b, ",\"params\":[");
    for (int i = 0; i < ex->n_params; i++) {
        if (i)
            mm_buf_char(&b, ',');
        write_param_meta(&b, &ex->params[i]);
    }
    mm_buf_puts(&b, "],\"outputs\":[");

    if (ex->n_outputs > 0)
        write_outputs_meta(&b, ex);
    else
        discover_outputs(&b, ex);
    mm_buf_puts(&b, "],\"references\":[");
    for (int i = 0; ex->references && ex->references[i]; i++) {
        if (i)
            mm_buf_char(&b, ',');
        mm_buf_str(&b, ex->references[i]);
    }
    mm_buf_puts(&b, "]}");
    if (b.failed || b.nonfinite) {
        mm_buf_free(&b);
        return NULL;
    }
    return mm_buf_take(&b, len);
}

/* ---- the build: what an answer's ETag is made from ------------------------------ */

static pthread_once_t build_once = PTHREAD_ONCE_INIT;
static char build_id[MM_DIGEST_SIZE];

/* The digest of the running binary and MM_VERSION: two instances of the
 * same build give the same ETags (nginx balancing between them keeps its
 * validators), a rebuilt exercise never passes for the old one. */
static void make_build_id(void)
{
    mm_hasher h;
    mm_hash_init(&h);
    mm_hash_part(&h, MM_VERSION, strlen(MM_VERSION));
    FILE *f = fopen("/proc/self/exe", "rb");
    if (f) {
        char chunk[65536];
        size_t n;
        while ((n = fread(chunk, 1, sizeof chunk, f)) > 0)
            mm_hash_update(&h, chunk, n);
        fclose(f);
    }
    mm_hash_final(&h, build_id);
}

const char *mm_api_build_id(void)
{
    pthread_once(&build_once, make_build_id);
    return build_id;
}

void mm_api_answer_etag(const char *key, size_t len, char out[MM_ETAG_SIZE])
{
    mm_hasher h;
    char d[MM_DIGEST_SIZE];
    const char *b = mm_api_build_id();
    mm_hash_init(&h);
    mm_hash_part(&h, b, strlen(b));
    mm_hash_part(&h, key, len);
    mm_hash_final(&h, d);
    snprintf(out, MM_ETAG_SIZE, "\"%s\"", d);
}

/* ---- the documents of a course ------------------------------------------------------ */

static int set_doc(mm_doc *d, mm_buf *b)
{
    if (b->failed || b->nonfinite) {
        mm_buf_free(b);
        return MM_ENOMEM;
    }
    char *text = mm_buf_take(b, &d->len);
    if (!text)
        return MM_ENOMEM;
    d->text = text;
    char dg[MM_DIGEST_SIZE];
    mm_digest(text, d->len, dg);
    snprintf(d->etag, sizeof d->etag, "\"%s\"", dg);
    return MM_OK;
}

static void free_doc(mm_doc *d)
{
    free((char *)d->text);
    d->text = NULL;
}

mm_api *mm_api_alloc(const char *root, mm_error *err)
{
    mm_course *c = mm_course_builtin();
    if (!c) {
        mm_error_set(err, MM_ENOMEM, "", "out of memory");
        return NULL;
    }
    return mm_api_alloc_course(root, c, err);
}

/* Every assignment of the course, checked against its exercise; a bad one
 * fails the course with its line.  What the instructor should know about
 * them (duplicate variants) goes to the log. */
static int load_assignments(mm_api *api, mm_error *err)
{
    const mm_course *c = api->course;
    int n = mm_course_assignment_count(c);
    api->assign = calloc((size_t)n + 1, sizeof *api->assign);
    if (!api->assign)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    mm_buf notes;
    mm_buf_init(&notes, 1 << 16);
    int rc = MM_OK;
    for (int i = 0; i < n && rc == MM_OK; i++) {
        const cJSON *j = mm_course_assignment(c, i);
        const char *id = mm_assign_exercise_id(j);
        const mm_exercise *ex = id ? mm_course_find(c, id) : NULL;
        mm_error e2;
        mm_error_clear(&e2);
        if (!ex)
            rc = mm_error_set(&e2, MM_EVALUE, "exercise", "\"exercise\" must name an exercise of this course%s%.60s%s",
                              id ? " ('" : "", id ? id : "", id ? "' is not one)" : "");
        else
            rc = mm_assign_load(j, ex, &api->assign[i], &notes, &e2);
        if (rc != MM_OK)
            mm_error_set(err, MM_EVALUE, e2.param, "line %d: assignment %s: %s", mm_course_line(c, j),
                         mm_course_assignment_name(c, i), e2.msg);
        else
            api->n_assign++;
    }
    if (rc == MM_OK && notes.len)
        fprintf(stderr, "mechmat: %.*s", (int)notes.len, notes.p);
    mm_buf_free(&notes);
    return rc;
}

mm_api *mm_api_alloc_course(const char *root, mm_course *course, mm_error *err)
{
    mm_api *api = calloc(1, sizeof *api);
    if (!api) {
        mm_course_free(course);
        mm_error_set(err, MM_ENOMEM, "", "out of memory");
        return NULL;
    }
    api->course = course;
    int n = mm_course_exercise_count(course);
    api->meta = calloc((size_t)n + 1, sizeof *api->meta);
    api->scripts = calloc((size_t)n + 1, sizeof *api->scripts);
    if (!api->meta || !api->scripts)
        goto nomem;
    mm_api_build_id();

    if (mm_registry_check(err) != MM_OK)
        goto fail;
    for (int i = 0; i < n; i++) {
        const mm_exercise *ex = mm_course_exercise(course, i);
        if (ex->n_params > MM_MAX_PARAMS || mm_params_check(ex, err) != MM_OK) {
            if (ex->n_params > MM_MAX_PARAMS)
                mm_error_set(err, MM_EINTERNAL, "", "%s has over %d parameters", ex->id, MM_MAX_PARAMS);
            goto fail;
        }
        char path[4096];
        size_t len = 0;
        snprintf(path, sizeof path, "%s/%.*sm", root, (int)strlen(ex->theory) - 2, ex->theory);
        api->scripts[i] = read_file(path, &len);       /* a missing body: the route says so */
        char *text = build_meta(ex, root, &len);
        mm_buf b = {.p = text, .len = len, .cap = len + 1, .max = len + 1};
        if (!text || set_doc(&api->meta[i], &b) != MM_OK) {
            mm_error_set(err, MM_EINTERNAL, "", "%s: metadata could not be written", ex->id);
            goto fail;
        }
    }

    mm_buf b;
    mm_buf_init(&b, 1u << 20);
    mm_buf_puts(&b, "{\"status\":\"ok\",\"version\":\"" MM_VERSION "\",\"exercises\":");
    mm_buf_int(&b, n);
    mm_buf_char(&b, '}');
    if (set_doc(&api->health, &b) != MM_OK)
        goto nomem;

    mm_buf_init(&b, 1u << 20);
    mm_buf_char(&b, '[');
    for (int i = 0; i < n; i++) {
        if (i)
            mm_buf_char(&b, ',');
        mm_buf_char(&b, '{');
        write_catalog_fields(&b, mm_course_exercise(course, i));
        mm_buf_char(&b, '}');
    }
    mm_buf_char(&b, ']');
    if (set_doc(&api->catalog, &b) != MM_OK)
        goto nomem;

    mm_buf_init(&b, 1u << 20);
    mm_buf_puts(&b, "{\"title\":");
    mm_buf_str(&b, mm_course_title(course));
    field_str(&b, "language", mm_course_language(course));
    field_str(&b, "base_path", mm_course_base_path(course));
    field_str(&b, "digest", mm_course_digest(course));
    field_str(&b, "build", mm_api_build_id());
    mm_buf_puts(&b, ",\"exercises\":[");
    for (int i = 0; i < n; i++) {
        if (i)
            mm_buf_char(&b, ',');
        mm_buf_str(&b, mm_course_exercise(course, i)->id);
    }
    mm_buf_puts(&b, "],\"assignments\":");
    mm_buf_int(&b, mm_course_assignment_count(course));
    mm_buf_char(&b, '}');
    if (set_doc(&api->course_doc, &b) != MM_OK)
        goto nomem;

    if (load_assignments(api, err) != MM_OK)
        goto fail;
    mm_buf_init(&b, 1u << 20);
    mm_buf_char(&b, '[');
    for (int i = 0; i < api->n_assign; i++) {
        if (i)
            mm_buf_char(&b, ',');
        mm_buf_puts(&b, "{\"name\":");
        mm_buf_str(&b, mm_assign_name(api->assign[i]));
        field_str(&b, "title", mm_assign_title(api->assign[i]));
        field_str(&b, "exercise", mm_assign_exercise(api->assign[i])->id);
        mm_buf_char(&b, '}');
    }
    mm_buf_char(&b, ']');
    if (set_doc(&api->assignments_doc, &b) != MM_OK)
        goto nomem;

    mm_buf_init(&b, 64u << 20);
    mm_openapi_write(&b, course);
    if (set_doc(&api->openapi, &b) != MM_OK) {
        mm_error_set(err, MM_EINTERNAL, "", "the OpenAPI document could not be written");
        goto fail;
    }
    return api;
nomem:
    mm_error_set(err, MM_ENOMEM, "", "out of memory");
fail:
    mm_api_free(api);
    return NULL;
}

void mm_api_free(mm_api *api)
{
    if (!api)
        return;
    int n = api->course ? mm_course_exercise_count(api->course) : 0;
    for (int i = 0; api->meta && i < n; i++)
        free_doc(&api->meta[i]);
    for (int i = 0; api->scripts && i < n; i++)
        free(api->scripts[i]);
    free(api->scripts);
    for (int i = 0; i < api->n_assign; i++)
        mm_assign_free(api->assign[i]);
    free(api->assign);
    free_doc(&api->assignments_doc);
    free(api->meta);
    free_doc(&api->health);
    free_doc(&api->catalog);
    free_doc(&api->course_doc);
    free_doc(&api->openapi);
    mm_course_free(api->course);
    free(api);
}

const mm_course *mm_api_course(const mm_api *api) { return api->course; }

const char *mm_api_script_body(const mm_api *api, const char *id)
{
    int n = mm_course_exercise_count(api->course);
    for (int i = 0; i < n; i++)
        if (strcmp(mm_course_exercise(api->course, i)->id, id) == 0)
            return api->scripts[i];
    return NULL;
}

const mm_assignment *mm_api_assignment(const mm_api *api, const char *name)
{
    for (int i = 0; i < api->n_assign; i++)
        if (strcmp(mm_assign_name(api->assign[i]), name) == 0)
            return api->assign[i];
    return NULL;
}

const mm_doc *mm_api_doc_assignments(const mm_api *api) { return &api->assignments_doc; }

const mm_exercise *mm_api_exercise(const mm_api *api, const char *id)
{
    return mm_course_find(api->course, id);
}

const mm_doc *mm_api_doc_health(const mm_api *api) { return &api->health; }
const mm_doc *mm_api_doc_catalog(const mm_api *api) { return &api->catalog; }
const mm_doc *mm_api_doc_course(const mm_api *api) { return &api->course_doc; }
const mm_doc *mm_api_doc_openapi(const mm_api *api) { return &api->openapi; }

const mm_doc *mm_api_doc_meta(const mm_api *api, const char *id)
{
    int n = mm_course_exercise_count(api->course);
    for (int i = 0; i < n; i++)
        if (strcmp(mm_course_exercise(api->course, i)->id, id) == 0)
            return &api->meta[i];
    return NULL;
}

const char *mm_api_health(const mm_api *api, size_t *len)
{
    *len = api->health.len;
    return api->health.text;
}

const char *mm_api_catalog(const mm_api *api, size_t *len)
{
    *len = api->catalog.len;
    return api->catalog.text;
}

const char *mm_api_meta(const mm_api *api, const char *id, size_t *len)
{
    const mm_doc *d = mm_api_doc_meta(api, id);
    if (!d)
        return NULL;
    *len = d->len;
    return d->text;
}
