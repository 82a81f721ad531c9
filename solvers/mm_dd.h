/* mm_dd.h — double-double arithmetic: a number as the unevaluated sum
 * hi + lo of two doubles, |lo| <= ulp(hi)/2, about 32 significant digits.
 *
 * Used where a double result must be right to its last digit: residuals
 * that cancel, reference computations that the double-precision methods
 * are checked against, error bounds that must not be rounding noise.
 * Algorithms: Dekker (1971), Knuth (TAOCP 2, 4.2.2); the "accurate"
 * addition and division of Bailey's QD library; exact products by fma
 * (C99; glibc uses the hardware instruction where there is one).  Each
 * operation has a relative error below 4 u^2 (u = 2^-53, so ~5e-32), the
 * bound the error analyses built on it use (MM_DD_EPS).
 *
 * Pure functions: no state, safe from any thread.  The real operations are
 * inline here; the complex ones, with their error bounds, in mm_dd.c.
 */
#ifndef MM_DD_H
#define MM_DD_H

#include <math.h>

typedef struct mm_dd {
    double hi, lo;
} mm_dd;

/* relative error of one double-double operation (4 u^2, u = 2^-53) */
#define MM_DD_EPS 4.93038065763132e-32

static inline mm_dd mm_dd_from(double a) { return (mm_dd){a, 0.0}; }

/* a + b exactly, as hi + lo (Knuth's TwoSum) */
static inline mm_dd mm_dd_two_sum(double a, double b)
{
    double s = a + b, bb = s - a;
    return (mm_dd){s, (a - (s - bb)) + (b - bb)};
}

/* a * b exactly, as hi + lo (fma gives the rounding error of the product) */
static inline mm_dd mm_dd_two_prod(double a, double b)
{
    double p = a * b;
    return (mm_dd){p, fma(a, b, -p)};
}

static inline mm_dd mm_dd_fast(double a, double b)     /* |a| >= |b| or a == 0 */
{
    double s = a + b;
    return (mm_dd){s, b - (s - a)};
}

static inline mm_dd mm_dd_add(mm_dd a, mm_dd b)
{
    mm_dd s = mm_dd_two_sum(a.hi, b.hi), t = mm_dd_two_sum(a.lo, b.lo);
    s = mm_dd_fast(s.hi, s.lo + t.hi);
    return mm_dd_fast(s.hi, s.lo + t.lo);
}

static inline mm_dd mm_dd_neg(mm_dd a) { return (mm_dd){-a.hi, -a.lo}; }

static inline mm_dd mm_dd_sub(mm_dd a, mm_dd b) { return mm_dd_add(a, mm_dd_neg(b)); }

static inline mm_dd mm_dd_mul(mm_dd a, mm_dd b)
{
    mm_dd p = mm_dd_two_prod(a.hi, b.hi);
    return mm_dd_fast(p.hi, p.lo + (a.hi * b.lo + a.lo * b.hi));
}

static inline mm_dd mm_dd_mul_d(mm_dd a, double b)
{
    mm_dd p = mm_dd_two_prod(a.hi, b);
    return mm_dd_fast(p.hi, p.lo + a.lo * b);
}

static inline mm_dd mm_dd_div(mm_dd a, mm_dd b)
{
    double q1 = a.hi / b.hi;
    mm_dd r = mm_dd_sub(a, mm_dd_mul_d(b, q1));
    double q2 = r.hi / b.hi;
    r = mm_dd_sub(r, mm_dd_mul_d(b, q2));
    double q3 = r.hi / b.hi;
    mm_dd q = mm_dd_fast(q1, q2);
    return mm_dd_add(q, mm_dd_from(q3));
}

/* sqrt(a), a >= 0 (0 for a <= 0): one Newton step from the double root */
static inline mm_dd mm_dd_sqrt(mm_dd a)
{
    if (!(a.hi > 0))
        return mm_dd_from(0.0);
    double x = sqrt(a.hi);
    mm_dd r = mm_dd_sub(a, mm_dd_two_prod(x, x));
    return mm_dd_fast(x, r.hi / (2 * x));
}

static inline double mm_dd_abs(mm_dd a) { return fabs(a.hi + a.lo); }

/* a rounded to the nearest double (|result - a| <= ulp/2) */
static inline double mm_dd_val(mm_dd a) { return a.hi + a.lo; }

/* ---- complex numbers in double-double, each with a bound of its error --------- */

