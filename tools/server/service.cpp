#include "service.h"

#include <sodium.h>

#include <chrono>
#include <ctime>

#include "polarcade_version.h"
#include "replay/replay_format.h"
#include "rules/game.h"
#include "signature.h"

namespace polar::server {
namespace {

constexpr std::int64_t kDayMs = 86'400'000;

const char* seasonWord(Season season) {
    switch (season) {
        case Season::kAllTime:
            return "all";
        case Season::kWeek:
            return "week";
        case Season::kToday:
            return "today";
    }
    return "all";
}

}  // namespace

Answer errorAnswer(int status, const std::string& word, const std::string& message) {
    JsonWriter out;
    out.beginObject().member("error", word).member("message", message).endObject();
    return Answer{status, out.text(), 0};
}

std::int64_t systemMilliseconds() {
    return std::chrono::duration_cast<std::chrono::milliseconds>(
               std::chrono::system_clock::now().time_since_epoch())
        .count();
}

std::int64_t seasonStart(Season season, std::int64_t nowMs) {
    const std::int64_t day = nowMs / kDayMs;
    switch (season) {
        case Season::kAllTime:
            return 0;
        case Season::kToday:
            return day * kDayMs;
        case Season::kWeek:
            // 1970-01-01 was a Thursday: (day + 3) % 7 counts the days since Monday.
            return (day - (day + 3) % 7) * kDayMs;
    }
    return 0;
}

std::string utcText(std::int64_t ms) {
    std::time_t seconds = static_cast<std::time_t>(ms / 1000);
    std::tm t{};
    gmtime_r(&seconds, &t);
    char text[80];
    std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", t.tm_year + 1900, t.tm_mon + 1,
                  t.tm_mday, t.tm_hour, t.tm_min, t.tm_sec, static_cast<int>(ms % 1000));
    return text;
}

void writeRunMembers(JsonWriter& out, const RunRecord& run) {
    out.member("id", run.id)
        .member("name", run.name)
        .member("score", run.score)
        .member("wave", run.wave)
        .member("ticks", run.ticks)
        .member("scene", run.scene)
        .member("mode", run.mode)
        .member("rules", run.rules)
        .member("speed", run.speed)
        .member("seed", std::to_string(run.seed))
        .member("ranked", run.ranked)
        .member("submitted", utcText(run.submittedMs))
        .member("run_hash", run.runHash)
        .member("public_key", run.publicKey);
}

Service::Service(Storage& storage, VerifyPool& pool, Limits limits, Clock clock)
    : storage_(storage),
      pool_(pool),
      limits_(limits),
      clock_(std::move(clock)),
      perKey_(limits.runsPerKeyPerMinute),
      perAddress_(limits.runsPerAddressPerMinute) {}

Answer Service::server() const {
    JsonWriter out;
    out.beginObject()
        .member("version", kPolarcadeVersion)
        .member("game_version", polar::game::gameVersion())
        .key("rules")
        .beginArray()
        .value(1)
        .value(polar::game::kRulesVersion)
        .endArray()
        .member("default_mode", defaultMode())
        .key("scenes")
        .beginArray();
    for (const auto& [scene, hash] : pool_.games().scenes) out.value(scene);
    out.endArray()
        .key("limits")
        .beginObject()
        .member("max_body_bytes", limits_.maxBodyBytes)
        .member("runs_per_key_per_minute", limits_.runsPerKeyPerMinute)
        .member("runs_per_address_per_minute", limits_.runsPerAddressPerMinute)
        .member("max_ticks", pool_.games().maxTicks)
        .member("verify_cpu_seconds", pool_.games().cpuSeconds)
        .member("token_tolerance", limits_.tokenTolerance)
        .endObject()
        .endObject();
    return Answer{200, out.text(), 0};
}

Answer Service::issueToken() {
    unsigned char bytes[16];
    randombytes_buf(bytes, sizeof bytes);
    const std::string token = toHex(std::string_view(reinterpret_cast<char*>(bytes), sizeof bytes));
    const std::int64_t now = clock_();
    storage_.issueToken(token, now);
    JsonWriter out;
    out.beginObject().member("token", token).member("issued", utcText(now)).endObject();
    return Answer{201, out.text(), 0};
}

