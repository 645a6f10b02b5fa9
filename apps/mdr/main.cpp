// mdr: viscoelastic contact mechanics by the Method of Dimensionality Reduction, from the command line.

#include "commands.hpp"

#include <csignal>
#include <cstdio>

#include "interrupt.hpp"
#include "mdr/error.hpp"

namespace mdr::cli {

int guarded(const std::function<void()>& body) {
    try {
        body();
        return 0;
    } catch (const Interrupted& error) {
        std::fprintf(stderr, "mdr: %s\n", error.what());
        return 128 + (received_signal() != 0 ? received_signal() : SIGINT);
    } catch (const InvalidInput& error) {
        std::fprintf(stderr, "mdr: error: %s\n", error.what());
        return 2;
    } catch (const std::exception& error) {
        // Other errors may quote the input (a parser's excerpt, a path): one line, escaped like InvalidInput's.
        std::fprintf(stderr, "mdr: error: %s\n", message_line(error.what()).c_str());
        return 1;
    }
}

}  // namespace mdr::cli

int main(int argc, char** argv) {
    CLI::App app{"mdr: viscoelastic contact mechanics by the Method of Dimensionality Reduction"};
    app.set_version_flag("--version", std::string("mdr ") + MDR_VERSION);
    app.require_subcommand(1);
    mdr::cli::install_interrupt_handlers();
    int exit_code = 0;
    mdr::cli::add_run_command(app, exit_code);
    mdr::cli::add_check_command(app, exit_code);
    mdr::cli::add_material_command(app, exit_code);
    mdr::cli::add_sweep_command(app, exit_code);
    mdr::cli::add_fit_command(app, exit_code);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        if (error.get_exit_code() == 0) return app.exit(error);  // --help, --version
        std::fprintf(stderr, "mdr: error: %s (see mdr --help)\n", mdr::message_line(error.what()).c_str());
        return 2;
    }
    return exit_code;
}
