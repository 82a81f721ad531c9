/* mm_json.c — see mm_json.h. */
#include "mm_json.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mm_dtoa.h"

void mm_buf_init(mm_buf *b, size_t max)
{
    memset(b, 0, sizeof *b);
    b->max = max;
}

void mm_buf_free(mm_buf *b)
{
    free(b->p);
    b->p = NULL;
    b->len = b->cap = 0;
}

void mm_buf_reset(mm_buf *b)
{
    b->len = 0;
    b->failed = b->nonfinite = 0;
    b->where[0] = '\0';
}

/* the growth, out of line: reserve's common case is the one comparison */
static int grow(mm_buf *b, size_t extra)
{
    if (b->failed)
        return 0;
    size_t need = b->len + extra + 1;
    if (need <= b->cap)
        return 1;
    if (need > b->max) {
        b->failed = 1;
        return 0;
    }
    size_t cap = b->cap ? b->cap : 4096;
    while (cap < need)
        cap *= 2;
    if (cap > b->max)
        cap = b->max;
    char *p = realloc(b->p, cap);
    if (!p) {
        b->failed = 1;
        return 0;
    }
    b->p = p;
    b->cap = cap;
    return 1;
}

/* Room for extra bytes and a NUL; 0 (and failed set) when there is none.
 * Inline: most calls are a few bytes into room already there. */
static inline int reserve(mm_buf *b, size_t extra)
{
    if (!b->failed && b->len + extra + 1 <= b->cap)
        return 1;
    return grow(b, extra);
}

void mm_buf_put(mm_buf *b, const char *s, size_t n)
{
    if (!reserve(b, n))
        return;
    memcpy(b->p + b->len, s, n);
    b->len += n;
    b->p[b->len] = '\0';
}

void mm_buf_puts(mm_buf *b, const char *s) { mm_buf_put(b, s, strlen(s)); }

void mm_buf_char(mm_buf *b, char c)
{
    if (!reserve(b, 1))
        return;
    b->p[b->len++] = c;
    b->p[b->len] = '\0';
}

/* Length of a valid UTF-8 sequence starting at s (at most n bytes), or 0. */
static size_t utf8_len(const unsigned char *s, size_t n)
{
    unsigned c = s[0];
    size_t len;
    unsigned min;
    if (c < 0x80)
        return 1;
    else if ((c & 0xE0) == 0xC0) { len = 2; min = 0x80; c &= 0x1F; }
    else if ((c & 0xF0) == 0xE0) { len = 3; min = 0x800; c &= 0x0F; }
    else if ((c & 0xF8) == 0xF0) { len = 4; min = 0x10000; c &= 0x07; }
    else
        return 0;
    if (len > n)
        return 0;
    for (size_t i = 1; i < len; i++) {
        if ((s[i] & 0xC0) != 0x80)
            return 0;
        c = (c << 6) | (s[i] & 0x3F);
    }
    if (c < min || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF))
        return 0;                                  /* overlong or surrogate */
    return len;
}

void mm_buf_strn(mm_buf *b, const char *s, size_t n)
{
    static const char hex[] = "0123456789abcdef";
    const unsigned char *u = (const unsigned char *)s;
    mm_buf_char(b, '"');
    size_t i = 0;
    while (i < n) {
        size_t run = i;                            /* copy plain runs at once */
        while (run < n && u[run] >= 0x20 && u[run] < 0x80 && u[run] != '"' && u[run] != '\\')
            run++;
        if (run > i) {
            mm_buf_put(b, s + i, run - i);
            i = run;
            continue;
        }
        unsigned char c = u[i];
        if (c == '"' || c == '\\') {
            char e[2] = {'\\', (char)c};
            mm_buf_put(b, e, 2);
            i++;
        } else if (c < 0x20) {
            char e[6] = {'\\', 'u', '0', '0', hex[c >> 4], hex[c & 15]};
            switch (c) {
            case '\n': mm_buf_put(b, "\\n", 2); break;
            case '\t': mm_buf_put(b, "\\t", 2); break;
            case '\r': mm_buf_put(b, "\\r", 2); break;
            default: mm_buf_put(b, e, 6);
            }
            i++;
        } else {
            size_t len = utf8_len(u + i, n - i);
            if (len) {
                mm_buf_put(b, s + i, len);
                i += len;
            } else {
                mm_buf_put(b, "\xEF\xBF\xBD", 3);  /* U+FFFD for a bad byte */
                i++;
            }
        }
    }
    mm_buf_char(b, '"');
}

