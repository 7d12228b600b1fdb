#pragma once
// Independent checks of bounds against pixels, for the generator's tests. Written apart from
// engine/src/bounds_gen.cpp on purpose: brute force over every pixel (not only boundary ones),
// Liang–Barsky clipping instead of slabs, libm trigonometry instead of the engine's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "polar/authoring/bounds_gen.h"
#include "polar/bound.h"

namespace polar::truth {

// A pixel square in bound space: [x0, x0 + 1] × [y0, y0 + 1].
inline Vec2 squareLowerLeft(int x, int y, int w, int h) {
    return Vec2(x - w * 0.5, h * 0.5 - y - 1.0);
}

// Clips the segment a + t·(b − a), t ∈ [t0, t1], to the box [lo, hi]; false when nothing is left.
inline bool clip(const Vec2& a, const Vec2& d, const Vec2& lo, const Vec2& hi, double& t0, double& t1) {
    for (int axis = 0; axis < 2; ++axis) {
        const double p[2] = {-d[axis], d[axis]};
        const double q[2] = {a[axis] - lo[axis], hi[axis] - a[axis]};
        for (int k = 0; k < 2; ++k) {
            if (p[k] == 0.0) {
                if (q[k] < 0.0) return false;
                continue;
            }
            double r = q[k] / p[k];
            if (p[k] < 0.0)
                t0 = std::max(t0, r);
            else
                t1 = std::min(t1, r);
        }
    }
    return t0 <= t1;
}

// Distances along rays from a centre to member squares: every member pixel is filed under the angular
// bins its square covers as seen from the centre, so a ray only clips against the squares it may meet.
class RayOracle {
  public:
    // `inset` shrinks every square on all sides (0: the closed squares).
    RayOracle(const PixelSet& set, const Vec2& centre, double inset = 0.0)
        : set_(set), centre_(centre), inset_(inset), bins_(kBins) {
        for (int y = 0; y < set.height; ++y)
            for (int x = 0; x < set.width; ++x) {
                if (!set.has(x, y)) continue;
                Vec2 lo = squareLowerLeft(x, y, set.width, set.height) - centre;
                if (lo.x() <= 0 && lo.y() <= 0 && lo.x() + 1 >= 0 && lo.y() + 1 >= 0) {
                    for (auto& bin : bins_) bin.push_back(lo);  // the centre is on this square
                    continue;
                }
                double first = std::atan2(lo.y(), lo.x()), least = 0.0, most = 0.0;
                for (int c = 1; c < 4; ++c) {
                    Vec2 q = lo + Vec2(c & 1, c >> 1);
                    double d = std::remainder(std::atan2(q.y(), q.x()) - first, 2 * kPi);
                    least = std::min(least, d), most = std::max(most, d);
                }
                long from = static_cast<long>(std::floor((first + least) / kBinWidth)) - 1;
                long to = static_cast<long>(std::floor((first + most) / kBinWidth)) + 1;
                for (long b = from; b <= to; ++b)
                    bins_[static_cast<std::size_t>(((b % kBins) + kBins) % kBins)].push_back(lo);
            }
    }

    // The distance to the farthest point of any member square on the ray toward φ (0 if none).
    double farthestMember(double phi) const {
        Vec2 d(std::cos(phi), std::sin(phi));
        double best = 0.0;
        for (const Vec2& lo : bin(phi)) {
            double t0 = 0.0, t1 = 1e6;
            if (clip(Vec2::Zero(), d, lo + Vec2(inset_, inset_), lo + Vec2(1 - inset_, 1 - inset_), t0, t1))
                best = std::max(best, t1);
        }
        return best;
    }

    // The distance to the nearest wall point on the ray toward φ: member squares, and everything
    // outside the image.
    double nearestWall(double phi) const {
        Vec2 d(std::cos(phi), std::sin(phi));
        double t0 = 0.0, t1 = 1e6;
        Vec2 half(set_.width * 0.5, set_.height * 0.5);
        clip(Vec2::Zero(), d, -half - centre_, half - centre_, t0, t1);
        double best = t1;
        for (const Vec2& lo : bin(phi)) {
            double s0 = 0.0, s1 = 1e6;
            if (clip(Vec2::Zero(), d, lo + Vec2(inset_, inset_), lo + Vec2(1 - inset_, 1 - inset_), s0, s1) &&
                (inset_ == 0.0 || s1 > s0))
                best = std::min(best, s0);
        }
        return best;
    }

  private:
    static constexpr int kBins = 1440;
    static constexpr double kBinWidth = 2 * kPi / kBins;
    const std::vector<Vec2>& bin(double phi) const {
        long b = static_cast<long>(std::floor(phi / kBinWidth));
        return bins_[static_cast<std::size_t>(((b % kBins) + kBins) % kBins)];
    }

