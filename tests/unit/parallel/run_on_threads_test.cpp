#include "mdr/parallel/run_on_threads.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

namespace mdr::parallel {
namespace {

TEST(RunOnThreads, RunsEveryItemOnceOnAtMostTheThreadsAskedAndReportsTheEnd) {
    std::vector<std::atomic<int>> runs(50);
    std::atomic<unsigned> highest_worker{0};
    std::vector<std::size_t> reports;
    run_on_threads(
        runs.size(), 3,
        [&](std::size_t item, unsigned worker, const std::atomic<bool>&) {
            ++runs[item];
            unsigned seen = highest_worker;
            while (worker > seen && !highest_worker.compare_exchange_weak(seen, worker)) {
            }
        },
        [&](std::size_t done) { reports.push_back(done); });
    for (const auto& count : runs) EXPECT_EQ(count, 1);
    EXPECT_LT(highest_worker, 3u);
    ASSERT_FALSE(reports.empty());
    EXPECT_EQ(reports.back(), runs.size());
}

TEST(RunOnThreads, NoMoreThreadsThanItems) {
    std::atomic<unsigned> highest_worker{0};
    std::atomic<unsigned> items{0};
    run_on_threads(
        2, 16,
        [&](std::size_t, unsigned worker, const std::atomic<bool>&) {
            if (worker >= 2) ++highest_worker;
            ++items;
        },
        [](std::size_t) {});
    EXPECT_EQ(items, 2u);
    EXPECT_EQ(highest_worker, 0u);  // no item ran on a third thread
}

TEST(RunOnThreads, AReportThatThrowsStopsTheWorkAndPassesTheExceptionOn) {
    std::atomic<bool> saw_stop{false};
    std::atomic<std::size_t> started{0};
    const auto work = [&](std::size_t, unsigned, const std::atomic<bool>& stop) {
        ++started;
        const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
        while (!stop && std::chrono::steady_clock::now() < give_up) {
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        saw_stop = saw_stop || stop.load();
    };
    EXPECT_THROW(run_on_threads(1000, 2, work, [](std::size_t) { throw std::out_of_range("stop"); }),
                 std::out_of_range);
    EXPECT_TRUE(saw_stop);
    EXPECT_LE(started, 2u);  // the items in progress ended early, no new one was started
}

TEST(RunOnThreads, TheFirstExceptionOfTheWorkIsRethrownAfterTheThreadsEnd) {
    // Item 0 throws; every other item waits for the stop, so the outcome does not depend on the threads' speed (a
    // trivial item could otherwise let the second thread run all 1000 before the first one's stop).
    std::atomic<std::size_t> ran{0};
    EXPECT_THROW(run_on_threads(
                     1000, 2,
                     [&](std::size_t item, unsigned, const std::atomic<bool>& stop) {
                         ++ran;
                         if (item == 0) throw std::invalid_argument("item 0");
                         while (!stop) std::this_thread::yield();
                     },
                     [](std::size_t) {}),
                 std::invalid_argument);
    EXPECT_LE(ran, 2u);  // the thrower's item and at most one in progress on the other thread
}

TEST(LocalThreads, TheRuleOfJobs) {
    const unsigned cores = available_cores();
    EXPECT_GE(cores, 1u);
    EXPECT_EQ(local_threads(0, 1000000), cores);  // 0: every core
    EXPECT_EQ(local_threads(1, 1000000), 1u);
    EXPECT_EQ(local_threads(cores + 5, 1000000), cores);  // never more than the cores
    EXPECT_EQ(local_threads(0, 1), 1u);                   // never more than the items
    EXPECT_EQ(local_threads(0, 0), 1u);                   // at least one
}

}  // namespace
}  // namespace mdr::parallel
