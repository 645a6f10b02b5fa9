#include "progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace mdr::cli {

ProgressReporter::ProgressReporter() : start_(std::chrono::steady_clock::now()), terminal_(isatty(STDERR_FILENO) != 0) {}

void ProgressReporter::operator()(double fraction) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (elapsed < 1.0 || fraction <= 0.0) return;
    const double left = elapsed * (1.0 - fraction) / fraction;
    if (terminal_) {
        const int width = 30;
        const int filled = static_cast<int>(fraction * width);
        std::fprintf(stderr, "\r[%-*.*s] %3.0f%%  %.0f s left ", width, filled, "##############################",
                     100.0 * fraction, left);
        drawn_ = true;
    } else if (const int decile = static_cast<int>(fraction * 10.0); decile > last_decile_) {
        last_decile_ = decile;
        std::fprintf(stderr, "mdr: %3.0f%% done, %.0f s elapsed, about %.0f s left\n", 100.0 * fraction, elapsed, left);
    }
}

void ProgressReporter::finish() {
    if (drawn_) std::fprintf(stderr, "\r%60s\r", "");
}

}  // namespace mdr::cli
