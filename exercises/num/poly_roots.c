/* poly_roots.c — num-poly-roots: all roots of a polynomial, MATLAB's roots(p).
 *
 *     p(x) = p_1 x^d + p_2 x^(d-1) + ... + p_(d+1) = 0                  (1)
 *
 * Goal: find the d roots, real and complex, of the book's x^3 + 2x^2 + 3x + 4
 * (-1.6506 and -0.1747 +- 1.5469i) or any other polynomial, and learn that
 * a root can be far less accurate than the coefficients: how much less is
 * its condition number (eq. 5), and a multiple root keeps only about 16/m
 * of the 16 digits (eq. 6).
 * Method: the roots are the eigenvalues of the companion matrix (eq. 3,
 * LAPACK dgeev, as MATLAB does), polished by Newton steps on p evaluated in
 * double-double arithmetic, each with an error estimate (mm_poly.h).
 * Checks: the backward error |p(z)| / sum |p_k| |z|^k of every root, and
 * Vieta's formulas (sum and product of the roots against the coefficients).
 * A root is counted real when its error disc meets the real axis: a
 * cluster of roots scattered around a multiple real root is real within
 * its error, and the count says how many of the roots that covers.
 * Reference: A. Edelman, H. Murakami, Polynomial roots from companion matrix
 * eigenvalues, Math. Comp. 64 (1995) 763-776; J. H. Wilkinson, Rounding
 * Errors in Algebraic Processes, Prentice-Hall 1963, ch. 2.
 */
#include <float.h>
#include <math.h>

#include "mm_exhelp.h"
#include "mm_poly.h"

#define MAXC 21                 /* coefficients: degree 20 at most */

enum { P_P };

static const mm_param params[] = {
    [P_P] = {"p", "coefficients, highest power first", "", MM_VECTOR, 0, -1e300, 1e300, "1,2,3,4", NULL, 0, MAXC,
             .help = "p(1) x^d + ... + p(d+1), as MATLAB's [1 2 3 4] for x^3 + 2x^2 + 3x + 4; at most degree 20 "
                     "(Wilkinson's (x-1)(x-2)...(x-20) is the classic hard case: beyond it double precision leaves "
                     "no digit of most roots); coefficients of any size a double holds (to 1e300): finding roots "
                     "does not depend on the scale of p"},
};

enum { O_DEGREE, O_REAL, O_MAXERR, O_ROOTS, O_PLANE, O_P };

static const char *const root_cols[] = {"re", "im", "modulus", "err", "multiplicity", NULL};
static const char *const root_units[] = {"", "", "", "", "", NULL};

static const mm_output outputs[] = {
    [O_DEGREE] = MM_SCALAR("degree", "degree of p", "", .flags = MM_ANSWER | MM_EXACT),
    [O_REAL] = MM_SCALAR("real_roots", "number of real roots (a root whose error disc meets the real axis counts "
                         "as real)", "", .flags = MM_ANSWER),
    [O_MAXERR] = MM_SCALAR("max_err", "largest error bound of a root (a size: known to a factor of 2)", ""),
    [O_ROOTS] = MM_TABLE("roots", "the roots, each within err of an exact root of p", root_cols, root_units),
    [O_PLANE] = MM_SERIES("roots", "roots on the complex plane", "", "Re", "", .mark = "dots", .aspect = "equal"),
    [O_P] = MM_SERIES("p", "p(x) on the real axis", "", "x", ""),
};

