#include "polar/narrow_phase.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace polar {
namespace {

// Touch: some guest point lies inside or on the host. Leave: some guest point lies on or outside it.
enum class Goal { Touch, Leave };

// Guest bound space → host bound space: q = t + M·y.
struct Frame {
    Mat2 m;
    Vec2 t;
};

// Real roots of a + b·x + c·x² (c may be 0), in no particular order; returns how many.
int quadraticRoots(double a, double b, double c, double roots[2]) {
    if (c == 0.0) {
        if (b == 0.0) return 0;
        roots[0] = -a / b;
        return 1;
    }
    double disc = b * b - 4 * c * a;
    if (disc < 0) return 0;
    // q = −(b + sign(b)·√disc)/2 avoids cancellation; the roots are q/c and a/q.
    double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    roots[0] = q / c;
    if (q == 0.0) return 1;
    roots[1] = a / q;
    return 2;
}

template <std::size_t N>
double polynomial(const std::array<double, N>& c, double x) {
    double v = c[N - 1];
    for (std::size_t i = N - 1; i-- > 0;) v = v * x + c[i];
    return v;
}

// The least value of c0 + c1·x + c2·x² on [a, b].
double quadraticMin(const std::array<double, 3>& c, double a, double b) {
    double best = std::min(polynomial(c, a), polynomial(c, b));
    if (c[2] > 0) {
        double vertex = -c[1] / (2 * c[2]);
        if (vertex > a && vertex < b) best = std::min(best, polynomial(c, vertex));
    }
    return best;
}

// The least value of the quartic c0 + … + c4·x⁴ on [a, b]. P' is monotone between the roots of
// the quadratic P'', so each interior minimum is the one sign change (− to +) of P' on such a
// piece, found by bisection down to adjacent doubles.
double quarticMin(const std::array<double, 5>& c, double a, double b) {
    double best = std::min(polynomial(c, a), polynomial(c, b));
    std::array<double, 4> d{c[1], 2 * c[2], 3 * c[3], 4 * c[4]};
    double roots[2];
    int n = quadraticRoots(2 * c[2], 6 * c[3], 12 * c[4], roots);
    std::array<double, 4> cuts{a, b, b, b};
    int count = 1;
    std::sort(roots, roots + n);
    for (int i = 0; i < n; ++i)
        if (roots[i] > a && roots[i] < b) cuts[count++] = roots[i];
    cuts[count++] = b;
    for (int i = 0; i + 1 < count; ++i) {
        double lo = cuts[i], hi = cuts[i + 1];
        if (!(polynomial(d, lo) < 0 && polynomial(d, hi) > 0)) continue;
        for (int step = 0; step < 200; ++step) {
            double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) break;
            (polynomial(d, mid) < 0 ? lo : hi) = mid;
        }
        best = std::min({best, polynomial(c, lo), polynomial(c, hi)});
    }
    return best;
}

// Walks guest pieces (segments and arcs, already in host space) against one host outline.
class HostTester {
public:
    HostTester(const Outline& host, Goal goal) : host_(host), goal_(goal), raysCount_(host.rayCount()) {}

    // Whether a point meets the goal.
    bool point(const Vec2& q) const {
        if (q.x() == 0.0 && q.y() == 0.0) return goal_ == Goal::Touch;
        return pieceMeetsPoint(host_.sectors()[canon(host_.sectorAt(pseudoAngle(q)))], q);
    }

