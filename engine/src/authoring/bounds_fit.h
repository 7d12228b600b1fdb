#pragma once
#include <functional>
#include <string>
#include <utility>

#include "polar/authoring/bounds_gen.h"
#include "polar/bounds_file.h"
#include "polar/error.h"
#include "polar/math.h"

namespace polar {

// One Bound with `samples` samples (0: BoundsGenOptions' automatic count) whose straight-edge
// outline around `centre` encloses every square of `set` with the least area, or, for a container,
// stays inside the free space around it (`set` being the walls) with the most. `progress` gets the
// fraction done. A container's centre on a wall is an Error naming no file.
Result<BoundSpec> fitBound(const PixelSet& set, const Vec2& centre, bool container, int samples,
                           const std::function<void(double)>& progress);

// An Error about what `generateBounds` was asked for, naming no file (the caller adds it).
inline Error optionError(std::string what, std::string expected) {
    return Error{"", 0, 0, std::move(what), std::move(expected)};
}

}  // namespace polar
