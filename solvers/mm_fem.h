/* mm_fem.h — one-dimensional finite elements for free vibration: axial bars
 * and Euler-Bernoulli beams, their natural frequencies and mode shapes, and
 * the closed-form frequencies they converge to.
 *
 * Elements (local DOFs; L element length, x along the axis):
 *   bar  (2 nodes, linear, DOFs u1 u2):
 *        k = EA/L [1 -1; -1 1],  m = rho A L/6 [2 1; 1 2] (consistent)
 *                                or rho A L/2 [1 0; 0 1]   (lumped)
 *   beam (2 nodes, Hermite cubic, DOFs w1 theta1 w2 theta2, theta = dw/dx):
 *        k = EI/L^3 [ 12   6L   -12   6L ;  6L 4L^2 -6L 2L^2 ;
 *                    -12  -6L    12  -6L ;  6L 2L^2 -6L 4L^2 ]
 *        m = rho A L/420 [ 156  22L   54  -13L ;  22L 4L^2  13L -3L^2 ;
 *                           54  13L  156  -22L ; -13L -3L^2 -22L 4L^2 ]
 *        (consistent only: a lumped beam mass has no rotary inertia and
 *        would make M singular).
 * Global DOFs: node i = 0..n_el from x = 0; bar DOF i = u_i; beam DOFs
 * 2i = w_i, 2i+1 = theta_i.  Boundary conditions remove DOFs (rows and
 * columns) rather than adding penalty springs, so the matrices stay exact.
 *
 * Eigen solve (through mm_linalg, never LAPACK directly): K phi = w^2 M phi
 * on the free DOFs.  Dense (all modes, LAPACK dsygvd), shift-invert
 * Lanczos (first modes only, on band storage, half-bandwidth 1 for bars
 * and 3 for beams: K factored once, a Krylov space of K^-1 M), subspace
 * iteration, or banded selective (dsbgvx, modes by inverse iteration);
 * MM_FEM_AUTO picks dense or Lanczos (see mm_fem_method).  Each frequency
 * is then the Rayleigh quotient of its mode, with the strain energy summed
 * from element strains and curvatures: the solvers' eigenvalues carry an
 * absolute error of about eps x (largest eigenvalue), which grows like
 * n_el^4 for a beam (8e-3 relative on mode 1 of a 1000-element cantilever
 * by dsbgvx; 1e-6 by Lanczos' own Ritz value), while the quotient of the
 * computed mode is second-order accurate in the mode and free of the
 * cancellation inside K phi.
 * Rigid-body modes (free ends) have w^2 = 0 up to rounding; they are
 * recognised by w^2 <= rigid_tol x (largest eigenvalue of the mesh),
 * counted in n_rigid and left out of the elastic modes (only free-free
 * members can have them: at most 1 for a bar, 2 for a beam).  The largest
 * eigenvalue is bounded above by the largest element eigenvalue (the
 * element eigenvalue bound theorem, Irons and Treharne 1971), computed in
 * closed form, so both solvers use the same test without computing the top
 * of the spectrum.  The test assumes elements of comparable length (a very
 * short element raises the bound).
 *
 * Accuracy to expect (tests/unit/test_fem.c checks it): consistent mass
 * gives frequencies above the exact ones (Rayleigh-Ritz), converging as h^2
 * for bars and h^4 for beams; lumped bar mass gives them below, as h^2.
 * Rounding sets a floor, for beams: with the dense solver about 1e-11
 * relative from some 250 elements on (3e-9 on mode 1 at 1000); with the
 * banded one 1e-10 at 300 elements and 6e-6 at 1000 (its inverse-iteration
 * modes are less accurate); Lanczos and subspace iteration keep mode 1 of
 * 1000 elements to 3e-13 (free-free 9e-13).  tests/bench/bench_fem.c
 * prints them.
 *
 * Memory: the caller owns the problem and the result arrays.  Scratch
 * matrices are allocated and freed inside mm_fem_modes_solve (O(n^2) for
 * the dense solver, O(n x modes) for the others).  Thread-safe: no
 * globals.
 *
 * Errors: MM_ERANGE (param "elements") for a mesh outside
 * 1..MM_FEM_MAX_ELEMENTS or more than MM_FEM_MAX_MODES modes ("modes");
 * MM_EVALUE for a property that is not finite and > 0 ("E", "A", "I",
 * "rho", "L"; for a per-element mesh "elements", naming the element), an
 * unknown kind, boundary condition ("bc") or mass ("mass"), or a
 * combination that does not exist (pinned ends on a bar, lumped beam mass);
 * MM_ENONFINITE when the frequencies overflow; MM_ENOMEM; MM_ENOCONV and
 * MM_EINTERNAL passed on from mm_linalg.
 */
