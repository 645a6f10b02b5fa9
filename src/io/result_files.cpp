#include "mdr/io/result_files.hpp"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <stdexcept>

#include "mdr/io/document.hpp"
#include "mdr/io/history_columns.hpp"
#include "mdr/io/output_file.hpp"
#include "mdr/io/profile_columns.hpp"
#include "mdr/io/summary.hpp"

namespace mdr::io {
namespace fs = std::filesystem;

std::string summary_json(const drivers::ContactCase& contact_case, const drivers::IndentationResult& result,
                         double wall_seconds) {
    return to_json(Document{summarize(contact_case, result, wall_seconds)});
}

void write_indentation_result(const fs::path& directory, const drivers::ContactCase& contact_case,
                              const drivers::IndentationResult& result, double wall_seconds) {
    auto history = OutputFile(directory / "history.csv");
    const auto columns = history_columns(result);
    for (std::size_t j = 0; j < columns.size(); ++j) history.print("{}{}", j == 0 ? "" : ",", columns[j].name);
    history.print("\n");
    fmt::memory_buffer row;
    for (std::size_t i = 0; i < result.time.size(); ++i) {
        row.clear();
        for (std::size_t j = 0; j < columns.size(); ++j) {
            if (j > 0) row.push_back(',');
            fmt::format_to(fmt::appender(row), FMT_COMPILE("{}"), columns[j].value(result, i));
        }
        row.push_back('\n');
        history.print("{}", fmt::string_view(row.data(), row.size()));
    }
    history.close();

    auto summary = OutputFile(directory / "summary.json");
    summary.print("{}\n", summary_json(contact_case, result, wall_seconds));
    summary.close();

    if (result.snapshots.empty()) return;
    auto profiles = OutputFile(directory / "profiles.csv");
    const auto profile = profile_columns(result);
    for (std::size_t k = 0; k < profile.size(); ++k) profiles.print("{}{}", k == 0 ? "" : ",", profile[k].name);
    profiles.print("\n");
    for (const auto& snapshot : result.snapshots) {
        for (std::size_t j = 0; j < snapshot.radius.size(); ++j) {
            for (std::size_t k = 0; k < profile.size(); ++k)
                profiles.print("{}{}", k == 0 ? "" : ",", profile[k].value(snapshot, j));
            profiles.print("\n");
        }
    }
    profiles.close();
}

}  // namespace mdr::io
