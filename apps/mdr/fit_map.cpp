#include "fit_map.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <vector>

#include "interrupt.hpp"
#include "mdr/error.hpp"
#include "mdr/fit/map_fit.hpp"
#include "mdr/instrument/read_curves.hpp"
#include "progress.hpp"

namespace mdr::cli {

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
            fit::write_map_summary(folder / "map.json", layout, fit_case.units, path, pixels);
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
