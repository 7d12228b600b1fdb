#include "app/screens/playing_screen.h"

#include "app/screens/game_over_screen.h"
#include "app/screens/paused_screen.h"
#include "app/screens/session.h"

namespace polar::game {
namespace {

class PlayingScreen : public Screen {
  public:
    const char* name() const override { return "playing"; }

    Next update(Session& session, const Input::Commands& commands) override {
        if (!session.games.player) return Next::toRoot();
        if (session.games.player->over()) return Next::replace(makeGameOverScreen());
        // The player looking away (another window, a hidden tab) pauses too.
        if (commands.pause || commands.focusLost) return Next::push(makePausedScreen());
        return Next::stay();
    }

    void tick(Session& session) override {
        if (!session.games.player || session.games.player->over()) return;
        const Actions actions = session.input.actions();
        session.games.advance(*session.games.player, actions);
        session.recorder.record(actions, *session.games.player);
        session.audio.play(session.games.player->events());
    }

    const Game* shownGame(const Session& session) const override {
        return session.games.player ? &*session.games.player : nullptr;
    }

    void draw(Session& session, render::Canvas& canvas, double alpha) override {
        if (session.games.player) session.drawWorld(canvas, *session.games.player, alpha, true);
    }
};

}  // namespace

std::unique_ptr<Screen> makePlayingScreen() {
    return std::make_unique<PlayingScreen>();
}

}  // namespace polar::game
