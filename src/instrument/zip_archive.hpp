#pragma once
/// \file
/// Read-only access to the members of a zip archive (libzip), with bounds on what it inflates.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

struct zip;
struct zip_stat;
struct libdeflate_decompressor;

namespace mdr::instrument {

/// A zip archive opened for reading. Every failure throws mdr::InvalidInput naming the file, the member and
/// what is wrong. Inflation is bounded per member, so that a map of any size can be read member after member: a
/// member that states more than `max_member_bytes`, or a deflated one that states more than deflate can give from
/// its compressed size (`max_deflate_ratio`), or one whose compressed size is more than the archive holds, is
/// refused (zip bombs, corrupted headers) before anything is allocated.
/// A deflated member is inflated whole by libdeflate (twice as fast as zlib) and its CRC-32 checked; any other
/// member (stored, encrypted, sizes not stated) is read through libzip's stream.
class ZipArchive {
public:
    static constexpr std::uint64_t max_member_bytes = std::uint64_t{256} << 20;  ///< 256 MiB per member
    /// The most bytes deflate gives per compressed byte: 258 bytes per 2-bit length/distance pair (RFC 1951).
    static constexpr std::uint64_t max_deflate_ratio = 1032;

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
    /// The same into `bytes`, whose storage is reused (for members read one after another).
    void read(const std::string& name, std::string& bytes);
    /// The archive's path as text, for messages.
    const std::string& file() const noexcept { return file_; }

private:
    /// The member at `index` through libzip's stream (which checks its CRC-32), expected `size` bytes long.
    void read_stream(std::uint64_t index, const std::string& name, std::uint64_t size, std::string& bytes);
    /// The deflated member at `index` inflated by libdeflate, its size and CRC-32 checked against `stat`.
    void inflate_whole(std::uint64_t index, const std::string& name, const struct zip_stat& stat, std::string& bytes);

    struct zip* archive_ = nullptr;
    struct libdeflate_decompressor* inflater_ = nullptr;  ///< made on the first deflated member
    std::string deflated_;  ///< the compressed bytes of the member being inflated, kept for the next one
    std::string file_;
    std::uint64_t archive_bytes_ = 0;  ///< the archive file's size: no member's compressed bytes exceed it
};

}  // namespace mdr::instrument
