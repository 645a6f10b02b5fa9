#include "fit_map.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

#include "interrupt.hpp"
#include "mdr/error.hpp"
#include "mdr/fit/map_fit.hpp"
#include "mdr/instrument/read_curves.hpp"
#include "mdr/io/units.hpp"
#include "progress.hpp"

namespace mdr::cli {
namespace {

void write_summary(const std::filesystem::path& path, const fit::MapLayout& layout, const io::FitCase& fit_case,
                   const std::filesystem::path& source, const std::vector<fit::PixelFit>& pixels) {
    const io::UnitSystem& system = io::unit_system(fit_case.units);
    std::size_t failed = 0;
    for (const auto& pixel : pixels) failed += pixel.result ? 0 : 1;
    const auto pixel_size = [](double size, std::size_t count) { return count ? size / double(count) : 0.0; };
    const nlohmann::json summary = {
        {"source", source.string()},
        {"units", fit_case.units},
        {"length_unit", std::string(system.length)},
        {"length_size", system.length_size},
        {"columns", layout.columns},
        {"rows", layout.rows},
        {"size", {layout.size_x, layout.size_y}},
        {"pixel_size", {pixel_size(layout.size_x, layout.columns), pixel_size(layout.size_y, layout.rows)}},
        {"pixels", pixels.size()},
        {"failed", failed},
    };
    std::ofstream out(path);
    out << summary.dump(1) << '\n';
    if (!out) throw std::runtime_error("could not write " + path.string());
}

}  // namespace

bool run_map(const io::FitCase& fit_case, const std::string& map, const io::ResultDirectory& directory) {
    fit::require_map_case(fit_case);
    io::FitCase quiet = fit_case;
    quiet.settings.on_iteration = nullptr;  // the map reports pixels, not the iterations of each
    const std::filesystem::path path = std::filesystem::absolute(map);
    instrument::CurveFile file = [&] {
        try {
            return instrument::CurveFile(path);
        } catch (const InvalidInput& error) {
            throw InvalidInput("--map", error.key() + ": " + error.value(), error.rule());
        }
    }();
    const fit::MapLayout layout = fit::map_layout(file, fit_case);
    std::vector<fit::PixelFit> pixels;
    ProgressReporter progress;
    for (std::size_t i = 0; i < file.size(); ++i) {
        pixels.push_back(fit::fit_map_pixel(quiet, path, file, i));
        progress(double(i + 1) / double(file.size()));
    }
    progress.finish();
    directory.write(
        [&](const std::filesystem::path& folder) {
            fit::write_map_table(folder / "map.csv", pixels);
            write_summary(folder / "map.json", layout, fit_case, path, pixels);
        },
        received_signal);
    std::size_t converged = 0, failed = 0;
    for (const auto& pixel : pixels) {
        if (!pixel.result) ++failed;
        else if (pixel.result->converged) ++converged;
    }
    fmt::print("map of {} pixel(s) ({} x {}) fitted alone with the case's [fit]: {} converged, {} not, {} failed\n",
               pixels.size(), layout.columns, layout.rows, converged, pixels.size() - converged - failed, failed);
    for (const auto& pixel : pixels) {
        if (!pixel.result) fmt::print("  pixel {}: {}\n", pixel.index, pixel.failure);
    }
    fmt::print("  results in {}/ (map.csv, map.json)\n", directory.shown());
    return converged == pixels.size();
}

}  // namespace mdr::cli