void mm_buf_str(mm_buf *b, const char *s)
{
    if (!s)
        mm_buf_put(b, "null", 4);
    else
        mm_buf_strn(b, s, strlen(s));
}

static void nonfinite(mm_buf *b, const char *where)
{
    if (!b->nonfinite)
        snprintf(b->where, sizeof b->where, "%s", where ? where : "");
    b->nonfinite = 1;
}

/* mm_dtoa writes straight into the buffer (room reserved first): the copy
 * from a temporary and its length-dependent memcpy call were a fifth of
 * the writing of a number. */
void mm_buf_num(mm_buf *b, double v, const char *where)
{
    if (!isfinite(v)) {
        nonfinite(b, where);
        mm_buf_char(b, '0');
        return;
    }
    if (!reserve(b, MM_DTOA_BUFSIZE))
        return;
    b->len += (size_t)mm_dtoa(v, b->p + b->len);     /* NUL-terminated by mm_dtoa */
}

/* [v0,...] the general way: room for CHUNK numbers at a time, and near the
 * buffer's end one number at a time, to fail where mm_buf_num would */
static void nums_chunked(mm_buf *b, const double *v, size_t n, const char *where)
{
    enum { CHUNK = 256 };
    mm_buf_char(b, '[');
    for (size_t i = 0; i < n; i += CHUNK) {
        size_t m = n - i < CHUNK ? n - i : CHUNK;
        if (b->failed)
            return;
        if (b->len + m * (MM_DTOA_BUFSIZE + 1) + MM_DTOA_SLACK + 1 > b->max) {
            for (size_t j = i; j < i + m; j++) {
                if (j)
                    mm_buf_char(b, ',');
                mm_buf_num(b, v[j], where);
            }
            continue;
        }
        if (!reserve(b, m * (MM_DTOA_BUFSIZE + 1) + MM_DTOA_SLACK))
            return;
        int bad = 0;
        char *w = mm_dtoa_list(v + i, m, i == 0, b->p + b->len, &bad);
        if (bad)
            nonfinite(b, where);
        b->len = (size_t)(w - b->p);
    }
    mm_buf_char(b, ']');
}

/* lead (a ',' or nothing) then [v0,...].  An answer is mostly short
 * arrays (an animation's frames: a few to a few dozen coordinates each, a
 * thousand arrays), so the usual array is written with one reservation,
 * brackets and comma included; what would come near the buffer's limit
 * goes the general way, which gives the same text and fails where it
 * always did. */
static void nums_lead(mm_buf *b, const double *v, size_t n, const char *where, int lead)
{
    enum { SHORT = 256 };
    size_t need = n * (MM_DTOA_BUFSIZE + 1) + MM_DTOA_SLACK + 3;
    if (n > SHORT || b->failed || b->len + need + 1 > b->max) {
        if (lead)
            mm_buf_char(b, ',');
        nums_chunked(b, v, n, where);
        return;
    }
    if (!reserve(b, need))
        return;
    char *w = b->p + b->len;
    *w = ',';
    w += lead != 0;
    *w++ = '[';
    int bad = 0;
    w = mm_dtoa_list(v, n, 1, w, &bad);
    *w++ = ']';
    *w = '\0';
    if (bad)
        nonfinite(b, where);
    b->len = (size_t)(w - b->p);
}

void mm_buf_nums(mm_buf *b, const double *v, size_t n, const char *where)
{
    nums_lead(b, v, n, where, 0);
}

void mm_buf_rows(mm_buf *b, const double *v, size_t rows, size_t cols, const char *where)
{
    mm_buf_char(b, '[');
    for (size_t r = 0; r < rows; r++)
        nums_lead(b, v + r * cols, cols, where, r > 0);
    mm_buf_char(b, ']');
}

void mm_buf_int(mm_buf *b, long long v)
{
    char tmp[32];
    int n = snprintf(tmp, sizeof tmp, "%lld", v);
    mm_buf_put(b, tmp, (size_t)n);
}

void mm_buf_key(mm_buf *b, const char *key)
{
    mm_buf_str(b, key);
    mm_buf_char(b, ':');
}

void mm_buf_reserve(mm_buf *b, size_t n)
{
    if (n > b->max - b->len - 1)
        n = b->max - b->len - 1;
    (void)reserve(b, n);
}

char *mm_buf_take(mm_buf *b, size_t *len)
{
    if (!b->p && reserve(b, 0))
        b->p[0] = '\0';                           /* an empty text, not NULL */
    char *p = b->p;
    if (len)
        *len = b->len;
    b->p = NULL;
    b->len = b->cap = 0;
    return p;
}
