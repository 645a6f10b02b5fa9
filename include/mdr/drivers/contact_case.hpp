#pragma once
/// \file
/// A normal-contact problem as the drivers see it: material, indenter, load and numerics (no file format here).

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mdr/contact/layer.hpp"
#include "mdr/drivers/control_parts.hpp"
#include "mdr/drivers/load.hpp"
#include "mdr/drivers/load_control.hpp"
#include "mdr/drivers/tangential_load.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/approximation.hpp"
#include "mdr/rheology/contact_bodies.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::drivers {

/// User choices of `[numerics]`; every field optional, defaults come from the problem's scales.
struct NumericsOptions {
    std::optional<std::size_t> elements;   ///< elements on the half-width
    std::optional<double> time_step;       ///< largest time step [s]
    std::optional<double> half_width;      ///< half-width L of the foundation [m]
    std::size_t output_every = 1;          ///< write every n-th step
    std::optional<double> max_element_steps;  ///< bound on steps x elements (default_max_element_steps)
    std::optional<double> max_memory;         ///< bound on the run's memory [bytes] (default_max_memory)
    /// On a `[layer]`: the cells of the coupled time-stepping (eq. L16 to L19; default: `elements`, else
    /// default_layer_cells; layer_cell_count, include/mdr/drivers/layer_indentation.hpp).
    std::optional<std::size_t> layer_cells;
    /// Smallest number of steps per history segment (ResolvedNumerics::min_segment_steps); a fit sets 1, as its
    /// measured points under displacement control are exact steps (not a case-file key).
    std::optional<std::size_t> min_segment_steps{};
    /// On a `[layer]`: run a history on cells from the start (eq. L16 to L19), not Ting's class first and cells only
    /// where its contact grows again; a fit sets it, so that its model does not switch between the two solutions
    /// (exact, and second order in the cell) as its parameters move (not a case-file key).
    bool cells_from_start = false;
};

/// The numerics actually used, after defaults.
struct ResolvedNumerics {
    std::size_t elements = 0;    ///< elements on the half-width
    double time_step = 0.0;      ///< largest time step [s]
    double half_width = 0.0;     ///< half-width L [m]
    std::size_t output_every = 1;
    double time_limit = 0.0;     ///< last time simulated [s]; for an impact the latest end allowed
    /// An impact's expected end of contact [s]: that of the elastic impact on the softest modulus (the one the
    /// half-width is sized for), at most time_limit; the scale of its progress (impact_progress). 0 elsewhere.
    double expected_end = 0.0;
    /// Smallest number of steps per history segment: min_steps_per_segment for a history written by hand; a dense
    /// one (a measured curve, more than default_steps / min_steps_per_segment segments) needs fewer, as its own
    /// points resolve it: enough that the history has default_steps steps in all, at least one per segment.
    std::size_t min_segment_steps = 1;
    /// > 0: the steps after a fast load change (fast_change_times) start at first_graded_step and grow as this
    /// ratio times the time since the change (grade_after_changes); 0: a uniform grid.
    double grading_ratio = 0.0;
    double first_graded_step = 0.0;  ///< the first step after a fast load change [s] (with grading_ratio > 0)
    /// > 0: the steps before each time the force falls linearly to zero are graded towards it with this exponent
    /// (cuts_towards_zeros over zero_graded_fraction of the falling segment); 0: not graded.
    double zero_grading_exponent = 0.0;
};

