#pragma once
// The two contents the kill -9 test's writer alternates between, known to the test as well, so a
// torn file (part of one, part of the other, or cut short) can never pass for either.
#include <cstddef>
#include <string>

namespace polar::testing {

// `size` bytes for version 0 or 1: a first line naming the version, then a pattern that differs
// between the versions at every byte.
inline std::string atomicContents(int version, std::size_t size) {
    std::string out = "version " + std::to_string(version) + "\n";
    out.reserve(size);
    for (std::size_t i = out.size(); i < size; ++i)
        out += static_cast<char>('a' + (i * 7 + static_cast<std::size_t>(version) * 13) % 26);
    out.resize(size);
    return out;
}

}  // namespace polar::testing
