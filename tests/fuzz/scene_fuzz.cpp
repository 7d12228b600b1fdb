// libFuzzer target: the bytes are a scene file's text, loaded as loadScene loads one (parseScene
// with a file reader), then built into a World. The bounds files a scene names come from memory:
// the committed sprites' bounds (read once at start-up) and one broken file.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

#include "fuzz_contract.h"
#include "polar/scene_file.h"

namespace {

const std::string kScenePath = "scenes/fuzz.json";

std::map<std::string, std::string>& files() {
    static std::map<std::string, std::string> files;
    return files;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    namespace fs = std::filesystem;
    polar::FileReader disk = polar::diskReader();
    for (const fs::directory_entry& entry : fs::directory_iterator(fs::path(POLAR_ASSET_DIR) / "sprites")) {
        std::string name = entry.path().filename().string();
        if (name.size() < 12 || name.compare(name.size() - 12, 12, ".bounds.json") != 0) continue;
        if (auto file = disk(entry.path().string())) files()["sprites/" + name] = file->text;
    }
    if (files().empty()) {
        std::fprintf(stderr, "scene_fuzz: no bounds files in %s/sprites\n", POLAR_ASSET_DIR);
        std::abort();
    }
    files()["sprites/broken.bounds.json"] = "{\"format\": 1, \"radii\": [{\"samples\": [[0, -3]]}]}";
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string text(reinterpret_cast<const char*>(data), size);
    polar::FileReader reader = [&](const std::string& path) -> std::optional<polar::SourceFile> {
        if (path == kScenePath) return polar::SourceFile{path, text};
        auto it = files().find(path);
        if (it == files().end()) return std::nullopt;
        return polar::SourceFile{path, it->second};
    };
    polar::Result<polar::SceneDef> scene = polar::loadScene(kScenePath, reader);
    if (!scene) {
        const polar::Error& error = scene.error();
        auto named = files().find(error.file);
        if (error.file != kScenePath && named == files().end())
            polar::fuzz::broken("the error names a file the scene did not read", error.message());
        polar::fuzz::checkError(error, error.file == kScenePath ? text : named->second);
        return 0;
    }
    polar::World world = polar::buildWorld(*scene);
    if (world.objects().size() != scene->objects.size()) polar::fuzz::broken("buildWorld lost objects", "");
    return 0;
}
