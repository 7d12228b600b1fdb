#pragma once
#include "polar/math.h"

namespace polar::render {

// The camera: which part of the y-up world shows on the y-down canvas, and how large.
//
// Why a class and not a loose matrix? World and canvas disagree on the direction of y, and mixing
// them up is the classic rendering bug. A View states the mapping once,
//   canvas = (W/2 + z·(x − cx), H/2 − z·(y − cy)),
// for a W × H canvas, centre (cx, cy) and zoom z (canvas pixels per world unit). Compose it with an
// object's world matrix like SFML's render states: `view.matrix() * transform.matrix()` maps the
// object's bound space to the canvas, and that is what drawSprite takes.
class View {
  public:
    // A view of a width × height canvas at zoom 1 centred on (W/2, H/2): world units are canvas
    // pixels, world (0, 0) is the bottom-left corner of the canvas.
    View(int canvasWidth, int canvasHeight);

    // The world point shown at the canvas centre.
    void setCentre(const Vec2& centre) { centre_ = centre; }
    // Canvas pixels per world unit; must be positive.
    void setZoom(double zoom) { zoom_ = zoom; }
    // The settings above, and the canvas size the view was made for.
    const Vec2& centre() const { return centre_; }
    double zoom() const { return zoom_; }
    int canvasWidth() const { return width_; }
    int canvasHeight() const { return height_; }

    // The world → canvas matrix V (homogeneous 3×3).
    Mat3 matrix() const;
    // V·p for a world point p.
    Vec2 toCanvas(const Vec2& world) const;
    // V⁻¹·c for a canvas point c.
    Vec2 toWorld(const Vec2& canvas) const;

  private:
    int width_;
    int height_;
    Vec2 centre_;
    double zoom_ = 1.0;
};

// m·(p, 1): a point through a homogeneous 2D matrix.
inline Vec2 transformPoint(const Mat3& m, const Vec2& p) {
    return {m(0, 0) * p.x() + m(0, 1) * p.y() + m(0, 2), m(1, 0) * p.x() + m(1, 1) * p.y() + m(1, 2)};
}

}  // namespace polar::render
