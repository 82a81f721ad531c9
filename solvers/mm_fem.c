/* mm_fem.c — 1-D bar and beam finite elements, modal analysis, and the
 * closed-form frequencies of the uniform continua (see mm_fem.h).
 */
#include "mm_fem.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "mm_linalg.h"
#include "mm_mdof.h"
#include "mm_newmark.h"

static const double PI = 3.14159265358979323846;

/* ==== checks ============================================================== */

static int dofs_per_node(mm_fem_kind kind) { return kind == MM_FEM_BEAM ? 2 : 1; }
static int half_band(mm_fem_kind kind) { return kind == MM_FEM_BEAM ? 3 : 1; }

static const char *bc_name(mm_fem_bc bc)
{
    switch (bc) {
    case MM_FEM_FIXED_FREE:    return "fixed-free";
    case MM_FEM_FIXED_FIXED:   return "fixed-fixed";
    case MM_FEM_FREE_FREE:     return "free-free";
    case MM_FEM_PINNED_PINNED: return "pinned-pinned";
    case MM_FEM_FIXED_PINNED:  return "fixed-pinned";
    }
    return "?";
}

/* One property: finite and > 0.  idx < 0 for a uniform mesh. */
static int check_prop(const char *name, double v, long idx, mm_error *err)
{
    if (isfinite(v) && v > 0)
        return MM_OK;
    if (idx < 0)
        return mm_error_set(err, MM_EVALUE, name,
                            "%s must be a finite number > 0; got %g", name, v);
    return mm_error_set(err, MM_EVALUE, "elements",
                        "element %ld: %s must be a finite number > 0; got %g",
                        idx + 1, name, v);
}

static int check_element(mm_fem_kind kind, const mm_fem_element *el, long idx,
                         mm_error *err)
{
    int rc;
    if ((rc = check_prop("L", el->L, idx, err)) ||
        (rc = check_prop("E", el->E, idx, err)) ||
        (rc = check_prop("A", el->A, idx, err)) ||
        (rc = check_prop("rho", el->rho, idx, err)))
        return rc;
    if (kind == MM_FEM_BEAM)
        return check_prop("I", el->I, idx, err);
    return MM_OK;
}

int mm_fem_check(const mm_fem_problem *p, mm_error *err)
{
    if (p->kind != MM_FEM_BAR && p->kind != MM_FEM_BEAM)
        return mm_error_set(err, MM_EVALUE, "kind",
                            "kind must be bar or beam; got code %d", (int)p->kind);
    if ((unsigned)p->bc > MM_FEM_FIXED_PINNED)
        return mm_error_set(err, MM_EVALUE, "bc",
                            "unknown boundary condition code %d", (int)p->bc);
    if (p->kind == MM_FEM_BAR && p->bc >= MM_FEM_PINNED_PINNED)
        return mm_error_set(err, MM_EVALUE, "bc",
                            "bc '%s' is for beams; a bar end is fixed or free",
                            bc_name(p->bc));
    if (p->mass != MM_FEM_CONSISTENT && p->mass != MM_FEM_LUMPED)
        return mm_error_set(err, MM_EVALUE, "mass",
                            "mass must be consistent or lumped; got code %d",
                            (int)p->mass);
    if (p->kind == MM_FEM_BEAM && p->mass == MM_FEM_LUMPED)
        return mm_error_set(err, MM_EVALUE, "mass",
                            "lumped mass is offered for bars only: a beam's "
                            "lumped mass has no rotary inertia, so the mass "
                            "matrix would be singular; use consistent");
    if (p->n_el < 1 || p->n_el > MM_FEM_MAX_ELEMENTS)
        return mm_error_set(err, MM_ERANGE, "elements",
                            "elements must be between 1 and %d; got %zu",
                            MM_FEM_MAX_ELEMENTS, p->n_el);
    /* a mesh whose every DOF is fixed has nothing to vibrate */
    if (p->n_el == 1 && ((p->kind == MM_FEM_BAR && p->bc == MM_FEM_FIXED_FIXED) ||
                         (p->kind == MM_FEM_BEAM && p->bc == MM_FEM_FIXED_FIXED)))
        return mm_error_set(err, MM_ERANGE, "elements",
                            "a %s %s needs at least 2 elements: with one, "
                            "every node is fixed",
                            bc_name(p->bc), p->kind == MM_FEM_BAR ? "bar" : "beam");
    if (!p->elements)
        return check_element(p->kind, &p->uniform, -1, err);
    for (size_t e = 0; e < p->n_el; e++) {
        int rc = check_element(p->kind, &p->elements[e], (long)e, err);
        if (rc)
            return rc;
    }
    return MM_OK;
}

void mm_fem_options_init(mm_fem_options *opt)
{
    opt->method = MM_FEM_AUTO;
    opt->rigid_tol = 1e-16;
}

size_t mm_fem_ndof(const mm_fem_problem *p)
{
    return (p->n_el + 1) * (size_t)dofs_per_node(p->kind);
}

/* Element e of the mesh (a uniform mesh cuts uniform.L into n_el). */
static mm_fem_element element_at(const mm_fem_problem *p, size_t e)
{
    if (p->elements)
        return p->elements[e];
    mm_fem_element el = p->uniform;
    el.L = p->uniform.L / (double)p->n_el;
    return el;
}

void mm_fem_node_x(const mm_fem_problem *p, double *x)
{
    x[0] = 0.0;
    for (size_t e = 0; e < p->n_el; e++)
        x[e + 1] = p->elements ? x[e] + p->elements[e].L
                               : p->uniform.L * (double)(e + 1) / (double)p->n_el;
}

/* ==== element matrices ===================================================== */

/* k, m of one valid element, row-major, 2x2 or 4x4. */
static void element_km(mm_fem_kind kind, mm_fem_mass mass,
                       const mm_fem_element *el, double *k, double *m)
{
    double L = el->L;
    if (kind == MM_FEM_BAR) {
        double s = el->E * el->A / L, mt = el->rho * el->A * L;
        k[0] = s;  k[1] = -s;
        k[2] = -s; k[3] = s;
        if (mass == MM_FEM_LUMPED) {      /* half the mass at each node */
            m[0] = mt / 2; m[1] = 0;
            m[2] = 0;      m[3] = mt / 2;
        } else {                          /* integral of rho A N^T N dx */
            m[0] = mt / 3; m[1] = mt / 6;
            m[2] = mt / 6; m[3] = mt / 3;
        }
        return;
    }
    double s = el->E * el->I / (L * L * L), L2 = L * L;
    const double kk[16] = {
        12,     6 * L,  -12,    6 * L,
        6 * L,  4 * L2, -6 * L, 2 * L2,
        -12,    -6 * L, 12,     -6 * L,
        6 * L,  2 * L2, -6 * L, 4 * L2,
    };
    double c = el->rho * el->A * L / 420;
    const double mm[16] = {
        156,     22 * L,  54,      -13 * L,
        22 * L,  4 * L2,  13 * L,  -3 * L2,
        54,      13 * L,  156,     -22 * L,
        -13 * L, -3 * L2, -22 * L, 4 * L2,
    };
    for (int i = 0; i < 16; i++) {
        k[i] = s * kk[i];
        m[i] = c * mm[i];
    }
}

int mm_fem_element_matrices(mm_fem_kind kind, mm_fem_mass mass,
                            const mm_fem_element *el, double *k, double *m,
                            mm_error *err)
{
    mm_fem_problem p = {kind, MM_FEM_FIXED_FREE, mass, 1, *el, NULL};
    int rc = mm_fem_check(&p, err);
    if (rc)
        return rc;
    element_km(kind, mass, el, k, m);
    return MM_OK;
}

/* Largest eigenvalue of a 2x2 pencil (k, m) whose k is singular: the other
 * eigenvalue is 0, so the largest is the trace of m^-1 k. */
static double pencil2_top(double k00, double k01, double k11, double m00,
                          double m01, double m11)
{
    return (k00 * m11 + k11 * m00 - 2 * k01 * m01) / (m00 * m11 - m01 * m01);
}

/* u^T a v for 4x4 row-major a. */
static double form4(const double *a, const double *u, const double *v)
{
    double s = 0;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            s += u[i] * a[4 * i + j] * v[j];
    return s;
}

/* Largest eigenvalue of the free element (k, m), in closed form.  A beam
 * element is symmetric about its centre, so (k, m) split into a symmetric
 * block (w1 = w2, theta1 = -theta2) and an antisymmetric one (w1 = -w2,
 * theta1 = theta2), each 2x2 with one rigid mode (translation, rotation). */
static double element_top(mm_fem_kind kind, mm_fem_mass mass,
                          const mm_fem_element *el)
{
    double k[16], m[16];
    element_km(kind, mass, el, k, m);
    if (kind == MM_FEM_BAR)
        return pencil2_top(k[0], k[1], k[3], m[0], m[1], m[3]);
    static const double s1[4] = {1, 0, 1, 0}, s2[4] = {0, 1, 0, -1};
    static const double a1[4] = {1, 0, -1, 0}, a2[4] = {0, 1, 0, 1};
    double ls = pencil2_top(form4(k, s1, s1), form4(k, s1, s2), form4(k, s2, s2),
                            form4(m, s1, s1), form4(m, s1, s2), form4(m, s2, s2));
    double la = pencil2_top(form4(k, a1, a1), form4(k, a1, a2), form4(k, a2, a2),
                            form4(m, a1, a1), form4(m, a1, a2), form4(m, a2, a2));
    return fmax(ls, la);
}

/* ==== assembly ============================================================= */

