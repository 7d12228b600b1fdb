#include "polar/platform/window.h"

#include <emscripten.h>
#include <emscripten/html5.h>

#include <array>
#include <cstring>
#include <deque>
#include <string_view>

// The page's canvas as a Window: the canvas's own size is the picture's, and the page scales it
// with CSS (whole pixels, image-rendering: pixelated), so a present is one putImageData.

EM_JS(void, polarWebPut, (const void* rgba, int width, int height), {
    var canvas = Module['canvas'];
    if (!canvas) return;
    if (canvas.width != width || canvas.height != height) {
        canvas.width = width;
        canvas.height = height;
    }
    if (!Module.polarContext) Module.polarContext = canvas.getContext('2d');
    var pixels = new Uint8ClampedArray(HEAPU8.buffer, rgba, width * height * 4);
    Module.polarContext.putImageData(new ImageData(pixels, width, height), 0, 0);
    if (Module['firstFrameMs'] == undefined) Module['firstFrameMs'] = performance.now();
});

// The page's own fullscreen (its stage, with the border), else the canvas alone.
EM_JS(void, polarWebToggleFullscreen, (), {
    if (Module['toggleFullscreen']) return Module['toggleFullscreen']();
    if (document.fullscreenElement)
        document.exitFullscreen();
    else if (Module['canvas'])
        Module['canvas'].requestFullscreen();
});

EM_JS(int, polarWebFullscreen, (), { return document.fullscreenElement ? 1 : 0; });

EM_JS(void, polarWebSetTitle, (const char* title), { document.title = UTF8ToString(title); });

// The canvas's pointer events (a mouse, a pen, or the first finger on it: Pointer Events give all
// three) and wheel, and the page hidden, frozen or left, each as a call of `pointer`, `wheel` or
// `away` with `self`. A pointer is (kind 0 down, 1 up, 2 move; DOM button; CSS pixels from the
// canvas's top left; the canvas's CSS size). Module.polarAway lets the page report a leave too.
EM_JS(void, polarWebListen, (void* self, std::intptr_t pointer, std::intptr_t wheel, std::intptr_t away), {
    var canvas = Module['canvas'];
    var entry = function(f) {
        return (typeof getWasmTableEntry != 'undefined') ? getWasmTableEntry(f) : wasmTable.get(f);
    };
    var onPointer = entry(pointer), onWheel = entry(wheel), onAway = entry(away);
    var send = function(kind) {
        return function(e) {
            if (!e.isPrimary) return;
            var r = canvas.getBoundingClientRect();
            if (kind == 0) {
                try {
                    canvas.setPointerCapture(e.pointerId);
                } catch (error) {
                }
                canvas.focus({preventScroll : true});
            }
            onPointer(self, kind, e.button, e.clientX - r.left, e.clientY - r.top, r.width, r.height);
            if (kind != 2) e.preventDefault();
        };
    };
    var notches = function(delta, mode) {
        return mode == 0 ? delta / 100 : mode == 1 ? delta / 3 : delta;
    };
    var listeners =
        [[canvas, 'pointerdown', send(0)], [canvas, 'pointerup', send(1)], [canvas, 'pointermove', send(2)],
         [canvas, 'wheel',
          function(e) {
              onWheel(self, notches(e.deltaX, e.deltaMode), -notches(e.deltaY, e.deltaMode));
              e.preventDefault();
          }],
         [canvas, 'contextmenu', function(e) { e.preventDefault(); }],
         [document, 'visibilitychange',
          function() {
              if (document.hidden) onAway(self);
          }],
         [document, 'freeze', function() { onAway(self); }],
         [window, 'pagehide', function() { onAway(self); }]];
    listeners.forEach(function(l) { l[0].addEventListener(l[1], l[2], {passive : false}); });
    Module['polarAway'] = function() {
        onAway(self);
    };
    Module.polarListeners = Module.polarListeners || {};
    Module.polarListeners[self] = listeners;
});

EM_JS(void, polarWebUnlisten, (void* self), {
    var listeners = (Module.polarListeners || {})[self] || [];
    listeners.forEach(function(l) { l[0].removeEventListener(l[1], l[2]); });
    delete Module.polarListeners[self];
});

