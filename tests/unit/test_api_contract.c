/* test_api_contract.c — the canonical exercises of API.md ("Canonical
 * exercises" and "Conventions of the canonical exercises"), as tests outside
 * the project call them: the exact ids and parameter names, the defaults in
 * brackets, the scalars and tables named there, and the values the stated
 * definitions give.  Every reference value is computed here from the
 * definition in API.md (closed forms, brute-force sums and scans written in
 * this file), never taken from the exercise's code.
 *
 * An exercise of API.md's table that is not registered yet (chapters 2-4,
 * vib-2dof, ...) is skipped and listed by the first test.
 * Runs through the real pipeline (mm_api_solve: text -> validation ->
 * solve -> JSON), read back by cJSON. */
#include "mm_test.h"

#include <cJSON.h>
#include <complex.h>
#include <ctype.h>
#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "mm_api.h"
#include "mm_json.h"
#include "mm_params.h"
#include "mm_result_impl.h"

#define EPS DBL_EPSILON

/* ---- the canonical ids (API.md, "Canonical exercises") ------------------------ */

static const char *const canonical_ids[] = {
    "num-linear-system", "num-poly-roots", "num-polyfit", "num-nonlinear-roots", "num-eigen",
    "vib-sdof-free", "vib-sdof-forced", "vib-base-excitation", "vib-coulomb", "vib-2dof",
    "vib-absorber", "vib-chain-modes", "vib-bar-modes", "vib-beam-modes", "vib-fourier-series",
    "vib-dft", "sta-truss", "sta-belt-friction", "kin-slider-crank", "kin-four-bar",
    "dyn-robot-2link", "dyn-slider-crank",
};

/* The exercise, or skip the calling test when it is not built yet. */
static const mm_exercise *need(const char *id)
{
    const mm_exercise *ex = mm_exercise_find(id);
    if (!ex) {
        print_message("%s is not registered yet: skipped\n", id);
        skip();
    }
    return ex;
}

/* ---- running a request ---------------------------------------------------------- */

typedef struct answer {
    int status;
    cJSON *doc;
    char *text;          /* the JSON as written */
} answer;

/* Every answer made is kept here and freed after the last test (also when a
 * test stops early on a failed assertion), so valgrind sees no leak. */
static cJSON *made_docs[4096];
static char *made_texts[4096];
static int n_made;

static void track(const answer *a)
{
    if (n_made < 4096) {
        made_docs[n_made] = a->doc;
        made_texts[n_made] = a->text;
        n_made++;
    }
}

static int release_answers(void **state)
{
    (void)state;
    for (int i = 0; i < n_made; i++) {
        cJSON_Delete(made_docs[i]);
        free(made_texts[i]);
    }
    n_made = 0;
    return 0;
}

static answer solve_v(const char *id, va_list ap)
{
    const mm_exercise *ex = need(id);
    mm_input in[MM_MAX_PARAMS];
    int n = 0;
    for (const char *name; (name = va_arg(ap, const char *)) != NULL && n < MM_MAX_PARAMS; n++) {
        const char *text = va_arg(ap, const char *);
        in[n] = (mm_input){name, text, strlen(name), strlen(text)};
    }
    mm_buf out;
    mm_buf_init(&out, MM_ANSWER_MAX);
    answer a;
    a.status = mm_api_solve(ex, in, n, &out);
    a.doc = cJSON_Parse(out.p);
    if (!a.doc)
        fail_msg("%s: the answer is not JSON: %.200s", id, out.p ? out.p : "(null)");
    a.text = mm_buf_take(&out, NULL);
    mm_buf_free(&out);
    track(&a);
    return a;
}

/* Solve id with "name", "value", ..., NULL; insists on 200 with every check
 * passed (a contract value from a failing solve would prove nothing). */
static answer solve(const char *id, ...)
{
    va_list ap;
    va_start(ap, id);
    answer a = solve_v(id, ap);
    va_end(ap);
    if (a.status != 200) {
        char *s = cJSON_PrintUnformatted(a.doc);
        fail_msg("%s: status %d: %.400s", id, a.status, s);
    }
    const cJSON *c;
    cJSON_ArrayForEach(c, cJSON_GetObjectItem(a.doc, "checks")) {
        if (!cJSON_IsTrue(cJSON_GetObjectItem(c, "passed"))) {
            char *s = cJSON_PrintUnformatted(c);
            fail_msg("%s: check failed: %s", id, s);
        }
    }
    return a;
}

/* Solve without insisting on 200 (for the error answers). */
static answer solve_any(const char *id, ...)
{
    va_list ap;
    va_start(ap, id);
    answer a = solve_v(id, ap);
    va_end(ap);
    return a;
}

static void done(answer *a)
{
    for (int i = 0; i < n_made; i++)          /* freed here: not again at the end */
        if (made_docs[i] == a->doc && made_texts[i] == a->text)
            made_docs[i] = NULL, made_texts[i] = NULL;
    cJSON_Delete(a->doc);
    free(a->text);
    a->doc = NULL;
    a->text = NULL;
}

static const cJSON *named(const cJSON *doc, const char *list, const char *name)
{
    const cJSON *e;
    cJSON_ArrayForEach(e, cJSON_GetObjectItem(doc, list)) {
        const cJSON *n = cJSON_GetObjectItem(e, "name");
        if (cJSON_IsString(n) && strcmp(n->valuestring, name) == 0)
            return e;
    }
    return NULL;
}

static double scalar(const answer *a, const char *name)
{
    const cJSON *s = named(a->doc, "scalars", name);
    if (!s)
        fail_msg("no scalar %s", name);
    const cJSON *v = cJSON_GetObjectItem(s, "value");
    if (!cJSON_IsNumber(v))
        fail_msg("scalar %s has no number", name);
    return v->valuedouble;
}

static const cJSON *table(const answer *a, const char *name)
{
    const cJSON *t = named(a->doc, "tables", name);
    if (!t)
        fail_msg("no table %s", name);
    return t;
}

/* Index of column col of table name. */
static int column(const answer *a, const char *name, const char *col)
{
    const cJSON *c;
    int i = 0;
    cJSON_ArrayForEach(c, cJSON_GetObjectItem(table(a, name), "columns")) {
        if (cJSON_IsString(c) && strcmp(c->valuestring, col) == 0)
            return i;
        i++;
    }
    fail_msg("table %s has no column %s", name, col);
    return -1;
}

/* The unit of column col of table name. */
static const char *column_unit(const answer *a, const char *name, const char *col)
{
    const cJSON *u = cJSON_GetArrayItem(cJSON_GetObjectItem(table(a, name), "units"), column(a, name, col));
    if (!cJSON_IsString(u))
        fail_msg("table %s: column %s has no unit", name, col);
    return u->valuestring;
}

static int nrows(const answer *a, const char *name)
{
    return cJSON_GetArraySize(cJSON_GetObjectItem(table(a, name), "rows"));
}

/* The number in table name, row, column col. */
static double cell(const answer *a, const char *name, int row, const char *col)
{
    int j = column(a, name, col);
    const cJSON *r = cJSON_GetArrayItem(cJSON_GetObjectItem(table(a, name), "rows"), row);
    const cJSON *c = cJSON_GetArrayItem(r, j);
    if (!cJSON_IsNumber(c))
        fail_msg("table %s: row %d, column %s is not a number", name, row, col);
    return c->valuedouble;
}

/* Series name: its points into x, y (at most cap); returns their number. */
static int series(const answer *a, const char *name, double *x, double *y, int cap)
{
    const cJSON *s = named(a->doc, "series", name);
    if (!s)
        fail_msg("no series %s", name);
    const cJSON *xs = cJSON_GetObjectItem(s, "x"), *ys = cJSON_GetObjectItem(s, "y");
    int n = cJSON_GetArraySize(xs);
    assert_int_equal(cJSON_GetArraySize(ys), n);
    assert_true(n <= cap);
    for (int i = 0; i < n; i++) {
        x[i] = cJSON_GetArrayItem(xs, i)->valuedouble;
        y[i] = cJSON_GetArrayItem(ys, i)->valuedouble;
    }
    return n;
}

static int cmp_double(const void *p, const void *q)
{
    double a = *(const double *)p, b = *(const double *)q;
    return (a > b) - (a < b);
}

/* ==== ids ========================================================================= */

static void every_canonical_id_should_be_registered_or_listed_as_not_built_yet(void **state)
{
    (void)state;
    int built = 0;
    for (int i = 0; i < MM_COUNT(canonical_ids); i++) {
        if (mm_exercise_find(canonical_ids[i]))
            built++;
        else
            print_message("not built yet (its contract tests are skipped): %s\n", canonical_ids[i]);
    }
    print_message("%d of %d canonical exercises are registered\n", built, MM_COUNT(canonical_ids));
    assert_true(built > 0);
    /* every registered id follows <chapter>-<topic> with the chapter's prefix */
    static const char *const prefix[6] = {"", "num-", "kin-", "sta-", "dyn-", "vib-"};
    for (int i = 0; i < mm_exercise_count; i++) {
        const mm_exercise *ex = mm_exercises[i];
        assert_true(ex->chapter >= 1 && ex->chapter <= 5);
        if (strncmp(ex->id, prefix[ex->chapter], strlen(prefix[ex->chapter])) != 0)
            fail_msg("%s (chapter %d) should start with %s", ex->id, ex->chapter, prefix[ex->chapter]);
        for (const char *c = ex->id; *c; c++)
            if (!(islower((unsigned char)*c) || isdigit((unsigned char)*c) || *c == '-'))
                fail_msg("%s: an id is lower case words joined by '-'", ex->id);
    }
}

/* ==== parameters: names, kinds, defaults ========================================== */

typedef struct pspec {
    const char *id, *name, *kind;
    double def;           /* real, integer */
    const char *text;     /* vector, matrix, expression, choice: the default as API.md writes it;
                             choice: "default|choice|choice..." */
    const char *unit;     /* the SI unit API.md writes beside it, or NULL */
} pspec;

