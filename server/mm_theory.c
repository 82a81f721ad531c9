/* mm_theory.c — Markdown with math to HTML (see mm_theory.h). */
#include "mm_theory.h"

#include <cmark.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mm_json.h"

/* Placeholders are plain letters and digits so that Markdown leaves them be. */
#define TOKEN_FMT "MMMATHTOKEN%dX"

typedef struct span {
    size_t start, len;    /* the TeX between the dollars */
    int display;
} span;

static void put_escaped(mm_buf *b, const char *s, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        switch (s[i]) {
        case '&': mm_buf_puts(b, "&amp;"); break;
        case '<': mm_buf_puts(b, "&lt;"); break;
        case '>': mm_buf_puts(b, "&gt;"); break;
        case '"': mm_buf_puts(b, "&quot;"); break;
        default: mm_buf_char(b, s[i]);
        }
    }
}

char *mm_theory_html(const char *md, size_t len)
{
    mm_buf pre, out;
    mm_buf_init(&pre, 16u << 20);
    mm_buf_init(&out, 32u << 20);
    span *spans = NULL;
    int nspans = 0, cap = 0;
    char *html = NULL;

    /* 1. take the math out */
    for (size_t i = 0; i < len;) {
        if (md[i] == '\\' && i + 1 < len && md[i + 1] == '$') {
            mm_buf_puts(&pre, "\\$");          /* CommonMark keeps \$ as $ */
            i += 2;
            continue;
        }
        if (md[i] == '`') {                    /* code spans pass through whole */
            size_t j = i + 1;
            while (j < len && md[j] != '`')
                j++;
            size_t end = j < len ? j + 1 : len;
            mm_buf_put(&pre, md + i, end - i);
            i = end;
            continue;
        }
        if (md[i] == '$') {
            int display = i + 1 < len && md[i + 1] == '$';
            size_t open = display ? 2 : 1, j = i + open;
            while (j < len && !(md[j] == '$' && md[j - 1] != '\\' &&
                                (!display || (j + 1 < len && md[j + 1] == '$'))))
                j++;
            if (j < len && j > i + open) {
                if (nspans == cap) {
                    cap = cap ? 2 * cap : 64;
                    span *s = realloc(spans, (size_t)cap * sizeof *s);
                    if (!s)
                        goto out;
                    spans = s;
                }
                spans[nspans] = (span){i + open, j - (i + open), display};
                char tok[32];
                snprintf(tok, sizeof tok, TOKEN_FMT, nspans);
                mm_buf_puts(&pre, tok);
                nspans++;
                i = j + open;
                continue;
            }
        }
        mm_buf_char(&pre, md[i]);
        i++;
    }
    if (pre.failed)
        goto out;

    /* 2. Markdown */
    char *body = cmark_markdown_to_html(pre.p ? pre.p : "", pre.len, CMARK_OPT_DEFAULT | CMARK_OPT_SMART);
    if (!body)
        goto out;

    /* 3. put the math back; a display formula alone in a paragraph replaces it */
    for (const char *s = body; *s;) {
        const char *t = strstr(s, "MMMATHTOKEN");
        if (!t) {
            mm_buf_puts(&out, s);
            break;
        }
        int k = atoi(t + 11);
        const char *after = t + 11;
        while (*after >= '0' && *after <= '9')
            after++;
        if (*after != 'X' || k < 0 || k >= nspans) {   /* not ours: keep it */
            mm_buf_put(&out, s, (size_t)(after - s));
            s = after;
            continue;
        }
        after++;
        const span *sp = &spans[k];
        int alone = sp->display && t - s >= 3 && strncmp(t - 3, "<p>", 3) == 0 &&
                    strncmp(after, "</p>", 4) == 0;
        mm_buf_put(&out, s, (size_t)(t - s) - (alone ? 3 : 0));
        mm_buf_puts(&out, sp->display ? "<div class=\"math math-display\">"
                                      : "<span class=\"math math-inline\">");
        put_escaped(&out, md + sp->start, sp->len);
        mm_buf_puts(&out, sp->display ? "</div>" : "</span>");
        s = after + (alone ? 4 : 0);
    }
    free(body);
    if (!out.failed)
        html = mm_buf_take(&out, NULL);
out:
    free(spans);
    mm_buf_free(&pre);
    mm_buf_free(&out);
    return html;
}
