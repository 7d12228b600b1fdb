#include "accuracy_pairs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "shapes/outline.h"

namespace polar::bench {
namespace {

// A uniform double in [0, 1) from the generator's bits (std distributions differ between libraries).
double uniform(std::mt19937_64& rng) {
    return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

Mat2 randomLinear(std::mt19937_64& rng) {
    double rotation = uniform(rng) * kTwoPi;
    double s = std::exp(std::log(0.5) + uniform(rng) * std::log(4.0));  // 0.5 … 2, log-uniform
    Vec2 scale(s, s);
    if (uniform(rng) < 1.0 / 3) scale.y() = s * std::exp(std::log(0.5) + uniform(rng) * std::log(4.0));
    if (uniform(rng) < 0.25) scale.x() = -scale.x();
    if (uniform(rng) < 0.25) scale.y() = -scale.y();
    return rotationMatrix(rotation) * scale.asDiagonal();
}

// A world circle about the pose's position holding every bound's outline:
// max_k |L·c_k| + maxRadius_k·σmax.
double boundRadiusOf(const ObjectPose& pose) {
    double reach = 0.0;
    for (const Bound& r : *pose.bounds)
        reach = std::max(reach, (pose.linear * r.centre()).norm() + r.maxRadius() * pose.stretchMax);
    return reach;
}

// The distance between `miss` (where `hit` does not hold) and `touch` (where it does) at which it
// starts to hold, to 24 halvings of their gap.
double bisect(const std::function<bool(double)>& hit, double miss, double touch) {
    for (int i = 0; i < 24; ++i) {
        double mid = 0.5 * (miss + touch);
        (hit(mid) ? touch : miss) = mid;
    }
    return 0.5 * (miss + touch);
}

}  // namespace

std::vector<SpritePair> spritePairs(const std::vector<Sprite>& sprites) {
    std::vector<SpritePair> pairs;
    for (std::size_t i = 0; i < sprites.size(); ++i)
        for (std::size_t j = i; j < sprites.size(); ++j)
            if (!(sprites[i].container && sprites[j].container)) pairs.emplace_back(i, j);
    return pairs;
}

std::vector<Placement> placeNearContact(const std::vector<Sprite>& sprites,
                                        const std::vector<SpritePair>& pairs, std::size_t placementCount,
                                        std::mt19937_64& rng, std::size_t& skipped) {
    std::vector<Placement> placements;
    skipped = 0;
    for (std::size_t n = 0; n < placementCount; ++n) {
        if (n % 50 == 0) std::fprintf(stderr, "\r  pixel truth: %zu/%zu placements", n, placementCount);
        Placement p;
        std::tie(p.a, p.b) = pairs[n % pairs.size()];
        if (sprites[p.b].container) std::swap(p.a, p.b);  // the container is always A
        p.position = Vec2(200 * uniform(rng) - 100, 200 * uniform(rng) - 100);
        p.la = randomLinear(rng);
        p.lb = randomLinear(rng);
        double angle = uniform(rng) * kTwoPi;
        p.dir = Vec2(std::cos(angle), std::sin(angle));
        const Sprite& sa = sprites[p.a];
        const Sprite& sb = sprites[p.b];
        p.container = sa.container;
        ObjectPose poseA(p.position, p.la, sa.bounds.get(), flagsOf(sa)),
            poseB(p.position, p.lb, sb.bounds.get(), kCollisions);
        double pixelReach = sa.pixels.boundRadius() * LinearMap(p.la).stretchMax +
                            sb.pixels.boundRadius() * LinearMap(p.lb).stretchMax;
        p.far = std::max(pixelReach, boundRadiusOf(poseA) + boundRadiusOf(poseB)) * 1.02 + 1.0;
        auto truthAt = [&](double d) {
            return opaquePixelsOverlap(sa.pixels, p.position, p.la, sb.pixels, p.position + d * p.dir, p.lb);
        };
        std::optional<double> truth =
            p.container ? firstWallContact(truthAt, p.far, 1.0) : firstContact(truthAt, p.far, 0.25);
        if (!truth) {
            ++skipped;
            continue;
        }
        p.truth = *truth;
        placements.push_back(p);
    }
    std::fprintf(stderr, "\r  pixel truth: %zu/%zu placements\n", placementCount, placementCount);
    return placements;
}

std::vector<Sample> samplesNearContact(const std::vector<Sprite>& sprites,
                                       const std::vector<Placement>& placements, std::mt19937_64& rng) {
    std::vector<Sample> samples;
    for (std::size_t i = 0; i < placements.size(); ++i) {
        const Placement& p = placements[i];
        for (int k = 0; k < 4; ++k) {
            double d = std::max(0.0, p.truth + 6 * uniform(rng) - 3);
            bool truth = opaquePixelsOverlap(sprites[p.a].pixels, p.position, p.la, sprites[p.b].pixels,
                                             p.position + d * p.dir, p.lb);
            samples.push_back({i, d, truth});
        }
    }
    return samples;
}

ObjectPose poseA(const std::vector<Sprite>& sprites, const Placement& p) {
    return ObjectPose(p.position, p.la, sprites[p.a].bounds.get(), flagsOf(sprites[p.a]));
}

ObjectPose poseB(const std::vector<Sprite>& sprites, const Placement& p, double d) {
    return ObjectPose(p.position + d * p.dir, p.lb, sprites[p.b].bounds.get(), kCollisions);
}

std::optional<double> firstContact(const std::function<bool(double)>& hit, double far, double step) {
    for (double d = far; d > 0;) {
        double next = std::max(0.0, d - step);
        if (hit(next)) return bisect(hit, d, next);
        d = next;
    }
    return std::nullopt;
}

std::optional<double> firstWallContact(const std::function<bool(double)>& hit, double far, double step) {
    if (hit(0.0)) return 0.0;
    for (double d = 0; d < far;) {
        double next = std::min(far, d + step);
        if (hit(next)) return bisect(hit, d, next);
        d = next;
    }
    return std::nullopt;
}

}  // namespace polar::bench
