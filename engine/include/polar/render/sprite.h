#pragma once
#include "polar/math.h"
#include "polar/render/canvas.h"
#include "polar/render/color.h"
#include "polar/render/image.h"
#include "polar/render/view.h"
#include "polar/transform.h"

namespace polar::render {

// How a sprite's colours are modulated: each texel's colour is multiplied by `tint` (per channel,
// tint.a included) and its alpha by `opacity`/255. The defaults change nothing.
struct SpriteStyle {
    Color tint = kWhite;
    std::uint8_t opacity = 255;
};

// Draws `image` under `toCanvas`, the matrix from the sprite's bound space to canvas coordinates.
//
// Bound space: origin at the image's centre, one unit per image pixel, y up; so texel (u, v) (row v
// from the top) is the square [u − w/2, u + 1 − w/2] × [h/2 − v − 1, h/2 − v]. Any affine matrix
// works: rotation, non-uniform scale, mirroring (negative scale), shear.
//
// Sampling rule (nearest, by inverse mapping): canvas pixel (x, y) shows the texel containing the
// point toCanvas⁻¹(x + ½, y + ½); pixels whose centres map outside the image's half-open rectangle
// [0, w) × [0, h) are left alone. The inverse is walked in 32.32 fixed point from an anchor pixel
// (the one holding the sprite's centre), with integer steps per pixel, so the result is the same
// bytes on every compiler, and moving a sprite by whole pixels moves its pixels unchanged. Texels
// are blended premultiplied "over", d' = s + d·(255 − a)/255 rounded per channel. Clipping at the
// canvas edges is exact: the pixels inside equal those of a larger canvas.
// Not drawn at all: singular or non-finite matrices, sprites shrunk more than 65536 times, sprites
// centred more than 2⁴⁰ pixels from the canvas, and images over 32767 pixels a side.
void drawSprite(Canvas& canvas, const Image& image, const Mat3& toCanvas, const SpriteStyle& style = {});
// Draws `image` for an object with world transform `transform` seen through `view`
// (toCanvas = view.matrix() · transform.matrix()).
void drawSprite(Canvas& canvas, const Image& image, const View& view, const Transform& transform,
                const SpriteStyle& style = {});
// Draws `image` upright and unscaled with its centre at canvas point `centre` (for HUD icons).
// Texels land exactly on pixels when centre is a whole number for an even size, a half for an odd.
void drawSprite(Canvas& canvas, const Image& image, const Vec2& centre, const SpriteStyle& style = {});

}  // namespace polar::render
