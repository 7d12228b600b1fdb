#pragma once
// What the server does, one function a request: a route has already read the request and hands
// its values here; the answer is a status and a JSON body. Nothing here knows HTTP's wire form.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "polar/json_writer.h"
#include "run_limits.h"
#include "storage.h"
#include "submission.h"
#include "verify_pool.h"

namespace polar::server {

// A status code and its JSON body; a 429 or 503 also says when to come back.
struct Answer {
    int status = 200;
    std::string body;  // JSON text
    int retryAfterSeconds = 0;
};
// The error body every refusal has: {"error": WORD, "message": SENTENCE}.
Answer errorAnswer(int status, const std::string& word, const std::string& message);

// Milliseconds since 1970 in UTC; the service reads time only through one of these.
using Clock = std::function<std::int64_t()>;
std::int64_t systemMilliseconds();

// Which runs a board shows.
enum class Season { kAllTime, kWeek, kToday };
// The first moment of a season that holds `nowMs`: 0, this week's Monday 00:00 UTC, today's 00:00 UTC.
std::int64_t seasonStart(Season season, std::int64_t nowMs);
// "2026-12-05T12:00:00.000Z"
std::string utcText(std::int64_t ms);

class Service {
  public:
    Service(Storage& storage, VerifyPool& pool, Limits limits, Clock clock = systemMilliseconds);

    Answer server() const;
    Answer issueToken();
    // `address` is the client's, for its rate limit.
    Answer submit(const Submission& submission, const std::string& address);
    Answer top(BoardQuery query, Season season);
    // The page of `query.count` runs around the best run of `name`.
    Answer around(BoardQuery query, Season season, const std::string& name);
    Answer playerBest(const std::string& name);
    Answer run(std::int64_t id);
    // The replay's bytes themselves (the body is then the text, not JSON): nothing for an unknown run.
    std::optional<std::string> replay(std::int64_t id);

    const Limits& limits() const { return limits_; }

  private:
    // A board page; `around` adds the player and their rank.
    Answer page(const BoardQuery& query, Season season, const BoardPage& page, const std::string& name = "",
                std::int64_t rank = 0) const;

    Storage& storage_;
    VerifyPool& pool_;
    const Limits limits_;
    Clock clock_;
    RateLimiter perKey_, perAddress_;
};

// A run's members as the API shows them (without its bytes), into an object being written.
void writeRunMembers(JsonWriter& out, const RunRecord& run);

}  // namespace polar::server
