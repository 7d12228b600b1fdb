#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "polar/error.h"
#include "polar/math.h"
#include "polar/platform/events.h"
#include "polar/render/canvas.h"

namespace polar::platform {

// How to open a Window. The canvas size is the picture's; the window opens at canvas·scale.
struct WindowSettings {
    std::string title = "Polar";
    int canvasWidth = 640;
    int canvasHeight = 360;
    int scale = 1;                      // the window's starting size in canvas pixels (at least 1)
    bool fullscreenKeys = true;         // pollEvent toggles fullscreen on F11 and Alt+Enter itself
    int width = 0, height = 0;          // the windowed size in pixels, when not 0 (instead of canvas·scale)
    std::optional<int> x = {}, y = {};  // the windowed position; nothing: centred
    bool fullscreen = false;            // open fullscreen (desktop-sized)
    bool integerScaling = false;        // scale by whole pixels only (see fit)
};

// A window that shows a Canvas, and the source of input events (keyboard, mouse, gamepads).
//
// Why not a GPU renderer? The software renderer draws every pixel itself into a Canvas, and the
// same Canvas is what headless runs save, so a screenshot is exactly what a player sees. All the
// window has to do is copy it onto the window's own surface, scaled: a whole number of times when
// that fills most of the window, otherwise by the largest factor that fits; either way centred,
// the aspect ratio kept, the borders black. Events arrive as plain structs (events.h), so a game
// reads its input without any platform header; gamepads are opened as they are plugged in.
class Window {
  public:
    // Where the canvas lands in the window, in window pixels.
    struct Placement {
        int x = 0, y = 0, width = 0, height = 0;
    };

    // Opens a resizable window (starting the video and gamepad subsystems). An Error when no
    // window can be opened, for example with no display at all.
    static Result<std::unique_ptr<Window>> open(const WindowSettings& settings);
    // Why a window would not be seen, or nothing when one would: neither DISPLAY nor
    // WAYLAND_DISPLAY is set, video cannot start, or it fell back to an invisible ("offscreen",
    // "dummy") driver that SDL_VIDEODRIVER did not ask for by name.
    static std::optional<Error> displayProblem();
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    // The next pending event, or nothing when the queue is empty. With settings.fullscreenKeys,
    // F11 and Alt+Enter are handled here (handleFullscreenKeys) and not returned.
    std::optional<Event> pollEvent();
    // Toggles fullscreen when `event` is an F11 or Alt+Enter press (not a repeat); true if it did.
    bool handleFullscreenKeys(const Event& event);
    // Shows the canvas in the window.
    void present(const render::Canvas& canvas);

    // Where the window is and how large, in screen coordinates, while windowed.
    struct Bounds {
        int x = 0, y = 0, width = 0, height = 0;
    };

    // Switches between a window and desktop-sized fullscreen.
    void toggleFullscreen();
    // The window's bounds when windowed: now, or the last ones before it went fullscreen.
    Bounds windowedBounds() const;
    // Scales the canvas by whole pixels only (true) or by fit's rule (false).
    void setIntegerScaling(bool integerOnly) { integerScaling_ = integerOnly; }
    // True while fullscreen.
    bool fullscreen() const;
    // Sets the window's size in pixels (not while fullscreen).
    void setSize(int width, int height);
    // The window's drawable size in pixels.
    int width() const;
    int height() const;
    void setTitle(const std::string& title);

    // True while the key at `position` (its US-layout name, see Key) is held down.
    bool keyHeld(Key position) const;
    // The gamepads connected now, oldest first.
    std::vector<GamepadId> gamepads() const;
    // True while `button` of `pad` is held (false for a pad that is gone).
    bool gamepadButton(GamepadId pad, GamepadButton button) const;
    // Where `axis` of `pad` is now (see GamepadAxis; 0 for a pad that is gone).
    double gamepadAxis(GamepadId pad, GamepadAxis axis) const;

    // The placement of a canvasWidth × canvasHeight canvas in a windowWidth × windowHeight window:
    // scale k = ⌊f⌋ for f = min(W/w, H/h) when k ≥ 1 and k ≥ 0.8·f (whole pixels, at most a fifth
    // of the room unused), otherwise f itself; centred. With `integerOnly`, k whenever k ≥ 1.
    static Placement fit(int canvasWidth, int canvasHeight, int windowWidth, int windowHeight,
                         bool integerOnly = false);
    // The canvas point under window pixel (x, y) of the last present (for pointers).
    Vec2 windowToCanvas(int x, int y) const;
    // What the window shows now, borders included, as an opaque canvas of its size (for tests
    // and screenshots of the whole window).
    render::Canvas capture() const;

  private:
    struct Native;  // the SDL window and the open gamepads
    explicit Window(std::unique_ptr<Native> native);

    std::unique_ptr<Native> native_;
    bool fullscreenKeys_ = true;
    bool integerScaling_ = false;
    Bounds windowed_;  // the bounds before the window went fullscreen
    Placement last_;
    int lastCanvasWidth_ = 1, lastCanvasHeight_ = 1;
};

}  // namespace polar::platform
