#pragma once
/// \file
/// The members of a zip archive unpacked (libzip) and packed again (libdeflate), so that the fit fuzzer can mutate
/// a member of an instrument archive (a JPK file's header properties, a channel's data) and give the reader an
/// archive whose sizes and CRC-32 agree with the mutated bytes: the mutation reaches the parser behind the zip.

#include <libdeflate.h>
#include <zip.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace mdr::fuzz {

/// One member of a zip archive: its name and its inflated bytes.
struct ZipMember {
    std::string name;
    std::string bytes;
};

/// The members of the zip archive held in `archive`, in its order; empty when it is not a readable archive.
inline std::vector<ZipMember> unzip(const std::string& archive) {
    zip_error_t error;
    zip_error_init(&error);
    zip_source_t* source = zip_source_buffer_create(archive.data(), archive.size(), 0, &error);
    zip_t* opened = source == nullptr ? nullptr : zip_open_from_source(source, ZIP_RDONLY, &error);
    zip_error_fini(&error);
    if (opened == nullptr) {
        if (source != nullptr) zip_source_free(source);
        return {};
    }
    const std::unique_ptr<zip_t, decltype(&zip_discard)> zip(opened, &zip_discard);
    std::vector<ZipMember> members;
    const zip_int64_t count = zip_get_num_entries(zip.get(), 0);
    for (zip_int64_t index = 0; index < count; ++index) {
        const auto at = static_cast<zip_uint64_t>(index);
        zip_stat_t stat;
        zip_stat_init(&stat);
        zip_file_t* file = zip_stat_index(zip.get(), at, 0, &stat) == 0 ? zip_fopen_index(zip.get(), at, 0) : nullptr;
        if (file == nullptr) return {};
        ZipMember member{stat.name, std::string(static_cast<std::size_t>(stat.size), '\0')};
        const zip_int64_t read = zip_fread(file, member.bytes.data(), stat.size);
        zip_fclose(file);
        if (read != static_cast<zip_int64_t>(stat.size)) return {};
        members.push_back(std::move(member));
    }
    return members;
}

/// A zip archive (APPNOTE 6.3.x, 4.3: local headers, central directory, end record) of `members`, each deflated
/// (libdeflate, level 1) or, with `store`, stored as it is.
inline std::string zip(const std::vector<ZipMember>& members, bool store) {
    std::string archive;
    std::string directory;
    const auto put = [](std::string& to, std::uint32_t value, std::size_t bytes) {  // little-endian
        for (std::size_t i = 0; i < bytes; ++i) to.push_back(static_cast<char>((value >> (8 * i)) & 0xffU));
    };
    const std::unique_ptr<libdeflate_compressor, decltype(&libdeflate_free_compressor)> compressor(
        libdeflate_alloc_compressor(1), &libdeflate_free_compressor);
    for (const auto& member : members) {
        std::string data = member.bytes;
        if (!store) {
            data.resize(libdeflate_deflate_compress_bound(compressor.get(), member.bytes.size()));
            data.resize(libdeflate_deflate_compress(compressor.get(), member.bytes.data(), member.bytes.size(),
                                                    data.data(), data.size()));
        }
        const auto crc = libdeflate_crc32(0, member.bytes.data(), member.bytes.size());
        const auto offset = static_cast<std::uint32_t>(archive.size());
        // The fields both headers share: version needed 2.0, no flags, method, time 0, date 1980-01-01, CRC-32,
        // compressed and inflated sizes, the name's length, no extra field.
        std::string common;
        put(common, 20, 2);
        put(common, 0, 2);
        put(common, store ? 0 : 8, 2);
        put(common, 0, 2);
        put(common, 0x21, 2);
        put(common, crc, 4);
        put(common, static_cast<std::uint32_t>(data.size()), 4);
        put(common, static_cast<std::uint32_t>(member.bytes.size()), 4);
        put(common, static_cast<std::uint32_t>(member.name.size()), 2);
        put(common, 0, 2);
        put(archive, 0x04034b50, 4);
        archive += common + member.name + data;
        put(directory, 0x02014b50, 4);
        put(directory, 20, 2);  // made by version 2.0
        directory += common;
        put(directory, 0, 4);  // no comment, disk 0
        put(directory, 0, 2);  // internal attributes
        put(directory, 0, 4);  // external attributes
        put(directory, offset, 4);
        directory += member.name;
    }
    const auto directory_offset = static_cast<std::uint32_t>(archive.size());
    archive += directory;
    put(archive, 0x06054b50, 4);
    put(archive, 0, 4);  // disk 0, the directory on disk 0
    put(archive, static_cast<std::uint32_t>(members.size()), 2);
    put(archive, static_cast<std::uint32_t>(members.size()), 2);
    put(archive, static_cast<std::uint32_t>(directory.size()), 4);
    put(archive, directory_offset, 4);
    put(archive, 0, 2);  // no comment
    return archive;
}

}  // namespace mdr::fuzz
