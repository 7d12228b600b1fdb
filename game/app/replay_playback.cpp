#include "app/replay_playback.h"

#include <cstdio>
#include <map>

#include "polar/platform/image_file.h"

namespace polar::game {

Result<std::unique_ptr<Playback>> Playback::open(const std::string& path, const AssetFs& assets,
                                                 TaskSystem& tasks, const HighScores* scores) {
    Result<Replay> replay = readReplay(path);
    if (!replay) return replay.error();
    for (const std::string& note : replayNotes(*replay))
        std::fprintf(stderr, "%s: note: %s\n", replay->path.c_str(), note.c_str());
    std::unique_ptr<Playback> play(new Playback());
    play->replay_ = std::make_unique<Replay>(std::move(*replay));
    StepThreads threads;
    threads.tasks = &tasks;
    Result<ReplayPlayer> player = ReplayPlayer::start(*play->replay_, assets, threads);
    if (!player) return player.error();
    play->player_.emplace(std::move(*player));
    play->markers_ = ReplayMarkers(scores ? scoreToBeat(*scores, *play->replay_) : 0);
    play->seek_.emplace(*play->player_, play->particles_, 1.0 / play->replay_->header.tuning.tickRate);
    return play;
}

bool Playback::tick(bool stopAtDesync) {
    interpolation_.capture(player_->game().world());
    std::optional<Desync> found = seek_->advance();
    markers_.observe(player_->game());
    return report(found, stopAtDesync);
}

bool Playback::seekTo(std::uint64_t tick, bool stopAtDesync) {
    std::optional<Desync> found = seek_->seek(tick);
    interpolation_.capture(player_->game().world());
    return report(found, stopAtDesync);
}

bool Playback::report(const std::optional<Desync>& found, bool stopAtDesync) {
    if (found && !desync_) {
        desync_ = found;
        std::fprintf(stderr, "%s", describe(*found, replay_->path).c_str());
        if (stopAtDesync) return false;
    }
    return true;
}

void Playback::draw(render::Canvas& canvas, SpriteCache& sprites, TaskSystem& tasks, double alpha,
                    bool debugOverlay) const {
    DrawOptions draw;
    draw.tasks = &tasks;
    draw.debugOverlay = debugOverlay;
    drawGame(canvas, player_->game(), sprites, interpolation_, particles_, alpha, draw);
}

void Playback::drawStill(render::Canvas& canvas, SpriteCache& sprites, TaskSystem& tasks) const {
    DrawOptions draw;
    draw.tasks = &tasks;
    drawGame(canvas, player_->game(), sprites, Interpolation{}, particles_, 1.0, draw);
}

int Playback::finish(bool verify) const {
    if (desync_) return verify ? 1 : 0;
    std::printf("%s: %llu ticks played, %zu checkpoints match the recording\n", replay_->path.c_str(),
                static_cast<unsigned long long>(player_->game().tickCount()), player_->checkpointsMatched());
    return 0;
}

int playReplayHeadless(const AppOptions& options, const AssetFs& assets, SpriteCache& sprites,
                       render::Canvas& canvas, TaskSystem& tasks) {
    Result<std::unique_ptr<Playback>> opened = Playback::open(options.replay, assets, tasks);
    if (!opened) {
        std::fprintf(stderr, "%s\n", opened.error().message().c_str());
        return 2;
    }
    Playback& play = **opened;
    std::map<std::uint64_t, std::vector<std::string>> shots;
    for (const auto& [tick, file] : options.screenshots) shots[tick].push_back(file);
    const std::uint64_t limit =
        options.ticks < 0 ? play.player().totalTicks() : static_cast<std::uint64_t>(options.ticks);
    bool seeking = options.seek >= 0;
    while (seeking || (!play.player().done() && play.player().game().tickCount() < limit)) {
        if (seeking) {
            seeking = false;
            if (!play.seekTo(static_cast<std::uint64_t>(options.seek), options.verify)) return 1;
        } else if (!play.tick(options.verify)) {
            return 1;
        }
        auto due = shots.find(play.player().game().tickCount());
        if (due == shots.end()) continue;
        play.drawStill(canvas, sprites, tasks);
        for (const std::string& file : due->second) {
            if (auto error = render::savePng(canvas, file)) {
                std::fprintf(stderr, "%s\n", error->message().c_str());
                return 2;
            }
            std::printf("saved tick %llu to %s\n", static_cast<unsigned long long>(due->first), file.c_str());
        }
    }
    return play.finish(options.verify);
}

}  // namespace polar::game
