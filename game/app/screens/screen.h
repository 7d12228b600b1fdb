#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/hud/overlay_layout.h"
#include "app/input/input.h"
#include "polar/render/canvas.h"

namespace polar::game {

class Game;
class Session;
class Screen;

// What a screen asks of the stack after an update: stay, open a screen over it, be replaced, go
// back one screen, go back to the first screen (the title), or leave the game.
struct Next {
    enum class Kind { Stay, Push, Replace, Back, ToRoot, Exit };
    Kind kind = Kind::Stay;
    std::unique_ptr<Screen> screen;  // Push and Replace
    int exitCode = 0;                // Exit

    static Next stay() { return {}; }
    static Next push(std::unique_ptr<Screen> screen) { return {Kind::Push, std::move(screen), 0}; }
    static Next replace(std::unique_ptr<Screen> screen) { return {Kind::Replace, std::move(screen), 0}; }
    static Next back() { return {Kind::Back, nullptr, 0}; }
    static Next toRoot() { return {Kind::ToRoot, nullptr, 0}; }
    static Next exit(int code) { return {Kind::Exit, nullptr, code}; }
};

// One room of the game: the title, the game being played, a menu, a list.
//
// Why this shape? It is raylib's game template (init, update, draw, unload per screen) with the
// hand-off made explicit: a screen takes the frame's menu commands, never raw devices (the key map
// is Input's business), steps on the fixed clock, draws into a Canvas, and answers with the Next
// screen. The ScreenStack owns the screens and the loop calls it; what screens share (the games,
// the high scores, the recorder, the audio) lives in the Session. A screen never opens a file
// while it draws.
class Screen {
  public:
    virtual ~Screen() = default;
    // The screen's name for observers (FrameView, tests): "title", "playing", "paused", …
    virtual const char* name() const = 0;
    // Called when the screen comes on top: pushed, or uncovered by the one above going back.
    virtual void enter(Session&) {}
    // The frame's menu commands; which screen comes next.
    virtual Next update(Session& session, const Input::Commands& commands) = 0;
    // One fixed step (1/60 s) while the screen is on top.
    virtual void tick(Session&) {}
    // Draws the screen; `alpha` is how far the frame lies between the last tick and the next.
    // Drawing writes nothing back to the session.
    virtual void draw(Session& session, render::Canvas& canvas, double alpha) = 0;
    // The game this screen shows when it draws (the debug panel describes it, FrameView reports
    // it), or null: a screen drawn over another (overlay()) shows what the one below shows.
    virtual const Game* shownGame(const Session&) const { return nullptr; }
    // The screen's bar across the bottom, drawn over everything by the overlay layout (the replay
    // bar); none by default.
    virtual std::vector<OverlayLine> bar(const Session&) const { return {}; }
    // The screen's line of controls near the bottom ("ENTER OPEN   ESC BACK", in the words of the
    // device in use: app/input/hints.h), and a message over it (a prompt, a refusal), both placed by
    // the overlay layout so that nothing is drawn over them; none by default.
    virtual std::string helpLine(const Session&) const { return {}; }
    virtual std::optional<OverlayLine> message(const Session&) const { return std::nullopt; }
    // Rows the bar holds above its lines for controls the screen draws itself (the theatre's
    // buttons and seek bar, in overlays.h's barControlsRect), and their drawing; none by default.
    virtual int barControls() const { return 0; }
    virtual void drawBarControls(const Session&, render::Canvas&, const PixelRect&) const {}
    // True for a screen drawn over the one below it (the pause menu, "Quit?"): that one is drawn
    // first, as it was, and keeps still.
    virtual bool overlay() const { return false; }
    // True for a screen under which the game holds its breath (the pause menu): the audio stops
    // while it is on top and resumes when it leaves.
    virtual bool silent() const { return false; }
};

}  // namespace polar::game
