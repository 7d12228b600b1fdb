#include "app/context/app_context.h"

#include <cstdio>

#include "app/hud/game_drawing.h"

namespace polar::game {

AppContext::AppContext(AppOptions opts, std::string assetRoot)
    : options(std::move(opts)),
      pool(options.threads > 0 ? options.threads : hardwareThreads()),
      assets(std::move(assetRoot), options.mods),
      sprites(assets),
      canvas(kScreenWidth, kScreenHeight),
      hotReload(assets) {}

const DataFolder& AppContext::dataFolder() {
    if (!data_) {
        data_ = openDataFolder(options.data);
        if (data_->problem)
            std::fprintf(stderr, "polarcade: high scores and replays will not be saved: %s\n",
                         data_->problem->message().c_str());
    }
    return *data_;
}

int AppContext::fail(const Error& error) const {
    std::fprintf(stderr, "%s\n", assets.onDisk(error).message().c_str());
    return 2;
}

void AppContext::tallyStep(const Game& game) {
    const StepStats& step = game.world().lastStepStats();
    statsTotal_ += step;
    ++statsSteps_;
    for (std::size_t i = 0; i < kEffectCount; ++i)
        effectMs[i] = effectMs[i] * 0.9 + 0.1 * (step.effects[i].nanoseconds * 1e-6);
}

void AppContext::printStats() const {
    if (!options.stats) return;
    std::printf("per-effect statistics over %llu steps on %u thread%s:\n%s",
                static_cast<unsigned long long>(statsSteps_), pool.workerCount(),
                pool.workerCount() == 1 ? "" : "s", formatStepStats(statsTotal_, statsSteps_).c_str());
}

void AppContext::reportSpriteProblems() {
    for (std::size_t i = reportedProblems_; i < sprites.problems().size(); ++i)
        std::fprintf(stderr, "%s\n", sprites.problems()[i].message().c_str());
    reportedProblems_ = sprites.problems().size();
}

HotReload::Report AppContext::reloadBetweenTicks(const std::vector<Game*>& games, bool now) {
    HotReload::Report report = hotReload.update(games, now);
    auto disk = [this](const std::string& logical) { return assets.resolve(logical).value_or(logical); };
    for (std::size_t i = 0; i < report.reloaded.size(); ++i)
        std::printf("reloaded %s (%zu object%s)\n", disk(report.reloaded[i]).c_str(), report.objects[i],
                    report.objects[i] == 1 ? "" : "s");
    for (const std::string& scene : report.scenes)
        std::printf("%s changed: it applies to the next game\n", disk(scene).c_str());
    for (const Error& error : report.errors)
        std::fprintf(stderr, "%s (the old version stays)\n", error.message().c_str());
    for (const std::string& file : report.fixed) std::printf("%s is valid again\n", disk(file).c_str());
    for (const std::string& sprite : report.spritesChanged) sprites.forget(sprite);
    if (!report.reloaded.empty() || !report.scenes.empty() || !report.fixed.empty()) std::fflush(stdout);
    return report;
}

}  // namespace polar::game