/* Global DOFs the boundary condition removes; returns how many (<= 4). */
static size_t fixed_dofs(const mm_fem_problem *p, size_t *fixed)
{
    size_t last = p->n_el;            /* node at x = L */
    if (p->kind == MM_FEM_BAR)
        switch (p->bc) {
        case MM_FEM_FIXED_FREE:  fixed[0] = 0; return 1;
        case MM_FEM_FIXED_FIXED: fixed[0] = 0; fixed[1] = last; return 2;
        default:                 return 0;
        }
    switch (p->bc) {
    case MM_FEM_FIXED_FREE:       /* w = theta = 0 at x = 0 */
        fixed[0] = 0; fixed[1] = 1; return 2;
    case MM_FEM_FIXED_FIXED:
        fixed[0] = 0; fixed[1] = 1; fixed[2] = 2 * last; fixed[3] = 2 * last + 1;
        return 4;
    case MM_FEM_PINNED_PINNED:    /* w = 0 at both ends, rotations free */
        fixed[0] = 0; fixed[1] = 2 * last; return 2;
    case MM_FEM_FIXED_PINNED:
        fixed[0] = 0; fixed[1] = 1; fixed[2] = 2 * last; return 3;
    default:
        return 0;
    }
}

/* Rigid-body modes the boundary condition leaves (how many to ask beyond
 * the elastic ones from the selective solver; the count reported comes
 * from the eigenvalues themselves). */
static size_t rigid_possible(const mm_fem_problem *p)
{
    if (p->bc != MM_FEM_FREE_FREE)
        return 0;
    return p->kind == MM_FEM_BEAM ? 2 : 1;
}

/* Assemble K and M on the free DOFs into band storage (mm_linalg layout:
 * Ab[i*(kd+1) + d] = A(i, i+d)), zeroed first.  map[g] is the free index
 * of global DOF g or -1.  Also returns the largest element eigenvalue. */
static double assemble_band(const mm_fem_problem *p, const long *map, size_t nf,
                            int kd, double *Kb, double *Mb)
{
    int nd = 2 * dofs_per_node(p->kind), dpn = dofs_per_node(p->kind);
    size_t w = (size_t)kd + 1;
    double k[16], m[16], top = 0;
    memset(Kb, 0, nf * w * sizeof *Kb);
    memset(Mb, 0, nf * w * sizeof *Mb);
    for (size_t e = 0; e < p->n_el; e++) {
        mm_fem_element el = element_at(p, e);
        element_km(p->kind, p->mass, &el, k, m);
        if (e == 0 || p->elements)    /* uniform: all elements alike */
            top = fmax(top, element_top(p->kind, p->mass, &el));
        long f[4];
        for (int a = 0; a < nd; a++)
            f[a] = map[e * (size_t)dpn + (size_t)a];
        for (int a = 0; a < nd; a++)
            for (int b = 0; b < nd; b++) {
                if (f[a] < 0 || f[b] < 0 || f[b] < f[a])
                    continue;         /* fixed, or below the diagonal */
                size_t at = (size_t)f[a] * w + (size_t)(f[b] - f[a]);
                Kb[at] += k[nd * a + b];
                Mb[at] += m[nd * a + b];
            }
    }
    return top;
}

size_t mm_fem_free_dofs(const mm_fem_problem *p, long *map)
{
    size_t ndof = mm_fem_ndof(p), fixed[4], nfix = fixed_dofs(p, fixed);
    for (size_t g = 0; g < ndof; g++)
        map[g] = 0;
    for (size_t i = 0; i < nfix; i++)
        map[fixed[i]] = -1;
    long next = 0;
    for (size_t g = 0; g < ndof; g++)
        map[g] = map[g] < 0 ? -1 : next++;
    return (size_t)next;
}

int mm_fem_half_band(const mm_fem_problem *p, size_t nf)
{
    int kd = half_band(p->kind);
    return (size_t)kd >= nf ? (int)nf - 1 : kd;
}

double mm_fem_assemble_band(const mm_fem_problem *p, const long *map, size_t nf,
                            double *Kb, double *Mb)
{
    return assemble_band(p, map, nf, mm_fem_half_band(p, nf), Kb, Mb);
}

/* Dense symmetric n x n from band storage. */
static void band_to_dense(size_t n, int kd, const double *Ab, double *A)
{
    size_t w = (size_t)kd + 1;
    memset(A, 0, n * n * sizeof *A);
    for (size_t i = 0; i < n; i++)
        for (size_t d = 0; d < w && i + d < n; d++)
            A[i * n + i + d] = A[(i + d) * n + i] = Ab[i * w + d];
}

/* ==== modal analysis ======================================================= */

/* phi^T K phi and phi^T M phi of a full-DOF vector, element by element.
 * The strain energy comes from strains, not from the matrix product: for a
 * smooth mode the entries of K phi cancel to a tiny remainder, and that
 * cancellation costs eps * n^4 (beam) of relative accuracy, while the
 * curvature w'' of each element, computed from nodal differences, loses
 * only eps * n^2.  w'' is linear along a Hermite element, from k0 to k1:
 * int (w'')^2 dx = L (k0^2 + k0 k1 + k1^2) / 3. */
static void rayleigh(const mm_fem_problem *p, const double *phi, double *kk,
                     double *mm)
{
    int dpn = dofs_per_node(p->kind), nd = 2 * dpn;
    double k[16], m[16];
    mm_fem_element el = element_at(p, 0);
    element_km(p->kind, p->mass, &el, k, m);   /* once for a uniform mesh */
    *kk = *mm = 0;
    for (size_t e = 0; e < p->n_el; e++) {
        if (p->elements && e > 0) {
            el = element_at(p, e);
            element_km(p->kind, p->mass, &el, k, m);
        }
        const double *v = phi + e * (size_t)dpn;
        double h = el.L;
        for (int a = 0; a < nd; a++)
            for (int b = 0; b < nd; b++)
                *mm += v[a] * m[nd * a + b] * v[b];
        if (p->kind == MM_FEM_BAR) {
            double du = v[1] - v[0];          /* strain times L */
            *kk += el.E * el.A / h * du * du;
        } else {
            double s = (v[2] - v[0]) / h;     /* chord slope */
            double k0 = (6 * s - 4 * v[1] - 2 * v[3]) / h;
            double k1 = (-6 * s + 2 * v[1] + 4 * v[3]) / h;
            *kk += el.E * el.I * h * (k0 * k0 + k0 * k1 + k1 * k1) / 3;
        }
    }
}

static mm_fem_method pick_method(mm_fem_method asked, size_t nf, size_t nev, int rigid)
{
    if (asked != MM_FEM_AUTO)
        return asked;
    /* Lanczos costs O(nf nev^2), dense O(nf^3): Lanczos wins from the
     * smallest meshes on (bench: the first mode of 8 free DOFs in 4 us
     * against 21 us, of 32 in 7 us against 86) unless a third of the
     * modes or more are wanted */
    int few = nf > MM_LINALG_MAX_N || (nf > 6 && 3 * nev < nf);
    (void)rigid;
    return few ? MM_FEM_LANCZOS : MM_FEM_DENSE;
}

/* What AUTO falls back to when Lanczos fails. */
static mm_fem_method fallback_method(size_t nev, int rigid)
{
    return !rigid && nev <= 20 ? MM_FEM_SUBSPACE : MM_FEM_BANDED;
}

/* Banded symmetric algebra, defined below with the transient drivers. */
static void band_matvec(size_t n, int kd, const double *Ab, const double *x, double *y);
static size_t band_cholesky(size_t n, int kd, double *Ab);
static void band_chol_solve(size_t n, int kd, const double *Ub, int diag, double *x);

/* The nwant lowest eigenpairs of the banded pencil (Kb, Mb), K positive
 * definite, by subspace iteration (K. J. Bathe, Finite Element Procedures,
 * sec. 11.6): X <- K^-1 M X, then the Ritz step on its span, until the
 * wanted Ritz values stop changing.  lambda[nwant], V (nf x nwant,
 * row-major, mass-normalised).  MM_ESINGULAR when K is not positive
 * definite, MM_ENOCONV when 300 iterations do not settle. */
