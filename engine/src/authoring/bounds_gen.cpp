#include "polar/authoring/bounds_gen.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "authoring/bounds_fit.h"
#include "authoring/radial_field.h"

namespace polar {

std::vector<PixelSet> splitAlongPrincipalAxis(const PixelSet& set, int k) {
    if (k <= 1) return {set};
    Vec2 mean = set.centroid();
    double sxx = 0, syy = 0, sxy = 0;
    std::vector<std::pair<int, int>> pixels;
    for (int y = 0; y < set.height; ++y)
        for (int x = 0; x < set.width; ++x)
            if (set.has(x, y)) {
                Vec2 d = Vec2(x + 0.5 - set.width * 0.5, set.height * 0.5 - y - 0.5) - mean;
                sxx += d.x() * d.x(), syy += d.y() * d.y(), sxy += d.x() * d.y();
                pixels.push_back({x, y});
            }
    // The principal axis of the covariance: θ = ½·atan2(2·sxy, sxx − syy).
    Vec2 axis = direction(0.5 * trig::atan2(2.0 * sxy, sxx - syy));
    double lo = kInf, hi = -kInf;
    auto along = [&](int x, int y) {
        return (Vec2(x + 0.5 - set.width * 0.5, set.height * 0.5 - y - 0.5) - mean).dot(axis);
    };
    for (auto [x, y] : pixels) lo = std::min(lo, along(x, y)), hi = std::max(hi, along(x, y));
    std::vector<PixelSet> parts(static_cast<std::size_t>(k), PixelSet{set.width, set.height, {}});
    for (PixelSet& part : parts) part.member.assign(set.member.size(), 0);
    for (auto [x, y] : pixels) {
        int index = hi > lo ? static_cast<int>((along(x, y) - lo) / (hi - lo) * k) : 0;
        parts[static_cast<std::size_t>(std::clamp(index, 0, k - 1))]
            .member[static_cast<std::size_t>(y) * set.width + x] = 1;
    }
    std::erase_if(parts, [](const PixelSet& p) { return p.count() == 0; });
    return parts;
}

int PixelSet::count() const {
    return static_cast<int>(std::count(member.begin(), member.end(), std::uint8_t{1}));
}

Vec2 PixelSet::centroid() const {
    Vec2 sum = Vec2::Zero();
    int n = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            if (has(x, y)) sum += Vec2(x + 0.5 - width * 0.5, height * 0.5 - y - 0.5), ++n;
    return n ? Vec2(sum / n) : Vec2(Vec2::Zero());
}

PixelSet PixelSet::opaque(const AlphaMask& mask, std::uint8_t threshold) {
    PixelSet set{mask.width, mask.height, {}};
    set.member.resize(mask.alpha.size());
    for (int y = 0; y < mask.height; ++y)
        for (int x = 0; x < mask.width; ++x)
            set.member[static_cast<std::size_t>(y) * mask.width + x] = mask.opaque(x, y, threshold) ? 1 : 0;
    return set;
}

Result<GeneratedBounds> generateBounds(const AlphaMask& sprite, const BoundsGenOptions& options) {
    if (options.samples != 0 && options.samples < 3)
        return optionError("-n " + std::to_string(options.samples) + " is too few samples",
                           "at least 3 samples (straight edges need 3), or 0 for automatic");
    if (options.samples > 720)
        return optionError("-n " + std::to_string(options.samples) + " is too many samples",
                           "at most 720 samples");
    if (options.radii < 1 || options.radii > 16)
        return optionError("--radii " + std::to_string(options.radii) + " is out of range", "1 to 16 radii");
    if (options.container && options.radii != 1)
        return optionError("--container with --radii " + std::to_string(options.radii),
                           "one bound for a container");
    if (options.radii > 1 && options.centre)
        return optionError("--centre with --radii " + std::to_string(options.radii),
                           "--centre only for one bound; each part of a split uses its own centroid");
    if (options.centre && !(std::isfinite(options.centre->x()) && std::isfinite(options.centre->y())))
        return optionError("a non-finite centre", "--centre X,Y with finite numbers");

    PixelSet opaque = PixelSet::opaque(sprite, options.threshold);
    GeneratedBounds out;
    if (!options.container && opaque.count() == 0)
        return optionError("no opaque pixels (alpha above " + std::to_string(options.threshold) + ")",
                           "a sprite with an opaque shape to enclose");
    std::vector<PixelSet> parts =
        options.container ? std::vector<PixelSet>{opaque} : splitAlongPrincipalAxis(opaque, options.radii);
    for (std::size_t k = 0; k < parts.size(); ++k) {
        Vec2 centre = options.centre      ? *options.centre
                      : options.container ? Vec2(Vec2::Zero())
                                          : parts[k].centroid();
        auto progress = [&](double fraction) {
            if (options.progress)
                options.progress("radii " + std::to_string(k + 1) + "/" + std::to_string(parts.size()),
                                 (k + fraction) / parts.size());
        };
        Result<BoundSpec> spec = fitBound(parts[k], centre, options.container, options.samples, progress);
        if (!spec) return spec.error();
        out.quality.push_back(
            measureFit(parts[k], Bound::fromDegrees(spec->centre, spec->samples, true), options.container));
        out.partPixels.push_back(parts[k].count());
        out.spec.radii.push_back(std::move(*spec));
    }
    if (options.progress) options.progress("done", 1.0);
    return out;
}

}  // namespace polar
