#include "app/input/input.h"

#include <cmath>

namespace polar::game {
namespace {

using platform::GamepadAxis;
using platform::GamepadButton;
using platform::Key;

// Axis readings past which a stick counts as pushed and a trigger as pulled (of ±1).
constexpr double kStickDeadZone = 12000.0 / 32768.0;

void keyCommand(Input::Commands& commands, const platform::KeyPressed& press, const Bindings& bindings) {
    if (press.key == Key::Backspace) commands.erase = true;  // repeats too: hold to erase
    if (press.repeat) return;
    if (bindings.actionOfKey(press.position) == BoundAction::Pause) commands.pause = true;
    if (bindings.actionOfKey(press.position) == BoundAction::Fire) commands.fire = true;
    switch (press.key) {
        case Key::Escape:
            commands.back = commands.pause = true;
            break;
        case Key::Enter:
        case Key::KeypadEnter:
            if (!(press.mods & platform::kModAlt)) commands.confirm = true;  // Alt+Enter: fullscreen
            break;
        case Key::Space:
            commands.confirm = true;
            break;
        case Key::F1:
            commands.debugOverlay = true;
            break;
        case Key::F5:
            commands.reload = true;
            break;
        case Key::Up:
        case Key::W:
            commands.up = true;
            break;
        case Key::Down:
        case Key::S:
            commands.down = true;
            break;
        case Key::Left:
        case Key::A:
            commands.left = true;
            break;
        case Key::Right:
        case Key::D:
            commands.right = true;
            break;
        default:
            break;
    }
}

void gamepadCommand(Input::Commands& commands, GamepadButton button, const Bindings& bindings) {
    if (bindings.actionOfButton(button) == BoundAction::Pause) commands.pause = true;
    if (bindings.actionOfButton(button) == BoundAction::Fire) commands.fire = true;
    switch (button) {
        case GamepadButton::A:
            commands.confirm = true;
            break;
        case GamepadButton::B:
        case GamepadButton::Back:
            commands.back = true;
            break;
        case GamepadButton::DpadUp:
            commands.up = true;
            break;
        case GamepadButton::DpadDown:
            commands.down = true;
            break;
        case GamepadButton::DpadLeft:
            commands.left = true;
            break;
        case GamepadButton::DpadRight:
            commands.right = true;
            break;
        default:
            break;
    }
}

template <class Array, class Index>
auto& at(Array& array, Index index) {
    return array[static_cast<std::size_t>(index)];
}

}  // namespace

void Input::padAxis(const platform::GamepadAxisMoved& moved) {
    Pad& pad = pads_[moved.pad];
    const double before = at(pad.axes, moved.axis);
    at(pad.axes, moved.axis) = moved.value;
    // A stick pushed past the dead zone is one menu step, as a d-pad press is.
    auto crossed = [&](double limit) {
        return limit < 0 ? before >= limit && moved.value < limit : before <= limit && moved.value > limit;
    };
    if (!pinned_ && std::abs(moved.value) > kStickDeadZone) device_ = Device::Gamepad;
    if (moved.axis == GamepadAxis::LeftY) {
        if (crossed(-kStickDeadZone)) commands_.up = true;
        if (crossed(kStickDeadZone)) commands_.down = true;
    } else if (moved.axis == GamepadAxis::LeftX) {
        if (crossed(-kStickDeadZone)) commands_.left = true;
        if (crossed(kStickDeadZone)) commands_.right = true;
    }
}

void Input::handle(const platform::Event& event) {
    commands_.events.push_back(event);
    if (std::holds_alternative<platform::QuitRequested>(event)) {
        commands_.quit = true;
    } else if (std::holds_alternative<platform::WindowFocusLost>(event)) {
        commands_.focusLost = true;
    } else if (const auto* press = std::get_if<platform::KeyPressed>(&event)) {
        at(keys_, press->position) = true;
        lastPressRepeated_ = press->repeat;
        if (!pinned_) device_ = Device::Keyboard;
        keyCommand(commands_, *press, bindings_);
    } else if (const auto* release = std::get_if<platform::KeyReleased>(&event)) {
        at(keys_, release->position) = false;
    } else if (const auto* typed = std::get_if<platform::TextEntered>(&event)) {
        // A window sends a key's text right after its press, repeats included: the text of a
        // repeat is a key held, not a letter typed.
        if (!lastPressRepeated_) commands_.text += typed->utf8;
    } else if (const auto* moved = std::get_if<platform::MouseMoved>(&event)) {
        commands_.pointer = moved->canvas;
    } else if (const auto* click = std::get_if<platform::MouseButtonPressed>(&event)) {
        commands_.pointer = click->canvas;
        if (click->button == platform::MouseButton::Left) commands_.click = click->canvas;
    } else if (const auto* wheel = std::get_if<platform::MouseWheelScrolled>(&event)) {
        commands_.wheel += wheel->dy;
    } else if (const auto* button = std::get_if<platform::GamepadButtonPressed>(&event)) {
        at(pads_[button->pad].buttons, button->button) = true;
        if (!pinned_) device_ = Device::Gamepad;
        gamepadCommand(commands_, button->button, bindings_);
    } else if (const auto* up = std::get_if<platform::GamepadButtonReleased>(&event)) {
        at(pads_[up->pad].buttons, up->button) = false;
    } else if (const auto* axis = std::get_if<platform::GamepadAxisMoved>(&event)) {
        padAxis(*axis);
    } else if (const auto* gone = std::get_if<platform::GamepadDisconnected>(&event)) {
        pads_.erase(gone->pad);
    }
}

Actions Input::actions() const {
    std::vector<Bindings::PadState> pads;
    for (const auto& [id, pad] : pads_) {
        Bindings::PadState state;
        state.buttons = pad.buttons;
        state.leftX = at(pad.axes, GamepadAxis::LeftX);
        state.leftY = at(pad.axes, GamepadAxis::LeftY);
        state.rightTrigger = at(pad.axes, GamepadAxis::RightTrigger);
        pads.push_back(state);
    }
    return bindings_.actions([this](Key key) { return at(keys_, key); }, pads);
}

Input::Commands Input::takeCommands() {
    Commands out = std::move(commands_);
    commands_ = Commands{};
    return out;
}

}  // namespace polar::game
