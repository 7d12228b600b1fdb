#include "app/screens/game_over_screen.h"

#include "app/hud/game_drawing.h"
#include "app/screens/name_entry_screen.h"
#include "app/screens/session.h"
#include "app/screens/widgets/screen_style.h"

namespace polar::game {
namespace {

constexpr int kLockedTicks = 90;    // 1.5 s before a key moves on (no skipping it by accident)
constexpr int kMovesOnTicks = 360;  // 6 s: moves on by itself

class GameOverScreen : public Screen {
  public:
    const char* name() const override { return "game-over"; }

    Next update(Session& session, const Input::Commands& commands) override {
        if (!session.games.player) return Next::toRoot();
        const bool pressed = commands.confirm || commands.back || commands.click;
        if (ticks_ <= kLockedTicks || !(pressed || ticks_ > kMovesOnTicks)) return Next::stay();
        if (session.scores.qualifies(session.games.player->score()))
            return Next::replace(makeNameEntryScreen());
        session.games.endGame("game-over");
        return Next::toRoot();
    }

    void tick(Session& session) override {
        ++ticks_;
        if (!session.games.player) return;
        session.games.advance(*session.games.player, Actions{0});
        session.audio.play(session.games.player->events());
    }

    const Game* shownGame(const Session& session) const override {
        return session.games.player ? &*session.games.player : nullptr;
    }

    void draw(Session& session, render::Canvas& canvas, double alpha) override {
        if (session.games.player) session.drawWorld(canvas, *session.games.player, alpha, true);
        drawCentredText(canvas, "GAME OVER", 150, 4, kGold);
    }

  private:
    int ticks_ = 0;
};

}  // namespace

std::unique_ptr<Screen> makeGameOverScreen() {
    return std::make_unique<GameOverScreen>();
}

}  // namespace polar::game
