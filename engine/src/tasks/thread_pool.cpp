#include "polar/tasks.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace polar {

namespace {

// One enqueued task. Its ranges are claimed and counted done under the pool's mutex, so a slot is
// never reused while a thread still reads it: finish() frees it only once every claimed range is
// done, and a thread claims a range of a slot only while holding the mutex.
struct Task {
    TaskFunction function = nullptr;
    void* context = nullptr;
    std::uint32_t count = 0;
    std::uint32_t rangeSize = 1;
    std::uint32_t ranges = 0;
    std::uint32_t nextRange = 0;
    std::uint32_t doneRanges = 0;
    bool inUse = false;
};

// Ranges per worker: enough that a worker that started late or ran slow ranges is balanced by the
// others (the wait for the last range is short), yet few enough that claiming one (a lock) costs
// nothing beside the range's work: a 100k-object step's loops get ranges of about 3000 items.
constexpr std::uint32_t kRangesPerWorker = 16;

// Threads a pool may start: none where the target has no threads (WebAssembly built without
// pthreads), so a pool asked for more runs every task on the calling thread.
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
constexpr std::uint32_t kMaxThreads = 1;
#else
constexpr std::uint32_t kMaxThreads = 1024;
#endif

}  // namespace

struct ThreadPool::State {
    std::uint32_t workers = 1;
    std::vector<std::thread> threads;
    std::mutex mutex;
    std::condition_variable wake;  // a task was enqueued, or the pool is stopping
    std::condition_variable done;  // a task's last range is done
    std::array<Task, kMaxTasks> tasks;
    bool stopping = false;

    Task* claimable() {
        for (Task& task : tasks)
            if (task.inUse && task.nextRange < task.ranges) return &task;
        return nullptr;
    }

    // Runs ranges of `task` until none is left to claim. Called and returns with `lock` held.
    void runRanges(Task& task, std::uint32_t worker, std::unique_lock<std::mutex>& lock) {
        while (task.nextRange < task.ranges) {
            std::uint32_t begin = task.nextRange++ * task.rangeSize;
            std::uint32_t end = std::min(task.count, begin + task.rangeSize);
            lock.unlock();
            task.function(begin, end, worker, task.context);
            lock.lock();
            if (++task.doneRanges == task.ranges) done.notify_all();
        }
    }

    void workerLoop(std::uint32_t worker) {
        std::unique_lock lock(mutex);
        for (;;) {
            if (Task* task = claimable()) {
                runRanges(*task, worker, lock);
                continue;
            }
            if (stopping) return;
            wake.wait(lock);
        }
    }
};

ThreadPool::ThreadPool(std::uint32_t workers) : state_(std::make_unique<State>()) {
    state_->workers = std::clamp<std::uint32_t>(workers, 1, kMaxThreads);
    state_->threads.reserve(state_->workers - 1);
    for (std::uint32_t w = 1; w < state_->workers; ++w)
        state_->threads.emplace_back([this, w] { state_->workerLoop(w); });
}

ThreadPool::~ThreadPool() {
    {
        std::lock_guard lock(state_->mutex);
        state_->stopping = true;
    }
    state_->wake.notify_all();
    for (std::thread& thread : state_->threads) thread.join();
}

std::uint32_t ThreadPool::workerCount() const {
    return state_->workers;
}

TaskHandle ThreadPool::enqueue(TaskFunction function, std::uint32_t count, std::uint32_t minRange,
                               void* context) {
    State& s = *state_;
    std::uint32_t target = s.workers * kRangesPerWorker;
    std::uint32_t rangeSize = std::max({1u, minRange, (count + target - 1) / target});
    std::uint32_t ranges = count == 0 ? 0 : (count + rangeSize - 1) / rangeSize;
    if (s.workers == 1 || ranges <= 1) {  // nothing to share: run it here, now
        for (std::uint32_t begin = 0; begin < count; begin += rangeSize)
            function(begin, std::min(count, begin + rangeSize), 0, context);
        return nullptr;
    }
    Task* task = nullptr;
    {
        std::lock_guard lock(s.mutex);
        for (Task& slot : s.tasks)
            if (!slot.inUse) {
                task = &slot;
                break;
            }
        assert(task && "more than ThreadPool::kMaxTasks tasks in flight");
        *task = Task{function, context, count, rangeSize, ranges, 0, 0, true};
    }
    s.wake.notify_all();
    return task;
}

void ThreadPool::finish(TaskHandle handle) {
    if (!handle) return;  // it ran inside enqueue()
    State& s = *state_;
    Task& task = *static_cast<Task*>(handle);
    std::unique_lock lock(s.mutex);
    s.runRanges(task, 0, lock);
    s.done.wait(lock, [&] { return task.doneRanges == task.ranges; });
    task.inUse = false;
}

std::uint32_t hardwareThreads() {
    return std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace polar
