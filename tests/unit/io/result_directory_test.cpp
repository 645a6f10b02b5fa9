// ResultDirectory from C++: the same refusals as the command line, an atomic write with a manifest, nothing left
// behind on failure or interruption. Every scenario lives in a fresh scratch directory.

#include "mdr/io/result_directory.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <random>
#include <set>
#include <stdexcept>

#include "mdr/error.hpp"

namespace mdr::io {
namespace {
namespace fs = std::filesystem;

class ResultDirectoryTest : public ::testing::Test {
protected:
    void SetUp() override {
        scratch_ = fs::temp_directory_path() / ("mdr-result-directory-" + std::to_string(getpid()) + "-" +
                                                std::to_string(std::random_device{}()));
        fs::create_directories(scratch_);
        write_text(scratch_ / "notes.txt", "the user's notes\n");
    }
    void TearDown() override { fs::remove_all(scratch_); }

    static void write_text(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }
    static std::string read_text(const fs::path& path) {
        std::ifstream file(path);
        return {std::istreambuf_iterator<char>(file), {}};
    }
    std::set<std::string> entries(const fs::path& directory) const {
        std::set<std::string> names;
        for (const auto& entry : fs::directory_iterator(directory)) names.insert(entry.path().filename().string());
        return names;
    }
    static void write_result(const fs::path& directory) { write_text(directory / "summary.json", "{}\n"); }

