#include "app/screens/replay_list_screen.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>

#include "app/hud/game_drawing.h"
#include "app/hud/hot_reload_hud.h"
#include "app/screens/confirm_screen.h"
#include "app/screens/demo_backdrop_screen.h"
#include "app/screens/session.h"
#include "app/screens/theatre_screen.h"
#include "app/screens/widgets/button_row.h"
#include "app/screens/widgets/menu.h"
#include "app/screens/widgets/screen_style.h"
#include "app/theatre/replay_summary.h"
#include "polar/platform/system.h"
#include "polar/render/text.h"

namespace polar::game {

namespace fs = std::filesystem;

std::vector<std::string> listReplays(const std::string& folder) {
    std::vector<std::string> found;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(folder, ec))
        if (entry.is_regular_file(ec) && entry.path().extension() == ".replay")
            found.push_back(entry.path().generic_string());
    struct Key {
        bool named;        // a recorder's name: its start's date and time
        std::string name;  // compares as that time
        fs::file_time_type written;
    };
    auto keyOf = [](const std::string& path) {
        std::error_code e;
        return Key{recorderTimeOf(path).has_value(), fs::path(path).stem().string(),
                   fs::last_write_time(path, e)};
    };
    std::vector<std::pair<Key, std::string>> keyed;
    for (std::string& path : found) keyed.emplace_back(keyOf(path), std::move(path));
    std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) {
        if (a.first.named != b.first.named) return a.first.named;
        if (a.first.named) return a.first.name > b.first.name;
        return a.first.written > b.first.written;
    });
    found.clear();
    for (auto& [key, path] : keyed) found.push_back(std::move(path));
    return found;
}

Result<std::string> exportReplay(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), {});
    if (!in.good() && !in.eof()) return Error{path, 0, 0, "cannot be read", "a readable replay file"};
    return platform::offerFile("polarcade-" + fs::path(path).filename().string(), bytes);
}

namespace {

using platform::GamepadButton;
using platform::Key;

enum class Verb { None, Watch, Delete, Export, Back };
constexpr Verb kButtons[] = {Verb::Watch, Verb::Delete, Verb::Export, Verb::Back};
constexpr const char* kButtonLabels[] = {"WATCH", "DELETE", "EXPORT", "BACK"};

constexpr render::Color kGoodColor{120, 230, 140, 255};
constexpr render::Color kCautionColor{255, 200, 90, 255};

Verb rawVerb(const platform::Event& event) {
    if (const auto* press = std::get_if<platform::KeyPressed>(&event)) {
        if (press->key == Key::Delete || press->key == Key::X) return Verb::Delete;
        if (press->key == Key::E) return Verb::Export;
    }
    if (const auto* button = std::get_if<platform::GamepadButtonPressed>(&event)) {
        if (button->button == GamepadButton::X) return Verb::Delete;
        if (button->button == GamepadButton::Y) return Verb::Export;
    }
    return Verb::None;
}

std::string lengthOf(const ReplaySummary& s) {
    const auto seconds = static_cast<unsigned long long>(static_cast<double>(s.ticks) / s.tickRate);
    char text[24];
    std::snprintf(text, sizeof text, "%llu:%02llu", seconds / 60, seconds % 60);
    return text;
}

class ReplayListScreen : public DemoBackdropScreen {
  public:
    ReplayListScreen(std::string folder, bool standalone)
        : folder_(std::move(folder)), standalone_(standalone) {}

    const char* name() const override { return "replays"; }

    // The folder is listed when the screen opens or comes back on top (after a replay, a delete);
    // each replay is then read one a frame in update(), never while the screen draws.
    void enter(Session& session) override {
        const std::string folder = !folder_.empty() ? folder_
                                   : session.context.dataFolder().path.empty()
                                       ? std::string()
                                       : session.context.dataFolder().path + "replays";
        paths_ = folder.empty() ? std::vector<std::string>{} : listReplays(folder);
        summaries_.assign(paths_.size(), std::nullopt);
        const std::size_t focus = menu_.focus();
        menu_ = Menu(rows(), Menu::Layout{320, 80, 600, 16, 1, 10});
        menu_.setFocus(std::min(focus, paths_.empty() ? 0 : paths_.size() - 1));
        buttons_.layOut({std::begin(kButtonLabels), std::end(kButtonLabels)}, 320, 296);
    }

    Next update(Session& session, const Input::Commands& commands) override {
        summariseOne(session);
        if (commands.back) return leave();
        std::vector<Verb> verbs;
        for (const platform::Event& event : commands.events)
            if (Verb verb = rawVerb(event); verb != Verb::None) verbs.push_back(verb);
        if (std::optional<std::size_t> pressed = buttons_.update(commands.pointer, commands.click))
            verbs.push_back(kButtons[*pressed]);
        else if (const Menu::Result chosen = menu_.update(commands); chosen.action == Menu::Action::Activate)
            verbs.push_back(Verb::Watch);
        for (Verb verb : verbs)
            if (Next next = apply(session, verb); next.kind != Next::Kind::Stay) return next;
        return Next::stay();
    }