static const pspec params_spec[] = {
    {"num-linear-system", "A", "matrix", 0, "1,2,3;4,5,6;7,8,10", NULL},
    {"num-linear-system", "b", "vector", 0, "10,0,1000", NULL},
    {"num-poly-roots", "p", "vector", 0, "1,2,3,4", NULL},
    {"num-polyfit", "x", "vector", 0, "1,3,10", NULL},
    {"num-polyfit", "y", "vector", 0, "10,18,37", NULL},
    {"num-polyfit", "degree", "integer", 1, NULL, NULL},
    {"num-nonlinear-roots", "f", "expression", 0, "x^3+sin(x)-2", NULL},
    {"num-nonlinear-roots", "a", "real", -1, NULL, NULL},
    {"num-nonlinear-roots", "b", "real", 10, NULL, NULL},
    {"num-nonlinear-roots", "n", "integer", 100, NULL, NULL},
    {"num-nonlinear-roots", "tol", "real", 1e-6, NULL, NULL},
    {"num-eigen", "K", "matrix", 0, "200,-100,0;-100,200,-100;0,-100,100", NULL},
    {"num-eigen", "M", "matrix", 0, "1,0,0;0,1,0;0,0,1", NULL},
    {"vib-sdof-free", "m", "real", 1, NULL, "kg"},
    {"vib-sdof-free", "k", "real", 100, NULL, "N/m"},
    {"vib-sdof-free", "c", "real", 2, NULL, NULL},
    {"vib-sdof-free", "x0", "real", 0.01, NULL, "m"},
    {"vib-sdof-free", "v0", "real", 0, NULL, "m/s"},
    {"vib-sdof-free", "t_end", "real", 5, NULL, "s"},
    {"vib-sdof-forced", "m", "real", 1, NULL, "kg"},
    {"vib-sdof-forced", "k", "real", 100, NULL, "N/m"},
    {"vib-sdof-forced", "c", "real", 2, NULL, NULL},
    {"vib-sdof-forced", "F0", "real", 1, NULL, "N"},
    {"vib-sdof-forced", "omega", "real", 8, NULL, "rad/s"},
    {"vib-sdof-forced", "x0", "real", 0, NULL, NULL},
    {"vib-sdof-forced", "v0", "real", 0, NULL, NULL},
    {"vib-sdof-forced", "t_end", "real", 10, NULL, NULL},
    {"vib-base-excitation", "m", "real", 1, NULL, NULL},
    {"vib-base-excitation", "k", "real", 100, NULL, NULL},
    {"vib-base-excitation", "c", "real", 2, NULL, NULL},
    {"vib-base-excitation", "Y", "real", 0.01, NULL, "m"},
    {"vib-base-excitation", "omega", "real", 8, NULL, "rad/s"},
    {"vib-coulomb", "m", "real", 1, NULL, "kg"},
    {"vib-coulomb", "k", "real", 100, NULL, "N/m"},
    {"vib-coulomb", "mu", "real", 0.1, NULL, NULL},
    {"vib-coulomb", "g", "real", 9.81, NULL, NULL},
    {"vib-coulomb", "x0", "real", 0.1, NULL, "m"},
    {"vib-coulomb", "v0", "real", 0, NULL, "m/s"},
    {"vib-2dof", "m1", "real", 1, NULL, NULL},
    {"vib-2dof", "m2", "real", 1, NULL, NULL},
    {"vib-2dof", "k1", "real", 100, NULL, NULL},
    {"vib-2dof", "k2", "real", 100, NULL, NULL},
    {"vib-2dof", "k3", "real", 0, NULL, NULL},
    {"vib-absorber", "m1", "real", 1, NULL, NULL},
    {"vib-absorber", "k1", "real", 100, NULL, NULL},
    {"vib-absorber", "m2", "real", 0.1, NULL, NULL},
    {"vib-absorber", "k2", "real", 10, NULL, NULL},
    {"vib-absorber", "F0", "real", 1, NULL, NULL},
    {"vib-chain-modes", "n", "integer", 10, NULL, NULL},
    {"vib-chain-modes", "m", "real", 1, NULL, NULL},
    {"vib-chain-modes", "k", "real", 100, NULL, NULL},
    {"vib-chain-modes", "ends", "choice", 0, "fixed-fixed|fixed-fixed|fixed-free", NULL},
    {"vib-bar-modes", "E", "real", 2.1e11, NULL, "Pa"},
    {"vib-bar-modes", "rho", "real", 7850, NULL, NULL},
    {"vib-bar-modes", "A", "real", 1e-4, NULL, NULL},
    {"vib-bar-modes", "L", "real", 1, NULL, "m"},
    {"vib-bar-modes", "elements", "integer", 20, NULL, NULL},
    {"vib-bar-modes", "bc", "choice", 0, "fixed-free|fixed-free|fixed-fixed|free-free", NULL},
    {"vib-bar-modes", "mass", "choice", 0, "consistent|consistent|lumped", NULL},
    {"vib-bar-modes", "modes", "integer", 5, NULL, NULL},
    {"vib-beam-modes", "E", "real", 2.1e11, NULL, NULL},
    {"vib-beam-modes", "I", "real", 1e-8, NULL, NULL},
    {"vib-beam-modes", "rho", "real", 7850, NULL, NULL},
    {"vib-beam-modes", "A", "real", 1e-4, NULL, NULL},
    {"vib-beam-modes", "L", "real", 1, NULL, NULL},
    {"vib-beam-modes", "elements", "integer", 20, NULL, NULL},
    {"vib-beam-modes", "bc", "choice", 0, "cantilever|cantilever|simply-supported|clamped-clamped|free-free", NULL},
    {"vib-beam-modes", "modes", "integer", 5, NULL, NULL},
    {"vib-fourier-series", "wave", "choice", 0, "square|square|sawtooth|triangle", NULL},
    {"vib-fourier-series", "terms", "integer", 25, NULL, NULL},
    {"vib-fourier-series", "T", "real", 1, NULL, "s"},
    {"vib-fourier-series", "A", "real", 1, NULL, NULL},
    {"vib-dft", "signal", "expression", 0, "sin(2*pi*5*t)+0.5*sin(2*pi*12*t)", NULL},
    {"vib-dft", "fs", "real", 100, NULL, "Hz"},
    {"vib-dft", "N", "integer", 256, NULL, NULL},
    {"vib-dft", "window", "choice", 0, "rect|rect|hann", NULL},
    {"sta-belt-friction", "T1", "real", 100, NULL, NULL},
    {"sta-belt-friction", "mu", "real", 0.3, NULL, NULL},
    {"sta-belt-friction", "theta", "real", M_PI, NULL, "rad"},
    {"kin-slider-crank", "r", "real", 0.1, NULL, NULL},
    {"kin-slider-crank", "l", "real", 0.4, NULL, NULL},
    {"kin-slider-crank", "e", "real", 0, NULL, NULL},
    {"kin-slider-crank", "omega", "real", 100, NULL, NULL},
    {"kin-slider-crank", "phi", "real", 0.5, NULL, NULL},
    {"kin-four-bar", "a", "real", 0.2, NULL, NULL},
    {"kin-four-bar", "b", "real", 0.5, NULL, NULL},
    {"kin-four-bar", "c", "real", 0.4, NULL, NULL},
    {"kin-four-bar", "d", "real", 0.6, NULL, NULL},
    {"kin-four-bar", "omega2", "real", 10, NULL, NULL},
    {"kin-four-bar", "theta2", "real", 1, NULL, NULL},
    {"kin-four-bar", "branch", "choice", 0, "open|open|crossed", NULL},
    {"dyn-robot-2link", "l1", "real", 1, NULL, NULL},
    {"dyn-robot-2link", "l2", "real", 1, NULL, NULL},
    {"dyn-robot-2link", "m1", "real", 1, NULL, NULL},
    {"dyn-robot-2link", "m2", "real", 1, NULL, NULL},
    {"dyn-robot-2link", "g", "real", 9.81, NULL, NULL},
    {"dyn-robot-2link", "trajectory", "choice", 0, "quintic|quintic", NULL},
    {"dyn-robot-2link", "q1_0", "real", 0, NULL, NULL},
    {"dyn-robot-2link", "q2_0", "real", 0, NULL, NULL},
    {"dyn-robot-2link", "q1_1", "real", M_PI / 2, NULL, NULL},
    {"dyn-robot-2link", "q2_1", "real", M_PI / 2, NULL, NULL},
    {"dyn-robot-2link", "T", "real", 2, NULL, "s"},
    {"dyn-slider-crank", "r", "real", 0.1, NULL, NULL},
    {"dyn-slider-crank", "l", "real", 0.4, NULL, NULL},
    {"dyn-slider-crank", "J_crank", "real", 0.05, NULL, NULL},
    {"dyn-slider-crank", "m_rod", "real", 1, NULL, NULL},
    {"dyn-slider-crank", "J_rod", "real", 0.015, NULL, NULL},
    {"dyn-slider-crank", "m_piston", "real", 1, NULL, NULL},
    {"dyn-slider-crank", "torque", "real", 0, NULL, NULL},
    {"dyn-slider-crank", "omega0", "real", 100, NULL, "rad/s"},
    {"dyn-slider-crank", "t_end", "real", 0.5, NULL, "s"},
};

/* s without white space, into out. */
static void squeeze(const char *s, char *out, size_t size)
{
    size_t n = 0;
    for (; *s && n + 1 < size; s++)
        if (!isspace((unsigned char)*s))
            out[n++] = *s;
    out[n] = '\0';
}

static const mm_param *param_of(const mm_exercise *ex, const char *name)
{
    for (int k = 0; k < ex->n_params; k++)
        if (strcmp(ex->params[k].name, name) == 0)
            return &ex->params[k];
    return NULL;
}

