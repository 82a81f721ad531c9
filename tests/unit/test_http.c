/* test_http.c — the real server over HTTP: every route, every error code,
 * static files and path traversal in every encoding, GET and POST giving
 * the same answer, concurrent requests, a busy server and a clean stop.
 *
 * The server runs with a web root made for the test in a temporary folder,
 * with a symlink that points out of it, so that the traversal cases have
 * something to find if the guard were broken. */
#include "mm_test.h"

#include <cJSON.h>
#include <pthread.h>
#include <sys/stat.h>

#include "mm_server_fixture.h"

static mm_fixture server;
static char webroot[256];
static const char SECRET[] = "SECRET-OUTSIDE-THE-WEB-ROOT";

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static int setup(void **state)
{
    (void)state;
    char path[512];
    snprintf(webroot, sizeof webroot, "/tmp/mm-http-test-XXXXXX");
    if (!mkdtemp(webroot))
        return -1;
    /* root/www is the web root; root/secret.txt lies outside it */
    snprintf(path, sizeof path, "%s/www", webroot);
    mkdir(path, 0755);
    snprintf(path, sizeof path, "%s/www/sub", webroot);
    mkdir(path, 0755);
    snprintf(path, sizeof path, "%s/secret.txt", webroot);
    write_file(path, SECRET);
    snprintf(path, sizeof path, "%s/www/index.html", webroot);
    write_file(path, "<!doctype html><title>t</title>index");
    snprintf(path, sizeof path, "%s/www/app.js", webroot);
    write_file(path, "export const x = 1;");
    snprintf(path, sizeof path, "%s/www/style.css", webroot);
    write_file(path, "body{}");
    snprintf(path, sizeof path, "%s/www/sub/index.html", webroot);
    write_file(path, "sub index");
    char target[512];
    snprintf(target, sizeof target, "%s/secret.txt", webroot);
    snprintf(path, sizeof path, "%s/www/leak.txt", webroot);
    if (symlink(target, path) != 0)
        return -1;
    snprintf(path, sizeof path, "%s/www/outside", webroot);
    if (symlink(webroot, path) != 0)
        return -1;

    char www[300];
    snprintf(www, sizeof www, "%s/www", webroot);
    const char *extra[] = {"--web-root", www, NULL};
    return mm_fixture_start(&server, extra);
}

static int teardown(void **state)
{
    (void)state;
    int status = mm_fixture_stop(&server);
    char cmd[512];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", webroot);
    if (system(cmd) != 0)
        return -1;
    return status == 0 ? 0 : -1;          /* a clean stop on SIGTERM */
}

static cJSON *get_json(const char *path, long want_status)
{
    mm_reply r;
    assert_int_equal(mm_http(&server, NULL, path, NULL, 0, &r), 0);
    if (r.status != want_status)
        fail_msg("%s: status %ld, wanted %ld: %.300s", path, r.status, want_status, r.body);
    assert_non_null(strstr(r.headers, "application/json"));
    cJSON *j = cJSON_Parse(r.body);
    if (!j)
        fail_msg("%s: not JSON: %.300s", path, r.body);
    mm_reply_free(&r);
    return j;
}

/* The error of a document, checked: code and (if want_param) its param. */
static void expect_error(cJSON *j, const char *code, const char *want_param)
{
    const cJSON *e = cJSON_GetObjectItem(j, "error");
    assert_non_null(e);
    assert_string_equal(cJSON_GetObjectItem(e, "code")->valuestring, code);
    assert_true(cJSON_IsString(cJSON_GetObjectItem(e, "message")));
    if (want_param)
        assert_string_equal(cJSON_GetObjectItem(e, "param")->valuestring, want_param);
    cJSON_Delete(j);
}

static double scalar(const cJSON *doc, const char *name)
{
    const cJSON *s;
    cJSON_ArrayForEach(s, cJSON_GetObjectItem(doc, "scalars"))
        if (strcmp(cJSON_GetObjectItem(s, "name")->valuestring, name) == 0)
            return cJSON_GetObjectItem(s, "value")->valuedouble;
    fail_msg("no scalar %s", name);
    return NAN;
}

