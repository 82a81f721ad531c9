/* test_assign.c — assignments: variants from a seed, answers judged with
 * tolerances, significant figures and units (issue 17's hard cases). */
#include "mm_test.h"

#include <stdlib.h>
#include <string.h>

#include "mm_assign.h"

static const mm_quantity force = {1, 1, 1, {1, 1, -2, 0}, 1};
static const mm_quantity plain = {1, 1, 1, {0, 0, 0, 0}, 0};
static const mm_quantity angle = {1, 1, 1, {0, 0, 0, 1}, 1};

static mm_judgement judge(mm_rule r, const mm_quantity *dim, double expected, const char *given)
{
    mm_judgement j;
    mm_assign_judge(&r, dim, expected, given, &j);
    return j;
}

static void tolerances_should_hold_at_their_edge_and_convert_units(void **state)
{
    (void)state;
    mm_rule rel1 = {.rel = 0.01, .unit = "N"};
    assert_true(judge(rel1, &force, 100, "101 N").correct);          /* exactly on the edge */
    assert_true(judge(rel1, &force, 100, "99 N").correct);
    assert_false(judge(rel1, &force, 100, "101.0001 N").correct);
    assert_true(judge(rel1, &force, 100, "0.101 kN").correct);       /* the edge after a conversion */
    assert_true(judge(rel1, &force, 256.6, "0.2566 kN").correct);
    assert_true(judge(rel1, &force, -50, "-50.4 N").correct);        /* a negative answer */
    assert_false(judge(rel1, &force, -50, "50 N").correct);
    mm_rule kn = {.abs = 0.05, .unit = "kN"};                         /* absolute, in the asked unit */
    mm_judgement j = judge(kn, &force, 1234, "1.28 kN");
    assert_true(j.correct);
    check_rel(j.expected, 1.234, 1e-15, "expected in kN");
    check_rel(j.tolerance, 0.05, 0, "tolerance in kN");
    assert_false(judge(kn, &force, 1234, "1290 N").correct);
    mm_rule deg = {.abs = 0.5, .unit = "deg"};
    assert_true(judge(deg, &angle, M_PI / 4, "45.4 deg").correct);
    assert_true(judge(deg, &angle, M_PI / 4, "0.7854 rad").correct);
}

static void zero_answers_should_follow_the_written_rule(void **state)
{
    (void)state;
    mm_rule rel = {.rel = 0.01, .unit = "N"}, both = {.rel = 0.01, .abs = 1e-3, .unit = "N"};
    mm_judgement j = judge(rel, &force, 0, "0 N");
    assert_true(j.correct);
    assert_non_null(strstr(j.note, "relative tolerance allows only 0"));
    assert_false(judge(rel, &force, 0, "1e-9 N").correct);
    assert_true(judge(both, &force, 0, "0.0009 N").correct);
    mm_rule sig = {.sig = 3, .unit = "N"};
    assert_true(judge(sig, &force, 0, "0 N").correct);
    assert_false(judge(sig, &force, 0, "0.0001 N").correct);
}

static void significant_figures_should_round_half_away_from_zero(void **state)
{
    (void)state;
    mm_rule s3 = {.sig = 3, .unit = ""};
    assert_true(judge(s3, &plain, 1, "1.0000").correct);           /* both are 1.00 */
    assert_true(judge(s3, &plain, 1.0049, "1.00").correct);
    assert_false(judge(s3, &plain, 1.0049, "1.01").correct);
    assert_true(judge(s3, &plain, 1.0051, "1.005").correct);       /* 1.005 as typed rounds to 1.01 */
    assert_true(judge(s3, &plain, 0.0012345, "0.00123").correct);
    assert_true(judge(s3, &plain, 99.96, "100").correct);          /* 99.96 -> 100. (a carry) */
    assert_true(judge(s3, &plain, -2.3456, "-2.35").correct);      /* half away from zero, negative */
    assert_false(judge(s3, &plain, -2.3456, "2.35").correct);
    assert_true(judge(s3, &plain, 1.5e-7, "1.50e-7").correct);
    mm_rule s4kn = {.sig = 4, .unit = "kN"};
    assert_true(judge(s4kn, &force, 256.6, "256.6 N").correct);    /* converted by decimal shift */
    assert_true(judge(s4kn, &force, 256.6, "0.2566 kN").correct);
    assert_false(judge(s4kn, &force, 256.6, "0.2567 kN").correct);
    mm_rule s3n = {.sig = 3, .unit = "N"};
    assert_true(judge(s3n, &force, 1005.1, "1.005 kN").correct);   /* 1005 N rounds to 1010 N, no binary noise */
}

