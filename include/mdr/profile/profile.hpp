#pragma once
/// \file
/// Axisymmetric indenter profiles f(r) and their MDR equivalents g(x) (handbook section 4, eq. 9 and 10).

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mdr::profile {

/// What defines a profile, named as in the case file's `[indenter]` table: enough to build it again (pickling,
/// writing a case back). The keys of each shape are those of its row in the registry (shapes.hpp).
struct ProfileDefinition {
    std::string shape;                                    ///< a shape of the registry: sphere, cone, ...
    std::map<std::string, double> numbers{};              ///< e.g. {"R", 0.01}
    std::map<std::string, std::vector<double>> arrays{};  ///< e.g. a table's {"r", ...} and {"f", ...}
    std::map<std::string, std::string> texts{};           ///< e.g. a table's {"interpolation", "linear"}

    /// The number under `key` (throws mdr::InvalidInput `key = (missing): is required` if absent).
    double number(const std::string& key) const;
    /// The array under `key` (throws as number()).
    const std::vector<double>& array(const std::string& key) const;
    /// The text under `key` (throws as number()).
    const std::string& text(const std::string& key) const;
    /// True when any kind of value is given for `key`.
    bool has(const std::string& key) const;
    /// The same shape with the same values: the same profile.
    bool operator==(const ProfileDefinition&) const = default;
};

/// An axisymmetric gap f(r) between the undeformed surfaces, f(0) = 0, non-decreasing in r.
class Profile {
public:
    virtual ~Profile() = default;

    /// The gap f(r) [m] at radius r >= 0.
    virtual double gap(double r) const = 0;
    /// The MDR profile g(x) = |x| int_0^|x| f'(r) / sqrt(x^2 - r^2) dr [m] (eq. 9); +infinity where the
    /// indenter is a rigid wall (beyond a flat punch's radius) or beyond the profile's range.
    virtual double equivalent(double x) const = 0;
    /// The smallest radius a >= 0 with g(a) >= d (the Lee-Radok contact radius of eq. 15 at depth d >= 0).
    virtual double contact_radius(double depth) const = 0;
    /// Largest radius where the profile is defined [m]: +infinity for analytic shapes, the punch radius for
    /// a flat punch, the last tabulated r for a table.
    virtual double max_radius() const = 0;
    /// True when g has a jump to a rigid wall at max_radius() (a flat punch; a durometer's rod): the contact radius
    /// cannot grow beyond it.
    virtual bool is_flat_punch() const { return false; }
    /// The radii 0 < r < max_radius() where the gap's slope f' jumps (a flat tip's edge, a truncated cone's, the
    /// inner points of a piecewise-linear table), ascending; none for a profile with a continuous slope. Beyond each,
    /// g(x) grows by (f'(r+) - f'(r-)) x arccos(r/x) ~ sqrt(x - r) (eq. 9): a quadrature of g over the contact splits
    /// there (contact::LayerContact).
    virtual std::vector<double> kinks() const { return {}; }
    /// The radius b >= 0 of the indenter's flat end, f = g = 0 for r <= b: the contact radius as it touches (a flat
    /// punch: its radius; a table: its last point with f = 0). 0 for a profile that touches at a point.
    virtual double flat_radius() const { return 0.0; }
    /// The exponent n when the MDR profile is exactly a power law g(x) = k |x|^n (sphere 2, eq. 30; cone 1, eq. 25;
    /// power law n): its contact radius a(d) = (d/k)^(1/n) is then smooth for d > 0, which the continuum (Ting)
    /// model of depth-driven fits needs. nullopt for any other profile (a flat punch, a table).
    virtual std::optional<double> power_law_exponent() const { return std::nullopt; }
    /// The radius R [m] of a spherical tip, parabolic near its apex (g = x^2/R, eq. 30): the depth that makes sense
    /// for it lies between a small fraction of R and R (a fit's depth flags, fit/plausibility.cpp), and it is the
    /// lever of an oblique impact's friction (drivers::oblique_sphere), which needs a profile that has one. nullopt
    /// for a tip without one (a cone, a flat punch, a power law, a table).
    virtual std::optional<double> tip_radius() const { return std::nullopt; }
    /// Short human description, e.g. `sphere R = 0.01`: by default describe_shape(definition()) of the registry.
    virtual std::string describe() const;
    /// The shape and parameters that build this profile again (make_profile).
    virtual ProfileDefinition definition() const = 0;
};

/// Sphere of radius R (parabolic approximation): f = r^2/(2R), g = x^2/R (eq. 30). Key `R`.
std::unique_ptr<Profile> make_sphere(double R);
/// Cone; slope_deg is the angle between the flank and the flat surface, 0 < slope < 90:
/// f = r tan(theta), g = (pi/2)|x| tan(theta) (eq. 24, 25). Key `slope_deg`.
std::unique_ptr<Profile> make_cone(double slope_deg);
/// The same cone given by its half-angle (between flank and axis, as nanoindentation tips are specified: 70.3 deg
/// for a Berkovich-equivalent cone): slope_deg = 90 - half_angle_deg. Throws mdr::InvalidInput (key
/// `half_angle_deg`) unless 0 < half_angle_deg < 90.
std::unique_ptr<Profile> make_cone_from_half_angle(double half_angle_deg);
/// Flat cylindrical punch of radius a: g = 0 for |x| <= a, rigid wall beyond. Key `a`.
std::unique_ptr<Profile> make_flat_punch(double a);
/// Power law f = c r^n, n > 0: g = kappa_n c |x|^n, kappa_n = sqrt(pi) Gamma(n/2+1)/Gamma(n/2+1/2). Keys `c`, `n`.
std::unique_ptr<Profile> make_power_law(double c, double n);
/// How a tabulated gap is interpolated between its points (key `indenter.interpolation`).
enum class Interpolation {
    monotone_cubic,  ///< Fritsch-Carlson: continuous slope, exact for quadratics (smooth profiles)
    linear,          ///< piecewise linear: keeps kinks (a flat tip, a truncated cone), exact for cones
};

/// Tabulated gap: r ascending from 0, f(0) = 0, f non-decreasing; f is interpolated as asked and g is computed by
/// eq. (9) in closed form per interval (f' is a polynomial there). Keys `r`, `f`, `interpolation`.
std::unique_ptr<Profile> make_table(std::vector<double> r, std::vector<double> f,
                                    Interpolation interpolation = Interpolation::monotone_cubic);

/// One row of the registry of interpolations: `interpolation = "name"` and what it is for.
struct InterpolationKind {
    Interpolation interpolation;  ///< the method
    std::string name;  ///< e.g. `monotone_cubic`
    std::string use;   ///< e.g. `smooth profiles`
};

/// The interpolations, the default first: the reader, its messages, the shape registry's documentation and the
/// docs' lists come from it.
const std::vector<InterpolationKind>& interpolations();
/// The row of `interpolation`.
const InterpolationKind& interpolation_kind(Interpolation interpolation);
/// The names as text, `monotone_cubic or linear`, each with its use in parentheses when `with_uses`.
std::string interpolation_list(bool with_uses);
/// The interpolation of that name (a row's); mdr::InvalidInput (key `interpolation`) naming the rows else.
Interpolation interpolation_named(const std::string& name);

/// Builds the profile that `definition` describes with the factory of its shape's row (shapes.hpp; errors name the
/// case-file keys without the `indenter.` prefix). Throws mdr::InvalidInput for an unknown shape, an unknown or a
/// missing key, or two alternatives given together (slope_deg with half_angle_deg).
std::unique_ptr<Profile> make_profile(const ProfileDefinition& definition);

}  // namespace mdr::profile
