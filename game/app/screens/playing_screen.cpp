#include "app/screens/playing_screen.h"

#include "app/screens/game_over_screen.h"
#include "app/screens/paused_screen.h"
#include "app/session.h"

namespace polar::game {
namespace {

class PlayingScreen : public Screen {
  public:
    const char* name() const override { return "playing"; }

    Next update(Session& session, const Input::Commands& commands) override {
        if (!session.game) return Next::toRoot();
        if (session.game->over()) return Next::replace(makeGameOverScreen());
        // The player looking away (another window, a hidden tab) pauses too.
        if (commands.pause || commands.focusLost) return Next::push(makePausedScreen());
        return Next::stay();
    }

    void tick(Session& session) override {
        if (!session.game || session.game->over()) return;
        const Actions actions = session.input.actions();
        session.advance(*session.game, actions);
        session.recorder.record(actions, *session.game);
        session.audio.play(session.game->events());
    }

    void draw(Session& session, render::Canvas& canvas, double alpha) override {
        if (session.game) session.drawWorld(canvas, *session.game, alpha, true);
    }
};

}  // namespace

std::unique_ptr<Screen> makePlayingScreen() {
    return std::make_unique<PlayingScreen>();
}

}  // namespace polar::game
