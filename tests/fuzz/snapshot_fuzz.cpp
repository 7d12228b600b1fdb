// libFuzzer target: the bytes are a world snapshot (world_snapshot.h), restored into a world with a
// table of three bounds. The first byte chooses how: odd, the rest is the whole buffer as given
// (header and all); even, the rest is the state after the header, which the target seals with a
// right header and checksum, so the fuzzer reaches the reader of the state itself and not only the
// checksum. A refused buffer must say what is wrong; a restored world must save and restore again to
// the same hash.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "fuzz_contract.h"
#include "polar/snapshot_bytes.h"
#include "polar/world.h"
#include "polar/world_snapshot.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    polar::WorldSnapshot snapshot;
    snapshot.bounds = {nullptr, polar::circleBounds(4.0), polar::circleBounds(9.0, polar::Vec2(1, 2))};
    if (data[0] & 1) {
        snapshot.bytes.assign(data + 1, data + size);
    } else {
        // A real header: magic and version as saveSnapshot writes them, then size and checksum.
        polar::WorldSnapshot empty;
        polar::saveSnapshot(polar::World(), empty);
        std::uint64_t payload = size - 1;
        std::uint64_t checksum = polar::snapshotChecksum(data + 1, payload);
        snapshot.bytes.assign(empty.bytes.begin(), empty.bytes.begin() + 8);
        snapshot.bytes.resize(24);
        std::memcpy(snapshot.bytes.data() + 8, &payload, 8);
        std::memcpy(snapshot.bytes.data() + 16, &checksum, 8);
        snapshot.bytes.insert(snapshot.bytes.end(), data + 1, data + size);
    }
    snapshot.bytes.shrink_to_fit();
    polar::World world;
    std::uint64_t before = world.hash();
    std::optional<polar::Error> error = polar::restoreSnapshot(world, snapshot);
    if (error) {
        if (error->what.empty()) polar::fuzz::broken("the error says nothing", error->message());
        if (error->message().find('\n') != std::string::npos)
            polar::fuzz::broken("the message spans more than one line", error->message());
        if (world.hash() != before)
            polar::fuzz::broken("a refused snapshot changed the world", error->message());
        return 0;
    }
    polar::WorldSnapshot again;
    polar::saveSnapshot(world, again);
    polar::World copy;
    if (std::optional<polar::Error> e = polar::restoreSnapshot(copy, again))
        polar::fuzz::broken("a restored world's own snapshot is refused", e->message());
    if (copy.hash() != world.hash()) polar::fuzz::broken("save → restore changed the hash", "");
    if (world.objects().size() < 200) world.step(1.0 / 60);  // whatever it holds, a step takes it
    return 0;
}