#ifndef MM_FEM_H
#define MM_FEM_H

#include <stddef.h>

#include "mm_status.h"

#define MM_FEM_MAX_ELEMENTS  1000   /* elements in one mesh */
#define MM_FEM_MAX_MODES     100    /* modes asked of one solve */

typedef enum mm_fem_kind {
    MM_FEM_BAR,     /* axial vibration, 1 DOF per node */
    MM_FEM_BEAM     /* bending vibration, 2 DOFs per node */
} mm_fem_kind;

typedef enum mm_fem_bc {
    MM_FEM_FIXED_FREE,     /* bar: u(0) = 0; beam: cantilever (clamped at 0) */
    MM_FEM_FIXED_FIXED,    /* bar: both ends fixed; beam: clamped-clamped */
    MM_FEM_FREE_FREE,      /* both ends free: 1 (bar) or 2 (beam) rigid modes */
    MM_FEM_PINNED_PINNED,  /* beam only: simply supported, w = 0 at both ends */
    MM_FEM_FIXED_PINNED    /* beam only: clamped at 0, pinned at L ("propped") */
} mm_fem_bc;

typedef enum mm_fem_mass {
    MM_FEM_CONSISTENT,     /* from the element's shape functions */
    MM_FEM_LUMPED          /* half of each element's mass at each node (bar) */
} mm_fem_mass;

/* Properties of one element (or of every element of a uniform mesh). */
typedef struct mm_fem_element {
    double L;      /* length [m] */
    double E;      /* Young's modulus [Pa] */
    double A;      /* cross-section area [m^2] */
    double I;      /* second moment of area [m^4] (beam only; ignored for a bar) */
    double rho;    /* density [kg/m^3] */
} mm_fem_element;

typedef struct mm_fem_problem {
    mm_fem_kind kind;
    mm_fem_bc bc;
    mm_fem_mass mass;
    size_t n_el;                      /* number of elements */
    mm_fem_element uniform;           /* a uniform mesh: uniform.L is the
                                         TOTAL length, cut into n_el equal
                                         elements */
    const mm_fem_element *elements;   /* or NULL; else n_el elements, each
                                         with its own length and properties
                                         (uniform is then ignored) */
} mm_fem_problem;

typedef enum mm_fem_method {
    MM_FEM_AUTO,     /* dense for at most 6 free DOFs or a third of the
                        modes or more; otherwise Lanczos; should it fail,
                        subspace iteration for up to 20 modes of a
                        supported mesh, banded otherwise (free-free, more
                        modes, or subspace iteration not settling).
                        bench_fem, ten modes of a 1000-element cantilever
                        (a loaded machine): Lanczos 3.5 ms and 3e-13 on
                        mode 1, subspace 16-22 ms and 3e-13, banded
                        100 ms and 6e-6, dense (every mode) 5 s and 3e-9 */
    MM_FEM_DENSE,    /* all eigenpairs, mm_linalg_sygv (dsygvd) */
    MM_FEM_BANDED,   /* first modes only, mm_linalg_sbgv_first (dsbgvx) */
    MM_FEM_SUBSPACE, /* first modes only, subspace iteration with K^-1 M
                        (K factored once, banded Cholesky) and a Ritz step
                        of p = max(2 nmodes, nmodes + 8) vectors (Bathe):
                        no O(n^2) work at all, and the lowest modes of a
                        stiff mesh come out accurate (inverse powers damp
                        the high-mode parts of the rounding).  Supported
                        meshes only (K positive definite); AUTO takes it
                        for up to 20 modes of a mesh with no rigid-body
                        modes, where banded would be taken */
    MM_FEM_LANCZOS   /* first modes only, shift-invert Lanczos in the M
                        inner product with full reorthogonalisation: K
                        factored once (banded Cholesky; a free-free member
                        held at its middle node, its rigid-body modes known
                        exactly and deflated), one solve per Lanczos vector
                        (fewer than 2 nmodes + 4 of them on the beams and
                        bars measured), stopping when each wanted Ritz
                        pair's residual is below 1e-10 of its value, then
                        a Sturm sequence count (LDL^T of K - sigma M)
                        proving no mode below the last was missed.  AUTO
                        falls back to subspace or banded if it fails (not
                        seen on any mesh the exercises allow) */
} mm_fem_method;

