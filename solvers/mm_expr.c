/* mm_expr.c — learner expressions over muParser's C API (see mm_expr.h).
 *
 * Every error is read from the handle that raised it (mupError,
 * mupGetErrorCode, mupGetErrorPos) and the message is built here from the
 * code, the position and our copy of the text: muParser's own message and
 * token getters return a static buffer shared by all threads.
 */
#include "mm_expr.h"

#include <ctype.h>
#include <fenv.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <muParserDLL.h>

struct mm_expr {
    muParserHandle_t h;
    size_t nvars;
    double vars[MM_EXPR_MAX_VARS];   /* muParser reads the variables here */
};

static const double PI_VALUE = 3.14159265358979323846;
static const double E_VALUE = 2.71828182845904523536;

/* muParser 2.3 built-in functions (mu::Parser::InitFun). */
static const char *const functions[] = {
    "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sinh", "cosh",
    "tanh", "asinh", "acosh", "atanh", "log2", "log10", "log", "ln", "exp",
    "sqrt", "sign", "rint", "abs", "sum", "avg", "min", "max", NULL
};

/* muParser error codes (mu::EErrorCodes in muParserDef.h, not part of the
 * C header): only the ones a learner's text can cause. */
enum {
    EC_UNEXPECTED_OPERATOR = 0, EC_UNASSIGNABLE_TOKEN = 1,
    EC_UNEXPECTED_EOF = 2, EC_UNEXPECTED_ARG_SEP = 3, EC_UNEXPECTED_ARG = 4,
    EC_UNEXPECTED_VAL = 5, EC_UNEXPECTED_VAR = 6, EC_UNEXPECTED_PARENS = 7,
    EC_UNEXPECTED_STR = 8, EC_STRING_EXPECTED = 9, EC_VAL_EXPECTED = 10,
    EC_MISSING_PARENS = 11, EC_UNEXPECTED_FUN = 12,
    EC_UNTERMINATED_STRING = 13, EC_TOO_MANY_PARAMS = 14,
    EC_TOO_FEW_PARAMS = 15, EC_OPRT_TYPE_CONFLICT = 16, EC_STR_RESULT = 17,
    EC_EMPTY_EXPRESSION = 25, EC_UNEXPECTED_CONDITIONAL = 32,
    EC_MISSING_ELSE_CLAUSE = 33, EC_MISPLACED_COLON = 34,
    EC_IDENTIFIER_TOO_LONG = 36
};

/* ==== small text helpers ================================================= */

static int is_ident_start(int c) { return isalpha(c) || c == '_'; }
static int is_ident_char(int c) { return isalnum(c) || c == '_'; }

static int is_function(const char *name, size_t len)
{
    for (const char *const *f = functions; *f; f++)
        if (strlen(*f) == len && strncmp(*f, name, len) == 0)
            return 1;
    return 0;
}

/* The token that starts at text[pos]: an identifier, a number, or one
 * character; cut to fit cap.  Empty at the end of the text. */
static void token_at(const char *text, size_t len, size_t pos, char *tok,
                     size_t cap)
{
    size_t end = pos;
    if (pos >= len) {
        tok[0] = '\0';
        return;
    }
    if (is_ident_start((unsigned char)text[pos])) {
        while (end < len && is_ident_char((unsigned char)text[end]))
            end++;
    } else if (isdigit((unsigned char)text[pos]) || text[pos] == '.') {
        while (end < len && (isdigit((unsigned char)text[end]) || text[end] == '.'))
            end++;
        if (end < len && (text[end] == 'e' || text[end] == 'E')) {
            end++;
            if (end < len && (text[end] == '+' || text[end] == '-'))
                end++;
            while (end < len && isdigit((unsigned char)text[end]))
                end++;
        }
    } else {
        end = pos + 1;
    }
    size_t n = end - pos < cap - 1 ? end - pos : cap - 1;
    memcpy(tok, text + pos, n);
    tok[n] = '\0';
}

/* Name of the function whose call contains text[pos] (muParser points at
 * or just past the closing parenthesis for a wrong argument count), or
 * "" if none is found. */
static void call_name_near(const char *text, size_t len, size_t pos,
                           char *name, size_t cap)
{
    name[0] = '\0';
    if (len == 0)
        return;
    size_t i = pos < len ? pos : len - 1;
    int depth = 0;
    for (;; i--) {
        if (text[i] == ')')
            depth++;
        else if (text[i] == '(' && --depth <= 0)
            break;
        if (i == 0)
            return;
    }
    size_t end = i;                   /* text[i] is the call's '(' */
    while (end > 0 && isspace((unsigned char)text[end - 1]))
        end--;
    size_t start = end;
    while (start > 0 && is_ident_char((unsigned char)text[start - 1]))
        start--;
    size_t n = end - start < cap - 1 ? end - start : cap - 1;
    memcpy(name, text + start, n);
    name[n] = '\0';
}

