/* test_fem_modal.c — the modal references of a transient beam run
 * (mm_fem, vibration chapter): every mode's Newmark recursion superposed
 * against the direct banded Newmark run on every DOF (the scheme commutes
 * with the modal decomposition: the two agree to rounding), and the static
 * residual of modal truncation against the modes left out (K^-1 = sum
 * phi phi^T / omega^2). */
#include "mm_test.h"

#include <float.h>
#include <stdlib.h>

#include "mm_fem.h"

#define EPS DBL_EPSILON

static mm_fem_problem beam(mm_fem_bc bc, size_t n_el)
{
    return (mm_fem_problem){MM_FEM_BEAM, bc, MM_FEM_CONSISTENT, n_el, {2, 2.1e11, 1e-4, 1e-8, 7850}, NULL};
}

/* Every mode of the mesh (dense), so the superposition is the whole motion. */
static size_t all_modes(const mm_fem_problem *p, double *w, double *sh)
{
    mm_fem_options o;
    mm_fem_options_init(&o);
    o.method = MM_FEM_DENSE;
    mm_fem_modes md = {w, sh, 0, 0, 0, MM_FEM_AUTO};
    mm_error err;
    size_t nf = mm_fem_ndof(p) - (p->bc == MM_FEM_FIXED_FIXED ? 4 : 2);
    assert_int_equal(mm_fem_modes_solve(p, nf, &o, &md, &err), MM_OK);
    assert_int_equal(md.n_modes, nf);
    return nf;
}

static void modal_newmark_should_be_the_direct_run(void **state)
{
    (void)state;
    enum { NEL = 8, ND = 2 * (NEL + 1), STEPS = 400, STRIDE = 8, ROWS = STEPS / STRIDE + 1 };
    static const mm_fem_bc bcs[2] = {MM_FEM_PINNED_PINNED, MM_FEM_FIXED_FREE};
    /* a force crossing the span, and a pulse at 0.7 L */
    static const mm_fem_load loads[2] = {{MM_FEM_LOAD_MOVING, -100, 0, 0, INFINITY, 80},
                                         {MM_FEM_LOAD_POINT, 50, 1.4, 0, 3e-3, 0}};
    double w[ND], *sh = malloc(ND * ND * sizeof *sh), h = 5e-5;
    for (int b = 0; b < 2; b++)
        for (int l = 0; l < 2; l++) {
            mm_fem_problem p = beam(bcs[b], NEL);
            mm_fem_modes md = {w, sh, all_modes(&p, w, sh), 0, 0, MM_FEM_DENSE};
            mm_fem_damping d = {3, 1e-5};
            size_t dof = 2 * 5;
            double direct[ROWS], modal[ROWS], scale;
            mm_fem_transient tr = {MM_FEM_AVERAGE, h, STEPS, d, STRIDE, 1, &dof, direct, 0, NULL, NULL, 0};
            mm_error err;
            assert_int_equal(mm_fem_transient_solve(&p, &loads[l], &tr, &err), MM_OK);
            assert_int_equal(mm_fem_modal_newmark(&p, &md, &d, &loads[l], h, STEPS, STRIDE, dof, modal, &scale, &err),
                             MM_OK);
            double dd = 0, big = 0;
            for (int i = 0; i < ROWS; i++) {
                dd = fmax(dd, fabs(direct[i] - modal[i]));
                big = fmax(big, fabs(direct[i]));
            }
            assert_true(big > 0);
            /* rounding: a few eps a step of the terms summed (measured: at most
             * 5.3 eps steps scale over these four runs) */
            check_abs(dd, 0, 32 * EPS * STEPS * scale, "direct run vs modal Newmark, at the probe");
        }
    free(sh);
}

static void static_residual_should_be_what_the_left_out_modes_carry(void **state)
{
    (void)state;
    enum { NEL = 6, ND = 2 * (NEL + 1), NT = 5 };
    double w[ND], *sh = malloc(ND * ND * sizeof *sh), t[NT] = {0, 1e-3, 2e-3, 4e-3, 9e-3}, r[NT], worst = 0;
    mm_fem_problem p = beam(MM_FEM_FIXED_FIXED, NEL);
    size_t nf = all_modes(&p, w, sh), dof = 2 * 2;
    mm_fem_modes md = {w, sh, nf, 0, 0, MM_FEM_DENSE};
    mm_fem_load ld = {MM_FEM_LOAD_POINT, 70, 0.9, 0, 3e-3, 0};      /* a pulse: off from 3 ms */
    mm_error err;
    double umax, f[ND];
    for (size_t m = 0; m <= nf; m++) {
        assert_int_equal(mm_fem_static_residual(&p, &md, m, &ld, NT, t, dof, r, &umax, &err), MM_OK);
        for (int i = 0; i < NT; i++) {
            mm_fem_load_vector(&p, &ld, t[i], f);
            double left = 0;
            for (size_t j = m; j < nf; j++) {
                double pj = 0;
                for (size_t g = 0; g < ND; g++)
                    pj += sh[j * ND + g] * f[g];
                left += sh[j * ND + dof] * pj / (w[j] * w[j]);
            }
            if (t[i] >= 3e-3)
                assert_true(r[i] == 0);                 /* the pulse is off: nothing to deflect */
            worst = fmax(worst, fabs(r[i] - left) / umax);
        }
    }
    assert_true(umax > 0);
    /* rounding of the solve and the modes: eps times cond(K) ~
     * (omega_max / omega_1)^2 (measured: 0.04 of it) */
    double kappa = (w[nf - 1] / w[0]) * (w[nf - 1] / w[0]);
    check_abs(worst, 0, 0.5 * EPS * kappa, "r against the left-out modes, relative to the largest deflection");
    free(sh);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(modal_newmark_should_be_the_direct_run),
        cmocka_unit_test(static_residual_should_be_what_the_left_out_modes_carry),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
