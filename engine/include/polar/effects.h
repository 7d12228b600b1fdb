#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace polar {

// The systems a scene runs. A scene lists them by name in "effects"; an object's flags decide
// whether it takes part in a running system. An effect a scene does not list costs nothing: the
// World makes no pass for it and holds no memory for it.
enum Effect : std::uint32_t {
    kEffectPhysics = 1u << 0,     // integration and damping of objects flagged physics
    kEffectCollisions = 1u << 1,  // detection between objects flagged collisions
    kEffectResponse = 1u << 2,    // pushing apart and bouncing after a hit
    kEffectContainers = 1u << 3,  // container pairs are tested
    kEffectCcd = 1u << 4,         // continuous collision: fast objects are cast along their motion
};
using Effects = std::uint32_t;

inline constexpr Effect kAllEffects[] = {kEffectPhysics, kEffectCollisions, kEffectResponse,
                                         kEffectContainers, kEffectCcd};
inline constexpr std::size_t kEffectCount = sizeof(kAllEffects) / sizeof(kAllEffects[0]);

const char* effectName(Effect effect);
std::optional<Effect> effectFromName(std::string_view name);
// The effect's position in kAllEffects, for per-effect tables.
std::size_t effectIndex(Effect effect);

}  // namespace polar
