#pragma once
#include <memory>
#include <string>

#include "polar/error.h"
#include "polar/math.h"
#include "polar/render/canvas.h"

struct SDL_Window;
union SDL_Event;

namespace polar::game {

// The game's window: shows a Canvas scaled to fit, resizable, F11 or Alt+Enter for fullscreen.
//
// Why not SDL_Renderer? The renderer draws every pixel itself into a Canvas, and the same Canvas
// is what headless runs save, so a screenshot is exactly what a player sees. All the window has to
// do is copy it onto the window surface (SDL_GetWindowSurface / SDL_UpdateWindowSurface), scaled:
// a whole number of times when that fills most of the window, otherwise by the largest factor
// that fits; either way centred, the aspect ratio kept, the borders black.
class Display {
  public:
    // Where the canvas lands in the window, in window pixels.
    struct Placement {
        int x = 0, y = 0, width = 0, height = 0;
    };

    // Opens a resizable window of canvasWidth·scale × canvasHeight·scale pixels (starting SDL's
    // video subsystem). An Error when no window can be opened, for example with no display.
    static Result<std::unique_ptr<Display>> open(const std::string& title, int canvasWidth, int canvasHeight,
                                                 int scale = 1);
    ~Display();
    Display(const Display&) = delete;
    Display& operator=(const Display&) = delete;

    // Handles F11 and Alt+Enter (toggle fullscreen); true when the event was used.
    bool handleEvent(const SDL_Event& event);
    // Shows the canvas in the window.
    void present(const render::Canvas& canvas);
    // Switches between a window and desktop-sized fullscreen.
    void toggleFullscreen();
    // True while fullscreen.
    bool fullscreen() const;
    // The SDL window (for its title, icon or size).
    SDL_Window* window() const { return window_; }

    // The placement of a canvasWidth × canvasHeight canvas in a windowWidth × windowHeight window:
    // scale k = ⌊f⌋ for f = min(W/w, H/h) when k ≥ 1 and k ≥ 0.8·f (whole pixels, at most a fifth
    // of the room unused), otherwise f itself; centred.
    static Placement fit(int canvasWidth, int canvasHeight, int windowWidth, int windowHeight);
    // The canvas point under window pixel (x, y) of the last present (for pointers).
    Vec2 windowToCanvas(int x, int y) const;

  private:
    explicit Display(SDL_Window* window) : window_(window) {}

    SDL_Window* window_ = nullptr;
    Placement last_;
    int lastCanvasWidth_ = 1, lastCanvasHeight_ = 1;
};

}  // namespace polar::game
