/* mm_poly.h — polynomials: evaluation, roots, least-squares fit.
 *
 * Coefficient order is MATLAB's, highest power first:
 *     p(x) = p[0] x^d + p[1] x^(d-1) + ... + p[d],   ncoef = d + 1.
 * Pure numerics: no globals, safe from many threads, every array is owned by
 * the caller and never kept after a call returns.  Fallible functions return
 * MM_OK or an MM_E* code and fill err (may be NULL).  NULL pointers for
 * required arguments are programmer errors (assert).
 *
 * Accuracy is reported, not hidden.  A root of a polynomial can be very
 * sensitive to its coefficients (Wilkinson's (x-1)(x-2)...(x-20) is the
 * classic) and a root of multiplicity m can only be found to about eps^(1/m)
 * in double precision.  mm_poly_roots therefore returns with each root an
 * error estimate that accounts for the rounding of the coefficients
 * themselves (each known only to a relative eps/2, as after reading them
 * from decimal text), and flags clusters of roots as (numerically) multiple.
 */
#ifndef MM_POLY_H
#define MM_POLY_H

#include "mm_status.h"

#define MM_POLY_MAX_DEGREE     200    /* largest degree for mm_poly_roots */
#define MM_POLY_MAX_FIT_DEGREE 30     /* largest degree for mm_poly_fit */
#define MM_POLY_MAX_POINTS     100000 /* most data points for mm_poly_fit */

/* p(x) by Horner's rule.  ncoef >= 1.  If err_bound is not NULL it receives
 * a running rounding-error bound (Higham, "Accuracy and Stability of
 * Numerical Algorithms", 2nd ed., Alg. 5.1): |computed - exact p(x)| <=
 * *err_bound for the given (double) coefficients and x.  Cannot fail
 * (non-finite input gives a non-finite result). */
double mm_poly_eval(int ncoef, const double *p, double x, double *err_bound);

/* The backward error of z = zr + i zi as a root of p: |p(z)| divided by
 * sum |p_k| |z|^(d-k) (the most a relative change of eps in every p_k can
 * move p(z)), both computed divided by max(1, |z|)^d so that nothing
 * overflows for large roots (for |z| > 1 Horner runs on the reversed
 * coefficients in 1/z).  0 <= result; a few eps for a root computed to
 * working precision.  |p(z)| itself when every coefficient is zero. */
double mm_poly_backward_error(int ncoef, const double *p, double zr, double zi);

/* ---- roots ------------------------------------------------------------------ */

enum {
    MM_POLY_ROOT_MULTIPLE = 1, /* part of a cluster of roots that cannot be
                                  told apart: a multiple root, or roots closer
                                  together than their error estimates */
    MM_POLY_ROOT_ILLCOND  = 2  /* err > 1e-8 * max(|root|, 1): at least half
                                  of the 16 digits are lost */
};

typedef struct mm_poly_root {
    double re, im;     /* the root re + i im; complex roots come in
                          conjugate pairs, im > 0 first */
    double err;        /* estimated bound on |computed root - exact root|:
                          first-order perturbation theory for a simple root,
                          |p(z)| + eps/2 * sum |p_k| |z|^k over |p'(z)|; for a
                          cluster of m roots, distance to the cluster's centre
                          plus (m! (that same numerator) / |p^(m)|)^(1/m) */
    double cond;       /* err / (eps/2 * |z|): how much the relative rounding
                          of the coefficients is amplified in this root
                          (err / (eps/2) for z = 0); the relative condition
                          number for a simple root */
    int multiplicity;  /* number of roots in this root's cluster (1 = simple) */
    int flags;         /* MM_POLY_ROOT_* bits */
} mm_poly_root;

/* All roots of p (ncoef coefficients, highest power first).
 *   - Leading zero coefficients are dropped (they lower the degree).
 *   - Trailing zero coefficients give exact zero roots (err 0), counted with
 *     their multiplicity.
 *   - The other roots are the eigenvalues of the companion matrix (LAPACK
 *     dgeev, balanced), each then polished by a few Newton steps on the
 *     original polynomial, evaluated in double-double (compensated) complex
 *     arithmetic; a step is kept only if it lowers |p| and stays within half
 *     the distance to the nearest other root (so two roots never merge).
 * roots must have room for ncoef - 1 entries; *nroots receives the number
 * found (the degree after dropping leading zeros).  Order: by decreasing
 * modulus, then decreasing real part, then decreasing imaginary part (the
 * order MATLAB's roots usually shows; zero roots last).
 * Fails with:
 *   MM_ERANGE  ncoef outside 1..MM_POLY_MAX_DEGREE+1 ("p");
 *   MM_EVALUE  a non-finite coefficient, or all coefficients zero (every
 *              x would be a root) ("p");
 *   MM_ENOCONV, MM_ENOMEM, MM_EINTERNAL from the eigenvalue solver. */
int mm_poly_roots(int ncoef, const double *p, mm_poly_root *roots, int *nroots,
                  mm_error *err);

