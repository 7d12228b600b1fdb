#include "files/assets.h"

#include <unistd.h>
#if defined(__EMSCRIPTEN__)
#include <emscripten.h>
#endif

#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <string_view>
#include <utility>

#include "polar/image_extensions.h"

namespace polar::game {

namespace fs = std::filesystem;

AssetFs::AssetFs(std::string assetRoot, std::vector<std::string> mods)
    : root_(std::move(assetRoot)), mods_(std::move(mods)) {}

std::string executableFolder() {
#if defined(__EMSCRIPTEN__)
    // Under node the program is its .js file, in the folder node names __dirname; a page has none.
    char folder[4096] = "";
    EM_ASM(
        {
            if (typeof __dirname == 'string' && lengthBytesUTF8(__dirname) < $1)
                stringToUTF8(__dirname, $0, $1);
        },
        folder, sizeof folder);
    return folder;
#endif
    // PATH_MAX is 4096 on Linux; a longer path is reported as unknown rather than cut.
    char buffer[4096];
    const ssize_t length = ::readlink("/proc/self/exe", buffer, sizeof buffer);
    if (length <= 0 || static_cast<std::size_t>(length) >= sizeof buffer) return "";
    return fs::path(std::string(buffer, static_cast<std::size_t>(length))).parent_path().string();
}

namespace {

// Why `folder` is not an asset folder, or "" when it is one.
std::string assetFolderProblem(const fs::path& folder) {
    std::error_code ec;
    if (!fs::exists(folder, ec)) return "no such folder";
    if (!fs::is_directory(folder, ec)) return "not a folder";
    for (const char* part : {"scenes", "sprites"})
        if (!fs::is_directory(folder / part, ec)) return std::string("no ") + part + "/ in it";
    return "";
}

bool sameFolder(const std::string& a, const std::string& b) {
    if (a.empty() || b.empty()) return false;
    std::error_code ecA, ecB;
    const fs::path canonicalA = fs::weakly_canonical(a, ecA), canonicalB = fs::weakly_canonical(b, ecB);
    return !ecA && !ecB && canonicalA == canonicalB;
}

}  // namespace

Result<std::string> findAssetRoot(const AssetPlaces& places) {
    std::vector<std::pair<std::string, std::string>> candidates;  // (folder, how the user knows it)
    if (places.override) {
        candidates.emplace_back(*places.override, "POLARCADE_ASSETS=");
    } else {
        if (!places.executableFolder.empty())
            candidates.emplace_back((fs::path(places.executableFolder) / places.fromExecutable).string(), "");
        if (sameFolder(places.executableFolder, places.buildBinFolder))
            candidates.emplace_back(places.sourceAssets, "");
    }
    std::string tried;
    for (const auto& [folder, label] : candidates) {
        const fs::path path = fs::path(folder).lexically_normal();
        const std::string problem = assetFolderProblem(path);
        if (problem.empty()) return path.string();
        tried += (tried.empty() ? "" : ", ") + label + path.string() + " (" + problem + ")";
    }
    if (candidates.empty()) tried = "nowhere (the executable's folder is unknown)";
    Error error;
    error.what = "no asset folder found; tried " + tried;
    error.expected = "a folder with scenes/ and sprites/ (POLARCADE_ASSETS=DIR chooses one)";
    return error;
}

std::string moddingGuidePath() {
    const std::string folder = executableFolder();
    if (folder.empty() || sameFolder(folder, POLAR_BUILD_BIN_DIR))
        return (fs::path(POLAR_SOURCE_ASSETS) / "README.md").lexically_normal().string();
    return (fs::path(folder) / POLAR_GUIDE_FROM_BIN).lexically_normal().string();
}

Result<std::string> AssetFs::findRoot() {
    AssetPlaces places;
    if (const char* env = std::getenv("POLARCADE_ASSETS"); env && *env) places.override = env;
    places.executableFolder = executableFolder();
    places.fromExecutable = POLAR_ASSETS_FROM_BIN;
    places.buildBinFolder = POLAR_BUILD_BIN_DIR;
    places.sourceAssets = POLAR_SOURCE_ASSETS;
    return findAssetRoot(places);
}

namespace {

// Where `name`'s image ending ("ship.GIF" → ".gif") stands in kImageExtensions, or nothing when it
// has none. The rank that breaks a tie between two images of one stem in one layer: PNG first.
std::optional<std::size_t> imageExtensionRank(std::string_view name) {
    const std::string_view stem = withoutImageExtension(name);
    if (stem.empty()) return std::nullopt;
    const std::string_view ending = name.substr(stem.size());
    for (std::size_t i = 0; i < std::size(kImageExtensions); ++i) {
        const std::string_view ext = kImageExtensions[i];
        bool same = ending.size() == ext.size();
        for (std::size_t k = 0; same && k < ext.size(); ++k) same = (ending[k] | 0x20) == ext[k];
        if (same) return i;
    }
    return std::nullopt;
}

// The file in one layer that a logical path names (AssetFs's rule): that exact file, else, for an
// image, the one image beside it with the same stem whose ending comes first in kImageExtensions
// (then the lowest name, for "ship.GIF" beside "ship.gif").
std::optional<fs::path> inLayer(const fs::path& layer, const std::string& logical) {
    std::error_code ec;
    const fs::path exact = layer / logical;
    if (fs::is_regular_file(exact, ec)) return exact;
    if (!imageExtensionRank(logical)) return std::nullopt;
    const std::string stem(withoutImageExtension(exact.filename().string()));
    if (stem.empty() || !fs::is_directory(exact.parent_path(), ec)) return std::nullopt;
    std::optional<fs::path> best;
    std::pair<std::size_t, std::string> bestKey;
    for (auto it =
             fs::directory_iterator(exact.parent_path(), fs::directory_options::skip_permission_denied, ec);
         !ec && it != fs::directory_iterator(); it.increment(ec)) {
        const std::string name = it->path().filename().string();
        const std::optional<std::size_t> rank = imageExtensionRank(name);
        if (!rank || withoutImageExtension(name) != stem || !it->is_regular_file(ec)) continue;
        std::pair<std::size_t, std::string> key{*rank, name};
        if (!best || key < bestKey) {
            best = it->path();
            bestKey = std::move(key);
        }
    }
    return best;
}

}  // namespace

std::optional<std::string> AssetFs::resolve(const std::string& logical) const {
    std::error_code ec;
    if (fs::path(logical).is_absolute()) {
        if (fs::is_regular_file(logical, ec)) return logical;
        return std::nullopt;
    }
    for (auto mod = mods_.rbegin(); mod != mods_.rend(); ++mod)
        if (std::optional<fs::path> file = inLayer(*mod, logical)) return file->generic_string();
    if (std::optional<fs::path> file = inLayer(root_, logical)) return file->generic_string();
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
    // The images below by folder and stem ("sprites/ship"): a mod's image of that stem replaces them.
    auto imageStems = [](const std::set<std::string>& files) {
        std::set<std::string, std::less<>> stems;
        for (const std::string& file : files)
            if (imageExtensionRank(file)) stems.emplace(withoutImageExtension(file));
        return stems;
    };
    std::set<std::string, std::less<>> belowImages = imageStems(below);
    for (const std::string& mod : mods_) {
        ModSummary summary{mod, {}, {}};
        std::set<std::string> files = filesUnder(mod, "");
        for (const std::string& file : files) {
            const bool image = imageExtensionRank(file).has_value();
            const bool replaces =
                below.count(file) || (image && belowImages.count(withoutImageExtension(file)));
            (replaces ? summary.replaces : summary.adds).push_back(file);
        }
        belowImages.merge(imageStems(files));
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
