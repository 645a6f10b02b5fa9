// A seeded mutation fuzzer of `mdr fit`: it mutates fit cases and the data files they read (curve and rebound CSV
// files, text instrument files; binary instrument files, such as a JPK zip, an Igor wave or a NanoScope file, by
// the byte and field mutations of Mutator::mutate_binary, and a zip's members unpacked, mutated and packed again)
// and runs each mutant as a user would, `mdr fit case.toml --out out` in a fresh directory, as a child process with
// a wall-clock and a memory limit. Each mutant must satisfy every oracle (docs/case-format.md, "Fitting" and
// "Bad input"):
//
//   crash         no signal ends mdr
//   hang          mdr ends within the time limit (--timeout, 10 s of processor time; killed after 3 times as
//                 long on the wall clock)
//   memory        no allocation failure under the address-space limit (--memory-limit, 2048 MiB), and a peak
//                 resident memory below half of it
//   exit_code     the exit code is 0, 1 or 2
//   exit1_result  exit 1 (not converged) has written its result (out/fit.json or out/ranking.json)
//   exit2_wrote   exit 2 (bad input) has written nothing: the directory holds what it held before
//   one_line      exit 2 prints exactly one line on stderr, `mdr: error: ...`
//   non_finite    exit 0 writes no NaN, infinity or null (but where the docs allow them: for undetermined
//                 parameters, a noise-free fit's residual_to_noise, a candidate's better_special_case and
//                 refitted_from when none)
//   unreadable    a written result (exit 0 or 1) is readable as its format: JSON, TOML, CSV with as many
//                 fields in every row as in its header
//   raw_bytes     stdout and stderr hold no control byte (but line ends), DEL or invalid UTF-8
//   solver_log    no log line of the solver (glog: "W1127 10:00:00 ... trust_region_minimizer.cc:NN] ...")
//   uncaught      no text of an escaped C++ exception or sanitizer report ("terminate called", "std::", ...)
//   user_files    the case, its data and a note of the user's beside them are unchanged; an existing --out
//                 directory that mdr did not write (with the user's file in it) is left alone (exit 2)
//   leftovers     no temporary directory and no process of mdr's is left behind
//
//   mdr_fit_fuzz CORPUS_DIR SECONDS [SEED] [--mutants N] [--mdr PATH] [--timeout S] [--memory-limit MIB]
//                [--keep K]
//
// CORPUS_DIR holds one folder per seed: `case.toml` and the files it reads. The seeds run first, unmutated; then
// mutants until SECONDS have passed or N mutants have run. The summary line counts the mutants that failed each
// oracle. Every failure is a line of `fit-fuzz-failures/failures.log` in the working directory, and the first K
// (default 3) failing mutants of each oracle are kept in `fit-fuzz-failures/ORACLE-N/` (the mutated case and
// data, mdr's stdout and stderr, and `failure.txt` saying what failed); the program exits with status 1 when any
// mutant failed. --mdr defaults to `mdr` beside this program.

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "child_process.hpp"
#include "mutator.hpp"
#include "output_checks.hpp"
#include "zip_members.hpp"

