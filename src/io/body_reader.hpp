#pragma once
// Reads one body of a case (`[material]`, `[indenter.material]`): its shear table and, for a compressible body, K or
// its `bulk` table; builds it once the time window of the case is known.

#include <optional>
#include <string>

#include "material_reader.hpp"
#include "mdr/io/units.hpp"
#include "mdr/rheology/contact_bodies.hpp"
#include "toml_reader.hpp"

namespace mdr::io {

/// One body as read, not yet built: a model converted to a series waits for the time window of the case.
struct BodySpec {
    MaterialSpec shear;
    std::optional<double> bulk_modulus;  ///< `K`, an elastic bulk part
    std::optional<MaterialSpec> bulk;    ///< `[bulk]`, a bulk model
    /// True when a model of the body is converted to a series over the case's time window.
    bool needs_window() const { return shear.model->needs_window || (bulk && bulk->model->needs_window); }
};

/// Reads a body's table (K checked by require_bulk_modulus). Throws mdr::InvalidInput with the full dotted key.
BodySpec read_body(TableReader& table);

/// The rule of a body's K (> 0), naming its full key (`material.K`).
void require_bulk_modulus(const BodySpec& body);

/// Builds a body over `window` (when a model is converted to a series); files a model names are found in
/// `directory`, its description in the case's `units`. Errors name the full key.
rheology::Body build_body(const BodySpec& spec, const std::optional<rheology::TimeWindow>& window,
                          const std::string& directory, const UnitSystem& units);

}  // namespace mdr::io
