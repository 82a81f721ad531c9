/* registry.c — every exercise, in the order of the book's contents.
 * To add one: declare it below and list it in mm_exercises[] at its section. */
#include <string.h>

#include "mm_exercise.h"

extern const mm_exercise mm_ex_vib_sdof_free;
extern const mm_exercise mm_ex_vib_sdof_forced;

const mm_exercise *const mm_exercises[] = {
    /* 5 Vibrations */
    &mm_ex_vib_sdof_free,
    &mm_ex_vib_sdof_forced,
};

const int mm_exercise_count = MM_COUNT(mm_exercises);

const mm_exercise *mm_exercise_find(const char *id)
{
    for (int i = 0; i < mm_exercise_count; i++)
        if (strcmp(mm_exercises[i]->id, id) == 0)
            return mm_exercises[i];
    return NULL;
}
