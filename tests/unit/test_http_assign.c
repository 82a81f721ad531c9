/* test_http_assign.c — the assignment and script routes over HTTP: the
 * built-in course's example assignments, a variant per student, answers
 * judged against the capstan equation T2 = T1 e^(mu theta) worked out here
 * (not by the server), the instructor's key and class sheet behind their
 * key, and the Octave script of an exercise. */
#include "mm_test.h"

#include <cJSON.h>
#include <math.h>

#include "mm_server_fixture.h"

static mm_fixture builtin, keyed;
static char course_path[64];

static const char COURSE[] =
    "{\"title\": \"Test course\",\n"
    " \"assignments\": [{\"name\": \"belt\", \"title\": \"Belt\", \"exercise\": \"sta-belt-friction\",\n"
    "   \"params\": {\"T1\": {\"min\": 50, \"max\": 500, \"step\": 10}, \"mu\": {\"values\": [0.2, 0.3]}},\n"
    "   \"ask\": [{\"name\": \"T2\", \"unit\": \"kN\", \"rel\": 0.01}],\n"
    "   \"instructor_key\": \"correct-horse\"}]}\n";

static int setup(void **state)
{
    (void)state;
    snprintf(course_path, sizeof course_path, "/tmp/mm-assign-test-XXXXXX");
    int fd = mkstemp(course_path);
    if (fd < 0 || write(fd, COURSE, sizeof COURSE - 1) != (ssize_t)(sizeof COURSE - 1))
        return -1;
    close(fd);
    const char *extra[] = {"--course", course_path, NULL};
    if (mm_fixture_start(&builtin, NULL) != 0)
        return -1;
    return mm_fixture_start(&keyed, extra);
}

static int teardown(void **state)
{
    (void)state;
    unlink(course_path);
    int a = mm_fixture_stop(&builtin), b = mm_fixture_stop(&keyed);
    return a == 0 && b == 0 ? 0 : -1;
}

static cJSON *request(const mm_fixture *f, const char *method, const char *path, const char *body,
                      long want_status)
{
    mm_reply r;
    assert_int_equal(mm_http(f, method, path, body, body ? strlen(body) : 0, &r), 0);
    if (r.status != want_status)
        fail_msg("%s %s: status %ld, wanted %ld: %.300s", method ? method : "GET", path, r.status,
                 want_status, r.body);
    cJSON *j = cJSON_Parse(r.body);
    if (!j)
        fail_msg("%s: not JSON: %.300s", path, r.body);
    mm_reply_free(&r);
    return j;
}

static double num(const cJSON *o, const char *name)
{
    const cJSON *v = cJSON_GetObjectItem(o, name);
    if (!cJSON_IsNumber(v))
        fail_msg("no number %s", name);
    return v->valuedouble;
}

/* T2 of a variant of sta-belt-friction with a flat belt (beta = pi/2). */
static double capstan(const cJSON *variant)
{
    const cJSON *p = cJSON_GetObjectItem(variant, "params");
    assert_true(fabs(num(p, "beta") - M_PI / 2) < 1e-15);
    return num(p, "T1") * exp(num(p, "mu") * num(p, "theta"));
}

static void the_builtin_course_should_list_example_assignments(void **state)
{
    (void)state;
    cJSON *list = request(&builtin, NULL, "/api/assignments", NULL, 200);
    assert_true(cJSON_GetArraySize(list) >= 1);
    const cJSON *a;
    cJSON_ArrayForEach(a, list) {
        assert_true(cJSON_IsString(cJSON_GetObjectItem(a, "title")));
        char path[256];
        snprintf(path, sizeof path, "/api/exercises/%s", cJSON_GetObjectItem(a, "exercise")->valuestring);
        cJSON_Delete(request(&builtin, NULL, path, NULL, 200));
        snprintf(path, sizeof path, "/api/assignments/%s/variant?student=s001",
                 cJSON_GetObjectItem(a, "name")->valuestring);
        cJSON *v = request(&builtin, NULL, path, NULL, 200);
        assert_true(cJSON_GetArraySize(cJSON_GetObjectItem(v, "asked")) >= 1);
        cJSON_Delete(v);
    }
    cJSON_Delete(list);
}