    // Whether some point of the segment q0 → q1 meets the goal: cut it where it crosses host rays and
    // test each cut against its sector's piece.
    bool segment(const Vec2& q0, const Vec2& q1) const {
        Vec2 dq = q1 - q0;
        if (raysCount_ == 0) return pieceMeetsSegment(host_.sectors()[0], q0, dq, 0.0, 1.0);
        double c = cross(q0, q1);
        if (c == 0.0) {  // on one line through the centre
            if (q0.dot(q1) <= 0.0) {  // through (or up to) the centre
                if (goal_ == Goal::Touch) return true;
                return point(q0) || point(q1);  // the far ends are the farthest points
            }
            std::size_t j = canon(host_.sectorAt(pseudoAngle(q0)));
            return pieceMeetsSegment(host_.sectors()[j], q0, dq, 0.0, 1.0);
        }
        const auto& rays = host_.rays();
        std::size_t j0 = canon(host_.sectorAt(pseudoAngle(q0)));
        std::size_t j1 = canon(host_.sectorAt(pseudoAngle(q1)));
        bool ccw = c > 0;
        std::size_t steps = ccw ? (j1 + raysCount_ - j0) % raysCount_ : (j0 + raysCount_ - j1) % raysCount_;
        if (steps == 0) {
            // Both ends in one sector: the segment stays in it unless it sweeps out through the ray
            // that ends it and all the way round (possible only for sectors wider than half a turn).
            const Vec2& e = rays[ccw ? j0 : previous(j0)].dir;
            bool through = ccw ? (cross(q0, e) > 0 && cross(e, q1) > 0) : (cross(q0, e) < 0 && cross(e, q1) < 0);
            if (through) steps = raysCount_;
        }
        double la = 0.0;
        std::size_t j = j0;
        for (std::size_t s = 0; s < steps; ++s) {
            const Vec2& e = rays[ccw ? j : previous(j)].dir;  // the ray that leaves sector j
            double f0 = cross(e, q0), f1 = cross(e, q1);
            double lb = f0 != f1 ? std::clamp(f0 / (f0 - f1), la, 1.0) : la;
            if (!empty(j) && pieceMeetsSegment(host_.sectors()[j], q0, dq, la, lb)) return true;
            la = lb;
            j = ccw ? canon(j + 1) : previous(j);
        }
        return !empty(j) && pieceMeetsSegment(host_.sectors()[j], q0, dq, la, 1.0);
    }

