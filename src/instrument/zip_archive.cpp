#include "instrument/zip_archive.hpp"

#include <zip.h>

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

}  // namespace

ZipArchive::ZipArchive(const std::filesystem::path& path) : file_(path.string()) {
    int code = 0;
    archive_ = zip_open(file_.c_str(), ZIP_RDONLY, &code);
    if (archive_ == nullptr) {
        throw InvalidInput(file_, "(zip archive)", "cannot be opened as a zip archive: " + libzip_message(code));
    }
}

ZipArchive::~ZipArchive() {
    zip_discard(archive_);
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
    const zip_int64_t index = zip_name_locate(archive_, name.c_str(), 0);
    if (index < 0) throw InvalidInput(file_, name, "the archive has no such member");
    zip_stat_t stat;
    zip_stat_init(&stat);
    if (zip_stat_index(archive_, static_cast<zip_uint64_t>(index), 0, &stat) != 0 || !(stat.valid & ZIP_STAT_SIZE)) {
        throw InvalidInput(file_, name, "the member's size cannot be read: " + std::string(zip_strerror(archive_)));
    }
    if (stat.size > max_member_bytes || inflated_bytes_ + stat.size > max_total_bytes) {
        throw InvalidInput(file_, name,
                           "inflates to " + std::to_string(stat.size) + " bytes, more than the " +
                               std::to_string(max_member_bytes >> 20) + " MiB per member or " +
                               std::to_string(max_total_bytes >> 30) + " GiB per archive that are read");
    }
    zip_file_t* member = zip_fopen_index(archive_, static_cast<zip_uint64_t>(index), 0);
    if (member == nullptr) {
        throw InvalidInput(file_, name, "cannot be opened: " + std::string(zip_strerror(archive_)));
    }
    // One byte more than stated: a member that inflates to more than its stated size is corrupted.
    std::string bytes(static_cast<std::size_t>(stat.size) + 1, '\0');
    std::uint64_t got = 0;
    while (got < bytes.size()) {
        const zip_int64_t n = zip_fread(member, bytes.data() + got, bytes.size() - got);
        if (n < 0) {
            const std::string reason = zip_file_strerror(member);
            zip_fclose(member);
            throw InvalidInput(file_, name, "is corrupted: " + reason);
        }
        if (n == 0) break;
        got += static_cast<std::uint64_t>(n);
    }
    const int closed = zip_fclose(member);
    if (got != stat.size || closed != 0) {
        throw InvalidInput(file_, name,
                           "is corrupted: inflates to " + std::to_string(got) + " bytes, the archive states " +
                               std::to_string(stat.size) + (closed != 0 ? " (" + libzip_message(closed) + ")" : ""));
    }
    bytes.resize(static_cast<std::size_t>(got));
    inflated_bytes_ += got;
    return bytes;
}

}  // namespace mdr::instrument