    void draw(Session& session, render::Canvas& canvas, double alpha) override {
        drawDemo(session, canvas, alpha);
        drawBand(canvas, 40, 292);
        drawHeading(canvas, "REPLAYS", 48);
        if (paths_.empty())
            drawCentredText(canvas, "NO REPLAYS YET - EVERY GAME YOU PLAY IS KEPT HERE", 150, 1, kDimColor);
        menu_.draw(canvas);
        drawDetail(canvas);
        buttons_.draw(canvas);
    }

    std::string helpLine(const Session& session) const override {
        switch (session.input.device()) {
            case Device::Gamepad:
                return "A WATCHES   X DELETES   Y EXPORTS   B BACK";
            case Device::Touch:
                return "TAP A REPLAY, THEN WATCH, DELETE OR EXPORT";
            case Device::Keyboard:
                break;
        }
        return "ENTER WATCHES   DEL OR X DELETES   E EXPORTS   PAD X DELETE  Y EXPORT   ESC BACK";
    }

  private:
    std::vector<Menu::Item> rows() const {
        std::vector<Menu::Item> items;
        for (std::size_t i = 0; i < paths_.size(); ++i) {
            const std::optional<ReplaySummary>& s = summaries_[i];
            if (!s) {
                items.push_back({fs::path(paths_[i]).stem().string(), "...", true});
                continue;
            }
            std::string label = s->when + "  " + s->scene;
            for (const std::string& mod : s->mods) label += " +" + mod;
            char value[64];
            std::snprintf(value, sizeof value, "%s  SCORE %d  WAVE %d  %s",
                          s->playable == ReplaySummary::Playable::No        ? "CANNOT PLAY"
                          : s->playable == ReplaySummary::Playable::Caution ? "OLDER VERSION"
                                                                            : "",
                          s->score, s->wave, lengthOf(*s).c_str());
            items.push_back({label, value, true});
        }
        return items;
    }

    // Reads one replay not read yet, the focused one first.
    void summariseOne(const Session& session) {
        std::optional<std::size_t> next;
        if (menu_.focus() < paths_.size() && !summaries_[menu_.focus()]) next = menu_.focus();
        for (std::size_t i = 0; !next && i < paths_.size(); ++i)
            if (!summaries_[i]) next = i;
        if (!next) return;
        summaries_[*next] = summariseReplay(paths_[*next], session.context.assets);
        menu_.setItems(rows());
    }

    void drawDetail(render::Canvas& canvas) const {
        const std::size_t i = menu_.focus();
        if (i >= paths_.size() || !summaries_[i]) return;
        const ReplaySummary& s = *summaries_[i];
        const std::string mods = s.mods.empty() ? "NO MODS" : "MODS:";
        std::string line = fs::path(s.path).filename().string() + "   " + mods;
        for (const std::string& mod : s.mods) line += " " + mod;
        drawCentredText(canvas, line, 248, 1, kTextColor);
        const bool yes = s.playable == ReplaySummary::Playable::Yes;
        const std::string verdict = yes ? "PLAYS HERE, CHECKED TICK BY TICK"
                                    : s.playable == ReplaySummary::Playable::Caution
                                        ? s.reason + ": IT MAY NOT PLAY THE SAME"
                                        : "CANNOT PLAY HERE: " + s.reason;
        drawCentredText(canvas, verdict, 260, 1,
                        yes                                              ? kGoodColor
                        : s.playable == ReplaySummary::Playable::Caution ? kCautionColor
                                                                         : kWarnColor);
        if (yes) return;
        const std::vector<std::string> lines = wrapText(s.detail, 100);
        for (std::size_t k = 0; k < std::min<std::size_t>(lines.size(), 2); ++k)
            drawCentredText(canvas, lines[k], 272 + 10 * static_cast<int>(k), 1, kDimColor);
    }

    Next apply(Session& session, Verb verb) {
        const std::size_t i = menu_.focus();
        if (verb == Verb::Back) return leave();
        if (i >= paths_.size()) return Next::stay();
        const std::string path = paths_[i];
        switch (verb) {
            case Verb::Watch: {
                std::unique_ptr<Screen> replay = makeTheatreScreen(session, path, false);
                return replay ? Next::push(std::move(replay)) : Next::stay();
            }
            case Verb::Delete:
                return Next::push(
                    makeConfirmScreen("delete-confirm", "DELETE THIS REPLAY?", [path](Session& s) {
                        std::error_code ec;
                        if (!fs::remove(path, ec) || ec)
                            s.notice.tell(path + ": cannot be deleted" +
                                          (ec ? ": " + ec.message() : std::string()));
                        else
                            s.notice.tell("DELETED " + fs::path(path).filename().string());
                        return Next::back();
                    }));
            case Verb::Export: {
                Result<std::string> written = exportReplay(path);
                session.notice.tell(written ? "EXPORTED TO " + *written : written.error().message());
                return Next::stay();
            }
            case Verb::Back:
            case Verb::None:
                break;
        }
        return Next::stay();
    }

    Next leave() const { return standalone_ ? Next::exit(0) : Next::back(); }

    std::string folder_;
    bool standalone_;
    std::vector<std::string> paths_;
    std::vector<std::optional<ReplaySummary>> summaries_;
    Menu menu_;
    ButtonRow buttons_;
};

}  // namespace

std::unique_ptr<Screen> makeReplayListScreen(std::string folder, bool standalone) {
    return std::make_unique<ReplayListScreen>(std::move(folder), standalone);
}

}  // namespace polar::game