static void parameters_should_have_the_api_names_kinds_and_defaults(void **state)
{
    (void)state;
    mm_error err;
    mm_api *api = mm_api_alloc(".", &err);
    if (!api)
        fail_msg("mm_api_alloc: %s", err.msg);
    int checked = 0;
    for (int i = 0; i < MM_COUNT(params_spec); i++) {
        const pspec *s = &params_spec[i];
        const mm_exercise *ex = mm_exercise_find(s->id);
        if (!ex)
            continue;                                   /* listed by the test above */
        checked++;
        /* in the exercise's table */
        const mm_param *p = param_of(ex, s->name);
        if (!p)
            fail_msg("%s has no parameter %s", s->id, s->name);
        if (strcmp(mm_param_kind_name(p->kind), s->kind) != 0)
            fail_msg("%s: %s is %s, API.md says %s", s->id, s->name, mm_param_kind_name(p->kind), s->kind);
        if (s->unit && strcmp(p->unit ? p->unit : "", s->unit) != 0)
            fail_msg("%s: %s has unit '%s', API.md says %s", s->id, s->name, p->unit ? p->unit : "", s->unit);
        mm_result arena;
        mm_result_init(&arena, 1 << 20);
        mm_value v;
        assert_int_equal(mm_param_default(p, &v, &arena, &err), MM_OK);
        if (p->kind == MM_REAL || p->kind == MM_INT) {
            if (v.x != s->def)
                fail_msg("%s: %s defaults to %.17g, API.md says %.17g", s->id, s->name, v.x, s->def);
        } else if (p->kind == MM_VECTOR || p->kind == MM_MATRIX) {
            mm_value w;                                 /* API.md's text, parsed the same way */
            if (mm_param_parse(p, s->text, strlen(s->text), &w, &arena, &err) != MM_OK)
                fail_msg("%s: API.md's default of %s does not parse: %s", s->id, s->name, err.msg);
            if (v.rows != w.rows || v.cols != w.cols)
                fail_msg("%s: %s defaults to %d x %d values, API.md to %d x %d", s->id, s->name, v.rows,
                         v.cols, w.rows, w.cols);
            for (int k = 0; k < v.rows * v.cols; k++)
                if (v.data[k] != w.data[k])
                    fail_msg("%s: %s default element %d is %.17g, API.md says %.17g", s->id, s->name, k,
                             v.data[k], w.data[k]);
        } else if (p->kind == MM_EXPR) {
            char a[512], b[512];
            squeeze(p->def_text, a, sizeof a);
            squeeze(s->text, b, sizeof b);
            if (strcmp(a, b) != 0)
                fail_msg("%s: %s defaults to '%s', API.md says '%s'", s->id, s->name, p->def_text, s->text);
        } else {                                        /* choice: default|choices... */
            char want[256];
            snprintf(want, sizeof want, "%s", s->text);
            char *save = NULL, *tok = strtok_r(want, "|", &save);
            if (strcmp(p->choices[(int)p->def], tok) != 0)
                fail_msg("%s: %s defaults to %s, API.md says %s", s->id, s->name, p->choices[(int)p->def], tok);
            int k = 0;
            while ((tok = strtok_r(NULL, "|", &save)) != NULL) {
                if (!p->choices[k] || strcmp(p->choices[k], tok) != 0)
                    fail_msg("%s: choice %d of %s is %s, API.md says %s", s->id, k + 1, s->name,
                             p->choices[k] ? p->choices[k] : "(none)", tok);
                k++;
            }
        }
        mm_result_release(&arena);

        /* and in the metadata document GET /api/exercises/{id} */
        size_t len;
        cJSON *meta = cJSON_Parse(mm_api_meta(api, s->id, &len));
        assert_non_null(meta);
        const cJSON *mp = named(meta, "params", s->name);
        if (!mp)
            fail_msg("%s: the metadata lists no parameter %s", s->id, s->name);
        assert_string_equal(cJSON_GetObjectItem(mp, "kind")->valuestring, s->kind);
        const cJSON *d = cJSON_GetObjectItem(mp, "default");
        if (!strcmp(s->kind, "real") || !strcmp(s->kind, "integer")) {
            if (!cJSON_IsNumber(d) || d->valuedouble != s->def)
                fail_msg("%s: metadata default of %s is not %.17g", s->id, s->name, s->def);
        } else {
            assert_true(cJSON_IsString(d));
            char a[512], b[512];
            squeeze(d->valuestring, a, sizeof a);
            squeeze(s->text, b, sizeof b);
            char *bar = strchr(b, '|');                 /* a choice: its default name */
            if (bar)
                *bar = '\0';
            if (strcmp(a, b) != 0)
                fail_msg("%s: metadata default of %s is '%s', API.md says '%s'", s->id, s->name,
                         d->valuestring, b);
        }
        cJSON_Delete(meta);
    }
    print_message("%d parameters of API.md checked\n", checked);
    mm_api_free(api);
}

/* ==== outputs at the defaults: names, columns, units ============================== */

typedef struct ospec {
    const char *id;
    char kind;            /* 's' scalar, 't' table, 'r' series */
    const char *name;
    const char *cols;     /* table: "a,b,c" in API.md's order */
    const char *unit;     /* scalar/series unit to insist on (SI), or NULL */
} ospec;

static const ospec outputs_spec[] = {
    {"num-linear-system", 's', "x1", NULL, NULL},
    {"num-linear-system", 's', "x2", NULL, NULL},
    {"num-linear-system", 's', "x3", NULL, NULL},
    {"num-linear-system", 's', "cond", NULL, ""},
    {"num-linear-system", 's', "residual", NULL, NULL},
    {"num-poly-roots", 't', "roots", "re,im", NULL},
    {"num-polyfit", 's', "c0", NULL, NULL},
    {"num-polyfit", 's', "c1", NULL, NULL},
    {"num-polyfit", 's', "rms_residual", NULL, NULL},
    {"num-nonlinear-roots", 't', "roots", "x", NULL},
    {"num-eigen", 't', "eigen", "lambda,omega", NULL},
    {"vib-sdof-free", 's', "omega_n", NULL, "rad/s"},
    {"vib-sdof-free", 's', "zeta", NULL, ""},
    {"vib-sdof-free", 's', "omega_d", NULL, "rad/s"},
    {"vib-sdof-free", 's', "regime", NULL, ""},
    {"vib-sdof-forced", 's', "omega_n", NULL, "rad/s"},
    {"vib-sdof-forced", 's', "zeta", NULL, ""},
    {"vib-sdof-forced", 's', "X", NULL, "m"},
    {"vib-sdof-forced", 's', "phase", NULL, "rad"},
    {"vib-sdof-forced", 's', "magnification", NULL, ""},
    {"vib-base-excitation", 's', "transmissibility", NULL, ""},
    {"vib-base-excitation", 's', "X", NULL, "m"},
    {"vib-coulomb", 's', "decay_per_cycle", NULL, "m"},
    {"vib-coulomb", 's', "stop_time", NULL, "s"},
    {"vib-coulomb", 's', "x_final", NULL, "m"},
    {"vib-2dof", 's', "omega1", NULL, "rad/s"},
    {"vib-2dof", 's', "omega2", NULL, "rad/s"},
    {"vib-2dof", 't', "modes", "mode,omega,phi1,phi2", NULL},
    {"vib-absorber", 's', "omega1", NULL, "rad/s"},
    {"vib-absorber", 's', "omega2", NULL, "rad/s"},
    {"vib-absorber", 's', "tuned_omega", NULL, "rad/s"},
    {"vib-absorber", 'r', "X1", NULL, NULL},
    {"vib-absorber", 'r', "X2", NULL, NULL},
    {"vib-chain-modes", 't', "modes", "omega", NULL},
    {"vib-chain-modes", 's', "max_rel_error", NULL, NULL},
    {"vib-bar-modes", 't', "modes", "omega,omega_exact,rel_error", NULL},
    {"vib-bar-modes", 's', "rigid_modes", NULL, NULL},
    {"vib-beam-modes", 't', "modes", "omega,omega_exact,rel_error", NULL},
    {"vib-beam-modes", 's', "rigid_modes", NULL, NULL},
    {"vib-fourier-series", 't', "coefficients", "k,a_k,b_k", NULL},
    {"vib-fourier-series", 's', "overshoot", NULL, NULL},
    {"vib-dft", 'r', "amplitude", NULL, NULL},
    {"vib-dft", 't', "peaks", "f,amplitude", NULL},
    {"sta-truss", 't', "members", "member,force", NULL},
    {"sta-truss", 't', "reactions", "node,Rx,Ry", NULL},
    {"sta-truss", 's', "determinacy", NULL, NULL},
    {"sta-belt-friction", 's', "T2", NULL, "N"},
    {"kin-slider-crank", 's', "x", NULL, "m"},
    {"kin-slider-crank", 's', "v", NULL, "m/s"},
    {"kin-slider-crank", 's', "a", NULL, "m/s^2"},
    {"kin-four-bar", 's', "theta3", NULL, "rad"},
    {"kin-four-bar", 's', "theta4", NULL, "rad"},
    {"kin-four-bar", 's', "omega3", NULL, "rad/s"},
    {"kin-four-bar", 's', "omega4", NULL, "rad/s"},
    {"kin-four-bar", 's', "alpha3", NULL, "rad/s^2"},
    {"kin-four-bar", 's', "alpha4", NULL, "rad/s^2"},
    {"kin-four-bar", 's', "grashof", NULL, NULL},
    {"dyn-robot-2link", 'r', "tau1", NULL, NULL},
    {"dyn-robot-2link", 'r', "tau2", NULL, NULL},
    {"dyn-slider-crank", 'r', "omega", NULL, NULL},
};

static void outputs_at_the_defaults_should_have_the_api_names_and_columns(void **state)
{
    (void)state;
    int checked = 0;
    for (int i = 0; i < MM_COUNT(outputs_spec); i++) {
        const ospec *o = &outputs_spec[i];
        if (!mm_exercise_find(o->id))
            continue;
        checked++;
        answer a = solve(o->id, NULL);
        const char *list = o->kind == 's' ? "scalars" : o->kind == 't' ? "tables" : "series";
        const cJSON *e = named(a.doc, list, o->name);
        if (!e)
            fail_msg("%s at its defaults: no %s named %s", o->id, list, o->name);
        if (o->kind == 's' && !cJSON_IsNumber(cJSON_GetObjectItem(e, "value")))
            fail_msg("%s: scalar %s has no number", o->id, o->name);
        if (o->unit) {
            const cJSON *u = cJSON_GetObjectItem(e, "unit");
            if (!cJSON_IsString(u) || strcmp(u->valuestring, o->unit) != 0)
                fail_msg("%s: %s has unit '%s', SI wants '%s'", o->id, o->name,
                         cJSON_IsString(u) ? u->valuestring : "(none)", o->unit);
        }
        if (o->kind == 't') {                           /* the columns, in API.md's order */
            char cols[128];
            snprintf(cols, sizeof cols, "%s", o->cols);
            int last = -1;
            char *save = NULL;
            for (char *c = strtok_r(cols, ",", &save); c; c = strtok_r(NULL, ",", &save)) {
                int j = column(&a, o->name, c);
                if (j <= last)
                    fail_msg("%s: table %s lists column %s out of API.md's order %s", o->id, o->name, c, o->cols);
                last = j;
            }
        }
        done(&a);
    }
    print_message("%d outputs of API.md checked\n", checked);
}

/* ==== num-linear-system ============================================================ */

/* 2-norm condition number of a 2x2 without an SVD: sigma1^2 + sigma2^2 =
 * ||A||_F^2 = F and sigma1 sigma2 = |det A|, so sigma1^2 = (F + sqrt(F^2 -
 * 4 det^2)) / 2 and cond = sigma1 / sigma2 = sigma1^2 / |det|. */
static double cond2x2(double a, double b, double c, double d)
{
    double F = a * a + b * b + c * c + d * d, det = a * d - b * c;
    double s1sq = 0.5 * (F + sqrt((F - 2 * fabs(det)) * (F + 2 * fabs(det))));
    return s1sq / fabs(det);
}

/* Error-free transformations in plain double arithmetic (Dekker, Knuth):
 * exact on any IEEE machine, also under valgrind, which runs long double
 * at double precision. */
static void two_sum(double a, double b, double *s, double *e)
{
    *s = a + b;
    double z = *s - a;
    *e = (a - (*s - z)) + (b - z);
}

static void two_prod(double a, double b, double *p, double *e)
{
    const double split = 134217729.0;              /* 2^27 + 1, Veltkamp */
    double ca = split * a, ah = ca - (ca - a), al = a - ah;
    double cb = split * b, bh = cb - (cb - b), bl = b - bh;
    *p = a * b;
    *e = ((ah * bh - *p) + ah * bl + al * bh) + al * bl;
}

/* ||b - A x||_2 with each r_i accumulated in double-double (about 106
 * bits), and the sum of |A_ij x_j| (the scale of the cancellation). */
