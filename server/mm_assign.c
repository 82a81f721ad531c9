/* mm_assign.c — assignments: variants and judging (see mm_assign.h). */
#include "mm_assign.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mm_dtoa.h"
#include "mm_params.h"
#include "mm_result_impl.h"

enum { SET_STEP, SET_SIG, SET_LIST };

typedef struct vary {
    int param;                  /* index in ex->params */
    int kind;
    double min, max, step;
    int sig, decimals;          /* SET_SIG: figures; SET_STEP: decimals of the grid */
    double count;               /* members of the set */
    char **texts;               /* SET_LIST: each member as parameter text */
} vary;

typedef struct ask {
    char name[64];
    const char *label;
    mm_rule rule;
    double ask_factor;          /* SI per asked unit */
    double out_factor;          /* SI per the output's declared unit */
    mm_quantity dim;            /* the dimension of the answer */
} ask;

struct mm_assignment {
    char name[64], title[200];
    const mm_exercise *ex;
    vary vary[MM_MAX_PARAMS];
    int nvary;
    char *fixed[MM_MAX_PARAMS]; /* text of a parameter the assignment fixes, or NULL */
    ask ask[MM_ASSIGN_MAX_ASK];
    int nask;
    int class_size, reveal;
    char key[128];              /* the instructor's key, "" for none */
    char **students;            /* the roster, in order */
    long *roster_draw;          /* the draw each roster student holds */
    int nstudents;
};

/* ---- small pieces ---------------------------------------------------------------- */

static uint64_t fnv1a(uint64_t h, const char *s, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        h ^= (unsigned char)s[i];
        h *= 0x100000001b3ULL;
    }
    return h;
}

