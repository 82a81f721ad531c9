/* complex.c — num-complex: complex numbers in rectangular and polar form.
 *
 *     z = x + i y = r e^{i theta},  r = |z| = hypot(x, y),  theta = atan2(y, x)   (1)-(3)
 *
 * Goal: do one operation — a^2 (the book's (2+i)^2 = 3+4i), a b, a / b, a^n
 * or the n n-th roots of a — twice: once in rectangular form (eqs. 4-5 of
 * the theory: multiply out, i^2 = -1) and once in polar form (eq. 6: moduli
 * multiply, arguments add; de Moivre, eqs. 7-8), and see on the Argand plane
 * why multiplying by a number turns and stretches.
 * Method: the printed result is the rectangular one, computed in
 * double-double (~32 digits) with a running bound of its error and rounded
 * to double, so every digit printed is right (a part that is exactly 0 is
 * printed 0); roots are refined by Newton's method on w^n = a, and where
 * the exact root lies on an axis (a on an axis, eq. 8) its zero part is
 * exact.  The polar form in double is the check, with its own error bound.
 * Checks: rectangular against polar; |ab| = |a||b|, |a^n| = |a|^n;
 * (a / b) b = a; for roots w^n = a and the sum of the n roots (zero).
 * Reference: E. Kreyszig, Advanced Engineering Mathematics, 10th ed., Wiley
 * 2011, sections 13.1-13.2.
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "mm_dd.h"
#include "mm_errbound.h"
#include "mm_exhelp.h"
#include "mm_num.h"

#define U (DBL_EPSILON / 2)

enum { P_ARE, P_AIM, P_BRE, P_BIM, P_OP, P_N };
enum { OP_SQUARE, OP_MULTIPLY, OP_DIVIDE, OP_POWER, OP_ROOTS };

static const char *const ops[] = {"square", "multiply", "divide", "power", "roots", NULL};

#define LIMIT_HELP "; between -100 and 100, so that a, b and the result fit one Argand plane"
static const mm_param params[] = {
    [P_ARE] = {"a_re", "real part of a", "", MM_REAL, 2, -100, 100, .help = "a = a_re + i a_im" LIMIT_HELP},
    [P_AIM] = {"a_im", "imaginary part of a", "", MM_REAL, 1, -100, 100,
               .help = "the book's example is a = 2 + i" LIMIT_HELP},
    [P_BRE] = {"b_re", "real part of b", "", MM_REAL, 1, -100, 100,
               .help = "b = b_re + i b_im, used by multiply and divide" LIMIT_HELP},
    [P_BIM] = {"b_im", "imaginary part of b", "", MM_REAL, 1, -100, 100,
               .help = "b = i turns a by 90 degrees when multiplying" LIMIT_HELP},
    [P_OP] = {"op", "operation", "", MM_CHOICE, OP_SQUARE, 0, 0, .choices = ops,
              .help = "square: a^2; multiply: a b; divide: a / b; power: a^n; roots: the n values of a^(1/n)"},
    [P_N] = {"n", "exponent or root order", "", MM_INT, 3, -12, 12,
             .help = "the whole exponent of power (negative: 1 / a^|n|), or how many roots (n >= 1); |n| <= 12 "
                     "keeps the powers and the root polygon readable on the plane"},
};

enum { O_RE, O_IM, O_MOD, O_ARG, O_AMOD, O_AARG, O_A, O_B, O_Z, O_ROOTS, O_POWERS };

static const mm_output outputs[] = {
    [O_RE] = MM_SCALAR("re", "real part of the result", "", .flags = MM_ANSWER),
    [O_IM] = MM_SCALAR("im", "imaginary part of the result", "", .flags = MM_ANSWER),
    [O_MOD] = MM_SCALAR("modulus", "modulus |z| of the result", "", .flags = MM_ANSWER),
    [O_ARG] = MM_SCALAR("argument", "argument of the result, in (-pi, pi]", "rad", .flags = MM_ANSWER),
    [O_AMOD] = MM_SCALAR("a_modulus", "modulus |a|", ""),
    [O_AARG] = MM_SCALAR("a_argument", "argument of a", "rad"),
    [O_A] = MM_SERIES("a", "a", "", "Re", "", .figure = "argand", .aspect = "equal"),
    [O_B] = MM_SERIES("b", "b", "", "Re", "", .figure = "argand", .aspect = "equal"),
    [O_Z] = MM_SERIES("z", "the result", "", "Re", "", .figure = "argand", .aspect = "equal"),
    [O_ROOTS] = MM_SERIES("roots", "the n roots of a", "", "Re", "", .figure = "argand", .aspect = "equal"),
    [O_POWERS] = MM_SERIES("powers", "a^0, a^1, ..., a^n", "", "Re", "", .figure = "argand", .aspect = "equal",
                           .mark = "dots"),
};

static int check(const mm_value *in, mm_error *err)
{
    int op = (int)in[P_OP].x, n = (int)in[P_N].x;
    if (op == OP_ROOTS && n < 1)
        return mm_error_set(err, MM_ERANGE, "n", "roots needs n >= 1 (how many roots of a to find); got %d", n);
    return MM_OK;
}

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    /* + 0.0 turns a typed -0 into +0, so that atan2 gives pi, not -pi, on
     * the negative real axis: the argument stays in (-pi, pi] */
    double are = in[P_ARE].x + 0.0, aim = in[P_AIM].x + 0.0, bre = in[P_BRE].x + 0.0, bim = in[P_BIM].x + 0.0;
    mm_cdd a = mm_cdd_exact(are, aim), b = mm_cdd_exact(bre, bim);
    int op = (int)in[P_OP].x, n = op == OP_SQUARE ? 2 : (int)in[P_N].x;
    double ra = hypot(are, aim), ta = atan2(aim, are), rb = hypot(bre, bim), tb = atan2(bim, bre);

    if (op == OP_DIVIDE && rb == 0)
        return mm_error_set(err, MM_ESINGULAR, "b_re", "division by zero: b = 0 + 0i has no inverse "
                            "(it has no direction to turn back); give b a nonzero part");
    if (op == OP_POWER && n < 0 && ra == 0)
        return mm_error_set(err, MM_ESINGULAR, "a_re", "a^%d = 1 / a^%d needs a != 0", n, -n);

    /* the result twice: rectangular in double-double, polar in double */
    mm_cdd z;
    double rp, tp;                               /* polar: modulus and angle */
    switch (op) {
    case OP_MULTIPLY:
        z = mm_cdd_mul(a, b);
        rp = ra * rb, tp = ta + tb;              /* eq. (6) */
        break;
    case OP_DIVIDE:
        z = mm_cdd_div(a, b);
        rp = ra / rb, tp = ta - tb;
        break;
    case OP_ROOTS:                               /* the principal root, eq. (8) with k = 0 */
        z = mm_cdd_root(a, ra, ta, n, 0);
        rp = pow(ra, 1.0 / n), tp = ta / n;
        break;
    default:                                     /* square, power: eq. (7) */
        z = n >= 0 ? mm_cdd_pow(a, n) : mm_cdd_div(mm_cdd_exact(1, 0), mm_cdd_pow(a, -n));
        rp = pow(ra, n), tp = n * ta;
        break;
    }
    double zre = mm_dd_val(z.re) + 0.0, zim = mm_dd_val(z.im) + 0.0;
    if (!isfinite(zre) || !isfinite(zim) || !isfinite(rp))
        return mm_error_set(err, MM_ENONFINITE, op == OP_DIVIDE ? "b_re" : "n",
                            "the result overflows the largest double (about 1.8e308); take %s",
                            op == OP_DIVIDE ? "a larger |b|" : "a smaller |a| or |n|");

    /* each part printed with its bound: the dd bound and the rounding to double */
    mm_num_scalar_dd(res, O_RE, z.re, z.err);
    mm_num_scalar_dd(res, O_IM, z.im, z.err);
    mm_dd m2 = mm_dd_add(mm_dd_mul(z.re, z.re), mm_dd_mul(z.im, z.im));
    mm_num_scalar_dd(res, O_MOD, mm_dd_sqrt(m2), z.err + 4 * MM_DD_EPS * sqrt(m2.hi));
    double mz = sqrt(m2.hi), aerr, arg = mm_errbound_arg(z, &aerr);     /* arg 0 of 0, by convention */
    mm_res_scalar_err(res, O_ARG, arg, aerr, MM_ERR_BOUND);
    mm_res_scalar_err(res, O_AMOD, ra, mm_errbound_ulp(ra), MM_ERR_BOUND);
    mm_res_scalar_err(res, O_AARG, ta, mm_errbound_ulp(ta), MM_ERR_BOUND);

    /* the Argand plane: a, b and the result as arrows from the origin */
    if (mm_num_arrow(res, O_A, are, aim) ||
        ((op == OP_MULTIPLY || op == OP_DIVIDE) && mm_num_arrow(res, O_B, bre, bim)) ||
        mm_num_arrow(res, O_Z, zre, zim))
        return MM_ENOMEM;

    /* polar in double (mm_errbound_polar): the modulus within (|n| + 3) u,
     * the angle within (3 |n| |theta| + 2) u */
    int an = op == OP_MULTIPLY || op == OP_DIVIDE ? 1 : abs(n);
    double th = op == OP_MULTIPLY || op == OP_DIVIDE ? fabs(ta) + fabs(tb) : fabs(ta);
    double polar_tol = mm_errbound_polar(rp, an, th) + z.err;
    double polar_dev = hypot(zre - rp * cos(tp), zim - rp * sin(tp));
    if (op == OP_ROOTS) {
        /* all n roots (eq. 8), a regular n-gon; w^n = a and sum w = 0, each
         * within what rounding the roots to double leaves */
        mm_series *s = mm_res_series(res, O_ROOTS, n + 1);
        if (!s)
            return MM_ENOMEM;
        double back, back_tol, sum, sum_tol;
        mm_errbound_roots(a, ra, ta, n, s->x, s->y, &back, &back_tol, &sum, &sum_tol);
        s->x[n] = s->x[0];                       /* close the polygon */
        s->y[n] = s->y[0];
        mm_res_check_abs(res, "roots as printed: worst |w^n - a| <= n |w|^(n-1) |rounding of w|", back, 0, back_tol);
        if (n >= 2)
            mm_res_check_abs(res, "roots: |sum of the n roots| = 0 (coefficient of z^(n-1) in z^n - a)",
                             sum, 0, sum_tol);
        mm_res_check_abs(res, "principal root: rectangular (Newton in double-double) vs polar form in double, eq. (8)",
                         polar_dev, 0, polar_tol);
        mm_res_method(res, "polar form r^(1/n) e^(i (theta + 2 pi k) / n), refined by Newton's method in double-double", 0);
        return MM_OK;
    }

    /* rectangular against polar: the same number by two routes */
    mm_res_check_abs(res, "|rectangular - polar|: eqs. 4-5 in double-double against eqs. 6-7 in double", polar_dev,
                     0, polar_tol);
    double zerr = z.err + U * mz;                    /* the printed z: dd bound + rounding */
    if (op == OP_MULTIPLY) {
        mm_res_check_abs(res, "|a b| = |a| |b|", mz, ra * rb, zerr + 3 * U * ra * rb);
    } else if (op == OP_DIVIDE) {
        mm_cdd back = mm_cdd_mul(mm_cdd_exact(zre, zim), b);
        mm_res_check_abs(res, "(a / b) b = a: |(a / b) b - a| for the printed a / b",
                         hypot(mm_dd_val(mm_dd_sub(back.re, a.re)), mm_dd_val(mm_dd_sub(back.im, a.im))), 0,
                         1.01 * (zerr + U * mz) * rb + back.err);
        mm_res_check_abs(res, "|a / b| = |a| / |b|", mz, ra / rb, zerr + 3 * U * ra / rb);
    } else {
        double rn = pow(ra, n);
        mm_res_check_abs(res, "|a^n| = |a|^n", mz, rn, zerr + (abs(n) + 2) * U * rn);
        /* the powers a^0, a^1, ..., a^n: a spiral that turns by arg a each step */
        if (mm_num_powers(res, O_POWERS, a, n))
            return MM_ENOMEM;
    }
    mm_res_method(res, "rectangular arithmetic in double-double, checked in polar form", 0);
    /* log10 |z| from the moduli, which cannot underflow */
    double lz = op == OP_MULTIPLY ? log10(ra) + log10(rb) : op == OP_DIVIDE ? log10(ra) - log10(rb) : n * log10(ra);
    if (ra != 0 && (op != OP_MULTIPLY || rb != 0) && lz < -300)
        mm_res_warn(res, "|z| = 10^%.1f is at or below the smallest doubles (about 1e-308): digits are lost to "
                    "underflow, or the result is rounded to 0", lz);
    return MM_OK;
}

static const char *const references[] = {
    "E. Kreyszig, Advanced Engineering Mathematics, 10th ed., Wiley 2011, sections 13.1-13.2",
    "T. J. Dekker, A floating-point technique for extending the available precision, Numer. Math. 18 (1971) 224-242",
    NULL,
};

const mm_exercise mm_ex_num_complex = {
    .id = "num-complex", .chapter = 1, .section = "1.4.1", .title = "Complex numbers: rectangular and polar form",
    .summary = "Square, multiply, divide, raise to a power or take roots of complex numbers, on the Argand plane.",
    .tags = "complex numbers, polar form, de Moivre, Argand plane", .theory = "exercises/num/complex.md",
    .params = params, .n_params = MM_COUNT(params), .outputs = outputs, .n_outputs = MM_COUNT(outputs),
    .references = references, .check = check, .solve = solve,
};
