/* fuzz_params.c — the parameter parser on arbitrary text.  The first byte
 * picks the kind of parameter; the rest is the text.  Invariants: no crash,
 * and an accepted value is finite, inside its limits and of a legal shape. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "mm_params.h"
#include "mm_result_impl.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static const char *const names[] = {"fixed-free", "fixed-fixed", "free-free", NULL};
static const mm_param kinds[] = {
    {"m", "mass", "kg", MM_REAL, 1, 1e-3, 1e3, .help = "h"},
    {"n", "count", "", MM_INT, 10, -5, 100, .help = "h"},
    {"bc", "ends", "", MM_CHOICE, 0, 0, 0, .choices = names, .help = "h"},
    {"b", "vector", "", MM_VECTOR, 0, -1e6, 1e6, "1,2,3", .max_cols = 50, .help = "h"},
    {"A", "matrix", "", MM_MATRIX, 0, -1e6, 1e6, "1,2;3,4", .max_rows = 20, .max_cols = 20, .help = "h"},
    {"f", "function", "", MM_EXPR, 0, 0, 0, "x", .vars = "x", .help = "h"},
};

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1)
        return 0;
    const mm_param *p = &kinds[data[0] % (sizeof kinds / sizeof kinds[0])];
    mm_result r;
    mm_result_init(&r, 1 << 22);
    mm_value v;
    mm_error err;
    int rc = mm_param_parse(p, (const char *)data + 1, size - 1, &v, &r, &err);
    if (rc == MM_OK) {
        if ((p->kind == MM_REAL || p->kind == MM_INT) && !(v.x >= p->min && v.x <= p->max))
            abort();
        if (p->kind == MM_INT && v.x != floor(v.x))
            abort();
        if (p->kind == MM_VECTOR || p->kind == MM_MATRIX) {
            if (v.rows < 1 || v.cols < 1 || v.rows > (p->kind == MM_MATRIX ? p->max_rows : 1) ||
                v.cols > p->max_cols)
                abort();
            for (int i = 0; i < v.rows * v.cols; i++)
                if (!(v.data[i] >= p->min && v.data[i] <= p->max))
                    abort();
        }
    } else if (rc != MM_EVALUE && rc != MM_ERANGE) {
        abort();
    } else if (err.param[0] == '\0') {
        abort();                                  /* every refusal names the parameter */
    }
    mm_result_release(&r);
    return 0;
}
