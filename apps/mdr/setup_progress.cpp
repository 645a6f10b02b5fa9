#include "setup_progress.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>

namespace mdr::cli {
namespace {

constexpr auto interval = std::chrono::seconds(5);

}  // namespace

SetupProgress::SetupProgress() : terminal_(isatty(STDERR_FILENO) != 0), thread_([this] { report(); }) {}

SetupProgress::~SetupProgress() {
    {
        const std::lock_guard lock(mutex_);
        done_ = true;
    }
    wake_.notify_one();
    thread_.join();
    if (drawn_) std::fprintf(stderr, "\r%60s\r", "");
}

void SetupProgress::report() {
    std::unique_lock lock(mutex_);
    for (long seconds = 0;;) {
        if (wake_.wait_for(lock, interval, [this] { return done_; })) return;
        seconds += static_cast<long>(std::chrono::duration_cast<std::chrono::seconds>(interval).count());
        std::fprintf(stderr,
                     terminal_ ? "\rmdr: preparing the case, %ld s so far " : "mdr: preparing the case, %ld s so far\n",
                     seconds);
        drawn_ = terminal_;
    }
}

}  // namespace mdr::cli
