/* test_draw.c — random parameter values (mm_draw.h): the same seed gives
 * the same values, every value parses inside its limits, whole requests
 * pass the exercise's joint check, and the generator is the one the tests
 * drew with before it moved into the product (xorshift64*). */
#include "mm_test.h"

#include <string.h>

#include "mm_api.h"
#include "mm_draw.h"
#include "mm_params.h"

static void the_generator_should_be_xorshift64_star(void **state)
{
    (void)state;
    /* the sequence of tests/load/loadtool.c's former generator, by hand */
    unsigned long long s = 0x2545F4914F6CDD1DULL;
    mm_rng g;
    mm_rng_seed(&g, 0x2545F4914F6CDD1DULL);
    for (int i = 0; i < 1000; i++) {
        s ^= s >> 12, s ^= s << 25, s ^= s >> 27;
        double want = (double)((s * 2685821657736338717ULL) >> 11) / 9007199254740992.0;
        double got = mm_rng_uniform(&g);
        assert_true(got == want);
        assert_true(got >= 0 && got < 1);
    }
}

static void seeds_from_texts_should_be_stable_and_distinct(void **state)
{
    (void)state;
    assert_true(mm_draw_seed("hw1", "alice") == mm_draw_seed("hw1", "alice"));
    assert_true(mm_draw_seed("hw1", "alice") != mm_draw_seed("hw1", "alicf"));
    assert_true(mm_draw_seed("hw1", "alice") != mm_draw_seed("hw1a", "lice"));
    assert_true(mm_draw_seed("hw1", "") != mm_draw_seed("", "hw1"));
    assert_true(mm_draw_seed(NULL, NULL) == mm_draw_seed("", ""));
    /* fixed forever: a student's variant must not change between versions */
    assert_true(mm_draw_seed("hw1", "alice") == 0x1ae6e1bd90f93042ULL);
}

static void every_drawn_value_should_parse_inside_its_limits(void **state)
{
    (void)state;
    mm_rng g;
    mm_rng_seed(&g, 12345);
    for (int i = 0; i < mm_exercise_count; i++) {
        const mm_exercise *ex = mm_exercises[i];
        for (int k = 0; k < ex->n_params; k++) {
            const mm_param *p = &ex->params[k];
            for (int d = 0; d < 20; d++) {
                char text[MM_DRAW_TEXT_MAX];
                assert_int_equal(mm_draw_text(p, &g, text, sizeof text), MM_OK);
                mm_result arena;
                mm_result_init(&arena, 1 << 22);
                mm_value v;
                mm_error err;
                if (mm_param_parse(p, text, strlen(text), &v, &arena, &err) != MM_OK)
                    fail_msg("%s.%s = '%s': %s", ex->id, p->name, text, err.msg);
                mm_result_release(&arena);
            }
        }
    }
    char tiny[2];                     /* too small: refused, and nothing half written */
    const mm_param big = {"x", "x", "", MM_REAL, 500, 100, 1000, .help = "h"};
    assert_int_equal(mm_draw_text(&big, &g, tiny, sizeof tiny), MM_ETOOBIG);
    assert_string_equal(tiny, "");
}

static void the_same_seed_should_give_the_same_request(void **state)
{
    (void)state;
    for (int i = 0; i < mm_exercise_count; i++) {
        const mm_exercise *ex = mm_exercises[i];
        static mm_draw_set a, b;
        mm_rng g1, g2;
        mm_error err;
        mm_rng_seed(&g1, mm_draw_seed("hw", ex->id));
        mm_rng_seed(&g2, mm_draw_seed("hw", ex->id));
        int r1 = mm_draw_request(ex, &g1, 100, &a, &err);
        int r2 = mm_draw_request(ex, &g2, 100, &b, &err);
        if (r1 != MM_OK)
            fail_msg("%s: no draw passed its joint check in 100: %s", ex->id, err.msg);
        assert_int_equal(r2, MM_OK);
        assert_int_equal(a.n, ex->n_params);
        for (int k = 0; k < a.n; k++)
            assert_string_equal(a.texts[k], b.texts[k]);
        /* and it resolves */
        mm_solve s;
        mm_solve_init(&s, ex);
        assert_int_equal(mm_api_resolve(&s, a.in, a.n), MM_OK);
        mm_solve_free(&s);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_generator_should_be_xorshift64_star),
        cmocka_unit_test(seeds_from_texts_should_be_stable_and_distinct),
        cmocka_unit_test(every_drawn_value_should_parse_inside_its_limits),
        cmocka_unit_test(the_same_seed_should_give_the_same_request),
    };
    return cmocka_run_group_tests_name("draw", tests, NULL, NULL);
}
