#include "polar/effects.h"

namespace polar {

const char* effectName(Effect effect) {
    switch (effect) {
        case kEffectPhysics: return "physics";
        case kEffectCollisions: return "collisions";
        case kEffectResponse: return "response";
        case kEffectContainers: return "containers";
    }
    return "?";
}

std::optional<Effect> effectFromName(std::string_view name) {
    for (Effect effect : kAllEffects)
        if (name == effectName(effect)) return effect;
    return std::nullopt;
}

}  // namespace polar
