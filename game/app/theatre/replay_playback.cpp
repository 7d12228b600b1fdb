#include "app/theatre/replay_playback.h"

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

int Playback::finish(bool verify, bool allowIncomplete) const {
    if (desync_) return verify ? 1 : 0;
    const std::optional<Error> incomplete = missingEnd(*replay_);
    if (incomplete && verify && !allowIncomplete) {
        std::fprintf(stderr, "%s\n", incomplete->message().c_str());
        return 1;
    }
    if (incomplete)
        std::fprintf(stderr, "%s:%d:%d: note: %s\n", incomplete->file.c_str(), incomplete->line,
                     incomplete->column, incomplete->what.c_str());
    std::printf("%s: %llu ticks played, %zu checkpoints match the recording%s\n", replay_->path.c_str(),
                static_cast<unsigned long long>(player_->game().tickCount()), player_->checkpointsMatched(),
                incomplete ? " (incomplete: no end line)" : "");
    return 0;
}

}  // namespace polar::game
