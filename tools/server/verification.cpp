#include "verification.h"

#include <time.h>

#include <cstdio>

#include "files/assets.h"
#include "replay/replay.h"
#include "signature.h"

namespace polar::server {
namespace {

using namespace polar::game;

Verdict refuse(std::string refusal, std::string reason) {
    Verdict v;
    v.refusal = std::move(refusal);
    v.reason = std::move(reason);
    return v;
}

// CPU seconds this thread has used.
double threadCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

std::string hex64(std::uint64_t v) {
    char text[20];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(v));
    return text;
}

// Line `number` (1-based) of `text`, or "".
std::string lineOf(std::string_view text, int number) {
    for (int n = 1; n < number && !text.empty(); ++n) {
        std::size_t end = text.find('\n');
        text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
    }
    return number > 0 ? std::string(text.substr(0, text.find('\n'))) : "";
}

std::string runHashOf(const Replay& replay, std::uint64_t sceneHash) {
    const ReplayHeader& h = replay.header;
    std::string identity = "scene " + h.scene + " " + hex64(sceneHash) + "\nseed " + std::to_string(h.seed) +
                           "\nrules " + std::to_string(h.rules) + "\nspeed " + std::to_string(h.speed) + "\n";
    identity.append(reinterpret_cast<const char*>(replay.actions.data()), replay.actions.size());
    return sha256Hex(identity);
}

}  // namespace

ServerGames serverGames(const std::string& assetRoot) {
    ServerGames games;
    games.assetRoot = assetRoot;
    AssetFs assets(assetRoot);
    FileReader read = assets.reader();
    for (const std::string& scene : assets.list("scenes")) {
        if (!scene.ends_with(".json")) continue;
        if (std::optional<SourceFile> file = read(scene)) games.scenes[scene] = stampHash(file->text);
    }
    return games;
}

std::string boardMode(int rules, int speed) {
    std::string mode = "rules-" + std::to_string(rules);
    if (speed != kMaxGameSpeed) mode += "-speed-" + std::to_string(speed);
    return mode;
}

std::string defaultMode() {
    return boardMode(kRulesVersion, kMaxGameSpeed);
}

Verdict verifyRun(std::string_view replayText, const ServerGames& games) {
    Result<Replay> parsed = parseReplay("submitted.replay", replayText);
    if (!parsed) {
        // A line the parser refuses that names the game or rules version (rules newer than this
        // build knows) is a version this server does not run, not a damaged file.
        const std::string line = lineOf(replayText, parsed.error().line);
        const bool version = line.starts_with("game ") || line.starts_with("rules ");
        return refuse(version ? "version" : "unreadable", parsed.error().message());
    }
    const Replay& replay = *parsed;
    const ReplayHeader& h = replay.header;
    if (h.gameVersion != gameVersion())
        return refuse("version", "the replay was recorded by game version " + h.gameVersion +
                                     "; this server runs version " + gameVersion());
    if (h.rules < 1 || h.rules > kRulesVersion)
        return refuse("version", "the replay plays by rules " + std::to_string(h.rules) +
                                     "; this server runs rules 1 to " + std::to_string(kRulesVersion));
    if (!h.mods.empty())
        return refuse("mods", "the replay was recorded with mods (" + h.mods.front() +
                                  "); this server holds only the game's own files");
    auto scene = games.scenes.find(h.scene);
    if (h.sceneIsFile || scene == games.scenes.end())
        return refuse("scene", "the scene " + h.scene + " is not one of this server's scenes");
    bool stamped = false;
    for (const AssetStamp& stamp : h.assets) {
        if (stamp.name != h.scene) continue;
        stamped = true;
        if (stamp.hash != scene->second)
            return refuse("scene", "the replay's " + h.scene + " (hash " + hex64(stamp.hash) +
                                       ") is not this server's (hash " + hex64(scene->second) + ")");
    }
    if (!stamped) return refuse("scene", "the replay does not record the hash of its scene " + h.scene);
    // A run played with a stronger ship is another game.
    if (std::string field = firstTuningDifference(h.tuning, Tuning{}); !field.empty())
        return refuse("tuning", "the replay's tuning differs from the game's in " + field);
    if (std::optional<Error> incomplete = missingEnd(replay))
        return refuse("incomplete", incomplete->message());
    if (replay.actions.size() > games.maxTicks)
        return refuse("too-long", "the replay has " + std::to_string(replay.actions.size()) +
                                      " ticks; this server verifies at most " +
                                      std::to_string(games.maxTicks));
    if (replay.checkpoints.empty() || replay.trace.empty())
        return refuse("unverifiable",
                      "the replay has no checkpoints or no trace; expected a recorded replay");

    AssetFs assets(games.assetRoot);
    Result<ReplayPlayer> player = ReplayPlayer::start(replay, assets);
    if (!player) return refuse("scene", player.error().message());
    const double start = threadCpuSeconds();
    while (!player->done()) {
        if (std::optional<Desync> desync = player->step())
            return refuse(desync->kind == Desync::Kind::kGame ? "desync" : "damaged",
                          describe(*desync, "submitted.replay"));
        if (player->game().tickCount() % kCheckpointInterval == 0 &&
            threadCpuSeconds() - start > games.cpuSeconds)
            return refuse("cpu-limit", "verifying took more than " + std::to_string(games.cpuSeconds) +
                                           " s of CPU time; this server stops there");
    }
    Verdict v;
    const Game& game = player->game();
    v.score = game.score();
    v.wave = game.wave();
    v.ticks = game.tickCount();
    v.tickRate = h.tuning.tickRate;
    v.scene = h.scene;
    v.rules = h.rules;
    v.speed = h.speed;
    v.mode = boardMode(h.rules, h.speed);
    v.seed = h.seed;
    v.runHash = runHashOf(replay, scene->second);
    return v;
}

}  // namespace polar::server