typedef struct mm_fem_options {
    mm_fem_method method;   /* default MM_FEM_AUTO */
    double rigid_tol;       /* rigid if w^2 <= rigid_tol * largest element
                               eigenvalue; default 1e-16.  Refined rigid
                               modes come out below 1e-20 of it; the lowest
                               elastic one of a 1000-element free beam is
                               6e-14 of it */
} mm_fem_options;

/* The answer.  The caller points omega (and shape, or NULL) at arrays for
 * the nmodes modes it asks for; the solver fills them and the counts. */
typedef struct mm_fem_modes {
    double *omega;     /* in: array[nmodes]; out: elastic natural
                          frequencies [rad/s], ascending */
    double *shape;     /* in: array[nmodes * mm_fem_ndof(p)] or NULL; out:
                          mode j at shape[j*ndof + i] over ALL global DOFs
                          (0 at fixed ones), mass-normalised
                          (phi^T M phi = 1), the first displacement (u or
                          w) larger than 1e-6 of the largest positive */
    size_t n_modes;    /* out: elastic modes written; < nmodes only when the
                          mesh has fewer (e.g. a 1-element fixed-free bar) */
    size_t n_rigid;    /* out: rigid-body modes found and left out */
    size_t n_free;     /* out: free DOFs (order of the eigenproblem) */
    mm_fem_method method;   /* out: MM_FEM_DENSE, MM_FEM_BANDED,
                               MM_FEM_SUBSPACE or MM_FEM_LANCZOS, as used */
} mm_fem_modes;

/* ---- set-up --------------------------------------------------------------- */

/* Defaults listed in mm_fem_options.  Cannot fail. */
void mm_fem_options_init(mm_fem_options *opt);

/* Validate the problem (limits, properties, bc/kind/mass combination)
 * without allocating.  No side effects. */
int mm_fem_check(const mm_fem_problem *p, mm_error *err);

/* Global DOFs of the mesh: (n_el + 1) for a bar, 2 (n_el + 1) for a beam,
 * fixed ones included.  Cannot fail. */
size_t mm_fem_ndof(const mm_fem_problem *p);

/* Node positions x[0..n_el] [m] from 0.  Cannot fail (p checked). */
void mm_fem_node_x(const mm_fem_problem *p, double *x);

/* Element stiffness k and mass m (row-major, 2x2 for a bar, 4x4 for a beam,
 * local DOFs as in the file comment) of one element.  Errors: MM_EVALUE for
 * a non-positive or non-finite property ("L", "E", "A", "I", "rho") or a
 * lumped beam mass ("mass"). */
int mm_fem_element_matrices(mm_fem_kind kind, mm_fem_mass mass,
                            const mm_fem_element *el, double *k, double *m,
                            mm_error *err);

/* ---- modal analysis ------------------------------------------------------- */

/* The first nmodes elastic modes (1 <= nmodes <= MM_FEM_MAX_MODES) of the
 * mesh: assembles K and M on the free DOFs, solves, detects rigid-body
 * modes, fills res as documented in mm_fem_modes.  opt may be NULL.
 * Errors as in the file comment. */
int mm_fem_modes_solve(const mm_fem_problem *p, size_t nmodes,
                       const mm_fem_options *opt, mm_fem_modes *res,
                       mm_error *err);

/* ---- closed-form references ----------------------------------------------- */

