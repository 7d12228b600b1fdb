#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/context/app_options.h"
#include "app/hud/sprite_cache.h"
#include "app/input/data_folder.h"
#include "files/assets.h"
#include "files/hot_reload.h"
#include "polar/render/canvas.h"
#include "polar/tasks.h"
#include "rules/game.h"

namespace polar::game {

// What every way of running the game shares (headless, in a window, under a script): the
// options, the threads, the files and the picture, the statistics.
class AppContext {
  public:
    AppContext(AppOptions options, std::string assetRoot);

    AppOptions options;
    ThreadPool pool;  // every game's world steps on it (--threads); frames are drawn on it too
    AssetFs assets;
    SpriteCache sprites;
    render::Canvas canvas;
    HotReload hotReload;
    std::array<double, kEffectCount> effectMs{};  // the overlay's time per effect, smoothed

    // The data folder, opened at the first use; when nothing can be saved there, that is said once.
    const DataFolder& dataFolder();
    // Prints the error with its file as the file on disk; returns the exit code 2.
    int fail(const Error& error) const;
    // Adds the step just taken to the --stats totals and the overlay's time per effect.
    void tallyStep(const Game& game);
    // With --stats: the per-effect totals of every step tallied.
    void printStats() const;
    // Prints the sprite problems not printed yet.
    void reportSpriteProblems();
    // Applies edited bounds files to the games (hot_reload.h); the output goes to stdout and stderr.
    HotReload::Report reloadBetweenTicks(const std::vector<Game*>& games, bool now);

  private:
    std::optional<DataFolder> data_;
    StepStats statsTotal_;
    std::uint64_t statsSteps_ = 0;
    std::size_t reportedProblems_ = 0;
};

}  // namespace polar::game
