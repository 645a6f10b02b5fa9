#pragma once
// Progress of a fit, like `mdr run`'s: after every solver iteration, on a terminal a line rewritten in place after a
// second (cleared when the fit ends or fails, so that a failure still leaves exactly one error line); when stderr
// is a file or a pipe, a line every 5 s: "mdr: fit iteration 12, chi^2 = 412.5, 10 s so far". A batch (`--each`)
// labels its fits: "mdr: [2/3 cell-b.csv] fit iteration 12, ...", a choice of models its candidates' fits:
// "mdr: [standard] fit iteration 3, ...".

#include <chrono>
#include <cstddef>
#include <string>

namespace mdr::cli {

/// Reports the iterations of a fit (fit::FitSettings::on_iteration).
class FitProgress {
public:
    FitProgress();
    ~FitProgress();
    FitProgress(const FitProgress&) = delete;
    FitProgress& operator=(const FitProgress&) = delete;

    /// Reports iteration `iteration` with its chi^2 (the sum of squared residuals in noise units).
    void operator()(std::size_t iteration, double chi_squared);
    /// Clears the line, if one was drawn on a terminal (before the result is printed).
    void finish();
    /// Names the fit whose iterations follow, shown in brackets after "mdr: " (as message_text shows it); empty: none.
    void label(const std::string& text);

private:
    std::chrono::steady_clock::time_point start_;
    bool terminal_;
    bool drawn_ = false;
    int drawn_width_ = 0;  // characters of the line drawn on a terminal, for clearing it
    std::string label_;    // "[2/3 cell-b.csv] " or empty
    double next_report_;  // s after the start when the next report is due
};

}  // namespace mdr::cli
