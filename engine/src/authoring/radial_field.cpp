#include "authoring/radial_field.h"

#include <cstdint>
#include <utility>

namespace polar {

RadialField::RadialField(const PixelSet& set, const Vec2& centre, bool container) : container_(container) {
    const int w = set.width, h = set.height;
    auto wall = [&](int x, int y) {
        if (x < 0 || y < 0 || x >= w || y >= h) return container;
        return set.has(x, y);
    };
    // Corner grid points (X, Y) with X ∈ [−1, w + 1], Y ∈ [−1, h + 1], deduplicated.
    const int gw = w + 3, gh = h + 3;
    std::vector<std::uint8_t> seen(static_cast<std::size_t>(gw) * gh, 0);
    const int lo = container ? -1 : 0;
    for (int y = lo; y < h - lo; ++y) {
        for (int x = lo; x < w - lo; ++x) {
            if (!wall(x, y)) continue;
            bool boundary = false;
            const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
            for (int k = 0; k < 4; ++k)
                if (!wall(nx[k], ny[k])) boundary = true;
            if (!boundary) continue;
            // Pixel (x, y) is [x − w/2, x + 1 − w/2] × [h/2 − y − 1, h/2 − y].
            Vec2 lowerLeft(x - w * 0.5, h * 0.5 - y - 1.0);
            squares_.push_back(lowerLeft - centre);
            for (int cy = y; cy <= y + 1; ++cy) {
                for (int cx = x; cx <= x + 1; ++cx) {
                    std::size_t key = static_cast<std::size_t>(cy + 1) * gw + (cx + 1);
                    if (seen[key]) continue;
                    seen[key] = 1;
                    Vec2 p = Vec2(cx - w * 0.5, h * 0.5 - cy) - centre;
                    double dist = p.norm();
                    if (dist > 0.0) corners_.push_back({angleOf(p), p, dist});
                }
            }
        }
    }
    std::sort(corners_.begin(), corners_.end(), [](const Corner& a, const Corner& b) {
        return a.angle < b.angle || (a.angle == b.angle && a.dist < b.dist);
    });
    for (const Corner& c : corners_) maxCornerDistance_ = std::max(maxCornerDistance_, c.dist);
    fileSquaresByAngle();
}

double RadialField::rayLimit(const Vec2& u) const {
    double best = container_ ? kInf : 0.0;
    for (std::size_t index : bins_[binOf(angleOf(u))]) {
        const Vec2& s = squares_[index];
        double tEnter = -kInf, tExit = kInf;
        bool hit = true;
        for (int a = 0; a < 2 && hit; ++a) {
            double lo = s[a], hi = s[a] + 1.0;
            if (u[a] == 0.0) {
                hit = lo <= 0.0 && 0.0 <= hi;
                continue;
            }
            double t1 = lo / u[a], t2 = hi / u[a];
            if (t1 > t2) std::swap(t1, t2);
            tEnter = std::max(tEnter, t1);
            tExit = std::min(tExit, t2);
        }
        if (!hit || tExit < std::max(tEnter, 0.0)) continue;
        if (container_)
            best = std::min(best, std::max(tEnter, 0.0));
        else
            best = std::max(best, tExit);
    }
    return best;
}

double RadialField::rayLimitWithCorners(double angle) const {
    Vec2 u = direction(angle);
    double limit = rayLimit(u);
    forEachCorner(angle - 1e-6, angle + 1e-6, [&](const Corner& c) {
        double along = c.p.dot(u);
        if (along <= 0.0 || std::fabs(cross(u, c.p)) > kOnRay) return;
        limit = container_ ? std::min(limit, along) : std::max(limit, along);
    });
    return limit;
}

double RadialField::nearestSquareDistance() const {
    double best = kInf;
    for (const Vec2& s : squares_) {
        double dx = std::max({s.x(), 0.0, -(s.x() + 1.0)});
        double dy = std::max({s.y(), 0.0, -(s.y() + 1.0)});
        best = std::min(best, std::hypot(dx, dy));
    }
    return best;
}

void RadialField::fileSquaresByAngle() {
    bins_.assign(kBins, {});
    for (std::size_t index = 0; index < squares_.size(); ++index) {
        const Vec2& s = squares_[index];
        if (s.x() <= 0.0 && s.y() <= 0.0 && s.x() + 1.0 >= 0.0 && s.y() + 1.0 >= 0.0) {
            for (auto& bin : bins_) bin.push_back(index);  // the centre is on this square
            continue;
        }
        // The square subtends less than 180°: measure its corners' angles from its first corner.
        double first = angleOf(s), least = 0.0, most = 0.0;
        for (int c = 1; c < 4; ++c) {
            double d = angleOf(s + Vec2(c & 1, c >> 1)) - first;
            if (d > kPi) d -= kTwoPi;
            if (d < -kPi) d += kTwoPi;
            least = std::min(least, d), most = std::max(most, d);
        }
        long from = static_cast<long>(std::floor((first + least) * (kBins / kTwoPi))) - 1;
        long to = static_cast<long>(std::floor((first + most) * (kBins / kTwoPi))) + 1;
        for (long b = from; b <= to; ++b)
            bins_[static_cast<std::size_t>(((b % kBins) + kBins) % kBins)].push_back(index);
    }
}

}  // namespace polar