static int subspace(size_t nf, int kd, const double *Kb, const double *Mb, size_t nwant,
                    double *lambda, double *V, mm_error *err)
{
    size_t w = (size_t)kd + 1, p = nwant + nwant / 2 + 4;
    if (p > nf)
        p = nf;
    int rc = MM_OK;
    double *Kc = malloc(nf * w * sizeof *Kc), *X = malloc(nf * p * sizeof *X), *Y = malloc(nf * p * sizeof *Y);
    double *Z = malloc(nf * p * sizeof *Z), *Kr = malloc(p * p * sizeof *Kr), *Mr = malloc(p * p * sizeof *Mr);
    double *Q = malloc(p * p * sizeof *Q), *lam = malloc(p * sizeof *lam), *prev = malloc(p * sizeof *prev);
    if (!Kc || !X || !Y || !Z || !Kr || !Mr || !Q || !lam || !prev) {
        rc = mm_error_set(err, MM_ENOMEM, NULL, "out of memory");
        goto out;
    }
    memcpy(Kc, Kb, nf * w * sizeof *Kc);
    if (band_cholesky(nf, kd, Kc)) {
        rc = mm_error_set(err, MM_ESINGULAR, "bc", "the stiffness matrix is not positive definite");
        goto out;
    }
    uint64_t st = UINT64_C(0x9E3779B97F4A7C15);        /* a fixed, irregular start */
    for (size_t j = 0; j < p; j++)
        for (size_t i = 0; i < nf; i++) {
            st ^= st << 13, st ^= st >> 7, st ^= st << 17;
            X[j * nf + i] = j == 0 ? 1.0 : (double)(st >> 11) / 9007199254740992.0 - 0.5;
        }
    int settled = 0;
    for (size_t j = 0; j < p; j++)                     /* Y = M X */
        band_matvec(nf, kd, Mb, X + j * nf, Y + j * nf);
    for (int it = 0;; it++) {
        for (size_t j = 0; j < p; j++) {               /* Z = K^-1 Y, X <- M Z */
            memcpy(Z + j * nf, Y + j * nf, nf * sizeof *Z);
            band_chol_solve(nf, kd, Kc, 0, Z + j * nf);
            band_matvec(nf, kd, Mb, Z + j * nf, X + j * nf);
        }
        for (size_t a = 0; a < p; a++)                 /* Kr = Z^T K Z = Z^T (old Y), Mr = Z^T M Z */
            for (size_t b = a; b < p; b++) {
                double sk = 0, sm = 0;
                for (size_t i = 0; i < nf; i++) {
                    sk += Z[a * nf + i] * Y[b * nf + i];
                    sm += Z[a * nf + i] * X[b * nf + i];
                }
                Kr[a * p + b] = Kr[b * p + a] = sk;
                Mr[a * p + b] = Mr[b * p + a] = sm;
            }
        for (size_t a = 0; a < p; a++)                 /* symmetric to rounding: make it exact */
            for (size_t b = a + 1; b < p; b++)
                Kr[a * p + b] = Kr[b * p + a] = 0.5 * (Kr[a * p + b] + Kr[b * p + a]);
        mm_error e2;
        if ((rc = mm_linalg_sygv((int)p, Kr, Mr, lam, Q, &e2))) {
            rc = mm_error_set(err, rc == MM_ESINGULAR ? MM_ENOCONV : rc, NULL, "subspace iteration: %s", e2.msg);
            goto out;
        }
        /* the new vectors Z Q, and their M products (M Z) Q for the next
         * round: Y <- (M Z) Q, Z <- Z Q (Z Q into Y's old place first) */
        for (size_t j = 0; j < p; j++)
            for (size_t i = 0; i < nf; i++) {
                double sum = 0;
                for (size_t k = 0; k < p; k++)
                    sum += Z[k * nf + i] * Q[k * p + j];
                Y[j * nf + i] = sum;
            }
        double *t = Z;
        Z = Y, Y = t;                                  /* Z: the Ritz vectors */
        for (size_t j = 0; j < p; j++)
            for (size_t i = 0; i < nf; i++) {
                double sum = 0;
                for (size_t k = 0; k < p; k++)
                    sum += X[k * nf + i] * Q[k * p + j];
                Y[j * nf + i] = sum;
            }
        /* settled: the wanted Ritz values change by less than 1e-10 twice
         * running (they then jitter at ~1e-12, their rounding; the modes
         * are good to ~1e-6 and the Rayleigh quotients the caller takes
         * of them to ~1e-12) */
        double change = 0;
        for (size_t j = 0; j < nwant && it > 0; j++)
            change = fmax(change, fabs(lam[j] - prev[j]) / fabs(lam[j]));
        memcpy(prev, lam, p * sizeof *lam);
        settled = it > 0 && change <= 1e-10 ? settled + 1 : 0;
        if (settled == 2)
            break;
        if (it == 300) {
            rc = mm_error_set(err, MM_ENOCONV, NULL, "subspace iteration did not settle");
            goto out;
        }
    }
    for (size_t j = 0; j < nwant; j++) {
        lambda[j] = lam[j];
        for (size_t i = 0; i < nf; i++)
            V[i * nwant + j] = Z[j * nf + i];
    }
out:
    free(prev);
    free(lam);
    free(Q);
    free(Mr);
    free(Kr);
    free(Z);
    free(Y);
    free(X);
    free(Kc);
    return rc;
}

/* Banded LDL^T of A - sigma B without pivoting (A, B symmetric bands of the
 * same kd): returns the number of negative pivots, the number of
 * eigenvalues of A v = lambda B v below sigma (Sylvester's law of inertia:
 * the Sturm sequence check of Bathe, sec. 11.4.3), or -1 when a pivot is 0
 * or not finite.  G (n*(kd+1)) is scratch. */
static long band_sturm(size_t n, int kd, const double *A, const double *B, double sigma, double *G)
{
    size_t w = (size_t)kd + 1;
    long neg = 0;
    for (size_t i = 0; i < n * w; i++)
        G[i] = A[i] - sigma * B[i];
    /* G[k*w] = d_k, G[k*w + d] = l_{k+d,k} once row k is done */
    for (size_t i = 0; i < n; i++) {
        double *gi = G + i * w;
        size_t k0 = i > (size_t)kd ? i - (size_t)kd : 0;
        double d = gi[0];
        for (size_t k = k0; k < i; k++)
            d -= G[k * w + (i - k)] * G[k * w + (i - k)] * G[k * w];
        if (!(d != 0) || !isfinite(d))
            return -1;
        neg += d < 0;
        gi[0] = d;
        for (size_t dj = 1; dj < w && i + dj < n; dj++) {
            size_t j = i + dj;
            double sum = gi[dj];
            for (size_t k = j > (size_t)kd ? j - (size_t)kd : 0; k < i; k++)
                sum -= G[k * w + (i - k)] * G[k * w + (j - k)] * G[k * w];
            gi[dj] = sum / d;
        }
    }
    return neg;
}

/* The rigid-body motions of a free-free member on its free DOFs (all of
 * them), M-orthonormal: a bar's translation u = 1; a beam's translation
 * (w = 1, theta = 0) and rotation about its centre (w = x - xc, theta = 1),
 * which the elements represent exactly (K R = 0 to rounding).  R is nrig x
 * nf, MR = M R.  Returns 0, or -1 without memory. */
static int rigid_basis(const mm_fem_problem *p, size_t nf, int kd, const double *Mb, size_t nrig,
                       double *R, double *MR)
{
    double *x = malloc((p->n_el + 1) * sizeof *x);
    if (!x)
        return -1;
    mm_fem_node_x(p, x);
    memset(R, 0, nrig * nf * sizeof *R);
    double xc = 0.5 * (x[0] + x[p->n_el]);
    size_t dpn = (size_t)dofs_per_node(p->kind);
    for (size_t i = 0; i < nf; i++) {      /* free-free: free DOF i = global DOF i */
        size_t node = i / dpn, dof = i % dpn;
        R[i] = dof == 0 ? 1.0 : 0.0;
        if (nrig > 1)
            R[nf + i] = dof == 0 ? x[node] - xc : 1.0;
    }
    free(x);
    for (size_t a = 0; a < nrig; a++) {    /* Gram-Schmidt in the M inner product */
        double *r = R + a * nf, *mr = MR + a * nf;
        for (size_t b = 0; b < a; b++) {
            double c = 0;
            for (size_t i = 0; i < nf; i++)
                c += MR[b * nf + i] * r[i];
            for (size_t i = 0; i < nf; i++)
                r[i] -= c * R[b * nf + i];
        }
        band_matvec(nf, kd, Mb, r, mr);
        double nn = 0;
        for (size_t i = 0; i < nf; i++)
            nn += r[i] * mr[i];
        nn = 1 / sqrt(nn);
        for (size_t i = 0; i < nf; i++)
            r[i] *= nn, mr[i] *= nn;
    }
    return 0;
}

/* Remove from r its M-components along the nb M-orthonormal vectors B
 * (MB = M B), classical Gram-Schmidt twice ("twice is enough", Parlett):
 * full reorthogonalisation.  c (nb doubles) is scratch.  Each pass forms
 * every coefficient first (MB^T r, four partial sums per product), then
 * subtracts B c: two sweeps over the basis instead of one per vector. */
static void m_orthogonalise(size_t nf, size_t nb, const double *B, const double *MB, double *r, double *c)
{
    for (int pass = 0; pass < 2; pass++) {
        for (size_t b = 0; b < nb; b++) {
            const double *mb = MB + b * nf;
            double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
            size_t i = 0;
            for (; i + 4 <= nf; i += 4) {
                s0 += mb[i] * r[i];
                s1 += mb[i + 1] * r[i + 1];
                s2 += mb[i + 2] * r[i + 2];
                s3 += mb[i + 3] * r[i + 3];
            }
            for (; i < nf; i++)
                s0 += mb[i] * r[i];
            c[b] = (s0 + s1) + (s2 + s3);
        }
        for (size_t b = 0; b < nb; b++) {
            const double *bb = B + b * nf;
            double cb = c[b];
            for (size_t i = 0; i < nf; i++)
                r[i] -= cb * bb[i];
        }
    }
}

/* The nwant lowest eigenpairs of the banded pencil (Kb, Mb) by
 * shift-invert Lanczos (Ericsson and Ruhe 1980; Parlett, The Symmetric
 * Eigenvalue Problem, ch. 13): the Krylov space of K^-1 M in the M inner
 * product, whose largest eigenvalues theta = 1 / lambda are the wanted
 * ones and come out first, each Lanczos vector M-orthogonalised against
 * all the previous ones (full reorthogonalisation: the Ritz values then
 * carry no ghost copies).  A free-free member's nrig rigid-body modes are
 * known exactly (rigid_basis): they are deflated (every vector kept
 * M-orthogonal to them), so the repeated eigenvalue 0 never enters the
 * iteration, and K^-1 is taken on that complement by temporary supports
 * (the middle node held: M y orthogonal to the rigid motions is a
 * self-equilibrated load, the supported member carries it without
 * reactions).  Stops when every wanted Ritz pair's residual
 * |beta_k s_ki| (= ||K^-1 M y - theta y||_M) is at most 1e-10 theta;
 * each Ritz vector y then gets the implicit extra inverse-iteration step
 * y + beta_k s_ki / theta q_k+1 (= K^-1 M y / theta, no solve), which damps
 * its high-mode part by lambda_1 / lambda_j.  Last, a Sturm sequence check
 * (an LDL^T of K - sigma M just above the last wanted eigenvalue) proves
 * none was missed.  lambda[nwant] (rigid ones first, 0), V (nf x nwant,
 * row-major, M-orthonormal).  MM_ESINGULAR when the (supported) K is not
 * positive definite, MM_ENOCONV when 3 nwant + 30 vectors do not settle or
 * the Sturm count disagrees: the caller falls back to another solver. */