static int solve(const mm_value *in, mm_result *res, mm_error *err)
{
    int nc = in[P_P].cols;
    const double *p = in[P_P].data;
    mm_poly_root *roots = mm_res_alloc(res, (size_t)nc * sizeof *roots);
    if (!roots)
        return MM_ENOMEM;
    int nr;
    int rc = mm_poly_roots(nc, p, roots, &nr, err);
    if (rc == MM_EVALUE)
        return mm_error_set(err, MM_EVALUE, "p", "p is all zeros: every x would be a root; give at least "
                            "one nonzero coefficient");
    if (rc != MM_OK)
        return rc;

    int lead = 0;
    while (p[lead] == 0)
        lead++;
    const double *q = p + lead;                 /* leading zeros dropped: degree d */
    int d = nc - 1 - lead;
    if (lead > 0)
        mm_res_warn(res, "the first %d coefficient%s zero, so the degree is %d, not %d", lead,
                    lead > 1 ? "s are" : " is", d, nc - 1);

    mm_table *t = mm_res_table(res, O_ROOTS, nr);
    mm_series *sz = mm_res_series(res, O_PLANE, nr);
    if (!t || !sz)
        return MM_ENOMEM;
    double worst_b = 0, max_err = 0;
    double sre = 0, serr = 0, sabs = 0, logprod = 0, lerr = 0;
    int zeros = 0, nmult = 0, nill = 0, nreal = 0, nsure = 0;
    double mult_err = 0, ill_err = 0;
    for (int i = 0; i < nr; i++) {
        const mm_poly_root *z = &roots[i];
        double mod = hypot(z->re, z->im);
        double *row = t->cell + 5 * i;
        row[0] = z->re;
        row[1] = z->im;
        row[2] = mod;
        row[3] = z->err;
        row[4] = z->multiplicity;
        sz->x[i] = z->re;
        sz->y[i] = z->im;
        /* real when the disc |x - z| <= err meets the real axis; certainly
         * real when the disc holds this root alone (a real polynomial's
         * complex roots come in pairs, and the disc is symmetric about the
         * axis), so it is computed real and simple */
        nreal += fabs(z->im) <= z->err;
        nsure += z->im == 0 && z->multiplicity == 1;
        max_err = fmax(max_err, z->err);
        if ((z->flags & MM_POLY_ROOT_MULTIPLE) && z->err > 0) {  /* exact zero roots are exact */
            nmult++;
            mult_err = fmax(mult_err, z->err);
        }
        if ((z->flags & MM_POLY_ROOT_ILLCOND) && !(z->flags & MM_POLY_ROOT_MULTIPLE)) {
            nill++;
            ill_err = fmax(ill_err, z->err);
        }
        worst_b = fmax(worst_b, mm_poly_backward_error(d + 1, q, z->re, z->im));
        sre += z->re;
        serr += z->err;
        sabs += mod;
        if (mod == 0) {
            zeros++;
        } else {
            logprod += log(mod);
            lerr += z->err / mod;
        }
    }

    mm_res_scalar(res, O_DEGREE, d);
    /* of the roots counted real but not certainly so, the true count can be
     * lower by an even number (pairs of complex roots) */
    int unsure = nreal - nsure;
    mm_scalar *sr = mm_res_scalar_err(res, O_REAL, nreal, unsure - unsure % 2, MM_ERR_BOUND);
    if (unsure > 1)
        sr->text = mm_res_printf(res, "%d of them within their error of the real axis: between %d and %d real roots",
                                 unsure, nreal - (unsure - unsure % 2), nreal);
    else
        sr->exact = 1;
    mm_res_scalar_err(res, O_MAXERR, max_err, 0.5 * max_err, MM_ERR_ESTIMATE);

    if (d == 0) {
        mm_res_warn(res, "p is a nonzero constant: it has no roots");
        mm_res_method(res, "none needed (degree 0)", 0);
        return MM_OK;
    }

    /* check 1: each root is the exact root of a polynomial whose
     * coefficients differ from p's by a few eps (backward error); Horner's
     * own rounding is at most 2d u of the scale (Higham, eq. 5.3) */
    double btol = (2.0 * d + 4) * DBL_EPSILON;
    mm_res_check_abs(res, "worst backward error |p(z)| / sum |p_k| |z|^k over the roots", worst_b, 0, btol);
    if (worst_b > btol)
        mm_res_warn(res, "some roots are not roots of p to working precision (backward error %.2g): the "
                    "coefficients span too many orders of magnitude for the companion matrix, and roots of very "
                    "different sizes cannot all be resolved", worst_b);

    /* check 2: Vieta, sum of the roots = -p_2 / p_1 (eq. 4) */
    double ref_sum = d >= 1 ? -q[1] / q[0] : 0;
    mm_res_check_abs(res, "Vieta: sum of the roots = -p(2)/p(1)", sre, ref_sum,
                     serr + 4 * d * DBL_EPSILON * (sabs + fabs(ref_sum)));
    /* check 3: product of the roots = (-1)^d p_(d+1) / p_1, on log |.| so that
     * it cannot overflow; skipped with exact zero roots (product 0 = p_(d+1)) */
    if (zeros == 0)
        mm_res_check_abs(res, "Vieta: log |product of the roots| = log |p(d+1)/p(1)|", logprod,
                         log(fabs(q[d])) - log(fabs(q[0])), lerr + 4 * d * DBL_EPSILON * (1 + fabs(logprod)));

    mm_res_method(res, "eigenvalues of the companion matrix (LAPACK dgeev), Newton polish in double-double", 0);
    mm_res_method_stat(res, "error_estimate", max_err);

    if (nmult)
        mm_res_warn(res, "%d roots form clusters (multiple roots, see the multiplicity column): a root of "
                    "multiplicity m is only determined to about eps^(1/m) of its size, here within %.2g; "
                    "the computed values are scattered around the true root%s", nmult, mult_err,
                    unsure > 1 ? ", and those whose error reaches the real axis are counted as real roots" : "");
    if (nill)
        mm_res_warn(res, "%d simple root%s ill-conditioned: more than half of the digits are lost (error up to "
                    "%.2g); small changes of p move %s far", nill, nill > 1 ? "s are" : " is", ill_err,
                    nill > 1 ? "them" : "it");

    /* p on the real axis, over the real parts of the roots and a margin */
    double lo = roots[0].re, hi = lo;
    for (int i = 0; i < nr; i++) {
        lo = fmin(lo, roots[i].re);
        hi = fmax(hi, roots[i].re);
    }
    double span = fmax(hi - lo, fmax(1e-3 * fmax(fabs(lo), fabs(hi)), 1e-3)), m = 0.25 * span;
    enum { NP = 201 };
    double xs[NP], ys[NP];
    int ok = 1;
    mm_linspace(lo - m, hi + m, NP, xs);
    for (int i = 0; i < NP && ok; i++) {
        ys[i] = mm_poly_eval(d + 1, q, xs[i], NULL);
        ok = isfinite(ys[i]);
    }
    if (ok) {
        mm_series *s = mm_res_series(res, O_P, NP);
        if (!s)
            return MM_ENOMEM;
        for (int i = 0; i < NP; i++) {
            s->x[i] = xs[i];
            s->y[i] = ys[i];
        }
    } else {
        mm_res_warn(res, "p(x) overflows on the plot range; the curve is left out");
    }
    return MM_OK;
}

static const char *const references[] = {
    "A. Edelman, H. Murakami, Polynomial roots from companion matrix eigenvalues, Math. Comp. 64 (1995) 763-776",
    "J. H. Wilkinson, Rounding Errors in Algebraic Processes, Prentice-Hall 1963, ch. 2",
    "N. J. Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed., SIAM 2002, ch. 5",
    NULL,
};

const mm_exercise mm_ex_num_poly_roots = {
    .id = "num-poly-roots",
    .chapter = 1,
    .section = "1.4.2",
    .title = "Roots of a polynomial",
    .summary = "All real and complex roots of a polynomial like MATLAB's roots(p), each with its error estimate.",
    .tags = "polynomial, roots, companion matrix, conditioning, multiple roots",
    .theory = "exercises/num/poly_roots.md",
    .params = params,
    .n_params = MM_COUNT(params),
    .outputs = outputs,
    .n_outputs = MM_COUNT(outputs),
    .references = references,
    .check = NULL,
    .solve = solve,
};
