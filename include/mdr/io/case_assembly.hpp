#pragma once
/// \file
/// The one assembly of a contact case from its parts, shared by the case file's reader (io::read_case) and the
/// callers that give the parts as objects (Python's mdr.ContactCase): a Shore test's durometer, an impact's
/// history, the default end, then the bodies and the case's rules (drivers::validate, drivers::validate_layer).

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mdr/contact/layer.hpp"
#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/shore.hpp"
#include "mdr/io/units.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/approximation.hpp"
#include "mdr/rheology/contact_bodies.hpp"

namespace mdr::io {

/// A case's parts as given, before assemble_case completes them; lengths, forces and times in the case's `units`.
struct CaseParts {
    std::string title{};
    std::string units = "SI";                          ///< the name of one of io::unit_systems()
    std::shared_ptr<const profile::Profile> indenter{};  ///< none with a Shore test (the standard's)
    drivers::LoadControl control{};                    ///< a Shore test: a spring control with its `shore`
    drivers::Load load{};                              ///< the history: none for an impact and a Shore test
    std::optional<double> end{};                       ///< `load.end`; none: default_end_time
    std::vector<double> snapshots{};
    drivers::NumericsOptions numerics{};
    std::optional<drivers::TangentialLoad> tangential{};
    std::optional<contact::Layer> layer{};
};

/// The last time simulated [s] of a case without `load.end`: infinite for a run that `stops_itself`
/// (drivers::ends_by_stop_rule: an impact's contact end stops it, eq. 39); otherwise the later of the normal load's
/// end (drivers::Load::end_time; it has a history) and the tangential load's.
double default_end_time(const drivers::Load& load, bool stops_itself,
                        const std::optional<drivers::TangentialLoad>& tangential);

/// Throws mdr::InvalidInput (key `indenter`) when a case with a Shore test gives an indenter too
/// (`case_has_indenter`): the durometer's is the standard's (docs/case-format.md, "Shore durometer").
void refuse_indenter_beside_durometer(bool case_has_indenter);

/// The bodies of a case, built once its load is complete (`parts` as assemble_case completed it; a model converted
/// to a series is converted over case_window(parts)). The reader also reads there what it has always read after
/// the bodies (a spring's force pauses, `[layer]`), into `parts`.
using BodiesBuilder = std::function<rheology::ContactBodies(CaseParts& parts)>;

/// Throws mdr::InvalidInput (key `prefix`K, its value `K_text`) when a body table `prefix` (`material.`,
/// `indenter.material.`) gives both a bulk modulus K and a bulk material: a body has one bulk part.
void refuse_two_bulk_parts(const std::string& prefix, bool has_bulk_modulus, bool has_bulk, const std::string& K_text);

/// The rule of a body table `prefix`'s bulk modulus: K > 0 (mdr::InvalidInput naming `prefix`K).
void require_bulk_modulus(const std::string& prefix, double K);

/// The body of the shear material `shear`, compressible with the bulk modulus `K` [Pa] (an elastic bulk part, whose
/// times count as a conversion's: none) or the bulk material `bulk` (K(t)), incompressible with neither, by a body
/// table `prefix`'s rules (require_bulk_modulus; not both: refuse_two_bulk_parts). Throws mdr::InvalidInput.
rheology::Body compressible_body(rheology::ModelMaterial shear, std::optional<double> K,
                                 std::optional<rheology::ModelMaterial> bulk, const std::string& prefix);

/// The time window of completed parts (drivers::material_window of their load, end, numerics and tangential load).
rheology::TimeWindow case_window(const CaseParts& parts);

/// The case of `parts`: its control completed in the case's units with the parts it brings
/// (drivers::complete_control: a Shore test's durometer, the standard's indenter and base history; an impact's
/// history, the point (0, 0)), the end
/// `load.end` or default_end_time; then the bodies (`bodies`, kept in the case: drivers::set_bodies) and the case's
/// rules (drivers::validate, which checks a model converted to a series against the case's window, and
/// drivers::validate_layer). Throws mdr::InvalidInput naming the key, the value and the rule.
drivers::ContactCase assemble_case(CaseParts parts, const BodiesBuilder& bodies);

}  // namespace mdr::io
