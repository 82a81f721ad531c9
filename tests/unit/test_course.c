/* test_course.c — the course file (mm_course.h): what it may say, what it
 * may not, and that every refusal names the line and the reason. */
#include "mm_test.h"

#include <string.h>

#include "mm_api.h"
#include "mm_course.h"
#include "mm_params.h"

static mm_course *parse(const char *text, mm_error *err)
{
    return mm_course_parse(text, strlen(text), "c.json", err);
}

/* The text must be refused with a message that holds `want`. */
static void refused(const char *text, const char *want)
{
    mm_error err;
    mm_course *c = parse(text, &err);
    if (c) {
        mm_course_free(c);
        fail_msg("accepted: %s", text);
    }
    assert_int_equal(err.code, MM_EVALUE);
    if (!strstr(err.msg, want))
        fail_msg("message '%s' lacks '%s'", err.msg, want);
}

static void the_builtin_course_should_hold_every_exercise_in_book_order(void **state)
{
    (void)state;
    mm_course *c = mm_course_builtin();
    assert_non_null(c);
    assert_int_equal(mm_course_exercise_count(c), mm_exercise_count);
    for (int i = 0; i < mm_exercise_count; i++) {
        const mm_exercise *ex = mm_course_exercise(c, i);
        assert_string_equal(ex->id, mm_exercises[i]->id);
        assert_ptr_equal(ex->solve, mm_exercises[i]->solve);
        assert_memory_equal(ex->params, mm_exercises[i]->params, (size_t)ex->n_params * sizeof *ex->params);
    }
    assert_string_equal(mm_course_title(c), "mechmat");
    assert_string_equal(mm_course_base_path(c), "/");
    assert_string_equal(mm_course_language(c), "en");
    assert_int_equal(mm_course_assignment_count(c), 2);   /* the two examples of b50e12e (API.md: at least one) */
    mm_course_free(c);
}

static void an_empty_object_should_be_the_builtin_course(void **state)
{
    (void)state;
    mm_error err;
    mm_course *c = parse("{}", &err);
    assert_non_null(c);
    assert_int_equal(mm_course_exercise_count(c), mm_exercise_count);
    assert_int_equal(strlen(mm_course_digest(c)), 22);
    mm_course_free(c);
}

static void overrides_should_narrow_limits_and_move_defaults(void **state)
{
    (void)state;
    mm_error err;
    mm_course *c = parse("{\"title\":\"T\",\"language\":\"de-CH\",\"base_path\":\"/mech\",\n"
                         "\"exercises\":[\"num-linear-system\",\n"
                         "{\"id\":\"vib-sdof-forced\",\"params\":{\"m\":{\"default\":2,\"min\":0.5,\"max\":10},"
                         "\"omega\":{\"default\":\"pi\"}}},\n"
                         "{\"id\":\"num-linear-system\"}]}", &err);
    assert_null(c);                                           /* listed twice */
    assert_non_null(strstr(err.msg, "c.json:4: exercise num-linear-system is listed twice"));

    c = parse("{\"title\":\"T\",\"language\":\"de-CH\",\"base_path\":\"/mech\",\n"
              "\"exercises\":[\"num-linear-system\",\n"
              "{\"id\":\"vib-sdof-forced\",\"params\":{\"m\":{\"default\":2,\"min\":0.5,\"max\":10},"
              "\"omega\":{\"default\":\"pi\"}}},\n"
              "{\"id\":\"num-eigen\",\"params\":{\"M\":{\"default\":[[2,0,0],[0,2,0],[0,0,2]]}}}]}", &err);
    if (!c)
        fail_msg("%s", err.msg);
    assert_string_equal(mm_course_title(c), "T");
    assert_string_equal(mm_course_language(c), "de-CH");
    assert_string_equal(mm_course_base_path(c), "/mech/");
    assert_int_equal(mm_course_exercise_count(c), 3);
    assert_null(mm_course_find(c, "vib-sdof-free"));
    const mm_exercise *ex = mm_course_find(c, "vib-sdof-forced");
    assert_non_null(ex);
    assert_true(ex->params[0].def == 2 && ex->params[0].min == 0.5 && ex->params[0].max == 10);
    const mm_exercise *orig = mm_exercise_find("vib-sdof-forced");
    assert_true(orig->params[0].min == 1e-3);                 /* the registry is untouched */
    for (int k = 0; k < ex->n_params; k++)
        if (strcmp(ex->params[k].name, "omega") == 0)
            check_rel(ex->params[k].def, M_PI, 0, "omega's default: pi, exactly as parsed");
    const mm_exercise *eig = mm_course_find(c, "num-eigen");
    assert_string_equal(eig->params[1].def_text, "2,0,0;0,2,0;0,0,2");

    /* a solve of the course's exercise uses its defaults and limits */
    mm_buf out;
    mm_buf_init(&out, MM_ANSWER_MAX);
    assert_int_equal(mm_api_solve(ex, NULL, 0, &out), 200);
    assert_non_null(strstr(out.p, "\"params\":{\"m\":2,"));
    mm_input in = {"m", "20", 1, 2};
    assert_int_equal(mm_api_solve(ex, &in, 1, &out), 400);
    assert_non_null(strstr(out.p, "m must be between 0.5 and 10 kg"));
    mm_buf_free(&out);
    mm_course_free(c);
}

