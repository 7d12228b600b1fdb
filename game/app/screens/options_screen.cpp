#include "app/screens/options_screen.h"

#include <algorithm>

#include "app/hud/game_drawing.h"
#include "app/input/app_settings.h"
#include "app/screens/demo_backdrop_screen.h"
#include "app/screens/session.h"
#include "app/screens/widgets/menu.h"
#include "app/screens/widgets/screen_style.h"
#include "polar/platform/window.h"

namespace polar::game {
namespace {

enum class Row { Master, Effects, Music, Mute, Fullscreen, Scaling, FrameTime, Key, Button, Reset, Back };

struct RowOf {
    Row row;
    BoundAction action = BoundAction::Fire;  // Key and Button rows: which action, which slot
    std::size_t slot = 0;
};

std::string upper(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return c == '-' ? ' ' : static_cast<char>(std::toupper(c)); });
    return text;
}

class OptionsScreen : public DemoBackdropScreen {
  public:
    const char* name() const override { return "options"; }

    void enter(Session& session) override {
        settings_ = session.settings ? session.settings->saved() : Settings{};
        rows_.clear();
        for (Row r : {Row::Master, Row::Effects, Row::Music, Row::Mute, Row::Fullscreen, Row::Scaling,
                      Row::FrameTime})
            rows_.push_back({r});
        for (Row device : {Row::Key, Row::Button})
            for (std::size_t a = 0; a < kBoundActions; ++a)
                for (std::size_t slot = 0; slot < Bindings::kSlots; ++slot)
                    rows_.push_back({device, BoundAction(a), slot});
        rows_.push_back({Row::Reset});
        rows_.push_back({Row::Back});
        menu_ = Menu(items(), Menu::Layout{320, 70, 400, 16, 1, 15});
    }

    Next update(Session& session, const Input::Commands& commands) override {
        if (waiting_) {
            for (const platform::Event& event : commands.events) {
                const RowOf row = rows_[menu_.focus()];
                std::optional<std::string> refused;
                if (const auto* press = std::get_if<platform::KeyPressed>(&event);
                    press && row.row == Row::Key) {
                    if (press->position == platform::Key::Escape) {
                        waiting_ = false;
                        return Next::stay();
                    }
                    refused = settings_.bindings.bindKey(row.action, row.slot, press->position);
                } else if (const auto* button = std::get_if<platform::GamepadButtonPressed>(&event);
                           button && row.row == Row::Button) {
                    refused = settings_.bindings.bindButton(row.action, row.slot, button->button);
                } else {
                    continue;
                }
                waiting_ = false;
                message_ = refused ? "REFUSED: " + upper(*refused) : "";
                if (!refused) apply(session);
                return Next::stay();
            }
            return Next::stay();
        }
        if (commands.back) return Next::back();
        const Menu::Result chosen = menu_.update(commands);
        if (chosen.action == Menu::Action::None) return Next::stay();
        const int step = chosen.action == Menu::Action::Decrease ? -10 : 10;
        const bool activate = chosen.action == Menu::Action::Activate;
        const RowOf row = rows_[chosen.item];
        message_.clear();
        auto volume = [&](int& v) { v = std::clamp(activate ? (v + 10) % 110 : v + step, 0, 100); };
        switch (row.row) {
            case Row::Master:
                volume(settings_.masterVolume);
                break;
            case Row::Effects:
                volume(settings_.effectsVolume);
                break;
            case Row::Music:
                volume(settings_.musicVolume);
                break;
            case Row::Mute:
                settings_.mute = !settings_.mute;
                break;
            case Row::Fullscreen:
                settings_.fullscreen = !settings_.fullscreen;
                break;
            case Row::Scaling:
                settings_.scaleMode =
                    settings_.scaleMode == ScaleMode::Fit ? ScaleMode::Integer : ScaleMode::Fit;
                break;
            case Row::FrameTime:
                settings_.showFrameTime = !settings_.showFrameTime;
                break;
            case Row::Key:
            case Row::Button:
                if (!activate) return Next::stay();
                waiting_ = true;
                message_ = row.row == Row::Key
                               ? "PRESS A KEY FOR " + upper(boundActionName(row.action)) + " (ESC KEEPS IT)"
                               : "PRESS A PAD BUTTON FOR " + upper(boundActionName(row.action));
                menu_.setItems(items());
                return Next::stay();
            case Row::Reset:
                if (!activate) return Next::stay();
                settings_ = Settings{};
                message_ = "DEFAULTS RESTORED";
                break;
            case Row::Back:
                return activate ? Next::back() : Next::stay();
        }
        apply(session);
        return Next::stay();
    }

