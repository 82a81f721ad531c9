/* mm_script.c — Octave/MATLAB scripts of the exercises (see mm_script.h). */
#include "mm_script.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mm_dtoa.h"

/* ==== expressions: muParser's language to vectorised MATLAB ==================== */

/* A small Pratt parser builds the tree with muParser's precedences (^ right
 * associative and above unary minus: -2^2 = -4, 2^3^2 = 512), then the tree
 * is printed with MATLAB's operators and only the parentheses MATLAB needs
 * (its .^ is left associative: 2.^3.^2 = 64, so a power on the right of a
 * power keeps its parentheses). */

enum { MAXNODES = 1024, MAXARGS = 16, MAXDEPTH = 200 };

typedef enum { N_NUM, N_NAME, N_CALL, N_NEG, N_BIN } ntype;

typedef struct node {
    ntype type;
    const char *s;          /* number or name text, or the operator */
    size_t len;
    int prec;               /* N_BIN: its muParser precedence */
    int a, b;               /* operands (node indices) */
    int args[MAXARGS], nargs;
} node;

typedef struct parser {
    const char *p;
    node n[MAXNODES];
    int count, depth;
    mm_error *err;
    int rc;
} parser;

static void skip(parser *ps)
{
    while (*ps->p == ' ' || *ps->p == '\t')
        ps->p++;
}

static int fail(parser *ps, const char *fmt, const char *what)
{
    if (ps->rc == MM_OK) {
        mm_error_set(ps->err, MM_EVALUE, "", fmt, what);
        ps->rc = MM_EVALUE;
    }
    return -1;
}

static int add(parser *ps, node nd)
{
    if (ps->count >= MAXNODES)
        return fail(ps, "%s", "the expression is too long for a script");
    ps->n[ps->count] = nd;
    return ps->count++;
}

static const struct { const char *op; int prec; } binops[] = {
    {"||", 1}, {"&&", 2}, {"==", 3}, {"!=", 3}, {"<=", 4}, {">=", 4}, {"<", 4}, {">", 4},
    {"+", 5}, {"-", 5}, {"*", 6}, {"/", 6}, {"^", 8},
};
enum { UNARY_PREC = 7 };

static int parse(parser *ps, int min_prec);

static int primary(parser *ps)
{
    skip(ps);
    const char *s = ps->p;
    if (*s == '-' || *s == '+') {
        ps->p++;
        int x = parse(ps, UNARY_PREC);
        if (x < 0 || *s == '+')
            return x;
        return add(ps, (node){.type = N_NEG, .a = x});
    }
    if (*s == '(') {
        ps->p++;
        int x = parse(ps, 0);
        skip(ps);
        if (x < 0)
            return x;
        if (*ps->p != ')')
            return fail(ps, "%s", "a '(' is not closed");
        ps->p++;
        return x;
    }
    if (isdigit((unsigned char)*s) || *s == '.') {
        const char *e = s;
        while (isdigit((unsigned char)*e) || *e == '.')
            e++;
        if ((*e == 'e' || *e == 'E') &&
            (isdigit((unsigned char)e[1]) || ((e[1] == '+' || e[1] == '-') && isdigit((unsigned char)e[2])))) {
            e += 2;
            while (isdigit((unsigned char)*e))
                e++;
        }
        ps->p = e;
        return add(ps, (node){.type = N_NUM, .s = s, .len = (size_t)(e - s)});
    }
    if (isalpha((unsigned char)*s) || *s == '_') {
        const char *e = s;
        while (isalnum((unsigned char)*e) || *e == '_')
            e++;
        ps->p = e;
        skip(ps);
        if (*ps->p != '(')
            return add(ps, (node){.type = N_NAME, .s = s, .len = (size_t)(e - s)});
        ps->p++;
        node call = {.type = N_CALL, .s = s, .len = (size_t)(e - s)};
        skip(ps);
        if (*ps->p == ')') {
            ps->p++;
            return add(ps, call);
        }
        for (;;) {
            int x = parse(ps, 0);
            if (x < 0)
                return x;
            if (call.nargs >= MAXARGS)
                return fail(ps, "%s", "a function has too many arguments for a script");
            call.args[call.nargs++] = x;
            skip(ps);
            if (*ps->p == ',') {
                ps->p++;
                continue;
            }
            if (*ps->p != ')')
                return fail(ps, "%s", "a function call is not closed");
            ps->p++;
            return add(ps, call);
        }
    }
    if (*s == '?' || *s == ':')
        return fail(ps, "%s", "the conditional c ? a : b has no MATLAB form; write it another way "
                              "(e.g. with (c).*a + (~c).*b)");
    char bad[2] = {*s ? *s : ' ', '\0'};
    return fail(ps, "the expression cannot be read at '%s'", bad);
}

