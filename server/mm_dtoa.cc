// mm_dtoa.cc — the one C++ file: a C entry point to {fmt}'s shortest
// round-trip formatting of doubles (Dragonbox), see mm_dtoa.h.
#include "mm_dtoa.h"

#include <cmath>
#include <fmt/compile.h>
#include <fmt/format.h>

extern "C" int mm_dtoa(double v, char *buf)
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