static int lanczos(const mm_fem_problem *p, size_t nf, int kd, const double *Kb, const double *Mb, size_t nrig,
                   size_t nwant, double *lambda, double *V, mm_error *err)
{
    size_t w = (size_t)kd + 1, ne = nwant - nrig, room = nf - nrig;
    size_t mmax = 3 * ne + 30 < room ? 3 * ne + 30 : room;
    int rc = MM_OK;
    /* the basis B = [R Q]: the rigid modes, then the Lanczos vectors, and
     * MB = M B; each new vector is orthogonalised against all of it at
     * once (R apart, its products with Q would bring R back) */
    double *Kc = malloc(nf * w * sizeof *Kc);
    double *B = malloc((nrig + mmax + 1) * nf * sizeof *B), *MB = malloc((nrig + mmax + 1) * nf * sizeof *MB);
    double *R = B, *MR = MB, *Q = B + nrig * nf, *MQ = MB + nrig * nf;
    double *al = malloc(mmax * sizeof *al), *be = malloc(mmax * sizeof *be), *th = malloc(mmax * sizeof *th);
    double *Z = malloc(mmax * mmax * sizeof *Z), *y = malloc((nf > nrig + mmax + 1 ? nf : nrig + mmax + 1) * sizeof *y);
    if (!Kc || !B || !MB || !al || !be || !th || !Z || !y ||
        (nrig && rigid_basis(p, nf, kd, Mb, nrig, R, MR))) {
        rc = mm_error_set(err, MM_ENOMEM, NULL, "out of memory");
        goto out;
    }
    memcpy(Kc, Kb, nf * w * sizeof *Kc);
    /* temporary supports: the middle node held (DOFs s0 .. s0 + nrig - 1;
     * free-free: free DOF = global DOF), its rows and columns taken out.
     * The middle, not an end: the two half-length cantilevers left are
     * 16 times stiffer than one of full length, and the rounding of the
     * solves grows with the compliance (an end support left mode 1 of a
     * 1000-element beam at 2e-10, the middle one at 1e-12) */
    size_t s0 = (size_t)dofs_per_node(p->kind) * (p->n_el / 2);
    if (nrig == 0)
        s0 = 0;
    for (size_t i = s0; i < s0 + nrig; i++) {
        for (size_t d = 1; d < w; d++) {
            Kc[i * w + d] = 0;                 /* row i, right of the diagonal */
            if (i >= d)
                Kc[(i - d) * w + d] = 0;       /* column i, above it */
        }
    }
    if (band_cholesky(nf, kd, Kc)) {
        rc = mm_error_set(err, MM_ESINGULAR, "bc", "the stiffness matrix is not positive definite");
        goto out;
    }
    /* the start: K^-1 M of a fixed irregular vector (already in the range
     * of the operator, so its high-mode part is damped once) */
    uint64_t st = UINT64_C(0x9E3779B97F4A7C15);
    size_t k = 0, off = 0;    /* Lanczos vectors so far; see below */
    for (size_t i = 0; i < nf; i++) {
        st ^= st << 13, st ^= st >> 7, st ^= st << 17;
        y[i] = 1.0 + (double)(st >> 11) / 9007199254740992.0;
    }
    band_matvec(nf, kd, Mb, y, Q);
    for (size_t i = s0; i < s0 + nrig; i++)
        Q[i] = 0;
    band_chol_solve(nf, kd, Kc, 0, Q);
    m_orthogonalise(nf, nrig, B, MB, Q, y);
    band_matvec(nf, kd, Mb, Q, MQ);
    int done = 0;
    while (!done) {
        /* normalise the newest vector q_k */
        double *qk = Q + k * nf, *mqk = MQ + k * nf, nn = 0;
        for (size_t i = 0; i < nf; i++)
            nn += qk[i] * mqk[i];
        double inv = 1 / sqrt(nn);
        for (size_t i = 0; i < nf; i++)
            qk[i] *= inv, mqk[i] *= inv;
        k++;
        /* r = K^-1 M q_k, minus its components along R and all of Q */
        double *r = Q + k * nf, *mr = MQ + k * nf;
        memcpy(r, mqk, nf * sizeof *r);
        for (size_t i = s0; i < s0 + nrig; i++)
            r[i] = 0;
        band_chol_solve(nf, kd, Kc, 0, r);
        double a = 0;
        for (size_t i = 0; i < nf; i++)
            a += mqk[i] * r[i];
        al[k - 1] = a;
        m_orthogonalise(nf, nrig + k, B, MB, r, y);
        band_matvec(nf, kd, Mb, r, mr);
        double bb = 0;
        for (size_t i = 0; i < nf; i++)
            bb += r[i] * mr[i];
        bb = bb > 0 ? sqrt(bb) : 0;
        /* an invariant subspace (bb tiny against alpha): the Ritz values are
         * exact; go on from a fresh vector if more are wanted */
        int broke = !(bb > 1e-12 * fabs(a));
        be[k - 1] = broke ? 0 : bb;
        /* the first check once k >= 1.5 ne (no sooner do the wanted ones
         * settle), then every k/8 + 1 steps: each costs a bisection for
         * ne + 1 eigenvalues of T_k */
        size_t first = ne + ne / 2;
        if (k == mmax || (k >= first && (broke || (k - first) % (k / 8 + 1) == 0))) {
            /* the largest ne + 1 Ritz values of T_k (ascending theta, the
             * first of them theta_off, 0-based in T_k's spectrum) and their
             * vectors; residual of the pair i: |beta_k Z(k-1, i)| */
            off = k > ne ? k - ne - 1 : 0;
            mm_error e2;
            if ((rc = mm_linalg_stev((int)k, al, be, (int)off + 1, (int)k, th, Z, &e2))) {
                rc = mm_error_set(err, MM_ENOCONV, NULL, "Lanczos: %s", e2.msg);
                goto out;
            }
            done = 1;
            for (size_t j = 0; j < ne && done; j++) {
                size_t i = k - 1 - j;
                done = th[i - off] > 0 && fabs(be[k - 1] * Z[(i - off) * k + k - 1]) <= 1e-10 * th[i - off];
            }
            if (done)
                break;
            if (k == mmax) {
                rc = mm_error_set(err, MM_ENOCONV, NULL, "Lanczos did not settle in %zu steps", k);
                goto out;
            }
        }
        if (broke) {      /* a fresh direction, M-orthogonal to all so far */
            for (size_t i = 0; i < nf; i++) {
                st ^= st << 13, st ^= st >> 7, st ^= st << 17;
                r[i] = (double)(st >> 11) / 9007199254740992.0 - 0.5;
            }
            m_orthogonalise(nf, nrig + k, B, MB, r, y);
            band_matvec(nf, kd, Mb, r, mr);
        }
    }
    /* rigid modes first (lambda 0; the caller takes their Rayleigh
     * quotients), then the Ritz vectors, largest theta first, each with its
     * implicit inverse-iteration step and M-normalised */
    for (size_t j = 0; j < nrig; j++) {
        lambda[j] = 0;
        for (size_t i = 0; i < nf; i++)
            V[i * nwant + j] = R[j * nf + i];
    }
    const double *rk = Q + k * nf;   /* beta_k q_k+1 (M-orthogonal to Q) */
    double bk = be[k - 1];
    for (size_t j = 0; j < ne; j++) {
        size_t c = k - 1 - j;
        const double *s = Z + (c - off) * k;
        double g = bk > 0 ? s[k - 1] / th[c - off] : 0, f = bk * g;
        for (size_t i = 0; i < nf; i++)
            y[i] = g * rk[i];
        for (size_t l = 0; l < k; l++)
            for (size_t i = 0; i < nf; i++)
                y[i] += s[l] * Q[l * nf + i];
        double sc = 1 / sqrt(1 + f * f);
        for (size_t i = 0; i < nf; i++)
            V[i * nwant + nrig + j] = sc * y[i];
        lambda[nrig + j] = 1 / th[c - off];
    }
    /* Sturm check: exactly nwant eigenvalues below sigma, just above the
     * last wanted one (and below the next Ritz value) */
    if (k < room) {
        double last = 1 / th[k - ne - off], next = k > ne ? 1 / th[k - ne - 1 - off] : INFINITY;
        double sigma = last + fmin(1e-3 * last, 0.5 * (next - last));
        long below = band_sturm(nf, kd, Kb, Mb, sigma, Kc);
        if (below != (long)nwant) {
            rc = mm_error_set(err, MM_ENOCONV, NULL, "Lanczos: the Sturm count below %g is %ld, not %zu", sigma,
                              below, nwant);
            goto out;
        }
    }
out:
    free(y);
    free(Z);
    free(th);
    free(be);
    free(al);
    free(MB);
    free(B);
    free(Kc);
    return rc;
}

/* Sign: the first displacement (u or w, not theta) larger than 1e-6 of the
 * largest displacement is positive; all DOFs if no displacement moves. */
static void fix_sign(double *v, size_t ndof, size_t stride)
{
    double big = 0;
    for (size_t i = 0; i < ndof; i += stride)
        big = fmax(big, fabs(v[i]));
    if (big == 0) {
        stride = 1;
        for (size_t i = 0; i < ndof; i++)
            big = fmax(big, fabs(v[i]));
    }
    for (size_t i = 0; i < ndof; i += stride)
        if (fabs(v[i]) > 1e-6 * big) {
            if (v[i] < 0)
                for (size_t j = 0; j < ndof; j++)
                    v[j] = -v[j];
            return;
        }
}