/// A normal indentation problem: a rigid axisymmetric indenter on a viscoelastic half-space. An aggregate: build
/// it with designated initializers (the fields after end_time are optional); drivers::validate checks it.
struct ContactCase {
    std::string title;                                  ///< free text
    rheology::Rheology material;                        ///< combined material (eq. 8)
    std::shared_ptr<const profile::Profile> indenter;   ///< the gap f(r)
    LoadControl control = DisplacementControl{};        ///< what the load prescribes, with its own data
    /// The history of (t, d), (t, F) or (t, z) points, required (with an impact the single point (0, 0)),
    /// and `load.harmonic`, a harmonic part added to it, whose last full cycle is measured (HarmonicOutcome).
    Load load;
    double end_time = 0.0;                              ///< last time simulated [s]
    std::vector<double> snapshots{};                    ///< times of pressure profiles [s]
    NumericsOptions numerics{};                         ///< `[numerics]`
    std::optional<rheology::Rheology> shear_material{}; ///< the shear part alone, when a bulk part was folded in
    /// K(t) of one compressible body (rheology::ContactMaterial::bulk_material); absent for an incompressible body and
    /// for two bodies. Set with `shear_material` (its G(t)) and `material` (eq. 56 of the two).
    std::optional<rheology::Rheology> bulk_material{};
    std::optional<TangentialLoad> tangential{};         ///< `[tangential]`, superimposed tangential loading
    /// False when `material` is a compressible body's or two bodies' (rheology::contact_material sets it): the MDR
    /// then maps the normal problem only exactly (section 7).
    bool tangential_exact = true;
    /// The model behind `material` (its description; for a model converted to a series, the certificate).
    rheology::MaterialOrigin material_origin{};

    /// True when tangential loading (or an oblique impact) meets a material that is not tangential_exact: the
    /// tangential result is then an approximation.
    bool tangential_approximate() const {
        return !tangential_exact && (tangential || brought_by(control).tangential_part);
    }
    /// The declared unit system (mdr/io/units.hpp): the names printed beside the numbers; nothing is converted.
    std::string units = "SI";
    /// `[layer]`: a layer of finite thickness on a rigid substrate; absent: the half-space
    /// (drivers/layer_indentation.hpp).
    std::optional<contact::Layer> layer{};
    /// The bodies as given (a bulk part, the indenter's own body; mdr.ContactCase's parts), of which set_bodies makes
    /// the `material`, `shear_material`, `bulk_material`, `tangential_exact` and `material_origin` the drivers read;
    /// whoever replaces those clears this (validate refuses a material or origin not theirs). Absent: none given.
    std::optional<rheology::ContactBodies> bodies{};
    /// True when `end_time` was given (`load.end`, io::assemble_case); false: it is the load's default end
    /// (io::default_end_time), which follows the load when a sweep changes it, as a case file without `load.end`.
    bool end_given = false;
};

/// Sets the material of `contact_case` from its bodies: `material`, `shear_material`, `bulk_material`,
/// `tangential_exact` and `material_origin` as rheology::contact_material combines `bodies`, and `bodies` itself.
void set_bodies(ContactCase& contact_case, rheology::ContactBodies bodies);

/// Elements on the half-width when `[numerics] elements` is not given. With the half-width 1.1 times the largest
/// contact radius, the contact spans ~1800 elements at the peak, so the midpoint-rule error of the force,
/// O((dx/a)^2), stays below 1e-5 of the peak force down to a tenth of the peak contact radius.
inline constexpr std::size_t default_elements = 2000;
/// Steps over the whole history when `[numerics] time_step` is not given; see resolve_numerics.
inline constexpr std::size_t default_steps = 2000;
/// Default ratio of the step to the time since the start or a fast load change (fast_change_times) under force
/// control (grade_after_changes): with a parallel dashpot the singular creep there is integrated to ~1e-5 of its
/// depth; a series converted from a continuous spectrum (power law, springpots), whose creep J ~ t^beta changes
/// on every scale from its shortest time on, to ~2e-4 for beta <= 0.5
/// (tests/verification/test_power_law_fast_force_step.cpp); a finite series whose shortest time is below the step,
/// from a fraction jump_grading_ratio of that time, to ~2e-5 (tests/verification/test_prony_fast_force_step.cpp).
inline constexpr double jump_grading_ratio = 0.02;
/// The first step after the start or such a change, as a fraction of the time step (its error is
/// O((step / tau)^(2/3)) of the creep depth, tau the retardation time).
inline constexpr double jump_first_step = 1e-6;
/// The finest first step of the grading after a fast change, as a fraction of the time step: a series time far below
/// it (tau = 1e-300 s, say) is resolved no further (it has relaxed within that step), so that the graded steps after
/// each change stay about ln(1e9) / jump_grading_ratio, and the grid of a record with many changes stays bounded.
inline constexpr double finest_graded_step = 1e-9;
/// The fraction of a segment on which the force falls to zero whose steps are graded towards the zero
/// (cuts_towards_zeros), where the depth is singular as the contact ends (docs/theory.md section 3).
inline constexpr double zero_graded_fraction = 0.2;
/// Steps per braking time m / (8 eta a) of an impact on a body with a parallel dashpot (resolve_numerics).
inline constexpr std::size_t braking_steps = 20;
/// Smallest number of steps per history segment.
inline constexpr std::size_t min_steps_per_segment = 20;

