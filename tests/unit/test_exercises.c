/* test_exercises.c — every exercise of the registry through the real
 * pipeline (text parameters -> validation -> solve -> JSON), read back by
 * cJSON:
 *   - at its defaults: 200, every check passed;
 *   - at >= 50 random draws inside its limits (seeded; draws its own `check`
 *     refuses are counted and skipped): 200, every check passed.  An array
 *     parameter whose scaled draws the exercise's `check` refuses three
 *     times in a row (joint numbers of a truss scaled by 1.3 are no joint
 *     numbers) keeps its default from then on, so that the other
 *     parameters are still drawn;
 *   - each number parameter just outside its limits: 400 out_of_range naming it;
 *   - an unknown parameter: 400 unknown_param;
 *   - the same request twice: byte-identical JSON but for elapsed_us;
 *   - the same request by GET (text) and by POST (JSON body): identical.
 * MM_SEED overrides the seed; MM_DRAWS the number of draws. */
#include "mm_test.h"

#include <cJSON.h>
#include <stdlib.h>
#include <string.h>

#include "mm_api.h"
#include "mm_draw.h"
#include "mm_dtoa.h"
#include "mm_json.h"
#include "mm_params.h"
#include "mm_result_impl.h"

/* ---- the seeded generator: mm_draw.h (the product's) ------------------------ */

static mm_rng rng;

/* ---- requests ------------------------------------------------------------------ */

typedef struct request {
    mm_input in[MM_MAX_PARAMS];
    char text[MM_MAX_PARAMS][4096];
    int n;
} request;

static void put(request *r, const char *name, const char *text)
{
    snprintf(r->text[r->n], sizeof r->text[r->n], "%s", text);
    r->in[r->n] = (mm_input){name, r->text[r->n], strlen(name), strlen(r->text[r->n])};
    r->n++;
}

static void num_text(double v, char *buf)
{
    mm_dtoa(v, buf);
}

/* A value drawn inside p's limits (mm_draw.h: log-uniform over wide
 * positive ranges, uniform otherwise; arrays keep the default's shape, each
 * element scaled by a factor in [0.5, 1.5], symmetric matrices stay
 * symmetric, clamped). */
static void draw(const mm_param *p, char *out, size_t size, mm_result *arena)
{
    (void)arena;
    assert_int_equal(mm_draw_text(p, &rng, out, size), MM_OK);
}

/* Solve and parse; returns the HTTP status and the parsed document. */
static int run(const mm_exercise *ex, const request *r, cJSON **doc, char **text)
{
    mm_buf out;
    mm_buf_init(&out, MM_ANSWER_MAX);
    int status = mm_api_solve(ex, r->in, r->n, &out);
    *doc = cJSON_Parse(out.p);
    if (!*doc)
        fail_msg("%s: the answer is not JSON: %.200s", ex->id, out.p ? out.p : "(null)");
    if (text)
        *text = mm_buf_take(&out, NULL);
    mm_buf_free(&out);
    return status;
}

/* Every check passed?  Prints the first failure. */
static int all_checks_pass(const mm_exercise *ex, const cJSON *doc, const char *what)
{
    const cJSON *checks = cJSON_GetObjectItem(doc, "checks");
    const cJSON *c;
    int ok = 1;
    cJSON_ArrayForEach(c, checks) {
        if (!cJSON_IsTrue(cJSON_GetObjectItem(c, "passed"))) {
            char *s = cJSON_PrintUnformatted(c);
            print_error("%s (%s): check failed: %s\n", ex->id, what, s);
            free(s);
            ok = 0;
        }
    }
    return ok;
}

/* The largest error / tolerance of the checks of an answer (and which). */
static void worst_check(const cJSON *doc, double *worst, char *name, size_t size)
{
    const cJSON *c;
    cJSON_ArrayForEach(c, cJSON_GetObjectItem(doc, "checks")) {
        const cJSON *k = cJSON_GetObjectItem(c, "tolerance_kind");
        int rel = cJSON_IsString(k) && strcmp(k->valuestring, "relative") == 0;
        const cJSON *e = cJSON_GetObjectItem(c, rel ? "rel_error" : "abs_error"), *t = cJSON_GetObjectItem(c, "tolerance");
        if (!cJSON_IsNumber(e) || !cJSON_IsNumber(t) || !(t->valuedouble > 0))
            continue;
        double r = e->valuedouble / t->valuedouble;
        if (r > *worst) {
            *worst = r;
            snprintf(name, size, "%.60s", cJSON_GetObjectItem(c, "name")->valuestring);
        }
    }
}