int mm_fem_modes_solve(const mm_fem_problem *p, size_t nmodes,
                       const mm_fem_options *opt, mm_fem_modes *res,
                       mm_error *err)
{
    mm_fem_options def;
    if (!opt) {
        mm_fem_options_init(&def);
        opt = &def;
    }
    int rc = mm_fem_check(p, err);
    if (rc)
        return rc;
    if (nmodes < 1 || nmodes > MM_FEM_MAX_MODES)
        return mm_error_set(err, MM_ERANGE, "modes",
                            "modes must be between 1 and %d; got %zu",
                            MM_FEM_MAX_MODES, nmodes);
    if (opt->method != MM_FEM_AUTO && opt->method != MM_FEM_DENSE &&
        opt->method != MM_FEM_BANDED && opt->method != MM_FEM_SUBSPACE &&
        opt->method != MM_FEM_LANCZOS)
        return mm_error_set(err, MM_EVALUE, "method",
                            "unknown solver method code %d", (int)opt->method);

    size_t ndof = mm_fem_ndof(p), fixed[4], nfix = fixed_dofs(p, fixed);
    size_t nf = ndof - nfix, nrig = rigid_possible(p);
    size_t nwant = nmodes + nrig < nf ? nmodes + nrig : nf;
    mm_fem_method method = pick_method(opt->method, nf, nwant, nrig > 0);
    if (method == MM_FEM_SUBSPACE && nrig > 0)
        method = MM_FEM_BANDED;           /* K is singular: no K^-1 */
    int kd = half_band(p->kind);
    if ((size_t)kd >= nf)
        kd = (int)nf - 1;             /* a tiny mesh: the band is the matrix */
    size_t neig = method == MM_FEM_DENSE ? nf : nwant;
    size_t w = (size_t)kd + 1;

    long *map = malloc(ndof * sizeof *map);
    size_t *order = malloc(nwant * sizeof *order);
    double *Kb = malloc(nf * w * sizeof *Kb), *Mb = malloc(nf * w * sizeof *Mb);
    double *lambda = malloc(neig * sizeof *lambda);
    double *V = malloc(nf * neig * sizeof *V);
    double *phis = malloc(nwant * ndof * sizeof *phis);
    double *K = NULL, *M = NULL;
    if (method == MM_FEM_DENSE) {
        K = malloc(nf * nf * sizeof *K);
        M = malloc(nf * nf * sizeof *M);
    }
    if (!map || !order || !Kb || !Mb || !lambda || !V || !phis ||
        (method == MM_FEM_DENSE && (!K || !M))) {
        rc = mm_error_set(err, MM_ENOMEM, NULL,
                          "out of memory for a %zu-DOF eigenproblem", nf);
        goto out;
    }

    mm_fem_free_dofs(p, map);      /* global order with the fixed DOFs taken out */

    double top = assemble_band(p, map, nf, kd, Kb, Mb);
    if (method == MM_FEM_LANCZOS) {
        rc = lanczos(p, nf, kd, Kb, Mb, nrig, nwant, lambda, V, err);
        if (rc && rc != MM_ENOMEM && opt->method == MM_FEM_AUTO)   /* fall back */
            method = fallback_method(nwant, nrig > 0);
    }
    if (method == MM_FEM_DENSE) {
        band_to_dense(nf, kd, Kb, K);
        band_to_dense(nf, kd, Mb, M);
        rc = mm_linalg_sygv((int)nf, K, M, lambda, V, err);
    } else if (method == MM_FEM_LANCZOS) {
        ;                              /* done above */
    } else if (method == MM_FEM_SUBSPACE) {
        rc = subspace(nf, kd, Kb, Mb, nwant, lambda, V, err);
        if (rc == MM_ENOCONV && opt->method == MM_FEM_AUTO) {   /* fall back */
            method = MM_FEM_BANDED;
            rc = mm_linalg_sbgv_first((int)nf, kd, (int)nwant, Kb, Mb, lambda, V, err);
        }
    } else {
        rc = mm_linalg_sbgv_first((int)nf, kd, (int)nwant, Kb, Mb, lambda, V, err);
    }
    if (rc)
        goto out;

    /* Rayleigh quotients of the wanted modes from element strains: the
     * solvers' eigenvalues carry an absolute error of about eps * top,
     * which for a fine beam mesh is a large part of the lowest ones
     * (8e-3 relative at 1000 cantilever elements); the quotient of the
     * computed mode, whose error is second order in the mode's, is good
     * to 1e-6 there and to 1e-11 at a few hundred elements. */
    for (size_t j = 0; j < nwant; j++) {
        double *phi = phis + j * ndof, kk, mm;
        for (size_t g = 0; g < ndof; g++)
            phi[g] = map[g] < 0 ? 0.0 : V[(size_t)map[g] * neig + j];
        rayleigh(p, phi, &kk, &mm);
        lambda[j] = kk / mm;
        order[j] = j;
    }
    for (size_t j = 1; j < nwant; j++)   /* ascending (insertion sort) */
        for (size_t i = j; i > 0 && lambda[order[i]] < lambda[order[i - 1]]; i--) {
            size_t t = order[i];
            order[i] = order[i - 1];
            order[i - 1] = t;
        }

    /* rigid-body modes: w^2 ~ 0 against the top of the spectrum (bounded by
     * the largest element eigenvalue); only where the supports allow them */
    size_t nr = 0;
    while (nr < nrig && nr < nwant && lambda[order[nr]] <= opt->rigid_tol * top)
        nr++;
    size_t got = nwant - nr < nmodes ? nwant - nr : nmodes;
    for (size_t j = 0; j < got; j++) {
        size_t src = order[nr + j];
        res->omega[j] = sqrt(lambda[src]);
        if (!isfinite(res->omega[j])) {
            rc = mm_error_set(err, MM_ENONFINITE, NULL,
                              "natural frequency %zu is not finite: the "
                              "properties overflow double precision", j + 1);
            goto out;
        }
        if (res->shape) {
            double *phi = res->shape + j * ndof;
            memcpy(phi, phis + src * ndof, ndof * sizeof *phi);
            fix_sign(phi, ndof, (size_t)dofs_per_node(p->kind));
        }
    }
    res->n_modes = got;
    res->n_rigid = nr;
    res->n_free = nf;
    res->method = method;
    rc = MM_OK;
out:
    free(M);
    free(K);
    free(phis);
    free(V);
    free(lambda);
    free(Mb);
    free(Kb);
    free(order);
    free(map);
    return rc;
}

/* ==== closed-form references ================================================ */

double mm_fem_beam_root(mm_fem_beam_eq eq, int n)
{
    double x;
    if (n < 1)
        return NAN;
    switch (eq) {                     /* asymptotic roots as starting points */
    case MM_FEM_COSCOSH_MINUS1: x = (2 * n - 1) * PI / 2; break;
    case MM_FEM_COSCOSH_PLUS1:  x = (2 * n + 1) * PI / 2; break;
    case MM_FEM_TAN_TANH:       x = (4 * n + 1) * PI / 4; break;
    default:                    return NAN;
    }
    /* Newton on the equation divided by cosh x, which keeps f = O(1):
     *   cos x cosh x = -1  ->  f = cos x + sech x
     *   cos x cosh x = +1  ->  f = cos x - sech x
     *   tan x = tanh x     ->  f = sin x - cos x tanh x  (times cos x) */
    for (int it = 0; it < 50; it++) {
        double sech = 1 / cosh(x), th = tanh(x), f, df;
        switch (eq) {
        case MM_FEM_COSCOSH_MINUS1:
            f = cos(x) + sech;
            df = -sin(x) - sech * th;
            break;
        case MM_FEM_COSCOSH_PLUS1:
            f = cos(x) - sech;
            df = -sin(x) + sech * th;
            break;
        default:
            f = sin(x) - cos(x) * th;
            df = cos(x) + sin(x) * th - cos(x) * sech * sech;
            break;
        }
        double dx = f / df;
        x -= dx;
        if (fabs(dx) <= 2 * DBL_EPSILON * x)
            break;                    /* quadratic convergence: done */
    }
    return x;
}

int mm_fem_exact_omegas(const mm_fem_problem *p, size_t nmodes,
                        double *omega, mm_error *err)
{
    int rc = mm_fem_check(p, err);
    if (rc)
        return rc;
    if (p->elements)
        return mm_error_set(err, MM_EVALUE, "elements",
                            "closed-form frequencies exist for a uniform "
                            "member only, not a per-element mesh");
    if (nmodes < 1 || nmodes > MM_FEM_MAX_MODES)
        return mm_error_set(err, MM_ERANGE, "modes",
                            "modes must be between 1 and %d; got %zu",
                            MM_FEM_MAX_MODES, nmodes);
    const mm_fem_element *u = &p->uniform;
    double L = u->L;
    for (size_t j = 0; j < nmodes; j++) {
        int n = (int)j + 1;
        if (p->kind == MM_FEM_BAR) {
            double c = sqrt(u->E / u->rho);   /* wave speed */
            omega[j] = p->bc == MM_FEM_FIXED_FREE ? (2 * n - 1) * PI * c / (2 * L)
                                                  : n * PI * c / L;
            continue;
        }
        double bl;
        switch (p->bc) {
        case MM_FEM_FIXED_FREE:    bl = mm_fem_beam_root(MM_FEM_COSCOSH_MINUS1, n); break;
        case MM_FEM_PINNED_PINNED: bl = n * PI; break;
        case MM_FEM_FIXED_PINNED:  bl = mm_fem_beam_root(MM_FEM_TAN_TANH, n); break;
        default:                   bl = mm_fem_beam_root(MM_FEM_COSCOSH_PLUS1, n); break;
        }
        omega[j] = bl * bl * sqrt(u->E * u->I / (u->rho * u->A * L * L * L * L));
    }
    return MM_OK;
}

/* ==== banded symmetric algebra ================================================ */

/* y = A x for the symmetric band A (upper band storage, half-bandwidth kd). */
static void band_matvec(size_t n, int kd, const double *Ab, const double *x, double *y)
{
    size_t w = (size_t)kd + 1;
    for (size_t i = 0; i < n; i++)
        y[i] = 0;
    for (size_t i = 0; i < n; i++) {
        const double *row = Ab + i * w;
        y[i] += row[0] * x[i];
        for (size_t d = 1; d < w && i + d < n; d++) {
            y[i] += row[d] * x[i + d];
            y[i + d] += row[d] * x[i];
        }
    }
}

/* A = U^T U in place (U upper, band storage); the diagonal slots receive
 * 1 / U_ii (the solves multiply).  Returns 0, or i + 1 when pivot i is
 * not positive (A not positive definite). */
