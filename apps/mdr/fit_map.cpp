#include "fit_map.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <vector>

#include "interrupt.hpp"
#include "mdr/error.hpp"
#include "mdr/fitcase/instrument_curve.hpp"
#include "mdr/fitcase/map_fit.hpp"
#include "mdr/instrument/read_curves.hpp"
#include "mdr/parallel/run_on_threads.hpp"
#include "progress.hpp"

namespace mdr::cli {

bool run_map(const fitcase::FitCase& fit_case, const std::string& map, const io::ResultDirectory& directory,
             unsigned jobs) {
    fitcase::require_map_case(fit_case);
    const std::filesystem::path path = std::filesystem::absolute(map);
    instrument::CurveFile file = [&] {
        try {
            return instrument::CurveFile(path, fitcase::read_options(fit_case.data.front()));
        } catch (const InvalidInput& error) {
            throw InvalidInput("--map", error.key() + ": " + error.value(), error.rule());
        }
    }();
    fitcase::require_map_time(file, fit_case, path);
    const fitcase::MapLayout layout = fitcase::map_layout(file, fit_case);
    const unsigned threads = parallel::local_threads(jobs, file.size());
    ProgressReporter progress;
    const std::vector<fitcase::PixelFit> pixels =
        fitcase::fit_map_pixels(fit_case, path, file.size(), threads, [&](std::size_t done, std::size_t total) {
            progress(total ? double(done) / double(total) : 1.0);
        });
    progress.finish();
    const fitcase::MapRows table = fitcase::map_rows(pixels, fit_case);
    directory.write(
        [&](const std::filesystem::path& folder) {
            fitcase::write_map_table(folder / "map.csv", table);
            fitcase::write_map_summary(folder / "map.json", layout, fit_case, path, table);
        },
        received_signal);
    std::size_t converged = 0, failed = 0;
    for (const auto& pixel : pixels) {
        if (!pixel.result) ++failed;
        else if (pixel.result->converged) ++converged;
    }
    fmt::print("map of {} pixel(s) ({} x {}) fitted alone with the case's [fit]: {} converged, {} not, {} failed ({} "
               "thread(s))\n",
               pixels.size(), layout.columns, layout.rows, converged, pixels.size() - converged - failed, failed,
               threads);
    for (const auto& pixel : pixels) {
        if (!pixel.result) fmt::print("  pixel {}: {}\n", pixel.index, pixel.failure);
    }
    fmt::print("  results in {}/ (map.csv, map.json)\n", directory.shown());
    return converged == pixels.size();
}

}  // namespace mdr::cli
