#include "app/input/settings.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "polar/json_doc.h"
#include "polar/json_writer.h"
#include "rules/game.h"

namespace polar::game {
namespace {

using platform::GamepadButton;
using platform::Key;

constexpr const char* kVolumeExpected = "a whole percent from 0 to 100";

int volume(const JsonNode& root, const char* key, int fallback) {
    std::optional<JsonNode> node = root.find(key);
    if (!node) return fallback;
    int value = node->integer(kVolumeExpected);
    if (value < 0 || value > 100)
        node->fail("volume " + std::to_string(value) + " is out of range", kVolumeExpected);
    return value;
}

bool flag(const JsonNode& root, const char* key, bool fallback) {
    std::optional<JsonNode> node = root.find(key);
    return node ? node->boolean("true or false") : fallback;
}

int ranged(const JsonNode& node, int low, int high, const std::string& expected) {
    int value = node.integer(expected.c_str());
    if (value < low || value > high) node.fail(std::to_string(value) + " is out of range", expected);
    return value;
}

// Reads "keys" or "pad": {"turn-left": ["left", "a"], …}; an action not listed has nothing bound.
// The lists are bound in file order, so a key given twice is blamed where it is repeated.
template <class Name, class Bind>
void readBindings(const JsonNode& table, const char* what, Name fromName, Bind bind) {
    if (!table.isObject())
        table.fail("expected an object, found " + table.kindName(), "{\"fire\": [...], ...}");
    table.allowKeys({"turn-left", "turn-right", "thrust", "fire", "pause"});
    for (const JsonNode& member : table.members("an object of actions")) {
        const BoundAction action = *boundActionFromName(member.key());
        std::string expected =
            "an array of up to " + std::to_string(Bindings::kSlots) + " " + what + " names";
        std::vector<JsonNode> names = member.items(expected.c_str());
        if (names.size() > Bindings::kSlots)
            member.fail(std::to_string(names.size()) + " " + what + "s for one action", expected);
        for (std::size_t slot = 0; slot < names.size(); ++slot) {
            std::string name = names[slot].string((std::string("a ") + what + " name").c_str());
            auto value = fromName(name);
            if (!value)
                names[slot].fail(
                    "unknown " + std::string(what) + " \"" + name + "\"",
                    std::string(what) == "key"
                        ? "a key name such as \"a\", \"space\", \"left\", \"f2\", \"left-shift\""
                        : "a button name such as \"a\", \"start\", \"dpad-left\", \"left-shoulder\"");
            if (std::optional<std::string> refused = bind(action, slot, *value))
                names[slot].fail(*refused, "each " + std::string(what) + " bound to one action");
        }
    }
}

Settings parse(const JsonDoc& doc) {
    JsonNode root = JsonNode::root(doc);
    if (!root.isObject()) root.fail("expected an object, found " + root.kindName(), "{\"format\": 1, ...}");
    root.allowKeys({"format", "master_volume", "effects_volume", "music_volume", "mute", "fullscreen",
                    "window", "scaling", "show_frame_time", "screen_shake", "flashes", "hold_fire",
                    "game_speed", "keys", "pad"});
    JsonNode format = root.require("format", "\"format\": 1");
    if (format.integer("the format number 1") != 1) format.fail("unsupported format", "\"format\": 1");
    Settings s;
    s.masterVolume = volume(root, "master_volume", s.masterVolume);
    s.effectsVolume = volume(root, "effects_volume", s.effectsVolume);
    s.musicVolume = volume(root, "music_volume", s.musicVolume);
    s.mute = flag(root, "mute", s.mute);
    s.fullscreen = flag(root, "fullscreen", s.fullscreen);
    s.showFrameTime = flag(root, "show_frame_time", s.showFrameTime);
    if (std::optional<JsonNode> shake = root.find("screen_shake"))
        s.screenShake = ranged(*shake, 0, 100, "a whole percent from 0 to 100");
    if (std::optional<JsonNode> flashes = root.find("flashes"))
        s.flashes = ranged(*flashes, 0, 100, "a whole percent from 0 to 100");
    s.holdFire = flag(root, "hold_fire", s.holdFire);
    if (std::optional<JsonNode> speed = root.find("game_speed"))
        s.gameSpeed = ranged(*speed, kMinGameSpeed, kMaxGameSpeed, "a whole percent from 50 to 100");
    if (std::optional<JsonNode> window = root.find("window")) {
        if (!window->isObject())
            window->fail("expected an object, found " + window->kindName(),
                         "{\"width\": W, \"height\": H, \"x\": X, \"y\": Y}");
        window->allowKeys({"width", "height", "x", "y"});
        std::string side = "a whole number of pixels from " + std::to_string(Settings::kMinWindowSide) +
                           " to " + std::to_string(Settings::kMaxWindowSide);
        std::string offset = "a whole number of pixels from -" + std::to_string(Settings::kMaxWindowOffset) +
                             " to " + std::to_string(Settings::kMaxWindowOffset);
        if (auto w = window->find("width"))
            s.windowWidth = ranged(*w, Settings::kMinWindowSide, Settings::kMaxWindowSide, side);
        if (auto h = window->find("height"))
            s.windowHeight = ranged(*h, Settings::kMinWindowSide, Settings::kMaxWindowSide, side);
        if (auto x = window->find("x"))
            s.windowX = ranged(*x, -Settings::kMaxWindowOffset, Settings::kMaxWindowOffset, offset);
        if (auto y = window->find("y"))
            s.windowY = ranged(*y, -Settings::kMaxWindowOffset, Settings::kMaxWindowOffset, offset);
        if (s.windowX.has_value() != s.windowY.has_value())
            window->fail("a window position needs both x and y", "both \"x\" and \"y\", or neither");
    }
    if (std::optional<JsonNode> scaling = root.find("scaling")) {
        std::string mode = scaling->string("\"integer\" or \"fit\"");
        if (mode == "integer")
            s.scaleMode = ScaleMode::Integer;
        else if (mode == "fit")
            s.scaleMode = ScaleMode::Fit;
        else
            scaling->fail("unknown scaling \"" + mode + "\"", "\"integer\" or \"fit\"");
    }
    if (std::optional<JsonNode> keys = root.find("keys")) {
        for (std::size_t a = 0; a < kBoundActions; ++a)
            for (std::size_t slot = 0; slot < Bindings::kSlots; ++slot)
                s.bindings.clearKey(static_cast<BoundAction>(a), slot);
        readBindings(
            *keys, "key", [](const std::string& n) { return platform::keyFromName(n); },
            [&](BoundAction a, std::size_t slot, Key k) { return s.bindings.bindKey(a, slot, k); });
    }
    if (std::optional<JsonNode> pad = root.find("pad")) {
        for (std::size_t a = 0; a < kBoundActions; ++a)
            for (std::size_t slot = 0; slot < Bindings::kSlots; ++slot)
                s.bindings.clearButton(static_cast<BoundAction>(a), slot);
        readBindings(
            *pad, "button", [](const std::string& n) { return gamepadButtonFromName(n); },
            [&](BoundAction a, std::size_t slot, GamepadButton b) {
                return s.bindings.bindButton(a, slot, b);
            });
    }
    return s;
}

}  // namespace

std::string settingsToJson(const Settings& s) {
    JsonWriter w(2);
    w.beginObject()
        .member("format", 1)
        .member("master_volume", s.masterVolume)
        .member("effects_volume", s.effectsVolume)
        .member("music_volume", s.musicVolume)
        .member("mute", s.mute)
        .member("fullscreen", s.fullscreen);
    w.key("window").beginObject().member("width", s.windowWidth).member("height", s.windowHeight);
    if (s.windowX && s.windowY) w.member("x", *s.windowX).member("y", *s.windowY);
    w.endObject();
    w.member("scaling", s.scaleMode == ScaleMode::Integer ? "integer" : "fit")
        .member("show_frame_time", s.showFrameTime)
        .member("screen_shake", s.screenShake)
        .member("flashes", s.flashes)
        .member("hold_fire", s.holdFire)
        .member("game_speed", s.gameSpeed);
    w.key("keys").beginObject();
    for (std::size_t a = 0; a < kBoundActions; ++a) {
        BoundAction action = static_cast<BoundAction>(a);
        w.key(boundActionName(action)).beginArray();
        for (Key key : s.bindings.keys(action))
            if (key != Key::Unknown) w.value(platform::keyName(key));
        w.endArray();
    }
    w.endObject();
    w.key("pad").beginObject();
    for (std::size_t a = 0; a < kBoundActions; ++a) {
        BoundAction action = static_cast<BoundAction>(a);
        w.key(boundActionName(action)).beginArray();
        for (GamepadButton button : s.bindings.buttons(action))
            if (button != GamepadButton::Count) w.value(gamepadButtonName(button));
        w.endArray();
    }
    w.endObject();
    w.endObject();
    return w.text() + "\n";
}

Result<Settings> parseSettings(const SourceFile& file) {
    Result<JsonDoc> doc = JsonDoc::parse(file);
    if (!doc) return doc.error();
    return catchLoadFailure<Settings>([&] { return parse(*doc); });
}

SettingsFile SettingsFile::load(const std::string& path) {
    SettingsFile out;
    out.path_ = path;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec) && !ec) return out;
    std::optional<Error> problem;
    std::string text;
    std::ifstream in(path, std::ios::binary);
    if (!std::filesystem::is_regular_file(path, ec) || !in) {
        problem = Error{path, 0, 0, "cannot be read", "a readable settings file"};
    } else {
        std::ostringstream buffer;
        buffer << in.rdbuf();
        if (in.bad()) problem = Error{path, 0, 0, "cannot be read", "a readable settings file"};
        text = buffer.str();
    }
    if (!problem) {
        Result<Settings> parsed = parseSettings(SourceFile{path, text});
        if (parsed) {
            out.settings_ = *parsed;
            out.written_ = text;
            return out;
        }
        problem = parsed.error();
    }
    // Keep the unusable file under another name; an earlier one set aside is not overwritten.
    std::string aside = path + ".bad";
    for (int n = 2; std::filesystem::exists(aside, ec); ++n) aside = path + ".bad-" + std::to_string(n);
    std::filesystem::rename(path, aside, ec);
    if (ec) {
        out.saveBlocked_ = true;
        problem->expected +=
            "; it could not be set aside (" + ec.message() + "), so nothing is saved this run";
    } else {
        out.setAside_ = aside;
        problem->expected += "; the defaults are used and the file is kept as " + aside;
    }
    out.problem_ = problem;
    return out;
}

std::optional<std::string> SettingsFile::takeProblem() {
    if (!problem_ || problemTaken_) return std::nullopt;
    problemTaken_ = true;
    return problem_->message();
}

std::optional<Error> SettingsFile::save(const Settings& settings, const AtomicWriteFault& fault) {
    settings_ = settings;
    if (saveBlocked_) return std::nullopt;
    std::string text = settingsToJson(settings);
    if (written_ && *written_ == text) return std::nullopt;
    if (std::optional<Error> error = writeFileAtomically(path_, text, fault)) return error;
    written_ = text;
    return std::nullopt;
}

}  // namespace polar::game
