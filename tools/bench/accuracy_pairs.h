#pragma once
// The accuracy benchmark's test set: the pairs of sprites, random placements of a pair near contact
// with the true contact distance D* from their opaque pixels, and four tests near contact per
// placement with their pixel truth.
#include <cstddef>
#include <functional>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include "accuracy_sprites.h"
#include "narrow_phase/pair_test.h"
#include "polar/collision.h"
#include "polar/math.h"

namespace polar::bench {

// Two sprites by index; the first is the container when one of them is.
using SpritePair = std::pair<std::size_t, std::size_t>;

// Two objects on a line: B approaches A (or, in a container, moves out from its centre) along `dir`.
struct Placement {
    std::size_t a = 0, b = 0;
    Vec2 position = Vec2::Zero();  // A's; B sits at position + D·dir
    Mat2 la, lb;
    Vec2 dir = Vec2::UnitX();
    double far = 0.0;    // a distance where nothing can touch yet (contact), or surely touches (container)
    double truth = 0.0;  // D*
    bool container = false;  // A holds B
};

// A test near contact: B at `distance` along its placement's line, and whether the pixels overlap.
struct Sample {
    std::size_t placement;
    double distance;
    bool truth;
};

// Every pair of sprites, each with itself too, but never two containers.
std::vector<SpritePair> spritePairs(const std::vector<Sprite>& sprites);
// `placementCount` placements, going round `pairs`, with their pixel truth; one whose line never brings the
// pixels into contact is left out and counted in `skipped`. Reports its progress on stderr.
std::vector<Placement> placeNearContact(const std::vector<Sprite>& sprites,
                                        const std::vector<SpritePair>& pairs, std::size_t placementCount,
                                        std::mt19937_64& rng, std::size_t& skipped);
// Four tests per placement at D* + δ (δ uniform in [−3, 3] px, never below 0), with their pixel truth.
std::vector<Sample> samplesNearContact(const std::vector<Sprite>& sprites,
                                       const std::vector<Placement>& placements, std::mt19937_64& rng);

// The pose of a placement's A, and of its B at distance `d` along the line.
ObjectPose poseA(const std::vector<Sprite>& sprites, const Placement& p);
ObjectPose poseB(const std::vector<Sprite>& sprites, const Placement& p, double d);

// Coming from `far` toward 0 in steps, the first distance at which `hit` holds, refined by bisection.
std::optional<double> firstContact(const std::function<bool(double)>& hit, double far, double step);

// Going out from 0 in steps, the first distance at which `hit` holds (touching the wall), refined.
std::optional<double> firstWallContact(const std::function<bool(double)>& hit, double far, double step);

}  // namespace polar::bench
