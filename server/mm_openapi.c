/* mm_openapi.c — see mm_openapi.h. */
#include "mm_openapi.h"

#include <stdio.h>
#include <string.h>

#include "mm_api.h"
#include "mm_params.h"

#define MM_API_VERSION_TEXT "mechmat " MM_VERSION

/* ,"key":"text" */
static void fstr(mm_buf *b, const char *key, const char *text)
{
    mm_buf_char(b, ',');
    mm_buf_key(b, key);
    mm_buf_str(b, text);
}

static void fnum(mm_buf *b, const char *key, double v)
{
    mm_buf_char(b, ',');
    mm_buf_key(b, key);
    mm_buf_num(b, v, key);
}

static void fint(mm_buf *b, const char *key, long long v)
{
    mm_buf_char(b, ',');
    mm_buf_key(b, key);
    mm_buf_int(b, v);
}

/* ---- shared pieces --------------------------------------------------------- */

static const struct {
    int status;
    const char *name, *what;
} errors[] = {
    {400, "BadRequest", "a value that does not parse or lies outside its limits, an unknown parameter, "
                        "a body that is not {\"params\":{...}}: the message names the parameter"},
    {403, "Forbidden", "an instructor's route without the assignment's instructor key (?key=)"},
    {404, "NotFound", "no such exercise, assignment or path"},
    {405, "MethodNotAllowed", "the route does not take this method; the Allow header lists those it takes"},
    {413, "TooLarge", "a body over 1 MiB, a query over 16 KiB, or an answer over the memory a request may use"},
    {422, "NoSolution", "the mechanics has no solution for these parameters (a singular system, no "
                        "convergence, a result that is not finite); the message says why"},
    {500, "Internal", "our fault: logged in full, a generic message sent"},
    {503, "Busy", "the server's work queue is full; try again in a moment"},
};

