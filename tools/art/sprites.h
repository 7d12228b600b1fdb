#pragma once
// The demo game's sprites, drawn procedurally. Every function is a pure function of its arguments.
#include <cstdint>
#include <string>
#include <vector>

#include "pixel_art.h"

namespace polar::art {

// Sizes in pixels.
inline constexpr int kShipSize = 20;
inline constexpr int kRockSizes[3] = {56, 32, 18};  // large, medium, small
inline constexpr int kBulletSize = 5;
inline constexpr int kPickupSize = 14;
inline constexpr int kCometSize = 24;
inline constexpr int kCaveWidth = 640;
inline constexpr int kCaveHeight = 360;
inline constexpr int kSaucerSize = 26;
inline constexpr int kSmallSaucerSize = 16;
inline constexpr int kMineSize = 18;
inline constexpr int kShardSize = 9;
inline constexpr int kHunterSize = 18;

// The player's ship, nose toward +x (angle 0 faces right).
Canvas drawShip();
// A lumpy, cratered rock; `variant` 1..3 picks the palette (warm, grey, rust) and the shape.
Canvas drawRock(int size, int variant, std::uint64_t seed);
// A small glowing shot.
Canvas drawBullet();
// Pickups: a shield emblem and a heart in a glowing ring.
Canvas drawPickupShield();
Canvas drawPickupLife();
// Power-ups: a fan of three shots, a lightning bolt, a ring in a ring.
Canvas drawPickupSpread();
Canvas drawPickupRapid();
Canvas drawPickupBarrier();
// Foes: a large and a small flying saucer; a spiked mine and the dart it bursts into; a wall turret
// facing +x; and the pink shot they fire.
Canvas drawSaucer();
Canvas drawSmallSaucer();
Canvas drawMine();
Canvas drawMineShard();
Canvas drawHunter();
Canvas drawFoeShot();
// An icy comet flying toward +x with its tail behind it.
Canvas drawComet(std::uint64_t seed);
// The cave arena: rock walls around an open interior (transparent) that is star-shaped from the
// image centre.
Canvas drawCave(std::uint64_t seed);

struct NamedSprite {
    std::string name;  // file name without ".png"
    Canvas canvas;
};

// Every sprite of the demo, in a fixed order, from one seed.
std::vector<NamedSprite> drawAll(std::uint64_t seed);

}  // namespace polar::art
