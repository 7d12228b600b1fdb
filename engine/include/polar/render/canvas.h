#pragma once
#include <cstddef>
#include <cstdint>
#include <new>
#include <vector>

#include "polar/render/color.h"

namespace polar::render {

namespace detail {

// Allocates on 64-byte boundaries (a cache line), where SIMD loads and stores like rows to start.
template <class T>
struct CacheLineAllocator {
    using value_type = T;
    static constexpr std::align_val_t kAlignment{64};

    CacheLineAllocator() = default;
    template <class U>
    CacheLineAllocator(const CacheLineAllocator<U>&) {}
    T* allocate(std::size_t n) { return static_cast<T*>(::operator new(n * sizeof(T), kAlignment)); }
    void deallocate(T* p, std::size_t) { ::operator delete(p, kAlignment); }
    template <class U>
    bool operator==(const CacheLineAllocator<U>&) const {
        return true;
    }
};

}  // namespace detail

// The surface everything is drawn into: ARGB8888 pixels (0xAARRGGBB), y down, pixel (x, y) the
// square [x, x+1) × [y, y+1) with its centre at (x + ½, y + ½) in canvas coordinates.
//
// Why plain memory? The renderer writes every pixel itself, so all it needs is a fixed pixel
// format, rows it can reach without locking, and one place where "outside the canvas" is decided.
// A Canvas owns its pixels (rows of 4·width bytes, the first one on a 64-byte boundary) or views
// memory someone else owns (wrap). The window and headless runs both draw into a Canvas, so a
// headless test sees exactly what a player sees. A Canvas is meant to be opaque: clear it with an
// opaque colour and blending keeps alpha at 255.
class Canvas {
  public:
    // A new width × height canvas, cleared to opaque black. Sizes must be positive.
    Canvas(int width, int height);
    // A canvas over width × height ARGB8888 pixels the caller owns, rows `pitchBytes` apart
    // (a multiple of 4, at least 4·width); the memory must outlive the canvas and is not freed here.
    static Canvas wrap(std::uint32_t* pixels, int width, int height, int pitchBytes);

    Canvas(Canvas&& other) noexcept;
    Canvas& operator=(Canvas&& other) noexcept;
    Canvas(const Canvas&) = delete;
    Canvas& operator=(const Canvas&) = delete;
    ~Canvas() = default;

    // Size in pixels.
    int width() const { return width_; }
    int height() const { return height_; }
    // Bytes from one row's first pixel to the next one's.
    int pitch() const { return stride_ * 4; }

    // Row y's first pixel; 0 ≤ y < height().
    std::uint32_t* row(int y) { return pixels_ + std::ptrdiff_t(y) * stride_; }
    const std::uint32_t* row(int y) const { return pixels_ + std::ptrdiff_t(y) * stride_; }
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
    // A deep copy (a new canvas that owns its pixels).
    Canvas clone() const;

  private:
    Canvas() = default;

    std::vector<std::uint32_t, detail::CacheLineAllocator<std::uint32_t>>
        owned_;                        // empty for a wrapped canvas
    std::uint32_t* pixels_ = nullptr;  // row 0, pixel 0
    int width_ = 0;
    int height_ = 0;
    int stride_ = 0;  // pixels from one row to the next, ≥ width
};

}  // namespace polar::render
