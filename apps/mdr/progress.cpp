#include "progress.hpp"

#include "interrupt.hpp"

#include <unistd.h>

#include <cstdio>

namespace mdr::cli {

ProgressReporter::ProgressReporter() : start_(std::chrono::steady_clock::now()), terminal_(isatty(STDERR_FILENO) != 0) {}

ProgressReporter::~ProgressReporter() { finish(); }

void ProgressReporter::operator()(double fraction) {
    throw_if_interrupted();
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (!terminal_ || elapsed < 1.0 || fraction <= 0.0) return;
    const double left = elapsed * (1.0 - fraction) / fraction;
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