static void missing_or_wrong_units_should_be_errors_not_judgements(void **state)
{
    (void)state;
    mm_rule r = {.rel = 0.01, .unit = "N"};
    mm_judgement j = judge(r, &force, 100, "100");
    assert_false(j.correct);
    assert_non_null(strstr(j.error, "give the unit"));
    j = judge(r, &force, 100, "100 m");
    assert_false(j.correct);
    assert_non_null(strstr(j.error, "measures m"));
    j = judge(r, &force, 100, "a lot");
    assert_false(j.correct);
    assert_true(j.error[0] != '\0');
    mm_rule d = {.rel = 0.01, .unit = ""};
    assert_true(judge(d, &plain, 0.05, "5 %").correct);            /* a dimensionless answer in % */
}

/* ---- assignments on a real exercise ------------------------------------------------ */

static mm_assignment *load(const char *json, mm_buf *notes, int expect)
{
    cJSON *j = cJSON_Parse(json);
    assert_non_null(j);
    const mm_exercise *ex = mm_exercise_find(mm_assign_exercise_id(j));
    assert_non_null(ex);
    mm_assignment *a = NULL;
    mm_error err;
    int rc = mm_assign_load(j, ex, &a, notes, &err);
    if (rc != expect)
        fail_msg("load gave %d (%s), expected %d", rc, err.msg, expect);
    cJSON_Delete(j);
    return a;
}

static const char *const forced =
    "{\"name\":\"hw1\",\"exercise\":\"vib-sdof-forced\","
    "\"params\":{\"m\":{\"min\":0.5,\"max\":5,\"step\":0.5},\"k\":{\"min\":50,\"max\":500,\"sig\":2},"
    "\"c\":{\"values\":[1,2,4]},\"t_end\":2},"
    "\"ask\":[{\"name\":\"X\",\"unit\":\"mm\",\"rel\":0.01},{\"name\":\"phase\",\"unit\":\"deg\",\"abs\":0.5},"
    "{\"name\":\"omega_n\",\"sig\":3}]}";