/* ---- least-squares fit ------------------------------------------------------ */

typedef struct mm_poly_fit_info {
    double rms;        /* sqrt(sum r_i^2 / n), r_i = y_i - p(x_i) */
    double mu, scale;  /* the fit is computed in t = (x - mu) / scale:
                          mu = mean of x, scale = max |x - mu| (1 if 0) */
    int rank;          /* numerical rank of the scaled Vandermonde matrix; <
                          degree + 1 means the data cannot fix all
                          coefficients (the minimum-norm fit is returned) */
    double cond;       /* 2-norm condition number of the scaled Vandermonde */
} mm_poly_fit_info;

/* Least-squares polynomial of the given degree through the npts points
 * (x[i], y[i]), like MATLAB's polyfit: p[degree + 1] receives the
 * coefficients highest power first, in the ORIGINAL variable x.  The fit
 * itself is done on centred and scaled t = (x - mu)/scale (far better
 * conditioned), by SVD least squares, and the coefficients are then
 * expanded back to x.  x, y are not modified; info may be NULL.
 * Fails with:
 *   MM_ERANGE  npts outside 1..MM_POLY_MAX_POINTS ("x"); degree outside
 *              0..MM_POLY_MAX_FIT_DEGREE, or degree >= the number of
 *              distinct x values ("degree");
 *   MM_EVALUE  a non-finite x or y ("x", "y");
 *   MM_ENOCONV, MM_ENOMEM, MM_EINTERNAL from the least-squares solver. */
int mm_poly_fit(int npts, const double *x, const double *y, int degree,
                double *p, mm_poly_fit_info *info, mm_error *err);

/* The fitted values p(x_i) of the least-squares polynomial, in double, two
 * ways in t = (x - mu) / scale: fit_svd by the SVD (as mm_poly_fit does),
 * fit_ne by the normal equations (A^T A) a = A^T y solved by LU, whose
 * error grows with cond(A)^2 instead of cond(A).  *bnorm_svd, *bnorm_ne
 * receive the 2-norms of the two coefficient vectors in t (for error
 * bounds).  A second solution for checks; npts, degree as mm_poly_fit
 * (degree <= MM_POLY_MAX_FIT_DEGREE).  Fails with MM_ERANGE, MM_EVALUE,
 * MM_ESINGULAR (A^T A singular in double), MM_ENOMEM. */
int mm_poly_fit_values(int npts, const double *x, const double *y, int degree, double mu, double scale,
                       double *fit_svd, double *fit_ne, double *bnorm_svd, double *bnorm_ne, mm_error *err);

/* ---- the same fit, every digit: double-double ----------------------------- */

#define MM_POLY_MAX_FIT_DD_DEGREE 15   /* largest degree for mm_poly_fit_dd */

typedef struct mm_poly_fit_dd_info {
    double mu;         /* t = (x - mu) / scale: mu the mean of x (as computed in double) */
    double scale;      /* a power of 2 >= max |x - mu| (1 if 0), so t is exact in double-double */
    double cond, cond_err;  /* 2-norm condition number of the Vandermonde matrix in
                               (x - mu) / max |x - mu|, with its bound */
    double rms, rms_err;    /* sqrt(sum r_i^2 / n) with its bound */
    int dof;           /* degrees of freedom left, npts - degree - 1 */
} mm_poly_fit_dd_info;

/* The least-squares polynomial of mm_poly_fit, computed in double-double
 * (Householder QR on the Vandermonde matrix in t, then expanded to powers
 * of x), each number rounded to double with its bound:
 *   c[degree + 1], c_err: coefficients, highest power first, as MATLAB's
 *     polyfit; |c[k] - c_exact[k]| <= c_err[k], where c_exact is the exact
 *     least-squares solution for the given doubles;
 *   fit[npts], fit_err: p(x_i), and the same bound for y_i - p(x_i);
 *   se[degree + 1] (may be NULL): the standard error of each coefficient
 *     from the scatter of the data, sigma sqrt(diag((A^T A)^-1)) with
 *     sigma^2 = sum r_i^2 / dof (0 when dof = 0): a statistical estimate,
 *     not a rounding error;
 *   bt[degree + 1] (may be NULL): the coefficients in t, highest first, for
 *     evaluating p(x) = sum bt t^k without the cancellation of powers of x.
 * The bounds of the QR step use the standard backward error of Householder
 * QR (a multiple n m of the double-double unit) through Wedin's
 * perturbation bound with the certified cond; they are far below a double's
 * rounding unless cond(A) passes ~1e15 or the powers of x cancel.
 * Fails as mm_poly_fit (degree limit MM_POLY_MAX_FIT_DD_DEGREE), and with
 * MM_ESINGULAR ("x") when the Vandermonde matrix is singular to ~32 digits. */
int mm_poly_fit_dd(int npts, const double *x, const double *y, int degree, double *c, double *c_err,
                   double *fit, double *fit_err, double *se, double *bt, mm_poly_fit_dd_info *info,
                   mm_error *err);

#endif