namespace {

namespace fs = std::filesystem;
using mdr::fuzz::read_file;

// The oracles in the order of the summary line.
const std::vector<std::string> oracle_names = {
    "crash",      "hang",       "memory",    "exit_code",  "exit1_result", "exit2_wrote", "one_line",
    "non_finite", "unreadable", "raw_bytes", "solver_log", "uncaught",     "user_files",  "leftovers"};

// A seed or a mutant: file name -> content; `case.toml` is the case.
using Files = std::map<std::string, std::string>;

struct Options {
    fs::path corpus;
    double seconds = 0.0;
    unsigned seed = 1;
    std::size_t mutants = static_cast<std::size_t>(-1);
    fs::path mdr;
    double timeout = 10.0;
    std::size_t memory_limit_mib = 2048;
    std::size_t keep = 3;
};

// The failed oracles of one mutant, each with what showed it.
using Failures = std::vector<std::pair<std::string, std::string>>;

// How one mutant ran, and what it failed.
struct MutantReport {
    Failures failures;
    mdr::fuzz::ChildOutcome outcome;
};

// A seed: its folder's name and its files.
struct Seed {
    std::string name;
    Files files;
};

std::vector<Seed> read_corpus(const fs::path& corpus) {
    std::vector<fs::path> folders;
    for (const auto& entry : fs::directory_iterator(corpus)) {
        if (entry.is_directory() && fs::exists(entry.path() / "case.toml")) folders.push_back(entry.path());
    }
    std::sort(folders.begin(), folders.end());  // the same order, and so the same mutants, on every machine
    std::vector<Seed> seeds;
    for (const auto& folder : folders) {
        Files files;
        for (const auto& entry : fs::directory_iterator(folder)) {
            if (entry.is_regular_file()) files[entry.path().filename().string()] = read_file(entry.path());
        }
        seeds.push_back({folder.filename().string(), std::move(files)});
    }
    return seeds;
}

// Whether a file is binary (an instrument file's bytes, not text): it holds a NUL byte.
bool is_binary(const std::string& text) { return text.find('\0') != std::string::npos; }

// One mutation of a member of the zip archive `archive` (a JPK file), packed again with sizes and CRC-32 that fit
// it (deflated, or stored a quarter of the time), so that the mutation passes the zip's checks and reaches the
// reader behind them: a number of a text member (header properties) replaced, or a binary member's bytes mutated.
// False when `archive` cannot be unpacked (an earlier mutation broke it).
bool mutate_zip_member(std::string& archive, mdr::fuzz::Mutator& mutator) {
    auto members = mdr::fuzz::unzip(archive);
    if (members.empty()) return false;
    std::string& bytes = members[mutator.pick(members.size())].bytes;
    if (is_binary(bytes)) {
        mutator.mutate_binary(bytes);
    } else if (mutator.pick(4) == 0) {
        mutator.mutate_structure(bytes);
    } else {
        mutator.replace_value(bytes, mutator.pick(2) == 0 ? mdr::fuzz::edge_values : mdr::fuzz::data_edge_values);
    }
    archive = mdr::fuzz::zip(members, mutator.pick(4) == 0);
    return true;
}

// A seed with one to four mutations (one, half of the time) of its case, of one of its data files, or of both.
// A zip archive gets a mutation of one of its members half of the time; a binary file otherwise gets byte and field
// mutations three times in four, else a number of its text (a header's) replaced.
Seed mutate(const std::vector<Seed>& seeds, mdr::fuzz::Mutator& mutator) {
    Seed mutant = seeds[mutator.pick(seeds.size())];
    Files& files = mutant.files;
    std::vector<std::string> data;
    for (const auto& [name, text] : files) {
        if (name != "case.toml") data.push_back(name);
    }
    const std::size_t target = data.empty() ? 0 : mutator.pick(3);  // 0: the case, 1: a data file, 2: both
    const std::size_t most = mutator.pick(2) == 0 ? 1 : 4;          // a single mutation half of the time
    std::vector<std::string> mutated;
    if (target != 1) mutated.push_back("case.toml");
    if (target != 0) mutated.push_back(data[mutator.pick(data.size())]);
    for (const auto& name : mutated) {
        const std::size_t mutations = 1 + mutator.pick(most);
        const bool binary = is_binary(files[name]);
        for (std::size_t m = 0; m < mutations; ++m) {  // a number half of the time: more mutants reach the fit
            if (binary && files[name].starts_with("PK\3\4") && mutator.pick(2) == 0 &&
                mutate_zip_member(files[name], mutator)) {
                continue;
            }
            if (binary && mutator.pick(4) != 0) {
                mutator.mutate_binary(files[name]);
                continue;
            }
            switch (binary ? 2 : mutator.pick(4)) {
                case 0: mutator.mutate(files[name]); break;
                case 1: mutator.mutate_structure(files[name]); break;
                default:
                    mutator.replace_value(files[name], name == "case.toml" || mutator.pick(2) == 0
                                                           ? mdr::fuzz::edge_values
                                                           : mdr::fuzz::data_edge_values);
                    break;
            }
        }
    }
    return mutant;
}

void write_files(const fs::path& directory, const Files& files) {
    fs::create_directories(directory);
    for (const auto& [name, text] : files) std::ofstream(directory / name, std::ios::binary) << text;
}

// Every regular file below `directory`, by relative path, with its content.
Files snapshot(const fs::path& directory) {
    Files files;
    for (const auto& entry : fs::recursive_directory_iterator(directory)) {
        if (entry.is_regular_file()) files[fs::relative(entry.path(), directory).string()] = read_file(entry.path());
    }
    return files;
}

std::set<std::string> entries(const fs::path& directory) {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(directory)) names.insert(entry.path().filename().string());
    return names;
}

