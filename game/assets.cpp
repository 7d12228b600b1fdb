#include "assets.h"

#include <cstdlib>
#include <filesystem>

namespace polar::game {

namespace fs = std::filesystem;

AssetFs::AssetFs(std::string assetRoot, std::vector<std::string> mods)
    : root_(std::move(assetRoot)), mods_(std::move(mods)) {}

std::string AssetFs::defaultRoot() {
    if (const char* env = std::getenv("POLAR_ASSETS"); env && *env) return env;
    return POLAR_ASSET_DIR;
}

std::optional<std::string> AssetFs::resolve(const std::string& logical) const {
    std::error_code ec;
    if (fs::path(logical).is_absolute()) {
        if (fs::is_regular_file(logical, ec)) return logical;
        return std::nullopt;
    }
    for (auto mod = mods_.rbegin(); mod != mods_.rend(); ++mod) {
        fs::path candidate = fs::path(*mod) / logical;
        if (fs::is_regular_file(candidate, ec)) return candidate.generic_string();
    }
    fs::path base = fs::path(root_) / logical;
    if (fs::is_regular_file(base, ec)) return base.generic_string();
    return std::nullopt;
}

FileReader AssetFs::reader() const {
    FileReader disk = diskReader();
    return [this, disk](const std::string& logical) -> std::optional<SourceFile> {
        std::optional<std::string> path = resolve(logical);
        if (!path) return std::nullopt;
        return disk(*path);
    };
}

}  // namespace polar::game
