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
// m 10^-k with m an integer not ending in 0, k <= 6, found by multiplying
// and checked exactly: m / 10^k is the correctly rounded value of the
// decimal, so it equals v only if the decimal reads back to v.  It is then
// the shortest text: another decimal as short or shorter lies on the grid
// 10^-k too, at least 10^-k from this one, which is more than an ulp of v
// when |v| < 2^52 10^-6 (4.5e9), so it cannot read back to v.  {fmt}
// writes such numbers in fixed notation when 1e-4 <= |v| < 1e16, as here.
// Anything else goes to Dragonbox.  Writes nothing and returns 0 when the
// fast path does not apply.
static int short_decimal(double v, char *buf)
{
    static const double p10[] = {1, 10, 100, 1e3, 1e4, 1e5, 1e6};
    double a = std::fabs(v);
    if (!(a >= 1e-4 && a < 4.5e9))
        return 0;
    for (int k = 0; k <= 6; k++) {
        double m = a * p10[k];              // < 4.5e15: an int64 holds it
        uint64_t mi = static_cast<uint64_t>(m);
        if (m != static_cast<double>(mi))
            continue;
        if ((k > 0 && mi % 10 == 0) || static_cast<double>(mi) / p10[k] != a)
            return 0;                       // a shorter k was missed by rounding: Dragonbox
        char digits[24];
        int nd = 0;
        for (uint64_t q = mi; q; q /= 10)
            digits[nd++] = static_cast<char>('0' + q % 10);   // least significant first
        char *w = buf;
        if (v < 0)
            *w++ = '-';
        if (nd <= k) {                      // 0.0xyz
            *w++ = '0';
            *w++ = '.';
            for (int i = nd; i < k; i++)
                *w++ = '0';
            for (int i = nd - 1; i >= 0; i--)
                *w++ = digits[i];
        } else {
            for (int i = nd - 1; i >= 0; i--) {
                *w++ = digits[i];
                if (i == k && k > 0)
                    *w++ = '.';
            }
        }
        *w = '\0';
        return static_cast<int>(w - buf);
    }
    return 0;
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
