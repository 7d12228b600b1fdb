#pragma once
#include <optional>
#include <string>
#include <vector>

#include "polar/error.h"

namespace polar::game {

// The game's view of its files: assets/ with mod folders laid over it.
//
// Why logical paths? Scenes and bounds name each other by paths relative to themselves, and a mod
// replaces a file by putting one at the same relative path. So the game speaks of "sprites/ship.png",
// and only here does that become a file on disk: the last mod that has it wins, then assets/.
// Absolute paths bypass the overlay (a scene given on the command line, and what it names).
class AssetFs {
public:
    explicit AssetFs(std::string assetRoot, std::vector<std::string> mods = {});

    // The folder assets/ is in, from POLAR_ASSETS in the environment or the build's source tree.
    static std::string defaultRoot();

    // The file on disk for a logical path, or nothing when no layer has it.
    std::optional<std::string> resolve(const std::string& logical) const;
    // Reads a logical path through the overlay (a polar::FileReader).
    FileReader reader() const;

    const std::string& root() const { return root_; }
    const std::vector<std::string>& mods() const { return mods_; }

private:
    std::string root_;
    std::vector<std::string> mods_;
};

}  // namespace polar::game
