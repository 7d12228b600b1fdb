#include "app/screens/name_entry_screen.h"

#include <algorithm>
#include <cstdio>

#include "app/hud/game_drawing.h"
#include "app/screens/high_scores_screen.h"
#include "app/screens/session.h"
#include "app/screens/widgets/screen_style.h"
#include "polar/render/shapes.h"
#include "polar/render/text.h"

namespace polar::game {

bool NameEntry::update(const Input::Commands& commands) {
    // A typed letter also arrives as its key (W is "up", A "left"): a frame that typed letters
    // takes them as letters only.
    bool typed = false;
    for (char c : commands.text) {
        if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
        if (c < 'A' || c > 'Z') continue;
        typed = true;
        name_[cursor()] = c;
        set_ = std::max(set_, cursor() + 1);
        if (place_ < 3) ++place_;
    }
    if (commands.erase && place_ > 0) {
        --place_;
        name_[place_] = 'A';
        set_ = place_;
    }
    if (!typed) {
        char& letter = name_[cursor()];
        if (commands.up) letter = letter == 'Z' ? 'A' : static_cast<char>(letter + 1);
        if (commands.down) letter = letter == 'A' ? 'Z' : static_cast<char>(letter - 1);
        if (commands.up || commands.down) set_ = std::max(set_, cursor() + 1);
        if (commands.left && cursor() > 0) place_ = cursor() - 1;
        if (commands.right && cursor() < 2) place_ = cursor() + 1;
    }
    if (!commands.confirm && !commands.click) return false;
    set_ = std::max(set_, cursor() + 1);
    if (place_ >= 2) return true;
    ++place_;
    return false;
}

std::string NameEntry::keptName(const std::string& lastName) const {
    if (set_ > 0) return name_.substr(0, set_);
    return lastName.empty() ? name_ : lastName;
}

namespace {

class NameEntryScreen : public Screen {
  public:
    const char* name() const override { return "name-entry"; }

    Next update(Session& session, const Input::Commands& commands) override {
        if (!session.games.player) return Next::toRoot();
        if (commands.back) return keep(session, entry_.keptName(session.scores.lastName()));
        if (!entry_.update(commands)) return Next::stay();
        return keep(session, entry_.name());
    }

    std::string helpLine(const Session& session) const override {
        const std::string kept = "KEEPS IT AS " + entry_.keptName(session.scores.lastName());
        switch (session.input.device()) {
            case Device::Gamepad:
                return "UP/DOWN CHANGE A LETTER   LEFT/RIGHT MOVE   A NEXT   B " + kept;
            case Device::Touch:
                return "THRUST CHANGES A LETTER   ARROWS MOVE   FIRE NEXT";
            case Device::Keyboard:
                break;
        }
        return "TYPE YOUR NAME   UP/DOWN CHANGE   BACKSPACE ERASES   ENTER NEXT   ESC " + kept;
    }

    const Game* shownGame(const Session& session) const override {
        return session.games.player ? &*session.games.player : nullptr;
    }

  private:
    // Puts the score in the table under `name`, saves it, ends the game and shows the table.
    Next keep(Session& session, const std::string& name) {
        const std::optional<std::size_t> rank =
            session.scores.insert({name, session.games.player->score(), session.games.player->wave()});
        // An unwritable folder was reported once at the start: the table then lives until the
        // game closes.
        std::optional<Error> error =
            session.context.dataFolder().writable() ? session.scores.save() : std::nullopt;
        if (error) session.notice.tell("high scores not saved: " + error->message());
        session.games.endGame("game-over");
        return Next::replace(makeHighScoresScreen(rank));
    }

  public:
    void draw(Session& session, render::Canvas& canvas, double) override {
        if (!session.games.player) return;
        session.drawWorld(canvas, *session.games.player, 1.0, true);
        drawBand(canvas, 110, 230);  // down past the help line, so it reads over the cave
        drawCentredText(canvas, "A NEW HIGH SCORE", 120, 2, kGold);
        char line[32];
        std::snprintf(line, sizeof line, "%d", session.games.player->score());
        drawCentredText(canvas, line, 146, 2, kTextColor);
        for (std::size_t i = 0; i < 3; ++i) {
            const std::string letter(1, entry_.name()[i]);
            const int x = canvas.width() / 2 - 45 + static_cast<int>(i) * 34;
            const bool here = i == entry_.cursor();
            render::drawText(canvas, letter, x, 176, 4, here ? kGold : kTextColor);
            if (here) render::fillRect(canvas, x, 214, 20, 2, kGold);
        }
    }

  private:
    NameEntry entry_;
};

}  // namespace

std::unique_ptr<Screen> makeNameEntryScreen() {
    return std::make_unique<NameEntryScreen>();
}

}  // namespace polar::game
