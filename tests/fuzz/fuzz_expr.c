/* fuzz_expr.c — the expression compiler (muParser) on arbitrary text, with
 * the variables x and t; a compiled expression is evaluated at a few points.
 * Invariants: no crash, no hang (muParser has no loops), errors are MM_EVALUE
 * or MM_ERANGE. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "mm_expr.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size > 4096)
        return 0;
    char *text = malloc(size + 1);
    memcpy(text, data, size);
    text[size] = '\0';
    const char *const vars[] = {"x", "t"};
    mm_expr *e = NULL;
    mm_error err;
    int rc = mm_expr_compile(text, vars, 2, &e, &err);
    if (rc == MM_OK) {
        double xs[2][2] = {{0.5, 1.0}, {-3.0, 1e6}};
        for (int i = 0; i < 2; i++)
            (void)mm_expr_eval(e, xs[i]);
        mm_expr_free(e);
    } else if (rc != MM_EVALUE && rc != MM_ERANGE) {
        abort();
    }
    double v;
    rc = mm_expr_eval_const(text, &v, &err);
    if (rc != MM_OK && rc != MM_EVALUE && rc != MM_ERANGE)
        abort();
    free(text);
    return 0;
}