static void a_variant_should_be_the_same_for_the_same_student_and_vary_between_students(void **state)
{
    (void)state;
    cJSON *first = request(&builtin, NULL, "/api/assignments/belt-1/variant?student=ada", NULL, 200);
    cJSON *again = request(&builtin, NULL, "/api/assignments/belt-1/variant?student=ada", NULL, 200);
    assert_true(cJSON_Compare(first, again, 1));
    assert_string_equal(cJSON_GetObjectItem(first, "exercise")->valuestring, "sta-belt-friction");
    int differ = 0;
    for (int i = 0; i < 10; i++) {
        char path[128];
        snprintf(path, sizeof path, "/api/assignments/belt-1/variant?student=s%03d", i);
        cJSON *other = request(&builtin, NULL, path, NULL, 200);
        differ += !cJSON_Compare(cJSON_GetObjectItem(first, "params"), cJSON_GetObjectItem(other, "params"), 1);
        cJSON_Delete(other);
    }
    assert_true(differ >= 9);                    /* 5,700 variants: a clash is rare */
    cJSON_Delete(first);
    cJSON_Delete(again);
    cJSON *e = request(&builtin, NULL, "/api/assignments/belt-1/variant", NULL, 400);
    assert_string_equal(cJSON_GetObjectItem(cJSON_GetObjectItem(e, "error"), "param")->valuestring, "student");
    cJSON_Delete(e);
    cJSON_Delete(request(&builtin, NULL, "/api/assignments/nothing/variant?student=a", NULL, 404));
}

