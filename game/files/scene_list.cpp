#include "files/scene_list.h"

#include <filesystem>

namespace polar::game {

namespace fs = std::filesystem;

std::vector<SceneEntry> listScenes(const AssetFs& assets) {
    std::vector<SceneEntry> scenes;
    for (const std::string& file : assets.list("scenes")) {
        const fs::path path(file);
        if (path.extension() != ".json" || path.parent_path() != "scenes") continue;
        SceneEntry entry{path.stem().string(), file, ""};
        std::error_code ec;
        for (auto mod = assets.mods().rbegin(); mod != assets.mods().rend(); ++mod) {
            if (!fs::is_regular_file(fs::path(*mod) / file, ec)) continue;
            const fs::path folder = fs::path(*mod).lexically_normal();
            entry.mod = (folder.filename().empty() ? folder.parent_path() : folder).filename().string();
            break;
        }
        scenes.push_back(std::move(entry));
    }
    return scenes;
}

Result<std::string> resolveScene(const AssetFs& assets, const std::string& scene) {
    std::error_code ec;
    if (fs::is_regular_file(scene, ec)) return fs::absolute(scene).lexically_normal().generic_string();
    std::string logical = "scenes/" + scene + ".json";
    if (assets.resolve(logical)) return logical;
    std::string names;  // from assets/ and every mod
    for (const SceneEntry& entry : listScenes(assets)) names += (names.empty() ? "" : ", ") + entry.name;
    return Error{scene, 0, 0, "no such scene file or scene name",
                 "a scene name (" + names + ") or the path of a scene .json file"};
}

}  // namespace polar::game
