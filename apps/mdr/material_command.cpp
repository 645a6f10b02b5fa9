// `mdr material CASE --out DIR`: tabulates the material functions of a case as `run` uses them.

#include <fmt/format.h>

#include <algorithm>

#include "commands.hpp"
#include "interrupt.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"
#include "mdr/io/document.hpp"
#include "mdr/io/material_table.hpp"
#include "mdr/io/output_file.hpp"
#include "mdr/io/result_directory.hpp"
#include "mdr/io/units.hpp"
#include "mdr/numerics/log_grid.hpp"
#include "mdr/rheology/material_models.hpp"
#include "setup_progress.hpp"

namespace mdr::cli {
namespace {

std::vector<double> parse_list(const std::string& text, const std::string& option) {
    std::vector<double> values;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        const std::string item = text.substr(start, comma - start);
        std::size_t used = 0;
        double value = 0.0;
        try {
            value = std::stod(item, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == 0 || used != item.size()) throw InvalidInput(option, item, "must be a comma-separated list of numbers");
        require_positive(option, value);
        values.push_back(value);
        start = comma + 1;
    }
    return values;
}

}  // namespace

void add_material_command(CLI::App& app, int& exit_code) {
    auto* command = app.add_subcommand("material", "Tabulate G(t), J(t) and the complex modulus of a case's material");
    auto case_path = std::make_shared<std::string>();
    auto out = std::make_shared<std::string>();
    auto times = std::make_shared<std::string>();
    auto omegas = std::make_shared<std::string>();
    command->add_option("case", *case_path, "The TOML case file")->required();
    command->add_option("--out,-o", *out, "Result directory (created, or replaced if mdr wrote it)")->required();
    command->add_option("--times", *times, "Comma-separated times t1,t2,... [s] (default: log grid)");
    command->add_option("--omegas", *omegas, "Comma-separated angular frequencies [rad/s] (default: log grid)");
    command->callback([=, &exit_code] {
        exit_code = guarded([&] {
            const io::ResultDirectory directory(*out, "--out", {*case_path});
            const auto contact_case = [&] {
                const SetupProgress preparing;
                return io::load_case(*case_path);
            }();
            const auto& material = contact_case.material;
            const auto& origin = contact_case.material_origin;
            // A model standing as a series: by default its certified window, model and series side by side.
            auto t = times->empty() ? io::default_times(material) : parse_list(*times, "--times");
            auto w = omegas->empty() ? io::default_omegas(material) : parse_list(*omegas, "--omegas");
            if (origin.certificate) {
                const auto& window = origin.certificate->window;
                if (times->empty()) t = numerics::log_grid(window.shortest, window.longest, 121);
                if (omegas->empty()) {  // the window's 1/t and the frequencies of the case's harmonic loads
                    w = numerics::log_grid(1.0 / window.longest, 1.0 / window.shortest, 121);
                    w.insert(w.end(), window.frequencies.begin(), window.frequencies.end());
                    std::sort(w.begin(), w.end());
                }
                fmt::print("{} {}\n", origin.description,
                           rheology::describe_certificate(*origin.certificate, material.terms().size(),
                                                          io::unit_names(io::unit_system(contact_case.units))));
            }
            directory.write(
                [&](const std::filesystem::path& files) {
                    io::write_material_tables(files, material, contact_case.shear_material, t, w, origin.model);
                    // The declared unit system (mdr/io/units.hpp), which the figures of the tables name.
                    auto summary = io::OutputFile(files / "summary.json");
                    summary.print("{}\n", io::to_json(Document{Document::Table{{"units", {contact_case.units}}}}));
                    summary.close();
                },
                received_signal);
            fmt::print("{} times, {} frequencies written to {}/ (functions.csv, dynamic.csv, summary.json)\n",
                       t.size(), w.size(), *out);
        });
    });
}

}  // namespace mdr::cli
