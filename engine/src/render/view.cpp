#include "polar/render/view.h"

namespace polar::render {

View::View(int canvasWidth, int canvasHeight)
    : width_(canvasWidth), height_(canvasHeight), centre_(canvasWidth / 2.0, canvasHeight / 2.0) {}

Mat3 View::matrix() const {
    // canvas = (W/2 + z·(x − cx), H/2 − z·(y − cy))
    Mat3 m = Mat3::Identity();
    m(0, 0) = zoom_;
    m(1, 1) = -zoom_;
    m(0, 2) = width_ / 2.0 - zoom_ * centre_.x();
    m(1, 2) = height_ / 2.0 + zoom_ * centre_.y();
    return m;
}

Vec2 View::toCanvas(const Vec2& world) const {
    return {width_ / 2.0 + zoom_ * (world.x() - centre_.x()),
            height_ / 2.0 - zoom_ * (world.y() - centre_.y())};
}

Vec2 View::toWorld(const Vec2& canvas) const {
    return {centre_.x() + (canvas.x() - width_ / 2.0) / zoom_,
            centre_.y() - (canvas.y() - height_ / 2.0) / zoom_};
}

}  // namespace polar::render
