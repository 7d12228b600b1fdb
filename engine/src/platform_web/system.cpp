#include "polar/platform/system.h"

#include <emscripten.h>

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

namespace {

// A link to the bytes as a Blob, clicked: the browser saves (or asks where to save) the file.
EM_JS(void, polarOfferDownload, (const char* name, const char* bytes, int size), {
    const data = HEAPU8.slice(bytes, bytes + size);
    const url = URL.createObjectURL(new Blob([data]));
    const link = document.createElement('a');
    link.href = url;
    link.download = UTF8ToString(name);
    document.body.appendChild(link);
    link.click();
    link.remove();
    setTimeout(
        function() { URL.revokeObjectURL(url); }, 10000);
});

}  // namespace

Result<std::string> offerFile(const std::string& name, std::string_view bytes) {
    if (!EM_ASM_INT({ return typeof document == 'undefined' ? 0 : 1; }))
        return Error{name, 0, 0, "there is no page to download it from", "the game in a web page"};
    polarOfferDownload(name.c_str(), bytes.data(), static_cast<int>(bytes.size()));
    return std::string("the browser's downloads");
}

}  // namespace polar::platform
