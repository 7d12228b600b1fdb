#include "app/screens/replays_screen.h"

#include <algorithm>
#include <filesystem>

#include "app/draw.h"
#include "app/screens/menu.h"
#include "app/screens/replay_screen.h"
#include "app/screens/screen_style.h"
#include "app/session.h"

namespace polar::game {

namespace fs = std::filesystem;

std::vector<std::string> listReplays(const std::string& folder) {
    std::vector<std::string> found;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(folder, ec))
        if (entry.is_regular_file(ec) && entry.path().extension() == ".replay")
            found.push_back(entry.path().generic_string());
    std::sort(found.begin(), found.end(), std::greater<>());
    return found;
}

namespace {

class ReplaysScreen : public Screen {
  public:
    const char* name() const override { return "replays"; }

    // The folder is read when the screen opens or comes back on top, never while it draws.
    void enter(Session& session) override {
        paths_ = session.data.path.empty() ? std::vector<std::string>{}
                                           : listReplays(session.data.path + "replays");
        std::vector<Menu::Item> items;
        for (const std::string& path : paths_) {
            std::string stem = fs::path(path).stem().string();  // "2024-05-01_18-04-09"
            std::replace(stem.begin(), stem.end(), '_', ' ');
            items.push_back({stem, "", true});
        }
        const std::size_t focus = menu_.focus();
        menu_ = Menu(std::move(items), Menu::Layout{320, 90, 300, 18, 1, 10});
        menu_.setFocus(focus);
    }

    Next update(Session& session, const Input::Commands& commands) override {
        if (commands.back) return Next::back();
        const Menu::Result chosen = menu_.update(commands);
        if (chosen.action != Menu::Action::Activate || paths_.empty()) return Next::stay();
        std::unique_ptr<Screen> replay = makeReplayScreen(session, paths_[chosen.item], false);
        return replay ? Next::push(std::move(replay)) : Next::stay();
    }

    void tick(Session& session) override { session.tickAttract(); }

    void draw(Session& session, render::Canvas& canvas, double alpha) override {
        if (session.attract) session.drawWorld(canvas, *session.attract, alpha, false);
        drawBand(canvas, 40, 272);
        drawHeading(canvas, "REPLAYS", 52);
        if (paths_.empty())
            drawCentredText(canvas, "NO REPLAYS YET - EVERY GAME YOU PLAY IS KEPT HERE", 150, 1, kDimColor);
        menu_.draw(canvas);
        drawHelpLine(canvas, "ENTER OR CLICK PLAYS   WHEEL SCROLLS   ESC BACK");
    }

  private:
    std::vector<std::string> paths_;
    Menu menu_;
};

}  // namespace

std::unique_ptr<Screen> makeReplaysScreen() {
    return std::make_unique<ReplaysScreen>();
}

}  // namespace polar::game
