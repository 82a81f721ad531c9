/* answers.c — every exercise's answer at its defaults and at N random
 * draws (the product's own generator, a fixed seed), one line each, with
 * the time-dependent fields (elapsed_us, and any method stat in ns or us)
 * blanked: two builds that print the same text give the same answers.
 * For refactoring: `make answers` before and after, then diff.
 *
 *   build/tools/answers [-n 20] [id ...] > answers.txt
 */
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
    int n = 20, first = 1;
    if (argc > 2 && strcmp(argv[1], "-n") == 0) {
        n = atoi(argv[2]);
        first = 3;
    }
    static mm_draw_set set;
    for (int e = 0; e < mm_exercise_count; e++) {
        const mm_exercise *ex = mm_exercises[e];
        if (first < argc) {
            int want = 0;
            for (int i = first; i < argc; i++)
                want |= strcmp(argv[i], ex->id) == 0;
            if (!want)
                continue;
        }
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
            one(ex, set.in, set.n, label);
        }
    }
    return 0;
}
