/* The DEM contact law (mdr/dem/contact_law.hpp) for engines and codes written in C or Fortran: an opaque law
 * object, each contact's state in the caller's memory, plain return codes and messages in a caller's buffer.
 * Link against mdr::core (C++ runtime). */
#ifndef MDR_DEM_CONTACT_LAW_C_H
#define MDR_DEM_CONTACT_LAW_C_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/** A viscoelastic body's shear relaxation modulus as a Prony series, G(t) = equilibrium_modulus +
 *  sum_k moduli[k] exp(-t / relaxation_times[k]) [Pa, s]; `terms` entries in each array (none when 0). */
typedef struct mdr_prony_material {
    double equilibrium_modulus;
    size_t terms;
    const double* moduli;
    const double* relaxation_times;
} mdr_prony_material;

/** The law of one kind of contact: two sphere materials in series, the equivalent radius, the friction, the
 *  resolution, and a workspace (one per thread). */
typedef struct mdr_contact_law mdr_contact_law;

/** Return codes: success, and bad input (the message names the parameter, its value and the rule). */
enum { MDR_OK = 0, MDR_INVALID_INPUT = 2 };

/** A law for two spheres of materials `first` and `second` (both incompressible), equivalent radius `radius`
 *  R1 R2 / (R1 + R2) [m], friction coefficient `friction` >= 0, `elements` N on the half-width `half_width` [m]
 *  (at least the largest contact radius), first time step `time_step` [s]. NULL on bad input, with the reason in
 *  `message` (at most `message_size` bytes with the final 0; `message` may be NULL). */
mdr_contact_law* mdr_contact_law_create(const mdr_prony_material* first, const mdr_prony_material* second,
                                        double radius, double friction, size_t elements, double half_width,
                                        double time_step, char* message, size_t message_size);
/** Frees a law (NULL is allowed). */
void mdr_contact_law_destroy(mdr_contact_law* law);
/** Doubles of one contact's state. */
size_t mdr_contact_law_state_size(const mdr_contact_law* law);
/** Zeroes a contact's state at first touch. */
void mdr_contact_law_initialise(const mdr_contact_law* law, double* state);
/** One step of length `time_step` [s] of a contact: `overlap` [m] at the end of the step, `normal` the unit normal
 *  from the first body to the second, `increment` [m] the displacement of the first body's contact point relative
 *  to the second's over the step. Writes the total force [N] on the second body into `force` (the first feels its
 *  opposite). MDR_INVALID_INPUT (state unchanged) for a bad time step, a corrupted state, an overlap, normal or
 *  increment that is not finite, or a contact beyond the half-width. */
int mdr_contact_law_step(mdr_contact_law* law, double* state, double time_step, double overlap, const double normal[3],
                         const double increment[3], double force[3], char* message, size_t message_size);
/** Two contacts' steps of length `time_step` [s] at once where both are held (no element entering or leaving normal
 *  contact and, with friction, every element in contact certainly sticking: a settled packing's contacts), each
 *  contact in one lane of the vector registers: `overlaps` [2], `normals` and `increments` [2][3] as
 *  mdr_contact_law_step's, the two contacts' total forces into `forces` [2][3] and their step works [J] into
 *  `works` [2], to the bit those of two mdr_contact_law_step calls. `*stepped` 1 where it stepped both, 0 where it
 *  wrote nothing (step each with mdr_contact_law_step then, which reports bad input). MDR_INVALID_INPUT (nothing
 *  written) for a bad time step. */
int mdr_contact_law_step_pair(mdr_contact_law* law, double* first_state, double* second_state, double time_step,
                              const double overlaps[2], const double normals[2][3], const double increments[2][3],
                              double forces[2][3], double works[2], int* stepped, char* message, size_t message_size);
/** Turns a contact's state into that of the same contact with the two bodies swapped. */
void mdr_contact_law_mirror(double* state);
/** MDR_OK when `state` (`size` doubles) is one this law could have written (e.g. read back from a restart). */
int mdr_contact_law_check(const mdr_contact_law* law, const double* state, size_t size, char* message,
                          size_t message_size);
/** Normal force [N] stored in a contact's state. */
double mdr_contact_law_normal_force(const mdr_contact_law* law, const double* state);
/** Work [J] the bodies did on the contact over the law's last step (the trapezoidal rule on its forces). */
double mdr_contact_law_step_work(const mdr_contact_law* law);
/** Writes the elastic energy [J] stored in a contact's state into `energy`; the summed step work less it is what the
 *  contact dissipated. MDR_INVALID_INPUT (`energy` unchanged) for a corrupted state. */
int mdr_contact_law_stored_energy(const mdr_contact_law* law, const double* state, double* energy, char* message,
                                  size_t message_size);

#ifdef __cplusplus
}
#endif

#endif
