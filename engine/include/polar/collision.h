#pragma once
#include <cstdint>

#include "polar/accuracy.h"
#include "polar/math.h"

namespace polar {

enum class ContactKind { Contact, Container };
const char* contactKindName(ContactKind kind);

// The outcome of a pair test (A earlier in the scene than B).
// The 16-byte-aligned normal comes first and the small fields last, so that no padding is needed
// inside: 64 bytes, and the World keeps one per hit.
struct PairTest {
    Vec2 normal = Vec2::UnitX();  // unit; B separates by moving along +normal, A along −normal
    double distance = 0.0;        // |u|, u = Bcr's world centre − Acr's world centre
    double ra = 0.0;              // A's world radius as the rule used it
    double rb = 0.0;              // B's
    double penetration = 0.0;     // how far apart to move them; > 0 means overlap
    ContactKind kind = ContactKind::Contact;
    bool hit = false;
    std::uint32_t radiiA = 0;  // the Bound of A that took part (Acr), in file order
    std::uint32_t radiiB = 0;  // Bcr
};

// One tested pair of a detection pass, by index in creation order (a < b).
struct PairReport {
    std::uint32_t a = 0;
    std::uint32_t b = 0;
    PairTest test;
};

}  // namespace polar
