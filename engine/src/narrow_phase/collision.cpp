#include "polar/collision.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "narrow_phase/exact_overlap.h"
#include "narrow_phase/pair_rule.h"
#include "narrow_phase/pair_test.h"

namespace polar {
namespace {

// The circle level: a bounding circle for a body, the inscribed circle for a container's wall.
double circleRadius(const Bound& r, const ObjectPose& p, bool wall) {
    if (p.singular()) return 0.0;  // a point, as at every level
    return wall ? outlineOf(r).minRadius() * p.stretchMin() : boundingRadius(r, p);
}

// World radius of r toward w (|w| = wNorm) through Outline's tables.
struct TableRadius {
    double operator()(const Bound& r, const ObjectPose& p, const Vec2& w, double wNorm, Accuracy level,
                      bool wall) const {
        if (level == Accuracy::Circle) return circleRadius(r, p, wall);
        return outlineOf(r, shapeAt(r, level)).worldRadius(p, w, wNorm);
    }
};

// The same through the plain formulas.
struct PlainRadius {
    double operator()(const Bound& r, const ObjectPose& p, const Vec2& w, double wNorm, Accuracy level,
                      bool wall) const {
        if (level == Accuracy::Circle) return circleRadius(r, p, wall);
        return r.worldRadius(p.linear, Vec2(w / wNorm), shapeAt(r, level));
    }
};

// The rule for one pair of bounds, u = Bcr's world centre − Acr's.
template <class Radius>
void applyRule(PairTest& t, const ObjectPose& a, const Bound& acr, const ObjectPose& b, const Bound& bcr,
               const Vec2& u, Accuracy level, Radius radius) {
    double squared = u.squaredNorm();
    t.distance = std::sqrt(squared);
    bool coincident = squared == 0.0;
    Vec2 w = coincident ? Vec2(Vec2::UnitX()) : u;
    double wNorm = coincident ? 1.0 : t.distance;
    Vec2 dir = w / wNorm;

    bool containerA = a.flags & kContainer, containerB = b.flags & kContainer;
    if (!containerA && !containerB) {
        t.kind = ContactKind::Contact;
        t.ra = radius(acr, a, w, wNorm, level, false);
        t.rb = radius(bcr, b, Vec2(-w), wNorm, level, false);
        double sum = t.ra + t.rb;
        t.hit = contactHit(squared, sum);
        t.penetration = contactPenetration(sum, t.distance);
        t.normal = dir;
        return;
    }
    // C holds O: both radii read toward `out`, from C's centre toward O (readDirections), the
    // container's as its wall.
    t.kind = ContactKind::Container;
    ReadDirections read = readDirections(true, containerA, w);
    t.ra = radius(acr, a, read.a, wNorm, level, containerA);
    t.rb = radius(bcr, b, read.b, wNorm, level, !containerA);
    double wall = wallOf(containerA, t.ra, t.rb), side = sideOf(containerA, t.ra, t.rb);
    t.hit = wallHit(t.distance, side, wall);
    t.penetration = wallPenetration(t.distance, side, wall);
    t.normal = normalComponent(true, dir);
}

// The contact rule when both radii are read by chord through the tables: the common case, and the
// one held to 10 ns. The chord contact path of pair_rule.h (chordKeys, the sector look-ups,
// chordRadii, contactHit). Returns false, touching nothing, when a product leaves the safe range of
// doubles (extreme scales); the caller then takes the plain-division path.
[[gnu::always_inline]] inline bool chordContact(PairTest& t, const ObjectPose& a, const Outline& oa,
                                                const ObjectPose& b, const Outline& ob, const Vec2& u,
                                                double squared) {
    Vec2 ea = a.toBound(u);
    Vec2 eb = -b.toBound(u);
    ChordKeys keys = chordKeys(ea.x(), ea.y(), eb.x(), eb.y());
    if (!keys.inRange) return false;
    const Outline::Sector& secA = oa.sectors()[oa.sectorOf(ea.x(), ea.y(), keys.ta)];
    const Outline::Sector& secB = ob.sectors()[ob.sectorOf(eb.x(), eb.y(), keys.tb)];
    double distance = std::sqrt(squared);
    ChordRadii r = chordRadii(secA.offset, a.absDet, secA.dot(ea.x(), ea.y()), secB.offset, b.absDet,
                              secB.dot(eb.x(), eb.y()), squared, distance);
    if (!r.inRange) return false;
    t.kind = ContactKind::Contact;
    t.distance = distance;
    t.ra = r.ra;
    t.rb = r.rb;
    double sum = t.ra + t.rb;
    t.hit = contactHit(squared, sum);
    t.penetration = contactPenetration(sum, distance);
    t.normal = u * r.toNormal;
    return true;
}

// u between bound i of A and bound j of B; bFromA = B's position − A's (exact for nearby objects,
// even 10⁷ units out).
Vec2 boundOffset(const ObjectPose& a, std::uint32_t i, const ObjectPose& b, std::uint32_t j,
                 const Vec2& bFromA) {
    return bFromA + b.linear * (*b.bounds)[j].centre() - a.linear * (*a.bounds)[i].centre();
}

// Takes a path of takePath (pair_rule.h): the chord contact path while its products stay in the
// safe range (else, like a lane handed back, the general path), or the rule's general path, both
// through the tables.
[[gnu::always_inline]] inline void followPath(PairTest& t, const ObjectPose& a, const ObjectPose& b,
                                              const PairPath& path, Accuracy level) {
    t.radiiA = path.a;
    t.radiiB = path.b;
    if (path.chord) {
        double squared = path.u.squaredNorm();
        if (squared > 0 && chordContact(t, a, *path.outlineA, b, *path.outlineB, path.u, squared)) return;
    }
    applyRule(t, a, (*a.bounds)[path.a], b, (*b.bounds)[path.b], path.u, level, TableRadius{});
}

// The rule on one given pair of bounds, through the tables.
PairTest ruleFor(const ObjectPose& a, std::uint32_t i, const ObjectPose& b, std::uint32_t j,
                 const Vec2& bFromA, Accuracy level) {
    PairTest t;
    followPath(t, a, b, boundPath(a, i, b, j, boundOffset(a, i, b, j, bFromA), level), level);
    return t;
}

// The closest-pair rule by one radius formula for every pair: the circle level, and the plain
// formulas (testPairPlain). Fills t in place: PairTest is returned through one object all the way
// up, never copied, since a copy of freshly written fields stalls on store forwarding and cost more
// than the test itself.
template <class Radius>
void closestPairTest(PairTest& t, const ObjectPose& a, const ObjectPose& b, Accuracy level, Radius radius) {
    ClosestBounds c = closestBounds(a, b);
    t.radiiA = c.a;
    t.radiiB = c.b;
    applyRule(t, a, (*a.bounds)[c.a], b, (*b.bounds)[c.b], c.u, level, radius);
}

// `all-radii` and `exact`: every pair of bounds (see accuracy.h for what several bounds mean). Not
// inlined: testPair's common path stays free of its registers and stack.
[[gnu::noinline]] PairTest everyPairTest(const ObjectPose& a, const ObjectPose& b, bool exact) {
    Vec2 bFromA = b.position - a.position;
    auto na = static_cast<std::uint32_t>(a.bounds->size()), nb = static_cast<std::uint32_t>(b.bounds->size());
    bool containerA = a.flags & kContainer, containerB = b.flags & kContainer;

    if (!containerA && !containerB) {
        // The rule's hits are sure hits of the exact test too: the two centre-line segments from each
        // centre to its own outline overlap, and each lies inside its star-shaped outline.
        if (na == 1 && nb == 1) {  // the common case: one rule, then bounding circles, then exact
            PairTest t = ruleFor(a, 0, b, 0, bFromA, Accuracy::Bounds);
            if (t.hit || !exact) return t;
            const Bound& ra = (*a.bounds)[0];
            const Bound& rb = (*b.bounds)[0];
            if (t.distance > boundingReach(ra, a, rb, b)) return t;  // bounding circles apart
            Vec2 u = boundOffset(a, 0, b, 0, bFromA);
            if (outlinesOverlap(outlineOf(ra), a, outlineOf(rb), b, u)) {
                t.hit = true;
                t.penetration = std::max(0.0, t.penetration);
            }
            return t;
        }
        PairTest best;
        bool found = false;
        for (std::uint32_t i = 0; i < na; ++i) {
            for (std::uint32_t j = 0; j < nb; ++j) {
                PairTest t = ruleFor(a, i, b, j, bFromA, Accuracy::Bounds);
                if (t.hit && (!found || t.penetration > best.penetration)) {
                    best = t;
                    found = true;
                }
            }
        }
        if (found || !exact) return found ? best : testPair(a, b, Accuracy::Bounds);
        for (std::uint32_t i = 0; i < na; ++i) {
            const Bound& ra = (*a.bounds)[i];
            for (std::uint32_t j = 0; j < nb; ++j) {
                const Bound& rb = (*b.bounds)[j];
                Vec2 u = boundOffset(a, i, b, j, bFromA);
                double reach = boundingReach(ra, a, rb, b);
                if (u.squaredNorm() > reach * reach) continue;  // bounding circles apart
                if (outlinesOverlap(outlineOf(ra), a, outlineOf(rb), b, u)) {
                    PairTest t = ruleFor(a, i, b, j, bFromA, Accuracy::Bounds);
                    t.hit = true;
                    t.penetration = std::max(0.0, t.penetration);
                    return t;
                }
            }
        }
        return testPair(a, b, Accuracy::Bounds);
    }

    // C holds O: O leaves when one of its bounds is outside every bound of C (each is a room).
    const ObjectPose& c = containerA ? a : b;
    const ObjectPose& o = containerA ? b : a;
    Vec2 oFromC = o.position - c.position;
    auto nc = static_cast<std::uint32_t>(c.bounds->size()), no = static_cast<std::uint32_t>(o.bounds->size());
    for (std::uint32_t k = 0; k < no; ++k) {
        const Bound& held = (*o.bounds)[k];
        Vec2 heldOffset = oFromC + o.linear * held.centre();
        bool leavesAll = true;
        for (std::uint32_t m = 0; m < nc && leavesAll; ++m) {
            const Bound& room = (*c.bounds)[m];
            Vec2 u = heldOffset - c.linear * room.centre();
            PairTest t = containerA ? ruleFor(a, m, b, k, bFromA, Accuracy::Bounds)
                                    : ruleFor(a, k, b, m, bFromA, Accuracy::Bounds);
            if (t.hit) continue;  // the rule's wall hit is a sure exact one: a point of O on or past the wall
            if (!exact) {
                leavesAll = false;
                continue;
            }
            double inner = outlineOf(room).minRadius() * c.stretchMin() * (1 - kRejectSlack);
            if (u.norm() + boundingRadius(held, o) < inner ||
                !outlineLeaves(outlineOf(held), o, outlineOf(room), c, u))
                leavesAll = false;
        }
        if (!leavesAll) continue;
        // Report O's bound k against the room the rule would pick for it.
        std::uint32_t room = closestBoundTo(c, heldOffset);
        PairTest t = containerA ? ruleFor(a, room, b, k, bFromA, Accuracy::Bounds)
                                : ruleFor(a, k, b, room, bFromA, Accuracy::Bounds);
        t.hit = true;
        t.penetration = std::max(0.0, t.penetration);
        return t;
    }
    PairTest miss = testPair(a, b, Accuracy::Bounds);
    miss.hit = false;
    return miss;
}

}  // namespace

ObjectPose::ObjectPose(const Vec2& position_, const Mat2& linear_, const Bounds* bounds_, ObjectFlags flags_)
    : LinearMap(linear_), flags(flags_), position(position_), bounds(bounds_) {
    if (bounds == nullptr || bounds->size() != 1) return;
    const Bound& only = (*bounds)[0];
    onlyCentreOffset = linear * only.centre();
    const Outline& chord = outlineOf(only, OutlineShape::Chord);
    onlyChord = chord.chord() ? &chord : nullptr;
    onlyChordByFlag = only.interpolate();
}

// Every pair test reads two poses and the scale benchmark keeps 100k of them: keep them this small.
static_assert(sizeof(ObjectPose) <= 112, "ObjectPose grew: check its field order (see collision.h)");

const char* contactKindName(ContactKind kind) {
    return kind == ContactKind::Container ? "container" : "contact";
}

bool pairIsTested(const ObjectPose& a, const ObjectPose& b, bool containers) {
    if (!(a.flags & kCollisions) || !(b.flags & kCollisions)) return false;
    if (a.bounds == nullptr || b.bounds == nullptr || a.bounds->empty() || b.bounds->empty()) return false;
    bool containerA = a.flags & kContainer, containerB = b.flags & kContainer;
    if (containerA && containerB) return false;
    if (containerA || containerB) {
        if (!containers) return false;
        const ObjectPose& held = containerA ? b : a;
        if (held.flags & kIgnoreContainers) return false;
    }
    return true;
}

PairTest testPair(const ObjectPose& a, const ObjectPose& b, Accuracy accuracy) {
    PairTest t;  // the return value itself (one object returned on every path)
    if (!closestPairByTables(accuracy)) {
        if (accuracy == Accuracy::Circle)
            closestPairTest(t, a, b, accuracy, TableRadius{});
        else
            t = everyPairTest(a, b, accuracy == Accuracy::Exact);  // all-radii, exact
        return t;
    }
    auto follow = [&](const PairPath& path) __attribute__((always_inline)) {
        followPath(t, a, b, path, accuracy);
    };
    takePath(a, b, accuracy, follow, follow);
    return t;
}

PairTest testPairPlain(const ObjectPose& a, const ObjectPose& b, Accuracy accuracy) {
    assert(accuracy != Accuracy::AllRadii && accuracy != Accuracy::Exact);
    PairTest t;
    closestPairTest(t, a, b, accuracy, PlainRadius{});
    return t;
}

}  // namespace polar