namespace polar::platform {
namespace {

// KeyboardEvent.code names (the key's place, by its US-layout name) and the Key each is.
struct CodeName {
    std::string_view code;
    Key key;
};
// clang-format off
constexpr CodeName kCodes[] = {
    {"Space", Key::Space}, {"Enter", Key::Enter}, {"NumpadEnter", Key::KeypadEnter},
    {"Escape", Key::Escape}, {"Backspace", Key::Backspace}, {"Tab", Key::Tab}, {"Delete", Key::Delete},
    {"Insert", Key::Insert}, {"Home", Key::Home}, {"End", Key::End}, {"PageUp", Key::PageUp},
    {"PageDown", Key::PageDown}, {"ArrowLeft", Key::Left}, {"ArrowRight", Key::Right},
    {"ArrowUp", Key::Up}, {"ArrowDown", Key::Down}, {"ShiftLeft", Key::LeftShift},
    {"ShiftRight", Key::RightShift}, {"ControlLeft", Key::LeftCtrl}, {"ControlRight", Key::RightCtrl},
    {"AltLeft", Key::LeftAlt}, {"AltRight", Key::RightAlt}, {"Minus", Key::Minus},
    {"Equal", Key::Equals}, {"Comma", Key::Comma}, {"Period", Key::Period}, {"Slash", Key::Slash},
    {"F1", Key::F1}, {"F2", Key::F2}, {"F3", Key::F3}, {"F4", Key::F4}, {"F5", Key::F5},
    {"F6", Key::F6}, {"F7", Key::F7}, {"F8", Key::F8}, {"F9", Key::F9}, {"F10", Key::F10},
    {"F11", Key::F11}, {"F12", Key::F12},
};
// clang-format on

// The key at a place: "KeyA"…"KeyZ", "Digit0"…"Digit9" and the names above.
Key keyOfCode(std::string_view code) {
    if (code.size() == 4 && code.substr(0, 3) == "Key" && code[3] >= 'A' && code[3] <= 'Z')
        return static_cast<Key>(static_cast<int>(Key::A) + (code[3] - 'A'));
    if (code.size() == 6 && code.substr(0, 5) == "Digit" && code[5] >= '0' && code[5] <= '9')
        return static_cast<Key>(static_cast<int>(Key::Num0) + (code[5] - '0'));
    for (const CodeName& c : kCodes)
        if (c.code == code) return c.key;
    return Key::Unknown;
}

// What the layout makes of the key (KeyboardEvent.key): a printed character, or a named key
// ("ArrowLeft", "Enter", …, which share their names with the codes); a modifier by its place.
Key keyOfKey(std::string_view key, Key position) {
    if (key.size() == 1) {
        char c = key[0];
        if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
        if (c >= 'A' && c <= 'Z') return static_cast<Key>(static_cast<int>(Key::A) + (c - 'A'));
        if (c >= '0' && c <= '9') return static_cast<Key>(static_cast<int>(Key::Num0) + (c - '0'));
        switch (c) {
            case ' ':
                return Key::Space;
            case '-':
                return Key::Minus;
            case '=':
                return Key::Equals;
            case ',':
                return Key::Comma;
            case '.':
                return Key::Period;
            case '/':
                return Key::Slash;
            default:
                return Key::Unknown;
        }
    }
    if (key == "Shift" || key == "Control" || key == "Alt") return position;
    if (key == "Enter" && position == Key::KeypadEnter) return position;
    return keyOfCode(key);
}

std::uint8_t modsOf(const EmscriptenKeyboardEvent& e) {
    return static_cast<std::uint8_t>((e.shiftKey ? kModShift : 0) | (e.ctrlKey ? kModCtrl : 0) |
                                     (e.altKey ? kModAlt : 0) | (e.metaKey ? kModGui : 0));
}

constexpr int kButtons = static_cast<int>(GamepadButton::Count);
constexpr int kAxes = static_cast<int>(GamepadAxis::Count);

// The Gamepad API's standard mapping: button index of each GamepadButton (16 is the guide).
constexpr std::array<int, kButtons> kStandardButton = {0, 1, 2, 3, 8, 16, 9, 10, 11, 4, 5, 12, 13, 14, 15};

}  // namespace

struct Window::Native {
    struct Pad {
        GamepadId id = 0;
        long index = -1;  // the browser's gamepad index
        std::array<bool, kButtons> buttons{};
        std::array<double, kAxes> axes{};
    };
    std::deque<Event> queue;
    std::array<bool, static_cast<std::size_t>(Key::Count)> held{};
    std::vector<Pad> pads;  // oldest first
    GamepadId nextPad = 1;
    bool fullscreenKeys = true;
    std::vector<std::uint32_t> rgba;  // the last present, as the canvas's RGBA bytes
    int lastWidth = 0, lastHeight = 0;

