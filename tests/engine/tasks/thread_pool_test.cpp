#include "polar/tasks.h"

#include <gtest/gtest.h>
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

namespace polar {
namespace {

// Writes each item's square into its own slot, and counts how often each item was run.
struct SquareJob {
    std::vector<std::uint64_t> out;
    std::vector<std::atomic<int>> runs;
    std::uint32_t workers = 1;
    std::atomic<bool> badWorker{false};
    explicit SquareJob(std::uint32_t n) : out(n), runs(n) {}

    static void run(std::uint32_t begin, std::uint32_t end, std::uint32_t worker, void* context) {
        auto& job = *static_cast<SquareJob*>(context);
        if (worker >= job.workers || begin >= end) job.badWorker = true;
        for (std::uint32_t i = begin; i < end; ++i) {
            job.out[i] = std::uint64_t(i) * i;
            ++job.runs[i];
        }
    }
};

void expectEveryItemOnce(const SquareJob& job) {
    for (std::size_t i = 0; i < job.out.size(); ++i) {
        ASSERT_EQ(job.runs[i].load(), 1) << "item " << i;
        ASSERT_EQ(job.out[i], std::uint64_t(i) * i) << "item " << i;
    }
    EXPECT_FALSE(job.badWorker.load());
}

TEST(ThreadPool, RunsEveryItemExactlyOnceAtAnyWorkerCount) {
    for (std::uint32_t workers : {1u, 2u, 3u, 4u, 7u, 16u}) {
        ThreadPool pool(workers);
        EXPECT_EQ(pool.workerCount(), workers);
        for (std::uint32_t count : {0u, 1u, 2u, 5u, 63u, 1000u, 100003u}) {
            SquareJob job(count);
            job.workers = workers;
            runTask(pool, &SquareJob::run, count, 1, &job);
            expectEveryItemOnce(job);
        }
    }
}

TEST(ThreadPool, KeepsRangesAtLeastMinRange) {
    ThreadPool pool(4);
    struct Ranges {
        std::atomic<std::uint32_t> shortest{~0u};
        std::atomic<int> lastSeen{0};
    } seen;
    auto fn = [](std::uint32_t begin, std::uint32_t end, std::uint32_t, void* context) {
        auto& r = *static_cast<Ranges*>(context);
        if (end == 1000)
            ++r.lastSeen;  // the last range may be shorter
        else {
            std::uint32_t cur = r.shortest.load();
            while (end - begin < cur && !r.shortest.compare_exchange_weak(cur, end - begin)) {
            }
        }
    };
    runTask(pool, fn, 1000, 300, &seen);
    EXPECT_EQ(seen.lastSeen.load(), 1);
    EXPECT_GE(seen.shortest.load(), 300u);
}

TEST(ThreadPool, RunsSeveralTasksInFlight) {
    ThreadPool pool(3);
    std::vector<std::unique_ptr<SquareJob>> jobs;
    std::vector<TaskHandle> handles;
    for (std::uint32_t k = 0; k < ThreadPool::kMaxTasks; ++k) {
        jobs.push_back(std::make_unique<SquareJob>(5000 + k));
        jobs.back()->workers = 3;
        handles.push_back(pool.enqueue(&SquareJob::run, 5000 + k, 16, jobs.back().get()));
    }
    for (std::uint32_t k = ThreadPool::kMaxTasks; k-- > 0;) pool.finish(handles[k]);  // any order
    for (const auto& job : jobs) expectEveryItemOnce(*job);
}

TEST(ThreadPool, ReusesItsSlotsTaskAfterTask) {
    ThreadPool pool(2);
    for (int round = 0; round < 2000; ++round) {
        SquareJob job(64);
        job.workers = 2;
        runTask(pool, &SquareJob::run, 64, 1, &job);
        expectEveryItemOnce(job);
        if (HasFatalFailure()) return;
    }
}

TEST(ThreadPool, HardwareThreadsIsAtLeastOne) {
    EXPECT_GE(hardwareThreads(), 1u);
}

}  // namespace
}  // namespace polar
