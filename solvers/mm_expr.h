/* mm_expr.h — expressions typed by a learner ("x^3+sin(x)-2"), compiled
 * once per request and evaluated fast, over libmuparser's C API.
 *
 * Language (muParser 2.3): numbers (1, 2.5, 1e-3), the variables the caller
 * names, the constants pi and e (also spelt _pi and _e, muParser's names,
 * here with the full double value: muParser's own stop at 12 digits),
 * operators + - * / ^ (power, right associative: 2^3^2 = 512; -2^2 = -4),
 * comparisons < <= > >= == != and && || giving 1 or 0, the conditional
 * c ? a : b, parentheses, and the functions sin cos tan asin acos atan
 * atan2(y,x) sinh cosh tanh asinh acosh atanh exp sqrt abs sign rint, ln
 * and log (both natural, as in MATLAB), log10 log2, and min max sum avg
 * with any number of arguments.
 * Angles are in radians.  '=' (assignment in muParser) and ',' at the top
 * level (several results) are refused.
 *
 * What evaluation can produce: muParser follows IEEE arithmetic and never
 * reports an error while evaluating: 1/0 gives inf, 0/0 and sqrt(-1) give
 * NaN, ln(0) gives -inf, exp(1000) overflows to inf.  This module returns
 * such values as they are: THE CALLER CHECKS isfinite() and rejects them
 * (an exercise turns them into MM_ENONFINITE or a warning, and never sends
 * NaN to the browser).  mm_expr_eval_const is the exception: it is a number
 * parser and refuses a non-finite value itself.
 *
 * Evaluation always terminates, in time proportional to the length of the
 * text: muParser has no loops, no recursion and no user-defined functions;
 * the text compiles to a linear bytecode with at most one instruction per
 * token, run once per evaluation, on explicit stacks (so deep nesting such
 * as 250 levels of parentheses cannot overflow the C stack either).  With
 * MM_EXPR_MAX_LEN characters, one evaluation is bounded by a few
 * microseconds (tests/unit/test_expr.c measures a worst case).
 *
 * Threads: an mm_expr belongs to one thread at a time (evaluation writes
 * the variable values into it); compile one per request.  Different
 * handles may be used concurrently: each has its own muParser instance,
 * and errors are read from that handle only (mupError, mupGetErrorCode,
 * mupGetErrorPos).  This module never calls mupGetErrorMsg, mupGetErrorToken,
 * mupGetExpr or mupGetExprVar: in muParser 2.3.3 they return a pointer to
 * one static buffer shared by all handles, a data race between threads;
 * messages are written here from the error code, the position and the
 * caller's own copy of the text.  Bulk evaluation loops over mupEval rather
 * than calling mupEvalBulk, which in Debian's build starts OpenMP threads
 * of its own inside whichever server thread called it.
 *
 * Errors (mm_error; param is left empty, since only the caller knows which
 * parameter the text came from, and sets it):
 *   MM_EVALUE  a syntax error, with the position counted in characters from
 *              1 and what was found: "bad expression at position 3:
 *              unexpected operator '*'"; an unknown variable or function,
 *              named, with the names that are allowed; an empty text; a
 *              character that is not printable ASCII;
 *   MM_ERANGE  text longer than MM_EXPR_MAX_LEN characters;
 *   MM_ENOMEM  allocation failed;
 *   MM_EINTERNAL the caller's variable list is invalid (our bug: too many
 *              names, not identifiers, duplicates, or clashing with pi, e
 *              or a function name).
 */
#ifndef MM_EXPR_H
#define MM_EXPR_H

#include <stddef.h>

#include "mm_status.h"

#define MM_EXPR_MAX_LEN   512   /* characters of expression text */
#define MM_EXPR_MAX_VARS  8     /* variables of one expression */
#define MM_EXPR_MAX_NAME  31    /* characters of a variable name */

typedef struct mm_expr mm_expr;   /* opaque: a compiled expression */

/* Validate without allocating: text non-empty, at most MM_EXPR_MAX_LEN
 * characters, printable ASCII only, no assignment '='; variable names
 * valid.  Syntax is checked by mm_expr_compile.  No side effects. */
int mm_expr_check(const char *text, const char *const *var_names,
                  size_t nvars, mm_error *err);

/* Compile text as a function of the variables var_names[0..nvars-1]
 * (nvars may be 0; var_names is then ignored).  On success *out is a new
 * expression the caller owns and releases with mm_expr_free; on failure
 * *out is NULL.  The text and names are copied (the caller's strings need
 * not outlive the call).  Errors as listed in the file comment. */
int mm_expr_compile(const char *text, const char *const *var_names,
                    size_t nvars, mm_expr **out, mm_error *err);

/* Release an expression.  mm_expr_free(NULL) does nothing. */
void mm_expr_free(mm_expr *e);

/* Number of variables the expression was compiled with.  Cannot fail. */
size_t mm_expr_nvars(const mm_expr *e);

/* Value at vars[0..nvars-1] (in the order of var_names; vars may be NULL
 * when nvars is 0).  Cannot fail; the result may be inf or NaN (see the
 * file comment: the caller checks). */
double mm_expr_eval(mm_expr *e, const double *vars);

/* The value at vars, as mm_expr_eval, with an ESTIMATE of its error in
 * *err: twice the largest change when the expression is evaluated again
 * in the three directed rounding modes (Kahan's test of how much the
 * rounding of each operation is amplified), plus half the change that a
 * relative 2 eps in each variable makes (which stands for the rounding of
 * constants such as pi and of the variables), plus u |value|.  An estimate,
 * not a bound: a systematic error that no rounding mode and no change of
 * the inputs reveals is not seen.  Costs 4 + 2 nvars evaluations; restores
 * the caller's rounding mode.  *err is inf when the value is not finite.
 * Cannot fail. */
double mm_expr_eval_err(mm_expr *e, const double *vars, double *err);

/* out[i] = value at the i-th row of vars, i < n, where vars is row-major
 * n x nvars (for one variable simply the array of its values).  Same
 * result as n calls of mm_expr_eval, at about 15 ns a point for
 * "x^3+sin(x)-2".  Cannot fail; inf and NaN as for mm_expr_eval. */
void mm_expr_eval_bulk(mm_expr *e, const double *vars, size_t n,
                       double *out);

/* Evaluate a constant expression such as "pi/2" or "2*e^-1" (no
 * variables) into *value.  Errors as mm_expr_compile, plus MM_EVALUE when
 * the value is not finite ("1/0").  On error *value is unchanged. */
int mm_expr_eval_const(const char *text, double *value, mm_error *err);

#endif
