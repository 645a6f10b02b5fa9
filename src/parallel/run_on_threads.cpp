#include "mdr/parallel/run_on_threads.hpp"

#include <fmt/format.h>
#include <sched.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <vector>

namespace mdr::parallel {
namespace {

// The threads: stopped and joined on every way out, so that no exception leaves a joinable thread.
class Workers {
public:
    explicit Workers(std::atomic<bool>& stop) : stop_(stop) {}
    Workers(const Workers&) = delete;
    Workers& operator=(const Workers&) = delete;
    ~Workers() {
        stop_ = true;
        for (auto& thread : threads_) thread.join();
    }
    void start(unsigned count, const std::function<void(unsigned)>& work) {
        for (unsigned j = 0; j < count; ++j) {
            try {
                threads_.emplace_back(work, j);
            } catch (const std::system_error& error) {
                throw std::runtime_error(fmt::format("--jobs = {}: could not start thread {} ({}); use fewer jobs",
                                                     count, j + 1, error.code().message()));
            }
        }
    }

private:
    std::atomic<bool>& stop_;
    std::vector<std::thread> threads_;
};

}  // namespace

unsigned available_cores() {
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof(set), &set) == 0) return static_cast<unsigned>(std::max(1, CPU_COUNT(&set)));
    return std::max(1u, std::thread::hardware_concurrency());
}

unsigned local_threads(unsigned jobs, std::size_t items) {
    const unsigned cores = available_cores();
    const std::size_t asked = jobs == 0 ? cores : std::min(jobs, cores);
    return static_cast<unsigned>(std::max<std::size_t>(1, std::min(asked, items)));
}

void run_on_threads(std::size_t count, unsigned threads,
                    const std::function<void(std::size_t, unsigned, const std::atomic<bool>&)>& work,
                    const std::function<void(std::size_t)>& report) {
    if (count == 0) {
        report(0);
        return;
    }
    const auto started = static_cast<unsigned>(std::min<std::size_t>(std::max(threads, 1u), count));
    std::atomic<bool> stop{false};
    std::atomic<std::size_t> next{0};
    std::size_t done = 0;
    std::exception_ptr failure;
    std::mutex mutex;
    std::condition_variable finished;
    {
        Workers workers(stop);
        workers.start(started, [&](unsigned worker) {
            for (std::size_t item = next++; item < count && !stop; item = next++) {
                try {
                    work(item, worker, stop);
                } catch (...) {
                    const std::lock_guard lock(mutex);
                    if (!failure) failure = std::current_exception();
                    stop = true;
                    finished.notify_one();
                    return;
                }
                const std::lock_guard lock(mutex);
                ++done;
                finished.notify_one();
            }
        });
        // Progress every 0.2 s and at the end (also when all ended before the first wait), outside the lock: the
        // caller sees it and can stop the work by throwing, also while a long item runs.
        std::unique_lock lock(mutex);
        do {
            finished.wait_for(lock, std::chrono::milliseconds(200), [&] { return done == count || failure; });
            if (failure) break;
            const std::size_t reported = done;
            lock.unlock();
            report(reported);
            lock.lock();
        } while (done < count);
    }  // joined (also when report throws: the Workers stop the work)
    if (failure) std::rethrow_exception(failure);
}

}  // namespace mdr::parallel
