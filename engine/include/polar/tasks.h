#pragma once

// How the engine runs work on several threads without owning any. The world and the renderer split
// a job into items (objects, pairs, bands of rows) and hand it to a TaskSystem, which runs ranges of
// items on whatever threads it has and reports when every range is done. The game may pass its own
// (a job system it already runs); ThreadPool is the default that ships with the engine.
//
// Determinism: a task writes only outputs indexed by item (or by range start), never something
// whose value depends on which worker ran which range or in what order. Every caller then reads the
// outputs in item order, so results are bit-identical at any worker count.

#include <cstdint>
#include <memory>

namespace polar {

// Runs the items [begin, end) of a task. `worker` is in [0, workerCount()): the index of the thread
// running this range, for per-worker scratch memory only (never for results).
using TaskFunction = void (*)(std::uint32_t begin, std::uint32_t end, std::uint32_t worker, void* context);

// What a task system returned for an enqueued task, to be passed back to finish().
using TaskHandle = void*;

class TaskSystem {
  public:
    virtual ~TaskSystem() = default;
    // The number of threads that may run ranges at once, the caller's own included; at least 1.
    virtual std::uint32_t workerCount() const = 0;
    // Starts running `function` over the items [0, count), split into ranges of at least `minRange`
    // items (the last may be shorter). May run some or all of it before returning.
    virtual TaskHandle enqueue(TaskFunction function, std::uint32_t count, std::uint32_t minRange,
                               void* context) = 0;
    // Returns once every range of the task is done. Each enqueued task is finished exactly once.
    virtual void finish(TaskHandle task) = 0;
};

// Runs a task to completion: enqueue, then finish.
inline void runTask(TaskSystem& tasks, TaskFunction function, std::uint32_t count, std::uint32_t minRange,
                    void* context) {
    tasks.finish(tasks.enqueue(function, count, minRange, context));
}

// The default task system: workerCount - 1 threads of its own, plus the thread that calls finish(),
// which runs ranges too. With one worker it starts no thread and runs each task inside enqueue();
// where the target has no threads (WebAssembly without pthreads) it always has one worker.
// Enqueue and finish allocate nothing; up to kMaxTasks tasks may be in flight at once (asserted).
class ThreadPool final : public TaskSystem {
  public:
    static constexpr std::uint32_t kMaxTasks = 16;

    explicit ThreadPool(std::uint32_t workers);
    ~ThreadPool() override;
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    std::uint32_t workerCount() const override;
    TaskHandle enqueue(TaskFunction function, std::uint32_t count, std::uint32_t minRange,
                       void* context) override;
    void finish(TaskHandle task) override;

  private:
    struct State;
    std::unique_ptr<State> state_;
};

// The number of hardware threads, at least 1.
std::uint32_t hardwareThreads();

}  // namespace polar
