#include "app/screens/high_scores_screen.h"

#include <cstdio>
#include <filesystem>

#include "app/hud/game_drawing.h"
#include "app/input/hints.h"
#include "app/screens/demo_backdrop_screen.h"
#include "app/screens/session.h"
#include "app/screens/widgets/screen_style.h"

namespace polar::game {
namespace {

class HighScoresScreen : public DemoBackdropScreen {
  public:
    explicit HighScoresScreen(std::optional<std::size_t> highlight) : highlight_(highlight) {}

    const char* name() const override { return "high-scores"; }

    Next update(Session&, const Input::Commands& commands) override {
        if (commands.back || commands.confirm || commands.click) return Next::back();
        return Next::stay();
    }

    void draw(Session& session, render::Canvas& canvas, double alpha) override {
        drawDemo(session, canvas, alpha);
        drawBand(canvas, 40, 260);
        drawHeading(canvas, "HIGH SCORES", 52);
        drawCentredText(canvas, tableName(session.scores.selected()), 80, 1, kDimColor);
        const auto& entries = session.scores.entries();
        if (entries.empty()) drawCentredText(canvas, "NO SCORES YET - PLAY A GAME", 150, 1, kDimColor);
        int y = 96;
        for (std::size_t i = 0; i < entries.size(); ++i) {
            const bool mine = highlight_ == i;
            char line[64];
            std::snprintf(line, sizeof line, "%s%2zu  %-3s %8d  WAVE %d%s", mine ? "> " : "", i + 1,
                          entries[i].name.c_str(), entries[i].score, entries[i].wave, mine ? " <" : "");
            drawCentredText(canvas, line, y, 1, i == 0 || mine ? kGold : kTextColor);
            y += 18;
        }
    }

    std::string helpLine(const Session& session) const override {
        const Device device = session.input.device();
        return device == Device::Touch ? "TAP TO GO BACK" : backWord(device) + " BACK";
    }

  private:
    // "CAVE", "CAVE  MODS GOLD", "FIELD  SPEED 75%": which table this is.
    static std::string tableName(const HighScores::TableKey& key) {
        std::string name = upperCase(std::filesystem::path(key.scene).stem().string());
        if (!key.mods.empty()) {
            name += "  MODS";
            for (const std::string& mod : key.mods) name += " " + upperCase(mod);
        }
        if (key.speed != kMaxGameSpeed) name += "  SPEED " + std::to_string(key.speed) + "%";
        return name;
    }

    std::optional<std::size_t> highlight_;
};

}  // namespace

std::unique_ptr<Screen> makeHighScoresScreen(std::optional<std::size_t> highlight) {
    return std::make_unique<HighScoresScreen>(highlight);
}

}  // namespace polar::game
