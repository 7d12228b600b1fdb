#include "polar/world_hash.h"

#include "world/world_impl.h"

namespace polar {

void addObjectState(StateHash& hash, const GameObject& object) {
    const Transform& t = object.transform;
    hash.add(std::uint64_t{object.id});
    hash.add(t.position().x());
    hash.add(t.position().y());
    hash.add(t.rotation());
    hash.add(t.scaleFactors().x());
    hash.add(t.scaleFactors().y());
    hash.add(object.velocity.x());
    hash.add(object.velocity.y());
    hash.add(object.spin);
    hash.add(object.damping);
    hash.add(std::uint64_t{object.flags});
}

std::uint64_t objectHash(const GameObject& object) {
    StateHash hash;
    addObjectState(hash, object);
    return hash.value();
}

std::uint64_t World::hash() const {
    // The rules (effects, restitution, narrow-phase accuracy) and the next id decide the future as
    // much as the objects do. The broad phase does not: every method finds the same pairs.
    const Impl& w = *impl_;
    StateHash hash;
    hash.add(std::uint64_t{w.def_.effects});
    hash.add(w.def_.restitution);
    hash.add(static_cast<int>(w.def_.accuracy));
    hash.add(std::uint64_t{w.nextId_});
    hash.add(std::uint64_t{w.objects_.size()});
    for (const GameObject& object : w.objects_) addObjectState(hash, object);
    return hash.value();
}

}  // namespace polar
