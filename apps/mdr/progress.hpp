#pragma once
// Progress of a long run: on a terminal a bar on stderr after a second, cleared when the run ends or fails, so that a
// failure still leaves exactly one error line; when stderr is a file or a pipe (a batch job), a line every 5 s.

#include <chrono>

namespace mdr::cli {

/// Reports the fraction done of a run once it has lasted longer than a second.
class ProgressReporter {
public:
    ProgressReporter();
    ~ProgressReporter();
    ProgressReporter(const ProgressReporter&) = delete;
    ProgressReporter& operator=(const ProgressReporter&) = delete;
    /// Reports `fraction` (0..1) done; throws mdr::Interrupted once Ctrl-C or SIGTERM was received.
    void operator()(double fraction);
    /// Clears the bar, if one was drawn.
    void finish();

private:
    std::chrono::steady_clock::time_point start_;
    bool terminal_;
    bool drawn_ = false;
    double next_line_;  // s after the start when the next line is due (stderr not a terminal)
};

}  // namespace mdr::cli
