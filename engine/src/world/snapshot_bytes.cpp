#include "polar/snapshot_bytes.h"

#include <string>

namespace polar {

Result<ByteReader> openSnapshotFrame(std::span<const std::uint8_t> bytes, const SnapshotKind& kind) {
    ByteReader header(bytes.data(), bytes.size());
    auto magic = header.get<std::uint32_t>();
    auto version = header.get<std::uint32_t>();
    auto payload = header.get<std::uint64_t>();
    auto checksum = header.get<std::uint64_t>();
    if (!header.ok())
        return snapshotError(kind, "cut off in the header (" + std::to_string(bytes.size()) + " bytes)");
    if (magic != kind.magic) return snapshotError(kind, "not a " + std::string(kind.name));
    if (version != kind.version) return snapshotError(kind, "version " + std::to_string(version));
    if (payload != header.left())
        return snapshotError(kind, "cut off: " + std::to_string(header.left()) + " bytes of a state of " +
                                       std::to_string(payload));
    const std::uint8_t* state = bytes.data() + kSnapshotHeaderBytes;
    if (snapshotChecksum(state, payload) != checksum)
        return snapshotError(kind, "damaged: the checksum does not match");
    return ByteReader(state, payload);
}

Error snapshotError(const SnapshotKind& kind, std::string what) {
    Error error;
    error.file = kind.name;
    error.what = std::move(what);
    error.expected =
        "a buffer written by " + std::string(kind.writtenBy) + ", version " + std::to_string(kind.version);
    return error;
}

std::uint64_t snapshotChecksum(const std::uint8_t* data, std::size_t size) {
    // Four lanes over interleaved words, so the multiplies of neighbouring words overlap instead of
    // waiting on each other: lane l takes words l, l + 4, …; each word: h ← (h ⊕ w)·m, h ⊕= h >> 29.
    // The tail is padded with zeros, and the lanes and the length are mixed at the end.
    constexpr std::uint64_t m = 0x9E3779B97F4A7C15ull;
    std::uint64_t h[4] = {0x2545F4914F6CDD1Dull ^ size, 0x632BE59BD9B4E019ull, 0x85EBCA77C2B2AE63ull,
                          0xC2B2AE3D27D4EB4Full};
    auto mix = [](std::uint64_t& lane, std::uint64_t word) {
        lane = (lane ^ word) * m;
        lane ^= lane >> 29;
    };
    std::size_t k = 0;
    for (; k + 32 <= size; k += 32) {
        std::uint64_t w[4];
        std::memcpy(w, data + k, 32);
        for (int l = 0; l < 4; ++l) mix(h[l], w[l]);
    }
    for (int l = 0; k + 8 <= size; k += 8, ++l) {
        std::uint64_t word;
        std::memcpy(&word, data + k, 8);
        mix(h[l], word);
    }
    std::uint64_t tail = 0;
    if (size > k) std::memcpy(&tail, data + k, size - k);
    mix(h[0], tail);
    std::uint64_t out = h[0];
    for (int l = 1; l < 4; ++l) mix(out, h[l]);
    return out ^ (out >> 32);
}

}  // namespace polar