/* ---- routes ----------------------------------------------------------------------- */

static void health_catalog_and_metadata_should_answer(void **state)
{
    (void)state;
    cJSON *h = get_json("/api/health", 200);
    assert_string_equal(cJSON_GetObjectItem(h, "status")->valuestring, "ok");
    int n = cJSON_GetObjectItem(h, "exercises")->valueint;
    assert_true(n >= 2);
    cJSON_Delete(h);

    cJSON *cat = get_json("/api/exercises", 200);
    assert_int_equal(cJSON_GetArraySize(cat), n);
    const cJSON *row;
    cJSON_ArrayForEach(row, cat) {
        const char *fields[] = {"id", "section", "title", "summary"};
        for (int i = 0; i < 4; i++)
            assert_true(cJSON_IsString(cJSON_GetObjectItem(row, fields[i])));
        assert_true(cJSON_IsNumber(cJSON_GetObjectItem(row, "chapter")));
        assert_true(cJSON_IsArray(cJSON_GetObjectItem(row, "tags")));
    }
    cJSON_Delete(cat);

    cJSON *m = get_json("/api/exercises/vib-sdof-forced", 200);
    assert_string_equal(cJSON_GetObjectItem(m, "id")->valuestring, "vib-sdof-forced");
    assert_non_null(strstr(cJSON_GetObjectItem(m, "theory_html")->valuestring, "class=\"math"));
    const cJSON *p = cJSON_GetArrayItem(cJSON_GetObjectItem(m, "params"), 0);
    assert_string_equal(cJSON_GetObjectItem(p, "name")->valuestring, "m");
    assert_string_equal(cJSON_GetObjectItem(p, "unit")->valuestring, "kg");
    assert_true(cJSON_GetObjectItem(p, "min")->valuedouble == 1e-3);
    cJSON_Delete(m);
}

static void the_issue_example_should_give_the_steady_amplitude(void **state)
{
    (void)state;
    cJSON *d = get_json("/api/exercises/vib-sdof-forced/solve?m=2&k=50&c=1&F0=3&omega=4", 200);
    double want = 3 / sqrt((50 - 2 * 16.0) * (50 - 2 * 16.0) + 1 * 16.0);
    check_rel(scalar(d, "X"), want, 1e-9, "X = F0/sqrt((k-m w^2)^2+(c w)^2)");
    const cJSON *c;
    cJSON_ArrayForEach(c, cJSON_GetObjectItem(d, "checks"))
        assert_true(cJSON_IsTrue(cJSON_GetObjectItem(c, "passed")));
    cJSON_Delete(d);
}

static void every_error_of_the_api_table_should_come_as_json(void **state)
{
    (void)state;
    const char *base = "/api/exercises/vib-sdof-forced/solve";
    char path[20000];

    snprintf(path, sizeof path, "%s?m=-1", base);
    expect_error(get_json(path, 400), "out_of_range", "m");
    snprintf(path, sizeof path, "%s?m=abc", base);
    expect_error(get_json(path, 400), "bad_value", "m");
    snprintf(path, sizeof path, "%s?m=1e999", base);
    expect_error(get_json(path, 400), "out_of_range", "m");
    snprintf(path, sizeof path, "%s?m=nan", base);
    expect_error(get_json(path, 400), "bad_value", "m");
    snprintf(path, sizeof path, "%s?m=", base);
    expect_error(get_json(path, 400), "bad_value", "m");
    snprintf(path, sizeof path, "%s?m=1%%00", base);                    /* NUL in the query */
    expect_error(get_json(path, 400), "bad_value", NULL);
    snprintf(path, sizeof path, "%s?m=1&m=2", base);
    expect_error(get_json(path, 400), "bad_value", "m");
    snprintf(path, sizeof path, "%s?mass=1", base);
    expect_error(get_json(path, 400), "unknown_param", "mass");
    snprintf(path, sizeof path, "%s?points=10.5", base);
    expect_error(get_json(path, 400), "bad_value", "points");
    /* a joint limit: 1e4 s at 1000 rad/s is too much work for one request */
    snprintf(path, sizeof path, "%s?k=1e6&t_end=1e4", base);
    expect_error(get_json(path, 400), "out_of_range", "t_end");

    expect_error(get_json("/api/exercises/no-such-exercise", 404), "not_found", NULL);
    expect_error(get_json("/api/exercises/no-such-exercise/solve", 404), "not_found", NULL);
    expect_error(get_json("/api/nothing", 404), "not_found", NULL);
    expect_error(get_json("/api/exercises/vib-sdof-forced/other", 404), "not_found", NULL);
    expect_error(get_json("/no-such-page.html", 404), "not_found", NULL);

    /* a query over 16 KiB */
    int n = snprintf(path, sizeof path, "%s?m=", base);
    memset(path + n, '1', 17000);
    path[n + 17000] = '\0';
    expect_error(get_json(path, 413), "too_large", NULL);
}

