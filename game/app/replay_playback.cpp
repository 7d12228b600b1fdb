#include "app/replay_playback.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <thread>

#include "app/input.h"
#include "app/replay_seek.h"
#include "polar/platform/image_file.h"
#include "polar/platform/window.h"
#include "polar/render/shapes.h"
#include "polar/render/text.h"
#include "replay/replay.h"

namespace polar::game {
namespace {

using render::Color;

struct Playback {
    const AppOptions& options;
    const Replay& replay;
    ReplayPlayer& player;
    ReplaySeek& seek;
    SpriteCache& sprites;
    render::Canvas& canvas;
    TaskSystem& tasks;  // the step's and the frames' threads
    Interpolation interpolation;
    Particles& particles;
    std::optional<Desync> desync;

    // Plays one tick; returns false when the run must stop (a desync under --verify).
    bool tick() {
        interpolation.capture(player.game().world());
        return report(seek.advance());
    }

    // Goes to `tick` by the keyframes; false as tick() is.
    bool seekTo(std::uint64_t tick) {
        std::optional<Desync> found = seek.seek(tick);
        interpolation.capture(player.game().world());
        return report(found);
    }

    bool report(const std::optional<Desync>& found) {
        if (found && !desync) {
            desync = found;
            std::fprintf(stderr, "%s", describe(*found, replay.path).c_str());
            if (options.verify) return false;
        }
        return true;
    }

    int finish() const {
        if (desync) return options.verify ? 1 : 0;
        std::printf("%s: %llu ticks played, %zu checkpoints match the recording\n", replay.path.c_str(),
                    static_cast<unsigned long long>(player.game().tickCount()), player.checkpointsMatched());
        return 0;
    }
};

int headless(Playback& play) {
    std::map<std::uint64_t, std::vector<std::string>> shots;
    for (const auto& [tick, file] : play.options.screenshots) shots[tick].push_back(file);
    std::uint64_t limit =
        play.options.ticks < 0 ? play.player.totalTicks() : static_cast<std::uint64_t>(play.options.ticks);
    bool seeking = play.options.seek >= 0;
    while (seeking || (!play.player.done() && play.player.game().tickCount() < limit)) {
        if (seeking) {
            seeking = false;
            if (!play.seekTo(static_cast<std::uint64_t>(play.options.seek))) return 1;
        } else if (!play.tick()) {
            return 1;
        }
        auto due = shots.find(play.player.game().tickCount());
        if (due == shots.end()) continue;
        DrawOptions draw;
        draw.tasks = &play.tasks;
        drawGame(play.canvas, play.player.game(), play.sprites, Interpolation{}, play.particles, 1.0, draw);
        for (const std::string& file : due->second) {
            if (auto error = render::savePng(play.canvas, file)) {
                std::fprintf(stderr, "%s\n", error->message().c_str());
                return 2;
            }
            std::printf("saved tick %llu to %s\n", static_cast<unsigned long long>(due->first), file.c_str());
        }
    }
    return play.finish();
}

int windowed(Playback& play, platform::Window& window) {
    Input input;
    const double tickSeconds = 1.0 / play.replay.header.tuning.tickRate;
    const double speeds[] = {0.25, 0.5, 1, 2, 4, 8};
    int speed = 2;
    bool paused = false, debug = false;
    auto last = std::chrono::steady_clock::now();
    double accumulator = 0;
    while (true) {
        Input::Commands cmd = input.pollEvents(window);
        if (cmd.quit || cmd.back) break;
        if (cmd.pause || cmd.confirm) paused = !paused;
        if (cmd.debugOverlay) debug = !debug;
        if (cmd.up) speed = std::min(speed + 1, 5);
        if (cmd.down) speed = std::max(speed - 1, 0);
        bool stepOnce = paused && cmd.right;
        // Back one tick by the keyframes: the state is straight play's at that tick.
        if (paused && cmd.left && play.player.game().tickCount() > 0 &&
            !play.seekTo(play.player.game().tickCount() - 1))
            return 1;

        auto now = std::chrono::steady_clock::now();
        double frame = std::min(std::chrono::duration<double>(now - last).count(), 0.25);
        last = now;
        if (!paused) accumulator += frame * speeds[speed];
        while ((accumulator >= tickSeconds || stepOnce) && !play.player.done()) {
            accumulator = std::max(0.0, accumulator - tickSeconds);
            stepOnce = false;
            if (!play.tick()) return 1;
        }
        if (play.player.done()) accumulator = 0;

        DrawOptions draw;
        draw.tasks = &play.tasks;
        draw.debugOverlay = debug;
        double alpha = paused || play.player.done() ? 1.0 : std::min(1.0, accumulator / tickSeconds);
        drawGame(play.canvas, play.player.game(), play.sprites, play.interpolation, play.particles, alpha,
                 draw);
        char line[160];
        std::snprintf(line, sizeof line, "REPLAY  TICK %llu/%llu  x%g%s   P PAUSE%s  UP/DOWN SPEED  ESC QUIT",
                      static_cast<unsigned long long>(play.player.game().tickCount()),
                      static_cast<unsigned long long>(play.player.totalTicks()), speeds[speed],
                      paused ? "  PAUSED" : "", paused ? "  LEFT/RIGHT STEP" : "");
        render::drawText(play.canvas, line, 6, kScreenHeight - 12, 1, Color{200, 210, 255, 255});
        if (play.desync) {
            std::snprintf(line, sizeof line, "DESYNC AFTER TICK %llu",
                          static_cast<unsigned long long>(play.desync->firstTick));
            drawCentredText(play.canvas, line, 40, 2, Color{255, 90, 90, 255});
        }
        if (play.player.done())
            drawCentredText(play.canvas, "END OF REPLAY", 150, 3, Color{255, 214, 120, 255});
        window.present(play.canvas);
        std::this_thread::sleep_for(std::chrono::milliseconds(play.player.done() || paused ? 15 : 1));
    }
    return play.finish();
}

}  // namespace

int playReplay(const AppOptions& options, const AssetFs& assets, SpriteCache& sprites, render::Canvas& canvas,
               TaskSystem& tasks) {
    Result<Replay> replay = readReplay(options.replay);
    if (!replay) {
        std::fprintf(stderr, "%s\n", replay.error().message().c_str());
        return 2;
    }
    for (const std::string& note : replayNotes(*replay))
        std::fprintf(stderr, "%s: note: %s\n", replay->path.c_str(), note.c_str());
    StepThreads threads;
    threads.tasks = &tasks;
    Result<ReplayPlayer> player = ReplayPlayer::start(*replay, assets, threads);
    if (!player) {
        std::fprintf(stderr, "%s\n", player.error().message().c_str());
        return 2;
    }
    Particles particles;
    ReplaySeek seek(*player, particles, 1.0 / replay->header.tuning.tickRate);
    Playback play{options, *replay, *player, seek, sprites, canvas, tasks, {}, particles, {}};
    if (options.headless) return headless(play);
    if (options.seek >= 0 && !play.seekTo(static_cast<std::uint64_t>(options.seek))) return 1;
    Result<std::unique_ptr<platform::Window>> window =
        platform::Window::open({"Polarcade replay", kScreenWidth, kScreenHeight, 2});
    if (!window) {
        std::printf("polarcade: no display found (%s); playing the replay headless instead\n",
                    window.error().what.c_str());
        return headless(play);
    }
    return windowed(play, **window);
}

}  // namespace polar::game