static void write_components(mm_buf *b)
{
    mm_buf_puts(b, ",\"components\":{\"schemas\":{");
    mm_buf_puts(b,
        "\"Error\":{\"type\":\"object\",\"required\":[\"error\"],\"properties\":{\"error\":{"
        "\"type\":\"object\",\"required\":[\"code\",\"param\",\"message\"],\"properties\":{"
        "\"code\":{\"type\":\"string\",\"enum\":[\"bad_value\",\"out_of_range\",\"unknown_param\","
        "\"bad_json\",\"not_found\",\"method_not_allowed\",\"too_large\",\"no_solution\",\"internal\",\"busy\"]},"
        "\"param\":{\"type\":[\"string\",\"null\"],\"description\":\"the parameter concerned, or null\"},"
        "\"message\":{\"type\":\"string\",\"description\":\"what is wrong and what would be valid, for a learner\"}}}}},");
    mm_buf_puts(b,
        "\"Scalar\":{\"type\":\"object\",\"required\":[\"name\",\"label\",\"unit\",\"value\"],\"properties\":{"
        "\"name\":{\"type\":\"string\"},\"label\":{\"type\":\"string\"},\"unit\":{\"type\":\"string\"},"
        "\"value\":{\"type\":\"number\"},\"text\":{\"type\":\"string\"},"
        "\"exact\":{\"type\":\"boolean\",\"description\":\"a closed form, exact to rounding\"},"
        "\"error\":{\"type\":\"number\",\"description\":\"absolute error of value\"},"
        "\"error_kind\":{\"type\":\"string\",\"enum\":[\"bound\",\"estimate\"]}}},");
    mm_buf_puts(b,
        "\"Series\":{\"type\":\"object\",\"required\":[\"name\",\"label\",\"x_label\",\"x_unit\",\"unit\",\"x\",\"y\"],"
        "\"properties\":{\"name\":{\"type\":\"string\"},\"label\":{\"type\":\"string\"},"
        "\"x_label\":{\"type\":\"string\"},\"x_unit\":{\"type\":\"string\"},\"unit\":{\"type\":\"string\"},"
        "\"figure\":{\"type\":\"string\"},\"mark\":{\"type\":\"string\",\"enum\":[\"line\",\"dots\",\"step\",\"bars\"]},"
        "\"role\":{\"type\":\"string\"},\"x_scale\":{\"type\":\"string\",\"enum\":[\"linear\",\"log\"]},"
        "\"y_scale\":{\"type\":\"string\",\"enum\":[\"linear\",\"log\"]},\"aspect\":{\"type\":\"string\"},"
        "\"x\":{\"type\":\"array\",\"items\":{\"type\":\"number\"}},\"y\":{\"type\":\"array\",\"items\":{\"type\":\"number\"}}}},");
    mm_buf_puts(b,
        "\"Table\":{\"type\":\"object\",\"required\":[\"name\",\"columns\",\"units\",\"rows\"],\"properties\":{"
        "\"name\":{\"type\":\"string\"},\"label\":{\"type\":\"string\"},"
        "\"columns\":{\"type\":\"array\",\"items\":{\"type\":\"string\"}},"
        "\"units\":{\"type\":\"array\",\"items\":{\"type\":\"string\"}},"
        "\"rows\":{\"type\":\"array\",\"items\":{\"type\":\"array\",\"items\":{\"type\":[\"number\",\"string\"]}}}}},");
    mm_buf_puts(b,
        "\"Check\":{\"type\":\"object\",\"required\":[\"name\",\"value\",\"reference\",\"abs_error\",\"tolerance\",\"passed\"],"
        "\"properties\":{\"name\":{\"type\":\"string\"},\"value\":{\"type\":\"number\"},\"reference\":{\"type\":\"number\"},"
        "\"abs_error\":{\"type\":\"number\"},\"rel_error\":{\"type\":\"number\",\"description\":\"left out when the reference is zero\"},"
        "\"tolerance\":{\"type\":\"number\"},\"tolerance_kind\":{\"type\":\"string\",\"enum\":[\"relative\",\"absolute\"]},"
        "\"passed\":{\"type\":\"boolean\"}}},");
    mm_buf_puts(b,
        "\"Animation\":{\"type\":\"object\",\"required\":[\"t\",\"bounds\",\"shapes\"],\"properties\":{"
        "\"t\":{\"type\":\"array\",\"items\":{\"type\":\"number\"}},\"t_label\":{\"type\":\"string\"},\"t_unit\":{\"type\":\"string\"},"
        "\"bounds\":{\"type\":\"array\",\"items\":{\"type\":\"number\"},\"minItems\":4,\"maxItems\":4},"
        "\"shapes\":{\"type\":\"array\",\"items\":{\"type\":\"object\",\"required\":[\"name\",\"kind\",\"x\",\"y\"],"
        "\"properties\":{\"name\":{\"type\":\"string\"},\"kind\":{\"type\":\"string\",\"enum\":[\"line\",\"polygon\",\"circle\",\"arrow\",\"path\",\"label\"]},"
        "\"x\":{\"type\":\"array\",\"items\":{\"type\":\"array\",\"items\":{\"type\":\"number\"}}},"
        "\"y\":{\"type\":\"array\",\"items\":{\"type\":\"array\",\"items\":{\"type\":\"number\"}}},"
        "\"r\":{\"type\":\"number\"},\"value\":{\"type\":\"array\",\"items\":{\"type\":\"number\"}},"
        "\"style\":{\"type\":\"string\"},\"unit\":{\"type\":\"string\"},\"scale\":{\"type\":\"number\"},\"text\":{\"type\":\"string\"}}}}}},");
    mm_buf_puts(b,
        "\"Answer\":{\"type\":\"object\",\"required\":[\"id\",\"params\",\"scalars\",\"series\",\"tables\",\"checks\",\"method\",\"warnings\",\"elapsed_us\"],"
        "\"properties\":{\"id\":{\"type\":\"string\"},\"params\":{\"type\":\"object\",\"description\":\"every parameter, resolved\"},"
        "\"scalars\":{\"type\":\"array\",\"items\":{\"$ref\":\"#/components/schemas/Scalar\"}},"
        "\"series\":{\"type\":\"array\",\"items\":{\"$ref\":\"#/components/schemas/Series\"}},"
        "\"tables\":{\"type\":\"array\",\"items\":{\"$ref\":\"#/components/schemas/Table\"}},"
        "\"checks\":{\"type\":\"array\",\"items\":{\"$ref\":\"#/components/schemas/Check\"}},"
        "\"method\":{\"type\":\"object\",\"required\":[\"name\",\"step\"],\"properties\":{\"name\":{\"type\":\"string\"},\"step\":{\"type\":\"number\"}},"
        "\"additionalProperties\":{\"type\":\"number\"}},"
        "\"warnings\":{\"type\":\"array\",\"items\":{\"type\":\"string\"}},"
        "\"animation\":{\"$ref\":\"#/components/schemas/Animation\"},"
        "\"elapsed_us\":{\"type\":\"integer\",\"description\":\"the time of the solve that made this answer, microseconds\"}}},");
    mm_buf_puts(b,
        "\"Param\":{\"type\":\"object\",\"required\":[\"name\",\"label\",\"unit\",\"kind\",\"default\",\"help\"],"
        "\"properties\":{\"name\":{\"type\":\"string\"},\"label\":{\"type\":\"string\"},\"unit\":{\"type\":\"string\"},"
        "\"kind\":{\"type\":\"string\",\"enum\":[\"real\",\"integer\",\"choice\",\"vector\",\"matrix\",\"expression\"]},"
        "\"default\":{},\"min\":{\"type\":\"number\"},\"max\":{\"type\":\"number\"},"
        "\"choices\":{\"type\":\"array\",\"items\":{\"type\":\"string\"}},\"max_length\":{\"type\":\"integer\"},"
        "\"max_rows\":{\"type\":\"integer\"},\"max_cols\":{\"type\":\"integer\"},"
        "\"variables\":{\"type\":\"array\",\"items\":{\"type\":\"string\"}},\"help\":{\"type\":\"string\"}}},");
    mm_buf_puts(b,
        "\"CatalogRow\":{\"type\":\"object\",\"required\":[\"id\",\"chapter\",\"chapter_title\",\"section\",\"section_title\",\"title\",\"summary\",\"tags\"],"
        "\"properties\":{\"id\":{\"type\":\"string\"},\"chapter\":{\"type\":\"integer\"},\"chapter_title\":{\"type\":\"string\"},"
        "\"section\":{\"type\":\"string\"},\"section_title\":{\"type\":\"string\"},\"title\":{\"type\":\"string\"},"
        "\"summary\":{\"type\":\"string\"},\"tags\":{\"type\":\"array\",\"items\":{\"type\":\"string\"}}}},");
    mm_buf_puts(b,
        "\"Metadata\":{\"allOf\":[{\"$ref\":\"#/components/schemas/CatalogRow\"},{\"type\":\"object\","
        "\"required\":[\"theory\",\"theory_html\",\"params\",\"outputs\",\"references\"],\"properties\":{"
        "\"theory\":{\"type\":\"string\",\"description\":\"Markdown with $...$ and $$...$$ math\"},"
        "\"theory_html\":{\"type\":\"string\"},"
        "\"params\":{\"type\":\"array\",\"items\":{\"$ref\":\"#/components/schemas/Param\"}},"
        "\"outputs\":{\"type\":\"array\",\"items\":{\"type\":\"object\",\"required\":[\"kind\",\"name\",\"label\"],"
        "\"properties\":{\"kind\":{\"type\":\"string\",\"enum\":[\"scalar\",\"series\",\"table\",\"animation\"]},"
        "\"name\":{\"type\":\"string\"},\"label\":{\"type\":\"string\"},\"unit\":{\"type\":\"string\"}}}},"
        "\"references\":{\"type\":\"array\",\"items\":{\"type\":\"string\"}}}}]}");
    mm_buf_puts(b, "},\"responses\":{");
    for (size_t i = 0; i < sizeof errors / sizeof errors[0]; i++) {
        if (i)
            mm_buf_char(b, ',');
        mm_buf_key(b, errors[i].name);
        mm_buf_puts(b, "{\"description\":");
        mm_buf_str(b, errors[i].what);
        mm_buf_puts(b, ",\"content\":{\"application/json\":{\"schema\":{\"$ref\":\"#/components/schemas/Error\"}}}}");
    }
    mm_buf_puts(b, ",\"NotModified\":{\"description\":\"the ETag given in If-None-Match still holds; nothing was solved\"}");
    mm_buf_puts(b, "},\"parameters\":{\"IfNoneMatch\":{\"name\":\"If-None-Match\",\"in\":\"header\",\"required\":false,"
                   "\"description\":\"an ETag of an earlier answer: 304 without solving when it still holds\","
                   "\"schema\":{\"type\":\"string\"}}}}");
}

