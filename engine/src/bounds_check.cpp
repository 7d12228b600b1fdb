#include "polar/bounds_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>

namespace polar {
namespace {

std::string pixels(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.1f", v);
    return buffer;
}

std::string number(double v) { return nlohmann::json(v).dump(); }

// The distance from p to the nearest pixel square for which `wanted(x, y)` holds (∞ if none).
template <class Wanted>
double distanceToPixels(const AlphaMask& mask, const Vec2& p, int margin, Wanted&& wanted) {
    double best = std::numeric_limits<double>::infinity();
    for (int y = -margin; y < mask.height + margin; ++y) {
        for (int x = -margin; x < mask.width + margin; ++x) {
            if (!wanted(x, y)) continue;
            // Square [x0, x0 + 1] × [y0, y0 + 1] in bound space.
            double x0 = x - mask.width * 0.5, y0 = mask.height * 0.5 - y - 1.0;
            double dx = std::max({x0 - p.x(), 0.0, p.x() - (x0 + 1.0)});
            double dy = std::max({y0 - p.y(), 0.0, p.y() - (y0 + 1.0)});
            best = std::min(best, std::hypot(dx, dy));
        }
    }
    return best;
}

}  // namespace

std::vector<BoundsWarning> suspiciousBounds(const BoundsSpec& spec, const AlphaMask& sprite, std::uint8_t threshold) {
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
        const RadiiSpec& r = spec.radii[i];
        std::string at = "/radii/" + std::to_string(i);
        if (std::fabs(r.centre.x()) > halfW || std::fabs(r.centre.y()) > halfH)
            out.push_back({at + "/centre",
                           "the centre [" + number(r.centre.x()) + ", " + number(r.centre.y()) +
                               "] lies outside the " + std::to_string(sprite.width) + "x" +
                               std::to_string(sprite.height) + " sprite",
                           "a centre within [" + number(-halfW) + ", " + number(halfW) + "] x [" + number(-halfH) +
                               ", " + number(halfH) + "] (sprite pixels, origin at the sprite's centre, y up)"});
        for (std::size_t k = 0; k < r.samples.size(); ++k) {
            double angle = degToRad(reduceDegrees(r.samples[k][0]));
            double s, c;
            trig::sincos(angle, s, c);
            Vec2 p = r.centre + r.samples[k][1] * Vec2(c, s);
            double limit = std::max(SuspicionLimits::kMinPixels, SuspicionLimits::kFraction * r.samples[k][1]);
            std::string sample = "sample " + std::to_string(k + 1) + " [" + number(r.samples[k][0]) + ", " +
                                 number(r.samples[k][1]) + "]";
            std::string pointer = at + "/samples/" + std::to_string(k);
            int px = 0, py = 0;
            sprite.pixelAt(p, px, py);
            if (!sprite.opaque(px, py, threshold)) {
                double d = distanceToPixels(sprite, p, 0, [&](int x, int y) { return sprite.opaque(x, y, threshold); });
                if (d > limit)
                    out.push_back({pointer, sample + " lies " + pixels(d) + " px outside the sprite's opaque area",
                                   "a sample point within " + pixels(limit) + " px of the sprite's edge"});
            } else {
                double d = distanceToPixels(sprite, p, 1, [&](int x, int y) { return !sprite.opaque(x, y, threshold); });
                if (d > limit)
                    out.push_back({pointer, sample + " lies " + pixels(d) + " px inside the sprite's opaque area",
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
    std::string stem = name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0
                           ? name.substr(0, name.size() - suffix.size())
                           : path.stem().string();
    std::vector<std::string> out{(path.parent_path() / (stem + ".png")).generic_string()};
    if (path.parent_path().filename() == "bounds")
        out.push_back((path.parent_path().parent_path() / "sprites" / (stem + ".png")).generic_string());
    return out;
}

}  // namespace polar
