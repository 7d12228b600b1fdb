#include "difficulty_plot.h"

#include <algorithm>
#include <array>

#include "line_panel.h"

namespace polar::bench {

std::optional<Error> DifficultyPlot::save(const std::string& path, int width, int height) const {
    // Colours far apart, cycled when there are more scenes than colours.
    constexpr std::array<std::uint32_t, 8> kColours{0xFF2060C0, 0xFFC03020, 0xFF30A040, 0xFFE0A020,
                                                    0xFF8040B0, 0xFF20A0A0, 0xFF805030, 0xFFD040A0};
    PlotCanvas canvas(width, height);
    const std::uint32_t ink = 0xFF202020;
    const int left = 90, right = width - 190, top = 50, gap = 60, bottom = height - 50;
    const int middle = (top + bottom - gap) / 2;

    LinePanel survival;
    survival.left = left, survival.top = top, survival.right = right, survival.bottom = middle;
    double longest = 0;  // the survival panel ends with the longest game, at most at the cap
    for (const Scene& scene : scenes)
        for (const GamePlayed& game : scene.games) longest = std::max(longest, game.minutes);
    survival.xMax = std::max(std::min(capMinutes, longest * 1.05), 1.0 / 60);
    survival.yMax = 1;
    survival.yLabel = "share of games going";
    survival.xLabel = "game minutes";
    LinePanel waves = survival;
    waves.top = middle + gap, waves.bottom = bottom;
    waves.yLabel = "share reaching wave";
    waves.xLabel = "wave";
    int highestWave = 1;
    for (std::size_t k = 0; k < scenes.size(); ++k) {
        const Scene& scene = scenes[k];
        const std::uint32_t colour = kColours[k % kColours.size()];
        survival.series.push_back({scene.name, colour, survivalCurve(scene.games, survival.xMax)});
        LineSeries reached{scene.name, colour, {}};
        for (const WaveFigures& wave : scene.curve.waves)
            reached.points.emplace_back(wave.wave, wave.fraction);
        // No game reached the wave after the last one: the line drops to zero there.
        const int next = static_cast<int>(scene.curve.waves.size()) + 1;
        reached.points.emplace_back(next, 0.0);
        highestWave = std::max(highestWave, next);
        waves.series.push_back(std::move(reached));
    }
    waves.xMax = highestWave;
    canvas.text(left, 16, title, ink, 2);
    survival.draw(canvas);
    waves.draw(canvas);
    return savePng(canvas.image, path);
}

}  // namespace polar::bench