/* "responses": the 200 (its schema written by the caller between begin
 * and end), 304 where a validator applies, errors */
static void responses_begin(mm_buf *b, const char *ok_what, const char *ok_type)
{
    mm_buf_puts(b, ",\"responses\":{\"200\":{\"description\":");
    mm_buf_str(b, ok_what);
    mm_buf_puts(b, ",\"headers\":{\"ETag\":{\"description\":\"from what determines the answer\",\"schema\":{\"type\":\"string\"}}}");
    mm_buf_puts(b, ",\"content\":{");
    mm_buf_str(b, ok_type);
    mm_buf_puts(b, ":{\"schema\":");
}

static void responses_end(mm_buf *b, const int *errs, int n_errs, int not_modified)
{
    mm_buf_puts(b, "}}}");
    if (not_modified)
        mm_buf_puts(b, ",\"304\":{\"$ref\":\"#/components/responses/NotModified\"}");
    for (int i = 0; i < n_errs; i++)
        for (size_t k = 0; k < sizeof errors / sizeof errors[0]; k++)
            if (errors[k].status == errs[i]) {
                mm_buf_puts(b, ",\"");
                mm_buf_int(b, errs[i]);
                mm_buf_puts(b, "\":{\"$ref\":\"#/components/responses/");
                mm_buf_puts(b, errors[k].name);
                mm_buf_puts(b, "\"}");
            }
    mm_buf_char(b, '}');
}

