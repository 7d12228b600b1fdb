#pragma once
// How much the server takes: the request size, runs a minute per key and per address, the
// verification queue. The numbers live in one struct; RateLimiter counts the runs.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <mutex>
#include <string>
#include <unordered_map>

namespace polar::server {

struct Limits {
    std::size_t maxBodyBytes = 1 << 20;  // a long replay is ~1 MB an hour; more answers 413
    unsigned runsPerKeyPerMinute = 30;   // more answers 429
    unsigned runsPerAddressPerMinute = 60;
    unsigned verifyWorkers = 2;
    std::size_t verifyQueue = 64;  // runs waiting for a worker; more answers 503
    int retryAfterSeconds = 5;     // what a 503 asks the client to wait
    double tokenTolerance = 0.9;  // a ranked run needs ticks / tick rate × this of wall time since its token
    std::int64_t tokenLifetimeMs = 24LL * 3600 * 1000;  // an older token ranks nothing
};

// Counts events per key in a sliding minute. Thread-safe.
class RateLimiter {
  public:
    explicit RateLimiter(unsigned perMinute) : perMinute_(perMinute) {}
    // Counts one event for `key` at `nowMs`; false (and nothing counted) when the key has had
    // perMinute events in the minute before.
    bool allow(const std::string& key, std::int64_t nowMs);

  private:
    const unsigned perMinute_;
    std::mutex mutex_;
    std::unordered_map<std::string, std::deque<std::int64_t>> events_;
    std::int64_t lastSweepMs_ = 0;
};

}  // namespace polar::server
