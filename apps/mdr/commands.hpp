#pragma once
// The sub-commands of the `mdr` command line; each registers itself on the app.

#include <CLI/CLI.hpp>
#include <functional>

namespace mdr::cli {

/// Runs `body`, turning mdr::InvalidInput and other errors into one stderr line; returns the exit code
/// (0, or 2 for bad input, 1 for other failures).
int guarded(const std::function<void()>& body);

/// `mdr run CASE --out DIR`.
void add_run_command(CLI::App& app, int& exit_code);
/// `mdr check CASE`.
void add_check_command(CLI::App& app, int& exit_code);
/// `mdr material CASE --out DIR [--times ...] [--omegas ...]`.
void add_material_command(CLI::App& app, int& exit_code);
/// `mdr sweep CASE --vary KEY=START:STOP:COUNT[:log] ... --out DIR [--jobs N | --scheduler tcp://HOST:PORT]`.
void add_sweep_command(CLI::App& app, int& exit_code);

/// `mdr fit CASE --out DIR`.
void add_fit_command(CLI::App& app, int& exit_code);

}  // namespace mdr::cli
