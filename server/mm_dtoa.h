/* mm_dtoa.h — shortest round-trip text of a double, for JSON.
 *
 * Uses {fmt} (Debian libfmt), whose Dragonbox algorithm writes the
 * shortest decimal that reads back to the same double, e.g. 0.1 -> "0.1",
 * 1e21 -> "1e+21", 1e-7 -> "1e-07", 1/3 -> "0.3333333333333333", at about
 * 40 ns a number here with {fmt}'s own layout (double-conversion: 84 ns,
 * printf %.17g: 170 ns, which is not even shortest); mm_dtoa takes only
 * the digits from {fmt} and lays them out itself, about 25 ns, and writes
 * a short decimal (0.0234) by its fast path in about 5.  Valid JSON for
 * every finite value.
 */
#ifndef MM_DTOA_H
#define MM_DTOA_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define MM_DTOA_BUFSIZE 32
/* mm_dtoa_list writes whole words past a number's text (copies of a fixed
 * size are faster than exact ones): the room it needs beyond the texts */
#define MM_DTOA_SLACK 16

/* Write v into buf (at least MM_DTOA_BUFSIZE bytes), NUL-terminated, and
 * return the length.  v must be finite (returns 0 and writes "" if not). */
int mm_dtoa(double v, char *buf);

/* v[0..n) as mm_dtoa writes each, commas between (and one before v[0]
 * unless first), from w on; a non-finite number is written 0 and sets
 * *nonfinite.  w needs n (MM_DTOA_BUFSIZE + 1) + MM_DTOA_SLACK bytes of
 * room.  Returns
 * the end, where a NUL is written. */
char *mm_dtoa_list(const double *v, size_t n, int first, char *w, int *nonfinite);

/* The same by {fmt}'s own formatting ("{}"), the reference: mm_dtoa takes
 * only Dragonbox's digits from {fmt} and lays them out itself, with a fast
 * path for short decimals (m 10^-k, k <= 6: 0.02, 0.0195, 100); the tests
 * compare the two character for character. */
int mm_dtoa_fmt(double v, char *buf);

#ifdef __cplusplus
}
#endif

#endif