static size_t band_cholesky(size_t n, int kd, double *Ab)
{
    size_t w = (size_t)kd + 1;
    for (size_t i = 0; i < n; i++) {
        double *ui = Ab + i * w;
        size_t k0 = i > (size_t)kd ? i - (size_t)kd : 0;
        double d = ui[0];
        for (size_t k = k0; k < i; k++)
            d -= Ab[k * w + (i - k)] * Ab[k * w + (i - k)];
        if (!(d > 0))
            return i + 1;
        double r = 1 / sqrt(d);
        ui[0] = r;
        for (size_t dj = 1; dj < w && i + dj < n; dj++) {
            size_t j = i + dj;
            double sum = ui[dj];
            for (size_t k = j > (size_t)kd ? j - (size_t)kd : 0; k < i; k++)
                sum -= Ab[k * w + (i - k)] * Ab[k * w + (j - k)];
            ui[dj] = sum * r;
        }
    }
    return 0;
}

/* Is the band matrix diagonal (a lumped mass, say)? */
static int band_is_diagonal(size_t n, int kd, const double *Ab)
{
    size_t w = (size_t)kd + 1;
    for (size_t i = 0; i < n; i++)
        for (size_t d = 1; d < w && i + d < n; d++)
            if (Ab[i * w + d] != 0)
                return 0;
    return 1;
}

/* Solve U^T U x = b in place (Ub from band_cholesky); diag: Ub is
 * diagonal (band_is_diagonal), one product per entry. */
static void band_chol_solve(size_t n, int kd, const double *Ub, int diag, double *x)
{
    size_t w = (size_t)kd + 1;
    if (diag) {
        for (size_t i = 0; i < n; i++)
            x[i] *= Ub[i * w] * Ub[i * w];
        return;
    }
    for (size_t i = 0; i < n; i++) {              /* U^T y = b */
        double sum = x[i];
        size_t k0 = i > (size_t)kd ? i - (size_t)kd : 0;
        for (size_t k = k0; k < i; k++)
            sum -= Ub[k * w + (i - k)] * x[k];
        x[i] = sum * Ub[i * w];
    }
    for (size_t i = n; i-- > 0;) {                /* U x = y */
        double sum = x[i];
        size_t dmax = n - 1 - i < w - 1 ? n - 1 - i : w - 1;
        for (size_t d = 1; d <= dmax; d++)
            sum -= Ub[i * w + d] * x[i + d];
        x[i] = sum * Ub[i * w];
    }
}

/* ==== omega_max, loads, statics ================================================ */

int mm_fem_omega_max(const mm_fem_problem *p, double *omega_max, mm_error *err)
{
    int rc = mm_fem_check(p, err);
    if (rc)
        return rc;
    size_t ndof = mm_fem_ndof(p);
    long *map = malloc(ndof * sizeof *map);
    double *Kb = NULL, *Mb = NULL;
    size_t nf = map ? mm_fem_free_dofs(p, map) : 0;
    int kd = mm_fem_half_band(p, nf);
    if (map) {
        Kb = malloc(nf * ((size_t)kd + 1) * sizeof *Kb);
        Mb = malloc(nf * ((size_t)kd + 1) * sizeof *Mb);
    }
    if (!map || !Kb || !Mb) {
        rc = mm_error_set(err, MM_ENOMEM, NULL, "out of memory");
        goto out;
    }
    double top = mm_fem_assemble_band(p, map, nf, Kb, Mb);
    /* s = 1e-3 of the bound: K + s M definite, and omega_max^2 + s known
     * to the solver's relative accuracy */
    double sh = 1e-3 * top, mu;
    for (size_t i = 0; i < nf * ((size_t)kd + 1); i++)
        Kb[i] += sh * Mb[i];
    if ((rc = mm_linalg_sbgv_first((int)nf, kd, 1, Mb, Kb, &mu, NULL, err)))
        goto out;
    *omega_max = sqrt(fmax(1 / mu - sh, 0));
out:
    free(Mb);
    free(Kb);
    free(map);
    return rc;
}

double mm_fem_omega_bound(const mm_fem_problem *p)
{
    double top = 0;
    for (size_t e = 0; e < p->n_el; e++) {
        mm_fem_element el = element_at(p, e);
        top = fmax(top, element_top(p->kind, p->mass, &el));
        if (!p->elements)
            break;                       /* uniform: every element alike */
    }
    return sqrt(top);
}

/* Element e and local coordinate xi in [0, 1] of the point x of the mesh;
 * -1 when x is outside [0, L]. */
static long locate(const mm_fem_problem *p, double x, double *xi, double *Le)
{
    if (!p->elements) {                      /* uniform: the element by division */
        double L = p->uniform.L, h = L / (double)p->n_el;
        if (!(x >= 0 && x <= L * (1 + 1e-15)))
            return -1;
        size_t e = (size_t)fmin(floor(x / h), (double)p->n_el - 1);
        *Le = h;
        *xi = fmin(fmax(x / h - (double)e, 0), 1);
        return (long)e;
    }
    double x0 = 0;
    for (size_t e = 0; e < p->n_el; e++) {
        mm_fem_element el = element_at(p, e);
        double x1 = p->elements ? x0 + el.L : p->uniform.L * (double)(e + 1) / (double)p->n_el;
        if (x >= x0 && (x <= x1 || e + 1 == p->n_el) && x <= x1 * (1 + 1e-15)) {
            *Le = x1 - x0;
            *xi = fmin(fmax((x - x0) / *Le, 0), 1);
            return (long)e;
        }
        x0 = x1;
    }
    return -1;
}

/* Shape functions at xi of an element of length Le: 2 (bar) or 4 (beam). */
static void shape_fns(mm_fem_kind kind, double xi, double Le, double *N)
{
    if (kind == MM_FEM_BAR) {
        N[0] = 1 - xi;
        N[1] = xi;
        return;
    }
    double x2 = xi * xi, x3 = x2 * xi;
    N[0] = 1 - 3 * x2 + 2 * x3;
    N[1] = Le * (xi - 2 * x2 + x3);
    N[2] = 3 * x2 - 2 * x3;
    N[3] = Le * (x3 - x2);
}

void mm_fem_load_vector(const mm_fem_problem *p, const mm_fem_load *ld, double t, double *f)
{
    size_t ndof = mm_fem_ndof(p);
    memset(f, 0, ndof * sizeof *f);
    double x, amp;
    if (ld->kind == MM_FEM_LOAD_MOVING) {
        x = ld->v * t;
        amp = ld->P;
    } else {
        if (!(t < ld->t_off))
            return;
        x = ld->x;
        amp = ld->Omega > 0 ? ld->P * cos(ld->Omega * t) : ld->P;
    }
    double xi, Le, N[4];
    long e = locate(p, x, &xi, &Le);
    if (e < 0)
        return;
    int dpn = dofs_per_node(p->kind);
    shape_fns(p->kind, xi, Le, N);
    for (int a = 0; a < 2 * dpn; a++)
        f[(size_t)e * (size_t)dpn + (size_t)a] += amp * N[a];
}

int mm_fem_static_solve(const mm_fem_problem *p, const double *f, double *u, mm_error *err)
{
    int rc = mm_fem_check(p, err);
    if (rc)
        return rc;
    if (p->bc == MM_FEM_FREE_FREE)
        return mm_error_set(err, MM_ESINGULAR, "bc", "a free-free member has no static "
                            "deflection: nothing holds it against the load");
    size_t ndof = mm_fem_ndof(p);
    long *map = malloc(ndof * sizeof *map);
    size_t nf = map ? mm_fem_free_dofs(p, map) : 0;
    int kd = mm_fem_half_band(p, nf);
    double *Kb = map ? malloc(nf * ((size_t)kd + 1) * sizeof *Kb) : NULL;
    double *Mb = map ? malloc(nf * ((size_t)kd + 1) * sizeof *Mb) : NULL;
    double *x = map ? malloc(nf * sizeof *x) : NULL;
    if (!map || !Kb || !Mb || !x) {
        rc = mm_error_set(err, MM_ENOMEM, NULL, "out of memory");
        goto out;
    }
    mm_fem_assemble_band(p, map, nf, Kb, Mb);
    if (band_cholesky(nf, kd, Kb)) {
        rc = mm_error_set(err, MM_ESINGULAR, "bc", "the stiffness matrix is singular");
        goto out;
    }
    for (size_t g = 0; g < ndof; g++)
        if (map[g] >= 0)
            x[map[g]] = f[g];
    band_chol_solve(nf, kd, Kb, 0, x);
    for (size_t g = 0; g < ndof; g++)
        u[g] = map[g] >= 0 ? x[map[g]] : 0;
out:
    free(x);
    free(Mb);
    free(Kb);
    free(map);
    return rc;
}

/* ==== modal superposition ======================================================== */

/* The modal coordinate of mode phi (all global DOFs) under a load crossing
 * at speed v, sampled at the nt times t: exact per element (the modal
 * force P phi(v t) is a cubic in t there), free after the load has left. */
static void moving_modal(const mm_fem_problem *p, const double *phi, double omega, double c,
                         const mm_fem_load *ld, int nt, const double *t, double *eta_out)
{
    double eta = 0, etad = 0, tnow = 0, x0 = 0, te = 0, tn = 0, a[4] = {0, 0, 0, 0};
    size_t e = 0;
    int on = 1;
    for (int i = 0; i < nt; i++) {
        while (tnow < t[i]) {
            if (on && tnow >= tn) {            /* the load enters the next element, or leaves */
                if (e == p->n_el) {
                    on = 0;
                    a[0] = a[1] = a[2] = a[3] = 0;
                    te = tnow;
                    tn = INFINITY;
                    continue;
                }
                mm_fem_element el = element_at(p, e);
                double L = el.L, r = ld->v / L;
                const double *u = phi + 2 * e;   /* w1 theta1 w2 theta2 */
                /* phi along the element, a cubic in xi = (x - x0)/L = r tau */
                double c0 = u[0], c1 = L * u[1], c2 = -3 * u[0] - 2 * L * u[1] + 3 * u[2] - L * u[3],
                       c3 = 2 * u[0] + L * u[1] - 2 * u[2] + L * u[3];
                a[0] = ld->P * c0;
                a[1] = ld->P * c1 * r;
                a[2] = ld->P * c2 * r * r;
                a[3] = ld->P * c3 * r * r * r;
                te = x0 / ld->v;
                x0 += L;
                tn = x0 / ld->v;
                e++;
                continue;
            }
            double target = fmin(t[i], tn), sft = tnow - te, b[4];
            /* the cubic in tau = t - te, rewritten from tnow */
            b[0] = a[0] + sft * (a[1] + sft * (a[2] + sft * a[3]));
            b[1] = a[1] + sft * (2 * a[2] + 3 * sft * a[3]);
            b[2] = a[2] + 3 * sft * a[3];
            b[3] = a[3];
            mm_mdof_sdof_poly(omega, c, b, target - tnow, &eta, &etad);
            tnow = target;
        }
        eta_out[i] = eta;
    }
}

