/* mm_test.h — numeric assertions on top of cmocka.
 *
 * Every tolerance in a test carries its reason in the call's description or
 * a comment beside it.  These print both numbers and the error on failure.
 */
#ifndef MM_TEST_H
#define MM_TEST_H

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include <cmocka.h>

/* |got - want| <= rtol * |want| (or <= rtol when want == 0). */
#define check_rel(got, want, rtol, desc) \
    mm_check_rel_at((got), (want), (rtol), (desc), __FILE__, __LINE__)
/* |got - want| <= atol. */
#define check_abs(got, want, atol, desc) \
    mm_check_abs_at((got), (want), (atol), (desc), __FILE__, __LINE__)

static inline void mm_check_rel_at(double got, double want, double rtol,
                                   const char *desc, const char *file, int line)
{
    double err = fabs(got - want), scale = fabs(want) > 0 ? fabs(want) : 1.0;
    if (!(err <= rtol * scale)) {
        print_error("%s: got %.17g, want %.17g, rel error %.3g > %.3g\n",
                    desc, got, want, err / scale, rtol);
        _fail(file, line);
    }
}

static inline void mm_check_abs_at(double got, double want, double atol,
                                   const char *desc, const char *file, int line)
{
    double err = fabs(got - want);
    if (!(err <= atol)) {
        print_error("%s: got %.17g, want %.17g, abs error %.3g > %.3g\n",
                    desc, got, want, err, atol);
        _fail(file, line);
    }
}

#endif
