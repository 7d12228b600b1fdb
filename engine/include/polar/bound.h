#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "polar/math.h"

namespace polar {

// Which boundary joins neighbouring samples: the nearest sample's arc, or the straight chord.
enum class OutlineShape : std::uint8_t { Nearest, Chord };

// One sample of an adaptive-radius outline: the outline's distance from the centre in one direction.
struct RadiusSample {
    double angle = 0.0;   // radians in [0, 2π), counter-clockwise from +x
    double radius = 0.0;  // bound-space pixels, > 0
};

// A sample as a file writes it: degrees (any value, reduced modulo 360) and radius.
using DegreeSample = std::array<double, 2>;

// What is wrong with a list of samples, so a loader can point at the sample in its file.
struct SampleProblem {
    std::size_t index = 0;  // the offending sample in file order, or kWholeList
    std::string what;
    std::string expected;
    static constexpr std::size_t kWholeList = static_cast<std::size_t>(-1);
};

// A bound: one adaptive-radius outline, a centre in bound space plus samples of its radius by angle.
// An object's Bounds are a list of them.
//
// Why this shape? A sprite's silhouette seen from its centre is a radius for each direction. A few
// samples of that function describe irregular rocks far better than one circle, and the test stays
// cheap: one radius lookup per object per pair. Without `interpolate` the radius between samples is
// that of the nearest sample (a star of circular arcs); with it, neighbouring samples are joined by
// straight edges (a star-shaped polygon). Samples are kept sorted by angle; the sample order of a
// file is kept by BoundsSpec, not here.
//
// The formulas below (radius, worldRadius) are the plain reference: atan2, a binary search and sin.
// The collision loop uses the same outlines through Outline's precomputed sector tables, which give
// the same radii within rounding with no trigonometry at all; tests hold the two together.
class Bound {
  public:
    // A circle of radius r about the centre.
    Bound(const Vec2& centre, double radius);
    // Samples in any order and any angle range; they must pass check() (asserted).
    Bound(const Vec2& centre, std::vector<RadiusSample> samples, bool interpolate);
    // The same from file-style degree samples, reduced modulo 360 in degrees (so −90 and 270 agree).
    static Bound fromDegrees(const Vec2& centre, const std::vector<DegreeSample>& samples, bool interpolate);

    // The first problem with these samples (degrees, file order), or nothing when they are valid:
    // radius ≤ 0 or non-finite values, two angles equal modulo 360, and with interpolation fewer than
    // 3 samples or a circular gap of 180° or more (the outline would not be star-shaped).
    static std::optional<SampleProblem> check(const std::vector<DegreeSample>& samples, bool interpolate);

    const Vec2& centre() const { return centre_; }
    bool interpolate() const { return interpolate_; }
    // Sorted by ascending angle in [0, 2π).
    const std::vector<RadiusSample>& samples() const { return samples_; }
    double maxRadius() const { return maxRadius_; }

    // Whether the chord rule is defined for these samples: 3 or more, every circular gap under π.
    // (A file's interpolate flag guarantees it; a chosen accuracy level may ask for chord anyway.)
    bool chordDefined() const { return chordDefined_; }
    // The rule the file's interpolate flag selects.
    OutlineShape shape() const { return interpolate_ ? OutlineShape::Chord : OutlineShape::Nearest; }

    // The outline's distance from the centre toward bound-space angle φ (radians, any value).
    double radius(double phi) const { return radius(phi, shape()); }
    // The same under a chosen rule. Chord where chordDefined() is false falls back to nearest.
    double radius(double phi, OutlineShape shape) const;
    // The nearest sample's radius by circular angle distance; ties go to the sample first in
    // ascending angle order.
    double radiusNearest(double phi) const;
    // The straight edge between the neighbouring samples (a1, r1), (a2, r2), Δ = a2 − a1 circularly:
    // r(φ) = r1·r2·sin Δ / (r1·sin(φ − a1) + r2·sin(a2 − φ)). One sample is a circle.
    double radiusChord(double phi) const;
    // The outline point toward φ, in bound space relative to the centre.
    Vec2 outlinePoint(double phi) const;

    // The world radius toward world direction w (any length) under the linear part L = R·S:
    // d = L⁻¹·w, φ = angle(d), result = radius(φ)·|L·d̂|. Exact under rotation, non-uniform scale
    // and mirroring, because an affine map sends rays from the centre to rays from the centre.
    // A singular L (a scale of 0) or a zero w gives 0.
    double worldRadius(const Mat2& linear, const Vec2& worldDir) const {
        return worldRadius(linear, worldDir, shape());
    }
    // The same under a chosen rule (chord falls back to nearest where it is not defined).
    double worldRadius(const Mat2& linear, const Vec2& worldDir, OutlineShape shape) const;

  private:
    friend struct OutlineAccess;  // the collision loop's reading of the tables below
    struct Outlines;              // the sector tables of both rules, built once, shared by copies
    // The index k of the sample at or before φ ∈ [0, 2π), circularly (the last one when φ < a₀).
    std::size_t segmentStart(double phi) const;

    Vec2 centre_ = Vec2::Zero();
    std::vector<RadiusSample> samples_;
    bool interpolate_ = false;
    bool chordDefined_ = false;
    double maxRadius_ = 0.0;
    std::shared_ptr<const Outlines> outlines_;
};

// The seed's name for a Bound, kept so programs written against it still compile.
using CollisionRadii = Bound;

// An object's bounds: every Bound of one sprite, in file order (a hit takes the closest
// pair of radii). Shared by every object that uses the sprite.
using Bounds = std::vector<Bound>;
using BoundsPtr = std::shared_ptr<const Bounds>;

// Shared bounds made in code, for ObjectDef::bounds (files give them through loadBounds).
inline BoundsPtr makeBounds(Bounds bounds) {
    return std::make_shared<const Bounds>(std::move(bounds));
}
inline BoundsPtr makeBounds(Bound bound) {
    return makeBounds(Bounds{std::move(bound)});
}
// A circle of `radius` bound-space units about `centre`.
inline BoundsPtr circleBounds(double radius, const Vec2& centre = Vec2::Zero()) {
    return makeBounds(Bound(centre, radius));
}

}  // namespace polar
