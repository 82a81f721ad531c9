/* registry.c — every exercise, in the order of the book's contents, and the
 * titles of the book's chapters and sections.
 *
 * To add an exercise: declare it in its chapter's block below and list it
 * in mm_exercises[] at its section.  Each chapter has its own block in both
 * places, so that work on different chapters never touches the same lines. */
#include <stdio.h>
#include <string.h>

#include "mm_exercise.h"

/* ==== 1 Numerical basics ==== */
extern const mm_exercise mm_ex_num_complex;
extern const mm_exercise mm_ex_num_linear_system;
extern const mm_exercise mm_ex_num_eigen;
extern const mm_exercise mm_ex_num_poly_roots;
extern const mm_exercise mm_ex_num_polyfit;
extern const mm_exercise mm_ex_num_nonlinear_roots;
extern const mm_exercise mm_ex_num_newmark;
extern const mm_exercise mm_ex_num_plot;
/* ==== end of 1 ==== */

/* ==== 2 Kinematics ==== */
extern const mm_exercise mm_ex_kin_particle_path;
extern const mm_exercise mm_ex_kin_relative_motion;
extern const mm_exercise mm_ex_kin_path_coordinates;
extern const mm_exercise mm_ex_kin_rotation_plane;
extern const mm_exercise mm_ex_kin_rigid_rotation;
extern const mm_exercise mm_ex_kin_plane_motion;
extern const mm_exercise mm_ex_kin_space_motion;
extern const mm_exercise mm_ex_kin_rolling_wheel;
extern const mm_exercise mm_ex_kin_mobility;
extern const mm_exercise mm_ex_kin_slider_crank;
extern const mm_exercise mm_ex_kin_four_bar;
extern const mm_exercise mm_ex_kin_cam_follower;
extern const mm_exercise mm_ex_kin_quick_return;
/* ==== end of 2 ==== */

/* ==== 3 Statics ==== */
extern const mm_exercise mm_ex_sta_moment;
extern const mm_exercise mm_ex_sta_force_system;
extern const mm_exercise mm_ex_sta_particle_cables;
extern const mm_exercise mm_ex_sta_plane_body;
extern const mm_exercise mm_ex_sta_space_body;
extern const mm_exercise mm_ex_sta_frame;
extern const mm_exercise mm_ex_sta_truss;
extern const mm_exercise mm_ex_sta_wedge_incline;
extern const mm_exercise mm_ex_sta_journal_bearing;
extern const mm_exercise mm_ex_sta_thrust_bearing;
extern const mm_exercise mm_ex_sta_rolling_resistance;
extern const mm_exercise mm_ex_sta_belt_friction;
extern const mm_exercise mm_ex_sta_centroid;
extern const mm_exercise mm_ex_sta_beam_diagrams;
extern const mm_exercise mm_ex_sta_stability;
extern const mm_exercise mm_ex_sta_virtual_work;
/* ==== end of 3 ==== */

/* ==== 4 Dynamics ==== */
extern const mm_exercise mm_ex_dyn_pendulum;
extern const mm_exercise mm_ex_dyn_double_pendulum;
extern const mm_exercise mm_ex_dyn_robot_2link;
extern const mm_exercise mm_ex_dyn_slider_crank;
/* ==== end of 4 ==== */

/* ==== 5 Vibrations, 5.2-5.9 ==== */
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
/* ==== end of 5.2-5.9 ==== */

/* ==== 5 Vibrations, 5.10-5.12 ==== */
extern const mm_exercise mm_ex_vib_2dof;
extern const mm_exercise mm_ex_vib_absorber;
extern const mm_exercise mm_ex_vib_2dof_transient;
extern const mm_exercise mm_ex_vib_chain_modes;
extern const mm_exercise mm_ex_vib_ndof_transient;
extern const mm_exercise mm_ex_vib_bar_modes;
extern const mm_exercise mm_ex_vib_bar_wave;
extern const mm_exercise mm_ex_vib_beam_modes;
extern const mm_exercise mm_ex_vib_beam_transient;
/* ==== end of 5.10-5.12 ==== */