    const Pad* pad(GamepadId id) const {
        for (const Pad& p : pads)
            if (p.id == id) return &p;
        return nullptr;
    }

    // Key events: held keys, the queue, fullscreen at once (a browser allows it only inside the
    // handler of the player's own key press). Returns whether the page should not see it too.
    static EM_BOOL onKey(int type, const EmscriptenKeyboardEvent* e, void* data) {
        auto& self = *static_cast<Native*>(data);
        const Key position = keyOfCode(e->code);
        const Key key = keyOfKey(e->key, position);
        const std::uint8_t mods = modsOf(*e);
        if (type == EMSCRIPTEN_EVENT_KEYDOWN) {
            const bool fullscreenKey =
                position == Key::F11 || ((mods & kModAlt) && (key == Key::Enter || key == Key::KeypadEnter));
            if (self.fullscreenKeys && fullscreenKey) {
                if (!e->repeat) polarWebToggleFullscreen();
                return EM_TRUE;
            }
            if (position != Key::Unknown) self.held[static_cast<std::size_t>(position)] = true;
            self.queue.push_back(KeyPressed{key, position, mods, e->repeat != 0});
            if (std::strlen(e->key) == 1 && !(mods & (kModCtrl | kModGui)))
                self.queue.push_back(TextEntered{e->key});
        } else {
            if (position != Key::Unknown) self.held[static_cast<std::size_t>(position)] = false;
            self.queue.push_back(KeyReleased{key, position, mods});
        }
        // The browser keeps its own keys (reload, developer tools, shortcuts); the game's keys do
        // not scroll the page.
        if (mods & (kModCtrl | kModGui)) return EM_FALSE;
        return position == Key::F5 || position == Key::F12 ? EM_FALSE : EM_TRUE;
    }

    // A focus lost while keys are held never sends their key-up: they are let go here, and the
    // game hears that the player looked away.
    void away() {
        for (std::size_t k = 0; k < held.size(); ++k) {
            if (!held[k]) continue;
            held[k] = false;
            queue.push_back(KeyReleased{static_cast<Key>(k), static_cast<Key>(k), kModNone});
        }
        queue.push_back(WindowFocusLost{});
    }
    // The blur callback listens on the window in the capture phase, so it also hears every
    // element of the page lose the focus: a tap on the legend or a button moves the focus from
    // the canvas to the page, which is no looking away. Only the window's own blur counts.
    static EM_BOOL onBlur(int, const EmscriptenFocusEvent* e, void* data) {
        if (std::strcmp(e->nodeName, "#window") == 0) static_cast<Native*>(data)->away();
        return EM_FALSE;
    }
    static void onAway(void* data) { static_cast<Native*>(data)->away(); }

    // A pointer on the canvas as the mouse: its point in CSS pixels, and on the last canvas shown.
    static void onPointer(void* data, int kind, int button, double x, double y, double width, double height) {
        auto& self = *static_cast<Native*>(data);
        const Vec2 at = width > 0 && height > 0
                            ? Vec2(x * self.lastWidth / width, y * self.lastHeight / height)
                            : Vec2(0, 0);
        const int wx = static_cast<int>(x), wy = static_cast<int>(y);
        if (kind == 2) {
            self.queue.push_back(MouseMoved{wx, wy, at});
            return;
        }
        if (button < 0 || button > 4) return;
        // DOM buttons: 0 left, 1 middle, 2 right, 3 back, 4 forward.
        constexpr MouseButton kButtons[] = {MouseButton::Left, MouseButton::Middle, MouseButton::Right,
                                            MouseButton::X1, MouseButton::X2};
        const MouseButton which = kButtons[button];
        if (kind == 0)
            self.queue.push_back(MouseButtonPressed{which, wx, wy, at});
        else
            self.queue.push_back(MouseButtonReleased{which, wx, wy, at});
    }
    static void onWheel(void* data, double dx, double dy) {
        static_cast<Native*>(data)->queue.push_back(MouseWheelScrolled{dx, dy});
    }