static void wrong_methods_should_get_405_with_allow(void **state)
{
    (void)state;
    struct { const char *method, *path, *allow; } cases[] = {
        {"DELETE", "/api/health", "GET, HEAD"},
        {"PUT", "/api/exercises/vib-sdof-forced/solve", "GET, HEAD, POST"},
        {"POST", "/api/exercises", "GET, HEAD"},
        {"POST", "/index.html", "GET, HEAD"},
    };
    for (unsigned i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        mm_reply r;
        assert_int_equal(mm_http(&server, cases[i].method, cases[i].path, NULL, 0, &r), 0);
        if (r.status != 405)
            fail_msg("%s %s: %ld", cases[i].method, cases[i].path, r.status);
        char allow[64];
        snprintf(allow, sizeof allow, "Allow: %s", cases[i].allow);
        assert_non_null(strstr(r.headers, allow));
        expect_error(cJSON_Parse(r.body), "method_not_allowed", NULL);
        mm_reply_free(&r);
    }
    mm_reply r;                                       /* HEAD: headers only */
    assert_int_equal(mm_http(&server, "HEAD", "/api/health", NULL, 0, &r), 0);
    assert_int_equal(r.status, 200);
    assert_int_equal(r.len, 0);
    mm_reply_free(&r);
}

static void post_bodies_should_be_checked_and_limited(void **state)
{
    (void)state;
    const char *solve = "/api/exercises/vib-sdof-forced/solve";
    const char *bad[] = {"{", "[]", "{\"params\":[1]}", "{\"other\":1}", "nul\x01l", "\"params\""};
    for (unsigned i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        mm_reply r;
        assert_int_equal(mm_http(&server, "POST", solve, bad[i], strlen(bad[i]), &r), 0);
        if (r.status != 400)
            fail_msg("body %s: %ld %s", bad[i], r.status, r.body);
        expect_error(cJSON_Parse(r.body), "bad_json", NULL);
        mm_reply_free(&r);
    }
    /* deeply nested JSON */
    size_t depth = 100000;
    char *deep = malloc(2 * depth + 1);
    memset(deep, '[', depth);
    memset(deep + depth, ']', depth);
    deep[2 * depth] = '\0';
    mm_reply r;
    assert_int_equal(mm_http(&server, "POST", solve, deep, 2 * depth, &r), 0);
    assert_int_equal(r.status, 400);
    mm_reply_free(&r);
    free(deep);
    /* a value of the wrong type names the parameter */
    const char *wrong = "{\"params\":{\"m\":{\"a\":1}}}";
    assert_int_equal(mm_http(&server, "POST", solve, wrong, strlen(wrong), &r), 0);
    assert_int_equal(r.status, 400);
    expect_error(cJSON_Parse(r.body), "bad_value", "m");
    mm_reply_free(&r);
    /* 10 MB */
    size_t big = 10u << 20;
    char *body = malloc(big);
    memset(body, ' ', big);
    body[0] = '{';
    body[big - 1] = '}';
    assert_int_equal(mm_http(&server, "POST", solve, body, big, &r), 0);
    assert_int_equal(r.status, 413);
    expect_error(cJSON_Parse(r.body), "too_large", NULL);
    mm_reply_free(&r);
    free(body);
}

