#include "replay/replay_recorder.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>

#include "replay/replay_game.h"

namespace polar::game {

namespace fs = std::filesystem;

GameRecorder::GameRecorder(Options options) : options_(std::move(options)) {
    if (options_.folder.empty()) return;
    for (const std::string& path : recoverInterruptedReplays(options_.folder))
        std::printf("polarcade: an interrupted recording was kept as %s\n", path.c_str());
}

GameRecorder::~GameRecorder() {
    stop(nullptr, "");
}

void GameRecorder::start(const Game& game, const AssetFs& assets) {
    stop(nullptr, "");
    std::vector<std::string> paths;
    if (!options_.recordPath.empty() && !recordPathUsed_) {
        paths.push_back(options_.recordPath);
        recordPathUsed_ = true;
    }
    if (!options_.folder.empty()) {
        std::error_code ec;
        fs::create_directories(options_.folder, ec);
        paths.push_back(newReplayPath(options_.folder));
    }
    Game::Config config;
    config.scene = game.scenePath();
    config.reader = assets.reader();
    config.seed = game.seed();
    config.tuning = game.tuning();
    for (const std::string& path : paths) {
        std::vector<AssetStamp> stamps;
        Result<Game> again = createStampedGame(config, &assets, path, stamps);
        if (!again) {
            std::fprintf(stderr, "polarcade: not recording: %s\n", again.error().message().c_str());
            continue;
        }
        auto writer =
            ReplayWriter::open(path, headerFor(game, path, options_.mods, std::move(stamps)), options_.fault);
        if (!writer) {
            std::fprintf(stderr, "polarcade: not recording: %s\n", writer.error().message().c_str());
            continue;
        }
        writers_.push_back(std::move(*writer));
    }
}

void GameRecorder::record(Actions actions, const Game& game) {
    // Hot reload changed the rules in the middle of the game: a replay could not reproduce it, so
    // the recording is given up (the app normally does that itself, and tells the player why).
    if (game.modified() && !writers_.empty()) {
        std::fprintf(stderr,
                     "polarcade: recording stopped at tick %llu: a file was reloaded during the game; its "
                     "replay is not kept\n",
                     static_cast<unsigned long long>(game.tickCount()));
        abandon();
        return;
    }
    for (auto it = writers_.begin(); it != writers_.end();) {
        if (auto error = (*it)->record(actions, game)) {
            std::fprintf(stderr, "polarcade: recording stopped: %s\n", error->message().c_str());
            it = writers_.erase(it);
        } else {
            ++it;
        }
    }
    if (game.over()) stop(&game, "game-over");
}

void GameRecorder::finish(const Game& game, std::string_view reason) {
    stop(&game, reason);
}

void GameRecorder::abandon() {
    for (auto& writer : writers_) writer->abandon();
    writers_.clear();
}

void GameRecorder::stop(const Game* game, std::string_view reason) {
    if (writers_.empty()) return;
    for (auto& writer : writers_) {
        if (!game) continue;  // no final state: the .part file stays, readable up to its last flush
        if (auto error = writer->finish(*game, reason))
            std::fprintf(stderr, "polarcade: replay not saved: %s\n", error->message().c_str());
        else
            std::printf("polarcade: replay saved to %s\n", writer->path().c_str());
    }
    writers_.clear();
    if (!options_.folder.empty()) pruneReplays(options_.folder, options_.keep);
}

std::string newReplayPath(const std::string& folder) {
    std::time_t now = std::time(nullptr);
    std::tm local{};
#if defined(_WIN32)
    localtime_s(&local, &now);
#else
    localtime_r(&now, &local);
#endif
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y-%m-%d_%H-%M-%S", &local);
    fs::path base = fs::path(folder) / stamp;
    std::error_code ec;
    for (int n = 1;; ++n) {
        // A second game in the same second gets "_02": names still sort by age.
        char suffix[16] = "";
        if (n > 1) std::snprintf(suffix, sizeof suffix, "_%02d", n);
        std::string path = base.generic_string() + suffix + ".replay";
        if (!fs::exists(path, ec) && !fs::exists(path + ".part", ec)) return path;
    }
}

std::size_t pruneReplays(const std::string& folder, std::size_t keep) {
    std::vector<fs::path> replays;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(folder, ec))
        if (entry.is_regular_file(ec) && entry.path().extension() == ".replay")
            replays.push_back(entry.path());
    if (replays.size() <= keep) return 0;
    std::sort(replays.begin(), replays.end());
    std::size_t removed = 0;
    for (std::size_t i = 0; i + keep < replays.size(); ++i) removed += fs::remove(replays[i], ec) ? 1 : 0;
    return removed;
}

std::vector<std::string> recoverInterruptedReplays(const std::string& folder) {
    std::vector<std::string> recovered;
    std::error_code ec;
    const auto now = fs::file_time_type::clock::now();
    for (const auto& entry : fs::directory_iterator(folder, ec)) {
        const std::string name = entry.path().filename().string();
        constexpr std::string_view suffix = ".replay.part";
        if (name.size() <= suffix.size() ||
            name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
            continue;
        auto written = entry.last_write_time(ec);
        if (ec || now - written < std::chrono::seconds(10)) continue;  // maybe another running game's
        fs::path target = entry.path();
        target.replace_extension();  // drops ".part"
        if (fs::exists(target, ec)) continue;
        fs::rename(entry.path(), target, ec);
        if (!ec) recovered.push_back(target.generic_string());
    }
    std::sort(recovered.begin(), recovered.end());
    return recovered;
}

}  // namespace polar::game
