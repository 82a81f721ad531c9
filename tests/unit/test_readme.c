/* test_readme.c — README's "How to add an exercise" example, taken from
 * README.md by the Makefile, compiled with the project's warnings and run
 * through the real pipeline: a newcomer who copies it gets an exercise
 * that builds, passes its checks and declares what it answers. */
#include "mm_test.h"

#include "readme_example.c"

#include <cJSON.h>
#include <string.h>

#include "mm_api.h"

static void the_readme_example_should_be_a_well_formed_exercise(void **state)
{
    (void)state;
    mm_error err;
    if (mm_exercise_check(&mm_ex_num_falling_ball, &err) != MM_OK)
        fail_msg("%s", err.msg);
}

static void the_readme_example_should_solve_and_pass_its_check(void **state)
{
    (void)state;
    static const char *const queries[][2] = {{NULL, NULL}, {"c", "1"}, {"c", "1e-6"}, {"t_end", "0.01"}};
    for (size_t q = 0; q < sizeof queries / sizeof queries[0]; q++) {
        mm_input in = {queries[q][0], queries[q][1], queries[q][0] ? strlen(queries[q][0]) : 0,
                       queries[q][1] ? strlen(queries[q][1]) : 0};
        mm_buf out;
        mm_buf_init(&out, 1 << 22);
        assert_int_equal(mm_api_solve(&mm_ex_num_falling_ball, &in, queries[q][0] ? 1 : 0, &out), 200);
        cJSON *doc = cJSON_Parse(out.p);
        const cJSON *c = cJSON_GetArrayItem(cJSON_GetObjectItem(doc, "checks"), 0);
        double e = cJSON_GetObjectItem(c, "abs_error")->valuedouble, tol = cJSON_GetObjectItem(c, "tolerance")->valuedouble;
        print_message("%s=%s: error %.3g, tolerance %.3g\n", queries[q][0] ? queries[q][0] : "defaults",
                      queries[q][1] ? queries[q][1] : "", e, tol);
        assert_true(cJSON_IsTrue(cJSON_GetObjectItem(c, "passed")));
        if (q == 0)                 /* at the defaults the bound is within 100x of the error: it can fail */
            assert_true(tol <= 100 * e);
        const cJSON *vt = cJSON_GetArrayItem(cJSON_GetObjectItem(doc, "scalars"), 0);
        assert_true(cJSON_IsTrue(cJSON_GetObjectItem(vt, "exact")));
        cJSON_Delete(doc);
        mm_buf_free(&out);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_readme_example_should_be_a_well_formed_exercise),
        cmocka_unit_test(the_readme_example_should_solve_and_pass_its_check),
    };
    return cmocka_run_group_tests_name("readme", tests, NULL, NULL);
}
