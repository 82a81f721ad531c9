/* test_fem_closed.c — the closed forms of the bar's mesh and the
 * convergence study of mm_fem (vibration chapter): mm_fem_bar_omega, the
 * mesh's dispersion relation, against every frequency LAPACK finds in the
 * assembled matrices (each end condition, both masses); and
 * mm_fem_omega1_errors against the errors that closed form gives, with the
 * order h^2 it must show. */
#include "mm_test.h"

#include <float.h>

#include "mm_fem.h"

#define EPS DBL_EPSILON

static mm_fem_problem bar(mm_fem_bc bc, mm_fem_mass mass, size_t n_el)
{
    return (mm_fem_problem){MM_FEM_BAR, bc, mass, n_el, {2.0, 7e10, 3e-4, 0, 2700}, NULL};
}

/* Every elastic mode of a 16-element mesh: the closed form against dsygvd,
 * within the eigen solver's rounding, eps omega_max^2 / omega_j^2 relative
 * (measured: 2 times that at most). */
static void bar_omega_should_be_every_frequency_of_the_mesh(void **state)
{
    (void)state;
    static const mm_fem_bc bcs[3] = {MM_FEM_FIXED_FREE, MM_FEM_FIXED_FIXED, MM_FEM_FREE_FREE};
    enum { N = 16 };
    for (int b = 0; b < 3; b++)
        for (int k = 0; k < 2; k++) {
            mm_fem_problem p = bar(bcs[b], k ? MM_FEM_LUMPED : MM_FEM_CONSISTENT, N);
            double w[N];
            mm_fem_options o;
            mm_fem_options_init(&o);
            o.method = MM_FEM_DENSE;
            mm_fem_modes md = {w, NULL, 0, 0, 0, MM_FEM_AUTO};
            mm_error err;
            size_t nm = bcs[b] == MM_FEM_FIXED_FIXED ? N - 1 : N - (bcs[b] == MM_FEM_FREE_FREE);
            assert_int_equal(mm_fem_modes_solve(&p, nm, &o, &md, &err), MM_OK);
            assert_int_equal(md.n_modes, nm);
            double top = w[nm - 1];
            for (size_t j = 0; j < nm; j++) {
                double f = mm_fem_bar_omega(&p, (int)j + 1), bound = EPS * (top / f) * (top / f);
                check_rel(w[j], f, 8 * bound, "omega_j: dsygvd vs the dispersion relation");
            }
        }
}

/* The errors of omega1 on 4 .. 64 elements: each the closed form's, and
 * falling like h^2 (consistent mass from above, lumped from below: both
 * with slope 2 between the finest meshes, to 1 %). */
static void omega1_errors_should_follow_the_closed_form(void **state)
{
    (void)state;
    enum { NC = 5 };
    static const int mesh[NC] = {4, 8, 16, 32, 64};
    for (int k = 0; k < 2; k++) {
        mm_fem_problem p = bar(MM_FEM_FIXED_FREE, k ? MM_FEM_LUMPED : MM_FEM_CONSISTENT, 10);
        double c = sqrt(p.uniform.E / p.uniform.rho), exact = M_PI * c / (2 * p.uniform.L), h[NC], e[NC];
        mm_error err;
        assert_int_equal(mm_fem_omega1_errors(&p, NC, mesh, exact, h, e, &err), MM_OK);
        for (int i = 0; i < NC; i++) {
            mm_fem_problem pm = p;
            pm.n_el = (size_t)mesh[i];
            check_rel(h[i], p.uniform.L / mesh[i], 0, "h = L / elements");
            /* omega1 to the eigen solver's rounding, eps (omega_max / omega1)^2
             * ~ eps (4 n / pi)^2 (measured: 0.04 of it) */
            double tol = EPS * (4.0 * mesh[i] / M_PI) * (4.0 * mesh[i] / M_PI);
            check_abs(e[i], fabs(mm_fem_bar_omega(&pm, 1) / exact - 1), tol, "e_i: the closed form's error");
        }
        check_rel(log(e[NC - 2] / e[NC - 1]) / log(2), 2, 0.01, "order h^2 between the finest meshes");
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(bar_omega_should_be_every_frequency_of_the_mesh),
        cmocka_unit_test(omega1_errors_should_follow_the_closed_form),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