static void write_responses(mm_buf *b, const char *ok_what, const char *ok_type, const char *ok_schema,
                            const int *errs, int n_errs, int not_modified)
{
    responses_begin(b, ok_what, ok_type);
    mm_buf_puts(b, ok_schema);
    responses_end(b, errs, n_errs, not_modified);
}

/* a plain GET route of the server: path, summary, answer */
static void write_get(mm_buf *b, const char *path, const char *op, const char *summary,
                      const char *type, const char *schema, int not_found)
{
    static const int errs[] = {404, 405, 503};
    mm_buf_char(b, ',');
    mm_buf_key(b, path);
    mm_buf_puts(b, "{\"get\":{\"operationId\":");
    mm_buf_str(b, op);
    fstr(b, "summary", summary);
    mm_buf_puts(b, ",\"parameters\":[{\"$ref\":\"#/components/parameters/IfNoneMatch\"}]");
    write_responses(b, summary, type, schema, not_found ? errs : errs + 1, not_found ? 3 : 2, 1);
    mm_buf_puts(b, "}}");
}

/* ---- one exercise -------------------------------------------------------------- */

static void write_description(mm_buf *b, const mm_param *p)
{
    char text[1024];
    int n = snprintf(text, sizeof text, "%s%s%s%s. %s", p->label, p->unit && p->unit[0] ? " [" : "",
                     p->unit ? p->unit : "", p->unit && p->unit[0] ? "]" : "", p->help);
    if (n > 0 && p->kind == MM_REAL)
        snprintf(text + n, sizeof text - (size_t)n, " A constant expression such as pi/2 is accepted.");
    if (n > 0 && p->kind == MM_VECTOR)
        snprintf(text + n, sizeof text - (size_t)n, " In a query: numbers separated by commas, 1,2,3.");
    if (n > 0 && p->kind == MM_MATRIX)
        snprintf(text + n, sizeof text - (size_t)n, " In a query: rows separated by semicolons, 1,2;3,4.");
    if (n > 0 && p->kind == MM_EXPR)
        snprintf(text + n, sizeof text - (size_t)n, " Variables: %s.", p->vars ? p->vars : "");
    fstr(b, "description", text);
}

/* The schema of one parameter's value; json: as in a POST body (arrays as
 * JSON arrays too), else as in a query string. */
