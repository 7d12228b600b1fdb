#include "app/screens/quit_confirm_screen.h"

#include "app/draw.h"
#include "app/screens/menu.h"
#include "app/screens/screen_style.h"

namespace polar::game {
namespace {

class QuitConfirmScreen : public Screen {
  public:
    QuitConfirmScreen()
        : menu_({{"NO", "", true}, {"YES", "", true}}, Menu::Layout{320, 186, 120, 22, 2, 2}) {}

    const char* name() const override { return "quit-confirm"; }
    bool overlay() const override { return true; }

    Next update(Session&, const Input::Commands& commands) override {
        if (commands.back) return Next::back();
        const Menu::Result chosen = menu_.update(commands);
        if (chosen.action != Menu::Action::Activate) return Next::stay();
        return chosen.item == 1 ? Next::exit(0) : Next::back();
    }

    void draw(Session&, render::Canvas& canvas, double) override {
        drawBand(canvas, 130, 110);
        drawHeading(canvas, "QUIT?", 146);
        menu_.draw(canvas);
    }

  private:
    Menu menu_;
};

}  // namespace

std::unique_ptr<Screen> makeQuitConfirmScreen() {
    return std::make_unique<QuitConfirmScreen>();
}

}  // namespace polar::game
