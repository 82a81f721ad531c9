// mm_dtoa.cc — the one C++ file: a C entry point to {fmt}'s shortest
// round-trip formatting of doubles (Dragonbox), see mm_dtoa.h, with a
// fast path for short decimals.
#include "mm_dtoa.h"

#include <cmath>
#include <cstdint>
#include <fmt/compile.h>
#include <fmt/format.h>

extern "C" int mm_dtoa_fmt(double v, char *buf)
{
    if (!std::isfinite(v)) {
        buf[0] = '\0';
        return 0;
    }
    // "{}" is the shortest text that reads back to v: 0.1, 100, 1e-07, 1e+21.
    // -0 is written as 0 (JSON has no use for the sign of zero).
    char *end = fmt::format_to(buf, FMT_COMPILE("{}"), v == 0.0 ? 0.0 : v);
    *end = '\0';
    return static_cast<int>(end - buf);
}

// Most numbers of an answer are short decimals: plot abscissae (0.02 k),
// animation coordinates rounded to a few places (0.0195).  Such a v is
// m 10^-k with m an integer not ending in 0, k <= 6.  It is found in one
// product: M = |v| 10^6 (below 4.5e15, so an int64 holds it exactly) must
// be a whole number, and M / 10^6, the correctly rounded value of the
// decimal (M and 10^6 are exact), must equal |v|, so that the decimal reads
// back to v; M's trailing zeros then leave the fraction (m = M / 10^(6-k)).  It is then the shortest
// text: another decimal as short or shorter lies on the grid 10^-6 too, at
// least 10^-6 from this one, which is more than an ulp of v when |v| <
// 2^52 10^-6 (4.5e9), so it cannot read back to v.  {fmt} writes such
// numbers in fixed notation when 1e-4 <= |v| < 1e16, as here, so the text
// is the one Dragonbox would give (the tests compare the two on millions of
// numbers).  When |v| 10^6 rounds off a whole number although v is a short
// decimal (possible when 10^6 crosses fewer binades than it spans) the
// number simply goes to Dragonbox.  Writes nothing and returns 0 when the
// fast path does not apply.  (It used to try k = 0..6 in turn, a product
// and two conversions each, and a loop of divisions for the digits.)
static const char digit_pairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

static int short_decimal(double v, char *buf)
{
    double a = std::fabs(v);
    if (!(a >= 1e-4 && a < 4.5e9))
        return 0;
    double m = a * 1e6;
    int64_t M = static_cast<int64_t>(m);
    // M / 10^6 is the same number as m / 10^k, so the same correctly rounded
    // quotient: checked before the zeros are known
    if (m != static_cast<double>(M) || static_cast<double>(M) / 1e6 != a)
        return 0;
    char digits[24], *end = digits + sizeof digits, *d = end;   // written from the end
    uint64_t q = static_cast<uint64_t>(M);
    while (q >= 100) {
        unsigned r = static_cast<unsigned>(q % 100);
        q /= 100;
        d -= 2;
        d[0] = digit_pairs[2 * r];
        d[1] = digit_pairs[2 * r + 1];
    }
    if (q >= 10) {
        d -= 2;
        d[0] = digit_pairs[2 * q];
        d[1] = digit_pairs[2 * q + 1];
    } else {
        *--d = static_cast<char>('0' + q);
    }
    int k = 6;                              // M's trailing zeros leave the fraction
    while (k > 0 && end[-1] == '0') {
        end--;
        k--;
    }
    int nd = static_cast<int>(end - d);
    char *w = buf;
    if (v < 0)
        *w++ = '-';
    if (nd <= k) {                          // 0.0xyz
        *w++ = '0';
        *w++ = '.';
        for (int i = nd; i < k; i++)
            *w++ = '0';
        for (int i = 0; i < nd; i++)
            *w++ = d[i];
    } else {
        for (int i = 0; i < nd - k; i++)
            *w++ = d[i];
        if (k > 0) {
            *w++ = '.';
            for (int i = nd - k; i < nd; i++)
                *w++ = d[i];
        }
    }
    *w = '\0';
    return static_cast<int>(w - buf);
}

extern "C" int mm_dtoa(double v, char *buf)
{
    if (v == 0.0) {
        buf[0] = '0';
        buf[1] = '\0';
        return 1;
    }
    int n = short_decimal(v, buf);
    return n > 0 ? n : mm_dtoa_fmt(v, buf);
}
