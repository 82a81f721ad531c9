/* num_draws.c — the requests the reference harness (num_ref.py) sends: for
 * each chapter-1 exercise named on the command line (all eight when none),
 * one line "id<TAB>name=value<TAB>..." per random draw, made by the
 * product's own generator (server/mm_draw.h) from a fixed seed, so a run
 * against an old server and one against a new one send the same requests.
 *
 *   build/ref/num_draws [-n 200] [id ...]
 *
 * Values are raw parameter text (not URL-encoded); the harness encodes them.
 * A draw the exercise's joint check refuses 50 times is printed as
 * "id<TAB>#refused: message" (none do today). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mm_draw.h"
#include "mm_exercise.h"

static const char *const chapter1[] = {
    "num-complex", "num-linear-system", "num-eigen", "num-poly-roots",
    "num-polyfit", "num-nonlinear-roots", "num-newmark", "num-plot",
};

static int print_draws(const char *id, int n)
{
    const mm_exercise *ex = mm_exercise_find(id);
    if (!ex) {
        fprintf(stderr, "num_draws: no exercise %s\n", id);
        return 1;
    }
    mm_rng g;
    mm_rng_seed(&g, mm_draw_seed("num-ref", id));
    static mm_draw_set set;                     /* 8192 * params bytes: not on the stack */
    for (int i = 0; i < n; i++) {
        mm_error err = {0};
        if (mm_draw_request(ex, &g, 50, &set, &err) != MM_OK) {
            printf("%s\t#refused: %s\n", id, err.msg);
            continue;
        }
        printf("%s", id);
        for (int k = 0; k < set.n; k++)
            printf("\t%.*s=%.*s", (int)set.in[k].name_len, set.in[k].name,
                   (int)set.in[k].text_len, set.in[k].text);
        printf("\n");
    }
    return 0;
}

int main(int argc, char **argv)
{
    int n = 200, first = 1, rc = 0;
    if (argc > 2 && strcmp(argv[1], "-n") == 0) {
        n = atoi(argv[2]);
        first = 3;
    }
    if (first >= argc) {
        for (size_t i = 0; i < sizeof chapter1 / sizeof chapter1[0]; i++)
            rc |= print_draws(chapter1[i], n);
    } else {
        for (int i = first; i < argc; i++)
            rc |= print_draws(argv[i], n);
    }
    return rc;
}
