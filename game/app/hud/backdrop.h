#pragma once
#include <cstdint>
#include <string>

#include "app/hud/particles.h"
#include "polar/render/color.h"
#include "polar/render/draw_list.h"
#include "rules/game.h"
#include "rules/scene_rules.h"

namespace polar::game {

// A scene's look: what is painted behind its objects and the colour its HUD is lettered in.
struct SceneLook {
    Backdrop backdrop = Backdrop::Plain;
    render::Color accent;  // the score and the wave in the HUD
};

// The look of `backdrop`: each has its own accent (plain keeps the HUD's usual colour).
SceneLook lookFor(Backdrop backdrop);

// The backdrop a game is drawn over: its scene's "backdrop" key, or else the one its name calls for
// (cave: cavern, field: starfield, ghosts: fog, storm: storm; any other name: plain, the old look).
// The built-in scene files leave the key out: a replay pins its scene file's bytes, and the look is
// no part of the rules, so their replays keep verifying.
Backdrop backdropOf(const Game& game);
// The same for a scene's rules and its path, before any game is made (the scene screen's card).
Backdrop backdropFor(const SceneRules& rules, const std::string& scenePath);
// What a player sees of a backdrop, in a few words ("RAIN AND LIGHTNING OVERHEAD."); empty for plain.
std::string aboutBackdrop(Backdrop backdrop);

// How bright the storm's lightning is at `tick` (and `alpha` of the way to the next) for a game of
// `seed`: 0 between strikes, up to 1 at a strike's peak. A strike comes every 3 to 7 seconds, drawn
// from the seed and the tick, never from the game's own generator.
double lightningAt(std::uint64_t seed, std::uint64_t tick, double alpha);

// Paints `backdrop` over the whole width × height canvas of `list`, as it is at `tick` and
// `alpha` of a game of `seed`: still pictures made once and drifting at their own speeds (the depth
// of a parallax), and moving parts drawn from the tick (stars, fog, rain, lightning, embers). It
// reads nothing of the game's state but these numbers, so it cannot feed the rules, and the same
// tick draws the same bytes on every run. The lightning is scaled by the player's flashes (0: none).
void drawBackdrop(render::DrawList& list, int width, int height, Backdrop backdrop, std::uint64_t seed,
                  std::uint64_t tick, double alpha, const EffectLevels& levels);

}  // namespace polar::game
