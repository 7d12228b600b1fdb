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
//
// Images by stem. A sprite is a folder and a stem in any format the image loader reads, so a mod's
// "sprites/ship.gif" replaces the game's "sprites/ship.png" without a scene or bounds file naming
// it. The rule, the one place it is written: a logical path with an image ending (kImageExtensions,
// any case) resolves layer by layer, from the last mod down to assets/, and in the first layer
// that holds either it is
//   1. the file with exactly that name, else
//   2. an image beside it with the same stem and another image ending, the ending first in
//      kImageExtensions winning (PNG, then GIF, WebP, …; then the lower name: "ship.GIF" before
//      "ship.gif").
// So a layer with both ship.png and ship.gif serves each name as it is written: a scene naming
// ship.png gets ship.png, one naming ship.gif gets ship.gif; the named file is never passed over
// for another one in the same folder, and in every layer that has the named file the result is
// what it was before stems counted. Other files (ship.txt, ship.bounds.json) match only by exact
// name. The decoder is chosen by the file's bytes, never by its ending.
class AssetFs {
  public:
    explicit AssetFs(std::string assetRoot, std::vector<std::string> mods = {});

    // The asset folder (the one with scenes/ and sprites/): $POLARCADE_ASSETS when set, else
    // EXE_DIR/../share/polarcade (an installed game, wherever its prefix was moved), else, for an
    // executable in the build tree, the source tree's assets/. An Error naming every place tried
    // when none is an asset folder.
    static Result<std::string> findRoot();

    // The file on disk for a logical path (by the rule above), or nothing when no layer has it.
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
        // Logical paths that assets/ or an earlier mod also has, or, for an image, has an image of the
        // same folder and stem ("sprites/ship.gif" over "sprites/ship.png").
        std::vector<std::string> replaces;
        std::vector<std::string> adds;  // logical paths no layer below it has
    };
    // One summary per mod, in command-line order (for the list the game prints at start).
    std::vector<ModSummary> summarise() const;

    const std::string& root() const { return root_; }
    const std::vector<std::string>& mods() const { return mods_; }

  private:
    std::string root_;
    std::vector<std::string> mods_;
};

// Where the asset folder is looked for, in order (AssetFs::findRoot with this process's places).
struct AssetPlaces {
    std::optional<std::string> override;                // $POLARCADE_ASSETS: when set, the only place
    std::string executableFolder;                       // the running executable's folder; empty when unknown
    std::string fromExecutable = "../share/polarcade";  // the installed assets, from executableFolder
    std::string buildBinFolder;  // the build tree's bin/, whose executables use sourceAssets
    std::string sourceAssets;    // the source tree's assets/
};
Result<std::string> findAssetRoot(const AssetPlaces& places);

// The folder of the running executable (from /proc/self/exe), or "" where the system does not say.
std::string executableFolder();

// Where the modding guide is for this executable: the source tree's assets/README.md when it runs
// from the build tree, else the installed copy (EXE_DIR/../share/doc/polarcade/README.md).
std::string moddingGuidePath();

}  // namespace polar::game
