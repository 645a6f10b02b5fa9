// A seeded mutation fuzzer over the case reader, `check` (the bounds of work) and small runs: every input must end
// in a result or in mdr::InvalidInput / std::runtime_error (one clear line on the command line), never in another
// exception, a crash, a hang, or (under the sanitizer build) a memory error or undefined behaviour.
//
//   mdr_case_fuzz CORPUS_DIR SECONDS [SEED]
//
// Mutations: byte flips, deleted and duplicated spans, numbers replaced by edge values (0, -1, 5e-324, 1e308,
// nan, inf, 2^53 + 1, ...), keys and whole lines taken from other corpus files. An input that fails (or takes
// longer than 10 s: a hang) is written to `fuzz-failure.toml` in the working directory and the program exits with
// status 1; it then belongs in tests/cli/test_robustness.py and in the corpus.

#include <atomic>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <random>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"

namespace {

namespace fs = std::filesystem;

const std::vector<std::string> edge_values = {
    "0",     "-1",   "1",     "5e-324", "1e-300", "1e308",  "-1e308", "nan", "inf",  "-inf",
    "9007199254740993", "9223372036854775807", "-0.0", "1e-15", "1e15", "0.5", "[]", "\"\"", "{}", "[[0, 0]]"};

std::string read_file(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(file), {}};
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

class Mutator {
public:
    Mutator(std::vector<std::string> corpus, unsigned seed) : corpus_(std::move(corpus)), random_(seed) {
        for (const auto& text : corpus_) {
            for (auto& line : lines_of(text)) all_lines_.push_back(std::move(line));
        }
    }

    std::string next() {
        std::string text = corpus_[pick(corpus_.size())];
        const std::size_t mutations = 1 + pick(4);
        for (std::size_t m = 0; m < mutations; ++m) mutate(text);
        return text;
    }

private:
    std::size_t pick(std::size_t count) { return std::uniform_int_distribution<std::size_t>(0, count - 1)(random_); }

    void mutate(std::string& text) {
        if (text.empty()) text.push_back('x');
        switch (pick(6)) {
            case 0:  // replace a number by an edge value
            {
                std::vector<std::pair<std::size_t, std::size_t>> spans;  // numbers: a digit, then [0-9_.eE+-]
                for (std::size_t i = 0; i < text.size(); ++i) {
                    if (!std::isdigit(static_cast<unsigned char>(text[i]))) continue;
                    const std::size_t begin = i > 0 && (text[i - 1] == '-' || text[i - 1] == '+') ? i - 1 : i;
                    while (i < text.size() && (std::isdigit(static_cast<unsigned char>(text[i])) ||
                                               std::string_view("_.eE+-").find(text[i]) != std::string_view::npos)) {
                        ++i;
                    }
                    spans.emplace_back(begin, i - begin);
                }
                if (spans.empty()) break;
                const auto [at, length] = spans[pick(spans.size())];
                text = text.substr(0, at) + edge_values[pick(edge_values.size())] + text.substr(at + length);
                break;
            }
            case 1:  // flip a byte
                text[pick(text.size())] = static_cast<char>(pick(256));
                break;
            case 2:  // delete a span
            {
                const std::size_t at = pick(text.size());
                text = text.substr(0, at) + text.substr(std::min(text.size(), at + 1 + pick(16)));
                break;
            }
            case 3:  // duplicate a span
            {
                const std::size_t at = pick(text.size());
                text = text.substr(0, at) + text.substr(at, 1 + pick(16)) + text.substr(at);
                break;
            }
            case 4:  // insert a line of another corpus file
            {
                auto lines = lines_of(text);
                lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(pick(lines.size() + 1)),
                             all_lines_[pick(all_lines_.size())]);
                text.clear();
                for (const auto& line : lines) text += line + "\n";
                break;
            }
            default:  // drop a line
            {
                auto lines = lines_of(text);
                if (lines.empty()) break;
                lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(pick(lines.size())));
                text.clear();
                for (const auto& line : lines) text += line + "\n";
                break;
            }
        }
    }

    std::vector<std::string> corpus_;
    std::vector<std::string> all_lines_;
    std::mt19937 random_;
};

