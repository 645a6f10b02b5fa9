// `mdr check CASE`: validates a case file without running it.

#include <fmt/format.h>

#include "commands.hpp"
#include "mdr/io/case_file.hpp"
#include "setup_progress.hpp"

namespace mdr::cli {

void add_check_command(CLI::App& app, int& exit_code) {
    auto* command = app.add_subcommand("check", "Validate a case file and describe it in one line");
    auto case_path = std::make_shared<std::string>();
    command->add_option("case", *case_path, "The TOML case file")->required();
    command->callback([case_path, &exit_code] {
        exit_code = guarded([&] {
            const auto contact_case = [&] {
                const SetupProgress preparing;
                return io::load_case(*case_path);
            }();
            fmt::print("ok: {}\n", io::check(contact_case));
        });
    });
}

}  // namespace mdr::cli
