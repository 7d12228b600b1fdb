#pragma once
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "polar/bound.h"
#include "polar/error.h"

namespace polar {

class World;

// A World's whole state, held to restore later: for rollback, replay seeking and tests.
//
// Why bytes and a table? Everything an object is, but its bounds, is plain data and goes into
// `bytes`: the rules, the objects in creation order (id, transform, motion, flags, name, user
// data), the next id, the step count and stats, the last step's hits and collidedWith lists.
// Bounds are shared and immutable (BoundsPtr), so the snapshot keeps each distinct one once in
// `bounds` and the objects refer to it by index: saving copies no outline, restoring allocates
// none, and a damaged index is caught like any other damage.
//
// `bytes` starts with a header: a magic number, the version (kWorldSnapshotVersion), the size of the
// rest and its checksum (snapshot_bytes.h). A buffer cut short, of another version or with a byte
// changed is refused whole, before the world is touched.
struct WorldSnapshot {
    std::vector<std::uint8_t> bytes;
    std::vector<BoundsPtr> bounds;

    // Memory this snapshot takes: its bytes and its table (not counting the shared bounds).
    std::size_t heldBytes() const { return bytes.size() + bounds.size() * sizeof(BoundsPtr); }
};

inline constexpr std::uint32_t kWorldSnapshotVersion = 2;

// Saves `world` into `out`, reusing the memory `out` holds (a warm save allocates nothing).
void saveSnapshot(const World& world, WorldSnapshot& out);

// Restores `world` to the state saved in `snapshot`: afterwards world.hash() is the one at the save,
// and stepping on gives the same bits as the saved world would have. The world keeps its threads
// (WorldDef's workers, tasks, parallelMin) and its timing switch; everything else is the snapshot's,
// its effects too. On a damaged snapshot, returns the error and leaves the world as it was.
// Nothing is returned on success.
std::optional<Error> restoreSnapshot(World& world, const WorldSnapshot& snapshot);

}  // namespace polar
