#include "app/theatre/replay_markers.h"

#include <algorithm>
#include <string>

namespace polar::game {

void ReplayMarkers::observe(const Game& game) {
    const std::uint64_t tick = game.tickCount();
    if (tick <= seen_) return;
    seen_ = tick;
    bool rockDestroyed = false;
    for (const GameEvent& event : game.events()) {
        if (event.type == GameEvent::ShipHit) markers_.push_back({tick, ReplayMarker::Kind::LifeLost, 0});
        if (event.type == GameEvent::CometShot) markers_.push_back({tick, ReplayMarker::Kind::CometShot, 0});
        rockDestroyed = rockDestroyed || event.type == GameEvent::RockDestroyed;
    }
    // A wave is cleared by the tick that destroys its last rock (the next starts after a delay).
    if (rockDestroyed) {
        const auto objects = game.world().objects();
        const bool rocksLeft = std::any_of(objects.begin(), objects.end(), [&](const GameObject& object) {
            return game.kindOf(object.id) == Kind::Rock;
        });
        if (!rocksLeft) markers_.push_back({tick, ReplayMarker::Kind::WaveCleared, game.wave()});
    }
    if (!beaten_ && game.score() > toBeat_) {
        beaten_ = true;
        markers_.push_back({tick, ReplayMarker::Kind::HighScore, toBeat_});
    }
}

std::optional<ReplayMarker> ReplayMarkers::next(std::uint64_t tick) const {
    auto after = std::upper_bound(markers_.begin(), markers_.end(), tick,
                                  [](std::uint64_t t, const ReplayMarker& m) { return t < m.tick; });
    if (after == markers_.end()) return std::nullopt;
    return *after;
}

std::optional<ReplayMarker> ReplayMarkers::previous(std::uint64_t tick) const {
    auto at = std::lower_bound(markers_.begin(), markers_.end(), tick,
                               [](const ReplayMarker& m, std::uint64_t t) { return m.tick < t; });
    if (at == markers_.begin()) return std::nullopt;
    return *std::prev(at);
}

int scoreToBeat(const HighScores& scores, const Replay& replay) {
    const HighScores::TableKey key{replay.header.scene, modSetOf(replay.header.mods)};
    const int final = replay.checkpoints.empty() ? 0 : replay.checkpoints.back().score;
    bool skipped = false;
    for (const HighScores::Entry& entry : scores.entriesOf(key)) {
        if (!skipped && entry.score == final) {
            skipped = true;
            continue;
        }
        return entry.score;
    }
    return 0;
}

std::string describe(const ReplayMarker& marker) {
    switch (marker.kind) {
        case ReplayMarker::Kind::LifeLost:
            return "LIFE LOST";
        case ReplayMarker::Kind::WaveCleared:
            return "WAVE " + std::to_string(marker.value) + " CLEARED";
        case ReplayMarker::Kind::CometShot:
            return "COMET SHOT";
        case ReplayMarker::Kind::HighScore:
            return marker.value > 0 ? "HIGH SCORE " + std::to_string(marker.value) + " BEATEN"
                                    : "FIRST POINTS";
    }
    return "";
}

}  // namespace polar::game
