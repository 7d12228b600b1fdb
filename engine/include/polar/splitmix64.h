#pragma once
#include <cstdint>

namespace polar {

// One step of splitmix64 (Steele, Lea and Flood, 2014): advances `state` by the golden-ratio
// increment and returns the mixed value. Its sequence is fixed by the seed on every platform (the
// standard library's distributions are not specified bit for bit), so seeded scenes and generated
// art come out the same everywhere. Not for anything an adversary may predict.
constexpr std::uint64_t splitmix64(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

}  // namespace polar