static void variants_should_be_pure_functions_of_assignment_and_student(void **state)
{
    (void)state;
    mm_buf notes, v1, v2, v3;
    mm_buf_init(&notes, 1 << 16);
    mm_buf_init(&v1, 1 << 16);
    mm_buf_init(&v2, 1 << 16);
    mm_buf_init(&v3, 1 << 16);
    mm_assignment *a = load(forced, &notes, MM_OK);
    check_rel(mm_assign_set_size(a), 10 * (50 + 41) * 3, 0, "10 masses x (50..99, 100..500 by 10) x 3 dampers");
    assert_int_equal(mm_assign_variant_json(a, "alice", &v1), 200);
    assert_int_equal(mm_assign_variant_json(a, "alice", &v2), 200);
    assert_string_equal(v1.p, v2.p);
    assert_int_equal(mm_assign_variant_json(a, "bob", &v3), 200);
    assert_string_not_equal(v1.p, v3.p);
    cJSON *d = cJSON_Parse(v1.p);
    const cJSON *p = cJSON_GetObjectItem(d, "params");
    double m = cJSON_GetObjectItem(p, "m")->valuedouble, k = cJSON_GetObjectItem(p, "k")->valuedouble;
    assert_true(m >= 0.5 && m <= 5 && fmod(m, 0.5) == 0);
    char ks[32];
    snprintf(ks, sizeof ks, "%.1e", k);
    check_rel(strtod(ks, NULL), k, 0, "k has two significant figures");
    check_rel(cJSON_GetObjectItem(p, "t_end")->valuedouble, 2, 0, "a fixed value");
    assert_int_equal(cJSON_GetArraySize(cJSON_GetObjectItem(d, "asked")), 3);
    cJSON_Delete(d);
    /* the same student's variant is the one checked: right answers score 3 */
    mm_buf ans, res;
    mm_buf_init(&ans, 1 << 22);
    mm_buf_init(&res, 1 << 16);
    mm_input in[MM_MAX_PARAMS];
    char (*text)[MM_ASSIGN_TEXT] = malloc(MM_MAX_PARAMS * sizeof *text);
    int n;
    mm_error err;
    assert_int_equal(mm_assign_variant(a, "alice", in, text, &n, &err), MM_OK);
    assert_int_equal(mm_api_solve(mm_assign_exercise(a), in, n, &ans), 200);
    cJSON *sol = cJSON_Parse(ans.p);
    double X = 0, phase = 0, wn = 0;
    const cJSON *s;
    cJSON_ArrayForEach(s, cJSON_GetObjectItem(sol, "scalars")) {
        const char *nm = cJSON_GetObjectItem(s, "name")->valuestring;
        double v = cJSON_GetObjectItem(s, "value")->valuedouble;
        if (!strcmp(nm, "X")) X = v;
        if (!strcmp(nm, "phase")) phase = v;
        if (!strcmp(nm, "omega_n")) wn = v;
    }
    char body[512];
    snprintf(body, sizeof body, "{\"student\":\"alice\",\"answers\":{\"X\":\"%.6g m\",\"phase\":\"%.4f rad\","
             "\"omega_n\":\"%.3g rad/s\"}}", X, phase, wn);
    assert_int_equal(mm_assign_check_json(a, body, strlen(body), &res), 200);
    cJSON *r = cJSON_Parse(res.p);
    assert_int_equal(cJSON_GetObjectItem(r, "score")->valueint, 3);
    cJSON_Delete(r);
    snprintf(body, sizeof body, "{\"student\":\"alice\",\"answers\":{\"X\":\"%.6g\",\"phase\":\"%.4f N\"}}", X, phase);
    assert_int_equal(mm_assign_check_json(a, body, strlen(body), &res), 200);
    r = cJSON_Parse(res.p);
    assert_int_equal(cJSON_GetObjectItem(r, "score")->valueint, 0);
    const cJSON *first = cJSON_GetArrayItem(cJSON_GetObjectItem(r, "results"), 0);
    assert_non_null(strstr(cJSON_GetObjectItem(first, "error")->valuestring, "unit"));
    cJSON_Delete(r);
    assert_int_equal(mm_assign_check_json(a, "{\"answers\":{}}", 14, &res), 400);
    cJSON_Delete(sol);
    free(text);
    mm_buf_free(&ans);
    mm_buf_free(&res);
    mm_assign_free(a);
    mm_buf_free(&notes);
    mm_buf_free(&v1);
    mm_buf_free(&v2);
    mm_buf_free(&v3);
}

static void a_roster_should_get_distinct_variants_and_small_sets_a_warning(void **state)
{
    (void)state;
    /* 300 students on a set of 50 values: duplicates unavoidable, said at load */
    mm_buf notes;
    mm_buf_init(&notes, 1 << 16);
    mm_assignment *a = load("{\"name\":\"small\",\"exercise\":\"vib-sdof-forced\","
                            "\"params\":{\"m\":{\"min\":0.1,\"max\":5,\"step\":0.1}},\"class_size\":300,"
                            "\"ask\":[{\"name\":\"X\",\"rel\":0.01}]}", &notes, MM_OK);
    assert_non_null(strstr(notes.p, "50 variants for a class of 300: duplicates are unavoidable"));
    mm_assign_free(a);
    /* a roster of 40 on those 50 values: all distinct */
    char json[8192];
    size_t len = (size_t)snprintf(json, sizeof json, "{\"name\":\"roster\",\"exercise\":\"vib-sdof-forced\","
                                  "\"params\":{\"m\":{\"min\":0.1,\"max\":5,\"step\":0.1}},"
                                  "\"ask\":[{\"name\":\"X\",\"rel\":0.01}],\"students\":[");
    for (int s = 0; s < 40; s++)
        len += (size_t)snprintf(json + len, sizeof json - len, "%s\"s%03d\"", s ? "," : "", s);
    snprintf(json + len, sizeof json - len, "]}");
    mm_buf_reset(&notes);
    a = load(json, &notes, MM_OK);
    double seen[40];
    for (int s = 0; s < 40; s++) {
        char id[8];
        snprintf(id, sizeof id, "s%03d", s);
        mm_input in[MM_MAX_PARAMS];
        char (*text)[MM_ASSIGN_TEXT] = malloc(MM_MAX_PARAMS * sizeof *text);
        int n;
        mm_error err;
        assert_int_equal(mm_assign_variant(a, id, in, text, &n, &err), MM_OK);
        seen[s] = strtod(text[0], NULL);
        for (int o = 0; o < s; o++)
            if (seen[o] == seen[s])
                fail_msg("students %d and %d share m = %g", o, s, seen[s]);
        free(text);
    }
    mm_assign_free(a);
    mm_buf_free(&notes);
}

