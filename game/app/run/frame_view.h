#pragma once
#include "app/theatre/seek_timing.h"
#include "files/high_scores.h"
#include "rules/game.h"

namespace polar::game {

// What a windowed frame shows, for an observer (the web page's test hooks).
struct FrameView {
    const Game& game;    // the game on screen: the attract demo under the title, else the player's
    const char* screen;  // the screen on top: "title", "playing", "paused", "game-over", "name-entry", …
    const HighScores& scores;
    const SeekTiming& seek;
};

}  // namespace polar::game
