#include "progress.hpp"

#include <unistd.h>

#include <cstdio>

#include "interrupt.hpp"

namespace mdr::cli {
namespace {

constexpr double terminal_delay = 1.0;   // s before the bar appears
constexpr double line_interval = 5.0;    // s between progress lines when stderr is a file or a pipe

}  // namespace

ProgressReporter::ProgressReporter()
    : start_(std::chrono::steady_clock::now()), terminal_(isatty(STDERR_FILENO) != 0), next_line_(line_interval) {}

ProgressReporter::~ProgressReporter() { finish(); }

void ProgressReporter::operator()(double fraction) {
    throw_if_interrupted();
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (fraction <= 0.0) return;
    const double left = elapsed * (1.0 - fraction) / fraction;
    if (!terminal_) {
        if (elapsed < next_line_) return;
        next_line_ = elapsed + line_interval;
        std::fprintf(stderr, "mdr: %.0f%% of the simulated time after %.0f s, about %.0f s left\n", 100.0 * fraction,
                     elapsed, left);
        return;
    }
    if (elapsed < terminal_delay) return;
    const int width = 30;
    const int filled = static_cast<int>(fraction * width);
    std::fprintf(stderr, "\r[%-*.*s] %3.0f%%  %.0f s left ", width, filled, "##############################",
                 100.0 * fraction, left);
    drawn_ = true;
}

void ProgressReporter::finish() {
    if (drawn_) std::fprintf(stderr, "\r%60s\r", "");
    drawn_ = false;
}

}  // namespace mdr::cli
