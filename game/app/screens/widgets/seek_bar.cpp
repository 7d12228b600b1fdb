#include "app/screens/widgets/seek_bar.h"

#include <algorithm>
#include <cmath>

#include "app/screens/widgets/screen_style.h"
#include "polar/render/shapes.h"

namespace polar::game {

namespace {
constexpr int kTrackTop = 5;  // rows above the track hold the markers' flags
constexpr int kTrackHeight = 5;
}  // namespace

render::Color markerColor(ReplayMarker::Kind kind) {
    switch (kind) {
        case ReplayMarker::Kind::LifeLost:
            return kWarnColor;
        case ReplayMarker::Kind::WaveCleared:
            return render::Color{120, 230, 140, 255};
        case ReplayMarker::Kind::CometShot:
            return render::Color{120, 200, 255, 255};
        case ReplayMarker::Kind::HighScore:
            return kGold;
    }
    return kTextColor;
}

void SeekBar::layOut(const PixelRect& track, std::uint64_t totalTicks) {
    track_ = track;
    total_ = std::max<std::uint64_t>(totalTicks, 1);
}

std::uint64_t SeekBar::tickAt(double x) const {
    const double along = std::clamp((x - track_.x) / std::max(1, track_.width - 1), 0.0, 1.0);
    return static_cast<std::uint64_t>(std::llround(along * static_cast<double>(total_)));
}

int SeekBar::columnOf(std::uint64_t tick) const {
    const double along = static_cast<double>(std::min(tick, total_)) / static_cast<double>(total_);
    return track_.x + static_cast<int>(std::lround(along * (track_.width - 1)));
}

std::optional<ReplayMarker> SeekBar::markerAt(const Vec2& point,
                                              const std::vector<ReplayMarker>& markers) const {
    if (!track_.contains(point)) return std::nullopt;
    std::optional<ReplayMarker> best;
    int bestDistance = kMarkerReach + 1;
    for (const ReplayMarker& marker : markers) {
        const int distance = std::abs(columnOf(marker.tick) - static_cast<int>(std::floor(point.x())));
        if (distance < bestDistance) {
            bestDistance = distance;
            best = marker;
        }
    }
    return best;
}

std::optional<std::uint64_t> SeekBar::update(const std::optional<Vec2>& pointer,
                                             const std::optional<Vec2>& press, bool released,
                                             const std::vector<ReplayMarker>& markers) {
    if (pointer) hovered_ = markerAt(*pointer, markers);
    std::optional<std::uint64_t> seek;
    if (press && track_.contains(*press)) {
        dragging_ = true;
        const std::optional<ReplayMarker> marker = markerAt(*press, markers);
        seek = marker ? marker->tick : tickAt(press->x());
    } else if (dragging_ && pointer) {
        seek = tickAt(pointer->x());
    }
    if (released) dragging_ = false;
    return seek;
}

void SeekBar::draw(render::Canvas& canvas, std::uint64_t tick, std::uint64_t readTicks,
                   const std::vector<ReplayMarker>& markers) const {
    const int y = track_.y + kTrackTop;
    render::fillRect(canvas, track_.x, y, track_.width, kTrackHeight, render::Color{40, 44, 70, 230});
    const int read = columnOf(readTicks) - track_.x;
    render::fillRect(canvas, track_.x, y, read, kTrackHeight, render::Color{70, 76, 110, 240});
    const int played = columnOf(tick) - track_.x;
    render::fillRect(canvas, track_.x, y + 1, played, kTrackHeight - 2, render::Color{150, 170, 255, 255});
    for (const ReplayMarker& marker : markers) {
        const int x = columnOf(marker.tick);
        const bool lit = hovered_ && hovered_->tick == marker.tick && hovered_->kind == marker.kind;
        const render::Color color = markerColor(marker.kind);
        render::fillRect(canvas, x, track_.y + (lit ? 0 : 1), 1, kTrackTop + kTrackHeight - (lit ? 0 : 1),
                         color);
        render::fillRect(canvas, x - 1, track_.y + (lit ? 0 : 1), 3, 2, color);
    }
    const int head = columnOf(tick);
    render::fillRect(canvas, head - 1, y - 2, 3, kTrackHeight + 4, render::Color{255, 255, 255, 255});
}

}  // namespace polar::game
