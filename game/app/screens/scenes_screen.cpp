#include "app/screens/scenes_screen.h"

#include <algorithm>

#include "app/draw.h"
#include "app/screens/menu.h"
#include "app/screens/playing_screen.h"
#include "app/screens/screen_style.h"
#include "app/session.h"
#include "files/scene_list.h"

namespace polar::game {
namespace {

class ScenesScreen : public Screen {
  public:
    const char* name() const override { return "scenes"; }

    // The scene folders are read when the screen opens, never while it draws.
    void enter(Session& session) override {
        scenes_ = listScenes(session.assets);
        std::vector<Menu::Item> items;
        std::size_t current = 0;
        for (std::size_t i = 0; i < scenes_.size(); ++i) {
            std::string name = scenes_[i].name;
            std::transform(name.begin(), name.end(), name.begin(),
                           [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
            items.push_back({name, scenes_[i].mod.empty() ? "" : "MOD " + scenes_[i].mod, true});
            if (scenes_[i].logical == session.scenePath) current = i;
        }
        menu_ = Menu(std::move(items), Menu::Layout{320, 90, 300, 20, 2, 10});
        menu_.setFocus(current);
    }

    Next update(Session& session, const Input::Commands& commands) override {
        if (commands.back) return Next::back();
        const Menu::Result chosen = menu_.update(commands);
        if (chosen.action != Menu::Action::Activate || scenes_.empty()) return Next::stay();
        const std::string before = session.scenePath;
        session.scenePath = scenes_[chosen.item].logical;
        if (!session.startGame()) {  // the reason is on screen; the old scene stays chosen
            session.scenePath = before;
            return Next::stay();
        }
        return Next::replace(makePlayingScreen());
    }

    void tick(Session& session) override { session.tickAttract(); }

    void draw(Session& session, render::Canvas& canvas, double alpha) override {
        if (session.attract) session.drawWorld(canvas, *session.attract, alpha, false);
        drawBand(canvas, 40, 272);
        drawHeading(canvas, "SCENES", 52);
        menu_.draw(canvas);
        drawHelpLine(canvas, "ENTER OR CLICK PLAYS   ESC BACK");
    }

  private:
    std::vector<SceneEntry> scenes_;
    Menu menu_;
};

}  // namespace

std::unique_ptr<Screen> makeScenesScreen() {
    return std::make_unique<ScenesScreen>();
}

}  // namespace polar::game
