#include "polar/bound_outline.h"

#include <algorithm>
#include <cmath>

namespace polar {
namespace {

Vec2 apply(const Mat3& m, const Vec2& p) {
    return {m(0, 0) * p.x() + m(0, 1) * p.y() + m(0, 2), m(1, 0) * p.x() + m(1, 1) * p.y() + m(1, 2)};
}

Vec2 pointAt(double angle, double radius) {
    double s, c;
    trig::sincos(angle, s, c);
    return {c * radius, s * radius};
}

// The most chords an arc is cut into, so a huge zoom cannot make a huge polygon.
constexpr int kMaxChordsPerArc = 2048;

// How many chords an arc of `span` radians and bound radius r needs under stretch σ.
int chordsFor(double span, double radius, double stretch, double tolerance) {
    double reach = stretch * radius;
    int minimum = std::max(1, static_cast<int>(std::ceil(span / (kTwoPi / 8))));
    if (!(reach > tolerance) || !(tolerance > 0)) return minimum;
    // s = reach·(1 − cos(Δ/2)) ≤ tolerance  ⇔  Δ ≤ 2·acos(1 − tolerance/reach).
    double step = 2.0 * std::acos(1.0 - tolerance / reach);
    int chords = static_cast<int>(std::ceil(span / step));
    return std::clamp(chords, minimum, kMaxChordsPerArc);
}

}  // namespace

std::vector<Vec2> boundOutline(const Bound& bound, const Mat3& toTarget, double tolerance) {
    const std::vector<RadiusSample>& s = bound.samples();
    const Vec2& c = bound.centre();
    // The Frobenius norm of the linear part bounds its largest singular value from above.
    double stretch = toTarget.topLeftCorner<2, 2>().norm();
    std::vector<Vec2> points;
    auto arc = [&](double from, double to, double radius, bool withEnd) {
        int chords = chordsFor(to - from, radius, stretch, tolerance);
        for (int i = 0; i < chords + (withEnd ? 1 : 0); ++i)
            points.push_back(apply(toTarget, c + pointAt(from + (to - from) * i / chords, radius)));
    };
    if (s.size() == 1) {
        arc(0.0, kTwoPi, s[0].radius, false);
        return points;
    }
    if (bound.interpolate()) {
        for (const RadiusSample& sample : s)
            points.push_back(apply(toTarget, c + pointAt(sample.angle, sample.radius)));
        return points;
    }
    std::size_t n = s.size();
    for (std::size_t k = 0; k < n; ++k) {
        double a = s[k].angle;
        double before = s[(k + n - 1) % n].angle, after = s[(k + 1) % n].angle;
        if (before >= a) before -= kTwoPi;
        if (after <= a) after += kTwoPi;
        // Both ends of each arc: the radial step at a bisector joins one arc's end to the next one's start.
        arc((before + a) / 2, (a + after) / 2, s[k].radius, true);
    }
    return points;
}

std::vector<Vec2> boundSamplePoints(const Bound& bound, const Mat3& toTarget) {
    std::vector<Vec2> points;
    points.reserve(bound.samples().size());
    for (const RadiusSample& sample : bound.samples())
        points.push_back(apply(toTarget, bound.centre() + pointAt(sample.angle, sample.radius)));
    return points;
}

}  // namespace polar