static uint64_t splitmix(uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

static double uniform(uint64_t *s) { return (double)(splitmix(s) >> 11) / 9007199254740992.0; }

static char *dupstr(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = malloc(n);
    if (d)
        memcpy(d, s, n);
    return d;
}

/* decimals a step needs: 0.05 -> 2, 10 -> 0, 2.5e-3 -> 4 */
static int decimals_of(double x)
{
    char s[MM_DTOA_BUFSIZE];
    mm_dtoa(x, s);
    const char *e = strchr(s, 'e'), *dot = strchr(s, '.');
    int d = 0;
    if (dot)
        d = (int)((e ? e : s + strlen(s)) - dot - 1);
    if (e)
        d -= atoi(e + 1);
    return d < 0 ? 0 : d;
}

/* a JSON value as parameter text (numbers shortest, arrays by , and ;) */
static int json_text(const cJSON *v, char *out, size_t size, int depth)
{
    size_t len = strlen(out);
    if (cJSON_IsNumber(v)) {
        char s[MM_DTOA_BUFSIZE];
        mm_dtoa(v->valuedouble, s);
        snprintf(out + len, size - len, "%s", s);
    } else if (cJSON_IsString(v)) {
        snprintf(out + len, size - len, "%s", v->valuestring);
    } else if (cJSON_IsArray(v) && depth < 2) {
        int i = 0;
        for (const cJSON *e = v->child; e; e = e->next, i++) {
            len = strlen(out);
            if (i)
                snprintf(out + len, size - len, "%s", depth == 0 && cJSON_IsArray(e) ? ";" : ",");
            if (json_text(e, out, size, depth + 1) != 0)
                return -1;
        }
    } else {
        return -1;
    }
    return strlen(out) + 1 < size ? 0 : -1;
}

static int find_param(const mm_exercise *ex, const char *name)
{
    for (int i = 0; i < ex->n_params; i++)
        if (strcmp(ex->params[i].name, name) == 0)
            return i;
    return -1;
}

/* the declared scalar output named name (a family member by its name) */
static const mm_output *find_scalar(const mm_exercise *ex, const char *name)
{
    for (int i = 0; i < ex->n_outputs; i++) {
        const mm_output *o = &ex->outputs[i];
        if (o->kind != MM_OUT_SCALAR)
            continue;
        for (int k = 0; k < mm_output_count(o); k++) {
            char m[160];
            mm_output_member(o, mm_output_index(o, k), m, sizeof m);
            if (strcmp(m, name) == 0)
                return o;
        }
    }
    return NULL;
}

/* ---- sets of values ---------------------------------------------------------------- */

/* every number with sig significant figures in [min, max] (min > 0): per
 * decade e, the mantissas 10^(sig-1) .. 10^sig - 1 times 10^(e - sig + 1) */
static double sig_count(double min, double max, int sig, double *member, double index)
{
    double count = 0;
    for (int e = (int)floor(log10(min)); e <= (int)floor(log10(max)); e++) {
        double unit = pow(10, e - sig + 1), lo = pow(10, sig - 1), hi = pow(10, sig) - 1;
        double first = fmax(lo, ceil(min / unit - 1e-9)), last = fmin(hi, floor(max / unit + 1e-9));
        if (last < first)
            continue;
        double n = last - first + 1;
        if (member && index < count + n) {
            char s[64];
            snprintf(s, sizeof s, "%.0fe%d", first + (index - count), e - sig + 1);
            *member = strtod(s, NULL);
            return count;
        }
        count += n;
    }
    return count;
}

static void member_text(const mm_assignment *a, const vary *v, double index, char *out, size_t size)
{
    const mm_param *p = &a->ex->params[v->param];
    double x = 0;
    switch (v->kind) {
    case SET_STEP:
        x = v->min + index * v->step;
        snprintf(out, size, "%.*f", v->decimals, x);
        if (p->kind == MM_INT)
            snprintf(out, size, "%.0f", x);
        return;
    case SET_SIG:
        sig_count(v->min, v->max, v->sig, &x, index);
        mm_dtoa(x, out);
        return;
    default:
        snprintf(out, size, "%s", v->texts[(size_t)index]);
        return;
    }
}

/* ---- loading --------------------------------------------------------------------- */

static int load_vary(mm_assignment *a, const cJSON *spec, int k, mm_error *err)
{
    const mm_param *p = &a->ex->params[k];
    vary *v = &a->vary[a->nvary];
    v->param = k;
    const cJSON *values = cJSON_GetObjectItem(spec, "values");
    const cJSON *mn = cJSON_GetObjectItem(spec, "min"), *mx = cJSON_GetObjectItem(spec, "max");
    const cJSON *step = cJSON_GetObjectItem(spec, "step"), *sig = cJSON_GetObjectItem(spec, "sig");
    if (cJSON_IsArray(values)) {
        int n = cJSON_GetArraySize(values);
        if (n < 1 || n > MM_ASSIGN_MAX_LIST)
            return mm_error_set(err, MM_EVALUE, p->name, "%s: values must list 1 to %d values", p->name,
                                MM_ASSIGN_MAX_LIST);
        v->kind = SET_LIST;
        v->texts = calloc((size_t)n, sizeof *v->texts);
        if (!v->texts)
            return mm_error_set(err, MM_ENOMEM, "", "out of memory");
        a->nvary++;                               /* owned from here: freed with a */
        int i = 0;
        for (const cJSON *e = values->child; e; e = e->next, i++) {
            char t[MM_ASSIGN_TEXT] = "";
            if (json_text(e, t, sizeof t, 0) != 0 || !(v->texts[i] = dupstr(t)))
                return mm_error_set(err, MM_EVALUE, p->name, "%s: value %d is not a number, a text or an array",
                                    p->name, i + 1);
        }
        v->count = n;
        return MM_OK;
    }
    if (!cJSON_IsNumber(mn) || !cJSON_IsNumber(mx) || (!cJSON_IsNumber(step) == !cJSON_IsNumber(sig)))
        return mm_error_set(err, MM_EVALUE, p->name, "%s: give \"values\": [...], or \"min\", \"max\" and "
                            "either \"step\" or \"sig\" (significant figures)", p->name);
    if (p->kind != MM_REAL && p->kind != MM_INT)
        return mm_error_set(err, MM_EVALUE, p->name, "%s is not a number: list its \"values\"", p->name);
    v->min = mn->valuedouble;
    v->max = mx->valuedouble;
    if (!(v->min <= v->max) || v->min < p->min || v->max > p->max)
        return mm_error_set(err, MM_EVALUE, p->name, "%s: the range %g..%g must lie within the exercise's "
                            "limits %g..%g", p->name, v->min, v->max, p->min, p->max);
    if (cJSON_IsNumber(step)) {
        v->kind = SET_STEP;
        v->step = step->valuedouble;
        if (!(v->step > 0) || (v->max - v->min) / v->step > 1e9)
            return mm_error_set(err, MM_EVALUE, p->name, "%s: step must be positive and give at most 1e9 values",
                                p->name);
        if (p->kind == MM_INT && (v->step != floor(v->step) || v->min != floor(v->min)))
            return mm_error_set(err, MM_EVALUE, p->name, "%s is a whole number: min and step must be whole",
                                p->name);
        v->decimals = decimals_of(v->step) > decimals_of(v->min) ? decimals_of(v->step) : decimals_of(v->min);
        v->count = floor((v->max - v->min) / v->step + 1e-9) + 1;
    } else {
        v->kind = SET_SIG;
        v->sig = sig->valueint;
        if (sig->valuedouble != v->sig || v->sig < 1 || v->sig > 6 || !(v->min > 0))
            return mm_error_set(err, MM_EVALUE, p->name, "%s: sig must be 1 to 6 significant figures, on a "
                                "range with min > 0", p->name);
        if (p->kind == MM_INT)
            return mm_error_set(err, MM_EVALUE, p->name, "%s is a whole number: give a step", p->name);
        v->count = sig_count(v->min, v->max, v->sig, NULL, 0);
        if (v->count < 1)
            return mm_error_set(err, MM_EVALUE, p->name, "%s: no number with %d significant figures lies in "
                                "%g..%g", p->name, v->sig, v->min, v->max);
    }
    a->nvary++;
    return MM_OK;
}

static int load_ask(mm_assignment *a, const cJSON *q, mm_error *err)
{
    const cJSON *name = cJSON_GetObjectItem(q, "name");
    if (a->nask >= MM_ASSIGN_MAX_ASK)
        return mm_error_set(err, MM_EVALUE, "ask", "at most %d answers may be asked", MM_ASSIGN_MAX_ASK);
    if (!cJSON_IsString(name))
        return mm_error_set(err, MM_EVALUE, "ask", "each asked answer needs a \"name\"");
    const mm_output *o = find_scalar(a->ex, name->valuestring);
    if (!o)
        return mm_error_set(err, MM_EVALUE, "ask", "%s has no scalar output '%.60s'", a->ex->id, name->valuestring);
    ask *k = &a->ask[a->nask];
    snprintf(k->name, sizeof k->name, "%s", name->valuestring);
    k->label = o->label;
    if (mm_unit_parse(o->unit ? o->unit : "", &k->dim, err) != MM_OK)
        return mm_error_set(err, MM_EINTERNAL, "ask", "the unit of %s ('%s') cannot be read", k->name, o->unit);
    k->out_factor = k->dim.value;
    const cJSON *unit = cJSON_GetObjectItem(q, "unit");
    snprintf(k->rule.unit, sizeof k->rule.unit, "%s", cJSON_IsString(unit) ? unit->valuestring : o->unit);
    mm_quantity u;
    if (mm_unit_parse(k->rule.unit, &u, err) != MM_OK)
        return mm_error_set(err, MM_EVALUE, "ask", "%s: %s", k->name, err->msg);
    if (!mm_dim_equal(&u, &k->dim)) {
        char d1[64], d2[64];
        mm_dim_text(&u, d1, sizeof d1);
        mm_dim_text(&k->dim, d2, sizeof d2);
        return mm_error_set(err, MM_EVALUE, "ask", "%s: unit '%s' is %s, the answer is %s", k->name,
                            k->rule.unit, d1, d2);
    }
    k->ask_factor = u.value;
    const cJSON *rel = cJSON_GetObjectItem(q, "rel"), *abs_ = cJSON_GetObjectItem(q, "abs"),
                *sig = cJSON_GetObjectItem(q, "sig");
    k->rule.rel = cJSON_IsNumber(rel) ? rel->valuedouble : 0;
    k->rule.abs = cJSON_IsNumber(abs_) ? abs_->valuedouble : 0;
    k->rule.sig = cJSON_IsNumber(sig) ? sig->valueint : 0;
    int tol = cJSON_IsNumber(rel) || cJSON_IsNumber(abs_);
    if (tol == (k->rule.sig > 0) || k->rule.rel < 0 || k->rule.abs < 0 || k->rule.rel >= 1 ||
        (cJSON_IsNumber(sig) && (k->rule.sig < 1 || k->rule.sig > 15)))
        return mm_error_set(err, MM_EVALUE, "ask", "%s: judge by \"rel\" (0 <= rel < 1) and/or \"abs\" "
                            "(>= 0, in the asked unit), or by \"sig\" (1 to 15 significant figures)", k->name);
    a->nask++;
    return MM_OK;
}

/* parse and check every parameter's text of one draw; 0 when the exercise takes it */
static int valid(const mm_assignment *a, mm_input *in, int n)
{
    mm_result arena;
    mm_result_init(&arena, 1 << 22);
    mm_value vals[MM_MAX_PARAMS];
    mm_error err;
    int rc = MM_OK;
    for (int k = 0; k < n && rc == MM_OK; k++)
        rc = mm_param_parse(&a->ex->params[k], in[k].text, in[k].text_len, &vals[k], &arena, &err);
    if (rc == MM_OK && a->ex->check)
        rc = a->ex->check(vals, &err);
    mm_result_release(&arena);
    return rc == MM_OK ? 0 : -1;
}

/* draw number `attempt` of a stream: every parameter's text and the
 * indices drawn (for telling variants apart) */
static void draw(const mm_assignment *a, uint64_t seed, long attempt, mm_input *in,
                 char (*text)[MM_ASSIGN_TEXT], double *idx)
{
    uint64_t s = seed ^ (0xD1B54A32D192ED03ULL * (uint64_t)(attempt + 1));
    int vi = 0;
    for (int k = 0; k < a->ex->n_params; k++) {
        const mm_param *p = &a->ex->params[k];
        const vary *v = vi < a->nvary && a->vary[vi].param == k ? &a->vary[vi++] : NULL;
        if (v) {
            double i = fmin(floor(uniform(&s) * v->count), v->count - 1);
            idx[v - a->vary] = i;
            member_text(a, v, i, text[k], MM_ASSIGN_TEXT);
        } else if (a->fixed[k]) {
            snprintf(text[k], MM_ASSIGN_TEXT, "%s", a->fixed[k]);
        } else if (p->kind == MM_REAL || p->kind == MM_INT) {
            mm_dtoa(p->def, text[k]);
        } else if (p->kind == MM_CHOICE) {
            snprintf(text[k], MM_ASSIGN_TEXT, "%s", p->choices[(int)p->def]);
        } else {
            snprintf(text[k], MM_ASSIGN_TEXT, "%s", p->def_text ? p->def_text : "");
        }
        in[k] = (mm_input){p->name, text[k], strlen(p->name), strlen(text[k])};
    }
}

static uint64_t seed_of(const mm_assignment *a, const char *student)
{
    uint64_t h = fnv1a(0xcbf29ce484222325ULL, "mechmat-assignment", 19);
    h = fnv1a(h, a->name, strlen(a->name) + 1);
    return fnv1a(h, student, strlen(student));
}

static int same(const double *x, const double *y, int n)
{
    for (int i = 0; i < n; i++)
        if (x[i] != y[i])
            return 0;
    return 1;
}

/* the first valid draw of the stream that no earlier roster student holds */
static int place_roster(mm_assignment *a, mm_buf *notes, mm_error *err)
{
    int nv = a->nvary > 0 ? a->nvary : 1, dup = 0;
    double *held = calloc((size_t)a->nstudents * (size_t)nv, sizeof *held);
    mm_input in[MM_MAX_PARAMS];
    char (*text)[MM_ASSIGN_TEXT] = malloc(MM_MAX_PARAMS * sizeof *text);
    if (!held || !text) {
        free(held);
        free(text);
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    }
    for (int s = 0; s < a->nstudents; s++) {
        uint64_t seed = seed_of(a, a->students[s]);
        long first_valid = -1;
        for (long t = 0; t < 1000; t++) {
            double *mine = held + (size_t)s * nv;
            draw(a, seed, t, in, text, mine);
            if (valid(a, in, a->ex->n_params) != 0)
                continue;
            if (first_valid < 0)
                first_valid = t;
            int taken = 0;
            for (int o = 0; o < s && !taken; o++)
                taken = same(mine, held + (size_t)o * nv, a->nvary);
            if (!taken) {
                a->roster_draw[s] = t;
                break;
            }
            if (t == 999 || (double)s >= mm_assign_set_size(a)) {   /* every variant is out: share */
                a->roster_draw[s] = first_valid;
                draw(a, seed, first_valid, in, text, mine);
                dup++;
                break;
            }
        }
        if (first_valid < 0) {
            free(held);
            free(text);
            return mm_error_set(err, MM_EVALUE, "params", "no draw for student %.40s passes %s's limits in "
                                "1000 tries: widen the sets", a->students[s], a->ex->id);
        }
    }
    if (dup) {
        char line[200];
        snprintf(line, sizeof line, "%s: %d of %d students share a variant with an earlier one (the set is "
                 "too small to keep them apart)\n", a->name, dup, a->nstudents);
        mm_buf_puts(notes, line);
    }
    free(held);
    free(text);
    return MM_OK;
}

const char *mm_assign_exercise_id(const cJSON *j)
{
    const cJSON *e = cJSON_GetObjectItem(j, "exercise");
    return cJSON_IsString(e) ? e->valuestring : NULL;
}

int mm_assign_load(const cJSON *j, const mm_exercise *ex, mm_assignment **out, mm_buf *notes, mm_error *err)
{
    *out = NULL;
    mm_assignment *a = calloc(1, sizeof *a);
    if (!a)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    a->ex = ex;
    a->reveal = 1;
    int rc = MM_OK;
    const cJSON *name = cJSON_GetObjectItem(j, "name"), *title = cJSON_GetObjectItem(j, "title");
    if (!cJSON_IsString(name) || !name->valuestring[0] || strlen(name->valuestring) >= sizeof a->name) {
        rc = mm_error_set(err, MM_EVALUE, "name", "an assignment needs a \"name\" of at most 63 characters");
        goto fail;
    }
    snprintf(a->name, sizeof a->name, "%s", name->valuestring);
    snprintf(a->title, sizeof a->title, "%s", cJSON_IsString(title) ? title->valuestring : ex->title);
    for (const cJSON *e = j->child; e; e = e->next) {
        static const char *const keys[] = {"name", "title", "exercise", "params", "ask", "class_size",
                                           "students", "reveal", "note", "instructor_key"};
        int known = 0;
        for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++)
            known |= strcmp(e->string, keys[k]) == 0;
        if (!known) {
            rc = mm_error_set(err, MM_EVALUE, e->string, "%s: unknown key \"%.40s\"", a->name, e->string);
            goto fail;
        }
    }
    const cJSON *params = cJSON_GetObjectItem(j, "params");
    for (int k = 0; k < ex->n_params && rc == MM_OK; k++) {      /* in parameter order: draws are stable */
        const cJSON *spec = cJSON_GetObjectItem(params, ex->params[k].name);
        if (!spec)
            continue;
        if (cJSON_IsObject(spec)) {
            rc = load_vary(a, spec, k, err);
        } else {
            char t[MM_ASSIGN_TEXT] = "";
            if (json_text(spec, t, sizeof t, 0) != 0 || !(a->fixed[k] = dupstr(t)))
                rc = mm_error_set(err, MM_EVALUE, ex->params[k].name, "%s: a fixed value must be a number, a "
                                  "text or an array", ex->params[k].name);
        }
    }
    for (const cJSON *e = params ? params->child : NULL; e && rc == MM_OK; e = e->next)
        if (find_param(ex, e->string) < 0)
            rc = mm_error_set(err, MM_EVALUE, e->string, "%s has no parameter '%.40s'", ex->id, e->string);
    if (rc != MM_OK)
        goto fail;
    const cJSON *asks = cJSON_GetObjectItem(j, "ask"), *q;
    if (!cJSON_IsArray(asks) || cJSON_GetArraySize(asks) < 1) {
        rc = mm_error_set(err, MM_EVALUE, "ask", "%s: \"ask\" must list the answers asked", a->name);
        goto fail;
    }
    cJSON_ArrayForEach(q, asks) {
        if ((rc = load_ask(a, q, err)) != MM_OK)
            goto fail;
    }
    const cJSON *cs = cJSON_GetObjectItem(j, "class_size"), *rv = cJSON_GetObjectItem(j, "reveal");
    a->class_size = cJSON_IsNumber(cs) ? cs->valueint : 0;
    if (rv)
        a->reveal = cJSON_IsTrue(rv);
    const cJSON *key = cJSON_GetObjectItem(j, "instructor_key");
    if (key && (!cJSON_IsString(key) || strlen(key->valuestring) < 8 || strlen(key->valuestring) >= sizeof a->key)) {
        rc = mm_error_set(err, MM_EVALUE, "instructor_key", "instructor_key must be a text of 8 to 127 characters");
        goto fail;
    }
    if (key)
        snprintf(a->key, sizeof a->key, "%s", key->valuestring);
    const cJSON *st = cJSON_GetObjectItem(j, "students");
    if (st) {
        int n = cJSON_GetArraySize(st);
        if (!cJSON_IsArray(st) || n > MM_ASSIGN_MAX_STUDENTS) {
            rc = mm_error_set(err, MM_EVALUE, "students", "students must list at most %d ids",
                              MM_ASSIGN_MAX_STUDENTS);
            goto fail;
        }
        a->students = calloc((size_t)n + 1, sizeof *a->students);
        a->roster_draw = calloc((size_t)n + 1, sizeof *a->roster_draw);
        if (!a->students || !a->roster_draw) {
            rc = mm_error_set(err, MM_ENOMEM, "", "out of memory");
            goto fail;
        }
        const cJSON *e;
        cJSON_ArrayForEach(e, st) {
            if (!cJSON_IsString(e) || !e->valuestring[0] || strlen(e->valuestring) > 128) {
                rc = mm_error_set(err, MM_EVALUE, "students", "a student id is a text of 1 to 128 characters");
                goto fail;
            }
            a->students[a->nstudents++] = dupstr(e->valuestring);
        }
        if (a->class_size < a->nstudents)
            a->class_size = a->nstudents;
    }
    /* the default variant must exist before anything is handed out */
    mm_input in[MM_MAX_PARAMS];
    char (*text)[MM_ASSIGN_TEXT] = malloc(MM_MAX_PARAMS * sizeof *text);
    int n;
    rc = text ? mm_assign_variant(a, "mechmat-check", in, text, &n, err) : MM_ENOMEM;
    free(text);
    if (rc != MM_OK) {
        if (rc == MM_ENOCONV)
            rc = mm_error_set(err, MM_EVALUE, "params", "%s: no draw passes %s's limits: widen the sets",
                              a->name, ex->id);
        goto fail;
    }
    if (a->nstudents && (rc = place_roster(a, notes, err)) != MM_OK)
        goto fail;
    double size = mm_assign_set_size(a);
    char line[300];
    if (a->class_size > 0 && size < a->class_size) {
        snprintf(line, sizeof line, "%s: %.0f variants for a class of %d: duplicates are unavoidable\n",
                 a->name, size, a->class_size);
        mm_buf_puts(notes, line);
    } else if (a->class_size > 1 && !a->nstudents) {
        double p = 1 - exp(-(double)a->class_size * (a->class_size - 1) / (2 * size));
        if (p > 0.01) {
            snprintf(line, sizeof line, "%s: %.3g variants for a class of %d: without a roster two students "
                     "share a variant with probability %.2g (list \"students\" to keep them apart)\n",
                     a->name, size, a->class_size, p);
            mm_buf_puts(notes, line);
        }
    }
    *out = a;
    return MM_OK;
fail:
    mm_assign_free(a);
    return rc;
}