static int parse(parser *ps, int min_prec)
{
    if (++ps->depth > MAXDEPTH) {
        ps->depth--;
        return fail(ps, "%s", "the expression is nested too deeply for a script");
    }
    int left = primary(ps);
    while (left >= 0) {
        skip(ps);
        if (*ps->p == '?')
            return fail(ps, "%s", "the conditional c ? a : b has no MATLAB form; write it another way "
                                  "(e.g. with (c).*a + (~c).*b)");
        int k = -1;
        for (size_t i = 0; i < sizeof binops / sizeof binops[0] && k < 0; i++)
            if (strncmp(ps->p, binops[i].op, strlen(binops[i].op)) == 0)
                k = (int)i;
        if (k < 0 || binops[k].prec < min_prec)
            break;
        int prec = binops[k].prec;
        ps->p += strlen(binops[k].op);
        int right = parse(ps, binops[k].op[0] == '^' ? prec : prec + 1);   /* ^ is right associative */
        if (right < 0)
            return right;
        left = add(ps, (node){.type = N_BIN, .s = binops[k].op, .len = strlen(binops[k].op),
                              .prec = prec, .a = left, .b = right});
    }
    ps->depth--;
    return left;
}

/* MATLAB precedence of a printed node: higher binds tighter. */
static int mprec(const node *nd)
{
    switch (nd->type) {
    case N_BIN: return nd->prec == 8 ? 9 : nd->prec == 3 ? 4 : nd->prec;   /* all relations at one level */
    case N_NEG: return UNARY_PREC;
    default: return 10;
    }
}

static void emit(const parser *ps, int i, mm_buf *out);

static void emit_wrapped(const parser *ps, int i, int need, mm_buf *out)
{
    int paren = mprec(&ps->n[i]) < need;
    if (paren)
        mm_buf_char(out, '(');
    emit(ps, i, out);
    if (paren)
        mm_buf_char(out, ')');
}

static int name_is(const node *nd, const char *s)
{
    return nd->len == strlen(s) && memcmp(nd->s, s, nd->len) == 0;
}

