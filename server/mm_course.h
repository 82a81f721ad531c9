/* mm_course.h — a course file: what one class sees of mechmat.
 *
 * One JSON file (read with cJSON), all keys optional:
 *
 *   {
 *     "title": "Vibrations, autumn term",       the site's title
 *     "language": "en",                          BCP 47 tag of the texts
 *     "base_path": "/mech/",                     where the site lives on its host
 *     "exercises": [                             which exercises, in this order
 *       "vib-sdof-free",                         an id: as built in
 *       {"id": "vib-sdof-forced",                or an id with overrides,
 *        "params": {"m": {"default": 2, "min": 0.5, "max": 10},
 *                   "wave": {"default": "square"}}}
 *     ],
 *     "assignments": [ {"name": "hw1", ...}, ... ]
 *   }
 *
 * Without "exercises" every exercise appears, in book order.  A parameter
 * override may set "default" (any kind: a number, a text in the API's text
 * form, or JSON arrays for vectors and matrices), "min" and "max" (real,
 * integer, vector and matrix elements), "max_length" (vector) and
 * "max_rows" / "max_cols" (matrix): limits only narrower than the built-in
 * ones, and the default inside them; the exercise's joint check still
 * applies.  An exercise left out is not served at all (404), so the course
 * is the whole site.
 *
 * "assignments" is an array of objects, each with a unique "name"
 * (letters, digits, '-', '_'); the rest of each object is kept as written
 * for the assignments (mm_course_assignment*) to read.
 *
 * A file that breaks any rule is refused as a whole with the line and the
 * reason ("course.json:12: m: min 0.0001 is below the built-in 0.001"),
 * and a server that reloads it (SIGHUP) keeps serving the course it had.
 */
#ifndef MM_COURSE_H
#define MM_COURSE_H

#include <cJSON.h>
#include <stddef.h>

#include "mm_exercise.h"

#define MM_COURSE_MAX_BYTES (4u << 20)    /* longest course file */

typedef struct mm_course mm_course;

/* The built-in course: every exercise in book order, built-in parameters,
 * no assignments.  NULL when out of memory. */
mm_course *mm_course_builtin(void);

/* Read and check a course file; NULL with err set ("PATH:LINE: reason",
 * MM_EVALUE for a file that breaks a rule, MM_ENOTFOUND when it cannot be
 * read). */
mm_course *mm_course_load(const char *path, mm_error *err);

/* The same from text; name stands for the file in messages. */
mm_course *mm_course_parse(const char *text, size_t len, const char *name, mm_error *err);

void mm_course_free(mm_course *c);

/* title ("mechmat" when none), language ("en"), base path (starts and
 * ends with '/': "/" when none). */
const char *mm_course_title(const mm_course *c);
const char *mm_course_language(const mm_course *c);
const char *mm_course_base_path(const mm_course *c);

/* A digest of the file's text (22 characters), "builtin" for the built-in
 * course: tells which course a server serves. */
const char *mm_course_digest(const mm_course *c);

/* The exercises in course order, overrides applied: the same solve and
 * outputs as the registry's, with the course's parameter table.  The
 * pointers live as long as c. */
int mm_course_exercise_count(const mm_course *c);
const mm_exercise *mm_course_exercise(const mm_course *c, int i);
/* NULL when the course does not have id. */
const mm_exercise *mm_course_find(const mm_course *c, const char *id);

/* Assignments as written in the file (objects), in file order. */
int mm_course_assignment_count(const mm_course *c);
const cJSON *mm_course_assignment(const mm_course *c, int i);
const char *mm_course_assignment_name(const mm_course *c, int i);
/* NULL when there is none of that name. */
const cJSON *mm_course_assignment_find(const mm_course *c, const char *name);

/* The line in the file where node (any node of an assignment) begins, for
 * messages; 0 when unknown. */
int mm_course_line(const mm_course *c, const cJSON *node);

#endif
