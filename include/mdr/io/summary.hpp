#pragma once
/// \file
/// The summary of a run as typed values (the keys of summary.json, docs/case-format.md): a table of the one result
/// document (mdr/document.hpp), so that the command line writes it as JSON (io::to_json) and Python gets it as a dict
/// (and sweeps as rows) without any text in between.

#include <string>

#include "mdr/document.hpp"
#include "mdr/drivers/indentation.hpp"

namespace mdr::io {

/// A run's summary: summary.json's keys and values, in its order; each value a number, a count, a flag, a text or a
/// list of numbers.
using Summary = Document::Table;

/// The summary of `result`, a run of `contact_case` that took `wall_seconds`: the case's and the run's keys, then
/// the run's outcomes (drivers::outcomes) as they are.
Summary summarize(const drivers::ContactCase& contact_case, const drivers::IndentationResult& result,
                  double wall_seconds);

/// The summary of JSON text written by io::to_json (read back exactly: integers are counts, a list holds numbers).
/// Throws std::runtime_error when `json_text` is not such an object.
Summary summary_from_json(const std::string& json_text);

}  // namespace mdr::io
