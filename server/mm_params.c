/* mm_params.c — parameter text to validated values (see mm_params.h). */
#include "mm_params.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mm_expr.h"

const char *mm_param_kind_name(mm_param_kind k)
{
    switch (k) {
    case MM_REAL: return "real";
    case MM_INT: return "integer";
    case MM_CHOICE: return "choice";
    case MM_VECTOR: return "vector";
    case MM_MATRIX: return "matrix";
    case MM_EXPR: return "expression";
    }
    return "real";
}

/* ---- small helpers ------------------------------------------------------- */

/* " kg" or "" — the unit as it follows a number in a message. */
static const char *unit_suffix(const mm_param *p, char *buf, size_t size)
{
    if (p->unit && p->unit[0])
        snprintf(buf, size, " %s", p->unit);
    else
        buf[0] = '\0';
    return buf;
}

/* The user's text cut short for a message, with non-printing bytes shown as
 * '?', so that an error never echoes much of what arrived (Redis: %.128s). */
static const char *echo(const char *s, size_t n, char *buf, size_t size)
{
    size_t k = 0, max = size - 4;
    for (size_t i = 0; i < n && k < max; i++)
        buf[k++] = isprint((unsigned char)s[i]) ? s[i] : '?';
    if (n > max)
        buf[k++] = '.', buf[k++] = '.', buf[k++] = '.';
    buf[k] = '\0';
    return buf;
}

static int is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

static void trim(const char **s, size_t *n)
{
    while (*n && is_space(**s))
        (*s)++, (*n)--;
    while (*n && is_space((*s)[*n - 1]))
        (*n)--;
}

/* Plain decimal syntax: [+-]digits[.digits][(e|E)[+-]digits], at least one
 * digit in the mantissa.  Rules out strtod's nan, inf and hex forms. */
static int decimal_syntax(const char *s, size_t n)
{
    size_t i = 0, digits = 0;
    if (i < n && (s[i] == '+' || s[i] == '-'))
        i++;
    while (i < n && isdigit((unsigned char)s[i]))
        i++, digits++;
    if (i < n && s[i] == '.') {
        i++;
        while (i < n && isdigit((unsigned char)s[i]))
            i++, digits++;
    }
    if (!digits)
        return 0;
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
        i++;
        if (i < n && (s[i] == '+' || s[i] == '-'))
            i++;
        size_t e = 0;
        while (i < n && isdigit((unsigned char)s[i]))
            i++, e++;
        if (!e)
            return 0;
    }
    return i == n;
}

/* One number: decimal text, or a constant expression such as pi/2.
 * what names the element in messages ("m", "A(2,3)").  Non-finite results
 * are MM_ERANGE for decimal text (1e999 overflows the limits) and MM_EVALUE
 * for expressions (1/0 is not a number). */
static int parse_number(const mm_param *p, const char *what, const char *s,
                        size_t n, double *out, mm_error *err)
{
    char tmp[128], shown[48];
    trim(&s, &n);
    if (n == 0)
        return mm_error_set(err, MM_EVALUE, p->name, "%s is empty; give a number", what);
    if (n < sizeof tmp && decimal_syntax(s, n)) {
        memcpy(tmp, s, n);
        tmp[n] = '\0';
        *out = strtod(tmp, NULL);
        if (!isfinite(*out))
            return mm_error_set(err, MM_ERANGE, p->name,
                                "%s must be between %g and %g; got %s", what,
                                p->min, p->max, echo(s, n, shown, sizeof shown));
        return MM_OK;
    }
    if (n >= sizeof tmp)               /* no constant expression is this long */
        return mm_error_set(err, MM_EVALUE, p->name, "%s must be a number (got '%s')",
                            what, echo(s, n, shown, sizeof shown));
    memcpy(tmp, s, n);
    tmp[n] = '\0';
    mm_error e2;
    int rc = mm_expr_eval_const(tmp, out, &e2);
    if (rc != MM_OK)
        return mm_error_set(err, MM_EVALUE, p->name,
                            "%s must be a number or a constant expression such as pi/2 (got '%s': %s)",
                            what, echo(s, n, shown, sizeof shown), e2.msg);
    if (!isfinite(*out))
        return mm_error_set(err, MM_EVALUE, p->name, "%s = '%s' is not a finite number",
                            what, echo(s, n, shown, sizeof shown));
    return MM_OK;
}

static int check_limits(const mm_param *p, const char *what, double v, mm_error *err)
{
    char u[32];
    if (v < p->min || v > p->max)
        return mm_error_set(err, MM_ERANGE, p->name, "%s must be between %g and %g%s; got %.10g",
                            what, p->min, p->max, unit_suffix(p, u, sizeof u), v);
    return MM_OK;
}

/* ---- vectors and matrices ----------------------------------------------- */

static int is_elem_sep(char c) { return c == ',' || is_space(c); }

/* Count the numbers in one row s[0..n): tokens between separators. */
static int count_tokens(const char *s, size_t n)
{
    int count = 0;
    size_t i = 0;
    while (i < n) {
        while (i < n && is_elem_sep(s[i]))
            i++;
        if (i >= n)
            break;
        count++;
        while (i < n && !is_elem_sep(s[i]))
            i++;
    }
    return count;
}

