#include "world/name_index.h"

#include <algorithm>
#include <functional>

namespace polar {
namespace {

std::uint32_t hashName(std::string_view name) {
    std::uint64_t h = std::hash<std::string_view>{}(name);
    return static_cast<std::uint32_t>(h ^ (h >> 32));
}

const GameObject* objectOf(ObjectId id, std::span<const GameObject> objects) {
    auto it = std::lower_bound(objects.begin(), objects.end(), id,
                               [](const GameObject& o, ObjectId i) { return o.id < i; });
    return (it != objects.end() && it->id == id) ? &*it : nullptr;
}

}  // namespace

std::size_t NameIndex::slotOf(std::string_view name, std::span<const GameObject> objects) const {
    if (slots_.empty()) return kNone;
    std::size_t mask = slots_.size() - 1;
    std::uint32_t hash = hashName(name);
    for (std::size_t k = hash & mask;; k = (k + 1) & mask) {
        const Slot& slot = slots_[k];
        if (slot.id == 0) return kNone;
        if (slot.hash == hash) {
            const GameObject* object = objectOf(slot.id, objects);
            if (object && object->name == name) return k;
        }
    }
}

ObjectId NameIndex::find(std::string_view name, std::span<const GameObject> objects) const {
    std::size_t k = slotOf(name, objects);
    return k == kNone ? 0 : slots_[k].id;
}

void NameIndex::reserve(std::size_t objects) {
    std::size_t size = 16;
    while (size < 2 * objects) size *= 2;
    if (size <= slots_.size()) return;
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(size, Slot{});
    for (const Slot& slot : old) {
        if (slot.id == 0) continue;
        std::size_t k = slot.hash & (size - 1);
        while (slots_[k].id != 0) k = (k + 1) & (size - 1);
        slots_[k] = slot;
    }
}

void NameIndex::insert(ObjectId id, std::string_view name, std::size_t objects) {
    reserve(objects);
    std::size_t mask = slots_.size() - 1;
    std::uint32_t hash = hashName(name);
    std::size_t k = hash & mask;
    while (slots_[k].id != 0) k = (k + 1) & mask;
    slots_[k] = {id, hash};
}

void NameIndex::erase(std::string_view name, std::span<const GameObject> objects) {
    std::size_t k = slotOf(name, objects);
    if (k == kNone) return;
    // Backward-shift deletion: pull later members of the probe run into the hole.
    std::size_t mask = slots_.size() - 1;
    slots_[k] = Slot{};
    for (std::size_t next = (k + 1) & mask; slots_[next].id != 0; next = (next + 1) & mask) {
        std::size_t home = slots_[next].hash & mask;
        // Move it back if its home is not in the (circular) range (k, next].
        bool between = k <= next ? (home > k && home <= next) : (home > k || home <= next);
        if (!between) {
            slots_[k] = slots_[next];
            slots_[next] = Slot{};
            k = next;
        }
    }
}

void NameIndex::rebuild(std::span<const GameObject> objects) {
    // The layout depends on the order names came and went; lookups do not.
    slots_.clear();
    reserve(objects.size());
    for (const GameObject& o : objects)
        if (!o.name.empty()) insert(o.id, o.name, objects.size());
}

}  // namespace polar
