#include "app/run/script.h"

#include <cctype>
#include <cstdlib>

#include "script_words.h"

namespace polar::game {
namespace {

using namespace platform;

using Word = cli::ScriptWord;

std::optional<double> number(const std::string& text, double low, double high) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !(v >= low && v <= high)) return std::nullopt;
    return v;
}

std::optional<GamepadButton> padButton(const std::string& name) {
    static const std::pair<const char*, GamepadButton> kNames[] = {
        {"a", GamepadButton::A},
        {"b", GamepadButton::B},
        {"x", GamepadButton::X},
        {"y", GamepadButton::Y},
        {"back", GamepadButton::Back},
        {"start", GamepadButton::Start},
        {"dpad-up", GamepadButton::DpadUp},
        {"dpad-down", GamepadButton::DpadDown},
        {"dpad-left", GamepadButton::DpadLeft},
        {"dpad-right", GamepadButton::DpadRight},
        {"left-shoulder", GamepadButton::LeftShoulder},
        {"right-shoulder", GamepadButton::RightShoulder}};
    for (const auto& [text, button] : kNames)
        if (name == text) return button;
    return std::nullopt;
}

constexpr GamepadId kScriptPad = 1;

}  // namespace

Result<std::vector<ScriptStep>> parseScript(const SourceFile& file) {
    std::vector<ScriptStep> steps;
    for (const cli::ScriptLine& line : cli::scriptLines(file.text)) {
        const std::vector<Word>& w = line.words;
        const int lineNumber = line.number;
        auto fail = [&](std::size_t at, const std::string& what, const std::string& expected) {
            return Error{file.path, lineNumber, line.columnOf(at), what, expected};
        };
        auto arguments = [&](std::size_t count, const std::string& what) -> std::optional<Error> {
            if (w.size() == count + 1) return std::nullopt;
            return fail(std::min(w.size(), count + 1),
                        "\"" + w[0].text + "\" with " + std::to_string(w.size() - 1) + " arguments",
                        std::to_string(count) + " after it: " + what);
        };
        const std::string& command = w[0].text;
        ScriptStep step;
        step.line = lineNumber;
        if (command == "key" || command == "down" || command == "up") {
            if (w.size() < 2 || (command != "key" && w.size() != 2))
                return fail(w.size() < 2 ? 1 : 2,
                            "\"" + command + "\" needs " + (command == "key" ? "keys" : "one key"),
                            "a key name such as enter, escape, a, up, f1");
            for (std::size_t i = 1; i < w.size(); ++i) {  // each key in a frame of its own
                std::optional<Key> key = keyFromName(w[i].text);
                if (!key)
                    return fail(i, "unknown key \"" + w[i].text + "\"",
                                "a key name such as enter, escape, a, up, f1");
                ScriptStep press;
                press.line = lineNumber;
                if (command != "up") press.events.push_back(KeyPressed{*key, *key, kModNone, false});
                if (command != "down") press.events.push_back(KeyReleased{*key, *key, kModNone});
                if (i + 1 < w.size())
                    steps.push_back(std::move(press));
                else
                    step = std::move(press);
            }
        } else if (command == "repeat") {
            if (auto error = arguments(1, "a key held down")) return *error;
            std::optional<Key> key = keyFromName(w[1].text);
            if (!key)
                return fail(1, "unknown key \"" + w[1].text + "\"",
                            "a key name such as enter, escape, a, up, f1");
            step.events.push_back(KeyPressed{*key, *key, kModNone, true});
            const std::string name = w[1].text;
            if (name.size() == 1 && std::isalnum(static_cast<unsigned char>(name[0])))
                step.events.push_back(TextEntered{name});
        } else if (command == "type") {
            if (w.size() < 2) return fail(1, "\"type\" with nothing to type", "the letters, e.g. type BOB");
            const std::size_t from = static_cast<std::size_t>(w[1].column - 1);
            std::string typed = line.text.substr(from, line.text.find('#', from) - from);
            while (!typed.empty() && (typed.back() == ' ' || typed.back() == '\r')) typed.pop_back();
            step.events.push_back(TextEntered{typed});
        } else if (command == "move" || command == "click" || command == "press" || command == "release") {
            if (auto error = arguments(2, "X Y, canvas pixels")) return *error;
            std::optional<double> x = number(w[1].text, -100000, 100000),
                                  y = number(w[2].text, -100000, 100000);
            if (!x || !y) return fail(x ? 2 : 1, "not a number", "X Y, canvas pixels");
            const Vec2 at(*x + 0.5, *y + 0.5);  // the pixel's centre, as from a window at scale 1
            const int px = static_cast<int>(*x), py = static_cast<int>(*y);
            step.events.push_back(MouseMoved{px, py, at});
            if (command == "click" || command == "press")
                step.events.push_back(MouseButtonPressed{MouseButton::Left, px, py, at});
            if (command == "click" || command == "release")
                step.events.push_back(MouseButtonReleased{MouseButton::Left, px, py, at});
        } else if (command == "wheel") {
            if (auto error = arguments(1, "DY, notches")) return *error;
            std::optional<double> dy = number(w[1].text, -100, 100);
            if (!dy) return fail(1, "not a number of notches", "DY from -100 to 100");
            step.events.push_back(MouseWheelScrolled{0, *dy});
        } else if (command == "pad") {
            if (auto error = arguments(1, "a gamepad button")) return *error;
            std::optional<GamepadButton> button = padButton(w[1].text);
            if (!button)
                return fail(
                    1, "unknown gamepad button \"" + w[1].text + "\"",
                    "a b x y back start dpad-up dpad-down dpad-left dpad-right left-shoulder right-shoulder");
            step.events.push_back(GamepadButtonPressed{kScriptPad, *button});
            step.events.push_back(GamepadButtonReleased{kScriptPad, *button});
        } else if (command == "stick") {
            if (auto error = arguments(2, "X Y, each from -1 to 1")) return *error;
            std::optional<double> x = number(w[1].text, -1, 1), y = number(w[2].text, -1, 1);
            if (!x || !y) return fail(x ? 2 : 1, "not a stick position", "X Y, each from -1 to 1");
            step.events.push_back(GamepadAxisMoved{kScriptPad, GamepadAxis::LeftX, *x});
            step.events.push_back(GamepadAxisMoved{kScriptPad, GamepadAxis::LeftY, *y});
        } else if (command == "expect-tick") {
            if (auto error = arguments(1, "N, a tick")) return *error;
            std::optional<double> n = number(w[1].text, 0, 1e9);
            if (!n || *n != static_cast<double>(static_cast<std::int64_t>(*n)))
                return fail(1, "not a tick", "a whole number from 0");
            step.kind = ScriptStep::Kind::ExpectTick;
            step.frames = static_cast<int>(*n);
        } else if (command == "wait") {
            if (auto error = arguments(1, "N, frames")) return *error;
            std::optional<double> n = number(w[1].text, 1, 1000000);
            if (!n || *n != static_cast<int>(*n))
                return fail(1, "not a number of frames", "a whole number from 1");
            step.kind = ScriptStep::Kind::Wait;
            step.frames = static_cast<int>(*n);
        } else if (command == "screenshot" || command == "expect") {
            if (auto error = arguments(1, command == "expect" ? "a screen's name" : "a .png file"))
                return *error;
            step.kind = command == "expect" ? ScriptStep::Kind::Expect : ScriptStep::Kind::Screenshot;
            step.text = w[1].text;
        } else if (command == "quit") {
            if (auto error = arguments(0, "nothing")) return *error;
            step.events.push_back(QuitRequested{});
        } else {
            return fail(0, "unknown command \"" + command + "\"",
                        "key, down, up, repeat, type, move, click, press, release, wheel, pad, stick, wait, "
                        "screenshot, expect, "
                        "expect-tick or quit");
        }
        steps.push_back(std::move(step));
    }
    return steps;
}

}  // namespace polar::game
