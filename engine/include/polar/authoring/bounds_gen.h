#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "polar/authoring/alpha_mask.h"
#include "polar/bound.h"
#include "polar/bounds_file.h"
#include "polar/error.h"

namespace polar {

// A set of sprite pixels, such as the opaque ones or one part of them, on the sprite's pixel grid.
// Pixel (x, y) is the square [x − w/2, x + 1 − w/2] × [h/2 − y − 1, h/2 − y] of bound space
// (AlphaMask's convention); a set always means those full squares, not the pixel centres.
struct PixelSet {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> member;  // row-major, top row first; 1 = in the set

    // Whether (x, y) is in the set; nothing outside the image is.
    bool has(int x, int y) const {
        return x >= 0 && y >= 0 && x < width && y < height && member[static_cast<std::size_t>(y) * width + x];
    }
    int count() const;
    // The mean of the member pixels' centres, in bound space (the origin for an empty set).
    Vec2 centroid() const;
    // The pixels whose alpha is above `threshold` (AlphaMask::opaque).
    static PixelSet opaque(const AlphaMask& mask, std::uint8_t threshold = AlphaMask::kDefaultThreshold);
};

// What generating bounds from a sprite asks for.
struct BoundsGenOptions {
    // Samples per Bound; 0 picks one per kAutoSpacing pixels of the outline's length.
    int samples = 0;
    // The centre in bound space (a single Bound only). Default: the centroid of the opaque
    // pixels; for a container, the sprite's centre (0, 0), around which its free space is drawn.
    std::optional<Vec2> centre;
    // How many Bound: more than one splits the sprite along its principal axis.
    int radii = 1;
    // Container bounds: the outline lies inside the free space around the centre, as large as it can.
    bool container = false;
    std::uint8_t threshold = AlphaMask::kDefaultThreshold;
    // Called now and then during long work with what is being done and the fraction done (0..1).
    std::function<void(const std::string& stage, double fraction)> progress;

    static constexpr double kAutoSpacing = 6.0;  // px of outline per sample when samples == 0
    static constexpr int kAutoMin = 8;
    static constexpr int kAutoMax = 64;
    static constexpr int kAutoMaxContainer = 192;
    static constexpr double kMaxGapDegrees = 150.0;  // the generator keeps every gap at most this
};

// How well one outline fits its pixels, measured along rays from its centre.
//
// For enclosing bounds, with ρ(φ) the distance from the centre to the farthest point of a member
// pixel square on the ray toward φ (0 when the ray meets none) and r(φ) the outline's radius
// (Bound::radius, exactly what the collision rule uses):
//   slack(φ) = r(φ) − ρ(φ): how far the outline stands off the sprite in that direction;
//   miss: how far any part of a member square lies outside the outline, along its ray.
// For container bounds, with σ(φ) the distance to the nearest point of a wall square (an opaque
// pixel, or anything outside the image) on the ray:
//   slack(φ) = σ(φ) − r(φ): free space the outline leaves before the wall;
//   miss: how far the outline reaches into a wall square, along the ray.
// Slack is taken over kSlackDirections directions φ_k = k · 360°/kSlackDirections. The miss is
// exact: it is the largest of (a) the miss over those directions and (b) the miss at every corner of
// a member (wall) square and at every sample's own ray. Within one edge's sector the outline is a
// straight line, so "inside" is a linear test and (b) is zero exactly when every square is wholly
// inside (outside) the outline.
struct FitQuality {
    double worstSlack = 0.0;         // px
    double worstSlackDegrees = 0.0;  // the direction of the worst slack
    double meanSlack = 0.0;          // px, averaged over the directions
    double worstMiss = 0.0;          // px; 0 when the outline encloses (avoids) every square
    int pixels = 0;                  // member pixels measured against

    static constexpr int kSlackDirections = 7200;  // every 0.05°
};

// Generated bounds, with the quality of each Bound in file order.
struct GeneratedBounds {
    BoundsSpec spec;
    std::vector<FitQuality> quality;
    std::vector<int> partPixels;  // opaque pixels assigned to each bound (all of them when one)
};

// Bounds from a sprite's alpha channel: for each Bound, sample angles and radii whose
// straight-edge outline (interpolate: true) encloses every opaque pixel square with the least area
// (a container's: stays inside the free space with the most area). Errors name no file; the caller
// adds it.
Result<GeneratedBounds> generateBounds(const AlphaMask& sprite, const BoundsGenOptions& options);

// `set` split into k parts (empty ones dropped) by where each pixel's centre projects on the principal
// axis of the pixel centres (the covariance's main eigenvector, θ = ½·atan2(2·sxy, sxx − syy)),
// cutting that axis's extent into k equal lengths.
std::vector<PixelSet> splitAlongPrincipalAxis(const PixelSet& set, int k);

// The quality of `bound` against `pixels` (see FitQuality); `container` measures against the walls.
FitQuality measureFit(const PixelSet& pixels, const Bound& bound, bool container);

}  // namespace polar
