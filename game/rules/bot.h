#pragma once
#include "rules/actions.h"
#include "rules/game.h"

namespace polar::game {

// A simple pilot for the attract demo and the soak test: it turns toward the rock it can hit
// soonest, fires when lined up, and thrusts away from rocks that come too close. It reads only
// the game state (and a seeded Rng for a little noise), so its games are as repeatable as any.
class Bot {
  public:
    explicit Bot(std::uint64_t seed = 7) : rng_(seed) {}
    Actions decide(const Game& game);
    // Its whole state is its Rng's: saved and restored beside a GameSnapshot.
    std::uint64_t state() const { return rng_.state(); }
    void restore(std::uint64_t state) { rng_.restore(state); }

  private:
    Rng rng_;
};

}  // namespace polar::game
