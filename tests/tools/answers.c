/* answers.c — every exercise's answer at its defaults and at N random
 * draws (the product's own generator, a fixed seed), one line each, with
 * the time-dependent fields (elapsed_us, and any method stat in ns or us)
 * blanked: two builds that print the same text give the same answers.
 * For refactoring: `make answers` before and after, then diff.
 *
 *   build/tools/answers [-n 20] [id ...] > answers.txt
 *
 * With --checks, a tolerance study for whoever writes an exercise: over the
 * defaults and N draws, each check's worst use of its tolerance (its error
 * over its tolerance; 1 is the edge) and the request it was seen at, and
 * the draws that were refused or failed:
 *
 *   build/tools/answers --checks -n 400 sta-ladder
 *
 * It ends "study: N passed, N failed" (one per exercise) and exits 1 when an
 * exercise failed: a check that did not pass, or an answer other than 200
 * or a 400 that names its parameter (a limit met while solving, "reduce h").
 * A draw lies inside every limit, so a learner could send it; a failed
 * check there is a wrong number or a tolerance that is not a bound, and a
 * 422 or 500 an answer lost (`make study`, 2,000 draws each).
 */
#include <cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mm_api.h"
#include "mm_draw.h"
#include "mm_exercise.h"

/* blank the value after each "key": that the machine's speed decides */
static void blank(char *s, const char *key)
{
    size_t k = strlen(key);
    for (char *p = strstr(s, key); p; p = strstr(p + k, key)) {
        char *v = p + k, *e = v;
        while (*e && *e != ',' && *e != '}')
            e++;
        if (e > v) {
            *v = '0';
            memmove(v + 1, e, strlen(e) + 1);
        }
    }
}

/* the --checks study: worst use of each check's tolerance */
#define MAX_CHECKS 256
typedef struct study {
    int n, runs, failed, bad;   /* bad: checks failed, answers lost */
    char key[MAX_CHECKS][160], name[MAX_CHECKS][160], at[MAX_CHECKS][1024];
    double worst[MAX_CHECKS];
} study;

/* A check named by a value ("zeta = 0.1: peak height ...") is one check
 * over the draws: its key has "= #" for each number after an equals sign
 * (the name shown is the one at the worst draw). */
static void check_key(const char *name, char *key, size_t size)
{
    size_t k = 0;
    for (const char *p = name; *p && k + 1 < size;) {
        key[k++] = *p;
        if (*p++ != '=')
            continue;
        while (*p == ' ' && k + 1 < size)
            key[k++] = *p++;
        const char *q = p + (*p == '-' || *p == '+');
        if (*q < '0' || *q > '9')
            continue;
        while ((*q >= '0' && *q <= '9') || *q == '.' || ((*q == 'e' || *q == 'E') && q[1] && strchr("+-0123456789", q[1])) ||
               ((*q == '+' || *q == '-') && (q[-1] == 'e' || q[-1] == 'E')))
            q++;
        if (k + 1 < size)
            key[k++] = '#';
        p = q;
    }
    key[k] = '\0';
}

static void query_text(const mm_input *in, int n, char *out, size_t size)
{
    out[0] = '\0';
    for (int k = 0; k < n; k++) {
        size_t l = strlen(out);
        snprintf(out + l, size - l, "%s%.*s=%.*s", k ? "&" : "", (int)in[k].name_len, in[k].name,
                 (int)in[k].text_len, in[k].text);
    }
}