static void write_param_schema(mm_buf *b, const mm_param *p, int json)
{
    char num[64];
    switch (p->kind) {
    case MM_REAL:
    case MM_INT:
        mm_buf_puts(b, p->kind == MM_INT ? "{\"type\":\"integer\"" : "{\"type\":\"number\"");
        fnum(b, "minimum", p->min);
        fnum(b, "maximum", p->max);
        fnum(b, "default", p->def);
        if (p->unit && p->unit[0])
            fstr(b, "x-unit", p->unit);
        mm_buf_char(b, '}');
        break;
    case MM_CHOICE:
        mm_buf_puts(b, "{\"type\":\"string\",\"enum\":[");
        for (int i = 0; p->choices[i]; i++) {
            if (i)
                mm_buf_char(b, ',');
            mm_buf_str(b, p->choices[i]);
        }
        mm_buf_char(b, ']');
        fstr(b, "default", p->choices[(int)p->def]);
        mm_buf_char(b, '}');
        break;
    case MM_EXPR:
        mm_buf_puts(b, "{\"type\":\"string\",\"minLength\":1");
        fint(b, "maxLength", MM_PARAM_EXPR_MAX);
        fstr(b, "default", p->def_text);
        mm_buf_char(b, '}');
        break;
    case MM_VECTOR:
    case MM_MATRIX:
        mm_buf_puts(b, "{");
        if (json) {
            mm_buf_puts(b, "\"anyOf\":[{\"type\":\"array\",\"minItems\":1");
            fint(b, "maxItems", p->kind == MM_MATRIX ? p->max_rows : p->max_cols);
            mm_buf_puts(b, ",\"items\":");
            if (p->kind == MM_MATRIX) {
                mm_buf_puts(b, "{\"type\":\"array\",\"minItems\":1");
                fint(b, "maxItems", p->max_cols);
                mm_buf_puts(b, ",\"items\":");
            }
            mm_buf_puts(b, "{\"type\":\"number\"");
            fnum(b, "minimum", p->min);
            fnum(b, "maximum", p->max);
            mm_buf_puts(b, p->kind == MM_MATRIX ? "}}}," : "}},");
            mm_buf_puts(b, "{\"type\":\"string\"}],");
        } else {
            mm_buf_puts(b, "\"type\":\"string\",");
        }
        mm_buf_puts(b, "\"default\":");
        mm_buf_str(b, p->def_text);
        snprintf(num, sizeof num, "%.17g", p->min);
        fstr(b, "x-element-minimum", num);
        snprintf(num, sizeof num, "%.17g", p->max);
        fstr(b, "x-element-maximum", num);
        if (p->kind == MM_MATRIX) {
            fint(b, "x-max-rows", p->max_rows);
            fint(b, "x-max-cols", p->max_cols);
        } else {
            fint(b, "x-max-length", p->max_cols);
        }
        if (p->unit && p->unit[0])
            fstr(b, "x-unit", p->unit);
        mm_buf_char(b, '}');
        break;
    }
}

/* x-outputs: every declared output, families expanded (as the metadata) */
static void write_outputs(mm_buf *b, const mm_exercise *ex, mm_output_kind only, int names_only)
{
    static const char *const kinds[] = {"", "scalar", "series", "table", "animation"};
    int first = 1;
    for (int i = 0; i < ex->n_outputs; i++) {
        const mm_output *o = &ex->outputs[i];
        if (only && o->kind != only)
            continue;
        for (int k = 0; k < mm_output_count(o); k++) {
            char name[160];
            mm_output_member(o, mm_output_index(o, k), name, sizeof name);
            if (!first)
                mm_buf_char(b, ',');
            first = 0;
            if (names_only) {
                mm_buf_str(b, name);
                continue;
            }
            mm_buf_puts(b, "{\"kind\":");
            mm_buf_str(b, kinds[o->kind]);
            fstr(b, "name", name);
            fstr(b, "label", o->label);
            if (o->kind == MM_OUT_SCALAR || o->kind == MM_OUT_SERIES)
                fstr(b, "unit", o->unit ? o->unit : "");
            if (o->kind == MM_OUT_SERIES)
                fstr(b, "x_unit", o->x_unit ? o->x_unit : "");
            if (o->flags & MM_ANSWER)
                mm_buf_puts(b, ",\"answer\":true");
            mm_buf_char(b, '}');
        }
    }
}

static int has_outputs(const mm_exercise *ex, mm_output_kind kind)
{
    for (int i = 0; i < ex->n_outputs; i++)
        if (ex->outputs[i].kind == kind)
            return 1;
    return 0;
}

/* the 200 schema of a solve: the Answer, with the names it may carry */
static void write_answer_schema(mm_buf *b, const mm_exercise *ex)
{
    if (ex->n_outputs == 0) {
        mm_buf_puts(b, "{\"$ref\":\"#/components/schemas/Answer\"}");
        return;
    }
    static const struct { const char *key; mm_output_kind kind; } lists[] = {
        {"scalars", MM_OUT_SCALAR}, {"series", MM_OUT_SERIES}, {"tables", MM_OUT_TABLE}};
    mm_buf_puts(b, "{\"allOf\":[{\"$ref\":\"#/components/schemas/Answer\"},{\"type\":\"object\",\"properties\":{");
    for (size_t l = 0; l < sizeof lists / sizeof lists[0]; l++) {
        if (l)
            mm_buf_char(b, ',');
        mm_buf_key(b, lists[l].key);
        if (!has_outputs(ex, lists[l].kind)) {
            mm_buf_puts(b, "{\"type\":\"array\",\"maxItems\":0}");
            continue;
        }
        mm_buf_puts(b, "{\"type\":\"array\",\"items\":{\"properties\":{\"name\":{\"enum\":[");
        write_outputs(b, ex, lists[l].kind, 1);
        mm_buf_puts(b, "]}}}}");
    }
    mm_buf_puts(b, "}}]}");
}