int mm_fem_modal_response(const mm_fem_problem *p, const mm_fem_modes *modes, size_t m,
                          const mm_fem_damping *d, const mm_fem_load *ld, int nt,
                          const double *t, int nout, const size_t *dofs, double *out,
                          mm_error *err)
{
    if (m < 1 || m > modes->n_modes || !modes->shape)
        return mm_error_set(err, MM_ERANGE, "modes", "modes retained must be between 1 and %zu; "
                            "got %zu", modes->n_modes, m);
    if (ld->kind == MM_FEM_LOAD_MOVING && p->kind != MM_FEM_BEAM)
        return mm_error_set(err, MM_EVALUE, "load", "a moving load is offered for beams only");
    size_t ndof = mm_fem_ndof(p);
    double *f = malloc(ndof * sizeof *f), *eta = malloc((size_t)nt * sizeof *eta);
    if (!f || !eta) {
        free(eta);
        free(f);
        return mm_error_set(err, MM_ENOMEM, NULL, "out of memory");
    }
    mm_fem_load unit = *ld;
    unit.P = 1;
    unit.t_off = INFINITY;
    unit.Omega = 0;
    if (ld->kind == MM_FEM_LOAD_POINT)
        mm_fem_load_vector(p, &unit, 0, f);        /* shape functions at x */
    memset(out, 0, (size_t)nt * (size_t)nout * sizeof *out);
    for (size_t j = 0; j < m; j++) {
        const double *phi = modes->shape + j * ndof;
        double w = modes->omega[j], c = d ? d->a + d->b * w * w : 0;
        if (ld->kind == MM_FEM_LOAD_POINT) {
            double pj = 0;
            for (size_t g = 0; g < ndof; g++)
                pj += phi[g] * f[g];
            mm_mdof_pulse g = {ld->P * pj, ld->Omega, ld->t_off};
            for (int i = 0; i < nt; i++)
                eta[i] = mm_mdof_sdof_pulse(w, c, 0, 0, &g, t[i], NULL);
        } else {
            moving_modal(p, phi, w, c, ld, nt, t, eta);
        }
        for (int i = 0; i < nt; i++)
            for (int r = 0; r < nout; r++)
                out[(size_t)i * (size_t)nout + (size_t)r] += phi[dofs[r]] * eta[i];
    }
    free(eta);
    free(f);
    return MM_OK;
}

/* ==== direct integration ========================================================== */

/* 1/2 q^T K q of the free-DOF vector q, from element strains and
 * curvatures (no cancellation inside K q, as in rayleigh()). */
static double strain_energy(const mm_fem_problem *p, const long *map, const double *q)
{
    int dpn = dofs_per_node(p->kind);
    double e = 0, v[4];
    for (size_t el = 0; el < p->n_el; el++) {
        mm_fem_element m = element_at(p, el);
        for (int a = 0; a < 2 * dpn; a++) {
            long fi = map[el * (size_t)dpn + (size_t)a];
            v[a] = fi >= 0 ? q[fi] : 0;
        }
        double h = m.L;
        if (p->kind == MM_FEM_BAR) {
            e += 0.5 * m.E * m.A / h * (v[1] - v[0]) * (v[1] - v[0]);
        } else {
            double sl = (v[2] - v[0]) / h, k0 = (6 * sl - 4 * v[1] - 2 * v[3]) / h, k1 = (-6 * sl + 2 * v[1] + 4 * v[3]) / h;
            e += m.E * m.I * h * (k0 * k0 + k0 * k1 + k1 * k1) / 6;
        }
    }
    return e;
}

int mm_fem_transient_solve(const mm_fem_problem *p, const mm_fem_load *ld, mm_fem_transient *tr,
                           mm_error *err)
{
    int rc = mm_fem_check(p, err);
    if (rc)
        return rc;
    size_t ndof = mm_fem_ndof(p);
    if (!(tr->h > 0) || !isfinite(tr->h))
        return mm_error_set(err, MM_ERANGE, "h", "the time step must be > 0; got %g", tr->h);
    if (tr->steps < 1 || tr->steps > MM_FEM_MAX_STEPS)
        return mm_error_set(err, MM_ERANGE, "steps", "steps must be between 1 and %ld; got %ld",
                            MM_FEM_MAX_STEPS, tr->steps);
    if (tr->stride < 1)
        return mm_error_set(err, MM_ERANGE, "stride", "stride must be at least 1");
    for (int r = 0; r < tr->nout; r++)
        if (tr->dofs[r] >= ndof)
            return mm_error_set(err, MM_ERANGE, "dofs", "DOF %zu is not in the mesh", tr->dofs[r]);
    for (int s = 0; s < tr->nsnap; s++)
        if (tr->snap[s] < 0 || tr->snap[s] > tr->steps)
            return mm_error_set(err, MM_ERANGE, "snap", "snapshot step %ld is not in the run",
                                tr->snap[s]);
    if (ld->kind == MM_FEM_LOAD_MOVING && p->kind != MM_FEM_BEAM)
        return mm_error_set(err, MM_EVALUE, "load", "a moving load is offered for beams only");

    long *map = malloc(ndof * sizeof *map);
    size_t nf = map ? mm_fem_free_dofs(p, map) : 0, w = 0;
    int kd = mm_fem_half_band(p, nf);
    w = (size_t)kd + 1;
    double *Kb = NULL, *Mb = NULL, *Sb = NULL, *Mf = NULL, *vec = NULL, *f = NULL, *fo = NULL;
    if (map) {
        Kb = malloc(nf * w * sizeof *Kb);
        Mb = malloc(nf * w * sizeof *Mb);
        Sb = malloc(nf * w * sizeof *Sb);
        Mf = malloc(nf * w * sizeof *Mf);
        vec = malloc(8 * nf * sizeof *vec);
        f = malloc(ndof * sizeof *f);
    }
    if (!map || !Kb || !Mb || !Sb || !Mf || !vec || !f) {
        rc = mm_error_set(err, MM_ENOMEM, NULL, "out of memory");
        goto out;
    }
    mm_fem_assemble_band(p, map, nf, Kb, Mb);
    double *q = vec, *v = vec + nf, *a = vec + 2 * nf, *r = vec + 3 * nf, *t1 = vec + 4 * nf,
           *qt = vec + 5 * nf, *vt = vec + 6 * nf, *t2 = vec + 7 * nf;
    const double h = tr->h, ca = tr->damping.a, cb = tr->damping.b;
    /* the matrices solved with: M (start), and S of the scheme */
    double sm, sk;          /* S = sm M + sk K */
    if (tr->scheme == MM_FEM_AVERAGE) {
        sm = 1 + 0.5 * h * ca;
        sk = 0.5 * h * cb + 0.25 * h * h;
    } else {
        sm = 1 + 0.5 * h * ca;
        sk = 0.5 * h * cb;
    }
    for (size_t i = 0; i < nf * w; i++) {
        Sb[i] = sm * Mb[i] + sk * Kb[i];
        Mf[i] = Mb[i];
    }
    int mdiag = band_is_diagonal(nf, kd, Mf), sdiag = band_is_diagonal(nf, kd, Sb);
    if (band_cholesky(nf, kd, Mf) || band_cholesky(nf, kd, Sb)) {
        rc = mm_error_set(err, MM_ESINGULAR, "h", "the matrix a step solves with is not positive "
                          "definite");
        goto out;
    }
    /* start at rest: a0 = M^-1 f(0) */
    memset(q, 0, 3 * nf * sizeof *q);
    mm_fem_load_vector(p, ld, 0, f);
    for (size_t g = 0; g < ndof; g++)
        if (map[g] >= 0)
            a[map[g]] = f[g];
    band_chol_solve(nf, kd, Mf, mdiag, a);

    /* the energy identity: E~ with the correction of beta, W and D by the
     * rule in q, accumulated every step, E~ evaluated at the stored steps */
    const double be = tr->scheme == MM_FEM_AVERAGE ? 0.25 : 0.0;
    fo = malloc(2 * nf * sizeof *fo);
    if (!fo) {
        rc = mm_error_set(err, MM_ENOMEM, NULL, "out of memory");
        goto out;
    }
    double *fprev = fo, *cv0 = fo + nf, Wq = 0, Dq = 0, E0 = 0, bal = 0, big = 0;
    for (size_t g = 0; g < ndof; g++)
        if (map[g] >= 0)
            fprev[map[g]] = f[g];
    memset(cv0, 0, nf * sizeof *cv0);            /* at rest: C v = 0 */
    int row = 0, snapi = 0;
    for (long k = 0;; k++) {
        /* record step k */
        if (k % tr->stride == 0 || k == tr->steps) {
            double ek = 0, ama = 0, e = strain_energy(p, map, q);
            band_matvec(nf, kd, Mb, v, t1);
            for (size_t i = 0; i < nf; i++)
                ek += 0.5 * v[i] * t1[i];
            band_matvec(nf, kd, Mb, a, t1);
            for (size_t i = 0; i < nf; i++)
                ama += a[i] * t1[i];
            double Et = ek + e - 0.5 * h * h * (0.25 - be) * ama;
            if (k == 0)
                E0 = Et;
            bal = fmax(bal, fabs(Et - E0 - Wq + Dq));
            big = fmax(big, fmax(fmax(ek, e), fmax(fabs(Wq), fabs(Dq))));
        }
        if (tr->out && k % tr->stride == 0) {
            for (int o = 0; o < tr->nout; o++) {
                long fi = map[tr->dofs[o]];
                tr->out[(size_t)row * (size_t)tr->nout + (size_t)o] = fi >= 0 ? q[fi] : 0;
            }
            row++;
        }
        for (int s = 0; s < tr->nsnap; s++)
            if (tr->snap[s] == k && tr->snaps) {
                double *dst = tr->snaps + (size_t)s * ndof;
                for (size_t g = 0; g < ndof; g++)
                    dst[g] = map[g] >= 0 ? q[map[g]] : 0;
                snapi++;
            }
        if (k == tr->steps)
            break;
        double tn = h * (double)(k + 1);
        mm_fem_load_vector(p, ld, tn, f);
        for (size_t g = 0; g < ndof; g++)
            if (map[g] >= 0)
                r[map[g]] = f[g];
        if (tr->scheme == MM_FEM_AVERAGE) {
            /* predictors, then S a1 = f1 - C vt - K qt */
            for (size_t i = 0; i < nf; i++) {
                qt[i] = q[i] + h * v[i] + 0.25 * h * h * a[i];
                vt[i] = v[i] + 0.5 * h * a[i];
            }
        } else {
            for (size_t i = 0; i < nf; i++) {
                qt[i] = q[i] + h * v[i] + 0.5 * h * h * a[i];
                vt[i] = v[i] + 0.5 * h * a[i];
            }
        }
        band_matvec(nf, kd, Kb, qt, t1);            /* K qt */
        for (size_t i = 0; i < nf; i++)
            r[i] -= t1[i];
        if (ca != 0 || cb != 0) {                   /* C vt = a M vt + b K vt */
            band_matvec(nf, kd, Mb, vt, t1);
            band_matvec(nf, kd, Kb, vt, t2);
            for (size_t i = 0; i < nf; i++)
                r[i] -= ca * t1[i] + cb * t2[i];
        }
        band_chol_solve(nf, kd, Sb, sdiag, r);      /* a_{k+1} */
        double qbig = 0, dW = 0, dD = 0;
        for (size_t g = 0; g < ndof; g++)            /* f_{k+1} again (r was overwritten) */
            if (map[g] >= 0)
                t2[map[g]] = f[g];
        for (size_t i = 0; i < nf; i++) {
            double bt = tr->scheme == MM_FEM_AVERAGE ? 0.25 * h * h : 0, qn = qt[i] + bt * r[i];
            dW += 0.5 * (qn - q[i]) * (fprev[i] + t2[i]);
            qt[i] = qn - q[i];                       /* keep the step's dq */
            q[i] = qn;
            v[i] = vt[i] + 0.5 * h * r[i];
            a[i] = r[i];
            qbig = fmax(qbig, fabs(q[i]));
        }
        memcpy(fprev, t2, nf * sizeof *fprev);
        if (ca != 0 || cb != 0) {                   /* C v_{k+1} into t1, D by the rule in q */
            band_matvec(nf, kd, Mb, v, t1);
            band_matvec(nf, kd, Kb, v, t2);
            for (size_t i = 0; i < nf; i++) {
                double cv = ca * t1[i] + cb * t2[i];
                dD += 0.5 * qt[i] * (cv0[i] + cv);
                cv0[i] = cv;
            }
        }
        Wq += dW;
        Dq += dD;
        if (!isfinite(qbig) || qbig > 1e150) {
            rc = mm_error_set(err, MM_ENONFINITE, "h", "the motion grew without bound by t = %g s: "
                              "the step h = %g s is past the stability limit of %s", tn, h,
                              tr->scheme == MM_FEM_CENTRAL ? "central difference" : "the scheme");
            goto out;
        }
    }
    (void)snapi;
    tr->energy_balance = big > 0 ? bal / big : 0;
    rc = MM_OK;
out:
    free(fo);
    free(f);
    free(vec);
    free(Mf);
    free(Sb);
    free(Mb);
    free(Kb);
    free(map);
    return rc;
}

