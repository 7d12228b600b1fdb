#include "replay/replay_verify.h"

#include <algorithm>
#include <string>
#include <tuple>
#include <utility>
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
        case Kind::Foe:
            return "foe";
        case Kind::FoeShot:
            return "foe shot";
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

std::string hex4(std::uint16_t v) {
    return hex64(v).substr(12);
}

// A trace token as the file writes it: two characters of the trace alphabet.
std::string token(std::uint16_t v) {
    return {detail::kTraceAlphabet[(v >> 6) & 63], detail::kTraceAlphabet[v & 63]};
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
    while (expected.hasObjects && (i < e.size() || j < a.size())) {
        if (j == a.size() || (i < e.size() && e[i].id < a[j].id)) {
            onlyRecorded.push_back("#" + std::to_string(e[i++].id));
        } else if (i == e.size() || a[j].id < e[i].id) {
            onlyHere.push_back(label(game, a[j++].id));
        } else {
            if (e[i].digest != a[j].digest)
                differ.push_back(label(game, a[j].id) + " (digest: expected " + hex4(e[i].digest) +
                                 ", actual " + hex4(a[j].digest) + ")");
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

// The first value of `recorded` that differs from `actual`: its name and where it is written (the
// check line's first column when it is not written).
struct DifferingValue {
    std::string name;
    int line = 0, column = 0;
};
DifferingValue firstDifferingValue(const Checkpoint& recorded, const Checkpoint& actual) {
    const Checkpoint::Columns& at = recorded.columns;
    if (recorded.hash != actual.hash) return {"state hash", recorded.line, at.hash};
    if (recorded.rng != actual.rng) return {"rng state", recorded.line, at.rng};
    if (recorded.score != actual.score) return {"score", recorded.line, at.score};
    if (recorded.lives != actual.lives) return {"lives", recorded.line, at.lives};
    if (recorded.wave != actual.wave) return {"wave", recorded.line, at.wave};
    for (std::size_t i = 0; recorded.hasObjects && i < recorded.objects.size(); ++i) {
        const ObjectDigest& object = recorded.objects[i];
        auto same = std::find_if(actual.objects.begin(), actual.objects.end(),
                                 [&](const ObjectDigest& o) { return o.id == object.id; });
        if (same != actual.objects.end() && *same == object) continue;
        const int column = i < recorded.objectColumns.size() ? recorded.objectColumns[i] : 1;
        return {same == actual.objects.end()
                    ? "object " + std::to_string(object.id) + ", which the game lacks,"
                    : "digest of object " + std::to_string(object.id),
                recorded.objectsLine, column};
    }
    return {"objects (one the recording lacks)", recorded.objectsLine ? recorded.objectsLine : recorded.line,
            1};
}

// Whether the game's checkpoint has every value recorded (the objects only when they were).
bool sameValues(const Checkpoint& recorded, const Checkpoint& actual) {
    return recorded.hash == actual.hash && recorded.rng == actual.rng && recorded.score == actual.score &&
           recorded.lives == actual.lives && recorded.wave == actual.wave &&
           (!recorded.hasObjects || recorded.objects == actual.objects);
}

}  // namespace

const char* kindWord(Desync::Kind kind) {
    switch (kind) {
        case Desync::Kind::kGame:
            return "desync";
        case Desync::Kind::kTrace:
            return "damaged trace";
        case Desync::Kind::kCheckpoint:
            return "damaged checkpoint";
    }
    return "desync";
}

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
    if (d.line > 0) out += ":" + std::to_string(d.line) + ":" + std::to_string(std::max(d.column, 1));
    out += std::string(": ") + kindWord(d.kind) + ": ";
    const std::string checkpoint =
        "the checkpoint after tick " + std::to_string(d.checkpointTick) +
        (d.checkpointLine ? " (line " + std::to_string(d.checkpointLine) + ")" : "");
    switch (d.kind) {
        case Desync::Kind::kGame:
            if (d.traced)
                out += "the game first differs after tick " + std::to_string(d.firstTick) +
                       (d.line && d.line != d.checkpointLine ? ", whose input is here" : "");
            else
                out += "the game differs at the checkpoint after tick " + std::to_string(d.checkpointTick) +
                       " (no per-tick trace: it first differs somewhere in ticks " +
                       std::to_string(d.firstTick) + "-" + std::to_string(d.checkpointTick) + ")";
            out += "; expected the recorded game\n";
            break;
        case Desync::Kind::kTrace:
            out += "the token of tick " + std::to_string(d.firstTick) + " is \"" + token(d.traceExpected) +
                   "\" but the game gives \"" + token(d.traceActual) + "\"";
            if (d.tokensDiffering > 1)
                out += " (the first of " + std::to_string(d.tokensDiffering) + " tokens that differ)";
            out += d.checkpointTick ? ", and the game matches " + checkpoint +
                                          ": the trace line is damaged, "
                                          "the game is not at fault"
                                    : ", and every later token matches (no checkpoint follows): the trace "
                                      "line is damaged, or the game differed for that tick only";
            out += "; expected the trace the game was recorded with\n";
            break;
        case Desync::Kind::kCheckpoint:
            out += d.expected != d.actual
                       ? checkpoint +
                             " disagrees with the per-tick trace, which matched every tick: the "
                             "checkpoint line is damaged or was edited, the game is not at fault"
                       : checkpoint + " has the game's state hash, but its " + d.value +
                             " differs: the line is damaged or was edited, the game is not at fault";
            out += "; expected the values the game was recorded with\n";
            break;
    }
    if (d.kind == Desync::Kind::kGame && d.traced)
        out += "  trace token of tick " + std::to_string(d.firstTick) + ": expected \"" +
               token(d.traceExpected) + "\", actual \"" + token(d.traceActual) + "\"\n";
    if (d.checkpointTick) {
        out += "  " + checkpoint + ": expected state hash " + hex64(d.expected) + ", actual " +
               hex64(d.actual) + "\n";
        if (d.kind == Desync::Kind::kGame && d.expected == d.actual)
            out += "  (the state differed from tick " + std::to_string(d.firstTick) +
                   " on but is the same again here)\n";
    } else {
        out += "  the replay ends before its next checkpoint, so no objects can be compared\n";
    }
    for (const std::string& line : d.differences) out += "  " + line + "\n";
    if (d.kind == Desync::Kind::kGame && d.traced && d.firstTick == 1) {
        std::string lines;
        for (const auto& [name, line] : {std::pair<const char*, int>{"seed", d.seedLine},
                                         {"tick-rate", d.tickRateLine},
                                         {"tuning", d.tuningLine}})
            if (line)
                lines += (lines.empty() ? "" : ", ") + std::string(name) + " on line " + std::to_string(line);
        out +=
            "  it differs from the very first tick: unless the game's start changed, look at the header (" +
            (lines.empty() ? std::string("seed, tick-rate, tuning") : lines) + ")\n";
    }
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
            if (i < stamps.size() && i < h.assets.size() && stamps[i].hash == h.assets[i].hash &&
                stamps[i].name == h.assets[i].name)
                continue;
            int line = i < h.assets.size() ? h.assets[i].line : h.assets.back().line;
            std::string what =
                i >= h.assets.size()
                    ? "the game now also reads " + stamps[i].name + ", which the recording did not"
                : i >= stamps.size()
                    ? "the recording read " + h.assets[i].name + ", which the game no longer does"
                : stamps[i].name != h.assets[i].name
                    ? "the game reads " + stamps[i].name + " here, where the recording read " +
                          h.assets[i].name
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

Desync ReplayPlayer::differs(Desync::Kind kind, const Checkpoint* expected, const Checkpoint* actual) const {
    const Replay& r = *replay_;
    Desync d;
    d.kind = kind;
    d.traced = firstDiffers_.has_value();
    d.firstTick =
        firstDiffers_.value_or(kind == Desync::Kind::kCheckpoint ? game_.tickCount() : lastMatched_ + 1);
    if (firstDiffers_) {
        d.traceExpected = r.trace[*firstDiffers_ - 1];
        d.traceActual = traceActual_;
        d.tokensDiffering = differing_;
    }
    d.seedLine = r.header.seedLine;
    d.tickRateLine = r.header.tickRateLine;
    d.tuningLine = r.header.tuningLine;
    if (expected && actual) {
        d.checkpointTick = expected->tick;
        d.checkpointLine = expected->line;
        d.expected = expected->hash;
        d.actual = actual->hash;
        d.differences = differences(*expected, *actual, game_, kind == Desync::Kind::kGame);
    }
    // Where the report points.
    std::optional<TickPlace> place;
    if (kind == Desync::Kind::kGame && firstDiffers_) place = placeOf(r.inputPlaces, *firstDiffers_);
    if (kind == Desync::Kind::kTrace) place = placeOf(r.tracePlaces, *firstDiffers_);
    if (place) {
        d.line = place->line;
        d.column = place->column;
    } else if (kind == Desync::Kind::kCheckpoint && expected && actual) {
        DifferingValue value = firstDifferingValue(*expected, *actual);
        d.value = value.name;
        d.line = value.line;
        d.column = value.column;
    } else if (expected) {
        d.line = expected->line;
        d.column = expected->columns.hash;
    }
    return d;
}

std::optional<Desync> ReplayPlayer::step() {
    const Replay& r = *replay_;
    if (done()) return std::nullopt;
    game_.tick(r.actions[game_.tickCount()]);
    const std::uint64_t t = game_.tickCount();
    if (t <= r.trace.size()) {
        const std::uint16_t now = traceOf(game_.hash());
        if (now != r.trace[t - 1]) {
            if (!firstDiffers_) firstDiffers_ = t, traceActual_ = now;
            if (lastDiffers_ != 0 && lastDiffers_ + 1 == t) twoInARow_ = true;
            lastDiffers_ = t;
            ++differing_;
        } else if (firstDiffers_) {
            ++matchedAfter_;
        }
    }
    if (nextCheckpoint_ < r.checkpoints.size() && r.checkpoints[nextCheckpoint_].tick == t) {
        const Checkpoint& expected = r.checkpoints[nextCheckpoint_++];
        Checkpoint actual = checkpointOf(game_);
        const bool sameHash = actual.hash == expected.hash;
        if (firstDiffers_)  // the checkpoint's full hash decides between the game and the trace
            return differs(sameHash && !twoInARow_ ? Desync::Kind::kTrace : Desync::Kind::kGame, &expected,
                           &actual);
        if (sameHash && sameValues(expected, actual)) {
            ++matched_;
            lastMatched_ = t;
            return std::nullopt;
        }
        // The trace matched up to here, or the hash itself matched: the checkpoint line is at fault.
        const bool lineDamaged = sameHash || t <= r.trace.size();
        return differs(lineDamaged ? Desync::Kind::kCheckpoint : Desync::Kind::kGame, &expected, &actual);
    }
    if (done() && firstDiffers_)
        return differs(matchedAfter_ > 0 && !twoInARow_ ? Desync::Kind::kTrace : Desync::Kind::kGame, nullptr,
                       nullptr);
    return std::nullopt;
}

void ReplayPlayer::mark(Mark& out) const {
    game_.save(out.game);
    out.nextCheckpoint = nextCheckpoint_;
    out.matched = matched_;
    out.lastMatched = lastMatched_;
    out.firstDiffers = firstDiffers_;
    out.traceActual = traceActual_;
    out.differing = differing_;
    out.matchedAfter = matchedAfter_;
    out.lastDiffers = lastDiffers_;
    out.twoInARow = twoInARow_;
}

std::optional<Error> ReplayPlayer::resume(const Mark& mark) {
    if (std::optional<Error> error = game_.restore(mark.game)) return error;
    nextCheckpoint_ = mark.nextCheckpoint;
    matched_ = mark.matched;
    lastMatched_ = mark.lastMatched;
    firstDiffers_ = mark.firstDiffers;
    traceActual_ = mark.traceActual;
    differing_ = mark.differing;
    matchedAfter_ = mark.matchedAfter;
    lastDiffers_ = mark.lastDiffers;
    twoInARow_ = mark.twoInARow;
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
