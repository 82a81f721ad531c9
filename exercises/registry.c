/* registry.c — every exercise, in the order of the book's contents.
 * To add one: declare it below and list it in mm_exercises[] at its section. */
#include <string.h>

#include "mm_exercise.h"

extern const mm_exercise mm_ex_num_complex;
extern const mm_exercise mm_ex_num_linear_system;
extern const mm_exercise mm_ex_num_eigen;
extern const mm_exercise mm_ex_num_poly_roots;
extern const mm_exercise mm_ex_num_polyfit;
extern const mm_exercise mm_ex_num_nonlinear_roots;
extern const mm_exercise mm_ex_num_newmark;
extern const mm_exercise mm_ex_num_plot;
extern const mm_exercise mm_ex_vib_harmonics;
extern const mm_exercise mm_ex_vib_dispersion;
extern const mm_exercise mm_ex_vib_fourier_series;
extern const mm_exercise mm_ex_vib_fourier_transform;
extern const mm_exercise mm_ex_vib_dft;
extern const mm_exercise mm_ex_vib_integrators;
extern const mm_exercise mm_ex_vib_sdof_free;
extern const mm_exercise mm_ex_vib_sdof_forced;
extern const mm_exercise mm_ex_vib_frequency_response;
extern const mm_exercise mm_ex_vib_base_excitation;
extern const mm_exercise mm_ex_vib_resonance;
extern const mm_exercise mm_ex_vib_coulomb;

const mm_exercise *const mm_exercises[] = {
    /* 1 Numerical basics */
    &mm_ex_num_complex,
    &mm_ex_num_linear_system,
    &mm_ex_num_eigen,
    &mm_ex_num_poly_roots,
    &mm_ex_num_polyfit,
    &mm_ex_num_nonlinear_roots,
    &mm_ex_num_newmark,
    &mm_ex_num_plot,
    /* 5 Vibrations */
    &mm_ex_vib_harmonics,
    &mm_ex_vib_dispersion,
    &mm_ex_vib_fourier_series,
    &mm_ex_vib_fourier_transform,
    &mm_ex_vib_dft,
    &mm_ex_vib_integrators,
    &mm_ex_vib_sdof_free,
    &mm_ex_vib_sdof_forced,
    &mm_ex_vib_frequency_response,
    &mm_ex_vib_base_excitation,
    &mm_ex_vib_resonance,
    &mm_ex_vib_coulomb,
};

const int mm_exercise_count = MM_COUNT(mm_exercises);

const mm_exercise *mm_exercise_find(const char *id)
{
    for (int i = 0; i < mm_exercise_count; i++)
        if (strcmp(mm_exercises[i]->id, id) == 0)
            return mm_exercises[i];
    return NULL;
}
