/* mm_status.c — tables generated from MM_STATUS_LIST (see mm_status.h). */
#include "mm_status.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

static const struct {
    int http;
    const char *api;
    const char *text;
} rows[] = {
#define MM_X_ROW(code, http, api, text) {http, api, text},
    MM_STATUS_LIST(MM_X_ROW)
#undef MM_X_ROW
};

static int valid(int code) { return code >= 0 && code < MM_STATUS_COUNT; }

const char *mm_strerror(int code)
{
    return rows[valid(code) ? code : MM_EINTERNAL].text;
}

int mm_http_status(int code)
{
    return rows[valid(code) ? code : MM_EINTERNAL].http;
}

const char *mm_api_code(int code)
{
    return rows[valid(code) ? code : MM_EINTERNAL].api;
}

void mm_error_clear(mm_error *err)
{
    if (!err)
        return;
    err->code = MM_OK;
    err->param[0] = '\0';
    err->msg[0] = '\0';
}

int mm_error_set(mm_error *err, int code, const char *param, const char *fmt, ...)
{
    if (!err)
        return code;
    err->code = code;
    snprintf(err->param, sizeof err->param, "%s", param ? param : "");
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err->msg, sizeof err->msg, fmt, ap);
    va_end(ap);
    return code;
}
