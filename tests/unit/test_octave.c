/* test_octave.c — the Octave/MATLAB script of every exercise (mm_script.h)
 * run in GNU Octave, its printed numbers compared with the API's answer:
 *   - at the defaults and at MM_OCTAVE_DRAWS (5) random draws per exercise,
 *     every scalar of the answer is printed by the script, with its unit, and
 *     agrees within the accuracy the answer states (exact: 1e-10 relative;
 *     with an error: twice the error plus 1e-10 relative; neither: 1e-9);
 *   - scripts use no Octave-only syntax, so that they run in MATLAB too;
 *   - the expression translation (muParser -> vectorised MATLAB) gives the
 *     same numbers as mm_expr at many points.
 * All scripts of a run go to one Octave process (start-up costs 0.3 s).
 * MM_SEED overrides the draws' seed; MM_ONLY=id,id runs just those
 * exercises' scripts (while one is written). */
#include "mm_test.h"

#include <cJSON.h>
#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "mm_api.h"
#include "mm_dtoa.h"
#include "mm_expr.h"
#include "mm_params.h"
#include "mm_result_impl.h"
#include "mm_script.h"

static char dir[256];

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *s = malloc((size_t)n + 1);
    if (s && fread(s, 1, (size_t)n, f) != (size_t)n) {
        free(s);
        s = NULL;
    }
    if (s)
        s[n] = '\0';
    fclose(f);
    return s;
}

static void spit(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

/* Run driver.m in Octave in dir; returns its output (malloc'd).  With
 * parts = 2, two Octave processes share the work (the driver takes every
 * second item from `part`), one per core, and their outputs follow each
 * other. */
static char *octave(int parts)
{
    char cmd[1200];
    /* a hang is stopped by a CPU-time limit, not a wall-clock one: on a
     * loaded machine (load 14-16) the two Octaves once took over 600 s of
     * wall time for their ~60 s of CPU */
    const char *oct = "(ulimit -t 900; exec octave --no-gui --no-window-system --norc --quiet";
    if (parts == 2)
        snprintf(cmd, sizeof cmd,
                 "cd '%s' && { %s --eval 'part = 1; driver') > out1.txt 2>&1 & "
                 "%s --eval 'part = 2; driver') > out2.txt 2>&1; wait; } ; cat out1.txt out2.txt",
                 dir, oct, oct);
    else
        snprintf(cmd, sizeof cmd, "cd '%s' && %s --eval 'driver') 2>&1", dir, oct);
    FILE *p = popen(cmd, "r");
    assert_non_null(p);
    size_t cap = 1 << 20, len = 0;
    char *out = malloc(cap);
    size_t n;
    while ((n = fread(out + len, 1, cap - len - 1, p)) > 0) {
        len += n;
        if (cap - len < 4096)
            out = realloc(out, cap *= 2);
    }
    out[len] = '\0';
    pclose(p);
    return out;
}

/* ---- draws (the same generator as test_exercises.c) --------------------------------------- */

static unsigned long long rng_state;

static double urand(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (double)((rng_state * 2685821657736338717ULL) >> 11) / 9007199254740992.0;
}

static void draw(const mm_param *p, char *out, size_t size, mm_result *arena)
{
    char num[MM_DTOA_BUFSIZE];
    switch (p->kind) {
    case MM_REAL:
    case MM_INT: {
        double v = p->min > 0 && p->max / p->min > 100 ? p->min * pow(p->max / p->min, urand())
                                                       : p->min + (p->max - p->min) * urand();
        if (p->kind == MM_INT)
            v = floor(v + 0.5);
        mm_dtoa(fmin(fmax(v, p->min), p->max), out);
        break;
    }
    case MM_CHOICE: {
        int n = 0;
        while (p->choices[n])
            n++;
        snprintf(out, size, "%s", p->choices[(int)(urand() * n) % n]);
        break;
    }
    case MM_EXPR:
        snprintf(out, size, "%s", p->def_text);
        break;
    case MM_VECTOR:
    case MM_MATRIX: {
        mm_value v;
        mm_error err;
        assert_int_equal(mm_param_default(p, &v, arena, &err), MM_OK);
        int sym = p->kind == MM_MATRIX && v.rows == v.cols;
        for (int i = 0; sym && i < v.rows; i++)
            for (int j = 0; j < i; j++)
                sym &= v.data[i * v.cols + j] == v.data[j * v.cols + i];
        double f[64 * 64];
        for (int k = 0; k < v.rows * v.cols && k < 64 * 64; k++)
            f[k] = 0.5 + urand();
        size_t len = 0;
        out[0] = '\0';
        for (int i = 0; i < v.rows; i++) {
            for (int j = 0; j < v.cols; j++) {
                int k = i * v.cols + j, kf = sym && j < i ? j * v.cols + i : k;
                double x = fmin(fmax(v.data[k] * (kf < 64 * 64 ? f[kf] : 1.0), p->min), p->max);
                mm_dtoa(x, num);
                len += (size_t)snprintf(out + len, size - len, "%s%s", j ? "," : "", num);
            }
            if (i + 1 < v.rows)
                len += (size_t)snprintf(out + len, size - len, ";");
        }
        break;
    }
    }
}

/* ---- MATLAB only: what Octave accepts and MATLAB does not ------------------------------------ */

/* The first Octave-only construct in code (strings and comments skipped), or NULL. */
static const char *octave_only(const char *s)
{
    static const char *const bad[] = {"!=", "++", "+=", "-=", "*=", "/=", "endif", "endfor",
                                      "endwhile", "endfunction", "end_try_catch", "printf(",
                                      "function ", "unwind_protect", "#", "\""};
    int line_start = 1;
    for (const char *p = s; *p; p++) {
        if (*p == '%') {                       /* a comment to the end of the line */
            while (*p && *p != '\n')
                p++;
            if (!*p)
                break;
            line_start = 1;
            continue;
        }
        if (*p == '\'') {                      /* a string, unless a transpose */
            char prev = p > s ? p[-1] : ' ';
            if (!(isalnum((unsigned char)prev) || prev == ')' || prev == ']' || prev == '}' ||
                  prev == '.' || prev == '\'' || prev == '_')) {
                for (p++; *p && *p != '\n'; p++)
                    if (*p == '\'') {
                        if (p[1] == '\'')
                            p++;
                        else
                            break;
                    }
                if (!*p)
                    break;
                continue;
            }
        }
        for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++)
            if (strncmp(p, bad[k], strlen(bad[k])) == 0) {
                int word = isalpha((unsigned char)bad[k][0]);
                char before = p > s ? p[-1] : ' ';
                if (word && (isalnum((unsigned char)before) || before == '_'))
                    continue;                 /* fprintf( holds printf( */
                if (strcmp(bad[k], "function ") == 0 && !line_start)
                    continue;
                return bad[k];
            }
        if (!isspace((unsigned char)*p))
            line_start = 0;
        if (*p == '\n')
            line_start = 1;
    }
    return NULL;
}

