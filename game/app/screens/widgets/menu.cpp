#include "app/screens/widgets/menu.h"

#include <algorithm>
#include <cmath>

#include "app/hud/lettering.h"
#include "polar/render/shapes.h"
#include "polar/render/text.h"

namespace polar::game {

using render::Color;

namespace {

constexpr Color kFocusBox{40, 48, 90, 200};
constexpr Color kDisabled{100, 106, 130, 255};

}  // namespace

Menu::Menu(std::vector<Item> items, Layout layout) : items_(std::move(items)), layout_(layout) {
    layout_.rows = std::max<std::size_t>(layout_.rows, 1);
    setFocus(0);
}

void Menu::setItems(std::vector<Item> items) {
    items_ = std::move(items);
    setFocus(std::min(focus_, items_.empty() ? 0 : items_.size() - 1));
    scroll_ = std::min(scroll_, items_.size() > layout_.rows ? items_.size() - layout_.rows : 0);
}

void Menu::setFocus(std::size_t item) {
    focus_ = std::min(item, items_.empty() ? 0 : items_.size() - 1);
    if (!items_.empty() && !items_[focus_].enabled) moveFocus(1);
    scrollTo(focus_);
}

void Menu::moveFocus(int step) {
    if (items_.empty()) return;
    const std::size_t n = items_.size();
    std::size_t at = focus_;
    for (std::size_t tried = 0; tried < n; ++tried) {  // wraps round, skipping disabled items
        at = (at + n + (step > 0 ? 1 : n - 1)) % n;
        if (items_[at].enabled) {
            focus_ = at;
            break;
        }
    }
    scrollTo(focus_);
}

void Menu::scrollTo(std::size_t item) {
    if (item < scroll_) scroll_ = item;
    if (item >= scroll_ + layout_.rows) scroll_ = item + 1 - layout_.rows;
}

void Menu::scrollBy(int rows) {
    const long most = items_.size() > layout_.rows ? static_cast<long>(items_.size() - layout_.rows) : 0;
    scroll_ = static_cast<std::size_t>(std::clamp(static_cast<long>(scroll_) + rows, 0L, most));
    // The focus stays on screen: it moves to the nearest visible row.
    if (focus_ < scroll_) setFocus(scroll_);
    if (focus_ >= scroll_ + layout_.rows) focus_ = scroll_ + layout_.rows - 1;
}

std::optional<PixelRect> Menu::rowRect(std::size_t item) const {
    if (item < scroll_ || item >= scroll_ + layout_.rows || item >= items_.size()) return std::nullopt;
    const int row = static_cast<int>(item - scroll_);
    return PixelRect{layout_.centreX - layout_.width / 2, layout_.top + row * layout_.rowHeight,
                     layout_.width, layout_.rowHeight};
}

std::optional<std::size_t> Menu::itemAt(const Vec2& point) const {
    for (std::size_t i = scroll_; i < items_.size() && i < scroll_ + layout_.rows; ++i)
        if (rowRect(i)->contains(point)) return i;
    return std::nullopt;
}

Menu::Result Menu::update(const Input::Commands& commands) {
    Result result;
    if (items_.empty()) return result;
    if (commands.wheel != 0) {
        // One row a notch; a fraction (a touchpad) still moves one row.
        const double notches = commands.wheel;
        const int rows = notches > 0 ? -std::max(1, static_cast<int>(std::lround(notches)))
                                     : std::max(1, static_cast<int>(std::lround(-notches)));
        scrollBy(rows);
    }
    if (commands.pointer)
        if (std::optional<std::size_t> hovered = itemAt(*commands.pointer);
            hovered && items_[*hovered].enabled)
            focus_ = *hovered;
    if (commands.up) moveFocus(-1);
    if (commands.down) moveFocus(1);
    result.item = focus_;
    if (commands.click) {
        std::optional<std::size_t> clicked = itemAt(*commands.click);
        if (clicked && items_[*clicked].enabled) {
            focus_ = *clicked;
            return {Action::Activate, *clicked};
        }
    }
    if (!items_[focus_].enabled) return result;
    if (commands.confirm)
        result.action = Action::Activate;
    else if (commands.left)
        result.action = Action::Decrease;
    else if (commands.right)
        result.action = Action::Increase;
    return result;
}

void Menu::draw(render::Canvas& canvas) const {
    const int glyph = render::kGlyphHeight * layout_.scale;
    for (std::size_t i = scroll_; i < items_.size() && i < scroll_ + layout_.rows; ++i) {
        const PixelRect row = *rowRect(i);
        const Item& item = items_[i];
        const bool focused = i == focus_;
        if (focused) {
            render::fillRect(canvas, row.x, row.y, row.width, row.height, kFocusBox);
            render::drawRect(canvas, row.x, row.y, row.width, row.height, kGold);
        }
        const Color color = !item.enabled ? kDisabled : focused ? kGold : kTextColor;
        const int textY = row.y + (row.height - glyph) / 2 + 1;
        if (item.value.empty()) {
            const render::TextSize size = render::measureText(item.label, layout_.scale);
            render::drawText(canvas, item.label, layout_.centreX - size.width / 2, textY, layout_.scale,
                             color);
        } else {
            render::drawText(canvas, item.label, row.x + 6, textY, layout_.scale, color);
            const render::TextSize size = render::measureText(item.value, layout_.scale);
            render::drawText(canvas, item.value, row.x + row.width - 6 - size.width, textY, layout_.scale,
                             color);
        }
    }
    // Marks that say more items lie above or below.
    const int x = layout_.centreX + layout_.width / 2 + 6;
    if (scroll_ > 0) render::drawText(canvas, "^", x, layout_.top, 1, kDimColor);
    if (scroll_ + layout_.rows < items_.size())
        render::drawText(canvas, "v", x,
                         layout_.top + static_cast<int>(layout_.rows) * layout_.rowHeight - 10, 1, kDimColor);
}

}  // namespace polar::game
