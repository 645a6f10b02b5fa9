#pragma once
/// \file
/// The Shore durometer (ASTM D2240, ISO 48-4) as a ready-made test: the standard's indenter pushed into the body by
/// its calibrated spring while the presser foot rests on the surface. The spring force is an affine function of
/// the depth, so the test is spring control (F(d) + k d = k z) with a constant base z, a step at the foot's landing
/// and a stop at the indenter's full extension; the general creep law (eq. 34) with a depth-dependent force.
/// Values and sources: docs/case-format.md, "Shore durometer".

#include <array>
#include <memory>
#include <string>
#include <tuple>

#include "mdr/drivers/control_field.hpp"
#include "mdr/drivers/load_history.hpp"
#include "mdr/profile/profile.hpp"

namespace mdr::drivers {

/// The durometer types mdr knows.
enum class ShoreScale {
    A,  ///< soft rubbers: a truncated 35 deg cone (0.79 mm flat tip), spring 0.55 + 0.075 H_A [N]
    D,  ///< hard rubbers and plastics: a 30 deg cone with a 0.1 mm spherical tip, spring 0.4445 H_D [N]
};

/// The scale of that name ("A" or "D"); mdr::InvalidInput (key `load.scale`) else.
ShoreScale shore_scale_named(const std::string& name);

/// The indenter's full extension beyond the presser foot: reading 0 [m].
inline constexpr double shore_full_extension = 2.5e-3;
/// The indentation depth of one Shore point: H = 100 - d / shore_point_depth [m].
inline constexpr double shore_point_depth = shore_full_extension / 100.0;
/// Diameter of the indenter's rod [m]: the standard's 1.10 .. 1.40 mm, its middle. The contact radius cannot exceed
/// the rod's radius (the profile ends there in a rigid wall); it reaches it below about 30 Shore A.
inline constexpr double shore_rod_diameter = 1.25e-3;
/// The times after the foot's landing at which the standards read [s]: ASTM D2240 1 s (and 15 s), ISO 48-4 3 s
/// (vulcanised rubber) and 15 s (thermoplastic rubber).
inline constexpr std::array<double, 3> shore_reading_times{1.0, 3.0, 15.0};
/// Duration of a Shore test when `load.duration` is not given [s]: the longest reading time.
inline constexpr double shore_default_duration = 15.0;

/// A durometer in the case's units: lengths in units of `length_unit` [m], forces of `force_unit` [N].
struct Durometer {
    ShoreScale scale = ShoreScale::A;
    double spring_rate = 0.0;      ///< k: the fall of the spring force per depth [force/length]
    double reading_100_force = 0.0;  ///< the spring force at depth 0 (reading 100) [force]
    double point_depth = 0.0;      ///< depth of one Shore point [length]
    /// The spring's base z = F(0) / k [length]: the force is k (z - d), spring control with a constant base.
    double base() const { return reading_100_force / spring_rate; }
    /// The full extension (reading 0) [length]: the indenter's stop.
    double full_extension() const { return 100.0 * point_depth; }
    /// The spring force at depth d: F = k (z - d) [force].
    double force(double depth) const { return spring_rate * (base() - depth); }
    /// The reading H = 100 - d / point_depth at depth d.
    double reading(double depth) const { return 100.0 - depth / point_depth; }
};

/// The durometer of `scale`: the standard's spring law F(H) written as a function of the depth d = (100 - H)
/// point_depth, in units of `length_unit` [m] and `force_unit` [N] (1, 1 for SI).
Durometer durometer(ShoreScale scale, double length_unit = 1.0, double force_unit = 1.0);

/// The standard's indenter of `scale` as a tabulated profile, in units of `length_unit` [m]. Type A: a flat tip of
/// 0.79 mm diameter, a 35 deg (included angle) frustum up to the rod, piecewise linear (exact, kinks kept). Type D:
/// a sphere of radius 0.1 mm tangent to a 30 deg cone, sampled on the cap and interpolated by the monotone cubic
/// (relative error of g below 3e-6, tests/unit/drivers/shore_test.cpp). Both end at the rod (a rigid wall beyond).
std::unique_ptr<profile::Profile> durometer_indenter(ShoreScale scale, double length_unit = 1.0);

/// A Shore test in a ContactCase (control = spring with the durometer's spring rate and a base history
/// [[0, z], [duration, z]]: the foot lands at t = 0). The readings are measured at shore_reading_times.
struct ShoreTest {
    ShoreScale scale = ShoreScale::A;
    double duration = shore_default_duration;  ///< [s] > 0
    Durometer instrument{};                    ///< in the case's units

    /// Its number and its key (the scale is a name; not its Python class's: mdr.ShoreTest is bound by hand).
    static constexpr auto fields() {
        return std::tuple{control_field("duration", &ShoreTest::duration, "s", "the test's duration > 0",
                                        "load.duration")};
    }
};

/// The Shore test of `scale` lasting `duration` [s] in the case's units (durometer). Throws mdr::InvalidInput
/// (`load.duration`) unless duration > 0 and finite.
ShoreTest make_shore_test(ShoreScale scale, double duration, double length_unit = 1.0, double force_unit = 1.0);

/// The base history of the test's spring: [[0, z], [duration, z]], a step at t = 0 (the foot lands).
LoadHistory shore_base_history(const ShoreTest& test);

/// The reading at one time.
struct ShoreReading {
    double time = 0.0;     ///< [s] after the foot's landing
    double reading = 0.0;  ///< H
};

}  // namespace mdr::drivers
