#pragma once
/// \file
/// Runs a command as a child process the way a user's shell would, with a wall-clock limit, an address-space
/// limit and its own process group, and reports how it ended (for fit_fuzz.cpp).

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

namespace mdr::fuzz {

/// How a child process ended.
struct ChildOutcome {
    int exit_code = -1;               ///< its exit status, -1 when a signal ended it
    int signal = 0;                   ///< the signal that ended it (0: it exited)
    bool timed_out = false;           ///< ended by the CPU-time limit (SIGXCPU) or killed after the wall-clock one
    bool left_processes = false;      ///< processes of its group still ran after it ended (they are killed)
    long max_resident_kib = 0;        ///< its peak resident memory [KiB]
    double wall_seconds = 0.0;        ///< how long it ran [s]
    double cpu_seconds = 0.0;         ///< the processor time it used, user and system [s]
};

/// Runs `argv` (argv[0] a path) in `directory` with stdin from /dev/null and stdout and stderr into the files
/// `stdout_path` and `stderr_path`. It may use `timeout_seconds` of processor time (RLIMIT_CPU), and its process
/// group is killed after three times as long on the wall clock (a child that waits for ever; the factor leaves
/// room for a machine shared with other work). `memory_limit_bytes` > 0
/// bounds its address space (RLIMIT_AS; leave it 0 for a program built with AddressSanitizer, which reserves
/// terabytes of address space).
inline ChildOutcome run_child(const std::vector<std::string>& argv, const std::filesystem::path& directory,
                              const std::filesystem::path& stdout_path, const std::filesystem::path& stderr_path,
                              double timeout_seconds, std::size_t memory_limit_bytes) {
    std::vector<char*> arguments;
    for (const auto& argument : argv) arguments.push_back(const_cast<char*>(argument.c_str()));
    arguments.push_back(nullptr);
    const auto start = std::chrono::steady_clock::now();
    const pid_t child = fork();
    if (child == 0) {  // only async-signal-safe calls until exec
        setpgid(0, 0);
        if (memory_limit_bytes > 0) {
            const rlimit limit{memory_limit_bytes, memory_limit_bytes};
            setrlimit(RLIMIT_AS, &limit);
        }
        const auto cpu_seconds = static_cast<rlim_t>(timeout_seconds) + 1;
        const rlimit cpu{cpu_seconds, cpu_seconds + 1};
        setrlimit(RLIMIT_CPU, &cpu);
        const rlimit no_core{0, 0};
        setrlimit(RLIMIT_CORE, &no_core);
        const int input = open("/dev/null", O_RDONLY);
        const int output = open(stdout_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int error = open(stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (input < 0 || output < 0 || error < 0 || chdir(directory.c_str()) != 0) _exit(126);
        dup2(input, STDIN_FILENO);
        dup2(output, STDOUT_FILENO);
        dup2(error, STDERR_FILENO);
        execv(arguments[0], arguments.data());
        _exit(127);
    }
    ChildOutcome outcome;
    if (child < 0) return outcome;
    setpgid(child, child);  // also here, so that the group exists whichever of the two runs first
    int status = 0;
    rusage usage{};
    for (auto pause = std::chrono::microseconds(200);; pause = std::min(pause * 2, std::chrono::microseconds(5000))) {
        if (wait4(child, &status, WNOHANG, &usage) == child) break;
        if (std::chrono::steady_clock::now() - start > std::chrono::duration<double>(3.0 * timeout_seconds)) {
            outcome.timed_out = true;
            kill(-child, SIGKILL);
            wait4(child, &status, 0, &usage);
            break;
        }
        std::this_thread::sleep_for(pause);
    }
    outcome.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    outcome.max_resident_kib = usage.ru_maxrss;
    outcome.cpu_seconds = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                          1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
    if (WIFEXITED(status)) outcome.exit_code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) outcome.signal = WTERMSIG(status);
    if (outcome.signal == SIGXCPU || outcome.cpu_seconds > timeout_seconds) outcome.timed_out = true;
    if (kill(-child, 0) == 0) {
        outcome.left_processes = true;
        kill(-child, SIGKILL);
    }
    return outcome;
}

}  // namespace mdr::fuzz