/* Is `name` a declared output of kind `kind`, member of a family included? */
static int declared(const mm_exercise *ex, mm_output_kind kind, const char *name)
{
    for (int i = 0; i < ex->n_outputs; i++) {
        const mm_output *o = &ex->outputs[i];
        if (o->kind != kind)
            continue;
        for (int k = 0; k < mm_output_count(o); k++) {
            char member[160];
            mm_output_member(o, mm_output_index(o, k), member, sizeof member);
            if (strcmp(member, name) == 0)
                return 1;
        }
    }
    return 0;
}

/* An answer carries only outputs its exercise declares (API.md
 * "Additions": outputs are declared, not discovered), each with the
 * declared label and unit; scalars say how accurate they are. */
static int only_declared_outputs(const mm_exercise *ex, const cJSON *doc, const char *what)
{
    if (ex->n_outputs == 0)              /* not converted yet: the transition */
        return 1;
    static const struct { const char *key; mm_output_kind kind; } lists[] = {
        {"scalars", MM_OUT_SCALAR}, {"series", MM_OUT_SERIES}, {"tables", MM_OUT_TABLE},
    };
    int ok = 1;
    for (size_t l = 0; l < sizeof lists / sizeof lists[0]; l++) {
        const cJSON *item;
        cJSON_ArrayForEach(item, cJSON_GetObjectItem(doc, lists[l].key)) {
            const cJSON *name = cJSON_GetObjectItem(item, "name");
            if (!cJSON_IsString(name) || !declared(ex, lists[l].kind, name->valuestring)) {
                print_error("%s (%s): %s '%s' is not declared in its outputs\n", ex->id, what,
                            lists[l].key, cJSON_IsString(name) ? name->valuestring : "?");
                ok = 0;
            }
        }
    }
    int anim = 0;
    for (int i = 0; i < ex->n_outputs; i++)
        anim |= ex->outputs[i].kind == MM_OUT_ANIMATION;
    if (cJSON_GetObjectItem(doc, "animation") && !anim) {
        print_error("%s (%s): an animation that is not declared\n", ex->id, what);
        ok = 0;
    }
    return ok;
}

static const char *error_code(const cJSON *doc, const char **param)
{
    const cJSON *e = cJSON_GetObjectItem(doc, "error");
    const cJSON *c = cJSON_GetObjectItem(e, "code");
    const cJSON *p = cJSON_GetObjectItem(e, "param");
    *param = cJSON_IsString(p) ? p->valuestring : "";
    return cJSON_IsString(c) ? c->valuestring : "";
}

/* ---- the tests ---------------------------------------------------------------- */

static void every_exercise_should_pass_its_checks_at_the_defaults(void **state)
{
    (void)state;
    assert_true(mm_exercise_count > 0);
    for (int i = 0; i < mm_exercise_count; i++) {
        const mm_exercise *ex = mm_exercises[i];
        request r = {.n = 0};
        cJSON *doc;
        int status = run(ex, &r, &doc, NULL);
        if (status != 200) {
            char *s = cJSON_PrintUnformatted(doc);
            fail_msg("%s at its defaults: status %d: %s", ex->id, status, s);
        }
        assert_true(cJSON_GetArraySize(cJSON_GetObjectItem(doc, "checks")) > 0);
        assert_true(all_checks_pass(ex, doc, "defaults"));
        assert_true(only_declared_outputs(ex, doc, "defaults"));
        cJSON_Delete(doc);
    }
}

/* A plot needs no more points than its pixels: every default answer fits
 * in 64 KB before compression (issue 16's figure), animations included. */
static void every_default_answer_should_fit_in_64_kb(void **state)
{
    (void)state;
    int over = 0;
    for (int i = 0; i < mm_exercise_count; i++) {
        const mm_exercise *ex = mm_exercises[i];
        request r = {.n = 0};
        cJSON *doc;
        char *text;
        run(ex, &r, &doc, &text);
        size_t len = text ? strlen(text) : 0;
        if (len > 64 * 1024) {
            print_error("%s: its default answer is %zu bytes (at most 65536)\n", ex->id, len);
            over++;
        }
        free(text);
        cJSON_Delete(doc);
    }
    assert_int_equal(over, 0);
}

