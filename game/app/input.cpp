#include "app/input.h"

#include "polar/platform/window.h"

namespace polar::game {
namespace {

using platform::GamepadAxis;
using platform::GamepadButton;
using platform::Key;

// Axis readings past which a stick counts as pushed and a trigger as pulled (of ±1).
constexpr double kStickDeadZone = 12000.0 / 32768.0;
constexpr double kTriggerPressed = 8000.0 / 32768.0;

void keyCommand(Input::Commands& commands, const platform::KeyPressed& press) {
    if (press.repeat) return;
    switch (press.key) {
        case Key::Escape:
            commands.back = commands.pause = true;
            break;
        case Key::P:
            commands.pause = true;
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

void gamepadCommand(Input::Commands& commands, GamepadButton button) {
    switch (button) {
        case GamepadButton::Start:
            commands.pause = true;
            break;
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
        keyCommand(commands_, *press);
    else if (const auto* button = std::get_if<platform::GamepadButtonPressed>(&event))
        gamepadCommand(commands_, button->button);
    else if (const auto* mouse = std::get_if<platform::MouseButtonPressed>(&event))
        commands_.click = commands_.click || mouse->button == platform::MouseButton::Left;
    else if (std::holds_alternative<platform::WindowFocusLost>(event))
        commands_.focusLost = true;
}

Actions Input::actions(const platform::Window& window) {
    Actions actions = 0;
    if (window.keyHeld(Key::Left) || window.keyHeld(Key::A)) actions |= kTurnLeft;
    if (window.keyHeld(Key::Right) || window.keyHeld(Key::D)) actions |= kTurnRight;
    if (window.keyHeld(Key::Up) || window.keyHeld(Key::W)) actions |= kThrust;
    if (window.keyHeld(Key::Space)) actions |= kFire;
    for (platform::GamepadId pad : window.gamepads()) {
        const double x = window.gamepadAxis(pad, GamepadAxis::LeftX);
        const double y = window.gamepadAxis(pad, GamepadAxis::LeftY);
        if (x < -kStickDeadZone || window.gamepadButton(pad, GamepadButton::DpadLeft)) actions |= kTurnLeft;
        if (x > kStickDeadZone || window.gamepadButton(pad, GamepadButton::DpadRight)) actions |= kTurnRight;
        if (y < -kStickDeadZone || window.gamepadButton(pad, GamepadButton::B) ||
            window.gamepadAxis(pad, GamepadAxis::RightTrigger) > kTriggerPressed)
            actions |= kThrust;
        if (window.gamepadButton(pad, GamepadButton::A)) actions |= kFire;
    }
    return actions;
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
