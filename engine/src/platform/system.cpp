#include "polar/platform/system.h"

#include <SDL.h>

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

}  // namespace polar::platform
