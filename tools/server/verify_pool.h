#pragma once
// Verification on a fixed pool of worker threads with a bounded queue.
//
// Why a pool? A run costs milliseconds to seconds of one core; the HTTP threads only wait for
// verdicts, so the CPU the server spends verifying is bounded by the workers, and a burst beyond
// the queue is answered at once (503 with Retry-After) instead of piling up.
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <future>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "verification.h"

namespace polar::server {

class VerifyPool {
  public:
    // `workers` threads verifying against `games`; at most `capacity` runs waiting.
    VerifyPool(ServerGames games, unsigned workers, std::size_t capacity);
    // Finishes the runs already queued, then stops the workers.
    ~VerifyPool();
    VerifyPool(const VerifyPool&) = delete;
    VerifyPool& operator=(const VerifyPool&) = delete;

    // Queues a replay for verification; nothing when the queue is full.
    std::optional<std::future<Verdict>> submit(std::string replay);

    const ServerGames& games() const { return games_; }

  private:
    struct Job {
        std::string replay;
        std::promise<Verdict> verdict;
    };
    void work();

    const ServerGames games_;
    const std::size_t capacity_;
    std::mutex mutex_;
    std::condition_variable ready_;
    std::deque<Job> queue_;
    bool stopping_ = false;
    std::vector<std::thread> workers_;
};

}  // namespace polar::server