static void scripts_should_use_no_octave_only_syntax(void **state)
{
    (void)state;
    assert_null(octave_only("x = 1; % x != 2 # no\ny = 'a \"quoted\" # text'; z = x';\nfprintf('%d\\n', x);\n"));
    assert_string_equal(octave_only("if x != 1\n"), "!=");
    assert_string_equal(octave_only("x += 1;\n"), "+=");
    assert_string_equal(octave_only("printf('a');\n"), "printf(");
    assert_string_equal(octave_only("s = \"a\";\n"), "\"");
    assert_string_equal(octave_only("endif\n"), "endif");
    int bodies = 0;
    for (int i = 0; i < mm_exercise_count; i++) {
        char path[512];
        snprintf(path, sizeof path, "%.*sm", (int)strlen(mm_exercises[i]->theory) - 2, mm_exercises[i]->theory);
        char *body = slurp(path);
        if (!body)
            continue;
        bodies++;
        const char *bad = octave_only(body);
        if (bad)
            fail_msg("%s: the script body uses '%s', which MATLAB does not accept", path, bad);
        free(body);
    }
    print_message("%d exercise bodies checked\n", bodies);
}

/* ---- the expression translation ------------------------------------------------------------- */

static void expressions_should_translate_to_the_same_numbers(void **state)
{
    (void)state;
    static const char *const exprs[] = {
        "x^3+sin(x)-2", "-x^2", "2^3^2", "(-x)^2", "-2^-x", "x/2/3", "x-(1-x)", "x*-2",
        "sin(pi*x)/(x^2+1)", "ln(abs(x)+1)+log10(2+x^2)+log2(3)", "rint(x*3)", "min(x,0.5,-x)",
        "max(x,1-x)", "sum(x,2,3)", "avg(1,x)", "exp(-x^2/2)*cos(5*x)", "sqrt(abs(x))*sign(x)",
        "(x<0.5)*1+(x>=0.5)*2", "(x!=0)&&(x<1)||(x>2)", "atan2(x,1+x^2)", "_pi*_e", "e^x", "3",
        "1e-3*x+2.5E2", "tanh(x)+asinh(x)", "x^2^0.5",
    };
    enum { N = sizeof exprs / sizeof exprs[0], PTS = 7 };
    static const double xs[PTS] = {-2.5, -1, -0.3, 0, 0.5, 1.75, 3};
    const char *const vars[] = {"x"};
    mm_buf drv;
    mm_buf_init(&drv, 1 << 20);
    mm_buf_puts(&drv, "x = [");
    for (int k = 0; k < PTS; k++) {
        char s[MM_DTOA_BUFSIZE];
        mm_dtoa(xs[k], s);
        mm_buf_puts(&drv, k ? " " : "");
        mm_buf_puts(&drv, s);
    }
    mm_buf_puts(&drv, "];\nmm_real = @(v) real(v) + 0 ./ (imag(v) == 0);\n");
    double want[N][PTS];
    for (int i = 0; i < N; i++) {
        mm_expr *e;
        mm_error err;
        assert_int_equal(mm_expr_compile(exprs[i], vars, 1, &e, &err), MM_OK);
        for (int k = 0; k < PTS; k++)
            want[i][k] = mm_expr_eval(e, &xs[k]);
        mm_expr_free(e);
        mm_buf m;
        mm_buf_init(&m, 1 << 16);
        if (mm_script_expr(exprs[i], &m, &err) != MM_OK)
            fail_msg("%s: %s", exprs[i], err.msg);
        mm_buf_puts(&drv, "v = mm_real(");
        mm_buf_put(&drv, m.p, m.len);
        mm_buf_puts(&drv, " + 0*x); fprintf('%.17g ', v); fprintf('\\n');\n");
        mm_buf_free(&m);
    }
    char path[300];
    snprintf(path, sizeof path, "%s/driver.m", dir);
    spit(path, drv.p);
    mm_buf_free(&drv);
    char *out = octave(1), *p = out;
    for (int i = 0; i < N; i++) {
        for (int k = 0; k < PTS; k++) {
            char *end;
            double got = strtod(p, &end);
            if (end == p)
                fail_msg("%s: Octave printed no number: %.300s", exprs[i], p);
            p = end;
            if (isnan(want[i][k]) ? !isnan(got) : fabs(got - want[i][k]) > 1e-13 * fmax(1, fabs(want[i][k])))
                fail_msg("%s at x = %g: muParser %.17g, Octave %.17g", exprs[i], xs[k], want[i][k], got);
        }
    }
    free(out);
    mm_error err;
    mm_buf m;
    mm_buf_init(&m, 1 << 16);
    assert_int_equal(mm_script_expr("x > 0 ? 1 : 2", &m, &err), MM_EVALUE);
    assert_non_null(strstr(err.msg, "conditional"));
    mm_buf_free(&m);
}