static void emit(const parser *ps, int i, mm_buf *out)
{
    const node *nd = &ps->n[i];
    switch (nd->type) {
    case N_NUM:
        mm_buf_put(out, nd->s, nd->len);
        break;
    case N_NAME:
        if (name_is(nd, "_pi"))
            mm_buf_puts(out, "pi");
        else if (name_is(nd, "_e") || name_is(nd, "e"))
            mm_buf_puts(out, "exp(1)");
        else
            mm_buf_put(out, nd->s, nd->len);
        break;
    case N_NEG:
        mm_buf_char(out, '-');
        emit_wrapped(ps, nd->a, UNARY_PREC + 1, out);     /* -(a+b), -(-a); -a.^2 keeps -(a.^2) */
        break;
    case N_BIN: {
        static const struct { const char *mu, *ml; } ops[] = {
            {"^", ".^"}, {"*", ".*"}, {"/", "./"}, {"!=", "~="}, {"&&", "&"}, {"||", "|"},
        };
        const char *op = NULL;
        for (size_t k = 0; k < sizeof ops / sizeof ops[0]; k++)
            if (name_is(nd, ops[k].mu))
                op = ops[k].ml;
        int p = mprec(nd);
        emit_wrapped(ps, nd->a, nd->prec == 8 && ps->n[nd->a].type == N_NEG ? p + 1 : p, out);
        if (op)
            mm_buf_puts(out, op);
        else
            mm_buf_put(out, nd->s, nd->len);
        emit_wrapped(ps, nd->b, p + 1, out);                /* left associative: equal on the right wraps */
        break;
    }
    case N_CALL: {
        /* min/max of any count nest by twos (they broadcast); sum and avg add up */
        int minmax = name_is(nd, "min") || name_is(nd, "max");
        int sum = name_is(nd, "sum"), avg = name_is(nd, "avg");
        if ((minmax || sum || avg) && nd->nargs >= 1) {
            if (nd->nargs == 1) {
                emit_wrapped(ps, nd->args[0], 10, out);
                break;
            }
            if (minmax) {
                for (int k = 0; k < nd->nargs - 1; k++) {
                    mm_buf_put(out, nd->s, nd->len);
                    mm_buf_char(out, '(');
                    emit(ps, nd->args[k], out);
                    mm_buf_puts(out, ", ");
                }
                emit(ps, nd->args[nd->nargs - 1], out);
                for (int k = 0; k < nd->nargs - 1; k++)
                    mm_buf_char(out, ')');
                break;
            }
            mm_buf_char(out, '(');
            for (int k = 0; k < nd->nargs; k++) {
                if (k)
                    mm_buf_char(out, '+');
                emit_wrapped(ps, nd->args[k], 6, out);
            }
            mm_buf_char(out, ')');
            if (avg) {
                char n[16];
                snprintf(n, sizeof n, "/%d", nd->nargs);
                mm_buf_puts(out, n);
            }
            break;
        }
        if (name_is(nd, "rint") && nd->nargs == 1) {    /* muParser: floor(x + 0.5), not round's away from 0 */
            mm_buf_puts(out, "floor(");
            emit_wrapped(ps, nd->args[0], 5, out);
            mm_buf_puts(out, " + 0.5)");
            break;
        }
        if (name_is(nd, "ln"))
            mm_buf_puts(out, "log");
        else
            mm_buf_put(out, nd->s, nd->len);
        mm_buf_char(out, '(');
        for (int k = 0; k < nd->nargs; k++) {
            if (k)
                mm_buf_puts(out, ", ");
            emit(ps, nd->args[k], out);
        }
        mm_buf_char(out, ')');
        break;
    }
    }
}

int mm_script_expr(const char *text, mm_buf *out, mm_error *err)
{
    parser *ps = calloc(1, sizeof *ps);
    if (!ps)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");
    ps->p = text;
    ps->err = err;
    int root = parse(ps, 0);
    skip(ps);
    if (root >= 0 && *ps->p)
        root = fail(ps, "the expression cannot be read at '%.20s'", ps->p);
    int rc = ps->rc;
    if (rc == MM_OK)
        emit(ps, root, out);
    free(ps);
    return rc;
}

/* ==== the script ============================================================ */

/* text inside a single-quoted MATLAB string: quotes doubled, no new lines */
static void quoted(mm_buf *b, const char *s)
{
    for (; s && *s; s++) {
        if (*s == '\'')
            mm_buf_puts(b, "''");
        else if (*s == '\n' || *s == '\r')
            mm_buf_char(b, ' ');
        else
            mm_buf_char(b, *s);
    }
}

/* the same, inside a format string of fprintf/error: % doubled too */
static void quoted_fmt(mm_buf *b, const char *s)
{
    for (; s && *s; s++) {
        if (*s == '%')
            mm_buf_puts(b, "%%");
        else if (*s == '\\')
            mm_buf_puts(b, "\\\\");
        else {
            char c[2] = {*s, '\0'};
            quoted(b, c);
        }
    }
}

