#include "fit_progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

#include "mdr/error.hpp"

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
    if (drawn_) std::fprintf(stderr, "\r%*s\r", drawn_width_, "");
    drawn_ = false;
}

void FitProgress::label(const std::string& text) {
    label_ = text.empty() ? "" : fmt::format("[{}] ", message_text(text));
}

void FitProgress::operator()(std::size_t iteration, double chi_squared) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (elapsed < next_report_) return;
    next_report_ = terminal_ ? elapsed : elapsed + line_interval;
    const int width = std::fprintf(stderr, terminal_ ? "\rmdr: %sfit iteration %zu, chi^2 = %.6g, %.0f s so far "
                                                     : "mdr: %sfit iteration %zu, chi^2 = %.6g, %.0f s so far\n",
                                   label_.c_str(), iteration, chi_squared, elapsed);
    if (terminal_) drawn_width_ = std::max(drawn_width_, width);
    drawn_ = terminal_;
}

}  // namespace mdr::cli
