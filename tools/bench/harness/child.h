#pragma once
// One measurement in a child process of its own, so that its peak memory (VmHWM) is its own and
// nothing a run leaves behind (heap, threads, caches) reaches the next.
#include <sys/wait.h>
#include <unistd.h>

#include <optional>
#include <type_traits>

namespace polar::bench {

// Runs `measure()` in a forked child and returns its result, sent back through a pipe as bytes;
// nothing when the child fails.
template <class Measure>
auto inChildProcess(Measure&& measure) -> std::optional<std::invoke_result_t<Measure&>> {
    using Result = std::invoke_result_t<Measure&>;
    static_assert(std::is_trivially_copyable_v<Result>, "a result crosses a pipe as bytes");
    int fds[2];
    if (::pipe(fds) != 0) return std::nullopt;
    const pid_t child = ::fork();
    if (child < 0) {
        ::close(fds[0]), ::close(fds[1]);
        return std::nullopt;
    }
    if (child == 0) {
        ::close(fds[0]);
        const Result r = measure();
        const ssize_t written = ::write(fds[1], &r, sizeof r);
        ::_exit(written == static_cast<ssize_t>(sizeof r) ? 0 : 1);
    }
    ::close(fds[1]);
    Result r{};
    const ssize_t got = ::read(fds[0], &r, sizeof r);
    ::close(fds[0]);
    int status = 0;
    ::waitpid(child, &status, 0);
    if (got != static_cast<ssize_t>(sizeof r) || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return std::nullopt;
    return r;
}

}  // namespace polar::bench
