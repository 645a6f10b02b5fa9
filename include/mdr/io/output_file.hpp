#pragma once

#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <string_view>
#include <utility>

namespace mdr::io {

/// A text file that mdr writes: formatted with fmt into a buffer, written in large blocks, and closed with a check.
/// Every write error, the last block's included (a full disk), is a std::system_error naming the file, thrown by
/// print or close; the destructor never throws (fmt 9's output_file throws again from its destructor after a failed
/// write, which ends the program). A file that is not closed may be incomplete: the result directory that holds
/// it is discarded when its writer throws (io::ResultDirectory).
class OutputFile {
public:
    /// Creates or truncates `path`; std::system_error naming it where it cannot be opened.
    explicit OutputFile(const std::filesystem::path& path);
    ~OutputFile();
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    /// Formats `args` by `format` (fmt's syntax) onto the file.
    template <typename... T>
    void print(fmt::format_string<T...> format, T&&... args) {
        fmt::format_to(fmt::appender(buffer_), format, std::forward<T>(args)...);
        if (buffer_.size() >= block_size) write_buffer();
    }
    /// Writes what is buffered and closes the file; std::system_error naming the file on any error.
    void close();

private:
    static constexpr std::size_t block_size = std::size_t{1} << 16;
    void write_buffer();
    [[noreturn]] void fail(int error) const;

    std::filesystem::path path_;
    std::FILE* file_;
    fmt::memory_buffer buffer_;
};

/// Writes `text` to `path` (created or truncated) and closes it; std::system_error naming the file on any error.
void write_text_file(const std::filesystem::path& path, std::string_view text);

}  // namespace mdr::io
