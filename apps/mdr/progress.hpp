#pragma once
// Progress on stderr for long runs: a bar on a terminal, a line every 10% otherwise; silent for short runs.

#include <chrono>

namespace mdr::cli {

/// Reports the fraction done of a run once it has lasted longer than a second.
class ProgressReporter {
public:
    ProgressReporter();
    /// Reports `fraction` (0..1) done.
    void operator()(double fraction);
    /// Clears the bar, if one was drawn.
    void finish();

private:
    std::chrono::steady_clock::time_point start_;
    bool terminal_;
    bool drawn_ = false;
    int last_decile_ = -1;
};

}  // namespace mdr::cli
