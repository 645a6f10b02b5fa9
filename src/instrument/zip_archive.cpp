#include "instrument/zip_archive.hpp"

#include <libdeflate.h>
#include <zip.h>

#include <cstdio>
#include <memory>
#include <new>

#include "mdr/error.hpp"

namespace mdr::instrument {

namespace {

std::string libzip_message(int code) {
    zip_error_t error;
    zip_error_init_with_code(&error, code);
    std::string message = zip_error_strerror(&error);
    zip_error_fini(&error);
    return message;
}

std::string hex32(std::uint32_t value) {
    char text[11];
    std::snprintf(text, sizeof text, "0x%08x", value);
    return text;
}

/// Whether a member can be inflated whole by libdeflate: deflated, not encrypted, its sizes and CRC-32 stated,
/// and its compressed size within what deflate can need for its inflated size (stored blocks: 5 bytes of header
/// per 65 535 bytes, RFC 1951 §3.2.4; a generous bound, so that a corrupted compressed size cannot make a large
/// allocation). Any other member is read through libzip's stream.
bool inflates_whole(const struct zip_stat& stat) {
    constexpr zip_uint64_t needed =
        ZIP_STAT_SIZE | ZIP_STAT_COMP_SIZE | ZIP_STAT_COMP_METHOD | ZIP_STAT_CRC | ZIP_STAT_ENCRYPTION_METHOD;
    return (stat.valid & needed) == needed && stat.comp_method == ZIP_CM_DEFLATE &&
           stat.encryption_method == ZIP_EM_NONE && stat.comp_size <= stat.size + stat.size / 8 + 1024;
}

/// An open member, closed (zip_fclose) when it goes out of scope; release() it to read zip_fclose's result.
struct MemberCloser {
    void operator()(zip_file_t* member) const noexcept { zip_fclose(member); }
};
using OpenMember = std::unique_ptr<zip_file_t, MemberCloser>;

}  // namespace

ZipArchive::ZipArchive(const std::filesystem::path& path) : file_(path.string()) {
    std::error_code size_error;
    archive_bytes_ = std::filesystem::file_size(path, size_error);
    if (size_error) throw InvalidInput(file_, "(zip archive)", "cannot be read: " + size_error.message());
    int code = 0;
    archive_ = zip_open(file_.c_str(), ZIP_RDONLY, &code);
    if (archive_ == nullptr) {
        throw InvalidInput(file_, "(zip archive)", "cannot be opened as a zip archive: " + libzip_message(code));
    }
}

ZipArchive::~ZipArchive() {
    zip_discard(archive_);
    libdeflate_free_decompressor(inflater_);
}

std::vector<std::string> ZipArchive::names() const {
    const zip_int64_t count = zip_get_num_entries(archive_, 0);
    std::vector<std::string> result;
    result.reserve(static_cast<std::size_t>(count > 0 ? count : 0));
    for (zip_int64_t index = 0; index < count; ++index) {
        const char* name = zip_get_name(archive_, static_cast<zip_uint64_t>(index), 0);
        if (name != nullptr) result.emplace_back(name);
    }
    return result;
}

bool ZipArchive::contains(const std::string& name) const {
    return zip_name_locate(archive_, name.c_str(), 0) >= 0;
}

std::string ZipArchive::read(const std::string& name) {
    std::string bytes;
    read(name, bytes);
    return bytes;
}

void ZipArchive::read(const std::string& name, std::string& bytes) {
    const zip_int64_t index = zip_name_locate(archive_, name.c_str(), 0);
    if (index < 0) throw InvalidInput(file_, name, "the archive has no such member");
    zip_stat_t stat;
    zip_stat_init(&stat);
    if (zip_stat_index(archive_, static_cast<zip_uint64_t>(index), 0, &stat) != 0 || !(stat.valid & ZIP_STAT_SIZE)) {
        throw InvalidInput(file_, name, "the member's size cannot be read: " + std::string(zip_strerror(archive_)));
    }
    if (stat.size > max_member_bytes) {
        throw InvalidInput(file_, name,
                           "inflates to " + std::to_string(stat.size) + " bytes, more than the " +
                               std::to_string(max_member_bytes >> 20) + " MiB per member that are read");
    }
    if ((stat.valid & ZIP_STAT_COMP_SIZE) && stat.comp_size > archive_bytes_) {
        throw InvalidInput(file_, name,
                           "states " + std::to_string(stat.comp_size) + " compressed bytes, more than the archive's " +
                               std::to_string(archive_bytes_) + " (a corrupted or truncated archive)");
    }
    const bool deflated = (stat.valid & ZIP_STAT_COMP_METHOD) && stat.comp_method == ZIP_CM_DEFLATE;
    if (deflated && (stat.valid & ZIP_STAT_COMP_SIZE) && stat.size / max_deflate_ratio > stat.comp_size) {
        throw InvalidInput(file_, name,
                           "states " + std::to_string(stat.size) + " bytes from " + std::to_string(stat.comp_size) +
                               " compressed, more than deflate's " + std::to_string(max_deflate_ratio) +
                               " bytes per compressed byte (RFC 1951)");
    }
    if (inflates_whole(stat))
        inflate_whole(static_cast<zip_uint64_t>(index), name, stat, bytes);
    else
        read_stream(static_cast<zip_uint64_t>(index), name, stat.size, bytes);
}

void ZipArchive::read_stream(std::uint64_t index, const std::string& name, std::uint64_t size, std::string& bytes) {
    OpenMember member(zip_fopen_index(archive_, index, 0));
    if (member == nullptr) {
        throw InvalidInput(file_, name, "cannot be opened: " + std::string(zip_strerror(archive_)));
    }
    // One byte more than stated: a member that inflates to more than its stated size is corrupted.
    bytes.resize(static_cast<std::size_t>(size) + 1);
    std::uint64_t got = 0;
    while (got < bytes.size()) {
        const zip_int64_t n = zip_fread(member.get(), bytes.data() + got, bytes.size() - got);
        if (n < 0) throw InvalidInput(file_, name, std::string("is corrupted: ") + zip_file_strerror(member.get()));
        if (n == 0) break;
        got += static_cast<std::uint64_t>(n);
    }
    const int closed = zip_fclose(member.release());
    if (got != size || closed != 0) {
        throw InvalidInput(file_, name,
                           "is corrupted: inflates to " + std::to_string(got) + " bytes, the archive states " +
                               std::to_string(size) + (closed != 0 ? " (" + libzip_message(closed) + ")" : ""));
    }
    bytes.resize(static_cast<std::size_t>(got));
}

void ZipArchive::inflate_whole(std::uint64_t index, const std::string& name, const struct zip_stat& stat,
                               std::string& bytes) {
    OpenMember member(zip_fopen_index(archive_, index, ZIP_FL_COMPRESSED));
    if (member == nullptr) {
        throw InvalidInput(file_, name, "cannot be opened: " + std::string(zip_strerror(archive_)));
    }
    std::string& deflated = deflated_;
    deflated.resize(static_cast<std::size_t>(stat.comp_size));
    std::uint64_t got = 0;
    std::string reason;
    while (got < deflated.size()) {
        const zip_int64_t n = zip_fread(member.get(), deflated.data() + got, deflated.size() - got);
        if (n < 0) reason = std::string(" (") + zip_file_strerror(member.get()) + ")";
        if (n <= 0) break;
        got += static_cast<std::uint64_t>(n);
    }
    member.reset();
    if (got != stat.comp_size) {
        throw InvalidInput(file_, name,
                           "is truncated: " + std::to_string(got) + " of its " + std::to_string(stat.comp_size) +
                               " compressed bytes can be read" + reason);
    }
    if (inflater_ == nullptr) inflater_ = libdeflate_alloc_decompressor();
    if (inflater_ == nullptr) throw std::bad_alloc();
    bytes.resize(static_cast<std::size_t>(stat.size));
    std::size_t inflated = 0;
    const libdeflate_result result = libdeflate_deflate_decompress(inflater_, deflated.data(), deflated.size(),
                                                                   bytes.data(), bytes.size(), &inflated);
    if (result == LIBDEFLATE_INSUFFICIENT_SPACE) {
        throw InvalidInput(file_, name,
                           "is corrupted: inflates to more than the " + std::to_string(stat.size) +
                               " bytes the archive states");
    }
    if (result == LIBDEFLATE_SUCCESS && inflated != stat.size) {
        throw InvalidInput(file_, name,
                           "is corrupted: inflates to " + std::to_string(inflated) + " bytes, the archive states " +
                               std::to_string(stat.size));
    }
    if (result != LIBDEFLATE_SUCCESS) throw InvalidInput(file_, name, "is corrupted: its deflate stream is invalid");
    const std::uint32_t crc = libdeflate_crc32(0, bytes.data(), bytes.size());
    if (crc != stat.crc) {
        throw InvalidInput(file_, name,
                           "is corrupted: its CRC-32 is " + hex32(crc) + ", the archive states " + hex32(stat.crc));
    }
}

}  // namespace mdr::instrument