// Parses and checks the case; then runs it on at most 100 elements when that stays below 2e6 element-steps, for
// at most a second.
void exercise(const std::string& text) {
    auto contact_case = mdr::io::parse_case(text, "fuzz");
    mdr::io::describe(contact_case);
    mdr::drivers::resolve_numerics(contact_case);
    if (!contact_case.numerics.elements || *contact_case.numerics.elements > 100) contact_case.numerics.elements = 100;
    contact_case.numerics.max_element_steps = 2e6;
    contact_case.numerics.max_memory = 2e8;
    try {
        mdr::drivers::resolve_numerics(contact_case);
    } catch (const mdr::InvalidInput&) {
        return;  // too large to run here; the check above is what counted
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(1);
    mdr::drivers::run_case(contact_case, [&](double) {
        if (std::chrono::steady_clock::now() > deadline) throw mdr::Interrupted();
    });
}

void write_failure(const std::string& text) { std::ofstream("fuzz-failure.toml", std::ios::binary) << text; }

// Watches the input under test: one that takes longer than `limit` is a hang; it is written out and the process
// ends with status 1 (a hung computation cannot be stopped from outside).
class Watchdog {
public:
    explicit Watchdog(std::chrono::seconds limit) : limit_(limit), thread_([this] { watch(); }) {}
    ~Watchdog() {
        done_ = true;
        thread_.join();
    }
    void start(const std::string& text) {
        const std::lock_guard lock(mutex_);
        text_ = text;
        started_ = std::chrono::steady_clock::now();
    }

private:
    void watch() {
        while (!done_) {
            std::this_thread::sleep_for(std::chrono::milliseconds(200));
            const std::lock_guard lock(mutex_);
            if (std::chrono::steady_clock::now() - started_ > limit_) {
                write_failure(text_);
                std::fprintf(stderr, "mdr_case_fuzz: an input ran for more than %lld s (a hang); written to "
                                     "fuzz-failure.toml\n", static_cast<long long>(limit_.count()));
                std::_Exit(1);
            }
        }
    }

    std::chrono::seconds limit_;
    std::mutex mutex_;
    std::string text_;
    std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
    std::atomic<bool> done_{false};
    std::thread thread_;
};

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: mdr_case_fuzz CORPUS_DIR SECONDS [SEED]\n");
        return 2;
    }
    std::vector<std::string> corpus;
    for (const auto& entry : fs::directory_iterator(argv[1])) {
        if (entry.path().extension() == ".toml") corpus.push_back(read_file(entry.path()));
    }
    if (corpus.empty()) {
        std::fprintf(stderr, "mdr_case_fuzz: no .toml files in %s\n", argv[1]);
        return 2;
    }
    const double seconds = std::stod(argv[2]);
    const unsigned seed = argc > 3 ? static_cast<unsigned>(std::stoul(argv[3])) : 1u;
    Mutator mutator(corpus, seed);
    Watchdog watchdog(std::chrono::seconds(10));
    const auto start = std::chrono::steady_clock::now();
    std::size_t inputs = 0, accepted = 0;
    // The corpus itself first, then mutations until the time is up.
    for (std::size_t i = 0;; ++i) {
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (i >= corpus.size() && elapsed > seconds) break;
        const std::string text = i < corpus.size() ? corpus[i] : mutator.next();
        ++inputs;
        watchdog.start(text);
        try {
            exercise(text);
            ++accepted;
        } catch (const mdr::InvalidInput&) {
        } catch (const mdr::Interrupted&) {
        } catch (const std::runtime_error&) {
        } catch (const std::exception& error) {
            write_failure(text);
            std::fprintf(stderr, "mdr_case_fuzz: input %zu (seed %u) threw %s: %s; written to fuzz-failure.toml\n",
                         inputs, seed, typeid(error).name(), error.what());
            return 1;
        }
    }
    std::printf("mdr_case_fuzz: %zu inputs (%zu ran or checked cleanly) in %.0f s, seed %u: no failure\n", inputs,
                accepted, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), seed);
    return 0;
}