void mm_assign_free(mm_assignment *a)
{
    if (!a)
        return;
    for (int i = 0; i < a->nvary; i++) {
        for (int k = 0; a->vary[i].texts && k < a->vary[i].count; k++)
            free(a->vary[i].texts[k]);
        free(a->vary[i].texts);
    }
    for (int k = 0; k < MM_MAX_PARAMS; k++)
        free(a->fixed[k]);
    for (int s = 0; s < a->nstudents; s++)
        free(a->students[s]);
    free(a->students);
    free(a->roster_draw);
    free(a);
}

const char *mm_assign_name(const mm_assignment *a) { return a->name; }
const char *mm_assign_title(const mm_assignment *a) { return a->title; }
const mm_exercise *mm_assign_exercise(const mm_assignment *a) { return a->ex; }

double mm_assign_set_size(const mm_assignment *a)
{
    double n = 1;
    for (int i = 0; i < a->nvary; i++)
        n *= a->vary[i].count;
    return n;
}

/* ---- variants ------------------------------------------------------------------- */

int mm_assign_variant(const mm_assignment *a, const char *student, mm_input *in,
                      char (*text)[MM_ASSIGN_TEXT], int *n, mm_error *err)
{
    if (!student || !student[0] || strlen(student) > 128)
        return mm_error_set(err, MM_EVALUE, "student", "student must be an id of 1 to 128 characters");
    uint64_t seed = seed_of(a, student);
    double idx[MM_MAX_PARAMS];
    *n = a->ex->n_params;
    for (int s = 0; s < a->nstudents; s++)
        if (strcmp(a->students[s], student) == 0) {
            draw(a, seed, a->roster_draw[s], in, text, idx);
            return MM_OK;
        }
    for (long t = 0; t < 1000; t++) {
        draw(a, seed, t, in, text, idx);
        if (valid(a, in, *n) == 0)
            return MM_OK;
    }
    return mm_error_set(err, MM_ENOCONV, "student", "no variant for this student passes the exercise's limits");
}

