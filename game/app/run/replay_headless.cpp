#include "app/run/replay_headless.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "app/run/headless_run.h"
#include "app/theatre/replay_playback.h"
#include "polar/platform/image_file.h"

namespace polar::game {

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
    // The frames saved are those after the seek (or the first tick) up to the end of the playing.
    const std::uint64_t total = play.player().totalTicks();
    const std::uint64_t first = options.seek >= 0 ? static_cast<std::uint64_t>(options.seek) : 1;
    const std::uint64_t last = std::max(first, std::min(limit, total));
    std::string why = limit < total ? "--ticks " + std::to_string(limit)
                                    : "the replay has " + std::to_string(total) + " ticks";
    if (options.seek >= 0) why = "--seek " + std::to_string(options.seek) + "; " + why;
    if (std::optional<Error> error = screenshotNotReached(options, first, last, why)) {
        std::fprintf(stderr, "%s\n", error->message().c_str());
        return 2;
    }
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
    return play.finish(options.verify, options.allowIncomplete);
}

}  // namespace polar::game
