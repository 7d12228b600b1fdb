#pragma once
// The difficulty benchmark's arithmetic: what each game of the demo pilot gave (how long it lasted,
// its score, when it reached each wave) summed up per scene as medians and fractions, and the
// survival curve (the share of games still going after t minutes of game time). Kept apart from
// the playing, so that a test can hold the sums against games written by hand.
#include <utility>
#include <vector>

namespace polar::bench {

// The moment a game first reached a wave.
struct WaveReached {
    int wave = 0;
    double minutes = 0;  // game time (ticks / 60 / 60) at the tick the wave began
    int score = 0;       // the score at that tick
};

// One game, from its first tick to its last.
struct GamePlayed {
    double minutes = 0;              // game time played: to the game's end, or to the cap
    int score = 0;                   // the score at its last tick
    int wave = 0;                    // the highest wave it reached
    bool capped = false;             // still going when the cap stopped it (its minutes are a lower bound)
    std::vector<WaveReached> waves;  // in order of wave, each wave the game reached once
};

// One wave across a scene's games.
struct WaveFigures {
    int wave = 0;
    int reached = 0;           // games that reached it
    double fraction = 0;       // reached / games
    double medianMinutes = 0;  // over the games that reached it
    double medianScore = 0;    // the score on reaching it, over those games
};

// A scene's games summed up.
struct DifficultyCurve {
    int games = 0;
    int capped = 0;                  // games the cap stopped
    double medianMinutes = 0;        // median survival (capped games count at the cap)
    double medianScore = 0;          // median final score
    double medianWave = 0;           // median of the highest wave reached
    std::vector<WaveFigures> waves;  // wave 1 up to the highest any game reached, none left out
};

// The medians and fractions of `games` (the median of an even count is the mean of the middle two).
DifficultyCurve summarizeGames(const std::vector<GamePlayed>& games);

// The share of `games` still going against game minutes, as the corners of a falling staircase
// from (0, 1) to (`untilMinutes`, the share left then); a capped game never ends.
std::vector<std::pair<double, double>> survivalCurve(const std::vector<GamePlayed>& games,
                                                     double untilMinutes);

}  // namespace polar::bench
