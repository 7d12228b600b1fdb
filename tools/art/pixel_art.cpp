#include "pixel_art.h"

#include <algorithm>
#include <cmath>

#include "polar/splitmix64.h"

namespace polar::art {

Colour Colour::hex(std::uint32_t rgb, double alpha) {
    return {((rgb >> 16) & 0xFF) / 255.0, ((rgb >> 8) & 0xFF) / 255.0, (rgb & 0xFF) / 255.0, alpha};
}

Colour mix(const Colour& a, const Colour& b, double t) {
    return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t, a.a + (b.a - a.a) * t};
}

double clamp01(double v) {
    return std::clamp(v, 0.0, 1.0);
}

double smoothstep(double e0, double e1, double x) {
    double t = clamp01((x - e0) / (e1 - e0));
    return t * t * (3.0 - 2.0 * t);
}

std::uint64_t Random::next() {
    return splitmix64(state_);
}

double Random::uniform() {
    return static_cast<double>(next() >> 11) * (1.0 / 9007199254740992.0);
}
double Random::uniform(double lo, double hi) {
    return lo + (hi - lo) * uniform();
}
int Random::below(int n) {
    return static_cast<int>(uniform() * n);
}

namespace {

double lattice(long x, long y, std::uint64_t seed) {
    Random r(seed ^ (static_cast<std::uint64_t>(x) * 0x9E3779B1ull) ^
             (static_cast<std::uint64_t>(y) * 0x85EBCA77C2B2AE63ull));
    return r.uniform();
}

}  // namespace

double valueNoise(double x, double y, std::uint64_t seed) {
    double fx = std::floor(x), fy = std::floor(y);
    long ix = static_cast<long>(fx), iy = static_cast<long>(fy);
    double tx = x - fx, ty = y - fy;
    tx = tx * tx * (3.0 - 2.0 * tx);
    ty = ty * ty * (3.0 - 2.0 * ty);
    double a = lattice(ix, iy, seed), b = lattice(ix + 1, iy, seed);
    double c = lattice(ix, iy + 1, seed), d = lattice(ix + 1, iy + 1, seed);
    return (a + (b - a) * tx) + ((c + (d - c) * tx) - (a + (b - a) * tx)) * ty;
}

double fbm(double x, double y, std::uint64_t seed, int octaves) {
    double sum = 0, weight = 0, amplitude = 1, frequency = 1;
    for (int k = 0; k < octaves; ++k) {
        sum +=
            amplitude * valueNoise(x * frequency, y * frequency, seed + static_cast<std::uint64_t>(k) * 7919);
        weight += amplitude;
        amplitude *= 0.5;
        frequency *= 2.0;
    }
    return sum / weight;
}

double bayer4(int x, int y) {
    static constexpr int kMatrix[4][4] = {{0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};
    return (kMatrix[((y % 4) + 4) % 4][((x % 4) + 4) % 4] + 0.5) / 16.0;
}

Colour Ramp::pick(double s, int x, int y, double dither) const {
    int n = static_cast<int>(colours.size());
    double v = clamp01(s) * (n - 1);
    int lo = std::min(static_cast<int>(std::floor(v)), n - 1);
    double frac = v - lo;
    // Within the middle `dither` part of a step, the Bayer threshold decides; outside it, the nearer
    // colour wins outright.
    double t = dither > 0 ? clamp01((frac - 0.5) / dither + 0.5) : (frac >= 0.5 ? 1.0 : 0.0);
    int index = (t > bayer4(x, y)) ? std::min(lo + 1, n - 1) : lo;
    return colours[static_cast<std::size_t>(index)];
}

bool Mask::isEdge(int x, int y) const {
    return at(x, y) && (!at(x - 1, y) || !at(x + 1, y) || !at(x, y - 1) || !at(x, y + 1));
}

bool Mask::touches(int x, int y, bool diagonal) const {
    if (at(x, y)) return false;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            if (dx == 0 && dy == 0) continue;
            if (!diagonal && dx != 0 && dy != 0) continue;
            if (at(x + dx, y + dy)) return true;
        }
    return false;
}

Canvas::Canvas(int w, int h)
    : width_(w), height_(h), pixels_(static_cast<std::size_t>(w) * h, Colour{0, 0, 0, 0}) {}

void Canvas::set(int x, int y, const Colour& c) {
    if (x >= 0 && y >= 0 && x < width_ && y < height_) pixels_[static_cast<std::size_t>(y) * width_ + x] = c;
}

void Canvas::blend(int x, int y, const Colour& c) {
    if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
    Colour& d = pixels_[static_cast<std::size_t>(y) * width_ + x];
    double a = c.a + d.a * (1.0 - c.a);
    if (a <= 0) {
        d = Colour{0, 0, 0, 0};
        return;
    }
    auto channel = [&](double s, double t) { return (s * c.a + t * d.a * (1.0 - c.a)) / a; };
    d = Colour{channel(c.r, d.r), channel(c.g, d.g), channel(c.b, d.b), a};
}

RgbaImage Canvas::image() const {
    RgbaImage out{width_, height_, {}};
    out.pixels.reserve(pixels_.size());
    auto byte = [](double v) { return static_cast<std::uint32_t>(std::lround(clamp01(v) * 255.0)); };
    for (const Colour& c : pixels_) {
        std::uint32_t a = byte(c.a);
        out.pixels.push_back(a == 0 ? 0u : (a << 24) | (byte(c.r) << 16) | (byte(c.g) << 8) | byte(c.b));
    }
    return out;
}

bool insidePolygon(const std::vector<Vec2>& polygon, double x, double y) {
    bool inside = false;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const Vec2& a = polygon[i];
        const Vec2& b = polygon[j];
        if ((a.y() > y) != (b.y() > y) && x < (b.x() - a.x()) * (y - a.y()) / (b.y() - a.y()) + a.x())
            inside = !inside;
    }
    return inside;
}

}  // namespace polar::art