static const char *rule_text(const mm_rule *r, char *buf, size_t size)
{
    char u[40] = "";
    if (r->unit[0])
        snprintf(u, sizeof u, " %s", r->unit);
    if (r->sig)
        snprintf(buf, size, "%d significant figures%s%s", r->sig, r->unit[0] ? ", in" : "", u);
    else if (r->rel > 0 && r->abs > 0)
        snprintf(buf, size, "within %g %% or %g%s", 100 * r->rel, r->abs, u);
    else if (r->rel > 0)
        snprintf(buf, size, "within %g %%%s%s", 100 * r->rel, r->unit[0] ? ", in" : "", u);
    else
        snprintf(buf, size, "within %g%s", r->abs, u);
    return buf;
}

/* the variant's parameter values as the JSON of a solve answer's params */
static void write_params(mm_buf *b, const mm_assignment *a, mm_input *in)
{
    mm_buf_char(b, '{');
    for (int k = 0; k < a->ex->n_params; k++) {
        const mm_param *p = &a->ex->params[k];
        if (k)
            mm_buf_char(b, ',');
        mm_buf_key(b, p->name);
        char *end;
        double x = strtod(in[k].text, &end);
        if ((p->kind == MM_REAL || p->kind == MM_INT) && *end == '\0' && end != in[k].text)
            mm_buf_num(b, x, p->name);
        else
            mm_buf_str(b, in[k].text);
    }
    mm_buf_char(b, '}');
}

