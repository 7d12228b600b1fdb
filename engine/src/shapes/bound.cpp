#include "polar/bound.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numeric>
#include <sstream>

#include "shapes/outline.h"

namespace polar {
namespace {

std::string formatNumber(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

}  // namespace

Bound::Bound(const Vec2& centre, double radius) : Bound(centre, {RadiusSample{0.0, radius}}, false) {}

Bound::Bound(const Vec2& centre, std::vector<RadiusSample> samples, bool interpolate)
    : centre_(centre), samples_(std::move(samples)), interpolate_(interpolate) {
    assert(!samples_.empty());
    for (RadiusSample& s : samples_) {
        assert(std::isfinite(s.angle) && std::isfinite(s.radius) && s.radius > 0);
        s.angle = reduceRadians(s.angle);
        maxRadius_ = std::max(maxRadius_, s.radius);
    }
    std::sort(samples_.begin(), samples_.end(),
              [](const RadiusSample& a, const RadiusSample& b) { return a.angle < b.angle; });
    assert(std::adjacent_find(samples_.begin(), samples_.end(),
                              [](auto& a, auto& b) { return a.angle == b.angle; }) == samples_.end());
    chordDefined_ = samples_.size() >= 3;
    for (std::size_t k = 0; k < samples_.size(); ++k) {
        double gap = (k + 1 < samples_.size() ? samples_[k + 1].angle : samples_[0].angle + kTwoPi) -
                     samples_[k].angle;
        if (gap >= kPi) chordDefined_ = false;
    }
    if (samples_.size() == 1) chordDefined_ = true;  // a circle under either rule
    // Files are checked (check()) so that interpolate implies chordDefined; radii built in code may
    // ask for chord on samples that cannot have it, and get the nearest rule there.
    assert(!interpolate_ || samples_.size() >= 3);
    auto outlines = std::make_shared<Outlines>();
    outlines->nearest = Outline(samples_, OutlineShape::Nearest);
    outlines->chord = chordDefined_ ? Outline(samples_, OutlineShape::Chord) : outlines->nearest;
    outlines_ = std::move(outlines);
}

Bound Bound::fromDegrees(const Vec2& centre, const std::vector<DegreeSample>& samples, bool interpolate) {
    std::vector<RadiusSample> radians;
    radians.reserve(samples.size());
    for (const DegreeSample& s : samples) radians.push_back({degToRad(reduceDegrees(s[0])), s[1]});
    return Bound(centre, std::move(radians), interpolate);
}

std::optional<SampleProblem> Bound::check(const std::vector<DegreeSample>& samples, bool interpolate) {
    if (samples.empty()) return SampleProblem{SampleProblem::kWholeList, "no samples", "at least one sample"};
    for (std::size_t i = 0; i < samples.size(); ++i) {
        if (!std::isfinite(samples[i][0]) || !std::isfinite(samples[i][1]))
            return SampleProblem{i, "a non-finite number", "finite numbers [angle, radius]"};
        if (samples[i][1] <= 0)
            return SampleProblem{i, "radius " + formatNumber(samples[i][1]) + " is not positive",
                                 "a radius > 0"};
    }
    // Sort file indices by reduced angle; equal neighbours are the same direction.
    std::vector<std::size_t> order(samples.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    auto reduced = [&](std::size_t i) { return reduceDegrees(samples[i][0]); };
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return reduced(a) < reduced(b); });
    for (std::size_t k = 1; k < order.size(); ++k) {
        if (reduced(order[k]) == reduced(order[k - 1])) {
            std::size_t later = std::max(order[k], order[k - 1]);
            std::size_t earlier = std::min(order[k], order[k - 1]);
            return SampleProblem{later,
                                 "angle " + formatNumber(samples[later][0]) + " is the same direction as " +
                                     formatNumber(samples[earlier][0]) + " (sample " +
                                     std::to_string(earlier + 1) + ") modulo 360",
                                 "one sample per direction"};
        }
    }
    if (!interpolate) return std::nullopt;
    if (samples.size() < 3)
        return SampleProblem{SampleProblem::kWholeList,
                             "interpolate needs at least 3 samples, found " + std::to_string(samples.size()),
                             "3 or more samples, or \"interpolate\": false"};
    for (std::size_t k = 0; k < order.size(); ++k) {
        std::size_t i = order[k], j = order[(k + 1) % order.size()];
        double gap = reduced(j) - reduced(i);
        if (gap <= 0) gap += 360.0;
        if (gap >= 180.0)
            return SampleProblem{i,
                                 "a gap of " + formatNumber(gap) + " degrees from angle " +
                                     formatNumber(samples[i][0]) + " to the next sample at " +
                                     formatNumber(samples[j][0]),
                                 "gaps under 180 degrees between neighbouring samples, so the "
                                 "straight-edge outline stays star-shaped"};
    }
    return std::nullopt;
}

std::size_t Bound::segmentStart(double phi) const {
    auto next = std::upper_bound(samples_.begin(), samples_.end(), phi,
                                 [](double p, const RadiusSample& s) { return p < s.angle; });
    if (next == samples_.begin()) return samples_.size() - 1;
    return static_cast<std::size_t>(next - samples_.begin()) - 1;
}

double Bound::radiusNearest(double phi) const {
    return nearestRuleRadius(samples_, phi);
}

double Bound::radiusChord(double phi) const {
    if (samples_.size() == 1) return samples_[0].radius;
    phi = reduceRadians(phi);
    std::size_t k = segmentStart(phi);
    const RadiusSample& s1 = samples_[k];
    const RadiusSample& s2 = samples_[(k + 1) % samples_.size()];
    double delta = s2.angle - s1.angle;
    if (delta <= 0) delta += kTwoPi;
    double fromA1 = phi - s1.angle;
    if (fromA1 < 0) fromA1 += kTwoPi;
    double denominator = s1.radius * trig::sin(fromA1) + s2.radius * trig::sin(delta - fromA1);
    return s1.radius * s2.radius * trig::sin(delta) / denominator;
}

double Bound::radius(double phi, OutlineShape shape) const {
    return shape == OutlineShape::Chord && chordDefined_ ? radiusChord(phi) : radiusNearest(phi);
}

Vec2 Bound::outlinePoint(double phi) const {
    double s, c;
    trig::sincos(phi, s, c);
    return radius(phi) * Vec2(c, s);
}

double Bound::worldRadius(const Mat2& linear, const Vec2& worldDir, OutlineShape shape) const {
    double det = linear(0, 0) * linear(1, 1) - linear(0, 1) * linear(1, 0);
    if (det == 0.0 || !std::isfinite(det)) return 0.0;
    // d = L⁻¹·w = adj(L)·w / det. Keep e = adj(L)·w and the sign of det, not the division, so a tiny
    // det cannot overflow: angle(d) = angle(sign(det)·e) and |L·d̂| = |w|/|d| = |w|·|det|/|e|.
    Vec2 e(linear(1, 1) * worldDir.x() - linear(0, 1) * worldDir.y(),
           -linear(1, 0) * worldDir.x() + linear(0, 0) * worldDir.y());
    double eNorm = e.norm();
    if (eNorm == 0.0) return 0.0;
    if (det < 0) e = -e;
    double phi = trig::atan2(e.y(), e.x());
    return radius(phi, shape) * worldDir.norm() * std::fabs(det) / eNorm;
}

}  // namespace polar