static void get_and_post_should_give_the_same_answer(void **state)
{
    (void)state;
    mm_reply g, p;
    const char *body = "{\"params\":{\"m\":2,\"k\":\"50\",\"c\":1,\"F0\":3,\"omega\":4}}";
    assert_int_equal(mm_http(&server, NULL, "/api/exercises/vib-sdof-forced/solve?m=2&k=50&c=1&F0=3&omega=4",
                             NULL, 0, &g), 0);
    assert_int_equal(mm_http(&server, "POST", "/api/exercises/vib-sdof-forced/solve", body, strlen(body), &p), 0);
    assert_int_equal(g.status, 200);
    assert_int_equal(p.status, 200);
    *strstr(g.body, ",\"elapsed_us\"") = '\0';
    *strstr(p.body, ",\"elapsed_us\"") = '\0';
    assert_string_equal(g.body, p.body);
    mm_reply_free(&g);
    mm_reply_free(&p);
}

/* ---- static files -------------------------------------------------------------------- */

static void static_files_should_come_with_their_mime_types(void **state)
{
    (void)state;
    struct { const char *path, *type, *text; } ok[] = {
        {"/", "text/html", "index"},
        {"/index.html", "text/html", "index"},
        {"/app.js", "text/javascript", "export"},
        {"/style.css", "text/css", "body{}"},
        {"/sub/", "text/html", "sub index"},
        {"/sub", "text/html", "sub index"},
        {"//index.html", "text/html", "index"},
    };
    for (unsigned i = 0; i < sizeof ok / sizeof ok[0]; i++) {
        mm_reply r;
        assert_int_equal(mm_http(&server, NULL, ok[i].path, NULL, 0, &r), 0);
        if (r.status != 200 || !strstr(r.headers, ok[i].type) || !strstr(r.body, ok[i].text))
            fail_msg("%s: %ld %s", ok[i].path, r.status, r.headers);
        mm_reply_free(&r);
    }
}

static void nothing_outside_the_web_root_should_ever_be_served(void **state)
{
    (void)state;
    const char *attacks[] = {
        "/../secret.txt", "/%2e%2e/secret.txt", "/%2E%2E/secret.txt", "/..%2fsecret.txt",
        "/%2e%2e%2fsecret.txt", "/sub/../../secret.txt", "/sub/%2e%2e/%2e%2e/secret.txt",
        "/./../secret.txt", "/..\\secret.txt", "/%5c..%5csecret.txt", "/..%5csecret.txt",
        "/leak.txt", "/outside/secret.txt", "/outside/www/../secret.txt",
        "/%252e%252e/secret.txt", "/..%c0%afsecret.txt", "/%c0%ae%c0%ae/secret.txt",
        "/index.html%00.txt", "/%00", "/.", "/..", "/...", "/....//secret.txt",
        "/etc/passwd", "/../../../../../../etc/passwd", "/%2e%2e/%2e%2e/%2e%2e/etc/passwd",
        "/vendor/../secret.txt", "/vendor/%2e%2e/%2e%2e/secret.txt", "/vendor/../../Makefile",
    };
    for (unsigned i = 0; i < sizeof attacks / sizeof attacks[0]; i++) {
        mm_reply r;
        int rc = mm_http(&server, NULL, attacks[i], NULL, 0, &r);
        if (rc == 0 && (r.status == 200 || strstr(r.body, SECRET) || strstr(r.body, "root:")))
            fail_msg("%s was served: %ld %.80s", attacks[i], r.status, r.body);
        if (rc == 0 && r.status != 404 && r.status != 400)
            fail_msg("%s: status %ld", attacks[i], r.status);
        mm_reply_free(&r);
    }
}

/* ---- load ----------------------------------------------------------------------------- */

typedef struct worker {
    const char *want;
    int mismatches, errors;
} worker;

static void *hammer(void *arg)
{
    worker *w = arg;
    for (int i = 0; i < 25; i++) {
        mm_reply r;
        const char *path = i % 2 ? "/api/exercises/vib-sdof-forced/solve?m=2&k=50&c=1&F0=3&omega=4"
                                 : "/api/health";
        if (mm_http(&server, NULL, path, NULL, 0, &r) != 0 || r.status != 200) {
            w->errors++;
        } else if (i % 2) {
            char *e = strstr(r.body, ",\"elapsed_us\"");
            if (e)
                *e = '\0';
            if (strcmp(r.body, w->want) != 0)
                w->mismatches++;
        }
        mm_reply_free(&r);
    }
    return NULL;
}

