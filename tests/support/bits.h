#pragma once
// A double's bit pattern, for tests that require results the same to the last bit (signed zeros
// and NaN payloads included).
#include <bit>
#include <cstdint>

namespace polar {

inline std::uint64_t bits(double v) {
    return std::bit_cast<std::uint64_t>(v);
}

}  // namespace polar
