#include "fit_progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace mdr::cli {
namespace {

constexpr double terminal_delay = 1.0;  // s before the line appears on a terminal
constexpr double line_interval = 5.0;   // s between lines when stderr is a file or a pipe

}  // namespace

FitProgress::FitProgress()
    : start_(std::chrono::steady_clock::now()),
      terminal_(isatty(STDERR_FILENO) != 0),
      next_report_(terminal_ ? terminal_delay : line_interval) {}

FitProgress::~FitProgress() { finish(); }

void FitProgress::finish() {
    if (drawn_) std::fprintf(stderr, "\r%70s\r", "");
    drawn_ = false;
}

void FitProgress::operator()(std::size_t iteration, double chi_squared) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (elapsed < next_report_) return;
    next_report_ = terminal_ ? elapsed : elapsed + line_interval;
    std::fprintf(stderr, terminal_ ? "\rmdr: fit iteration %zu, chi^2 = %.6g, %.0f s so far "
                                   : "mdr: fit iteration %zu, chi^2 = %.6g, %.0f s so far\n",
                 iteration, chi_squared, elapsed);
    drawn_ = terminal_;
}

}  // namespace mdr::cli
