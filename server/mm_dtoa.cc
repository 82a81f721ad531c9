// mm_dtoa.cc — the one C++ file: a C entry point to double-conversion's
// shortest round-trip formatting (see mm_dtoa.h).
#include "mm_dtoa.h"

#include <cmath>
#include <double-conversion/double-conversion.h>

extern "C" int mm_dtoa(double v, char *buf)
{
    if (!std::isfinite(v)) {
        buf[0] = '\0';
        return 0;
    }
    // EcmaScript style: decimal for 1e-7 <= |v| < 1e21, exponent outside,
    // "-0" printed as "0" (JSON has no use for the sign of zero).
    const auto &conv = double_conversion::DoubleToStringConverter::EcmaScriptConverter();
    double_conversion::StringBuilder sb(buf, MM_DTOA_BUFSIZE);
    conv.ToShortest(v == 0.0 ? 0.0 : v, &sb);
    int n = sb.position();
    sb.Finalize();
    return n;
}
