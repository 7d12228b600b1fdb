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
        // Hold fire: a press starts firing and the next one stops it.
        if (commands.fire) firing_ = !firing_;
        return Next::stay();
    }

    void tick(Session& session) override {
        if (!session.games.player || session.games.player->over()) return;
        Actions actions = session.input.actions();
        if (session.holdFire) actions = static_cast<Actions>((actions & ~kFire) | (firing_ ? kFire : 0));
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

  private:
    bool firing_ = false;  // with hold fire on: firing until the next press
};

}  // namespace

std::unique_ptr<Screen> makePlayingScreen() {
    return std::make_unique<PlayingScreen>();
}

}  // namespace polar::game
