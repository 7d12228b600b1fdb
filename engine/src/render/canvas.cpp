#include "polar/render/canvas.h"

#include <SDL.h>

#include <algorithm>
#include <cassert>
#include <cstring>
#include <new>
#include <utility>

#include "polar/render/image.h"
#include "render/blend.h"

namespace polar::render {

Canvas::Canvas(int width, int height) {
    assert(width > 0 && height > 0);
    surface_ = SDL_CreateRGBSurfaceWithFormat(0, width, height, 32, SDL_PIXELFORMAT_ARGB8888);
    if (!surface_) throw std::bad_alloc();
    owned_ = true;
    width_ = width;
    height_ = height;
    pitch_ = surface_->pitch;
    pixels_ = static_cast<std::uint8_t*>(surface_->pixels);
    clear(kBlack);
}

Canvas Canvas::wrap(SDL_Surface* surface) {
    assert(surface && surface->format->format == SDL_PIXELFORMAT_ARGB8888 && !SDL_MUSTLOCK(surface));
    Canvas canvas;
    canvas.surface_ = surface;
    canvas.width_ = surface->w;
    canvas.height_ = surface->h;
    canvas.pitch_ = surface->pitch;
    canvas.pixels_ = static_cast<std::uint8_t*>(surface->pixels);
    return canvas;
}

Canvas::Canvas(Canvas&& other) noexcept {
    *this = std::move(other);
}

Canvas& Canvas::operator=(Canvas&& other) noexcept {
    if (this != &other) {
        if (owned_) SDL_FreeSurface(surface_);
        surface_ = std::exchange(other.surface_, nullptr);
        owned_ = std::exchange(other.owned_, false);
        width_ = std::exchange(other.width_, 0);
        height_ = std::exchange(other.height_, 0);
        pitch_ = std::exchange(other.pitch_, 0);
        pixels_ = std::exchange(other.pixels_, nullptr);
    }
    return *this;
}

Canvas::~Canvas() {
    if (owned_) SDL_FreeSurface(surface_);
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
    std::uint32_t v = c.argb();
    for (int y = 0; y < height_; ++y) std::fill_n(row(y), width_, v);
}

Canvas Canvas::clone() const {
    Canvas copy(width_, height_);
    for (int y = 0; y < height_; ++y) std::memcpy(copy.row(y), row(y), std::size_t(width_) * 4);
    return copy;
}

}  // namespace polar::render
