#include "run_limits.h"

namespace polar::server {

bool RateLimiter::allow(const std::string& key, std::int64_t nowMs) {
    constexpr std::int64_t kMinuteMs = 60'000;
    std::lock_guard lock(mutex_);
    // Keys quiet for a minute are forgotten now and then, so the table holds only the last minute's.
    if (nowMs - lastSweepMs_ > kMinuteMs) {
        for (auto it = events_.begin(); it != events_.end();)
            it = it->second.empty() || nowMs - it->second.back() >= kMinuteMs ? events_.erase(it)
                                                                              : std::next(it);
        lastSweepMs_ = nowMs;
    }
    std::deque<std::int64_t>& times = events_[key];
    while (!times.empty() && nowMs - times.front() >= kMinuteMs) times.pop_front();
    if (times.size() >= perMinute_) return false;
    times.push_back(nowMs);
    return true;
}

}  // namespace polar::server
