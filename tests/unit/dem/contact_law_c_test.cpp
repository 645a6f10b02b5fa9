// The C interface of the DEM contact law (include/mdr/dem/contact_law_c.h): it steps a contact as the C++ law's
// advance_spatial does, reports bad input through its return code and message (naming the parameter), and leaves a
// contact's state alone when a step fails.

#include "mdr/dem/contact_law_c.h"

#include <gtest/gtest.h>

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