Answer Service::submit(const Submission& s, const std::string& address) {
    const std::int64_t now = clock_();
    const std::string keyHex = toHex(s.publicKey);
    if (!perAddress_.allow(address, now) || !perKey_.allow(keyHex, now)) {
        Answer a = errorAnswer(429, "rate-limited",
                               "too many runs in the last minute from this key or address; at most " +
                                   std::to_string(limits_.runsPerKeyPerMinute) + " a key and " +
                                   std::to_string(limits_.runsPerAddressPerMinute) + " an address");
        a.retryAfterSeconds = 60;
        return a;
    }
    const std::string bytesHash = sha256Hex(s.replay);
    if (!signatureValid(s.publicKey, s.signature, signedMessage(s.name, bytesHash, s.token)))
        return errorAnswer(
            403, "bad-signature",
            "the signature is not this key's over the name, the replay's SHA-256 and the token");
    if (std::optional<std::string> owner = storage_.nameOwner(s.name); owner && *owner != keyHex)
        return errorAnswer(403, "name-taken", "the name " + s.name + " belongs to another key");
    std::optional<std::int64_t> issued;
    if (!s.token.empty()) {
        issued = storage_.tokenIssued(s.token);
        if (!issued || now - *issued > limits_.tokenLifetimeMs)
            return errorAnswer(
                403, "bad-token",
                "the run token is unknown, used or expired; expected one from POST /v1/tokens, used once");
    }

    std::optional<std::future<Verdict>> queued = pool_.submit(s.replay);
    if (!queued) {
        Answer a = errorAnswer(503, "busy", "the verification queue is full; try again later");
        a.retryAfterSeconds = limits_.retryAfterSeconds;
        return a;
    }
    const Verdict v = queued->get();
    if (!v.refusal.empty()) return errorAnswer(422, v.refusal, v.reason);
    if (storage_.hasRun(v.runHash))
        return errorAnswer(409, "duplicate",
                           "this run (the same scene, seed, rules and inputs) is stored already");
    if (issued) {
        // The run's ticks need ticks / tick rate seconds of play; a token issued more recently than
        // that (with the tolerance) means the run was made faster than real time.
        const double playedMs = static_cast<double>(v.ticks) / v.tickRate * 1000.0 * limits_.tokenTolerance;
        const std::int64_t elapsed = clock_() - *issued;
        if (static_cast<double>(elapsed) < playedMs)
            return errorAnswer(422, "too-fast",
                               "the run's " + std::to_string(v.ticks) + " ticks need " +
                                   std::to_string(static_cast<std::int64_t>(playedMs)) +
                                   " ms of play, but its token was issued " + std::to_string(elapsed) +
                                   " ms ago");
    }

    RunRecord run;
    run.name = s.name;
    run.publicKey = keyHex;
    run.scene = v.scene;
    run.mode = v.mode;
    run.rules = v.rules;
    run.speed = v.speed;
    run.seed = v.seed;
    run.score = v.score;
    run.wave = v.wave;
    run.ticks = v.ticks;
    run.ranked = issued.has_value();
    run.submittedMs = now;
    run.runHash = v.runHash;
    run.bytesHash = bytesHash;
    run.replay = s.replay;
    std::int64_t id = 0;
    switch (storage_.store(run, s.token, id)) {
        case StoreOutcome::kStored:
            break;
        case StoreOutcome::kDuplicate:
            return errorAnswer(409, "duplicate",
                               "this run (the same scene, seed, rules and inputs) is stored already");
        case StoreOutcome::kNameTaken:
            return errorAnswer(403, "name-taken", "the name " + s.name + " belongs to another key");
        case StoreOutcome::kTokenUsed:
            return errorAnswer(403, "bad-token", "the run token was used by another run");
    }
    run.id = id;
    BoardQuery board{run.scene, run.mode, run.ranked, 0, 1, 1};
    const std::int64_t rank = *storage_.bestRank(board, run.name);
    board.sinceMs = seasonStart(Season::kWeek, now);
    const std::int64_t weekRank = *storage_.bestRank(board, run.name);
    JsonWriter out;
    out.beginObject().member("verdict", "verified");
    writeRunMembers(out, run);
    out.member("rank", rank).member("rank_week", weekRank).endObject();
    return Answer{201, out.text(), 0};
}

Answer Service::page(const BoardQuery& query, Season season, const BoardPage& page, const std::string& name,
                     std::int64_t rank) const {
    JsonWriter out;
    out.beginObject()
        .member("scene", query.scene)
        .member("mode", query.mode)
        .member("season", seasonWord(season))
        .member("ranked", query.ranked)
        .member("from", query.from)
        .member("count", query.count)
        .member("total", page.total);
    if (!name.empty()) out.member("name", name).member("rank", rank);
    out.key("previous");
    if (query.from > 1)
        out.value(std::max<std::int64_t>(1, query.from - query.count));
    else
        out.null();
    out.key("next");
    if (query.from + query.count <= page.total)
        out.value(query.from + query.count);
    else
        out.null();
    out.key("runs").beginArray();
    for (const BoardEntry& entry : page.entries) {
        out.beginObject();
        writeRunMembers(out, entry.run);
        out.member("rank", entry.rank).endObject();
    }
    out.endArray().endObject();
    return Answer{200, out.text(), 0};
}

Answer Service::top(BoardQuery query, Season season) {
    query.sinceMs = seasonStart(season, clock_());
    return page(query, season, storage_.top(query));
}

Answer Service::around(BoardQuery query, Season season, const std::string& name) {
    query.sinceMs = seasonStart(season, clock_());
    std::optional<std::int64_t> rank = storage_.bestRank(query, name);
    if (!rank) return errorAnswer(404, "no-run", "no run of " + name + " on this board");
    query.from = std::max<std::int64_t>(1, *rank - query.count / 2);
    return page(query, season, storage_.top(query), name, *rank);
}

Answer Service::playerBest(const std::string& name) {
    std::vector<RunRecord> runs = storage_.playerBest(name);
    if (runs.empty()) return errorAnswer(404, "no-run", "no run of " + name);
    JsonWriter out;
    out.beginObject().member("name", name).key("runs").beginArray();
    for (const RunRecord& run : runs) {
        out.beginObject();
        writeRunMembers(out, run);
        out.endObject();
    }
    out.endArray().endObject();
    return Answer{200, out.text(), 0};
}

Answer Service::run(std::int64_t id) {
    std::optional<RunRecord> run = storage_.run(id, false);
    if (!run) return errorAnswer(404, "no-run", "no run " + std::to_string(id));
    JsonWriter out;
    out.beginObject();
    writeRunMembers(out, *run);
    out.endObject();
    return Answer{200, out.text(), 0};
}

std::optional<std::string> Service::replay(std::int64_t id) {
    std::optional<RunRecord> run = storage_.run(id, true);
    if (!run) return std::nullopt;
    return run->replay;
}

}  // namespace polar::server
