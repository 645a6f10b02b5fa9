#pragma once
// Progress while a case is prepared (a Prony series of thousands of terms, a profile of tens of thousands of
// points take seconds before the first step): every 5 s a line "mdr: preparing the case, 10 s so far" on stderr
// (rewritten in place, and cleared at the end, on a terminal).

#include <condition_variable>
#include <mutex>
#include <thread>

namespace mdr::cli {

/// Reports, from its own thread, while it lives; the destructor stops and joins the thread.
class SetupProgress {
public:
    SetupProgress();
    ~SetupProgress();
    SetupProgress(const SetupProgress&) = delete;
    SetupProgress& operator=(const SetupProgress&) = delete;

private:
    void report();

    std::mutex mutex_;
    std::condition_variable wake_;
    bool done_ = false;
    bool terminal_;
    bool drawn_ = false;
    std::thread thread_;
};

}  // namespace mdr::cli