const mm_exercise *const mm_exercises[] = {
    /* ==== 1 Numerical basics ==== */
    &mm_ex_num_complex,
    &mm_ex_num_linear_system,
    &mm_ex_num_eigen,
    &mm_ex_num_poly_roots,
    &mm_ex_num_polyfit,
    &mm_ex_num_nonlinear_roots,
    &mm_ex_num_newmark,
    &mm_ex_num_plot,
    /* ==== end of 1 ==== */

    /* ==== 2 Kinematics ==== */
    &mm_ex_kin_particle_path,
    &mm_ex_kin_relative_motion,
    &mm_ex_kin_path_coordinates,
    &mm_ex_kin_rotation_plane,
    &mm_ex_kin_rigid_rotation,
    &mm_ex_kin_plane_motion,
    &mm_ex_kin_space_motion,
    &mm_ex_kin_rolling_wheel,
    &mm_ex_kin_mobility,
    &mm_ex_kin_slider_crank,
    &mm_ex_kin_four_bar,
    &mm_ex_kin_cam_follower,
    &mm_ex_kin_quick_return,
    /* ==== end of 2 ==== */

    /* ==== 3 Statics ==== */
    &mm_ex_sta_moment,
    &mm_ex_sta_force_system,
    &mm_ex_sta_particle_cables,
    &mm_ex_sta_plane_body,
    &mm_ex_sta_space_body,
    &mm_ex_sta_frame,
    &mm_ex_sta_truss,
    &mm_ex_sta_wedge_incline,
    &mm_ex_sta_journal_bearing,
    &mm_ex_sta_thrust_bearing,
    &mm_ex_sta_rolling_resistance,
    &mm_ex_sta_belt_friction,
    &mm_ex_sta_centroid,
    &mm_ex_sta_beam_diagrams,
    &mm_ex_sta_stability,
    &mm_ex_sta_virtual_work,
    /* ==== end of 3 ==== */

    /* ==== 4 Dynamics ==== */
    &mm_ex_dyn_pendulum,
    &mm_ex_dyn_double_pendulum,
    &mm_ex_dyn_robot_2link,
    &mm_ex_dyn_slider_crank,
    /* ==== end of 4 ==== */

    /* ==== 5 Vibrations, 5.2-5.9 ==== */
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
    /* ==== end of 5.2-5.9 ==== */

    /* ==== 5 Vibrations, 5.10-5.12 ==== */
    &mm_ex_vib_2dof,
    &mm_ex_vib_absorber,
    &mm_ex_vib_2dof_transient,
    &mm_ex_vib_chain_modes,
    &mm_ex_vib_ndof_transient,
    &mm_ex_vib_bar_modes,
    &mm_ex_vib_bar_wave,
    &mm_ex_vib_beam_modes,
    &mm_ex_vib_beam_transient,
    /* ==== end of 5.10-5.12 ==== */
};

const int mm_exercise_count = MM_COUNT(mm_exercises);

const mm_exercise *mm_exercise_find(const char *id)
{
    for (int i = 0; i < mm_exercise_count; i++)
        if (strcmp(mm_exercises[i]->id, id) == 0)
            return mm_exercises[i];
    return NULL;
}

/* ---- the book's contents (seed/: "Mechanics with Matlab", 2001) ------------- */

const char *mm_chapter_title(int chapter)
{
    static const char *const titles[] = {
        "", "Numerical basics", "Kinematics", "Statics", "Dynamics", "Vibrations",
    };
    return chapter >= 1 && chapter <= 5 ? titles[chapter] : "";
}

