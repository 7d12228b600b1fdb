#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "polar/authoring/bounds_gen.h"
#include "polar/math.h"

namespace polar {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
// Points this close to a sample's ray (px) count as on it: its ray limit covers them.
inline constexpr double kOnRay = 1e-9;

// The unit vector at `radians`, with the engine's own trigonometry.
inline Vec2 direction(double radians) {
    double s, c;
    trig::sincos(radians, s, c);
    return Vec2(c, s);
}

// The angle of p in [0, 2π).
inline double angleOf(const Vec2& p) {
    return reduceRadians(trig::atan2(p.y(), p.x()));
}

// The pixels as seen from a centre: the squares on the set's boundary (only they can be the first or
// last thing a ray meets, or a corner an edge must clear), their corners sorted by angle, and the
// limit along any ray. For a container, the set is the walls and everything outside the image is
// wall too.
class RadialField {
  public:
    struct Corner {
        double angle;  // [0, 2π)
        Vec2 p;        // relative to the centre
        double dist;
    };

    RadialField(const PixelSet& set, const Vec2& centre, bool container);

    bool container() const { return container_; }
    const std::vector<Corner>& corners() const { return corners_; }
    double maxCornerDistance() const { return maxCornerDistance_; }

    // Enclosing: the distance to the farthest point of a square on the ray along unit u (0 if none).
    // Container: the distance to the nearest point of a wall square on it (∞ if none).
    double rayLimit(const Vec2& u) const;

    // rayLimit, also counting corners within kOnRay of the ray, which rounding may let the slab
    // test miss; the fitter leaves such corners to this limit.
    double rayLimitWithCorners(double angle) const;

    // The distance from the centre to the nearest square (0 when the centre is on one).
    double nearestSquareDistance() const;

    // Calls f for each corner with angle in [a1, a2] (radians, a1 ≤ a2, either may lie outside
    // [0, 2π): the range wraps).
    template <class F>
    void forEachCorner(double a1, double a2, F&& f) const {
        auto range = [&](double lo, double hi) {
            auto first = std::lower_bound(corners_.begin(), corners_.end(), lo,
                                          [](const Corner& c, double v) { return c.angle < v; });
            for (auto it = first; it != corners_.end() && it->angle <= hi; ++it) f(*it);
        };
        if (a2 - a1 >= kTwoPi) {
            range(0.0, kTwoPi);
            return;
        }
        double lo = a1, hi = a2;
        if (lo < 0.0) {
            range(lo + kTwoPi, kTwoPi);
            range(0.0, hi);
        } else if (hi >= kTwoPi) {
            range(lo, kTwoPi);
            range(0.0, hi - kTwoPi);
        } else {
            range(lo, hi);
        }
    }

  private:
    static constexpr int kBins = 2048;
    static std::size_t binOf(double angle) {
        long b = static_cast<long>(std::floor(angle * (kBins / kTwoPi)));
        return static_cast<std::size_t>(((b % kBins) + kBins) % kBins);
    }

    // Files each square under every angular bin it covers as seen from the centre (with a bin to
    // spare on either side), so that a ray only tests the squares it can meet.
    void fileSquaresByAngle();

    bool container_ = false;
    std::vector<Vec2> squares_;
    std::vector<std::vector<std::size_t>> bins_;
    std::vector<Corner> corners_;
    double maxCornerDistance_ = 0.0;
};

}  // namespace polar