/* Names a learner may use, for messages: "x, t, pi and e". */
static void allowed_names(const char *const *names, size_t nvars, char *buf,
                          size_t cap)
{
    size_t used = 0;
    buf[0] = '\0';
    for (size_t i = 0; i < nvars && used < cap; i++)
        used += (size_t)snprintf(buf + used, cap - used, "%s, ", names[i]);
    if (used < cap)
        snprintf(buf + used, cap - used, "pi and e");
}

/* ==== checks ============================================================= */

static int check_names(const char *const *names, size_t nvars, mm_error *err)
{
    if (nvars > MM_EXPR_MAX_VARS)
        return mm_error_set(err, MM_EINTERNAL, NULL,
                            "an expression takes at most %d variables; got %zu",
                            MM_EXPR_MAX_VARS, nvars);
    for (size_t i = 0; i < nvars; i++) {
        const char *s = names[i];
        size_t n = s ? strlen(s) : 0;
        int ok = n > 0 && n <= MM_EXPR_MAX_NAME && is_ident_start((unsigned char)s[0]);
        for (size_t j = 1; ok && j < n; j++)
            ok = is_ident_char((unsigned char)s[j]);
        if (ok)
            ok = strcmp(s, "pi") && strcmp(s, "e") && strcmp(s, "_pi")
                 && strcmp(s, "_e") && !is_function(s, n);
        for (size_t j = 0; ok && j < i; j++)
            ok = strcmp(s, names[j]) != 0;
        if (!ok)
            return mm_error_set(err, MM_EINTERNAL, NULL,
                                "variable name %zu ('%.32s') is not a new "
                                "identifier", i, s ? s : "(null)");
    }
    return MM_OK;
}

int mm_expr_check(const char *text, const char *const *var_names,
                  size_t nvars, mm_error *err)
{
    int rc = check_names(var_names, nvars, err);
    if (rc)
        return rc;
    if (!text)
        text = "";
    size_t len = strnlen(text, MM_EXPR_MAX_LEN + 1), blank = 1;
    if (len > MM_EXPR_MAX_LEN)
        return mm_error_set(err, MM_ERANGE, NULL,
                            "the expression is longer than %d characters",
                            MM_EXPR_MAX_LEN);
    for (size_t i = 0; i < len; i++) {
        unsigned char c = (unsigned char)text[i];
        if ((c < 0x20 && c != '\t') || c >= 0x7f)
            return mm_error_set(err, MM_EVALUE, NULL,
                                "bad expression at position %zu: character "
                                "0x%02x is not allowed; use plain ASCII "
                                "(pi, not the Greek letter)", i + 1, c);
        if (!isspace(c))
            blank = 0;
        /* '=' alone assigns in muParser; == <= >= != compare */
        if (c == '=') {
            if (i + 1 < len && text[i + 1] == '=') {
                i++;
                continue;
            }
            char p = i > 0 ? text[i - 1] : '\0';
            if (p != '<' && p != '>' && p != '!')
                return mm_error_set(err, MM_EVALUE, NULL,
                                    "bad expression at position %zu: '=' is "
                                    "not allowed (write == to compare; give "
                                    "only the right-hand side of a formula)",
                                    i + 1);
        }
    }
    if (blank)
        return mm_error_set(err, MM_EVALUE, NULL, "bad expression: it is empty");
    return MM_OK;
}

/* ==== compile ============================================================ */

