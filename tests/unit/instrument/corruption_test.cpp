// Damaged instrument files: a byte changed anywhere gives a curve (the damage hit sample values) or
// mdr::InvalidInput naming the file, never a crash, a hang or another exception (run under the sanitizers in CI).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "mdr/error.hpp"
#include "mdr/instrument/read_curves.hpp"

namespace {

namespace fs = std::filesystem;

class DamagedFile : public ::testing::TestWithParam<std::string> {};

TEST_P(DamagedFile, EveryDamageReadsOrIsRefusedAsInvalidInput) {
    const fs::path original = fs::path(MDR_VENDOR_DATA) / GetParam();
    std::ifstream stream(original, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
    ASSERT_FALSE(bytes.empty());
    const fs::path damaged = fs::temp_directory_path() / ("mdr_instrument_damaged_" + GetParam());
    // The formats without their own calibration (AFM Workshop, NT-MDT) are given one.
    const std::string extension = original.extension().string();
    const mdr::instrument::ReadOptions options = extension == ".zip" || extension == ".csv" || extension == ".txt"
                                                     ? mdr::instrument::ReadOptions{20.0, 1e-8}
                                                     : mdr::instrument::ReadOptions{};
    // 80 positions spread over the file, each flipped to its complement, plus the file cut there.
    const std::size_t stride = std::max<std::size_t>(1, bytes.size() / 80);
    for (std::size_t at = 0; at < bytes.size(); at += stride) {
        std::string copy = bytes;
        copy[at] = static_cast<char>(~copy[at]);
        for (const std::string& variant : {copy, bytes.substr(0, at)}) {
            std::ofstream(damaged, std::ios::binary | std::ios::trunc) << variant;
            try {
                mdr::instrument::read_curves(damaged, options);
            } catch (const mdr::InvalidInput& error) {
                EXPECT_NE(std::string(error.what()).find(damaged.filename().string()), std::string::npos)
                    << "byte " << at << ": " << error.what();
            } catch (const std::exception& error) {
                ADD_FAILURE() << "byte " << at << ": not InvalidInput: " << error.what();
            }
        }
    }
    fs::remove(damaged);
}

INSTANTIATE_TEST_SUITE_P(VendorFiles, DamagedFile,
                         ::testing::Values("fmt-jpk-fd_spot3-0192.jpk-force", "fmt-igor-fd_SiN_FD_plot.ibw",
                                           "fmt-afm-workshop-fd_single_2018-08-01_13.06.09.csv",
                                           "fmt-afm-workshop-fd_mapping_16_2018-08-01_13.07.zip",
                                           "fmt-jpk-fd_2020.02.07-16.29.05.036.jpk-qi-data",
                                           "20200904_Egel4-Z1.0_00025.spm",
                                           "fmt-ntmdt-txt-fd_2015_01_17_gel4-0,1_mQ_adh_6B_Curve_DFL_Height_51.txt"));

}  // namespace
