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

/* ---- outputs: declared, not discovered ------------------------------------ */

/* Every scalar, series, table and animation an answer of the exercise can
 * carry is declared in its output table; the builders below refer to an
 * entry by its index, so an answer cannot carry an output its metadata does
 * not list, and the names, labels and units live in one place.  The
 * metadata (GET /api/exercises/{id}), OpenAPI, assignments and the Octave
 * script are all written from this table.
 *
 *   enum { O_OMEGA_N, O_X, O_MODES, O_ANIM };
 *   static const char *const mode_cols[] = {"mode", "omega", NULL}, *const mode_units[] = {"", "rad/s", NULL};
 *   static const mm_output outputs[] = {
 *       [O_OMEGA_N] = MM_SCALAR("omega_n", "natural frequency", "rad/s", .flags = MM_ANSWER | MM_EXACT),
 *       [O_X]       = MM_SERIES("x", "displacement", "m", "t", "s", .figure = "response"),
 *       [O_MODES]   = MM_TABLE("modes", "natural modes", mode_cols, mode_units),
 *       [O_ANIM]    = MM_ANIMATION("the mass on its spring"),
 *   };
 *
 * A family is one entry for several outputs that differ by an index or a
 * key: name and label hold one %d (indices first..last) or one %s (each of
 * keys[], NULL-terminated), e.g. MM_SCALAR("x%d", "x_%d of the solution",
 * "", .first = 1, .last = 12).  The metadata lists every member by name. */

typedef enum mm_output_kind {
    MM_OUT_SCALAR = 1,
    MM_OUT_SERIES,
    MM_OUT_TABLE,
    MM_OUT_ANIMATION
} mm_output_kind;

/* flags of an output */
enum {
    MM_ANSWER = 1u << 0,  /* a scalar a learner writes at the end of the solution:
                             assignments may ask for it */
    MM_EXACT = 1u << 1    /* a scalar that is exact (a closed form, exact to
                             rounding): "exact": true unless solve says otherwise */
};

typedef struct mm_output {
    const char *name;     /* as in the JSON: "omega_n" (a family: "x%d", "x_%s") */
    const char *label;    /* for a learner: "natural frequency" */
    const char *unit;     /* SI unit of the value (series: of y), "" if none */
    mm_output_kind kind;
    unsigned flags;       /* MM_ANSWER, MM_EXACT */
    int first, last;      /* a "%d" family: the indices */
    const char *const *keys;  /* a "%s" family: NULL-terminated keys */
    /* series */
    const char *x_label, *x_unit;
    const char *figure;   /* series with the same figure share one plot */
    const char *mark;     /* "line" (default), "dots", "step", "bars" */
    const char *role;     /* "reference": drawn as a reference under the result */
    const char *x_scale, *y_scale;  /* "linear" (default) or "log" */
    const char *aspect;   /* "equal" for paths in a plane */
    /* table: NULL-terminated column names and their units (same count) */
    const char *const *columns, *const *units;
} mm_output;

#define MM_SCALAR(nm, lb, un, ...) \
    {.name = (nm), .label = (lb), .unit = (un), .kind = MM_OUT_SCALAR, __VA_ARGS__}
#define MM_SERIES(nm, lb, un, xl, xu, ...)                                       \
    {.name = (nm), .label = (lb), .unit = (un), .kind = MM_OUT_SERIES, .x_label = (xl), \
     .x_unit = (xu), __VA_ARGS__}
#define MM_TABLE(nm, lb, cols, uns, ...)                                          \
    {.name = (nm), .label = (lb), .unit = "", .kind = MM_OUT_TABLE, .columns = (cols), \
     .units = (uns), __VA_ARGS__}
#define MM_ANIMATION(lb) {.name = "animation", .label = (lb), .unit = "m", .kind = MM_OUT_ANIMATION}

/* ---- results ------------------------------------------------------------- */

typedef struct mm_result mm_result;   /* opaque, owned by the server */

/* Failures are sticky.  When a builder cannot get memory (or is misused:
 * an output of the wrong kind, an index outside its family) the result
 * remembers it, and the server refuses the whole answer (500, or 413 when
 * the request's memory cap was reached) whatever solve returns: a check can
 * never silently go missing from a 200.  So solve may ignore the int
 * returns of the builders; it must test the pointers it writes through:
 *     mm_series *s = mm_res_series(res, O_X, n);
 *     if (!s)
 *         return MM_ENOMEM;
 */

