#pragma once
/// \file
/// Result directories (`--out DIR`): mdr creates them, and replaces only what it wrote itself. A user's files are
/// never changed: an existing file, device or link, a directory holding anything mdr did not write, the working
/// directory and the directories of the input files (with all their parents) are refused before any computing.

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace mdr::io {

/// The file that marks a directory as a result directory of mdr: a regular file (never a link or a folder). It
/// lists, one path a line after a comment line, every file that mdr (or `python3 -m mdr plot`, which appends its
/// figures) wrote into the directory; a file in a folder mdr wrote as `folder/name`.
inline constexpr std::string_view manifest_file_name = ".mdr-result";

/// A result directory, checked when it is named and written atomically at the end.
///
/// The temporary directory is `.NAME.mdr-partial-PID-N` beside it. It is removed on every error and on
/// interruption; those of killed runs (their process gone) are recognised by their manifest, and the next write
/// beside them removes the regular files the manifest lists, then the folders left empty; anything else stays
/// (with a warning on stderr).
class ResultDirectory {
public:
    /// Checks that `directory` may be written. `key` names it in messages (`--out`); `inputs` are the files the
    /// command reads, whose directories must not be replaced. Throws mdr::InvalidInput (`--out = DIR: rule`) for
    /// an empty path, an existing file, device or symbolic link, a directory that is not a result directory of mdr
    /// (no manifest, a manifest that is not a regular file, or an entry that is not a regular file the manifest
    /// lists nor a folder holding one; links are never followed), the working directory, an input's directory or a
    /// parent of any of them, or a path below an existing file.
    ResultDirectory(const std::filesystem::path& directory, std::string key,
                    std::vector<std::filesystem::path> inputs = {});

    /// The directory as the user named it (for messages).
    const std::string& shown() const noexcept { return shown_; }

    /// Writes the files with `write_files(temporary)`, records them in the manifest, then puts the temporary
    /// directory in place of the result directory (checked again first). Throws mdr::Interrupted when
    /// `interrupted()` is true once the files are written, mdr::InvalidInput when the directory no longer passes
    /// the check, std::runtime_error when the file system refuses; in each case nothing is left behind.
    void write(const std::function<void(const std::filesystem::path&)>& write_files,
               const std::function<bool()>& interrupted = {}) const;

private:
    void check() const;

    std::filesystem::path target_;   // absolute, normalised, without a trailing separator
    std::string key_;
    std::string shown_;
    std::vector<std::filesystem::path> inputs_;
};

}  // namespace mdr::io
