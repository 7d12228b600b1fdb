#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "polar/error.h"
#include "polar/math.h"

namespace polar::game {

// How a scene plays, beyond its objects and effects: the scene file's "game" block, which the engine
// passes through unread.
//   "game": {"edges": "wrap", "field": [640, 360], "bullets": "fast", "bullet_speed": 1500,
//            "bullet_life": 0.3, "backdrop": "storm", "accent": [255, 120, 80],
//            "foes": ["saucer", "mine", "hunter"], "powerups": ["spread", "rapid", "barrier"]}
//
// Why here and not in Tuning? Tuning is the feel of every scene and a replay records it; these
// belong to one scene and come with its file, which a replay already pins by its hash. A scene
// without the block plays as the cave always has: its first container is the arena.
// What is painted behind a scene's objects (app/hud/backdrop.h draws them).
enum class Backdrop { Plain, Starfield, Fog, Storm, Cavern };
inline constexpr int kBackdropCount = 5;

// The name a scene file gives a backdrop ("starfield"), and the backdrop a name gives.
const char* backdropName(Backdrop backdrop);
std::optional<Backdrop> backdropFromName(const std::string& name);
// The backdrop names a scene file may give, quoted and joined for an error message.
std::string backdropNames();

// The foes a scene may call for (rules 3): saucers that enter, wander and shoot (the small ones
// aim); mines that burst into homing shards; hunters that crawl along the arena's edge and fire.
enum class Foe : std::uint8_t { Saucer, Mine, Hunter };
inline constexpr int kFoeCount = 3;
// The power-ups a scene may call for (rules 3), each timed: three bullets a shot; a gun that cools
// twice as fast; a barrier that guards the ship and breaks whatever it touches.
enum class PowerUp : std::uint8_t { Spread, Rapid, Barrier };
inline constexpr int kPowerUpCount = 3;

// The names a scene file gives them ("saucer", "spread"), and back.
const char* foeName(Foe foe);
const char* powerUpName(PowerUp powerUp);

struct SceneRules {
    enum class Edges { Container, Wrap };
    Edges edges = Edges::Container;
    // With wrap edges: the field is the rectangle from (0, 0) to this size; a thing that leaves one
    // side comes back on the other, once it is wholly out of sight.
    Vec2 field = Vec2(640, 360);
    bool fastBullets = false;           // bullets flagged "fast", so the scene must run "ccd"
    std::optional<double> bulletSpeed;  // units per second, instead of Tuning's
    std::optional<double> bulletLife;   // seconds, instead of Tuning's
    // Presentation, carried here because it comes in the same block: the rules never read it (the
    // game's hash is the same under any backdrop). Without the key, the scene's name chooses
    // (backdrop.h), so the built-in files, which replays pin by their bytes, need not change.
    std::optional<Backdrop> backdrop;
    // The HUD's accent colour (red, green, blue, 0 to 255) instead of the backdrop's; presentation.
    std::optional<std::array<std::uint8_t, 3>> accent;
    // What the scene calls for under rules 3, one bit a Foe or PowerUp; none: the game spends
    // nothing on them (no prototype loaded, no work in a tick).
    std::uint8_t foes = 0;
    std::uint8_t powerUps = 0;
    // The foes in the file's order: the first comes from wave 1, the next ones in later waves.
    std::vector<Foe> foeOrder;

    bool callsFor(Foe foe) const { return (foes >> static_cast<int>(foe)) & 1u; }
    bool callsFor(PowerUp powerUp) const { return (powerUps >> static_cast<int>(powerUp)) & 1u; }
};

// Reads the "game" block of the scene file `file` (default rules when there is none), with
// file:line:column errors. Unknown keys are refused, as everywhere in the scene format.
Result<SceneRules> parseSceneRules(const SourceFile& file);

}  // namespace polar::game