static double residual_norm(int n, const double *A, const double *b, const double *x, double *terms)
{
    double s2 = 0, big = 0;
    for (int i = 0; i < n; i++) {
        double hi = b[i], lo = 0;
        for (int j = 0; j < n; j++) {
            double p, pe, t, te;
            two_prod(-A[i * n + j], x[j], &p, &pe);
            two_sum(hi, p, &t, &te);
            hi = t;
            lo += te + pe;
            big += fabs(A[i * n + j] * x[j]);
        }
        double r = hi + lo;
        s2 += r * r;
    }
    *terms = big;
    return sqrt(s2);
}

static void num_linear_system_should_give_x_the_2_norm_condition_number_and_the_residual(void **state)
{
    (void)state;
    need("num-linear-system");
    /* defaults: Cramer's rule in exact arithmetic, det A = -3:
     * x = (2980/3, -6020/3, 1010) */
    answer a = solve("num-linear-system", NULL);
    const double A[9] = {1, 2, 3, 4, 5, 6, 7, 8, 10}, b[3] = {10, 0, 1000};
    double x[3] = {scalar(&a, "x1"), scalar(&a, "x2"), scalar(&a, "x3")};
    /* cond ~ 88: about 2 of 16 digits go */
    check_rel(x[0], 2980.0 / 3, 1e-13, "x1 by Cramer's rule");
    check_rel(x[1], -6020.0 / 3, 1e-13, "x2 by Cramer's rule");
    check_rel(x[2], 1010, 1e-13, "x3 by Cramer's rule");
    /* cond_2 = sqrt(lmax / lmin) of A^T A, eigenvalues by the symmetric 3x3
     * closed form (trigonometric); lmin = det(A)^2 / (l1 l2) keeps its digits */
    double B[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            B[3 * i + j] = 0;
            for (int k = 0; k < 3; k++)
                B[3 * i + j] += A[3 * k + i] * A[3 * k + j];
        }
    double q = (B[0] + B[4] + B[8]) / 3, p1 = B[1] * B[1] + B[2] * B[2] + B[5] * B[5];
    double p2 = (B[0] - q) * (B[0] - q) + (B[4] - q) * (B[4] - q) + (B[8] - q) * (B[8] - q) + 2 * p1;
    double p = sqrt(p2 / 6), C[9];
    for (int k = 0; k < 9; k++)
        C[k] = (B[k] - (k % 4 == 0 ? q : 0)) / p;
    double detC = C[0] * (C[4] * C[8] - C[5] * C[7]) - C[1] * (C[3] * C[8] - C[5] * C[6]) +
                  C[2] * (C[3] * C[7] - C[4] * C[6]);
    double phi = acos(fmax(-1, fmin(1, detC / 2))) / 3;
    double l1 = q + 2 * p * cos(phi), l3 = q + 2 * p * cos(phi + 2 * M_PI / 3), l2 = 3 * q - l1 - l3;
    double lmin = 9.0 / (l1 * l2);                      /* det(A^T A) = det(A)^2 = 9 */
    check_rel(scalar(&a, "cond"), sqrt(l1 / lmin), 1e-12, "cond_2(A) = sqrt(lmax/lmin) of A^T A");
    double terms, r = residual_norm(3, A, b, x, &terms);
    /* ||b - A x||_2 of the x shown; double-double sums err by ~2^-104 of
     * each term, and the exercise's compensated residual by a few eps of r */
    check_abs(scalar(&a, "residual"), r, 1e-28 * terms + 1e-3 * r, "residual = ||b - A x||_2");
    double xn = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]), bn = sqrt(10 * 10 + 1000 * 1000);
    check_abs(scalar(&a, "residual"), 0, 16 * 3 * EPS * (sqrt(l1) * xn + bn),
              "backward stable: residual within 16 n eps (||A|| ||x|| + ||b||)");
    done(&a);

    /* diag(2, 0.5): cond = 4 exactly */
    a = solve("num-linear-system", "A", "2,0;0,0.5", "b", "1,1", NULL);
    check_rel(scalar(&a, "cond"), 4, 4 * EPS, "cond_2 diag(2, 0.5) = 2 / 0.5");
    check_rel(scalar(&a, "cond"), cond2x2(2, 0, 0, 0.5), 4 * EPS, "2x2 closed form");
    check_abs(scalar(&a, "x1"), 0.5, 0, "x1 = 1/2 (exact)");
    check_abs(scalar(&a, "x2"), 2, 0, "x2 = 1/0.5 (exact)");
    check_abs(scalar(&a, "residual"), 0, 0, "exact solution, zero residual");
    done(&a);

    /* [1,2;3,4] x = [5;6]: x = (-4, 4.5); cond from the 2x2 closed form */
    a = solve("num-linear-system", "A", "1,2;3,4", "b", "5,6", NULL);
    check_rel(scalar(&a, "x1"), -4, 1e-14, "x1 = (5*4 - 2*6)/(-2)");
    check_rel(scalar(&a, "x2"), 4.5, 1e-14, "x2 = (1*6 - 3*5)/(-2)");
    check_rel(scalar(&a, "cond"), cond2x2(1, 2, 3, 4), 1e-14, "cond_2 = sigma1^2/|det| (2x2, no SVD)");
    const double A2[4] = {1, 2, 3, 4}, b2[2] = {5, 6};
    double x2[2] = {scalar(&a, "x1"), scalar(&a, "x2")};
    r = residual_norm(2, A2, b2, x2, &terms);
    check_abs(scalar(&a, "residual"), r, 1e-28 * terms + 1e-3 * r, "residual = ||b - A x||_2");
    done(&a);

    /* a singular matrix has no solution: 422 no_solution naming A */
    a = solve_any("num-linear-system", "A", "1,2;2,4", "b", "1,1", NULL);
    assert_int_equal(a.status, 422);
    const cJSON *e = cJSON_GetObjectItem(a.doc, "error");
    assert_string_equal(cJSON_GetObjectItem(e, "code")->valuestring, "no_solution");
    assert_string_equal(cJSON_GetObjectItem(e, "param")->valuestring, "A");
    done(&a);
}

/* ==== num-poly-roots ================================================================ */

/* Is z within tol of some root (re, im) of the table? Marks it used. */
static void expect_root(const answer *a, double re, double im, double tol, int *used, const char *what)
{
    int n = nrows(a, "roots"), best = -1;
    double dbest = INFINITY;
    for (int i = 0; i < n; i++) {
        if (used[i])
            continue;
        double d = hypot(cell(a, "roots", i, "re") - re, cell(a, "roots", i, "im") - im);
        if (d < dbest) {
            dbest = d;
            best = i;
        }
    }
    if (best < 0 || !(dbest <= tol))
        fail_msg("%s: no root within %g of %.17g%+.17gi (nearest at %g)", what, tol, re, im, dbest);
    used[best] = 1;
}

static void num_poly_roots_should_read_p_highest_power_first_and_list_re_and_im(void **state)
{
    (void)state;
    need("num-poly-roots");
    int used[8] = {0};
    /* x^3 + 2x^2 + 3x + 4 by Cardano: x = t - 2/3, t^3 + P t + Q = 0 with
     * P = 5/3, Q = 70/27; one real root and a complex pair */
    answer a = solve("num-poly-roots", NULL);
    assert_int_equal(nrows(&a, "roots"), 3);
    double P = 5.0 / 3, Q = 70.0 / 27, D = sqrt(Q * Q / 4 + P * P * P / 27);
    double u = cbrt(-Q / 2 + D), v = cbrt(-Q / 2 - D);
    expect_root(&a, u + v - 2.0 / 3, 0, 1e-14, used, "real root of x^3+2x^2+3x+4");
    expect_root(&a, -(u + v) / 2 - 2.0 / 3, (u - v) * sqrt(3) / 2, 1e-14, used, "complex root");
    expect_root(&a, -(u + v) / 2 - 2.0 / 3, -(u - v) * sqrt(3) / 2, 1e-14, used, "its conjugate");
    done(&a);

    /* highest power first: [2,-4] is 2x - 4 (root 2), not 2 - 4x (root 0.5) */
    a = solve("num-poly-roots", "p", "2,-4", NULL);
    assert_int_equal(nrows(&a, "roots"), 1);
    check_abs(cell(&a, "roots", 0, "re"), 2, 4 * EPS, "root of 2x - 4");
    check_abs(cell(&a, "roots", 0, "im"), 0, 0, "a real root has im = 0");
    done(&a);

    /* (x-1)(x-2)(x-3) = x^3 - 6x^2 + 11x - 6 */
    memset(used, 0, sizeof used);
    a = solve("num-poly-roots", "p", "1,-6,11,-6", NULL);
    assert_int_equal(nrows(&a, "roots"), 3);
    for (int k = 1; k <= 3; k++)
        expect_root(&a, k, 0, 1e-13, used, "roots 1, 2, 3");
    done(&a);

    /* x^2 + 1: +-i, re 0 */
    memset(used, 0, sizeof used);
    a = solve("num-poly-roots", "p", "1,0,1", NULL);
    assert_int_equal(nrows(&a, "roots"), 2);
    expect_root(&a, 0, 1, 4 * EPS, used, "i");
    expect_root(&a, 0, -1, 4 * EPS, used, "-i");
    done(&a);
}

/* ==== num-polyfit =================================================================== */