typedef enum mm_fem_beam_eq {
    MM_FEM_COSCOSH_MINUS1,   /* cos bL cosh bL = -1: clamped-free */
    MM_FEM_COSCOSH_PLUS1,    /* cos bL cosh bL = +1: clamped-clamped, free-free */
    MM_FEM_TAN_TANH          /* tan bL = tanh bL: clamped-pinned, free-pinned */
} mm_fem_beam_eq;

/* The n-th positive root (n >= 1) of the beam frequency equation, to full
 * double precision: Newton's method on the equation divided by cosh bL
 * (so the terms stay O(1)), from the asymptotic root (2n-1)pi/2,
 * (2n+1)pi/2 or (4n+1)pi/4, converging in 3 to 6 steps.  1.8751040687...,
 * 4.7300407448..., 3.9266023120... for n = 1.  Returns NaN for n < 1 or an
 * unknown equation. */
double mm_fem_beam_root(mm_fem_beam_eq eq, int n);

/* Exact natural frequencies [rad/s] of the first nmodes elastic modes of
 * the uniform continuum the mesh p approximates (p->elements must be NULL;
 * kind, bc, uniform matter, n_el and mass do not):
 *   bar, c = sqrt(E/rho):  fixed-free (2n-1) pi c / 2L;  fixed-fixed and
 *                          free-free n pi c / L;
 *   beam: (beta_n L)^2 sqrt(EI / (rho A L^4)) with beta_n L from
 *         mm_fem_beam_root (cantilever: -1; clamped-clamped and free-free:
 *         +1; fixed-pinned: tan = tanh) or n pi (simply supported).
 * Errors: those of mm_fem_check, MM_EVALUE ("elements") for a per-element
 * mesh, MM_ERANGE ("modes") for nmodes outside 1..MM_FEM_MAX_MODES. */
int mm_fem_exact_omegas(const mm_fem_problem *p, size_t nmodes,
                        double *omega, mm_error *err);

/* ---- assembly and loads ------------------------------------------------------ */

/* The free-DOF numbering: map[g] (ndof entries) is the index of global DOF
 * g among the free ones, or -1 where the boundary condition fixes it.
 * Returns the number of free DOFs nf.  p must pass mm_fem_check.  Cannot
 * fail. */
size_t mm_fem_free_dofs(const mm_fem_problem *p, long *map);

/* Half-bandwidth of K and M on the free DOFs: 1 for a bar, 3 for a beam
 * (less for a mesh of fewer free DOFs: nf - 1).  Cannot fail. */
int mm_fem_half_band(const mm_fem_problem *p, size_t nf);

/* K and M on the free DOFs in mm_linalg's band storage
 * (Ab[i*(kd+1) + d] = A(i, i+d)), kd = mm_fem_half_band; Kb and Mb hold
 * nf*(kd+1) doubles (overwritten).  Returns the largest element eigenvalue
 * of the mesh, an upper bound of omega_max^2 (Irons and Treharne): the
 * Courant bound of an explicit step.  p must pass mm_fem_check.  Cannot
 * fail. */
double mm_fem_assemble_band(const mm_fem_problem *p, const long *map, size_t nf,
                            double *Kb, double *Mb);

/* The highest natural frequency of the mesh [rad/s], exact to rounding:
 * the lowest eigenvalue mu of M phi = mu (K + s M) phi (s > 0 keeps a
 * free-free mesh definite) is 1 / (omega_max^2 + s), by the banded
 * selective solver.  Errors: those of mm_fem_check, MM_ENOMEM, and
 * mm_linalg's. */
int mm_fem_omega_max(const mm_fem_problem *p, double *omega_max, mm_error *err);

/* An upper bound of the mesh's highest natural frequency [rad/s]: the
 * square root of the largest element eigenvalue (Irons and Treharne), in
 * closed form, no eigen solve.  p must pass mm_fem_check.  Cannot fail. */
double mm_fem_omega_bound(const mm_fem_problem *p);

typedef enum mm_fem_load_kind {
    MM_FEM_LOAD_POINT,     /* a force P at x, P cos(Omega t) until t_off */
    MM_FEM_LOAD_MOVING     /* a constant force P crossing at speed v (beams) */
} mm_fem_load_kind;

