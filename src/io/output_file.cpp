#include "mdr/io/output_file.hpp"

#include <cerrno>
#include <string>
#include <system_error>

namespace mdr::io {

OutputFile::OutputFile(const std::filesystem::path& path) : path_(path), file_(std::fopen(path.c_str(), "wb")) {
    if (file_ == nullptr) fail(errno);
}

OutputFile::~OutputFile() {
    if (file_ != nullptr) std::fclose(file_);
}

void OutputFile::write_buffer() {
    if (buffer_.size() == 0) return;
    const std::size_t size = buffer_.size();
    const std::size_t written = std::fwrite(buffer_.data(), 1, size, file_);
    buffer_.clear();  // whatever happened: a failed block is reported once, never written again
    if (written != size) fail(errno != 0 ? errno : EIO);
}

void OutputFile::close() {
    if (file_ == nullptr) return;
    write_buffer();
    const bool flushed = std::fflush(file_) == 0 && std::ferror(file_) == 0;
    const int flush_error = errno;
    const int closed = std::fclose(file_);
    const int close_error = errno;
    file_ = nullptr;
    if (!flushed) fail(flush_error != 0 ? flush_error : EIO);
    if (closed != 0) fail(close_error != 0 ? close_error : EIO);
}

void OutputFile::fail(int error) const {
    throw std::system_error(error, std::generic_category(), "cannot write " + path_.string());
}

void write_text_file(const std::filesystem::path& path, std::string_view text) {
    OutputFile file(path);
    file.print("{}", text);
    file.close();
}

}  // namespace mdr::io
