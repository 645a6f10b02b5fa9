#include "interrupt.hpp"

#include <csignal>

#include "mdr/error.hpp"

namespace mdr::cli {
namespace {

volatile std::sig_atomic_t received = 0;

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
