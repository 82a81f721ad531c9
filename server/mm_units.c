/* mm_units.c — numbers with units (see mm_units.h). */
#include "mm_units.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct unit {
    const char *sym;
    double factor;                 /* to SI */
    signed char dim[MM_DIM_COUNT]; /* kg m s rad */
    int prefixable;
} unit;

static const unit units[] = {
    {"m", 1, {0, 1, 0, 0}, 1},
    {"g", 1e-3, {1, 0, 0, 0}, 1},
    {"t", 1e3, {1, 0, 0, 0}, 0},          /* the tonne */
    {"s", 1, {0, 0, 1, 0}, 1},
    {"min", 60, {0, 0, 1, 0}, 0},
    {"h", 3600, {0, 0, 1, 0}, 0},
    {"N", 1, {1, 1, -2, 0}, 1},
    {"Nm", 1, {1, 2, -2, 0}, 1},          /* the newton-metre as learners write it */
    {"Pa", 1, {1, -1, -2, 0}, 1},
    {"J", 1, {1, 2, -2, 0}, 1},
    {"W", 1, {1, 2, -3, 0}, 1},
    {"Hz", 1, {0, 0, -1, 0}, 1},
    {"rad", 1, {0, 0, 0, 1}, 1},
    {"deg", M_PI / 180, {0, 0, 0, 1}, 0},
    {"\xc2\xb0", M_PI / 180, {0, 0, 0, 1}, 0},    /* ° */
    {"rev", 2 * M_PI, {0, 0, 0, 1}, 0},
    {"rpm", 2 * M_PI / 60, {0, 0, -1, 1}, 0},
    {"%", 0.01, {0, 0, 0, 0}, 0},
};

static const struct { const char *sym; double factor; } prefixes[] = {
    {"n", 1e-9}, {"u", 1e-6}, {"\xc2\xb5", 1e-6}, {"m", 1e-3}, {"c", 1e-2}, {"d", 1e-1},
    {"k", 1e3}, {"M", 1e6}, {"G", 1e9},
};

static const unit *find(const char *s, size_t n)
{
    for (size_t i = 0; i < sizeof units / sizeof units[0]; i++)
        if (strlen(units[i].sym) == n && memcmp(units[i].sym, s, n) == 0)
            return &units[i];
    return NULL;
}

/* one symbol with its prefix: "kN", "mm", "min" */
static int symbol(const char *s, size_t n, double *factor, signed char dim[MM_DIM_COUNT])
{
    const unit *u = find(s, n);
    double f = 1;
    for (size_t i = 0; !u && i < sizeof prefixes / sizeof prefixes[0]; i++) {
        size_t pl = strlen(prefixes[i].sym);
        if (n > pl && memcmp(s, prefixes[i].sym, pl) == 0) {
            const unit *v = find(s + pl, n - pl);
            if (v && v->prefixable) {
                u = v;
                f = prefixes[i].factor;
            }
        }
    }
    if (!u)
        return -1;
    if (strcmp(u->sym, "g") == 0 && f == 1e3) {   /* kg is the base: exactly 1 */
        *factor = 1;
    } else {
        *factor = f * u->factor;
    }
    memcpy(dim, u->dim, sizeof u->dim);
    return 0;
}

static int is_sep(const char *p, size_t *len)
{
    if (*p == ' ' || *p == '*' || *p == '\t') {
        *len = 1;
        return 1;
    }
    if ((unsigned char)p[0] == 0xc2 && (unsigned char)p[1] == 0xb7) {   /* · */
        *len = 2;
        return 1;
    }
    return 0;
}

/* a power after a symbol: ^2, ^-1, ², ³; returns bytes read */
static size_t power(const char *p, int *pw)
{
    if (*p == '^') {
        char *end;
        long v = strtol(p + 1, &end, 10);
        if (end == p + 1 || v < -9 || v > 9)
            return 0;
        *pw = (int)v;
        return (size_t)(end - p);
    }
    if ((unsigned char)p[0] == 0xc2 && ((unsigned char)p[1] == 0xb2 || (unsigned char)p[1] == 0xb3)) {
        *pw = (unsigned char)p[1] == 0xb2 ? 2 : 3;
        return 2;
    }
    *pw = 1;
    return 0;
}

