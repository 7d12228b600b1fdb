#include "replay_check.h"

#include <filesystem>
#include <map>

#include "app/hud/game_drawing.h"
#include "files/assets.h"
#include "polar/atomic_file.h"
#include "polar/platform/image_file.h"
#include "replay/replay.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;

std::string hex(std::uint32_t v) {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "%08x", v);
    return buffer;
}

std::string pngPath(const Replay& replay, const ReplayScreenshot& shot) {
    return (fs::absolute(replay.path).parent_path() / shot.png).lexically_normal().generic_string();
}

// Draws the frame after the current tick exactly as `polarcade --headless --screenshot` saves it.
struct Frames {
    explicit Frames(const AssetFs& assets) : sprites(assets) {}
    void tick(const Game& game, double tickRate) {
        particles.spawnFor(game.events(), game.tickCount());
        particles.tick(1.0 / tickRate);
    }
    const render::Canvas& draw(const Game& game) {
        drawGame(canvas, game, sprites, Interpolation{}, particles, 1.0, DrawOptions{});
        return canvas;
    }
    SpriteCache sprites;
    Particles particles;
    render::Canvas canvas{kScreenWidth, kScreenHeight};
};

// Compares a frame with its golden PNG; on a difference writes the actual frame and a diff picture
// (the golden dimmed, differing pixels magenta) and returns what differs.
std::optional<std::string> compareFrame(const render::Canvas& frame, const Replay& replay,
                                        const ReplayScreenshot& shot, const std::string& failureDir,
                                        std::vector<std::string>& pictures) {
    const std::string where = replay.path + ":" + std::to_string(shot.line) + ":1: screenshot after tick " +
                              std::to_string(shot.tick) + ": ";
    Result<render::Canvas> golden = render::loadCanvas(pngPath(replay, shot));
    if (!golden)
        return where + golden.error().message() +
               "\n  (run polarcade-replay --update-screenshots to create it, then look at it)";
    if (golden->width() != frame.width() || golden->height() != frame.height())
        return where + shot.png + " is " + std::to_string(golden->width()) + "x" +
               std::to_string(golden->height()) + ", the frame " + std::to_string(frame.width()) + "x" +
               std::to_string(frame.height());
    render::Canvas diff(frame.width(), frame.height());
    long differing = 0;
    int firstX = 0, firstY = 0;
    for (int y = 0; y < frame.height(); ++y) {
        for (int x = 0; x < frame.width(); ++x) {
            std::uint32_t want = golden->row(y)[x], got = frame.row(y)[x];
            if (want == got) {
                diff.row(y)[x] = 0xFF000000u | ((want >> 2) & 0x3F3F3Fu);
                continue;
            }
            diff.row(y)[x] = 0xFFFF00FFu;
            if (differing++ == 0) firstX = x, firstY = y;
        }
    }
    if (differing == 0) return std::nullopt;
    std::error_code ec;
    fs::create_directories(failureDir, ec);
    std::string stem =
        (fs::path(failureDir) / (fs::path(replay.path).stem().string() + "-" + std::to_string(shot.tick)))
            .generic_string();
    // A picture that cannot be written (a full disk) is said in its place; the report stands.
    auto saved = [&pictures](const render::Canvas& canvas, const std::string& path) {
        std::optional<Error> error = render::savePng(canvas, path);
        if (!error) pictures.push_back(path);
        return error ? "not saved: " + error->message() : path;
    };
    std::string actualPath = saved(frame, stem + ".actual.png");
    std::string diffPath = saved(diff, stem + ".diff.png");
    return where + std::to_string(differing) + " pixels differ from " + shot.png + ", the first at (" +
           std::to_string(firstX) + ", " + std::to_string(firstY) + "): golden " +
           hex(golden->row(firstY)[firstX]) + ", actual " + hex(frame.row(firstY)[firstX]) +
           "\n  actual: " + actualPath + "\n  diff:   " + diffPath;
}

void addProgress(const CheckOptions& options, std::uint64_t ticks) {
    if (options.ticksDone) options.ticksDone->fetch_add(ticks, std::memory_order_relaxed);
}

// Plays the recorded inputs with this build and writes the replay again: new trace, checkpoints,
// file stamps and screenshots. For after an intended change to the game.
CheckResult rerecord(const Replay& old, const AssetFs& assets, const CheckOptions& options,
                     CheckResult result) {
    std::vector<AssetStamp> stamps;
    Game::Config config = configFor(old, assets);
    config.threads = options.threads;
    Result<Game> game = createStampedGame(config, &assets, old.path, stamps);
    if (!game) {
        result.report = old.path + ":" + std::to_string(old.header.sceneLine) +
                        ":1: the recorded game cannot start: " + game.error().message();
        return result;
    }
    Replay fresh = old;
    fresh.header.gameVersion = gameVersion();
    fresh.header.assets = std::move(stamps);
    fresh.trace.clear();
    fresh.checkpoints.clear();
    Frames frames(assets);
    std::map<std::uint64_t, const ReplayScreenshot*> shots;
    for (const ReplayScreenshot& shot : old.header.screenshots) shots[shot.tick] = &shot;
    for (Actions actions : old.actions) {
        game->tick(actions);
        const std::uint64_t t = game->tickCount();
        fresh.trace.push_back(traceOf(game->hash()));
        if (t % kCheckpointInterval == 0 || t == old.actions.size())
            fresh.checkpoints.push_back(checkpointOf(*game));
        frames.tick(*game, old.header.tuning.tickRate);
        if (auto shot = shots.find(t); shot != shots.end()) {
            if (auto error = render::savePng(frames.draw(*game), pngPath(old, *shot->second))) {
                result.report = error->message();
                return result;
            }
            ++result.screenshots;
        }
        if (t % kCheckpointInterval == 0) addProgress(options, kCheckpointInterval);
    }
    addProgress(options, old.actions.size() % kCheckpointInterval);
    if (fresh.end) fresh.end->tick = fresh.actions.size();
    if (auto error = writeFileAtomically(old.path, formatReplay(fresh))) {
        result.report = error->message();
        return result;
    }
    result.ticks = game->tickCount();
    result.checkpoints = fresh.checkpoints.size();
    result.status = CheckResult::kUpdated;
    return result;
}

}  // namespace