static int error_doc(mm_buf *out, int code, const char *param, const char *msg)
{
    mm_error err;
    mm_error_set(&err, code, param, "%s", msg);
    return mm_api_error(out, &err);
}

int mm_assign_variant_json(const mm_assignment *a, const char *student, mm_buf *out)
{
    mm_input in[MM_MAX_PARAMS];
    char (*text)[MM_ASSIGN_TEXT] = malloc(MM_MAX_PARAMS * sizeof *text);
    mm_error err;
    int n;
    mm_buf_reset(out);
    if (!text)
        return error_doc(out, MM_ENOMEM, "", "out of memory");
    int rc = mm_assign_variant(a, student, in, text, &n, &err);
    if (rc != MM_OK) {
        free(text);
        return mm_api_error(out, &err);
    }
    mm_buf_puts(out, "{\"assignment\":");
    mm_buf_str(out, a->name);
    mm_buf_puts(out, ",\"title\":");
    mm_buf_str(out, a->title);
    mm_buf_puts(out, ",\"student\":");
    mm_buf_str(out, student);
    mm_buf_puts(out, ",\"exercise\":");
    mm_buf_str(out, a->ex->id);
    mm_buf_puts(out, ",\"params\":");
    write_params(out, a, in);
    mm_buf_puts(out, ",\"asked\":[");
    for (int i = 0; i < a->nask; i++) {
        char r[120];
        if (i)
            mm_buf_char(out, ',');
        mm_buf_puts(out, "{\"name\":");
        mm_buf_str(out, a->ask[i].name);
        mm_buf_puts(out, ",\"label\":");
        mm_buf_str(out, a->ask[i].label);
        mm_buf_puts(out, ",\"unit\":");
        mm_buf_str(out, a->ask[i].rule.unit);
        mm_buf_puts(out, ",\"rule\":");
        mm_buf_str(out, rule_text(&a->ask[i].rule, r, sizeof r));
        mm_buf_char(out, '}');
    }
    mm_buf_puts(out, "]}");
    free(text);
    return 200;
}