/* Parse rows x cols numbers.  A vector treats ';' and new lines as plain
 * separators (MATLAB's [10;0;1000] is a vector too); a matrix splits rows on
 * them.  Sizes are counted before anything is allocated. */
static int parse_array(const mm_param *p, const char *s, size_t n, mm_value *out,
                       mm_result *res, mm_error *err)
{
    int is_matrix = p->kind == MM_MATRIX;
    trim(&s, &n);
    if (n >= 2 && s[0] == '[' && s[n - 1] == ']') {
        s++, n -= 2;
        trim(&s, &n);
    }
    if (n == 0 && is_matrix && p->def_text && p->def_text[0] == '\0') {
        /* a matrix whose default is empty may be empty ("" or "[]"): a list
         * of loads with nothing in it (API.md's "[empty]") */
        memset(out, 0, sizeof *out);
        return MM_OK;
    }
    if (n == 0)
        return mm_error_set(err, MM_EVALUE, p->name, "%s is empty; give numbers such as %s",
                            p->name, p->def_text ? p->def_text : "1,2,3");

    /* pass 1: shape */
    int rows = 0, cols = -1, total = 0;
    size_t i = 0;
    while (i <= n) {
        size_t j = i;
        while (j < n && !(is_matrix && (s[j] == ';' || s[j] == '\n')))
            j++;
        int c = 0;
        if (is_matrix) {
            c = count_tokens(s + i, j - i);
        } else {                       /* a vector: ';' separates too */
            for (size_t k = i; k < j;) {
                while (k < j && (is_elem_sep(s[k]) || s[k] == ';'))
                    k++;
                if (k >= j)
                    break;
                c++;
                while (k < j && !(is_elem_sep(s[k]) || s[k] == ';'))
                    k++;
            }
        }
        if (c > 0 || (is_matrix && j < n)) {
            if (c == 0 && is_matrix) {
                /* an empty row in the middle: "1,2;;3,4" */
                return mm_error_set(err, MM_EVALUE, p->name,
                                    "%s has an empty row %d; write rows as 1,2;3,4", p->name, rows + 1);
            }
            if (is_matrix && (c > p->max_cols || rows + 1 > p->max_rows))
                return mm_error_set(err, MM_ERANGE, p->name,
                                    "%s may have at most %d rows and %d columns; got %s%d %s",
                                    p->name, p->max_rows, p->max_cols,
                                    c > p->max_cols ? "a row of " : "", c > p->max_cols ? c : rows + 1,
                                    c > p->max_cols ? "numbers" : "rows or more");
            if (!is_matrix && total + c > p->max_cols)
                return mm_error_set(err, MM_ERANGE, p->name, "%s may have at most %d numbers; got %d or more",
                                    p->name, p->max_cols, total + c);
            if (cols >= 0 && c != cols)
                return mm_error_set(err, MM_EVALUE, p->name,
                                    "%s row %d has %d numbers but row 1 has %d; every row needs the same count",
                                    p->name, rows + 1, c, cols);
            cols = c;
            rows++;
            total += c;
        }
        i = j + 1;
    }

    if (total == 0)                    /* only separators: ",", ";;" */
        return mm_error_set(err, MM_EVALUE, p->name, "%s has no numbers; give numbers such as %s",
                            p->name, p->def_text ? p->def_text : "1,2,3");

    /* pass 2: values */
    double *data = mm_res_alloc(res, (size_t)total * sizeof(double) + 1);
    if (!data)
        return mm_error_set(err, MM_ENOMEM, p->name, "out of memory");
    int k = 0;
    for (i = 0; i < n && k < total;) {
        while (i < n && (is_elem_sep(s[i]) || s[i] == ';'))
            i++;
        size_t j = i;
        while (j < n && !(is_elem_sep(s[j]) || s[j] == ';'))
            j++;
        if (j == i)
            break;
        char what[48];
        if (is_matrix)
            snprintf(what, sizeof what, "%s(%d,%d)", p->name, k / cols + 1, k % cols + 1);
        else
            snprintf(what, sizeof what, "%s(%d)", p->name, k + 1);
        int rc = parse_number(p, what, s + i, j - i, &data[k], err);
        if (rc == MM_OK)
            rc = check_limits(p, what, data[k], err);
        if (rc != MM_OK)
            return rc;
        k++;
        i = j;
    }
    out->data = data;
    out->rows = is_matrix ? rows : 1;
    out->cols = is_matrix ? cols : total;
    out->x = total > 0 ? data[0] : 0.0;
    return MM_OK;
}

/* ---- one value ----------------------------------------------------------- */

