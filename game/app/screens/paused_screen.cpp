#include "app/screens/paused_screen.h"

#include "app/screens/options_screen.h"
#include "app/screens/session.h"
#include "app/screens/widgets/menu.h"
#include "app/screens/widgets/screen_style.h"

namespace polar::game {
namespace {

enum class Entry { Resume, Restart, Options, QuitToTitle };

class PausedScreen : public Screen {
  public:
    PausedScreen()
        : menu_({{"RESUME", "", true},
                 {"RESTART", "", true},
                 {"OPTIONS", "", true},
                 {"QUIT TO TITLE", "", true}},
                Menu::Layout{320, 150, 220, 22, 2, 4}) {}

    const char* name() const override { return "paused"; }
    bool overlay() const override { return true; }
    bool silent() const override { return true; }

    Next update(Session& session, const Input::Commands& commands) override {
        if (commands.back || commands.pause) return Next::back();
        const Menu::Result chosen = menu_.update(commands);
        if (chosen.action != Menu::Action::Activate) return Next::stay();
        switch (static_cast<Entry>(chosen.item)) {
            case Entry::Resume:
                return Next::back();
            case Entry::Restart:
                // A scene that broke since stays paused, with the reason on screen.
                return session.games.startGame() ? Next::back() : Next::stay();
            case Entry::Options:
                return Next::push(makeOptionsScreen());
            case Entry::QuitToTitle:
                session.games.endGame("quit");
                return Next::toRoot();
        }
        return Next::stay();
    }

    void draw(Session&, render::Canvas& canvas, double) override {
        drawBand(canvas, 100, 150);
        drawHeading(canvas, "PAUSED", 112);
        menu_.draw(canvas);
    }

  private:
    Menu menu_;
};

}  // namespace

std::unique_ptr<Screen> makePausedScreen() {
    return std::make_unique<PausedScreen>();
}

}  // namespace polar::game