static void every_rule_should_be_refused_with_its_line(void **state)
{
    (void)state;
    refused("{\n\"title\": 3}", "c.json:2: \"title\" must be a text");
    refused("{\"titel\": \"x\"}", "c.json:1: course: unknown key \"titel\"");
    refused("{\"title\": \"a\", \"title\": \"b\"}", "\"title\" is given twice");
    refused("{\n\n  \"exercises\": [\"nope\"]}", "c.json:3: no exercise \"nope\"");
    refused("{\"exercises\": []}", "\"exercises\" is empty");
    refused("{\"exercises\": \"vib-sdof-free\"}", "must be an array");
    refused("{\"base_path\": \"mech\"}", "must start with '/'");
    refused("{\"base_path\": \"/a/../b\"}", "\"..\"");
    refused("{\"language\": \"en us\"}", "language tag");
    refused("{\"exercises\":[{\"id\":\"vib-sdof-free\",\n\"params\":{\"mass\":{\"default\":1}}}]}",
            "c.json:2: vib-sdof-free has no parameter \"mass\"");
    refused("{\"exercises\":[{\"id\":\"vib-sdof-free\",\"params\":{\n\"m\":{\"max\":5000}}}]}",
            "c.json:2: vib-sdof-free: m: max 5000 is above the built-in 1000");
    refused("{\"exercises\":[{\"id\":\"vib-sdof-free\",\"params\":{\"m\":{\"min\":5,\"max\":2}}}]}",
            "min 5 is above max 2");
    refused("{\"exercises\":[{\"id\":\"vib-sdof-free\",\"params\":{\"m\":{\"min\":5}}}]}",
            "the built-in default lies outside the course's limits");
    refused("{\"exercises\":[{\"id\":\"vib-sdof-free\",\"params\":{\"m\":{\"default\":5000}}}]}",
            "the default does not fit: m must be between");
    refused("{\"exercises\":[{\"id\":\"vib-sdof-free\",\"params\":{\"m\":{\"step\":1}}}]}",
            "unknown key \"step\"");
    refused("{\"exercises\":[{\"id\":\"vib-fourier-series\",\"params\":{\"wave\":{\"default\":\"loose\"}}}]}",
            "must be one of");
    refused("{\"exercises\":[{\"id\":\"vib-fourier-series\",\"params\":{\"wave\":{\"min\":1}}}]}",
            "unknown key \"min\"");
    refused("{\"exercises\":[{\"id\":\"num-linear-system\",\"params\":{\"A\":{\"max_rows\":1000}}}]}",
            "max_rows 1000 is above the built-in");
    refused("{\"assignments\": [{\"title\": \"no name\"}]}", "an assignment is an object with a \"name\"");
    refused("{\"assignments\": [{\"name\": \"a b\"}]}", "letters, digits");
    refused("{\"assignments\": [{\"name\": \"hw\"},\n{\"name\": \"hw\"}]}", "c.json:2: assignment \"hw\" is defined twice");
    refused("{\n  \"title\": \"x\",\n  oops\n}", "c.json:3: not valid JSON");
    refused("{} {}", "text after the end");
    refused("[1,2]", "one JSON object");
}

/* cJSON reads every byte up to ' ' as white space; the scan that finds
 * each value's line once looped for ever (and grew without bound) on a
 * stray control character between two values: found by fuzz_course. */
static void a_control_character_between_values_should_not_stop_the_line_count(void **state)
{
    (void)state;
    refused("{\"exercises\": [\"vib-sdof-free\",\n \x19 \"nope\"]}", "c.json:2: no exercise \"nope\"");
    refused("{\x01\n\x1f\"title\":\x0b 3}", "c.json:2: \"title\" must be a text");
}

static void assignments_should_be_kept_as_written(void **state)
{
    (void)state;
    mm_error err;
    mm_course *c = parse("{\"assignments\":[\n  {\"name\":\"hw1\",\"exercise\":\"sta-belt-friction\",\"ask\":[\"T2\"]},\n"
                         "  {\"name\":\"hw-2\",\"extra\":{\"any\":[1,2,3]}}\n]}", &err);
    assert_non_null(c);
    assert_int_equal(mm_course_assignment_count(c), 2);
    assert_string_equal(mm_course_assignment_name(c, 0), "hw1");
    assert_string_equal(mm_course_assignment_name(c, 1), "hw-2");
    const cJSON *a = mm_course_assignment_find(c, "hw1");
    assert_non_null(a);
    assert_string_equal(cJSON_GetObjectItem(a, "exercise")->valuestring, "sta-belt-friction");
    assert_int_equal(mm_course_line(c, a), 2);
    assert_int_equal(mm_course_line(c, cJSON_GetObjectItem(mm_course_assignment(c, 1), "extra")), 3);
    assert_null(mm_course_assignment_find(c, "hw3"));
    mm_course_free(c);
}

static void a_missing_file_should_say_so(void **state)
{
    (void)state;
    mm_error err;
    assert_null(mm_course_load("/nonexistent/course.json", &err));
    assert_int_equal(err.code, MM_ENOTFOUND);
    assert_non_null(strstr(err.msg, "/nonexistent/course.json"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_builtin_course_should_hold_every_exercise_in_book_order),
        cmocka_unit_test(an_empty_object_should_be_the_builtin_course),
        cmocka_unit_test(overrides_should_narrow_limits_and_move_defaults),
        cmocka_unit_test(every_rule_should_be_refused_with_its_line),
        cmocka_unit_test(a_control_character_between_values_should_not_stop_the_line_count),
        cmocka_unit_test(assignments_should_be_kept_as_written),
        cmocka_unit_test(a_missing_file_should_say_so),
    };
    return cmocka_run_group_tests_name("course", tests, NULL, NULL);
}
