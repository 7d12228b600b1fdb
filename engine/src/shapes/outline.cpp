#include "shapes/outline.h"

#include <algorithm>
#include <bit>
#include <cassert>

#include "polar/bound.h"

namespace polar {
namespace {

// The distance from the origin to the segment P1P2.
double originToSegment(const Vec2& p1, const Vec2& p2) {
    Vec2 d = p2 - p1;
    double len2 = d.squaredNorm();
    double lambda = len2 > 0 ? std::clamp(-p1.dot(d) / len2, 0.0, 1.0) : 0.0;
    return (p1 + lambda * d).norm();
}

Outline::Ray rayAt(double angle, double radius) {
    Outline::Ray ray;
    double s, c;
    trig::sincos(angle, s, c);
    ray.dir = Vec2(c, s);
    ray.pseudo = pseudoAngle(c, s);
    ray.radius = radius;
    return ray;
}

}  // namespace

LinearMap::LinearMap(const Mat2& l) : linear(l) {
    double a = l(0, 0), b = l(0, 1), c = l(1, 0), d = l(1, 1);
    double det = a * d - b * c;
    mirrored = det < 0;
    absDet = std::isfinite(det) ? std::fabs(det) : 0.0;
    // σmax ± σmin = √(‖L‖F² ± 2|det L|), since ‖L‖F² = σmax² + σmin² and |det L| = σmax·σmin.
    double frobenius = a * a + b * b + c * c + d * d;
    double sum = std::sqrt(frobenius + 2 * absDet);
    double difference = std::sqrt(std::max(0.0, frobenius - 2 * absDet));
    stretchMax = 0.5 * (sum + difference);
    // σmin = |det L| / σmax, more accurate than (sum − difference)/2; stretchMin() computes it so.
    condition = absDet == 0.0 ? INFINITY : stretchMax / stretchMin();
}

Outline::Outline(const std::vector<RadiusSample>& sorted, OutlineShape shape) : shape_(shape) {
    assert(!sorted.empty());
    std::size_t count = sorted.size();
    maxRadius_ = 0.0;
    minRadius_ = INFINITY;
    for (const RadiusSample& s : sorted) {
        maxRadius_ = std::max(maxRadius_, s.radius);
        minRadius_ = std::min(minRadius_, s.radius);
    }
    sectors_.clear();
    if (count == 1) {
        shape_ = OutlineShape::Nearest;  // one sample is a circle under either rule
        sectors_.push_back(Sector{0.0, 0.0, sorted[0].radius, INFINITY});
    } else if (shape == OutlineShape::Chord) {
        assert(count >= 3);
        for (const RadiusSample& s : sorted) rays_.push_back(rayAt(s.angle, s.radius));
        // Sector j is the edge from vertex j − 1 to vertex j; sectors 0 and S the edge from S − 1 to 0.
        auto edge = [&](std::size_t from, std::size_t to, double end) {
            Vec2 p1 = rays_[from].radius * rays_[from].dir, p2 = rays_[to].radius * rays_[to].dir;
            // The line through P1 and P2: n = (P2 − P1) turned clockwise (outward for counter-clockwise
            // vertices), h = n·P1 = cross(P1, P2) = r1·r2·sin Δ > 0 while Δ < π.
            return Sector{p2.y() - p1.y(), p1.x() - p2.x(), cross(p1, p2), end};
        };
        std::size_t last = count - 1;
        sectors_.push_back(edge(last, 0, 0.0));
        for (std::size_t j = 1; j < count; ++j) sectors_.push_back(edge(j - 1, j, 0.0));
        sectors_.push_back(edge(last, 0, INFINITY));
        minRadius_ = INFINITY;
        for (std::size_t j = 0; j < count; ++j) {
            const Ray& a = rays_[j];
            const Ray& b = rays_[(j + 1) % count];
            minRadius_ = std::min(minRadius_, originToSegment(a.radius * a.dir, b.radius * b.dir));
        }
    } else {
        samples_ = sorted;
        // Rays on the bisectors: the one between samples k and k + 1 sits at a_k + gap/2, and the
        // sector after it belongs to sample k + 1.
        struct Bisector {
            double angle;
            std::size_t after;
        };
        std::vector<Bisector> bisectors;
        for (std::size_t k = 0; k < count; ++k) {
            std::size_t next = (k + 1) % count;
            double gap = sorted[next].angle - sorted[k].angle;
            if (gap <= 0) gap += kTwoPi;
            double angle = sorted[k].angle + 0.5 * gap;
            if (angle >= kTwoPi) angle -= kTwoPi;
            bisectors.push_back({angle, next});
        }
        std::sort(bisectors.begin(), bisectors.end(),
                  [](const Bisector& a, const Bisector& b) { return a.angle < b.angle; });
        for (const Bisector& b : bisectors) rays_.push_back(rayAt(b.angle, 0.0));
        double wrap = sorted[bisectors.back().after].radius;
        sectors_.push_back(Sector{0.0, 0.0, wrap, 0.0});
        for (std::size_t j = 1; j < count; ++j)
            sectors_.push_back(Sector{0.0, 0.0, sorted[bisectors[j - 1].after].radius, 0.0});
        sectors_.push_back(Sector{0.0, 0.0, wrap, INFINITY});
    }

    // Rounding must not unsort the rays: two angles an ulp apart may share a pseudo-angle (an empty
    // sector, never returned by sectorAt), but never swap.
    for (std::size_t j = 1; j < rays_.size(); ++j)
        rays_[j].pseudo = std::max(rays_[j].pseudo, rays_[j - 1].pseudo);
    for (std::size_t j = 0; j < rays_.size(); ++j) sectors_[j].end = rays_[j].pseudo;

    // A power-of-two number of cells (so p·cells/4 is exact), 16 or more per ray up to 16384 cells: a
    // cell then rarely holds a ray, so the step after the look-up is almost never a loop.
    std::size_t cells = 64;
    while (cells < 16 * rays_.size() && cells < 16384) cells *= 2;
    cellsPerUnit_ = static_cast<double>(cells) / 4.0;
    table_.assign(cells + 1, 0u);
    std::uint32_t j = 0;
    for (std::size_t c = 0; c <= cells; ++c) {
        double start = static_cast<double>(c) / cellsPerUnit_;
        while (sectors_[j].end <= start) ++j;
        table_[c] = j;
    }
    buildCells();
}

void Outline::buildCells() {
    // The rays by quadrant and sector key, as queries find them.
    std::vector<double> rayT[4];
    for (const Ray& r : rays_)
        rayT[quadrantOf(r.dir.x(), r.dir.y())].push_back(sectorKey(r.dir.x(), r.dir.y()));
    for (auto& list : rayT) std::sort(list.begin(), list.end());
    // The direction of quadrant q at t, and its sector by the pseudo-angle table.
    auto sectorFor = [&](std::size_t q, double t) {
        static const double kSx[4] = {1, -1, -1, 1}, kSy[4] = {1, 1, -1, -1};
        return static_cast<std::uint32_t>(sectorAt(pseudoAngle(kSx[q] * (1 - t), kSy[q] * t)));
    };
    // Enough cells that each holds at most one ray, up to 1024 per quadrant; crowded cells beyond that
    // fall back to the pseudo-angle table.
    std::size_t perQuadrant = 16;
    auto crowded = [&](std::size_t n) {
        for (const auto& list : rayT)
            for (std::size_t i = 1; i < list.size(); ++i)
                if (static_cast<std::size_t>(list[i] * n) == static_cast<std::size_t>(list[i - 1] * n))
                    return true;
        return false;
    };
    while (perQuadrant < 1024 && crowded(perQuadrant)) perQuadrant *= 2;
    cellsPerQuadrant_ = static_cast<double>(perQuadrant);
    cellStride_ = perQuadrant + 1;
    cells_.assign(4 * cellStride_, Cell{});
    for (std::size_t q = 0; q < 4; ++q) {
        std::size_t next = 0;  // rayT[q] is sorted: walk it alongside the cells
        for (std::size_t c = 0; c <= perQuadrant; ++c) {
            double t0 = static_cast<double>(c) / cellsPerQuadrant_;
            double t1 = c == perQuadrant ? 1.0 : static_cast<double>(c + 1) / cellsPerQuadrant_;
            std::vector<double> inside;
            while (next < rayT[q].size() && static_cast<std::size_t>(rayT[q][next] * cellsPerQuadrant_) == c)
                inside.push_back(rayT[q][next++]);
            Cell& cell = cells_[q * cellStride_ + c];
            if (inside.size() > 1) {
                cell.sector[0] = cell.sector[1] = kCrowded;
                continue;
            }
            if (inside.empty()) {
                cell.sector[0] = cell.sector[1] = sectorFor(q, c == perQuadrant ? 1.0 : 0.5 * (t0 + t1));
                continue;
            }
            double b = inside[0];
            cell.ray = b;
            cell.sector[1] = sectorFor(q, b < t1 ? 0.5 * (b + t1) : b);
            cell.sector[0] = b > t0 ? sectorFor(q, 0.5 * (t0 + b)) : cell.sector[1];
        }
    }
}

double Outline::radiusToward(const Vec2& d) const {
    std::size_t j = sectorAt(pseudoAngle(d));
    const Sector& s = sectors_[j];
    if (shape_ == OutlineShape::Chord) return sectorRadius(s.offset, 1.0, d.norm(), s.dot(d.x(), d.y()));
    return nearBisector(j, d, d.norm()) ? tieOffset(d) : s.offset;
}

bool Outline::contains(const Vec2& y, double k) const {
    if (y.x() == 0.0 && y.y() == 0.0) return true;
    std::size_t j = sectorAt(pseudoAngle(y));
    const Sector& s = sectors_[j];
    if (shape_ == OutlineShape::Chord) return s.dot(y.x(), y.y()) <= s.offset * k;
    double offset = s.offset;
    if (nearBisector(j, y, y.norm())) {
        // On a radial step the region is the union of both closed sectors: the larger radius holds.
        std::size_t count = rays_.size();
        std::size_t c = j % count;  // sectors 0 and S are one
        offset =
            std::max({offset, sectors_[(c + count - 1) % count].offset, sectors_[(c + 1) % count].offset});
    }
    double r = offset * k;
    return y.squaredNorm() <= r * r;
}

double Outline::tieOffset(const Vec2& d) const {
    return nearestRuleRadius(samples_, trig::atan2(d.y(), d.x()));
}

double nearestRuleRadius(const std::vector<RadiusSample>& sorted, double phi) {
    if (sorted.size() == 1) return sorted[0].radius;
    phi = reduceRadians(phi);
    auto next = std::upper_bound(sorted.begin(), sorted.end(), phi,
                                 [](double p, const RadiusSample& s) { return p < s.angle; });
    std::size_t k =
        next == sorted.begin() ? sorted.size() - 1 : static_cast<std::size_t>(next - sorted.begin()) - 1;
    std::size_t after = (k + 1) % sorted.size();
    double toPrev = phi - sorted[k].angle;
    if (toPrev < 0) toPrev += kTwoPi;
    double toNext = sorted[after].angle - phi;
    if (toNext < 0) toNext += kTwoPi;
    // Samples given in degrees are rounded once as radians, so a tie that is exact in the file
    // (0° between 350° and 10°) differs here by a few ulps; within kTieTolerance it is a tie.
    constexpr double kTieTolerance = 1e-12;
    if (toPrev < toNext - kTieTolerance) return sorted[k].radius;
    if (toNext < toPrev - kTieTolerance) return sorted[after].radius;
    return sorted[std::min(k, after)].radius;  // a tie: the one first in ascending angle order
}

}  // namespace polar
