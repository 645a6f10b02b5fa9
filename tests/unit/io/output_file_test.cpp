// The files mdr writes (io::OutputFile): a write error, the last block's included, is an exception naming the file,
// never a crash (fmt 9's output_file threw again from its destructor after a failed flush: std::terminate).

#include "mdr/io/output_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>

namespace mdr::io {
namespace {

// Runs `body` and returns the message of the std::system_error it throws ("" when it throws none).
template <typename Body>
std::string system_error_of(Body&& body) {
    try {
        body();
    } catch (const std::system_error& error) {
        return error.what();
    }
    return "";
}

TEST(OutputFile, WritesWhatItPrints) {
    const auto path = std::filesystem::temp_directory_path() / "mdr_output_file_test.csv";
    {
        OutputFile file(path);
        file.print("t,F\n");
        for (int i = 0; i < 20000; ++i) file.print("{},{}\n", i, 0.5 * i);  // several blocks
        file.close();
    }
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    std::string expected = "t,F\n";
    for (int i = 0; i < 20000; ++i) expected += std::to_string(i) + "," + fmt::format("{}", 0.5 * i) + "\n";
    EXPECT_EQ(text.str(), expected);
    std::filesystem::remove(path);
}

TEST(OutputFile, AFullDiskAtTheLastBlockIsAnErrorNamingTheFile) {
    // Less than a block: nothing reaches the disk before close.
    const std::string message = system_error_of([] {
        OutputFile file("/dev/full");
        file.print("{}\n", "a short table");
        file.close();
    });
    EXPECT_EQ(message.rfind("cannot write /dev/full", 0), 0u) << message;
}

TEST(OutputFile, AFullDiskWhilePrintingIsAnErrorAndTheFileClosesQuietly) {
    const std::string message = system_error_of([] {
        OutputFile file("/dev/full");
        for (int i = 0; i < 100000; ++i) file.print("{},{}\n", i, i);
        file.close();
    });
    EXPECT_EQ(message.rfind("cannot write /dev/full", 0), 0u) << message;
    // Destroyed without close after a failed write: no second exception.
    EXPECT_NO_THROW({
        OutputFile file("/dev/full");
        EXPECT_THROW(
            for (int i = 0; i < 100000; ++i) file.print("{},{}\n", i, i), std::system_error);
    });
}

TEST(OutputFile, AFileThatCannotBeOpenedIsNamed) {
    const std::string message = system_error_of([] { OutputFile file("/nonexistent-folder/x.csv"); });
    EXPECT_EQ(message.rfind("cannot write /nonexistent-folder/x.csv", 0), 0u) << message;
}


}  // namespace
}  // namespace mdr::io
