#include "narrow_phase/exact_overlap.h"

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
// piece; Newton's method on P' finds it, kept inside a shrinking bracket (a bisection step whenever
// Newton would leave it), down to adjacent doubles.
double quarticMin(const std::array<double, 5>& c, double a, double b) {
    double best = std::min(polynomial(c, a), polynomial(c, b));
    std::array<double, 4> d{c[1], 2 * c[2], 3 * c[3], 4 * c[4]};
    std::array<double, 3> dd{2 * c[2], 6 * c[3], 12 * c[4]};
    double roots[2];
    int n = quadraticRoots(dd[0], dd[1], dd[2], roots);
    std::array<double, 4> cuts{a, b, b, b};
    int count = 1;
    std::sort(roots, roots + n);
    for (int i = 0; i < n; ++i)
        if (roots[i] > a && roots[i] < b) cuts[count++] = roots[i];
    cuts[count++] = b;
    for (int i = 0; i + 1 < count; ++i) {
        double lo = cuts[i], hi = cuts[i + 1];
        if (!(polynomial(d, lo) < 0 && polynomial(d, hi) > 0)) continue;
        double x = 0.5 * (lo + hi);
        for (int step = 0; step < 100; ++step) {
            double slope = polynomial(d, x);
            if (slope < 0)
                lo = x;
            else
                hi = x;
            double curvature = polynomial(dd, x);
            double next = curvature > 0 ? x - slope / curvature : 0.5 * (lo + hi);
            if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
            if (next == x || next <= lo || next >= hi) break;
            x = next;
        }
        best = std::min({best, polynomial(c, x), polynomial(c, lo), polynomial(c, hi)});
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

    // The host sector (canonical: 0 … S − 1) of a point q ≠ 0.
    std::size_t sectorOf(const Vec2& q) const {
        return canon(host_.sectorOf(q.x(), q.y(), sectorKey(q.x(), q.y())));
    }

    // Whether some point of the segment q0 → q1 meets the goal: cut it where it crosses host rays and
    // test each cut against its sector's piece.
    bool segment(const Vec2& q0, const Vec2& q1) const {
        if (raysCount_ == 0 || q0.isZero() || q1.isZero()) return segment(q0, 0, q1, 0);
        return segment(q0, sectorOf(q0), q1, sectorOf(q1));
    }

    // The same with the ends' sectors known (j0, j1; ignored for a zero end or a circle host).
    bool segment(const Vec2& q0, std::size_t j0, const Vec2& q1, std::size_t j1) const {
        Vec2 dq = q1 - q0;
        if (raysCount_ == 0) return pieceMeetsSegment(host_.sectors()[0], q0, dq, 0.0, 1.0);
        double c = cross(q0, q1);
        if (c == 0.0) {               // on one line through the centre
            if (q0.dot(q1) <= 0.0) {  // through (or up to) the centre
                if (goal_ == Goal::Touch) return true;
                return point(q0) || point(q1);  // the far ends are the farthest points
            }
            return pieceMeetsSegment(host_.sectors()[j0], q0, dq, 0.0, 1.0);
        }
        const auto& rays = host_.rays();
        bool ccw = c > 0;
        std::size_t steps = ccw ? (j1 + raysCount_ - j0) % raysCount_ : (j0 + raysCount_ - j1) % raysCount_;
        if (steps == 0) {
            // Both ends in one sector: the segment stays in it unless it sweeps out through the ray
            // that ends it and all the way round (possible only for sectors wider than half a turn).
            const Vec2& e = rays[ccw ? j0 : previous(j0)].dir;
            bool through =
                ccw ? (cross(q0, e) > 0 && cross(e, q1) > 0) : (cross(q0, e) < 0 && cross(e, q1) < 0);
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
                    if (roots[i] > -tMax && roots[i] < tMax && e.dot(at(roots[i])) > 0)
                        cuts_.push_back(roots[i]);
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
            double f = s.dot(q.x(), q.y()) - s.offset;
            return goal_ == Goal::Touch ? f <= 0 : f >= 0;
        }
        double f = q.squaredNorm() - s.offset * s.offset;
        return goal_ == Goal::Touch ? f <= 0 : f >= 0;
    }

    // The sub-segment q0 + λ·dq, λ ∈ [la, lb], against one sector's piece. A line's signed distance
    // is linear along it (ends decide); |q|² is convex (ends decide a maximum; the foot of the
    // perpendicular, clamped, the minimum).
    bool pieceMeetsSegment(const Outline::Sector& s, const Vec2& q0, const Vec2& dq, double la,
                           double lb) const {
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
            std::array<double, 3> c{sign * (n.dot(a0) - s.offset), sign * n.dot(a1),
                                    sign * (n.dot(a2) - s.offset)};
            return quadraticMin(c, ta, tb) <= 0;
        }
        double r2 = s.offset * s.offset;
        std::array<double, 5> c{sign * (a0.squaredNorm() - r2), sign * (2 * a0.dot(a1)),
                                sign * (a1.squaredNorm() + 2 * a0.dot(a2) - 2 * r2), sign * (2 * a1.dot(a2)),
                                sign * (a2.squaredNorm() - r2)};
        // When the guest's arc stays circular in host space (both maps uniform scales, rotations or
        // mirrors), the quartic is (1 + τ²) times the quadratic c0 + c1·τ + c4·τ²: c1 = c3 and
        // c2 = c0 + c4 up to rounding. Then the closed-form quadratic decides.
        double size = std::fabs(c[0]) + std::fabs(c[1]) + std::fabs(c[2]) + std::fabs(c[3]) + std::fabs(c[4]);
        if (std::fabs(c[1] - c[3]) <= 1e-13 * size && std::fabs(c[2] - c[0] - c[4]) <= 1e-13 * size)
            return quadraticMin({c[0], c[1], c[4]}, ta, tb) <= 0;
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
// centre in the world; both maps are non-singular. Work happens in host space, where the host is
// exact and lies within the circle |q| ≤ maxRadius and holds the circle |q| ≤ minRadius: guest
// pieces wholly outside the first (Touch) or inside the second (Leave) are skipped unwalked, and for
// Touch only the guest sectors between the two tangents from the guest centre to the first circle
// are visited at all.
bool guestBoundaryMeets(const Outline& host, const LinearMap& mh, const Outline& guest, const LinearMap& mg,
                        const Vec2& u, Goal goal) {
    Frame f;
    f.m = mh.inverseScaled() * mg.linear / mh.absDet;
    f.t = mh.inverseScaled() * u / mh.absDet;
    HostTester tester(host, goal);
    bool touch = goal == Goal::Touch;
    double radius = touch ? host.maxRadius() * (1 + 1e-9) : host.minRadius() * (1 - 1e-9);
    double radius2 = radius * radius;
    auto toHost = [&](const Vec2& y) { return Vec2(f.t + f.m * y); };
    // A segment that cannot matter: wholly outside the host's circle (Touch), or inside its inner one.
    auto skipSegment = [&](const Vec2& q0, const Vec2& q1) {
        if (!touch) return q0.squaredNorm() <= radius2 && q1.squaredNorm() <= radius2;
        Vec2 d = q1 - q0;
        double len2 = d.squaredNorm();
        double lambda = len2 > 0 ? std::clamp(-q0.dot(d) / len2, 0.0, 1.0) : 0.0;
        return (q0 + lambda * d).squaredNorm() > radius2;
    };
    // The same for an arc inside its triangle (start, end, apex).
    auto skipTriangle = [&](const Vec2& p0, const Vec2& p1, const Vec2& p2) {
        if (!touch)
            return p0.squaredNorm() <= radius2 && p1.squaredNorm() <= radius2 && p2.squaredNorm() <= radius2;
        double s1 = cross(p0, p1), s2 = cross(p1, p2), s3 = cross(p2, p0);
        if ((s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0))
            return false;  // holds the centre
        return skipSegment(p0, p1) && skipSegment(p1, p2) && skipSegment(p2, p0);
    };
    auto arc = [&](double r, const Vec2& ds, const Vec2& de, int depth) {
        return forEachArcPiece(
            ds, de, depth, [&](const Vec2& ps, const Vec2& pe, const Vec2& m, double tMax, double cosHalf) {
                Vec2 apex = toHost(r / cosHalf * m);
                if (skipTriangle(toHost(r * ps), toHost(r * pe), apex)) return false;
                Vec2 mm = f.m * (r * m), mp = f.m * (r * Vec2(-m.y(), m.x()));
                return tester.arc(f.t + mm, 2.0 * mp, f.t - mm, tMax, apex);
            });
    };

    const auto& rays = guest.rays();
    const auto& sectors = guest.sectors();
    std::size_t count = rays.size();
    if (count == 0) {  // a circle: four quarter turns
        double r = sectors[0].offset;
        Vec2 axes[5] = {Vec2(1, 0), Vec2(0, 1), Vec2(-1, 0), Vec2(0, -1), Vec2(1, 0)};
        for (int i = 0; i < 4; ++i)
            if (arc(r, axes[i], axes[i + 1], 1)) return true;
        return false;
    }

    // Which guest sectors to visit. For Touch: the guest centre sits at t in host space; the rays
    // from it that meet the circle |q| ≤ radius lie between the tangent directions w1 and w2, which
    // map back to guest directions L_g⁻¹·L_h·w (the order flips when exactly one map mirrors).
    std::size_t first = 0, visits = count;
    double t2 = f.t.squaredNorm();
    if (touch && t2 > radius2) {
        double tn = std::sqrt(t2), s = radius / tn, c = std::sqrt(std::max(0.0, 1 - s * s));
        Vec2 toward = -f.t / tn, across(-toward.y(), toward.x());
        Vec2 d1 = mg.inverseScaled() * (mh.linear * Vec2(c * toward - s * across));
        Vec2 d2 = mg.inverseScaled() * (mh.linear * Vec2(c * toward + s * across));
        auto det = [](const Mat2& l) { return l(0, 0) * l(1, 1) - l(0, 1) * l(1, 0); };
        double detH = det(mh.linear), detG = det(mg.linear);
        if ((detH < 0) != (detG < 0)) std::swap(d1, d2);
        std::size_t jLo = guest.sectorAt(pseudoAngle(d1)) % count,
                    jHi = guest.sectorAt(pseudoAngle(d2)) % count;
        visits = (jHi + count - jLo) % count + 1;
        // Both tangents in one sector: the range is inside it unless it wraps past the sector's end.
        if (jLo == jHi && cross(d1, rays[jLo].dir) > 0 && cross(rays[jLo].dir, d2) > 0) visits = count;
        first = jLo;
    }

    if (guest.chord()) {
        // Vertex j (on ray j) ends sector j; walk the edges of the visited sectors, each vertex mapped
        // and looked up once.
        auto vertex = [&](std::size_t j) { return toHost(rays[j].radius * rays[j].dir); };
        constexpr std::size_t kUnknown = static_cast<std::size_t>(-1);
        std::size_t start = first == 0 ? count - 1 : first - 1;
        Vec2 q0 = vertex(start);
        std::size_t j0 = kUnknown;
        for (std::size_t n = 0; n < visits; ++n) {
            Vec2 q1 = vertex((first + n) % count);
            std::size_t j1 = kUnknown;
            if (!skipSegment(q0, q1)) {
                if (q0.isZero() || q1.isZero()) {
                    if (tester.segment(q0, q1)) return true;
                } else {
                    if (j0 == kUnknown) j0 = tester.sectorOf(q0);
                    j1 = tester.sectorOf(q1);
                    if (tester.segment(q0, j0, q1, j1)) return true;
                }
            }
            q0 = q1;
            j0 = j1;
        }
        return false;
    }
    for (std::size_t n = 0; n < visits; ++n) {
        std::size_t j = (first + n) % count;
        std::size_t before = j == 0 ? count - 1 : j - 1;  // the ray that starts sector j; ray j ends it
        if (j > 0 && rays[j].pseudo == rays[before].pseudo) continue;
        double r = sectors[j].offset;
        if (arc(r, rays[before].dir, rays[j].dir, 0)) return true;
        // The radial steps where the nearest sample changes: the one ending this sector, and for the
        // first visited sector also the one starting it.
        auto step = [&](std::size_t ray, double r0, double r1) {
            if (r0 == r1) return false;
            Vec2 q0 = toHost(r0 * rays[ray].dir), q1 = toHost(r1 * rays[ray].dir);
            return !skipSegment(q0, q1) && tester.segment(q0, q1);
        };
        if (step(j, r, sectors[(j + 1) % count].offset)) return true;
        if (n == 0 && visits < count && step(before, sectors[before].offset, r)) return true;
    }
    return false;
}

// Point tests in the world: x = point − the outline's world centre.
bool containsWorld(const Outline& o, const LinearMap& m, const Vec2& x) {
    return o.contains(m.inverseScaled() * x, m.absDet);
}

bool onOrOutsideWorld(const Outline& o, const LinearMap& m, const Vec2& x) {
    Vec2 y = m.inverseScaled() * x;
    if (y.x() == 0.0 && y.y() == 0.0) return false;
    const Outline::Sector& s = o.sectors()[o.sectorAt(pseudoAngle(y))];
    if (o.chord()) return s.dot(y.x(), y.y()) >= s.offset * m.absDet;
    double r = s.offset * m.absDet;
    return y.squaredNorm() >= r * r;
}

}  // namespace

bool outlinesOverlap(const Outline& a, const LinearMap& ma, const Outline& b, const LinearMap& mb,
                     const Vec2& u) {
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
    if (mc.singular()) return true;                                // a point holds nothing
    if (mh.singular()) return onOrOutsideWorld(container, mc, u);  // a point: is it inside?
    if (onOrOutsideWorld(container, mc, u)) return true;           // the held centre is out already
    return guestBoundaryMeets(container, mc, held, mh, u, Goal::Leave);
}

}  // namespace polar