// Runs one mutant in `work` (emptied first) and returns the oracles it failed. With `existing_out` the --out
// directory exists beforehand, holding a file of the user's and no manifest: mdr must refuse it.
MutantReport run_mutant(const Files& files, const fs::path& work, bool existing_out, const Options& options) {
    fs::remove_all(work);
    const fs::path case_directory = work / "case";
    write_files(case_directory, files);
    std::ofstream(case_directory / "notes.txt") << "the user's notes beside the case\n";
    const fs::path out = case_directory / "out";
    if (existing_out) {
        fs::create_directories(out);
        std::ofstream(out / "user.txt") << "the user's file in a directory mdr did not write\n";
    }
    const Files before = snapshot(case_directory);
    const auto entries_before = entries(case_directory);
    const auto outcome =
        mdr::fuzz::run_child({options.mdr.string(), "fit", "case.toml", "--out", "out"}, case_directory,
                             work / "stdout", work / "stderr", options.timeout, options.memory_limit_mib << 20);
    const std::string out_text = read_file(work / "stdout");
    const std::string err_text = read_file(work / "stderr");
    const int code = outcome.exit_code;

    Failures failures;
    const auto fail = [&](const std::string& oracle, const std::string& what) { failures.emplace_back(oracle, what); };
    if (outcome.timed_out) {
        fail("hang", "ran " + std::to_string(outcome.cpu_seconds) + " s of processor time and " +
                         std::to_string(outcome.wall_seconds) + " s on the wall clock (limit " +
                         std::to_string(options.timeout) + " s)");
    } else if (outcome.signal != 0) {
        fail("crash", "signal " + std::to_string(outcome.signal));
    }
    if (err_text.find("bad_alloc") != std::string::npos || err_text.find("Cannot allocate") != std::string::npos ||
        err_text.find("out of memory") != std::string::npos) {
        fail("memory", "an allocation failed (peak " + std::to_string(outcome.max_resident_kib / 1024) + " MiB)");
    } else if (options.memory_limit_mib > 0 &&
               static_cast<std::size_t>(outcome.max_resident_kib) > options.memory_limit_mib * 1024 / 2) {
        fail("memory", "a peak of " + std::to_string(outcome.max_resident_kib / 1024) + " MiB resident");
    }
    if (!outcome.timed_out && outcome.signal == 0 && code != 0 && code != 1 && code != 2) {
        fail("exit_code", "exit code " + std::to_string(code));
    }
    const bool result_written = fs::exists(out / "fit.json") || fs::exists(out / "ranking.json");
    if (code == 1 && !result_written) fail("exit1_result", "exit 1 without a result: " + err_text);
    const Files after = snapshot(case_directory);
    if (code == 2 && after != before) fail("exit2_wrote", "exit 2, and the directory changed");
    if (code == 2 && (std::count(err_text.begin(), err_text.end(), '\n') != 1 || !err_text.ends_with("\n") ||
                      !err_text.starts_with("mdr: error: "))) {
        fail("one_line", "exit 2 with stderr: " + err_text);
    }
    if (code == 0 && !result_written) fail("non_finite", "exit 0 without a result");
    if ((code == 0 || code == 1) && result_written) {
        using mdr::fuzz::ResultCheck, mdr::fuzz::ResultScan;
        if (const auto where = ResultScan::scan(out, ResultCheck::format); !where.empty()) fail("unreadable", where);
        if (const auto where = ResultScan::scan(out, ResultCheck::values); code == 0 && !where.empty()) {
            fail("non_finite", where);
        }
    }
    for (const auto& [stream, text] : {std::pair{"stderr", &err_text}, std::pair{"stdout", &out_text}}) {
        const std::string name = stream;
        if (const auto where = mdr::fuzz::raw_byte(*text); !where.empty()) {
            fail("raw_bytes", name + ": " + where + " of: " + *text);
        }
        if (const auto line = mdr::fuzz::solver_log_line(*text); !line.empty()) fail("solver_log", name + ": " + line);
        if (const auto what = mdr::fuzz::uncaught_exception_text(*text); !what.empty()) {
            fail("uncaught", name + ": " + what);
        }
    }
    for (const auto& [name, content] : before) {
        const auto found = after.find(name);
        if (found == after.end() || found->second != content) fail("user_files", name + " was changed or removed");
    }
    if (existing_out && code != 2) fail("user_files", "an --out directory mdr did not write was not refused");
    std::string leftovers = outcome.left_processes ? "a process of mdr's still ran" : "";
    for (const auto& name : entries(case_directory)) {
        if (!entries_before.contains(name) && name != "out") leftovers += " " + name;
    }
    if (!leftovers.empty()) fail("leftovers", leftovers);
    return {failures, outcome};
}

