#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "files/assets.h"
#include "polar/render/canvas.h"
#include "polar/render/draw_list.h"
#include "polar/render/image.h"
#include "polar/render/view.h"
#include "polar/tasks.h"
#include "rules/game.h"

namespace polar::game {

// The game's logical screen: 640 × 360, shown scaled up by whole numbers (2× at 1280 × 720).
inline constexpr int kScreenWidth = 640;
inline constexpr int kScreenHeight = 360;

// Sprite images by logical asset path, loaded on first use through the asset overlay.
//
// A missing or corrupt PNG must not stop the game: it is reported once (problems()) and drawn as a
// magenta box of the bounds' size, so the player sees where it is and the modder sees what is wrong.
class SpriteCache {
  public:
    explicit SpriteCache(const AssetFs& assets) : assets_(assets) {}
    const render::Image& get(const std::string& logical);
    // Forgets an image so it is read again (after a mod or hot reload changed it).
    void forget(const std::string& logical) { images_.erase(logical); }
    const std::vector<Error>& problems() const { return problems_; }

  private:
    const AssetFs& assets_;
    std::map<std::string, render::Image> images_;
    std::vector<Error> problems_;
};

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

// Object transforms as they were before the last tick, so a frame can be drawn between two ticks.
class Interpolation {
  public:
    void capture(const World& world);
    // The transform `alpha` of the way from the captured one to the current one.
    Transform at(const GameObject& object, double alpha) const;

  private:
    std::map<ObjectId, Transform> previous_;
};

struct DrawOptions {
    bool debugOverlay = false;  // the bounds and the pairs hit (the debug panel's text is an overlay)
    std::uint64_t highScore = 0;
    bool hud = true;
    // Where the frame is drawn: in bands of rows on this task system (the game's pool), or on the
    // calling thread when null. The picture is the same bytes either way.
    TaskSystem* tasks = nullptr;
};

// Draws one frame of the game: the cave, every object under its interpolated transform, particles
// and the HUD; with the debug overlay, every object's world bounds exactly as the collision rule
// sees them and the pairs hit in the last step (debug_panel.h adds the numbers). The frame is
// recorded in a DrawList (one per thread, kept from frame to frame) and drawn on options.tasks.
void drawGame(render::Canvas& canvas, const Game& game, SpriteCache& sprites,
              const Interpolation& interpolation, const Particles& particles, double alpha,
              const DrawOptions& options);

// Draws the outline of a Bound under a world transform as the collision rule sees it
// (polar::boundOutline, shared with `polarcade-bounds view`) and a cross at its centre.
void drawBoundOutline(render::DrawList& list, const render::View& view, const Bound& bound,
                      const Transform& transform, render::Color color);

// Text centred horizontally on the screen.
void drawCentredText(render::Canvas& canvas, const std::string& text, int y, int scale, render::Color color);

}  // namespace polar::game
