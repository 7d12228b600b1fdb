#include "replay/replay_verify.h"

#include <algorithm>
#include <string>
#include <vector>

#include "polar/state_hash.h"
#include "polar/world_hash.h"
#include "replay/replay_game.h"
#include "replay/replay_text.h"

namespace polar::game {
namespace {

using detail::hex64;

const char* kindName(Kind kind) {
    switch (kind) {
        case Kind::Arena:
            return "arena";
        case Kind::Ship:
            return "ship";
        case Kind::Rock:
            return "rock";
        case Kind::Bullet:
            return "bullet";
        case Kind::Pickup:
            return "pickup";
        case Kind::Comet:
            return "comet";
        case Kind::Scenery:
            return "scenery";
    }
    return "object";
}

std::uint16_t digestOf(const Game& game, const GameObject& object) {
    StateHash h;
    h.add(objectHash(object));
    h.add(static_cast<int>(game.kindOf(object.id)));
    h.add(game.rockSize(object.id));
    return static_cast<std::uint16_t>(h.value() >> 48);
}

std::string label(const Game& game, ObjectId id) {
    const GameObject* object = game.world().find(id);
    std::string out = "#" + std::to_string(id);
    if (!object) return out;
    Kind kind = game.kindOf(id);
    out += " " + object->name + " (" + kindName(kind);
    if (kind == Kind::Rock) out += ", size " + std::to_string(game.rockSize(id));
    return out + ")";
}

std::string joinList(const std::vector<std::string>& items) {
    constexpr std::size_t kShown = 12;
    std::string out;
    for (std::size_t i = 0; i < items.size() && i < kShown; ++i) out += (i ? ", " : "") + items[i];
    if (items.size() > kShown) out += " and " + std::to_string(items.size() - kShown) + " more";
    return out;
}

std::vector<std::string> differences(const Checkpoint& expected, const Checkpoint& actual, const Game& game,
                                     bool explainHidden) {
    std::vector<std::string> out;
    auto counter = [&](const char* name, long long e, long long a) {
        if (e != a)
            out.push_back(std::string(name) + ": expected " + std::to_string(e) + ", actual " +
                          std::to_string(a));
    };
    counter("score", expected.score, actual.score);
    counter("lives", expected.lives, actual.lives);
    counter("wave", expected.wave, actual.wave);
    if (expected.rng != actual.rng)
        out.push_back("rng state: expected " + hex64(expected.rng) + ", actual " + hex64(actual.rng));
    std::vector<std::string> differ, onlyRecorded, onlyHere;
    std::size_t i = 0, j = 0;
    const auto& e = expected.objects;
    const auto& a = actual.objects;
    while (i < e.size() || j < a.size()) {
        if (j == a.size() || (i < e.size() && e[i].id < a[j].id)) {
            onlyRecorded.push_back("#" + std::to_string(e[i++].id));
        } else if (i == e.size() || a[j].id < e[i].id) {
            onlyHere.push_back(label(game, a[j++].id));
        } else {
            if (e[i].digest != a[j].digest) differ.push_back(label(game, a[j].id));
            ++i, ++j;
        }
    }
    if (!differ.empty()) out.push_back("objects that differ: " + joinList(differ));
    if (!onlyRecorded.empty()) out.push_back("objects only in the recording: " + joinList(onlyRecorded));
    if (!onlyHere.empty()) out.push_back("objects only in this run: " + joinList(onlyHere));
    if (out.empty() && expected.hash != actual.hash && explainHidden)
        out.push_back(
            "no object or counter differs: the difference is in the game's timers or bookkeeping "
            "(fire cooldown, respawn, wave and comet timers, bullet and pickup lives)");
    return out;
}

}  // namespace

Checkpoint checkpointOf(const Game& game) {
    Checkpoint c;
    c.tick = game.tickCount();
    c.hash = game.hash();
    c.rng = game.rng().state();
    c.score = game.score();
    c.lives = game.lives();
    c.wave = game.wave();
    c.objects.reserve(game.world().objects().size());
    for (const GameObject& object : game.world().objects())
        c.objects.push_back({object.id, digestOf(game, object)});
    return c;
}

std::string describe(const Desync& d, const std::string& path) {
    std::string out = path;
    if (d.line > 0) out += ":" + std::to_string(d.line) + ":1";
    out += ": desync: ";
    if (d.traced) {
        out += "the game first differs after tick " + std::to_string(d.firstTick);
    } else if (d.traceAgrees) {
        out += "the checkpoint after tick " + std::to_string(d.checkpointTick) +
               " disagrees with the per-tick trace, which matched every tick: the checkpoint line is "
               "damaged or was edited, the game is not at fault";
    } else {
        out += "the game differs at the checkpoint after tick " + std::to_string(d.checkpointTick) +
               " (no per-tick trace: it first differs somewhere in ticks " + std::to_string(d.firstTick) +
               "-" + std::to_string(d.checkpointTick) + ")";
    }
    out += "; expected the recorded game\n";
    if (d.checkpointTick) {
        out += "  checkpoint after tick " + std::to_string(d.checkpointTick) + ": expected state hash " +
               hex64(d.expected) + ", actual " + hex64(d.actual) + "\n";
        if (d.expected == d.actual)
            out += "  (the state differed from tick " + std::to_string(d.firstTick) +
                   " on but is the same again here)\n";
    } else {
        out += "  the replay ends before its next checkpoint, so no objects can be compared\n";
    }
    for (const std::string& line : d.differences) out += "  " + line + "\n";
    return out;
}

Result<ReplayPlayer> ReplayPlayer::start(const Replay& replay, const AssetFs& assets,
                                         const StepThreads& threads) {
    const ReplayHeader& h = replay.header;
    Game::Config config = configFor(replay, assets);
    config.threads = threads;
    std::string mods = h.mods.empty() ? std::string("no mods") : "mods " + joinList(h.mods);
    if (!assets.resolve(config.scene))
        return Error{replay.path, h.sceneLine, 1,
                     "the recorded scene " + h.scene + " is not here (it was recorded with " + mods + ")",
                     h.sceneIsFile ? "the scene file next to the replay, where it was when recorded"
                                   : "that scene in assets/ or a mod folder given with --mod"};
    std::vector<AssetStamp> stamps;
    Result<Game> game = createStampedGame(config, &assets, replay.path, stamps);
    if (!game)
        return Error{replay.path, h.sceneLine, 1, "the recorded game cannot start: " + game.error().message(),
                     "the scene and bounds files it was recorded with (" + mods + ")"};
    if (!h.assets.empty()) {
        for (std::size_t i = 0; i < std::max(stamps.size(), h.assets.size()); ++i) {
            if (i < stamps.size() && i < h.assets.size() && stamps[i].hash == h.assets[i].hash) continue;
            int line = i < h.assets.size() ? h.assets[i].line : h.assets.back().line;
            std::string what =
                i >= h.assets.size()
                    ? "the game now also reads " + stamps[i].name + ", which the recording did not"
                : i >= stamps.size()
                    ? "the recording read " + h.assets[i].name + ", which the game no longer does"
                    : stamps[i].name + " is not the file this replay was recorded with (hash " +
                          hex64(stamps[i].hash) + ", recorded " + hex64(h.assets[i].hash) + ")";
            return Error{
                replay.path, line, 1, what,
                "the same scene and bounds files (it was recorded with " + mods +
                    "); after an intended change, re-record the replay or run polarcade-replay --update"};
        }
    }
    return ReplayPlayer(replay, std::move(*game));
}

std::optional<Desync> ReplayPlayer::step() {
    const Replay& r = *replay_;
    if (done()) return std::nullopt;
    game_.tick(r.actions[game_.tickCount()]);
    const std::uint64_t t = game_.tickCount();
    if (!firstDiffers_ && t <= r.trace.size() && traceOf(game_.hash()) != r.trace[t - 1]) firstDiffers_ = t;
    if (nextCheckpoint_ < r.checkpoints.size() && r.checkpoints[nextCheckpoint_].tick == t) {
        const Checkpoint& expected = r.checkpoints[nextCheckpoint_++];
        Checkpoint actual = checkpointOf(game_);
        if (actual.hash == expected.hash && !firstDiffers_) {
            ++matched_;
            lastMatched_ = t;
            return std::nullopt;
        }
        Desync d;
        d.traced = firstDiffers_.has_value();
        d.traceAgrees = !firstDiffers_ && t <= r.trace.size();
        d.firstTick = firstDiffers_.value_or(d.traceAgrees ? t : lastMatched_ + 1);
        d.checkpointTick = t;
        d.line = expected.line;
        d.expected = expected.hash;
        d.actual = actual.hash;
        d.differences = differences(expected, actual, game_, !d.traceAgrees);
        return d;
    }
    if (done() && firstDiffers_) {
        Desync d;
        d.traced = true;
        d.firstTick = *firstDiffers_;
        return d;
    }
    return std::nullopt;
}

void ReplayPlayer::mark(Mark& out) const {
    game_.save(out.game);
    out.nextCheckpoint = nextCheckpoint_;
    out.matched = matched_;
    out.lastMatched = lastMatched_;
    out.firstDiffers = firstDiffers_;
}

std::optional<Error> ReplayPlayer::resume(const Mark& mark) {
    if (std::optional<Error> error = game_.restore(mark.game)) return error;
    nextCheckpoint_ = mark.nextCheckpoint;
    matched_ = mark.matched;
    lastMatched_ = mark.lastMatched;
    firstDiffers_ = mark.firstDiffers;
    return std::nullopt;
}

Result<Verification> verifyReplay(const Replay& replay, const AssetFs& assets, const StepThreads& threads) {
    Result<ReplayPlayer> player = ReplayPlayer::start(replay, assets, threads);
    if (!player) return player.error();
    Verification v;
    while (!player->done()) {
        std::optional<Desync> desync = player->step();
        if (desync) {
            v.desync = std::move(desync);
            break;
        }
    }
    v.ticks = player->game().tickCount();
    v.checkpoints = player->checkpointsMatched();
    return v;
}

}  // namespace polar::game