    void draw(Session& session, render::Canvas& canvas, double alpha) override {
        drawDemo(session, canvas, alpha);
        drawBand(canvas, 20, 330);
        drawHeading(canvas, "OPTIONS", 32);
        menu_.draw(canvas);
        if (!message_.empty()) drawCentredText(canvas, message_, 318, 1, waiting_ ? kGold : kWarnColor);
        drawHelpLine(canvas, "UP/DOWN CHOOSE   LEFT/RIGHT CHANGE   ENTER REMAP   ESC BACK");
    }

  private:
    void apply(Session& session) {
        session.showFrameTime = settings_.showFrameTime;
        if (session.settings && session.window)
            session.settings->change(settings_, session.audio, session.input, *session.window);
        else
            session.input.setBindings(settings_.bindings);
        menu_.setItems(items());
    }

    std::vector<Menu::Item> items() const {
        std::vector<Menu::Item> out;
        auto percent = [](int v) { return std::to_string(v) + "%"; };
        for (const RowOf& row : rows_) {
            switch (row.row) {
                case Row::Master:
                    out.push_back({"MASTER VOLUME", percent(settings_.masterVolume)});
                    break;
                case Row::Effects:
                    out.push_back({"EFFECTS VOLUME", percent(settings_.effectsVolume)});
                    break;
                case Row::Music:
                    out.push_back({"MUSIC VOLUME", percent(settings_.musicVolume)});
                    break;
                case Row::Mute:
                    out.push_back({"MUTE", settings_.mute ? "ON" : "OFF"});
                    break;
                case Row::Fullscreen:
                    out.push_back({"FULLSCREEN", settings_.fullscreen ? "ON" : "OFF"});
                    break;
                case Row::Scaling:
                    out.push_back(
                        {"SCALING", settings_.scaleMode == ScaleMode::Fit ? "FIT" : "WHOLE PIXELS"});
                    break;
                case Row::FrameTime:
                    out.push_back({"SHOW FRAME TIME", settings_.showFrameTime ? "ON" : "OFF"});
                    break;
                case Row::Key: {
                    platform::Key key = settings_.bindings.keys(row.action)[row.slot];
                    out.push_back(
                        {upper(boundActionName(row.action)) + " KEY " + std::to_string(row.slot + 1),
                         key == platform::Key::Unknown ? "-" : upper(platform::keyName(key))});
                    break;
                }
                case Row::Button: {
                    platform::GamepadButton b = settings_.bindings.buttons(row.action)[row.slot];
                    out.push_back(
                        {upper(boundActionName(row.action)) + " PAD " + std::to_string(row.slot + 1),
                         b == platform::GamepadButton::Count ? "-" : upper(gamepadButtonName(b))});
                    break;
                }
                case Row::Reset:
                    out.push_back({"RESET TO DEFAULTS", ""});
                    break;
                case Row::Back:
                    out.push_back({"BACK", ""});
                    break;
            }
        }
        return out;
    }

    Settings settings_;
    std::vector<RowOf> rows_;
    Menu menu_;
    bool waiting_ = false;  // for the key or button of the focused row
    std::string message_;
};

}  // namespace

std::unique_ptr<Screen> makeOptionsScreen() {
    return std::make_unique<OptionsScreen>();
}

}  // namespace polar::game
