#pragma once
/// \file
/// The one JSON writer of results: a document (mdr/document.hpp) as the text of summary.json, fit.json,
/// ranking.json, each.json, map.json and scheduler.json.

#include <string>

#include "mdr/document.hpp"

namespace mdr::io {

/// The document as JSON text indented by `indent` spaces a level: numbers with the digits that give back the same
/// double, counts as integers, null for null and for a number that is not finite.
std::string to_json(const Document& document, int indent = 2);

}  // namespace mdr::io
