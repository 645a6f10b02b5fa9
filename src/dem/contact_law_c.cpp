#include "mdr/dem/contact_law_c.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "mdr/dem/contact_law.hpp"
#include "mdr/error.hpp"

struct mdr_contact_law {
    mdr::dem::ContactLaw law;
    std::vector<double> scratch;  ///< a step's state until it succeeded: a failed step leaves the caller's alone
};

namespace {

void write_message(const std::string& text, char* message, std::size_t message_size) {
    if (message == nullptr || message_size == 0) return;
    const std::size_t length = std::min(text.size(), message_size - 1);
    std::memcpy(message, text.data(), length);
    message[length] = '\0';
}

mdr::rheology::Rheology material_of(const mdr_prony_material* material, const char* name) {
    if (material == nullptr) throw mdr::InvalidInput(name, "NULL", "a material is required");
    if (material->terms > 0 && (material->moduli == nullptr || material->relaxation_times == nullptr)) {
        throw mdr::InvalidInput(std::string(name) + ".moduli", "NULL", "terms > 0 needs both arrays");
    }
    std::vector<mdr::rheology::RelaxationTerm> terms(material->terms);
    for (std::size_t k = 0; k < terms.size(); ++k) terms[k] = {material->moduli[k], material->relaxation_times[k]};
    try {
        return mdr::rheology::Rheology::prony(material->equilibrium_modulus, std::move(terms));
    } catch (const mdr::InvalidInput& error) {
        throw error.with_prefix(std::string(name) + ".");
    }
}

// Runs `body`; an exception becomes MDR_INVALID_INPUT (or a message for anything else) in the caller's buffer.
template <typename Body>
int guarded(Body&& body, char* message, std::size_t message_size) {
    try {
        body();
        return MDR_OK;
    } catch (const mdr::InvalidInput& error) {
        write_message(error.what(), message, message_size);
    } catch (const std::exception& error) {
        write_message(error.what(), message, message_size);
    }
    return MDR_INVALID_INPUT;
}

}  // namespace

extern "C" {

mdr_contact_law* mdr_contact_law_create(const mdr_prony_material* first, const mdr_prony_material* second,
                                        double radius, double friction, std::size_t elements, double half_width,
                                        double time_step, char* message, std::size_t message_size) {
    mdr_contact_law* created = nullptr;
    guarded(
        [&] {
            const auto material = mdr::rheology::in_series(material_of(first, "first"), material_of(second, "second"));
            mdr::dem::ContactLaw law(material, radius, friction, elements, half_width, time_step);
            const std::size_t size = law.state_size();
            created = new mdr_contact_law{std::move(law), std::vector<double>(size)};
        },
        message, message_size);
    return created;
}

void mdr_contact_law_destroy(mdr_contact_law* law) { delete law; }

std::size_t mdr_contact_law_state_size(const mdr_contact_law* law) { return law->law.state_size(); }

void mdr_contact_law_initialise(const mdr_contact_law* law, double* state) {
    law->law.initialise(std::span<double>(state, law->law.state_size()));
}

int mdr_contact_law_step(mdr_contact_law* law, double* state, double time_step, double overlap, const double normal[3],
                         const double increment[3], double force[3], char* message, std::size_t message_size) {
    return guarded(
        [&] {
            const std::size_t size = law->law.state_size();
            std::copy_n(state, size, law->scratch.data());
            law->law.set_time_step(time_step);
            const mdr::dem::SpatialVector n{normal[0], normal[1], normal[2]};
            const auto tangential = law->law.advance_spatial(law->scratch, overlap, n,
                                                             {increment[0], increment[1], increment[2]});
            const double normal_force = law->law.normal_force();
            for (int i = 0; i < 3; ++i) force[i] = normal_force * n[static_cast<std::size_t>(i)] +
                                                   tangential[static_cast<std::size_t>(i)];
            std::copy_n(law->scratch.data(), size, state);
        },
        message, message_size);
}

int mdr_contact_law_step_pair(mdr_contact_law* law, double* first_state, double* second_state, double time_step,
                              const double overlaps[2], const double normals[2][3], const double increments[2][3],
                              double forces[2][3], double works[2], int* stepped, char* message,
                              std::size_t message_size) {
    return guarded(
        [&] {
            *stepped = 0;
            law->law.set_time_step(time_step);
            const std::size_t size = law->law.state_size();
            std::array<mdr::dem::ContactLaw::SpatialStep, 2> steps;
            double* states[2] = {first_state, second_state};
            for (std::size_t c = 0; c < 2; ++c) {
                steps[c] = {{states[c], size},
                            overlaps[c],
                            {normals[c][0], normals[c][1], normals[c][2]},
                            {increments[c][0], increments[c][1], increments[c][2]}};
            }
            std::array<mdr::dem::ContactLaw::SpatialOutcome, 2> outcomes;
            if (!law->law.advance_spatial_pair(steps[0], steps[1], outcomes)) return;
            for (std::size_t c = 0; c < 2; ++c) {
                // the total force as mdr_contact_law_step's: F_N n + F_t
                const double normal_force = law->law.normal_force(steps[c].state);
                for (std::size_t i = 0; i < 3; ++i) {
                    forces[c][i] = normal_force * steps[c].normal[i] + outcomes[c].tangential_force[i];
                }
                works[c] = outcomes[c].work;
            }
            *stepped = 1;
        },
        message, message_size);
}

void mdr_contact_law_mirror(double* state) {
    mdr::dem::ContactLaw::mirror(std::span<double>(state, 6));
}

int mdr_contact_law_check(const mdr_contact_law* law, const double* state, std::size_t size, char* message,
                          std::size_t message_size) {
    return guarded([&] { law->law.check(std::span<const double>(state, size)); }, message, message_size);
}

double mdr_contact_law_normal_force(const mdr_contact_law* law, const double* state) {
    return law->law.normal_force(std::span<const double>(state, law->law.state_size()));
}

double mdr_contact_law_step_work(const mdr_contact_law* law) { return law->law.step_work(); }

int mdr_contact_law_stored_energy(const mdr_contact_law* law, const double* state, double* energy, char* message,
                                  std::size_t message_size) {
    return guarded([&] { *energy = law->law.stored_energy(std::span<const double>(state, law->law.state_size())); },
                   message, message_size);
}

}  // extern "C"