/* ---- every exercise's script ------------------------------------------------------------------ */

typedef struct run {
    const mm_exercise *ex;
    char name[16];
    char query[2048];
    cJSON *answer;
} run;

static int parse_inputs(const mm_exercise *ex, mm_input *in, int n, mm_value *vals, mm_result *arena)
{
    int given[MM_MAX_PARAMS] = {0};
    mm_error err;
    for (int i = 0; i < n; i++)
        for (int k = 0; k < ex->n_params; k++)
            if (strlen(ex->params[k].name) == in[i].name_len &&
                memcmp(ex->params[k].name, in[i].name, in[i].name_len) == 0) {
                given[k] = 1;
                if (mm_param_parse(&ex->params[k], in[i].text, in[i].text_len, &vals[k], arena, &err) != MM_OK)
                    return -1;
            }
    for (int k = 0; k < ex->n_params; k++)
        if (!given[k] && mm_param_default(&ex->params[k], &vals[k], arena, &err) != MM_OK)
            return -1;
    return 0;
}

/* Does the script's line "name = value unit" agree with the answer's scalar? */
/* The worst agreement seen: |Octave - API| / allowed, and where. */
static double worst_ratio, worst_rel;
static char worst_where[256];

static int agrees(const cJSON *scalar, const char *output, const run *r)
{
    const char *name = cJSON_GetObjectItem(scalar, "name")->valuestring;
    const char *unit = cJSON_GetObjectItem(scalar, "unit")->valuestring;
    double want = cJSON_GetObjectItem(scalar, "value")->valuedouble;
    char key[200];
    snprintf(key, sizeof key, "\n%s = ", name);
    const char *at = strstr(output, key);
    if (!at) {
        print_error("%s (%s): the script prints no %s\n", r->ex->id, r->query, name);
        return 0;
    }
    at += strlen(key);
    char *end;
    double got = strtod(at, &end);
    while (*end == ' ')
        end++;
    size_t ul = strcspn(end, "\n");
    if (ul != strlen(unit) || strncmp(end, unit, ul) != 0) {
        print_error("%s (%s): %s printed with unit '%.*s', the API's is '%s'\n", r->ex->id, r->query, name,
                    (int)ul, end, unit);
        return 0;
    }
    const cJSON *exact = cJSON_GetObjectItem(scalar, "exact"), *error = cJSON_GetObjectItem(scalar, "error");
    double tol = cJSON_IsTrue(exact) ? 1e-10 * fabs(want)
               : error ? 2 * error->valuedouble + 1e-10 * fabs(want)
                       : 1e-9 * fabs(want);
    double ratio = fabs(got - want) / (tol + 1e-300);
    if (ratio > worst_ratio) {
        worst_ratio = ratio;
        worst_rel = want != 0 ? fabs(got - want) / fabs(want) : fabs(got - want);
        snprintf(worst_where, sizeof worst_where, "%s %s (%.120s)", r->ex->id, name, r->query);
    }
    if (!(fabs(got - want) <= tol + 1e-300)) {
        print_error("%s (%s): %s = %.17g in Octave, %.17g by the API (difference %.3g > %.3g)\n", r->ex->id,
                    r->query, name, got, want, fabs(got - want), tol);
        return 0;
    }
    return 1;
}

