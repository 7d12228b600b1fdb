#include "editor/script.h"

#include <cstdlib>
#include <optional>

#include "script_words.h"

namespace polar::bounds_tool::editor {
namespace {

using namespace platform;

using Word = cli::ScriptWord;

std::optional<int> integer(const std::string& text) {
    char* end = nullptr;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || v < -100000 || v > 100000) return std::nullopt;
    return static_cast<int>(v);
}

std::optional<MouseButton> button(const std::string& text) {
    if (text == "left") return MouseButton::Left;
    if (text == "middle") return MouseButton::Middle;
    if (text == "right") return MouseButton::Right;
    return std::nullopt;
}

Vec2 canvasPoint(int x, int y) {
    return Vec2(x + 0.5, y + 0.5);
}

}  // namespace

Result<std::vector<ScriptStep>> parseScript(const SourceFile& file) {
    std::vector<ScriptStep> steps;
    for (const cli::ScriptLine& line : cli::scriptLines(file.text)) {
        const std::vector<Word>& w = line.words;
        const int lineNumber = line.number;
        auto fail = [&](std::size_t at, const std::string& what, const std::string& expected) {
            return Error{file.path, lineNumber, line.columnOf(at), what, expected};
        };
        const std::string& command = w[0].text;
        // The numbers from word `from` on, exactly `count` of them.
        std::vector<int> numbers;
        auto takeNumbers = [&](std::size_t from, std::size_t count,
                               std::size_t optional = 0) -> std::optional<Error> {
            if (w.size() < from + count || w.size() > from + count + optional)
                return fail(std::min(w.size(), from + count + optional),
                            "\"" + command + "\" with " + std::to_string(w.size() - 1) + " arguments",
                            std::to_string(count) +
                                (optional ? " or " + std::to_string(count + optional) : "") +
                                " numbers after " + std::string(from > 1 ? "the button" : "it"));
            for (std::size_t i = from; i < w.size(); ++i) {
                std::optional<int> v = integer(w[i].text);
                if (!v)
                    return fail(i, "\"" + w[i].text + "\" is not a whole number", "a canvas pixel, e.g. 320");
                numbers.push_back(*v);
            }
            return std::nullopt;
        };
        if (command == "move") {
            if (auto e = takeNumbers(1, 2)) return *e;
            steps.push_back(Event{MouseMoved{numbers[0], numbers[1], canvasPoint(numbers[0], numbers[1])}});
        } else if (command == "press" || command == "release" || command == "click" || command == "drag") {
            std::optional<MouseButton> b = w.size() > 1 ? button(w[1].text) : std::nullopt;
            if (!b) return fail(1, "\"" + command + "\" needs a button", "left, middle or right");
            if (auto e = takeNumbers(2, command == "drag" ? 4 : 2, command == "drag" ? 1 : 0)) return *e;
            const int x = numbers[0], y = numbers[1];
            const Vec2 p = canvasPoint(x, y);
            steps.push_back(Event{MouseMoved{x, y, p}});
            if (command == "press" || command == "click" || command == "drag")
                steps.push_back(Event{MouseButtonPressed{*b, x, y, p}});
            int endX = x, endY = y;
            if (command == "drag") {
                endX = numbers[2];
                endY = numbers[3];
                const int n = numbers.size() > 4 ? numbers[4] : 8;
                if (n < 1) return fail(6, "a drag in " + std::to_string(n) + " moves", "1 or more moves");
                for (int i = 1; i <= n; ++i) {
                    const int mx = x + (endX - x) * i / n, my = y + (endY - y) * i / n;
                    steps.push_back(Event{MouseMoved{mx, my, canvasPoint(mx, my)}});
                }
            }
            if (command != "press")
                steps.push_back(Event{MouseButtonReleased{*b, endX, endY, canvasPoint(endX, endY)}});
        } else if (command == "wheel") {
            if (auto e = takeNumbers(1, 1)) return *e;
            steps.push_back(Event{MouseWheelScrolled{0.0, static_cast<double>(numbers[0])}});
        } else if (command == "key" || command == "down" || command == "up") {
            if (w.size() != 2)
                return fail(std::min<std::size_t>(w.size(), 2), "\"" + command + "\" needs one key",
                            "e.g. key ctrl+z");
            std::string name = w[1].text;
            std::uint8_t mods = kModNone;
            for (;;) {
                const std::size_t plus = name.find('+');
                if (plus == std::string::npos || plus == 0 || plus + 1 == name.size()) break;
                const std::string mod = name.substr(0, plus);
                if (mod == "ctrl")
                    mods |= kModCtrl;
                else if (mod == "shift")
                    mods |= kModShift;
                else if (mod == "alt")
                    mods |= kModAlt;
                else
                    return fail(1, "\"" + mod + "\" is not a modifier",
                                "ctrl+, shift+ or alt+ before the key");
                name = name.substr(plus + 1);
            }
            std::optional<Key> key = keyFromName(name);
            if (!key)
                return fail(1, "\"" + name + "\" is not a key name",
                            "a key as platform::keyName writes it, e.g. z, delete, tab, space, f12");
            if (command != "up") steps.push_back(Event{KeyPressed{*key, *key, mods, false}});
            if (command != "down") steps.push_back(Event{KeyReleased{*key, *key, mods}});
        } else if (command == "quit") {
            if (w.size() != 1) return fail(1, "\"quit\" with arguments", "quit alone");
            steps.push_back(Event{QuitRequested{}});
        } else if (command == "screenshot") {
            if (w.size() != 2 || w[1].text.size() < 5 || w[1].text.substr(w[1].text.size() - 4) != ".png")
                return fail(1, "\"screenshot\" needs a .png file", "screenshot FILE.png");
            steps.push_back(Screenshot{resolveRelative(file.path, w[1].text)});
        } else {
            return fail(0, "unknown command \"" + command + "\"",
                        "move, press, release, click, drag, wheel, key, down, up, quit or screenshot");
        }
    }
    return steps;
}

}  // namespace polar::bounds_tool::editor
