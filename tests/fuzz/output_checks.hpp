#pragma once
/// \file
/// The checks fit_fuzz.cpp makes of what `mdr fit` printed and wrote: messages are clean lines (no control bytes,
/// valid UTF-8, no solver log, no text of an uncaught C++ exception), result files are readable as their format,
/// and those of a converged fit hold no NaN, infinity or null outside the places docs/case-format.md allows them.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <regex>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "mutator.hpp"

namespace mdr::fuzz {

/// The first byte of `text` that is a control character (but the line end '\n') or DEL, or that breaks UTF-8, as
/// "byte 0xNN at N"; "" when there is none.
inline std::string raw_byte(std::string_view text) {
    const auto describe = [&](std::size_t at) {
        static constexpr char digits[] = "0123456789abcdef";
        const auto byte = static_cast<unsigned char>(text[at]);
        return std::string("byte 0x") + digits[byte >> 4] + digits[byte & 15] + " at " + std::to_string(at);
    };
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto byte = static_cast<unsigned char>(text[i]);
        if (byte == '\n') continue;
        if (byte < 0x20 || byte == 0x7f) return describe(i);
        if (byte < 0x80) continue;
        const std::size_t length = byte >= 0xf5 ? 0 : byte >= 0xf0 ? 4 : byte >= 0xe0 ? 3 : byte >= 0xc2 ? 2 : 0;
        if (length == 0 || i + length > text.size()) return describe(i);
        for (std::size_t k = 1; k < length; ++k) {
            if ((static_cast<unsigned char>(text[i + k]) & 0xc0) != 0x80) return describe(i);
        }
        i += length - 1;
    }
    return {};
}

/// A line of a solver's own log (glog, as Ceres writes it when it is not silenced), or "" when `text` has none.
inline std::string solver_log_line(const std::string& text) {
    static const std::regex glog(R"((^|\n)[IWEF]\d{4,8} \d\d:\d\d:\d\d|\.(cc|cpp|h):\d+\]|)"
                                 R"(Logging before InitGoogleLogging|trust_region|levenberg_marquardt|ceres::)");
    std::smatch match;
    return std::regex_search(text, match, glog) ? match.str() : std::string();
}

/// The text of an exception that escaped the command's own error handling (its type, a standard library message,
/// a sanitizer report), or "" when `text` has none.
inline std::string uncaught_exception_text(const std::string& text) {
    static const std::regex uncaught(
        R"(terminate called|what\(\):|std::|bad optional access|bad_alloc|bad_variant|basic_string|vector::|)"
        R"(stoi|stod|stoul|Assertion .* failed|AddressSanitizer|LeakSanitizer|runtime error:|Segmentation fault)");
    std::smatch match;
    return std::regex_search(text, match, uncaught) ? match.str() : std::string();
}

/// What ResultScan looks for: files that are not readable as their format (JSON, CSV with as many fields in
/// every row as in its header, TOML), or, in readable files, values that are not finite.
enum class ResultCheck { format, values };

/// Where a result file (fit.json, ranking.json, a CSV file, fitted.toml) is not readable as its format, or holds a
/// value that is not finite (NaN, infinity, null); "" when it has none. Allowed, as docs/case-format.md documents
/// them: the standard errors, 95 % intervals and correlations of a fit with undetermined parameters (and its
/// bands `*_lower`, `*_upper` and `standard_error` columns), spectrum.csv's `tau` of G_inf (`inf`), and
/// `residual_to_noise` of a fit without noise (noise-free data: null in JSON beside `noise` = 0, nan in a CSV file
/// beside a fit.json or ranking.json that reports such a fit).
class ResultScan {
public:
    /// Scans every file below `directory` (a fit's result directory: one fit, or a model choice with one directory
    /// per candidate); the allowances hold where the fit.json beside a file lists undetermined parameters.
    static std::string scan(const std::filesystem::path& directory, ResultCheck check) {
        for (const auto& entry : std::filesystem::recursive_directory_iterator(directory)) {
            if (!entry.is_regular_file()) continue;
            const auto& path = entry.path();
            const ResultScan file{check, has_undetermined(path.parent_path() / "fit.json"),
                                  path.filename() == "spectrum.csv", has_noise_free_fit(path.parent_path())};
            std::string where;
            if (path.extension() == ".json") where = file.scan_json(read_file(path));
            if (path.extension() == ".csv") where = file.scan_csv(read_file(path));
            if (path.extension() == ".toml") where = file.scan_toml(read_file(path));
            if (!where.empty()) return std::filesystem::relative(path, directory).string() + ": " + where;
        }
        return {};
    }

private:
    static bool has_undetermined(const std::filesystem::path& fit_json) {
        const auto json = nlohmann::json::parse(read_file(fit_json), nullptr, false);
        return json.is_object() && json.contains("undetermined") && !json["undetermined"].empty();
    }

    // Whether a fit.json or ranking.json in `directory` reports a fit without noise (`noise` = 0).
    static bool has_noise_free_fit(const std::filesystem::path& directory) {
        const auto noise_free = [](const nlohmann::json& fit) {
            return fit.is_object() && fit.contains("noise") && fit["noise"].is_number() && fit["noise"] == 0.0;
        };
        const auto fit = nlohmann::json::parse(read_file(directory / "fit.json"), nullptr, false);
        if (noise_free(fit)) return true;
        const auto ranking = nlohmann::json::parse(read_file(directory / "ranking.json"), nullptr, false);
        if (!ranking.is_object() || !ranking.contains("candidates") || !ranking["candidates"].is_array()) return false;
        return std::any_of(ranking["candidates"].begin(), ranking["candidates"].end(), noise_free);
    }

