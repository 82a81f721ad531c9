/* complex.c — num-complex: complex numbers in rectangular and polar form.
 *
 *     z = x + i y = r e^{i theta},  r = |z| = hypot(x, y),  theta = atan2(y, x)   (1)-(3)
 *
 * Goal: do one operation — a^2 (the book's (2+i)^2 = 3+4i), a b, a / b, a^n
 * or the n n-th roots of a — twice: once in rectangular form (eqs. 4-5 of
 * the theory: multiply out, i^2 = -1) and once in polar form (eq. 6: moduli
 * multiply, arguments add; de Moivre, eqs. 7-8), and see on the Argand plane
 * why multiplying by a number turns and stretches.  The two computations
 * check each other; |ab| = |a||b| and, for roots, w^n = a and the sum of the
 * n roots (zero) are further checks.
 * Reference: E. Kreyszig, Advanced Engineering Mathematics, 10th ed., Wiley
 * 2011, sections 13.1-13.2.
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "mm_exhelp.h"

enum { P_ARE, P_AIM, P_BRE, P_BIM, P_OP, P_N };
enum { OP_SQUARE, OP_MULTIPLY, OP_DIVIDE, OP_POWER, OP_ROOTS };

static const char *const ops[] = {"square", "multiply", "divide", "power", "roots", NULL};

static const mm_param params[] = {
    [P_ARE] = {"a_re", "real part of a", "", MM_REAL, 2, -100, 100, .help = "a = a_re + i a_im"},
    [P_AIM] = {"a_im", "imaginary part of a", "", MM_REAL, 1, -100, 100,
               .help = "the book's example is a = 2 + i"},
    [P_BRE] = {"b_re", "real part of b", "", MM_REAL, 1, -100, 100,
               .help = "b = b_re + i b_im, used by multiply and divide"},
    [P_BIM] = {"b_im", "imaginary part of b", "", MM_REAL, 1, -100, 100,
               .help = "b = i turns a by 90 degrees when multiplying"},
    [P_OP] = {"op", "operation", "", MM_CHOICE, OP_SQUARE, 0, 0, .choices = ops,
              .help = "square: a^2; multiply: a b; divide: a / b; power: a^n; roots: the n values of a^(1/n)"},
    [P_N] = {"n", "exponent or root order", "", MM_INT, 3, -12, 12,
             .help = "the whole exponent of power (negative: 1 / a^|n|), or how many roots (n >= 1)"},
};

typedef struct cplx {
    double re, im;
} cplx;

static cplx mul(cplx a, cplx b)                  /* eq. (4) */
{
    return (cplx){a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
}

/* a / b by eq. (5), with b scaled first so that |b|^2 cannot overflow or
 * underflow (Smith's idea).  b != 0. */
static cplx divide(cplx a, cplx b)
{
    double s = fmax(fabs(b.re), fabs(b.im));
    double c = b.re / s, d = b.im / s, den = c * c + d * d;
    return (cplx){(a.re * c + a.im * d) / den / s, (a.im * c - a.re * d) / den / s};
}

/* a^n by repeated squaring in rectangular form (n >= 0). */
static cplx ipow(cplx a, int n)
{
    cplx z = {1, 0};
    while (n > 0) {
        if (n & 1)
            z = mul(z, a);
        a = mul(a, a);
        n >>= 1;
    }
    return z;
}

static cplx polar(double r, double theta)       /* eq. (2) backwards */
{
    return (cplx){r * cos(theta), r * sin(theta)};
}

static double cabs_(cplx z) { return hypot(z.re, z.im); }
static double carg_(cplx z) { return atan2(z.im, z.re); }

/* Rounding bound for a result of size mag after k roundings of relative
 * size eps, with a floor for results in the subnormal range. */
static double bound(double mag, int k) { return k * DBL_EPSILON * mag + k * 4 * DBL_TRUE_MIN; }

static int check(const mm_value *in, mm_error *err)
{
    int op = (int)in[P_OP].x, n = (int)in[P_N].x;
    if (op == OP_ROOTS && n < 1)
        return mm_error_set(err, MM_ERANGE, "n", "roots needs n >= 1 (how many roots of a to find); got %d", n);
    return MM_OK;
}

/* A segment from the origin to z, the way an arrow is drawn on the Argand plane. */
static int arrow(mm_result *res, const char *name, const char *label, cplx z)
{
    mm_series *s = mm_res_series_v1(res, name, label, "", "Re", "", 2);
    if (!s)
        return MM_ENOMEM;
    s->x[1] = z.re;
    s->y[1] = z.im;
    return MM_OK;
}

static int is_finite(cplx z) { return isfinite(z.re) && isfinite(z.im); }

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    /* + 0.0 turns a typed -0 into +0, so that atan2 gives pi, not -pi, on
     * the negative real axis: the argument stays in (-pi, pi] */
    cplx a = {in[P_ARE].x + 0.0, in[P_AIM].x + 0.0}, b = {in[P_BRE].x + 0.0, in[P_BIM].x + 0.0};
    int op = (int)in[P_OP].x, n = op == OP_SQUARE ? 2 : (int)in[P_N].x;
    double ra = cabs_(a), ta = carg_(a), rb = cabs_(b), tb = carg_(b);
    int uses_b = op == OP_MULTIPLY || op == OP_DIVIDE;

    if (op == OP_DIVIDE && rb == 0)
        return mm_error_set(err, MM_ESINGULAR, "b_re", "division by zero: b = 0 + 0i has no inverse "
                            "(it has no direction to turn back); give b a nonzero part");
    if (op == OP_POWER && n < 0 && ra == 0)
        return mm_error_set(err, MM_ESINGULAR, "a_re", "a^%d = 1 / a^%d needs a != 0", n, -n);

    /* the result twice: rectangular and polar */
    cplx z, zp;
    const char *what;
    switch (op) {
    case OP_MULTIPLY:
        z = mul(a, b);
        zp = polar(ra * rb, ta + tb);           /* eq. (6) */
        what = "a b";
        break;
    case OP_DIVIDE:
        z = divide(a, b);
        zp = polar(ra / rb, ta - tb);
        what = "a / b";
        break;
    case OP_ROOTS:                              /* the principal root, eq. (8) with k = 0 */
        z = zp = polar(pow(ra, 1.0 / n), ta / n);
        what = "a^(1/n)";
        break;
    default:                                    /* square, power: eq. (7) */
        z = n >= 0 ? ipow(a, n) : divide((cplx){1, 0}, ipow(a, -n));
        zp = polar(pow(ra, n), n * ta);
        what = "a^n";
        break;
    }
    if (!is_finite(z) || !is_finite(zp))
        return mm_error_set(err, MM_ENONFINITE, op == OP_DIVIDE ? "b_re" : "n",
                            "%s overflows the largest double (about 1.8e308); take %s", what,
                            op == OP_DIVIDE ? "a larger |b|" : "a smaller |a| or |n|");

    z.re += 0.0;                                 /* no -0 in the answer either */
    z.im += 0.0;
    mm_res_scalar_v1(res, "re", "real part of the result", "", z.re);
    mm_res_scalar_v1(res, "im", "imaginary part of the result", "", z.im);
    mm_res_scalar_v1(res, "modulus", "modulus |z| of the result", "", cabs_(z));
    mm_res_scalar_v1(res, "argument", "argument of the result, in (-pi, pi]", "rad", carg_(z));
    mm_res_scalar_v1(res, "a_modulus", "modulus |a|", "", ra);
    mm_res_scalar_v1(res, "a_argument", "argument of a", "rad", ta);

    /* the Argand plane: a, b and the result as arrows from the origin */
    int rc = arrow(res, "a", "a", a);
    if (rc == MM_OK && uses_b)
        rc = arrow(res, "b", "b", b);
    if (rc == MM_OK)
        rc = arrow(res, "z", op == OP_ROOTS ? "principal root" : "result", z);
    if (rc != MM_OK)
        return mm_error_set(err, MM_ENOMEM, "", "out of memory");

    int k = abs(n) + 3;                          /* roundings in the longest chain */
    double mag = cabs_(zp);
    if (op == OP_ROOTS) {
        /* all n roots (eq. 8), a regular n-gon; w^n = a and sum w = 0 */
        mm_series *s = mm_res_series_v1(res, "roots", "the n roots of a", "", "Re", "", n + 1);
        if (!s)
            return mm_error_set(err, MM_ENOMEM, "", "out of memory");
        double back = 0, sre = 0, sim = 0, r1 = pow(ra, 1.0 / n);
        for (int j = 0; j < n; j++) {
            cplx w = polar(r1, (ta + 2 * M_PI * j) / n);
            s->x[j] = w.re;
            s->y[j] = w.im;
            cplx wn = ipow(w, n);
            back = fmax(back, hypot(wn.re - a.re, wn.im - a.im));
            sre += w.re;
            sim += w.im;
        }
        s->x[n] = s->x[0];                       /* close the polygon */
        s->y[n] = s->y[0];
        /* w^n carries n times the relative error of w, and the angle
         * theta + 2 pi k, up to 2 pi n, is rounded to eps of its size */
        mm_res_check_abs(res, "roots: worst |w^n - a| (w^n by repeated multiplication)", back, 0,
                         bound(ra, 12 * (n + 1)));
        if (n >= 2)
            mm_res_check_abs(res, "roots: |sum of the n roots| = 0 (coefficient of z^(n-1) in z^n - a)",
                             hypot(sre, sim), 0, bound(r1, 12 * n));
        mm_res_method(res, "polar form: r^(1/n) e^(i (theta + 2 pi k) / n)", 0);
        return MM_OK;
    }

    /* rectangular against polar: the same number by two routes */
    mm_res_check_abs(res, "|rectangular - polar| (eqs. 4-5 against eqs. 6-7)",
                     hypot(z.re - zp.re, z.im - zp.im), 0, bound(mag, 2 * k));
    if (op == OP_MULTIPLY) {
        mm_res_check_abs(res, "|a b| = |a| |b|", cabs_(z), ra * rb, bound(ra * rb, 4));
    } else if (op == OP_DIVIDE) {
        cplx back = mul(z, b);
        mm_res_check_abs(res, "(a / b) b = a: |(a / b) b - a|", hypot(back.re - a.re, back.im - a.im), 0,
                         bound(ra, 8));
        mm_res_check_abs(res, "|a / b| = |a| / |b|", cabs_(z), ra / rb, bound(ra / rb, 6));
    } else {
        double rn = pow(ra, n);
        mm_res_check_abs(res, "|a^n| = |a|^n", cabs_(z), rn, bound(rn, 2 * k));
        /* the powers a^0, a^1, ..., a^n: a spiral that turns by arg a each step */
        int m = abs(n) + 1;
        mm_series *s = mm_res_series_v1(res, "powers", n >= 0 ? "a^0, a^1, ..., a^n" : "a^0, a^-1, ..., a^n",
                                     "", "Re", "", m);
        if (!s)
            return mm_error_set(err, MM_ENOMEM, "", "out of memory");
        cplx step = n >= 0 ? a : divide((cplx){1, 0}, a), p = {1, 0};
        for (int j = 0; j < m; j++) {
            s->x[j] = p.re;
            s->y[j] = p.im;
            p = mul(p, step);
        }
    }
    mm_res_method(res, "rectangular arithmetic, checked in polar form", 0);
    /* log10 |z| from the moduli, which cannot underflow */
    double lz = op == OP_MULTIPLY ? log10(ra) + log10(rb) : op == OP_DIVIDE ? log10(ra) - log10(rb) : n * log10(ra);
    if (ra != 0 && (op != OP_MULTIPLY || rb != 0) && lz < -300)
        mm_res_warn(res, "|z| = 10^%.1f is at or below the smallest doubles (about 1e-308): digits are lost to "
                    "underflow, or the result is rounded to 0", lz);
    return MM_OK;
}

static const char *const references[] = {
    "E. Kreyszig, Advanced Engineering Mathematics, 10th ed., Wiley 2011, sections 13.1-13.2",
    NULL,
};

const mm_exercise mm_ex_num_complex = {
    .id = "num-complex",
    .chapter = 1,
    .section = "1.4.1",
    .title = "Complex numbers: rectangular and polar form",
    .summary = "Square, multiply, divide, raise to a power or take roots of complex numbers, on the Argand plane.",
    .tags = "complex numbers, polar form, de Moivre, Argand plane",
    .theory = "exercises/num/complex.md",
    .params = params,
    .n_params = MM_COUNT(params),
    .references = references,
    .check = check,
    .solve = solve,
};
