// polarcade-bounds check: validates bounds files with the game's own loader (polar::loadBounds) and scene
// files with polar::loadScene, then warns about legal but suspicious bounds (polar::suspiciousBounds).
#include <cstdio>
#include <filesystem>

#include "bounds_tool.h"
#include "cli.h"
#include "files/assets.h"
#include "polar/authoring/bounds_check.h"
#include "polar/bounds_file.h"
#include "polar/json_doc.h"
#include "polar/platform/image_file.h"
#include "polar/scene_file.h"

namespace polar::bounds_tool {
namespace {

bool isBoundsFile(const std::string& path) {
    const std::string suffix = ".bounds.json";
    return path.size() >= suffix.size() &&
           path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
}

void printWarning(const Error& at) {
    std::fprintf(stderr, "%s\n", warningLine(at).c_str());
}

// The sprite to check `boundsPath` against, or nothing (with the places tried).
std::optional<std::string> findSprite(const std::string& boundsPath, const std::string& given) {
    if (!given.empty()) return given;
    for (const std::string& candidate : spriteCandidates(boundsPath)) {
        std::error_code ec;
        if (std::filesystem::is_regular_file(candidate, ec)) return candidate;
    }
    return std::nullopt;
}

// Checks one bounds file; returns false when it is invalid.
bool checkBounds(const std::string& path, const CheckArgs& args) {
    FileReader reader = diskReader();
    // Validity is decided by exactly what the game calls.
    Result<BoundsPtr> loaded = loadBounds(path, reader);
    if (!loaded) {
        std::fprintf(stderr, "%s\n", loaded.error().message().c_str());
        return false;
    }
    std::optional<SourceFile> file = reader(path);
    Result<JsonDoc> doc = JsonDoc::parse(*file);
    Result<BoundsSpec> spec = parseBounds(*file);
    std::size_t samples = 0;
    for (const BoundSpec& r : spec->radii) samples += r.samples.size();
    std::string summary =
        std::to_string(spec->radii.size()) + " radii, " + std::to_string(samples) + " samples";

    std::optional<std::string> sprite = findSprite(path, args.sprite);
    if (!sprite) {
        if (!args.quiet)
            std::printf("%s: ok (%s; no sprite found beside it, sprite checks skipped)\n", path.c_str(),
                        summary.c_str());
        return true;
    }
    Result<RgbaImage> image = loadRgbaImage(*sprite);
    if (!image) {
        printWarning(Error{path, 0, 0, "cannot check against the sprite: " + image.error().message(),
                           "a readable sprite image"});
        return true;
    }
    std::vector<BoundsWarning> warnings =
        suspiciousBounds(*spec, alphaMaskOf(*image), static_cast<std::uint8_t>(args.threshold));
    for (const BoundsWarning& w : warnings) printWarning(doc->errorAt(w.pointer, w.what, w.expected));
    if (!args.quiet)
        std::printf("%s: ok (%s; checked against %s%s)\n", path.c_str(), summary.c_str(), sprite->c_str(),
                    warnings.empty() ? ""
                                     : (", " + std::to_string(warnings.size()) + " warning" +
                                        (warnings.size() == 1 ? "" : "s"))
                                           .c_str());
    return true;
}

// The logical path of `path` when it lies inside one of the mod folders ("scenes/moon.json"), or nothing.
std::optional<std::string> logicalInMod(const std::string& path, const std::vector<std::string>& mods) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::path file = fs::weakly_canonical(path, ec);
    for (auto mod = mods.rbegin(); mod != mods.rend(); ++mod) {
        fs::path relative = file.lexically_relative(fs::weakly_canonical(*mod, ec));
        if (!relative.empty() && *relative.begin() != ".." && relative.is_relative())
            return relative.generic_string();
    }
    return std::nullopt;
}

bool checkScene(const std::string& path, const CheckArgs& args) {
    // A scene inside a mod is read as the game reads it: by its logical path, through the overlay,
    // so it may name the sprites and bounds of assets/ and of other mods.
    Result<std::string> root = game::AssetFs::findRoot();
    if (!root) {
        std::fprintf(stderr, "polarcade-bounds: %s\n", root.error().message().c_str());
        return false;
    }
    game::AssetFs assets(*root, args.mods);
    std::optional<std::string> logical = logicalInMod(path, args.mods);
    Result<SceneDef> scene = logical ? loadScene(*logical, assets.reader()) : loadScene(path, diskReader());
    if (!scene) {
        std::fprintf(stderr, "%s\n", assets.onDisk(scene.error()).message().c_str());
        if (!logical && std::filesystem::path(path).parent_path().filename() == "scenes")
            std::fprintf(stderr,
                         "note: a mod's scene that names files of assets/ is checked with --mod MODFOLDER\n");
        return false;
    }
    if (!args.quiet) std::printf("%s: ok (scene, %zu objects)\n", path.c_str(), scene->objects.size());
    return true;
}

}  // namespace

std::string warningLine(const Error& at) {
    std::string text = at.message();
    // "file:line:column: what; expected …" with "warning: " before what.
    std::string prefix =
        at.file.empty()
            ? ""
            : at.file + (at.line > 0 ? ":" + std::to_string(at.line) + ":" + std::to_string(at.column) : "") +
                  ": ";
    return prefix + "warning: " + text.substr(prefix.size());
}

void addCheck(cli::Command& app, CheckArgs& args) {
    app.footer(
        "Check bounds files with exactly the loader the game uses; errors are printed as "
        "file:line:column: what is wrong; what was expected. Files named *.bounds.json are bounds files; any "
        "other file is read as a scene (with every bounds file it names). Exit 0 when all are valid, 2 "
        "otherwise. Valid bounds are also checked against their sprite (NAME.png, or NAME.gif or another "
        "image format, beside NAME.bounds.json, or in sprites/ for bounds/NAME.bounds.json), with warnings, "
        "which do not change the exit code, "
        "for a "
        "centre outside the sprite and for a sample point more than max(4 px, 25% of its radius) outside the "
        "opaque area or inside it.");
    app.option("files", args.files, "Bounds or scene files").required();
    app.option("--sprite", args.sprite, "The sprite to check a single bounds file against");
    app.option(
           "--mod", args.mods,
           "A mod folder laid over assets/ (repeatable; later ones win), as polarcade --mod: a scene inside "
           "a mod is read through the overlay, so it may name files of assets/ and of other mods")
        .existingFolder()
        .oneValueEach();  // one folder per --mod, so the files after it stay files
    app.option("--threshold", args.threshold, "Alpha above which a sprite pixel is opaque (0..254)",
               {0, 254});
    app.flag("-q,--quiet", args.quiet, "Print only errors and warnings");
}

int runCheck(const CheckArgs& args) {
    if (!args.sprite.empty() && args.files.size() != 1) {
        std::fprintf(stderr,
                     "polarcade-bounds check: --sprite with %zu files; expected exactly one bounds file\n",
                     args.files.size());
        return cli::kBadInput;
    }
    bool allValid = true;
    for (const std::string& path : args.files)
        allValid &= isBoundsFile(path) ? checkBounds(path, args) : checkScene(path, args);
    return allValid ? 0 : cli::kBadInput;
}

}  // namespace polar::bounds_tool
