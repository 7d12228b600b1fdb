#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "app/hud/pixel_rect.h"
#include "app/input/input.h"
#include "polar/render/canvas.h"

namespace polar::game {

// A column of items with one focus, moved by the keyboard, a game controller and the mouse alike:
// up/down (arrows, WASD, d-pad, stick) move it, the pointer puts it on the row under it, confirm
// (Enter, Space, A) or a click on a row activates, left/right ask the focused item to change its
// value (for options). A list longer than its rows scrolls, by the wheel or by the focus.
//
// Why one widget? So every menu and list of the game answers the same keys, buttons and clicks in
// the same way, and the rule lives in one place.
class Menu {
  public:
    struct Item {
        std::string label;
        std::string value;    // drawn right-aligned on the row ("80%"); empty for none
        bool enabled = true;  // a disabled item is drawn dim and never takes the focus
    };
    // Where and how the rows are drawn.
    struct Layout {
        int centreX = 320;  // rows are centred on this column
        int top = 150;      // the first visible row's top
        int width = 240;    // a row's width
        int rowHeight = 20;
        int scale = 2;         // the font scale of the labels
        std::size_t rows = 8;  // rows visible at once; more items scroll
    };
    enum class Action { None, Activate, Decrease, Increase };
    struct Result {
        Action action = Action::None;
        std::size_t item = 0;
    };

    Menu() = default;
    Menu(std::vector<Item> items, Layout layout);

    // Applies the frame's commands; what the player asked of which item.
    Result update(const Input::Commands& commands);
    void draw(render::Canvas& canvas) const;

    const std::vector<Item>& items() const { return items_; }
    // Replaces the items, keeping the focus on the same index where it still can be.
    void setItems(std::vector<Item> items);
    std::size_t focus() const { return focus_; }
    void setFocus(std::size_t item);
    // The first visible item.
    std::size_t scroll() const { return scroll_; }
    // Row `item`'s rectangle on the canvas, or nothing while it is scrolled out of view.
    std::optional<PixelRect> rowRect(std::size_t item) const;
    // The item under a canvas point, if a visible row is there.
    std::optional<std::size_t> itemAt(const Vec2& point) const;
    const Layout& layout() const { return layout_; }

  private:
    void moveFocus(int step);
    void scrollTo(std::size_t item);
    void scrollBy(int rows);

    std::vector<Item> items_;
    Layout layout_;
    std::size_t focus_ = 0;
    std::size_t scroll_ = 0;
};

}  // namespace polar::game
