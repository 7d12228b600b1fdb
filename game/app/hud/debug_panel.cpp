#include "app/hud/debug_panel.h"

#include <cstdio>

namespace polar::game {

std::vector<std::string> debugPanelLines(const World& world, double fps,
                                         const std::array<double, kEffectCount>& effectMs) {
    std::vector<std::string> lines;
    char line[128];
    for (std::size_t i = 0; i < kEffectCount; ++i) {
        // An effect the scene does not call for is absent and costs nothing.
        if (!(world.def().effects & kAllEffects[i]))
            std::snprintf(line, sizeof line, "%-10s  absent", effectName(kAllEffects[i]));
        else
            std::snprintf(line, sizeof line, "%-10s %7.1f \xC2\xB5s", effectName(kAllEffects[i]),
                          effectMs[i] * 1000);
        lines.push_back(line);
    }
    std::snprintf(line, sizeof line, "FPS %.0f  THREADS %u  OBJECTS %zu  PAIRS TESTED %llu  HITS %zu", fps,
                  world.workerCount(), world.objects().size(),
                  static_cast<unsigned long long>(world.lastStepStats().pairsTested), world.hits().size());
    lines.push_back(line);
    return lines;
}

}  // namespace polar::game