static void write_solve(mm_buf *b, const mm_exercise *ex)
{
    static const int errs[] = {400, 404, 405, 413, 422, 500, 503};
    char path[200], op[200];
    snprintf(path, sizeof path, "/api/exercises/%s/solve", ex->id);
    mm_buf_char(b, ',');
    mm_buf_key(b, path);
    mm_buf_puts(b, "{\"summary\":");
    mm_buf_str(b, ex->title);
    fstr(b, "description", ex->summary);
    mm_buf_puts(b, ",\"x-outputs\":[");
    write_outputs(b, ex, 0, 0);
    mm_buf_char(b, ']');

    snprintf(op, sizeof op, "solve-%s", ex->id);
    mm_buf_puts(b, ",\"get\":{\"operationId\":");
    mm_buf_str(b, op);
    fstr(b, "summary", "solve with the parameters of the query, the defaults for the rest");
    mm_buf_puts(b, ",\"tags\":[");
    mm_buf_str(b, ex->id);
    mm_buf_puts(b, "],\"parameters\":[{\"$ref\":\"#/components/parameters/IfNoneMatch\"}");
    for (int i = 0; i < ex->n_params; i++) {
        const mm_param *p = &ex->params[i];
        mm_buf_puts(b, ",{\"name\":");
        mm_buf_str(b, p->name);
        mm_buf_puts(b, ",\"in\":\"query\",\"required\":false");
        write_description(b, p);
        mm_buf_puts(b, ",\"schema\":");
        write_param_schema(b, p, 0);
        mm_buf_char(b, '}');
    }
    mm_buf_char(b, ']');
    responses_begin(b, "the answer", "application/json");
    write_answer_schema(b, ex);
    responses_end(b, errs, sizeof errs / sizeof errs[0], 1);
    mm_buf_char(b, '}');

    snprintf(op, sizeof op, "solve-%s-post", ex->id);
    mm_buf_puts(b, ",\"post\":{\"operationId\":");
    mm_buf_str(b, op);
    fstr(b, "summary", "solve with the parameters of a JSON body, the defaults for the rest");
    mm_buf_puts(b, ",\"tags\":[");
    mm_buf_str(b, ex->id);
    mm_buf_puts(b, "],\"requestBody\":{\"required\":true,\"content\":{\"application/json\":{\"schema\":{"
                   "\"type\":\"object\",\"required\":[\"params\"],\"additionalProperties\":false,"
                   "\"properties\":{\"params\":{\"type\":\"object\",\"additionalProperties\":false,\"properties\":{");
    for (int i = 0; i < ex->n_params; i++) {
        const mm_param *p = &ex->params[i];
        if (i)
            mm_buf_char(b, ',');
        mm_buf_key(b, p->name);
        mm_buf_puts(b, "{\"allOf\":[");
        write_param_schema(b, p, 1);
        mm_buf_puts(b, "]");
        write_description(b, p);
        mm_buf_char(b, '}');
    }
    mm_buf_puts(b, "}}}}}}}");
    responses_begin(b, "the answer", "application/json");
    write_answer_schema(b, ex);
    responses_end(b, errs, sizeof errs / sizeof errs[0], 0);
    mm_buf_puts(b, "}}");
}

/* ---- the Octave script and the assignments ----------------------------------------- */

#define NAME_PARAM "{\"name\":\"name\",\"in\":\"path\",\"required\":true,\"schema\":{\"type\":\"string\"}}"
#define QUERY_PARAM(n, req, what) \
    "{\"name\":\"" n "\",\"in\":\"query\",\"required\":" req ",\"description\":\"" what "\",\"schema\":{\"type\":\"string\"}}"