/* ==== convergence studies and the bar's closed form (chapter 5) =============== */

int mm_fem_omega1_errors(const mm_fem_problem *p, int nc, const int *mesh, double exact, double *h, double *e,
                         mm_error *err)
{
    for (int i = 0; i < nc; i++) {
        mm_fem_problem pc = *p;
        pc.n_el = (size_t)mesh[i];
        double w1;
        mm_fem_modes r = {&w1, NULL, 0, 0, 0, MM_FEM_AUTO};
        int rc = mm_fem_modes_solve(&pc, 1, NULL, &r, err);
        if (rc)
            return rc;
        h[i] = p->uniform.L / mesh[i];
        e[i] = fabs(w1 / exact - 1);
    }
    return MM_OK;
}

double mm_fem_bar_omega(const mm_fem_problem *p, int j)
{
    double n = (double)p->n_el, h = p->uniform.L / n, c = sqrt(p->uniform.E / p->uniform.rho);
    double th = p->bc == MM_FEM_FIXED_FREE ? (2 * j - 1) * M_PI / (2 * n) : j * M_PI / n, s = sin(th / 2);
    return 2 * c / h * s * (p->mass == MM_FEM_CONSISTENT ? sqrt(3 / (3 - 2 * s * s)) : 1);
}

/* ==== modal references of a transient run (chapter 5) ========================= */

static int modal_newmark(const mm_fem_problem *p, const mm_fem_modes *md, const mm_fem_damping *d,
                         const mm_fem_load *ld, double h, long steps, long stride, size_t dof, double *out,
                         double *scale, double *f, double *y, double *A, double *B, double *pk, mm_error *err)
{
    size_t nd = mm_fem_ndof(p), nm = md->n_modes;
    mm_newmark_options o;
    mm_newmark_options_init(&o);
    o.h = h;
    for (size_t j = 0; j < nm; j++) {
        double one = 1, k2 = md->omega[j] * md->omega[j], c = d->a + d->b * k2;
        int rc = mm_newmark_amplification(1, &one, &c, &k2, &o, A + 9 * j, B + 6 * j, B + 6 * j + 3, err);
        if (rc)
            return rc;
    }
    mm_fem_load_vector(p, ld, 0, f);
    for (size_t j = 0; j < nm; j++) {           /* from rest: a_0 = p_0 */
        pk[j] = 0;
        for (size_t g = 0; g < nd; g++)
            pk[j] += md->shape[j * nd + g] * f[g];
        y[3 * j] = y[3 * j + 1] = 0, y[3 * j + 2] = pk[j];
    }
    int row = 0;
    *scale = 0;
    for (long k = 0;; k++) {
        if (k % stride == 0) {
            double s = 0, sa = 0;         /* the sum, and the size of its terms: q + h v + h^2 a */
            for (size_t j = 0; j < nm; j++) {
                s += md->shape[j * nd + dof] * y[3 * j];
                sa += fabs(md->shape[j * nd + dof]) *
                      (fabs(y[3 * j]) + h * fabs(y[3 * j + 1]) + h * h * fabs(y[3 * j + 2]));
            }
            out[row++] = s;
            *scale = fmax(*scale, sa);
        }
        if (k == steps)
            break;
        mm_fem_load_vector(p, ld, h * (double)(k + 1), f);
        for (size_t j = 0; j < nm; j++) {
            const double *a = A + 9 * j, *b0 = B + 6 * j, *b1 = b0 + 3, *phi = md->shape + j * nd;
            double p1 = 0, z[3];
            for (size_t g = 0; g < nd; g++)
                p1 += phi[g] * f[g];
            for (int i = 0; i < 3; i++)
                z[i] = a[3 * i] * y[3 * j] + a[3 * i + 1] * y[3 * j + 1] + a[3 * i + 2] * y[3 * j + 2] + b0[i] * pk[j] +
                       b1[i] * p1;
            memcpy(y + 3 * j, z, sizeof z);
            pk[j] = p1;
        }
    }
    return MM_OK;
}

int mm_fem_modal_newmark(const mm_fem_problem *p, const mm_fem_modes *md, const mm_fem_damping *d,
                         const mm_fem_load *ld, double h, long steps, long stride, size_t dof, double *out,
                         double *scale, mm_error *err)
{
    size_t nd = mm_fem_ndof(p), nm = md->n_modes;
    double *f = calloc(nd + 19 * nm, sizeof *f);     /* f, then y 3 nm, A 9 nm, B 6 nm, pk nm */
    if (!f)
        return mm_error_set(err, MM_ENOMEM, NULL, "out of memory");
    double *y = f + nd, *A = y + 3 * nm, *B = A + 9 * nm, *pk = B + 6 * nm;
    int rc = modal_newmark(p, md, d, ld, h, steps, stride, dof, out, scale, f, y, A, B, pk, err);
    free(f);
    return rc;
}

int mm_fem_static_residual(const mm_fem_problem *p, const mm_fem_modes *md, size_t m, const mm_fem_load *ld,
                           int nt, const double *t, size_t dof, double *r, double *umax, mm_error *err)
{
    size_t nd = mm_fem_ndof(p), step = p->kind == MM_FEM_BEAM ? 2 : 1;
    double *f = calloc(2 * nd, sizeof *f), *u = f ? f + nd : NULL;
    if (!f)
        return mm_error_set(err, MM_ENOMEM, NULL, "out of memory");
    int rc = MM_OK;
    *umax = 0;
    for (int i = 0; i < nt && !rc; i++) {
        mm_fem_load_vector(p, ld, t[i], f);
        if ((rc = mm_fem_static_solve(p, f, u, err)))
            break;
        r[i] = u[dof];
        for (size_t j = 0; j < m; j++) {
            double pj = 0;
            for (size_t g = 0; g < nd; g++)
                pj += md->shape[j * nd + g] * f[g];
            r[i] -= md->shape[j * nd + dof] * pj / (md->omega[j] * md->omega[j]);
        }
        for (size_t g = 0; g < nd; g += step)
            *umax = fmax(*umax, fabs(u[g]));
    }
    free(f);
    return rc;
}