static const struct { const char *number, *title; } sections[] = {
    {"1.4", "MATLAB basics"},
    {"1.4.1", "Basic calculations"},
    {"1.4.2", "Solving linear algebra problems"},
    {"1.4.3", "Plotting data"},
    {"2.2", "Kinematics of a particle: rectilinear and curvilinear motion"},
    {"2.2.1", "Position, velocity and acceleration vectors"},
    {"2.2.2", "Average and instantaneous velocities"},
    {"2.2.3", "Average and instantaneous acceleration"},
    {"2.2.4", "Absolute frame"},
    {"2.2.5", "Tangential and normal coordinates"},
    {"2.2.6", "Rotation around a fixed point in a plane"},
    {"2.3", "Kinematics of a rigid body"},
    {"2.3.1", "Translation"},
    {"2.3.2", "Rotation about a fixed axis"},
    {"2.3.3", "Motion in a plane"},
    {"2.3.4", "General motion in space"},
    {"2.3.5", "Rolling without slipping"},
    {"2.4", "Kinematics of systems of rigid bodies"},
    {"2.4.1", "Mechanisms"},
    {"2.4.2", "Degrees of freedom"},
    {"2.4.3", "Lower pairs and higher pairs"},
    {"2.4.4", "Kinematics exercises"},
    {"3.1", "Basic concepts"},
    {"3.1.1", "Force"},
    {"3.1.2", "Moment of a force about a point"},
    {"3.2", "Moment of a force about an axis"},
    {"3.2.1", "Couples of forces"},
    {"3.2.2", "Principle of transmissibility"},
    {"3.2.3", "Force systems"},
    {"3.2.4", "Equivalence of two systems of forces"},
    {"3.2.5", "Equilibrium of force systems"},
    {"3.3", "Equilibrium of a particle"},
    {"3.4", "Equilibrium of a rigid body in a plane"},
    {"3.5", "Equilibrium of a rigid body in space"},
    {"3.6", "Systems of rigid bodies"},
    {"3.7", "Trusses"},
    {"3.8", "Bodies and systems of bodies with friction"},
    {"3.8.1", "Journal bearing"},
    {"3.8.2", "Thrust bearing"},
    {"3.8.3", "Rolling resistance"},
    {"3.8.4", "Belt friction"},
    {"3.9", "Centre of gravity"},
    {"3.10", "Internal forces in a body"},
    {"3.11", "Work and potential energy"},
    {"3.12", "Principle of virtual work"},
    {"4.2", "Mechanical modelling"},
    {"4.2.1", "Elements of multibody systems"},
    {"4.2.2", "System forces"},
    {"4.2.3", "Kinematical constraints"},
    {"4.3", "Mathematical modelling"},
    {"4.3.1", "Introduction to mathematical modelling"},
    {"4.3.2", "Mathematical models and procedures"},
    {"4.3.3", "Formulation of governing equations of mechanical systems"},
    {"4.4", "Computational procedures in dynamic analysis"},
    {"4.4.2", "Dynamics of a robot"},
    {"4.4.3", "Dynamics of a slider-crank mechanism"},
    {"5.2", "Harmonic and periodic motions"},
    {"5.3", "Phase and group velocities"},
    {"5.4", "Fourier series"},
    {"5.5", "Fourier integral"},
    {"5.6", "Discrete Fourier series"},
    {"5.7", "Deriving governing equations"},
    {"5.8", "Numerical methods"},
    {"5.8.1", "Numerical methods for steady-state vibration"},
    {"5.8.2", "Numerical methods for transient problems"},
    {"5.9", "Vibration with one degree of freedom"},
    {"5.9.1", "Undamped free vibration"},
    {"5.9.2", "Undamped forced vibration"},
    {"5.9.3", "Damped vibration"},
    {"5.9.4", "Overdamped, critically damped and underdamped vibration"},
    {"5.9.5", "A vibrating system attached to a moving support"},
    {"5.9.6", "Behaviour at resonance"},
    {"5.9.7", "Vibration with Coulomb friction"},
    {"5.10", "Systems with two degrees of freedom"},
    {"5.10.1", "Undamped free and forced vibration with two degrees of freedom"},
    {"5.10.2", "Analytical and numerical approaches to the transient"},
    {"5.11", "Systems with n degrees of freedom"},
    {"5.11.1", "Vibration of a linear system with n degrees of freedom"},
    {"5.12", "Continuous systems and their discretizations"},
    {"5.12.1", "Bars"},
    {"5.12.2", "Beams"},
};

const char *mm_section_title(const char *section)
{
    char s[16];
    if (!section || strlen(section) >= sizeof s)
        return "";
    snprintf(s, sizeof s, "%s", section);
    for (;;) {                                   /* "2.2.3" -> "2.2" -> "2" */
        for (size_t i = 0; i < sizeof sections / sizeof sections[0]; i++)
            if (strcmp(sections[i].number, s) == 0)
                return sections[i].title;
        char *dot = strrchr(s, '.');
        if (!dot)
            return "";
        *dot = '\0';
    }
}

/* ---- checking the tables ---------------------------------------------------------- */

static int is_ident(const char *s)
{
    if (!s || !((*s >= 'a' && *s <= 'z') || (*s >= 'A' && *s <= 'Z')))
        return 0;
    for (; *s; s++)
        if (!((*s >= 'a' && *s <= 'z') || (*s >= 'A' && *s <= 'Z') || (*s >= '0' && *s <= '9') || *s == '_'))
            return 0;
    return 1;
}