static void write_scripts_and_assignments(mm_buf *b, const mm_course *c)
{
    mm_buf_puts(b, ",\"/api/exercises/{id}/script.m\":{\"get\":{\"operationId\":\"script\","
                   "\"summary\":\"an Octave/MATLAB script that reproduces the answer's scalars for the same "
                   "parameters (the same query as solve), printing each as a line name = value\","
                   "\"parameters\":[{\"$ref\":\"#/components/parameters/IfNoneMatch\"},"
                   "{\"name\":\"id\",\"in\":\"path\",\"required\":true,\"schema\":{\"type\":\"string\",\"enum\":[");
    for (int i = 0; i < mm_course_exercise_count(c); i++) {
        if (i)
            mm_buf_char(b, ',');
        mm_buf_str(b, mm_course_exercise(c, i)->id);
    }
    mm_buf_puts(b, "]}}]");
    static const int script_errs[] = {400, 404, 405, 413, 503};
    write_responses(b, "the script", "text/plain; charset=utf-8", "{\"type\":\"string\"}", script_errs, 5, 1);
    mm_buf_puts(b, "}}");

    write_get(b, "/api/assignments", "assignments", "the course's assignments", "application/json",
              "{\"type\":\"array\",\"items\":{\"type\":\"object\",\"required\":[\"name\",\"title\",\"exercise\"],"
              "\"properties\":{\"name\":{\"type\":\"string\"},\"title\":{\"type\":\"string\"},"
              "\"exercise\":{\"type\":\"string\"}}}}",
              0);

    static const int errs[] = {400, 404, 405, 413, 503};
    static const int key_errs[] = {400, 403, 404, 405, 413, 503};
    mm_buf_puts(b, ",\"/api/assignments/{name}/variant\":{\"get\":{\"operationId\":\"variant\","
                   "\"summary\":\"one student's variant: the same parameters for the same student, always\","
                   "\"parameters\":[" NAME_PARAM "," QUERY_PARAM("student", "true", "the student's id (at most 128 bytes)") "]");
    write_responses(b, "the variant", "application/json",
                    "{\"type\":\"object\",\"required\":[\"assignment\",\"student\",\"exercise\",\"params\",\"asked\"],"
                    "\"properties\":{\"assignment\":{\"type\":\"string\"},\"student\":{\"type\":\"string\"},"
                    "\"exercise\":{\"type\":\"string\"},\"title\":{\"type\":\"string\"},\"params\":{\"type\":\"object\"},"
                    "\"asked\":{\"type\":\"array\",\"items\":{\"type\":\"object\",\"required\":[\"name\",\"label\",\"unit\"]}}}}",
                    errs, 4, 0);
    mm_buf_puts(b, "}}");

    mm_buf_puts(b, ",\"/api/assignments/{name}/check\":{\"post\":{\"operationId\":\"check\","
                   "\"summary\":\"judge a student's answers (numbers with units) against the variant's\","
                   "\"parameters\":[" NAME_PARAM "],"
                   "\"requestBody\":{\"required\":true,\"content\":{\"application/json\":{\"schema\":{"
                   "\"type\":\"object\",\"required\":[\"student\",\"answers\"],\"properties\":{"
                   "\"student\":{\"type\":\"string\"},\"answers\":{\"type\":\"object\","
                   "\"additionalProperties\":{\"type\":\"string\"}}}}}}}");
    write_responses(b, "the judgement", "application/json",
                    "{\"type\":\"object\",\"required\":[\"results\",\"score\"],\"properties\":{"
                    "\"results\":{\"type\":\"array\",\"items\":{\"type\":\"object\",\"required\":[\"name\",\"correct\"]}},"
                    "\"score\":{\"type\":\"number\"},\"max_score\":{\"type\":\"number\"}}}",
                    errs, 5, 0);
    mm_buf_puts(b, "}}");

    mm_buf_puts(b, ",\"/api/assignments/{name}/key\":{\"get\":{\"operationId\":\"key\","
                   "\"summary\":\"for the instructor: a student's variant with the expected answers\","
                   "\"parameters\":[" NAME_PARAM "," QUERY_PARAM("student", "true", "the student's id") ","
                   QUERY_PARAM("key", "true", "the assignment's instructor_key") "]");
    write_responses(b, "the key", "application/json", "{\"type\":\"object\"}", key_errs, 6, 0);
    mm_buf_puts(b, "}}");

    mm_buf_puts(b, ",\"/api/assignments/{name}/csv\":{\"post\":{\"operationId\":\"csv\","
                   "\"summary\":\"for the instructor: one row per student of a class list (variant and answers)\","
                   "\"parameters\":[" NAME_PARAM "," QUERY_PARAM("key", "true", "the assignment's instructor_key") "],"
                   "\"requestBody\":{\"required\":true,\"content\":{\"text/csv\":{\"schema\":{\"type\":\"string\"}}}}");
    write_responses(b, "the class sheet", "text/csv; charset=utf-8", "{\"type\":\"string\"}", key_errs, 6, 0);
    mm_buf_puts(b, "}}");
}

