#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "app/hud/pixel_rect.h"
#include "app/theatre/replay_markers.h"
#include "polar/math.h"
#include "polar/render/canvas.h"

namespace polar::game {

// The replay theatre's seek bar: the replay's length across a track, the part played, the
// markers, and the head. The mouse presses anywhere on it and drags to scrub; a press within a few
// pixels of a marker lands on the marker's tick exactly.
class SeekBar {
  public:
    static constexpr int kHeight = 12;      // the track with its markers above it
    static constexpr int kMarkerReach = 3;  // pixels each side of a marker that pick it

    // The bar fills `track` (kHeight tall) for a replay of `totalTicks`.
    void layOut(const PixelRect& track, std::uint64_t totalTicks);
    // Follows the mouse: a press on the bar starts a drag, moving while it is held scrubs, the
    // release ends it. The tick to seek to this frame, if the bar asks for one.
    std::optional<std::uint64_t> update(const std::optional<Vec2>& pointer, const std::optional<Vec2>& press,
                                        bool released, const std::vector<ReplayMarker>& markers);
    // Draws the track up to `readTicks` (the part read so far, while the theatre reads ahead), the
    // played part to `tick`, the markers and the head.
    void draw(render::Canvas& canvas, std::uint64_t tick, std::uint64_t readTicks,
              const std::vector<ReplayMarker>& markers) const;

    // The tick under canvas column `x` (clamped to the replay).
    std::uint64_t tickAt(double x) const;
    // The column of `tick`.
    int columnOf(std::uint64_t tick) const;
    // The marker a press at `point` picks, if it is within reach of one.
    std::optional<ReplayMarker> markerAt(const Vec2& point, const std::vector<ReplayMarker>& markers) const;
    // The marker under the pointer (for its label), if any.
    const std::optional<ReplayMarker>& hovered() const { return hovered_; }
    bool dragging() const { return dragging_; }
    const PixelRect& rect() const { return track_; }

  private:
    PixelRect track_;
    std::uint64_t total_ = 1;
    bool dragging_ = false;
    std::optional<ReplayMarker> hovered_;
};

// The colour a marker of `kind` is drawn in, on the bar and in its label.
render::Color markerColor(ReplayMarker::Kind kind);

}  // namespace polar::game
