#include "app/screens/demo_backdrop_screen.h"

#include "app/screens/session.h"

namespace polar::game {

void DemoBackdropScreen::tick(Session& session) {
    session.games.tickAttract();
}

const Game* DemoBackdropScreen::shownGame(const Session& session) const {
    return session.games.attract ? &*session.games.attract : nullptr;
}

void DemoBackdropScreen::drawDemo(Session& session, render::Canvas& canvas, double alpha) {
    if (session.games.attract) session.drawWorld(canvas, *session.games.attract, alpha, false);
}

}  // namespace polar::game
