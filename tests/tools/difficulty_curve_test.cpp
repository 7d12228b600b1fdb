// The difficulty benchmark's sums (tools/bench/difficulty_curve.h) on games written by hand: the
// medians per scene (a capped game counted at the cap), each wave's share and its medians over the
// games that reached it, and the survival staircase.
#include "difficulty_curve.h"

#include <gtest/gtest.h>

#include <vector>

namespace polar::bench {
namespace {

// Four games: one ends in wave 1, one in wave 2, one in wave 3, and one still going at the cap.
std::vector<GamePlayed> fourGames() {
    GamePlayed a{1.0, 100, 2, false, {{1, 0.0, 0}, {2, 0.5, 50}}};
    GamePlayed b{2.0, 300, 3, false, {{1, 0.0, 0}, {2, 0.4, 40}, {3, 1.5, 200}}};
    GamePlayed capped{5.0, 900, 3, true, {{1, 0.0, 0}, {2, 0.6, 60}, {3, 2.5, 400}}};
    GamePlayed d{0.5, 10, 1, false, {{1, 0.0, 0}}};
    return {a, b, capped, d};
}

TEST(DifficultyCurve, ASceneHasTheMediansOfItsGames) {
    const DifficultyCurve curve = summarizeGames(fourGames());
    EXPECT_EQ(curve.games, 4);
    EXPECT_EQ(curve.capped, 1);
    EXPECT_DOUBLE_EQ(curve.medianMinutes, 1.5);  // of 0.5, 1, 2, 5 (the cap)
    EXPECT_DOUBLE_EQ(curve.medianScore, 200);    // of 10, 100, 300, 900
    EXPECT_DOUBLE_EQ(curve.medianWave, 2.5);     // of 1, 2, 3, 3
}

TEST(DifficultyCurve, AWaveHasItsShareAndTheMediansOfTheGamesThatReachedIt) {
    const DifficultyCurve curve = summarizeGames(fourGames());
    ASSERT_EQ(curve.waves.size(), 3u);
    EXPECT_EQ(curve.waves[0].wave, 1);
    EXPECT_EQ(curve.waves[0].reached, 4);
    EXPECT_DOUBLE_EQ(curve.waves[0].fraction, 1.0);
    EXPECT_DOUBLE_EQ(curve.waves[0].medianMinutes, 0.0);

    EXPECT_EQ(curve.waves[1].wave, 2);
    EXPECT_EQ(curve.waves[1].reached, 3);
    EXPECT_DOUBLE_EQ(curve.waves[1].fraction, 0.75);
    EXPECT_DOUBLE_EQ(curve.waves[1].medianMinutes, 0.5);  // of 0.4, 0.5, 0.6
    EXPECT_DOUBLE_EQ(curve.waves[1].medianScore, 50);     // of 40, 50, 60

    EXPECT_EQ(curve.waves[2].wave, 3);
    EXPECT_EQ(curve.waves[2].reached, 2);
    EXPECT_DOUBLE_EQ(curve.waves[2].fraction, 0.5);
    EXPECT_DOUBLE_EQ(curve.waves[2].medianMinutes, 2.0);  // of 1.5, 2.5
    EXPECT_DOUBLE_EQ(curve.waves[2].medianScore, 300);    // of 200, 400
}

TEST(DifficultyCurve, NoGamesGiveNoWavesAndZeros) {
    const DifficultyCurve curve = summarizeGames({});
    EXPECT_EQ(curve.games, 0);
    EXPECT_TRUE(curve.waves.empty());
    EXPECT_EQ(curve.medianMinutes, 0.0);
}

TEST(DifficultyCurve, TheSurvivalCurveStepsDownAtEachEndAndNeverForACappedGame) {
    using Corners = std::vector<std::pair<double, double>>;
    EXPECT_EQ(survivalCurve(fourGames(), 6.0),
              (Corners{{0, 1}, {0.5, 1}, {0.5, 0.75}, {1, 0.75}, {1, 0.5}, {2, 0.5}, {2, 0.25}, {6, 0.25}}));
    // Two games ending on the same tick make one step.
    std::vector<GamePlayed> tied(2);
    tied[0].minutes = tied[1].minutes = 1.0;
    EXPECT_EQ(survivalCurve(tied, 3.0), (Corners{{0, 1}, {1, 1}, {1, 0}, {3, 0}}));
}

}  // namespace
}  // namespace polar::bench
