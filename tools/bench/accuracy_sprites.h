#pragma once
// The accuracy benchmark's sprites: the game's (a PNG with its .bounds.json beside it), or stand-ins
// the benchmark draws itself when those are not there.
#include <string>
#include <vector>

#include "polar/authoring/pixel_truth.h"
#include "polar/bound.h"
#include "polar/collision.h"
#include "polar/object_flags.h"

namespace polar::bench {

// A sprite as the benchmark tests it: its opaque pixels are the truth, its bounds what the levels read.
struct Sprite {
    std::string name;
    OpaquePixels pixels;
    BoundsPtr bounds;
    bool container = false;  // its opaque pixels surround its transparent centre (the cave)
};

// The game's sprites: every PNG in `dir` with a `.bounds.json` of the same name beside it.
std::vector<Sprite> loadSprites(const std::string& dir, std::string& problem);
// A lumpy rock, a dart and a long bar, drawn here (nothing is written to assets/).
std::vector<Sprite> standInSprites();
// The flags of a sprite's object: a container holds the other object of its pairs.
ObjectFlags flagsOf(const Sprite& s);

}  // namespace polar::bench
