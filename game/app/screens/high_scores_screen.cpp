#include "app/screens/high_scores_screen.h"

#include <cstdio>

#include "app/hud/game_drawing.h"
#include "app/screens/demo_backdrop_screen.h"
#include "app/screens/session.h"
#include "app/screens/widgets/screen_style.h"

namespace polar::game {
namespace {

class HighScoresScreen : public DemoBackdropScreen {
  public:
    const char* name() const override { return "high-scores"; }

    Next update(Session&, const Input::Commands& commands) override {
        if (commands.back || commands.confirm || commands.click) return Next::back();
        return Next::stay();
    }

    void draw(Session& session, render::Canvas& canvas, double alpha) override {
        drawDemo(session, canvas, alpha);
        drawBand(canvas, 40, 260);
        drawHeading(canvas, "HIGH SCORES", 52);
        const auto& entries = session.scores.entries();
        if (entries.empty()) drawCentredText(canvas, "NO SCORES YET - PLAY A GAME", 150, 1, kDimColor);
        int y = 96;
        for (std::size_t i = 0; i < entries.size(); ++i) {
            char line[64];
            std::snprintf(line, sizeof line, "%2zu  %-3s %8d  WAVE %d", i + 1, entries[i].name.c_str(),
                          entries[i].score, entries[i].wave);
            drawCentredText(canvas, line, y, 1, i == 0 ? kGold : kTextColor);
            y += 18;
        }
        drawHelpLine(canvas, "ESC BACK");
    }
};

}  // namespace

std::unique_ptr<Screen> makeHighScoresScreen() {
    return std::make_unique<HighScoresScreen>();
}

}  // namespace polar::game