int mm_unit_parse(const char *text, mm_quantity *q, mm_error *err)
{
    memset(q, 0, sizeof *q);
    q->value = 1;
    q->number = 1;
    int denominator = 0;
    const char *p = text;
    for (;;) {
        size_t sl;
        while (is_sep(p, &sl))
            p += sl;
        if (!*p)
            break;
        if (*p == '/') {
            if (denominator)
                return mm_error_set(err, MM_EVALUE, "", "a unit may have one '/' only: '%.40s'", text);
            denominator = 1;
            p++;
            continue;
        }
        const char *s = p;
        while (*p && *p != '/' && *p != '^' && !is_sep(p, &sl) &&
               !((unsigned char)p[0] == 0xc2 && ((unsigned char)p[1] == 0xb2 || (unsigned char)p[1] == 0xb3)))
            p++;
        if (p - s == 1 && *s == '1' && !denominator && !q->has_unit && *p == '/')
            continue;                       /* "1/s": a numerator of one */
        double f;
        signed char dim[MM_DIM_COUNT];
        if (p == s || symbol(s, (size_t)(p - s), &f, dim) != 0)
            return mm_error_set(err, MM_EVALUE, "", "unknown unit '%.*s' (known: m, g, kg, t, s, min, h, "
                                "N, Pa, J, W, Hz, rad, deg, rev, rpm, %% with prefixes n u m c d k M G)",
                                (int)(p - s > 20 ? 20 : p - s), s);
        int pw = 1;
        size_t used = power(p, &pw);
        if (*p == '^' && used == 0)
            return mm_error_set(err, MM_EVALUE, "", "a power must be a whole number from -9 to 9: '%.40s'", text);
        p += used;
        if (denominator)
            pw = -pw;
        q->value *= pow(f, pw);
        for (int k = 0; k < MM_DIM_COUNT; k++)
            q->dim[k] = (signed char)(q->dim[k] + pw * dim[k]);
        q->has_unit = 1;
    }
    q->factor = q->value;
    return MM_OK;
}

int mm_quantity_parse(const char *text, mm_quantity *q, mm_error *err)
{
    char num[64];
    const char *p = text;
    while (*p == ' ' || *p == '\t')
        p++;
    /* the number: digits, one decimal point or comma, an exponent */
    size_t n = 0;
    const char *s = p;
    if (*p == '+' || *p == '-')
        p++;
    int digits = 0, point = 0;
    while ((*p >= '0' && *p <= '9') || ((*p == '.' || *p == ',') && !point)) {
        if (*p == '.' || *p == ',')
            point = 1;
        else
            digits++;
        p++;
    }
    if ((*p == 'e' || *p == 'E') && digits &&
        ((p[1] >= '0' && p[1] <= '9') || ((p[1] == '-' || p[1] == '+') && p[2] >= '0' && p[2] <= '9'))) {
        p += 2;
        while (*p >= '0' && *p <= '9')
            p++;
    }
    n = (size_t)(p - s);
    if (!digits || n >= sizeof num)
        return mm_error_set(err, MM_EVALUE, "", "'%.40s' does not start with a number", text);
    memcpy(num, s, n);
    num[n] = '\0';
    for (char *c = num; *c; c++)
        if (*c == ',')
            *c = '.';                               /* 1,5 kN: a decimal comma */
    double v = strtod(num, NULL);
    if (!isfinite(v))
        return mm_error_set(err, MM_EVALUE, "", "'%.40s' is not a finite number", text);
    int rc = mm_unit_parse(p, q, err);
    if (rc != MM_OK)
        return rc;
    q->number = v;
    q->factor = q->value;
    q->value *= v;
    return MM_OK;
}

int mm_dim_equal(const mm_quantity *a, const mm_quantity *b)
{
    return memcmp(a->dim, b->dim, sizeof a->dim) == 0;
}

void mm_dim_text(const mm_quantity *q, char *buf, size_t size)
{
    static const char *const names[MM_DIM_COUNT] = {"kg", "m", "s", "rad"};
    size_t len = 0;
    buf[0] = '\0';
    for (int k = 0; k < MM_DIM_COUNT; k++) {
        if (!q->dim[k])
            continue;
        int w = q->dim[k] == 1 ? snprintf(buf + len, size - len, "%s%s", len ? " " : "", names[k])
                               : snprintf(buf + len, size - len, "%s%s^%d", len ? " " : "", names[k], q->dim[k]);
        if (w < 0 || (size_t)w >= size - len)
            return;
        len += (size_t)w;
    }
    if (!len)
        snprintf(buf, size, "1");
}
