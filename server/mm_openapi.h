/* mm_openapi.h — the OpenAPI 3.1 document of a course, written from the
 * registry: every route, every exercise's parameters with their limits and
 * units, its declared outputs (families expanded), every error.
 *
 * A route added to the HTTP layer (mm_http.c's route table) must be added
 * here too: test_http_cache.c checks that every route of the table has its
 * path in this document. */
#ifndef MM_OPENAPI_H
#define MM_OPENAPI_H

#include "mm_course.h"
#include "mm_json.h"

void mm_openapi_write(mm_buf *b, const mm_course *course);

#endif