static void num(mm_buf *b, double v)
{
    char s[MM_DTOA_BUFSIZE];
    mm_buf_put(b, s, (size_t)mm_dtoa(v, s));
}

/* %g of C, for limits written into messages as the API writes them */
static void gnum(mm_buf *b, double v)
{
    char s[32];
    snprintf(s, sizeof s, "%g", v);
    mm_buf_puts(b, s);
}

static void comment_line(mm_buf *b, const char *prefix, const char *text)
{
    mm_buf_puts(b, prefix);
    for (const char *s = text; s && *s; s++)
        mm_buf_char(b, *s == '\n' ? ' ' : *s);
    mm_buf_char(b, '\n');
}

static void value(mm_buf *b, const mm_param *p, const mm_value *v)
{
    switch (p->kind) {
    case MM_REAL:
    case MM_INT:
        num(b, v->x);
        break;
    case MM_CHOICE:
        mm_buf_char(b, '\'');
        quoted(b, v->text);
        mm_buf_char(b, '\'');
        break;
    case MM_EXPR:
        break;                                      /* written by the caller */
    case MM_VECTOR:
    case MM_MATRIX:
        mm_buf_char(b, '[');
        for (int i = 0; i < v->rows; i++) {
            if (i)
                mm_buf_puts(b, "; ");
            for (int j = 0; j < v->cols; j++) {
                if (j)
                    mm_buf_char(b, ' ');
                num(b, v->data[i * v->cols + j]);
            }
        }
        mm_buf_char(b, ']');
        break;
    }
}

/* the parameter as a function handle: @(x, y) <expr>, broadcast to the
 * shape of its first variable when the expression does not use it */
static void expr_param(mm_buf *b, const mm_param *p, const mm_value *v)
{
    mm_buf e;
    mm_buf_init(&e, 1 << 16);
    mm_error err;
    int rc = mm_script_expr(v->text, &e, &err);
    char first[64] = "x";
    const char *vars = p->vars ? p->vars : "x";
    size_t n = strcspn(vars, ",");
    snprintf(first, sizeof first, "%.*s", (int)n, vars);
    mm_buf_puts(b, p->name);
    mm_buf_puts(b, "_text = '");
    quoted(b, v->text);
    mm_buf_puts(b, "';\n");
    mm_buf_puts(b, p->name);
    mm_buf_puts(b, " = @(");
    for (const char *s = vars; *s; s++)
        if (*s != ' ')
            mm_buf_puts(b, *s == ',' ? ", " : (char[]){*s, '\0'});
    mm_buf_puts(b, ") ");
    if (rc == MM_OK) {
        mm_buf_puts(b, "mm_real(");
        mm_buf_put(b, e.p, e.len);
        mm_buf_puts(b, " + 0*");
        mm_buf_puts(b, first);
        mm_buf_char(b, ')');
    } else {
        mm_buf_puts(b, "error('mechmat:expression', '");
        quoted_fmt(b, err.msg);
        mm_buf_puts(b, "')");
    }
    mm_buf_puts(b, ";");
    mm_buf_free(&e);
}

static void unit_text(mm_buf *b, const char *unit)
{
    if (unit && unit[0]) {
        mm_buf_char(b, ' ');
        quoted_fmt(b, unit);
    }
}