    const PixelSet& set_;
    Vec2 centre_;
    double inset_ = 0.0;
    std::vector<std::vector<Vec2>> bins_;
};

struct Slack {
    double worst = -std::numeric_limits<double>::infinity();
    double mean = 0.0;
};

// Slack over the documented directions φ_k = k·360°/7200 (see FitQuality).
inline Slack slackOf(const PixelSet& set, const Bound& radii, bool container) {
    RayOracle oracle(set, radii.centre());
    Slack s;
    const int n = FitQuality::kSlackDirections;
    for (int k = 0; k < n; ++k) {
        double phi = k * 360.0 / n * (kPi / 180.0);
        double r = radii.radius(phi);
        double v = container ? oracle.nearestWall(phi) - r : r - oracle.farthestMember(phi);
        s.worst = std::max(s.worst, v);
        s.mean += v / n;
    }
    return s;
}

// The outline's vertices (sample points) in bound space.
inline std::vector<Vec2> vertices(const Bound& radii) {
    std::vector<Vec2> out;
    for (const RadiusSample& s : radii.samples())
        out.push_back(radii.centre() + s.radius * Vec2(std::cos(s.angle), std::sin(s.angle)));
    return out;
}

inline bool insideOutline(const Bound& radii, const Vec2& p, double tolerance) {
    Vec2 q = p - radii.centre();
    double dist = q.norm();
    return dist <= tolerance || dist <= radii.radius(std::atan2(q.y(), q.x())) + tolerance;
}

// Whether every member square lies wholly inside one of the radii: all four corners inside it and
// none of its outline vertices strictly inside the square (a straight edge can only cut into a
// square between its corners through a vertex). Reports the first offender.
inline ::testing::AssertionResult enclosesEveryPixel(const PixelSet& set, const Bounds& bounds) {
    const double eps = 1e-9;
    for (int y = 0; y < set.height; ++y)
        for (int x = 0; x < set.width; ++x) {
            if (!set.has(x, y)) continue;
            Vec2 lo = squareLowerLeft(x, y, set.width, set.height);
            bool covered = false;
            for (const Bound& r : bounds) {
                bool ok = true;
                for (int c = 0; c < 4 && ok; ++c) ok = insideOutline(r, lo + Vec2(c & 1, c >> 1), eps);
                for (const Vec2& v : vertices(r))
                    if (v.x() > lo.x() + eps && v.x() < lo.x() + 1 - eps && v.y() > lo.y() + eps &&
                        v.y() < lo.y() + 1 - eps)
                        ok = false;
                covered = covered || ok;
            }
            if (!covered)
                return ::testing::AssertionFailure()
                       << "opaque pixel (" << x << ", " << y << ") is not enclosed";
        }
    return ::testing::AssertionSuccess();
}

// Whether a container outline stays out of every wall square (member pixels and the outside of the
// image): no wall corner strictly inside, no edge through a wall square's interior, every vertex
// within the image.
inline ::testing::AssertionResult avoidsEveryWall(const PixelSet& set, const Bound& radii) {
    const double eps = 1e-9;
    std::vector<Vec2> v = vertices(radii);
    for (const Vec2& p : v)
        if (std::fabs(p.x()) > set.width * 0.5 + eps || std::fabs(p.y()) > set.height * 0.5 + eps)
            return ::testing::AssertionFailure()
                   << "vertex (" << p.x() << ", " << p.y() << ") is outside the image";
    for (int y = 0; y < set.height; ++y)
        for (int x = 0; x < set.width; ++x) {
            if (!set.has(x, y)) continue;
            Vec2 lo = squareLowerLeft(x, y, set.width, set.height);
            for (int c = 0; c < 4; ++c) {
                Vec2 q = lo + Vec2(c & 1, c >> 1) - radii.centre();
                if (q.norm() < radii.radius(std::atan2(q.y(), q.x())) - eps)
                    return ::testing::AssertionFailure()
                           << "a corner of wall pixel (" << x << ", " << y << ") is inside";
            }
        }
    for (std::size_t k = 0; k < v.size(); ++k) {
        Vec2 a = v[k], b = v[(k + 1) % v.size()];
        int x0 = static_cast<int>(std::floor(std::min(a.x(), b.x()) + set.width * 0.5)) - 1;
        int x1 = static_cast<int>(std::floor(std::max(a.x(), b.x()) + set.width * 0.5)) + 1;
        int y0 = static_cast<int>(std::floor(set.height * 0.5 - std::max(a.y(), b.y()))) - 1;
        int y1 = static_cast<int>(std::floor(set.height * 0.5 - std::min(a.y(), b.y()))) + 1;
        for (int y = std::max(y0, 0); y <= std::min(y1, set.height - 1); ++y)
            for (int x = std::max(x0, 0); x <= std::min(x1, set.width - 1); ++x) {
                if (!set.has(x, y)) continue;
                Vec2 lo = squareLowerLeft(x, y, set.width, set.height) + Vec2(eps, eps);
                double t0 = 0.0, t1 = 1.0;
                if (clip(a, b - a, lo, lo + Vec2(1 - 2 * eps, 1 - 2 * eps), t0, t1) && t1 - t0 > 1e-12)
                    return ::testing::AssertionFailure()
                           << "edge " << k << " crosses wall pixel (" << x << ", " << y << ")";
            }
    }
    return ::testing::AssertionSuccess();
}

}  // namespace polar::truth
