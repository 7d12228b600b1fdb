#include "app/screens/confirm_screen.h"

#include "app/hud/game_drawing.h"
#include "app/input/hints.h"
#include "app/screens/session.h"
#include "app/screens/widgets/menu.h"
#include "app/screens/widgets/screen_style.h"

namespace polar::game {
namespace {

class ConfirmScreen : public Screen {
  public:
    ConfirmScreen(const char* name, std::string question, std::function<Next(Session&)> yes)
        : name_(name),
          question_(std::move(question)),
          yes_(std::move(yes)),
          menu_({{"NO", "", true}, {"YES", "", true}}, Menu::Layout{320, 186, 120, 22, 2, 2}) {}

    const char* name() const override { return name_; }
    bool overlay() const override { return true; }

    Next update(Session& session, const Input::Commands& commands) override {
        if (commands.back) return Next::back();
        const Menu::Result chosen = menu_.update(commands);
        if (chosen.action != Menu::Action::Activate) return Next::stay();
        return chosen.item == 1 ? yes_(session) : Next::back();
    }

    void draw(Session&, render::Canvas& canvas, double) override {
        // The screen below dimmed, and the question on a panel of its own: nothing of the menu
        // underneath shows through the answers.
        drawBand(canvas, 0, canvas.height());
        drawPanel(canvas, 200, 130, 240, 110);
        drawHeading(canvas, question_, 146);
        menu_.draw(canvas);
    }

    std::string helpLine(const Session& session) const override {
        const Device device = session.input.device();
        if (device == Device::Touch) return "TAP YES OR NO";
        return "UP/DOWN CHOOSE   " + confirmWord(device) + " ANSWERS   " + backWord(device) + " SAYS NO";
    }

  private:
    const char* name_;
    std::string question_;
    std::function<Next(Session&)> yes_;
    Menu menu_;
};

}  // namespace

std::unique_ptr<Screen> makeConfirmScreen(const char* name, std::string question,
                                          std::function<Next(Session&)> yes) {
    return std::make_unique<ConfirmScreen>(name, std::move(question), std::move(yes));
}

std::unique_ptr<Screen> makeQuitConfirmScreen() {
    return makeConfirmScreen("quit-confirm", "QUIT?", [](Session&) { return Next::exit(0); });
}

}  // namespace polar::game
