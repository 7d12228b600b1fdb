#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/context/app_context.h"
#include "app/hud/overlay_layout.h"
#include "app/input/audio.h"
#include "app/input/input.h"
#include "app/run/frame_view.h"
#include "app/screens/screen_stack.h"
#include "app/screens/session.h"
#include "files/high_scores.h"
#include "polar/platform/events.h"
#include "replay/replay_recorder.h"

namespace polar::platform {
class Window;
}

namespace polar::game {

// The fixed-step loop the screens run in, fed one frame at a time: the frame's platform events
// and the seconds since the last frame go in, a drawn canvas comes out. A window (app.cpp) feeds
// it what the player does; a script (script.h) feeds it the same events from a file, one tick a
// frame, so every screen is tested through the path a player's input takes.
class ScreenLoop {
  public:
    // Opens what the screens need (the high scores, the recorder, the audio unless muted or
    // scripted) and the first screen, made by `root` (nothing: it could not be made, already told).
    ScreenLoop(AppContext& context, platform::Window* window, std::string scenePath,
               const std::function<std::unique_ptr<Screen>(Session&)>& root);
    ~ScreenLoop();
    ScreenLoop(const ScreenLoop&) = delete;
    ScreenLoop& operator=(const ScreenLoop&) = delete;

    // False when the first screen could not be made.
    bool ready() const { return stack_ != nullptr; }
    // One frame: hands the events to the input and the top screen, runs the ticks that are due,
    // draws the screens and the overlays into context.canvas. The exit code once the game ends
    // (the recording is then finished and the statistics printed).
    std::optional<int> frame(const std::vector<platform::Event>& events, double seconds);
    // How long the next frame can wait: until the next tick is nearly due.
    double idleSeconds() const;
    // What the last frame showed, for FrameView observers; nothing when it showed no game.
    std::optional<FrameView> view() const;
    // Opens the replay at `path` in the theatre over the screen on top (told on screen when it
    // cannot be played).
    void openReplay(const std::string& path);
    // Draws the overlays over the screens (the frame does; tests call it to see the boxes).
    OverlayLayout drawOverlays();
    Session& session() { return *session_; }
    ScreenStack& stack() { return *stack_; }

  private:
    int finish(int code);
    // After hot reload changed the player's game: its recording is given up, and the player told.
    void stopRecordingIfReloaded(const HotReload::Report& reload);

    AppContext& context_;
    Input input_;
    std::optional<Audio> audio_;
    HighScores scores_;
    std::optional<GameRecorder> recorder_;
    std::optional<Session> session_;
    std::unique_ptr<ScreenStack> stack_;
    double accumulator_ = 0;
};

}  // namespace polar::game