    // Whether some point of the arc q(τ) = (A0 + A1·τ + A2·τ²)/(1 + τ²), τ ∈ [−T, T], meets the goal.
    // `apex` is the tip of the triangle (the two ends and the tangents' crossing) that holds the arc.
    bool arc(const Vec2& a0, const Vec2& a1, const Vec2& a2, double tMax, const Vec2& apex) const {
        auto at = [&](double tau) { return Vec2(a0 + tau * (a1 + tau * a2)); };
        cuts_.clear();
        cuts_.push_back(-tMax);
        cuts_.push_back(tMax);
        if (raysCount_ > 0) {
            auto addCrossings = [&](std::size_t r) {
                const Vec2& e = host_.rays()[r].dir;
                double roots[2];
                int n = quadraticRoots(cross(e, a0), cross(e, a1), cross(e, a2), roots);
                for (int i = 0; i < n; ++i)
                    if (roots[i] > -tMax && roots[i] < tMax && e.dot(at(roots[i])) > 0) cuts_.push_back(roots[i]);
            };
            // Only rays that point into the triangle can cross the arc: the triangle subtends the
            // arc between the pseudo-angles of two of its corners, unless it holds the centre.
            Vec2 start = at(-tMax), end = at(tMax);
            double s1 = cross(start, end), s2 = cross(end, apex), s3 = cross(apex, start);
            bool holdsCentre = (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
            if (holdsCentre || start.isZero() || end.isZero() || apex.isZero()) {
                for (std::size_t r = 0; r < raysCount_; ++r) addCrossings(r);
            } else {
                std::array<double, 3> p{pseudoAngle(start), pseudoAngle(end), pseudoAngle(apex)};
                std::sort(p.begin(), p.end());
                // The triangle's angular range is the circle minus its widest pseudo-angle gap.
                double gaps[3] = {p[1] - p[0], p[2] - p[1], p[0] + 4 - p[2]};
                int widest = static_cast<int>(std::max_element(gaps, gaps + 3) - gaps);
                double from = p[(widest + 1) % 3], to = p[widest];
                // Rays with pseudo-angle in [from, to] circularly, starting one early to be safe.
                std::size_t r = previous(canon(host_.sectorAt(from)));
                for (std::size_t n = 0; n < raysCount_; ++n, r = (r + 1) % raysCount_) {
                    double pr = host_.rays()[r].pseudo;
                    bool inside = from <= to ? (pr >= from && pr <= to) : (pr >= from || pr <= to);
                    if (!inside && n > 0) break;
                    addCrossings(r);
                }
            }
        }
        std::sort(cuts_.begin(), cuts_.end());
        for (std::size_t i = 0; i + 1 < cuts_.size(); ++i) {
            double ta = cuts_[i], tb = cuts_[i + 1];
            if (!(tb > ta) && cuts_.size() > 2) continue;
            Vec2 mid = at(0.5 * (ta + tb));
            if (mid.isZero()) {
                if (goal_ == Goal::Touch) return true;
                continue;
            }
            std::size_t j = canon(host_.sectorAt(pseudoAngle(mid)));
            if (pieceMeetsArc(host_.sectors()[j], a0, a1, a2, ta, tb)) return true;
        }
        return false;
    }

private:
    std::size_t canon(std::size_t j) const { return j == raysCount_ ? 0 : j; }
    std::size_t previous(std::size_t j) const { return j == 0 ? raysCount_ - 1 : j - 1; }
    // A sector between two rays with the same pseudo-angle: no direction lies in it.
    bool empty(std::size_t j) const { return j > 0 && host_.rays()[j].pseudo == host_.rays()[j - 1].pseudo; }

    bool pieceMeetsPoint(const Outline::Sector& s, const Vec2& q) const {
        if (host_.chord()) {
            double f = s.nx * q.x() + s.ny * q.y() - s.level;
            return goal_ == Goal::Touch ? f <= 0 : f >= 0;
        }
        double f = q.squaredNorm() - s.level * s.level;
        return goal_ == Goal::Touch ? f <= 0 : f >= 0;
    }

    // The sub-segment q0 + λ·dq, λ ∈ [la, lb], against one sector's piece. A line's signed distance
    // is linear along it (ends decide); |q|² is convex (ends decide a maximum; the foot of the
    // perpendicular, clamped, the minimum).
    bool pieceMeetsSegment(const Outline::Sector& s, const Vec2& q0, const Vec2& dq, double la, double lb) const {
        Vec2 pa = q0 + la * dq, pb = q0 + lb * dq;
        if (host_.chord() || goal_ == Goal::Leave) return pieceMeetsPoint(s, pa) || pieceMeetsPoint(s, pb);
        double len2 = dq.squaredNorm();
        double lambda = len2 > 0 ? std::clamp(-q0.dot(dq) / len2, la, lb) : la;
        return pieceMeetsPoint(s, q0 + lambda * dq);
    }

    // The arc on [ta, tb] against one sector's piece. Multiplying by 1 + τ² > 0 keeps the sign:
    //   line:   n·V(τ) − h·(1 + τ²)            (a quadratic in τ)
    //   circle: |V(τ)|² − r²·(1 + τ²)²         (a quartic in τ)
    // Touch asks whether its minimum is ≤ 0, Leave whether its maximum is ≥ 0.
    bool pieceMeetsArc(const Outline::Sector& s, const Vec2& a0, const Vec2& a1, const Vec2& a2, double ta,
                       double tb) const {
        double sign = goal_ == Goal::Touch ? 1.0 : -1.0;
        if (host_.chord()) {
            Vec2 n(s.nx, s.ny);
            std::array<double, 3> c{sign * (n.dot(a0) - s.level), sign * n.dot(a1), sign * (n.dot(a2) - s.level)};
            return quadraticMin(c, ta, tb) <= 0;
        }
        double r2 = s.level * s.level;
        std::array<double, 5> c{sign * (a0.squaredNorm() - r2), sign * (2 * a0.dot(a1)),
                                sign * (a1.squaredNorm() + 2 * a0.dot(a2) - 2 * r2), sign * (2 * a1.dot(a2)),
                                sign * (a2.squaredNorm() - r2)};
        return quarticMin(c, ta, tb) <= 0;
    }

    const Outline& host_;
    Goal goal_;
    std::size_t raysCount_;
    mutable std::vector<double> cuts_;  // the arc's parameters where it crosses rays, reused
};

// Splits the guest arc of radius r from unit direction ds to de (counter-clockwise) into pieces of
// at most a quarter turn and hands each to `visit(m, tMax)`.
template <class Visit>
bool forEachArcPiece(const Vec2& ds, const Vec2& de, int depth, Visit&& visit) {
    double c = cross(ds, de), d = ds.dot(de);
    if ((c >= 0 && d >= 0) || depth > 4) {
        if (c == 0 && d >= 0 && depth > 0) return false;  // an empty piece
        Vec2 m = (ds + de).normalized();
        double cosHalf = m.dot(ds);
        return visit(ds, de, m, cross(ds, m) / (1.0 + cosHalf), cosHalf);
    }
    Vec2 mid;
    if (c > 0)
        mid = (ds + de).normalized();
    else if (c < 0)
        mid = -(ds + de).normalized();
    else
        mid = Vec2(-ds.y(), ds.x());  // half a turn (or a whole one when ds = de)
    return forEachArcPiece(ds, mid, depth + 1, visit) || forEachArcPiece(mid, de, depth + 1, visit);
}

// Whether the guest's boundary meets the host (Touch) or leaves it (Leave). u = guest centre − host
// centre in the world; both maps are non-singular.
bool guestBoundaryMeets(const Outline& host, const LinearMap& mh, const Outline& guest, const LinearMap& mg,
                        const Vec2& u, Goal goal) {
    Frame f;
    f.m = mh.inverseScaled * mg.linear / mh.absDet;
    f.t = mh.inverseScaled * u / mh.absDet;
    HostTester tester(host, goal);

    // The host seen from guest space: centre g0, and a radius ρ such that (Touch) the host lies in
    // the disk (g0, ρ), or (Leave) the disk lies in the host. Guest pieces that cannot reach the
    // first disk, or that stay within the second, are skipped.
    Vec2 g0 = -(mg.inverseScaled * u) / mg.absDet;
    double rho = goal == Goal::Touch ? host.maxRadius() * mh.stretchMax / mg.stretchMin * (1 + 1e-9)
                                     : host.minRadius() * mh.stretchMin / mg.stretchMax * (1 - 1e-9);
    auto skipSegment = [&](const Vec2& p1, const Vec2& p2) {
        if (goal == Goal::Leave) return (p1 - g0).norm() <= rho && (p2 - g0).norm() <= rho;
        Vec2 d = p2 - p1;
        double len2 = d.squaredNorm();
        double lambda = len2 > 0 ? std::clamp((g0 - p1).dot(d) / len2, 0.0, 1.0) : 0.0;
        return (p1 + lambda * d - g0).norm() > rho;
    };
    auto toHost = [&](const Vec2& y) { return Vec2(f.t + f.m * y); };
    auto segment = [&](const Vec2& p1, const Vec2& p2) {
        return !skipSegment(p1, p2) && tester.segment(toHost(p1), toHost(p2));
    };
    double g0Norm = g0.norm();
    auto arc = [&](double r, const Vec2& ds, const Vec2& de, int depth) {
        if (goal == Goal::Touch ? std::fabs(g0Norm - r) > rho : g0Norm + r <= rho) return false;
        return forEachArcPiece(ds, de, depth, [&](const Vec2& ps, const Vec2& pe, const Vec2& m, double tMax,
                                                  double cosHalf) {
            // Leave: a piece whose triangle stays in the disk that the container surely holds.
            if (goal == Goal::Leave && (r * ps - g0).norm() <= rho && (r * pe - g0).norm() <= rho &&
                (r / cosHalf * m - g0).norm() <= rho)
                return false;
            Vec2 mm = f.m * (r * m), mp = f.m * (r * Vec2(-m.y(), m.x()));
            return tester.arc(f.t + mm, 2.0 * mp, f.t - mm, tMax, Vec2(f.t + mm / cosHalf));
        });
    };

    const auto& rays = guest.rays();
    const auto& sectors = guest.sectors();
    std::size_t count = rays.size();
    if (count == 0) {  // a circle: four quarter turns
        double r = sectors[0].level;
        Vec2 axes[5] = {Vec2(1, 0), Vec2(0, 1), Vec2(-1, 0), Vec2(0, -1), Vec2(1, 0)};
        for (int i = 0; i < 4; ++i)
            if (arc(r, axes[i], axes[i + 1], 1)) return true;
        return false;
    }

    // Which guest sectors to visit: for Touch, those facing the disk (g0, ρ), between the two
    // tangents from the guest centre; otherwise all.
    std::size_t first = 0, visits = count;
    if (goal == Goal::Touch && g0Norm > rho) {
        double s = rho / g0Norm, c = std::sqrt(std::max(0.0, 1 - s * s));
        Vec2 g = g0 / g0Norm, gp(-g.y(), g.x());
        Vec2 lo = c * g - s * gp, hi = c * g + s * gp;
        std::size_t jLo = guest.sectorAt(pseudoAngle(lo)) % count, jHi = guest.sectorAt(pseudoAngle(hi)) % count;
        visits = (jHi + count - jLo) % count + 1;
        // Both tangents in one sector: the range is inside it unless it wraps past the sector's end.
        if (jLo == jHi && cross(lo, rays[jLo].dir) > 0 && cross(rays[jLo].dir, hi) > 0) visits = count;
        first = jLo;
    }
    for (std::size_t n = 0; n < visits; ++n) {
        std::size_t j = (first + n) % count;
        std::size_t before = j == 0 ? count - 1 : j - 1;  // the ray that starts sector j; ray j ends it
        if (j > 0 && rays[j].pseudo == rays[before].pseudo) continue;
        if (guest.chord()) {
            if (segment(rays[before].radius * rays[before].dir, rays[j].radius * rays[j].dir)) return true;
            continue;
        }
        double r = sectors[j].level;
        if (arc(r, rays[before].dir, rays[j].dir, 0)) return true;
        // The radial steps where the nearest sample changes: the one ending this sector, and for the
        // first visited sector also the one starting it.
        double next = sectors[(j + 1) % count].level;
        if (next != r && segment(r * rays[j].dir, next * rays[j].dir)) return true;
        if (n == 0 && visits < count) {
            double previousLevel = sectors[before].level;
            if (previousLevel != r && segment(previousLevel * rays[before].dir, r * rays[before].dir)) return true;
        }
    }
    return false;
}

// Point tests in the world: x = point − the outline's world centre.
bool containsWorld(const Outline& o, const LinearMap& m, const Vec2& x) {
    return o.contains(m.inverseScaled * x, m.absDet);
}

bool onOrOutsideWorld(const Outline& o, const LinearMap& m, const Vec2& x) {
    Vec2 y = m.inverseScaled * x;
    if (y.x() == 0.0 && y.y() == 0.0) return false;
    const Outline::Sector& s = o.sectors()[o.sectorAt(pseudoAngle(y))];
    if (o.chord()) return s.nx * y.x() + s.ny * y.y() >= s.level * m.absDet;
    double r = s.level * m.absDet;
    return y.squaredNorm() >= r * r;
}

}  // namespace