static void bad_assignments_should_be_refused_with_the_reason(void **state)
{
    (void)state;
    mm_buf notes;
    mm_buf_init(&notes, 1 << 16);
    static const char *const bad[] = {
        "{\"name\":\"x\",\"exercise\":\"vib-sdof-forced\",\"ask\":[{\"name\":\"nothing\",\"rel\":0.1}]}",
        "{\"name\":\"x\",\"exercise\":\"vib-sdof-forced\",\"ask\":[{\"name\":\"X\",\"unit\":\"N\",\"rel\":0.1}]}",
        "{\"name\":\"x\",\"exercise\":\"vib-sdof-forced\",\"ask\":[{\"name\":\"X\"}]}",
        "{\"name\":\"x\",\"exercise\":\"vib-sdof-forced\",\"params\":{\"m\":{\"min\":0,\"max\":5,\"step\":1}},"
        "\"ask\":[{\"name\":\"X\",\"rel\":0.1}]}",
        "{\"name\":\"x\",\"exercise\":\"vib-sdof-forced\",\"params\":{\"zz\":1},\"ask\":[{\"name\":\"X\",\"rel\":0.1}]}",
        "{\"name\":\"x\",\"exercise\":\"vib-sdof-forced\",\"ask\":[]}",
        "{\"name\":\"x\",\"exercise\":\"vib-sdof-forced\",\"extra\":1,\"ask\":[{\"name\":\"X\",\"rel\":0.1}]}",
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        assert_null(load(bad[i], &notes, MM_EVALUE));
    mm_buf_free(&notes);
}

static void the_instructor_should_get_a_class_csv_and_an_answer_key(void **state)
{
    (void)state;
    mm_buf notes, csv, key;
    mm_buf_init(&notes, 1 << 16);
    mm_buf_init(&csv, 1 << 20);
    mm_buf_init(&key, 1 << 22);
    mm_assignment *a = load(forced, &notes, MM_OK);
    const char *list = "id,name\nalice,Alice A.\n\n\"bob\",Bob B.\r\ncarol\n";
    assert_int_equal(mm_assign_csv(a, list, strlen(list), &csv), 200);
    /* a header and three rows; each row's X agrees with the key for that student */
    int rows = 0;
    for (const char *p = csv.p; (p = strstr(p, "\r\n")); p += 2)
        rows++;
    assert_int_equal(rows, 4);
    assert_non_null(strstr(csv.p, "student,m,k,c,F0,omega,x0,v0,t_end,points,integrator,X [mm],phase [deg],omega_n [rad/s]\r\n"));
    assert_int_equal(mm_assign_key_json(a, "bob", &key), 200);
    cJSON *k = cJSON_Parse(key.p);
    double X = cJSON_GetObjectItem(cJSON_GetArrayItem(cJSON_GetObjectItem(k, "expected"), 0), "value")->valuedouble;
    const char *row = strstr(csv.p, "\r\nbob,");
    assert_non_null(row);
    const char *last3 = row + strcspn(row + 2, "\r") + 2;            /* end of bob's row */
    int commas = 0;
    const char *xfield = last3;
    while (xfield > row && commas < 3)
        if (*--xfield == ',')
            commas++;
    check_rel(strtod(xfield + 1, NULL), X, 0, "the CSV and the key give the same X (mm)");
    assert_non_null(cJSON_GetObjectItem(cJSON_GetObjectItem(k, "answer"), "scalars"));
    cJSON_Delete(k);
    assert_int_equal(mm_assign_csv(a, "id\n", 3, &csv), 400);
    mm_assign_free(a);
    mm_buf_free(&notes);
    mm_buf_free(&csv);
    mm_buf_free(&key);
}

/* Every exercise with declared answers can be assigned: an assignment that
 * asks every answer, the key's expected values written back with their
 * units as a student would type them, and the check finds them all right. */
static void every_exercise_with_answers_should_be_assignable(void **state)
{
    (void)state;
    int assigned = 0;
    for (int i = 0; i < mm_exercise_count; i++) {
        const mm_exercise *ex = mm_exercises[i];
        cJSON *j = cJSON_CreateObject(), *ask = cJSON_CreateArray();
        cJSON_AddStringToObject(j, "name", "all");
        cJSON_AddStringToObject(j, "exercise", ex->id);
        for (int k = 0; k < ex->n_outputs; k++) {
            const mm_output *o = &ex->outputs[k];
            if (o->kind != MM_OUT_SCALAR || !(o->flags & MM_ANSWER) || strchr(o->name, '%') ||
                cJSON_GetArraySize(ask) >= MM_ASSIGN_MAX_ASK)
                continue;
            cJSON *q = cJSON_CreateObject();
            cJSON_AddStringToObject(q, "name", o->name);
            cJSON_AddNumberToObject(q, "rel", 1e-9);
            cJSON_AddItemToArray(ask, q);
        }
        cJSON_AddItemToObject(j, "ask", ask);
        if (cJSON_GetArraySize(ask) == 0) {
            cJSON_Delete(j);
            continue;
        }
        mm_assignment *a = NULL;
        mm_error err;
        mm_buf notes, key, body, out;
        mm_buf_init(&notes, 1 << 16);
        mm_buf_init(&key, 1 << 24);
        mm_buf_init(&body, 1 << 16);
        mm_buf_init(&out, 1 << 20);
        if (mm_assign_load(j, ex, &a, &notes, &err) != MM_OK)
            fail_msg("%s: its answers cannot be asked: %s", ex->id, err.msg);
        assert_int_equal(mm_assign_key_json(a, "s1", &key), 200);
        cJSON *k = cJSON_Parse(key.p);
        mm_buf_puts(&body, "{\"student\":\"s1\",\"answers\":{");
        const cJSON *x;
        int n = 0;
        cJSON_ArrayForEach(x, cJSON_GetObjectItem(k, "expected")) {
            if (!cJSON_IsNumber(cJSON_GetObjectItem(x, "value")))
                continue;                   /* not given for this variant (another case of the exercise) */
            char text[160];
            snprintf(text, sizeof text, "%.17g %s", cJSON_GetObjectItem(x, "value")->valuedouble,
                     cJSON_GetObjectItem(x, "unit")->valuestring);
            mm_buf_puts(&body, n++ ? "," : "");
            mm_buf_str(&body, cJSON_GetObjectItem(x, "name")->valuestring);
            mm_buf_char(&body, ':');
            mm_buf_str(&body, text);
        }
        mm_buf_puts(&body, "}}");
        assert_int_equal(mm_assign_check_json(a, body.p, body.len, &out), 200);
        cJSON *c = cJSON_Parse(out.p);
        if (cJSON_GetObjectItem(c, "score")->valuedouble != n)
            fail_msg("%s: its own expected answers judged %g of %d right: %.3000s", ex->id,
                     cJSON_GetObjectItem(c, "score")->valuedouble, n, out.p);
        assigned++;
        cJSON_Delete(c);
        cJSON_Delete(k);
        cJSON_Delete(j);
        mm_assign_free(a);
        mm_buf_free(&notes);
        mm_buf_free(&key);
        mm_buf_free(&body);
        mm_buf_free(&out);
    }
    print_message("%d exercises with declared answers, each assignable\n", assigned);
    assert_true(assigned >= 10);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(tolerances_should_hold_at_their_edge_and_convert_units),
        cmocka_unit_test(zero_answers_should_follow_the_written_rule),
        cmocka_unit_test(significant_figures_should_round_half_away_from_zero),
        cmocka_unit_test(missing_or_wrong_units_should_be_errors_not_judgements),
        cmocka_unit_test(variants_should_be_pure_functions_of_assignment_and_student),
        cmocka_unit_test(a_roster_should_get_distinct_variants_and_small_sets_a_warning),
        cmocka_unit_test(bad_assignments_should_be_refused_with_the_reason),
        cmocka_unit_test(the_instructor_should_get_a_class_csv_and_an_answer_key),
        cmocka_unit_test(every_exercise_with_answers_should_be_assignable),
    };
    return cmocka_run_group_tests_name("assign", tests, NULL, NULL);
}
