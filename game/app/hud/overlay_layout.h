#pragma once
#include <optional>
#include <string>
#include <vector>

#include "app/hud/pixel_rect.h"
#include "polar/render/canvas.h"
#include "polar/render/color.h"

namespace polar::game {

// The corners overlays stack in.
enum class Corner { BottomLeft, BottomRight, TopLeft, TopRight };

// Places the overlays of a frame (the replay bar, the debug panel, hot reload's messages, the
// notices) so that no two share a pixel: the one layout rule every overlay goes through.
//
// The rule: a box goes into its corner, inside the margin (below the HUD's line at the top), and
// then as far from the corner as it must (up from a bottom corner, down from a top one) to clear
// every box placed before it, with a gap between. A box that no longer fits on the screen is not
// placed, and its overlay is not drawn; the ones placed first (the most important) always are.
class OverlayLayout {
  public:
    static constexpr int kMargin = 4;
    static constexpr int kGap = 2;
    // The HUD's line across the top (score, high score, wave: drawGame) belongs to the game, so
    // the top corners start below it.
    static constexpr int kHudRows = 16;

    OverlayLayout(int canvasWidth, int canvasHeight) : width_(canvasWidth), height_(canvasHeight) {}

    // A width × height box in `corner` (a width past the screen is cut to it), or nothing when there
    // is no room left.
    std::optional<PixelRect> place(Corner corner, int width, int height);
    // A width × height box centred across the screen with its bottom row just above row `bottom`,
    // moved up as far as it must to clear every box placed before it (a screen's help line, the
    // message over it), or nothing when there is no room left.
    std::optional<PixelRect> placeCentred(int width, int height, int bottom);
    // The widest box that fits between the margins.
    int fullWidth() const { return width_ - 2 * kMargin; }
    // Every box placed, in order.
    const std::vector<PixelRect>& boxes() const { return boxes_; }

  private:
    int width_, height_;
    std::vector<PixelRect> boxes_;
};

// A line of an overlay, in its colour.
struct OverlayLine {
    std::string text;
    render::Color color;
};

// Lines of text in a box placed by `layout` in `corner` (as wide as the longest line, or with
// `fullWidth` the whole screen), on `backing`. Returns the box, or nothing when there was no room.
std::optional<PixelRect> drawOverlayText(render::Canvas& canvas, OverlayLayout& layout, Corner corner,
                                         const std::vector<OverlayLine>& lines, render::Color backing,
                                         bool fullWidth = false);

}  // namespace polar::game