static int check_outputs(const mm_exercise *ex, mm_error *err)
{
    int animations = 0;
    for (int i = 0; i < ex->n_outputs; i++) {
        const mm_output *o = &ex->outputs[i];
        if (!o->name || !o->label || !o->kind)
            return mm_error_set(err, MM_EINTERNAL, "", "%s: output %d lacks a name, label or kind", ex->id, i);
        int n = mm_output_count(o);
        if (n < 1)
            return mm_error_set(err, MM_EINTERNAL, o->name, "%s: family %s has no members", ex->id, o->name);
        for (int k = 0; k < n; k++) {
            char name[128];
            if (mm_output_member(o, mm_output_index(o, k), name, sizeof name) != 0 || !is_ident(name))
                return mm_error_set(err, MM_EINTERNAL, o->name, "%s: output name '%s' is not an identifier",
                                    ex->id, name);
            for (int j = 0; j <= i; j++) {       /* unique across every member of every output */
                const mm_output *q = &ex->outputs[j];
                for (int m = 0; m < (j == i ? k : mm_output_count(q)); m++) {
                    char other[128];
                    mm_output_member(q, mm_output_index(q, m), other, sizeof other);
                    if (strcmp(name, other) == 0 && q->kind == o->kind)
                        return mm_error_set(err, MM_EINTERNAL, o->name, "%s: output %s declared twice",
                                            ex->id, name);
                }
            }
        }
        if (o->kind == MM_OUT_TABLE) {
            int nc = 0, nu = 0;
            while (o->columns && o->columns[nc])
                nc++;
            while (o->units && o->units[nu])
                nu++;
            if (nc == 0 || nc != nu)
                return mm_error_set(err, MM_EINTERNAL, o->name,
                                    "%s: table %s needs NULL-terminated columns and as many units",
                                    ex->id, o->name);
        }
        if (o->kind == MM_OUT_SERIES && !o->x_label)
            return mm_error_set(err, MM_EINTERNAL, o->name, "%s: series %s has no x_label", ex->id, o->name);
        if (o->kind == MM_OUT_ANIMATION && animations++)
            return mm_error_set(err, MM_EINTERNAL, o->name, "%s: more than one animation", ex->id);
        if ((o->flags & (MM_ANSWER | MM_EXACT)) && o->kind != MM_OUT_SCALAR)
            return mm_error_set(err, MM_EINTERNAL, o->name, "%s: only scalars are answers or exact", ex->id);
    }
    return MM_OK;
}

int mm_exercise_check(const mm_exercise *ex, mm_error *err)
{
    static const char *const prefix[] = {"", "num-", "kin-", "sta-", "dyn-", "vib-"};
    if (!ex->id || ex->chapter < 1 || ex->chapter > 5 ||
        strncmp(ex->id, prefix[ex->chapter], 4) != 0 || strlen(ex->id) > 40)
        return mm_error_set(err, MM_EINTERNAL, "", "id '%s' does not match its chapter %d",
                            ex->id ? ex->id : "(null)", ex->chapter);
    if (!ex->section || ex->section[0] != '0' + ex->chapter || !mm_section_title(ex->section)[0])
        return mm_error_set(err, MM_EINTERNAL, "", "%s: section '%s' is not in chapter %d's contents",
                            ex->id, ex->section ? ex->section : "(null)", ex->chapter);
    if (!ex->title || !ex->summary || !ex->theory || !ex->solve)
        return mm_error_set(err, MM_EINTERNAL, "", "%s: title, summary, theory and solve are required", ex->id);
    return check_outputs(ex, err);
}

int mm_registry_check(mm_error *err)
{
    for (int i = 0; i < mm_exercise_count; i++) {
        const mm_exercise *ex = mm_exercises[i];
        int rc = mm_exercise_check(ex, err);
        if (rc != MM_OK)
            return rc;
        for (int j = 0; j < i; j++)
            if (strcmp(mm_exercises[j]->id, ex->id) == 0)
                return mm_error_set(err, MM_EINTERNAL, "", "%s is registered twice", ex->id);
        if (i > 0 && mm_exercises[i - 1]->chapter > ex->chapter)
            return mm_error_set(err, MM_EINTERNAL, "", "%s: not in book order", ex->id);
    }
    return MM_OK;
}