/* Is id one of the comma-separated ids of list? */
static int listed(const char *list, const char *id)
{
    size_t n = strlen(id);
    for (const char *p = list; *p;) {
        const char *e = strchr(p, ',');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        if (len == n && strncmp(p, id, n) == 0)
            return 1;
        p += len + (e != NULL);
    }
    return 0;
}

static void every_script_should_reproduce_the_answer_in_octave(void **state)
{
    (void)state;
    const char *seed = getenv("MM_SEED"), *draws_env = getenv("MM_OCTAVE_DRAWS");
    int draws = draws_env ? atoi(draws_env) : 5, nrun = 0, missing = 0;
    run *runs = calloc((size_t)mm_exercise_count * (size_t)(draws + 1), sizeof *runs);
    mm_buf drv;
    mm_buf_init(&drv, 1 << 20);
    mm_buf_puts(&drv, "files = {");
    const char *only = getenv("MM_ONLY");          /* "id,id": just these exercises (while writing one) */
    for (int i = 0; i < mm_exercise_count; i++) {
        const mm_exercise *ex = mm_exercises[i];
        if (only && !listed(only, ex->id))
            continue;
        char path[512];
        snprintf(path, sizeof path, "%.*sm", (int)strlen(ex->theory) - 2, ex->theory);
        char *body = slurp(path);
        if (!body) {
            print_error("%s has no Octave script: write %s (README, \"How to add an exercise\")\n", ex->id, path);
            missing++;
            continue;
        }
        rng_state = seed ? strtoull(seed, NULL, 10) : 0x5DEECE66DULL ^ (unsigned long long)(i + 1);
        for (int d = 0, attempts = 0; d <= draws && attempts < 50 * (draws + 1); attempts++) {
            mm_result arena;
            mm_result_init(&arena, 1 << 22);
            mm_input in[MM_MAX_PARAMS];
            char text[MM_MAX_PARAMS][4096];
            int n = 0;
            run *r = &runs[nrun];
            r->query[0] = '\0';
            for (int k = 0; d > 0 && k < ex->n_params; k++, n++) {
                draw(&ex->params[k], text[n], sizeof text[n], &arena);
                in[n] = (mm_input){ex->params[k].name, text[n], strlen(ex->params[k].name), strlen(text[n])};
                size_t l = strlen(r->query);
                snprintf(r->query + l, sizeof r->query - l, "%s%s=%s", n ? "&" : "", ex->params[k].name, text[n]);
            }
            mm_buf out;
            mm_buf_init(&out, MM_ANSWER_MAX);
            int status = mm_api_solve(ex, in, n, &out);
            mm_value vals[MM_MAX_PARAMS];
            if (status != 200 || parse_inputs(ex, in, n, vals, &arena) != 0) {
                if (d == 0)
                    fail_msg("%s at its defaults: status %d", ex->id, status);
                mm_buf_free(&out);
                mm_result_release(&arena);
                continue;                       /* a joint limit refused the draw */
            }
            r->ex = ex;
            r->answer = cJSON_Parse(out.p);
            snprintf(r->name, sizeof r->name, "s%04d", nrun);
            mm_buf script;
            mm_buf_init(&script, 1 << 22);
            assert_int_equal(mm_script_write(ex, vals, body, r->query, MM_VERSION, &script), MM_OK);
            char file[300];
            snprintf(file, sizeof file, "%s/%s.m", dir, r->name);
            spit(file, script.p);
            const char *bad = octave_only(script.p);
            if (bad)
                fail_msg("%s: the script uses '%s', which MATLAB does not accept", ex->id, bad);
            mm_buf_free(&script);
            mm_buf_free(&out);
            mm_result_release(&arena);
            mm_buf_puts(&drv, nrun ? ", '" : "'");
            mm_buf_puts(&drv, r->name);
            mm_buf_puts(&drv, "'");
            nrun++;
            d++;
        }
        free(body);
    }
    mm_buf_puts(&drv, "};\n"
                      "for i = part:2:numel(files)\n"
                      "    fprintf('\\n=== %s\\n', files{i});\n"
                      "    try\n"
                      "        mm_run_one(files{i});\n"
                      "    catch err\n"
                      "        fprintf('\\n!!! %s\\n', err.message);\n"
                      "    end\n"
                      "end\n"
                      "fprintf('\\n=== end\\n');\n");
    char path[300];
    snprintf(path, sizeof path, "%s/driver.m", dir);
    spit(path, drv.p);
    snprintf(path, sizeof path, "%s/mm_run_one.m", dir);
    spit(path, "function mm_run_one(name)\n    % each script in a workspace of its own\n    eval(name);\nend\n");
    mm_buf_free(&drv);

    int failures = 0, compared = 0;
    if (nrun > 0) {
        char *out = octave(2);
        for (int k = 0; k < nrun; k++) {
            run *r = &runs[k];
            char mark[40];
            snprintf(mark, sizeof mark, "\n=== %s\n", r->name);
            char *start = strstr(out, mark), *stop = start ? strstr(start + 1, "\n=== ") : NULL;
            if (!start || !stop) {
                print_error("%s: no output from Octave for %s\n%.2000s\n", r->ex->id, r->name, out);
                failures++;
                continue;
            }
            start += strlen(mark) - 1;             /* keep the \n before the first line */
            char *section = strndup(start, (size_t)(stop - start) + 1);
            char *err = strstr(section, "\n!!! ");
            if (err) {
                print_error("%s (%s): Octave stopped: %.300s\n", r->ex->id, r->query, err + 5);
                failures++;
            } else {
                const cJSON *s;
                cJSON_ArrayForEach(s, cJSON_GetObjectItem(r->answer, "scalars")) {
                    compared++;
                    failures += !agrees(s, section, r);
                }
            }
            free(section);
        }
        free(out);
    }
    for (int k = 0; k < nrun; k++)
        cJSON_Delete(runs[k].answer);
    free(runs);
    print_message("%d scripts run, %d numbers compared, %d exercises without a script\n", nrun, compared,
                  missing);
    print_message("worst agreement: %.3g of the allowed difference (relative %.3g), %s\n", worst_ratio, worst_rel,
                  worst_where);
    assert_int_equal(failures, 0);
    assert_int_equal(missing, 0);          /* a new exercise without a script fails the suite */
}

static int setup(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/mm-octave-XXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd) == 0 ? 0 : -1;
}

int main(void)
{
    if (system("command -v octave > /dev/null 2>&1") != 0) {
        fprintf(stderr, "octave is not installed: make deps installs it\n");
        return 1;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(scripts_should_use_no_octave_only_syntax),
        cmocka_unit_test(expressions_should_translate_to_the_same_numbers),
        cmocka_unit_test(every_script_should_reproduce_the_answer_in_octave),
    };
    return cmocka_run_group_tests_name("octave", tests, setup, teardown);
}
