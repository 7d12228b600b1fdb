#include "polar/platform/window.h"

#include <SDL.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

#include "platform/sdl_input.h"

namespace polar::platform {

using detail::axisValue;

// The SDL side of a Window: the window itself and every gamepad opened, by instance id (which SDL
// never hands out twice, so a pad plugged out and in again is a new id).
struct Window::Native {
    SDL_Window* window = nullptr;
    std::map<SDL_JoystickID, SDL_GameController*> pads;

    // Opens the controller at `deviceIndex` unless it is open already; its id, or nothing.
    std::optional<SDL_JoystickID> openPad(int deviceIndex) {
        SDL_GameController* pad = SDL_GameControllerOpen(deviceIndex);
        if (!pad) return std::nullopt;
        const SDL_JoystickID id = SDL_JoystickInstanceID(SDL_GameControllerGetJoystick(pad));
        if (pads.count(id)) {
            SDL_GameControllerClose(pad);  // SDL counts opens: this one is released again
            return std::nullopt;
        }
        pads[id] = pad;
        return id;
    }
    SDL_GameController* pad(GamepadId id) const {
        auto it = pads.find(id);
        return it == pads.end() ? nullptr : it->second;
    }
    // The Event for an SDL event, or nothing for one a game never sees (or a pad already open).
    std::optional<Event> translate(const SDL_Event& e, const Window& owner);
};

namespace {

constexpr Uint32 kSubsystems = SDL_INIT_VIDEO | SDL_INIT_GAMECONTROLLER;

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

std::optional<Event> Window::Native::translate(const SDL_Event& e, const Window& owner) {
    switch (e.type) {
        case SDL_QUIT:
            return QuitRequested{};
        case SDL_KEYDOWN:
            return KeyPressed{detail::keyFromKeycode(e.key.keysym.sym),
                              detail::keyFromScancode(e.key.keysym.scancode),
                              detail::modsFrom(e.key.keysym.mod), e.key.repeat != 0};
        case SDL_KEYUP:
            return KeyReleased{detail::keyFromKeycode(e.key.keysym.sym),
                               detail::keyFromScancode(e.key.keysym.scancode),
                               detail::modsFrom(e.key.keysym.mod)};
        case SDL_TEXTINPUT:
            return TextEntered{e.text.text};
        case SDL_MOUSEBUTTONDOWN:
        case SDL_MOUSEBUTTONUP: {
            const std::optional<MouseButton> button = detail::mouseButtonFrom(e.button.button);
            if (!button) return std::nullopt;
            const Vec2 at = owner.windowToCanvas(e.button.x, e.button.y);
            if (e.type == SDL_MOUSEBUTTONDOWN) return MouseButtonPressed{*button, e.button.x, e.button.y, at};
            return MouseButtonReleased{*button, e.button.x, e.button.y, at};
        }
        case SDL_MOUSEMOTION:
            return MouseMoved{e.motion.x, e.motion.y, owner.windowToCanvas(e.motion.x, e.motion.y)};
        case SDL_MOUSEWHEEL: {
            const double flip = e.wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -1.0 : 1.0;
            return MouseWheelScrolled{flip * e.wheel.preciseX, flip * e.wheel.preciseY};
        }
        case SDL_CONTROLLERDEVICEADDED: {
            const std::optional<SDL_JoystickID> id = openPad(e.cdevice.which);
            if (!id) return std::nullopt;
            const char* name = SDL_GameControllerName(pads[*id]);
            return GamepadConnected{*id, name ? name : ""};
        }
        case SDL_CONTROLLERDEVICEREMOVED: {
            auto it = pads.find(e.cdevice.which);
            if (it == pads.end()) return std::nullopt;
            SDL_GameControllerClose(it->second);
            pads.erase(it);
            return GamepadDisconnected{e.cdevice.which};
        }
        case SDL_CONTROLLERBUTTONDOWN:
        case SDL_CONTROLLERBUTTONUP: {
            const std::optional<GamepadButton> button = detail::gamepadButtonFrom(e.cbutton.button);
            if (!button) return std::nullopt;
            if (e.type == SDL_CONTROLLERBUTTONDOWN) return GamepadButtonPressed{e.cbutton.which, *button};
            return GamepadButtonReleased{e.cbutton.which, *button};
        }
        case SDL_CONTROLLERAXISMOTION: {
            const std::optional<GamepadAxis> axis = detail::gamepadAxisFrom(e.caxis.axis);
            if (!axis) return std::nullopt;
            return GamepadAxisMoved{e.caxis.which, *axis, axisValue(e.caxis.value)};
        }
        case SDL_WINDOWEVENT:
            if (e.window.event == SDL_WINDOWEVENT_SIZE_CHANGED)
                return WindowResized{e.window.data1, e.window.data2};
            if (e.window.event == SDL_WINDOWEVENT_FOCUS_LOST) return WindowFocusLost{};
            return std::nullopt;
        default:
            return std::nullopt;
    }
}

Window::Window(std::unique_ptr<Native> native) : native_(std::move(native)) {}

Result<std::unique_ptr<Window>> Window::open(const WindowSettings& settings) {
    // The present path (README.md): the window surface is SDL's own shared-memory framebuffer, not
    // a texture drawn through OpenGL, which on a software OpenGL costs three times the CPU. A low
    // priority, so SDL_FRAMEBUFFER_ACCELERATION=1 in the environment still picks the GPU path.
    SDL_SetHintWithPriority(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0", SDL_HINT_DEFAULT);
    if (SDL_InitSubSystem(kSubsystems) != 0) return windowError("cannot start SDL video");
    if (SDL_GetNumVideoDisplays() < 1) {
        Error error = windowError("no display to open a window on");
        SDL_QuitSubSystem(kSubsystems);
        return error;
    }
    const int scale = std::max(settings.scale, 1);
    const int width = settings.width > 0 ? settings.width : settings.canvasWidth * scale;
    const int height = settings.height > 0 ? settings.height : settings.canvasHeight * scale;
    const bool placed = settings.x && settings.y;
    SDL_Window* window =
        SDL_CreateWindow(settings.title.c_str(), placed ? *settings.x : SDL_WINDOWPOS_CENTERED,
                         placed ? *settings.y : SDL_WINDOWPOS_CENTERED, width, height,
                         SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI);
    if (!window) {
        Error error = windowError("cannot open a window");
        SDL_QuitSubSystem(kSubsystems);
        return error;
    }
    SDL_SetWindowMinimumSize(window, std::min(settings.canvasWidth, 160),
                             std::min(settings.canvasHeight, 90));
    auto native = std::make_unique<Native>();
    native->window = window;
    // Pads plugged in before the start; SDL also queues a "device added" for each (ignored then).
    for (int i = 0; i < SDL_NumJoysticks(); ++i)
        if (SDL_IsGameController(i)) native->openPad(i);
    std::unique_ptr<Window> opened(new Window(std::move(native)));
    opened->fullscreenKeys_ = settings.fullscreenKeys;
    opened->integerScaling_ = settings.integerScaling;
    opened->windowed_ = opened->windowedBounds();
    if (settings.fullscreen) opened->toggleFullscreen();
    opened->lastCanvasWidth_ = settings.canvasWidth;
    opened->lastCanvasHeight_ = settings.canvasHeight;
    return opened;
}

std::optional<Error> Window::displayProblem() {
    // With no X11 or Wayland, SDL quietly falls back to an invisible driver, and a window there
    // would run forever unseen; those count only when asked for by name.
    const char* asked = SDL_getenv("SDL_VIDEODRIVER");
    if (!asked && !SDL_getenv("DISPLAY") && !SDL_getenv("WAYLAND_DISPLAY"))
        return Error{"", 0, 0, "neither DISPLAY nor WAYLAND_DISPLAY is set", ""};
    if (SDL_InitSubSystem(kSubsystems) != 0) return Error{"", 0, 0, SDL_GetError(), ""};
    const std::string driver = SDL_GetCurrentVideoDriver() ? SDL_GetCurrentVideoDriver() : "";
    const bool invisible = driver == "offscreen" || driver == "dummy";
    std::optional<Error> problem;
    if ((invisible && !(asked && driver == asked)) || SDL_GetNumVideoDisplays() < 1)
        problem =
            Error{"", 0, 0, "no X11 or Wayland display (SDL chose the \"" + driver + "\" video driver)", ""};
    SDL_QuitSubSystem(kSubsystems);
    return problem;
}

Window::~Window() {
    for (auto& [id, pad] : native_->pads) SDL_GameControllerClose(pad);
    SDL_DestroyWindow(native_->window);
    SDL_QuitSubSystem(kSubsystems);
}

std::optional<Event> Window::pollEvent() {
    SDL_Event event;
    while (SDL_PollEvent(&event)) {
        std::optional<Event> translated = native_->translate(event, *this);
        if (!translated) continue;
        if (fullscreenKeys_ && handleFullscreenKeys(*translated)) continue;
        return translated;
    }
    return std::nullopt;
}

bool Window::handleFullscreenKeys(const Event& event) {
    const auto* press = std::get_if<KeyPressed>(&event);
    if (!press || press->repeat) return false;
    const bool altEnter =
        (press->key == Key::Enter || press->key == Key::KeypadEnter) && (press->mods & kModAlt);
    if (press->key != Key::F11 && !altEnter) return false;
    toggleFullscreen();
    return true;
}

Window::Bounds Window::windowedBounds() const {
    if (fullscreen()) return windowed_;
    Bounds b;
    SDL_GetWindowPosition(native_->window, &b.x, &b.y);
    SDL_GetWindowSize(native_->window, &b.width, &b.height);
    return b;
}

void Window::toggleFullscreen() {
    if (!fullscreen()) windowed_ = windowedBounds();
    SDL_SetWindowFullscreen(native_->window, fullscreen() ? 0 : SDL_WINDOW_FULLSCREEN_DESKTOP);
}

bool Window::fullscreen() const {
    return (SDL_GetWindowFlags(native_->window) & SDL_WINDOW_FULLSCREEN_DESKTOP) != 0;
}

void Window::setSize(int width, int height) {
    SDL_SetWindowSize(native_->window, width, height);
}

int Window::width() const {
    int w = 0;
    SDL_GetWindowSizeInPixels(native_->window, &w, nullptr);
    return w;
}

int Window::height() const {
    int h = 0;
    SDL_GetWindowSizeInPixels(native_->window, nullptr, &h);
    return h;
}

void Window::setTitle(const std::string& title) {
    SDL_SetWindowTitle(native_->window, title.c_str());
}

bool Window::keyHeld(Key position) const {
    const SDL_Scancode code = detail::scancodeOf(position);
    return code != SDL_SCANCODE_UNKNOWN && SDL_GetKeyboardState(nullptr)[code] != 0;
}

std::vector<GamepadId> Window::gamepads() const {
    std::vector<GamepadId> ids;
    for (const auto& [id, pad] : native_->pads) ids.push_back(id);
    return ids;
}

bool Window::gamepadButton(GamepadId pad, GamepadButton button) const {
    SDL_GameController* p = native_->pad(pad);
    return p && SDL_GameControllerGetButton(p, detail::sdlButtonOf(button)) != 0;
}

double Window::gamepadAxis(GamepadId pad, GamepadAxis axis) const {
    SDL_GameController* p = native_->pad(pad);
    return p ? axisValue(SDL_GameControllerGetAxis(p, detail::sdlAxisOf(axis))) : 0.0;
}

void Window::present(const render::Canvas& canvas) {
    SDL_Surface* target = SDL_GetWindowSurface(native_->window);
    if (!target) return;  // minimised, or the window system refused: nothing to show
    const Placement p = fit(canvas.width(), canvas.height(), target->w, target->h, integerScaling_);
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
    SDL_UpdateWindowSurface(native_->window);
}

render::Canvas Window::capture() const {
    SDL_Surface* shown = SDL_GetWindowSurface(native_->window);
    if (!shown || shown->w <= 0 || shown->h <= 0) return render::Canvas(1, 1);
    render::Canvas canvas(shown->w, shown->h);
    // SDL converts from whatever the window's format is into the canvas's ARGB8888.
    SDL_ConvertPixels(shown->w, shown->h, shown->format->format, shown->pixels, shown->pitch,
                      SDL_PIXELFORMAT_ARGB8888, canvas.row(0), canvas.pitch());
    for (int y = 0; y < canvas.height(); ++y)
        for (int x = 0; x < canvas.width(); ++x) canvas.row(y)[x] |= 0xFF000000u;
    return canvas;
}

}  // namespace polar::platform
