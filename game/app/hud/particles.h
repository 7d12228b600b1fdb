#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "app/hud/sprite_cache.h"
#include "polar/render/draw_list.h"
#include "polar/render/view.h"
#include "rules/game.h"
#include "rules/rng.h"

namespace polar::game {

// How strong the effects that move or light the whole screen are drawn, in percent of full: the
// screen's shake, and the flashes (a hit object's white flash, the muzzle's, the screen's on a
// life lost). 0 turns them off, for players who need less motion or fewer flashes.
struct EffectLevels {
    int shake = 100;
    int flashes = 100;
    bool operator==(const EffectLevels&) const = default;
};

// What the game's events leave on screen, one tick at a time: debris in the broken thing's own
// colours that tumbles and fades, dust that lingers, sparks where bullets meet walls, the muzzle's
// flash and the thruster's flame, a white flash on the hit object, score pop-ups, the wave's banner
// and the screen's shake, each scaled by the weight of its event (a large rock more than a small).
//
// Why apart from the rules? It is presentation: it reads the events a tick leaves and never
// writes to the game, so the game's state hash is the same with every effect on or off (a test).
// It uses its own generator seeded by the tick, so a replay draws the same frames on every run;
// and it is a plain value, so the theatre keeps copies beside its keyframes and a seek draws what
// straight play draws.
class Particles {
  public:
    // Starts the effects of one tick's events; `tick` is the game's tick (the seed).
    void spawnFor(const std::vector<GameEvent>& events, std::uint64_t tick);
    // Ages everything by `dt` seconds.
    void tick(double dt);
    // Draws the debris, sparks, flames and flashes of `game`'s events over its objects, each at its
    // position `alpha` of the way through the current tick; a look's colours come from `sprites`.
    void draw(render::DrawList& list, const render::View& view, double alpha, const Game& game,
              SpriteCache& sprites, const EffectLevels& levels) const;
    // Draws the score pop-ups where they were earned and the wave's banner across the middle (over
    // the HUD).
    void drawWords(render::DrawList& list, const render::View& view, double alpha) const;
    // Where the screen's shake puts the world now, in whole canvas pixels.
    Vec2 shake(const EffectLevels& levels) const;
    std::size_t size() const { return particles_.size(); }
    std::size_t heldBytes() const;

  private:
    enum class Shape : std::uint8_t { Dot, Shard, Spark, Dust, Flame };
    struct Particle {
        Vec2 position, velocity;
        double life = 0, maxLife = 1;
        double angle = 0, spin = 0;  // shards tumble
        double size = 1;             // a shard's radius, a spark's length in seconds of its motion
        double keep = 0.97;          // the share of its velocity kept each tick
        std::uint32_t color = 0;     // 0xAARRGGBB, unless `look` is set
        std::uint32_t look = 0;      // its colour is shade `shade` of this look's sprite palette
        std::uint8_t shade = 0;
        Shape shape = Shape::Dot;
    };
    // A hit object's shape in white, growing and fading where it was hit.
    struct Flash {
        Vec2 where;
        double angle = 0;
        std::uint32_t look = 0;
        double life = 0, maxLife = 1;
    };
    // A bright disc: a muzzle flash, an impact's core, a pickup's ring.
    struct Burst {
        Vec2 where;
        double radius = 4, grow = 0;  // pixels, pixels a second
        double life = 0, maxLife = 1;
        std::uint32_t color = 0;
        bool ring = false;
    };
    // Words that rise from where they were earned and fade: "+100", "1UP".
    struct PopUp {
        Vec2 where;
        std::string text;
        double life = 0, maxLife = 1;
    };

    void debris(Rng& rng, const GameEvent& e, int count, double speed);
    void dust(Rng& rng, const GameEvent& e, int count);
    void sparks(Rng& rng, const Vec2& where, double towards, double spread, int count, double speed,
                std::uint32_t color);
    void addTrauma(double amount);

    std::vector<Particle> particles_;
    std::vector<Flash> flashes_;
    std::vector<Burst> bursts_;
    std::vector<PopUp> popUps_;
    std::string banner_;  // "WAVE 3 CLEARED", "WAVE 4"
    double bannerLife_ = 0, bannerMaxLife_ = 1;
    double trauma_ = 0;       // the shake's strength, 0 … 1; the offset grows with its square
    double screenFlash_ = 0;  // a life lost lights the whole screen, 0 … 1
    Vec2 shake_ = Vec2::Zero();
    std::uint64_t tick_ = 0;  // the last tick spawned for: the shake's seed
};

}  // namespace polar::game