    // The Gamepad API is polled: each frame's state against the last one gives the events.
    void pollGamepads() {
        if (emscripten_sample_gamepad_data() != EMSCRIPTEN_RESULT_SUCCESS) return;
        const int count = emscripten_get_num_gamepads();
        std::vector<bool> seen(pads.size(), false);
        for (int i = 0; i < count; ++i) {
            EmscriptenGamepadEvent state;
            if (emscripten_get_gamepad_status(i, &state) != EMSCRIPTEN_RESULT_SUCCESS || !state.connected)
                continue;
            std::size_t at = 0;
            while (at < pads.size() && pads[at].index != state.index) ++at;
            if (at == pads.size()) {
                pads.push_back(Pad{nextPad++, state.index, {}, {}});
                seen.push_back(false);
                queue.push_back(GamepadConnected{pads.back().id, state.id});
            }
            seen[at] = true;
            Pad& pad = pads[at];
            for (int b = 0; b < kButtons; ++b) {
                const int index = kStandardButton[static_cast<std::size_t>(b)];
                const bool down = index < state.numButtons && state.digitalButton[index];
                if (down == pad.buttons[static_cast<std::size_t>(b)]) continue;
                pad.buttons[static_cast<std::size_t>(b)] = down;
                const auto button = static_cast<GamepadButton>(b);
                if (down)
                    queue.push_back(GamepadButtonPressed{pad.id, button});
                else
                    queue.push_back(GamepadButtonReleased{pad.id, button});
            }
            // Sticks are axes 0–3 (x right, y down); the triggers are the analog buttons 6 and 7.
            const std::array<double, kAxes> axes = {state.numAxes > 0 ? state.axis[0] : 0.0,
                                                    state.numAxes > 1 ? state.axis[1] : 0.0,
                                                    state.numAxes > 2 ? state.axis[2] : 0.0,
                                                    state.numAxes > 3 ? state.axis[3] : 0.0,
                                                    state.numButtons > 6 ? state.analogButton[6] : 0.0,
                                                    state.numButtons > 7 ? state.analogButton[7] : 0.0};
            for (int a = 0; a < kAxes; ++a) {
                if (axes[static_cast<std::size_t>(a)] == pad.axes[static_cast<std::size_t>(a)]) continue;
                pad.axes[static_cast<std::size_t>(a)] = axes[static_cast<std::size_t>(a)];
                queue.push_back(
                    GamepadAxisMoved{pad.id, static_cast<GamepadAxis>(a), axes[static_cast<std::size_t>(a)]});
            }
        }
        for (std::size_t i = seen.size(); i-- > 0;) {
            if (seen[i]) continue;
            queue.push_back(GamepadDisconnected{pads[i].id});
            pads.erase(pads.begin() + static_cast<std::ptrdiff_t>(i));
        }
    }
};

Window::Window(std::unique_ptr<Native> native) : native_(std::move(native)) {}

Window::~Window() {
    emscripten_set_keydown_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, nullptr, EM_TRUE, nullptr);
    emscripten_set_keyup_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, nullptr, EM_TRUE, nullptr);
    emscripten_set_blur_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, nullptr, EM_TRUE, nullptr);
    polarWebUnlisten(native_.get());
}

Result<std::unique_ptr<Window>> Window::open(const WindowSettings& settings) {
    auto native = std::make_unique<Native>();
    native->fullscreenKeys = settings.fullscreenKeys;
    Native* self = native.get();
    emscripten_set_keydown_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, self, EM_TRUE, Native::onKey);
    emscripten_set_keyup_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, self, EM_TRUE, Native::onKey);
    emscripten_set_blur_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, self, EM_TRUE, Native::onBlur);
    polarWebListen(self, reinterpret_cast<std::intptr_t>(&Native::onPointer),
                   reinterpret_cast<std::intptr_t>(&Native::onWheel),
                   reinterpret_cast<std::intptr_t>(&Native::onAway));
    std::unique_ptr<Window> window(new Window(std::move(native)));
    window->fullscreenKeys_ = settings.fullscreenKeys;
    window->setTitle(settings.title);
    return window;
}

