// Game::save and Game::restore: the game's own state beside its world's snapshot.
#include <cmath>
#include <string>

#include "polar/snapshot_bytes.h"
#include "rules/game.h"

namespace polar::game {
namespace {

constexpr SnapshotKind kGameSnapshot{0x4e534750, kGameSnapshotVersion, "game snapshot",
                                     "Game::save"};  // magic "PGSN"
constexpr std::size_t kEntityRecordBytes = 4 + 1 + 4 + 1 + 8;
constexpr std::size_t kFoeRecordBytes = 1 + 4 + 8 + 8 + 8;  // after each entity's, in an arcade game only
constexpr std::size_t kEventRecordBytes = 1 + 16 + 4 + 4 + 8 + 16 + 4;

Error gameSnapshotError(std::string what) {
    return snapshotError(kGameSnapshot, std::move(what));
}

}  // namespace

void Game::save(GameSnapshot& out) const {
    saveSnapshot(world_, out.world);
    ByteWriter w = startSnapshotFrame(out.bytes, kGameSnapshot);

    w.put(rng_.state());
    w.put(ticks_);
    w.put(serial_);
    w.put(boundsEdits_);
    w.put(arena_);
    w.put(ship_);
    const double numbers[] = {arenaCentre_.x(), arenaCentre_.y(), shipStart_.x(), shipStart_.y(),
                              fireCooldown_,    respawnTimer_,    invulnerable_,  shield_,
                              waveTimer_,       cometTimer_,      chainTimer_,    foeTimer_,
                              spread_,          rapid_,           barrier_};
    w.bytes(numbers, sizeof numbers);
    const std::int32_t counts[] = {score_, nextExtraLife_, lives_, wave_, hitStop_, multiplier_};
    w.bytes(counts, sizeof counts);
    w.put(static_cast<std::uint8_t>(over_));

    w.put(static_cast<std::uint32_t>(entities_.size()));
    for (const auto& [id, e] : entities_) {
        w.put(id);
        w.put(static_cast<std::uint8_t>(e.kind));
        w.put(static_cast<std::int32_t>(e.size));
        w.put(static_cast<std::uint8_t>(e.pickup));
        w.put(e.life);
        if (!arcade_) continue;
        w.put(static_cast<std::uint8_t>(e.foe));
        w.put(static_cast<std::int32_t>(e.hits));
        w.put(e.timer);
        w.put(e.heading);
        w.put(e.turn);
    }
    w.put(static_cast<std::uint32_t>(events_.size()));
    for (const GameEvent& event : events_) {
        w.put(static_cast<std::uint8_t>(event.type));
        w.put(event.where.x());
        w.put(event.where.y());
        w.put(static_cast<std::int32_t>(event.size));
        w.put(event.look);
        w.put(event.angle);
        w.put(event.motion.x());
        w.put(event.motion.y());
        w.put(static_cast<std::int32_t>(event.points));
    }
    endSnapshotFrame(w);
}

std::optional<Error> Game::restore(const GameSnapshot& snapshot) {
    Result<ByteReader> payload = openSnapshotFrame(snapshot.bytes, kGameSnapshot);
    if (!payload) return payload.error();

    // Checked whole first, applied only when the world's snapshot is taken too.
    auto read = [&](bool apply) -> std::optional<Error> {
        ByteReader in = *payload;
        auto rng = in.get<std::uint64_t>();
        auto ticks = in.get<std::uint64_t>();
        auto serial = in.get<std::uint64_t>();
        auto edits = in.get<std::uint32_t>();
        auto arena = in.get<ObjectId>();
        auto ship = in.get<ObjectId>();
        double n[15];
        in.bytes(n, sizeof n);
        std::int32_t c[6];
        in.bytes(c, sizeof c);
        auto over = in.get<std::uint8_t>();
        if (!in.ok()) return gameSnapshotError("cut off in the game's numbers");
        for (double x : n)
            if (!std::isfinite(x)) return gameSnapshotError("a timer that is not finite");
        if (over > 1) return gameSnapshotError("a game-over flag that is neither 0 nor 1");
        if (c[4] < 0) return gameSnapshotError("a hit-stop of negative length");
        if (c[5] < 1) return gameSnapshotError("a score multiplier under 1");
        if (apply) {
            rng_.restore(rng);
            ticks_ = ticks;
            serial_ = serial;
            boundsEdits_ = edits;
            arena_ = arena;
            ship_ = ship;
            arenaCentre_ = Vec2(n[0], n[1]);
            shipStart_ = Vec2(n[2], n[3]);
            fireCooldown_ = n[4];
            respawnTimer_ = n[5];
            invulnerable_ = n[6];
            shield_ = n[7];
            waveTimer_ = n[8];
            cometTimer_ = n[9];
            chainTimer_ = n[10];
            foeTimer_ = n[11];
            spread_ = n[12];
            rapid_ = n[13];
            barrier_ = n[14];
            multiplier_ = c[5];
            score_ = c[0];
            nextExtraLife_ = c[1];
            lives_ = c[2];
            wave_ = c[3];
            hitStop_ = c[4];
            over_ = over != 0;
        }

        auto count = in.get<std::uint32_t>();
        if (!in.canHold(count, kEntityRecordBytes + (arcade_ ? kFoeRecordBytes : 0)))
            return gameSnapshotError("cut off before the kinds table");
        // Walks the old table beside the new one: an entity in both keeps its node.
        auto at = entities_.begin();
        ObjectId previous = 0;
        for (std::uint32_t k = 0; k < count; ++k) {
            auto id = in.get<ObjectId>();
            auto kind = in.get<std::uint8_t>();
            auto size = in.get<std::int32_t>();
            auto pickup = in.get<std::uint8_t>();
            auto life = in.get<double>();
            std::uint8_t foe = 0;
            std::int32_t hits = 0;
            double timer = 0, heading = 0, turn = 0;
            if (arcade_) {
                foe = in.get<std::uint8_t>();
                hits = in.get<std::int32_t>();
                timer = in.get<double>(), heading = in.get<double>(), turn = in.get<double>();
            }
            if (!in.ok()) return gameSnapshotError("cut off in the kinds table");
            if (!apply) {
                if (k > 0 && id <= previous) return gameSnapshotError("the kinds table out of order");
                if (kind > static_cast<std::uint8_t>(Kind::FoeShot) ||
                    pickup > static_cast<std::uint8_t>(PickupKind::Barrier) || foe >= kFoeKindCount ||
                    !std::isfinite(life) || !std::isfinite(timer) || !std::isfinite(heading) ||
                    !std::isfinite(turn))
                    return gameSnapshotError("an entity of unknown kind");
                previous = id;
                continue;
            }
            while (at != entities_.end() && at->first < id) at = entities_.erase(at);
            if (at == entities_.end() || at->first != id) at = entities_.emplace_hint(at, id, Entity{});
            Entity& e = at->second;
            e.kind = static_cast<Kind>(kind);
            e.size = size;
            e.pickup = static_cast<PickupKind>(pickup);
            e.life = life;
            e.foe = static_cast<FoeKind>(foe);
            e.hits = hits;
            e.timer = timer;
            e.heading = heading;
            e.turn = turn;
            ++at;
        }
        if (apply) entities_.erase(at, entities_.end());

        auto events = in.get<std::uint32_t>();
        if (!in.canHold(events, kEventRecordBytes)) return gameSnapshotError("cut off before the events");
        if (apply) events_.resize(events);
        for (std::uint32_t k = 0; k < events; ++k) {
            auto type = in.get<std::uint8_t>();
            double x = in.get<double>(), y = in.get<double>();
            auto size = in.get<std::int32_t>();
            auto look = in.get<std::uint32_t>();
            double angle = in.get<double>(), mx = in.get<double>(), my = in.get<double>();
            auto points = in.get<std::int32_t>();
            if (!apply && (type > GameEvent::kLastType || !std::isfinite(x) || !std::isfinite(y) ||
                           !std::isfinite(angle) || !std::isfinite(mx) || !std::isfinite(my)))
                return gameSnapshotError("an event of unknown type");
            if (apply)
                events_[k] = {
                    static_cast<GameEvent::Type>(type), Vec2(x, y), size, look, angle, Vec2(mx, my), points};
        }
        if (!in.ok()) return gameSnapshotError("cut off in the events");
        if (in.left() != 0) return gameSnapshotError("bytes past the end of the state");
        return std::nullopt;
    };
    if (std::optional<Error> error = read(false)) return error;
    if (std::optional<Error> error = restoreSnapshot(world_, snapshot.world)) return error;
    read(true);
    return std::nullopt;
}

}  // namespace polar::game
