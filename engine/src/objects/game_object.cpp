#include "polar/game_object.h"

namespace polar {

const char* flagName(ObjectFlag flag) {
    switch (flag) {
        case kPhysics:
            return "physics";
        case kCollisions:
            return "collisions";
        case kGhost:
            return "ghost";
        case kContainer:
            return "container";
        case kIgnoreContainers:
            return "ignore_containers";
        case kFast:
            return "fast";
    }
    return "?";
}

std::optional<ObjectFlag> flagFromName(std::string_view name) {
    for (ObjectFlag flag : kAllFlags)
        if (name == flagName(flag)) return flag;
    return std::nullopt;
}

}  // namespace polar
