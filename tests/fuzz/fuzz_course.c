/* fuzz_course.c — a course file (mm_course.h) from arbitrary bytes.
 * Invariants: no crash; a refusal has a message that begins with the
 * file's name; an accepted course has its exercises in the registry, each
 * parameter's limits inside the built-in ones and its default inside its
 * own limits, and its assignments named and found by name. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "mm_course.h"
#include "mm_params.h"
#include "mm_result_impl.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size > 65536)
        return 0;
    mm_error err;
    mm_course *c = mm_course_parse((const char *)data, size, "f.json", &err);
    if (!c) {
        if (strncmp(err.msg, "f.json", 6) != 0 || err.code != MM_EVALUE)
            abort();
        return 0;
    }
    for (int i = 0; i < mm_course_exercise_count(c); i++) {
        const mm_exercise *ex = mm_course_exercise(c, i), *orig = mm_exercise_find(ex->id);
        if (!orig || ex->n_params != orig->n_params || mm_course_find(c, ex->id) != ex)
            abort();
        for (int k = 0; k < ex->n_params; k++) {
            const mm_param *p = &ex->params[k], *o = &orig->params[k];
            if (p->min < o->min || p->max > o->max || p->max_cols > o->max_cols || p->max_rows > o->max_rows)
                abort();
            mm_result arena;
            mm_result_init(&arena, 1 << 22);
            mm_value v;
            if (mm_param_default(p, &v, &arena, &err) != MM_OK)
                abort();
            if ((p->kind == MM_REAL || p->kind == MM_INT) && !(v.x >= p->min && v.x <= p->max))
                abort();
            mm_result_release(&arena);
        }
    }
    for (int i = 0; i < mm_course_assignment_count(c); i++) {
        const char *name = mm_course_assignment_name(c, i);
        if (!name || mm_course_assignment_find(c, name) != mm_course_assignment(c, i))
            abort();
    }
    mm_course_free(c);
    return 0;
}