// Keeps a failing mutant in fit-fuzz-failures/ORACLE-N/.
void keep_failure(const Seed& input, const fs::path& work, const std::string& oracle, std::size_t number,
                  const std::string& origin, const Failures& failures) {
    const fs::path folder = fs::path("fit-fuzz-failures") / (oracle + "-" + std::to_string(number));
    fs::remove_all(folder);
    write_files(folder, input.files);
    for (const char* stream : {"stdout", "stderr"}) fs::copy_file(work / stream, folder / stream);
    std::ofstream note(folder / "failure.txt");
    note << origin << "\n";
    for (const auto& [name, what] : failures) note << name << ": " << what << "\n";
}

// `text` on one line as printable ASCII: other bytes as \xNN, at most 300 characters.
std::string printable(const std::string& text) {
    std::string line;
    for (const char c : text.substr(0, 300)) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte >= 0x20 && byte < 0x7f) {
            line += c;
        } else {
            static constexpr char digits[] = "0123456789abcdef";
            line += "\\x";
            line += digits[byte >> 4];
            line += digits[byte & 15];
        }
    }
    return line;
}

std::string summary_line(const std::map<std::string, std::size_t>& counts) {
    std::string line;
    for (const auto& name : oracle_names) {
        const auto found = counts.find(name);
        line += " " + name + "=" + std::to_string(found == counts.end() ? 0 : found->second);
    }
    return line;
}

