#pragma once
/// \file
/// The result directory of `mdr run` (spec: history.csv, summary.json, profiles.csv), written atomically.

#include <filesystem>
#include <functional>
#include <string>

#include "mdr/drivers/indentation.hpp"

namespace mdr::io {

/// Writes into a fresh temporary directory beside `directory` with `write`, then replaces `directory` by it, so
/// that a failed run leaves no partial files. Throws std::runtime_error when the directory cannot be written.
void write_directory_atomically(const std::filesystem::path& directory,
                                const std::function<void(const std::filesystem::path&)>& write);

/// Writes history.csv, summary.json and (with snapshots) profiles.csv of an indentation run into `directory`.
void write_indentation_result(const std::filesystem::path& directory, const drivers::ContactCase& contact_case,
                              const drivers::IndentationResult& result, double wall_seconds);

/// The summary.json object of a run, as JSON text.
std::string summary_json(const drivers::ContactCase& contact_case, const drivers::IndentationResult& result,
                         double wall_seconds);

}  // namespace mdr::io
