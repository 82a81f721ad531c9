/* mm_params.h — turn parameter text into validated values, for every
 * exercise alike.
 *
 * One path for all inputs: a query string value and a JSON body value are
 * both first made into text (a JSON number by its shortest round-trip form,
 * a JSON array of numbers as "1,2,3", nested arrays as "1,2;3,4"), then
 * parsed here.  So GET and POST cannot disagree.
 *
 * Text forms (API.md):
 *   real     12.5, -3e-4, or a constant expression: pi/2, 2*pi, sqrt(2)
 *   integer  the same, but it must be a whole number
 *   choice   one of the names listed in the parameter
 *   vector   1,2,3 (commas, spaces or semicolons; optional [ ])
 *   matrix   1,2,3;4,5,6 (rows by semicolons or new lines; optional [ ])
 *   expr     text, at most MM_PARAM_EXPR_MAX bytes (compiled by the exercise)
 * Errors name the parameter and say what would be valid:
 *   MM_EVALUE  "m must be a number (got 'abc')"
 *   MM_ERANGE  "m must be between 0.001 and 1000 kg; got -1"
 */
#ifndef MM_PARAMS_H
#define MM_PARAMS_H

#include <stddef.h>

#include "mm_exercise.h"

#define MM_PARAM_TEXT_MAX 65536   /* longest text of one value, bytes */
#define MM_PARAM_EXPR_MAX 512     /* longest expression, bytes */

/* Parse text (len bytes, need not be NUL-terminated, must not contain NUL)
 * as a value of p into *out; arrays and strings are taken from the arena of
 * res.  Returns MM_OK, MM_EVALUE, MM_ERANGE or MM_ENOMEM, with err filled. */
int mm_param_parse(const mm_param *p, const char *text, size_t len,
                   mm_value *out, mm_result *res, mm_error *err);

/* The default of p, parsed from its table entry.  A default that does not
 * parse is our bug: MM_EINTERNAL. */
int mm_param_default(const mm_param *p, mm_value *out, mm_result *res,
                     mm_error *err);

/* Check the table of an exercise: names unique and non-empty, min <= def <=
 * max, defaults parse.  For start-up and tests.  Returns MM_OK or
 * MM_EINTERNAL with a message naming the exercise and the parameter. */
int mm_params_check(const mm_exercise *ex, mm_error *err);

/* The kind's name as in API.md: "real", "integer", ... */
const char *mm_param_kind_name(mm_param_kind k);

#endif
