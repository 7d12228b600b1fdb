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

enum class Row {
    Master,
    Effects,
    Music,
    Mute,
    Fullscreen,
    Scaling,
    FrameTime,
    Shake,
    Flashes,
    HoldFire,
    Speed,
    Key,
    Button,
    Reset,
    Back
};

// How long a message stays, in ticks: a refusal long enough to read, a confirmation shorter. The
// prompt for a key stays while the screen waits for it.
constexpr int kRefusalTicks = 240;
constexpr int kConfirmationTicks = 120;

// A level of the screen's shake or the flashes, as the row shows it.
const char* levelName(int percent) {
    return percent >= 100 ? "FULL" : percent > 0 ? "REDUCED" : "OFF";
}

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
                      Row::FrameTime, Row::Shake, Row::Flashes, Row::HoldFire, Row::Speed})
            rows_.push_back({r});
        for (Row device : {Row::Key, Row::Button})
            for (std::size_t a = 0; a < kBoundActions; ++a)
                for (std::size_t slot = 0; slot < Bindings::kSlots; ++slot)
                    rows_.push_back({device, BoundAction(a), slot});
        rows_.push_back({Row::Reset});
        rows_.push_back({Row::Back});
        // 14 rows, from 70 to 294: the message and the help line below them have their own rows.
        menu_ = Menu(items(), Menu::Layout{320, 70, 400, 16, 1, 14});
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
                        message_.clear();
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
                say(refused ? "REFUSED: " + upper(*refused) : "", kRefusalTicks);
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
        // Enter raises a volume a step, as right does, and stops at 100 %: it never jumps to 0.
        auto volume = [&](int& v) { v = std::clamp(v + step, 0, 100); };
        // A level is a choice of three: Enter goes round them, left and right step and stop.
        auto level = [&](int& v) {
            v = activate ? (v >= 100 ? 50 : v > 0 ? 0 : 100) : std::clamp(v + 5 * step, 0, 100);
        };
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
            case Row::Shake:
                level(settings_.screenShake);
                break;
            case Row::Flashes:
                level(settings_.flashes);
                break;
            case Row::HoldFire:
                settings_.holdFire = !settings_.holdFire;
                break;
            case Row::Speed:
                settings_.gameSpeed = std::clamp(settings_.gameSpeed + step, kMinGameSpeed, kMaxGameSpeed);
                say("THE NEXT GAME PLAYS AT " + std::to_string(settings_.gameSpeed) + "%",
                    kConfirmationTicks);
                break;
            case Row::Key:
            case Row::Button:
                if (!activate) return Next::stay();
                waiting_ = true;
                say(row.row == Row::Key
                        ? "PRESS A KEY FOR " + upper(boundActionName(row.action)) + " (ESC KEEPS IT)"
                        : "PRESS A PAD BUTTON FOR " + upper(boundActionName(row.action)),
                    0);
                menu_.setItems(items());
                return Next::stay();
            case Row::Reset:
                if (!activate) return Next::stay();
                settings_ = Settings{};
                say("DEFAULTS RESTORED", kConfirmationTicks);
                break;
            case Row::Back:
                return activate ? Next::back() : Next::stay();
        }
        apply(session);
        return Next::stay();
    }

    void tick(Session& session) override {
        DemoBackdropScreen::tick(session);
        if (messageTicks_ > 0 && --messageTicks_ == 0) message_.clear();
    }

    void draw(Session& session, render::Canvas& canvas, double alpha) override {
        drawDemo(session, canvas, alpha);
        drawBand(canvas, 20, 330);
        drawHeading(canvas, "OPTIONS", 32);
        menu_.draw(canvas);
    }

    std::string helpLine(const Session& session) const override {
        switch (session.input.device()) {
            case Device::Gamepad:
                return "UP/DOWN CHOOSE   LEFT/RIGHT CHANGE   A REMAPS   B BACK";
            case Device::Touch:
                return "TAP A ROW TO CHANGE IT   ARROWS CHANGE";
            case Device::Keyboard:
                break;
        }
        return "UP/DOWN CHOOSE   LEFT/RIGHT CHANGE   ENTER REMAP   ESC BACK";
    }

    std::optional<OverlayLine> message(const Session&) const override {
        if (message_.empty()) return std::nullopt;
        return OverlayLine{message_, waiting_ || !refusal_ ? kGold : kWarnColor};
    }

  private:
    // Shows `text` for `ticks` (0: until the next change); a "REFUSED" text is drawn in red.
    void say(std::string text, int ticks) {
        refusal_ = text.rfind("REFUSED", 0) == 0;
        message_ = std::move(text);
        messageTicks_ = ticks;
    }

    void apply(Session& session) {
        session.follow(settings_);
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
                case Row::Shake:
                    out.push_back({"SCREEN SHAKE", levelName(settings_.screenShake)});
                    break;
                case Row::Flashes:
                    out.push_back({"FLASHES", levelName(settings_.flashes)});
                    break;
                case Row::HoldFire:
                    out.push_back(
                        {"HOLD FIRE (PRESS TO START, AGAIN TO STOP)", settings_.holdFire ? "ON" : "OFF"});
                    break;
                case Row::Speed:
                    out.push_back({"GAME SPEED", percent(settings_.gameSpeed)});
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
    int messageTicks_ = 0;  // until the message goes; 0: it stays
    bool refusal_ = false;
};

}  // namespace

std::unique_ptr<Screen> makeOptionsScreen() {
    return std::make_unique<OptionsScreen>();
}

}  // namespace polar::game
