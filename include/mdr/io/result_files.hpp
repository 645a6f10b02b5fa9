#pragma once
/// \file
/// The files of a result directory of `mdr run` (spec: history.csv, summary.json, profiles.csv).

#include <filesystem>
#include <string>

#include "mdr/drivers/indentation.hpp"

namespace mdr::io {

/// Writes history.csv, summary.json and (with snapshots) profiles.csv of an indentation run into `directory`.
void write_indentation_result(const std::filesystem::path& directory, const drivers::ContactCase& contact_case,
                              const drivers::IndentationResult& result, double wall_seconds);

/// The summary.json object of a run, as JSON text: to_json(summarize(...)) (mdr/io/summary.hpp).
std::string summary_json(const drivers::ContactCase& contact_case, const drivers::IndentationResult& result,
                         double wall_seconds);

}  // namespace mdr::io
