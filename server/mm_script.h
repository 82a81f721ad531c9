/* mm_script.h — an exercise as a readable Octave/MATLAB script (API.md:
 * GET /api/exercises/{id}/script.m).
 *
 * The source course was m-files that students ran and changed; every
 * exercise can be taken back there.  A script is written from the same
 * tables as the JSON answer, so a parameter or an output cannot exist in
 * one and not the other:
 *
 *   header      what it is, the request it reproduces, the versions it was
 *               written for (GNU Octave 7.3, MATLAB R2019b or later);
 *   parameters  one assignment per parameter, with the request's resolved
 *               values, label, unit and help as a comment; an expression
 *               becomes a vectorised function handle of its variables;
 *   limits      each parameter checked against the exercise's limits with
 *               the API's message, so that an edited script fails clearly;
 *   body        the exercise's own <name>.m (the model and the method,
 *               written out for a learner), which stores its answers in a
 *               struct `out` under their declared names;
 *   footer      one line per declared scalar the body stored:
 *               "name = value unit", value with 17 significant digits
 *               (enough to read back the same double).
 *
 * Joint limits (an exercise's check()) are not repeated in the script.
 */
#ifndef MM_SCRIPT_H
#define MM_SCRIPT_H

#include "mm_exercise.h"
#include "mm_json.h"

/* Write the script of ex for the resolved values vals (one per parameter,
 * in table order) and the exercise's body text into out (reset first).
 * query is the canonical query the script reproduces (may be ""); version
 * the server's.  Returns MM_OK, or MM_ETOOBIG when out overflows.
 * Cannot fail otherwise. */
int mm_script_write(const mm_exercise *ex, const mm_value *vals, const char *body,
                    const char *query, const char *version, mm_buf *out);

/* An expression of mm_expr's language (muParser: ^ * / on scalars, ln, rint,
 * min/max/sum/avg of any number of arguments, _pi, _e, != && ||) as a
 * vectorised MATLAB expression (.^ .* ./, log, floor(x + 0.5), min(a, min(b, c)), pi,
 * exp(1), ~= & |) into out.  Returns MM_OK, or MM_EVALUE when it has no
 * MATLAB form (the conditional c ? a : b), with err saying so. */
int mm_script_expr(const char *text, mm_buf *out, mm_error *err);

#endif