    fs::path scratch_;
};

void expect_refused(const fs::path& directory, const std::string& rule_fragment) {
    try {
        ResultDirectory(directory, "--out");
        ADD_FAILURE() << directory << " was accepted";
    } catch (const InvalidInput& error) {
        EXPECT_EQ(error.key(), "--out");
        EXPECT_NE(error.rule().find(rule_fragment), std::string::npos) << error.what();
    }
}

TEST_F(ResultDirectoryTest, WritesANewDirectoryWithItsManifest) {
    const ResultDirectory directory(scratch_ / "res", "--out");
    directory.write(write_result);
    EXPECT_EQ(entries(scratch_ / "res"), (std::set<std::string>{".mdr-result", "summary.json"}));
    EXPECT_NE(read_text(scratch_ / "res" / ".mdr-result").find("\nsummary.json\n"), std::string::npos);
    EXPECT_EQ(entries(scratch_), (std::set<std::string>{"notes.txt", "res"}));
}

TEST_F(ResultDirectoryTest, ReplacesOnlyWhatItWrote) {
    ResultDirectory(scratch_ / "res", "--out").write(write_result);
    ResultDirectory(scratch_ / "res/", "--out").write([](const fs::path& d) { write_text(d / "other.csv", "1\n"); });
    EXPECT_EQ(entries(scratch_ / "res"), (std::set<std::string>{".mdr-result", "other.csv"}));
    write_text(scratch_ / "res" / "mine.txt", "x");
    expect_refused(scratch_ / "res", "holds mine.txt, which mdr did not write");
}

TEST_F(ResultDirectoryTest, RefusesTheUsersFilesAndDirectories) {
    expect_refused(scratch_ / "notes.txt", "existing file");
    expect_refused(scratch_ / "notes.txt" / "below", "not a directory");
    expect_refused(scratch_, "did not write");
    fs::create_directory(scratch_ / "link-target");
    fs::create_directory_symlink(scratch_ / "link-target", scratch_ / "link");
    expect_refused(scratch_ / "link", "symbolic link");
    expect_refused(fs::current_path(), "working directory");
    expect_refused(fs::current_path().parent_path(), "working directory");
    expect_refused("", "must name a directory");
    try {
        ResultDirectory(scratch_, "--out", {scratch_ / "notes.txt"});
        ADD_FAILURE() << "the input's directory was accepted";
    } catch (const InvalidInput& error) {
        EXPECT_NE(error.rule().find("input file"), std::string::npos) << error.what();
    }
    EXPECT_EQ(read_text(scratch_ / "notes.txt"), "the user's notes\n");
}

TEST_F(ResultDirectoryTest, FailuresAndInterruptionsLeaveNothingBehind) {
    ResultDirectory(scratch_ / "res", "--out").write(write_result);
    const auto before = read_text(scratch_ / "res" / "summary.json");
    const ResultDirectory directory(scratch_ / "res", "--out");
    EXPECT_THROW(directory.write([](const fs::path& d) {
        write_text(d / "history.csv", "t\n");
        throw std::runtime_error("disk full");
    }),
                 std::runtime_error);
    EXPECT_THROW(directory.write(write_result, [] { return true; }), Interrupted);
    EXPECT_EQ(entries(scratch_), (std::set<std::string>{"notes.txt", "res"}));
    EXPECT_EQ(read_text(scratch_ / "res" / "summary.json"), before);
}

TEST_F(ResultDirectoryTest, ChecksAgainBeforeReplacing) {
    ResultDirectory(scratch_ / "res", "--out").write(write_result);
    const ResultDirectory directory(scratch_ / "res", "--out");
    write_text(scratch_ / "res" / "added-meanwhile.txt", "x");
    EXPECT_THROW(directory.write(write_result), InvalidInput);
    EXPECT_EQ(read_text(scratch_ / "res" / "added-meanwhile.txt"), "x");
    EXPECT_EQ(entries(scratch_), (std::set<std::string>{"notes.txt", "res"}));
}

// Rule: mdr's mark is a regular file it wrote; a folder or a link named .mdr-result is the user's (issue 23).
TEST_F(ResultDirectoryTest, RefusesAManifestThatIsNotARegularFile) {
    fs::create_directories(scratch_ / "res" / ".mdr-result");
    write_text(scratch_ / "res" / ".mdr-result" / "thesis.tex", "chapter 1\n");
    expect_refused(scratch_ / "res", "holds .mdr-result, which is not a regular file");
    EXPECT_EQ(read_text(scratch_ / "res" / ".mdr-result" / "thesis.tex"), "chapter 1\n");

    fs::create_directories(scratch_ / "linked");
    write_text(scratch_ / "linked" / "notes.txt", "mine\n");
    write_text(scratch_ / "list", "# a list\nnotes.txt\n");
    fs::create_symlink(scratch_ / "list", scratch_ / "linked" / ".mdr-result");
    expect_refused(scratch_ / "linked", "holds .mdr-result, which is not a regular file");
    EXPECT_EQ(read_text(scratch_ / "linked" / "notes.txt"), "mine\n");
}

// A folder mdr wrote (one per candidate model of a fit) is listed file by file and may be replaced; a file or a
// folder of the user's inside it may not.
TEST_F(ResultDirectoryTest, ReplacesTheFoldersItWroteButNotWhatWasAddedToThem) {
    const auto write_folders = [](const fs::path& d) {
        write_text(d / "models.csv", "rank\n");
        fs::create_directory(d / "prony2");
        write_text(d / "prony2" / "fit.json", "{}\n");
    };
    ResultDirectory(scratch_ / "res", "--out").write(write_folders);
    const std::string manifest = read_text(scratch_ / "res" / ".mdr-result");
    EXPECT_EQ(manifest.substr(manifest.find('\n')), "\nmodels.csv\nprony2/fit.json\n");
    ResultDirectory(scratch_ / "res", "--out").write(write_folders);
    write_text(scratch_ / "res" / "prony2" / "mine.txt", "x");
    expect_refused(scratch_ / "res", "holds prony2/mine.txt, which mdr did not write");
    fs::remove(scratch_ / "res" / "prony2" / "mine.txt");
    fs::create_directory(scratch_ / "res" / "prony2" / "figures");
    expect_refused(scratch_ / "res", "holds prony2/figures, which mdr did not write");
}

pid_t dead_pid() {
    const pid_t child = fork();
    if (child == 0) _exit(0);
    waitpid(child, nullptr, 0);
    return child;
}

// A killed run's temporary directory: only the regular files its manifest lists go, then the folders left empty;
// a file of the user's stays, and so does the directory. A listed path outside it is never followed.
TEST_F(ResultDirectoryTest, CleansOnlyWhatAKilledRunListed) {
    const fs::path stale = scratch_ / (".res.mdr-partial-" + std::to_string(dead_pid()) + "-1");
    fs::create_directories(stale / "prony2");
    write_text(stale / ".mdr-result", "# mdr\nhistory.csv\nprony2/fit.json\n../notes.txt\n");
    write_text(stale / "history.csv", "t\n");
    write_text(stale / "prony2" / "fit.json", "{}\n");
    write_text(stale / "precious.txt", "x\n");
    const fs::path clean = scratch_ / (".res.mdr-old-" + std::to_string(dead_pid()) + "-1");
    fs::create_directories(clean / "elastic");
    write_text(clean / ".mdr-result", "# mdr\nelastic/fit.json\n");
    write_text(clean / "elastic" / "fit.json", "{}\n");
    ResultDirectory(scratch_ / "res", "--out").write(write_result);
    EXPECT_EQ(entries(stale), (std::set<std::string>{"precious.txt"}));
    EXPECT_EQ(read_text(stale / "precious.txt"), "x\n");
    EXPECT_EQ(read_text(scratch_ / "notes.txt"), "the user's notes\n");
    EXPECT_FALSE(fs::exists(clean));
}

}  // namespace
}  // namespace mdr::io