/* The accuracy of a scalar (API.md "Accuracy of a number"). */
typedef enum mm_err_kind {
    MM_ERR_NONE = 0,      /* no error attached */
    MM_ERR_BOUND,         /* error is a bound of the absolute error */
    MM_ERR_ESTIMATE       /* error is an estimate of the absolute error */
} mm_err_kind;

typedef struct mm_scalar {
    double value;
    int exact;            /* 1: exact (closed form, exact to rounding) */
    double error;         /* absolute error, with error_kind */
    mm_err_kind error_kind;
    const char *text;     /* a word beside the number ("underdamped"), or NULL;
                             must live as long as the result (arena or literal) */
} mm_scalar;

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
 * passed (sticky).  Freed by the server when the request ends; never free it. */
void *mm_res_alloc(mm_result *r, size_t bytes);

/* A copy of s in the arena (NULL if the cap is reached). */
char *mm_res_strdup(mm_result *r, const char *s);

/* A printf-formatted string in the arena (NULL if the cap is reached). */
char *mm_res_printf(mm_result *r, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Scalars: the numbers that end the solution.  out is the index of a
 * scalar in the output table; _i picks a member of a family (an index of a
 * "%d" family, or the position of the key in keys[] for a "%s" family).
 * The returned scalar may be refined (exact, error, text); it is never
 * NULL (after a failure it points at a scratch scalar that is not written
 * out).  A non-finite value is refused when the answer is written (422). */
mm_scalar *mm_res_scalar(mm_result *r, int out, double value);
mm_scalar *mm_res_scalar_i(mm_result *r, int out, int i, double value);

/* The same with its absolute error: a bound or an estimate. */
mm_scalar *mm_res_scalar_err(mm_result *r, int out, double value, double error,
                             mm_err_kind kind);

/* The same with a word beside the number (regime 0 "underdamped"); text is
 * copied. */
mm_scalar *mm_res_scalar_text(mm_result *r, int out, double value, const char *text);

/* A series of n points to plot; x and y are allocated in the arena.  NULL
 * when out of memory.  Keep n to what a plot can show (a few hundred to a
 * few thousand points). */
mm_series *mm_res_series(mm_result *r, int out, int n);
mm_series *mm_res_series_i(mm_result *r, int out, int i, int n);

/* A table of nrows rows with the declared columns.  NULL when out of memory. */
mm_table *mm_res_table(mm_result *r, int out, int nrows);

/* Checks: numerical value against an independent reference.
 * rel: passed when |value-ref| <= tol*|ref|   (tolerance is relative)
 * abs: passed when |value-ref| <= tol          (tolerance is absolute)
 * A failed check is reported, never hidden.  name is copied.  Returns MM_OK
 * or MM_ENOMEM (sticky). */
int mm_res_check_rel(mm_result *r, const char *name, double value,
                     double reference, double tol);
int mm_res_check_abs(mm_result *r, const char *name, double value,
                     double reference, double tol);

/* The method: its name and step (0 when not a stepping method); further
 * figures (steps, evaluations, rejected, error_estimate, ...) by
 * mm_res_method_stat.  Names are copied.  Returns MM_OK or MM_ENOMEM. */
int mm_res_method(mm_result *r, const char *name, double step);
int mm_res_method_stat(mm_result *r, const char *key, double value);

/* A warning for the learner ("the matrix is nearly singular: cond = 3e16"). */
int mm_res_warn(mm_result *r, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* ---- animation: the physical system drawn over time ---------------------- */

/* API.md "animation": frames of shapes in metres, x right, y up.  An
 * exercise that declares MM_ANIMATION calls mm_res_animation once, fills
 * t[], then adds shapes.  A shape has `frames` frames (1 when it does not
 * move, or the animation's frame count) of npts points each, frame-major:
 * point k of frame f is (x[f * npts + k], y[f * npts + k]).  Keep the frame
 * count to what a smooth animation needs (at most MM_ANIM_MAX_FRAMES).
 * bounds are computed from the shapes when the exercise leaves them 0. */
#define MM_ANIM_MAX_FRAMES 240

typedef enum mm_shape_kind {
    MM_SHAPE_LINE,        /* a polyline: links, members, springs as zigzags */
    MM_SHAPE_POLYGON,     /* a closed body, ground */
    MM_SHAPE_CIRCLE,      /* one point per frame, the centre; radius */
    MM_SHAPE_ARROW,       /* two points per frame: from, to; a vector quantity */
    MM_SHAPE_PATH,        /* a traced curve, drawn whole */
    MM_SHAPE_LABEL        /* one point per frame; text */
} mm_shape_kind;

typedef struct mm_anim {
    double *t;            /* nframes times (or crank angles), to fill */
    int nframes;
    double bounds[4];     /* xmin, ymin, xmax, ymax [m]; 0,0,0,0: from the shapes */
} mm_anim;

typedef struct mm_shape {
    double *x, *y;        /* frames * npts coordinates [m], to fill */
    int frames, npts;
    double radius;        /* MM_SHAPE_CIRCLE [m] */
    double *value;        /* NULL, or one number per frame (mm_shape_values) */
    const char *style;    /* NULL or "tension", "compression", "ground", "highlight" */
    const char *unit;     /* MM_SHAPE_ARROW: unit of the quantity drawn */
    double scale;         /* MM_SHAPE_ARROW: metres of arrow per unit */
    const char *text;     /* MM_SHAPE_LABEL: the text (literal or arena) */
} mm_shape;

/* Start the animation (one per answer; the output table must declare
 * MM_ANIMATION).  t_label and t_unit name what a frame stands for ("t", "s";
 * "crank angle", "rad").  NULL when out of memory or misused. */
mm_anim *mm_res_animation(mm_result *r, int nframes, const char *t_label, const char *t_unit);

/* A shape of the animation; name is copied.  frames is 1 or the
 * animation's nframes.  NULL when out of memory or misused. */
mm_shape *mm_anim_shape(mm_result *r, const char *name, mm_shape_kind kind, int frames, int npts);

/* Give s one number per frame (a force, a speed), returned to fill; NULL
 * when out of memory. */
double *mm_shape_values(mm_result *r, mm_shape *s);

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
    const char *theory;    /* path of the Markdown file from the source root; the
                              Octave/MATLAB body of its script is beside it, with
                              the extension .m instead of .md */
    const mm_param *params;
    int n_params;
    const mm_output *outputs;   /* every output an answer can carry */
    int n_outputs;
    const char *const *references; /* NULL-terminated, may be NULL */
    mm_check_fn check;     /* may be NULL */
    mm_solve_fn solve;
} mm_exercise;

#define MM_COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* The registry (exercises/registry.c), in book order. */
extern const mm_exercise *const mm_exercises[];
extern const int mm_exercise_count;
const mm_exercise *mm_exercise_find(const char *id);

/* Title of a chapter (1..5) and of a section number ("5.9.2"; a number the
 * book's contents do not list takes its nearest listed parent's title);
 * "" when there is none.  Cannot fail. */
const char *mm_chapter_title(int chapter);
const char *mm_section_title(const char *section);

/* Check one exercise: id matching its chapter, a section of the book's
 * contents, the required texts, an output table well formed (names unique
 * identifiers, families sane, tables with columns and units, one
 * animation at most).  Returns MM_OK or MM_EINTERNAL saying what is wrong. */
int mm_exercise_check(const mm_exercise *ex, mm_error *err);

/* Check the registry: ids unique and well formed, every section titled,
 * parameter and output tables well formed (names unique, families sane,
 * tables with columns).  For start-up and tests.  Returns MM_OK or
 * MM_EINTERNAL naming the exercise and what is wrong. */
int mm_registry_check(mm_error *err);

/* The concrete name of member i of family output o into buf (o itself
 * when it is not a family); index i as for mm_res_scalar_i.  Returns 0,
 * or -1 when i is outside the family. */
int mm_output_member(const mm_output *o, int i, char *buf, size_t size);

/* The members of a family: their count, and the index to pass for the k-th
 * (k from 0).  A plain output has one member, index 0. */
int mm_output_count(const mm_output *o);
int mm_output_index(const mm_output *o, int k);

#endif
