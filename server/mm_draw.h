/* mm_draw.h — random parameter values inside an exercise's limits, from a
 * seeded generator: the same seed gives the same values on every machine.
 *
 * The exercise tests draw random requests with it (tests/unit/
 * test_exercises.c), so do the load test and the worst-case bench, and an
 * assignment draws each student's variant with it (the seed made from the
 * assignment and the student with mm_draw_seed), so a variant is the same
 * for the same student, always.
 *
 * The generator is xorshift64* (Vigna 2016): 64 bits of state, period
 * 2^64 - 1, good enough for test values and variants; not for secrets.
 *
 * How a value is drawn (mm_draw_text):
 *   real, integer  log-uniform when min > 0 and max/min > 100, uniform
 *                  otherwise; integers rounded; clamped to [min, max];
 *                  written in the shortest text that reads back the same
 *   choice         uniform over the choices
 *   expression     the default (a random formula is no exercise)
 *   vector, matrix the default's shape, each element times a factor
 *                  uniform in [0.5, 1.5] (a symmetric matrix stays
 *                  symmetric), clamped to [min, max]; "1,2;3,4"
 * Every value it writes parses (mm_params.h) inside the limits of p; joint
 * limits (the exercise's check) are for mm_draw_request.
 */
#ifndef MM_DRAW_H
#define MM_DRAW_H

#include <stddef.h>
#include <stdint.h>

#include "mm_api.h"

typedef struct mm_rng {
    uint64_t s;          /* never 0 */
} mm_rng;

/* Seed g; a seed of 0 is replaced by a fixed non-zero constant. */
void mm_rng_seed(mm_rng *g, uint64_t seed);

/* Uniform in [0, 1), 53 bits. */
double mm_rng_uniform(mm_rng *g);

/* A seed from two texts (either may be NULL), e.g. an assignment's name
 * and a student's id: FNV-1a over both with a separator, then one round of
 * splitmix64 so that near texts give unrelated seeds. */
uint64_t mm_draw_seed(const char *a, const char *b);

/* A real or integer value of p as above (p->kind MM_REAL or MM_INT). */
double mm_draw_number(const mm_param *p, mm_rng *g);

/* A value of p as parameter text into out (size bytes).  Returns MM_OK,
 * MM_ETOOBIG when out is too small, or MM_EINTERNAL when p's default does
 * not parse (a registry bug).  On error out holds "". */
int mm_draw_text(const mm_param *p, mm_rng *g, char *out, size_t size);

/* A whole request: every parameter of ex drawn (texts[k] for parameter k,
 * in[k] pointing at it), resolved, and drawn again while the exercise's
 * joint check refuses it, up to `tries` times (a vector or matrix the
 * check names three times in a row keeps its default from then on: a
 * random truss rarely holds together).  Returns MM_OK, or the last
 * refusal (MM_ERANGE/MM_EVALUE, err filled) when every try was refused. */
#define MM_DRAW_TEXT_MAX 8192
typedef struct mm_draw_set {
    mm_input in[MM_MAX_PARAMS];
    char texts[MM_MAX_PARAMS][MM_DRAW_TEXT_MAX];
    int n;
} mm_draw_set;

int mm_draw_request(const mm_exercise *ex, mm_rng *g, int tries, mm_draw_set *set, mm_error *err);

#endif
