// A seeded mutation fuzzer over the case reader, `check` (the bounds of work) and small runs: every input must end
// in a result or in mdr::InvalidInput / std::runtime_error (one clear line on the command line), never in another
// exception, a crash, a hang, or (under the sanitizer build) a memory error or undefined behaviour; a run that ends
// must have a finite history and summary.
//
//   mdr_case_fuzz CORPUS_DIR SECONDS [SEED]
//
// Mutations (mutator.hpp, shared with fit_fuzz.cpp): byte flips, deleted and duplicated spans, numbers replaced by
// edge values (0, -1, 5e-324, 1e308, nan, inf, 2^53 + 1, ...), keys and whole lines taken from other corpus files.
// An input that fails (or takes longer than 10 s: a hang) is written to `fuzz-failure.toml` in the working
// directory and the program exits with status 1; it then belongs in tests/cli/test_robustness.py and in the corpus.

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <typeinfo>
#include <utility>
#include <variant>
#include <vector>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"
#include "mdr/io/summary.hpp"
#include "mutator.hpp"

namespace {

namespace fs = std::filesystem;
using mdr::fuzz::read_file;

// A corpus file with one to four mutations.
std::string next_input(const std::vector<std::string>& corpus, mdr::fuzz::Mutator& mutator) {
    std::string text = corpus[mutator.pick(corpus.size())];
    const std::size_t mutations = 1 + mutator.pick(4);
    for (std::size_t m = 0; m < mutations; ++m) mutator.mutate(text);
    return text;
}

// A run that ends is reported: its history columns and every number of its summary (summary.json) must be finite
// (docs/case-format.md: no run ever reports NaN or infinity). Throws NonFiniteOutput naming the first that is not.
struct NonFiniteOutput : std::logic_error {
    using std::logic_error::logic_error;
};

void require_finite_output(const mdr::drivers::ContactCase& contact_case,
                           const mdr::drivers::IndentationResult& result) {
    const std::pair<const char*, const std::vector<double>*> columns[] = {
        {"t", &result.time}, {"d", &result.depth}, {"F", &result.force}, {"a", &result.radius},
        {"v", &result.velocity}, {"u", &result.tangential_displacement}, {"Fx", &result.tangential_force},
        {"c", &result.stick_radius}, {"z", &result.base}, {"shore", &result.shore},
        {"v_t", &result.tangential_velocity}, {"omega", &result.spin}};
    for (const auto& [name, column] : columns) {
        for (const double value : *column) {
            if (!std::isfinite(value)) throw NonFiniteOutput(std::string("history column ") + name + " not finite");
        }
    }
    for (const auto& entry : mdr::io::summarize(contact_case, result, 0.0)) {
        std::vector<double> numbers;
        if (const auto* number = std::get_if<double>(&entry.value.value)) numbers.push_back(*number);
        if (const auto* list = std::get_if<mdr::Document::List>(&entry.value.value)) {
            for (const auto& item : *list) numbers.push_back(std::get<double>(item.value));
        }
        for (const double value : numbers) {
            if (!std::isfinite(value)) throw NonFiniteOutput("summary." + entry.key + " = " + std::to_string(value));
        }
    }
}

// Parses and checks the case; then runs it on at most 100 elements (on a [layer] at most 30 cells, which count m^2 a
// step, and 24 Gauss nodes, which count 4 n^3/96 a step) when that stays below 2e6 element-steps, for at most a
// second.
void exercise(const std::string& text) {
    auto contact_case = mdr::io::parse_case(text, "fuzz");
    mdr::io::describe(contact_case);
    mdr::drivers::resolve_numerics(contact_case);
    if (!contact_case.numerics.elements || *contact_case.numerics.elements > 100) contact_case.numerics.elements = 100;
    auto& cells = contact_case.numerics.layer_cells;
    if (contact_case.layer && (!cells || *cells > 30)) cells = 30;
    if (contact_case.layer && *contact_case.numerics.elements > 24) contact_case.numerics.elements = 24;
    contact_case.numerics.max_element_steps = 2e6;
    contact_case.numerics.max_memory = 2e8;
    try {
        mdr::drivers::resolve_numerics(contact_case);
    } catch (const mdr::InvalidInput&) {
        return;  // too large to run here; the check above is what counted
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(1);
    const auto result = mdr::drivers::run_case(contact_case, [&](double) {
        if (std::chrono::steady_clock::now() > deadline) throw mdr::Interrupted();
    });
    require_finite_output(contact_case, result);
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
    std::vector<std::string> line_pool;
    for (const auto& text : corpus) {
        for (auto& line : mdr::fuzz::lines_of(text)) line_pool.push_back(std::move(line));
    }
    mdr::fuzz::Mutator mutator(std::move(line_pool), seed);
    Watchdog watchdog(std::chrono::seconds(10));
    const auto start = std::chrono::steady_clock::now();
    std::size_t inputs = 0, accepted = 0;
    // The corpus itself first, then mutations until the time is up.
    for (std::size_t i = 0;; ++i) {
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (i >= corpus.size() && elapsed > seconds) break;
        const std::string text = i < corpus.size() ? corpus[i] : next_input(corpus, mutator);
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
