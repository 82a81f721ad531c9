/* mm_result_impl.h — the inside of an mm_result, for the server that writes
 * it out as JSON and for tests.  Exercises use only mm_exercise.h.
 *
 * Everything lives in one arena: a chain of blocks freed together.  Lists
 * keep insertion order (the order an exercise adds things is the order a
 * learner reads them).
 */
#ifndef MM_RESULT_IMPL_H
#define MM_RESULT_IMPL_H

#include "mm_exercise.h"

typedef struct mm_block {
    struct mm_block *next;
    size_t size, used;
    /* data follows, max_align_t aligned */
} mm_block;

typedef struct mm_scalar_node {
    struct mm_scalar_node *next;
    const char *name, *label, *unit;
    const mm_output *decl;         /* NULL for a scalar of the old builders */
    mm_scalar s;
} mm_scalar_node;

typedef struct mm_series_node {
    struct mm_series_node *next;
    const char *name, *label, *unit, *x_label, *x_unit;
    const mm_output *decl;         /* figure hints; NULL for the old builders */
    mm_series s;
} mm_series_node;

typedef struct mm_table_node {
    struct mm_table_node *next;
    const char *name, *label;
    const char *const *columns, *const *units;
    mm_table t;
} mm_table_node;

typedef struct mm_check_node {
    struct mm_check_node *next;
    const char *name;
    double value, reference, tolerance;
    int relative;                  /* 1: tolerance is relative */
} mm_check_node;

typedef struct mm_stat_node {
    struct mm_stat_node *next;
    const char *key;
    double value;
} mm_stat_node;

typedef struct mm_warn_node {
    struct mm_warn_node *next;
    const char *text;
} mm_warn_node;

typedef struct mm_shape_node {
    struct mm_shape_node *next;
    const char *name;
    mm_shape_kind kind;
    mm_shape s;
} mm_shape_node;

#define MM_LIST(type) struct { type *head, *tail; int n; }

struct mm_result {
    const mm_exercise *ex;         /* whose output table the builders use */
    mm_block *blocks;
    size_t cap, total;             /* arena cap and bytes taken, in bytes */
    int over_cap;                  /* an allocation was refused by the cap */
    int failed;                    /* sticky: MM_ENOMEM or MM_EINTERNAL (misuse) */
    char failure[120];             /* what failed, for the server log */
    MM_LIST(mm_scalar_node) scalars;
    MM_LIST(mm_series_node) series;
    MM_LIST(mm_table_node) tables;
    MM_LIST(mm_check_node) checks;
    MM_LIST(mm_stat_node) stats;
    MM_LIST(mm_warn_node) warnings;
    const char *method;            /* NULL when the exercise names none */
    double step;
    mm_anim *anim;                 /* NULL when there is no animation */
    const char *anim_t_label, *anim_t_unit;
    MM_LIST(mm_shape_node) shapes;
    mm_scalar sink;                /* written to after a failed mm_res_scalar */
};

/* Start an empty result whose arena may grow to cap bytes, for exercise ex
 * (NULL: only the arena and the old builders may be used).  Cannot fail (the
 * first block is taken lazily). */
void mm_result_init(mm_result *r, size_t cap);
void mm_result_bind(mm_result *r, const mm_exercise *ex);

/* Free the arena; r may be reused after mm_result_init. */
void mm_result_release(mm_result *r);

/* on: the calling thread keeps the largest block of each released arena
 * (up to 1 MiB) for its next result, which then needs no new memory;
 * off: that block is freed (call it before the thread ends).  Off by
 * default; the server's solve workers turn it on. */
void mm_result_keep_blocks(int on);

/* The status that refuses the answer (MM_ETOOBIG over the cap, MM_ENOMEM,
 * MM_EINTERNAL), or MM_OK when every builder call succeeded. */
int mm_result_status(const mm_result *r);

#endif
