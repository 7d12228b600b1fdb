#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "polar/authoring/alpha_mask.h"
#include "polar/bounds_file.h"

namespace polar {

// Something legal but suspicious in a bounds file, placed by the JSON pointer of the value.
struct BoundsWarning {
    std::string pointer;  // "/radii/0/samples/3"
    std::string what;
    std::string expected;
};

// How far a sample point may stray from the sprite's edge before `check` warns:
// max(kMinPixels, kFraction × the sample's radius), in sprite pixels.
struct SuspicionLimits {
    static constexpr double kMinPixels = 4.0;
    static constexpr double kFraction = 0.25;
};

// Legal but suspicious things about `spec` as bounds of `sprite`:
//   - a centre outside the sprite's image rectangle [−w/2, w/2] × [−h/2, h/2];
//   - a sample point (centre + radius in the sample's direction) far outside the opaque area: its
//     distance to the nearest opaque pixel square exceeds the SuspicionLimits;
//   - a sample point deep inside the opaque area: its distance to the nearest transparent pixel
//     square (or the image's edge) exceeds them, so the outline cuts into the sprite;
//   - a sprite with no opaque pixels at all.
std::vector<BoundsWarning> suspiciousBounds(const BoundsSpec& spec, const AlphaMask& sprite,
                                            std::uint8_t threshold = AlphaMask::kDefaultThreshold);

// Where the sprite of a bounds file may be, in the order to try: NAME.png beside NAME.bounds.json,
// then, for a file in a folder named "bounds", NAME.png in the sibling folder "sprites".
std::vector<std::string> spriteCandidates(const std::string& boundsPath);

}  // namespace polar
