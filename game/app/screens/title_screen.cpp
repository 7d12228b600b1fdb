#include "app/screens/title_screen.h"

#include "app/input/hints.h"
#include "app/screens/confirm_screen.h"
#include "app/screens/demo_backdrop_screen.h"
#include "app/screens/high_scores_screen.h"
#include "app/screens/options_screen.h"
#include "app/screens/playing_screen.h"
#include "app/screens/replay_list_screen.h"
#include "app/screens/scenes_screen.h"
#include "app/screens/session.h"
#include "app/screens/widgets/menu.h"
#include "app/screens/widgets/screen_style.h"
#include "polar/render/text.h"

namespace polar::game {
namespace {

// The title menu's entries, in the order shown.
enum class Entry { Play, Scenes, Replays, Options, HighScores, Quit };

class TitleScreen : public DemoBackdropScreen {
  public:
    TitleScreen() {
        std::vector<Menu::Item> items;
        for (Entry entry : entries_) items.push_back({label(entry), "", true});
        menu_ = Menu(std::move(items), Menu::Layout{320, 136, 200, 22, 2, 8});
    }

    const char* name() const override { return "title"; }

    void enter(Session& session) override {
        if (!session.games.attract) session.games.renewAttract();
    }

    Next update(Session& session, const Input::Commands& commands) override {
        if (commands.back) {
#ifdef __EMSCRIPTEN__
            return Next::stay();  // a page has no Quit: the player closes the tab
#else
            return Next::push(makeQuitConfirmScreen());
#endif
        }
        const Menu::Result chosen = menu_.update(commands);
        if (chosen.action != Menu::Action::Activate) return Next::stay();
        switch (entries_[chosen.item]) {
            case Entry::Play:
                if (!session.games.startGame()) return Next::stay();
                return Next::push(makePlayingScreen());
            case Entry::Scenes:
                return Next::push(makeScenesScreen());
            case Entry::Replays:
                return Next::push(makeReplayListScreen());
            case Entry::Options:
                return Next::push(makeOptionsScreen());
            case Entry::HighScores:
                return Next::push(makeHighScoresScreen());
            case Entry::Quit:
                return Next::exit(0);
        }
        return Next::stay();
    }

    void draw(Session& session, render::Canvas& canvas, double alpha) override {
        drawDemo(session, canvas, alpha);
        drawCentredText(canvas, "POLARCADE", 56, 5, kGold);
        drawCentredText(canvas, "A ROCK CAVE. A SHIP. NO WAY OUT.", 110, 1, kDimColor);
        menu_.draw(canvas);
    }

    // How to play, as the controls are bound, on the device in use.
    std::string helpLine(const Session& session) const override {
        return playHint(session.input.bindings(), session.input.device());
    }

  private:
    static const char* label(Entry entry) {
        switch (entry) {
            case Entry::Play:
                return "PLAY";
            case Entry::Scenes:
                return "SCENES";
            case Entry::Replays:
                return "REPLAYS";
            case Entry::Options:
                return "OPTIONS";
            case Entry::HighScores:
                return "HIGH SCORES";
            case Entry::Quit:
                return "QUIT";
        }
        return "?";
    }

#ifdef __EMSCRIPTEN__
    std::vector<Entry> entries_{Entry::Play, Entry::Scenes, Entry::Replays, Entry::Options,
                                Entry::HighScores};
#else
    std::vector<Entry> entries_{Entry::Play,    Entry::Scenes,     Entry::Replays,
                                Entry::Options, Entry::HighScores, Entry::Quit};
#endif
    Menu menu_;
};

}  // namespace

std::unique_ptr<Screen> makeTitleScreen() {
    return std::make_unique<TitleScreen>();
}

}  // namespace polar::game
