#pragma once
#include "app/screens/screen.h"

namespace polar::game {

// A menu screen with the attract demo playing behind it (the title, Scenes, Replays, High scores,
// Options): the demo steps while the screen is on top, it is the game the screen shows, and the
// screen draws it first as its backdrop, without a score line.
class DemoBackdropScreen : public Screen {
  public:
    void tick(Session& session) override;
    const Game* shownGame(const Session& session) const override;

  protected:
    // Draws the demo, when there is one, over the whole canvas.
    static void drawDemo(Session& session, render::Canvas& canvas, double alpha);
};

}  // namespace polar::game