/* ---- judging ----------------------------------------------------------------------- */

/* x given by its shortest decimal text shifted by shift decades, rounded
 * to n significant figures half away from zero: sign, n digits, exponent
 * of the first digit.  0 gives sign 0. */
typedef struct rounded { int sign, exp10; char digits[20]; } rounded;

static rounded round_sig(double x, int shift, int n)
{
    rounded r = {0, 0, ""};
    if (x == 0)
        return r;
    char s[MM_DTOA_BUFSIZE], d[48];
    mm_dtoa(fabs(x), s);
    int nd = 0, before = -1, e = 0;            /* digits, digits before the point, exponent */
    for (const char *p = s; *p; p++) {
        if (*p >= '0' && *p <= '9' && nd < 40)
            d[nd++] = *p;
        else if (*p == '.')
            before = nd;
        else if (*p == 'e' || *p == 'E') {
            e = atoi(p + 1);
            break;
        }
    }
    if (before < 0)
        before = nd;
    int lead = before - 1 + e + shift, skip = 0;   /* the exponent of d[0] */
    while (skip < nd - 1 && d[skip] == '0')
        skip++, lead--;
    memmove(d, d + skip, (size_t)(nd - skip));
    nd -= skip;
    while (nd < n + 1)
        d[nd++] = '0';
    int carry = d[n] >= '5';                   /* half away from zero: on the magnitude */
    for (int i = n - 1; i >= 0 && carry; i--) {
        if (d[i] == '9')
            d[i] = '0';
        else
            d[i]++, carry = 0;
    }
    if (carry) {                               /* 9.99 -> 10.0 */
        memmove(d + 1, d, (size_t)n);
        d[0] = '1';
        lead++;
    }
    memcpy(r.digits, d, (size_t)n);
    r.digits[n] = '\0';
    r.sign = x < 0 ? -1 : 1;
    r.exp10 = lead;
    return r;
}

/* k when f is 10^k (to 1e-12), else INT_MIN-like sentinel */
static int decade(double f)
{
    double k = round(log10(f));
    return fabs(f / pow(10, k) - 1) < 1e-12 ? (int)k : -1000;
}

void mm_assign_judge(const mm_rule *rule, const mm_quantity *dim, double expected_si, const char *given,
                     mm_judgement *j)
{
    memset(j, 0, sizeof *j);
    mm_quantity asked, g;
    mm_error err;
    mm_unit_parse(rule->unit, &asked, &err);
    j->expected = expected_si / asked.value;
    if (mm_quantity_parse(given ? given : "", &g, &err) != MM_OK) {
        snprintf(j->error, sizeof j->error, "%s", err.msg);
        return;
    }
    int dimensionless = !memcmp(dim->dim, (signed char[MM_DIM_COUNT]){0}, sizeof dim->dim);
    if (!g.has_unit && !dimensionless) {
        snprintf(j->error, sizeof j->error, "give the unit too (the answer is in %s)", rule->unit);
        return;
    }
    if (!mm_dim_equal(&g, dim)) {
        char d1[40], d2[40];
        mm_dim_text(&g, d1, sizeof d1);
        mm_dim_text(dim, d2, sizeof d2);
        snprintf(j->error, sizeof j->error, "that unit measures %s; the answer is in %.31s (%s)", d1, rule->unit, d2);
        return;
    }
    j->given = g.value / asked.value;
    if (rule->sig) {
        /* round the digits as typed (and the exact answer) in the asked unit */
        int gs = decade(g.factor / asked.value), es = decade(1 / asked.value);
        rounded rg = gs > -1000 ? round_sig(g.number, gs, rule->sig) : round_sig(j->given, 0, rule->sig);
        rounded re = es > -1000 ? round_sig(expected_si, es, rule->sig) : round_sig(j->expected, 0, rule->sig);
        j->correct = rg.sign == re.sign && (re.sign == 0 || (rg.exp10 == re.exp10 && !strcmp(rg.digits, re.digits)));
        j->tolerance = re.sign ? 0.5 * pow(10, re.exp10 - rule->sig + 1) : 0;
        if (expected_si == 0)
            snprintf(j->note, sizeof j->note, "the answer is exactly 0, which has no significant figures: only "
                     "0 is right");
        return;
    }
    j->tolerance = fmax(rule->abs, rule->rel * fabs(j->expected));
    double slack = 1e-12 * fmax(fabs(j->expected), fabs(j->given));
    j->correct = fabs(j->given - j->expected) <= j->tolerance + slack;
    if (j->expected == 0 && rule->abs == 0)
        snprintf(j->note, sizeof j->note, "the answer is exactly 0: a relative tolerance allows only 0 itself");
}

