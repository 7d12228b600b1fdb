#include "display.h"

#include <SDL.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

namespace polar::game {

namespace {

Error windowError(const std::string& what) {
    Error e;
    e.what = what + " (" + SDL_GetError() + ")";
    e.expected = "a graphical display (X11 or Wayland)";
    return e;
}

// True when the surface stores pixels as 32-bit 0x??RRGGBB, the Canvas layout (alpha ignored).
bool sameLayoutAsCanvas(const SDL_Surface* s) {
    const SDL_PixelFormat* f = s->format;
    return f->BytesPerPixel == 4 && f->Rmask == 0x00FF0000u && f->Gmask == 0x0000FF00u &&
           f->Bmask == 0x000000FFu;
}

}  // namespace

Result<std::unique_ptr<Display>> Display::open(const std::string& title, int canvasWidth, int canvasHeight,
                                               int scale) {
    if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) return windowError("cannot start SDL video");
    SDL_Window* window = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                                          canvasWidth * std::max(scale, 1), canvasHeight * std::max(scale, 1),
                                          SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI);
    if (!window) {
        Error error = windowError("cannot open a window");
        SDL_QuitSubSystem(SDL_INIT_VIDEO);
        return error;
    }
    SDL_SetWindowMinimumSize(window, std::min(canvasWidth, 160), std::min(canvasHeight, 90));
    std::unique_ptr<Display> display(new Display(window));
    display->lastCanvasWidth_ = canvasWidth;
    display->lastCanvasHeight_ = canvasHeight;
    return display;
}

Display::~Display() {
    SDL_DestroyWindow(window_);
    SDL_QuitSubSystem(SDL_INIT_VIDEO);
}

bool Display::handleEvent(const SDL_Event& event) {
    if (event.type != SDL_KEYDOWN || event.key.repeat) return false;
    const SDL_Keycode key = event.key.keysym.sym;
    const bool altEnter = (key == SDLK_RETURN || key == SDLK_KP_ENTER) && (event.key.keysym.mod & KMOD_ALT);
    if (key != SDLK_F11 && !altEnter) return false;
    toggleFullscreen();
    return true;
}

void Display::toggleFullscreen() {
    SDL_SetWindowFullscreen(window_, fullscreen() ? 0 : SDL_WINDOW_FULLSCREEN_DESKTOP);
}

bool Display::fullscreen() const {
    return (SDL_GetWindowFlags(window_) & SDL_WINDOW_FULLSCREEN_DESKTOP) != 0;
}

Display::Placement Display::fit(int canvasWidth, int canvasHeight, int windowWidth, int windowHeight) {
    if (canvasWidth <= 0 || canvasHeight <= 0 || windowWidth <= 0 || windowHeight <= 0) return {};
    const double f = std::min(double(windowWidth) / canvasWidth, double(windowHeight) / canvasHeight);
    const double k = std::floor(f);
    Placement p;
    if (k >= 1.0 && k >= 0.8 * f) {
        p.width = canvasWidth * int(k);
        p.height = canvasHeight * int(k);
    } else {
        p.width = std::clamp(int(std::floor(canvasWidth * f)), 1, windowWidth);
        p.height = std::clamp(int(std::floor(canvasHeight * f)), 1, windowHeight);
    }
    p.x = (windowWidth - p.width) / 2;
    p.y = (windowHeight - p.height) / 2;
    return p;
}

void Display::present(const render::Canvas& canvas) {
    SDL_Surface* target = SDL_GetWindowSurface(window_);
    if (!target) return;  // minimised, or the window system refused: nothing to show
    const Placement p = fit(canvas.width(), canvas.height(), target->w, target->h);
    last_ = p;
    lastCanvasWidth_ = canvas.width();
    lastCanvasHeight_ = canvas.height();
    if (p.width == 0) return;

    // Black borders around the picture.
    const Uint32 black = SDL_MapRGB(target->format, 0, 0, 0);
    const SDL_Rect borders[4] = {{0, 0, target->w, p.y},
                                 {0, p.y + p.height, target->w, target->h - p.y - p.height},
                                 {0, p.y, p.x, p.height},
                                 {p.x + p.width, p.y, target->w - p.x - p.width, p.height}};
    for (const SDL_Rect& r : borders)
        if (r.w > 0 && r.h > 0) SDL_FillRect(target, &r, black);

    if (!sameLayoutAsCanvas(target)) {
        // An unusual window format: let SDL convert while it scales, from a surface over the canvas.
        SDL_Surface* source =
            SDL_CreateRGBSurfaceWithFormatFrom(const_cast<std::uint32_t*>(canvas.row(0)), canvas.width(),
                                               canvas.height(), 32, canvas.pitch(), SDL_PIXELFORMAT_ARGB8888);
        SDL_Rect dst{p.x, p.y, p.width, p.height};
        if (source) SDL_BlitScaled(source, nullptr, target, &dst);
        SDL_FreeSurface(source);
    } else {
        // Nearest neighbour: window pixel (x, y) of the picture shows canvas pixel
        // (⌊x·w/W⌋, ⌊y·h/H⌋), which for a whole factor k is (⌊x/k⌋, ⌊y/k⌋).
        if (SDL_MUSTLOCK(target)) SDL_LockSurface(target);
        std::vector<int> sourceColumn(std::size_t(p.width));
        for (int x = 0; x < p.width; ++x) sourceColumn[x] = int(std::int64_t(x) * canvas.width() / p.width);
        int previousSourceRow = -1;
        std::uint32_t* previousRow = nullptr;
        for (int y = 0; y < p.height; ++y) {
            const int sourceRow = int(std::int64_t(y) * canvas.height() / p.height);
            auto* out = reinterpret_cast<std::uint32_t*>(static_cast<std::uint8_t*>(target->pixels) +
                                                         std::ptrdiff_t(p.y + y) * target->pitch) +
                        p.x;
            if (sourceRow == previousSourceRow) {
                std::memcpy(out, previousRow, std::size_t(p.width) * 4);  // a repeated row
            } else {
                const std::uint32_t* in = canvas.row(sourceRow);
                for (int x = 0; x < p.width; ++x) out[x] = in[sourceColumn[x]] | 0xFF000000u;
            }
            previousSourceRow = sourceRow;
            previousRow = out;
        }
        if (SDL_MUSTLOCK(target)) SDL_UnlockSurface(target);
    }
    SDL_UpdateWindowSurface(window_);
}

Vec2 Display::windowToCanvas(int x, int y) const {
    if (last_.width == 0 || last_.height == 0) return {0, 0};
    return {(x + 0.5 - last_.x) * lastCanvasWidth_ / last_.width,
            (y + 0.5 - last_.y) * lastCanvasHeight_ / last_.height};
}

}  // namespace polar::game
