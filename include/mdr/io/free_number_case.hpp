#pragma once
/// \file
/// A case built once whose numbers under some dotted keys vary (a fit's free keys): each build rebuilds only the
/// parts those keys touch, from typed values, without reading the case's tables again.

#include <memory>
#include <string>
#include <vector>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/io/case_template.hpp"

namespace mdr::io {

/// A CaseTemplate built once, with the numbers under `keys` free. A key of a body's material model
/// (`material.tau1`, `material.terms[0][1]`, `material.G[2]`, `material.K`, `material.bulk.K_inf`,
/// `indenter.material.G`), of the indenter's shape (`indenter.R`) or `layer.thickness` is typed: build() sets it
/// in the values as read and rebuilds that body's material from its registry row, the indenter from its shape row,
/// or the layer, with CaseTemplate::build()'s rules and messages in its order (a converted model over the template's
/// conversion window when it has one, as its build() converts it). When any key is of another kind
/// (`indenter.mass`, `material.tolerance`), build() goes through the template: a copy, set_number() and build().
class FreeNumberCase {
public:
    /// Builds `model` once (throws as CaseTemplate::build()); `keys` must name numbers of the case (mdr::InvalidInput
    /// naming the key otherwise).
    FreeNumberCase(const CaseTemplate& model, std::vector<std::string> keys);

    /// True when build() takes the typed path for every key.
    bool typed() const;
    /// The case with `values[j]` under `keys[j]`: the case that a copy of the template with set_number(keys[j],
    /// values[j]) builds. Throws mdr::InvalidInput as that build would, with the same message.
    drivers::ContactCase build(const std::vector<double>& values) const;

private:
    struct Parts;
    std::shared_ptr<const Parts> parts_;  // shared by copies: build() only reads it
};

}  // namespace mdr::io
