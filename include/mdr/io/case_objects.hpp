#pragma once
/// \file
/// A contact case given as objects (mdr.ContactCase: a drivers::ContactCase with its bodies) as a sweep varies it,
/// without text: a key of a case file sets a typed value on a copy of the part it names; the parts no key names are
/// shared as they are (a converted material keeps its series and certificate, and is not converted again).

#include <string>
#include <vector>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/io/case_assembly.hpp"
#include "mdr/io/sweep.hpp"

namespace mdr::io {

/// The parts of an assembled case (one io::assemble_case built) from which assemble_case, given the case's bodies,
/// builds it again: its end only where it was given (ContactCase::end_given; else the default end, which follows the
/// load), no indenter with a Shore test (the standard's, brought again). What a sweep of the case edits, and what an
/// mdr.ContactCase pickles.
CaseParts case_parts(const drivers::ContactCase& contact_case);

/// The case `base` with its numbers named by the keys of its case file, below each part's table:
/// - `material.KEY`, `indenter.material.KEY`: a number of a body's (shear) material model, by the table of its
///   definition (rheology::ModelDefinition; a series that stands for itself by rheology::series_definition:
///   `material.G_inf`, `material.terms[0][1]`), its `tolerance` where its definition gives one; a compressible body's
///   `K` (a bulk part that is an elastic modulus without a model) or `bulk.KEY` (the bulk model's table, K for G);
///   a material is built again from its registry row, a model converted to a series over its own certificate's window
///   and frequencies with its tolerance;
/// - `indenter.KEY`: a number of the indenter's shape by its definition (profile::Profile::definition: `indenter.R`,
///   `indenter.r[3]`, a cone's `slope_deg`; not with a Shore test);
/// - the numbers of the control by the keys its type declares (drivers::ControlField::key: `load.spring_constant`,
///   `load.force_pauses[i][j]`, `indenter.mass`, `load.velocity`, an oblique impact's `tangential.friction`,
///   `load.tangential_velocity`, `load.spin`, `indenter.moment_of_inertia`, a Shore test's `load.duration`), where the
///   case's control has them;
/// - `load.history[i][j]` (under a control that takes a history), `load.harmonic.KEY`, `load.end` (where it was
///   given: ContactCase::end_given), `output.snapshots[i]`, `tangential.friction` of a `[tangential]` load,
///   `layer.thickness`, and the `[numerics]` values the case holds (`numerics.elements` an integer >= 1).
/// Every point is assembled by io::assemble_case, with the case file's rules and messages.
class CaseObjects final : public SweepCase {
public:
    /// The case as given (a case that drivers::validate accepts, built by io::assemble_case or read from a file).
    explicit CaseObjects(drivers::ContactCase base);

    bool has_number(const std::string& key) const override;
    std::string numbers_rule() const override;
    drivers::ContactCase build(const std::vector<std::string>& keys, const std::vector<double>& values) const override;

private:
    drivers::ContactCase base_;
};

}  // namespace mdr::io
