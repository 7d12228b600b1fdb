#include <array>
#include <cctype>

#include "polar/platform/events.h"

namespace polar::platform {
namespace {

// Row i names Key i (Key::Unknown first).
// clang-format off
constexpr const char* kNames[] = {
    "unknown",
    "a", "b", "c", "d", "e", "f", "g", "h", "i", "j", "k", "l", "m", "n", "o", "p", "q", "r", "s", "t",
    "u", "v", "w", "x", "y", "z",
    "0", "1", "2", "3", "4", "5", "6", "7", "8", "9",
    "space", "enter", "keypad-enter", "escape", "backspace", "tab", "delete", "insert", "home", "end",
    "page-up", "page-down",
    "left", "right", "up", "down",
    "f1", "f2", "f3", "f4", "f5", "f6", "f7", "f8", "f9", "f10", "f11", "f12",
    "left-shift", "right-shift", "left-ctrl", "right-ctrl", "left-alt", "right-alt",
    "minus", "equals", "comma", "period", "slash",
};
// clang-format on
static_assert(std::size(kNames) == std::size_t(Key::Count), "one name per Key");

bool sameName(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) != b[i]) return false;
    return true;
}

}  // namespace

const char* keyName(Key key) {
    return key < Key::Count ? kNames[std::size_t(key)] : kNames[0];
}

std::optional<Key> keyFromName(std::string_view name) {
    for (std::size_t i = 1; i < std::size(kNames); ++i)
        if (sameName(name, kNames[i])) return Key(i);
    return std::nullopt;
}

}  // namespace polar::platform
