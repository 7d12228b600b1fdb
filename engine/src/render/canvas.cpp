#include "polar/render/canvas.h"

#include <algorithm>
#include <cassert>
#include <cstring>
#include <utility>

#include "polar/render/image.h"
#include "render/blend.h"
#include "render/row_clip.h"

namespace polar::render {

Canvas::Canvas(int width, int height)
    : owned_(std::size_t(width) * std::size_t(height)), width_(width), height_(height), stride_(width) {
    assert(width > 0 && height > 0);
    pixels_ = owned_.data();
    clear(kBlack);
}

Canvas Canvas::wrap(std::uint32_t* pixels, int width, int height, int pitchBytes) {
    assert(pixels && width > 0 && height > 0 && pitchBytes % 4 == 0 && pitchBytes >= 4 * width);
    Canvas canvas;
    canvas.pixels_ = pixels;
    canvas.width_ = width;
    canvas.height_ = height;
    canvas.stride_ = pitchBytes / 4;
    return canvas;
}

Canvas::Canvas(Canvas&& other) noexcept {
    *this = std::move(other);
}

Canvas& Canvas::operator=(Canvas&& other) noexcept {
    if (this != &other) {
        // Moving a vector keeps its buffer, so pixels_ stays valid for an owned canvas too.
        owned_ = std::exchange(other.owned_, {});
        pixels_ = std::exchange(other.pixels_, nullptr);
        width_ = std::exchange(other.width_, 0);
        height_ = std::exchange(other.height_, 0);
        stride_ = std::exchange(other.stride_, 0);
    }
    return *this;
}

Color Canvas::pixel(int x, int y) const {
    if (!contains(x, y)) return kTransparent;
    return Color::fromArgb(row(y)[x]);
}

void Canvas::setPixel(int x, int y, Color c) {
    if (contains(x, y)) row(y)[x] = c.argb();
}

void Canvas::blendPixel(int x, int y, Color c) {
    if (contains(x, y)) detail::blendInto(&row(y)[x], premultiply(c));
}

void Canvas::clear(Color c) {
    detail::clear(*this, detail::allRows(*this), c);
}

void detail::clear(Canvas& canvas, RowClip rows, Color color) {
    const std::uint32_t v = color.argb();
    for (int y = rows.begin; y < rows.end; ++y) std::fill_n(canvas.row(y), canvas.width(), v);
}

void detail::setPixel(Canvas& canvas, RowClip rows, int x, int y, Color color) {
    if (y >= rows.begin && y < rows.end) canvas.setPixel(x, y, color);
}

void detail::blendPixel(Canvas& canvas, RowClip rows, int x, int y, Color color) {
    if (y >= rows.begin && y < rows.end) canvas.blendPixel(x, y, color);
}

Canvas Canvas::clone() const {
    Canvas copy(width_, height_);
    for (int y = 0; y < height_; ++y) std::memcpy(copy.row(y), row(y), std::size_t(width_) * 4);
    return copy;
}

}  // namespace polar::render
