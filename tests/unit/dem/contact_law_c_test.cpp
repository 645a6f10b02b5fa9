// The C interface of the DEM contact law (include/mdr/dem/contact_law_c.h): it steps a contact as the C++ law's
// advance_spatial does, reports bad input through its return code and message (naming the parameter), and leaves a
// contact's state alone when a step fails.

#include "mdr/dem/contact_law_c.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "mdr/dem/contact_law.hpp"

namespace {

const double moduli[] = {3e6};
const double times[] = {1e-3};
const mdr_prony_material standard{1e6, 1, moduli, times};
const mdr_prony_material elastic{2e6, 0, nullptr, nullptr};

TEST(DemContactLawC, StepsAsTheCppLaw) {
    char message[256] = "";
    mdr_contact_law* law = mdr_contact_law_create(&standard, &elastic, 0.005, 0.3, 40, 1e-3, 2e-6, message,
                                                  sizeof message);
    ASSERT_NE(law, nullptr) << message;
    const auto material = mdr::rheology::in_series(mdr::rheology::Rheology::standard(1e6, 3e6, 1e-3),
                                                   mdr::rheology::Rheology::prony(2e6, {}));
    mdr::dem::ContactLaw reference(material, 0.005, 0.3, 40, 1e-3, 2e-6);
    ASSERT_EQ(mdr_contact_law_state_size(law), reference.state_size());
    std::vector<double> state(mdr_contact_law_state_size(law)), expected(reference.state_size());
    mdr_contact_law_initialise(law, state.data());
    reference.initialise(expected);
    const double normal[3] = {0.0, 0.6, 0.8};
    for (int n = 1; n < 300; ++n) {
        const double step = n % 2 == 0 ? 2e-6 : 1e-6;
        const double overlap = 2e-7 * n, increment[3] = {1e-8, 4e-9, -3e-9};
        double force[3];
        ASSERT_EQ(mdr_contact_law_step(law, state.data(), step, overlap, normal, increment, force, message,
                                       sizeof message),
                  MDR_OK)
            << message;
        reference.set_time_step(step);
        const auto tangential = reference.advance_spatial(expected, overlap, {0.0, 0.6, 0.8}, {1e-8, 4e-9, -3e-9});
        const double normal_force = reference.normal_force(expected);
        ASSERT_EQ(mdr_contact_law_normal_force(law, state.data()), normal_force);
        for (std::size_t i = 0; i < 3; ++i) ASSERT_EQ(force[i], normal_force * normal[i] + tangential[i]);
        ASSERT_EQ(mdr_contact_law_step_work(law), reference.step_work());
        double energy = -1.0;
        ASSERT_EQ(mdr_contact_law_stored_energy(law, state.data(), &energy, message, sizeof message), MDR_OK)
            << message;
        ASSERT_EQ(energy, reference.stored_energy(expected));
    }
    EXPECT_EQ(state, expected);
    EXPECT_EQ(mdr_contact_law_check(law, state.data(), state.size(), message, sizeof message), MDR_OK);
    mdr_contact_law_destroy(law);
}

// Two held contacts stepped at once give the states, forces and works of two single steps; a pair it does not take
// (here the first step, at first touch) is left as it was.
TEST(DemContactLawC, APairStepsAsTwoSteps) {
    char message[256] = "";
    mdr_contact_law* law = mdr_contact_law_create(&standard, &elastic, 0.005, 0.3, 40, 1e-3, 2e-6, message,
                                                  sizeof message);
    ASSERT_NE(law, nullptr) << message;
    const std::size_t size = mdr_contact_law_state_size(law);
    std::vector<double> first(size), second(size);
    mdr_contact_law_initialise(law, first.data());
    mdr_contact_law_initialise(law, second.data());
    std::vector<double> single_first = first, single_second = second;
    const double normals[2][3] = {{0.0, 0.6, 0.8}, {0.8, 0.0, -0.6}};
    int paired = 0;
    for (int n = 1; n < 400; ++n) {
        const double overlaps[2] = {2e-7 * std::min(n, 150), 1.5e-7 * std::min(n, 150)};
        const double increments[2][3] = {{1e-12, 4e-13, -3e-13}, {-2e-13, 1e-12, 0.0}};
        double forces[2][3], works[2], expected[2][3], expected_works[2];
        std::vector<double>* singles[2] = {&single_first, &single_second};
        for (int c = 0; c < 2; ++c) {
            ASSERT_EQ(mdr_contact_law_step(law, singles[c]->data(), 2e-6, overlaps[c], normals[c], increments[c],
                                           expected[c], message, sizeof message),
                      MDR_OK)
                << message;
            expected_works[c] = mdr_contact_law_step_work(law);
        }
        const std::vector<double> before_first = first, before_second = second;
        int stepped = -1;
        ASSERT_EQ(mdr_contact_law_step_pair(law, first.data(), second.data(), 2e-6, overlaps, normals, increments,
                                            forces, works, &stepped, message, sizeof message),
                  MDR_OK)
            << message;
        if (stepped == 1) {
            ++paired;
            for (int c = 0; c < 2; ++c) {
                for (int i = 0; i < 3; ++i) ASSERT_EQ(forces[c][i], expected[c][i]) << "step " << n;
                ASSERT_EQ(works[c], expected_works[c]) << "step " << n;
            }
        } else {
            ASSERT_EQ(stepped, 0);
            ASSERT_EQ(first, before_first) << "step " << n;
            ASSERT_EQ(second, before_second) << "step " << n;
            double force[3];
            ASSERT_EQ(mdr_contact_law_step(law, first.data(), 2e-6, overlaps[0], normals[0], increments[0], force,
                                           message, sizeof message),
                      MDR_OK);
            ASSERT_EQ(mdr_contact_law_step(law, second.data(), 2e-6, overlaps[1], normals[1], increments[1], force,
                                           message, sizeof message),
                      MDR_OK);
        }
        ASSERT_EQ(first, single_first) << "step " << n;
        ASSERT_EQ(second, single_second) << "step " << n;
    }
    EXPECT_GT(paired, 200);  // held once loaded (from step 150)
    int stepped = -1;
    double forces[2][3], works[2];
    const double overlaps[2] = {1e-5, 1e-5}, increments[2][3] = {};
    EXPECT_EQ(mdr_contact_law_step_pair(law, first.data(), second.data(), -1.0, overlaps, normals, increments, forces,
                                        works, &stepped, message, sizeof message),
              MDR_INVALID_INPUT);
    EXPECT_NE(std::string(message).find("time_step"), std::string::npos) << message;
    EXPECT_EQ(stepped, 0);
    mdr_contact_law_destroy(law);
}

TEST(DemContactLawC, BadInputIsACodeAndAMessage) {
    char message[256] = "";
    const mdr_prony_material negative{-1.0, 0, nullptr, nullptr};
    EXPECT_EQ(mdr_contact_law_create(&standard, &negative, 0.005, 0.3, 40, 1e-3, 2e-6, message, sizeof message),
              nullptr);
    EXPECT_EQ(std::string(message).rfind("second.G_inf = -1", 0), 0u) << message;
    EXPECT_EQ(mdr_contact_law_create(&standard, &elastic, 0.005, 0.3, 40, 1e-3, 0.0, message, sizeof message), nullptr);
    EXPECT_EQ(std::string(message).rfind("time_step = 0", 0), 0u) << message;

    mdr_contact_law* law = mdr_contact_law_create(&standard, &elastic, 0.005, 0.3, 40, 1e-3, 2e-6, nullptr, 0);
    ASSERT_NE(law, nullptr);
    std::vector<double> state(mdr_contact_law_state_size(law));
    mdr_contact_law_initialise(law, state.data());
    const double normal[3] = {0.0, 0.0, 1.0}, increment[3] = {0.0, 0.0, 0.0};
    double force[3];
    ASSERT_EQ(mdr_contact_law_step(law, state.data(), 2e-6, 1e-5, normal, increment, force, message, sizeof message),
              MDR_OK);
    const auto before = state;
    // Beyond the half-width: an error naming it, and the contact's state as it was.
    EXPECT_EQ(mdr_contact_law_step(law, state.data(), 2e-6, 1e-3, normal, increment, force, message, sizeof message),
              MDR_INVALID_INPUT);
    EXPECT_EQ(std::string(message).rfind("half_width = ", 0), 0u) << message;
    EXPECT_EQ(state, before);
    // A corrupted element count: the Foundation's, after the law's 6 doubles and the composed step's header (M = 1).
    const std::size_t count = 6 + mdr::foundation::ComposedNormalStep::header_size(1) + 2;
    const std::string count_key = "state[" + std::to_string(count) + "] = ";
    state[count] = 1e12;
    EXPECT_EQ(mdr_contact_law_check(law, state.data(), state.size(), message, sizeof message), MDR_INVALID_INPUT);
    EXPECT_EQ(std::string(message).rfind(count_key, 0), 0u) << message;
    EXPECT_EQ(mdr_contact_law_step(law, state.data(), 2e-6, 1e-5, normal, increment, force, nullptr, 0),
              MDR_INVALID_INPUT);
    // The stored energy of a corrupted state: a code and a message, not an exception through the C interface.
    double energy = -1.0;
    EXPECT_EQ(mdr_contact_law_stored_energy(law, state.data(), &energy, message, sizeof message), MDR_INVALID_INPUT);
    EXPECT_EQ(std::string(message).rfind(count_key, 0), 0u) << message;
    EXPECT_EQ(energy, -1.0);
    mdr_contact_law_destroy(law);
}

}  // namespace
