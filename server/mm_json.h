/* mm_json.h — a small, fast JSON writer into a growable buffer.
 *
 * cJSON parses request bodies; answers are written here instead, because an
 * answer is mostly numbers and cJSON prints each one twice and reads it
 * back (see PERFORMANCE.md).  Numbers go out in the shortest round-trip
 * form (mm_dtoa).  A non-finite number is never written: the buffer
 * remembers it (nonfinite) and the caller turns the answer into an error.
 * Strings are escaped and invalid UTF-8 is replaced by U+FFFD, so the
 * output is always valid JSON whatever the user typed.
 */
#ifndef MM_JSON_H
#define MM_JSON_H

#include <stddef.h>

typedef struct mm_buf {
    char *p;
    size_t len, cap;
    size_t max;          /* most bytes the buffer may hold */
    int failed;          /* out of memory or over max: content is cut */
    int nonfinite;       /* a NaN or infinity was asked for */
    char where[64];      /* what the first non-finite number belonged to */
} mm_buf;

void mm_buf_init(mm_buf *b, size_t max);
void mm_buf_free(mm_buf *b);
void mm_buf_reset(mm_buf *b);

void mm_buf_put(mm_buf *b, const char *s, size_t n);
void mm_buf_puts(mm_buf *b, const char *s);
void mm_buf_char(mm_buf *b, char c);
/* A JSON string with quotes; NULL writes null. */
void mm_buf_str(mm_buf *b, const char *s);
void mm_buf_strn(mm_buf *b, const char *s, size_t n);
/* A JSON number; non-finite sets nonfinite (with `where`) and writes 0. */
void mm_buf_num(mm_buf *b, double v, const char *where);
/* [v0,v1,...] as mm_buf_num writes each, in one pass. */
void mm_buf_nums(mm_buf *b, const double *v, size_t n, const char *where);
/* [[row 0],[row 1],...] of a rows x cols array stored row after row, each
 * row as mm_buf_nums writes it. */
void mm_buf_rows(mm_buf *b, const double *v, size_t rows, size_t cols, const char *where);
void mm_buf_int(mm_buf *b, long long v);
/* "key": */
void mm_buf_key(mm_buf *b, const char *key);

/* Make room for n more bytes at once (as one allocation); failed is set
 * when it cannot be had.  For a writer that knows roughly how much it
 * will write: a large block is mapped, and its pages cost only once
 * written. */
void mm_buf_reserve(mm_buf *b, size_t n);

/* Detach the text (NUL-terminated, malloc'd; caller frees) and its length. */
char *mm_buf_take(mm_buf *b, size_t *len);

#endif
