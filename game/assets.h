#pragma once
#include <optional>
#include <set>
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
    // Reads a logical path through the overlay (a polar::FileReader). The file keeps its logical
    // path, so the paths a scene names stay logical and go through the overlay too.
    FileReader reader() const;
    // The error with its file shown as the file on disk ("mymod/sprites/ship.bounds.json"), so a
    // modder knows which layer's file to fix; unchanged when no layer has the file.
    Error onDisk(Error error) const;

    // The logical paths of the regular files under `folder` ("scenes") in any layer, sorted, each once.
    std::vector<std::string> list(const std::string& folder) const;

    // What one mod folder does to the game's files.
    struct ModSummary {
        std::string folder;
        std::vector<std::string> replaces;  // logical paths that assets/ or an earlier mod also has
        std::vector<std::string> adds;      // logical paths no layer below it has
    };
    // One summary per mod, in command-line order (for the list the game prints at start).
    std::vector<ModSummary> summarise() const;

    const std::string& root() const { return root_; }
    const std::vector<std::string>& mods() const { return mods_; }

  private:
    std::string root_;
    std::vector<std::string> mods_;
};

}  // namespace polar::game