bool parse_options(int argc, char** argv, Options& options) {
    std::vector<std::string> positional;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        const bool has_value = i + 1 < argc;
        if (argument == "--mutants" && has_value) {
            options.mutants = std::stoul(argv[++i]);
        } else if (argument == "--mdr" && has_value) {
            options.mdr = argv[++i];
        } else if (argument == "--timeout" && has_value) {
            options.timeout = std::stod(argv[++i]);
        } else if (argument == "--memory-limit" && has_value) {
            options.memory_limit_mib = std::stoul(argv[++i]);
        } else if (argument == "--keep" && has_value) {
            options.keep = std::stoul(argv[++i]);
        } else if (argument.starts_with("--")) {
            return false;
        } else {
            positional.push_back(argument);
        }
    }
    if (positional.size() < 2 || positional.size() > 3) return false;
    options.corpus = positional[0];
    options.seconds = std::stod(positional[1]);
    if (positional.size() == 3) options.seed = static_cast<unsigned>(std::stoul(positional[2]));
    if (options.mdr.empty()) options.mdr = fs::read_symlink("/proc/self/exe").parent_path() / "mdr";
    options.mdr = fs::absolute(options.mdr);
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    bool parsed = false;
    try {
        parsed = parse_options(argc, argv, options);
    } catch (const std::exception&) {  // a number that is not one
    }
    if (!parsed) {
        std::fprintf(stderr, "usage: mdr_fit_fuzz CORPUS_DIR SECONDS [SEED] [--mutants N] [--mdr PATH] "
                             "[--timeout S] [--memory-limit MIB] [--keep K]\n");
        return 2;
    }
    const auto seeds = read_corpus(options.corpus);
    if (seeds.empty() || !fs::exists(options.mdr)) {
        std::fprintf(stderr, "mdr_fit_fuzz: no seed folder with a case.toml in %s, or no %s\n",
                     options.corpus.c_str(), options.mdr.c_str());
        return 2;
    }
    std::vector<std::string> line_pool;
    for (const auto& seed : seeds) {
        for (const auto& [name, text] : seed.files) {  // the lines of text files: those of binary ones are noise
            if (is_binary(text)) continue;
            for (auto& line : mdr::fuzz::lines_of(text)) line_pool.push_back(std::move(line));
        }
    }
    mdr::fuzz::Mutator mutator(std::move(line_pool), options.seed);
    const fs::path work = fs::temp_directory_path() / ("mdr-fit-fuzz-" + std::to_string(getpid()));
    std::map<std::string, std::size_t> counts;
    std::size_t failed = 0;
    std::size_t exit_codes[4] = {0, 0, 0, 0};  // 0, 1, 2, other (a signal, a hang)
    double slowest = 0.0;
    long peak_kib = 0;
    const auto start = std::chrono::steady_clock::now();
    std::size_t inputs = 0;
    for (;; ++inputs) {
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const bool seed_input = inputs < seeds.size();
        if (!seed_input && (elapsed > options.seconds || inputs - seeds.size() >= options.mutants)) break;
        const Seed input = seed_input ? seeds[inputs] : mutate(seeds, mutator);
        const std::string origin = "input " + std::to_string(inputs) + (seed_input ? " (seed " : " (a mutant of ") +
                                   input.name + ", fuzzer seed " + std::to_string(options.seed) + ")";
        const bool existing_out = !seed_input && mutator.pick(16) == 0;
        const auto [failures, outcome] = run_mutant(input.files, work, existing_out, options);
        ++exit_codes[outcome.exit_code >= 0 && outcome.exit_code <= 2 ? outcome.exit_code : 3];
        slowest = std::max(slowest, outcome.cpu_seconds);
        peak_kib = std::max(peak_kib, outcome.max_resident_kib);
        std::set<std::string> failed_oracles;
        for (const auto& [oracle, what] : failures) failed_oracles.insert(oracle);
        if (!failures.empty()) {
            ++failed;
            fs::create_directories("fit-fuzz-failures");
            std::ofstream log("fit-fuzz-failures/failures.log", std::ios::app);
            for (const auto& [oracle, what] : failures) {
                log << origin << " " << oracle << ": " << printable(what) << '\n';
            }
        }
        for (const auto& oracle : failed_oracles) {
            const std::size_t number = ++counts[oracle];
            if (number <= options.keep) keep_failure(input, work, oracle, number, origin, failures);
            if (number == 1) {  // the first of each kind as it happens
                const auto what = std::find_if(failures.begin(), failures.end(),
                                               [&](const auto& failure) { return failure.first == oracle; })->second;
                std::fprintf(stderr, "mdr_fit_fuzz: %s fails %s: %s\n", origin.c_str(), oracle.c_str(),
                             printable(what).c_str());
            }
        }
        if (inputs % 1000 == 999) {
            std::fprintf(stderr, "mdr_fit_fuzz: %zu inputs, %zu failed:%s\n", inputs + 1, failed,
                         summary_line(counts).c_str());
        }
    }
    fs::remove_all(work);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("mdr_fit_fuzz: %zu inputs (%zu seeds, %zu mutants) in %.0f s, seed %u; exit 0/1/2/other: "
                "%zu/%zu/%zu/%zu; slowest %.2f s (processor), peak %ld MiB; %zu failed:%s\n",
                inputs, seeds.size(), inputs - seeds.size(), elapsed, options.seed, exit_codes[0], exit_codes[1],
                exit_codes[2], exit_codes[3], slowest, peak_kib / 1024, failed, summary_line(counts).c_str());
    return failed == 0 ? 0 : 1;
}
