#include "replay/replay_game.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "polar/state_hash.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;

fs::path folderOf(const std::string& file) {
    return fs::absolute(fs::path(file)).lexically_normal().parent_path();
}

// `path` relative to `folder`, or nothing when it lies outside.
std::optional<std::string> inside(const fs::path& path, const fs::path& folder) {
    fs::path relative = path.lexically_relative(fs::absolute(folder).lexically_normal());
    if (relative.empty() || *relative.begin() == "..") return std::nullopt;
    return relative.generic_string();
}

// How a replay names a file the game read: logical paths as they are; an absolute path inside a mod
// or the asset folder as the logical path it stands for; any other relative to `anchor`'s folder.
std::string nameFor(const std::string& path, const AssetFs* assets, const std::string& anchor) {
    fs::path p(path);
    if (!p.is_absolute()) return path;
    p = p.lexically_normal();
    if (assets) {
        for (auto mod = assets->mods().rbegin(); mod != assets->mods().rend(); ++mod)
            if (auto logical = inside(p, *mod)) return *logical;
        if (auto logical = inside(p, assets->root())) return *logical;
    }
    fs::path relative = p.lexically_relative(folderOf(anchor));
    return relative.empty() ? p.generic_string() : relative.generic_string();
}

}  // namespace

std::uint64_t stampHash(std::string_view bytes) {
    StateHash h;
    h.addBytes(bytes.data(), bytes.size());
    return h.value();
}

Result<Game> createStampedGame(const Game::Config& config, const AssetFs* assets, const std::string& anchor,
                               std::vector<AssetStamp>& stamps) {
    auto seen = std::make_shared<std::vector<AssetStamp>>();
    Game::Config stamped = config;
    stamped.reader = [inner = config.reader, seen, assets,
                      anchor](const std::string& name) -> std::optional<SourceFile> {
        std::optional<SourceFile> file = inner(name);
        if (file) seen->push_back({nameFor(name, assets, anchor), stampHash(file->text), 0});
        return file;
    };
    Result<Game> game = Game::create(stamped);
    stamps = *seen;
    return game;
}

ReplayHeader headerFor(const Game& game, const std::string& replayPath, std::vector<std::string> mods,
                       std::vector<AssetStamp> stamps) {
    ReplayHeader h;
    h.sceneIsFile = fs::path(game.scenePath()).is_absolute();
    h.scene = h.sceneIsFile ? nameFor(game.scenePath(), nullptr, replayPath) : game.scenePath();
    h.seed = game.seed();
    h.tuning = game.tuning();
    h.rules = game.rulesVersion();
    h.speed = game.speed();
    h.mods = std::move(mods);
    h.assets = std::move(stamps);
    return h;
}

Game::Config configFor(const Replay& replay, const AssetFs& assets) {
    Game::Config config;
    config.scene = replay.header.sceneIsFile
                       ? (folderOf(replay.path) / replay.header.scene).lexically_normal().generic_string()
                       : replay.header.scene;
    config.reader = assets.reader();
    config.seed = replay.header.seed;
    config.tuning = replay.header.tuning;
    config.rules = replay.header.rules;
    config.speed = replay.header.speed;
    return config;
}

}  // namespace polar::game
