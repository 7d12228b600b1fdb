#include "verify_pool.h"

namespace polar::server {

VerifyPool::VerifyPool(ServerGames games, unsigned workers, std::size_t capacity)
    : games_(std::move(games)), capacity_(capacity) {
    for (unsigned i = 0; i < workers; ++i) workers_.emplace_back([this] { work(); });
}

VerifyPool::~VerifyPool() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    ready_.notify_all();
    for (std::thread& worker : workers_) worker.join();
}

std::optional<std::future<Verdict>> VerifyPool::submit(std::string replay) {
    std::future<Verdict> verdict;
    {
        std::lock_guard lock(mutex_);
        if (queue_.size() >= capacity_ || stopping_) return std::nullopt;
        queue_.push_back(Job{std::move(replay), {}});
        verdict = queue_.back().verdict.get_future();
    }
    ready_.notify_one();
    return verdict;
}

void VerifyPool::work() {
    for (;;) {
        Job job;
        {
            std::unique_lock lock(mutex_);
            ready_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
            if (queue_.empty()) return;  // stopping, and nothing left
            job = std::move(queue_.front());
            queue_.pop_front();
        }
        job.verdict.set_value(verifyRun(job.replay, games_));
    }
}

}  // namespace polar::server
