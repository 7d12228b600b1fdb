#pragma once
#include <cstdint>

#include "polar/render/color.h"

struct SDL_Surface;

namespace polar::render {

// The surface everything is drawn into: ARGB8888 pixels (0xAARRGGBB), y down, pixel (x, y) the
// square [x, x+1) × [y, y+1) with its centre at (x + ½, y + ½) in canvas coordinates.
//
// Why its own class around an SDL_Surface? The renderer writes pixels itself (SDL is only the
// container and the PNG codec), so it needs a fixed pixel format, row access without locking, and
// one place where "outside the canvas" is decided. The window and headless runs both draw into a
// Canvas, so a headless test sees exactly what a player sees. A Canvas is meant to be opaque: clear
// it with an opaque colour and blending keeps alpha at 255.
class Canvas {
  public:
    // A new width × height surface, cleared to opaque black. Sizes must be positive.
    Canvas(int width, int height);
    // Wraps a surface the caller owns (it must be ARGB8888 and need no locking); not freed here.
    static Canvas wrap(SDL_Surface* surface);

    Canvas(Canvas&& other) noexcept;
    Canvas& operator=(Canvas&& other) noexcept;
    Canvas(const Canvas&) = delete;
    Canvas& operator=(const Canvas&) = delete;
    ~Canvas();

    // Size in pixels.
    int width() const { return width_; }
    int height() const { return height_; }
    // The underlying SDL surface (for PNG I/O and presenting).
    SDL_Surface* surface() const { return surface_; }

    // Row y's first pixel; 0 ≤ y < height().
    std::uint32_t* row(int y) {
        return reinterpret_cast<std::uint32_t*>(pixels_ + std::intptr_t(y) * pitch_);
    }
    const std::uint32_t* row(int y) const {
        return reinterpret_cast<const std::uint32_t*>(pixels_ + std::intptr_t(y) * pitch_);
    }
    // True when (x, y) is a pixel of the canvas.
    bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }

    // The colour at (x, y); transparent black outside the canvas.
    Color pixel(int x, int y) const;
    // Sets (x, y) to c without blending; does nothing outside the canvas.
    void setPixel(int x, int y, Color c);
    // Blends c over (x, y) ("over" operator); does nothing outside the canvas.
    void blendPixel(int x, int y, Color c);
    // Sets every pixel to c.
    void clear(Color c = kBlack);
    // A deep copy (a new owned surface).
    Canvas clone() const;

  private:
    Canvas() = default;

    SDL_Surface* surface_ = nullptr;
    bool owned_ = false;
    int width_ = 0;
    int height_ = 0;
    int pitch_ = 0;  // bytes per row, ≥ 4·width
    std::uint8_t* pixels_ = nullptr;
};

}  // namespace polar::render
