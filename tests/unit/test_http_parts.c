/* test_http_parts.c — the small parsers of the HTTP layer, alone:
 * Accept-Encoding, If-None-Match, the access log's escaping, the route
 * table, and the canonical key of a resolved request. */
#include "mm_test.h"

#include <string.h>

#include "mm_api.h"
#include "mm_http.h"

static void accept_encoding_should_be_read_with_its_q_values(void **state)
{
    (void)state;
    assert_true(mm_accepts_gzip("gzip"));
    assert_true(mm_accepts_gzip("gzip, deflate, br"));
    assert_true(mm_accepts_gzip("br;q=1.0, gzip;q=0.8, *;q=0.1"));
    assert_true(mm_accepts_gzip("GZIP"));
    assert_true(mm_accepts_gzip("x-gzip"));
    assert_true(mm_accepts_gzip("*"));
    assert_false(mm_accepts_gzip(NULL));
    assert_false(mm_accepts_gzip(""));
    assert_false(mm_accepts_gzip("identity"));
    assert_false(mm_accepts_gzip("deflate, br"));
    assert_false(mm_accepts_gzip("gzip;q=0"));
    assert_false(mm_accepts_gzip("gzip; q=0.000, identity"));
    assert_false(mm_accepts_gzip("gzipx"));
}

static void if_none_match_should_match_every_form_of_the_etag(void **state)
{
    (void)state;
    const char *e = "\"abc\"";
    assert_true(mm_etag_matches("\"abc\"", e));
    assert_true(mm_etag_matches("W/\"abc\"", e));
    assert_true(mm_etag_matches("\"abc-gz\"", e));
    assert_true(mm_etag_matches("\"x\", \"abc\"", e));
    assert_true(mm_etag_matches("*", e));
    assert_false(mm_etag_matches(NULL, e));
    assert_false(mm_etag_matches("\"ab\"", e));
    assert_false(mm_etag_matches("\"abcd\"", e));
    assert_false(mm_etag_matches("\"abc-gzz\"", e));
    assert_false(mm_etag_matches("abc", e));
}

static void the_log_should_escape_what_could_forge_a_line(void **state)
{
    (void)state;
    char out[64];
    mm_log_escape("/a\nGET /x 200\r\"\\\x7f\xc3\xa9", out, sizeof out);
    assert_string_equal(out, "/a\\x0aGET /x 200\\x0d\\x22\\x5c\\x7f\\xc3\\xa9");
    assert_null(strchr(out, '\n'));
    char tiny[6];
    mm_log_escape("\n\n\n", tiny, sizeof tiny);            /* cut whole, never half an escape */
    assert_string_equal(tiny, "\\x0a");
}

static void every_route_should_have_methods_and_a_pattern(void **state)
{
    (void)state;
    int n;
    const mm_route_info *r = mm_http_routes(&n);
    assert_true(n >= 8);
    for (int i = 0; i < n; i++) {
        assert_true(r[i].pattern[0] == '/');
        assert_true(strstr(r[i].methods, "GET") || strstr(r[i].methods, "POST"));
        if (strstr(r[i].methods, "GET"))
            assert_non_null(strstr(r[i].methods, "HEAD"));  /* HEAD wherever GET (check, csv: POST only) */
    }
    assert_string_equal(r[n - 1].pattern, "/*");             /* static files last */
}

static void the_key_should_be_the_canonical_resolved_request(void **state)
{
    (void)state;
    const mm_exercise *ex = mm_exercise_find("num-linear-system");
    assert_non_null(ex);
    mm_input in[] = {{"b", " [10; 0 ;1000] ", 1, 15}};
    mm_solve s;
    mm_solve_init(&s, ex);
    assert_int_equal(mm_api_resolve(&s, in, 1), MM_OK);
    assert_string_equal(s.key.p, "num-linear-system?A=1,2,3;4,5,6;7,8,10&b=10,0,1000");
    mm_solve_free(&s);
    const mm_exercise *nl = mm_exercise_find("num-nonlinear-roots");
    mm_input f[] = {{"f", " x^2-2&b=1 ", 1, 11}};
    mm_solve_init(&s, nl);
    assert_int_equal(mm_api_resolve(&s, f, 1), MM_OK);
    assert_non_null(strstr(s.key.p, "?f=x^2-2%26b%3D1&"));    /* a separator in a text is escaped */
    mm_solve_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(accept_encoding_should_be_read_with_its_q_values),
        cmocka_unit_test(if_none_match_should_match_every_form_of_the_etag),
        cmocka_unit_test(the_log_should_escape_what_could_forge_a_line),
        cmocka_unit_test(every_route_should_have_methods_and_a_pattern),
        cmocka_unit_test(the_key_should_be_the_canonical_resolved_request),
    };
    return cmocka_run_group_tests_name("http-parts", tests, NULL, NULL);
}
