#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "polar/game_object.h"

namespace polar {

// A world's objects by name: which object, if any, holds a non-empty name.
//
// Why open addressing over (id, hash) slots? About 8 bytes per object, where a map of strings
// would copy every name: a slot keeps the id and the name's hash, and a lookup compares the name
// itself on the object. Linear probing, a power-of-two size at most half full, and backward-shift
// deletion, so no tombstones are needed. The objects are passed in (ascending ids, the world's
// creation order), never held.
class NameIndex {
  public:
    // The id of the object named `name`, or 0 (no object has id 0).
    ObjectId find(std::string_view name, std::span<const GameObject> objects) const;
    // Adds a name no object holds yet; `objects` counts the objects once it is added.
    void insert(ObjectId id, std::string_view name, std::size_t objects);
    // Drops a name, if an object holds it; `objects` still holds that object.
    void erase(std::string_view name, std::span<const GameObject> objects);
    // Makes room for this many named objects.
    void reserve(std::size_t objects);
    // Forgets every name and indexes the named ones of `objects` afresh.
    void rebuild(std::span<const GameObject> objects);

  private:
    struct Slot {
        ObjectId id = 0;  // 0: empty
        std::uint32_t hash = 0;
    };
    static constexpr std::size_t kNone = ~std::size_t(0);
    std::size_t slotOf(std::string_view name, std::span<const GameObject> objects) const;  // or kNone

    std::vector<Slot> slots_;  // size a power of two, at most half full
};

}  // namespace polar
