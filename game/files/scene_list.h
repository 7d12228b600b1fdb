#pragma once
#include <string>
#include <vector>

#include "files/assets.h"
#include "polar/error.h"

namespace polar::game {

// A scene the game can start: one of assets/scenes/*.json or a mod's.
struct SceneEntry {
    std::string name;     // the file's stem ("cave"), what --scene takes
    std::string logical;  // "scenes/cave.json"
    std::string mod;      // the mod folder that has the file (the last one wins); empty for assets/
};

// The scenes in assets/scenes/ and every mod's scenes/, by name, each once.
std::vector<SceneEntry> listScenes(const AssetFs& assets);

// A scene by name (assets/scenes/NAME.json, through the mods) or by file path: its logical path,
// or an absolute one for a file. An Error listing the names when there is no such scene.
Result<std::string> resolveScene(const AssetFs& assets, const std::string& scene);

}  // namespace polar::game