static void concurrent_requests_should_all_get_the_same_right_answer(void **state)
{
    (void)state;
    mm_reply ref;
    assert_int_equal(mm_http(&server, NULL, "/api/exercises/vib-sdof-forced/solve?m=2&k=50&c=1&F0=3&omega=4",
                             NULL, 0, &ref), 0);
    *strstr(ref.body, ",\"elapsed_us\"") = '\0';
    enum { T = 8 };
    pthread_t th[T];
    worker w[T];
    for (int i = 0; i < T; i++) {
        w[i] = (worker){ref.body, 0, 0};
        pthread_create(&th[i], NULL, hammer, &w[i]);
    }
    int errors = 0, mismatches = 0;
    for (int i = 0; i < T; i++) {
        pthread_join(th[i], NULL);
        errors += w[i].errors;
        mismatches += w[i].mismatches;
    }
    assert_int_equal(errors, 0);
    assert_int_equal(mismatches, 0);
    mm_reply_free(&ref);
}

static void a_server_over_its_connection_limit_should_answer_busy(void **state)
{
    (void)state;
    mm_fixture small;
    const char *extra[] = {"--max-connections", "1", NULL};
    assert_int_equal(mm_fixture_start(&small, extra), 0);
    /* connection A stays open (keep-alive); a request on B is over the limit */
    CURL *a = curl_easy_init(), *b = curl_easy_init();
    char url[128];
    snprintf(url, sizeof url, "http://127.0.0.1:%d/api/health", small.port);
    mm_reply ra = {0}, rb = {0};
    ra.body = calloc(1, 1);
    rb.body = calloc(1, 1);
    curl_easy_setopt(a, CURLOPT_URL, url);
    curl_easy_setopt(a, CURLOPT_WRITEFUNCTION, mm_collect);
    curl_easy_setopt(a, CURLOPT_WRITEDATA, &ra);
    curl_easy_setopt(b, CURLOPT_URL, url);
    curl_easy_setopt(b, CURLOPT_WRITEFUNCTION, mm_collect);
    curl_easy_setopt(b, CURLOPT_WRITEDATA, &rb);
    long sa = 0, sb = 0;
    assert_int_equal(curl_easy_perform(a), CURLE_OK);
    curl_easy_getinfo(a, CURLINFO_RESPONSE_CODE, &sa);
    assert_int_equal(curl_easy_perform(b), CURLE_OK);
    curl_easy_getinfo(b, CURLINFO_RESPONSE_CODE, &sb);
    assert_int_equal(sa, 200);
    assert_int_equal(sb, 503);
    expect_error(cJSON_Parse(rb.body), "busy", NULL);
    curl_easy_cleanup(a);
    curl_easy_cleanup(b);
    mm_reply_free(&ra);
    mm_reply_free(&rb);
    assert_int_equal(mm_fixture_stop(&small), 0);
}

int main(void)
{
    curl_global_init(CURL_GLOBAL_DEFAULT);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(health_catalog_and_metadata_should_answer),
        cmocka_unit_test(the_issue_example_should_give_the_steady_amplitude),
        cmocka_unit_test(every_error_of_the_api_table_should_come_as_json),
        cmocka_unit_test(wrong_methods_should_get_405_with_allow),
        cmocka_unit_test(post_bodies_should_be_checked_and_limited),
        cmocka_unit_test(get_and_post_should_give_the_same_answer),
        cmocka_unit_test(static_files_should_come_with_their_mime_types),
        cmocka_unit_test(nothing_outside_the_web_root_should_ever_be_served),
        cmocka_unit_test(concurrent_requests_should_all_get_the_same_right_answer),
        cmocka_unit_test(a_server_over_its_connection_limit_should_answer_busy),
    };
    int rc = cmocka_run_group_tests_name("http", tests, setup, teardown);
    curl_global_cleanup();
    return rc;
}
