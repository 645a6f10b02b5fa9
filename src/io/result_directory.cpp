#include "mdr/io/result_directory.hpp"

#include <fmt/format.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstdio>
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

// A regular file, told by lstat: a symbolic link, even to a regular file, is not one.
bool is_regular_file_itself(const fs::path& path) {
    std::error_code ignored;
    return fs::is_regular_file(fs::symlink_status(path, ignored));
}

// The paths listed in a directory's manifest (relative, `/`-separated: `prony2/fit.json` for a file in a folder
// mdr wrote); nullopt when it has none or its manifest is not a regular file of its own.
std::optional<std::set<std::string>> read_manifest(const fs::path& directory) {
    if (!is_regular_file_itself(directory / manifest_file_name)) return std::nullopt;
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

// True when `name` is a folder that mdr wrote: some listed path lies below it.
bool holds_listed(const std::set<std::string>& listed, const std::string& name) {
    const std::string prefix = name + "/";
    const auto next = listed.lower_bound(prefix);
    return next != listed.end() && next->starts_with(prefix);
}

// The first entry below `directory` that is not mdr's: anything but the manifest, the regular files it lists and
// the folders that hold them (symbolic links are never followed). Empty when there is none.
std::string first_foreign_entry(const fs::path& directory, const std::set<std::string>& listed,
                                std::error_code& error) {
    for (fs::recursive_directory_iterator it(directory, error), end; !error && it != end; it.increment(error)) {
        const std::string name = it->path().lexically_relative(directory).generic_string();
        if (name == manifest_file_name) continue;
        const auto status = it->symlink_status(error);
        if (error) break;
        const bool mine = fs::is_regular_file(status) ? listed.contains(name)
                                                      : fs::is_directory(status) && holds_listed(listed, name);
        if (!mine) return name;
    }
    return {};
}

// The regular files below `directory` (relative, `/`-separated, sorted), the manifest left out.
std::vector<std::string> written_files(const fs::path& directory) {
    std::vector<std::string> names;
    for (const auto& entry : fs::recursive_directory_iterator(directory)) {
        const std::string name = entry.path().lexically_relative(directory).generic_string();
        if (name != manifest_file_name && fs::is_regular_file(entry.symlink_status())) names.push_back(name);
    }
    std::sort(names.begin(), names.end());
    return names;
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
        return fs::is_directory(entry.symlink_status(ignored)) && read_manifest(entry.path()).has_value();
    }
    return false;
}

// The path of a manifest entry below `directory`, when every step to it is a real folder and it is a regular
// file; nullopt for anything else (`..`, an absolute path, a link on the way).
std::optional<fs::path> listed_file(const fs::path& directory, const std::string& entry) {
    const fs::path relative = fs::path(entry).lexically_normal();
    if (relative.empty() || relative.is_absolute() || *relative.begin() == "..") return std::nullopt;
    fs::path path = directory;
    std::error_code ignored;
    for (auto part = relative.begin(); part != relative.end(); ++part) {
        if (path != directory && !fs::is_directory(fs::symlink_status(path, ignored))) return std::nullopt;
        path /= *part;
    }
    return is_regular_file_itself(path) ? std::optional<fs::path>(path) : std::nullopt;
}

// Removes what a killed run wrote into `directory`: the regular files its manifest lists, the manifest, then the
// folders that are empty. Anything else stays, and so does the directory, with a warning on stderr.
void remove_stale_temporary(const fs::path& directory) {
    std::error_code ignored;
    const auto listed = read_manifest(directory);
    for (const auto& entry : listed.value_or(std::set<std::string>{})) {
        if (const auto file = listed_file(directory, entry)) fs::remove(*file, ignored);
    }
    fs::remove(directory / manifest_file_name, ignored);
    std::vector<fs::path> folders;  // deepest last: removed in reverse
    for (fs::recursive_directory_iterator it(directory, ignored), end; !ignored && it != end; it.increment(ignored)) {
        if (fs::is_directory(it->symlink_status(ignored))) folders.push_back(it->path());
    }
    for (auto folder = folders.rbegin(); folder != folders.rend(); ++folder) fs::remove(*folder, ignored);
    if (!fs::remove(directory, ignored)) {
        fmt::print(stderr, "mdr: warning: left {} of a killed run in place: it holds files mdr did not list\n",
                   message_line(directory.string()));
    }
}

void remove_stale_temporaries(const fs::path& parent, const std::string& name) {
    std::error_code error;
    std::vector<fs::path> stale;
    for (fs::directory_iterator it(parent, error), end; !error && it != end; it.increment(error)) {
        if (is_stale_temporary(*it, name)) stale.push_back(it->path());
    }
    for (const auto& path : stale) remove_stale_temporary(path);
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
    const auto mark = fs::symlink_status(target_ / manifest_file_name, error);
    if (fs::exists(mark) && !fs::is_regular_file(mark)) {
        refuse("holds " + std::string(manifest_file_name) + ", which is not a regular file (mdr marks its result "
               "directories with a file it wrote); name a new directory or remove it yourself");
    }
    const auto listed = read_manifest(target_);
    if (!listed) {
        refuse("is a directory that mdr did not write (it has no " + std::string(manifest_file_name) +
               "); name a new directory");
    }
    const std::string foreign = first_foreign_entry(target_, *listed, error);
    if (error) refuse("cannot be read (" + error.message() + ")");
    if (!foreign.empty()) {
        refuse("holds " + message_text(foreign) + ", which mdr did not write; name a new directory or remove it "
               "yourself");
    }
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
        write_manifest(temporary, written_files(temporary));
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
