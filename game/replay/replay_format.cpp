#include "replay/replay_format.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <iterator>
#include <span>
#include <string>

#include "polarcade_version.h"
#include "replay/double_text.h"
#include "replay/replay_text.h"

namespace polar::game {
namespace detail {
namespace {

std::string hex16(std::uint16_t v) {
    char buffer[5];
    std::snprintf(buffer, sizeof buffer, "%04x", static_cast<unsigned>(v));
    return buffer;
}

// The shortest text that reads back as exactly the same double.
std::string exactDouble(double v) {
    return shortestDouble(v);
}

std::string actionLetters(Actions actions) {
    std::string out;
    for (const auto& [letter, bit] : kActionLetters)
        if (actions & bit) out += letter;
    return out.empty() ? "." : out;
}

}  // namespace

std::string hex64(std::uint64_t v) {
    char buffer[17];
    std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(v));
    return buffer;
}

void appendInputs(std::string& out, std::span<const Actions> actions) {
    if (actions.empty()) return;
    out += "in";
    for (std::size_t i = 0; i < actions.size();) {
        std::size_t j = i;
        while (j < actions.size() && actions[j] == actions[i]) ++j;
        out += ' ';
        out += actionLetters(actions[i]);
        if (j - i > 1) out += '*' + std::to_string(j - i);
        i = j;
    }
    out += '\n';
}

void appendTrace(std::string& out, std::span<const std::uint16_t> trace) {
    if (trace.empty()) return;
    out += "trace ";
    for (std::uint16_t v : trace) {
        out += kTraceAlphabet[(v >> 6) & 63];
        out += kTraceAlphabet[v & 63];
    }
    out += '\n';
}

void appendCheckpoint(std::string& out, const Checkpoint& c) {
    out += "check " + std::to_string(c.tick) + ' ' + hex64(c.hash) + " rng=" + hex64(c.rng) +
           " score=" + std::to_string(c.score) + " lives=" + std::to_string(c.lives) +
           " wave=" + std::to_string(c.wave) + '\n';
    out += "objects";
    for (const ObjectDigest& o : c.objects) out += ' ' + std::to_string(o.id) + ':' + hex16(o.digest);
    out += '\n';
}

std::string headerText(const ReplayHeader& h) {
    std::string out = std::string(kMagic) + ' ' + std::to_string(kReplayFormat) + '\n';
    for (const std::string& comment : h.comments) out += comment + '\n';
    out += "game " + h.gameVersion + '\n';
    out += (h.sceneIsFile ? "scene-file " : "scene ") + h.scene + '\n';
    out += "seed " + std::to_string(h.seed) + '\n';
    out += "tick-rate " + exactDouble(h.tuning.tickRate) + '\n';
    out += "tuning";
    for (const TuningField& f : kTuningFields)
        out += std::string(" ") + f.name + '=' +
               (f.real ? exactDouble(h.tuning.*f.real) : std::to_string(h.tuning.*f.whole));
    out += '\n';
    // Written only when they differ from what a file without them means, so an older replay is
    // written back exactly as it was.
    if (h.rules != 1) out += "rules " + std::to_string(h.rules) + '\n';
    if (h.speed != kMaxGameSpeed) out += "speed " + std::to_string(h.speed) + '\n';
    for (const std::string& mod : h.mods) out += "mod " + mod + '\n';
    for (const AssetStamp& a : h.assets) out += "asset " + hex64(a.hash) + ' ' + a.name + '\n';
    for (const ReplayScreenshot& s : h.screenshots)
        out += "screenshot " + std::to_string(s.tick) + ':' + s.png + '\n';
    return out + "begin\n";
}

}  // namespace detail

using detail::appendCheckpoint;
using detail::appendInputs;
using detail::appendTrace;
using detail::headerText;

const char* gameVersion() {
    return kPolarcadeVersion;
}

bool isEndReason(std::string_view reason) {
    return std::any_of(std::begin(kEndReasons), std::end(kEndReasons),
                       [&](const char* known) { return reason == known; });
}

std::optional<TickPlace> placeOf(const std::vector<TickPlace>& places, std::uint64_t tick) {
    auto after = std::upper_bound(places.begin(), places.end(), tick,
                                  [](std::uint64_t t, const TickPlace& p) { return t < p.firstTick; });
    if (after == places.begin()) return std::nullopt;
    TickPlace place = *std::prev(after);
    place.column += place.columnsPerTick * static_cast<int>(tick - place.firstTick);
    place.firstTick = tick;
    return place;
}

std::string firstTuningDifference(const Tuning& a, const Tuning& b) {
    if (a.tickRate != b.tickRate) return "tick-rate";
    for (const detail::TuningField& f : detail::kTuningFields) {
        if (f.real && a.*f.real != b.*f.real) return f.name;
        if (f.whole && a.*f.whole != b.*f.whole) return f.name;
    }
    return "";
}

std::string formatReplay(const Replay& replay) {
    std::string out = headerText(replay.header);
    const std::uint64_t total = replay.actions.size();
    std::span<const Actions> actions(replay.actions);
    std::span<const std::uint16_t> trace(replay.trace);
    std::uint64_t pos = 0;
    std::size_t next = 0;
    // The same pieces the writer makes: a segment every kCheckpointInterval ticks and one at each
    // checkpoint.
    while (pos < total) {
        std::uint64_t checkpoint =
            next < replay.checkpoints.size() ? replay.checkpoints[next].tick : total + 1;
        std::uint64_t to =
            std::min({checkpoint, (pos / kCheckpointInterval + 1) * kCheckpointInterval, total});
        appendInputs(out, actions.subspan(pos, to - pos));
        if (pos < trace.size())
            appendTrace(out, trace.subspan(pos, std::min<std::uint64_t>(to, trace.size()) - pos));
        if (checkpoint == to) appendCheckpoint(out, replay.checkpoints[next++]);
        pos = to;
    }
    if (replay.end) out += "end " + std::to_string(replay.end->tick) + ' ' + replay.end->reason + '\n';
    return out;
}

}  // namespace polar::game
