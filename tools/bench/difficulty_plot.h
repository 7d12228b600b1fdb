#pragma once
// The difficulty benchmark's picture, two panels with linear axes and one line per scene: above,
// the share of games still going against game minutes (the survival curve); below, the share of
// games that reached each wave.
#include <optional>
#include <string>
#include <vector>

#include "difficulty_curve.h"
#include "polar/error.h"

namespace polar::bench {

struct DifficultyPlot {
    struct Scene {
        std::string name;
        std::vector<GamePlayed> games;
        DifficultyCurve curve;
    };
    std::string title;
    double capMinutes = 15;  // the longest a game was let run
    std::vector<Scene> scenes;

    // Draws both panels and writes the PNG atomically.
    std::optional<Error> save(const std::string& path, int width = 900, int height = 680) const;
};

}  // namespace polar::bench
