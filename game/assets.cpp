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

namespace {

// The logical paths of the regular files under `root`/`folder`, or all of `root` for an empty folder.
std::set<std::string> filesUnder(const std::string& root, const std::string& folder) {
    std::set<std::string> out;
    std::error_code ec;
    fs::path base = fs::path(root);
    fs::path start = folder.empty() ? base : base / folder;
    if (!fs::is_directory(start, ec)) return out;
    for (auto it = fs::recursive_directory_iterator(start, fs::directory_options::skip_permission_denied, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (it->is_regular_file(ec)) out.insert(fs::relative(it->path(), base, ec).generic_string());
    }
    return out;
}

}  // namespace

std::vector<std::string> AssetFs::list(const std::string& folder) const {
    std::set<std::string> all = filesUnder(root_, folder);
    for (const std::string& mod : mods_) all.merge(filesUnder(mod, folder));
    return {all.begin(), all.end()};
}

std::vector<AssetFs::ModSummary> AssetFs::summarise() const {
    std::vector<ModSummary> out;
    std::set<std::string> below = filesUnder(root_, "");
    for (const std::string& mod : mods_) {
        ModSummary summary{mod, {}, {}};
        std::set<std::string> files = filesUnder(mod, "");
        for (const std::string& file : files)
            (below.count(file) ? summary.replaces : summary.adds).push_back(file);
        below.merge(files);
        out.push_back(std::move(summary));
    }
    return out;
}

FileReader AssetFs::reader() const {
    FileReader disk = diskReader();
    return [this, disk](const std::string& logical) -> std::optional<SourceFile> {
        std::optional<std::string> path = resolve(logical);
        if (!path) return std::nullopt;
        std::optional<SourceFile> file = disk(*path);
        if (file) file->path = logical;
        return file;
    };
}

Error AssetFs::onDisk(Error error) const {
    if (error.file.empty()) return error;
    if (std::optional<std::string> path = resolve(error.file)) error.file = *path;
    return error;
}

}  // namespace polar::game
