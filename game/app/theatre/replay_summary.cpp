#include "app/theatre/replay_summary.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>

#include "app/hud/lettering.h"
#include "files/high_scores.h"
#include "replay/replay.h"

namespace polar::game {

namespace fs = std::filesystem;

namespace {

// "2026-01-02 12:00" from a recorder's file name, else from the file's modification time.
std::string whenOf(const std::string& path) {
    if (std::optional<std::string> recorded = recorderTimeOf(path)) return *recorded;
    std::error_code ec;
    const fs::file_time_type written = fs::last_write_time(path, ec);
    if (ec) return "";
    const auto since = written - fs::file_time_type::clock::now() + std::chrono::system_clock::now();
    const std::time_t t = std::chrono::system_clock::to_time_t(
        std::chrono::time_point_cast<std::chrono::system_clock::duration>(since));
    std::tm local{};
    localtime_r(&t, &local);
    char text[24];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M", &local);
    return text;
}

}  // namespace

std::optional<std::string> recorderTimeOf(const std::string& path) {
    const std::string stem = fs::path(path).stem().string();
    int y, mo, d, h, mi, s, used = 0;
    if (std::sscanf(stem.c_str(), "%4d-%2d-%2d_%2d-%2d-%2d%n", &y, &mo, &d, &h, &mi, &s, &used) != 6 ||
        used != 19)
        return std::nullopt;
    const std::string rest = stem.substr(19);  // "" or a second game's "_02"
    if (!rest.empty() &&
        (rest.size() < 2 || rest[0] != '_' ||
         !std::all_of(rest.begin() + 1, rest.end(), [](char c) { return c >= '0' && c <= '9'; })))
        return std::nullopt;
    char text[24];
    std::snprintf(text, sizeof text, "%04d-%02d-%02d %02d:%02d", y, mo, d, h, mi);
    return text;
}

ReplaySummary summariseReplay(const std::string& path, const AssetFs& assets) {
    ReplaySummary summary;
    summary.path = path;
    summary.when = whenOf(path);
    summary.scene = upperCase(fs::path(path).stem().string());
    Result<Replay> replay = readReplay(path);
    if (!replay) {
        summary.reason = "CANNOT BE READ";
        summary.detail = replay.error().message();
        return summary;
    }
    const ReplayHeader& h = replay->header;
    summary.scene = upperCase(fs::path(h.scene).stem().string());
    summary.mods = modSetOf(h.mods);
    summary.ticks = replay->actions.size();
    summary.tickRate = h.tuning.tickRate;
    if (!replay->checkpoints.empty()) {
        summary.score = replay->checkpoints.back().score;
        summary.wave = replay->checkpoints.back().wave;
    }
    const std::vector<std::string> here = modSetOf(assets.mods());
    for (const std::string& mod : summary.mods)
        if (!std::binary_search(here.begin(), here.end(), mod)) {
            summary.reason = "NEEDS MOD " + upperCase(mod);
            summary.detail =
                path + ": recorded with the mod " + mod + ", which this game was not started with (--mod)";
            return summary;
        }
    // The very check a replay's start makes: the scene is here, and every file hashes as recorded.
    Result<ReplayPlayer> player = ReplayPlayer::start(*replay, assets);
    if (!player) {
        summary.reason = assets.resolve(configFor(*replay, assets).scene) ? "FILES CHANGED" : "SCENE MISSING";
        summary.detail = player.error().message();
        return summary;
    }
    if (h.gameVersion != gameVersion()) {
        summary.playable = ReplaySummary::Playable::Caution;
        summary.reason = "FROM VERSION " + h.gameVersion;
        summary.detail = path + ": recorded by polarcade " + h.gameVersion + ", played by " + gameVersion() +
                         ": a change in the game between them can make it differ";
        return summary;
    }
    summary.playable = ReplaySummary::Playable::Yes;
    return summary;
}

}  // namespace polar::game