std::uint64_t replayTicks(const std::string& path) {
    Result<Replay> replay = readReplay(path);
    return replay ? replay->actions.size() : 0;
}

CheckResult checkReplayFile(const std::string& path, const CheckOptions& options) {
    CheckResult result;
    result.path = path;
    Result<Replay> replay = readReplay(path);
    if (!replay) {
        result.report = replay.error().message();
        return result;
    }
    result.notes = replayNotes(*replay);
    const std::optional<Error> incomplete = missingEnd(*replay);
    auto failIncomplete = [&] {
        result.status = CheckResult::kIncomplete;
        result.report = incomplete->message();
        return result;
    };
    if (incomplete && options.allowIncomplete) result.notes.push_back(incomplete->message());
    AssetFs assets(options.assetRoot, options.mods);
    for (const ReplayScreenshot& shot : replay->header.screenshots) {
        if (shot.tick <= replay->actions.size()) continue;
        // An interrupted recording stops before its screenshots: they were never played.
        if (incomplete) {
            result.notes.push_back("the screenshot after tick " + std::to_string(shot.tick) + " (line " +
                                   std::to_string(shot.line) +
                                   ") lies past the recorded ticks: not compared");
            continue;
        }
        result.report = path + ":" + std::to_string(shot.line) + ":12: a screenshot after tick " +
                        std::to_string(shot.tick) + " but the replay has " +
                        std::to_string(replay->actions.size()) + " ticks; expected a tick it has";
        return result;
    }
    if (options.update) return rerecord(*replay, assets, options, std::move(result));
    if (replay->checkpoints.empty() && replay->trace.empty()) {
        if (incomplete && !options.allowIncomplete) return failIncomplete();
        result.report =
            path +
            ": nothing to verify: the replay has no checkpoints and no trace; expected a recorded "
            "replay (polarcade-replay --update fills them in from this build)";
        return result;
    }

    Result<ReplayPlayer> player = ReplayPlayer::start(*replay, assets, options.threads);
    if (!player) {
        result.report = player.error().message();
        return result;
    }
    Frames frames(assets);
    std::map<std::uint64_t, std::vector<const ReplayScreenshot*>> shots;
    for (const ReplayScreenshot& shot : replay->header.screenshots) shots[shot.tick].push_back(&shot);
    std::vector<std::string> frameProblems;
    std::uint64_t reported = 0;
    while (!player->done()) {
        std::optional<Desync> desync = player->step();
        const Game& game = player->game();
        if (!shots.empty()) frames.tick(game, replay->header.tuning.tickRate);
        if (game.tickCount() % kCheckpointInterval == 0) {
            addProgress(options, game.tickCount() - reported);
            reported = game.tickCount();
        }
        if (desync) {
            result.status =
                desync->kind == Desync::Kind::kGame ? CheckResult::kDesynced : CheckResult::kDamaged;
            result.desyncTick = desync->firstTick;
            result.report = describe(*desync, path);
            break;
        }
        auto due = shots.find(game.tickCount());
        if (due == shots.end()) continue;
        const render::Canvas& frame = frames.draw(game);
        for (const ReplayScreenshot* shot : due->second) {
            if (options.updateScreenshots) {
                if (auto error = render::savePng(frame, pngPath(*replay, *shot)))
                    frameProblems.push_back(error->message());
                else
                    ++result.screenshots;
            } else if (auto problem =
                           compareFrame(frame, *replay, *shot, options.failureDir, result.pictures)) {
                frameProblems.push_back(*problem);
            } else {
                ++result.screenshots;
            }
        }
    }
    addProgress(options, player->totalTicks() - reported);
    result.ticks = player->game().tickCount();
    result.checkpoints = player->checkpointsMatched();
    // A desync found at a checkpoint may have begun before a screenshot that already differed.
    if (result.status == CheckResult::kDesynced || result.status == CheckResult::kDamaged) {
        if (!result.report.empty() && result.report.back() != '\n') result.report += '\n';
        for (const std::string& problem : frameProblems) result.report += problem + "\n";
        return result;
    }
    if (!frameProblems.empty()) {
        result.status = CheckResult::kScreenshotDiffers;
        for (const std::string& problem : frameProblems) result.report += problem + "\n";
        return result;
    }
    // All that was recorded matched; a recording that never reached its end line still fails.
    if (incomplete && !options.allowIncomplete) return failIncomplete();
    result.status = options.updateScreenshots && !replay->header.screenshots.empty() ? CheckResult::kUpdated
                                                                                     : CheckResult::kPassed;
    return result;
}

}  // namespace polar::game
