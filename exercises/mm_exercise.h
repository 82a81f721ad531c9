/* mm_exercise.h — what an exercise declares and how it answers.
 *
 * An exercise is one file, exercises/<chapter>/<name>.c, with its theory in
 * <name>.md beside it.  It declares
 *   - a parameter table (mm_param): name, label, unit, kind, default,
 *     limits, help.  The server parses and validates every value against
 *     this table *before* solve is called, and the web form is generated
 *     from it, so the limits live in one place;
 *   - a solve function that receives validated values (mm_value, one per
 *     parameter, in table order) and fills an mm_result through the builder
 *     functions below.  It never sees JSON or HTTP.
 *
 * Memory: everything an exercise needs during solve (series, tables, scratch
 * arrays) comes from mm_res_alloc(), a per-request arena freed in one go by
 * the server after the answer is written.  The arena has a cap; when it is
 * reached the allocation returns NULL and solve returns MM_ENOMEM (the caps
 * on the parameters should make that impossible).
 *
 * Thread safety: solve may run on many threads at once.  It reads only its
 * arguments; no static mutable state.
 */
#ifndef MM_EXERCISE_H
#define MM_EXERCISE_H

#include <stddef.h>
#include <stdint.h>

#include "mm_status.h"

/* ---- parameters ---------------------------------------------------------- */

typedef enum mm_param_kind {
    MM_REAL,     /* a double in [min, max]; text may be a constant expression: pi/2 */
    MM_INT,      /* an integer in [min, max] */
    MM_CHOICE,   /* one of choices[]; the value is its index */
    MM_VECTOR,   /* 1..max_cols numbers, each in [min, max]: "1,2,3" */
    MM_MATRIX,   /* rows x cols numbers, each in [min, max]: "1,2;3,4" */
    MM_EXPR      /* an expression of the variables in vars: "x^3+sin(x)-2" */
} mm_param_kind;

typedef struct mm_param {
    const char *name;     /* as in the URL: "m" */
    const char *label;    /* for a learner: "mass" */
    const char *unit;     /* SI unit, "" when dimensionless */
    mm_param_kind kind;
    double def;           /* default of MM_REAL / MM_INT / MM_CHOICE (index) */
    double min, max;      /* limits of the value, or of each element */
    const char *def_text; /* default of MM_VECTOR / MM_MATRIX / MM_EXPR, as text */
    const char *const *choices; /* MM_CHOICE: NULL-terminated list of names */
    int max_rows;         /* MM_MATRIX: most rows (MM_VECTOR: ignored) */
    int max_cols;         /* MM_VECTOR: most elements; MM_MATRIX: most columns */
    const char *vars;     /* MM_EXPR: comma-separated variable names: "x" or "t" */
    const char *help;     /* one sentence: what it is, what changes with it */
} mm_param;

/* A validated value handed to solve.  For MM_VECTOR rows = 1, cols = n; for
 * MM_MATRIX data is row-major rows x cols.  For MM_CHOICE x is the index and
 * text the name; for MM_EXPR text is the expression (compile it with
 * mm_expr from solvers/).  Pointers stay valid until the request ends. */
typedef struct mm_value {
    double x;
    const double *data;
    int rows, cols;
    const char *text;
} mm_value;

/* ---- results ------------------------------------------------------------- */

typedef struct mm_result mm_result;   /* opaque, owned by the server */

typedef struct mm_series {
    double *x, *y;        /* n points each, to be filled by the exercise */
    int n;
} mm_series;

typedef struct mm_table {
    double *cell;         /* nrows x ncols, row-major, to be filled */
    const char **text;    /* optional text per cell (NULL = use the number);
                             allocated with the table, all NULL at first */
    int nrows, ncols;
} mm_table;

/* Arena allocation, zero-filled.  NULL when the request's memory cap would be
 * passed.  Freed by the server when the request ends; never free it. */
void *mm_res_alloc(mm_result *r, size_t bytes);

/* A copy of s in the arena (NULL if the cap is reached). */
char *mm_res_strdup(mm_result *r, const char *s);

/* Scalars: the numbers that end the solution.  Returns MM_OK or MM_ENOMEM.
 * A non-finite value is refused later, when the answer is written (422). */
int mm_res_scalar(mm_result *r, const char *name, const char *label,
                  const char *unit, double value);

/* A scalar with a word beside the number, e.g. regime 0 "underdamped".
 * text is copied into the arena.  (name, label and unit of every builder
 * function are kept as pointers: pass string literals.) */
int mm_res_scalar_text(mm_result *r, const char *name, const char *label,
                       const char *unit, double value, const char *text);

/* A series of n points to plot; x and y arrays are allocated in the arena.
 * Returns NULL when out of memory.  Keep n to what a plot can show (a few
 * hundred to a few thousand). */
mm_series *mm_res_series(mm_result *r, const char *name, const char *label,
                         const char *unit, const char *x_label,
                         const char *x_unit, int n);

/* A table; columns and units are arrays of ncols strings (copied pointers:
 * pass string literals or arena strings).  NULL when out of memory. */
mm_table *mm_res_table(mm_result *r, const char *name, int nrows, int ncols,
                       const char *const *columns, const char *const *units);

/* Checks: numerical value against an independent reference.
 * rel: passed when |value-ref| <= tol*|ref|   (tolerance is relative)
 * abs: passed when |value-ref| <= tol          (tolerance is absolute)
 * A failed check is reported, never hidden.  Returns MM_OK or MM_ENOMEM. */
int mm_res_check_rel(mm_result *r, const char *name, double value,
                     double reference, double tol);
int mm_res_check_abs(mm_result *r, const char *name, double value,
                     double reference, double tol);

/* The method: its name and step (0 when not a stepping method); further
 * figures (steps, evaluations, rejected, error_estimate, ...) by
 * mm_res_method_stat.  Returns MM_OK or MM_ENOMEM. */
int mm_res_method(mm_result *r, const char *name, double step);
int mm_res_method_stat(mm_result *r, const char *key, double value);

/* A warning for the learner ("the matrix is nearly singular: cond = 3e16"). */
int mm_res_warn(mm_result *r, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* ---- the exercise -------------------------------------------------------- */

typedef int (*mm_solve_fn)(const mm_value *in, mm_result *res, mm_error *err);

/* Limits that join several parameters (the number of periods t_end spans,
 * a matrix that must be square...).  Called after every value passed its own
 * limits and before solve; no side effects.  Returns MM_OK, or MM_ERANGE /
 * MM_EVALUE naming the parameter to change and saying what would be valid.
 * The random-parameter tests draw values inside the table's limits and keep
 * the draws this accepts. */
typedef int (*mm_check_fn)(const mm_value *in, mm_error *err);

typedef struct mm_exercise {
    const char *id;        /* canonical id: "vib-sdof-forced" */
    int chapter;           /* 1 numerical basics .. 5 vibrations */
    const char *section;   /* "5.9.2" */
    const char *title;
    const char *summary;   /* one line for the catalog */
    const char *tags;      /* comma-separated */
    const char *theory;    /* path of the Markdown file from the source root */
    const mm_param *params;
    int n_params;
    const char *const *references; /* NULL-terminated, may be NULL */
    mm_check_fn check;     /* may be NULL */
    mm_solve_fn solve;
} mm_exercise;

#define MM_COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* The registry (exercises/registry.c), in book order. */
extern const mm_exercise *const mm_exercises[];
extern const int mm_exercise_count;
const mm_exercise *mm_exercise_find(const char *id);

#endif
