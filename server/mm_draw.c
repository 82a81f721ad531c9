/* mm_draw.c — random parameter values (see mm_draw.h). */
#include "mm_draw.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mm_dtoa.h"
#include "mm_params.h"
#include "mm_result_impl.h"

void mm_rng_seed(mm_rng *g, uint64_t seed)
{
    g->s = seed ? seed : 0x9E3779B97F4A7C15ULL;
}

double mm_rng_uniform(mm_rng *g)
{
    g->s ^= g->s >> 12;
    g->s ^= g->s << 25;
    g->s ^= g->s >> 27;
    return (double)((g->s * 2685821657736338717ULL) >> 11) / 9007199254740992.0;
}

uint64_t mm_draw_seed(const char *a, const char *b)
{
    uint64_t h = 0xcbf29ce484222325ULL;           /* FNV-1a 64 */
    const char *parts[2] = {a ? a : "", b ? b : ""};
    for (int i = 0; i < 2; i++) {
        for (const unsigned char *s = (const unsigned char *)parts[i]; *s; s++)
            h = (h ^ *s) * 0x100000001b3ULL;
        h = (h ^ 0xffu) * 0x100000001b3ULL;          /* a byte no UTF-8 text holds */
    }
    h += 0x9E3779B97F4A7C15ULL;                   /* splitmix64's finaliser */
    h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ULL;
    h = (h ^ (h >> 27)) * 0x94D049BB133111EBULL;
    return h ^ (h >> 31);
}

double mm_draw_number(const mm_param *p, mm_rng *g)
{
    double v;
    if (p->min > 0 && p->max / p->min > 100)
        v = p->min * pow(p->max / p->min, mm_rng_uniform(g));
    else
        v = p->min + (p->max - p->min) * mm_rng_uniform(g);
    if (p->kind == MM_INT)
        v = floor(v + 0.5);
    return fmin(fmax(v, p->min), p->max);
}

/* out += text; MM_ETOOBIG when it does not fit */
static int append(char *out, size_t size, size_t *len, const char *text)
{
    size_t n = strlen(text);
    if (*len + n + 1 > size)
        return MM_ETOOBIG;
    memcpy(out + *len, text, n + 1);
    *len += n;
    return MM_OK;
}

static int draw_array(const mm_param *p, mm_rng *g, char *out, size_t size)
{
    mm_result arena;
    mm_value v;
    mm_error err;
    mm_result_init(&arena, 1 << 22);
    int rc = mm_param_default(p, &v, &arena, &err);
    if (rc != MM_OK) {
        mm_result_release(&arena);
        return MM_EINTERNAL;
    }
    int cells = v.rows * v.cols;
    int sym = p->kind == MM_MATRIX && v.rows == v.cols;
    for (int i = 0; sym && i < v.rows; i++)
        for (int j = 0; j < i; j++)
            if (v.data[i * v.cols + j] != v.data[j * v.cols + i])
                sym = 0;
    double *f = mm_res_alloc(&arena, (size_t)cells * sizeof *f + 1);
    if (!f) {
        mm_result_release(&arena);
        return MM_ETOOBIG;
    }
    for (int k = 0; k < cells; k++)
        f[k] = 0.5 + mm_rng_uniform(g);
    size_t len = 0;
    char num[MM_DTOA_BUFSIZE];
    for (int i = 0; i < v.rows && rc == MM_OK; i++) {
        if (i)
            rc = append(out, size, &len, ";");
        for (int j = 0; j < v.cols && rc == MM_OK; j++) {
            int kf = sym && j < i ? j * v.cols + i : i * v.cols + j;   /* mirror the factor */
            double x = fmin(fmax(v.data[i * v.cols + j] * f[kf], p->min), p->max);
            mm_dtoa(x, num);
            if (j)
                rc = append(out, size, &len, ",");
            if (rc == MM_OK)
                rc = append(out, size, &len, num);
        }
    }
    mm_result_release(&arena);
    return rc;
}

int mm_draw_text(const mm_param *p, mm_rng *g, char *out, size_t size)
{
    if (size == 0)
        return MM_ETOOBIG;
    out[0] = '\0';
    int rc = MM_OK;
    switch (p->kind) {
    case MM_REAL:
    case MM_INT: {
        char num[MM_DTOA_BUFSIZE];
        mm_dtoa(mm_draw_number(p, g), num);
        size_t len = 0;
        rc = append(out, size, &len, num);
        break;
    }
    case MM_CHOICE: {
        int n = 0;
        while (p->choices && p->choices[n])
            n++;
        if (n == 0)
            return MM_EINTERNAL;
        size_t len = 0;
        rc = append(out, size, &len, p->choices[(int)(mm_rng_uniform(g) * n) % n]);
        break;
    }
    case MM_EXPR: {
        size_t len = 0;
        rc = append(out, size, &len, p->def_text ? p->def_text : "");
        break;
    }
    case MM_VECTOR:
    case MM_MATRIX:
        rc = draw_array(p, g, out, size);
        break;
    }
    if (rc != MM_OK)
        out[0] = '\0';
    return rc;
}

int mm_draw_request(const mm_exercise *ex, mm_rng *g, int tries, mm_draw_set *set, mm_error *err)
{
    int rc = MM_EINTERNAL;
    int keep[MM_MAX_PARAMS] = {0}, streak[MM_MAX_PARAMS] = {0};
    mm_error_clear(err);
    for (int t = 0; t < (tries > 0 ? tries : 1); t++) {
        set->n = 0;
        for (int k = 0; k < ex->n_params && k < MM_MAX_PARAMS; k++) {
            const mm_param *p = &ex->params[k];
            rc = mm_draw_text(p, g, set->texts[k], sizeof set->texts[k]);
            if (rc != MM_OK)
                return mm_error_set(err, rc, p->name, "%s: no value could be drawn for %s", ex->id, p->name);
            if (keep[k])
                snprintf(set->texts[k], sizeof set->texts[k], "%s", p->def_text);
            set->in[k] = (mm_input){p->name, set->texts[k], strlen(p->name), strlen(set->texts[k])};
            set->n++;
        }
        mm_solve s;
        mm_solve_init(&s, ex);
        rc = mm_api_resolve(&s, set->in, set->n);
        if (rc != MM_OK && err)
            *err = s.err;
        /* A structure (a truss's members, a mesh) drawn at random rarely
         * holds together: a vector or matrix named by three refusals in a
         * row keeps its default, and the rest still varies. */
        for (int k = 0; rc != MM_OK && k < ex->n_params && k < MM_MAX_PARAMS; k++)
            if (strcmp(ex->params[k].name, s.err.param) == 0 &&
                (ex->params[k].kind == MM_MATRIX || ex->params[k].kind == MM_VECTOR) && ex->params[k].def_text &&
                ++streak[k] >= 3)
                keep[k] = 1;
        mm_solve_free(&s);
        if (rc == MM_OK)
            return MM_OK;
    }
    return rc;
}