/* Turn the error held by handle h into an MM_EVALUE message. */
static int syntax_error(muParserHandle_t h, const char *text,
                        const char *const *names, size_t nvars, mm_error *err)
{
    int code = mupGetErrorCode(h), pos = mupGetErrorPos(h);
    size_t len = strlen(text), p = pos < 0 ? len : (size_t)pos;
    char tok[28], what[150], known[80];
    token_at(text, len, p, tok, sizeof tok);

    switch (code) {
    case EC_UNEXPECTED_OPERATOR:
        snprintf(what, sizeof what, "unexpected operator '%s'", tok);
        break;
    case EC_UNASSIGNABLE_TOKEN: {
        size_t after = p + strlen(tok);
        while (after < len && isspace((unsigned char)text[after]))
            after++;
        int call = after < len && text[after] == '(';
        if (is_ident_start((unsigned char)tok[0]) && is_function(tok, strlen(tok)))
            snprintf(what, sizeof what,
                     "function '%s' needs its argument in parentheses: %s(...)",
                     tok, tok);
        else if (is_ident_start((unsigned char)tok[0]) && call)
            snprintf(what, sizeof what, "unknown function '%s'", tok);
        else if (is_ident_start((unsigned char)tok[0])) {
            allowed_names(names, nvars, known, sizeof known);
            snprintf(what, sizeof what, "unknown variable '%s' (known: %s)",
                     tok, known);
        } else if (isdigit((unsigned char)tok[0]) || tok[0] == '.')
            snprintf(what, sizeof what,
                     "cannot read the number '%s' (outside the range of doubles?)",
                     tok);
        else
            snprintf(what, sizeof what, "unexpected character '%s'", tok);
        break;
    }
    case EC_UNEXPECTED_EOF:
        snprintf(what, sizeof what,
                 "the expression ends too early (an operand is missing)");
        p = len;
        break;
    case EC_UNEXPECTED_ARG_SEP:
        snprintf(what, sizeof what, "unexpected ','");
        break;
    case EC_UNEXPECTED_ARG:
    case EC_UNEXPECTED_VAL:
    case EC_UNEXPECTED_VAR:
        snprintf(what, sizeof what,
                 "unexpected '%s' (is an operator missing? write 2*x, not 2x)",
                 tok);
        break;
    case EC_UNEXPECTED_FUN:
        snprintf(what, sizeof what,
                 "unexpected function '%s' (is an operator missing before it?)",
                 tok);
        break;
    case EC_UNEXPECTED_PARENS:
        snprintf(what, sizeof what, "unexpected parenthesis '%s'", tok);
        break;
    case EC_MISSING_PARENS:
        snprintf(what, sizeof what, "a ')' is missing");
        p = len;
        break;
    case EC_TOO_MANY_PARAMS:
    case EC_TOO_FEW_PARAMS: {
        char fn[32];
        call_name_near(text, len, p, fn, sizeof fn);
        snprintf(what, sizeof what, "too %s arguments for function '%s'",
                 code == EC_TOO_MANY_PARAMS ? "many" : "few", fn);
        break;
    }
    case EC_UNEXPECTED_STR: case EC_STRING_EXPECTED: case EC_VAL_EXPECTED:
    case EC_UNTERMINATED_STRING: case EC_OPRT_TYPE_CONFLICT:
    case EC_STR_RESULT:
        snprintf(what, sizeof what, "text in quotes is not allowed; "
                 "expressions work with numbers only");
        break;
    case EC_EMPTY_EXPRESSION:
        snprintf(what, sizeof what, "it is empty");
        pos = -1;
        break;
    case EC_UNEXPECTED_CONDITIONAL:
        snprintf(what, sizeof what, "unexpected '?' (write c ? a : b)");
        break;
    case EC_MISSING_ELSE_CLAUSE:
        snprintf(what, sizeof what, "'?' needs its ': value' part (write c ? a : b)");
        break;
    case EC_MISPLACED_COLON:
        snprintf(what, sizeof what, "':' without a '?' before it");
        break;
    case EC_IDENTIFIER_TOO_LONG:
        snprintf(what, sizeof what, "a name is too long");
        break;
    default:
        snprintf(what, sizeof what, "cannot parse it (muParser error %d)", code);
        break;
    }
    if (pos < 0)
        return mm_error_set(err, MM_EVALUE, NULL, "bad expression: %s", what);
    if (p >= len)
        return mm_error_set(err, MM_EVALUE, NULL,
                            "bad expression at the end: %s", what);
    return mm_error_set(err, MM_EVALUE, NULL,
                        "bad expression at position %zu: %s", p + 1, what);
}

