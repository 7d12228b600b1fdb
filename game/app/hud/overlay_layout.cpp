#include "app/hud/overlay_layout.h"

#include <algorithm>

#include "polar/render/shapes.h"
#include "polar/render/text.h"

namespace polar::game {

std::optional<PixelRect> OverlayLayout::place(Corner corner, int width, int height) {
    width = std::min(width, fullWidth());
    if (width <= 0 || height <= 0) return std::nullopt;
    const bool bottom = corner == Corner::BottomLeft || corner == Corner::BottomRight;
    const bool left = corner == Corner::BottomLeft || corner == Corner::TopLeft;
    PixelRect box{left ? kMargin : width_ - kMargin - width, bottom ? height_ - kMargin - height : kHudRows,
                  width, height};
    // Each move clears one box and only goes away from the corner, so this ends.
    for (bool moved = true; moved;) {
        moved = false;
        for (const PixelRect& other : boxes_) {
            if (!box.overlaps(other)) continue;
            box.y = bottom ? other.y - kGap - height : other.y + other.height + kGap;
            moved = true;
        }
        if (box.y < kMargin || box.y + height > height_ - kMargin) return std::nullopt;
    }
    boxes_.push_back(box);
    return box;
}

std::optional<PixelRect> OverlayLayout::placeCentred(int width, int height, int bottom) {
    width = std::min(width, fullWidth());
    if (width <= 0 || height <= 0) return std::nullopt;
    PixelRect box{(width_ - width) / 2, bottom - height, width, height};
    for (bool moved = true; moved;) {
        moved = false;
        for (const PixelRect& other : boxes_) {
            if (!box.overlaps(other)) continue;
            box.y = other.y - kGap - height;
            moved = true;
        }
        if (box.y < kHudRows) return std::nullopt;
    }
    boxes_.push_back(box);
    return box;
}

std::optional<PixelRect> drawOverlayText(render::Canvas& canvas, OverlayLayout& layout, Corner corner,
                                         const std::vector<OverlayLine>& lines, render::Color backing,
                                         bool fullWidth) {
    if (lines.empty()) return std::nullopt;
    int width = 0;
    for (const OverlayLine& line : lines) width = std::max(width, render::measureText(line.text, 1).width);
    const int pad = 2;
    if (fullWidth) width = layout.fullWidth() - 2 * pad;
    const int height = static_cast<int>(lines.size()) * render::kLineHeight - 1;
    std::optional<PixelRect> box = layout.place(corner, width + 2 * pad, height + 2 * pad);
    if (!box) return std::nullopt;
    render::fillRect(canvas, box->x, box->y, box->width, box->height, backing);
    for (std::size_t i = 0; i < lines.size(); ++i)
        render::drawText(canvas, lines[i].text, box->x + pad,
                         box->y + pad + static_cast<int>(i) * render::kLineHeight, 1, lines[i].color);
    return box;
}

}  // namespace polar::game
