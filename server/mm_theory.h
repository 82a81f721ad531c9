/* mm_theory.h — a theory text (Markdown with $…$ and $$…$$ math) to HTML.
 *
 * Markdown goes through cmark (the CommonMark reference library), in its
 * safe mode (raw HTML is dropped).  Math is taken out first so that
 * Markdown never touches it (an underscore in $x_1$ is not emphasis), and
 * put back as
 *     <span class="math math-inline">…TeX, HTML-escaped…</span>
 *     <div class="math math-display">…</div>
 * for KaTeX to typeset in the browser.  \$ is a literal dollar sign.
 */
#ifndef MM_THEORY_H
#define MM_THEORY_H

#include <stddef.h>

/* The HTML of md (len bytes), malloc'd, NUL-terminated; NULL when out of
 * memory.  The caller frees it. */
char *mm_theory_html(const char *md, size_t len);

#endif