static void num_polyfit_should_give_matlab_order_coefficients_and_the_rms_residual_over_n(void **state)
{
    (void)state;
    need("num-polyfit");
    /* defaults: the regression line, slope = S_xy / S_xx, highest power first */
    answer a = solve("num-polyfit", NULL);
    const double x[3] = {1, 3, 10}, y[3] = {10, 18, 37};
    double xm = 14.0 / 3, ym = 65.0 / 3, sxx = 0, sxy = 0;
    for (int i = 0; i < 3; i++) {
        sxx += (x[i] - xm) * (x[i] - xm);
        sxy += (x[i] - xm) * (y[i] - ym);
    }
    double slope = sxy / sxx, icpt = ym - slope * xm, ss = 0;
    for (int i = 0; i < 3; i++)
        ss += (y[i] - (slope * x[i] + icpt)) * (y[i] - (slope * x[i] + icpt));
    check_rel(scalar(&a, "c0"), slope, 1e-13, "c0 = slope (MATLAB order: highest power first)");
    check_rel(scalar(&a, "c1"), icpt, 1e-13, "c1 = intercept");
    check_rel(scalar(&a, "c0"), 2.925373134328358, 1e-13, "the book's 2.92537 (= 196/67)");
    check_rel(scalar(&a, "rms_residual"), sqrt(ss / 3), 1e-12, "rms_residual = sqrt(sum r^2 / n), n = 3");
    done(&a);

    /* exact quadratic 2x^2 - 3x + 1 through 5 points: c = (2, -3, 1) */
    a = solve("num-polyfit", "x", "0,1,2,3,4", "y", "1,0,3,10,21", "degree", "2", NULL);
    check_rel(scalar(&a, "c0"), 2, 1e-13, "c0 multiplies x^2");
    check_rel(scalar(&a, "c1"), -3, 1e-13, "c1 multiplies x");
    check_rel(scalar(&a, "c2"), 1, 1e-13, "c2 is the constant");
    check_abs(scalar(&a, "rms_residual"), 0, 1e-13, "exact data: no residual");
    done(&a);

    /* a least-squares quadratic: rms over n (not n - degree - 1), from the
     * coefficients as shown */
    const double xs[6] = {-2, -1, 0, 1, 2, 3}, ys[6] = {5.1, 1.9, 1.2, 2.1, 4.8, 10.3};
    a = solve("num-polyfit", "x", "-2,-1,0,1,2,3", "y", "5.1,1.9,1.2,2.1,4.8,10.3", "degree", "2", NULL);
    double c0 = scalar(&a, "c0"), c1 = scalar(&a, "c1"), c2 = scalar(&a, "c2");
    ss = 0;
    for (int i = 0; i < 6; i++) {
        double r = ys[i] - ((c0 * xs[i] + c1) * xs[i] + c2);
        ss += r * r;
    }
    check_rel(scalar(&a, "rms_residual"), sqrt(ss / 6), 1e-10, "rms_residual = sqrt(sum r^2 / n), n = 6");
    /* normal equations by hand: sum x^j r = 0 for j = 0, 1, 2 */
    for (int j = 0; j <= 2; j++) {
        double s = 0, sa = 0;
        for (int i = 0; i < 6; i++) {
            double r = ys[i] - ((c0 * xs[i] + c1) * xs[i] + c2);
            s += pow(xs[i], j) * r;
            sa += fabs(pow(xs[i], j)) * (fabs(ys[i]) + 20);
        }
        check_abs(s, 0, 64 * EPS * sa, "least squares: residual orthogonal to x^j");
    }
    done(&a);
}

/* ==== num-nonlinear-roots =========================================================== */