/* if ~(test), error('mechmat:out_of_range', 'message', value); end */
static void limit_check(mm_buf *b, const mm_param *p)
{
    const char *n = p->name;
    char t[512];
    switch (p->kind) {
    case MM_REAL:
        snprintf(t, sizeof t, "if ~(isscalar(%s) && isreal(%s) && %s >= ", n, n, n);
        mm_buf_puts(b, t);
        num(b, p->min);
        snprintf(t, sizeof t, " && %s <= ", n);
        mm_buf_puts(b, t);
        num(b, p->max);
        mm_buf_puts(b, ")\n    error('mechmat:out_of_range', '");
        quoted_fmt(b, n);
        mm_buf_puts(b, " must be between ");
        gnum(b, p->min);
        mm_buf_puts(b, " and ");
        gnum(b, p->max);
        unit_text(b, p->unit);
        snprintf(t, sizeof t, "; got %%.10g', %s);\nend\n", n);
        mm_buf_puts(b, t);
        break;
    case MM_INT:
        snprintf(t, sizeof t, "if ~(isscalar(%s) && %s == round(%s) && %s >= ", n, n, n, n);
        mm_buf_puts(b, t);
        num(b, p->min);
        snprintf(t, sizeof t, " && %s <= ", n);
        mm_buf_puts(b, t);
        num(b, p->max);
        mm_buf_puts(b, ")\n    error('mechmat:out_of_range', '");
        quoted_fmt(b, n);
        mm_buf_puts(b, " must be a whole number between ");
        gnum(b, p->min);
        mm_buf_puts(b, " and ");
        gnum(b, p->max);
        snprintf(t, sizeof t, "; got %%.10g', %s);\nend\n", n);
        mm_buf_puts(b, t);
        break;
    case MM_CHOICE:
        snprintf(t, sizeof t, "if ~any(strcmp(%s, {", n);
        mm_buf_puts(b, t);
        for (int i = 0; p->choices[i]; i++) {
            mm_buf_puts(b, i ? ", '" : "'");
            quoted(b, p->choices[i]);
            mm_buf_char(b, '\'');
        }
        mm_buf_puts(b, "}))\n    error('mechmat:bad_value', '");
        quoted_fmt(b, n);
        mm_buf_puts(b, " must be one of ");
        for (int i = 0; p->choices[i]; i++) {
            if (i)
                mm_buf_puts(b, ", ");
            quoted_fmt(b, p->choices[i]);
        }
        snprintf(t, sizeof t, "; got ''%%s''', %s);\nend\n", n);
        mm_buf_puts(b, t);
        break;
    case MM_VECTOR:
    case MM_MATRIX:
        if (p->kind == MM_VECTOR)
            snprintf(t, sizeof t, "if ~(isempty(%s) || (isvector(%s) && numel(%s) <= %d))\n"
                                  "    error('mechmat:out_of_range', '%s may have at most %d numbers; got %%d', numel(%s));\nend\n",
                     n, n, n, p->max_cols, n, p->max_cols, n);
        else
            snprintf(t, sizeof t, "if ~(size(%s, 1) <= %d && size(%s, 2) <= %d)\n"
                                  "    error('mechmat:out_of_range', '%s may have at most %d rows and %d columns; got %%d by %%d', size(%s, 1), size(%s, 2));\nend\n",
                     n, p->max_rows, n, p->max_cols, n, p->max_rows, p->max_cols, n, n);
        mm_buf_puts(b, t);
        snprintf(t, sizeof t, "if any(%s(:) < ", n);
        mm_buf_puts(b, t);
        num(b, p->min);
        snprintf(t, sizeof t, " | %s(:) > ", n);
        mm_buf_puts(b, t);
        num(b, p->max);
        mm_buf_puts(b, ")\n    error('mechmat:out_of_range', 'each number of ");
        quoted_fmt(b, n);
        mm_buf_puts(b, " must be between ");
        gnum(b, p->min);
        mm_buf_puts(b, " and ");
        gnum(b, p->max);
        unit_text(b, p->unit);
        mm_buf_puts(b, "');\nend\n");
        break;
    case MM_EXPR:
        break;
    }
}