/* A load (bar: axial, along +x; beam: transverse, along +w). */
typedef struct mm_fem_load {
    mm_fem_load_kind kind;
    double P;        /* force [N] */
    double x;        /* POINT: where, 0 <= x <= L [m] */
    double Omega;    /* POINT: frequency of P cos(Omega t), >= 0; 0 a constant P [rad/s] */
    double t_off;    /* POINT: the load stops at t_off > 0; INFINITY: never [s] */
    double v;        /* MOVING: speed > 0; enters at x = 0 at t = 0, leaves at L / v [m/s] */
} mm_fem_load;

/* The consistent nodal load vector f (ndof values, every global DOF, fixed
 * ones included) at time t: P times the element's shape functions at the
 * load's position (linear for a bar, Hermite cubics for a beam), times the
 * time function.  p must pass mm_fem_check; a load outside 0..L gives 0.
 * Cannot fail. */
void mm_fem_load_vector(const mm_fem_problem *p, const mm_fem_load *ld, double t, double *f);

/* The static deflection u (ndof values) under the nodal loads f (ndof): K u
 * = f on the free DOFs by a banded Cholesky factorisation, u = 0 at fixed
 * DOFs.  Errors: MM_ESINGULAR for a free-free mesh (no static solution
 * without supports), MM_ENOMEM, those of mm_fem_check. */
int mm_fem_static_solve(const mm_fem_problem *p, const double *f, double *u, mm_error *err);

/* ---- transient response ---------------------------------------------------------- */

/* Rayleigh damping C = a M + b K: modal damping ratios
 * zeta_j = a / (2 omega_j) + b omega_j / 2. */
typedef struct mm_fem_damping {
    double a;        /* mass-proportional [1/s], >= 0 */
    double b;        /* stiffness-proportional [s], >= 0 */
} mm_fem_damping;

/* The response by superposition of the first m modes of modes (from
 * mm_fem_modes_solve with shapes; m <= modes->n_modes), starting at rest,
 * each mode exact in time (mm_mdof): a point load through its closed form,
 * a moving load through the exact response to the cubic modal force of
 * each element it crosses (the Hermite interpolation of the mode), free
 * vibration once it has left.  Damping d (NULL: none) gives each mode
 * c_j = a + b omega_j^2.  out[i*nout + r] receives the displacement of
 * global DOF dofs[r] at time t[i] (t nondecreasing, >= 0).  Rigid-body
 * modes are not superposed (the caller excludes free-free meshes or
 * accepts that).  Errors: MM_ERANGE (m), MM_EVALUE (a moving load on a
 * bar), MM_ENOMEM. */
int mm_fem_modal_response(const mm_fem_problem *p, const mm_fem_modes *modes, size_t m,
                          const mm_fem_damping *d, const mm_fem_load *ld, int nt,
                          const double *t, int nout, const size_t *dofs, double *out,
                          mm_error *err);

typedef enum mm_fem_scheme {
    MM_FEM_AVERAGE,  /* Newmark average acceleration: implicit, unconditionally
                        stable; M + h/2 C + h^2/4 K factored once (banded) */
    MM_FEM_CENTRAL   /* central difference: explicit, stable for
                        h < 2 / omega_max (undamped); M + h/2 C factored
                        once (diagonal for a lumped bar mass) */
} mm_fem_scheme;

typedef struct mm_fem_transient {
    mm_fem_scheme scheme;
    double h;                 /* time step > 0 [s] */
    long steps;               /* steps to take, 1..MM_FEM_MAX_STEPS */
    mm_fem_damping damping;   /* Rayleigh; zero for none */
    long stride;              /* history every stride-th step (and step 0) */
    int nout;                 /* DOFs recorded in the history */
    const size_t *dofs;       /* their global indices */
    double *out;              /* (steps / stride + 1) x nout, or NULL */
    int nsnap;                /* full displacement fields to keep */
    const long *snap;         /* at these steps (each 0..steps) */
    double *snaps;            /* nsnap x ndof, or NULL */
    double energy_balance;    /* out: the scheme's energy identity over the
                                 run, max |E~_k - E~_0 - W_k + D_k| over the
                                 largest term, where E~ = 1/2 v'Mv + 1/2 q'Kq
                                 - h^2/2 (1/4 - beta) a'Ma (beta = 1/4 average
                                 acceleration, 0 central difference) and W, D
                                 the trapezoidal rule in q of f and C v: zero
                                 but for rounding, a check of the run */
} mm_fem_transient;