static void answers_should_be_judged_against_the_capstan_equation(void **state)
{
    (void)state;
    cJSON *v = request(&builtin, NULL, "/api/assignments/belt-1/variant?student=grace", NULL, 200);
    double t2 = capstan(v);
    cJSON_Delete(v);
    struct {
        double factor;
        const char *unit;
        int right;
    } cases[] = {
        {1.0, "N", 1}, {1.009, "N", 1}, {0.991e-3, "kN", 1}, {1.02, "N", 0}, {0.97e-3, "kN", 0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char body[256];
        snprintf(body, sizeof body, "{\"student\":\"grace\",\"answers\":{\"T2\":\"%.6g %s\"}}",
                 t2 * cases[i].factor, cases[i].unit);
        cJSON *j = request(&builtin, "POST", "/api/assignments/belt-1/check", body, 200);
        const cJSON *res = cJSON_GetArrayItem(cJSON_GetObjectItem(j, "results"), 0);
        assert_string_equal(cJSON_GetObjectItem(res, "name")->valuestring, "T2");
        if (cJSON_IsTrue(cJSON_GetObjectItem(res, "correct")) != cases[i].right)
            fail_msg("%s judged %s", body, cases[i].right ? "wrong" : "right");
        assert_true(fabs(num(res, "expected") - t2) <= 1e-12 * t2);
        assert_true(num(j, "score") == cases[i].right);
        assert_true(num(j, "max_score") == 2);
        cJSON_Delete(j);
    }
    /* a number without its unit is an error of the answer, not a judgement */
    char body[256];
    snprintf(body, sizeof body, "{\"student\":\"grace\",\"answers\":{\"T2\":\"%.6g\"}}", t2);
    cJSON *j = request(&builtin, "POST", "/api/assignments/belt-1/check", body, 200);
    const cJSON *res = cJSON_GetArrayItem(cJSON_GetObjectItem(j, "results"), 0);
    assert_false(cJSON_IsTrue(cJSON_GetObjectItem(res, "correct")));
    assert_true(cJSON_IsString(cJSON_GetObjectItem(res, "error")));
    cJSON_Delete(j);
    cJSON_Delete(request(&builtin, "POST", "/api/assignments/belt-1/check", "not json", 400));
    cJSON_Delete(request(&builtin, NULL, "/api/assignments/belt-1/check", NULL, 405));
}

static void the_instructors_routes_should_need_the_key(void **state)
{
    (void)state;
    cJSON *e = request(&builtin, NULL, "/api/assignments/belt-1/key?student=a&key=anything", NULL, 403);
    assert_string_equal(cJSON_GetObjectItem(cJSON_GetObjectItem(e, "error"), "code")->valuestring, "forbidden");
    cJSON_Delete(e);
    cJSON_Delete(request(&keyed, NULL, "/api/assignments/belt/key?student=a", NULL, 403));
    cJSON_Delete(request(&keyed, NULL, "/api/assignments/belt/key?student=a&key=correct-hors", NULL, 403));
    cJSON_Delete(request(&keyed, NULL, "/api/assignments/belt/key?student=a&key=correct-horse!", NULL, 403));
    cJSON_Delete(request(&keyed, "POST", "/api/assignments/belt/csv?key=wrong", "id\na\n", 403));

    cJSON *k = request(&keyed, NULL, "/api/assignments/belt/key?student=lin&key=correct-horse", NULL, 200);
    double t2 = capstan(cJSON_GetObjectItem(k, "variant"));
    const cJSON *x = cJSON_GetArrayItem(cJSON_GetObjectItem(k, "expected"), 0);
    assert_string_equal(cJSON_GetObjectItem(x, "unit")->valuestring, "kN");
    assert_true(fabs(num(x, "value") - t2 * 1e-3) <= 1e-12 * t2 * 1e-3);
    cJSON_Delete(k);

    mm_reply r;
    const char list[] = "id,name\nlin,Lin\nmo,Mo\n";
    assert_int_equal(mm_http(&keyed, "POST", "/api/assignments/belt/csv?key=correct-horse", list,
                             sizeof list - 1, &r), 0);
    assert_int_equal(r.status, 200);
    assert_non_null(strstr(r.headers, "text/csv"));
    assert_non_null(strstr(r.headers, "no-store"));
    int lines = 0;
    for (const char *p = r.body; *p; p++)
        lines += *p == '\n';
    assert_int_equal(lines, 3);                  /* a header and one row per student */
    const char *row = strstr(r.body, "\nlin,");
    assert_non_null(row);
    char *end = strchr(row + 1, '\n');
    *end = '\0';
    double csv_t2 = strtod(strrchr(row, ',') + 1, NULL);
    assert_true(fabs(csv_t2 - t2 * 1e-3) <= 1e-12 * t2 * 1e-3);
    mm_reply_free(&r);
}

static void an_exercise_should_export_its_octave_script(void **state)
{
    (void)state;
    mm_reply r;
    assert_int_equal(mm_http(&builtin, NULL, "/api/exercises/sta-belt-friction/script.m?mu=0.25", NULL, 0, &r), 0);
    assert_int_equal(r.status, 200);
    assert_non_null(strstr(r.headers, "text/plain; charset=utf-8"));
    assert_non_null(strstr(r.headers, "ETag:"));
    assert_non_null(strstr(r.body, "GET /api/exercises/sta-belt-friction/solve?T1=100&mu=0.25&"));
    assert_non_null(strstr(r.body, "\nmu = 0.25;"));
    mm_reply_free(&r);
    assert_int_equal(mm_http(&builtin, "HEAD", "/api/exercises/sta-belt-friction/script.m", NULL, 0, &r), 0);
    assert_int_equal(r.status, 200);
    assert_int_equal(r.len, 0);
    mm_reply_free(&r);
    cJSON *e = request(&builtin, NULL, "/api/exercises/sta-belt-friction/script.m?mu=7", NULL, 400);
    assert_string_equal(cJSON_GetObjectItem(cJSON_GetObjectItem(e, "error"), "param")->valuestring, "mu");
    cJSON_Delete(e);
    cJSON_Delete(request(&builtin, NULL, "/api/exercises/no-such/script.m", NULL, 404));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_builtin_course_should_list_example_assignments),
        cmocka_unit_test(a_variant_should_be_the_same_for_the_same_student_and_vary_between_students),
        cmocka_unit_test(answers_should_be_judged_against_the_capstan_equation),
        cmocka_unit_test(the_instructors_routes_should_need_the_key),
        cmocka_unit_test(an_exercise_should_export_its_octave_script),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