int mm_script_write(const mm_exercise *ex, const mm_value *vals, const char *body,
                    const char *query, const char *version, mm_buf *out)
{
    mm_buf_reset(out);
    mm_buf *b = out;
    char line[600];

    snprintf(line, sizeof line, "%% %s: %s\n", ex->id, ex->title);
    mm_buf_puts(b, line);
    comment_line(b, "% ", ex->summary);
    mm_buf_puts(b, "%\n");
    snprintf(line, sizeof line, "%% Written by mechmat %s for the request\n%%   GET /api/exercises/%s/solve%s%.400s\n",
             version, ex->id, query && query[0] ? "?" : "", query ? query : "");
    mm_buf_puts(b, line);
    mm_buf_puts(b, "% It runs unchanged in GNU Octave 7.3 and MATLAB R2019b or later.  Change a\n"
                   "% constant below and run it again: the limits are checked as on the web page.\n"
                   "% At the end it prints the answer's numbers, as the API gives them.\n\n");

    mm_buf_puts(b, "%% Parameters\n");
    for (int i = 0; i < ex->n_params; i++)
        if (ex->params[i].kind == MM_EXPR) {
            mm_buf_puts(b, "% A negative number to a fractional power is not a real number: NaN, as on the\n"
                           "% web page (MATLAB would go on with a complex one).\n"
                           "mm_real = @(v) real(v) + 0 ./ (imag(v) == 0);\n");
            break;
        }
    for (int i = 0; i < ex->n_params; i++) {
        const mm_param *p = &ex->params[i];
        if (p->kind == MM_EXPR) {
            expr_param(b, p, &vals[i]);
        } else {
            mm_buf_puts(b, p->name);
            mm_buf_puts(b, " = ");
            value(b, p, &vals[i]);
            mm_buf_char(b, ';');
        }
        snprintf(line, sizeof line, "  %% %s%s%s%s: %s", p->label, p->unit && p->unit[0] ? " [" : "",
                 p->unit ? p->unit : "", p->unit && p->unit[0] ? "]" : "", p->help ? p->help : "");
        comment_line(b, "", line);
    }

    mm_buf_puts(b, "\n%% Limits (the web page's)\n");
    for (int i = 0; i < ex->n_params; i++)
        limit_check(b, &ex->params[i]);

    mm_buf_puts(b, "\n%% The model and the method\nout = struct();\n");
    mm_buf_puts(b, body ? body : "");
    if (b->len && b->p[b->len - 1] != '\n')
        mm_buf_char(b, '\n');

    mm_buf_puts(b, "\n%% The answer: name = value unit\nnames = {");
    mm_buf *u = NULL;
    mm_buf units;
    mm_buf_init(&units, 1 << 20);
    u = &units;
    int first = 1;
    for (int i = 0; i < ex->n_outputs; i++) {
        const mm_output *o = &ex->outputs[i];
        if (o->kind != MM_OUT_SCALAR)
            continue;
        for (int k = 0; k < mm_output_count(o); k++, first = 0) {
            char name[160];
            mm_output_member(o, mm_output_index(o, k), name, sizeof name);
            mm_buf_puts(b, first ? "'" : ", '");
            mm_buf_puts(b, name);
            mm_buf_char(b, '\'');
            mm_buf_puts(u, first ? "'" : ", '");
            quoted(u, o->unit);
            mm_buf_char(u, '\'');
        }
    }
    mm_buf_puts(b, "};\nunits = {");
    mm_buf_put(b, units.p ? units.p : "", units.len);
    mm_buf_free(&units);
    mm_buf_puts(b, "};\n"
                   "for i = 1:numel(names)\n"
                   "    if isfield(out, names{i})\n"
                   "        fprintf('%s = %.17g', names{i}, out.(names{i}));\n"
                   "        if ~isempty(units{i})\n"
                   "            fprintf(' %s', units{i});\n"
                   "        end\n"
                   "        fprintf('\\n');\n"
                   "    end\n"
                   "end\n");
    return b->failed ? MM_ETOOBIG : MM_OK;
}