void mm_openapi_write(mm_buf *b, const mm_course *c)
{
    mm_buf_puts(b, "{\"openapi\":\"3.1.0\",\"info\":{\"title\":");
    mm_buf_str(b, mm_course_title(c));
    fstr(b, "version", MM_VERSION);
    fstr(b, "summary", "engineering mechanics by worked numerical examples");
    fstr(b, "description",
         "Every exercise is a pure function of its resolved parameters: the same request gives the same "
         "answer, with an ETag made from the server's build and the canonical parameters, so that "
         "If-None-Match gets 304 without solving. Answers and files are compressed (gzip) when the "
         "client accepts it. Limits, units and outputs below are those of this course.");
    mm_buf_puts(b, ",\"license\":{\"name\":\"see the project\",\"identifier\":\"UNLICENSED\"}}");
    mm_buf_puts(b, ",\"servers\":[{\"url\":");
    char base[300];
    snprintf(base, sizeof base, "%s", mm_course_base_path(c));
    size_t n = strlen(base);
    if (n > 1 && base[n - 1] == '/')
        base[n - 1] = '\0';
    mm_buf_str(b, base);
    mm_buf_puts(b, "}],\"paths\":{");

    mm_buf_puts(b, "\"/api/health\":{\"get\":{\"operationId\":\"health\",\"summary\":\"is the server up\"");
    mm_buf_puts(b, ",\"parameters\":[{\"$ref\":\"#/components/parameters/IfNoneMatch\"}]");
    {
        static const int errs[] = {405, 503};
        write_responses(b, "up", "application/json",
                        "{\"type\":\"object\",\"required\":[\"status\",\"version\",\"exercises\"],\"properties\":{"
                        "\"status\":{\"const\":\"ok\"},\"version\":{\"type\":\"string\"},\"exercises\":{\"type\":\"integer\"}}}",
                        errs, 2, 1);
    }
    mm_buf_puts(b, "}}");
    write_get(b, "/api/exercises", "catalog", "the catalog, in the course's order", "application/json",
              "{\"type\":\"array\",\"items\":{\"$ref\":\"#/components/schemas/CatalogRow\"}}", 0);
    write_get(b, "/api/course", "course", "the course: title, language, base path, its exercises",
              "application/json",
              "{\"type\":\"object\",\"required\":[\"title\",\"language\",\"base_path\",\"exercises\"],\"properties\":{"
              "\"title\":{\"type\":\"string\"},\"language\":{\"type\":\"string\"},\"base_path\":{\"type\":\"string\"},"
              "\"digest\":{\"type\":\"string\"},\"build\":{\"type\":\"string\"},"
              "\"exercises\":{\"type\":\"array\",\"items\":{\"type\":\"string\"}},\"assignments\":{\"type\":\"integer\"}}}",
              0);
    write_get(b, "/api/openapi.json", "openapi", "this document", "application/json", "{\"type\":\"object\"}", 0);
    write_get(b, "/api/metrics", "metrics", "counters in the Prometheus text format",
              "text/plain; version=0.0.4", "{\"type\":\"string\"}", 0);

    /* /api/exercises/{id}: one path, the ids as an enum */
    mm_buf_puts(b, ",\"/api/exercises/{id}\":{\"get\":{\"operationId\":\"metadata\","
                   "\"summary\":\"one exercise: theory, parameters, declared outputs\","
                   "\"parameters\":[{\"$ref\":\"#/components/parameters/IfNoneMatch\"},"
                   "{\"name\":\"id\",\"in\":\"path\",\"required\":true,\"schema\":{\"type\":\"string\",\"enum\":[");
    for (int i = 0; i < mm_course_exercise_count(c); i++) {
        if (i)
            mm_buf_char(b, ',');
        mm_buf_str(b, mm_course_exercise(c, i)->id);
    }
    mm_buf_puts(b, "]}}]");
    {
        static const int errs[] = {404, 405, 503};
        write_responses(b, "the metadata", "application/json", "{\"$ref\":\"#/components/schemas/Metadata\"}",
                        errs, 3, 1);
    }
    mm_buf_puts(b, "}}");
    for (int i = 0; i < mm_course_exercise_count(c); i++)
        write_solve(b, mm_course_exercise(c, i));
    write_scripts_and_assignments(b, c);
    mm_buf_char(b, '}');
    write_components(b);
    mm_buf_char(b, '}');
}
