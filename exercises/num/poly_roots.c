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
#include "mm_num.h"
#include "mm_polycheck.h"

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

static const char *const root_cols[] = {"re", "im", "modulus", "err", "multiplicity", NULL},
                         *const root_units[] = {"", "", "", "", "", NULL};

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
    for (int i = 0; i < nr; i++) {
        const mm_poly_root *z = &roots[i];
        double *row = t->cell + 5 * i;
        row[0] = z->re;
        row[1] = z->im;
        row[2] = hypot(z->re, z->im);
        row[3] = z->err;
        row[4] = z->multiplicity;
        sz->x[i] = z->re;
        sz->y[i] = z->im;
    }
    /* real when the disc |x - z| <= err meets the real axis; certainly real
     * when computed real and simple (mm_poly_roots_summarize) */
    mm_poly_roots_summary S;
    mm_poly_roots_summarize(d + 1, q, roots, &S);

    mm_res_scalar(res, O_DEGREE, d);
    /* of the roots counted real but not certainly so, the true count can be
     * lower by an even number (pairs of complex roots) */
    int unsure = S.real - S.sure_real;
    mm_scalar *sr = mm_res_scalar_err(res, O_REAL, S.real, unsure - unsure % 2, MM_ERR_BOUND);
    if (unsure > 1)
        sr->text = mm_res_printf(res, "%d of them within their error of the real axis: between %d and %d real roots",
                                 unsure, S.real - (unsure - unsure % 2), S.real);
    else
        sr->exact = 1;
    mm_res_scalar_err(res, O_MAXERR, S.max_err, 0.5 * S.max_err, MM_ERR_ESTIMATE);

    if (d == 0) {
        mm_res_warn(res, "p is a nonzero constant: it has no roots");
        mm_res_method(res, "none needed (degree 0)", 0);
        return MM_OK;
    }

    /* check 1: each root is the exact root of a polynomial whose
     * coefficients differ from p's by a few eps (backward error); Horner's
     * own rounding is at most 2d u of the scale (Higham, eq. 5.3) */
    double btol = (2.0 * d + 4) * DBL_EPSILON;
    mm_res_check_abs(res, "worst backward error |p(z)| / sum |p_k| |z|^k over the roots", S.backward, 0, btol);
    if (S.backward > btol)
        mm_res_warn(res, "some roots are not roots of p to working precision (backward error %.2g): the "
                    "coefficients span too many orders of magnitude for the companion matrix, and roots of very "
                    "different sizes cannot all be resolved", S.backward);

    /* check 2: Vieta, sum of the roots = -p_2 / p_1 (eq. 4) */
    mm_res_check_abs(res, "Vieta: sum of the roots = -p(2)/p(1)", S.sum, S.sum_ref, S.sum_tol);
    /* check 3: product of the roots = (-1)^d p_(d+1) / p_1, on log |.| so that
     * it cannot overflow; skipped with exact zero roots (product 0 = p_(d+1)) */
    if (S.zeros == 0)
        mm_res_check_abs(res, "Vieta: log |product of the roots| = log |p(d+1)/p(1)|", S.logprod, S.logprod_ref,
                         S.logprod_tol);

    mm_res_method(res, "eigenvalues of the companion matrix (LAPACK dgeev), Newton polish in double-double", 0);
    mm_res_method_stat(res, "error_estimate", S.max_err);

    if (S.multiple)
        mm_res_warn(res, "%d roots form clusters (multiple roots, see the multiplicity column): a root of "
                    "multiplicity m is only determined to about eps^(1/m) of its size, here within %.2g; "
                    "the computed values are scattered around the true root%s", S.multiple, S.mult_err,
                    unsure > 1 ? ", and those whose error reaches the real axis are counted as real roots" : "");
    if (S.illcond)
        mm_res_warn(res, "%d simple root%s ill-conditioned: more than half of the digits are lost (error up to "
                    "%.2g); small changes of p move %s far", S.illcond, S.illcond > 1 ? "s are" : " is", S.ill_err,
                    S.illcond > 1 ? "them" : "it");
    /* p on the real axis, over the real parts of the roots and a margin */
    return mm_num_poly_curve(res, O_P, d + 1, q, roots, nr);
}

static const char *const references[] = {
    "A. Edelman, H. Murakami, Polynomial roots from companion matrix eigenvalues, Math. Comp. 64 (1995) 763-776",
    "J. H. Wilkinson, Rounding Errors in Algebraic Processes, Prentice-Hall 1963, ch. 2",
    "N. J. Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed., SIAM 2002, ch. 5",
    NULL,
};

const mm_exercise mm_ex_num_poly_roots = {
    .id = "num-poly-roots", .chapter = 1, .section = "1.4.2", .title = "Roots of a polynomial",
    .summary = "All real and complex roots of a polynomial like MATLAB's roots(p), each with its error estimate.",
    .tags = "polynomial, roots, companion matrix, conditioning, multiple roots",
    .theory = "exercises/num/poly_roots.md", .params = params, .n_params = MM_COUNT(params), .outputs = outputs,
    .n_outputs = MM_COUNT(outputs), .references = references, .solve = solve,
};