/* re + i im, and err: |this - the exact value it stands for| <= err (the
 * modulus of the error), carried through every operation (a running error
 * analysis: each operation adds its own rounding, a few MM_DD_EPS of its
 * size, to the errors its operands bring). */
typedef struct mm_cdd {
    mm_dd re, im;
    double err;
} mm_cdd;

/* x + i y exactly (err 0); -0 becomes +0. */
static inline mm_cdd mm_cdd_exact(double x, double y)
{
    return (mm_cdd){mm_dd_from(x + 0.0), mm_dd_from(y + 0.0), 0};
}

/* |z| of the value rounded to double (a size for the bounds). */
double mm_cdd_abs(mm_cdd z);

/* a b (multiplied out: (ac - bd) + i (ad + bc)). */
mm_cdd mm_cdd_mul(mm_cdd a, mm_cdd b);

/* a / b = a conj(b) / |b|^2, b scaled by a power of 2 first so that |b|^2
 * cannot overflow or underflow.  b = 0 gives infinities (the caller checks
 * isfinite). */
mm_cdd mm_cdd_div(mm_cdd a, mm_cdd b);

/* a^n by repeated squaring, n >= 0. */
mm_cdd mm_cdd_pow(mm_cdd a, int n);

/* Root k (0 <= k < n) of a^(1/n), r^(1/n) e^(i (theta + 2 pi k) / n) with
 * r = |a| and theta = arg a as given in double: from that polar form, two
 * Newton steps on w^n = a; err = 2 |w^n - a| / |n w^(n-1)| (Kantorovich, a
 * simple root).  When a lies on an axis the angle is a rational multiple of
 * pi, and a root on an axis gets its zero part exactly.  a = 0 gives 0. */
mm_cdd mm_cdd_root(mm_cdd a, double r, double theta, int n, int k);

/* ---- real numbers in double-double, each with a bound of its error ------------ */

/* x, and e: |x - the exact value it stands for| <= e, carried through
 * every operation like mm_cdd's err.  Each double-double operation adds
 * MM_DDB_R of its result (8 MM_DD_EPS: twice the operation's bound, for
 * room); a sum or product of two doubles adds nothing (TwoSum, TwoProd
 * are exact).  Where a double computation loses digits to cancellation
 * (v x a near an inflection, a reaction from loads that cancel), the same
 * formula in mm_ddb keeps ~32 digits and says how many are left. */
typedef struct mm_ddb {
    mm_dd x;
    double e;
} mm_ddb;

#define MM_DDB_R (8 * MM_DD_EPS)

/* a exactly (e 0) */
static inline mm_ddb mm_ddb_exact(double a) { return (mm_ddb){mm_dd_from(a), 0}; }

/* |x| (of the value rounded to double) */
static inline double mm_ddb_mag(mm_ddb a) { return mm_dd_abs(a.x); }

mm_ddb mm_ddb_add(mm_ddb a, mm_ddb b);
mm_ddb mm_ddb_sub(mm_ddb a, mm_ddb b);
mm_ddb mm_ddb_mul(mm_ddb a, mm_ddb b);

/* k a for k a power of 2 (exact) */
static inline mm_ddb mm_ddb_scale2(mm_ddb a, double k) { return (mm_ddb){{k * a.x.hi, k * a.x.lo}, fabs(k) * a.e}; }

static inline mm_ddb mm_ddb_abs(mm_ddb a) { return mm_dd_val(a.x) < 0 ? (mm_ddb){mm_dd_neg(a.x), a.e} : a; }

/* a / b: |A/B - a/b| <= (e_a + |a/b| e_b) / (|b| - e_b); e = +inf when b
 * may be 0 (|b| <= e_b) */
mm_ddb mm_ddb_quot(mm_ddb a, mm_ddb b);

/* sqrt(a^2 + b^2): |sqrt(Q) - sqrt(q)| = |Q - q| / (sqrt(Q) + sqrt(q)) */
mm_ddb mm_ddb_norm(mm_ddb a, mm_ddb b);

/* a rounded to double, and into *err a bound of that double's error (a's
 * bound plus the rounding) */
static inline double mm_ddb_round(mm_ddb a, double *err)
{
    double x = mm_dd_val(a.x) + 0.0;                         /* no -0 */
    *err = a.e + mm_dd_abs(mm_dd_sub(a.x, mm_dd_from(x)));
    return x;
}

#endif
