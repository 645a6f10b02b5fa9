// Damaged zip members on the libdeflate path (src/instrument/zip_archive.cpp): a copy of the vendor single curve
// fmt-jpk-fd_spot3-0192.jpk-force with one field of the member segments/0/channels/vDeflection.dat changed where
// the zip format (PKWARE APPNOTE 4.3.7, 4.3.12) puts it. Each is refused with one mdr::InvalidInput naming the
// file and the member, and a stated size is checked before anything of that size is allocated.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "mdr/error.hpp"
#include "mdr/instrument/read_curves.hpp"

namespace {

namespace fs = std::filesystem;

const std::string member = "segments/0/channels/vDeflection.dat";

std::string vendor_curve() {
    std::ifstream stream(fs::path(MDR_VENDOR_DATA) / "fmt-jpk-fd_spot3-0192.jpk-force", std::ios::binary);
    return {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
}

std::uint32_t little_endian(const std::string& bytes, std::size_t at, std::size_t width) {
    std::uint32_t value = 0;
    for (std::size_t i = 0; i < width; ++i) {
        value |= std::uint32_t{static_cast<unsigned char>(bytes[at + i])} << (8 * i);
    }
    return value;
}

void put_little_endian(std::string& bytes, std::size_t at, std::uint32_t value) {
    for (std::size_t i = 0; i < 4; ++i) bytes[at + i] = static_cast<char>((value >> (8 * i)) & 0xffu);
}

/// The offset of `member`'s central directory header (signature PK\1\2, the name at byte 46; APPNOTE 4.3.12).
std::size_t central_header(const std::string& bytes) {
    for (std::size_t at = bytes.find("PK\x01\x02"); at != std::string::npos; at = bytes.find("PK\x01\x02", at + 4)) {
        if (bytes.compare(at + 46, member.size(), member) == 0 && little_endian(bytes, at + 28, 2) == member.size()) {
            return at;
        }
    }
    ADD_FAILURE() << "no central header for " << member;
    return 0;
}

/// The offset of `member`'s deflated data: after its local header (30 bytes, name, extra field; APPNOTE 4.3.7).
std::size_t deflated_data(const std::string& bytes) {
    const std::size_t local = little_endian(bytes, central_header(bytes) + 42, 4);
    return local + 30 + little_endian(bytes, local + 26, 2) + little_endian(bytes, local + 28, 2);
}

/// The mdr::InvalidInput of reading `bytes` as a .jpk-force file, checked to name the file and the member.
std::string read_error(const std::string& bytes, const std::string& name) {
    const fs::path path = fs::temp_directory_path() / ("mdr_zip_member_" + name + ".jpk-force");
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    std::string message;
    try {
        mdr::instrument::read_curves(path);
        ADD_FAILURE() << "no exception";
    } catch (const mdr::InvalidInput& error) {
        message = error.what();
        EXPECT_NE(error.key().find(path.filename().string()), std::string::npos) << message;
        EXPECT_EQ(error.value(), member) << message;
    }
    fs::remove(path);
    return message;
}

TEST(ZipMember, TheVendorCurveReadsUndamaged) {
    const fs::path path = fs::temp_directory_path() / "mdr_zip_member_intact.jpk-force";
    std::ofstream(path, std::ios::binary | std::ios::trunc) << vendor_curve();
    EXPECT_EQ(mdr::instrument::read_curves(path).at(0).force.size(), 4000u);  // 2 segments of 2000 points (num-points)
    fs::remove(path);
}

TEST(ZipMember, CrcDifferingFromTheStatedOneIsRefused) {
    std::string bytes = vendor_curve();
    const std::size_t at = central_header(bytes) + 16;  // CRC-32 (APPNOTE 4.4.7): c6ce0ef5 as unzip -lv lists it
    ASSERT_EQ(little_endian(bytes, at, 4), 0xc6ce0ef5u);
    put_little_endian(bytes, at, 0xc6ce0ef4u);
    const std::string message = read_error(bytes, "crc");
    EXPECT_NE(message.find("is corrupted: its CRC-32 is 0xc6ce0ef5, the archive states 0xc6ce0ef4"),
              std::string::npos)
        << message;
}

TEST(ZipMember, InvalidDeflateStreamIsRefused) {
    std::string bytes = vendor_curve();
    // First byte of the stream: BFINAL = 1 and BTYPE = 11, a block type RFC 1951 §3.2.3 reserves (an error).
    bytes[deflated_data(bytes)] = static_cast<char>(0x07);
    const std::string message = read_error(bytes, "stream");
    EXPECT_NE(message.find("is corrupted: its deflate stream is invalid"), std::string::npos) << message;
}

TEST(ZipMember, MemberInflatingPastItsStatedSizeIsRefused) {
    std::string bytes = vendor_curve();
    // Uncompressed size (APPNOTE 4.4.9): 4000 -> 2000, still at least its 2403 compressed bytes less an eighth.
    put_little_endian(bytes, central_header(bytes) + 24, 2000);
    const std::string message = read_error(bytes, "longer");
    EXPECT_NE(message.find("is corrupted: inflates to more than the 2000 bytes the archive states"), std::string::npos)
        << message;
}

TEST(ZipMember, StatedSizeFarBelowTheCompressedSizeGoesThroughLibzipAndIsRefused) {
    // 4000 -> 100: the 2403 compressed bytes exceed 100 + 100 / 8 + 1024, more than deflate can need, so they are
    // not buffered whole; libzip's stream inflates one byte past the stated size and the member is refused.
    std::string bytes = vendor_curve();
    put_little_endian(bytes, central_header(bytes) + 24, 100);
    const std::string message = read_error(bytes, "stream_path");
    EXPECT_NE(message.find("is corrupted: inflates to 101 bytes, the archive states 100"), std::string::npos)
        << message;
}

TEST(ZipMember, HugeStatedSizeIsRefusedBeforeAllocating) {
    // A zip bomb's header: 4000 bytes stated as 4 GiB - 16 (0xffffffff would announce Zip64). Refused by the
    // 256 MiB bound before any allocation (one of that size would exhaust memory or fail under the sanitizers).
    std::string bytes = vendor_curve();
    put_little_endian(bytes, central_header(bytes) + 24, 0xfffffff0u);
    const std::string message = read_error(bytes, "bomb");
    EXPECT_NE(message.find("inflates to 4294967280 bytes, more than the 256 MiB per member"), std::string::npos)
        << message;
}

TEST(ZipMember, StatedSizeBeyondDeflatesRatioIsRefusedBeforeAllocating) {
    // 4000 -> 200 MiB, within the 256 MiB per member but 87 000 times its 2403 compressed bytes: deflate gives at
    // most 1032 bytes per compressed byte (RFC 1951: 258 bytes per 2-bit pair), so the header lies (a zip bomb's).
    std::string bytes = vendor_curve();
    put_little_endian(bytes, central_header(bytes) + 24, 200u << 20);
    const std::string message = read_error(bytes, "ratio");
    EXPECT_NE(message.find("states 209715200 bytes from 2403 compressed, more than deflate's 1032 bytes per "
                           "compressed byte"),
              std::string::npos)
        << message;
}

TEST(ZipMember, CompressedSizeBeyondTheArchiveIsRefusedBeforeAllocating) {
    // Compressed size (APPNOTE 4.4.8) 2403 -> 200 MiB and the stated size with it: within every per-member bound,
    // but more than the whole archive holds, so the header is corrupted; refused before 200 MiB are allocated for
    // the compressed bytes.
    std::string bytes = vendor_curve();
    put_little_endian(bytes, central_header(bytes) + 20, 200u << 20);
    put_little_endian(bytes, central_header(bytes) + 24, 200u << 20);
    const std::string message = read_error(bytes, "compressed_size");
    EXPECT_NE(message.find("states 209715200 compressed bytes, more than the archive's " +
                           std::to_string(bytes.size())),
              std::string::npos)
        << message;
}

}  // namespace
