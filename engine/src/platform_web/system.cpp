#include "polar/platform/system.h"

#include <filesystem>

namespace polar::platform {

// /data is IndexedDB-backed in the page (web_runtime.js mounts IDBFS there and writes it back),
// plain memory elsewhere (node).
Result<std::string> userDataFolder(const std::string&, const std::string& app) {
    const std::string folder = "/data/" + app + "/";
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) return Error{folder, 0, 0, "the browser's data folder cannot be created: " + ec.message(), ""};
    return folder;
}

}  // namespace polar::platform