int mm_assign_check_json(const mm_assignment *a, const char *body, size_t len, mm_buf *out)
{
    mm_buf_reset(out);
    cJSON *root = cJSON_ParseWithLength(body, len);
    const cJSON *student = cJSON_GetObjectItem(root, "student"), *answers = cJSON_GetObjectItem(root, "answers");
    if (!cJSON_IsObject(root) || !cJSON_IsString(student) || (answers && !cJSON_IsObject(answers))) {
        cJSON_Delete(root);
        return error_doc(out, MM_EJSON, "", "send {\"student\":\"id\",\"answers\":{\"name\":\"value unit\",...}}");
    }
    mm_input in[MM_MAX_PARAMS];
    char (*text)[MM_ASSIGN_TEXT] = malloc(MM_MAX_PARAMS * sizeof *text);
    mm_error err;
    int n, rc = text ? mm_assign_variant(a, student->valuestring, in, text, &n, &err) : MM_ENOMEM;
    if (rc != MM_OK) {
        free(text);
        cJSON_Delete(root);
        if (rc == MM_ENOMEM)
            return error_doc(out, MM_ENOMEM, "", "out of memory");
        return mm_api_error(out, &err);
    }
    mm_buf ans;
    mm_buf_init(&ans, MM_ANSWER_MAX);
    int status = mm_api_solve(a->ex, in, n, &ans);
    free(text);
    cJSON *doc = status == 200 ? cJSON_Parse(ans.p) : NULL;
    mm_buf_free(&ans);
    if (!doc) {
        cJSON_Delete(root);
        return error_doc(out, MM_EINTERNAL, "", "the variant could not be solved");
    }
    mm_buf_puts(out, "{\"assignment\":");
    mm_buf_str(out, a->name);
    mm_buf_puts(out, ",\"student\":");
    mm_buf_str(out, student->valuestring);
    mm_buf_puts(out, ",\"results\":[");
    int score = 0;
    for (int i = 0; i < a->nask; i++) {
        const ask *k = &a->ask[i];
        double expected = NAN;
        const cJSON *s;
        cJSON_ArrayForEach(s, cJSON_GetObjectItem(doc, "scalars")) {
            if (strcmp(cJSON_GetObjectItem(s, "name")->valuestring, k->name) == 0)
                expected = cJSON_GetObjectItem(s, "value")->valuedouble * k->out_factor;
        }
        const cJSON *given = cJSON_GetObjectItem(answers, k->name);
        char gtext[128] = "";
        if (cJSON_IsString(given))
            snprintf(gtext, sizeof gtext, "%s", given->valuestring);
        else if (cJSON_IsNumber(given))
            mm_dtoa(given->valuedouble, gtext);
        mm_judgement j;
        memset(&j, 0, sizeof j);
        if (isnan(expected))
            snprintf(j.error, sizeof j.error, "this variant has no %s (the exercise did not give it)", k->name);
        else if (!given)
            snprintf(j.error, sizeof j.error, "no answer given");
        else
            mm_assign_judge(&k->rule, &k->dim, expected, gtext, &j);
        score += j.correct;
        char r[120];
        if (i)
            mm_buf_char(out, ',');
        mm_buf_puts(out, "{\"name\":");
        mm_buf_str(out, k->name);
        mm_buf_puts(out, j.correct ? ",\"correct\":true" : ",\"correct\":false");
        mm_buf_puts(out, ",\"given\":");
        mm_buf_str(out, given ? gtext : NULL);
        if (a->reveal && !isnan(expected)) {
            mm_buf_puts(out, ",\"expected\":");
            mm_buf_num(out, j.expected, k->name);
            mm_buf_puts(out, ",\"tolerance\":");
            mm_buf_num(out, j.tolerance, k->name);
        }
        mm_buf_puts(out, ",\"unit\":");
        mm_buf_str(out, k->rule.unit);
        mm_buf_puts(out, ",\"rule\":");
        mm_buf_str(out, rule_text(&k->rule, r, sizeof r));
        if (j.error[0]) {
            mm_buf_puts(out, ",\"error\":");
            mm_buf_str(out, j.error);
        }
        if (j.note[0]) {
            mm_buf_puts(out, ",\"note\":");
            mm_buf_str(out, j.note);
        }
        mm_buf_char(out, '}');
    }
    mm_buf_puts(out, "],\"score\":");
    mm_buf_int(out, score);
    mm_buf_puts(out, ",\"max_score\":");
    mm_buf_int(out, a->nask);
    mm_buf_char(out, '}');
    cJSON_Delete(doc);
    cJSON_Delete(root);
    return out->nonfinite ? error_doc(out, MM_ENONFINITE, "", "the expected answer is not finite") : 200;
}

const char *mm_assign_key(const mm_assignment *a) { return a->key[0] ? a->key : NULL; }

/* the variant solved: its inputs and the parsed answer (NULL on failure) */
static cJSON *solve_variant(const mm_assignment *a, const char *student, mm_input *in,
                            char (*text)[MM_ASSIGN_TEXT], int *n, mm_error *err)
{
    if (mm_assign_variant(a, student, in, text, n, err) != MM_OK)
        return NULL;
    mm_buf ans;
    mm_buf_init(&ans, MM_ANSWER_MAX);
    int status = mm_api_solve(a->ex, in, *n, &ans);
    cJSON *doc = status == 200 ? cJSON_Parse(ans.p) : NULL;
    if (!doc)
        mm_error_set(err, MM_EINTERNAL, "", "the variant could not be solved");
    mm_buf_free(&ans);
    return doc;
}

