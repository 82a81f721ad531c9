// mm_dtoa.cc — the one C++ file: shortest round-trip text of doubles, see
// mm_dtoa.h.  {fmt}'s Dragonbox finds the digits; we write them ourselves,
// in {fmt}'s "{}" layout, with a fast path for short decimals, and a whole
// array in one call (one call per number from C was a tenth of the cost).
#include "mm_dtoa.h"

#include <cmath>
#include <cstdint>
#include <cstring>
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

namespace {
// inlined into mm_dtoa_list's loop whatever the compiler's estimate
#define MM_INL inline __attribute__((always_inline))

const char digit_pairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

inline void put2(char *w, unsigned r) { std::memcpy(w, digit_pairs + 2 * r, 2); }

const uint64_t pow10[20] = {1ULL, 10ULL, 100ULL, 1000ULL, 10000ULL, 100000ULL, 1000000ULL, 10000000ULL,
                            100000000ULL, 1000000000ULL, 10000000000ULL, 100000000000ULL,
                            1000000000000ULL, 10000000000000ULL, 100000000000000ULL,
                            1000000000000000ULL, 10000000000000000ULL, 100000000000000000ULL,
                            1000000000000000000ULL, 10000000000000000000ULL};

// Decimal digits of x > 0: from its bit length (log10 2 ~ 1233/4096, which
// gives floor(log10 x) or one less), corrected by one comparison.
inline int count_digits(uint64_t x)
{
    int bits = 64 - __builtin_clzll(x | 1);
    int n = (bits * 1233) >> 12;
    return n + (x >= pow10[n]);
}

// The n digits of x (n = count_digits(x)) at w[0..n), written from the end.
inline void put_digits(char *w, uint64_t x, int n)
{
    char *d = w + n;
    while (x >= 100000000) {                  // 8 at a time in 32-bit arithmetic
        uint32_t lo = static_cast<uint32_t>(x % 100000000);
        x /= 100000000;
        uint32_t a = lo / 10000, b = lo % 10000;
        put2(d - 8, a / 100), put2(d - 6, a % 100), put2(d - 4, b / 100), put2(d - 2, b % 100);
        d -= 8;
    }
    uint32_t y = static_cast<uint32_t>(x);
    while (y >= 100) {
        put2(d - 2, y % 100);
        y /= 100;
        d -= 2;
    }
    if (y >= 10)
        put2(d - 2, y);
    else
        d[-1] = static_cast<char>('0' + y);
}

// Most numbers of an answer are short decimals: plot abscissae (0.02 k),
// animation coordinates rounded to a few places (0.0195).  Such a v is
// m 10^-k with m an integer not ending in 0, k <= 6, i.e. M 10^-6 with M
// whole.  It is found in one product: M = |v| 10^6 rounded to a whole
// number, and then M / 10^6, the correctly rounded value of the decimal
// M 10^-6 (M below 4.5e15 < 2^52 and 10^6 are exact), must equal |v|: the
// decimal reads back to v.  M's trailing zeros then leave the fraction.
// It is then the shortest text, the one Dragonbox gives: every decimal as
// short or shorter lies on the grid 10^-6 too (one with a digit below
// 10^-6 has at least 8 digits after |v|'s first, this one at most 7), at
// least 10^-6 from this one, which is more than an ulp of v when
// |v| < 2^52 10^-6 (4.5e9), so it cannot read back to v.  {fmt} writes
// such numbers in fixed notation when 1e-4 <= |v| < 1e16, as here (the
// tests compare the two on millions of numbers).  Near 4.5e9, |v| 10^6 can
// round to a neighbour of the M of a short v (its errors add up to 0.73):
// the check fails and the number simply goes to Dragonbox.
//
// A list of such numbers goes as fast as few instructions a number allow
// (the processor overlaps the numbers), so: one unsigned comparison of the
// bits for 1e-4 <= |v| < 4.5e9 (which also turns away 0, infinities and
// NaN), the sign from the sign bit, M rounded by adding 2^52 (M is then in
// the low bits; no conversions to and from int64), the fraction's six
// digits as two table entries of three in one word and their count from
// its last non-zero byte, no branch on the digits.  Returns NULL, having
// written nothing, when the fast path does not apply; else the end.
// Writes up to 20 bytes from w.
const uint64_t lo_bits = 0x3F1A36E2EB1C432DULL;      // 1e-4
const uint64_t hi_bits = 0x41F0C388D0000000ULL;      // 4.5e9

// "000" to "999" as the low three bytes of a word, first digit lowest
struct digit_triples {
    uint32_t t[1000];
    constexpr digit_triples() : t()
    {
        for (uint32_t i = 0; i < 1000; i++)
            t[i] = ('0' + i / 100) | ('0' + i / 10 % 10) << 8 | ('0' + i % 10) << 16;
    }
};
constexpr digit_triples triples;

MM_INL char *short_decimal(double v, char *w)
{
    uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    uint64_t abits = bits & ~(1ULL << 63);
    if (abits - lo_bits >= hi_bits - lo_bits)
        return nullptr;
    double a;
    std::memcpy(&a, &abits, sizeof a);
    double big = a * 1e6 + 0x1p52;           // M + 2^52, M = |v| 10^6 rounded
    if ((big - 0x1p52) / 1e6 != a)
        return nullptr;
    uint64_t M;
    std::memcpy(&M, &big, sizeof M);
    M &= (1ULL << 52) - 1;
    *w = '-';                                 // kept only when v < 0
    w += bits >> 63;
    uint64_t ip = M / 1000000;                // up to 4.5e9: more than 32 bits
    uint32_t fr = static_cast<uint32_t>(M - ip * 1000000);
    if (ip < 10) {                            // the integer part, at least "0"
        *w++ = static_cast<char>('0' + ip);
    } else if (ip < 100) {
        put2(w, static_cast<unsigned>(ip));
        w += 2;
    } else {
        int n = count_digits(ip);
        put_digits(w, ip, n);
        w += n;
    }
    if (fr == 0)
        return w;
    // the fraction as six digits, cut after the last non-zero one
    w[0] = '.';
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    uint32_t hi = fr / 1000;
    uint64_t six = triples.t[hi] | static_cast<uint64_t>(triples.t[fr - 1000 * hi]) << 24;
    std::memcpy(w + 1, &six, 8);
    int k = (71 - __builtin_clzll(six ^ 0x303030303030ULL)) / 8;   // six != "000000": fr > 0
#else
    uint32_t h = fr / 100, p0 = fr / 10000, p1 = h - 100 * p0, p2 = fr - 100 * h;
    int k = 6 - (fr % 10 == 0) - (p2 == 0) - (fr % 1000 == 0) - (p1 == 0 && p2 == 0) - (fr % 100000 == 0);
    put2(w + 1, p0), put2(w + 3, p1), put2(w + 5, p2);
#endif
    return w + 1 + k;
}

// Any positive finite v: Dragonbox's digits s and exponent e (v = s 10^e)
// laid out as {fmt}'s "{}" lays them (fmt/format.h do_write_float, general
// format, no precision): exponent notation d[.ddd]e+XX when the decimal
// exponent of the first digit is below -4 or 16 or more, else fixed.  The
// digits are written where they belong, never written and then moved (a
// read of bytes just written in pieces waits for them: store forwarding
// fails); it writes up to 34 bytes from w.
char *dragonbox(double v, char *w)
{
    auto dec = fmt::detail::dragonbox::to_decimal(v);
    uint64_t s = dec.significand;
    int e = dec.exponent;
    int nd = count_digits(s);                 // 1..17
    int oe = e + nd - 1;                      // the first digit's exponent
    if (oe < -4 || oe >= 16) {                // d.ddde+XX
        put_digits(w + 1, s, nd);             // then the first digit moved left
        w[0] = w[1];                          // over the point (a byte of a pair
        w[1] = '.';                           // just written: that one forwards)
        w += nd > 1 ? nd + 1 : 1;
        *w++ = 'e';
        *w = '+';
        if (oe < 0) {
            *w = '-';
            oe = -oe;
        }
        w++;
        if (oe >= 100) {                      // |oe| <= 324
            *w++ = static_cast<char>('0' + oe / 100);
            oe %= 100;
        }
        put2(w, static_cast<unsigned>(oe));
        return w + 2;
    }
    if (e >= 0) {                             // 1234e5 -> 123400000 (nd + e <= 16)
        put_digits(w, s, nd);
        std::memset(w + nd, '0', 16);
        return w + nd + e;
    }
    int ip = nd + e;                          // digits before the point
    if (ip > 0) {                             // 1234e-2 -> 12.34 (ip <= 16)
        // v's integer part is s's first ip digits: an integer between v and
        // s 10^e would be a shorter text of v than s 10^e; and checked
        int nf = -e;
        uint64_t whole = static_cast<uint64_t>(v), frac = s - whole * pow10[nf];
        if (frac < pow10[nf]) {
            put_digits(w, whole, ip);
            w[ip] = '.';
            std::memset(w + ip + 1, '0', 16);                 // the fraction's leading zeros
            int nfd = count_digits(frac | 1);                         // (frac | 1: 0 as one digit)
            put_digits(w + ip + 1 + nf - nfd, frac, nfd);
            return w + nd + 1;
        }
        char d[40];                                           // (never seen; kept safe)
        put_digits(d, s, nd);
        std::memcpy(w, d, static_cast<size_t>(ip));
        w[ip] = '.';
        std::memcpy(w + ip + 1, d + ip, static_cast<size_t>(nf));
        return w + nd + 1;
    }
    std::memcpy(w, "0.000", 5);               // 1234e-6 -> 0.001234 (-ip <= 3)
    put_digits(w + 2 - ip, s, nd);
    return w + 2 - ip + nd;
}

// v as text at w, the end returned; -0 is written as 0 (JSON has no use
// for the sign of zero), a non-finite v as 0 with *nonfinite set.
MM_INL char *write_number(double v, char *w, int *nonfinite)
{
    if (char *end = short_decimal(v, w))
        return end;
    if (v == 0.0 || !std::isfinite(v)) {
        *nonfinite |= v != 0.0;
        *w = '0';
        return w + 1;
    }
    *w = '-';
    return dragonbox(std::fabs(v), w + (v < 0));
}

}  // namespace

extern "C" int mm_dtoa(double v, char *buf)
{
    if (!std::isfinite(v)) {
        buf[0] = '\0';
        return 0;
    }
    char t[MM_DTOA_BUFSIZE + MM_DTOA_SLACK];       // room for what write_number touches
    int nonfinite = 0;
    char *end = write_number(v, t, &nonfinite);
    *end = '\0';
    size_t n = static_cast<size_t>(end - t);
    std::memcpy(buf, t, n + 1);
    return static_cast<int>(n);
}

extern "C" char *mm_dtoa_list(const double *v, size_t n, int first, char *w, int *nonfinite)
{
    if (n > 0) {
        if (!first)
            *w++ = ',';
        w = write_number(v[0], w, nonfinite);
        for (size_t i = 1; i < n; i++) {
            *w++ = ',';
            w = write_number(v[i], w, nonfinite);
        }
    }
    *w = '\0';
    return w;
}