/* The root of x^3 + sin x - 2 by bisection on [1, 1.1] to the last bit. */
static double book_root(void)
{
    double lo = 1, hi = 1.1;
    for (int i = 0; i < 200 && hi - lo > 0; i++) {
        double mid = lo + 0.5 * (hi - lo);
        if (mid == lo || mid == hi)
            break;
        if (mid * mid * mid + sin(mid) - 2 < 0)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

static void num_nonlinear_roots_should_refine_to_an_absolute_tol_and_report_a_grid_root_once(void **state)
{
    (void)state;
    need("num-nonlinear-roots");
    double x = book_root();                             /* 1.0434... */
    answer a = solve("num-nonlinear-roots", NULL);
    assert_int_equal(nrows(&a, "roots"), 1);
    check_abs(cell(&a, "roots", 0, "x"), x, 1e-6 + 8 * EPS, "within tol = 1e-6 (absolute) of the root");
    done(&a);
    a = solve("num-nonlinear-roots", "tol", "1e-13", NULL);
    check_abs(cell(&a, "roots", 0, "x"), x, 1e-13 + 8 * EPS, "within tol = 1e-13 of the root");
    done(&a);

    /* absolute, not relative: a root near 523.6 with tol = 1e-9 is within
     * 1e-9 (a relative tol would allow 5e-7) */
    double want = 1000 * M_PI / 6;                      /* sin(x/1000) = 1/2 */
    a = solve("num-nonlinear-roots", "f", "sin(x/1000)-0.5", "a", "0", "b", "1000", "n", "3", "tol", "1e-9", NULL);
    assert_int_equal(nrows(&a, "roots"), 1);
    check_abs(cell(&a, "roots", 0, "x"), want, 1e-9 + 8 * EPS * want, "absolute tol on x");
    done(&a);

    /* a root exactly on a subdivision point is reported once: x - 2 on
     * [0, 4] with n = 4 has grid points 0, 1, 2, 3, 4 */
    a = solve("num-nonlinear-roots", "f", "x-2", "a", "0", "b", "4", "n", "4", NULL);
    assert_int_equal(nrows(&a, "roots"), 1);
    check_abs(cell(&a, "roots", 0, "x"), 2, 0, "the grid point x = 2 itself");
    done(&a);
    /* two grid roots, (x-1)(x-3) */
    a = solve("num-nonlinear-roots", "f", "(x-1)*(x-3)", "a", "0", "b", "4", "n", "4", NULL);
    assert_int_equal(nrows(&a, "roots"), 2);
    double r0 = cell(&a, "roots", 0, "x"), r1 = cell(&a, "roots", 1, "x");
    check_abs(fmin(r0, r1), 1, 0, "grid root 1, once");
    check_abs(fmax(r0, r1), 3, 0, "grid root 3, once");
    done(&a);
    /* 0.3 is a grid point of [0, 1] with n = 10, but 3*0.3 - 0.9 is not 0 in
     * doubles: the sign change is then in one part only, still one root */
    a = solve("num-nonlinear-roots", "f", "3*x-0.9", "a", "0", "b", "1", "n", "10", NULL);
    assert_int_equal(nrows(&a, "roots"), 1);
    check_abs(cell(&a, "roots", 0, "x"), 0.3, 1e-6 + 4 * EPS, "the root 0.3, once");
    done(&a);
    /* a root at an end of the interval: once */
    a = solve("num-nonlinear-roots", "f", "x", "a", "0", "b", "4", "n", "4", NULL);
    assert_int_equal(nrows(&a, "roots"), 1);
    check_abs(cell(&a, "roots", 0, "x"), 0, 0, "the root at a = 0");
    done(&a);
    a = solve("num-nonlinear-roots", "f", "x-4", "a", "0", "b", "4", "n", "4", NULL);
    assert_int_equal(nrows(&a, "roots"), 1);
    check_abs(cell(&a, "roots", 0, "x"), 4, 0, "the root at b = 4");
    done(&a);
}

/* ==== num-eigen ===================================================================== */

static void num_eigen_should_solve_k_v_equals_lambda_m_v_with_omega_the_square_root(void **state)
{
    (void)state;
    need("num-eigen");
    /* defaults: fixed-free chain of 3 unit masses and 100 N/m springs,
     * lambda_j = 2 k (1 - cos((2j - 1) pi / 7)) */
    answer a = solve("num-eigen", NULL);
    assert_int_equal(nrows(&a, "eigen"), 3);
    double lam[3], want[3];
    for (int j = 0; j < 3; j++) {
        lam[j] = cell(&a, "eigen", j, "lambda");
        want[j] = 200 * (1 - cos((2 * j + 1) * M_PI / 7));
        check_rel(cell(&a, "eigen", j, "omega"), sqrt(lam[j]), 2 * EPS, "omega = sqrt(lambda), same row");
    }
    assert_string_equal(column_unit(&a, "eigen", "omega"), "rad/s");
    qsort(lam, 3, sizeof *lam, cmp_double);
    for (int j = 0; j < 3; j++)
        check_rel(lam[j], want[j], 1e-13, "lambda of the chain, closed form");
    done(&a);

    /* generalized, M not the identity (nor diagonal):
     * det(K - lambda M) = 0 -> a lambda^2 + b lambda + c = 0 */
    const double k11 = 300, k12 = -100, k22 = 100, m11 = 2, m12 = 0.5, m22 = 1;
    a = solve("num-eigen", "K", "300,-100;-100,100", "M", "2,0.5;0.5,1", NULL);
    assert_int_equal(nrows(&a, "eigen"), 2);
    double qa = m11 * m22 - m12 * m12, qb = -(k11 * m22 + k22 * m11 - 2 * k12 * m12), qc = k11 * k22 - k12 * k12;
    double disc = sqrt(qb * qb - 4 * qa * qc), lhi = (-qb + disc) / (2 * qa), llo = qc / (qa * lhi);
    double got[2] = {cell(&a, "eigen", 0, "lambda"), cell(&a, "eigen", 1, "lambda")};
    for (int j = 0; j < 2; j++)
        check_rel(cell(&a, "eigen", j, "omega"), sqrt(got[j]), 2 * EPS, "omega = sqrt(lambda)");
    qsort(got, 2, sizeof *got, cmp_double);
    check_rel(got[0], llo, 1e-13, "lower root of det(K - lambda M) = 0");
    check_rel(got[1], lhi, 1e-13, "upper root of det(K - lambda M) = 0");
    /* not the eigenvalues of K alone */
    assert_true(fabs(got[1] - (200 + sqrt(200 * 200 - 20000))) > 1);
    done(&a);
}

/* ==== vib-sdof-free ================================================================= */

static void vib_sdof_free_should_give_omega_n_zeta_omega_d_and_the_regime(void **state)
{
    (void)state;
    need("vib-sdof-free");
    static const struct {
        const char *m, *k, *c;
        double mv, kv, cv;
        int regime;
    } cases[] = {
        {"1", "100", "2", 1, 100, 2, 0},       /* the defaults, zeta = 0.1 */
        {"1", "100", "20", 1, 100, 20, 1},     /* c = 2 sqrt(k m) = 20 exactly */
        {"1", "100", "50", 1, 100, 50, 2},
        {"2", "50", "20", 2, 50, 20, 1},       /* 2 sqrt(100) = 20 */
        {"2", "50", "0", 2, 50, 0, 0},         /* undamped counts as under */
        {"2", "50", "19.9", 2, 50, 19.9, 0},
        {"2", "50", "20.1", 2, 50, 20.1, 2},
        {"2", "3", "2*sqrt(6)", 2, 3, 2 * 2.449489742783178, 1},  /* c = 2 sqrt(k m) as an expression */
    };
    for (int i = 0; i < MM_COUNT(cases); i++) {
        answer a = solve("vib-sdof-free", "m", cases[i].m, "k", cases[i].k, "c", cases[i].c, NULL);
        double wn = sqrt(cases[i].kv / cases[i].mv), z = cases[i].cv / (2 * sqrt(cases[i].kv * cases[i].mv));
        check_rel(scalar(&a, "omega_n"), wn, 2 * EPS, "omega_n = sqrt(k/m)");
        check_rel(scalar(&a, "zeta"), z, 4 * EPS, "zeta = c / (2 sqrt(k m))");
        if (scalar(&a, "regime") != cases[i].regime)
            fail_msg("m=%s k=%s c=%s: regime %g, want %d (0 under, 1 critical, 2 over)", cases[i].m, cases[i].k,
                     cases[i].c, scalar(&a, "regime"), cases[i].regime);
        if (cases[i].regime == 0)
            check_rel(scalar(&a, "omega_d"), wn * sqrt(1 - z * z), 1e-14, "omega_d = omega_n sqrt(1 - zeta^2)");
        done(&a);
    }
}

/* ==== vib-sdof-forced =============================================================== */

static void vib_sdof_forced_should_give_the_steady_amplitude_and_a_lag_in_0_to_pi(void **state)
{
    (void)state;
    need("vib-sdof-forced");
    static const struct {
        const char *m, *k, *c, *F0, *w;
    } cases[] = {
        {"1", "100", "2", "1", "8"},        /* the defaults */
        {"2", "50", "1", "3", "4"},
        {"1", "100", "2", "1", "15"},       /* above resonance: lag past pi/2 */
        {"1", "100", "0", "1", "8"},        /* undamped below: in phase */
        {"1", "100", "0", "1", "12"},       /* undamped above: lag pi */
        {"0.5", "2000", "30", "7", "63.2"}, /* near resonance */
        {"3", "10", "40", "2", "0.5"},      /* overdamped */
    };
    for (int i = 0; i < MM_COUNT(cases); i++) {
        double m = atof(cases[i].m), k = atof(cases[i].k), c = atof(cases[i].c), F0 = atof(cases[i].F0),
               w = atof(cases[i].w);
        answer a = solve("vib-sdof-forced", "m", cases[i].m, "k", cases[i].k, "c", cases[i].c, "F0",
                         cases[i].F0, "omega", cases[i].w, NULL);
        double D = k - m * w * w, cw = c * w;
        double X = F0 / sqrt(D * D + cw * cw), ph = atan2(cw, D);
        check_rel(scalar(&a, "omega_n"), sqrt(k / m), 2 * EPS, "omega_n = sqrt(k/m)");
        check_rel(scalar(&a, "zeta"), c / (2 * sqrt(k * m)), 4 * EPS, "zeta = c / (2 sqrt(k m))");
        check_rel(scalar(&a, "X"), X, 1e-9, "X = F0 / sqrt((k - m w^2)^2 + (c w)^2)");
        double phase = scalar(&a, "phase");
        assert_true(phase >= 0 && phase <= M_PI);
        check_abs(phase, ph, 1e-12, "phase = atan2(c w, k - m w^2), a lag in [0, pi]");
        check_rel(scalar(&a, "magnification"), X * k / F0, 1e-9, "magnification = X / (F0/k)");
        done(&a);
    }
}

/* Worst |x(t) - X cos(w t - phase)| over the samples with t >= t0. */
static double settle_error(const answer *a, double X, double w, double phase, double t0)
{
    static double t[4001], x[4001];
    int n = series(a, "x", t, x, 4001);
    double worst = 0;
    int used = 0;
    for (int i = 0; i < n; i++)
        if (t[i] >= t0) {
            worst = fmax(worst, fabs(x[i] - X * cos(w * t[i] - phase)));
            used++;
        }
    assert_true(used > 50);
    return worst;
}

static void vib_sdof_forced_response_should_settle_on_x_cos_omega_t_minus_phase(void **state)
{
    (void)state;
    need("vib-sdof-forced");
    /* critical damping, decay e^(-10 t): after 6 s the transient is
     * e^-60 of the motion; the force is F0 cos(w t), the lag positive */
    answer a = solve("vib-sdof-forced", "c", "20", "omega", "8", "F0", "3", "t_end", "10", NULL);
    double D = 100 - 64, cw = 160, X = 3 / sqrt(D * D + cw * cw), ph = atan2(cw, D);
    /* the integrator works at rtol 1e-8 */
    check_abs(settle_error(&a, X, 8, ph, 6), 0, 1e-6 * X, "x(t) -> X cos(w t - phase)");
    done(&a);
    /* above resonance, lag close to pi */
    a = solve("vib-sdof-forced", "c", "20", "omega", "25", "t_end", "10", NULL);
    D = 100 - 625;
    cw = 500;
    X = 1 / sqrt(D * D + cw * cw);
    ph = atan2(cw, D);
    check_abs(settle_error(&a, X, 25, ph, 6), 0, 1e-6 * X, "x(t) -> X cos(w t - phase), above resonance");
    done(&a);
}

/* ==== vib-base-excitation =========================================================== */

static void vib_base_excitation_should_give_x_as_transmissibility_times_y(void **state)
{
    (void)state;
    need("vib-base-excitation");
    static const struct {
        const char *m, *k, *c, *Y, *w;
    } cases[] = {
        {"1", "100", "2", "0.01", "8"},     /* the defaults */
        {"1", "100", "2", "0.01", "14.142135623730951"},  /* sqrt(2) omega_n: T = 1 */
        {"2", "50", "1", "0.03", "20"},     /* isolation */
        {"1", "100", "0", "0.01", "5"},
        {"1", "100", "0", "0.01", "30"},
        {"4", "900", "150", "0.2", "9"},
    };
    for (int i = 0; i < MM_COUNT(cases); i++) {
        double m = atof(cases[i].m), k = atof(cases[i].k), c = atof(cases[i].c), Y = atof(cases[i].Y),
               w = atof(cases[i].w);
        answer a = solve("vib-base-excitation", "m", cases[i].m, "k", cases[i].k, "c", cases[i].c, "Y",
                         cases[i].Y, "omega", cases[i].w, NULL);
        double D = k - m * w * w, cw = c * w;
        double T = sqrt((k * k + cw * cw) / (D * D + cw * cw));
        check_rel(scalar(&a, "transmissibility"), T, 1e-12,
                  "T = sqrt((k^2 + (c w)^2) / ((k - m w^2)^2 + (c w)^2))");
        check_rel(scalar(&a, "X"), T * Y, 1e-12, "X = transmissibility * Y (absolute amplitude)");
        check_rel(scalar(&a, "X"), scalar(&a, "transmissibility") * Y, 4 * EPS, "X = T Y as reported");
        /* the lag of x behind y = Y cos(w t): X e^(-i phase) = Y (k + i c w) / (D + i c w) */
        double complex H = (k + I * cw) / (D + I * cw);
        double want = -carg(H), phase = scalar(&a, "phase");
        assert_true(phase >= 0 && phase <= M_PI);
        check_abs(phase, want, 1e-12, "phase: lag of the mass behind the support, in [0, pi]");
        done(&a);
    }
    /* the mass's absolute motion settles on X cos(w t - phase) (heavy
     * damping: the transient decays as e^(-10 t)) */
    answer a = solve("vib-base-excitation", "c", "20", "omega", "8", "t_end", "10", NULL);
    double D = 36, cw = 160, T = sqrt((1e4 + cw * cw) / (D * D + cw * cw));
    double complex H = (100 + I * cw) / (D + I * cw);
    check_abs(settle_error(&a, T * 0.01, 8, -carg(H), 6), 0, 1e-6 * T * 0.01,
              "x(t) -> X cos(w t - phase), X absolute");
    done(&a);
}

/* ==== vib-coulomb =================================================================== */

/* The piecewise closed form: half-period arcs pi/omega_n about +-mu m g/k;
 * the mass stops at the first velocity zero where |k x| <= mu m g. */
static void coulomb_exact(double m, double k, double mu, double g, double x0, double v0, double *stop,
                          double *xf, int *arcs)
{
    double w = sqrt(k / m), d = mu * m * g / k, F = mu * m * g, t = 0, x = x0;
    *arcs = 0;
    if (v0 != 0) {                                   /* first arc from (x0, v0) */
        double sg = v0 > 0 ? 1 : -1, c = -sg * d;   /* friction -sg mu m g: centre -sg d */
        double R = hypot(x0 - c, v0 / w), phi = atan2(v0 / w, x0 - c);  /* x - c = R cos(w t - phi) */
        t = (sg > 0 ? phi : phi + M_PI) / w;
        x = c + sg * R;
        (*arcs)++;
    }
    while (fabs(k * x) > F) {                        /* from rest: turn back */
        double dir = x > 0 ? -1 : 1, c = -dir * d;
        x = 2 * c - x;
        t += M_PI / w;
        (*arcs)++;
    }
    *stop = t;
    *xf = x;
}

static void vib_coulomb_should_stop_where_the_piecewise_closed_form_stops(void **state)
{
    (void)state;
    need("vib-coulomb");
    static const struct {
        const char *m, *k, *mu, *g, *x0, *v0;
    } cases[] = {
        {"1", "100", "0.1", "9.81", "0.1", "0"},      /* the defaults: 5 arcs */
        {"2", "50", "0.05", "9.81", "-0.3", "0.4"},
        {"1", "100", "0.1", "9.81", "0.1", "-1"},
        {"0.5", "300", "0.3", "1.62", "0.004", "0"},  /* |k x0| = 1.2 > mu m g = 0.243 */
        {"1", "100", "0.1", "9.81", "0.005", "0.2"},  /* inside the band but moving */
    };
    for (int i = 0; i < MM_COUNT(cases); i++) {
        double m = atof(cases[i].m), k = atof(cases[i].k), mu = atof(cases[i].mu), g = atof(cases[i].g),
               x0 = atof(cases[i].x0), v0 = atof(cases[i].v0), stop, xf;
        int arcs;
        coulomb_exact(m, k, mu, g, x0, v0, &stop, &xf, &arcs);
        answer a = solve("vib-coulomb", "m", cases[i].m, "k", cases[i].k, "mu", cases[i].mu, "g", cases[i].g,
                         "x0", cases[i].x0, "v0", cases[i].v0, NULL);
        double w = sqrt(k / m), size = fabs(x0) + fabs(v0) / w + mu * m * g / k;
        check_rel(scalar(&a, "decay_per_cycle"), 4 * mu * m * g / k, 4 * EPS, "decay_per_cycle = 4 mu m g / k");
        assert_true(arcs >= 1);
        /* events located by root finding, not on a time step: far better
         * than the plot grid (t_end / 500) */
        check_abs(scalar(&a, "stop_time"), stop, 1e-8 * (arcs + 5) / w, "stop_time, piecewise closed form");
        check_abs(scalar(&a, "x_final"), xf, 1e-9 * (arcs + 5) * size, "x_final, piecewise closed form");
        assert_true(fabs(k * scalar(&a, "x_final")) <= mu * m * g * (1 + 1e-8));
        done(&a);
    }
    /* the defaults by hand: |x| = 0.1 - 2 j d, d = 0.00981, stops after 5
     * half periods of pi/10 s at -(0.1 - 10 d) */
    answer a = solve("vib-coulomb", NULL);
    check_rel(scalar(&a, "stop_time"), 5 * M_PI / 10, 1e-8, "5 half periods");
    check_rel(scalar(&a, "x_final"), -(0.1 - 10 * 0.00981), 1e-7, "x_final = -(x0 - 10 d)");
    done(&a);
}

static void vib_coulomb_should_never_move_from_inside_the_friction_band(void **state)
{
    (void)state;
    need("vib-coulomb");
    /* band mu m g / k = 0.00981 m: x0 = 0.005 at rest is held by static friction */
    answer a = solve("vib-coulomb", "x0", "0.005", "v0", "0", NULL);
    check_abs(scalar(&a, "stop_time"), 0, 0, "stop_time = 0 when it never moves");
    check_abs(scalar(&a, "x_final"), 0.005, 0, "x_final = x0");
    check_rel(scalar(&a, "decay_per_cycle"), 4 * 0.1 * 9.81 / 100, 4 * EPS, "decay_per_cycle = 4 mu m g / k");
    done(&a);
    a = solve("vib-coulomb", "x0", "-0.009", "v0", "0", NULL);
    check_abs(scalar(&a, "stop_time"), 0, 0, "stop_time = 0 when it never moves");
    check_abs(scalar(&a, "x_final"), -0.009, 0, "x_final = x0");
    done(&a);
}

/* ==== vib-fourier-series ============================================================ */

enum { SQUARE, SAWTOOTH, TRIANGLE };

/* The coefficients of API.md's waves, of amplitude A, by the definition
 * a_k = (2/T) int f cos, b_k = (2/T) int f sin integrated by hand:
 *   square   +A on (0, T/2), -A on (T/2, T) (odd):   b_k = 4A/(k pi), k odd
 *   sawtooth A (2t/T - 1) on (0, T), jump 2A at t = 0: b_k = -2A/(k pi)
 *   triangle |a_k + i b_k| = 8A/(pi^2 k^2), k odd (origin not fixed by API.md) */
static void wave_coeff(int wave, double A, int k, double *a, double *b)
{
    *a = *b = 0;
    if (wave == SQUARE && k % 2)
        *b = 4 * A / (k * M_PI);
    else if (wave == SAWTOOTH && k > 0)
        *b = -2 * A / (k * M_PI);
    else if (wave == TRIANGLE && k % 2)
        *a = 8 * A / (M_PI * M_PI * (double)k * k);
}

/* How far a coefficient computed from N samples of one period may be from
 * the integral, the aliasing bound the exercise's theory states (eq. 9 of
 * vib/fourier_series.md: the table lists the trapezoidal-rule coefficients,
 * N >= max(4096, 256 K) samples), for coefficients c/k and c/k^2.  API.md
 * asks for the Fourier coefficients and says nothing of their accuracy;
 * this is the documented approximation. */
static double alias_tol(int wave, double A, int k, int K)
{
    double N = fmax(4096, 256.0 * K), c = wave == SQUARE ? 4 * A / M_PI : wave == SAWTOOTH ? 2 * A / M_PI
                                                                                      : 8 * A / (M_PI * M_PI);
    if (k == 0)
        return 64 * EPS * A;
    if (wave == TRIANGLE)
        return M_PI * M_PI / 3 * c / ((N - k) * (N - k)) + 64 * EPS * A;
    return M_PI * M_PI / 3 * c * k / (N * N - (double)k * k) + 64 * EPS * A;
}

static double partial_sum(const double *a, const double *b, int K, double T, double t)
{
    double s = 0, wt = 2 * M_PI * t / T;
    for (int k = 1; k <= K; k++)
        s += a[k] * cos(k * wt) + b[k] * sin(k * wt);
    return s;
}

/* max over one period of S_K: a scan at 32 points per period of harmonic
 * K + 1, then golden section around the best sample. */
static double max_partial_sum(const double *a, const double *b, int K, double T)
{
    int M = 32 * (K + 1);
    double h = T / M, tbest = 0, sbest = -INFINITY;
    for (int i = 0; i < M; i++) {
        double t = -T / 2 + i * h, s = partial_sum(a, b, K, T, t);
        if (s > sbest) {
            sbest = s;
            tbest = t;
        }
    }
    double lo = tbest - h, hi = tbest + h, g = (sqrt(5) - 1) / 2;
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    double f1 = partial_sum(a, b, K, T, x1), f2 = partial_sum(a, b, K, T, x2);
    for (int it = 0; it < 200 && hi - lo > 1e-15 * T; it++) {
        if (f1 > f2) {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - g * (hi - lo);
            f1 = partial_sum(a, b, K, T, x1);
        } else {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + g * (hi - lo);
            f2 = partial_sum(a, b, K, T, x2);
        }
    }
    return fmax(sbest, fmax(f1, f2));
}

static const char *const wave_name[3] = {"square", "sawtooth", "triangle"};

static void vib_fourier_series_should_give_the_coefficients_up_to_harmonic_terms(void **state)
{
    (void)state;
    need("vib-fourier-series");
    static const struct {
        int wave;
        const char *terms, *T, *A;
    } cases[] = {
        {SQUARE, "25", "1", "1"}, {SAWTOOTH, "25", "1", "1"}, {TRIANGLE, "25", "1", "1"},
        {SQUARE, "7", "3", "2.5"}, {SAWTOOTH, "60", "0.2", "0.4"}, {TRIANGLE, "9", "2", "5"},
    };
    for (int i = 0; i < MM_COUNT(cases); i++) {
        int K = atoi(cases[i].terms);
        double A = atof(cases[i].A);
        answer a = solve("vib-fourier-series", "wave", wave_name[cases[i].wave], "terms", cases[i].terms, "T",
                         cases[i].T, "A", cases[i].A, NULL);
        int n = nrows(&a, "coefficients");
        /* terms = the highest harmonic included: rows k = 0..K (k = 0, the
         * mean, is 0 for all three waves) */
        assert_int_equal(n, K + 1);
        check_abs(cell(&a, "coefficients", n - 1, "k"), K, 0, "the last row is harmonic k = terms");
        for (int r = 0; r < n; r++) {
            int k = (int)cell(&a, "coefficients", r, "k");
            assert_int_equal(k, r);
            double ak = cell(&a, "coefficients", r, "a_k"), bk = cell(&a, "coefficients", r, "b_k"), ae, be;
            wave_coeff(cases[i].wave, A, k, &ae, &be);
            double tol = alias_tol(cases[i].wave, A, k, K);
            if (cases[i].wave == TRIANGLE) {
                check_abs(hypot(ak, bk), hypot(ae, be), tol, "triangle |c_k| = 8A/(pi k)^2, odd k");
            } else {
                check_abs(ak, ae, tol, "a_k = 0 (odd wave)");
                check_abs(bk, be, tol,
                          cases[i].wave == SQUARE ? "square b_k = 4A/(k pi), odd k"
                                                  : "sawtooth ramp -A..A: b_k = -2A/(k pi)");
            }
        }
        done(&a);
    }
}

static void vib_fourier_series_overshoot_should_be_max_s_k_minus_a_and_approach_gibbs(void **state)
{
    (void)state;
    need("vib-fourier-series");
    /* Gibbs constant (1/pi) Si(pi) - 1/2 (mpmath: si(pi)/pi - 0.5 at 30 digits) */
    const double G = 0.0894898722360836351;
    static const struct {
        int wave;
        const char *terms, *T, *A;
    } cases[] = {
        {SQUARE, "25", "1", "1"},   {SAWTOOTH, "25", "1", "1"},  {SQUARE, "400", "1", "1"},
        {SAWTOOTH, "400", "1", "1"}, {SQUARE, "60", "3", "2.5"},  {SAWTOOTH, "9", "0.5", "4"},
        {SQUARE, "1", "1", "1"},    {TRIANGLE, "25", "1", "1"},
    };
    double dist_sq[2] = {0}, dist_saw[2] = {0};
    for (int i = 0; i < MM_COUNT(cases); i++) {
        int K = atoi(cases[i].terms), w = cases[i].wave;
        double T = atof(cases[i].T), A = atof(cases[i].A);
        double *ca = calloc((size_t)K + 1, sizeof *ca), *cb = calloc((size_t)K + 1, sizeof *cb);
        assert_non_null(ca);
        assert_non_null(cb);
        for (int k = 1; k <= K; k++)
            wave_coeff(w, A, k, &ca[k], &cb[k]);
        double want = max_partial_sum(ca, cb, K, T) - A, tol = 16 * EPS * A * (K + 10);
        for (int k = 1; k <= K; k++)        /* |S_K - S_K(sampled coefficients)| <= sum of their errors */
            tol += alias_tol(w, A, k, K);
        free(ca);
        free(cb);
        answer a = solve("vib-fourier-series", "wave", wave_name[w], "terms", cases[i].terms, "T", cases[i].T, "A",
                         cases[i].A, NULL);
        double ov = scalar(&a, "overshoot");
        /* max over t of S_K - A, refined, not read off a plot grid (a grid of
         * 2001 points misses the top of a K = 400 ripple by far more than tol,
         * which allows only the coefficients' documented aliasing) */
        check_abs(ov, want, tol, "overshoot = max_t S_K(t) - A (refined)");
        check_abs(ov, want, 1e-4 * A, "overshoot within 1e-4 A of the exact S_K's");
        if (w != TRIANGLE) {
            double frac = ov / (2 * A);                     /* the jump is 2A */
            if (K == 400) {
                if (w == SQUARE)
                    check_abs(frac, G, 1e-4, "square, K = 400: overshoot/jump within 1e-4 of Gibbs");
                else    /* the sawtooth approaches as G - 1/(2(K+1)) */
                    check_abs(frac, G, 1.0 / (K + 1), "sawtooth, K = 400: within O(1/K) of Gibbs");
            }
            if (K == 25 || K == 400) {
                double *d = w == SQUARE ? dist_sq : dist_saw;
                d[K == 400] = fabs(frac - G);
            }
        }
        done(&a);
    }
    /* the distance to the Gibbs constant shrinks as K grows */
    assert_true(dist_sq[1] < dist_sq[0]);
    assert_true(dist_saw[1] < dist_saw[0]);
}

/* ==== vib-dft ======================================================================= */

/* Single-sided amplitude of bin k of x[0..n-1] by the defining sum, the
 * angle reduced exactly (j k mod n): 2|X_k|/N, |X_0|/N at 0 Hz. */
static double dft_amp(const double *x, int n, int k)
{
    long double re = 0, im = 0;
    for (long j = 0; j < n; j++) {
        long double ang = 2 * (long double)M_PI * (long double)((j * k) % n) / n;
        re += x[j] * cosl(ang);
        im -= x[j] * sinl(ang);
    }
    return (double)((k == 0 ? 1 : 2) * sqrtl(re * re + im * im) / n);
}

static void vib_dft_should_give_the_single_sided_amplitude_of_the_defining_sum(void **state)
{
    (void)state;
    need("vib-dft");
    static const struct {
        const char *signal, *fs, *N;
    } cases[] = {
        {"sin(2*pi*5*t)+0.5*sin(2*pi*12*t)", "100", "256"},    /* the defaults: leakage */
        {"0.2+cos(2*pi*3*t)^3-0.4*t", "40", "100"},            /* odd-ish N, a trend */
        {"exp(-3*t)*sin(2*pi*7.3*t)", "64", "129"},           /* odd N: no Nyquist bin */
    };
    static double f[8192], amp[8192], x[8192];
    for (int i = 0; i < MM_COUNT(cases); i++) {
        answer a = solve("vib-dft", "signal", cases[i].signal, "fs", cases[i].fs, "N", cases[i].N, NULL);
        double fs = atof(cases[i].fs);
        int N = atoi(cases[i].N), nb = series(&a, "amplitude", f, amp, 8192);
        assert_int_equal(nb, N / 2 + 1);
        /* the samples x_j = signal(j / fs), written here */
        for (int j = 0; j < N; j++) {
            double t = j / fs;
            x[j] = i == 0   ? sin(2 * M_PI * 5 * t) + 0.5 * sin(2 * M_PI * 12 * t)
                   : i == 1 ? 0.2 + pow(cos(2 * M_PI * 3 * t), 3) - 0.4 * t
                            : exp(-3 * t) * sin(2 * M_PI * 7.3 * t);
        }
        double scale = 0;
        for (int j = 0; j < N; j++)
            scale += fabs(x[j]);
        for (int k = 0; k < nb; k++) {
            check_rel(f[k], k * fs / N, 4 * EPS, "bin frequency k fs / N");
            if (2 * k == N)
                continue;       /* the Nyquist bin: see the report (no mirror image) */
            /* an FFT of N terms: rounding of a few eps of sum |x_j| / N */
            check_abs(amp[k], dft_amp(x, N, k), 64 * EPS * scale / N,
                      "single-sided amplitude 2|X_k|/N (|X_0|/N at 0 Hz)");
        }
        /* peaks: local maxima at bins, largest first, read off the spectrum */
        int np = nrows(&a, "peaks");
        assert_true(np >= 1);
        double prev = INFINITY;
        for (int r = 0; r < np; r++) {
            double pf = cell(&a, "peaks", r, "f"), pa = cell(&a, "peaks", r, "amplitude");
            double kk = pf * N / fs;
            int k = (int)nearbyint(kk);
            check_abs(kk, k, 1e-9, "a peak sits at a bin frequency (no interpolation)");
            check_rel(pa, amp[k], 4 * EPS, "a peak's amplitude is its bin's");
            assert_true(pa <= prev);
            prev = pa;
            if (k > 0)
                assert_true(amp[k] >= amp[k - 1]);
            if (k + 1 < nb)
                assert_true(amp[k] >= amp[k + 1]);
        }
        if (i == 0) {
            /* the two largest peaks are the 5 Hz and 12 Hz lines, at their nearest bins */
            check_abs(cell(&a, "peaks", 0, "f"), 13 * 100.0 / 256, 1e-12, "5 Hz reads at bin 13");
            check_abs(cell(&a, "peaks", 1, "f"), 31 * 100.0 / 256, 1e-12, "12 Hz reads at bin 31");
        }
        done(&a);
    }
}

static void vib_dft_should_read_a_bin_centred_sine_and_a_constant_at_their_amplitudes(void **state)
{
    (void)state;
    need("vib-dft");
    static double f[8192], amp[8192];
    /* 10 Hz at fs = 100, N = 200: bin 20 exactly */
    answer a = solve("vib-dft", "signal", "0.7*sin(2*pi*10*t)", "fs", "100", "N", "200", NULL);
    int nb = series(&a, "amplitude", f, amp, 8192);
    assert_int_equal(nb, 101);
    check_abs(f[20], 10, 1e-12, "bin 20 is 10 Hz");
    check_rel(amp[20], 0.7, 1e-12, "a bin-centred sine of amplitude 0.7 reads 0.7");
    assert_string_equal(column_unit(&a, "peaks", "f"), "Hz");
    assert_string_equal(cJSON_GetObjectItem(named(a.doc, "series", "amplitude"), "x_unit")->valuestring, "Hz");
    check_abs(cell(&a, "peaks", 0, "f"), 10, 1e-12, "the peak at 10 Hz");
    check_rel(cell(&a, "peaks", 0, "amplitude"), 0.7, 1e-12, "peak amplitude 0.7");
    done(&a);

    a = solve("vib-dft", "signal", "0.3", "fs", "100", "N", "200", NULL);
    nb = series(&a, "amplitude", f, amp, 8192);
    check_abs(f[0], 0, 0, "bin 0 is 0 Hz");
    check_rel(amp[0], 0.3, 1e-14, "a constant 0.3 reads 0.3 at 0 Hz (|X_0|/N)");
    check_abs(cell(&a, "peaks", 0, "f"), 0, 0, "the peak at 0 Hz");
    check_rel(cell(&a, "peaks", 0, "amplitude"), 0.3, 1e-14, "its amplitude 0.3");
    done(&a);

    /* both, largest first */
    a = solve("vib-dft", "signal", "0.3+0.7*sin(2*pi*10*t)+0.2*cos(2*pi*31.5*t)", "fs", "100", "N", "200", NULL);
    assert_true(nrows(&a, "peaks") >= 3);
    check_abs(cell(&a, "peaks", 0, "f"), 10, 1e-12, "largest first: 10 Hz");
    check_rel(cell(&a, "peaks", 0, "amplitude"), 0.7, 1e-12, "0.7");
    check_abs(cell(&a, "peaks", 1, "f"), 0, 1e-12, "then 0 Hz");
    check_rel(cell(&a, "peaks", 1, "amplitude"), 0.3, 1e-12, "0.3");
    check_abs(cell(&a, "peaks", 2, "f"), 31.5, 1e-12, "then 31.5 Hz (bin 63)");
    check_rel(cell(&a, "peaks", 2, "amplitude"), 0.2, 1e-12, "a cosine reads its amplitude too");
    done(&a);
}

static void vib_dft_should_accept_the_hann_window(void **state)
{
    (void)state;
    need("vib-dft");
    answer a = solve("vib-dft", "signal", "0.7*sin(2*pi*10*t)", "fs", "100", "N", "200", "window", "hann", NULL);
    const cJSON *pw = cJSON_GetObjectItem(cJSON_GetObjectItem(a.doc, "params"), "window");
    assert_true(cJSON_IsString(pw));
    assert_string_equal(pw->valuestring, "hann");
    check_abs(cell(&a, "peaks", 0, "f"), 10, 1e-12, "hann: the peak stays at its bin");
    done(&a);
    a = solve("vib-dft", "window", "rect", NULL);
    done(&a);
}

/* ==== GET and POST ================================================================== */

static void strip_elapsed(char *s)
{
    char *e = strstr(s, ",\"elapsed_us\":");
    if (e)
        *e = '\0';
}

/* The answer to a JSON body, elapsed_us cut off. */
static char *post(const char *id, const char *body, int *status)
{
    const mm_exercise *ex = need(id);
    mm_buf out;
    mm_buf_init(&out, MM_ANSWER_MAX);
    *status = mm_api_solve_json(ex, body, strlen(body), &out);
    char *s = mm_buf_take(&out, NULL);
    mm_buf_free(&out);
    assert_non_null(s);
    strip_elapsed(s);
    return s;
}

static void a_post_with_json_numbers_and_nested_arrays_should_equal_the_get_text(void **state)
{
    (void)state;
    need("num-linear-system");
    answer g = solve("num-linear-system", "A", "2,1,0;1,3,-1;0,-1,4", "b", "1,2,3.5", NULL);
    strip_elapsed(g.text);
    int status;
    char *p = post("num-linear-system", "{\"params\":{\"A\":[[2,1,0],[1,3,-1],[0,-1,4]],\"b\":[1,2,3.5]}}", &status);
    assert_int_equal(status, 200);
    if (strcmp(p, g.text) != 0)
        fail_msg("POST (JSON arrays) and GET (text) differ:\n%s\n%s", p, g.text);
    free(p);
    /* the same with the text forms inside the JSON */
    p = post("num-linear-system", "{\"params\":{\"A\":\"2,1,0;1,3,-1;0,-1,4\",\"b\":\"1,2,3.5\"}}", &status);
    assert_int_equal(status, 200);
    assert_string_equal(p, g.text);
    free(p);
    done(&g);

    if (mm_exercise_find("num-eigen")) {
        g = solve("num-eigen", "K", "300,-100;-100,100", "M", "2,0.5;0.5,1", NULL);
        strip_elapsed(g.text);
        p = post("num-eigen", "{\"params\":{\"K\":[[300,-100],[-100,100]],\"M\":[[2,0.5],[0.5,1]]}}", &status);
        assert_int_equal(status, 200);
        assert_string_equal(p, g.text);
        free(p);
        done(&g);
    }
    if (mm_exercise_find("vib-sdof-forced")) {
        g = solve("vib-sdof-forced", "m", "2", "k", "50", "c", "0.3", "F0", "3", "omega", "4.1", NULL);
        strip_elapsed(g.text);
        p = post("vib-sdof-forced", "{\"params\":{\"m\":2,\"k\":50,\"c\":0.3,\"F0\":3,\"omega\":4.1}}", &status);
        assert_int_equal(status, 200);
        assert_string_equal(p, g.text);
        free(p);
        done(&g);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_canonical_id_should_be_registered_or_listed_as_not_built_yet),
        cmocka_unit_test(parameters_should_have_the_api_names_kinds_and_defaults),
        cmocka_unit_test(outputs_at_the_defaults_should_have_the_api_names_and_columns),
        cmocka_unit_test(num_linear_system_should_give_x_the_2_norm_condition_number_and_the_residual),
        cmocka_unit_test(num_poly_roots_should_read_p_highest_power_first_and_list_re_and_im),
        cmocka_unit_test(num_polyfit_should_give_matlab_order_coefficients_and_the_rms_residual_over_n),
        cmocka_unit_test(num_nonlinear_roots_should_refine_to_an_absolute_tol_and_report_a_grid_root_once),
        cmocka_unit_test(num_eigen_should_solve_k_v_equals_lambda_m_v_with_omega_the_square_root),
        cmocka_unit_test(vib_sdof_free_should_give_omega_n_zeta_omega_d_and_the_regime),
        cmocka_unit_test(vib_sdof_forced_should_give_the_steady_amplitude_and_a_lag_in_0_to_pi),
        cmocka_unit_test(vib_sdof_forced_response_should_settle_on_x_cos_omega_t_minus_phase),
        cmocka_unit_test(vib_base_excitation_should_give_x_as_transmissibility_times_y),
        cmocka_unit_test(vib_coulomb_should_stop_where_the_piecewise_closed_form_stops),
        cmocka_unit_test(vib_coulomb_should_never_move_from_inside_the_friction_band),
        cmocka_unit_test(vib_fourier_series_should_give_the_coefficients_up_to_harmonic_terms),
        cmocka_unit_test(vib_fourier_series_overshoot_should_be_max_s_k_minus_a_and_approach_gibbs),
        cmocka_unit_test(vib_dft_should_give_the_single_sided_amplitude_of_the_defining_sum),
        cmocka_unit_test(vib_dft_should_read_a_bin_centred_sine_and_a_constant_at_their_amplitudes),
        cmocka_unit_test(vib_dft_should_accept_the_hann_window),
        cmocka_unit_test(a_post_with_json_numbers_and_nested_arrays_should_equal_the_get_text),
    };
    return cmocka_run_group_tests_name("api contract", tests, NULL, release_answers);
}