static void every_exercise_should_pass_its_checks_at_random_parameters(void **state)
{
    (void)state;
    const char *seed = getenv("MM_SEED"), *draws_env = getenv("MM_DRAWS");
    int want = draws_env ? atoi(draws_env) : 50;
    int failures = 0;
    for (int i = 0; i < mm_exercise_count; i++) {
        const mm_exercise *ex = mm_exercises[i];
        mm_rng_seed(&rng, seed ? strtoull(seed, NULL, 10) : 0x9E3779B97F4A7C15ULL ^ (unsigned long long)(i + 1));
        int accepted = 0, refused = 0, attempts = 0, keep[MM_MAX_PARAMS] = {0}, streak[MM_MAX_PARAMS] = {0};
        long long worst_us = 0;
        double worst = 0;
        char worst_name[64] = "";
        while (accepted < want && attempts < 20 * want) {
            attempts++;
            mm_result arena;
            mm_result_init(&arena, 1 << 20);
            request r = {.n = 0};
            char text[4096];
            for (int k = 0; k < ex->n_params; k++) {
                draw(&ex->params[k], text, sizeof text, &arena);
                put(&r, ex->params[k].name, keep[k] ? ex->params[k].def_text : text);
            }
            mm_result_release(&arena);
            cJSON *doc;
            int status = run(ex, &r, &doc, NULL);
            const char *param, *code = error_code(doc, &param);
            int names_a_param = 0;             /* a refusal names one of the exercise's parameters */
            for (int k = 0; param && k < ex->n_params; k++)
                names_a_param |= strcmp(ex->params[k].name, param) == 0;
            if (status == 400 && ex->check && strcmp(code, "out_of_range") == 0 && names_a_param) {
                refused++;                          /* a joint limit said no */
                for (int k = 0; k < ex->n_params; k++)
                    if (strcmp(ex->params[k].name, param) == 0 &&
                        (ex->params[k].kind == MM_MATRIX || ex->params[k].kind == MM_VECTOR) &&
                        ++streak[k] >= 3)
                        keep[k] = 1;
            } else if (status != 200 || !all_checks_pass(ex, doc, "random") ||
                       !only_declared_outputs(ex, doc, "random")) {
                char *s = cJSON_PrintUnformatted(doc);
                print_error("%s: status %d for", ex->id, status);
                for (int k = 0; k < r.n; k++)
                    print_error(" %s=%s", r.in[k].name, r.text[k]);
                print_error("\n   -> %.400s\n", s);
                free(s);
                failures++;
                accepted++;
            } else {
                accepted++;
                memset(streak, 0, sizeof streak);
                long long us = (long long)cJSON_GetObjectItem(doc, "elapsed_us")->valuedouble;
                if (us > worst_us)
                    worst_us = us;
                worst_check(doc, &worst, worst_name, sizeof worst_name);
            }
            cJSON_Delete(doc);
        }
        print_message("%-26s %3d draws solved, %3d refused by joint limits, slowest %lld us, "
                      "worst check %.2f of its tolerance (%s)\n", ex->id, accepted, refused, worst_us, worst,
                      worst_name);
        if (accepted < want)
            fail_msg("%s: only %d of %d attempts were inside its joint limits", ex->id, accepted, attempts);
    }
    assert_int_equal(failures, 0);
}

static void values_outside_the_limits_should_be_refused_naming_the_parameter(void **state)
{
    (void)state;
    for (int i = 0; i < mm_exercise_count; i++) {
        const mm_exercise *ex = mm_exercises[i];
        for (int k = 0; k < ex->n_params; k++) {
            const mm_param *p = &ex->params[k];
            if (p->kind != MM_REAL && p->kind != MM_INT)
                continue;
            double outside[2] = {p->min - fmax(1.0, fabs(p->min)), p->max + fmax(1.0, fabs(p->max))};
            for (int side = 0; side < 2; side++) {
                request r = {.n = 0};
                char num[MM_DTOA_BUFSIZE];
                num_text(outside[side], num);
                put(&r, p->name, num);
                cJSON *doc;
                int status = run(ex, &r, &doc, NULL);
                const char *param, *code = error_code(doc, &param);
                if (status != 400 || strcmp(code, "out_of_range") || strcmp(param, p->name))
                    fail_msg("%s: %s=%s gave %d %s (param '%s')", ex->id, p->name, num, status, code, param);
                cJSON_Delete(doc);
            }
        }
        request r = {.n = 0};
        put(&r, "no_such_parameter", "1");
        cJSON *doc;
        int status = run(ex, &r, &doc, NULL);
        const char *param, *code = error_code(doc, &param);
        assert_int_equal(status, 400);
        assert_string_equal(code, "unknown_param");
        cJSON_Delete(doc);
    }
}

/* The answer without its "elapsed_us" tail. */
static void strip_elapsed(char *s)
{
    char *e = strstr(s, ",\"elapsed_us\":");
    if (e)
        *e = '\0';
}

