#include "polar/effects.h"

#include <bit>

namespace polar {

const char* effectName(Effect effect) {
    switch (effect) {
        case kEffectPhysics:
            return "physics";
        case kEffectCollisions:
            return "collisions";
        case kEffectResponse:
            return "response";
        case kEffectContainers:
            return "containers";
        case kEffectCcd:
            return "ccd";
    }
    return "?";
}

std::optional<Effect> effectFromName(std::string_view name) {
    for (Effect effect : kAllEffects)
        if (name == effectName(effect)) return effect;
    return std::nullopt;
}

std::size_t effectIndex(Effect effect) {
    return static_cast<std::size_t>(std::countr_zero(static_cast<std::uint32_t>(effect)));
}

}  // namespace polar
