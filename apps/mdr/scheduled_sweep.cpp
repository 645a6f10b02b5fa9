#include "scheduled_sweep.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <system_error>

#include "mdr/error.hpp"

extern char** environ;

namespace mdr::cli {
namespace {

// The helper process with a pipe to its stdin and one from its stdout (its stderr is ours: its own errors show).
class Helper {
public:
    Helper(const std::string& python) : python_(python) {
        int in[2];
        int out[2];
        if (pipe2(in, O_CLOEXEC) != 0) throw std::system_error(errno, std::generic_category(), "pipe");
        if (pipe2(out, O_CLOEXEC) != 0) {
            close(in[0]);
            close(in[1]);
            throw std::system_error(errno, std::generic_category(), "pipe");
        }
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_adddup2(&actions, in[0], STDIN_FILENO);
        posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
        std::vector<std::string> arguments{python, "-m", "mdr._sweep_rows"};
        std::vector<char*> argv;
        for (auto& argument : arguments) argv.push_back(argument.data());
        argv.push_back(nullptr);
        const int error = posix_spawnp(&pid_, python.c_str(), &actions, nullptr, argv.data(), environ);
        posix_spawn_file_actions_destroy(&actions);
        close(in[0]);
        close(out[1]);
        to_child_ = in[1];
        from_child_ = out[0];
        if (error != 0) {
            pid_ = -1;
            throw std::runtime_error(fmt::format("--scheduler: cannot start the Python helper {} ({}); set "
                                                 "MDR_PYTHON to a python3 that has the mdr package and "
                                                 "python3-distributed",
                                                 python, std::generic_category().message(error)));
        }
    }
    Helper(const Helper&) = delete;
    Helper& operator=(const Helper&) = delete;
    ~Helper() {
        close_input();
        if (from_child_ >= 0) close(from_child_);
        if (pid_ > 0) stop();  // an exception on the way out
    }

    void send(const std::string& text) {
        for (std::size_t written = 0; written < text.size();) {
            const ssize_t n = write(to_child_, text.data() + written, text.size() - written);
            if (n < 0 && errno == EINTR) continue;
            if (n < 0) throw std::runtime_error(fmt::format("--scheduler: the Python helper {} stopped reading",
                                                            python_));
            written += static_cast<std::size_t>(n);
        }
        close_input();
    }

    /// The next line the helper wrote, false at its end.
    bool next_line(std::string& line) {
        while (true) {
            const std::size_t end = buffer_.find('\n');
            if (end != std::string::npos) {
                line = buffer_.substr(0, end);
                buffer_.erase(0, end + 1);
                return true;
            }
            char chunk[65536];
            const ssize_t n = read(from_child_, chunk, sizeof chunk);
            if (n < 0 && errno == EINTR) continue;  // the helper's progress lines come every 0.2 s: checked there
            if (n <= 0) return false;
            buffer_.append(chunk, static_cast<std::size_t>(n));
        }
    }

    /// Waits for the helper to end; its exit status.
    int wait() {
        int status = 0;
        while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
        }
        pid_ = -1;
        return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }

private:
    // Asks the helper to stop (SIGINT: it cancels its tasks and closes its client); after 10 s ends it (SIGKILL).
    void stop() {
        kill(pid_, SIGINT);
        for (int tenth = 0; tenth < 100; ++tenth) {
            int status = 0;
            if (waitpid(pid_, &status, WNOHANG) == pid_) {
                pid_ = -1;
                return;
            }
            usleep(100'000);
        }
        kill(pid_, SIGKILL);
        wait();
    }
    void close_input() {
        if (to_child_ >= 0) close(to_child_);
        to_child_ = -1;
    }

    std::string python_;
    pid_t pid_ = -1;
    int to_child_ = -1;
    int from_child_ = -1;
    std::string buffer_;
};

}  // namespace

std::string scheduler_python() {
    if (const char* python = std::getenv("MDR_PYTHON"); python != nullptr && *python != '\0') return python;
    std::error_code error;
    const auto beside = std::filesystem::read_symlink("/proc/self/exe", error).parent_path() / "python3";
    if (!error && access(beside.c_str(), X_OK) == 0) return beside.string();
    return "python3";
}

std::vector<io::SweepRow> run_scheduled_sweep(const std::string& case_text, const std::string& source,
                                              const std::vector<std::string>& specs,
                                              const std::vector<io::SweepAxis>& axes, const std::string& scheduler,
                                              const std::function<void(std::size_t, std::size_t)>& progress,
                                              ScheduledSweepInfo& info) {
    info.python = scheduler_python();
    std::vector<io::SweepRow> rows;
    for (auto& point : io::sweep_points(axes)) rows.push_back({std::move(point), {}, {}});
    std::vector<bool> filled(rows.size(), false);
    Helper helper(info.python);
    helper.send(nlohmann::json{{"version", MDR_VERSION},
                               {"case_text", case_text},
                               {"source", source},
                               {"specs", specs},
                               {"scheduler", scheduler}}
                    .dump() +
                "\n");
    std::string line;
    bool finished = false;
    std::size_t done = 0;
    while (helper.next_line(line)) {
        const auto message = nlohmann::ordered_json::parse(line);  // a row's summary keeps its key order
        if (message.contains("progress")) {
            done = message["progress"][0].get<std::size_t>();
            progress(done, rows.size());
        } else if (message.contains("rows")) {
            std::size_t index = message["first"].get<std::size_t>();
            for (const auto& row : message["rows"]) {
                if (index >= rows.size() || filled[index]) {
                    throw std::runtime_error(fmt::format("--scheduler: row {} came back twice or out of range", index));
                }
                rows[index].summary = io::summary_from_json(row[0].dump());
                rows[index].error = row[1].get<std::string>();
                filled[index++] = true;
            }
        } else if (message.contains("error")) {
            helper.wait();
            if (message.contains("rule")) {  // the scheduler refused or did not answer: like bad input, exit 2
                throw InvalidInput("--scheduler", message["value"].get<std::string>(),
                                   message["rule"].get<std::string>());
            }
            throw std::runtime_error(message["error"].get<std::string>());
        } else if (message.contains("done")) {
            const auto& batch = message["done"];
            info.scheduler = batch["scheduler"].get<std::string>();
            info.workers = batch["workers"].get<std::size_t>();
            info.tasks = batch["tasks"].get<std::size_t>();
            info.retried = batch["retried"].get<std::size_t>();
            finished = true;
        }
    }
    const int status = helper.wait();
    if (done < rows.size()) progress(done, rows.size());  // an interruption that ended the helper is reported so
    if (!finished || status != 0) {
        throw std::runtime_error(fmt::format("--scheduler: the Python helper `{} -m mdr._sweep_rows` ended (exit {}) "
                                             "without a result; it needs the Python package mdr {} and "
                                             "python3-distributed (MDR_PYTHON names another python3)",
                                             info.python, status, MDR_VERSION));
    }
    for (std::size_t r = 0; r < rows.size(); ++r) {
        if (!filled[r]) throw std::runtime_error(fmt::format("--scheduler: row {} never came back", r));
    }
    return rows;
}

}  // namespace mdr::cli
