/* fuzz_json.c — a POST body through the whole solve pipeline (cJSON, the
 * text forms, validation, solve, the JSON writer) for an exercise picked by
 * the first byte.  Invariants: no crash; the answer is valid JSON; the
 * status is one of API.md's; a 200 carries no error and a 4xx/422 one. */
#include <cJSON.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "mm_api.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1 || size > 65536)
        return 0;
    const mm_exercise *ex = mm_exercises[data[0] % mm_exercise_count];
    mm_buf out;
    mm_buf_init(&out, MM_ANSWER_MAX);
    int status = mm_api_solve_json(ex, (const char *)data + 1, size - 1, &out);
    cJSON *doc = cJSON_ParseWithLength(out.p, out.len);
    if (!doc)
        abort();
    int has_error = cJSON_GetObjectItem(doc, "error") != NULL;
    if (status == 200 ? has_error : !has_error)
        abort();
    if (status != 200 && status != 400 && status != 413 && status != 422)
        abort();
    cJSON_Delete(doc);
    mm_buf_free(&out);
    return 0;
}
