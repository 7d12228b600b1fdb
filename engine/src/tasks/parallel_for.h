#pragma once
#include <cstddef>
#include <cstdint>

#include "polar/tasks.h"

namespace polar {

// Whether a phase of `count` items is worth handing to `tasks`: there is a task system with more
// than one worker, and enough items that waking the workers (microseconds) is paid back.
inline bool worthSharing(const TaskSystem* tasks, std::size_t count, std::uint32_t parallelMin) {
    return tasks != nullptr && count >= parallelMin && count >= 2 && tasks->workerCount() > 1;
}

// Runs body(begin, end, worker) over the items [0, count) on `tasks`, in ranges of at least
// `minRange` items, and returns when every range is done. The body must write only outputs owned
// by its items (or by the worker's scratch), so the result does not depend on the split.
template <class Body>
void parallelFor(TaskSystem& tasks, std::uint32_t count, std::uint32_t minRange, Body& body) {
    TaskFunction run = [](std::uint32_t begin, std::uint32_t end, std::uint32_t worker, void* context) {
        (*static_cast<Body*>(context))(begin, end, worker);
    };
    runTask(tasks, run, count, minRange, &body);
}

// parallelFor on `tasks` when worthSharing says so; otherwise body(0, count, 0), all on the calling
// thread. `tasks` may be null.
template <class Body>
void parallelForIfWorth(TaskSystem* tasks, std::size_t count, std::uint32_t parallelMin,
                        std::uint32_t minRange, Body& body) {
    if (worthSharing(tasks, count, parallelMin))
        parallelFor(*tasks, static_cast<std::uint32_t>(count), minRange, body);
    else
        body(std::uint32_t(0), static_cast<std::uint32_t>(count), std::uint32_t(0));
}

}  // namespace polar
