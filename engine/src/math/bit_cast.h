#pragma once
#include <cstring>
#include <type_traits>

namespace polar {

// The object representation of `from` read as a To: std::bit_cast's result, through memcpy, which
// every standard library has (emscripten's libc++ lacks std::bit_cast). Compilers turn the copy
// into one register move.
template <class To, class From>
inline To bitCast(const From& from) {
    static_assert(sizeof(To) == sizeof(From), "bitCast needs types of one size");
    static_assert(std::is_trivially_copyable_v<To> && std::is_trivially_copyable_v<From>,
                  "bitCast needs trivially copyable types");
    To to;
    std::memcpy(&to, &from, sizeof(To));
    return to;
}

}  // namespace polar
