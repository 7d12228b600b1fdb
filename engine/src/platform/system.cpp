#include "polar/platform/system.h"

#include <SDL.h>

#include <cstdlib>
#include <filesystem>

#include "polar/atomic_file.h"

namespace polar::platform {

Result<std::string> userDataFolder(const std::string& organisation, const std::string& app) {
    char* folder = SDL_GetPrefPath(organisation.c_str(), app.c_str());
    if (!folder)
        return Error{"the per-user data folder", 0, 0,
                     std::string("SDL could not find or create it: ") + SDL_GetError(), ""};
    std::string path = folder;
    SDL_free(folder);
    return path;
}

Result<std::string> offerFile(const std::string& name, std::string_view bytes) {
    namespace fs = std::filesystem;
    fs::path folder;
    std::error_code ec;
    if (const char* chosen = std::getenv("XDG_DOWNLOAD_DIR"); chosen && *chosen) {
        folder = chosen;
    } else if (const char* home = std::getenv("HOME"); home && *home) {
        folder = home;
        if (fs::is_directory(folder / "Downloads", ec)) folder /= "Downloads";
    } else {
        return Error{name, 0, 0, "there is no folder to export to", "$XDG_DOWNLOAD_DIR or a home folder"};
    }
    const fs::path wanted(name);
    fs::path path = folder / wanted;
    for (int n = 2; fs::exists(path, ec); ++n)
        path = folder / (wanted.stem().string() + "-" + std::to_string(n) + wanted.extension().string());
    if (std::optional<Error> error = writeFileAtomically(path.string(), bytes)) return *error;
    return path.string();
}

}  // namespace polar::platform