#define MM_FEM_MAX_STEPS 1000000L

/* Integrate M q'' + C q' + K q = f(t) from rest with the load ld by the
 * chosen scheme on the free DOFs (band storage throughout: memory O(ndof),
 * work O(ndof) per step).  Fills tr->out and tr->snaps (fixed DOFs 0).
 * Errors: those of mm_fem_check; MM_ERANGE (h, steps, stride, dofs, snap
 * out of range); MM_ENONFINITE (the motion overflowed: an explicit step
 * past its stability limit; the message says so); MM_ENOMEM. */
int mm_fem_transient_solve(const mm_fem_problem *p, const mm_fem_load *ld, mm_fem_transient *tr,
                           mm_error *err);

/* ---- convergence studies and the bar's closed form (chapter 5, vib-bar-modes, vib-beam-modes) ---- */

/* The relative error of the lowest elastic frequency on nc meshes of the
 * same member: for each i, p with mesh[i] elements solved for one mode
 * (mm_fem_modes_solve, MM_FEM_AUTO), h[i] = L / mesh[i] and e[i] =
 * |omega1 / exact - 1|.  Returns MM_OK or the solver's error with err
 * filled. */
int mm_fem_omega1_errors(const mm_fem_problem *p, int nc, const int *mesh, double exact, double *h, double *e,
                         mm_error *err);

/* The natural frequency of mode j (1-based, elastic) of a uniform bar's
 * mesh in closed form, its dispersion relation: the modes are sampled
 * sines, theta = j pi / n (fixed-fixed, free-free) or (2j - 1) pi / (2n)
 * (fixed-free), s = sin(theta / 2), h = L / n, c = sqrt(E / rho):
 *   omega = (2c/h) s sqrt(3 / (3 - 2 s^2))  consistent mass,
 *   omega = (2c/h) s                         lumped mass
 * (T. J. R. Hughes, The Finite Element Method, sec. 9.2).  p: a bar
 * (MM_FEM_BAR), uniform.  Cannot fail. */
double mm_fem_bar_omega(const mm_fem_problem *p, int j);

/* ---- modal references of a transient run (chapter 5, vib-beam-transient) ---- */

/* Every mode's Newmark recursion (average acceleration at step h,
 * mm_newmark_amplification on the 1-DOF modal equation eta'' + (a + b
 * omega_j^2) eta' + omega_j^2 eta = phi_j^T f(t), from rest) under the
 * load ld, superposed at the global DOF dof at every stride-th of the
 * steps (and step 0): out[steps / stride + 1].  What mm_fem_transient_solve
 * must give at that DOF, to rounding, when md holds every mode (the scheme
 * commutes with the modal decomposition).  *scale receives the largest
 * size of the terms summed, sum |phi_j(dof)| (|eta| + h |eta'| + h^2
 * |eta''|): what that rounding is relative to.  md from mm_fem_modes_solve
 * with shapes.  Returns MM_OK, or MM_ENOMEM or mm_newmark's error with err
 * filled. */
int mm_fem_modal_newmark(const mm_fem_problem *p, const mm_fem_modes *md, const mm_fem_damping *d,
                         const mm_fem_load *ld, double h, long steps, long stride, size_t dof, double *out,
                         double *scale, mm_error *err);

/* The static deflection the first m modes of md miss at the global DOF dof
 * under the load ld at each of the nt times t (modal truncation):
 *   r(t) = (K^-1 f(t))_dof - sum_{j < m} phi_j(dof) phi_j^T f(t) / omega_j^2,
 * into r[nt]; *umax receives the largest |K^-1 f| over those times and the
 * deflection DOFs (every DOF of a bar, every other of a beam).  md from
 * mm_fem_modes_solve with shapes; p must have supports (K regular).
 * Returns MM_OK, or MM_ENOMEM or mm_fem_static_solve's error with err
 * filled. */
int mm_fem_static_residual(const mm_fem_problem *p, const mm_fem_modes *md, size_t m, const mm_fem_load *ld,
                           int nt, const double *t, size_t dof, double *r, double *umax, mm_error *err);

#endif
