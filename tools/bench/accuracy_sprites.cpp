#include "accuracy_sprites.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>

#include "polar/bounds_file.h"
#include "polar/platform/png_io.h"

namespace polar::bench {
namespace {

// Whether the sprite's opaque pixels surround its transparent centre: walking out from the centre
// in each of 16 directions meets an opaque pixel.
bool surroundsItsCentre(const OpaquePixels& pixels) {
    int x, y;
    pixels.mask().pixelAt(Vec2::Zero(), x, y);
    if (pixels.opaque(x, y)) return false;
    for (int k = 0; k < 16; ++k) {
        Vec2 dir(std::cos(kTwoPi * k / 16), std::sin(kTwoPi * k / 16));
        bool met = false;
        for (double t = 0; t < pixels.boundRadius() && !met; t += 0.5) {
            pixels.mask().pixelAt(t * dir, x, y);
            met = pixels.opaque(x, y);
        }
        if (!met) return false;
    }
    return true;
}

AlphaMask drawMask(int width, int height, const std::function<bool(const Vec2&)>& inside) {
    AlphaMask mask;
    mask.width = width;
    mask.height = height;
    mask.alpha.assign(static_cast<std::size_t>(width) * height, 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            mask.alpha[static_cast<std::size_t>(y) * width + x] = inside(mask.pixelCentre(x, y)) ? 255 : 0;
    return mask;
}

// Radii about `centre` whose samples reach where each ray leaves the last opaque pixel within `keep`.
Bound traceRadii(const OpaquePixels& pixels, const Vec2& centre, int count, bool interpolate,
                 const std::function<bool(const Vec2&)>& keep) {
    std::vector<RadiusSample> samples;
    for (int k = 0; k < count; ++k) {
        double angle = kTwoPi * k / count;
        Vec2 dir(std::cos(angle), std::sin(angle));
        double last = 0.5;
        for (double t = 0; t < 200; t += 0.02) {
            Vec2 p = centre + t * dir;
            int x, y;
            pixels.mask().pixelAt(p, x, y);
            if (keep(p) && pixels.opaque(x, y)) last = t;
        }
        samples.push_back({angle, last + 0.02});
    }
    return Bound(centre, samples, interpolate);
}

}  // namespace

std::vector<Sprite> loadSprites(const std::string& dir, std::string& problem) {
    std::vector<Sprite> sprites;
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) return sprites;
    std::vector<std::filesystem::path> pngs;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
        if (entry.path().extension() == ".png") pngs.push_back(entry.path());
    std::sort(pngs.begin(), pngs.end());
    for (const auto& png : pngs) {
        std::filesystem::path boundsPath = png;
        boundsPath.replace_extension(".bounds.json");
        if (!std::filesystem::exists(boundsPath)) continue;
        Result<RgbaImage> image = loadPng(png.string());
        if (!image) {
            problem = image.error().message();
            return {};
        }
        Result<BoundsPtr> bounds = loadBounds(boundsPath.string(), diskReader());
        if (!bounds) {
            problem = bounds.error().message();
            return {};
        }
        if ((*bounds)->empty()) continue;
        OpaquePixels pixels(alphaMaskOf(*image));
        bool container = surroundsItsCentre(pixels);
        sprites.push_back({png.stem().string(), std::move(pixels), *bounds, container});
    }
    return sprites;
}

std::vector<Sprite> standInSprites() {
    std::vector<Sprite> sprites;
    auto all = [](const Vec2&) { return true; };
    {  // a lumpy rock, read with the nearest rule (a star of arcs)
        OpaquePixels px(drawMask(52, 48, [](const Vec2& p) {
            double a = std::atan2(p.y(), p.x());
            return p.norm() < 17 + 3.5 * std::sin(3 * a + 1) + 2 * std::cos(5 * a);
        }));
        Bounds b{traceRadii(px, Vec2::Zero(), 32, false, all)};
        sprites.push_back({"rock", px, std::make_shared<const Bounds>(b)});
    }
    {  // a dart: a concave quadrilateral, read by chord
        auto inTriangle = [](const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
            double d1 = cross(b - a, p - a), d2 = cross(c - b, p - b), d3 = cross(a - c, p - c);
            return (d1 >= 0 && d2 >= 0 && d3 >= 0) || (d1 <= 0 && d2 <= 0 && d3 <= 0);
        };
        OpaquePixels px(drawMask(44, 36, [&](const Vec2& p) {
            return inTriangle(p, Vec2(20, 0), Vec2(-16, 15), Vec2(-9, 0)) ||
                   inTriangle(p, Vec2(20, 0), Vec2(-9, 0), Vec2(-16, -15));
        }));
        Bounds b{traceRadii(px, Vec2::Zero(), 24, true, all)};
        sprites.push_back({"dart", px, std::make_shared<const Bounds>(b)});
    }
    {  // a long bar, three radii along it
        OpaquePixels px(
            drawMask(74, 10, [](const Vec2& p) { return std::fabs(p.x()) < 35 && std::fabs(p.y()) < 3.5; }));
        Bounds b;
        for (double cx : {-24.0, 0.0, 24.0})
            b.push_back(traceRadii(px, Vec2(cx, 0), 16, true,
                                   [cx](const Vec2& p) { return std::fabs(p.x() - cx) <= 12; }));
        sprites.push_back({"bar", px, std::make_shared<const Bounds>(b)});
    }
    return sprites;
}

ObjectFlags flagsOf(const Sprite& s) {
    return s.container ? kCollisions | kContainer : kCollisions;
}

}  // namespace polar::bench