std::optional<Error> Window::displayProblem() {
    return std::nullopt;  // a page is always seen
}

std::optional<Event> Window::pollEvent() {
    if (native_->queue.empty()) native_->pollGamepads();
    if (native_->queue.empty()) return std::nullopt;
    Event event = std::move(native_->queue.front());
    native_->queue.pop_front();
    return event;
}

bool Window::handleFullscreenKeys(const Event& event) {
    const auto* press = std::get_if<KeyPressed>(&event);
    if (!press || press->repeat) return false;
    const bool altEnter =
        (press->mods & kModAlt) && (press->key == Key::Enter || press->key == Key::KeypadEnter);
    if (press->position != Key::F11 && !altEnter) return false;
    toggleFullscreen();
    return true;
}

void Window::present(const render::Canvas& canvas) {
    const int w = canvas.width(), h = canvas.height();
    native_->rgba.resize(static_cast<std::size_t>(w) * h);
    // Canvas pixels are 0xAARRGGBB words; ImageData wants the bytes R, G, B, A (little-endian:
    // the word 0xAABBGGRR), opaque as on the desktop.
    std::uint32_t* out = native_->rgba.data();
    for (int y = 0; y < h; ++y) {
        const std::uint32_t* in = canvas.row(y);
        for (int x = 0; x < w; ++x) {
            const std::uint32_t v = in[x];
            *out++ = 0xFF000000u | ((v & 0xFFu) << 16) | (v & 0xFF00u) | ((v >> 16) & 0xFFu);
        }
    }
    polarWebPut(native_->rgba.data(), w, h);
    native_->lastWidth = w;
    native_->lastHeight = h;
    lastCanvasWidth_ = w;
    lastCanvasHeight_ = h;
    last_ = fit(w, h, width(), height(), integerScaling_);
}

void Window::toggleFullscreen() {
    polarWebToggleFullscreen();
}

// The page places and sizes the canvas: the bounds are the canvas's, at the page's origin.
Window::Bounds Window::windowedBounds() const {
    return {0, 0, width(), height()};
}

bool Window::fullscreen() const {
    return polarWebFullscreen() != 0;
}

void Window::setSize(int, int) {}  // the page lays the canvas out

int Window::width() const {
    double w = 0, h = 0;
    emscripten_get_element_css_size("#canvas", &w, &h);
    return static_cast<int>(w);
}

int Window::height() const {
    double w = 0, h = 0;
    emscripten_get_element_css_size("#canvas", &w, &h);
    return static_cast<int>(h);
}

void Window::setTitle(const std::string& title) {
    polarWebSetTitle(title.c_str());
}

bool Window::keyHeld(Key position) const {
    return position != Key::Unknown && position < Key::Count &&
           native_->held[static_cast<std::size_t>(position)];
}

std::vector<GamepadId> Window::gamepads() const {
    std::vector<GamepadId> ids;
    for (const Native::Pad& p : native_->pads) ids.push_back(p.id);
    return ids;
}

bool Window::gamepadButton(GamepadId pad, GamepadButton button) const {
    const Native::Pad* p = native_->pad(pad);
    return p && button < GamepadButton::Count && p->buttons[static_cast<std::size_t>(button)];
}

double Window::gamepadAxis(GamepadId pad, GamepadAxis axis) const {
    const Native::Pad* p = native_->pad(pad);
    return p && axis < GamepadAxis::Count ? p->axes[static_cast<std::size_t>(axis)] : 0.0;
}

render::Canvas Window::capture() const {
    const int w = std::max(1, native_->lastWidth), h = std::max(1, native_->lastHeight);
    render::Canvas canvas(w, h);
    if (native_->rgba.size() < static_cast<std::size_t>(w) * h) return canvas;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::uint32_t v = native_->rgba[static_cast<std::size_t>(y) * w + x];
            canvas.row(y)[x] = 0xFF000000u | ((v & 0xFFu) << 16) | (v & 0xFF00u) | ((v >> 16) & 0xFFu);
        }
    return canvas;
}

}  // namespace polar::platform
