#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "app/context/app_context.h"
#include "app/hud/interpolation.h"
#include "app/hud/notice.h"
#include "app/hud/particles.h"
#include "files/high_scores.h"
#include "replay/replay_recorder.h"
#include "rules/bot.h"
#include "rules/game.h"

namespace polar::game {

// The games the screens play and show: the attract demo behind the title, played by its pilot,
// and the player's game, recorded from Play until the title. What is drawn between two ticks (the
// interpolation, the particles) follows whichever was stepped last.
//
// Why apart from the rest of the Session? These are the state a game screen changes each tick;
// the rest (devices, files, the notice) only serves it. A second player or a game over the network
// is a change here.
class Games {
  public:
    // What the games are made with and kept by; everything outlives them. `scripted`: a script
    // drives the screens, so every fresh seed is 1 and the runs repeat.
    struct Parts {
        AppContext& context;
        HighScores& scores;
        GameRecorder& recorder;
        Notice& notice;
        bool scripted = false;
    };
    Games(Parts parts, std::string scenePath);

    std::string scenePath;        // the scene the next game plays (--scene, or the Scenes screen)
    std::optional<Game> attract;  // the demo under the title, played by `bot`
    std::optional<Game> player;   // the player's game, from Play until the title
    int speed = kMaxGameSpeed;    // the game-speed assist of the player's next game (Options)
    Bot bot{7};
    Interpolation interpolation;
    Particles particles;

    // A game of `scene` (default: scenePath) with `seed` at `speed` percent on the run's threads, or
    // the loader's error.
    Result<Game> make(std::uint64_t seed, const std::string& scene = {}, int speed = kMaxGameSpeed) const;
    // The seed of a new game: --seed, else one from the clock (a script's runs: 1, so they repeat).
    std::uint64_t freshSeed() const;
    // Starts the player's game on scenePath at `speed` and records it; false (with the reason on stderr and
    // on screen) when the scene cannot be loaded.
    bool startGame();
    // Ends the player's game, finishing its recordings with `reason` ("quit", "restart").
    void endGame(std::string_view reason);
    // A new attract demo when there is none or the last one is over.
    void renewAttract();
    // One tick of the attract demo with its pilot (the screens over it call this from tick()).
    void tickAttract();
    // Ticks `game` with `actions`, keeping the interpolation, the statistics and the particles.
    void advance(Game& game, Actions actions);

  private:
    AppContext& context_;
    HighScores& scores_;
    GameRecorder& recorder_;
    Notice& notice_;
    bool scripted_;
};

}  // namespace polar::game