bool outlinesOverlap(const Outline& a, const LinearMap& ma, const Outline& b, const LinearMap& mb, const Vec2& u) {
    if (ma.singular() && mb.singular()) return u.x() == 0.0 && u.y() == 0.0;
    if (ma.singular()) return containsWorld(b, mb, -u);
    if (mb.singular()) return containsWorld(a, ma, u);
    if (containsWorld(a, ma, u) || containsWorld(b, mb, -u)) return true;  // a centre inside the other
    // Neither centre is inside the other outline, so they overlap iff their boundaries meet, i.e. iff
    // the guest's boundary touches the host. Prefer a polygon guest (straight pieces), then the
    // outline with fewer rays.
    bool guestB;
    if (a.chord() != b.chord())
        guestB = b.chord();
    else
        guestB = b.rayCount() <= a.rayCount();
    return guestB ? guestBoundaryMeets(a, ma, b, mb, u, Goal::Touch)
                  : guestBoundaryMeets(b, mb, a, ma, -u, Goal::Touch);
}

bool outlineLeaves(const Outline& held, const LinearMap& mh, const Outline& container, const LinearMap& mc,
                   const Vec2& u) {
    if (mc.singular()) return true;                                  // a point holds nothing
    if (mh.singular()) return onOrOutsideWorld(container, mc, u);     // a point: is it inside?
    if (onOrOutsideWorld(container, mc, u)) return true;              // the held centre is out already
    return guestBoundaryMeets(container, mc, held, mh, u, Goal::Leave);
}

}  // namespace polar
