#pragma once
#include <cstdint>
#include <vector>

#include "polar/render/draw_list.h"
#include "polar/render/view.h"
#include "rules/game.h"

namespace polar::game {

// Purely visual debris and sparks, driven by the game's events one tick at a time. They use their
// own seeded generator and never touch the simulation, so a replay draws the same frames every run.
class Particles {
  public:
    void spawnFor(const std::vector<GameEvent>& events, std::uint64_t tick);
    void tick(double dt);
    // Draws each particle at its position `alpha` of the way through the current tick.
    void draw(render::DrawList& list, const render::View& view, double alpha) const;
    std::size_t size() const { return particles_.size(); }
    std::size_t heldBytes() const { return particles_.capacity() * sizeof(Particle); }

  private:
    struct Particle {
        Vec2 position, velocity;
        double life, maxLife;
        std::uint32_t color;
    };
    std::vector<Particle> particles_;
};

}  // namespace polar::game
