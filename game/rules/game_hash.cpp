// The game's state hash: the world's and every field of the game's own (game.h).
#include "rules/game.h"

#include "polar/state_hash.h"

namespace polar::game {

std::uint64_t Game::hash() const {
    StateHash h;
    h.add(world_.hash());
    for (const auto& [id, e] : entities_) {
        h.add(std::uint64_t{id});
        h.add(static_cast<int>(e.kind));
        h.add(e.size);
        h.add(static_cast<int>(e.pickup));
        h.add(e.life);
        if (arcade_) {  // rules 3's foes: only games that have them hash their fields
            h.add(static_cast<int>(e.foe));
            h.add(e.hits);
            h.add(e.timer);
            h.add(e.heading);
            h.add(e.turn);
        }
    }
    h.add(score_);
    h.add(nextExtraLife_);
    h.add(lives_);
    h.add(wave_);
    h.add(static_cast<int>(over_));
    h.add(std::uint64_t{arena_});
    h.add(std::uint64_t{ship_});
    h.add(rng_.state());
    h.add(fireCooldown_);
    h.add(respawnTimer_);
    h.add(invulnerable_);
    h.add(shield_);
    h.add(waveTimer_);
    h.add(cometTimer_);
    h.add(serial_);
    h.add(ticks_);
    // Rules 1 had no hit-stop: its games hash as they always did.
    if (rulesVersion_ >= 2) h.add(hitStop_);
    if (arcade_) {
        h.add(multiplier_);
        h.add(chainTimer_);
        h.add(foeTimer_);
        h.add(spread_);
        h.add(rapid_);
        h.add(barrier_);
    }
    // Only a modified game mixes in its edits, so the hash of every reproducible game is unchanged.
    if (boundsEdits_ > 0) h.add(std::uint64_t{boundsEdits_});
    return h.value();
}

}  // namespace polar::game
