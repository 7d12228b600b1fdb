#include "difficulty_curve.h"

#include <algorithm>

#include "harness/samples.h"

namespace polar::bench {

DifficultyCurve summarizeGames(const std::vector<GamePlayed>& games) {
    DifficultyCurve curve;
    curve.games = static_cast<int>(games.size());
    std::vector<double> minutes, scores, waves;
    int highest = 0;
    for (const GamePlayed& game : games) {
        curve.capped += game.capped;
        minutes.push_back(game.minutes);
        scores.push_back(game.score);
        waves.push_back(game.wave);
        highest = std::max(highest, game.wave);
    }
    curve.medianMinutes = median(minutes);
    curve.medianScore = median(scores);
    curve.medianWave = median(waves);
    for (int wave = 1; wave <= highest; ++wave) {
        WaveFigures figures;
        figures.wave = wave;
        std::vector<double> at, score;
        for (const GamePlayed& game : games)
            for (const WaveReached& reached : game.waves)
                if (reached.wave == wave) {
                    at.push_back(reached.minutes);
                    score.push_back(reached.score);
                }
        figures.reached = static_cast<int>(at.size());
        figures.fraction = games.empty() ? 0.0 : static_cast<double>(at.size()) / games.size();
        figures.medianMinutes = median(at);
        figures.medianScore = median(score);
        curve.waves.push_back(figures);
    }
    return curve;
}

std::vector<std::pair<double, double>> survivalCurve(const std::vector<GamePlayed>& games,
                                                     double untilMinutes) {
    std::vector<double> ends;
    for (const GamePlayed& game : games)
        if (!game.capped) ends.push_back(game.minutes);
    std::sort(ends.begin(), ends.end());
    const double count = static_cast<double>(std::max<std::size_t>(games.size(), 1));
    std::vector<std::pair<double, double>> corners{{0.0, 1.0}};
    double alive = static_cast<double>(games.size());
    for (std::size_t k = 0; k < ends.size();) {
        std::size_t next = k;  // games that end on the same tick make one step
        while (next < ends.size() && ends[next] == ends[k]) ++next;
        corners.emplace_back(ends[k], alive / count);
        alive -= static_cast<double>(next - k);
        corners.emplace_back(ends[k], alive / count);
        k = next;
    }
    corners.emplace_back(std::max(untilMinutes, corners.back().first), alive / count);
    return corners;
}

}  // namespace polar::bench
