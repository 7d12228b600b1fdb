#include "app/screens/widgets/button_row.h"

#include <algorithm>

#include "app/screens/widgets/screen_style.h"
#include "polar/render/shapes.h"
#include "polar/render/text.h"

namespace polar::game {

namespace {
constexpr int kPad = 3;  // pixels each side of a label
}

void ButtonRow::layOut(std::vector<std::string> labels, int centreX, int top, int gap) {
    labels_ = std::move(labels);
    rects_.clear();
    int total = 0;
    for (const std::string& label : labels_) total += render::measureText(label, 1).width + 2 * kPad + gap;
    int x = centreX - (total - gap) / 2;
    for (const std::string& label : labels_) {
        const int width = render::measureText(label, 1).width + 2 * kPad;
        rects_.push_back({x, top, width, kHeight});
        x += width + gap;
    }
}

std::optional<std::size_t> ButtonRow::update(const std::optional<Vec2>& pointer,
                                             const std::optional<Vec2>& click) {
    auto at = [&](const Vec2& point) -> std::optional<std::size_t> {
        for (std::size_t i = 0; i < rects_.size(); ++i)
            if (rects_[i].contains(point)) return i;
        return std::nullopt;
    };
    if (pointer) hover_ = at(*pointer);
    if (!click) return std::nullopt;
    hover_ = at(*click);
    return hover_;
}

void ButtonRow::draw(render::Canvas& canvas) const {
    for (std::size_t i = 0; i < rects_.size(); ++i) {
        const PixelRect& r = rects_[i];
        const bool lit = hover_ == i;
        render::fillRect(canvas, r.x, r.y, r.width, r.height,
                         lit ? render::Color{70, 80, 130, 230} : render::Color{30, 34, 60, 220});
        render::drawRect(canvas, r.x, r.y, r.width, r.height, lit ? kGold : kDimColor);
        render::drawText(canvas, labels_[i], r.x + kPad, r.y + 2, 1, lit ? kGold : kTextColor);
    }
}

PixelRect ButtonRow::bounds() const {
    if (rects_.empty()) return {};
    return {rects_.front().x, rects_.front().y, rects_.back().x + rects_.back().width - rects_.front().x,
            kHeight};
}

}  // namespace polar::game
