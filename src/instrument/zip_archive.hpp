#pragma once
/// \file
/// Read-only access to the members of a zip archive (libzip), with bounds on what it inflates.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

struct zip;

namespace mdr::instrument {

/// A zip archive opened for reading. Every failure throws mdr::InvalidInput naming the file, the member and
/// what is wrong. Inflation is bounded: a member larger than `max_member_bytes`, or more than
/// `max_total_bytes` inflated from one archive in all, is refused (zip bombs).
class ZipArchive {
public:
    static constexpr std::uint64_t max_member_bytes = std::uint64_t{256} << 20;  ///< 256 MiB per member
    static constexpr std::uint64_t max_total_bytes = std::uint64_t{8} << 30;     ///< 8 GiB per archive

    /// Opens `path`; throws mdr::InvalidInput if it is not a readable zip archive.
    explicit ZipArchive(const std::filesystem::path& path);
    ~ZipArchive();
    ZipArchive(const ZipArchive&) = delete;
    ZipArchive& operator=(const ZipArchive&) = delete;

    /// The names of all members, in the archive's order.
    std::vector<std::string> names() const;
    /// Whether a member of this exact name exists.
    bool contains(const std::string& name) const;
    /// The member's inflated bytes; throws mdr::InvalidInput if it is missing, too large or corrupted.
    std::string read(const std::string& name);
    /// The archive's path as text, for messages.
    const std::string& file() const noexcept { return file_; }

private:
    struct zip* archive_ = nullptr;
    std::string file_;
    std::uint64_t inflated_bytes_ = 0;
};

}  // namespace mdr::instrument