static double expected_of(const ask *k, const cJSON *doc)
{
    const cJSON *s;
    cJSON_ArrayForEach(s, cJSON_GetObjectItem(doc, "scalars")) {
        if (strcmp(cJSON_GetObjectItem(s, "name")->valuestring, k->name) == 0)
            return cJSON_GetObjectItem(s, "value")->valuedouble * k->out_factor / k->ask_factor;
    }
    return NAN;
}

static void csv_field(mm_buf *b, const char *s)
{
    int quote = strpbrk(s, ",\"\n\r") != NULL;
    if (quote)
        mm_buf_char(b, '"');
    for (; *s; s++) {
        if (*s == '"')
            mm_buf_char(b, '"');
        mm_buf_char(b, *s);
    }
    if (quote)
        mm_buf_char(b, '"');
}

int mm_assign_csv(const mm_assignment *a, const char *list, size_t len, mm_buf *out)
{
    mm_buf_reset(out);
    mm_buf_puts(out, "student");
    for (int k = 0; k < a->ex->n_params; k++) {
        mm_buf_char(out, ',');
        csv_field(out, a->ex->params[k].name);
    }
    for (int i = 0; i < a->nask; i++) {
        char h[128];
        snprintf(h, sizeof h, "%s%s%s%s", a->ask[i].name, a->ask[i].rule.unit[0] ? " [" : "",
                 a->ask[i].rule.unit, a->ask[i].rule.unit[0] ? "]" : "");
        mm_buf_char(out, ',');
        csv_field(out, h);
    }
    mm_buf_puts(out, "\r\n");
    mm_input in[MM_MAX_PARAMS];
    char (*text)[MM_ASSIGN_TEXT] = malloc(MM_MAX_PARAMS * sizeof *text);
    if (!text)
        return error_doc(out, MM_ENOMEM, "", "out of memory");
    int lines = 0, status = 200;
    for (size_t at = 0; at < len && status == 200;) {
        size_t end = at;
        while (end < len && list[end] != '\n')
            end++;
        char id[160];
        size_t idl = 0, k = at;
        int quoted = k < end && list[k] == '"';
        for (k += (size_t)quoted; k < end && idl + 1 < sizeof id; k++) {
            if (quoted ? list[k] == '"' : (list[k] == ',' || list[k] == ';' || list[k] == '\r'))
                break;
            id[idl++] = list[k];
        }
        while (idl && (id[idl - 1] == ' ' || id[idl - 1] == '\t'))
            idl--;
        id[idl] = '\0';
        at = end + 1;
        if (!idl || (lines == 0 && (strcmp(id, "id") == 0 || strcmp(id, "student") == 0)))
            continue;                                   /* blank lines, a header */
        if (++lines > MM_ASSIGN_MAX_STUDENTS) {
            status = error_doc(out, MM_ETOOBIG, "", "at most 5000 students in one list");
            break;
        }
        int n;
        mm_error err;
        cJSON *doc = solve_variant(a, id, in, text, &n, &err);
        if (!doc) {
            status = mm_api_error(out, &err);
            break;
        }
        csv_field(out, id);
        for (int p = 0; p < n; p++) {
            mm_buf_char(out, ',');
            csv_field(out, text[p]);
        }
        for (int i = 0; i < a->nask; i++) {
            char v[40] = "";
            double x = expected_of(&a->ask[i], doc);
            if (isfinite(x))
                snprintf(v, sizeof v, "%.17g", x);
            mm_buf_char(out, ',');
            mm_buf_puts(out, v);
        }
        mm_buf_puts(out, "\r\n");
        cJSON_Delete(doc);
    }
    free(text);
    if (status == 200 && lines == 0)
        status = error_doc(out, MM_EVALUE, "", "the class list has no student ids (one per line, first column)");
    return out->failed ? error_doc(out, MM_ETOOBIG, "", "the table is too large") : status;
}

int mm_assign_key_json(const mm_assignment *a, const char *student, mm_buf *out)
{
    mm_buf variant;
    mm_buf_init(&variant, 1 << 20);
    int status = mm_assign_variant_json(a, student, &variant);
    if (status != 200) {
        mm_buf_reset(out);
        mm_buf_put(out, variant.p, variant.len);
        mm_buf_free(&variant);
        return status;
    }
    mm_input in[MM_MAX_PARAMS];
    char (*text)[MM_ASSIGN_TEXT] = malloc(MM_MAX_PARAMS * sizeof *text);
    int n;
    mm_error err;
    cJSON *doc = text ? solve_variant(a, student, in, text, &n, &err) : NULL;
    free(text);
    mm_buf_reset(out);
    if (!doc) {
        mm_buf_free(&variant);
        return error_doc(out, MM_EINTERNAL, "", "the variant could not be solved");
    }
    mm_buf_puts(out, "{\"variant\":");
    mm_buf_put(out, variant.p, variant.len);
    mm_buf_puts(out, ",\"expected\":[");
    for (int i = 0; i < a->nask; i++) {
        if (i)
            mm_buf_char(out, ',');
        mm_buf_puts(out, "{\"name\":");
        mm_buf_str(out, a->ask[i].name);
        double x = expected_of(&a->ask[i], doc);
        mm_buf_puts(out, ",\"value\":");
        if (isfinite(x))
            mm_buf_num(out, x, a->ask[i].name);
        else
            mm_buf_puts(out, "null");
        mm_buf_puts(out, ",\"unit\":");
        mm_buf_str(out, a->ask[i].rule.unit);
        mm_buf_char(out, '}');
    }
    mm_buf_puts(out, "],\"answer\":");
    char *ans = cJSON_PrintUnformatted(doc);
    mm_buf_puts(out, ans ? ans : "null");
    free(ans);
    mm_buf_char(out, '}');
    cJSON_Delete(doc);
    mm_buf_free(&variant);
    return 200;
}
