#pragma once
// `mdr fit CASE --each A.csv B.csv ... --out DIR`: one material per file, a batch. Each file is fitted alone with
// the case's [fit] (in place of its one [[fit.data]] file) into DIR/<stem>/, and DIR/each.csv has one row per file:
// file, every free key and its KEY_stderr, status, residual_to_noise; DIR/each.json the spread of the values against
// the fits' errors (fit::spread_of_repeats).

#include <string>
#include <vector>

#include "fit_progress.hpp"
#include "mdr/fitcase/fit_case.hpp"
#include "mdr/io/result_directory.hpp"

namespace mdr::cli {

/// Fits each of `files` alone with `fit_case` (which must have exactly one curve table `fit.data[0]` and fit its
/// own material), writes the results into `directory` and prints one line per file. Every file is loaded and
/// checked before the first fit, so that bad input leaves nothing written. Returns true when every fit converged.
bool run_each(const fitcase::FitCase& fit_case, const std::vector<std::string>& files,
              const io::ResultDirectory& directory, FitProgress& progress);

}  // namespace mdr::cli