int mm_param_parse(const mm_param *p, const char *text, size_t len,
                   mm_value *out, mm_result *res, mm_error *err)
{
    char shown[48];
    memset(out, 0, sizeof *out);
    if (len > MM_PARAM_TEXT_MAX)
        return mm_error_set(err, MM_ERANGE, p->name, "%s is too long (%zu bytes; at most %d)",
                            p->name, len, MM_PARAM_TEXT_MAX);
    if (memchr(text, '\0', len))
        return mm_error_set(err, MM_EVALUE, p->name, "%s contains a NUL byte", p->name);

    switch (p->kind) {
    case MM_REAL:
    case MM_INT: {
        int rc = parse_number(p, p->name, text, len, &out->x, err);
        if (rc != MM_OK)
            return rc;
        if (p->kind == MM_INT && out->x != floor(out->x))
            return mm_error_set(err, MM_EVALUE, p->name,
                                "%s must be a whole number between %g and %g; got %.10g",
                                p->name, p->min, p->max, out->x);
        return check_limits(p, p->name, out->x, err);
    }
    case MM_CHOICE: {
        const char *s = text;
        size_t n = len;
        trim(&s, &n);
        for (int i = 0; p->choices && p->choices[i]; i++) {
            if (strlen(p->choices[i]) == n && memcmp(p->choices[i], s, n) == 0) {
                out->x = i;
                out->text = p->choices[i];
                return MM_OK;
            }
        }
        char list[160] = "";
        for (int i = 0; p->choices && p->choices[i]; i++) {
            size_t l = strlen(list);
            snprintf(list + l, sizeof list - l, "%s%s", i ? ", " : "", p->choices[i]);
        }
        return mm_error_set(err, MM_EVALUE, p->name, "%s must be one of %s; got '%s'",
                            p->name, list, echo(s, n, shown, sizeof shown));
    }
    case MM_VECTOR:
    case MM_MATRIX:
        return parse_array(p, text, len, out, res, err);
    case MM_EXPR: {
        const char *s = text;
        size_t n = len;
        trim(&s, &n);
        if (n == 0)
            return mm_error_set(err, MM_EVALUE, p->name, "%s is empty; give an expression such as %s",
                                p->name, p->def_text ? p->def_text : "x^2-2");
        if (n > MM_PARAM_EXPR_MAX)
            return mm_error_set(err, MM_ERANGE, p->name, "%s is too long (%zu characters; at most %d)",
                                p->name, n, MM_PARAM_EXPR_MAX);
        char *t = mm_res_alloc(res, n + 1);
        if (!t)
            return mm_error_set(err, MM_ENOMEM, p->name, "out of memory");
        memcpy(t, s, n);
        out->text = t;
        return MM_OK;
    }
    }
    return mm_error_set(err, MM_EINTERNAL, p->name, "unknown parameter kind");
}

int mm_param_default(const mm_param *p, mm_value *out, mm_result *res, mm_error *err)
{
    int rc;
    if (p->kind == MM_REAL || p->kind == MM_INT) {
        memset(out, 0, sizeof *out);
        out->x = p->def;
        rc = MM_OK;
    } else if (p->kind == MM_CHOICE) {
        memset(out, 0, sizeof *out);
        out->x = p->def;
        out->text = p->choices ? p->choices[(int)p->def] : NULL;
        rc = out->text ? MM_OK : MM_EINTERNAL;
    } else {
        const char *t = p->def_text ? p->def_text : "";
        rc = mm_param_parse(p, t, strlen(t), out, res, err);
    }
    if (rc != MM_OK) {
        char why[sizeof err->msg] = "";
        if (err)
            memcpy(why, err->msg, sizeof why);    /* err->msg is rewritten below */
        return mm_error_set(err, MM_EINTERNAL, p->name, "default of %s does not parse: %s",
                            p->name, why);
    }
    return MM_OK;
}

int mm_params_check(const mm_exercise *ex, mm_error *err)
{
    for (int i = 0; i < ex->n_params; i++) {
        const mm_param *p = &ex->params[i];
        if (!p->name || !p->name[0] || !p->label || !p->help)
            return mm_error_set(err, MM_EINTERNAL, "", "%s: parameter %d lacks a name, label or help",
                                ex->id, i);
        for (int j = 0; j < i; j++)
            if (strcmp(ex->params[j].name, p->name) == 0)
                return mm_error_set(err, MM_EINTERNAL, p->name, "%s: parameter %s declared twice",
                                    ex->id, p->name);
        if (!(p->min <= p->max))
            return mm_error_set(err, MM_EINTERNAL, p->name, "%s: %s has min > max", ex->id, p->name);
        if ((p->kind == MM_REAL || p->kind == MM_INT) && !(p->def >= p->min && p->def <= p->max))
            return mm_error_set(err, MM_EINTERNAL, p->name, "%s: default of %s outside its limits",
                                ex->id, p->name);
        if (p->kind == MM_CHOICE) {
            int n = 0;
            while (p->choices && p->choices[n])
                n++;
            if (n == 0 || p->def < 0 || p->def >= n)
                return mm_error_set(err, MM_EINTERNAL, p->name, "%s: choice %s has no valid default",
                                    ex->id, p->name);
        }
        if ((p->kind == MM_VECTOR && p->max_cols < 1) ||
            (p->kind == MM_MATRIX && (p->max_rows < 1 || p->max_cols < 1)))
            return mm_error_set(err, MM_EINTERNAL, p->name, "%s: %s has no size limit", ex->id, p->name);
    }
    return MM_OK;
}
