#include "app/input.h"

#include "polar/platform/window.h"

namespace polar::game {
namespace {

using platform::GamepadButton;
using platform::Key;

void keyCommand(Input::Commands& commands, const platform::KeyPressed& press, const Bindings& bindings) {
    if (press.repeat) return;
    if (bindings.actionOfKey(press.position) == BoundAction::Pause) commands.pause = true;
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
    switch (button) {
        case GamepadButton::A:
            commands.confirm = true;
            break;
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

}  // namespace

void Input::handle(const platform::Event& event) {
    if (std::holds_alternative<platform::QuitRequested>(event))
        commands_.quit = true;
    else if (const auto* press = std::get_if<platform::KeyPressed>(&event))
        keyCommand(commands_, *press, bindings_);
    else if (const auto* button = std::get_if<platform::GamepadButtonPressed>(&event))
        gamepadCommand(commands_, button->button, bindings_);
}

Input::Commands Input::takeCommands() {
    Commands out = commands_;
    commands_ = Commands{};
    return out;
}

Input::Commands Input::pollEvents(platform::Window& window) {
    while (std::optional<platform::Event> event = window.pollEvent()) handle(*event);
    return takeCommands();
}

}  // namespace polar::game
