#pragma once
#include <memory>
#include <optional>
#include <vector>

#include "app/screens/screen.h"

namespace polar::game {

// The screens open now, the first (the title) at the bottom and the one the player sees on top.
// Only the top screen takes commands and ticks; drawing starts at the highest screen that is not
// an overlay, so a pause menu shows the game under it.
class ScreenStack {
  public:
    explicit ScreenStack(std::unique_ptr<Screen> root) { screens_.push_back(std::move(root)); }

    Screen& top() { return *screens_.back(); }
    std::size_t size() const { return screens_.size(); }
    // The screen at `depth` from the bottom (0: the root).
    Screen& at(std::size_t depth) { return *screens_[depth]; }

    // Gives the top screen the frame's commands and does what it answers; an exit code when the
    // game must end (Next::exit, or Back from the root).
    std::optional<int> update(Session& session, const Input::Commands& commands);
    // Carries out one Next (for the loop, and for tests that build a stack).
    std::optional<int> apply(Session& session, Next next);
    void tick(Session& session) { top().tick(session); }
    void draw(Session& session, render::Canvas& canvas, double alpha);
    // The game the frame shows: the one the topmost screen that draws a game shows, among those
    // draw() draws (an overlay's and the screen under it); null when none shows one.
    const Game* shownGame(const Session& session) const;

  private:
    std::vector<std::unique_ptr<Screen>> screens_;
};

}  // namespace polar::game