/// Resolves the defaults: the half-width covers the largest contact radius with a 10% margin (displacement control: the
/// Lee-Radok radius g^-1(max d), an upper bound also under unloading since the free surface never rises above the
/// undeformed level; force control: the elastic radius at the largest force with the softest modulus 1/J(t_end -
/// t_start), 25% margin); a flat punch uses its own radius. The time step is the history duration over default_steps,
/// and at most a fifth of the shortest material time that is longer than that (not for a series whose times all come
/// from a conversion, MaterialOrigin); under force control a material with a parallel dashpot (its creep is singular in
/// time after the start and after a fast load change) has its steps graded from there (grading_ratio =
/// jump_grading_ratio from jump_first_step of the time step, see fast_change_times and grade_after_changes), so that
/// the step count stays bounded for any record length; a converted series (its creep changes on every scale from its
/// shortest time) is graded likewise from its shortest time, and a finite series with a time shorter than the time step
/// from jump_grading_ratio of that time; a user's time_step is graded by the same rules, scaled to it (a finer step is
/// never worse). Impact: the time step is the elastic contact time with the instantaneous spring modulus over
/// default_steps (and the material-time rule), the half-width 1.2 times the elastic contact radius with the equilibrium
/// modulus (an upper bound: the viscoelastic body is stiffer and dissipates); with a parallel dashpot the step is at
/// most the braking time m / (8 eta a) over braking_steps (an overdamped impact is decided on that scale); an oblique
/// impact whose contact point is lighter than a solid sphere's (m_t < 2/7 m) has the step scaled by sqrt(m_t / (2/7
/// m)). A harmonic load (normal or tangential) caps the default time step at its period over default_steps_per_period.
/// Spring control takes the smaller of the displacement-control half-width for the largest base displacement (d <= z)
/// and the force-control one for the force k max z (F <= k z), and grades its steps as force control does; with force
/// pauses the largest z is bounded by paused_base_peak, each pause's creep by the depth of the force-control bound for
/// the largest force (at most k max z and the elastic force of the depth max z with G(0+), as the contact grows up to a
/// pause). Throws mdr::InvalidInput for a problem that breaks a rule (validate) or would exceed its bounds of work or
/// memory (require_bounded_work).
ResolvedNumerics resolve_numerics(const ContactCase& contact_case);

/// The body's Poisson ratio when it is constant in time: 0.5 for an incompressible body (one, or two in series), the
/// ratio of one compressible body whose bulk relaxation is proportional to its shear one (K(t) = c G(t),
/// rheology::constant_poisson_ratio); none for one whose ratio changes in time, or a compressible body against a
/// deformable indenter (the pair's material has no one nu).
std::optional<double> body_poisson_ratio(const ContactCase& contact_case);

/// Scales of an elastic impact (energy balance m v0^2 / 2 = int F_el dd), used for the impact defaults.
struct ElasticImpact {
    double depth = 0.0;     ///< largest depth [m]
    double radius = 0.0;    ///< largest contact radius [m]
    double duration = 0.0;  ///< contact time estimate 3 d_max / v0 [s] (Hertz: 2.94 d_max / v0)
};

/// The elastic impact of `indenter` (mass [kg], approach speed [m/s]) on a half-space of shear modulus G.
ElasticImpact elastic_impact(const profile::Profile& indenter, double shear_modulus, double mass, double velocity);

/// Elastic force [N] at contact radius a for shear modulus G and the given profile (incompressible, eq. 21 with
/// w = g(a) - g(x)): F = 8 G int_0^a (g(a) - g(x)) dx.
double elastic_force(const profile::Profile& indenter, double shear_modulus, double contact_radius);

}  // namespace mdr::drivers