static void answers_should_be_deterministic_and_the_same_by_get_and_post(void **state)
{
    (void)state;
    for (int i = 0; i < mm_exercise_count; i++) {
        const mm_exercise *ex = mm_exercises[i];
        /* defaults given explicitly: as text (GET) and as a JSON body (POST) */
        mm_result arena;
        mm_result_init(&arena, 1 << 20);
        request r = {.n = 0};
        cJSON *body = cJSON_CreateObject(), *ps = cJSON_AddObjectToObject(body, "params");
        for (int k = 0; k < ex->n_params; k++) {
            const mm_param *p = &ex->params[k];
            char text[4096];
            mm_value v;
            mm_error err;
            assert_int_equal(mm_param_default(p, &v, &arena, &err), MM_OK);
            if (p->kind == MM_REAL || p->kind == MM_INT) {
                num_text(v.x, text);
                cJSON_AddNumberToObject(ps, p->name, v.x);
            } else if (p->kind == MM_VECTOR || p->kind == MM_MATRIX) {
                snprintf(text, sizeof text, "%s", p->def_text);
                cJSON *rows = cJSON_AddArrayToObject(ps, p->name);
                for (int a = 0; a < v.rows; a++) {
                    cJSON *row = p->kind == MM_MATRIX ? cJSON_CreateArray() : rows;
                    for (int b = 0; b < v.cols; b++)
                        cJSON_AddItemToArray(row, cJSON_CreateNumber(v.data[a * v.cols + b]));
                    if (p->kind == MM_MATRIX)
                        cJSON_AddItemToArray(rows, row);
                }
            } else {
                snprintf(text, sizeof text, "%s", v.text);
                cJSON_AddStringToObject(ps, p->name, v.text);
            }
            put(&r, p->name, text);
        }
        mm_result_release(&arena);

        cJSON *d1, *d2;
        char *t1, *t2;
        assert_int_equal(run(ex, &r, &d1, &t1), 200);
        assert_int_equal(run(ex, &r, &d2, &t2), 200);
        strip_elapsed(t1);
        strip_elapsed(t2);
        if (strcmp(t1, t2) != 0)
            fail_msg("%s: two identical requests gave different answers", ex->id);

        char *json = cJSON_PrintUnformatted(body);
        mm_buf out;
        mm_buf_init(&out, MM_ANSWER_MAX);
        assert_int_equal(mm_api_solve_json(ex, json, strlen(json), &out), 200);
        strip_elapsed(out.p);
        if (strcmp(out.p, t1) != 0)
            fail_msg("%s: GET and POST answers differ", ex->id);
        mm_buf_free(&out);
        free(json);
        cJSON_Delete(body);
        cJSON_Delete(d1);
        cJSON_Delete(d2);
        free(t1);
        free(t2);
    }
}

static void metadata_should_list_params_and_outputs_for_every_exercise(void **state)
{
    (void)state;
    mm_error err;
    mm_api *api = mm_api_alloc(".", &err);
    if (!api)
        fail_msg("mm_api_alloc: %s", err.msg);
    size_t len;
    cJSON *cat = cJSON_Parse(mm_api_catalog(api, &len));
    assert_int_equal(cJSON_GetArraySize(cat), mm_exercise_count);
    for (int i = 0; i < mm_exercise_count; i++) {
        const mm_exercise *ex = mm_exercises[i];
        cJSON *meta = cJSON_Parse(mm_api_meta(api, ex->id, &len));
        assert_non_null(meta);
        assert_int_equal(cJSON_GetArraySize(cJSON_GetObjectItem(meta, "params")), ex->n_params);
        assert_true(cJSON_GetArraySize(cJSON_GetObjectItem(meta, "outputs")) > 0);
        const cJSON *html = cJSON_GetObjectItem(meta, "theory_html");
        if (!cJSON_IsString(html) || strlen(html->valuestring) < 200)
            fail_msg("%s: no theory text (looked for %s)", ex->id, ex->theory);
        /* no control character but the newline: a TeX "\\approx" or "\\tfrac"
           written through a string escape becomes BEL or TAB + "frac" */
        for (const char *c = html->valuestring; *c; c++)
            if ((unsigned char)*c < 0x20 && *c != '\n')
                fail_msg("%s: control character 0x%02x in the theory text (%s) near \"%.40s\"", ex->id, *c, ex->theory,
                         c - html->valuestring > 20 ? c - 20 : html->valuestring);
        cJSON_Delete(meta);
    }
    cJSON_Delete(cat);
    mm_api_free(api);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_exercise_should_pass_its_checks_at_the_defaults),
        cmocka_unit_test(every_default_answer_should_fit_in_64_kb),
        cmocka_unit_test(every_exercise_should_pass_its_checks_at_random_parameters),
        cmocka_unit_test(values_outside_the_limits_should_be_refused_naming_the_parameter),
        cmocka_unit_test(answers_should_be_deterministic_and_the_same_by_get_and_post),
        cmocka_unit_test(metadata_should_list_params_and_outputs_for_every_exercise),
    };
    return cmocka_run_group_tests_name("exercises", tests, NULL, NULL);
}
