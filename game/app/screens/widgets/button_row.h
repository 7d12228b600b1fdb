#pragma once
#include <optional>
#include <string>
#include <vector>

#include "app/hud/pixel_rect.h"
#include "polar/math.h"
#include "polar/render/canvas.h"

namespace polar::game {

// A row of text buttons for the mouse (and a finger): the pointer lights the one under it, a click
// presses it. Keys and pads reach the same actions by their own bindings, so the row takes no focus.
//
// Why not a Menu? A menu is a column with one focus moved by the keys; these are shortcuts laid
// side by side, each a click away, like a video player's transport buttons.
class ButtonRow {
  public:
    // Lays `labels` out centred on `centreX`, their tops at `top`, `gap` pixels apart.
    void layOut(std::vector<std::string> labels, int centreX, int top, int gap = 4);
    // Follows the pointer; the index of the button a click at `click` pressed, if any.
    std::optional<std::size_t> update(const std::optional<Vec2>& pointer, const std::optional<Vec2>& click);
    void draw(render::Canvas& canvas) const;

    const std::vector<PixelRect>& rects() const { return rects_; }
    // The rectangle the row covers (empty before layOut).
    PixelRect bounds() const;
    static constexpr int kHeight = 12;  // a button's height

  private:
    std::vector<std::string> labels_;
    std::vector<PixelRect> rects_;
    std::optional<std::size_t> hover_;
};

}  // namespace polar::game
