#include "polar/authoring/bounds_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "polar/image_extensions.h"
#include "polar/json_writer.h"

namespace polar {
namespace {

std::string pixels(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.1f", v);
    return buffer;
}

// The distance from p to the nearest pixel square for which `wanted(x, y)` holds, searching pixels
// x ∈ [−margin, w + margin), y likewise (∞ if none). Looks in growing boxes around p: a box reaching
// `reach` pixels beyond p's pixel holds every square nearer than `reach`, so a hit nearer than that
// is final.
template <class Wanted>
double distanceToPixels(const AlphaMask& mask, const Vec2& p, int margin, Wanted&& wanted) {
    int px = 0, py = 0;
    mask.pixelAt(p, px, py);
    const int span = std::max(mask.width, mask.height) + 2 * margin;
    for (int reach = 8;; reach *= 2) {
        double best = std::numeric_limits<double>::infinity();
        int x0 = std::max(px - reach, -margin), x1 = std::min(px + reach, mask.width + margin - 1);
        int y0 = std::max(py - reach, -margin), y1 = std::min(py + reach, mask.height + margin - 1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                if (!wanted(x, y)) continue;
                // Square [sx, sx + 1] × [sy, sy + 1] in bound space.
                double sx = x - mask.width * 0.5, sy = mask.height * 0.5 - y - 1.0;
                double dx = std::max({sx - p.x(), 0.0, p.x() - (sx + 1.0)});
                double dy = std::max({sy - p.y(), 0.0, p.y() - (sy + 1.0)});
                best = std::min(best, std::hypot(dx, dy));
            }
        if (best <= reach || reach > span + std::abs(px) + std::abs(py)) return best;
    }
}

}  // namespace

std::vector<BoundsWarning> suspiciousBounds(const BoundsSpec& spec, const AlphaMask& sprite,
                                            std::uint8_t threshold) {
    std::vector<BoundsWarning> out;
    bool anyOpaque = false;
    for (int y = 0; y < sprite.height && !anyOpaque; ++y)
        for (int x = 0; x < sprite.width && !anyOpaque; ++x) anyOpaque = sprite.opaque(x, y, threshold);
    if (!anyOpaque) {
        out.push_back({"", "the sprite has no opaque pixels (alpha above " + std::to_string(threshold) + ")",
                       "a sprite with a visible shape for these bounds"});
        return out;
    }
    const double halfW = sprite.width * 0.5, halfH = sprite.height * 0.5;
    for (std::size_t i = 0; i < spec.radii.size(); ++i) {
        const BoundSpec& r = spec.radii[i];
        std::string at = "/radii/" + std::to_string(i);
        if (std::fabs(r.centre.x()) > halfW || std::fabs(r.centre.y()) > halfH)
            out.push_back({at + "/centre",
                           "the centre [" + jsonNumberText(r.centre.x()) + ", " +
                               jsonNumberText(r.centre.y()) + "] lies outside the " +
                               std::to_string(sprite.width) + "x" + std::to_string(sprite.height) + " sprite",
                           "a centre within [" + jsonNumberText(-halfW) + ", " + jsonNumberText(halfW) +
                               "] x [" + jsonNumberText(-halfH) + ", " + jsonNumberText(halfH) +
                               "] (sprite pixels, origin at the sprite's centre, y up)"});
        for (std::size_t k = 0; k < r.samples.size(); ++k) {
            double angle = degToRad(reduceDegrees(r.samples[k][0]));
            double s, c;
            trig::sincos(angle, s, c);
            Vec2 p = r.centre + r.samples[k][1] * Vec2(c, s);
            double limit =
                std::max(SuspicionLimits::kMinPixels, SuspicionLimits::kFraction * r.samples[k][1]);
            std::string sample = "sample " + std::to_string(k + 1) + " [" + jsonNumberText(r.samples[k][0]) +
                                 ", " + jsonNumberText(r.samples[k][1]) + "]";
            std::string pointer = at + "/samples/" + std::to_string(k);
            int px = 0, py = 0;
            sprite.pixelAt(p, px, py);
            if (!sprite.opaque(px, py, threshold)) {
                double d = distanceToPixels(sprite, p, 0,
                                            [&](int x, int y) { return sprite.opaque(x, y, threshold); });
                if (d > limit)
                    out.push_back({pointer,
                                   sample + " lies " + pixels(d) + " px outside the sprite's opaque area",
                                   "a sample point within " + pixels(limit) + " px of the sprite's edge"});
            } else {
                double d = distanceToPixels(sprite, p, 1,
                                            [&](int x, int y) { return !sprite.opaque(x, y, threshold); });
                if (d > limit)
                    out.push_back({pointer,
                                   sample + " lies " + pixels(d) + " px inside the sprite's opaque area",
                                   "a sample point within " + pixels(limit) +
                                       " px of the sprite's edge (the outline cuts into the sprite here)"});
            }
        }
    }
    return out;
}

std::vector<std::string> spriteCandidates(const std::string& boundsPath) {
    namespace fs = std::filesystem;
    fs::path path(boundsPath);
    std::string name = path.filename().string();
    const std::string suffix = ".bounds.json";
    std::string stem =
        name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0
            ? name.substr(0, name.size() - suffix.size())
            : path.stem().string();
    // Beside the file first, then in sprites/ for bounds/NAME.bounds.json; PNG first in each place.
    std::vector<std::string> out;
    for (std::string_view ext : kImageExtensions)
        out.push_back((path.parent_path() / (stem + std::string(ext))).generic_string());
    if (path.parent_path().filename() == "bounds")
        for (std::string_view ext : kImageExtensions)
            out.push_back(
                (path.parent_path().parent_path() / "sprites" / (stem + std::string(ext))).generic_string());
    return out;
}

}  // namespace polar
