/* mm_pipeline.h — run an exercise through the real pipeline (text values
 * -> validation -> solve -> JSON) in-process, for the exercise tests.
 * Include after mm_test.h. */
#ifndef MM_PIPELINE_H
#define MM_PIPELINE_H

#include <cJSON.h>
#include <stdio.h>
#include <string.h>

#include "mm_api.h"

typedef struct answer {
    int status;
    cJSON *doc;          /* the answer or the error document, parsed */
} answer;

/* query: "a=1&b=2" (no URL encoding; values must not contain '&'). */
static answer solve(const char *id, const char *query)
{
    const mm_exercise *ex = mm_exercise_find(id);
    if (!ex)
        fail_msg("%s is not registered", id);
    static char buf[4096];
    snprintf(buf, sizeof buf, "%s", query);
    mm_input in[MM_MAX_PARAMS];
    int n = 0;
    for (char *save = NULL, *tok = strtok_r(buf, "&", &save); tok && n < MM_MAX_PARAMS;
         tok = strtok_r(NULL, "&", &save)) {
        char *eq = strchr(tok, '=');
        assert_non_null(eq);
        *eq = '\0';
        in[n] = (mm_input){tok, eq + 1, strlen(tok), strlen(eq + 1)};
        n++;
    }
    mm_buf out;
    mm_buf_init(&out, MM_ANSWER_MAX);
    answer a = {.status = mm_api_solve(ex, in, n, &out)};
    a.doc = cJSON_Parse(out.p);
    if (!a.doc)
        fail_msg("%s?%s: the answer is not JSON", id, query);
    mm_buf_free(&out);
    return a;
}

/* Solve and insist on 200 with at least one check, every one passed. */
static cJSON *solve_ok(const char *id, const char *query)
{
    answer a = solve(id, query);
    if (a.status != 200) {
        char *s = cJSON_PrintUnformatted(a.doc);
        fail_msg("%s?%s: status %d: %.300s", id, query, a.status, s);
    }
    const cJSON *c;
    int n = 0;
    cJSON_ArrayForEach(c, cJSON_GetObjectItem(a.doc, "checks")) {
        n++;
        if (!cJSON_IsTrue(cJSON_GetObjectItem(c, "passed"))) {
            char *s = cJSON_PrintUnformatted(c);
            fail_msg("%s?%s: check failed: %s", id, query, s);
        }
    }
    if (n == 0)
        fail_msg("%s?%s: no checks", id, query);
    return a.doc;
}

#endif
