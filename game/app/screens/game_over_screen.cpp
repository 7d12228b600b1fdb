#include "app/screens/game_over_screen.h"

#include "app/draw.h"
#include "app/screens/name_entry_screen.h"
#include "app/screens/screen_style.h"
#include "app/session.h"

namespace polar::game {
namespace {

constexpr int kLockedTicks = 90;    // 1.5 s before a key moves on (no skipping it by accident)
constexpr int kMovesOnTicks = 360;  // 6 s: moves on by itself

class GameOverScreen : public Screen {
  public:
    const char* name() const override { return "game-over"; }

    Next update(Session& session, const Input::Commands& commands) override {
        if (!session.game) return Next::toRoot();
        const bool pressed = commands.confirm || commands.back || commands.click;
        if (ticks_ <= kLockedTicks || !(pressed || ticks_ > kMovesOnTicks)) return Next::stay();
        if (session.scores.qualifies(session.game->score())) return Next::replace(makeNameEntryScreen());
        session.endGame("game-over");
        return Next::toRoot();
    }

    void tick(Session& session) override {
        ++ticks_;
        if (!session.game) return;
        session.advance(*session.game, Actions{0});
        session.audio.play(session.game->events());
    }

    void draw(Session& session, render::Canvas& canvas, double alpha) override {
        if (session.game) session.drawWorld(canvas, *session.game, alpha, true);
        drawCentredText(canvas, "GAME OVER", 150, 4, kTitleColor);
    }

  private:
    int ticks_ = 0;
};

}  // namespace

std::unique_ptr<Screen> makeGameOverScreen() {
    return std::make_unique<GameOverScreen>();
}

}  // namespace polar::game
