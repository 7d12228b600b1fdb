#pragma once
// The render benchmark's scene, shared by `polarcade-bench render` and the web build's
// polarcade-render-bench: N copies of one 64×64 sprite rotated, scaled and alpha-blended over a
// 1280×720 canvas, at the same pseudo-random places every run.
#include <vector>

#include "polar/math.h"
#include "polar/render/render.h"

namespace polar::bench::render_scene {

constexpr int kWidth = 1280;
constexpr int kHeight = 720;
constexpr int kSpriteSide = 64;
constexpr render::Color kBackground{24, 28, 40, 255};

// A 64×64 sprite with every kind of alpha: an opaque striped core (r < 22), a translucent halo
// fading from alpha 200 to 40 (22 ≤ r < 30) with a brighter nose marking the heading, and fully
// transparent corners (r ≥ 30). By area: 37% opaque, 32% translucent, 31% transparent.
render::Canvas makeSpriteArt();

struct Placement {
    double x, y;     // centre on the canvas (y down)
    double degrees;  // counter-clockwise as seen on the screen
    double scale;    // uniform, 0.5 to 1.5
};

// `count` placements from a fixed 32-bit LCG, spread over the whole canvas and a little beyond its
// edges so clipping is exercised too.
std::vector<Placement> makePlacements(int count);

// The sprite's transform for a placement, through a view whose world is the canvas with y up.
Transform placementTransform(const render::View& view, const Placement& p);

// A frame into `list`: a clear, then one sprite per placement (with `style`).
void recordScene(render::DrawList& list, const render::Image& sprite, const render::View& view,
                 const std::vector<Placement>& placements, const render::SpriteStyle& style = {});

}  // namespace polar::bench::render_scene
