#pragma once
// Small helpers for drawing pixel art procedurally: colours, a seeded random source, value noise, a
// canvas with masks, outlines and ordered dithering. Everything is deterministic: no libm calls whose
// rounding differs between C libraries (the engine's own trig, sqrt and plain arithmetic only).
#include <cstdint>
#include <functional>
#include <vector>

#include "polar/math.h"
#include "polar/platform/png_io.h"

namespace polar::art {

// A straight-alpha colour with channels in [0, 1].
struct Colour {
    double r = 0, g = 0, b = 0, a = 1;

    static Colour hex(std::uint32_t rgb, double alpha = 1.0);
    Colour withAlpha(double alpha) const { return {r, g, b, alpha}; }
};

Colour mix(const Colour& a, const Colour& b, double t);
double clamp01(double v);
double smoothstep(double e0, double e1, double x);

// A seeded random source over the engine's splitmix64 (polar/splitmix64.h): its sequence is fixed by
// its seed on every platform (std::uniform_real_distribution is not).
class Random {
  public:
    explicit Random(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next();
    double uniform();                      // [0, 1)
    double uniform(double lo, double hi);  // [lo, hi)
    int below(int n);                      // [0, n)

  private:
    std::uint64_t state_;
};

// Smooth value noise in [0, 1] on a unit lattice, and its fractal sum over `octaves`.
double valueNoise(double x, double y, std::uint64_t seed);
double fbm(double x, double y, std::uint64_t seed, int octaves);

// The 4×4 Bayer threshold for ordered dithering, in (0, 1).
double bayer4(int x, int y);

// A ramp of palette colours from dark to light; `pick` quantises a shade in [0, 1] with dithering.
struct Ramp {
    std::vector<Colour> colours;
    // The colour for shade s at pixel (x, y): ordered dithering between neighbouring entries, with
    // `dither` ∈ [0, 1] the fraction of each step that is dithered (0: hard bands).
    Colour pick(double s, int x, int y, double dither = 0.5) const;
};

// A boolean mask over a w × h pixel grid.
struct Mask {
    int width = 0, height = 0;
    std::vector<std::uint8_t> bits;

    Mask(int w, int h) : width(w), height(h), bits(static_cast<std::size_t>(w) * h, 0) {}
    bool at(int x, int y) const {
        return x >= 0 && y >= 0 && x < width && y < height && bits[static_cast<std::size_t>(y) * width + x];
    }
    void set(int x, int y, bool v = true) {
        if (x >= 0 && y >= 0 && x < width && y < height) bits[static_cast<std::size_t>(y) * width + x] = v;
    }
    // Members with a 4-neighbour outside the mask.
    bool isEdge(int x, int y) const;
    // Non-members with a 4-neighbour (or, with `diagonal`, an 8-neighbour) inside the mask.
    bool touches(int x, int y, bool diagonal) const;
};

// A drawing surface: straight-alpha colours, converted to a PNG image at the end.
class Canvas {
  public:
    Canvas(int w, int h);
    int width() const { return width_; }
    int height() const { return height_; }
    const Colour& at(int x, int y) const { return pixels_[static_cast<std::size_t>(y) * width_ + x]; }
    void set(int x, int y, const Colour& c);
    // Source-over blend of c onto the pixel.
    void blend(int x, int y, const Colour& c);
    RgbaImage image() const;

  private:
    int width_, height_;
    std::vector<Colour> pixels_;
};

// Whether point (x, y) lies inside the polygon (even-odd rule).
bool insidePolygon(const std::vector<Vec2>& polygon, double x, double y);

}  // namespace polar::art
