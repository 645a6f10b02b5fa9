#include "interrupt.hpp"

#include <atomic>
#include <csignal>

#include "mdr/error.hpp"

namespace mdr::cli {
namespace {

// Atomic, not only volatile: the threads of a map read it (throw_if_interrupted as a fit's check_interrupt) while
// the handler may write it; lock-free, so that the handler may touch it.
std::atomic<int> received{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_signal(int signal_number) {
    if (received != 0) {  // the second request: stop now, the next run removes what is left
        std::signal(signal_number, SIG_DFL);
        std::raise(signal_number);
        return;
    }
    received = signal_number;
}

}  // namespace

void install_interrupt_handlers() {
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
}

int received_signal() { return received; }

void throw_if_interrupted() {
    if (received != 0) throw Interrupted();
}

}  // namespace mdr::cli