int mm_expr_compile(const char *text, const char *const *var_names,
                    size_t nvars, mm_expr **out, mm_error *err)
{
    *out = NULL;
    int rc = mm_expr_check(text, var_names, nvars, err);
    if (rc)
        return rc;
    mm_expr *e = calloc(1, sizeof *e);
    if (!e)
        return mm_error_set(err, MM_ENOMEM, NULL, "out of memory for an expression");
    e->nvars = nvars;
    e->h = mupCreate(muBASETYPE_FLOAT);
    if (!e->h) {
        rc = mm_error_set(err, MM_ENOMEM, NULL, "out of memory for an expression");
        goto out;
    }
    /* muParser's own _pi and _e have 12 digits (3.141592653589): replace
     * them too, so that every spelling gives the correctly rounded value */
    mupDefineConst(e->h, "pi", PI_VALUE);
    mupDefineConst(e->h, "e", E_VALUE);
    mupDefineConst(e->h, "_pi", PI_VALUE);
    mupDefineConst(e->h, "_e", E_VALUE);
    for (size_t i = 0; i < nvars; i++)
        mupDefineVar(e->h, var_names[i], &e->vars[i]);
    if (mupError(e->h)) {
        rc = mm_error_set(err, MM_EINTERNAL, NULL,
                          "muParser refused the variable names");
        goto out;
    }

    /* muParser parses on the first evaluation: SetExpr only stores the
     * text.  Evaluating once (variables 0) finds every syntax error. */
    mupSetExpr(e->h, text);
    if (!mupError(e->h)) {
        mupEval(e->h);
        if (!mupError(e->h)) {
            int nres = 0;
            mupEvalMulti(e->h, &nres);   /* "1, 2" gives two results */
            if (mupError(e->h))
                rc = syntax_error(e->h, text, var_names, nvars, err);
            else if (nres != 1)
                rc = mm_error_set(err, MM_EVALUE, NULL,
                                  "bad expression: it gives %d values "
                                  "separated by ','; give one", nres);
            goto out;
        }
    }
    rc = syntax_error(e->h, text, var_names, nvars, err);
out:
    if (rc) {
        mm_expr_free(e);
        return rc;
    }
    *out = e;
    return MM_OK;
}

void mm_expr_free(mm_expr *e)
{
    if (!e)
        return;
    if (e->h)
        mupRelease(e->h);
    free(e);
}

size_t mm_expr_nvars(const mm_expr *e) { return e->nvars; }

/* ==== evaluate =========================================================== */

double mm_expr_eval(mm_expr *e, const double *vars)
{
    for (size_t i = 0; i < e->nvars; i++)
        e->vars[i] = vars[i];
    double v = mupEval(e->h);
    /* muParser raises nothing at run time; if it ever did, say NaN so the
     * caller's isfinite() check catches it */
    return mupError(e->h) ? (double)NAN : v;
}

double mm_expr_eval_err(mm_expr *e, const double *vars, double *err)
{
    double v = mm_expr_eval(e, vars);
    if (!isfinite(v)) {
        *err = INFINITY;
        return v;
    }
    /* Kahan's test: the same evaluation in the three directed rounding
     * modes; every operation rounds the other way, so the spread shows how
     * much rounding the expression amplifies (cancellation, ill-conditioned
     * functions) */
    static const int modes[] = {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    int saved = fegetround();
    double spread = 0;
    for (int m = 0; m < 3; m++) {
        if (fesetround(modes[m]) != 0)
            continue;
        double w = mm_expr_eval(e, vars);
        spread = fmax(spread, fabs(w - v));
    }
    fesetround(saved);
    /* the rounding of the constants (pi, 0.1) and of the variables acts like
     * a relative change of about u in them: what 2u in each variable does */
    double sens = 0, x[MM_EXPR_MAX_VARS];
    for (size_t i = 0; i < e->nvars; i++)
        x[i] = vars[i];
    for (size_t i = 0; i < e->nvars; i++) {
        double h = 2 * DBL_EPSILON * fabs(vars[i]);
        x[i] = vars[i] + h;
        double up = mm_expr_eval(e, x);
        x[i] = vars[i] - h;
        double dn = mm_expr_eval(e, x);
        x[i] = vars[i];
        sens += 0.5 * fabs(up - dn);
    }
    double total = 2 * spread + sens + DBL_EPSILON / 2 * fabs(v);
    *err = isfinite(total) ? total : INFINITY;
    return v;
}

void mm_expr_eval_bulk(mm_expr *e, const double *vars, size_t n, double *out)
{
    size_t nv = e->nvars;
    for (size_t i = 0; i < n; i++) {
        for (size_t j = 0; j < nv; j++)
            e->vars[j] = vars[i * nv + j];
        double v = mupEval(e->h);
        out[i] = mupError(e->h) ? (double)NAN : v;
    }
}

int mm_expr_eval_const(const char *text, double *value, mm_error *err)
{
    mm_expr *e;
    int rc = mm_expr_compile(text, NULL, 0, &e, err);
    if (rc)
        return rc;
    double v = mm_expr_eval(e, NULL);
    mm_expr_free(e);
    if (!isfinite(v))
        return mm_error_set(err, MM_EVALUE, NULL,
                            "'%.64s' is not a finite number (it gives %g)",
                            text, v);
    *value = v;
    return MM_OK;
}