static void learn(study *st, const mm_exercise *ex, const mm_input *in, int n)
{
    mm_buf out;
    mm_buf_init(&out, MM_ANSWER_MAX);
    int status = mm_api_solve(ex, in, n, &out);
    char q[1024];
    query_text(in, n, q, sizeof q);
    cJSON *doc = cJSON_Parse(out.p ? out.p : "");
    mm_buf_free(&out);
    st->runs++;
    if (status != 200 || !doc) {
        st->failed++;
        /* a limit met while solving names its parameter: a refusal, not a loss */
        const cJSON *e = doc ? cJSON_GetObjectItem(doc, "error") : NULL;
        int named = status == 400 && cJSON_IsString(cJSON_GetObjectItem(e, "param"));
        st->bad += !named;
        printf("   status %d%s at %s\n", status, named ? "" : " (an answer lost)", n ? q : "the defaults");
        cJSON_Delete(doc);
        return;
    }
    const cJSON *c;
    cJSON_ArrayForEach(c, cJSON_GetObjectItem(doc, "checks")) {
        const char *name = cJSON_GetStringValue(cJSON_GetObjectItem(c, "name"));
        double e = cJSON_GetNumberValue(cJSON_GetObjectItem(c, "abs_error"));
        double tol = cJSON_GetNumberValue(cJSON_GetObjectItem(c, "tolerance"));
        const char *kind = cJSON_GetStringValue(cJSON_GetObjectItem(c, "tolerance_kind"));
        if (kind && strcmp(kind, "relative") == 0)
            tol *= fabs(cJSON_GetNumberValue(cJSON_GetObjectItem(c, "reference")));
        double use = tol > 0 ? e / tol : (e > 0 ? INFINITY : 0);
        if (!cJSON_IsTrue(cJSON_GetObjectItem(c, "passed"))) {
            st->bad++;
            printf("   FAILED %s at %s\n", name ? name : "?", n ? q : "the defaults");
        }
        char key[160];
        check_key(name ? name : "?", key, sizeof key);
        int k = 0;
        while (k < st->n && strcmp(st->key[k], key) != 0)
            k++;
        if (k == st->n && st->n < MAX_CHECKS) {
            snprintf(st->key[k], sizeof st->key[k], "%s", key);
            st->worst[k] = -1;
            st->n++;
        }
        if (k < st->n && (use > st->worst[k] || isnan(use))) {
            st->worst[k] = use;
            snprintf(st->name[k], sizeof st->name[k], "%s", name ? name : "?");
            snprintf(st->at[k], sizeof st->at[k], "%s", n ? q : "the defaults");
        }
    }
    cJSON_Delete(doc);
}

static void one(const mm_exercise *ex, const mm_input *in, int n, const char *label)
{
    mm_buf out;
    mm_buf_init(&out, MM_ANSWER_MAX);
    int status = mm_api_solve(ex, in, n, &out);
    char *s = out.p ? out.p : (char *)"";
    blank(s, "\"elapsed_us\":");
    blank(s, "_ns\":");
    blank(s, "_us\":");
    printf("%s %s %d %s\n", ex->id, label, status, s);
    mm_buf_free(&out);
}

int main(int argc, char **argv)
{
    int n = 20, first = 1, checks = 0;
    if (argc > first && strcmp(argv[first], "--checks") == 0)
        checks = 1, first++;
    if (argc > first + 1 && strcmp(argv[first], "-n") == 0) {
        n = atoi(argv[first + 1]);
        first += 2;
    }
    static mm_draw_set set;
    static study st;
    int passed = 0, failed = 0;
    for (int e = 0; e < mm_exercise_count; e++) {
        const mm_exercise *ex = mm_exercises[e];
        if (first < argc) {
            int want = 0;
            for (int i = first; i < argc; i++)
                want |= strcmp(argv[i], ex->id) == 0;
            if (!want)
                continue;
        }
        if (checks) {
            memset(&st, 0, sizeof st);
            printf("%s: every check's worst error / tolerance over the defaults and %d draws\n", ex->id, n);
            learn(&st, ex, NULL, 0);
        } else
            one(ex, NULL, 0, "defaults");
        mm_rng g;
        mm_rng_seed(&g, mm_draw_seed("answers", ex->id));
        for (int i = 0; i < n; i++) {
            mm_error err = {0};
            char label[32];
            snprintf(label, sizeof label, "draw%d", i);
            if (mm_draw_request(ex, &g, 50, &set, &err) != MM_OK) {
                printf("%s %s refused %s\n", ex->id, label, err.msg);
                continue;
            }
            if (checks)
                learn(&st, ex, set.in, set.n);
            else
                one(ex, set.in, set.n, label);
        }
        for (int k = 0; checks && k < st.n; k++)
            printf("   %8.3g  %s\n            at %s\n", st.worst[k], st.name[k], st.at[k]);
        if (checks) {
            printf("   %d answers, %d not 200\n", st.runs, st.failed);
            if (st.bad)
                printf("   %s: %d failed checks or answers lost\n", ex->id, st.bad);
            passed += !st.bad, failed += !!st.bad;
        }
    }
    if (checks)
        printf("study: %d passed, %d failed\n", passed, failed);
    return failed > 0;
}
