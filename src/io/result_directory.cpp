#include "mdr/io/result_directory.hpp"

#include <fmt/format.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <fstream>
#include <optional>
#include <set>
#include <system_error>

#include "mdr/error.hpp"

namespace mdr::io {
namespace fs = std::filesystem;

namespace {

constexpr std::string_view manifest_comment =
    "# mdr result directory: mdr replaces it only while it holds nothing but the files listed below";
constexpr std::string_view partial_infix = ".mdr-partial-";
constexpr std::string_view old_infix = ".mdr-old-";

// Absolute and normalised, without a trailing separator: `res/` and `res` are the same directory.
fs::path normalised(const fs::path& path) {
    fs::path result = fs::absolute(path).lexically_normal();
    while (!result.has_filename() && result != result.root_path()) result = result.parent_path();
    return result;
}

// True when `path` is `ancestor` or lies below it (both canonical).
bool is_within(const fs::path& path, const fs::path& ancestor) {
    auto a = ancestor.begin();
    for (auto p = path.begin(); a != ancestor.end(); ++a, ++p) {
        if (a->empty()) continue;  // the empty element after a trailing separator
        if (p == path.end() || *p != *a) return false;
    }
    return true;
}

fs::path resolved(const fs::path& path) {
    std::error_code error;
    const fs::path canonical = fs::weakly_canonical(path, error);
    return error ? normalised(path) : canonical;
}

// The names listed in a directory's manifest; nullopt when it has none.
std::optional<std::set<std::string>> read_manifest(const fs::path& directory) {
    std::ifstream file(directory / manifest_file_name);
    if (!file) return std::nullopt;
    std::set<std::string> names;
    for (std::string line; std::getline(file, line);) {
        if (!line.empty() && line.front() != '#') names.insert(line);
    }
    return names;
}

void write_manifest(const fs::path& directory, const std::vector<std::string>& names) {
    std::ofstream file(directory / manifest_file_name);
    file << manifest_comment << '\n';
    for (const auto& name : names) file << name << '\n';
    if (!file.flush()) throw std::system_error(errno, std::generic_category(), "cannot write the manifest");
}

// True when the entry `name` of a result directory is what mdr wrote there: a regular file the manifest lists, or a
// folder it lists (a candidate's, mdr fit) holding only regular files that it lists as `name/file`.
bool is_listed(const fs::path& path, const std::string& name, const std::set<std::string>& listed) {
    std::error_code error;
    const auto status = fs::symlink_status(path, error);
    if (error || !listed.contains(name)) return false;
    if (fs::is_regular_file(status)) return true;
    if (!fs::is_directory(status)) return false;
    for (fs::directory_iterator it(path, error), end; !error && it != end; it.increment(error)) {
        const auto inner = fs::symlink_status(it->path(), error);
        if (error || !fs::is_regular_file(inner) || !listed.contains(name + "/" + it->path().filename().string())) {
            return false;
        }
    }
    return !error;
}

bool process_alive(pid_t pid) { return kill(pid, 0) == 0 || errno == EPERM; }

// `.NAME<infix>PID-N` of a process that no longer runs, holding a manifest: left by a killed run of mdr.
bool is_stale_temporary(const fs::directory_entry& entry, const std::string& name) {
    const std::string file = entry.path().filename().string();
    for (const auto infix : {partial_infix, old_infix}) {
        const std::string prefix = "." + name + std::string(infix);
        if (!file.starts_with(prefix)) continue;
        pid_t pid = 0;
        const char* first = file.data() + prefix.size();
        const auto [end, error] = std::from_chars(first, file.data() + file.size(), pid);
        if (error != std::errc() || end == first || pid <= 0 || pid == getpid() || process_alive(pid)) return false;
        std::error_code ignored;
        return entry.is_directory(ignored) && !entry.is_symlink(ignored) && read_manifest(entry.path()).has_value();
    }
    return false;
}

void remove_stale_temporaries(const fs::path& parent, const std::string& name) {
    std::error_code error;
    std::vector<fs::path> stale;
    for (fs::directory_iterator it(parent, error), end; !error && it != end; it.increment(error)) {
        if (is_stale_temporary(*it, name)) stale.push_back(it->path());
    }
    for (const auto& path : stale) fs::remove_all(path, error);
}

}  // namespace

ResultDirectory::ResultDirectory(const fs::path& directory, std::string key, std::vector<fs::path> inputs)
    : target_(normalised(directory.empty() ? fs::path(".") : directory)),
      key_(std::move(key)),
      shown_(directory.string()),
      inputs_(std::move(inputs)) {
    if (directory.empty()) throw InvalidInput(key_, "\"\"", "must name a directory");
    check();
}

void ResultDirectory::check() const {
    const auto refuse = [&](const std::string& rule) { throw InvalidInput(key_, shown_, rule); };
    const fs::path real = resolved(target_);
    if (is_within(resolved(fs::current_path()), real)) {
        refuse("is the working directory or one of its parents; mdr never replaces it, name a new directory");
    }
    for (const auto& input : inputs_) {
        if (is_within(resolved(input).parent_path(), real)) {
            refuse("holds the input file " + input.string() + "; mdr never replaces it, name a new directory");
        }
    }
    std::error_code error;
    const auto status = fs::symlink_status(target_, error);
    if (!fs::exists(status)) {
        for (fs::path ancestor = target_.parent_path();; ancestor = ancestor.parent_path()) {
            if (fs::exists(ancestor, error)) {
                if (!fs::is_directory(ancestor, error)) {
                    refuse("lies below " + ancestor.string() + ", which is not a directory");
                }
                return;
            }
            if (ancestor == ancestor.root_path()) return;
        }
    }
    if (fs::is_symlink(status)) refuse("is a symbolic link; mdr writes only directories it created itself");
    if (!fs::is_directory(status)) {
        refuse("is an existing file or device; mdr writes only new directories or result directories it wrote "
               "itself");
    }
    const auto listed = read_manifest(target_);
    if (!listed) {
        refuse("is a directory that mdr did not write (it has no " + std::string(manifest_file_name) +
               "); name a new directory");
    }
    for (fs::directory_iterator it(target_, error), end; it != end; it.increment(error)) {
        if (error) break;
        const std::string name = it->path().filename().string();
        if (name == manifest_file_name) continue;
        if (!is_listed(it->path(), name, *listed)) {
            refuse("holds " + name + ", which mdr did not write; name a new directory or remove it yourself");
        }
    }
    if (error) refuse("cannot be read (" + error.message() + ")");
}

void ResultDirectory::write(const std::function<void(const fs::path&)>& write_files,
                            const std::function<bool()>& interrupted) const {
    static std::atomic<unsigned> writes{0};
    check();
    const fs::path parent = target_.parent_path();
    const std::string name = target_.filename().string();
    const std::string suffix = fmt::format("{}-{}", getpid(), writes++);
    const fs::path temporary = parent / ("." + name + std::string(partial_infix) + suffix);
    const fs::path old = parent / ("." + name + std::string(old_infix) + suffix);
    std::error_code ignored;
    try {
        fs::create_directories(parent);
        remove_stale_temporaries(parent, name);
        fs::create_directory(temporary);
        write_manifest(temporary, {});  // marks it as mdr's before anything else is written
        write_files(temporary);
        if (interrupted && interrupted()) throw Interrupted();
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(temporary)) {
            const std::string entry_name = entry.path().filename().string();
            if (entry_name == manifest_file_name) continue;
            names.push_back(entry_name);
            if (!entry.is_directory()) continue;
            for (const auto& inner : fs::directory_iterator(entry.path())) {
                names.push_back(entry_name + "/" + inner.path().filename().string());
            }
        }
        std::sort(names.begin(), names.end());
        write_manifest(temporary, names);
        check();
        if (fs::exists(fs::symlink_status(target_))) {
            fs::rename(target_, old);
            try {
                fs::rename(temporary, target_);
            } catch (...) {
                fs::rename(old, target_, ignored);
                throw;
            }
            fs::remove_all(old, ignored);
        } else {
            fs::rename(temporary, target_);
        }
    } catch (const std::system_error& error) {
        fs::remove_all(temporary, ignored);
        throw std::runtime_error(
            fmt::format("{} = {}: cannot write the result ({})", key_, shown_, error.code().message()));
    } catch (...) {
        fs::remove_all(temporary, ignored);
        throw;
    }
}

}  // namespace mdr::io