    ResultScan(ResultCheck check, bool undetermined, bool spectrum, bool noise_free)
        : check_(check), undetermined_(undetermined), spectrum_(spectrum), noise_free_(noise_free) {}

    std::string scan_json(const std::string& text) const {
        const auto json = nlohmann::json::parse(text, nullptr, false);
        if (json.is_discarded()) return check_ == ResultCheck::format ? "not JSON" : "";
        return check_ == ResultCheck::values ? walk(json, "") : "";
    }

    std::string walk(const nlohmann::json& value, const std::string& path) const {
        const bool allowed = undetermined_ && (path.starts_with("/standard_errors") ||
                                              path.starts_with("/intervals_95") || path.starts_with("/correlation") ||
                                              path.starts_with("/young_moduli_errors"));
        if ((value.is_null() || (value.is_number_float() && !std::isfinite(value.get<double>()))) && !allowed) {
            return path + " = " + value.dump();
        }
        if (value.is_object()) {
            // A fit without noise has no residual-to-noise ratio: null beside its `noise` of 0 (documented).
            const bool noise_free = value.contains("noise") && value["noise"].is_number() && value["noise"] == 0.0;
            for (const auto& [key, item] : value.items()) {
                if (noise_free && key == "residual_to_noise" && item.is_null()) continue;
                // A candidate's special case that fits better, and the one it was refitted from: null when none
                // (documented: docs/case-format.md, "Model choice and spectrum"); names, not numbers.
                if ((key == "better_special_case" || key == "refitted_from") && item.is_null()) continue;
                if (auto where = walk(item, path + "/" + key); !where.empty()) return where;
            }
        }
        if (value.is_array()) {
            for (std::size_t i = 0; i < value.size(); ++i) {
                if (auto where = walk(value[i], path + "/" + std::to_string(i)); !where.empty()) {
                    return where;
                }
            }
        }
        return {};
    }

    std::string scan_csv(const std::string& text) const {
        const auto lines = lines_of(text);
        if (lines.empty()) return check_ == ResultCheck::format ? "empty" : "";
        const auto header = fields_of(lines[0]);
        for (std::size_t row = 1; row < lines.size(); ++row) {
            const auto fields = fields_of(lines[row]);
            if (fields.size() != header.size()) {
                if (check_ == ResultCheck::values) return {};
                return "line " + std::to_string(row + 1) + ": another number of fields than the header";
            }
            if (check_ == ResultCheck::format) continue;
            for (std::size_t column = 0; column < fields.size(); ++column) {
                std::string field = fields[column];
                std::transform(field.begin(), field.end(), field.begin(),
                               [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
                static const std::vector<std::string> non_finite = {"nan",  "-nan", "+nan",     "inf",      "-inf",
                                                                   "+inf", "null", "infinity", "-infinity"};
                if (std::find(non_finite.begin(), non_finite.end(), field) == non_finite.end()) continue;
                const std::string& name = header[column];
                const bool text_column = name == "curve" || name == "candidate" || name == "name";
                const bool band = name.ends_with("_lower") || name.ends_with("_upper") || name == "standard_error";
                const bool g_inf_time = spectrum_ && name == "tau" && fields[0] == "G_inf";
                // A rebound row of curves.csv (NAME:restitution, NAME:contact_time) has no drive: nan, as documented.
                const bool rebound_drive = name == "drive" && (fields[0].ends_with(":restitution") ||
                                                               fields[0].ends_with(":contact_time"));
                const bool no_noise_ratio = noise_free_ && name == "residual_to_noise";
                if (text_column || (band && undetermined_) || g_inf_time || rebound_drive || no_noise_ratio) continue;
                return "line " + std::to_string(row + 1) + ", " + name + " = " + fields[column];
            }
        }
        return {};
    }

    std::string scan_toml(const std::string& text) const {
        try {
            const auto table = toml::parse(text);
            if (check_ == ResultCheck::format) return {};
            std::string where;
            table.for_each([&](const toml::key& key, auto&& node) {
                if (where.empty()) where = walk_toml(node, std::string(key.str()));
            });
            return where;
        } catch (const toml::parse_error& error) {
            return check_ == ResultCheck::format ? "not TOML: " + std::string(error.description()) : "";
        }
    }

    static std::string walk_toml(const toml::node& node, const std::string& path) {
        if (const auto* number = node.as_floating_point(); number && !std::isfinite(number->get())) return path;
        std::string where;
        if (const auto* table = node.as_table()) {
            table->for_each([&](const toml::key& key, auto&& item) {
                if (where.empty()) where = walk_toml(item, path + "." + std::string(key.str()));
            });
        }
        if (const auto* array = node.as_array()) {
            for (std::size_t i = 0; i < array->size() && where.empty(); ++i) {
                where = walk_toml(*array->get(i), path + "[" + std::to_string(i) + "]");
            }
        }
        return where;
    }

    ResultCheck check_;
    bool undetermined_;
    bool spectrum_;
    bool noise_free_;

    // The fields of a CSV line mdr wrote: comma-separated, a field in double quotes may hold commas.
    static std::vector<std::string> fields_of(const std::string& line) {
        std::vector<std::string> fields(1);
        bool quoted = false;
        for (const char c : line) {
            if (c == '"') {
                quoted = !quoted;
            } else if (c == ',' && !quoted) {
                fields.emplace_back();
            } else if (c != '\r') {
                fields.back().push_back(c);
            }
        }
        return fields;
    }
};

}  // namespace mdr::fuzz
